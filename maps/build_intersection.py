"""Build the four-way urban intersection map used by the SceML reference scenarios.

Usage::

    python maps/build_intersection.py [-o maps/intersection.xodr] [--positions FILE] [--plot PNG]

The road network is generated with ``scenariogeneration.xodr`` (CommonJunctionCreator):

* four straight arms (north, east, south, west), each ``ARM_LENGTH`` m long, starting on a
  circle of radius ``JUNCTION_RADIUS`` around the origin and pointing away from it;
* per arm one 3.5 m driving lane per direction (right-hand traffic) and a 2 m sidewalk on
  each outer side;
* one junction whose connecting roads cover every straight, left and right movement of the
  driving lanes, plus four corner sidewalks linking the sidewalks of neighbouring arms;
* a crosswalk object on every arm right at the junction boundary.

Besides the .xodr the script writes ``positions.json``: road/lane ids per arm and the start and
destination positions of the reference scenarios UIS1 and UIS2, in world coordinates and in
lane coordinates. World coordinates are evaluated from the generated geometry (pyclothoids).

The output is deterministic: the FileHeader ``date`` written by scenariogeneration is replaced
by a fixed value, so two runs give byte-identical files.
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import pyclothoids
from scenariogeneration import xodr
from scenariogeneration.helpers import prettify

HERE = Path(__file__).resolve().parent
DEFAULT_OUTPUT = HERE / "intersection.xodr"
DEFAULT_POSITIONS = HERE / "positions.json"

FIXED_DATE = "2024-01-01T00:00:00"
MAP_NAME = "sceml_intersection"

ARM_LENGTH = 100.0  # m
JUNCTION_RADIUS = 9.0  # m, distance from junction centre to the start of each arm
DRIVING_WIDTH = 3.5  # m
SIDEWALK_WIDTH = 2.0  # m
CROSSWALK_LENGTH = 2.0  # m, along the arm, starting at the junction boundary

JUNCTION_ID = 10
CONNECTING_ROAD_START_ID = 100

# Arm name -> (road id, direction from the junction centre in rad).
# Every arm starts at the junction (predecessor = junction) and points outwards, so on every
# arm lane -1 carries outbound traffic and lane 1 inbound traffic (right-hand traffic).
ARMS = {
    "north": (1, math.pi / 2),
    "east": (2, 0.0),
    "south": (3, -math.pi / 2),
    "west": (4, math.pi),
}
INBOUND_LANE, OUTBOUND_LANE = 1, -1
LEFT_SIDEWALK, RIGHT_SIDEWALK = 2, -2  # left/right as seen looking along the arm, outwards


def build_arm(road_id: int, direction: float) -> xodr.Road:
    """Create one straight arm starting on the junction circle and pointing outwards."""
    x0 = JUNCTION_RADIUS * math.cos(direction)
    y0 = JUNCTION_RADIUS * math.sin(direction)
    planview = xodr.PlanView(round(x0, 9), round(y0, 9), direction)
    planview.add_geometry(xodr.Line(ARM_LENGTH))

    section = xodr.LaneSection(0, xodr.standard_lane(0, xodr.std_roadmark_solid()))
    for add in (section.add_left_lane, section.add_right_lane):
        driving = xodr.Lane(xodr.LaneType.driving, a=DRIVING_WIDTH)
        driving.add_roadmark(xodr.std_roadmark_solid())
        add(driving)
        sidewalk = xodr.Lane(xodr.LaneType.sidewalk, a=SIDEWALK_WIDTH)
        sidewalk.add_roadmark(xodr.RoadMark(xodr.RoadMarkType.none))
        add(sidewalk)
    lanes = xodr.Lanes()
    lanes.add_lanesection(section)

    road = xodr.Road(road_id, planview, lanes)
    crosswalk = xodr.Object(
        s=CROSSWALK_LENGTH / 2,
        t=0.0,
        Type=xodr.ObjectType.crosswalk,
        id=str(road_id),
        name=f"crosswalk_{road_id}",
        width=2 * DRIVING_WIDTH,
        length=CROSSWALK_LENGTH,
    )
    road.add_object(crosswalk)
    return road


def build_network() -> tuple[xodr.OpenDrive, dict[str, int]]:
    """Build the OpenDRIVE network; return it and a movement-name -> connecting-road-id map."""
    odr = xodr.OpenDrive(MAP_NAME, revMajor="1", revMinor="7")
    creator = xodr.CommonJunctionCreator(JUNCTION_ID, "intersection", CONNECTING_ROAD_START_ID)
    for road_id, direction in ARMS.values():
        road = build_arm(road_id, direction)
        odr.add_road(road)
        creator.add_incoming_road_circular_geometry(
            road, JUNCTION_RADIUS, direction, road_connection="predecessor"
        )

    connecting: dict[str, int] = {}
    names = list(ARMS)
    # Driving lanes: from the inbound lane of every arm to the outbound lane of every other arm.
    for src in names:
        for dst in names:
            if src != dst:
                connecting[f"{src}->{dst}"] = creator.startnum
                creator.add_connection(ARMS[src][0], ARMS[dst][0], INBOUND_LANE, OUTBOUND_LANE)
    # Corner sidewalks: the left sidewalk of an arm joins the right sidewalk of the arm that
    # lies 90 degrees counter-clockwise from it (e.g. south/east sidewalk -> east/south one).
    for src, dst in (("south", "east"), ("east", "north"), ("north", "west"), ("west", "south")):
        connecting[f"sidewalk {src}->{dst}"] = creator.startnum
        creator.add_connection(ARMS[src][0], ARMS[dst][0], LEFT_SIDEWALK, RIGHT_SIDEWALK)
        lane = creator.junction_roads[-1].lanes.lanesections[0].rightlanes[0]
        lane.lane_type = xodr.LaneType.sidewalk
        lane.roadmark = [xodr.RoadMark(xodr.RoadMarkType.none)]

    odr.add_junction_creator(creator)
    odr.adjust_roads_and_lanes()
    return odr, connecting


def render(odr: xodr.OpenDrive) -> bytes:
    """Serialise the network with a fixed FileHeader date (deterministic output)."""
    root = odr.get_element()
    root.find("header").set("date", FIXED_DATE)
    for obj in root.iter("object"):  # scenariogeneration writes subtype="None" if unset
        if obj.get("subtype") == "None":
            del obj.attrib["subtype"]
    return prettify(root, encoding="utf-8")


# --- lane coordinates -> world coordinates ------------------------------------------------


def _reference_point(road: xodr.Road, s: float) -> tuple[float, float, float]:
    """Point and heading of the road reference line at ``s`` (line, arc and spiral)."""
    geoms = road.planview._adjusted_geometries
    start = 0.0
    for i, geom in enumerate(geoms):
        if s <= start + geom.length + 1e-9 or i == len(geoms) - 1:
            break
        start += geom.length
    kind = geom.geom_type
    k0 = k1 = 0.0
    if isinstance(kind, xodr.Arc):
        k0 = k1 = kind.curvature
    elif isinstance(kind, xodr.Spiral):
        k0, k1 = kind.curvstart, kind.curvend
    dk = (k1 - k0) / geom.length
    clothoid = pyclothoids.Clothoid.StandardParams(
        geom.x, geom.y, geom.heading, k0, dk, geom.length
    )
    ds = s - start
    return clothoid.X(ds), clothoid.Y(ds), clothoid.Theta(ds)


def _lane_centre_t(road: xodr.Road, lane_id: int, s: float) -> tuple[float, float]:
    """Lateral position of the lane centre and the lane width at ``s`` (single lane section)."""
    section = road.lanes.lanesections[0]
    lanes = section.leftlanes if lane_id > 0 else section.rightlanes
    inner = sum(lane.get_width(s) for lane in lanes[: abs(lane_id) - 1])
    width = lanes[abs(lane_id) - 1].get_width(s)
    return math.copysign(inner + width / 2, lane_id), width


def _wrap(angle: float) -> float:
    """Wrap an angle to [0, 2*pi)."""
    return round(angle % (2 * math.pi), 6) % (2 * math.pi)


def lane_position(
    odr: xodr.OpenDrive, road_id: int, lane_id: int, s: float, heading: float | None = None
) -> dict:
    """World and lane coordinates of a point on the centre of a lane.

    ``heading`` is the world heading of the actor; by default the driving direction of the lane
    (along s for negative lane ids, against s for positive ones, right-hand traffic).
    """
    road = odr.roads[str(road_id)]
    x, y, h = _reference_point(road, s)
    t, _ = _lane_centre_t(road, lane_id, s)
    if heading is None:
        heading = h if lane_id < 0 else h + math.pi
    return {
        "x": round(x - t * math.sin(h), 3),
        "y": round(y + t * math.cos(h), 3),
        "z": 0.0,
        "h": round(_wrap(heading), 6),
        "roadId": str(road_id),
        "laneId": lane_id,
        "s": round(s, 3),
        "offset": 0.0,
    }


def scenario_positions(odr: xodr.OpenDrive, connecting: dict[str, int]) -> dict:
    """Start/destination positions of the reference scenarios UIS1 and UIS2."""
    north, east, south, west = (ARMS[name][0] for name in ("north", "east", "south", "west"))
    left_turn = odr.roads[str(connecting["south->west"])]
    north_h = math.pi / 2
    ego_start = lane_position(odr, south, INBOUND_LANE, 30.0)
    uis1 = {
        "ego_start": ego_start,
        "ego_destination": lane_position(odr, east, OUTBOUND_LANE, 25.0),
        # The bike rides north on the east sidewalk of the south arm, follows the south-east
        # corner and crosses the east arm on its crosswalk, ending on the north sidewalk.
        "bike_start": lane_position(odr, south, LEFT_SIDEWALK, 15.0, north_h),
        "bike_destination": lane_position(odr, east, LEFT_SIDEWALK, 1.0, north_h),
    }
    uis2 = {
        "ego_start": ego_start,
        "ego_destination": lane_position(odr, west, OUTBOUND_LANE, 25.0),
        "oncoming_start": lane_position(odr, north, INBOUND_LANE, 30.0),
        # 30 m to the junction + 2 * JUNCTION_RADIUS through it + 12 m = 60 m drive distance.
        "oncoming_destination": lane_position(odr, south, OUTBOUND_LANE, 12.0),
        "intersection_location": lane_position(
            odr, left_turn.id, OUTBOUND_LANE, left_turn.planview.get_total_length() / 2
        ),
        # The pedestrian crosses the west arm on its crosswalk, from the south to the north
        # sidewalk, right where the left-turning ego enters the west arm.
        "pedestrian_start": lane_position(odr, west, LEFT_SIDEWALK, 1.0, north_h),
        "pedestrian_destination": lane_position(odr, west, RIGHT_SIDEWALK, 1.0, north_h),
    }
    return {"uis1": uis1, "uis2": uis2}


def map_description(connecting: dict[str, int]) -> dict:
    """Road ids, lane ids and lane types of the map (for scenario authors)."""
    arms = {
        name: {
            "roadId": str(road_id),
            "direction_from_centre": round(direction % (2 * math.pi), 6),
            "length": ARM_LENGTH,
            "driving": {"inbound": INBOUND_LANE, "outbound": OUTBOUND_LANE},
            "sidewalk": {"left": LEFT_SIDEWALK, "right": RIGHT_SIDEWALK},
        }
        for name, (road_id, direction) in ARMS.items()
    }
    return {
        "file": DEFAULT_OUTPUT.name,
        "junctionId": str(JUNCTION_ID),
        "junction_centre": {"x": 0.0, "y": 0.0},
        "junction_radius": JUNCTION_RADIUS,
        "lane_width": {"driving": DRIVING_WIDTH, "sidewalk": SIDEWALK_WIDTH},
        "arms": arms,
        "connecting_roads": {name: str(road_id) for name, road_id in connecting.items()},
    }


def plot(odr: xodr.OpenDrive, data: dict, path: Path) -> None:
    """Draw lane outlines and scenario positions to a PNG (needs matplotlib, optional)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fill = {"driving": "#d9d9d9", "sidewalk": "#f3d9a4"}
    fig, ax = plt.subplots(figsize=(11, 11))
    for road in odr.roads.values():
        section = road.lanes.lanesections[0]
        length = road.planview.get_total_length()
        samples = [length * i / 60 for i in range(61)]
        ref = [_reference_point(road, s) for s in samples]
        for lanes, sign in ((section.leftlanes, 1), (section.rightlanes, -1)):
            inner = 0.0
            for lane in lanes:
                outer = inner + lane.get_width(0)
                outline = [
                    (x - t * math.sin(h), y + t * math.cos(h))
                    for x, y, h in ref
                    for t in [sign * inner]
                ]
                outline += [
                    (x - t * math.sin(h), y + t * math.cos(h))
                    for x, y, h in reversed(ref)
                    for t in [sign * outer]
                ]
                in_junction = road.road_type != -1
                ax.fill(
                    *zip(*outline, strict=True),
                    facecolor=fill[lane.lane_type.name],
                    edgecolor="#1f77b4" if in_junction else "#555555",
                    linewidth=0.4,
                    alpha=0.35 if in_junction else 1.0,
                )
                inner = outer
        if road.road_type == -1:
            ax.annotate(f"road {road.id}", ref[-8][:2], ha="center", fontsize=9)
    for road_id, direction in ARMS.values():  # crosswalks, stripes along the arm
        road = odr.roads[str(road_id)]
        corners = [(s, t) for s, t in ((0, -1), (1, -1), (1, 1), (0, 1))]
        xy = []
        for s, t in corners:
            x, y, h = _reference_point(road, s * CROSSWALK_LENGTH)
            xy.append((x - t * DRIVING_WIDTH * math.sin(h), y + t * DRIVING_WIDTH * math.cos(h)))
        ax.fill(
            *zip(*xy, strict=True),
            facecolor="white",
            edgecolor="k",
            lw=0.3,
            hatch="||" if abs(math.cos(direction)) < 0.5 else "--",
        )

    conn = data["map"]["connecting_roads"]
    south, east, north, west = (ARMS[n][0] for n in ("south", "east", "north", "west"))
    routes = {  # (colour, linestyle, [(road, lane, s_from, s_to), ...])
        "uis1 ego": (
            "tab:red",
            "--",
            [(south, 1, 30, 0), (conn["south->east"], -1, 0, None), (east, -1, 0, 25)],
        ),
        "uis1 bike": (
            "tab:red",
            ":",
            [(south, 2, 15, 0), (conn["sidewalk south->east"], -1, 0, None), (east, -2, 0, 1)],
        ),
        "uis2 ego": (
            "tab:green",
            "--",
            [(south, 1, 30, 0), (conn["south->west"], -1, 0, None), (west, -1, 0, 25)],
        ),
        "uis2 oncoming": (
            "tab:green",
            "-.",
            [(north, 1, 30, 0), (conn["north->south"], -1, 0, None), (south, -1, 0, 12)],
        ),
    }
    for colour, style, legs in routes.values():
        points = []
        for road_id, lane_id, s_from, s_to in legs:
            road = odr.roads[str(road_id)]
            s_to = road.planview.get_total_length() if s_to is None else s_to
            for i in range(41):
                s = s_from + (s_to - s_from) * i / 40
                pos = lane_position(odr, road_id, lane_id, s)
                points.append((pos["x"], pos["y"]))
        ax.plot(*zip(*points, strict=True), color=colour, linestyle=style, linewidth=1.2)
    for scenario, colour in (("uis1", "tab:red"), ("uis2", "tab:green")):
        crossing = [data[scenario][k] for k in data[scenario] if k.startswith(("bike_d", "ped"))]
        if scenario == "uis1":
            crossing.insert(0, lane_position(odr, east, -2, 1.0))
        ax.plot([p["x"] for p in crossing], [p["y"] for p in crossing], color=colour, ls=":")

    seen = {}
    for scenario, colour in (("uis1", "tab:red"), ("uis2", "tab:green")):
        for name, pos in data[scenario].items():
            key = (pos["x"], pos["y"], pos["h"])
            if key in seen:  # UIS2 reuses the UIS1 ego start
                continue
            seen[key] = name
            ax.plot(pos["x"], pos["y"], marker="o", color=colour, markersize=5)
            dx, dy = 2.5 * math.cos(pos["h"]), 2.5 * math.sin(pos["h"])
            ax.arrow(
                pos["x"], pos["y"], dx, dy, color=colour, width=0.15, length_includes_head=True
            )
            label = "uis1+uis2" if name == "ego_start" else scenario
            ax.annotate(
                f"{label}.{name}\n(road {pos['roadId']}, lane {pos['laneId']}, s={pos['s']:g})",
                (pos["x"], pos["y"]),
                xytext=(6, -18),
                textcoords="offset points",
                fontsize=7,
                color=colour,
            )
    ax.set_aspect("equal")
    ax.set_xlim(-45, 45)
    ax.set_ylim(-45, 45)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(
        "intersection.xodr, central 90 m x 90 m; grey: driving, "
        "beige: sidewalk; UIS1 red, UIS2 green",
        fontsize=9,
    )
    ax.grid(True, linewidth=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", type=Path, default=DEFAULT_OUTPUT, help=".xodr file")
    parser.add_argument(
        "--positions", type=Path, default=None, help="positions.json (default: next to output)"
    )
    parser.add_argument("--plot", type=Path, default=None, help="also draw a PNG (matplotlib)")
    args = parser.parse_args(argv)
    positions_path = args.positions or args.output.with_name(DEFAULT_POSITIONS.name)

    odr, connecting = build_network()
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_bytes(render(odr))
    data = {"map": map_description(connecting), **scenario_positions(odr, connecting)}
    positions_path.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    print(f"wrote {args.output} and {positions_path}")
    if args.plot:
        plot(odr, data, args.plot)
        print(f"wrote {args.plot}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
