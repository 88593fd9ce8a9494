"""What migration needs of an `.ecore`: its release, classes, features and enums, read with lxml.

Reading the XML directly (rather than building pyecore's dynamic metamodel) keeps loading an old
file cheap and lets two releases of the same package be compared side by side.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from lxml import etree

from ..errors import LoadError
from ..files.safexml import hardened_parser

_XSI_TYPE = "{http://www.w3.org/2001/XMLSchema-instance}type"
_ECORE_TYPE = re.compile(r"#//(\w+)$")
#: The nsURI of every SceML release ends in its version: https://sceml.org/metamodel/<version>.
RELEASE_URI = re.compile(r"^(?P<base>.*/metamodel/)(?P<version>\d+(\.\d+)*)$")


@dataclass(frozen=True)
class Feature:
    """One structural feature as the file format sees it."""

    name: str
    kind: str  # "attribute" or "reference"
    type: str  # the classifier's name: a class, an enum or an Ecore data type (EDouble, ...)
    lower: int = 0
    upper: int = 1  # -1: many
    containment: bool = False
    transient: bool = False
    default: str | None = None

    @property
    def many(self) -> bool:
        return self.upper != 1

    def describe(self) -> str:
        bounds = f"[{self.lower}..{'*' if self.upper == -1 else self.upper}]"
        role = "containment " if self.containment else ""
        return f"{role}{self.kind} of {self.type} {bounds}"


@dataclass
class EClassInfo:
    name: str
    abstract: bool
    supertypes: tuple[str, ...]
    own: dict[str, Feature] = field(default_factory=dict)


@dataclass
class Metamodel:
    """One release of the SceML package, as read from its `.ecore`."""

    path: Path
    ns_uri: str
    prefix: str
    classes: dict[str, EClassInfo]
    enums: dict[str, tuple[str, ...]]

    @property
    def version(self) -> str:
        return release_of(self.ns_uri) or "?"

    def ancestors(self, name: str) -> list[str]:
        """`name` and every class it inherits from, nearest first."""
        seen: list[str] = []
        pending = [name]
        while pending:
            current = pending.pop(0)
            if current in seen or current not in self.classes:
                continue
            seen.append(current)
            pending.extend(self.classes[current].supertypes)
        return seen

    def is_kind_of(self, name: str, ancestor: str) -> bool:
        return ancestor in self.ancestors(name)

    def features(self, name: str) -> dict[str, Feature]:
        """Every feature of class `name`, inherited ones included."""
        found: dict[str, Feature] = {}
        for cls in reversed(self.ancestors(name)):
            found.update(self.classes[cls].own)
        return found

    def feature(self, cls: str, name: str) -> Feature | None:
        return self.features(cls).get(name)


def release_of(ns_uri: str) -> str | None:
    """The release version an nsURI names (`https://sceml.org/metamodel/1.0` -> `1.0`)."""
    found = RELEASE_URI.match(ns_uri)
    return found.group("version") if found else None


def version_key(version: str) -> tuple[int, ...]:
    return tuple(int(part) for part in version.split("."))


def read(path: Path) -> Metamodel:
    """Read an `.ecore` file; LoadError names the file when it is not an Ecore package."""
    path = Path(path).resolve()
    try:
        stamp = path.stat()
    except OSError as error:
        raise LoadError(f"cannot read the metamodel: {error.strerror}", file=path) from None
    # Read once per version of the file: the releases do not change while a command runs,
    # but a developer's edited .ecore (and the tests' copies) must be read afresh.
    return _read(path, stamp.st_mtime_ns, stamp.st_size)


@cache
def _read(path: Path, mtime: int, size: int) -> Metamodel:
    try:
        root = etree.parse(str(path), parser=hardened_parser(drop_comments=True)).getroot()
    except (OSError, etree.XMLSyntaxError) as error:
        raise LoadError(f"cannot read the metamodel: {error}", file=path) from None
    if etree.QName(root).localname != "EPackage" or root.get("nsURI") is None:
        raise LoadError("not an Ecore package (no EPackage with an nsURI)", file=path)
    classes: dict[str, EClassInfo] = {}
    enums: dict[str, tuple[str, ...]] = {}
    for classifier in root.iterchildren("eClassifiers"):
        kind = classifier.get(_XSI_TYPE, "").rpartition(":")[2]
        name = classifier.get("name", "")
        if kind == "EEnum":
            enums[name] = tuple(
                literal.get("name", "") for literal in classifier.iterchildren("eLiterals")
            )
        elif kind == "EClass":
            supertypes = tuple(
                _type_name(reference) for reference in (classifier.get("eSuperTypes") or "").split()
            )
            info = EClassInfo(name, classifier.get("abstract") == "true", supertypes)
            for element in classifier.iterchildren("eStructuralFeatures"):
                info.own[element.get("name", "")] = _feature(element)
            classes[name] = info
    return Metamodel(path, root.get("nsURI", ""), root.get("nsPrefix", ""), classes, enums)


def _feature(element: etree._Element) -> Feature:
    kind = element.get(_XSI_TYPE, "").rpartition(":")[2]
    return Feature(
        name=element.get("name", ""),
        kind="reference" if kind == "EReference" else "attribute",
        type=_type_name(element.get("eType", "")),
        lower=int(element.get("lowerBound", "0")),
        upper=int(element.get("upperBound", "1")),
        containment=element.get("containment") == "true",
        transient=element.get("transient") == "true",
        default=element.get("defaultValueLiteral"),
    )


def _type_name(reference: str) -> str:
    found = _ECORE_TYPE.search(reference)
    return found.group(1) if found else reference
