"""The manifest of a sampling run: one row per sample, as CSV and as JSON, written atomically.

Each row holds the sample index, its status (`written` or `skipped`), the reason a sample was
skipped, the files written, and the value of every varied parameter. The JSON file also records
the run: logical scenario, strategy, n, seed, OpenSCENARIO version and the varied dimensions.
"""

from __future__ import annotations

import csv
import io as _io
import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..io import write_atomically

CSV_NAME = "manifest.csv"
JSON_NAME = "manifest.json"


@dataclass(frozen=True)
class SampleRecord:
    """What happened to one sample."""

    index: int
    values: tuple[float, ...]
    files: tuple[str, ...] = ()
    status: str = "written"
    reason: str = ""


def write_manifest(
    directory: Path,
    paths: Sequence[str],
    records: Sequence[SampleRecord],
    run: Mapping[str, Any],
) -> tuple[Path, Path]:
    """Write manifest.csv and manifest.json into `directory`, rows ordered by sample index."""
    ordered = sorted(records, key=lambda record: record.index)
    csv_path, json_path = directory / CSV_NAME, directory / JSON_NAME
    write_atomically(csv_path, _csv_bytes(paths, ordered))
    document = {
        "run": dict(run),
        "parameters": list(paths),
        "samples": [_json_row(paths, record) for record in ordered],
    }
    write_atomically(json_path, (json.dumps(document, indent=2) + "\n").encode("utf-8"))
    return csv_path, json_path


def _csv_bytes(paths: Sequence[str], records: Sequence[SampleRecord]) -> bytes:
    buffer = _io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["index", "status", "reason", "files", *paths])
    for record in records:
        # repr() keeps every float exact, so the manifest can be compared with the files.
        numbers = [repr(float(v)) for v in record.values]
        writer.writerow(
            [record.index, record.status, record.reason, ";".join(record.files), *numbers]
        )
    return buffer.getvalue().encode("utf-8")


def _json_row(paths: Sequence[str], record: SampleRecord) -> dict[str, Any]:
    return {
        "index": record.index,
        "status": record.status,
        "reason": record.reason or None,
        "files": list(record.files),
        "values": {path: float(v) for path, v in zip(paths, record.values, strict=True)},
    }


def read_manifest(directory: Path) -> dict[str, Any]:
    """The JSON manifest of a run, as written."""
    data: dict[str, Any] = json.loads((directory / JSON_NAME).read_text(encoding="utf-8"))
    return data
