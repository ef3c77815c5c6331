"""Level kinds of the thirtieth held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each about 400-1,200 navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py`` (imported, not copied): ``aircraft_carrier`` (a flight deck over a hangar joined by two
stair trunks, deck-edge lifts that are floor at one level only, helicopters whose drooping rotor blades hang 1.7-2.6 m
over the deck, about the agent's 2 m), ``submarine`` (three decks of compartments in a line, every bulkhead crossed
through a hatch whose sill, 0.30-0.36 m, stands just under the agent's 0.4 m climb and whose clear height over the sill,
2.05-2.25 m, just over its 2 m height), ``velodrome`` (a banked oval track whose bends stand at 40-44 degrees, just
under the agent's 45-degree limit, reached from outside through a tunnel under it), ``drained_pools`` (a leisure
centre's emptied pools sunk 0.9-4.5 m into the deck, entered only by their steps and a beach ramp, the main pool's floor
breaking down to its deep end at 30-42 degrees), ``mogul_piste`` (a ski slope at 36-41 degrees whose mogul field's lee
faces pass 45 degrees, snow fences across it, chalets on its terraces) and ``marina`` (five pontoons reached down
gangways, each with finger berths 1.2-1.8 m wide, about the 1.5 m the agent's 1 m needs on Recast's cells of 0.25 m,
between moored boats).

Run: ``.venv/bin/python benchmarks/level_kinds30.py OUT_DIR [--kinds velodrome marina] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _car, _gable, _lid, _ridged, _Solids, _stair_tower, _strip, _terrain, _trunk, _well_length
from level_kinds import main as write_kinds

RIDGE = math.tan(math.radians(50.0))
"""Rise per metre of a roof ridged at 50 degrees (over the agent's 45: nothing on it is floor)."""


def _ridged_strip(s: _Solids, a: np.ndarray, b: np.ndarray, width: float, y0: float, y1: float) -> None:
    """A closed body over the strip ``width`` m wide from plan point ``a`` (x, z) to ``b`` (:func:`level_kinds._strip`):
    walls from ``y0`` to ``y1`` and a roof ridged along the strip at 50 degrees, one convex hull (a vehicle's or a
    boat's body at any heading, with no top face for Recast to read as floor)."""
    plan = _strip(a, b, width)
    ridge = y1 + width / 2 * RIDGE
    s.hull(np.array([[p[0], y, p[1]] for p in plan for y in (y0, y1)] + [[p[0], ridge, p[1]] for p in (a, b)]))


def _placed(rng: np.random.Generator, spots: list[tuple[np.ndarray, float]], x0: float, x1: float, z0: float,
            z1: float, radius: float, keep_out: list[tuple[float, float, float, float]]) -> np.ndarray | None:
    """A plan point in [x0, x1] x [z0, z1] whose circle of ``radius`` m meets no circle of ``spots`` (centre, radius;
    appended to) and no rectangle of ``keep_out`` (x0, x1, z0, z1), or None after 60 tries. O(tries x spots)."""
    for _ in range(60):
        p = np.array([float(rng.uniform(x0 + radius, x1 - radius)), float(rng.uniform(z0 + radius, z1 - radius))])
        if all(np.linalg.norm(p - c) > r + radius for c, r in spots) and not any(
                k[0] - radius < p[0] < k[1] + radius and k[2] - radius < p[1] < k[3] + radius for k in keep_out):
            spots.append((p, radius))
            return p
    return None


def _jet(s: _Solids, p: np.ndarray, heading: np.ndarray, y: float) -> None:
    """A carrier jet parked at plan point ``p`` (x, z) facing the unit ``heading``, on a deck at ``y``: a ridged body
    16 m long and 2.2 m wide, its eaves 0.5 m and its ridge 1.8 m up (:func:`_ridged_strip`; the deck inside it, under
    less than the agent's height, is no floor) and its wings folded up, two plates 0.3 m thick and 5 m
    long standing against the body's sides from 1.0 to 4.0 m up (no floor under them: 1 m of head room)."""
    side = np.array([-heading[1], heading[0]])
    _ridged_strip(s, p - heading * 8.0, p + heading * 8.0, 2.2, y - 0.3, y + 0.5)
    for sign in (-1.0, 1.0):
        centre = p + side * sign * 1.25 - heading * 1.5
        s.prism(_strip(centre - heading * 2.5, centre + heading * 2.5, 0.3), y + 1.0, y + 4.0)


def _helicopter(s: _Solids, p: np.ndarray, heading: np.ndarray, y: float, tip: float, spin: float) -> None:
    """A helicopter at plan point ``p`` (x, z) facing the unit ``heading`` on a deck at ``y``: a ridged body 12 m long, 2.4
    m wide, 0.5 m to its eaves (its ridge 1.9 m up: the deck inside it is no floor), a mast to a hub 4.0 m up and four
    blades 0.5 m in chord and 7 m long turned ``spin`` radians, each drooping from the hub to its tip's underside
    ``tip`` m over the deck (under a blade tip under 2 m the agent does not stand; a blade is too narrow to hold floor)."""
    _ridged_strip(s, p - heading * 6.0, p + heading * 6.0, 2.4, y - 0.3, y + 0.5)
    s.box(p[0] - 0.3, p[0] + 0.3, y + 1.0, y + 4.2, p[1] - 0.3, p[1] + 0.3)
    for k in range(4):
        angle = spin + k * math.pi / 2
        out = np.array([math.cos(angle), math.sin(angle)])
        across = np.array([-out[1], out[0]]) * 0.25
        root, end = p + out * 0.3, p + out * 7.3
        s.hull(np.array([[q[0], h + d, q[1]] for q, h in ((root, y + 3.9), (end, y + tip)) for q in (q - across, q + across)
                         for d in (0.0, 0.12)]))


def aircraft_carrier(seed: int) -> trimesh.Trimesh:
    """An aircraft carrier (a naval shooter's or a spy game's ship) 240-260 m long, 36-40 m in beam: a flight deck 8 m over
    the sea (nothing under the ship is floor) with an angled deck sponsoned out to port aft, over a hangar 0.2-0.8 of
    its length under 7.5 m of head room, walled, whose floor is the hangar deck (y = 0). Three deck-edge lifts 14 x 10 m
    outside the hull, each through an opening 14 m wide in the hangar's side wall: two at the flight deck's height, one
    (drawn) lowered to the hangar deck's, so each is floor at one level only (the lifts are not walked up or down); a
    centre-line lift lowered too, leaving a hole 14 x 12 m in the flight deck over the hangar floor, unrailed. The
    island (ridged, 26-30 x 8 m) on the starboard edge between the starboard lifts; two stair trunks
    (:func:`level_kinds._stair_tower`, two storeys of 4 m) inside the hangar along its port wall, doors onto the hangar
    and onto the flight deck (a deckhouse): the only ways between the two decks. Parked on the flight deck 16-20 jets
    (:func:`_jet`, wings folded), 6-8 helicopters (:func:`_helicopter`) whose four blades droop to a tip 1.7-2.6 m over
    the deck, drawn per helicopter (about the agent's 2 m), and 10-14 tow tractors; in the hangar 7-9 jets and 3-4
    helicopters (as many as fit of each, 9 m and 7.6 m clear of each other's middles).
    
    Expected (written before the first run): one area (the two decks joined by the trunks alone); the lowered lifts
    floor of the hangar, the raised ones of the flight deck, the centre-line lift's hole and the hangar's openings onto
    the raised lifts' shafts drops a designer expects the structure never to cross. Floor under a blade whose tip is
    over 2 m, none under the outer part of one under it. Traffic highest on the flight deck's open middle between the
    trunks' deckhouses and along the hangar between its trunk doors, lowest at the bow and stern corners and in the
    lowered lifts; the structure round the parked aircraft, never through a body, a folded wing or the island."""
    rng = np.random.default_rng(seed)
    length, beam, deck = float(rng.uniform(240.0, 260.0)), float(rng.uniform(36.0, 40.0)), 8.0
    h0, h1, z0h, z1h = 0.2 * length, 0.8 * length, 2.0, beam - 2.0  # the hangar
    s = _Solids()
    lifts = [(h0 + 0.15 * (h1 - h0) + float(rng.uniform(0.0, 8.0)), -1.0),  # (x start, side: -1 starboard, 1 port)
             (h0 + 0.62 * (h1 - h0) + float(rng.uniform(0.0, 8.0)), -1.0),
             (0.65 * length, 1.0)]
    lowered = int(rng.integers(0, 3))
    well = _well_length(4.0)
    trunks = [h0 + 25.0 + float(rng.uniform(0.0, 6.0)), h1 - 20.0]
    trunk_z = z1h - well - 0.7
    centre_lift = (h0 + 6.0, h0 + 20.0, beam / 2 - 6.0, beam / 2 + 6.0)
    island_x = lifts[0][0] + 14.0 + float(rng.uniform(4.0, 8.0))
    island = (island_x, island_x + float(rng.uniform(26.0, 30.0)), 0.5, 8.5)
    # the deck stops under the island (Recast would find floor inside it) and the trunks (their own landings)
    holes = [centre_lift, island] + [(x - 0.4, x + 4.4, trunk_z - 0.4, trunk_z + well + 0.4) for x in trunks]
    s.slab(0.0, length, 0.0, beam, deck, holes, thickness=0.5)
    angled = np.array([(0.05 * length, beam), (0.6 * length, beam), (0.5 * length, beam + 12.0), (0.15 * length, beam + 12.0)])
    s.prism(angled, deck - 0.5, deck)
    s.slab(h0, h1, z0h, z1h, 0.0, [], thickness=0.5)  # the hangar deck
    for z, side in ((z0h, -1.0), (z1h, 1.0)):  # the hangar's side walls, open onto each lift on their side
        s.wall((h0, z), (h1, z), 0.0, deck - 0.5, [(x - h0, 14.0) for x, sign in lifts if sign == side], thickness=0.3)
    for x in (h0, h1):
        s.wall((x, z0h), (x, z1h), 0.0, deck - 0.5, thickness=0.3)
    for k, (x, side) in enumerate(lifts):
        top = 0.0 if k == lowered else deck
        inner = (z0h if k == lowered else 0.0) if side < 0 else (z1h if k == lowered else beam)
        outer = -10.0 if side < 0 else beam + 10.0
        s.box(x, x + 14.0, top - 0.5, top, *sorted((inner, outer)))
    for x in trunks:
        _stair_tower(s, x, trunk_z, 0.0, 2, (0, 2), 4.0)
    _ridged(s, *island, deck - 0.5, deck + 12.0)
    keep_deck = [island, centre_lift] + [(x - 0.4, x + 4.4, trunk_z - 0.4, trunk_z + well + 0.4) for x in trunks]
    keep_deck += [(x, x + 14.0, -10.0, 0.0) if side < 0 else (x, x + 14.0, beam, beam + 10.0) for x, side in lifts]
    keep_deck += [(x - 1.0, x + 5.4, trunk_z - 6.0, trunk_z) for x in trunks]  # room before the deckhouses' doors

    def park(spots: list[tuple[np.ndarray, float]], x0: float, x1: float, z0: float, z1: float, y: float,
             jets: int, helicopters: int, keep_out: list[tuple[float, float, float, float]]) -> None:
        """``jets`` jets and ``helicopters`` helicopters parked in [x0, x1] x [z0, z1] on a deck at ``y``."""
        for kind in ["jet"] * jets + ["helicopter"] * helicopters:
            p = _placed(rng, spots, x0, x1, z0, z1, 9.0 if kind == "jet" else 7.6, keep_out)
            angle = float(rng.uniform(0.0, 2 * math.pi))
            heading = np.array([math.cos(angle), math.sin(angle)])
            if p is not None and kind == "jet":
                _jet(s, p, heading, y)
            elif p is not None:
                _helicopter(s, p, heading, y, float(rng.uniform(1.7, 2.6)), float(rng.uniform(0.0, math.pi / 2)))

    spots: list[tuple[np.ndarray, float]] = []
    park(spots, 2.0, length - 2.0, 1.0, beam - 1.0, deck, int(rng.integers(16, 21)), int(rng.integers(6, 9)), keep_deck)
    for _ in range(int(rng.integers(10, 15))):  # tow tractors (:func:`level_kinds._car`) between the aircraft
        p = _placed(rng, spots, 2.0, length - 2.0, 1.0, beam - 1.0, 2.5, keep_deck)
        if p is not None:
            _car(s, p[0] - 1.5, p[0] + 1.5, p[1] - 1.0, p[1] + 1.0, deck)
    keep_hangar = [(x, x + 14.0, z0h - 1.0, z0h + 4.0) if side < 0 else (x, x + 14.0, z1h - 4.0, z1h + 1.0) for x, side in lifts]
    keep_hangar += [(x - 1.0, x + 5.4, trunk_z - 6.0, z1h) for x in trunks]
    park([], h0 + 1.0, h1 - 1.0, z0h + 1.0, z1h - 1.0, 0.0, int(rng.integers(7, 10)), int(rng.integers(3, 5)), keep_hangar)
    return s.mesh()


def submarine(seed: int) -> trimesh.Trimesh:
    """A missile submarine's pressure hull (a submarine level) 120-140 m long along x, three decks inside it 2.9 m apart,
    each under 2.6 m of head room: the lower deck (y = 0) 5.6-6.4 m wide, the middle (2.9) 8.4 m, the upper (5.8) 7.6 m
    (a closed lid over it, :func:`level_kinds._lid`), the hull's sides vertical walls at each deck's width. Bulkheads
    0.4 m thick cut it into 8-9 compartments 11-17 m long (the missile compartment 22-26 m); each bulkhead is crossed on
    each deck by one hatch 1.6 m wide (a real one is nearer 0.8 m, but the agent is 1 m wide) on the deck's centre line:
    *a sill 0.30-0.36 m high* (just under the agent's 0.4 m climb) 0.5 m deep, and over it *a clear height of 2.15-2.30
    m* (0.15-0.3 m over the agent's 2 m) under a lintel, both drawn per hatch. On each deck a passage 1.8-2.0 m wide
    along the centre line: on the lower deck machinery, racks and tanks (blocks 0.8-1.2 m deep, 1-2.2 m high) along both
    hull sides, on the decks above cabins and offices (3-4.5 m wide, doors 1.6 m, a bunk or desk each) along both sides,
    but in the control room and the mess (open, consoles or tables). The missile compartment holds two rows of 6-8 tubes
    (octagons 1.1 m in radius through every deck, stopping 1 m under the lid) either side of the passage, closed blocks
    1.6 m high between them and the hull on every deck (the tubes' access, no floor). Four steep flights (10 steps of
    0.29 / 0.30 m, about 44 degrees, 1.6 m wide, walled from the passage, railed round their hole) join the decks: lower
    to middle in the control room and the engine room, middle to upper in the mess and the torpedo room.
    
    Expected (written before the first run): one area (every hatch's sill climbed and its clear height over the agent's;
    docs/navmesh.md, "Head room a little over the agent's height", walks every doorway from 2.15 m on this grid, and a
    draft's hatches of 2.05-2.25 m closed where its rule says, so the clear height is drawn from 2.15 m; a sill over
    0.375 m, Recast's three cells of climb, would close a hatch too, which none is drawn to be). Traffic highest along
    the decks' centre lines through the hatches and at the flights, lowest in the cabins and at the bow and stern ends;
    the structure through each hatch, never through a bulkhead or a tube."""
    rng = np.random.default_rng(seed)
    length = float(rng.uniform(120.0, 140.0))
    decks = [(0.0, float(rng.uniform(2.8, 3.2))), (2.9, 4.2), (5.8, 3.8)]  # (floor, half width)
    head = 2.6
    count = int(rng.integers(8, 10))
    parts = rng.uniform(11.0, 17.0, count)
    missile = int(rng.integers(3, count - 3))
    parts[missile] = float(rng.uniform(22.0, 26.0))
    cuts = np.concatenate([[0.0], np.cumsum(parts / parts.sum() * length)])
    kinds = ["torpedo"] + ["berthing"] * (count - 2) + ["engine"]
    kinds[missile] = "missile"
    kinds[1], kinds[count - 2] = "control", "mess"
    flights = {0: (1, count - 1), 1: (count - 2, 0)}  # deck -> the compartments of its flights up to the next deck
    passage = float(rng.uniform(0.9, 1.0))  # the passages' half width
    s = _Solids()
    holes: dict[int, list[tuple[float, float, float, float]]] = {1: [], 2: []}
    for level, ks in flights.items():  # each flight along +x against the hull, walled from the passage
        y, half = decks[level]
        for k in ks:
            x = float(cuts[k] + 3.0)
            z0, z1 = min(half, decks[level + 1][1]) - 1.75, min(half, decks[level + 1][1]) - 0.15
            s.stairs(np.array([x, (z0 + z1) / 2]), np.array([1.0, 0.0]), z1 - z0, y, 2.9, 0.29, 0.30)
            s.wall((x - 1.0, z0 - 0.05), (x + 3.0, z0 - 0.05), y, y + head, thickness=0.1)
            holes[level + 1].append((x - 1.0, x + 3.0, z0, z1))  # open over the foot too: head room up the flight
            top = decks[level + 1][0]
            for z in (z0 - 0.05, z1 + 0.05):  # rails round the hole on the deck above
                s.wall((x - 1.0, z), (x + 3.0, z), top, top + 1.0, thickness=0.1)
            s.wall((x - 1.05, z0 - 0.1), (x - 1.05, z1 + 0.1), top, top + 1.0, thickness=0.1)
    for level, (y, half) in enumerate(decks):
        s.slab(0.0, length, -half, half, y, holes.get(level, []), thickness=0.3)
        top = y + head
        for z in (-half, half):
            s.wall((0.0, z), (length, z), y, top, thickness=0.3)
        for k, x in enumerate(cuts):
            if k in (0, count):
                s.wall((float(x), -half), (float(x), half), y, top, thickness=0.4)
                continue
            sill, clear = float(rng.uniform(0.30, 0.36)), float(rng.uniform(2.15, 2.3))
            s.wall((float(x), -half), (float(x), half), y, top, [(half - 0.8, 1.6)], thickness=0.4)
            s.box(float(x) - 0.25, float(x) + 0.25, y - 0.3, y + sill, -0.8, 0.8)
            s.box(float(x) - 0.2, float(x) + 0.2, y + sill + clear, top, -0.8, 0.8)
    lid = decks[-1][0] + head
    _lid(s, -1.0, length + 1.0, -5.2, 5.2, lid)
    for k in range(count):
        x0, x1 = float(cuts[k]) + 0.2, float(cuts[k + 1]) - 0.2
        if kinds[k] == "missile":
            pitch = (x1 - x0 - 3.0) / int(rng.integers(6, 9))
            for x in np.arange(x0 + 1.5 + pitch / 2, x1 - 1.5, pitch):
                for z in (-2.1, 2.1):
                    ring = [(float(x) + 1.1 * math.cos(t), z + 1.1 * math.sin(t)) for t in np.arange(8) * math.pi / 4 + math.pi / 8]
                    s.prism(np.array(ring), -0.3, lid - 1.0)
            for y, half in decks:
                for side in (-1.0, 1.0):
                    s.box(x0, x1, y, y + 1.6, *sorted((side * 2.1, side * half)))
            continue
        for level, (y, half) in enumerate(decks):
            leaving = k in flights.get(level, ())  # a flight's foot on this deck's +z side
            arriving = k in flights.get(level - 1, ())  # a flight's head on this deck's +z side
            if level == 0:  # machinery along the hull's sides, gaps between blocks
                for side in (-1.0, 1.0):
                    x = x0 + float(rng.uniform(0.5, 1.5))
                    while x < x1 - 2.0 and not (side > 0 and leaving):
                        long, depth = float(rng.uniform(1.5, 4.0)), float(rng.uniform(0.8, 1.2))
                        s.box(x, min(x + long, x1), y, y + float(rng.uniform(1.0, 2.2)), *sorted((side * half, side * (half - depth))))
                        x += long + float(rng.uniform(1.0, 2.5))
            elif kinds[k] in ("control", "mess"):  # consoles or tables, clear of the passage and of a flight's ends
                for x in np.arange(x0 + 7.5 if leaving or arriving else x0 + 1.5, x1 - 2.0, 3.2):
                    for side in (-1.0, 1.0):
                        z = side * (passage + 1.2)
                        s.box(float(x), float(x) + 1.6, y, y + (1.2 if kinds[k] == "control" else 0.75), *sorted((z, z + side * 0.9)))
            else:  # cabins along both sides of the passage
                for side in (-1.0, 1.0):
                    if side > 0 and (leaving or arriving):
                        continue
                    doors, edges = [], np.linspace(x0, x1, max(2, round((x1 - x0) / float(rng.uniform(3.0, 4.5)))) + 1)
                    line = side * (passage + 0.05)
                    for c0, c1 in zip(edges[:-1], edges[1:]):
                        doors.append((float(c0 - x0 + (c1 - c0 - 1.6) / 2), 1.6))
                        s.box(float(c0) + 0.2, float(c1) - 0.2, y, y + 0.6, *sorted((side * (half - 0.9), side * half)))
                    for c in edges[1:-1]:
                        s.wall((float(c), line), (float(c), side * half), y, y + head, thickness=0.1)
                    s.wall((x0, line), (x1, line), y, y + head, doors, thickness=0.1)
    return s.mesh()


def velodrome(seed: int) -> trimesh.Trimesh:
    """A velodrome (a cycling or racing game's track): a banked oval of two straights 36-44 m long joined by two bends of
    20-24 m radius at the track's inner edge, the track 7-8 m wide, its surface a ruled sheet rising from the inner edge
    (y = 0, a flat apron 1 m wide inside it) to the outer one at the banking of each point: 10-13 degrees on the
    straights and *40-44 degrees in the bends* (drawn per bend, just under the agent's 45-degree limit), each change
    eased over 20 m of the inner edge; a wall 0.3 m thick stands round the outer edge to 1.1 m over it. The infield
    (ground at 0, team cabins, benches) lies inside the inner edge, the grounds (ground at 0, trees, parked cars, a car
    park of rows of cars in the north-east corner, a fence 2 m high round them) outside the wall; the only way between
    them is a tunnel 3 m wide under the south straight, its floor 3 m down, reached by a flight of 20 steps (0.15 / 0.30
    m) at each end.
    
    Expected (written before the first run): one area (the tunnel the way between the infield and the grounds; the track
    joined to the infield along the whole apron). The whole track walked, bends included (each under 45 degrees), up to
    its outer wall; no floor on the wall, under the track or on a cabin. Traffic highest through the tunnel and on the
    infield's and the grounds' ways to it, lowest on the bends' upper banking; a designer expects the structure through
    the tunnel, never through the track's sheet or over the outer wall."""
    rng = np.random.default_rng(seed)
    straight, radius, width = float(rng.uniform(36.0, 44.0)), float(rng.uniform(20.0, 24.0)), float(rng.uniform(7.0, 8.0))
    banks = [math.tan(math.radians(float(rng.uniform(40.0, 44.0)))) for _ in range(2)]
    flat = math.tan(math.radians(float(rng.uniform(10.0, 13.0))))
    half = straight / 2
    bend_len = math.pi * radius
    total = 2 * straight + 2 * bend_len
    u = np.linspace(0.0, total, int(total / 0.8) + 1)[:-1]  # arc length along the inner edge from the south straight's west end

    def edge(t: float) -> tuple[np.ndarray, np.ndarray, float, float]:
        """The inner edge's plan point, its outward unit normal, the arc length into the nearest bend (negative on a
        straight) and that bend's banking (tan) at arc length ``t``."""
        if t < straight:
            return np.array([-half + t, -radius]), np.array([0.0, -1.0]), -min(t, straight - t), banks[0]
        t -= straight
        if t < bend_len:
            a = -math.pi / 2 + t / radius
            return (np.array([half + radius * math.cos(a), radius * math.sin(a)]), np.array([math.cos(a), math.sin(a)]),
                    min(t, bend_len - t), banks[0])
        t -= bend_len
        if t < straight:
            return np.array([half - t, radius]), np.array([0.0, 1.0]), -min(t, straight - t), banks[1]
        t -= straight
        a = math.pi / 2 + t / radius
        return (np.array([-half + radius * math.cos(a), radius * math.sin(a)]), np.array([math.cos(a), math.sin(a)]),
                min(t, bend_len - t), banks[1])

    rows = []
    for t in u:
        p, normal, into, bank = edge(float(t))
        ease = float(np.clip((into + 10.0) / 20.0, 0.0, 1.0))
        tan = flat + (bank - flat) * ease * ease * (3 - 2 * ease)
        rows.append([(p - normal, 0.0), (p, 0.0), (p + normal * width, width * tan)])
    n = len(rows)
    vertices = np.array([[q[0], y, q[1]] for row in rows for q, y in row])
    faces = []
    for i in range(n):
        j = (i + 1) % n
        for c in range(2):
            a, b, c2, d = 3 * i + c, 3 * j + c, 3 * j + c + 1, 3 * i + c + 1
            faces += [[a, d, c2], [a, c2, b]]
    sheet = trimesh.Trimesh(vertices, np.array(faces), process=False)
    if sheet.face_normals[:, 1].mean() < 0:
        sheet.invert()
    skirt = sheet.copy()
    skirt.vertices[:, 1] -= 0.5
    skirt.invert()
    s = _Solids()
    s.parts += [sheet, skirt]
    for i in range(n):  # the outer wall, a prism a piece
        (p, _), (q, _) = rows[i][2], rows[(i + 1) % n][2]
        _, normal_p, _, _ = edge(float(u[i]))
        y = max(rows[i][2][1], rows[(i + 1) % n][2][1])
        out = normal_p * 0.3
        s.hull(np.array([[r[0], h, r[1]] for r in (p, q, p + out, q + out) for h in (-0.5, y + 1.1)]))
    tunnel_x = float(rng.uniform(-half / 2, half / 2))
    inner_end, outer_end = -(radius - 1.5), -(radius + width + 1.0)
    s.box(tunnel_x - 1.5, tunnel_x + 1.5, -3.3, -3.0, outer_end, inner_end)
    s.stairs(np.array([tunnel_x, inner_end]), np.array([0.0, 1.0]), 3.0, -3.0, 3.0)
    s.stairs(np.array([tunnel_x, outer_end]), np.array([0.0, -1.0]), 3.0, -3.0, 3.0)
    for z0, z1 in ((inner_end + 6.0, inner_end + 7.5), (outer_end - 7.5, outer_end - 6.0)):  # landings over the slot's edge
        s.box(tunnel_x - 1.5, tunnel_x + 1.5, -0.3, 0.0, z0, z1)
    for x in (tunnel_x - 1.65, tunnel_x + 1.65):
        s.wall((x, outer_end), (x, inner_end), -3.3, -0.6, thickness=0.3)
        s.wall((x, inner_end), (x, inner_end + 6.0), -3.3, 1.0, thickness=0.3)
        s.wall((x, outer_end - 6.0), (x, outer_end), -3.3, 1.0, thickness=0.3)
    reach = half + radius + width + 30.0
    xs, zs = np.arange(-reach, reach + 0.5, 1.0), np.arange(-(radius + width + 30.0), radius + width + 30.5, 1.0)
    cx, cz = np.meshgrid((xs[:-1] + xs[1:]) / 2, (zs[:-1] + zs[1:]) / 2, indexing="ij")
    apart = np.hypot(np.maximum(np.abs(cx) - half, 0.0), cz) - radius  # signed distance from the inner edge (plan)
    slot = (np.abs(cx - tunnel_x) < 2.0) & (cz > outer_end - 6.5) & (cz < inner_end + 6.5)
    cabins = [(-half + k * straight / 5.5, radius - 9.0) for k in range(int(rng.integers(4, 7)))]
    under = np.zeros_like(slot)
    for x, z in cabins:  # the ground stops under the cabins (Recast would find floor inside them)
        under |= (cx > x - 0.5) & (cx < x + 5.5) & (cz > z - 0.5) & (cz < z + 4.5)
    keep = ((apart < -0.5) | (apart > width + 0.8)) & ~slot & ~under
    _terrain(s, xs, zs, np.zeros((len(xs), len(zs))), keep)
    s.wall((-reach + 1.0, -(radius + width + 29.0)), (reach - 1.0, -(radius + width + 29.0)), 0.0, 2.0)
    s.wall((-reach + 1.0, radius + width + 29.0), (reach - 1.0, radius + width + 29.0), 0.0, 2.0)
    for x in (-reach + 1.0, reach - 1.0):
        s.wall((x, -(radius + width + 29.0)), (x, radius + width + 29.0), 0.0, 2.0)
    for x, z in cabins:  # team cabins along the infield's north side, benches along its south
        _ridged(s, x - 0.5, x + 5.5, z - 0.5, z + 4.5, -0.3, 2.6)
        s.box(x + 0.5, x + 3.0, 0.0, 0.45, -radius + 9.0, -radius + 9.5)
    spots: list[tuple[np.ndarray, float]] = []
    park_x = reach - 40.0  # a car park in the grounds' north-east corner: rows of cars along x, aisles 6 m wide
    for z in np.arange(radius + width + 6.0, radius + width + 27.0, 7.0):
        for x in np.arange(park_x, reach - 4.0, 2.6):
            if rng.random() < 0.75:
                _car(s, float(x), float(x) + 1.8, float(z), float(z) + 4.2, 0.0)
    spots.append((np.array([reach - 22.0, radius + width + 17.0]), 24.0))
    for _ in range(int(rng.integers(30, 41))):  # trees and cars in the grounds, clear of the track, its wall and the tunnel
        p = _placed(rng, spots, -reach + 2.0, reach - 2.0, -(radius + width + 28.0), radius + width + 28.0, 2.5,
                    [(tunnel_x - 2.0, tunnel_x + 2.0, outer_end - 8.0, inner_end)])
        if p is None or math.hypot(max(abs(p[0]) - half, 0.0), p[1]) < radius + width + 4.0:
            continue
        if rng.random() < 0.5:
            _trunk(s, p, 0.3, -0.5, 6.0)
        else:
            _car(s, p[0] - 2.1, p[0] + 2.1, p[1] - 0.9, p[1] + 0.9, 0.0)
    return s.mesh()


def drained_pools(seed: int) -> trimesh.Trimesh:
    """A leisure centre's pool hall with its pools drained (a liminal or a horror level) 64-70 x 40-44 m, walls 0.3 m
    thick to a ceiling 7 m up (:func:`level_kinds._lid`), the pool deck a slab at y = 0 over nothing (no floor under
    it) with the pools sunk into it, each walled, floored, entered only by its own way: the main pool (25 x 12-15 m)
    whose floor falls from 1.0 m down at its shallow end to 1.4 m over 11-13 m, then *breaks at 30-42 degrees* (drawn)
    down to a flat deep end 3.6 m down, entered by a flight of 5 steps (0.2 / 0.3 m, 1.6 m wide) in a shallow corner;
    a diving pool (9-10 m square, 4.5 m deep) entered by a flight of 15 steps (0.3 m, 1.6 m wide) along one wall; a
    learner pool (12-14 x 8-9 m, 0.9 m deep) with steps of 0.18 m across its whole width at one end; a leisure pool
    (16-18 x 10-12 m, 1.2 m deep) entered down a beach ramp at 7-9 degrees across its width, a rock island in it
    (ridged); a spa (5 m square, 0.9 m deep, a bench 0.45 m high round three sides, three steps of 0.3 m). A gallery
    3 m up along the north wall (4 m deep, railed, one flight up); changing rooms across the west end (a corridor and
    locker rows 2 m high with aisles 1.6-2.0 m) through two doorways 2 m wide; a diving platform 3 m up over the diving
    pool's north wall (a drop into it, one way), up a flight of its own; columns (0.6 m) down the deck between the
    rows of pools; rows of loungers (ridged, 0.3 m up) on the deck east of the pools; 3-6 heaps of rubble (0.5-1.2 m
    high) on each pool's floor but the spa's.

    Expected (written before the first run): one area (each pool reached down its steps or ramp; a pool whose way in
    closed would be an area apart); every pool's floor walked, the main pool's break too (under 45 degrees); the walls
    round the pools drops of 0.9-4.5 m a designer expects the structure never to cross but at the steps. Traffic
    highest on the deck between the changing rooms and the pools' ways in, lowest in the diving pool and the spa; the
    structure down each pool's steps, never straight over a pool's wall."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(64.0, 70.0)), float(rng.uniform(40.0, 44.0))
    west = 9.0  # the changing rooms' depth along x
    s = _Solids()
    main_w = float(rng.uniform(12.0, 15.0))
    main = (west + 4.0, west + 29.0, 3.0, 3.0 + main_w)
    dive_side = float(rng.uniform(9.0, 10.0))
    dive = (main[1] + 4.0, main[1] + 4.0 + dive_side, 4.0, 4.0 + dive_side)
    leisure = (west + 4.0, west + 4.0 + float(rng.uniform(16.0, 18.0)), size_z - 18.0,
               size_z - 18.0 + float(rng.uniform(10.0, 12.0)))
    learner = (leisure[1] + 4.0, leisure[1] + 4.0 + float(rng.uniform(12.0, 14.0)), size_z - 17.0,
               size_z - 17.0 + float(rng.uniform(8.0, 9.0)))
    spa = (learner[1] + 4.0, learner[1] + 9.0, size_z - 15.0, size_z - 10.0)
    pools = [main, dive, leisure, learner, spa]
    s.slab(0.0, size_x, 0.0, size_z, 0.0, pools, thickness=0.3)
    for x0, x1, z0, z1 in pools:  # each pool's walls round its hole, down to under its deepest floor
        for z in (z0 - 0.15, z1 + 0.15):
            s.box(x0 - 0.3, x1 + 0.3, -5.0, 0.0, z - 0.15, z + 0.15)
        for x in (x0 - 0.15, x1 + 0.15):
            s.box(x - 0.15, x + 0.15, -5.0, 0.0, z0, z1)
    # the main pool: shallow slope, the break, the deep end
    shallow = float(rng.uniform(11.0, 13.0))
    drop = 3.6 - 1.4
    break_run = drop / math.tan(math.radians(float(rng.uniform(30.0, 42.0))))
    x0, x1, z0, z1 = main
    mid = (z0 + z1) / 2
    s.ramp(np.array([x0, mid]), np.array([x0 + shallow, mid]), z1 - z0, -1.0, -1.4)
    s.ramp(np.array([x0 + shallow, mid]), np.array([x0 + shallow + break_run, mid]), z1 - z0, -1.4, -3.6)
    s.box(x0 + shallow + break_run, x1, -3.9, -3.6, z0, z1)
    s.stairs(np.array([x0 + 1.5, z0 + 0.8]), np.array([-1.0, 0.0]), 1.6, -1.0, 1.0, 0.2, 0.3)
    x0, x1, z0, z1 = dive  # the diving pool: its flight along its south wall, rising toward its west wall
    s.box(x0, x1, -4.8, -4.5, z0, z1)
    s.stairs(np.array([x0 + 4.5, z0 + 0.8]), np.array([-1.0, 0.0]), 1.6, -4.5, 4.5, 0.3, 0.3)
    x0, x1, z0, z1 = learner  # the learner pool: steps across its east end
    s.box(x0, x1, -1.2, -0.9, z0, z1)
    s.stairs(np.array([x1 - 1.5, (z0 + z1) / 2]), np.array([1.0, 0.0]), z1 - z0, -0.9, 0.9, 0.18, 0.3)
    x0, x1, z0, z1 = leisure  # the leisure pool: a beach ramp from its west end, a rock island
    run = 1.2 / math.tan(math.radians(float(rng.uniform(7.0, 9.0))))
    s.ramp(np.array([x0, (z0 + z1) / 2]), np.array([x0 + run, (z0 + z1) / 2]), z1 - z0, 0.0, -1.2)
    s.box(x0 + run, x1, -1.5, -1.2, z0, z1)
    _ridged(s, x1 - 5.0, x1 - 2.5, z0 + 3.5, z0 + 6.0, -1.5, 0.5)
    x0, x1, z0, z1 = spa  # the spa: a bench round three sides, steps from the fourth
    s.box(x0, x1, -1.2, -0.9, z0, z1)
    for a, b, c, d in ((x0, x1, z1 - 0.5, z1), (x0, x0 + 0.5, z0, z1), (x1 - 0.5, x1, z0, z1)):
        s.box(a, b, -0.9, -0.45, c, d)
    s.stairs(np.array([(x0 + x1) / 2, z0 + 0.9]), np.array([0.0, -1.0]), 1.6, -0.9, 0.9, 0.3, 0.3)
    # the hall's walls, ceiling, gallery and changing rooms
    _lid(s, -0.3, size_x + 0.3, -0.3, size_z + 0.3, 7.0)
    for z in (0.0, size_z):
        s.wall((0.0, z), (size_x, z), -0.3, 6.0, thickness=0.3)
    for x in (0.0, size_x):
        s.wall((x, 0.0), (x, size_z), -0.3, 6.0, thickness=0.3)
    gallery_x0 = spa[0] - 14.0
    s.slab(gallery_x0, size_x, size_z - 4.0, size_z, 3.0, [], thickness=0.3)
    s.wall((gallery_x0, size_z - 4.0), (size_x, size_z - 4.0), 3.0, 4.1, thickness=0.1)
    s.wall((gallery_x0, size_z - 4.0), (gallery_x0, size_z), 3.0, 4.1, [(1.45, 2.4)], thickness=0.1)
    s.stairs(np.array([gallery_x0 - 6.0, size_z - 1.35]), np.array([1.0, 0.0]), 2.4, 0.0, 3.0, 0.15, 0.3)
    door_z = [float(rng.uniform(4.0, size_z / 2 - 4.0)), float(rng.uniform(size_z / 2 + 2.0, size_z - 6.0))]
    s.wall((west, 0.0), (west, size_z), 0.0, 6.0, [(z, 2.0) for z in door_z], thickness=0.3)
    s.wall((3.0, 0.0), (3.0, size_z), 0.0, 2.8, [(size_z / 2 - 1.0, 2.0)], thickness=0.2)  # the corridor's wall
    for z in np.arange(2.0, size_z - 2.0, float(rng.uniform(2.4, 2.8))):  # locker rows along x between the doorways' ways
        if all(abs(z - d - 1.0) > 2.5 for d in door_z) and abs(z - size_z / 2) > 2.5:
            s.box(3.9, west - 1.9, 0.0, 2.0, float(z), float(z) + 0.5)
    x0, x1, z0, z1 = dive  # the diving platform, 3 m up, over the diving pool's north wall, and its flight from the north
    px = x0 + float(rng.uniform(2.0, x1 - x0 - 4.5))
    s.box(px, px + 2.4, 2.7, 3.0, z1 - 1.5, z1 + 1.5)
    s.stairs(np.array([px + 1.2, z1 + 7.5]), np.array([0.0, -1.0]), 2.4, 0.0, 3.0, 0.15, 0.3)
    for x in (px - 0.05, px + 2.45):
        s.wall((x, z1 - 1.5), (x, z1 + 7.5), 3.0, 4.0, thickness=0.1)
    middle = (main[3] + leisure[2]) / 2  # columns down the deck between the two rows of pools
    for x in np.arange(west + 3.0, size_x - 2.0, 6.0):
        if all(not (p[0] - 1.0 < x < p[1] + 1.0 and p[2] - 1.0 < middle < p[3] + 1.0) for p in pools):
            s.box(float(x) - 0.3, float(x) + 0.3, 0.0, 6.0, middle - 0.3, middle + 0.3)
    for x in np.arange(max(dive[1], spa[1]) + 3.0, size_x - 2.5, 2.2):  # loungers at the east end, rows along z
        for z in np.arange(3.0, size_z - 6.0, 3.2):
            _ridged_strip(s, np.array([float(x), float(z)]), np.array([float(x), float(z) + 2.0]), 0.7, -0.3, 0.3)
    floors = {main: -1.0, dive: -4.5, leisure: -1.2, learner: -0.9}  # each pool's floor (the main pool's shallowest)
    for (x0, x1, z0, z1), y in floors.items():  # debris on the pools' floors: fallen tiles and rubble, 0.5-1.2 m high
        for _ in range(int(rng.integers(3, 7))):
            p = np.array([float(rng.uniform(x0 + 1.5, x1 - 1.5)), float(rng.uniform(z0 + 2.5, z1 - 1.5))])
            floor = y if (x0, x1, z0, z1) != main else (-1.0 if p[0] < x0 + shallow else -3.6)
            s.rock(rng, p, 0.4, floor - 2.5, floor + float(rng.uniform(0.5, 1.2)))
    return s.mesh()


def mogul_piste(seed: int) -> trimesh.Trimesh:
    """A ski slope (a winter sports or an open-world game's mountain) on a 1 m grid (:func:`level_kinds._terrain`)
    100-110 m wide along x, rising along +z: a base terrace 30 m deep (flat) with 5-7 chalets (ridged, 8-10 x 6-8 m),
    then two pitches of the piste 45-55 m long at one slope drawn per level from *36-41 degrees* (under the agent's
    45), a mid-station terrace 18-22 m deep between them (a restaurant, ridged) and a top terrace 20 m deep (the lift
    station, ridged). The middle third of both pitches is a *mogul field*: bumps 0.3-0.5 m high in a diagonal pattern
    3.8-4.6 m apart, so on the slope their lee faces pass 45 degrees and their crests and stoss faces do not. Snow
    fences (1.2 m high, 0.1 m thick, 8-14 m long, 3-5 a pitch) across the groomed slope east of the field; lift
    pylons (0.3 m posts) up the east edge, trees along the west edge.

    Expected (written before the first run): one area (the groomed slope under 45 degrees walked from terrace to
    terrace, round the fences); in the mogul field floor in patches (the lee faces over the limit holed), which a
    designer would read as walked across where the patches join and round it where they do not. Traffic highest on the
    groomed slope's straight line between the terraces and through the fences' gaps, lowest in the mogul field's
    middle and the terraces' corners; the structure never straight up a lee face over 45 degrees or through a fence."""
    rng = np.random.default_rng(seed)
    size_x = float(rng.uniform(100.0, 110.0))
    slope = math.tan(math.radians(float(rng.uniform(36.0, 41.0))))
    pitches = [float(rng.uniform(45.0, 55.0)) for _ in range(2)]
    mid_depth = float(rng.uniform(18.0, 22.0))
    bounds = np.cumsum([0.0, 30.0, pitches[0], mid_depth, pitches[1], 20.0])
    xs, zs = np.arange(0.0, size_x + 0.5, 1.0), np.arange(0.0, float(bounds[-1]) + 0.5, 1.0)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    rise = np.clip(gz - bounds[1], 0.0, pitches[0]) + np.clip(gz - bounds[3], 0.0, pitches[1])
    heights = rise * slope
    on_pitch = ((gz > bounds[1] + 2.0) & (gz < bounds[2] - 2.0)) | ((gz > bounds[3] + 2.0) & (gz < bounds[4] - 2.0))
    field = on_pitch & (gx > size_x / 3) & (gx < 2 * size_x / 3)
    spacing, bump = float(rng.uniform(3.8, 4.6)), float(rng.uniform(0.3, 0.5))
    moguls = bump * np.maximum(np.sin(2 * math.pi * (gx + gz) / spacing / 1.414)
                               * np.sin(2 * math.pi * (gx - gz) / spacing / 1.414), 0.0)
    heights = heights + np.where(field, moguls, 0.0)
    s = _Solids()

    def ground_at(x: float, z: float) -> float:
        """The ground's height (m) at the grid point nearest plan point (x, z)."""
        return float(heights[int(round(min(max(x, 0.0), size_x))), int(round(min(max(z, 0.0), float(bounds[-1]))))])

    x, buildings = 6.0, []
    for _ in range(int(rng.integers(5, 8))):  # chalets on the base terrace
        w, d = float(rng.uniform(8.0, 10.0)), float(rng.uniform(6.0, 8.0))
        if x + w > size_x - 6.0:
            break
        z = float(rng.uniform(4.0, 26.0 - d))
        buildings.append(_ridged(s, x, x + w, z, z + d, -0.5, 3.0))
        x += w + float(rng.uniform(4.0, 7.0))
    mid_y = ground_at(size_x / 2, float(bounds[2]) + 1.0)
    buildings.append(_ridged(s, size_x / 2 - 10.0, size_x / 2 + 6.0, float(bounds[2]) + 6.0, float(bounds[3]) - 4.0,
                             mid_y - 0.5, mid_y + 4.0))
    top_y = ground_at(size_x / 2, float(bounds[-1]))
    buildings.append(_ridged(s, size_x - 24.0, size_x - 10.0, float(bounds[4]) + 6.0, float(bounds[5]) - 2.0, top_y - 0.5,
                             top_y + 4.0))
    cx, cz = gx[:-1, :-1] + 0.5, gz[:-1, :-1] + 0.5
    under = np.zeros(cx.shape, dtype=bool)
    for x0, x1, z0, z1 in buildings:  # the ground stops under the buildings (Recast would find floor inside them)
        under |= (cx > x0 - 0.5) & (cx < x1 + 0.5) & (cz > z0 - 0.5) & (cz < z1 + 0.5)
    _terrain(s, xs, zs, heights, ~under)
    for p in range(2):  # snow fences across the groomed slope east of the field, each on the slope at its middle
        for _ in range(int(rng.integers(3, 6))):
            x = float(rng.uniform(2 * size_x / 3 + 2.0, size_x - 20.0))
            z = float(rng.uniform(bounds[2 * p + 1] + 8.0, bounds[2 * p + 2] - 8.0))
            long = float(rng.uniform(8.0, 14.0))
            y = ground_at(x + long / 2, z)
            s.box(x, x + long, y - 1.0, y + 1.2, z - 0.05, z + 0.05)
    for z in np.arange(bounds[1] + 6.0, bounds[4], 18.0):  # lift pylons up the east edge
        p = np.array([size_x - 3.0, float(z)])
        _trunk(s, p, 0.3, ground_at(*p) - 1.0, ground_at(*p) + 8.0)
    for z in np.arange(bounds[1] + 3.0, bounds[4], 5.0):  # trees along the west edge
        p = np.array([float(rng.uniform(1.0, 4.0)), float(z) + float(rng.uniform(-1.5, 1.5))])
        _trunk(s, p, 0.3, ground_at(*p) - 1.0, ground_at(*p) + 6.0)
    return s.mesh()


def marina(seed: int) -> trimesh.Trimesh:
    """A marina (an open-world coast's harbour, a heist's getaway) in a basin 190-210 m wide along x: a quay 20 m deep (its
    top 2.2 m over the water, no floor on the water) along the north with 4-6 buildings (ridged) and bollards; from it 5
    main pontoons 2.4-3.0 m wide and 60-80 m long run south, decks 0.4 m over the water, each reached down a gangway 1.8
    m wide, railed (1 m), 8-9 m long (10-12 degrees) from the quay's edge to the pontoon's head; each pontoon ends in a
    T-head 3 m wide and 18-22 m long, and along both its sides finger berths 8-11 m long every 5-6 m whose *width,
    1.2-1.8 m drawn per pontoon, straddles the 1.5 m the agent's 1 m needs on Recast's cells of 0.25 m*; a boat (a
    ridged hull 3-4 m wide, 8-10 m long) in 70 % of the berths; a fuel kiosk at one T-head's east end.
    
    Expected (written before the first run): one area (every pontoon reached down its gangway); a pontoon's fingers
    floor where wider than the agent's need and none where narrower (a designer would see those berths left out, a real
    limit of the agent's size, not a fault); traffic highest on the quay and the gangways, then down the main pontoons,
    lowest at the fingers' tips and the T-heads' ends; a designer expects the structure along the pontoons with leaves
    onto the fingers, never across the water between two fingers, two pontoons or a pontoon and the quay but down a
    gangway."""
    rng = np.random.default_rng(seed)
    size_x = float(rng.uniform(190.0, 210.0))
    quay_z, quay_y, deck = 0.0, 2.2, 0.4
    s = _Solids()
    x, buildings = float(rng.uniform(4.0, 12.0)), []
    for _ in range(int(rng.integers(4, 7))):  # buildings along the quay's back
        w = float(rng.uniform(12.0, 20.0))
        if x + w > size_x:
            break
        buildings.append(_ridged(s, x, x + w, quay_z + 12.0, quay_z + 19.5, quay_y - 0.3, quay_y + 5.0))
        x += w + float(rng.uniform(5.0, 9.0))
    s.ground(-10.0, size_x + 10.0, quay_z, quay_z + 20.0, quay_y, buildings, thickness=3.2)  # none under a building
    pontoons = np.linspace(20.0, size_x - 20.0, 5)
    kiosk = int(rng.integers(0, 5))
    for k, px in enumerate(pontoons):
        px = float(px + rng.uniform(-4.0, 4.0))
        width, finger = float(rng.uniform(2.4, 3.0)), float(rng.uniform(1.2, 1.8))
        head = quay_z - float(rng.uniform(8.0, 9.0))  # the pontoon's head (north end), a gangway down from the quay
        end = head - float(rng.uniform(60.0, 80.0))
        s.box(px - width / 2, px + width / 2, deck - 0.6, deck, end, head)
        s.ramp(np.array([px, quay_z]), np.array([px, head]), 1.8, quay_y, deck)
        for side in (-1.0, 1.0):
            s.hull(np.array([[px + side * 1.0 + d, y + h, z] for z, y in ((quay_z, quay_y), (head, deck))
                             for d in (0.0, side * 0.1) for h in (0.0, 1.0)]))
        for x in (px - 1.5, px + 1.5):  # bollards either side of the gangway's top
            s.box(x - 0.2, x + 0.2, quay_y, quay_y + 0.6, quay_z + 0.5, quay_z + 0.9)
        t_len = float(rng.uniform(18.0, 22.0))
        s.box(px - t_len / 2, px + t_len / 2, deck - 0.6, deck, end - 3.0, end)
        if k == kiosk:  # at the T-head's east end
            _ridged(s, px + t_len / 2 - 4.0, px + t_len / 2, end - 2.8, end - 0.6, deck - 0.3, deck + 2.4)
        pitch, reach = float(rng.uniform(5.0, 6.0)), float(rng.uniform(8.0, 11.0))
        for side in (-1.0, 1.0):
            edge = px + side * width / 2
            z = head - 4.0
            while z - pitch > end + 2.0:
                s.box(*sorted((edge, edge + side * reach)), deck - 0.6, deck, z - finger, z)
                if rng.random() < 0.7:  # a boat in the berth south of this finger
                    bz = z - finger - (pitch - finger) / 2
                    a, b = np.array([edge + side * 1.0, bz]), np.array([edge + side * (reach - 0.5), bz])
                    _ridged_strip(s, a, b, min(pitch - finger - 0.6, float(rng.uniform(3.0, 4.0))), -1.0, 1.2)
                z -= pitch
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "aircraft_carrier": aircraft_carrier, "submarine": submarine, "velodrome": velodrome,
    "drained_pools": drained_pools, "mogul_piste": mogul_piste, "marina": marina,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirtieth round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
