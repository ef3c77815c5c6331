"""Level kinds of the thirty-second held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each about 400-1,200 navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py`` and ``level_kinds30.py`` (imported, not copied): ``sewer_planks`` (walkways beside
channels whose beds lie 1.0-2.0 m lower, crossed on planks 0.7-1.5 m wide, about what the agent needs, drawn per
plank), ``stalactite_cave`` (a cavern whose stalactites hang in patches to tips 1.4-2.6 m over the floor, about the
agent's height), ``ring_tunnels`` (a ring of four straight tunnels 150-190 m long joined by bends, few side rooms: long
lines of sight), ``hangar`` (parked vehicles on a floor and on a mezzanine reached by two flights, a freight lift
shaft open at both levels with no car and no floor but its pit's), ``domus`` (three Roman courtyard houses: an atrium
with a sunk basin, a peristyle whose garden lies 0.45-0.6 m under its colonnade, just over the climb, entered down
its own steps, a fountain) and ``bamboo_grove`` (clumps and single culms 0.06-0.14 m across, narrower than Recast's
cell of 0.25 m, round paths).

Run: ``.venv/bin/python benchmarks/level_kinds32.py OUT_DIR [--kinds hangar domus] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _lid, _ridged, _Solids, _trunk, _wall_line
from level_kinds import main as write_kinds
from level_kinds30 import _placed


def sewer_planks(seed: int) -> trimesh.Trimesh:
    """A storm-relief sewer (a stealth game's or a shooter's) 130-150 m long under a lid 3.6 m over its walkways: 4-5
    channels along x, each 2.4-3.2 m wide with its bed (dry silt, a floor) 1.0-2.0 m under the walkways (drawn per
    channel), between walkways 2.0-2.6 m wide (y = 0); a cross gallery 4 m wide over every channel's end at each end.
    Every 12-20 m along each channel a plank (0.1 m thick, flush with the walkways) crosses it, 0.7-1.5 m wide (drawn
    per plank): about the agent's 1 m across plus the cells Recast rounds off its two drop edges. Under a plank the
    bed has 0.9-1.9 m of head room, under the agent's 2 m, so every plank also cuts its channel's bed; two in three
    stretches of bed between crossings have a flight down (2.0 m wide, against the channel's north wall at the
    stretch's east end, rising east to a landing 1.5 m long, risers at most 0.18 m). Three to six pump rooms (6-8 x 5 m,
    pumps 1.2 m high) off the outer walkways through doors 1.6 m wide.

    Expected (written before the first run): planks of about 1.3 m or more hold floor and join the walkways either
    side, planks of 1.1 m or less hold none (as the twenty-third round's beams); the walkways, galleries and rooms one
    area through the galleries; each stretch of bed with a flight joined to it, each stretch without one an area apart
    (20-60 m², none crossing under a plank), some left out under the cover's smallest area with a warning. The
    structure along the walkways and across the wide planks, never across a channel where no plank holds floor nor
    from a walkway down to a bed but by a flight. Traffic highest on the galleries and the walkways next to the
    widest planks, lowest in the beds and the pump rooms."""
    rng = np.random.default_rng(seed)
    length, channels = float(rng.uniform(130.0, 150.0)), int(rng.integers(4, 6))
    s = _Solids()
    z, walkways, beds = 0.0, [], []
    for k in range(channels + 1):
        w = float(rng.uniform(2.0, 2.6))
        walkways.append((z, z + w))
        z += w
        if k < channels:
            width, depth = float(rng.uniform(2.4, 3.2)), float(rng.uniform(1.0, 2.0))
            beds.append((z, z + width, depth))
            z += width
    z_max, lid = z, 3.6
    for z0, z1 in walkways:
        s.box(-4.0, length + 4.0, -2.5, 0.0, z0, z1)
    for x0, x1 in ((-4.0, 0.0), (length, length + 4.0)):  # the cross galleries over the channels' ends
        s.box(x0, x1, -2.5, 0.0, 0.0, z_max)
    rooms = []
    for z_wall, outward in ((0.0, -1.0), (z_max, 1.0)):  # pump rooms off the outer walkways
        for _ in range(int(rng.integers(2, 4))):
            x = float(rng.uniform(10.0, length - 18.0))
            if any(abs(x - r[0]) < 12.0 for r in rooms):
                continue
            w = float(rng.uniform(6.0, 8.0))
            rooms.append((x, x + w, *sorted((z_wall, z_wall + outward * 5.0))))
    for x0, x1, z0, z1 in rooms:
        s.box(x0, x1, -0.5, 0.0, z0, z1)
        far = z0 if z1 in (0.0, z_max) else z1
        s.wall((x0, far), (x1, far), 0.0, lid, thickness=0.3)
        for x in (x0, x1):
            s.wall((x, z0), (x, z1), 0.0, lid, thickness=0.3)
        for k in range(2):  # pumps
            px = x0 + (k + 1) * (x1 - x0) / 3
            s.box(px - 0.6, px + 0.6, 0.0, 1.2, (z0 + z1) / 2 - 0.6, (z0 + z1) / 2 + 0.6)
    for z_wall in (0.0, z_max):  # the outer walls, open at each room's door
        doors = [(r[0] + 1.0 + 4.0, 1.6) for r in rooms if z_wall in (r[2], r[3])]  # offsets from x = -4
        s.wall((-4.0, z_wall), (length + 4.0, z_wall), -2.5, lid, doors, thickness=0.3)
    for x in (-4.0, length + 4.0):
        s.wall((x, 0.0), (x, z_max), -2.5, lid, thickness=0.3)
    _lid(s, -4.5, length + 4.5, -5.5, z_max + 5.5, lid)
    for z0, z1, depth in beds:
        s.box(0.0, length, -depth - 0.5, -depth, z0, z1)
        crossings = [0.0]
        while crossings[-1] + 20.0 < length - 6.0:
            crossings.append(crossings[-1] + float(rng.uniform(12.0, 20.0)))
        crossings = crossings[1:]
        for x in crossings:
            w = float(rng.uniform(0.7, 1.5))
            s.box(x - w / 2, x + w / 2, -0.1, 0.0, z0, z1)
        steps = math.ceil(depth / 0.18)
        for a, b in zip([0.0, *crossings], [*crossings, length]):  # a flight down into two stretches in three
            if rng.random() < 2 / 3:  # rising east to a landing at the walkway's level 1 m short of the stretch's end
                s.stairs(np.array([b - 2.5 - steps * 0.3, z1 - 1.0]), np.array([1.0, 0.0]), 2.0, -depth, depth,
                         depth / steps, 0.3)
                s.box(b - 2.5, b - 1.0, -depth - 0.3, 0.0, z1 - 2.0, z1)
    return s.mesh()


def stalactite_cave(seed: int) -> trimesh.Trimesh:
    """A show cave's great hall (an adventure game's or a survival game's) 70-85 x 50-60 m, its floor flat (y = 0), its
    ceiling 3.4-3.8 m up (a lid, :func:`level_kinds._lid`), walled: 9-12 patches of stalactites (each 3-7 m in radius,
    12-29 cones hanging from the ceiling, 0.5-1.4 m across at the root) whose tips hang to a height drawn per patch
    about the agent's 2 m (a patch's mean 1.7-2.4 m, each tip within 0.2 m of it as a normal spread, clipped to
    1.4 m-0.5 m under the ceiling), so the head room runs out in some patches and not in others; 4-6 columns (0.8-1.5
    m in radius, floor to ceiling), 20-30 stalagmites (cones 0.3-0.8 m in radius, 0.5-2.5 m high) and 10-15 boulders.
    Two entrances: tunnels 4 m wide, 10 m long, at the west and east walls.

    Expected (written before the first run): one area. No floor under a stalactite whose tip hangs under 2 m, within
    the agent's radius of where its cone passes 2 m; floor under every tip at 2 m or more; a patch of low tips a hole
    of a few square metres or a solid no-go, the structure round it, never under a low tip. Traffic highest between
    the two entrances, lowest in the hall's corners and behind the columns."""
    rng = np.random.default_rng(seed)
    size_x, size_z, ceiling = float(rng.uniform(70.0, 85.0)), float(rng.uniform(50.0, 60.0)), float(rng.uniform(3.4, 3.8))
    s = _Solids()
    door_z = size_z / 2
    s.box(-10.0, size_x + 10.0, -0.5, 0.0, door_z - 2.0, door_z + 2.0)  # the entrance tunnels' floor
    s.box(0.0, size_x, -0.5, 0.0, 0.0, size_z)
    for x in (0.0, size_x):
        s.wall((x, 0.0), (x, size_z), 0.0, ceiling, [(door_z - 2.0, 4.0)], thickness=0.6)
    for z in (0.0, size_z):
        s.wall((-0.3, z), (size_x + 0.3, z), 0.0, ceiling, thickness=0.6)
    for x0, x1 in ((-10.0, -0.3), (size_x + 0.3, size_x + 10.0)):
        for z in (door_z - 2.3, door_z + 2.3):
            s.box(x0, x1, 0.0, ceiling, z - 0.3, z + 0.3)
    _lid(s, -10.0, size_x + 10.0, -0.3, size_z + 0.3, ceiling)
    spots: list[tuple[np.ndarray, float]] = [(np.array([0.0, door_z]), 6.0), (np.array([size_x, door_z]), 6.0)]
    ring = np.linspace(0.0, 2 * math.pi, 8, endpoint=False)
    for _ in range(int(rng.integers(9, 13))):
        radius = float(rng.uniform(3.0, 7.0))
        centre = _placed(rng, spots, 2.0, size_x - 2.0, 2.0, size_z - 2.0, radius, [])
        if centre is None:
            continue
        mean = float(rng.uniform(1.7, 2.4))
        for _ in range(int(rng.integers(12, 30))):
            r, a = radius * math.sqrt(float(rng.random())), float(rng.uniform(0.0, 2 * math.pi))
            p = centre + r * np.array([math.cos(a), math.sin(a)])
            root = float(rng.uniform(0.25, 0.7))
            tip = float(np.clip(rng.normal(mean, 0.2), 1.4, ceiling - 0.5))
            base = p + root * np.stack([np.cos(ring), np.sin(ring)], 1)
            s.hull(np.vstack([np.insert(base, 1, ceiling + 0.05, axis=1), [[p[0], tip, p[1]]]]))
    for _ in range(int(rng.integers(4, 7))):  # columns, floor to ceiling
        radius = float(rng.uniform(0.8, 1.5))
        p = _placed(rng, spots, 3.0, size_x - 3.0, 3.0, size_z - 3.0, radius + 1.5, [])
        if p is not None:
            _trunk(s, p, radius, -0.1, ceiling + 0.05)
    for _ in range(int(rng.integers(20, 31))):  # stalagmites
        radius = float(rng.uniform(0.3, 0.8))
        p = _placed(rng, spots, 1.0, size_x - 1.0, 1.0, size_z - 1.0, radius + 0.6, [])
        if p is not None:
            base = p + radius * np.stack([np.cos(ring), np.sin(ring)], 1)
            top = float(rng.uniform(0.5, 2.5))
            s.hull(np.vstack([np.insert(base, 1, -0.05, axis=1), [[p[0], top, p[1]]]]))
    for _ in range(int(rng.integers(10, 16))):  # boulders, under 1 m short of the ceiling
        p = _placed(rng, spots, 2.0, size_x - 2.0, 2.0, size_z - 2.0, 1.2, [])
        if p is not None:
            s.rock(rng, p, 0.5, -0.1, 1.4)
    return s.mesh()


