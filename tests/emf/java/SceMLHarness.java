// Test harness: drives real Eclipse EMF (standalone, no OSGi) on SceML metamodels and models.
//
// Every mode prints one line per finding and exits 0 when all went well, 1 when EMF reported a
// problem (diagnostics, load errors, differences), 2 on wrong usage. The Python tests read the
// output; nothing here decides what "correct" means beyond what EMF itself says.
//
//   check-ecore ECORE                      Diagnostician on every EPackage of ECORE
//   roundtrip ECORE IN_ROOT OUT_ROOT F...  load F (relative to IN_ROOT), resolve all, validate,
//                                          save every loaded resource under OUT_ROOT (same layout)
//   compare ECORE LEFT RIGHT               structural equality of two model files (EqualityHelper)
//   load ECORE FILE                        load FILE and print the load time in milliseconds
//   features ECORE FILE                    print every attribute value and reference target of FILE

import java.io.File;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.TreeIterator;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.EcorePackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.Diagnostician;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.impl.EcoreResourceFactoryImpl;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceFactoryImpl;

public final class SceMLHarness {
    private SceMLHarness() {}

    public static void main(String[] args) throws Exception {
        if (args.length < 2) {
            usage();
        }
        EcorePackage.eINSTANCE.eClass(); // registers Ecore itself before any .ecore is read
        String mode = args[0];
        int status;
        switch (mode) {
            case "check-ecore": status = checkEcore(args[1]); break;
            case "roundtrip": status = roundtrip(args); break;
            case "compare": status = compare(args); break;
            case "load": status = loadTimed(args); break;
            case "features": status = features(args); break;
            default: usage(); return;
        }
        System.out.flush();
        System.exit(status);
    }

    private static void usage() {
        System.err.println("usage: SceMLHarness check-ecore|roundtrip|compare|load|features ECORE ...");
        System.exit(2);
    }

    /** A resource set that reads .ecore files as metamodels and everything else as XMI. */
    private static ResourceSet newResourceSet() {
        ResourceSet set = new ResourceSetImpl();
        Map<String, Object> factories = set.getResourceFactoryRegistry().getExtensionToFactoryMap();
        factories.put("ecore", new EcoreResourceFactoryImpl());
        factories.put("*", new XMIResourceFactoryImpl());
        return set;
    }

    private static URI fileUri(String path) {
        try {
            // Canonical, so that a file named on the command line and the same file reached
            // through a relative href are one resource, not two.
            return URI.createFileURI(new File(path).getCanonicalPath());
        } catch (java.io.IOException error) {
            throw new IllegalArgumentException(path, error);
        }
    }

    /** Loads ECORE and registers each of its packages (and subpackages) under its nsURI. */
    private static List<EPackage> registerMetamodel(ResourceSet set, String ecore) {
        Resource resource = set.getResource(fileUri(ecore), true);
        List<EPackage> packages = new ArrayList<>();
        for (EObject root : resource.getContents()) {
            if (root instanceof EPackage) {
                collect((EPackage) root, packages);
            }
        }
        for (EPackage pkg : packages) {
            set.getPackageRegistry().put(pkg.getNsURI(), pkg);
        }
        return packages;
    }

    private static void collect(EPackage pkg, List<EPackage> into) {
        into.add(pkg);
        for (EPackage sub : pkg.getESubpackages()) {
            collect(sub, into);
        }
    }

    private static int report(String what, Diagnostic diagnostic) {
        if (diagnostic.getSeverity() == Diagnostic.OK) {
            return 0;
        }
        int count = 0;
        for (Diagnostic child : diagnostic.getChildren()) {
            if (child.getSeverity() >= Diagnostic.WARNING) {
                System.out.println("DIAGNOSTIC " + what + ": " + child.getMessage());
                count++;
            }
        }
        if (count == 0) {
            System.out.println("DIAGNOSTIC " + what + ": " + diagnostic.getMessage());
        }
        return 1;
    }

    private static int checkEcore(String ecore) {
        ResourceSet set = newResourceSet();
        int status = 0;
        for (EPackage pkg : registerMetamodel(set, ecore)) {
            status |= report(pkg.getName(), Diagnostician.INSTANCE.validate(pkg));
            System.out.println("PACKAGE " + pkg.getName() + " " + pkg.getNsURI());
        }
        return status;
    }

