"""Write a recording in OSC-Generator's CSV input format, for comparing it with `sceml extract`.

    .venv/bin/python benchmarks/osc_generator_input.py RUN.csv OUT.csv [--origin 48,11]

RUN.csv is `sceml simulate --csv` output. OUT.csv has OSC-Generator 0.2.0's columns: the ego
(the actor named `ego`) as timestamp, lat, long, heading (degrees clockwise from north) and
speed (km/h, as OSC-Generator reads it); every other actor N relative to the ego (pos_x_N
ahead, pos_y_N to the left, m; speed_x_N, speed_y_N in km/h; class_N by its own codes: 7 car,
9 truck, 5 bicycle, 3 pedestrian); and the two lane lines it needs, here the lines of a
straight east-west road through y = 0 (the centre) and y = -3.5 (the right edge), in the ego's
frame. Positions become latitude and longitude by OSC-Generator's flat-earth formula about
`--origin`; give OSC-Generator a copy of the map whose header has a matching geoReference
(`+proj=tmerc +lat_0=48 +lon_0=11 +ellps=WGS84`). docs/extract.md says what came of it.
"""

from __future__ import annotations

import argparse
import csv
import math
from pathlib import Path

EARTH_RADIUS = 6378137.0
CLASSES = {"truck": 9, "bike": 5, "pedestrian": 3}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", type=Path)
    parser.add_argument("out", type=Path)
    parser.add_argument("--origin", default="48,11", help="LAT,LON of the map's (0, 0)")
    options = parser.parse_args()
    lat0, lon0 = (math.radians(float(v)) for v in options.origin.split(","))
    samples: dict[str, dict[str, dict[str, str]]] = {}
    with options.run.open(encoding="utf-8") as stream:
        for row in csv.DictReader(stream):
            samples.setdefault(row["time"], {})[row["actor"]] = row
    others = sorted({a for rows in samples.values() for a in rows} - {"ego"})
    header = ["timestamp", "lat", "long", "heading", "speed"]
    for n, _ in enumerate(others, 1):
        header += [f"pos_x_{n}", f"pos_y_{n}", f"speed_x_{n}", f"speed_y_{n}", f"class_{n}"]
    for side in ("left", "right"):
        header += [f"lin_{side}_{c}" for c in ("typ", "beginn_x", "y_abstand", "kruemm", "ende_x")]
    with options.out.open("w", newline="", encoding="utf-8") as stream:
        writer = csv.writer(stream)
        writer.writerow(header)
        for time in sorted(samples, key=float):
            writer.writerow(_row(float(time), samples[time], others, lat0, lon0))


def _row(
    time: float, rows: dict[str, dict[str, str]], others: list[str], lat0: float, lon0: float
) -> list[float]:
    ego = rows["ego"]
    x, y, h, v = (float(ego[k]) for k in ("x", "y", "heading", "speed"))
    lat = math.degrees(lat0 + y / EARTH_RADIUS)
    lon = math.degrees(lon0 + x / (EARTH_RADIUS * math.cos(lat0)))
    row = [time, lat, lon, (90.0 - math.degrees(h)) % 360.0, v * 3.6]
    for name in others:
        other = rows[name]
        dx, dy = float(other["x"]) - x, float(other["y"]) - y
        speed, heading = float(other["speed"]) * 3.6, float(other["heading"]) - h
        row += [
            dx * math.cos(h) + dy * math.sin(h),
            -dx * math.sin(h) + dy * math.cos(h),
            speed * math.cos(heading),
            speed * math.sin(heading),
            CLASSES.get(name, 7),
        ]
    return row + [1, 0.0, -y, 0.0, 60.0, 1, 0.0, -3.5 - y, 0.0, 60.0]


if __name__ == "__main__":
    main()
