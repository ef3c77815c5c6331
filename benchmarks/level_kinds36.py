"""Level kinds of the thirty-sixth held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each a few hundred navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py``, ``level_kinds30.py`` and ``level_kinds34.py`` (imported, not copied):
``grating_plant`` (a process hall whose two upper levels are bar gratings: bars 30-50 mm wide with gaps of 25-60 mm
between them, drawn per platform, over a drop of 4.5 m), ``stepping_stones`` (a garden whose pond is crossed by paths
of stepping stones 0.8-2.2 m across with gaps of 0.15-0.5 m, drawn per path, and whose islet is reached by stones
only), ``bridge_arena`` (a sky arena's platforms over a void joined by bridges with no rails, 1.4-3.2 m wide drawn per
bridge, two platforms reached only by jump pads, half-cover walls 1.0-1.2 m high), ``queue_hall`` (a security hall's
serpentine queue between belt barriers that hang 0.85-0.95 m over an open floor, and shops behind shutters half down,
their lower edge 1.1-2.4 m up), ``far_outpost`` (tunnels 1.7-2.6 m wide at any heading between round hubs, the whole
35-55 km from the origin and 1.5-3 km up) and ``canteen`` (a mess hall of real furniture: table tops and bench seats on
thin legs, tables pushed together into tops up to 2.9 m deep).

Run: ``.venv/bin/python benchmarks/level_kinds36.py OUT_DIR [--kinds grating_plant canteen] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _ridged, _Solids, _strip, _trunk, _wall_line
from level_kinds import main as write_kinds
from level_kinds30 import _placed

BAR_DEPTH = 0.05
"""Height of a grating's bars, metres (a light-duty bar grating's)."""


def _grating(s: _Solids, x0: float, x1: float, z0: float, z1: float, top: float, bar: float, gap: float,
             along_x: bool) -> None:
    """A bar grating over [x0, x1] x [z0, z1] with its top at ``top``: bars ``bar`` m wide, ``gap`` m apart, running
    along x (or z), in a frame of two bars across their ends; every bar a closed box :data:`BAR_DEPTH` high. The gaps
    open onto whatever is under the grating. O(extent / (bar + gap)) boxes."""
    y0 = top - BAR_DEPTH
    if along_x:
        for z in np.arange(z0, z1 - bar + 1e-9, bar + gap):
            s.box(x0, x1, y0, top, float(z), float(z) + bar)
        s.box(x0, x0 + bar, y0, top, z0, z1)
        s.box(x1 - bar, x1, y0, top, z0, z1)
    else:
        for x in np.arange(x0, x1 - bar + 1e-9, bar + gap):
            s.box(float(x), float(x) + bar, y0, top, z0, z1)
        s.box(x0, x1, y0, top, z0, z0 + bar)
        s.box(x0, x1, y0, top, z1 - bar, z1)


def grating_plant_plan(seed: int) -> dict:
    """The plan of :func:`grating_plant` for ``seed``: the hall's size, each grating's rectangle (x0, x1, z0, z1), top,
    bar width, gap, direction (``along_x``) and kind (spine, landing or platform), and the flights (foot plan point,
    foot height; each 25 risers of 0.18 m along +x). O(gratings)."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(60.0, 70.0)), float(rng.uniform(36.0, 42.0))
    zs = size_z / 2
    x0 = 10.0
    gratings = []

    def add(rect: tuple[float, float, float, float], top: float, kind: str) -> None:
        gratings.append({"rect": rect, "top": top, "bar": float(rng.uniform(0.03, 0.05)), "kind": kind,
                         "gap": float(rng.uniform(0.025, 0.06)), "along_x": bool(rng.random() < 0.5)})

    for level, top in enumerate((4.5, 9.0)):
        z_spine = zs + 3.0 * level  # the upper spine 3 m north of the lower one: 4.5 m of head room over it
        width = float(rng.uniform(3.0, 3.6))
        start = x0 if level == 0 else x0 + 8.5
        add((start, size_x - 6.0, z_spine - width / 2, z_spine + width / 2), top, "spine")
        if level == 0:  # the landing at its west end, the upper flight standing on its north half
            add((x0 - 0.5, x0 + 10.0, zs - 4.5, zs + 4.5), top, "landing")
        n = 4 if level == 0 else 3
        xs = np.linspace(start + 14.0, size_x - 16.0, n)
        for k, x in enumerate(xs):
            w, d = float(rng.uniform(8.0, 12.0)), float(rng.uniform(6.0, 9.0))
            north = (k + level) % 2 == 0
            z_edge = z_spine + (width / 2 - 0.1 if north else -width / 2 + 0.1)
            z_far = min(z_edge + d, size_z - 1.5) if north else max(z_edge - d, 1.5)
            add((float(x) - w / 2, float(x) + w / 2, min(z_edge, z_far), max(z_edge, z_far)), top, "platform")
    flights = [(np.array([x0 - 7.0, zs]), 0.0), (np.array([x0 + 1.5, zs + 3.0]), 4.5)]  # 25 risers of 0.18, 7 m
    return {"size": (size_x, size_z), "gratings": gratings, "flights": flights}


