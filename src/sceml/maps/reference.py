"""Which map a scenario names: an OpenDRIVE file (found relative to the scenario) or a town."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from ..files.safefiles import reading_roots

#: 3D scenery formats a player loads as a scene graph (OpenSCENARIO's RoadNetwork/SceneGraphFile):
#: a place with no roads, such as esmini's parking lot, where every position is a world position.
SCENERY_SUFFIXES = (".osgb", ".osg", ".ive", ".fbx", ".obj", ".dae", ".3ds")


def is_scenery_file(map_text: str) -> bool:
    """A scene graph file (3D scenery with no road network) rather than an OpenDRIVE file."""
    return map_text.strip().lower().endswith(SCENERY_SUFFIXES)


def is_town_name(map_text: str) -> bool:
    """A simulator town (e.g. `Town03`) rather than an OpenDRIVE or scenery file."""
    return (
        not map_text.lower().endswith(".xodr")
        and not is_scenery_file(map_text)
        and "/" not in map_text
        and "\\" not in map_text
    )


@dataclass(frozen=True)
class MapReference:
    """The root node's `map` text and what it names: an OpenDRIVE file (`path`), a scene graph
    with no roads (`scenery`), or a simulator town (neither). Only `path` is ever read as roads."""

    text: str
    path: Path | None
    #: The folders the map file may be read from (None: any, for a model that has no file).
    roots: tuple[Path, ...] | None = None
    scenery: Path | None = None

    @property
    def is_town(self) -> bool:
        return self.path is None and self.scenery is None


def map_reference(
    map_text: str | None,
    scenario_file: str | Path | None,
    roots: Iterable[str | Path] | None = None,
) -> MapReference | None:
    """What `map_text` names; a relative path is resolved from the scenario file's folder.

    None when no map is named. A relative path of a model that has no file (built in Python) is
    resolved from the working directory. The map may be read from `roots`, by default the
    reading rule's folders of the scenario file (`reading_roots`); a model without a file has
    no such rule.
    """
    text = (map_text or "").strip()
    if not text:
        return None
    if is_town_name(text):
        return MapReference(text, None)
    path = Path(text)
    scenery = is_scenery_file(text)
    if not path.is_absolute():
        base = Path(scenario_file).resolve().parent if scenario_file is not None else Path.cwd()
        path = base / path
    if roots is None and scenario_file is not None:
        roots = reading_roots(scenario_file)
    allowed = None if roots is None else tuple(Path(root) for root in roots)
    if scenery:
        return MapReference(text, None, allowed, scenery=path.resolve())
    return MapReference(text, path.resolve(), allowed)
