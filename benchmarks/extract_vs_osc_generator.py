"""Benchmark: `sceml extract` against OSC-Generator on the same recordings (issue 30).

For each concrete example the preview's run is the recording (20 Hz, `sceml simulate --csv`).
`osc_generator_input.py` writes it in OSC-Generator's CSV format; OSC-Generator (in a
virtualenv of its own: it needs NumPy 1.x) turns that into a .xosc, which
`osc_generator_repair.py` renames to OpenSCENARIO 1.0 (docs/extract.md lists each repair);
esmini plays it. `sceml extract` reads the same OSC-Generator CSV; its scenario is replayed in
the preview and, exported to OpenSCENARIO 1.0, in esmini. Printed per recording and actor: the
largest and the mean distance (m) between each replay and the recording, over the time both
cover, and whether the repaired file passes the 1.0 XSD.

    .venv/bin/python benchmarks/extract_vs_osc_generator.py --osc-generator \\
        /tmp/oscgen-venv/bin/osc_generator --esmini /tmp/esmini/bin/esmini --work /tmp/vs-oscgen

Each replay starts from the recording's first sample; a player that cannot place an actor or
stops early is compared over what it played.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
from lxml import etree
from numpy.typing import NDArray
from osc_generator_repair import repair

from sceml import io
from sceml.extract import extract, read_recording
from sceml.extract.recording import Recording, Track
from sceml.maps import load_map
from sceml.schema import validate_file

REPO = Path(__file__).resolve().parents[1]
HERE = Path(__file__).resolve().parent
EXAMPLES = ("overtaking-concrete", "uis1-concrete", "uis2-concrete")
ORIGIN = "48,11"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--osc-generator", type=Path, required=True, help="its executable")
    parser.add_argument("--esmini", type=Path, required=True, help="esmini's executable")
    parser.add_argument("--work", type=Path, required=True, help="a folder for the files")
    parser.add_argument("--examples", nargs="*", default=list(EXAMPLES))
    options = parser.parse_args()
    options.work.mkdir(parents=True, exist_ok=True)
    maps = options.work / "maps"
    maps.mkdir(exist_ok=True)
    shutil.copyfile(REPO / "maps" / "intersection.xodr", maps / "intersection.xodr")
    geo_text = _with_geo_reference(REPO / "maps" / "intersection.xodr")
    road_map = load_map(maps / "intersection.xodr")
    print("recording, actor: largest / mean distance (m) to the recording")
    print("  OSC-Generator (repaired) in esmini | ours in the preview | ours in esmini")
    for example in options.examples:
        folder = options.work / example
        folder.mkdir(exist_ok=True)
        truth_csv = folder / "run.csv"
        _run(
            [
                str(Path(sys.executable).with_name("sceml")),
                "simulate",
                str(REPO / "examples" / f"{example}.xmi"),
                "-o",
                str(folder / "run.html"),
                "--csv",
                str(truth_csv),
            ],
            folder,
        )
        truth = read_recording(truth_csv)
        order = [t.name for t in truth.tracks if t.name == "ego"]
        order += sorted(t.name for t in truth.tracks if t.name != "ego")
        og_csv = folder / "osc-generator-input.csv"
        _run(
            [sys.executable, str(HERE / "osc_generator_input.py"), str(truth_csv), str(og_csv)],
            folder,
        )
        # OSC-Generator writes a file of its own into the current folder: run it in `folder`.
        og_xosc = folder / "osc-generator.xosc"
        # It names the map by its file name only: beside the .xosc, so that esmini finds it.
        geo_map = folder / "intersection-geo.xodr"
        geo_map.write_text(geo_text, "utf-8")
        _run(
            [str(options.osc_generator), "-t", str(og_csv), "-d", str(geo_map), "-s", str(og_xosc)],
            folder,
        )
        fixed = folder / "osc-generator-1.0.xosc"
        end = float(truth.end - truth.start)
        repair(etree.parse(str(og_xosc)), end).write(
            str(fixed), xml_declaration=True, encoding="utf-8", pretty_print=True
        )
        xsd = validate_file(fixed, "1.0")
        theirs = _esmini(options.esmini, fixed, folder / "osc-generator-esmini.csv", folder)
        their_names = ["EGO", *[f"Player{n}" for n in range(1, len(order))]]
        found = extract(
            read_recording(og_csv, geo_origin=_origin()),
            road_map,
            map_reference="../maps/intersection.xodr",
        )
        our_names = ["ego", *[f"object_{n}" for n in range(1, len(order))]]
        assert found.replay is not None
        ours_preview = {
            name: found.replay.run.states[found.replay.run.actor_index(name), :, :2]
            for name in our_names
        }
        ours_xmi = folder / "ours.xmi"
        io.save(found.scenario, ours_xmi)
        ours_xosc = folder / "ours-1.0.xosc"
        _run(
            [
                str(Path(sys.executable).with_name("sceml")),
                "export",
                str(ours_xmi),
                "-o",
                str(ours_xosc),
                "--osc-version",
                "1.0",
            ],
            folder,
        )
        ours_esmini = _esmini(options.esmini, ours_xosc, folder / "ours-esmini.csv", folder)
        print(f"{example} ({len(xsd)} XSD errors in the repaired OSC-Generator file):")
        for k, name in enumerate(order):
            track = truth.track(name)
            columns = [
                _distance(track, theirs, their_names[k]),
                _distance_to(track, found.replay.run.times, ours_preview[our_names[k]]),
                _distance(track, ours_esmini, our_names[k]),
            ]
            print(f"  {name}: " + " | ".join(columns))


def _origin() -> tuple[float, float]:
    lat, lon = (float(v) for v in ORIGIN.split(","))
    return lat, lon


def _with_geo_reference(path: Path) -> str:
    """The map with a geoReference about ORIGIN, which OSC-Generator needs to place lat/lon."""
    lat, lon = ORIGIN.split(",")
    text = path.read_text("utf-8")
    reference = f"<geoReference><![CDATA[+proj=tmerc +lat_0={lat} +lon_0={lon} +ellps=WGS84]]></geoReference>"
    head, sep, rest = text.partition("<header ")
    tag, close, tail = rest.partition("/>")
    return f"{head}{sep}{tag}>{reference}</header>{tail}"


def _run(command: list[str], folder: Path) -> None:
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed ({done.returncode}):\n{done.stderr[-2000:]}")


def _esmini(esmini: Path, xosc: Path, csv: Path, folder: Path) -> Recording | None:
    """esmini's run of `xosc` as a recording, or None when it refused the file."""
    done = subprocess.run(
        [
            str(esmini),
            "--headless",
            "--osc",
            str(xosc),
            "--fixed_timestep",
            "0.05",
            # A fixed seed: esmini picks a junction's way at random for an actor without a route.
            "--seed",
            "0",
            "--logfile_path",
            str(csv.with_suffix(".log")),
            "--csv_logger",
            str(csv),
        ],
        cwd=folder,
        capture_output=True,
        text=True,
        check=False,
    )
    if done.returncode != 0 or not csv.is_file():
        return None
    return read_recording(csv)


def _distance(track: Track, run: Recording | None, name: str) -> str:
    if run is None:
        return "refused"
    other = run.track(name)
    return _distance_to(track, other.times - run.start, np.column_stack([other.x, other.y]))


def _distance_to(track: Track, times: NDArray[np.float64], points: NDArray[np.float64]) -> str:
    """Largest and mean distance between `points` at `times` (from the recording's start) and
    the recorded track, over the time both cover."""
    t0 = float(track.times[0])
    keep = times <= float(track.times[-1]) - t0 + 1e-9
    when = times[keep] + t0
    x = np.interp(when, track.times, track.x)
    y = np.interp(when, track.times, track.y)
    error = np.hypot(points[keep, 0] - x, points[keep, 1] - y)
    if not len(error) or not np.isfinite(error).all():
        return "no replay"
    return f"{error.max():.2f} / {error.mean():.2f}"


if __name__ == "__main__":
    main()
