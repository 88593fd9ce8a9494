"""Load and save scenarios and module libraries as XMI, safely, atomically and with locations."""

from __future__ import annotations

import contextlib
import io as _io
import math
import os
import re
import tempfile
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

from lxml import etree
from pyecore.ecore import EAttribute, EClass, EEnum, EObject, EProxy, EReference
from pyecore.resources import URI, ResourceSet
from pyecore.resources.xmi import XMIOptions, XMIResource

import scemlmodel as scm

from . import xmi_reader
from .collector import collector_paused
from .errors import LoadError, SaveError, SceMLError

# The roots rule lives with the reading rule; it is part of this module's API too.
from .safefiles import PROJECT_MARKERS as PROJECT_MARKERS
from .safefiles import output_target, read_input
from .safefiles import project_root as project_root
from .safefiles import reading_roots as reading_roots
from .safexml import (  # noqa: F401 (the size limit is part of this module's API)
    DEFAULT_MAX_BYTES,
    MAX_BYTES_VARIABLE,
    doctype_line,
    hardened_parser,
    has_dtd,
    max_bytes_limit,
    size_problem,
)
from .traversal import all_contents, cross_references, stored

# Deeper documents are refused by libxml2 itself (its limit without huge_tree is 256 levels), so
# pyecore's recursive decoder never sees more than that and cannot overflow Python's stack.
_LINE_IN_MESSAGE = re.compile(r"line (\d+)")
# pyecore names a package by its Python repr, which shows the install path; keep the name only.
_MODULE_REPR = re.compile(r"<module '([\w.]+)' from '[^']*'>")

# EMF's own number syntax, minus what it alone accepts (hex floats, a trailing d or f): Python's
# float() would also take "1_000", "inf" and "nan", which EMF refuses when it reads the file back.
_DECIMAL = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")
_INTEGER = re.compile(r"[+-]?\d+")
_INT_RANGE = (-(2**31), 2**31 - 1)  # EInt is a Java int
_FLOAT_TYPES = frozenset({"EDouble", "EDoubleObject", "EFloat", "EFloatObject"})
_INT_TYPES = frozenset({"EInt", "EIntegerObject", "EShort", "EShortObject", "EByte", "EByteObject"})
_BOOLEAN_TYPES = frozenset({"EBoolean", "EBooleanObject"})


def parse_xml_safely(path: Path, max_bytes: int | None = None) -> etree._ElementTree:
    """Parse an XML file with every dangerous feature off; LoadError names the file and line.

    Read by the one reading rule (`sceml.safefiles.read_input`): a regular file of at most
    `max_bytes` (default: `max_bytes_limit()`); a larger file is refused before it is read.
    """
    try:
        data = read_input(path, max_bytes=max_bytes)
    except FileNotFoundError:
        raise LoadError("no such file", file=path) from None
    except OSError as error:
        raise LoadError(f"cannot read file: {error.strerror}", file=path) from None
    line = doctype_line(data)
    if line is not None:
        raise LoadError("DTDs and entity declarations are not accepted", file=path, line=line)
    try:
        tree = etree.parse(
            _io.BytesIO(data), parser=hardened_parser(drop_comments=True), base_url=None
        )
    except etree.XMLSyntaxError as error:
        raise LoadError(f"malformed XML: {error.msg}", file=path, line=error.lineno) from None
    # The prolog scan cannot read every encoding (UTF-32, say); the parser, which did not expand
    # the DTD (resolve_entities is off), still reports it.
    if has_dtd(tree):
        raise LoadError("DTDs and entity declarations are not accepted", file=path, line=1)
    return tree


class _Located(Exception):
    """A decoding failure tied to the XML element being decoded (internal to this module)."""

    def __init__(self, error: BaseException, line: int | None) -> None:
        super().__init__(str(error) or type(error).__name__)
        self.line = line