def _band(s: _Solids, line: np.ndarray, left: float, right: float, y0: float, y1: float,
          gaps: set[int] = frozenset()) -> None:
    """Prisms between offsets ``left`` and ``right`` (metres, left of the direction of travel positive) of the closed
    plan polyline ``line`` (n, 2), between heights y0 < y1, over every piece of the line but the pieces in ``gaps``
    (indices): one prism a run of pieces along one direction (a straight cut into pieces, a run broken by a gap or a
    turn). Corners are mitred (the bisector of the two pieces' normals, scaled so that each piece's offset stays
    parallel to it). O(n)."""
    n = len(line)
    ahead = np.roll(line, -1, axis=0) - line
    ahead /= np.linalg.norm(ahead, axis=1, keepdims=True)
    normal = np.stack([-ahead[:, 1], ahead[:, 0]], 1)
    mitre = normal + np.roll(normal, 1, axis=0)  # at vertex i, between piece i - 1 and piece i
    mitre /= np.einsum("ij,ij->i", mitre, normal)[:, None]
    kept = [i for i in range(n) if i not in gaps]
    runs: list[list[int]] = []
    for i in kept:  # consecutive kept pieces of one direction join a run
        if runs and runs[-1][-1] == i - 1 and float(ahead[i] @ ahead[i - 1]) > 1.0 - 1e-9:
            runs[-1].append(i)
        else:
            runs.append([i])
    for run in runs:
        i, j = run[0], (run[-1] + 1) % n
        s.prism(np.array([line[i] + mitre[i] * left, line[j] + mitre[j] * left,
                          line[j] + mitre[j] * right, line[i] + mitre[i] * right]), y0, y1)


