"""Level kinds of the thirty-ninth held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each a few hundred navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py``, ``level_kinds30.py`` and ``level_kinds38.py`` (imported, not copied): ``ski_lodge``
(a lodge of split-level floor plates 0.75-1.6 m apart, each pair joined by *one open-sided half-flight of 5-9 risers*
whose width is drawn per flight from 1.0-1.8 m, a sunken fireplace pit), ``shell_bowls`` (a battlefield of shell
craters as bowls *whose inner walls stand at a slope drawn per bowl from 25-55 degrees*, so a bowl over the 45-degree
limit is a trap), ``airport_pier`` (a pier whose satellite is reached only along *travelator lanes 1.0-1.4 m wide
between a wall and a balustrade*, belts 0.05 m up, and whose aircraft are boarded along *glazed jet bridges 1.4-2.4 m
wide* sloping 0-4 degrees, drawn per bridge), ``cliff_path`` (a path winding up a butte, a shelf with a wall on one
side and a drop on the other *whose width is drawn per stretch from 1.0-1.8 m, or a pinch of 0.6-1.0 m*, pinches under
the agent's 1 m cutting it), ``cellar_stairs`` (terraced houses whose cellars are reached down a stair *under the
ground floor's edge, whose clearance over the tread it overhangs is drawn per house, about 1.65-2.33 m*, about the
agent's 2 m) and ``stack_tiers`` (a library's cast-iron book stack of 4-5 tiers *2.35-2.7 m apart floor to floor*,
aisles between ranges 0.8-1.3 m wide, tiers joined by *enclosed stairs 1.0-1.6 m wide*, drawn per stair).

Measured in docs/analysis_quality.md, "A thirty-ninth round of level kinds".

Run: ``.venv/bin/python benchmarks/level_kinds39.py OUT_DIR [--kinds ski_lodge stack_tiers] [--seeds 0 1 2]``
writes ``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _lid, _ridged, _Solids, _trunk
from level_kinds import main as write_kinds
from level_kinds30 import _placed
from level_kinds38 import AGENT_DIAMETER, AGENT_SLOPE

AGENT_HEIGHT = 2.0
"""The presets' agent's height, metres: the head room a player needs, by which the plans' answers read."""

TREAD = 0.28
"""The going of every flight's step, metres."""


def ski_lodge_plan(seed: int) -> dict:
    """The plan of :func:`ski_lodge` for ``seed``: the lodge's depth (z), per plate its x range and floor height, per
    boundary between plates its flight (risers, riser height, width, z centre, whether it climbs along +x) and the pit
    (its plate, its x and z ranges, depth and steps). O(plates)."""
    rng = np.random.default_rng(seed)
    depth = float(rng.uniform(16.0, 20.0))
    count = int(rng.integers(9, 12))
    pit_plate = int(rng.integers(2, count - 2))
    lengths = [float(rng.uniform(11.0, 12.0)) if i == pit_plate else float(rng.uniform(6.0, 9.0)) for i in range(count)]
    xs = np.concatenate([[0.0], np.cumsum(lengths)])
    heights, flights = [0.0], []
    for _ in range(count - 1):
        risers, riser = int(rng.integers(5, 10)), float(rng.uniform(0.15, 0.18))
        rise = risers * riser
        up = rng.random() < 0.6 or heights[-1] - rise < 0.0
        width = float(rng.uniform(1.0, 1.8))
        flights.append({"risers": risers, "riser": riser, "width": width, "up": bool(up),
                        "z": float(rng.uniform(width / 2 + 2.0, depth - width / 2 - 2.0))})
        heights.append(heights[-1] + rise if up else heights[-1] - rise)
    px = (float(xs[pit_plate] + xs[pit_plate + 1]) / 2)
    pit_depth = float(rng.uniform(0.5, 0.7))
    pz = float(rng.uniform(4.5, depth - 4.5))
    pit = {"plate": pit_plate, "x": (px - 2.2, px + 2.2), "z": (pz - 2.2, pz + 2.2), "depth": pit_depth,
           "risers": math.ceil(pit_depth / 0.18)}
    return {"depth": depth, "xs": [float(x) for x in xs], "heights": heights, "flights": flights, "pit": pit}