class SafeXMIResource(XMIResource):  # type: ignore[misc]  # pyecore is untyped
    """An XMI resource that parses with the hardened parser and only reads allowed local files.

    Besides what pyecore checks, it refuses what EMF would refuse or what no SceML tool writes:
    values EMF cannot read back (non-finite or malformed numbers, ints beyond 32 bits, unknown
    enum literals), duplicate ids, more than one root, and cross-file containment.

    Files are decoded by `sceml.xmi_reader`, which builds the objects directly; what it declines
    goes through pyecore's decoder (`fast_decoding = False` makes every file take that path).
    """

    fast_decoding = True

    def load(self, options: dict[XMIOptions, Any] | None = None) -> None:
        path = _local_path(self.uri)
        resource_set = self.resource_set
        allowed = getattr(resource_set, "sceml_allowed_roots", None)
        named = path.resolve() in getattr(resource_set, "sceml_named_files", ())
        if allowed is not None and not named and not any(_is_within(path, r) for r in allowed):
            roots = ", ".join(str(r) for r in allowed)
            raise LoadError(
                f"reference leaves the allowed folders ({roots}); to read it, allow its folder "
                f"(--allow {path.parent})",
                file=path,
            )
        tree = parse_xml_safely(path, getattr(resource_set, "sceml_max_bytes", None))
        self.sceml_migration = _migrate_if_older(tree, path)
        _check_tree(tree, path)
        self.sceml_tree = tree
        # iD attribute values seen so far: EMF fragments name elements by them, so they must be
        # unique per file (ModuleDefinition.name is one).
        self._sceml_ids: dict[tuple[str, str], tuple[EObject, int | None]] = {}
        try:
            with collector_paused():
                self._decode_tree(tree, options)
        except LoadError:
            raise
        except _Located as error:
            message = _MODULE_REPR.sub(r"\1", str(error))
            raise LoadError(
                f"not a valid SceML model: {message}", file=path, line=error.line
            ) from None
        except RecursionError:
            raise LoadError("model nesting is too deep", file=path) from None
        except Exception as error:  # pyecore signals bad content with bare exceptions
            message = _MODULE_REPR.sub(r"\1", str(error) or type(error).__name__)
            found = _LINE_IN_MESSAGE.search(message)
            raise LoadError(
                f"not a valid SceML model: {message}",
                file=path,
                line=int(found.group(1)) if found else None,
            ) from None
        finally:
            self._clean_registers()
        self._keep_lines(tree)

    def _keep_lines(self, tree: etree._ElementTree) -> None:
        # Where each object was written is all that is needed of the parse tree later; the tree
        # itself is dropped (about a quarter of a large model's memory). The fast reader notes
        # the lines as it goes; pyecore's decoder leaves them to be read off the tree.
        if getattr(self, "sceml_lines", None) is None:
            self.sceml_lines = {
                obj: _line_in(self, obj)
                for root in self.contents
                for obj in (root, *all_contents(root))
            }
        for root in self.contents:
            self.sceml_lines[root] = tree.getroot().sourceline
        self.sceml_tree = None
        self.__dict__.pop("sceml_children", None)

    def _decode_tree(self, tree: etree._ElementTree, options: dict[XMIOptions, Any] | None) -> None:
        # Mirrors XMIResource.load, but decodes the tree parsed above instead of re-reading the file.
        self.options = options or {}
        self.cache_enabled = True
        xmlroot = tree.getroot()
        self.prefixes.update(xmlroot.nsmap)
        self.reverse_nsmap = {v: k for k, v in self.prefixes.items()}
        xsi, xmi = self.prefixes.get("xsi"), self.prefixes.get("xmi")
        self.xsitype = f"{{{xsi}}}type"
        self.xmiid = f"{{{xmi}}}id"
        self.schema_tag = f"{{{xsi}}}schemaLocation"
        self.schema_locations: dict[str, object] = {}
        if self.fast_decoding and xmi_reader.decode(self, xmlroot, _check_literal):
            return
        self._decode_with_pyecore(xmlroot, xmi)

    def _decode_with_pyecore(self, xmlroot: etree._Element, xmi: str | None) -> None:
        # pyecore's own decoder, through the overrides below: what the fast reader declines
        # (anything unusual or wrong) is decoded or reported here, with pyecore's messages.
        roots = xmlroot if xmlroot.tag == f"{{{xmi}}}XMI" else [xmlroot]
        for root in roots:
            self._sceml_node = root
            try:
                model_root = self._init_modelroot(root)
            except Exception as error:
                raise _Located(error, root.sourceline) from None
            for child in root:
                self._decode_eobject(child, model_root)
        if self.contents:
            self._decode_ereferences()

    def _decode_eobject(self, current_node: etree._Element, parent_eobj: EObject) -> None:
        # The innermost element that fails names the line; outer levels pass it through.
        self._sceml_node = current_node
        try:
            if current_node.get("href") is not None:
                _refuse_containment_href(self, current_node, parent_eobj)
            super()._decode_eobject(current_node, parent_eobj)
        except (_Located, RecursionError):
            raise
        except Exception as error:
            raise _Located(error, current_node.sourceline) from None

    def _decode_eattribute_value(
        self, eobject: EObject, eattribute: EAttribute, value: str, from_tag: bool = False
    ) -> None:
        _check_literal(eattribute, value)
        super()._decode_eattribute_value(eobject, eattribute, value, from_tag)
        if eattribute.iD:
            key = (eobject.eClass.name, value)
            first, line = self._sceml_ids.setdefault(key, (eobject, self._sceml_node.sourceline))
            if first is not eobject:
                raise ValueError(
                    f"duplicate {eobject.eClass.name} {eattribute.name} {value!r} "
                    f"(first on line {line})"
                )

    def _decode_ereferences(self) -> None:
        # One holder at a time, so a reference that does not resolve is reported at its line.
        pending: list[tuple[EObject, list[tuple[EReference, str]]]] = list(self._later)  # type: ignore[has-type]
        for holder, references in pending:
            self._later = [(holder, references)]
            try:
                super()._decode_ereferences()
            except Exception as error:
                hrefs = ", ".join(repr(value) for _, value in references)
                raise _Located(
                    ValueError(
                        f"reference {hrefs} does not resolve to a suitable element ({error})"
                    ),
                    _line_in(self, holder),
                ) from None
        self._later = []


