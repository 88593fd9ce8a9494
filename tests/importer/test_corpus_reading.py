"""How benchmarks/import_corpus.py reads esmini's runs (issue 24's comparison).

esmini's CSV header names the entities of the first step only; the vehicles a swarm adds come
in later blocks of the same width. `swarm-small.csv` is esmini 3.6's recording of the
hand-written `swarm-small.xosc` (--seed 1): the ego and one car the swarm adds at t = 0. The
header's block ends in a trailing comma: read as one column wider, the added car's block was
taken from the wrong columns (an entity named `1`, its id; `swarm.xosc`'s comparison reported
"entity 1.246974 is missing").
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

from conftest import REPO

FILES = Path(__file__).resolve().parent / "files"


def _corpus_module():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location(
        "import_corpus", REPO / "benchmarks" / "import_corpus.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    # Its dataclasses look their module up while they are made.
    sys.modules.setdefault(spec.name, module)
    spec.loader.exec_module(module)
    return sys.modules[spec.name]


def test_entities_a_swarm_adds_are_read_by_their_names_and_positions() -> None:
    paths, end = _corpus_module()._paths(FILES / "swarm-small.csv")
    assert sorted(paths) == ["Ego", "swarm_0"]
    assert end == 0.55
    # Every step of the run, each at the time stamp of its row (12 rows, 0 to 0.55 s).
    assert [len(path) for path in paths.values()] == [12, 12]
    # The ego starts at road 1, lane -1, s 300 of highway.xodr (the lane's centre, y -1.75).
    assert paths["Ego"][0] == (0.0, 300.0, -1.75)
    # The added car, read from its own columns: 20 m/s along lane -2 (y -5.25), 11 m in 0.55 s.
    assert paths["swarm_0"][0] == (0.0, 240.900001, -5.25)
    assert paths["swarm_0"][-1] == (0.55, 251.900001, -5.25)
