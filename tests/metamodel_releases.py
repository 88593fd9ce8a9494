"""Test helpers for metamodel releases: copies of metamodel/ in which tests make releases of
their own, and loading a file the way an EMF tool with a given .ecore would (plain pyecore)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from lxml import etree
from pyecore.resources import URI, ResourceSet

from sceml.migrations import History

REPO = Path(__file__).resolve().parents[1]
METAMODEL = REPO / "metamodel"
HISTORY_10 = METAMODEL / "history" / "1.0"
#: The repository's current release, and the one a test's own next release is.
CURRENT = History(METAMODEL).current.version
NEXT = f"{CURRENT.split('.')[0]}.{int(CURRENT.split('.')[1]) + 1}"


def next_release(
    folder: Path, edit: Callable[[str], str], migration: str | None, version: str = NEXT
) -> History:
    """Edit the copy's .ecore into release `version` and add the migration step to it."""
    history = History(folder)
    old = history.current.version
    ecore = folder / "scemlmodel.ecore"
    text = edit(ecore.read_text(encoding="utf-8"))
    text = text.replace(f'/metamodel/{old}"', f'/metamodel/{version}"', 1)
    text = text.replace(f'key="version" value="{old}"', f'key="version" value="{version}"', 1)
    ecore.write_text(text, encoding="utf-8")
    if migration is not None:
        (folder / "migrations" / f"{old}-to-{version}.yaml").write_text(
            f'from: "{old}"\nto: "{version}"\n{migration}', encoding="utf-8"
        )
    return History(folder)


def edit_ecore(folder: Path, edit: Callable[[str], str]) -> History:
    """Edit the copy's .ecore without a new release."""
    ecore = folder / "scemlmodel.ecore"
    ecore.write_text(edit(ecore.read_text(encoding="utf-8")), encoding="utf-8")
    return History(folder)


def load_with_ecore(ecore: Path, xmi: Path) -> object:
    """Load `xmi` with plain pyecore and the metamodel read from `ecore` (not the generated
    classes): what an EMF tool with that .ecore would see."""
    resources = ResourceSet()
    package = resources.get_resource(URI(str(ecore))).contents[0]
    resources.metamodel_registry[package.nsURI] = package
    return resources.get_resource(URI(str(xmi))).contents[0]


def migrated_copy(source: Path, target: Path, history: History) -> tuple[Path, object]:
    """Migrate `source` with `history` as the loader does and write the tree to `target`."""
    from sceml.migrations import upgrade

    tree = etree.parse(str(source))
    report = upgrade(tree, source, history)
    target.write_bytes(etree.tostring(tree, xml_declaration=True, encoding="UTF-8"))
    return target, report