def _migrate_if_older(tree: etree._ElementTree, path: Path) -> Any:
    """Rewrite a file saved with an older metamodel release to the current one, in memory.

    Returns the migration's report (`sceml.migrations.Report`), or None for a file of the
    current release; the migration code is imported only for the others.
    """
    root = tree.getroot()
    model = next(iter(root), None) if etree.QName(root).localname == "XMI" else root
    if model is None or etree.QName(model).namespace == scm.nsURI:
        return None
    from . import migrations

    report = migrations.upgrade(tree, path)
    if report is not None:
        for listener in list(_MIGRATION_LISTENERS):
            listener(report)
    return report


_MIGRATION_LISTENERS: list[Any] = []


@contextlib.contextmanager
def migration_notices(listener: Any) -> Iterator[None]:
    """Call `listener(report)` for every file migrated while loading, within the block.

    For front ends (the CLI prints a notice); library code never says anything itself.
    """
    _MIGRATION_LISTENERS.append(listener)
    try:
        yield
    finally:
        _MIGRATION_LISTENERS.remove(listener)


def _check_tree(tree: etree._ElementTree, path: Path) -> None:
    """Refuse, before decoding, a document that is not one SceML model or repeats an xmi:id."""
    root = tree.getroot()
    xmi_namespace = root.nsmap.get("xmi", "http://www.omg.org/XMI")
    models = list(root) if root.tag == f"{{{xmi_namespace}}}XMI" else [root]
    if len(models) != 1:
        raise LoadError(
            f"a SceML file holds one model per file, this one holds {len(models)}",
            file=path,
            line=root.sourceline,
        )
    namespace = etree.QName(models[0]).namespace
    if namespace != scm.nsURI:
        raise LoadError(
            f"not a SceML model: root element <{etree.QName(models[0]).localname}> is in "
            f"namespace {namespace!r}, not {scm.nsURI!r}",
            file=path,
            line=models[0].sourceline,
        )
    _check_types_and_ids(root, path, f"{{{xmi_namespace}}}id")


_XSI_TYPE = "{http://www.w3.org/2001/XMLSchema-instance}type"


def _check_types_and_ids(root: etree._Element, path: Path, id_attribute: str) -> None:
    """Refuse an xsi:type that names no concrete SceML class, in the file's own terms, and
    then a repeated xmi:id.

    One walk over the tree does both (each was a walk of its own, a third of a large file's
    load); a wrong type anywhere is still reported before a repeated id, as it was.
    """
    # Files SceML and EMF write declare their prefixes on the root element alone; then every
    # element has the root's prefixes, and building each one's nsmap (most of this pass's
    # time on a large file) is not needed.
    declared = sum(1 for _ in etree.iterwalk(root, events=("start-ns",)))
    shared = _prefixes(root) if declared == len(root.nsmap) else None
    seen: dict[str, etree._Element] = {}
    repeated: tuple[etree._Element, etree._Element] | None = None
    for element in root.iter(etree.Element):
        value = element.get(_XSI_TYPE)
        if value is not None:
            # A file names a handful of types under one set of prefixes: judge each pair once.
            problem = _type_problem_of(value, shared or _prefixes(element))
            if problem is not None:
                raise LoadError(problem, file=path, line=element.sourceline)
        identifier = element.get(id_attribute)
        if identifier is None:
            continue
        first = seen.setdefault(identifier, element)
        if first is not element and repeated is None:
            repeated = (first, element)
    if repeated is not None:
        first, again = repeated
        raise LoadError(
            f"duplicate xmi:id {again.get(id_attribute)!r} (first on line {first.sourceline})",
            file=path,
            line=again.sourceline,
        )


