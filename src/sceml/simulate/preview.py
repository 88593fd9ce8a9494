"""Run a concrete scenario in the preview: set up, schedule, record, measure."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

import scemlmodel as scm

from ..maps import RoadMap, load_map
from ..maps.reference import map_reference
from ..maps.resolve import start_poses
from ..model.documents import allowed_roots_of
from ..model.graph import actors as scenario_actors
from ..model.graph import root_node, scenario_level
from ..model.params import concrete
from ..model.towing import couplings, is_towed
from ..modules.flatten import Flattened, expand
from ..xosc import PLAYER_STEP
from . import trailers
from .engine import Scheduler, run_schedule
from .global_values import initial_values
from .limits import located_in, refuse_unresolved, refuse_unusable
from .metrics import pair_metrics
from .run import ActorInfo, Run
from .setup import make_actor, trailer_at_rest
from .world import SimulationError, World

#: The default time step (s): fine enough for walking and urban speeds.
DEFAULT_STEP = PLAYER_STEP


def simulate(
    scenario: scm.Scenario,
    scenario_file: str | Path | None = None,
    *,
    step: float = DEFAULT_STEP,
    road_map: RoadMap | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> Run:
    """Run a concrete scenario with kinematic actors on its map (module uses flattened first).

    The map is the OpenDRIVE file the root names, relative to `scenario_file`, unless
    `road_map` is given. SimulationError when the scenario is not concrete or cannot be set up.
    `progress` is called with (steps done, most steps) now and then on long runs. Every
    SimulationError names the file and, where it can be found, the line of what it is about.
    """
    try:
        return _simulate(scenario, scenario_file, step, road_map, progress)
    except SimulationError as error:
        raise located_in(error, scenario, scenario_file) from None


def _simulate(
    scenario: scm.Scenario,
    scenario_file: str | Path | None,
    step: float,
    road_map: RoadMap | None,
    progress: Callable[[int, int], None] | None,
) -> Run:
    if not step > 0:
        raise SimulationError(f"the time step must be positive, got {step:g} s")
    root = root_node(scenario)
    if root is None:
        raise SimulationError("the scenario has no root node")
    level = scenario_level(scenario)
    if level != "concrete":
        raise SimulationError(
            f"the preview runs concrete scenarios; this one is {level} "
            "(concretize or sample it first)",
            element=str(root.name),
        )
    refuse_unresolved(scenario)
    flattened = (
        expand(scenario)
        if any(isinstance(n, scm.ModuleUse) for n in scenario.nodes)
        else Flattened(scenario)
    )
    refuse_unusable(flattened, step)  # before anything is allocated by what the values say
    flat = flattened.scenario
    flat_root = root_node(flat)
    assert flat_root is not None
    if road_map is None:
        road_map = _road_map(flat_root, scenario_file, allowed_roots_of(scenario))
    world = World(road_map, {}, step, values=initial_values(flat_root))
    actors = scenario_actors(flat)
    starts = start_poses(actors, road_map)
    for actor in actors:
        world.actors[str(actor.name)] = (
            make_actor(actor, road_map, starts)
            if actor.startPosition is not None or not is_towed(actor)
            else trailer_at_rest(actor)
        )
    world.couplings = couplings(actors)
    trailers.couple(world.actors, world.couplings)
    scheduler = Scheduler(list(flat.nodes), world)
    names = list(world.actors)
    times: list[float] = []
    rows: list[list[tuple[float, float, float, float]]] = []

    def record() -> None:
        times.append(world.t)
        rows.append([(a.x, a.y, a.heading, a.speed) for a in world.actors.values()])

    reason = run_schedule(scheduler, concrete(flat_root, "maxDuration"), record, progress)
    states = np.array(rows, dtype=float).reshape(len(rows), len(names), 4).transpose(1, 0, 2)
    states[:, :, 2] = np.unwrap(states[:, :, 2], axis=1)
    time_array = np.array(times)
    towers = {**world.towed_by, **{link.trailer: link.tower for link in world.couplings}}
    infos = tuple(
        ActorInfo(a.name, a.kind, a.ego, a.length, a.width, a.box_ahead, towers.get(a.name, ""))
        for a in world.actors.values()
    )
    return Run(
        str(root.scenarioName or root.name or "scenario"),
        step,
        time_array,
        infos,
        states,
        scheduler.timeline(),
        reason,
        world.t,
        pair_metrics(time_array, infos, states),
        tuple(world.notes),
    )


def _road_map(
    root: scm.RootNode, scenario_file: str | Path | None, roots: list[Path] | None
) -> RoadMap | None:
    reference = map_reference(root.map, scenario_file, roots)
    if reference is None or reference.path is None:
        return None  # no map, or a simulator town: world positions only
    return load_map(reference.path, reference.roots)