def grating_plant(seed: int) -> trimesh.Trimesh:
    """A process plant's hall (a shooter's refinery interior, a stealth game's factory) 60-70 x 36-42 m, walls 10 m
    high, two doors 4 m wide in the south wall, under no roof, whose two upper levels (4.5 and 9 m up) are *bar
    gratings*: bars 30-50 mm wide and 50 mm deep with *gaps of 25-60 mm between them* (drawn per grating), running
    along x or along z (drawn per grating), over the open drop to the level below (``grating_plant_plan(seed)``). Each
    level is a spine catwalk 3.0-3.6 m wide along x (unrailed) with 3-4 platforms 8-12 x 6-9 m off its sides; the
    lower level has a landing 10.5 x 9 m at its west end, reached from the ground by a solid flight (25 risers of 0.18
    m, 2 m wide) along x, and a second solid flight standing on the landing's north half climbs from it to the upper
    spine's west end. The ground (solid, y = 0) holds 20-27 tanks and pumps (ridged), each platform a pump or two.

    Expected (written before the first run): one area, every grating walked: a gap of 25-60 mm is far under Recast's
    0.25 m cells, each of which holds bars, so the navmesh route sees a floor at each grating's top (less the ledge
    rule and the radius at its open edges: catwalks of 3-3.6 m keep 1-2 m). The sampling route finds floor by casting
    down: a probe between two bars (a gap of 25-60 mm in a pitch of 55-110 mm, so a third to a half of all probes)
    meets the level below 4.5 m down, so it may see the gratings as floor full of holes or lose them (the seam plaza
    of round 35 had a seam every 1-1.5 m, not every few centimetres). The structure along each spine with a branch
    onto each platform, up each flight; traffic highest on the flights (the only ways up) and the spines' west
    halves, lowest on the far platforms."""
    plan = grating_plant_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    size_x, size_z = plan["size"]
    s = _Solids()
    doors = sorted(float(x) for x in rng.uniform(18.0, size_x - 8.0, 2))
    if doors[1] - doors[0] < 6.0:
        doors[1] = doors[0] + 6.0 if doors[0] + 6.0 <= size_x - 8.0 else doors[0] - 6.0
    s.wall((0.0, 0.0), (size_x, 0.0), -0.1, 10.0, [(x, 4.0) for x in sorted(doors)], thickness=0.3)
    s.wall((0.0, size_z), (size_x, size_z), -0.1, 10.0, thickness=0.3)
    s.wall((0.0, 0.0), (0.0, size_z), -0.1, 10.0, thickness=0.3)
    s.wall((size_x, 0.0), (size_x, size_z), -0.1, 10.0, thickness=0.3)
    for g in plan["gratings"]:
        _grating(s, *g["rect"], g["top"], g["bar"], g["gap"], g["along_x"])
        if g["kind"] == "platform":  # a pump or two on skids, 0.5 m of room under it (no head room: no floor)
            x0, x1, z0, z1 = g["rect"]
            for _ in range(int(rng.integers(1, 3))):
                p = np.array([float(rng.uniform(x0 + 2.5, x1 - 2.5)), float(rng.uniform(z0 + 2.0, z1 - 2.0))])
                _ridged(s, p[0] - 1.0, p[0] + 1.0, p[1] - 0.6, p[1] + 0.6, g["top"] + 0.5, g["top"] + 1.6)
    for foot, y0 in plan["flights"]:
        s.stairs(foot, np.array([1.0, 0.0]), 2.0, y0, 4.5, 0.18, 0.28)
    holes: list[tuple[float, float, float, float]] = []
    spots: list[tuple[np.ndarray, float]] = []
    keep = [(0.0, 12.0, size_z / 2 - 3.0, size_z / 2 + 3.0)] + [(x - 1.0, x + 5.0, 0.0, 5.0) for x in doors]
    for _ in range(int(rng.integers(20, 28))):  # tanks and pumps on the ground, clear of the first flight and doors
        p = _placed(rng, spots, 2.0, size_x - 2.0, 2.0, size_z - 2.0, 1.8, keep)
        if p is not None:
            a, b = float(rng.uniform(0.8, 1.6)), float(rng.uniform(0.8, 1.6))
            holes.append(_ridged(s, p[0] - a, p[0] + a, p[1] - b, p[1] + b, -0.1, float(rng.uniform(1.5, 3.5))))
    s.ground(-8.0, size_x + 8.0, -10.0, size_z + 4.0, 0.0, holes)
    return s.mesh()