def _prefixes(element: etree._Element) -> tuple[tuple[str | None, str], ...]:
    return tuple(sorted(element.nsmap.items(), key=str))


@lru_cache(maxsize=1024)
def _type_problem_of(value: str, namespaces: tuple[tuple[str | None, str], ...]) -> str | None:
    return _type_problem(value, dict(namespaces))


def _type_problem(value: str, namespaces: dict[str | None, str]) -> str | None:
    prefix, colon, name = value.rpartition(":")
    ours = next((p for p, uri in namespaces.items() if p and uri == scm.nsURI), scm.nsPrefix)
    expected = f'expected "{ours}:{name}"'
    if not colon:
        return f'xsi:type "{value}" has no namespace prefix; {expected}'
    if prefix not in namespaces:
        return f'xsi:type "{value}": prefix "{prefix}" is not declared; {expected}'
    if namespaces[prefix] != scm.nsURI:
        return (
            f'xsi:type "{value}": prefix "{prefix}" is not the SceML metamodel\'s namespace '
            f"({scm.nsURI}); {expected}"
        )
    kind = scm.eClass.getEClassifier(name)
    if not isinstance(kind, EClass):
        return f'xsi:type "{value}": the SceML metamodel has no type {name}'
    if kind.abstract:
        concrete = sorted(
            c.name
            for c in scm.eClass.eClassifiers
            if isinstance(c, EClass) and not c.abstract and kind in c.eAllSuperTypes()
        )
        return (
            f'xsi:type "{value}": {name} is abstract; use one of its kinds: {", ".join(concrete)}'
        )
    return None


def _refuse_containment_href(resource: XMIResource, node: etree._Element, parent: EObject) -> None:
    # EMF can keep a contained element in another file ("cross-resource containment"); SceML
    # never writes that, and a proxy in a containment is how a file could claim that an element
    # contains itself.
    feature = resource._find_feature(parent.eClass, etree.QName(node).localname)
    if feature is not None and getattr(feature, "containment", False):
        raise ValueError(
            f"{parent.eClass.name}.{feature.name} is a containment and cannot refer to another "
            f"element (href={node.get('href')!r})"
        )


def _check_literal(attribute: EAttribute, text: str) -> None:
    """Refuse attribute text that EMF would not read back as the same value."""
    kind = attribute.eType
    name = kind.name
    for word in text.split() if attribute.many else [text]:
        if isinstance(kind, EEnum):
            if kind.getEEnumLiteral(word) is None:
                options = ", ".join(literal.name for literal in kind.eLiterals)
                raise ValueError(f"{attribute.name}={word!r} is not one of: {options}")
        elif name in _FLOAT_TYPES:
            if not _DECIMAL.fullmatch(word):
                raise ValueError(f"{attribute.name}={word!r} is not a finite decimal number")
        elif name in _INT_TYPES:
            if not _INTEGER.fullmatch(word):
                raise ValueError(f"{attribute.name}={word!r} is not a whole number")
            if not _INT_RANGE[0] <= int(word) <= _INT_RANGE[1]:
                raise ValueError(f"{attribute.name}={word} does not fit a 32-bit int")
        elif name in _BOOLEAN_TYPES and word.lower() not in ("true", "false"):
            raise ValueError(f"{attribute.name}={word!r} is neither true nor false")


def _line_in(resource: XMIResource, obj: EObject) -> int | None:
    element = _element_of(resource, obj)
    return element.sourceline if element is not None else None


def _local_path(uri: URI) -> Path:
    if uri.protocol not in (None, "file"):
        raise LoadError(f"only local files are read, not {uri.protocol}: URIs", file=uri.plain)
    return Path(uri.normalize())


def _is_within(path: Path, root: Path) -> bool:
    try:
        path.resolve().relative_to(root.resolve())
    except ValueError:
        return False
    return True


def new_resource_set(
    allowed_roots: Iterable[str | Path] | None = None, max_bytes: int | None = None
) -> ResourceSet:
    """A fresh resource set that knows the SceML metamodel and reads files safely.

    `allowed_roots`, when given, are the only folders files may be read from, cross-file
    references included. `max_bytes` limits each file's size (default: `max_bytes_limit()`).
    """
    resource_set = ResourceSet()
    resource_set.metamodel_registry[scm.nsURI] = scm
    resource_set.resource_factory["xmi"] = SafeXMIResource
    resource_set.resource_factory["*"] = SafeXMIResource
    resource_set.sceml_allowed_roots = (
        None if allowed_roots is None else [Path(r).resolve() for r in allowed_roots]
    )
    resource_set.sceml_max_bytes = max_bytes
    return resource_set


