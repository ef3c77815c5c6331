"""A thirty-third round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds33.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A thirty-third round of piece kinds", each with its known openings (count, place,
width, height) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. A round lookout platform over a drop, railed round its rim but for two
gaps; an approach to a raised doorway whose south half is a flight of steps and north half a ramp, side by side with
nothing between them, down to one foot; a road ending in a walled turning circle; a carriage arch through a building,
roofed, with a porter's lodge off each side through a door; a yard whose south side is a sitting wall 1.0 m high but
for a stretch only 0.3 m high (within the climb); three garden terraces 0.9 m apart joined by flights at alternate
sides; a doorway at the outward fold of a wall bent 15 degrees either side of it; a stair module with a handrail
down its middle from end to end. Built with :mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
import trimesh
from piece_parts import ROOM_OPENINGS, SLAB, arc_band, box, hull, kinds_by_name, prism, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(33)


def round_lookout_rail_gaps(radius: float = 4.0, gap: float = 1.2, drop: float = 6.0) -> SampleLevel:
    """A round lookout: a solid disc ``radius`` m (4) in radius about (5, 5), its top (y 0) the platform, ``drop`` m
    (6) high, nothing below or beyond it (96 flat sides circumscribing the circle); round its rim a railing 1.0 m high
    and 0.1 m thick (radii ``radius`` - 0.1 to ``radius``) in facets of at most 7.5 degrees, but for two gaps whose
    chord at the railing's outer face is ``gap`` m (1.2), centred on the bearings 90 and 225 degrees (from +x towards
    +z; radial ends). Known: two, at the platform's height (y 0), where a kit's ladder or stair module joins (as round
    19's balcony railing's gap and round 32's cliff terrace's): each gap, ``gap`` m at the railing's outer face on its
    bearing, (5.0, 9.0) facing north and (2.17, 2.17) facing 225 degrees (south-west); not the railing's length (a
    drop of ``drop`` m behind a rail)."""
    cx, cz = 5.0, 5.0
    half = math.degrees(math.asin(gap / 2 / radius))
    sides = 96
    rim = radius / math.cos(math.pi / sides)
    parts = [prism([(cx + rim * math.cos(a), cz + rim * math.sin(a)) for a in np.arange(sides) * 2 * math.pi / sides],
                   -drop, 0.0)]
    for a0, a1 in ((90.0 + half, 225.0 - half), (225.0 + half, 450.0 - half)):
        parts += arc_band(cx, cz, radius - 0.1, radius, a0, a1, 0.0, 1.0)
    ends = [_opening((cx + radius * math.cos(math.radians(b)), 0.0, cz + radius * math.sin(math.radians(b))),
                     (math.cos(math.radians(b)), 0.0, math.sin(math.radians(b))), gap) for b in (90.0, 225.0)]
    return _level("round_lookout_rail_gaps", parts, ends)


def stair_beside_ramp_approach(rise: float = 0.9) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, its floor ``rise`` m (0.9) up on a solid
    block, a 1.6 m west doorway (z 2.2-3.8, lintel 2.2 m over the floor); east a 2.4 m doorway (z 1.8-4.2, lintel 2.2
    m) onto a landing at the floor's height 1.2 m deep (x 8.3-9.5) and 4.8 m wide (z 0.6-5.4), from which the approach
    runs east to the piece's edge at x 14.9, 4.8 m wide: its south half (z 0.6-3.0) six risers of 0.15 m down (treads
    0.3 m, x 9.5-11.0, solid) to the ground (y 0), level from x 11.0 to 14.9; its north half (z 3.0-5.4) a ramp from
    the landing's edge straight down to the ground at x 14.9 (5.4 m, 9.5 degrees); nothing between the halves (the
    step beside the ramp is at most 0.15 m, within the 0.4 m climb); cheek walls 0.3 m thick (z 0.3-0.6 and 5.4-5.7)
    from the wall's face to the edge, 1.9 m high over the ground. Known: two: the west doorway, 1.6 m at (-0.3, 3.0)
    at y ``rise``, facing west, 2.2 m high; the approach's foot as ONE opening, 4.8 m at (14.9, 3.0) at y 0, facing
    east, open to the sky (a designer's one entrance; stair and ramp meet the ground side by side). Not the east
    doorway (inside the piece)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.8, 4.2, 2.2)]}, floor=rise)
    parts.append(box(-0.3, 8.3, -SLAB, rise - SLAB, -0.3, 6.3))
    parts.append(box(8.3, 9.5, -SLAB, rise, 0.6, 5.4))
    steps = 6
    riser = rise / steps
    parts += [box(9.5 + 0.3 * (i - 1), 9.5 + 0.3 * i, -SLAB, rise - riser * i, 0.6, 3.0) for i in range(1, steps)]
    parts.append(box(9.5 + 0.3 * (steps - 1), 14.9, -SLAB, 0.0, 0.6, 3.0))
    parts.append(hull([[x, y, z] for x, y in ((9.5, -SLAB), (9.5, rise), (14.9, 0.0), (14.9, -SLAB))
                       for z in (3.0, 5.4)]))
    parts += [box(8.3, 14.9, -SLAB, 1.9, 0.3, 0.6), box(8.3, 14.9, -SLAB, 1.9, 5.4, 5.7)]
    return _level("stair_beside_ramp_approach", parts,
                  [_opening((-0.3, rise, 3.0), _W, 1.6), _opening((14.9, 0.0, 3.0), _E, 4.8)])


def turning_circle_dead_end(road: float = 4.0, radius: float = 5.0) -> SampleLevel:
    """A road ``road`` m (4) wide (clear z 0-4) from x 0 to 10 between walls 0.3 m thick and 3 m high, ending in a
    turning circle: clear radius ``radius`` m (5) about (14.5, 2.0), walled all round (0.3 m thick, 3 m high, facets of
    at most 7.5 degrees, radial ends where the road's walls meet it) but where the road enters; the slab under the road
    and the circle to the walls' outer faces. Known: one, at the floor (y 0): the road's west end, ``road`` m at (0,
    2.0), facing west, 3 m high. Nothing round the circle (no gap in its wall)."""
    cx, cz = 14.5, road / 2
    mouth = math.degrees(math.asin(road / 2 / radius))
    ring = np.radians(np.arange(0.0, 360.0, 7.5))
    parts = [box(0.0, 10.0, -SLAB, 0.0, -0.3, road + 0.3),
             prism([(cx + (radius + 0.3) * math.cos(a), cz + (radius + 0.3) * math.sin(a)) for a in ring], -SLAB, 0.0)]
    parts += [box(0.0, 10.0, -SLAB, 3.0, -0.3, 0.0), box(0.0, 10.0, -SLAB, 3.0, road, road + 0.3)]
    parts += arc_band(cx, cz, radius, radius + 0.3, 180.0 + mouth, 540.0 - mouth, -SLAB, 3.0)
    return _level("turning_circle_dead_end", parts, [_opening((0.0, 0.0, cz), _W, road)])


def carriage_arch_lodges(arch: float = 3.2) -> SampleLevel:
    """A building 8.6 x 11.8 m (outer x -0.3-8.3, z -0.3-11.5), walls 0.3 m thick and 3.5 m high under a roof slab
    over the whole (y 3.5-3.7), floored to its outer faces at y 0. Through its middle a carriage arch: a passage
    ``arch`` m (3.2) wide (clear z 4.0-7.2), x -0.3 to 8.3, open at both facades to the roof's underside (3.5 m),
    between walls z 3.7-4.0 and 7.2-7.5. Either side a porter's lodge (clear x 0-8, z 0-3.7 south and z 7.5-11.2
    north), each reached only by a 1.0 m door (x 3.5-4.5, lintel 2.2 m) in the passage's wall, each lit by a window
    1.2 m wide in a facade (the south lodge's in the west one, z 1.2-2.4; the north lodge's in the east one, z
    8.7-9.9), sill 1.0 m (over the climb) and head 2.2 m. Known: two, at the floor (y 0), ``arch`` m each, 3.5 m high:
    the passage's ends, (-0.3, 5.6) facing west and (8.3, 5.6) facing east. Not the lodges' doors (inside the piece),
    not their windows (a sill 1.0 m up)."""
    z0, z1 = 4.0, 4.0 + arch
    top = 11.2 + (arch - 3.2)
    parts = [box(-0.3, 8.3, -SLAB, 0.0, -0.3, top + 0.3), box(-0.3, 8.3, 3.5, 3.7, -0.3, top + 0.3),
             box(-0.3, 8.3, -SLAB, 3.5, -0.3, 0.0), box(-0.3, 8.3, -SLAB, 3.5, top, top + 0.3)]

    def facade(x0: float, x1: float, za: float, zb: float, window: tuple[float, float] | None) -> None:
        if window is None:
            parts.append(box(x0, x1, -SLAB, 3.5, za, zb))
            return
        w0, w1 = window
        parts.extend([box(x0, x1, -SLAB, 3.5, za, w0), box(x0, x1, -SLAB, 3.5, w1, zb),
                      box(x0, x1, -SLAB, 1.0, w0, w1), box(x0, x1, 2.2, 3.5, w0, w1)])

    facade(-0.3, 0.0, 0.0, z0 - 0.3, (1.2, 2.4))
    facade(8.0, 8.3, 0.0, z0 - 0.3, None)
    facade(-0.3, 0.0, z1 + 0.3, top, None)
    facade(8.0, 8.3, z1 + 0.3, top, (z1 + 1.5, z1 + 2.7))
    for za, zb in ((z0 - 0.3, z0), (z1, z1 + 0.3)):
        parts += [box(-0.3, 3.5, -SLAB, 3.5, za, zb), box(4.5, 8.3, -SLAB, 3.5, za, zb),
                  box(3.5, 4.5, 2.2, 3.5, za, zb)]
    mid = (z0 + z1) / 2
    return _level("carriage_arch_lodges", parts,
                  [_opening((-0.3, 0.0, mid), _W, arch), _opening((8.3, 0.0, mid), _E, arch)])


def sitting_wall_step_over(low: float = 0.3, high: float = 1.0, stretch: float = 2.4) -> SampleLevel:
    """A yard 10 x 6 m (clear x 0-10, z 0-6) open to the sky, walls 0.3 m thick and 3 m high on its west (x -0.3-0),
    east (x 10-10.3) and north (z 6.0-6.3) sides, a 1.6 m doorway in the north wall (x 4.2-5.8, lintel 2.2 m); its
    south side a sitting wall 0.4 m thick (z -0.4-0) ``high`` m (1.0, over the 0.4 m climb) high along x 0-10, but for
    a stretch ``stretch`` m (2.4) long in its middle (x 3.8-6.2) only ``low`` m (0.3, within the climb) high; the slab
    ends at the walls' outer faces, nothing beyond. Known: two: the north doorway, 1.6 m at (5.0, 6.3) at y 0, facing
    north, 2.2 m high; the low stretch, ``stretch`` m at its outer face (5.0, -0.4) at the floor (y 0, as round 26's
    kerb across a corridor's end), facing south, open to the sky. Not the sitting wall's high run."""
    s0, s1 = 5.0 - stretch / 2, 5.0 + stretch / 2
    parts = [box(-0.3, 10.3, -SLAB, 0.0, -0.4, 6.3),
             box(-0.3, 0.0, -SLAB, 3.0, -0.4, 6.0), box(10.0, 10.3, -SLAB, 3.0, -0.4, 6.0),
             box(-0.3, 4.2, -SLAB, 3.0, 6.0, 6.3), box(5.8, 10.3, -SLAB, 3.0, 6.0, 6.3),
             box(4.2, 5.8, 2.2, 3.0, 6.0, 6.3),
             box(0.0, s0, -SLAB, high, -0.4, 0.0), box(s1, 10.0, -SLAB, high, -0.4, 0.0),
             box(s0, s1, -SLAB, low, -0.4, 0.0)]
    return _level("sitting_wall_step_over", parts,
                  [_opening((5.0, 0.0, 6.3), _N, 1.6), _opening((5.0, 0.0, -0.4), _S, stretch)])


def terraced_garden_flights(step: float = 0.9) -> SampleLevel:
    """Three garden terraces 8 m wide (clear z 0-8) between side walls 0.3 m thick (z -0.3-0 and 8.0-8.3) standing 3 m
    over the top terrace: the lowest x 0-4 at y 0, the middle x 4-8 at ``step`` m (0.9), the top x 8-12 at 2 ``step``
    m (1.8), each a solid block; between them retaining walls' faces (x 4 and x 8) dropping ``step`` m, unrailed (over
    the 0.4 m climb: no way up or down but the flights); up each a flight 1.2 m wide of six risers ``step`` / 6 m
    (0.15) on 0.3 m treads, solid, set on the lower terrace against the face: the first at the south side (z 0.5-1.7,
    x 2.2-4.0), the second at the north side (z 6.3-7.5, x 6.2-8.0). Known: two, 8.0 m each, open to the sky: the
    lowest terrace's west end at (0, 4.0) at y 0, facing west; the top terrace's east end at (12, 4.0) at y 2
    ``step`` (1.8), facing east. Not the retaining walls' edges (drops inside the piece), not the flights."""
    parts = [box(0.0, 4.0, -SLAB, 0.0, 0.0, 8.0), box(4.0, 8.0, -SLAB, step, 0.0, 8.0),
             box(8.0, 12.0, -SLAB, 2 * step, 0.0, 8.0),
             box(0.0, 12.0, -SLAB, 2 * step + 3.0, -0.3, 0.0), box(0.0, 12.0, -SLAB, 2 * step + 3.0, 8.0, 8.3)]
    riser = step / 6
    for base, x_face, (z0, z1) in ((0.0, 4.0, (0.5, 1.7)), (step, 8.0, (6.3, 7.5))):
        parts += [box(x_face - 0.3 * (6 - i), x_face - 0.3 * (5 - i), -SLAB, base + riser * (i + 1), z0, z1)
                  for i in range(6)]
    return _level("terraced_garden_flights", parts,
                  [_opening((0.0, 0.0, 4.0), _W, 8.0), _opening((12.0, 2 * step, 4.0), _E, 8.0)])


