// Loads one SceML file with Eclipse EMF N times in this JVM, each time into a fresh resource set,
// and prints each load's own time: the first is a cold load (a fresh JVM, nothing compiled yet),
// the best of the rest a warm one. Used by benchmarks/xmi_load.py.
//
//   java -cp CLASSES:EMF_JARS EmfLoad ECORE FILE N
//
// Prints "LOAD <ms> <objects>" per load; exit 1 if the file has load errors.

import java.io.File;
import java.io.IOException;
import java.util.Map;

import org.eclipse.emf.common.util.TreeIterator;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.impl.EcoreResourceFactoryImpl;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceFactoryImpl;

public final class EmfLoad {
    public static void main(String[] args) throws IOException {
        URI ecore = URI.createFileURI(new File(args[0]).getCanonicalPath());
        URI file = URI.createFileURI(new File(args[1]).getCanonicalPath());
        int times = Integer.parseInt(args[2]);
        int status = 0;
        for (int i = 0; i < times; i++) {
            ResourceSet set = new ResourceSetImpl();
            Map<String, Object> factories = set.getResourceFactoryRegistry().getExtensionToFactoryMap();
            factories.put("ecore", new EcoreResourceFactoryImpl());
            factories.put("*", new XMIResourceFactoryImpl());
            // The metamodel is registered before the clock: SceML's Python classes are generated.
            for (EObject root : set.getResource(ecore, true).getContents()) {
                register(set, (EPackage) root);
            }
            long start = System.nanoTime();
            Resource resource = set.getResource(file, true);
            EcoreUtil.resolveAll(resource);
            long elapsed = System.nanoTime() - start;
            int objects = 0;
            for (TreeIterator<EObject> it = resource.getAllContents(); it.hasNext(); it.next()) {
                objects++;
            }
            if (!resource.getErrors().isEmpty()) {
                status = 1;
            }
            System.out.println("LOAD " + (elapsed / 1_000_000.0) + " " + objects);
        }
        System.exit(status);
    }

    private static void register(ResourceSet set, EPackage pkg) {
        set.getPackageRegistry().put(pkg.getNsURI(), pkg);
        for (EPackage sub : pkg.getESubpackages()) {
            register(set, sub);
        }
    }
}
