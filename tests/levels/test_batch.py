"""The batch fast path writes exactly what a full export of the same sample writes."""

from __future__ import annotations

from pathlib import Path

from sceml import io
from sceml.export import build_xosc
from sceml.levels.apply import apply
from sceml.levels.batch import BatchConfig, Worker
from sceml.levels.sampling import Plan, design
from sceml.levels.space import parameter_space

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_fast_path_bytes_equal_a_full_export_of_apply(tmp_path: Path) -> None:
    # UIS1: UIS2's DriveDistance finishes after distance / speed, a number the export derives
    # from a sampled one, so its samples take the full export (see the next test).
    logical_path = EXAMPLES / "uis1-logical.xmi"
    logical = io.load_scenario(logical_path).root
    space = parameter_space(logical)
    config = BatchConfig(logical_path, tmp_path, space.paths, ("xosc",), "1.2", "uis1", 5)
    worker = Worker(config)
    assert worker.fast is not None  # substitution reproduced the probe export
    for index, row in enumerate(design(space, Plan("random", 5, seed=21))):
        record = worker.run(index, row)
        assert record.status == "written", record.reason
        concrete = apply(logical, dict(zip(space.paths, (float(v) for v in row), strict=True)))
        target = tmp_path / record.files[0]
        expected = build_xosc(
            concrete, version="1.2", source_path=logical_path, output_path=target
        ).data
        assert target.read_bytes() == expected
    assert worker.fast is not None  # the per-worker byte comparison held


def test_a_derived_number_sends_samples_to_the_full_export(tmp_path: Path) -> None:
    logical_path = EXAMPLES / "uis2-logical.xmi"
    logical = io.load_scenario(logical_path).root
    space = parameter_space(logical)
    worker = Worker(BatchConfig(logical_path, tmp_path, space.paths, ("xosc",), "1.2", "uis2", 2))
    assert worker.fast is None  # the probe's substitution did not reproduce the export
    for index, row in enumerate(design(space, Plan("random", 2, seed=21))):
        record = worker.run(index, row)
        assert record.status == "written", record.reason
        concrete = apply(logical, dict(zip(space.paths, (float(v) for v in row), strict=True)))
        target = tmp_path / record.files[0]
        expected = build_xosc(
            concrete, version="1.2", source_path=logical_path, output_path=target
        ).data
        assert target.read_bytes() == expected


def test_samples_breaking_a_rule_are_skipped_with_a_reason(tmp_path: Path) -> None:
    logical_path = EXAMPLES / "uis2-logical.xmi"
    space = parameter_space(io.load_scenario(logical_path).root)
    worker = Worker(BatchConfig(logical_path, tmp_path, space.paths, ("xosc",)))
    row = [5.0, 7.0, -1.0, 10.0, 15.0, 1.5]  # InLocationRadius_2.radius below zero
    record = worker.run(0, row)
    assert record.status == "skipped"
    assert record.reason == "validation: SCEML-P007 at InLocationRadius_2.radius"
    assert list(tmp_path.glob("*.xosc")) == []
    walking_fast = worker.run(1, [5.0, 7.0, 4.0, 10.0, 15.0, 9.0])  # a pedestrian at 9 m/s
    assert walking_fast.status == "skipped" and "SCEML-L001" in walking_fast.reason