def ski_lodge(seed: int) -> trimesh.Trimesh:
    """A ski lodge (a chalet level of a winter resort, a stealth game's mountain retreat) of 9-11 *split-level floor
    plates* in a row along x, 6-9 m long (one 11-12 m, holding the pit) and 16-20 m deep (``ski_lodge_plan(seed)``),
    each 0.75-1.62 m above or below the one before it (up in about three of five), so every face between plates is a
    wall to a walker; each pair of neighbouring plates is joined by *one half-flight of 5-9 risers of 0.15-0.18 m* (goings
    0.28 m) standing on the lower plate square to the face, 2 m or more from the side walls, *open on both sides* (its
    sides drop to the lower plate by up to its rise) and *1.0-1.8 m wide, drawn per flight*; the higher plate's edge
    is railed 1 m high but at the flight's head. The pit plate holds a sunken fireplace pit 4.4 m square, 0.5-0.7 m
    deep (over the climb), entered down 3-4 risers 1.4 m wide along its west side, a hearth in its middle. Sofas
    (0.45 m high), tables (0.75 m) and timber posts (to the roof) stand on the plates off the flights' ways; walls
    4 m over the highest plate, no roof.

    Expected (written before the first run): a player (1 m across, climbing 0.4 m) walks every flight (each riser under
    the climb, each flight at least 1.0 m wide) and the pit's steps, so *one area* on every seed with every plate and
    the pit reached (10 / 11 / 9 plates on seeds 0-2). Flights of 1.0-1.3 m on open sides are about what the navmesh
    keeps (round 36 lost bridges without rails under about 1.55 m): by the plan 3 / 3 / 1 flights under 1.3 m (the
    narrowest 1.14 / 1.11 / 1.27 m) and 7 / 5 / 6 under 1.55 m, of 9 / 10 / 8, each the only way between its plates,
    so the navmesh route may part the row there (a plate or a run of plates apart per lost flight); the sampling
    route's walk test is the body, which a 1.0 m flight fits. Traffic highest on the flights
    and along the plates' middles, the pit a dead end."""
    plan = ski_lodge_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    xs, heights, depth = plan["xs"], plan["heights"], plan["depth"]
    top = max(heights) + 4.0
    s = _Solids()
    s.wall((xs[0], 0.0), (xs[-1], 0.0), -0.1, top, thickness=0.4)
    s.wall((xs[0], depth), (xs[-1], depth), -0.1, top, thickness=0.4)
    s.wall((xs[0], 0.0), (xs[0], depth), -0.1, top, thickness=0.4)
    s.wall((xs[-1], 0.0), (xs[-1], depth), -0.1, top, thickness=0.4)
    pit = plan["pit"]
    keep: list[list[tuple[float, float, float, float]]] = [[] for _ in heights]
    for i, y in enumerate(heights):
        if i == pit["plate"]:
            px0, px1 = pit["x"]
            pz0, pz1 = pit["z"]
            s.slab(xs[i], xs[i + 1], 0.0, depth, y, [(px0, px1, pz0, pz1)], thickness=y + 0.1)
            floor = y - pit["depth"]
            s.box(px0, px1, floor - 0.3, floor, pz0, pz1)
            s.stairs(np.array([px0 + pit["risers"] * TREAD, (pz0 + pz1) / 2]), np.array([-1.0, 0.0]), 1.4, floor, pit["depth"],
                     riser=pit["depth"] / pit["risers"], tread=TREAD)
            s.box(px1 - 2.6, px1 - 1.4, floor - 0.1, floor + 0.45, pz0 + 1.6, pz1 - 1.6)  # the hearth
            _trunk(s, np.array([px1 - 2.0, (pz0 + pz1) / 2]), 0.3, floor + 0.45, top)  # its flue
            keep[i].append((px0 - 1.0, px1 + 1.0, pz0 - 1.0, pz1 + 1.0))
        else:
            s.box(xs[i], xs[i + 1], -0.1, y, 0.0, depth)
    for b, flight in enumerate(plan["flights"]):
        x, low, high = xs[b + 1], heights[b] if flight["up"] else heights[b + 1], heights[b + 1] if flight["up"] else heights[b]
        heading = 1.0 if flight["up"] else -1.0
        run = flight["risers"] * TREAD
        w, z = flight["width"], flight["z"]
        s.stairs(np.array([x - heading * run, z]), np.array([heading, 0.0]), w, low, high - low,
                 riser=flight["riser"], tread=TREAD)
        s.wall((x, 0.0), (x, depth), high, high + 1.0, doors=[(z - w / 2, w)], thickness=0.08)  # the rail
        lower, upper = (b, b + 1) if flight["up"] else (b + 1, b)
        keep[lower].append((min(x, x - heading * (run + 1.5)), max(x, x - heading * (run + 1.5)), z - w / 2 - 1.0,
                            z + w / 2 + 1.0))
        keep[upper].append((min(x, x + heading * 1.5), max(x, x + heading * 1.5), z - w / 2 - 1.0, z + w / 2 + 1.0))
    for i, y in enumerate(heights):
        spots: list[tuple[np.ndarray, float]] = []
        for _ in range(int(rng.integers(9, 14))):
            p = _placed(rng, spots, xs[i] + 0.4, xs[i + 1] - 0.4, 0.4, depth - 0.4, 1.3, keep[i])
            if p is None:
                continue
            kind = rng.random()
            if kind < 0.4:
                s.box(p[0] - 1.0, p[0] + 1.0, y - 0.1, y + 0.45, p[1] - 0.45, p[1] + 0.45)  # a sofa
            elif kind < 0.75:
                s.box(p[0] - 0.8, p[0] + 0.8, y - 0.1, y + 0.75, p[1] - 0.45, p[1] + 0.45)  # a table
            else:
                _trunk(s, p, 0.2, y - 0.1, top)  # a post
    return s.mesh()


def shell_bowls_plan(seed: int) -> dict:
    """The plan of :func:`shell_bowls` for ``seed``: the field's size and per bowl its centre, floor radius, depth,
    inner slope (degrees), rim height and the half-side of the square its sheet covers. O(bowls^2) placement."""
    rng = np.random.default_rng(seed)
    size = (float(rng.uniform(130.0, 150.0)), float(rng.uniform(95.0, 110.0)))
    bowls: list[dict] = []
    for _ in range(400):
        if len(bowls) >= 40:
            break
        floor, deep = float(rng.uniform(2.3, 3.5)), float(rng.uniform(1.6, 3.0))
        slope, rim = float(rng.uniform(25.0, 55.0)), float(rng.uniform(0.3, 0.5))
        crest = floor + (deep + rim) / math.tan(math.radians(slope))
        half = crest + rim / math.tan(math.radians(20.0)) + 0.8
        c = np.array([float(rng.uniform(half + 2.0, size[0] - half - 2.0)), float(rng.uniform(half + 2.0, size[1] - half - 2.0))])
        if all(abs(c[0] - o["centre"][0]) >= half + o["half"] + 1.0 or abs(c[1] - o["centre"][1]) >= half + o["half"] + 1.0
               for o in bowls):
            bowls.append({"centre": (float(c[0]), float(c[1])), "floor": floor, "depth": deep, "slope": slope,
                          "rim": rim, "crest": crest, "half": half})
    return {"size": size, "bowls": bowls}


def shell_bowls_traps(plan: dict, slope: float = AGENT_SLOPE) -> list[int]:
    """The indices of the plan's bowls a player with the slope limit ``slope`` (degrees) cannot climb out of: those whose
    inner wall is steeper."""
    return [i for i, bowl in enumerate(plan["bowls"]) if bowl["slope"] > slope]


