"""Hostile limits files (`validate --limits FILE`): no code execution, no blow-up, clean errors."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.errors import SceMLError
from sceml.validation import load_limits

from .test_corpus import deadline


def test_python_tags_are_not_executed(tmp_path: Path) -> None:
    marker = tmp_path / "pwned"
    limits = tmp_path / "limits.yaml"
    limits.write_text(f'Car: !!python/object/apply:os.system ["touch {marker}"]\n')
    with pytest.raises(SceMLError, match="malformed limits file") as caught:
        load_limits(limits)
    assert caught.value.file == str(limits) and caught.value.line == 1
    assert not marker.exists()


def test_alias_bomb_is_refused_quickly(tmp_path: Path) -> None:
    # Nine levels of nine aliases: 9**9 leaves if anything walked it expanded.
    lines = ["a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    for level in range(1, 9):
        lines.append(f"a{level}: &a{level} [{', '.join([f'*a{level - 1}'] * 9)}]")
    limits = tmp_path / "bomb.yaml"
    limits.write_text("\n".join(lines) + "\n")
    with deadline(10), pytest.raises(SceMLError):
        load_limits(limits)


def test_limits_file_that_is_not_utf8_is_a_clean_error(tmp_path: Path) -> None:
    limits = tmp_path / "limits.yaml"
    limits.write_bytes(b"Car:\n  maxSpeed: 3\xff\n")
    with pytest.raises(SceMLError, match=r"not UTF-8 \(byte 18\)") as caught:
        load_limits(limits)
    assert caught.value.file == str(limits) and caught.value.line == 2


def test_oversized_limits_file_is_refused_before_reading(tmp_path: Path) -> None:
    limits = tmp_path / "limits.yaml"
    with limits.open("wb") as stream:
        stream.truncate(5 * 1024 * 1024)  # sparse: costs no disk
    with deadline(5), pytest.raises(SceMLError, match="above the 1048576 byte limit"):
        load_limits(limits)
