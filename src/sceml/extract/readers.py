"""Read recordings: SceML's preview CSV, esmini's --csv_logger CSV, OSC-Generator's CSV.

Each reader turns its file into a `Recording` with world x, y in the map's frame. The format
is told by the header unless named. Bad input is a LoadError naming the file and line.
"""

from __future__ import annotations

import csv
import math
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np

from ..errors import LoadError
from .recording import Recording, Track

#: The formats `read_recording` knows, by name.
FORMATS = ("sceml", "esmini", "osc-generator")

#: Earth radius (m) of OSC-Generator's flat-earth conversion between metres and degrees.
_EARTH_RADIUS = 6378137.0

#: OSC-Generator's object classes (its `class_N` column, as its man_helpers.label_maneuvers
#: names them) as SceML actor kinds; 0 (unknown) and 11 (animal) have none.
_OSC_GENERATOR_KINDS = {
    3: "Pedestrian",
    5: "Bicycle",
    6: "Motorcycle",
    7: "Car",
    8: "Van",
    9: "Truck",
}


def read_recording(
    path: str | Path, format: str | None = None, *, geo_origin: tuple[float, float] = (0.0, 0.0)
) -> Recording:
    """Read a recording; `format` is one of FORMATS, or None to tell it by the header.

    `geo_origin` (latitude, longitude in degrees) is where the map's (0, 0) lies, for
    OSC-Generator's geographic positions.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError as error:
        line = text_line(path, error.start)
        raise LoadError("the recording is not valid UTF-8", file=path, line=line) from None
    except OSError as error:
        raise LoadError(
            f"cannot read the recording: {error.strerror or error}", file=path
        ) from None
    rows = list(csv.reader(text.splitlines(), skipinitialspace=True))
    chosen = format or _detect(rows, path)
    readers: dict[str, Callable[[list[list[str]], Path], Recording]] = {
        "sceml": _read_sceml,
        "esmini": _read_esmini,
        "osc-generator": lambda r, p: _read_osc_generator(r, p, geo_origin),
    }
    if chosen not in readers:
        raise LoadError(f"unknown recording format {chosen!r}; choose one of {', '.join(FORMATS)}")
    recording = readers[chosen](rows, path)
    if not recording.tracks:
        raise LoadError("the recording has no actor with samples", file=path)
    return recording


def text_line(path: Path, offset: int) -> int | None:
    """The line of a byte offset in a file (for an encoding error), None if unreadable."""
    try:
        return path.read_bytes()[:offset].count(b"\n") + 1
    except OSError:
        return None


def _detect(rows: list[list[str]], path: Path) -> str:
    for row in rows[:20]:
        cells = [c.strip() for c in row]
        if cells[:2] == ["time", "actor"]:
            return "sceml"
        if cells[:2] == ["Index [-]", "TimeStamp [s]"] or (cells and cells[0].startswith("esmini")):
            return "esmini"
        if "timestamp" in cells and "lat" in cells:
            return "osc-generator"
    raise LoadError(
        "cannot tell the recording's format from its header; name it with --format "
        f"({', '.join(FORMATS)})",
        file=path,
        line=1,
    )


def _number(cell: str, path: Path, line: int, what: str) -> float:
    try:
        value = float(cell)
    except ValueError:
        raise LoadError(f"{what} is not a number: {cell!r}", file=path, line=line) from None
    if not math.isfinite(value):
        raise LoadError(f"{what} is not finite: {cell!r}", file=path, line=line)
    return value


class _Samples:
    """Samples gathered per actor in file order, made into tracks at the end."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self.rows: dict[str, list[tuple[float, float, float, float]]] = {}
        self.boxes: dict[str, tuple[float, float]] = {}
        self.kinds: dict[str, str] = {}
        self.last_line: dict[str, int] = {}

    def add(self, name: str, line: int, t: float, x: float, y: float, h: float) -> None:
        """One sample of an actor; its time must follow the actor's last one."""
        samples = self.rows.setdefault(name, [])
        if samples and t <= samples[-1][0]:
            raise LoadError(
                f"time {t:g} s of {name!r} does not follow {samples[-1][0]:g} s",
                file=self.path,
                line=line,
                element=name,
            )
        samples.append((t, x, y, h))

    def tracks(self, ego: str | None) -> tuple[Track, ...]:
        """The gathered samples as tracks, in the order the actors first appeared."""
        made = []
        for name, samples in self.rows.items():
            array = np.array(samples, dtype=float)
            box = self.boxes.get(name)
            made.append(
                Track(
                    name,
                    array[:, 0],
                    array[:, 1],
                    array[:, 2],
                    None if np.isnan(array[:, 3]).all() else np.unwrap(array[:, 3]),
                    kind=self.kinds.get(name),
                    length=box[0] if box else None,
                    width=box[1] if box else None,
                    ego=name == ego,
                )
            )
        return tuple(made)