def _bowl(s: _Solids, bowl: dict, segments: int = 64) -> None:
    """One bowl of :func:`shell_bowls_plan`: a sheet over the square of half-side ``bowl["half"]`` about its centre,
    rings at the floor's edge (``-depth``), the rim's crest (``rim`` up, reached at the inner slope), the rim's outer
    foot (0, at 20 degrees) and the square's edge (0), with a skirt 0.5 m under it facing down (as
    :func:`level_kinds._terrain`), so Recast reads its top as floor."""
    cx, cz = bowl["centre"]
    angles = np.linspace(0.0, 2 * math.pi, segments, endpoint=False)
    ring = np.stack([np.cos(angles), np.sin(angles)], 1)
    foot = bowl["crest"] + bowl["rim"] / math.tan(math.radians(20.0))
    square = ring * (bowl["half"] / np.max(np.abs(ring), axis=1))[:, None]
    rings = [(ring * bowl["floor"], -bowl["depth"]), (ring * bowl["crest"], bowl["rim"]), (ring * foot, 0.0), (square, 0.0)]
    vertices = [[cx, -bowl["depth"], cz]]
    for plan, y in rings:
        vertices += [[cx + p[0], y, cz + p[1]] for p in plan]
    faces = [[0, 1 + (k + 1) % segments, 1 + k] for k in range(segments)]
    for r in range(len(rings) - 1):
        a, b = 1 + r * segments, 1 + (r + 1) * segments
        for k in range(segments):
            k1 = (k + 1) % segments
            faces += [[a + k, a + k1, b + k1], [a + k, b + k1, b + k]]
    sheet = trimesh.Trimesh(np.array(vertices), np.array(faces), process=False)
    if sheet.face_normals[:, 1].mean() < 0:
        sheet.invert()
    skirt = sheet.copy()
    skirt.vertices[:, 1] -= 0.5
    skirt.invert()
    s.parts += [sheet, skirt]


def shell_bowls(seed: int) -> trimesh.Trimesh:
    """A shelled battlefield (a war shooter's no man's land, a survival map's blast zone) 130-150 x 95-110 m, flat ground
    at y = 0 pocked by up to 40 shell craters built as exact bowls (``shell_bowls_plan(seed)``), none overlapping: a
    flat floor 2.3-3.5 m in radius, 1.6-3.0 m deep, *an inner wall at one slope drawn per bowl from 25-55 degrees* up to
    a rim 0.3-0.5 m over the ground, whose outside falls at 20 degrees (polygons of 64 sides); wrecks (ridged bodies)
    and stumps (trunks) between the bowls, a boundary wall 2.5 m high.

    Expected (written before the first run): a player (45-degree limit) walks down and up a wall of 45 degrees or less
    and cannot climb out of a steeper one, so each bowl over 45 degrees is a trap: *its floor an area of its own*
    (reachable by dropping in, not back), every other bowl joined to the field. By the plan 12 / 8 / 10 traps of 21 /
    23 / 22 bowls on seeds 0-2, so *13 / 9 / 11 areas*; the walls nearest the limit are 44.7, 45.1 and 45.4 degrees
    (seed 0), 44.2 and 44.9 (seed 1) and 43.5 / 46.3 (seed 2), which Recast's per-triangle slope reads exactly (the
    sampling route's probes may read a wall within a degree of 45 either way). Each trap's floor, 2.30-3.44 m in radius,
    holds the agent. Traffic
    highest between the bowls; a joined bowl a dead end (cold), a trap's floor cold."""
    plan = shell_bowls_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    sx, sz = plan["size"]
    s = _Solids()
    holes = []
    for bowl in plan["bowls"]:
        _bowl(s, bowl)
        (cx, cz), h = bowl["centre"], bowl["half"]
        holes.append((cx - h, cx + h, cz - h, cz + h))
    spots = [(np.array(b["centre"]), b["half"] * 1.2) for b in plan["bowls"]]
    for _ in range(int(rng.integers(24, 32))):
        p = _placed(rng, spots, 2.0, sx - 2.0, 2.0, sz - 2.0, 2.5, holes)
        if p is None:
            continue
        if rng.random() < 0.5:
            holes.append(_ridged(s, p[0] - 2.1, p[0] + 2.1, p[1] - 1.0, p[1] + 1.0, -0.1, 1.2))  # a wreck
        else:
            _trunk(s, p, float(rng.uniform(0.3, 0.5)), -0.1, float(rng.uniform(1.5, 4.0)))  # a stump
    for a, b in (((0.0, 0.0), (sx, 0.0)), ((0.0, sz), (sx, sz)), ((0.0, 0.0), (0.0, sz)), ((sx, 0.0), (sx, sz))):
        s.wall(a, b, -0.1, 2.5, thickness=0.5)
    s.ground(0.0, sx, 0.0, sz, 0.0, holes)
    return s.mesh()


def airport_pier_plan(seed: int) -> dict:
    """The plan of :func:`airport_pier` for ``seed``: the pier's length and width, the link's length and its two
    lanes' widths, the satellite's size, and per jet bridge its side (south +1 / north -1 of which building), x, width,
    length and slope. O(bridges)."""
    rng = np.random.default_rng(seed)
    length, width = float(rng.uniform(110.0, 130.0)), float(rng.uniform(18.0, 22.0))
    link = float(rng.uniform(50.0, 70.0))
    lanes = [float(rng.uniform(1.0, 1.4)), float(rng.uniform(1.0, 1.4))]
    satellite = (float(rng.uniform(36.0, 44.0)), float(rng.uniform(18.0, 22.0)))
    bridges = []
    for building, extent in (("pier", length), ("satellite", satellite[0])):
        for side in (-1, 1):
            for x in np.arange(10.0, extent - 8.0, 26.0):
                bridges.append({"building": building, "side": side, "x": float(x + rng.uniform(-2.0, 2.0)),
                                "width": float(rng.uniform(1.4, 2.4)), "length": float(rng.uniform(14.0, 20.0)),
                                "slope": float(rng.uniform(0.0, 4.0)) * (1 if rng.random() < 0.5 else -1)})
    return {"length": length, "width": width, "link": link, "lanes": lanes, "satellite": satellite, "bridges": bridges}


def _gate_room(s: _Solids, rng: np.random.Generator, x0: float, x1: float, z0: float, z1: float) -> None:
    """Rows of seats 0.45 m high (over the climb: furniture) along x between ``x0`` and ``x1`` in a gate's holdroom
    [z0, z1], aisles 1.6 m between rows, gaps 2 m between runs."""
    for z in np.arange(z0 + 1.5, z1 - 1.5, 2.4):
        for x in np.arange(x0 + 1.0, x1 - 6.0, float(rng.uniform(7.0, 9.0))):
            s.box(float(x), float(x) + 5.0, -0.1, 0.45, float(z), float(z) + 0.8)