def stepping_stones_plan(seed: int) -> dict:
    """The plan of :func:`stepping_stones` for ``seed``: the garden's size, the pond band (z0, z1), the islet pond
    (x0, x1, z0, z1) and islet (centre, radius), and each stone path's line (start, end plan points), stones'
    diameter and the gap between them (``paths``; the islet's last). O(paths)."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(84.0, 96.0)), float(rng.uniform(56.0, 64.0))
    width = float(rng.uniform(8.0, 11.0))
    band = (size_z * 0.45, size_z * 0.45 + width)
    pond = (size_x - 34.0, size_x - 10.0, 6.0, 6.0 + 18.0)
    islet = (np.array([(pond[0] + pond[1]) / 2, (pond[2] + pond[3]) / 2 + 2.0]), float(rng.uniform(3.5, 4.5)))
    paths = []
    xs = [20.0 + 14.0 * k + float(rng.uniform(-2.0, 2.0)) for k in range(int(rng.integers(3, 5)))]
    for x in xs:
        d, gap = float(rng.uniform(0.8, 2.2)), float(rng.uniform(0.15, 0.5))
        drift = float(rng.uniform(-4.0, 4.0))  # the path's line is not square to the bank
        paths.append({"start": np.array([x, band[0] - 0.8]), "end": np.array([x + drift, band[1] + 0.8]),
                      "diameter": d, "gap": gap})
    d, gap = float(rng.uniform(1.2, 2.0)), float(rng.uniform(0.2, 0.4))
    paths.append({"start": np.array([islet[0][0] - 3.0, pond[2] - 0.8]), "end": islet[0] - np.array([0.0, islet[1] - 0.8]),
                  "diameter": d, "gap": gap})
    return {"size": (size_x, size_z), "band": band, "pond": pond, "islet": islet, "paths": paths}


def _octagon(c: np.ndarray, diameter: float) -> np.ndarray:
    """The plan (8, 2) of a regular octagon ``diameter`` m across its corners about plan point ``c`` (x, z)."""
    angles = np.linspace(0.0, 2 * math.pi, 8, endpoint=False) + math.pi / 8
    return c + diameter / 2 * np.stack([np.cos(angles), np.sin(angles)], 1)


def stepping_stones(seed: int) -> trimesh.Trimesh:
    """A stroll garden (an adventure game's temple garden, a walking sim's park) 84-96 x 56-64 m inside a wall 2 m high:
    two lawns (y = 0) parted by a pond band 8-11 m wide along x from wall to wall (water: no floor), crossed at its
    west end by a railed footbridge 2.4 m wide and by 3-4 *paths of stepping stones*: octagonal stones *0.8-2.2 m
    across with gaps of 0.15-0.5 m between them, drawn per path*, their tops 0.0-0.1 m over the lawns (under the
    climb), each path's line up to 4 m off square to the banks. In the south lawn a second pond 24 x 18 m holds an
    islet (4-4.5 m in radius, a stone lantern on it) *reached only by stepping stones* (1.2-2.0 m, gaps 0.2-0.4 m).
    Trees, hedges (ridged) and a tea house (ridged) on the lawns (``stepping_stones_plan(seed)``).

    Expected (written before the first run): for a player one area (the stones are walked, the islet reached). The
    presets' agent is a disc 1 m across whose centre Recast keeps 0.5 m (two of its cells) from every edge, and a gap
    of 0.15-0.5 m is an edge: no agent's centre stands at a gap, so the navmesh route cannot cross a stone path,
    whatever its stones' size (a stone of 1.5 m or more may keep a polygon of its own: an area apart). So on the
    navmesh route the lawns stay one area by the footbridge, the stone paths join nothing (no traffic on them), and
    the islet is an area apart: its disconnected-areas warning should name the stones' gaps (a designer would call
    it reachable). The sampling route joins samples up to its step's length apart where floor lies between, so it
    may cross the narrower gaps; whether it reaches the islet is open. Traffic on the navmesh route highest over the
    footbridge (the lawns' only join)."""
    plan = stepping_stones_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    size_x, size_z = plan["size"]
    band, pond = plan["band"], plan["pond"]
    s = _Solids()
    for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)), ((0.0, 0.0), (0.0, size_z)),
                 ((size_x, 0.0), (size_x, size_z))):
        s.wall(a, b, -0.6, 2.0, thickness=0.4)
    # the footbridge at the west end: a deck 2.4 m wide over the band, walled 1 m along both sides
    s.box(5.0, 7.4, -0.3, 0.0, band[0] - 1.0, band[1] + 1.0)
    for x in (4.9, 7.5):
        s.box(x - 0.1, x + 0.1, 0.0, 1.0, band[0] - 0.5, band[1] + 0.5)
    for path in plan["paths"]:
        start, end, d, gap = path["start"], path["end"], path["diameter"], path["gap"]
        length = float(np.linalg.norm(end - start))
        along = (end - start) / length
        side = np.array([-along[1], along[0]])
        n = int(length // (d + gap)) + 1
        pitch = length / max(n - 1, 1)  # first and last stones on the banks' edges, the gaps as drawn on average
        for k in range(n):
            c = start + along * pitch * k + side * float(rng.uniform(-0.1, 0.1)) * d
            s.prism(_octagon(c, d * min(1.0, (pitch - gap) / d)), -1.5, float(rng.uniform(0.0, 0.1)))
    c, r = plan["islet"]
    s.prism(_octagon(c, 2 * r), -1.5, 0.0)
    _trunk(s, c, 0.35, -0.1, 1.6)  # the lantern
    holes = [(0.0, size_x, band[0], band[1]), pond]
    spots: list[tuple[np.ndarray, float]] = []
    keep = [(0.0, size_x, band[0] - 2.0, band[1] + 2.0), (pond[0] - 2.0, pond[1] + 2.0, pond[2] - 2.0, pond[3] + 2.0)]
    tea = _placed(rng, spots, 4.0, size_x - 4.0, band[1] + 4.0, size_z - 4.0, 4.0, keep)
    if tea is not None:
        holes.append(_ridged(s, tea[0] - 3.5, tea[0] + 3.5, tea[1] - 2.5, tea[1] + 2.5, -0.1, 2.6))
    for _ in range(int(rng.integers(14, 20))):  # hedges
        p = _placed(rng, spots, 2.0, size_x - 2.0, 2.0, size_z - 2.0, 2.2, keep)
        if p is not None:
            holes.append(_ridged(s, p[0] - 2.0, p[0] + 2.0, p[1] - 0.5, p[1] + 0.5, -0.1, 1.2))
    for _ in range(int(rng.integers(45, 60))):  # trees
        p = _placed(rng, spots, 1.0, size_x - 1.0, 1.0, size_z - 1.0, 0.6, keep)
        if p is not None:
            _trunk(s, p, float(rng.uniform(0.15, 0.35)), -0.1, 5.0)
    s.ground(-0.2, size_x + 0.2, -0.2, size_z + 0.2, 0.0, holes)
    return s.mesh()


def bridge_arena_plan(seed: int) -> dict:
    """The plan of :func:`bridge_arena` for ``seed``: each platform's centre, radius and top; the bridges (i, j,
    width: platforms' indices, metres), a spanning tree of the platforms and two more; the jump pads (the platform
    a pad stands on, the pad's plan point, the high platform it throws to: centre, radius, top). O(platforms^2)."""
    rng = np.random.default_rng(seed)
    centres, radii, tops = [], [], []
    for i in range(5):
        for j in range(3):
            centres.append(np.array([i * 28.0 + float(rng.uniform(-4.0, 4.0)), j * 30.0 + float(rng.uniform(-4.0, 4.0))]))
            radii.append(float(rng.uniform(6.0, 8.0)))
            tops.append(float(rng.choice([0.0, 1.5, 3.0])))
    n = len(centres)
    dist = np.array([[np.linalg.norm(a - b) for b in centres] for a in centres])
    inside, edges = {0}, []
    while len(inside) < n:  # Prim's tree on the centres' distances
        i, j = min(((i, j) for i in inside for j in range(n) if j not in inside), key=lambda e: dist[e])
        edges.append((i, j))
        inside.add(j)
    extra = sorted(((i, j) for i in range(n) for j in range(i + 1, n) if (i, j) not in edges and (j, i) not in edges
                    and dist[i, j] < 45.0), key=lambda e: dist[e])
    edges += extra[:2]
    bridges = [(i, j, float(rng.uniform(1.4, 3.2))) for i, j in edges]
    pads = []
    for i in (int(rng.integers(0, 5)) * 3, int(rng.integers(0, 5)) * 3 + 2):  # one in each outer row
        outward = np.array([0.0, -1.0 if i % 3 == 0 else 1.0])
        high = centres[i] + outward * (radii[i] + 6.0)
        pads.append({"on": i, "at": centres[i] + outward * (radii[i] - 2.0),
                     "high": (high, float(rng.uniform(4.0, 5.0)), tops[i] + float(rng.uniform(6.0, 8.0)))})
    return {"centres": centres, "radii": radii, "tops": tops, "bridges": bridges, "pads": pads}


def bridge_arena(seed: int) -> trimesh.Trimesh:
    """A sky arena (an arena shooter's map over a kill plane): 15 platforms (octagons 6-8 m in radius, tops at 0, 1.5
    or 3 m, drawn) on a jittered 5 x 3 grid 28-30 m apart over a void (no floor under anything), joined along a
    spanning tree and two more pairs by *bridges with no rails, 1.4-3.2 m wide (drawn per bridge)*, each a straight
    deck (flat, or sloping up to about 8 degrees between platforms of different heights) at whatever heading its
    platforms' centres give. Two *high platforms* (radius 4-5 m, 6-8 m over their neighbour) stand 6 m outside the
    grid, *reached only by a jump pad* (a disc 2 m across, 0.1 m high, under the climb) on the platform in front of
    them; one drops back. On each platform 2-3 *half-cover walls 1.0-1.2 m high* (0.3 m thick, 3-5 m long, at any
    heading, kept off the bridges' ends) and a pillar 4 m high (``bridge_arena_plan(seed)``).

    Expected (written before the first run): for a player one area (every platform by a bridge, the high ones by the
    pads). For the presets' agent the high platforms are areas apart on both routes (a pad is no geometry a walker
    uses): each disconnected-areas warning should name the high platform, some 6-8 m over the one in front of it (a
    designer knows its pad). The low platforms are one area on the sampling route (bridges of 1.4 m and more hold the
    agent's 1 m); the navmesh route erodes a bridge with a drop on both sides by the ledge rule and the radius from
    each edge (round 35: a band between a wall and a drop keeps floor from about 1.6-1.8 m), so its bridges under
    about 2-2.4 m may be lost and the platforms they alone join fall apart: there the two routes disagree on which
    places are reachable, and the navmesh route's warning names a gap a designer did not leave. The half-cover walls
    (over the climb, under the agent's height) are walls on both routes. The structure a node on each platform, an
    edge along each kept bridge; traffic highest on the bridges of the tree's middle."""
    plan = bridge_arena_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    centres, radii, tops = plan["centres"], plan["radii"], plan["tops"]
    s = _Solids()
    for c, r, top in zip(centres, radii, tops):
        s.prism(_octagon(c, 2 * r), top - 2.0, top)
    lines = []
    for i, j, width in plan["bridges"]:
        along = (centres[j] - centres[i]) / np.linalg.norm(centres[j] - centres[i])
        a, b = centres[i] + along * (radii[i] * 0.85), centres[j] - along * (radii[j] * 0.85)  # inside each rim
        s.ramp(a, b, width, tops[i], tops[j], thickness=0.4)
        lines.append((a, b))
    for pad in plan["pads"]:
        i, (high, r, top) = pad["on"], pad["high"]
        s.prism(_octagon(pad["at"], 2.0), tops[i] - 0.2, tops[i] + 0.1)
        s.prism(_octagon(high, 2 * r), top - 2.0, top)

    def clear(p: np.ndarray) -> bool:  # 3 m or more from every bridge's centre line
        for a, b in lines:
            t = float(np.clip(np.dot(p - a, b - a) / np.dot(b - a, b - a), 0.0, 1.0))
            if np.linalg.norm(p - (a + t * (b - a))) < 3.0:
                return False
        return all(np.linalg.norm(p - pad["at"]) > 3.0 for pad in plan["pads"])

    for c, r, top in zip(centres, radii, tops):
        placed, wanted = 0, int(rng.integers(2, 4))
        for _ in range(40):
            if placed == wanted:
                break
            p = c + rng.uniform(-r * 0.55, r * 0.55, 2)
            heading = float(rng.uniform(0.0, math.pi))
            u = np.array([math.cos(heading), math.sin(heading)]) * float(rng.uniform(1.5, 2.5))
            if clear(p) and clear(p + u) and clear(p - u):
                s.prism(_strip(p - u, p + u, 0.3), top - 0.1, top + float(rng.uniform(1.0, 1.2)))
                placed += 1
        q = c + rng.uniform(-r * 0.4, r * 0.4, 2)
        if clear(q):
            _trunk(s, q, 0.5, top - 0.1, top + 4.0)
    return s.mesh()


def queue_hall_plan(seed: int) -> dict:
    """The plan of :func:`queue_hall` for ``seed``: the hall's size, the queue's lanes (count, width, x range, first
    lane's z) and belts' top, and each shop's front (x0, x1) and shutter's lower edge (``shutters``, metres over the
    floor). O(shops)."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(64.0, 74.0)), float(rng.uniform(40.0, 46.0))
    lanes, width = int(rng.integers(8, 13)), float(rng.uniform(1.6, 2.3))
    belt = float(rng.uniform(0.85, 0.95))
    x_range = (4.0, float(rng.uniform(30.0, 36.0)))
    shops = []
    x = x_range[1] + 4.0
    while x + 6.0 <= size_x - 2.0 and len(shops) < 6:
        shops.append(((x, x + 5.0), float(rng.uniform(1.1, 2.4))))
        x += 6.5
    return {"size": (size_x, size_z), "lanes": lanes, "width": width, "x": x_range, "z0": 4.0, "belt": belt,
            "shops": shops}


def queue_hall(seed: int) -> trimesh.Trimesh:
    """An airport's security hall (a heist's or a shooter's terminal, a theme park's queue): a hall 64-74 x 40-46 m,
    walls 6 m high, open to the sky, entered by a door 3 m wide in its south wall at the queue's mouth and left by a
    door in its north wall. In its west part *a serpentine queue of 8-12 lanes 1.6-2.3 m wide (drawn per seed)
    between belt barriers*: posts 0.08 m across and 0.95 m high every 2.2 m, joined by *belts 0.05 m deep and 0.02 m
    thick whose tops hang 0.85-0.95 m over the floor, with open floor under them*, each line of belts open at
    alternate ends, so the queue is one way folded back and forth; its last lane leads to a screening line of 4
    cabinets (ridged, 1.8 m high) with passages 1.6 m wide between them, and on to the north doors. Along the north
    wall, east of the queue, 4-6 shops 5 m wide and 6 m deep *behind shutters half down: a shutter's lower edge
    stands 1.1-2.4 m over the floor (drawn per shop)*, the floor running on under it (``queue_hall_plan(seed)``).

    Expected (written before the first run): for the presets' agent (2 m high) the floor under a belt, with 0.85-0.95
    m of head room, is no floor, so each line of belts is a wall with nothing under it a walker uses, and the queue
    is walked lane by lane (never under a belt); a shop is reached where its shutter's edge is 2.0 m or more up and
    is an area apart where it is lower (a player crouches; the agent does not), named by a warning as head room too
    low (a ceiling 1.1-2.0 m over the floor: the shutter, which a designer would raise). The navmesh route reads
    heights in 0.125 m cells, so a shutter at 1.9-2.1 m may read either way. On the sampling route whether an edge
    between two samples either side of a belt, 1.6-2.3 m apart, is refused (a belt over its line) is open. Traffic
    highest along the queue's lanes and the screening passages; the structure a chain down each lane."""
    plan = queue_hall_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    size_x, size_z = plan["size"]
    s = _Solids()
    lanes, width, (qx0, qx1), z0, belt = plan["lanes"], plan["width"], plan["x"], plan["z0"], plan["belt"]
    s.wall((0.0, 0.0), (size_x, 0.0), -0.1, 6.0, [(qx0 - 3.0 if qx0 > 3.5 else 0.5, 3.0)], thickness=0.3)
    s.wall((0.0, 0.0), (0.0, size_z), -0.1, 6.0, thickness=0.3)
    s.wall((size_x, 0.0), (size_x, size_z), -0.1, 6.0, thickness=0.3)
    north_doors = [(float(rng.uniform(4.0, qx1 - 6.0)), 3.0)]
    shop_depth = 6.0
    front_z = size_z - shop_depth
    s.wall((0.0, size_z), (size_x, size_z), -0.1, 6.0, north_doors, thickness=0.3)
    # the queue: belt lines along x between lanes, each open at alternate ends by a lane's width
    for k in range(lanes + 1):
        z = z0 + k * width
        if k in (0, lanes):
            x_a, x_b = qx0, qx1
        elif k % 2:
            x_a, x_b = qx0, qx1 - width
        else:
            x_a, x_b = qx0 + width, qx1
        if k == 0:  # the mouth: the first lane open at its west end onto the entrance
            x_a = qx0 + width
        posts = np.linspace(x_a, x_b, max(2, int(round((x_b - x_a) / 2.2)) + 1))
        for x in posts:
            _trunk(s, np.array([float(x), z]), 0.04, -0.05, 0.95)
        s.box(x_a, x_b, belt - 0.05, belt, z - 0.01, z + 0.01)
    for x in (qx0, qx1):  # the queue's ends: belts along z, open at the mouth (south-west) and the exit (north-east)
        z_a, z_b = (z0 + width, z0 + lanes * width) if x == qx0 else (z0, z0 + (lanes - 1) * width)
        for z in np.linspace(z_a, z_b, max(2, int(round((z_b - z_a) / 2.2)) + 1)):
            _trunk(s, np.array([x, float(z)]), 0.04, -0.05, 0.95)
        s.box(x - 0.01, x + 0.01, belt - 0.05, belt, z_a, z_b)
    # the screening line north of the queue's exit: cabinets with passages 1.6 m wide
    zq = z0 + lanes * width + 3.0
    holes: list[tuple[float, float, float, float]] = []
    for k in range(4):
        x = qx0 + 2.0 + k * 3.6
        holes.append(_ridged(s, x, x + 2.0, zq, zq + 1.2, -0.1, 1.8))
    # the shops: walls 0.2 m, a shutter over the front from its lower edge to 3 m, a lintel wall above
    for (sx0, sx1), edge in plan["shops"]:
        for x in (sx0, sx1):
            s.box(x - 0.1, x + 0.1, -0.1, 4.0, front_z, size_z)
        s.box(sx0, sx1, edge, 4.0, front_z - 0.05, front_z + 0.05)
        p = np.array([(sx0 + sx1) / 2, size_z - 1.0])
        holes.append(_ridged(s, p[0] - 1.5, p[0] + 1.5, p[1] - 0.4, p[1] + 0.4, -0.1, 1.0))  # a counter
    spots: list[tuple[np.ndarray, float]] = []
    keep = [(qx0 - 1.0, qx1 + 1.0, 0.0, zq + 3.0), (qx1, size_x, front_z - 2.5, size_z)]
    for _ in range(int(rng.integers(5, 9))):  # benches and bins in the hall's east part
        p = _placed(rng, spots, qx1 + 3.0, size_x - 2.0, 2.0, front_z - 3.0, 1.2, keep)
        if p is not None:
            holes.append(_ridged(s, p[0] - 1.0, p[0] + 1.0, p[1] - 0.3, p[1] + 0.3, -0.1, 0.5))
    s.ground(-6.0, size_x + 6.0, -8.0, size_z + 4.0, 0.0, holes)
    return s.mesh()


