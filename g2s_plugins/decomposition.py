"""Regions and chokepoints of a navigation mesh: rooms, and the narrow passages that join them.

The walkable surface is split where it narrows, as strategy-game map analysers
do on their tile grids (BWEM grows areas from the points farthest from the
walls and puts a chokepoint where two grown areas meet; BWTA uses the
Voronoi diagram of the walls: L. Perkins, "Terrain analysis in real-time
strategy games: an integrated approach to choke point detection and region
decomposition", AIIDE 2010). Here the same idea runs on the navmesh
polygons and their shared edges (portals):

1. Clearance. The navmesh's boundary edges (polygon edges with no
   neighbour: the walls, already eroded by the agent radius) are cut into
   pieces of at most :data:`PIECE`; the clearance of a point is its exact
   distance to the nearest piece (scipy ``cKDTree`` over the pieces'
   midpoints, heights scaled by :data:`HEIGHT_SCALE` so that another floor's
   walls stay far). A polygon's clearance is its centre's, measured
   :data:`CENTRE_LIFT` over its floor whatever the navmesh's cell height
   (:func:`measured_centres`); a portal's is the
   largest clearance of points along it at most one navmesh cell apart (five
   at least, always its middle: :func:`portal_samples`), so a door's portal
   measures the middle of the door, and a long portal that crosses a passage
   only in part measures the passage. Small holes in the walkable surface (closed
   boundary loops of the hole orientation enclosing less than
   ``obstacle_area`` m²: pillars, crates) are left out of the clearances
   that split the level, so they neither make a room as narrow as its doors
   nor make passages of their own (with ``through_holes``, a portal that ends
   on one, with a gap about as wide beyond it, is measured through it as well: :func:`_through_holes`); but a
   small hole that is a piece of wall
   between two openings (:func:`wall_pieces`: long for its width, its ends
   near other walls, its long sides not) counts as a wall, so that a front of
   doors is not one opening as wide as the front. ``width = 2 x clearance``
   with every wall counted is the walkable width reported for a chokepoint.
   Two more widths of a cut are used below and kept apart by name: its
   *span*, the walkable width and the agent's diameter (the opening the
   eroded navmesh stands for), and its *clear width*, wall to wall in the
   level: measured in the mesh (:class:`DoorWidths`) or estimated as the
   span and a navmesh cell of rasterisation (``wall_to_wall``).
2. Merge tree (watershed by clearance). Portals are taken widest first and
   join the groups of polygons on their two sides (union-find), except when
   both groups are already *rooms*: they hold at least ``min_region_area`` m²
   and their widest point is wider than the portal by the factor
   1 / ``narrowness``. Such a portal is a chokepoint candidate and is never
   merged: groups only grow and portals only narrow, so the two sides stay
   apart. Small or barely wider groups (slivers, corridors, corners) merge
   into their neighbours. A smaller group is a room too when it is walled in
   but for one opening (:class:`Outlines`: at least
   :data:`SMALL_ROOM_ENCLOSURE` of its outline is wall, the portals out of it
   lie within :data:`SMALL_ROOM_OPENING` of its longest extent, it holds
   the agent's footprint, and its door is narrower than it, both measured wall
   to wall in the level's mesh: :class:`DoorWidths`): a prison cell or a box
   room behind its door, not a niche or a bay open over its width, nor a
   piece of walkway open at both ends. Such a small room is never a passage
   (step 3).
3. Passages (:func:`join_passages`). A group whose mean walkable width,
   its area over its longest extent (:func:`longest_extents`), is below
   ``passage_width`` agent diameters is a passage (an aisle, a catwalk, a
   narrow corridor: two agents cannot pass each other in it), not a room,
   however much narrower its ends are than its widest point. Passages joined
   by candidates are one passage; a passage whose candidates all lead to one
   room is part of that room (an aisle between desk rows, a dead end, a
   catwalk up a ramp); one between several rooms stays a region and carries
   the chokepoints to them.
   Pinches (:func:`pinches`): a candidate between two *corridor-like*
   groups (area at least :data:`CORRIDOR_ELONGATION` squares of their
   widest walkable width: long for their width; and that width at most
   :data:`CORRIDOR_WIDTH` agent diameters) is a pinch, not a
   chokepoint, when the corridor is locally wider than the cut on both
   sides by 1 / ``narrowness`` at least but not by 1 / ``pinch`` or more:
   a pilaster narrows a corridor for a step and the corridor goes on as
   wide on both sides, so the two groups are one space (a ring or straight
   corridor cut at its pilasters). The local width of a side is twice the
   largest clearance of that side's floor within :data:`PINCH_REACH` spans
   of the cut (:func:`local_widths`, on a grid one navmesh cell
   apart): there a pilaster's corridor has its full width again, while a
   corridor's mouth into a room is as narrow as the cut on the corridor's
   side and the room is wide on the other (the rooms at the corridor's ends
   stay apart), and a door takes more of a corridor than ``pinch`` allows
   (a door across a corridor parts it as a door between rooms does). The
   two groups of every pinch join. This is the project's own rule, set on
   the generated samples (docs/plugins.md, "Pinches").
   Side strips (:func:`join_side_strips`, after the pinches): a group all of
   whose candidates lead to one other group, at both its ends (spread over
   :data:`STRIP_ENDS` of its longest extent and ``min_separation``), and whose
   widest candidate keeps at least ``narrowness`` of the group's own mean
   width, is a strip beside that group and joins it: a shelving aisle whose
   ends read narrower than its widest point only because the racks' corners
   are rasterised at an angle. A room with two doors to one corridor is far
   wider than its doors and stays; a dead end is left to the merge tree (a
   room and its corridor, measured as one group, are narrow on average). The
   project's own rule, set on the held-out level kinds (docs/plugins.md,
   "Level kinds it was not tuned on").
   Lanes side by side (:func:`lane_mouths`): a candidate whose floor on one side, within
   :data:`PINCH_REACH` spans of it, is narrower than ``passage_width`` agent diameters opens a passage;
   when another candidate of the same two regions opening a passage lies beside it (at least
   ``min_separation`` and at most :data:`LANE_PITCH` clear widths away), both are mouths of lanes side by
   side (grave rows, shelving, queue rails) and the two regions join, again on the joined regions until no
   such pair is left. Two doors off a corridor open no passage (the corridor and the room are wide behind
   them); passages far apart (footbridges, gates) are ways of their own. The project's own rule, set on the
   eleventh round's cemetery and library (docs/plugins.md, "Lanes side by side").
   Ways round obstacles (:func:`_join_ways_round`, last): each opening between two regions on one floor is
   closed (with the cuts on the far side of a pillar or post it ends on: small holes the split leaves out) and
   the shortest walk between its two sides is looked for on the polygon graph (:class:`PolygonWalks`: centre,
   portal middle, centre; Dijkstra). When one of at most :data:`WAY_ROUND` times the regions' size is there, the
   opening is a way round something standing in open floor (a container on a quay, an enclosure among paths, a
   feature on a plaza), not a narrowing of a way, and the two regions join, again on the joined regions until no
   such opening is left. Size is the larger region's longest extent, or the smaller's when either is walled in
   (:data:`WALLED_IN` of its outline wall, and no passage: a house with a door at each end keeps both) and the
   opening is no wider than a door can be (:data:`CORRIDOR_WIDTH` agent diameters walkable); a wider opening is
   weighed against the walled-in region itself (a yard's mouths onto a zoo walled in by its fence). Doors
   of rooms in a loop, a wall's gaps between two fields and a room's two doors onto a corridor cost walks of one
   to several regions' sizes. The project's own rule, set on the thirteenth round's kinds (docs/plugins.md,
   "Ways round obstacles"). Spans (:func:`_spans`) are never joined: two regions whose openings together are
   narrower than :data:`SPAN_SHARE` of the narrower one's mean walkable width (bridges over a crevasse or a river,
   planks between roofs) are parted along almost all their front (docs/plugins.md, "Spans").
   Stair runs (:func:`stair_runs`, after the ways round): a *flight* is a region with exactly two chokepoints, to two
   different regions, no wider than :data:`CORRIDOR_WIDTH` agent diameters on average, whose chokepoints lie at least
   half the agent's height and :data:`STAIR_GRADIENT` of its longest extent apart in height (a piece of a stair
   between two landings). Flights joined by chokepoints are a run; a run of two flights or more whose foot and head
   lie in regions larger than the whole run is one way between them: its flights join, the chokepoints at its
   landings go and those at its foot and head stay. Landings where flights meet from several sides (a lattice of
   flights) have three chokepoints or more, or are no larger than the run: they stay regions. The project's own
   rule, set on the fifteenth round's monastery and dam (docs/plugins.md, "Stairs in one run").
   Ways (last; :func:`way_pieces`, :func:`_way_ends`): a *way* is a region at most :func:`way_width` wide on
   average. A chokepoint between two ways on one floor that keeps at least ``narrowness`` of both their mean
   walkable widths parts two pieces of one way (a causeway or a platform cut where a passing bay or a corner widens
   it for a few metres): the two join, again until none is left. A way :data:`WAY_ELONGATION` times as long as it
   is wide whose chokepoints, to two regions or more, each keep at least ``narrowness`` of its mean width (as narrow
   as its openings) goes on to its ends: where the floor beyond a chokepoint is no wider than the chokepoint over
   ``narrowness`` (:func:`local_widths`), the merge tree merged the way's last stretch into the region beyond (no
   wider than the way, so no room of its own); that stub, the polygons going on from the chokepoint on its floor as
   narrow (:func:`narrow_stub`), joins the way with what of the neighbour only it reaches, and the chokepoint moves
   to where the floor widens: at least ``min_separation`` on, the stub larger than what it cuts off (else it links
   two parts of the neighbour). The project's own rules, set on the sixteenth round's lighthouse (docs/plugins.md,
   "Ways and their ends").
4. Regions are the groups left (``scipy.sparse.csgraph.connected_components``
   of the merged portals, joined passages, pinches, side strips, lanes, ways round, stair runs and ways), numbered by
   their lowest polygon id.
   Candidates between the same two regions that are chained end to end (one opening:
   Recast's region contours may bend across a wide gap), that end on the same
   small hole less than half as wide between them, wall to wall, as the narrower
   of the two (a post in a gap, a slim pier between arches: :func:`_post_links`), or closer than
   ``min_separation`` are one chokepoint (the widest portal of them stays:
   a door cut by a tile border is several portals).
5. A chokepoint is an articulation of the level when it is a bridge of the
   region multigraph (regions joined by one edge per chokepoint;
   ``rustworkx.bridges``, which sees parallel edges as one, so a pair of
   regions with two chokepoints is left out): closing it disconnects the level.
6. Traffic (:func:`score`). A structure edge whose two ends lie in different
   regions crosses the chokepoint between them nearest to it; the
   chokepoint's traffic is the largest edge betweenness of the structure
   edges crossing it (:func:`g2s_plugins.centrality.edge_betweenness`: the
   share of structure node pairs whose path uses the edge) and its score is
   ``traffic / width``.

Floors: polygons within 10 degrees of flat are grouped into height bands
(split where sorted heights jump by more than half the agent height); a
region's floor is the band holding most of its flat area (the nearest band
to its mean height when it has none). Multi-floor levels need nothing else:
the polygon graph already joins floors only where the agent can walk (ramps,
stairs).

Complexity: clearance O((B + P + E) log B) for B wall pieces, P polygons,
E portals; extents O(V) for V polygon corners; pinches O(C (Q M + Q log B)) for
C candidates between corridor-like groups, Q grid points within a cut's reach
(hundreds) and M polygons near it; side strips O(V + C log C) (extents, then
sorting the candidates' region pairs); lanes O(R (C' (Q M + Q log B) + sum of k^2)) for R rounds (joins; 1-4
measured), C' candidates of region pairs with openings at least ``min_separation`` apart and k passage openings
per pair; ways round O(R' (V + C + O K log K)) for R' rounds (1-4 measured), O openings and K polygons within the
walk's length of an opening (few in rooms, up to a region in open ground); stair runs O(V + C log C) (extents, the
chokepoints once more, sorting their ends); ways O(R'' (V + C log C) + W (P + E)) for R'' rounds of joins and W
chokepoints of ways (each stub looked for once, and the region it leaves split into its parts); openings
O(C log C + sum of k^2) for k candidate ends on each small hole; small rooms O(k) per look at a group under
``min_region_area`` (k: its polygons and their portals, few), and O(k) rays for the groups walled in but for one
opening (:class:`DoorWidths`, each polygon and portal cast once); wall pieces O(B) and O(B) more per elongated
small hole (few: pillars are compact); the merge tree sorts the portals and runs one union-find step per portal
(a Python loop of O(E alpha(P)): a merge order is sequential by nature and no library offers it on a general graph);
everything else is numpy/scipy over arrays, networkx only on the small region graph.
"""

from __future__ import annotations

import math
import weakref
from collections import Counter
from collections.abc import Hashable
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
from pydantic import Field

from g2s_core.errors import PluginError
from g2s_core.lazy import lazy_module
from g2s_core.plugin import PluginParams
from g2s_plugins import centrality
from g2s_plugins._raycasting import RayCaster, hit_from_behind
from g2s_plugins.play_space import held_polygons

rx, trimesh = lazy_module("rustworkx"), lazy_module("trimesh")
sparse, csgraph, spatial = lazy_module("scipy.sparse"), lazy_module("scipy.sparse.csgraph"), lazy_module("scipy.spatial")
nx = lazy_module("networkx")

HEIGHT_SCALE = 4.0
"""Height differences count this many times in clearance distances, so a wall 2 m above is 8 m away."""

CENTRE_LIFT = 0.125
"""How high over its floor a polygon's centre is measured (m; :func:`measured_centres`): Recast's detail surface, on
which the centres lie, stands one cell height over the polygons' corners, where the walls and portals are, and the
rooms' split and every constant below were measured on Recast's own 0.125 m cells, so with centres 0.125 m up (0.5 m
in quadrature to a clearance, heights counted :data:`HEIGHT_SCALE` times). Fixed here, the split no longer depends on
the cell height: on the agent's climb cells (0.025 m) the centres' own lift (0.1 m in quadrature) lost doors, the
pillared dungeon's, three of a building's and the maze's two (docs/plugins.md, "Regions on the agent's climb
cells")."""

FLAT_DEG = 10.0
"""Polygons within this angle of horizontal define the floors' height bands, degrees."""

PIECE = 1.0
"""Walls are cut into pieces at most this long (m) for the nearest-wall search."""

NEAREST_PIECES = 6
"""Wall pieces whose exact distance is computed for each point (the nearest by midpoint)."""

PORTAL_SAMPLES = 5
"""The fewest points along a portal where its clearance is measured (:func:`portal_samples`)."""

CORRIDOR_ELONGATION = 3.0
"""A group whose area is at least this many squares of its widest walkable width is corridor-like (:func:`pinches`):
a corridor 2.5 m walkable and 7.5 m long or longer. Measured: a square room is 1, the offices and the rooms of the
samples 1.2-1.9, the ring corridor's pieces 4.1-8.7 (docs/plugins.md, "Pinches")."""