def ring_tunnels(seed: int) -> trimesh.Trimesh:
    """A service ring (a shooter's metro loop or a research facility's ring) of four straight tunnels, 160-190 m
    along x and 150-170 m along z (centre lines), joined by bends of 14-20 m radius (12 pieces each), 4.5-5.5 m wide
    (drawn per seed), walls 0.4 m thick, all under one lid 4.2 m up: every straight a line of sight of 120-160 m.
    Pieces of about 2 m along the straights; 3-4 side rooms (14-20 x 10-14 m, ridged machinery in them) off the
    straights' outer walls through openings 4 m wide, at most one a straight; crates and carts (ridged, 1.2 x 2-3 m)
    against either wall (drawn) in about one piece in three, none within two pieces of another; a cable trench's cover (0.25 m high, 0.8 m wide) along the
    inner wall of each straight.

    Expected (written before the first run): one area. The structure a loop round the ring, one node or a chain along
    each straight, a leaf into each room; never through the ring's inner wall (the middle holds nothing). Traffic
    spread round the loop (two ways round between any two rooms), highest on the straights between the rooms, lowest
    in the rooms' far corners."""
    rng = np.random.default_rng(seed)
    along_x, along_z = float(rng.uniform(160.0, 190.0)), float(rng.uniform(150.0, 170.0))
    bend, width = float(rng.uniform(14.0, 20.0)), float(rng.uniform(4.5, 5.5))
    hx, hz = along_x / 2 - bend, along_z / 2 - bend  # the bends' centres at (+-hx, +-hz)
    line: list[np.ndarray] = []
    straights: list[tuple[int, int, np.ndarray]] = []  # (first piece, last piece + 1, outward normal)
    for k, (cx, cz) in enumerate(((hx, -hz), (hx, hz), (-hx, hz), (-hx, -hz))):
        a0 = -math.pi / 2 + k * math.pi / 2  # the bend turns counter-clockwise from a0 to a0 + 90 degrees
        for a in np.linspace(a0, a0 + math.pi / 2, 13):
            line.append(np.array([cx + bend * math.cos(a), cz + bend * math.sin(a)]))
        nxt = ((hx, hz), (-hx, hz), (-hx, -hz), (hx, -hz))[k]
        end = np.array(nxt) + bend * np.array([math.cos(a0 + math.pi / 2), math.sin(a0 + math.pi / 2)])
        start = line[-1]
        pieces = max(1, round(float(np.linalg.norm(end - start)) / 2.0))
        first = len(line) - 1
        for t in np.linspace(0.0, 1.0, pieces + 1)[1:-1]:
            line.append(start + (end - start) * t)
        straights.append((first, first + pieces, np.array([math.cos(a0 + math.pi / 2), math.sin(a0 + math.pi / 2)])))
    plan = np.array(line)
    s = _Solids()
    half, wall, lid = width / 2, 0.4, 4.2
    rooms, doors = [], set()
    for k in rng.permutation(4)[: int(rng.integers(3, 5))]:
        first, last, out = straights[k]
        mid = (first + last) // 2 + int(rng.integers(-(last - first) // 4, (last - first) // 4 + 1))
        doors |= {mid, mid + 1}
        centre = plan[(mid + 1) % len(plan)]
        depth, span = float(rng.uniform(10.0, 14.0)), float(rng.uniform(14.0, 20.0))
        along = np.array([-out[1], out[0]])
        inner = centre + out * half  # the room's floor starts under the tunnel's outer wall, through its opening
        rooms.append((inner, along, out, span, depth))
    _band(s, plan, -half, half, -0.5, 0.0)  # the floor; left of travel (counter-clockwise) is the ring's inside
    _band(s, plan, half, half + wall, 0.0, lid)
    _band(s, plan, -half - wall, -half, 0.0, lid, doors)
    _band(s, plan, half - 0.8, half, 0.0, 0.25, set(range(len(plan))) - {i for f, l, _ in straights
                                                                           for i in range(f, l)})
    for inner, along, out, span, depth in rooms:
        corners = [inner + along * span / 2, inner - along * span / 2,
                   inner - along * span / 2 + out * depth, inner + along * span / 2 + out * depth]
        s.prism(np.array(corners), -0.5, 0.0)
        far = inner + out * depth
        _wall_line(s, far + along * (span / 2 + wall), far - along * (span / 2 + wall), 0.0, lid, wall, [])
        for sign in (1.0, -1.0):
            _wall_line(s, inner + sign * along * span / 2, far + sign * along * span / 2, 0.0, lid, wall, [])
        for k in range(int(rng.integers(2, 5))):  # machinery, ridged
            c = inner + out * float(rng.uniform(4.0, depth - 3.0)) + along * float(rng.uniform(-span / 2 + 3.0, span / 2 - 3.0))
            if abs(float((c - inner) @ along)) < 3.0 and float((c - inner) @ out) < 6.0:
                continue
            if abs(along[0]) > 0.5:
                _ridged(s, c[0] - 1.2, c[0] + 1.2, c[1] - 1.0, c[1] + 1.0, 0.0, 1.8)
            else:
                _ridged(s, c[0] - 1.0, c[0] + 1.0, c[1] - 1.2, c[1] + 1.2, 0.0, 1.8)
    for first, last, out in straights:  # crates and carts against alternate walls
        along, last_crate = np.array([-out[1], out[0]]), -10
        for i in range(first + 1, last - 1):
            if i in doors or i - 1 in doors or i + 1 in doors or i - last_crate < 3 or rng.random() > 1 / 3:
                continue
            last_crate = i
            side = -1.0 if rng.random() < 0.5 else 1.0  # -1: the outer wall, 1: the inner (over the trench)
            c = (plan[i] + plan[i + 1]) / 2 - out * side * (half - 0.9 - (0.8 if side > 0 else 0.0))
            size = float(rng.uniform(2.0, 3.0)) / 2
            ext = np.abs(along) * size + np.abs(out) * 0.6
            _ridged(s, c[0] - ext[0], c[0] + ext[0], c[1] - ext[1], c[1] + ext[1], 0.0, 1.3)
    margin = half + wall + 16.0
    _lid(s, -along_x / 2 - margin, along_x / 2 + margin, -along_z / 2 - margin, along_z / 2 + margin, lid)
    return s.mesh()


