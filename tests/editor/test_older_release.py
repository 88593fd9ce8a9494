"""The editor opens a file saved with an older metamodel release and offers to save it in the
current one; saving does, and the offer goes away."""

from __future__ import annotations

import shutil
from pathlib import Path

from metamodel_releases import CURRENT

from sceml.editor import EditorSession, SessionOptions

HISTORY_10 = Path(__file__).resolve().parents[2] / "metamodel" / "history" / "1.0"


def test_an_older_file_is_offered_for_saving_in_the_current_release(tmp_path: Path) -> None:
    shutil.copytree(HISTORY_10 / "examples", tmp_path / "examples")
    shutil.copytree(HISTORY_10 / "maps", tmp_path / "maps")
    (tmp_path / ".sceml-root").touch()
    scenario = tmp_path / "examples" / "uis2-concrete.xmi"
    session = EditorSession(SessionOptions())
    view = session.open(scenario)
    assert view["document"]["olderRelease"] == {"saved": "1.0", "current": CURRENT}
    assert not view["dirty"]  # the model is as the file says; only its release is older
    assert [n["name"] for n in view["nodes"] if n["name"] == "TurnLeft_1"] == ["TurnLeft_1"]
    view = session.save()
    assert "olderRelease" not in view["document"]
    assert (
        f'xmlns:scemlmodel="https://sceml.org/metamodel/{CURRENT}"'.encode()
        in scenario.read_bytes()
    )
    # Its library stays as it is until it is saved itself: the editor saved only the scenario.
    library = tmp_path / "examples" / "library" / "sceml-library.xmi"
    assert b"metamodel/1.0" in library.read_bytes()


def test_a_current_file_has_no_offer(open_example) -> None:
    assert "olderRelease" not in open_example("uis1-concrete.xmi").view()["document"]