def airport_pier(seed: int) -> trimesh.Trimesh:
    """An airport pier (an airport level of a shooter, a terminal of a stealth game): a concourse 110-130 x 18-22 m
    (``airport_pier_plan(seed)``) at y = 0 between glass walls 4 m high, rows of seats at its gates and shops (ridged
    blocks) down its middle; at its east end a *link 50-70 m long whose whole floor is two travelators*: belts 0.05 m
    over the floor, each lane *1.0-1.4 m wide, drawn per lane*, between the link's glass wall and a balustrade 1.0 m
    high and 0.3 m thick between the lanes, entered at their ends only; beyond it a satellite 36-44 x 18-22 m with gates of its own.
    Every gate has a *glazed jet bridge 1.4-2.4 m wide, drawn per bridge*, 14-20 m long, sloping 0-4 degrees up or
    down, between glass walls 2.4 m high (no roof), to an aircraft: a cabin 3.6 m wide and 20 m long (its floor the
    bridge's end height, seats along its sides, an aisle 1.6 m wide, its roof ridged), entered only from its bridge.
    Nothing is built under the bridges and aircraft (no apron).

    Expected (written before the first run): a player (1 m across) walks every lane and every bridge, so *one area* on
    every seed with the satellite and every aircraft reached. The lanes (1.0-1.4 m between walls: by the plan 1.01 /
    1.33, 1.38 / 1.12 and 1.04 / 1.24 m on seeds 0-2) are about what the navmesh keeps between walls after the agent's
    radius each side (Recast's cells of 0.25 m), so the navmesh route may lose a lane, and where it loses both part
    the satellite with its 2 aircraft (an area apart); likewise bridges under 1.6 m (by the plan 3 / 2 / 2 of 12 / 10 /
    10, 1.43-1.56 m) may part their aircraft. The sampling route's walk test is the agent's body, which a lane of 1.0 m fits.
    Traffic highest along the concourse and the link; aircraft dead ends."""
    plan = airport_pier_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    length, width, link = plan["length"], plan["width"], plan["link"]
    lane_a, lane_b = plan["lanes"]
    sat_x, sat_z = plan["satellite"]
    link_w = 0.1 + lane_a + 0.3 + lane_b + 0.1
    zc = width / 2
    sat0 = length + link
    s = _Solids()
    shops = []  # the shops' plans: no floor inside a closed solid (it would be floor under its roof)
    for x0, x1 in ((0.0, length), (sat0, sat0 + sat_x)):
        for x in np.arange(x0 + 12.0, x1 - 12.0, float(rng.uniform(16.0, 20.0))):  # shops down the middle
            shops.append(_ridged(s, float(x), float(x) + 8.0, zc - 1.5, zc + 1.5, -0.1, 3.0))
    s.ground(0.0, length, 0.0, width, 0.0, shops, thickness=0.3)
    s.box(length, sat0, -0.3, 0.0, zc - link_w / 2, zc + link_w / 2)
    s.ground(sat0, sat0 + sat_x, zc - sat_z / 2, zc + sat_z / 2, 0.0, shops, thickness=0.3)
    # the link: belts 0.05 m up between balustrades, its side walls the outer balustrades' backs
    za = zc - link_w / 2 + 0.1
    s.box(length + 1.0, sat0 - 1.0, 0.0, 0.05, za, za + lane_a)
    s.box(length + 1.0, sat0 - 1.0, 0.0, 0.05, za + lane_a + 0.3, za + lane_a + 0.3 + lane_b)
    s.box(length + 1.0, sat0 - 1.0, -0.1, 1.0, za + lane_a, za + lane_a + 0.3)
    for z in (zc - link_w / 2 + 0.05, zc + link_w / 2 - 0.05):
        s.wall((length, z), (sat0, z), -0.1, 4.0, thickness=0.1)
    doors: dict[tuple[str, int], list[tuple[float, float]]] = {}
    for bridge in plan["bridges"]:
        doors.setdefault((bridge["building"], bridge["side"]), []).append((bridge["x"] - bridge["width"] / 2, bridge["width"]))
    half = link_w / 2
    for side in (-1, 1):
        z = 0.0 if side < 0 else width
        s.wall((0.0, z), (length, z), -0.1, 4.0, doors=doors.get(("pier", side), []), thickness=0.2)
        zs = zc + side * sat_z / 2
        s.wall((sat0, zs), (sat0 + sat_x, zs), -0.1, 4.0,
               doors=doors.get(("satellite", side), []), thickness=0.2)  # the plan's x are along the satellite
    s.wall((0.0, 0.0), (0.0, width), -0.1, 4.0, thickness=0.2)
    s.wall((length, 0.0), (length, width), -0.1, 4.0, doors=[(zc - half + 0.1, link_w - 0.2)], thickness=0.2)
    s.wall((sat0, zc - sat_z / 2), (sat0, zc + sat_z / 2), -0.1, 4.0, doors=[(sat_z / 2 - half + 0.1, link_w - 0.2)],
           thickness=0.2)
    s.wall((sat0 + sat_x, zc - sat_z / 2), (sat0 + sat_x, zc + sat_z / 2), -0.1, 4.0, thickness=0.2)
    for x0, x1 in ((0.0, length), (sat0, sat0 + sat_x)):
        z0, z1 = (0.0, width) if x0 == 0.0 else (zc - sat_z / 2, zc + sat_z / 2)
        _gate_room(s, rng, x0, x1, z0 + 0.5, z0 + 5.5)
        _gate_room(s, rng, x0, x1, z1 - 5.5, z1 - 0.5)
    for bridge in plan["bridges"]:
        side, w, x = bridge["side"], bridge["width"], bridge["x"]
        z0 = (0.0 if side < 0 else width) if bridge["building"] == "pier" else zc + side * sat_z / 2
        x = x if bridge["building"] == "pier" else x + sat0
        z1 = z0 + side * bridge["length"]
        y1 = bridge["length"] * math.tan(math.radians(bridge["slope"]))
        s.ramp(np.array([x, z0]), np.array([x, z1]), w + 0.2, 0.0, y1, thickness=0.3)
        for dx in (-(w / 2 + 0.05), w / 2 + 0.05):
            s.hull(np.array([[x + dx + t, y + d, z] for t in (-0.05, 0.05) for z, y in ((z0, 0.0), (z1, y1))
                             for d in (-0.1, 2.4)]))
        # the aircraft: a cabin 3.6 m wide and 20 m long across the bridge's end, its door facing the bridge
        c0, c1 = z1, z1 + side * 3.6
        lo, hi = min(c0, c1), max(c0, c1)
        s.box(x - 6.0, x + 14.0, y1 - 0.3, y1, lo, hi)
        s.wall((x - 6.0, c0), (x + 14.0, c0), y1, y1 + 2.3, doors=[(6.0 - w / 2, w)], thickness=0.1)
        s.wall((x - 6.0, c1), (x + 14.0, c1), y1, y1 + 2.3, thickness=0.1)
        s.wall((x - 6.0, lo), (x - 6.0, hi), y1, y1 + 2.3, thickness=0.1)
        s.wall((x + 14.0, lo), (x + 14.0, hi), y1, y1 + 2.3, thickness=0.1)
        _lid(s, x - 6.0, x + 14.0, lo, hi, y1 + 2.3)
        for u in np.arange(x - 4.5, x + 13.0, 1.0):  # seat rows either side of the aisle, off the door's bay
            if abs(u - x) > 2.0:
                s.box(float(u), float(u) + 0.5, y1, y1 + 1.0, lo + 0.05, lo + 1.0)
                s.box(float(u), float(u) + 0.5, y1, y1 + 1.0, hi - 1.0, hi - 0.05)
    return s.mesh()