def far_outpost_plan(seed: int) -> dict:
    """The plan of :func:`far_outpost` for ``seed``: each hub's centre and radius, the tunnels (i, j, width) along a
    spanning tree of the hubs and two more pairs, and the offset (x, y, z, metres) the whole is moved by. O(hubs^2)."""
    rng = np.random.default_rng(seed)
    centres: list[np.ndarray] = []
    while len(centres) < 14:
        p = rng.uniform(0.0, 160.0, 2)
        if all(np.linalg.norm(p - c) > 26.0 for c in centres):
            centres.append(p)
    radii = [float(rng.uniform(4.0, 6.0)) for _ in centres]
    n = len(centres)
    dist = np.array([[np.linalg.norm(a - b) for b in centres] for a in centres])

    def heading(i: int, j: int) -> float:
        return math.atan2(*(centres[j] - centres[i])[::-1])

    def apart(i: int, j: int, edges: list[tuple[int, int]]) -> bool:  # 45 degrees or more from every tunnel at i or j
        for a, b in ((i, j), (j, i)):
            for e in edges:
                if a in e:
                    other = e[1] if e[0] == a else e[0]
                    diff = abs((heading(a, b) - heading(a, other) + math.pi) % (2 * math.pi) - math.pi)
                    if diff < math.radians(45.0):
                        return False
        return True

    inside, edges = {0}, []
    while len(inside) < n:  # Prim's tree, a join close in angle to a tunnel already at a hub taken last
        options = sorted(((i, j) for i in inside for j in range(n) if j not in inside), key=lambda e: dist[e])
        i, j = next((e for e in options if apart(*e, edges)), options[0])
        edges.append((i, j))
        inside.add(j)
    for i, j in sorted(((i, j) for i in range(n) for j in range(i + 1, n)), key=lambda e: dist[e]):
        if len(edges) == n + 1:
            break
        if (i, j) not in edges and (j, i) not in edges and dist[i, j] < 60.0 and apart(i, j, edges):
            edges.append((i, j))
    tunnels = [(i, j, float(rng.uniform(1.7, 2.6))) for i, j in edges]
    offset = (float(rng.choice([-1.0, 1.0]) * rng.uniform(35e3, 55e3)), float(rng.uniform(1.5e3, 3e3)),
              float(rng.choice([-1.0, 1.0]) * rng.uniform(35e3, 55e3)))
    return {"centres": centres, "radii": radii, "tunnels": tunnels, "offset": offset}


