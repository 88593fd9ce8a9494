"""Keeping a release of the metamodel in `metamodel/history/<version>/` (`sceml dev release`)."""

from __future__ import annotations

import shutil
from pathlib import Path

from ..errors import SceMLError
from ..migrations import ecore

#: What is exported from each concrete example when a release is kept: (version, profile).
EXPORTS = (("1.0", "generic"), ("1.3", "generic"), ("1.0", "carla"))


def keep_release(root: Path) -> Path:
    """Copy the current release's metamodel and material into the history; the new folder."""
    from ..export.writer import ExportError, export_to_file
    from ..model.loading import load_scenario

    current = ecore.read(root / "metamodel" / "scemlmodel.ecore")
    folder = root / "metamodel" / "history" / current.version
    if folder.exists():
        raise SceMLError(f"release {current.version} is kept already", file=folder)
    try:
        (folder / "examples" / "library").mkdir(parents=True)
        (folder / "maps").mkdir()
        (folder / "exports").mkdir()
        shutil.copyfile(current.path, folder / "scemlmodel.ecore")
        for example in sorted((root / "examples").glob("*.xmi")):
            shutil.copyfile(example, folder / "examples" / example.name)
        for library in sorted((root / "examples" / "library").glob("*.xmi")):
            shutil.copyfile(library, folder / "examples" / "library" / library.name)
        shutil.copyfile(root / "maps" / "intersection.xodr", folder / "maps" / "intersection.xodr")
        for example in sorted((folder / "examples").glob("*-concrete.xmi")):
            document = load_scenario(example)
            for version, profile in EXPORTS:
                suffix = version if profile == "generic" else profile
                target = folder / "exports" / f"{example.stem}-{suffix}.xosc"
                try:
                    export_to_file(
                        document.root, target, version=version, profile=profile, source_path=example
                    )
                except ExportError:
                    continue  # that version or profile cannot say this example: nothing to keep
    except BaseException:
        shutil.rmtree(folder, ignore_errors=True)
        raise
    return folder