def _read_sceml(rows: list[list[str]], path: Path) -> Recording:
    """`sceml simulate --csv`: time, actor, x, y, heading, speed; one row per actor and sample."""
    header = [c.strip() for c in rows[0]] if rows else []
    needed = ("time", "actor", "x", "y")
    missing = [c for c in needed if c not in header]
    if missing:
        raise LoadError(f"missing column(s) {', '.join(missing)}", file=path, line=1)
    at = {name: header.index(name) for name in header}
    samples = _Samples(path)
    for line, row in enumerate(rows[1:], start=2):
        if not row:
            continue
        if len(row) < len(header):
            raise LoadError(
                f"{len(row)} cells where the header has {len(header)}", file=path, line=line
            )
        name = row[at["actor"]].strip()
        t, x, y = (_number(row[at[c]], path, line, c) for c in ("time", "x", "y"))
        h = _number(row[at["heading"]], path, line, "heading") if "heading" in at else math.nan
        samples.add(name, line, t, x, y, h)
    ego = "ego" if "ego" in samples.rows else None
    return Recording(samples.tracks(ego), str(path), "sceml")


#: esmini's per-entity columns (CSV_Logger in EnvironmentSimulator/Modules/CommonMini).
_ESMINI_FIELDS = 31
_ESMINI_AT = {"name": 0, "length": 8, "width": 9, "x": 11, "y": 12, "heading": 24}


def _read_esmini(rows: list[list[str]], path: Path) -> Recording:
    """esmini `--csv_logger`: six lines of preamble, a header, then one line per time step with
    31 fields per entity (name, id, speed, ..., bounding box, world x, y, z, ..., heading, ...).

    Positions are the entity's reference point (the rear axle for vehicles), which is what an
    OpenSCENARIO position places; the first entity is taken as the ego, as esmini's is.
    """
    start = next((i for i, r in enumerate(rows) if r and r[0].strip() == "Index [-]"), None)
    if start is None:
        raise LoadError("no esmini header line (Index [-], TimeStamp [s], ...)", file=path)
    samples = _Samples(path)
    first: str | None = None
    for index, row in enumerate(rows[start + 1 :], start=start + 2):
        cells = [c.strip() for c in row]
        while cells and cells[-1] == "":
            cells.pop()
        if not cells:
            continue
        t = _number(cells[1], path, index, "TimeStamp")
        for entity in _entities(cells[2:], path, index):
            name = entity[_ESMINI_AT["name"]]
            first = first or name
            x, y, h, length, width = (
                _number(entity[_ESMINI_AT[k]], path, index, f"{k} of {name}")
                for k in ("x", "y", "heading", "length", "width")
            )
            samples.boxes[name] = (length, width)
            samples.add(name, index, t, x, y, h)
    return Recording(samples.tracks(first), str(path), "esmini")


def _entities(cells: list[str], path: Path, line: int) -> Iterator[list[str]]:
    """The entity groups of one esmini line; the collision-id field may be empty."""
    # Each group ends with a collision list that may be empty; trailing empties were trimmed.
    padded = cells + [""] * (-len(cells) % _ESMINI_FIELDS)
    if len(padded) % _ESMINI_FIELDS:
        raise LoadError("a line with a broken entity group", file=path, line=line)
    for i in range(0, len(padded), _ESMINI_FIELDS):
        yield padded[i : i + _ESMINI_FIELDS]


def _read_osc_generator(
    rows: list[list[str]], path: Path, origin: tuple[float, float]
) -> Recording:
    """OSC-Generator's CSV: the ego as timestamp, lat, long, heading (degrees clockwise from
    north), speed; every other object N relative to the ego (pos_x_N forward, pos_y_N left, m)
    with class_N. Converted to the map's frame with OSC-Generator's own flat-earth formula
    about `origin`, which is accurate to millimetres over a few hundred metres.
    """
    header = [c.strip() for c in rows[0]] if rows else []
    at = {name: i for i, name in enumerate(header)}
    missing = [c for c in ("timestamp", "lat", "long", "heading") if c not in at]
    if missing:
        raise LoadError(f"missing column(s) {', '.join(missing)}", file=path, line=1)
    objects = sorted(
        int(name[len("pos_x_") :])
        for name in header
        if name.startswith("pos_x_") and name[6:].isdigit()
    )
    samples = _Samples(path)
    lat0, lon0 = (math.radians(v) for v in origin)
    for line, row in enumerate(rows[1:], start=2):
        if not row:
            continue

        def cell(name: str, row: list[str] = row, line: int = line) -> float:
            return _number(row[at[name]], path, line, name)

        t = cell("timestamp")
        lat, lon = math.radians(cell("lat")), math.radians(cell("long"))
        x = (lon - lon0) * _EARTH_RADIUS * math.cos(lat0)
        y = (lat - lat0) * _EARTH_RADIUS
        h = math.radians(90.0 - cell("heading"))
        samples.add("ego", line, t, x, y, h)
        for n in objects:
            if row[at[f"pos_x_{n}"]].strip() in ("", "nan"):
                continue  # the object is not seen at this sample
            forward, left = cell(f"pos_x_{n}"), cell(f"pos_y_{n}")
            name = f"object_{n}"
            samples.add(
                name,
                line,
                t,
                x + forward * math.cos(h) - left * math.sin(h),
                y + forward * math.sin(h) + left * math.cos(h),
                math.nan,
            )
            if f"class_{n}" in at and row[at[f"class_{n}"]].strip() not in ("", "nan"):
                kind = _OSC_GENERATOR_KINDS.get(int(cell(f"class_{n}")))
                if kind:
                    samples.kinds[name] = kind
    return Recording(samples.tracks("ego"), str(path), "osc-generator")