def cliff_path_plan(seed: int) -> dict:
    """The plan of :func:`cliff_path` for ``seed``: the butte's side, and per face of the path (counter-clockwise
    from the south face, 5-6 faces: 1.25-1.5 turns) its start and end height and its stretches (start and end
    metres along the face, width out from it). Each face's shelf climbs at 6-9 degrees; flat landings 2.2 m square
    stand at the corners. O(stretches)."""
    rng = np.random.default_rng(seed)
    side = float(rng.uniform(34.0, 40.0))
    faces, y, after_pinch = [], 0.0, True  # no pinch at the path's foot, none next to another
    count = int(rng.integers(5, 7))
    for f in range(count):
        rise = side * math.tan(math.radians(float(rng.uniform(6.0, 9.0))))
        while True:  # stretches 3 m long or more
            edges = [0.0, *np.sort(rng.uniform(3.0, side - 3.0, int(rng.integers(2, 5)))).tolist(), side]
            if min(np.diff(edges)) >= 3.0:
                break
        stretches = []
        for k, (a, b) in enumerate(zip(edges[:-1], edges[1:])):
            last = f == count - 1 and k == len(edges) - 2
            pinch = rng.random() < 0.2 and not after_pinch and not last
            stretches.append({"t": (float(a), float(b)),
                              "width": float(rng.uniform(0.6, 1.0) if pinch else rng.uniform(1.0, 1.8))})
            after_pinch = pinch
        faces.append({"y": (y, y + rise), "stretches": stretches})
        y += rise
    return {"side": side, "faces": faces, "top": y}


def cliff_path_areas(plan: dict, width: float = AGENT_DIAMETER) -> list[list[tuple[int, int]]]:
    """The plan's areas for a player ``width`` m across: lists of (face, stretch) joined along the path, parted at each
    stretch narrower than ``width`` (a pinch belongs to no area); the valley holds the first list, the plateau the last
    (either may be empty: the path pinched at its foot or head)."""
    areas: list[list[tuple[int, int]]] = [[]]
    for f, face in enumerate(plan["faces"]):
        for k, stretch in enumerate(face["stretches"]):
            if stretch["width"] < width:
                areas.append([])
            else:
                areas[-1].append((f, k))
    return [a for i, a in enumerate(areas) if a or i in (0, len(areas) - 1)]


_FACE_FRAMES = ((np.array([0.0, 0.0]), np.array([1.0, 0.0]), np.array([0.0, -1.0])),
                (np.array([1.0, 0.0]), np.array([0.0, 1.0]), np.array([1.0, 0.0])),
                (np.array([1.0, 1.0]), np.array([-1.0, 0.0]), np.array([0.0, 1.0])),
                (np.array([0.0, 1.0]), np.array([0.0, -1.0]), np.array([-1.0, 0.0])))
"""Per face of a square butte of side 1 (counter-clockwise seen from above with x east and z north... going round
from the south-west corner): its start corner, its heading along the face and its outward normal, all in plan."""