@dataclass
class Document:
    """A loaded model file: its root object and where each element was written."""

    path: Path
    root: EObject
    resource: XMIResource
    resource_set: ResourceSet = field(repr=False)

    def line_of(self, obj: EObject) -> int | None:
        """The line of the element `obj` was read from in this file, if it was read from it."""
        # Lines are those of the file as it was read: an object made since has none, and one
        # moved since keeps the line it was read from.
        lines = getattr(obj.eResource, "sceml_lines", None) if obj.eResource else None
        return lines.get(obj) if lines is not None else None

    @property
    def migration(self) -> Any:
        """How this file was migrated from an older metamodel release (a
        `sceml.migrations.Report`), or None when it was saved with the current one."""
        return getattr(self.resource, "sceml_migration", None)

    def migrations(self) -> list[Any]:
        """The migration reports of this file and of every file it has loaded since (libraries)."""
        # A resource set may hold one file under two URIs; each file is reported once.
        found: dict[Path, Any] = {}
        for resource in self.resource_set.resources.values():
            report = getattr(resource, "sceml_migration", None)
            if report is not None:
                found.setdefault(Path(report.file).resolve(), report)
        return list(found.values())

    @property
    def allowed_roots(self) -> list[Path] | None:
        """The folders files this model names (libraries, maps) may be read from; None: any."""
        return allowed_roots_of(self.root)

    def file_of(self, obj: EObject) -> Path | None:
        """The file an object was read from (a library, for module internals)."""
        resource = obj.eResource
        return Path(resource.uri.normalize()) if resource is not None else None


def allowed_roots_of(obj: EObject) -> list[Path] | None:
    """The folders the files `obj`'s model names may be read from, as it was loaded (`load`'s
    allowed roots); None for a model that was not loaded with them (built in Python)."""
    resource = obj.eResource
    resource_set = resource.resource_set if resource is not None else None
    roots: list[Path] | None = getattr(resource_set, "sceml_allowed_roots", None)
    return roots


def _containment_steps(obj: EObject) -> list[tuple[str, int]]:
    steps: list[tuple[str, int]] = []
    while obj.eContainer() is not None and obj.eContainmentFeature() is not None:
        feature = obj.eContainmentFeature()
        container = obj.eContainer()
        index = container.eGet(feature).index(obj) if feature.many else 0
        steps.append((feature.name, index))
        obj = container
    return list(reversed(steps))


def _element_of(resource: XMIResource, obj: EObject) -> etree._Element | None:
    """The XML element `obj` was read from, found by its containment steps in the parsed file.

    Each element's children are grouped by tag once per file (kept on the resource), so that
    locating thousands of diagnostics in a large file costs a dictionary lookup per step rather
    than a scan of every sibling.
    """
    tree = getattr(resource, "sceml_tree", None)
    if tree is None:
        return None
    groups: dict[etree._Element, dict[str, list[etree._Element]]]
    groups = resource.__dict__.setdefault("sceml_children", {})
    element = tree.getroot()
    for name, index in _containment_steps(obj):
        by_tag = groups.get(element)
        if by_tag is None:
            by_tag = groups[element] = {}
            for child in element:
                by_tag.setdefault(child.tag, []).append(child)
        children = by_tag.get(name, ())
        if index >= len(children):
            return None
        element = children[index]
    return element


def model_path(obj: EObject) -> str:
    """A readable path of element names from the document root, e.g. `CrossingManeuver/Accelerate_1`."""
    names = []
    current: EObject | None = obj
    while current is not None:
        label = _label(current)
        if label:
            names.append(label)
        current = current.eContainer()
    return "/".join(reversed(names))


def _label(obj: EObject) -> str:
    name = getattr(obj, "name", None)
    if name:
        return str(name)
    feature = obj.eContainmentFeature()
    if feature is None:
        return ""
    if feature.many:
        return f"{feature.name}[{obj.eContainer().eGet(feature).index(obj)}]"
    return str(feature.name)


def uri_fragment(obj: EObject) -> str:
    """The EMF URI fragment of an object inside its file, e.g. `//@nodes.3/@targetSpeed`."""
    return str(obj.eURIFragment())