def folded_wall(fold_deg: float, near: float, far: float) -> tuple[list[trimesh.Trimesh], np.ndarray, np.ndarray]:
    """The room of :func:`folded_wall_door` with a doorway in its folded east wall, its jambs square to the wings
    ``near`` m along the south wing's inner face and ``far`` m along the north wing's from the apex: the parts, and the
    jambs' outer corners (2,) (x, z) at the south and the north, metres."""
    t = math.radians(fold_deg)
    apex = np.array([8.0 + 3.0 * math.tan(t), 3.0])
    d1, d2 = np.array([math.sin(t), math.cos(t)]), np.array([-math.sin(t), math.cos(t)])
    n1, n2 = np.array([d1[1], -d1[0]]), np.array([d2[1], -d2[0]])  # outward (east) normals of the two wings
    j1 = np.array([8.0, 0.0]) + d1 * (3.0 / math.cos(t) - near)
    j2 = apex + d2 * far
    o1, o2 = j1 + n1 * 0.3, j2 + n2 * 0.3
    tip = apex + np.array([0.3 / math.cos(t), 0.0])
    s_out = np.array([8.0, 0.0]) + n1 * 0.3 + d1 * ((-0.3 - (n1 * 0.3)[1]) / d1[1])  # wing 1's outer face at z -0.3
    n_out = np.array([s_out[0], 6.3])
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})  # no straight east wall
    parts += [prism([(8.0, -0.3), tuple(s_out), tuple(tip), tuple(n_out), (8.0, 6.3)], -SLAB, 0.0),
              prism([(8.0, -0.3), tuple(s_out), tuple(o1), tuple(j1), (8.0, 0.0)], -SLAB, 3.0),
              prism([(8.0, 6.3), tuple(n_out), tuple(o2), tuple(j2), (8.0, 6.0)], -SLAB, 3.0),
              prism([tuple(j1), tuple(o1), tuple(tip), tuple(o2), tuple(j2), tuple(apex)], 2.2, 3.0)]
    return parts, o1, o2


