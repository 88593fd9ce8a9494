"""The corpus of invalid models: it is what make_corpus.py builds, and each file gives exactly the
codes its MANIFEST line lists."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from sceml.model.loading import load
from sceml.validation import REGISTRY, iter_diagnostics

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus"

#: Rules the corpus (validated without options) cannot show, each tested elsewhere: load
#: refuses duplicate module names (IDs) itself, so M014 fires on models built in memory
#: (test_rules.py); E003 needs an export profile or version (tests/cli/test_rules_fire.py), and
#: so does E007 (tests/importer/test_cli_and_editor.py) and E008 (test_rules.py). R009 needs a
#: shoulder, stop or parking lane, which the corpus's map has not (test_edge_lanes.py).
NOT_IN_CORPUS = {
    "SCEML-M014",
    "SCEML-E003",
    "SCEML-E007",
    "SCEML-E008",
    "SCEML-Y003",
    "SCEML-R009",
}


def manifest() -> list[tuple[str, set[str]]]:
    entries = []
    for line in (CORPUS / "MANIFEST").read_text(encoding="utf-8").splitlines():
        name, *codes = line.split()
        entries.append((name, set(codes)))
    return entries


def test_committed_corpus_equals_the_script_output(tmp_path: Path) -> None:
    spec = importlib.util.spec_from_file_location("make_corpus", HERE / "make_corpus.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    written = module.build_all(tmp_path)
    committed = {p.relative_to(CORPUS) for p in CORPUS.rglob("*") if p.is_file()}
    assert {p.relative_to(tmp_path) for p in written} == committed
    for path in written:
        relative = path.relative_to(tmp_path)
        assert path.read_bytes() == (CORPUS / relative).read_bytes(), f"{relative} is stale"


@pytest.mark.parametrize(("name", "codes"), manifest(), ids=[n for n, _ in manifest()])
def test_case_gives_exactly_its_codes(name: str, codes: set[str]) -> None:
    document = load(CORPUS / name)
    found = list(iter_diagnostics(document.root, document=document))
    assert {d.code for d in found} == codes, "\n".join(str(d) for d in found)
    for diagnostic in found:
        assert diagnostic.file is not None and diagnostic.line is not None, diagnostic
        assert diagnostic.fragment is not None and diagnostic.fragment.startswith("/")


def test_every_rule_fails_somewhere_in_the_corpus() -> None:
    covered = set().union(*(codes for _, codes in manifest()))
    registered = {rule.code for rule in REGISTRY.rules()}
    assert registered - NOT_IN_CORPUS <= covered
    assert covered <= registered


def test_corpus_has_cases_with_several_faults() -> None:
    assert sum(1 for _, codes in manifest() if len(codes) >= 5) >= 3
