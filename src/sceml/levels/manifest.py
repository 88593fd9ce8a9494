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

from ..files.writing import write_atomically

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
    write_atomically(json_path, _json_bytes(paths, ordered, run))
    return csv_path, json_path


def _json_bytes(
    paths: Sequence[str], records: Sequence[SampleRecord], run: Mapping[str, Any]
) -> bytes:
    """What `json.dumps(document, indent=2)` writes for the manifest, and a newline.

    json's C encoder does not indent, and its Python one took most of the manifest's time for
    large runs; the rows all have one shape, so each is written from a template, with json's
    own encoders for the strings and numbers in it. A test compares the two.
    """
    if not records or len(set(paths)) != len(paths):  # (duplicate paths: one key, as dicts do)
        document = {
            "run": dict(run),
            "parameters": list(paths),
            "samples": [_json_row(paths, record) for record in records],
        }
        return (json.dumps(document, indent=2) + "\n").encode("utf-8")
    head = json.dumps({"run": dict(run), "parameters": list(paths), "samples": []}, indent=2)
    text, number = json.encoder.encode_basestring_ascii, _json_number
    keys = [f"        {text(path)}: " for path in paths]
    rows = []
    for record in records:
        files = (
            "[\n" + ",\n".join(f"        {text(name)}" for name in record.files) + "\n      ]"
            if record.files
            else "[]"
        )
        values = (
            "{\n"
            + ",\n".join(k + number(v) for k, v in zip(keys, record.values, strict=True))
            + "\n      }"
            if paths
            else "{}"
        )
        reason = text(record.reason) if record.reason else "null"
        rows.append(
            f'    {{\n      "index": {int(record.index)},\n'
            f'      "status": {text(record.status)},\n      "reason": {reason},\n'
            f'      "files": {files},\n      "values": {values}\n    }}'
        )
    start, end = head.rsplit('"samples": []', 1)
    return (start + '"samples": [\n' + ",\n".join(rows) + "\n  ]" + end + "\n").encode("utf-8")


def _json_number(value: float) -> str:
    """A float as json.dumps writes it (NaN and the infinities as JavaScript spells them)."""
    value = float(value)
    if value != value:
        return "NaN"
    if value in (float("inf"), float("-inf")):
        return "Infinity" if value > 0 else "-Infinity"
    return repr(value)


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