def far_outpost(seed: int, far: bool = True) -> trimesh.Trimesh:
    """A research outpost (a survival game's or an open-world shooter's, placed where the world's map puts it): 14 round
    hubs (16-gons 4-6 m in radius, walls 3 m high) on a site of about 170 m square, joined along a spanning tree and
    two more pairs by *tunnels 1.7-2.6 m wide (drawn per tunnel) at whatever heading their hubs give* (no two at one
    hub within 45 degrees), each a floor strip walled 3 m high along both sides, nothing but the hubs and tunnels
    being floor, open to the sky; crates and a console (ridged) in each hub. *The whole stands 35-55 km from the
    origin along x and along z (either way, drawn) and 1.5-3 km up* (``far_outpost_plan(seed)["offset"]``: as an
    open world's cell keeps its world coordinates); ``far=False`` builds the same outpost at the origin.

    Expected (written before the first run): one area for a player. The figures of every route should be those of
    its twin at the origin (in float32, which Recast and ray casting use, a coordinate of 55 km is held to about 4
    mm, far under a 0.25 m cell and the tunnels' widths), so what differs from the twin is a fault of precision. On
    both the twin and the far outpost, the navmesh route may lose tunnels under about 1.7 m at angles to its grid
    (rounds 33-34), leaving hubs apart; the structure a node in each hub and a chain along each tunnel, traffic
    highest on the tree's middle tunnels."""
    plan = far_outpost_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    centres, radii = plan["centres"], plan["radii"]
    s = _Solids()
    sides = 16
    ring = np.linspace(0.0, 2 * math.pi, sides, endpoint=False)
    for c, r in zip(centres, radii):
        s.prism(c + r * np.stack([np.cos(ring), np.sin(ring)], 1), -0.5, 0.0)
    openings: list[list[tuple[float, float]]] = [[] for _ in centres]  # per hub: (heading, half angle) of its tunnels
    for i, j, width in plan["tunnels"]:
        a, b = centres[i], centres[j]
        along = (b - a) / np.linalg.norm(b - a)
        side = np.array([-along[1], along[0]])
        p, q = a + along * (radii[i] - 0.6), b - along * (radii[j] - 0.6)  # into each hub past its wall
        s.prism(_strip(p, q, width), -0.5, 0.0)
        wp, wq = a + along * math.sqrt(max(radii[i] ** 2 - (width / 2 + 0.15) ** 2, 0.0)), \
            b - along * math.sqrt(max(radii[j] ** 2 - (width / 2 + 0.15) ** 2, 0.0))
        for sign in (-1.0, 1.0):
            off = side * sign * (width / 2 + 0.15)
            _wall_line(s, wp + off, wq + off, -0.1, 3.0, 0.3, [])
        for hub, direction in ((i, along), (j, -along)):
            openings[hub].append((math.atan2(direction[1], direction[0]), math.asin(min(1.0, (width / 2 + 0.3) / radii[hub]))))
    for h, (c, r) in enumerate(zip(centres, radii)):  # the hub's wall: a 16-gon of chords, open over each tunnel
        angles = np.linspace(0.0, 2 * math.pi, sides + 1)
        for a0, a1 in zip(angles[:-1], angles[1:]):
            mid = (a0 + a1) / 2
            if any(abs((mid - t + math.pi) % (2 * math.pi) - math.pi) < half + math.pi / sides for t, half in openings[h]):
                continue
            p0, p1 = c + (r + 0.15) * np.array([math.cos(a0), math.sin(a0)]), c + (r + 0.15) * np.array([math.cos(a1), math.sin(a1)])
            _wall_line(s, p0, p1, -0.1, 3.0, 0.3, [])
        for _ in range(int(rng.integers(1, 3))):  # crates or a console near the middle, off the tunnels' mouths
            ang = float(rng.uniform(0.0, 2 * math.pi))
            if any(abs((ang - t + math.pi) % (2 * math.pi) - math.pi) < 0.7 for t, _ in openings[h]):
                continue
            p = c + 0.45 * r * np.array([math.cos(ang), math.sin(ang)])
            _ridged(s, p[0] - 0.6, p[0] + 0.6, p[1] - 0.6, p[1] + 0.6, -0.1, 1.2)
    mesh = s.mesh()
    if far:
        mesh.apply_translation(plan["offset"])
    return mesh


