"""Regenerate `generated/` from `metamodel/*.ecore` with the pinned pyecoregen (sceml.dev.generator),
and the catalog's facts beside it (sceml.model.ecore_facts)."""

from __future__ import annotations

import filecmp
import shutil
import tempfile
from pathlib import Path

from ..errors import SceMLError


def project_root() -> Path:
    """The source checkout this package runs from (an editable install), found by its layout."""
    here = Path(__file__).resolve()
    for candidate in here.parents:
        if (candidate / "metamodel").is_dir() and (candidate / "generated").is_dir():
            return candidate
    raise SceMLError("not running from a source checkout; pass --root")


def _generate_into(ecore: Path, out: Path) -> None:
    from pyecore.resources import URI, ResourceSet

    from ..model.ecore_facts import MODULE_FILE, facts_module, read_facts
    from .generator import StaticFeaturesGenerator

    package = ResourceSet().get_resource(URI(str(ecore))).contents[0]
    StaticFeaturesGenerator(auto_register_package=False).generate(package, str(out))
    # What the catalog reads of the .ecore, as literals it loads without parsing the file.
    facts = facts_module(read_facts(ecore.read_bytes()))
    (out / str(package.name) / MODULE_FILE).write_text(facts, encoding="utf-8")


def generate(root: Path, *, check: bool = False) -> list[str]:
    """Generate every .ecore of `root/metamodel` into `root/generated`.

    With `check`, nothing is written and the relative paths of files that differ are returned.
    """
    try:
        import pyecoregen  # noqa: F401
    except ImportError:
        raise SceMLError("pyecoregen is not installed; run `pip install -e .[generate]`") from None
    target = root / "generated"
    with tempfile.TemporaryDirectory() as scratch:
        fresh = Path(scratch)
        for ecore in sorted((root / "metamodel").glob("*.ecore")):
            _generate_into(ecore, fresh)
        differences = _differences(fresh, target)
        if not check and differences:
            for name in differences:
                source, destination = fresh / name, target / name
                if source.exists():
                    destination.parent.mkdir(parents=True, exist_ok=True)
                    shutil.copyfile(source, destination)
                else:
                    destination.unlink()
        return differences


def _files(folder: Path) -> set[str]:
    if not folder.is_dir():
        return set()
    return {
        str(p.relative_to(folder))
        for p in folder.rglob("*")
        if p.is_file() and "__pycache__" not in p.parts
    }


def _differences(fresh: Path, committed: Path) -> list[str]:
    names = _files(fresh) | _files(committed)
    return sorted(
        name
        for name in names
        if not (fresh / name).exists()
        or not (committed / name).exists()
        or not filecmp.cmp(fresh / name, committed / name, shallow=False)
    )
