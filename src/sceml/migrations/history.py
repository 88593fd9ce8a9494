"""The releases of the metamodel, the steps between them, and bringing an old file up to date.

The folder laid out as in the source tree: `scemlmodel.ecore` (the current metamodel),
`history/<version>/scemlmodel.ecore` (each release as it was released), and
`migrations/<from>-to-<to>.yaml` (one step per release).
"""

from __future__ import annotations

import importlib.resources
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from lxml import etree

from ..errors import LoadError
from . import ecore
from .compat import BreakingChange, breaking_changes
from .ecore import Metamodel, release_of, version_key
from .report import Report
from .steps import Step, read_step
from .tree import TreeModel

RELEASE_ANNOTATION = "http://sceml.org/release"


@dataclass(frozen=True)
class History:
    folder: Path

    @property
    def current(self) -> Metamodel:
        return ecore.read(self.folder / "scemlmodel.ecore")

    def releases(self) -> dict[str, Metamodel]:
        """Every kept release, oldest first."""
        found = {
            path.parent.name: ecore.read(path)
            for path in (self.folder / "history").glob("*/scemlmodel.ecore")
        }
        return dict(sorted(found.items(), key=lambda item: version_key(item[0])))

    def steps(self) -> dict[str, Step]:
        """Each step by the release it starts from."""
        steps = [read_step(p) for p in sorted((self.folder / "migrations").glob("*.yaml"))]
        return {step.from_release: step for step in steps}

    def chain(self, version: str) -> list[Step]:
        """The steps from release `version` to the current one, in order."""
        steps = self.steps()
        target = self.current.version
        chain = []
        while version != target:
            step = steps.get(version)
            if step is None:
                raise LoadError(
                    f"no migration from metamodel release {version} "
                    f"(metamodel/migrations/ has none starting there)",
                    file=self.folder,
                )
            chain.append(step)
            version = step.to_release
        return chain

    def metamodel_of(self, version: str) -> Metamodel:
        if version == self.current.version:
            return self.current
        release = self.releases().get(version)
        if release is None:
            raise LoadError(
                f"metamodel release {version} is not kept in history/", file=self.folder
            )
        return release


@cache
def installed() -> History:
    """The history shipped with this SceML (the `metamodel/` folder of the source tree)."""
    return History(Path(str(importlib.resources.files("sceml.metamodel"))))


def upgrade(tree: etree._ElementTree, path: Path, history: History | None = None) -> Report | None:
    """Bring a parsed file saved with an older release to the current one, in place.

    Returns what was done, or None when the file is of the current release or not a SceML file
    at all (the loader says what it is). A release newer than this SceML's, or one it does not
    know, is a LoadError naming the file.
    """
    history = history or installed()
    root = tree.getroot()
    model_root = root if etree.QName(root).localname != "XMI" else next(iter(root), None)
    if model_root is None:
        return None
    namespace = etree.QName(model_root).namespace or ""
    current = history.current
    version = release_of(namespace)
    if namespace == current.ns_uri or version is None:
        return None
    if namespace.rpartition("/")[0] != current.ns_uri.rpartition("/")[0]:
        return None
    if version_key(version) > version_key(current.version):
        raise LoadError(
            f"saved with SceML metamodel release {version}, newer than this SceML's "
            f"{current.version}: update SceML to read it",
            file=path,
            line=model_root.sourceline,
        )
    if version not in history.releases():
        raise LoadError(
            f"saved with SceML metamodel release {version}, which no SceML released "
            f"(known: {', '.join(history.releases())})",
            file=path,
            line=model_root.sourceline,
        )
    report = Report(_shown(path), version, current.version)
    for step in history.chain(version):
        model = TreeModel.of(model_root, history.metamodel_of(step.from_release))
        report.changes.extend(step.apply(model))
    model_root = _rename_namespace(tree, model_root, namespace, current.ns_uri)
    return report