def hangar(seed: int) -> trimesh.Trimesh:
    """A maintenance hangar (a heist's or a shooter's) 70-80 x 48-55 m, walls 12 m under a ridged lid, its door 20-28
    m wide onto an apron 25 m deep; a mezzanine 9-11 m deep along the north wall (its floor 4.5 m up, on columns every
    6 m, railed 1.1 m high) reached by two straight flights (2.2 m wide, 25 risers of 0.18 m, landing 2.2 m) along its
    edge; a freight lift shaft 3.6 x 4.2 m through the mezzanine, walled 0.3 m, with no car and no floor but its pit's,
    1.4 m under the hangar's floor: a door 3 m wide at the ground on its south side (a drop into the pit) and one on
    its west side at the mezzanine (a drop of 5.9 m). Parked on the floor 12-16 vans and lorries (ridged, 2.2-2.8 x
    5-9 m, 2.0-3.2 m to the eaves; two in five tool carts of 1 x 1.6 m) and up to three light aircraft (fuselages ridged 1.4 m wide, wings 0.15 m thick 2.2-2.6 m
    up, 10-12 m span, on two legs); on the mezzanine 3-4 vans (brought up by the lift) and rows of crates (ridged); under
    the mezzanine workbenches 0.9 m high and 0.7 m deep; on the apron a fuel bowser and tugs.

    Expected (written before the first run): the floor, the apron, the flights and the mezzanine one area; the lift
    pit apart (under 14 m² of floor after the agent's radius, left out under the cover's smallest area and named in a
    warning, or an area of its own), and so each wing's top (an island out of reach, seen on the draft's polygon
    count); nothing joins the mezzanine to the pit or the floor through the shaft. Floor
    under the wings (head room 2.05-2.45 m over the wing's thickness), none on the benches. The structure round the
    parked vehicles and up each flight, never through the shaft's walls nor over the rail's edge. Traffic highest
    between the door and the flights' feet, then along the mezzanine between the flights' heads."""
    rng = np.random.default_rng(seed)
    size_x, size_z, mezz = float(rng.uniform(70.0, 80.0)), float(rng.uniform(48.0, 55.0)), float(rng.uniform(9.0, 11.0))
    height, deck = 12.0, 4.5
    edge = size_z - mezz
    shaft_x = float(rng.uniform(size_x * 0.4, size_x * 0.6))
    shaft = (shaft_x, shaft_x + 3.6, edge + 1.0, edge + 5.2)
    s = _Solids()
    door_w = float(rng.uniform(20.0, 28.0))
    door_x = float(rng.uniform(8.0, size_x - 8.0 - door_w))
    holes = [shaft]  # the ground stops under the shaft and under every closed body on it (their insides no floor)
    s.box(shaft[0], shaft[1], -1.9, -1.4, shaft[2], shaft[3])  # the pit's floor
    s.wall((0.0, 0.0), (size_x, 0.0), 0.0, height, [(door_x, door_w)], thickness=0.4)
    s.box(door_x, door_x + door_w, 8.0, height, -0.2, 0.2)  # over the door
    s.wall((0.0, size_z), (size_x, size_z), 0.0, height, thickness=0.4)
    for x in (0.0, size_x):
        s.wall((x, -0.2), (x, size_z + 0.2), 0.0, height, thickness=0.4)
    _lid(s, -0.2, size_x + 0.2, -0.2, size_z + 0.2, height)
    s.slab(0.2, size_x - 0.2, edge, size_z - 0.2, deck, [shaft])
    # the shaft's walls from the pit up to 2.5 m over the deck, open over each door
    s.wall((shaft[0], shaft[2]), (shaft[1], shaft[2]), -1.9, deck + 2.5, [(0.3, 3.0)], thickness=0.3)
    s.box(shaft[0] + 0.3, shaft[0] + 3.3, 3.0, deck + 2.5, shaft[2] - 0.15, shaft[2] + 0.15)  # over the ground door
    s.wall((shaft[0], shaft[3]), (shaft[1], shaft[3]), -1.9, deck + 2.5, thickness=0.3)
    s.wall((shaft[1], shaft[2]), (shaft[1], shaft[3]), -1.9, deck + 2.5, thickness=0.3)
    s.wall((shaft[0], shaft[2]), (shaft[0], shaft[3]), -1.9, deck, thickness=0.3)
    s.wall((shaft[0], shaft[2]), (shaft[0], shaft[3]), deck, deck + 2.5, [(0.6, 3.0)], thickness=0.3)
    x = 3.0
    while x < size_x - 1.0:  # columns under the mezzanine's edge
        s.box(x - 0.25, x + 0.25, 0.0, deck - 0.3, edge + 0.1, edge + 0.6)
        x += 6.0
    steps, run = 25, 25 * 0.28
    flights = [float(rng.uniform(6.0, shaft_x - run - 6.0)), float(rng.uniform(shaft[1] + 6.0, size_x - run - 4.0))]
    rail_gaps = []
    for fx in flights:  # each flight along the edge, rising east to a landing in front of the edge
        s.stairs(np.array([fx, edge - 1.2]), np.array([1.0, 0.0]), 2.2, 0.0, deck, deck / steps, 0.28)
        s.box(fx + run, fx + run + 2.2, deck - 0.3, deck, edge - 2.3, edge)
        s.box(fx - 0.1, fx + run, 0.0, deck + 1.1, edge - 2.4, edge - 2.3)  # the flight's outer rail
        rail_gaps.append((fx + run - 0.4, 2.6))  # offsets from x = 0.2
    s.wall((0.2, edge + 0.05), (size_x - 0.2, edge + 0.05), deck, deck + 1.1, rail_gaps, thickness=0.1)
    spots: list[tuple[np.ndarray, float]] = []
    keep = [(shaft[0] - 3.0, shaft[1] + 3.0, shaft[2] - 5.0, shaft[3]), (door_x, door_x + door_w, -1.0, 6.0)]
    keep += [(fx - 1.0, fx + run + 3.0, edge - 3.5, edge) for fx in flights]
    for _ in range(3):  # light aircraft: a fuselage along x, wings across it over the agent's head
        p = _placed(rng, spots, 8.0, size_x - 8.0, 8.0, edge - 4.0, 7.0, keep)
        if p is None:
            continue
        holes.append(_ridged(s, p[0] - 4.0, p[0] + 4.0, p[1] - 0.7, p[1] + 0.7, 0.0, 1.6))
        wing, span = float(rng.uniform(2.2, 2.6)), float(rng.uniform(5.0, 6.0))
        s.box(p[0] - 0.6, p[0] + 1.0, wing - 0.15, wing, p[1] - span, p[1] + span)
        for side in (-1.0, 1.0):
            s.box(p[0] - 0.1, p[0] + 0.1, 0.0, wing - 0.15, p[1] + side * 1.8 - 0.1, p[1] + side * 1.8 + 0.1)
    for _ in range(int(rng.integers(12, 17))):  # vans, lorries and tool carts on the floor
        w, l = (float(rng.uniform(2.2, 2.8)), float(rng.uniform(5.0, 9.0))) if rng.random() < 0.6 else (1.0, 1.6)
        p = _placed(rng, spots, 4.0, size_x - 4.0, 2.0, edge - 2.0, l / 2 + 0.8, keep)
        if p is not None:
            holes.append(_ridged(s, p[0] - l / 2, p[0] + l / 2, p[1] - w / 2, p[1] + w / 2, 0.0,
                                 float(rng.uniform(2.0, 3.2))))
    upper: list[float] = []
    taken = [(shaft[0] - 3.5, shaft[1] + 3.5)] + [(fx + run - 3.5, fx + run + 4.5) for fx in flights]
    for _ in range(int(rng.integers(3, 5))):  # vans on the mezzanine, a row 2.4-4.6 m behind its edge
        for _ in range(30):
            x = float(rng.uniform(3.0, size_x - 3.0))
            if not any(a < x < b for a, b in taken) and all(abs(x - u) > 6.0 for u in upper):
                upper.append(x)
                _ridged(s, x - 2.5, x + 2.5, edge + 2.4, edge + 4.6, deck, deck + 2.2)
                break
    x = 1.0
    while x < size_x - 4.0:  # crates along the north wall upstairs, benches along it downstairs
        if not shaft[0] - 2.0 < x < shaft[1] + 1.0:
            _ridged(s, x, x + 2.4, size_z - 1.6, size_z - 0.3, deck, deck + 1.8)
            s.box(x, x + 2.4, 0.0, 0.9, size_z - 0.9, size_z - 0.2)
        x += float(rng.uniform(3.5, 6.0))
    holes.append(_ridged(s, door_x + 2.0, door_x + 10.0, -16.0, -13.5, 0.0, 2.6))  # a fuel bowser on the apron, tugs
    for k in range(3):
        holes.append(_ridged(s, door_x + 14.0 + 4.0 * k, door_x + 16.5 + 4.0 * k, -9.0, -7.5, 0.0, 1.2))
    s.ground(-10.0, size_x + 10.0, -25.0, size_z, 0.0, holes)
    return s.mesh()


