"""A walk on a cue starts in the step its condition and delay hold after the round trip (issue
24, `traffic_lights`' walkers): files/walk-on-cue.xosc's Walk event (a speed change and a path)
waits for the ego within 20 m of the crosswalk, then 0.5 s. The export writes the distance and
its delay into the walk's own StartTrigger, with no marker event for them, and the path's
arrival marker waits for the walk's event to have started, not for the distance again.

Worked by hand from the file: the ego starts 26 m before the crosswalk at 8 m/s, so it is
within 20 m from 0.75 s (esmini first sees `lessThan 20` hold at 0.80 s, and starts Walk at
1.30 s, the original and the re-export alike; with a marker event for the distance the
re-export started it at 1.35 s)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model.loading import load
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "walk-on-cue.xosc"


def states(event: etree._Element) -> set[tuple[str, str]]:
    return {
        (str(c.get("storyboardElementRef")), str(c.get("state")))
        for c in event.iter("StoryboardElementStateCondition")
    }


@pytest.mark.parametrize("version", ("1.1", "1.2", "1.3"))
def test_the_walk_waits_for_its_cue_in_its_own_trigger(
    version: str, tmp_path: Path, same: Callable[[scm.Scenario, scm.Scenario], None]
) -> None:
    model = tmp_path / "walk.xmi"
    import_to_file(SOURCE, model)
    exported = tmp_path / "walk.xosc"
    export_to_file(load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    document = etree.parse(str(exported)).getroot()
    events = {str(e.get("name")): e for e in document.iter("Event")}
    assert "HeroNear" not in events  # no marker event for the distance
    for walk in ("Walk", "Walk_2"):  # the speed change and the path
        (group,) = events[walk].iterfind("StartTrigger/ConditionGroup")
        # 1.1 writes the radius as a ReachPositionCondition (deprecated from 1.2 on).
        (near,) = group.iterfind("Condition/ByEntityCondition/EntityCondition/*")
        assert near.get("value", near.get("tolerance")) == "20.0"
        assert near.getparent().getparent().getparent().get("delay") == "0.5"
    assert states(events["Walk_2__arrived"]) == {
        ("Walk_2", "runningState"),
        ("Walk_2", "completeState"),
    }
    # Read again: the same scenario (the arrival marker folds back into the path). The file
    # sets no environment; the export writes SceML's default one, which reads back.
    first = import_file(SOURCE).scenario
    first.nodes[0].environment = scm.Environment()
    same(first, import_file(exported).scenario)
