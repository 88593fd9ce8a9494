"""Reading SceML XMI safely: a hardened parse, checked values and types, and locations."""

from __future__ import annotations

import contextlib
import io as _io
import re
from collections.abc import Iterator
from functools import lru_cache
from pathlib import Path
from typing import Any

from lxml import etree
from pyecore.ecore import EAttribute, EClass, EEnum, EObject, EReference
from pyecore.resources import URI
from pyecore.resources.xmi import XMIOptions, XMIResource

import scemlmodel as scm

from ..errors import LoadError
from ..files.safefiles import (
    read_input,
)
from ..files.safexml import (
    doctype_line,
    hardened_parser,
    has_dtd,
)
from . import xmi_reader, xmi_stream
from .collector import collector_paused
from .locating import line_in
from .traversal import all_contents

# Deeper documents are refused by libxml2 itself (its limit without huge_tree is 256 levels), so
# pyecore's recursive decoder never sees more than that and cannot overflow Python's stack.

_LINE_IN_MESSAGE = re.compile(r"line (\d+)")
# pyecore names a package by its Python repr, which shows the install path; keep the name only.
_MODULE_REPR = re.compile(r"<module '([\w.]+)' from '[^']*'>")

# EMF's own number syntax, minus what it alone accepts (hex floats, a trailing d or f): Python's
# float() would also take "1_000", "inf" and "nan", which EMF refuses when it reads the file back.
_DECIMAL = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")
_INTEGER = re.compile(r"[+-]?\d+")
INT_RANGE = (-(2**31), 2**31 - 1)  # EInt is a Java int
FLOAT_TYPES = frozenset({"EDouble", "EDoubleObject", "EFloat", "EFloatObject"})
INT_TYPES = frozenset({"EInt", "EIntegerObject", "EShort", "EShortObject", "EByte", "EByteObject"})
BOOLEAN_TYPES = frozenset({"EBoolean", "EBooleanObject"})


def parse_xml_safely(path: Path, max_bytes: int | None = None) -> etree._ElementTree:
    """Parse an XML file with every dangerous feature off; LoadError names the file and line.

    Read by the one reading rule (`sceml.files.safefiles.read_input`): a regular file of at most
    `max_bytes` (default: `max_bytes_limit()`); a larger file is refused before it is read.
    """
    return _parse(_read_xml(path, max_bytes), path)


def _read_xml(path: Path, max_bytes: int | None) -> bytes:
    """The bytes of an XML file, refused (LoadError) if unreadable or if it declares a DTD."""
    try:
        data = read_input(path, max_bytes=max_bytes)
    except FileNotFoundError:
        raise LoadError("no such file", file=path) from None
    except OSError as error:
        raise LoadError(f"cannot read file: {error.strerror}", file=path) from None
    line = doctype_line(data)
    if line is not None:
        raise LoadError("DTDs and entity declarations are not accepted", file=path, line=line)
    return data


def _parse(data: bytes, path: Path) -> etree._ElementTree:
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

    Files are decoded by `sceml.model.xmi_reader`, which builds the objects directly; what it declines
    goes through pyecore's decoder (`fast_decoding = False` makes every file take that path). In
    a resource set made `read_only`, the reader makes `sceml.model.lightobjects`' objects.
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
        data = _read_xml(path, getattr(resource_set, "sceml_max_bytes", None))
        # iD attribute values seen so far: EMF fragments name elements by them, so they must be
        # unique per file (ModuleDefinition.name is one).
        self._sceml_ids: dict[tuple[str, str], tuple[EObject, int | None]] = {}
        if self._streamed(data):
            return
        tree = _parse(data, path)
        del data
        self.sceml_migration = _migrate_if_older(tree, path)
        _check_tree(tree, path)
        self.sceml_tree = tree
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

    def _streamed(self, data: bytes) -> bool:
        # A read-only load of a plain current file is read while it is parsed, each part of the
        # tree freed once read (sceml.model.xmi_stream); anything else is parsed whole below.
        if not (self.fast_decoding and getattr(self.resource_set, "sceml_read_only", False)):
            return False
        try:
            with collector_paused():
                streamed = xmi_stream.decode(self, data, _check_literal, _type_problem_of)
        finally:
            self._clean_registers()
        if streamed:
            self.sceml_migration = None
            self.sceml_tree = None
        return streamed

    def _keep_lines(self, tree: etree._ElementTree) -> None:
        # Where each object was written is all that is needed of the parse tree later; the tree
        # itself is dropped (about a quarter of a large model's memory). The fast reader notes
        # the lines as it goes; pyecore's decoder leaves them to be read off the tree.
        if getattr(self, "sceml_lines", None) is None:
            self.sceml_lines = {
                obj: line_in(self, obj)
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
        read_only = getattr(self.resource_set, "sceml_read_only", False)
        if self.fast_decoding and xmi_reader.decode(self, xmlroot, _check_literal, read_only):
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
                    line_in(self, holder),
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
    from .. import migrations

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
        elif name in FLOAT_TYPES:
            if not _DECIMAL.fullmatch(word):
                raise ValueError(f"{attribute.name}={word!r} is not a finite decimal number")
        elif name in INT_TYPES:
            if not _INTEGER.fullmatch(word):
                raise ValueError(f"{attribute.name}={word!r} is not a whole number")
            if not INT_RANGE[0] <= int(word) <= INT_RANGE[1]:
                raise ValueError(f"{attribute.name}={word} does not fit a 32-bit int")
        elif name in BOOLEAN_TYPES and word.lower() not in ("true", "false"):
            raise ValueError(f"{attribute.name}={word!r} is neither true nor false")


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
