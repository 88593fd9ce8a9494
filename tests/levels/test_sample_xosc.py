"""The batch's XSD check of a sample sets its numbers into one parsed tree instead of parsing
each sample's bytes: its verdicts must be those of parsing the bytes and validating them."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from lxml import etree

from sceml.levels import xosc
from sceml.levels.batch import BatchConfig, Worker
from sceml.levels.sampling import Plan, design
from sceml.levels.space import parameter_space
from sceml.model.loading import load_scenario
from sceml.xosc import schema

#: UIS1 (tests/levels/test_batch.py covers UIS2's derived delay on the same path).
LOGICAL = Path(__file__).resolve().parents[2] / "examples" / "uis1-logical.xmi"


@pytest.fixture(scope="module")
def worker(tmp_path_factory: pytest.TempPathFactory) -> Worker:
    space = parameter_space(load_scenario(LOGICAL).root)
    config = BatchConfig(LOGICAL, tmp_path_factory.mktemp("out"), space.paths, ("xosc",), "1.3")
    return Worker(config)


def _parsed_verdict(data: bytes) -> str:
    """The XSD verdict on a document's bytes, parsed afresh as any reader would."""
    issues = schema.validate_tree(etree.fromstring(data), "1.3")
    return f"xsd: {issues[0].reason}" if issues else ""


def _rows() -> list[list[float]]:
    space = parameter_space(load_scenario(LOGICAL).root)
    drawn = [[float(v) for v in row] for row in design(space, Plan("random", 40, seed=5))]
    odd = [float("nan"), float("inf"), -0.0, 1e300, 5e-324, -2.5]
    # Numbers the XSD refuses (nan, inf: it spells them NaN and INF) or that look unusual.
    return drawn + [[value] * len(drawn[0]) for value in odd]


def test_the_tree_check_gives_the_verdict_of_parsing_the_bytes(worker: Worker) -> None:
    fast = worker.fast
    assert fast is not None
    verdicts = []
    for row in _rows():
        verdict = fast.schema_problem(row)
        assert verdict == _parsed_verdict(fast.render(row)), row
        verdicts.append(verdict)
    assert "" in verdicts and any(v.startswith("xsd: ") for v in verdicts)


def test_a_sample_is_checked_without_parsing_it(
    worker: Worker, monkeypatch: pytest.MonkeyPatch
) -> None:
    fast = worker.fast
    assert fast is not None

    def no_parsing(*args: object, **kwargs: object) -> object:
        raise AssertionError("a sample was parsed")

    monkeypatch.setattr(etree, "fromstring", no_parsing)  # the module xosc parses with
    assert fast.schema_problem([5.0, 7.0, 4.0, 10.0, 15.0, 1.5]) == ""
    assert fast.schema_problem([float("nan")] * 6).startswith("xsd: ")


def test_placeholders_are_found_only_in_attribute_values() -> None:
    in_attributes = b'<a x="$SceMLsample0"><b y="p$SceMLsample1q$SceMLsample0"/></a>'
    tree = xosc._SlottedTree.of(in_attributes, 3)
    assert tree is not None
    filled = tree.filled(["1.5", "-2.0"])
    assert etree.tostring(filled) == b'<a x="1.5"><b y="p-2.0q1.5"/></a>'
    assert tree.agrees(["1.5", "-2.0"], b'<a x="1.5"><b y="p-2.0q1.5"/></a>')
    assert not tree.agrees(["1.5", "-2.0"], b'<a x="1.5"><b y="p-2.0q1.50"/></a>')
    # One placeholder in text: the tree cannot hold it, so samples are parsed instead.
    in_text = b'<a x="$SceMLsample0"><b>$SceMLsample1</b></a>'
    assert xosc._SlottedTree.of(in_text, 2) is None


# Texts a number's slot could receive, and near misses: every spelling of infinity and NaN,
# exponents, signs, blanks, parameter references and expressions, and junk.
_TEXTS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.integers(min_value=-(2**70), max_value=2**70).map(str),
    st.sampled_from(["INF", "-INF", "+INF", "NaN", "nan", "1e", ".5", "5.", " 1.5 ", "", "$x"]),
    st.sampled_from(["${1 + 2}", "${$x * 2}", "1,5", "0x10", "1_000", "+1.5E+3", "-0"]),
    st.text(alphabet="0123456789.eE+-INFNa $", max_size=8),
)


@pytest.mark.parametrize(
    ("name", "version"),
    [
        (name, version)
        for name in ("uis1-logical.xmi", "uis2-logical.xmi", "overtaking-logical.xmi")
        for version in ("1.0", "1.1", "1.2", "1.3")
        # A DriveDistance's delay is an expression of sampled values, which 1.0 cannot write:
        # there, every sample of UIS2 and the overtaking is exported in full.
        if version != "1.0" or name == "uis1-logical.xmi"
    ],
)
def test_checking_the_sampled_values_alone_gives_the_whole_documents_verdict(
    name: str, version: str, tmp_path: Path
) -> None:
    logical = LOGICAL.parent / name
    space = parameter_space(load_scenario(logical).root)
    fast = Worker(BatchConfig(logical, tmp_path, space.paths, ("xosc",), version)).fast
    assert fast is not None
    slotted, values = fast._tree, fast._values
    assert slotted is not None and values is not None  # the values-only check is in use
    count = len(fast.texts([1.0] * len(space.paths)))
    whole = []

    @settings(max_examples=150, deadline=None, database=None)
    @given(st.lists(_TEXTS, min_size=count, max_size=count))
    def same_verdict(texts: list[str]) -> None:
        verdict = schema.is_valid_tree(slotted.filled(texts), version)
        assert values.valid(slotted.values(texts)) == verdict, texts
        whole.append(verdict)

    same_verdict()
    assert True in whole and False in whole  # both verdicts were reached