def cliff_path(seed: int) -> trimesh.Trimesh:
    """A path up a butte (an adventure game's goat track, a shooter's mountain monastery): a rock 34-40 m square whose
    top, the plateau, stands 19-36 m over a valley at y = 0 (``cliff_path_plan(seed)``), its sheer faces climbed by a
    shelf that winds round it 1.25-1.5 turns at 6-9 degrees from the valley at its south-west corner to the plateau,
    flat landings 2.2 m square at the corners (one turn puts 17 m or more of head room over the shelf). Each face's
    shelf is cut into 3-5 stretches 3 m long or more *whose width out from the face is drawn per stretch*: 1.0-1.8 m, or, about one
    stretch in five, *a pinch of 0.6-1.0 m*, with no rail: its open side drops to the valley. Boulders and trees in the
    valley, a hermitage (ridged) and trees on the plateau.

    Expected (written before the first run): a player (1 m across) passes every stretch of 1.0 m or more and no pinch,
    so the path parts at each pinch (``cliff_path_areas``; no pinch at the path's ends nor next to another, stretches
    3 m long or more): by the plan 3 / 2 / 3 pinches (0.62-0.99 m), so *4 / 3 / 4 areas* on seeds 0-2 (the valley with
    the path to the first pinch, the path between each two pinches, 20.5-113.5 m of it, the plateau with the path above
    the last). Stretches of 1.0-1.3 m (by the plan 2 / 10 / 5 of 19 / 21 / 18) with a wall on one side
    and a drop on the other are about what the navmesh's radius and ledge cells leave nothing of, so the navmesh route
    may part the path at them too (more areas); the sampling route's walk test is the body. The plateau and the valley
    are the largest areas; traffic highest along the path's joined pieces."""
    plan = cliff_path_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    side, top = plan["side"], plan["top"]
    s = _Solids()
    holes = [_ridged(s, side / 2 - 5.0, side / 2 + 5.0, side / 2 - 4.0, side / 2 + 4.0, top - 0.1, top + 4.0)]  # the hermitage
    s.slab(0.0, side, 0.0, side, top, holes, thickness=top + 0.1)  # the butte, its top the plateau (none in the hermitage)
    for f, face in enumerate(plan["faces"]):
        corner, along, out = (v * (side if i == 0 else 1.0) for i, v in enumerate(_FACE_FRAMES[f % 4]))
        y0, y1 = face["y"]
        for stretch in face["stretches"]:
            a, b = stretch["t"]
            points = []
            for t in (a, b):
                for u in (-0.2, stretch["width"]):
                    p = corner + along * t + out * u
                    y = y0 + (y1 - y0) * t / side
                    points += [[p[0], y, p[1]], [p[0], y - 0.4, p[1]]]
            s.hull(np.array(points))
        nxt = _FACE_FRAMES[(f + 1) % 4][2]
        end = corner + along * side
        s.hull(np.array([[q[0], y, q[1]] for u in (-0.2, 2.2) for v in (-0.2, 2.2) for q in [end + out * u + nxt * v]
                         for y in (y1 - 0.4, y1)]))  # the landing at the corner
    s.ground(-30.0, side + 30.0, -30.0, side + 30.0, 0.0, [(0.0, side, 0.0, side)])
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(8):  # trees on the plateau, clear of its edge
        p = _placed(rng, spots, 4.0, side - 4.0, 4.0, side - 4.0, 1.0, holes)
        if p is not None:
            _trunk(s, p, 0.35, top - 0.1, top + 5.0)
    spots = []
    for _ in range(48):  # boulders and trees in the valley, clear of the butte's foot
        p = _placed(rng, spots, -28.0, side + 28.0, -28.0, side + 28.0, 1.5, [(-4.0, side + 4.0, -4.0, side + 4.0)])
        if p is not None:
            if rng.random() < 0.5:
                s.rock(rng, p, 0.6, -0.1, float(rng.uniform(0.8, 1.8)))
            else:
                _trunk(s, p, 0.35, -0.1, 6.0)
    return s.mesh()


def cellar_stairs_plan(seed: int) -> dict:
    """The plan of :func:`cellar_stairs` for ``seed``: the houses' depth and per house its x range, its cellar's depth,
    the cellar stair's riser, the tread (counted from the top, 0) whose start the ground floor's edge overhangs and the
    clearance that leaves over it. O(houses)."""
    rng = np.random.default_rng(seed)
    depth = float(rng.uniform(11.0, 13.0))
    houses, x = [], 0.0
    for _ in range(int(rng.integers(6, 9))):
        width = float(rng.uniform(7.0, 9.0))
        cellar = float(rng.uniform(2.6, 3.0))
        riser = cellar / 16
        tread = int(rng.integers(12, 15))
        houses.append({"x": (x, x + width), "cellar": cellar, "riser": riser, "tread": tread,
                       "clearance": riser * tread - 0.3})
        x += width
    return {"depth": depth, "houses": houses}


def cellar_stairs_cut(plan: dict, height: float = AGENT_HEIGHT) -> list[int]:
    """The indices of the plan's houses whose cellar a player ``height`` m tall does not reach: the slab's clearance over
    the tread it overhangs under ``height``."""
    return [i for i, house in enumerate(plan["houses"]) if house["clearance"] < height]