def load(
    path: str | Path,
    *,
    resource_set: ResourceSet | None = None,
    allowed_roots: Iterable[str | Path] | None = None,
    allow: Iterable[str | Path] = (),
    max_bytes: int | None = None,
) -> Document:
    """Load a scenario or library XMI file; references to other files load on first use.

    Referenced files are read only from `allowed_roots`, by default `reading_roots(path, allow)`
    (the file's folder, its project root and `allow`), and only up to `max_bytes` each (default:
    $SCEML_MAX_BYTES, else DEFAULT_MAX_BYTES).
    """
    path = Path(path)
    if resource_set is None:
        roots = allowed_roots if allowed_roots is not None else reading_roots(path, allow)
        resource_set = new_resource_set(roots, max_bytes)
    # The file the user names is always read; allowed_roots govern what it refers to.
    named: set[Path] = getattr(resource_set, "sceml_named_files", set())
    named.add(path.resolve())
    resource_set.sceml_named_files = named
    resource = resource_set.get_resource(URI(str(path)))
    if not resource.contents:
        raise LoadError("the file holds no model", file=path)
    root = resource.contents[0]
    if not isinstance(root, scm.Scenario | scm.Library):
        raise LoadError(
            f"expected a Scenario or Library, found {root.eClass.name}",
            file=path,
            line=_root_line(resource),
        )
    return Document(path=path, root=root, resource=resource, resource_set=resource_set)


def _root_line(resource: XMIResource) -> int | None:
    lines = getattr(resource, "sceml_lines", None)
    return lines.get(resource.contents[0]) if lines and resource.contents else None


def load_scenario(path: str | Path, **kwargs: object) -> Document:
    """Load a file that must hold a Scenario."""
    document = load(path, **kwargs)  # type: ignore[arg-type]
    if not isinstance(document.root, scm.Scenario):
        raise LoadError(
            "expected a scenario, found a module library",
            file=path,
            line=_root_line(document.resource),
        )
    return document


def load_library(path: str | Path, **kwargs: object) -> Document:
    """Load a file that must hold a module Library."""
    document = load(path, **kwargs)  # type: ignore[arg-type]
    if not isinstance(document.root, scm.Library):
        raise LoadError(
            "expected a module library, found a scenario",
            file=path,
            line=_root_line(document.resource),
        )
    return document


def unresolved_references(
    root: EObject, *, through_files: bool = False
) -> Iterator[tuple[EObject, str, str]]:
    """Every cross-file reference below `root` that cannot be loaded: (holder, href, reason).

    Any reference may name another file (a ModuleUse's definition by design, a node's
    referenceActor by a hand-edited file); each is tried here, so that no tool meets a proxy
    that fails later with pyecore's TypeError. With `through_files`, the files reached are
    searched too, each once: a library's own broken reference is found before a tool expands
    its modules.
    """
    pending, seen = [root], {id(root)}
    while pending:
        top = pending.pop()
        for obj in [top, *all_contents(top)]:
            for holder, target, failure in _proxies_of(obj):
                if failure is not None:
                    yield holder, target._proxy_path, failure
                    continue
                reached = target.eRoot() if through_files else None
                if reached is not None and id(reached) not in seen:
                    seen.add(id(reached))
                    pending.append(reached)


def _proxies_of(obj: EObject) -> Iterator[tuple[EObject, EProxy, str | None]]:
    """`obj`'s references to other files, each tried: (obj, proxy, why it fails or None).

    Only a module use's definition may name another file (SceML writes no other); any other
    reference that does is a failure without reading what it names.
    """
    for reference in cross_references(obj.eClass):
        held = stored(obj, reference.name)
        for target in list(held) if reference.many and held is not None else [held]:
            if not isinstance(target, EProxy):
                continue
            if not (isinstance(obj, scm.ModuleUse) and reference.name == "definition"):
                yield (
                    obj,
                    target,
                    (
                        f"{reference.name} refers to another file ({target._proxy_path!r}); only a "
                        "module use's definition may"
                    ),
                )
                continue
            try:
                target.force_resolve()
            except Exception as error:  # pyecore wraps our LoadError, or raises its own
                yield obj, target, _resolution_failure(target._proxy_path, error)
                continue
            # `#//` names the file's own root: it loads, and is no module definition.
            kind = target.eClass
            # The generated package types a reference by its Python class, which holds the EClass.
            wanted = (
                reference.eType if isinstance(reference.eType, EClass) else reference.eType.eClass
            )
            fits = kind is wanted or wanted in kind.eAllSuperTypes()
            yield (
                obj,
                target,
                None
                if fits
                else (
                    f"cannot resolve {target._proxy_path!r}: it names a {kind.name}, not a "
                    f"{wanted.name}"
                ),
            )