def canteen_plan(seed: int) -> dict:
    """The plan of :func:`canteen` for ``seed``: the hall's size and each table block (x0, x1, z0, z1 of its top,
    the top's height, how many tables pushed together across it). O(blocks)."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(56.0, 64.0)), float(rng.uniform(32.0, 38.0))
    blocks = []
    z = 4.0
    while z + 4.0 < size_z - 6.0:  # rows of blocks along x, 2.6-3.4 m of aisle between a row's benches and the next
        across = int(rng.choice([1, 1, 2, 3]))
        depth = across * float(rng.uniform(0.85, 0.95))
        x = 3.0
        while x + 6.0 < size_x - 3.0:
            length = float(rng.uniform(3.6, 6.0))
            blocks.append({"rect": (x, x + length, z + 0.5, z + 0.5 + depth), "top": float(rng.uniform(0.74, 0.77)),
                           "across": across})
            x += length + float(rng.uniform(2.2, 3.2))
        z += depth + 1.0 + float(rng.uniform(2.6, 3.4))
    return {"size": (size_x, size_z), "blocks": blocks}


def _legged_top(s: _Solids, x0: float, x1: float, z0: float, z1: float, top: float, thickness: float,
                legs_x: int, legs_z: int) -> None:
    """A furniture top over [x0, x1] x [z0, z1], ``thickness`` m thick, its upper face at ``top``, on a legs_x x
    legs_z grid of legs 0.05 m square standing from the floor (y = 0): the floor runs on under it."""
    s.box(x0, x1, top - thickness, top, z0, z1)
    for x in np.linspace(x0 + 0.05, x1 - 0.1, legs_x):
        for z in np.linspace(z0 + 0.05, z1 - 0.1, legs_z):
            s.box(float(x), float(x) + 0.05, -0.05, top - thickness, float(z), float(z) + 0.05)


def canteen(seed: int) -> trimesh.Trimesh:
    """A mess hall (a school's canteen in a horror game, a barracks' in a shooter) 56-64 x 32-38 m, walls 4 m high,
    two doors 2.4 m wide, open to the sky, furnished *as real furniture is modelled*: tables are a top 0.04 m thick
    0.74-0.77 m up on legs 0.05 m square, with *open floor under them*; along each table block's two long sides a
    bench (a seat 0.35 m deep, 0.45 m up, on legs). Blocks stand in rows along x; *a block is one table (0.85-0.95 m
    deep) or two or three pushed together (1.7-2.9 m deep), drawn per row*, 3.6-6 m long, 2.2-3.2 m apart along a row,
    with aisles of 2.6-3.4 m between the benches of two rows. A serving counter (solid, 0.9 m high, 0.8 m deep) along
    the north wall with a kitchen door beside it; round cafe tables (a top 0.9 m across on one post) with chairs near
    the doors (``canteen_plan(seed)``).

    Expected (written before the first run): for a player one area, the aisles between the rows, no floor under or on
    the furniture (a table's top 0.75 m up is over the climb, the floor under it has 0.7 m of head room). Recast reads
    surfaces: a top is floor to it, out of reach, and a top of 1.7-2.9 m deep keeps floor after the ledge rule and the
    radius (one cell and two from each edge, about 1.6-1.8 m) only on the three-table blocks, so on the navmesh route
    those tops may be areas apart (as the container tops of round 18 and the racks' tops of round 28 were); their
    warnings would name a floor 0.75 m over the hall's, a table a designer would not call a place. The sampling
    route places samples on any top wide enough for the agent's 1 m, so more of them may be areas apart there. The
    benches (0.45 m, over the climb; 0.35 m deep) hold nothing. Traffic highest between the doors and along the
    aisle by the counter, lowest in the rows' far ends."""
    plan = canteen_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    size_x, size_z = plan["size"]
    s = _Solids()
    west_door = float(rng.uniform(4.0, size_z - 8.0))
    south_door = float(rng.uniform(size_x / 2, size_x - 6.0))
    s.wall((0.0, 0.0), (size_x, 0.0), -0.1, 4.0, [(south_door, 2.4)], thickness=0.3)
    s.wall((0.0, size_z), (size_x, size_z), -0.1, 4.0, [(3.0, 1.8)], thickness=0.3)  # the kitchen door
    s.wall((0.0, 0.0), (0.0, size_z), -0.1, 4.0, [(west_door, 2.4)], thickness=0.3)
    s.wall((size_x, 0.0), (size_x, size_z), -0.1, 4.0, thickness=0.3)
    holes = [(6.0, size_x - 4.0, size_z - 0.95, size_z - 0.15)]
    s.box(6.0, size_x - 4.0, -0.1, 0.9, size_z - 0.95, size_z - 0.15)  # the serving counter, flat topped
    for block in plan["blocks"]:
        x0, x1, z0, z1 = block["rect"]
        legs_x = max(2, int(round((x1 - x0) / 1.8)) + 1)
        _legged_top(s, x0, x1, z0, z1, block["top"], 0.04, legs_x, block["across"] + 1)
        for zb in (z0 - 0.5, z1 + 0.15):  # the benches, 0.15 m off the table's edges
            _legged_top(s, x0 + 0.2, x1 - 0.2, zb, zb + 0.35, 0.45, 0.04, legs_x, 2)
    for k in range(int(rng.integers(3, 6))):  # cafe tables and chairs in the strip inside the south door
        c = np.array([south_door - 6.0 + 3.0 * k, 2.0])
        if not 1.0 < c[0] < size_x - 1.5:
            continue
        s.prism(_octagon(c, 0.9), 0.72, 0.75)
        _trunk(s, c, 0.04, -0.05, 0.72)
        for dx in (-0.75, 0.75):  # a chair each side: a seat on four legs and a back
            cx = c[0] + dx
            _legged_top(s, cx - 0.21, cx + 0.21, c[1] - 0.21, c[1] + 0.21, 0.45, 0.03, 2, 2)
            bx = cx + (0.19 if dx > 0 else -0.21)
            s.box(bx, bx + 0.02, 0.45, 0.9, c[1] - 0.21, c[1] + 0.21)
    s.ground(-6.0, size_x + 6.0, -6.0, size_z + 4.0, 0.0, holes)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "grating_plant": grating_plant, "stepping_stones": stepping_stones, "bridge_arena": bridge_arena,
    "queue_hall": queue_hall, "far_outpost": far_outpost, "canteen": canteen,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirty-sixth round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
