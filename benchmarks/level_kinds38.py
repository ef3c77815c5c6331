"""Level kinds of the thirty-eighth held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each a few hundred navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py`` and ``level_kinds30.py`` (imported, not copied): ``headstone_yard`` (a churchyard of
family plots each ringed by *thin leaning headstones 0.5-1.35 m apart*, drawn per side, a plot entered only between
them), ``coaming_deck`` (a ship's deck whose cabin doors stand on *coamings 0.25-0.55 m high*, drawn per door, whose
hatch covers stand as high, and whose decks are joined by *companionways of open treads at 50-60 degrees*, drawn per
stair, each tread shorter than a navmesh cell), ``rubble_nave`` (a roofless church whose galleries are reached only
*up rubble heaps of 28-52 degrees*, drawn per heap, strewn with rocks), ``raised_beds`` (a glasshouse of planting beds
*0.3-0.7 m high*, drawn per bed, between *paths 0.8-1.6 m wide*, drawn per path), ``open_stairs`` (an office atrium
whose storeys are joined only by *open-riser flights*: floating treads 0.04-0.06 m thick whose fronts overlap the tread
below by -0.05 to +0.04 m, drawn per flight) and ``stile_fields`` (pastures between dry-stone walls crossed at gates,
at *step stiles of risers 0.3-0.5 m* and at *squeeze stiles whose slot is 0.25-0.45 m wide at the ground and 0.9-1.2 m
at 1 m up*, drawn per stile).

Run: ``.venv/bin/python benchmarks/level_kinds38.py OUT_DIR [--kinds headstone_yard stile_fields] [--seeds 0 1 2]``
writes ``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _lid, _ridged, _Solids, _trunk
from level_kinds import main as write_kinds
from level_kinds30 import _placed

STONE_THICKNESS = 0.12
"""Thickness of a headstone, metres (under half a navmesh cell of the presets' 0.25 m)."""

AGENT_DIAMETER = 1.0
"""The presets' agent's diameter (2 x radius 0.5 m): the gap a player fits through, by which the plans' answers read."""

AGENT_CLIMB = 0.4
"""The presets' agent's climb, metres: the step a player takes, by which the plans' answers read."""

AGENT_SLOPE = 45.0
"""The presets' agent's slope limit, degrees."""


def _side_stones(length: float, width: float, gap: float, wider: bool) -> tuple[int, float]:
    """How many stones ``width`` m wide stand along a side ``length`` m long at gaps of about ``gap`` m, and the gap
    they leave (the stones spread over the side, the first and the last at its ends; at least two): the gap left at
    least ``gap`` when ``wider``, else at most ``gap``."""
    stones = (length + gap) / (width + gap)
    n = max(2, math.floor(stones) if wider else math.ceil(stones))
    if wider and (length - (n + 1) * width) / n >= gap - 0.05:  # one stone more while the gap stays about as drawn
        n += 1
    return n, (length - n * width) / (n - 1)


def headstone_yard_plan(seed: int) -> dict:
    """The plan of :func:`headstone_yard` for ``seed``: the grid of plots (columns, rows, plot size along x and z, the
    path between plots, the yard's south-west plot corner) and per plot its stone width, its four sides' gaps as built
    (south, north, west, east), whether it is open (one side drawn with gaps of 1.0-1.35 m, the others 0.5-0.9 m) and
    whether a chest tomb stands in it. O(plots)."""
    rng = np.random.default_rng(seed)
    cols, rows = int(rng.integers(6, 8)), int(rng.integers(4, 6))
    size = (float(rng.uniform(5.0, 6.5)), float(rng.uniform(4.0, 5.0)))
    path = float(rng.uniform(2.0, 2.6))
    plots = []
    for c in range(cols):
        for r in range(rows):
            width = float(rng.uniform(0.5, 0.8))
            is_open = rng.random() < 0.65
            way_in = int(rng.integers(4)) if is_open else -1
            gaps = {}
            for i, side in enumerate(("south", "north", "west", "east")):
                wanted = float(rng.uniform(1.0, 1.35)) if i == way_in else float(rng.uniform(0.5, 0.9))
                length = size[0] if side in ("south", "north") else size[1] - 2 * STONE_THICKNESS
                gaps[side] = _side_stones(length, width, wanted, wider=i == way_in)
            plots.append({"cell": (c, r), "width": width, "gaps": gaps, "open": is_open,
                          "tomb": bool(rng.random() < 0.5), "height": float(rng.uniform(0.7, 1.2))})
    return {"grid": (cols, rows, size, path, (8.0, 8.0)), "plots": plots}


def _headstone(s: _Solids, p: np.ndarray, along: np.ndarray, width: float, height: float, lean: float) -> None:
    """A headstone: a slab ``width`` m along the unit plan vector ``along``, :data:`STONE_THICKNESS` thick, centred
    on plan point ``p``, ``height`` m high and leaning ``lean`` degrees across its face (its top shifted that way)."""
    side = np.array([-along[1], along[0]])
    shift = side * height * math.tan(math.radians(lean))
    points = []
    for a in (-width / 2, width / 2):
        for t in (-STONE_THICKNESS / 2, STONE_THICKNESS / 2):
            q = p + along * a + side * t
            points += [[q[0], -0.1, q[1]], [q[0] + shift[0], height, q[1] + shift[1]]]
    s.hull(np.array(points))


def headstone_yard(seed: int) -> trimesh.Trimesh:
    """An old churchyard (a horror game's, an open world's village) of 6-7 x 4-5 family plots 5.0-6.5 x 4.0-5.0 m
    (``headstone_yard_plan(seed)``) between grass paths 2.0-2.6 m wide, inside a wall 1.8 m high with a lych gate 3 m
    wide in the south, a church (ridged) north of the plots and yews (trunks) in the margins west and east. Each plot is
    *ringed by headstones*: thin slabs 0.12 m thick, 0.5-0.8 m wide (drawn per plot), 0.7-1.2 m high, each leaning 0-15
    degrees across its face, standing along the plot's four sides *at gaps drawn per side*: an open plot (about two in
    three) has one side of gaps 1.0-1.35 m (its way in), its other sides and every side of a closed plot gaps of 0.5-0.9
    m (the stones spread over the side: a way in's gaps at least what was drawn, the others' at most). Half the plots
    hold a chest tomb (1.9 x 0.9 m, 0.8 m high), the rest a ledger 0.1 m high.

    Expected (written before the first run): a player (1 m across) walks into a plot between two stones 1 m or more
    apart and never between stones under 1 m apart; so one area for the paths and every open plot, and *each closed plot
    an area apart* (its inside 4-6 m across holds the agent): by the plan 17 / 13 / 10 closed plots of 35 / 30 / 28 on
    seeds 0-2 (their widest gaps 0.39-0.81 m), so 18 / 14 / 11 areas; the open plots' widest gaps are 1.01-3.13 m, one a
    seed under 1.1 m on seeds 0 and 2, which may read either way on the navmesh (0.25 m cells: round 37 walked piers
    1.15 m apart). The sampling route should agree (its walk test is the agent's body). The thin stones (under half a
    cell) are walls on both routes. Traffic highest on the paths between the gate and the church, each open plot a dead
    end (cold) behind its way in; the structure should enter an open plot through its way in, never between stones under
    1 m apart."""
    plan = headstone_yard_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    cols, rows, (px, pz), path, (ox, oz) = plan["grid"]
    size_x, size_z = ox * 2 + cols * px + (cols - 1) * path, oz + 14.0 + rows * pz + (rows - 1) * path
    s = _Solids()
    s.wall((0.0, 0.0), (size_x, 0.0), -0.1, 1.8, [(size_x / 2 - 1.5, 3.0)], thickness=0.5)
    s.wall((0.0, size_z), (size_x, size_z), -0.1, 1.8, thickness=0.5)
    s.wall((0.0, 0.0), (0.0, size_z), -0.1, 1.8, thickness=0.5)
    s.wall((size_x, 0.0), (size_x, size_z), -0.1, 1.8, thickness=0.5)
    holes = [_ridged(s, size_x / 2 - 9.0, size_x / 2 + 9.0, size_z - 11.0, size_z - 3.0, -0.1, 6.0)]  # the church
    for plot in plan["plots"]:
        c, r = plot["cell"]
        x0, z0 = ox + c * (px + path), oz + r * (pz + path)
        x1, z1 = x0 + px, z0 + pz
        w, h = plot["width"], plot["height"]
        for side, (n, gap) in plot["gaps"].items():
            if side in ("south", "north"):
                z = z0 + STONE_THICKNESS / 2 if side == "south" else z1 - STONE_THICKNESS / 2
                start, along = np.array([x0 + w / 2, z]), np.array([1.0, 0.0])
            else:
                x = x0 + STONE_THICKNESS / 2 if side == "west" else x1 - STONE_THICKNESS / 2
                start, along = np.array([x, z0 + STONE_THICKNESS + w / 2]), np.array([0.0, 1.0])
            for i in range(n):
                lean = float(rng.uniform(0.0, 15.0)) * (1 if rng.random() < 0.5 else -1)
                _headstone(s, start + along * i * (w + gap), along, w, h * float(rng.uniform(0.9, 1.1)), lean)
        mx, mz = (x0 + x1) / 2, (z0 + z1) / 2
        if plot["tomb"]:
            s.box(mx - 0.95, mx + 0.95, -0.1, 0.8, mz - 0.45, mz + 0.45)
        else:
            s.box(mx - 0.9, mx + 0.9, -0.1, 0.1, mz - 0.4, mz + 0.4)
    for z in np.arange(oz + 2.0, size_z - 14.0, 7.0):  # yews in the margins west and east of the plots
        for x in (ox / 2, size_x - ox / 2):
            if rng.random() < 0.6:
                _trunk(s, np.array([float(x), float(z)]), 0.35, -0.1, 4.0)
    s.ground(-4.0, size_x + 4.0, -4.0, size_z + 4.0, 0.0, holes)
    return s.mesh()


def _flight_run(y0: float, y1: float, riser: float, going: float) -> float:
    """The plan length of :func:`_open_flight` from a floor at ``y0`` to one at ``y1``: ``round((y1 - y0) / riser)``
    risers, the last onto the upper floor itself, so one going fewer than risers."""
    return going * (max(1, round((y1 - y0) / riser)) - 1)


def _open_flight(s: _Solids, foot: np.ndarray, heading: np.ndarray, width: float, y0: float, y1: float,
                 riser: float, going: float, thickness: float, overlap: float) -> None:
    """An open-riser flight from plan point ``foot`` (x, z) along the unit ``heading``, from a floor at ``y0`` to one
    at ``y1`` whose edge lies :func:`_flight_run` ahead: ``round((y1 - y0) / riser)`` risers, the last onto the upper
    floor, each tread a plate ``thickness`` m thick and ``going + overlap`` m deep (its front over the tread below by
    ``overlap``; a gap of ``-overlap`` in plan between them when negative), nothing between the treads; beside each
    side a stringer 0.1 m thick (0.05 m clear of the treads) and over it a handrail 0.9-1.0 m over the nosings."""
    n = max(1, round((y1 - y0) / riser))
    rise = (y1 - y0) / n
    side = np.array([-heading[1], heading[0]])
    half = side * width / 2
    for i in range(n - 1):
        back = foot + heading * going * (i + 1)
        front = back - heading * (going + overlap)
        top = y0 + rise * (i + 1)
        s.prism(np.array([front - half, back - half, back + half, front + half]), top - thickness, top)
    end = foot + heading * _flight_run(y0, y1, riser, going)
    for sign in (-1.0, 1.0):
        inner, outer = side * sign * (width / 2 + 0.05), side * sign * (width / 2 + 0.15)
        stringer = ((y0 - 0.3, y0 + 0.05), (y1 - 0.3, y1 - thickness))
        for low, high in (stringer, ((y0 + 0.9, y0 + 1.0), (y1 + 0.9, y1 + 1.0))):
            s.hull(np.array([[p[0], y, p[1]] for base, ys in ((foot, low), (end, high)) for y in ys
                             for p in (base + inner, base + outer)]))


def coaming_deck_plan(seed: int) -> dict:
    """The plan of :func:`coaming_deck` for ``seed``: the deck's length and beam, the deckhouse's x range, its roof's
    height, each cabin (side, x range, door coaming), the deckhouse's two doors' coamings (fore, aft), each hatch
    (x range, coaming), and each companionway (where, pitch, riser, going). O(cabins)."""
    rng = np.random.default_rng(seed)
    length, beam = float(rng.uniform(100.0, 110.0)), float(rng.uniform(15.0, 17.0))
    house = (length - 30.0, length - 3.0)
    cabins = []
    for side in ("port", "starboard"):
        x = house[0] + 0.2
        while True:
            w = float(rng.uniform(3.4, 4.4))
            if x + w > house[1] - 0.2:
                break
            cabins.append({"side": side, "x": (x, x + w), "coaming": float(rng.uniform(0.25, 0.55))})
            x += w
    hatches = []
    x = 6.0
    for _ in range(5):
        w = float(rng.uniform(6.0, 8.0))
        hatches.append({"x": (x, x + w), "coaming": float(rng.uniform(0.3, 0.55))})
        x += w + float(rng.uniform(4.0, 6.0))
    stairs = []
    for where in ("tween_fore", "tween_aft", "roof_port", "roof_starboard"):
        pitch = float(rng.uniform(50.0, 60.0))
        riser = float(rng.uniform(0.2, 0.24))
        stairs.append({"where": where, "pitch": pitch, "riser": riser, "going": riser / math.tan(math.radians(pitch))})
    return {"length": length, "beam": beam, "house": house, "roof": 2.8, "tween": -3.0, "cabins": cabins,
            "doors": {"fore": float(rng.uniform(0.25, 0.55)), "aft": float(rng.uniform(0.25, 0.55))},
            "hatches": hatches, "stairs": stairs}


def coaming_deck(seed: int) -> trimesh.Trimesh:
    """A cargo ship's weather deck (a shooter's boarding map, a stealth game's freighter) 100-110 x 15-17 m
    (``coaming_deck_plan(seed)``) behind bulwarks 1.1 m high. Forward five hatches 6-8 m long whose covers stand *on
    coamings 0.3-0.55 m high* (drawn per hatch: the cover's top at the coaming's). Aft a deckhouse 27 m long, walls 2.6
    m high under a roof deck 2.8 m up railed 1 m, entered from the deck by a door 1.4 m wide at each end (the aft one
    from the deck's stern, reached along the side decks), *over a coaming 0.25-0.55 m high and 0.12 m thick* (drawn per
    door), into a corridor 1.8 m wide along its middle off which cabins 3.4-4.4 m wide open, each by a door 1.2 m wide
    *over its own coaming of 0.25-0.55 m*. Under the fore deck a tween deck 3 m down and 60 m long (head room 2.7 m,
    cargo boxes), reached through two railed openings in the deck by *companionways*, and the roof deck reached from the
    deck by two more, one on each side: every companionway an open stair 1.4 m wide *at 50-60 degrees* (drawn per
    stair), risers 0.20-0.24 m, so each tread 0.12-0.20 m deep, under the navmesh's 0.25 m cell; bollards, winches,
    vents and lashing boxes on the deck.

    Expected (written before the first run): a player with the agent's 0.4 m climb steps over a coaming of 0.4 m or less
    and not over a higher one, so a cabin behind a coaming over 0.4 m is an area apart (its floor 3-4 m across), the
    deckhouse's corridor and the cabins it reaches apart if both its doors' coamings are over 0.4 m, a hatch cover over
    0.4 m up an area apart (a top 6 x 6-8 m). By the plan (seeds 0-2) the corridor is reached on every seed (a door's
    coaming of 0.32 / 0.31 / 0.39 m), cabins apart 7 / 4 / 5 of 12, hatches apart 2 / 4 / 3 of 5: 10 / 9 / 9 areas;
    coamings of 0.40-0.425 m (seed 1 two cabins of 0.411-0.412 m and a hatch of 0.415 m, seed 2 a hatch of 0.402 m) may
    read either way. Each companionway's riser is under the climb: a player (whose controller climbs by the step) walks
    them, so the tween deck and the roof deck belong to the deck's area. *The navmesh route may cut them*: its cells of
    0.25 m hold two tread edges where a tread is shorter than a cell, so neighbouring cells' tops differ by two risers
    (0.40-0.48 m), over the climb; if it does, the tween deck and the roof deck are areas apart on the navmesh route (a
    miss of its cell size, not of the level). The flight's line at 50-60 degrees is over the slope limit but no surface
    slopes so. The sampling route should follow the player. Traffic highest on the deck along the hatches and at the
    deckhouse's doors."""
    plan = coaming_deck_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    length, beam, (h0, h1), roof, tween = plan["length"], plan["beam"], plan["house"], plan["roof"], plan["tween"]
    s = _Solids()
    stairs = {st["where"]: st for st in plan["stairs"]}
    width = 1.4
    openings, flights = [], []
    for where, x in (("tween_fore", 3.0), ("tween_aft", 50.0)):  # each climbs to the opening's forward edge
        st = stairs[where]
        run = _flight_run(tween, 0.0, st["riser"], st["going"])
        z = beam / 2 - 4.5 if where == "tween_fore" else beam / 2 + 4.5
        openings.append((x, x + run + 1.0, z - width / 2 - 0.1, z + width / 2 + 0.1))
        flights.append((st, np.array([x + run, z]), np.array([-1.0, 0.0]), tween, 0.0))
    s.slab(0.0, length, 0.0, beam, 0.0, openings)  # the weather deck, open over each companionway
    s.box(0.0, 60.0, tween - 0.3, tween, 0.0, beam)  # the tween deck under the fore deck
    s.wall((0.0, 0.0), (0.0, beam), tween, 1.1, thickness=0.3)
    s.wall((0.0, 0.0), (length, 0.0), tween, 1.1, thickness=0.3)
    s.wall((0.0, beam), (length, beam), tween, 1.1, thickness=0.3)
    s.wall((length, 0.0), (length, beam), -0.3, 1.1, thickness=0.3)
    s.wall((60.0, 0.0), (60.0, beam), tween, -0.3, thickness=0.3)  # the tween deck's aft bulkhead
    for x0, x1, z0, z1 in openings:  # rails round each opening but at the stair's head
        s.wall((x0, z0), (x1, z0), 0.0, 1.0, thickness=0.08)
        s.wall((x0, z1), (x1, z1), 0.0, 1.0, thickness=0.08)
        s.wall((x1, z0), (x1, z1), 0.0, 1.0, thickness=0.08)
    for _ in range(int(rng.integers(30, 40))):  # cargo on the tween deck
        x, z = float(rng.uniform(8.0, 56.0)), float(rng.uniform(1.5, beam - 1.5))
        if any(o[0] - 1.5 < x < o[1] + 1.5 and o[2] - 1.5 < z < o[3] + 1.5 for o in openings):
            continue
        s.box(x - 0.8, x + 0.8, tween, tween + float(rng.uniform(1.0, 2.2)), z - 0.6, z + 0.6)
    for hatch in plan["hatches"]:  # a cover on its coaming: one solid as high as the coaming
        x0, x1 = hatch["x"]
        s.box(x0, x1, -0.1, hatch["coaming"], beam / 2 - 3.0, beam / 2 + 3.0)
    # the deckhouse: walls, a corridor along its middle, cabins either side, a roof deck
    zc0, zc1 = beam / 2 - 0.9, beam / 2 + 0.9
    z_in0, z_in1 = 2.0, beam - 2.0
    s.wall((h0, z_in0), (h1, z_in0), 0.0, roof - 0.2, thickness=0.2)
    s.wall((h0, z_in1), (h1, z_in1), 0.0, roof - 0.2, thickness=0.2)
    for x, door in ((h0, "fore"), (h1, "aft")):  # a door into the corridor at each end, over its coaming
        s.wall((x, z_in0), (x, z_in1), 0.0, roof - 0.2, [(beam / 2 - 0.7 - z_in0, 1.4)], thickness=0.2)
        s.box(x - 0.06, x + 0.06, -0.1, plan["doors"][door], beam / 2 - 0.7, beam / 2 + 0.7)
    for z, side in ((zc0, "port"), (zc1, "starboard")):
        cabins = [c for c in plan["cabins"] if c["side"] == side]
        doors = [(c["x"][0] - h0 + 1.0, 1.2) for c in cabins]
        s.wall((h0, z), (h1, z), 0.0, roof - 0.2, doors, thickness=0.12)
        for c in cabins:
            s.box(c["x"][0] + 1.0, c["x"][0] + 2.2, -0.1, c["coaming"], z - 0.06, z + 0.06)
            if c is not cabins[-1]:  # the last cabin runs on to the deckhouse's aft wall
                s.wall((c["x"][1], z_in0 if side == "port" else z), (c["x"][1], z if side == "port" else z_in1), 0.0,
                       roof - 0.2, thickness=0.12)
            far = z_in0 + 0.5 if side == "port" else z_in1 - 1.3
            s.box(c["x"][0] + 0.5, c["x"][0] + 2.5, -0.1, 0.5, far, far + 0.8)  # a bunk against the hull side
    s.box(h0 - 0.1, h1 + 0.1, roof - 0.2, roof, z_in0 - 0.1, z_in1 + 0.1)
    s.wall((h0, z_in0), (h1, z_in0), roof, roof + 1.0, thickness=0.08)
    s.wall((h0, z_in1), (h1, z_in1), roof, roof + 1.0, thickness=0.08)
    s.wall((h1, z_in0), (h1, z_in1), roof, roof + 1.0, thickness=0.08)
    for where, z in (("roof_port", z_in0 + 1.0), ("roof_starboard", z_in1 - 1.0)):
        st = stairs[where]
        run = _flight_run(0.0, roof, st["riser"], st["going"])
        flights.append((st, np.array([h0 - run, z]), np.array([1.0, 0.0]), 0.0, roof))
    s.wall((h0, z_in0), (h0, z_in1), roof, roof + 1.0, [(0.2, 1.6), (z_in1 - z_in0 - 1.8, 1.6)], thickness=0.08)
    for st, foot, heading, y0, y1 in flights:
        _open_flight(s, foot, heading, width, y0, y1, st["riser"], st["going"], 0.05, 0.02)
    for x in np.arange(4.0, length - 32.0, 6.0):  # bollards along both bulwarks
        for z in (0.8, beam - 0.8):
            _trunk(s, np.array([float(x), z]), 0.2, -0.1, 0.6)
    for hatch in plan["hatches"][:4]:  # a winch aft of a hatch
        x = hatch["x"][1] + 1.5
        s.box(x - 0.6, x + 0.6, -0.1, 1.2, beam / 2 - 1.0, beam / 2 + 1.0)
    spots: list[tuple[np.ndarray, float]] = []
    keep = [(o[0] - 1.0, o[1] + 1.0, o[2] - 1.0, o[3] + 1.0) for o in openings]
    keep += [(h["x"][0] - 1.0, h["x"][1] + 2.5, beam / 2 - 4.0, beam / 2 + 4.0) for h in plan["hatches"]]
    for _ in range(int(rng.integers(16, 24))):  # vents and lashing boxes on the side decks
        p = _placed(rng, spots, 2.0, h0 - 4.0, 0.5, beam - 0.5, 0.6, keep)
        if p is None:
            continue
        if rng.random() < 0.5:
            _trunk(s, p, 0.3, -0.1, 1.6)
        else:
            s.box(p[0] - 0.5, p[0] + 0.5, -0.1, 0.9, p[1] - 0.3, p[1] + 0.3)
    return s.mesh()


def rubble_nave_plan(seed: int) -> dict:
    """The plan of :func:`rubble_nave` for ``seed``: the church's length, nave and aisle widths, the bay pitch, the
    galleries' height, and per aisle ("south", "north") its heaps (the bay where each starts, its slope in degrees).
    O(heaps)."""
    rng = np.random.default_rng(seed)
    bays = int(rng.integers(13, 15))
    pitch = float(rng.uniform(4.4, 5.0))
    gallery = float(rng.uniform(4.0, 4.6))
    heaps = {}
    for aisle in ("south", "north"):
        starts = sorted(rng.choice(np.arange(1, bays - 2, 3), size=int(rng.integers(1, 3)), replace=False).tolist())
        heaps[aisle] = [{"bay": int(b), "slope": float(rng.uniform(28.0, 52.0))} for b in starts]
    return {"bays": bays, "pitch": pitch, "nave": float(rng.uniform(10.0, 12.0)), "aisle": float(rng.uniform(5.0, 6.0)),
            "gallery": gallery, "heaps": heaps}


def rubble_nave(seed: int) -> trimesh.Trimesh:
    """A ruined abbey church (a war game's, a fantasy dungeon's way in) of 13-14 bays 4.4-5.0 m long
    (``rubble_nave_plan(seed)``), open to the sky: a nave 10-12 m wide between two aisles 5-6 m wide, parted by
    arcades of piers 1.2 m square at every bay; outer walls 9 m high with a west door 3 m wide into the nave and a
    door 2 m wide into each aisle from a churchyard round the church. Over each aisle a gallery 4.0-4.6 m up, from
    the outer wall to the arcade, behind a parapet 1 m high between the piers, with no stair: *where its floor fell
    (one or two breaches a gallery, each two bays long and the inner 3 m of its width) a rubble heap rises from the
    aisle to the gallery's floor at 28-52 degrees* (drawn per heap), strewn with rocks 0.1-0.3 m proud. On the nave's
    floor mounds of rubble (cones 1-2 m high, flanks of 30-40 degrees) and fallen column drums (1 m through); stones
    about the churchyard.

    Expected (written before the first run): a player climbs a slope under the agent's 45 degrees, rocks and all
    (each rock's step under the climb), and not one over it: a gallery is reached if one of its heaps slopes under
    45 degrees and is otherwise an area apart (the gallery's walk 2.5-3 m wide along the outer wall, 57-70 m long,
    around the breach). Heaps of 43-47 degrees may read either way on the navmesh (its slope read per triangle of the
    heap's face, rocks cutting it up). By the plan: seed 0's south gallery reached (heaps of 49.9 and 42.6 degrees),
    its north one apart (50.4, 47.6); seed 1's galleries reached (38.2 and 47.9; 41.2), seed 2's too (42.4; 32.5): 2 /
    1 / 1 areas. The nave, the aisles and the churchyard are one area; the mounds are walked over. Traffic
    highest along the nave between the west door and the aisles' doors; on a reached gallery along its walk from
    the heap; the structure climbs a heap, never a parapet or the arcade."""
    plan = rubble_nave_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    bays, pitch, nave, aisle, g = plan["bays"], plan["pitch"], plan["nave"], plan["aisle"], plan["gallery"]
    x0, z0 = 12.0, 12.0
    length, width = bays * pitch, nave + 2 * aisle
    x1, z1 = x0 + length, z0 + width
    s = _Solids()
    heap_plans: list[tuple[float, float, float, float]] = []  # the ground stops under each heap (no floor inside it)
    s.wall((x0, z0), (x1, z0), -0.1, 9.0, [(2.5 * pitch - 1.0, 2.0)], thickness=0.8)
    s.wall((x0, z1), (x1, z1), -0.1, 9.0, [(length - 2.5 * pitch - 1.0, 2.0)], thickness=0.8)
    s.wall((x0, z0), (x0, z1), -0.1, 9.0, [(aisle + nave / 2 - 1.5, 3.0)], thickness=0.8)
    s.wall((x1, z0), (x1, z1), -0.1, 9.0, thickness=0.8)
    for za in (z0 + aisle, z1 - aisle):  # the arcades: a pier at every bay line inside the church
        for i in range(1, bays):
            x = x0 + i * pitch
            s.box(x - 0.6, x + 0.6, -0.1, 8.0, za - 0.6, za + 0.6)
    for name, (wa, wb) in (("south", (z0 + 0.4, z0 + aisle)), ("north", (z1 - aisle, z1 - 0.4))):
        inner = (wb - 3.0, wb) if name == "south" else (wa, wa + 3.0)
        breaches = []
        for heap in plan["heaps"][name]:
            bx0, bx1 = x0 + heap["bay"] * pitch + 0.6, x0 + (heap["bay"] + 2) * pitch - 0.6
            breaches.append((bx0, bx1, inner[0], inner[1]))
            run = g / math.tan(math.radians(heap["slope"]))
            zm = (inner[0] + inner[1]) / 2
            foot = np.array([bx1 - run, zm])
            s.ramp(foot, np.array([bx1, zm]), 2.8, 0.0, g, thickness=g + 0.5)
            heap_plans.append((float(foot[0]), bx1, zm - 1.4, zm + 1.4))
            along = math.tan(math.radians(heap["slope"]))
            for _ in range(int(rng.integers(6, 10))):  # rocks strewn on its face
                t = float(rng.uniform(0.15, 0.85))
                p = foot + (np.array([bx1, zm]) - foot) * t + np.array([0.0, float(rng.uniform(-1.0, 1.0))])
                y = (p[0] - foot[0]) * along
                s.rock(rng, p, 0.12, y - 0.2, y + float(rng.uniform(0.1, 0.3)))
        s.slab(x0 + 0.4, x1 - 0.4, wa, wb, g, breaches)
        zp = wb - 0.1 if name == "south" else wa + 0.1
        for i in range(bays):  # the parapet between the piers, and round each breach's open sides
            s.box(x0 + i * pitch + 0.6, x0 + (i + 1) * pitch - 0.6, g, g + 1.0, zp - 0.1, zp + 0.1)
        for bx0, bx1, bz0, bz1 in breaches:
            zo = bz0 if name == "south" else bz1
            s.box(bx0, bx1, g, g + 1.0, zo - 0.1, zo + 0.1)
            s.box(bx0 - 0.1, bx0 + 0.1, g, g + 1.0, bz0, bz1)
    spots: list[tuple[np.ndarray, float]] = []
    keep = [(x0, x0 + 3.0, z0 + aisle + nave / 2 - 2.0, z0 + aisle + nave / 2 + 2.0)]
    for _ in range(int(rng.integers(8, 12))):  # mounds of rubble in the nave
        p = _placed(rng, spots, x0 + 3.0, x1 - 2.0, z0 + aisle + 1.5, z1 - aisle - 1.5, 2.6, keep)
        if p is None:
            continue
        h = float(rng.uniform(1.0, 2.0))
        r = h / math.tan(math.radians(float(rng.uniform(30.0, 40.0))))
        ring = [[p[0] + r * math.cos(a), -0.1, p[1] + r * math.sin(a)] for a in np.linspace(0, 2 * math.pi, 9)[:-1]]
        s.hull(np.array(ring + [[p[0], h, p[1]]]))
    for _ in range(int(rng.integers(6, 10))):  # fallen drums, lying along z
        p = _placed(rng, spots, x0 + 3.0, x1 - 2.0, z0 + aisle + 1.5, z1 - aisle - 1.5, 1.4, keep)
        if p is not None:
            s.hull(np.array([[p[0] + 0.5 * math.cos(a), 0.5 + 0.5 * math.sin(a), p[1] + dz]
                             for a in np.linspace(0, 2 * math.pi, 9)[:-1] for dz in (-0.9, 0.9)]))
    for _ in range(int(rng.integers(24, 34))):  # stones about the churchyard
        p = np.array([float(rng.uniform(2.0, x1 + 10.0)), float(rng.uniform(2.0, 8.0))])
        if rng.random() < 0.5:
            p[1] = z1 + 12.0 - p[1]
        s.rock(rng, p, 0.4, -0.1, float(rng.uniform(0.5, 1.2)))
    s.ground(0.0, x1 + 12.0, 0.0, z1 + 12.0, 0.0, heap_plans)
    return s.mesh()


def _glasshouse_plan(rng: np.random.Generator, south: float) -> dict:
    """One glasshouse of :func:`raised_beds_plan` whose south wall's path starts at z = ``south``."""
    x0 = 4.0
    columns, x = [], x0 + float(rng.uniform(0.8, 1.6))
    while True:
        length = float(rng.uniform(2.2, 3.6))
        if x + length > x0 + 56.0:
            break
        columns.append((x, x + length))
        x += length + float(rng.uniform(0.8, 1.6))
    x1 = columns[-1][1] + float(rng.uniform(0.8, 1.6))
    depths = [[float(rng.uniform(1.6, 2.0)) for _ in range(4)] for _ in range(2)]
    paths = [[float(rng.uniform(0.8, 1.6)) for _ in range(4)] for _ in range(2)]
    wall_path = [float(rng.uniform(1.8, 2.6)) for _ in range(2)]
    z_aisle = south + wall_path[0] + sum(depths[0]) + sum(paths[0][1:]) + paths[0][0]
    aisle = (z_aisle, z_aisle + 2.4)
    halves = {}
    for i, half in enumerate(("south", "north")):
        rows, z = [], aisle[0] - paths[i][0] if half == "south" else aisle[1] + paths[i][0]
        for k, depth in enumerate(depths[i]):
            rows.append((z - depth, z) if half == "south" else (z, z + depth))
            gap = paths[i][k + 1] if k + 1 < 4 else wall_path[i]
            z = (z - depth - gap) if half == "south" else (z + depth + gap)
        heights = {(c, r): float(rng.uniform(0.3, 0.4) if rng.random() < 0.75 else rng.uniform(0.41, 0.7))
                   for c in range(len(columns)) for r in range(len(rows))}
        halves[half] = {"rows": rows, "heights": heights, "edge": z}
    return {"x": (x0, x1), "aisle": aisle, "columns": columns, "halves": halves}


def raised_beds_plan(seed: int) -> dict:
    """The plan of :func:`raised_beds` for ``seed``: two glasshouses 8 m apart, each its x range, its main aisle's z
    range, and per half ("south", "north") the beds' columns (x0, x1), the rows (z0, z1), each bed's height (by
    (column, row)) and the z of its side wall ("edge"). O(beds)."""
    rng = np.random.default_rng(seed)
    first = _glasshouse_plan(rng, 4.0)
    return {"houses": [first, _glasshouse_plan(rng, first["halves"]["north"]["edge"] + 8.0)]}


def _glasshouse(s: _Solids, house: dict) -> list[tuple[float, float, float, float]]:
    """The glass walls, doors and beds of ``house`` (one of :func:`raised_beds_plan`'s), a potting bench and a water
    butt in its corners; returns the benches' plans (holes for the ground)."""
    x0, x1 = house["x"]
    z0, z1 = house["halves"]["south"]["edge"], house["halves"]["north"]["edge"]
    zm = (house["aisle"][0] + house["aisle"][1]) / 2
    s.wall((x0, z0), (x1, z0), -0.1, 3.0, thickness=0.1)
    s.wall((x0, z1), (x1, z1), -0.1, 3.0, thickness=0.1)
    s.wall((x0, z0), (x0, z1), -0.1, 3.0, [(zm - z0 - 1.0, 2.0)], thickness=0.1)
    s.wall((x1, z0), (x1, z1), -0.1, 3.0, [(zm - z0 - 1.0, 2.0)], thickness=0.1)
    for half in house["halves"].values():
        for (c, r), h in half["heights"].items():
            (bx0, bx1), (bz0, bz1) = house["columns"][c], half["rows"][r]
            s.box(bx0, bx1, -0.1, h, bz0, bz1)
    holes = []
    for x, z in ((x0 + 0.9, z0 + 0.5), (x1 - 0.9, z1 - 0.5)):  # potting benches in two corners
        holes.append(_ridged(s, x - 0.7, x + 0.7, z - 0.3, z + 0.3, -0.1, 0.9))
    for x, z in ((x1 - 0.5, z0 + 0.5), (x0 + 0.5, z1 - 0.5)):  # water butts in the other two
        _trunk(s, np.array([x, z]), 0.3, -0.1, 1.0)
    return holes


def raised_beds(seed: int) -> trimesh.Trimesh:
    """Two glasshouses 8 m apart (a farming game's, a survival game's base), each about 58 x 28 m
    (``raised_beds_plan(seed)``): glass walls 3 m high, a main aisle 2.4 m wide along x through its middle with a door 2
    m wide at each end, and on each side of it four rows of *planting beds 1.6-2.0 m deep and 2.2-3.6 m long, each a
    solid box of soil 0.3-0.4 m high, one in four 0.41-0.7 m* (drawn per bed), in columns *between paths 0.8-1.6 m wide*
    (drawn per path between columns and per path between rows; 1.8-2.6 m along the side walls); potting benches (ridged)
    and water butts (trunks) in the corners; barrows outside by the doors.

    Expected (written before the first run): a player steps onto a bed 0.4 m high or lower and walks over it, and not
    onto a higher one; a path under the agent's 1 m is not walked but where a low bed beside it is. So one area for the
    aisles, the paths of 1 m or more, the yard round the houses and every bed of 0.4 m or lower (three in four), and
    *each bed over 0.4 m an area apart* (its top 1.6-2.0 m across holds the agent): by the plan 53 / 48 / 48 of the 208
    / 216 / 216 beds on seeds 0-2 (54 / 49 / 49 areas), and 5 / 5 / 3 more of 0.40-0.425 m either way. Paths under 1 m
    between two high beds hold no floor. Both routes should read each high bed's top apart (a designer would call those
    tops out of reach; the warnings should name each as a separate floor 0.4-0.7 m up). Traffic highest on the main
    aisles between the doors, then on the paths of 1 m or more and over the low beds next to them."""
    plan = raised_beds_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    s = _Solids()
    holes = sum((_glasshouse(s, house) for house in plan["houses"]), [])
    x0, x1 = plan["houses"][0]["x"][0], max(house["x"][1] for house in plan["houses"])
    z0, z1 = plan["houses"][0]["halves"]["south"]["edge"], plan["houses"][1]["halves"]["north"]["edge"]
    s.ground(x0 - 6.0, x1 + 6.0, z0 - 6.0, z1 + 6.0, 0.0, holes)
    for house in plan["houses"]:
        zm = (house["aisle"][0] + house["aisle"][1]) / 2
        for _ in range(int(rng.integers(2, 4))):  # barrows and sacks outside, by the doors
            x = float(rng.choice([house["x"][0] - 3.0, house["x"][1] + 3.0])) + float(rng.uniform(-1.0, 1.0))
            z = zm + float(rng.choice([-1.0, 1.0])) * float(rng.uniform(2.5, 5.0))
            s.box(x - 0.4, x + 0.4, -0.1, 0.7, z - 0.3, z + 0.3)
    return s.mesh()


def open_stairs_plan(seed: int) -> dict:
    """The plan of :func:`open_stairs` for ``seed``: the building's size, its storey height, the atrium's x and z
    ranges, and each flight (its storeys, riser, going, tread thickness, overlap, width). O(1)."""
    rng = np.random.default_rng(seed)
    storey = float(rng.uniform(3.6, 4.2))
    flights = []
    for lower in (0, 0, 1, 1):
        flights.append({"from": lower, "riser": float(rng.uniform(0.17, 0.2)), "going": float(rng.uniform(0.25, 0.3)),
                        "thickness": float(rng.uniform(0.04, 0.06)), "overlap": float(rng.uniform(-0.05, 0.04)),
                        "width": float(rng.uniform(1.4, 1.8))})
    sx, sz = float(rng.uniform(50.0, 56.0)), float(rng.uniform(28.0, 32.0))
    return {"size": (sx, sz), "storey": storey, "atrium": (10.0, sx - 10.0, 10.0, sz - 10.0), "flights": flights}


def open_stairs(seed: int) -> trimesh.Trimesh:
    """An office block of three storeys 3.6-4.2 m apart (a heist game's, a shooter's office) 50-56 x 28-32 m
    (``open_stairs_plan(seed)``), round an atrium 30-36 x 8-12 m open from the ground to the roof (balustrades 1.1 m
    high round it on the upper storeys). The storeys are joined *only by open-riser flights*: four straight flights
    1.4-1.8 m wide, two from the ground up to the first storey across the atrium (landing at its east and west ends) and
    two from the first storey to the second through stairwells in the second storey's floor, each of *floating treads
    0.04-0.06 m thick with nothing between them, the front of each over the tread below by -0.05 to +0.04 m* (drawn per
    flight: a negative overlap is a gap in plan), risers 0.17-0.20 m, goings 0.25-0.30 m, on two stringers, railed. On
    each storey a ring of office floor round the atrium, rooms (partitions 3 m high, doors 1.4 m wide) along the outer
    walls, desks (boxes 0.75 m high) in them, a door 2 m wide at the ground storey's west and east ends.

    Expected (written before the first run): every riser is under the climb and every tread as deep as a cell, so a
    player walks every flight: *one area*, all three storeys, on both routes. The treads float: under a flight the floor
    keeps head room where the flight is over 2 m up, and a ray down between two treads (a gap of up to 0.05 m in plan,
    0.11-0.16 m of open riser) meets the floor below; neither route should read the open risers as walls or holes.
    Traffic highest on the atrium's flights and on the first storey's ring between the flights, lowest in the second
    storey's rooms; the structure runs up each flight."""
    plan = open_stairs_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    (sx, sz), storey = plan["size"], plan["storey"]
    ax0, ax1, az0, az1 = plan["atrium"]
    s = _Solids()
    f0, f1, f2, f3 = plan["flights"]
    runs = [_flight_run(0.0, storey, f["riser"], f["going"]) for f in plan["flights"]]
    wells = [(sx - 7.5 - runs[2], sx - 5.5, 2.0, 2.0 + f2["width"] + 0.4),
             (5.5, 7.5 + runs[3], sz - 2.0 - f3["width"] - 0.4, sz - 2.0)]  # 2 m of well over each flight's foot
    s.box(0.0, sx, -0.3, 0.0, 0.0, sz)
    s.slab(0.0, sx, 0.0, sz, storey, [(ax0, ax1, az0, az1)])
    s.slab(0.0, sx, 0.0, sz, 2 * storey, [(ax0, ax1, az0, az1)] + wells)
    _lid(s, 0.0, sx, 0.0, sz, 3 * storey - 0.3)  # the roof, ridged: no floor on it
    for level in range(3):
        y = level * storey
        doors = [(sz / 2 - 1.0, 2.0)] if level == 0 else []
        s.wall((0.0, 0.0), (sx, 0.0), y, y + storey - 0.3, thickness=0.3)
        s.wall((0.0, sz), (sx, sz), y, y + storey - 0.3, thickness=0.3)
        s.wall((0.0, 0.0), (0.0, sz), y, y + storey - 0.3, doors, thickness=0.3)
        s.wall((sx, 0.0), (sx, sz), y, y + storey - 0.3, doors, thickness=0.3)
        for z, room in ((4.5, (0.15, 4.5)), (sz - 4.5, (sz - 4.5, sz - 0.15))):  # rooms along the south and north
            xs = np.arange(8.0, sx - 8.0 + 0.01, 6.0)
            if level > 0:  # no partition over a stairwell or round a flight's foot
                xs = xs[xs > wells[1][1] + 1.0] if z > sz / 2 else xs[xs < wells[0][0] - 1.0]
            s.wall((float(xs[0]), z), (float(xs[-1]), z), y, y + 3.0, [(float(x - xs[0]) + 2.0, 1.4) for x in xs[:-1]],
                   thickness=0.12)
            for xa in xs:
                s.wall((float(xa), room[0]), (float(xa), room[1]), y, y + 3.0, thickness=0.12)
            for xa in xs[:-1]:
                for xd in (0.6, 3.8):  # two desks a room, most rooms
                    if rng.random() < 0.8:
                        zd = (room[0] + room[1]) / 2
                        s.box(float(xa) + xd, float(xa) + xd + 1.6, y, y + 0.75, zd - 0.4, zd + 0.4)
        if level > 0:  # balustrades round the atrium, open at the flights' heads
            s.wall((ax0, az0), (ax1, az0), y, y + 1.1, thickness=0.08)
            s.wall((ax0, az1), (ax1, az1), y, y + 1.1, thickness=0.08)
            if level == 2:
                s.wall((ax0, az0), (ax0, az1), y, y + 1.1, thickness=0.08)
                s.wall((ax1, az0), (ax1, az1), y, y + 1.1, thickness=0.08)
    # the atrium's flights: one landing at its east end (climbing east), one at its west end (climbing west)
    _open_flight(s, np.array([ax1 - runs[0], az0 + 0.3 + f0["width"] / 2]), np.array([1.0, 0.0]), f0["width"], 0.0,
                 storey, f0["riser"], f0["going"], f0["thickness"], f0["overlap"])
    _open_flight(s, np.array([ax0 + runs[1], az1 - 0.3 - f1["width"] / 2]), np.array([-1.0, 0.0]), f1["width"], 0.0,
                 storey, f1["riser"], f1["going"], f1["thickness"], f1["overlap"])
    s.wall((ax0, az0), (ax0, az1 - 0.3 - f1["width"] - 0.1), storey, storey + 1.1, thickness=0.08)
    s.wall((ax1, az0 + 0.3 + f0["width"] + 0.1), (ax1, az1), storey, storey + 1.1, thickness=0.08)
    for f, run, well, heading in ((f2, runs[2], wells[0], 1.0), (f3, runs[3], wells[1], -1.0)):
        zc = (well[2] + well[3]) / 2
        foot = np.array([well[1] - run if heading > 0 else well[0] + run, zc])  # its head at the well's edge
        _open_flight(s, foot, np.array([heading, 0.0]), f["width"], storey, 2 * storey, f["riser"], f["going"],
                     f["thickness"], f["overlap"])
        s.wall((well[0], well[2]), (well[1], well[2]), 2 * storey, 2 * storey + 1.1, thickness=0.08)
        s.wall((well[0], well[3]), (well[1], well[3]), 2 * storey, 2 * storey + 1.1, thickness=0.08)
        far = well[0] if heading > 0 else well[1]
        s.wall((far, well[2]), (far, well[3]), 2 * storey, 2 * storey + 1.1, thickness=0.08)
    for _ in range(int(rng.integers(3, 6))):  # planters on the atrium's floor
        x, z = float(rng.uniform(ax0 + 4.0, ax1 - 4.0)), float(rng.uniform(az0 + 3.0, az1 - 3.0))
        s.box(x - 0.5, x + 0.5, 0.0, 0.6, z - 0.5, z + 0.5)
    s.ground(-8.0, sx + 8.0, -4.0, sz + 4.0, 0.0, [(0.0, sx, 0.0, sz)])
    return s.mesh()


def stile_fields_plan(seed: int) -> dict:
    """The plan of :func:`stile_fields` for ``seed``: the fields' column widths and row depths, and per wall between
    two fields (a pair of (column, row) cells) its crossing: ``{"kind": "gate"}``, ``{"kind": "step", "riser": r}``,
    ``{"kind": "squeeze", "ground": w0, "hip": w1}`` or ``{"kind": "none"}``; the lane along the south and the gate
    from it into each field of the first row (or not). O(fields)."""
    rng = np.random.default_rng(seed)
    cols, rows = int(rng.integers(4, 6)), int(rng.integers(3, 5))
    widths = [float(rng.uniform(16.0, 22.0)) for _ in range(cols)]
    depths = [float(rng.uniform(14.0, 18.0)) for _ in range(rows)]
    crossings = {}
    for c in range(cols):
        for r in range(rows):
            for nb in ((c + 1, r), (c, r + 1)):
                if nb[0] >= cols or nb[1] >= rows:
                    continue
                kind = str(rng.choice(["gate", "step", "step", "squeeze", "squeeze", "none"]))
                if kind == "step":
                    crossing = {"kind": kind, "riser": float(rng.uniform(0.3, 0.5))}
                elif kind == "squeeze":
                    crossing = {"kind": kind, "ground": float(rng.uniform(0.25, 0.45)),
                                "hip": float(rng.uniform(0.9, 1.2))}
                else:
                    crossing = {"kind": kind}
                crossings[((c, r), nb)] = crossing
    lane_gates = [c for c in range(cols) if rng.random() < 0.5] or [0]
    return {"widths": widths, "depths": depths, "crossings": crossings, "lane_gates": lane_gates}


def stile_fields_areas(plan: dict, climb: float = AGENT_CLIMB) -> list[set]:
    """The plan's areas for a player with ``climb``: sets of fields (column, row) joined by gates and by step stiles
    whose risers are ``climb`` or under (a squeeze stile is never passed by a body 1 m across), the lane counted as
    the field (-1, -1). O(fields)."""
    parent: dict = {}

    def find(a):
        while parent.setdefault(a, a) != a:
            a = parent[a]
        return a

    for (a, b), crossing in plan["crossings"].items():
        find(a), find(b)
        if crossing["kind"] == "gate" or (crossing["kind"] == "step" and crossing["riser"] <= climb):
            parent[find(a)] = find(b)
    for c in plan["lane_gates"]:
        parent[find((c, 0))] = find((-1, -1))
    groups: dict = {}
    for a in list(parent):
        groups.setdefault(find(a), set()).add(a)
    return list(groups.values())


def _crossing(s: _Solids, crossing: dict, mid: np.ndarray, along_x: bool, height: float, thickness: float) -> None:
    """The crossing ``crossing`` of a wall (its opening 1.6 m wide centred on plan point ``mid``; the wall runs
    along x when ``along_x``), ``height`` m high and ``thickness`` m thick: nothing for a gate, a stone stair up and
    over it for a step stile (three risers a side, its top as deep as the wall), two stone wedges leaving a slot for a
    squeeze stile, the wall itself for none."""
    def box(a0: float, a1: float, y0: float, y1: float, b0: float, b1: float) -> None:
        """A box whose ``a`` runs along the wall and ``b`` across it, about ``mid``."""
        if along_x:
            s.box(mid[0] + a0, mid[0] + a1, y0, y1, mid[1] + b0, mid[1] + b1)
        else:
            s.box(mid[0] + b0, mid[0] + b1, y0, y1, mid[1] + a0, mid[1] + a1)

    t = thickness / 2
    if crossing["kind"] == "none":
        box(-0.8, 0.8, -0.1, height, -t, t)
    elif crossing["kind"] == "step":
        r = crossing["riser"]
        box(-0.8, 0.8, -0.1, 3 * r, -t, t)
        for i, depth in ((1, 0.7), (2, 0.35)):  # two treads a side below the top
            box(-0.8, 0.8, -0.1, i * r, t, t + depth)
            box(-0.8, 0.8, -0.1, i * r, -t - depth, -t)
        box(-0.9, -0.8, -0.1, height, -t, t)
        box(0.8, 0.9, -0.1, height, -t, t)
    elif crossing["kind"] == "squeeze":
        w0, w1 = crossing["ground"], crossing["hip"]
        top = min(w0 + (w1 - w0) * height, 1.5)  # the slot widens linearly (w1 at 1 m up) to the wall's top
        for sign in (-1.0, 1.0):
            pts = []
            for y, w in ((-0.1, w0), (height, top)):
                for b in (-t, t):
                    for a in (sign * w / 2, sign * 0.8):
                        pts.append((a, y, b))
            if along_x:
                s.hull(np.array([[mid[0] + a, y, mid[1] + b] for a, y, b in pts]))
            else:
                s.hull(np.array([[mid[0] + b, y, mid[1] + a] for a, y, b in pts]))


def stile_fields(seed: int) -> trimesh.Trimesh:
    """Pastures (an open world's farmland, a walking simulator's dales) of 4-5 x 3-4 fields 16-22 x 14-18 m
    (``stile_fields_plan(seed)``) between dry-stone walls 1.4 m high and 0.6 m thick, a lane 5 m wide along the
    south with a gate 2 m wide into about half the first row's fields. Each wall between two fields is crossed, at its
    middle, by one of (drawn per wall): a gate 1.6 m wide; a *step stile* (a stone stair 1.6 m wide up and over the
    wall, three *risers of 0.3-0.5 m* a side, drawn per stile); a *squeeze stile* (a slot between two stone wedges
    *0.25-0.45 m wide at the ground and 0.9-1.2 m at 1 m up*, widening on to the wall's top, drawn per stile); or
    nothing. Trees (trunks), boulders and troughs in the fields.

    Expected (written before the first run): a player 1 m across passes a gate, climbs a step stile whose risers are
    0.4 m or less (not one over), and never passes a squeeze stile (narrower than the body below the hip), so the
    fields fall into the plan's groups (``stile_fields_areas``: fields joined by gates and low stiles, with the lane
    where it has a gate): 10 / 7 / 9 areas on seeds 0-2 (9 / 4 / 5 with a climb of 0.425 m: 1 / 3 / 4 stiles of
    0.40-0.425 m). A step stile of risers 0.40-0.425 m may read either way on the navmesh
    (``climb: agent`` climbs 0.4 m and none over 0.425 m). The squeeze stiles' slots are walls on both routes if the
    routes read the agent's body as a whole; a route that tests clearance at a few heights only (a knee ray at 0.5 m
    where the slot is 0.6-0.8 m wide) might join fields through one. Traffic highest through the gates and low stiles
    on the way between the lane and the far fields; each field reached by one crossing a dead end."""
    plan = stile_fields_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    widths, depths = plan["widths"], plan["depths"]
    xs = np.concatenate([[0.0], np.cumsum(widths)]) + 4.0
    zs = np.concatenate([[0.0], np.cumsum(depths)]) + 9.0
    height, thick = 1.4, 0.6
    s = _Solids()
    for ci in range(len(widths)):  # the lane's wall, gated into some fields
        mid = (xs[ci] + xs[ci + 1]) / 2
        gates = [(mid - xs[ci] - 1.0, 2.0)] if ci in plan["lane_gates"] else []
        s.wall((float(xs[ci]), float(zs[0])), (float(xs[ci + 1]), float(zs[0])), -0.1, height, gates, thickness=thick)
    s.wall((float(xs[0]), float(zs[-1])), (float(xs[-1]), float(zs[-1])), -0.1, height, thickness=thick)
    s.wall((float(xs[0]), 4.0), (float(xs[0]), float(zs[-1])), -0.1, height, thickness=thick)
    s.wall((float(xs[-1]), 4.0), (float(xs[-1]), float(zs[-1])), -0.1, height, thickness=thick)
    s.wall((float(xs[0]), 4.0), (float(xs[-1]), 4.0), -0.1, height, thickness=thick)  # the lane's far side
    for ((c, r), (c2, r2)), crossing in plan["crossings"].items():
        if c2 > c:  # a wall along z at xs[c + 1], between rows' z
            x, za, zb = float(xs[c + 1]), float(zs[r]), float(zs[r + 1])
            mid = np.array([x, (za + zb) / 2])
            s.wall((x, za), (x, zb), -0.1, height, [(mid[1] - za - 0.8, 1.6)], thickness=thick)
            _crossing(s, crossing, mid, False, height, thick)
        else:
            z, xa, xb = float(zs[r + 1]), float(xs[c]), float(xs[c + 1])
            mid = np.array([(xa + xb) / 2, z])
            s.wall((xa, z), (xb, z), -0.1, height, [(mid[0] - xa - 0.8, 1.6)], thickness=thick)
            _crossing(s, crossing, mid, True, height, thick)
    for ci in range(len(widths)):
        for ri in range(len(depths)):
            spots: list[tuple[np.ndarray, float]] = []
            keep = [(float(xs[ci]), float(xs[ci + 1]), float(zs[ri]) - 3.0, float(zs[ri]) + 3.0),
                    (float(xs[ci]), float(xs[ci + 1]), float(zs[ri + 1]) - 3.0, float(zs[ri + 1]) + 3.0),
                    (float(xs[ci]) - 3.0, float(xs[ci]) + 3.0, float(zs[ri]), float(zs[ri + 1])),
                    (float(xs[ci + 1]) - 3.0, float(xs[ci + 1]) + 3.0, float(zs[ri]), float(zs[ri + 1]))]
            for _ in range(int(rng.integers(3, 6))):
                p = _placed(rng, spots, float(xs[ci]) + 1.0, float(xs[ci + 1]) - 1.0, float(zs[ri]) + 1.0,
                            float(zs[ri + 1]) - 1.0, 1.2, keep)
                if p is None:
                    continue
                kind = rng.random()
                if kind < 0.4:
                    _trunk(s, p, 0.4, -0.1, 6.0)
                elif kind < 0.8:
                    s.rock(rng, p, 0.5, -0.1, float(rng.uniform(0.8, 1.6)))
                else:
                    s.box(p[0] - 1.0, p[0] + 1.0, -0.1, 0.7, p[1] - 0.35, p[1] + 0.35)
    s.ground(float(xs[0]), float(xs[-1]), 4.0, float(zs[-1]), 0.0, [])  # inside the boundary walls only
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "headstone_yard": headstone_yard, "coaming_deck": coaming_deck, "rubble_nave": rubble_nave,
    "raised_beds": raised_beds, "open_stairs": open_stairs, "stile_fields": stile_fields,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirty-eighth round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