def broken_references(document: Document) -> list[SceMLError]:
    """Every module use of a loaded file whose definition cannot be had, located in the file.

    The file itself was read, so these are errors of its content (exit 1), not unusable input.
    """
    return [
        SceMLError(
            reason,
            file=document.file_of(holder) or document.path,
            line=document.line_of(holder),
            element=model_path(holder),
        )
        for holder, _href, reason in unresolved_references(document.root, through_files=True)
    ]


def _resolution_failure(href: str, error: BaseException) -> str:
    cause: BaseException | None = error
    while cause is not None:
        if isinstance(cause, LoadError):
            return f"cannot resolve {href!r}: {cause}"
        cause = cause.__cause__ or cause.__context__
    # The file loaded, so what failed is the fragment after '#' (KeyError, IndexError, ...).
    file, _, fragment = href.partition("#")
    return f"cannot resolve {href!r}: {file or 'this file'} has no element {fragment!r}"


def save(root: EObject, path: str | Path, *, origin: str | Path | None = None) -> Path:
    """Write a model atomically: to a temporary file beside `path`, then renamed over it.

    Cross-file references are written relative to `path`, and so is a relative map path: it is
    read relative to `origin`, the file the model (or the model it was derived from, for a
    flattened or sampled copy) was loaded from; by default the model's own file. On any failure
    the previous file, if any, is left as it was.
    """
    path = Path(path)
    resource = root.eResource
    if resource is None:
        resource_set = new_resource_set()
        resource = resource_set.create_resource(URI(str(path)))
        resource.append(root)
    _resolve_before_moving(root, resource, path)
    _refuse_unreadable_values(root, path)
    buffer = _MemoryURI(str(path))
    original_uri = resource.uri
    source = Path(origin) if origin is not None else Path(original_uri.normalize())
    moved_maps = _rebase_map_paths(root, source.parent, path.parent)
    resource.uri = URI(str(path))
    try:
        # Defaults are written out: `kind="Pedestrian"` and `value="0.0"` read better than an
        # empty element, and no reader has to know the metamodel's defaults.
        resource.save(output=buffer, options={XMIOptions.SERIALIZE_DEFAULT_VALUES: True})
    except Exception as error:
        raise SaveError(f"cannot serialise the model: {error}", file=path) from None
    finally:
        resource.uri = original_uri
        for node, original in moved_maps:
            node.map = original
    write_atomically(path, buffer.data.getvalue())
    return path


def _rebase_map_paths(
    root: EObject, old_folder: Path, new_folder: Path
) -> list[tuple[scm.RootNode, str]]:
    """Point relative OpenDRIVE map paths at the same file from the new folder, for this save.

    The model in memory keeps its own paths: the changed values are returned to be restored. A
    map that is a simulator town name (no `.xodr`) or an absolute path is left as it is.
    """
    if old_folder.resolve() == new_folder.resolve() or not isinstance(root, scm.Scenario):
        return []
    changed = []
    for node in root.nodes:
        mapped = node.map if isinstance(node, scm.RootNode) else None
        if not mapped or not mapped.lower().endswith(".xodr") or Path(mapped).is_absolute():
            continue
        target = (old_folder / mapped).resolve()
        node.map = Path(os.path.relpath(target, new_folder.resolve())).as_posix()
        changed.append((node, mapped))
    return changed


def _refuse_unreadable_values(root: EObject, path: Path) -> None:
    # pyecore would write these as "inf", "nan" or a 64-bit number, and EMF refuses to read the
    # file back; refusing here keeps a good file from being replaced by one EMF cannot open.
    for obj in [root, *root.eAllContents()]:
        for attribute in obj.eClass.eAllAttributes():
            name = attribute.eType.name
            if name not in _FLOAT_TYPES and name not in _INT_TYPES:
                continue
            value = obj.eGet(attribute)
            for item in list(value) if attribute.many else [value]:
                if item is None:
                    continue
                if name in _FLOAT_TYPES and not math.isfinite(item):
                    problem = f"{attribute.name} is {item}, which EMF cannot read"
                elif name in _INT_TYPES and not _INT_RANGE[0] <= item <= _INT_RANGE[1]:
                    problem = f"{attribute.name}={item} does not fit a 32-bit int"
                else:
                    continue
                raise SaveError(f"cannot save: {problem}", file=path, element=model_path(obj))


class _MemoryURI(URI):  # type: ignore[misc]  # pyecore is untyped
    """A URI pyecore can save into that keeps the bytes in memory, for the atomic write."""

    def __init__(self, uri: str) -> None:
        super().__init__(uri)
        self.data = _io.BytesIO()

    def create_outstream(self) -> _io.BytesIO:
        return self.data

    def close_stream(self) -> None:
        pass  # the bytes are read after pyecore is done


