"""What every XML reader of SceML shares: a size limit, a hardened parser, and refusing DTDs.

Scenario and library XMI (`sceml.model`), OpenSCENARIO files (`sceml.xosc.schema`), OpenDRIVE maps
(`sceml.maps`), and the XML SceML makes itself (the export's text, Graphviz's SVG) are all parsed
with `hardened_parser`: it is the only place that builds an lxml parser. Each reader keeps its
own error types and messages.
"""

from __future__ import annotations

import codecs
import os
from typing import Any

from lxml import etree

from ..errors import LoadError

#: Files larger than this (64 MiB) are refused before parsing; a 50,000-node scenario is ~15 MB.
DEFAULT_MAX_BYTES = 64 * 1024 * 1024

#: Environment variable that overrides DEFAULT_MAX_BYTES (a whole number of bytes).
MAX_BYTES_VARIABLE = "SCEML_MAX_BYTES"


def max_bytes_limit() -> int:
    """The file size limit in bytes: $SCEML_MAX_BYTES if set, else DEFAULT_MAX_BYTES."""
    given = os.environ.get(MAX_BYTES_VARIABLE, "").strip()
    if not given:
        return DEFAULT_MAX_BYTES
    if not given.isdigit() or int(given) == 0:
        raise LoadError(f"{MAX_BYTES_VARIABLE}={given!r} is not a positive whole number of bytes")
    return int(given)


def size_problem(size: int, limit: int) -> str | None:
    """Why a file of `size` bytes is refused under `limit`, in the units the docs use; or None."""
    if size <= limit:
        return None
    return (
        f"file is {_amount(size)}, above the {_amount(limit, single=True)} limit "
        f"(set {MAX_BYTES_VARIABLE} to change it)"
    )


def _amount(size: int, single: bool = False) -> str:
    if size < 2**20:
        return f"{size}-byte" if single else f"{size} bytes"
    return f"{size / 2**20:.1f}".removesuffix(".0") + " MiB"


def hardened_parser(
    *, drop_comments: bool = False, drop_blank_text: bool = False
) -> etree.XMLParser:
    """A parser with DTDs, entities and network access off.

    No file kind SceML reads needs them, and they are how billion-laughs and XXE attacks get in.
    A fresh parser per call: lxml parsers must not be shared between threads, and one costs
    microseconds. `drop_comments` also drops comments and processing instructions (pyecore
    cannot decode them); `drop_blank_text` drops whitespace-only text, so that a tree
    pretty-prints with consistent indentation.
    """
    return etree.XMLParser(**_hardened_options(drop_comments, drop_blank_text))


def hardened_iterparse(
    source: Any, *, events: tuple[str, ...], tag: tuple[str, ...], drop_comments: bool = False
) -> etree.iterparse:
    """lxml's `iterparse` over `source` with `hardened_parser`'s options: for a reader that
    frees each part of a large document once it has read it (`sceml.model.xmi_stream`)."""
    return etree.iterparse(
        source, events=events, tag=tag, **_hardened_options(drop_comments, False)
    )


def _hardened_options(drop_comments: bool, drop_blank_text: bool) -> dict[str, bool]:
    return {
        "resolve_entities": False,
        "no_network": True,
        "load_dtd": False,
        "dtd_validation": False,
        "huge_tree": False,
        "remove_comments": drop_comments,
        "remove_pis": drop_comments,
        "remove_blank_text": drop_blank_text,
    }


def doctype_line(data: bytes) -> int | None:
    """The line of a DOCTYPE in the document's prolog, or None; read before parsing.

    A linear scan rather than a regex, so a hostile prolog cannot make it backtrack, and it stops
    at the root element, so large documents cost nothing extra. UTF-16 is re-encoded first (its
    newlines survive, so the line stays right); encodings it cannot read are caught after parsing
    by `has_dtd`.
    """
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        data = data.decode("utf-16", errors="replace").encode("utf-8")
    i = len(codecs.BOM_UTF8) if data.startswith(codecs.BOM_UTF8) else 0
    n = len(data)
    while i < n:
        if data[i] in b" \t\r\n":
            i += 1
        elif data.startswith(b"<?", i):
            end = data.find(b"?>", i + 2)
            if end < 0:
                return None
            i = end + 2
        elif data.startswith(b"<!--", i):
            end = data.find(b"-->", i + 4)
            if end < 0:
                return None
            i = end + 3
        elif data.startswith(b"<!DOCTYPE", i):
            return data.count(b"\n", 0, i) + 1
        else:
            return None
    return None


def has_dtd(tree: etree._ElementTree) -> bool:
    """Whether a parsed document declares a DTD (the parser did not expand it)."""
    return bool(tree.docinfo.doctype) or tree.docinfo.internalDTD is not None