def _domus_house(s: _Solids, rng: np.random.Generator, x0: float, width: float, depth: float) -> None:
    """One house of :func:`domus` over [x0, x0 + width] x [0, depth + 6] (its front on z = 0): see there. O(rooms +
    columns) solids."""
    wall, high = 0.4, 4.5
    x1, mid = x0 + width, x0 + width / 2
    side = 7.0  # the depth of the rooms either side of the atrium
    sunk = float(rng.uniform(0.45, 0.6))
    garden = (x0 + 3.4, x1 - 3.4, 26.4, depth - 3.4)
    basin = (mid - 1.75, mid + 1.75, 9.0, 11.5)
    s.ground(x0, x1, 0.0, depth + 6.0, 0.0, [garden, basin], thickness=0.8)
    s.box(*basin[:2], -0.8, -0.3, *basin[2:])  # the impluvium, 0.3 m down (a step)
    s.box(*garden[:2], -sunk - 0.5, -sunk, *garden[2:])
    # outer walls: the front with its door (the fauces), the back
    s.wall((x0, 0.0), (x1, 0.0), 0.0, high, [(1.5, 3.0), (width / 2 - 1.0, 2.0), (width - 4.5, 3.0)], thickness=wall)
    s.wall((x0, depth + 6.0), (x1, depth + 6.0), 0.0, high, thickness=wall)
    for x in (x0, x1):
        s.wall((x, 0.0), (x, depth + 6.0), 0.0, high, thickness=wall)
    for x in (x0 + side, x1 - side):  # cubicula either side of the atrium, three a side, each a door onto it
        cuts = np.linspace(3.0, 18.0, 4)
        s.wall((x, 0.0), (x, 18.0), 0.0, high, [(c + 1.0, 1.6) for c in cuts[:-1]], thickness=wall)
        lo, hi = (x0, x) if x < mid else (x, x1)
        for c in cuts:
            s.wall((lo, c), (hi, c), 0.0, high, thickness=wall)
        for a, b in zip(cuts[:-1], cuts[1:]):  # a bed or a chest against the room's outer wall
            bx = lo + 0.3 if x < mid else hi - 1.2
            s.box(bx, bx + 0.9, 0.0, 0.6, a + 0.6, a + 2.6)
    # the tablinum's wall line at z = 18 and the peristyle's at z = 23: wide openings in the middle, andrones beside
    s.wall((x0 + side, 18.0), (x1 - side, 18.0), 0.0, high, [(width / 2 - side - 2.0, 4.0)], thickness=wall)
    s.wall((x0, 23.0), (x1, 23.0), 0.0, high, [(side - 2.2, 1.6), (width / 2 - 2.0, 4.0), (width - side + 0.6, 1.6)],
           thickness=wall)
    for x in (x0 + side, x1 - side):  # each andron's door from the tablinum
        s.wall((x, 18.0), (x, 23.0), 0.0, high, [(1.7, 1.6)], thickness=wall)
    # the peristyle: columns on the stylobate's edge (the garden 0.45-0.6 m down), steps down at the middle of two sides
    gx0, gx1, gz0, gz1 = garden
    flight_w, riser = 1.6, sunk / 2
    flights = [(mid, gz0, 1.0), (mid, gz1, -1.0)]
    for fx, fz, inward in flights:  # two risers into the garden
        s.stairs(np.array([fx, fz + inward * 0.7]), np.array([0.0, -inward]), flight_w, -sunk, sunk, riser, 0.35)
    spacing = float(rng.uniform(2.2, 2.6))
    for a, b, fixed, along_x in ((gx0, gx1, gz0, True), (gx0, gx1, gz1, True), (gz0, gz1, gx0, False), (gz0, gz1, gx1, False)):
        n = max(2, round((b - a) / spacing) + 1)
        for q in np.linspace(a, b, n):
            if along_x and abs(q - mid) < flight_w / 2 + 0.5:
                continue
            _trunk(s, np.array([q, fixed] if along_x else [fixed, q]), 0.25, -0.1, high)
    # the garden: a fountain's basin (its water a flat top 0.5 m over the garden, its jet a column), four beds
    gm = np.array([mid, (gz0 + gz1) / 2])
    radius = float(rng.uniform(1.5, 2.2))
    _trunk(s, gm, radius, -sunk - 0.1, -sunk + 0.5)
    _trunk(s, gm, 0.25, -sunk + 0.5, -sunk + 1.8)
    for sx in (-1.0, 1.0):
        for sz in (-1.0, 1.0):
            cx, cz = gm[0] + sx * (radius + 3.0), gm[1] + sz * (radius + 2.0)
            _ridged(s, cx - 1.8, cx + 1.8, cz - 1.2, cz + 1.2, -sunk - 0.1, -sunk + 0.4)  # hedged beds
    # rooms off the peristyle's back: a triclinium between two smaller rooms, doors onto the portico
    s.wall((x0, depth), (x1, depth), 0.0, high, [(side - 2.0, 1.6), (width / 2 - 1.5, 3.0), (width - side + 0.4, 1.6)],
           thickness=wall)
    for x in (x0 + side, x1 - side):
        s.wall((x, depth), (x, depth + 6.0), 0.0, high, thickness=wall)
    for k in range(3):  # the triclinium's three couches
        cx = mid + (k - 1) * 2.4
        s.box(cx - 0.9, cx + 0.9, 0.0, 0.7, depth + 4.0, depth + 5.6)


