"""Level kinds of the thirty-fourth held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each a few hundred navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py`` and ``level_kinds30.py`` (imported, not copied), as ``level_kinds33.py`` is:
``turned_wings`` (houses round a yard, each turned 10-40 degrees off the grid, their doors 1.5-1.7 m wide at those
angles), ``gap_roofs`` (a parkour block whose neighbouring roofs stand 0.3-0.6 m apart, about one to two of Recast's
cells, or share a wall), ``gangway_quay`` (ships moored at 15-30 degrees to a quay, boarded by railed gangways at 15-30
degrees to the quay's normal), ``scree_cave`` (a cave of chambers on floors tilted 5-20 degrees, joined by passages
sloping 10-30 degrees, one shortcut cut by a scree at 50-55 degrees; pillars 0.25-3 m in radius), ``track_beds`` (a
station whose track beds, walkable ballast 1.2 m under the platforms, are reached only down ramps at the platforms' west
ends) and ``expo_hall`` (a trade-fair hall: 140-164 booths 3 m deep on seeds 0-2, each a dead-end bay, beside an open
floor and a stage).

Run: ``.venv/bin/python benchmarks/level_kinds34.py OUT_DIR [--kinds gap_roofs expo_hall] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _lid, _ridged, _Solids, _strip, _terrain, _trunk, _wall_line
from level_kinds import main as write_kinds
from level_kinds30 import _placed


def _yawed(parts: list[trimesh.Trimesh], yaw_deg: float, at: np.ndarray) -> list[trimesh.Trimesh]:
    """``parts`` turned by ``yaw_deg`` about the vertical through the plan origin, then moved to plan point ``at``
    (x, z); in place, returned. The plan point (x, z) goes where :func:`_yaw_point` sends it."""
    turn = trimesh.transformations.rotation_matrix(math.radians(yaw_deg), [0.0, 1.0, 0.0])
    turn[0, 3], turn[2, 3] = float(at[0]), float(at[1])
    for part in parts:
        part.apply_transform(turn)
    return parts


def _yaw_point(p: np.ndarray, yaw_deg: float, at: np.ndarray) -> np.ndarray:
    """Plan point ``p`` (x, z) turned and moved as :func:`_yawed` turns and moves a solid."""
    c, s = math.cos(math.radians(yaw_deg)), math.sin(math.radians(yaw_deg))
    return np.array([c * p[0] + s * p[1], -s * p[0] + c * p[1]]) + at  # a turn about +y maps z -> x as +sin


def _house(rng: np.random.Generator) -> tuple[_Solids, float, float]:
    """One house of :func:`turned_wings` in its own frame, its front wall on z = 0, its rooms in a row along +x: see
    there. Returns the solids, its length along x and its depth along z. O(rooms) solids."""
    rooms = int(rng.integers(2, 4))
    widths = [float(rng.uniform(7.0, 10.0)) for _ in range(rooms)]
    depth = float(rng.uniform(7.0, 9.5))
    edges = np.concatenate([[0.0], np.cumsum(widths)])
    length = float(edges[-1])
    s = _Solids()
    s.box(-0.15, length + 0.15, -0.4, 0.15, -0.15, depth + 0.15)  # the floor slab, a sill of 0.15 m over the yard
    front = [(float(rng.uniform(edges[k] + 0.8, edges[k + 1] - 2.5)), float(rng.uniform(1.5, 1.7)))
             for k in range(rooms) if k == 0 or rng.random() < 0.4]  # a door into the first room, maybe others
    s.wall((0.0, 0.0), (length, 0.0), 0.15, 3.0, front, thickness=0.3)
    s.wall((0.0, depth), (length, depth), 0.15, 3.0, thickness=0.3)
    for k, x in enumerate(edges):
        if 0 < k < rooms:  # the partition between rooms k - 1 and k, one door 1.5-1.7 m wide
            width = float(rng.uniform(1.5, 1.7))
            s.wall((float(x), 0.0), (float(x), depth), 0.15, 3.0, [(float(rng.uniform(0.8, depth - 0.8 - width)), width)],
                   thickness=0.3)
        else:
            s.wall((float(x), 0.0), (float(x), depth), 0.15, 3.0, thickness=0.3)
    for k in range(rooms):  # a table (ridged: no floor on it) and a cupboard against the back wall
        cx = float(rng.uniform(edges[k] + 2.2, edges[k + 1] - 2.2))
        cz = float(rng.uniform(2.8, depth - 2.8))
        _ridged(s, cx - 0.9, cx + 0.9, cz - 0.45, cz + 0.45, 0.15, 0.9)
        bx = float(rng.uniform(edges[k] + 1.6, edges[k + 1] - 2.8))  # 1.3 m or more from a partition's door
        _ridged(s, bx, bx + 1.2, depth - 0.75, depth - 0.15, 0.15, 1.9)
    return s, length, depth


def turned_wings(seed: int) -> trimesh.Trimesh:
    """A yard of houses none of which is square to the grid (a village in an action game, a compound in a shooter, as
    level designers lay them out by eye): a yard of packed earth 120 x 120 m (y = 0), walled 2.5 m high round its edge
    with a gate 4 m wide in each side, holding up to 9-11 houses (as many as fit 3 m apart; walls 0.3 m thick, 2.85 m
    high over their floors, no roofs, as a top-down game draws them), each *turned by 10-40 degrees (either way, drawn
    per house) off the yard's grid*. A house is 2-3 rooms in a row (7-10 m wide each, drawn per room; 7-9.5 m deep,
    drawn per house) on a floor slab 0.15 m over the yard (a sill under the climb); *every door 1.5-1.7 m wide* (the
    agent's 1 m plus 0.5-0.7 m, drawn per door), one into the first room from the front, each later room's own front
    door with a chance of 0.4, and one door through each partition. Each room holds a table and a cupboard (ridged: no
    floor on them). In the yard 12-20 crates and a well.

    Expected (written before the first run): one area; every room reached through its doors, the doors held open
    whatever their angle to Recast's grid (the thirty-third round's labyrinth lost corridors of 1.75 m at angles to
    the grid until ``erosion: joined``; these doors are 0.3 m deep, not corridors). The structure reaches every house
    through a front door, a chain through each house's rooms door by door with a leaf into its last room; never
    through a wall, however the house is turned. Traffic highest across the yard between the gates, then through
    the first rooms of the houses with more than one front door (a way through); lowest in the last rooms."""
    rng = np.random.default_rng(seed)
    size = 120.0
    s = _Solids()
    holes: list[tuple[float, float, float, float]] = []
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(int(rng.integers(9, 12))):
        house, length, depth = _house(rng)
        reach = math.hypot(length, depth) / 2
        at = _placed(rng, spots, 6.0, size - 6.0, 6.0, size - 6.0, reach + 3.0, [])
        if at is None:
            continue
        yaw = float(rng.choice([-1.0, 1.0]) * rng.uniform(10.0, 40.0))
        for part in house.parts:  # about the house's centre
            part.apply_translation([-length / 2, 0.0, -depth / 2])
        s.parts += _yawed(house.parts, yaw, at)
    for _ in range(int(rng.integers(12, 21))):  # crates in the yard
        p = _placed(rng, spots, 3.0, size - 3.0, 3.0, size - 3.0, 1.0, [])
        if p is not None:
            holes.append(_ridged(s, p[0] - 0.6, p[0] + 0.6, p[1] - 0.6, p[1] + 0.6, -0.1, 1.2))
    well = _placed(rng, spots, 10.0, size - 10.0, 10.0, size - 10.0, 2.0, [])
    if well is not None:
        _trunk(s, well, 1.0, -0.1, 0.9)
    s.ground(0.0, size, 0.0, size, 0.0, holes)
    for a, b in (((0.0, 0.0), (size, 0.0)), ((0.0, size), (size, size)), ((0.0, 0.0), (0.0, size)),
                 ((size, 0.0), (size, size))):
        s.wall(a, b, 0.0, 2.5, [(float(rng.uniform(20.0, size - 24.0)), 4.0)], thickness=0.4)
    return s.mesh()


def gap_roofs_plan(seed: int) -> dict:
    """The plan of :func:`gap_roofs` for ``seed``: rows (each a list of (x0, x1, height)), the rows' z spans, and the
    roofs a walking agent joins (``areas``: lists of (row, index), the street's first). Joined: two roofs of a row
    that share a wall (no gap) and differ by at most 0.35 m; a roof with a flight is joined to the street. O(roofs)."""
    rng = np.random.default_rng(seed)
    n_rows = int(rng.integers(4, 6))
    rows, spans, z = [], [], 0.0
    height = 4.5
    for _ in range(n_rows):
        depth = float(rng.uniform(7.0, 10.0))
        x, roofs = 0.0, []
        for k in range(int(rng.integers(6, 9))):
            if k:
                x += 0.0 if rng.random() < 0.45 else float(rng.uniform(0.3, 0.6))  # a shared wall or a gap
                step = float(rng.uniform(0.05, 0.35)) if rng.random() < 0.7 else float(rng.uniform(0.6, 1.2))
                height = float(np.clip(height + float(rng.choice([-1.0, 1.0])) * step, 3.0, 7.0))
            width = float(rng.uniform(7.0, 11.0))
            roofs.append((x, x + width, height))
            x += width
        rows.append(roofs)
        spans.append((z, z + depth))
        z += depth + float(rng.uniform(0.3, 0.6))  # every pair of rows a gap apart
        height = float(rng.uniform(3.5, 6.0))
    parent = {(r, k): (r, k) for r, roofs in enumerate(rows) for k in range(len(roofs))}
    parent["street"] = "street"

    def root(a):
        while parent[a] != a:
            a = parent[a]
        return a

    for r, roofs in enumerate(rows):
        for k in range(1, len(roofs)):
            if abs(roofs[k][0] - roofs[k - 1][1]) < 1e-9 and abs(roofs[k][2] - roofs[k - 1][2]) <= 0.35:
                parent[root((r, k))] = root((r, k - 1))
    flights = [(0, 0), (n_rows - 1, len(rows[-1]) - 1)]
    for f in flights:
        parent[root(f)] = root("street")
    groups: dict = {}
    for a in parent:
        groups.setdefault(root(a), []).append(a)
    areas = sorted(groups.values(), key=lambda g: ("street" not in g, min(str(x) for x in g)))
    return {"rows": rows, "spans": spans, "flights": flights, "areas": areas,
            "gaps": sum(1 for roofs in rows for k in range(1, len(roofs)) if roofs[k][0] > roofs[k - 1][1] + 1e-9)}


def gap_roofs(seed: int) -> trimesh.Trimesh:
    """A parkour course over one city block (a free-running game's, an assassin's): 4-5 rows along x of 6-8 flat-roofed
    buildings (7-11 m wide along x, each row 7-10 m deep), the roofs 3-7 m up; along a row two neighbours share a wall
    (a chance of 0.45) or *stand 0.3-0.6 m apart* (a gap of one to two of Recast's 0.25 m cells, under the agent's
    1 m stride), each roof 0.05-0.35 m over or under the last (a step under the 0.4 m climb, a chance of 0.7) or
    0.6-1.2 m (clamped to 3-7 m); *every pair of rows stands 0.3-0.6 m apart*. On the roofs air-conditioning units
    and stair huts (ridged). A street 12 m wide round the block (y = 0) with two flights 1.8 m wide from it, up to
    the west end of the first row and the east end of the last.

    Expected (written before the first run; the areas come from :func:`gap_roofs_plan`, which joins only roofs that
    share a wall and differ by at most 0.35 m): a player of the game crosses every gap (a step over 0.3 m, a stride or
    a hop over 0.6 m), so one area; a walking agent on the navmesh crosses none, so the navmesh's areas are the plan's
    (the street with the two runs of roofs its flights reach, the rest of the roofs in runs apart), and the
    disconnected-areas warning should name a gap a designer would bridge (a plank, an off-mesh link), the two
    places about 0.3-0.6 m apart at the same height. Whether Recast's 0.25 m cells see a gap of 0.3 m at all is open
    (a gap under two cells may be filled by the voxels either side). The structure never across a gap; within a run
    a chain along it."""
    plan = gap_roofs_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    s = _Solids()
    holes = []
    for (z0, z1), roofs in zip(plan["spans"], plan["rows"]):
        for x0, x1, h in roofs:
            s.box(x0, x1, -0.1, h, z0, z1)
            holes.append((x0, x1, z0, z1))
            for _ in range(int(rng.integers(0, 3))):  # an air-conditioning unit or a stair hut, ridged
                w, d = float(rng.uniform(1.0, 2.5)), float(rng.uniform(1.0, 2.0))
                cx, cz = float(rng.uniform(x0 + 1.0, x1 - 1.0 - w)), float(rng.uniform(z0 + 1.0, z1 - 1.0 - d))
                _ridged(s, cx, cx + w, cz, cz + d, h, h + float(rng.uniform(1.0, 2.4)))
    for r, k in plan["flights"]:  # a flight from the street up to the roof's outer end along x, 1.8 m wide
        x0, x1, h = plan["rows"][r][k]
        z0, z1 = plan["spans"][r]
        run = h / 0.2 * 0.3
        if k == 0:
            start, heading = np.array([x0 - run, (z0 + z1) / 2]), np.array([1.0, 0.0])
        else:
            start, heading = np.array([x1 + run, (z0 + z1) / 2]), np.array([-1.0, 0.0])
        s.stairs(start, heading, 1.8, 0.0, h, 0.2, 0.3)
        lo, hi = sorted((float(start[0]), float(start[0] + heading[0] * run)))
        holes.append((lo, hi, (z0 + z1) / 2 - 0.9, (z0 + z1) / 2 + 0.9))
    x_max = max(roofs[-1][1] for roofs in plan["rows"])
    z_max = plan["spans"][-1][1]
    s.ground(-18.0, x_max + 18.0, -12.0, z_max + 12.0, 0.0, holes)
    return s.mesh()


def _ship(rng: np.random.Generator, length: float, beam: float, deck: float, gangway_at: float,
          opening: float) -> _Solids:
    """One ship of :func:`gangway_quay` in its own frame: stern at x = 0, bow at x = ``length``, the beam across z
    (-beam / 2 to beam / 2), its main deck at ``deck``, its +z side's rail open over ``opening`` m about
    ``gangway_at`` m from the stern. A raised foredeck 1.4 m up a flight, an engine casing (ridged), hatches and crates
    (ridged), rails 1.1 m high and 0.06 m thick. O(1) solids."""
    s = _Solids()
    half = beam / 2
    plan = np.array([[0.0, -half], [0.82 * length, -half], [length, 0.0], [0.82 * length, half], [0.0, half]])
    house = float(rng.uniform(6.0, 8.0))
    aft = 1.5 + house  # the engine casing over x 1.5 to aft, |z| under 0.3 beam
    # the hull, solid from under the water line to the main deck, its deck stopping under the casing (Recast reads
    # surfaces: the deck inside a closed body with head room over it would be floor)
    s.prism(np.array([[aft, -half], [0.82 * length, -half], [length, 0.0], [0.82 * length, half], [aft, half]]),
            -6.0, deck)
    s.box(0.0, 1.5, -6.0, deck, -half, half)
    for z0, z1 in ((-half, -0.3 * beam), (0.3 * beam, half)):
        s.box(1.5, aft, -6.0, deck, z0, z1)
    fore = 0.78 * length  # the foredeck from here forward, 1.4 m up
    s.prism(np.array([[fore, -half], [0.82 * length, -half], [length, 0.0], [0.82 * length, half], [fore, half]]),
            deck, deck + 1.4)
    s.stairs(np.array([fore - 7 * 0.3, 0.0]), np.array([1.0, 0.0]), 2.4, deck, 1.4, 0.2, 0.3)
    for side in (-1.0, 1.0):  # the foredeck's aft edge railed either side of the flight
        _wall_line(s, np.array([fore, side * 1.2]), np.array([fore, side * half]), deck + 1.4, deck + 2.5, 0.06, [])
    edges = list(zip(plan, np.roll(plan, -1, axis=0)))
    for a, b in edges:  # the rails along the deck's edge, 0.05 m in
        inward = -0.05 * np.sign(a[1] + b[1]) if abs(a[1] + b[1]) > 1e-9 else 0.05
        p, q = a + np.array([0.0, inward]), b + np.array([0.0, inward])
        top = deck + 1.4 if min(p[0], q[0]) >= fore - 1e-9 else deck
        gaps = []
        if a[1] == half and b[1] == half and top == deck:  # the +z side runs from the bow's shoulder to the stern
            gaps = [(0.82 * length - gangway_at - opening / 2, opening)]
        if min(p[0], q[0]) < fore < max(p[0], q[0]):  # a side along the foredeck's edge: two pieces
            mid = p + (q - p) * (fore - p[0]) / (q[0] - p[0])
            near, far = (p, q) if p[0] < fore else (q, p)
            _wall_line(s, near, mid, deck, deck + 1.1, 0.06, gaps)
            _wall_line(s, mid, far, deck + 1.4, deck + 2.5, 0.06, [])
        else:
            _wall_line(s, p, q, top, top + 1.1, 0.06, gaps)
    _ridged(s, 1.5, aft, -0.3 * beam, 0.3 * beam, deck - 0.1, deck + 2.6)  # the engine casing
    x = 1.5 + house + 3.0
    while x + 4.0 < fore - 3.0:  # hatches along the centreline, a crate or two beside them
        _ridged(s, x, x + 4.0, -0.2 * beam, 0.2 * beam, deck, deck + 0.8)
        if rng.random() < 0.6:
            cz = float(rng.choice([-1.0, 1.0])) * (0.2 * beam + 1.6)
            _ridged(s, x + 0.5, x + 1.7, cz - 0.6, cz + 0.6, deck, deck + 1.2)
        x += float(rng.uniform(6.0, 8.0))
    return s


def gangway_quay(seed: int) -> trimesh.Trimesh:
    """A ferry terminal's quay (a harbour in an open-world game, a smuggling mission): a quay 200 m along x and 20 m
    deep (y = 0, its face on z = 0, the water south of it left out: no floor), with sheds (ridged), bollards and
    containers, and 4 ships moored off it *each turned 15-30 degrees to the quay's face* (either way), 32-40 m long,
    9-12 m in beam, their main decks 1.5-2.6 m over the quay (drawn per ship), the nearest corner 3-5 m off the face.
    Each ship: a raised foredeck 1.4 m up a flight 2.4 m wide, an engine casing, hatches and crates (ridged), rails 1.1
    m high and 0.06 m thick round every deck edge. Each ship is boarded by *one gangway 1.8-2.2 m wide, railed 1 m high
    on both sides, running from the quay at 15-30 degrees to the quay's normal* (either way) to an opening in the ship's
    near rail, at 12-22 degrees of slope; so the gangway meets the ship's side and the quay's face at odd angles, its
    rails at 15-30 degrees to both.

    Expected (written before the first run): one area, the quay and every ship's two decks on it, each ship reached
    only up its gangway and its foredeck only up its flight. The structure up each gangway to a node on its deck, a
    chain along each deck round its hatches, a leaf onto each foredeck; never across the water from the quay to a
    deck, never through a rail but at its opening. Traffic highest on the quay between the gangways' feet, then on the
    gangways (every path to a ship climbs one); lowest on the foredecks."""
    rng = np.random.default_rng(seed)
    s = _Solids()
    quay_x, quay_z = 200.0, 20.0
    holes: list[tuple[float, float, float, float]] = []
    feet: list[float] = []  # the gangways' feet (x)
    for k in range(4):
        length, beam = float(rng.uniform(32.0, 40.0)), float(rng.uniform(9.0, 12.0))
        deck = float(rng.uniform(1.5, 2.6))
        yaw = float(rng.choice([-1.0, 1.0]) * rng.uniform(15.0, 30.0))
        tilt = float(rng.choice([-1.0, 1.0]) * rng.uniform(15.0, 30.0))  # the gangway's angle to the quay's normal
        slope = math.radians(float(rng.uniform(12.0, 22.0)))
        run = deck / math.tan(slope)  # the gangway's plan length
        gangway_at = float(rng.uniform(0.35, 0.5)) * length  # from the bow's shoulder aft along the near side
        width = float(rng.uniform(1.8, 2.2))
        # the ship's frame: its near side (+z in its frame) faces the quay; place it so the gangway's top lands on it
        centre_x = 25.0 + 50.0 * k
        probe = _yaw_point(np.array([0.82 * length - gangway_at, beam / 2]), yaw, np.zeros(2))
        heading = np.array([math.sin(math.radians(tilt)), 1.0 * math.cos(math.radians(tilt))])  # from deck to quay
        top = np.array([centre_x, -run * heading[1]])  # the gangway's top on the ship, its foot on the quay's face
        at = top - probe
        corners = [_yaw_point(np.array(c), yaw, at) for c in ((0.0, beam / 2), (0.82 * length, beam / 2), (length, 0.0))]
        nearest = max(c[1] for c in corners)  # the corner nearest the quay (largest z)
        if nearest > -3.0:  # keep 3-5 m of water between the ship and the quay: push the ship out, the gangway longer
            shift = nearest + float(rng.uniform(3.0, 5.0))
            at = at - np.array([0.0, shift])
            top = top - np.array([0.0, shift])
        foot = top + heading * (-top[1] / heading[1] + 1.0)  # a metre onto the quay
        feet.append(float(foot[0]))
        along_side = _yaw_point(np.array([1.0, 0.0]), yaw, np.zeros(2))
        meet = abs(float(along_side[0] * heading[1] - along_side[1] * heading[0]))  # sine of its angle to the side
        ship = _ship(rng, length, beam, deck, gangway_at, width / max(meet, 0.3) + 1.0)
        s.parts += _yawed(ship.parts, yaw, at)
        top_in = top - heading * 0.6  # the gangway's top 0.6 m in over the deck
        s.ramp(top_in, foot, width, deck, 0.0, thickness=0.25)
        side = np.array([-heading[1], heading[0]]) * (width / 2 + 0.04)
        for sgn in (-1.0, 1.0):  # its rails: sloped hulls 0.08 m thick, 1 m over the gangway from the ship's side
            rail = _strip(top + sgn * side, foot - heading * 0.6 + sgn * side, 0.08)
            end = deck * 0.6 / float(np.linalg.norm(foot - top))  # the gangway's height 0.6 m short of its foot
            s.hull(np.array([[p[0], y + lift, p[1]] for p, y in zip(rail, (deck, end, end, deck)) for lift in (0.0, 1.0)]))
    # the quay: sheds along its back, bollards along its face, containers
    x = 4.0
    while x < quay_x - 24.0:
        w = float(rng.uniform(14.0, 20.0))
        holes.append(_ridged(s, x, x + w, quay_z - 7.0, quay_z - 1.0, -0.1, 5.0))
        x += w + float(rng.uniform(6.0, 10.0))
    for bx in np.arange(6.0, quay_x - 3.0, 12.0):  # bollards, none within 3 m of a gangway's foot
        if all(abs(float(bx) - f) > 3.0 for f in feet):
            _trunk(s, np.array([float(bx), 0.7]), 0.25, -0.1, 0.6)
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(int(rng.integers(8, 13))):
        p = _placed(rng, spots, 4.0, quay_x - 4.0, 4.0, quay_z - 8.5, 2.0, [])
        if p is not None:
            holes.append(_ridged(s, p[0] - 3.0, p[0] + 3.0, p[1] - 1.2, p[1] + 1.2, -0.1, 2.6))
    s.ground(-2.0, quay_x + 2.0, 0.0, quay_z, 0.0, holes)
    return s.mesh()


def scree_cave(seed: int) -> trimesh.Trimesh:
    """A cave whose floors are never level (an adventure game's, a survival game's) under a lid (:func:`_lid`), ground
    on a 0.5 m grid (:func:`_terrain`) 112 x 106 m: 12-15 chambers (discs 6-9 m in radius) on a jittered 5 x 3 lattice,
    *each chamber's floor a plane tilted 5-20 degrees* (drawn per chamber); passages 3.5-5 m wide along a spanning tree
    of the lattice's neighbours *whose centre lines slope 10-30 degrees* from one chamber's mouth to the next (the
    chambers' heights set down the tree so), meeting each chamber's plane across their width, and one more passage
    between two lattice neighbours not on the tree (the pair whose mouths' heights differ most), *level from one
    chamber's mouth to a scree rising or falling at 50-55 degrees* (over the agent's 45) to the other's; pillars 0.25-3
    m in radius (8-sided, floor to rock, drawn) standing on the slopes, 2-4 a chamber. Rock rises outside the open plan
    to 1 m under the lid (no agent fits on it).

    Expected (written before the first run): one area; every chamber reached along the tree's passages, the scree
    no way between its two chambers (a dead end from the flat side, its foot or top; a chamber joined only through it
    would be apart, but every chamber is on the tree), floor on every tilted chamber and sloping passage. The
    structure along the tree's passages and round the pillars, never up or down the scree; a leaf into the scree
    passage's flat end at most. Traffic highest on the tree's passages near its middle, lowest in the leaf
    chambers."""
    rng = np.random.default_rng(seed)
    size_x, size_z, cell = 112.0, 106.0, 0.5
    xs, zs = np.arange(0.0, size_x + cell / 2, cell), np.arange(0.0, size_z + cell / 2, cell)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    lattice = [(i, j) for i in range(5) for j in range(3)]
    keep = sorted(int(k) for k in rng.choice(15, int(rng.integers(12, 16)), replace=False))
    kept = [lattice[k] for k in keep]
    centres = np.array([[12.0 + 22.0 * i + float(rng.uniform(-2.5, 2.5)), 17.0 + 36.0 * j + float(rng.uniform(-2.5, 2.5))]
                        for i, j in kept])
    radii = rng.uniform(6.0, 9.0, len(kept))
    n = len(kept)
    near = [(a, b) for a in range(n) for b in range(a + 1, n)
            if abs(kept[a][0] - kept[b][0]) + abs(kept[a][1] - kept[b][1]) == 1]
    # a spanning tree of the lattice neighbours (random order, union-find); chambers not joined by neighbours are
    # joined to their nearest joined chamber
    parent = list(range(n))

    def root(a: int) -> int:
        while parent[a] != a:
            a = parent[a]
        return a

    tree, extra = [], []
    for e in rng.permutation(len(near)):
        a, b = near[int(e)]
        if root(a) != root(b):
            parent[root(a)] = root(b)
            tree.append((a, b))
        else:
            extra.append((a, b))
    for a in range(n):
        if root(a) != root(0):
            b = min((b for b in range(n) if root(b) == root(0)), key=lambda b: np.linalg.norm(centres[a] - centres[b]))
            parent[root(a)] = root(0)
            tree.append((a, b))
    tilt = np.radians(rng.uniform(5.0, 20.0, n))
    facing = rng.uniform(0.0, 2 * math.pi, n)
    grade = np.tan(tilt)[:, None] * np.stack([np.cos(facing), np.sin(facing)], 1)  # each chamber plane's gradient
    height = np.full(n, np.nan)  # each chamber plane's height at its centre
    height[0] = 0.0

    def plane(i: int, p: np.ndarray) -> np.ndarray:
        """Chamber i's floor plane at plan points ``p`` (..., 2)."""
        return height[i] + (p - centres[i]) @ grade[i]

    def mouths(a: int, b: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, float]:
        """The passage from a to b: its unit direction, its mouths (where its centre line crosses each chamber's
        edge) and their distances t0, t1 from a's centre."""
        along = (centres[b] - centres[a]) / np.linalg.norm(centres[b] - centres[a])
        t0, t1 = float(radii[a]), float(np.linalg.norm(centres[b] - centres[a]) - radii[b])
        return along, centres[a] + along * t0, centres[a] + along * t1, t0, t1

    while np.isnan(height).any():  # chamber heights down the tree: each passage's centre line slopes 10-30 degrees
        for a, b in tree:
            for u, v in ((a, b), (b, a)):
                if not np.isnan(height[u]) and np.isnan(height[v]):
                    _, mu, mv, t0, t1 = mouths(u, v)
                    rise = float(rng.choice([-1.0, 1.0])) * (t1 - t0) * math.tan(math.radians(rng.uniform(10.0, 30.0)))
                    height[v] = float(plane(u, mu)) + rise - float((mv - centres[v]) @ grade[v])
    cells = np.stack([gx, gz], -1)
    floor = np.full(gx.shape, np.nan)
    for i, (c, r) in enumerate(zip(centres, radii)):
        disc = np.hypot(gx - c[0], gz - c[1]) < r
        floor = np.where(disc & np.isnan(floor), plane(i, cells), floor)

    def passage(a: int, b: int, scree: bool) -> None:
        """The floor of the passage from chamber a's mouth to chamber b's, 3.5-5 m wide, meeting each chamber's
        plane across its width: a straight slope, or with ``scree`` level with a's mouth to a slope of 50-55
        degrees up or down to b's."""
        along, _, _, t0, t1 = mouths(a, b)
        half = float(rng.uniform(1.75, 2.5))
        t = (gx - centres[a][0]) * along[0] + (gz - centres[a][1]) * along[1]
        across = np.abs(-(gx - centres[a][0]) * along[1] + (gz - centres[a][1]) * along[0])
        inside = (across < half) & (t > t0 - 1.0) & (t < t1 + 1.0) & np.isnan(floor)  # and the crescents by the mouths
        ya = plane(a, cells - (t - t0)[..., None] * along)  # a's plane on the mouth's line, level with the cell
        yb = plane(b, cells + (t1 - t)[..., None] * along)
        if scree:
            steep = math.tan(math.radians(float(rng.uniform(50.0, 55.0))))
            ahead = np.maximum(t1 - t, 0.0)
            y = np.where(ahead > np.abs(yb - ya) / steep, ya, yb - np.sign(yb - ya) * ahead * steep)
        else:
            u = np.clip((t - t0) / (t1 - t0), 0.0, 1.0)
            y = ya + (yb - ya) * u
        floor[inside] = y[inside]

    def floor_at(p: np.ndarray) -> float:
        i, j = int(round(p[0] / cell)), int(round(p[1] / cell))
        return float(floor[i, j])

    for a, b in tree:
        passage(a, b, False)
    if extra:  # the scree on the passage between the two lattice neighbours off the tree whose heights differ most
        a, b = max(extra, key=lambda e: abs(float(plane(e[0], mouths(*e)[1]) - plane(e[1], mouths(*e)[2]))))
        passage(a, b, True)
    rock = float(np.nanmax(floor)) + 4.0
    s = _Solids()
    a8 = np.linspace(0, 2 * math.pi, 8, endpoint=False)
    for c, r in zip(centres, radii):  # pillars on the chambers' slopes, 0.25-3 m in radius
        for _ in range(int(rng.integers(2, 5))):
            pr = float(rng.uniform(0.25, 3.0))
            reach = r - pr - 1.6
            if reach <= 0.5:
                continue
            ang, dist = float(rng.uniform(0.0, 2 * math.pi)), float(rng.uniform(0.0, reach))
            p = c + dist * np.array([math.cos(ang), math.sin(ang)])
            s.prism(np.stack([p[0] + pr * np.cos(a8), p[1] + pr * np.sin(a8)], 1), floor_at(p) - 3.0, rock)
            # the ground inside a pillar is rock too (Recast reads surfaces: ground inside a solid with head room
            # over it would be floor)
            floor[np.hypot(gx - p[0], gz - p[1]) < pr - cell] = rock
    _terrain(s, xs, zs, np.where(np.isnan(floor), rock, floor))
    _lid(s, 0.0, size_x, 0.0, size_z, rock + 1.0)
    return s.mesh()


def track_beds(seed: int) -> trimesh.Trimesh:
    """A country station (a shooter's, a stealth game's) of four tracks and three platforms 160-200 m long along x
    (drawn), their tops at y = 0: a side platform 5 m wide, two tracks, an island platform 8 m wide, two tracks, a side
    platform 5 m wide, each pair of tracks in a bed 9.2 m wide of *walkable ballast 1.2 m under the platforms* (three
    times the climb: a drop a player takes, no step back up), rails 0.15 m high. The ballast runs 30 m past the
    platforms at both ends (the track field, y = -1.2); *each platform's west end is a ramp 2 m wide down to it at 1
    in 8* (a barrow crossing's ramp), its east end a plain drop. A footbridge 6 m over the platforms at the middle
    (a deck 3 m wide, railed, a flight 2 m wide up from each platform). On the platforms benches (ridged), lamp posts
    and bins every 9-13 m, a waiting room (ridged) on each side platform; in the beds a standing train (ridged,
    60-100 m long, on a track drawn) and relay cabinets (ridged) along the beds' edges.

    Expected (written before the first run): one area: each bed and the track field reached down the ramps, each
    platform from the others by the footbridge or through the track field; the platforms' long edges walls to a
    walking agent (a player drops down them: not a navmesh way). The structure along each platform and each bed,
    joined at the ramps and the footbridge; never across a platform's long edge between a platform and a bed (1.2 m
    apart in height), never through the train. Traffic highest along the platforms towards the footbridge and the
    ramps, lowest at the beds' east ends."""
    rng = np.random.default_rng(seed)
    length = float(rng.uniform(160.0, 200.0))
    s = _Solids()
    bed_y, field = -1.2, 30.0
    platforms = [(0.0, 5.0), (14.2, 22.2), (31.4, 36.4)]  # (z0, z1) of the side, island and side platforms
    beds = [(5.0, 14.2), (22.2, 31.4)]
    tracks = [z0 + off for z0, _ in beds for off in (2.3, 6.9)]
    holes: list[tuple[float, float, float, float]] = []
    ramp_len = 1.2 * 8.0
    rooms = []  # the waiting rooms on the side platforms (x0, x1, z0, z1); the platforms stop under them
    for z0, z1 in (platforms[0], platforms[2]):
        wx = float(rng.uniform(15.0, length / 2 - 30.0))
        zb = z0 if z0 == 0.0 else z1 - 2.5
        rooms.append(_ridged(s, wx, wx + 10.0, zb, zb + 2.5, -0.1, 3.0))
    for z0, z1 in platforms:
        s.slab(0.0, length, z0, z1, 0.0, rooms, thickness=1.5)
        zc = (z0 + z1) / 2
        s.ramp(np.array([0.0, zc]), np.array([-ramp_len, zc]), 2.0, 0.0, bed_y, thickness=0.4)
        holes.append((0.0, length, z0, z1))
    for zt in tracks:  # rails 0.15 m high, 1.435 m apart
        for off in (-0.72, 0.72):
            s.box(-field, length + field, bed_y - 0.1, bed_y + 0.15, zt + off - 0.035, zt + off + 0.035)
    train_track = float(rng.choice(tracks))
    t0 = float(rng.uniform(10.0, length - 110.0))
    t1 = t0 + float(rng.uniform(60.0, 100.0))
    holes.append(_ridged(s, t0, t1, train_track - 1.5, train_track + 1.5, bed_y - 0.1, bed_y + 3.8))
    for z0, z1 in beds:  # relay cabinets along the beds' edges
        for _ in range(int(rng.integers(3, 6))):
            cx = float(rng.uniform(-field + 3.0, length + field - 3.0))
            if t0 - 2.0 < cx < t1 + 2.0:
                continue
            cz = z0 + 0.6 if rng.random() < 0.5 else z1 - 1.2
            holes.append(_ridged(s, cx - 0.8, cx + 0.8, cz, cz + 0.6, bed_y - 0.1, bed_y + 1.5))
    s.ground(-field - ramp_len, length + field, -6.0, 42.4, bed_y, holes)
    mid = length / 2
    deck = 6.0
    s.box(mid - 1.5, mid + 1.5, deck - 0.3, deck, -1.0, 37.4)  # the footbridge's deck, from over the south platform
    tops = [1.5, 18.2, 34.9]  # each flight's centre line (z): beside the south, on the island's, beside the north
    s.wall((mid - 1.5, -1.0), (mid - 1.5, 37.4), deck, deck + 1.1, [(z + 1.0 - 1.1, 2.2) for z in tops], thickness=0.1)
    s.wall((mid + 1.5, -1.0), (mid + 1.5, 37.4), deck, deck + 1.1, thickness=0.1)
    for z in (-1.0, 37.4):
        s.box(mid - 1.5, mid + 1.5, deck, deck + 1.1, z - 0.05, z + 0.05)
    run = deck / 0.17 * 0.28
    for zc in tops:  # a flight up from each platform, its top against the deck's west side
        s.stairs(np.array([mid - 1.5 - run, zc]), np.array([1.0, 0.0]), 2.0, 0.0, deck, 0.17, 0.28)
    for z0, z1 in platforms:  # benches, lamp posts and bins
        x = float(rng.uniform(3.0, 8.0))
        while x < length - 3.0:
            if not (mid - 1.5 - run - 1.0 < x < mid + 2.5):
                zc = (z0 + z1) / 2 + float(rng.uniform(-0.5, 0.5)) * (z1 - z0 - 2.5)
                pick = rng.random()
                if pick < 0.4:
                    _ridged(s, x - 0.9, x + 0.9, zc - 0.25, zc + 0.25, 0.0, 0.45)
                elif pick < 0.8:
                    _trunk(s, np.array([x, zc]), 0.12, -0.1, 4.0)
                else:
                    _trunk(s, np.array([x, zc]), 0.3, -0.1, 0.9)
            x += float(rng.uniform(9.0, 13.0))
    return s.mesh()


def expo_hall(seed: int) -> trimesh.Trimesh:
    """A trade-fair hall (a shooter's convention-centre map, a heist's exhibition): a hall 84-96 x 54-60 m (drawn),
    walls 6 m high with 4 doors 3 m wide (two in the west wall, two in the east), under no roof. Its west 58-64 % is
    *a grid of booths*: blocks of two rows of 5-7 booths back to back (each booth 3 m wide and 3 m deep, walled
    2.5 m high at its back and sides, 0.1 m thick, open to its aisle: a dead-end bay of about 3 x 3 m), blocks 2-3
    along x with cross aisles 3 m wide, aisles 3 m wide between block rows; in a booth a counter (ridged) with a
    chance of 0.5. The rest is *an open floor*: a stage 1 m high (ridged at its back, a flight of 5 steps up its
    front), a seating block (rows of chairs 0.9 m apart: no way between them) and a few pillars (0.4 m in radius).

    Expected (written before the first run): one area, every booth reached from its aisle (its bay 2.9 m wide
    inside: the agent's 1 m with 0.95 m either side), the stage up its steps. The structure a grid along the aisles
    with the booths left to the cover radius (a booth 3 m deep within 6 m of an aisle node), few leaves into the
    booths; the open floor a few nodes. Traffic highest along the aisles between the doors and across the open
    floor, lowest in the booths and on the stage: most polygons (the booths' bays) carry little area and little
    traffic, a few big ones (the open floor) much."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(84.0, 96.0)), float(rng.uniform(54.0, 60.0))
    booths_x = size_x * float(rng.uniform(0.58, 0.64))
    s = _Solids()
    holes: list[tuple[float, float, float, float]] = []
    doors_w = sorted(float(z) for z in rng.uniform(6.0, size_z - 9.0, 2))
    doors_e = sorted(float(z) for z in rng.uniform(6.0, size_z - 9.0, 2))
    if doors_w[1] - doors_w[0] < 4.0:
        doors_w[1] = doors_w[0] + 4.0
    if doors_e[1] - doors_e[0] < 4.0:
        doors_e[1] = doors_e[0] + 4.0
    s.wall((0.0, 0.0), (0.0, size_z), 0.0, 6.0, [(z, 3.0) for z in doors_w], thickness=0.4)
    s.wall((size_x, 0.0), (size_x, size_z), 0.0, 6.0, [(z, 3.0) for z in doors_e], thickness=0.4)
    s.wall((0.0, 0.0), (size_x, 0.0), 0.0, 6.0, thickness=0.4)
    s.wall((0.0, size_z), (size_x, size_z), 0.0, 6.0, thickness=0.4)
    z = 3.0
    while z + 6.0 < size_z - 3.0:  # block rows: two rows of booths back to back, 6 m deep, an aisle of 3 m after
        x = 3.0
        while True:
            n = int(rng.integers(5, 8))
            if x + 3.0 * n > booths_x:
                n = int((booths_x - x) // 3.0)
            if n < 2:
                break
            x1 = x + 3.0 * n
            s.box(x, x1, 0.0, 2.5, z + 2.95, z + 3.05)  # the back wall the two rows share
            for k in range(n + 1):  # the side walls
                s.box(x + 3.0 * k - 0.05, x + 3.0 * k + 0.05, 0.0, 2.5, z, z + 6.0)
            for k in range(n):
                for zb, facing in ((z, 1.0), (z + 3.05, -1.0)):
                    if rng.random() < 0.5:
                        cz = zb + 1.6 if facing > 0 else zb + 0.8
                        holes.append(_ridged(s, x + 3.0 * k + 0.8, x + 3.0 * k + 2.2, cz, cz + 0.55, -0.1, 1.0))
            x = x1 + 3.0
        z += 9.0
    # the open floor: the stage against the east wall between the doors or in the north-east corner, chairs, pillars
    stage_w, stage_d = float(rng.uniform(12.0, 16.0)), 6.0
    sz0 = float(rng.uniform(4.0, size_z - stage_w - 4.0))
    sx1 = size_x - 6.0
    s.box(sx1 - stage_d, sx1, -0.1, 1.0, sz0, sz0 + stage_w)
    holes.append((sx1 - stage_d, sx1, sz0, sz0 + stage_w))
    _ridged(s, sx1 - 0.6, sx1, sz0, sz0 + stage_w, 1.0, 4.0)
    s.stairs(np.array([sx1 - stage_d - 5 * 0.3, sz0 + stage_w / 2]), np.array([1.0, 0.0]), 3.0, 0.0, 1.0, 0.2, 0.3)
    seat_x0 = booths_x + 6.0
    seat_x1 = sx1 - stage_d - 6.0
    rows = int(rng.integers(6, 10))
    for r in range(rows):  # chairs: 0.5 m wide, 0.9 m apart in a row, rows 0.9 m apart: a block no one threads
        cx = seat_x1 - r * 0.9
        if cx < seat_x0:
            break
        zc = sz0 + 1.0
        while zc < sz0 + stage_w - 1.0:
            _ridged(s, cx - 0.25, cx + 0.25, zc - 0.25, zc + 0.25, 0.0, 0.9)
            zc += 0.9
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(int(rng.integers(3, 7))):
        p = _placed(rng, spots, booths_x + 3.0, size_x - 3.0, 3.0, size_z - 3.0, 1.5,
                    [(seat_x1 - rows * 0.9 - 1.0, sx1 + 1.0, sz0 - 1.0, sz0 + stage_w + 1.0)])
        if p is not None:
            _trunk(s, p, 0.4, -0.1, 6.0)
    s.ground(-6.0, size_x + 6.0, -0.2, size_z + 0.2, 0.0, holes)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "turned_wings": turned_wings, "gap_roofs": gap_roofs, "gangway_quay": gangway_quay,
    "scree_cave": scree_cave, "track_beds": track_beds, "expo_hall": expo_hall,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirty-fourth round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
