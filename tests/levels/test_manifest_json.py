"""manifest.json is written from a row template for speed; it must be, byte for byte, what
`json.dumps(document, indent=2)` writes."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from sceml.levels.manifest import JSON_NAME, SampleRecord, write_manifest

RUN: dict[str, Any] = {
    "logical": "examples/uis2-logical.xmi",
    "strategy": "random",
    "n": 5,
    "seed": 7,
    "format": "both",
    "osc_version": "1.3",
    "interrupted": True,
}
PATHS = ("ego.initialSpeed", "Accelerate_1.targetSpeed", 'a "quoted" path\\é')

RECORDS = [
    SampleRecord(3, (1.0, -0.0, 2.5e-300), files=("uis2_00003.xosc", "uis2_00003.xmi")),
    SampleRecord(0, (5.0, 7.123456789012345, 1e16), files=("uis2_00000.xosc",)),
    SampleRecord(1, (float("nan"), float("inf"), float("-inf")), status="skipped", reason="xsd: …"),
    SampleRecord(2, (0.1, 0.2, 0.3), status="failed", reason='lost: OSError: "disk" full\n'),
    SampleRecord(4, (1.0, 2.0, 3.0), status="skipped", reason=""),
]


def _expected(paths: tuple[str, ...], records: list[SampleRecord]) -> bytes:
    rows = [
        {
            "index": r.index,
            "status": r.status,
            "reason": r.reason or None,
            "files": list(r.files),
            "values": {p: float(v) for p, v in zip(paths, r.values, strict=True)},
        }
        for r in sorted(records, key=lambda r: r.index)
    ]
    document = {"run": RUN, "parameters": list(paths), "samples": rows}
    return (json.dumps(document, indent=2) + "\n").encode("utf-8")


@pytest.mark.parametrize(
    ("paths", "records"),
    [
        (PATHS, RECORDS),
        (PATHS, []),
        ((), [SampleRecord(0, ()), SampleRecord(1, (), status="skipped", reason="x")]),
        (("a", "a"), [SampleRecord(0, (1.0, 2.0))]),  # one key, as a dict has it
    ],
    ids=["mixed", "no-samples", "no-parameters", "duplicate-paths"],
)
def test_manifest_json_is_what_json_dumps_writes(
    tmp_path: Path, paths: tuple[str, ...], records: list[SampleRecord]
) -> None:
    write_manifest(tmp_path, paths, records, RUN)
    assert (tmp_path / JSON_NAME).read_bytes() == _expected(paths, records)
