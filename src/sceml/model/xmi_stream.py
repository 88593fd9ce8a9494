"""Read a SceML file while lxml parses it, freeing each top-level element once its objects exist.

A parsed tree of a large scenario takes about as much memory as the model made from it, and
the whole-tree reader keeps it until the last object is made, so the two add up at the peak.
Here lxml's `iterparse` hands over each child of the root element (a node, a flow, a module)
once it is complete; `sceml.model.xmi_reader` makes its objects, and the element is cleared
and dropped from the tree before the next one is parsed.

Only the files the whole-tree path would read without a word are read this way: a current
release's model root, namespace prefixes declared on the root element alone, every xsi:type a
concrete SceML class, no repeated xmi:id, no DTD, nothing the reader declines. On anything else
`decode` returns False having changed nothing the whole-tree path does not set again, and the
caller parses the file again and goes the usual way (migration, pyecore's decoder), which gives
the usual errors and lines.
"""

from __future__ import annotations

import io
from collections.abc import Callable
from typing import Any

from lxml import etree
from pyecore.ecore import EObject

import scemlmodel as scm

from ..files.safexml import hardened_iterparse, has_dtd
from .traversal import features
from .xmi_reader import XSI_TYPE, CheckLiteral, _Declined, _Plan, _Reader

TypeProblem = Callable[[str, tuple[tuple[str | None, str], ...]], str | None]

# The elements a root may hold: the features of a Scenario or a Library. A child of the root
# with another tag is not handed over; it is found still in the tree, and the file declined.
_TOP_LEVEL = tuple(
    sorted(
        {feature.name for cls in (scm.Scenario, scm.Library) for feature in features(cls.eClass)}
    )
)


def decode(
    resource: Any, data: bytes, check_literal: CheckLiteral, type_problem: TypeProblem
) -> bool:
    """Build the read-only model of the XML document `data` into `resource` as it is parsed;
    False if declined (then nothing the caller keeps was changed).

    `resource` is a fresh SafeXMIResource; `type_problem(xsi_type, prefixes)` says what is
    wrong with an xsi:type, or None.
    """
    if resource.contents or resource.uuid_dict:
        return False
    stream = _Stream(resource, data, check_literal, type_problem)
    try:
        root = stream.run()
    except Exception:  # _Declined, a syntax error, a file this reader was not written for
        return False
    assert stream.reader is not None
    stream.reader.commit(root, None)
    return True


class _Stream:
    """One reading of one document."""

    def __init__(
        self, resource: Any, data: bytes, check_literal: CheckLiteral, type_problem: TypeProblem
    ) -> None:
        self.resource = resource
        self.data = data
        self.check_literal = check_literal
        self.type_problem = type_problem
        self.reader: _Reader | None = None
        self.prefixes: tuple[tuple[str | None, str], ...] = ()
        self.ids: set[str] = set()
        # The xsi:type texts found fine: a file repeats a few dozen of them thousands of times.
        self.fine_types: set[str] = set()

    def run(self) -> EObject:
        events = hardened_iterparse(
            io.BytesIO(self.data), events=("end",), tag=_TOP_LEVEL, drop_comments=True
        )
        xmlroot: etree._Element | None = None
        root: EObject | None = None
        plan: _Plan | None = None
        last: etree._Element | None = None  # the element handed over before, cleared
        for _event, element in events:
            parent = element.getparent()
            if xmlroot is None:
                xmlroot = element.getroottree().getroot()
                root, plan = self._start(xmlroot)
            if parent is not xmlroot:
                continue  # a deeper element of the same name, read with its top-level element
            previous = element.getprevious()
            if previous is not last:
                raise _Declined  # an element between the two that was not handed over
            self._check(element)
            self.reader.walk((element,), root, plan)  # type: ignore[union-attr, arg-type]
            # The iterparse idiom: clear the element now, drop it from the tree once the next
            # one is done (the parser may still be writing to the element it just ended).
            element.clear()
            if previous is not None:
                del xmlroot[0]
            last = element
        if xmlroot is None:
            xmlroot = events.root
            root, plan = self._start(xmlroot)
        if len(xmlroot) != (last is not None) or has_dtd(xmlroot.getroottree()):
            raise _Declined
        assert self.reader is not None and root is not None
        self.reader.finish(root)
        return root

    def _start(self, xmlroot: etree._Element) -> tuple[EObject, _Plan]:
        # What the whole-tree path checks and sets up before decoding (`_check_tree`,
        # `_migrate_if_older`, `SafeXMIResource._decode_tree`).
        if etree.QName(xmlroot).namespace != scm.nsURI:
            raise _Declined  # another release (migrated first) or not a SceML model
        nsmap = xmlroot.nsmap
        if self.data.count(b"xmlns") != len(nsmap):
            raise _Declined  # a prefix declared below the root, or a text naming xmlns
        self.prefixes = tuple(sorted(nsmap.items(), key=str))
        resource = self.resource
        resource.options = {}
        resource.cache_enabled = True
        resource.prefixes.update(nsmap)
        resource.reverse_nsmap = {v: k for k, v in resource.prefixes.items()}
        xsi, xmi = resource.prefixes.get("xsi"), resource.prefixes.get("xmi")
        resource.xsitype = f"{{{xsi}}}type"
        resource.xmiid = f"{{{xmi}}}id"
        resource.schema_tag = f"{{{xsi}}}schemaLocation"
        resource.schema_locations = {}
        if resource.xsitype != XSI_TYPE:
            raise _Declined
        self.reader = _Reader(resource, self.check_literal, read_only=True)
        self._check(xmlroot, deep=False)
        return self.reader.start(xmlroot)

    def _check(self, top: etree._Element, deep: bool = True) -> None:
        # `_check_types_and_ids` of the whole-tree path, one top-level element at a time.
        xmiid = self.resource.xmiid
        prefixes = self.prefixes
        type_problem = self.type_problem
        ids = self.ids
        fine_types = self.fine_types
        for element in top.iter(etree.Element) if deep else (top,):
            value = element.get(XSI_TYPE)
            if value is not None and value not in fine_types:
                if type_problem(value, prefixes) is not None:
                    raise _Declined
                fine_types.add(value)
            identifier = element.get(xmiid)
            if identifier is not None:
                if identifier in ids:
                    raise _Declined
                ids.add(identifier)