def domus(seed: int) -> trimesh.Trimesh:
    """Three Roman town houses side by side on a street (a historical adventure's or an assassination game's), each
    22-26 m wide and 44-50 m deep plus a row of rooms 6 m deep at its back, walls 0.4 m thick and 4.5 m high, roofs left
    out: a front door 2 m wide (the fauces) between two shops open to the street (3 m) into an atrium with a sunk basin (the impluvium, 3.5 x 2.5 m, 0.3 m down:
    a step one walks into), three cubicula either side each through its own door 1.6 m wide, the tablinum (openings
    4 m wide from the atrium and to the peristyle) and beside it two andrones (doors 1.6 m) to a peristyle: a portico 3.4 m deep round a garden that lies 0.45-0.6 m under
    it (drawn per house: just over the 0.4 m climb), on whose stylobate's edge columns 0.5 m across stand every 2.2-2.6
    m, the garden reached only by two steps of half that height, 1.6 m wide, in the middle of its south and north
    sides; in the garden four hedged beds (ridged) and a fountain whose basin (1.5-2.2 m in radius) stands 0.5 m over
    the garden, its water a flat top out of reach. At the back a triclinium (couches) and two rooms through doors onto
    the portico. The street (12 m, y = 0) before the houses has a public fountain, stalls and a shop front (ridged).

    Expected (written before the first run): one area, the street, the houses and their gardens; each garden joined to
    its portico through its two flights only, never across the stylobate's edge between columns; each basin's water an
    island of a few square metres out of reach, left out under the cover's smallest area and named in a warning. The
    structure a leaf into each cubiculum, a loop round each portico with spurs down the steps into the garden, a chain
    from each front door through the atrium and tablinum; never through a column or up the stylobate. Traffic highest
    on the street between the doors and along each house's axis from its door to the garden, lowest in the
    cubicula and the gardens' corners."""
    rng = np.random.default_rng(seed)
    s = _Solids()
    widths = [float(rng.uniform(22.0, 26.0)) for _ in range(3)]
    depth = float(rng.uniform(44.0, 50.0))
    x0 = 0.0
    for width in widths:
        _domus_house(s, rng, x0, width, depth)
        x0 += width
    total = x0
    s.box(-10.0, total + 10.0, -0.8, 0.0, -12.0, 0.0)  # the street, up to the houses' fronts
    _trunk(s, np.array([total / 2, -6.0]), 1.2, -0.1, 0.8)
    spots: list[tuple[np.ndarray, float]] = [(np.array([total / 2, -6.0]), 2.5)]
    for _ in range(6):
        q = _placed(rng, spots, -8.0, total + 8.0, -10.5, -1.5, 1.4, [])
        if q is not None:
            s.box(q[0] - 1.0, q[0] + 1.0, -0.1, 0.9, q[1] - 0.5, q[1] + 0.5)
    _ridged(s, -10.0, -1.0, -12.0 - 8.0, -12.0, 0.0, 4.0)
    return s.mesh()