def cellar_stairs(seed: int) -> trimesh.Trimesh:
    """A terrace of 6-8 town houses 7-9 m wide and 11-13 m deep (a survival horror's street, a heist's row) along a
    street at y = 0 (``cellar_stairs_plan(seed)``), each with a front door, a back door onto its walled yard (walls 1.8
    m), a ground floor at 0 (a slab 0.3 m thick), a first floor at 3 m up a stair 1.8 m wide along its east wall (the
    floor open over its whole run), a roof (ridged), and a cellar 2.6-3.0 m down reached only by a stair of 16 risers
    1.8 m wide along its west wall, railed on the ground floor. *The ground floor's opening over the cellar stair stops
    short*: its edge overhangs the start of tread 12-14 (counted from the top), so the slab's underside passes *1.75-2.33
    m over that tread, drawn per house*, about the agent's 2 m (each tread below has a riser more). Tables and sofas on the
    floors, barrels and racks in the cellars, off the stairs' ways.

    Expected (written before the first run): a player 2 m tall walks under the slab where it leaves 2.0 m or more and
    not where it leaves less, so *each cellar under less than 2.0 m is an area apart* and the rest joined: by the plan
    clearances under 2.0 m in 4 / 3 / 4 of 7 / 8 / 6 houses (1.655-1.875 m, and 1.989 m on seed 0, which the routes'
    height steps may read either way; the rest 2.069-2.307 m), so *5 / 4 / 5 areas*; every first floor joined. Traffic highest along the street and the stairs; cellars and first floors dead
    ends."""
    plan = cellar_stairs_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    depth, width, stair = plan["depth"], 1.8, 1.8
    x_end = plan["houses"][-1]["x"][1]
    s = _Solids()
    s.ground(-4.0, x_end + 4.0, -10.0, 0.0, 0.0, [])
    s.ground(0.0, x_end, depth, depth + 8.0, 0.0, [])
    s.wall((-4.0, -10.0), (x_end + 4.0, -10.0), -0.1, 2.5, thickness=0.3)
    s.wall((-4.0, -10.0), (-4.0, 0.0), -0.1, 2.5, thickness=0.3)
    s.wall((x_end + 4.0, -10.0), (x_end + 4.0, 0.0), -0.1, 2.5, thickness=0.3)
    s.wall((0.0, depth + 8.0), (x_end, depth + 8.0), -0.1, 1.8, thickness=0.3)
    s.wall((0.0, depth), (0.0, depth + 8.0), -0.1, 1.8, thickness=0.2)
    for house in plan["houses"]:
        x0, x1 = house["x"]
        cellar, riser, tread = house["cellar"], house["riser"], house["tread"]
        run = 16 * TREAD
        z_top = 2.0  # the cellar stair's top tread starts here and the stair goes down along +z
        opening = (x0 + 0.1, x0 + 0.1 + stair, z_top, z_top + tread * TREAD + 0.1)
        main_run = 17 * TREAD
        upper = (x1 - 0.1 - stair, x1 - 0.1, 1.2, 1.5 + main_run - TREAD)  # the top tread flush with the floor
        s.box(x0, x1, -cellar - 0.3, -cellar, 0.0, depth)  # the cellar's floor
        s.slab(x0, x1, 0.0, depth, 0.0, [opening], thickness=0.3)
        s.slab(x0, x1, 0.0, depth, 3.0, [upper], thickness=0.3)
        s.stairs(np.array([x0 + 0.1 + stair / 2, z_top + run]), np.array([0.0, -1.0]), stair, -cellar, cellar,
                 riser=riser, tread=TREAD)
        s.stairs(np.array([x1 - 0.1 - stair / 2, 1.5]), np.array([0.0, 1.0]), stair, 0.0, 3.0, riser=3.0 / 17, tread=TREAD)
        rail = x0 + 0.1 + stair + 0.05
        s.wall((rail, z_top + TREAD), (rail, opening[3]), 0.0, 1.0, thickness=0.1)
        s.wall((x1 - 0.1 - stair - 0.05, upper[2]), (x1 - 0.1 - stair - 0.05, upper[3]), 3.0, 4.0, thickness=0.1)
        s.wall((x1 - 0.1 - stair - 0.05, upper[2] - 0.05), (x1 - 0.1, upper[2] - 0.05), 3.0, 4.0, thickness=0.1)
        s.wall((x0, 0.0), (x0, depth), -cellar - 0.3, 6.0, thickness=0.2)
        s.wall((x1, 0.0), (x1, depth), -cellar - 0.3, 6.0, thickness=0.2)
        s.wall((x0, 0.0), (x1, 0.0), -cellar - 0.3, 6.0, doors=[((x1 - x0) / 2 - 0.8, 1.6)], thickness=0.3)
        s.wall((x0, depth), (x1, depth), -cellar - 0.3, 6.0, doors=[((x1 - x0) / 2 - 0.8, 1.6)], thickness=0.3)
        s.wall((x1, depth), (x1, depth + 8.0), -0.1, 1.8, thickness=0.2)  # the yard's wall
        _lid(s, x0, x1, 0.0, depth, 6.0)
        for y, bottom, keep in ((0.0, 0.0, [opening, (x0, x0 + 2.2, 0.0, z_top), (x1 - 0.1 - stair, x1, 0.0, 1.5 + main_run + 1.5),
                                             ((x0 + x1) / 2 - 1.5, (x0 + x1) / 2 + 1.5, 0.0, 2.0),
                                             ((x0 + x1) / 2 - 1.5, (x0 + x1) / 2 + 1.5, depth - 2.0, depth)]),
                                (3.0, 3.0, [upper, (x1 - 0.1 - stair - 0.3, x1, 0.0, 1.5 + main_run + 1.5)]),
                                (-cellar, -cellar, [(x0, x0 + 0.1 + stair + 0.3, 0.0, z_top + run + 1.8)])):
            spots: list[tuple[np.ndarray, float]] = []
            for _ in range(int(rng.integers(2, 5))):
                p = _placed(rng, spots, x0 + 0.2, x1 - 0.2, 0.2, depth - 0.2, 1.0, keep)
                if p is None:
                    continue
                if y < 0.0:
                    _trunk(s, p, 0.35, y - 0.1, y + 1.0)  # a barrel
                elif rng.random() < 0.5:
                    s.box(p[0] - 0.8, p[0] + 0.8, bottom - 0.1, bottom + 0.75, p[1] - 0.45, p[1] + 0.45)  # a table
                else:
                    s.box(p[0] - 0.9, p[0] + 0.9, bottom - 0.1, bottom + 0.45, p[1] - 0.45, p[1] + 0.45)  # a sofa, a bed
    return s.mesh()


def stack_tiers_plan(seed: int) -> dict:
    """The plan of :func:`stack_tiers` for ``seed``: the stack's length (x) and depth (z), the walkway's width, per
    tier its floor height and per side (south, north) the aisle between its ranges, and per gap between tiers its two
    stairs' widths (west, east) and risers. O(tiers)."""
    rng = np.random.default_rng(seed)
    length, depth, walkway = float(rng.uniform(60.0, 72.0)), float(rng.uniform(22.0, 26.0)), float(rng.uniform(1.8, 2.2))
    tiers, gaps, y = [], [], 0.0
    count = int(rng.integers(4, 6))
    for k in range(count):
        tiers.append({"y": y, "aisles": (float(rng.uniform(0.8, 1.3)), float(rng.uniform(0.8, 1.3)))})
        if k + 1 < count:
            gap = float(rng.uniform(2.35, 2.7))
            gaps.append({"height": gap, "risers": math.ceil(gap / 0.19),
                         "widths": (float(rng.uniform(1.0, 1.6)), float(rng.uniform(1.0, 1.6)))})
            y += gap
    return {"length": length, "depth": depth, "walkway": walkway, "tiers": tiers, "gaps": gaps,
            "top": y + float(rng.uniform(2.35, 2.7))}


