"""Level kinds of the thirty-third held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each about 400-1,200 navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py`` and ``level_kinds30.py`` (imported, not copied): ``attic_row`` (two terraces of houses
whose lofts under roofs pitched at 38-45 degrees leave head room only in a band under the ridge and in dormer bays,
joined through openings in the party walls), ``labyrinth`` (a unicursal labyrinth of 8-10 concentric ring corridors
1.9-2.5 m wide, one path of 0.9-1.1 km), ``hill_fort`` (a hilltop ringed by three earthwork
ramparts whose outer faces fall steeper than the slope limit into ditches, entered through staggered gates),
``subway_roundabout`` (a sunken garden 4 m under a roundabout, left by subways under its carriageway to ramps and
flights in open troughs; the carriageway railed off), ``ramp_towers`` (a concourse 6-8 m over a plaza reached by
zigzag ramps whose side-by-side runs are parted only by a rail 0.06 m thick, their heights equal at every landing)
and ``cenote`` (a sinkhole 18-24 m deep descended by one ledge 2.0-2.6 m wide spiralling down its wall under rock
overhangs 2.3-2.8 m over it, caves off it).

Run: ``.venv/bin/python benchmarks/level_kinds33.py OUT_DIR [--kinds labyrinth cenote] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _ridged, _Solids, _terrain, _trunk, _wall_line
from level_kinds import main as write_kinds
from level_kinds30 import RIDGE, _placed


def _roof_piece(s: _Solids, x0: float, x1: float, z_eave: float, z_ridge: float, y_eave: float, y_ridge: float) -> None:
    """One side of a pitched roof over [x0, x1] from the eave line z = ``z_eave`` (its underside at ``y_eave``) to the
    ridge line z = ``z_ridge`` (its underside at ``y_ridge``): one convex hull whose top rises at 50 degrees (over the
    agent's 45) from 0.2 m over the eave, so the outside of the roof is never floor while its underside sets the loft's
    head room."""
    rise = 0.2 + abs(z_ridge - z_eave) * RIDGE
    s.hull(np.array([[x, y, z] for x in (x0, x1) for z, y in
                     ((z_eave, y_eave), (z_eave, y_eave + 0.2), (z_ridge, y_ridge), (z_ridge, y_eave + rise))]))


def _gable_wall(s: _Solids, x: float, depth: float, floor: float, knee: float, ridge: float, opening: float) -> None:
    """A party or end wall 0.3 m thick at ``x`` across a loft [0, depth] in z, from ``floor`` up to the roof's
    underside (``knee`` over the floor at each eave, ``ridge`` at z = depth / 2), open over a passage ``opening`` m
    wide and 2.3 m high under the ridge (none when 0): three convex hulls (the wall either side, the lintel)."""
    mid, half = depth / 2, opening / 2

    def roof(z: float) -> float:
        return knee + (ridge - knee) * (1.0 - abs(z - mid) / mid)

    pieces = [[(0.0, 0.0), (mid - half, 0.0), (mid - half, roof(mid - half)), (0.0, knee)],
              [(depth, 0.0), (mid + half, 0.0), (mid + half, roof(mid + half)), (depth, knee)]]
    if opening > 0.0:
        pieces.append([(mid - half, 2.3), (mid + half, 2.3), (mid + half, roof(mid + half)), (mid, ridge),
                       (mid - half, roof(mid - half))])
    else:
        pieces = [[(0.0, 0.0), (depth, 0.0), (depth, knee), (mid, ridge), (0.0, knee)]]
    for plan in pieces:
        s.hull(np.array([[xx, floor + y, z] for xx in (x - 0.15, x + 0.15) for z, y in plan]))


def _terrace(rng: np.random.Generator) -> _Solids:
    """One terrace of :func:`attic_row` with its front on z = 0 (the street at z < 0), its houses along +x from x = 0:
    see there. O(houses + dormers) solids."""
    houses, depth = int(rng.integers(5, 8)), float(rng.uniform(9.0, 11.0))
    pitch, knee, loft = math.radians(float(rng.uniform(38.0, 45.0))), float(rng.uniform(0.4, 0.6)), 2.7
    ridge = knee + depth / 2 * math.tan(pitch)  # the roof's underside over the loft floor under the ridge
    widths = [float(rng.uniform(6.5, 8.5)) for _ in range(houses)]
    edges = np.concatenate([[0.0], np.cumsum(widths)])
    total, mid = float(edges[-1]), depth / 2
    s = _Solids()
    s.box(-3.0, total + 3.0, -0.5, 0.0, depth + 6.0, depth + 10.0)  # the back lane
    run = 15 * 0.25
    for k in range(houses):
        x0, x1 = float(edges[k]), float(edges[k + 1])
        w = x1 - x0
        s.box(x0, x1, -0.5, 0.0, 0.0, depth + 6.0)  # the ground floor and the yard
        # the flight across the middle of the house, rising east to the loft's floor under the ridge; the rooms in
        # front of it and behind it joined round its foot
        hole = (x0 + 1.5, x0 + 1.5 + run, mid - 1.0, mid + 1.0)
        s.stairs(np.array([hole[0], mid]), np.array([1.0, 0.0]), 2.0, 0.0, loft, 0.18, 0.25)
        s.slab(x0, x1, 0.0, depth, loft, [hole])
        for z in (hole[2] - 0.1, hole[3]):  # the hole's rails
            s.box(hole[0], hole[1], loft, loft + 1.0, z, z + 0.1)
        s.box(hole[0] - 0.1, hole[0], loft, loft + 1.0, hole[2] - 0.1, hole[3] + 0.1)
        for wall_z in (0.0, depth):  # the front and back walls, a door in each; the loft's knee walls over them
            s.wall((x0, wall_z), (x1, wall_z), 0.0, loft - 0.3, [(float(rng.uniform(2.6, w - 2.0)), 1.5)], thickness=0.3)
            s.wall((x0, wall_z), (x1, wall_z), loft - 0.3, loft + knee, thickness=0.3)
        gate = float(rng.uniform(0.5, w - 2.1))
        s.wall((x0, depth + 6.0), (x1, depth + 6.0), 0.0, 2.0, [(gate, 1.6)], thickness=0.2)
        s.wall((x0, depth), (x0, depth + 6.0), 0.0, 2.0, thickness=0.2)
        # the roof either side, open over each dormer
        dormers = {side: [] for side in (0, 1)}
        for side in (0, 1):
            for _ in range(int(rng.integers(0, 3))):
                dw = float(rng.uniform(1.8, 2.6))
                dx = float(rng.uniform(x0 + 0.5, x1 - 0.5 - dw))
                if all(dx > b + 0.6 or dx + dw < a - 0.6 for a, b in dormers[side]):
                    dormers[side].append((dx, dx + dw))
        reach = (2.5 - knee) / math.tan(pitch)  # how far in from the eave the roof's underside passes 2.5 m
        for side, (z_eave, z_in) in enumerate(((0.0, reach), (depth, depth - reach))):
            cuts = sorted([x0, x1, *[c for d in dormers[side] for c in d]])
            for a, b in zip(cuts[:-1], cuts[1:]):
                if any(abs(a - d[0]) < 1e-9 for d in dormers[side]):  # over a dormer: the roof from its back only
                    _roof_piece(s, a, b, z_in, mid, loft + 2.5, loft + ridge)
                else:
                    _roof_piece(s, a, b, z_eave, mid, loft + knee, loft + ridge)
            for a, b in dormers[side]:  # each dormer's cheeks, its front up to 2.5 m, its roof ridged along z
                lo, hi = sorted((z_eave, z_in))
                for x in (a, b):
                    s.box(x - 0.1, x + 0.1, loft, loft + 2.5, lo, hi)
                s.box(a, b, loft + knee, loft + 2.5, z_eave - 0.15, z_eave + 0.15)
                top = loft + 2.7 + (b - a + 0.3) / 2 * RIDGE
                s.hull(np.array([[x, y, z] for x in (a - 0.15, b + 0.15) for y in (loft + 2.5, loft + 2.7)
                                 for z in (lo - 0.2, hi + 0.2)] + [[(a + b) / 2, top, z] for z in (lo - 0.2, hi + 0.2)]))
        # the loft's clutter: trunks and crates under the eaves, a water tank in the band
        for _ in range(int(rng.integers(3, 7))):
            cx = float(rng.uniform(x0 + 0.8, x1 - 0.8))
            cz = float(rng.uniform(0.5, 1.2)) if rng.random() < 0.5 else depth - float(rng.uniform(0.5, 1.2))
            if not any(a - 0.5 < cx < b + 0.5 for d in dormers.values() for a, b in d):
                _ridged(s, cx - 0.5, cx + 0.5, cz - 0.35, cz + 0.35, loft, loft + 0.5)
        _ridged(s, x1 - 1.5, x1 - 0.3, mid + 1.0, mid + 2.2, loft, loft + 1.1)  # the water tank
    for k in range(houses + 1):  # party walls and end gables in the lofts, ground floor walls between houses
        x = float(edges[k])
        inner = 0 < k < houses
        opening = float(rng.uniform(1.4, 1.8)) if inner and rng.random() >= 1 / 3 else 0.0
        _gable_wall(s, x, depth, loft, knee, ridge, opening)
        s.wall((x, 0.0), (x, depth), 0.0, loft, thickness=0.3)
    s.wall((total, depth), (total, depth + 6.0), 0.0, 2.0, thickness=0.2)
    return s


def attic_row(seed: int) -> trimesh.Trimesh:
    """Two terraces of houses facing each other across a street 8 m wide (a stealth game's or a horror game's, whose
    thieves and ghosts run through the lofts), 5-7 houses each, 6.5-8.5 m wide (drawn per house) and 9-11 m deep
    (drawn per terrace), a yard 6 m deep behind each (fenced 2 m high from its neighbours; a back gate 1.6 m wide onto
    a lane 4 m wide). The ground floor (y = 0): a front door and a back door 1.5 m wide; a flight 2 m wide across the
    middle of the depth, its foot 1.5 m from the west party wall, rising east (15 risers of 0.18 m, treads 0.25 m) to
    the loft's floor 2.7 m up through a hole railed 1 m high, the rooms in front of it and behind it joined round its
    foot. The loft: a roof pitched at 38-45 degrees (drawn per terrace) springing from knee walls 0.4-0.6 m high (drawn
    per terrace) to a ridge along x over the middle, so head room reaches the agent's 2 m only in a band about 5-8 m
    wide under the ridge (the stair hole in its middle); 0-2 dormers a side (drawn per house; 1.8-2.6 m wide, a flat
    ceiling 2.5 m over the floor, reaching in from the eave to where the roof passes 2.5 m) whose bays hold head room
    out to the eave wall; 3-6 trunks and crates (ridged) under the eaves, a water tank (ridged) in the band. The party
    walls rise to the roof, each open under the ridge by a passage 1.4-1.8 m wide and 2.3 m high but one in three
    (drawn) bricked up; the end gables closed.

    Expected (written before the first run; the areas counted on the drafts): the street, the houses, the lanes and
    the yards one area through the doors and the gates, with every loft on it up its flight; floor in a loft only in
    the band under the ridge (the agent's radius in from where the roof's underside passes 2 m) and in the dormer
    bays, none under the eaves; strips of the band beside a stair hole's rails may be cut off by the low roof (islands
    of 4-8 m², left out under the cover's smallest area and named in a warning). The lofts of a run of open party walls
    joined through them, a bricked-up wall parting two lofts that the structure never crosses. The structure a chain
    along each loft's band with a leaf into each dormer bay, a node or two in each room; never through a party wall or
    up through the roof. Traffic highest on the street and at the flights' feet, then along the lofts' bands between
    open passages; lowest in the dormer bays and the yards."""
    rng = np.random.default_rng(seed)
    north, south = _terrace(rng), _terrace(rng)
    mirror = np.diag([1.0, 1.0, -1.0, 1.0])  # the south terrace faces the north one across the street
    mirror[2, 3] = -8.0
    for part in south.parts:
        part.apply_transform(mirror)
    s = _Solids()
    s.parts = north.parts + south.parts
    lo, hi = s.mesh().bounds[:, 0]
    s.box(float(lo) - 3.0, float(hi) + 3.0, -0.5, 0.0, -8.0, 0.0)  # the street
    return s.mesh()


def labyrinth(seed: int, ring_width: float | None = None) -> trimesh.Trimesh:
    """A unicursal labyrinth (a puzzle game's, a horror game's garden) on a lawn: 8-10 concentric ring corridors
    round a centre court 4.5 m in radius, each corridor 1.9-2.5 m wide (drawn per ring: the agent's 1 m plus a metre
    or so; the drafts' 1.3-1.9 m held no floor along most rings), hedges 0.4 m thick and 2.4 m high drawn as chords
    about 0.8 m long. Each ring's hedge has one opening
    (the corridor's width plus 0.2 m) and each corridor one radial hedge beside its way in, so the one path runs
    almost a full turn round every corridor, turning back at each ring (clockwise, then counter-clockwise): 0.9-1.1
    km from the lawn to the court. The court: a well (1 m across, 0.9 m high) and two benches. The lawn 14 m wide round
    the outer hedge, fenced 1.1 m high but at a gate; a gazebo (ridged; the lawn stops under it) and benches on it.

    Expected (written before the first run): one area. Floor in every corridor (eroded to a lane 0.9-1.5 m wide);
    the structure a chain along each corridor joined only at the openings, a leaf at each radial hedge's
    blind side (the short end of a corridor past its way in); never through a hedge between two rings, however close
    two nodes of neighbouring rings stand. Traffic falling from the outer corridor (every path to the court and the
    inner rings runs through it) to the court, lowest in the blind ends; the lawn's coverage from a ring round the
    outer hedge."""
    rng = np.random.default_rng(seed)
    rings = int(rng.integers(8, 11))
    widths = [float(rng.uniform(1.9, 2.5)) for _ in range(rings)]
    if ring_width is not None:  # every corridor that wide, the rest of the level as drawn (benchmarks/curved_corridors.py)
        widths = [ring_width] * rings
    thick, high, court = 0.4, 2.4, 4.5
    radii = [court]  # the centre line of each hedge, innermost first
    for w in widths:
        radii.append(radii[-1] + thick / 2 + w + thick / 2)
    outer = radii[-1] + thick / 2
    lawn = outer + 14.0
    s = _Solids()
    start = float(rng.uniform(0.0, 2 * math.pi))
    # the openings: hedge k (0 = round the court) between corridor k - 1 and corridor k (the corridors outward of it)
    opening = [0.0] * (rings + 1)
    blocker = [0.0] * rings
    opening[rings] = start
    for k in range(rings - 1, -1, -1):  # corridor k entered through hedge k + 1, left through hedge k
        turn = 1.0 if (rings - 1 - k) % 2 == 0 else -1.0
        mid_r = (radii[k] + radii[k + 1]) / 2
        offset = (widths[k] + 1.6) / mid_r  # the blocker and the way out a corridor's width or so from the way in
        blocker[k] = opening[k + 1] - turn * offset / 2
        opening[k] = opening[k + 1] - turn * offset
    for k, r in enumerate(radii):
        pieces = max(24, round(2 * math.pi * r / 0.8))
        angles = np.linspace(0.0, 2 * math.pi, pieces + 1) + opening[k]
        between = min(widths[max(k - 1, 0)], widths[min(k, rings - 1)])  # the narrower corridor it joins
        gap = (between + 0.2) / r  # the opening's angle, centred on opening[k]
        for a, b in zip(angles[:-1], angles[1:]):
            lo, hi = a - opening[k], b - opening[k]
            if hi <= gap / 2 or lo >= 2 * math.pi - gap / 2:
                continue  # inside the opening
            a0, b0 = max(lo, gap / 2) + opening[k], min(hi, 2 * math.pi - gap / 2) + opening[k]
            _wall_line(s, r * np.array([math.cos(a0), math.sin(a0)]), r * np.array([math.cos(b0), math.sin(b0)]),
                       0.0, high, thick, [])
    for k in range(rings):
        a = blocker[k]
        direction = np.array([math.cos(a), math.sin(a)])
        _wall_line(s, direction * radii[k], direction * radii[k + 1], 0.0, high, thick, [])
    _trunk(s, np.zeros(2), 0.5, -0.1, 0.9)  # the well
    for a in (start + 2.0, start + 4.0):
        p = (court - 1.2) * np.array([math.cos(a), math.sin(a)])
        _ridged(s, p[0] - 0.7, p[0] + 0.7, p[1] - 0.25, p[1] + 0.25, 0.0, 0.45)
    gate = float(rng.uniform(-lawn + 6.0, lawn - 9.0))
    s.wall((-lawn, -lawn), (lawn, -lawn), 0.0, 1.1, [(gate + lawn, 3.0)], thickness=0.1)
    s.wall((-lawn, lawn), (lawn, lawn), 0.0, 1.1, thickness=0.1)
    for x in (-lawn, lawn):
        s.wall((x, -lawn), (x, lawn), 0.0, 1.1, thickness=0.1)
    spots: list[tuple[np.ndarray, float]] = [(np.zeros(2), outer + 2.5)]
    holes = []  # the lawn stops under the gazebo (a closed body: the ground inside it would be floor)
    g = _placed(rng, spots, -lawn + 1.0, lawn - 1.0, -lawn + 1.0, lawn - 1.0, 3.0, [])
    if g is not None:
        holes.append(_ridged(s, g[0] - 2.5, g[0] + 2.5, g[1] - 2.5, g[1] + 2.5, -0.1, 2.6))
    for _ in range(int(rng.integers(4, 8))):
        p = _placed(rng, spots, -lawn + 1.0, lawn - 1.0, -lawn + 1.0, lawn - 1.0, 1.2, [])
        if p is not None:
            _ridged(s, p[0] - 0.8, p[0] + 0.8, p[1] - 0.3, p[1] + 0.3, 0.0, 0.45)
    s.ground(-lawn, lawn, -lawn, lawn, 0.0, holes)
    return s.mesh()


def hill_fort(seed: int) -> trimesh.Trimesh:
    """An iron-age hill fort (an open-world RPG's or a historical shooter's) on a hill 8-12 m high (a smooth dome on
    a grid of 1 m, 170 x 170 m): three earthwork ramparts round its top (30, 48 and 66 m out) on closed curves
    (ellipses of aspect 0.8-1.0, wobbling 2-4 %), each a bank 2.5-3.5 m high over 6 m of inner slope (23-30 degrees,
    walkable), a crest 2 m wide, an outer face that falls 4.5-6.5 m over 2 m into a ditch 3 m wide (66-73 degrees: a
    cliff of earth) and a counterscarp rising out of it 2-3 m over 4 m (27-37 degrees, walkable). Each rampart has one gate
    7 m wide, a causeway over its ditch with the bank cut away (blended over 4 m either side), the gates staggered
    100-160 degrees round from one another, so the way in winds round in the ditches and along the berms between the
    ramparts. On the top up to 4-7 roundhouses (walls 5-6.5 m across on 24 chords, 2.6 m high, a door about 2 m wide,
    a roof cone at 52 degrees) and a well.

    Expected (written before the first run): one area (every ditch reached down its counterscarp, every crest up its
    inner slope, the top through the three gates). No floor on the outer faces. The structure loops along the ditches
    and the berms and threads the gates one after the other; never up or down an outer face (a straight edge from a
    ditch to the crest above it) nor across a ditch outside a causeway. A leaf into each roundhouse. Traffic highest
    through the gates and along the stretches of berm and ditch between them, lowest on the far sides of the ditches
    and on the hill's foot."""
    rng = np.random.default_rng(seed)
    half, hill = 85.0, float(rng.uniform(8.0, 12.0))
    xs = np.arange(-half, half + 0.5, 1.0)
    gx, gz = np.meshgrid(xs, xs, indexing="ij")
    r = np.hypot(gx, gz)
    theta = np.arctan2(gz, gx)
    height = hill * np.exp(-(r / 55.0) ** 2)
    aspect = float(rng.uniform(0.8, 1.0))
    wobble = [(float(rng.uniform(0.02, 0.04)), float(rng.uniform(0.0, 2 * math.pi)), int(rng.integers(2, 5)))
              for _ in range(3)]
    gate0 = float(rng.uniform(0.0, 2 * math.pi))
    gates = [gate0]
    for _ in range(2):
        gates.append(gates[-1] + float(rng.choice([-1.0, 1.0])) * math.radians(float(rng.uniform(100.0, 160.0))))
    rampart_radii = [30.0, 48.0, 66.0]  # innermost first
    for k, base in enumerate(rampart_radii):
        amp, phase, lobes = wobble[k]
        # the rampart's line in polar form, scaled per direction by the ellipse and the wobble
        scale = base * (1.0 + amp * np.sin(lobes * theta + phase)) / np.sqrt(
            np.cos(theta) ** 2 + (np.sin(theta) / aspect) ** 2)
        t = r - scale  # metres outward of the rampart's line (the crest's outer edge)
        bank, ditch = float(rng.uniform(2.5, 3.5)), float(rng.uniform(2.0, 3.0))
        profile = np.zeros_like(t)
        inner = (t > -8.0) & (t <= -2.0)
        profile[inner] = bank * (t[inner] + 8.0) / 6.0
        profile[(t > -2.0) & (t <= 0.0)] = bank
        face = (t > 0.0) & (t <= 2.0)
        profile[face] = bank - (bank + ditch) * t[face] / 2.0
        profile[(t > 2.0) & (t <= 5.0)] = -ditch
        scarp = (t > 5.0) & (t <= 9.0)
        profile[scarp] = -ditch * (9.0 - t[scarp]) / 4.0
        along = np.abs((theta - gates[k] + math.pi) % (2 * math.pi) - math.pi) * scale  # arc metres from the gate
        keep = np.clip((along - 3.5) / 4.0, 0.0, 1.0)  # 0 in the gate's 7 m, blended to 1 over 4 m either side
        height += profile * keep
    s = _Solids()
    _terrain(s, xs, xs, height)

    def ground(p: np.ndarray) -> float:
        i, j = int(round(p[0] + half)), int(round(p[1] + half))
        return float(height[i, j])

    spots: list[tuple[np.ndarray, float]] = []
    inner_r = rampart_radii[0] * aspect * 0.96 - 10.0
    for _ in range(int(rng.integers(4, 8))):
        radius = float(rng.uniform(2.5, 3.25))
        c = _placed(rng, spots, -inner_r, inner_r, -inner_r, inner_r, radius + 2.0, [])
        if c is None or np.linalg.norm(c) > inner_r:
            continue
        floor = ground(c)
        door = float(rng.uniform(0.0, 2 * math.pi))
        pieces = 24
        for i in range(pieces):
            a, b = 2 * math.pi * i / pieces, 2 * math.pi * (i + 1) / pieces
            if abs((((a + b) / 2 - door + math.pi) % (2 * math.pi)) - math.pi) < 1.0 / radius:
                continue  # the door's chords
            pa, pb = c + radius * np.array([math.cos(a), math.sin(a)]), c + radius * np.array([math.cos(b), math.sin(b)])
            _wall_line(s, pa, pb, floor - 1.5, floor + 2.6, 0.25, [])
        ring = np.linspace(0.0, 2 * math.pi, 12, endpoint=False)
        eave = c + (radius + 0.4) * np.stack([np.cos(ring), np.sin(ring)], 1)
        s.hull(np.vstack([np.insert(eave, 1, floor + 2.6, axis=1), np.insert(eave, 1, floor + 2.8, axis=1),
                          [[c[0], floor + 2.8 + (radius + 0.4) * 1.28, c[1]]]]))
    w = _placed(rng, spots, -inner_r, inner_r, -inner_r, inner_r, 1.5, [])
    if w is not None:
        _trunk(s, w, 0.7, ground(w) - 1.0, ground(w) + 0.9)
    return s.mesh()


def subway_roundabout(seed: int) -> trimesh.Trimesh:
    """A sunken garden under a roundabout (a city shooter's or a walking sim's): a round garden 15-19 m in radius
    4 m under the street (y = 0), walled by a retaining wall 0.4 m thick with a parapet 1.1 m high; round it a
    carriageway 10 m wide at the street's level, railed 1.1 m high on both edges (no crossing for people); outside it
    the streets' ground (a grid of 0.5 m, out to 75 m) with blocks of buildings (ridged) between 4-5 subways. Each
    subway (3.5-4.5 m wide, drawn) leaves the garden through an opening in its wall and runs under the carriageway
    (head room 3.5 m) to an open trough walled to 1.1 m over the street, which climbs to the street by a ramp (1 in
    10, 40 m) or a flight (25 risers of 0.16 m) drawn per subway, one ramp at least. In the garden a fountain (a
    basin 0.8 m high, a spire), 5-8 trees, 4-6 benches, a kiosk (ridged).

    Expected (written before the first run): the garden, the subways, the troughs and the streets one area; the
    carriageway an area apart (floor, railed off), left as its own structure or named. The structure a ring round the
    garden with a spoke out through each subway and up its trough to the streets, and along the streets round the
    carriageway's outer rail; never through the retaining wall (garden to carriageway or street), never from a subway
    up through the carriageway. Traffic highest in the subways (every path between two streets crosses the garden,
    or goes round on the streets), lowest in the garden's middle and the streets' corners."""
    rng = np.random.default_rng(seed)
    garden, sunk, road = float(rng.uniform(15.0, 19.0)), 4.0, 10.0
    outer = garden + 0.4 + road
    subways = int(rng.integers(4, 6))
    angles = np.sort((float(rng.uniform(0.0, 2 * math.pi)) + np.arange(subways) * 2 * math.pi / subways
                      + rng.uniform(-0.25, 0.25, subways)) % (2 * math.pi))
    kinds = ["ramp" if rng.random() < 0.5 else "flight" for _ in range(subways)]
    kinds[int(rng.integers(subways))] = "ramp"
    widths = [float(rng.uniform(3.5, 4.5)) for _ in range(subways)]
    lengths = [40.0 if k == "ramp" else 25 * 0.3 for k in kinds]  # the climb's plan length
    s = _Solids()
    half = 75.0

    def local(p: np.ndarray, a: float) -> tuple[np.ndarray, np.ndarray]:
        """Plan points p (..., 2) in the frame of a subway at angle a: (metres outward from the centre, across)."""
        u, v = np.array([math.cos(a), math.sin(a)]), np.array([-math.sin(a), math.cos(a)])
        return p @ u, p @ v

    xs = np.arange(-half, half + 0.25, 0.5)
    cx, cz = np.meshgrid((xs[:-1] + xs[1:]) / 2, (xs[:-1] + xs[1:]) / 2, indexing="ij")
    cells = np.stack([cx, cz], -1)
    keep = np.hypot(cx, cz) > garden + 0.3  # the street and the carriageway's deck (a sheet 0.5 m thick)
    for a, w, length in zip(angles, widths, lengths):
        out, across = local(cells, a)
        keep &= ~((out > outer) & (out < outer + 2.0 + length) & (np.abs(across) < w / 2 + 0.45))
    for k in range(subways):  # a block of buildings between each two subways, clear of the troughs
        a0, a1 = angles[k], angles[(k + 1) % subways] + (2 * math.pi if k == subways - 1 else 0.0)
        mid = (a0 + a1) / 2
        centre = (outer + 22.0) * np.array([math.cos(mid), math.sin(mid)])
        size = min(14.0, (outer + 22.0) * (a1 - a0) / 2 - 9.0)
        if size > 4.0:
            b = (centre[0] - size / 2, centre[0] + size / 2, centre[1] - size / 2, centre[1] + size / 2)
            _ridged(s, *b, -0.1, float(rng.uniform(6.0, 12.0)))
            keep &= ~((cx > b[0]) & (cx < b[1]) & (cz > b[2]) & (cz < b[3]))
    _terrain(s, xs, xs, np.zeros((len(xs), len(xs))), keep)
    ring = np.linspace(0.0, 2 * math.pi, 73)
    disc = np.stack([np.cos(ring[:-1]), np.sin(ring[:-1])], 1)
    s.prism(garden * disc, -sunk - 0.5, -sunk)  # the garden's floor

    def in_mouth(a: float, r: float, extra: float) -> int | None:
        """The subway whose opening (widened by ``extra`` m) the chord at angle a of a ring of radius r meets."""
        for k, (b, w) in enumerate(zip(angles, widths)):
            if abs(((a - b + math.pi) % (2 * math.pi)) - math.pi) * r < w / 2 + extra:
                return k
        return None

    for a, b in zip(ring[:-1], ring[1:]):  # the retaining wall, open over each subway's mouth under the deck
        pa, pb = (garden + 0.2) * np.array([math.cos(a), math.sin(a)]), (garden + 0.2) * np.array([math.cos(b), math.sin(b)])
        if in_mouth((a + b) / 2, garden, 0.3) is None:
            _wall_line(s, pa, pb, -sunk - 0.5, 1.1, 0.4, [])
        else:
            _wall_line(s, pa, pb, -0.5, 1.1, 0.4, [])
        # the carriageway's outer rail (its inner edge railed by the retaining wall's parapet)
        _wall_line(s, outer * np.array([math.cos(a), math.sin(a)]), outer * np.array([math.cos(b), math.sin(b)]),
                   0.0, 1.1, 0.1, [])
    for a, w, kind, length in zip(angles, widths, kinds, lengths):
        u, v = np.array([math.cos(a), math.sin(a)]), np.array([-math.sin(a), math.cos(a)])

        def strip(r0: float, r1: float, c0: float, c1: float) -> np.ndarray:
            return np.array([u * r0 + v * c0, u * r1 + v * c0, u * r1 + v * c1, u * r0 + v * c1])

        foot = outer + 2.0
        s.prism(strip(garden - 1.0, foot, -w / 2, w / 2), -sunk - 0.5, -sunk)  # the subway's floor, to the trough's foot
        for side in (-1.0, 1.0):  # its walls under the deck, the trough's walls to 1.1 m over the street
            c = side * (w / 2 + 0.2)
            _wall_line(s, u * (garden + 0.4) + v * c, u * outer + v * c, -sunk - 0.5, -0.5, 0.4, [])
            _wall_line(s, u * outer + v * c, u * (outer + 2.0 + length) + v * c, -sunk - 0.5, 1.1, 0.4, [])
        if kind == "ramp":
            s.ramp(u * foot, u * (foot + length), w, -sunk, 0.0, thickness=0.5)
        else:
            s.stairs(u * foot, u, w, -sunk, sunk, 0.16, 0.3)
    fountain = np.zeros(2)
    _trunk(s, fountain, 2.5, -sunk - 0.1, -sunk + 0.8)
    s.hull(np.array([[0.6 * math.cos(t), -sunk + 0.8, 0.6 * math.sin(t)] for t in ring[:-1:6]] + [[0.0, -sunk + 4.0, 0.0]]))
    spots: list[tuple[np.ndarray, float]] = [(fountain, 4.0)]
    span = garden - 2.0
    for _ in range(int(rng.integers(5, 9))):
        p = _placed(rng, spots, -span, span, -span, span, 1.5, [])
        if p is not None and np.linalg.norm(p) < span:
            _trunk(s, p, 0.3, -sunk - 0.1, -sunk + 6.0)
    for _ in range(int(rng.integers(4, 7))):
        p = _placed(rng, spots, -span, span, -span, span, 1.0, [])
        if p is not None and np.linalg.norm(p) < span:
            _ridged(s, p[0] - 0.8, p[0] + 0.8, p[1] - 0.3, p[1] + 0.3, -sunk, -sunk + 0.45)
    p = _placed(rng, spots, -span, span, -span, span, 2.2, [])
    if p is not None and np.linalg.norm(p) < span - 1.0:
        _ridged(s, p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, -sunk, -sunk + 2.6)
    return s.mesh()


def _ramp_tower(s: _Solids, x0: float, z0: float, deck: float, length: float,
                width: float) -> list[tuple[float, float, float, float]]:
    """One zigzag ramp of :func:`ramp_towers` from the plaza at x0 (its first run's foot) up to ``deck``: runs
    ``length`` m along x, ``width`` m wide, side by side towards +z, each rising about 1 in 12 (the runs' count the
    fewest that keep to it), parted by rails 0.06 m thick that stand 1.1 m over the higher run; landings 2 m long at
    the ends, railed; a rail along the first run's open side. The last run (its far edge at z0 + runs x (width + 0.06)
    - 0.06) ends at ``deck``, at x0 + length when the runs' count is odd, at x0 when even: the caller's landing there.
    Returns the plans (x0, x1, z0, z1) of the solids standing on the ground, holes for the plaza
    (:meth:`_Solids.ground`: the ground inside a closed body with head room over it would be floor). O(runs) solids."""
    rail = 0.06
    runs = math.ceil(deck / (length / 12.0))
    rise, pitch, x1 = deck / runs, width + rail, x0 + length
    plans = [(x0, x1, z0 - rail, z0 + runs * pitch - rail)]

    def at(k: int, x: float) -> float:
        """The height of run k's top at x (even runs rise towards +x, odd ones towards -x)."""
        t = (x - x0) / length if k % 2 == 0 else (x1 - x) / length
        return (k + t) * rise

    for k in range(runs):
        za = z0 + k * pitch
        s.hull(np.array([[x, y, z] for x in (x0, x1) for y in (-0.1, at(k, x)) for z in (za, za + width)]))
        if k + 1 < runs:  # the rail to the next run, over the higher of the two at each end
            s.hull(np.array([[x, y, z] for x in (x0, x1) for y in (-0.1, max(at(k, x), at(k + 1, x)) + 1.1)
                             for z in (za + width, za + pitch)]))
    s.hull(np.array([[x, y, z] for x in (x0, x1) for y in (-0.1, at(0, x) + 1.1) for z in (z0 - rail, z0)]))
    for k in range(runs - 1):  # the landing between run k and k + 1: at x1 after an even run, at x0 after an odd one
        top = (k + 1) * rise
        xa, xb = (x1, x1 + 2.0) if k % 2 == 0 else (x0 - 2.0, x0)
        za, zb = z0 + k * pitch, z0 + (k + 1) * pitch + width
        s.box(xa, xb, -0.1, top, za, zb)
        plans.append((xa, xb, za - rail, zb + rail))
        beside = (k + 3) * rise if k + 2 < runs else top  # the next landing (or the last run's end) beyond zb
        s.box(xa, xb, -0.1, beside + 1.1, zb, zb + rail)
        s.box(xa, xb, -0.1, top + 1.1, za - rail, za)
        end = xb if k % 2 == 0 else xa
        s.box(end - rail / 2, end + rail / 2, top, top + 1.1, za, zb)
    return plans


def ramp_towers(seed: int) -> trimesh.Trimesh:
    """A stadium's ramp towers (a sports game's or a shooter's arena outside): a plaza 110-130 x 60 m at y = 0 and,
    along its north side, a concourse 14 m deep at 6-8 m up (drawn per seed) on columns every 8 m, railed 1.1 m high
    along its edge but at the towers, walled behind by the stands' wall with 4-6 gates (openings 3 m wide, leading
    to nothing: vomitories 4 m deep). Three ramp towers (:func:`_ramp_tower`) stand against the concourse's edge:
    zigzag ramps of 6-9 runs 1.6-2.2 m wide side by side, 1 in 12, parted only by rails 0.06 m thick (a quarter of
    Recast's cell) and 1.1 m high, so two neighbouring runs stand at the same height at the landing they share and
    2 x 0.83-1.0 m apart at their other end; the last landing joins the concourse. Under the concourse (head room over
    5.6 m) kiosks; on the plaza bollards, kiosks and benches (ridged), a statue; the plaza stops under every closed
    body standing on it (the towers' runs and landings are solid to the ground).

    Expected (written before the first run): one area; each tower a chain of runs joined only at their landings, the
    concourse reached only up the towers. The structure up each tower run by run (one edge or chain a run, a node a
    landing); never across a rail from one run to the next, even at the landing end where their floors meet at the
    same height a rail's thickness apart; never from the plaza straight up to the concourse. Traffic highest on the
    towers (every path to the concourse climbs one) and the concourse between them, lowest in the vomitories and the
    plaza's far corners."""
    rng = np.random.default_rng(seed)
    size_x, deck = float(rng.uniform(110.0, 130.0)), float(rng.uniform(6.0, 8.0))
    north = 60.0  # the concourse from z = north to north + 14
    s = _Solids()
    holes: list[tuple[float, float, float, float]] = []  # the plaza stops under every closed body standing on it
    s.slab(0.0, size_x, north, north + 14.0, deck, [], thickness=0.4)
    x = 4.0
    while x < size_x - 2.0:  # columns under the concourse, kept off its edge by 1 m
        s.box(x - 0.3, x + 0.3, 0.0, deck - 0.4, north + 1.0, north + 1.6)
        s.box(x - 0.3, x + 0.3, 0.0, deck - 0.4, north + 12.0, north + 12.6)
        x += 8.0
    gates = sorted(float(g) for g in rng.uniform(4.0, size_x - 8.0, int(rng.integers(4, 7))))
    kept = [gates[0]]
    for g in gates[1:]:
        if g - kept[-1] > 6.0:
            kept.append(g)
    s.wall((0.0, north + 14.0), (size_x, north + 14.0), deck, deck + 6.0, [(g, 3.0) for g in kept], thickness=0.4)
    s.wall((0.0, north + 14.0), (size_x, north + 14.0), 0.0, deck, thickness=0.4)
    for g in kept:  # each vomitory: a passage 4 m deep into the stands, a dead end
        s.box(g, g + 3.0, deck - 0.4, deck, north + 14.0, north + 18.0)
        for xx in (g - 0.2, g + 3.2):
            s.box(xx - 0.2, xx + 0.2, deck, deck + 3.0, north + 14.0, north + 18.0)
        s.box(g - 0.4, g + 3.4, deck, deck + 3.0, north + 18.0, north + 18.4)
        _ridged(s, g - 0.4, g + 3.4, north + 14.0, north + 18.4, deck + 3.0, deck + 3.2)
    for x_end in (0.0, size_x):
        s.wall((x_end, north), (x_end, north + 14.0), deck, deck + 1.1, thickness=0.1)
    # the towers: each against the concourse's edge, its runs along x, stacking towards the concourse
    spans, rail_gaps = [], []
    for base in np.linspace(6.0, size_x - 22.0, 3):
        x0 = float(base + rng.uniform(0.0, 6.0))
        length, width = float(rng.uniform(10.0, 12.0)), float(rng.uniform(1.6, 2.2))
        runs = math.ceil(deck / (length / 12.0))
        z0 = north - (runs * (width + 0.06) - 0.06)
        holes += _ramp_tower(s, x0, z0, deck, length, width)
        end = x0 + length if runs % 2 == 1 else x0 - 2.0  # the last landing, beyond the last run's top, on to the deck
        s.box(end, end + 2.0, deck - 0.4, deck, north - width, north + 0.5)
        far = end + 2.0 if runs % 2 == 1 else end
        s.box(far - 0.03, far + 0.03, deck, deck + 1.1, north - width, north)
        rail_gaps.append((end, 2.0))
        spans.append((x0 - 2.5, x0 + length + 2.5, z0 - 1.0, north))
    s.wall((0.0, north + 0.05), (size_x, north + 0.05), deck, deck + 1.1, rail_gaps, thickness=0.1)
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(int(rng.integers(3, 5))):  # kiosks and turnstile lines under the concourse
        p = _placed(rng, spots, 2.0, size_x - 2.0, north + 2.0, north + 11.5, 2.0, spans)
        if p is not None:
            holes.append(_ridged(s, p[0] - 1.5, p[0] + 1.5, p[1] - 1.2, p[1] + 1.2, -0.1, 2.5))
    for _ in range(int(rng.integers(14, 22))):  # bollards, benches, kiosks on the plaza
        p = _placed(rng, spots, 0.0, size_x, -8.0, north - 2.0, 1.5, spans)
        if p is None:
            continue
        if rng.random() < 0.5:
            _trunk(s, p, 0.2, -0.1, 0.9)
        elif rng.random() < 0.6:
            _ridged(s, p[0] - 0.8, p[0] + 0.8, p[1] - 0.3, p[1] + 0.3, 0.0, 0.45)
        else:
            holes.append(_ridged(s, p[0] - 1.3, p[0] + 1.3, p[1] - 1.3, p[1] + 1.3, -0.1, 2.6))
    statue = _placed(rng, spots, 10.0, size_x - 10.0, 5.0, north - 12.0, 3.0, spans)
    if statue is not None:
        _trunk(s, statue, 2.0, -0.1, 1.2)
        _trunk(s, statue, 0.6, 1.2, 5.0)
    s.ground(-5.0, size_x + 5.0, -10.0, north + 14.0, 0.0, holes)
    return s.mesh()


def cenote(seed: int) -> trimesh.Trimesh:
    """A cenote (an adventure game's or a tomb raider's): a round sinkhole 14-18 m in radius and 18-24 m deep (drawn)
    in flat jungle ground (y = 0, 100 m square, trees, two huts ridged), its wall 3 m of rock on 64 chords, descended
    by one ledge (2.0-2.6 m wide, drawn per chord: the agent's 1 m plus a metre or so; the drafts' 1.5-2.4 m broke it
    into pieces) that spirals down the wall 1.6-2.0 turns (clockwise or not, drawn) from a notch at the rim to a beach 3 m
    wide round a pool (no floor: the water left out) at the bottom; the ledge's underside slopes back into the wall
    (a shelf). Over the ledge 3-5 overhangs (rock bulging out of the wall, 5-9 m along the ledge) leave it 2.3-2.8
    m of head room (drawn per overhang); 2-3 caves (rooms 5-7 x 4-6 m, 3 m high, mouths two chords wide, each on chords
    of its own round the wall, from a third of the way down) open off the ledge into the rock.

    Expected (written before the first run): one area, the ground, the ledge, the caves and the beach; floor under
    every overhang (head room 2.3 m or more). The structure down the ledge in a spiral chain (a node every few
    chords), a leaf into each cave, a ring round the beach; never across the open pit from one turn of the ledge to
    another or from the rim to the beach, never through the wall into a cave but by its mouth. Traffic highest on
    the ledge's upper turns (every path down passes them), lowest on the beach's far side and in the caves."""
    rng = np.random.default_rng(seed)
    radius, depth = float(rng.uniform(14.0, 18.0)), float(rng.uniform(18.0, 24.0))
    turns, hand = float(rng.uniform(1.6, 2.0)), float(rng.choice([-1.0, 1.0]))
    chords, rock = 64, 3.0
    s = _Solids()
    half = 50.0
    xs = np.arange(-half, half + 0.25, 0.5)
    cx, cz = np.meshgrid((xs[:-1] + xs[1:]) / 2, (xs[:-1] + xs[1:]) / 2, indexing="ij")
    start = float(rng.uniform(0.0, 2 * math.pi))
    steps = round(turns * chords)
    angle = [start + hand * 2 * math.pi * i / chords for i in range(steps + 1)]
    height = [-depth * i / steps for i in range(steps + 1)]
    widths = [float(rng.uniform(2.0, 2.6)) for _ in range(steps)]
    huts = []
    for _ in range(2):
        a = float(rng.uniform(0.0, 2 * math.pi))
        c = (radius + rock + float(rng.uniform(8.0, 20.0))) * np.array([math.cos(a), math.sin(a)])
        huts.append(_ridged(s, c[0] - 2.5, c[0] + 2.5, c[1] - 2.0, c[1] + 2.0, -0.1, 2.4))
    keep = np.hypot(cx, cz) > radius + 0.1
    for b in huts:
        keep &= ~((cx > b[0]) & (cx < b[1]) & (cz > b[2]) & (cz < b[3]))
    _terrain(s, xs, xs, np.zeros((len(xs), len(xs))), keep)

    def on_ring(r: float, a: float) -> np.ndarray:
        return r * np.array([math.cos(a), math.sin(a)])

    # the caves: mouths on chords of the ledge, each a room behind the wall at the ledge's height there
    caves: list[int] = []  # each on chords of its own round the wall (one mouth a chord of the wall)
    for i in rng.permutation(np.arange(steps // 3, steps - 8, 5))[: int(rng.integers(2, 4)) * 3]:
        if len(caves) < 3 and all(abs((int(i) - c + chords // 2) % chords - chords // 2) > 4 for c in caves):
            caves.append(int(i))
    caves.sort()
    cave_chords = {}  # ledge chord index modulo a turn -> the cave's floor (its mouth two chords wide)
    for i in caves:
        cave_chords[i % chords] = cave_chords[(i + 1) % chords] = min(height[i], height[i + 2])
    overhang_at = sorted(int(i) for i in rng.choice(np.arange(4, steps - 8), int(rng.integers(3, 6)), replace=False))
    # the wall: one prism a chord from the bottom to the rim, cut round each cave's mouth
    for j in range(chords):
        a, b = start + 2 * math.pi * j / chords, start + 2 * math.pi * (j + 1) / chords
        plan = np.array([on_ring(radius, a), on_ring(radius + rock, a), on_ring(radius + rock, b), on_ring(radius, b)])
        key = j if hand > 0 else (-j - 1) % chords
        if key in cave_chords:
            floor = cave_chords[key]
            s.prism(plan, -depth - 1.0, floor)
            s.prism(plan, floor + 3.0, 0.0)
        else:
            s.prism(plan, -depth - 1.0, 0.0)
    for i in caves:  # each cave's room, out from its mouth through the rock
        a = angle[i + 1]
        floor = min(height[i], height[i + 2])
        u, v = np.array([math.cos(a), math.sin(a)]), np.array([-math.sin(a), math.cos(a)])
        span, reach = float(rng.uniform(5.0, 7.0)), float(rng.uniform(4.0, 6.0))
        room = [u * (radius + rock) + v * span / 2, u * (radius + rock + reach) + v * span / 2,
                u * (radius + rock + reach) - v * span / 2, u * (radius + rock) - v * span / 2]
        mouth = [u * radius + v * 1.5, u * (radius + rock) + v * 1.5, u * (radius + rock) - v * 1.5, u * radius - v * 1.5]
        s.prism(np.array(room), floor - 0.5, floor)
        s.prism(np.array(mouth), floor - 0.5, floor)
        s.prism(np.array(room), floor + 3.0, -0.6)  # rock up to just under the ground's skirt: no floor on it
    # the ledge: a shelf a chord, its top from height[i] to height[i + 1], its underside sloping back into the wall
    for i in range(steps):
        a, b, w = angle[i], angle[i + 1], widths[i]
        ya, yb = height[i], height[i + 1]
        top = [(on_ring(radius - w, a), ya), (on_ring(radius + 0.5, a), ya), (on_ring(radius - w, b), yb),
               (on_ring(radius + 0.5, b), yb)]
        under = [(on_ring(radius - w, a), ya - 0.4), (on_ring(radius + 0.5, a), ya - 2.0), (on_ring(radius - w, b), yb - 0.4),
                 (on_ring(radius + 0.5, b), yb - 2.0)]
        s.hull(np.array([[p[0], y, p[1]] for p, y in top + under]))
    for i in overhang_at:  # rock bulging out over the ledge, 5-9 m along it, its underside 2.3-2.8 m over it
        n = max(2, round(float(rng.uniform(5.0, 9.0)) / (2 * math.pi * radius / chords)))
        clear = float(rng.uniform(2.3, 2.8))
        for k in range(i, min(i + n, steps)):
            a, b = angle[k], angle[k + 1]
            y0 = max(height[k], height[k + 1]) + clear
            out = min(widths[k], 1.6)
            s.hull(np.array([[p[0], y, p[1]] for p in (on_ring(radius + 0.2, a), on_ring(radius - out, a),
                                                        on_ring(radius + 0.2, b), on_ring(radius - out, b))
                             for y in (y0, y0 + 1.0)] + [[p[0], y0 + 1.0 + (out + 0.2) * RIDGE, p[1]]
                                                        for p in (on_ring(radius + 0.2, a), on_ring(radius + 0.2, b))]))
    ring = np.linspace(0.0, 2 * math.pi, chords + 1)
    for a, b in zip(ring[:-1], ring[1:]):  # the beach round the pool
        s.prism(np.array([on_ring(radius - 3.0, a), on_ring(radius + 0.5, a), on_ring(radius + 0.5, b),
                          on_ring(radius - 3.0, b)]), -depth - 0.5, -depth)
    spots: list[tuple[np.ndarray, float]] = [(np.zeros(2), radius + rock + 3.0)]
    keep_out = [tuple(h) for h in huts]
    for _ in range(int(rng.integers(25, 40))):  # trees on the ground
        p = _placed(rng, spots, -half + 1.0, half - 1.0, -half + 1.0, half - 1.0, 1.0, keep_out)
        if p is not None:
            _trunk(s, p, float(rng.uniform(0.25, 0.5)), -0.1, 8.0)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "attic_row": attic_row, "labyrinth": labyrinth, "hill_fort": hill_fort,
    "subway_roundabout": subway_roundabout, "ramp_towers": ramp_towers, "cenote": cenote,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirty-third round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
