"""Absurd numbers at the edge (docs/security.md): sample and explore counts that no machine
holds, and speeds, distances and durations the preview cannot simulate, are refused before
anything is allocated, with what they would take, the file and line, and exit 2."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.errors import ArgumentError
from sceml.levels import counts
from sceml.levels.counts import check_count, parse_count
from sceml.levels.paths import LevelArgumentError

from .confined import sceml


@pytest.mark.parametrize(
    ("text", "value"),
    [("1000", 1000), ("1_000", 1000), ("1e6", 1_000_000), ("2^20", 1_048_576), ("0", 0)],
)
def test_counts_read_as_people_type_them(text: str, value: int) -> None:
    assert parse_count(text) == value


@pytest.mark.parametrize("text", ["abc", "-1", "1.5", "1e", "2^", "1e400", "2^1000", ""])
def test_what_is_no_count_is_refused(text: str) -> None:
    with pytest.raises(ArgumentError):
        parse_count(text)


def test_check_count_says_what_the_request_would_take(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(counts, "available_memory", lambda: 4000)
    check_count(10, "samples", memory_each=200)  # 2000 bytes: half of what is free
    with pytest.raises(LevelArgumentError) as refused:
        check_count(11, "samples", memory_each=200, hint="ask for fewer")
    assert str(refused.value) == (
        "11 samples would take about 2.15 KiB of memory (available: 3.91 KiB, of which at "
        "most half is used); ask for fewer"
    )


@pytest.mark.parametrize("n", ["1e9", "1e30", "2^63", "9223372036854775808"])
def test_sample_refuses_counts_no_machine_holds(examples_copy: Path, n: str) -> None:
    out = examples_copy / "samples"
    logical = examples_copy / "uis1-logical.xmi"
    run = sceml("sample", logical, "--strategy", "random", "--n", n, "-o", out, cwd=examples_copy)
    assert "Traceback" not in run.output
    assert run.code == 2, run.output
    assert f"{parse_count(n):,} samples would take about" in run.output
    assert not out.exists()


def test_one_sample_of_a_huge_latin_hypercube_is_refused(examples_copy: Path) -> None:
    out = examples_copy / "samples"
    logical = examples_copy / "uis1-logical.xmi"
    arguments = ["--strategy", "lhs", "--n", "1e9", "--index", "0", "-o", out]
    run = sceml("sample", logical, *arguments, cwd=examples_copy)
    assert "Traceback" not in run.output
    assert run.code == 2, run.output
    assert "1,000,000,000 rows of the Latin hypercube would take about" in run.output
    assert not out.exists()


def test_a_grid_of_two_800001_level_ranges_is_refused_by_its_size(examples_copy: Path) -> None:
    logical = examples_copy / "uis1-logical.xmi"
    text = logical.read_text(encoding="utf-8")
    for old, new in [
        ('min="3.0" max="7.0" step="1.0"', 'min="3.0" max="7.0" step="0.000005"'),
        ('min="8.0" max="16.0" step="4.0"', 'min="8.0" max="16.0" step="0.00001"'),
    ]:
        assert old in text
        text = text.replace(old, new)
    logical.write_text(text, encoding="utf-8")
    out = examples_copy / "grid"
    run = sceml("sample", logical, "-o", out, cwd=examples_copy)
    assert "Traceback" not in run.output
    assert run.code == 2, run.output
    assert "640,001,600,001 samples would take about" in run.output  # 800,001^2
    assert "cap it with --n" in run.output
    assert not out.exists()


def test_explore_refuses_a_budget_no_machine_holds(examples_copy: Path) -> None:
    out = examples_copy / "explored"
    logical = examples_copy / "uis1-logical.xmi"
    run = sceml("explore", logical, "--budget", "1e9", "-o", out, cwd=examples_copy)
    assert "Traceback" not in run.output
    assert run.code == 2, run.output
    assert "1,000,000,000 runs would take about" in run.output
    assert not out.exists()


# Simulate: (where in uis1-concrete.xmi, what it holds there, the line, what is said)
SPEEDS = {
    "2^31 m/s": ('<initialSpeed xsi:type="scemlmodel:Value" value="5.0"/>', 11, "2147483648"),
    "1e6 m/s": ('<initialSpeed xsi:type="scemlmodel:Value" value="5.0"/>', 11, "1e6"),
    "1e309 (inf)": ('<targetSpeed xsi:type="scemlmodel:Value" value="8.0"/>', 23, "1e309"),
    "a distance of 1e12 m": ('<offset xsi:type="scemlmodel:Value" value="0.0"/>', 9, "1e12"),
}


@pytest.mark.parametrize("case", sorted(SPEEDS))
def test_simulate_refuses_implausible_values_at_their_line(examples_copy: Path, case: str) -> None:
    element, line, value = SPEEDS[case]
    scenario = examples_copy / "uis1-concrete.xmi"
    text = scenario.read_text(encoding="utf-8")
    assert text.splitlines()[line - 1].strip() == element
    changed = element.replace(element.split('value="')[1].split('"')[0], value)
    scenario.write_text(text.replace(element, changed, 1), encoding="utf-8")
    page = examples_copy / "run.html"
    run = sceml("simulate", scenario, "-o", page, cwd=examples_copy)
    assert "Traceback" not in run.output
    assert run.code == 2, run.output
    assert f"uis1-concrete.xmi:{line}: " in run.output
    assert ("not a finite number" if value == "1e309" else "beyond what the preview") in run.output
    assert not page.exists()


def test_simulate_refuses_an_unset_speed_and_a_range(examples_copy: Path) -> None:
    scenario = examples_copy / "uis1-concrete.xmi"
    text = scenario.read_text(encoding="utf-8")
    speed = '<targetSpeed xsi:type="scemlmodel:Value" value="8.0"/>'
    scenario.write_text(text.replace(speed, "", 1), encoding="utf-8")
    unset = sceml("simulate", scenario, "-o", examples_copy / "a.html", cwd=examples_copy)
    assert unset.code == 2 and "uis1-concrete.xmi:22: " in unset.output, unset.output
    assert "targetSpeed is not set and has no language default" in unset.output
    ranged = '<targetSpeed xsi:type="scemlmodel:Range" min="1" max="3"/>'
    scenario.write_text(text.replace(speed, ranged, 1), encoding="utf-8")
    held = sceml("simulate", scenario, "-o", examples_copy / "b.html", cwd=examples_copy)
    assert held.code == 2 and "uis1-concrete.xmi:23: " in held.output, held.output
    assert "holds [1, 3], not a single value" in held.output


def test_simulate_refuses_a_library_default_that_is_a_range_at_its_line(
    examples_copy: Path,
) -> None:
    library = examples_copy / "library" / "sceml-library.xmi"
    text = library.read_text(encoding="utf-8")
    default = '<default xsi:type="scemlmodel:Value" value="2.0"/>'
    assert text.splitlines()[47].strip() == default  # arrivalRadius, which uis2 does not set
    library.write_text(
        text.replace(default, '<default xsi:type="scemlmodel:Range" min="1" max="3"/>', 1)
    )
    run = sceml("simulate", examples_copy / "uis2-concrete.xmi", "-o", "r.html", cwd=examples_copy)
    assert "Traceback" not in run.output
    assert run.code == 2, run.output
    assert "sceml-library.xmi:48: " in run.output and "not a single value" in run.output


def test_simulate_refuses_a_run_too_long_to_record(examples_copy: Path) -> None:
    scenario = examples_copy / "uis1-concrete.xmi"
    text = scenario.read_text(encoding="utf-8")
    duration = '<maxDuration xsi:type="scemlmodel:Value" value="60.0"/>'
    scenario.write_text(text.replace(duration, duration.replace("60.0", "80000"), 1))
    run = sceml("simulate", scenario, "--step", "0.001", "-o", "r.html", cwd=examples_copy)
    assert "Traceback" not in run.output
    assert run.code == 2, run.output
    # 80,000 s / 0.001 s + 1 = 80,000,001 steps, of 2 actors
    assert "uis1-concrete.xmi:4: " in run.output and "160,000,002 samples" in run.output
