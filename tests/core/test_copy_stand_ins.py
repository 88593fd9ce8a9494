"""`Copier(stand_ins=...)`: single references to a stand-in's original point at the stand-in in
the copies, as a module use binds its definition's roles to actors while copying it."""

from __future__ import annotations

from pathlib import Path

import scemlmodel as scm
from sceml.model.copying import Copier
from sceml.model.loading import load_library

LIBRARY = Path(__file__).resolve().parents[2] / "examples" / "library" / "sceml-library.xmi"


def test_roles_become_the_actors_standing_in_for_them() -> None:
    crossing = load_library(LIBRARY).root.modules[0]
    assert crossing.name == "CrossingManeuver"
    roles = {str(role.name): role for role in crossing.roles}
    walker, car = scm.Pedestrian(name="walker"), scm.Car(name="car")
    copier = Copier(stand_ins={roles["crosser"]: walker, roles["trigger"]: car})
    copies = copier.copy_all(crossing.nodes)
    copier.copy_references()
    by_name = {str(node.name): node for node in copies}
    # In the library: InVehicleRadius_1 is the crosser's, watching the trigger; the other
    # three nodes are the crosser's.
    radius = by_name["InVehicleRadius_1"]
    assert radius.referenceActor is walker
    assert radius.targetActor is car
    for name in ("Accelerate_1", "Cross_1", "InLocationRadius_1"):
        assert by_name[name].referenceActor is walker
    # pyecore's record of who refers to what names the actors, not the roles.
    reference_actor = scm.ActionNode.referenceActor
    assert (radius, reference_actor) in walker._inverse_rels
    assert (radius, scm.InVehicleRadius.targetActor) in car._inverse_rels
    assert not any(source in copies for source, _ in roles["crosser"]._inverse_rels)
    # Anything else keeps its target: a parameter reference still names the module's parameter.
    speed = by_name["Accelerate_1"].targetSpeed
    assert isinstance(speed, scm.ParameterRef)
    assert speed.parameter is crossing.parameters[1]
    # The originals are untouched.
    assert crossing.nodes[2].referenceActor is roles["crosser"]