CORRIDOR_WIDTH = 4.0
"""A corridor-like group is also at most this many agent diameters wide at its widest (walkable): a corridor holds a
few agents abreast, however long a hall is (measured: the corridors of the samples 2.1-2.7 diameters, turned or not;
docs/plugins.md, "Pinches"). A room's door is no wider either (:func:`_join_ways_round`)."""

PINCH_REACH = 1.5
"""A side's local width near a cut is measured within this many times the cut's span (its walkable width and the
agent's diameter) of it (:func:`local_widths`): past a pilaster a corridor is as wide as before within about one span,
while a room
beyond a corridor's mouth shows its width only further in. Measured on the generated dungeons and samples against
1.0 and 2.0 (docs/plugins.md, "Pinches")."""

STRIP_ENDS = 2.0 / 3.0
"""A side strip's chokepoint candidates are spread over at least this fraction of its longest extent: it meets its
region at both ends (:func:`join_side_strips`). Measured (docs/plugins.md, "Level kinds it was not tuned on"; the
farthest pair's distance over the extent): a warehouse aisle turned 45 degrees 1.00, pieces of pillared dungeon rooms
cut off by pillar gaps 0.82-0.84, the part of a pillared room holding its centre (the rest gone to the next room
through its corridor) 0.56."""

WALL_PIECE_ELONGATION = 3.0
"""A small hole whose longest plan extent squared is at least this many times its area (a rectangle 2.6 times as
long as it is wide or more), or whose solid (the hole less the agent's diameter and a navmesh cell across each way)
is at least this many times as long as it is wide, and whose ends lie near other walls, is a piece of wall between
openings (:func:`wall_pieces`). Measured: square pillars and posts 1.7-2.0 and 1.0-1.33 (solid), the cathedral's west
front between its doors 3.26 and 5.75, 1.5 m piers of a 0.2 m wall 1.9-2.5 and 6.0 (docs/plugins.md, "One opening,
one chokepoint" and "Posts, niches and aisles")."""

POST_SHARE = 0.5
"""A small hole between two chokepoint candidates of one region pair is a post (or a pier) in one opening when it is
less than this share as wide, between the candidates' ends on it, as the narrower of the two is wide, both wall to
wall (:func:`_post_links`): a gate with a post, two arches on a slim pier. At least as wide: a wall between two doors.
The designer's rule of docs/plugins.md, "Posts, niches and aisles"; measured there on posts of 0.3-1.5 m in gaps of
4-20 m and on doors of 1.5-3 m 0.5-3 m apart, at 0, 22 and 45 degrees."""

THROUGH_GAP_SHARE = 0.5
"""With ``through_holes``, a portal ending on a small hole left out of the clearances is measured through it when the
gap beyond the hole, along the portal's line, and the portal's own gap are each at least this share as wide as the
other, wall to wall (:func:`_between_gaps`): two gaps of one opening, the hole standing between them. Set before
measuring, as :data:`POST_SHARE` (a post at most half an opening's width); docs/plugins.md, "Cuts through the holes
left out, between two gaps", gives 0.33 and 0.67 beside it."""

SMALL_ROOM_ENCLOSURE = 0.85
"""A group under ``min_region_area`` is a room when at least this share of its outline (walls and the portals out of
it) is wall, its exits are :data:`SMALL_ROOM_OPENING` together and it holds :data:`SMALL_ROOM_FOOTPRINT` (step 2 of the
module doc). Measured (docs/plugins.md, "Small rooms of their own"; 0, 22 and 45 degrees): rooms of 4-16 m² behind
1.5-2 m doors 0.85-0.98 (one 0.76), open-fronted cubicles 0.24-0.87 (all but one under 0.85), a bay between piers and
a wall 0.57-0.81, niches open over their width 0.81-0.94 (only the 2 m wide ones, 2-3 m deep, cut off at all)."""

SMALL_ROOM_OPENING = 0.5
"""A small room's exits (the portals out of it) spread over at most this share of its longest plan extent: one door,
not a piece of walkway open at both ends (measured, seed 0: 36 strips of the airport's concourse where its moving
walkways run, 16 pieces of the arena's end strips and 22 of the sewer's walkways, 0.87-0.98 of their outline wall,
each open at both ends; docs/plugins.md, "Small rooms of their own")."""

SMALL_ROOM_FOOTPRINT = 1.0
"""A small room holds at least this many squares of the agent's diameter (its own footprint), m² per m²."""

DOOR_STEP = 0.05
"""A door's clear width is looked for at points this far apart across its portal, m: finer than a wall is thick, so
that one point lies in the doorway (:class:`DoorWidths`)."""

SMALL_ROOM_DOOR = 0.95
"""A small room's door is narrower than the room: under this share of it, both clear widths wall to wall in the
level's mesh (:class:`DoorWidths`). Measured (docs/plugins.md, "Doors narrower than their rooms"): niches and pieces
of them 1.0 (as wide as their mouths), castle nooks 0.97-1.0, pieces of the sewer's walkways 0.96-1.0 and of
hospital rooms behind their beds 1.0; prison cells 0.10-0.80, rooms of 2-4 m behind 1.5-2 m doors up to 0.8, a
hallway 1.6 m wide behind a 1.5 m door 0.94."""

LANE_PITCH = 4.0
"""Two passage openings of one region pair at most this many clear widths apart (the wider of the two, estimated:
walkable width, agent's diameter and a navmesh cell; at least ``min_separation``) are lanes side by side (:func:`lane_mouths`). Measured (docs/plugins.md, "Lanes side by side"),
the nearest other passage opening of the same region pair in clear widths: neighbouring lanes of the cemetery 2.1
(10th percentile; a lane every 3.6 m, mouths 0.2-0.5 m walkable), the warehouse's racking aisles 2.3, the library's
shelf aisles 2.3-3.9, against 5.0 for two gaps of a pillared dungeon room turned 45 degrees, 5.4 and more on the
aqueduct, 17 on the scaffold and 41-48 for the golf course's footbridges."""

WAY_ROUND = 0.75
"""An opening between two regions is a way round an obstacle, not a narrowing of a way, when closing it lengthens the
walk from one of its sides to the other by at most this many times the regions' size: the larger region's longest
extent, or the smaller's when either is walled in (:func:`_join_ways_round`). Measured (docs/plugins.md, "Ways round
obstacles"; before any join, over the larger extent): the cuts across open floor of the skate park, cemetery,
interchange and zoo 0.30-0.76 at the median, the dry dock's 1.00 (its quay cut into pieces as small as the walk
round a container: they join once their neighbours have); two fields parted by a wall with three gaps 0.99-2.18, a
room's two doors onto a corridor 0.48-1.00 (1.49-3.00 of the room's own extent, walled in), a loop of four rooms
2.49, the generated dungeons' doors 2.2 and more. At 1.0 the two fields join, at every yaw."""

SPAN_SHARE = 0.25
"""Openings between two regions that together are narrower than this share of the narrower region's mean walkable
width are spans (:func:`_spans`): the two regions are parted along almost all their common front (a crevasse crossed
by snow bridges, a river by footbridges, an alley by planks, a sandbag line at its gaps, a fence at its stiles), and
"Ways round obstacles" never joins them: the walk round by another span is no way round something standing in open
floor. Set at a quarter before measuring; measured (docs/plugins.md, "Spans"; per region pair joined by the ways
round on seed 0 of every kind): the glacier's bands 0.058-0.091, the water park's island 0.197, the medina's road and
alleys at a gate 0.147-0.221; 72 of 574 pairs joined below 0.3, in 35 kinds."""

WALLED_IN = 0.95
"""A region at least this share of whose outline is wall (the small holes left out of the clearances not counted:
pillars and posts stand in it) and which is no passage is walled in: a room behind its doors, whose openings are
weighed against its own size (:func:`_join_ways_round`). Measured (docs/plugins.md, "Ways round obstacles"): the zoo's
reptile house, aviary and cafe 0.97-0.99, pieces of the dry dock's quays between containers and stacks 0.59-0.93.
An opening wider than :data:`CORRIDOR_WIDTH` agent diameters (walkable) is no door: it is weighed against the
walled-in region's own extent, not the smaller region's (docs/plugins.md, "Yards beside walled-in ground": the
zoo's paths, walled in by its fence at 0.98, and a corner yard of 1,001 m² beside them, 0.79, at mouths 6.7-11.1
m)."""

STAIR_GRADIENT = 0.25
"""A flight (:func:`stair_runs`) climbs at least this share of its longest plan extent between its two chokepoints: a
stair rises 0.6-0.7 m a metre along a flight (risers of at most 0.18 m on 0.28 m treads), so a piece of a stair with
landings about as long as its flights still climbs over a quarter, while a gallery reached by a stair at each end, a
ledge or a bridge between platforms climbs less. Measured (docs/plugins.md, "Stairs in one run"; regions with two
chokepoints at least 1 m apart in height): pieces of the monastery's, dam's, estate's and stairhall's stairs
0.32-0.75, the hillside's flights and the cinema's stepped aisles 0.23-0.41 (none of them in a run); galleries with a
stair at each end 0.02-0.04 (the estate's top gallery, 77 m long: 0.04), canyon ledges 0.06-0.21, tree bridges
0.06-0.24."""

WAY_ELONGATION = 10.0
"""A way's stub is carried on to its end (:func:`_way_ends`) only when the way is at least this many times as long as
it is wide on average (longest extent over mean walkable width): a causeway, a gallery, a long corridor, not a piece
of a room between pillars. Measured (docs/plugins.md, "Ways and their ends"): the lighthouse's causeway 25-29, a
gallery of the estate 32, a corridor of the bunker 52; pieces of pillared dungeon rooms whose gaps keep their mean
width 5.2-7.3 (grown, they took chokepoints off corridors' mouths)."""

EXTENT_DIRECTIONS = 8
"""Directions, evenly spread over 180 degrees, along which a region's longest extent is measured
(:func:`longest_extents`: at least cos(90 / 8 degrees) = 98 % of its diameter)."""


class DecompositionParams(PluginParams):
    """How the walkable surface is split into regions at chokepoints (shared by ``chokepoints`` and ``regions``)."""

    narrowness: float = Field(
        0.75, gt=0, lt=1,
        description="a passage is a chokepoint when its width is at most this fraction of the widest "
        "point of the rooms on both sides; a region whose chokepoints all lead to one region, at both its ends, "
        "and keep at least this fraction of its mean width joins it (side strips); two regions on one floor whose "
        "chokepoint keeps this fraction of both their mean widths are pieces of one way and join (ways)",
    )
    obstacle_area: float = Field(
        16.0, ge=0, description="holes in the walkable surface smaller than this (pillars, crates) neither "
        "narrow a room nor make a passage, m²",
    )
    through_holes: bool = Field(
        False, description="measure a portal that ends on such a small hole through it as well (at least the "
        "clearance of the hole's centre) when the gap beyond the hole along the portal's line is about as wide as the "
        "portal's own (two gaps of one opening): a row of trees or posts down an avenue no longer cuts it into pieces "
        "(the radial town, subway, cemetery); but fewer rooms of a pillared dungeon have a region of their own and "
        "cuts beside pillars near walls stay (docs/plugins.md, \"Cuts through the holes left out, between two "
        "gaps\"), so it is off by default",
    )
    min_region_area: float = Field(
        8.0, ge=0, description="smaller areas (slivers, corners) merge into a neighbour, m², unless walled in but for "
        "one opening (a small room behind its door)",
    )
    min_separation: float = Field(
        3.0, ge=0, description="chokepoints between the same two regions closer than this are one, metres"
    )
    passage_width: float = Field(
        1.4, ge=0, description="a region narrower than this on average (walkable area / longest extent, in agent "
        "diameters) is a passage: it joins the room it leads to when it leads to one only; two openings of one region "
        "pair side by side, each narrower than this with a passage behind it, are lanes: the two regions join",
    )
    pinch: float = Field(
        0.4, ge=0, le=1, description="a cut between two corridor-like regions (area at least 3 squares of their "
        "width, width at most 4 agent diameters) that keeps at least this fraction of the corridor's walkable width "
        "on both sides of it is a pinch (pilasters), not a chokepoint: the two regions are one (1: off)",
    )


@dataclass(frozen=True)
class Decomposition:
    """Regions and chokepoints of one navmesh.

    Attributes:
        labels: (P,) int64, the region of every navmesh polygon.
        regions: one JSON record per region, by id (see :func:`decompose`).
        chokepoints: one JSON record per chokepoint, by region pair (widest
            first); :func:`score` orders them by score and numbers them.
    """

    labels: np.ndarray
    regions: list[dict[str, Any]]
    chokepoints: list[dict[str, Any]]


def require_navmesh(context: Any, analyzer: str) -> Any:
    """The run's navmesh, or a one-line error for graphs built without one."""
    if context.navmesh is None:
        raise PluginError(
            f"the {analyzer} analyzer needs a navigation mesh (graph plugin 'navmesh'); "
            "a sampled graph has no portals to measure"
        )
    return context.navmesh


def boundary_edges(navmesh: Any) -> tuple[np.ndarray, np.ndarray]:
    """The navmesh's boundary edges (polygon edges with no neighbour): start and end points, (B,3) each, m."""
    return polygon_boundary_edges(navmesh)[1:]


