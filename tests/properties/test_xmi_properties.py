"""Properties of the XMI readers and writer: random valid scenarios survive a round trip, and
random damage to real files ends in a SceML error, never a traceback or a hang."""

from __future__ import annotations

import signal
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from strategies import scenarios as shared_scenarios

import scemlmodel as scm
from sceml.cli import cli
from sceml.errors import SceMLError
from sceml.model.build import ScenarioBuilder, lane, world
from sceml.model.compare import differences
from sceml.model.loading import load, unresolved_references
from sceml.model.saving import save

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SOURCES = [EXAMPLES / "uis1-concrete.xmi", EXAMPLES / "uis2-logical.xmi"]
PROPERTY = settings(
    max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)

finite = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False).map(lambda x: round(x, 3))
KINDS = ["Accelerate", "Decelerate", "KeepVelocity", "DriveDistance", "TimeElapsed", "Stop"]


@st.composite
def scenarios(draw: st.DrawFn) -> scm.Scenario:
    """A scenario of random actors and action nodes in parallel chains from root to end."""
    # XML 1.0 cannot carry control characters or lone surrogates (save refuses them).
    name = st.text(st.characters(exclude_categories=("Cc", "Cs")), min_size=1, max_size=12)
    builder = ScenarioBuilder(draw(name), level="concrete")
    actors = []
    for index in range(draw(st.integers(1, 3))):
        start = draw(
            st.one_of(
                st.builds(world, finite, finite),
                st.builds(lane, st.integers(1, 9), st.integers(-(2**31), 2**31 - 1), finite),
            )
        )
        kind = draw(st.sampled_from(["Car", "Bicycle", "Pedestrian", "Truck"]))
        actors.append(
            builder.actor(kind, f"a{index}", ego=index == 0, start=start, speed=draw(finite))
        )
    for _ in range(draw(st.integers(1, 3))):
        chain = [builder.root]
        for _ in range(draw(st.integers(1, 4))):
            node = builder.add(draw(st.sampled_from(KINDS)), draw(st.sampled_from(actors)))
            chain.append(node)
        builder.chain(*chain, builder.end)
    return builder.scenario


@PROPERTY
@given(scenario=scenarios())
def test_random_scenarios_round_trip_unchanged(tmp_path: Path, scenario: scm.Scenario) -> None:
    path = save(scenario, tmp_path / "random.xmi")
    assert differences(scenario, load(path).root) == []


@PROPERTY
@given(data=st.data())
def test_shared_random_scenarios_round_trip(tmp_path: Path, data: st.DataObject) -> None:
    level = data.draw(st.sampled_from(["functional", "logical", "concrete"]))
    scenario = data.draw(shared_scenarios(level))
    path = save(scenario, tmp_path / "random.xmi")
    reloaded = load(path).root
    assert differences(scenario, reloaded) == []


@contextmanager
def deadline(seconds: int = 20) -> Iterator[None]:
    """Fail instead of hanging."""

    def expire(signum: int, frame: object) -> None:
        raise TimeoutError(f"took longer than {seconds} s")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def _load_and_walk(path: Path) -> None:
    """What a tool does with a file: load it, resolve its references, walk everything."""
    try:
        document = load(path)
    except SceMLError:
        return
    list(unresolved_references(document.root))
    for obj in document.root.eAllContents():
        for feature in obj.eClass.eAllStructuralFeatures():
            obj.eGet(feature)


def _check_cli(path: Path) -> None:
    with deadline():
        result = CliRunner().invoke(cli, ["info", str(path)])
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"traceback on {path.read_bytes()[:200]!r}") from result.exception
    assert result.exit_code in (0, 1, 2)


@PROPERTY
@given(
    source=st.sampled_from(SOURCES),
    edits=st.lists(
        st.tuples(st.floats(0, 1), st.binary(min_size=0, max_size=4)), min_size=1, max_size=4
    ),
)
def test_byte_mutations_never_crash(tmp_path: Path, source: Path, edits: list) -> None:
    data = bytearray(source.read_bytes())
    for where, replacement in edits:
        at = int(where * (len(data) - 1))
        data[at : at + len(replacement) or at + 1] = replacement
    path = tmp_path / source.name
    path.write_bytes(bytes(data))
    with deadline():
        _load_and_walk(path)
    _check_cli(path)


TOKENS = [
    b'"//@nodes.0"',
    b'"//@nodes.99"',
    b'"#//"',
    b'"-1"',
    b'"1e400"',
    b'"scemlmodel:Flow"',
    b'"scemlmodel:Value"',
    b'"true"',
    b'"x"',
    b"",
    b'"library/sceml-library.xmi#X"',
]


@PROPERTY
@given(
    source=st.sampled_from(SOURCES),
    choices=st.lists(
        st.tuples(st.integers(0, 10**6), st.sampled_from(TOKENS)), min_size=1, max_size=3
    ),
    drop=st.lists(st.integers(0, 10**6), max_size=2),
)
def test_structure_mutations_never_crash(
    tmp_path: Path, source: Path, choices: list, drop: list
) -> None:
    # Swap attribute values for other plausible ones, and delete whole lines (elements).
    lines = source.read_bytes().splitlines(keepends=True)
    for index in drop:
        del lines[index % len(lines)]
    data = b"".join(lines)
    for index, token in choices:
        quoted = [i for i, byte in enumerate(data) if byte == ord('"')]
        if len(quoted) < 2:
            break
        start = quoted[(index % (len(quoted) // 2)) * 2]
        end = data.index(b'"', start + 1) + 1
        data = data[:start] + (token or b'""') + data[end:]
    path = tmp_path / source.name
    path.write_bytes(data)
    (tmp_path / "library").mkdir(exist_ok=True)
    (tmp_path / "library" / "sceml-library.xmi").write_bytes(
        (EXAMPLES / "library" / "sceml-library.xmi").read_bytes()
    )
    with deadline():
        _load_and_walk(path)
    _check_cli(path)
