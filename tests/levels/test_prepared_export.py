"""Forked workers inherit the exporter the caller prepared once (issue 31: the first file).

Before the process pool forks, the caller imports the exporter and compiles its template and
the XSD; workers then set up without doing it again. Executors whose workers do not start as
copies of the caller (in-process, spawn, Dask) are not asked to, and the files are the same.
"""

from __future__ import annotations

import multiprocessing
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from sceml.executors import LocalExecutor, ProcessExecutor
from sceml.levels import batch
from sceml.levels.batch import BatchConfig, run_batch
from sceml.levels.sampling import Plan, values_at
from sceml.levels.space import parameter_space
from sceml.model.loading import load_scenario
from sceml.xosc.profiles import DEFAULT_VERSION

UIS2 = Path(__file__).resolve().parents[2] / "examples" / "uis2-logical.xmi"


class _ForkLike(LocalExecutor):
    """In-process, but declared to start its workers as copies of the caller."""

    inherits_imports = True


def _run(out: Path, executor: LocalExecutor, formats: tuple[str, ...]) -> dict[str, bytes]:
    space = parameter_space(load_scenario(UIS2).root)
    indices = np.arange(4)
    rows = values_at(space, Plan("random", 4, seed=5), indices)
    config = BatchConfig(UIS2, out, space.paths, formats, stem="uis2")
    assert len(run_batch(config, indices, rows, executor=executor).records) == 4
    return {p.name: p.read_bytes() for p in sorted(out.iterdir()) if p.suffix in (".xosc", ".xmi")}


def test_only_a_forking_pool_says_its_workers_inherit() -> None:
    forks = "fork" in multiprocessing.get_all_start_methods()
    assert ProcessExecutor(2).inherits_imports is forks
    assert LocalExecutor().inherits_imports is False


def test_the_caller_prepares_the_export_once_for_inheriting_workers(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    prepared: list[str] = []
    monkeypatch.setattr(batch, "prepare_export", prepared.append)
    inherited = _run(tmp_path / "fork", _ForkLike(), ("xosc",))
    assert prepared == [DEFAULT_VERSION]
    plain = _run(tmp_path / "plain", LocalExecutor(), ("xosc",))
    assert prepared == [DEFAULT_VERSION]  # not again: these workers would not inherit it
    assert inherited == plain
    assert len(plain) == 4


def test_nothing_is_prepared_when_no_xosc_is_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    prepared: list[str] = []
    monkeypatch.setattr(batch, "prepare_export", prepared.append)
    assert len(_run(tmp_path / "xmi", _ForkLike(), ("xmi",))) == 4
    assert prepared == []


def test_preparing_leaves_the_exporter_the_template_and_the_schema_in_the_process() -> None:
    # A fresh interpreter: in this one, earlier tests may have compiled them already.
    script = (
        "import sys\n"
        "from sceml.levels.xosc import prepare_export\n"
        "from sceml.templating import environment\n"
        "from sceml.xosc import schema\n"
        "assert 'sceml.export.writer' not in sys.modules\n"
        f"prepare_export({DEFAULT_VERSION!r})\n"
        "print('sceml.export.writer' in sys.modules)\n"
        "print(sorted(key[1] for key in environment().cache))\n"
        "print(schema._lxml_schema.cache_info().currsize)\n"
    )
    ran = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert ran.returncode == 0, ran.stderr
    assert ran.stdout.splitlines() == ["True", "['openscenario.xosc.j2']", "1"]