def polygon_boundary_edges(navmesh: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The navmesh's boundary edges: (B,) the polygon of each, and its start and end points, (B,3) each, m."""
    polygons = np.asarray(navmesh.polygons, dtype=np.int64)
    valid = polygons >= 0
    count = valid.sum(axis=1)
    j = np.arange(polygons.shape[1])[None, :]
    following = np.where(j + 1 < count[:, None], j + 1, 0)
    rows, cols = np.nonzero(valid & (np.asarray(navmesh.neighbours) < 0))
    vertices = np.asarray(navmesh.vertices, dtype=np.float64)
    return rows, vertices[polygons[rows, cols]], vertices[polygons[rows, following[rows, cols]]]


def small_holes(start: np.ndarray, end: np.ndarray, max_area: float) -> np.ndarray:
    """(B,) int64: the hole (a loop id) of each boundary edge ``start`` -> ``end`` (B,3 each) that bounds a hole
    smaller than ``max_area`` m² (pillars, crates), -1 for the others.

    Boundary edges are joined into loops at equal end points (vertices equal
    to 1 cm, so loops close across tile borders; scipy connected components).
    A loop's signed xz area (shoelace, summed per loop) has one sign for
    outer boundaries and the other for holes; the outer sign is that of the
    loop with the largest area.
    """
    if len(start) == 0:
        return np.zeros(0, dtype=np.int64)
    _, vertex = np.unique(_point_keys(np.concatenate([start, end])), return_inverse=True)
    vertex = vertex.reshape(-1)
    n, b = int(vertex.max()) + 1, len(start)
    links = sparse.coo_array((np.ones(b), (vertex[:b], vertex[b:])), shape=(n, n))
    count, loop_of_vertex = csgraph.connected_components(links, directed=False)
    loop = loop_of_vertex[vertex[:b]]
    signed = 0.5 * np.bincount(loop, weights=start[:, 0] * end[:, 2] - end[:, 0] * start[:, 2], minlength=count)
    outer = np.sign(signed[np.argmax(np.abs(signed))])
    small_hole = (np.sign(signed) == -outer) & (np.abs(signed) < max_area)
    return np.where(small_hole[loop], loop, -1).astype(np.int64)


def wall_pieces(start: np.ndarray, end: np.ndarray, hole: np.ndarray, grown: float) -> np.ndarray:
    """(B,) bool: the edges of small holes (``hole`` (B,), :func:`small_holes`) that are pieces of wall between
    openings, not pillars: elongated (its longest plan extent squared at least :data:`WALL_PIECE_ELONGATION`
    times its area, which takes a wall turning a corner too; or the solid inside, the hole less ``grown`` m across
    each way, at least that many times as long as it is wide, its plan extent across the direction of its
    narrowest against that narrowest, and at least ``grown`` long: a shorter solid, a gravestone or a mullion, is
    a post whatever its shape), with both its ends (its extreme corners along its longest extent) nearer to the
    other walls (other holes' too) than it is long, and the middles of both its long sides farther from them than
    either end is.

    A hole's outline is the solid's grown by the agent's radius and about a navmesh cell of rasterisation each
    side (``grown``: the agent's diameter and a cell), which makes the pier of a 0.2 m wall look as compact as a
    post: a 2.5 x 0.2 m pier is a hole of about 3.75 x 1.5 m (docs/plugins.md, "Posts, niches and aisles").

    The wall between two doors is a small hole whose ends face the doors' far jambs, with a room on either
    side; a pillar or a post is compact, a pair of gravestones grown into one hole stands in open ground, and a
    row of desks has the next row or a wall beside it as near as the aisles at its ends. Counting the pieces as walls
    keeps a front of three doors from reading as one opening as wide as the front (docs/plugins.md, "One
    opening, one chokepoint"). Cost: O(B) for the holes' extents, then O(B) per elongated hole (the walls near
    its ends, whose distance is then exact: :func:`_distance_to`).
    """
    piece = np.zeros(len(start), dtype=bool)
    member = np.flatnonzero(hole >= 0)
    ids, index = np.unique(hole[member], return_inverse=True)
    if len(ids) == 0:
        return piece
    a, b = start[member], end[member]
    area = 0.5 * np.abs(np.bincount(index, weights=a[:, 0] * b[:, 2] - b[:, 0] * a[:, 2], minlength=len(ids)))
    spreads = directional_spreads(a[:, [0, 2]], index, len(ids))
    direction = np.argmax(spreads, axis=1)
    extent = spreads[np.arange(len(ids)), direction]
    narrowest = np.argmin(spreads, axis=1)  # a rectangle's diagonals spread farther than its length
    length = spreads[np.arange(len(ids)), (narrowest + EXTENT_DIRECTIONS // 2) % EXTENT_DIRECTIONS] - grown
    width = spreads[np.arange(len(ids)), narrowest] - grown  # the solid's, shorter than ``grown``: a post
    solid = length >= np.maximum(WALL_PIECE_ELONGATION * width, grown)
    elongated = (extent**2 >= WALL_PIECE_ELONGATION * area) | solid
    if not elongated.any():
        return piece
    plan_low, plan_high = np.minimum(start, end)[:, [0, 2]], np.maximum(start, end)[:, [0, 2]]
    for k in np.flatnonzero(elongated):  # few: pillars and posts are compact
        corners = a[index == k]
        angle = direction[k] * math.pi / EXTENT_DIRECTIONS
        axis = np.array([math.cos(angle), math.sin(angle)])
        across = np.array([-axis[1], axis[0]])
        lengthwise, crosswise = corners[:, [0, 2]] @ axis, corners[:, [0, 2]] @ across
        middle = 0.5 * (lengthwise.min() + lengthwise.max()) * axis
        sides = np.stack([middle + crosswise.min() * across, middle + crosswise.max() * across])  # long sides' middles
        points = np.concatenate([corners[[np.argmin(lengthwise), np.argmax(lengthwise)]],
                                 np.insert(sides, 1, corners[:, 1].mean(), axis=1)])
        box_low, box_high = points[:, [0, 2]].min(axis=0) - extent[k], points[:, [0, 2]].max(axis=0) + extent[k]
        nearby = (plan_high >= box_low).all(axis=1) & (plan_low <= box_high).all(axis=1)
        other = np.flatnonzero(nearby & (hole != ids[k]))
        gaps, room = np.split(_distance_to(points, start[other], end[other]), 2)
        piece[member[index == k]] = bool((gaps <= extent[k]).all() and room.min() > gaps.max())
    return piece


def _point_keys(points: np.ndarray) -> np.ndarray:
    """(N,) int64 keys equal for points equal to 1 cm (21 bits a coordinate: levels up to 20 km across)."""
    cells = np.round(points * 100.0).astype(np.int64)
    if len(cells):  # counted from the level's own corner, so a level far from the origin keys as one near it
        cells -= cells.min(axis=0)
    if cells.size and cells.max() >= 1 << 21:
        raise PluginError("the level is more than 20 km across; chokepoints and regions cannot key its vertices")
    return (cells[:, 0] << 42) | (cells[:, 1] << 21) | cells[:, 2]


def wall_samples(start: np.ndarray, end: np.ndarray, spacing: float) -> np.ndarray:
    """(K,3) points every ``spacing`` metres (at most) along the edges ``start`` -> ``end`` (B,3)."""
    pieces = np.maximum(np.ceil(np.linalg.norm(end - start, axis=1) / spacing), 1).astype(np.int64)
    edge = np.repeat(np.arange(len(start)), pieces + 1)
    offsets = np.arange(len(edge)) - np.repeat(np.cumsum(pieces + 1) - (pieces + 1), pieces + 1)
    t = (offsets / pieces[edge])[:, None]
    return start[edge] * (1.0 - t) + end[edge] * t


def _pieces(start: np.ndarray, end: np.ndarray, scale: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The segments ``start`` -> ``end`` (B,3 each), their coordinates times ``scale`` (3,), cut into pieces at most
    :data:`PIECE` long: each piece's start and end points, (K,3) each, and (K,) the segment it is cut from."""
    ends = wall_samples(start * scale, end * scale, PIECE)
    count = np.maximum(np.ceil(np.linalg.norm((end - start) * scale, axis=1) / PIECE), 1).astype(np.int64) + 1
    is_start = np.ones(len(ends), dtype=bool)
    is_start[np.cumsum(count) - 1] = False  # a piece runs from each sample to the next one of its edge
    return ends[is_start], ends[np.flatnonzero(is_start) + 1], np.repeat(np.arange(len(start)), count)[is_start]


def _distance_to(points: np.ndarray, start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """Distance (m, heights scaled) from each of ``points`` (N,3) to the nearest segment ``start`` -> ``end``
    (B,3 each; inf when there is none).

    Segments are cut into pieces at most :data:`PIECE` long; a kd-tree over the
    pieces' midpoints gives each point its :data:`NEAREST_PIECES` nearest
    pieces, and the exact point-segment distance to those is taken.
    """
    if len(start) == 0:
        return np.full(len(points), np.inf)
    scale = np.array([1.0, HEIGHT_SCALE, 1.0])
    a, b, _ = _pieces(start, end, scale)
    k = min(NEAREST_PIECES, len(a))
    q = points * scale
    nearest = spatial.cKDTree(0.5 * (a + b)).query(q, k=k)[1].reshape(len(q), k)
    pa, pb = a[nearest], b[nearest]
    d = pb - pa
    t = np.clip(np.einsum("nkc,nkc->nk", q[:, None] - pa, d) / np.maximum(np.einsum("nkc,nkc->nk", d, d), 1e-12), 0, 1)
    return np.linalg.norm(q[:, None] - (pa + t[..., None] * d), axis=2).min(axis=1)


@dataclass(frozen=True)
class Clearances:
    """How far the navmesh's polygon centres and portals are from its walls, m.

    Attributes:
        polygons: (P,) clearance of each polygon centre (:func:`measured_centres`), small holes ignored.
        portals_open: (E,) clearance of each portal, small holes ignored (with ``through_holes``, a portal ending on
            one measured through it: :func:`_through_holes`).
        portals: (E,) clearance of each portal, every wall counted.
        widest: (E,3) each portal's point of largest clearance (every wall counted).
        open_walls: the walls the clearances that split the level are measured to (small holes left out):
            start and end points, (B',3) each, m.
        holes: the small holes' boundary (wall pieces too: a piece less than half as wide as the doors beside it
            is a pier in one opening, :func:`_post_links`): their edges' start points, (H,3) m, and the hole of
            each, (H,) int64.
        left_out: (B,) int64, for each boundary edge (:func:`boundary_edges` order) the small hole it bounds when
            that hole is left out of the clearances (a pillar, a post: not a wall piece), -1 for the others.
    """

    polygons: np.ndarray
    portals_open: np.ndarray
    portals: np.ndarray
    widest: np.ndarray
    open_walls: tuple[np.ndarray, np.ndarray]
    holes: tuple[np.ndarray, np.ndarray]
    left_out: np.ndarray


def measured_centres(navmesh: Any) -> np.ndarray:
    """(P, 3) the polygons' centres as the split measures them, m: :data:`CENTRE_LIFT` over the floor, whatever the
    navmesh's cell height. Recast lifts its detail surface, and with it ``navmesh.centres``, one cell height over the
    polygons' corners (measured: docs/plugins.md, "Regions on the agent's climb cells")."""
    centres = np.asarray(navmesh.centres, dtype=np.float64).reshape(-1, 3).copy()
    centres[:, 1] += CENTRE_LIFT - float(navmesh.settings["cell_height"])
    return centres


def portal_samples(ends: np.ndarray, spacing: float) -> tuple[np.ndarray, np.ndarray]:
    """Points along each portal ``ends`` (E,2,3) where its clearance is measured: (K,3) points, m, and (K,) portal index.

    A portal of length L gets n points at the middles of its n equal parts
    (0.1, 0.3 ... 0.9 for n = 5), n the smallest odd number at or above
    max(:data:`PORTAL_SAMPLES`, ceil(L / spacing)). On flat ground a clearance
    changes by at most the distance moved, so the largest sample is within ``spacing`` / 2
    of the portal's largest clearance, and a door's portal (wall to wall,
    widest in its middle) is measured exactly. Why not five points always:
    where walls lie at an angle to Recast's voxel grid, a thin polygon along a
    wall can border a corridor's mouth with one long portal, of which the
    mouth is a short stretch that five points may all miss (measured on
    turned dungeons: docs/plugins.md, turned levels).
    """
    length = np.linalg.norm(ends[:, 1] - ends[:, 0], axis=1)
    count = np.maximum(np.ceil(length / spacing), PORTAL_SAMPLES).astype(np.int64) | 1  # odd: the middle is one
    portal = np.repeat(np.arange(len(ends)), count)
    k = np.arange(len(portal)) - np.repeat(np.cumsum(count) - count, count)
    t = ((k + 0.5) / count[portal])[:, None]
    return ends[portal, 0] * (1.0 - t) + ends[portal, 1] * t, portal


def _ray_hits(origin: np.ndarray, direction: np.ndarray, start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """(S,) how far (m) along the ray ``origin`` + t ``direction`` (plan (x, z), t > 0, unit direction) it crosses each
    segment ``start`` -> ``end`` (S, 2), inf for the segments it misses. O(S)."""
    edge = end - start
    offset = start - origin
    denominator = direction[0] * edge[:, 1] - direction[1] * edge[:, 0]
    parallel = np.abs(denominator) < 1e-12
    denominator = np.where(parallel, 1.0, denominator)
    along = (offset[:, 0] * edge[:, 1] - offset[:, 1] * edge[:, 0]) / denominator
    across = (offset[:, 0] * direction[1] - offset[:, 1] * direction[0]) / denominator
    return np.where(~parallel & (along > 1e-9) & (across >= -1e-9) & (across <= 1.0 + 1e-9), along, np.inf)


def _between_gaps(ends: np.ndarray, side: np.ndarray, hole: np.ndarray, start: np.ndarray, end: np.ndarray,
                  left_out: np.ndarray, wall_to_wall: float) -> np.ndarray:
    """(K,) bool: whether each portal ``ends`` (K, 2, 3), ending at ``side`` (K,) on the left-out small hole ``hole``
    (K,), is one of two gaps of one opening either side of that hole (:func:`_through_holes`).

    The portal's line is carried on past its end on the hole, through the hole (to where it leaves the hole's
    outline) and across the floor beyond it to the next boundary edge (a wall or another hole), in plan, over
    the boundary edges ``start`` -> ``end`` (B, 3) cut into :data:`PIECE` pieces (``left_out`` (B,): the hole of
    each, :class:`Clearances`). The gap beside the hole is the portal, the gap beyond it that stretch of floor; both
    walkable, so each is widened by ``wall_to_wall`` (m) to wall to wall. They are one opening's when the narrower
    is at least :data:`THROUGH_GAP_SHARE` as wide as the wider. O(B log B) to sort the edges by hole and build the
    kd-tree over their pieces, then per portal a binary search, a ball query and O(h + q) for the hole's h edges and
    the q pieces within its reach.
    """
    scale = np.array([1.0, HEIGHT_SCALE, 1.0])
    a, b, edge_of = _pieces(start, end, np.ones(3))
    tree = spatial.cKDTree(0.5 * (a + b) * scale)
    by_hole = np.argsort(left_out, kind="stable")  # each hole's edges, found by binary search
    bounds = np.searchsorted(left_out[by_hole], np.stack([hole, hole + 1]))
    paired = np.zeros(len(ends), dtype=bool)
    for k in range(len(ends)):
        there, other = ends[k, side[k]], ends[k, 1 - side[k]]
        direction = (there - other)[[0, 2]]
        near = float(np.linalg.norm(direction))
        if near < 1e-9:
            continue
        direction /= near
        own = by_hole[bounds[0, k]:bounds[1, k]]
        leaves = _ray_hits(there[[0, 2]] - 1e-6 * direction, direction, start[own][:, [0, 2]], end[own][:, [0, 2]])
        leaves = float(leaves[np.isfinite(leaves)].max()) if np.isfinite(leaves).any() else 0.0
        exit_point = there + leaves * np.array([direction[0], 0.0, direction[1]])
        reach = (near + wall_to_wall) / THROUGH_GAP_SHARE - wall_to_wall  # a farther wall makes the gaps unequal
        near_pieces = np.asarray(tree.query_ball_point(exit_point * scale, reach + PIECE), dtype=np.int64)
        near_pieces = near_pieces[left_out[edge_of[near_pieces]] != hole[k]]
        far = _ray_hits(exit_point[[0, 2]], direction, a[near_pieces][:, [0, 2]], b[near_pieces][:, [0, 2]])
        far = float(far.min()) if len(far) else np.inf
        gaps = np.array([near, far]) + wall_to_wall
        paired[k] = bool(np.isfinite(far) and gaps.min() >= THROUGH_GAP_SHARE * gaps.max())
    return paired


def _through_holes(ends: np.ndarray, start: np.ndarray, end: np.ndarray, left_out: np.ndarray,
                   walls: tuple[np.ndarray, np.ndarray], wall_to_wall: float) -> np.ndarray:
    """(E,) the largest clearance (to ``walls``, start and end (B', 3) m: the walls with the small holes left out) at
    the centres of the left-out small holes each portal ``ends`` (E, 2, 3) ends on as one of two gaps either side of
    the hole (:func:`_between_gaps`; 0 for a portal that ends on none); ``start``, ``end`` (B, 3): the boundary
    edges, ``left_out`` (B,): the left-out hole each bounds, -1 for none (:class:`Clearances`); ``wall_to_wall``: the
    agent's diameter and a navmesh cell, m. A hole's centre is the mean of its outline's corners.

    Recast's polygons go round a small hole, so the portals beside a pillar or a tree run from the hole to a wall and
    do not cross the floor where the hole stands: with the hole left out, the cut there runs on through it (as
    :func:`_join_ways_round` closes it), and its clearance is at least that of the hole's centre. Without this the
    portals beside a trunk of a row of trees down an avenue measure 3.04-4.27 m of clearance where the avenue's
    middle has 4.5 m (the radial town; docs/plugins.md, "Cuts through the holes left out"): narrower than the
    polygons beside them by ``narrowness`` or not, as Recast placed those polygons' centres, so the avenues were cut
    at some trees and not at others. But only a hole with a gap of about the portal's width beyond it stands in
    the opening the portal crosses (a tree in an avenue, a post in a gate, a bench between two lanes of a
    platform): a pillar standing before a corridor's mouth, with the room open beyond it, has the room's clearance
    at its centre, not the corridor's (docs/plugins.md, "Cuts through the holes left out, between two gaps").
    O(E + B) and a nearest-wall search per hole, and :func:`_between_gaps` per portal on a hole.
    """
    on_hole = np.flatnonzero(left_out >= 0)
    through = np.zeros(len(ends))
    if len(on_hole) == 0 or len(ends) == 0:
        return through
    ids, member = np.unique(left_out[on_hole], return_inverse=True)
    centre = np.zeros((len(ids), 3))
    np.add.at(centre, member, start[on_hole])
    centre /= np.bincount(member, minlength=len(ids))[:, None]
    at_centre = _distance_to(centre, *walls)
    hole = _holes_at(ends.reshape(-1, 3), start, left_out).reshape(-1, 2)
    portal, side = np.nonzero(hole >= 0)
    paired = _between_gaps(ends[portal], side, hole[portal, side], start, end, left_out, wall_to_wall)
    portal, side = portal[paired], side[paired]
    np.maximum.at(through, portal, at_centre[np.searchsorted(ids, hole[portal, side])])
    return through


def clearances(navmesh: Any, obstacle_area: float, wall_to_wall: float, through_holes: bool) -> Clearances:
    """The clearances of ``navmesh`` (a portal's is the largest of its :func:`portal_samples`, one navmesh cell apart).

    Small holes (:func:`small_holes`: pillars, crates; not :func:`wall_pieces`, whose outlines are grown by
    ``wall_to_wall``, m) are left out of the clearances that split the level, so that they neither make a room as
    narrow as its doors nor make passages of their own; the width reported
    for a chokepoint counts them. With ``through_holes``, a portal that ends on such a hole is measured through it
    too (:func:`_through_holes`).
    """
    start, end = boundary_edges(navmesh)
    hole = small_holes(start, end, obstacle_area)
    obstacle = (hole >= 0) & ~wall_pieces(start, end, hole, wall_to_wall)
    ends = np.asarray(navmesh.portals().endpoints, dtype=np.float64)
    points, portal = portal_samples(ends, float(navmesh.settings["cell_size"]))
    walls = _distance_to(points, start[~obstacle], end[~obstacle])
    every = np.minimum(walls, _distance_to(points, start[obstacle], end[obstacle]))
    first = np.searchsorted(portal, np.arange(len(ends)))
    widest = np.lexsort((-every, portal))[first]  # each portal's first sample of largest clearance
    left_out = np.where(obstacle, hole, -1)
    portals_open = np.maximum.reduceat(walls, first) if len(ends) else np.zeros(0)
    if through_holes:
        portals_open = np.maximum(portals_open,
                                  _through_holes(ends, start, end, left_out, (start[~obstacle], end[~obstacle]),
                                                 wall_to_wall))
    return Clearances(
        polygons=_distance_to(measured_centres(navmesh), start[~obstacle], end[~obstacle]),
        portals_open=portals_open,
        portals=every[widest],
        widest=points[widest],
        open_walls=(start[~obstacle], end[~obstacle]),
        holes=(start[hole >= 0], hole[hole >= 0]),
        left_out=left_out,
    )


@dataclass(frozen=True)
class Outlines:
    """What a group of navmesh polygons is bounded by: walls, or portals to the rest of the level.

    The merge tree asks it whether a group under ``min_region_area`` is walled in but for one opening (step 2 of
    the module doc); a group's exits are found through its polygons' portals, O(k) for k polygons and their portals.

    Attributes:
        walls: (P,) length of each polygon's boundary edges (walls, small holes' outlines included), m.
        portal_length: (E,) length of each portal, m.
        portals_of: CSR of polygon -> portal ids, ``(indptr (P+1,), portal ids (2E,))``.
        pairs: (E, 2) each portal's two polygons; ``endpoints``: (E, 2, 3) their end points, m.
        corners: (P, K, 2) each polygon's corners in plan (x, z), NaN past its last, m.
        footprint: groups smaller than this (m²) are never rooms of their own.
        enclosure: a group under ``min_region_area`` is a room when at least this share of its outline is wall
            (and its exits are one opening: :meth:`one_opening`).
    """

    walls: np.ndarray
    portal_length: np.ndarray
    portals_of: tuple[np.ndarray, np.ndarray]
    pairs: np.ndarray
    endpoints: np.ndarray
    corners: np.ndarray
    footprint: float
    enclosure: float

    def exits(self, polygons: list[int]) -> np.ndarray:
        """The portals from the group ``polygons`` to polygons outside it, ids."""
        inside = np.asarray(polygons, dtype=np.int64)
        indptr, ids = self.portals_of
        touching = np.unique(np.concatenate([ids[indptr[p]:indptr[p + 1]] for p in inside]))
        return touching[~np.isin(self.pairs[touching], inside).all(axis=1)]

    def wall_share(self, polygons: list[int]) -> float:
        """The share of the outline of the group ``polygons`` that is wall (0-1): its walls' length over that and the
        length of its portals to polygons outside it."""
        wall = float(self.walls[polygons].sum())
        return wall / max(wall + float(self.portal_length[self.exits(polygons)].sum()), 1e-12)

    def one_opening(self, polygons: list[int]) -> bool:
        """Whether the portals out of the group ``polygons`` lie together at one side of it: their end points spread
        over at most :data:`SMALL_ROOM_OPENING` of the group's longest plan extent (a door, not a piece of walkway
        open at both ends)."""
        ends = self.endpoints[self.exits(polygons)].reshape(-1, 3)[:, [0, 2]]
        corners = self.corners[polygons].reshape(-1, 2)
        corners = corners[np.isfinite(corners[:, 0])]
        spread = plan_spreads(ends, np.zeros(len(ends), dtype=np.int64), 1)[0]
        return bool(spread <= SMALL_ROOM_OPENING * plan_spreads(corners, np.zeros(len(corners), dtype=np.int64), 1)[0])

    def enclosed(self, polygons: list[int]) -> bool:
        """Whether the group ``polygons`` is walled in all round but for one opening (``enclosure`` of its outline is
        wall, :meth:`one_opening`)."""
        return self.wall_share(polygons) >= self.enclosure and self.one_opening(polygons)


def portals_of(pairs: np.ndarray, count: int) -> tuple[np.ndarray, np.ndarray]:
    """CSR of polygon -> portal ids for ``count`` polygons and the portals ``pairs`` (E, 2) (each portal's two
    polygons): ``(indptr (count+1,), portal ids (2E,))``, a polygon's portals in id order."""
    owner = pairs.reshape(-1)
    indptr = np.concatenate([[0], np.cumsum(np.bincount(owner, minlength=count))])
    return indptr, np.argsort(owner, kind="stable") // 2


def outlines(navmesh: Any, pairs: np.ndarray, endpoints: np.ndarray, footprint: float,
             enclosure: float) -> Outlines:
    """The :class:`Outlines` of ``navmesh``'s polygons (``pairs`` (E, 2) and ``endpoints`` (E, 2, 3): its portals)."""
    owner_of_wall, start, end = polygon_boundary_edges(navmesh)
    polygons = np.asarray(navmesh.polygons, dtype=np.int64)
    valid = polygons >= 0
    vertices = np.asarray(navmesh.vertices, dtype=np.float64)
    n = len(polygons)
    return Outlines(walls=np.bincount(owner_of_wall, weights=np.linalg.norm(end - start, axis=1), minlength=n),
                    portal_length=np.linalg.norm(endpoints[:, 1] - endpoints[:, 0], axis=1),
                    portals_of=portals_of(pairs, n), pairs=pairs, endpoints=endpoints,
                    corners=np.where(valid[..., None], vertices[np.where(valid, polygons, 0)][..., [0, 2]], np.nan),
                    footprint=footprint, enclosure=enclosure)


@dataclass
class DoorWidths:
    """Clear widths, wall to wall in the level's mesh, of small groups of polygons and of the doors out of them.

    The navmesh is eroded by the agent's radius and rasterised on its cell, so the stubs of wall beside a door
    (0.2-0.4 m) are within a cell of vanishing and a door's walkable width reads as wide as its room's or wider
    (docs/plugins.md, "Posts, niches and aisles"). The level's own walls are not: the clear width at a point is the
    shortest horizontal chord through it over :data:`EXTENT_DIRECTIONS` directions (two rays each, against the
    mesh, at half the agent's height above the navmesh), exact for a door or a rectangular room whatever the
    level's yaw. A door's is the shortest at points along its portal's normal through the portal's widest point,
    up to the agent's diameter either side, :data:`DOOR_STEP` apart (a portal lies up to about a radius and a cell
    from the doorway, in the room or outside it); a group's, the longest at its polygons' centres. Chords are cast
    on first use, for the few groups the outline rule keeps apart, and kept: O(k) rays for k polygons and portals
    asked about (Embree through :class:`g2s_plugins._raycasting.RayCaster`).

    Attributes:
        mesh: the level, metres, Y up.
        centres: (P, 3) navmesh polygon centres, m.
        widest: (E, 3) each portal's point of largest clearance (:class:`Clearances`), m.
        endpoints: (E, 2, 3) each portal's end points, m.
        agent: the agent settings (``radius``, ``height``, m).
    """

    mesh: trimesh.Trimesh
    centres: np.ndarray
    widest: np.ndarray
    endpoints: np.ndarray
    agent: Any
    _polygons: dict[int, float] = field(default_factory=dict, init=False, repr=False)
    _portals: dict[int, float] = field(default_factory=dict, init=False, repr=False)

    @cached_property
    def _caster(self) -> RayCaster:
        return RayCaster(self.mesh)

    def chords(self, points: np.ndarray) -> np.ndarray:
        """(N,) the shortest horizontal chord through each of ``points`` (N, 3), m (inf where a ray leaves the level, or
        where the point lies inside a solid: a ray meets the back of a wall first)."""
        angle = np.arange(EXTENT_DIRECTIONS) * (math.pi / EXTENT_DIRECTIONS)
        directions = np.stack([np.cos(angle), np.zeros(EXTENT_DIRECTIONS), np.sin(angle)], axis=1)
        origins = np.repeat(points + [0.0, 0.5 * float(self.agent.height), 0.0], EXTENT_DIRECTIONS, axis=0)
        ahead, behind = self._caster.first_hits_of([(origins, np.tile(directions, (len(points), 1))),
                                                    (origins, np.tile(-directions, (len(points), 1)))])
        chord = ahead.distance + behind.distance
        chord[hit_from_behind(self._caster, ahead) | hit_from_behind(self._caster, behind)] = np.inf  # in a solid
        return chord.reshape(len(points), EXTENT_DIRECTIONS).min(axis=1)

    def door(self, portal: int) -> float:
        """The clear width of the door of ``portal`` (the shortest near its widest point, across it), m."""
        if portal not in self._portals:
            a, b = self.endpoints[portal]
            along = np.array([b[0] - a[0], b[2] - a[2]]) / max(math.hypot(b[0] - a[0], b[2] - a[2]), 1e-12)
            reach = math.ceil(2.0 * float(self.agent.radius) / DOOR_STEP)  # one agent diameter either side
            offsets = np.arange(-reach, reach + 1) * DOOR_STEP
            normal = np.array([-along[1], 0.0, along[0]])
            self._portals[portal] = float(self.chords(self.widest[portal] + offsets[:, None] * normal).min())
        return self._portals[portal]

    def narrower(self, polygons: list[int], exits: np.ndarray) -> bool:
        """Whether the door of the group ``polygons`` (its widest exit of ``exits``, portal ids) is narrower than the
        group: under :data:`SMALL_ROOM_DOOR` of its clear width."""
        missing = [p for p in polygons if p not in self._polygons]
        if missing:
            self._polygons.update(zip(missing, self.chords(self.centres[missing]).tolist()))
        room = max(self._polygons[p] for p in polygons)
        return max(self.door(int(e)) for e in exits) < SMALL_ROOM_DOOR * room


def _merge_tree(pairs: np.ndarray, portal_clearance: np.ndarray, polygon_clearance: np.ndarray,
                areas: np.ndarray, narrowness: float, min_area: float,
                outline: Outlines, doors: DoorWidths) -> tuple[np.ndarray, np.ndarray]:
    """(merged, blocked): boolean masks over the portals (step 2 of the module doc)."""
    n = len(polygon_clearance)
    parent = list(range(n))
    peak = polygon_clearance.tolist()
    area = areas.tolist()
    following = [-1] * n  # each group's polygons as a chain from its root, so that a small group's outline is measured
    last = list(range(n))
    merged = np.zeros(len(pairs), dtype=bool)
    blocked = np.zeros(len(pairs), dtype=bool)

    def members(root: int) -> list[int]:  # a small group's polygons: few
        found = [root]
        while following[found[-1]] >= 0:
            found.append(following[found[-1]])
        return found

    def room(root: int) -> bool:
        if area[root] >= min_area:
            return True
        if area[root] < outline.footprint:
            return False
        group = members(root)
        return outline.enclosed(group) and doors.narrower(group, outline.exits(group))

    def find(x: int) -> int:
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    order = np.lexsort((np.arange(len(pairs)), -portal_clearance))
    a_list, b_list, c_list = pairs[order, 0].tolist(), pairs[order, 1].tolist(), portal_clearance[order].tolist()
    for e, a, b, c in zip(order.tolist(), a_list, b_list, c_list):
        ra, rb = find(a), find(b)
        if ra == rb:
            continue
        if c <= narrowness * min(peak[ra], peak[rb]) and room(ra) and room(rb):
            blocked[e] = True
            continue
        if area[ra] < area[rb]:
            ra, rb = rb, ra
        parent[rb] = ra
        following[last[ra]] = rb
        last[ra] = last[rb]
        peak[ra] = max(peak[ra], peak[rb])
        area[ra] += area[rb]
        merged[e] = True
    return merged, blocked


def plan_spreads(xz: np.ndarray, owner: np.ndarray, count: int) -> np.ndarray:
    """(count,) how far apart each group's points reach in plan, m: the largest of their spreads along
    :data:`EXTENT_DIRECTIONS` directions evenly spread over 180 degrees (within 2 % of the farthest pair's
    distance); 0 for a group with no point. ``xz``: (V, 2) points, ``owner``: (V,) the group of each."""
    return directional_spreads(xz, owner, count).max(axis=1)


def directional_spreads(xz: np.ndarray, owner: np.ndarray, count: int) -> np.ndarray:
    """(count, D) how far each group's points ``xz`` (V, 2) reach along each of the D = :data:`EXTENT_DIRECTIONS`
    directions at angles ``d * 180 / D`` degrees from +x towards +z, m (0 for a group with no point; ``owner``
    (V,) is the group of each point)."""
    angle = np.arange(EXTENT_DIRECTIONS) * (math.pi / EXTENT_DIRECTIONS)
    along = xz @ np.stack([np.cos(angle), np.sin(angle)])  # (V, D) each point along each direction
    low = np.full((count, EXTENT_DIRECTIONS), np.inf)
    high = np.full((count, EXTENT_DIRECTIONS), -np.inf)
    np.minimum.at(low, owner, along)
    np.maximum.at(high, owner, along)
    return np.where(np.isfinite(low), high - low, 0.0)


def longest_extents(navmesh: Any, labels: np.ndarray, count: int) -> np.ndarray:
    """(count,) the longest plan (xz) extent of each region of ``labels`` (P,), m: the largest of its
    widths along :data:`EXTENT_DIRECTIONS` directions, over its polygons' corners."""
    polygons = np.asarray(navmesh.polygons, dtype=np.int64)
    rows, cols = np.nonzero(polygons >= 0)
    xz = np.asarray(navmesh.vertices, dtype=np.float64)[polygons[rows, cols]][:, [0, 2]]
    return plan_spreads(xz, labels[rows], count)


def mean_widths(navmesh: Any, labels: np.ndarray, areas: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(G,) the mean walkable width of each group of ``labels`` (P,), m: its area (``areas`` (P,), m²) over its
    longest extent; and (G,) that extent (:func:`longest_extents`), m."""
    count = int(labels.max()) + 1 if len(labels) else 0
    extents = longest_extents(navmesh, labels, count)
    return np.bincount(labels, weights=areas, minlength=count) / np.maximum(extents, 1e-9), extents


def join_side_strips(labels: np.ndarray, cuts: np.ndarray, width: np.ndarray, points: np.ndarray,
                     mean_width: np.ndarray, extent: np.ndarray, narrowness: float, separation: float) -> np.ndarray:
    """(P,) int64 region labels once side strips are joined to the region they run beside (step 3 of the module doc).

    A region all of whose chokepoint candidates lead to one other region, at both its ends (candidates spread at
    least :data:`STRIP_ENDS` of its longest extent and ``separation`` apart: the two go round something, as an
    aisle and its hall go round a rack), and whose widest candidate keeps at least ``narrowness`` of its own mean
    width, is a strip beside that region, not a room behind doors: it joins that region. A room with two doors to
    one corridor is far wider than its doors; a dead end (one place) is left to the merge tree.

    Args:
        labels: (P,) the region of every polygon.
        cuts: (C, 2) the two polygons of every chokepoint candidate.
        width: (C,) each candidate's walkable width (small holes left out), m.
        points: (C, 3) each candidate's widest point, m.
        mean_width: (G,) each region's mean walkable width (:func:`mean_widths`), m.
        extent: (G,) each region's longest extent (:func:`longest_extents`), m.
        narrowness: the fraction of a region's mean width a candidate must keep for the region to be a strip.
        separation: how far apart (plan) a strip's candidates reach at least, m.
    """
    count = len(mean_width)
    sides = labels[cuts]
    between = sides[:, 0] != sides[:, 1]
    sides, width, plan = sides[between], width[between], points[between][:, [0, 2]]
    ends = np.concatenate([sides, sides[:, ::-1]])  # (region, neighbour) both ways
    widths, plan = np.concatenate([width, width]), np.concatenate([plan, plan])
    neighbours = np.unique(ends, axis=0)
    one_neighbour = np.bincount(neighbours[:, 0], minlength=count) == 1
    widest = np.zeros(count)
    np.maximum.at(widest, ends[:, 0], widths)
    at_ends = plan_spreads(plan, ends[:, 0], count) >= np.maximum(separation, STRIP_ENDS * extent)
    strip = one_neighbour & at_ends & (widest >= narrowness * mean_width)
    return join_groups(labels, count, ends[strip[ends[:, 0]]])


def join_passages(labels: np.ndarray, sides: np.ndarray, passage: np.ndarray) -> np.ndarray:
    """(P,) int64 region labels once passages are joined (step 3 of the module doc).

    Args:
        labels: (P,) the merge tree's group of every polygon.
        sides: (C, 2) the groups on the two sides of every chokepoint candidate.
        passage: (G,) bool, whether each group is a passage.

    Returns:
        (P,) the region of every polygon, regions numbered by their lowest polygon id.
    """
    count = len(passage)
    sides = sides[sides[:, 0] != sides[:, 1]]
    both = passage[sides].all(axis=1)
    links = sparse.coo_array((np.ones(int(both.sum())), (sides[both, 0], sides[both, 1])), shape=(count, count))
    system = csgraph.connected_components(links, directed=False)[1]  # passages joined by candidates
    one = passage[sides].sum(axis=1) == 1
    way = np.where(passage[sides[one, 0]][:, None], sides[one], sides[one, ::-1])  # (passage, room)
    ways = np.unique(np.column_stack([system[way[:, 0]], way[:, 1]]), axis=0)  # (passage system, room)
    rooms_reached = np.bincount(ways[:, 0], minlength=count)
    into = way[rooms_reached[system[way[:, 0]]] == 1]  # passages of systems that lead to one room
    return join_groups(labels, count, np.concatenate([sides[both], into]))


def join_groups(labels: np.ndarray, count: int, links: np.ndarray) -> np.ndarray:
    """(P,) int64: the groups ``labels`` (P,) of ``count`` groups joined along ``links`` (K, 2) group pairs
    (scipy connected components), numbered by their lowest polygon id."""
    graph = sparse.coo_array((np.ones(len(links)), (links[:, 0], links[:, 1])), shape=(count, count))
    group = csgraph.connected_components(graph, directed=False)[1][labels]
    _, first, group = np.unique(group, return_index=True, return_inverse=True)
    return np.argsort(np.argsort(first))[group.reshape(-1)].astype(np.int64)


def widest_widths(labels: np.ndarray, count: int, polygon_clearance: np.ndarray, pairs: np.ndarray,
                  portal_clearance: np.ndarray) -> np.ndarray:
    """(count,) each group's widest walkable width, m: twice the largest clearance of its polygon centres
    (P,) and of the portals (E,) inside it (``pairs`` (E, 2): a portal's two polygons), so that a corridor
    whose polygon centres lie off its middle is measured across its portals."""
    widest = np.zeros(count)
    np.maximum.at(widest, labels, polygon_clearance)
    inside = labels[pairs[:, 0]] == labels[pairs[:, 1]]
    np.maximum.at(widest, labels[pairs[inside, 0]], portal_clearance[inside])
    return 2.0 * widest


def local_widths(navmesh: Any, labels: np.ndarray, points: np.ndarray, sides: np.ndarray, reach: np.ndarray,
                 walls: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """(C, 2) the walkable width of each of the two groups ``sides`` (C, 2) near each cut ``points`` (C, 3), m:
    twice the largest clearance (to ``walls``, start and end (B, 3)) of that group's floor within ``reach``
    (C,) metres of the point in plan (0 where it has none).

    The floor is sampled on a square grid one navmesh cell apart, centred on the cut; a grid point belongs
    to the group of the (convex) polygon holding it in plan and stands as high as that polygon's centre is measured
    (:func:`measured_centres`). On
    flat ground the largest sample is within 0.71 cells of the largest clearance.
    """
    polygons = np.asarray(navmesh.polygons, dtype=np.int64)
    valid = polygons >= 0
    corners = np.asarray(navmesh.vertices, dtype=np.float64)[np.where(valid, polygons, 0)][..., [0, 2]]
    following = np.roll(corners, -1, axis=1)
    last = valid.sum(axis=1) - 1
    following[np.arange(len(polygons)), last] = corners[:, 0]  # each polygon's last corner closes on its first
    low = np.where(valid[..., None], corners, np.inf).min(axis=1)
    high = np.where(valid[..., None], corners, -np.inf).max(axis=1)
    heights = measured_centres(navmesh)[:, 1]
    cell = float(navmesh.settings["cell_size"])
    samples, owner = [], []
    for i, (point, pair, radius) in enumerate(zip(points, sides, reach)):
        steps = np.arange(-math.floor(radius / cell), math.floor(radius / cell) + 1) * cell
        grid = np.stack(np.meshgrid(steps, steps), axis=-1).reshape(-1, 2)
        grid = grid[np.einsum("kc,kc->k", grid, grid) <= radius * radius] + point[[0, 2]]
        near = np.flatnonzero(np.isin(labels, pair) & (low <= point[[0, 2]] + radius).all(axis=1)
                              & (high >= point[[0, 2]] - radius).all(axis=1))
        edge = (following - corners)[near]
        offset = grid[None, None, :, :] - corners[near][:, :, None, :]
        cross = edge[..., 0, None] * offset[..., 1] - edge[..., 1, None] * offset[..., 0]  # (M, 6, Q)
        pad = ~valid[near][..., None]
        inside = ((cross >= -1e-9) | pad).all(axis=1) | ((cross <= 1e-9) | pad).all(axis=1)  # either winding
        holder, sample = np.nonzero(inside)
        sample, first = np.unique(sample, return_index=True)
        polygon = near[holder[first]]
        samples.append(np.column_stack([grid[sample, 0], heights[polygon], grid[sample, 1]]))
        owner.append(2 * i + (labels[polygon] == pair[1]))
    widths = np.zeros(2 * len(points))
    if samples:
        clearance = _distance_to(np.concatenate(samples), *walls)
        np.maximum.at(widths, np.concatenate(owner), 2.0 * clearance)
    return widths.reshape(-1, 2)


def pinches(cut: np.ndarray, local: np.ndarray, pinch: float, narrowness: float) -> np.ndarray:
    """(C,) bool: which cuts between corridor-like groups are pinches, not chokepoints (step 3 of the module doc).

    Args:
        cut: (C,) walkable width of each cut, m.
        local: (C, 2) the walkable width of the groups on its two sides near it (:func:`local_widths`), m.
        pinch: a pinch keeps at least this fraction of the local width on both sides (narrower: a door) ...
        narrowness: ... and at most this fraction (wider: the cut is the mouth of a passage as narrow as it).
    """
    keeps = cut[:, None] / np.maximum(local, 1e-9)
    return ((keeps >= pinch) & (keeps <= narrowness)).all(axis=1)


def floor_bands(heights: np.ndarray, normals: np.ndarray, areas: np.ndarray, gap: float) -> np.ndarray:
    """(P,) int64: the height band of every flat polygon, -1 for sloped ones (bands lowest first)."""
    flat = np.asarray(normals)[:, 1] >= math.cos(math.radians(FLAT_DEG))
    band = np.full(len(heights), -1, dtype=np.int64)
    if not flat.any():
        return band
    index = np.flatnonzero(flat)
    order = index[np.argsort(heights[index], kind="stable")]
    band[order] = np.concatenate([[0], np.cumsum(np.diff(heights[order]) > gap)])
    return band


def decompose(navmesh: Any, agent: Any, params: DecompositionParams, mesh: trimesh.Trimesh) -> Decomposition:
    """Regions and (unscored) chokepoints of ``navmesh`` for ``agent`` (see the module doc); ``mesh`` is the level
    the navmesh was built from (a small room's door and its width are measured wall to wall in it).

    Region record: ``id``, ``area`` (m²), ``polygons`` (ids), ``centroid``
    (area-weighted polygon centres, m), ``floor`` (band index, lowest 0),
    ``height_range`` ([min, max] polygon centre heights, m) and ``neighbours``
    (``[{"region", "chokepoints"}]``, filled in by :func:`score`).
    Chokepoint record (before :func:`score`): ``position`` (the widest point of
    its portal, m), ``portal`` (the portal's two end points), ``width``
    (walkable width, m), ``regions`` ([a, b], a < b), ``polygons`` (the
    portal's two polygons), ``floors``, ``articulation``.
    """
    wall_to_wall = 2.0 * float(agent.radius) + float(navmesh.settings["cell_size"])
    clearance = clearances(navmesh, params.obstacle_area, wall_to_wall, params.through_holes)
    portals = navmesh.portals()
    pairs = np.asarray(portals.pairs, dtype=np.int64).reshape(-1, 2)
    ends = np.asarray(portals.endpoints, dtype=np.float64)
    areas = np.asarray(navmesh.areas, dtype=np.float64)
    outline = outlines(navmesh, pairs, ends, SMALL_ROOM_FOOTPRINT * (2.0 * float(agent.radius)) ** 2,
                       SMALL_ROOM_ENCLOSURE)
    doors = DoorWidths(mesh, np.asarray(navmesh.centres, dtype=np.float64), clearance.widest, ends, agent)
    merged, blocked = _merge_tree(pairs, clearance.portals_open, clearance.polygons, areas,
                                  params.narrowness, params.min_region_area, outline, doors)
    n = navmesh.polygon_count
    joined = sparse.coo_array((np.ones(int(merged.sum())), (pairs[merged, 0], pairs[merged, 1])), shape=(n, n))
    count, labels = csgraph.connected_components(joined, directed=False)
    small = np.bincount(labels, weights=areas) < params.min_region_area  # a small room the outline kept apart
    passage = (mean_widths(navmesh, labels, areas)[0] < params.passage_width * 2.0 * float(agent.radius)) & ~small
    labels = join_passages(labels, labels[pairs[blocked]], passage)
    count = int(labels.max()) + 1 if len(labels) else 0
    if params.pinch <= params.narrowness:  # above it no cut can keep the fraction and be a candidate at once
        labels = _join_pinches(navmesh, labels, count, pairs, blocked, areas, clearance, float(agent.radius), params)
        count = int(labels.max()) + 1 if len(labels) else 0
    labels = join_side_strips(labels, pairs[blocked], 2.0 * clearance.portals_open[blocked], clearance.widest[blocked],
                              *mean_widths(navmesh, labels, areas), params.narrowness, params.min_separation)
    labels = _join_lanes(navmesh, labels, pairs, blocked, clearance, float(agent.radius), wall_to_wall, params)
    centres = np.asarray(navmesh.centres, dtype=np.float64)
    band = floor_bands(centres[:, 1], navmesh.normals, areas, 0.5 * float(agent.height))
    labels = _join_ways_round(navmesh, labels, pairs, blocked, clearance, areas, band, agent, wall_to_wall, params)
    labels = _join_stair_runs(navmesh, labels, pairs, blocked, clearance, areas, band, agent, wall_to_wall, params)
    radius = float(agent.radius)
    labels = _join_way_pieces(navmesh, labels, pairs, blocked, clearance, areas, band, radius, wall_to_wall, params)
    labels = _way_ends(navmesh, labels, pairs, blocked, clearance, areas, band, radius, wall_to_wall, params)
    count = int(labels.max()) + 1 if len(labels) else 0
    blocked &= labels[pairs[:, 0]] != labels[pairs[:, 1]]

    region_area = np.bincount(labels, weights=areas, minlength=count)
    weight = np.where(region_area > 0, region_area, 1.0)[:, None]
    centroid = np.stack([np.bincount(labels, weights=areas * centres[:, k], minlength=count) for k in range(3)], axis=1)
    centroid = np.where(region_area[:, None] > 0, centroid / weight, 0.0)
    low = np.full(count, np.inf)
    high = np.full(count, -np.inf)
    np.minimum.at(low, labels, centres[:, 1])
    np.maximum.at(high, labels, centres[:, 1])
    floor = _region_floors(labels, count, band, areas, centres[:, 1])
    members = np.split(np.argsort(labels, kind="stable"), np.cumsum(np.bincount(labels, minlength=count))[:-1])
    regions = [
        {"id": r, "area": float(region_area[r]), "polygons": members[r].tolist(), "centroid": centroid[r].tolist(),
         "floor": int(floor[r]), "height_range": [float(low[r]), float(high[r])], "neighbours": []}
        for r in range(count)
    ]
    chokepoints = _chokepoints(np.flatnonzero(blocked), pairs, labels, portals.endpoints, clearance.widest,
                               2.0 * clearance.portals, floor, params.min_separation, clearance.holes, wall_to_wall)
    return Decomposition(labels, regions, chokepoints)


_SPLITS: weakref.WeakKeyDictionary[Any, dict[Hashable, tuple[trimesh.Trimesh, Decomposition]]] = (
    weakref.WeakKeyDictionary()
)
"""Per navmesh object (dropped with it): the :func:`decompose` results :func:`shared_decomposition` computed, by
the mesh's id, the agent's size and the split settings, each with the mesh it was measured in."""


def shared_decomposition(navmesh: Any, agent: Any, params: DecompositionParams, mesh: trimesh.Trimesh,
                         graph: nx.Graph | None = None) -> Decomposition:
    """:func:`decompose`, computed once per navmesh object, mesh object, agent size and split settings: the
    ``chokepoints`` and ``regions`` analyzers of one run, given the same settings, split the level once.

    ``graph``: the run's initial graph, whose nodes include every polygon of the navmesh unless the graph was cut
    to a play space (:func:`g2s_plugins.play_space.held_polygons`); the regions none of whose polygons it holds, and
    the chokepoints beside them, are left out, so that the split reports the play space alone. O(P).

    The key holds every input :func:`decompose` reads: the agent's ``radius`` and ``height`` (the only fields it
    uses) and the fields of :class:`DecompositionParams` (an analyzer's own others, such as ``top_k``, left out);
    the navmesh is the cache's weak key and the mesh is held with its entry, so its id names no other mesh while
    the entry lives. Each call gets its own region and chokepoint records (:func:`score` fills in the regions'
    ``neighbours`` of the decomposition it is given), with a fresh empty ``neighbours`` list each; the records'
    other values and the read-only ``labels`` are shared and only read.
    """
    key = (id(mesh), float(agent.radius), float(agent.height),
           *(getattr(params, name) for name in DecompositionParams.model_fields))
    splits = _SPLITS.setdefault(navmesh, {})
    if key not in splits:
        split = decompose(navmesh, agent, params, mesh)
        split.labels.flags.writeable = False
        splits[key] = (mesh, split)
    split = splits[key][1]
    held = None if graph is None else held_polygons(graph, navmesh.polygon_count)
    regions = split.regions if held is None else [region for region in split.regions if held[region["polygons"]].any()]
    kept = {region["id"] for region in regions}
    return Decomposition(split.labels, [region | {"neighbours": []} for region in regions],
                         [dict(chokepoint) for chokepoint in split.chokepoints if set(chokepoint["regions"]) <= kept])


def _join_pinches(navmesh: Any, labels: np.ndarray, count: int, pairs: np.ndarray, blocked: np.ndarray,
                  areas: np.ndarray, clearance: Clearances, radius: float, params: DecompositionParams) -> np.ndarray:
    """(P,) the regions ``labels`` with the groups on both sides of every pinch joined (step 3 of the module doc)."""
    width = widest_widths(labels, count, clearance.polygons, pairs, clearance.portals_open)
    area = np.bincount(labels, weights=areas, minlength=count)
    corridor_like = (area >= CORRIDOR_ELONGATION * width**2) & (width <= CORRIDOR_WIDTH * 2.0 * radius)
    candidates = np.flatnonzero(blocked)
    sides = labels[pairs[candidates]]
    between = (sides[:, 0] != sides[:, 1]) & corridor_like[sides].all(axis=1)
    candidates, sides = candidates[between], sides[between]
    cut = 2.0 * clearance.portals_open[candidates]
    reach = PINCH_REACH * (cut + 2.0 * radius)  # the cut's span: its walkable width and the agent's diameter
    local = local_widths(navmesh, labels, clearance.widest[candidates], sides, reach, clearance.open_walls)
    return join_groups(labels, count, sides[pinches(cut, local, params.pinch, params.narrowness)])


def _join_lanes(navmesh: Any, labels: np.ndarray, pairs: np.ndarray, blocked: np.ndarray, clearance: Clearances,
                radius: float, wall_to_wall: float, params: DecompositionParams) -> np.ndarray:
    """(P,) the regions ``labels`` with the two regions of every lane mouth (:func:`lane_mouths`) joined, again on the
    joined regions until no lane mouth is left (step 3 of the module doc); each round joins at least two regions.
    Only candidates narrower than a passage are looked at: the floor beside a cut is about as wide as the cut."""
    passage = params.passage_width * 2.0 * radius
    narrow = 2.0 * clearance.portals_open < passage  # a cut's floor near it is at least about as wide as it
    while True:
        count = int(labels.max()) + 1 if len(labels) else 0
        candidates = np.flatnonzero(blocked & narrow & (labels[pairs[:, 0]] != labels[pairs[:, 1]]))
        sides = np.sort(labels[pairs[candidates]], axis=1)
        points = clearance.widest[candidates]
        _, pair = np.unique(sides, axis=0, return_inverse=True)
        pair = pair.reshape(-1)
        several = plan_spreads(points[:, [0, 2]], pair, int(pair.max()) + 1 if len(pair) else 0)[pair]
        candidates, sides, points = (a[several >= params.min_separation] for a in (candidates, sides, points))
        if len(candidates) < 2:
            return labels
        cut = 2.0 * clearance.portals_open[candidates]
        span = cut + 2.0 * radius  # walkable width and the agent's diameter; a navmesh cell more is the clear width
        local = local_widths(navmesh, labels, points, sides, PINCH_REACH * span, clearance.open_walls)
        mouths = lane_mouths(sides, points, local, passage, cut + wall_to_wall, params.min_separation)
        if not mouths.any():
            return labels
        labels = join_groups(labels, count, sides[mouths])


@dataclass(frozen=True)
class PolygonWalks:
    """Walks on the navmesh's polygon graph: from a polygon's centre to a portal's middle to the next centre, m.

    Attributes:
        centres: (P, 3) polygon centres, as high as they are measured (:func:`measured_centres`), m.
        pairs: (E, 2) each portal's two polygons.
        steps: (E,) the walk across each portal, centre to its middle to centre, m.
        portals_of: CSR of polygon -> portal ids, ``(indptr (P+1,), portal ids (2E,))``.
        near: a kd-tree of the centres.
    """

    centres: np.ndarray
    pairs: np.ndarray
    steps: np.ndarray
    portals_of: tuple[np.ndarray, np.ndarray]
    near: spatial.cKDTree

    @classmethod
    def of(cls, navmesh: Any, pairs: np.ndarray, endpoints: np.ndarray) -> PolygonWalks:
        """The walks of ``navmesh`` (``pairs`` (E, 2) and ``endpoints`` (E, 2, 3): its portals), from centres as high
        as they are measured (:func:`measured_centres`): Recast's lift of one cell height made each step longer on
        coarser cells, enough to part a school's ground-floor rooms on Recast's cells and join them on the agent's."""
        centres = measured_centres(navmesh)
        middle = endpoints.mean(axis=1)
        steps = (np.linalg.norm(centres[pairs[:, 0]] - middle, axis=1)
                 + np.linalg.norm(centres[pairs[:, 1]] - middle, axis=1))
        return cls(centres, pairs, steps, portals_of(pairs, len(centres)), spatial.cKDTree(centres))

    def round_within(self, portal: int, closed: np.ndarray, length: float) -> bool:
        """Whether a walk of at most ``length`` m joins the two polygons of ``portal`` without crossing the portals
        ``closed`` (ids). Only polygons within ``length`` of the first one's centre can lie on such a walk, so the
        search (scipy Dijkstra, bounded by ``length``) runs on those: O(k log k) for k polygons near the portal."""
        a, b = (int(p) for p in self.pairs[portal])
        ball = np.asarray(self.near.query_ball_point(self.centres[a], length), dtype=np.int64)
        if not np.isin(b, ball):
            return False
        indptr, ids = self.portals_of
        counts = indptr[ball + 1] - indptr[ball]
        touching = np.unique(ids[np.repeat(indptr[ball] - np.cumsum(counts) + counts, counts) + np.arange(counts.sum())])
        local = np.full(len(self.centres), -1, dtype=np.int64)
        local[ball] = np.arange(len(ball))
        ends = local[self.pairs[touching]]
        open_ = (ends >= 0).all(axis=1) & ~np.isin(touching, closed)
        graph = sparse.coo_array((self.steps[touching[open_]], (ends[open_, 0], ends[open_, 1])),
                                 shape=(len(ball), len(ball)))
        return bool(csgraph.dijkstra(graph, directed=False, indices=int(local[a]), limit=length)[local[b]] <= length)


def _join_ways_round(navmesh: Any, labels: np.ndarray, pairs: np.ndarray, blocked: np.ndarray, clearance: Clearances,
                     areas: np.ndarray, band: np.ndarray, agent: Any, wall_to_wall: float,
                     params: DecompositionParams) -> np.ndarray:
    """(P,) the regions ``labels`` with the two regions of every way round an obstacle joined (step 3 of the module
    doc), again on the joined regions until none is left.

    Each opening between two regions (the candidates :func:`_chokepoints` would keep as one chokepoint: one
    :func:`_openings` group, and those of its region pair within ``min_separation``) is closed, with every candidate
    that ends on a small hole left out of the clearances that one of its candidates ends on (the cuts round a pillar
    are one cut through it, as the split sees it), and the walk between its widest portal's two polygons is looked for
    on the polygon graph (:class:`PolygonWalks`). When one of at most :data:`WAY_ROUND` times the regions' size is
    there, the two regions join: the larger's longest extent is their size, or the smaller's when either is walled in
    (:data:`WALLED_IN`: a room behind its doors) and the widest portal is at most a door wide (:data:`CORRIDOR_WIDTH`
    agent diameters walkable); past that, the walled-in region's own extent (the smaller's when both are). Only regions
    on one floor join: ``band`` (P,) is each polygon's height band (:func:`floor_bands`); spans (:func:`_spans`:
    openings together narrow against both regions) never do.
    """
    ends = np.asarray(navmesh.portals().endpoints, dtype=np.float64)
    walks = PolygonWalks.of(navmesh, pairs, ends)
    owner, start, end = polygon_boundary_edges(navmesh)
    wall = np.linalg.norm(end - start, axis=1) * (clearance.left_out < 0)
    opening_length = np.linalg.norm(ends[:, 1] - ends[:, 0], axis=1)
    passage = params.passage_width * 2.0 * float(agent.radius)
    door = CORRIDOR_WIDTH * 2.0 * float(agent.radius)  # the widest walkable width an opening of a room is a door at
    heights = walks.centres[:, 1]
    while True:
        count = int(labels.max()) + 1 if len(labels) else 0
        candidates = np.flatnonzero(blocked & (labels[pairs[:, 0]] != labels[pairs[:, 1]]))
        if len(candidates) == 0:
            return labels
        sides = np.sort(labels[pairs[candidates]], axis=1)
        cut = np.bincount(sides.reshape(-1), weights=np.repeat(opening_length[candidates], 2), minlength=count)
        walls = np.bincount(labels[owner], weights=wall, minlength=count)
        mean_width, extent = mean_widths(navmesh, labels, areas)
        walled_in = (walls >= WALLED_IN * (walls + cut)) & (mean_width >= passage)
        floor = _region_floors(labels, count, band, areas, heights)
        opening = _openings(candidates, sides, ends, 2.0 * clearance.portals, clearance.holes, wall_to_wall)
        around = _joined_by(_holes_at(ends[candidates].reshape(-1, 3), start, clearance.left_out).reshape(-1, 2))
        points = clearance.widest[candidates]
        _, pair = np.unique(sides, axis=0, return_inverse=True)
        pair = pair.reshape(-1)
        of_pair = np.split(np.argsort(pair, kind="stable"), np.flatnonzero(np.diff(np.sort(pair))) + 1)
        spans = _spans(pair, opening, 2.0 * clearance.portals[candidates], mean_width[sides].min(axis=1))
        joins = []
        for group in np.split(np.argsort(opening, kind="stable"),
                              np.flatnonzero(np.diff(np.sort(opening, kind="stable"))) + 1):
            a, b = sides[group[0]]
            if floor[a] != floor[b] or spans[group[0]]:
                continue
            same = of_pair[pair[group[0]]]
            near = same[(np.linalg.norm(points[same][:, None] - points[group][None], axis=2)
                         < params.min_separation).any(axis=1)]
            closed = candidates[np.union1d(near, np.flatnonzero(np.isin(around, around[group])))]
            widest = candidates[group[np.argmax(clearance.portals[candidates[group]])]]
            if not walled_in[[a, b]].any():
                size = max(extent[a], extent[b])
            elif 2.0 * clearance.portals[widest] <= door:
                size = min(extent[a], extent[b])
            else:  # wider than any door: weighed against the room it opens, not against a yard beside it
                size = extent[[a, b]][walled_in[[a, b]]].min()
            if walks.round_within(widest, closed, walks.steps[widest] + WAY_ROUND * size):
                joins.append((a, b))
        if not joins:
            return labels
        labels = join_groups(labels, count, np.array(joins))


def _spans(pair: np.ndarray, opening: np.ndarray, width: np.ndarray, mean_width: np.ndarray) -> np.ndarray:
    """(C,) bool: which chokepoint candidates are spans (:data:`SPAN_SHARE`): the openings between their two regions,
    each as wide as its widest candidate, are together narrower than :data:`SPAN_SHARE` of the narrower region's mean
    walkable width. O(C).

    Args:
        pair: (C,) each candidate's region pair (equal for candidates of one pair).
        opening: (C,) each candidate's opening (:func:`_openings`).
        width: (C,) each candidate's walkable width, m.
        mean_width: (C,) the narrower of each candidate's two regions' mean walkable widths, m.
    """
    if len(pair) == 0:
        return np.zeros(0, dtype=bool)
    widest = np.zeros(int(opening.max()) + 1)
    np.maximum.at(widest, opening, width)
    first = np.unique(opening, return_index=True)[1]  # one candidate of each opening, for its pair
    together = np.bincount(pair[first], weights=widest[opening[first]], minlength=int(pair.max()) + 1)
    return together[pair] < SPAN_SHARE * mean_width


def stair_runs(sides: np.ndarray, heights: np.ndarray, mean_width: np.ndarray, extent: np.ndarray, area: np.ndarray,
               narrow: float, climb: float) -> np.ndarray:
    """(K, 2) the region pairs to join so that every run of flights is one region (step 3 of the module doc).

    A *flight* is a region no wider than ``narrow`` on average (``mean_width`` (G,), m) with exactly two
    chokepoints, to two different regions, at heights at least ``climb`` and :data:`STAIR_GRADIENT` of its extent
    apart: a piece of a stair between its landings, or a stair between two floors. Flights joined by a chokepoint form a run (scipy connected components);
    a run of two flights or more whose every other neighbour (the regions at its foot and head) is larger than the
    whole run (``area`` (G,), m²) is one way between those regions: its flights join and the chokepoints at its
    landings go, those at its foot and head stay. Landings 4 m square where flights meet from several sides (a
    lattice of flights) have three chokepoints or more, or are the run's small ends: they stay regions.

    Args:
        sides: (K, 2) the two regions of every chokepoint.
        heights: (K,) the height of every chokepoint's widest point, m.
        mean_width: (G,) each region's mean walkable width (area over longest extent), m.
        extent: (G,) each region's longest plan extent, m: a flight climbs at least :data:`STAIR_GRADIENT` of it.
        area: (G,) each region's walkable area, m².
        narrow: the widest mean walkable width of a flight, m.
        climb: the least height between a flight's two chokepoints, m.
    """
    count = len(area)
    ends = np.concatenate([sides, sides[:, ::-1]])  # (2K, 2): a region and the region across each of its chokepoints
    at = np.concatenate([heights, heights])
    order = np.lexsort((np.arange(len(ends)), ends[:, 0]))
    ends, at = ends[order], at[order]
    degree = np.bincount(ends[:, 0], minlength=count)
    first = np.concatenate([[0], np.cumsum(degree)[:-1]])
    two = np.flatnonzero(degree == 2)
    flight = np.zeros(count, dtype=bool)
    rise = np.abs(at[first[two]] - at[first[two] + 1])
    flight[two] = ((ends[first[two], 1] != ends[first[two] + 1, 1]) & (mean_width[two] <= narrow) & (rise >= climb)
                   & (rise >= STAIR_GRADIENT * extent[two]))
    inside = flight[sides].all(axis=1)
    links = sparse.coo_array((np.ones(int(inside.sum())), (sides[inside, 0], sides[inside, 1])), shape=(count, count))
    run = csgraph.connected_components(links, directed=False)[1]
    run_area = np.bincount(run[flight], weights=area[flight], minlength=count)
    out = flight[ends[:, 0]] & ~flight[ends[:, 1]]  # a run's foot or head: a flight's chokepoint to another region
    small_end = np.zeros(count, dtype=bool)
    np.logical_or.at(small_end, run[ends[out, 0]], area[ends[out, 1]] <= run_area[run[ends[out, 0]]])
    # a chokepoint between two flights (a landing) always lies in a run of two flights or more
    joined = inside & ~small_end[run[sides[:, 0]]]
    return sides[joined]


def _join_stair_runs(navmesh: Any, labels: np.ndarray, pairs: np.ndarray, blocked: np.ndarray,
                     clearance: Clearances, areas: np.ndarray, band: np.ndarray, agent: Any, wall_to_wall: float,
                     params: DecompositionParams) -> np.ndarray:
    """(P,) the regions ``labels`` with every run of flights joined (:func:`stair_runs`; step 3 of the module doc).

    The chokepoints are those :func:`_chokepoints` keeps for ``labels`` (one per opening); a flight is at most
    :data:`CORRIDOR_WIDTH` agent diameters wide on average and climbs at least half the agent's height between
    its two chokepoints (the floors' height bands split at that gap: ``band`` (P,), :func:`floor_bands`)."""
    count = int(labels.max()) + 1 if len(labels) else 0
    kept = _kept_chokepoints(navmesh, labels, pairs, blocked, clearance, areas, band, wall_to_wall, params)
    if not kept:
        return labels
    sides = np.array([k["regions"] for k in kept], dtype=np.int64)
    heights = np.array([k["position"][1] for k in kept])
    mean_width, extent = mean_widths(navmesh, labels, areas)
    joins = stair_runs(sides, heights, mean_width, extent, np.bincount(labels, weights=areas, minlength=count),
                       CORRIDOR_WIDTH * 2.0 * float(agent.radius), 0.5 * float(agent.height))
    return join_groups(labels, count, joins) if len(joins) else labels


def _kept_chokepoints(navmesh: Any, labels: np.ndarray, pairs: np.ndarray, blocked: np.ndarray,
                      clearance: Clearances, areas: np.ndarray, band: np.ndarray, wall_to_wall: float,
                      params: DecompositionParams, portal_ids: bool = False) -> list[dict[str, Any]]:
    """The chokepoints :func:`_chokepoints` keeps for the regions ``labels`` (P,) (one per opening), of the
    candidates ``blocked`` (E,) between two of them; floors by ``band`` (P,) (:func:`floor_bands`)."""
    count = int(labels.max()) + 1 if len(labels) else 0
    candidates = np.flatnonzero(blocked & (labels[pairs[:, 0]] != labels[pairs[:, 1]]))
    floor = _region_floors(labels, count, band, areas, np.asarray(navmesh.centres, dtype=np.float64)[:, 1])
    return _chokepoints(candidates, pairs, labels, np.asarray(navmesh.portals().endpoints, dtype=np.float64),
                        clearance.widest, 2.0 * clearance.portals, floor, params.min_separation, clearance.holes,
                        wall_to_wall, portal_ids)


def way_pieces(sides: np.ndarray, floors: np.ndarray, width: np.ndarray, mean_width: np.ndarray,
               narrowness: float, widest: float) -> np.ndarray:
    """(K,) bool: which chokepoints part two pieces of one way (step 3 of the module doc): the chokepoint keeps at
    least ``narrowness`` of the mean walkable width of both its regions (``sides`` (K, 2), ``width`` (K,) m,
    ``mean_width`` (G,) m: area over longest extent), so it is no narrowing of either: a way as wide as its cuts
    on average, cut only where a bay or a corner widens it for a few metres. Both regions are ways, at most
    ``widest`` m on average (:func:`way_width`), and on one floor (``floors`` (K, 2)): a flight's foot and head stay
    chokepoints however narrow the ground it climbs from."""
    if len(sides) == 0:
        return np.zeros(0, dtype=bool)
    wider = mean_width[sides].max(axis=1)
    return (floors[:, 0] == floors[:, 1]) & (width >= narrowness * wider) & (wider <= widest)


def way_width(radius: float, narrowness: float) -> float:
    """The widest mean walkable width of a way, m: :data:`CORRIDOR_WIDTH` agent diameters over ``narrowness``, a way
    as wide as a corridor whose passing bays or corners (as wide again as its cuts over ``narrowness``) make rooms
    of its pieces to the merge tree. A wider region is a yard or a court, whose openings the merge tree weighs
    (measured: the lighthouse's causeway 4.0-4.7 m; a castle's courts 11.2-11.9 m; docs/plugins.md, "Ways and their
    ends")."""
    return CORRIDOR_WIDTH * 2.0 * radius / narrowness


def _join_way_pieces(navmesh: Any, labels: np.ndarray, pairs: np.ndarray, blocked: np.ndarray,
                     clearance: Clearances, areas: np.ndarray, band: np.ndarray, radius: float, wall_to_wall: float,
                     params: DecompositionParams) -> np.ndarray:
    """(P,) the regions ``labels`` with the two regions of every chokepoint between pieces of one way joined
    (:func:`way_pieces`), again on the joined regions until none is left (step 3 of the module doc)."""
    while True:
        count = int(labels.max()) + 1 if len(labels) else 0
        kept = _kept_chokepoints(navmesh, labels, pairs, blocked, clearance, areas, band, wall_to_wall, params)
        if not kept:
            return labels
        sides = np.array([k["regions"] for k in kept], dtype=np.int64)
        width = np.array([k["width"] for k in kept])
        joins = way_pieces(sides, np.array([k["floors"] for k in kept], dtype=np.int64), width,
                           mean_widths(navmesh, labels, areas)[0], params.narrowness,
                           way_width(radius, params.narrowness))
        if not joins.any():
            return labels
        labels = join_groups(labels, count, sides[joins])


def narrow_stub(portal: int, limit: float, inside: np.ndarray, pairs: np.ndarray,
                portals: tuple[np.ndarray, np.ndarray], polygon_clearance: np.ndarray, portal_clearance: np.ndarray,
                band: np.ndarray) -> np.ndarray:
    """(K,) int64 sorted: the polygons of the region ``inside`` (P,) bool that go on from ``portal`` as narrow as
    ``limit`` (clearance, m): reached from it through portals of clearance at most ``limit`` (``portal_clearance``
    (E,)), each with a centre as near its walls (``polygon_clearance`` (P,)), on the floor (``band`` (P,), flat
    polygons only) of the first, and with such a portal onward (a polygon with none is where the floor widens, or
    a dead end). ``pairs`` (E, 2): each portal's polygons; ``portals``: CSR polygon -> portal ids
    (:func:`portals_of`). Depth-first over the polygons, O(k) for k polygons and portals looked at."""
    indptr, ids = portals
    start = int(pairs[portal, 0] if inside[pairs[portal, 0]] else pairs[portal, 1])
    grown: set[int] = set()
    stack = [(start, portal)]
    while stack:
        q, came = stack.pop()
        if q in grown or not inside[q] or polygon_clearance[q] > limit or band[q] < 0 or band[q] != band[start]:
            continue
        onward = [int(f) for f in ids[indptr[q]:indptr[q + 1]]
                  if f != came and portal_clearance[f] <= limit and inside[pairs[f]].all()]
        if onward:
            grown.add(q)
            stack.extend((int(pairs[f, 0] if pairs[f, 1] == q else pairs[f, 1]), f) for f in onward)
    return np.array(sorted(grown), dtype=np.int64)


def _way_ends(navmesh: Any, labels: np.ndarray, pairs: np.ndarray, blocked: np.ndarray, clearance: Clearances,
              areas: np.ndarray, band: np.ndarray, radius: float, wall_to_wall: float,
              params: DecompositionParams) -> np.ndarray:
    """(P,) the regions ``labels`` with every way carried on to its ends; the portals at them are set in ``blocked``
    (E,), in place (they become chokepoint candidates).

    A *way* here is a region at most :func:`way_width` wide on average (``radius``: the agent's, m) and at least
    :data:`WAY_ELONGATION` times as long as that, with chokepoints to two regions or more, each keeping at least
    ``narrowness`` of its mean walkable width (it is as narrow as its openings: no room behind them). Where the
    floor beyond one of its chokepoints (:func:`local_widths`, the pinch rule's reach) is no wider than the
    chokepoint over ``narrowness``, the chokepoint lies out along the way from its true end (the merge tree cut it
    at a bay or a corner and merged the stub beyond into the neighbour): the neighbour's polygons that go on as
    narrow (clearance at most the chokepoint's over ``narrowness``, with a portal as narrow onward, on the
    chokepoint's floor: :func:`narrow_stub`) join the way, with whatever of the neighbour only they reach, and the
    chokepoint moves to the portals where the floor widens; not when those lie within ``min_separation`` of it (no
    stub) or when what they cut off is larger than the stub (a link between two parts of the neighbour, not the
    way's end). A neighbour that is a way itself is left as it is."""
    count = int(labels.max()) + 1 if len(labels) else 0
    kept = _kept_chokepoints(navmesh, labels, pairs, blocked, clearance, areas, band, wall_to_wall, params,
                             portal_ids=True)
    if not kept:
        return labels
    sides = np.array([k["regions"] for k in kept], dtype=np.int64)
    width = np.array([k["width"] for k in kept])
    mean_width, extent = mean_widths(navmesh, labels, areas)
    both = np.concatenate([sides, sides[:, ::-1]])
    narrow_enough = np.concatenate([width, width]) >= params.narrowness * mean_width[both[:, 0]]
    neighbours = np.unique(both, axis=0)
    way = ((np.bincount(neighbours[:, 0], minlength=count) >= 2) & (mean_width <= way_width(radius, params.narrowness))
           & (extent >= WAY_ELONGATION * mean_width)
           & (np.bincount(both[:, 0], weights=~narrow_enough, minlength=count) == 0))
    n = len(labels)
    csr = portals_of(pairs, n)
    points = np.array([k["position"] for k in kept])
    beside = np.zeros((len(kept), 2))  # the pinch rule's floor near a cut, each side
    look = np.flatnonzero(way[sides].any(axis=1))
    beside[look] = local_widths(navmesh, labels, points[look], sides[look], PINCH_REACH * (width[look] + 2.0 * radius),
                                clearance.open_walls)
    labels = labels.copy()
    for k, (a, b), floor_near in zip(kept, sides.tolist(), beside):
        for w, other, beyond in ((a, b, floor_near[1]), (b, a, floor_near[0])):
            if not way[w] or way[other] or beyond * params.narrowness > float(k["width"]):
                continue  # no way, or the floor beyond the cut is wider than it: the way ends there
            stub = narrow_stub(int(k["portal_id"]), 0.5 * float(k["width"]) / params.narrowness, labels == other,
                               pairs, csr, clearance.polygons, clearance.portals_open, band)
            rest = np.flatnonzero(labels == other)
            rest = rest[~np.isin(rest, stub)]
            if len(stub) == 0 or len(rest) == 0:
                continue
            local = np.full(n, -1, dtype=np.int64)
            local[rest] = np.arange(len(rest))
            inner = (local[pairs] >= 0).all(axis=1)
            graph = sparse.coo_array((np.ones(int(inner.sum())), (local[pairs[inner, 0]], local[pairs[inner, 1]])),
                                     shape=(len(rest), len(rest)))
            parts, part = csgraph.connected_components(graph, directed=False)
            main_part = int(np.argmax(np.bincount(part, weights=areas[rest])))
            cut_off = rest[part != main_part]
            moved = np.concatenate([stub, cut_off])
            edge = np.isin(pairs, moved).any(axis=1) & (labels[pairs] == other).all(axis=1)
            edge &= ~np.isin(pairs, moved).all(axis=1)
            reach = np.linalg.norm(clearance.widest[edge][:, [0, 2]] - np.asarray(k["position"])[[0, 2]], axis=1)
            if areas[cut_off].sum() > areas[stub].sum() or not len(reach) or reach.min() < params.min_separation:
                continue  # a link between two parts of the neighbour, or no stub: the chokepoint is at the way's end
            labels[moved] = w
            blocked |= edge
    return join_groups(labels, count, np.zeros((0, 2), dtype=np.int64))


def _holes_at(points: np.ndarray, start: np.ndarray, hole: np.ndarray) -> np.ndarray:
    """(N,) int64: the hole of ``hole`` (B,) (-1: none) whose boundary has a corner at each of ``points`` (N, 3) (equal
    to 1 cm; the boundary edges start at ``start`` (B, 3)), -1 for points on none."""
    on = hole >= 0
    _, point = np.unique(_point_keys(np.concatenate([points, start[on]])), return_inverse=True)
    point = point.reshape(-1)
    hole_at = np.full(int(point.max()) + 1 if len(point) else 0, -1, dtype=np.int64)
    hole_at[point[len(points):]] = hole[on]
    return hole_at[point[:len(points)]]


def _joined_by(hole: np.ndarray) -> np.ndarray:
    """(C,) int64: candidates equal when they end on the same hole (``hole`` (C, 2): the hole at each end, -1: none),
    directly or through others (scipy connected components)."""
    candidate, side = np.nonzero(hole >= 0)
    n = len(hole)
    size = n + (int(hole.max()) + 1 if len(candidate) else 0)
    links = sparse.coo_array((np.ones(len(candidate)), (candidate, n + hole[candidate, side])), shape=(size, size))
    return csgraph.connected_components(links, directed=False)[1][:n].astype(np.int64)


def lane_mouths(sides: np.ndarray, points: np.ndarray, local: np.ndarray, passage: float, clear: np.ndarray,
                separation: float) -> np.ndarray:
    """(C,) bool: which chokepoint candidates are mouths of lanes side by side (step 3 of the module doc).

    A candidate opens a passage when the floor on one of its two sides near it is narrower than ``passage``; it is
    a lane mouth when another candidate between the same two regions that opens a passage lies beside it: at least
    ``separation`` and at most :data:`LANE_PITCH` times the wider of the two clear widths away in plan. Lanes
    between grave rows, shelving aisles and queue rails are passages side by side, parted by solids about as wide
    as themselves; two doors off a corridor lead into one room (wide behind both), and passages far apart (two
    footbridges, the gates of a wall) are each a way of their own.

    Args:
        sides: (C, 2) the two regions of every candidate.
        points: (C, 3) each candidate's widest point, m.
        local: (C, 2) the walkable width of each side's floor near the candidate (:func:`local_widths`), m.
        passage: a side narrower than this walkable width near a candidate is a passage, m.
        clear: (C,) each candidate's clear width (estimated: walkable width, the agent's diameter and a navmesh
            cell), m.
        separation: candidates closer than this are one opening (``min_separation``), m.
    """
    mouth = np.zeros(len(sides), dtype=bool)
    opens = np.flatnonzero(local.min(axis=1) < passage) if len(sides) else np.zeros(0, dtype=np.int64)
    if len(opens) < 2:
        return mouth
    _, pair = np.unique(np.sort(sides[opens], axis=1), axis=0, return_inverse=True)
    order = np.argsort(pair.reshape(-1), kind="stable")
    starts = np.flatnonzero(np.r_[True, np.diff(pair.reshape(-1)[order]) != 0])
    for group in np.split(opens[order], starts[1:]):  # the passage openings of one region pair: a few
        if len(group) < 2:
            continue
        apart = np.linalg.norm(points[group][:, None, [0, 2]] - points[group][None, :, [0, 2]], axis=2)
        reach = LANE_PITCH * np.maximum(clear[group][:, None], clear[group][None, :])
        mouth[group] = ((apart >= separation) & (apart <= reach)).any(axis=1)
    return mouth


def _region_floors(labels: np.ndarray, count: int, band: np.ndarray, areas: np.ndarray,
                   heights: np.ndarray) -> np.ndarray:
    """(count,) int64: the floor of each region of ``labels`` (P,): the height band (``band`` (P,), -1 for sloped
    polygons) holding most of its flat area (``areas`` (P,), m²), else the band nearest its mean height (``heights``
    (P,), m, area-weighted; 0 for a region of no area)."""
    mean_height = np.bincount(labels, weights=areas * heights, minlength=count) / np.maximum(
        np.bincount(labels, weights=areas, minlength=count), 1e-12)
    bands = int(band.max()) + 1 if (band >= 0).any() else 0
    if bands == 0:
        return np.zeros(count, dtype=np.int64)
    flat = band >= 0
    table = np.bincount(labels[flat] * bands + band[flat], weights=areas[flat], minlength=count * bands)
    table = table.reshape(count, bands)
    band_height = np.bincount(band[flat], weights=heights[flat] * areas[flat], minlength=bands) / np.maximum(
        np.bincount(band[flat], weights=areas[flat], minlength=bands), 1e-12)
    nearest = np.abs(mean_height[:, None] - band_height[None, :]).argmin(axis=1)
    return np.where(table.max(axis=1) > 0, table.argmax(axis=1), nearest).astype(np.int64)


def _openings(candidates: np.ndarray, sides: np.ndarray, endpoints: np.ndarray, width: np.ndarray,
              holes: tuple[np.ndarray, np.ndarray], wall_to_wall: float) -> np.ndarray:
    """(C,) int64: the opening of each candidate portal, equal for candidates of the same region pair chained by
    shared end points (equal to 1 cm), or ending on the same small hole that is a post between them
    (:func:`_post_links`; scipy connected components).

    Recast cuts a passage between its regions' contours, which may turn: a wide gap whose cut bends at a
    contour vertex is two portals end to end, one opening (measured: docs/plugins.md, real levels). A post
    in a gap (a gravestone, a bollard) parts the cut into portals that end on its outline; the post is a small
    hole, left out of the clearances that split the level, and the gap on either side of it is more than twice
    as wide as the post: one opening too. The wall between two doors is a small hole as well, but at least half
    as long as a door is wide, so two doors stay two (docs/plugins.md, "Posts, niches and aisles").

    Args:
        candidates: (C,) portal ids; ``sides``: (C, 2) their region pairs; ``endpoints``: (E, 2, 3) every
            portal's end points, m; ``width``: (E,) every portal's walkable width, m.
        holes: the small holes' boundary vertices, (H, 3) m, and the hole of each, (H,) (:class:`Clearances`).
        wall_to_wall: what a walkable width lacks of the width wall to wall, m: the agent's diameter and a
            navmesh cell of rasterisation (:func:`_post_links`).
    """
    if len(candidates) == 0:
        return np.zeros(0, dtype=np.int64)
    ends = endpoints[candidates].reshape(-1, 3)
    _, point = np.unique(_point_keys(ends), return_inverse=True)
    point = point.reshape(-1, 2)
    _, pair = np.unique(sides, axis=0, return_inverse=True)
    pair = pair.reshape(-1)
    # a candidate joins its two end points, each taken within its region pair
    _, node = np.unique(pair[:, None] * (int(point.max()) + 1) + point, return_inverse=True)
    node = node.reshape(-1, 2)
    hole = _holes_at(ends, *holes).reshape(-1, 2)
    posts = _post_links(pair, hole, ends.reshape(-1, 2, 3), width[candidates], wall_to_wall)
    links = np.concatenate([node, np.column_stack([node[posts[:, 0], 0], node[posts[:, 1], 0]])])
    graph = sparse.coo_array((np.ones(len(links)), (links[:, 0], links[:, 1])), shape=(int(node.max()) + 1,) * 2)
    return csgraph.connected_components(graph, directed=False)[1][node[:, 0]].astype(np.int64)


def _post_links(pair: np.ndarray, hole: np.ndarray, ends: np.ndarray, width: np.ndarray,
                wall_to_wall: float) -> np.ndarray:
    """(K, 2) candidate pairs of one region pair with an end point each on one small hole that is a post between
    them: less than :data:`POST_SHARE` as wide as the narrower candidate, both wall to wall (:func:`_openings`).

    The hole's outline is the post's grown by the agent's radius, and a door's walkable width is its width wall
    to wall less the agent's diameter, each within about a navmesh cell of rasterisation (docs/plugins.md,
    "Widths turned"): so the post is the distance between the two end points on it less ``wall_to_wall``, and a
    candidate's width wall to wall is its walkable width plus ``wall_to_wall``.

    Args:
        pair: (C,) each candidate's region pair; ``hole``: (C, 2) the small hole each end point lies on (-1:
            none); ``ends``: (C, 2, 3) the end points, m; ``width``: (C,) walkable widths, m.
        wall_to_wall: the agent's diameter and a navmesh cell, m.
    """
    candidate, end = np.nonzero(hole >= 0)
    order = np.lexsort((candidate, hole[candidate, end], pair[candidate]))
    candidate, end = candidate[order], end[order]
    key = np.column_stack([pair[candidate], hole[candidate, end]])
    starts = np.flatnonzero(np.r_[True, (key[1:] != key[:-1]).any(axis=1)])
    found = []
    for group in np.split(np.arange(len(candidate)), starts[1:]):  # a few end points on each hole
        if len(group) < 2:
            continue
        i, j = np.triu_indices(len(group), 1)
        a, b = candidate[group[i]], candidate[group[j]]
        post = np.linalg.norm(ends[a, end[group[i]]] - ends[b, end[group[j]]], axis=1) - wall_to_wall
        keep = (a != b) & (post < POST_SHARE * (np.minimum(width[a], width[b]) + wall_to_wall))
        found.append(np.column_stack([a[keep], b[keep]]))
    return np.concatenate(found) if found else np.zeros((0, 2), dtype=np.int64)


def _chokepoints(candidates: np.ndarray, pairs: np.ndarray, labels: np.ndarray, endpoints: np.ndarray,
                 widest: np.ndarray, width: np.ndarray, floor: np.ndarray, separation: float,
                 holes: tuple[np.ndarray, np.ndarray], wall_to_wall: float,
                 portal_ids: bool = False) -> list[dict[str, Any]]:
    """One record per chokepoint: candidates grouped by region pair, widest first; the others of an
    opening (:func:`_openings`, ``holes`` and ``wall_to_wall`` as there) and near ones dropped. With
    ``portal_ids`` each record also names its portal (``portal_id``), for the steps of the split that use it."""
    sides = np.sort(labels[pairs[candidates]], axis=1)
    opening = _openings(candidates, sides, endpoints, width, holes, wall_to_wall)
    order = np.lexsort((candidates, -width[candidates], sides[:, 1], sides[:, 0]))
    kept: list[dict[str, Any]] = []
    kept_at: dict[tuple[int, int], list[np.ndarray]] = {}
    kept_openings: set[int] = set()
    for i in order.tolist():
        e = int(candidates[i])
        a, b = int(sides[i, 0]), int(sides[i, 1])
        position = widest[e]
        others = kept_at.setdefault((a, b), [])
        if int(opening[i]) in kept_openings or any(np.linalg.norm(q - position) < separation for q in others):
            continue
        kept_openings.add(int(opening[i]))
        others.append(position)
        kept.append({
            "position": position.tolist(),
            "portal": endpoints[e].tolist(),
            "width": float(width[e]),
            "regions": [a, b],
            "polygons": [int(pairs[e, 0]), int(pairs[e, 1])],
            "floors": [int(floor[a]), int(floor[b])],
        } | ({"portal_id": e} if portal_ids else {}))
    pairs_kept = [tuple(k["regions"]) for k in kept]
    count = max((b for _, b in pairs_kept), default=-1) + 1
    region_graph = rx.PyGraph(multigraph=True)
    region_graph.add_nodes_from(range(count))
    region_graph.add_edges_from_no_data(pairs_kept)
    # rustworkx's bridges sees parallel edges as one; a pair of regions with two chokepoints has no bridge
    doubled = {pair for pair, times in Counter(pairs_kept).items() if times > 1}
    bridges = {tuple(sorted(e)) for e in rx.bridges(region_graph)} - doubled
    for k, pair in zip(kept, pairs_kept):
        k["articulation"] = pair in bridges
    return kept


def score(decomposition: Decomposition, structure: nx.Graph) -> tuple[list[dict[str, Any]], dict[int, float]]:
    """Chokepoints with ``traffic`` and ``score``, sorted by score (ids 0, 1 ... in that order),
    and each structure node's largest score among the chokepoints its edges cross (0 if none).

    Fills in the regions' ``neighbours``. See step 5 of the module doc.
    """
    records = [dict(k) for k in decomposition.chokepoints]
    labels = decomposition.labels
    by_pair: dict[tuple[int, int], list[int]] = {}
    for index, k in enumerate(records):
        by_pair.setdefault(tuple(k["regions"]), []).append(index)
    traffic = np.zeros(len(records))
    crossing: list[tuple[int, int, int]] = []
    edge_traffic = centrality.edge_betweenness(structure) if structure.number_of_edges() else {}
    for (u, v), value in edge_traffic.items():
        pu, pv = structure.nodes[u].get("polygon", -1), structure.nodes[v].get("polygon", -1)
        if pu is None or pv is None or pu < 0 or pv < 0 or labels[pu] == labels[pv]:
            continue
        options = by_pair.get(tuple(sorted((int(labels[pu]), int(labels[pv])))))
        if not options:
            continue  # the edge skips a region: it crosses two chokepoints and is not counted
        a, b = np.asarray(structure.nodes[u]["pos"]), np.asarray(structure.nodes[v]["pos"])
        nearest = min(options, key=lambda i: (_segment_distance(np.asarray(records[i]["position"]), a, b), i))
        traffic[nearest] = max(traffic[nearest], value)
        crossing.append((nearest, u, v))
    for index, k in enumerate(records):
        k["traffic"] = float(traffic[index])
        k["score"] = float(traffic[index] / max(k["width"], 1e-6))
    order = sorted(range(len(records)), key=lambda i: (-records[i]["score"], records[i]["width"], i))
    rank = {old: new for new, old in enumerate(order)}
    ranked = [records[i] | {"id": rank[i]} for i in order]
    node_score = dict.fromkeys(structure.nodes, 0.0)
    for index, u, v in crossing:
        for node in (u, v):
            node_score[node] = max(node_score[node], records[index]["score"])
    neighbours: dict[int, dict[int, list[int]]] = {}
    for k in ranked:
        a, b = k["regions"]
        neighbours.setdefault(a, {}).setdefault(b, []).append(k["id"])
        neighbours.setdefault(b, {}).setdefault(a, []).append(k["id"])
    for region in decomposition.regions:
        region["neighbours"] = [{"region": other, "chokepoints": sorted(ids)}
                                for other, ids in sorted(neighbours.get(region["id"], {}).items())]
    return ranked, node_score


def _segment_distance(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    d = b - a
    t = float(np.clip(np.dot(p - a, d) / max(float(np.dot(d, d)), 1e-12), 0.0, 1.0))
    return float(np.linalg.norm(p - (a + t * d)))


def region_values(decomposition: Decomposition, structure: nx.Graph) -> dict[int, float]:
    """The region id of every structure node's polygon (-1 for nodes that are not polygons)."""
    labels = decomposition.labels
    values = {}
    for node, polygon in structure.nodes(data="polygon", default=-1):
        values[node] = float(labels[polygon]) if polygon is not None and 0 <= polygon < len(labels) else -1.0
    return values