def folded_wall_door(fold_deg: float = 15.0, door: float = 1.6) -> SampleLevel:
    """Room (clear x 0-8, z 0-6 and east of it), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8,
    lintel 2.2 m); its east wall folded outward: two wings, each ``fold_deg`` (15) degrees off north-south, their inner
    faces from (8, 0) and (8, 6) to an apex at (8 + 3 tan ``fold_deg``, 3) = (8.80, 3.0), their outer faces 0.3 m out
    meeting at (9.12, 3.0); at the fold a doorway under a lintel 2.2 m up, its jambs square to each wing ``door`` / 2 m
    (0.8) along the wing's inner face from the apex: the inner corners (8.60, 2.23) and (8.60, 3.77) (1.55 m apart),
    the outer (8.89, 2.15) and (8.89, 3.85) (1.70 m apart). The slab under the walls' whole footprint, so through the
    doorway the floor runs out to the outer faces' apex. Known: two, at the floor (y 0), 2.2 m high: the west doorway,
    1.6 m at (-0.3, 3.0); the fold's doorway, 1.70 m (the chord between its jambs' outer corners) at that chord's
    middle (8.89, 3.0), facing east (the floor's point 0.23 m beyond it)."""
    parts, o1, o2 = folded_wall(fold_deg, door / 2, door / 2)
    mid = (o1 + o2) / 2
    return _level("folded_wall_door", parts,
                  [ROOM_OPENINGS[0], _opening((mid[0], 0.0, mid[1]), _E, float(np.linalg.norm(o2 - o1)))])


