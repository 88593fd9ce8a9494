"""The batch fast path writes exactly what a full export of the same sample writes."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.export import build_xosc
from sceml.levels.apply import apply
from sceml.levels.batch import BatchConfig, Worker
from sceml.levels.sampling import Plan, design
from sceml.levels.space import parameter_space
from sceml.model.loading import load_scenario

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize(("name", "samples"), [("uis1", 5), ("uis2", 12)])
def test_fast_path_bytes_equal_a_full_export_of_apply(
    tmp_path: Path, name: str, samples: int
) -> None:
    # UIS2's DriveDistance finishes distance / speed after it starts, a delay the export derives
    # from the sampled speed: the fast path must write that too.
    logical_path = EXAMPLES / f"{name}-logical.xmi"
    logical = load_scenario(logical_path).root
    space = parameter_space(logical)
    config = BatchConfig(logical_path, tmp_path, space.paths, ("xosc",), "1.2", name, 5)
    worker = Worker(config)
    assert worker.fast is not None  # substitution reproduced the probe export
    for index, row in enumerate(design(space, Plan("random", samples, seed=21))):
        record = worker.run(index, row)
        assert record.status == "written", record.reason
        concrete = apply(logical, dict(zip(space.paths, (float(v) for v in row), strict=True)))
        target = tmp_path / record.files[0]
        expected = build_xosc(
            concrete, version="1.2", source_path=logical_path, output_path=target
        ).data
        assert target.read_bytes() == expected
    assert worker.fast is not None  # the per-worker byte comparison held


def test_the_derived_delay_is_distance_over_the_sampled_speed(tmp_path: Path) -> None:
    logical_path = EXAMPLES / "uis2-logical.xmi"
    space = parameter_space(load_scenario(logical_path).root)
    worker = Worker(BatchConfig(logical_path, tmp_path, space.paths, ("xosc",), "1.2"))
    assert worker.fast is not None
    speed = space.paths.index("DriveDistance_1.speed")
    row = [5.0, 7.0, 4.0, 10.0, 15.0, 1.5]
    for sampled, delay in [(8.0, b'delay="7.5"'), (12.0, b'delay="5.0"')]:  # 60 m at that speed
        row[speed] = sampled
        assert delay in worker.fast.render(row)
    # At 0 m/s the DriveDistance never finishes: the full export refuses that sample itself.
    row[speed] = 0.0
    assert not worker.fast.covers(row)


def test_samples_breaking_a_rule_are_skipped_with_a_reason(tmp_path: Path) -> None:
    logical_path = EXAMPLES / "uis2-logical.xmi"
    space = parameter_space(load_scenario(logical_path).root)
    worker = Worker(BatchConfig(logical_path, tmp_path, space.paths, ("xosc",)))
    row = [5.0, 7.0, -1.0, 10.0, 15.0, 1.5]  # InLocationRadius_2.radius below zero
    record = worker.run(0, row)
    assert record.status == "skipped"
    assert record.reason == "validation: SCEML-P007 at InLocationRadius_2.radius"
    assert list(tmp_path.glob("*.xosc")) == []
    walking_fast = worker.run(1, [5.0, 7.0, 4.0, 10.0, 15.0, 9.0])  # a pedestrian at 9 m/s
    assert walking_fast.status == "skipped" and "SCEML-L001" in walking_fast.reason