    private static int loadErrors(Resource resource) {
        int status = 0;
        for (Resource.Diagnostic error : resource.getErrors()) {
            System.out.println("ERROR " + resource.getURI().lastSegment() + ":" + error.getLine()
                + ": " + error.getMessage());
            status = 1;
        }
        return status;
    }

    private static int roundtrip(String[] args) throws Exception {
        if (args.length < 5) {
            usage();
        }
        ResourceSet set = newResourceSet();
        registerMetamodel(set, args[1]);
        File inRoot = new File(args[2]).getCanonicalFile();
        File outRoot = new File(args[3]).getCanonicalFile();
        int status = 0;
        List<Resource> named = new ArrayList<>();
        for (int i = 4; i < args.length; i++) {
            Resource resource;
            try {
                resource = set.getResource(fileUri(new File(inRoot, args[i]).getPath()), true);
            } catch (RuntimeException error) {
                System.out.println("LOADFAIL " + args[i] + ": " + rootCause(error));
                status = 1;
                continue;
            }
            named.add(resource);
        }
        for (Resource resource : named) {
            EcoreUtil.resolveAll(resource);
        }
        // resolveAll may have pulled in other files (libraries); those are written too.
        List<Resource> all = new ArrayList<>(set.getResources());
        Map<Resource, URI> targets = new HashMap<>();
        for (Resource resource : all) {
            if (resource.getURI().fileExtension() != null
                    && resource.getURI().fileExtension().equals("ecore")) {
                continue;
            }
            status |= loadErrors(resource);
            for (EObject root : resource.getContents()) {
                status |= report(resource.getURI().lastSegment(), Diagnostician.INSTANCE.validate(root));
            }
            String relative = relativeTo(inRoot, new File(resource.getURI().toFileString()));
            if (relative == null) {
                System.out.println("OUTSIDE " + resource.getURI());
                status = 1;
                continue;
            }
            targets.put(resource, fileUri(new File(outRoot, relative).getPath()));
        }
        // Move every resource first, then save, so cross-file hrefs are written relative to the
        // new locations.
        for (Map.Entry<Resource, URI> entry : targets.entrySet()) {
            entry.getKey().setURI(entry.getValue());
        }
        for (Map.Entry<Resource, URI> entry : targets.entrySet()) {
            new File(entry.getValue().toFileString()).getParentFile().mkdirs();
            entry.getKey().save(null);
            System.out.println("SAVED " + entry.getValue().toFileString());
        }
        return status;
    }

    private static String relativeTo(File root, File file) {
        String rootPath = root.getAbsolutePath() + File.separator;
        String filePath = file.getAbsolutePath();
        return filePath.startsWith(rootPath) ? filePath.substring(rootPath.length()) : null;
    }

    private static String rootCause(Throwable error) {
        Throwable cause = error;
        while (cause.getCause() != null && cause.getCause() != cause) {
            cause = cause.getCause();
        }
        return cause.getClass().getSimpleName() + ": " + cause.getMessage();
    }

    private static Resource loadResolved(ResourceSet set, String path) {
        Resource resource = set.getResource(fileUri(path), true);
        EcoreUtil.resolveAll(resource);
        return resource;
    }

    private static int compare(String[] args) {
        if (args.length != 4) {
            usage();
        }
        // Two resource sets: the files may share names and refer to libraries of their own.
        ResourceSet leftSet = newResourceSet();
        registerMetamodel(leftSet, args[1]);
        ResourceSet rightSet = newResourceSet();
        registerMetamodel(rightSet, args[1]);
        Resource left = loadResolved(leftSet, args[2]);
        Resource right = loadResolved(rightSet, args[3]);
        int status = loadErrors(left) | loadErrors(right);
        List<String> found = new ArrayList<>();
        compareLists("/", left.getContents(), right.getContents(), found);
        for (String difference : found) {
            System.out.println("DIFF " + difference);
        }
        System.out.println(found.isEmpty() ? "EQUAL" : "DIFFERENT");
        return found.isEmpty() ? status : 1;
    }

    // A structural comparison by value, not EcoreUtil.EqualityHelper: that one also compares
    // the "is set" state, and a file that spells out a default (pyecore writes them) leaves the
    // feature set where EMF's own output leaves it unset, although both mean the same model.
    private static void compareLists(String path, List<?> left, List<?> right, List<String> found) {
        if (left.size() != right.size()) {
            found.add(path + ": " + left.size() + " items != " + right.size());
            return;
        }
        for (int i = 0; i < left.size(); i++) {
            compareObjects(path + "[" + i + "]", (EObject) left.get(i), (EObject) right.get(i), found);
        }
    }

