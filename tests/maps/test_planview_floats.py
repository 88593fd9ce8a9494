"""The plan view's plain-float arithmetic against numpy's, bit for bit.

`sceml.maps.planview` samples and projects onto reference lines without numpy (its import costs
`sceml validate` more than the work). What the map rules compare must stay what the arrays gave,
to the last bit: here each helper is held to the numpy function it replaces, and every road's
samples and projections to the array code the plan view had before (written out again below
with numpy, as the reference).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from maps import sg_networks as sg
from maps import test_intersection_map as evaluator
from sceml.maps.planview import ReferenceLine, clip, linspace, unwrap
from sceml.maps.roadmap import RoadMap, load_map

IMPORT_FILES = Path(__file__).resolve().parents[1] / "importer" / "files"
finite = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False)


def same_bits(ours: list[float], theirs: np.ndarray) -> bool:
    """Equal value for value, zeros' signs included."""
    theirs_list = [float(v) for v in theirs]
    return len(ours) == len(theirs_list) and all(
        a == b and math.copysign(1.0, a) == math.copysign(1.0, b)
        for a, b in zip(ours, theirs_list, strict=True)
    )


@given(finite, finite, st.integers(min_value=2, max_value=500))
def test_linspace_is_numpys(start: float, stop: float, count: int) -> None:
    assert same_bits(linspace(start, stop, count), np.linspace(start, stop, count))


def test_linspace_of_a_step_too_small_for_a_float_is_numpys() -> None:
    start, stop = 1.0, math.nextafter(1.0, 2.0)
    assert same_bits(linspace(start, stop, 7), np.linspace(start, stop, 7))
    assert same_bits(linspace(5.0, 5.0, 3), np.linspace(5.0, 5.0, 3))


@given(st.lists(st.floats(min_value=-50.0, max_value=50.0), min_size=1, max_size=60))
def test_unwrap_is_numpys(angles: list[float]) -> None:
    assert same_bits(unwrap(angles), np.unwrap(np.array(angles)))


def test_unwrap_of_jumps_of_exactly_pi_is_numpys() -> None:
    angles = [0.0, math.pi, 0.0, -math.pi, 2 * math.pi, -3 * math.pi, 0.5]
    assert same_bits(unwrap(angles), np.unwrap(np.array(angles)))
    assert unwrap([]) == []


@given(st.floats(allow_nan=False) | st.sampled_from([0.0, -0.0, 1.0, -1.0]))
def test_clip_is_numpys(value: float) -> None:
    assert same_bits([clip(value, 0.0, 1.0)], np.clip(np.array([value]), 0.0, 1.0))


def _array_samples(line: ReferenceLine) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """s, xy and the segments' curvature as the array code computed them."""
    samples: list[float] = []
    for start, piece_length in zip(line._starts, line._lengths, strict=True):
        count = max(2, math.ceil(piece_length / 0.5) + 1)
        samples.extend(np.linspace(start, start + piece_length, count)[:-1].tolist())
    samples.append(line.length)
    s = np.clip(np.array(samples), 0.0, line.length)
    poses = np.array([line.pose(float(v)) for v in s])
    spans = np.maximum(np.diff(s), 1e-12)
    return s, poses[:, :2], np.diff(np.unwrap(poses[:, 2])) / spans


def _array_nearest(xy: np.ndarray, s: np.ndarray, x: float, y: float) -> tuple[int, float]:
    """The array code's nearest segment of the polyline and the s of its nearest point."""
    point = np.array([x, y])
    a, b = xy[:-1], xy[1:]
    d = b - a
    squared = np.einsum("ij,ij->i", d, d)
    squared[squared == 0.0] = 1.0
    u = np.clip(np.einsum("ij,ij->i", point - a, d) / squared, 0.0, 1.0)
    nearest = a + u[:, None] * d
    index = int(np.argmin(np.einsum("ij,ij->i", nearest - point, nearest - point)))
    return index, float(s[index] + u[index] * (s[index + 1] - s[index]))


def _maps(folder: Path) -> list[RoadMap]:
    return [
        load_map(evaluator.XODR),
        load_map(IMPORT_FILES / "highway.xodr"),
        load_map(sg.curvy_network(folder)),  # paramPoly3 and poly3 roads as well
    ]


def test_every_roads_samples_and_projections_are_the_arrays_to_the_last_bit(
    tmp_path: Path,
) -> None:
    checked = 0
    for road_map in _maps(tmp_path):
        for road_id in road_map.roads:
            line = road_map.reference_line(road_id)
            s, xy, curvature = _array_samples(line)
            assert same_bits(line.s, s)
            assert same_bits([c for pair in line.xy for c in pair], xy.ravel())
            assert same_bits(line._curvature, curvature)
            x0, y0 = xy.min(axis=0) - 15.0
            x1, y1 = xy.max(axis=0) + 15.0
            for i in range(9):
                for j in range(9):
                    x, y = float(x0 + (x1 - x0) * i / 8), float(y0 + (y1 - y0) * j / 8)
                    index, start = _array_nearest(xy, s, x, y)
                    ours_index, fraction = line._nearest_segment(x, y)
                    assert ours_index == index
                    assert line.s[index] + fraction * (line.s[index + 1] - line.s[index]) == start
                    checked += 1
    assert checked == 81 * 24  # the intersection's 20 roads, the highway's one, the curvy's 3