def bamboo_grove(seed: int) -> trimesh.Trimesh:
    """A bamboo grove (a samurai game's or an open-world RPG's) 80-95 x 60-70 m on flat ground, fenced 1.2 m high but
    at a gate in each short side: 60-90 clumps (each 0.8-2.2 m in radius, 8-24 culms) and 150-230 single culms,
    every culm an octagonal post 0.06-0.14 m across (under Recast's cell of 0.25 m) and 6-10 m tall, kept off two or
    three paths 2.0-2.6 m wide that wind from gate to gate and side to side (each a polyline of five points); a
    shrine (ridged, on a stone base 0.3 m high, steps) in a clearing 10 m across, 6-10 stone lanterns (1.6 m), a
    bench or two.

    Expected (written before the first run): one area. Every culm, though narrower than a cell, a hole in the floor of
    about the agent's radius round it; a clump a solid no-go; between single culms floor wherever they stand more
    than the agent's 1 m plus a cell apart. The structure along the paths and through the open stands, never
    through a clump; traffic highest on the paths between the gates, lowest deep in the stands."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(80.0, 95.0)), float(rng.uniform(60.0, 70.0))
    s = _Solids()
    s.box(-0.5, size_x + 0.5, -0.5, 0.0, -0.5, size_z + 0.5)
    gates = [np.array([0.0, float(rng.uniform(0.3, 0.7)) * size_z]), np.array([size_x, float(rng.uniform(0.3, 0.7)) * size_z])]
    for x, g in ((0.0, gates[0]), (size_x, gates[1])):
        s.wall((x, 0.0), (x, size_z), 0.0, 1.2, [(g[1] - 1.5, 3.0)], thickness=0.1)
    for z in (0.0, size_z):
        s.wall((0.0, z), (size_x, z), 0.0, 1.2, thickness=0.1)
    clearing = np.array([float(rng.uniform(0.35, 0.65)) * size_x, float(rng.uniform(0.35, 0.65)) * size_z])
    paths = [np.array([gates[0], *[[size_x * t, float(rng.uniform(0.2, 0.8)) * size_z] for t in (0.25, 0.5, 0.75)],
                       gates[1]])]
    for _ in range(int(rng.integers(1, 3))):
        a = np.array([float(rng.uniform(0.2, 0.8)) * size_x, 0.0])
        paths.append(np.array([a, *[[float(rng.uniform(0.2, 0.8)) * size_x, size_z * t] for t in (0.25, 0.5)], clearing,
                               [float(rng.uniform(0.2, 0.8)) * size_x, size_z]]))
    widths = [float(rng.uniform(2.0, 2.6)) for _ in paths]

    def on_path(p: np.ndarray, margin: float) -> bool:
        """Whether plan point p lies within a path's half width plus ``margin`` of its line, or in the clearing."""
        if np.linalg.norm(p - clearing) < 5.0 + margin:
            return True
        for line, w in zip(paths, widths):
            a, b = line[:-1], line[1:]
            t = np.clip(np.einsum("ij,ij->i", p - a, b - a) / np.einsum("ij,ij->i", b - a, b - a), 0.0, 1.0)
            if np.min(np.linalg.norm(a + (b - a) * t[:, None] - p, axis=1)) < w / 2 + margin:
                return True
        return False

    unit = _Solids()
    _trunk(unit, np.zeros(2), 1.0, 0.0, 1.0)  # one octagonal prism, scaled and moved for every culm (one hull)
    template = unit.parts[0]

    def culm(p: np.ndarray) -> None:
        radius, top = float(rng.uniform(0.03, 0.07)), float(rng.uniform(6.0, 10.0))
        s.parts.append(template.copy().apply_transform(
            trimesh.transformations.translation_matrix([p[0], -0.1, p[1]]) @ np.diag([radius, top + 0.1, radius, 1.0])))

    for _ in range(int(rng.integers(60, 91))):
        radius = float(rng.uniform(0.8, 2.2))
        c = np.array([float(rng.uniform(1.0, size_x - 1.0)), float(rng.uniform(1.0, size_z - 1.0))])
        if on_path(c, radius):
            continue
        for _ in range(int(rng.integers(8, 25))):
            r, a = radius * math.sqrt(float(rng.random())), float(rng.uniform(0.0, 2 * math.pi))
            culm(c + r * np.array([math.cos(a), math.sin(a)]))
    for _ in range(int(rng.integers(150, 231))):
        p = np.array([float(rng.uniform(0.5, size_x - 0.5)), float(rng.uniform(0.5, size_z - 0.5))])
        if not on_path(p, 0.2):
            culm(p)
    shrine = _ridged(s, clearing[0] - 1.8, clearing[0] + 1.8, clearing[1] - 1.2, clearing[1] + 1.2, -0.1, 2.4)
    s.slab(clearing[0] - 2.5, clearing[0] + 2.5, clearing[1] - 2.0, clearing[1] + 2.0, 0.3, [shrine], thickness=0.4)
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(int(rng.integers(6, 11))):  # stone lanterns beside the paths
        pick = int(rng.integers(len(paths)))
        line = paths[pick]
        k = int(rng.integers(len(line) - 1))
        t = float(rng.uniform(0.2, 0.8))
        p = line[k] + (line[k + 1] - line[k]) * t
        ahead = (line[k + 1] - line[k]) / np.linalg.norm(line[k + 1] - line[k])
        q = p + np.array([-ahead[1], ahead[0]]) * (widths[pick] / 2 + 0.6)
        if all(np.linalg.norm(q - c) > 2.0 for c, _ in spots):
            spots.append((q, 0.4))
            s.box(q[0] - 0.3, q[0] + 0.3, -0.1, 1.0, q[1] - 0.3, q[1] + 0.3)
            _ridged(s, q[0] - 0.4, q[0] + 0.4, q[1] - 0.4, q[1] + 0.4, 1.0, 1.3)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "sewer_planks": sewer_planks, "stalactite_cave": stalactite_cave, "ring_tunnels": ring_tunnels,
    "hangar": hangar, "domus": domus, "bamboo_grove": bamboo_grove,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirty-second round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