    private static void compareObjects(String path, EObject left, EObject right, List<String> found) {
        // Each side has its own resource set, hence its own copy of the metamodel: compare names.
        if (!left.eClass().getName().equals(right.eClass().getName())) {
            found.add(path + ": " + left.eClass().getName() + " != " + right.eClass().getName());
            return;
        }
        for (EStructuralFeature feature : left.eClass().getEAllStructuralFeatures()) {
            if (feature.isTransient() || feature.isDerived()) {
                continue;
            }
            String here = path + "/" + feature.getName();
            List<?> a = asList(feature, left.eGet(feature));
            List<?> b = asList(feature, right.eGet(right.eClass().getEStructuralFeature(feature.getName())));
            if (feature instanceof EAttribute) {
                // Text form: enum literals of two metamodel copies are distinct objects.
                if (!a.toString().equals(b.toString())) {
                    found.add(here + ": " + a + " != " + b);
                }
            } else if (((EReference) feature).isContainment()) {
                compareLists(here, a, b, found);
            } else if (!referenceKeys(left, a).equals(referenceKeys(right, b))) {
                found.add(here + ": " + referenceKeys(left, a) + " != " + referenceKeys(right, b));
            }
        }
    }

    private static List<?> asList(EStructuralFeature feature, Object value) {
        if (feature.isMany()) {
            return (List<?>) value;
        }
        return value == null ? List.of() : List.of(value);
    }

    /** How reference targets are identified: their fragment, plus the file name (folders may
     *  differ) when they live in another file than the holder. */
    private static List<String> referenceKeys(EObject holder, List<?> targets) {
        List<String> keys = new ArrayList<>();
        for (Object target : targets) {
            EObject object = (EObject) target;
            URI uri = EcoreUtil.getURI(object);
            boolean here = object.eResource() == holder.eResource();
            keys.add((here ? "" : uri.lastSegment()) + "#" + uri.fragment());
        }
        return keys;
    }

    private static int loadTimed(String[] args) {
        if (args.length != 3) {
            usage();
        }
        ResourceSet set = newResourceSet();
        registerMetamodel(set, args[1]);
        long start = System.nanoTime();
        Resource resource = set.getResource(fileUri(args[2]), true);
        EcoreUtil.resolveAll(resource);
        long elapsed = System.nanoTime() - start;
        int objects = 0;
        for (TreeIterator<EObject> it = resource.getAllContents(); it.hasNext(); it.next()) {
            objects++;
        }
        System.out.println("LOADED " + objects + " objects in " + (elapsed / 1_000_000.0) + " ms");
        return loadErrors(resource);
    }

    private static int features(String[] args) {
        if (args.length != 3) {
            usage();
        }
        ResourceSet set = newResourceSet();
        registerMetamodel(set, args[1]);
        Resource resource;
        try {
            resource = set.getResource(fileUri(args[2]), true);
        } catch (RuntimeException error) {
            System.out.println("LOADFAIL " + rootCause(error));
            return 1;
        }
        int status = loadErrors(resource);
        for (TreeIterator<EObject> it = resource.getAllContents(); it.hasNext();) {
            EObject object = it.next();
            String where = EcoreUtil.getURI(object).fragment();
            for (EStructuralFeature feature : object.eClass().getEAllStructuralFeatures()) {
                if (!object.eIsSet(feature)) {
                    continue;
                }
                Object value = object.eGet(feature, false);
                if (feature instanceof EAttribute) {
                    System.out.println("ATTR " + where + " " + feature.getName() + "=" + value);
                } else if (!((EReference) feature).isContainment()) {
                    List<?> targets = feature.isMany() ? (List<?>) value : List.of(value);
                    for (Object target : targets) {
                        EObject resolved = EcoreUtil.resolve((EObject) target, object);
                        String state = resolved.eIsProxy() ? "UNRESOLVED " : "";
                        System.out.println("REF " + where + " " + feature.getName() + " -> "
                            + state + EcoreUtil.getURI(resolved));
                    }
                }
            }
        }
        return status;
    }
}