def _stair_floor(x: float, pad: float, steps: int, tread: float, riser: float) -> float:
    """The stair module's floor height (m) at ``x``: 0 over the bottom pad, ``riser`` more per tread, then the top."""
    return riser * min(steps, max(0, math.ceil((x - pad) / tread - 1e-9)))


def stair_central_handrail(width: float = 3.2, steps: int = 8, riser: float = 0.2, tread: float = 0.3) -> SampleLevel:
    """A stair module ``width`` m (3.2) wide (clear z 0-3.2) between cheek walls 0.3 m thick standing 3 m over its top:
    a bottom pad 1.2 m long (x 0-1.2, y 0), ``steps`` (8) risers of ``riser`` m (0.2) on ``tread`` m (0.3) treads
    east (x 1.2-3.6, solid), a top pad 1.2 m long (x 3.6-4.8) at 1.6 m; both ends open. Down its middle from end to
    end a handrail as a kit's stair modules carry it, to run on into the next module: posts 0.06 m square (z
    1.57-1.63) 1.0 m high over the floor beneath them at x 0, 1.2, 2.4, 3.6 and 4.74 (their west faces), a rail 0.05
    m square on their tops. Known: two, ``width`` m each, 3 m high or more: the bottom end at (0, 1.6) at y 0, facing
    west; the top end at (4.8, 1.6) at y 1.6, facing east. Decided before the run: ONE opening at each end, not two
    either side of the end post: a handrail parts the way's two lanes, not two ways (each half, 1.57 m, is wider than
    the agent; the rail 1 m high is open above, unlike round 32's post between two doors under one lintel)."""
    pad = 1.2
    top = steps * riser
    end = 2 * pad + steps * tread
    parts = [box(0.0, pad, -SLAB, 0.0, 0.0, width), box(end - pad, end, -SLAB, top, 0.0, width)]
    parts += [box(pad + tread * i, pad + tread * (i + 1), -SLAB, riser * (i + 1), 0.0, width) for i in range(steps)]
    parts += [box(0.0, end, -SLAB, top + 3.0, -0.3, 0.0), box(0.0, end, -SLAB, top + 3.0, width, width + 0.3)]
    r0, r1 = width / 2 - 0.03, width / 2 + 0.03
    posts = [0.0, pad, 2 * pad, 3 * pad, end - 0.06]
    heads = []
    for x in posts:
        floor = _stair_floor(x + 0.03, pad, steps, tread, riser)
        parts.append(box(x, x + 0.06, floor, floor + 1.0, r0, r1))
        heads.append((x, floor + 1.0))
    for (xa, ya), (xb, yb) in zip(heads[:-1], heads[1:]):
        parts.append(hull([[x, y + dy, z] for x, y in ((xa, ya), (xb + 0.06, yb)) for dy in (0.0, 0.05)
                           for z in (width / 2 - 0.025, width / 2 + 0.025)]))
    return _level("stair_central_handrail", parts,
                  [_opening((0.0, 0.0, width / 2), _W, width), _opening((end, top, width / 2), _E, width)])


KINDS = kinds_by_name(round_lookout_rail_gaps, stair_beside_ramp_approach, turning_circle_dead_end,
                      carriage_arch_lodges, sitting_wall_step_over, terraced_garden_flights, folded_wall_door,
                      stair_central_handrail)
"""Kind name -> factory of the thirty-third round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