def stack_tiers(seed: int) -> trimesh.Trimesh:
    """A library's cast-iron book stack (a mystery game's archive, a heist's vault of records) 60-72 x 22-26 m of 4-5
    tiers *2.35-2.7 m apart floor to floor, drawn per tier* (slabs 0.12 m thick: 2.23-2.58 m clear, just over the
    agent's 2 m; ``stack_tiers_plan(seed)``): on each tier a walkway 1.8-2.2 m wide along x down the middle and, either
    side of it, ranges of shelves 0.5 m deep from the walkway to the outer wall, floor to the tier above, in two runs
    with a cross aisle 1.5 m wide between them, *the aisles between ranges 0.8-1.3 m wide, drawn per tier and side*. Each tier is joined to the next by two
    *enclosed stairs 1.0-1.6 m wide, drawn per stair*, between walls (risers of 0.17-0.19 m, goings 0.25 m), one at
    each end beside the walkway (south of it from even tiers, north from odd), the upper tier's opening railed, 2.3 m
    landings at the ends. A ridged roof over the top tier; no way out.

    Expected (written before the first run): a player (1 m across, 2 m tall) walks every stair (each at least 1.0 m
    wide, the head room over each tier 2.23 m or more) and every aisle of 1.0 m or more, so *one area* on every seed
    with every tier reached (4 / 5 / 4 on seeds 0-2); aisles under 1.0 m are not walked (by the plan the tiers' sides
    of 0.81-0.97 m: 2 / 4 / 2 of 8 / 10 / 8). Stairs of 1.0-1.3 m between walls (by the plan 2 / 5 / 4 of 6 / 8 / 6;
    both stairs of one gap under 1.3 m on seed 1, the third gap, 1.24 / 1.12 m, and on seed 2, the first, 1.03 / 1.16
    m) are about what the navmesh keeps between walls after the agent's radius each side, so the navmesh route may
    part the tiers where both stairs of a gap are lost. Traffic highest on the walkways and stairs; the aisles cold
    dead ends."""
    plan = stack_tiers_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    length, depth, walkway = plan["length"], plan["depth"], plan["walkway"]
    zc = depth / 2
    tiers, gaps = plan["tiers"], plan["gaps"]
    runs = [g["risers"] * 0.25 for g in gaps]
    reserve = 2.5 + max(runs) + 2.0
    s = _Solids()
    for a, b in (((0.0, 0.0), (length, 0.0)), ((0.0, depth), (length, depth)), ((0.0, 0.0), (0.0, depth)),
                 ((length, 0.0), (length, depth))):
        s.wall(a, b, -0.3, plan["top"], thickness=0.3)
    _lid(s, 0.0, length, 0.0, depth, plan["top"])

    def band(k: int, width: float) -> tuple[float, float]:
        """The z range of gap k's stairs (south of the walkway from even tiers, north from odd)."""
        return (zc - walkway / 2 - 0.1 - width, zc - walkway / 2 - 0.1) if k % 2 == 0 else \
            (zc + walkway / 2 + 0.1, zc + walkway / 2 + 0.1 + width)
    for k, tier in enumerate(tiers):
        y = tier["y"]
        ceiling = tiers[k + 1]["y"] - 0.12 if k + 1 < len(tiers) else y + 2.3
        holes = []
        if k > 0:
            g = gaps[k - 1]
            for end, w in zip((0, 1), g["widths"]):
                z0, z1 = band(k - 1, w)
                x0, x1 = (2.5, 2.5 + runs[k - 1]) if end == 0 else (length - 2.5 - runs[k - 1], length - 2.5)
                holes.append((x0, x1, z0, z1))
                s.wall((x0, z0 - 0.05), (x1, z0 - 0.05), y, y + 1.0, thickness=0.1)  # the opening's rails
                s.wall((x0, z1 + 0.05), (x1, z1 + 0.05), y, y + 1.0, thickness=0.1)
                foot = x1 + 0.05 if end == 0 else x0 - 0.05
                s.wall((foot, z0 - 0.1), (foot, z1 + 0.1), y, y + 1.0, thickness=0.1)
        s.slab(0.0, length, 0.0, depth, y, holes, thickness=0.12 if k > 0 else 0.4)
        if k + 1 < len(tiers):
            g = gaps[k]
            for end, w in zip((0, 1), g["widths"]):
                z0, z1 = band(k, w)
                rise = g["height"]
                if end == 0:  # climbing -x to its head at x = 2.5
                    s.stairs(np.array([2.5 + runs[k], (z0 + z1) / 2]), np.array([-1.0, 0.0]), w, y, rise,
                             riser=rise / g["risers"], tread=0.25)
                    xs = (2.5, 2.5 + runs[k])
                else:
                    s.stairs(np.array([length - 2.5 - runs[k], (z0 + z1) / 2]), np.array([1.0, 0.0]), w, y, rise,
                             riser=rise / g["risers"], tread=0.25)
                    xs = (length - 2.5 - runs[k], length - 2.5)
                for z in (z0 - 0.05, z1 + 0.05):  # the enclosing walls, up to the tier above
                    s.wall((xs[0], z), (xs[1], z), y - 0.1, ceiling, thickness=0.1)
        for side, aisle in zip((-1, 1), tier["aisles"]):
            z0, z1 = (0.15, zc - walkway / 2) if side < 0 else (zc + walkway / 2, depth - 0.15)
            mid = (z0 + z1) / 2
            for x in np.arange(reserve, length - reserve - 0.5, 0.5 + aisle):  # two runs of ranges, a cross aisle between
                s.box(float(x), float(x) + 0.5, y - 0.1, ceiling, z0, mid - 0.75)
                s.box(float(x), float(x) + 0.5, y - 0.1, ceiling, mid + 0.75, z1)
        for end in (0, 1):  # reading tables in the corners beyond the ranges
            x = float(rng.uniform(reserve - 3.0, reserve - 2.0)) if end == 0 else float(rng.uniform(length - reserve + 1.0, length - reserve + 2.0))
            for zz in (float(rng.uniform(1.0, 2.0)), float(rng.uniform(depth - 3.0, depth - 2.0))):
                s.box(x, x + 1.2, y - 0.1, y + 0.75, zz, zz + 0.8)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "ski_lodge": ski_lodge, "shell_bowls": shell_bowls, "airport_pier": airport_pier,
    "cliff_path": cliff_path, "cellar_stairs": cellar_stairs, "stack_tiers": stack_tiers,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirty-ninth round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