def _rename_namespace(
    tree: etree._ElementTree, model_root: etree._Element, old: str, new: str
) -> etree._Element:
    """Rebuild the model root with the new namespace under the same prefix; children move over.

    lxml cannot change a namespace declaration in place; moving the children keeps them (and the
    lines they were read from).
    """
    nsmap = {prefix: (new if uri == old else uri) for prefix, uri in model_root.nsmap.items()}
    replacement = etree.Element(
        etree.QName(new, etree.QName(model_root).localname).text, nsmap=nsmap
    )
    for key, value in model_root.attrib.items():
        replacement.set(key, value)
    replacement.extend(list(model_root))
    replacement.sourceline = model_root.sourceline
    parent = model_root.getparent()
    if parent is None:
        tree._setroot(replacement)
    else:
        parent.replace(model_root, replacement)
    return replacement


@dataclass(frozen=True)
class ReleaseCheck:
    """What `sceml dev check-release` found: problems stop CI, notes only inform."""

    current: str
    last_release: str
    problems: list[str]
    notes: list[str]


def check_release(history: History | None = None) -> ReleaseCheck:
    """Compare the current metamodel with the last kept release and its migration step.

    A breaking change is a problem unless the current release is newer than the last one and the
    step from the last one covers it; additive changes pass.
    """
    history = history or installed()
    current = history.current
    releases = history.releases()
    problems: list[str] = []
    notes: list[str] = []
    recorded = _recorded_version(current.path)
    if recorded != current.version:
        problems.append(
            f"the package records release {recorded!r} ({RELEASE_ANNOTATION}) but its nsURI says "
            f"{current.version!r}"
        )
    older = [v for v in releases if version_key(v) <= version_key(current.version)]
    if not older:
        problems.append("metamodel/history/ keeps no release up to the current one")
        return ReleaseCheck(current.version, "", problems, notes)
    last = older[-1]
    last_metamodel = releases[last]
    newer = [v for v in releases if version_key(v) > version_key(current.version)]
    if newer:
        problems.append(f"history/ keeps release {newer[0]}, newer than the current .ecore")
    if last == current.version:
        for change in breaking_changes(last_metamodel, current):
            problems.append(
                f"{change.describe()}: files saved with release {last} would no longer load; "
                f"raise the release in the nsURI and add metamodel/migrations/{last}-to-"
                f"<next>.yaml with the operation that migrates it"
            )
        return ReleaseCheck(current.version, last, problems, notes)
    step = history.steps().get(last)
    if step is None or step.to_release != current.version:
        problems.append(
            f"no migration step from release {last} to {current.version} "
            f"(metamodel/migrations/{last}-to-{current.version}.yaml)"
        )
        return ReleaseCheck(current.version, last, problems, notes)
    problems.extend(step.problems(last_metamodel, current))
    for change in breaking_changes(last_metamodel, current, step.renamed_classes()):
        if not any(op.covers(change, last_metamodel) for op in step.operations):
            problems.append(
                f"{change.describe()} since release {last}, and {step.source.name} has no "
                f"operation that migrates it"
            )
    if current.version not in releases:
        notes.append(
            f"release {current.version} is not kept in metamodel/history/ yet "
            f"(sceml dev release keeps it)"
        )
    return ReleaseCheck(current.version, last, problems, notes)


def _recorded_version(path: Path) -> str | None:
    root = etree.parse(str(path)).getroot()
    for annotation in root.iterchildren("eAnnotations"):
        if annotation.get("source") == RELEASE_ANNOTATION:
            for detail in annotation.iterchildren("details"):
                if detail.get("key") == "version":
                    value: str | None = detail.get("value")
                    return value
    return None


def breaking_since(history: History, version: str) -> list[BreakingChange]:
    """The breaking changes from a kept release to the current metamodel (for the docs)."""
    step = history.steps().get(version)
    renamed = step.renamed_classes() if step else {}
    return breaking_changes(history.releases()[version], history.current, renamed)


def _shown(path: Path) -> Path:
    """A path as a person would type it: relative to the working folder when inside it."""
    try:
        return Path(path).resolve().relative_to(Path.cwd())
    except ValueError:
        return Path(path)