def _resolve_before_moving(root: EObject, resource: XMIResource, path: Path) -> None:
    # An unresolved proxy keeps its href text verbatim, which would be wrong relative to a new
    # folder; resolving it first lets pyecore write a correct relative href.
    same_folder = Path(resource.uri.normalize()).parent == path.resolve().parent
    if same_folder:
        return
    for holder, href, reason in unresolved_references(root):
        raise SaveError(
            f"cannot save into another folder: reference {href!r} does not resolve ({reason})",
            file=path,
            element=model_path(holder),
        )


def make_folder(folder: str | Path, *, target: str | Path | None = None) -> list[Path]:
    """Create `folder` and missing parents; SaveError naming `target` (default: the folder).

    Returns the folders it created, outermost first, for `remove_folders` to undo.
    """
    folder = Path(folder)
    named = Path(target) if target is not None else folder
    missing = [p for p in [folder, *folder.parents] if not p.is_dir()]
    blocking = next((p for p in missing if p.exists() or p.is_symlink()), None)
    if blocking is not None:
        raise SaveError(f"cannot write: {blocking} is a file, not a folder", file=named)
    created: list[Path] = []
    for missing_folder in reversed(missing):
        try:
            missing_folder.mkdir()
        except FileExistsError:
            continue  # made by someone else meanwhile: fine
        except OSError as error:
            remove_folders(created)
            raise SaveError(f"cannot write: {_reason(error)}", file=named) from None
        created.append(missing_folder)
    return created


def remove_folders(created: list[Path]) -> None:
    """Remove folders `make_folder` created, innermost first, where they are still empty."""
    for folder in reversed(created):
        with contextlib.suppress(OSError):
            folder.rmdir()


def _reason(error: OSError) -> str:
    return error.strerror or str(error)


def write_atomically(path: str | Path, data: bytes) -> None:
    """Write bytes to `path` through a temporary file in the same folder and an atomic rename.

    What is replaced follows the one writing rule (`sceml.safefiles.output_target`): a regular
    file, or the regular file a symbolic link names; a folder, device, FIFO or socket is refused.
    Any failure is a SaveError naming `path` (`cannot write: reason`); the previous file, if
    any, stays as it was, and neither the temporary file nor folders made for it are left.
    """
    path = Path(path)
    target = output_target(path)
    created = make_folder(target.parent, target=path)
    try:
        handle, temporary = tempfile.mkstemp(
            prefix=f".{target.name}.", suffix=".tmp", dir=target.parent
        )
    except OSError as error:
        remove_folders(created)
        raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
    try:
        with os.fdopen(handle, "wb") as stream:
            # No fsync: the rename alone guarantees readers never see a half-written file, and
            # batch export of thousands of files would pay for a disk flush on every one.
            stream.write(data)
        os.chmod(temporary, 0o644)
        os.replace(temporary, target)
    except BaseException as error:
        Path(temporary).unlink(missing_ok=True)
        remove_folders(created)
        if isinstance(error, OSError):
            raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
        raise


def write_staged(path: str | Path, data: bytes, staging: str | Path) -> None:
    """Write bytes to `path` through a file of the same name in `staging` and an atomic rename.

    For writers of many files at once (the batch's worker processes): `staging` is a private
    folder on the same file system as `path` (e.g. inside the output folder) that its owner
    creates beforehand and removes as a whole afterwards, so no temporary name has to be made
    up: one file creation and one rename. `path`'s folder must exist. What is replaced follows
    the writing rule of `write_atomically`.
    Any failure is a SaveError naming `path` (`cannot write: reason`); the previous file, if
    any, stays as it was and the staged file is removed. A process killed midway can leave a
    staged file, never a half-written `path`; removing `staging` removes that too.
    """
    path = Path(path)
    target = output_target(path)
    staged = Path(staging) / path.name
    flags = os.O_WRONLY | os.O_CREAT | os.O_TRUNC | getattr(os, "O_BINARY", 0)  # (Windows)
    try:
        handle = os.open(staged, flags, 0o644)
    except OSError as error:
        raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
    try:
        try:
            view = memoryview(data)
            while view:  # No fsync, as in write_atomically: the rename is the guarantee.
                view = view[os.write(handle, view) :]
        finally:
            os.close(handle)
        os.chmod(staged, 0o644)  # as write_atomically leaves a file, whatever the umask
        os.replace(staged, target)
    except BaseException as error:
        staged.unlink(missing_ok=True)
        if isinstance(error, OSError):
            raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
        raise
