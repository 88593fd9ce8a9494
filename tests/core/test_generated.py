"""generated/ is exactly what pyecoregen makes of metamodel/, and a hand edit is caught."""

from __future__ import annotations

import shutil
from pathlib import Path

from sceml.dev.regenerate import generate

REPO = Path(__file__).resolve().parents[2]


def copy_of_sources(tmp_path: Path) -> Path:
    root = tmp_path / "checkout"
    shutil.copytree(REPO / "metamodel", root / "metamodel")
    shutil.copytree(
        REPO / "generated", root / "generated", ignore=shutil.ignore_patterns("__pycache__")
    )
    return root


def test_committed_generated_code_matches_a_fresh_generation(tmp_path: Path) -> None:
    assert generate(copy_of_sources(tmp_path), check=True) == []


def test_a_hand_edit_of_generated_code_is_detected(tmp_path: Path) -> None:
    root = copy_of_sources(tmp_path)
    module = root / "generated" / "scemlmodel" / "scemlmodel.py"
    module.write_text(module.read_text() + "\n# tweaked by hand\n")
    assert generate(root, check=True) == ["scemlmodel/scemlmodel.py"]


def test_regeneration_repairs_a_hand_edit(tmp_path: Path) -> None:
    root = copy_of_sources(tmp_path)
    module = root / "generated" / "scemlmodel" / "scemlmodel.py"
    original = module.read_bytes()
    module.write_text("broken")
    (root / "generated" / "scemlmodel" / "stray.py").write_text("x = 1\n")
    generate(root)
    assert module.read_bytes() == original
    assert not (root / "generated" / "scemlmodel" / "stray.py").exists()
    assert generate(root, check=True) == []
