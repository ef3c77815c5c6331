"""Level kinds of the fifth to twenty-fifth held-out rounds (issue 9): generators no preset setting was made on.

Fifth round: six kinds, each about 1,000 navmesh polygons with the presets' agent (radius 0.5 m, height 2 m, climb 0.4 m):
``subway`` (platforms, track pits 1.2 m lower, stairs up to two concourses), ``archipelago`` (islands joined by
narrow railed bridges), ``car_park`` (three storeys joined by ramps and two switchback stairwells, the top one
an office), ``forest`` (hilly ground, 300 trunks, fallen logs), ``stadium`` (a bowl of stepped tiers, aisle
stairs, a cross aisle and vomitories out to an outer deck) and ``harbour`` (a quay, piers, moored boats with
walkable decks). Y up, metres, ``numpy.random.default_rng(seed)``; every solid is a closed convex body with
outward faces (trimesh's convex hull), so Recast reads each top as floor. Recast also reads as floor the ground
inside a closed solid with head room over it, so the ground stops under the stadium's stands and the harbour's
warehouses (a first draft had walkable strips inside the stands and a floor in every warehouse).

Sixth round: six more kinds, 630-970 navmesh polygons with that agent: ``school`` (two storeys of classrooms
round a courtyard), ``cathedral`` (nave, aisles between pillars, chapels, transept, raised chancel over a crypt,
cloister, churchyard), ``mine`` (four room-and-pillar levels joined by a switchback decline and steep stairs
standing for ladders), ``ship`` (a cargo ship's tank top, tween deck, cabin deck, main deck and superstructure),
``village`` (rolling ground, a river and two bridges, houses one enters) and ``market`` (a square of stalls and
crates, streets, a hall). The same rule holds: the floor stops inside the mine's pillars, and the ship's
engine and funnel are too low or too narrow to hold a floor. Stairs rise at most 0.18 m a step: with 0.2 m
risers Recast's ledge filter cuts the flight at the presets' 0.4 m climb (found on a first draft of the ship).

Seventh round: six more kinds, 734-1,216 navmesh polygons with that agent (seeds 0-2): ``office`` (three
open-plan storeys of cubicles behind 1.2 m partitions round a solid core), ``airport`` (check-in hall, security
line, a 360-390 m concourse with gate holdrooms, jet bridges, shops, moving walkways and a mezzanine), ``sewer``
(a grid of tunnels, channels between walkways, chambers, footbridges, side rooms), ``lanes`` (a three-lane
multiplayer arena, symmetric under a half turn, with catwalks, a bridge and jump-down ledges), ``prison`` (three
cell blocks of two tiers round open wells with galleries and bridges, a mess hall, a yard) and ``museum``
(galleries in enfilade on two storeys, an entrance hall open to the roof with a grand flight). Tops of tall
solids that a first draft left flat (the office's core, the arena's blocks, the prison's guard post) are
ridged or pointed at 50 degrees, which no agent stands on; the ground stops under the arena's tall blocks.

Eighth round: six more kinds, 782-1,126 navmesh polygons with that agent (seeds 0-2): ``tower`` (seven office
storeys joined only by two switchback stairwells), ``hospital`` (three storeys of wards off a racetrack of
corridors, small rooms in the core, a stairwell and two lift shafts no one walks through), ``mall`` (three storeys
of shops off galleries round an atrium open over all three, escalators as ramps across it), ``canyon`` (ledges in
three tiers on both walls, ramps up them, sagging rope bridges across, a stream bed with fords), ``hillside`` (a
terraced town whose streets climb as stairs between houses) and ``spaceship`` (three ring corridors joined by
spokes, rooms off the rings, airlocks). Doors in walls at an angle are 2 m wide (the spaceship): a 1.6 m door,
enough on the axes, closes there for the presets' agent. Stairwells' steps are blocks 0.45 m deep (``stairs``'s
``depth``), so the flight of the storey below keeps its head room.

Ninth round: six more kinds, 583-1,048 navmesh polygons with that agent (seeds 0-2), each stressing something the
earlier rounds had not: ``kart`` (a 2.7 km figure-of-eight circuit crossing itself on a bridge, a pit lane, garages,
a paddock), ``bunker`` (three levels of rooms behind blast doors, crawlways too low for the agent, two stairwells),
``hall`` (a 240 x 150 m exhibition hall of open floor between sparse pillars), ``slopes`` (ridges whose flanks run
through the 45-degree limit), ``islets`` (scores of small islands out of reach) and ``catacombs`` (galleries 1.8-2.2
m wide and about 200 m long). Recast reads surfaces, not solids: a ceiling laid on the tops of solids leaves those
tops floor under it (:func:`_lid` stops 1 m above them), and the floor stops under every hollow solid one could
stand inside (the catacombs' rock, the bunker's machines, the paddock's trailers).

Tenth round: six more kinds, 545-909 navmesh polygons with that agent (seeds 0-2): ``helix`` (a car park that is one
helical ramp of six turns round a solid core), ``rooftops`` (roofs at 8-20 m joined by steps under the climb, flights
and planks, with nothing below), ``flooded`` (a town whose streets hold no floor: pavements, duckboards, shops),
``cave`` (chambers and tunnels on rolling ground, stalagmites, columns), ``train`` (a station of three platforms
with two trains of carriages one walks through) and ``ruins`` (three storeys joined only by slabs fallen through
holes, some too steep, and one stairwell). The same rule again: the top of a solid under a roof is floor unless
it stops 1 m short (:func:`_gable`), and a flat top out of reach (a tank's, a skylight's) is floor of its own.

Eleventh round: six more kinds, 548-855 navmesh polygons with that agent (seeds 0-2): ``library`` (three storeys
of floor-to-ceiling shelves in rows round a reading hall open to the roof, galleries, a grand flight, two
stairwells), ``trenches`` (three zig-zag trench lines 2.5 m deep under an open field, communication trenches,
dugouts, exits, footbridges), ``refinery`` (a yard cut into fields by pipe runs crossed only by crossover stairs,
tanks whose roofs are reached by stairs wound round their shells, a catwalk), ``cemetery`` (a lattice of graves
in plots between paths, mausoleums, a chapel over a crypt), ``quarry`` (an open pit of five benches joined only by
a switchback haul road, berms, machines) and ``stairhall`` (landings 3-12 m up over a hall's floor joined only by
flights and bridges). A round solid standing on the ground needs the ground to stop under it too
(:func:`_round_ground`), and a stair that ends on a roof needs a landing: the last step alone joined no tank roof.

Twelfth round: six more kinds, 557-829 navmesh polygons with that agent (seeds 0-2): ``hotel`` (six storeys of
rooms off corridors, a stair core with lift shafts open from the ground to the roof, a fire stair, a lobby),
``theme_park`` (paths looping round fenced rides, queue mazes of folded lanes, a turnstile gate), ``aqueduct`` (a
lower town under a bridge street 8 m up on an arcade, stairs up its piers, upper towns on terraces), ``warehouse``
(racking aisles on a dock floor 1.2 m over the yard, a mezzanine, dock doors, a ramp), ``golf`` (rolling lawns cut by
a creek crossed only by footbridges, ponds, tree clumps) and ``scaffold`` (a concrete frame's slabs, railed, each
joined through gaps to a scaffold deck round the building, a stair tower). Closed solids stacked on one another
leave a floor between them: a pier under a bridge's deck now rises to the deck's top (a first draft had floor on
every pier's top, 7.4 m² each, under the deck), and :func:`_ridged` makes each solid no one enters one convex body.

Thirteenth round: six more kinds, 459-787 navmesh polygons with that agent (seeds 0-2): ``dry_dock`` (quays round a
dock 10 m deep with altars, flights down its walls, a ship on keel blocks reached by gangways, a gantry's girder
walk 14 m up), ``mountain_pass`` (a cliff over the 45-degree limit climbed by a switchback path cut into it, a
walkable piste beside it, lift stations, huts), ``zoo`` (paths round railed enclosures the ground stops in, viewing
decks, a walk-through aviary entered by two airlocks), ``skatepark`` (bowls whose walls turn vertical, so only a
channelled one is entered on foot, quarter pipes, funboxes, stair sets), ``interchange`` (a concourse over three
metro lines 8, 16 and 24 m down, crossing, joined by banks of three escalators) and ``stepwell`` (a pit of terraces
1.8 m apart joined by short flights two or one a side, pillars). A flight meets a floor beside it at its first and
last steps only (Recast's ledge filter: a span whose walkable neighbours differ by more than the climb is a ledge),
so each flight here ends on a landing or head-on (a first draft's flights down the dock's walls, along the wall,
joined nothing); the top of a closed solid inside another is floor (the ship's hull under its superstructure, the
first draft), so covers reach down to the hull's bottom and the hull stops under them.

Fourteenth round: six more kinds, 601-898 navmesh polygons with that agent (seeds 0-2): ``farm`` (fields joined only
by gates, gaps in hedges and stiles over fences, barn lofts up ladders no agent climbs), ``cruise_ship`` (five open
decks each stepping back from the one below, joined only at their stern and bow terraces, covered promenades round a
cabin block), ``treetops`` (platforms 4-11 m up round trunks joined by ramps into a tree over a walkable forest
floor, one flight up a group, hides by ladder only), ``beach`` (bays between groynes, each reached from one promenade
only by its own flights, a pier), ``railyard`` (rows of wagons crossed through random gaps, a footbridge) and
``craters`` (rolling ground pocked by overlapping shell craters, sandbag lines crossed only at gaps). A flight at an
angle to the axes is cut by Recast's ledge filter (a first draft's treetop flights: its cells' neighbours differ by
more than the climb), so every flight here runs along x or z; and the top of a deck inside any closed solid standing
on it is floor (the cruise ship's first draft: its cabin blocks, funnel and pools), so the block rises from under the
lowest deck and the decks stop at it.

Fifteenth round: six more kinds, 535-696 navmesh polygons with that agent (seeds 0-2): ``oil_rig`` (three decks of
equipment over the sea joined by flights through openings in the deck above, a bridge to an accommodation platform
whose block's top is the helideck), ``monastery`` (a compound on a rock with vertical faces reached only by one stair
of 10-11 flights along two faces), ``night_market`` (stall rows either side of a viaduct whose halves meet only through
its arches and round its ends), ``cinema`` (auditoria whose raked floors join a foyer 6 m up to exit corridors at the
ground: parallel stepped links between two storeys), ``estate`` (slab blocks with galleries on three storeys, sky
bridges and pends) and ``dam`` (a crest between two hilltops over a valley, two switchback stairs up vertical faces).
A flat top under a ridged deck is floor inside it (a first draft's viaduct piers: 11-12 areas of 15 m² at 8.2 m on
each seed), so the piers are ridged up into the deck.

Sixteenth round: six more kinds, 580-864 navmesh polygons with that agent (seeds 0-2): ``garden`` (a formal garden: a
terrace up three flights, a parterre of ridged beds round a fountain, a canal crossed by two bridges, a hedge maze with
one way between any two cells, a grotto under a lid, a bosquet), ``lighthouse`` (a causeway 190-265 m long over the sea,
the only way to an island of tide pools round a plinth with keeper's cottages and a tower of five switchback storeys to
a gallery), ``canal_locks`` (a flight of 7-9 locks: two banks stepping up 2 m a lock by flights on the towpaths, joined
only by the lock gates' footbridges and one road bridge), ``water_park`` (pools and a lazy river round an island in a
deck, crossed by 3-4 bridges, turnstile lanes, slide towers whose tops are dead ends, cubicles), ``paddies`` (rice
terraces whose only floor is a lattice of bunds 1.8 m wide, climbed by flights from bund to bund and a main stair)
and ``cistern`` (a forest of columns in water under a lid, walkways along a random tree of the aisles' crossings
between two stair wells down from streets). A closed solid's top inside another is floor again (a first draft's
garden terrace under its house, 317 m²; the paddies' shrine yard inside the shrine, 25 m²): the house and the shrine
now rise from under the floor round them, which stops at them.

Seventeenth round: six more kinds, 647-873 navmesh polygons with that agent (seeds 0-2): ``star_fort`` (a square
enceinte with diamond bastions, ramparts whose walk is climbed by ramps, a dry moat 5 m deep crossed only over a
ravelin to the gate, flights and a postern down into it, a glacis), ``glacier`` (sloped ice cut by crevasses en
echelon and edge to edge, crossed on snow bridges and ladders, an icefall climbed by two ramps), ``medina`` (a braid
maze of alleys 2.6 m wide among houses, courtyard houses, covered passages, a mosque's courtyard, a wall with gates),
``suburb`` (cul-de-sacs off a distributor road, plots whose fenced back gardens open only through a side gate,
footpaths to a green), ``cloverleaf`` (two motorways crossing at two heights, each split by an unbroken barrier, joined
only by four 270-degree loops) and ``radial_town`` (a round place, avenues, lanes and ring streets between ridged
blocks: the streets are the only floor). The same rules as before: the floor stops under every closed solid one could
stand inside (the fort's courtyard under its buildings, the service area's deck under its shop), a monument stands in
a ring of floor, not on it, and a car (:func:`_car`) is a hull too low inside for the agent and too steep on top.

Eighteenth round: six more kinds, 550-1,108 navmesh polygons with that agent (seeds 0-2): ``bazaar`` (a covered souk
whose stalls are the cells of a Voronoi diagram cut back from their edges, so its alleys run at every angle and change
width at every junction, some built over, courtyards, four gates), ``container_port`` (an apron under cranes, a
straddle-carrier yard of rows stacked 1-3 high between lanes 1.8-2.4 m wide, a gate: 150-180 container tops out of
reach at three heights), ``theatre`` (a Greek theatre in a hillside: seat tiers over the climb, climbed only by radial
aisle stairs at every angle between rails, a diazoma, a terrace above), ``stilt_village`` (platforms over a lagoon
joined by boardwalks at whatever angle their centres lie, houses, pontoons), ``nursery`` (glasshouses whose benches
leave combs of dead-end aisles 1.3-1.7 m wide, polytunnels, beds) and ``cliff_dwellings`` (five storeys of ledges and
rooms cut into a cliff, joined only by stair wells inside the rock, :func:`_carve`). A flight off the axes climbs
(no earlier flight ran off them), but seats beside it join the floor unless a rail parts them (the theatre's); a cell
cut back from its edges is clipped by each moved edge in turn (:func:`_inset`: a first draft met the moved lines at
each corner, so an edge the insets shrank under 0.5 m failed the cell, and 51 of seed 0's 84 inner cells became open
squares); and a door needs floor under it on both sides (the bazaar's street first stopped 0.6 m short of its gates:
two areas of 5,341 and 4,866 m² on seed 0).

Nineteenth round: six kinds with features of real game levels no earlier generator had, 398-858 navmesh polygons
with that agent (seeds 0-2): ``drop_downs`` (terraces whose edges are ledges 1.0-2.6 m high one steps off but cannot
climb, joined by flights along a spanning tree, one terrace reached only by dropping), ``house`` (two semi-detached
houses of two storeys: hallways, a narrow stair, rooms behind doors just wider than the agent passes, furniture),
``pitched_roofs`` (terraces whose roofs at 30-40 degrees are floor, each reached only from a balcony up a flight),
``kit_arena`` (a symmetric arena of modular 4 m tiles, each piece moved by up to 1.5 cm: seams of up to 3 cm),
``spiral_towers`` (two towers climbed only by helical stairs of 16-20 wedges a turn, a wall walk between them) and
``backdrop`` (a town square in a bowl of distant walkable terrain no one reaches, under an inward skybox 1 km
across). A door through a wall 0.15-0.25 m thick opens for the presets' agent (radius 0.5 m) at every offset to
Recast's 0.25 m grid from 1.5 m wide, at some from 1.3 m, never at a real house's 0.9-1.0 m; a helical stair holds
floor only where the turn above clears its treads by the agent's height with a cell or two to spare (a first draft,
two landing wedges and treads 0.15 m thick at 16 wedges of 0.175 m, held none); a stair tile fills its tile but for
its foot, so a layout joins runs of tiles through the tile behind each flight (:func:`_kit_layout`; a first draft,
whose flights could start against a wall and whose check counted a stair tile as floor of its own level, left 20 areas
on seed 0, the same with its seams closed).

Twentieth round: six more kinds with features of real exported levels, 423-817 navmesh polygons with that agent (seeds
0-2): ``closed_doors`` (two blocks of rooms off corridors whose doorways keep their leaves, closed, ajar or gone),
``paper_walls`` (a compound whose walls, fences, railings, roofs and a deck are one-sided quads with no thickness),
``split_level`` (two houses of six half storeys 1.4-1.6 m apart joined by short flights across a stair hall),
``hub_rooms`` (a caravanserai: two storeys of small rooms entered only from a courtyard and its gallery),
``corridor_shooter`` (one path of corridors, alcoves and arenas) and ``roof_town`` (a town of flat roofs out of reach,
a few reached by a flight). A lintel 2.25 m over the floor lets the presets' agent (2 m tall) pass at each of three
offsets to Recast's grid tried, one of 2.15-2.2 m at some, one of 2.1 m (a real door's) at none (:func:`_doored_wall`:
a first draft's 2.2 m lintels shut every room of the caravanserai, 58 areas on seed 0); a paper wall stops the agent as a solid one
does (the same areas; 1.4 % more walkable area, the walls' thickness); a flight's foot under a storey keeps two half
storeys less a riser and the slab of head room (2.26 m at 1.31 m a half storey closed a split-level house's storeys
into three areas on a first draft's seed 2).

Twenty-first round: six more kinds with features of real exported levels, 523-785 navmesh route graph nodes with
that agent (seeds 0-2): ``ladders`` (a pump house of three storeys joined only by ladders and lift shafts),
``jump_gaps`` (platforms over a void joined by walkways broken by gaps 0.8-2 m a player jumps), ``collision_hulls`` (a
town square exported with the invisible boxes wrapping its statues, stalls, fountain, bandstand and cars, a blocking
volume over a ledge), ``thresholds`` (shops entered over door steps of 0.05-0.3 m from pavements behind kerbs of
0.1-0.3 m, sills between rooms), ``prop_pile`` (a yard of crates, barrels, pipes and containers pushed into the floor
and into one another on overlapping floor tiles) and ``beams`` (roofs joined by balance beams 0.4-0.8 m wide, under the
presets' agent's diameter, and planks 1.2-1.6 m). A closed prop sunk into the floor leaves the floor inside it (a
container's, 2.5 m of head room) and its top as floor (:func:`prop_pile`), as a collision hull left in the file does
(:func:`collision_hulls`); a pipe lying half sunk stops the agent only where its top stands over the 0.4 m climb (a
first draft's pipes, 0.11-0.44 m up, stopped it at 3 of seed 0's 31).

Twenty-second round: six kinds of game levels designers ship that no earlier generator made, 452-873 navmesh
polygons with that agent (seeds 0-2): ``moba`` (three lanes between two bases, a river, jungles of winding paths
and camps, drawn on 2 m tiles, :func:`_tiles`), ``capture_flag`` (two mirrored bases with a flag room upstairs, a mid
field of cover, two flank tunnels under it, :func:`_mirrored`), ``platform_tower`` (a square spiral of small platforms
round a core joined by ramps and flights over a void, dead-end perches), ``diagonal_dungeon`` (rooms joined by
corridors one 2 m tile wide, at 45 degrees a staircase of tiles, :func:`_paint`), ``battle_royale`` (rolling ground
240 m square with small houses of 1-3 rooms and rock clusters) and ``arena_shooter`` (three storeys holed by atria
and joined by 6-8 ramps a storey). A rock tile is one solid from under the floor up (a first draft's turrets, ridged
blocks standing on the MOBA's floor tiles, left the floor inside each as an area of 8 m²: six a seed), and a crate on a
platform keeps off the line its joins arrive on (a first draft's crates at the spiral's corners parted the tower into
6 / 5 / 7 areas, seeds 0-2).

Twenty-third round: six more kinds of shipped game levels, 389-594 navmesh polygons with that agent (seeds 0-2):
``stealth_mansion`` (a house of two storeys on a plinth over a crawlspace, a hall and a parallel servants' corridor on
each, vents too low to walk, grand and servants' stairs, hedged parterres), ``defusal`` (a bomb-defusal map: two
bombsites, a mid lane, long and short routes, connectors, spawn yards at both ends, side rooms), ``payload`` (one road
winding 340-370 m through a town on rolling ground, side alleys, flanking buildings, shops), ``metroidvania`` (a grid of
rooms 9-11 across and 5-6 storeys joined by doors, flights and ramps along a spanning tree and loops),
``tower_defence`` (one lane switching back 10-12 times between wall strips notched by build pads) and ``hub_world`` (a
round plaza whose four portals lead down wings to dead-end zones: rooms, pillars, a stepped hill, a maze, caves). A
room carved beside a route opens only onto the route's open floor (:func:`_tile_rooms`: a first draft's side room
opened onto a doorway's frame, an area of 61 m² on the defusal map's seed 1), and a flight rising through a room's
slab stands against its wall with a doorway at its top (:func:`stealth_mansion`: a first draft's grand stair, its
rails 1.5 m from the walls, cut a strip of the room above off, 40 m² on seed 1; against the wall but arriving at the
hall's wall with no doorway, it cut off the room, 49-50 m² on every seed).

Twenty-fourth round: six more kinds of shipped game levels, 409-827 navmesh polygons with that agent (seeds 0-2):
``tavern`` (an inn of three storeys: a taproom of table groups, a bar, a kitchen over a cellar, galleries round a well
open to the roof, two flights, bedrooms), ``military_base`` (a battle-royale compound: a fence with 3-4 gates, a hangar,
buildings and sheds with loot rooms, :func:`_tile_building`), ``king_of_hill`` (a stepped hill of four terraces 1.2 m
apart, each step climbed by two ramps, round a capture point), ``favela`` (bands of houses up a hillside whose roofs
are the alley above's floor, climbed by stair lanes), ``hive`` (hexagonal cells whose walls run at 60 degrees,
doorways along a spanning tree and loops, a queen's chamber, :func:`_wall_line`) and ``western_town`` (a main street
between rows of one- and two-storey buildings on boardwalks, balconies joined over alleys by bridges, alley flights,
corrals). A first draft's tavern put the second flight's foot 0.8 m past the first's head: the first storey's gallery
was an area of its own (391 / 383 / 380 m² on seeds 0-2); the feet are now 8 m apart. A flight 1.4 m wide between
drops (the western town's first draft, inside and up its alleys) holds no floor past its first steps: the ledge
filter and the agent's radius take both sides (upper storeys apart, 6 / 5 / 5 areas); at 2 m wide each climbs.

Twenty-fifth round: six more kinds of game levels, 377-594 navmesh polygons with that agent (seeds 0-2):
``killhouse`` (roofless plywood rooms divided recursively, :func:`_divide`, under an observation catwalk over the
walls reached by two flights), ``supermarket`` (gondola aisles, a bank of checkout lanes, a storeroom, a car park, on
2 m tiles), ``rts_map`` (a real-time-strategy map the same under a half turn: each main a plateau left by one ramp
to a natural expansion and one more to the low ground), ``ziggurat`` (a temple city: step pyramids whose terraces are
reached only up one stair of flights on one face, :func:`_step_pyramid`, a ball court, a causeway), ``reactor``
(round galleries on 6-7 levels over one void, bridges at random angles to rings round a core, two stair towers,
:func:`_chorded_ring`) and ``gorge_bridge`` (a deck over a gorge, a catwalk under it joined by flights at its piers, banks
with houses). The floor stops under closed solids again: a first draft's reactor kept the ground inside its core
pillar and inside two machines (4 areas on seed 0), the bridge's banks ran on inside their houses (15 areas), and a
pyramid's terraces 4 m wide, the flight up each starting 0.4 m from the one below's top, left its upper tiers apart
(3 / 5 / 3 areas on seeds 0-2); with terraces 6 m wide each tier climbs.

Run: ``.venv/bin/python benchmarks/level_kinds.py OUT_DIR [--kinds subway forest] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``, the files ``benchmarks/analysis_quality.py --levels`` takes (which also takes the
kinds' names and builds them with ``--seeds``).
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from itertools import pairwise
from pathlib import Path

import numpy as np
import scipy.sparse as sp
import trimesh
from scipy import ndimage
from scipy.sparse.csgraph import connected_components, minimum_spanning_tree
from scipy.spatial import Voronoi, cKDTree


def _cut_lines(x0: float, x1: float, z0: float, z1: float,
               holes: list[tuple[float, float, float, float]]) -> tuple[np.ndarray, np.ndarray]:
    """The sorted x (k,) and z (m,) of the rectangle [x0, x1] x [z0, z1]'s edges and its holes' edges, clipped to it."""
    xs = np.unique(np.clip([x0, x1, *[h[i] for h in holes for i in (0, 1)]], x0, x1))
    zs = np.unique(np.clip([z0, z1, *[h[i] for h in holes for i in (2, 3)]], z0, z1))
    return xs, zs


def _pieces(lo: float, hi: float, gaps: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The spans (start, end) of the line from ``lo`` to ``hi`` left between the gaps (start, width), each start in
    metres from ``lo``: a wall's solid pieces (:meth:`_Solids.wall`, :func:`_wall_line`), none shorter than a
    micrometre. O(gaps log gaps)."""
    cuts = [lo, *sum(([lo + start, lo + start + width] for start, width in sorted(gaps)), []), hi]
    return [(c0, c1) for c0, c1 in zip(cuts[0::2], cuts[1::2]) if c1 - c0 > 1e-6]


class _Solids:
    """Convex solids gathered into one mesh."""

    def __init__(self) -> None:
        self.parts: list[trimesh.Trimesh] = []

    def hull(self, points: np.ndarray) -> None:
        """The convex hull of ``points`` (k, 3), metres."""
        self.parts.append(trimesh.convex.convex_hull(np.asarray(points, dtype=np.float64)))

    def rock(self, rng: np.random.Generator, p: np.ndarray, spread: float, y0: float, y1: float) -> None:
        """A rock: the hull of 8 points scattered round plan point ``p`` (x, z) with a standard deviation of
        ``spread`` m, at heights uniform in [y0, y1]."""
        self.hull(np.concatenate([p + rng.normal(0, spread, size=(8, 2)), rng.uniform(y0, y1, (8, 1))], axis=1)[:, [0, 2, 1]])

    def box(self, x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> None:
        """An axis-aligned box over [x0, x1] x [y0, y1] x [z0, z1]."""
        self.hull(np.array([[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]))

    def prism(self, plan: np.ndarray, y0: float, y1: float) -> None:
        """A vertical prism over the convex plan polygon ``plan`` (k, 2) of x, z, between heights y0 < y1."""
        plan = np.asarray(plan, dtype=np.float64)
        self.hull(np.concatenate([np.insert(plan, 1, y, axis=1) for y in (y0, y1)]))

    def slab(self, x0: float, x1: float, z0: float, z1: float, top: float, holes: list[tuple[float, float, float, float]],
             thickness: float = 0.3) -> None:
        """A floor slab over [x0, x1] x [z0, z1] with its top at ``top``, open over each hole (x0, x1, z0, z1).

        Cut along every hole's edges into a grid of rectangles; the cells outside all holes are kept.
        """
        xs, zs = _cut_lines(x0, x1, z0, z1, holes)
        for a, b in zip(xs[:-1], xs[1:]):
            for c, d in zip(zs[:-1], zs[1:]):
                mx, mz = (a + b) / 2, (c + d) / 2
                if not any(h[0] < mx < h[1] and h[2] < mz < h[3] for h in holes):
                    self.box(a, b, top - thickness, top, c, d)

    def ground(self, x0: float, x1: float, z0: float, z1: float, top: float, holes: list[tuple[float, float, float, float]],
               thickness: float = 0.5) -> None:
        """Ground over [x0, x1] x [z0, z1] with its top at ``top``, stopping under each hole (x0, x1, z0, z1).

        As :meth:`slab`, but the cells of a strip between two cut lines along x are joined into one box per run
        outside the holes: about (strips x holes crossing them) boxes for many holes, not (2 holes)^2.
        """
        xs, zs = _cut_lines(x0, x1, z0, z1, holes)
        for a, b in zip(xs[:-1], xs[1:]):
            mx = (a + b) / 2
            start = None
            for c, d in zip(zs[:-1], zs[1:]):
                mz = (c + d) / 2
                if any(h[0] < mx < h[1] and h[2] < mz < h[3] for h in holes):
                    if start is not None:
                        self.box(a, b, top - thickness, top, start, c)
                    start = None
                elif start is None:
                    start = c
            if start is not None:
                self.box(a, b, top - thickness, top, start, zs[-1])

    def stairs(self, start: np.ndarray, heading: np.ndarray, width: float, y0: float, rise: float,
               riser: float = 0.15, tread: float = 0.30, depth: float | None = None) -> None:
        """A straight flight from ``start`` (x, z) along the unit ``heading`` (x, z), climbing ``rise`` from ``y0``.

        Each step is a solid block from ``y0`` (0.3 m under it) up to its tread, or with ``depth`` a block that deep
        under its tread (a flight with room under it); the flight's plan is ``rise / riser * tread`` long.
        """
        start, heading = np.asarray(start, dtype=np.float64), np.asarray(heading, dtype=np.float64)
        side = np.array([-heading[1], heading[0]]) * width / 2
        for i in range(int(round(rise / riser))):
            a, b = start + heading * tread * i, start + heading * tread * (i + 1)
            top = y0 + riser * (i + 1)
            self.prism(np.array([a - side, b - side, b + side, a + side]), y0 - 0.3 if depth is None else top - depth, top)

    def ramp(self, a: np.ndarray, b: np.ndarray, width: float, ya: float, yb: float, thickness: float = 0.3) -> None:
        """A straight deck from plan point ``a`` (x, z) with its top at ``ya`` to ``b`` at ``yb``, ``width`` m wide."""
        a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
        along = (b - a) / np.linalg.norm(b - a)
        side = np.array([-along[1], along[0]]) * width / 2
        corners = [(a - side, ya), (a + side, ya), (b - side, yb), (b + side, yb)]
        self.hull(np.array([[p[0], y - d, p[1]] for p, y in corners for d in (0.0, thickness)]))

    def wall(self, a: tuple[float, float], b: tuple[float, float], y0: float, y1: float,
             doors: list[tuple[float, float]] = (), thickness: float = 0.2) -> None:
        """A wall along x or along z from plan point ``a`` (x, z) to ``b``, between heights y0 < y1, open over each
        door (start, width), metres along the wall from its end of lower x (or z); ``thickness`` centred on the line.
        Each piece between the doors (:func:`_pieces`) is one box; :func:`_wall_line` draws a wall at any other angle."""
        along = 0 if a[1] == b[1] else 1
        lo, hi = sorted((a[along], b[along]))
        fixed, half = a[1 - along], thickness / 2
        for c0, c1 in _pieces(lo, hi, doors):
            x0, x1, z0, z1 = (c0, c1, fixed - half, fixed + half) if along == 0 else (fixed - half, fixed + half, c0, c1)
            self.box(x0, x1, y0, y1, z0, z1)

    def mesh(self) -> trimesh.Trimesh:
        """Every solid in one mesh, coincident vertices merged."""
        mesh = trimesh.util.concatenate(self.parts)
        mesh.merge_vertices()
        return mesh


def subway(seed: int) -> trimesh.Trimesh:
    """A subway station: side and island platforms at y = 0, two track pits 1.2 m lower, a concourse at each end.

    Across z: side platform, pit, island platform, pit, island platform, pit, side platform, walled in. Each end has a concourse
    4.5 m up (a slab over the whole width with a gate line across it), reached from every platform by a
    flight of 0.15 / 0.30 m steps 2.5 m wide. Two rows of pillars every 4.5-5.5 m on each island, benches on the platforms.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length = rng.uniform(230.0, 250.0)
    side_w, island_w, pit_w = rng.uniform(4.5, 6.0), rng.uniform(8.0, 11.0), 4.6
    edges = np.cumsum([0.0, side_w, pit_w, island_w, pit_w, island_w, pit_w, side_w])  # z of each band's edges
    platforms = list(zip(edges[0::2], edges[1::2]))
    pits = list(zip(edges[1::2], edges[2::2]))
    width = edges[-1]
    concourse = rng.uniform(18.0, 26.0, size=2)  # x extent of the concourse at each end
    s.box(0, length, -1.7, -1.2, 0, width)  # pit floor everywhere under the bands
    for z0, z1 in platforms:
        s.box(0, length, -1.7, 0.0, z0, z1)
    for z0, z1 in pits:  # rails in the pits
        for offset in (1.5, 3.1):
            s.box(0, length, -1.2, -1.05, z0 + offset - 0.04, z0 + offset + 0.04)
    s.box(-0.5, 0, -1.7, 8.0, -0.5, width + 0.5)
    s.box(length, length + 0.5, -1.7, 8.0, -0.5, width + 0.5)
    s.box(-0.5, length + 0.5, -1.7, 8.0, -0.5, 0)
    s.box(-0.5, length + 0.5, -1.7, 8.0, width, width + 0.5)
    run = 4.5 / 0.15 * 0.30
    for end, extent in enumerate(concourse):
        x0, x1 = (0.0, extent) if end == 0 else (length - extent, length)
        s.slab(x0, x1, 0, width, 4.5, [])
        gate = (x0 + x1) / 2 + (-3.0 if end == 0 else 3.0)  # a gate line: 0.6 m cabinets, 1.3 m passages
        for z in np.arange(0.4, width - 1.0, 1.9):
            s.box(gate - 0.4, gate + 0.4, 4.5, 5.5, z, z + 0.6)
        toward = np.array([-1.0, 0.0]) if end == 0 else np.array([1.0, 0.0])
        foot_x = x1 + run if end == 0 else x0 - run
        for z0, z1 in platforms:
            zc = (z0 + z1) / 2 + rng.uniform(-0.2, 0.2) * (z1 - z0 - 2.5)
            s.stairs(np.array([foot_x, zc]), toward, 2.5, 0.0, 4.5)
    for x in np.arange(concourse[0] + run + 4.0, length - concourse[1] - run - 2.0, rng.uniform(4.5, 5.5)):
        for z0, z1 in platforms[1:-1]:  # two rows of pillars on each island, benches between them
            for zc in (z0 + 2.2, z1 - 2.2):
                s.box(x - 0.4, x + 0.4, 0.0, 4.2, zc - 0.4, zc + 0.4)
            if rng.random() < 0.5:
                s.box(x + 2.0, x + 4.0, 0.0, 0.45, (z0 + z1) / 2 - 0.3, (z0 + z1) / 2 + 0.3)
        for z0, z1 in (platforms[0], platforms[-1]):
            if rng.random() < 0.8:
                zb = z0 + 0.6 if z0 == 0 else z1 - 1.1
                s.box(x - 1.0, x + 1.0, 0.0, 0.45, zb, zb + 0.5)
    return s.mesh()


def _islands(rng: np.random.Generator, n: int, extent: float) -> tuple[np.ndarray, np.ndarray]:
    """Centres (n, 2) and radii (n,) of islands in a square ``extent`` m wide, at least 12 m of water apart."""
    centres, radii = [], []
    while len(centres) < n:
        c, r = rng.uniform(20, extent - 20, size=2), rng.uniform(9.0, 18.0)
        if all(np.linalg.norm(c - d) > r + q + 12.0 for d, q in zip(centres, radii)):
            centres.append(c)
            radii.append(r)
    return np.array(centres), np.array(radii)


def _rock_or_palm(s: _Solids, rng: np.random.Generator, p: np.ndarray, top: float, rock: tuple[float, float],
                  trunk: float, height: float) -> None:
    """At plan point ``p`` (x, z) on ground at ``top``: a rock (the hull of 8 points scattered round ``p``, up to
    U(*rock) m high) or, as often, a palm's trunk (an octagon ``trunk`` m in radius, ``height`` m above the ground)."""
    if rng.random() < 0.5:
        size = rng.uniform(*rock)
        s.rock(rng, p, size / 2, top - 0.2, top + size)
    else:
        ring = np.linspace(0, 2 * math.pi, 8, endpoint=False)
        s.prism(p + trunk * np.stack([np.cos(ring), np.sin(ring)], 1), top - 0.5, top + height)


def archipelago(seed: int) -> trimesh.Trimesh:
    """Islands (flat convex tops 0.5-2 m up, rocks and palm trunks on them) joined by narrow railed bridges.

    The bridges follow the islands' minimum spanning tree plus 3 of the next shortest pairs (a few loops);
    each deck is 1.8-2.4 m between 1 m railings and slopes from one island's top to the other's.
    No water surface: the sea is nothing to walk on.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    centres, radii = _islands(rng, 26, 330.0)
    tops = rng.uniform(0.5, 2.0, size=len(centres))
    for c, r, top in zip(centres, radii, tops):
        angles = np.sort(rng.uniform(0, 2 * math.pi, size=14))
        plan = c + (r * rng.uniform(0.75, 1.0, size=14))[:, None] * np.stack([np.cos(angles), np.sin(angles)], 1)
        s.prism(plan, top - 3.0, top)
        for _ in range(rng.integers(6, 12)):  # rocks and palms well inside the shore
            _rock_or_palm(s, rng, c + rng.uniform(-0.5, 0.5, size=2) * r, top, (0.8, 2.2), 0.25, 6.0)
    gaps = np.linalg.norm(centres[:, None] - centres[None], axis=2) - radii[:, None] - radii[None]
    pairs = sorted((gaps[i, j], i, j) for i in range(len(centres)) for j in range(i + 1, len(centres)))
    group = list(range(len(centres)))

    def root(i: int) -> int:
        while group[i] != i:
            i = group[i]
        return i

    chosen, extra = [], []
    for _, i, j in pairs:  # Kruskal's minimum spanning tree, then the shortest pairs left
        if root(i) != root(j):
            group[root(i)] = root(j)
            chosen.append((i, j))
        elif len(extra) < 3:
            extra.append((i, j))
    for i, j in chosen + extra:
        along = (centres[j] - centres[i]) / np.linalg.norm(centres[j] - centres[i])
        a, b = centres[i] + along * (radii[i] * 0.6), centres[j] - along * (radii[j] * 0.6)
        width = rng.uniform(1.8, 2.4)
        s.ramp(a, b, width, tops[i], tops[j])
        side = np.array([-along[1], along[0]]) * (width / 2 - 0.05)
        shore_a, shore_b = centres[i] + along * radii[i], centres[j] - along * radii[j]
        span = np.linalg.norm(b - a)
        t = np.array([np.dot(shore_a - a, along), np.dot(shore_b - a, along)]) / span
        ya, yb = tops[i] + t * (tops[j] - tops[i])
        for sign in (-1, 1):  # railings over the water only, so the bridge's ends stay open
            s.ramp(shore_a + sign * side, shore_b + sign * side, 0.1, ya + 1.0, yb + 1.0, thickness=1.3)
    return s.mesh()


def car_park(seed: int) -> trimesh.Trimesh:
    """Three storeys 3.5 m apart on a 90 x 58 m plan: two car-park decks and an office on top.

    Storey k joins k + 1 by a 6 m ramp at 10 degrees through a slot in k + 1, at alternate ends; two
    switchback stairwells (3 x 6.4 m shafts, walls with one 1.6 m door a storey) at opposite corners. Decks
    have 0.6 m pillars on an 8 m grid and parked cars (4.2 x 1.8 x 1.5 m blocks); the office has a row of 6 x 12 m
    rooms along its back (a 1.2 m door each) and desks in the open floor; 1.1 m parapets.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, storey = 90.0, 58.0, 3.5
    run = storey / math.tan(math.radians(10.0))
    ramps = [(10.0, 10.0 + run, 2.0, 8.0) if k % 2 == 0 else (size_x - 10.0 - run, size_x - 10.0, 2.0, 8.0)
             for k in range(2)]
    wells = [(size_x - 3.0, size_x, size_z - 6.4, size_z), (0.0, 3.0, size_z - 6.4, size_z)]
    for k in range(3):
        y = k * storey
        holes = list(wells) if k > 0 else []
        if k > 0:
            holes.append(ramps[k - 1])
        s.slab(0, size_x, -0.2, size_z, y, holes)
        for x0, x1, z0, z1 in ((-0.3, 0, -0.2, size_z), (size_x, size_x + 0.3, -0.2, size_z),
                               (-0.3, size_x + 0.3, -0.5, -0.2), (-0.3, size_x + 0.3, size_z, size_z + 0.3)):
            s.box(x0, x1, y, y + 1.1, z0, z1)
        for x0, x1, z0, z1 in wells:  # shaft walls, a door toward the deck on the inner long side
            inner = x0 - 0.2 if x0 > 0 else x1
            s.box(inner, inner + 0.2, y, y + storey - 0.3, z0, z0 + 2.0)
            s.box(inner, inner + 0.2, y, y + storey - 0.3, z0 + 3.6, z1)
            s.box(x0, x1, y, y + storey - 0.3, z0 - 0.2, z0)
        if k < 2:
            x0, x1, z0, z1 = ramps[k]
            up = k % 2 == 0
            s.ramp(np.array([x0 if up else x1, 5.0]), np.array([x1 if up else x0, 5.0]), 6.0, y, y + storey)
            for z in (z0 - 0.2, z1):  # kerbs along the ramp's slot
                s.box(x0, x1, y, y + 1.0, z, z + 0.2)
        if k < 2:
            for x in np.arange(8.0, size_x - 4.0, 8.0):
                for z in np.arange(12.0, size_z - 4.0, 8.0):
                    s.box(x - 0.3, x + 0.3, y, y + storey - 0.3, z - 0.3, z + 0.3)
            for _ in range(45):
                x, z = rng.uniform(5, size_x - 9), rng.uniform(11.0, size_z - 8.0)
                s.box(x, x + 4.2, y, y + 1.5, z, z + 1.8) if rng.random() < 0.7 else s.box(x, x + 1.8, y, y + 1.5, z, z + 4.2)
        else:
            wall = size_z - 12.0  # one row of rooms along the back, 12 m deep, a 1.2 m door each
            rooms = np.arange(6.0, size_x - 6.0 + 1e-9, 6.0)
            doors = rooms[:-1] + rng.uniform(1.0, 3.8, size=len(rooms) - 1)
            xs = [rooms[0], *sum(([d, d + 1.2] for d in doors), []), rooms[-1]]
            for a, b in zip(xs[0::2], xs[1::2]):
                s.box(a, b, y, y + 3.0, wall, wall + 0.15)
            for x in rooms:
                s.box(x, x + 0.15, y, y + 3.0, wall, size_z)
            for _ in range(90):
                x, z = rng.uniform(6, size_x - 8), rng.uniform(11.0, size_z - 15.0)
                s.box(x, x + 1.6, y, y + 0.75, z, z + 0.8)
    for x0, x1, z0, z1 in wells:  # switchbacks: up along +z on one half, landing, back along -z on the other
        for k in range(2):
            y = k * storey
            s.stairs(np.array([x0 + 0.75, z0 + 0.4]), np.array([0.0, 1.0]), 1.5, y, storey / 2, riser=0.175, tread=0.28)
            landing = z0 + 0.4 + 10 * 0.28
            s.box(x0, x1, y, y + storey / 2, landing, z1)
            s.stairs(np.array([x0 + 2.25, landing]), np.array([0.0, -1.0]), 1.5, y + storey / 2, storey / 2,
                     riser=0.175, tread=0.28)
    return s.mesh()


def forest(seed: int) -> trimesh.Trimesh:
    """Open hilly ground 120 m square (hills up to about 6 m, slopes under 25 degrees) with 300 tree trunks
    (octagons 0.2-0.6 m in radius) and 30 fallen logs (0.3-0.5 m radius, 4-10 m long) lying on it."""
    rng = np.random.default_rng(seed)
    s = _Solids()
    size, step = 120.0, 2.5
    grid = np.arange(0.0, size + step / 2, step)
    waves = rng.normal(size=(6, 4))

    def height(x: np.ndarray, z: np.ndarray) -> np.ndarray:
        return sum(1.2 * np.sin(x * (0.02 + 0.03 * abs(w[0])) + w[1] * 3) * np.cos(z * (0.02 + 0.03 * abs(w[2])) + w[3] * 3)
                   for w in waves)

    gx, gz = np.meshgrid(grid, grid, indexing="ij")
    n = len(grid)
    vertices = np.stack([gx.ravel(), height(gx, gz).ravel(), gz.ravel()], axis=1)
    index = np.arange(n * n).reshape(n, n)
    a, b, c, d = index[:-1, :-1].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel(), index[:-1, 1:].ravel()
    faces = np.concatenate([np.stack([a, c, b], 1), np.stack([a, d, c], 1)])  # counter-clockwise seen from +y
    ground = trimesh.Trimesh(vertices, faces, process=False)
    skirt = ground.copy()
    skirt.vertices[:, 1] -= 0.5
    skirt.invert()
    s.parts += [ground, skirt]
    angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
    ring = np.stack([np.cos(angles), np.sin(angles)], 1)
    trunks = rng.uniform(3.0, size - 3.0, size=(300, 2))
    for (x, z), r in zip(trunks, rng.uniform(0.2, 0.6, size=300)):
        y = float(height(np.array(x), np.array(z)))
        s.prism(np.array([x, z]) + r * ring, y - 1.5, y + 9.0)
    for _ in range(30):
        centre, heading = rng.uniform(8.0, size - 8.0, size=2), rng.uniform(0, math.pi)
        half, r = rng.uniform(2.0, 5.0), rng.uniform(0.3, 0.5)
        along = np.array([math.cos(heading), math.sin(heading)])
        ends = [centre - half * along, centre + half * along]
        ys = [float(height(np.array(p[0]), np.array(p[1]))) + r * 0.8 for p in ends]
        side = np.array([-along[1], along[0]])
        s.hull(np.array([[p[0] + r * ca * side[0], y + r * sa, p[1] + r * ca * side[1]]
                         for p, y in zip(ends, ys) for ca, sa in ring]))
    return s.mesh()


def stadium(seed: int) -> trimesh.Trimesh:
    """A bowl: a pitch at y = 0, four stands of stepped tiers (open corners), each with aisle stairs, a cross aisle
    half way up, a top walkway, and vomitories (tunnels 3 m wide) from the cross aisle out to an outer deck at
    the cross aisle's height, which stairs at both ends of the stand bring down to the ground.

    Tier rows are 0.8 m deep and 0.45 m high (more than the agent's climb: seats are not walked on); aisles
    (2 m wide) climb them in half steps of 0.225 / 0.4 m.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    half_x, half_z = rng.uniform(52.0, 58.0), rng.uniform(34.0, 38.0)
    lower, upper, row, rise = int(rng.integers(9, 12)), int(rng.integers(9, 12)), 0.8, 0.45
    margin = 5.0  # flat walk between the pitch and the first row
    cross_depth, top_depth = 3.0, 3.0
    # one stand's depth profile, distance from its front (toward the pitch): (start, end, top) per step
    steps: list[tuple[float, float, float]] = []
    d, y = 0.0, 0.0
    for i in range(lower):
        y += rise
        steps.append((d, d + row, y))
        d += row
    steps.append((d, d + cross_depth, y))
    cross = (d, d + cross_depth, y)
    d += cross_depth
    for i in range(upper):
        y += rise
        steps.append((d, d + row, y))
        d += row
    steps.append((d, d + top_depth, y))
    depth, cross_y = d + top_depth, cross[2]
    near_x, near_z = half_x + margin, half_z + margin
    # the ground stops under the stands, whose solid tiers reach down to its bottom: no floor inside a solid
    s.slab(-half_x - 40, half_x + 40, -half_z - 40, half_z + 40, 0.0, [
        (-half_x, half_x, near_z, near_z + depth), (-half_x, half_x, -near_z - depth, -near_z),
        (near_x, near_x + depth, -half_z, half_z), (-near_x - depth, -near_x, -half_z, half_z)], thickness=0.5)
    deck_depth = 5.0
    for side in range(4):
        along_x = side < 2
        span = half_x if along_x else half_z
        front = (half_z if along_x else half_x) + margin
        sign = 1.0 if side % 2 == 0 else -1.0

        def put(a0: float, a1: float, d0: float, d1: float, y0: float, y1: float) -> None:
            """A box in the stand's frame: ``a`` along it, ``d`` outward from its front."""
            n0, n1 = sorted((sign * (front + d0), sign * (front + d1)))
            if along_x:
                s.box(a0, a1, y0, y1, n0, n1)
            else:
                s.box(n0, n1, y0, y1, a0, a1)

        aisles = np.linspace(-span + 6.0, span - 6.0, int(rng.integers(12, 15)))
        vomitories = (aisles[:-1] + aisles[1:]) / 2
        vomitories = vomitories[::3]
        cuts = sorted([(a - 1.0, a + 1.0, "aisle") for a in aisles] + [(v - 1.5, v + 1.5, "vom") for v in vomitories])
        bounds = [-span, *sum(([c[0], c[1]] for c in cuts), []), span]
        for a0, a1 in zip(bounds[0::2], bounds[1::2]):  # plain tiers between the cuts
            for d0, d1, top in steps:
                put(a0, a1, d0, d1, -0.5, top)
        for a0, a1, kind in cuts:
            for d0, d1, top in steps:
                if kind == "aisle":
                    if d1 - d0 > row + 1e-9:  # cross aisle and top walkway stay whole across the aisle
                        put(a0, a1, d0, d1, -0.5, top)
                    else:
                        put(a0, a1, d0, d0 + row / 2, -0.5, top - rise / 2)
                        put(a0, a1, d0 + row / 2, d1, -0.5, top)
                elif d0 < cross[1] - 1e-9:  # a vomitory cuts only the upper tiers
                    put(a0, a1, d0, d1, -0.5, top)
                else:  # the tunnel: floor at the cross aisle, roof 2.6 m over it under the upper tiers
                    put(a0, a1, d0, d1, -0.5, cross_y)
                    if top > cross_y + 2.9:
                        put(a0, a1, d0, d1, cross_y + 2.6, top)
        put(-span, span, depth, depth + deck_depth, cross_y - 0.3, cross_y)  # the outer deck
        put(-span, span, depth + deck_depth, depth + deck_depth + 0.2, cross_y, cross_y + 1.1)
        run = cross_y / 0.15 * 0.30
        for end in (-1.0, 1.0):  # stairs from the deck's ends down to the ground, going outward along the stand
            a = end * span
            centre_d = sign * (front + depth + deck_depth / 2)
            start = np.array([a + end * run, centre_d]) if along_x else np.array([centre_d, a + end * run])
            heading = np.array([-end, 0.0]) if along_x else np.array([0.0, -end])
            s.stairs(start, heading, deck_depth - 0.4, 0.0, cross_y)
    return s.mesh()


def harbour(seed: int) -> trimesh.Trimesh:
    """A quay 2 m above the water with warehouses, bollards and crates, 9-10 piers out over the water, and boats moored
    along the piers: small ones whose decks lie 0.2-0.35 m under the pier (stepped onto over a gap in their
    bulwark), larger ones whose decks lie 1 m above it, reached by a gangway. No water surface."""
    rng = np.random.default_rng(seed)
    s = _Solids()
    length, quay = 300.0, 24.0
    warehouses = [(x, x + rng.uniform(12.0, 18.0), -quay, -quay + rng.uniform(7.0, 10.0))
                  for x in np.arange(6.0, length - 20.0, rng.uniform(24.0, 30.0))]  # along the back
    s.slab(0, length, -quay, 0.0, 2.0, warehouses, thickness=4.0)  # no quay inside a warehouse's solid
    for x0, x1, z0, z1 in warehouses:
        s.box(x0, x1, -2.0, 9.0, z0, z1)
    for x in np.arange(3.0, length - 2.0, 6.0):
        s.box(x - 0.25, x + 0.25, 2.0, 2.6, -1.0, -0.5)
    for _ in range(70):  # crates and containers on the open quay
        x, z = rng.uniform(2.0, length - 8.0), rng.uniform(-quay + 11.0, -3.5)
        w, d = (rng.uniform(1.0, 2.0), rng.uniform(1.0, 2.0)) if rng.random() < 0.6 else (6.0, 2.4)
        s.box(x, x + w, 2.0, 2.0 + rng.uniform(0.8, 2.6), z, z + d)
    piers = np.linspace(14.0, length - 14.0, int(rng.integers(9, 11)))
    for px in piers + rng.uniform(-3.0, 3.0, size=len(piers)):
        width, reach = rng.uniform(3.0, 5.0), rng.uniform(30.0, 55.0)
        s.box(px - width / 2, px + width / 2, 1.5, 2.0, -0.1, reach)
        for z in np.arange(3.0, reach - 1.0, 7.0):
            for sx in (-1, 1):
                bx = px + sx * (width / 2 - 0.35)
                s.box(bx - 0.2, bx + 0.2, 2.0, 2.5, z - 0.2, z + 0.2)
        for sx in (-1, 1):
            z = 2.0
            while z < reach - 8.0:
                big = rng.random() < 0.3
                beam, hull_len = (rng.uniform(5.0, 7.0), rng.uniform(14.0, 20.0)) if big else (rng.uniform(2.6, 3.8), rng.uniform(7.0, 11.0))
                if z + hull_len > reach:
                    break
                deck = 3.0 if big else 2.0 - rng.uniform(0.2, 0.35)
                near = px + sx * width / 2 + (sx * 1.5 if big else 0.0)
                far = near + sx * beam
                x0, x1 = sorted((near, far))
                bow = hull_len * 0.2
                plan = np.array([[x0, z], [x1, z], [x1, z + hull_len - bow], [(x0 + x1) / 2, z + hull_len],
                                 [x0, z + hull_len - bow]])
                s.prism(plan, deck - 1.5, deck)
                gap = (z + hull_len * 0.4, z + hull_len * 0.4 + 1.8)
                for a, b in ((z, gap[0]), (gap[1], z + hull_len - bow)):  # bulwark along the pier side, open at the gap
                    s.box(near - 0.1 if sx > 0 else near, near if sx > 0 else near + 0.1, deck, deck + 0.8, a, b)
                s.box(x0, x1, deck, deck + 0.8, z, z + 0.15)
                outer = far - sx * 0.15
                s.box(min(outer, far), max(outer, far), deck, deck + 0.8, z, z + hull_len - bow)
                cx0, cx1 = sorted((near + sx * beam * 0.35, far - sx * 0.5))
                s.box(cx0, cx1, deck, deck + 2.2, z + hull_len * 0.55, z + hull_len * 0.8)  # the cabin
                if big:  # a gangway from the pier's edge up to the bulwark's gap
                    s.ramp(np.array([px + sx * (width / 2 - 1.0), sum(gap) / 2]), np.array([near + sx * 0.6, sum(gap) / 2]),
                          1.4, 2.0, deck)
                z += hull_len + rng.uniform(1.0, 4.0)
    return s.mesh()


def school(seed: int) -> trimesh.Trimesh:
    """A two-storey school round a courtyard: a 3 m corridor rings the courtyard on both floors, classrooms 9 m
    deep between the corridor and the outer walls, each through one door 1.6-2.0 m wide, with desks (1.2 x 0.6 m,
    0.75 m high) in rows. Ground floor: the courtyard (planters, benches, trees) through 2.4 m openings in its
    wall; upper floor: a 1.1 m parapet over it. Two classrooms at opposite sides hold a straight flight (0.18 /
    0.28 m steps, 2 m wide) to the one above, railed round its opening. No roof.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, depth, corridor, storey = rng.uniform(84.0, 96.0), rng.uniform(60.0, 68.0), 9.0, 3.0, 3.6
    inner = (depth, size_x - depth, depth, size_z - depth)  # the corridor's outer edge
    court = (depth + corridor, size_x - depth - corridor, depth + corridor, size_z - depth - corridor)

    def cuts(lo: float, hi: float, corner: float) -> list[float]:
        """Partition positions from ``lo`` to ``hi``, rooms 7-9.5 m wide; the end rooms reach 4-6 m past ``corner``
        (m from each end), so that they have a door on the corridor."""
        xs = [lo, lo + corner + rng.uniform(4.0, 6.0)]
        while xs[-1] + 9.5 < hi - corner - 4.0:
            xs.append(xs[-1] + rng.uniform(7.0, 9.5))
        return [*xs, hi]

    # rooms: (side, c0, c1) along x for the sides at z = 0 ("south") and z = size_z ("north"), along z for the others
    rooms = [(side, a, b) for side in ("south", "north") for a, b in pairwise(cuts(0.0, size_x, depth))]
    rooms += [(side, a, b) for side in ("west", "east") for a, b in pairwise(cuts(depth, size_z - depth, 0.0))]
    south = sum(side == "south" for side, _, _ in rooms)
    stair_rooms = {1, 2 * south - 2}  # the second room from the west on the south side, from the east on the north
    run = storey / 0.18 * 0.28
    holes, doors = [], {side: [] for side in ("south", "north", "west", "east")}
    for index, (side, a, b) in enumerate(rooms):
        lo, hi = (max(a, inner[0]), min(b, inner[1])) if side in ("south", "north") else (a, b)
        width = rng.uniform(1.6, 2.0)
        if index in stair_rooms:  # the door beside the flight's foot
            start = a + 0.4 if a >= inner[0] else lo + 0.3
        else:
            start = rng.uniform(lo + 0.3, hi - 0.3 - width)
        doors[side].append((start, width))
        if index in stair_rooms:
            outward = -1.0 if side == "south" else 1.0
            foot_z = depth - 1.4 if side == "south" else size_z - depth + 1.4
            x0 = start + width + 0.3
            holes.append((x0, x0 + 2.0, *sorted((foot_z, foot_z + outward * run))))
            s.stairs(np.array([x0 + 1.0, foot_z]), np.array([0.0, outward]), 2.0, 0.0, storey, riser=0.18, tread=0.28)
    for level in range(2):
        y = level * storey
        s.slab(0, size_x, 0, size_z, y, [court, *holes] if level else [])
        top = y + storey - 0.3
        for z in (0, size_z):
            s.wall((0, z), (size_x, z), y, top)
        for x in (0, size_x):
            s.wall((x, 0), (x, size_z), y, top)
        for side, (a, b) in {"south": ((inner[0], inner[2]), (inner[1], inner[2])),
                             "north": ((inner[0], inner[3]), (inner[1], inner[3])),
                             "west": ((inner[0], inner[2]), (inner[0], inner[3])),
                             "east": ((inner[1], inner[2]), (inner[1], inner[3]))}.items():
            origin = a[0] if side in ("south", "north") else a[1]
            s.wall(a, b, y, top, [(start - origin, width) for start, width in doors[side]])
        court_top = top if level == 0 else y + 1.1
        for a, b in (((court[0], court[2]), (court[1], court[2])), ((court[0], court[3]), (court[1], court[3])),
                     ((court[0], court[2]), (court[0], court[3])), ((court[1], court[2]), (court[1], court[3]))):
            span = abs(b[0] - a[0]) + abs(b[1] - a[1])
            openings = [(rng.uniform(0.2, 0.45) * span, 2.4), (rng.uniform(0.55, 0.8) * span, 2.4)] if level == 0 else []
            s.wall(a, b, y, court_top, openings)
        for index, (side, a, b) in enumerate(rooms):
            if side in ("south", "north"):
                z0, z1 = (0.0, depth) if side == "south" else (size_z - depth, size_z)
                if b < size_x:
                    s.wall((b, z0), (b, z1), y, top)
                if index in stair_rooms:
                    continue
                for x in np.arange(a + 2.0, b - 2.0, 2.4):
                    for z in np.arange(z0 + 2.0, z1 - 2.5, 1.9):
                        if rng.random() < 0.75:
                            s.box(x, x + 1.2, y, y + 0.75, z, z + 0.6)
            else:
                x0, x1 = (0.0, depth) if side == "west" else (size_x - depth, size_x)
                if b < size_z - depth:
                    s.wall((x0, b), (x1, b), y, top)
                for z in np.arange(a + 2.0, b - 2.0, 2.4):
                    for x in np.arange(x0 + 2.0, x1 - 2.5, 1.9):
                        if rng.random() < 0.75:
                            s.box(x, x + 0.6, y, y + 0.75, z, z + 1.2)
    for x0, x1, z0, z1 in holes:  # railings round each flight's opening, open at its top end
        for x in (x0 - 0.1, x1):
            s.box(x, x + 0.1, storey, storey + 1.0, z0, z1)
        foot = z0 if z0 > size_z / 2 else z1
        s.box(x0 - 0.1, x1 + 0.1, storey, storey + 1.0, foot - 0.05, foot + 0.05)
    for _ in range(int(rng.integers(10, 16))):  # courtyard: planters (0.5 m, not stepped on), benches, trees
        x, z = rng.uniform(court[0] + 3, court[1] - 6), rng.uniform(court[2] + 3, court[3] - 6)
        kind = rng.random()
        if kind < 0.4:
            s.box(x, x + rng.uniform(2.0, 4.0), 0.0, 0.5, z, z + rng.uniform(1.0, 3.0))
        elif kind < 0.7:
            s.box(x, x + 1.8, 0.0, 0.45, z, z + 0.5)
        else:
            angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
            s.prism(np.array([x, z]) + 0.3 * np.stack([np.cos(angles), np.sin(angles)], 1), -0.3, 6.0)
    return s.mesh()


def cathedral(seed: int) -> trimesh.Trimesh:
    """A cathedral in its churchyard. Nave 12 m wide and 55-70 m long between two arcades of octagonal pillars
    (0.75 m in radius, bays 5-6 m), aisles 4.5 m wide, pews (0.45 m deep, 0.95 m high, 0.55 m apart: not walked
    between) either side of a 3 m central walk; side chapels (5 x 4.5 m, a 3 m arch) off every other bay of the
    north aisle; a crossing and transept arms 12 m wide reaching 20 m from the axis, a door at each end; a chancel
    raised three 0.15 m steps, with choir aisles at floor level, over a crypt 4.2 m down (pillars on a 3.5 m
    grid) that a 2 m flight (0.175 / 0.28 m steps) in each choir aisle goes down to; a half-octagon apse. A cloister
    (4 m walks round a garth, a low arcade wall with openings) off the south aisle. The west front has a 3 m and
    two 2 m doors onto the churchyard, which has gravestones and a boundary wall. Walls 1 m thick; no vaults.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    nave_len, choir_len = rng.uniform(55.0, 70.0), rng.uniform(16.0, 22.0)
    cross0, cross1 = nave_len, nave_len + 12.0
    east = cross1 + choir_len  # the chancel's east end; the apse beyond it
    crypt = (cross1, east, -10.5, 10.5)
    run = 4.2 / 0.175 * 0.28
    flights = [(cross1, cross1 + run, zc - 1.0, zc + 1.0) for zc in (-9.4, 9.4)]  # along the choir aisles' outer walls
    yard = (-35.0, east + 25.0, -55.0, 42.0)
    s.slab(*yard, 0.0, [crypt], thickness=0.5)
    s.box(cross1, east, -4.7, -4.2, -10.5, 10.5)  # the crypt's floor
    s.slab(cross1, east, -6.0, 6.0, 0.45, [])  # the raised chancel over it
    s.slab(cross1, east, -10.5, -6.0, 0.0, [flights[0]])  # choir aisles over it, open over each flight
    s.slab(cross1, east, 6.0, 10.5, 0.0, [flights[1]])
    s.stairs(np.array([cross1 - 0.9, 0.0]), np.array([1.0, 0.0]), 12.0, 0.0, 0.45)  # up to the chancel
    for x0, x1, z0, z1 in flights:
        s.stairs(np.array([x1, (z0 + z1) / 2]), np.array([-1.0, 0.0]), 2.0, -4.2, 4.2, riser=0.175, tread=0.28)
        inner = z0 - 0.1 if z0 > 0 else z1
        s.box(x0, x1, 0.0, 1.0, inner, inner + 0.1)
        s.box(x1, x1 + 0.1, 0.0, 1.0, z0 - 0.1, z1 + 0.1)
    for x in np.arange(cross1 + run + 2.0, east - 1.0, 3.5):  # the crypt's pillars
        for z in (-7.0, -3.0, 3.0, 7.0):
            s.box(x - 0.3, x + 0.3, -4.2, -0.3, z - 0.3, z + 0.3)
    s.wall((cross1, -10.5), (east, -10.5), -4.2, -0.3)
    s.wall((cross1, 10.5), (east, 10.5), -4.2, -0.3)
    s.wall((east, -10.5), (east, 10.5), -4.2, -0.3)
    s.wall((cross1, -10.5), (cross1, 10.5), -4.2, -0.3)
    height = 14.0
    angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
    octagon = np.stack([np.cos(angles), np.sin(angles)], 1)
    bays = np.arange(4.0, nave_len - 2.0, rng.uniform(5.0, 6.0))
    for x in bays:
        for z in (-6.0, 6.0):
            s.prism(np.array([x, z]) + 0.75 * octagon, -0.5, height)
    for x in (cross0, cross1):  # the crossing's piers
        for z in (-6.0, 6.0):
            s.box(x - 0.8, x + 0.8, -0.5, height, z - 0.8, z + 0.8)
    for x in np.arange(cross1 + 5.0, east - 2.0, 5.0):  # the chancel's arcade, standing on its edge
        for z in (-6.0, 6.0):
            s.prism(np.array([x, z]) + 0.6 * octagon, 0.0, height)
    west_doors = [(2.75 - 1.0, 2.0), (11.0 - 1.5, 3.0), (19.25 - 1.0, 2.0)]  # from z = -11: south aisle, nave, north aisle
    s.wall((0.0, -11.0), (0.0, 11.0), -0.5, height, west_doors, thickness=1.0)
    chapels = bays[1::2][:-1] + 0.5 * (bays[1] - bays[0])
    s.wall((0.0, 11.0), (cross0, 11.0), -0.5, height, [(x - 1.5, 3.0) for x in chapels], thickness=1.0)
    cloister = (6.0, 6.0 + rng.uniform(24.0, 30.0), -11.0 - rng.uniform(24.0, 30.0), -11.0)
    cloister_door = rng.uniform(cloister[0] + 5.0, cloister[1] - 8.0)
    s.wall((0.0, -11.0), (cross0, -11.0), -0.5, height, [(cloister_door, 2.0)], thickness=1.0)
    for x in chapels:
        s.wall((x - 2.5, 11.0), (x - 2.5, 15.5), -0.5, 6.0, thickness=0.6)
        s.wall((x + 2.5, 11.0), (x + 2.5, 15.5), -0.5, 6.0, thickness=0.6)
        s.wall((x - 2.5, 15.5), (x + 2.5, 15.5), -0.5, 6.0, thickness=0.6)
        s.box(x - 0.9, x + 0.9, 0.0, 1.0, 14.2, 14.9)  # the chapel's altar
    for sign in (-1.0, 1.0):  # transept arms
        s.wall((cross0, sign * 11.0), (cross0, sign * 20.0), -0.5, height, thickness=1.0)
        s.wall((cross1, sign * 11.0), (cross1, sign * 20.0), -0.5, height, thickness=1.0)
        s.wall((cross0, sign * 20.0), (cross1, sign * 20.0), -0.5, height, [(rng.uniform(3.0, 6.5), 2.5)], thickness=1.0)
        s.wall((cross1, sign * 11.0), (east, sign * 11.0), -0.5, height, thickness=1.0)
        s.wall((east, sign * 6.0), (east, sign * 11.0), -0.5, height, thickness=1.0)
    apse = np.array([[east + 6.0 * math.sin(a), 6.0 * math.cos(a)] for a in np.linspace(0, math.pi, 5)])
    s.prism(np.concatenate([apse, [[east, -6.0], [east, 6.0]]]), -0.5, 0.45)
    for a, b in zip(apse[:-1], apse[1:]):
        s.ramp(a, b, 1.0, height, height, thickness=height + 0.5)
    s.box(east + 1.0, east + 3.0, 0.45, 1.5, -1.0, 1.0)  # the high altar
    for x in np.arange(cross1 + 1.0, east - 1.0, 0.9):  # choir stalls along the chancel's sides
        for z in (-5.2, 4.6):
            s.box(x, x + 0.6, 0.45, 1.4, z, z + 0.6)
    for x in np.arange(6.0, cross0 - 4.0, 1.0):  # pews either side of the central walk
        for z0, z1 in ((-5.0, -1.5), (1.5, 5.0)):
            s.box(x, x + 0.45, 0.0, 0.95, z0, z1)
    x0, x1, z0, z1 = cloister  # the cloister: outer walls, a garth inside an arcade wall with openings
    s.wall((x0, z0), (x1, z0), -0.5, 6.0, thickness=0.6)
    s.wall((x0, z0), (x0, z1), -0.5, 6.0, [(rng.uniform(3.0, z1 - z0 - 5.0), 2.0)], thickness=0.6)
    s.wall((x1, z0), (x1, z1), -0.5, 6.0, thickness=0.6)
    g0, g1, h0, h1 = x0 + 4.3, x1 - 4.3, z0 + 4.3, z1 - 4.3
    for a, b in (((g0, h0), (g1, h0)), ((g0, h1), (g1, h1)), ((g0, h0), (g0, h1)), ((g1, h0), (g1, h1))):
        span = abs(b[0] - a[0]) + abs(b[1] - a[1])
        s.wall(a, b, 0.0, 0.8, [(span / 2 - 1.0, 2.0)], thickness=0.4)
    s.prism(np.array([(g0 + g1) / 2, (h0 + h1) / 2]) + 1.2 * octagon, -0.5, 0.7)  # a well in the garth
    footprint = [(-1.0, east + 7.0, -12.0, 12.0), (cross0 - 1.0, cross1 + 1.0, -21.0, 21.0), (0.0, cross0, 10.0, 16.5),
                 (x0 - 1.0, x1 + 1.0, z0 - 1.0, z1)]
    stones = 0
    while stones < 160:  # gravestones in the churchyard, clear of the buildings and the west front
        x, z = rng.uniform(yard[0] + 2.0, yard[1] - 2.0), rng.uniform(yard[2] + 2.0, yard[3] - 2.0)
        if any(a - 2.0 < x < b + 2.0 and c - 2.0 < z < d + 2.0 for a, b, c, d in footprint) or (x < 0 and abs(z) < 13.0):
            continue
        s.box(x, x + 0.8, 0.0, 0.9, z, z + 0.25)
        stones += 1
    for a, b in (((yard[0], yard[2]), (yard[1], yard[2])), ((yard[0], yard[3]), (yard[1], yard[3])),
                 ((yard[0], yard[2]), (yard[0], yard[3])), ((yard[1], yard[2]), (yard[1], yard[3]))):
        s.wall(a, b, 0.0, 1.5, thickness=0.5)
    return s.mesh()


def mine(seed: int) -> trimesh.Trimesh:
    """A room-and-pillar mine of four levels 10 m apart (y = 0 to -30), each a 76 x 56 m floor left between
    irregular rock pillars (convex heptagons 2.2-3.8 m in radius on a 10 m grid, 3.5 m straight, then tapering to
    the rock over the level), so that its drifts are 2.4-5.6 m wide,
    with a cavern where two pillars were taken out (boulders on its floor) and rock walls 3.5 m high round it.
    The levels are joined on the east by a decline (two 3.5 m legs at 11 degrees a level, a landing between
    them, a rock wall between the legs) and on the west by ladders modelled as steep stairs, 1.4 m wide, from a
    bay of the level below up to the level above: 0.18 m risers on 0.25 m treads (36 degrees), the steepest
    Recast's ledge filter lets the presets' agent (0.4 m climb) walk; 0.3 m risers, a true ladder's, are cut.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    levels, gap, size_x, size_z = 4, 10.0, 70.0, 50.0
    lo_x, hi_x, lo_z, hi_z = -3.0, size_x + 3.0, -3.0, size_z + 3.0
    leg = 0.5 * gap / math.tan(math.radians(11.0))
    ladder_z = [18.0 + 8.0 * k for k in range(levels - 1)]
    angles = np.linspace(0, 2 * math.pi, 7, endpoint=False)
    for k in range(levels):
        y = -gap * k
        cavern = (int(rng.integers(1, 5)), int(rng.integers(1, 4)))
        for i, (x0, x1) in enumerate(pairwise([lo_x, *np.arange(10.0, size_x - 1.0, 10.0), hi_x])):
            for j, (z0, z1) in enumerate(pairwise([lo_z, *np.arange(10.0, size_z - 1.0, 10.0), hi_z])):
                if (i, j) in (cavern, (cavern[0] + 1, cavern[1])):
                    s.box(x0, x1, y - 0.5, y, z0, z1)
                    continue
                radius = rng.uniform(2.6, 3.8) * rng.uniform(0.85, 1.0, size=7)
                turn = rng.uniform(0, 2 * math.pi)
                centre = np.array([5.0 + 10.0 * i, 5.0 + 10.0 * j])
                plan = centre + radius[:, None] * np.stack([np.cos(angles + turn), np.sin(angles + turn)], 1)
                s.hull(np.concatenate([np.insert(plan, 1, y - 0.5, axis=1), np.insert(plan, 1, y + 3.5, axis=1),
                                       [[centre[0], y + gap - 0.5, centre[1]]]]))  # tapering up to the rock above
                # the cell's floor stops at a square inside the pillar: Recast would find floor inside it
                core = 0.6 * radius.min()
                s.slab(x0, x1, z0, z1, y, [(centre[0] - core, centre[0] + core, centre[1] - core, centre[1] + core)],
                       thickness=0.5)
        for _ in range(int(rng.integers(3, 6))):  # boulders in the cavern
            p = np.array([10.0 + 10.0 * cavern[0], 5.0 + 10.0 * cavern[1]]) + rng.uniform(-6.0, 6.0, size=2) * [1.0, 0.4]
            size = rng.uniform(0.8, 1.6)
            s.rock(rng, p, size / 2, y - 0.2, y + size)
        west = [(ladder_z[k] - 1.0 - lo_z, 2.0)] if k < levels - 1 else []  # the ladder's top
        if k > 0:
            west.append((ladder_z[k - 1] + 0.7 - lo_z, 2.5))  # the bay the ladder below starts from
        s.wall((lo_x, lo_z), (lo_x, hi_z), y, y + 3.5, west, thickness=0.6)
        s.wall((hi_x, lo_z), (hi_x, hi_z), y, y + 3.5, [(3.0 - lo_z, 5.0)], thickness=0.6)
        s.wall((lo_x, lo_z), (hi_x, lo_z), y, y + 3.5, thickness=0.6)
        s.wall((lo_x, hi_z), (hi_x, hi_z), y, y + 3.5, thickness=0.6)
        s.box(hi_x, hi_x + 9.0, y - 0.5, y, 3.0, 8.0)  # the decline's platform at this level
        if k < levels - 1:  # the decline down to the next level: out along +z, back along -z
            z1 = 8.0 + leg
            s.ramp(np.array([hi_x + 2.25, 8.0]), np.array([hi_x + 2.25, z1]), 3.5, y, y - gap / 2)
            s.box(hi_x + 0.5, hi_x + 8.5, y - gap / 2 - 0.5, y - gap / 2, z1, z1 + 4.0)
            s.ramp(np.array([hi_x + 6.75, z1]), np.array([hi_x + 6.75, 8.0]), 3.5, y - gap / 2, y - gap)
            s.hull(np.array([[hi_x + 4.0 + dx, yy, z] for dx in (0.0, 1.0)
                             for z, yy in ((8.0, y + 1.0), (8.0, y - gap - 0.3), (z1, y - gap / 2 + 1.0), (z1, y - gap / 2 - 0.3))]))
            rise, tread = gap / 56, 0.25  # the ladder from the bay of level k + 1 up to level k's west edge
            run = gap / rise * tread
            s.stairs(np.array([lo_x - run, ladder_z[k]]), np.array([1.0, 0.0]), 1.4, y - gap, gap, riser=rise, tread=tread)
            s.box(lo_x - run - 2.0, lo_x - run, y - gap - 0.5, y - gap, ladder_z[k] - 0.7, ladder_z[k] + 0.7)
            s.box(lo_x - run - 2.0, lo_x, y - gap - 0.5, y - gap, ladder_z[k] + 0.7, ladder_z[k] + 3.2)
    return s.mesh()


def ship(seed: int) -> trimesh.Trimesh:
    """A cargo ship 150-165 m long (and a 16 m bow) and 20-24 m in beam, bow toward +x. Tank top (y = 0): an
    engine room aft (main engine, generators) and, forward of a bulkhead with a 1.8 m door at both levels, a
    hold with cargo (boxes 1-2.6 m high) and two rows of stanchions under a tween deck (3.2 m, cargo too) open
    under every hatch. Deck 2 (3.2 m) over the engine room: a 2 m corridor between cabins (about 4 m wide, the
    last two 8 m; doors 1.6-1.8 m, a bunk each). Main deck (6.4 m): open, 1.1 m bulwarks, hatch covers 1.2 m
    high with steps up, cranes and bollards, and a superstructure aft (walls, two 1.8 m doors, a mess with
    tables) under a boat deck (9.6 m; lifeboats, funnel) and a bridge deck (12.8 m) with wings. Companionways
    (0.16 / 0.25 m steps, 2 m wide; 0.2 m risers are cut by Recast's ledge filter at the presets' 0.4 m climb)
    join tank top and deck 2 and deck 2 and the main deck through cabins, the hold's tank top, tween deck and
    main deck, and, outside the superstructure's front, the main deck and the boat deck (two) and the boat and
    bridge decks; every opening is railed.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length, half = rng.uniform(150.0, 165.0), rng.uniform(10.0, 12.0)
    bow, aft, house, rise = 16.0, 0.35 * length, 20.0, 3.2  # deck 2 ends at x = aft, the superstructure at house
    riser, tread = 0.16, 0.25
    run = rise / riser * tread
    s.box(0.0, length, -0.5, 0.0, -half, half)  # tank top
    for z in (-half - 0.3, half):  # shell and bulwarks
        s.box(-0.3, length, -0.5, 7.5, z, z + 0.3)
    s.box(-0.3, 0.0, -0.5, 7.5, -half, half)
    for sign in (-1.0, 1.0):
        s.ramp(np.array([length, sign * (half + 0.15)]), np.array([length + bow, 0.0]), 0.3, 7.5, 7.5, thickness=8.0)
    cabin_edges = [*np.arange(0.0, aft - 20.0, 4.0), aft - 16.0, aft - 8.0, aft]
    hatches = [(x, x + 12.0, -half + 4.5, half - 4.5) for x in np.arange(aft + 10.0, length - 12.0, rng.uniform(16.0, 19.0))]
    # companionways, each (x0, x1, z0, z1) of its opening, climbing along +x: tank top -> deck 2 in the last cabin on
    # +z, deck 2 -> main deck in the one before on -z; in the hold, tank top -> tween deck near the bow and tween
    # deck -> main deck by the bulkhead
    lower = (aft - 7.7, aft - 7.7 + run, half - 2.6, half - 0.6)
    upper = (aft - 13.5, aft - 13.5 + run, -half + 0.6, -half + 2.6)
    hold_lower = (length - 5.0 - run, length - 5.0, half - 3.0, half - 1.0)
    hold_upper = (aft + 3.0, aft + 3.0 + run, -half + 0.6, -half + 2.6)
    s.slab(0.0, aft, -half, half, rise, [lower])
    s.slab(aft, length, -half, half, rise, [hold_lower, *hatches])  # the tween deck, open under every hatch
    s.slab(0.0, length, -half, half, 2 * rise, [upper, hold_upper])
    s.prism(np.array([[length, -half], [length + bow, 0.0], [length, half]]), 2 * rise - 1.0, 2 * rise)
    for (x0, x1, z0, z1), y0, y1 in ((lower, 0.0, rise), (upper, rise, 2 * rise), (hold_lower, 0.0, rise),
                                     (hold_upper, rise, 2 * rise)):
        s.stairs(np.array([x0, (z0 + z1) / 2]), np.array([1.0, 0.0]), 2.0, y0, y1 - y0, riser=riser, tread=tread)
        for z in (z0 - 0.1, z1):  # railed on both sides and at the foot end
            s.box(x0, x1, y1, y1 + 1.0, z, z + 0.1)
        s.box(x0 - 0.1, x0, y1, y1 + 1.0, z0 - 0.1, z1 + 0.1)
    s.wall((aft, -half), (aft, half), 0.0, rise - 0.3, [(half - 0.9, 1.8)], thickness=0.3)  # the bulkhead
    s.wall((aft, -half), (aft, half), rise, 2 * rise - 0.3, [(half - 0.9, 1.8)], thickness=0.3)
    # the main engine and generators, under 2 m: Recast reads the floor inside a solid with head room as floor
    s.box(aft * 0.3, aft * 0.3 + 12.0, 0.0, 1.9, -2.0, 2.0)
    for x in (aft * 0.3 + 2.0, aft * 0.3 + 8.0):
        for z in (-half + 1.5, half - 3.5):
            s.box(x, x + 3.5, 0.0, 1.8, z, z + 2.0)
    for x in np.arange(aft + 2.0, length - 2.0, 5.0):  # the hold's stanchions on both levels, beside the openings
        for z in (-half + 3.6, half - 4.0):
            if not any(a - 0.5 < x < b + 0.5 and c - 0.5 < z < d + 0.5 for a, b, c, d in (hold_lower, hold_upper)):
                s.box(x, x + 0.4, 0.0, 2 * rise - 0.3, z, z + 0.4)
    for level in (0.0, rise):  # cargo in the hold and on the tween deck, clear of its openings
        placed = 0
        while placed < 70:
            x, z = rng.uniform(aft + 8.0, length - 8.0 - run), rng.uniform(-half + 1.0, half - 3.0)
            w, d = rng.uniform(1.5, 6.0), rng.uniform(1.5, 2.4)
            if level and any(x < b + 1.0 and a - 1.0 < x + w and z < d_ + 1.0 and c - 1.0 < z + d for a, b, c, d_ in hatches):
                continue
            s.box(x, x + w, level, level + rng.uniform(1.0, min(2.6, rise - 0.5)), z, z + d)
            placed += 1
    for sign in (-1.0, 1.0):  # deck 2: the corridor's walls with a door into each cabin, partitions, bunks
        doors = [(a + rng.uniform(0.3, b - a - 2.1), rng.uniform(1.6, 1.8)) for a, b in pairwise(cabin_edges)]
        s.wall((0.0, sign * 1.1), (aft, sign * 1.1), rise, 2 * rise - 0.3, doors)
        for x in cabin_edges[1:-1]:
            s.wall((x, sign * 1.1), (x, sign * half), rise, 2 * rise - 0.3)
        for a, b in pairwise(cabin_edges[:-2]):
            s.box(a + 0.3, a + 2.3, rise, rise + 0.6, *sorted((sign * (half - 0.2), sign * (half - 1.1))))
    y = 2 * rise  # the superstructure on the main deck, a mess inside, the boat deck on it
    x0, x1, z0, z1 = 2.0, house, -half + 2.0, half - 2.0
    for a, b in (((x0, z0), (x1, z0)), ((x0, z1), (x1, z1)), ((x0, z0), (x0, z1))):
        s.wall(a, b, y, y + rise - 0.3)
    s.wall((x1, z0), (x1, z1), y, y + rise - 0.3, [(2.6, 1.8), (z1 - z0 - 4.4, 1.8)])
    for x in (x0 + 4.0, x0 + 9.0):
        s.box(x, x + 2.5, y, y + 0.75, -1.5, 1.5)
    s.slab(x0, x1, z0, z1, 3 * rise, [])
    for a, b in (((x0, z0), (x1, z0)), ((x0, z1), (x1, z1)), ((x0, z0), (x0, z1))):
        s.wall(a, b, 3 * rise, 3 * rise + 1.0, thickness=0.1)
    s.wall((x1, z0), (x1, z1), 3 * rise, 3 * rise + 1.0, [(0.2, 2.2), (z1 - z0 - 2.4, 2.2)], thickness=0.1)
    for zc in (z0 + 1.3, z1 - 1.3):  # up from the main deck outside its front, to its front corners
        s.stairs(np.array([x1 + run, zc]), np.array([-1.0, 0.0]), 2.0, y, rise, riser=riser, tread=tread)
    s.box(x0 + 3.0, x0 + 5.5, 3 * rise, 5 * rise, -1.0, 1.0)  # the funnel, through the bridge deck, too narrow to
    # leave the decks inside it a floor
    for zc in (z0 + 1.5, z1 - 3.0):
        s.box(x0 + 8.0, x0 + 14.0, 3 * rise, 3 * rise + 1.5, zc, zc + 1.5)  # lifeboats
    bridge = x1 - 2.5 - run  # the bridge deck and its wings, a stair up from the boat deck
    s.slab(x0, bridge, -half, half, 4 * rise, [])
    s.stairs(np.array([x1 - 2.5, 0.0]), np.array([-1.0, 0.0]), 2.0, 3 * rise, rise, riser=riser, tread=tread)
    s.box(x0 + 6.5, x0 + 8.5, 4 * rise, 4 * rise + 1.0, -3.0, 3.0)  # the console
    for a, b in (((x0, -half), (bridge, -half)), ((x0, half), (bridge, half)), ((x0, -half), (x0, half))):
        s.wall(a, b, 4 * rise, 4 * rise + 1.0, thickness=0.1)
    s.wall((bridge, -half), (bridge, half), 4 * rise, 4 * rise + 1.0, [(half - 1.1, 2.2)], thickness=0.1)
    for x0, x1, z0, z1 in hatches:  # hatch covers with steps up, a crane beside each
        s.box(x0, x1, y, y + 1.2, z0, z1)
        s.stairs(np.array([x0 + 6.0, z0 - 8 * 0.3]), np.array([0.0, 1.0]), 2.0, y, 1.2, riser=0.15, tread=0.3)
        s.box(x1 + 1.5, x1 + 2.5, y, y + 9.0, -0.5, 0.5)
    for x in np.arange(aft + 10.0, length - 2.0, 9.0):
        for z in (-half + 0.6, half - 1.0):
            if rng.random() < 0.6:
                s.box(x, x + 0.4, y, y + 0.6, z, z + 0.4)  # bollards
    return s.mesh()


def village(seed: int) -> trimesh.Trimesh:
    """An open-world village on rolling ground 180 m square (a 2.5 m grid, heights within about 2.4 m of the mean)
    cut by a river 11-13 m wide (no water surface: the ground stops at its banks) that two bridges cross, a cart
    bridge 3.5 m wide and a footbridge 2 m wide, both railed over the water. 26-32 houses (7-11 x 6-8 m, walls
    0.25 m, one door 1.6-1.9 m, a 1.6 m opening in the partition of the larger ones, empty (a first draft's
    table stood in front of some doors), a 50-degree gable roof no one stands on), each on a floor 0.15 m over the highest ground under it, with steps
    up to its door where the ground is lower; 90 trees and three fences of posts.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size, step = 180.0, 2.5
    grid = np.arange(0.0, size + step / 2, step)
    waves = rng.normal(size=(5, 4))
    river_x, bend, phase = rng.uniform(0.4, 0.6) * size, rng.uniform(8.0, 14.0), rng.uniform(0, 2 * math.pi)
    river_half = rng.uniform(5.5, 6.5)

    def height(x: np.ndarray, z: np.ndarray) -> np.ndarray:
        return sum(0.5 * np.sin(x * (0.02 + 0.02 * abs(w[0])) + w[1] * 3) * np.cos(z * (0.02 + 0.02 * abs(w[2])) + w[3] * 3)
                   for w in waves)

    def river(z: np.ndarray) -> np.ndarray:
        """The river's centre line, x at ``z``."""
        return river_x + bend * np.sin(z * 0.04 + phase)

    gx, gz = np.meshgrid(grid, grid, indexing="ij")
    n = len(grid)
    vertices = np.stack([gx.ravel(), height(gx, gz).ravel(), gz.ravel()], axis=1)
    index = np.arange(n * n).reshape(n, n)
    a, b, c, d = index[:-1, :-1].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel(), index[:-1, 1:].ravel()
    faces = np.concatenate([np.stack([a, c, b], 1), np.stack([a, d, c], 1)])
    centre = vertices[faces].mean(axis=1)
    faces = faces[np.abs(centre[:, 0] - river(centre[:, 2])) > river_half]  # no ground in the river
    ground = trimesh.Trimesh(vertices, faces, process=False)
    skirt = ground.copy()
    skirt.vertices[:, 1] -= 0.5
    skirt.invert()
    s.parts += [ground, skirt]
    for z, width in ((rng.uniform(0.2, 0.4) * size, 3.5), (rng.uniform(0.6, 0.8) * size, 2.0)):
        xc = float(river(np.array(z)))
        ends = [np.array([xc - river_half - 4.0, z]), np.array([xc + river_half + 4.0, z])]
        ys = [float(height(np.array(p[0]), np.array(p[1]))) + 0.05 for p in ends]
        s.ramp(ends[0], ends[1], width, ys[0], ys[1], thickness=1.0)
        for sign in (-1.0, 1.0):  # railings over the water, open at the ends
            t0 = 3.0 / (2.0 * (river_half + 4.0))  # 1 m inland of each bank
            t1 = 1.0 - t0
            a_, b_ = ends[0] + t0 * (ends[1] - ends[0]), ends[0] + t1 * (ends[1] - ends[0])
            side = np.array([0.0, sign * (width / 2 - 0.05)])
            s.ramp(a_ + side, b_ + side, 0.1, ys[0] + t0 * (ys[1] - ys[0]) + 1.0, ys[0] + t1 * (ys[1] - ys[0]) + 1.0,
                   thickness=1.0)
    taken: list[tuple[float, float, float, float]] = []
    angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
    ring = np.stack([np.cos(angles), np.sin(angles)], 1)
    houses = int(rng.integers(26, 33))
    while len(taken) < houses:
        w, d = rng.uniform(7.0, 11.0), rng.uniform(6.0, 8.0)
        x0, z0 = rng.uniform(8.0, size - 8.0 - w), rng.uniform(8.0, size - 8.0 - d)
        x1, z1 = x0 + w, z0 + d
        zs = np.linspace(z0, z1, 5)
        if np.any(np.abs(river(zs)[:, None] - np.array([x0, x1])[None]) < river_half + 6.0) or \
                np.any((river(zs) > x0) & (river(zs) < x1)):
            continue
        if any(x0 < b + 5.0 and a < x1 + 5.0 and z0 < d_ + 5.0 and c < z1 + 5.0 for a, b, c, d_ in taken):
            continue
        taken.append((x0, x1, z0, z1))
        px, pz = np.meshgrid(np.linspace(x0 - 1.0, x1 + 1.0, 7), np.linspace(z0 - 1.0, z1 + 1.0, 7))
        under = height(px, pz)
        floor = float(under.max()) + 0.15
        s.box(x0, x1, float(under.min()) - 0.5, floor, z0, z1)
        top = floor + 2.8
        door_side = int(rng.integers(4))
        door_w = rng.uniform(1.6, 1.9)
        walls = [((x0, z0), (x1, z0)), ((x0, z1), (x1, z1)), ((x0, z0), (x0, z1)), ((x1, z0), (x1, z1))]
        for k, (a_, b_) in enumerate(walls):
            span = abs(b_[0] - a_[0]) + abs(b_[1] - a_[1])
            # clear of the partition of a larger house (at the middle of the long walls)
            start = rng.uniform(1.0, (span / 2 if w > 9.0 and k < 2 else span) - 1.0 - door_w)
            s.wall(a_, b_, floor, top, [(start, door_w)] if k == door_side else [], thickness=0.25)
            if k == door_side:  # steps from the ground outside up to the door
                along = 0 if a_[1] == b_[1] else 1
                mid = np.array(a_, dtype=float)
                mid[along] += start + door_w / 2
                outward = np.zeros(2)
                outward[1 - along] = -1.0 if k in (0, 2) else 1.0
                outside = mid + outward * 0.125  # the wall's outer face
                ground_y = float(height(np.array(outside[0]), np.array(outside[1])))
                rise = floor - ground_y
                if rise > 0.3:
                    count = math.ceil(rise / 0.17)
                    s.stairs(outside + outward * count * 0.3, -outward, door_w + 0.4, ground_y, rise, riser=rise / count)
        if w > 9.0:  # a partition with an opening
            xm = (x0 + x1) / 2
            s.wall((xm, z0), (xm, z1), floor, top, [(rng.uniform(1.0, d - 2.6), 1.6)], thickness=0.2)
        ridge = (d / 2 + 0.4) * math.tan(math.radians(50.0))
        s.hull(np.array([[x, top, z] for x in (x0 - 0.4, x1 + 0.4) for z in (z0 - 0.4, z1 + 0.4)]
                        + [[x, top + ridge, (z0 + z1) / 2] for x in (x0 - 0.4, x1 + 0.4)]))
    trees, placed = 90, 0
    while placed < trees:
        x, z = rng.uniform(3.0, size - 3.0, size=2)
        if abs(x - float(river(np.array(z)))) < river_half + 1.5 or \
                any(a - 2.0 < x < b + 2.0 and c - 2.0 < z < d_ + 2.0 for a, b, c, d_ in taken):
            continue
        y = float(height(np.array(x), np.array(z)))
        s.prism(np.array([x, z]) + rng.uniform(0.25, 0.5) * ring, y - 1.0, y + 8.0)
        placed += 1
    for _ in range(3):  # fences: rows of posts 0.9 m apart (a fence, not walked through), 8-20 m long
        x, z = rng.uniform(10.0, size - 30.0, size=2)
        heading = np.array([1.0, 0.0]) if rng.random() < 0.5 else np.array([0.0, 1.0])
        for t in np.arange(0.0, rng.uniform(8.0, 20.0), 0.9):
            p = np.array([x, z]) + t * heading
            if abs(p[0] - float(river(np.array(p[1])))) < river_half + 1.0 or \
                    any(a - 1.0 < p[0] < b + 1.0 and c - 1.0 < p[1] < d_ + 1.0 for a, b, c, d_ in taken):
                continue
            y = float(height(np.array(p[0]), np.array(p[1])))
            s.box(p[0] - 0.08, p[0] + 0.08, y - 0.5, y + 1.1, p[1] - 0.08, p[1] + 0.08)
    return s.mesh()


def market(seed: int) -> trimesh.Trimesh:
    """A town's market square 84-96 x 60-70 m, closed by house fronts 9 m high, five streets 5-7 m wide leading
    out 20-30 m to the map's edge. Rows of stalls 6-7 m apart fill the square (counters 2-3 x 1 m, 0.9 m high,
    0.5-1.5 m apart; half of them under a canvas awning 2.3-2.6 m up on four posts, sloping 20 degrees, whose top
    no one reaches), crates stacked behind the counters and 30 loose about the square; a fountain (an octagonal
    basin 0.7 m high, 3.5 m in radius); a market hall in one corner (pillars on a 4 m grid under a 50-degree
    roof); a stage 1 m high with steps; carts in the streets.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = rng.uniform(84.0, 96.0), rng.uniform(60.0, 70.0)
    angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
    ring = np.stack([np.cos(angles), np.sin(angles)], 1)
    # streets: (side, offset of its near edge along that side, width, length)
    streets = [("south", rng.uniform(8.0, 0.4 * size_x), rng.uniform(5.0, 7.0), rng.uniform(20.0, 30.0)),
               ("south", rng.uniform(0.55 * size_x, size_x - 15.0), rng.uniform(5.0, 7.0), rng.uniform(20.0, 30.0)),
               ("north", rng.uniform(0.3 * size_x, 0.6 * size_x), rng.uniform(5.0, 7.0), rng.uniform(20.0, 30.0)),
               ("west", rng.uniform(8.0, size_z - 15.0), rng.uniform(5.0, 7.0), rng.uniform(20.0, 30.0)),
               ("east", rng.uniform(8.0, size_z - 15.0), rng.uniform(5.0, 7.0), rng.uniform(20.0, 30.0))]
    s.box(0.0, size_x, -0.5, 0.0, 0.0, size_z)
    sides = {"south": ((0.0, 0.0), (size_x, 0.0)), "north": ((0.0, size_z), (size_x, size_z)),
             "west": ((0.0, 0.0), (0.0, size_z)), "east": ((size_x, 0.0), (size_x, size_z))}
    for side, (a, b) in sides.items():
        s.wall(a, b, 0.0, 9.0, [(start, width) for name, start, width, _ in streets if name == side], thickness=1.0)
    for side, start, width, length in streets:  # each street: paving, house fronts both sides, a cart
        if side in ("south", "north"):
            z0, z1 = (-length, 0.0) if side == "south" else (size_z, size_z + length)
            s.box(start, start + width, -0.5, 0.0, z0, z1)
            for x in (start, start + width):
                s.wall((x, z0), (x, z1), 0.0, 9.0, thickness=1.0)
            cz = rng.uniform(z0 + 4.0, z1 - 6.0)
            s.box(start + 0.8, start + 2.4, 0.0, 1.3, cz, cz + 3.0)
        else:
            x0, x1 = (-length, 0.0) if side == "west" else (size_x, size_x + length)
            s.box(x0, x1, -0.5, 0.0, start, start + width)
            for z in (start, start + width):
                s.wall((x0, z), (x1, z), 0.0, 9.0, thickness=1.0)
            cx = rng.uniform(x0 + 4.0, x1 - 6.0)
            s.box(cx, cx + 3.0, 0.0, 1.3, start + 0.8, start + 2.4)
    hall = (size_x - 22.0, size_x - 0.5, size_z - 14.0, size_z - 0.5)  # the market hall in the north-east corner
    for x in np.arange(hall[0] + 1.0, hall[1], 4.0):
        for z in np.arange(hall[2] + 1.0, hall[3], 4.0):
            s.box(x - 0.3, x + 0.3, 0.0, 5.0, z - 0.3, z + 0.3)
    ridge = (hall[3] - hall[2]) / 2 * math.tan(math.radians(50.0))
    s.hull(np.array([[x, 5.0, z] for x in hall[:2] for z in hall[2:]]
                    + [[x, 5.0 + ridge, (hall[2] + hall[3]) / 2] for x in hall[:2]]))
    fountain = np.array([rng.uniform(0.4, 0.5) * size_x, rng.uniform(0.4, 0.6) * size_z])
    s.prism(fountain + 3.5 * ring, -0.5, 0.7)
    s.prism(fountain + 0.5 * ring, 0.0, 3.0)
    stage = (rng.uniform(3.0, 8.0), size_z - 6.5)
    s.box(stage[0], stage[0] + 8.0, -0.5, 1.0, stage[1], stage[1] + 5.0)
    s.stairs(np.array([stage[0] + 4.0, stage[1] - 1.8]), np.array([0.0, 1.0]), 3.0, 0.0, 1.0, riser=1.0 / 6, tread=0.3)
    clear = [(fountain[0] - 6.0, fountain[0] + 6.0, fountain[1] - 6.0, fountain[1] + 6.0),
             (stage[0] - 2.0, stage[0] + 10.0, stage[1] - 4.0, size_z)]

    def free(x0: float, x1: float, z0: float, z1: float) -> bool:
        return not any(x0 < b and a < x1 and z0 < d and c < z1 for a, b, c, d in clear)

    def crates(x: float, z: float) -> None:
        """A stack of one to three crates 0.6-1.2 m, each a little smaller than the one under it."""
        y, size = 0.0, rng.uniform(0.6, 1.2)
        for _ in range(int(rng.integers(1, 4))):
            s.box(x, x + size, y, y + size, z, z + size)
            y, size = y + size, size * 0.8

    for z in np.arange(5.0, size_z - 8.0, rng.uniform(6.0, 7.0)):  # rows of stalls facing -z
        x = 4.0 + rng.uniform(0.0, 2.0)
        while x < size_x - 6.0:
            w = rng.uniform(2.0, 3.0)
            if free(x - 0.5, x + w + 0.5, z - 1.5, z + 2.5) and (x > hall[1] or x + w < hall[0] or z + 2.5 < hall[2]):
                s.box(x, x + w, 0.0, 0.9, z, z + 1.0)
                crates(x + rng.uniform(0.0, w - 1.2), z + 1.4)
                if rng.random() < 0.5:  # the awning: four posts and a sloping canvas
                    for px in (x, x + w - 0.1):
                        for pz in (z - 0.6, z + 1.6):
                            s.box(px, px + 0.1, 0.0, 2.3, pz, pz + 0.1)
                    low = rng.uniform(2.3, 2.6)
                    high = low + 2.4 * math.tan(math.radians(20.0))
                    s.hull(np.array([[px, y + dy, pz] for px in (x - 0.2, x + w + 0.2)
                                     for pz, y in ((z - 0.8, low), (z + 1.8, high)) for dy in (0.0, 0.05)]))
            x += w + rng.uniform(0.5, 1.5)
    placed = 0
    while placed < 30:
        x, z = rng.uniform(2.0, size_x - 3.0), rng.uniform(2.0, size_z - 3.0)
        if free(x - 1.0, x + 2.0, z - 1.0, z + 2.0):
            crates(x, z)
            clear.append((x - 0.5, x + 1.7, z - 0.5, z + 1.7))
            placed += 1
    return s.mesh()


def office(seed: int) -> trimesh.Trimesh:
    """Three open-plan office storeys 3.8 m apart on a 64-72 x 40-46 m plate, round a solid 16 x 8 m core (lifts,
    risers: no floor inside it), joined by straight flights (0.173 / 0.28 m steps, 2 m wide, railed round their
    slots) beside each end of the core, side by side: storey k's flights in lane k. Along one long side a row of
    meeting rooms 5 m deep (0.12 m glass walls to the ceiling, a 1.6 m door each, a table); the rest is clusters of
    cubicles, 3.2 x 3.2 m, two deep, back to back, between partitions 1.2 m high and 0.06 m thick (under the
    agent's 2 m, but not walked over), each entered through a 1.6 m gap in its front and holding a desk 0.7 m deep
    along its back; aisles 1.8-2.4 m between clusters.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, storey, storeys, cube = rng.uniform(64.0, 72.0), rng.uniform(40.0, 46.0), 3.8, 3, 3.2
    xc, zc = size_x / 2, size_z / 2
    core = (xc - 8.0, xc + 8.0, zc - 4.0, zc + 4.0)
    riser, tread = storey / 22, 0.28
    run = 22 * tread
    flight_lanes = [[(core[0] - 3.4 - 2.4 * k, core[0] - 1.4 - 2.4 * k), (core[1] + 1.4 + 2.4 * k, core[1] + 3.4 + 2.4 * k)]
              for k in range(storeys - 1)]  # x extents of storey k's two flights
    slots = [[(x0, x1, zc - run / 2 - 0.4, zc + run / 2) for x0, x1 in lane] for lane in flight_lanes]
    s.slab(0.0, size_x, 0.0, size_z, 0.0, [core])
    for k in range(1, storeys):
        s.slab(0.0, size_x, 0.0, size_z, k * storey, [core, *slots[k - 1]])
    top = storeys * storey - 0.3  # the core's top is a roof no one stands on
    s.hull(np.array([[x, y, z] for x in core[:2] for z in core[2:] for y in (-0.3, top)] + [[x, top + 5.0, zc] for x in core[:2]]))
    for k, lane in enumerate(flight_lanes):
        for x0, x1 in lane:
            s.stairs(np.array([(x0 + x1) / 2, zc - run / 2]), np.array([0.0, 1.0]), x1 - x0, k * storey, storey, riser, tread)
    for k in range(storeys):
        y = k * storey
        for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)),
                     ((0.0, 0.0), (0.0, size_z)), ((size_x, 0.0), (size_x, size_z))):
            s.wall(a, b, y, y + storey - 0.3, thickness=0.3)
        for x0, x1, z0, z1 in slots[k - 1] if k > 0 else []:  # railing round each slot, open where the flight arrives
            for a, b in (((x0, z0), (x1, z0)), ((x0, z0), (x0, z1)), ((x1, z0), (x1, z1))):
                s.wall(a, b, y, y + 1.0, thickness=0.1)
        back = size_z - 5.0  # meeting rooms along the back, a glass wall in front with a door each
        edges = [0.0, *np.cumsum(rng.uniform(4.5, 7.0, size=40))]
        edges = [e for e in edges if e < size_x - 4.0] + [size_x]
        doors = [(a + rng.uniform(0.5, b - a - 2.1), 1.6) for a, b in pairwise(edges)]
        s.wall((0.0, back), (size_x, back), y, y + storey - 0.3, doors, thickness=0.12)
        for x in edges[1:-1]:
            s.wall((x, back), (x, size_z), y, y + storey - 0.3, thickness=0.12)
        for a, b in pairwise(edges):  # a table in each room
            s.box((a + b) / 2 - 1.0, (a + b) / 2 + 1.0, y, y + 0.75, back + 1.8, back + 3.2)
        z = 2.5  # clusters of cubicles: two rows back to back, opening toward the aisles
        while z + 2 * cube < back - 2.0:
            x = 2.5
            while True:
                cubes = int(rng.integers(2, 6))
                x1 = x + cube * cubes
                if x1 > size_x - 2.5:
                    break
                stairs_x = (flight_lanes[-1][0][0] - 1.5, flight_lanes[-1][1][1] + 1.5)
                clear = x1 < stairs_x[0] or x > stairs_x[1] or z + 2 * cube < core[2] - 2.5 or z > core[3] + 2.5
                if clear:
                    s.wall((x, z + cube), (x1, z + cube), y, y + 1.2, thickness=0.06)  # the spine
                    for i in range(cubes + 1):
                        s.wall((x + cube * i, z), (x + cube * i, z + 2 * cube), y, y + 1.2, thickness=0.06)
                    for i in range(cubes):
                        a = x + cube * i
                        gap = rng.uniform(0.2, cube - 1.8)
                        for front, inner in ((z, z + cube), (z + 2 * cube, z + cube)):
                            s.wall((a, front), (a + cube, front), y, y + 1.2, [(gap, 1.6)], thickness=0.06)
                            c0, c1 = sorted((inner, inner - 0.73 if inner > front else inner + 0.73))
                            s.box(a + 0.03, a + cube - 0.03, y, y + 0.75, c0, c1)
                x = x1 + rng.uniform(1.8, 2.4)
            z += 2 * cube + rng.uniform(1.8, 2.4)
    return s.mesh()


def airport(seed: int) -> trimesh.Trimesh:
    """An airport terminal: a check-in hall 50 x 40 m (islands of counters and belts 1 m high), a security line
    (cabinets 0.8 m wide, passages 1.2 m) into an airside concourse 220-250 m long and 18-22 m wide. South of the
    concourse 8-10 gate holdrooms 18-24 m wide, open to it, with rows of seats 0.45 m high, a desk and a jet bridge
    (a corridor 2.6 m wide, 14-18 m long, a dead end) each; north of it shops 10 m deep behind storefronts with a
    4 m opening, under a mezzanine (a lounge 5 m up, 40-50 m long, over the shops and a 4 m strip of the
    concourse, railed, with sofas) reached by a flight at each end (0.179 / 0.28 m steps, 2.4 m wide). Two pairs
    of moving walkways (1.4 m belts 0.15 m up, 40-60 m long, 1 m balustrades both sides, open at the ends) run
    down the concourse's middle.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length, width = rng.uniform(360.0, 390.0), rng.uniform(18.0, 22.0)
    shop_depth, wall_h = 10.0, 8.0
    s.box(-50.0, 0.0, -0.5, 0.0, -10.0, 30.0)  # the check-in hall, x < 0
    s.box(0.0, length, -0.5, 0.0, 0.0, width + shop_depth)  # concourse and the shops' floor
    s.wall((-50.0, -10.0), (-50.0, 30.0), -0.5, wall_h, [(16.0, 8.0)], thickness=0.4)  # the landside doors
    s.wall((-50.0, -10.0), (0.0, -10.0), -0.5, wall_h, thickness=0.4)
    s.wall((-50.0, 30.0), (0.0, 30.0), -0.5, wall_h, thickness=0.4)
    s.wall((0.0, -10.0), (0.0, 0.0), -0.5, wall_h, thickness=0.4)
    s.wall((0.0, width + shop_depth), (0.0, 30.0), -0.5, wall_h, thickness=0.4)
    for z in np.arange(-4.0, 24.0, 7.0):  # check-in islands along x: a belt between two rows of counters
        x0 = rng.uniform(-44.0, -40.0)
        s.box(x0, x0 + 24.0, 0.0, 1.1, z, z + 0.8)
        s.box(x0, x0 + 24.0, 0.0, 0.6, z + 0.8, z + 1.8)
        s.box(x0, x0 + 24.0, 0.0, 1.1, z + 1.8, z + 2.6)
    gate_x = -6.0  # the security line across the hall's end: cabinets 0.8 m wide, passages 1.3 m
    for z in np.arange(-9.4, 29.0, 2.1):
        s.box(gate_x - 1.5, gate_x + 1.5, 0.0, 1.1, z, z + 0.8)
    holdrooms = [0.0]
    while holdrooms[-1] < length - 24.0:
        holdrooms.append(holdrooms[-1] + rng.uniform(18.0, 24.0))
    holdrooms[-1] = length
    depth = 16.0
    s.box(0.0, length, -0.5, 0.0, -depth, 0.0)
    s.wall((0.0, -depth), (length, -depth), -0.5, wall_h, [((a + b) / 2 - 1.3, 2.6) for a, b in pairwise(holdrooms)],
           thickness=0.4)
    for a, b in pairwise(holdrooms):
        s.wall((a, -depth), (a, 0.0), -0.5, wall_h, thickness=0.3)
        jet = rng.uniform(14.0, 18.0)
        xm = (a + b) / 2
        s.box(xm - 1.3, xm + 1.3, -0.5, 0.0, -depth - jet, -depth)
        for x in (xm - 1.5, xm + 1.3):
            s.box(x, x + 0.2, -0.5, 2.6, -depth - jet, -depth)
        s.box(xm - 1.5, xm + 1.5, -0.5, 2.6, -depth - jet - 0.2, -depth - jet)
        s.box(xm - 3.0, xm + 0.5, 0.0, 1.0, -depth + 2.5, -depth + 3.5)  # the gate desk
        for z in np.arange(-depth + 5.5, -2.5, rng.uniform(1.6, 2.0)):  # rows of seats, an aisle down the middle
            s.box(a + 1.5, xm - 1.2, 0.0, 0.45, z, z + 0.6)
            s.box(xm + 1.2, b - 1.5, 0.0, 0.45, z, z + 0.6)
    s.wall((length, -depth), (length, width + shop_depth), -0.5, wall_h, thickness=0.4)
    s.wall((0.0, width + shop_depth), (length, width + shop_depth), -0.5, wall_h, thickness=0.4)
    shops = [0.0]
    while shops[-1] < length - 12.0:
        shops.append(shops[-1] + rng.uniform(9.0, 14.0))
    shops[-1] = length
    s.wall((0.0, width), (length, width), 0.0, 4.0, [(a + rng.uniform(0.5, b - a - 4.5) - 0.0, 4.0) for a, b in pairwise(shops)],
           thickness=0.2)
    for a, b in pairwise(shops):
        s.wall((a, width), (a, width + shop_depth), 0.0, 4.0, thickness=0.2)
        for z in np.arange(width + 2.5, width + shop_depth - 1.5, 2.5):  # shelves
            s.box(a + 2.0, b - 2.0, 0.0, 1.6, z, z + 0.5)
    mx0 = rng.uniform(0.25, 0.45) * length
    mx1 = mx0 + rng.uniform(40.0, 50.0)
    s.box(mx0, mx1, 4.7, 5.0, width - 4.0, width + shop_depth)
    s.wall((mx0, width - 4.0), (mx1, width - 4.0), 5.0, 6.0, [(0.3, 2.6), (mx1 - mx0 - 2.9, 2.6)], thickness=0.1)
    for x in (mx0, mx1):  # railed, open where the flights arrive
        s.wall((x, width - 4.0), (x, width + shop_depth), 5.0, 6.0, thickness=0.1)
    for x in np.arange(mx0 + 5.0, mx1 - 5.0, 4.5):  # sofas
        z = width + rng.uniform(1.0, 8.0)
        s.box(x, x + 2.0, 5.0, 5.8, z, z + 0.9)
    run = 28 * 0.28
    for x in (mx0 + 1.6, mx1 - 1.6):  # up across the concourse to the mezzanine's edge
        s.stairs(np.array([x, width - 4.0 - run]), np.array([0.0, 1.0]), 2.4, 0.0, 5.0, riser=5.0 / 28, tread=0.28)
    x = rng.uniform(15.0, 25.0)
    while x + 40.0 < length - 10.0:  # moving walkways, a pair at a time, clear of the mezzanine's flights
        x1 = min(x + rng.uniform(40.0, 60.0), length - 10.0)
        if x1 < mx0 - 3.0 or x > mx1 + 3.0:
            for zc in (width / 2 - 1.5, width / 2 + 1.5):  # belt and balustrades, a gap between the two
                s.box(x, x1, 0.0, 0.15, zc - 0.7, zc + 0.7)
                for z in (zc - 0.85, zc + 0.7):
                    s.box(x, x1, 0.0, 1.0, z, z + 0.15)
        x = x1 + rng.uniform(12.0, 20.0)
    return s.mesh()


def sewer(seed: int) -> trimesh.Trimesh:
    """A storm sewer: tunnels on a grid (four along x 36-44 m apart, five along z 40-48 m apart), each a channel
    3-4 m wide (no water surface: nothing to walk on) between walkways 2-2.4 m wide, walled 3.5 m high. Where two
    tunnels cross, a chamber whose floor is one grate over the crossing channels; between chambers the walkways
    are joined by footbridges 1.5 m wide every 18-30 m, a fifth of the stretches between chambers lose 8-20 m of
    walkway on one side (the channel against the wall there), pipes 0.5 m high lie along a third of the walkways,
    and the tunnels at the grid's edge run 12-20 m on to dead-end outfalls. Six to eight side rooms 7-9 x 6-8 m
    (pumps, valves: blocks 1-1.5 m high), floors 0.3 m up, open off the tunnels along x through 1.6 m doors with a
    0.15 m sill.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    xs = np.cumsum([20.0, *rng.uniform(40.0, 48.0, size=4)])  # tunnels along z, at these x
    zs = np.cumsum([20.0, *rng.uniform(36.0, 44.0, size=3)])  # tunnels along x, at these z
    channel, walk = rng.uniform(1.5, 2.0), rng.uniform(2.0, 2.4)
    half = channel + walk  # a tunnel's half width, wall to centre line
    ends = (xs[0] - half - rng.uniform(12.0, 20.0), xs[-1] + half + rng.uniform(12.0, 20.0),
            zs[0] - half - rng.uniform(12.0, 20.0), zs[-1] + half + rng.uniform(12.0, 20.0))
    rooms: list[tuple[int, float, float, float, float, float]] = []  # (tunnel, side, x0, width, depth, door)
    count = int(rng.integers(6, 9))
    while len(rooms) < count:  # side rooms off the tunnels along x, between the tunnels along z
        i, j = int(rng.integers(len(zs))), int(rng.integers(len(xs) - 1))
        sign = 1.0 if rng.random() < 0.5 else -1.0
        w, d = rng.uniform(7.0, 9.0), rng.uniform(6.0, 8.0)
        x0 = rng.uniform(xs[j] + half + 3.0, xs[j + 1] - half - 3.0 - w)
        if not any(q == i and t == sign and abs(x0 - p) < w + 4.0 for q, t, p, *_ in rooms):
            rooms.append((i, sign, x0, w, d, rng.uniform(x0 + 1.0, x0 + w - 2.6)))

    def box(along_x: bool, at: float, a0: float, a1: float, y0: float, y1: float, c0: float, c1: float) -> None:
        """A box in a tunnel's frame: ``a`` along it, ``c`` across it from its centre line ``at``."""
        s.box(a0, a1, y0, y1, at + c0, at + c1) if along_x else s.box(at + c0, at + c1, y0, y1, a0, a1)

    for along_x, centres, stops, lo, hi in ((True, zs, xs, ends[0], ends[1]), (False, xs, zs, ends[2], ends[3])):
        cuts = [lo, *sum(([c - half, c + half] for c in stops), []), hi]
        for k, at in enumerate(centres):
            for a0, a1 in zip(cuts[0::2], cuts[1::2]):
                for sign in (-1.0, 1.0):
                    c0, c1 = sorted((sign * channel, sign * half))
                    doors = [(door - a0, 1.6) for i, side, _, _, _, door in rooms
                             if along_x and i == k and side == sign and a0 < door < a1]
                    missing = (a0, a0)
                    if rng.random() < 0.2 and a1 - a0 > 20.0 and not doors:  # a stretch with the channel against the wall
                        start = rng.uniform(a0 + 4.0, a1 - 14.0)
                        missing = (start, start + rng.uniform(8.0, min(20.0, a1 - start - 4.0)))
                    for b0, b1 in ((a0, missing[0]), (missing[1], a1)):
                        if b1 - b0 > 1e-6:
                            box(along_x, at, b0, b1, -0.6, 0.0, c0, c1)
                            if rng.random() < 0.33 and b1 - b0 > 4.0 and not doors:  # a pipe along the wall
                                box(along_x, at, b0 + 1.0, b1 - 1.0, 0.0, 0.5, *sorted((sign * (half - 0.6), sign * half)))
                    line = at + sign * (half + 0.15)
                    s.wall((a0, line) if along_x else (line, a0), (a1, line) if along_x else (line, a1), -0.6, 3.5,
                           doors, thickness=0.3)
                a = a0 + rng.uniform(8.0, 14.0)
                while a < a1 - 6.0:  # footbridges
                    box(along_x, at, a, a + 1.5, -0.3, 0.0, -channel, channel)
                    a += rng.uniform(18.0, 30.0)
            for c in stops:  # the chamber: a grate over the whole crossing
                box(along_x, at, c - half, c + half, -0.3, 0.0, -half, half)
            for a in (lo - 0.3, hi):  # the outfall's end wall
                box(along_x, at, a, a + 0.3, -0.6, 3.5, -half, half)
    for i, sign, x0, w, d, door in rooms:
        face = zs[i] + sign * (half + 0.3)  # the tunnel wall's outer face
        far = face + sign * d
        z0, z1 = sorted((face, far))
        s.box(x0, x0 + w, -0.6, 0.3, z0, z1)
        s.box(door, door + 1.6, -0.6, 0.15, *sorted((face - sign * 0.3, face)))  # the sill in the door
        for a, b in (((x0, far), (x0 + w, far)), ((x0, z0), (x0, z1)), ((x0 + w, z0), (x0 + w, z1))):
            s.wall(a, b, 0.3, 3.5, thickness=0.3)
        for _ in range(int(rng.integers(2, 5))):
            px, pz = rng.uniform(x0 + 1.0, x0 + w - 2.5), rng.uniform(z0 + 1.5, z1 - 2.0)
            s.box(px, px + 1.5, 0.3, 0.3 + rng.uniform(1.0, 1.5), pz, pz + 1.0)
    return s.mesh()



def lanes(seed: int) -> trimesh.Trimesh:
    """A three-lane multiplayer arena 220 x 124 m, symmetric under a half turn about its centre as competitive maps
    are: a base at each end (a platform 1.2 m up, reached by a ramp 8 m wide and two flights of 0.15 / 0.30 m
    steps), three lanes 9-11 m wide between them (top, middle, bottom), and between the lanes two jungles of solid
    blocks 4-7 m high (ridged roofs at 50 degrees, which no one stands on) with alleys 3.5-6 m wide. Along each side lane a catwalk 3 m up (3.5 m wide, the lane
    passing under it, ramps at 12 degrees at both ends) whose edge is a jump-down ledge all along; a bridge 3 m
    up across the middle lane at the map's centre between two blocks 3 m high, each with a ramp; cover walls
    1 m high and crates 1.2 m high in the lanes.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = 220.0, 124.0
    footprints: list[tuple[float, float, float, float]] = []  # of solids on the ground: the ground stops under them

    def turned(x: float, z: float) -> tuple[float, float]:
        return size_x - x, size_z - z

    def block(x0: float, x1: float, top: float, z0: float, z1: float, roof: bool = False) -> None:
        """A solid block on the ground and its copy turned half round the map's centre; with ``roof``, a ridge
        along x over ``top``, its sides at 50 degrees (a top no one stands on)."""
        for (a, c), (b, d) in (((x0, z0), (x1, z1)), (turned(x1, z1), turned(x0, z0))):
            corners = [[x, y, z] for x in (a, b) for z in (c, d) for y in (-0.5, top)]
            ridge = top + (d - c) / 2 * math.tan(math.radians(50.0))
            s.hull(np.array(corners + ([[x, ridge, (c + d) / 2] for x in (a, b)] if roof else [])))
            if top > 2.0:
                footprints.append((a, b, c, d))

    def ramp(a: tuple[float, float], b: tuple[float, float], width: float, ya: float, yb: float) -> None:
        for p, q in ((a, b), (turned(*a), turned(*b))):
            s.ramp(np.array(p), np.array(q), width, ya, yb)

    lane = rng.uniform(9.0, 11.0, size=2)
    bottom, middle = (4.0, 4.0 + lane[0]), (size_z / 2 - lane[1] / 2, size_z / 2 + lane[1] / 2)
    base, rise = 18.0, 3.0
    run = rise / math.tan(math.radians(12.0))
    block(2.0, base, 1.2, 2.0, size_z - 2.0)  # a base's platform
    ramp((base + 8.0, size_z / 2), (base, size_z / 2), 8.0, 0.0, 1.2)
    for z in (bottom[0] + 2.0, size_z - bottom[0] - 4.5):
        for start, heading in (((base + 8 * 0.30, z + 1.25), (-1.0, 0.0)), ((size_x - base - 8 * 0.30, size_z - z - 1.25), (1.0, 0.0))):
            s.stairs(np.array(start), np.array(heading), 2.5, 0.0, 1.2)
    pad = (size_x / 2 - 3.0, size_x / 2 + 3.0, middle[0] - 6.0, middle[0])  # the bridge's block on this side
    keep_out = (pad[0] - run - 2.0, pad[1] + 1.0, pad[2] - 2.0, pad[3])
    x = base + rng.uniform(8.0, 12.0)
    while x < size_x - base - 12.0:  # the jungle between the bottom and the middle lane
        x1 = min(x + rng.uniform(6.0, 14.0), size_x - base - 8.0)
        z = bottom[1] + rng.uniform(3.5, 6.0)
        while z < middle[0] - 7.0:
            z1 = min(z + rng.uniform(5.0, 12.0), middle[0] - rng.uniform(3.5, 6.0))
            clear = x1 < keep_out[0] or x > keep_out[1] or z1 < keep_out[2] or z > keep_out[3]
            if z1 - z > 3.0 and x1 - x > 3.0 and clear:
                block(x, x1, rng.uniform(4.0, 7.0), z, z1, roof=True)
            z = z1 + rng.uniform(3.5, 6.0)
        x = x1 + rng.uniform(3.5, 6.0)
    block(pad[0], pad[1], rise, pad[2], pad[3])
    ramp((pad[0] - run, (pad[2] + pad[3]) / 2), (pad[0], (pad[2] + pad[3]) / 2), 3.0, 0.0, rise)
    s.box(size_x / 2 - 1.5, size_x / 2 + 1.5, rise - 0.4, rise, middle[0], middle[1])  # the bridge
    c0, c1 = rng.uniform(0.3, 0.4) * size_x, rng.uniform(0.55, 0.65) * size_x
    zc = bottom[1] - 1.75  # the catwalk along the bottom lane's far side
    for (a, c), (b, d) in (((c0, zc - 1.75), (c1, zc + 1.75)), (turned(c1, zc + 1.75), turned(c0, zc - 1.75))):
        s.box(a, b, rise - 0.4, rise, c, d)
    ramp((c0 - run, zc), (c0, zc), 3.5, 0.0, rise)
    ramp((c1 + run, zc), (c1, zc), 3.5, 0.0, rise)
    for lo, hi in (bottom, middle):  # cover in the lanes, clear of the catwalk's ramps
        for _ in range(18):
            x, z = rng.uniform(base + 10.0, size_x - base - 10.0), rng.uniform(lo + 1.5, hi - 2.5)
            if lo == bottom[0] and (abs(x - c0 + run / 2) < run / 2 + 2.0 or abs(x - c1 - run / 2) < run / 2 + 2.0):
                continue
            if rng.random() < 0.5:
                block(x, x + rng.uniform(2.0, 4.0), 1.0, z, z + 0.4)
            else:
                block(x, x + 1.2, 1.2, z, z + 1.2)
    s.ground(0.0, size_x, 0.0, size_z, 0.0, footprints)
    for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)),
                 ((0.0, 0.0), (0.0, size_z)), ((size_x, 0.0), (size_x, size_z))):
        s.wall(a, b, -0.5, 6.0, thickness=0.5)
    return s.mesh()


def prison(seed: int) -> trimesh.Trimesh:
    """A prison: three cell blocks side by side, each a hall 9-11 m wide between two rows of 14-18 cells on two
    tiers 3.2 m apart; the upper cells open on galleries 1.8 m wide, railed over the open well, with bridges 2 m
    wide across it every 4-6 cells and a flight (0.16 / 0.28 m steps, 1.6 m wide) in the well up to each gallery
    at alternate ends. A cell is 3.2-3.5 x 3.6 m behind a wall with a 1.6 m door (a real one is narrower, but the
    agent is 1 m wide and a first draft's 1.3 m doors closed most cells), with a bunk 0.5 m high and a basin. A
    corridor 4 m wide joins the halls at one end to a hub round a guard post (4 x 4 m, solid, a pyramid roof) and
    on to a mess hall 24 x 16 m of tables and benches and, through a 2 m gate, a walled yard 40 x 30 m with a few
    benches and a hoop's post.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    storey, depth = 3.2, 3.6
    riser, tread = storey / 20, 0.28
    blocks_z = [0.0]
    for b in range(3):
        cells, cell_w, hall = int(rng.integers(14, 19)), rng.uniform(3.2, 3.5), rng.uniform(9.0, 11.0)
        z0 = blocks_z[-1]
        length = cells * cell_w
        width = 2 * depth + hall
        s.box(0.0, length, -0.3, 0.0, z0, z0 + width)
        well = (z0 + depth + 1.8, z0 + depth + hall - 1.8)  # open between the galleries
        bridges = [(i * cell_w, i * cell_w + 2.0) for i in range(4, cells - 3, int(rng.integers(4, 7)))]
        flights = [(1.0, well[0], 1.0), (length - 1.0, well[1] - 1.6, -1.0)]  # foot x, z of the flight's edge, heading
        holes = [(0.0, length, well[0], well[1])]
        s.slab(0.0, length, z0 + depth, z0 + depth + hall, storey, holes)
        for a, b_ in bridges:
            s.box(a, b_, storey - 0.3, storey, *well)
        for x, zf, heading in flights:
            s.stairs(np.array([x, zf + 0.8]), np.array([heading, 0.0]), 1.6, 0.0, storey, riser, tread)
            top = x + heading * 20 * tread
            s.box(*sorted((top, top + heading * 1.6)), storey - 0.3, storey, zf, zf + 1.6)  # landing at the gallery
        for edge in well:  # railings, open at the bridges and the landings
            gaps = [(a, b_ - a) for a, b_ in bridges]
            for x, zf, heading in flights:
                top = x + heading * 20 * tread
                if abs(zf - edge) < 1.7 or abs(zf + 1.6 - edge) < 1.7:
                    lo = min(top, top + heading * 1.6)
                    gaps.append((lo, 1.6))
            s.wall((0.0, edge), (length, edge), storey, storey + 1.0, sorted(gaps), thickness=0.1)
        for y in (0.0, storey):
            for side in range(2):
                back, front = (z0, z0 + depth) if side == 0 else (z0 + width, z0 + width - depth)
                out = 1.0 if side == 0 else -1.0
                if y > 0.0:
                    s.box(0.0, length, y - 0.3, y, *sorted((back, front)))  # the upper cells' floor
                s.wall((0.0, back), (length, back), y, y + storey - 0.3, thickness=0.3)
                doors = [(i * cell_w + rng.uniform(0.3, cell_w - 1.9), 1.6) for i in range(cells)]
                s.wall((0.0, front), (length, front), y, y + storey - 0.3, doors, thickness=0.2)
                for i in range(cells + 1):
                    s.wall((i * cell_w, back), (i * cell_w, front), y, y + storey - 0.3, thickness=0.2)
                for i, (door, _) in enumerate(doors):
                    bunk_x = i * cell_w + 0.1 if door - i * cell_w > 0.9 else (i + 1) * cell_w - 0.9
                    s.box(bunk_x, bunk_x + 0.8, y, y + 0.5, *sorted((back + out * 0.15, back + out * 2.15)))
                    basin_x = (i + 1) * cell_w - 0.6 if bunk_x < i * cell_w + 1.0 else i * cell_w + 0.1
                    s.box(basin_x, basin_x + 0.5, y, y + 0.9, *sorted((back + out * 0.15, back + out * 0.65)))
        s.wall((length, z0 + depth), (length, z0 + width - depth), 0.0, 2 * storey, thickness=0.3)
        blocks_z.append(z0 + width + 0.3)
    total = blocks_z[-1]
    s.wall((0.0, 0.0), (0.0, total), 0.0, 2 * storey,  # the halls' west ends open on the corridor
           [(blocks_z[b] + depth + 0.5, blocks_z[b + 1] - blocks_z[b] - 2 * depth - 1.3) for b in range(3)], thickness=0.3)
    s.box(-4.0, 0.0, -0.3, 0.0, 0.0, total)  # the corridor along the blocks' ends
    s.wall((-4.0, 0.0), (-4.0, total), 0.0, storey, [(total / 2 - 2.0, 4.0)], thickness=0.3)
    s.wall((-4.0, 0.0), (0.0, 0.0), 0.0, storey, thickness=0.3)
    s.wall((-4.0, total), (0.0, total), 0.0, storey, thickness=0.3)
    hub = (-16.0, -4.0, total / 2 - 6.0, total / 2 + 6.0)  # the hub round a solid guard post
    s.slab(hub[0], hub[1], hub[2], hub[3], 0.0, [(-12.0, -8.0, total / 2 - 2.0, total / 2 + 2.0)])
    s.hull(np.array([[x, y, z] for x in (-12.0, -8.0) for z in (total / 2 - 2.0, total / 2 + 2.0) for y in (-0.3, storey)]
                    + [[-10.0, storey + 2.5, total / 2]]))
    s.wall((hub[0], hub[2]), (hub[1], hub[2]), 0.0, storey, thickness=0.3)
    s.wall((hub[0], hub[3]), (hub[1], hub[3]), 0.0, storey, thickness=0.3)
    mess = (-40.0, -16.0, total / 2 - 8.0, total / 2 + 8.0)
    s.box(mess[0], mess[1], -0.3, 0.0, mess[2], mess[3])
    s.wall((mess[1], mess[2]), (mess[1], mess[3]), 0.0, storey, [(4.0, 4.0)], thickness=0.3)
    s.wall((mess[0], mess[2]), (mess[1], mess[2]), 0.0, storey, thickness=0.3)
    s.wall((mess[0], mess[2]), (mess[0], mess[3]), 0.0, storey, thickness=0.3)
    gate = rng.uniform(4.0, 18.0)
    s.wall((mess[0], mess[3]), (mess[1], mess[3]), 0.0, storey, [(gate, 2.0)], thickness=0.3)
    for x in np.arange(mess[0] + 2.0, mess[1] - 3.0, 4.0):  # tables with a bench either side
        for z in np.arange(mess[2] + 2.0, mess[3] - 2.0, 3.2):
            s.box(x, x + 2.4, 0.0, 0.75, z + 0.5, z + 1.3)
            for bz in (z, z + 1.5):
                s.box(x, x + 2.4, 0.0, 0.45, bz, bz + 0.3)
    yard = (mess[1] - 40.0, mess[1], mess[3] + 0.15, mess[3] + 30.0)
    s.box(yard[0], yard[1], -0.3, 0.0, yard[2], yard[3])
    for a, b in (((yard[0], yard[3]), (yard[1], yard[3])), ((yard[0], yard[2]), (yard[0], yard[3])), ((yard[0], mess[3]), (mess[0], mess[3])),
                 ((yard[1], yard[2]), (yard[1], yard[3]))):
        s.wall(a, b, 0.0, 5.0, thickness=0.2)
    for _ in range(int(rng.integers(4, 8))):
        x, z = rng.uniform(yard[0] + 2.0, yard[1] - 4.0), rng.uniform(yard[2] + 3.0, yard[3] - 2.0)
        s.box(x, x + 2.0, 0.0, 0.45, z, z + 0.5)
    s.box(yard[1] - 6.0, yard[1] - 5.7, 0.0, 3.5, (yard[2] + yard[3]) / 2, (yard[2] + yard[3]) / 2 + 0.3)
    return s.mesh()


def museum(seed: int) -> trimesh.Trimesh:
    """A museum of two storeys 5.5 m apart: a grid of 6 x 5 galleries 12-16 m wide and 10-14 m deep (the front
    row 15-16 m deep) behind 0.4 m walls, every wall between two galleries pierced by a 2.4 m door on the line
    through their centres, so the doors stand in line (an enfilade) along both axes on both storeys. One front
    gallery is the entrance hall, open to the roof: a 3 m door from a forecourt, a flight up along its back
    (0.172 / 0.30 m steps, 3 m wide) to a landing 3 m deep across the hall upstairs, railed, with doors to the
    galleries behind and beside it. In the galleries, off the door lines: plinths 1 x 1 m (1.2 m high) for
    statues, display cases 2 x 0.8 m (1 m high) along the walls, a bench, and in some a free-standing screen
    4 m long and 3 m high.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    storey, door = 5.5, 2.4
    xs = np.cumsum([0.0, *rng.uniform(12.0, 16.0, size=6)])
    zs = np.cumsum([0.0, rng.uniform(15.0, 16.0), *rng.uniform(10.0, 14.0, size=4)])
    hall = int(rng.integers(2, 4))  # the entrance hall's column, in the front row
    hx0, hx1, hz0, hz1 = xs[hall], xs[hall + 1], zs[0], zs[1]
    landing = hz1 - 3.0
    s.box(xs[0] - 0.2, xs[-1] + 0.2, -0.3, 0.0, zs[0] - 0.2, zs[-1] + 0.2)
    s.box(hx0 - 6.0, hx1 + 6.0, -0.3, 0.0, zs[0] - 12.0, zs[0] - 0.2)  # the forecourt
    s.slab(xs[0] - 0.2, xs[-1] + 0.2, zs[0] - 0.2, zs[-1] + 0.2, storey, [(hx0 + 0.2, hx1 - 0.2, hz0 + 0.2, landing)])
    stair_x = (hx0 + hx1) / 2 + 3.5
    run = 32 * 0.30
    s.stairs(np.array([stair_x, landing - run]), np.array([0.0, 1.0]), 3.0, 0.0, storey, riser=storey / 32, tread=0.30)
    s.wall((hx0 + 0.2, landing), (hx1 - 0.2, landing), storey, storey + 1.0, [(stair_x - 1.5 - hx0 - 0.2, 3.0)],
           thickness=0.1)
    for y in (0.0, storey):
        top = y + storey - 0.3
        for i, x in enumerate(xs):  # walls along z, one door per gallery they part, on its centre line
            inner = 0 < i < len(xs) - 1
            doors = []
            for j in range(len(zs) - 1):
                centre = (zs[j] + zs[j + 1]) / 2
                beside_void = y > 0 and j == 0 and i in (hall, hall + 1)
                if beside_void:  # upstairs, the hall's side walls open on its landing only
                    doors.append((hz1 - 2.7 - zs[0] + 0.2, door))
                elif inner:
                    doors.append((centre - door / 2 - zs[0] + 0.2, door))
            s.wall((x, zs[0] - 0.2), (x, zs[-1] + 0.2), y, top, doors, thickness=0.4)
        for j, z in enumerate(zs):  # walls along x
            doors = []
            for i in range(len(xs) - 1):
                centre = (xs[i] + xs[i + 1]) / 2
                if 0 < j < len(zs) - 1:  # upstairs too where the hall's landing meets its back wall
                    doors.append((centre - door / 2 - xs[0] + 0.2, door))
                elif j == 0 and y == 0 and i == hall:
                    doors.append((centre - 1.5 - xs[0] + 0.2, 3.0))
            s.wall((xs[0] - 0.2, z), (xs[-1] + 0.2, z), y, top, doors, thickness=0.4)
        for i in range(len(xs) - 1):
            for j in range(len(zs) - 1):
                if i == hall and j == 0:
                    continue
                x0, x1, z0, z1 = xs[i] + 0.2, xs[i + 1] - 0.2, zs[j] + 0.2, zs[j + 1] - 0.2
                xc, zc = (x0 + x1) / 2, (z0 + z1) / 2

                def clear(a0: float, a1: float, c0: float, c1: float) -> bool:
                    """Off both door lines (1.8 m either side of the centre lines)."""
                    return (a1 < xc - 1.8 or a0 > xc + 1.8) and (c1 < zc - 1.8 or c0 > zc + 1.8)

                for _ in range(int(rng.integers(4, 9))):  # cases along a wall
                    along_x = rng.random() < 0.5
                    if along_x:
                        a = rng.uniform(x0 + 0.5, x1 - 2.5)
                        c = z0 + 0.3 if rng.random() < 0.5 else z1 - 1.1
                        box = (a, a + 2.0, c, c + 0.8)
                    else:
                        c = rng.uniform(z0 + 0.5, z1 - 2.5)
                        a = x0 + 0.3 if rng.random() < 0.5 else x1 - 1.1
                        box = (a, a + 0.8, c, c + 2.0)
                    if clear(*box):
                        s.box(box[0], box[1], y, y + 1.0, box[2], box[3])
                for _ in range(int(rng.integers(2, 6))):  # plinths
                    a, c = rng.uniform(x0 + 2.0, x1 - 3.0), rng.uniform(z0 + 2.0, z1 - 3.0)
                    if clear(a, a + 1.0, c, c + 1.0):
                        s.box(a, a + 1.0, y, y + 1.2, c, c + 1.0)
                a = xc + rng.choice([-1.0, 1.0]) * rng.uniform(2.5, 3.5)
                if clear(a - 0.9, a + 0.9, zc + 2.0, zc + 2.5):
                    s.box(a - 0.9, a + 0.9, y, y + 0.45, zc + 2.0, zc + 2.5)  # a bench
                if rng.random() < 0.4 and x1 - x0 > 13.0:  # a screen, parallel to the front
                    a, c = xc + rng.choice([-1.0, 1.0]) * 3.5, zc + rng.choice([-1.0, 1.0]) * rng.uniform(2.5, 3.5)
                    s.box(a - 1.5, a + 1.5, y, y + 3.0, c - 0.1, c + 0.1)
    return s.mesh()


def _strip(a: np.ndarray, b: np.ndarray, width: float) -> np.ndarray:
    """The plan (4, 2) of a strip ``width`` m wide along the segment from plan point ``a`` (x, z) to ``b``."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    along = (b - a) / np.linalg.norm(b - a)
    side = np.array([-along[1], along[0]]) * width / 2
    return np.array([a - side, b - side, b + side, a + side])


def _switchback(s: _Solids, x0: float, z0: float, y: float, storey: float) -> None:
    """Storey ``y``'s switchback in a well 4 m wide (x0 to x0 + 4) from z0 along +z: a landing 2 m deep at the
    well's z0 end on every storey, a flight up along +z in the lane x0 to x0 + 2, a landing across the far end
    half a storey up, a flight back along -z in the other lane to the next storey's landing. Steps are 0.28 m treads,
    risers of at most 0.18 m, each a block 0.45 m deep, so the flights of the storey below keep their head room.
    The well is :func:`_well_length` long; storeys above ``y`` leave it open beyond the landing."""
    steps = math.ceil(storey / 2 / 0.18)
    riser, run = storey / 2 / steps, steps * 0.28
    s.stairs(np.array([x0 + 1.0, z0 + 2.0]), np.array([0.0, 1.0]), 2.0, y, storey / 2, riser, 0.28, depth=0.45)
    s.box(x0, x0 + 4.0, y + storey / 2 - 0.45, y + storey / 2, z0 + 2.0 + run, z0 + 4.0 + run)
    s.stairs(np.array([x0 + 3.0, z0 + 2.0 + run]), np.array([0.0, -1.0]), 2.0, y + storey / 2, storey / 2, riser, 0.28,
             depth=0.45)


def _well_length(storey: float) -> float:
    """The length (m) of :func:`_switchback`'s well for a storey ``storey`` m high."""
    return 4.0 + 0.28 * math.ceil(storey / 2 / 0.18)


def tower(seed: int) -> trimesh.Trimesh:
    """An office tower's floors: seven storeys 3.5 m apart on a 42-48 x 28-32 m plate round a solid core (lifts and
    risers, no floor, a roof at 50 degrees) joined by two switchback stairwells only, one at each end of the core
    (wells 4 m wide, walled, a 1.6 m door a storey toward the corridor, 0.28 m treads, risers under 0.18 m). A
    corridor 2.4 m wide rings the core and wells; offices 3.5-6.5 m wide line the outer walls (a 1.6 m door on
    the corridor each, a desk and a cabinet; a neighbour joined through a 1.6 m door in a third of the partitions;
    the corner rooms only through their neighbours), and on each storey one stretch of 2-4 offices on a long side is
    an open room.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, storey, storeys = rng.uniform(42.0, 48.0), rng.uniform(28.0, 32.0), 3.5, 7
    xc, zc = size_x / 2, size_z / 2
    well = _well_length(storey)
    core = (xc - 6.0, xc + 6.0, zc - well / 2, zc + well / 2)
    wells = [core[0] - 4.4, core[1] + 0.4]  # x0 of each well, z from core[2]
    block = (wells[0] - 0.2, wells[1] + 4.2, core[2], core[3])
    ring = (block[0] - 2.4, block[1] + 2.4, block[2] - 2.4, block[3] + 2.4)  # the corridor's outer edge
    holes = [(x0, x0 + 4.0, core[2] + 2.0, core[3]) for x0 in wells]
    top = storeys * storey - 0.3
    s.hull(np.array([[x, y, z] for x in core[:2] for z in core[2:] for y in (-0.3, top)] + [[x, top + 4.0, zc] for x in core[:2]]))
    for k in range(storeys):
        y = k * storey
        s.slab(0.0, size_x, 0.0, size_z, y, [core] + (holes if k else []))
        ceiling = y + storey - 0.3
        for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)),
                     ((0.0, 0.0), (0.0, size_z)), ((size_x, 0.0), (size_x, size_z))):
            s.wall(a, b, y, ceiling, thickness=0.3)
        for x0 in wells:  # the well's walls, its door toward the corridor at the landing's end
            s.wall((x0, core[2]), (x0 + 4.0, core[2]), y, ceiling, [(1.2, 1.6)])
            s.wall((x0, core[3]), (x0 + 4.0, core[3]), y, ceiling)
            for x in (x0, x0 + 4.0):
                s.wall((x, core[2]), (x, core[3]), y, ceiling)
            if k < storeys - 1:
                _switchback(s, x0, core[2], y, storey)
            else:  # a rail across the open flight at the top
                s.box(x0, x0 + 2.0, y, y + 1.0, core[2] + 1.9, core[2] + 2.0)
        # offices: a row along each long wall between the corridor's ends, a row along each short wall, corner rooms
        open_row, open_at, open_n = int(rng.integers(0, 2)), int(rng.integers(1, 4)), int(rng.integers(2, 5))
        for r, (out_z, wall_z) in enumerate(((0.0, ring[2]), (size_z, ring[3]))):
            cuts = [ring[0]]
            while cuts[-1] < ring[1] - 7.0:
                cuts.append(cuts[-1] + rng.uniform(3.5, 6.5))
            cuts = [*cuts[:-1], ring[1]] if len(cuts) > 1 else [ring[0], ring[1]]
            doors = [(a - ring[0] + rng.uniform(0.4, b - a - 2.0), 1.6) for a, b in pairwise(cuts)]
            s.wall((ring[0], wall_z), (ring[1], wall_z), y, ceiling, doors, thickness=0.15)
            z0, z1 = sorted((out_z, wall_z))
            for i, x in enumerate(cuts):
                if r == open_row and open_at <= i < open_at + open_n - 1:
                    continue
                passage = [(rng.uniform(0.3, z1 - z0 - 2.0), 1.6)] if rng.random() < 0.33 else []
                s.wall((x, z0), (x, z1), y, ceiling, passage, thickness=0.12)
            for a, b in pairwise(cuts):  # a desk by the window, a cabinet against a partition
                xm, z = (a + b) / 2, (z0 + 1.2 if out_z == 0.0 else z1 - 1.9)
                s.box(xm - 0.8, xm + 0.8, y, y + 0.75, z, z + 0.7)
                zc_ = rng.uniform(z0 + 2.5, z1 - 2.5)
                s.box(a + 0.1, a + 0.6, y, y + 1.8, zc_ - 0.5, zc_ + 0.5)
        for out_x, wall_x in ((0.0, ring[0]), (size_x, ring[1])):
            x0, x1 = sorted((out_x, wall_x))
            cuts = [ring[2]]
            while cuts[-1] < ring[3] - 6.0:
                cuts.append(cuts[-1] + rng.uniform(3.5, 5.5))
            cuts = [*cuts[:-1], ring[3]]
            doors = [(a - ring[2] + rng.uniform(0.4, b - a - 2.0), 1.6) for a, b in pairwise(cuts)]
            s.wall((wall_x, ring[2]), (wall_x, ring[3]), y, ceiling, doors, thickness=0.15)
            for i, z in enumerate(cuts):  # the end cuts part a corner room off, joined through a door
                passage = [(rng.uniform(0.3, x1 - x0 - 2.0), 1.6)] if i in (0, len(cuts) - 1) or rng.random() < 0.33 else []
                s.wall((x0, z), (x1, z), y, ceiling, passage, thickness=0.12)
            for a, b in [(0.0, ring[2]), *pairwise(cuts), (ring[3], size_z)]:
                zm, x = (a + b) / 2, (x0 + 1.2 if out_x == 0.0 else x1 - 1.9)
                s.box(x, x + 0.7, y, y + 0.75, zm - 0.8, zm + 0.8)
    return s.mesh()


def hospital(seed: int) -> trimesh.Trimesh:
    """A hospital ward block of three storeys 4 m apart on a 96-108 x 30 m plate: two corridors 2.6 m wide along x
    (a racetrack, joined by cross corridors at both ends and in the middle), patient rooms 3.8-4.6 m wide and 6 m
    deep along both outer walls (a 1.6 m door each, one or two beds 1 x 2.1 m, a chair), and between the corridors
    a core 12 m deep of small rooms (stores, sluices, offices, 3-5 m wide, a 1.6 m door on either corridor), a
    nurses' station (a counter open to the corridor), a switchback stairwell (4 m wide, :func:`_switchback`) and two
    lifts: walled shafts 2.6 m square with no door and no floor above the ground, which no one walks through,
    beside a solid machine room (no floor inside, a roof at 50 degrees).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, storey, storeys, room, corridor, core = rng.uniform(96.0, 108.0), 4.0, 3, 6.0, 2.6, 12.0
    size_z = 2 * (room + corridor) + core
    c0, c1 = room + corridor, room + corridor + core  # the core's z extent
    cross = [rng.uniform(6.0, 10.0), size_x / 2 + rng.uniform(-8.0, 8.0), size_x - rng.uniform(8.0, 12.0)]
    well_x, well_z = cross[1] + 5.0, c0 + 0.3
    lifts = [(cross[1] - 6.0, cross[1] - 3.4), (cross[1] - 3.0, cross[1] - 0.4)]
    holes = [(well_x, well_x + 4.0, well_z + 2.0, well_z + _well_length(storey))] + [(a, b, c1 - 2.6, c1) for a, b in lifts]
    machine = (lifts[0][0] - 0.1, lifts[1][1] + 0.1, c0, c1 - 2.7)  # between the lifts and a corridor, solid
    holes.append(machine)
    top = storeys * storey - 0.3
    s.hull(np.array([[x, y, z] for x in machine[:2] for z in machine[2:] for y in (-0.3, top)]
                    + [[(machine[0] + machine[1]) / 2, top + (machine[1] - machine[0]) / 2 * math.tan(math.radians(50.0)), z]
                       for z in machine[2:]]))  # a roof ridged along z at 50 degrees
    for k in range(storeys):
        y = k * storey
        ceiling = y + storey - 0.3
        s.slab(0.0, size_x, 0.0, size_z, y, holes if k else [machine])
        for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)),
                     ((0.0, 0.0), (0.0, size_z)), ((size_x, 0.0), (size_x, size_z))):
            s.wall(a, b, y, ceiling, thickness=0.3)
        for side, (out_z, wall_z) in enumerate(((0.0, room), (size_z, size_z - room))):  # patient rooms
            cuts = [0.0]
            while cuts[-1] < size_x - 5.0:
                cuts.append(cuts[-1] + rng.uniform(3.8, 4.6))
            cuts[-1] = size_x
            s.wall((0.0, wall_z), (size_x, wall_z), y, ceiling, [(a + rng.uniform(0.2, b - a - 1.9), 1.6) for a, b in pairwise(cuts)],
                   thickness=0.15)
            z0, z1 = sorted((out_z, wall_z))
            for x in cuts[1:-1]:
                s.wall((x, z0), (x, z1), y, ceiling, thickness=0.12)
            for a, b in pairwise(cuts):
                beds = [a + 0.3] if rng.random() < 0.5 or b - a < 4.2 else [a + 0.2, b - 1.2]
                for bx in beds:  # heads against the outer wall
                    bz = z0 + 0.3 if out_z == 0.0 else z1 - 2.4
                    s.box(bx, bx + 1.0, y, y + 0.6, bz, bz + 2.1)
                cz = z0 + 3.5 if out_z == 0.0 else z1 - 4.0
                s.box(b - 0.8, b - 0.2, y, y + 0.9, cz, cz + 0.5)
        # the core: small rooms along both corridors, back to back, except at the cross corridors, stair and lifts
        busy = [(x - 1.5, x + 1.5) for x in (cross[0], cross[2])] + [(cross[1] - 7.0, well_x + 9.5)]
        spine = (c0 + c1) / 2
        for wall_z, inner in ((c0, spine), (c1, spine)):
            x = 0.3
            while x < size_x - 3.5:
                w = rng.uniform(3.0, 5.0)
                x1 = min(x + w, size_x - 0.3)
                if all(x1 < a or x > b for a, b in busy):
                    z0, z1 = sorted((wall_z, inner))
                    door_z = wall_z
                    s.wall((x, door_z), (x1, door_z), y, ceiling, [(rng.uniform(0.1, max(0.11, x1 - x - 1.8)), 1.6)], thickness=0.15)
                    for xw in (x, x1):
                        s.wall((xw, z0), (xw, z1), y, ceiling, thickness=0.12)
                    s.wall((x, inner), (x1, inner), y, ceiling, thickness=0.12)
                    if rng.random() < 0.6:  # shelving along the back
                        zb = inner - 0.6 if inner > wall_z else inner
                        s.box(x + 0.2, x1 - 0.2, y, y + 1.8, zb, zb + 0.6)
                x = x1 + (0.0 if rng.random() < 0.8 else rng.uniform(2.0, 4.0))
        s.box(well_x + 5.5, well_x + 9.0, y, y + 1.1, c0 + 1.0, c0 + 1.6)  # the nurses' station's counter
        s.box(well_x + 5.5, well_x + 6.1, y, y + 1.1, c0 + 1.6, c0 + 4.0)
        for x0 in (well_x,):  # the stairwell's walls, its door on the corridor at the landing
            s.wall((x0, well_z), (x0 + 4.0, well_z), y, ceiling, [(1.2, 1.6)])
            s.wall((x0, well_z + _well_length(storey)), (x0 + 4.0, well_z + _well_length(storey)), y, ceiling)
            for x in (x0, x0 + 4.0):
                s.wall((x, well_z), (x, well_z + _well_length(storey)), y, ceiling)
            if k < storeys - 1:
                _switchback(s, x0, well_z, y, storey)
            else:
                s.box(x0, x0 + 2.0, y, y + 1.0, well_z + 1.9, well_z + 2.0)
        for a, b in lifts:  # lift shafts: walled all round
            for z in (c1 - 2.7, c1 + 0.0):
                s.wall((a, z), (b, z), y, ceiling, thickness=0.2)
            for x in (a, b):
                s.wall((x, c1 - 2.7), (x, c1), y, ceiling, thickness=0.2)
    return s.mesh()


def mall(seed: int) -> trimesh.Trimesh:
    """A shopping mall of three storeys 5 m apart on a 100-116 x 52 m plan: an atrium 10 m wide down the middle,
    open over all three (the upper floors railed 1.1 m along it), galleries 6 m wide on both sides of it, shops
    8-12 m wide and 14 m deep off the galleries behind storefronts with a 4-6 m opening (shelves and a counter
    inside), and an anchor store 22-26 m deep across each end (an 8 m opening on each gallery, islands of racks).
    Escalators are ramps 1.6 m wide with 1 m balustrades, straight across the atrium from one gallery to the
    one opposite a storey up (27 degrees); two per storey, the upper one turned the other way.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, storey, shop = rng.uniform(100.0, 116.0), 52.0, 5.0, 14.0
    anchors = (rng.uniform(22.0, 26.0), size_x - rng.uniform(22.0, 26.0))
    a0, a1 = size_z / 2 - 5.0, size_z / 2 + 5.0  # the atrium's z extent
    hole = (anchors[0] + 6.0, anchors[1] - 6.0, a0, a1)
    mid = (hole[0] + hole[1]) / 2  # storey 0's escalators in the atrium's west half, storey 1's in its east half
    escalators = [[x, x + rng.uniform(8.0, 12.0)] for x in (hole[0] + rng.uniform(4.0, 8.0), mid + rng.uniform(4.0, 8.0))]
    for k in range(3):
        y = k * storey
        ceiling = y + storey - 0.3
        s.slab(0.0, size_x, 0.0, size_z, y, [hole] if k else [])
        for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)),
                     ((0.0, 0.0), (0.0, size_z)), ((size_x, 0.0), (size_x, size_z))):
            s.wall(a, b, y, ceiling, [(size_z / 2 - 3.0, 6.0)] if k == 0 and a[0] == b[0] else [], thickness=0.3)
        leaving = escalators[k] if k < 2 else []
        if k:  # rails along the atrium, open where an escalator arrives or leaves (on the a0 side on even storeys)
            for z, xs in ((a0, [] if k % 2 else escalators[k - 1] + leaving), (a1, escalators[k - 1] + leaving if k % 2 else [])):
                cuts = [hole[0], *sum(([x - 0.9, x + 0.9] for x in sorted(xs)), []), hole[1]]
                for c0, c1 in zip(cuts[0::2], cuts[1::2]):
                    s.box(c0, c1, y, y + 1.1, z - 0.05, z + 0.05)
            for x in hole[:2]:
                s.box(x - 0.05, x + 0.05, y, y + 1.1, a0, a1)
        for x in (anchors[0], anchors[1]):  # anchor stores' fronts, an opening on each gallery
            s.wall((x, 0.0), (x, size_z), y, ceiling, [(shop + 0.5, 8.0), (size_z - shop - 8.5, 8.0)], thickness=0.3)
        for x0, x1 in ((0.0, anchors[0]), (anchors[1], size_x)):
            for _ in range(int(rng.integers(10, 16))):
                x, z = rng.uniform(x0 + 2.0, x1 - 5.0), rng.uniform(2.0, size_z - 4.0)
                s.box(x, x + 3.0, y, y + 1.4, z, z + 1.2)
        for front in (shop, size_z - shop):  # shops along both galleries
            cuts = [anchors[0]]
            while cuts[-1] < anchors[1] - 12.0:
                cuts.append(cuts[-1] + rng.uniform(8.0, 12.0))
            cuts[-1] = anchors[1]
            openings = []
            for a, b in pairwise(cuts):
                w = rng.uniform(4.0, 6.0)
                openings.append((a - anchors[0] + rng.uniform(0.5, b - a - w - 0.5), w))
            s.wall((anchors[0], front), (anchors[1], front), y, ceiling, openings, thickness=0.2)
            back = 0.0 if front == shop else size_z
            z0, z1 = sorted((front, back))
            for x in cuts[1:-1]:
                s.wall((x, z0), (x, z1), y, ceiling, thickness=0.15)
            for a, b in pairwise(cuts):
                for z in np.arange(z0 + 2.5, z1 - 3.5, 2.6):  # shelves across the shop
                    if rng.random() < 0.7:
                        s.box(a + 1.8, b - 1.8, y, y + 1.6, z, z + 0.6)
                zc = z1 - 1.6 if back == 0.0 else z0 + 1.0
                s.box(a + 0.8, a + 2.6, y, y + 1.0, zc, zc + 0.6)  # the counter
        for x in leaving:  # up across the atrium: from z < a0 to z > a1 on storeys 0 and 2, the other way on 1
            za, zb = (a0, a1) if k % 2 == 0 else (a1, a0)
            s.ramp(np.array([x, za]), np.array([x, zb]), 1.6, y, y + storey)
            for dx in (-0.85, 0.85):
                s.ramp(np.array([x + dx, za]), np.array([x + dx, zb]), 0.1, y + 1.0, y + storey + 1.0, thickness=1.3)
    return s.mesh()


def canyon(seed: int) -> trimesh.Trimesh:
    """A canyon 380-420 m long along x and 18-24 m wide between rock walls 26 m high (tops sloped at more than 60
    degrees, which no one stands on). Its floor at y = 0 is split along its length by a stream bed 3 m wide with
    no bottom (nothing to walk on), crossed by four fords 3 m wide, 0.2 m down. On each wall, ledges 3.5-5 m wide in
    tiers 5, 10 and 15 m up, each a run of pieces up to 25-60 m long, each within a piece of the tier below, with
    gaps between; a ramp 2 m wide against the wall climbs at 20 degrees from a piece (or the floor) to the start of
    each piece of the tier above, so every piece is reached from below. Rope bridges 1.6 m wide, railed 1 m,
    sagging 0.6 m in the middle, cross the canyon between ledges of the same tier where both walls have one, two
    or three a tier. 200-260 boulders (0.4-1.2 m) lie on the floor, clear of the ramps' lane.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length, width, tier, bed = rng.uniform(380.0, 420.0), rng.uniform(18.0, 24.0), 5.0, 3.0
    run = tier / math.tan(math.radians(20.0))
    for face, out in ((0.0, -5.0), (width, width + 5.0)):  # the walls: vertical inside, steep tops outside
        s.hull(np.array([[x, y, z] for x in (-2.0, length + 2.0) for y, z in ((-1.5, face), (26.0, face), (-1.5, out), (36.0, out))]))
    for face, out in ((0.0, -5.0), (length, length + 5.0)):  # the ends, as steep
        s.hull(np.array([[x, y, z] for z in (0.0, width) for y, x in ((-1.5, face), (26.0, face), (-1.5, out), (36.0, out))]))
    mid = width / 2 + rng.uniform(-2.0, 2.0)
    s.box(0.0, length, -1.5, 0.0, 0.0, mid - bed / 2)
    s.box(0.0, length, -1.5, 0.0, mid + bed / 2, width)
    for x in np.sort(rng.uniform(15.0, length - 15.0, size=4)):  # fords 3 m wide, 0.2 m under the floor
        s.box(x - 1.5, x + 1.5, -1.5, -0.2, mid - bed / 2, mid + bed / 2)
    pieces = {}
    for side, face in ((0, 0.0), (1, width)):
        below = [(0.0, length)]
        for k in (1, 2, 3):
            deep = rng.uniform(3.5, 5.0)
            z0, z1 = (face, face + deep) if side == 0 else (face - deep, face)
            row = []
            for a, b in below:  # pieces of this tier start above a piece of the tier below, after a ramp
                x = a + rng.uniform(1.0, 6.0)
                while x + run + 15.0 < b:  # within the piece below, so no ramp climbs into a piece above
                    start = x + run
                    end = min(start + rng.uniform(25.0, 60.0), b)
                    row.append((start, end))
                    wall_z = (z0 + 1.0) if side == 0 else (z1 - 1.0)
                    s.ramp(np.array([x, wall_z]), np.array([start + 0.5, wall_z]), 2.0, (k - 1) * tier, k * tier)
                    x = end + rng.uniform(15.0, 30.0)
            for a, b in row:
                s.box(a, b, k * tier - 0.6, k * tier, z0, z1)
            pieces[side, k] = (row, z0, z1)
            below = row
    for k in (1, 2, 3):
        (row0, _, near), (row1, far, _) = pieces[0, k], pieces[1, k]
        both = [(max(a, c) + 3.0, min(b, d) - 3.0) for a, b in row0 for c, d in row1 if min(b, d) - max(a, c) > 8.0]
        for a, b in both[:int(rng.integers(2, 4))]:
            x = rng.uniform(a, b)
            y, sag = k * tier, k * tier - 0.6
            for p, q, ya, yb in (((x, near - 0.5), (x, width / 2), y, sag), ((x, width / 2), (x, far + 0.5), sag, y)):
                s.ramp(np.array(p), np.array(q), 1.6, ya, yb, thickness=0.2)
                for dx in (-0.85, 0.85):  # ropes over the gap, open at the ledges
                    pp, qq = np.array(p) + [dx, 0.0], np.array(q) + [dx, 0.0]
                    pp[1], qq[1] = max(pp[1], near + 0.1), min(qq[1], far - 0.1)
                    s.ramp(pp, qq, 0.1, ya + 1.0, yb + 1.0, thickness=1.1)
    for _ in range(int(rng.integers(200, 260))):  # boulders clear of the stream bed
        c = np.array([rng.uniform(5.0, length - 5.0), rng.choice([rng.uniform(3.5, mid - bed), rng.uniform(mid + bed, width - 3.5)])])
        r = rng.uniform(0.4, 1.2)
        s.rock(rng, c, r / 2, -0.3, r * 1.5)
    return s.mesh()


def hillside(seed: int) -> trimesh.Trimesh:
    """A terraced hillside town 130-150 m wide climbing along +z: nine terraces 4 m apart in height and 15-19 m
    deep, each a street 5-7 m wide along its front and behind it a row of houses (solid, 6-11 m wide, ridged roofs
    at 50 degrees) backed against the retaining wall of the terrace above. Streets climb as stairs (0.16 / 0.30 m
    steps, 2.5-3.5 m wide) between houses from each street to the next, at least two a terrace (the widest other
    gaps when chance gave fewer, 2-3.5 m wide); other gaps are
    alleys 2-2.4 m wide that end at the wall, or small gardens with a tree. A square 14 m deep before the middle terrace's row (a
    pointed fountain, benches), a church closing the top street, and on every street 10-17 planters and stalls.
    The ground stops under the houses and the church.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, rise, terraces = rng.uniform(130.0, 150.0), 4.0, 9
    steps = 25
    run = steps * 0.30
    square = terraces // 2
    depths = rng.uniform(15.0, 19.0, size=terraces) + 14.0 * (np.arange(terraces) == square)  # the square's 14 m more
    fronts = np.cumsum([0.0, *depths])  # z of each terrace's front, and the last one's back
    for i in range(terraces):
        y, z0, z1 = i * rise, fronts[i], fronts[i + 1]
        footprints: list[tuple[float, float, float, float]] = []  # of houses and the church: the ground stops under them
        for x in (-0.3, size_x):  # the town's side walls
            s.box(x, x + 0.3, y - 1.0, y + 1.2, z0, z1)
        street = rng.uniform(5.0, 7.0) + (14.0 if i == square else 0.0)
        houses_z0 = z0 + street
        if i == terraces - 1:  # the top terrace: a church closes the street, no row behind
            footprints.append((size_x / 2 - 8.0, size_x / 2 + 8.0, houses_z0, z1))
            s.hull(np.array([[x, yy, z] for x in (size_x / 2 - 8.0, size_x / 2 + 8.0) for z in (houses_z0, z1)
                             for yy in (y - 0.5, y + 10.0)] + [[size_x / 2, y + 10.0 + 8.0 * math.tan(math.radians(50.0)), z]
                                                                for z in (houses_z0, z1)]))
            for x in (rng.uniform(5.0, size_x / 2 - 15.0), rng.uniform(size_x / 2 + 10.0, size_x - 10.0)):
                s.box(x, x + 4.0, y, y + 0.8, houses_z0 + 1.0, houses_z0 + 2.0)
            s.ground(0.0, size_x, z0, z1, y, footprints, thickness=rise + 1.0)
            continue
        x = rng.uniform(0.0, 4.0)
        gaps = []
        while x < size_x - 8.0:
            w = rng.uniform(6.0, 11.0)
            x1 = min(x + w, size_x)
            depth = z1 - houses_z0
            ridge = y + 6.0 + min(w, depth) / 2 * math.tan(math.radians(50.0))
            along_x = w > depth
            corners = [[a, yy, c] for a in (x, x1) for c in (houses_z0, z1) for yy in (y - 0.5, y + 6.0)]
            top = [[a, ridge, (houses_z0 + z1) / 2] for a in (x, x1)] if along_x else [[(x + x1) / 2, ridge, c] for c in (houses_z0, z1)]
            s.hull(np.array(corners + top))
            footprints.append((x, x1, houses_z0, z1))
            kind = rng.random()
            if kind < 0.35:
                gap = rng.uniform(2.5, 3.5)
                gaps.append(("stairs", x1, gap))
            elif kind < 0.7:
                gap = rng.uniform(2.0, 2.4)
                gaps.append(("alley", x1, gap))
            else:
                gap = rng.uniform(5.0, 8.0)
                gaps.append(("garden", x1, gap))
            x = x1 + gap
        gaps = [g for g in gaps if g[1] + g[2] <= size_x - 0.5]
        others = sorted((g for g in gaps if g[0] != "stairs"), key=lambda g: -g[2])
        for g in others[:max(0, 2 - sum(g[0] == "stairs" for g in gaps))]:  # every terrace has two ways up at least
            gaps[gaps.index(g)] = ("stairs", *g[1:])
        for kind, gx, gw in gaps:
            if kind == "stairs":  # up to the next street, cut into the back of this terrace's row, at most 3.5 m wide
                s.stairs(np.array([gx + gw / 2, z1 - run]), np.array([0.0, 1.0]), min(gw, 3.5), y, rise, riser=rise / steps,
                         tread=0.30)
            elif kind == "garden":
                angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
                c = np.array([gx + gw / 2, (houses_z0 + z1) / 2])
                s.prism(c + 0.35 * np.stack([np.cos(angles), np.sin(angles)], 1), y - 0.5, y + 7.0)
                s.box(gx, gx + gw, y, y + 1.0, z1 - 1.2, z1)  # a bench against the wall
        s.ground(0.0, size_x, z0, z1, y, footprints, thickness=rise + 1.0)
        for _ in range(int(rng.integers(10, 18))):  # planters and stalls in the street
            px, pz = rng.uniform(2.0, size_x - 5.0), rng.uniform(z0 + 1.0, z0 + street - 2.0)
            s.box(px, px + rng.uniform(1.0, 3.0), y, y + 0.8, pz, pz + 1.0)
        if i == square:
            c = np.array([size_x / 2, z0 + 8.0])
            angles = np.linspace(0, 2 * math.pi, 12, endpoint=False)
            s.hull(np.array([[*(c + 2.5 * np.array([math.cos(a), math.sin(a)])), y] for a in angles] + [[*c, y + 4.0]])[:, [0, 2, 1]])
            for dx in (-7.0, 5.0):
                s.box(c[0] + dx, c[0] + dx + 2.0, y, y + 0.45, c[1] + 4.0, c[1] + 4.6)
    return s.mesh()


def spaceship(seed: int) -> trimesh.Trimesh:
    """A space station's deck: a hub 9 m across (a 12-gon) and three ring corridors 3 m wide, 28-32, 52-58 and
    76-82 m from the centre (24-gons of straight segments, walls 3 m high), joined by six spokes from the hub to
    the first ring and eight between each ring and the next (corridors 2.6 m wide, offset by a step so no spoke runs
    straight through). Off each ring's outside, on every segment no spoke leaves from, a room 6-9 m deep between
    radial walls (cabins and labs, a door 2 m wide each, a bunk or bench and lockers: the walls are chords at
    angles, where a 1.6 m door, enough along the axes, closes for the presets' agent); off the outer ring four
    airlocks instead of rooms: a stub corridor out to a chamber 3 x 4 m behind a door, then an outer door onto a
    docking platform. Crates and consoles line the rings. No floor elsewhere: space is nothing to walk on.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    hub, ring_w, spoke_w, wall_h, sides = 4.5 / math.cos(math.pi / 12), 3.0, 2.6, 3.0, 24
    rings = [rng.uniform(28.0, 32.0), rng.uniform(52.0, 58.0), rng.uniform(76.0, 82.0)]
    angles = np.linspace(0.0, 2 * math.pi, sides, endpoint=False) + rng.uniform(0.0, 2 * math.pi / sides)
    step = angles[1] - angles[0]
    locks = set(rng.choice(sides, size=4, replace=False).tolist())  # the outer ring's segments with an airlock
    spokes = [set(range(0, sides, 4)), set(range(1, sides, 3)), set(range(2, sides, 3))]  # segments, into each ring

    def at(radius: float, angle: float) -> np.ndarray:
        return radius * np.array([math.cos(angle), math.sin(angle)])

    def wall(p: np.ndarray, q: np.ndarray, gap: float = 0.0) -> None:
        """A wall 0.2 m thick from plan point p to q, open over ``gap`` m in its middle."""
        half = (q - p) / np.linalg.norm(q - p) * gap / 2
        for u, v in ((p, (p + q) / 2 - half), ((p + q) / 2 + half, q)) if gap else ((p, q),):
            s.prism(_strip(u, v, 0.2), 0.0, wall_h)

    s.prism(np.array([at(hub, a) for a in np.linspace(0, 2 * math.pi, 12, endpoint=False)]), -0.3, 0.0)
    starts = [4.3] + [(r + ring_w / 2) * math.cos(step / 2) - 0.2 for r in rings[:-1]]  # into the chords' middles
    for n, (radius, start) in enumerate(zip(rings, starts)):
        r0, r1 = radius - ring_w / 2, radius + ring_w / 2
        outward = spokes[n + 1] if n + 1 < len(rings) else locks
        depth = rng.uniform(6.0, 9.0)
        for i, (a, b) in enumerate(zip(angles, np.roll(angles, -1))):
            mid = a + step / 2
            s.prism(np.array([at(r0, a), at(r1, a), at(r1, b), at(r0, b)]), -0.3, 0.0)
            wall(at(r0, a), at(r0, b), spoke_w + 0.2 if i in spokes[n] else 0.0)
            wall(at(r1, a), at(r1, b), spoke_w + 0.2 if i in outward else 2.0)
            if i in spokes[n]:  # a spoke in from the ring (or hub) inside, to the middle of this segment
                s.prism(_strip(at(start, mid), at(r0 + 0.3, mid), spoke_w), -0.3, 0.0)
                side = at(spoke_w / 2 + 0.1, mid + math.pi / 2)
                for sign in (-1, 1):
                    s.prism(_strip(at(start + 0.4, mid) + sign * side, at(r0 - 0.1, mid) + sign * side, 0.2), 0.0, wall_h)
            if i % 2 == 0 and rng.random() < 0.5:  # a crate or console against the outer wall, a quarter along
                c = at(r1 - 0.6, a + step / 4)
                s.prism(_strip(c - at(0.5, a + math.pi / 2), c + at(0.5, a + math.pi / 2), 0.8), 0.0, rng.uniform(0.8, 1.4))
            if n + 1 == len(rings) and i in locks:  # an airlock: stub, inner door, chamber, outer door, platform
                for r_a, r_b, w in ((r1 * math.cos(step / 2) - 0.2, r1 + 3.0, 2.6), (r1 + 3.0, r1 + 7.0, 3.0),
                                    (r1 + 7.0, r1 + 13.0, 6.0)):
                    s.prism(_strip(at(r_a, mid), at(r_b, mid), w), -0.3, 0.0)
                for r_a, r_b, w in ((r1, r1 + 3.0, 2.6), (r1 + 3.0, r1 + 7.0, 3.0)):
                    for sign in (-1, 1):
                        off = at(w / 2 + 0.1, mid + math.pi / 2) * sign
                        s.prism(_strip(at(r_a, mid) + off, at(r_b, mid) + off, 0.2), 0.0, wall_h)
                for r_door in (r1 + 3.0, r1 + 7.0):  # door walls 2 m open in the middle
                    wall(at(r_door, mid) - at(1.7, mid + math.pi / 2), at(r_door, mid) + at(1.7, mid + math.pi / 2), 2.0)
            elif i not in outward:  # a room: floor, walls along the radii and across its back, lockers, a bunk
                pa, pb, qa, qb = at(r1, a), at(r1, b), at(r1 + depth, a), at(r1 + depth, b)
                s.prism(np.array([pa, pb, qb, qa]), -0.3, 0.0)
                for p, q in ((pa, qa), (qa, qb), (pb, qb)):
                    wall(p, q)
                lockers = (qa + qb) / 2 + (pa - qa) * 0.12
                s.prism(_strip(lockers + (qb - qa) * 0.25, lockers - (qb - qa) * 0.25, 0.6), 0.0, 1.9)
                bunk = (pa + qb) / 2 + (qa - pa) * 0.1
                s.prism(_strip(bunk - (pa - qa) * 0.25, bunk + (pa - qa) * 0.25, 0.9), 0.0, 0.5)
    return s.mesh()


def _terrain(s: _Solids, xs: np.ndarray, zs: np.ndarray, heights: np.ndarray, keep: np.ndarray | None = None) -> None:
    """Ground over the grid ``xs`` (n,) x ``zs`` (m,) with the heights (n, m), metres: two triangles a cell, and a
    skirt 0.5 m under it facing down, so the ground is a closed sheet whose top Recast reads as floor. With ``keep``
    (n - 1, m - 1) of bools, only the cells it marks (the rest hold no ground: water, a hole)."""
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    vertices = np.stack([gx.ravel(), np.asarray(heights, dtype=np.float64).ravel(), gz.ravel()], axis=1)
    index = np.arange(len(xs) * len(zs)).reshape(len(xs), len(zs))
    a, b, c, d = index[:-1, :-1].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel(), index[:-1, 1:].ravel()
    faces = np.concatenate([np.stack([a, c, b], 1), np.stack([a, d, c], 1)])
    if keep is not None:
        faces = faces[np.tile(np.asarray(keep, dtype=bool).ravel(), 2)]
    ground = trimesh.Trimesh(vertices, faces, process=False)
    skirt = ground.copy()
    skirt.vertices[:, 1] -= 0.5
    skirt.invert()
    s.parts += [ground, skirt]


def _chaikin(points: np.ndarray, rounds: int) -> np.ndarray:
    """The closed polygon ``points`` (k, d) with its corners cut ``rounds`` times (Chaikin 1974, corner cutting at
    1/4 and 3/4 of each side): (k * 2**rounds, d), O(k * 2**rounds)."""
    for _ in range(rounds):
        after = np.roll(points, -1, axis=0)
        points = np.stack([0.75 * points + 0.25 * after, 0.25 * points + 0.75 * after], axis=1).reshape(-1, points.shape[1])
    return points


def kart(seed: int) -> trimesh.Trimesh:
    """A karting circuit about 2.7 km round, 9-11 m wide, which crosses itself once on a bridge 6 m up (a figure
    of eight): a closed line through 13 corners jittered 0-6 m, its corners cut three times (:func:`_chaikin`),
    split into pieces at most 5 m long, each a deck on the line with a wedge filling the outside of each joint; the
    height rises 6 m and falls again over 90 m of track either side of the crossing's upper pass (8-11 degrees).
    Barriers 1 m high line both sides (no floor beyond them: the grass is nothing to walk on). Along the start
    straight, behind its barrier, a pit lane 6 m wide with a lane in and a lane out through gaps in the barrier,
    twelve garages 5.5 m wide (walls on three sides, open to the pit lane, a kart each) and, behind them, a paddock
    of up to 25-35 trailers at least 2 m apart (roofs at 50 degrees, no floor inside) reached through a 1.6 m door at the back of every third
    garage.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    corners = 2.2 * np.array([[0, 0], [300, 0], [360, 60], [330, 140], [180, 140], [140, 210], [230, 270], [250, 40],
                              [150, 60], [40, 80], [-40, 90], [-70, 40], [-40, 0]], dtype=np.float64)
    corners[1:] += rng.uniform(-6.0, 6.0, size=(len(corners) - 1, 2))  # the start straight stays on z = 0
    line = _chaikin(corners, 3)
    pieces = [line[0]]
    for a, b in pairwise(np.vstack([line, line[:1]])):  # pieces at most 5 m long
        n = max(1, math.ceil(np.linalg.norm(b - a) / 5.0))
        pieces += [a + (b - a) * t for t in np.arange(1, n + 1) / n]
    line = np.array(pieces[:-1])
    ahead = np.roll(line, -1, axis=0)
    lengths = np.linalg.norm(ahead - line, axis=1)
    along = np.concatenate([[0.0], np.cumsum(lengths)[:-1]])
    # the crossing: the first pair of pieces far apart along the track whose segments intersect
    crossing = None
    for i in range(len(line)):
        for j in range(i + 3, len(line) - 2 if i == 0 else len(line)):
            p, r, q, t = line[i], ahead[i] - line[i], line[j], ahead[j] - line[j]
            den = r[0] * t[1] - r[1] * t[0]
            if abs(den) > 1e-9:
                u, v = ((q - p)[0] * t[1] - (q - p)[1] * t[0]) / den, ((q - p)[0] * r[1] - (q - p)[1] * r[0]) / den
                if 0 <= u <= 1 and 0 <= v <= 1:
                    crossing = along[j] + v * lengths[j]
                    break
        if crossing is not None:
            break
    assert crossing is not None, "the circuit's corners make no figure of eight"
    gap = np.abs(along - crossing)
    heights = np.where(gap < 90.0, 6.0 * np.cos(np.clip(gap / 90.0, 0, 1) * math.pi / 2) ** 2, 0.0)
    width = rng.uniform(9.0, 11.0)
    pit_gaps = [(8.0, 24.0), (276.0, 292.0)]  # x ranges where the start straight's south barrier opens
    for i in range(len(line)):
        a, b, ya, yb = line[i], ahead[i], heights[i], heights[(i + 1) % len(line)]
        s.ramp(a, b, width, ya, yb)
        nxt = (i + 1) % len(line)
        after = ahead[nxt]
        d0, d1 = (b - a) / np.linalg.norm(b - a), (after - b) / np.linalg.norm(after - b)
        sides = [np.array([-d[1], d[0]]) * width / 2 for d in (d0, d1)]
        if abs(d0[0] * d1[1] - d0[1] * d1[0]) > 1e-3:  # a wedge where the line turns; none where it runs straight on
            s.hull(np.array([[*(b + sign * side), y] for side in sides for sign in (-1, 1) for y in (yb - 0.3, yb)])[:, [0, 2, 1]])
        for sign in (-1, 1):  # the barriers, each piece's own
            off = np.array([-d0[1], d0[0]]) * sign * (width / 2 + 0.15)
            mid = (a + b) / 2 + off
            if abs(mid[1]) < width and mid[1] < 0 and any(x0 < mid[0] < x1 for x0, x1 in pit_gaps):
                continue
            s.ramp(a + off, b + off, 0.3, ya + 1.0, yb + 1.0, thickness=1.3)
    south = -width / 2 - 0.3
    pit = (south - 4.0, south - 10.0)  # the pit lane's z extent, north to south
    s.box(20.0, 280.0, -0.3, 0.0, pit[1], pit[0])
    for a, b in (((10.0, south + 1.0), (26.0, (pit[0] + pit[1]) / 2)), ((274.0, (pit[0] + pit[1]) / 2), (290.0, south + 1.0))):
        s.ramp(np.array(a), np.array(b), 6.0, 0.0, 0.0)
    s.wall((26.0, south - 0.1), (274.0, south - 0.1), 0.0, 1.0, thickness=0.3)  # the pit wall behind the barrier's gaps
    back = pit[1] - 8.0
    paddock = (back - 50.0, back)
    x = 40.0
    for k in range(12):  # garages: a floor, walls at the sides and the back, a kart
        s.box(x, x + 5.5, -0.3, 0.0, back, pit[1])
        for wx in (x, x + 5.5):
            s.wall((wx, back), (wx, pit[1]), 0.0, 3.0)
        s.wall((x, back), (x + 5.5, back), 0.0, 3.0, [(1.5, 1.6)] if k % 3 == 1 else [])
        kx = x + rng.uniform(1.0, 2.5)
        s.box(kx, kx + 1.2, 0.0, 0.6, back + 2.5, back + 4.5)
        x += 5.5
    trailers = []
    for _ in range(int(rng.integers(25, 36))):  # trailers in the paddock, their roofs at 50 degrees
        tx, tz = rng.uniform(32.0, 108.0), rng.uniform(paddock[0] + 2.0, paddock[1] - 8.0)
        tw, td = rng.uniform(2.5, 8.0), rng.uniform(2.4, 6.0)
        if any(tx < b + 2.0 and a < tx + tw + 2.0 and tz < d + 2.0 and c < tz + td + 2.0 for a, b, c, d in trailers):
            continue  # 2 m apart at least, so no pocket is closed in between
        trailers.append((tx, tx + tw, tz, tz + td))
        ridge = 2.8 + td / 2 * math.tan(math.radians(50.0))
        s.hull(np.array([[x, y, z] for x in (tx, tx + tw) for z in (tz, tz + td) for y in (-0.3, 2.8)]
                        + [[x, ridge, tz + td / 2] for x in (tx, tx + tw)]))
    s.ground(30.0, 120.0, paddock[0], paddock[1], 0.0, trailers, thickness=0.3)  # stopping under the trailers
    for a, b in (((30.0, paddock[0]), (120.0, paddock[0])), ((30.0, paddock[0]), (30.0, paddock[1])),
                 ((120.0, paddock[0]), (120.0, paddock[1]))):
        s.wall(a, b, 0.0, 2.0)
    return s.mesh()


def _lid(s: _Solids, x0: float, x1: float, z0: float, z1: float, y: float) -> None:
    """A ceiling over [x0, x1] x [z0, z1] from height ``y`` up, ridged along x at 50 degrees, so nothing on it is
    floor. Recast reads surfaces, not solids: the top of a solid reaching ``y`` under it would be floor with the
    lid's underside as its ceiling, so solids under a lid stop 1 m short of it (less than the agent's height)."""
    ridge = y + 0.3 + (z1 - z0) / 2 * math.tan(math.radians(50.0))
    s.hull(np.array([[x, yy, z] for x in (x0, x1) for z in (z0, z1) for yy in (y, y + 0.3)]
                    + [[x, ridge, (z0 + z1) / 2] for x in (x0, x1)]))


def bunker(seed: int) -> trimesh.Trimesh:
    """An underground bunker of three levels 6 m apart, 110 x 72 m, closed (no way out) under a lid
    (:func:`_lid`). On each level corridors 3 m wide (a spine along x, cross corridors along z every 20-26 m)
    between blocks of rooms behind concrete walls 0.6 m thick; every room opens on a corridor through a blast
    door: a 1.8 m opening with its steel leaf (0.3 m thick, 2 m long) swung open against the wall inside. Rooms side
    by side in a block are joined by a ventilation crawlway: an opening 1.4 m wide and 1.0 m high in the wall
    between them, under a solid lintel (too low for the presets' 2 m agent), in half the pairs through a double
    wall (a crawlway 1.6 m long, a cavity 0.4 m wide between the walls). Furniture: bunks or consoles and lockers
    against the side walls. The levels are joined by two switchback
    stairwells (:func:`_switchback`) in stair halls at both ends of the spine's north side (a 3 m opening on the
    spine); the floor stops under the machines (Recast would find floor inside them).
    The lowest level holds a generator hall (the north side's second and third blocks, machines 4.2 m high
    in two rows) and an escape tunnel 2.4 m wide along the south wall, behind the rooms, entered from the last room.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, storey, levels, spine_w, cross_w, wall_t = 110.0, 72.0, 6.0, 3, 3.0, 3.0, 0.6
    spine = (size_z / 2 - spine_w / 2, size_z / 2 + spine_w / 2)
    crosses = [rng.uniform(20.0, 26.0)]
    while crosses[-1] < size_x - 40.0:
        crosses.append(crosses[-1] + cross_w + rng.uniform(20.0, 26.0))
    edges_x = [0.0, *sum(([c, c + cross_w] for c in crosses), []), size_x]
    blocks_x = list(zip(edges_x[0::2], edges_x[1::2]))
    well = _well_length(storey)
    stair_blocks = (0, len(blocks_x) - 1)
    wells = [(blocks_x[b][0] + (blocks_x[b][1] - blocks_x[b][0]) / 2 - 2.0, spine[1] + 5.0) for b in stair_blocks]
    holes = [(x0, x0 + 4.0, z0 + 2.0, z0 + well) for x0, z0 in wells]
    _lid(s, 0.0, size_x, 0.0, size_z, storey + 0.7)
    for k in range(levels):
        y = -k * storey
        ceiling = y + storey - 0.3
        solid: list[tuple[float, float, float, float]] = []  # plans of solids the floor stops under
        for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)),
                     ((0.0, 0.0), (0.0, size_z)), ((size_x, 0.0), (size_x, size_z))):
            s.wall(a, b, y, ceiling, thickness=wall_t)
        for x0, z0 in wells:  # the stairwell's walls, its door at the landing's end, toward the spine
            s.wall((x0, z0), (x0 + 4.0, z0), y, ceiling, [(1.2, 1.6)])
            s.wall((x0, z0 + well), (x0 + 4.0, z0 + well), y, ceiling)
            for x in (x0, x0 + 4.0):
                s.wall((x, z0), (x, z0 + well), y, ceiling)
            if k:
                _switchback(s, x0, z0, y, storey)
        if k == levels - 1:  # the escape tunnel along the south wall, entered from the last room
            s.wall((0.3, 3.0), (size_x - 0.3, 3.0), y, ceiling, [(size_x - 4.5, 2.0)], thickness=wall_t)
        for side, (z_wall, z_out) in enumerate(((spine[0], 3.3 if k == levels - 1 else 0.3), (spine[1], size_z - 0.3))):
            z0, z1 = sorted((z_wall, z_out))
            inward = 1.0 if z_out > z_wall else -1.0
            for bi, (bx0, bx1) in enumerate(blocks_x):
                for x in (bx0, bx1):
                    s.wall((x, z0), (x, z1), y, ceiling, thickness=wall_t)
                if side == 1 and (bi in stair_blocks or (k == levels - 1 and bi in (1, 2))):  # a stair hall, the generator hall
                    s.wall((bx0, z_wall), (bx1, z_wall), y, ceiling, [(2.0, 3.0), (bx1 - bx0 - 5.0, 3.0)], thickness=wall_t)
                    continue
                cuts = [bx0]
                while cuts[-1] < bx1 - 9.0:
                    cuts.append(cuts[-1] + rng.uniform(6.0, 9.0))
                cuts = [*cuts[:-1], bx1] if len(cuts) > 1 else [bx0, bx1]
                doors = [((a + b) / 2 - bx0 - 0.9 + rng.uniform(-0.8, 0.8), 1.8) for a, b in pairwise(cuts)]
                s.wall((bx0, z_wall), (bx1, z_wall), y, ceiling, doors, thickness=wall_t)
                for (a, b), (start, _) in zip(pairwise(cuts), doors):
                    lx = bx0 + start + 1.9  # the leaf, swung open inside
                    s.box(lx, lx + 0.3, y, y + 2.2, *sorted((z_wall + inward * 0.35, z_wall + inward * 2.35)))
                    if rng.random() < 0.6:  # a bunk or a console against a side wall
                        zb = (z0 + z1) / 2 + rng.uniform(-4.0, 4.0)
                        s.box(b - 1.3, b - 0.4, y, y + float(rng.choice([0.6, 1.1])), zb - 1.1, zb + 1.1)
                    if rng.random() < 0.4:  # lockers against a side wall
                        zl = (z0 + z1) / 2
                        s.box(a + 0.4, a + 1.0, y, y + 1.9, zl - 1.0, zl + 1.0)
                for x in cuts[1:-1]:  # walls between rooms, each with a crawlway under a lintel
                    zc = rng.uniform(3.0, z1 - z0 - 4.4)
                    for wx in ((x,) if rng.random() < 0.5 else (x - 0.5, x + 0.5)):  # or a double wall
                        s.wall((wx, z0), (wx, z1), y, y + 1.0, [(zc, 1.4)], thickness=wall_t)
                        s.wall((wx, z0), (wx, z1), y + 1.0, ceiling, thickness=wall_t)
        if k == levels - 1:  # the generator hall's machines, too tall to stand on under the ceiling
            for hx0, hx1 in blocks_x[1:3]:
                for mx in np.arange(hx0 + 4.0, hx1 - 6.0, rng.uniform(7.0, 9.0)):
                    for mz in (spine[1] + 8.0, spine[1] + 20.0):
                        s.box(mx, mx + 4.0, y - 0.3, y + 4.2, mz, mz + 5.0)
                        solid.append((mx, mx + 4.0, mz, mz + 5.0))
        s.ground(0.0, size_x, 0.0, size_z, y, (holes if k < levels - 1 else []) + solid, thickness=0.3)
    return s.mesh()


def hall(seed: int) -> trimesh.Trimesh:
    """An exhibition hall 230-250 x 140-160 m under one roof, nearly all open floor: pillars 1 m square on a grid
    of 14-16 m (a tenth of them left out), 4 m entrances in the middle of each wall onto a strip of forecourt 6 m
    deep, and 8-12 exhibitors' stands (6-12 m square: two back walls 2.5 m high in an L, a counter 1.1 m high, a few
    display plinths) each in a bay between pillars; pallets of boxes here and there (1.2 m square, 1.5 m high).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, grid = rng.uniform(230.0, 250.0), rng.uniform(140.0, 160.0), rng.uniform(14.0, 16.0)
    s.box(-6.0, size_x + 6.0, -0.3, 0.0, -6.0, size_z + 6.0)
    for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z))):
        s.wall(a, b, 0.0, 12.0, [(size_x / 2 - 2.0, 4.0)], thickness=0.4)
    for a, b in (((0.0, 0.0), (0.0, size_z)), ((size_x, 0.0), (size_x, size_z))):
        s.wall(a, b, 0.0, 12.0, [(size_z / 2 - 2.0, 4.0)], thickness=0.4)
    xs = np.arange(grid, size_x - grid / 2, grid)
    zs = np.arange(grid, size_z - grid / 2, grid)
    bays = [(i, j) for i in range(len(xs) - 1) for j in range(len(zs) - 1)]
    stands = [bays[k] for k in rng.choice(len(bays), size=int(rng.integers(8, 13)), replace=False)]
    for x in xs:
        for z in zs:
            if rng.random() >= 0.1:
                s.box(x - 0.5, x + 0.5, 0.0, 12.0, z - 0.5, z + 0.5)
    for i, j in stands:
        side = rng.uniform(6.0, min(12.0, grid - 2.0))
        x0, z0 = xs[i] + (grid - side) / 2, zs[j] + (grid - side) / 2
        s.wall((x0, z0), (x0 + side, z0), 0.0, 2.5, thickness=0.1)
        s.wall((x0, z0), (x0, z0 + side), 0.0, 2.5, thickness=0.1)
        s.box(x0 + side - 3.5, x0 + side - 0.5, 0.0, 1.1, z0 + side - 1.2, z0 + side - 0.6)
        for _ in range(int(rng.integers(1, 4))):
            px, pz = x0 + rng.uniform(1.0, side - 2.0), z0 + rng.uniform(1.0, side - 3.0)
            s.box(px, px + 0.8, 0.0, 1.0, pz, pz + 0.8)
    for _ in range(int(rng.integers(15, 25))):
        px, pz = rng.uniform(2.0, size_x - 3.0), rng.uniform(2.0, size_z - 3.0)
        s.box(px, px + 1.2, 0.0, 1.5, pz, pz + 1.2)
    return s.mesh()


def slopes(seed: int) -> trimesh.Trimesh:
    """Mountain ground 176 x 160 m on a 1 m grid (:func:`_terrain`): four ridges 9 m high along z between five
    flat valleys, each ridge a crest 4 m wide between two flanks whose slope runs from 32 degrees at z = 0 to 58 at
    z = 160, through the presets' 45-degree limit near the middle, with ripples of 0.15 m every 8 m (a few degrees
    either way), so the walkable part of each flank ends raggedly. The crests run the whole length, so they are
    joined to the valleys only where the flanks are under the limit; boulders lie in the valleys.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    period, height, crest, length = 44.0, 9.0, 4.0, 160.0
    xs, zs = np.arange(0.0, 4 * period + 0.5, 1.0), np.arange(0.0, length + 0.5, 1.0)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    phase = rng.uniform(0, 2 * math.pi, size=2)
    angle = np.radians(32.0 + 26.0 * gz / length + rng.uniform(-1.5, 1.5))
    from_crest = np.abs((gx % period) - period / 2) - crest / 2  # m from the nearest crest's edge, negative on it
    ridge = np.clip(height - np.maximum(from_crest, 0.0) * np.tan(angle), 0.0, height)
    ripple = 0.15 * np.sin(gx * 2 * math.pi / 8.0 + phase[0]) * np.sin(gz * 2 * math.pi / 8.0 + phase[1])
    ridge[(gx < 1.0) | (gx > 4 * period - 1.0)] = 0.0
    _terrain(s, xs, zs, ridge + ripple * (ridge > 0.0) * (ridge < height))
    for _ in range(int(rng.integers(25, 40))):  # boulders in the valleys
        k = int(rng.integers(0, 5))
        c = np.array([k * period + rng.uniform(-3.0, 3.0), rng.uniform(5.0, length - 5.0)])
        c[0] = np.clip(c[0], 3.0, 4 * period - 3.0)
        r = rng.uniform(0.5, 1.5)
        s.rock(rng, c, r / 2, -0.3, r * 1.5)
    return s.mesh()


def islets(seed: int) -> trimesh.Trimesh:
    """A lake 420 m square of many small islands, most of them out of reach: a main island (a 60 x 40 m
    octagon 1 m up, six huts one enters through a 1.6 m door, a bed against the back wall, a jetty), 14 clusters of 4-7 islets joined by plank
    walks 1.8 m wide (one cluster joined to the main island), and 60-80 lone islets no walk reaches; islets are
    flat convex tops 0.3-1.5 m up, 4-12 m across, with a rock or a tree on the larger ones. No water surface.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size = 420.0
    main = np.array([size / 2, size / 2])
    angles = np.linspace(0, 2 * math.pi, 8, endpoint=False) + math.pi / 8
    s.prism(main + np.stack([30.0 * np.cos(angles), 20.0 * np.sin(angles)], 1), -2.0, 1.0)
    for k in range(6):  # huts round the island's middle, doors facing it
        a = k * math.pi / 3 + rng.uniform(-0.2, 0.2)
        c = main + np.array([16.0 * math.cos(a), 9.0 * math.sin(a)])
        x0, x1, z0, z1 = c[0] - 3.0, c[0] + 3.0, c[1] - 2.5, c[1] + 2.5
        facing_z = z0 if c[1] > main[1] else z1
        s.wall((x0, facing_z), (x1, facing_z), 1.0, 3.5, [(2.2, 1.6)], thickness=0.2)
        s.wall((x0, z0 + z1 - facing_z), (x1, z0 + z1 - facing_z), 1.0, 3.5, thickness=0.2)
        for x in (x0, x1):
            s.wall((x, z0), (x, z1), 1.0, 3.5, thickness=0.2)
        s.hull(np.array([[x, 3.5, z] for x in (x0 - 0.3, x1 + 0.3) for z in (z0 - 0.3, z1 + 0.3)]
                        + [[x, 3.5 + 2.8 * math.tan(math.radians(50.0)), (z0 + z1) / 2] for x in (x0 - 0.3, x1 + 0.3)]))
        bed_z = z1 - 1.4 if facing_z == z0 else z0 + 0.4  # against the back wall: in front of the door it shut four huts
        s.box(x0 + 0.5, x0 + 2.5, 1.0, 1.5, bed_z, bed_z + 1.0)
    s.ramp(main + np.array([29.0, 0.0]), main + np.array([45.0, 0.0]), 2.4, 1.0, 0.6)  # the jetty
    placed: list[tuple[np.ndarray, float]] = [(main, 36.0), (main + np.array([45.0, 0.0]), 1.5)]

    def islet(near: np.ndarray | None, spread: float) -> tuple[np.ndarray, float, float] | None:
        """A new islet's centre, radius and top, at least 5 m of water from every other one (None after 200 tries)."""
        for _ in range(200):
            c = (near + rng.uniform(-spread, spread, size=2)) if near is not None else rng.uniform(10.0, size - 10.0, size=2)
            r = rng.uniform(2.0, 6.0)
            if 6.0 < c[0] < size - 6.0 and 6.0 < c[1] < size - 6.0 and all(np.linalg.norm(c - d) > r + q + 5.0 for d, q in placed):
                placed.append((c, r))
                return c, r, float(rng.uniform(0.3, 1.5))
        return None

    def build(c: np.ndarray, r: float, top: float) -> None:
        a = np.sort(rng.uniform(0, 2 * math.pi, size=10))
        s.prism(c + (r * rng.uniform(0.8, 1.0, size=10))[:, None] * np.stack([np.cos(a), np.sin(a)], 1), top - 2.0, top)
        if r > 3.5:
            _rock_or_palm(s, rng, c + rng.uniform(-0.3, 0.3, size=2) * r, top, (0.6, 1.5), 0.3, 5.0)

    def walk(a: tuple[np.ndarray, float, float], b: tuple[np.ndarray, float, float]) -> None:
        """A plank walk 1.8 m wide from islet ``a`` (centre, radius, top) to ``b``, from 0.5 of a radius in."""
        along = (b[0] - a[0]) / np.linalg.norm(b[0] - a[0])
        s.ramp(a[0] + along * a[1] * 0.5, b[0] - along * b[1] * 0.5, 1.8, a[2], b[2])

    for k in range(14):
        if k == 0:
            first = (main + np.array([45.0, 0.0]), 1.5, 0.6)  # the jetty's end
        else:
            found = islet(None, 0.0)
            if found is None:
                continue
            first = found
            build(*first)
        members = [first]
        for _ in range(int(rng.integers(3, 7))):
            found = islet(members[-1][0], 16.0)
            if found is None:
                break
            build(*found)
            walk(members[-1], found)
            members.append(found)
    for _ in range(int(rng.integers(60, 81))):
        found = islet(None, 0.0)
        if found is not None:
            build(*found)
    return s.mesh()


def catacombs(seed: int) -> trimesh.Trimesh:
    """Catacombs cut in rock, one level under a lid (:func:`_lid`), 200-220 x 95-105 m: eight galleries along x,
    1.8-2.2 m wide and nearly the whole length, 10-13 m apart, joined by 4-7 cross passages (1.8 m) between each
    pair, staggered; burial niches 0.7 m deep and 2 m long on both sides of the galleries every 4-8 m; 12-16
    chambers 5-9 m square off the galleries (through a 1.8 m opening), a sarcophagus in some. Rock fills everything
    else (:meth:`_Solids.ground` with the open plan as holes, 2.8 m high); the floor lies under the open plan only.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = rng.uniform(200.0, 220.0), rng.uniform(95.0, 105.0)
    open_plan: list[tuple[float, float, float, float]] = []
    galleries = []
    z = 4.0
    while z < size_z - 6.0 and len(galleries) < 8:
        w = rng.uniform(1.8, 2.2)
        x0, x1 = rng.uniform(3.0, 12.0), size_x - rng.uniform(3.0, 12.0)
        galleries.append((x0, x1, z, z + w))
        open_plan.append((x0, x1, z, z + w))
        x = x0 + rng.uniform(2.0, 6.0)
        while x < x1 - 3.0:  # niches on both sides
            for zz in ((z - 0.7, z), (z + w, z + w + 0.7)):
                if rng.random() < 0.7:
                    open_plan.append((x, x + 2.0, *zz))
            x += rng.uniform(4.0, 8.0)
        z += w + rng.uniform(10.0, 13.0)
    for (a0, a1, az0, az1), (b0, b1, bz0, bz1) in pairwise(galleries):
        lo, hi = max(a0, b0) + 2.0, min(a1, b1) - 4.0
        for x in np.sort(rng.uniform(lo, hi, size=int(rng.integers(4, 8)))):
            open_plan.append((x, x + 1.8, az1, bz0))
    for _ in range(int(rng.integers(12, 17))):
        x0, x1, gz0, gz1 = galleries[int(rng.integers(0, len(galleries)))]
        side, w, d = rng.choice([-1.0, 1.0]), rng.uniform(5.0, 9.0), rng.uniform(5.0, 9.0)
        x = rng.uniform(x0 + 3.0, x1 - w - 3.0)
        z0 = gz1 + 1.0 if side > 0 else gz0 - 1.0 - d
        if z0 < 1.0 or z0 + d > size_z - 1.0:
            continue
        open_plan.append((x, x + w, z0, z0 + d))
        door = x + rng.uniform(0.5, w - 2.3)
        open_plan.append((door, door + 1.8, *sorted((z0 if side > 0 else z0 + d, gz1 if side > 0 else gz0))))
        if rng.random() < 0.5:
            s.box(x + w / 2 - 1.0, x + w / 2 + 1.0, 0.0, 0.9, z0 + d / 2 - 0.5, z0 + d / 2 + 0.5)
    for x0, x1, z0, z1 in open_plan:  # floor only where it is open: Recast would find floor inside the rock
        s.box(x0, x1, -0.3, 0.0, z0, z1)
    s.ground(0.0, size_x, 0.0, size_z, 2.8, open_plan, thickness=2.8)
    _lid(s, 0.0, size_x, 0.0, size_z, 3.8)
    return s.mesh()


def _sector(r0: float, r1: float, a0: float, a1: float) -> np.ndarray:
    """The plan (4, 2) of the ring sector between radii r0 < r1 and angles a0 < a1 (radians) about the origin,
    its arcs cut as chords."""
    return np.array([[r * math.cos(a), r * math.sin(a)] for r, a in ((r0, a0), (r1, a0), (r1, a1), (r0, a1))])


def helix(seed: int) -> trimesh.Trimesh:
    """A multi-storey car park that is one helical ramp: a deck from radius 9 m (a solid core) to 21-22 m that
    climbs 3.2 m a turn (a slope of about 2 degrees mid-deck) for six turns, in pieces of 7.5 degrees; a driving
    lane on the inner 7 m, parking bays on the outer side with cars (4.2 x 1.8 x 1.5 m) in 55-75 % of them,
    pillars 0.6 m square between lane and bays every 15 degrees, a parapet 1.1 m high on the outer edge. The deck
    starts on the ground (a plaza 80 m square round the core, which is floor under the first turn where it has
    head room) and ends 19.2 m up on a flat landing of 60 degrees joined to the core's flat top (the roof); no
    stairs: a walker goes the whole spiral.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    core, lane_out, outer, pitch, turns, pieces = 9.0, 16.0, rng.uniform(21.0, 22.0), 3.2, 6, 48
    step = 2 * math.pi / pieces
    occupied = rng.uniform(0.55, 0.75, size=turns)  # each turn's share of occupied bays
    top = pitch * turns
    for k in range(pieces):  # the plaza round the core, as sectors out to the square's edge (its corners on cut lines)
        a0, a1 = k * step, (k + 1) * step
        far = [40.0 / max(abs(math.cos(a)), abs(math.sin(a))) for a in (a0, a1)]
        plan = np.array([[core * math.cos(a0), core * math.sin(a0)], [far[0] * math.cos(a0), far[0] * math.sin(a0)],
                         [far[1] * math.cos(a1), far[1] * math.sin(a1)], [core * math.cos(a1), core * math.sin(a1)]])
        s.prism(plan, -0.5, 0.0)
    ring = np.array([[core * math.cos(k * step), core * math.sin(k * step)] for k in range(pieces)])
    s.prism(ring, -0.5, top)  # the core, its top the roof
    for t in range(turns):
        for k in range(pieces):
            a0, a1 = k * step, (k + 1) * step
            y0, y1 = pitch * (t + k / pieces), pitch * (t + (k + 1) / pieces)
            plan = _sector(core, outer, a0, a1)
            s.hull(np.array([[x, y + d, z] for (x, z), y in zip(plan, (y0, y0, y1, y1)) for d in (0.0, -0.3)]))
            wall = _sector(outer - 0.2, outer, a0, a1)
            s.hull(np.array([[x, y + d, z] for (x, z), y in zip(wall, (y0, y0, y1, y1)) for d in (0.0, 1.1)]))
            if k % 2 == 0:  # a pillar at the lane's outer edge, up to the deck above
                c = np.array([lane_out * math.cos(a0), lane_out * math.sin(a0)])
                s.prism(c + np.array([[-0.3, -0.3], [0.3, -0.3], [0.3, 0.3], [-0.3, 0.3]]), y0 - 0.3, y0 + pitch - 0.3)
            a = a0 + step / 2  # a bay a piece: 2.4 m of arc mid-bay, a car 1.8 m wide
            if rng.random() < occupied[t] and not (t == 0 and k < 3):
                y = pitch * (t + a / (2 * math.pi))
                radial, tangent = np.array([math.cos(a), math.sin(a)]), np.array([-math.sin(a), math.cos(a)])
                c = radial * (lane_out + 0.5 + outer - 0.2) / 2
                plan = np.array([c + radial * dr * 2.1 + tangent * dt * 0.9 for dr, dt in ((-1, -1), (1, -1), (1, 1), (-1, 1))])
                s.prism(plan, y - 0.3, y + 1.5)
    landing = 8
    for k in range(landing):  # the landing at the top, over the first sixth of the last turn
        s.prism(_sector(core - 0.01, outer, k * step, (k + 1) * step), top - 0.3, top)
        s.prism(_sector(outer - 0.2, outer, k * step, (k + 1) * step), top, top + 1.1)
    for _ in range(int(rng.integers(12, 20))):  # bollards on the plaza
        a, r = rng.uniform(0, 2 * math.pi), rng.uniform(outer + 3.0, 36.0)
        x, z = r * math.cos(a), r * math.sin(a)
        s.box(x - 0.15, x + 0.15, 0.0, 1.0, z - 0.15, z + 0.15)
    return s.mesh()


def _clear(x0: float, x1: float, z0: float, z1: float, rects: list[tuple[float, float, float, float]]) -> bool:
    """Whether the plan [x0, x1] x [z0, z1] keeps out of every rectangle (x0, x1, z0, z1) of ``rects``."""
    return not any(x0 < h[1] and h[0] < x1 and z0 < h[3] and h[2] < z1 for h in rects)


def _gable(s: _Solids, x0: float, x1: float, z0: float, z1: float, y: float) -> None:
    """A roof over [x0, x1] x [z0, z1] from height ``y`` up, ridged along x at 50 degrees: nothing on it is floor.
    As under :func:`_lid`, the top of a solid under it is floor with the roof's slopes as its ceiling unless it stops
    short of ``y`` by less than the agent's height: a solid under a gable stops 1 m below it."""
    ridge = y + (z1 - z0) / 2 * math.tan(math.radians(50.0))
    s.hull(np.array([[x, y, z] for x in (x0, x1) for z in (z0, z1)] + [[x, ridge, (z0 + z1) / 2] for x in (x0, x1)]))


def rooftops(seed: int) -> trimesh.Trimesh:
    """A rooftop run with no street: eight rows of terraced buildings along x (7-10 buildings 8-14 m wide, 12-16 m
    deep, sharing walls), rows 3-5 m apart (alleys with nothing in them). Roofs are flat, 8-20 m up (a row starts at
    11-17 m); along a row each roof is 0.1-0.35 m above or below the last (a step under the presets' 0.4 m climb)
    or, one time in four, 1-2.5 m (a drop, climbed by a flight 1.6 m wide against the higher wall in three of
    four), toward 14 m seven times in ten, so facing roofs of two rows are near in height; one roof in eight
    is gabled at 50 degrees (nothing to walk on). Across each alley 5-8 planks 1.8 m wide join facing flat roofs
    less than 2.5 m apart in height. On the roofs: chimneys, air-conditioning units, water tanks under cones and
    ridged skylights (no flat top out of reach).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    rows, z = [], 0.0
    for _ in range(8):
        depth = rng.uniform(12.0, 16.0)
        x, h, row = rng.uniform(0.0, 6.0), rng.uniform(11.0, 17.0), []
        for _ in range(int(rng.integers(7, 11))):
            width = rng.uniform(8.0, 14.0)
            gabled = rng.random() < 0.125
            row.append((x, x + width, z, z + depth, h, gabled))
            x += width
            toward = 1.0 if h < 14.0 else -1.0  # back toward 14 m seven times in ten, so rows stay near each other
            h = float(np.clip(h + (toward if rng.random() < 0.7 else -toward) * (
                rng.uniform(0.1, 0.35) if rng.random() < 0.75 else rng.uniform(1.0, 2.5)), 8.0, 20.0))
        rows.append(row)
        z += depth + rng.uniform(3.0, 5.0)
    for row in rows:
        for x0, x1, z0, z1, h, gabled in row:
            s.box(x0, x1, 0.0, h - 1.0 if gabled else h, z0, z1)
            if gabled:
                _gable(s, x0, x1, z0, z1, h)
                continue
            for _ in range(int(rng.integers(1, 4))):  # roof furniture at least 1 m in from the edges
                kind = rng.integers(0, 4)
                px, pz = rng.uniform(x0 + 1.0, x1 - 3.0), rng.uniform(z0 + 1.0, z1 - 3.0)
                if kind == 0:  # chimney
                    s.box(px, px + 0.9, h, h + 1.6, pz, pz + 0.9)
                elif kind == 1:  # air-conditioning unit
                    s.box(px, px + 1.6, h, h + 1.2, pz, pz + 1.0)
                elif kind == 2:  # water tank under a cone at 50 degrees (a first draft's flat top was floor out of reach)
                    a = np.linspace(0, 2 * math.pi, 10, endpoint=False)
                    ring = np.stack([px + 1.0 + np.cos(a), np.zeros(10), pz + 1.0 + np.sin(a)], 1)
                    s.hull(np.concatenate([ring + [0.0, h, 0.0], ring + [0.0, h + 2.5, 0.0],
                                           [[px + 1.0, h + 2.5 + math.tan(math.radians(50.0)), pz + 1.0]]]))
                else:  # skylight, ridged at 50 degrees
                    s.hull(np.array([[x, h, z] for x in (px, px + 1.4) for z in (pz, pz + 1.4)]
                                    + [[x, h + 0.7 * math.tan(math.radians(50.0)), pz + 0.7] for x in (px, px + 1.4)]))
        for (x0, x1, z0, z1, h, gabled), (_, _, _, _, h2, gabled2) in pairwise(row):
            if gabled or gabled2 or not 0.4 < abs(h2 - h) or rng.random() < 0.25:
                continue
            low, rise = min(h, h2), abs(h2 - h)  # a flight against the higher wall, climbing toward it
            heading = np.array([1.0, 0.0]) if h2 > h else np.array([-1.0, 0.0])
            steps = math.ceil(rise / 0.18)
            run = steps * 0.28
            zc = rng.uniform(z0 + 1.5, z1 - 1.5)
            start = np.array([x1 - run, zc]) if h2 > h else np.array([x1 + run, zc])
            s.stairs(start, heading, 1.6, low, rise, rise / steps, 0.28)
    for north, south in pairwise(rows):  # planks across each alley
        pairs = [(a, b) for a in north for b in south
                 if not a[5] and not b[5] and abs(a[4] - b[4]) < 2.5 and min(a[1], b[1]) - max(a[0], b[0]) > 3.0]
        for i in rng.choice(len(pairs), size=min(len(pairs), int(rng.integers(5, 9))), replace=False) if pairs else []:
            a, b = pairs[i]
            x = rng.uniform(max(a[0], b[0]) + 1.2, min(a[1], b[1]) - 1.2)
            s.ramp(np.array([x, a[3] - 0.3]), np.array([x, b[2] + 0.3]), 1.8, a[4], b[4], thickness=0.15)
    return s.mesh()


def flooded(seed: int) -> trimesh.Trimesh:
    """A flooded town: a grid of 6 x 4 blocks (22-32 x 18-26 m) between streets 9-11 m wide with no floor in
    them (the water is nothing to walk on). Each block is one building mass 9-15 m high under a gabled roof
    (:func:`_gable`), ringed by a pavement 2.4-2.8 m wide, 0.15 m up, broken in 0-2 places where it has
    collapsed (a gap 1.5-3 m long); lamp posts on the pavements' kerbs every 12-16 m. Duckboards 1.8 m wide cross
    the streets between facing pavements, 1-2 per street side in 80 % of them, landing at least 1 m from a collapse
    or a lamp post (a first draft landed some on a collapse, stranding them). One block in four has a shop
    (6-9 x 6 m) entered from its pavement through a 1.6 m door, its floor 0.3 m above the pavement, a counter
    inside.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    xs, x = [], 0.0
    for _ in range(6):
        w = rng.uniform(22.0, 32.0)
        xs.append((x, x + w))
        x += w + rng.uniform(9.0, 11.0)
    zs, z = [], 0.0
    for _ in range(4):
        d = rng.uniform(18.0, 26.0)
        zs.append((z, z + d))
        z += d + rng.uniform(9.0, 11.0)
    pave = rng.uniform(2.4, 2.8)
    kept_clear: list[tuple[float, float, float, float]] = []  # plans of collapses and lamp posts, 1 m round them

    for bx0, bx1 in xs:
        for bz0, bz1 in zs:
            x0, x1, z0, z1 = bx0 + pave, bx1 - pave, bz0 + pave, bz1 - pave  # the building inside its pavement
            height = rng.uniform(9.0, 15.0)
            shops = []
            if rng.random() < 0.25:
                w = rng.uniform(6.0, 9.0)
                sx = rng.uniform(x0 + 2.0, x1 - w - 2.0)
                shops.append((sx, sx + w, z0, z0 + 6.2))  # the mass stops at the front wall, door and all
                s.box(sx, sx + w, -1.0, 0.45, z0, z0 + 6.2)  # the shop's floor, 0.3 m above the pavement
                s.wall((sx, z0 + 0.1), (sx + w, z0 + 0.1), 0.45, height, [(w / 2 - 0.8, 1.6)])
                s.box(sx + 1.0, sx + w - 1.0, 0.45, 1.5, z0 + 4.6, z0 + 5.2)  # the counter
                kept_clear.append((sx + w / 2 - 2.0, sx + w / 2 + 2.0, bz0 - 1.0, z0))  # the pavement at its door
            s.ground(x0, x1, z0, z1, height - 1.0, shops, thickness=height)
            _gable(s, x0 - 0.3, x1 + 0.3, z0 - 0.3, z1 + 0.3, height)
            sides = [((bx0, bx1), (bz0, bz0 + pave), 0), ((bx0, bx1), (bz1 - pave, bz1), 0),
                     ((bx0, bx0 + pave), (bz0 + pave, bz1 - pave), 1), ((bx1 - pave, bx1), (bz0 + pave, bz1 - pave), 1)]
            collapsed = rng.choice(4, size=int(rng.integers(0, 3)), replace=False)
            for k, ((px0, px1), (pz0, pz1), along) in enumerate(sides):
                lo, hi = (px0, px1) if along == 0 else (pz0, pz1)

                def plan(a: float, b: float) -> tuple[float, float, float, float]:
                    """The plan of this pavement between a and b along it, 1 m wider each way."""
                    return (a - 1.0, b + 1.0, pz0 - 1.0, pz1 + 1.0) if along == 0 else (px0 - 1.0, px1 + 1.0, a - 1.0, b + 1.0)

                cuts = [lo, hi]
                if k in collapsed:
                    c, gap = rng.uniform(lo + 2.0, hi - 5.0), rng.uniform(1.5, 3.0)
                    if _clear(*plan(c, c + gap), kept_clear):  # never in front of a shop's door
                        cuts = [lo, c, c + gap, hi]
                        kept_clear.append(plan(c, c + gap))
                for c0, c1 in zip(cuts[0::2], cuts[1::2]):
                    if along == 0:
                        s.box(c0, c1, -1.0, 0.15, pz0, pz1)
                    else:
                        s.box(px0, px1, -1.0, 0.15, c0, c1)
                kerb = {0: pz0 + 0.2 if k == 0 else pz1 - 0.5, 1: px0 + 0.2 if k == 2 else px1 - 0.5}[along]
                for p in np.arange(lo + rng.uniform(3.0, 8.0), hi - 3.0, rng.uniform(12.0, 16.0)):
                    if _clear(*plan(p, p + 0.3), kept_clear):
                        kept_clear.append(plan(p, p + 0.3))
                        if along == 0:
                            s.box(p, p + 0.3, 0.15, 4.0, kerb, kerb + 0.3)
                        else:
                            s.box(kerb, kerb + 0.3, 0.15, 4.0, p, p + 0.3)
    for (a0, a1), (b0, b1) in pairwise(xs):  # duckboards across the streets along z, between blocks side by side
        for z0, z1 in zs:
            for _ in range(int(rng.integers(1, 3)) if rng.random() < 0.8 else 0):
                for _ in range(20):  # landing clear of collapses and lamp posts
                    zc = rng.uniform(z0 + 4.0, z1 - 4.0)
                    if _clear(a1 - 0.3, b0 + 0.3, zc - 0.9, zc + 0.9, kept_clear):
                        s.box(a1 - 0.3, b0 + 0.3, -0.5, 0.15, zc - 0.9, zc + 0.9)
                        break
    for (a0, a1), (b0, b1) in pairwise(zs):  # and across the streets along x
        for x0, x1 in xs:
            for _ in range(int(rng.integers(1, 3)) if rng.random() < 0.8 else 0):
                for _ in range(20):
                    xc = rng.uniform(x0 + 4.0, x1 - 4.0)
                    if _clear(xc - 0.9, xc + 0.9, a1 - 0.3, b0 + 0.3, kept_clear):
                        s.box(xc - 0.9, xc + 0.9, -0.5, 0.15, a1 - 0.3, b0 + 0.3)
                        break
    return s.mesh()


def cave(seed: int) -> trimesh.Trimesh:
    """A limestone cave under a lid (:func:`_lid`), ground on a 1 m grid (:func:`_terrain`) 150 x 110 m: 8-11
    chambers (ellipses 7-15 m in radius, their outlines wobbling by up to 1.5 m) joined by tunnels 3.5-5 m wide
    along a minimum spanning tree of the chambers' centres and 1-2 more; the floor rolls (each chamber's own
    height, -2 to 2 m, blended over 12 m, and bumps of up to 1.2 m, at most about 20 degrees) and rock rises
    outside the open plan in a step steeper than 60 degrees to a flat top 1 m under the lid, where no agent fits.
    In the open: 60-100 stalagmites (cones 0.3-1.0 m across the base, 1-3.5 m high), 10-18 columns from the floor
    to the rock's top (8-sided, 0.8-2 m in radius) and 20-30 boulders.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = 150.0, 110.0
    xs, zs = np.arange(0.0, size_x + 0.5, 1.0), np.arange(0.0, size_z + 0.5, 1.0)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    wanted, centres = int(rng.integers(8, 12)), []
    for _ in range(5000):  # rejection sampling, keeping fewer if the room runs out
        if len(centres) == wanted:
            break
        c = rng.uniform([18.0, 18.0], [size_x - 18.0, size_z - 18.0])
        if all(np.linalg.norm(c - d) > 26.0 for d in centres):
            centres.append(c)
    centres_a = np.array(centres)
    radii = rng.uniform(7.0, 15.0, size=(len(centres), 2))
    wobble = rng.uniform(0, 2 * math.pi, size=(2, 2))
    edge = 1.5 * np.sin(gx / 9.0 + wobble[0, 0]) * np.sin(gz / 7.0 + wobble[0, 1])  # outlines wobble by 1.5 m
    inside = np.zeros(gx.shape, dtype=bool)
    for c, (rx, rz) in zip(centres_a, radii):
        inside |= np.hypot((gx - c[0]) / rx, (gz - c[1]) / rz) * min(rx, rz) < min(rx, rz) + edge
    n = len(centres)
    dist = np.linalg.norm(centres_a[:, None] - centres_a[None], axis=2)
    tree, joined = [], {0}
    while len(joined) < n:  # Prim's minimum spanning tree of the centres
        i, j = min(((i, j) for i in joined for j in range(n) if j not in joined), key=lambda p: dist[p])
        tree.append((i, j))
        joined.add(j)
    extra = [(i, j) for i in range(n) for j in range(i + 1, n) if (i, j) not in tree and (j, i) not in tree]
    extra.sort(key=lambda p: dist[p])
    for i, j in tree + extra[:int(rng.integers(1, 3))]:
        a, b, half = centres_a[i], centres_a[j], rng.uniform(1.75, 2.5)
        ab = b - a
        t = np.clip(((gx - a[0]) * ab[0] + (gz - a[1]) * ab[1]) / (ab @ ab), 0.0, 1.0)
        inside |= np.hypot(gx - a[0] - t * ab[0], gz - a[1] - t * ab[1]) < half + 0.3 * edge
    bases = rng.uniform(-2.0, 2.0, size=n)
    weights = np.exp(-((gx[..., None] - centres_a[:, 0]) ** 2 + (gz[..., None] - centres_a[:, 1]) ** 2) / (2 * 12.0 ** 2))
    floor = (weights * bases).sum(-1) / np.maximum(weights.sum(-1), 1e-9)
    for _ in range(25):  # bumps
        c, sigma = rng.uniform([0.0, 0.0], [size_x, size_z]), rng.uniform(3.0, 8.0)
        floor += rng.uniform(-1.2, 1.2) * np.exp(-((gx - c[0]) ** 2 + (gz - c[1]) ** 2) / (2 * sigma ** 2))
    rock = float(floor.max()) + 4.0
    _terrain(s, xs, zs, np.where(inside, floor, rock))
    _lid(s, 0.0, size_x, 0.0, size_z, rock + 1.0)
    open_cells = np.argwhere(inside[1:-1, 1:-1]) + 1

    def spot(margin: int) -> tuple[float, float, float] | None:
        """A grid point of the open plan at least ``margin`` cells from rock, and its floor height."""
        for _ in range(50):
            i, j = open_cells[rng.integers(len(open_cells))]
            if inside[max(i - margin, 0):i + margin + 1, max(j - margin, 0):j + margin + 1].all():
                return float(xs[i]), float(zs[j]), float(floor[i, j])
        return None

    a8 = np.linspace(0, 2 * math.pi, 8, endpoint=False)
    for _ in range(int(rng.integers(60, 101))):  # stalagmites
        found = spot(2)
        if found is not None:
            x, z, y = found
            r, h = rng.uniform(0.15, 0.5), rng.uniform(1.0, 3.5)
            s.hull(np.concatenate([np.stack([x + r * np.cos(a8), np.full(8, y - 0.5), z + r * np.sin(a8)], 1), [[x, y + h, z]]]))
    for _ in range(int(rng.integers(10, 19))):  # columns
        found = spot(4)
        if found is not None:
            x, z, y = found
            r = rng.uniform(0.8, 2.0)
            s.prism(np.stack([x + r * np.cos(a8), z + r * np.sin(a8)], 1), y - 0.5, rock)
    for _ in range(int(rng.integers(20, 31))):  # boulders
        found = spot(3)
        if found is not None:
            x, z, y = found
            r = rng.uniform(0.5, 1.5)
            s.rock(rng, np.array([x, z]), r / 2, y - 0.5, y + r * 1.5)
    return s.mesh()


def _carriage(s: _Solids, x0: float, zc: float, floor: float, length: float, gangways: tuple[bool, bool]) -> None:
    """A passenger carriage from x0 along +x, ``length`` m long and 3 m wide about z = ``zc``, its floor at ``floor``:
    walls 0.1 m thick up to 2.25 m over the floor under a roof at 50 degrees (:func:`_gable`); at each end a
    vestibule 2.6 m long with a 1.6 m door in both sides and, where ``gangways`` (west, east) says so, a 1.6 m door in
    the end wall; a partition with a 1.6 m opening between each vestibule and the saloon, where seats (0.65 m deep
    across, 0.6 m along, 1.1 m high) line both walls every 1.9 m, leaving an aisle 1.5 m wide."""
    x1, z0, z1, top = x0 + length, zc - 1.5, zc + 1.5, floor + 2.25
    s.box(x0, x1, floor - 0.8, floor, z0, z1)
    for z in (z0 + 0.05, z1 - 0.05):
        s.wall((x0, z), (x1, z), floor, top, [(0.8, 1.6), (length - 2.4, 1.6)], thickness=0.1)
    for x, open_ in zip((x0 + 0.05, x1 - 0.05), gangways):
        s.wall((x, z0), (x, z1), floor, top, [(0.7, 1.6)] if open_ else [], thickness=0.1)
    for x in (x0 + 2.6, x1 - 2.6):
        s.wall((x, z0), (x, z1), floor, top, [(0.7, 1.6)], thickness=0.1)
    _gable(s, x0, x1, z0, z1, top)
    for x in np.arange(x0 + 3.2, x1 - 3.3, 1.9):
        for a, b in ((z0 + 0.1, z0 + 0.75), (z1 - 0.75, z1 - 0.1)):
            s.box(x, x + 0.6, floor, floor + 1.1, a, b)


def train(seed: int) -> trimesh.Trimesh:
    """A station of three platforms 1.1 m high (two 6 m wide on the sides, an island 8 m wide between two tracks
    with no floor in the track beds), 200-230 m long, a concourse 18 m deep across their west ends, and two trains
    standing in the station, 6-8 and 4-6 carriages 20 m long (:func:`_carriage`) 0.6 m apart, joined by gangways
    (a floor and two walls between the end doors), their floors 0.1 m above the platforms, a threshold over the
    0.2 m gap at every side door: each carriage joins the platforms either side and the next carriage. A
    footbridge 5.6 m above the platforms crosses the tracks, a flight up to it on each platform; benches, canopy
    pillars and vending machines on the platforms, ticket machines and a kiosk on the concourse.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length, deck = rng.uniform(200.0, 230.0), 1.1
    platforms = [(-6.0, 0.0), (3.4, 11.4), (14.8, 20.8)]
    tracks = [(0.0, 3.4), (11.4, 14.8)]
    for z0, z1 in platforms:
        s.box(0.0, length, -1.0, deck, z0, z1)
    s.box(-18.0, 0.0, -1.0, deck, -6.0, 20.8)  # the concourse
    s.wall((-18.0, -6.0), (-18.0, 20.8), deck, deck + 4.0, thickness=0.3)
    for _ in range(int(rng.integers(3, 6))):  # ticket machines
        x, z = rng.uniform(-16.0, -3.0), rng.uniform(-4.0, 18.0)
        s.box(x, x + 0.8, deck, deck + 1.6, z, z + 0.6)
    kx, kz = rng.uniform(-14.0, -6.0), rng.uniform(2.0, 12.0)
    s.box(kx, kx + 3.0, deck, deck + 1.6, kz, kz + 2.5)
    for z in (kz, kz + 2.5):
        s.wall((kx, z), (kx + 3.0, z), deck + 1.6, deck + 2.6, thickness=0.1)
    _gable(s, kx, kx + 3.0, kz, kz + 2.5, deck + 2.6)
    for (z0, z1), cars in zip(tracks, (int(rng.integers(6, 9)), int(rng.integers(4, 7)))):
        x = rng.uniform(4.0, length - cars * 20.6 - 4.0)
        zc = (z0 + z1) / 2
        for k in range(cars):
            _carriage(s, x, zc, deck + 0.1, 20.0, (k > 0, k < cars - 1))
            for dx in (0.8, 17.6):  # thresholds over the gaps at the side doors
                s.box(x + dx, x + dx + 1.6, deck - 0.3, deck + 0.1, z0, z1)
            if k < cars - 1:  # the gangway to the next carriage
                s.box(x + 20.0, x + 20.6, deck - 0.7, deck + 0.1, zc - 1.0, zc + 1.0)
                for z in (zc - 0.9, zc + 0.9):
                    s.box(x + 19.95, x + 20.65, deck + 0.1, deck + 2.35, z - 0.05, z + 0.05)
                _gable(s, x + 19.95, x + 20.65, zc - 1.0, zc + 1.0, deck + 2.35)
            x += 20.6
    bridge = rng.uniform(0.45, 0.7) * length
    top = deck + 5.6
    s.box(bridge, bridge + 3.0, top - 0.4, top, -5.0, 19.8)
    for z in (-5.0, 19.8):
        s.wall((bridge, z), (bridge + 3.0, z), top, top + 1.1, thickness=0.1)
    steps = math.ceil(5.6 / 0.17)
    for z0, z1 in platforms:  # a flight up to the bridge on each platform, along +x, ending at its west side
        s.stairs(np.array([bridge - steps * 0.28, (z0 + z1) / 2]), np.array([1.0, 0.0]), 2.0, deck, 5.6, 5.6 / steps, 0.28)
    for z0, z1 in platforms:
        zc = (z0 + z1) / 2
        for x in np.arange(rng.uniform(6.0, 10.0), length - 4.0, 10.0):  # canopy pillars and benches along the middle
            if abs(x - bridge + steps * 0.14) < steps * 0.14 + 3.0:
                continue
            s.box(x, x + 0.4, deck, deck + 4.0, zc - 0.2, zc + 0.2)
            if rng.random() < 0.5:
                s.box(x + 2.0, x + 3.8, deck, deck + 0.5, zc - 0.25, zc + 0.25)
            elif rng.random() < 0.3:
                s.box(x + 2.0, x + 3.0, deck, deck + 1.9, zc - 0.4, zc + 0.4)
    return s.mesh()


def ruins(seed: int) -> trimesh.Trimesh:
    """A three-storey building falling down, 56-64 x 36-42 m, storeys 3.6 m apart, no roof, in a yard 12 m wide
    all round: the floor slabs of the upper two storeys have 3-4 holes each (8-12 m along x or z, 4-7 m across,
    2 m or more apart), and into each hole a slab has fallen as a ramp from the hole's edge down to the storey
    below, 3-5.5 m wide: in the first two holes of each storey at 18-35 degrees (walkable), in the others at
    18-60 degrees (over 45 the presets' agent slides off). Storeys 0 and 1 are also joined by a switchback
    stairwell (:func:`_switchback`) in one corner; the stairs above it fell. Outer walls 0.3 m thick, 3-5 breaches
    2-5 m wide in the ground storey's and 2-4 in each upper storey's (openings onto a drop); columns 0.5 m square
    on a 6 m grid, one in five fallen; standing stretches of inner walls (4-12 m, 8-14 a storey) and rubble heaps.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, storey = rng.uniform(56.0, 64.0), rng.uniform(36.0, 42.0), 3.6
    s.box(-12.0, size_x + 12.0, -0.5, 0.0, -12.0, size_z + 12.0)
    well_x, well_z = 1.0, 1.0
    well = (well_x, well_x + 4.0, well_z + 2.0, well_z + _well_length(storey))
    _switchback(s, well_x, well_z, 0.0, storey)
    open_over: dict[int, list[tuple[float, float, float, float]]] = {0: []}  # each storey's holes (storey 1's: the well too)
    stairwell = (0.0, well_x + 5.0, 0.0, well[3] + 1.0)  # kept clear of inner walls and rubble
    for k in (1, 2):
        y = k * storey
        holes: list[tuple[float, float, float, float]] = [well] if k == 1 else []
        ramps, wanted = 0, int(rng.integers(3, 5))
        for _ in range(400):
            if ramps == wanted:
                break
            along_x = rng.random() < 0.5
            long, across = rng.uniform(8.0, 12.0), rng.uniform(4.0, 7.0)
            w, d = (long, across) if along_x else (across, long)
            x0, z0 = rng.uniform(2.0, size_x - w - 2.0), rng.uniform(2.0, size_z - d - 2.0)
            if not _clear(x0 - 2.0, x0 + w + 2.0, z0 - 2.0, z0 + d + 2.0, holes):
                continue
            holes.append((x0, x0 + w, z0, z0 + d))
            angle = math.radians(rng.uniform(18.0, 35.0) if ramps < 2 else rng.uniform(18.0, 60.0))
            angle = max(angle, math.atan2(storey, long - 0.3))  # the slab reaches the floor below inside the hole
            run = storey / math.tan(angle)
            width = rng.uniform(3.0, min(5.5, across - 0.6))
            if along_x:
                start, heading = np.array([x0, z0 + d / 2]), np.array([1.0, 0.0])
            else:
                start, heading = np.array([x0 + w / 2, z0]), np.array([0.0, 1.0])
            if rng.random() < 0.5:  # fallen from the other edge
                start, heading = start + heading * long, -heading
            s.ramp(start, start + heading * run, width, y, y - storey)
            ramps += 1
        s.slab(0.0, size_x, 0.0, size_z, y, holes)
        open_over[k] = holes
    for k in range(3):
        y = k * storey
        for a, b, along in (((0.0, 0.0), (size_x, 0.0), size_x), ((0.0, size_z), (size_x, size_z), size_x),
                            ((0.0, 0.0), (0.0, size_z), size_z), ((size_x, 0.0), (size_x, size_z), size_z)):
            breaches, starts = [], np.sort(rng.uniform(3.0, along - 8.0, size=int(rng.integers(1, 3 if k else 4))))
            for p in starts:
                if not breaches or p > breaches[-1][0] + breaches[-1][1] + 1.0:
                    breaches.append((float(p), float(rng.uniform(2.0, 5.0))))
            s.wall(a, b, y, y + storey - 0.3, breaches, thickness=0.3)
        for gx in np.arange(6.0, size_x - 3.0, 6.0):  # columns up to the slab above (none on the top storey)
            for gz in np.arange(6.0, size_z - 3.0, 6.0):
                if k < 2 and rng.random() >= 0.2:
                    s.box(gx - 0.25, gx + 0.25, y, y + storey - 0.3, gz - 0.25, gz + 0.25)
        for _ in range(int(rng.integers(8, 15))):  # inner walls on the grid lines, 4-12 m long
            n, high = rng.uniform(4.0, 12.0), y + storey - 0.3 if k < 2 else y + rng.uniform(1.0, 3.0)
            if rng.random() < 0.5:
                z, x = float(rng.choice(np.arange(6.0, size_z - 3.0, 6.0))), rng.uniform(0.0, size_x - n)
                if _clear(x, x + n, z - 0.1, z + 0.1, [stairwell, *open_over[k]]):
                    s.wall((x, z), (x + n, z), y, high)
            else:
                x, z = float(rng.choice(np.arange(6.0, size_x - 3.0, 6.0))), rng.uniform(0.0, size_z - n)
                if _clear(x - 0.1, x + 0.1, z, z + n, [stairwell, *open_over[k]]):
                    s.wall((x, z), (x, z + n), y, high)
        for _ in range(int(rng.integers(12, 21))):  # rubble
            r, p = rng.uniform(0.6, 1.6), rng.uniform([2.0, 2.0], [size_x - 2.0, size_z - 2.0])
            if _clear(p[0] - r, p[0] + r, p[1] - r, p[1] + r, [stairwell, *open_over[k]]):
                s.rock(rng, p, r / 2, y - 0.3, y + r)
    for _ in range(int(rng.integers(10, 16))):  # rubble in the yard
        side = rng.integers(0, 4)
        p = [np.array([rng.uniform(-10.0, size_x + 10.0), rng.uniform(-10.0, -2.0)]),
             np.array([rng.uniform(-10.0, size_x + 10.0), rng.uniform(size_z + 2.0, size_z + 10.0)]),
             np.array([rng.uniform(-10.0, -2.0), rng.uniform(0.0, size_z)]),
             np.array([rng.uniform(size_x + 2.0, size_x + 10.0), rng.uniform(0.0, size_z)])][side]
        r = rng.uniform(0.8, 2.0)
        s.rock(rng, p, r / 2, -0.3, r)
    return s.mesh()


def library(seed: int) -> trimesh.Trimesh:
    """A library of three storeys 4.5 m apart, 60-70 x 40-46 m, under a roof at 50 degrees (:func:`_lid`): a
    reading hall (20-26 x 14-18 m) in the middle open from the ground to the roof, with reading tables on its floor
    and a grand flight 2.5 m wide up to the first storey; round it on the upper storeys, galleries behind a rail
    1.1 m high; two switchback stairwells (:func:`_switchback`) in opposite corners join all three storeys. On every
    storey the wings east and west of the hall hold blocks of bookshelves 0.6 m deep, floor to ceiling, 5-9 m
    long, in rows along z with aisles 1.3-1.6 m wide between them and cross aisles 2 m wide; the upper storeys'
    strips north and south of the hall hold rows of shelves along z with a walk 3 m wide along the rail, and the
    ground storey's hold reading tables. A main aisle 6 m wide runs from the entrance (a 3 m door in the west wall,
    onto a forecourt) to the hall on every storey.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, storey = rng.uniform(60.0, 70.0), rng.uniform(40.0, 46.0), 4.5
    hw, hd = rng.uniform(10.0, 13.0), rng.uniform(7.0, 9.0)
    hall = (size_x / 2 - hw, size_x / 2 + hw, size_z / 2 - hd, size_z / 2 + hd)
    length = _well_length(storey)
    wells = [(0.5, 0.5), (size_x - 4.5, size_z - 0.5 - length)]
    open_wells = [(x, x + 4.0, z + 2.0, z + length) for x, z in wells]
    steps = math.ceil(storey / 0.18)
    run = steps * 0.28
    grand = (hall[1] - run, hall[1], hall[3] - 3.0, hall[3] - 0.5)
    kept = [(x - 2.5, x + 6.5, z - 2.5, z + length + 1.5) for x, z in wells]  # each well and an apron at its landing
    kept.append((0.0, hall[0], size_z / 2 - 3.0, size_z / 2 + 3.0))  # the main aisle
    s.box(-12.0, size_x, -0.5, 0.0, 0.0, size_z)  # the ground storey's floor and the forecourt
    for x, z in wells:
        _switchback(s, x, z, 0.0, storey)
        _switchback(s, x, z, storey, storey)
    s.stairs(np.array([grand[0], (grand[2] + grand[3]) / 2]), np.array([1.0, 0.0]), 2.5, 0.0, storey, storey / steps,
             0.28)

    def shelves(x0: float, x1: float, z0: float, z1: float, y: float) -> None:
        """Rows of shelves along z over the plan [x0, x1] x [z0, z1], from storey ``y`` up to the ceiling, an aisle
        all round the rows (so every aisle between two rows is open at both ends)."""
        aisle = rng.uniform(1.3, 1.6)
        for x in np.arange(x0 + aisle, x1 - 0.6 - aisle, 0.6 + aisle):
            z = z0 + 1.5
            while z < z1 - 3.5:
                n = min(rng.uniform(5.0, 9.0), z1 - 1.5 - z)
                if n > 2.0 and _clear(x, x + 0.6, z, z + n, kept):
                    s.box(x, x + 0.6, y, y + storey - 0.3, z, z + n)
                z += n + 2.0

    for k in range(3):
        y = k * storey
        if k:
            s.slab(0.0, size_x, 0.0, size_z, y, [hall, *open_wells])
            rail_gap = [(grand[2] - hall[2], grand[3] - grand[2])] if k == 1 else []
            s.wall((hall[1], hall[2]), (hall[1], hall[3]), y, y + 1.1, rail_gap)
            s.wall((hall[0], hall[2]), (hall[0], hall[3]), y, y + 1.1)
            for z in (hall[2], hall[3]):
                s.wall((hall[0], z), (hall[1], z), y, y + 1.1)
        top = y + storey - 0.3
        s.wall((0.0, 0.0), (0.0, size_z), y, top, [(size_z / 2 - 1.5, 3.0)] if k == 0 else [], thickness=0.3)
        s.wall((size_x, 0.0), (size_x, size_z), y, top, thickness=0.3)
        for z in (0.0, size_z):
            s.wall((0.0, z), (size_x, z), y, top, thickness=0.3)
        shelves(0.3, hall[0] - 3.0, 0.3, size_z - 0.3, y)
        shelves(hall[1] + 3.0, size_x - 0.3, 0.3, size_z - 0.3, y)
        if k:
            shelves(hall[0], hall[1], 0.3, hall[2] - 3.0, y)
            shelves(hall[0], hall[1], hall[3] + 3.0, size_z - 0.3, y)
    for z0, z1 in ((1.5, hall[2] - 2.0), (hall[2] + 2.0, hall[3] - 4.5), (hall[3] + 2.0, size_z - 1.5)):
        for x in np.arange(hall[0] + 2.0, hall[1] - 4.0, rng.uniform(5.0, 6.0)):  # reading tables, 3.6 x 1.2 m
            for z in np.arange(z0, z1 - 1.2, 3.4):
                if _clear(x, x + 3.6, z, z + 1.2, [grand]):
                    s.box(x, x + 3.6, 0.0, 0.75, z, z + 1.2)
    _lid(s, 0.0, size_x, 0.0, size_z, 3 * storey - 0.3)
    return s.mesh()


def trenches(seed: int) -> trimesh.Trimesh:
    """A battlefield 150-170 x 110-125 m of open ground with three lines of trench (front, support and reserve,
    each 2 m wide and 2.5 m deep, running along x 25-35 m apart): fire bays 8-11 m long between traverses, where
    the trench steps back 3 m round a block of earth 2.5 m wide. Zig-zag communication trenches (legs 7-10 m long
    along z, jogging 4 m along x) join neighbouring lines in 2-3 places; dugouts (5 x 3 m rooms under a roof 0.25
    m thick flush with the field, entered by a passage 1.6 m wide) open off the bays of the support and reserve
    lines; ramps at 23 degrees lead out of the trench, two over the front line's parapet and two behind the
    reserve line. Wire entanglements (1.2 m high, 6-16 m long) lie in front of the front line; shell-broken stumps
    and rubble on the field.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, depth = rng.uniform(150.0, 170.0), rng.uniform(110.0, 125.0), 2.5
    holes: list[tuple[float, float, float, float]] = []
    roofs: list[tuple[float, float, float, float]] = []
    bridges: list[tuple[float, float, float, float]] = []  # footbridges, so the field between trenches is reached
    lines = [rng.uniform(28.0, 34.0)]
    for _ in range(2):
        lines.append(lines[-1] + rng.uniform(25.0, 35.0))
    bays: list[list[tuple[float, float]]] = []  # each line's bays (x0, x1)
    for k, zl in enumerate(lines):
        x, row = 10.0, []
        while x < size_x - 25.0:
            bay = rng.uniform(8.0, 11.0)
            holes.append((x, x + bay, zl, zl + 2.0))
            row.append((x, x + bay))
            xa = x + bay  # the traverse: round a block of earth (xa + 2, xa + 4.5) x (zl, zl + 3)
            holes += [(xa, xa + 2.0, zl, zl + 5.0), (xa, xa + 6.5, zl + 3.0, zl + 5.0),
                      (xa + 4.5, xa + 6.5, zl, zl + 5.0)]
            x = xa + 6.5
        holes.append((x, x + rng.uniform(8.0, 11.0), zl, zl + 2.0))
        bays.append(row)
    for (za, zb), row in zip(pairwise(lines), bays):
        for _ in range(int(rng.integers(2, 4))):  # communication trenches from a bay down to a bay of the next line
            x0, x1 = row[int(rng.integers(len(row)))]
            x, z = rng.uniform(x0 + 1.0, x1 - 3.0), za + 2.0
            while zb - z > 12.0:
                leg = rng.uniform(7.0, 10.0)
                holes.append((x, x + 2.0, z, z + leg + 2.0))
                z += leg
                jog = 4.0 if rng.random() < 0.5 else -4.0
                holes.append((min(x, x + jog), max(x, x + jog) + 2.0, z, z + 2.0))
                x += jog
            b0, b1 = min(bays[lines.index(zb)], key=lambda b: abs((b[0] + b[1]) / 2 - x))
            xt = float(np.clip(x, b0 + 0.5, b1 - 2.5))  # the last leg lands in a bay, not on a traverse's block
            holes += [(min(x, xt), max(x, xt) + 2.0, z, z + 2.0), (xt, xt + 2.0, z, zb + 1.0)]
            bridges.append((xt - 1.0, xt + 3.0, (z + zb) / 2 - 1.0, (z + zb) / 2 + 1.0))  # over the last leg
    for k in (1, 2):  # dugouts behind the support and reserve lines' bays
        for x0, x1 in bays[k]:
            if rng.random() < 0.45:
                xm, zl = (x0 + x1) / 2, lines[k]
                holes += [(xm - 0.8, xm + 0.8, zl + 2.0, zl + 3.5), (xm - 2.5, xm + 2.5, zl + 3.5, zl + 6.5)]
                roofs += [(xm - 0.8, xm + 0.8, zl + 2.0, zl + 3.5), (xm - 2.5, xm + 2.5, zl + 3.5, zl + 6.5)]
    for x0, x1, z0, z1 in holes:
        s.box(x0, x1, -depth - 0.5, -depth, z0, z1)
    exits = [(0, -1.0), (0, -1.0), (2, 1.0), (2, 1.0)]  # (line, side: -1 toward the front, +1 behind)
    for k, side in exits:
        x0, x1 = bays[k][int(rng.integers(len(bays[k])))]
        xm = rng.uniform(x0 + 1.5, x1 - 1.5)
        edge = lines[k] if side < 0 else lines[k] + 2.0
        far = edge + side * depth / math.tan(math.radians(23.0))
        holes.append((xm - 1.0, xm + 1.0, min(edge, far), max(edge, far)))
        s.ramp(np.array([xm, edge]), np.array([xm, far]), 2.0, -depth, 0.0, thickness=depth)
    for x0, x1, z0, z1 in roofs:
        s.box(x0, x1, -0.25, 0.0, z0, z1)
    for x0, x1, z0, z1 in bridges:
        s.box(x0, x1, -0.2, 0.1, z0, z1)
    s.ground(0.0, size_x, 0.0, size_z, 0.0, holes, thickness=depth)
    for _ in range(int(rng.integers(8, 13))):  # wire in front of the front line
        x, z, n = rng.uniform(5.0, size_x - 20.0), rng.uniform(4.0, lines[0] - 10.0), rng.uniform(6.0, 16.0)
        s.box(x, x + n, 0.0, 1.2, z, z + 0.6)
    for _ in range(int(rng.integers(20, 31))):  # stumps and rubble, clear of the trenches
        p, r = rng.uniform([3.0, 3.0], [size_x - 3.0, size_z - 3.0]), rng.uniform(0.4, 1.2)
        if _clear(p[0] - r - 1.0, p[0] + r + 1.0, p[1] - r - 1.0, p[1] + r + 1.0, holes):
            s.rock(rng, p, r / 2, -0.3, r * 1.5)
    return s.mesh()


def _round_ground(s: _Solids, c: np.ndarray, r: float, sides: int, top: float) -> tuple[float, float, float, float]:
    """Ground 0.5 m thick, its top at ``top``, between the regular ``sides``-gon of radius ``r`` about the plan point
    ``c`` (x, z; its first corner on +x) and the square round it, in one piece a side (``sides`` a multiple of 8,
    so the square's corners lie on its rays). Returns the square (x0, x1, z0, z1), a hole to leave in
    :meth:`_Solids.ground`: under a round solid standing there the ground stops (Recast would find floor inside it)."""
    a = np.arange(sides + 1) * 2 * math.pi / sides
    unit = np.stack([np.cos(a), np.sin(a)], 1)
    far = unit / np.abs(unit).max(axis=1, keepdims=True)
    for k in range(sides):
        s.prism(c + r * np.array([unit[k], far[k], far[k + 1], unit[k + 1]]), top - 0.5, top)
    return c[0] - r, c[0] + r, c[1] - r, c[1] + r


def refinery(seed: int) -> trimesh.Trimesh:
    """A refinery's plant yard 140-160 x 100-115 m cut into six fields by pipe runs 0.9 m high and 1.2 m deep (two
    along x, one along z, edge to edge), crossed only by crossover stairs (1.6 m wide, 1.2 m up, a platform over
    the run, down the other side) every 18-35 m. In the fields north and south: storage tanks 6-9 m in radius and
    8-12 m high, their flat roofs floor, each reached by a stair 2 m wide wound round its shell (risers under
    0.18 m, treads 0.28 m at mid-stair, steps 0.45 m deep) ending on a landing 1.5 m long (without it the last
    step alone did not join the roof for the presets' agent). In the middle field: a pipe-rack catwalk 2.4 m
    wide, 5 m up on posts, crossing the run along z, a flight up at each end; process columns (0.8-2 m in radius,
    15-35 m high under 50-degree cones), heat exchangers under ridged tops, pumps, and a control room one enters
    (14 x 9 m, a 1.6 m door, a desk). The ground stops under the tanks and columns (:func:`_round_ground`).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = rng.uniform(140.0, 160.0), rng.uniform(100.0, 115.0)
    under: list[tuple[float, float, float, float]] = []  # squares round the round solids, no ground there
    runs_z = [size_z * rng.uniform(0.32, 0.36), size_z * rng.uniform(0.64, 0.68)]  # pipe runs along x at these z
    run_x = size_x * rng.uniform(0.45, 0.55)  # and one along z
    for z in runs_z:
        s.box(0.0, size_x, 0.0, 0.9, z, z + 1.2)
    s.box(run_x, run_x + 1.2, 0.0, 0.9, 0.0, size_z)
    flight = 7 * 0.28
    kept = [(0.0, size_x, z - flight - 1.0, z + 1.2 + flight + 1.0) for z in runs_z]
    kept.append((run_x - flight - 1.0, run_x + 1.2 + flight + 1.0, 0.0, size_z))

    def crossover(p: np.ndarray, across: np.ndarray) -> None:
        """Stairs up to a platform over a run and down again: ``p`` (x, z) the middle of the run's near edge,
        ``across`` the unit plan vector across it."""
        far = p + across * 1.2
        s.stairs(p - across * flight, across, 1.6, 0.0, 1.2, 1.2 / 7, 0.28)
        s.prism(_strip(p, far, 1.6), 0.9, 1.2)
        s.stairs(far + across * flight, -across, 1.6, 0.0, 1.2, 1.2 / 7, 0.28)

    for z in runs_z:
        for x in np.arange(rng.uniform(6.0, 14.0), size_x - 6.0, rng.uniform(18.0, 30.0)):
            if abs(x - run_x - 0.6) > 5.0:
                crossover(np.array([x, z]), np.array([0.0, 1.0]))
    for z in np.arange(rng.uniform(6.0, 12.0), size_z - 6.0, rng.uniform(20.0, 35.0)):
        if all(abs(z - r - 0.6) > 5.0 for r in runs_z):
            crossover(np.array([run_x, z]), np.array([1.0, 0.0]))
    a24 = np.linspace(0, 2 * math.pi, 24, endpoint=False)
    circle = np.stack([np.cos(a24), np.sin(a24)], 1)
    for z0, z1 in ((0.0, runs_z[0]), (runs_z[1] + 1.2, size_z)):  # tanks in the south and north fields
        x = rng.uniform(2.0, 8.0)
        while True:
            r = rng.uniform(6.0, 9.0)
            if z1 - z0 < 2 * r + 10.0:
                r = (z1 - z0 - 10.0) / 2
            cx = x + r + 2.5
            if abs(cx - run_x - 0.6) < r + 5.0:
                x = run_x + 1.2 + 3.0
                continue
            if cx + r + 5.0 > size_x:
                break
            c = np.array([cx, rng.uniform(z0 + r + 5.0, z1 - r - 5.0)])
            height = rng.uniform(8.0, 12.0)
            s.prism(c + r * circle, -0.3, height)
            under.append(_round_ground(s, c, r, 24, 0.0))
            steps = math.ceil(height / 0.18)
            turn, a0 = (1.0 if rng.random() < 0.5 else -1.0) * 0.28 / (r + 1.0), rng.uniform(0, 2 * math.pi)
            for i in range(steps):  # the stair wound round the shell, each step a block 0.45 m deep
                a, b = sorted((a0 + turn * i, a0 + turn * (i + 1)))
                y = height * (i + 1) / steps
                s.prism(c + _sector(r - 0.2, r + 2.0, a, b), y - 0.45, y)
            a, b = sorted((a0 + turn * steps, a0 + turn * (steps + 1.5 / 0.28)))  # a landing 1.5 m long at the top
            s.prism(c + _sector(r - 0.2, r + 2.0, a, b), height - 0.45, height)
            x = cx + r + rng.uniform(5.0, 9.0)
    zc = (runs_z[0] + runs_z[1] + 1.2) / 2 + rng.uniform(-3.0, 3.0)  # the catwalk across the middle field
    xa, xb = rng.uniform(14.0, run_x - 20.0), rng.uniform(run_x + 20.0, size_x - 14.0)
    s.box(xa, xb, 4.7, 5.0, zc - 1.2, zc + 1.2)
    for x in np.arange(xa + 0.5, xb, 6.0):
        for z in (zc - 1.2, zc + 0.9):
            s.box(x - 0.15, x + 0.15, 0.0, 4.7, z, z + 0.3)
    steps = math.ceil(5.0 / 0.18)
    run = steps * 0.28
    s.stairs(np.array([xa - run, zc]), np.array([1.0, 0.0]), 2.0, 0.0, 5.0, 5.0 / steps, 0.28)
    s.stairs(np.array([xb + run, zc]), np.array([-1.0, 0.0]), 2.0, 0.0, 5.0, 5.0 / steps, 0.28)
    kept.append((xa - run - 1.5, xb + run + 1.5, zc - 2.5, zc + 2.5))
    rx, rz = rng.uniform(3.0, 8.0), runs_z[0] + 4.5
    room = (rx, rx + 14.0, rz, rz + 9.0)
    if _clear(*room, kept[-1:]):
        s.wall((room[0], room[2]), (room[1], room[2]), 0.0, 3.5, [(6.2, 1.6)])
        s.wall((room[0], room[3]), (room[1], room[3]), 0.0, 3.5)
        for x in room[:2]:
            s.wall((x, room[2]), (x, room[3]), 0.0, 3.5)
        s.box(room[0] + 3.0, room[1] - 3.0, 0.0, 0.8, room[3] - 3.0, room[3] - 2.0)  # the desk
        _gable(s, room[0] - 0.2, room[1] + 0.2, room[2] - 0.2, room[3] + 0.2, 3.5)
        kept.append((room[0] - 1.0, room[1] + 1.0, room[2] - 3.0, room[3] + 1.0))
    z_lo, z_hi = runs_z[0] + 1.2, runs_z[1]
    placed = 0
    for _ in range(300):  # process columns, exchangers and pumps in the middle field
        if placed == 24:
            break
        kind = 0 if placed < 5 else (1 if placed < 10 else 2)
        w, d = ((4.2, 4.2) if kind == 0 else (6.0, 1.6) if kind == 1 else (1.4, 0.9))
        x, z = rng.uniform(2.0, size_x - w - 2.0), rng.uniform(z_lo + 1.0, z_hi - d - 1.0)
        if not _clear(x - 1.0, x + w + 1.0, z - 1.0, z + d + 1.0, kept):
            continue
        kept.append((x - 1.0, x + w + 1.0, z - 1.0, z + d + 1.0))
        placed += 1
        if kind == 0:
            r, h = rng.uniform(0.8, 2.0), rng.uniform(15.0, 35.0)
            under.append(_round_ground(s, np.array([x + 2.1, z + 2.1]), r, 8, 0.0))
            ring = np.insert(np.array([x + 2.1, z + 2.1]) + r * circle[::3], 1, -0.3, axis=1)
            apex = [[x + 2.1, h + r * math.tan(math.radians(50.0)), z + 2.1]]
            s.hull(np.concatenate([ring, ring + [0.0, h, 0.0], apex]))
        elif kind == 1:
            s.box(x, x + w, 0.0, 1.0, z, z + d)
            _gable(s, x, x + w, z, z + d, 2.0)
        else:
            s.box(x, x + w, 0.0, 1.2, z, z + d)
    s.ground(0.0, size_x, 0.0, size_z, 0.0, under)
    return s.mesh()


def cemetery(seed: int) -> trimesh.Trimesh:
    """A walled cemetery 100-120 x 80-90 m (walls 2.5 m high, two gates 3 m wide in the south wall and one in the
    east): a main path 5 m wide from the south to a chapel at the north end, a cross path 4 m wide, a path 3.5 m
    wide inside the walls and secondary paths 2.5 m wide cut the ground into 16 plots. Each plot holds rows of
    graves along x (a ledger 0.9 x 2 m, 0.5 m high, and a headstone to 1.1 m, 1.5 m apart along a row, too close
    to pass between) with lanes 1.6 m wide between the rows; one grave in eight is missing (a way across to the
    next lane) and one in twelve carries an obelisk (under a 50-degree point) on its ledger instead of a
    headstone. Four to six mausoleums (4 x 5 m, a 1.6 m door, a sarcophagus) stand in plots; trees and benches
    line the main path. The chapel (12 x 16 m, a 2.4 m
    door, pews either side of an aisle, an altar) has a flight down to a crypt 3.5 m below: a corridor 2.5 m wide
    under the plots west of it with chambers 3 x 3 m on its south side, a sarcophagus in each.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = rng.uniform(100.0, 120.0), rng.uniform(80.0, 90.0)
    xm, zc = size_x / 2, size_z * rng.uniform(0.42, 0.5)
    chapel = (xm - 6.0, xm + 6.0, size_z - 20.0, size_z - 4.0)
    steps = math.ceil(3.5 / 0.18)
    run = steps * 0.28
    sx, sz = chapel[1] - 2.0, chapel[3] - 2.0 - run  # the crypt's flight, along +z up to the chapel's floor
    flight = (sx - 0.9, sx + 0.9, sz, sz + run)
    corridor = (rng.uniform(8.0, 20.0), sx + 0.9, sz - 2.5, sz)
    chambers = [(x, x + 3.0, sz - 5.5, sz - 2.5) for x in np.arange(corridor[0] + 1.0, corridor[1] - 4.0, 6.0)]
    crypt = [corridor, *chambers]
    s.ground(-2.0, size_x + 2.0, -2.0, size_z + 2.0, 0.0, [*crypt, flight], thickness=0.5)
    for x0, x1, z0, z1 in crypt:
        s.box(x0, x1, -4.0, -3.5, z0, z1)
        s.box(x0, x1, -0.3, 0.0, z0, z1)
    s.stairs(np.array([sx, sz]), np.array([0.0, 1.0]), 1.8, -3.5, 3.5, 3.5 / steps, 0.28)
    for x0, x1, z0, z1 in chambers:
        s.box(x0 + 0.5, x1 - 0.5, -3.5, -2.7, z0 + 0.5, z0 + 1.4)
    s.wall((0.0, 0.0), (size_x, 0.0), 0.0, 2.5, [(rng.uniform(12.0, 25.0), 3.0), (xm - 1.5, 3.0)], thickness=0.5)
    s.wall((0.0, size_z), (size_x, size_z), 0.0, 2.5, thickness=0.5)
    s.wall((0.0, 0.0), (0.0, size_z), 0.0, 2.5, thickness=0.5)
    s.wall((size_x, 0.0), (size_x, size_z), 0.0, 2.5, [(zc - 1.5, 3.0)], thickness=0.5)
    top = 6.0  # the chapel
    s.wall((chapel[0], chapel[2]), (chapel[1], chapel[2]), 0.0, top, [(4.8, 2.4)], thickness=0.3)
    s.wall((chapel[0], chapel[3]), (chapel[1], chapel[3]), 0.0, top, thickness=0.3)
    for x in chapel[:2]:
        s.wall((x, chapel[2]), (x, chapel[3]), 0.0, top, thickness=0.3)
    _gable(s, chapel[0] - 0.3, chapel[1] + 0.3, chapel[2] - 0.3, chapel[3] + 0.3, top)
    for z in np.arange(chapel[2] + 2.0, chapel[3] - 6.0, 1.1):  # pews either side of a 2 m aisle
        s.box(chapel[0] + 1.0, xm - 1.0, 0.0, 0.45, z, z + 0.5)
        s.box(xm + 1.0, chapel[1] - 3.5, 0.0, 0.45, z, z + 0.5)
    s.box(xm - 1.5, xm + 1.5, 0.0, 1.0, chapel[3] - 3.0, chapel[3] - 2.0)  # the altar
    cols = [3.5, xm - 2.5, xm + 2.5, size_x - 3.5]
    rows = [3.5, zc - 2.0, zc + 2.0, size_z - 3.5]
    splits_x = [(a, a + rng.uniform(0.4, 0.6) * (b - a)) for a, b in pairwise(cols) if b - a > 10.0]
    splits_z = [(a, a + rng.uniform(0.4, 0.6) * (b - a)) for a, b in pairwise(rows) if b - a > 10.0]
    plots = []
    for (a, b), (_, cut) in zip([(cols[0], cols[1]), (cols[2], cols[3])], splits_x):
        for x0, x1 in ((a, cut - 1.25), (cut + 1.25, b)):
            for (c, d), (_, cz) in zip([(rows[0], rows[1]), (rows[2], rows[3])], splits_z):
                for z0, z1 in ((c, cz - 1.25), (cz + 1.25, d)):
                    plots.append((x0, x1, z0, z1))
    kept = [(chapel[0] - 3.0, chapel[1] + 3.0, chapel[2] - 3.0, size_z)]
    for i in rng.choice(len(plots), size=int(rng.integers(4, 7)), replace=False):  # mausoleums
        x0, _, z0, _ = plots[i]
        x0 += rng.uniform(0.5, 4.0)
        s.wall((x0, z0 + 0.1), (x0 + 4.0, z0 + 0.1), 0.0, 3.0, [(1.2, 1.6)])
        s.wall((x0, z0 + 5.0), (x0 + 4.0, z0 + 5.0), 0.0, 3.0)
        for x in (x0 + 0.1, x0 + 3.9):
            s.wall((x, z0), (x, z0 + 5.0), 0.0, 3.0)
        _gable(s, x0 - 0.2, x0 + 4.2, z0 - 0.1, z0 + 5.2, 3.0)
        s.box(x0 + 1.2, x0 + 2.8, 0.0, 0.9, z0 + 3.2, z0 + 4.4)
        kept.append((x0 - 1.0, x0 + 5.0, z0 - 1.0, z0 + 6.0))
    for x0, x1, z0, z1 in plots:  # graves
        for z in np.arange(z0 + 0.3, z1 - 2.0, 3.6):
            for x in np.arange(x0 + 0.3, x1 - 0.9, 1.5):
                if rng.random() < 0.125 or not _clear(x, x + 0.9, z, z + 2.0, kept):
                    continue
                s.box(x, x + 0.9, 0.0, 0.5, z, z + 2.0)  # the ledger, under an obelisk too (alone, an obelisk left
                # notches 0.5 m deep either side of it in the row, which the cover took for dead ends)
                if rng.random() < 1 / 12:
                    point = [[x + 0.45, 2.0 + 0.45 * math.tan(math.radians(50.0)), z + 0.95]]
                    s.hull(np.array([[px, y, pz] for px in (x, x + 0.9) for pz in (z + 0.5, z + 1.4)
                                     for y in (0.5, 2.0)] + point))
                else:
                    s.box(x + 0.05, x + 0.85, 0.5, 1.1, z, z + 0.15)
    octagon = np.stack([np.cos(np.arange(8) * math.pi / 4), np.sin(np.arange(8) * math.pi / 4)], 1)
    for z in np.arange(8.0, chapel[2] - 4.0, rng.uniform(9.0, 12.0)):  # trees and benches along the main path
        if abs(z - zc) > 4.0:
            for x in (xm - 2.4, xm + 2.0):
                s.prism(np.array([x + 0.2, z]) + 0.35 * octagon, 0.0, 9.0)
            s.box(xm - 2.3, xm - 1.8, 0.0, 0.45, z + 3.0, z + 4.8)
    return s.mesh()


def quarry(seed: int) -> trimesh.Trimesh:
    """An open-pit quarry 150-170 x 110-120 m at the rim: five benches 4 m below one another (faces vertical, each
    bench 8-11 m wide on each side, the bottom 35-60 m across with a pond in it, no floor over the water), joined
    only by a haul road 7 m wide at 9 degrees: one ramp a bench, lying on the lower bench along its outer face,
    alternately on the north and south faces and heading alternately east and west. Safety berms (rocks 1-1.8 m
    high every 2.8-4 m) line each bench's drop, cut where a ramp meets it; 2-4 haul trucks and excavators (9 x 5
    or 6 x 3.5 m) under ridged tops and 12-18 rock piles on each bench and the bottom; a yard 25 m wide round the
    rim with five stockpiles (cones at 38 degrees, which a walker climbs), a site office and a crusher. The ground
    stops under every ramp, machine and stockpile (Recast would find floor inside them).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, rise = rng.uniform(150.0, 170.0), rng.uniform(110.0, 120.0), 4.0
    rects = [(0.0, size_x, 0.0, size_z)]  # each level's outline below the rim: bench k is rects[k - 1] less rects[k]
    for _ in range(4):
        x0, x1, z0, z1 = rects[-1]
        w = rng.uniform(8.0, 11.0, size=4)
        rects.append((x0 + w[0], x1 - w[1], z0 + w[2], z1 - w[3]))
    bottom = rects[-1]
    pond_w, pond_d = rng.uniform(0.3, 0.45) * (bottom[1] - bottom[0]), rng.uniform(0.25, 0.35) * (bottom[3] - bottom[2])
    px = rng.uniform(bottom[0] + 4.0, bottom[1] - pond_w - 4.0)
    pz = (bottom[2] + bottom[3] - pond_d) / 2
    kept = [(px, px + pond_w, pz, pz + pond_d)]
    under: list[list[tuple[float, float, float, float]]] = [[rects[0]], *([r] for r in rects[1:]), [kept[0]]]
    length = rise / math.tan(math.radians(9.0))
    for k, (x0, x1, z0, z1) in enumerate(rects):  # the ramp from level k (0: the rim) down to level k + 1
        start = rng.uniform(x0 + 6.0, x1 - 6.0 - length)
        a, b = (start, start + length) if k % 4 < 2 else (start + length, start)
        z = z0 + 3.5 if k % 2 == 0 else z1 - 3.5
        s.ramp(np.array([a, z]), np.array([b, z]), 7.0, -rise * k, -rise * (k + 1), thickness=rise)
        under[k + 1].append((min(a, b), max(a, b), z - 3.5, z + 3.5))
        kept += [(min(a, b) - 1.0, max(a, b) + 1.0, z - 4.5, z + 4.5), (a - 3.0, a + 3.0, z - 6.0, z + 6.0)]
    for k in range(len(rects) - 1):  # berms along each level's drop into the next, clear of the ramps' ends
        x0, x1, z0, z1 = rects[k + 1]
        y = -rise * k
        for p in np.arange(x0 + rng.uniform(0.0, 3.0), x1, rng.uniform(2.8, 4.0)):
            for z in (z0 - 1.5, z1 + 1.5):
                if _clear(p - 1.0, p + 1.0, z - 1.0, z + 1.0, kept):
                    s.rock(rng, np.array([p, z]), 0.35, y - 0.3, y + rng.uniform(1.0, 1.8))
        for q in np.arange(z0 + rng.uniform(0.0, 3.0), z1, rng.uniform(2.8, 4.0)):
            for x in (x0 - 1.5, x1 + 1.5):
                if _clear(x - 1.0, x + 1.0, q - 1.0, q + 1.0, kept):
                    s.rock(rng, np.array([x, q]), 0.35, y - 0.3, y + rng.uniform(1.0, 1.8))
    for k in range(1, len(rects) + 1):  # machines and rock piles on the benches and the bottom
        outer, inner = rects[k - 1], rects[k] if k < len(rects) else None
        y = -rise * k
        for _ in range(int(rng.integers(2, 5))):
            for _ in range(30):
                w, d = (9.0, 5.0) if rng.random() < 0.5 else (6.0, 3.5)
                x, z = rng.uniform(outer[0] + 3.0, outer[1] - w - 3.0), rng.uniform(outer[2] + 3.0, outer[3] - d - 3.0)
                if inner is not None and not _clear(x - 3.0, x + w + 3.0, z - 3.0, z + d + 3.0, [inner]):
                    continue
                if _clear(x - 2.0, x + w + 2.0, z - 2.0, z + d + 2.0, kept):
                    s.box(x, x + w, y - 0.3, y + 2.0, z, z + d)  # 1 m under its top, as under any gable
                    _gable(s, x, x + w, z, z + d, y + 3.0)
                    under[k].append((x, x + w, z, z + d))
                    kept.append((x - 2.0, x + w + 2.0, z - 2.0, z + d + 2.0))
                    break
        for _ in range(int(rng.integers(12, 19))):  # rock piles
            r = rng.uniform(0.8, 2.0)
            x, z = rng.uniform(outer[0] + 2.0, outer[1] - 2.0), rng.uniform(outer[2] + 2.0, outer[3] - 2.0)
            if (inner is None or _clear(x - r - 2.0, x + r + 2.0, z - r - 2.0, z + r + 2.0, [inner])) and \
                    _clear(x - r - 1.0, x + r + 1.0, z - r - 1.0, z + r + 1.0, kept):
                s.rock(rng, np.array([x, z]), r / 2, y - 0.3, y + r)
                kept.append((x - r - 1.0, x + r + 1.0, z - r - 1.0, z + r + 1.0))
    a16 = np.linspace(0, 2 * math.pi, 16, endpoint=False)
    ring = np.stack([np.cos(a16), np.sin(a16)], 1)
    yard = [(-25.0, size_x + 25.0, -25.0, -3.0), (-25.0, size_x + 25.0, size_z + 3.0, size_z + 25.0)]
    placed = 0
    for _ in range(200):  # stockpiles, a site office and a crusher in the yard, north and south of the pit
        if placed == 7:
            break
        x0, x1, z0, z1 = yard[int(rng.integers(2))]
        r = rng.uniform(4.0, 7.0)
        x, z = rng.uniform(x0 + r + 2.0, x1 - r - 2.0), rng.uniform(z0 + r + 2.0, z1 - r - 2.0)
        if not _clear(x - r - 2.0, x + r + 2.0, z - r - 2.0, z + r + 2.0, kept):
            continue
        kept.append((x - r - 2.0, x + r + 2.0, z - r - 2.0, z + r + 2.0))
        if placed < 5:
            base = np.insert(np.array([x, z]) + r * ring, 1, -0.3, axis=1)
            s.hull(np.concatenate([base, [[x, r * math.tan(math.radians(38.0)), z]]]))
            under[0].append(_round_ground(s, np.array([x, z]), r, 16, 0.0))
        else:
            s.box(x - r, x + r, -0.3, 3.0, z - r / 2, z + r / 2)
            _gable(s, x - r, x + r, z - r / 2, z + r / 2, 4.0)
            under[0].append((x - r, x + r, z - r / 2, z + r / 2))
        placed += 1
    s.ground(-25.0, size_x + 25.0, -25.0, size_z + 25.0, 0.0, under[0], thickness=rise)
    for k, r in enumerate(rects):
        s.ground(*r, -rise * (k + 1), under[k + 1], thickness=rise)
    return s.mesh()


def stairhall(seed: int) -> trimesh.Trimesh:
    """A hall 58 m square whose only floors above the ground are landings: a 6 x 6 grid of landings 4 m square,
    3-12 m up (3 m a level), each on four posts, 4.76 m apart, joined only by flights (17 risers of 0.176 m, 0.28 m
    treads, 2 m wide, blocks 0.45 m deep, so one walks under them) between neighbours a level apart and flat bridges
    between neighbours at one level. The landings' levels grow as a spanning tree from three or four landings at 3
    m reached by solid flights from the hall's floor (each landing a level above, at, or below the one it is
    reached from, upward twice as often), so every landing is reached; a quarter of the other pairs a level apart
    or less are joined as well. Walls 16 m high close the hall, open to the sky; planters on its floor.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    n, margin, size, storey = 6, 5.0, 4.0, 3.0
    steps = math.ceil(storey / 0.18)
    run = steps * 0.28
    pitch = size + run
    side = 2 * margin + n * size + (n - 1) * run
    s.box(0.0, side, -0.5, 0.0, 0.0, side)
    for a, b in (((0.0, 0.0), (side, 0.0)), ((0.0, side), (side, side)), ((0.0, 0.0), (0.0, side)),
                 ((side, 0.0), (side, side))):
        s.wall(a, b, 0.0, 16.0, thickness=0.5)
    level = np.zeros((n, n), dtype=int)
    roots = [divmod(int(p), n) for p in rng.choice(n * n, size=int(rng.integers(3, 5)), replace=False)]
    links: set[tuple[tuple[int, int], tuple[int, int]]] = set()
    used: set[frozenset] = set()
    frontier = []
    for i, j in roots:
        level[i, j] = 1
        frontier.append((i, j))
        di, dj = [(-1, 0), (1, 0), (0, -1), (0, 1)][int(rng.integers(4))]
        used.add(frozenset([(i, j), (i + di, j + dj)]))
        x0, z0 = margin + i * pitch, margin + j * pitch
        heading = np.array([-di, -dj], dtype=np.float64)
        edge = np.array([x0 + size / 2, z0 + size / 2]) + np.array([di, dj]) * size / 2
        s.stairs(edge - heading * run, heading, 2.0, 0.0, storey, storey / steps, 0.28)
    while frontier:
        i, j = frontier.pop(int(rng.integers(len(frontier))))
        for di, dj in rng.permutation([(-1, 0), (1, 0), (0, -1), (0, 1)]):
            a, b = int(i + di), int(j + dj)
            if 0 <= a < n and 0 <= b < n and level[a, b] == 0 and frozenset([(i, j), (a, b)]) not in used:
                level[a, b] = int(np.clip(level[i, j] + rng.choice([-1, 0, 1, 1]), 1, 4))
                links.add(((i, j), (a, b)))
                used.add(frozenset([(i, j), (a, b)]))
                frontier.append((a, b))
    for i in range(n):
        for j in range(n):
            for a, b in ((i + 1, j), (i, j + 1)):
                if a < n and b < n and frozenset([(i, j), (a, b)]) not in used and abs(level[i, j] - level[a, b]) <= 1:
                    if rng.random() < 0.25:
                        links.add(((i, j), (a, b)))
    for i in range(n):
        for j in range(n):
            y, x0, z0 = storey * level[i, j], margin + i * pitch, margin + j * pitch
            s.box(x0, x0 + size, y - 0.3, y, z0, z0 + size)
            for px in (x0 + 0.2, x0 + size - 0.5):
                for pz in (z0 + 0.2, z0 + size - 0.5):
                    s.box(px, px + 0.3, 0.0, y - 0.3, pz, pz + 0.3)
    for p, q in sorted(links):
        low, high = (p, q) if level[p] <= level[q] else (q, p)
        y = storey * level[low]
        heading = np.array([high[0] - low[0], high[1] - low[1]], dtype=np.float64)
        edge = np.array([margin + low[0] * pitch + size / 2, margin + low[1] * pitch + size / 2]) + heading * size / 2
        if level[low] == level[high]:
            s.prism(_strip(edge, edge + heading * run, 2.0), y - 0.3, y)
        else:
            s.stairs(edge, heading, 2.0, y, storey, storey / steps, 0.28, depth=0.45)
    for _ in range(int(rng.integers(6, 11))):  # planters between the landings
        i, j = rng.integers(0, n - 1, size=2)
        x, z = margin + i * pitch + size + run / 2, margin + j * pitch + size + run / 2
        s.box(x - 1.0, x + 1.0, 0.0, 0.8, z - 1.0, z + 1.0)
    return s.mesh()


def _ridged(s: _Solids, x0: float, x1: float, z0: float, z1: float, y0: float, y1: float) -> tuple[float, float, float, float]:
    """A solid one does not enter over [x0, x1] x [z0, z1]: walls from ``y0`` to ``y1`` and a roof ridged along x at 50
    degrees, one convex body, so it has no top face for Recast to read as floor. Returns its plan, a hole for
    :meth:`_Solids.ground` (the ground inside a closed solid with head room over it would be floor)."""
    ridge = y1 + (z1 - z0) / 2 * math.tan(math.radians(50.0))
    s.hull(np.array([[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
                    + [[x, ridge, (z0 + z1) / 2] for x in (x0, x1)]))
    return x0, x1, z0, z1


def _split(a: float, b: float, width: float) -> np.ndarray:
    """The cuts (k + 1,) of [a, b] into k equal parts as near ``width`` m wide as whole parts allow (k >= 1)."""
    return np.linspace(a, b, max(1, round((b - a) / width)) + 1)


def hotel(seed: int) -> trimesh.Trimesh:
    """A hotel of six storeys 3.2 m apart on a 54-62 x 19-21 m plate under a roof at 50 degrees (:func:`_lid`): on the
    five upper storeys a corridor 2.2 m wide along x between two rows of guest rooms (3.6-4.6 m wide, a 1.6 m door
    each, a bathroom pod beside the door, 1.8 m high: too low inside to stand); a stair core in the middle (a
    switchback well, :func:`_switchback`, opening on the corridor, and across the corridor two lift shafts 2.4 m
    square, walled, open from the ground to the roof: no floor in them on any storey) and a fire stair at the
    corridor's east end; closets 1.8 m high (no floor in them or on them) fill the pockets behind the fire stair,
    the lifts and the core's well. The ground storey is a lobby from the west wall to 8-14 m east of the core (columns, a reception counter,
    sofas, a restaurant behind a wall with a 3 m opening at the west end), staff rooms as the guest rooms east of it,
    and a 3 m entrance in the south wall onto a forecourt 12 m deep. Every trip between storeys takes the core or
    the fire stair.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, storey, storeys = rng.uniform(54.0, 62.0), rng.uniform(19.0, 21.0), 3.2, 6
    cz0, cz1 = size_z / 2 - 1.1, size_z / 2 + 1.1
    length = _well_length(storey)
    core_x = round(rng.uniform(0.4, 0.5) * size_x, 1)
    fire_x = size_x - 4.6
    wells = [(core_x, cz1), (fire_x, cz0)]
    open_wells = [(x, x + 4.0, z + 2.0, z + length) for x, z in wells]
    shafts = [(core_x + i * 2.6, core_x + i * 2.6 + 2.4, cz0 - 2.6, cz0 - 0.2) for i in range(2)]
    lobby_end = round(core_x + rng.uniform(8.0, 14.0), 1)
    rest = (3.0, 14.0)  # the restaurant at the west end of the lobby
    entrance = (rest[1] + lobby_end) / 2
    s.ground(-5.0, size_x + 5.0, -12.0, size_z + 3.0, 0.0, shafts)
    for y in np.arange(storeys - 1) * storey:
        for x, z in wells:
            _switchback(s, x, z, float(y), storey)
    for k in range(storeys):
        y = k * storey
        top = y + storey - 0.3
        if k:
            s.slab(0.0, size_x, 0.0, size_z, y, [*open_wells, *shafts])
        s.wall((0.0, 0.0), (size_x, 0.0), y, top, [(entrance - 1.5, 3.0)] if k == 0 else [], thickness=0.3)
        s.wall((0.0, size_z), (size_x, size_z), y, top, thickness=0.3)
        for x in (0.0, size_x):
            s.wall((x, 0.0), (x, size_z), y, top, thickness=0.3)
        for x0, x1, z0, z1 in shafts:  # closed on every storey
            for z in (z0, z1):
                s.wall((x0 - 0.1, z), (x1 + 0.1, z), y, top)
            for x in (x0, x1):
                s.wall((x, z0), (x, z1), y, top)
        s.wall((core_x, cz1), (core_x, cz1 + length), y, top)  # the core's well, open on the corridor
        s.wall((core_x + 4.0, cz1), (core_x + 4.0, cz1 + length), y, top)
        s.wall((core_x, cz1 + length), (core_x + 4.0, cz1 + length), y, top)
        s.wall((fire_x, cz1), (fire_x, cz0 + length), y, top)  # the fire stair's well, the corridor's east end
        s.wall((fire_x, cz0 + length), (size_x, cz0 + length), y, top)
        pockets = [(fire_x + 0.1, size_x - 0.15, cz0 + length + 0.1, size_z - 0.15)]  # closets behind the fire stair
        if k:  # and behind the lifts and the core's well, between two rooms
            pockets += [(shafts[0][0] - 0.1, shafts[1][1] + 0.1, 0.15, shafts[0][2] - 0.1),
                        (core_x + 0.1, core_x + 3.9, cz1 + length + 0.1, size_z - 0.15)]
        for x0, x1, z0, z1 in pockets:  # 1.8 m high: no floor in them (the slab above is 1.1 m over their tops)
            s.box(x0, x1, y, y + 1.8, z0, z1)
        start = lobby_end if k == 0 else 0.15
        rows = (  # (z of the corridor wall, z of the outer wall, x ranges of rooms)
            (cz1, size_z - 0.15, [(start, core_x - 0.1), (max(start, core_x + 4.1), fire_x)]),
            (cz0, 0.15, [(start, shafts[0][0] - 0.2), (max(start, shafts[1][1] + 0.2), size_x - 0.15)]),
        )
        for wall_z, outer_z, ranges in rows:
            side = 1.0 if outer_z > wall_z else -1.0
            doors = []
            for a, b in ranges:
                if b - a < 3.0:
                    continue
                cuts = _split(a, b, rng.uniform(3.6, 4.6))
                for x0, x1 in pairwise(cuts):
                    doors.append((x0 + 0.3, 1.6))
                    pod = sorted((wall_z + side * 0.1, wall_z + side * 2.3))
                    s.box(x0 + 2.1, x1 - 0.1, y, y + 1.8, pod[0], pod[1])
                for x in cuts:
                    s.wall((x, wall_z), (x, outer_z), y, top, thickness=0.15)
            end = fire_x if side > 0 else size_x
            if k == 0:  # the lobby's side of the corridor is open
                doors.append((0.0, lobby_end))
            if side > 0:
                doors.append((core_x, 4.0))
            s.wall((0.0, wall_z), (end, wall_z), y, top, sorted(_merge(doors)), thickness=0.15)
    s.wall((rest[1], 0.0), (rest[1], size_z), 0.0, storey - 0.3, [(size_z / 2 - 1.5, 3.0)], thickness=0.2)
    for x in np.arange(rest[0], rest[1] - 1.5, 2.6):
        for z in np.arange(1.5, size_z - 1.5, 2.6):
            s.box(x, x + 1.0, 0.0, 0.75, z, z + 1.0)
    for x in np.arange(rest[1] + 5.0, lobby_end - 2.0, 7.0):  # columns
        for z in (cz0 - 3.0, cz1 + 3.0):
            if _clear(x, x + 0.5, z, z + 0.5, [(core_x - 1.0, core_x + 6.0, 0.0, size_z)]):
                s.box(x, x + 0.5, 0.0, storey - 0.3, z, z + 0.5)
    desk = max(rest[1] + 2.0, core_x - 8.0)
    s.box(desk, desk + 6.0, 0.0, 1.1, cz1 + 2.0, cz1 + 2.8)  # the reception counter
    for _ in range(int(rng.integers(5, 9))):  # sofas
        x, z = rng.uniform(rest[1] + 2.0, lobby_end - 3.0), rng.uniform(1.5, size_z - 2.5)
        if _clear(x, x + 2.0, z, z + 0.9, [(desk - 1.0, desk + 7.0, cz1 + 1.0, cz1 + 4.0),
                                           (core_x - 1.0, core_x + 6.0, 0.0, size_z),
                                           (entrance - 3.0, entrance + 3.0, 0.0, 4.0)]):
            s.box(x, x + 2.0, 0.0, 0.8, z, z + 0.9)
    _lid(s, 0.0, size_x, 0.0, size_z, storeys * storey - 0.3)
    return s.mesh()


def _merge(doors: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Openings (start, width) along a wall, overlapping ones joined into one."""
    merged: list[list[float]] = []
    for a, w in sorted(doors):
        if merged and a <= merged[-1][1]:
            merged[-1][1] = max(merged[-1][1], a + w)
        else:
            merged.append([a, a + w])
    return [(a, b - a) for a, b in merged]


def theme_park(seed: int) -> trimesh.Trimesh:
    """A theme park 170 x 115 m behind a fence 2.5 m high, entered from a plaza 15 m deep through a gate of
    turnstiles (ten gaps 1.6 m wide). Its ground is a 4 x 3 grid of plots (37.5 x 33.3 m) between paths about 10
    m wide that loop round every plot; each plot holds a ride (three in five), a food court or a garden. A ride is
    a fenced plot (1.2 m, no way in; the ground stops inside and a tent or tower no one climbs stands there, 16-26 x
    10-14 m) with a queue maze in front of it (south of it in the two rows nearer the gate, north in the far row): lanes 1.7-1.8 m wide between
    rails 1 m high, a turn at alternate ends, entered at one corner and ending at the ride's fence (a dead end
    folded 4-5 times). A food court holds tables and kiosks (ridged roofs, no floor inside); a garden hedges 0.8 m
    wide and 1.1 m high in rows with gaps, round a fountain no one climbs.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, gate_z = 170.0, 130.0, 15.0
    cols, rows = 4, 3
    cell_x, cell_z = (size_x - 20.0) / cols, (size_z - gate_z - 15.0) / rows
    holes: list[tuple[float, float, float, float]] = []
    for i in range(cols):
        for j in range(rows):
            x0, z0 = 10.0 + i * cell_x + 5.0, gate_z + 10.0 + j * cell_z + 5.0
            x1, z1 = x0 + cell_x - 10.0, z0 + cell_z - 10.0
            what = rng.choice(["ride", "ride", "ride", "food", "garden"])
            if what == "ride":
                w, d, qd = rng.uniform(16.0, x1 - x0 - 1.0), rng.uniform(10.0, 14.0), rng.uniform(7.0, 9.0)
                rx0 = rng.uniform(x0, x1 - w)
                side = -1.0 if j < rows / 2 else 1.0  # the queue south of the ride, or north in the far row
                if side < 0:
                    far, rz0 = z0, z0 + qd
                else:
                    rz0 = z1 - qd - d
                    far = z1
                rz1 = rz0 + d
                near = rz0 if side < 0 else rz1
                holes.append((rx0, rx0 + w, rz0, rz1))
                for a, b in (((rx0, rz0), (rx0 + w, rz0)), ((rx0, rz1), (rx0 + w, rz1))):
                    s.wall(a, b, -0.5, 1.2, thickness=0.1)
                for x in (rx0, rx0 + w):
                    s.wall((x, rz0), (x, rz1), -0.5, 1.2, thickness=0.1)
                if rng.random() < 0.5:
                    _ridged(s, rx0 + 1.0, rx0 + w - 1.0, rz0 + 1.0, rz1 - 1.0, -0.5, 3.0)
                else:  # a drop tower: a pyramid no one climbs
                    c = np.array([rx0 + w / 2, (rz0 + rz1) / 2])
                    s.hull(np.array([[c[0] + dx, -0.5, c[1] + dz] for dx in (-4.0, 4.0) for dz in (-4.0, 4.0)]
                                    + [[c[0], 30.0, c[1]]]))
                qw = rng.uniform(10.0, min(w, 16.0))
                qx0 = rng.uniform(rx0, rx0 + w - qw)
                qx1 = qx0 + qw
                lanes = int(qd // 1.75)
                pitch = qd / lanes
                s.wall((qx0, far), (qx1, far), 0.0, 1.0, [(0.0, 1.6)], thickness=0.1)  # entered at the west corner
                for k in range(lanes - 1):
                    z = far - side * (k + 1) * pitch
                    s.wall((qx0, z), (qx1, z), 0.0, 1.0, [(qw - 1.6, 1.6)] if k % 2 == 0 else [(0.0, 1.6)], thickness=0.1)
                for x in (qx0, qx1):
                    s.wall((x, min(far, near)), (x, max(far, near)), 0.0, 1.0, thickness=0.1)
            elif what == "food":
                kiosks = [(x0 + rng.uniform(0.0, x1 - x0 - 4.0), z0 + rng.uniform(0.0, z1 - z0 - 3.0)) for _ in range(3)]
                plans = [(x, x + 4.0, z, z + 3.0) for x, z in kiosks]
                for x, z in kiosks:
                    if _clear(x, x + 4.0, z, z + 3.0, holes):
                        holes.append(_ridged(s, x, x + 4.0, z, z + 3.0, -0.5, 2.8))
                for x in np.arange(x0 + 1.0, x1 - 1.2, 3.0):
                    for z in np.arange(z0 + 1.0, z1 - 1.2, 3.0):
                        if _clear(x - 1.0, x + 2.2, z - 1.0, z + 2.2, plans):
                            s.box(x, x + 1.2, 0.0, 0.75, z, z + 1.2)
            else:
                c = np.array([(x0 + x1) / 2, (z0 + z1) / 2])
                s.hull(np.array([[c[0] + dx, 0.0, c[1] + dz] for dx in (-1.5, 1.5) for dz in (-1.5, 1.5)]
                                + [[c[0], 4.0, c[1]]]))
                for z in np.arange(z0 + 2.0, z1 - 1.0, 4.5):
                    gaps = sorted(rng.uniform(0.0, x1 - x0 - 2.0, size=2))
                    if abs(z - c[1]) > 2.5:
                        s.wall((x0, z), (x1, z), 0.0, 1.1, _merge([(g, 2.0) for g in gaps]), thickness=0.8)
    s.ground(0.0, size_x, 0.0, size_z, 0.0, holes)
    s.wall((0.0, gate_z), (size_x, gate_z), 0.0, 2.5, [(size_x / 2 - 10.0, 20.0)], thickness=0.3)
    for k in range(11):  # turnstiles: 10 gaps of 1.6 m between posts 0.4 m wide, walls either side
        x = size_x / 2 - 10.0 + k * 2.0
        s.box(x, x + 0.4, 0.0, 1.0, gate_z - 1.5, gate_z + 1.5)
    for a, b in (((0.0, size_z), (size_x, size_z)), ((0.0, gate_z), (0.0, size_z)), ((size_x, gate_z), (size_x, size_z))):
        s.wall(a, b, 0.0, 2.5, thickness=0.3)
    return s.mesh()


def aqueduct(seed: int) -> trimesh.Trimesh:
    """A bridge town: a lower town 140 x 120 m in a valley between two upper towns on terraces 8 m up (40 m wide,
    cliffs between), joined across the valley by a bridge along x carrying a street 5.5 m wide at 8 m (parapets 1.1
    m) on an arcade: piers 2.4 m thick every 9-11 m, arches 5 m high between them, through which the lower town's
    streets along z pass. The lower town's houses (5-8 m wide, ridged, not entered) stand in blocks between streets 5-6 m
    wide: streets along z through every second or third arch, a lane along each side of the arcade (market stalls 2 x 1.5 m, 0.9 m high, in it), a street
    along x near each end; nearly one house gap in two is an alley 1.6-2 m wide. Two or three piers carry a switchback
    stair (:func:`_switchback`, a well 4 m wide beside the arcade) from the lower town to the bridge's street, and a
    ramp street 4 m wide climbs the west cliff at about 1 in 6 from the lower town to the west terrace. The upper
    towns are a street on the bridge's line between rows of houses, a back lane 5 m wide behind each row and a
    second row beyond it, a street along the cliff's edge, and open ground.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    west, east, size_z, high = 30.0, 170.0, 120.0, 8.0
    zb = rng.uniform(48.0, 56.0)
    deck = (zb - 2.75, zb + 2.75)
    pitch = rng.uniform(9.0, 11.0)
    piers = list(np.arange(west + pitch, east - 3.0, pitch))
    arches = [(a + 1.2, b - 1.2) for a, b in pairwise([west - 1.2, *piers, east + 1.2])]
    holes = [(p - 1.2, p + 1.2, *deck) for p in piers]
    for p in piers:  # up to the deck's top: a pier's top under the deck would be floor with the deck as its ceiling
        s.box(p - 1.2, p + 1.2, -0.5, high, *deck)
    s.box(west, east, 5.0, high, *deck)
    stairs = sorted(rng.choice(range(1, len(piers) - 1), size=int(rng.integers(2, 4)), replace=False))
    length = _well_length(high)
    gaps = []
    kept: list[tuple[float, float, float, float]] = []  # plans clear of houses
    for k in stairs:
        x0 = piers[k] - 2.0
        _switchback(s, x0, deck[1], 0.0, high)
        s.box(x0, x0 + 4.0, high - 0.3, high, deck[1], deck[1] + 2.0)
        kept.append((x0 - 0.5, x0 + 4.5, deck[1], deck[1] + length + 0.5))  # no houses in the well
        gaps.append((x0 - west, 4.0))
    s.wall((west, deck[1] - 0.15), (east, deck[1] - 0.15), high, high + 1.1, gaps, thickness=0.3)
    s.wall((west, deck[0] + 0.15), (east, deck[0] + 0.15), high, high + 1.1, thickness=0.3)
    ramp_z = (size_z - 2.0, deck[1] + 6.0)
    s.ramp(np.array([west + 2.0, ramp_z[0]]), np.array([west + 2.0, ramp_z[1] + 4.0]), 4.0, 0.0, high)
    s.box(west, west + 4.0, high - 0.3, high, ramp_z[1], ramp_z[1] + 4.0)  # its landing against the terrace
    kept.append((west, west + 4.5, ramp_z[1], size_z))
    # the lower town: streets along z through some arches, lanes beside the arcade, streets along x near the ends
    through = [arches[i] for i in range(int(rng.integers(0, 2)), len(arches), int(rng.integers(2, 4)))]
    streets_x = [((a + b) / 2 - 2.75, (a + b) / 2 + 2.75) for a, b in through]
    bands = [(6.0, deck[0] - 5.5), (deck[1] + 5.5, size_z - 6.0)]
    edges = [west + 0.5, *sum(streets_x, ()), east - 0.5]
    for za, zb_ in bands:
        for xa, xb in zip(edges[0::2], edges[1::2]):
            if xb - xa < 5.0:
                continue
            parts = list(pairwise(_split(za, zb_, 17.0)))  # blocks about 12 m deep, streets 5 m wide between
            for i, (pa, pb) in enumerate(parts):
                za_, zb2 = pa + (2.5 if i else 0.0), pb - (2.5 if i < len(parts) - 1 else 0.0)
                for x0, x1 in pairwise(_split(xa, xb, rng.uniform(5.0, 8.0))):
                    gap = rng.uniform(1.6, 2.0) if rng.random() < 0.45 else 0.0
                    if _clear(x0, x1 - gap, za_, zb2, holes + kept):
                        holes.append(_ridged(s, x0, x1 - gap, za_, zb2, -0.5, rng.uniform(5.0, 9.0)))
    for _ in range(int(rng.integers(16, 26))):  # market stalls in the lanes beside the arcade, clear of the arches' middles
        x, z = rng.uniform(west + 2.0, east - 4.0), rng.choice([deck[0] - rng.uniform(2.0, 4.0), deck[1] + rng.uniform(0.5, 2.5)])
        if _clear(x - 1.0, x + 3.0, z - 0.5, z + 2.0, kept + [(a + 1.0, b - 1.0, 0.0, size_z) for a, b in through]):
            s.box(x, x + 2.0, 0.0, 0.9, z, z + 1.5)
    s.ground(west, east, 0.0, size_z, 0.0, holes)
    # the upper towns: a street on the bridge's line, two rows of houses either side with a back lane between, open ground beyond
    for t0, t1, h0, h1 in ((west - 40.0, west, 1.0, 6.0), (east, east + 40.0, 6.0, 1.0)):  # a street 5 m wide on the cliff
        houses = []
        for z0, z1 in ((deck[1] + 0.25, deck[1] + 10.0), (deck[1] + 15.0, deck[1] + 25.0), (deck[0] - 10.0, deck[0] - 0.25),
                       (deck[0] - 25.0, deck[0] - 15.0)):
            for x0, x1 in pairwise(_split(t0 + h0, t1 - h1, rng.uniform(6.0, 9.0))):
                gap = rng.uniform(1.6, 2.0) if rng.random() < 0.45 else 0.0
                houses.append(_ridged(s, x0, x1 - gap, z0, z1, high - 0.5, high + rng.uniform(5.0, 8.0)))
        s.ground(t0, t1, 0.0, size_z, high, houses, thickness=high + 0.5)
    return s.mesh()


def warehouse(seed: int) -> trimesh.Trimesh:
    """A warehouse 110-120 x 58-64 m whose floor is a dock 1.2 m over its yard, under a roof 11 m up (:func:`_lid`).
    North of a staging strip 16 m deep along the dock wall, racking 9.8 m high (to 1 m under the roof; the floor
    stops under it) in double rows 2.4 m deep, single rows along the walls, with aisles 3-3.4 m wide along z and two
    cross aisles 4 m wide (the northern band's rows reach the north wall: its aisles are dead ends); in the north-west corner a mezzanine 4.2 m up (18-24 x 14 m, posts on a 5 m grid, rails,
    low shelving, one straight flight) over open floor; pallet stacks 1.5 m high, at least 1.2 m apart, on the staging strip and under the mezzanine. The south
    wall has 8-10 dock doors 3.5 m wide: the eastern two open on an apron at dock height with a ramp (1 in 10) down
    to the yard, the rest on the 1.2 m drop, half of them with a trailer backed up (ridged, floating on no
    wheels), and a row of parked trailers across the yard. A personnel door in the west wall with steps down to the yard. The yard runs 30 m south of the dock
    wall and 6-10 m round the other sides.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, dock, roof = rng.uniform(110.0, 120.0), rng.uniform(58.0, 64.0), 1.2, 11.0
    s.ground(-10.0, size_x + 12.0, -30.0, size_z + 6.0, 0.0, [(0.0, size_x, 0.0, size_z)])
    racks: list[tuple[float, float, float, float]] = []
    mez = (0.3, rng.uniform(18.0, 24.0), size_z - 14.3, size_z - 0.3)
    aisle = rng.uniform(3.0, 3.4)
    cross = np.array([0.33, 0.67]) * (size_z - 16.0) + 16.0 + rng.uniform(-3.0, 3.0, size=2)
    rows, x, depth = [], mez[1] + 3.0, 1.2  # the first row stands alone, and so does the last, on the east wall
    while x + depth + aisle + 1.2 < size_x - 0.3:
        rows.append((x, depth))
        x, depth = x + depth + aisle, 2.4
    for x, depth in [*rows, (size_x - 1.5, 1.2)]:
        racks += [(x, x + depth, z0 + 2.0, z1 - 2.0) for z0, z1 in pairwise([14.0, *cross, size_z + 1.7])]
    for x0, x1, z0, z1 in racks:
        s.box(x0, x1, 0.0, roof - 1.0, z0, z1)
    s.ground(0.0, size_x, 0.0, size_z, dock, racks, thickness=dock + 0.5)
    for a, b in (((0.0, size_z), (size_x, size_z)), ((size_x, 0.0), (size_x, size_z))):
        s.wall(a, b, dock, roof, thickness=0.3)
    s.wall((0.0, 0.0), (0.0, size_z), dock, roof, [(8.0, 1.6)], thickness=0.3)
    steps = 7
    s.stairs(np.array([-steps * 0.28, 8.8]), np.array([1.0, 0.0]), 1.6, 0.0, dock, dock / steps, 0.28)
    doors = list(_split(6.0, size_x - 6.0, rng.uniform(8.5, 10.0)))
    doors = [(a + b) / 2 for a, b in pairwise(doors)]
    s.wall((0.0, 0.0), (size_x, 0.0), dock, roof, [(x - 1.75, 3.5) for x in doors], thickness=0.3)
    apron = (doors[-2] - 3.0, doors[-1] + 3.0)
    s.box(apron[0], apron[1], -0.5, dock, -4.0, 0.0)
    s.ramp(np.array([apron[1], -2.0]), np.array([apron[1] + 12.0, -2.0]), 3.0, dock, 0.0)
    for x in doors[:-2]:
        if rng.random() < 0.5:  # a trailer backed up to the door
            ridge = 3.6 + 1.25 * math.tan(math.radians(50.0))
            s.hull(np.array([[xx, y, z] for xx in (x - 1.25, x + 1.25) for y in (1.0, 3.6) for z in (-13.0, -0.4)]
                            + [[x, ridge, z] for z in (-13.0, -0.4)]))
    for x in np.arange(rng.uniform(0.0, 3.0), size_x - 3.0, rng.uniform(4.0, 5.0)):  # trailers parked across the yard
        if rng.random() < 0.7:
            ridge = 3.6 + 1.25 * math.tan(math.radians(50.0))
            s.hull(np.array([[xx, y, z] for xx in (x, x + 2.5) for y in (1.0, 3.6) for z in (-28.0, -15.5)]
                            + [[x + 1.25, ridge, z] for z in (-28.0, -15.5)]))
    # the mezzanine: a deck on posts, rails on its open sides, low shelving, one flight along +z to its south edge
    top = dock + 4.2
    s.box(mez[0], mez[1], top - 0.3, top, mez[2], mez[3])
    for px in np.arange(mez[0] + 4.0, mez[1] - 0.5, 5.0):
        for pz in np.arange(mez[2] + 2.0, mez[3] - 0.5, 5.0):
            s.box(px, px + 0.3, dock, top - 0.3, pz, pz + 0.3)
    flight_x = mez[0] + rng.uniform(3.0, mez[1] - mez[0] - 5.0)
    risers = math.ceil(4.2 / 0.18)
    s.stairs(np.array([flight_x + 1.0, mez[2] - risers * 0.28]), np.array([0.0, 1.0]), 2.0, dock, 4.2, 4.2 / risers, 0.28)
    s.wall((mez[0], mez[2]), (mez[1], mez[2]), top, top + 1.1, [(flight_x - mez[0], 2.0)], thickness=0.1)
    s.wall((mez[1], mez[2]), (mez[1], mez[3]), top, top + 1.1, thickness=0.1)
    for x in np.arange(mez[0] + 2.0, mez[1] - 2.5, 3.2):
        s.box(x, x + 0.8, top, top + 2.2, mez[2] + 3.0, mez[3] - 2.0)
    placed = [(px - 0.1, px + 0.4, pz - 0.1, pz + 0.4) for px in np.arange(mez[0] + 4.0, mez[1] - 0.5, 5.0)
              for pz in np.arange(mez[2] + 2.0, mez[3] - 0.5, 5.0)]
    for _ in range(int(rng.integers(90, 120))):  # pallet stacks on the staging strip and under the mezzanine, 1.2 m apart
        x, z = (rng.uniform(2.0, size_x - 3.0), rng.uniform(4.5, 14.0)) if rng.random() < 0.7 else \
            (rng.uniform(mez[0] + 1.5, mez[1] - 2.7), rng.uniform(mez[2] + 1.0, mez[3] - 2.5))
        if _clear(x - 1.2, x + 2.4, z - 1.2, z + 2.2, placed):
            s.box(x, x + 1.2, dock, dock + 1.5, z, z + 1.0)
            placed.append((x, x + 1.2, z, z + 1.0))
    _lid(s, 0.0, size_x, 0.0, size_z, roof)
    return s.mesh()


def golf(seed: int) -> trimesh.Trimesh:
    """A golf course as a park: rolling lawns 220 x 170 m (a 2 m grid, four waves of 40-140 m, slopes under about
    12 degrees, six to ten sand hollows up to 1 m deep) cut in two by a creek 5-7 m wide from the west edge to the
    east (no water surface: the ground stops at its banks) crossed only by three footbridges 1.8 m wide, railed
    over the water, and holding three or four ponds (ellipses 8-22 m across), one of them crossed by a fourth
    footbridge; 12-18 clumps of 6-14 trees (trunks 0.25-0.45 m, 5 m high); a clubhouse (24 x 14 m, one 2 m door,
    a gable roof) on the lawn near the south-west corner.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, step = 220.0, 170.0, 2.0
    xs, zs = np.arange(0.0, size_x + step / 2, step), np.arange(0.0, size_z + step / 2, step)
    waves = [(rng.uniform(0.4, 0.9), rng.uniform(40.0, 140.0), rng.uniform(0, 2 * math.pi), rng.uniform(0, math.pi))
             for _ in range(4)]
    hollows = [(rng.uniform(20.0, size_x - 20.0), rng.uniform(20.0, size_z - 20.0), rng.uniform(3.0, 6.0))
               for _ in range(int(rng.integers(6, 11)))]

    def height(x: np.ndarray, z: np.ndarray) -> np.ndarray:
        h = sum(a * np.sin(2 * math.pi / length * (x * math.cos(turn) + z * math.sin(turn)) + phase)
                for a, length, phase, turn in waves)
        return h - sum(np.exp(-((x - hx) ** 2 + (z - hz) ** 2) / (2 * r * r)) for hx, hz, r in hollows)

    creek_z, bend, creek_phase = rng.uniform(0.4, 0.6) * size_z, rng.uniform(10.0, 18.0), rng.uniform(0, 2 * math.pi)
    creek_half = rng.uniform(2.5, 3.5)

    def creek(x: np.ndarray) -> np.ndarray:
        """The creek's centre line, z at ``x``."""
        return creek_z + bend * np.sin(x * 0.03 + creek_phase)

    x0, z0 = rng.uniform(10.0, 30.0), rng.uniform(10.0, 25.0)
    club = (x0, x0 + 24.0, z0, z0 + 14.0)
    taken = [(club[0] - 4.0, club[1] + 4.0, club[2] - 4.0, club[3] + 4.0)]
    ponds: list[tuple[np.ndarray, np.ndarray]] = []
    count = int(rng.integers(3, 5))
    while len(ponds) < count:
        c = np.array([rng.uniform(25.0, size_x - 25.0), rng.uniform(20.0, size_z - 20.0)])
        r = rng.uniform(4.0, 11.0, size=2)
        if abs(c[1] - creek(c[0])) > r.max() + creek_half + 12.0 and all(np.linalg.norm(c - p[0]) > 40.0 for p in ponds) \
                and _clear(c[0] - r[0] - 6.0, c[0] + r[0] + 6.0, c[1] - r[1] - 6.0, c[1] + r[1] + 6.0, taken):
            ponds.append((c, r))
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    cx, cz = (gx[:-1, :-1] + gx[1:, 1:]) / 2, (gz[:-1, :-1] + gz[1:, 1:]) / 2
    water = np.abs(cz - creek(cx)) < creek_half
    for c, r in ponds:
        water |= ((cx - c[0]) / r[0]) ** 2 + ((cz - c[1]) / r[1]) ** 2 < 1.0
    _terrain(s, xs, zs, height(gx, gz), keep=~water)
    crossings = [(x, np.array([creek(x) - creek_half, creek(x) + creek_half])) for x in
                 np.array([0.2, 0.5, 0.8]) * size_x + rng.uniform(-10.0, 10.0, size=3)]
    c, r = ponds[int(rng.integers(len(ponds)))]
    crossings.append((c[0], np.array([c[1] - r[1], c[1] + r[1]])))
    for x, (z0, z1) in crossings:
        column = water[min(int(x // step), water.shape[0] - 1)]
        wet = zs[:-1][column & (zs[:-1] > z0 - 8.0) & (zs[:-1] < z1 + 8.0)]
        z0, z1 = wet.min() - 3.0, wet.max() + step + 3.0
        taken.append((x - 3.0, x + 3.0, z0, z1))
        ends = [np.array([x, z0]), np.array([x, z1])]
        ys = [float(height(np.array(p[0]), np.array(p[1]))) + 0.05 for p in ends]
        s.ramp(ends[0], ends[1], 1.8, ys[0], ys[1], thickness=1.0)
        t0, t1 = 2.0 / (z1 - z0), 1.0 - 2.0 / (z1 - z0)  # railed over the water, open 2 m from each end
        for sign in (-1.0, 1.0):
            a, b = ends[0] + t0 * (ends[1] - ends[0]), ends[0] + t1 * (ends[1] - ends[0])
            side = np.array([sign * 0.85, 0.0])
            s.ramp(a + side, b + side, 0.1, ys[0] + t0 * (ys[1] - ys[0]) + 1.0, ys[0] + t1 * (ys[1] - ys[0]) + 1.0,
                   thickness=1.0)
    under = height(np.linspace(club[0], club[1], 13)[:, None], np.linspace(club[2], club[3], 8)[None])
    low, high = float(under.min()) - 0.5, float(under.max()) + 3.5
    door = rng.uniform(4.0, 18.0)
    s.wall((club[0], club[2]), (club[1], club[2]), low, high, [(door, 2.0)], thickness=0.3)
    s.wall((club[0], club[3]), (club[1], club[3]), low, high, thickness=0.3)
    for x in club[:2]:
        s.wall((x, club[2]), (x, club[3]), low, high, thickness=0.3)
    _gable(s, club[0] - 0.3, club[1] + 0.3, club[2] - 0.3, club[3] + 0.3, high)
    clumps, target = 0, int(rng.integers(12, 19))
    while clumps < target:
        c = np.array([rng.uniform(10.0, size_x - 10.0), rng.uniform(10.0, size_z - 10.0)])
        if not _clear(c[0] - 10.0, c[0] + 10.0, c[1] - 10.0, c[1] + 10.0, taken):
            continue
        clumps += 1
        for p in c + rng.normal(0.0, rng.uniform(2.5, 4.5), size=(int(rng.integers(6, 15)), 2)):
            i, j = int(np.clip(p[0] // step, 0, water.shape[0] - 1)), int(np.clip(p[1] // step, 0, water.shape[1] - 1))
            if not water[max(i - 1, 0):i + 2, max(j - 1, 0):j + 2].any() and _clear(*np.repeat(p, 2), taken):
                y = float(height(np.array(p[0]), np.array(p[1])))
                trunk = rng.uniform(0.25, 0.45)
                angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
                s.prism(p + trunk * np.stack([np.cos(angles), np.sin(angles)], 1), y - 0.5, y + 5.0)
    return s.mesh()


def scaffold(seed: int) -> trimesh.Trimesh:
    """A building site 90 x 75 m behind a hoarding 2.4 m high (a 6 m gate): a concrete frame of four slabs 3.5 m
    apart over a 30-36 x 20-24 m plan, on columns every 5-6 m (stubs 1 m above the top slab), no walls, every slab
    edge railed 1 m high with one or two gaps 2 m wide a side onto the scaffold; a switchback stair in a walled core
    (:func:`_switchback`) up to the top slab. Round the frame on every slab's level a scaffold deck 1.6 m wide,
    railed on its outer edge, so each storey's gaps lead out onto a ring round the building; a scaffold stair tower
    (another switchback, open) on the ring's north side, from the ground to the top. On the ground: site cabins,
    a crane's mast, skips (all ridged: no floor on or in them), pallets of blocks and bundles of bars.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    site_x, site_z, storey, slabs = 90.0, 75.0, 3.5, 4
    lx, lz = rng.uniform(30.0, 36.0), rng.uniform(20.0, 24.0)
    bx0, bz0 = rng.uniform(24.0, 30.0), rng.uniform(18.0, 22.0)
    bx1, bz1 = bx0 + lx, bz0 + lz
    length = _well_length(storey)
    core = (bx0 + round(rng.uniform(0.3, 0.6) * (lx - 4.0), 1), bz0 + 3.0)
    well = (core[0], core[0] + 4.0, core[1] + 2.0, core[1] + length)
    tower_x = bx0 + rng.uniform(2.0, lx - 6.0)
    ring = 1.6
    for k in range(slabs):
        _switchback(s, core[0], core[1], k * storey, storey)
        _switchback(s, tower_x, bz1 + ring, k * storey, storey)
    columns_x, columns_z = _split(bx0, bx1 - 0.4, rng.uniform(5.0, 6.0)), _split(bz0, bz1 - 0.4, rng.uniform(5.0, 6.0))
    for x in columns_x:
        for z in columns_z:
            if _clear(x, x + 0.4, z, z + 0.4, [(core[0] - 0.3, core[0] + 4.3, core[1] - 0.3, core[1] + length + 0.3)]):
                s.box(x, x + 0.4, 0.0, slabs * storey + 1.0, z, z + 0.4)
    for k in range(1, slabs + 1):
        y = k * storey
        s.slab(bx0, bx1, bz0, bz1, y, [well])
        for x0, x1, z0, z1 in ((bx0 - ring, bx1 + ring, bz0 - ring, bz0), (bx0 - ring, bx1 + ring, bz1, bz1 + ring),
                               (bx0 - ring, bx0, bz0, bz1), (bx1, bx1 + ring, bz0, bz1)):
            s.box(x0, x1, y - 0.1, y, z0, z1)  # the scaffold's boards
        s.box(tower_x, tower_x + 4.0, y - 0.3, y, bz1 + ring, bz1 + ring + 2.0)  # the stair tower's landing
        for a, b in (((bx0, bz0), (bx1, bz0)), ((bx0, bz1), (bx1, bz1)), ((bx0, bz0), (bx0, bz1)), ((bx1, bz0), (bx1, bz1))):
            side = abs(b[0] - a[0]) + abs(b[1] - a[1])
            gaps = [(g, 2.0) for g in sorted(rng.uniform(1.0, side - 3.0, size=int(rng.integers(1, 3))))]
            s.wall(a, b, y, y + 1.0, _merge(gaps), thickness=0.1)  # the slab's edge rail
        outer = ((bx0 - ring, bz0 - ring), (bx1 + ring, bz0 - ring), (bx1 + ring, bz1 + ring), (bx0 - ring, bz1 + ring))
        for a, b in pairwise([*outer, outer[0]]):
            gaps = [(tower_x - (bx0 - ring), 4.0)] if a[1] == b[1] == bz1 + ring else []
            lo = (min(a[0], b[0]), min(a[1], b[1]))
            hi = (max(a[0], b[0]), max(a[1], b[1]))
            s.wall(lo, hi, y, y + 1.0, gaps, thickness=0.1)
        top = y + storey - 0.3
        if k < slabs:
            s.wall((core[0], core[1]), (core[0], core[1] + length), y, top)
            s.wall((core[0] + 4.0, core[1]), (core[0] + 4.0, core[1] + length), y, top)
            s.wall((core[0], core[1] + length), (core[0] + 4.0, core[1] + length), y, top)
        else:  # railed round the well on the top slab
            s.wall((core[0], well[2]), (core[0], well[3]), y, y + 1.0, thickness=0.1)
            s.wall((core[0] + 4.0, well[2]), (core[0] + 4.0, well[3]), y, y + 1.0, thickness=0.1)
            s.wall((core[0], well[3]), (core[0] + 4.0, well[3]), y, y + 1.0, thickness=0.1)
    s.wall((core[0], core[1]), (core[0], core[1] + length), 0.0, storey - 0.3)
    s.wall((core[0] + 4.0, core[1]), (core[0] + 4.0, core[1] + length), 0.0, storey - 0.3)
    s.wall((core[0], core[1] + length), (core[0] + 4.0, core[1] + length), 0.0, storey - 0.3)
    keep_out = [(bx0 - ring - 3.0, bx1 + ring + 3.0, bz0 - ring - 3.0, bz1 + ring + length + 3.0),
                (site_x / 2 - 5.0, site_x / 2 + 5.0, 0.0, 8.0)]
    holes: list[tuple[float, float, float, float]] = []
    things = [(6.0, 2.5, 2.8)] * int(rng.integers(3, 6)) + [(2.0, 2.0, 30.0)] + [(4.0, 1.8, 1.6)] * int(rng.integers(3, 6))
    for w, d, h in things:  # cabins, the crane's mast, skips
        for _ in range(50):
            x, z = rng.uniform(2.0, site_x - 2.0 - w), rng.uniform(2.0, site_z - 2.0 - d)
            if _clear(x - 2.0, x + w + 2.0, z - 2.0, z + d + 2.0, keep_out + holes):
                holes.append(_ridged(s, x, x + w, z, z + d, -0.5, h))
                break
    for _ in range(int(rng.integers(25, 40))):  # pallets of blocks (1 m high), bundles of bars (0.6 m wide)
        w, d = (1.2, 1.0) if rng.random() < 0.6 else (6.0, 0.6)
        x, z = rng.uniform(2.0, site_x - 2.0 - w), rng.uniform(2.0, site_z - 2.0 - d)
        if _clear(x - 1.0, x + w + 1.0, z - 1.0, z + d + 1.0, holes + keep_out[1:]) and \
                _clear(x, x + w, z, z + d, [(core[0] - 1.0, core[0] + 5.0, core[1] - 1.0, core[1] + length),
                                            (tower_x - 1.0, tower_x + 5.0, bz1, bz1 + ring + length + 1.0)]):
            s.box(x, x + w, 0.0, 1.0, z, z + d)
    s.ground(0.0, site_x, 0.0, site_z, 0.0, holes)
    for a, b in (((0.0, 0.0), (site_x, 0.0)), ((0.0, site_z), (site_x, site_z)), ((0.0, 0.0), (0.0, site_z)),
                 ((site_x, 0.0), (site_x, site_z))):
        s.wall(a, b, 0.0, 2.4, [(site_x / 2 - 3.0, 6.0)] if a[1] == b[1] == 0.0 else [], thickness=0.3)
    return s.mesh()


def _trunk(s: _Solids, p: np.ndarray, radius: float, y0: float, y1: float) -> None:
    """A tree's trunk (or a post): an octagonal prism of ``radius`` m about plan point ``p`` (x, z) from y0 to y1."""
    angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
    s.prism(p + radius * np.stack([np.cos(angles), np.sin(angles)], 1), y0, y1)


def dry_dock(seed: int) -> trimesh.Trimesh:
    """A shipyard's dry dock: quays at y = 0 round a dock 110-120 x 36 m cut 10 m down (the quays are 10.5 m thick, so
    the dock's walls are solid), open to the sea at its east end, where a caisson 2.5 m wide, railed, joins the two
    quays. Along each long wall an altar (a ledge 5 m wide, 5 m down; the dock's floor stops under it); two or three
    stairs down each long wall (a flight 2.4 m wide from the quay down to the altar along the wall, a second from the
    altar to the floor, 0.179 / 0.28 m steps, each ending on a landing 2.5 m long) and a flight 3 m wide down the head
    wall. A ship on keel blocks (hull
    80-90 x 14-16 m, bow east, its deck 2 m over the quays; the blocks leave 1.6 m under the hull, too low to stand),
    joined to the north quay by two gangways 2.2 m wide, railed; its superstructure and hatches stand under ridged tops
    and the deck stops under them (no floor on them or in them). A gantry crane across
    the dock, its girder 14 m up with a railed walk 2.8 m wide on it, reached by an open switchback stair tower on the
    north quay (:func:`_switchback`). Two workshops, 24-33 containers and 18-25 stacks of plate on the quays, all ridged
    (the quay stops under them); bollards every 5-6 m along the dock's edges.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    dock_x0, dock_x1, dock_z0, dock_z1 = 30.0, 30.0 + rng.uniform(110.0, 120.0), 40.0, 76.0
    size_x, size_z, floor, altar, ledge, width = dock_x1 + 2.5, 116.0, -10.0, -5.0, 5.0, 2.4
    riser, tread = 5.0 / 28, 0.28
    s.box(dock_x0, dock_x1, floor - 0.5, floor, dock_z0 + ledge, dock_z1 - ledge)
    for z0, z1 in ((dock_z0, dock_z0 + ledge), (dock_z1 - ledge, dock_z1)):
        s.box(dock_x0, dock_x1, floor - 0.5, altar, z0, z1)
    run = 28 * tread
    s.stairs(np.array([dock_x0 + 2 * run, (dock_z0 + dock_z1) / 2]), np.array([-1.0, 0.0]), 3.0, floor, -floor, riser, tread)
    for rail_x in (dock_x1, size_x - 0.1):  # the caisson's rails
        s.box(rail_x, rail_x + 0.1, 0.0, 1.1, dock_z0, dock_z1)
    hull_x0 = dock_x0 + 2 * run + 3.0
    hull_x1 = min(hull_x0 + rng.uniform(80.0, 90.0), dock_x1 - 5.0)
    beam = rng.uniform(14.0, 16.0)
    mid = (dock_z0 + dock_z1) / 2
    hz0, hz1 = mid - beam / 2, mid + beam / 2
    s.prism(np.array([[hull_x1 - 10.0, hz0], [hull_x1, mid], [hull_x1 - 10.0, hz1]]), floor + 1.6, 2.0)  # the bow
    for x in np.arange(hull_x0 + 3.0, hull_x1 - 8.0, 6.0):  # keel blocks
        s.box(x, x + 1.2, floor, floor + 1.6, mid - 1.0, mid + 1.0)
    # the hull stops under the superstructure and the hatches, which reach down to its bottom: an up-facing top
    # inside a closed solid with head room over it would be floor
    covers = [_ridged(s, hull_x0, hull_x0 + rng.uniform(12.0, 16.0), hz0 + 1.0, hz1 - 1.0, floor + 1.6, 10.0)]
    x = hull_x0 + 20.0
    while x + 12.0 < hull_x1 - 14.0:  # hatches
        covers.append(_ridged(s, x, x + rng.uniform(8.0, 12.0), hz0 + 3.0, hz1 - 3.0, floor + 1.6, 2.8))
        x += rng.uniform(14.0, 18.0)
    s.slab(hull_x0, hull_x1 - 10.0, hz0, hz1, 2.0, covers, thickness=2.0 - floor - 1.6)
    gangways = sorted(rng.uniform(hull_x0 + 22.0, hull_x1 - 16.0, size=2))
    if gangways[1] - gangways[0] < 12.0:
        gangways[1] = gangways[0] + 12.0
    for gx in gangways:
        a, b = np.array([gx, dock_z1 + 1.5]), np.array([gx, hz1 - 1.5])
        s.ramp(a, b, 2.2, 0.0, 2.0)
        for side in (-1.05, 1.05):
            s.ramp(a + [side, -1.5], b + [side, 1.0], 0.1, 0.12 + 1.0, 1.85 + 1.0, thickness=1.0)
    # flights down the long walls, kept clear of the gangways
    for z_wall, toward in ((dock_z1, -1.0), (dock_z0, 1.0)):
        xs_flights: list[float] = []
        flights = int(rng.integers(2, 4))
        while len(xs_flights) < flights:
            x = rng.uniform(dock_x0 + 2 * run + 5.0, dock_x1 - run - 5.0)
            if all(abs(x - f) > 2 * run + 9.0 for f in xs_flights) and all(abs(x + run / 2 - g) > run / 2 + 6.0 for g in gangways):
                xs_flights.append(x)
        for x in xs_flights:
            heading = np.array([1.0, 0.0]) if rng.random() < 0.5 else np.array([-1.0, 0.0])
            start = x if heading[0] > 0 else x + run
            upper, lower = z_wall + toward * width / 2, z_wall + toward * (ledge + width / 2)
            s.stairs(np.array([start, upper]), heading, width, altar, -altar, riser, tread)
            s.stairs(np.array([start + heading[0] * run, lower]), -heading, width, floor, altar - floor, riser, tread)
            # a landing 2.5 m long at each flight's top: a flight meets a floor beside it only at its last step
            for x_top, y_top, z_mid in ((start + heading[0] * run, 0.0, upper), (start, altar, lower)):
                x_far = x_top + heading[0] * 2.5 * (1.0 if y_top == 0.0 else -1.0)
                s.box(min(x_top, x_far), max(x_top, x_far), floor, y_top, z_mid - width / 2, z_mid + width / 2)
    # the gantry crane and its stair tower on the north quay
    xc = rng.uniform(dock_x0 + 30.0, dock_x1 - 30.0)
    while any(abs(xc - g) < 6.0 for g in gangways):
        xc += 7.0
    for lx in (xc - 5.0, xc + 4.0):
        for lz in (dock_z0 - 5.0, dock_z1 + 4.0):
            s.box(lx, lx + 1.0, 0.0, 13.0, lz, lz + 1.0)
    tower_z = dock_z1 + 9.0
    s.box(xc - 1.5, xc + 1.5, 13.0, 14.0, dock_z0 - 6.0, tower_z)
    for rail_x in (xc - 1.5, xc + 1.4):
        s.box(rail_x, rail_x + 0.1, 14.0, 15.1, dock_z0 - 6.0, tower_z - 2.0)
    s.box(xc - 1.5, xc + 1.5, 14.0, 15.1, dock_z0 - 6.0, dock_z0 - 5.9)
    for storey in range(4):
        _switchback(s, xc - 2.0, tower_z, 3.5 * storey, 3.5)
        s.box(xc - 2.0, xc + 2.0, 3.5 * (storey + 1) - 0.45, 3.5 * (storey + 1), tower_z, tower_z + 2.0)
    # workshops, containers and plate stacks (ridged: the quay stops under them)
    taken = [(xc - 7.0, xc + 7.0, dock_z1, tower_z + _well_length(3.5) + 2.0), (xc - 7.0, xc + 7.0, dock_z0 - 8.0, dock_z0),
             *[(g - 3.0, g + 3.0, dock_z1, dock_z1 + 6.0) for g in gangways], (0.0, dock_x0 + 2.0, mid - 4.0, mid + 4.0)]
    footprints: list[tuple[float, float, float, float]] = []
    wanted = [(rng.uniform(24.0, 36.0), rng.uniform(14.0, 18.0), 9.0) for _ in range(2)]
    wanted += [(12.2, 2.5, 2.6) for _ in range(int(rng.integers(24, 34)))]
    wanted += [(rng.uniform(4.0, 7.0), rng.uniform(2.0, 3.0), 1.2) for _ in range(int(rng.integers(18, 26)))]
    for size, depth, h in wanted:
        for _ in range(200):
            w, d = (depth, size) if size < 13.0 and rng.random() < 0.5 else (size, depth)
            x0 = rng.uniform(2.0, size_x - w - 2.0)
            z0 = rng.uniform(2.0, dock_z0 - d - 4.0) if rng.random() < 0.5 else rng.uniform(dock_z1 + 4.0, size_z - d - 2.0)
            if _clear(x0 - 2.5, x0 + w + 2.5, z0 - 2.5, z0 + d + 2.5, taken):
                taken.append((x0, x0 + w, z0, z0 + d))
                footprints.append(_ridged(s, x0, x0 + w, z0, z0 + d, -10.5, h))
                break
    s.ground(0.0, size_x, 0.0, size_z, 0.0, [(dock_x0, dock_x1, dock_z0, dock_z1), *footprints], thickness=10.5)
    for x in np.arange(dock_x0 + 4.0, dock_x1 - 2.0, rng.uniform(5.0, 6.0)):  # bollards along both edges
        for z in (dock_z0 - 1.4, dock_z1 + 1.0):
            if _clear(x - 0.5, x + 0.9, z - 0.5, z + 0.9, taken):
                s.box(x, x + 0.4, 0.0, 0.7, z, z + 0.4)
    return s.mesh()


def mountain_pass(seed: int) -> trimesh.Trimesh:
    """A mountain pass on a 1 m grid (:func:`_terrain`), 200 x 130 m: a valley floor to the south, a face rising
    24-30 m along +z to a plateau (the pass) from z = 100, and on the face two ways up. West of x = 110 the face is a
    cliff at 50-55 degrees, over the presets' 45-degree limit, climbed only by a switchback path: legs 4.5 m wide cut
    into it and built out from it (flat across, climbing along x at about 10 %, 15-100 m), hairpins joining them
    at alternate ends, a cut from the valley to the first leg and one from the last to the plateau. East of x = 140
    the face is a ski piste at 28-32 degrees that one walks anywhere; between the two it turns from one into the other.
    Ripples of 0.3 m on valley and plateau; a chair lift's stations (platforms 1.2 m over their highest ground, eight
    steps up from the side away from the face) in the valley and on the plateau with pylons between (no walk along the
    lift); three huts under ridged roofs in the valley (the ground stops under them) and a mountain hut one enters (a
    1.6 m door, a gable roof) on the plateau; up to 80-120 spruce trunks in the valley and on the plateau, 20-30
    boulders.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, z_top = 200.0, 130.0, 100.0
    rise = rng.uniform(24.0, 30.0)
    cliff, piste = math.radians(rng.uniform(50.0, 55.0)), math.radians(rng.uniform(28.0, 32.0))
    waves = [(0.15, rng.uniform(25.0, 60.0), rng.uniform(0, 2 * math.pi), rng.uniform(0, math.pi)) for _ in range(2)]

    def base(x: np.ndarray) -> np.ndarray:
        """The z where the face starts at ``x``."""
        angle = cliff + (piste - cliff) * np.clip((x - 110.0) / 30.0, 0.0, 1.0)
        return z_top - rise / np.tan(angle)

    def natural(x: np.ndarray, z: np.ndarray) -> np.ndarray:
        """The ground's height at plan points (x, z) without the path's cuts."""
        zb = base(x)
        ripple = sum(a * np.sin(2 * math.pi / length * (x * math.cos(turn) + z * math.sin(turn)) + phase)
                     for a, length, phase, turn in waves)
        return np.clip((z - zb) / (z_top - zb), 0.0, 1.0) * rise + ripple

    xs, zs = np.arange(0.0, size_x + 0.5, 1.0), np.arange(0.0, size_z + 0.5, 1.0)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    heights = natural(gx, gz)
    legs = math.ceil(rise / 8.5)
    west, east = rng.uniform(12.0, 18.0), rng.uniform(95.0, 100.0)
    face_depth = rise / math.tan(cliff)
    centres = z_top - face_depth + face_depth * (np.arange(legs) + 0.5) / legs
    half = 2.25
    ends = []
    for i, zc in enumerate(centres):
        y0, y1 = rise * i / legs, rise * (i + 1) / legs
        x0, x1 = (west, east) if i % 2 == 0 else (east, west)
        band = (np.abs(gz - zc) <= half) & (gx >= west - half) & (gx <= east + half)
        heights[band] = (y0 + (y1 - y0) * np.clip((gx - x0) / (x1 - x0), 0.0, 1.0))[band]
        ends.append((x1, y1))
    for i in range(legs - 1):  # hairpins
        x, y = ends[i]
        band = (np.abs(gx - x) <= half) & (gz >= centres[i]) & (gz <= centres[i + 1])
        heights[band] = y
    foot = (np.abs(gx - west) <= half) & (gz >= centres[0] - face_depth / legs - 4.0) & (gz <= centres[0])
    heights[foot] = np.minimum(heights[foot], 0.0)
    x, y = ends[-1]
    head = (np.abs(gx - x) <= half) & (gz >= centres[-1]) & (gz <= z_top + 4.0)
    heights[head] = np.maximum(heights[head], rise)
    path = [(west - 5.0, east + 5.0, z_top - face_depth - 6.0, z_top + 6.0)]

    def ground_at(x: float, z: float) -> float:
        return float(natural(np.array(x), np.array(z)))

    lift_x = rng.uniform(120.0, 130.0)
    low_z, high_z = float(base(np.array(lift_x))) - rng.uniform(12.0, 18.0), z_top + rng.uniform(8.0, 12.0)
    for z0, toward in ((low_z, -1.0), (high_z, 1.0)):  # the stations, steps on the side away from the face
        y = max(ground_at(x, z) for x in (lift_x - 3.0, lift_x + 3.0) for z in (z0 - 2.0, z0 + 2.0)) + 1.2
        foot = z0 + toward * (2.0 + 8 * 0.28)
        y_foot = ground_at(lift_x, foot)
        s.box(lift_x - 3.0, lift_x + 3.0, y - 3.2, y, z0 - 2.0, z0 + 2.0)
        s.stairs(np.array([lift_x, foot]), np.array([0.0, -toward]), 2.4, y_foot, y - y_foot, (y - y_foot) / 8, 0.28)
        path.append((lift_x - 5.0, lift_x + 5.0, z0 - 6.0, z0 + 6.0))
    for z in np.arange(low_z + 15.0, high_z - 5.0, 15.0):  # pylons
        y = ground_at(lift_x, z)
        s.box(lift_x - 0.4, lift_x + 0.4, y - 1.0, y + 9.0, z - 0.4, z + 0.4)
    hut_x = rng.uniform(20.0, 80.0)
    hut = (hut_x, hut_x + 10.0, z_top + 10.0, z_top + 17.0)
    under = [ground_at(x, z) for x in hut[:2] for z in hut[2:]]
    low, high = min(under) - 0.5, max(under) + 3.0
    s.wall((hut[0], hut[2]), (hut[1], hut[2]), low, high, [(rng.uniform(2.0, 6.0), 1.6)])
    s.wall((hut[0], hut[3]), (hut[1], hut[3]), low, high)
    for x in hut[:2]:
        s.wall((x, hut[2]), (x, hut[3]), low, high)
    _gable(s, hut[0] - 0.3, hut[1] + 0.3, hut[2] - 0.3, hut[3] + 0.3, high)
    path.append((hut[0] - 3.0, hut[1] + 3.0, hut[2] - 3.0, hut[3] + 3.0))
    keep = np.ones((len(xs) - 1, len(zs) - 1), dtype=bool)
    huts = 0
    for _ in range(500):
        if huts == 3:
            break
        x, z = float(rng.integers(5, int(size_x) - 12)), float(rng.integers(5, int(base(np.array(size_x))) - 12))
        if _clear(x - 3.0, x + 11.0, z - 3.0, z + 9.0, path) and z + 9.0 < float(base(np.array([x, x + 8.0])).min()) - 3.0:
            y = min(ground_at(x + dx, z + dz) for dx in (0.0, 8.0) for dz in (0.0, 6.0))
            _ridged(s, x, x + 8.0, z, z + 6.0, y - 1.0, y + 1.8)
            keep[int(x):int(x) + 8, int(z):int(z) + 6] = False  # the ground stops under the hut
            path.append((x, x + 8.0, z, z + 6.0))
            huts += 1
    _terrain(s, xs, zs, heights, keep=keep)
    for _ in range(int(rng.integers(80, 121))):
        p = np.array([rng.uniform(3.0, size_x - 3.0), rng.choice([rng.uniform(3.0, 60.0), rng.uniform(z_top + 3.0, size_z - 3.0)])])
        if (p[1] > z_top + 2.0 or p[1] < float(base(np.array(p[0]))) - 4.0) and _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, path):
            y = ground_at(*p)
            _trunk(s, p, 0.3, y - 0.5, y + 6.0)
    for _ in range(int(rng.integers(20, 31))):
        p = np.array([rng.uniform(5.0, size_x - 5.0), rng.choice([rng.uniform(5.0, 55.0), rng.uniform(z_top + 5.0, size_z - 5.0)])])
        if _clear(p[0] - 3.0, p[0] + 3.0, p[1] - 3.0, p[1] + 3.0, path) and (p[1] > z_top or p[1] < float(base(np.array(p[0]))) - 5.0):
            y = ground_at(*p)
            s.rock(rng, p, 0.7, y - 0.5, y + 1.5)
    return s.mesh()


def zoo(seed: int) -> trimesh.Trimesh:
    """A zoo 200 x 150 m on a 1 m grid (:func:`_terrain`, flat) behind a fence 2.5 m high, entered from a forecourt 15
    m deep through one gate 6 m wide. Its ground is the visitors' paths round 9-12 enclosures, irregular blobs 9-20 m
    across (an ellipse with two waves on its outline) kept 7 m apart: the ground stops inside each (no visitor goes
    in) and a rail 1.1 m high follows it 0.8 m out; every third enclosure has a viewing deck 3 m wide, railed,
    reaching 6 m into it through a gap in its rail. A walk-through aviary, a ring of net walls 6 m high and 28-34 m
    across, is entered only through two airlocks on opposite sides (a vestibule 3.5 m square: a 2 m opening on the
    aviary, an outer door 2 m wide set off to one side; 1.6 m, the first draft's, closed on one airlock of
    seeds 1 and 2, the ring being at an angle to the axes); inside, a pond crossed by a boardwalk 2 m wide, and trees.
    A reptile house (30 x 10 m under a lid, a 2 m door at each end, a 6 m hall between rows of glass tanks 2 m square
    under ridged tops), a cafe (a 3 m opening, tables), 12-20 planting beds (ridged, 0.6 m) and 50-80 trees on the
    paths; the ground stops under tanks and beds.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, front = 200.0, 150.0, 15.0
    xs, zs = np.arange(0.0, size_x + 0.5, 1.0), np.arange(-front, size_z + 0.5, 1.0)
    gx, gz = np.meshgrid(xs[:-1] + 0.5, zs[:-1] + 0.5, indexing="ij")
    keep = np.ones(gx.shape, dtype=bool)
    taken: list[tuple[float, float, float, float]] = [(size_x / 2 - 12.0, size_x / 2 + 12.0, 0.0, 12.0)]  # inside the gate
    aviary_c = np.array([rng.uniform(40.0, size_x - 40.0), rng.uniform(95.0, size_z - 25.0)])
    aviary_r = rng.uniform(14.0, 17.0)
    taken.append((*(aviary_c[0] + np.array([-1, 1]) * (aviary_r + 8.0)), *(aviary_c[1] + np.array([-1, 1]) * (aviary_r + 8.0))))
    house_x, house_z = float(round(rng.uniform(10.0, 80.0))), float(round(rng.uniform(20.0, 60.0)))
    house = (house_x, house_x + 30.0, house_z, house_z + 10.0)
    cafe_x, cafe_z = float(round(rng.uniform(120.0, 170.0))), float(round(rng.uniform(20.0, 50.0)))
    cafe = (cafe_x, cafe_x + 16.0, cafe_z, cafe_z + 10.0)
    for r in (house, cafe):
        taken.append((r[0] - 6.0, r[1] + 6.0, r[2] - 6.0, r[3] + 6.0))

    def outline(waves: np.ndarray, angle: np.ndarray) -> np.ndarray:
        """A blob's radius factor at polar angles ``angle`` about its centre; ``waves`` (4,): the amplitude and phase
        of its three-lobed wave, then of its five-lobed one."""
        return 1.0 + waves[0] * np.sin(3 * angle + waves[1]) + waves[2] * np.sin(5 * angle + waves[3])

    blobs = []
    count = int(rng.integers(9, 13))
    for _ in range(400):
        if len(blobs) == count:
            break
        c = np.array([rng.uniform(20.0, size_x - 20.0), rng.uniform(20.0, size_z - 15.0)])
        radii = rng.uniform(4.5, 10.0, size=2)
        reach = radii.max() * 1.2
        if all(np.linalg.norm(c - b[0]) > reach + b[1].max() * 1.2 + 7.0 for b in blobs) and \
                _clear(c[0] - reach - 4.0, c[0] + reach + 4.0, c[1] - reach - 4.0, c[1] + reach + 4.0, taken):
            blobs.append((c, radii, np.array([rng.uniform(0.05, 0.12), rng.uniform(0, 6.3), rng.uniform(0.0, 0.06),
                                              rng.uniform(0, 6.3)])))
    decks = []
    for k, (c, radii, waves) in enumerate(blobs):
        angle = np.arctan2((gz - c[1]) / radii[1], (gx - c[0]) / radii[0])
        rho = np.hypot((gx - c[0]) / radii[0], (gz - c[1]) / radii[1])
        keep &= rho >= outline(waves, angle)
        deck_angle = rng.uniform(0, 2 * math.pi) if k % 3 == 0 else None
        points = []
        for a in np.linspace(0, 2 * math.pi, 33):
            unit = np.array([math.cos(a) * radii[0], math.sin(a) * radii[1]])
            edge = c + unit * float(outline(waves, np.array(a)))
            points.append(edge + unit / np.linalg.norm(unit) * 0.8)
        if deck_angle is not None:
            unit = np.array([math.cos(deck_angle) * radii[0], math.sin(deck_angle) * radii[1]])
            edge = c + unit * float(outline(waves, np.array(deck_angle)))
            out = unit / np.linalg.norm(unit)
            decks.append((edge + out * 1.5, edge - out * 6.0, out))
        for a, b in pairwise(points):
            if deck_angle is not None and np.linalg.norm((a + b) / 2 - decks[-1][0]) < 2.6:
                continue
            s.prism(_strip(a, b, 0.12), -0.3, 1.1)
    for start, end, out in decks:
        s.prism(_strip(start, end, 3.0), -0.5, 0.0)
        side = np.array([-out[1], out[0]])
        for sign in (-1.45, 1.45):
            s.prism(_strip(start + side * sign - out * 0.7, end + side * sign, 0.1), -0.3, 1.1)
        s.prism(_strip(end - side * 1.5, end + side * 1.5, 0.1), -0.3, 1.1)
    # the aviary: a ring of 24 net walls, doors at ring segments 0 and 12
    door_angle = rng.uniform(0, 2 * math.pi)
    corners = [aviary_c + aviary_r * np.array([math.cos(a), math.sin(a)])
               for a in door_angle + 2 * math.pi * (np.arange(25) - 0.5) / 24]
    for k, (a, b) in enumerate(pairwise(corners)):
        if k % 12 == 0:
            along = (b - a) / np.linalg.norm(b - a)
            m = (a + b) / 2
            s.prism(_strip(a, m - along, 0.2), -0.3, 6.0)
            s.prism(_strip(m + along, b, 0.2), -0.3, 6.0)
            out = (m - aviary_c) / np.linalg.norm(m - aviary_c)
            for sign in (-1.75, 1.75):
                s.prism(_strip(m + along * sign, m + along * sign + out * 3.5, 0.2), -0.3, 3.0)
            far = m + out * 3.5
            s.prism(_strip(far - along * 1.75, far - along * 0.5, 0.2), -0.3, 3.0)
            s.prism(_strip(far + along * 1.5, far + along * 1.75, 0.2), -0.3, 3.0)
        else:
            s.prism(_strip(a, b, 0.2), -0.3, 6.0)
    pond_c, pond_r = aviary_c + rng.uniform(-2.0, 2.0, size=2), rng.uniform(3.5, 5.0)
    keep &= np.hypot(gx - pond_c[0], gz - pond_c[1]) >= pond_r
    walk = rng.uniform(0, math.pi)
    direction = np.array([math.cos(walk), math.sin(walk)])
    s.prism(_strip(pond_c - direction * (pond_r + 2.0), pond_c + direction * (pond_r + 2.0), 2.0), -0.5, 0.25)
    for _ in range(int(rng.integers(12, 20))):
        p = aviary_c + rng.uniform(-1, 1, size=2) * aviary_r * 0.7
        if np.linalg.norm(p - pond_c) > pond_r + 1.5 and abs(direction[0] * (p - pond_c)[1] - direction[1] * (p - pond_c)[0]) > 2.0:
            _trunk(s, p, 0.3, -0.5, 5.0)
    # the reptile house and the cafe
    s.wall((house[0], house[2]), (house[1], house[2]), -0.3, 3.5)
    s.wall((house[0], house[3]), (house[1], house[3]), -0.3, 3.5)
    for x in house[:2]:
        s.wall((x, house[2]), (x, house[3]), -0.3, 3.5, [(4.0, 2.0)])
    solids: list[tuple[float, float, float, float]] = []
    for z0, z1 in ((house[2], house[2] + 2.0), (house[3] - 2.0, house[3])):
        for x in np.arange(house[0] + 2.0, house[1] - 2.0, 3.0):
            solids.append(_ridged(s, float(x), float(x) + 2.0, z0, z1, -0.3, 1.3))
    _lid(s, house[0], house[1], house[2], house[3], 3.5)
    s.wall((cafe[0], cafe[2]), (cafe[1], cafe[2]), -0.3, 3.2, [(rng.uniform(2.0, 11.0), 3.0)])
    s.wall((cafe[0], cafe[3]), (cafe[1], cafe[3]), -0.3, 3.2)
    for x in cafe[:2]:
        s.wall((x, cafe[2]), (x, cafe[3]), -0.3, 3.2)
    _lid(s, cafe[0], cafe[1], cafe[2], cafe[3], 3.2)
    for x in np.arange(cafe[0] + 2.0, cafe[1] - 1.5, 3.0):
        for z in np.arange(cafe[2] + 3.0, cafe[3] - 1.5, 3.0):
            s.box(float(x), float(x) + 0.9, 0.0, 0.75, float(z), float(z) + 0.9)
    taken += [(c[0] - r.max() * 1.2 - 2.0, c[0] + r.max() * 1.2 + 2.0, c[1] - r.max() * 1.2 - 2.0, c[1] + r.max() * 1.2 + 2.0)
              for c, r, _ in blobs]
    beds, wanted_beds = 0, int(rng.integers(12, 21))
    for _ in range(400):
        if beds == wanted_beds:
            break
        w, d = float(rng.integers(3, 8)), float(rng.integers(2, 4))
        x0, z0 = float(rng.integers(4, int(size_x - w - 4))), float(rng.integers(4, int(size_z - d - 4)))
        if _clear(x0 - 3.0, x0 + w + 3.0, z0 - 3.0, z0 + d + 3.0, taken):
            solids.append(_ridged(s, x0, x0 + w, z0, z0 + d, -0.3, 0.6))
            taken.append(solids[-1])
            beds += 1
    for x0, x1, z0, z1 in solids:
        keep &= ~((gx > x0) & (gx < x1) & (gz > z0) & (gz < z1))
    trees, wanted = 0, int(rng.integers(50, 81))
    for _ in range(600):  # trees along the paths
        if trees == wanted:
            break
        p = np.array([rng.uniform(3.0, size_x - 3.0), rng.uniform(3.0, size_z - 3.0)])
        if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken):
            _trunk(s, p, 0.3, -0.5, 5.0)
            taken.append((p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0))
            trees += 1
    _terrain(s, xs, zs, np.zeros((len(xs), len(zs))), keep=keep)
    s.wall((0.0, 0.0), (size_x, 0.0), -0.3, 2.5, [(size_x / 2 - 3.0, 6.0)])
    s.wall((0.0, size_z), (size_x, size_z), -0.3, 2.5)
    for x in (0.0, size_x):
        s.wall((x, 0.0), (x, size_z), -0.3, 2.5)
    return s.mesh()


def skatepark(seed: int) -> trimesh.Trimesh:
    """A skate park 140 x 110 m on a 0.5 m grid (:func:`_terrain`): a plaza at y = 0 holding, kept 4 m apart, three or
    four bowls (radius 6-9 m, 2.4-3.2 m deep: a flat bottom and a quarter-circle wall as deep as the bowl, which
    turns vertical at the lip, so only its lowest 29 % is under the 45-degree limit and the bottom is out of reach on
    foot) of which the first is entered by a channel 3 m wide sloping at 18 degrees down through its wall; three to
    five quarter pipes (a bank at 20 degrees up to a deck 2.5 m deep, 2.2 m up, then the quarter-circle down to the
    plaza; steep sides); three to five funboxes (1 m up, 20-degree banks at both ends); two pyramids (25-degree faces
    to a top 1.2 m up); and two stair sets: a block 1.35 m up with steep sides, climbed by a flight 3 m wide (nine 0.15
    / 0.30 m steps; the flight covers the block's steep edge). 45-60 ledges (0.45 m high, 0.6 m wide, 3-6 m long) and
    as many light poles stand on the plaza, benches and ledges along its edges.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, step = 140.0, 110.0, 0.5
    xs, zs = np.arange(0.0, size_x + step / 2, step), np.arange(0.0, size_z + step / 2, step)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    heights = np.zeros(gx.shape)
    taken: list[tuple[float, float, float, float]] = []

    def place(w: float, d: float) -> tuple[float, float]:
        """A free plan corner (x0, z0) for a w x d feature, 4 m from every other and 6 m from the edges."""
        for _ in range(500):
            x0, z0 = rng.uniform(6.0, size_x - w - 6.0), rng.uniform(6.0, size_z - d - 6.0)
            if _clear(x0 - 4.0, x0 + w + 4.0, z0 - 4.0, z0 + d + 4.0, taken):
                taken.append((x0, x0 + w, z0, z0 + d))
                return x0, z0
        raise RuntimeError("no room for a skate park feature")

    for k in range(int(rng.integers(3, 5))):
        r, depth = rng.uniform(6.0, 9.0), rng.uniform(2.4, 3.2)
        channel = depth / math.tan(math.radians(18.0))
        reach = r - depth + channel if k == 0 else r
        x0, z0 = place(2 * reach, 2 * reach)
        c = np.array([x0 + reach, z0 + reach])
        u = np.clip(np.hypot(gx - c[0], gz - c[1]) - (r - depth), 0.0, None)
        bowl = np.where(u < depth, -np.sqrt(np.clip(depth ** 2 - u ** 2, 0.0, None)), 0.0)
        if k == 0:
            turn = rng.integers(4) * math.pi / 2
            along, across = (gx - c[0]) * math.cos(turn) + (gz - c[1]) * math.sin(turn), \
                -(gx - c[0]) * math.sin(turn) + (gz - c[1]) * math.cos(turn)
            floor = -depth + np.clip(along - (r - depth), 0.0, None) * math.tan(math.radians(18.0))
            bowl = np.where((np.abs(across) <= 1.5) & (along >= 0.0), np.minimum(floor, 0.0), bowl)
        heights = np.minimum(heights, bowl)
    for _ in range(int(rng.integers(3, 6))):  # quarter pipes along x or z
        width, top = rng.uniform(6.0, 10.0), 2.2
        bank = top / math.tan(math.radians(20.0))
        length = bank + 2.5 + top
        along_x = rng.random() < 0.5
        x0, z0 = place(length, width) if along_x else place(width, length)
        t = (gx - x0) if along_x else (gz - z0)
        inside = ((gz >= z0) & (gz <= z0 + width)) if along_x else ((gx >= x0) & (gx <= x0 + width))
        curve = np.clip(t - bank - 2.5, 0.0, top)
        profile = np.where(t < bank, t * math.tan(math.radians(20.0)), np.where(t <= bank + 2.5, top,
                                                                                top - np.sqrt(np.clip(top ** 2 - (top - curve) ** 2, 0, None))))
        heights = np.where(inside & (t >= 0.0) & (t <= length), np.maximum(heights, profile), heights)
    for _ in range(int(rng.integers(3, 6))):  # funboxes
        top, width, flat = 1.0, rng.uniform(3.0, 4.0), rng.uniform(4.0, 6.0)
        bank = top / math.tan(math.radians(20.0))
        length = 2 * bank + flat
        along_x = rng.random() < 0.5
        x0, z0 = place(length, width) if along_x else place(width, length)
        t = (gx - x0) if along_x else (gz - z0)
        inside = ((gz >= z0) & (gz <= z0 + width)) if along_x else ((gx >= x0) & (gx <= x0 + width))
        profile = np.clip(np.minimum(t, length - t) * math.tan(math.radians(20.0)), 0.0, top)
        heights = np.where(inside & (t >= 0.0) & (t <= length), np.maximum(heights, profile), heights)
    for _ in range(2):  # pyramids
        x0, z0 = place(8.0, 8.0)
        pyramid = np.clip((4.0 - np.maximum(np.abs(gx - x0 - 4.0), np.abs(gz - z0 - 4.0))) * math.tan(math.radians(25.0)), 0.0, 1.2)
        heights = np.where(pyramid > 0.0, np.maximum(heights, pyramid), heights)
    for _ in range(2):  # stair sets: a block, a flight up its south side
        x0, z0 = (round(v / step) * step for v in place(10.0, 9.0))
        block = (gx >= x0) & (gx <= x0 + 10.0) & (gz >= z0 + 3.0) & (gz <= z0 + 9.0)
        heights = np.where(block, 1.35, heights)
        s.stairs(np.array([x0 + rng.uniform(2.5, 7.5), z0 + 0.5]), np.array([0.0, 1.0]), 3.0, 0.0, 1.35, 0.15, 0.30)
    _terrain(s, xs, zs, heights)
    for _ in range(int(rng.integers(45, 61))):  # ledges and light poles on the open plaza
        length = rng.uniform(3.0, 6.0)
        x0, z0 = place(length, 0.6) if rng.random() < 0.5 else place(0.6, length)
        s.box(x0, x0 + (taken[-1][1] - taken[-1][0]), -0.3, 0.45, z0, z0 + (taken[-1][3] - taken[-1][2]))
        x0, z0 = place(0.3, 0.3)
        s.box(x0, x0 + 0.3, -0.3, 6.0, z0, z0 + 0.3)
    for _ in range(int(rng.integers(8, 14))):  # benches and ledges along the edges
        along_x = rng.random() < 0.5
        length = rng.uniform(2.0, 6.0)
        if along_x:
            x, z = rng.uniform(2.0, size_x - length - 2.0), rng.choice([rng.uniform(0.5, 3.0), rng.uniform(size_z - 3.5, size_z - 1.0)])
            s.box(x, x + length, -0.3, 0.45, z, z + 0.5)
        else:
            x, z = rng.choice([rng.uniform(0.5, 3.0), rng.uniform(size_x - 3.5, size_x - 1.0)]), rng.uniform(2.0, size_z - length - 2.0)
            s.box(x, x + 0.5, -0.3, 0.45, z, z + length)
    return s.mesh()


def _escalators(s: _Solids, x0: float, z0: float, toward: float, top: float, drop: float) -> None:
    """A bank of three escalators as ramps 1.6 m wide at 30 degrees, side by side from x0 along +x (5.4 m in all,
    balustrades 1 m high and 0.15 m thick between and beside them), from plan z ``z0`` at height ``top`` heading along
    z by ``toward`` (+1 or -1) down ``drop`` m."""
    length = drop / math.tan(math.radians(30.0))
    for k in range(4):
        rail = x0 + k * 1.75 + 0.075
        s.ramp(np.array([rail, z0]), np.array([rail, z0 + toward * length]), 0.15, top + 1.0, top - drop + 1.0, thickness=1.2)
    for k in range(3):
        lane = x0 + 0.15 + k * 1.75 + 0.8
        s.ramp(np.array([lane, z0]), np.array([lane, z0 + toward * length]), 1.6, top, top - drop)


def interchange(seed: int) -> trimesh.Trimesh:
    """A metro interchange of three lines at three depths, crossing: a concourse at y = 0 (50 x 36 m, walled; a gate
    line of barriers with eight 1.4 m gaps across it, two street stairs up 4.5 m to dead-end exits); line A's island
    platform (100 m along x, 12 m wide) 8 m down, line B's (along z, 125 m) 16 m down passing under A, line C's (along
    x, 100 m) 24 m down passing under B; the tracks either side of each island have no floor. Banks of three
    escalators (:func:`_escalators`, ramps at 30 degrees) join the concourse to A (two banks), A to B (one bank,
    beside a fixed flight of 50 0.16 / 0.30 m steps) and B to C (one bank, through a hole in B's platform railed on
    both sides). Columns 0.6 m square every 4.5-5.5 m in two rows on each platform (stopping 1.7 m under the platform
    above, so their tops are no floor), benches; C is reached only down its one bank.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    drop = 8.0
    length = drop / math.tan(math.radians(30.0))
    cx0, cx1, cz0, cz1 = 25.0, 75.0, 24.0, 60.0
    a_z, b_x, c_z = (4.0, 16.0), (80.0, 92.0), (70.0, 82.0)
    banks_a = [rng.uniform(cx0 + 3.0, 45.0), rng.uniform(52.0, cx1 - 7.5)]
    bank_b, flight_b = b_x[0] + rng.uniform(0.5, 2.5), b_x[1] - 3.0
    bank_c = rng.uniform(b_x[0] + 1.0, b_x[1] - 6.6)
    c_start = c_z[0] + 1.0 - length + rng.uniform(0.0, 4.0)
    # concourse
    s.box(cx0, cx1, -0.3, 0.0, cz0, cz1)
    gate_z = rng.uniform(38.0, 46.0)
    exits = [rng.uniform(cx0 + 3.0, 45.0), rng.uniform(52.0, cx1 - 6.0)]
    s.wall((cx0, cz1), (cx1, cz1), -0.3, 4.0, [(x - cx0, 3.0) for x in exits])
    for x in (cx0, cx1):
        s.wall((x, cz0), (x, cz1), -0.3, 4.0)
    s.wall((cx0, cz0), (cx1, cz0), 0.0, 1.1, [(x - cx0, 5.4) for x in sorted(banks_a)])
    barrier_x = cx0 + 12.0
    s.wall((cx0, gate_z), (barrier_x, gate_z), 0.0, 1.1, thickness=0.6)
    for _ in range(8):
        s.box(barrier_x, barrier_x + 1.4, 0.0, 1.1, gate_z - 1.0, gate_z + 1.0)
        barrier_x += 2.8
    s.wall((barrier_x, gate_z), (cx1, gate_z), 0.0, 1.1, thickness=0.6)
    for x in exits:
        s.stairs(np.array([x + 1.5, cz1]), np.array([0.0, 1.0]), 3.0, 0.0, 4.5, 0.16, 0.30)
        s.box(x - 1.5, x + 4.5, 4.2, 4.5, cz1 + 8.4, cz1 + 12.4)
    for x in banks_a:
        _escalators(s, x, cz0, -1.0, 0.0, drop)
    # line A along x, B along z under it, C along x under B
    s.box(0.0, 100.0, -drop - 0.3, -drop, *a_z)
    _escalators(s, bank_b, a_z[1], 1.0, -drop, drop)
    s.stairs(np.array([flight_b + 1.25, a_z[0] - 50 * 0.30]), np.array([0.0, 1.0]), 2.5, -2 * drop, drop, 0.16, 0.30)
    hole = (bank_c - 0.2, bank_c + 5.6, c_start, c_start + length + 1.0)
    s.slab(b_x[0], b_x[1], -25.0, 100.0, -2 * drop, [hole])
    for x in (hole[0] - 0.15, hole[1]):
        s.box(x, x + 0.15, -2 * drop, -2 * drop + 1.1, hole[2], hole[3])
    s.box(hole[0] - 0.15, hole[1] + 0.15, -2 * drop, -2 * drop + 1.1, hole[3], hole[3] + 0.15)
    _escalators(s, bank_c, c_start, 1.0, -2 * drop, drop)
    s.box(10.0, 110.0, -3 * drop - 0.3, -3 * drop, *c_z)
    keep_out = [(x - 0.5, x + 5.9, a_z[0], cz0) for x in banks_a] + [(bank_b - 0.5, bank_b + 5.9, a_z[0], a_z[1] + length + 1.0),
                                                                    (flight_b - 0.5, flight_b + 3.0, a_z[0] - 16.0, a_z[0]), hole,
                                                                    (bank_c - 0.5, bank_c + 5.9, hole[2], hole[3] + 1.5)]
    # columns and benches
    spacing = rng.uniform(4.5, 5.5)
    for level, (lo, hi), along_x, (u0, u1) in ((1, a_z, True, (0.0, 100.0)), (2, b_x, False, (-25.0, 100.0)),
                                               (3, c_z, True, (10.0, 110.0))):
        y = -drop * level
        for across in (lo + 3.0, hi - 3.6):
            for u in np.arange(u0 + spacing / 2, u1 - 1.0, spacing):
                x0, z0 = (u, across) if along_x else (across, u)
                if _clear(x0 - 0.3, x0 + 0.9, z0 - 0.3, z0 + 0.9, keep_out):
                    s.box(x0, x0 + 0.6, y, y + drop - 2.0 + 0.3, z0, z0 + 0.6)
                b0, c0 = (u + spacing / 2 - 1.0, across) if along_x else (across, u + spacing / 2 - 1.0)
                b1, c1 = (b0 + 2.0, c0 + 0.5) if along_x else (b0 + 0.5, c0 + 2.0)
                if rng.random() < 0.6 and u + spacing / 2 < u1 - 2.0 and _clear(b0 - 0.5, b1 + 0.5, c0 - 0.5, c1 + 0.5, keep_out):
                    s.box(b0, b1, y, y + 0.45, c0, c1)
    return s.mesh()


def stepwell(seed: int) -> trimesh.Trimesh:
    """A stepwell: a rectangular pit 60-80 x 52-60 m at the rim, in a plaza 16 m wide round it, stepping down in four
    or five ring terraces 1.8 m below one another (more than the agent's climb: the terraces' faces are walls) to a
    pool with no floor (no floor over the water). Each terrace is 5 m wide or more; flights of ten 0.18 / 0.28 m steps,
    2.4 m wide, stand on a terrace against the face of the one above, square to it (a flight meets a floor beside it
    at its first and last steps only, so each is entered from the 2.2 m or more in front of its foot): two on each side of the even
    terraces (at a quarter and three quarters of the side), one in the middle of each side of the odd ones, so the
    way down zig-zags and every side offers the same choices. A parapet 0.9 m high rings the rim, open at the top
    flights. A row of pillars (0.6 m square, 3.6 m high, every 2.4-3 m) stands 1.5 m from the face along each side of
    every terrace, kept 2.4 m from the flights; shrines (ridged, the plaza stops under them) and trees stand in the
    plaza.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    rz0 = rng.uniform(26.0, 30.0)
    rx0 = rz0 + rng.uniform(4.0, 10.0)
    pool = rng.uniform(3.5, 5.0, size=2)
    rings = min(5, int((rz0 - pool[1]) // 5.0))
    rise, bottom = 1.8, -1.8 * rings - 1.0
    half = [np.array([rx0 - (rx0 - pool[0]) * k / rings, rz0 - (rz0 - pool[1]) * k / rings]) for k in range(rings + 1)]
    spacing = rng.uniform(2.4, 3.0)
    for k in range(rings):
        top = -rise * (k + 1)
        (ox, oz), (ix, iz) = half[k], half[k + 1]
        s.ground(-ox, ox, -oz, oz, top, [(-ix, ix, -iz, iz)], thickness=top - bottom)
        for axis in (0, 1):
            for sign in (-1.0, 1.0):
                normal = np.zeros(2)
                normal[axis] = sign
                tangent = np.array([-normal[1], normal[0]])
                offsets = (-0.5, 0.5) if k % 2 == 0 else (0.0,)
                for off in offsets:
                    start = normal * (half[k][axis] - 2.8) + tangent * off * half[k + 1][1 - axis]
                    s.stairs(start, normal, 2.4, top, rise, rise / 10, 0.28)
                flights = [off * half[k + 1][1 - axis] for off in offsets]
                for u in np.arange(-half[k + 1][1 - axis] + spacing / 2, half[k + 1][1 - axis], spacing):  # pillars
                    if all(abs(u - f) > 2.4 for f in flights):
                        p = normal * (half[k][axis] - 1.5) + tangent * u
                        s.box(p[0] - 0.3, p[0] + 0.3, top, top + 3.6, p[1] - 0.3, p[1] + 0.3)
    size = 16.0
    footprints = [(-rx0, rx0, -rz0, rz0)]
    for x in (-rx0 - 8.0, rx0 + 3.0):
        for z in (-rz0 - 8.0, rz0 + 3.0):
            if rng.random() < 0.75:
                footprints.append(_ridged(s, x, x + 5.0, z, z + 5.0, bottom, 2.5))
    for axis, r in ((0, rx0), (1, rz0)):
        other = half[0][1 - axis]
        gaps = [(other + off * half[1][1 - axis] - 1.5, 3.0) for off in (-0.5, 0.5)]
        for sign in (-1.0, 1.0):
            line = sign * (r + 0.15)
            a, b = ((line, -other), (line, other)) if axis == 0 else ((-other, line), (other, line))
            s.wall(a, b, 0.0, 0.9, gaps, thickness=0.3)
    for _ in range(int(rng.integers(20, 30))):
        p = np.array([rng.uniform(-rx0 - size + 1.5, rx0 + size - 1.5), rng.uniform(-rz0 - size + 1.5, rz0 + size - 1.5)])
        if _clear(p[0] - 2.0, p[0] + 2.0, p[1] - 2.0, p[1] + 2.0, footprints):
            _trunk(s, p, 0.35, -0.5, 6.0)
    s.ground(-rx0 - size, rx0 + size, -rz0 - size, rz0 + size, 0.0, footprints, thickness=-bottom)
    return s.mesh()


def _stile(s: _Solids, p: np.ndarray, normal: np.ndarray, width: float) -> None:
    """A stile over a fence at plan point ``p`` (x, z), the fence square to the unit ``normal`` (x, z): five 0.18 /
    0.28 m steps up from each side to a top 0.6 m deep at 0.9 m over the fence line, ``width`` m wide (the fence
    leaves a gap for it). A flight meets the ground only at its first step, so each is walked onto head-on."""
    run = 5 * 0.28
    for side in (-1.0, 1.0):
        s.stairs(p + normal * side * (0.3 + run), -normal * side, width, 0.0, 0.9, 0.18, 0.28)
    s.prism(_strip(p - normal * 0.3, p + normal * 0.3, width), -0.3, 0.9)


def farm(seed: int) -> trimesh.Trimesh:
    """A farm 210 x 160 m of flat ground cut by fences (post-and-rail, 1.2 m high) and hedges (1.4 m wide, ridged)
    into a 3 x 3 grid of fields round a farmyard in the middle. The farmyard opens through a gate 4 m wide onto each
    of the four fields beside it and onto the lane through the south field; between outer fields a fence holds one
    or two stiles (:func:`_stile`, 1.8 m wide, 0.9 m up) or nothing, a hedge a gap 2.5 m wide or nothing, and every
    corner field has at least one way in. In the farmyard a farmhouse (ridged), a silo (an octagon 3 m in radius,
    pointed) and two barns 20-24 x 12-14 m under a roof at 50 degrees (:func:`_lid`, 6.5 m): a door 4 m wide,
    machines (ridged), and a loft over half the barn 3.2 m up reached only by a ladder (a board 0.1 m deep no agent
    climbs), so each loft is an area of its own. Haystacks (ridged), round bales, trees and a pond (no floor) in the
    fields; the ground stops under every ridged solid and the silo.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = 210.0, 160.0
    xc = [0.0, 70.0 + rng.uniform(-8.0, 8.0), 140.0 + rng.uniform(-8.0, 8.0), size_x]
    zc = [0.0, 55.0 + rng.uniform(-6.0, 6.0), 105.0 + rng.uniform(-6.0, 6.0), size_z]
    holes: list[tuple[float, float, float, float]] = []
    taken: list[tuple[float, float, float, float]] = []
    # boundaries between fields: (fixed coordinate, axis of the line, lo, hi, hedge, ways); every corner field keeps
    # at least one way in (the four fields beside the yard open on it through gates)
    bounds = []
    for i in (1, 2):
        for j in range(3):
            for line, along, lo, hi, pair in ((xc[i], 1, zc[j], zc[j + 1], ((i - 1, j), (i, j))),
                                              (zc[i], 0, xc[j], xc[j + 1], ((j, i - 1), (j, i)))):
                length = hi - lo
                if (1, 1) in pair:
                    bounds.append([line, along, lo, hi, False, [("gate", rng.uniform(6.0, length - 10.0))], pair])
                    continue
                hedge = rng.random() < 0.35
                if hedge:
                    ways = [("gap", rng.uniform(6.0, length - 9.0))] if rng.random() < 0.75 else []
                else:
                    ways = [("stile", t) for t in np.sort(rng.uniform(8.0, length - 8.0, size=int(rng.choice([0, 1, 1, 2]))))]
                    if len(ways) == 2 and ways[1][1] - ways[0][1] < 6.0:
                        ways = ways[:1]
                bounds.append([line, along, lo, hi, hedge, ways, pair])
    for corner in ((0, 0), (0, 2), (2, 0), (2, 2)):
        own = [b for b in bounds if corner in b[6]]
        if not any(b[5] for b in own):
            b = own[int(rng.integers(len(own)))]
            b[5] = [("gap", (b[3] - b[2]) / 2)] if b[4] else [("stile", (b[3] - b[2]) / 2)]
    widths = {"gate": 4.0, "gap": 2.5, "stile": 1.8}
    for line, along, lo, hi, hedge, ways, _ in bounds:
        doors = [(t, widths[kind]) for kind, t in ways]
        start = (line, lo) if along == 1 else (lo, line)
        end = (line, hi) if along == 1 else (hi, line)
        if hedge:
            cuts = [lo, *sum(([lo + t, lo + t + w] for t, w in doors), []), hi]
            for c0, c1 in zip(cuts[0::2], cuts[1::2]):
                rect = (line - 0.7, line + 0.7, c0, c1) if along == 1 else (c0, c1, line - 0.7, line + 0.7)
                if along == 1:  # a hedge along z: ridged along z
                    s.hull(np.array([[x, y, z] for x in rect[:2] for y in (-0.5, 1.6) for z in rect[2:]]
                                    + [[line, 2.4, z] for z in rect[2:]]))
                else:
                    _ridged(s, *rect, -0.5, 1.6)
                holes.append(rect)
        else:
            s.wall(start, end, -0.3, 1.2, doors, thickness=0.12)
            for kind, t in ways:
                if kind == "stile":
                    p = np.array([line, lo + t + 0.9]) if along == 1 else np.array([lo + t + 0.9, line])
                    _stile(s, p, np.array([1.0, 0.0]) if along == 1 else np.array([0.0, 1.0]), 1.8)
        for t, w in doors:
            c = lo + t + w / 2
            taken.append((line - 4.0, line + 4.0, c - 4.0, c + 4.0) if along == 1 else (c - 4.0, c + 4.0, line - 4.0, line + 4.0))
        taken.append((line - 1.5, line + 1.5, lo, hi) if along == 1 else (lo, hi, line - 1.5, line + 1.5))
    # the outer fence, the lane's gate in the south one
    lane = rng.uniform(xc[1] + 8.0, xc[2] - 12.0)
    s.wall((0.0, 0.0), (size_x, 0.0), -0.3, 1.2, [(lane, 4.0)], thickness=0.12)
    s.wall((0.0, size_z), (size_x, size_z), -0.3, 1.2, thickness=0.12)
    for x in (0.0, size_x):
        s.wall((x, 0.0), (x, size_z), -0.3, 1.2, thickness=0.12)
    taken.append((lane - 2.0, lane + 6.0, 0.0, zc[1] + 6.0))  # the lane up the south field, kept clear
    # the farmyard
    yx0, yx1, yz0, yz1 = xc[1] + 4.0, xc[2] - 4.0, zc[1] + 4.0, zc[2] - 4.0
    for k, x0 in enumerate((yx0 + 2.0, yx1 - 24.0 - 2.0)):
        bl, bd = rng.uniform(20.0, 24.0), rng.uniform(12.0, 14.0)
        z0 = yz1 - bd - 2.0 if k == 0 else yz0 + 2.0
        x1, z1 = x0 + bl, z0 + bd
        door_wall = z0 if k == 0 else z1
        back_wall = z1 if k == 0 else z0
        s.wall((x0, door_wall), (x1, door_wall), -0.3, 6.5, [(bl / 2 - 2.0, 4.0)])
        s.wall((x0, back_wall), (x1, back_wall), -0.3, 6.5)
        for x in (x0, x1):
            s.wall((x, z0), (x, z1), -0.3, 6.5)
        loft_x = x0 + bl / 2 if rng.random() < 0.5 else x0
        s.box(loft_x, loft_x + bl / 2, 2.9, 3.2, z0 + 0.1, z1 - 0.1)
        edge = loft_x if loft_x > x0 else loft_x + bl / 2
        s.box(edge - 0.05, edge + 0.05, 0.0, 3.2, (z0 + z1) / 2 - 0.3, (z0 + z1) / 2 + 0.3)  # the ladder
        for _ in range(int(rng.integers(2, 5))):  # bales on the loft
            bx = rng.uniform(loft_x + 1.0, loft_x + bl / 2 - 3.0)
            bz = rng.uniform(z0 + 1.0, z1 - 3.0)
            s.box(bx, bx + 2.0, 3.2, 4.2, bz, bz + 1.2)
        ground_x = (x0, x0 + bl / 2) if loft_x > x0 else (x0 + bl / 2, x1)
        machine_x = rng.uniform(ground_x[0] + 1.5, ground_x[1] - 5.5)
        holes.append(_ridged(s, machine_x, machine_x + 4.0, z0 + 2.5, z0 + 5.0, -0.5, 2.0))
        _lid(s, x0, x1, z0, z1, 6.5)
        taken.append((x0 - 3.0, x1 + 3.0, z0 - 3.0, z1 + 3.0))
    house_x = rng.uniform(yx0 + 2.0, yx1 - 16.0)
    house_z = (yz0 + yz1) / 2 - 4.5
    if _clear(house_x - 3.0, house_x + 15.0, house_z - 3.0, house_z + 12.0, taken):
        holes.append(_ridged(s, house_x, house_x + 12.0, house_z, house_z + 9.0, -0.5, 6.0))
        taken.append((house_x - 3.0, house_x + 15.0, house_z - 3.0, house_z + 12.0))
    for _ in range(100):  # the silo
        c = np.array([rng.uniform(yx0 + 5.0, yx1 - 5.0), rng.uniform(yz0 + 5.0, yz1 - 5.0)])
        if _clear(c[0] - 5.0, c[0] + 5.0, c[1] - 5.0, c[1] + 5.0, taken):
            angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
            ring = c + 3.0 * np.stack([np.cos(angles), np.sin(angles)], 1)
            s.hull(np.array([[p[0], y, p[1]] for p in ring for y in (-0.5, 14.0)] + [[c[0], 18.0, c[1]]]))
            holes.append((c[0] - 3.0, c[0] + 3.0, c[1] - 3.0, c[1] + 3.0))
            taken.append((c[0] - 5.0, c[0] + 5.0, c[1] - 5.0, c[1] + 5.0))
            break
    for i in range(3):
        for j in range(3):
            x0, x1, z0, z1 = xc[i] + 3.0, xc[i + 1] - 3.0, zc[j] + 3.0, zc[j + 1] - 3.0
            if (i, j) == (1, 1):
                count = int(rng.integers(6, 10))  # carts and bale stacks in the yard
            else:
                count = int(rng.integers(4, 9))
            if (i, j) != (1, 1) and rng.random() < 0.2:  # a pond
                c = np.array([rng.uniform(x0 + 12.0, x1 - 12.0), rng.uniform(z0 + 10.0, z1 - 10.0)])
                if _clear(c[0] - 9.0, c[0] + 9.0, c[1] - 7.0, c[1] + 7.0, taken):
                    holes.append((c[0] - 7.0, c[0] + 7.0, c[1] - 5.0, c[1] + 5.0))
                    taken.append((c[0] - 9.0, c[0] + 9.0, c[1] - 7.0, c[1] + 7.0))
            placed = 0
            for _ in range(200):
                if placed == count:
                    break
                w, d = rng.uniform(3.0, 6.0), rng.uniform(2.5, 4.0)
                px, pz = rng.uniform(x0, x1 - w), rng.uniform(z0, z1 - d)
                if _clear(px - 3.0, px + w + 3.0, pz - 3.0, pz + d + 3.0, taken):
                    holes.append(_ridged(s, px, px + w, pz, pz + d, -0.5, 2.2))
                    taken.append((px - 1.0, px + w + 1.0, pz - 1.0, pz + d + 1.0))
                    placed += 1
            for _ in range(int(rng.integers(6, 16))):  # round bales (1.5 m, too high to climb) and trees
                p = np.array([rng.uniform(x0, x1), rng.uniform(z0, z1)])
                if _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, taken):
                    _trunk(s, p, 0.8 if rng.random() < 0.6 else 0.35, -0.5, 1.5 if rng.random() < 0.6 else 8.0)
                    taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    s.ground(0.0, size_x, 0.0, size_z, 0.0, holes)
    return s.mesh()


def cruise_ship(seed: int) -> trimesh.Trimesh:
    """A cruise ship's open decks: five decks 3 m apart (y = 0 to 12), 28-32 m in beam, the lowest 230-250 m long,
    each deck above starting 12-16 m further forward at the stern and ending 6-10 m further aft at the bow, so each
    deck's ends are open terraces under the sky. A closed block of cabins about 4 m shorter than the top deck stands
    from under the lowest deck to the top one (the decks stop at it; its top is the sun deck's floor), leaving on each
    lower deck a covered promenade 3.5-4.5 m wide along each side, the block cut across every 30-45 m by a passage 2.5 m wide; two flights 2 m wide (17 steps of 0.176 / 0.28 m) climb from each stern
    terrace head-on onto the stern edge of the deck above and one from each bow terrace onto its bow edge: the only
    ways between decks. Rails 1.1 m high along every open edge, open at the flights' heads. The top (sun) deck holds
    two or three pools (lanes 2 m wide, ridged, 0.5 m: no floor inside), rows of loungers (ridged, 0.45 m) and bar
    counters (0.8 m deep); the funnel's casing, ridged, rises through every deck across the block's width (the block
    and the decks stop at it); the promenades deck chairs (ridged) along the rails, the stern terraces tables.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length, half = rng.uniform(230.0, 250.0), rng.uniform(14.0, 16.0)
    starts = np.cumsum([0.0, *rng.uniform(12.0, 16.0, size=4)])
    ends = length - np.cumsum([0.0, *rng.uniform(6.0, 10.0, size=4)])
    steps, rise = 17, 3.0
    run = steps * 0.28
    prom = rng.uniform(3.5, 4.5)
    cx0, cx1 = starts[-1] + 2.0, ends[-1] - 2.0
    cuts = [cx0]
    while cuts[-1] + 30.0 < cx1 - 20.0:
        cuts.append(cuts[-1] + rng.uniform(30.0, 45.0))
    cuts.append(cx1)
    blocks = [(a + 1.25 if a > cx0 else a, b - 1.25 if b < cx1 else b, -half + prom, half - prom) for a, b in pairwise(cuts)]
    # the funnel's casing, a shaft through every deck across the block's width: the blocks stop at it
    funnel_x = rng.uniform(cx0 + 0.3 * (cx1 - cx0), cx0 + 0.5 * (cx1 - cx0))
    funnel = _ridged(s, funnel_x, funnel_x + 12.0, -half + prom, half - prom, -0.3, 18.0)
    blocks = [piece for x0, x1, z0, z1 in blocks
              for piece in ((x0, min(x1, funnel_x), z0, z1), (max(x0, funnel_x + 12.0), x1, z0, z1)) if piece[1] - piece[0] > 1.0]
    for x0, x1, z0, z1 in blocks:  # the cabin blocks, from the lowest deck's underside to the sun deck's floor
        s.box(x0, x1, -0.3, 12.0, z0, z1)
    prev_stern: list[float] = []  # the z of the flights up from the deck below (none below the lowest)
    for k in range(5):
        top, x0, x1 = 3.0 * k, starts[k], ends[k]
        if k < 4:
            s.slab(x0, x1, -half, half, top, [*blocks, funnel])
        stern = [rng.uniform(-half + 2.5, -3.0), rng.uniform(3.0, half - 4.5)]  # the flights up from this deck
        if k < 4:
            for z in stern:
                s.stairs(np.array([starts[k + 1] - run, z + 1.0]), np.array([1.0, 0.0]), 2.0, top, rise, rise / steps, 0.28)
            s.stairs(np.array([ends[k + 1] + run, 0.0]), np.array([-1.0, 0.0]), 2.0, top, rise, rise / steps, 0.28)
            for _ in range(int(rng.integers(3, 7))):  # tables on the stern terrace, clear of the flights
                px, pz = rng.uniform(x0 + 1.5, starts[k + 1] - run - 2.5), rng.uniform(-half + 1.5, half - 2.5)
                if all(abs(pz + 0.5 - (z + 1.0)) > 2.5 for z in stern):
                    s.box(px, px + 1.0, top, top + 0.75, pz, pz + 1.0)
            for side in (-1.0, 1.0):  # deck chairs along the rails of the covered promenades
                for x in np.arange(cx0 + rng.uniform(2.0, 6.0), cx1 - 3.0, rng.uniform(6.0, 9.0)):
                    if rng.random() < 0.6:
                        z0 = side * (half - 0.3) - (0.7 if side > 0 else 0.0)
                        _ridged(s, float(x), float(x) + 1.8, z0, z0 + 0.7, top, top + 0.45)
        # rails along the open edges: the sides (all along), the stern and bow edges, open at the flights' heads
        for z in (-half, half):
            s.wall((x0, z), (x1, z), top, top + 1.1, thickness=0.1)
        if k > 0:
            heads = [(z + half, 2.0) for z in prev_stern]
            s.wall((x0, -half), (x0, half), top, top + 1.1, heads, thickness=0.1)
            s.wall((x1, -half), (x1, half), top, top + 1.1, [(half - 1.0, 2.0)], thickness=0.1)
        else:
            s.wall((x0, -half), (x0, half), top, top + 1.1, thickness=0.1)
            s.wall((x1, -half), (x1, half), top, top + 1.1, thickness=0.1)
        prev_stern = stern
    # the sun deck: pools, loungers, bars (the funnel's casing stands already)
    top, x0, x1 = 12.0, starts[4], ends[4]
    features: list[tuple[float, float, float, float]] = [funnel]
    for _ in range(int(rng.integers(2, 4))):
        for _ in range(100):
            w, d = rng.uniform(8.0, 14.0), rng.uniform(5.0, 8.0)
            px, pz = rng.uniform(x0 + 4.0, x1 - w - 4.0), rng.uniform(-half + 4.0, half - d - 4.0)
            if _clear(px - 4.0, px + w + 4.0, pz - 4.0, pz + d + 4.0, features):
                for z0, z1 in pairwise(_split(pz, pz + d, 2.0)):  # lanes ridged low enough to hold no floor inside
                    _ridged(s, px, px + w, z0, z1, top - 0.3, top + 0.5)
                features.append((px, px + w, pz, pz + d))
                break
    for _ in range(int(rng.integers(8, 14))):  # rows of loungers, 0.8 m apart
        for _ in range(100):
            n = int(rng.integers(3, 7))
            px, pz = rng.uniform(x0 + 3.0, x1 - 1.6 * n - 3.0), rng.uniform(-half + 2.5, half - 4.5)
            if _clear(px - 1.5, px + 1.6 * n + 1.5, pz - 1.5, pz + 3.5, features):
                for i in range(n):
                    _ridged(s, px + 1.6 * i, px + 1.6 * i + 0.8, pz, pz + 2.0, top, top + 0.45)
                features.append((px, px + 1.6 * n, pz, pz + 2.0))
                break
    for _ in range(int(rng.integers(2, 4))):  # bars
        for _ in range(100):
            px, pz = rng.uniform(x0 + 3.0, x1 - 9.0), rng.uniform(-half + 3.0, half - 6.0)
            if _clear(px - 2.0, px + 8.0, pz - 2.0, pz + 5.0, features):
                s.box(px, px + 6.0, top, top + 1.1, pz, pz + 0.8)
                features.append((px, px + 6.0, pz, pz + 3.0))
                break
    s.slab(x0, x1, -half, half, top, [funnel])
    return s.mesh()


def treetops(seed: int) -> trimesh.Trimesh:
    """A treetop village over a forest floor 140 x 110 m on a 1 m grid (:func:`_terrain`; waves under 1.5 m): 22-28
    platforms (octagons 3-4.2 m in radius, 0.3 m thick, 4-11 m up) round big trunks at least 11 m apart, joined by
    bridges 1.8 m wide (ramps, no steeper than 20 degrees, 3-20 m long between platform edges, none passing within
    1 m of a third platform): a minimum spanning tree of the allowed pairs by length and a quarter of the other
    allowed pairs. Each group of three or more platforms is reached from the floor by a flight (0.18 / 0.28 m steps)
    up to its lowest platform with a side (along x or z) clear of the other platforms, of its bridges and of the
    floor's edge, walked onto head-on; a smaller group (a hide) by a ladder only (a board no agent climbs), so a hide
    is an area of its own, and so is a group none of whose platforms has a clear side (no flight, no ladder).
    120-180 other trunks (0.2-0.5 m) and bushes (rocks) stand on the floor, clear of the flights; a ranger's hut
    (ridged; the ground stops under it).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = 140.0, 110.0
    phases = rng.uniform(0, 2 * math.pi, size=3)

    def height(x: np.ndarray, z: np.ndarray) -> np.ndarray:
        """The floor's height (m) at plan points x, z."""
        return (0.8 * np.sin(2 * math.pi * x / 60.0 + phases[0]) * np.sin(2 * math.pi * z / 50.0 + phases[1])
                + 0.5 * np.sin(2 * math.pi * (x + z) / 45.0 + phases[2]))

    centres: list[np.ndarray] = []
    for _ in range(2000):
        if len(centres) == 28:
            break
        c = np.array([rng.uniform(12.0, size_x - 12.0), rng.uniform(12.0, size_z - 12.0)])
        if all(np.linalg.norm(c - o) > 11.0 for o in centres):
            centres.append(c)
    n = min(int(rng.integers(22, 29)), len(centres))  # fewer when fewer than 22-28 fit 11 m apart
    centres = centres[:n]
    radii = rng.uniform(3.0, 4.2, size=n)
    heights = np.round(rng.uniform(4.0, 11.0, size=n) * 2) / 2
    allowed = []
    for i in range(n):
        for j in range(i + 1, n):
            gap = np.linalg.norm(centres[i] - centres[j]) - radii[i] - radii[j]
            if not 3.0 <= gap <= 20.0 or abs(heights[i] - heights[j]) > gap * math.tan(math.radians(20.0)):
                continue
            a, b = centres[i], centres[j]
            u = (b - a) / np.linalg.norm(b - a)
            if any(k not in (i, j) and abs(np.dot(centres[k] - a, u)) < np.linalg.norm(b - a)
                   and np.dot(centres[k] - a, u) > 0 and abs(u[0] * (centres[k] - a)[1] - u[1] * (centres[k] - a)[0]) < radii[k] + 1.9
                   for k in range(n)):
                continue
            allowed.append((gap, i, j))
    allowed.sort()
    group = list(range(n))

    def root(i: int) -> int:
        while group[i] != i:
            i = group[i]
        return i

    def crosses(i: int, j: int) -> bool:
        """Whether the bridge i-j would cross a bridge already chosen, in plan (one would pass under the other), or
        leave a platform within 40 degrees of one (their ends would overlap at two heights)."""
        def side(p: np.ndarray, q: np.ndarray, r: np.ndarray) -> float:
            return float(np.sign((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])))

        def heading(p: int, q: int) -> np.ndarray:
            return (centres[q] - centres[p]) / np.linalg.norm(centres[q] - centres[p])
        a, b = centres[i], centres[j]
        for k, m in bridges:
            if len({i, j, k, m}) == 4:
                if side(a, b, centres[k]) != side(a, b, centres[m]) and side(centres[k], centres[m], a) != side(centres[k], centres[m], b):
                    return True
            else:
                p = ({i, j} & {k, m}).pop()
                if np.dot(heading(p, i + j - p), heading(p, k + m - p)) > math.cos(math.radians(40.0)):
                    return True
        return False

    bridges: list[tuple[int, int]] = []
    others = []
    for gap, i, j in allowed:
        if root(i) != root(j):
            if not crosses(i, j):
                group[root(i)] = root(j)
                bridges.append((i, j))
        else:
            others.append((i, j))
    for k in rng.permutation(len(others))[:len(others) // 4]:
        if not crosses(*others[k]):
            bridges.append(others[k])
    taken: list[tuple[float, float, float, float]] = []
    for i, c in enumerate(centres):
        angles = np.linspace(0, 2 * math.pi, 8, endpoint=False) + math.pi / 8
        s.prism(c + radii[i] / math.cos(math.pi / 8) * np.stack([np.cos(angles), np.sin(angles)], 1),
                heights[i] - 0.3, heights[i])
        _trunk(s, c, 0.7, -1.5, heights[i] + 7.0)
        taken.append((c[0] - radii[i] - 1.0, c[0] + radii[i] + 1.0, c[1] - radii[i] - 1.0, c[1] + radii[i] + 1.0))
    for i, j in bridges:
        a, b = centres[i], centres[j]
        u = (b - a) / np.linalg.norm(b - a)
        s.ramp(a + u * (radii[i] - 0.4), b - u * (radii[j] - 0.4), 1.8, heights[i], heights[j])
    members: dict[int, list[int]] = {}
    for i in range(n):
        members.setdefault(root(i), []).append(i)

    def clear_side(low: int, ladder: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """A side of platform ``low`` along x or z (a flight at an angle to the axes has cells whose neighbours differ
        by more than the climb, ledges to Recast) from which its flight (or ladder) keeps clear of the other
        platforms, of its bridges and of the floor's edge: the direction u (2,), the flight's top and foot (2,)
        each, or None when no side is clear. The sides are tried in a random order."""
        c = centres[low]
        for u in rng.permutation(np.array([[1.0, 0.0], [-1.0, 0.0], [0.0, 1.0], [0.0, -1.0]])):
            end = c + u * (radii[low] - 0.2)
            run = math.ceil((heights[low] - float(height(*(end + u * 14.0)))) / 0.18) * 0.28
            reach = end + u * (run + 3.0 if not ladder else 1.0)
            away = [np.dot(u, (centres[j if i == low else i] - c) / np.linalg.norm(centres[j if i == low else i] - c))
                    for i, j in bridges if low in (i, j)]
            if all(np.linalg.norm(reach - o) > r + 3.0 for k, (o, r) in enumerate(zip(centres, radii)) if k != low) and \
                    all(cos < math.cos(math.radians(50.0)) for cos in away) and \
                    2.0 < reach[0] < size_x - 2.0 and 2.0 < reach[1] < size_z - 2.0:
                return u, end, end + u * run
        return None

    for group_members in members.values():
        ladder = len(group_members) < 3
        # the lowest platform with a clear side, the next lowest when none of its sides is clear
        for low in sorted(group_members, key=lambda i: heights[i]):
            side_found = clear_side(low, ladder)
            if side_found is not None:
                break
        else:
            continue  # no platform of the group has a clear side: no way up, an area of its own as a hide is
        u, end, foot = side_found
        c = centres[low]
        if ladder:
            p = c + u * (radii[low] + 0.05)
            side = np.array([-u[1], u[0]]) * 0.3
            s.prism(np.array([p - side - u * 0.05, p - side + u * 0.05, p + side + u * 0.05, p + side - u * 0.05]),
                    float(height(*p)) - 0.5, heights[low])
        else:
            foot_height = float(height(*foot))
            steps_n = math.ceil((heights[low] - foot_height) / 0.18)
            riser = (heights[low] - foot_height) / steps_n
            foot = end + u * steps_n * 0.28
            s.stairs(foot, -u, 2.0, foot_height, heights[low] - foot_height, riser, 0.28)
            lo, hi = np.minimum(foot, end) - 2.0, np.maximum(foot, end) + 2.0
            taken.append((lo[0], hi[0], lo[1], hi[1]))
            taken.append((foot[0] + u[0] * 2.0 - 2.0, foot[0] + u[0] * 2.0 + 2.0, foot[1] + u[1] * 2.0 - 2.0,
                          foot[1] + u[1] * 2.0 + 2.0))
    hut = None
    for _ in range(100):
        hx, hz = rng.uniform(5.0, size_x - 15.0), rng.uniform(5.0, size_z - 12.0)
        if _clear(hx - 2.0, hx + 12.0, hz - 2.0, hz + 9.0, taken):
            hut = _ridged(s, hx, hx + 10.0, hz, hz + 7.0, -2.0, 3.0)
            taken.append((hx - 2.0, hx + 12.0, hz - 2.0, hz + 9.0))
            break
    for _ in range(int(rng.integers(120, 181))):
        p = np.array([rng.uniform(2.0, size_x - 2.0), rng.uniform(2.0, size_z - 2.0)])
        spans = [(centres[i], centres[j]) for i, j in bridges]
        if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken) and all(
                np.linalg.norm(p - (a + np.clip(np.dot(p - a, b - a) / np.dot(b - a, b - a), 0.0, 1.0) * (b - a))) > 2.0
                for a, b in spans):  # and 2 m or more from every bridge's line
            if rng.random() < 0.75:
                _trunk(s, p, rng.uniform(0.2, 0.5), -1.5, 14.0)
            else:
                s.rock(rng, p, 0.5, float(height(*p)) - 0.5, float(height(*p)) + 1.2)
            taken.append((p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0))
    xs, zs = np.arange(0.0, size_x + 0.5, 1.0), np.arange(0.0, size_z + 0.5, 1.0)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    keep = None
    if hut is not None:
        cx, cz = np.meshgrid(xs[:-1] + 0.5, zs[:-1] + 0.5, indexing="ij")
        keep = ~((cx > hut[0]) & (cx < hut[1]) & (cz > hut[2]) & (cz < hut[3]))
    _terrain(s, xs, zs, height(gx, gz), keep=keep)
    return s.mesh()


def beach(seed: int) -> trimesh.Trimesh:
    """A seaside front 240 m long: a beach of sand on a 1 m grid (:func:`_terrain`) from the waterline (z = 0, y = 0;
    no floor beyond it) rising 1.6-2.2 m over 70 m with ripples and low dunes (z 45-62 m; none in the 8 m before the wall, where
    the flights stand), under a sea wall at
    z = 70 whose promenade (y = 4.5, 14 m deep, railed along the wall) runs the whole front. Timber groynes (0.4 m
    thick, 3 m over the waterline, too high to step over anywhere) cut the beach into bays 30-48 m wide from the
    wall out past the waterline; each bay is reached from the promenade only by its own flights down the wall (one,
    or two in a bay wider than 40 m; 2.4 m wide, walked onto head-on at both ends). A pier 8 m wide at the
    promenade's height runs 90 m out from it over one bay and the sea on piles (the beach goes on under it, 2 m and
    more of head room), a pavilion (ridged) on its head. Beach huts (ridged) in rows along the wall's foot,
    lifeguard towers (a platform 2 m square 2.5 m up on posts, a ladder: too small to hold floor for the
    agent), windbreaks and umbrella poles on the
    sand; kiosks (ridged; the promenade stops under them), benches and lamp posts on the promenade.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, wall_z, prom_y, prom_d = 240.0, 70.0, 4.5, 14.0
    rise = rng.uniform(1.6, 2.2)
    phases = rng.uniform(0, 2 * math.pi, size=3)

    groynes = [0.0]
    while groynes[-1] + 30.0 < size_x:
        groynes.append(min(groynes[-1] + rng.uniform(30.0, 48.0), size_x))
    if size_x - groynes[-1] < 30.0:
        groynes[-1] = size_x

    def height(x: np.ndarray, z: np.ndarray) -> np.ndarray:
        """The sand's height (m) at plan points x, z: the slope, ripples and dunes near the wall. The dunes die out
        over the last 4 m before a groyne (none within 1 m), where the sand stays 0.68 m and more under the
        groyne's top (a dune reaching within the climb of it joined two bays over it)."""
        to_groyne = np.min(np.abs(np.asarray(x)[..., None] - np.array(groynes[1:-1])), axis=-1)
        dune = (np.clip(np.minimum((z - 45.0) / 8.0, (wall_z - 8.0 - z) / 4.0), 0.0, 1.0) * np.clip((to_groyne - 1.0) / 3.0, 0.0, 1.0)
                * (0.6 + 0.5 * np.sin(2 * math.pi * x / 23.0 + phases[0]) * np.sin(2 * math.pi * z / 11.0 + phases[1])))
        return rise * z / wall_z + 0.12 * np.sin(2 * math.pi * x / 7.0 + phases[2]) * np.clip(z / 10.0, 0.0, 1.0) + dune

    # bays and their flights
    taken: list[tuple[float, float, float, float]] = []
    run = math.ceil(prom_y / 0.18) * 0.28
    pier_bay = int(rng.integers(1, len(groynes) - 2))
    pier_x = (groynes[pier_bay] + groynes[pier_bay + 1]) / 2 - 4.0
    flights: list[float] = []
    for g in groynes[1:-1]:
        s.box(g - 0.2, g + 0.2, -1.0, 3.0, -6.0, wall_z)
        taken.append((g - 2.0, g + 2.0, 0.0, wall_z))
    for a, b in pairwise(groynes):
        count = 2 if b - a > 40.0 else 1
        for k in range(count):
            x = a + (b - a) * (k + 1) / (count + 1) + rng.uniform(-4.0, 4.0)
            if a + 4.0 < pier_x + 8.0 and pier_x < b - 4.0 and abs(x - (pier_x + 4.0)) < 8.0:
                x = pier_x - 6.0 if x < pier_x + 4.0 else pier_x + 14.0
            foot_z = wall_z - run
            foot_y = float(height(np.array(x), np.array(foot_z)))
            steps = math.ceil((prom_y - foot_y) / 0.18)
            foot_z = wall_z - steps * 0.28
            foot_y = float(height(np.array(x), np.array(foot_z)))
            s.stairs(np.array([x, foot_z]), np.array([0.0, 1.0]), 2.4, foot_y, prom_y - foot_y, (prom_y - foot_y) / steps, 0.28)
            taken.append((x - 3.5, x + 3.5, foot_z - 4.0, wall_z))
            flights.append(x)
    s.wall((0.0, wall_z + 0.1), (size_x, wall_z + 0.1), prom_y, prom_y + 1.0,
           [(x - 1.2, 2.4) for x in flights] + [(pier_x, 8.0)], thickness=0.2)
    # the pier and its pavilion
    pz0 = -90.0 + wall_z
    s.box(pier_x, pier_x + 8.0, prom_y - 0.4, prom_y, pz0, wall_z)
    pavilion = _ridged(s, pier_x - 2.0, pier_x + 10.0, pz0 - 16.0, pz0 - 6.0, prom_y - 0.4, prom_y + 4.0)
    s.slab(pier_x - 8.0, pier_x + 16.0, pz0 - 20.0, pz0, prom_y, [pavilion], thickness=0.4)  # its head stops under it
    for z in np.arange(wall_z - 6.0, pz0 - 20.0, -6.0):
        for x in (pier_x + 0.5, pier_x + 7.5):
            _trunk(s, np.array([x, z]), 0.25, -2.0, prom_y - 0.4)
    for x in (pier_x, pier_x + 8.0):  # its rails
        s.box(x - 0.05, x + 0.05, prom_y, prom_y + 1.1, pz0, wall_z)
    taken.append((pier_x - 2.0, pier_x + 10.0, pz0 - 20.0, wall_z))
    # huts along the wall's foot, towers, windbreaks and poles on the sand
    holes = []
    for a, b in pairwise(groynes):
        if rng.random() < 0.6:
            for x in np.arange(a + 3.0, b - 5.0, 3.2):
                if _clear(x, x + 2.5, wall_z - 3.5, wall_z, taken):
                    holes.append(_ridged(s, float(x), float(x) + 2.5, wall_z - 3.0, wall_z - 0.5, -1.0, 2.6))
        if rng.random() < 0.7:  # a lifeguard tower
            tx, tz = rng.uniform(a + 6.0, b - 8.0), rng.uniform(15.0, 30.0)
            if _clear(tx - 1.0, tx + 3.0, tz - 1.0, tz + 3.0, taken):
                for px in (tx, tx + 1.8):
                    for pz in (tz, tz + 1.8):
                        s.box(px, px + 0.2, -1.0, 2.5, pz, pz + 0.2)
                s.box(tx, tx + 2.0, 2.3, 2.5, tz, tz + 2.0)
                s.box(tx + 0.7, tx + 1.3, -1.0, 2.5, tz - 0.1, tz)  # the ladder
                taken.append((tx - 1.0, tx + 3.0, tz - 1.0, tz + 3.0))
    for _ in range(int(rng.integers(60, 90))):
        p = np.array([rng.uniform(2.0, size_x - 2.0), rng.uniform(3.0, wall_z - 6.0)])
        if _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, taken):
            y = float(height(*p))
            if rng.random() < 0.5:  # a windbreak, 3-5 m of canvas on poles
                w = rng.uniform(3.0, 5.0)
                s.box(p[0], p[0] + w, y - 1.0, y + 1.3, p[1], p[1] + 0.1)
                taken.append((p[0] - 1.0, p[0] + w + 1.0, p[1] - 1.0, p[1] + 1.0))
            else:
                _trunk(s, p, 0.06, y - 1.0, y + 2.2)
                taken.append((p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0))
    # the promenade's kiosks, benches and lamp posts
    kiosks = [_ridged(s, float(x), float(x) + 4.0, wall_z + 6.0, wall_z + 9.0, -1.0, prom_y + 2.6)
              for x in np.arange(rng.uniform(4.0, 10.0), size_x - 6.0, rng.uniform(18.0, 26.0)) if not pier_x - 6.0 < x < pier_x + 12.0]
    s.ground(0.0, size_x, wall_z, wall_z + prom_d, prom_y, kiosks, thickness=prom_y + 1.0)  # the wall and the promenade
    for x in np.arange(rng.uniform(2.0, 6.0), size_x - 2.0, rng.uniform(9.0, 12.0)):
        _trunk(s, np.array([x, wall_z + 1.2]), 0.12, prom_y, prom_y + 5.0)
        if rng.random() < 0.5:
            s.box(float(x) + 2.0, float(x) + 4.0, prom_y, prom_y + 0.5, wall_z + 12.5, wall_z + 13.2)
    xs, zs = np.arange(0.0, size_x + 0.5, 1.0), np.arange(0.0, wall_z + 0.5, 1.0)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    cx, cz = np.meshgrid(xs[:-1] + 0.5, zs[:-1] + 0.5, indexing="ij")
    keep = np.ones(cx.shape, dtype=bool)
    for x0, x1, z0, z1 in holes:
        keep &= ~((cx > x0) & (cx < x1) & (cz > z0) & (cz < z1))
    _terrain(s, xs, zs, height(gx, gz), keep=keep)
    return s.mesh()


def railyard(seed: int) -> trimesh.Trimesh:
    """A marshalling yard 240 x 80-100 m of flat ground: 13-16 tracks along x 4.6-5 m apart (rails 0.15 m high, under
    the climb), each holding strings of wagons (ridged, 3 m wide, 10-18 m long; the ground stops under them) coupled
    0.8 m apart, the strings broken by gaps of 3-12 m at random, so one crosses the yard through whichever gaps line
    up. A service road 10 m wide along each long side; a footbridge 6.5 m up across the yard (stairs at both ends,
    2.4 m wide, along x, and piers on the roads; wagons stand under it, 0.7 m and more below its deck: a first
    draft kept them clear of it, which left a lane across the yard under the bridge, and piers between
    tracks, which closed the aisles between wagons there) and an engine shed over the last 40 m of four tracks (walls,
    open at its west end, a roof at 50 degrees, :func:`_lid`), engines (ridged) inside; a signal box on the north
    road (ridged) and stacks of sleepers (ridged).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, road = 240.0, 10.0
    tracks = int(rng.integers(13, 17))
    pitch = rng.uniform(4.6, 5.0)
    size_z = 2 * road + tracks * pitch
    holes: list[tuple[float, float, float, float]] = []
    shed_x = size_x - 40.0
    shed_tracks = set(range(tracks - 4, tracks)) if rng.random() < 0.5 else set(range(4))
    fb_x = rng.uniform(60.0, 140.0)
    for i in range(tracks):
        zc = road + pitch * (i + 0.5)
        for dz in (-0.72, 0.72):
            s.box(0.0, size_x, 0.0, 0.15, zc + dz - 0.04, zc + dz + 0.04)
        x = rng.uniform(0.0, 12.0)
        end = shed_x - 2.0 if i in shed_tracks else size_x - 2.0
        while x < end - 10.0:
            if rng.random() < 0.3:  # a gap in the string
                x += rng.uniform(3.0, 12.0)
                continue
            length = rng.uniform(10.0, 18.0)
            if x + length > end:
                break
            holes.append(_ridged(s, x, x + length, zc - 1.5, zc + 1.5, -0.5, 3.6))  # under the footbridge too
            x += length + 0.8
    # the footbridge: a deck 3 m wide along z at x = fb_x, 6.5 m up, flights along x at both ends on the roads
    deck_y = 6.5
    steps = math.ceil(deck_y / 0.18)
    run = steps * 0.28
    s.box(fb_x - 1.5, fb_x + 1.5, deck_y - 0.4, deck_y, road - 3.0, size_z - road + 3.0)
    for z0, z1 in ((road - 5.5, road - 3.0), (size_z - road + 3.0, size_z - road + 5.5)):
        s.box(fb_x - 1.5, fb_x + 1.5, deck_y - 0.4, deck_y, z0, z1)  # landings over the roads
        s.stairs(np.array([fb_x - 1.5 - run, (z0 + z1) / 2]), np.array([1.0, 0.0]), 2.4, 0.0, deck_y, deck_y / steps, 0.28,
                 depth=0.45)
    for zc in (road - 1.5, size_z - road + 1.5):  # piers on the roads only: one between tracks closed the aisle there
        s.box(fb_x - 0.3, fb_x + 0.3, -0.5, deck_y - 0.4, zc - 0.3, zc + 0.3)
    s.box(fb_x - 1.5, fb_x - 1.4, deck_y, deck_y + 1.1, road - 3.0, size_z - road + 3.0)  # rails, open at the flights' heads
    s.box(fb_x + 1.4, fb_x + 1.5, deck_y, deck_y + 1.1, road - 5.5, size_z - road + 5.5)
    # the engine shed
    lo = road + pitch * min(shed_tracks) - 0.4
    hi = road + pitch * (max(shed_tracks) + 1) + 0.4
    for z in (lo, hi):
        s.wall((shed_x, z), (size_x, z), -0.3, 7.0, [(6.0, 2.0), (28.0, 2.0)])
    s.wall((size_x, lo), (size_x, hi), -0.3, 7.0)
    _lid(s, shed_x, size_x, lo, hi, 7.0)
    for i in shed_tracks:
        zc = road + pitch * (i + 0.5)
        x = shed_x + rng.uniform(1.0, 6.0)
        while x + 14.0 < size_x - 1.0:
            if rng.random() < 0.7:
                holes.append(_ridged(s, x, x + 14.0, zc - 1.5, zc + 1.5, -0.5, 4.0))
            x += 14.0 + rng.uniform(1.5, 4.0)
    # the signal box and stacks of sleepers on the roads
    bx = rng.uniform(10.0, fb_x - 20.0)
    holes.append(_ridged(s, bx, bx + 8.0, size_z - road + 2.0, size_z - 1.0, -0.5, 6.0))
    for _ in range(int(rng.integers(10, 16))):
        x = rng.uniform(2.0, size_x - 8.0)
        z0 = rng.uniform(1.0, road - 4.0) if rng.random() < 0.5 else rng.uniform(size_z - road + 1.0, size_z - 4.0)
        if _clear(x - 2.0, x + 8.0, z0 - 2.0, z0 + 5.0, [*holes, (fb_x - run - 4.0, fb_x + 4.0, 0.0, size_z)]):
            holes.append(_ridged(s, x, x + 6.0, z0, z0 + 2.6, -0.5, 1.2))
    bands = [0.0, *(road + pitch * np.arange(tracks + 1)), size_z]
    for z0, z1 in pairwise(bands):  # the ground band by band, each stopping under its own holes (quick)
        s.ground(0.0, size_x, z0, z1, 0.0, [h for h in holes if z0 < (h[2] + h[3]) / 2 < z1])
    return s.mesh()


def craters(seed: int) -> trimesh.Trimesh:
    """A shelled battlefield 170 x 130 m on a 1 m grid (:func:`_terrain`): rolling ground (waves under 1.5 m) pocked
    by 45-70 shell craters (2.5-7.5 m in radius, 0.15-0.4 of the radius deep, a rim a quarter of the depth high;
    overlapping craters add up, so the deepest walls pass 45 degrees near the rim and a few bottoms may be out of
    reach), crossed by three or four lines of sandbags along x (pieces 2 m long, 0.8 m wide, 1.1 m over the highest
    ground under them: too high to climb) zig-zagging in legs of 8-14 m, each leg open or not at its end by a gap of
    2.5-4 m, so the lines are crossed only at their gaps; 6-10 wrecked vehicles (ridged; the ground stops under them),
    two or three ruined houses (walls 3 m high, wide breaches, no roof) and 40-70 shattered stumps.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = 170.0, 130.0
    phases = rng.uniform(0, 2 * math.pi, size=3)
    n = int(rng.integers(45, 71))
    centres = np.stack([rng.uniform(5.0, size_x - 5.0, n), rng.uniform(5.0, size_z - 5.0, n)], 1)
    radii = rng.uniform(2.5, 7.5, n)
    depths = radii * rng.uniform(0.15, 0.4, n)

    def height(x: np.ndarray, z: np.ndarray) -> np.ndarray:
        """The ground's height (m) at plan points x, z: waves and every crater's bowl and rim."""
        x, z = np.asarray(x, dtype=np.float64), np.asarray(z, dtype=np.float64)
        h = (0.8 * np.sin(2 * math.pi * x / 70.0 + phases[0]) * np.sin(2 * math.pi * z / 55.0 + phases[1])
             + 0.5 * np.sin(2 * math.pi * (x + z) / 45.0 + phases[2]))
        for (cx, cz), r, d in zip(centres, radii, depths):
            t = np.hypot(x - cx, z - cz) / r
            rim = d / 4
            h = h + np.where(t < 1.0, -d + (d + rim) * t ** 2, rim * np.exp(-((t - 1.0) / 0.5) ** 2))
        return h

    xs, zs = np.arange(0.0, size_x + 0.5, 1.0), np.arange(0.0, size_z + 0.5, 1.0)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    heights = height(gx, gz)
    cx, cz = np.meshgrid(xs[:-1] + 0.5, zs[:-1] + 0.5, indexing="ij")
    keep = np.ones(cx.shape, dtype=bool)
    taken: list[tuple[float, float, float, float]] = []

    def ground_range(points: np.ndarray) -> tuple[float, float]:
        """The lowest and highest ground (m) under plan points (k, 2)."""
        h = height(points[:, 0], points[:, 1])
        return float(h.min()), float(h.max())

    lines = int(rng.integers(3, 5))
    for k in range(lines):
        z = size_z * (k + 1) / (lines + 1) + rng.uniform(-6.0, 6.0)
        x, up = 0.0, rng.random() < 0.5
        while x < size_x:
            leg = rng.uniform(8.0, 14.0)
            dz = rng.uniform(4.0, 8.0) * (1.0 if up else -1.0)
            a, b = np.array([x, z]), np.array([min(x + leg, size_x), z + dz])
            gap = rng.uniform(2.5, 4.0) if rng.random() < 0.45 else 0.0
            length = float(np.linalg.norm(b - a)) - gap
            u = (b - a) / np.linalg.norm(b - a)
            for t0 in np.arange(0.0, length, 2.0):
                p, q = a + u * t0, a + u * min(t0 + 2.0, length)
                if np.linalg.norm(q - p) < 0.3:
                    continue
                lo, hi = ground_range(np.linspace(p, q, 5))
                s.prism(_strip(p, q, 0.8), lo - 0.5, hi + 1.1)
            taken.append((min(a[0], b[0]) - 2.0, max(a[0], b[0]) + 2.0, min(a[1], b[1]) - 2.0, max(a[1], b[1]) + 2.0))
            x, z, up = b[0], b[1], not up
    for _ in range(int(rng.integers(2, 4))):  # ruined houses
        for _ in range(100):
            hx, hz = rng.uniform(5.0, size_x - 17.0), rng.uniform(5.0, size_z - 14.0)
            w, d = rng.uniform(9.0, 12.0), rng.uniform(7.0, 9.0)
            if _clear(hx - 2.0, hx + w + 2.0, hz - 2.0, hz + d + 2.0, taken):
                lo, hi = ground_range(np.array([[hx, hz], [hx + w, hz], [hx, hz + d], [hx + w, hz + d], [hx + w / 2, hz + d / 2]]))
                for a, b, span in (((hx, hz), (hx + w, hz), w), ((hx, hz + d), (hx + w, hz + d), w),
                                   ((hx, hz), (hx, hz + d), d), ((hx + w, hz), (hx + w, hz + d), d)):
                    doors = [(rng.uniform(0.5, span - 3.5), rng.uniform(2.0, 3.0))] if rng.random() < 0.75 else []
                    s.wall(a, b, lo - 0.5, hi + 3.0, doors, thickness=0.4)
                taken.append((hx - 2.0, hx + w + 2.0, hz - 2.0, hz + d + 2.0))
                break
    for _ in range(int(rng.integers(6, 11))):  # wrecks
        for _ in range(100):
            along = rng.random() < 0.5
            w, d = (7.0, 3.6) if along else (3.6, 7.0)
            wx, wz = rng.uniform(3.0, size_x - w - 3.0), rng.uniform(3.0, size_z - d - 3.0)
            if _clear(wx - 2.0, wx + w + 2.0, wz - 2.0, wz + d + 2.0, taken):
                lo, hi = ground_range(np.array([[wx, wz], [wx + w, wz], [wx, wz + d], [wx + w, wz + d]]))
                if along:
                    _ridged(s, wx, wx + w, wz, wz + d, lo - 1.0, hi + 1.6)
                else:  # ridged along z
                    s.hull(np.array([[x, y, z] for x in (wx, wx + w) for y in (lo - 1.0, hi + 1.6) for z in (wz, wz + d)]
                                    + [[wx + w / 2, hi + 1.6 + w / 2 * math.tan(math.radians(50.0)), z] for z in (wz, wz + d)]))
                keep &= ~((cx > wx) & (cx < wx + w) & (cz > wz) & (cz < wz + d))
                taken.append((wx - 2.0, wx + w + 2.0, wz - 2.0, wz + d + 2.0))
                break
    for _ in range(int(rng.integers(40, 71))):  # stumps
        p = np.array([rng.uniform(2.0, size_x - 2.0), rng.uniform(2.0, size_z - 2.0)])
        if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken):
            y = float(height(*p))
            _trunk(s, p, rng.uniform(0.2, 0.45), y - 1.0, y + rng.uniform(1.0, 4.0))
    _terrain(s, xs, zs, heights, keep=keep)
    return s.mesh()


def _rail_ring(s: _Solids, x0: float, x1: float, z0: float, z1: float, y: float,
               openings: dict[str, list[tuple[float, float]]]) -> None:
    """Rails 1.1 m high, 0.1 m thick, round the rectangle [x0, x1] x [z0, z1] on a floor at ``y``, open over the
    ``openings`` of each side ("south" z0, "north" z1, "west" x0, "east" x1: (start, width), metres from the side's
    low end)."""
    s.wall((x0, z0), (x1, z0), y, y + 1.1, openings.get("south", []), thickness=0.1)
    s.wall((x0, z1), (x1, z1), y, y + 1.1, openings.get("north", []), thickness=0.1)
    s.wall((x0, z0), (x0, z1), y, y + 1.1, openings.get("west", []), thickness=0.1)
    s.wall((x1, z0), (x1, z1), y, y + 1.1, openings.get("east", []), thickness=0.1)


def _grid_edges(nx: int, nz: int) -> tuple[np.ndarray, list[tuple[int, int]]]:
    """The ids (nx, nz) of an nx x nz grid's junctions and its edges, those along x first, then those along z."""
    node = np.arange(nx * nz).reshape(nx, nz)
    edges = [(node[i, j], node[i + 1, j]) for i in range(nx - 1) for j in range(nz)]
    edges += [(node[i, j], node[i, j + 1]) for i in range(nx) for j in range(nz - 1)]
    return node, edges


def _random_tree(rng: np.random.Generator, n: int, edges: list[tuple[int, int]]) -> np.ndarray:
    """(n, n) symmetric bool: the edges of a random spanning tree of the graph of ``n`` nodes and ``edges``, the minimum
    spanning tree (scipy's) for weights uniform in [1, 2) drawn from ``rng`` in the edges' order. O(n^2) for the dense
    weight matrix."""
    weights = np.zeros((n, n))
    for a, b in edges:
        weights[a, b] = rng.uniform(1.0, 2.0)
    tree = minimum_spanning_tree(weights).toarray() > 0
    return tree | tree.T


def oil_rig(seed: int) -> trimesh.Trimesh:
    """An offshore oil rig over the sea (no floor below the decks): a production platform 85-95 x 50-56 m of three
    open decks 7 m apart (12, 19 and 26 m up) on four legs 3 m square, each deck cut by a well bay 8 m square through
    all three (railed) and crowded with equipment (40-50 ridged modules 2-7 x 2-5 m, 2.5-5 m high, 2.2 m and more
    apart; the decks stop under them), railed along every edge; two flights (39 steps of 0.179 / 0.28 m, 2 m wide, along x, through openings in
    the deck above, met head-on) between each pair of decks; a flight of 50 steps from a boat landing 3 m up at the
    west edge to the lowest deck. A bridge 2.4 m wide and 40-55 m long, railed, joins the middle deck to the
    accommodation platform's deck (19 m), where a walkway 3-3.5 m wide (5-6.5 m on the south, beside the flight) rings
    a closed accommodation block whose top is the helideck (26 m), reached by one flight along the block's south face
    onto a landing beside it.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    px, pz = rng.uniform(85.0, 95.0), rng.uniform(50.0, 56.0)
    ax0 = px + rng.uniform(40.0, 55.0)
    ax1, az0, az1 = ax0 + rng.uniform(30.0, 36.0), pz / 2 - 14.0, pz / 2 + 14.0
    decks, storey = [12.0, 19.0, 26.0], 7.0
    steps = math.ceil(storey / 0.18)
    run = steps * 0.28
    legs = [(x, x + 3.0, z, z + 3.0) for x in (3.0, px - 6.0) for z in (3.0, pz - 6.0)]
    for x0, x1, z0, z1 in legs:
        s.box(x0, x1, -20.0, decks[-1], z0, z1)
    wx, wz = rng.uniform(15.0, px - 23.0), rng.uniform(10.0, pz - 18.0)
    well = (wx, wx + 8.0, wz, wz + 8.0)
    flights: list[list[tuple[float, float, float]]] = []  # per deck pair: (x of the foot, z of the axis, heading)
    for _ in range(2):
        pair: list[tuple[float, float, float]] = []
        while len(pair) < 2:
            heading = 1.0 if rng.random() < 0.5 else -1.0
            fx, fz = rng.uniform(4.0 + run, px - 4.0 - run), rng.uniform(4.0, pz - 4.0)
            lo, hi = min(fx, fx + heading * run), max(fx, fx + heading * run)
            box = (lo - 3.0, hi + 3.0, fz - 2.5, fz + 2.5)
            below = [(min(a, a + h * run) - 3.0, max(a, a + h * run) + 3.0, c - 2.5, c + 2.5) for f in flights for a, c, h in f]
            if _clear(*box, [well, *legs, *below, *[(min(a, a + h * run) - 3.0, max(a, a + h * run) + 3.0, c - 2.5, c + 2.5)
                                                   for a, c, h in pair]]):
                pair.append((fx, fz, heading))
        flights.append(pair)
    for k, top in enumerate(decks):
        holes = [well, *legs]
        if k > 0:  # the openings over the flights from the deck below
            holes += [(min(a, a + h * run), max(a, a + h * run), c - 1.0, c + 1.0) for a, c, h in flights[k - 1]]
        taken = [(h[0] - 2.0, h[1] + 2.0, h[2] - 2.0, h[3] + 2.0) for h in holes]
        if k < 2:
            taken += [(min(a, a + h * run) - 3.0, max(a, a + h * run) + 3.0, c - 2.5, c + 2.5) for a, c, h in flights[k]]
            for a, c, h in flights[k]:
                s.stairs(np.array([a, c]), np.array([h, 0.0]), 2.0, top, storey, storey / steps, 0.28, depth=0.45)
        if k == 1:
            taken.append((px - 8.0, px, pz / 2 - 4.0, pz / 2 + 4.0))  # the bridge's head
        if k == 0:
            taken.append((0.0, 6.0, pz / 2 - 4.0, pz / 2 + 4.0))  # the boat landing flight's head
        for _ in range(int(rng.integers(40, 51))):  # equipment modules, 2.5 m and more from the edges
            for _ in range(60):
                w, d = rng.uniform(2.0, 7.0), rng.uniform(2.0, 5.0)
                mx, mz = rng.uniform(2.5, px - 2.5 - w), rng.uniform(2.5, pz - 2.5 - d)
                if _clear(mx - 2.2, mx + w + 2.2, mz - 2.2, mz + d + 2.2, taken):
                    holes.append(_ridged(s, mx, mx + w, mz, mz + d, top - 0.3, top + rng.uniform(2.5, 5.0)))
                    taken.append((mx - 2.2, mx + w + 2.2, mz - 2.2, mz + d + 2.2))
                    break
        s.ground(0.0, px, 0.0, pz, top, holes, thickness=0.3)  # strips, not a grid of cells: many holes
        openings: dict[str, list[tuple[float, float]]] = {}
        if k == 1:
            openings["east"] = [(pz / 2 - 1.2, 2.4)]
        if k == 0:
            openings["west"] = [(pz / 2 - 1.0, 2.0)]
        _rail_ring(s, 0.0, px, 0.0, pz, top, openings)
        _rail_ring(s, *well, top, {})
    # the boat landing and its flight up to the lowest deck
    low_steps = 50
    low_run = low_steps * 0.28
    s.box(-low_run - 5.0, -low_run, 2.7, 3.0, pz / 2 - 3.0, pz / 2 + 3.0)
    s.stairs(np.array([-low_run, pz / 2]), np.array([1.0, 0.0]), 2.0, 3.0, decks[0] - 3.0, (decks[0] - 3.0) / low_steps, 0.28)
    s.box(-low_run - 5.5, -low_run - 4.0, -20.0, 2.7, pz / 2 - 0.75, pz / 2 + 0.75)  # the landing's pile
    # the bridge to the accommodation platform
    s.box(px, ax0, decks[1] - 1.0, decks[1], pz / 2 - 1.2, pz / 2 + 1.2)
    for side in (-1.0, 1.0):
        s.box(px, ax0, decks[1], decks[1] + 1.1, pz / 2 + side * 1.2 - 0.05, pz / 2 + side * 1.2 + 0.05)
    # the accommodation platform: a walkway round a closed block whose top is the helideck
    for x in (ax0 + 2.0, ax1 - 5.0):
        for z in (az0 + 2.0, az1 - 5.0):
            s.box(x, x + 3.0, -20.0, decks[1] - 0.3, z, z + 3.0)
    south = rng.uniform(3.0, 4.5) + 2.0
    block = (ax0 + 3.5, ax1 - 3.5, az0 + south, az1 - 3.0)
    s.box(block[0], block[1], decks[1] - 0.3, decks[2], block[2], block[3])
    s.slab(ax0, ax1, az0, az1, decks[1], [block])
    _rail_ring(s, ax0, ax1, az0, az1, decks[1], {"west": [(pz / 2 - 1.2 - az0, 2.4)]})
    fx = rng.uniform(block[0] + 1.0, block[1] - run - 3.0)
    fz = block[2] - 1.1
    s.stairs(np.array([fx, fz]), np.array([1.0, 0.0]), 2.0, decks[1], storey, storey / steps, 0.28, depth=0.45)
    s.box(fx + run, fx + run + 2.5, decks[2] - 0.3, decks[2], fz - 1.0, block[2])  # the landing beside the helideck
    _rail_ring(s, *block, decks[2], {"south": [(fx + run - block[0], 2.5)]})
    return s.mesh()


def _trees(s: _Solids, rng: np.random.Generator, tries: int, size_x: float, size_z: float,
           taken: list[tuple[float, float, float, float]], radii: tuple[float, float], top: float) -> None:
    """``tries`` trunks at plan points uniform over [2, size_x - 2] x [2, size_z - 2] m, each placed only 1 m clear of
    every rectangle of ``taken`` (which then holds it, 1.5 m round), radius uniform in ``radii`` (m), from 0.5 m under
    the ground to ``top``."""
    for _ in range(tries):
        p = np.array([rng.uniform(2.0, size_x - 2.0), rng.uniform(2.0, size_z - 2.0)])
        if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken):
            _trunk(s, p, rng.uniform(*radii), -0.5, top)
            taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))


def monastery(seed: int) -> trimesh.Trimesh:
    """A monastery on a rock: flat ground 170 x 140 m (a hamlet of houses, ridged, and trees at the foot) round a
    rock 62-70 x 50-54 m with vertical faces, its top 32.4 or 35.6 m up (10 or 11 flights), reached only by one long
    stair: flights of 18 steps (0.18 / 0.28 m, 2.4 m wide, solid) with 2.4 m landings along the rock's south face
    (+x) and round its south-east corner up its east face (+z), to a gate in the wall round the top (2.5 m high, a
    parapet). On the top: a cloister (a walk 3 m wide round a square garth 18 m across, pillars 0.5 m every 3 m on
    the garth's side, a wall on the outer side with a 2 m door on each side), a church north of it (a nave of ridged
    pews, a door from the cloister and one to the yard), a range of 9 or 10 cells (3.5-3.9 m wide, 1.6 m doors) off a
    corridor east of the cloister, a refectory west of it (ridged tables), kitchen-garden beds (0.25 m, under the
    climb) and a railed terrace at the west end; rooms are walled (4 m) under roofs at 50 degrees (:func:`_gable`).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = 170.0, 140.0
    width, depth = rng.uniform(62.0, 70.0), rng.uniform(50.0, 54.0)
    rx0, rz0 = rng.uniform(45.0, size_x - width - 45.0), rng.uniform(40.0, size_z - depth - 30.0)
    rx1, rz1 = rx0 + width, rz0 + depth
    n_flights, riser, per = int(rng.integers(10, 12)), 0.18, 18
    rise, run, landing = per * riser, per * 0.28, 2.4
    top = n_flights * rise
    rock = (rx0, rx1, rz0, rz1)
    s.box(rx0, rx1, -1.0, top, rz0, rz1)
    # the stair: along the south face (+x), round the corner, up the east face (+z)
    lane = (rz0 - landing, rz0)
    x, y, z = rx0 + 4.0, 0.0, rz0
    heading_x = True
    for _ in range(n_flights):
        if heading_x and x + run > rx1:
            s.box(x - landing, rx1 + landing, y - 0.45, y, lane[0], lane[1])  # on to the corner
            heading_x, z = False, rz0
        if heading_x:
            s.stairs(np.array([x, (lane[0] + lane[1]) / 2]), np.array([1.0, 0.0]), landing, y, rise, riser, 0.28,
                     depth=0.45)
            x += run
            y += rise
            s.box(x, x + landing, y - 0.45, y, lane[0], lane[1])
            x += landing
        else:
            s.stairs(np.array([rx1 + landing / 2, z]), np.array([0.0, 1.0]), landing, y, rise, riser, 0.28, depth=0.45)
            z += run
            y += rise
            s.box(rx1, rx1 + landing, y - 0.45, y, z, z + landing)
            z += landing
    # the wall round the top (a parapet 2.5 m high), the gate at the stair's last landing
    gates = {"south": [(x - landing - rx0, landing)]} if heading_x else {"east": [(z - landing - rz0, landing)]}
    for side, (a, b) in {"south": ((rx0, rz0), (rx1, rz0)), "north": ((rx0, rz1), (rx1, rz1)),
                         "west": ((rx0, rz0), (rx0, rz1)), "east": ((rx1, rz0), (rx1, rz1))}.items():
        s.wall(a, b, top, top + 2.5, gates.get(side, []), thickness=0.4)
    # the cloister
    q, walk = 24.0, 3.0
    cx0, cz0 = rx0 + 20.0, rz0 + 10.0
    cx1, cz1 = cx0 + q, cz0 + q
    s.wall((cx0, cz0), (cx1, cz0), top, top + 4.0, [(q / 2 - 1.0, 2.0)])
    s.wall((cx0, cz1), (cx1, cz1), top, top + 4.0, [(q / 2 - 1.0, 2.0)])
    s.wall((cx0, cz0), (cx0, cz1), top, top + 4.0, [(q / 2 - 1.0, 2.0)])
    s.wall((cx1, cz0), (cx1, cz1), top, top + 4.0, [(q / 2 - 1.0, 2.0)])
    for t in np.arange(cx0 + walk, cx1 - walk + 0.1, 3.0):
        for zz in (cz0 + walk, cz1 - walk):
            s.box(t - 0.25, t + 0.25, top, top + 3.5, zz - 0.25, zz + 0.25)
    for t in np.arange(cz0 + walk + 3.0, cz1 - walk - 0.1, 3.0):
        for xx in (cx0 + walk, cx1 - walk):
            s.box(xx - 0.25, xx + 0.25, top, top + 3.5, t - 0.25, t + 0.25)
    ring = [(cx0, cx1, cz0, cz0 + walk), (cx0, cx1, cz1 - walk, cz1), (cx0, cx0 + walk, cz0, cz1), (cx1 - walk, cx1, cz0, cz1)]
    for r in ring:
        _lid(s, r[0], r[1], r[2], r[3], top + 4.0)
    # the church, north of the cloister: a door from the cloister walk's north door and one to the yard
    hz0, hz1 = cz1, cz1 + 11.0
    s.wall((cx0, hz1), (cx1, hz1), top, top + 6.0)
    s.wall((cx0, hz0), (cx0, hz1), top, top + 6.0, [(4.0, 2.0)])
    s.wall((cx1, hz0), (cx1, hz1), top, top + 6.0)
    for zz in np.arange(hz0 + 2.0, hz1 - 2.0, 1.2):  # pews either side of the nave's aisle
        _ridged(s, cx0 + 3.0, cx0 + q / 2 - 1.5, zz, zz + 0.5, top, top + 0.45)
        _ridged(s, cx0 + q / 2 + 1.5, cx1 - 5.0, zz, zz + 0.5, top, top + 0.45)
    _gable(s, cx0 - 0.3, cx1 + 0.3, hz0 - 0.3, hz1 + 0.3, top + 6.0)
    # the cells east of the cloister: a corridor along z, the cells off it
    ex0 = cx1 + 3.0
    ex1 = min(ex0 + 9.0, rx1 - 3.0)
    s.wall((ex0, cz0), (ex0, hz1), top, top + 3.5, [(2.0, 2.0), (hz1 - cz0 - 4.0, 2.0)])
    s.wall((ex1, cz0), (ex1, hz1), top, top + 3.5)
    s.wall((ex0, cz0), (ex1, cz0), top, top + 3.5)
    s.wall((ex0, hz1), (ex1, hz1), top, top + 3.5)
    cells = _split(cz0, hz1, rng.uniform(3.5, 4.0))
    s.wall((ex0 + 2.0, cz0), (ex0 + 2.0, hz1), top, top + 3.5, [(a - cz0 + 0.6, 1.6) for a in cells[:-1]])
    for zz in cells[1:-1]:
        s.wall((ex0 + 2.0, zz), (ex1, zz), top, top + 3.5)
    _gable(s, ex0 - 0.3, ex1 + 0.3, cz0 - 0.3, hz1 + 0.3, top + 3.5)
    # the refectory west of the cloister, tables and benches
    fx0, fx1 = rx0 + 5.0, cx0 - 3.0
    s.wall((fx0, cz0), (fx1, cz0), top, top + 4.0, [((fx1 - fx0) / 2 - 1.0, 2.0)])
    s.wall((fx0, cz1), (fx1, cz1), top, top + 4.0)
    s.wall((fx0, cz0), (fx0, cz1), top, top + 4.0)
    s.wall((fx1, cz0), (fx1, cz1), top, top + 4.0, [(q / 2 - 1.0, 2.0)])
    for zz in np.arange(cz0 + 3.0, cz1 - 3.0, 3.5):
        _ridged(s, fx0 + 2.0, fx1 - 2.5, zz, zz + 0.9, top, top + 0.75)
    _gable(s, fx0 - 0.3, fx1 + 0.3, cz0 - 0.3, cz1 + 0.3, top + 4.0)
    # kitchen garden beds in the north-west, a railed terrace at the west end (the parapet is its rail)
    for zz in np.arange(hz0 + 1.0, rz1 - 2.0, 2.2):
        for xx in np.arange(rx0 + 3.0, cx0 - 4.0, 5.0):
            if rng.random() < 0.7:
                s.box(xx, xx + 3.5, top, top + 0.25, zz, zz + 1.2)
    for _ in range(int(rng.integers(4, 8))):  # benches in the yard south of the buildings
        bx = rng.uniform(rx0 + 3.0, rx1 - 6.0)
        _ridged(s, bx, bx + 2.0, rz0 + 3.0, rz0 + 3.6, top, top + 0.5)
    # the hamlet and the trees at the foot, clear of the rock, the stair and the approach
    taken = [(rx0 - 6.0, rx1 + 6.0, rz0 - 6.0, rz1 + 2.0), (rx0 - 10.0, rx0 + 8.0, 0.0, rz0)]
    holes = [rock]
    for _ in range(int(rng.integers(26, 36))):
        for _ in range(50):
            w, d = rng.uniform(6.0, 12.0), rng.uniform(5.0, 9.0)
            hx, hz = rng.uniform(3.0, size_x - w - 3.0), rng.uniform(3.0, size_z - d - 3.0)
            if _clear(hx - 3.0, hx + w + 3.0, hz - 3.0, hz + d + 3.0, taken):
                holes.append(_ridged(s, hx, hx + w, hz, hz + d, -0.5, rng.uniform(3.0, 6.0)))
                taken.append((hx - 3.0, hx + w + 3.0, hz - 3.0, hz + d + 3.0))
                break
    _trees(s, rng, int(rng.integers(80, 120)), size_x, size_z, taken, (0.25, 0.45), 6.0)
    s.ground(0.0, size_x, 0.0, size_z, 0.0, holes)
    return s.mesh()


def night_market(seed: int) -> trimesh.Trimesh:
    """A night market 270-300 m long either side of a railway viaduct along x (a deck 12 m wide, 8 m up, ridged on
    top: no floor, on piers 2.5 m thick across it every 18.5-22.5 m). The arches between piers are open passages
    (two in five), shops with a 2 m door in both faces (one in three), shops with one door (a dead end) or closed
    stores (ridged, the ground stops under them): the market's two halves (14.5-16.5 m deep) meet only through the
    open arches and the two-door shops and round the viaduct's ends. Each half: an aisle 3.5 m wide along the
    viaduct, a double row of stalls (ridged, 2.5-4.5 m long, 2.4 m deep, 2.3 m high), an aisle 3.6-5.6 m wide and a
    single row of stalls against the site's wall (4 m high); the double row broken every 3-7 stalls by a cross aisle
    2.5-4 m wide, the single row only at the two or three side streets (4 m wide, through the wall onto a pavement 6
    m wide outside it; a first draft's gaps in the single row were dead-end bays, all 19 of seed 0's terminals), both
    stopping 16 m short of one end, where a food court of tables (ridged) stands; 8 m of street beyond each end.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length = rng.uniform(270.0, 300.0)
    half = rng.uniform(14.5, 16.5, size=2)  # the south and north halves' depths
    zv0 = float(half[0])
    zv1, size_z = zv0 + 12.0, zv0 + 12.0 + float(half[1])
    holes: list[tuple[float, float, float, float]] = []
    _ridged(s, 0.0, length, zv0, zv1, 8.0, 9.0)
    piers = [0.0]
    while piers[-1] + 2.5 + 22.5 < length:
        piers.append(piers[-1] + 2.5 + rng.uniform(16.0, 20.0))
    if length - piers[-1] - 2.5 > 6.0:
        piers.append(length - 2.5)
    for p in piers:  # ridged up into the deck: a flat top under it would be floor inside it
        holes.append(_ridged(s, p, p + 2.5, zv0, zv1, -0.5, 8.0))
    for a, b in pairwise(piers):
        kind = rng.choice(["open", "through", "shop", "store"], p=[0.4, 0.33, 0.14, 0.13])
        x0, x1 = a + 2.5, b
        if x1 - x0 < 10.0:
            continue  # a short last span is open
        if kind == "store":
            holes.append(_ridged(s, x0, x1, zv0, zv1, -0.5, 7.9))
        elif kind != "open":
            door = rng.uniform(2.0, x1 - x0 - 4.0)
            south = kind == "through" or rng.random() < 0.5  # a one-door shop opens to the south or the north
            s.wall((x0, zv0), (x1, zv0), -0.3, 8.0, [(door, 2.0)] if south else [])
            s.wall((x0, zv1), (x1, zv1), -0.3, 8.0, [(x1 - x0 - door - 2.0, 2.0)] if kind == "through" or not south else [])
            for zz in (zv0 + 2.5, zv1 - 3.3):  # shelves along the walls inside
                holes.append(_ridged(s, x0 + 1.5, x1 - 1.5, zz, zz + 0.8, -0.5, 1.8))
    for side in (0, 1):
        sign = -1.0 if side == 0 else 1.0
        edge = zv0 if side == 0 else zv1  # the viaduct's face on this half
        wall_z = 0.0 if side == 0 else size_z
        court_west = rng.random() < 0.5
        xa, xb = (16.0, length - 2.0) if court_west else (2.0, length - 16.0)
        double = sorted((edge + sign * 3.5, edge + sign * 8.3))
        single = sorted((wall_z - sign * 0.2, wall_z - sign * 2.6))
        streets = sorted(rng.uniform(20.0, length - 24.0, size=int(rng.integers(2, 4))))
        streets = [a for k, a in enumerate(streets) if k == 0 or a - streets[k - 1] > 10.0]
        s.wall((0.0, wall_z), (length, wall_z), -0.3, 4.0, [(a, 4.0) for a in streets], thickness=0.4)
        for r, (lo_z, hi_z) in enumerate((double, single)):
            x = xa + rng.uniform(0.0, 4.0)
            count = int(rng.integers(3, 8))
            while True:
                if count == 0 and r == 0:  # a cross aisle through the double row
                    x += rng.uniform(2.5, 4.0)
                    count = int(rng.integers(3, 8))
                w = rng.uniform(2.5, 4.5)
                street = [a for a in streets if x < a + 4.5 and a - 0.5 < x + w]
                if r == 1 and street:  # the row against the wall breaks only at the side streets
                    x = street[0] + 4.5
                    continue
                if x + w > xb:
                    break
                if r == 0:  # back to back
                    mid = (lo_z + hi_z) / 2
                    holes.append(_ridged(s, x, x + w, lo_z, mid, -0.5, 2.3))
                    holes.append(_ridged(s, x, x + w, mid, hi_z, -0.5, 2.3))
                else:
                    holes.append(_ridged(s, x, x + w, lo_z, hi_z, -0.5, 2.3))
                x += w
                count -= 1
        # the food court: tables 1.2 x 0.8 m in a grid in the 14 m the rows leave at one end
        x_court = 3.0 if court_west else length - 14.0
        lo, hi = sorted((wall_z - sign * 3.5, edge + sign * 1.5))
        for tx in np.arange(x_court, x_court + 11.0, 3.0):
            for tz in np.arange(lo, hi - 0.8, 2.6):
                holes.append(_ridged(s, float(tx), float(tx) + 1.2, float(tz), float(tz) + 0.8, -0.5, 0.75))
    s.ground(-8.0, length + 8.0, -6.0, size_z + 6.0, 0.0, holes)
    return s.mesh()


def cinema(seed: int) -> trimesh.Trimesh:
    """A multiplex cinema: 9-12 auditoria 13-17 m wide side by side along x north of a lobby 14 m deep (y = 0) whose
    north part is overhung by a foyer (y = 6, 6 m deep) reached by two flights (34 steps of 0.176 / 0.28 m) through
    openings in it. Each auditorium's floor rakes down from a cross aisle at the foyer's height (a 2 m door from the
    foyer) toward the screen: 12-14 tiers 1.1 m deep, each 0.43-0.5 m below the one behind (over the climb), with a
    row of seats (ridged) on each, so one walks only its two stepped aisles (1.4 m wide along the side walls, three
    steps a tier) to a flat front 6 m deep, whence a 2 m side door opens onto an exit corridor 2 m wide between the
    auditoria, which leads back to the lobby (a 2 m door) and out to a service yard behind (a 2 m door). A forecourt
    25 m deep with 40-59 parked cars (ridged, where they fit) and trees in front of the lobby's five entrance doors; the building under a
    roof at 50 degrees (:func:`_lid`), the lobby's counters and pillars.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    n = int(rng.integers(9, 13))
    widths = rng.uniform(13.0, 17.0, size=n)
    corridor, foyer_y = 2.0, 6.0
    tiers = int(rng.integers(12, 15))
    tread = 1.1
    depth = 2.0 + tiers * tread + 6.0
    lobby = 14.0
    xs = [0.0]
    for w in widths:
        xs.append(xs[-1] + w)
        xs.append(xs[-1] + corridor)
    width = xs[-1]
    z_back, z_screen = lobby, lobby + depth
    holes: list[tuple[float, float, float, float]] = []
    # the building's walls: south (entrances), north (the service doors), west and east
    doors = sorted(rng.uniform(3.0, width - 6.0, size=5))
    doors = [a for k, a in enumerate(doors) if k == 0 or a - doors[k - 1] > 4.0]
    s.wall((0.0, 0.0), (width, 0.0), -0.3, 10.0, [(a, 2.0) for a in doors], thickness=0.3)
    exits = [xs[2 * i + 1] for i in range(n)]  # the exit corridors' west edges
    s.wall((0.0, z_screen), (width, z_screen), -0.3, 10.0, [(x, corridor) for x in exits], thickness=0.3)
    s.wall((0.0, 0.0), (0.0, z_screen), -0.3, 10.0, thickness=0.3)
    s.wall((width, 0.0), (width, z_screen), -0.3, 10.0, thickness=0.3)
    # the lobby's north wall: a door at each exit corridor (ground) and each auditorium's foyer door (upper)
    for i in range(n):
        a0, a1 = xs[2 * i], xs[2 * i] + widths[i]
        s.wall((a0, z_back), (a1, z_back), -0.3, 10.0, [((a1 - a0) / 2 - 1.0, 2.0)], thickness=0.3)
        s.wall((a1, z_back), (a1 + corridor, z_back), foyer_y - 0.3, 10.0, thickness=0.3)  # over the corridor's door
        # side walls of the auditorium (the east one holds the exit door at the front)
        s.wall((a0, z_back), (a0, z_screen), -0.3, 10.0, thickness=0.3)
        s.wall((a1, z_back), (a1, z_screen), -0.3, 10.0, [(depth - 5.0, 2.0)], thickness=0.3)
        # the rake: the cross aisle at the foyer's height, then the tiers down to the flat front
        s.box(a0, a1, -0.3, foyer_y, z_back, z_back + 2.0)
        for t in range(tiers):
            y = foyer_y * (tiers - 1 - t) / tiers
            z0 = z_back + 2.0 + t * tread
            if t < tiers - 1:
                s.box(a0 + 1.55, a1 - 1.55, -0.3, y, z0, z0 + tread)
            _ridged(s, a0 + 1.7, a1 - 1.7, z0 + 0.05, z0 + 0.55, y, y + 0.45)
        holes.append((a0, a1, z_back, z_back + 2.0 + (tiers - 1) * tread))  # no ground inside the rake's blocks
        for ax in (a0 + 0.85, a1 - 0.85):  # the stepped aisles, three steps a tier, up from the front
            s.stairs(np.array([ax, z_back + 2.0 + tiers * tread]), np.array([0.0, -1.0]), 1.4, 0.0, foyer_y,
                     foyer_y / tiers / 3, tread / 3)
        # the screen, a low stage in front of it
        holes.append(_ridged(s, a0 + 1.0, a1 - 1.0, z_screen - 1.5, z_screen - 0.2, -0.5, 0.9))
    # the foyer over the lobby's north part, the two flights up to it through openings in it
    run = 34 * 0.28
    f_lo = rng.uniform(4.0, width / 2 - run - 4.0)
    f_hi = rng.uniform(width / 2 + 4.0, width - run - 4.0)
    openings = [(f_lo, f_lo + run, lobby - 6.0, lobby - 3.6), (f_hi, f_hi + run, lobby - 6.0, lobby - 3.6)]
    s.slab(0.0, width, lobby - 6.0, lobby, foyer_y, openings)
    for x0, _x1, z0, z1 in openings:
        s.stairs(np.array([x0, (z0 + z1) / 2]), np.array([1.0, 0.0]), 2.2, 0.0, foyer_y, foyer_y / 34, 0.28, depth=0.45)
    s.wall((0.0, lobby - 6.0), (width, lobby - 6.0), foyer_y, foyer_y + 1.1, thickness=0.1)
    for x0, x1, z0, z1 in openings:  # rails round the openings but at the flights' heads
        s.wall((x0, z0), (x1, z0), foyer_y, foyer_y + 1.1, thickness=0.1)
        s.wall((x0, z1), (x1, z1), foyer_y, foyer_y + 1.1, thickness=0.1)
        s.wall((x0, z0), (x0, z1), foyer_y, foyer_y + 1.1, thickness=0.1)
    # the lobby's counters and pillars, clear of the flights and doors
    taken = [(x0 - 3.0, x1 + 3.0, z0 - 3.0, z1 + 1.0) for x0, x1, z0, z1 in openings]
    taken += [(a - 1.0, a + 3.0, 0.0, 4.0) for a in doors]
    for _ in range(int(rng.integers(3, 6))):
        for _ in range(50):
            w = rng.uniform(4.0, 9.0)
            cx, cz = rng.uniform(2.0, width - w - 2.0), rng.uniform(3.5, lobby - 9.0)
            if _clear(cx - 2.0, cx + w + 2.0, cz - 2.0, cz + 3.0, taken):
                holes.append(_ridged(s, cx, cx + w, cz, cz + 0.8, -0.5, 1.1))
                taken.append((cx - 2.0, cx + w + 2.0, cz - 2.0, cz + 3.0))
                break
    for px in np.arange(8.0, width - 4.0, 8.0):
        if _clear(px - 0.8, px + 0.8, lobby - 6.8, lobby - 5.2, taken):
            s.box(px - 0.3, px + 0.3, -0.3, foyer_y - 0.3, lobby - 6.3, lobby - 5.7)
    _lid(s, -0.3, width + 0.3, -0.3, z_screen + 0.3, 10.0)
    # the forecourt (cars, trees) in front, a service yard 8 m deep behind, a path 4 m wide round each end
    for _ in range(int(rng.integers(40, 60))):
        cx, cz = rng.uniform(2.0, width - 6.5), rng.uniform(-24.0, -4.0)
        if _clear(cx - 0.6, cx + 5.1, cz - 0.6, cz + 2.4, taken):
            holes.append(_ridged(s, cx, cx + 4.5, cz, cz + 1.8, -0.5, 1.4))
            taken.append((cx - 0.6, cx + 5.1, cz - 0.6, cz + 2.4))
    for _ in range(int(rng.integers(8, 14))):
        p = np.array([rng.uniform(-3.0, width + 3.0), rng.uniform(z_screen + 2.0, z_screen + 7.0)])
        _trunk(s, p, 0.3, -0.5, 5.0)
    s.ground(-5.0, width + 5.0, -26.0, z_screen + 8.0, 0.0, holes)
    return s.mesh()


def estate(seed: int) -> trimesh.Trimesh:
    """A deck-access housing estate ("streets in the sky"): four or five slab blocks 70-90 m long and 10 m deep
    along x, 16-20 m apart (courtyards), each closed (flats one does not enter; a roof at 50 degrees) with an open
    gallery 2.4 m wide along its north face on storeys 1-3 (3, 6 and 9 m up, railed), reached by an open switchback
    stair at each end (:func:`_switchback`, 3 m storeys). Through each block but the first a pend 3 m wide at the
    ground (a passage between courtyards) and, on one or two storeys, a landing through it from its north gallery
    to the block's south face, where a bridge 3 m wide (railed) crosses the courtyard from the gallery of the block
    to the south (a first draft's landings on the other storeys, railed, were dead ends 10 m long: 4 of seed 0's 10
    terminals): one crosses between blocks in the sky or on the ground. The
    courtyards hold play areas (frames 0.3 m high, under the climb), bin stores and parked cars (ridged) and trees.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    n = int(rng.integers(4, 6))
    storey, gallery = 3.0, 2.4
    well = _well_length(storey)
    blocks: list[tuple[float, float, float, float]] = []
    z = 12.0
    for _ in range(n):
        length = rng.uniform(70.0, 90.0)
        bx0 = 12.0 + rng.uniform(-4.0, 4.0)
        blocks.append((bx0, bx0 + length, z, z + 10.0))
        z += 10.0 + gallery + rng.uniform(16.0, 20.0)
    size_x = max(b[1] for b in blocks) + 12.0
    size_z = blocks[-1][3] + gallery + well + 8.0
    pends: list[float] = []  # the pend of block k + 1, reached from block k's gallery
    bridges: list[list[int]] = []  # the storeys of each pend's bridges
    for k in range(1, n):
        lo = max(blocks[k][0], blocks[k - 1][0]) + 12.0
        hi = min(blocks[k][1], blocks[k - 1][1]) - 15.0
        pends.append(float(rng.uniform(lo, hi)))
        bridges.append(sorted(int(v) for v in rng.choice([1, 2, 3], size=int(rng.integers(1, 3)), replace=False)))
    holes: list[tuple[float, float, float, float]] = []
    for k, (bx0, bx1, bz0, bz1) in enumerate(blocks):
        pend = pends[k - 1] if k > 0 else None
        pieces = [(bx0, bx1)] if pend is None else [(bx0, pend), (pend + 3.0, bx1)]
        for a, b in pieces:
            holes.append(_ridged(s, a, b, bz0, bz1, -0.5, storey * 4 - 0.3))
        for level in range(1, 4):
            y = storey * level
            s.slab(bx0 - 4.0, bx1 + 4.0, bz1, bz1 + gallery, y, [])  # the gallery and the stairs' landings
            openings = [(0.0, 4.0), (bx1 - bx0 + 4.0, 4.0)]  # the stairs
            if k + 1 < n and level in bridges[k]:
                openings.append((pends[k] - (bx0 - 4.0), 3.0))
            s.wall((bx0 - 4.0, bz1 + gallery), (bx1 + 4.0, bz1 + gallery), y, y + 1.1, openings, thickness=0.1)
            for end in (bx0 - 4.0, bx1 + 4.0):
                s.wall((end, bz1), (end, bz1 + gallery), y, y + 1.1, thickness=0.1)
            if pend is not None and level in bridges[k - 1]:  # a landing through the pend and the bridge
                s.slab(pend, pend + 3.0, bz0, bz1, y, [])
                z_from = blocks[k - 1][3] + gallery
                s.box(pend, pend + 3.0, y - 0.5, y, z_from, bz0)
                for rx in (pend, pend + 3.0):
                    s.box(rx - 0.05, rx + 0.05, y, y + 1.1, z_from, bz0)
        for level in range(3):
            for wx in (bx0 - 4.0, bx1):
                _switchback(s, wx, bz1 + gallery - 2.0, storey * level, storey)
    # the courtyards: play frames, bin stores, cars, trees, clear of the blocks, their stairs and the pends
    taken = [(b[0] - 5.0, b[1] + 5.0, b[2] - 1.0, b[3] + gallery + well + 1.0) for b in blocks]
    taken += [(p - 1.0, p + 4.0, 0.0, size_z) for p in pends]
    for _ in range(int(rng.integers(50, 70))):
        for _ in range(30):
            w, d = rng.uniform(3.0, 6.0), rng.uniform(1.5, 4.0)
            cx, cz = rng.uniform(2.0, size_x - w - 2.0), rng.uniform(2.0, size_z - d - 2.0)
            if _clear(cx - 1.5, cx + w + 1.5, cz - 1.5, cz + d + 1.5, taken):
                if rng.random() < 0.5:
                    holes.append(_ridged(s, cx, cx + w, cz, cz + d, -0.5, rng.uniform(1.2, 2.0)))
                else:
                    s.box(cx, cx + w, 0.0, 0.3, cz, cz + d)
                taken.append((cx - 1.5, cx + w + 1.5, cz - 1.5, cz + d + 1.5))
                break
    _trees(s, rng, int(rng.integers(20, 35)), size_x, size_z, taken, (0.25, 0.4), 7.0)
    s.ground(0.0, size_x, 0.0, size_z, 0.0, holes)
    return s.mesh()


def _face_switchback(s: _Solids, origin: np.ndarray, along: np.ndarray, out: np.ndarray, flights: int) -> tuple[float, float]:
    """A switchback up a vertical face in two lanes 2 m wide: flight k (17 steps of 0.176 / 0.28 m, blocks 0.45 m
    deep, 3 m a flight) climbs from 3k m, the even ones along ``along`` in the lane next to the face from 2 m past
    ``origin`` (x, z: on the face's foot line), the odd ones back in the outer lane, each onto a landing 2 m long
    across both lanes (the even flights' 6.76 m past ``origin``, the odd ones' at ``origin``). ``along`` and ``out``
    (away from the face) are unit plan vectors along x or z. Returns the span (from, to) along ``along``, metres from
    ``origin``, of the top landing."""
    run, landing = 17 * 0.28, 2.0

    def box(u0: float, u1: float, y: float) -> None:
        corners = np.array([origin + along * u + out * v for u in (u0, u1) for v in (0.0, 4.0)])
        lo, hi = corners.min(axis=0), corners.max(axis=0)
        s.box(lo[0], hi[0], y - 0.45, y, lo[1], hi[1])

    span = (0.0, landing)
    for k in range(flights):
        if k % 2 == 0:
            s.stairs(origin + along * landing + out * 1.0, along, 2.0, 3.0 * k, 3.0, 3.0 / 17, 0.28, depth=0.45)
            span = (landing + run, 2 * landing + run)
        else:
            s.stairs(origin + along * (landing + run) + out * 3.0, -along, 2.0, 3.0 * k, 3.0, 3.0 / 17, 0.28, depth=0.45)
            span = (0.0, landing)
        box(*span, 3.0 * (k + 1))
    return span


def dam(seed: int) -> trimesh.Trimesh:
    """A gravity dam: a wall 150-180 m long along x and 8 m thick, its crest a road 24 or 27 m up between parapets
    1.1 m high (lamp posts on the down-stream one), its down-stream face vertical, between two hilltops at the
    crest's height (40 m wide, 90 m deep, vertical cliffs; a car park and a visitor centre on the west one) over a
    valley floor at y = 0 down stream (no floor up stream: the reservoir). A spillway 16-20 m wide near the middle
    (a chute steeper than 45 degrees; the road crosses it on a bridge) feeds a river 10-12 m wide down the valley
    (no floor), crossed by a footbridge 2 m and a road bridge 5 m wide (railed). The only ways between the valley
    and the crest: a switchback stair (:func:`_face_switchback`) against the dam's face on one side of the spillway
    and one against the east hilltop's cliff. A powerhouse (walled, a 2 m door, machines) against the face on the
    spillway's other side.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length = rng.uniform(150.0, 180.0)
    crest = 24.0 if rng.random() < 0.5 else 27.0
    hill, zd = 40.0, 60.0  # the hilltops' width; the dam's down-stream face (the valley floor from z = 0 to it)
    dx0, dx1 = hill, hill + length
    sw = rng.uniform(16.0, 20.0)
    sx0 = dx0 + length / 2 - sw / 2 + rng.uniform(-10.0, 10.0)
    sx1 = sx0 + sw
    for a, b in ((dx0, sx0), (sx1, dx1)):  # the dam either side of the spillway
        s.box(a, b, -1.0, crest, zd, zd + 8.0)
    # the chute: 21-24 m down over 16 m, 53-56 degrees (a first draft's, over 22 m, was 44 degrees under a 24 m crest:
    # walkable, an area of 428 m² on seed 0 no walk joins)
    s.hull(np.array([[x, y, z] for x in (sx0, sx1) for y, z in ((crest - 4.0, zd + 8.0), (-1.0, zd + 8.0), (-1.0, zd - 8.0))]))
    s.box(sx0, sx1, crest - 0.8, crest, zd, zd + 8.0)  # the road's bridge over the spillway
    for a, b in ((0.0, dx0), (dx1, dx1 + hill)):  # the hilltops
        s.box(a, b, -1.0, crest, 0.0, zd + 30.0)
    flights = int(crest / 3.0)
    east = rng.random() < 0.5
    stair_x = sx1 + 8.0 if east else sx0 - 8.0 - 6.76
    span = _face_switchback(s, np.array([stair_x, zd]), np.array([1.0, 0.0]), np.array([0.0, -1.0]), flights)
    s.wall((dx0, zd), (dx1, zd), crest, crest + 1.1, [(stair_x - dx0 + span[0], span[1] - span[0])], thickness=0.3)
    s.wall((dx0, zd + 8.0), (dx1, zd + 8.0), crest, crest + 1.1, thickness=0.3)
    for lx in np.arange(dx0 + 8.0, dx1 - 4.0, 16.0):  # lamp posts on the down-stream parapet
        s.box(lx - 0.15, lx + 0.15, crest, crest + 5.0, zd + 0.15, zd + 0.45)
    cliff_z = rng.uniform(8.0, zd - 25.0)
    _face_switchback(s, np.array([dx1, cliff_z]), np.array([0.0, 1.0]), np.array([-1.0, 0.0]), flights)
    # the river from the chute's foot down the valley, its bridges
    rw = rng.uniform(10.0, 12.0)
    rx0 = (sx0 + sx1) / 2 - rw / 2
    river = (rx0, rx0 + rw, 0.0, zd - 8.0)
    holes = [river, (sx0, sx1, zd - 8.0, zd)]
    for width, bz in ((2.0, rng.uniform(8.0, 20.0)), (5.0, rng.uniform(28.0, 38.0))):
        s.box(rx0 - 1.5, rx0 + rw + 1.5, -0.5, 0.15, bz, bz + width)
        for rz in (bz, bz + width):
            s.box(rx0, rx0 + rw, 0.15, 1.25, rz - 0.05, rz + 0.05)
    # the powerhouse against the face on the spillway's other side: walls, a door, machines
    px0 = sx0 - 34.0 if east else sx1 + 10.0
    pz0 = zd - 16.0
    door = rng.uniform(3.0, 19.0)
    s.wall((px0, pz0), (px0 + 24.0, pz0), -0.3, 10.0, [(door, 2.0)], thickness=0.3)
    for x in (px0, px0 + 24.0):
        s.wall((x, pz0), (x, zd), -0.3, 10.0, thickness=0.3)
    _gable(s, px0 - 0.3, px0 + 24.3, pz0 - 0.3, zd, 10.0)
    for k in range(3):
        holes.append(_ridged(s, px0 + 3.0 + 7.0 * k, px0 + 7.5 + 7.0 * k, zd - 9.0, zd - 4.0, -0.5, 3.0))
    # the west hilltop: a car park and a visitor centre (a room with a 2 m door)
    for _ in range(int(rng.integers(10, 18))):
        cx, cz = rng.uniform(4.0, hill - 8.0), rng.uniform(zd - 30.0, zd - 2.0)
        _ridged(s, cx, cx + 4.5, cz, cz + 1.8, crest - 0.5, crest + 1.2)  # low: no head room inside
    vz0 = rng.uniform(6.0, 14.0)
    s.wall((6.0, vz0), (30.0, vz0), crest, crest + 4.0, thickness=0.3)
    s.wall((6.0, vz0 + 14.0), (30.0, vz0 + 14.0), crest, crest + 4.0, [(10.0, 2.0)], thickness=0.3)
    for x in (6.0, 30.0):
        s.wall((x, vz0), (x, vz0 + 14.0), crest, crest + 4.0, thickness=0.3)
    _gable(s, 5.7, 30.3, vz0 - 0.3, vz0 + 14.3, crest + 4.0)
    # rocks and trees on the valley floor
    taken = [river, (sx0 - 2.0, sx1 + 2.0, zd - 16.0, zd), (px0 - 2.0, px0 + 26.0, pz0 - 4.0, zd),
             (stair_x - 3.0, stair_x + 10.0, zd - 7.0, zd), (dx1 - 7.0, dx1, cliff_z - 2.0, cliff_z + 11.0)]
    for _ in range(int(rng.integers(110, 150))):
        p = np.array([rng.uniform(dx0 + 2.0, dx1 - 2.0), rng.uniform(2.0, zd - 2.0)])
        if _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, taken):
            if rng.random() < 0.6:
                _trunk(s, p, rng.uniform(0.25, 0.45), -0.5, 6.0)
            else:
                s.rock(rng, p, 0.6, -0.5, 1.0)
            taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    s.ground(dx0, dx1, 0.0, zd, 0.0, holes)
    return s.mesh()


def garden(seed: int) -> trimesh.Trimesh:
    """A formal garden inside a wall 3 m high, 150-170 x 110-120 m, with one gate 4 m wide in the south wall (nothing
    beyond it). Along the north a terrace 1.5 m up (balustraded, the house behind it ridged, no way in) reached by
    three flights down its front along -z (6 m wide on the axis, 2.4 m at its ends); in the middle a parterre of box
    beds (ridged, 0.3 m eaves: nothing on them is floor) in a grid of gravel paths 3 m wide round a fountain basin
    (ridged) on the main axis (6 m wide); a canal 6 m wide along x (no floor) from wall to wall across the south,
    crossed only by a bridge on the axis and one more; in the west a hedge maze of 11-12 x 10-11 cells 2.8 m square
    (hedges 2.2 m high and 0.6 m thick, a perfect maze: one way between any two cells, cut by a depth-first walk;
    one entrance on its east side, one exit on its south side), a clearing of 2 x 2 cells at its centre; in the
    south-west a grotto (a chamber 14 x 10 m under a ridged lid at 3.6 m, two openings 2 m wide, rocks and a basin
    inside); in the east
    a bosquet of trees in a grid with an orangery (ridged) and a belvedere up a flight (a platform 2.5 m up, railed).
    Statues (octagonal plinths) and benches along the paths.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = rng.uniform(150.0, 170.0), rng.uniform(110.0, 120.0)
    axis = size_x / 2 + rng.uniform(-5.0, 5.0)
    holes: list[tuple[float, float, float, float]] = []
    taken: list[tuple[float, float, float, float]] = []
    # the wall round, its gate on the axis
    s.wall((0.0, 0.0), (size_x, 0.0), -0.5, 3.0, [(axis - 2.0, 4.0)], thickness=0.5)
    s.wall((0.0, size_z), (size_x, size_z), -0.5, 3.0, thickness=0.5)
    for x in (0.0, size_x):
        s.wall((x, 0.0), (x, size_z), -0.5, 3.0, thickness=0.5)
    # the terrace and the house
    tz0, tz1 = size_z - 22.0, size_z - 8.0
    run = math.ceil(1.5 / 0.18) * 0.28
    s.box(0.25, size_x - 0.25, -0.5, 1.5, tz0, tz1)
    for x0, x1 in ((0.25, axis - 25.0), (axis + 25.0, size_x - 0.25)):  # the terrace stops under the house
        s.box(x0, x1, -0.5, 1.5, tz1, size_z - 0.25)
    holes.append((0.0, size_x, tz0, size_z))
    _ridged(s, axis - 25.0, axis + 25.0, tz1, size_z - 0.25, -0.5, 9.0)
    flights = [(axis, 6.0), (12.0, 2.4), (size_x - 12.0, 2.4)]
    for x, w in flights:
        s.stairs(np.array([x, tz0 - run]), np.array([0.0, 1.0]), w, 0.0, 1.5, 1.5 / math.ceil(1.5 / 0.18), 0.28)
        taken.append((x - w / 2 - 1.5, x + w / 2 + 1.5, tz0 - run - 3.0, tz0))
    s.wall((0.25, tz0 + 0.1), (size_x - 0.25, tz0 + 0.1), 1.5, 2.5,
           sorted((x - w / 2 - 0.25, w) for x, w in flights), thickness=0.2)
    for x in np.arange(6.0, size_x - 6.0, rng.uniform(7.0, 10.0)):  # urns on the terrace
        if all(abs(x - fx) > 5.0 for fx, _ in flights) and not axis - 26.0 < x < axis + 26.0:
            _trunk(s, np.array([x, tz1 - 1.0]), 0.4, 1.5, 2.6)
    # the canal across the south and its bridges
    cz0 = rng.uniform(14.0, 18.0)
    canal = (0.0, size_x, cz0, cz0 + 6.0)  # wall to wall: the bridges are the only ways over
    second = rng.uniform(size_x * 0.62, size_x - 20.0)
    for bx, w in ((axis, 6.0), (second, 3.0)):
        holes.append((canal[0], bx - w / 2, canal[2], canal[3]))
        canal = (bx + w / 2, canal[1], canal[2], canal[3])
        for x in (bx - w / 2, bx + w / 2):
            s.box(x - 0.1, x + 0.1, 0.0, 1.1, cz0 - 0.5, cz0 + 6.5)
    holes.append(canal)
    taken.append((0.0, size_x, cz0 - 1.5, cz0 + 7.5))
    # the parterre: beds in a grid of paths round the fountain on the axis
    px0, px1, pz0, pz1 = axis - rng.uniform(28.0, 34.0), axis + rng.uniform(28.0, 34.0), cz0 + 12.0, tz0 - run - 6.0
    cols, rows = int(rng.integers(3, 5)), int(rng.integers(4, 6))
    xs, zs = np.linspace(px0, px1, 2 * cols + 2), np.linspace(pz0, pz1, rows + 1)
    for i in range(len(xs) - 1):
        for a, b in pairwise(zs):
            x0, x1 = xs[i] + 1.5, xs[i + 1] - 1.5
            if x1 - x0 < 2.0 or (x0 < axis + 3.0 and x1 > axis - 3.0):
                continue
            if rng.random() < 0.2:  # a bed cut in two by a path along x
                m = (a + b) / 2
                holes += [_ridged(s, x0, x1, a + 1.5, m - 1.5, -0.5, 0.3), _ridged(s, x0, x1, m + 1.5, b - 1.5, -0.5, 0.3)]
            else:
                holes.append(_ridged(s, x0, x1, a + 1.5, b - 1.5, -0.5, 0.3))
    fz = (pz0 + pz1) / 2
    holes.append(_ridged(s, axis - 4.0, axis + 4.0, fz - 4.0, fz + 4.0, -0.5, 0.6))
    taken.append((px0 - 2.0, px1 + 2.0, pz0 - 2.0, pz1 + 2.0))
    for z in zs:  # statues where the cross paths meet the axis
        for x in (axis - 4.5, axis + 4.5):
            _trunk(s, np.array([x, z]), 0.5, -0.5, 2.5)
    # the hedge maze in the west
    n, m, cell = int(rng.integers(11, 13)), int(rng.integers(10, 12)), 2.8
    mx0 = rng.uniform(6.0, max(6.5, px0 - 6.0 - n * cell))
    mz0 = cz0 + 22.0 + rng.uniform(0.0, max(0.5, pz1 - cz0 - 22.0 - m * cell))  # the grotto goes south of it
    centre = {(n // 2 - 1 + i, m // 2 - 1 + j) for i in (0, 1) for j in (0, 1)}
    seen, stack, open_walls = {(0, 0)} | centre, [(0, 0)], set()
    for c in centre:
        for d in centre:
            if abs(c[0] - d[0]) + abs(c[1] - d[1]) == 1:
                open_walls.add(frozenset((c, d)))
    door_to_centre = False
    while stack:
        i, j = stack[-1]
        nexts = [(i + di, j + dj) for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1))
                 if 0 <= i + di < n and 0 <= j + dj < m
                 and ((i + di, j + dj) not in seen or ((i + di, j + dj) in centre and not door_to_centre))]
        if not nexts:
            stack.pop()
            continue
        c = nexts[int(rng.integers(len(nexts)))]
        open_walls.add(frozenset(((i, j), c)))
        if c in centre:
            door_to_centre = True
            continue
        seen.add(c)
        stack.append(c)
    entrance, exit_ = int(rng.integers(m)), int(rng.integers(n))
    for i in range(n + 1):  # walls along z at x = mx0 + i * cell
        for j in range(m):
            inner = 0 < i < n and frozenset(((i - 1, j), (i, j))) in open_walls
            if not inner and not (i == n and j == entrance):
                s.box(mx0 + i * cell - 0.3, mx0 + i * cell + 0.3, -0.5, 2.2, mz0 + j * cell - 0.3, mz0 + (j + 1) * cell + 0.3)
    for j in range(m + 1):  # walls along x
        for i in range(n):
            inner = 0 < j < m and frozenset(((i, j - 1), (i, j))) in open_walls
            if not inner and not (j == 0 and i == exit_):
                s.box(mx0 + i * cell - 0.3, mx0 + (i + 1) * cell + 0.3, -0.5, 2.2, mz0 + j * cell - 0.3, mz0 + j * cell + 0.3)
    taken.append((mx0 - 2.0, mx0 + n * cell + 2.0, mz0 - 2.0, mz0 + m * cell + 2.0))
    # the grotto in the south-west, between the canal and the maze
    gx0, gz0 = rng.uniform(8.0, 14.0), cz0 + 9.5
    gx1, gz1 = gx0 + 14.0, gz0 + 10.0
    s.wall((gx0, gz0), (gx1, gz0), -0.5, 2.6, thickness=0.8)
    s.wall((gx0, gz1), (gx1, gz1), -0.5, 2.6, [(rng.uniform(2.0, 10.0), 2.0)], thickness=0.8)
    s.wall((gx0, gz0), (gx0, gz1), -0.5, 2.6, thickness=0.8)
    s.wall((gx1, gz0), (gx1, gz1), -0.5, 2.6, [(rng.uniform(2.0, 6.0), 2.0)], thickness=0.8)
    _lid(s, gx0 - 0.4, gx1 + 0.4, gz0 - 0.4, gz1 + 0.4, 3.6)
    holes.append(_ridged(s, gx0 + 5.0, gx0 + 8.0, gz0 + 0.4, gz0 + 2.5, -0.5, 0.5))  # the basin
    for _ in range(4):
        s.rock(rng, np.array([rng.uniform(gx0 + 2.0, gx1 - 2.0), rng.uniform(gz0 + 4.0, gz1 - 2.5)]), 0.4, -0.5, 1.8)
    taken.append((gx0 - 2.0, gx1 + 2.0, gz0 - 2.0, gz1 + 2.0))
    # the bosquet in the east: trees in a grid, the orangery and the belvedere
    bx0 = px1 + 6.0
    ox = rng.uniform(bx0 + 2.0, size_x - 22.0)
    holes.append(_ridged(s, ox, ox + 18.0, tz0 - run - 14.0, tz0 - run - 6.0, -0.5, 4.0))
    taken.append((ox - 2.0, ox + 20.0, tz0 - run - 16.0, tz0))
    vx, vz = rng.uniform(bx0 + 2.0, size_x - 12.0), rng.uniform(cz0 + 12.0, cz0 + 20.0)
    s.box(vx, vx + 6.0, -0.5, 2.5, vz, vz + 6.0)
    holes.append((vx, vx + 6.0, vz, vz + 6.0))
    vrun = math.ceil(2.5 / 0.18) * 0.28
    s.stairs(np.array([vx - vrun, vz + 1.5]), np.array([1.0, 0.0]), 2.0, 0.0, 2.5, 2.5 / math.ceil(2.5 / 0.18), 0.28)
    _rail_ring(s, vx, vx + 6.0, vz, vz + 6.0, 2.5, {"west": [(0.4, 2.2)]})
    taken.append((vx - vrun - 2.0, vx + 8.0, vz - 2.0, vz + 8.0))
    for x in np.arange(bx0 + 2.0, size_x - 3.0, 5.0):
        for z in np.arange(cz0 + 10.0, tz0 - run - 3.0, 5.0):
            p = np.array([x, z]) + rng.uniform(-0.8, 0.8, 2)
            if rng.random() < 0.75 and _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken):
                _trunk(s, p, rng.uniform(0.25, 0.4), -0.5, 6.0)
    _benches(s, rng, int(rng.integers(25, 40)), size_x - 5.0, tz0 - 4.0, taken)  # along the paths
    s.ground(0.0, size_x, 0.0, size_z, 0.0, holes)
    return s.mesh()


def _benches(s: _Solids, rng: np.random.Generator, tries: int, x1: float, z1: float,
             taken: list[tuple[float, float, float, float]]) -> None:
    """``tries`` benches (1.8 x 0.6 m, 0.5 m high, along x) at plan corners uniform over [3, x1] x [3, z1] m, each
    placed only 1 m clear of every rectangle of ``taken`` (which then holds it, 1 m round)."""
    for _ in range(tries):
        p = np.array([rng.uniform(3.0, x1), rng.uniform(3.0, z1)])
        if _clear(p[0] - 1.0, p[0] + 2.8, p[1] - 1.0, p[1] + 1.6, taken):
            s.box(p[0], p[0] + 1.8, -0.5, 0.5, p[1], p[1] + 0.6)
            taken.append((p[0] - 1.0, p[0] + 2.8, p[1] - 1.0, p[1] + 1.6))


def _stair_tower(s: _Solids, x0: float, z0: float, y0: float, storeys: int, doors: tuple[int, ...] = (0,),
                 storey: float = 4.0) -> float:
    """A walled switchback well 4 m wide (:func:`_switchback`) from plan point (x0, z0) along +z, up ``storeys``
    storeys ``storey`` m apart from ``y0``: a floor over the landing of every storey above the first (the well beyond
    it open), walls 0.4 m thick round the well, a door 1.6 m wide at the landing's end on each storey of ``doors`` (0
    the foot; ``storeys``, the top, is walled only when it has a door), and on the top a rail across the lane no
    flight climbs. Returns the top's height (m)."""
    well = _well_length(storey)
    for k in range(storeys + 1):
        y = y0 + k * storey
        if k:
            s.slab(x0, x0 + 4.0, z0, z0 + well, y, [(x0, x0 + 4.0, z0 + 2.0, z0 + well)])
        if k < storeys:
            _switchback(s, x0, z0, y, storey)
        if k < storeys or k in doors:
            s.wall((x0, z0 - 0.2), (x0 + 4.0, z0 - 0.2), y, y + storey, [(1.2, 1.6)] if k in doors else [], thickness=0.4)
            s.wall((x0, z0 + well + 0.2), (x0 + 4.0, z0 + well + 0.2), y, y + storey, thickness=0.4)
            for x in (x0 - 0.2, x0 + 4.2):
                s.wall((x, z0 - 0.4), (x, z0 + well + 0.4), y, y + storey, thickness=0.4)
    top = y0 + storeys * storey
    s.box(x0, x0 + 2.0, top, top + 1.0, z0 + 1.9, z0 + 2.0)
    return top


def lighthouse(seed: int) -> trimesh.Trimesh:
    """A lighthouse on a tidal island at the end of a causeway, the sea (no floor) all round. The mainland, 70 x 110
    m at y = 0: a village street of houses (ridged), a car park of cars (ridged), trees and benches. The causeway, 5 m
    wide at y = 0 and the only way to the island: 120-160 m out along +x, a dog-leg of 20-35 m along z, 50-70 m on
    along x, with two passing bays (3 m wider over 10 m) and a refuge (a platform 4 m square 3 m up on legs, railed,
    up a flight square to the causeway). The island: a rock shelf at y = 0, 72-80 x 60-68 m, pocked by tide
    pools (holes, no floor) and rocks, round a plinth 3 m high with vertical faces (36 x 30 m), reached by one flight
    3 m wide from the causeway's side and one 1.6 m wide on the far side, toward a jetty 30-40 m long. On the plinth,
    inside a wall 1.2 m high open at the flights' heads: two keeper's cottages (a door 1.6 m wide and a room through a
    second door; gabled), a fog-horn house and an oil store (ridged), and the tower: a switchback well 4 m wide
    (:func:`_switchback`) up five storeys 4 m apart, walled, entered by a door at its foot; the top storey opens by a
    door onto a gallery 2.2 m wide round the tower, railed, under the lantern's ridged cap.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    # the mainland: a street of houses, a car park, trees
    land_x, land_z = 70.0, 110.0
    zc = rng.uniform(45.0, 65.0)
    holes: list[tuple[float, float, float, float]] = []
    taken = [(land_x - 12.0, land_x, zc - 5.0, zc + 10.0)]
    for z0, z1 in ((zc + 12.0, zc + 22.0), (zc - 22.0, zc - 12.0), (zc + 32.0, zc + 40.0), (zc - 40.0, zc - 32.0)):
        # houses either side of the street to the causeway, a row behind each
        x = rng.uniform(2.0, 6.0)
        while x < land_x - 14.0:
            w = rng.uniform(6.0, 10.0)
            holes.append(_ridged(s, x, x + w, z0, z1, -0.5, rng.uniform(4.0, 6.0)))
            taken.append((x - 1.0, x + w + 1.0, z0 - 1.0, z1 + 1.0))
            x += w + rng.uniform(1.5, 5.0)
    cz = rng.uniform(land_z - 30.0, land_z - 24.0)
    for i in range(int(rng.integers(6, 11))):  # cars in the car park
        x = 6.0 + i * 3.0
        if rng.random() < 0.75:
            holes.append(_ridged(s, x, x + 1.9, cz, cz + 4.4, -0.5, 1.0))
        taken.append((x - 0.5, x + 2.4, cz - 1.0, cz + 5.4))
    _trees(s, rng, int(rng.integers(90, 120)), land_x - 4.0, land_z, taken, (0.25, 0.45), 6.0)
    _benches(s, rng, 20, land_x - 6.0, land_z - 4.0, taken)
    s.ground(0.0, land_x, 0.0, land_z, 0.0, holes)
    # the causeway: out along x, a dog-leg along z, on along x
    l1, dz, l2 = rng.uniform(120.0, 160.0), rng.choice([-1.0, 1.0]) * rng.uniform(20.0, 35.0), rng.uniform(50.0, 70.0)
    x1, z1, x2 = land_x + l1, zc + dz, land_x + l1 + l2
    s.box(land_x, x1 + 2.5, -1.0, 0.0, zc - 2.5, zc + 2.5)
    s.box(x1 - 2.5, x1 + 2.5, -1.0, 0.0, min(zc, z1) - 2.5, max(zc, z1) + 2.5)
    s.box(x1 - 2.5, x2, -1.0, 0.0, z1 - 2.5, z1 + 2.5)
    for f in rng.uniform(0.2, 0.8, 2):  # passing bays on the first leg
        bx = land_x + f * (l1 - 20.0) + 5.0
        s.box(bx, bx + 10.0, -1.0, 0.0, zc + 2.5, zc + 5.5)
    rx = x1 + rng.uniform(0.3, 0.7) * l2  # the refuge, on the last leg
    side = 1.0 if rng.random() < 0.5 else -1.0
    steps = 17
    run = steps * 0.28
    rz = z1 + side * 2.5
    s.stairs(np.array([rx, rz]), np.array([0.0, side]), 1.8, 0.0, 3.0, 3.0 / steps, 0.28, depth=0.45)
    pz0, pz1 = sorted((rz + side * run, rz + side * (run + 4.0)))
    s.box(rx - 2.0, rx + 2.0, 2.6, 3.0, pz0, pz1)
    for px in (rx - 1.9, rx + 1.7):
        for pz in (pz0 + 0.1, pz1 - 0.3):
            s.box(px, px + 0.2, -1.0, 2.6, pz, pz + 0.2)
    _rail_ring(s, rx - 2.0, rx + 2.0, pz0, pz1, 3.0, {"south" if side > 0 else "north": [(1.1, 1.8)]})
    # the island: a shelf with tide pools round the plinth
    ix0, iw, idp = x2, rng.uniform(72.0, 80.0), rng.uniform(60.0, 68.0)
    iz0 = z1 - idp / 2 + rng.uniform(-6.0, 6.0)
    plinth = (ix0 + 16.0, ix0 + 52.0, iz0 + idp / 2 - 15.0, iz0 + idp / 2 + 15.0)
    shelf: list[tuple[float, float, float, float]] = [plinth]
    prun = math.ceil(3.0 / 0.18) * 0.28
    pr = 3.0 / math.ceil(3.0 / 0.18)
    front_z = (plinth[2] + plinth[3]) / 2 + rng.uniform(-8.0, 8.0)
    s.stairs(np.array([plinth[0] - prun, front_z]), np.array([1.0, 0.0]), 3.0, 0.0, 3.0, pr, 0.28)
    back_z = (plinth[2] + plinth[3]) / 2 + rng.uniform(-10.0, 10.0)
    s.stairs(np.array([plinth[1] + prun, back_z]), np.array([-1.0, 0.0]), 1.6, 0.0, 3.0, pr, 0.28)
    clear = [(plinth[0] - prun - 3.0, plinth[0], front_z - 3.0, front_z + 3.0),
             (plinth[1], plinth[1] + prun + 3.0, back_z - 2.0, back_z + 2.0), (ix0, ix0 + 6.0, z1 - 4.0, z1 + 4.0),
             (plinth[0] - 1.0, plinth[1] + 1.0, plinth[2] - 1.0, plinth[3] + 1.0)]
    jz = back_z + rng.uniform(-6.0, 6.0)
    s.box(ix0 + iw - 0.5, ix0 + iw + rng.uniform(30.0, 40.0), -1.0, 0.0, jz - 1.5, jz + 1.5)  # the jetty
    clear.append((ix0 + iw - 8.0, ix0 + iw, jz - 3.0, jz + 3.0))
    for _ in range(int(rng.integers(30, 40))):
        w, d = rng.uniform(2.0, 7.0), rng.uniform(2.0, 6.0)
        x, z = rng.uniform(ix0 + 2.0, ix0 + iw - w - 2.0), rng.uniform(iz0 + 2.0, iz0 + idp - d - 2.0)
        if _clear(x - 2.5, x + w + 2.5, z - 2.5, z + d + 2.5, clear + shelf):
            shelf.append((x, x + w, z, z + d))
    for _ in range(int(rng.integers(40, 55))):
        p = np.array([rng.uniform(ix0 + 2.0, ix0 + iw - 2.0), rng.uniform(iz0 + 2.0, iz0 + idp - 2.0)])
        if _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, clear + shelf):
            s.rock(rng, p, 0.5, -0.5, rng.uniform(0.8, 1.8))
            clear.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    s.ground(ix0, ix0 + iw, iz0, iz0 + idp, 0.0, shelf)
    # the plinth and its compound
    y = 3.0
    tower_x, tower_z = plinth[0] + rng.uniform(14.0, 20.0), plinth[2] + rng.uniform(8.0, 12.0)
    well = _well_length(4.0)
    tw = (tower_x, tower_x + 4.0, tower_z, tower_z + well)
    roofs = [(plinth[0] + 2.0, plinth[0] + 12.0, plinth[3] - 9.0, plinth[3] - 2.0),
             (plinth[0] + 2.0, plinth[0] + 12.0, plinth[2] + 2.0, plinth[2] + 9.0)]
    ridged = [_ridged(s, plinth[1] - 10.0, plinth[1] - 3.0, plinth[3] - 8.0, plinth[3] - 3.0, y - 0.5, y + 3.5),
              _ridged(s, plinth[1] - 8.0, plinth[1] - 3.0, plinth[2] + 3.0, plinth[2] + 7.0, y - 0.5, y + 2.8)]
    s.ground(*plinth, y, ridged, thickness=y + 1.0)
    s.wall((plinth[0], plinth[2]), (plinth[0], plinth[3]), y, y + 1.2, [(front_z - plinth[2] - 1.5, 3.0)])
    s.wall((plinth[1], plinth[2]), (plinth[1], plinth[3]), y, y + 1.2, [(back_z - plinth[2] - 0.8, 1.6)])
    for z in (plinth[2], plinth[3]):
        s.wall((plinth[0], z), (plinth[1], z), y, y + 1.2)
    for k, (x0, x1, z0, z1) in enumerate(roofs):  # the cottages, door toward the yard, a back room
        door_side = z0 if k == 0 else z1
        s.wall((x0, door_side), (x1, door_side), y, y + 3.0, [(rng.uniform(1.0, 3.0), 1.6)])
        s.wall((x0, z0 + z1 - door_side), (x1, z0 + z1 - door_side), y, y + 3.0)
        for x in (x0, x1):
            s.wall((x, z0), (x, z1), y, y + 3.0)
        s.wall((x0 + 6.0, z0), (x0 + 6.0, z1), y, y + 3.0, [(rng.uniform(0.5, 4.5), 1.6)])
        s.box(x0 + 2.0, x0 + 3.6, y, y + 0.75, (z0 + z1) / 2 - 0.5, (z0 + z1) / 2 + 0.5)
        _gable(s, x0 - 0.3, x1 + 0.3, z0 - 0.3, z1 + 0.3, y + 3.0)
    # the tower: five storeys of switchback, its door at the foot, the lantern's door onto the gallery at the top
    top = _stair_tower(s, tower_x, tower_z, y, 5, doors=(0, 5))
    ceiling = top + 4.0
    g = (tw[0] - 2.6, tw[1] + 2.6, tw[2] - 2.6, tw[3] + 2.6)
    s.slab(*g, top, [(tw[0] - 0.4, tw[1] + 0.4, tw[2] - 0.4, tw[3] + 0.4)])
    _rail_ring(s, *g, top, {})
    _ridged(s, tw[0] - 0.4, tw[1] + 0.4, tw[2] - 0.4, tw[3] + 0.4, ceiling, ceiling + 1.0)
    return s.mesh()


def canal_locks(seed: int) -> trimesh.Trimesh:
    """A flight of 7-9 locks lifting a canal 2 m each along +x. The canal is 7 m wide (water: no floor); on each side
    a bank (a towpath 3.5 m wide along the water, then 8-14 m of land with trees, benches, lock cottages, ridged)
    stands at its pound's height and steps up 2 m at each lock's lower gate, where a flight 2.4 m wide along x
    (12 steps of 0.167 / 0.28 m) climbs the towpath only; beside a lock chamber (26 m) the banks are at the upper
    pound's height. The only ways across the water: a footbridge 2 m wide (railed) on each lock gate, two a lock,
    and one road bridge 6 m wide over a pound. Narrowboats (ridged) moored in the pounds, bollards on the towpaths.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    locks, rise, chamber = int(rng.integers(7, 10)), 2.0, 26.0
    steps = math.ceil(rise / 0.18)
    run = steps * 0.28
    zc, north, south = 0.0, rng.uniform(11.5, 17.5), rng.uniform(11.5, 15.5)
    gates = [rng.uniform(22.0, 30.0)]
    for _ in range(locks - 1):
        gates.append(gates[-1] + chamber + rng.uniform(18.0, 32.0))
    end = gates[-1] + chamber + rng.uniform(22.0, 30.0)
    bounds = [0.0, *gates, end]
    road_pound = int(rng.integers(1, locks))
    road_x = rng.uniform(bounds[road_pound] + chamber + 4.0, bounds[road_pound + 1] - run - 10.0)
    for k, (x0, x1) in enumerate(pairwise(bounds)):  # the banks at pound k's height
        y = k * rise
        for z0, z1, lane in ((zc + 3.5, zc + 3.5 + north, (zc + 3.5, zc + 7.0)), (zc - 3.5 - south, zc - 3.5, (zc - 7.0, zc - 3.5))):
            holes: list[tuple[float, float, float, float]] = []
            taken = [(x0, x1, *lane)]  # the towpath kept clear
            if k:  # the lock cottage beside the chamber
                cz = (z1 - 8.0, z1 - 2.0) if z0 > zc else (z0 + 2.0, z0 + 8.0)
                cx = x0 + rng.uniform(6.0, chamber - 10.0)
                holes.append(_ridged(s, cx, cx + 8.0, *cz, y - 0.5, y + 3.0))
                taken.append((cx - 1.0, cx + 9.0, cz[0] - 1.0, cz[1] + 1.0))
            if k == road_pound:
                taken.append((road_x - 4.0, road_x + 4.0, z0, z1))
            for _ in range(int((x1 - x0) * (z1 - z0) / 90.0)):
                p = np.array([rng.uniform(x0 + 1.5, x1 - 1.5), rng.uniform(z0 + 1.5, z1 - 1.5)])
                if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken):
                    if rng.random() < 0.7:
                        _trunk(s, p, rng.uniform(0.25, 0.45), y - 0.5, y + 6.0)
                    else:
                        s.box(p[0], p[0] + 1.8, y - 0.5, y + 0.5, p[1], p[1] + 0.6)
                    taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
            s.ground(x0, x1, z0, z1, y, holes, thickness=y + 1.0)
            edge = zc + 3.7 if z0 > zc else zc - 3.7
            for x in np.arange(x0 + chamber + 4.0 if k else x0 + 4.0, x1 - run - 4.0, rng.uniform(9.0, 14.0)):
                _trunk(s, np.array([x, edge]), 0.15, y - 0.5, y + 0.6)  # bollards
            if k < locks:  # the flight up the towpath at the next lower gate
                s.stairs(np.array([x1 - run, (lane[0] + lane[1]) / 2]), np.array([1.0, 0.0]), 2.4, y, rise, rise / steps, 0.28)
        if k < locks:  # the gates' footbridges at the upper pound's height
            for gx in (x1, x1 + chamber - 2.0):
                s.box(gx, gx + 2.0, y + rise - 0.4, y + rise, zc - 3.5, zc + 3.5)
                for x in (gx, gx + 2.0):
                    s.box(x - 0.05, x + 0.05, y + rise, y + rise + 1.1, zc - 3.5, zc + 3.5)
        if k == road_pound:
            s.box(road_x - 3.0, road_x + 3.0, y - 0.6, y, zc - 3.5, zc + 3.5)
            for x in (road_x - 3.0, road_x + 3.0):
                s.box(x - 0.1, x + 0.1, y, y + 1.1, zc - 3.5, zc + 3.5)
        if rng.random() < 0.7 and k:  # a narrowboat moored in the pound
            bx = rng.uniform(x0 + chamber + 2.0, max(x0 + chamber + 2.5, x1 - 22.0))
            if not (k == road_pound and bx - 4.0 < road_x < bx + 22.0):
                _ridged(s, bx, bx + rng.uniform(14.0, 20.0), zc + 1.2, zc + 3.3, y - 1.5, y + 0.4)
    return s.mesh()


def water_park(seed: int) -> trimesh.Trimesh:
    """An outdoor water park 150-170 x 110-120 m inside a fence 2.5 m high, entered through a pay hall in the south
    fence (ridged roof; 4-6 turnstile lanes 1.6 m wide between rails 1.1 m high). The water has no floor: a wave pool
    (34-40 x 20-24 m), a lap pool (25 x 12 m), a children's pool and splash pools at the slides' feet lie in a deck at
    y = 0; a lazy river 5 m wide rings an island 50-60 x 34-40 m in the middle (its café ridged, loungers, umbrellas),
    crossed only by 3-4 bridges 3 m wide (railed). Two slide towers, each a walled switchback well 4 m wide
    (:func:`_switchback`) up three storeys 4 m apart to a railed top platform (4 x 6 m): the slides' chutes, 0.9 m
    wide, are too narrow to walk (the agent is 1 m across), so each tower's top is a dead end. Changing rooms (a block of
    cubicles off a corridor 2.4 m wide, two doors), loungers 0.5 m high in rows, umbrella poles.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = rng.uniform(150.0, 170.0), rng.uniform(110.0, 120.0)
    holes: list[tuple[float, float, float, float]] = []
    taken: list[tuple[float, float, float, float]] = []
    gate_x = size_x / 2 + rng.uniform(-20.0, 20.0)
    # the fence and the pay hall across its gate
    s.wall((0.0, 0.0), (size_x, 0.0), -0.5, 2.5, [(gate_x - 9.0, 18.0)], thickness=0.3)
    s.wall((0.0, size_z), (size_x, size_z), -0.5, 2.5, thickness=0.3)
    for x in (0.0, size_x):
        s.wall((x, 0.0), (x, size_z), -0.5, 2.5, thickness=0.3)
    lanes = int(rng.integers(4, 7))
    s.ground(gate_x - 12.0, gate_x + 12.0, -14.0, 0.0, 0.0, [])  # the forecourt outside
    hall = (gate_x - 9.0, gate_x + 9.0, 0.0, 10.0)
    for x in (hall[0], hall[1]):
        s.wall((x, 0.0), (x, 10.0), -0.5, 3.5, thickness=0.3)
    lane_x0 = gate_x - lanes * 1.7 / 2
    for i in range(lanes + 1):
        x = lane_x0 + i * 1.7
        s.box(x - 0.05, x + 0.05, 0.0, 1.1, 4.0, 6.0)
    s.wall((hall[0], 5.0), (lane_x0, 5.0), -0.5, 3.5, thickness=0.3)
    s.wall((lane_x0 + lanes * 1.7, 5.0), (hall[1], 5.0), -0.5, 3.5, thickness=0.3)
    _lid(s, hall[0] - 0.3, hall[1] + 0.3, -0.3, 10.3, 4.5)
    taken.append((hall[0] - 2.0, hall[1] + 2.0, 0.0, 13.0))
    # the lazy river round the island
    iw, idp = rng.uniform(50.0, 60.0), rng.uniform(34.0, 40.0)
    ix0, iz0 = size_x / 2 - iw / 2 + rng.uniform(-8.0, 8.0), size_z / 2 - idp / 2 + rng.uniform(0.0, 8.0)
    r = (ix0 - 5.0, ix0 + iw + 5.0, iz0 - 5.0, iz0 + idp + 5.0)
    sides = [("south", r[0], r[1]), ("north", r[0], r[1]), ("west", r[2], r[3]), ("east", r[2], r[3])]
    bridged = rng.choice(4, size=int(rng.integers(3, 5)), replace=False)
    for k, (side, a, b) in enumerate(sides):
        cuts = [a, b]
        if k in bridged:
            m = rng.uniform(a + 12.0, b - 15.0)
            cuts = [a, m, m + 3.0, b]
        for c0, c1 in zip(cuts[0::2], cuts[1::2]):
            if side in ("south", "north"):
                z0 = r[2] if side == "south" else r[3] - 5.0
                holes.append((c0, c1, z0, z0 + 5.0))
            else:
                x0 = r[0] if side == "west" else r[1] - 5.0
                holes.append((x0, x0 + 5.0, max(c0, r[2] + 5.0), min(c1, r[3] - 5.0)))
        if len(cuts) == 4:
            for c in (cuts[1], cuts[2]):
                if side in ("south", "north"):
                    z0 = r[2] if side == "south" else r[3] - 5.0
                    s.box(c - 0.05, c + 0.05, 0.0, 1.1, z0, z0 + 5.0)
                else:
                    x0 = r[0] if side == "west" else r[1] - 5.0
                    s.box(x0, x0 + 5.0, 0.0, 1.1, c - 0.05, c + 0.05)
    taken.append((r[0] - 2.0, r[1] + 2.0, r[2] - 2.0, r[3] + 2.0))
    cafe = _ridged(s, ix0 + iw / 2 - 7.0, ix0 + iw / 2 + 7.0, iz0 + idp / 2 - 5.0, iz0 + idp / 2 + 5.0, -0.5, 3.5)
    holes.append(cafe)
    island_taken = [(cafe[0] - 2.0, cafe[1] + 2.0, cafe[2] - 2.0, cafe[3] + 2.0)]
    for _ in range(int(rng.integers(50, 70))):
        p = np.array([rng.uniform(ix0 + 1.5, ix0 + iw - 3.5), rng.uniform(iz0 + 1.5, iz0 + idp - 3.5)])
        if _clear(p[0] - 1.2, p[0] + 1.9, p[1] - 1.2, p[1] + 3.2, island_taken):
            s.box(p[0], p[0] + 0.7, -0.5, 0.5, p[1], p[1] + 2.0)  # a lounger: too narrow a top to stand on
            island_taken.append((p[0] - 1.2, p[0] + 1.9, p[1] - 1.2, p[1] + 3.2))
    # pools in the deck round the river
    pools = [(rng.uniform(36.0, 40.0), rng.uniform(20.0, 24.0)), (25.0, 12.0), (rng.uniform(12.0, 16.0), rng.uniform(10.0, 12.0))]
    for w, d in pools:
        for _ in range(200):
            x, z = rng.uniform(4.0, size_x - w - 4.0), rng.uniform(16.0, size_z - d - 4.0)
            if _clear(x - 4.0, x + w + 4.0, z - 4.0, z + d + 4.0, taken):
                holes.append((x, x + w, z, z + d))
                taken.append((x - 3.0, x + w + 3.0, z - 3.0, z + d + 3.0))
                break
    # the slide towers, each with its splash pool and chute
    well = _well_length(4.0)
    for _ in range(2):
        for _ in range(300):
            x, z = rng.uniform(4.0, size_x - 30.0), rng.uniform(16.0, size_z - well - 6.0)
            if _clear(x - 3.0, x + 30.0, z - 3.0, z + well + 3.0, taken):
                break
        top = _stair_tower(s, x, z, 0.0, 3)
        s.slab(x - 0.4, x + 4.4, z - 0.4, z + well + 0.4, top, [(x, x + 4.0, z, z + well)])  # the top platform round it
        _rail_ring(s, x - 0.4, x + 4.4, z - 0.4, z + well + 0.4, top, {})
        s.ramp(np.array([x + 4.4, z + 1.0]), np.array([x + 22.0, z + 1.0]), 0.9, top, 0.8)  # the chute, 33 degrees, 0.9 m wide
        holes.append((x + 22.0, x + 28.0, z - 2.0, z + 4.0))  # its splash pool
        taken.append((x - 3.0, x + 30.0, z - 3.0, z + well + 3.0))
    # the changing rooms: cubicles off a corridor
    for _ in range(300):
        cx, cz = rng.uniform(4.0, size_x - 34.0), rng.uniform(14.0, size_z - 16.0)
        if _clear(cx - 2.0, cx + 32.0, cz - 2.0, cz + 12.0, taken):
            break
    s.wall((cx, cz), (cx + 30.0, cz), -0.5, 2.6, thickness=0.2)
    s.wall((cx, cz + 10.0), (cx + 30.0, cz + 10.0), -0.5, 2.6, thickness=0.2)
    s.wall((cx, cz), (cx, cz + 10.0), -0.5, 2.6, [(3.8, 2.4)], thickness=0.2)
    s.wall((cx + 30.0, cz), (cx + 30.0, cz + 10.0), -0.5, 2.6, [(3.8, 2.4)], thickness=0.2)
    for zw in (cz + 3.8, cz + 6.2):
        s.wall((cx, zw), (cx + 30.0, zw), -0.5, 2.6, [(0.2 + 2.0 * i, 1.6) for i in range(15) if rng.random() < 0.8], thickness=0.1)
    for x in np.arange(cx + 2.0, cx + 30.0, 2.0):
        for z0, z1 in ((cz, cz + 3.8), (cz + 6.2, cz + 10.0)):
            s.box(x - 0.05, x + 0.05, -0.5, 2.6, z0, z1)
    _lid(s, cx - 0.2, cx + 30.2, cz - 0.2, cz + 10.2, 3.6)
    taken.append((cx - 2.0, cx + 32.0, cz - 2.0, cz + 12.0))
    for _ in range(int(rng.integers(260, 320))):  # loungers and umbrellas on the deck
        p = np.array([rng.uniform(2.0, size_x - 4.0), rng.uniform(14.0, size_z - 4.0)])
        if _clear(p[0] - 1.2, p[0] + 1.9, p[1] - 1.2, p[1] + 3.2, taken + holes):
            if rng.random() < 0.7:
                s.box(p[0], p[0] + 0.7, -0.5, 0.5, p[1], p[1] + 2.0)
            else:
                _trunk(s, p, 0.06, -0.5, 2.4)
            taken.append((p[0] - 1.2, p[0] + 1.9, p[1] - 1.2, p[1] + 3.2))
    s.ground(0.0, size_x, 0.0, size_z, 0.0, holes)
    return s.mesh()


def paddies(seed: int) -> trimesh.Trimesh:
    """Rice terraces up a hillside along +z: 9-11 terraces 9-13 m deep, each 1.2-1.5 m above the one below, narrower
    the higher (the lowest 150-170 m wide along x, each next 2-5 m shorter at either end). A terrace is a paddy of
    water (no floor) between bunds 1.8 m wide: one along its front edge, cross bunds along z every 9-20 m from it to
    the riser of the next terrace. A bund climbs to the next terrace only by a flight along +z (0.28 m treads, risers
    under 0.18 m) ending head-on on that terrace's front bund: one to three a terrace, besides the main stair 3 m wide
    up a cross bund 3 m wide near the west end of every terrace. A village at the foot (ground at y = 0, 30 m deep, houses ridged, a well, trees)
    and a shrine (ridged) on a yard 20 x 12 m at the top, up its own flight.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    terraces = int(rng.integers(9, 12))
    bund = 1.8
    x0, x1, z, y = 0.0, rng.uniform(150.0, 170.0), 30.0, 0.0
    # the village at the foot
    holes: list[tuple[float, float, float, float]] = []
    taken = [(0.0, x1, 26.0, 30.0)]
    for _ in range(int(rng.integers(12, 18))):
        w, d = rng.uniform(6.0, 10.0), rng.uniform(5.0, 8.0)
        hx, hz = rng.uniform(2.0, x1 - w - 2.0), rng.uniform(2.0, 24.0 - d)
        if _clear(hx - 3.0, hx + w + 3.0, hz - 3.0, hz + d + 3.0, taken):
            holes.append(_ridged(s, hx, hx + w, hz, hz + d, -0.5, rng.uniform(3.0, 4.5)))
            taken.append((hx - 0.5, hx + w + 0.5, hz - 0.5, hz + d + 0.5))
    _trees(s, rng, int(rng.integers(20, 30)), x1, 24.0, taken, (0.25, 0.4), 6.0)
    s.ground(0.0, x1, 0.0, 30.0, 0.0, holes)
    shrink = rng.uniform(2.0, 5.0, size=(terraces, 2))
    shrink[0] = 0.0
    main_x = x0 + shrink[:, 0].sum() + rng.uniform(6.0, 10.0)  # the main stair's bund, a cross bund 3 m wide
    prev_flights: list[float] = []
    for k in range(terraces):
        depth = rng.uniform(9.0, 13.0)
        top = y + rng.uniform(1.2, 1.5)
        steps = math.ceil((top - y) / 0.18)
        run = steps * 0.28
        x0, x1 = x0 + shrink[k, 0], x1 - shrink[k, 1]
        # the flights up to this terrace's front bund, from the bunds of the one below (or the village)
        for fx in [main_x, *prev_flights]:
            s.stairs(np.array([fx, z - run]), np.array([0.0, 1.0]), 3.0 if fx == main_x else bund, y, top - y,
                     (top - y) / steps, 0.28)
        s.box(x0, x1, top - 3.0, top, z, z + bund)  # the front bund
        cross = [main_x]
        s.box(main_x - 1.5, main_x + 1.5, top - 3.0, top, z + bund, z + depth)
        cx = main_x + rng.uniform(9.0, 20.0)
        while cx < x1 - 4.0:
            s.box(cx - bund / 2, cx + bund / 2, top - 3.0, top, z + bund, z + depth)
            cross.append(cx)
            cx += rng.uniform(9.0, 20.0)
        for ex in (x0 + bund / 2, x1 - bund / 2):  # the ends' bunds
            s.box(ex - bund / 2, ex + bund / 2, top - 3.0, top, z + bund, z + depth)
        inner = [c for c in cross[1:] if x0 + 12.0 < c < x1 - 12.0]
        prev_flights = [float(c) for c in rng.choice(inner, size=min(len(inner), int(rng.integers(1, 4))), replace=False)]
        for _ in range(int(rng.integers(1, 4))):  # a field hut on a widening of the front bund
            hx = rng.uniform(x0 + 8.0, x1 - 8.0)
            if all(abs(hx - c) > 4.0 for c in cross):
                s.box(hx - 2.0, hx + 2.0, top - 3.0, top, z - 2.0, z)
                _ridged(s, hx - 1.2, hx + 1.2, z - 1.8, z - 0.2, top - 0.5, top + 1.6)
        y, z = top, z + depth
    # the shrine's yard at the top, up the main stair
    top = y + 1.4
    steps = math.ceil(1.4 / 0.18)
    run = steps * 0.28
    sx = (x0 + x1) / 2
    s.stairs(np.array([main_x, z - run]), np.array([0.0, 1.0]), 3.0, y, 1.4, 1.4 / steps, 0.28)
    s.box(x0, x1, top - 3.0, top, z, z + bund)
    shrine = _ridged(s, sx - 4.0, sx + 4.0, z + bund + 6.0, z + bund + 11.0, top - 3.0, top + 3.0)
    s.ground(sx - 10.0, sx + 10.0, z + bund, z + bund + 12.0, top, [shrine], thickness=3.0)
    return s.mesh()


def cistern(seed: int) -> trimesh.Trimesh:
    """An underground cistern 100-120 x 60-70 m under a ridged lid 6 m up (:func:`_lid`), between two streets at y = 6
    (25 m wide, houses ridged, trees): a forest of columns 0.9 m square on a 5 m grid standing in water (no floor),
    the only floor a network of walkways 2.2 m wide at y = 0 along the aisles between them: a random tree over 70 % of
    their crossings (grown from the west entrance's until it holds the east one's) and a twentieth of the other
    links, so most ways are the only way; 3-5 viewing platforms 6 m square at the tree's leaves. From each street a
    stair house goes down a walled switchback well 4 m wide (:func:`_switchback`, 6 m) to a passage onto the
    walkways, one at the west wall, one at the east.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    w, d, ceiling, street = rng.uniform(100.0, 120.0), rng.uniform(60.0, 70.0), 6.0, 25.0
    nx, nz = int(w // 5.0), int(d // 5.0)
    nodes = {(i, j) for i in range(1, nx) for j in range(1, nz)}
    # the walkways: a tree grown at random from the west entrance's crossing (Prim's order over random picks) until
    # it holds the east one's and 70 % of the crossings, and a twentieth of the other links
    start, goal = (1, int(rng.integers(2, nz - 1))), (nx - 1, int(rng.integers(2, nz - 1)))
    tree, frontier, links = {start}, [(start, c) for c in ((2, start[1]), (1, start[1] - 1), (1, start[1] + 1))], set()
    while goal not in tree or len(tree) < 0.7 * len(nodes):
        a, b = frontier.pop(int(rng.integers(len(frontier))))
        if b in tree:
            continue
        tree.add(b)
        links.add(frozenset((a, b)))
        frontier += [(b, c) for c in ((b[0] + 1, b[1]), (b[0] - 1, b[1]), (b[0], b[1] + 1), (b[0], b[1] - 1)) if c in nodes]
    for i, j in sorted(tree):
        for c in ((i + 1, j), (i, j + 1)):
            if c in tree and rng.random() < 0.05:
                links.add(frozenset(((i, j), c)))
    for link in links:
        (i0, j0), (i1, j1) = sorted(link)
        s.box(5.0 * i0 - 1.1, 5.0 * i1 + 1.1, -0.4, 0.0, 5.0 * j0 - 1.1, 5.0 * j1 + 1.1)
    degree = {n: sum(n in link for link in links) for n in sorted(tree)}
    leaves = [n for n in sorted(tree) if degree[n] == 1 and n not in (start, goal)]
    for k in rng.choice(len(leaves), size=min(len(leaves), int(rng.integers(3, 6))), replace=False):
        i, j = leaves[k]
        s.box(5.0 * i - 3.0, 5.0 * i + 3.0, -0.4, 0.0, 5.0 * j - 3.0, 5.0 * j + 3.0)
    for x in np.arange(2.5, w - 1.0, 5.0):
        for z in np.arange(2.5, d - 1.0, 5.0):
            s.box(x - 0.45, x + 0.45, -3.0, ceiling - 1.0, z - 0.45, z + 0.45)
    # the walls, 1 m short of the lid, and the lid
    for a, b in (((0.0, -0.25), (w, -0.25)), ((0.0, d + 0.25), (w, d + 0.25))):
        s.wall(a, b, -3.0, ceiling - 1.0, thickness=0.5)
    # the two streets and their stair houses
    exits = {0.0: start[1], w: goal[1]}
    for edge, j in exits.items():
        out = -1.0 if edge == 0.0 else 1.0
        sx0, sx1 = sorted((edge + out * 0.5, edge + out * (street + 0.5)))
        well = _well_length(ceiling)
        wx = edge + out * 2.0 if out > 0 else edge - 6.0
        wz = 5.0 * j - 1.0
        shaft = (wx, wx + 4.0, wz, wz + well)
        passage = (min(edge, wx + 4.0 if out < 0 else wx), max(edge, wx + 4.0 if out < 0 else wx), wz, wz + 2.0)
        s.box(*shaft[:2], -0.4, 0.0, wz, wz + 2.0)  # the landing at the foot
        s.box(passage[0], passage[1], -0.4, 0.0, passage[2], passage[3])
        first = 5.0 * (1 if out < 0 else nx - 1)  # on to the walkways' crossing
        s.box(min(edge, first), max(edge, first), -0.4, 0.0, wz, wz + 2.0)
        _switchback(s, wx, wz, 0.0, ceiling)
        hole = (min(wx - 0.6, passage[0]) - 0.2, max(wx + 4.6, passage[1]) + 0.2, wz - 0.6, wz + well + 0.6)
        s.slab(hole[0], hole[1], wz, wz + 2.0, ceiling, [])  # the top landing, over the door and the passage
        s.wall((edge, 0.0), (edge, d), -3.0, ceiling - 1.0, [(wz, 2.0)], thickness=0.5)
        hx0, hx1 = wx - 0.4, wx + 4.4  # the stair house over the well, its door on the street at the landing
        s.wall((hx0, wz - 0.2), (hx1, wz - 0.2), ceiling, ceiling + 3.0, thickness=0.4)
        s.wall((hx0, wz + well + 0.2), (hx1, wz + well + 0.2), ceiling, ceiling + 3.0, thickness=0.4)
        door_x = hx0 if out < 0 else hx1
        back_x = hx1 if out < 0 else hx0
        s.wall((door_x, wz - 0.4), (door_x, wz + well + 0.4), ceiling, ceiling + 3.0, [(0.6, 1.6)], thickness=0.4)
        s.wall((back_x, wz - 0.4), (back_x, wz + well + 0.4), ceiling, ceiling + 3.0, thickness=0.4)
        _ridged(s, hx0 - 0.2, hx1 + 0.2, wz - 0.6, wz + well + 0.6, ceiling + 3.0, ceiling + 3.5)
        holes = [hole]
        taken = list(holes)
        far = sx0 if out < 0 else sx1 - 10.0
        z = rng.uniform(1.0, 4.0)
        while z < d - 8.0:  # houses along the far side of the street
            hw = rng.uniform(6.0, 10.0)
            holes.append(_ridged(s, far, far + 10.0, z, min(z + hw, d), ceiling - 1.0, ceiling + rng.uniform(4.0, 7.0)))
            taken.append((far - 1.0, far + 11.0, z - 1.0, z + hw + 1.0))
            z += hw + rng.uniform(2.0, 6.0)
        for _ in range(int(rng.integers(50, 70))):
            p = np.array([rng.uniform(sx0 + 1.5, sx1 - 1.5), rng.uniform(1.5, d - 1.5)])
            if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken):
                _trunk(s, p, rng.uniform(0.2, 0.4), ceiling - 0.5, ceiling + 5.0)
                taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
        s.ground(sx0, sx1, 0.0, d, ceiling, holes, thickness=ceiling + 4.0)
    _lid(s, -0.5, w + 0.5, -0.5, d + 0.5, ceiling)
    return s.mesh()


def star_fort(seed: int) -> trimesh.Trimesh:
    """A bastioned fort: a square enceinte 84-100 m a side whose courtyard (y = 0; barracks, a chapel, a magazine, all
    ridged) is ringed by ramparts 8 m wide, their walk 4.5 m up behind a parapet 1.2 m high (guns on it), climbed by
    3-4 ramps 3.5 m wide from the courtyard; a diamond bastion (half-diagonal 15-18 m, its top the walk) on each
    corner; a dry moat 5 m deep round it all, 12-16 m beyond the bastions' points (its counterscarp a rectangle),
    crossed only before the gate in the south curtain: a bridge from the glacis to a ravelin (an island at y = 0 in
    the moat, railed) and a drawbridge (lowered) from it to the gate, a passage 4 m wide under the walk. The moat
    floor is reached by two flights down the counterscarp, one down the ravelin's side and a postern: a passage 3 m
    wide under the north rampart and a flight down the scarp. A glacis 20-26 m wide round the moat (y = 0, trees).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    side, r, moat = rng.uniform(84.0, 100.0), rng.uniform(15.0, 18.0), rng.uniform(12.0, 16.0)
    walk, deep, band = 4.5, -5.0, 8.0
    c0, c1 = -r - moat, side + r + moat  # the counterscarp, a square
    g0, g1 = c0 - rng.uniform(20.0, 26.0), c1 + rng.uniform(20.0, 26.0)
    gate, postern = side / 2, rng.uniform(r + 8.0, side - r - 8.0)
    # the ramparts, cut by the gate (south) and the postern (north), with their passages' floors and vaults
    for x0, x1 in ((0.0, gate - 2.0), (gate + 2.0, side)):
        s.box(x0, x1, deep - 0.5, walk, 0.0, band)
    for x0, x1 in ((0.0, postern - 1.5), (postern + 1.5, side)):
        s.box(x0, x1, deep - 0.5, walk, side - band, side)
    for x in (0.0, side - band):
        s.box(x, x + band, deep - 0.5, walk, band, side - band)
    for x0, x1, z0, z1 in ((gate - 2.0, gate + 2.0, 0.0, band), (postern - 1.5, postern + 1.5, side - band, side)):
        s.box(x0, x1, deep - 0.5, 0.0, z0, z1)
        s.box(x0, x1, 2.6, walk, z0, z1)  # the vault: the walk goes on over the passage
    # the bastions, their parapets on the three outer edges, and the curtains' parapets between them
    corners = [(cx, cz) for cx in (0.0, side) for cz in (0.0, side)]
    diamond = np.array([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]])
    moat_floor: list[np.ndarray] = []
    for cx, cz in corners:
        c = np.array([cx, cz])
        inward = np.array([1.0 if cx == 0.0 else -1.0, 1.0 if cz == 0.0 else -1.0])
        s.prism(c + r * diamond, deep - 0.5, walk)
        points = [c + r * d for d in diamond]
        for a, b in zip(points, points[1:] + points[:1]):
            if not (np.dot(a - c, inward) > 0 and np.dot(b - c, inward) > 0):  # not the edge inside the square
                s.prism(_strip(a - 0.3 * (a - c) / r, b - 0.3 * (b - c) / r, 0.4), walk, walk + 1.2)
        for k in range(4):  # the moat floor round the diamond: the corners of its box outside it and the square
            corner = np.array([(1.0 if k & 1 else -1.0), (1.0 if k & 2 else -1.0)])
            if not (corner == inward).all():
                moat_floor.append(c + r * np.array([corner, [corner[0], 0.0], [0.0, corner[1]]]))
    for a, b, doors in (((r, 0.2), (side - r, 0.2), [(gate - 2.0 - r, 4.0)]),
                        ((r, side - 0.2), (side - r, side - 0.2), [(postern - 1.5 - r, 3.0)]),
                        ((0.2, r), (0.2, side - r), []), ((side - 0.2, r), (side - 0.2, side - r), [])):
        s.wall(a, b, walk, walk + 1.2, doors, thickness=0.4)
    for _ in range(int(rng.integers(14, 22))):  # guns along the parapets
        k, t = int(rng.integers(4)), rng.uniform(r + 3.0, side - r - 3.0)
        if abs(t - gate) > 4.0 and abs(t - postern) > 4.0:
            x0, z0 = [(t, 1.0), (t, side - 3.0), (1.0, t), (side - 3.0, t)][k]
            s.box(x0, x0 + (1.0 if k < 2 else 2.0), walk - 0.3, walk + 1.1, z0, z0 + (2.0 if k < 2 else 1.0))
    for prism in moat_floor:
        s.prism(prism, deep - 0.5, deep)
    # the ravelin in the moat before the gate, its bridges and its flight down to the moat
    rz0, rz1, rx0, rx1 = c0 + 7.0, -r + 5.0, gate - 12.0, gate + 12.0
    s.box(rx0, rx1, deep - 0.5, 0.0, rz0, rz1)
    run = math.ceil(-deep / 0.18) * 0.28
    s.stairs(np.array([rx1 + run, rz0 + 3.0]), np.array([-1.0, 0.0]), 2.0, deep, -deep, -deep / math.ceil(-deep / 0.18), 0.28)
    _rail_ring(s, rx0, rx1, rz0, rz1, 0.0, {"south": [(10.0, 4.0)], "north": [(10.0, 4.0)], "east": [(2.0, 2.0)]})
    for z0, z1 in ((c0, rz0), (rz1, 0.0)):
        s.box(gate - 2.0, gate + 2.0, -0.6, 0.0, z0, z1)
        for x in (gate - 2.05, gate + 2.05):
            s.box(x - 0.05, x + 0.05, 0.0, 1.1, z0, z1)
    # the flights down the counterscarp (north and east) and the postern's down the scarp
    steps = math.ceil(-deep / 0.18)
    fx = rng.uniform(r + 6.0, side - r - 6.0)
    while abs(fx - postern) < 10.0:
        fx = rng.uniform(r + 6.0, side - r - 6.0)
    fz = rng.uniform(r + 6.0, side - r - 6.0)
    for start, heading in (((fx, c1 - run), (0.0, 1.0)), ((c1 - run, fz), (1.0, 0.0)), ((postern, side + run), (0.0, -1.0))):
        s.stairs(np.array(start), np.array(heading), 2.4, deep, -deep, -deep / steps, 0.28)
    s.ground(c0, c1, c0, c1, deep, [(-r, r, -r, r), (side - r, side + r, -r, r), (-r, r, side - r, side + r),
                                     (side - r, side + r, side - r, side + r), (0.0, side, 0.0, side), (rx0, rx1, rz0, rz1)])
    # the courtyard and its buildings
    holes: list[tuple[float, float, float, float]] = []
    taken = [(gate - 4.0, gate + 4.0, band, band + 14.0), (postern - 3.0, postern + 3.0, side - band - 10.0, side - band)]
    mid = side / 2
    holes.append(_ridged(s, mid - 7.0, mid + 7.0, mid + 2.0, mid + 18.0, -0.5, 7.0))  # the chapel
    taken.append((mid - 9.0, mid + 9.0, mid, mid + 20.0))
    for k in range(int(rng.integers(3, 5))):  # ramps up to the walk, square to the rampart (west, east, north, west)
        for _ in range(100):
            t = rng.uniform(band + 10.0, side - band - 10.0)
            a, b = [((band + 22.0, t), (band, t)), ((side - band - 22.0, t), (side - band, t)),
                    ((t, side - band - 22.0), (t, side - band)), ((band + 22.0, t), (band, t))][k]
            box = (min(a[0], b[0]) - 3.0, max(a[0], b[0]) + 3.0, min(a[1], b[1]) - 3.0, max(a[1], b[1]) + 3.0)
            if _clear(*box, taken):
                s.ramp(np.array(a), np.array(b), 3.5, 0.0, walk)
                taken.append(box)
                break
    for _ in range(int(rng.integers(6, 10))):  # barracks, stores, the magazine
        w, d = rng.uniform(8.0, 24.0), rng.uniform(7.0, 10.0)
        for _ in range(100):
            x, z = rng.uniform(band + 4.0, side - band - 4.0 - w), rng.uniform(band + 4.0, side - band - 4.0 - d)
            if _clear(x - 4.0, x + w + 4.0, z - 4.0, z + d + 4.0, taken):
                holes.append(_ridged(s, x, x + w, z, z + d, -0.5, rng.uniform(4.0, 6.0)))
                taken.append((x - 1.0, x + w + 1.0, z - 1.0, z + d + 1.0))
                break
    _trunk(s, np.array([mid, mid - 10.0]), 0.8, -0.5, 1.0)  # the well on the parade
    s.ground(band, side - band, band, side - band, 0.0, holes, thickness=5.5)
    # the glacis, trees on it
    outside: list[tuple[float, float, float, float]] = [(c0, c1, c0, c1), (gate - 6.0, gate + 6.0, c0 - 8.0, c0)]
    for _ in range(int(rng.integers(150, 200))):
        p = np.array([rng.uniform(g0 + 1.0, g1 - 1.0), rng.uniform(g0 + 1.0, g1 - 1.0)])
        if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, outside):
            _trunk(s, p, rng.uniform(0.25, 0.5), -0.5, 6.0)
            outside.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    s.ground(g0, g1, g0, g1, 0.0, [(c0, c1, c0, c1)])
    return s.mesh()


def glacier(seed: int) -> trimesh.Trimesh:
    """A glacier tongue 110-130 m wide and 250-290 m long rising along +z at 5-7 degrees (ground undulating by 0.4 m),
    cut across by crevasses (no floor): slots 1.5-4 m wide along x in bands 14-22 m apart. In two bands of three,
    1-3 slots 15-70 m long, en echelon, leaving a way 6 m wide somewhere across the band; in the third, slots from
    edge to edge crossed only on 1-2 snow bridges (2.5-4 m wide, where the slot stops) and perhaps a ladder (a plank
    deck 1.6 m wide). Half way up an icefall: a step of 6 m over 2 m (72 degrees), climbed only by two fixed-rope
    ramps 2.5 m wide and 22 m long. Seracs and boulders (hulls) scattered; at the snout a camp of tents, at the top
    a hut (both ridged). :func:`_terrain` builds the ice on a grid cut at every slot's edges, leaving out the slots'
    cells, those under the hut and the tents, and any ice the slots cut off from the rest.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    width, length = rng.uniform(110.0, 130.0), rng.uniform(250.0, 290.0)
    grade, step = math.tan(math.radians(rng.uniform(5.0, 7.0))), 6.0
    fall = length * rng.uniform(0.45, 0.55)  # the icefall's foot
    bumps = rng.uniform(0.0, 2 * math.pi, 3)

    def height(x: float, z: float) -> float:
        """The ice's top (m) at plan point x, z (floats or arrays of one shape)."""
        return (z * grade + step * np.clip((z - fall) / 2.0, 0.0, 1.0)
                + 0.4 * np.sin(x / 17.0 + bumps[0]) * np.sin(z / 23.0 + bumps[1]) + 0.2 * np.sin(z / 9.0 + bumps[2]))

    slots: list[tuple[float, float, float, float]] = []
    ladders: list[tuple[float, float, float]] = []  # x, z0, z1
    z, band = 25.0, 0
    while z < length - 25.0:
        if not fall - 26.0 < z < fall + 8.0:  # the ramps' feet and the icefall keep clear
            w = rng.uniform(1.5, 4.0)
            if band % 3 == 1:  # edge to edge: snow bridges and perhaps a ladder
                cuts = sorted(rng.uniform(8.0, width - 8.0, int(rng.integers(1, 3))))
                x0 = -1.0
                for c in cuts:
                    if c > x0:
                        slots.append((x0, c, z, z + w))
                        x0 = c + rng.uniform(2.5, 4.0)
                slots.append((x0, width + 1.0, z, z + w))
                lx = rng.uniform(6.0, width - 6.0)
                if all(abs(lx - c) > 8.0 for c in cuts):
                    ladders.append((lx, z, z + w))
            else:  # en echelon, clear of a way 6 m wide at gap
                gap = rng.uniform(5.0, width - 5.0)
                for _ in range(int(rng.integers(1, 4))):
                    x0 = rng.uniform(-10.0, width - 10.0)
                    x1 = min(x0 + rng.uniform(15.0, 70.0), width + 1.0)
                    dz = rng.uniform(-3.0, 3.0)
                    for a, b in ((max(x0, -1.0), min(x1, gap - 3.0)), (max(x0, gap + 3.0), x1)):
                        if b - a > 4.0:
                            slots.append((a, b, z + dz, z + dz + w))
            band += 1
        z += rng.uniform(14.0, 22.0)
    # the camp's tents and the hut: no ice under them (it would be floor inside)
    huts: list[tuple[float, float, float, float]] = []
    for _ in range(int(rng.integers(6, 10))):
        x, z = rng.uniform(5.0, width - 8.0), rng.uniform(3.0, 16.0)
        if _clear(x - 1.5, x + 4.5, z - 1.5, z + 4.0, huts):
            huts.append((x, x + 3.0, z, z + 2.5))
    hx = rng.uniform(20.0, width - 35.0)
    huts.append((hx, hx + 12.0, length - 16.0, length - 7.0))
    cuts = [v for q in slots + huts for v in q]
    xs = np.unique(np.concatenate([np.linspace(0.0, width, int(width / 4.0) + 1), np.clip(cuts[0::4] + cuts[1::4], 0.0, width)]))
    zs = np.unique(np.concatenate([np.linspace(0.0, length, int(length / 4.0) + 1), [fall, fall + 2.0], cuts[2::4] + cuts[3::4]]))
    mx, mz = np.meshgrid((xs[:-1] + xs[1:]) / 2, (zs[:-1] + zs[1:]) / 2, indexing="ij")
    keep = np.ones(mx.shape, dtype=bool)
    for x0, x1, z0, z1 in slots + huts:
        keep &= ~((mx > x0) & (mx < x1) & (mz > z0) & (mz < z1))
    label, _ = ndimage.label(keep)  # 4-neighbour pieces of ice: only the largest is kept
    keep = label == np.argmax(np.bincount(label.ravel())[1:]) + 1
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    _terrain(s, xs, zs, height(gx, gz), keep)
    for x0, x1, z0, z1 in huts:
        y = float(np.min(height(np.array([x0, x1, x0, x1]), np.array([z0, z0, z1, z1]))))
        _ridged(s, x0, x1, z0, z1, y - 1.0, y + (0.4 if x1 - x0 < 5.0 else 3.0))
    for lx, z0, z1 in ladders:  # plank decks on the ice either side
        s.ramp(np.array([lx, z0 - 0.8]), np.array([lx, z1 + 0.8]), 1.6, height(lx, z0 - 0.8) + 0.05, height(lx, z1 + 0.8) + 0.05)
    for rx in rng.uniform([8.0, width / 2 + 8.0], [width / 2 - 8.0, width - 8.0]):  # the icefall's fixed-rope ramps
        s.ramp(np.array([rx, fall - 20.0]), np.array([rx, fall + 2.0]), 2.5, height(rx, fall - 20.0), height(rx, fall + 2.0) + 0.05)
    # seracs and boulders
    taken = [(x0 - 1.0, x1 + 1.0, z0 - 1.0, z1 + 1.0) for x0, x1, z0, z1 in slots + huts]
    taken += [(lx - 2.0, lx + 2.0, z0 - 2.0, z1 + 2.0) for lx, z0, z1 in ladders] + [(0.0, width, fall - 22.0, fall + 6.0)]
    for _ in range(int(rng.integers(130, 170))):
        p = np.array([rng.uniform(3.0, width - 3.0), rng.uniform(10.0, length - 20.0)])
        if _clear(p[0] - 2.0, p[0] + 2.0, p[1] - 2.0, p[1] + 2.0, taken):
            y = float(height(p[0], p[1]))
            s.rock(rng, p, rng.uniform(0.5, 1.0), y - 1.0, y + rng.uniform(1.5, 3.0))
            taken.append((p[0] - 2.5, p[0] + 2.5, p[1] - 2.5, p[1] + 2.5))
    return s.mesh()


def medina(seed: int) -> trimesh.Trimesh:
    """An old walled town of alleys: a lattice of 16-18 x 12-14 junctions 9 m apart whose alleys (2.6 m wide) are a
    random spanning tree of it (a depth-first walk) and a tenth of the other links, so many alleys end blind; the
    rest of the lattice's cells and links is houses (ridged, 5-9 m). Some alleys run under houses (a lid at 3.2 m:
    covered passages); 10-15 courtyard houses (drawn among the house cells over 5.5 m square beside an alley) open
    off an alley through a door 1.8 m wide into a yard with a fountain; a mosque's courtyard of 2 x 2 cells with an
    arcade of pillars. A wall 6 m high round the town, 3-4 gates (one a side but the north, sometimes there too)
    where an alley meets it, and a road 10-12 m wide outside (trees, stalls).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    n, m, cell, lane = int(rng.integers(16, 19)), int(rng.integers(12, 15)), 9.0, 2.6
    half = lane / 2
    # the alleys: a depth-first spanning tree of the junctions and a tenth of the other links
    links: set[frozenset[tuple[int, int]]] = set()
    seen, stack = {(0, 0)}, [(0, 0)]
    while stack:
        i, j = stack[-1]
        nexts = [(i + di, j + dj) for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1))
                 if 0 <= i + di < n and 0 <= j + dj < m and (i + di, j + dj) not in seen]
        if not nexts:
            stack.pop()
            continue
        c = nexts[int(rng.integers(len(nexts)))]
        links.add(frozenset(((i, j), c)))
        seen.add(c)
        stack.append(c)
    for i in range(n):
        for j in range(m):
            for c in ((i + 1, j), (i, j + 1)):
                if c[0] < n and c[1] < m and rng.random() < 0.1:
                    links.add(frozenset(((i, j), c)))
    # the mosque's courtyard: 2 x 2 cells open, their junctions and links all joined
    qi, qj = int(rng.integers(3, n - 5)), int(rng.integers(3, m - 5))
    court = [(qi + a, qj + b) for a in range(3) for b in range(3)]
    for a in court:
        for b in court:
            if abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1:
                links.add(frozenset((a, b)))
    x0, z0 = 16.0, 16.0  # the junction (0, 0); the wall at 4.5 m beyond the outer junctions
    wx0, wx1, wz0, wz1 = x0 - 4.5 - half, x0 + (n - 1) * cell + 4.5 + half, z0 - 4.5 - half, z0 + (m - 1) * cell + 4.5 + half
    # the gates: an alley on through the wall from an outer junction, one a side (the north only sometimes)
    gates = [("south", int(rng.integers(1, n - 1))), ("west", int(rng.integers(1, m - 1))), ("east", int(rng.integers(1, m - 1)))]
    if rng.random() < 0.5:
        gates.append(("north", int(rng.integers(1, n - 1))))
    alleys = []  # open rectangles: the junctions' squares, the links' strips, the gates' passages
    for i in range(n):
        for j in range(m):
            if any((i, j) in link for link in links):
                alleys.append((x0 + i * cell - half, x0 + i * cell + half, z0 + j * cell - half, z0 + j * cell + half))
    for link in links:
        (i0, j0), (i1, j1) = sorted(link)
        alleys.append((x0 + i0 * cell - half, x0 + i1 * cell + half, z0 + j0 * cell - half, z0 + j1 * cell + half))
    for side, k in gates:
        x, z = x0 + k * cell, z0 + k * cell
        alleys.append({"south": (x - half, x + half, wz0 - 1.0, z0), "north": (x - half, x + half, z0 + (m - 1) * cell, wz1 + 1.0),
                       "west": (wx0 - 1.0, x0, z - half, z + half), "east": (x0 + (n - 1) * cell, wx1 + 1.0, z - half, z + half)}[side])
    cx0, cx1, cz0, cz1 = x0 + qi * cell - half, x0 + (qi + 2) * cell + half, z0 + qj * cell - half, z0 + (qj + 2) * cell + half
    alleys.append((cx0, cx1, cz0, cz1))
    # houses: every cell of the grid cut at the alleys' edges that is no alley, inside the wall
    xs, zs = _cut_lines(wx0 + 0.3, wx1 - 0.3, wz0 + 0.3, wz1 - 0.3, alleys)
    holes: list[tuple[float, float, float, float]] = []
    cells, doors_of = [], []  # the house cells, and the sides of each (0 south, 1 north, 2 west, 3 east) on an alley
    for a, b in pairwise(xs):
        for c, d in pairwise(zs):
            mx, mz = (a + b) / 2, (c + d) / 2
            if not any(h[0] < mx < h[1] and h[2] < mz < h[3] for h in alleys):
                cells.append((a, b, c, d))
                doors_of.append([k for k, (px, pz) in enumerate(((mx, c - 1.0), (mx, d + 1.0), (a - 1.0, mz), (b + 1.0, mz)))
                                 if b - a > 5.5 and d - c > 5.5 and any(h[0] < px < h[1] and h[2] < pz < h[3] for h in alleys)])
    candidates = [i for i, sides in enumerate(doors_of) if sides]
    yards = set(rng.choice(candidates, size=min(len(candidates), int(rng.integers(10, 16))), replace=False).tolist())
    for i, (a, b, c, d) in enumerate(cells):
        mx, mz = (a + b) / 2, (c + d) / 2
        if i not in yards:
            holes.append(_ridged(s, a, b, c, d, -0.5, rng.uniform(5.0, 9.0)))
        else:  # a courtyard house off an alley beside it
            door = doors_of[i][int(rng.integers(len(doors_of[i])))]
            top = rng.uniform(5.0, 7.0)
            for k, (p, q) in enumerate((((a, c), (b, c)), ((a, d), (b, d)), ((a, c), (a, d)), ((b, c), (b, d)))):
                length = abs(q[0] - p[0]) + abs(q[1] - p[1])
                s.wall(p, q, -0.5, top, [(length / 2 - 0.9, 1.8)] if k == door else [], thickness=0.6)
            _trunk(s, np.array([mx, mz]), 0.7, -0.5, 0.8)  # the fountain
    # covered passages: a lid over a tenth of the links away from the gates
    for link in sorted(links, key=sorted):
        (i0, j0), (i1, j1) = sorted(link)
        ax, az = x0 + i0 * cell, z0 + j0 * cell
        if rng.random() < 0.1 and not (cx0 < ax < cx1 and cz0 < az < cz1):
            bx, bz = x0 + i1 * cell, z0 + j1 * cell
            if i0 == i1:
                _lid(s, ax - half - 0.3, ax + half + 0.3, az + half + 0.5, bz - half - 0.5, 3.2)
            else:
                _lid(s, ax + half + 0.5, bx - half - 0.5, az - half - 0.3, az + half + 0.3, 3.2)
    # the mosque's arcade round its courtyard, a basin in the middle
    for x in np.arange(cx0 + 3.0, cx1 - 2.0, 3.0):
        for z in (cz0 + 2.5, cz1 - 2.5):
            _trunk(s, np.array([x, z]), 0.3, -0.5, 4.0)
    holes.append(_ridged(s, (cx0 + cx1) / 2 - 2.0, (cx0 + cx1) / 2 + 2.0, (cz0 + cz1) / 2 - 2.0, (cz0 + cz1) / 2 + 2.0, -0.5, 0.4))
    # the wall and its gates
    doors = {side: [] for side in ("south", "north", "west", "east")}
    for side, k in gates:
        doors[side].append(((k * cell + x0 - half - wx0) if side in ("south", "north") else (k * cell + z0 - half - wz0), lane))
    s.wall((wx0, wz0), (wx1, wz0), -0.5, 6.0, doors["south"], thickness=0.6)
    s.wall((wx0, wz1), (wx1, wz1), -0.5, 6.0, doors["north"], thickness=0.6)
    s.wall((wx0, wz0), (wx0, wz1), -0.5, 6.0, doors["west"], thickness=0.6)
    s.wall((wx1, wz0), (wx1, wz1), -0.5, 6.0, doors["east"], thickness=0.6)
    # the road outside: trees and stalls
    size_x, size_z = wx1 + 12.0, wz1 + 12.0
    taken = [(wx0 - 1.0, wx1 + 1.0, wz0 - 1.0, wz1 + 1.0)]
    taken += [(h[0] - 2.0, h[1] + 2.0, h[2] - 6.0, h[3] + 6.0) for h in alleys if h[2] < wz0 or h[3] > wz1]
    taken += [(h[0] - 6.0, h[1] + 6.0, h[2] - 2.0, h[3] + 2.0) for h in alleys if h[0] < wx0 or h[1] > wx1]
    for _ in range(int(rng.integers(40, 60))):
        p = np.array([rng.uniform(2.0, size_x - 2.0), rng.uniform(2.0, size_z - 2.0)])
        if _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, taken):
            if rng.random() < 0.5:
                _trunk(s, p, rng.uniform(0.25, 0.4), -0.5, 6.0)
            else:
                holes.append(_ridged(s, p[0] - 1.0, p[0] + 1.0, p[1] - 0.8, p[1] + 0.8, -0.5, 1.0))
            taken.append((p[0] - 2.5, p[0] + 2.5, p[1] - 2.5, p[1] + 2.5))
    s.ground(0.0, size_x, 0.0, size_z, 0.0, holes)
    return s.mesh()


def suburb(seed: int) -> trimesh.Trimesh:
    """A suburb of cul-de-sacs: a distributor road 9 m wide along x (open ground, as the shops' car park south of it);
    north of it 5-6 closes 6 m wide and 48-72 m long, each ending in a turning head 16 m across, lined both sides by
    plots 12 m wide and 24 m deep: a front garden open to the road (a car on the drive of most), a house (ridged) with
    a side way 2.2 m wide past it, closed by a fence with a gate 1.4 m wide, to a back garden fenced 1.8 m high (a shed
    in some). Behind the heads a green 24 m deep (trees, a playground's frames) across the whole width, reached from
    half the heads (at least one) by a footpath 3 m wide between fences; back to back plots of neighbouring closes meet
    at a fence, and garages (ridged) fill the ground between a short close's head and the green. South of the road a
    row of shops (ridged) with a car park of parked cars in front, and a playing field fenced 1.8 m high with two gates.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    closes, plot, depth, road = int(rng.integers(5, 7)), 12.0, 24.0, 6.0
    strip = road + 2 * depth
    size_x = closes * strip
    lengths = [float(rng.choice([48.0, 60.0, 72.0])) for _ in range(closes)]
    rz = 40.0  # the distributor's north edge; it runs from z = 31 to 40
    gz0 = rz + max(lengths) + 16.0  # the green's south edge
    size_z = gz0 + 24.0
    holes: list[tuple[float, float, float, float]] = []
    paths = [k for k in range(closes) if rng.random() < 0.5] or [int(rng.integers(closes))]

    def plot_at(x_road: float, out: float, z0: float) -> None:
        """A plot from the road's edge ``x_road`` outward (``out`` = +1 east, -1 west) between z0 and z0 + 12."""
        xf, xh, xb = x_road + out * 5.0, x_road + out * 14.0, x_road + out * depth
        holes.append(_ridged(s, min(xf, xh), max(xf, xh), z0 + 2.2, z0 + plot, -0.5, rng.uniform(5.0, 6.5)))
        s.wall((xf, z0), (xb, z0), -0.5, 1.8, thickness=0.1)  # the side fences: the plot's south and north
        s.wall((xh, z0 + plot), (xb, z0 + plot), -0.5, 1.8, thickness=0.1)
        s.wall((xb, z0), (xb, z0 + plot), -0.5, 1.8, thickness=0.1)
        s.wall((xf + out * 1.0, z0), (xf + out * 1.0, z0 + 2.2), -0.5, 1.8, [(0.4, 1.4)], thickness=0.1)  # the gate
        if rng.random() < 0.6:  # a car on the drive
            _car(s, min(xf, xf - out * 4.5), max(xf, xf - out * 4.5), z0 + 6.0, z0 + 7.8, 0.0)
        if rng.random() < 0.4:
            xs = xb - out * 3.5
            holes.append(_ridged(s, min(xs, xs + out * 2.5), max(xs, xs + out * 2.5), z0 + 8.0, z0 + 11.0, -0.5, 2.0))

    for k in range(closes):
        x0 = k * strip
        xc0, xc1 = x0 + depth, x0 + depth + road
        head = rz + lengths[k]
        for z0 in np.arange(rz, head - 1.0, plot):
            plot_at(xc0, -1.0, z0)
            plot_at(xc1, 1.0, z0)
        # beside the head: fences from the last plots back to the green; the head's far side closed but for a path
        for xa, xb_ in ((x0, xc0 - 5.0), (xc1 + 5.0, x0 + strip)):
            s.wall((xa, head), (xb_, head), -0.5, 1.8, thickness=0.1)
        for x in (xc0 - 5.0, xc1 + 5.0):
            s.wall((x, head), (x, head + 16.0), -0.5, 1.8, thickness=0.1)
        far = head + 16.0
        mid = (xc0 + xc1) / 2
        if k in paths:
            s.wall((xc0 - 5.0, far), (xc1 + 5.0, far), -0.5, 1.8, [(mid - 1.5 - xc0 + 5.0, 3.0)], thickness=0.1)
            for x in (mid - 1.55, mid + 1.55):
                s.wall((x, far), (x, gz0), -0.5, 1.8, thickness=0.1)
            walls = ((x0, mid - 1.55), (mid + 1.55, x0 + strip))
        else:
            s.wall((xc0 - 5.0, far), (xc1 + 5.0, far), -0.5, 1.8, thickness=0.1)
            walls = ((x0, x0 + strip),)
        for xa, xb_ in walls:  # the green's fence
            s.wall((xa, gz0), (xb_, gz0), -0.5, 1.8, thickness=0.1)
        if gz0 - far > 1.0:  # a short close: garages fill the ground behind its head (but the path)
            for xa, xb_ in (((xc0 - 5.0, mid - 1.55), (mid + 1.55, xc1 + 5.0)) if k in paths else ((xc0 - 5.0, xc1 + 5.0),)):
                holes.append(_ridged(s, xa + 0.5, xb_ - 0.5, far + 0.5, gz0 - 0.5, -0.5, 3.0))
        # the back-to-back strip behind the head's fences up to the green: closed yards of the corner houses
        for xa, xb_ in ((x0, xc0 - 5.0), (xc1 + 5.0, x0 + strip)):
            if gz0 - head > 0.5:
                holes.append(_ridged(s, xa + 0.5, xb_ - 0.5, head + 0.5, gz0 - 0.5, -0.5, rng.uniform(5.0, 6.5)))
    s.wall((0.0, rz), (0.0, gz0), -0.5, 1.8, thickness=0.1)
    s.wall((size_x, rz), (size_x, gz0), -0.5, 1.8, thickness=0.1)
    # the green: trees and play frames
    taken = [(0.0, size_x, 0.0, gz0 + 1.0)]
    _trees(s, rng, int(rng.integers(30, 45)), size_x, size_z, taken, (0.25, 0.45), 6.0)
    for _ in range(int(rng.integers(4, 7))):
        p = np.array([rng.uniform(4.0, size_x - 8.0), rng.uniform(gz0 + 4.0, size_z - 6.0)])
        if _clear(p[0] - 1.0, p[0] + 5.0, p[1] - 1.0, p[1] + 3.0, taken):
            for dx in (0.0, 4.0):
                for dz in (0.0, 2.0):
                    _trunk(s, p + np.array([dx, dz]), 0.1, -0.5, 2.5)
            for dz in (0.0, 2.0):  # the bars, too thin to stand on
                s.box(p[0], p[0] + 4.1, 2.5, 2.6, p[1] + dz - 0.05, p[1] + dz + 0.05)
            taken.append((p[0] - 1.5, p[0] + 5.5, p[1] - 1.5, p[1] + 3.5))
    # south of the road: shops, the car park, the playing field
    sx = rng.uniform(10.0, size_x * 0.4)
    shops = (sx, sx + rng.uniform(40.0, 60.0), 2.0, 14.0)
    holes.append(_ridged(s, *shops, -0.5, 5.0))
    for x in np.arange(shops[0] + 2.0, shops[1] - 2.0, 2.6):
        for z in (17.0, 24.0):
            if rng.random() < 0.7:
                _car(s, x, x + 1.8, z, z + 4.5, 0.0)
    fx0, fx1 = shops[1] + 12.0, min(size_x - 4.0, shops[1] + 12.0 + rng.uniform(60.0, 80.0))
    gates = [(rng.uniform(2.0, (fx1 - fx0) / 2 - 4.0), 2.0), (rng.uniform((fx1 - fx0) / 2, fx1 - fx0 - 4.0), 2.0)]
    s.wall((fx0, 27.0), (fx1, 27.0), -0.5, 1.8, gates, thickness=0.1)
    s.wall((fx0, 3.0), (fx1, 3.0), -0.5, 1.8, thickness=0.1)
    for x in (fx0, fx1):
        s.wall((x, 3.0), (x, 27.0), -0.5, 1.8, thickness=0.1)
    for x in (fx0 + 4.0, fx1 - 4.0):  # goals
        for z in (12.0, 18.0):
            _trunk(s, np.array([x, z]), 0.08, -0.5, 2.4)
    s.ground(0.0, size_x, 0.0, size_z, 0.0, holes)
    return s.mesh()


def _car(s: _Solids, x0: float, x1: float, z0: float, z1: float, y: float) -> None:
    """A car on a floor at ``y`` over [x0, x1] x [z0, z1]: a hull from 0.3 m under the floor to a ridge 1.4 m over it
    along its longer side, so neither its top nor the floor under it (less than the agent's height) is floor."""
    mx, mz = (x0 + x1) / 2, (z0 + z1) / 2
    ridge = [[x0, y + 1.4, mz], [x1, y + 1.4, mz]] if x1 - x0 > z1 - z0 else [[mx, y + 1.4, z0], [mx, y + 1.4, z1]]
    s.hull(np.array([[x, y - 0.3, z] for x in (x0, x1) for z in (z0, z1)] + ridge))


def cloverleaf(seed: int) -> trimesh.Trimesh:
    """A cloverleaf junction over a marsh (no floor but the roads): motorway A along x on a causeway (deck top y = 0),
    motorway B along z on a viaduct 7.5-8.5 m up crossing over it, each 560-640 m long and two carriageways of 8.5 m
    split by a barrier 0.9 m high (no gap), so a carriageway of one road meets the other only through the loops: in
    each quadrant a loop ramp 6 m wide of radius 28-34 m turning 270 degrees, flat where it merges with A and with B
    (its first and last 25 degrees) and climbing 4 degrees between. A toll plaza across B's north arm (booths 1.5 m
    wide, lanes 2.6-3 m between them); off A's south carriageway in the west a service area (a deck behind a fence
    1.2 m high with an entry and an exit, a shop, fuel pumps, parked cars); 70-100 abandoned cars (:func:`_car`)
    tried on the roads, those clear of the others kept (46-56 on seeds 0-2).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    half_len, top, radius, edge = rng.uniform(280.0, 320.0), rng.uniform(7.5, 8.5), rng.uniform(28.0, 34.0), 9.5
    s.box(-half_len, half_len, -1.0, 0.0, -edge, edge)  # A
    s.box(-edge, edge, top - 1.0, top, -half_len, half_len)  # B
    s.box(-half_len, half_len, 0.0, 0.9, -0.4, 0.4)
    s.box(-0.4, 0.4, top, top + 0.9, -half_len, half_len)
    for z in np.arange(-half_len + 20.0, half_len, 40.0):  # B's piers, clear of A
        if abs(z) > edge + 4.0:
            s.box(-3.0, 3.0, -12.0, top - 1.0, z - 1.0, z + 1.0)
    # the loops
    flat = math.radians(25.0)
    for sx in (-1.0, 1.0):
        for sz in (-1.0, 1.0):
            c = np.array([sx * (edge + radius), sz * (edge + radius)])
            a_a, a_b = math.atan2(-sz, 0.0), math.atan2(0.0, -sx)
            turn = -math.copysign(1.0, math.remainder(a_b - a_a, 2 * math.pi)) * 1.5 * math.pi
            angles = np.linspace(0.0, 1.0, 55)
            heights = top * np.clip((angles * 1.5 * math.pi - flat) / (1.5 * math.pi - 2 * flat), 0.0, 1.0)
            for (t0, y0), (t1, y1) in pairwise(zip(angles, heights)):
                a0, a1 = a_a + turn * t0, a_a + turn * t1
                corners = [(c + r * np.array([math.cos(a), math.sin(a)]), y) for a, y in ((a0, y0), (a1, y1)) for r in (radius - 3.0, radius + 3.0)]
                s.hull(np.array([[p[0], y - d, p[1]] for p, y in corners for d in (0.0, 0.3)]))
    # the toll plaza on B's north arm
    zt = rng.uniform(edge + 2 * radius + 30.0, half_len - 40.0)
    for x in np.concatenate([np.arange(-edge + 3.0, -2.0, 4.3), np.arange(3.0, edge - 1.0, 4.3)]):
        _ridged(s, x, x + 1.5, zt, zt + 6.0, top - 0.5, top + 1.0)  # under 2 m inside
    # the service area in the west, south of A
    x0, x1 = -half_len + 30.0, -half_len + 30.0 + rng.uniform(90.0, 110.0)
    s.wall((x0, -edge - 0.3), (x1, -edge - 0.3), 0.0, 1.2, [(2.0, 10.0), (x1 - x0 - 12.0, 10.0)], thickness=0.2)
    taken = [(x0 - 1.0, x0 + 13.0, -edge - 8.0, -edge), (x1 - 13.0, x1 + 1.0, -edge - 8.0, -edge)]
    sx0 = rng.uniform(x0 + 14.0, x1 - 44.0)
    shop = _ridged(s, sx0, sx0 + 30.0, -edge - 38.0, -edge - 26.0, -1.0, 4.5)
    s.ground(x0, x1, -edge - 40.0, -edge, 0.0, [shop], thickness=1.0)  # the deck stops under the shop
    taken.append((sx0 - 2.0, sx0 + 32.0, -edge - 40.0, -edge - 24.0))
    px = rng.uniform(x0 + 14.0, x1 - 34.0)
    for x in np.arange(px, px + 20.0, 6.0):  # the pumps
        for z in (-edge - 14.0, -edge - 20.0):
            s.box(x, x + 1.2, -1.0, 1.6, z, z + 0.6)
    taken.append((px - 3.0, px + 23.0, -edge - 23.0, -edge - 11.0))
    for i, x in enumerate(np.arange(x0 + 2.0, x1 - 3.0, 2.4)):  # bays 2.4 m: 0.6 m between cars, too narrow to enter
        for z in (-edge - 40.0, -edge - 30.0):
            if i % 6 and rng.random() < 0.6 and _clear(x, x + 1.8, z, z + 4.5, taken):  # an aisle every sixth bay
                _car(s, x, x + 1.8, z, z + 4.5, 0.0)
    # abandoned cars: along a road, in a carriageway
    cars = [(x0 - 5.0, x1 + 5.0, -edge, 0.0), (-edge - 2.0, edge + 2.0, -edge - 2.0, edge + 2.0), (-edge, edge, zt - 8.0, zt + 14.0)]
    for _ in range(int(rng.integers(70, 101))):  # 1.6-2.2 m clear of the barrier and the edge, 3 m of each other
        lane = rng.choice([-1.0, 1.0]) * rng.uniform(2.0, 5.5)
        low = lane if lane > 0.0 else lane - 1.8  # the car's low side: its near side 2.0-5.5 m from the centre line
        if rng.random() < 0.35:  # on A
            x, z, w, d, y = rng.uniform(-half_len + 5.0, half_len - 10.0), low, 4.5, 1.8, 0.0
        else:  # on B
            x, z, w, d, y = low, rng.uniform(-half_len + 5.0, half_len - 10.0), 1.8, 4.5, top
        if _clear(x - 3.0, x + w + 3.0, z - 3.0, z + d + 3.0, cars):
            _car(s, x, x + w, z, z + d, y)
            cars.append((x, x + w, z, z + d))
    return s.mesh()


def _polar(r: float, a: float) -> np.ndarray:
    """The plan point (2,) at radius ``r`` (m) and angle ``a`` (radians) about the origin."""
    return np.array([r * math.cos(a), r * math.sin(a)])


def radial_town(seed: int) -> trimesh.Trimesh:
    """An ideal town of rings and radials (its only floor the streets, y = 0): a round place of radius 18 m round a
    monument (a pointed octagon 3 m in radius), 8-10 avenues 10 m wide out from it (a row of trees down each), three
    ring streets 6 m wide 30 m apart (the outer one the town's edge) and, beyond the first ring, lanes 4 m wide half
    way between the avenues. Between them blocks of houses with ridged roofs (no floor), but one block a ring a
    garden (floor, trees). Avenues and lanes are straight strips; the rings are chords about 5 m long (5.6-6.4
    degrees on the first ring, 2.6-2.8 on the outer), the blocks slices of 3 degrees or less.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    place, ring_w, avenue, lane = 18.0, 6.0, 10.0, 4.0
    rings = [place + 30.0 * (k + 1) + rng.uniform(-3.0, 3.0) for k in range(3)]
    n = int(rng.integers(8, 11))
    turn = rng.uniform(0.0, 2 * math.pi)
    avenues = [turn + 2 * math.pi * k / n + rng.uniform(-0.08, 0.08) for k in range(n)]
    lanes = [(a + b) / 2 for a, b in pairwise(avenues + [avenues[0] + 2 * math.pi])]
    outer = rings[-1] + ring_w / 2
    # the place, its monument, the rings, the avenues and the lanes
    sides = np.linspace(0.0, 2 * math.pi, 49)
    for a0, a1 in pairwise(sides):  # the place stops at the monument (its floor would be inside it)
        s.prism(np.array([_polar(3.0, a0), _polar(place, a0), _polar(place, a1), _polar(3.0, a1)]), -0.5, 0.0)
    s.hull(np.concatenate([[[x, y, z] for x, z in (_polar(3.0, a) for a in sides[:-1:6]) for y in (-0.5, 4.0)], [[0.0, 12.0, 0.0]]]))
    for r in rings:
        steps = np.linspace(0.0, 2 * math.pi, int(2 * math.pi * r / 5.0) + 1)
        for a0, a1 in pairwise(steps):
            s.prism(np.array([_polar(r - ring_w / 2, a0), _polar(r + ring_w / 2, a0), _polar(r + ring_w / 2, a1),
                              _polar(r - ring_w / 2, a1)]), -0.5, 0.0)
    for a in avenues:
        s.prism(_strip(_polar(place - 2.0, a), _polar(outer, a), avenue), -0.5, 0.0)
        for r in np.arange(place + 6.0, outer - 4.0, 8.0):
            if all(abs(r - q) > ring_w / 2 + 1.5 for q in rings):
                _trunk(s, _polar(r, a), 0.35, -0.5, 6.0)
    for a in lanes:
        s.prism(_strip(_polar(rings[0], a), _polar(outer, a), lane), -0.5, 0.0)
    # the blocks: between two radial ways (avenues, and lanes beyond the first ring) and two rings
    bounds = [(place + 0.0, rings[0] - ring_w / 2)] + [(a + ring_w / 2, b - ring_w / 2) for a, b in pairwise(rings)]
    for k, (r0, r1) in enumerate(bounds):
        ways = sorted([(a, avenue) for a in avenues] + ([(a, lane) for a in lanes] if k else []))
        ways.append((ways[0][0] + 2 * math.pi, ways[0][1]))
        garden = int(rng.integers(len(ways) - 1))
        for g, ((a0, w0), (a1, w1)) in enumerate(pairwise(ways)):
            r_in = max(r0, (w0 + w1) / 2 / math.sin((a1 - a0) / 2) + 1.0)
            inner = (a0 + math.asin(w0 / 2 / r_in), a1 - math.asin(w1 / 2 / r_in))
            outer_ = (a0 + math.asin(w0 / 2 / r1), a1 - math.asin(w1 / 2 / r1))
            m = max(1, math.ceil((outer_[1] - outer_[0]) / math.radians(3.0)))
            top = rng.uniform(6.0, 12.0)
            for j in range(m):
                t0, t1 = j / m, (j + 1) / m
                quad = np.array([_polar(r_in, inner[0] + t0 * (inner[1] - inner[0])), _polar(r1, outer_[0] + t0 * (outer_[1] - outer_[0])),
                                 _polar(r1, outer_[0] + t1 * (outer_[1] - outer_[0])), _polar(r_in, inner[0] + t1 * (inner[1] - inner[0]))])
                if g == garden:
                    s.prism(quad, -0.5, 0.0)
                    continue
                mid_in, mid_out = (quad[0] + quad[3]) / 2, (quad[1] + quad[2]) / 2
                s.hull(np.concatenate([np.insert(quad, 1, -0.5, axis=1), np.insert(quad, 1, top, axis=1),
                                       [[mid_in[0], top + 6.0, mid_in[1]], [mid_out[0], top + 6.0, mid_out[1]]]]))
            if g == garden:
                for _ in range(int(rng.integers(6, 12))):
                    r, a = rng.uniform(r_in + 2.0, r1 - 2.0), rng.uniform(*outer_)
                    if a0 + math.asin((w0 / 2 + 2.0) / r) < a < a1 - math.asin((w1 / 2 + 2.0) / r):
                        _trunk(s, _polar(r, a), 0.35, -0.5, 6.0)
    return s.mesh()


def _inset(poly: np.ndarray, dist: list[float]) -> np.ndarray | None:
    """The convex polygon ``poly`` (k, 2) of x, z, counter-clockwise, cut back by ``dist[i]`` m from each edge i
    (vertex i to i + 1): clipped by each edge's moved line in turn (Sutherland and Hodgman 1974, O(k) a line, O(k²)
    in all), so a short edge may vanish. None when less than 4 m² is left."""
    edges = np.roll(poly, -1, axis=0) - poly
    inward = np.stack([-edges[:, 1], edges[:, 0]], axis=1) / np.linalg.norm(edges, axis=1)[:, None]
    out = poly
    for normal, start, d in zip(inward, poly, dist):
        if d <= 0.0:
            continue
        side = (out - start) @ normal - d  # >= 0 inside the moved line
        kept = []
        for p, q, sp_, sq in zip(out, np.roll(out, -1, axis=0), side, np.roll(side, -1)):
            if sp_ >= 0.0:
                kept.append(p)
            if sp_ * sq < 0.0:
                kept.append(p + (q - p) * sp_ / (sp_ - sq))
        if len(kept) < 3:
            return None
        out = np.array(kept)
    area = 0.5 * abs(np.sum(out[:, 0] * np.roll(out[:, 1], -1) - np.roll(out[:, 0], -1) * out[:, 1]))
    return out if area >= 4.0 else None


def _ring(outer: np.ndarray, inner: np.ndarray) -> list[np.ndarray]:
    """Triangles (3, 2) tiling the ring between the convex polygons ``outer`` (k, 2) and ``inner`` (m, 2) inside it,
    both counter-clockwise: both walked round in the order of their corners' angles about inner's centroid, each step
    a triangle of the two current corners and the next of the one whose next angle comes first (a merge of two
    sorted lists, O(k + m))."""
    c = inner.mean(axis=0)

    def from_first(poly: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        angles = np.arctan2(poly[:, 1] - c[1], poly[:, 0] - c[0])
        start = int(np.argmin(angles))
        poly, angles = np.roll(poly, -start, axis=0), np.roll(angles, -start)
        angles = np.unwrap(angles)
        return np.vstack([poly, poly[:1]]), np.append(angles, angles[0] + 2 * math.pi)

    o, ao = from_first(outer)
    n, an = from_first(inner)
    i = j = 0
    triangles = []
    while i < len(outer) or j < len(inner):
        if j == len(inner) or (i < len(outer) and ao[i + 1] <= an[j + 1]):
            triangles.append(np.array([o[i], o[i + 1], n[j]]))
            i += 1
        else:
            triangles.append(np.array([o[i], n[j + 1], n[j]]))
            j += 1
    return triangles


def bazaar(seed: int) -> trimesh.Trimesh:
    """A covered bazaar (a souk) 110-130 x 80-95 m under one roof 5.5 m up (:func:`_lid`): stalls of irregular
    plan, the cells of a Voronoi diagram of a jittered 7.5 m grid of points (140-200), each cell's stall shrunk
    from its edges by 0.9-2.0 m (drawn a cell), so the alleys between them, 1.8-4 m wide, run at every angle and
    change width at every junction; up to a sixth of the alleys (those whose loss keeps the alleys one network)
    are built over, leaving blind alleys; 3-4 cells are open courtyards (khans) with a fountain; a cell too small
    for its insets is an open square. Stalls are solid to 4.5 m (1 m under the roof, so their tops hold no floor);
    the only floor is the alleys, squares and courtyards. A wall 0.6 m thick round it, open at one gate a side
    (a border cell left open), and a street 12 m wide outside, uncovered, with trees.

    Expected (written before the first run): the structure covers every alley and blind alley (the blind ones as
    leaves, with a terminal at each end), the courtyards and the four gates; a designer expects traffic highest on
    the ways between the gates (the widest, most direct alleys through the middle), on the street outside between
    neighbouring gates and in the courtyards on those ways; lowest in blind alleys and the bazaar's corners.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, roof, stall = rng.uniform(110.0, 130.0), rng.uniform(80.0, 95.0), 5.5, 4.5
    nx, nz = int(size_x / 7.5), int(size_z / 7.5)
    gx, gz = np.meshgrid((np.arange(nx) + 0.5) * size_x / nx, (np.arange(nz) + 0.5) * size_z / nz, indexing="ij")
    points = np.stack([gx.ravel(), gz.ravel()], axis=1) + rng.uniform(-0.3, 0.3, (nx * nz, 2)) * [size_x / nx, size_z / nz]
    n = len(points)
    # mirrored over the four sides, so every cell of the points is bounded by the rectangle
    mirrored = np.concatenate([points, points * [-1, 1], points * [-1, 1] + [2 * size_x, 0],
                               points * [1, -1], points * [1, -1] + [0, 2 * size_z]])
    vor, tree = Voronoi(mirrored), cKDTree(mirrored)
    cells, neighbours = [], []  # each cell's corners (k, 2), counter-clockwise, and the point across each edge (-1: a side)
    for i in range(n):
        poly = np.clip(vor.vertices[vor.regions[vor.point_region[i]]], [0.0, 0.0], [size_x, size_z])
        centre = poly.mean(axis=0)
        poly = poly[np.argsort(np.arctan2(poly[:, 1] - centre[1], poly[:, 0] - centre[0]))]
        poly = poly[np.linalg.norm(np.roll(poly, -1, axis=0) - poly, axis=1) > 1e-6]
        _, near = tree.query((poly + np.roll(poly, -1, axis=0)) / 2, k=2)
        across = [int(b) if a == i else int(a) for a, b in near]
        neighbours.append([j if j < n else -1 for j in across])
        cells.append(poly)
    half = rng.uniform(0.9, 2.0, n)
    border = [i for i in range(n) if -1 in neighbours[i]]
    inner = [i for i in range(n) if i not in border]
    open_cells = {i for i in inner if _inset(cells[i], [half[i]] * len(cells[i])) is None}  # too small: squares
    gates: list[tuple[int, int]] = []  # (cell, its edge on the side)
    for side in range(4):
        t = rng.uniform(0.25, 0.75)
        target = [(t * size_x, 0.0), (t * size_x, size_z), (0.0, t * size_z), (size_x, t * size_z)][side]
        best = min(border, key=lambda i: np.linalg.norm(cells[i].mean(axis=0) - target))
        edge = min((k for k, j in enumerate(neighbours[best]) if j < 0),
                   key=lambda k: np.linalg.norm((cells[best][k] + cells[best][(k + 1) % len(cells[best])]) / 2 - target))
        gates.append((best, edge))
        open_cells.add(best)
    khans = rng.choice([i for i in inner if i not in open_cells], int(rng.integers(3, 5)), replace=False)
    open_cells |= {int(k) for k in khans}
    # the alleys as a graph on the cells' corners; built-over alleys drawn among those whose loss keeps it one
    key = {}

    def corner(p: np.ndarray) -> int:
        return key.setdefault((round(p[0], 3), round(p[1], 3)), len(key))

    alleys: dict[frozenset[int], tuple[int, int]] = {}
    plazas: list[list[int]] = []
    for i, poly in enumerate(cells):
        ids = [corner(p) for p in poly]
        if i in open_cells:
            plazas.append(ids)
        for k, j in enumerate(neighbours[i]):
            if j >= 0:
                alleys[frozenset((i, j))] = (ids[k], ids[(k + 1) % len(ids)])

    def connected(edges: list[tuple[int, int]]) -> bool:
        rows = [a for a, _ in edges] + [p[0] for p in plazas for _ in p[1:]]
        cols = [b for _, b in edges] + [q for p in plazas for q in p[1:]]
        graph = sp.coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(len(key),) * 2)
        label = connected_components(graph, directed=False)[1]
        used = np.unique(rows + cols)
        return len(np.unique(label[used])) == 1

    closed: set[frozenset[int]] = set()
    candidates = [e for e in alleys if not e & open_cells]
    for e in rng.permutation(len(candidates))[: len(candidates) // 6 + 20]:
        edge = candidates[int(e)]
        if len(closed) < len(alleys) // 6 and connected([v for k, v in alleys.items() if k not in closed | {edge}]):
            closed.add(edge)
    for i, poly in enumerate(cells):  # a built-over alley: both stalls reach its middle
        inset = None if i in open_cells else _inset(poly, [0.0 if j < 0 or frozenset((i, j)) in closed else half[i]
                                                          for j in neighbours[i]])
        if inset is None:
            s.prism(poly, -0.5, 0.0 if i in open_cells else stall)
            continue
        s.prism(inset, -0.5, stall)
        for triangle in _ring(poly, inset):
            if abs(_turn(*triangle)) > 1e-6:
                s.prism(triangle, -0.5, 0.0)
    for k in khans:  # a fountain in each courtyard: a basin 0.8 m high
        _trunk(s, cells[k].mean(axis=0), 1.2, -0.5, 0.8)
    # the wall, open over each gate's edge, the roof and the street outside
    doors: dict[int, list[tuple[float, float]]] = {0: [], 1: [], 2: [], 3: []}
    for cell, k in gates:
        a, b = cells[cell][k], cells[cell][(k + 1) % len(cells[cell])]
        side = 0 if np.isclose(a[1], 0.0) and np.isclose(b[1], 0.0) else 1 if np.isclose(a[1], size_z) and np.isclose(b[1], size_z) \
            else 2 if np.isclose(a[0], 0.0) else 3
        lo, hi = sorted((a[0], b[0]) if side < 2 else (a[1], b[1]))
        doors[side].append((lo + 0.6 + 0.5, hi - lo - 1.0))
    s.wall((-0.6, -0.3), (size_x + 0.6, -0.3), -0.5, stall, doors[0], thickness=0.6)
    s.wall((-0.6, size_z + 0.3), (size_x + 0.6, size_z + 0.3), -0.5, stall, doors[1], thickness=0.6)
    s.wall((-0.3, 0.0), (-0.3, size_z), -0.5, stall, doors[2], thickness=0.6)
    s.wall((size_x + 0.3, 0.0), (size_x + 0.3, size_z), -0.5, stall, doors[3], thickness=0.6)
    _lid(s, -0.6, size_x + 0.6, -0.6, size_z + 0.6, roof)
    for _ in range(int(rng.integers(40, 60))):  # trees along the street, 4-8 m out from the wall
        t, out, side = rng.uniform(0.0, 1.0), rng.uniform(4.5, 8.0), int(rng.integers(4))
        p = [(t * size_x, -out), (t * size_x, size_z + out), (-out, t * size_z), (size_x + out, t * size_z)][side]
        _trunk(s, np.array(p), 0.35, -0.5, 6.0)
    s.ground(-12.6, size_x + 12.6, -12.6, size_z + 12.6, 0.0, [(0.0, size_x, 0.0, size_z)])  # on under the wall
    return s.mesh()


def container_port(seed: int) -> trimesh.Trimesh:
    """A container terminal 230-260 m along its quay (z = 0; the sea, no floor, beyond): an apron 36 m deep under 3-4
    ship-to-shore cranes (legs 1.2 m square on a 16 x 28 m portal, a girder 40 m up ridged), then a straddle-carrier
    yard: 18-22 rows along x, each one container wide (2.44 m), cut into blocks of 5-7 slots of 12.2 m (40-foot
    boxes) by cross aisles 12 m wide, stacked 1-3 high (2.6 m a box; a slot left empty one time in twelve, a pocket
    joining the lanes either side of it), the rows 1.8-2.4 m apart (the straddle lanes); behind the yard a road 14 m
    wide, a gate of 6-8 lanes between ridged booths, an office (ridged) and a car park. The containers' tops are flat
    floor out of reach at 2.6, 5.2 and 7.8 m, 150-180 pieces; the ground stops under every stack.

    Expected (written before the first run): on the ground the structure covers the apron, every straddle lane (long
    narrow corridors with both ends on a cross aisle), the pockets, the cross aisles, the road, gate lanes and car
    park; the container tops are covered as pieces of their own (out of reach, so no traffic), those under the
    cover's smallest area left out with a warning. Traffic highest on the cross aisles and the apron (the ways
    between the yard's blocks and along the quay) and on the road to the gate; each straddle lane carries little,
    evenly along its length; the pockets are short cuts between lanes.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length, apron, box, slot = rng.uniform(230.0, 260.0), 36.0, 2.6, 12.2
    holes: list[tuple[float, float, float, float]] = []
    # the cranes on the apron
    x = rng.uniform(10.0, 30.0)
    for _ in range(int(rng.integers(3, 5))):
        if x + 18.0 > length - 10.0:
            break
        for dx in (0.0, 16.0):
            for z in (3.0, 31.0):
                s.box(x + dx, x + dx + 1.2, -0.5, 40.0, z, z + 1.2)
                holes.append((x + dx, x + dx + 1.2, z, z + 1.2))
        _ridged(s, x - 1.0, x + 18.2, -40.0, 40.0, 40.0, 42.0)
        x += rng.uniform(40.0, 60.0)
    # the yard: rows of stacks along x, blocks of slots between cross aisles
    z, rows = apron, int(rng.integers(18, 23))
    blocks: list[tuple[float, float]] = []
    xb = 10.0
    while True:
        span = int(rng.integers(5, 8)) * slot
        if xb + span > length - 10.0:
            break
        blocks.append((xb, xb + span))
        xb += span + 12.0
    for _ in range(rows):
        z += rng.uniform(1.8, 2.4)
        for x0, x1 in blocks:
            ends = x0 + slot * np.arange(round((x1 - x0) / slot) + 1)  # one sum per end: no sliver between slots
            for xs, xe in pairwise(ends):
                if rng.random() < 1.0 / 12.0:
                    continue
                h = int(rng.choice([1, 2, 3], p=[0.3, 0.4, 0.3]))
                s.box(xs, xe, -0.5, h * box, z, z + 2.44)
                holes.append((xs, xe, z, z + 2.44))
        z += 2.44
    z += rng.uniform(1.8, 2.4)
    # the road, the gate, the office and the car park
    road = z + 14.0
    depth = road + 40.0
    lanes = int(rng.integers(6, 9))
    gx = rng.uniform(20.0, length - 20.0 - lanes * 5.0)
    for k in range(lanes + 1):
        holes.append(_ridged(s, gx + 5.0 * k, gx + 5.0 * k + 1.2, road + 6.0, road + 12.0, -0.5, 1.6))
    ox = gx + lanes * 5.0 + 15.0 if gx < length / 2 else gx - 45.0
    holes.append(_ridged(s, ox, ox + 30.0, road + 4.0, road + 16.0, -0.5, 9.0))
    px = rng.uniform(5.0, length - 60.0)
    while px < gx + lanes * 5.0 + 5.0 and px + 55.0 > gx - 5.0 or px < ox + 35.0 and px + 55.0 > ox - 5.0:
        px = rng.uniform(5.0, length - 60.0)
    for i, xc in enumerate(np.arange(px, px + 52.0, 2.6)):
        for zc in (road + 22.0, road + 32.0):
            if i % 5 and rng.random() < 0.7:
                _car(s, xc, xc + 1.8, zc, zc + 4.5, 0.0)
    s.wall((0.0, depth), (length, depth), -0.5, 2.4, [(gx - 1.0, lanes * 5.0 + 3.2)], thickness=0.2)
    for xw in (0.0, length):
        s.wall((xw, 0.0), (xw, depth), -0.5, 2.4, thickness=0.2)
    for _ in range(int(rng.integers(10, 16))):  # trucks waiting in the gate lanes and on the road
        if rng.random() < 0.5:
            k = int(rng.integers(lanes))
            _car(s, gx + 5.0 * k + 1.9, gx + 5.0 * k + 4.3, road + 1.0, road + 13.0, 0.0)
        else:
            xt = rng.uniform(5.0, length - 20.0)
            if _clear(xt, xt + 14.0, z + 1.0, z + 4.0, [(gx - 2.0, gx + lanes * 5.0 + 3.0, z, road + 14.0)]):
                _car(s, xt, xt + 14.0, z + 1.5, z + 4.0, 0.0)
    s.ground(0.0, length, 0.0, depth, 0.0, holes)
    return s.mesh()


def theatre(seed: int) -> trimesh.Trimesh:
    """A Greek theatre cut into a hillside: an orchestra 11 m in radius (y = 0) and a cavea over the half turn north
    of it (x, z = r cos a, r sin a, 0 <= a <= 180 degrees) of seat tiers 0.84 m deep rising 0.45 m each (over the
    climb, and too shallow for the agent to stand on but for slivers of 0.5-7 m² where they run diagonally, which
    Recast's erosion leaves), 18-22 in the lower section and 12-16 in the upper, with a walkway (the diazoma) 2.6 m
    wide between them. The only ways up the cavea are radial aisles 1.8 m wide, three steps of 0.15 / 0.28 m a tier,
    between rails 0.3 m thick and 0.9 m over the seats (without them the seats beside the aisles join the floor:
    585 m² on seed 0, 209 m² of it over 1.5 m from an aisle's line): 5-7 in the lower section, twice as many and one
    more in the upper. Above the top tier the hill: a terrace 24 m deep round the cavea (a temple, altars, trees), which ends in a drop of 15-18 m to
    the plain at z = 0 and is also reached by two straight flights 2.4 m wide from the plain up to its ends. South
    of the orchestra the plain (y = 0, 160 x 50 m): the stage building (ridged) with a stage 2.5 m high before it
    (a flight at each end), statues, a stoa and trees. No flight before this one ran off the x and z axes.

    Expected (written before the first run): the structure covers the orchestra, every aisle (as a chain up the
    cavea), the diazoma (a curved ring), the terrace and the plain with the stage; the seats hold no floor. Traffic
    highest on the aisles nearest the middle and on the diazoma between them (the ways between plain and terrace
    besides the two flights), on the orchestra and on the plain between the flights' feet and the orchestra; lowest
    on the terrace's far corners, the stage and the plain's corners.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    orchestra, depth, rise, aisle, rail = 11.0, 0.84, 0.45, 1.8, 0.3
    lower, upper, wedges = int(rng.integers(18, 23)), int(rng.integers(12, 17)), int(rng.integers(6, 9))
    low_aisles = [math.pi * k / wedges for k in range(1, wedges)]
    up_aisles = [math.pi * k / (2 * wedges) for k in range(1, 2 * wedges)]
    first = int(rng.integers(10, 74))  # the terrace's temple stands over its 2-degree chords first to first + 5
    # tiers: (inner radius, seats' outer radius, outer radius, top, aisles' angles); a walkway tier has more beyond
    # its seat row: the diazoma (its aisles the lower ones) and the terrace (its aisles the upper ones)
    tiers: list[tuple[float, float, float, float, list[float]]] = []
    r, y = orchestra, 0.0
    for i in range(lower + 1 + upper + 1):
        y += rise
        aisles = low_aisles if i <= lower else up_aisles
        beyond = 2.6 if i == lower else 24.0 if i == lower + upper + 1 else 0.0
        tiers.append((r, r + depth, r + depth + beyond, y, aisles))
        r += depth + beyond
    top = y
    ends = (0.0, math.pi)
    for r0, r1, r2, y, aisles in tiers:
        gaps_in = [math.asin((aisle / 2 + rail) / r0) for _ in aisles]
        gaps_out = [math.asin((aisle / 2 + rail) / r1) for _ in aisles]
        bounds = [(ends[0], ends[0])] + [(a - g0, a - g1) for a, g0, g1 in zip(aisles, gaps_in, gaps_out)]
        starts = [(ends[0], ends[0])] + [(a + g0, a + g1) for a, g0, g1 in zip(aisles, gaps_in, gaps_out)]
        bounds = bounds[1:] + [(ends[1], ends[1])]
        for (a0_in, a0_out), (a1_in, a1_out) in zip(starts, bounds):  # the seats between aisles, chords of <= 3 degrees
            m = max(1, math.ceil((a1_out - a0_out) / math.radians(3.0)))
            for j in range(m):
                t0, t1 = j / m, (j + 1) / m
                s.prism(np.array([_polar(r0, a0_in + t0 * (a1_in - a0_in)), _polar(r1, a0_out + t0 * (a1_out - a0_out)),
                                  _polar(r1, a0_out + t1 * (a1_out - a0_out)), _polar(r0, a0_in + t1 * (a1_in - a0_in))]),
                        -0.5, y)
        for a in aisles:  # three steps and a rail either side
            for j in range(3):
                s.prism(_strip(_polar(r0 + j * depth / 3, a), _polar(r0 + (j + 1) * depth / 3, a), aisle), -0.5, y - rise + 0.15 * (j + 1))
            for side in (-1.0, 1.0):
                offset = np.array([-math.sin(a), math.cos(a)]) * side * (aisle + rail) / 2
                s.prism(_strip(_polar(r0, a) + offset, _polar(r1, a) + offset, rail), -0.5, y + 0.9)
        if r2 > r1:  # the walkway beyond the seat row: chords round the whole half turn
            m = 60 if r2 - r1 < 5.0 else 90  # chords of 3 or 2 degrees
            for j in range(m):
                a0, a1 = math.pi * j / m, math.pi * (j + 1) / m
                bands = [(r1, r2)] if r2 - r1 < 5.0 or not first <= j < first + 6 else [(r1, r1 + 8.0), (r1 + 16.0, r2)]
                for ra, rb in bands:
                    s.prism(np.array([_polar(ra, a0), _polar(rb, a0), _polar(rb, a1), _polar(ra, a1)]), -0.5, y)
    outer = r
    s.prism(np.array([_polar(orchestra, math.pi * k / 24) for k in range(48)]), -0.5, 0.0)
    # on the terrace: a temple (the terrace stops under it: its floor would be inside), altars and trees
    terrace = (outer - 24.0, outer)
    temple = (math.pi * first / 90, math.pi * (first + 6) / 90, terrace[0] + 8.0, terrace[0] + 16.0)
    corners = [_polar(rr, aa) for aa in temple[:2] for rr in temple[2:]]
    ridge = [_polar((temple[2] + temple[3]) / 2, aa) for aa in temple[:2]]
    s.hull(np.array([[p[0], yy, p[1]] for p in corners for yy in (top - 0.5, top + 6.0)] + [[p[0], top + 12.0, p[1]] for p in ridge]))
    c = _polar((temple[2] + temple[3]) / 2, (temple[0] + temple[1]) / 2)
    for _ in range(int(rng.integers(40, 60))):
        rr, aa = rng.uniform(terrace[0] + 4.0, terrace[1] - 1.5), rng.uniform(0.05, math.pi - 0.05)
        p = _polar(rr, aa)
        if np.linalg.norm(p - c) > 12.0 and min(abs(aa - q) for q in up_aisles) * rr > 3.0:
            if rng.random() < 0.2:
                s.box(p[0] - 0.6, p[0] + 0.6, top - 0.5, top + 1.0, p[1] - 0.6, p[1] + 0.6)
            else:
                _trunk(s, p, rng.uniform(0.25, 0.45), top - 0.5, top + 6.0)
    # the two flights from the plain up to the terrace's ends (head-on into its end face, along +z)
    steps = math.ceil(top / 0.18)
    run = steps * 0.28
    holes: list[tuple[float, float, float, float]] = []
    for sign in (-1.0, 1.0):
        xf = sign * (outer - 8.0)
        s.stairs(np.array([xf, -run]), np.array([0.0, 1.0]), 2.4, 0.0, top, top / steps, 0.28)
        holes.append((xf - 1.2, xf + 1.2, -run, 0.0))
    # the plain: the stage building and stage, a stoa, statues, trees
    holes.append(_ridged(s, -20.0, 20.0, -30.0, -20.0, -0.5, 9.0))
    s.box(-16.0, 16.0, -0.5, 2.5, -20.0, -15.0)
    holes.append((-16.0, 16.0, -20.0, -15.0))
    stage_steps = math.ceil(2.5 / 0.18)
    for sign in (-1.0, 1.0):
        s.stairs(np.array([sign * (16.0 + stage_steps * 0.28), -17.5]), np.array([-sign, 0.0]), 2.0, 0.0, 2.5,
                 2.5 / stage_steps, 0.28)
        holes.append((min(sign * 16.0, sign * (16.0 + stage_steps * 0.28)), max(sign * 16.0, sign * (16.0 + stage_steps * 0.28)),
                      -18.5, -16.5))
    sx = rng.uniform(-60.0, 20.0)
    holes.append(_ridged(s, sx, sx + 40.0, -48.0, -42.0, -0.5, 5.0))
    taken = [(h[0] - 2.0, h[1] + 2.0, h[2] - 2.0, h[3] + 2.0) for h in holes] + [(-orchestra - 2.0, orchestra + 2.0, -orchestra - 2.0, 1.0)]
    taken += [(sign * (outer - 8.0) - 4.0, sign * (outer - 8.0) + 4.0, -run - 6.0, 0.0) for sign in (-1.0, 1.0)]
    for _ in range(int(rng.integers(60, 90))):
        p = np.array([rng.uniform(-78.0, 78.0), rng.uniform(-48.0, -2.0)])
        if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken):
            if rng.random() < 0.15:
                s.box(p[0] - 0.8, p[0] + 0.8, -0.5, 2.0, p[1] - 0.8, p[1] + 0.8)
                holes.append((p[0] - 0.8, p[0] + 0.8, p[1] - 0.8, p[1] + 0.8))
            else:
                _trunk(s, p, rng.uniform(0.25, 0.45), -0.5, 6.0)
            taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    s.ground(-80.0, 80.0, -50.0, 0.0, 0.0, holes)
    return s.mesh()


def _turn(u: np.ndarray, v: np.ndarray, w: np.ndarray) -> float:
    """Twice the signed area (m²) of the plan triangle u, v, w (each (2,)): > 0 when w is left of u -> v."""
    return float((v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0]))


def _crosses(p: np.ndarray, q: np.ndarray, a: np.ndarray, b: np.ndarray) -> bool:
    """Whether the plan segments p-q and a-b (each end (2,)) cross at a point inside both."""
    return _turn(p, q, a) * _turn(p, q, b) < 0 and _turn(a, b, p) * _turn(a, b, q) < 0


def stilt_village(seed: int) -> trimesh.Trimesh:
    """A village on stilts over a lagoon 170 x 120 m (water: no floor) off a bank 2.4 m up to the north (z 120-150,
    trees, huts): 30-36 house platforms 7-11 m square, their tops 2.25-2.55 m up, at least 14 m apart, each with a
    house of one room (walls 2.6 m high, a door 1.6 m wide on a side drawn, a gable roof) on a verandah 2 m wide, and
    a market platform 16 x 12 m of stalls. Boardwalks 1.8 m wide, without rails, join them at whatever angle their
    centres lie: the Euclidean minimum spanning tree of the platforms and three landings on the bank, and about a
    third of the other pairs under 30 m apart whose walk crosses none already laid; each boardwalk slopes from one
    platform's top to the other's. Posts under the platforms' corners; 5-7 platforms have a ramp down to a pontoon
    0.4 m over the water with a boat (ridged) beside it. Decks at random angles over nothing: every earlier round's
    bridges and boardwalks ran along x or z or round a circle.

    Expected (written before the first run): the structure covers every boardwalk (a chain each), every verandah
    round its house and the house's room behind its door (a leaf), the market, the pontoons (leaves at their ramps'
    ends) and the bank. Traffic highest on the tree's trunk boardwalks (those the most platforms reach the bank
    through: near the bank's landings and the market), lowest on the platforms at the tree's leaves, the pontoons
    and inside the houses.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, bank = 170.0, 120.0, 2.4
    centres: list[np.ndarray] = [np.array([rng.uniform(50.0, 120.0), rng.uniform(45.0, 80.0)])]
    halves: list[tuple[float, float]] = [(8.0, 6.0)]  # the market
    target = int(rng.integers(30, 37))
    while len(centres) < target:
        p = np.array([rng.uniform(8.0, size_x - 8.0), rng.uniform(8.0, size_z - 12.0)])
        if all(np.linalg.norm(p - c) > 14.0 + (6.0 if k == 0 else 0.0) for k, c in enumerate(centres)):
            h = rng.uniform(3.5, 5.5)
            centres.append(p)
            halves.append((h, h))
    tops = [bank] + [bank + rng.uniform(-0.15, 0.15) for _ in centres[1:]]
    landings = [np.array([x, size_z]) for x in np.sort(rng.uniform(15.0, size_x - 15.0, 3))]
    nodes = centres + landings
    heights = tops + [bank] * 3
    count = len(nodes)
    d = np.array([[np.linalg.norm(a - b) for b in nodes] for a in nodes])
    apart = d.copy()
    apart[len(centres):, len(centres):] = 0.0  # no walk from landing to landing (0: no edge)
    tree = minimum_spanning_tree(sp.csr_matrix(apart)).tocoo()
    walks = [tuple(sorted((int(i), int(j)))) for i, j in zip(tree.row, tree.col)]
    others = sorted(((d[i, j], i, j) for i in range(count) for j in range(i + 1, count)
                     if (i, j) not in walks and d[i, j] < 30.0 and not (i >= len(centres) and j >= len(centres))))
    for _, i, j in others:
        clear = all(not _crosses(nodes[i], nodes[j], nodes[a], nodes[b]) for a, b in walks if len({a, b, i, j}) == 4)
        away = all(abs(_turn(nodes[i], nodes[j], nodes[k])) / d[i, j] > max(halves[k]) + 2.0
                   for k in range(len(centres)) if k not in (i, j)
                   and 0.0 < np.dot(nodes[k] - nodes[i], nodes[j] - nodes[i]) < d[i, j] ** 2)
        if clear and away and rng.random() < 0.35:
            walks.append((i, j))

    def edge_point(k: int, toward: np.ndarray) -> np.ndarray:
        """Where the walk from node ``k`` toward ``toward`` starts: 1 m inside the platform's edge (a landing's
        point on the bank, 1 m in)."""
        u = (toward - nodes[k]) / np.linalg.norm(toward - nodes[k])
        if k >= len(centres):
            return nodes[k] + np.array([0.0, 1.0])
        hx, hz = halves[k]
        t = min(hx / abs(u[0]) if abs(u[0]) > 1e-9 else math.inf, hz / abs(u[1]) if abs(u[1]) > 1e-9 else math.inf)
        return nodes[k] + u * (t - 1.0)

    for i, j in walks:
        a, b = edge_point(i, nodes[j]), edge_point(j, nodes[i])
        s.ramp(a, b, 1.8, heights[i], heights[j])
    # the platforms, their houses and posts; the market's stalls
    for k, (c, (hx, hz), y) in enumerate(zip(centres, halves, tops)):
        s.box(c[0] - hx, c[0] + hx, y - 0.4, y, c[1] - hz, c[1] + hz)
        for dx in (-hx + 0.3, hx - 0.3):
            for dz in (-hz + 0.3, hz - 0.3):
                _trunk(s, c + np.array([dx, dz]), 0.15, -3.0, y - 0.35)
        if k == 0:
            for x in np.arange(c[0] - 6.0, c[0] + 5.0, 4.0):
                for z in (c[1] - 3.5, c[1] + 2.0):
                    if rng.random() < 0.8:
                        _ridged(s, x, x + 2.2, z, z + 1.5, y - 0.3, y + 1.0)
            continue
        r = hx - 2.0
        side = int(rng.integers(4))
        x0, x1, z0, z1 = c[0] - r, c[0] + r, c[1] - r, c[1] + r
        door = [(r - 0.8, 1.6)]
        s.wall((x0, z0), (x1, z0), y, y + 2.6, door if side == 0 else [])
        s.wall((x0, z1), (x1, z1), y, y + 2.6, door if side == 1 else [])
        s.wall((x0, z0), (x0, z1), y, y + 2.6, door if side == 2 else [])
        s.wall((x1, z0), (x1, z1), y, y + 2.6, door if side == 3 else [])
        _gable(s, x0 - 0.3, x1 + 0.3, z0 - 0.3, z1 + 0.3, y + 2.6)
    # pontoons: off the side of a platform no walk leaves from, where the water is clear
    used = 0
    for k in rng.permutation(np.arange(1, len(centres))):
        if used >= int(rng.integers(5, 8)):
            break
        c, (hx, _), y = centres[k], halves[k], tops[k]
        leaving = [nodes[j if i == k else i] - c for i, j in walks if k in (i, j)]
        for u in (np.array([1.0, 0.0]), np.array([-1.0, 0.0]), np.array([0.0, -1.0])):
            if all(np.dot(u, w) / np.linalg.norm(w) < 0.5 for w in leaving):
                a, b = c + u * (hx - 1.0), c + u * (hx + 13.0)
                end = c + u * (hx + 21.0)
                lo, hi = np.minimum(a, end) - 5.0, np.maximum(a, end) + 5.0
                if hi[0] < size_x and lo[0] > 0.0 and lo[1] > 0.0 and all(
                        np.any(np.abs(o - (a + end) / 2) > (hi - lo) / 2 + max(halves[m])) for m, o in enumerate(centres) if m != k) \
                        and all(not _crosses(a, end, edge_point(i, nodes[j]), edge_point(j, nodes[i])) for i, j in walks):
                    s.ramp(a, b, 1.6, y, 0.4)
                    side = np.array([-u[1], u[0]])
                    p0, p1 = b - side * 1.5, end + side * 1.5
                    s.box(min(p0[0], p1[0]), max(p0[0], p1[0]), 0.0, 0.4, min(p0[1], p1[1]), max(p0[1], p1[1]))
                    q0, q1 = b + side * 2.0 + u * 1.0, end + side * 4.5 - u * 1.0
                    _ridged(s, min(q0[0], q1[0]), max(q0[0], q1[0]), min(q0[1], q1[1]), max(q0[1], q1[1]), -0.5, 0.9)
                    used += 1
                    break
    # the bank: huts and trees
    holes: list[tuple[float, float, float, float]] = []
    taken = [(lp[0] - 3.0, lp[0] + 3.0, size_z - 1.0, size_z + 6.0) for lp in landings]
    for _ in range(int(rng.integers(5, 9))):
        x, z = rng.uniform(0.0, size_x - 8.0), rng.uniform(size_z + 8.0, size_z + 22.0)
        if _clear(x - 3.0, x + 11.0, z - 3.0, z + 9.0, taken):
            holes.append(_ridged(s, x, x + 8.0, z, z + 6.0, bank - 0.5, bank + 3.0))
            taken.append((x - 1.0, x + 9.0, z - 1.0, z + 7.0))
    for _ in range(int(rng.integers(50, 80))):
        p = np.array([rng.uniform(-8.0, size_x + 8.0), rng.uniform(size_z + 2.0, size_z + 28.0)])
        if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken):
            _trunk(s, p, rng.uniform(0.25, 0.45), bank - 0.5, bank + 6.0)
            taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    s.ground(-10.0, size_x + 10.0, size_z, size_z + 30.0, bank, holes)
    return s.mesh()


def nursery(seed: int) -> trimesh.Trimesh:
    """A plant nursery 170 x 125 m behind a fence 1.8 m high (a gate 8 m wide in the south): three glasshouses
    36-44 x 30-36 m side by side (glass walls 4 m high, a gable roof, a door 2 m wide at each end of a main aisle
    2.4 m wide along z through the middle, a cross aisle 2.2 m wide along the south wall), each side of the main aisle
    filled by benches 1.4-1.7 m deep (ridged: trays of plants, no floor) along x to the side wall, so the aisles
    between them, 1.3-1.7 m wide (drawn a glasshouse), are 8-10 dead ends off the main aisle a side; north of them
    5-7 polytunnels 8 x 30 m (a door 2 m wide at the south end only, beds either side of a path), south of them
    standing-out beds (ridged, 1.5 m wide, in blocks between paths 1.6-2.2 m wide), and by the gate a shop (ridged),
    a car park and a potting shed. Combs of narrow dead-end aisles, about fifty of them.

    Expected (written before the first run): the structure covers every bench aisle (a leaf each, a terminal at its
    end), the main and cross aisles, the tunnels' paths (leaves), the paths between beds and the yard. Traffic highest
    on the yard between the gate and the glasshouses' south doors and on the main aisles; each bench aisle carries
    little (its own area's share), the far ends of the tunnels and the beds' blocks' far paths least.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z = 170.0, 125.0
    holes: list[tuple[float, float, float, float]] = []
    x = rng.uniform(6.0, 12.0)
    z0 = 48.0
    for _ in range(3):
        w, d = rng.uniform(36.0, 44.0), rng.uniform(30.0, 36.0)
        x0, x1, z1 = x, x + w, z0 + d
        xc = (x0 + x1) / 2
        door = [(xc - 1.0 - x0, 2.0)]
        s.wall((x0, z0), (x1, z0), -0.5, 4.0, door, thickness=0.1)
        s.wall((x0, z1), (x1, z1), -0.5, 4.0, door, thickness=0.1)
        s.wall((x0, z0), (x0, z1), -0.5, 4.0, thickness=0.1)
        s.wall((x1, z0), (x1, z1), -0.5, 4.0, thickness=0.1)
        _gable(s, x0 - 0.1, x1 + 0.1, z0 - 0.1, z1 + 0.1, 4.0)
        bench, gap = rng.uniform(1.4, 1.7), rng.uniform(1.3, 1.7)
        for zb in np.arange(z0 + 2.2, z1 - bench - 0.05, bench + gap):  # benches to the north wall, a cross aisle south
            for a, b in ((x0 + 0.05, xc - 1.2), (xc + 1.2, x1 - 0.05)):
                _ridged(s, a, b, zb, zb + bench, -0.5, 0.5)
        x = x1 + rng.uniform(6.0, 10.0)
    # the polytunnels north of the glasshouses
    x, zt = rng.uniform(4.0, 10.0), z0 + 36.0 + rng.uniform(5.0, 8.0)
    for _ in range(int(rng.integers(5, 8))):
        if x + 8.0 > size_x - 4.0 or zt + 30.0 > size_z - 3.0:
            break
        s.wall((x, zt), (x + 8.0, zt), -0.5, 2.8, [(3.0, 2.0)], thickness=0.1)
        s.wall((x, zt + 30.0), (x + 8.0, zt + 30.0), -0.5, 2.8, thickness=0.1)
        for xw in (x, x + 8.0):
            s.wall((xw, zt), (xw, zt + 30.0), -0.5, 2.8, thickness=0.1)
        _gable(s, x - 0.1, x + 8.1, zt - 0.1, zt + 30.1, 2.8)
        for a, b in ((x + 0.05, x + 3.0), (x + 5.0, x + 7.95)):  # beds ridged along z, their long side
            s.hull(np.array([[xx, yy, zz] for xx in (a, b) for yy in (-0.5, 0.3) for zz in (zt + 1.5, zt + 29.95)]
                            + [[(a + b) / 2, 0.3 + (b - a) / 2 * math.tan(math.radians(50.0)), zz] for zz in (zt + 1.5, zt + 29.95)]))
        x += 8.0 + rng.uniform(2.0, 4.0)
    # the shop, car park and potting shed by the gate; the standing-out beds
    gate = rng.uniform(40.0, size_x - 50.0)
    shop_x = gate + 14.0 if gate < size_x / 2 else gate - 44.0
    holes.append(_ridged(s, shop_x, shop_x + 30.0, 3.0, 15.0, -0.5, 5.0))
    for i, xc in enumerate(np.arange(shop_x, shop_x + 30.0, 2.6)):
        if i % 5 and rng.random() < 0.7:
            _car(s, xc, xc + 1.8, 19.0, 23.5, 0.0)
    shed_x = rng.uniform(4.0, size_x - 20.0)
    while not _clear(shed_x - 2.0, shed_x + 14.0, 0.0, 46.0, [(gate - 4.0, gate + 12.0, 0.0, 46.0), (shop_x - 2.0, shop_x + 32.0, 0.0, 46.0)]):
        shed_x = rng.uniform(4.0, size_x - 20.0)
    holes.append(_ridged(s, shed_x, shed_x + 12.0, 36.0, 44.0, -0.5, 3.5))
    taken = [(gate - 4.0, gate + 12.0, 0.0, 46.0), (shop_x - 2.0, shop_x + 32.0, 0.0, 26.0), (shed_x - 2.0, shed_x + 14.0, 34.0, 46.0)]
    path = rng.uniform(1.6, 2.2)
    for xb in np.arange(4.0, size_x - 26.0, 26.0):  # blocks 22 m long, tracks 4 m between them
        for zb in np.arange(20.0, 44.0 - 1.5, 1.5 + path):
            if _clear(xb, xb + 22.0, zb, zb + 1.5, taken):
                _ridged(s, xb, xb + 22.0, zb, zb + 1.5, -0.5, 0.3)
    s.wall((0.0, 0.0), (size_x, 0.0), -0.5, 1.8, [(gate, 8.0)], thickness=0.1)
    s.wall((0.0, size_z), (size_x, size_z), -0.5, 1.8, thickness=0.1)
    for xw in (0.0, size_x):
        s.wall((xw, 0.0), (xw, size_z), -0.5, 1.8, thickness=0.1)
    s.ground(-6.0, size_x + 6.0, -10.0, size_z, 0.0, holes)
    return s.mesh()


def _carve(s: _Solids, x0: float, x1: float, z0: float, z1: float, y0: float, y1: float,
           voids: list[tuple[float, float, float, float, float, float]]) -> None:
    """Rock over [x0, x1] x [y0, y1] x [z0, z1] but the ``voids``, boxes (x0, x1, y0, y1, z0, z1). The plan is cut at
    every void's edges; each cell holds one box per height range the voids leave solid, and a run of cells along z
    with the same ranges one box: no box of rock stands on another (their shared face would be a floor inside the
    rock, the rule of the twelfth round). About (x cuts) x (z cuts) cells."""
    xs, zs = _cut_lines(x0, x1, z0, z1, [(v[0], v[1], v[4], v[5]) for v in voids])
    for a, b in pairwise(xs):
        mx = (a + b) / 2
        start, current = None, None
        for c, d in [*pairwise(zs), (zs[-1], zs[-1])]:
            mz = (c + d) / 2
            ranges: list[tuple[float, float]] = []
            if d > c:
                y = y0
                for g0, g1 in sorted((v[2], v[3]) for v in voids if v[0] < mx < v[1] and v[4] < mz < v[5]):
                    if g0 > y:
                        ranges.append((y, min(g0, y1)))
                    y = max(y, g1)
                if y < y1:
                    ranges.append((y, y1))
            if tuple(ranges) != current:
                for r0, r1 in current or ():
                    s.box(a, b, r0, r1, start, c)
                start, current = c, tuple(ranges)


def cliff_dwellings(seed: int) -> trimesh.Trimesh:
    """Dwellings cut into a cliff 140-160 m long (its face the plane z = 0, the rock 24 m deep behind it, its top a
    plateau 25 m up) over a valley (y = 0, 60 m deep, trees, huts): five storeys 5 m apart (y = 0 to 20), on each
    above the ground a ledge 3 m deep cut into the face (3 m of head room, no rail; 40-120 m long, drawn a storey),
    and behind each ledge (on the ground, behind the face) rooms 4-7 m wide and 4-8 m deep, 2.8 m high, each entered
    from its ledge by one door 2 m wide through 0.6 m of rock. The storeys are joined only inside the rock: a stair
    well of switchbacks (:func:`_switchback`) from the ground to the plateau, entered from each storey's ledge, a
    second from the first ledge to the third, and a flight up the face (along x, 2.4 m wide) from the valley to the
    first ledge's end. :func:`_carve` builds the rock as boxes round the voids. Five stacked floors each a narrow
    ledge over a drop, rooms behind it as dead ends, joined at two or three points.

    Expected (written before the first run): the structure covers every ledge (a chain along it), each room (a leaf
    at its door), the stair wells' flights and landings (chains through the rock), the valley and the plateau.
    Traffic highest in the main stair well and on the ledges between it and the second well and the face's flight
    (the only ways between storeys), the valley before the main well's entrance; lowest in the rooms at the
    ledges' far ends and on the plateau's far corners.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length, rock, storey, storeys, ledge = rng.uniform(140.0, 160.0), 24.0, 5.0, 5, 3.0
    top = storey * storeys
    well = _well_length(storey)
    main = rng.uniform(length * 0.35, length * 0.65)
    steps = math.ceil(storey / 0.18)
    run = steps * 0.28
    second = rng.uniform(run + 20.0, length - 16.0)
    while abs(second - main) < 20.0:
        second = rng.uniform(run + 20.0, length - 16.0)
    voids: list[tuple[float, float, float, float, float, float]] = []
    # the wells: open from their foot to above the top landing, a landing slab on every storey above the foot
    voids.append((main, main + 4.0, 0.0, top + 3.0, ledge, ledge + well))
    voids.append((main, main + 4.0, 0.0, 3.0, -0.1, ledge))  # the main well's entrance from the valley
    voids.append((second, second + 4.0, storey, 3 * storey + 3.0, ledge, ledge + well))
    for k in range(storeys):
        _switchback(s, main, ledge, k * storey, storey)
        if k:
            s.box(main, main + 4.0, k * storey - 0.45, k * storey, ledge, ledge + 2.0)
    s.box(main, main + 4.0, top - 0.45, top, ledge, ledge + 2.0)
    s.box(main, main + 2.0, top, top + 1.0, ledge + 1.9, ledge + 2.0)  # the rail across the lane no flight climbs
    for k in (1, 2):
        _switchback(s, second, ledge, k * storey, storey)
        s.box(second, second + 4.0, (k + 1) * storey - 0.45, (k + 1) * storey, ledge, ledge + 2.0)
    s.box(second, second + 2.0, 3 * storey, 3 * storey + 1.0, ledge + 1.9, ledge + 2.0)
    # the flight up the face from the valley, west of the wells, to a landing at the first ledge's west end
    fx = rng.uniform(6.0, min(main, second) - run - 8.0)
    s.stairs(np.array([fx, -1.2]), np.array([1.0, 0.0]), 2.4, 0.0, storey, storey / steps, 0.28)
    landing = fx + run
    s.box(landing, landing + 2.4, -0.5, storey, -2.4, 0.0)
    # ledges and rooms
    for k in range(storeys):
        y = k * storey
        needs = [main, main + 4.0] + ([second, second + 4.0] if 1 <= k <= 3 else [])
        if k:
            lx0 = landing if k == 1 else max(0.0, min(needs) - rng.uniform(10.0, 40.0))
            lx1 = min(length, max(max(needs) + rng.uniform(10.0, 40.0), lx0 + 40.0))
            voids.append((lx0, lx1, y, y + 3.0, -0.1, ledge))
            front = ledge
        else:
            lx0, lx1, front = 0.0, length, 0.0
        x = lx0 + rng.uniform(1.0, 4.0)
        while x < lx1 - 5.0:
            w, d = rng.uniform(4.0, 7.0), rng.uniform(4.0, 8.0)
            x1 = min(x + w, lx1 - 1.0)
            clash = [(q - 1.0, q + 5.0) for q in (main, second)] + ([(fx - 1.0, landing + 3.4)] if k == 0 else [])
            if x1 - x >= 4.0 and all(x1 < a or x > b for a, b in clash):
                dx = rng.uniform(x, x1 - 2.0)
                voids.append((x, x1, y, y + 2.8, front + 0.6, front + 0.6 + d))
                voids.append((dx, dx + 2.0, y, y + 2.4, front - 0.1, front + 0.7))
                x = x1 + rng.uniform(1.5, 4.0)
            else:
                x += 2.0
    _carve(s, 0.0, length, 0.0, rock, -0.5, top, voids)
    # the valley: huts and trees; on the plateau, trees
    holes: list[tuple[float, float, float, float]] = [(fx, landing + 2.4, -2.4, 0.0)]
    taken = [(fx - 2.0, landing + 2.0, -5.0, 0.0), (main - 3.0, main + 7.0, -8.0, 0.0)]
    for _ in range(int(rng.integers(6, 10))):
        x, z = rng.uniform(-5.0, length - 5.0), rng.uniform(-55.0, -12.0)
        if _clear(x - 3.0, x + 11.0, z - 3.0, z + 9.0, taken):
            holes.append(_ridged(s, x, x + 8.0, z, z + 6.0, -0.5, 3.0))
            taken.append((x - 1.0, x + 9.0, z - 1.0, z + 7.0))
    for _ in range(int(rng.integers(60, 90))):
        p = np.array([rng.uniform(-8.0, length + 8.0), rng.uniform(-58.0, -4.0)])
        if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, taken):
            _trunk(s, p, rng.uniform(0.25, 0.45), -0.5, 6.0)
            taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    wells = [(main - 1.0, main + 5.0, ledge - 1.0, ledge + well + 1.0)]
    for _ in range(int(rng.integers(25, 40))):
        p = np.array([rng.uniform(2.0, length - 2.0), rng.uniform(2.0, rock - 2.0)])
        if _clear(p[0] - 1.0, p[0] + 1.0, p[1] - 1.0, p[1] + 1.0, wells):
            _trunk(s, p, rng.uniform(0.25, 0.4), top - 0.5, top + 6.0)
            wells.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    s.ground(-10.0, length + 10.0, -60.0, 0.0, 0.0, holes)
    return s.mesh()


def _flight_to(s: _Solids, edge: np.ndarray, heading: np.ndarray, width: float, y0: float, y1: float,
               tread: float = 0.30) -> float:
    """A flight from ``y0`` up to ``y1`` (risers of at most 0.18 m) ending head-on at the plan point ``edge`` (x, z),
    the middle of its top step's far side, climbing along the unit ``heading`` (x, z). Returns its run (m)."""
    steps = math.ceil((y1 - y0) / 0.18 - 1e-9)
    run = steps * tread
    s.stairs(np.asarray(edge, dtype=np.float64) - np.asarray(heading, dtype=np.float64) * run, heading, width, y0, y1 - y0,
             (y1 - y0) / steps, tread)
    return run


def drop_downs(seed: int) -> trimesh.Trimesh:
    """Terraces one steps off but cannot climb: a grid of 5 x 5 solid blocks 15-18 m square, their tops 1 m up at
    one corner and rising 1.0-1.5 m a block along one axis and 1.6-2.6 m along the other (to 11.4-17.4 m), so every
    edge between two blocks is a ledge 1.0-2.6 m high an agent steps off (a drop-down: one-way in a game, no link in
    Recast). Flights (2 m wide, risers of at most 0.18 m, set on the lower block and ending head-on at the edge) join
    the blocks along a random spanning tree of the grid and about a quarter of the other edges; one block inside the
    grid has no flight (reached in a game only by dropping onto it and left only by dropping off it: an area of its
    own for Recast). Cover on every block (crates 1.2 m, low walls 1 m, pillars), a parapet 1.1 m round the grid.

    Expected (written before the first run): the structure covers every block (a terrace, a few nodes each) and each
    flight (a short chain), the drop-only block as an area of its own with no traffic; the ledges carry nothing, so
    traffic runs only along the flights' tree: highest on the flights and blocks near the tree's middle (every path
    between its halves), lowest on the blocks at the tree's leaves, the rest of each block's traffic toward its
    flights. A designer would mark the drop-downs as the busy short cuts; the heat map cannot, by construction.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    n, cell = 5, rng.uniform(15.0, 18.0)
    steps_x, steps_z = rng.uniform(1.0, 1.5), rng.uniform(1.6, 2.6)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    if rng.random() < 0.5:
        i = n - 1 - i
    if rng.random() < 0.5:
        j = n - 1 - j
    height = 1.0 + steps_x * i + steps_z * j
    for a in range(n):
        for b in range(n):
            s.box(a * cell, (a + 1) * cell, -0.5, height[a, b], b * cell, (b + 1) * cell)
    isolated = (int(rng.integers(1, n - 1)), int(rng.integers(1, n - 1)))
    edges = [((a, b), (a + da, b + db)) for a in range(n) for b in range(n) for da, db in ((1, 0), (0, 1))
             if a + da < n and b + db < n and isolated not in ((a, b), (a + da, b + db))]
    index = {(a, b): a * n + b for a in range(n) for b in range(n)}
    weights = rng.uniform(1.0, 2.0, len(edges))
    tree = minimum_spanning_tree(sp.coo_matrix((weights, ([index[p] for p, _ in edges], [index[q] for _, q in edges])),
                                               shape=(n * n, n * n))).tocoo()
    chosen = {(int(r), int(c)) for r, c in zip(tree.row, tree.col)}
    taken: list[tuple[float, float, float, float]] = []
    for p, q in edges:
        if (index[p], index[q]) not in chosen and rng.random() > 0.25:
            continue
        low, high = (p, q) if height[p] < height[q] else (q, p)
        along = 0 if p[0] != q[0] else 1  # the axis the flight climbs along
        heading = np.array([float(high[0] - low[0]), float(high[1] - low[1])])
        boundary = max(p[along], q[along]) * cell
        across = rng.uniform(low[1 - along] * cell + 3.0, (low[1 - along] + 1) * cell - 3.0)
        edge = np.array([boundary, across]) if along == 0 else np.array([across, boundary])
        run = _flight_to(s, edge, heading, 2.0, height[low], height[high])
        foot, top = edge - heading * (run + 2.0), edge + heading * 2.5
        corners = np.stack([foot, top]) + np.array([[-1.5, -1.5], [1.5, 1.5]]) * (1 - np.abs(heading))
        taken.append((corners[:, 0].min(), corners[:, 0].max(), corners[:, 1].min(), corners[:, 1].max()))
    for a in range(n):
        for b in range(n):
            y, placed = height[a, b], 0
            for _ in range(40):
                if placed >= int(rng.integers(5, 9)):
                    break
                kind = rng.integers(3)
                w, d = ((1.2, 1.2), (rng.uniform(3.0, 5.0), 0.4), (0.8, 0.8))[kind]
                if rng.random() < 0.5:
                    w, d = d, w
                x0, z0 = rng.uniform(a * cell + 1.0, (a + 1) * cell - 1.0 - w), rng.uniform(b * cell + 1.0, (b + 1) * cell - 1.0 - d)
                if _clear(x0 - 1.2, x0 + w + 1.2, z0 - 1.2, z0 + d + 1.2, taken):
                    s.box(x0, x0 + w, y - 0.3, y + (1.2, 1.0, 4.0)[kind], z0, z0 + d)
                    taken.append((x0, x0 + w, z0, z0 + d))
                    placed += 1
    side = n * cell
    for k in range(n):  # the parapet round the grid, a block at a time (each at its block's height)
        for (a, b), wall in (((k, 0), ((k * cell, 0.0), ((k + 1) * cell, 0.0))),
                             ((k, n - 1), ((k * cell, side), ((k + 1) * cell, side))),
                             ((0, k), ((0.0, k * cell), (0.0, (k + 1) * cell))),
                             ((n - 1, k), ((side, k * cell), (side, (k + 1) * cell)))):
            s.wall(*wall, height[a, b] - 0.3, height[a, b] + 1.1, thickness=0.3)
    return s.mesh()


def _house_interior(s: _Solids, rng: np.random.Generator, width: float, depth: float) -> float:
    """One house of :func:`house` over [0, width] x [0, depth] (its front door in the west wall at x = 0, its back
    door in the back wall at z = depth): walls, the upper floor, the stair, rooms, doors, furniture, the roof. Returns
    the x (m) of the back door's room's west wall, the back door 1.2 m east of it."""
    storey, outer = 3.0, 0.3
    hall0 = rng.uniform(0.4, 0.5) * depth - 1.6
    hall1 = hall0 + 3.3
    steps, tread = 17, 0.26
    run = steps * tread
    xs = rng.uniform(outer + 3.0, width - outer - run - 3.0)
    stair = (xs - 0.3, xs + run + 0.3)  # no room door opens on the flight or its well
    well = (xs, xs + run, hall1 - 1.6, hall1)
    s.stairs(np.array([xs, hall1 - 0.8]), np.array([1.0, 0.0]), 1.6, 0.0, storey, storey / steps, tread)
    s.slab(0.0, width, 0.0, depth, storey, [well], thickness=0.25)
    s.wall((xs, hall1 - 1.65), (xs + run, hall1 - 1.65), storey, storey + 1.0, thickness=0.1)  # the well's rails
    s.wall((xs - 0.05, hall1 - 1.6), (xs - 0.05, hall1), storey, storey + 1.0, thickness=0.1)
    _lid(s, -0.3, width + 0.3, -0.3, depth + 0.3, 2 * storey)
    front_door = rng.uniform(hall0 + 0.2, hall1 - 1.8)
    s.wall((outer / 2, 0.0), (outer / 2, depth), -0.5, storey, [(front_door, 1.6)], thickness=outer)
    s.wall((outer / 2, 0.0), (outer / 2, depth), storey, 2 * storey, thickness=outer)
    s.wall((width - outer / 2, 0.0), (width - outer / 2, depth), -0.5, 2 * storey, thickness=outer)
    back_room = (0.0, 0.0)
    for floor in (0.0, storey):
        top = floor + storey
        for side, (z0, z1) in enumerate(((outer, hall0 - 0.12), (hall1 + 0.12, depth - outer))):
            cuts = [outer]
            while cuts[-1] < width - outer - 6.0:
                cuts.append(cuts[-1] + rng.uniform(3.5, 5.0))
            if width - outer - cuts[-1] < 3.0:
                cuts.pop()
            cuts.append(width - outer)
            hall_wall, hall_doors = hall0 - 0.06 if side == 0 else hall1 + 0.06, []
            if floor == 0.0 and side == 1:
                back_room = list(pairwise(cuts))[int(rng.integers(len(cuts) - 1))]
            for k, (x0, x1) in enumerate(pairwise(cuts)):
                spans = [(a, b) for a, b in ((x0 + 0.2, x1 - 0.2),) if side == 0] or \
                        [(a, b) for a, b in ((x0 + 0.2, min(x1, stair[0]) - 0.2), (max(x0, stair[1]) + 0.2, x1 - 0.2)) if b - a >= 1.6]
                doors: list[tuple[float, float]] = []
                if spans:
                    a, b = spans[int(rng.integers(len(spans)))]
                    hall_doors.append((rng.uniform(a, b - 1.6) - outer, rng.uniform(1.5, 1.6)))
                    doors = [(hall_doors[-1][0] + outer, hall_doors[-1][0] + outer + hall_doors[-1][1])]
                if k and (not spans or rng.random() < 1.0 / 3.0):  # a door to the west neighbour
                    dz = rng.uniform(z0 + 0.2, z1 - 1.8)
                    s.wall((x0, z0), (x0, z1), floor, top, [(dz - z0, rng.uniform(1.5, 1.6))], thickness=0.12)
                    side_door = (x0 - 1.2, x0 + 1.2, dz, dz + 1.6)
                else:
                    if k:
                        s.wall((x0, z0), (x0, z1), floor, top, thickness=0.12)
                    side_door = None
                keep = [(a, b, hall_wall - 1.3, hall_wall + 1.3) for a, b in doors]
                keep += [side_door] if side_door else []
                if floor == 0.0 and back_room == (x0, x1):
                    keep.append((x0 + 1.0, x0 + 3.0, depth - 2.0, depth))
                placed = 0
                for _ in range(30):
                    if placed >= int(rng.integers(2, 5)):
                        break
                    w, d, h = [(2.0, 1.6, 0.55), (1.6, 0.9, 0.75), (2.0, 0.9, 0.8), (1.2, 0.6, 2.0), (1.4, 0.7, 0.75),
                               (1.0, 0.4, 1.8)][int(rng.integers(6))]
                    if rng.random() < 0.5:
                        w, d = d, w
                    if x1 - x0 - 0.4 < w or z1 - z0 - 0.4 < d:
                        continue
                    fx, fz = rng.uniform(x0 + 0.15, x1 - 0.15 - w), rng.uniform(z0 + 0.15, z1 - 0.15 - d)
                    against = int(rng.integers(4))  # set against one of the room's walls, as furniture stands
                    fx = (fx, fx, x0 + 0.1, x1 - 0.1 - w)[against]
                    fz = (z0 + 0.1, z1 - 0.1 - d, fz, fz)[against]
                    if _clear(fx, fx + w, fz, fz + d, keep):
                        s.box(fx, fx + w, floor - 0.1, floor + h, fz, fz + d)
                        keep.append((fx - 0.1, fx + w + 0.1, fz - 0.1, fz + d + 0.1))
                        placed += 1
            s.wall((outer, hall_wall), (width - outer, hall_wall), floor, top, hall_doors, thickness=0.12)
    s.wall((0.0, outer / 2), (width, outer / 2), -0.5, 2 * storey, thickness=outer)
    s.wall((0.0, depth - outer / 2), (width, depth - outer / 2), -0.5, storey, [(back_room[0] + 1.2, 1.6)], thickness=outer)
    s.wall((0.0, depth - outer / 2), (width, depth - outer / 2), storey, 2 * storey, thickness=outer)
    return back_room[0]


def house(seed: int) -> trimesh.Trimesh:
    """A pair of semi-detached houses of two storeys 3 m apart in one garden, each 24-28 x 13-15 m (walls 0.3 m, a
    roof at 50 degrees over it, :func:`_lid`; the second mirrored about the party wall), built by
    :func:`_house_interior`: on each storey a hallway along x, 3.3 m wide on the ground (half of it a straight flight
    1.6 m wide and 17 steps of 0.176 / 0.26 m against its back wall, the narrow stair) and upstairs a passage 1.6 m
    clear beside the stair's well (railed); rooms 3.5-5 m wide in a row either side, each entered from the hallway by
    one door 1.5-1.6 m wide (rooms beside the flight through a neighbour), a third of the neighbours joined by a door
    too; 2-4 pieces of furniture a room (beds, tables, sofas, wardrobes, desks, shelves), each against a wall and
    clear of the doors (a first draft's 3-7 pieces anywhere in rooms 3-4.5 m wide left 79 m² of the first house's
    ground storey walkable on seed 0, 174 m² without them; now 140 m²). The
    doors are just wider than the presets' agent passes: through a wall 0.15-0.25 m thick a door of 1.5 m opens at
    every offset to Recast's grid, 1.3-1.45 m at some, 0.9-1.0 m (a real house's) at none. A front door at the
    hallway's outer end, a back door; the garden has a hedge with a gate, a shed, trees, shrubs and two patio tables.

    Expected (written before the first run): the structure covers both hallways (chains), the flight (a chain up the
    well), every room (a leaf at its door, or a node between two doors), the garden round the house; furniture makes
    rooms' corners dents, no terminals. Traffic highest in the ground hallway between the front door, the flight's
    foot and the back door, then the flight and the upstairs landing; lowest in the rooms at the hallways' ends and
    the garden's corners.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    width, depth = rng.uniform(24.0, 28.0), rng.uniform(13.0, 15.0)
    back_doors = []
    for k in range(2):  # the second house mirrored about the party wall at x = width
        half = _Solids()
        x0 = _house_interior(half, rng, width, depth)
        if k:
            s.parts += [trimesh.convex.convex_hull(part.vertices * np.array([-1.0, 1.0, 1.0]) + np.array([2 * width, 0.0, 0.0]))
                        for part in half.parts]
            back_doors.append(2 * width - x0 - 2.8)
        else:
            s.parts += half.parts
            back_doors.append(x0 + 1.2)
    # the garden: a hedge round both plots with a gate, a shed, trees and shrubs, a patio table at each back door
    g0, g1, h0, h1 = -14.0, 2 * width + 14.0, -16.0, depth + 18.0
    gate = rng.uniform(g0 + 3.0, g1 - 5.0)
    s.wall((g0, h0), (g1, h0), -0.5, 1.8, [(gate - g0, 2.0)], thickness=0.8)
    s.wall((g0, h1), (g1, h1), -0.5, 1.8, thickness=0.8)
    for gx in (g0, g1):
        s.wall((gx, h0), (gx, h1), -0.5, 1.8, thickness=0.8)
    holes = [_ridged(s, g1 - 7.0, g1 - 2.0, h1 - 6.0, h1 - 2.0, -0.5, 2.2)]
    taken = [(-4.0, 2 * width + 4.0, -1.0, depth + 1.0), (g1 - 8.0, g1 - 1.0, h1 - 7.0, h1 - 1.0),
             (gate - 2.0, gate + 4.0, h0, h0 + 4.0)]
    for x in back_doors:
        s.box(x - 0.7, x + 0.9, -0.3, 0.75, depth + 3.0, depth + 4.0)
        taken.append((x - 1.2, x + 2.8, depth, depth + 6.0))
    for _ in range(int(rng.integers(60, 80))):
        p = np.array([rng.uniform(g0 + 2.0, g1 - 2.0), rng.uniform(h0 + 2.0, h1 - 2.0)])
        if _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, taken):
            if rng.random() < 0.4:
                _trunk(s, p, rng.uniform(0.2, 0.35), -0.5, 5.0)
            else:  # a shrub
                s.rock(rng, p, 0.5, -0.3, rng.uniform(0.8, 1.5))
            taken.append((p[0] - 2.0, p[0] + 2.0, p[1] - 2.0, p[1] + 2.0))
    s.ground(g0, g1, h0, h1, 0.0, holes)
    return s.mesh()


def pitched_roofs(seed: int) -> trimesh.Trimesh:
    """Two streets 10-14 m wide, 36-40 m apart, each between two terraces of blocks 2.5-4 m apart (alleys to the back
    yards and the back lane between the streets); a block is 3-5 houses 6-8.5 m wide and 9-11 m deep under one roof
    pitched at 30-40 degrees (under
    the presets' 45, so both slopes are floor), ridged along x, its eaves 5.5-7.5 m up (each house one convex body,
    so the roof is its top). On each block's street side a balcony (4-6 m long, 2.2 m deep, railed on its street and
    far sides) at the eaves, where the roof's slope starts, reached from the street by a flight along the facade
    (1.6 m wide, risers of at most 0.18 m): the only way onto the roof. Chimneys on the party walls, dormers (ridged at
    50 degrees) on the slopes; back yards between garden walls 4-5.5 m long, reached along the alleys; lamp posts and
    parked cars.

    Expected (written before the first run): the structure covers the street, the alleys and yards, each flight (a
    chain), balcony and roof (both slopes: a roof is an upper floor whose only way in is its balcony, so its far
    slope and gable ends are leaves); traffic highest along the street between the alleys and at the flights' feet,
    then on the flights and balconies, lowest on the roofs' back slopes and far ends and in the yards.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    street, length = rng.uniform(10.0, 14.0), rng.uniform(95.0, 115.0)
    holes: list[tuple[float, float, float, float]] = []
    taken: list[tuple[float, float, float, float]] = []
    back, streets = street / 2, (0.0, street + rng.uniform(36.0, 40.0))  # two streets, back lanes between
    for centre, out in [(c, o) for c in streets for o in (-1.0, 1.0)]:  # a row's houses lie out * depth deep
        x = rng.uniform(2.0, 6.0)
        while x < length - 20.0:
            houses, eave, pitch = int(rng.integers(3, 6)), rng.uniform(5.5, 7.5), math.radians(rng.uniform(30.0, 40.0))
            depth = rng.uniform(9.0, 11.0)
            back = max(back, street / 2 + depth)
            cuts = np.cumsum([x, *rng.uniform(6.0, 8.5, houses)])
            if cuts[-1] > length:
                break
            front, rear = centre + out * street / 2, centre + out * (street / 2 + depth)
            ridge = eave + depth / 2 * math.tan(pitch)

            def roof(z: float) -> float:
                return eave + (depth / 2 - abs(z - (front + rear) / 2)) * math.tan(pitch)

            for x0, x1 in pairwise(cuts):
                s.hull(np.array([[xx, y, z] for xx in (x0, x1) for y in (-0.5, eave) for z in (front, rear)]
                                + [[xx, ridge, (front + rear) / 2] for xx in (x0, x1)]))
                if x0 > cuts[0]:  # a chimney on the party wall at the ridge
                    s.box(x0 - 0.4, x0 + 0.4, eave, ridge + 1.2, (front + rear) / 2 - 0.4, (front + rear) / 2 + 0.4)
                for _ in range(int(rng.integers(0, 3))):  # dormers on either slope
                    dx = rng.uniform(x0 + 1.0, x1 - 2.8)
                    zc = (front + rear) / 2 + rng.choice([-1.0, 1.0]) * rng.uniform(1.8, depth / 2 - 1.8)
                    z0, z1 = zc - 0.9, zc + 0.9
                    _ridged(s, dx, dx + 1.8, z0, z1, min(roof(z0), roof(z1)) - 0.5, max(roof(z0), roof(z1)) + 1.0)
            holes.append((cuts[0], cuts[-1], min(front, rear), max(front, rear)))
            # the balcony and its flight along the facade (out = -1: the street is at +z)
            bw = rng.uniform(4.0, 6.0)
            steps = math.ceil(eave / 0.18)
            run = steps * 0.28
            bx = rng.uniform(cuts[0] + run + 1.0, cuts[-1] - bw - 1.0) if cuts[-1] - cuts[0] > run + bw + 2.0 else None
            if bx is None:
                x = cuts[-1] + rng.uniform(2.5, 4.0)
                continue
            toward = -out  # from the facade into the street
            zb0, zb1 = sorted((front, front + toward * 2.2))
            s.box(bx, bx + bw, eave - 0.3, eave, zb0, zb1)
            rail_z = front + toward * 2.15
            s.wall((bx, rail_z), (bx + bw, rail_z), eave, eave + 1.1, thickness=0.1)
            s.wall((bx + bw - 0.05, zb0), (bx + bw - 0.05, zb1), eave, eave + 1.1, thickness=0.1)
            _flight_to(s, np.array([bx, front + toward * 0.8]), np.array([1.0, 0.0]), 1.6, 0.0, eave, 0.28)
            for px in (bx + 0.2, bx + bw - 0.2):  # the balcony's posts
                s.box(px - 0.1, px + 0.1, -0.3, eave - 0.3, zb0 + 0.1 if toward < 0 else zb1 - 0.3,
                      zb0 + 0.3 if toward < 0 else zb1 - 0.1)
            taken.append((bx - run - 1.5, bx + bw + 1.0, zb0 - 2.5, zb1 + 2.5))
            # garden walls behind the party walls, 4-5.5 m out into the yards (6-8 m closed the back lane)
            for x0 in cuts[1:-1]:
                reach = rng.uniform(4.0, 5.5)
                s.wall((x0, rear), (x0, rear + out * reach), -0.5, 1.8, thickness=0.25)
            x = cuts[-1] + rng.uniform(2.5, 4.0)
    for _ in range(int(rng.integers(28, 44))):  # lamp posts and parked cars along the kerbs
        xc, side, centre = rng.uniform(3.0, length - 6.0), rng.choice([-1.0, 1.0]), streets[int(rng.integers(2))]
        z = centre + side * (street / 2 - 1.2)
        if rng.random() < 0.4:
            if _clear(xc - 0.5, xc + 0.5, z - 0.5, z + 0.5, taken):
                _trunk(s, np.array([xc, z]), 0.12, -0.3, 4.5)
                taken.append((xc - 0.5, xc + 0.5, z - 0.5, z + 0.5))
        elif _clear(xc - 0.5, xc + 4.7, z - 1.5, z + 1.5, taken):
            zc = centre + side * (street / 2 - 2.8)
            _car(s, xc, xc + 4.2, zc - 0.9, zc + 0.9, 0.0)
            taken.append((xc - 0.5, xc + 4.7, z - 1.5, z + 1.5))
    s.ground(-4.0, length + 4.0, -back - 10.0, streets[1] + back + 10.0, 0.0, holes)
    return s.mesh()


def _kit_layout(rng: np.random.Generator, n: int) -> tuple[np.ndarray, dict[tuple[int, int], tuple[int, int]]]:
    """The levels (n, n) of 0, 1 or 2 of an arena's tiles, symmetric under a half turn (n even), and its stair tiles
    (tile -> the step (di, dj) toward the higher neighbour it climbs to): platforms (10-13 rectangles of 2-4 x 2-3
    tiles at level 1 in the first half, three in five of those 3-4 tiles wide with a smaller one at level 2 on them),
    each stair tile one level under its higher neighbour with a tile of its own level behind it (the way onto it),
    placed along a random spanning tree of the runs of tiles of one level and at a sixth of the other places, each
    with its copy turned half round. Drawn again until the flights join every run, the stair tiles left out of the
    runs (a flight fills its tile but for its foot), each flight joining the run behind it to the one it climbs to."""
    while True:
        level = np.zeros((n, n), dtype=int)
        for _ in range(int(rng.integers(10, 14))):
            w, d = int(rng.integers(2, 5)), int(rng.integers(2, 4))
            i0, j0 = int(rng.integers(0, n - w + 1)), int(rng.integers(1, n // 2 - d + 1))
            level[i0:i0 + w, j0:j0 + d] = 1
            if w >= 3 and rng.random() < 0.6:
                level[i0 + 1:i0 + w - 1, j0:j0 + d - 1] = 2
        level[:, n // 2:] = level[::-1, n // 2 - 1::-1]
        labels, count = np.zeros((n, n), dtype=int), 0
        for lv in range(3):
            part, k = ndimage.label(level == lv)
            labels[part > 0] = part[part > 0] + count
            count += k
        parent = list(range(count + 1))

        def root(k: int) -> int:
            while parent[k] != k:
                parent[k] = parent[parent[k]]
                k = parent[k]
            return k

        options = [((i, j), (di, dj)) for i in range(n) for j in range(n // 2) for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1))
                   if 0 <= i + di < n and 0 <= j + dj < n and level[i + di, j + dj] == level[i, j] + 1
                   and 0 <= i - di < n and 0 <= j - dj < n and level[i - di, j - dj] == level[i, j]]
        stairs: dict[tuple[int, int], tuple[int, int]] = {}
        for o in rng.permutation(len(options)):
            (i, j), (di, dj) = options[o]
            near = [(i, j), (i + di, j + dj), (i - di, j - dj)]
            if any(t in stairs or (n - 1 - t[0], n - 1 - t[1]) in stairs for t in near):
                continue
            a, b = root(labels[i, j]), root(labels[i + di, j + dj])
            if a != b or rng.random() < 1.0 / 6.0:
                parent[a] = b
                parent[root(labels[n - 1 - i, n - 1 - j])] = root(labels[n - 1 - i - di, n - 1 - j - dj])
                stairs[(i, j)], stairs[(n - 1 - i, n - 1 - j)] = (di, dj), (-di, -dj)
        # the check: runs of tiles of one level without the stair tiles (a flight fills its tile but for its foot),
        # joined by each flight from the tile behind it to the tile it climbs to
        runs, count = np.zeros((n, n), dtype=int), 0
        for lv in range(3):
            part, k = ndimage.label((level == lv) & ~np.isin(np.arange(n * n).reshape(n, n), [i * n + j for i, j in stairs]))
            runs[part > 0] = part[part > 0] + count
            count += k
        parent = list(range(count + 1))
        for (i, j), (di, dj) in stairs.items():
            parent[root(runs[i - di, j - dj])] = root(runs[i + di, j + dj])
        if len({root(k) for k in range(1, count + 1)}) == 1:
            return level, stairs


def kit_arena(seed: int) -> trimesh.Trimesh:
    """A competitive arena built from a modular kit, as real multiplayer maps are: 20 x 20 floor tiles 4 m square,
    symmetric under a half turn about the centre, laid out by :func:`_kit_layout` (platforms of tiles 2 m and 4 m up,
    each raised tile a solid block; stair tiles of 12 steps of 0.167 / 0.30 m ending head-on at the higher tile,
    joining every run of tiles); wall tiles 4 m long round the arena (4 m high), cover walls (1.6 m long, 2.5 m high)
    on two fifths of the edges between tiles of open floor (a tile whose four neighbours are on its level), half walls
    (1 m) on the higher tile along a third of the drops, crates 1.2 m in half the tiles of open floor; no cover on a
    stair tile, the tile behind it or the tile it climbs to. Every piece is
    placed as a kit piece is: its edges moved by up to 1.5 cm each way, so neighbouring tiles leave gaps and overlaps
    of up to 3 cm (the seams of a real kit), and its top by up to 5 mm.

    Expected (written before the first run): the seams change nothing a walker sees: one area over the floor, the
    platforms and the stairs (gaps under Recast's 0.25 m cells), and a structure as symmetric as the arena (up to the
    seams): the floor's open lanes, each platform (a few nodes) and each stair (a short chain). Traffic highest on
    the open floor between the two halves and on the stairs of the platforms in the middle, lowest on the 4 m
    platforms and in the arena's corners.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    n, tile = 20, 4.0
    size = n * tile

    def placed(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> None:
        """A kit piece over the box, its edges moved by up to 1.5 cm and its top by up to 5 mm."""
        dx0, dx1, dz0, dz1 = rng.uniform(-0.015, 0.015, 4)
        s.box(x0 + dx0, x1 + dx1, y0, y1 + rng.uniform(-0.005, 0.005), z0 + dz0, z1 + dz1)

    def turned(x0: float, x1: float, z0: float, z1: float) -> tuple[float, float, float, float]:
        return size - x1, size - x0, size - z1, size - z0

    level, stairs = _kit_layout(rng, n)
    free = set(stairs) | {(i - di, j - dj) for (i, j), (di, dj) in stairs.items()} | \
        {(i + di, j + dj) for (i, j), (di, dj) in stairs.items()}  # no cover on a flight, its foot or its top
    for i in range(n):
        for j in range(n):
            placed(i * tile, (i + 1) * tile, -0.3, 2.0 * level[i, j], j * tile, (j + 1) * tile)
            if (i, j) in stairs:
                heading = np.array(stairs[(i, j)], dtype=np.float64)
                centre = np.array([(i + 0.5) * tile, (j + 0.5) * tile])
                _flight_to(s, centre + heading * (tile / 2 + rng.uniform(-0.015, 0.015)), heading, 2.4,
                           2.0 * level[i, j], 2.0 * level[i, j] + 2.0)
    for k in range(n):  # the outer wall tiles
        for x0, x1, z0, z1 in ((k * tile, (k + 1) * tile, -0.4, 0.0), (k * tile, (k + 1) * tile, size, size + 0.4),
                               (-0.4, 0.0, k * tile, (k + 1) * tile), (size, size + 0.4, k * tile, (k + 1) * tile)):
            placed(x0, x1, -0.3, 4.0, z0, z1)
    def open_floor(i: int, j: int) -> bool:
        """Whether tile (i, j) and its four neighbours are on one level: cover there shuts no way."""
        return 0 < i < n - 1 and 0 < j < n - 1 and all(level[i + di, j + dj] == level[i, j]
                                                       for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)))

    for i in range(n):  # cover in the first half and turned: half walls on drops, walls and crates on open floor
        for j in range(n // 2):
            for di, dj in ((1, 0), (0, 1)):
                p, q = (i, j), (i + di, j + dj)
                if q[0] >= n or p in free or q in free:
                    continue
                edge = (i + di) * tile if di else (j + dj) * tile
                if level[p] != level[q] and rng.random() < 1.0 / 3.0:  # on the higher tile, along the drop
                    inner = (edge - 0.4, edge) if level[p] > level[q] else (edge, edge + 0.4)
                    height, top = 1.0, 2.0 * max(level[p], level[q])
                elif level[p] == level[q] and open_floor(*p) and open_floor(*q) and rng.random() < 0.4:
                    inner, height, top = (edge - 0.2, edge + 0.2), 2.5, 2.0 * level[p]
                else:
                    continue
                box = (inner[0], inner[1], j * tile + 1.2, (j + 1) * tile - 1.2) if di else \
                    (i * tile + 1.2, (i + 1) * tile - 1.2, inner[0], inner[1])
                for b in (box, turned(*box)):
                    placed(b[0], b[1], top - 0.3, top + height, b[2], b[3])
            if open_floor(i, j) and (i, j) not in free and rng.random() < 0.5:
                cx, cz = (i + rng.uniform(0.4, 0.6)) * tile, (j + rng.uniform(0.4, 0.6)) * tile
                for b in ((cx - 0.6, cx + 0.6, cz - 0.6, cz + 0.6), turned(cx - 0.6, cx + 0.6, cz - 0.6, cz + 0.6)):
                    placed(b[0], b[1], 2.0 * level[i, j] - 0.3, 2.0 * level[i, j] + 1.2, b[2], b[3])
    return s.mesh()


def _spiral_stair(s: _Solids, centre: np.ndarray, storeys: int, storey: float, per_turn: int, hand: float,
                  start: float) -> list[float]:
    """A helical stair in a round shaft about plan point ``centre`` (x, z), from the ground (0) up ``storeys`` storeys
    ``storey`` m apart: a central column 0.5 m in radius, steps 0.1 m thick from it to the shaft's wall at 2.8 m,
    ``per_turn`` wedges a turn (risers ``storey / per_turn``), turning by ``hand`` (+1 or -1) from the angle ``start``
    (radians); a full turn a storey, the last step of each joined by a landing of one wedge's arc; the shaft's wall
    (0.3 m, 24 pieces) open over the landing and a wedge either side. Returns each storey's door angle (radians, the
    ground's first, then one a landing). A step clears the turn above it by (per_turn - 1) risers less the tread's
    0.1 m, less a riser and a cell or two where Recast's cells straddle two steps: about 2.1 m for 16 risers of
    0.172 m, where with a landing of two wedges and treads 0.15 m thick no step of a turn held floor."""
    sector, riser, pieces = hand * 2 * math.pi / per_turn, storey / per_turn, 24
    angle, doors = start, [start - sector * 1.5]
    for k in range(storeys):
        y = k * storey
        if k:
            s.prism(centre + _sector(0.45, 2.85, angle, angle + sector), y - 0.1, y)
            doors.append(angle + sector / 2)
            angle += sector
        for m in range(per_turn):
            plan = _sector(0.45, 2.85, angle + m * sector, angle + (m + 1.02) * sector)
            s.prism(centre + plan, y + riser * (m + 1) - 0.1, y + riser * (m + 1))
        angle += per_turn * sector
    s.prism(centre + _sector(0.45, 2.85, angle, angle + sector), storeys * storey - 0.1, storeys * storey)  # the top landing
    doors.append(angle + sector / 2)
    _trunk(s, centre, 0.5, -0.5, storeys * storey + 1.0)
    width = 2 * math.pi / pieces
    for k in range(storeys + 1):
        for m in range(pieces):
            if abs(math.remainder((m + 0.5) * width - doors[k], 2 * math.pi)) < abs(sector) * 1.5 + width / 2:
                continue
            s.prism(centre + _sector(2.8, 3.1, m * width, (m + 1) * width), k * storey, k * storey + (storey if k < storeys else 1.1))
    return doors


def spiral_towers(seed: int) -> trimesh.Trimesh:
    """Two round towers (7-8 m in radius, walls 0.6 m) 34-42 m apart in a walled bailey, each of 6-7 storeys climbed
    only by a helical stair in a central shaft (:func:`_spiral_stair`: 16-20 wedges a turn, the same in both, risers
    of 0.172-0.18 m, one turn a storey, so storeys 2.75-3.6 m apart; a landing and a door on every storey), the two
    towers turning opposite ways. Each storey is a ring of floor round the shaft (8-11 tables, chests and beds); the
    top is a roof behind a parapet. A curtain wall 3 m thick joins the towers, its walk (railed) at the second storey
    through a door in each tower; each tower opens on the bailey by a door about 2.6 m wide. The bailey holds up to
    23 ridged buildings, a well and trees.

    Expected (written before the first run): the structure covers each helix as a chain from the ground to the roof
    (nodes at the landings), each storey's ring (a loop or a few nodes), the wall walk, the bailey. Traffic highest
    on the bailey between the towers' doors, up both helices to the second storey and along the wall walk (the
    loop bailey - tower - walk - tower - bailey), lower on each helix above the second storey, lowest on the top
    storeys and roofs.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    per_turn, gap = int(rng.integers(16, 21)), rng.uniform(34.0, 42.0)
    storey = per_turn * rng.uniform(0.172, 0.18)
    holes: list[tuple[float, float, float, float]] = []
    radii = rng.uniform(7.0, 8.0, 2)
    walk = (radii[0] - 0.6, gap - radii[1] + 0.6)
    s.box(walk[0], walk[1], -0.5, 2 * storey, -1.5, 1.5)
    holes.append((walk[0], walk[1], -1.5, 1.5))
    for z in (-1.5, 1.5):  # the walk's rails
        s.wall((walk[0] + 0.3, z - np.sign(z) * 0.05), (walk[1] - 0.3, z - np.sign(z) * 0.05), 2 * storey, 2 * storey + 1.1,
               thickness=0.1)
    pieces = 36
    width = 2 * math.pi / pieces
    for t, (cx, hand) in enumerate(((0.0, 1.0), (gap, -1.0))):
        centre, radius = np.array([cx, 0.0]), radii[t]
        storeys = int(rng.integers(6, 8))
        toward = 0.0 if t == 0 else math.pi  # the walk's direction
        outside = rng.uniform(0.5, 1.5) * math.pi * (1 if rng.random() < 0.5 else -1) + toward
        doors = _spiral_stair(s, centre, storeys, storey, per_turn, hand, rng.uniform(0, 2 * math.pi))
        for k in range(1, storeys + 1):  # the rings of floor round the shaft
            for m in range(pieces):
                s.prism(centre + _sector(3.1, radius - 0.55, m * width, (m + 1) * width), k * storey - 0.25, k * storey)
        for k in range(storeys + 1):  # the tower's wall, open at the bailey door and the walk's door
            for m in range(pieces):
                mid = (m + 0.5) * width
                if k == 0 and abs(math.remainder(mid - outside, 2 * math.pi)) < 1.3 / radius or \
                        k == 2 and abs(math.remainder(mid - toward, 2 * math.pi)) < 1.3 / radius:
                    continue
                s.prism(centre + _sector(radius - 0.6, radius, m * width, (m + 1) * width), k * storey - (0.5 if k == 0 else 0.0),
                        k * storey + (storey if k < storeys else 1.2))
        for k in range(storeys):  # furniture on the rings, away from the doors
            for _ in range(int(rng.integers(8, 12))):
                a = rng.uniform(0, 2 * math.pi)
                if min(abs(math.remainder(a - d, 2 * math.pi)) for d in (doors[k], toward, outside)) < 0.6:
                    continue
                radial, tangent = np.array([math.cos(a), math.sin(a)]), np.array([-math.sin(a), math.cos(a)])
                w, d, h = [(1.6, 0.8, 0.75), (1.0, 0.6, 0.6), (2.0, 1.0, 0.55)][int(rng.integers(3))]
                c = centre + radial * (radius - 0.6 - d / 2 - 0.05)
                plan = np.array([c + radial * dr * d / 2 + tangent * dt * w / 2 for dr, dt in ((-1, -1), (1, -1), (1, 1), (-1, 1))])
                s.prism(plan, k * storey - 0.1, k * storey + h)
        holes.append((cx - 0.5, cx + 0.5, -0.5, 0.5))  # under the column
    # the bailey: buildings, a well, trees
    x0, x1, z0, z1 = -radii[0] - 30.0, gap + radii[1] + 30.0, -40.0, 40.0
    taken = [(-radii[0] - 3.0, gap + radii[1] + 3.0, -radii.max() - 3.0, radii.max() + 3.0)]
    for _ in range(int(rng.integers(18, 24))):
        w, d = rng.uniform(6.0, 12.0), rng.uniform(5.0, 8.0)
        x, z = rng.uniform(x0 + 2.0, x1 - w - 2.0), rng.uniform(z0 + 2.0, z1 - d - 2.0)
        if _clear(x - 3.0, x + w + 3.0, z - 3.0, z + d + 3.0, taken):
            holes.append(_ridged(s, x, x + w, z, z + d, -0.5, 3.0))
            taken.append((x, x + w, z, z + d))
    for k in range(int(rng.integers(45, 60))):
        p = np.array([rng.uniform(x0 + 2.0, x1 - 2.0), rng.uniform(z0 + 2.0, z1 - 2.0)])
        if _clear(p[0] - 2.0, p[0] + 2.0, p[1] - 2.0, p[1] + 2.0, taken):
            _trunk(s, p, 1.0 if k == 0 else rng.uniform(0.25, 0.4), -0.5, 1.0 if k == 0 else 6.0)  # the first, the well
            taken.append((p[0] - 2.0, p[0] + 2.0, p[1] - 2.0, p[1] + 2.0))
    for a, b in (((x0, z0), (x1, z0)), ((x0, z1), (x1, z1)), ((x0, z0), (x0, z1)), ((x1, z0), (x1, z1))):
        s.wall(a, b, -0.5, 6.0, thickness=1.0)
    s.ground(x0, x1, z0, z1, 0.0, holes)
    return s.mesh()


def backdrop(seed: int) -> trimesh.Trimesh:
    """A play space wrapped in background geometry, as a real level's file is: a town square 70-80 m across (ridged
    houses, a fountain, crates, a raised terrace up two flights, trees) in a bowl of distant terrain out to 100 m
    beyond it (a height field on a 6 m grid rising at 63-72 degrees from the square's edge to 12-18 m, then 0.15 m a
    metre under three waves 8-14 m high, whose slopes cross the 45-degree limit: walkable hillsides and patches no one
    reaches), cliffs (rock hulls) on it, far houses with flat roofs out of reach, and a skybox: a box 1 km across and
    200 m high with its faces turned inward and no floor (walls and a ceiling facing down, nothing Recast reads as
    floor, but the level's bounds grow from 80 m to 1 km).

    Expected (written before the first run): the structure covers the square as any town square (its streets
    round the houses, the terrace, the flights) and the background's walkable patches as areas of their own, each
    with its leaves or left out under the cover's smallest area (named in a warning), with no traffic. Traffic
    highest on the square's middle and between the houses' gaps, lowest on the terrace and in the corners; every
    background node coldest. A designer marks nothing outside the play space.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size = rng.uniform(70.0, 80.0)
    holes: list[tuple[float, float, float, float]] = []
    taken: list[tuple[float, float, float, float]] = []
    for _ in range(int(rng.integers(8, 12))):  # houses round the square's edge
        w, d = rng.uniform(7.0, 12.0), rng.uniform(6.0, 9.0)
        side = int(rng.integers(4))
        along = rng.uniform(2.0, size - w - 2.0)
        x, z = ((along, 1.0), (along, size - d - 1.0), (1.0, along), (size - d - 1.0, along))[side]
        if side >= 2:
            w, d = d, w
        if _clear(x - 3.0, x + w + 3.0, z - 3.0, z + d + 3.0, taken):
            holes.append(_ridged(s, x, x + w, z, z + d, -0.5, rng.uniform(5.0, 8.0)))
            taken.append((x, x + w, z, z + d))
    tx, tz = rng.uniform(20.0, size - 36.0), rng.uniform(20.0, size - 30.0)  # the terrace, 1.8 m up
    s.box(tx, tx + 16.0, -0.5, 1.8, tz, tz + 10.0)
    holes.append((tx, tx + 16.0, tz, tz + 10.0))
    for edge, heading in (((tx, tz + 5.0), (1.0, 0.0)), ((tx + 16.0, tz + 5.0), (-1.0, 0.0))):
        _flight_to(s, np.array(edge), np.array(heading), 2.4, 0.0, 1.8)
    taken.append((tx - 6.0, tx + 22.0, tz - 2.0, tz + 12.0))
    fc = np.array([rng.uniform(15.0, size - 15.0), rng.uniform(15.0, size - 15.0)])
    if _clear(fc[0] - 4.0, fc[0] + 4.0, fc[1] - 4.0, fc[1] + 4.0, taken):
        holes.append(_round_ground(s, fc, 3.0, 12, 0.6))
        taken.append((fc[0] - 4.0, fc[0] + 4.0, fc[1] - 4.0, fc[1] + 4.0))
    for k in range(int(rng.integers(20, 30))):
        p = np.array([rng.uniform(3.0, size - 3.0), rng.uniform(3.0, size - 3.0)])
        if _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, taken):
            if k % 2:
                s.box(p[0] - 0.6, p[0] + 0.6, -0.3, 1.2, p[1] - 0.6, p[1] + 0.6)
            else:
                _trunk(s, p, rng.uniform(0.25, 0.4), -0.5, 6.0)
            taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    s.ground(0.0, size, 0.0, size, 0.0, holes)
    # the distant terrain: a bowl rising from the square's edge, hills beyond
    far, grid = 100.0, 6.0
    xs = np.concatenate([np.arange(-far, 0.0, grid), [0.0, size], size + np.arange(grid, far + grid / 2, grid)])
    gx, gz = np.meshgrid(xs, xs, indexing="ij")
    out = np.maximum(np.maximum(-gx, gx - size), np.maximum(-gz, gz - size)).clip(0.0)
    rim = rng.uniform(12.0, 18.0)
    waves = sum(rng.uniform(8.0, 14.0) * np.sin(gx / rng.uniform(14.0, 26.0) + rng.uniform(0, 2 * math.pi))
                * np.cos(gz / rng.uniform(14.0, 26.0) + rng.uniform(0, 2 * math.pi)) for _ in range(3))
    heights = np.where(out > 0, rim + 0.15 * (out - grid) + np.where(out > grid, waves, 0.0), 0.0)
    keep = np.ones((len(xs) - 1, len(xs) - 1), dtype=bool)
    inside = (xs[:-1] >= 0.0) & (xs[1:] <= size)
    keep[np.ix_(inside, inside)] = False
    _terrain(s, xs, xs, heights, keep)
    for _ in range(int(rng.integers(25, 40))):  # cliffs and far houses on the terrain
        p = rng.uniform(-far + 10.0, size + far - 10.0, 2)
        d = max(-p[0], p[0] - size, -p[1], p[1] - size)
        if d < 20.0:
            continue
        y = float(heights[np.abs(xs - p[0]).argmin(), np.abs(xs - p[1]).argmin()])
        if rng.random() < 0.6:
            s.rock(rng, p, rng.uniform(3.0, 6.0), y - 2.0, y + rng.uniform(15.0, 30.0))
        else:
            w = rng.uniform(8.0, 14.0)
            s.box(p[0], p[0] + w, y - 6.0, y + rng.uniform(5.0, 10.0), p[1], p[1] + w)
    # the skybox: five faces turned inward
    lo, hi = size / 2 - 500.0, size / 2 + 500.0
    corners = np.array([[x, y, z] for x in (lo, hi) for y in (-20.0, 180.0) for z in (lo, hi)])
    sky = [[0, 3, 1], [0, 2, 3], [4, 7, 6], [4, 5, 7], [0, 6, 2], [0, 4, 6], [2, 7, 3], [2, 6, 7], [1, 7, 5], [1, 3, 7]]
    s.parts.append(trimesh.Trimesh(corners, np.array(sky), process=False))
    return s.mesh()


def _furnish(s: _Solids, rng: np.random.Generator, room: tuple[float, float, float, float], floor: float,
             keep: list[tuple[float, float, float, float]], count: int) -> None:
    """Up to ``count`` pieces of furniture (beds, shelves, tables, chests, sideboards) each against one of the walls of
    the room ``room`` (x0, x1, z0, z1) on the floor at ``floor``, clear of the rectangles ``keep`` (a door's approach)
    and of each other; a piece that does not fit is left out after ``4 * count`` tries."""
    x0, x1, z0, z1 = room
    taken = list(keep)
    for _ in range(4 * count):
        if count <= 0:
            break
        w, d, h = [(1.8, 0.9, 0.55), (1.2, 0.5, 1.9), (1.6, 0.9, 0.75), (0.9, 0.6, 0.8), (1.6, 0.5, 1.0)][int(rng.integers(5))]
        against = int(rng.integers(4))  # 0 the low-z wall, 1 the high-z one, 2 the low-x one, 3 the high-x one
        if against >= 2:
            w, d = d, w
        if x1 - x0 < w + 0.6 or z1 - z0 < d + 0.6:
            continue
        fx, fz = rng.uniform(x0 + 0.1, x1 - 0.1 - w), rng.uniform(z0 + 0.1, z1 - 0.1 - d)
        fx, fz = [(fx, z0 + 0.1), (fx, z1 - 0.1 - d), (x0 + 0.1, fz), (x1 - 0.1 - w, fz)][against]
        if _clear(fx - 0.1, fx + w + 0.1, fz - 0.1, fz + d + 0.1, taken):
            s.box(fx, fx + w, floor - 0.1, floor + h, fz, fz + d)
            taken.append((fx - 0.1, fx + w + 0.1, fz - 0.1, fz + d + 0.1))
            count -= 1


def _doored_wall(s: _Solids, a: tuple[float, float], b: tuple[float, float], floor: float, y1: float,
                 doors: list[tuple[float, float, str, float]], thickness: float = 0.2, lintel: float = 2.3) -> None:
    """A wall along x or z from plan point ``a`` to ``b`` from 0.5 m under the floor at ``floor`` up to ``y1`` (as
    :meth:`_Solids.wall`) whose doorways (start, width, leaf, into) have a lintel from ``lintel`` m over the floor (2.3
    m for a door: at 2.2 m the presets' agent, 2 m tall, passes at some offsets to Recast's grid only; under 2 m a
    vent or grate) and a leaf 5 cm thick and 2.15 m high as a level's file keeps it:
    "closed" fills the doorway on the wall's line, "ajar" stands open at 90 degrees from the hinge at the doorway's
    start into the side ``into`` (+1 or -1 across the wall), "open" has none."""
    s.wall(a, b, floor - 0.5, y1, [(start, width) for start, width, _, _ in doors], thickness)
    along = 0 if a[1] == b[1] else 1
    lo, fixed = min(a[along], b[along]), a[1 - along]

    def box(u0: float, u1: float, v0: float, v1: float, h0: float, h1: float) -> None:  # u along the wall, v across
        if along == 0:
            s.box(u0, u1, h0, h1, v0, v1)
        else:
            s.box(v0, v1, h0, h1, u0, u1)

    for start, width, leaf, into in doors:
        u0, u1 = lo + start, lo + start + width
        box(u0, u1, fixed - thickness / 2, fixed + thickness / 2, floor + lintel, y1)
        if leaf == "closed":
            box(u0, u1, fixed - 0.025, fixed + 0.025, floor - 0.05, floor + 2.15)
        elif leaf == "ajar":
            v0 = fixed + into * thickness / 2
            box(u0 + 0.02, u0 + 0.07, min(v0, v0 + into * (width - 0.05)), max(v0, v0 + into * (width - 0.05)),
                floor - 0.05, floor + 2.15)


def _door_block(rng: np.random.Generator) -> tuple[_Solids, float, float]:
    """One block of :func:`closed_doors` from the origin along +x and +z. Returns its solids, width and depth (m)."""
    s = _Solids()
    cols = np.cumsum([0.0, *rng.uniform(6.0, 9.0, 7)])
    width, r, c = cols[-1], rng.uniform(6.0, 8.0), 3.0
    depth = 4 * r + 2 * c
    lobby = int(rng.integers(2, 5))
    leaves = ("closed", "ajar", "open")
    # the rows (z0, z1, the corridor wall's z, the side the room lies on from that wall)
    rows = [(0.0, r, r, -1.0), (r + c, 2 * r + c, r + c, 1.0), (2 * r + c, 3 * r + c, 3 * r + c, -1.0),
            (3 * r + 2 * c, depth, 3 * r + 2 * c, 1.0)]
    for j, (z0, z1, line, into) in enumerate(rows):
        inner = j in (1, 2)
        doors = []
        for k, (x0, x1) in enumerate(pairwise(cols)):
            if inner and k == lobby:  # the lobby's west wall
                _doored_wall(s, (x0, z0), (x0, z1), 0.0, 3.0, [])
                continue
            start = rng.uniform(x0 + 0.5, x1 - 2.1)
            doors.append((start, 1.6, str(rng.choice(leaves, p=[0.4, 0.3, 0.3])), into))
            keep = [(start - 0.4, start + 2.0, min(line, line + into * 2.0), max(line, line + into * 2.0))]
            if k and not (inner and k - 1 == lobby):
                side = []
                if rng.random() < 0.3:
                    dz = rng.uniform(z0 + 0.4, z1 - 2.0)
                    side = [(dz - z0, 1.6, str(rng.choice(leaves, p=[0.4, 0.3, 0.3])), 1.0)]
                    keep.append((x0 - 2.0, x0 + 2.0, dz - 0.4, dz + 2.0))
                _doored_wall(s, (x0, z0), (x0, z1), 0.0, 3.0, side)
            elif inner and k == lobby + 1:  # the lobby's east wall
                _doored_wall(s, (x0, z0), (x0, z1), 0.0, 3.0, [])
            _furnish(s, rng, (x0 + 0.1, x1 - 0.1, z0 + 0.1, z1 - 0.1), 0.0, keep, int(rng.integers(1, 5)))
        if inner:  # the corridor wall, open over the lobby
            for part in ((0.0, cols[lobby]), (cols[lobby + 1], width)):
                inside = [(a - part[0], w, leaf, i) for a, w, leaf, i in doors if part[0] <= a < part[1]]
                _doored_wall(s, (part[0], line), (part[1], line), 0.0, 3.0, inside)
        else:
            _doored_wall(s, (0.0, line), (width, line), 0.0, 3.0, doors)
    for part in ((0.0, cols[lobby]), (cols[lobby + 1], width)):  # between the inner rows, but for the lobby
        _doored_wall(s, (part[0], 2 * r + c), (part[1], 2 * r + c), 0.0, 3.0, [])
    for z in (r, 3 * r + c):  # the corridors' fire doors, at a column line away from the lobby
        k = int(rng.choice([k for k in range(1, 7) if k not in (lobby, lobby + 1)]))
        _doored_wall(s, (cols[k], z), (cols[k], z + c), 0.0, 3.0,
                     [(0.6, 1.8, str(rng.choice(leaves, p=[0.5, 0.25, 0.25])), 1.0)])
    _doored_wall(s, (0.0, 0.0), (width, 0.0), 0.0, 3.0, [], 0.3)
    _doored_wall(s, (0.0, depth), (width, depth), 0.0, 3.0, [], 0.3)
    _doored_wall(s, (0.0, 0.0), (0.0, depth), 0.0, 3.0, [(r + 0.5, 2.0, "open", -1.0), (3 * r + c + 0.5, 2.0, "open", -1.0)], 0.3)
    _doored_wall(s, (width, 0.0), (width, depth), 0.0, 3.0,
                 [(z + 0.5, 2.0, str(rng.choice(leaves, p=[0.4, 0.3, 0.3])), 1.0) for z in (r, 3 * r + c)], 0.3)
    return s, width, depth


def _yard(s: _Solids, rng: np.random.Generator, width: float, depth: float, clear: float, out: float, tries: int) -> None:
    """``tries`` tries at parked cars (every third) and tree trunks at plan points uniform over [-out, width + out] x
    [-out, depth + out] m, each kept off the building [-clear, width + clear] x [-clear, depth + clear] and off the
    others."""
    taken = [(-clear, width + clear, -clear, depth + clear)]
    for k in range(tries):
        p = np.array([rng.uniform(-out, width + out), rng.uniform(-out, depth + out)])
        if k % 3 == 0 and _clear(p[0] - 0.5, p[0] + 4.7, p[1] - 1.5, p[1] + 1.5, taken):
            _car(s, p[0], p[0] + 4.2, p[1] - 0.9, p[1] + 0.9, 0.0)
            taken.append((p[0] - 0.5, p[0] + 4.7, p[1] - 1.5, p[1] + 1.5))
        elif k % 3 and _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, taken):
            _trunk(s, p, rng.uniform(0.25, 0.4), -0.5, 6.0)
            taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))


def closed_doors(seed: int) -> trimesh.Trimesh:
    """Two one-storey blocks 16-22 m apart (:func:`_door_block`) exported with their doors' leaves in place, as a
    real level's file keeps them. Each block: 7 columns of rooms 6-9 m wide in four rows 6-8 m deep, two corridors 3 m wide along x between the outer and inner rows, joined
    by a lobby (one column of the inner rows) and entered by an open doorway 2 m wide at each corridor's west end and
    a door at its east end; a fire door 1.8 m wide across each corridor at a column line away from the lobby. Every
    room opens on its corridor by a door 1.6 m wide (wider than the presets' agent needs) and on its west neighbour by
    another with a chance of 0.3; each door's leaf is closed (a chance of 0.4; a fire door 0.5), ajar (standing at 90
    degrees into the room, 0.3) or gone (0.3); every doorway has a lintel at 2.3 m. Walls 3 m high, 0.2 m thick;
    1-4 pieces of furniture a room (:func:`_furnish`); a yard 15 m wide round the blocks with trees and cars.

    Expected (written before the first run): for Recast a closed leaf is a wall, so every room whose doors are all
    closed is an island (seed 0 should have several), covered by a structure of its own with no traffic; a corridor
    whose fire door is closed is two halves joined only round the yard. What a designer expects is the block as the
    game plays it (doors open when walked into): traffic highest in the corridors and the lobby between the
    entrances, lowest in the rooms (leaves at their doors), the yard busy between the entrances. The heat map cannot
    show that: behind a closed leaf it has no way; within the main area, traffic runs round the closed fire doors
    through the yard.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    width, depth, gap = 0.0, 0.0, rng.uniform(16.0, 22.0)
    for k in range(2):  # two blocks, the second north of the first across a yard
        block, w, d = _door_block(rng)
        for part in block.parts:
            s.parts.append(part.apply_translation((0.0, 0.0, depth + gap * k)))
        width, depth = max(width, w), depth + gap * k + d
    _yard(s, rng, width, depth, 3.0, 14.0, int(rng.integers(25, 35)))
    s.ground(-15.0, width + 15.0, -15.0, depth + 15.0, 0.0, [])
    return s.mesh()


def _paper(s: _Solids, a: np.ndarray, b: np.ndarray, y0: float, y1: float, flip: bool) -> None:
    """A paper wall: one quad (two triangles, no thickness, one-sided) standing over the plan segment from ``a`` (x,
    z) to ``b`` between heights y0 < y1, facing one way or (``flip``) the other."""
    (ax, az), (bx, bz) = a, b
    faces = np.array([[0, 1, 2], [0, 2, 3]])
    s.parts.append(trimesh.Trimesh(np.array([[ax, y0, az], [bx, y0, bz], [bx, y1, bz], [ax, y1, az]]),
                                   faces[:, ::-1] if flip else faces, process=False))


def _paper_run(s: _Solids, rng: np.random.Generator, a: np.ndarray, b: np.ndarray, y0: float, y1: float,
               gaps: list[tuple[float, float]]) -> None:
    """Paper walls (:func:`_paper`) along the segment from ``a`` to ``b`` (x, z) between heights about y0 and y1,
    open over each gap (start, width: metres from ``a``); each piece floats up to 5 cm over ``y0`` or sinks as far
    into it (as an export's walls do) and faces a random way."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    length = float(np.linalg.norm(b - a))
    along = (b - a) / length
    cuts = [0.0, *sum(([start, start + width] for start, width in sorted(gaps)), []), length]
    for c0, c1 in zip(cuts[0::2], cuts[1::2]):
        if c1 - c0 > 1e-6:
            _paper(s, a + along * c0, a + along * c1, y0 + rng.uniform(-0.05, 0.05), y1, bool(rng.random() < 0.5))


def paper_walls(seed: int) -> trimesh.Trimesh:
    """A walled compound whose walls, fences and railings are paper: single quads with no thickness, one-sided and
    facing either way, standing up to 5 cm over the floor or sunk as far into it (:func:`_paper_run`), as a real
    level's file often has them. On closed ground 100-115 m square: 11-14 buildings 9-16 x 7-12 m, each of 2-4 rooms
    behind paper partitions 3 m high with a gap 1.8 m wide, a door 2 m wide in an end wall, solid
    furniture; half of them under a flat paper roof (one quad facing up, 3.2 m up: floor out of reach); a raised deck
    (a paper floor 3 m up, one quad facing up, on solid posts) 16-24 m long reached by a solid flight at each end,
    railed by paper railings 1.1 m high; paper fences 1.5 m high across the yard with gaps 2 m wide; a paper wall 3 m
    high round the compound with two gates.

    Expected (written before the first run): Recast rasterises a vertical quad into the cells it crosses, so a paper
    wall stops the agent as a solid one does (the same areas, the same doors, the navmesh within a few per cent of
    the same walls 0.2 m thick); the paper deck is floor reached by its flights, the paper roofs are islands out of
    reach. Traffic highest in the yard between the gates and the buildings' doors, on the deck's flights and deck
    (a short cut over the fences), lowest in the buildings' back rooms; the structure covers the yard's lanes between
    fences, each building (a node or two a room) and the deck as a chain.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size = rng.uniform(100.0, 115.0)
    taken: list[tuple[float, float, float, float]] = []
    deck_length = rng.uniform(16.0, 24.0)  # the deck along x, 2.4 m wide, 3 m up, a flight each end
    dx, dz = rng.uniform(15.0, size - deck_length - 15.0), rng.uniform(15.0, size - 15.0)
    run = math.ceil(3.0 / 0.18) * 0.28
    deck = (dx, dx + deck_length, dz - 1.2, dz + 1.2)
    s.parts.append(trimesh.Trimesh(np.array([[deck[0], 3.0, deck[2]], [deck[1], 3.0, deck[2]], [deck[1], 3.0, deck[3]],
                                             [deck[0], 3.0, deck[3]]]), np.array([[0, 2, 1], [0, 3, 2]]), process=False))
    for x in np.linspace(deck[0] + 0.3, deck[1] - 0.3, 5):  # posts
        for z in (deck[2] + 0.3, deck[3] - 0.3):
            s.box(x - 0.15, x + 0.15, -0.3, 2.99, z - 0.15, z + 0.15)
    for edge, heading in (((deck[0], dz), (1.0, 0.0)), ((deck[1], dz), (-1.0, 0.0))):
        _flight_to(s, np.array(edge), np.array(heading), 2.0, 0.0, 3.0, 0.28)
    for z in (deck[2] + 0.05, deck[3] - 0.05):
        _paper_run(s, rng, np.array([deck[0], z]), np.array([deck[1], z]), 3.0, 4.1, [])
    taken.append((deck[0] - run - 2.0, deck[1] + run + 2.0, deck[2] - 1.5, deck[3] + 1.5))
    placed, tries = 0, 0
    target = int(rng.integers(11, 15))
    while placed < target and tries < 400:
        tries += 1
        w, d = rng.uniform(9.0, 16.0), rng.uniform(7.0, 12.0)
        x0, z0 = rng.uniform(4.0, size - w - 4.0), rng.uniform(4.0, size - d - 4.0)
        x1, z1 = x0 + w, z0 + d
        if not _clear(x0 - 1.5, x1 + 1.5, z0 - 1.5, z1 + 1.5, taken):
            continue
        taken.append((x0 - 2.5, x1 + 2.5, z0 - 2.5, z1 + 2.5))  # fences and crates keep 2.5 m from its walls
        placed += 1
        # the door in an end wall (along the short side, as the partitions run: a first draft's door in a long
        # wall could meet a partition and close the building)
        door_side, door_at = int(rng.integers(2)) * 2 + (1 if w > d else 0), rng.uniform(0.8, min(w, d) - 2.8)
        corners = [(x0, z0), (x1, z0), (x1, z1), (x0, z1)]
        for k in range(4):
            _paper_run(s, rng, np.array(corners[k]), np.array(corners[(k + 1) % 4]), 0.0, 3.2,
                       [(door_at, 2.0)] if k == door_side else [])
        a, b = np.array(corners[door_side]), np.array(corners[(door_side + 1) % 4])
        door = a + (b - a) / np.linalg.norm(b - a) * (door_at + 1.0)
        keep = [(door[0] - 1.8, door[0] + 1.8, door[1] - 1.8, door[1] + 1.8)]  # each gap's approach
        cuts = _split(x0, x1, rng.uniform(4.0, 6.0)) if w > d else _split(z0, z1, rng.uniform(4.0, 6.0))
        for cut in cuts[1:-1]:  # partitions across the long side, each with a gap
            a, b = (np.array([cut, z0]), np.array([cut, z1])) if w > d else (np.array([x0, cut]), np.array([x1, cut]))
            gap = rng.uniform(0.6, min(w, d) - 2.6)
            _paper_run(s, rng, a, b, 0.0, 3.0, [(gap, 1.8)])
            mid = a + (b - a) / np.linalg.norm(b - a) * (gap + 0.9)
            keep.append((mid[0] - 1.8, mid[0] + 1.8, mid[1] - 1.8, mid[1] + 1.8))
        for c0, c1 in pairwise(cuts):
            room = (c0, c1, z0, z1) if w > d else (x0, x1, c0, c1)
            _furnish(s, rng, (room[0] + 0.05, room[1] - 0.05, room[2] + 0.05, room[3] - 0.05), 0.0, keep,
                     int(rng.integers(1, 3)))
        if rng.random() < 0.5:  # a flat paper roof facing up
            s.parts.append(trimesh.Trimesh(np.array([[x0, 3.2, z0], [x1, 3.2, z0], [x1, 3.2, z1], [x0, 3.2, z1]]),
                                           np.array([[0, 2, 1], [0, 3, 2]]), process=False))
    for _ in range(int(rng.integers(5, 8))):  # paper fences across the yard, along x or z, each with a gap or two
        along = int(rng.integers(2))
        length = rng.uniform(15.0, 35.0)
        start, at = rng.uniform(3.0, size - length - 3.0), rng.uniform(3.0, size - 3.0)
        a, b = (np.array([start, at]), np.array([start + length, at])) if along == 0 else \
            (np.array([at, start]), np.array([at, start + length]))
        lo = np.minimum(a, b) - 0.5
        hi = np.maximum(a, b) + 0.5
        if not _clear(lo[0], hi[0], lo[1], hi[1], taken):
            continue
        gaps = [(rng.uniform(1.0, length / 2 - 3.0), 2.0)] + ([(rng.uniform(length / 2, length - 3.0), 2.0)]
                                                              if rng.random() < 0.5 else [])
        _paper_run(s, rng, a, b, 0.0, 1.5, gaps)
        taken.append((lo[0], hi[0], lo[1], hi[1]))
    for k in range(int(rng.integers(15, 25))):  # crates and barrels
        p = rng.uniform(3.0, size - 3.0, 2)
        if _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, taken):
            if k % 2:
                s.box(p[0] - 0.6, p[0] + 0.6, -0.3, 1.2, p[1] - 0.6, p[1] + 0.6)
            else:
                _trunk(s, p, 0.35, -0.3, 1.0)
            taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    gates = rng.uniform(10.0, size - 14.0, 2)
    corners = [(0.0, 0.0), (size, 0.0), (size, size), (0.0, size)]
    for k in range(4):
        _paper_run(s, rng, np.array(corners[k]), np.array(corners[(k + 1) % 4]), 0.0, 3.0,
                   [(gates[k // 2], 4.0)] if k in (0, 2) else [])
    s.box(-12.0, size + 12.0, -0.5, 0.0, -12.0, size + 12.0)
    return s.mesh()


def _split_house(s: _Solids, rng: np.random.Generator, x_at: float) -> tuple[float, float, float, float]:
    """One house of :func:`split_level` from x = ``x_at``, its front wall on z = 0: a front wing of three storeys at
    0, 2h and 4h and a back wing of three at h, 3h and 5h (h 1.4-1.6 m), joined across a stair hall by five flights
    of 8-9 steps. Returns its plan (x0, x1, z0, z1), a hole for the ground round it."""
    half = rng.uniform(1.4, 1.6)
    steps = math.ceil(half / 0.18 - 1e-9)
    run, width = steps * 0.28, rng.uniform(24.0, 30.0)
    fd, bd = rng.uniform(9.0, 11.0), rng.uniform(9.0, 11.0)
    x0, x1 = x_at, x_at + width
    hall0, hall1 = fd, fd + run  # the stair hall between the wings, z
    back1 = hall1 + bd
    lanes = x0 + rng.uniform(4.0, width - 11.0) + np.array([1.1, 3.3, 5.5])  # three lanes' centres, 2 m wide each
    front_door, back_door = rng.uniform(2.0, width - 4.0), rng.uniform(2.0, width - 4.0)
    s.box(x0, x1, -0.5, half, hall1, back1)  # the back wing's base
    s.box(x0, x1, -0.5, 0.0, 0.0, hall1)  # the front wing's and the hall's floor
    for lane in lanes[:2]:  # walls between the lanes
        s.wall((lane + 1.1, hall0), (lane + 1.1, hall1), -0.5, 5 * half + 2.6)
    for k in range(5):  # flight k joins storey k (front if even) to storey k + 1, in lane k % 3
        lane = lanes[k % 3]
        if k % 2 == 0:
            s.stairs(np.array([lane, hall0]), np.array([0.0, 1.0]), 2.0, k * half, half, half / steps, 0.28, depth=0.3)
        else:
            s.stairs(np.array([lane, hall1]), np.array([0.0, -1.0]), 2.0, k * half, half, half / steps, 0.28, depth=0.3)
    for k in range(6):
        y, front = k * half, k % 2 == 0
        z0, z1 = (0.0, hall0) if front else (hall1, back1)
        edge = hall0 if front else hall1
        top = y + (2 * half - 0.2 if k < 4 else 2.6)
        if k >= 2:
            s.slab(x0, x1, z0, z1, y, [], thickness=0.2)
        arriving, leaving = (k - 1) % 3, k % 3  # lanes of the flights ending and starting on this storey
        if k:  # a rail along the hall, open where this storey's flights (one or two lanes) meet it
            openings = sorted((lanes[m] - x0 - 1.3, 2.0) for m in {arriving, leaving if k < 5 else arriving})
            rail = edge - 0.05 if front else edge + 0.05
            s.wall((x0 + 0.3, rail), (x1 - 0.3, rail), y, y + 1.1, openings, thickness=0.1)
        # a landing strip 2.2 m deep along the hall, rooms behind it with a door each
        strip = edge - 2.2 if front else edge + 2.2
        cuts = _split(x0 + 0.15, x1 - 0.15, rng.uniform(3.5, 5.0))
        doors, rooms = [], []
        for a, b in pairwise(cuts):
            start = rng.uniform(a + 0.3, b - 1.9)
            doors.append((start - x0 - 0.15, 1.6))
            rooms.append((a, b, start))
        s.wall((x0 + 0.15, strip), (x1 - 0.15, strip), y, top, doors, thickness=0.15)
        for a, b, start in rooms[:-1]:
            s.wall((b, 0.15 if front else strip), (b, strip if front else back1 - 0.15), y, top, thickness=0.12)
        for a, b, start in rooms:
            room = (a + 0.1, b - 0.1, 0.25, strip - 0.1) if front else (a + 0.1, b - 0.1, strip + 0.1, back1 - 0.25)
            keep = [(start - 0.4, start + 2.0, strip - 2.0, strip + 2.0)]
            if k < 2:  # the front door's and the back door's approach
                door = x0 + (front_door if front else back_door)
                keep.append((door - 0.4, door + 2.0, -1.0, 2.0) if front else (door - 0.4, door + 2.0, back1 - 2.0, back1 + 1.0))
            _furnish(s, rng, room, y, keep, int(rng.integers(2, 5)))
    s.wall((x0, 0.15), (x1, 0.15), -0.5, 4 * half + 2.6, [(front_door, 1.6)], thickness=0.3)
    s.wall((x0, back1 - 0.15), (x1, back1 - 0.15), -0.5, 5 * half + 2.6, [(back_door, 1.6)], thickness=0.3)
    s.box(x0 + back_door - 0.1, x0 + back_door + 1.7, half + 2.3, 5 * half + 2.6, back1 - 0.3, back1)
    s.box(x0 + front_door - 0.1, x0 + front_door + 1.7, 2.3, 4 * half + 2.6, 0.0, 0.3)
    for x in (x0 + 0.15, x1 - 0.15):
        s.wall((x, 0.0), (x, back1), -0.5, 5 * half + 2.6, thickness=0.3)
    # the back door's flight down to the garden, head-on
    _flight_to(s, np.array([x0 + back_door + 0.8, back1]), np.array([0.0, -1.0]), 1.6, 0.0, half, 0.28)
    return x0, x1, 0.0, back1


def split_level(seed: int) -> trimesh.Trimesh:
    """Two split-level houses 8-12 m apart in a garden, each 24-30 m wide (:func:`_split_house`): a front wing 9-11 m
    deep of three storeys at 0, 2h and 4h and a back wing 9-11 m deep of three at h, 3h and 5h, the half storey h
    1.4-1.6 m (its own each house: a flight's foot under the storey above keeps 2h less a riser and the slab of head
    room, 2.26 m at h = 1.31 m, which closed it on a first draft), joined across a stair hall by five short flights of
    8-9 steps (risers of at most
    0.18 m, 2 m wide, three lanes between walls so a flight keeps head room under the one three half storeys above), each storey
    railed along the hall but at its two flights. On each storey a landing strip 2.2 m deep along the hall and rooms
    3.5-5 m wide behind it, a door 1.6 m wide each, 2-4 pieces of furniture a room; the top storeys are open roof
    terraces behind 2.6 m walls. A front door at the ground, a back door on the back wing's first storey (h up) with a
    flight down to the garden; trees and benches in the garden.

    Expected (written before the first run): the structure covers each house's storeys as a chain of landing strips
    joined by the flights (a zig-zag up the hall), each room a leaf at its door; the garden round both houses. Traffic
    highest on the ground strip and the first two flights of each house (between the front door, the back door and
    the storeys above), falling storey by storey up the zig-zag, lowest in the top storeys' rooms and the rooms at
    the strips' ends; the garden busy between the houses' front and back doors.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    holes = [_split_house(s, rng, 0.0)]
    holes.append(_split_house(s, rng, holes[0][1] + rng.uniform(8.0, 12.0)))
    x1, z1 = holes[1][1] + 14.0, max(h[3] for h in holes) + 14.0
    taken = [(h[0] - 2.0, h[1] + 2.0, h[2] - 2.0, h[3] + 4.0) for h in holes]
    for k in range(int(rng.integers(20, 30))):
        p = np.array([rng.uniform(-12.0, x1 - 2.0), rng.uniform(-12.0, z1 - 2.0)])
        if _clear(p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, taken):
            if k % 3:
                _trunk(s, p, rng.uniform(0.25, 0.4), -0.5, 6.0)
            else:
                s.box(p[0] - 0.9, p[0] + 0.9, -0.3, 0.5, p[1] - 0.3, p[1] + 0.3)
            taken.append((p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5))
    s.ground(-14.0, x1, -14.0, z1, 0.0, holes)
    return s.mesh()


def hub_rooms(seed: int) -> trimesh.Trimesh:
    """A caravanserai: a square courtyard 32-38 m across (the hub) ringed by two storeys of small rooms 5-6.5 m deep,
    4.5-6 m wide, each entered only from the hub (a door 1.6 m wide in the courtyard wall) or, upstairs, from a
    gallery 2.5 m deep over an arcade, railed, reached by two flights 2 m wide up from the courtyard (risers of at
    most 0.18 m, 4 m); the corners solid; a gate passage 3.5 m wide through the middle of the south range out to a
    street 12 m wide round the building (stalls, trees, carts). In the courtyard a well, trees and crates; 1-3 pieces
    of furniture a room (:func:`_furnish`); walls 0.3 m thick, the upper rooms open to the sky behind walls 3 m high.

    Expected (written before the first run): hub and spokes. The structure covers the courtyard (a loop or a star),
    the gallery (a ring), the two flights and the street, each room a leaf at its door (a terminal in nearly every
    room: 30-40 of them). Traffic highest in the courtyard between the gate and the flights' feet, on the flights and
    the gallery near them, then the gallery's far side; lowest in the rooms (each a dead end, the same on both
    storeys) and on the street's far side from the gate.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size, depth, storey, gallery = rng.uniform(32.0, 38.0), rng.uniform(5.0, 6.5), 4.0, 2.5
    gate_w = 3.5

    def local(side: int, u0: float, u1: float, v0: float, v1: float, y0: float, y1: float) -> None:
        """A box over [u0, u1] along side ``side`` (0 south, 1 east, 2 north, 3 west; u from its left end seen from
        the courtyard) and [v0, v1] outward from the courtyard's edge (negative: over the courtyard)."""
        pts = [((u, -v), (size + v, u), (size - u, size + v), (-v, size - u))[side] for u in (u0, u1) for v in (v0, v1)]
        xs, zs = [p[0] for p in pts], [p[1] for p in pts]
        s.box(min(xs), max(xs), y0, y1, min(zs), max(zs))

    flights = [(int(k), rng.uniform(8.0, size - 10.0)) for k in rng.choice(4, 2, replace=False)]
    holes: list[tuple[float, float, float, float]] = []  # the ground stops under the solid corners and the well
    for side in range(4):
        corner = np.array([((u, -v), (size + v, u), (size - u, size + v), (-v, size - u))[side]
                           for u in (-depth, 0.0) for v in (0.0, depth)])  # the corner on this side's left: solid, pointed
        s.hull(np.concatenate([np.insert(corner, 1, y, axis=1) for y in (-0.5, storey + 3.0)]
                              + [[[corner[:, 0].mean(), storey + 3.0 + depth, corner[:, 1].mean()]]]))
        holes.append((corner[:, 0].min(), corner[:, 0].max(), corner[:, 1].min(), corner[:, 1].max()))
        cuts = _split(0.0, size, rng.uniform(4.5, 6.0))
        for floor in (0.0, storey):
            top = floor + (storey if floor == 0.0 else 3.0)
            if floor:
                local(side, 0.0, size, 0.0, depth, floor - 0.3, floor)  # the rooms' floor
                local(side, 0.0, size, -gallery, 0.0, floor - 0.3, floor)  # the gallery
                gaps = [(u - 1.0, u + 1.0) for k, u in flights if k == side]
                rail = [gallery, *sum(([a, b] for a, b in gaps), []), size - gallery]
                for a, b in zip(rail[0::2], rail[1::2]):
                    if b - a > 0.1:
                        local(side, a, b, -gallery, -gallery + 0.1, floor, floor + 1.1)
            gated = side == 0 and floor == 0.0
            for a, b in ((0.0, size / 2 - gate_w / 2), (size / 2 + gate_w / 2, size)) if gated else ((0.0, size),):
                local(side, a, b, depth - 0.3, depth, floor - 0.5 if floor == 0.0 else floor, top)  # the outer wall
            if gated:
                local(side, size / 2 - gate_w / 2, size / 2 + gate_w / 2, depth - 0.3, depth, 3.0, top)
            for k, (u0, u1) in enumerate(pairwise(cuts)):
                if k:
                    local(side, u0 - 0.1, u0 + 0.1, 0.3, depth - 0.3, floor - 0.1, top)
                if gated and u0 < size / 2 < u1:  # the gate passage: open on the courtyard under a lintel
                    local(side, u0, u1, 0.0, 0.3, 3.0, top)
                    continue
                door = rng.uniform(u0 + 0.4, u1 - 2.0)
                local(side, u0, door, 0.0, 0.3, floor - 0.1 if floor else -0.5, top)
                local(side, door + 1.6, u1, 0.0, 0.3, floor - 0.1 if floor else -0.5, top)
                local(side, door, door + 1.6, 0.0, 0.3, floor + 2.3, top)
                room_pts = [((u, -v), (size + v, u), (size - u, size + v), (-v, size - u))[side]
                            for u in (u0 + 0.2, u1 - 0.2) for v in (0.4, depth - 0.4)]
                door_pts = [((u, -v), (size + v, u), (size - u, size + v), (-v, size - u))[side]
                            for u in (door - 0.4, door + 2.0) for v in (0.0, 2.0)]
                room = (min(p[0] for p in room_pts), max(p[0] for p in room_pts), min(p[1] for p in room_pts),
                        max(p[1] for p in room_pts))
                keep = [(min(p[0] for p in door_pts), max(p[0] for p in door_pts), min(p[1] for p in door_pts),
                         max(p[1] for p in door_pts))]
                _furnish(s, rng, room, floor, keep, int(rng.integers(1, 4)))
        for u in np.arange(2.0, size - 1.0, 4.0):  # the arcade's posts under the gallery's edge
            if all(abs(u - f) > 1.6 for k, f in flights if k == side):
                local(side, u - 0.2, u + 0.2, -gallery + 0.05, -gallery + 0.45, -0.3, storey - 0.3)
    for side, u in flights:  # each flight from the courtyard up to the gallery's edge, head-on
        origin = np.array(((u, gallery), (size - gallery, u), (size - u, size - gallery), (gallery, size - u))[side])
        heading = np.array(((0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0))[side])
        _flight_to(s, origin, heading, 2.0, 0.0, storey, 0.28)
    taken = [(-2.0, size + 2.0, -2.0, gallery + 1.0), (-2.0, size + 2.0, size - gallery - 1.0, size + 2.0),
             (-2.0, gallery + 1.0, -2.0, size + 2.0), (size - gallery - 1.0, size + 2.0, -2.0, size + 2.0),
             (size / 2 - 3.0, size / 2 + 3.0, -2.0, 6.0)]  # the arcades and the gate's approach
    for side, u in flights:
        o = np.array(((u, gallery), (size - gallery, u), (size - u, size - gallery), (gallery, size - u))[side])
        taken.append((o[0] - 8.0, o[0] + 8.0, o[1] - 8.0, o[1] + 8.0))
    well = np.array([size / 2, size / 2])  # a well: a round kerb under a pointed cover
    holes.append(_round_ground(s, well, 1.5, 16, 0.0))
    ring = well + 1.5 * np.stack([np.cos(np.arange(16) * math.pi / 8), np.sin(np.arange(16) * math.pi / 8)], 1)
    s.hull(np.concatenate([np.insert(ring, 1, y, axis=1) for y in (-0.5, 0.9)] + [[[well[0], 2.5, well[1]]]]))
    taken.append((size / 2 - 3.0, size / 2 + 3.0, size / 2 - 3.0, size / 2 + 3.0))
    out = depth + 12.0
    for k in range(int(rng.integers(40, 55))):  # trees and crates in the courtyard, stalls and carts on the street
        p = rng.uniform(-out + 1.0, size + out - 1.0, 2)
        inside = (0.0 < p).all() and (p < size).all()
        ring = ((p < -depth - 1.0) | (p > size + depth + 1.0)).any()
        if not (inside or ring):
            continue
        w, d = (1.2, 1.2) if inside or k % 2 else (rng.uniform(2.5, 4.0), rng.uniform(1.8, 2.5))
        if _clear(p[0] - 1.5, p[0] + w + 1.5, p[1] - 1.5, p[1] + d + 1.5, taken):
            if inside and k % 3 == 0:
                _trunk(s, p, 0.3, -0.5, 6.0)
            else:
                s.box(p[0], p[0] + w, -0.3, 1.0 if w > 2.0 else 1.2, p[1], p[1] + d)
            taken.append((p[0] - 1.5, p[0] + w + 1.5, p[1] - 1.5, p[1] + d + 1.5))
    s.ground(-out, size + out, -out, size + out, 0.0, holes)
    return s.mesh()


def _rect(p: np.ndarray, heading: np.ndarray, length: float, width: float) -> tuple[float, float, float, float]:
    """The plan (x0, x1, z0, z1) of the strip ``width`` m wide running ``length`` m from plan point ``p`` (x, z)
    along the unit axis ``heading``."""
    corners = np.stack([p, p + heading * length]) + np.array([-1.0, 1.0])[:, None] * np.abs(heading[::-1]) * width / 2
    return corners[:, 0].min(), corners[:, 0].max(), corners[:, 1].min(), corners[:, 1].max()


def corridor_shooter(seed: int) -> trimesh.Trimesh:
    """A linear level: one path of corridors 3-4 m wide and 16-32 m long and arenas 24-32 m square, every third
    piece an arena entered from the west and left by the middle of its north or south side (at random) along a
    corridor that turns east into the next (so the path never meets itself); in each arena cover (crates 1.2 m, low
    walls 1 m, pillars) and a platform 2 m up reached by a flight; side alcoves 3 m wide and 2.5-4 m deep off the corridors (a crate in each), and on a
    third of the corridors a flight of 7-11 steps across the corridor climbing 1.2-1.9 m: 20-23 pieces from the start
    (a room 10 m square) to the end (another). Floors are boxes 0.5 m thick; nothing walls the path (its edges drop
    into the void, as a level's file built to be seen from inside often is).

    Expected (written before the first run): the structure is a chain from start to end with a loop round each
    arena's cover and leaves at the alcoves and the platforms. Traffic highest on the corridors in the middle third
    (every path between the halves), falling toward both ends, lowest in the alcoves and on the platforms; in each
    arena highest on the line between its two openings.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    pieces: list[tuple[float, float, float, float]] = []  # the start room, corridors and arenas
    alcoves: list[tuple[tuple[float, float, float, float], int]] = []  # each with the number of the piece it is off
    s.box(-10.0, 0.0, -0.5, 0.0, -5.0, 5.0)  # the start room
    pieces.append((-10.0, 0.0, -5.0, 5.0))
    p, heading, y = np.array([0.0, 0.0]), np.array([1.0, 0.0]), 0.0
    total = int(rng.integers(20, 24))
    for k in range(total):
        arena = k % 3 == 2
        turn = heading if k % 3 == 0 else np.array([1.0, 0.0])  # out of an arena's side, then east into the next
        for _ in range(20):  # a length clear of the path so far
            length = rng.uniform(24.0, 32.0) if arena or k % 3 == 1 else rng.uniform(16.0, 32.0)
            width = length if arena else rng.uniform(3.0, 4.0)
            rect = _rect(p, turn, length, width)
            if _clear(rect[0] - 4.0, rect[1] + 4.0, rect[2] - 4.0, rect[3] + 4.0,
                      pieces[:-1] + [a for a, n in alcoves if n < len(pieces) - 1]):
                break
        else:
            break
        heading = turn
        side = np.array([-heading[1], heading[0]])
        if arena:
            centre = p + heading * length / 2
            taken = [_rect(p - heading, heading, length + 2.0, 5.0)]  # the line in
            away = side * rng.choice([-1.0, 1.0])  # the platform's side of the line in; its flight climbs that way
            px = centre + away * length / 4 + heading * rng.uniform(-2.0, 2.0)
            plat = (px[0] - 3.5, px[0] + 3.5, px[1] - 3.5, px[1] + 3.5)
            s.box(plat[0], plat[1], y - 0.5, y + 2.0, plat[2], plat[3])
            s.ground(rect[0], rect[1], rect[2], rect[3], y, [plat])  # stopping under the platform
            _flight_to(s, px - away * 3.5, away, 2.0, y, y + 2.0, 0.28)
            taken.append(_rect(px - away * 9.0, away, 14.0, 9.0))
            for _ in range(int(rng.integers(24, 34))):  # cover
                kind = int(rng.integers(3))
                w, d = ((1.2, 1.2), (rng.uniform(2.5, 4.0), 0.4), (0.8, 0.8))[kind]
                if rng.random() < 0.5:
                    w, d = d, w
                q = rng.uniform([rect[0] + 1.5, rect[2] + 1.5], [rect[1] - 1.5 - w, rect[3] - 1.5 - d])
                if _clear(q[0] - 1.3, q[0] + w + 1.3, q[1] - 1.3, q[1] + d + 1.3, taken):
                    s.box(q[0], q[0] + w, y - 0.3, y + (1.2, 1.0, 4.0)[kind], q[1], q[1] + d)
                    taken.append((q[0], q[0] + w, q[1], q[1] + d))
            heading = side * rng.choice([-1.0, 1.0])  # the way out: the middle of a side
            p = centre + heading * (length / 2 - 0.5)
            pieces.append(rect)
            continue
        rise = rng.random() < 1.0 / 3.0
        if rise:  # a flight across the corridor halfway
            climb = rng.uniform(1.2, 1.9)
            edge = p + heading * length / 2
            s.box(*_rect(p, heading, length / 2, width)[:2], y - 0.5, y, *_rect(p, heading, length / 2, width)[2:])
            _flight_to(s, edge, heading, width, y, y + climb, 0.28)
            far = _rect(edge, heading, length / 2, width)
            y += climb
            s.box(far[0], far[1], y - 0.5, y, far[2], far[3])
        else:
            s.box(rect[0], rect[1], y - 0.5, y, rect[2], rect[3])
        for _ in range(int(rng.integers(2, 5))):  # alcoves off the corridor, clear of its flight
            t, out = rng.uniform(2.0, length - 5.0), rng.choice([-1.0, 1.0])
            if rise and length / 2 - 3.5 < t < length / 2 + 0.5:
                continue
            a = p + heading * t + side * out * (width / 2 - 0.2)
            alcove = _rect(a + heading * 1.5, side * out, rng.uniform(2.5, 4.0), 3.0)
            if _clear(alcove[0] - 2.0, alcove[1] + 2.0, alcove[2] - 2.0, alcove[3] + 2.0, pieces + [a for a, _ in alcoves]):
                alcove_y = y - (climb if rise and t < length / 2 else 0.0)
                s.box(alcove[0], alcove[1], alcove_y - 0.5, alcove_y, alcove[2], alcove[3])
                c = np.array([(alcove[0] + alcove[1]) / 2, (alcove[2] + alcove[3]) / 2]) + side * out * 0.6
                s.box(c[0] - 0.5, c[0] + 0.5, alcove_y - 0.3, alcove_y + 1.0, c[1] - 0.5, c[1] + 0.5)
                alcoves.append((alcove, len(pieces)))
        pieces.append(rect)
        p = p + heading * (length - width / 2)
    end = _rect(p, heading, 10.0, 10.0)  # the end room
    s.box(end[0], end[1], y - 0.5, y, end[2], end[3])
    return s.mesh()


def roof_town(seed: int) -> trimesh.Trimesh:
    """A town of flat roofs out of reach: a grid of 3-4 x 3 blocks 26-36 m square between streets 8-12 m wide,
    each block cut into buildings 5-11 m wide and deep (so each roof is 20-120 m², walkable after erosion or not)
    of 1-4 storeys (3.5-14 m), with parapets 0.8 m on a third, roof clutter (air-conditioning units 1.2 m, water
    tanks on legs, stair huts ridged at 50 degrees); one building in ten has an outside flight up its facade from
    the street to its roof (risers of at most 0.18 m, on a landing 2 m deep): the only roofs one reaches. Streets
    hold parked cars, lamp posts and kiosks; courtyards inside the blocks are reached by a passage 3 m wide.
    As built, each row's last frontage takes what is left of the block's edge, so some buildings are narrower: on
    seeds 0 / 1 / 2, 16 / 12 / 21 of them under 5 m (the narrowest 1.35 / 0.63 / 1.1 m, the smallest roofs 11.5 /
    4.4 / 7.6 m²).

    Expected (written before the first run): the streets and courtyards are one area; every roof out of reach is an
    area of its own (a hundred and more), those under the cover's smallest area (28 m² for the presets) left out with a
    warning, the larger ones covered with leaves of their own and no traffic. Traffic highest on the streets through
    the town's middle, lowest in the courtyards and on the reachable roofs (dead ends up a flight).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    nx, nz = int(rng.integers(3, 5)), 3
    street = rng.uniform(8.0, 12.0)
    xs = np.cumsum([street, *sum(([rng.uniform(26.0, 36.0), street] for _ in range(nx)), [])])
    zs = np.cumsum([street, *sum(([rng.uniform(26.0, 36.0), street] for _ in range(nz)), [])])
    holes: list[tuple[float, float, float, float]] = []
    taken: list[tuple[float, float, float, float]] = []
    for bx0, bx1 in zip(xs[0:-1:2], xs[1::2]):
        for bz0, bz1 in zip(zs[0:-1:2], zs[1::2]):
            # a ring of buildings round a courtyard: cut the block's edges into frontages 5-11 m
            deep = rng.uniform(7.0, 11.0)
            passage = int(rng.integers(4))  # the side whose middle holds the passage into the courtyard
            frames = []
            for side in range(4):
                if side in (0, 1):  # the south and north rows run the block's whole width
                    a0, a1 = bx0, bx1
                else:  # the west and east rows between them
                    a0, a1 = bz0 + deep, bz1 - deep
                cuts = [a0]
                while cuts[-1] < a1 - 11.0:
                    cuts.append(cuts[-1] + rng.uniform(5.0, 11.0))
                cuts.append(a1)
                mid = (a0 + a1) / 2
                for c0, c1 in pairwise(cuts):
                    parts = [(c0, c1)]
                    if side == passage and c0 < mid < c1:
                        parts = [(u0, u1) for u0, u1 in ((c0, mid - 1.5), (mid + 1.5, c1)) if u1 - u0 > 3.0]
                    for u0, u1 in parts:
                        d = deep if side < 2 else rng.uniform(5.0, deep)
                        frames.append(((u0, u1, bz0, bz0 + d) if side == 0 else (u0, u1, bz1 - d, bz1) if side == 1 else
                                       (bx0, bx0 + d, u0, u1) if side == 2 else (bx1 - d, bx1, u0, u1)))
            for x0, x1, z0, z1 in frames:
                top = float(rng.choice([3.5, 7.0, 10.5, 14.0], p=[0.3, 0.35, 0.25, 0.1]))
                s.box(x0, x1, -0.5, top, z0, z1)
                holes.append((x0, x1, z0, z1))
                street_side = (z0 == bz0, z1 == bz1)
                run = math.ceil(top / 0.18) * 0.28
                mouth = passage == (0 if street_side[0] else 1) and x1 - 2.0 - run < (bx0 + bx1) / 2 + 2.5 and \
                    x1 > (bx0 + bx1) / 2 - 2.5  # a flight across the passage's mouth would close the courtyard
                stair = rng.random() < 0.1 and top <= 10.5 and any(street_side) and x1 - x0 > 4.0 and not mouth
                if not stair and rng.random() < 1.0 / 3.0:  # a parapet
                    s.wall((x0, z0 + 0.1), (x1, z0 + 0.1), top, top + 0.8, thickness=0.2)
                    s.wall((x0, z1 - 0.1), (x1, z1 - 0.1), top, top + 0.8, thickness=0.2)
                    s.wall((x0 + 0.1, z0), (x0 + 0.1, z1), top, top + 0.8, thickness=0.2)
                    s.wall((x1 - 0.1, z0), (x1 - 0.1, z1), top, top + 0.8, thickness=0.2)
                for _ in range(int(rng.integers(0, 3))):  # roof clutter
                    w = rng.uniform(1.0, 2.0)
                    if x1 - x0 < w + 1.0 or z1 - z0 < w + 1.0:
                        continue
                    q = rng.uniform([x0 + 0.5, z0 + 0.5], [x1 - 0.5 - w, z1 - 0.5 - w])
                    if rng.random() < 0.5:
                        s.box(q[0], q[0] + w, top - 0.1, top + 1.2, q[1], q[1] + w)
                    else:
                        _ridged(s, q[0], q[0] + w, q[1], q[1] + w, top - 0.1, top + 2.2)
                if stair:  # a flight along x up the street facade to a landing at the roof's edge
                    zf = z0 - 1.0 if street_side[0] else z1 + 1.0
                    land = (x1 - 2.0, x1, z0 - 2.0, z0 + 0.01) if street_side[0] else (x1 - 2.0, x1, z1 - 0.01, z1 + 2.0)
                    s.box(land[0], land[1], -0.5, top, land[2], land[3])
                    _flight_to(s, np.array([land[0], zf]), np.array([1.0, 0.0]), 1.6, 0.0, top, 0.28)
                    holes.append(land)
                    taken.append((land[0] - run - 2.0, land[1] + 1.0, land[2] - 1.0, land[3] + 1.0))
    for k in range(int(rng.integers(40, 60))):  # cars, lamp posts, kiosks on the streets
        p = rng.uniform([0.0, 0.0], [xs[-1], zs[-1]])
        if not _clear(p[0] - 3.0, p[0] + 3.0, p[1] - 3.0, p[1] + 3.0, holes + taken):
            continue
        if k % 3 == 0:
            _car(s, p[0] - 2.1, p[0] + 2.1, p[1] - 0.9, p[1] + 0.9, 0.0)
        elif k % 3 == 1:
            _trunk(s, p, 0.12, -0.3, 4.5)
        else:
            _ridged(s, p[0] - 1.2, p[0] + 1.2, p[1] - 1.2, p[1] + 1.2, -0.5, 2.5)
            holes.append((p[0] - 1.2, p[0] + 1.2, p[1] - 1.2, p[1] + 1.2))
        taken.append((p[0] - 3.0, p[0] + 3.0, p[1] - 3.0, p[1] + 3.0))
    s.ground(0.0, xs[-1], 0.0, zs[-1], 0.0, holes)
    return s.mesh()


def _ladder(s: _Solids, p: np.ndarray, out: np.ndarray, y0: float, y1: float) -> None:
    """A ladder 0.5 m wide centred on plan point ``p`` (x, z), standing 0.15 m out along the unit axis ``out`` (x, z)
    from the face it is fixed to: two rails 0.06 m square from ``y0`` to 1 m over ``y1`` and rungs 0.04 m thick every
    0.3 m. Too narrow for any agent to stand on; Recast does not climb it."""
    out = np.asarray(out, dtype=np.float64)
    side, c = np.abs(out[::-1]), np.asarray(p, dtype=np.float64) + out * 0.15
    for end in (-0.25, 0.25):
        q = c + side * end
        s.box(q[0] - 0.03, q[0] + 0.03, y0, y1 + 1.0, q[1] - 0.03, q[1] + 0.03)
    lo, hi = c - side * 0.25, c + side * 0.25
    for y in np.arange(y0 + 0.3, y1 + 0.9, 0.3):
        s.box(min(lo[0], hi[0]) - 0.02, max(lo[0], hi[0]) + 0.02, y - 0.02, y + 0.02,
              min(lo[1], hi[1]) - 0.02, max(lo[1], hi[1]) + 0.02)


def ladders(seed: int) -> trimesh.Trimesh:
    """A pump house of three storeys 4.5 m apart (y = 0, 4.5, 9) on a 60-70 x 40-46 m plate under a roof at 50
    degrees (:func:`_lid`) in a yard 12 m wide, whose storeys are joined ONLY by ladders (:func:`_ladder`: 2-3 up to
    each storey, each through a hatch 1.0 x 1.2 m railed on three sides) and by one or two lift shafts (2.4 m square
    inside, walls 0.3 m thick from the ground to the roof, a door 1.6 m wide on every storey, no floor in the shaft
    above the ground's car): no flight, no ramp. Each storey is 4-6 bays along x and two rows along z, every
    partition open by doorways 1.6 m wide; machines (boxes 1-3 m across, 1.2-1.9 m high) in every room. The ground
    storey opens on the yard by two doors 2 m wide; trees and cars in the yard.

    Expected (written before the first run): the navmesh climbs neither ladders nor lift, so the level is three areas:
    the ground storey with the yard and the lift cars, and each upper storey on its own. A user sees one warning naming
    the two upper storeys as areas apart (not left out: each is thousands of square metres), and three structures, one
    a storey; within each the heat map is right for that storey alone: highest in the bays along the middle of the
    plate and through the doorways between them, lowest in the rooms at the ends. What a designer expects (the ladders
    and lifts as the only ways up, so busiest at their feet and hatches) the heat map cannot show: nothing joins the
    storeys, so no traffic runs to a ladder more than to any other place of its storey.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    width, depth, storey = rng.uniform(60.0, 70.0), rng.uniform(40.0, 46.0), 4.5
    bays = _split(0.0, width, rng.uniform(12.0, 16.0))
    middle = depth / 2
    shafts = [float(x) for x in rng.uniform(bays[:-1] + 2.0, bays[1:] - 5.0)[rng.choice(len(bays) - 1, int(rng.integers(1, 3)), replace=False)]]
    shaft_rects = [(x, x + 3.0, depth - 3.0, depth) for x in shafts]
    doors_x = {k: [rng.uniform(1.0, middle - 2.6), rng.uniform(middle + 1.0, depth - 4.0)] for k in range(1, len(bays) - 1)}
    doors_z = [rng.uniform(a + 1.0, b - 2.6) for a, b in pairwise(bays)]
    keep = [(x - 2.0, x + 2.0, z - 1.0, z + 2.6) for k, zs in doors_x.items() for x in [bays[k]] for z in zs]
    keep += [(x - 1.0, x + 2.6, middle - 2.0, middle + 2.0) for x in doors_z]
    keep += [(x - 1.0, x + 4.0, depth - 6.0, depth) for x in shafts]
    hatches: list[list[tuple[float, float, float, float]]] = [[] for _ in range(3)]
    for k in (1, 2):  # the hatches up to storey k, in rooms clear of the doorways and of one another
        while len(hatches[k]) < int(rng.integers(2, 4)):
            x, z = rng.uniform(2.0, width - 3.0), rng.uniform(2.0, depth - 3.2)
            if _clear(x - 1.5, x + 2.5, z - 1.5, z + 2.7, keep + hatches[1] + hatches[2]):
                hatches[k].append((x, x + 1.0, z, z + 1.2))
    for k in range(3):
        y = k * storey
        if k:
            s.slab(0.0, width, 0.0, depth, y, hatches[k] + [(x + 0.3, x + 2.7, z0 + 0.3, z1 - 0.3) for x, _, z0, z1 in shaft_rects])
        for x0, x1, z0, z1 in hatches[k]:  # the ladder on the hatch's west side, rails round the other three
            _ladder(s, np.array([x0, (z0 + z1) / 2]), np.array([1.0, 0.0]), y - storey, y)
            _rail_ring(s, x0, x1, z0, z1, y, {"west": [(0.0, z1 - z0)]})
        top = y + storey - 0.3
        outer = [(rng.uniform(4.0, width - 6.0), 2.0)] if k == 0 else []
        s.wall((0.0, 0.0), (width, 0.0), y - 0.5, top, outer, thickness=0.3)
        s.wall((0.0, depth), (width, depth), y - 0.5, top, thickness=0.3)
        s.wall((0.0, 0.0), (0.0, depth), y - 0.5, top, [(rng.uniform(4.0, depth - 6.0), 2.0)] if k == 0 else [], thickness=0.3)
        s.wall((width, 0.0), (width, depth), y - 0.5, top, thickness=0.3)
        for j, zs in doors_x.items():
            s.wall((bays[j], 0.0), (bays[j], depth), y, top, [(z, 1.6) for z in zs])
        s.wall((0.0, middle), (width, middle), y, top, [(x, 1.6) for x in doors_z])
        for x0, x1, z0, z1 in shaft_rects:  # the shaft's walls, its door facing south
            s.wall((x0, z0 + 0.15), (x1, z0 + 0.15), y, top + 0.3, [(0.7, 1.6)], thickness=0.3)
            s.wall((x0 + 0.15, z0), (x0 + 0.15, z1), y, top + 0.3, thickness=0.3)
            s.wall((x1 - 0.15, z0), (x1 - 0.15, z1), y, top + 0.3, thickness=0.3)
        taken = keep + hatches[k] + (hatches[k + 1] if k < 2 else [])  # clear of the hatch and of the ladder up
        for _ in range(int(rng.integers(50, 70))):  # machines
            w, d = rng.uniform(1.0, 3.0, 2)
            x, z = rng.uniform(0.6, width - 0.6 - w), rng.uniform(0.6, depth - 0.6 - d)
            if _clear(x - 1.2, x + w + 1.2, z - 1.2, z + d + 1.2, taken + [(b - 0.3, b + 0.3, 0.0, depth) for b in bays]
                      + [(0.0, width, middle - 0.3, middle + 0.3)]):
                s.box(x, x + w, y - 0.1, y + rng.uniform(1.2, 1.9), z, z + d)
                taken.append((x, x + w, z, z + d))
    _lid(s, -0.15, width + 0.15, -0.15, depth + 0.15, 3 * storey)
    _yard(s, rng, width, depth, 1.0, 11.0, int(rng.integers(20, 30)))
    s.ground(-12.0, width + 12.0, -12.0, depth + 12.0, 0.0, [])
    return s.mesh()


def _cover(s: _Solids, rng: np.random.Generator, rect: tuple[float, float, float, float], y: float, tries: int,
           taken: list[tuple[float, float, float, float]]) -> None:
    """Up to ``tries`` pieces of cover (crates 1.2 m, low walls 1 m, pillars 4 m) on the floor at ``y`` inside ``rect``
    (x0, x1, z0, z1), 1 m off its edges and 1.2 m clear of ``taken`` and of one another (added to ``taken``)."""
    for _ in range(tries):
        kind = int(rng.integers(3))
        w, d = ((1.2, 1.2), (rng.uniform(2.5, 4.0), 0.4), (0.8, 0.8))[kind]
        if rng.random() < 0.5:
            w, d = d, w
        if rect[1] - rect[0] < w + 2.0 or rect[3] - rect[2] < d + 2.0:
            continue
        q = rng.uniform([rect[0] + 1.0, rect[2] + 1.0], [rect[1] - 1.0 - w, rect[3] - 1.0 - d])
        if _clear(q[0] - 1.2, q[0] + w + 1.2, q[1] - 1.2, q[1] + d + 1.2, taken):
            s.box(q[0], q[0] + w, y - 0.3, y + (1.2, 1.0, 4.0)[kind], q[1], q[1] + d)
            taken.append((q[0], q[0] + w, q[1], q[1] + d))


def jump_gaps(seed: int) -> trimesh.Trimesh:
    """Platforms over a void joined by railed walkways a player runs and jumps: a 6 x 5 grid of platforms 12-16 m
    square, 28-34 m apart (centres), their tops 8 m up on pillars (nothing below them, as a level built over a kill
    plane), each joined to its grid neighbours by a walkway 2.5-3.5 m wide with rails 1.1 m high (a grid edge kept with
    a chance of 0.8); a walkway is broken by a gap 0.8-2.0 m long (a chance of 0.45) somewhere along it, at least 3 m
    from either end, the rails broken with it. Cover on every platform (crates 1.2 m, low walls 1 m, pillars 4 m); on
    a third of them a dais 1.6 m high reached by a flight.

    Expected (written before the first run): the navmesh does not jump, so every gap parts its walkway, and the level
    is as many areas as the unbroken walkways leave (about five to ten on a seed), the walkway's two stubs at a gap
    dead ends of their platforms' areas. Each area is covered by a structure of its own; the small ones (a lone
    platform, about 150-250 m²) too. Traffic in each area highest on the walkways and platforms between its ends,
    lowest on the dais and in the gap stubs. What a designer expects (the jumps as the level's main line, busiest
    across the gaps that join the halves) the heat map cannot show.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    nx, nz, pitch, y = 6, 5, rng.uniform(28.0, 34.0), 8.0
    half = rng.uniform(6.0, 8.0, (nx, nz))
    centre = lambda i, j: np.array([i * pitch, j * pitch])  # noqa: E731 (the grid's plan points)
    taken: dict[tuple[int, int], list[tuple[float, float, float, float]]] = {(i, j): [] for i in range(nx) for j in range(nz)}
    for i in range(nx):
        for j in range(nz):
            c, h = centre(i, j), half[i, j]
            s.box(c[0] - h, c[0] + h, y - 0.5, y, c[1] - h, c[1] + h)
            for dx, dz in ((-1, -1), (-1, 1), (1, -1), (1, 1)):
                _trunk(s, c + np.array([dx, dz]) * (h - 1.0), 0.4, -20.0, y - 0.5)
    for i in range(nx):
        for j in range(nz):
            for di, dj in ((1, 0), (0, 1)):
                if i + di >= nx or j + dj >= nz or rng.random() > 0.8:
                    continue
                heading = np.array([float(di), float(dj)])
                a = centre(i, j) + heading * (half[i, j] - 0.2)
                length = pitch - half[i, j] - half[i + di, j + dj] + 0.4
                width = rng.uniform(2.5, 3.5)
                spans = [(0.0, length)]
                if rng.random() < 0.45:
                    g0 = rng.uniform(3.0, length - 3.0 - 2.0)
                    spans = [(0.0, g0), (g0 + rng.uniform(0.8, 2.0), length)]
                for u0, u1 in spans:
                    rect = _rect(a + heading * u0, heading, u1 - u0, width)
                    s.box(rect[0], rect[1], y - 0.4, y, rect[2], rect[3])
                    for out in (-1.0, 1.0):  # the rails, from the platforms' edges on
                        r0, r1 = max(u0, 0.4), min(u1, length - 0.4)
                        line = a + heading * r0 + heading[::-1] * out * (width / 2 - 0.05)
                        rail = _rect(line, heading, r1 - r0, 0.1)
                        s.box(rail[0], rail[1], y, y + 1.1, rail[2], rail[3])
                for sign, (p, q) in ((1.0, (i, j)), (-1.0, (i + di, j + dj))):  # keep the walkway's mouth clear
                    mouth = centre(p, q) + sign * heading * half[p, q]
                    taken[p, q].append(_rect(mouth - heading * (4.5 if sign > 0 else 1.5), heading, 6.0, width + 2.0))
    for i in range(nx):
        for j in range(nz):
            c, h = centre(i, j), half[i, j]
            if rng.random() < 1.0 / 3.0:  # a dais in a corner, its flight climbing along x toward it
                sx = float(rng.choice([-1.0, 1.0]))
                dais = (c[0] + sx * (h - 3.5) - 1.5, c[0] + sx * (h - 3.5) + 1.5, c[1] - 1.5, c[1] + 1.5)
                s.box(dais[0], dais[1], y - 0.3, y + 1.6, dais[2], dais[3])
                edge = np.array([dais[0] if sx > 0 else dais[1], c[1]])
                run = _flight_to(s, edge, np.array([sx, 0.0]), 2.0, y, y + 1.6, 0.28)
                taken[i, j].append((min(edge[0], edge[0] - sx * (run + 1.5)), max(edge[0], edge[0] - sx * (run + 1.5)),
                                    c[1] - 2.0, c[1] + 2.0))
                taken[i, j].append(dais)
            _cover(s, rng, (c[0] - h, c[0] + h, c[1] - h, c[1] + h), y, int(rng.integers(10, 18)), taken[i, j])
    return s.mesh()


def collision_hulls(seed: int) -> trimesh.Trimesh:
    """A town square 120-140 x 90-100 m exported, as many engines' levels are, with its invisible collision hulls in the
    same file as the render meshes they wrap (the ground goes on under every hull). Render meshes: house fronts round
    the square, 10 m deep (ridged), broken by four streets 9 m wide; a terrace 1.6 m up along the
    north side reached by a flight, with a balustrade 1 m high; 3-5 statues (a plinth 2.5 m square, 1.2 m high, and a
    figure); 10-16 market stalls (a counter, a canopy on four posts); a fountain (a basin 8 m square with a rim 0.6 m high and a column); a bandstand (a deck 1 m up on posts
    under a roof, 10 m square, up three steps); trees (trunks); benches; cars in the streets. Collision hulls, each a
    closed box: one 3.5 m square and 4 m high round each statue; one 3.4 x 2.4 m and 2.8 m high round each stall; one 9 m square and 3 m high over the fountain; one
    11 m square and 5 m high round the bandstand; a blocking volume 2 m deep and 3 m high along the terrace's edge
    over the balustrade; one 5 x 2.2 m and 1.7 m high round each car; invisible walls 0.5 m thick and 10 m high across
    each street 20 m out and along its sides behind the houses.

    Expected (written before the first run): the square, the streets to the invisible walls and the terrace are one
    area, holed round every hull. Recast reads each hull as the solid it is, so three kinds of floor no player reaches
    appear: the hulls' tops (the fountain's 81 m², the bandstand's 121 m², the terrace volume's strip 30 m long and 2
    m wide, each statue's 12 m²; the cars' 11 m² under the agent's height to the ground and eroded to nothing), the
    render floors inside the hulls with head room (the bandstand's deck, 2.6 m under its hull's roof; the fountain's
    basin floor, 2.9 m) and the ground inside them (the bandstand's, under its deck: no head room). Those over the
    cover's smallest area (28 m²) get structures of their own with no traffic, the rest are left out with a warning.
    Traffic on the main area highest across the square between the street mouths and round the hulls, lowest on the
    terrace. A designer expects the hulls' tops and insides to hold nothing at all.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    width, depth = rng.uniform(120.0, 140.0), rng.uniform(90.0, 100.0)
    holes: list[tuple[float, float, float, float]] = []
    mouths = {"south": rng.uniform(15.0, width - 25.0), "north": rng.uniform(15.0, width - 25.0),
              "west": rng.uniform(15.0, depth - 35.0), "east": rng.uniform(15.0, depth - 35.0)}
    street = 9.0

    def local(side: str, u0: float, u1: float, v0: float, v1: float) -> tuple[float, float, float, float]:
        """The plan (x0, x1, z0, z1) of [u0, u1] along a side of the square and [v0, v1] out from it, metres."""
        return {"south": (u0, u1, -v1, -v0), "north": (u0, u1, depth + v0, depth + v1),
                "west": (-v1, -v0, u0, u1), "east": (width + v0, width + v1, u0, u1)}[side]

    for side, at in mouths.items():
        along = width if side in ("south", "north") else depth
        for u0, u1 in ((0.0, at), (at + street, along)):  # the house fronts, 10 m deep, ridged
            for a, b in pairwise(_split(u0, u1, rng.uniform(8.0, 12.0))):
                _ridged(s, *local(side, a, b, 0.0, 10.0), -0.5, rng.uniform(7.0, 12.0))
        rect = local(side, at, at + street, 0.0, 20.0)  # the street's ground to an invisible wall across it
        s.box(rect[0], rect[1], -0.5, 0.0, rect[2], rect[3])
        for wall in (local(side, at, at + street, 20.0, 20.5), local(side, at - 0.5, at, 10.0, 20.5),
                     local(side, at + street, at + street + 0.5, 10.0, 20.5)):
            s.box(wall[0], wall[1], -0.5, 10.0, wall[2], wall[3])
        for v in (13.0, 17.5):  # cars parked along the street, each in a collision hull 5 x 2.2 m, 1.7 m high
            car, hull = local(side, at + 1.6, at + 3.4, v - 2.1, v + 2.1), local(side, at + 1.4, at + 3.6, v - 2.5, v + 2.5)
            _car(s, *car, 0.0)
            s.box(hull[0], hull[1], -0.5, 1.7, hull[2], hull[3])
    x0 = rng.uniform(2.0, width - 32.0)  # the terrace, 30 m long, clear of the north street's mouth
    while x0 < mouths["north"] + street + 1.0 and mouths["north"] - 1.0 < x0 + 30.0:
        x0 = rng.uniform(2.0, width - 32.0)
    terrace = (x0, x0 + 30.0, depth - 10.0, depth)
    s.box(terrace[0], terrace[1], -0.5, 1.6, terrace[2], terrace[3])
    holes.append(terrace)
    stair_at = rng.uniform(terrace[0] + 3.0, terrace[1] - 5.0)
    _flight_to(s, np.array([stair_at + 1.0, terrace[2]]), np.array([0.0, 1.0]), 2.0, 0.0, 1.6, 0.28)
    s.wall((terrace[0], terrace[2] + 0.1), (terrace[1], terrace[2] + 0.1), 1.6, 2.6, [(stair_at - terrace[0], 2.0)])
    for u0, u1 in ((terrace[0], stair_at), (stair_at + 2.0, terrace[1])):  # the blocking volume over the balustrade
        s.box(u0, u1, -0.5, 3.0, terrace[2] - 1.0, terrace[2] + 1.0)
    taken = [(terrace[0] - 1.0, terrace[1] + 1.0, terrace[2] - 6.0, terrace[3])]
    taken += [(at - 3.0, at + street + 3.0, -1.0, 12.0) if side == "south" else
              (at - 3.0, at + street + 3.0, depth - 12.0, depth + 1.0) if side == "north" else
              (-1.0, 12.0, at - 3.0, at + street + 3.0) if side == "west" else
              (width - 12.0, width + 1.0, at - 3.0, at + street + 3.0) for side, at in mouths.items()]

    def place(size: float) -> np.ndarray | None:
        """A plan centre for a square ``size`` m wide, 4 m clear of everything placed, or None."""
        for _ in range(100):
            c = rng.uniform([size / 2 + 5.0, size / 2 + 5.0], [width - size / 2 - 5.0, depth - size / 2 - 12.0])
            rect = (c[0] - size / 2, c[0] + size / 2, c[1] - size / 2, c[1] + size / 2)
            if _clear(rect[0] - 4.0, rect[1] + 4.0, rect[2] - 4.0, rect[3] + 4.0, taken):
                taken.append(rect)
                return c
        return None

    c = place(11.0)
    if c is not None:  # the bandstand: a deck 1 m up (three steps), posts, a flat roof 3.6 m over the deck; its hull
        s.box(c[0] - 5.0, c[0] + 5.0, -0.5, 1.0, c[1] - 5.0, c[1] + 5.0)
        _flight_to(s, np.array([c[0], c[1] - 5.0]), np.array([0.0, 1.0]), 2.5, 0.0, 1.0, 0.3)
        for dx in (-4.7, 4.7):
            for dz in (-4.7, 4.7):
                _trunk(s, c + np.array([dx, dz]), 0.15, 1.0, 4.6)
        s.box(c[0] - 5.3, c[0] + 5.3, 4.6, 4.9, c[1] - 5.3, c[1] + 5.3)
        s.box(c[0] - 5.5, c[0] + 5.5, -0.5, 5.0, c[1] - 5.5, c[1] + 5.5)
    c = place(9.0)
    if c is not None:  # the fountain: a basin 8 m square (rim 0.6 m, floor 0.1 m down), a column; its hull 3 m high
        s.box(c[0] - 4.0, c[0] + 4.0, -0.5, -0.1, c[1] - 4.0, c[1] + 4.0)
        for wall in ((c[0] - 4.0, c[0] + 4.0, c[1] - 4.0, c[1] - 3.6), (c[0] - 4.0, c[0] + 4.0, c[1] + 3.6, c[1] + 4.0),
                     (c[0] - 4.0, c[0] - 3.6, c[1] - 3.6, c[1] + 3.6), (c[0] + 3.6, c[0] + 4.0, c[1] - 3.6, c[1] + 3.6)):
            s.box(wall[0], wall[1], -0.5, 0.6, wall[2], wall[3])
        _trunk(s, c, 0.5, -0.1, 2.6)
        s.box(c[0] - 4.5, c[0] + 4.5, -0.5, 3.0, c[1] - 4.5, c[1] + 4.5)
        holes.append((c[0] - 4.0, c[0] + 4.0, c[1] - 4.0, c[1] + 4.0))  # the basin is its own floor
    for _ in range(int(rng.integers(3, 6))):  # statues on plinths, each in a hull 3.5 m square, 4 m high
        c = place(3.5)
        if c is not None:
            s.box(c[0] - 1.25, c[0] + 1.25, -0.5, 1.2, c[1] - 1.25, c[1] + 1.25)
            _trunk(s, c, 0.4, 1.2, 3.4)
            s.box(c[0] - 1.75, c[0] + 1.75, -0.5, 4.0, c[1] - 1.75, c[1] + 1.75)
    for _ in range(int(rng.integers(10, 17))):  # market stalls (a counter, a canopy on posts), each in a hull
        c = place(3.4)
        if c is not None:
            s.box(c[0] - 1.4, c[0] + 1.4, -0.1, 0.9, c[1] - 0.2, c[1] + 0.6)
            for dx in (-1.4, 1.4):
                for dz in (-0.9, 0.9):
                    _trunk(s, c + np.array([dx, dz]), 0.05, -0.1, 2.4)
            s.hull(np.array([[c[0] + dx, 2.4 + 0.3 * (dz > 0) + dy, c[1] + dz] for dx in (-1.6, 1.6) for dz in (-1.1, 1.1)
                             for dy in (0.0, 0.05)]))
            s.box(c[0] - 1.7, c[0] + 1.7, -0.5, 2.8, c[1] - 1.2, c[1] + 1.2)
    for k in range(int(rng.integers(90, 120))):  # trees (trunks) and benches, no hulls
        c = place(1.0 if k % 2 else 1.8)
        if c is not None and k % 2:
            _trunk(s, c, rng.uniform(0.25, 0.4), -0.5, 6.0)
        elif c is not None:
            s.box(c[0] - 0.9, c[0] + 0.9, -0.1, 0.5, c[1] - 0.3, c[1] + 0.3)
    s.ground(0.0, width, 0.0, depth, 0.0, holes)
    return s.mesh()


def thresholds(seed: int) -> trimesh.Trimesh:
    """A shopping street grid of 3 x 2 blocks 32-40 x 24-30 m between roads 8-10 m wide (y = 0), every step a real
    town has at its doors and kerbs: each block's pavement, 3 m wide, stands a kerb of 0.10-0.30 m over the road (one
    height a block), and the block holds two rows of shops back to back, 6-10 m wide, each entered from the pavement
    by a door 1.6 m wide whose threshold is a step of 0.05-0.30 m up to the shop's floor; a shop's front room opens
    on its back room by a doorway 1.6 m wide across a sill 0.15 m deep and 0.05-0.15 m high. Walls 0.2 m thick, 3.5 m
    high under a roof at 50 degrees (:func:`_gable`); 1-3 pieces of furniture a room (:func:`_furnish`); cars parked
    on the roads, lamp posts on the pavements.

    Expected (written before the first run): every step is under the presets' 0.4 m climb, so the town is one area:
    roads, pavements and every room. Each kerb and threshold is a border between floors of two heights, so the navmesh
    has more polygons than the same town flat, but the structure and heat map should not see the steps: traffic
    highest on the roads and pavements through the middle of the grid, lowest in the back rooms (each a dead end
    behind its front room), the front rooms between. A designer expects the same.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    road = rng.uniform(8.0, 10.0)
    xs = np.cumsum([road, *sum(([rng.uniform(32.0, 40.0), road] for _ in range(3)), [])])
    zs = np.cumsum([road, *sum(([rng.uniform(24.0, 30.0), road] for _ in range(2)), [])])
    holes: list[tuple[float, float, float, float]] = []
    for bx0, bx1 in zip(xs[0:-1:2], xs[1::2]):
        for bz0, bz1 in zip(zs[0:-1:2], zs[1::2]):
            kerb = rng.uniform(0.10, 0.30)
            holes.append((bx0, bx1, bz0, bz1))
            s.ground(bx0, bx1, bz0, bz1, kerb, [(bx0 + 3.0, bx1 - 3.0, bz0 + 3.0, bz1 - 3.0)])
            for k in range(int(rng.integers(4, 7))):  # lamp posts on the pavement
                p = np.array([rng.uniform(bx0 + 1.0, bx1 - 1.0), bz0 + 0.5 if k % 2 else bz1 - 0.5])
                _trunk(s, p, 0.1, kerb - 0.3, kerb + 4.5)
            middle = (bz0 + bz1) / 2
            for row, (z0, z1, front) in enumerate(((bz0 + 3.0, middle, bz0 + 3.0), (middle, bz1 - 3.0, bz1 - 3.0))):
                into = 1.0 if row == 0 else -1.0  # from the pavement into the shop
                for x0, x1 in pairwise(_split(bx0 + 3.0, bx1 - 3.0, rng.uniform(6.0, 10.0))):
                    floor = kerb + rng.uniform(0.05, 0.30)
                    s.box(x0, x1, -0.5, floor, z0, z1)
                    door = rng.uniform(x0 + 0.6, x1 - 2.2)
                    s.wall((x0, front), (x1, front), floor - 0.5, floor + 3.5, [(door - x0, 1.6)])
                    back = front + into * (z1 - z0) * rng.uniform(0.5, 0.6)  # the wall between front and back room
                    inner = rng.uniform(x0 + 0.6, x1 - 2.2)
                    s.wall((x0, back), (x1, back), floor, floor + 3.5, [(inner - x0, 1.6)])
                    sill = rng.uniform(0.05, 0.15)
                    s.box(inner, inner + 1.6, floor - 0.1, floor + sill, back - 0.075, back + 0.075)
                    for x in (x0, x1):
                        s.wall((x, z0), (x, z1), floor - 0.5, floor + 3.5)
                    _gable(s, x0 - 0.1, x1 + 0.1, z0, z1, floor + 3.5)
                    far = z1 if row == 0 else z0
                    keep = [(door - 0.4, door + 2.0, front - 2.0, front + 2.0), (inner - 0.4, inner + 2.0, back - 2.0, back + 2.0)]
                    for room in ((x0 + 0.1, x1 - 0.1, min(front, back) + 0.1, max(front, back) - 0.1),
                                 (x0 + 0.1, x1 - 0.1, min(back, far) + 0.1, max(back, far) - 0.1)):
                        _furnish(s, rng, room, floor, keep, int(rng.integers(1, 4)))
                s.wall((bx0 + 3.0, middle), (bx1 - 3.0, middle), kerb, kerb + 3.8)  # the rows' shared back wall
    taken = list(holes)
    for _ in range(int(rng.integers(16, 24))):  # cars parked along the roads
        p = rng.uniform([0.0, 0.0], [xs[-1], zs[-1]])
        along_x = rng.random() < 0.5
        hx, hz = (2.1, 0.9) if along_x else (0.9, 2.1)
        if _clear(p[0] - hx - 1.0, p[0] + hx + 1.0, p[1] - hz - 1.0, p[1] + hz + 1.0, taken):
            _car(s, p[0] - hx, p[0] + hx, p[1] - hz, p[1] + hz, 0.0)
            taken.append((p[0] - hx - 3.0, p[0] + hx + 3.0, p[1] - hz - 3.0, p[1] + hz + 3.0))
    s.ground(0.0, xs[-1], 0.0, zs[-1], 0.0, holes)
    return s.mesh()


def _pipe(s: _Solids, a: np.ndarray, b: np.ndarray, radius: float, axis_y: float) -> None:
    """A pipe lying from plan point ``a`` (x, z) to ``b``: an octagonal prism of ``radius`` m about the horizontal axis
    at height ``axis_y``."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    along = (b - a) / np.linalg.norm(b - a)
    side = np.array([-along[1], along[0]])
    ring = [(radius * math.cos(t), radius * math.sin(t)) for t in np.linspace(0, 2 * math.pi, 8, endpoint=False)]
    s.hull(np.array([[p[0] + side[0] * u, axis_y + v, p[1] + side[1] * u] for p in (a, b) for u, v in ring]))


def prop_pile(seed: int) -> trimesh.Trimesh:
    """A loading yard 100-108 x 76-84 m built, as kit-bashed levels are, of modular props pushed into the floor and into
    each other, none trimmed: the floor is tiles 4 m square, 0.3 m thick, each 4.1 m wide (overlapping its neighbours by
    10 cm) and moved by up to 3 cm in plan and 1 cm in height; the yard's wall is pieces 4.2 m long (overlapping), 3 m
    high. 90-120 clusters of props, each 2.4 m clear of the others: stacks of 2-5 crates (cubes 1.0-1.4 m, turned to any
    angle, sunk 0.05-0.3 m into the floor and up to 0.4 m into one another, from the third crate on, half of them raised
    to a base 0.7-0.9 m up, 0.8 m at most off the stack's centre: resting on, sunk up to 0.6 m into or just over the
    crates below, held by other raised crates alone or, rarely, in the air), rings of 3-7 barrels (octagons 0.3-0.35 m
    in radius, 0.9 m high, sunk up to 0.2 m, overlapping), runs of 1-3 pipes lying along x or z (radius 0.2-0.8 m, 4-12
    m long, a third one across the run 2 m long, the axis 0.1-0.4 radii under the floor's top, so their tops stand
    0.12-0.72 m up, crossing one another), and shipping containers (2.4 x 6 x 2.6 m, along x or z, sunk 0.1 m: closed
    boxes).

    Expected (written before the first run): the yard is one area round the clusters; the crates', barrels' and thick
    pipes' tops hold no floor (under 2 m² after the agent's erosion) and pipes whose top stands under the 0.4 m climb
    are stepped over. The containers are the trap: a closed box pushed into the floor leaves the floor inside it with
    2.5 m of head room, so each container holds an island of floor (about 2 x 5 m, eroded to under 7 m²) as well as its
    top (eroded to about 7 m²); both are under the cover's smallest area (28 m²), so they are left out with a warning
    naming them. Traffic highest in the aisles through the yard's middle, lowest in the corners and the pockets
    between clusters. A designer expects the same, and nothing inside a container.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    nx, nz = int(rng.integers(25, 28)), int(rng.integers(19, 22))
    width, depth = nx * 4.0, nz * 4.0
    for i in range(nx):
        for j in range(nz):
            dx, dz = rng.uniform(-0.03, 0.03, 2)
            top = rng.uniform(-0.01, 0.01)
            s.box(i * 4.0 - 0.05 + dx, i * 4.0 + 4.05 + dx, top - 0.3, top, j * 4.0 - 0.05 + dz, j * 4.0 + 4.05 + dz)
    for a, b in (((0.0, 0.0), (width, 0.0)), ((0.0, depth), (width, depth)), ((0.0, 0.0), (0.0, depth)), ((width, 0.0), (width, depth))):
        along = 0 if a[1] == b[1] else 1
        for u in np.arange(0.0, (width, depth)[along], 4.0):
            lo, hi = u - 0.1, u + 4.1
            x0, x1, z0, z1 = (lo, hi, a[1] - 0.15, a[1] + 0.15) if along == 0 else (a[0] - 0.15, a[0] + 0.15, lo, hi)
            s.box(x0, x1, -0.35, 3.0, z0, z1)
    taken: list[tuple[float, float, float, float]] = []
    placed, tries = 0, 0
    count = int(rng.integers(90, 121))
    while placed < count and tries < 2000:
        tries += 1
        kind = int(rng.choice(4, p=[0.4, 0.25, 0.2, 0.15]))
        along_x = rng.random() < 0.5
        w, d = [(3.0, 3.0), (2.4, 2.4), (float(rng.uniform(4.0, 12.0)), 2.0), (6.0, 2.4)][kind]
        if kind >= 2 and not along_x:
            w, d = d, w
        c = rng.uniform([w / 2 + 1.5, d / 2 + 1.5], [width - w / 2 - 1.5, depth - d / 2 - 1.5])
        rect = (c[0] - w / 2, c[0] + w / 2, c[1] - d / 2, c[1] + d / 2)
        if not _clear(rect[0] - 2.4, rect[1] + 2.4, rect[2] - 2.4, rect[3] + 2.4, taken):
            continue
        taken.append(rect)
        placed += 1
        if kind == 0:  # a stack of crates
            for k in range(int(rng.integers(2, 6))):
                size, turn = rng.uniform(1.0, 1.4), rng.uniform(0.0, math.pi / 2)
                q = c + rng.uniform(-0.8, 0.8, 2)
                corners = q + size / 2 * np.array([[math.cos(turn + t), math.sin(turn + t)]
                                                    for t in np.arange(4) * math.pi / 2 + math.pi / 4]) * math.sqrt(2)
                base = -rng.uniform(0.05, 0.3) if k < 2 or rng.random() < 0.5 else 1.0 - rng.uniform(0.1, 0.3)
                s.prism(corners, base, base + size)
        elif kind == 1:  # a ring of barrels
            for k in range(int(rng.integers(3, 8))):
                q = c + 0.55 * np.array([math.cos(k * 0.9), math.sin(k * 0.9)]) + rng.uniform(-0.1, 0.1, 2)
                sink = rng.uniform(0.0, 0.2)
                _trunk(s, q, rng.uniform(0.3, 0.35), -sink, 0.9 - sink)
        elif kind == 2:  # a run of pipes, crossing
            for k in range(int(rng.integers(1, 4))):
                radius, off = rng.uniform(0.2, 0.8), rng.uniform(-0.6, 0.6)
                if along_x != (k == 2):  # the third pipe lies across the run
                    a, b = np.array([rect[0], c[1] + off]), np.array([rect[1], c[1] + off])
                else:
                    a, b = np.array([c[0] + off, rect[2]]), np.array([c[0] + off, rect[3]])
                _pipe(s, a, b, radius, -radius * rng.uniform(0.1, 0.4))
        else:  # a shipping container, a closed box sunk 0.1 m
            s.box(rect[0], rect[1], -0.1, 2.5, rect[2], rect[3])
    return s.mesh()


def beams(seed: int) -> trimesh.Trimesh:
    """A parkour run over a town's roofs: a 6 x 5 grid of buildings 9-14 m square on plots 17-20 m apart (so 3-11 m
    of street between them), flat roofs rising from 4 m at the west to 11.5-15.5 m at the east (1.5-2 m a column, up to
    1.5 m more at random), each closed solid standing in the street's ground. Neighbouring roofs are joined across
    the street by a balance beam 0.4-0.8 m wide (a chance of 0.45), a plank 1.2-1.6 m wide (0.35) or nothing (0.2),
    sloping from roof to roof; where the rise over the gap is steeper than 40 degrees nothing joins them. Roof clutter
    (air-conditioning units 1.2 m, ridged skylights); one roof of the west column, 4 m up, is reached from the street
    by a flight; the street holds cars and lamp posts.

    Expected (written before the first run): the presets' agent (radius 0.5 m) fits on no beam, so beams hold no floor
    and join nothing; the planks (over 1 m wide) do. So the street and the roofs joined to the start roof through
    planks are one area; every other group of roofs joined by planks is an area of its own (about five to ten, most of
    one or two roofs, 80-400 m²). Traffic highest in the street, then on the start roof and across the planks near
    it, nothing on the roofs apart. A designer expects the run along the beams from the start roof east to the top as
    the busiest line; the heat map cannot show it, and a user sees a warning naming the roofs apart.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    nx, nz, pitch = 6, 5, rng.uniform(17.0, 20.0)
    half = rng.uniform(4.5, 7.0, (nx, nz))
    rise = rng.uniform(1.5, 2.0)
    height = np.round(4.0 + rise * np.arange(nx)[:, None] + rng.uniform(0.0, 1.5, (nx, nz)), 1)
    start = int(rng.integers(nz))
    height[0, start], half[0, start] = 4.0, max(half[0, start], 6.0)
    centre = np.stack(np.meshgrid(np.arange(nx), np.arange(nz), indexing="ij"), -1) * pitch + pitch / 2
    holes: list[tuple[float, float, float, float]] = []
    for i in range(nx):
        for j in range(nz):
            c, h, y = centre[i, j], half[i, j], height[i, j]
            s.box(c[0] - h, c[0] + h, -0.5, y, c[1] - h, c[1] + h)
            holes.append((c[0] - h, c[0] + h, c[1] - h, c[1] + h))
            taken: list[tuple[float, float, float, float]] = []
            for _ in range(int(rng.integers(1, 4))):  # roof clutter, in the roof's middle
                w = rng.uniform(1.0, 2.0)
                q = rng.uniform(c - h + 2.5, c + h - 2.5 - w)
                if _clear(q[0] - 1.5, q[0] + w + 1.5, q[1] - 1.5, q[1] + w + 1.5, taken):
                    if rng.random() < 0.5:
                        s.box(q[0], q[0] + w, y - 0.1, y + 1.2, q[1], q[1] + w)
                    else:
                        _ridged(s, q[0], q[0] + w, q[1], q[1] + w, y - 0.1, y + 0.6)
                    taken.append((q[0], q[0] + w, q[1], q[1] + w))
    for i in range(nx):
        for j in range(nz):
            for di, dj in ((1, 0), (0, 1)):
                if i + di >= nx or j + dj >= nz:
                    continue
                link = rng.choice(3, p=[0.45, 0.35, 0.2])  # a beam, a plank or nothing
                heading = np.array([float(di), float(dj)])
                a = centre[i, j] + heading * (half[i, j] - 0.3)
                b = centre[i + di, j + dj] - heading * (half[i + di, j + dj] - 0.3)
                ya, yb = height[i, j], height[i + di, j + dj]
                if link == 2 or abs(yb - ya) > math.tan(math.radians(40.0)) * (np.linalg.norm(b - a) - 0.6):
                    continue
                across = rng.uniform(-1.0, 1.0) * (min(half[i, j], half[i + di, j + dj]) - 2.0) * heading[::-1]
                width = rng.uniform(0.4, 0.8) if link == 0 else rng.uniform(1.2, 1.6)
                s.ramp(a + across, b + across, width, ya, yb, 0.2)
    c, h = centre[0, start], half[0, start]  # the flight from the street up along the start building's west face
    run = math.ceil(4.0 / 0.18) * 0.28
    land = (c[0] - h - 1.8, c[0] - h + 0.01, c[1] - h + run + 1.0, c[1] - h + run + 3.0)
    _flight_to(s, np.array([c[0] - h - 0.9, land[2]]), np.array([0.0, 1.0]), 1.6, 0.0, 4.0, 0.28)
    s.box(land[0], land[1], -0.5, 4.0, land[2], land[3])
    holes.append(land)
    taken = list(holes) + [(land[0] - 1.0, land[0] + 2.0, land[2] - run - 2.0, land[2])]
    side = nx * pitch
    for k in range(int(rng.integers(24, 34))):  # cars and lamp posts in the street
        p = rng.uniform([-5.0, -5.0], [side + 5.0, nz * pitch + 5.0])
        if not _clear(p[0] - 2.6, p[0] + 2.6, p[1] - 1.5, p[1] + 1.5, taken):
            continue
        if k % 2:
            _car(s, p[0] - 2.1, p[0] + 2.1, p[1] - 0.9, p[1] + 0.9, 0.0)
        else:
            _trunk(s, p, 0.12, -0.3, 4.5)
        taken.append((p[0] - 3.0, p[0] + 3.0, p[1] - 2.0, p[1] + 2.0))
    s.ground(-6.0, side + 6.0, -6.0, nz * pitch + 6.0, 0.0, holes)
    return s.mesh()



def _tiles(s: _Solids, floor: np.ndarray, cell: float, wall_top: float) -> None:
    """A level drawn on a grid of square tiles ``cell`` m wide from the origin: tile (i, j) covers [i cell, (i + 1)
    cell] along x and [j cell, (j + 1) cell] along z. ``floor`` (n, m) holds each tile's floor height (m), NaN for a
    tile of rock. Each run along x of tiles of one height, joined with the same run of the rows after it into one
    rectangle, is one box from 0.5 m under the lowest floor up to that height, each rectangle of rock one solid ridged
    along x (:func:`_ridged`) up to ``wall_top``, so nothing stands on the rock and no floor runs under it. O(n m).
    """
    base = float(np.nanmin(floor)) - 0.5
    key = np.where(np.isnan(floor), np.inf, floor)  # rock compares equal to rock
    open_runs: dict[tuple[int, int, float], int] = {}  # (first tile, end tile, height) -> the row it started on

    def emit(i: int, k: int, height: float, j0: int, j1: int) -> None:
        if height == np.inf:
            _ridged(s, i * cell, k * cell, j0 * cell, j1 * cell, base, wall_top)
        else:
            s.box(i * cell, k * cell, base, height, j0 * cell, j1 * cell)

    for j in range(floor.shape[1] + 1):
        runs: set[tuple[int, int, float]] = set()
        if j < floor.shape[1]:
            row, i = key[:, j], 0
            while i < len(row):
                k = i + 1
                while k < len(row) and row[k] == row[i]:
                    k += 1
                runs.add((i, k, float(row[i])))
                i = k
        for run in sorted(set(open_runs) - runs):
            emit(*run, open_runs.pop(run), j)
        for run in runs - set(open_runs):
            open_runs[run] = j

def _paint(mask: np.ndarray, a: np.ndarray, b: np.ndarray, half: int) -> None:
    """Marks in ``mask`` (n, m) the tiles within ``half`` tiles (a square brush) of the 4-connected run of tiles from
    tile ``a`` (i, j) to ``b``: steps along i and j alternate while both remain, so a run at 45 degrees is a staircase
    of tiles that share edges, as a tile editor draws it. O(|b - a| half^2).
    """
    p, b = np.array(a, dtype=int), np.array(b, dtype=int)
    n, m = mask.shape
    axis = 0
    while True:
        mask[max(p[0] - half, 0):min(p[0] + half + 1, n), max(p[1] - half, 0):min(p[1] + half + 1, m)] = True
        if (p == b).all():
            return
        if p[axis] == b[axis]:
            axis = 1 - axis
        p[axis] += int(np.sign(b[axis] - p[axis]))
        axis = 1 - axis


def moba(seed: int) -> trimesh.Trimesh:
    """A MOBA map on a grid of 2 m tiles (:func:`_tiles`), 71-79 tiles a side (142-158 m), symmetric under a half turn
    about its centre: two bases 24-28 m square in opposite corners (south-west and north-east), three lanes between them
    8-10 m wide (a top lane up the west edge and along the north edge, a bottom lane along the south edge and up the
    east edge, a mid lane straight along the diagonal as a staircase of tiles), a river 10 m wide along the other
    diagonal 0.3 m below the lanes (under the climb) from the top lane's corner to the bottom lane's, and in the four
    jungles between lanes and river a tree of winding paths 6 m wide (a random spanning tree of junctions 6-10 m apart,
    each leg a staircase of tiles) with 3-4 camps a half (clearings 10 m square) and 4-6 openings a half, each onto the
    nearest of a side lane, the mid lane and the river. Everything else is rock ridged at 50 degrees over 2.5 m walls;
    the bases hold turrets (rock tiles 4 m square) in their lane mouths and a fountain (the same) in the far corner.

    Expected (written before the first run): one area. Traffic highest on the mid lane and where the river crosses it
    (the map's centre), then on the river and the side lanes; the jungle paths middling where they join lanes to the
    river, lowest in the camps and the jungle's dead ends; the bases' far corners coldest. A designer expects the
    structure to follow the three lanes, the river and the jungle's tree, with terminals in the camps and the bases; the
    staircase edges of the diagonals (2 m steps) should not show in the structure as nodes of their own.
    """
    rng = np.random.default_rng(seed)
    n, cell = int(rng.integers(71, 80)), 2.0
    walk = np.zeros((n, n), dtype=bool)
    base = int(rng.integers(13, 16))
    walk[1:base, 1:base] = True
    lane = int(rng.integers(4, 6))
    walk[1:1 + lane, 1:n - 1] = True  # top lane: up the west edge, along the north edge
    walk[1:n - 1, n - 1 - lane:n - 1] = True
    _paint(walk, np.array([base - 3, base - 3]), np.array([n - base + 2, n - base + 2]), lane // 2)  # mid lane
    river = np.zeros((n, n), dtype=bool)
    _paint(river, np.array([1 + lane, n - 2 - lane]), np.array([n - 2 - lane, 1 + lane]), 2)
    junctions = [(i, j) for i in range(lane + 4, n - lane - 3, 4) for j in range(lane + 4, n - lane - 3, 4)
                 if i + 4 < j and abs(i + j - (n - 1)) > 6]  # the jungle north of the mid lane (the south by the turn)
    jitter = rng.integers(-1, 2, (len(junctions), 2))
    points = np.array(junctions) + jitter
    jungle = np.zeros((n, n), dtype=bool)
    tree = minimum_spanning_tree(sp.csr_matrix(np.triu(
        np.linalg.norm(points[:, None] - points[None], axis=2) * rng.uniform(1.0, 1.6, (len(points),) * 2)
        * (np.linalg.norm(points[:, None] - points[None], axis=2) < 7.0)))).tocoo()
    for u, v in zip(tree.row, tree.col):
        _paint(jungle, points[u], points[v], 1)
    ends = rng.choice(len(points), size=min(len(points), int(rng.integers(3, 5))), replace=False)
    for k in ends:  # camps
        jungle[points[k][0] - 2:points[k][0] + 3, points[k][1] - 2:points[k][1] + 3] = True
    for k in rng.choice(len(points), size=int(rng.integers(4, 7)), replace=False):  # openings onto a lane or the river
        i, j = points[k]
        target = min([(i, n - 1 - lane), (lane, j), (i, i + 1), (i, n - 1 - i)],
                     key=lambda t: abs(t[0] - i) + abs(t[1] - j))
        _paint(jungle, np.array([i, j]), np.array(target), 1)
    walk |= jungle | river
    walk |= walk[::-1, ::-1]
    river |= river[::-1, ::-1]
    for i, j, w in ((base - 4, 2, 2), (2, base - 4, 2), (base - 6, base - 6, 2), (1, 1, 2)):  # turrets, fountain
        walk[i:i + w, j:j + w] = False
    walk &= walk[::-1, ::-1]
    walk[[0, -1], :] = walk[:, [0, -1]] = False
    floor = np.where(walk, np.where(river, -0.3, 0.0), np.nan)
    _tiles(s := _Solids(), floor, cell, 2.5)
    return s.mesh()


def _mirrored(half: _Solids, length: float) -> list[trimesh.Trimesh]:
    """The solids of ``half`` and their mirror images in the plane x = ``length`` / 2 (faces turned back outward)."""
    mirror = np.diag([-1.0, 1.0, 1.0, 1.0])
    mirror[0, 3] = length
    images = [part.copy() for part in half.parts]
    for image in images:
        image.apply_transform(mirror)
    return half.parts + images


def capture_flag(seed: int) -> trimesh.Trimesh:
    """A capture-the-flag map 190-210 x 70-78 m (walls 4 m high all round), mirrored in its middle plane x = L / 2. Each
    end holds a base (y = 0): a hall 30-34 m deep along x and 28-32 m wide under a ridged lid 8 m up (:func:`_lid`),
    open to the field through two doorways 3 m wide in its front wall and one 2.5 m wide in each side wall; across its
    back an upper storey 12-14 m deep at y = 4, reached by one flight up its edge (risers 0.174 m, railed), holding the
    flag room (9 x 10 m, one door 1.6 m wide under a lintel 2.3 m up, :func:`_doored_wall`; the flag a ridged plinth).
    Between the bases the mid field (y = 0) of up to 26-34 low walls and rocks (ridged, 1.2-1.8 m) a half, mirrored. Two
    flank tunnels 4 m wide and 4 m high under the field, 6 m in from its long sides, run from base yard to base yard:
    each end is a flight of 25 risers of 0.18 m (7.5 m) down through a railed hole in the field beside a base, so a
    tunnel is 91-119 m long with no way up between its ends.

    Expected (written before the first run): one area. Traffic highest across the mid field on the lines between the
    bases' front doors, then in the doorways and the halls; the tunnels carry the flank traffic, middling and even along
    their length (no junction) but high near their stairs; the flag rooms (dead ends up a flight) and the upper storeys
    low, the field's corners lowest. A designer expects the structure to show the field's lanes between the cover, both
    tunnels as single long edges under the field, the flights to the upper storeys, and a terminal in each flag room.
    """
    rng = np.random.default_rng(seed)
    length, width = rng.uniform(190.0, 210.0), rng.uniform(70.0, 78.0)
    deep, half_wide, upper = rng.uniform(30.0, 34.0), rng.uniform(14.0, 16.0), rng.uniform(12.0, 14.0)
    west = _Solids()
    bx0, bx1, bz0, bz1, zc = 4.0, 4.0 + deep, width / 2 - half_wide, width / 2 + half_wide, width / 2
    west.wall((bx0, bz0), (bx0, bz1), -0.5, 8.0)
    front = [(half_wide / 2 - 1.5, 3.0), (1.5 * half_wide - 1.5, 3.0)]
    west.wall((bx1, bz0), (bx1, bz1), -0.5, 8.0, front)
    for z in (bz0, bz1):
        west.wall((bx0, z), (bx1, z), -0.5, 8.0, [(deep * 0.6, 2.5)])
    _lid(west, bx0 - 0.1, bx1 + 0.1, bz0 - 0.1, bz1 + 0.1, 8.0)
    west.box(bx0, bx0 + upper, 3.7, 4.0, bz0, bz1)  # the upper storey
    stair_z = zc - half_wide / 2
    _flight_to(west, np.array([bx0 + upper, stair_z]), np.array([-1.0, 0.0]), 2.4, 0.0, 4.0)
    west.wall((bx0 + upper, bz0), (bx0 + upper, bz1), 4.0, 5.1, [(stair_z - 1.2 - bz0, 2.4)], thickness=0.1)
    room_z0, room_x1 = zc + 1.0, bx0 + 9.0
    _doored_wall(west, (bx0, room_z0), (room_x1, room_z0), 4.0, 7.0, [])
    _doored_wall(west, (room_x1, room_z0), (room_x1, room_z0 + 10.0), 4.0, 7.0,
                 [(rng.uniform(2.0, 6.0), 1.6, "open", 1)])
    _doored_wall(west, (bx0, room_z0 + 10.0), (room_x1, room_z0 + 10.0), 4.0, 7.0, [])
    _ridged(west, bx0 + 4.0, bx0 + 5.0, room_z0 + 4.5, room_z0 + 5.5, 3.9, 5.0)  # the flag's plinth
    holes, taken = [], [(bx0 - 2.0, bx1 + 3.0, bz0 - 2.0, bz1 + 2.0)]
    run = 25 * 0.3
    for zt in (6.0, width - 6.0):  # the tunnels' stairs down, railed
        xs = bx1 + 4.0
        _flight_to(west, np.array([xs, zt]), np.array([-1.0, 0.0]), 3.0, -4.5, 0.0)
        holes.append((xs, xs + run, zt - 1.5, zt + 1.5))
        taken.append((xs - 2.0, xs + run + 2.0, zt - 4.0, zt + 4.0))
        for z in (zt - 1.6, zt + 1.6):
            west.wall((xs, z), (xs + run + 0.1, z), 0.0, 1.1, thickness=0.1)
        west.wall((xs + run + 0.1, zt - 1.6), (xs + run + 0.1, zt + 1.6), 0.0, 1.1, thickness=0.1)
        west.box(xs + run - 0.05, length / 2, -5.0, -4.5, zt - 2.0, zt + 2.0)  # the tunnel's floor, walls and end
        for z in (zt - 2.1, zt + 2.1):
            west.box(xs - 0.2, length / 2, -5.0, -0.5, z - 0.1, z + 0.1)
        west.box(xs - 0.3, xs, -5.0, -0.5, zt - 2.0, zt + 2.0)
    cover = int(rng.integers(26, 35))
    for _ in range(cover * 3):  # cover on the field, kept 3 m apart
        w, d = (rng.uniform(2.0, 4.0), rng.uniform(0.6, 1.0)) if rng.random() < 0.5 else (rng.uniform(1.5, 3.0),) * 2
        if rng.random() < 0.5:
            w, d = d, w
        p = rng.uniform([bx1 + 5.0, 4.0], [length / 2 - w - 1.0, width - 4.0 - d])
        if len(taken) < cover + 3 and _clear(p[0] - 3.0, p[0] + w + 3.0, p[1] - 3.0, p[1] + d + 3.0, taken):
            _ridged(west, p[0], p[0] + w, p[1], p[1] + d, -0.1, rng.uniform(1.2, 1.8))
            taken.append((p[0], p[0] + w, p[1], p[1] + d))
    s = _Solids()
    s.parts = _mirrored(west, length)
    s.ground(0.0, length, 0.0, width, 0.0, holes + [(length - h[1], length - h[0], h[2], h[3]) for h in holes])
    for a, b in (((0.0, 0.0), (length, 0.0)), ((0.0, width), (length, width)), ((0.0, 0.0), (0.0, width)),
                 ((length, 0.0), (length, width))):
        s.wall(a, b, -0.5, 4.0, thickness=0.4)
    return s.mesh()


def platform_tower(seed: int) -> trimesh.Trimesh:
    """A platformer's tower: a solid core 10-12 m square (pointed at 50 degrees on top) ringed by a square spiral of
    platforms over a void, seven or eight turns of 16 (a platform at each corner of a square ring 30-34 m across and
    three between), each platform 4-5 m square and 0.4 m thick, 0.8-1.8 m above the one before it. Each join runs along
    the ring's side over the gap between two platforms: a ramp 2 m wide, or a flight 2 m wide whose risers (at most 0.18
    m) and long treads span the gap. A quarter of the side platforms hold a perch: a flight out from the core up 1-2 m
    to a dead-end platform 3 m square; some other side platforms hold a crate (ridged, 1 m) on the core's side, off the
    joins' line. The spiral starts on a plaza (y = 0, 5 m wide round the ring, 3 m out from it) by a strip to its first
    platform.

    Expected (written before the first run): one area (every platform joined to the next; the perches dead ends).
    Traffic highest on the plaza and the lowest turn, falling steadily up the spiral (every path above passes every join
    below it): the top turn and the perches coldest. A designer expects the structure to be a single chain of nodes up
    the spiral (one to three per platform and join) with short spurs to the perches, terminals on the perches and at the
    top; nothing joins turns vertically.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    core, ring = rng.uniform(5.0, 6.0), rng.uniform(15.0, 17.0)
    turns, per_side = int(rng.integers(7, 9)), 4
    sides = [np.array(v) for v in ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))]
    corners = [np.array(v) * ring for v in ((-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0))]
    centres = [corners[k] + sides[k] * ring * 2 * t / per_side for _ in range(turns) for k in range(4)
               for t in range(per_side)]
    headings = [sides[k] for _ in range(turns) for k in range(4) for t in range(per_side)]
    size = rng.uniform(4.0, 5.0, len(centres))
    height = np.concatenate([[0.0], np.cumsum(np.round(rng.uniform(0.8, 1.8, len(centres) - 1), 2))])
    for k, (c, h, y) in enumerate(zip(centres, size, height)):
        s.box(c[0] - h / 2, c[0] + h / 2, y - 0.4, y, c[1] - h / 2, c[1] + h / 2)
        if k + 1 < len(centres):  # the join to the next platform, along this side
            heading, nxt = headings[k], centres[k + 1]
            a, b = c + heading * h / 2, nxt - heading * size[k + 1] / 2
            if rng.random() < 0.5:
                s.ramp(a, b, 2.0, y, height[k + 1], 0.4)
            else:
                steps = math.ceil((height[k + 1] - y) / 0.18 - 1e-9)
                _flight_to(s, b, heading, 2.0, y, height[k + 1], float(np.linalg.norm(b - a)) / steps)
        out = np.array([-headings[k][1], headings[k][0]]) * -1.0  # away from the core (the ring runs anticlockwise)
        if k % per_side in (1, 2) and rng.random() < 1 / 4:
            rise = round(float(rng.uniform(1.0, 2.0)), 2)
            edge = c + out * (h / 2 + math.ceil(rise / 0.18 - 1e-9) * 0.3)
            _flight_to(s, edge, out, 1.8, y, y + rise)
            p = edge + out * 1.5
            s.box(p[0] - 1.5, p[0] + 1.5, y + rise - 0.4, y + rise, p[1] - 1.5, p[1] + 1.5)
        elif rng.random() < 0.3 and k % per_side:  # not on a corner, where the joins turn
            q = c - out * (h / 2 - 1.0) + headings[k] * rng.uniform(-0.5, 0.5) * (h - 2.0)  # off the joins' line
            _ridged(s, q[0] - 0.5, q[0] + 0.5, q[1] - 0.5, q[1] + 0.5, y - 0.1, y + 1.0)
    top = height[-1] + 6.0
    _ridged(s, -core, core, -core, core, -0.5, top)
    c0 = centres[0]
    s.box(c0[0] - 1.0, c0[0] + 1.0, -0.4, 0.0, -ring - 8.0, c0[1])
    s.ground(-ring - 8.0, ring + 8.0, -ring - 8.0, ring + 8.0, 0.0,
             [(-ring - 3.0, ring + 3.0, -ring - 3.0, ring + 3.0)])
    return s.mesh()

def diagonal_dungeon(seed: int) -> trimesh.Trimesh:
    """A dungeon crawler's level on a grid of 2 m tiles (:func:`_tiles`), 100 x 79 tiles (200 x 158 m): a 6 x 5 lattice
    of rooms, each 5-9 tiles a side at a random place in its lattice cell (16 x 15 tiles), 0-3 rock pillars (one tile)
    in the rooms of 7 tiles or more a side. Corridors one tile wide (2 m) join the rooms along a random spanning tree of
    the lattice's eight-neighbour graph and a quarter of its other edges: each runs from one room's centre at 45
    degrees until level with the other's row or column, then straight, and a run at 45 degrees is a staircase of tiles
    that share edges (:func:`_paint`), as a tile editor draws it. Corridors cross where they meet. Everything else is
    rock ridged at 50 degrees over 3 m walls.

    Expected (written before the first run): one area; a diagonal corridor passes the presets' agent (1 m across) down
    its staircase of 2 m tiles. Traffic highest on the corridors of the middle rows joining the lattice's middle rooms,
    lowest in the corner rooms and on the tree's dead-end rooms. A designer expects one node a room (two or three in a
    large room round its pillars) and each corridor as one edge, straight or with one bend, not a chain of nodes along
    each staircase.
    """
    rng = np.random.default_rng(seed)
    n, m, cols, rows, pitch_x, pitch_z = 100, 79, 6, 5, 16, 15
    walk = np.zeros((n, m), dtype=bool)
    centre = np.zeros((cols, rows, 2), dtype=int)
    for a in range(cols):
        for b in range(rows):
            w, d = rng.integers(5, 10, 2)
            i0 = 2 + a * pitch_x + int(rng.integers(0, pitch_x - w - 1))
            j0 = 2 + b * pitch_z + int(rng.integers(0, pitch_z - d - 1))
            walk[i0:i0 + w, j0:j0 + d] = True
            centre[a, b] = i0 + w // 2, j0 + d // 2
            if w > 6 and d > 6:
                for _ in range(int(rng.integers(0, 4))):
                    walk[i0 + int(rng.integers(2, w - 2)), j0 + int(rng.integers(2, d - 2))] = False
    cells = [(a, b) for a in range(cols) for b in range(rows)]
    index = {c: k for k, c in enumerate(cells)}
    edges = [(index[a, b], index[a + da, b + db]) for a, b in cells for da, db in ((1, 0), (0, 1), (1, 1), (1, -1))
             if (a + da, b + db) in index]
    weight = sp.coo_matrix((rng.uniform(1.0, 2.0, len(edges)), tuple(np.array(edges).T)), shape=(len(cells),) * 2)
    tree = minimum_spanning_tree(weight.tocsr()).tocoo()
    chosen = set(zip(tree.row.tolist(), tree.col.tolist()))
    chosen |= {e for e in edges if e not in chosen and rng.random() < 0.25}
    for u, v in sorted(chosen):
        p, q = centre[cells[u]], centre[cells[v]]
        step = min(abs(q[0] - p[0]), abs(q[1] - p[1]))
        bend = p + np.sign(q - p) * step
        _paint(walk, p, bend, 0)
        _paint(walk, bend, q, 0)
    s = _Solids()
    _tiles(s, np.where(walk, 0.0, np.nan), 2.0, 3.0)
    return s.mesh()


def battle_royale(seed: int) -> trimesh.Trimesh:
    """An open battle-royale field 240 m square on a 2 m grid (:func:`_terrain`): rolling ground (four waves 60-140 m
    long and 1-2.5 m high, slopes under about 15 degrees), 14-18 small houses and 12-18 rock clusters, kept 12 m apart.
    A house is 8-14 x 8-12 m on ground levelled round it (flat within 3 m of its walls, blended back over 8 m), its
    floor 0.15 m over that ground on a block the ground stops at, walls 0.25 m thick and 3 m high under a roof ridged at
    50 degrees (:func:`_gable`): one door 1.6 m wide in a random outside wall and 1-3 rooms in a row joined by doors 1.6
    m wide (lintels 2.3 m up, :func:`_doored_wall`). A rock cluster is 3-6 rocks (hulls of 8 points,
    :meth:`_Solids.rock`) from 0.5 m under the ground to 0.8-1.9 m over it, so the ground inside one keeps under the
    agent's height; up to 60-90 trunks stand at random.

    Expected (written before the first run): one area of ground and houses, and a few small areas on rock tops out of
    reach. Traffic highest across the middle of the field, spread thin (no paths: every line between two places is
    open), lowest in the field's corners and in the houses' inner rooms. A designer expects few structure nodes on the
    open ground (a coarse net between the houses and rock clusters), a node and terminal in each house's inner room and
    an edge through each door.
    """
    rng = np.random.default_rng(seed)
    size, step = 240.0, 2.0
    xs = zs = np.arange(0.0, size + step / 2, step)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    heights = np.zeros_like(gx)
    for _ in range(4):
        angle, wave = rng.uniform(0.0, math.pi), rng.uniform(60.0, 140.0)
        along = gx * math.cos(angle) + gz * math.sin(angle)
        heights += rng.uniform(1.0, 2.5) * np.sin(2 * math.pi * along / wave + rng.uniform(0.0, 2 * math.pi))
    s = _Solids()
    keep = np.ones((len(xs) - 1, len(zs) - 1), dtype=bool)
    taken: list[tuple[float, float, float, float]] = []
    houses = []
    for _ in range(200):
        if len(houses) == int(rng.integers(14, 19)):
            break
        w, d = 2 * rng.integers(4, 8), 2 * rng.integers(4, 7)
        x0, z0 = 2 * rng.integers(8, int(size / 2) - 8 - w // 2, 2)
        if _clear(x0 - 12, x0 + w + 12, z0 - 12, z0 + d + 12, taken):
            taken.append((x0, x0 + w, z0, z0 + d))
            houses.append((float(x0), float(x0 + w), float(z0), float(z0 + d)))
    for x0, x1, z0, z1 in houses:  # level the ground round each house
        out = np.maximum(np.maximum(x0 - gx, gx - x1), np.maximum(z0 - gz, gz - z1))
        level = float(heights[(out <= 3.0)].mean())
        blend = np.clip((out - 3.0) / 8.0, 0.0, 1.0)
        heights = level * (1 - blend) + heights * blend
    for x0, x1, z0, z1 in houses:
        out = np.maximum(np.maximum(x0 - gx, gx - x1), np.maximum(z0 - gz, gz - z1))
        floor = float(heights[out <= 3.0].mean()) + 0.15
        keep[int(x0 / step):int(x1 / step), int(z0 / step):int(z1 / step)] = False
        s.box(x0, x1, floor - 1.5, floor, z0, z1)
        rooms = int(rng.integers(1, 4))
        cuts = np.linspace(x0, x1, rooms + 1)
        door_side = int(rng.integers(4))
        walls = [((x0, z0), (x1, z0)), ((x0, z1), (x1, z1)), ((x0, z0), (x0, z1)), ((x1, z0), (x1, z1))]
        for k, (a, b) in enumerate(walls):
            span = abs(b[0] - a[0]) + abs(b[1] - a[1])
            room = cuts[1] - x0 if k < 2 else span  # a door along x opens into the first room
            doors = [(rng.uniform(0.5, room - 2.1), 1.6, "open", 1)] if k == door_side else []
            _doored_wall(s, a, b, floor, floor + 3.0, doors, 0.25)
        for c in cuts[1:-1]:
            _doored_wall(s, (c, z0), (c, z1), floor, floor + 3.0,
                         [(rng.uniform(1.0, z1 - z0 - 2.6), 1.6, "open", 1)], 0.25)
        _gable(s, x0 - 0.3, x1 + 0.3, z0 - 0.3, z1 + 0.3, floor + 3.0)
    rocks = 0
    for _ in range(200):
        if rocks == int(rng.integers(12, 19)):
            break
        p = rng.uniform(10.0, size - 10.0, 2)
        if not _clear(p[0] - 10, p[0] + 10, p[1] - 10, p[1] + 10, taken):
            continue
        taken.append((p[0] - 4, p[0] + 4, p[1] - 4, p[1] + 4))
        rocks += 1
        for _ in range(int(rng.integers(3, 7))):
            q = p + rng.normal(0.0, 2.0, 2)
            y = float(heights[int(round(q[0] / step)), int(round(q[1] / step))])
            s.rock(rng, q, 0.9, y - 0.5, y + rng.uniform(0.8, 1.9))
    for _ in range(int(rng.integers(60, 91))):
        p = rng.uniform(4.0, size - 4.0, 2)
        if _clear(p[0] - 2, p[0] + 2, p[1] - 2, p[1] + 2, taken):
            y = float(heights[int(round(p[0] / step)), int(round(p[1] / step))])
            _trunk(s, p, 0.3, y - 1.0, y + 7.0)
    _terrain(s, xs, zs, heights, keep)
    return s.mesh()


def arena_shooter(seed: int) -> trimesh.Trimesh:
    """An arena shooter's map: three storeys 4.5 m apart (y = 0, 4.5, 9) on a 110-124 x 76-86 m plan inside walls 13 m
    high, open to the sky. The upper two slabs (0.3 m) are holed by 4-5 atria 10-18 m across, each railed (1.1 m), and
    joined to the storey below by 6-8 ramps each (3 m wide, at 25-30 degrees, 7.8-9.7 m long, along x or z), every ramp
    rising through a hole in the slab above over its whole plan and meeting the upper storey head-on at the hole's far
    end (rails 1.1 m along the hole's other three sides). Ramps, atria and each other keep 2 m apart on both storeys
    they touch. Each storey holds up to 12-18 pieces of cover (ridged, 1.2-1.6 m; fewer where they do not fit) and up to
    three pillars 1.5 m square rise through all three (the ground and slabs stop at them).

    Expected (written before the first run): one area. Many loops at three heights: each pair of storeys is joined by
    6-8 ramps, so every storey is a ring of ways up and down round the atria. Traffic highest on the middle storey and
    on the ramps near the plan's middle, lowest in the ground storey's corners and under the atria's far sides. A
    designer expects the structure to hold every ramp as an edge, loops on every storey round the atria, and few
    terminals (the map has few dead ends: corners only).
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    width, depth, storey = rng.uniform(110.0, 124.0), rng.uniform(76.0, 86.0), 4.5
    for a, b in (((0.0, 0.0), (width, 0.0)), ((0.0, depth), (width, depth)), ((0.0, 0.0), (0.0, depth)),
                 ((width, 0.0), (width, depth))):
        s.wall(a, b, -0.5, 13.0, thickness=0.4)
    plans: dict[int, list[tuple[float, float, float, float]]] = {0: [], 1: [], 2: []}  # kept-clear plans a storey
    holes: dict[int, list[tuple[float, float, float, float]]] = {1: [], 2: []}
    for level in (1, 2):
        for _ in range(100):
            if len(holes[level]) == int(rng.integers(4, 6)):
                break
            w, d = rng.uniform(10.0, 18.0, 2)
            p = rng.uniform([4.0, 4.0], [width - 4.0 - w, depth - 4.0 - d])
            atrium = (p[0], p[0] + w, p[1], p[1] + d)
            if _clear(atrium[0] - 2, atrium[1] + 2, atrium[2] - 2, atrium[3] + 2, plans[level]):
                holes[level].append(atrium)
                plans[level].append(atrium)
                _rail_ring(s, *atrium, level * storey, {})
    for level in (1, 2):
        y0, y1 = (level - 1) * storey, level * storey
        ramps = 0
        for _ in range(300):
            if ramps == int(rng.integers(6, 9)):
                break
            run = storey / math.tan(math.radians(rng.uniform(25.0, 30.0)))
            heading = [np.array(v) for v in ((1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0))][int(rng.integers(4))]
            foot = rng.uniform([3.0, 3.0], [width - 3.0, depth - 3.0])
            top = foot + heading * run
            side = np.array([-heading[1], heading[0]]) * 1.5
            corners = np.array([foot - side, foot + side, top - side, top + side])
            lo, hi = corners.min(axis=0), corners.max(axis=0)
            plan = (lo[0], hi[0], lo[1], hi[1])
            if lo.min() < 3.0 or hi[0] > width - 3.0 or hi[1] > depth - 3.0:
                continue
            reach = (plan[0] - 2, plan[1] + 2, plan[2] - 2, plan[3] + 2)
            ahead = (min(top[0], top[0] + heading[0] * 3) - 1.5, max(top[0], top[0] + heading[0] * 3) + 1.5,
                     min(top[1], top[1] + heading[1] * 3) - 1.5, max(top[1], top[1] + heading[1] * 3) + 1.5)
            if not (_clear(*reach, plans[level - 1]) and _clear(*reach, plans[level]) and _clear(*ahead, holes[level])):
                continue
            s.ramp(foot, top, 3.0, y0, y1, 0.3)
            holes[level].append(plan)
            plans[level - 1].append(plan)
            plans[level].append(plan)
            open_side = {(1.0, 0.0): "east", (-1.0, 0.0): "west", (0.0, 1.0): "north", (0.0, -1.0): "south"}
            _rail_ring(s, plan[0] - 0.1, plan[1] + 0.1, plan[2] - 0.1, plan[3] + 0.1, y1,
                       {open_side[tuple(heading)]: [(0.0, 40.0)]})
            ramps += 1
    pillars: list[tuple[float, float, float, float]] = []
    for level in (0, 1, 2):
        y = level * storey
        for k in range(int(rng.integers(12, 19)) + 3):
            w, d = rng.uniform(1.0, 4.0, 2)
            p = rng.uniform([2.0, 2.0], [width - 2.0 - w, depth - 2.0 - d])
            if not _clear(p[0] - 2.0, p[0] + w + 2.0, p[1] - 2.0, p[1] + d + 2.0, plans[level]):
                continue
            if k < 3 and level == 0:  # pillars through every storey, the slabs stop at them
                _ridged(s, p[0], p[0] + 1.5, p[1], p[1] + 1.5, -0.5, 14.0)
                for up in (1, 2):
                    holes[up].append((p[0], p[0] + 1.5, p[1], p[1] + 1.5))
                    plans[up].append((p[0] - 1.0, p[0] + 2.5, p[1] - 1.0, p[1] + 2.5))
                plans[0].append((p[0], p[0] + 1.5, p[1], p[1] + 1.5))
                pillars.append((p[0], p[0] + 1.5, p[1], p[1] + 1.5))
            else:
                _ridged(s, p[0], p[0] + w, p[1], p[1] + d, y - 0.1, y + rng.uniform(1.2, 1.6))
                plans[level].append((p[0], p[0] + w, p[1], p[1] + d))
    s.ground(0.0, width, 0.0, depth, 0.0, pillars)
    for level in (1, 2):
        s.ground(0.0, width, 0.0, depth, level * storey, holes[level], 0.3)  # one box a run: the slab's 5-6 x fewer solids
    return s.mesh()


def _rolling(rng: np.random.Generator, shape: tuple[int, int], riser: float = 0.15) -> np.ndarray:
    """Floor heights (n, m) of tiles on gently rolling ground, in whole risers of ``riser`` m: two waves 40-80 tiles long
    whose sum changes by under half a riser a tile each, floored to risers, so tiles sharing an edge differ by at most
    one riser (0.15 m, under the presets' 0.4 m climb) and tiles sharing a corner by two; up to about 1.3 m of relief.
    O(n m)."""
    gi, gj = np.meshgrid(np.arange(shape[0]), np.arange(shape[1]), indexing="ij")
    field = np.zeros(shape)
    for _ in range(2):
        angle, wave = rng.uniform(0.0, math.pi), rng.uniform(40.0, 80.0)
        along = gi * math.cos(angle) + gj * math.sin(angle)
        field += 0.45 * wave / (2 * math.pi) * np.sin(2 * math.pi * along / wave + rng.uniform(0.0, 2 * math.pi))
    return np.floor(field) * riser


def _tile_crates(rng: np.random.Generator, walk: np.ndarray, rects: list[tuple[int, int, int, int]]) -> None:
    """Crates one tile square against the walls of routes drawn on tiles: along each rectangle (i0, i1, j0, j1) of
    tiles of ``walk`` (n, m) 3 or more tiles wide, from 3 tiles after its start to 3 before its end, one every 4-7
    tiles on alternate sides, each where rock stands behind it (so no crate closes another route's mouth); each
    leaves two tiles of the route open beside it. O(total length)."""
    for i0, i1, j0, j1 in rects:
        along = 0 if i1 - i0 >= j1 - j0 else 1
        (lo, hi), (c0, c1) = ((i0, i1), (j0, j1)) if along == 0 else ((j0, j1), (i0, i1))
        if c1 - c0 < 3:
            continue
        k, side = lo + 3 + int(rng.integers(0, 3)), int(rng.integers(2))
        while k < hi - 3:
            c, behind = (c0, c0 - 1) if side == 0 else (c1 - 1, c1)
            tile, back = ((k, c), (k, behind)) if along == 0 else ((c, k), (behind, k))
            if 0 <= back[0] < walk.shape[0] and 0 <= back[1] < walk.shape[1] and not walk[back]:
                walk[tile] = False
            k, side = k + int(rng.integers(4, 8)), 1 - side

def _tile_rooms(rng: np.random.Generator, walk: np.ndarray, rects: list[tuple[int, int, int, int]], tries: int) -> None:
    """Side rooms off routes drawn on tiles: ``tries`` times, a room 3-5 x 3-4 tiles one tile of rock beyond a random
    long side of a random rectangle (i0, i1, j0, j1) of ``rects``, opened to it by a door one tile wide, made in
    ``walk`` (n, m) only where the room and a tile round it are all rock (so rooms never join anything but their
    route) and the door opens onto open floor of the route (not a doorway's frame). O(tries)."""
    n, m = walk.shape
    for _ in range(tries):
        i0, i1, j0, j1 = rects[int(rng.integers(len(rects)))]
        along = 0 if i1 - i0 >= j1 - j0 else 1
        (lo, hi), (c0, c1) = ((i0, i1), (j0, j1)) if along == 0 else ((j0, j1), (i0, i1))
        w, d = int(rng.integers(3, 6)), int(rng.integers(3, 5))
        if hi - lo < w + 2:
            continue
        k = int(rng.integers(lo + 1, hi - w))
        e0, e1 = (c0 - 1 - d, c0 - 1) if rng.random() < 0.5 else (c1 + 1, c1 + 1 + d)  # the room's rows across
        room = (k, k + w, e0, e1) if along == 0 else (e0, e1, k, k + w)
        if room[0] < 2 or room[2] < 2 or room[1] > n - 2 or room[3] > m - 2:
            continue
        if walk[room[0] - 1:room[1] + 1, room[2] - 1:room[3] + 1].any():
            continue
        door, wall = k + int(rng.integers(w)), (c0 - 1 if e1 == c0 - 1 else c1)
        inside = (c0 if wall == c0 - 1 else c1 - 1)  # the route's tile the door opens onto
        if not walk[(door, inside) if along == 0 else (inside, door)]:
            continue
        walk[room[0]:room[1], room[2]:room[3]] = True
        walk[(door, wall) if along == 0 else (wall, door)] = True

def defusal(seed: int) -> trimesh.Trimesh:
    """A bomb-defusal map on 2 m tiles (:func:`_tiles`), 92-100 x 86-94 tiles (184-200 x 172-188 m): the attackers' spawn
    (a yard 12-14 x 7 tiles) in the middle of the south edge, the defenders' (10-12 x 6) in the middle of the north edge,
    bombsite A (11-13 tiles square) in the north-west on a plateau 0.9 m up (six risers of 0.15 m, one a tile, on every
    way in) and bombsite B (12-14 tiles square) in the north-east, each holding 5-8 crates (rock tiles 1-2 tiles a side).
    Routes 4-6 m wide (2-3 tiles) unless named narrower: the mid lane straight north from spawn to spawn, narrowed to
    one tile (a doorway, 2 m) at the mid doors; long A along the west edge from the attackers' yard, through a doorway
    of one tile; short A (a catwalk 1 tile wide) from mid to the plateau's south-east corner; B tunnels from the yard
    east and north, bent twice, into B's south side; a mid-to-B connector one tile wide; the defenders' ways to each
    site. Along the routes 3 tiles wide, crates against the walls (:func:`_tile_crates`), and off every route up to
    120 tries of side rooms behind one-tile doors (:func:`_tile_rooms`: corners, closets, a designer's "pit" or "car").
    The rest is rock ridged at 50 degrees over 3 m walls.

    Expected (written before the first run): one area. Traffic highest on the mid lane (the one straight way from spawn
    to spawn) and in the defenders' and attackers' yards where every route fans out, then on the routes into the sites;
    the sites' corners behind crates and the doorways' ends lowest. A designer expects the structure to show the five
    routes between the yards as separate edges or chains (long A, short A, mid, connector, B tunnels), a junction where
    each joins a site or mid, and chokepoints at the one-tile doorways; the sites' crates should leave loops round them.
    """
    rng = np.random.default_rng(seed)
    n, m = int(rng.integers(92, 101)), int(rng.integers(86, 95))
    walk, height = np.zeros((n, m), dtype=bool), np.zeros((n, m))
    mid = n // 2 + int(rng.integers(-2, 3))
    t_half, ct_half = int(rng.integers(6, 8)), int(rng.integers(5, 7))
    walk[mid - t_half:mid + t_half, 1:8] = True  # the attackers' yard
    walk[mid - ct_half:mid + ct_half, m - 7:m - 1] = True  # the defenders' yard
    a_size, b_size = int(rng.integers(11, 14)), int(rng.integers(12, 15))
    a0, aj = 2, m - 8 - a_size - int(rng.integers(2, 5))  # site A's south-west tile
    b0, bj = n - 2 - b_size, m - 8 - b_size - int(rng.integers(4, 8))
    walk[a0:a0 + a_size, aj:aj + a_size] = True
    walk[b0:b0 + b_size, bj:bj + b_size] = True
    for i0, j0, size in ((a0, aj, a_size), (b0, bj, b_size)):  # crates, kept off the sites' rims
        for _ in range(int(rng.integers(5, 9))):
            w, d = rng.integers(1, 3, 2)
            ci, cj = i0 + int(rng.integers(3, size - 3 - w)), j0 + int(rng.integers(3, size - 3 - d))
            walk[ci:ci + w, cj:cj + d] = False
    doors_j = int(rng.integers(m // 2 + 3, m // 2 + 7))
    lane = [(mid - 1, mid + 2, 8, m - 7)]  # rectangles (i0, i1, j0, j1) of routes 2-3 tiles wide
    lane.append((2, 5, 3, aj))  # long A up the west edge
    lane.append((2, mid - t_half, 3, 6))  # from the yard west to it
    cross = int(rng.integers(m // 3, m // 2))
    lane.append((mid + t_half, b0 + 4, cross - 6, cross - 3))  # B tunnels: north from the yard, east ...
    lane.append((mid + t_half, mid + t_half + 4, 2, cross - 3))
    lane.append((b0 + 2, b0 + 5, cross - 6, bj))  # ... then north into B
    lane.append((mid - 2, mid + 2, m - 7, m - 6))
    lane.append((a0 + a_size, mid - ct_half, m - 6, m - 3))  # the defenders' ways to A and B
    lane.append((mid + ct_half, b0 + 3, m - 6, m - 3))
    lane.append((b0 + 3, b0 + 6, bj + b_size, m - 3))
    lane.append((a0 + 4, a0 + 7, aj + a_size, m - 3))
    for i0, i1, j0, j1 in lane:
        walk[i0:i1, j0:j1] = True
    walk[mid - 1:mid + 2, doors_j] = False  # the mid doors: one tile open
    walk[mid, doors_j] = True
    walk[2:5, aj - 6] = False  # long A's doorway
    walk[3, aj - 6] = True
    short_j = cross + int(rng.integers(1, 3))
    _paint(walk, np.array([mid - 2, short_j]), np.array([a0 + a_size + 1, short_j]), 0)  # short A, then north
    _paint(walk, np.array([a0 + a_size + 1, short_j]), np.array([a0 + a_size + 1, aj + 1]), 0)
    _paint(walk, np.array([a0 + a_size + 1, aj + 1]), np.array([a0 + a_size - 1, aj + 1]), 0)
    conn_j = int(rng.integers(max(doors_j + 2, bj + 1), bj + b_size - 2))
    _paint(walk, np.array([mid + 2, conn_j]), np.array([b0 - 1, conn_j]), 0)  # mid to B
    walk[[0, -1], :] = walk[:, [0, -1]] = False
    _tile_rooms(rng, walk, lane, 120)
    _tile_crates(rng, walk, lane)
    height[a0:a0 + a_size, aj:aj + a_size] = 0.9
    for k in range(1, 7):  # six risers down every way off the plateau
        ring = np.zeros_like(walk)
        ring[max(a0 - k, 0):a0 + a_size + k, max(aj - k, 0):aj + a_size + k] = True
        height[ring & (height == 0.0)] = round(0.9 - 0.15 * k, 2)
    floor = np.where(walk, np.maximum(height, 0.0), np.nan)
    _tiles(s := _Solids(), floor, 2.0, 3.0)
    return s.mesh()


def payload(seed: int, along: tuple[int, int] = (170, 186)) -> trimesh.Trimesh:
    """A payload (escort) map on 2 m tiles (:func:`_tiles`) over gently rolling ground (:func:`_rolling`: up to about
    1.3 m of relief, every step between tiles 0.15 m), 170-185 x 50-56 tiles (340-370 x 100-112 m): one road 10 m wide
    (5 tiles) winding from the attackers' spawn yard at the west edge to the defenders' base at the east, legs along x
    of 12-20 tiles and jogs along z of 6-12, widened into two checkpoint squares (8 tiles) a third and two thirds of
    the way along it. Along most legs (each with probability 0.8) a side route: an alley 2 m wide 8 tiles (16 m) to
    one side of the road's middle, joined to the road at both ends by cross alleys, and between road and alley 1-3
    flanking buildings (rooms 4-6 x 3 tiles) each entered by a one-tile door from the road and another from the alley;
    2-4 crates (rock tiles) in each checkpoint square, crates against the road's walls (:func:`_tile_crates`) and up to
    200 tries of shops off it behind one-tile doors (:func:`_tile_rooms`). The rest is town blocks: rock ridged at 50
    degrees over 3 m walls.

    Expected (written before the first run): one area. Traffic highest along the road, above all on its middle third
    (every trip between the two halves passes it), lower on the side routes and lowest in the flanking buildings' rooms
    and the spawn's and base's far corners; the checkpoint squares busy. A designer expects the structure to follow the
    road as one chain with loops where each side route leaves and rejoins it, a node in each flanking building on its
    loop, and no terminals but in the yards' corners and the checkpoints' crate bays.

    ``along`` bounds the map's tiles along x (low inclusive, high exclusive): a shorter road by the same rules (the same
    level for the default, the one the docstring describes).
    """
    rng = np.random.default_rng(seed)
    n, m = int(rng.integers(*along)), int(rng.integers(50, 57))
    walk = np.zeros((n, m), dtype=bool)
    points, x, z = [np.array([8, m // 2])], 8, m // 2
    while x < n - 14:
        x = min(x + int(rng.integers(12, 21)), n - 10)
        points.append(np.array([x, z]))
        if x < n - 14:
            z = int(np.clip(z + rng.choice([-1, 1]) * int(rng.integers(6, 13)), 9, m - 10))
            points.append(np.array([x, z]))
    for a, b in pairwise(points):
        _paint(walk, a, b, 2)
    walk[1:9, m // 2 - 7:m // 2 + 7] = True  # the spawn yard
    walk[n - 11:n - 1, z - 6:z + 6] = True  # the base
    lengths = np.cumsum([0] + [int(np.abs(b - a).sum()) for a, b in pairwise(points)])
    for share in (1 / 3, 2 / 3):  # the checkpoints, with crates
        k = int(np.searchsorted(lengths, share * lengths[-1])) - 1
        a, b = points[k], points[k + 1]
        c = a + (b - a) * (share * lengths[-1] - lengths[k]) / max(lengths[k + 1] - lengths[k], 1)
        ci, cj = int(c[0]), int(c[1])
        walk[ci - 4:ci + 4, cj - 4:cj + 4] = True
        for _ in range(int(rng.integers(2, 5))):
            walk[ci + int(rng.integers(-3, 3)), cj + rng.choice([-3, 2])] = False
    for a, b in pairwise(points):
        if a[1] != b[1] or b[0] - a[0] < 12 or rng.random() > 0.8:
            continue
        side = int(rng.choice([-1, 1]))
        j = a[1] + side * 8
        if not 2 <= j < m - 2:
            continue
        i0, i1 = a[0] + 2, b[0] - 2
        _paint(walk, np.array([i0, j]), np.array([i1, j]), 0)  # the alley
        for i in (i0, i1):  # the cross alleys
            _paint(walk, np.array([i, j]), np.array([i, a[1]]), 0)
        edge = a[1] + side * 3  # the road's first tile row of rock on that side
        i = i0 + 2
        for _ in range(int(rng.integers(1, 4))):
            w = int(rng.integers(4, 7))
            if i + w > i1 - 1:
                break
            rows = sorted((edge + side, edge + side * 3))
            walk[i:i + w, rows[0]:rows[1] + 1] = True
            walk[i + int(rng.integers(0, w)), edge] = True  # door from the road
            walk[i + int(rng.integers(0, w)), edge + side * 4] = True  # door onto the alley through its wall row
            i += w + int(rng.integers(1, 3))
    walk[[0, -1], :] = walk[:, [0, -1]] = False
    road = [(min(a[0], b[0]) - 2, max(a[0], b[0]) + 3, min(a[1], b[1]) - 2, max(a[1], b[1]) + 3)
            for a, b in pairwise(points)]
    _tile_rooms(rng, walk, road, 200)
    _tile_crates(rng, walk, road)
    height = _rolling(rng, (n, m))
    floor = np.where(walk, height, np.nan)
    _tiles(s := _Solids(), floor, 2.0, float(height.max()) + 3.0)
    return s.mesh()


def tower_defence(seed: int) -> trimesh.Trimesh:
    """A tower-defence maze on 2 m tiles (:func:`_tiles`): one lane 6 m wide (3 tiles) in 11-13 legs along x, each 40-46
    tiles (80-92 m) long, switching back at alternate ends through the wall strips (3 tiles, 6 m thick) between legs,
    from a spawn gate at the west end of the first leg to a base (8 x 6 tiles) past the end of the last. Build pads 2
    tiles square, raised 0.3 m (one step, under the climb), are notched 2 tiles deep into the wall strips, every 3-5
    tiles along them, alternately from the leg below and the leg above, so each is a dead-end bay off one leg. The
    rest is rock ridged at 50 degrees over 3 m walls.

    Expected (written before the first run): one area, one long chain with no loop. Traffic, all-pairs walking flow on a
    chain, peaks in the middle legs and falls towards the spawn and the base (as on the platform tower of the
    twenty-second round); the pads lowest. A designer expects the structure to be one chain of nodes down the lane,
    a node at each turn, with a short spur (or terminal) into each pad, and nothing crossing the wall strips.
    """
    rng = np.random.default_rng(seed)
    legs, length, w, t = int(rng.integers(11, 14)), int(rng.integers(40, 47)), 3, 3
    n, m = 1 + w + length + w + 1, 1 + legs * w + (legs - 1) * t + 7
    floor = np.full((n, m), np.nan)
    for r in range(legs):
        j0 = 1 + r * (w + t)
        floor[1 + w:1 + w + length, j0:j0 + w] = 0.0
        if r + 1 < legs:  # the turn to the next leg, at the east end after an even leg
            i0 = 1 + w + length if r % 2 == 0 else 1
            floor[i0:i0 + w, j0:j0 + 2 * w + t] = 0.0
    floor[1:1 + w, 1:1 + w] = 0.0  # the spawn gate
    last = 1 + (legs - 1) * (w + t)
    base_i = 1 + w + length if (legs - 1) % 2 == 0 else 1
    floor[base_i:base_i + w, last:m - 1] = 0.0
    floor[base_i - 5 if base_i > 1 else 1:base_i + w if base_i > 1 else 9, m - 7:m - 1] = 0.0  # the base
    for r in range(legs - 1):
        j_low = 1 + r * (w + t) + w  # the strip's first row
        i, below = 1 + w + int(rng.integers(1, 4)), bool(rng.integers(2))
        while i + 2 <= w + length - 1:
            j0 = j_low if below else j_low + t - 2
            floor[i:i + 2, j0:j0 + 2] = 0.3
            i, below = i + int(rng.integers(3, 6)), not below
    _tiles(s := _Solids(), floor, 2.0, 3.0)
    return s.mesh()


def _hub_zone(rng: np.random.Generator, kind: str, size: int) -> np.ndarray:
    """A themed zone of :func:`hub_world`: floor heights (size, size) of 2 m tiles, NaN for rock, entered from the middle
    of its edge j = 0. ``kind`` "rooms" (a 3 x 3 grid of rooms 5 tiles square behind walls of one tile, joined by
    one-tile doors along a random spanning tree: dead ends), "pillars" (open floor, 12 % of it single rock tiles),
    "terraces" (a stepped hill rising a riser of 0.15 m a tile from the rim to 1.5 m, two rocks on it), "maze" (a
    perfect maze of corridors one tile wide: a random spanning tree of cells two tiles apart) or "caves" (a random
    spanning tree of tunnels three tiles wide between junctions on a jittered 5-tile lattice, chambers at three of
    them). O(size^2 log size)."""
    floor = np.full((size, size), np.nan)
    centre = size // 2
    if kind == "pillars":
        floor[1:-1, 1:-1] = 0.0
        rocks = rng.random((size, size)) < 0.12
        rocks[centre - 2:centre + 3, :4] = False
        floor[rocks] = np.nan
    elif kind == "terraces":
        floor[1:-1, 1:-1] = 0.0
        gi, gj = np.meshgrid(np.arange(size), np.arange(size), indexing="ij")
        rim = np.minimum.reduce([gi - 1, gj - 1, size - 2 - gi, size - 2 - gj])
        floor[1:-1, 1:-1] = np.minimum(rim[1:-1, 1:-1], 10) * 0.15
        for _ in range(2):
            p = rng.integers(4, size - 4, 2)
            floor[p[0]:p[0] + 2, p[1]:p[1] + 2] = np.nan
    else:
        step, first, brush = {"rooms": (6, 1, 0), "maze": (2, 1, 0), "caves": (5, 2, 1)}[kind]
        span = range(first, first + 3 * step, step) if kind == "rooms" else range(first, size - 2, step)
        cells = [(a, b) for a in span for b in span]
        index = {c: k for k, c in enumerate(cells)}
        edges = [(index[c], index[c[0] + da, c[1] + db]) for c in cells for da, db in ((step, 0), (0, step))
                 if (c[0] + da, c[1] + db) in index]
        weight = sp.coo_matrix((rng.uniform(1.0, 2.0, len(edges)), tuple(np.array(edges).T)), shape=(len(cells),) * 2)
        tree = minimum_spanning_tree(weight.tocsr()).tocoo()
        walk = np.zeros((size, size), dtype=bool)
        points = np.array(cells) + (rng.integers(-1, 2, (len(cells), 2)) if kind == "caves"
                                    else 2 if kind == "rooms" else 0)  # rooms: their centres
        for u, v in zip(tree.row, tree.col):
            _paint(walk, points[u], points[v], brush)
        if kind == "rooms":
            for a, b in cells:
                walk[a:a + 5, b:b + 5] = True
        if kind == "caves":
            for k in rng.choice(len(cells), size=3, replace=False):
                walk[points[k][0] - 2:points[k][0] + 3, points[k][1] - 2:points[k][1] + 3] = True
        near = points[np.argmin(np.abs(points[:, 0] - centre) + points[:, 1])]
        _paint(walk, np.array([centre, 1]), near, brush)
        walk[[0, -1], :] = walk[:, [0, -1]] = False
        floor[walk] = 0.0
    floor[centre - 1:centre + 1, :2] = 0.0  # the entrance, two tiles wide
    return floor


def hub_world(seed: int) -> trimesh.Trimesh:
    """A hub world on 2 m tiles (:func:`_tiles`): a round plaza 10-12 tiles in radius (40-48 m across) with a fountain
    (rock 2 tiles square) in its middle and four portals on its rim, one a side: each an arch (a lintel 2.6 m up,
    ridged at 50 degrees) over a wing 2 tiles wide and 8-12 long out to a themed zone 26-30 tiles square
    (:func:`_hub_zone`), a dead-end cluster of one of five kinds (rooms behind doors, a pillar field, a stepped hill,
    a maze, caves), four of the five drawn at random, one a wing. The rest is rock ridged at 50 degrees over 3 m walls.

    Expected (written before the first run): one area, a tree of five parts joined only at the plaza. Traffic highest
    on the plaza and in the four wings (every trip between zones crosses the plaza through two wings), then at each
    zone's entrance; lowest in the zones' dead ends (the maze's and rooms' far ends, the hill's top). A designer
    expects the structure to be a star: a loop or hub round the fountain, each wing one edge through its portal (a
    chokepoint), and in each zone its own pattern: a tree in the maze and caves, a node a room, a coarse net among the
    pillars and on the hill.
    """
    rng = np.random.default_rng(seed)
    radius, wing, size = int(rng.integers(10, 13)), int(rng.integers(8, 13)), int(rng.integers(26, 31))
    half = radius + wing + size + 1
    n = 2 * half + 1
    floor = np.full((n, n), np.nan)
    gi, gj = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    floor[(gi - half) ** 2 + (gj - half) ** 2 <= radius ** 2] = 0.0
    floor[half - 1:half + 1, half - 1:half + 1] = np.nan  # the fountain
    kinds = rng.permutation(["rooms", "pillars", "terraces", "maze", "caves"])[:4]
    s = _Solids()
    for turn, kind in enumerate(kinds):
        local = np.full((n, n), np.nan)  # the wing and zone built south of the plaza (j < half), then turned
        local[half - 1:half + 1, half - radius - wing:half - radius + 1] = 0.0
        zone = _hub_zone(rng, str(kind), size)
        z0 = half - radius - wing - size
        local[half - size // 2:half - size // 2 + size, z0:z0 + size] = zone[:, ::-1]
        turned = np.rot90(local, turn)
        floor = np.where(np.isnan(floor), turned, floor)
        # the portal's arch on the plaza's rim, turned with the wing: (x0, x1, z0, z1) in tiles about the centre
        rect = np.array([[half - 1, half - radius - 1], [half + 1, half - radius]], dtype=float)
        for _ in range(turn):
            rect = np.array([[n - r[1], r[0]] for r in rect])
        lo, hi = rect.min(axis=0) * 2.0, rect.max(axis=0) * 2.0
        _ridged(s, lo[0], hi[0], lo[1], hi[1], 2.6, 3.0)
    floor[[0, -1], :] = floor[:, [0, -1]] = np.nan
    _tiles(s, floor, 2.0, 3.0)
    return s.mesh()


def _flight_through(s: _Solids, foot: np.ndarray, heading: np.ndarray, width: float, y0: float, y1: float,
                    holes: list[tuple[float, float, float, float]]) -> tuple[float, float, float, float]:
    """A flight from ``y0`` up to ``y1`` (risers of at most 0.18 m, treads 0.30 m) along the unit ``heading`` (x or z)
    from the plan point ``foot`` (the middle of its first step's near side), rising through a hole it adds to
    ``holes`` (the upper slab's), whose rails (1.1 m, :func:`_rail_ring`) are open only at its top, where it meets the
    upper floor head-on. Returns the flight's plan (x0, x1, z0, z1)."""
    steps = math.ceil((y1 - y0) / 0.18 - 1e-9)
    top = foot + heading * 0.30 * steps
    run = _flight_to(s, top, heading, width, y0, y1)
    side = np.array([-heading[1], heading[0]]) * width / 2
    corners = np.array([foot - side, foot + side, top - side, top + side])
    (x0, z0), (x1, z1) = corners.min(axis=0), corners.max(axis=0)
    holes.append((x0, x1, z0, z1))
    open_side = {(1.0, 0.0): "east", (-1.0, 0.0): "west", (0.0, 1.0): "north", (0.0, -1.0): "south"}
    _rail_ring(s, x0 - 0.1, x1 + 0.1, z0 - 0.1, z1 + 0.1, y1, {open_side[tuple(heading)]: [(0.0, run + width)]})
    return x0, x1, z0, z1


def metroidvania(seed: int, across: tuple[int, int] = (9, 12)) -> trimesh.Trimesh:
    """A metroidvania's castle as a grid of cells, 9-11 across (x) and 5-6 storeys (y, 5 m apart), each cell a room 16 m
    along x and 12 m deep (z), inside outer walls. Cells are joined along a random spanning tree of the grid plus a
    quarter of the other neighbour pairs (the backtracking loops): side by side through a doorway 2 m wide in the
    partition (lintel 2.3 m up, :func:`_doored_wall`) or, with probability 0.3, by no partition at all (a hall two
    cells long); one above the other by a flight (risers 0.18 m, 28 of them, 8.4 m) or, a third of the time, a ramp
    at 25 degrees (10.7 m), both 2.4 m wide along the lower cell's back wall (from an even storey) or front wall (from
    an odd one, so a cell's flight up never stands in the hole of its flight from below) and rising through a railed
    hole in the slab above (:func:`_flight_through`). Each cell holds 0-2 crates (ridged, 1.2 m) clear of its doors and
    shafts.

    Expected (written before the first run): one area. Traffic highest on the vertical links of the middle columns and
    on the cells of the middle storeys that the spanning tree makes cut vertices, lowest in dead-end cells (a cell of
    one link); with the loops few cells are dead ends. A designer expects one structure node or two a room, an edge
    through every door and up every flight or ramp (a chokepoint where a link is a bridge of the tree), loops where
    the extra links close them, and a terminal in each dead-end cell.

    ``across`` bounds the cells across (low inclusive, high exclusive): a smaller castle of the same rules (the same
    level for the default, the one the docstring describes).
    """
    rng = np.random.default_rng(seed)
    cols, storeys, cell_x, cell_z, storey = int(rng.integers(*across)), int(rng.integers(5, 7)), 16.0, 12.0, 5.0
    cells = [(c, r) for c in range(cols) for r in range(storeys)]
    index = {c: k for k, c in enumerate(cells)}
    pairs = [(index[c, r], index[c + dc, r + dr]) for c, r in cells for dc, dr in ((1, 0), (0, 1))
             if (c + dc, r + dr) in index]
    weight = sp.coo_matrix((rng.uniform(1.0, 2.0, len(pairs)), tuple(np.array(pairs).T)), shape=(len(cells),) * 2)
    tree = minimum_spanning_tree(weight.tocsr()).tocoo()
    links = set(zip(tree.row.tolist(), tree.col.tolist()))
    links |= {p for p in pairs if p not in links and (p[1], p[0]) not in links and rng.random() < 0.25}
    links = {tuple(sorted(p)) for p in links}
    s = _Solids()
    width, depth = cols * cell_x, cell_z
    holes: dict[int, list[tuple[float, float, float, float]]] = {r: [] for r in range(storeys)}
    keep: dict[tuple[int, int], list[tuple[float, float, float, float]]] = {c: [] for c in cells}
    for u, v in sorted(links):
        (c, r), (c2, r2) = cells[u], cells[v]
        if r2 == r + 1:  # a flight or ramp along the back wall (even storeys) or front wall (odd) of the lower cell
            heading = np.array([1.0, 0.0]) if rng.random() < 0.5 else np.array([-1.0, 0.0])
            x_start = c * cell_x + (2.5 if heading[0] > 0 else cell_x - 2.5)
            foot = np.array([x_start, depth - 1.7 if r % 2 == 0 else 1.7])
            y0, y1 = r * storey, (r + 1) * storey
            if rng.random() < 1 / 3:
                run = storey / math.tan(math.radians(25.0))
                top = foot + heading * run
                s.ramp(foot, top, 2.4, y0, y1)
                x0, x1 = sorted((foot[0], top[0]))
                plan = (x0, x1, foot[1] - 1.2, foot[1] + 1.2)
                holes[r + 1].append(plan)
                _rail_ring(s, x0 - 0.1, x1 + 0.1, plan[2] - 0.1, plan[3] + 0.1, y1,
                           {"east" if heading[0] > 0 else "west": [(0.0, 40.0)]})
            else:
                plan = _flight_through(s, foot, heading, 2.4, y0, y1, holes[r + 1])
            for level in (r, r + 1):
                keep[c, level].append((plan[0] - 2.0, plan[1] + 2.0, plan[2] - 2.0, plan[3] + 2.0))
    for r in range(storeys):
        y = r * storey
        for c in range(1, cols):  # partitions
            x = c * cell_x
            link = tuple(sorted((index[c - 1, r], index[c, r])))
            if link in links and rng.random() < 0.3:
                continue
            doors = []
            if link in links:
                start = float(rng.uniform(1.0, depth - 4.5))
                doors = [(start, 2.0, "open", 1)]
                for cc in (c - 1, c):
                    keep[cc, r].append((x - 3.0, x + 3.0, start - 1.0, start + 3.0))
            _doored_wall(s, (x, 0.0), (x, depth), y, y + storey - 0.3, doors)
        for c in range(cols):
            for _ in range(int(rng.integers(0, 3))):
                p = rng.uniform([c * cell_x + 1.5, 1.0], [(c + 1) * cell_x - 3.0, depth - 4.0])
                if _clear(p[0] - 1.5, p[0] + 3.0, p[1] - 1.5, p[1] + 3.0, keep[c, r]):
                    _ridged(s, p[0], p[0] + 1.5, p[1], p[1] + 1.5, y - 0.1, y + 1.2)
                    keep[c, r].append((p[0], p[0] + 1.5, p[1], p[1] + 1.5))
        s.ground(0.0, width, 0.0, depth, y, holes[r], 0.3)
    for a, b in (((0.0, 0.0), (width, 0.0)), ((0.0, depth), (width, depth)), ((0.0, 0.0), (0.0, depth)),
                 ((width, 0.0), (width, depth))):
        s.wall(a, b, -0.5, storeys * storey, thickness=0.4)
    return s.mesh()


def stealth_mansion(seed: int) -> trimesh.Trimesh:
    """A stealth game's mansion in its grounds, 120-140 x 80-95 m inside a boundary wall 3 m high with a gate 4 m wide
    in its south side. The house, 64-74 x 22.2 m, has two storeys 4 m apart on a plinth: its ground floor is 1.08 m up
    (six risers of 0.18 m up the front steps, the same down the back steps from the servants' corridor by the
    kitchen), over a crawlspace 0.78 m high whose grates (openings 0.9 m wide, 0.6 m high) pierce the plinth's front
    and back every 7-10 m. On each storey, along x: front rooms 9.5 m deep (7-11 m wide; the entrance hall, 10 m, behind
    the front door), the hall 4 m wide the whole length, back rooms 6.8 m deep, and behind them the servants'
    corridor 1.7 m wide, joined to the hall only by a service passage 4 m wide at the west end and to every back room
    by a door; doors 1.6 m wide (lintels 2.3 m up, :func:`_doored_wall`) from each front room to the hall, from 60 % of
    the back rooms to the hall, between neighbouring rooms 40 % of the time; half the other partitions hold a vent
    (an opening 0.8 m wide and 0.9 m high, too low for the agent). Two flights (risers 0.18 m, 1.6 m wide) rise
    through railed holes (:func:`_flight_through`): the grand stair in the entrance hall against its east partition,
    arriving head-on at a doorway into the upper hall, and the servants' stair in the service passage, arriving at the
    upper servants' corridor. Rooms are furnished (:func:`_furnish`), under a roof ridged at 50 degrees
    (:func:`_gable`). The front garden holds four hedged parterres (hedges 1.8 m high, ridged, each entered by one gap
    2 m wide, a statue in the middle) either side of the drive; the grounds 20-30 trees (where they fit) and, behind
    the house, two outbuildings (rooms 8 x 6 m, one door each).

    Expected (written before the first run): one area for the grounds and both storeys (the crawlspace and the vents
    hold no floor: no way under the house or through a vent). Traffic highest on the drive and the front steps, the
    ground floor's hall (the spine of the house), the grand stair and the back steps (the second way in); the
    servants' corridors middling, a parallel way to each hall; lowest in the parterres, the outbuildings and the end
    rooms reached through other rooms, and on the upper storey, reached by two stairs only. A designer expects the
    structure to follow each hall and servants' corridor as two parallel chains joined through the back rooms and the
    service passage, a node in each room and each parterre, an edge up each stair, and the garden as a coarse net
    round the house.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    gx, gz = rng.uniform(120.0, 140.0), rng.uniform(80.0, 95.0)
    w, d, floor, storey = rng.uniform(64.0, 74.0), 22.2, 1.08, 4.0
    upper, y1 = floor + storey, floor + 2 * storey - 0.3  # the upper storey's floor, the walls' top
    hx0, hz0 = (gx - w) / 2, gz * 0.45
    hx1, hz1 = hx0 + w, hz0 + d
    door_x = (hx0 + hx1) / 2 + rng.uniform(-6.0, 6.0)
    for a, b, doors in (((0.0, 0.0), (gx, 0.0), [(gx / 2 - 2.0, 4.0)]), ((0.0, gz), (gx, gz), []),
                        ((0.0, 0.0), (0.0, gz), []), ((gx, 0.0), (gx, gz), [])):
        s.wall(a, b, -0.5, 3.0, doors, thickness=0.4)
    for z in (hz0, hz1):  # the plinth's long sides, pierced by grates into the crawlspace
        grates = [(float(u), 0.9, "open", 1) for u in np.arange(rng.uniform(2.0, 5.0), w - 2.0, rng.uniform(7.0, 10.0))]
        _doored_wall(s, (hx0, z), (hx1, z), 0.0, floor - 0.3, grates, 0.4, lintel=0.6)
    for x in (hx0, hx1):
        s.wall((x, hz0), (x, hz1), -0.5, floor - 0.3, thickness=0.4)
    s.box(hx0, hx1, floor - 0.3, floor, hz0, hz1)  # the ground floor's slab over the crawlspace
    front, hall, back = hz0 + 9.5, hz0 + 13.5, hz0 + 20.3
    kitchen_x, stair_x, passage = hx1 - 4.0, door_x + 4.1, hx0 + 4.0  # the grand stair against the partition
    _flight_to(s, np.array([door_x, hz0]), np.array([0.0, 1.0]), 3.0, 0.0, floor)
    _flight_to(s, np.array([kitchen_x, hz1]), np.array([0.0, -1.0]), 2.0, 0.0, floor)
    holes: list[tuple[float, float, float, float]] = []
    grand = _flight_through(s, np.array([stair_x, hz0 + 1.8]), np.array([0.0, 1.0]), 1.6, floor, upper, holes)
    service = _flight_through(s, np.array([hx0 + 1.0, hall - 0.5]), np.array([0.0, 1.0]), 1.6, floor, upper, holes)
    s.ground(hx0, hx1, hz0, hz1, upper, holes, 0.3)
    for level, y in enumerate((floor, upper)):
        top = y + storey - 0.3 if level == 0 else y1
        outer = ([[(door_x - 1.0 - hx0, 2.0, "open", 1)], [(kitchen_x - 0.8 - hx0, 1.6, "open", 1)]] if level == 0
                 else [[], []])
        _doored_wall(s, (hx0, hz0), (hx1, hz0), y, top, outer[0], 0.4)
        _doored_wall(s, (hx0, hz1), (hx1, hz1), y, top, outer[1], 0.4)
        for x in (hx0, hx1):
            _doored_wall(s, (x, hz0), (x, hz1), y, top, [], 0.4)

        def cuts(x0: float, x1: float) -> list[float]:
            """Partitions from x0 to x1 at 7-11 m, the last room up to 14 m wide."""
            xs = [x0]
            while x1 - xs[-1] > 14.0:
                xs.append(xs[-1] + rng.uniform(7.0, 11.0))
            return [*xs, x1]

        entrance = (door_x - 5.0, door_x + 5.0)  # the entrance hall (the grand stair's landing above it)
        west = [2 * entrance[0] - x for x in cuts(entrance[0], 2 * entrance[0] - hx0)][::-1]  # mirrored from hx0
        front_xs = [*west, *cuts(entrance[1], hx1)]
        doors: dict[float, list[tuple[float, float, str, float]]] = {front: [], hall: [], back: []}  # wall z -> doors
        for z0, z1, xs in ((hz0, front, front_xs), (hall, back, cuts(passage, hx1))):
            for x0, x1 in pairwise(xs):
                approach = [(h[0] - 1.0, h[1] + 1.0, h[2] - 1.5, h[3] + 1.0) for h in (grand, service)]
                if z0 == hz0 or rng.random() < 0.6:  # a door to the hall
                    u = rng.uniform(x0 + 0.6, (door_x - 2.6) if (x0, x1) == entrance else x1 - 2.2)
                    doors[z1 if z0 == hz0 else z0].append((u, 1.6, "open", 1))
                    approach.append((u - 0.5, u + 2.1, z1 - 1.5, z1) if z0 == hz0 else (u - 0.5, u + 2.1, z0, z0 + 1.5))
                if level and (x0, x1) == entrance:  # the grand stair's doorway, head-on at its top
                    doors[front].append((stair_x - 0.9, 1.8, "open", 1))
                if z0 == hall:  # a door to the servants' corridor
                    u = rng.uniform(x0 + 0.6, x1 - 2.2)
                    doors[back].append((u, 1.6, "open", 1))
                    approach.append((u - 0.5, u + 2.1, z1 - 1.5, z1))
                if level == 0 and (x0, x1) == entrance:
                    approach.append((door_x - 1.5, door_x + 1.5, z0, z0 + 2.5))
                _furnish(s, rng, (x0, x1, z0, z1), y, approach, int(rng.integers(2, 5)))
            for x in xs[1:-1]:  # partitions: a door, a vent too low to walk, or neither
                pick, u = rng.random(), rng.uniform(0.8, z1 - z0 - 2.4)
                if pick < 0.4:
                    _doored_wall(s, (x, z0), (x, z1), y, top, [(u, 1.6, "open", 1)])
                else:
                    _doored_wall(s, (x, z0), (x, z1), y, top, [(u, 0.8, "open", 1)] if pick < 0.7 else [], lintel=0.9)
        for z, x0 in ((front, hx0), (hall, passage), (back, passage)):
            _doored_wall(s, (x0, z), (hx1, z), y, top, [(u - x0, wd, leaf, into) for u, wd, leaf, into in doors[z]])
        s.wall((passage, hall), (passage, back), y - 0.5, top)  # the service passage's side
    _gable(s, hx0 - 0.3, hx1 + 0.3, hz0 - 0.3, hz1 + 0.3, y1)
    holes: list[tuple[float, float, float, float]] = []  # the ground runs on under the house: the crawlspace
    taken = [(hx0 - 4.0, hx1 + 4.0, hz0 - 8.0, hz1 + 5.0), (gx / 2 - 5.0, gx / 2 + 5.0, 0.0, hz0)]
    for side in (-1, 1):  # the parterres either side of the drive
        for row in range(2):
            x0 = gx / 2 + side * 8.0 if side > 0 else gx / 2 - 8.0 - 16.0
            z0 = 6.0 + row * (hz0 - 12.0) / 2
            x1, z1 = x0 + 16.0, z0 + (hz0 - 12.0) / 2 - 4.0
            gap = rng.uniform(x0 + 2.0, x1 - 4.0)
            for c0, c1, z in ((x0 - 0.4, x1 + 0.4, z0), (x0 - 0.4, gap, z1), (gap + 2.0, x1 + 0.4, z1)):
                _ridged(s, c0, c1, z - 0.4, z + 0.4, -0.1, 1.8)
            for x in (x0, x1):
                _ridged(s, x - 0.4, x + 0.4, z0 + 0.4, z1 - 0.4, -0.1, 1.8)
            _ridged(s, (x0 + x1) / 2 - 0.5, (x0 + x1) / 2 + 0.5, (z0 + z1) / 2 - 0.5, (z0 + z1) / 2 + 0.5, -0.1, 2.5)
            taken.append((x0 - 1.0, x1 + 1.0, z0 - 1.0, z1 + 1.0))
    for k in range(2):  # the outbuildings behind the house
        for _ in range(50):
            x0, z0 = rng.uniform(4.0, gx - 12.0), rng.uniform(hz1 + 6.0, gz - 10.0)
            if _clear(x0 - 3.0, x0 + 11.0, z0 - 3.0, z0 + 9.0, taken):
                break
        taken.append((x0 - 3.0, x0 + 11.0, z0 - 3.0, z0 + 9.0))
        _doored_wall(s, (x0, z0), (x0 + 8.0, z0), 0.0, 3.0, [(rng.uniform(1.0, 5.4), 1.6, "open", 1)])
        _doored_wall(s, (x0, z0 + 6.0), (x0 + 8.0, z0 + 6.0), 0.0, 3.0, [])
        for x in (x0, x0 + 8.0):
            _doored_wall(s, (x, z0), (x, z0 + 6.0), 0.0, 3.0, [])
        _gable(s, x0 - 0.3, x0 + 8.3, z0 - 0.3, z0 + 6.3, 3.0)
    _trees(s, rng, int(rng.integers(20, 31)), gx, gz, taken, (0.2, 0.4), 8.0)
    s.ground(0.0, gx, 0.0, gz, 0.0, holes)
    return s.mesh()


def _tile_building(rng: np.random.Generator, walk: np.ndarray, rect: tuple[int, int, int, int], doors: int,
                   door_width: int = 1) -> bool:
    """A building of one or two rooms drawn on tiles: the rectangle ``rect`` (i0, i1, j0, j1) of ``walk`` (n, m) becomes
    a shell of rock one tile thick round its inside; an inside 7 or more tiles along i is parted across i by a wall of
    rock with a door one tile wide (the inner room a dead end behind the outer), and ``doors`` openings
    ``door_width`` tiles wide go through the shell at random places on the outer room's sides, each onto an open tile
    outside. Drawn only where the rectangle and a ring of two tiles round it are all open floor; returns whether it was.
    O(rect's area)."""
    i0, i1, j0, j1 = rect
    n, m = walk.shape
    if i0 < 3 or j0 < 3 or i1 > n - 3 or j1 > m - 3 or not walk[i0 - 2:i1 + 2, j0 - 2:j1 + 2].all():
        return False
    walk[i0:i1, j0:j1] = False
    walk[i0 + 1:i1 - 1, j0 + 1:j1 - 1] = True
    outer = (i0, i1)  # the outer room's span along i
    if i1 - i0 - 2 >= 7:
        cut = i0 + 1 + int(rng.integers(3, i1 - i0 - 5))
        walk[cut, j0 + 1:j1 - 1] = False
        walk[cut, int(rng.integers(j0 + 1, j1 - 1))] = True
        outer = (cut, i1) if rng.random() < 0.5 else (i0, cut + 1)
    made = 0
    for _ in range(20 * doors):
        if made == doors:
            break
        side = int(rng.integers(4))
        if side < 2:  # through a wall along i (the j0 or the j1 side)
            if outer[1] - outer[0] - 2 < door_width:
                continue
            i = int(rng.integers(outer[0] + 1, outer[1] - door_width))
            walk[i:i + door_width, j0 if side == 0 else j1 - 1] = True
            made += 1
        else:  # through an end wall (2 the low-i one, 3 the high-i one) of the outer room
            if outer[side - 2] != (i0, i1)[side - 2] or j1 - j0 - 2 < door_width:
                continue
            j = int(rng.integers(j0 + 1, j1 - door_width))
            walk[i0 if side == 2 else i1 - 1, j:j + door_width] = True
            made += 1
    return True


def _tile_cover(rng: np.random.Generator, walk: np.ndarray, count: int, tries: int, margin: int,
                allowed: Callable[[tuple[slice, slice]], bool]) -> None:
    """Up to ``count`` cover blocks of rock, 1 x 2 or 2 x 1 tiles, in ``walk`` (n, m) from ``tries`` random places: each
    where the box of tiles ``margin`` round it is all open floor and ``allowed`` (given that box's slices) holds, so no
    block closes a way another leaves open. O(tries margin^2)."""
    n, m = walk.shape
    for _ in range(tries):
        if count == 0:
            break
        i, j = int(rng.integers(2, n - 3)), int(rng.integers(2, m - 3))
        di, dj = (1, 2) if rng.random() < 0.5 else (2, 1)
        box = (slice(i - margin, i + di + margin), slice(j - margin, j + dj + margin))
        if walk[box].all() and allowed(box):
            walk[i:i + di, j:j + dj] = False
            count -= 1


def military_base(seed: int, scale: float = 1.0) -> trimesh.Trimesh:
    """A battle-royale compound on 2 m tiles (:func:`_tiles`) on flat ground, 100-110 x 90-100 tiles (200-220 x 180-200 m): in its middle a fenced compound 50-60 x 40-48
    tiles (its yard paved 0.15 m up, one step) inside a fence one tile thick, open at 3-4 gates 2 tiles (4 m) wide on different sides; in the compound a
    hangar (14-16 x 10-12 tiles, a door 3 tiles wide, a parted-off workshop) and up to 7 buildings 7-11 x 6-8 tiles, in
    the field outside up to 12 sheds 5-6 tiles square, each a shell of rock round one or two rooms (the inner one a loot
    room behind a one-tile door) entered by 1-2 doors one tile wide (:func:`_tile_building`), kept two tiles apart;
    watchtowers (rock 2 tiles square) inside the fence's corners and 40-60 cover tiles (rock, 1 x 1 or 1 x 2) where the
    tiles round them are open. Rock stands as walls 4 m high ridged at 50 degrees. Unlike round 22's
    :func:`battle_royale` (houses and rock clusters on open rolling ground, no way between two places shut), every way
    into the compound goes through a gate of its fence, on flat ground.

    Expected (written before the first run): one area. Traffic highest through the gates (every way between the field
    and the compound goes through 3-4 openings 4 m wide) and on the compound's open ground between them, then on the
    field's ring round the fence; lowest in the loot rooms, the sheds and the field's corners. A designer expects the
    structure to show each gate as a chokepoint (a node or an edge through it), a loop round the fence outside and a
    net between the buildings inside, a terminal in each loot room and shed, and edges through the doors.

    ``scale`` multiplies the bounds in tiles of the field, the compound and the hangar (each rounded): a smaller base by
    the same rules (the same level at 1, the one the docstring describes).
    """
    rng = np.random.default_rng(seed)

    def tiles(low: int, high: int) -> int:  # a size in tiles drawn in [low, high) times ``scale``
        return int(rng.integers(round(low * scale), round(high * scale)))

    n, m = tiles(100, 111), tiles(90, 101)
    walk = np.ones((n, m), dtype=bool)
    walk[[0, -1], :] = walk[:, [0, -1]] = False
    cw, cd = tiles(50, 61), tiles(40, 49)
    ci0, cj0 = (n - cw) // 2 + int(rng.integers(-3, 4)), (m - cd) // 2 + int(rng.integers(-3, 4))
    ci1, cj1 = ci0 + cw, cj0 + cd
    inside = np.zeros_like(walk)
    inside[ci0 + 1:ci1 - 1, cj0 + 1:cj1 - 1] = True
    outside = walk.copy()
    outside[ci0 - 3:ci1 + 3, cj0 - 3:cj1 + 3] = False  # sheds keep 3 tiles off the fence
    walk[ci0:ci1, [cj0, cj1 - 1]] = False  # the fence
    walk[[ci0, ci1 - 1], cj0:cj1] = False
    for side in rng.choice(4, size=int(rng.integers(3, 5)), replace=False):  # the gates
        if side < 2:
            i = int(rng.integers(ci0 + 4, ci1 - 6))
            walk[i:i + 2, cj0 if side == 0 else cj1 - 1] = True
        else:
            j = int(rng.integers(cj0 + 4, cj1 - 6))
            walk[ci0 if side == 2 else ci1 - 1, j:j + 2] = True
    for i, j in ((ci0 + 2, cj0 + 2), (ci0 + 2, cj1 - 4), (ci1 - 4, cj0 + 2), (ci1 - 4, cj1 - 4)):  # watchtowers
        walk[i:i + 2, j:j + 2] = False
    hw, hd = tiles(14, 17), tiles(10, 13)
    for _ in range(40):  # the hangar first, then the buildings
        i, j = int(rng.integers(ci0 + 4, ci1 - 4 - hw)), int(rng.integers(cj0 + 4, cj1 - 4 - hd))
        if _tile_building(rng, walk, (i, i + hw, j, j + hd), 1, 3):
            break
    built = 0
    for _ in range(200):
        if built == 7:
            break
        w, d = int(rng.integers(7, 12)), int(rng.integers(6, 9))
        i, j = int(rng.integers(ci0 + 4, ci1 - 4 - w)), int(rng.integers(cj0 + 4, cj1 - 4 - d))
        built += _tile_building(rng, walk, (i, i + w, j, j + d), int(rng.integers(1, 3)))
    sheds = 0
    for _ in range(300):
        if sheds == 12:
            break
        w, d = int(rng.integers(5, 7)), int(rng.integers(5, 7))
        i, j = int(rng.integers(3, n - 3 - w)), int(rng.integers(3, m - 3 - d))
        if outside[i - 2:i + w + 2, j - 2:j + d + 2].all():
            sheds += _tile_building(rng, walk, (i, i + w, j, j + d), 1)
    target = int(rng.integers(40, 61))
    _tile_cover(rng, walk, target, 20 * target, 2, lambda box: True)
    floor = np.where(walk, 0.0, np.nan)
    floor[inside & walk] = 0.15  # the compound's yard, paved one step up
    _tiles(s := _Solids(), floor, 2.0, 4.0)
    return s.mesh()


def king_of_hill(seed: int) -> trimesh.Trimesh:
    """A king-of-the-hill map on 2 m tiles (:func:`_tiles`), 66-74 tiles square (132-148 m) inside rock walls: in the
    middle a stepped hill of four square terraces 1.2 m apart (three times the climb: each edge a ledge one drops off but
    cannot climb), each ring 5-6 tiles wide, round a capture point on the top (4.8 m up, 8-10 tiles square); each step
    is climbed only by two ramps 2 tiles (4 m) wide on two different sides of it, three tiles of 0.3 m risers running
    out from the step onto the ring below. Two spawn rooms (8 x 6 tiles behind a wall of rock with two openings 2 tiles
    wide) at the middles of opposite walls; cover tiles (rock, 1 x 1 or 1 x 2) on every ring, the top and the field,
    kept off the ramps and their approaches. Rock stands as walls 9 m high ridged at 50 degrees.

    Expected (written before the first run): one area. Traffic highest on the field's ring round the hill's foot between
    the two spawns (the way round is shorter than over the top) and at the spawns' openings, then on the first
    terrace's ramps; the capture point and the upper rings low (a dead end for walking flow, however much a designer
    wants players there). A designer expects the structure to show the rings as loops, each ramp as an edge between
    two rings, a node or two on the top, and a chokepoint at each spawn's openings.
    """
    rng = np.random.default_rng(seed)
    n = int(rng.integers(66, 75))
    height = np.zeros((n, n))
    walk = np.ones((n, n), dtype=bool)
    walk[[0, -1], :] = walk[:, [0, -1]] = False
    c = n // 2
    radii = [int(rng.integers(4, 6))]  # half sizes of the top and then of each ring outwards
    for _ in range(3):
        radii.append(radii[-1] + int(rng.integers(5, 7)))
    gi, gj = np.meshgrid(np.arange(n) - c, np.arange(n) - c, indexing="ij")
    reach = np.maximum(np.abs(gi), np.abs(gj))
    for k, r in enumerate(radii[::-1]):  # terrace k + 1 out to half size r
        height[reach <= r] = 1.2 * (k + 1)
    keep = np.zeros_like(walk)  # the ramps and their approaches, kept clear of cover
    for step in range(4):  # the ramps up to terrace 4 - step (half size radii[step]), on the ring below
        r = radii[step]
        for side in rng.choice(4, size=2, replace=False):
            along = int(rng.integers(-r + 1, r - 2))
            for t in range(3):  # t = 0 the ramp's top tile, next to the step
                out = r + 1 + t
                tiles = [(c + out * (1 if side == 0 else -1), c + along + u) for u in (0, 1)] if side < 2 else \
                    [(c + along + u, c + out * (1 if side == 2 else -1)) for u in (0, 1)]
                for i, j in tiles:
                    height[i, j] = 1.2 * (4 - step) - 0.3 * (t + 1)
            lo = (c + (r + 1) * (1 if side in (0, 2) else -1), c + (r + 6) * (1 if side in (0, 2) else -1))
            span = slice(min(lo) - 1, max(lo) + 2)
            wide = slice(c + along - 2, c + along + 4)
            if side < 2:
                keep[span, wide] = True
            else:
                keep[wide, span] = True
    for wall, rows in ((7, slice(1, 8)), (n - 8, slice(n - 8, n - 1))):  # the spawn rooms
        walk[c - 5:c + 5, wall] = False
        walk[[c - 5, c + 4], rows] = False
        walk[c - 3:c - 1, wall] = walk[c + 1:c + 3, wall] = True
        keep[c - 7:c + 7, max(rows.start - 2, 0):rows.stop + 2] = True
    target = int(rng.integers(50, 71))
    _tile_cover(rng, walk, target, 30 * target, 1, lambda box: not keep[box].any() and np.ptp(height[box]) == 0.0)
    floor = np.where(walk, height, np.nan)
    _tiles(s := _Solids(), floor, 2.0, 9.0)
    return s.mesh()


def favela(seed: int, along: tuple[int, int] = (84, 93)) -> trimesh.Trimesh:
    """A favela on a hillside, on 2 m tiles (:func:`_tiles`), 84-92 tiles along x and 6-7 bands of 12 tiles up the
    slope (z): each band an alley 3 tiles wide at 3 m a band up (the lowest the road) and above it a row of houses 9
    tiles deep, 3-6 tiles wide, whose flat roofs are floor at the next alley's height (so the alley above runs out over
    the roofs below it), each roof flush, a riser (0.3 m) lower or higher, or, one house in six, a taller house of rock
    whose top is out of reach (ridged at 50 degrees); 2-3 stair lanes 2 tiles wide a band climb through the row of houses
    from alley to alley in risers of 0.3 m a tile, and a water tank (rock, one tile) stands on one roof in five. The
    houses' fronts are ledges 2.7-3.3 m high one drops off but cannot climb. Rock stands as walls 3 m over the top
    alley, ridged at 50 degrees.

    Expected (written before the first run): one area (each roof meets the alley above it). Traffic highest on the stair
    lanes (the only ways up a band) and on the alleys between their heads and feet, lowest on roofs far from a stair and
    in the corners of the road. A designer expects the structure to be a ladder: each alley-and-roofs plateau a chain or
    net of nodes joined to the next by one edge up each stair lane; tanks and tall houses leave holes in the roof
    plateaus that the structure loops round.

    ``along`` bounds the tiles along x (low inclusive, high exclusive): a shorter hillside by the same rules (the same
    level for the default, the one the docstring describes).
    """
    rng = np.random.default_rng(seed)
    n, bands = int(rng.integers(*along)), int(rng.integers(6, 8))
    m = 12 * bands + 5
    floor = np.full((n, m), np.nan)
    for b in range(bands + 1):
        floor[1:n - 1, 12 * b + 1:12 * b + 4] = 3.0 * b  # the alleys
    for b in range(bands):
        rows = slice(12 * b + 4, 12 * b + 13)
        i = 1
        while i < n - 1:  # the row of houses
            w = min(int(rng.integers(3, 7)), n - 1 - i)
            kind = rng.random()
            roof = np.nan if kind < 1 / 6 else 3.0 * (b + 1) + (0.3 if kind > 0.85 else -0.3 if kind > 0.7 else 0.0)
            floor[i:i + w, rows] = roof
            if not np.isnan(roof) and rng.random() < 0.2:
                ti, tj = i + int(rng.integers(0, w)), 12 * b + int(rng.integers(5, 11))
                floor[ti, tj] = np.nan
            i += w
        lanes = int(rng.integers(2, 4))
        edges = np.linspace(2, n - 4, lanes + 1).astype(int)
        for a, z in pairwise(edges):
            i = int(rng.integers(a, max(a + 1, z - 2)))
            for t in range(9):
                floor[i:i + 2, 12 * b + 4 + t] = 3.0 * b + 0.3 * (t + 1)
    _tiles(s := _Solids(), floor, 2.0, 3.0 * bands + 3.0)
    return s.mesh()


def _wall_line(s: _Solids, p: np.ndarray, q: np.ndarray, y0: float, y1: float, thickness: float,
               gaps: list[tuple[float, float]]) -> None:
    """A wall at any angle from plan point ``p`` (x, z) to ``q`` between heights y0 < y1, ``thickness`` m thick about
    the line, open over each gap (start, width), metres from ``p`` along it: each piece between the gaps
    (:func:`_pieces`) one prism."""
    p, q = np.asarray(p, dtype=np.float64), np.asarray(q, dtype=np.float64)
    length = float(np.linalg.norm(q - p))
    along = (q - p) / length
    side = np.array([-along[1], along[0]]) * thickness / 2
    for c0, c1 in _pieces(0.0, length, gaps):
        a, b = p + along * c0, p + along * c1
        s.prism(np.array([a - side, b - side, b + side, a + side]), y0, y1)


def _spire(s: _Solids, c: np.ndarray, radius: float, top: float) -> None:
    """A hexagonal pyramid on the plan point ``c`` (x, z), ``radius`` m from its axis to its base's corners, from 0.5 m
    under the floor at 0 up to its apex at ``top``: steep enough that nothing on it is floor when ``top`` is over 1.2
    times ``radius``."""
    base = [c + radius * np.array([math.cos(math.radians(60 * k)), math.sin(math.radians(60 * k))]) for k in range(6)]
    s.hull(np.array([[p[0], y, p[1]] for p in base for y in (-0.5, 0.0)] + [[c[0], top, c[1]]]))


def hive(seed: int, columns: tuple[int, int] = (9, 11)) -> trimesh.Trimesh:
    """An alien hive of hexagonal cells (flat-topped, 7 m from centre to corner, walls 0.3 m thick and 3.5 m high, so
    every wall but those along x runs at 60 degrees to them), 9-10 columns of 7-8 cells, each cell a floor
    of its own (a hexagonal slab: no floor outside the hive). Neighbouring cells are joined along a random spanning tree
    of the cells plus a quarter of the other neighbour pairs by a doorway 2.2 m wide in the middle of their shared
    wall; the cell nearest the middle and its six neighbours are one chamber (the queen's, no walls between them) round
    a pillar (:func:`_spire`). In other cells: with probability 0.35 a pod (a hexagonal pyramid 2 m from its axis to its base's
    corners, 5 m high, too steep to stand on) in the middle, else with probability 0.4 a cluster of 3-6 eggs (rocks 0.6-1.4 m high) off the
    middle. Two entrances, doorways in the outer wall of a westmost cell (facing north-west) and an eastmost cell (facing
    south-east), onto a landing outside each.

    Expected (written before the first run): one area. Traffic highest in the queen's chamber and on the spanning tree's
    cells that join big subtrees (cut cells near the middle), lowest in dead-end cells at the rim. A designer expects one
    structure node in each cell (more round a pod), an edge through each doorway, loops where the extra doorways close
    them, and no node in a doorway; walls at 60 degrees should read as well as those along the axes.

    ``columns`` bounds the columns of cells (low inclusive, high exclusive): a narrower hive by the same rules (the same
    level for the default, the one the docstring describes).
    """
    rng = np.random.default_rng(seed)
    cols, rows, radius = int(rng.integers(*columns)), int(rng.integers(7, 9)), 7.0
    centres = {(q, r): np.array([1.5 * radius * q, math.sqrt(3.0) * radius * (r + 0.5 * (q % 2))])
               for q in range(cols) for r in range(rows)}
    corner = [radius * np.array([math.cos(math.radians(60 * k)), math.sin(math.radians(60 * k))]) for k in range(6)]
    s = _Solids()
    for c in centres.values():
        s.prism(np.array([c + v for v in corner]), -0.5, 0.0)
    middle = np.mean(list(centres.values()), axis=0)
    queen = min(centres, key=lambda k: float(np.linalg.norm(centres[k] - middle)))
    keys = list(centres)
    index = {k: i for i, k in enumerate(keys)}
    at = {tuple(np.round(c, 3)): k for k, c in centres.items()}
    edges: dict[tuple[int, int], tuple[int, int]] = {}  # (cell, neighbour; -1 - side outside) -> (cell, side)
    for k in keys:
        for e in range(6):  # the wall between corners e and e + 1 faces the direction 60 e + 30 degrees
            other = at.get(tuple(np.round(centres[k] + corner[e] + corner[(e + 1) % 6], 3)))
            if other is None:
                edges[index[k], -1 - e] = (index[k], e)
            elif index[other] > index[k]:
                edges[index[k], index[other]] = (index[k], e)
    near = [(a, b) for a, b in edges if b >= 0]
    weights = rng.uniform(1.0, 2.0, len(near))
    graph = sp.coo_matrix((weights, ([a for a, _ in near], [b for _, b in near])), shape=(len(keys),) * 2)
    tree = {tuple(sorted(p)) for p in zip(*minimum_spanning_tree(graph.tocsr()).nonzero())}
    open_pairs = {p for p in near if tuple(sorted(p)) in tree or rng.random() < 0.25}
    chamber = {index[queen]} | {b if a == index[queen] else a for a, b in near if index[queen] in (a, b)}
    west = min(keys, key=lambda k: (centres[k][0], abs(k[1] - rows // 2)))
    east = max(keys, key=lambda k: (centres[k][0], -abs(k[1] - rows // 2)))
    entrances = {(index[west], -1 - 2), (index[east], -1 - 5)}
    for (a, b), (cell, e) in edges.items():
        if a in chamber and b in chamber:
            continue
        p, q = centres[keys[cell]] + corner[e], centres[keys[cell]] + corner[(e + 1) % 6]
        gaps = [(radius / 2 - 1.1, 2.2)] if (a, b) in open_pairs or (a, b) in entrances else []
        _wall_line(s, p, q, -0.5, 3.5, 0.3, gaps)
    for key in (west, east):  # landings outside the entrances
        e = 2 if key == west else 5
        c = centres[key]
        out = (corner[e] + corner[(e + 1) % 6]) / np.linalg.norm(corner[e] + corner[(e + 1) % 6])
        mid = c + (corner[e] + corner[(e + 1) % 6]) / 2
        along = np.array([-out[1], out[0]])
        s.prism(np.array([mid - along * 3, mid + along * 3, mid + along * 3 + out * 6, mid - along * 3 + out * 6]),
                -0.5, 0.0)
    _spire(s, centres[queen], 1.75, 8.0)  # the queen's pillar
    for k in keys:
        if index[k] in chamber:
            continue
        c = centres[k]
        if rng.random() < 0.35:
            _spire(s, c, 2.0, 5.0)
        elif rng.random() < 0.4:
            spot = c + rng.uniform(-2.5, 2.5, 2)
            for _ in range(int(rng.integers(3, 7))):
                s.rock(rng, spot + rng.normal(0.0, 0.6, 2), 0.3, -0.2, rng.uniform(0.6, 1.4))
    return s.mesh()


def tavern(seed: int, wide: tuple[int, int] = (54, 61)) -> trimesh.Trimesh:
    """A tavern's interior and its yard: an inn 54-60 x 24-28 m (walls 0.3 m thick, floors 0.15 m over the street) of
    three storeys 3.6 m apart under a gable (:func:`_gable`), standing in a yard 14 m wide all round. On the ground
    floor the taproom (the front 18-22 m of the house): 26-34 groups of a table (0.75 m high) between two benches (0.45
    m, over the climb) 1.3 m or more apart, a hearth, and a bar counter 1.1 m high from the west wall with room behind it
    (2 m to the shelves, 2.45 m to the wall) entered round its east end; behind the taproom's back wall a kitchen (door
    from behind the bar, a back door to the yard, a flight down through its floor to a cellar 3 m below under the
    kitchen and the taproom's back, with barrels) and a snug (door from the taproom, furniture). The front door is 2 m
    wide. On each upper storey a gallery 3-5 m wide round a well over the taproom open to the roof (rails 1.1 m round
    it); two flights (1.6 m wide, 20 risers of 0.18 m) climb the east wall one beyond the other, ground to first storey
    and first to second, and off each gallery 8-12 bedrooms along the back and 3-4 along the west side open by doors 1.6
    m wide (lintels 2.3 m up, :func:`_doored_wall`), each with furniture (:func:`_furnish`).

    Expected (written before the first run): one area (no table top nor counter holds floor after the agent's radius).
    Traffic highest on the taproom's floor between the front door, the bar's end and the foot of the stair, and on the
    flights and the galleries' east sides; the bedrooms, the cellar and the snug lowest. A designer expects the
    structure to show the taproom as a net round the table groups, each flight as one edge up to a loop round its
    gallery, a terminal in each bedroom, and a chain down to the cellar through the kitchen.

    ``wide`` bounds the inn's width in metres (low inclusive, high exclusive): a narrower inn by the same rules (the same
    level for the default, the one the docstring describes).
    """
    rng = np.random.default_rng(seed)
    width, depth = float(rng.integers(*wide)), float(rng.integers(24, 29))
    ground, uppers, roof = 0.15, (3.75, 7.35), 10.95
    upper = uppers[0]
    back = depth - 6.0  # the taproom's back wall
    s = _Solids()
    s.ground(-14.0, width + 14.0, -14.0, depth + 14.0, 0.0, [(0.0, width, 0.0, depth)])
    cellar_holes: list[tuple[float, float, float, float]] = []
    kitchen_x = float(rng.integers(14, 18))
    _flight_through(s, np.array([kitchen_x - 2.0, depth - 1.2]), np.array([-1.0, 0.0]), 1.4, ground - 3.0, ground,
                    cellar_holes)
    s.slab(0.0, width, 0.0, depth, ground, cellar_holes)
    s.box(0.0, kitchen_x, ground - 3.5, ground - 3.0, back - 6.0, depth)  # the cellar's floor and its walls
    for a, b in (((0.0, back - 6.0), (kitchen_x, back - 6.0)), ((0.0, depth), (kitchen_x, depth)),
                 ((0.0, back - 6.0), (0.0, depth)), ((kitchen_x, back - 6.0), (kitchen_x, depth))):
        s.wall(a, b, ground - 3.5, ground - 0.3, thickness=0.3)
    for _ in range(int(rng.integers(6, 11))):  # barrels
        p = np.array([rng.uniform(0.8, kitchen_x - 0.8), rng.uniform(back - 5.2, back - 2.0)])
        s.prism(p + 0.45 * np.array([[math.cos(a), math.sin(a)] for a in np.linspace(0, 2 * math.pi, 9)[:-1]]),
                ground - 3.1, ground - 3.0 + 1.0)
    well = (8.0, width - 5.0, 3.5, back - 3.0)
    stair = (0.0, 0.0, 0.0, 0.0)
    for k, (y0, y1) in enumerate(pairwise((ground, *uppers))):  # flights up the east wall, the second beyond the first
        holes = [well]
        flight = _flight_through(s, np.array([width - 1.0, 2.5 + 8.0 * k]), np.array([0.0, 1.0]), 1.6, y0, y1, holes)
        stair = flight if k == 0 else stair
        s.slab(0.0, width, 0.0, depth, y1, holes)
        _rail_ring(s, *well, y1, {})
    front = float(rng.uniform(8.0, width - 12.0))
    _doored_wall(s, (0.0, 0.0), (width, 0.0), ground, roof, [(front, 2.0, "open", 1)], 0.3)
    _doored_wall(s, (0.0, depth), (width, depth), ground, roof, [(2.0, 1.6, "open", 1)], 0.3)
    for x in (0.0, width):
        s.wall((x, 0.0), (x, depth), ground - 0.5, roof, thickness=0.3)
    _doored_wall(s, (0.0, back), (width, back), ground, upper, [(4.0, 1.6, "open", 1), (kitchen_x + 4.0, 1.6, "open", 1)])
    s.wall((kitchen_x, back), (kitchen_x, depth), ground - 0.5, upper)
    bar_end = kitchen_x - 3.0
    s.box(0.0, bar_end, ground - 0.1, ground + 1.1, back - 3.1, back - 2.5)  # the counter
    s.box(6.2, bar_end - 1.0, ground - 0.1, ground + 2.0, back - 0.5, back - 0.15)  # the shelves behind it
    s.box(0.15, 0.95, ground - 0.1, ground + 1.4, 5.0, 7.4)  # the hearth
    _furnish(s, rng, (kitchen_x + 0.15, width - 0.15, back + 0.1, depth - 0.15), ground, [(kitchen_x + 3.5, kitchen_x + 6.5, back, back + 1.5)], 4)
    _furnish(s, rng, (0.15, kitchen_x - 0.1, back + 0.1, depth - 0.15), ground,
             [(0.0, 6.5, back, back + 1.5), (1.5, 4.0, depth - 1.5, depth), (kitchen_x - 8.5, kitchen_x, depth - 2.3, depth)], 3)
    taken = [(0.0, bar_end + 1.6, back - 4.6, back), (width - 2.6, width, 0.0, stair[3] + 1.6), (front - 1.0, front + 3.0, 0.0, 3.0),
             (0.0, 1.6, 4.4, 8.0)]
    groups = 0
    for _ in range(600):
        if groups == int(rng.integers(26, 35)):
            break
        gx, gz = rng.uniform(1.5, width - 4.0), rng.uniform(1.2, back - 4.0)
        if _clear(gx - 0.65, gx + 1.4 + 0.65, gz - 0.65, gz + 1.9 + 0.65, taken):
            taken.append((gx - 0.65, gx + 1.4 + 0.65, gz - 0.65, gz + 1.9 + 0.65))
            s.box(gx, gx + 1.4, ground - 0.1, ground + 0.45, gz, gz + 0.35)
            s.box(gx, gx + 1.4, ground - 0.1, ground + 0.75, gz + 0.55, gz + 1.35)
            s.box(gx, gx + 1.4, ground - 0.1, ground + 0.45, gz + 1.55, gz + 1.9)
            groups += 1
    for y0, y1 in pairwise((*uppers, roof)):  # bedrooms on each upper storey
        rooms = _split(5.0, width, float(rng.uniform(4.6, 6.0)))  # along the back, the first reaching to x = 0
        doors = [(a + b) / 2 for a, b in pairwise(rooms)]
        _doored_wall(s, (0.0, back), (width, back), y0, y1, [(x - 0.8, 1.6, "open", 1) for x in doors])
        for x in rooms[1:-1]:
            s.wall((x, back), (x, depth), y0 - 0.5, y1)
        rooms[0] = 0.0
        side = _split(0.0, back, 6.0)
        _doored_wall(s, (5.0, 0.0), (5.0, back), y0, y1, [(a + (b - a) / 2 - 0.8, 1.6, "open", -1) for a, b in pairwise(side)])
        for z in side[1:-1]:
            s.wall((0.0, z), (5.0, z), y0 - 0.5, y1)
        for (a, b), x in zip(pairwise(rooms), doors):
            _furnish(s, rng, (a + 0.1, b - 0.1, back + 0.1, depth - 0.15), y0, [(x - 1.3, x + 1.3, back, back + 1.5)], 2)
        for a, b in pairwise(side):
            _furnish(s, rng, (0.15, 4.9, a + 0.1, b - 0.1), y0, [(3.5, 5.0, (a + b) / 2 - 1.3, (a + b) / 2 + 1.3)], 2)
    _gable(s, -0.3, width + 0.3, -0.3, depth + 0.3, roof)
    return s.mesh()


def _western_row(s: _Solids, rng: np.random.Generator, length: float, north: bool,
                 yards: list[tuple[float, float, float, float]]) -> None:
    """One side of the western town's street (:func:`western_town`): buildings along x from 0 to ``length``, their
    fronts 13 m from the street's axis on the ``north`` (+z) or south side, each adding its plan to ``yards`` (holes
    for the ground)."""
    sign = 1.0 if north else -1.0

    def z_of(a: float, b: float) -> tuple[float, float]:  # distances a < b from the axis -> z0 < z1 on this side
        return (a, b) if north else (-b, -a)

    floor, upper, roof = 0.3, 3.8, 7.4
    x, previous_upper = 2.0, None
    while x < length - 10.0:
        w, d = float(rng.integers(8, 13)), float(rng.integers(10, 13))
        two = rng.random() < 0.6
        z0, z1 = z_of(13.0, 13.0 + d)
        yards.append((x, x + w, z0, z1))
        s.box(x, x + w, floor - 0.5, floor, z0, z1)
        bz0, bz1 = z_of(10.0, 13.0)
        s.box(x, x + w, floor - 0.5, floor, bz0, bz1)  # the boardwalk
        top = upper if two else floor + 3.6
        front, back = (z0, z1) if north else (z1, z0)
        _doored_wall(s, (x, front), (x + w, front), floor, top, [(w / 2 - 0.9, 1.8, "open", 1)], 0.25)
        _doored_wall(s, (x, back), (x + w, back), floor, roof if two else top, [(1.0, 1.6, "open", 1)], 0.25)
        for wx in (x, x + w):
            s.wall((wx, z0), (wx, z1), floor - 0.5, roof if two else top, thickness=0.25)
        if two:
            holes: list[tuple[float, float, float, float]] = []
            _flight_through(s, np.array([x + w - 1.2, front + sign * 1.5]), np.array([0.0, sign]), 2.0, floor, upper, holes)
            s.slab(x, x + w, z0, z1, upper, holes)
            _doored_wall(s, (x, front), (x + w, front), upper, roof, [(w / 2 - 0.8, 1.6, "open", 1)], 0.25)
            s.box(x, x + w, upper - 0.3, upper, bz0, bz1)  # the balcony over the boardwalk, railed at its front
            s.wall((x, 10.0 * sign), (x + w, 10.0 * sign), upper, upper + 1.1, thickness=0.1)
            if previous_upper is not None and previous_upper < x:  # a bridge over the alley from the last balcony
                s.box(previous_upper, x, upper - 0.3, upper, bz0, bz1)
                s.wall((previous_upper, 10.0 * sign), (x, 10.0 * sign), upper, upper + 1.1, thickness=0.1)
                if rng.random() < 0.7:  # a flight up the alley onto the bridge, arriving head-on at its back
                    _flight_to(s, np.array([(previous_upper + x) / 2, 13.0 * sign]), np.array([0.0, -sign]), 2.0, 0.0,
                               upper)
            previous_upper = x + w
        else:
            previous_upper = None
        _gable(s, x - 0.2, x + w + 0.2, z0 - 0.2, z1 + 0.2, roof if two else top)
        x += w + (float(rng.uniform(3.5, 5.0)) if rng.random() < 0.6 else 0.0)


def western_town(seed: int, street: tuple[int, int] = (130, 151)) -> trimesh.Trimesh:
    """A western town's main street 20 m wide and 130-150 m long between two rows of buildings (:func:`_western_row`),
    each 8-12 m wide and 10-12 m deep, one house after another or across alleys 3.5-5 m wide (six in ten): each on a
    boardwalk 3 m deep and 0.3 m up (one step) along its front, entered by a front door 1.8 m wide and a back door to the
    yards behind; three in five have an upper storey (3.8 m up), reached inside by a flight 2 m wide (risers of at most
    0.18 m) up the east wall, whose front door opens onto a balcony over the boardwalk (railed, 1.1 m): balconies of
    neighbours meet, or over an alley by a bridge, seven in ten of those bridges reached by a flight 2 m wide up the
    alley. Roofs are gables at 50 degrees (:func:`_gable`); the ground runs 17 m past the rows into the yards, with up to
    4-6 corrals 12 x 10 m, 3 m or more apart (rails 1.1 m high, a gate 2 m wide facing the rows), and 10-16 water troughs
    and covered wagons (0.9-1.6 m high, ridged at 50 degrees, :func:`_ridged`) on the street off its middle.

    Expected (written before the first run): one area. Traffic highest along the street's middle and at the alley
    mouths, then on the boardwalks; the balconies, the upper rooms and the corrals lowest; the alleys with flights
    middling (they join the yards, the street and the balconies). A designer expects the structure to show the street
    as a chain or net, an edge through each alley to a loop round the rows by the yards, the balconies as chains joined
    down each alley flight and inside stair, and a terminal in each upper room.

    ``street`` bounds the street's length in metres (low inclusive, high exclusive): a shorter town by the same rules
    (the same level for the default, the one the docstring describes).
    """
    rng = np.random.default_rng(seed)
    length = float(rng.integers(*street))
    s = _Solids()
    yards: list[tuple[float, float, float, float]] = []
    _western_row(s, rng, length, True, yards)
    _western_row(s, rng, length, False, yards)
    corrals: list[tuple[float, float, float, float]] = []
    for _ in range(40):  # corrals in the yards, 3 m or more apart
        if len(corrals) == int(rng.integers(4, 7)):
            break
        x0, north = float(rng.uniform(4.0, length - 20.0)), rng.random() < 0.5
        z0 = 30.0 if north else -40.0
        if _clear(x0 - 3.0, x0 + 15.0, z0, z0 + 10.0, corrals):
            corrals.append((x0, x0 + 12.0, z0, z0 + 10.0))
            _rail_ring(s, x0, x0 + 12.0, z0, z0 + 10.0, 0.0, {"south" if north else "north": [(5.0, 2.0)]})
    for _ in range(int(rng.integers(10, 17))):  # troughs and covered wagons on the street, off its middle, ridged
        x0, z0 = float(rng.uniform(4.0, length - 6.0)), float(rng.choice([-8.0, 5.5]))
        _ridged(s, x0, x0 + float(rng.uniform(1.8, 3.5)), z0, z0 + 2.5, -0.5, float(rng.uniform(0.9, 1.6)))
    s.ground(-5.0, length + 5.0, -42.0, 42.0, 0.0, yards)
    return s.mesh()


def _divide(rng: np.random.Generator, box: tuple[int, int, int, int], walls: list[list], loops: float) -> None:
    """Recursive division (Buck, *Mazes for Programmers*, 2015) of the rectangle ``box`` (i0, i1, j0, j1) of
    2 m cells into rooms of 3-5 cells a side: a region 6 or more cells along its longer side is cut across it on a
    cell boundary 3 or more cells from each end by a wall with one door (the cell it opens, a second one with
    probability ``loops``), and each part is divided again. Walls lie on cell boundaries and doors within cells, so a
    wall ending on another never meets its door's cell edge-on and no door is closed. Appends each wall as [axis (0:
    the wall runs along z at i = index, 1: along x at j = index), index, lo, hi, door cells] to ``walls``.
    O(cells)."""
    i0, i1, j0, j1 = box
    along_i = i1 - i0 >= j1 - j0
    lo, hi = (i0, i1) if along_i else (j0, j1)
    if hi - lo < 6:
        return
    cut = int(rng.integers(lo + 3, hi - 2))
    span = (j0, j1) if along_i else (i0, i1)
    doors = [int(rng.integers(*span))]
    if rng.random() < loops and span[1] - span[0] > 1:
        doors.append(int(rng.choice([c for c in range(*span) if c != doors[0]])))
    walls.append([0 if along_i else 1, cut, span[0], span[1], doors])
    for part in ((i0, cut, j0, j1), (cut, i1, j0, j1)) if along_i else ((i0, i1, j0, cut), (i0, i1, cut, j1)):
        _divide(rng, part, walls, loops)


def killhouse(seed: int, cells: tuple[int, int] = (28, 33)) -> trimesh.Trimesh:
    """A training killhouse in a hall: a block of roofless rooms 28-32 x 20-25 cells of 2 m (56-64 x 40-50 m) walled by
    plywood 0.2 m thick and 2.4 m high, divided recursively into rooms of 3-5 cells (:func:`_divide`: one door 1.8 m
    wide a wall, a second in a third of the walls), entered by 3-4 doors in its outer wall from an aisle 8 m wide
    round it inside the hall's walls (8 m high); crates (ridged, 1.2 m) in the rooms of 3 x 3 cells or more. Over the
    walls an observation catwalk 2 m wide, its top 4.2 m up: a ring over the outer wall and two spans over the first
    two dividing walls (one across each way), reached only by two flights up the hall's west and east walls, each
    with a landing and a bridge over the aisle to the ring. No earlier kind laid a walkable level over the tops of
    another's walls: the catwalk's spans are a second net over the rooms, joined to the ground at two points only.

    Expected (written before the first run): one area. Traffic highest in the aisle round the block between its
    doors and in the rooms strung between two doors (the loops through the block), lowest on the catwalk (its only
    ways up are the two flights; a dead end for walking flow but at its two ends) and in rooms with one door. A
    designer expects the structure to show the aisle as a loop, a node per room with edges through the doors, the
    catwalk as a ring with spans and two edges down the flights, and terminals in the one-door rooms.

    ``cells`` bounds the block's width in cells along x (its depth is 3/4 of it); a smaller killhouse by the same
    rules (the same level at the default)."""
    rng = np.random.default_rng(seed)
    w = int(rng.integers(*cells))
    d = int(round(w * 0.75)) + int(rng.integers(-1, 2))
    aisle, cell, top = 8.0, 2.0, 4.2
    x0, z0 = aisle, aisle  # the block's corner; the hall runs from 0 to the block's far side plus the aisle
    x1, z1 = x0 + w * cell, z0 + d * cell
    hx, hz = x1 + aisle, z1 + aisle
    s = _Solids()
    s.box(-0.5, hx + 0.5, -0.5, 0.0, -0.5, hz + 0.5)  # the hall's floor
    for a, b, c, e in ((-0.5, 0.0, -0.5, hz + 0.5), (hx, hx + 0.5, -0.5, hz + 0.5), (0.0, hx, -0.5, 0.0),
                       (0.0, hx, hz, hz + 0.5)):
        s.box(a, b, -0.5, 8.0, c, e)
    walls: list[list] = []
    _divide(rng, (0, w, 0, d), walls, 1.0 / 3.0)
    outer: list[list] = [[0, 0, 0, d, []], [0, w, 0, d, []], [1, 0, 0, w, []], [1, d, 0, w, []]]
    for side in rng.choice(4, size=int(rng.integers(3, 5)), replace=False):
        outer[side][4].append(int(rng.integers(1, outer[side][3] - 1)))
    for axis, index, lo, hi, doors in walls + outer:
        gaps = [((c - lo) * cell + 0.1, 1.8) for c in doors]
        if axis == 0:
            s.wall((x0 + index * cell, z0 + lo * cell), (x0 + index * cell, z0 + hi * cell), 0.0, 2.4, gaps)
        else:
            s.wall((x0 + lo * cell, z0 + index * cell), (x0 + hi * cell, z0 + index * cell), 0.0, 2.4, gaps)
    rooms = [(0, w, 0, d)]
    for axis, index, lo, hi, _ in walls:  # the leaf rooms: each wall cuts the region it spans (walls in preorder)
        for k, (i0, i1, j0, j1) in enumerate(rooms):
            if axis == 0 and i0 < index < i1 and (j0, j1) == (lo, hi):
                rooms[k:k + 1] = [(i0, index, j0, j1), (index, i1, j0, j1)]
                break
            if axis == 1 and j0 < index < j1 and (i0, i1) == (lo, hi):
                rooms[k:k + 1] = [(i0, i1, j0, index), (i0, i1, index, j1)]
                break
    for i0, i1, j0, j1 in rooms:  # a crate near the middle of each room 3 x 3 cells or more
        if i1 - i0 >= 3 and j1 - j0 >= 3:
            cx = x0 + (i0 + i1) / 2 * cell + rng.uniform(-0.8, 0.8)
            cz = z0 + (j0 + j1) / 2 * cell + rng.uniform(-0.8, 0.8)
            _ridged(s, cx - 0.6, cx + 0.6, cz - 0.6, cz + 0.6, -0.3, 1.0)

    def catwalk(axis: int, at: float, lo: float, hi: float) -> None:  # 2 m wide over the wall line ``at``
        if axis == 0:
            s.box(at - 1.0, at + 1.0, top - 0.3, top, lo - 1.0, hi + 1.0)
        else:
            s.box(lo - 1.0, hi + 1.0, top - 0.3, top, at - 1.0, at + 1.0)

    for a, b, axis in ((x0, x1, 1), (z0, z1, 0)):
        for at in ((z0, z1) if axis == 1 else (x0, x1)):
            catwalk(axis, at, a, b)
    for axis in (0, 1):  # the first dividing wall each way
        first = next((wall for wall in walls if wall[0] == axis), None)
        if first is not None:
            _, index, lo, hi, _ = first
            catwalk(axis, (x0 if axis == 0 else z0) + index * cell, (z0 if axis == 0 else x0) + lo * cell,
                    (z0 if axis == 0 else x0) + hi * cell)
    for west in (True, False):  # a flight up the hall's wall, a landing, a bridge over the aisle to the ring
        fx0, fx1 = (0.5, 2.5) if west else (hx - 2.5, hx - 0.5)
        foot = z0 + rng.uniform(0.2, 0.5) * (z1 - z0)
        run = _flight_to(s, np.array([(fx0 + fx1) / 2, foot + 7.2]), np.array([0.0, 1.0]), 2.0, 0.0, top)
        edge = foot + run
        if west:
            s.box(fx0, x0, top - 0.3, top, edge, edge + 2.0)
        else:
            s.box(x1, fx1, top - 0.3, top, edge, edge + 2.0)
    return s.mesh()


def supermarket(seed: int, aisles: tuple[int, int] = (12, 16)) -> trimesh.Trimesh:
    """A supermarket and its car park on 2 m tiles (:func:`_tiles`), the store's floor 0.15 m up (one step): 12-15
    gondolas (rock, one tile thick) along z with aisles one tile (2 m) wide between them, cut by a cross aisle two
    tiles wide, side aisles three tiles wide and a back aisle two; at the front an aisle three tiles wide, then a bank of 6-9
    checkout counters (one tile wide, three long, a lane of one tile between two), an entry gap two tiles wide at
    one end of the bank and a service desk closing the rest, a lobby three tiles deep and two entrances two tiles
    wide onto the car park. Behind the back wall, entered by two doors one tile wide, a storeroom seven tiles deep of
    pallets (cover) with a dock door two tiles wide onto a service yard, which joins the car park down both sides of
    the store. The car park (14-16 tiles deep) holds rows of cars (rock, 1 x 2 tiles) between driving lanes, trolley
    bays and kerb islands. Rock stands as walls 3 m high ridged at 50 degrees.

    Expected (written before the first run): one area. Traffic highest through the checkout lanes and the entry gap
    (every way between the shop floor and the entrances), in the lobby and the front aisle along the bank, then the
    cross aisle and the side aisles; the gondola aisles and the storeroom low, the service yard lowest but for the
    way round the store's sides. A designer expects the structure to show the checkout bank as a row of parallel
    edges (or a chokepoint), each gondola aisle as an edge between the front (or cross) aisle and the back one, the
    car park as a net between the cars, and the way round the building to the service yard as a loop.

    ``aisles`` bounds the number of gondolas: a smaller store by the same rules (the same level at the default)."""
    rng = np.random.default_rng(seed)
    count = int(rng.integers(*aisles))
    run = int(rng.integers(14, 18))  # a gondola's length in tiles, the cross aisle included
    inner = 2 + 2 * count + 1 + 2  # the store's inside along i: side aisles and gondolas with aisles between
    side, park, yard = 4, int(rng.integers(14, 17)), 8
    n = 1 + side + 1 + inner + 1 + side + 1
    si0, si1 = 1 + side + 1, 1 + side + 1 + inner  # the store's inside along i
    sj0 = 1 + park + 1  # the store's inside begins (the front wall at sj0 - 1)
    lobby, bank, front, back, store = 3, 3, 3, 2, 7
    sj1 = sj0 + lobby + bank + front + run + back  # the back wall at sj1
    rj0, rj1 = sj1 + 1, sj1 + 1 + store  # the storeroom, its back wall at rj1
    m = rj1 + 1 + yard + 1
    walk = np.ones((n, m), dtype=bool)
    walk[[0, -1], :] = walk[:, [0, -1]] = False
    indoor = np.zeros_like(walk)
    indoor[si0:si1, sj0:sj1] = indoor[si0:si1, rj0:rj1] = True
    walk[si0 - 1:si1 + 1, sj0 - 1:rj1 + 1] = False  # the building's shell and its inside, opened below
    walk[indoor] = True
    walk[si0:si1, sj1] = False  # the back wall between shop floor and storeroom
    for i in rng.choice(np.arange(si0 + 1, si1 - 1), size=2, replace=False):
        walk[i, sj1] = True  # the storeroom's doors
    dock = int(rng.integers(si0 + 1, si1 - 3))
    walk[dock:dock + 2, rj1] = True
    for i in (si0 + 2 + int(rng.integers(0, 3)), si1 - 4 - int(rng.integers(0, 3))):
        walk[i:i + 2, sj0 - 1] = True  # the entrances
    bj = sj0 + lobby  # the checkout bank's rows bj .. bj + 2
    tills = int(rng.integers(6, 10))
    left = bool(rng.random() < 0.5)  # the bank's end the entry gap is at
    i = si0 + 2 if left else si1 - 2 - (2 * tills + 1)
    gap = (i - 2, i) if left else (i + 2 * tills + 1, i + 2 * tills + 3)
    walk[si0:si1, bj:bj + bank] = False  # the service desk, opened at the lanes and the gap
    walk[gap[0]:gap[1], bj:bj + bank] = True
    for k in range(tills):
        walk[i + 2 * k + 1, bj:bj + bank] = True  # lane k beside counter k (i + 2 k)
    gj0 = bj + bank + front  # the gondolas' rows
    cross = gj0 + int(rng.integers(run // 3, 2 * run // 3))
    for k in range(count):
        gi = si0 + 2 + 2 * k + 1
        walk[gi, gj0:gj0 + run] = False
        walk[gi, cross:cross + 2] = True
    inside_store = np.zeros_like(walk)
    inside_store[si0:si1, rj0:rj1] = True
    _tile_cover(rng, walk, int(rng.integers(8, 13)), 400, 1, lambda box: inside_store[box].all())  # pallets
    for row in range(3, park - 3, 5):  # car rows: pairs of bays back to back along i, a lane of 3 tiles after
        for i in range(3, n - 3, 2):
            if rng.random() < 0.55:
                walk[i, row:row + 2] = False
    islands = np.zeros_like(walk)
    islands[2:n - 2, 2:park - 1] = True
    _tile_cover(rng, walk, int(rng.integers(4, 8)), 300, 1, lambda box: islands[box].all())  # trolley bays
    floor = np.where(walk, 0.0, np.nan)
    floor[indoor & walk] = 0.15
    doors = floor[si0:si1, sj1]  # the storeroom's doors, a view
    doors[walk[si0:si1, sj1]] = 0.15
    _tiles(s := _Solids(), floor, 2.0, 3.0)
    return s.mesh()


def rts_map(seed: int, size: tuple[int, int] = (96, 107)) -> trimesh.Trimesh:
    """A two-player real-time-strategy map on 2 m tiles (:func:`_tiles`), 96-106 tiles square (192-212 m), the same
    under a half turn about its middle: each player's main base a plateau 18-21 tiles square 2.4 m up in a corner,
    left by one ramp two tiles wide (risers of 0.3 m a tile) down to a natural expansion 1.2 m up, whose ramp three
    tiles wide leads to the low ground (0 m); mineral lines (a row of rock one tile thick along the base's back
    edge) and gas geysers (rock 2 x 2) in each base; on the low ground two third bases a player, a central plateau
    1.2 m up (10-12 tiles square, a watchtower) climbed by four ramps, 6-8 unpathable doodads (rock 2-4 tiles) and
    cover a player. Every plateau's edge is a cliff (a ledge over the climb). Rock stands as walls 4 m high ridged
    at 50 degrees. Unlike round 22's :func:`moba` (lanes between two bases), the way out of each base is one ramp
    and then one more: two chokepoints in series before the open low ground.

    Expected (written before the first run): one area. Traffic highest on the low ground's middle between the two
    naturals' ramps (round both sides of the central plateau), on the naturals' ramps and across the naturals
    between their two ramps; the main ramps and the mains themselves low (a dead end each, behind one ramp), the
    central plateau low, the third bases' mineral pockets lowest. A designer expects the structure to show each
    main ramp and each natural ramp as a chokepoint (a node or an edge through it), the low ground as a net round
    the central plateau and the doodads, and terminals in the mains' and the bases' corners.

    ``size`` bounds the map's side in tiles: a smaller map by the same rules (the same level at the default)."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(*size))
    height = np.zeros((n, n))
    walk = np.ones((n, n), dtype=bool)
    keep = np.zeros_like(walk)  # ramps, their approaches and the bases' mining ground: no doodads or cover
    main = int(rng.integers(18, 22))
    height[1:1 + main, 1:1 + main] = 2.4
    nat_w, nat_d = int(rng.integers(14, 17)), int(rng.integers(12, 15))
    ni0 = 1 + main  # the natural east of the main, along the map's south edge
    height[ni0:ni0 + nat_w, 1:1 + nat_d] = 1.2
    rj = int(rng.integers(3, min(main, nat_d) - 3))  # the main ramp, down along +i onto the natural
    for t in range(4):
        height[ni0 + t, rj:rj + 2] = 2.4 - 0.3 * (t + 1)
    keep[ni0 - 3:ni0 + 7, rj - 2:rj + 4] = True
    ri = int(rng.integers(ni0 + 2, ni0 + nat_w - 5))  # the natural ramp, down along +j onto the low ground
    for t in range(4):
        height[ri:ri + 3, 1 + nat_d + t] = 1.2 - 0.3 * (t + 1)
    keep[ri - 2:ri + 5, nat_d - 3:nat_d + 8] = True
    walk[3:3 + main - 6, 2] = False  # the main's mineral line along its back (south) edge
    walk[2, 5:7] = walk[3, 5:7] = False  # its gas geyser
    walk[ni0 + 3:ni0 + nat_w - 3, 2] = False  # the natural's mineral line
    walk[ni0 + nat_w - 3:ni0 + nat_w - 1, 4:6] = False
    keep[1:1 + main, 1:6] = keep[ni0:ni0 + nat_w, 1:5] = True
    c, half = n // 2, int(rng.integers(5, 7))
    height[c - half:c + half, c - half:c + half] = 1.2  # the central plateau
    walk[c - 1:c + 1, c - 1:c + 1] = False  # its watchtower
    for along in (0, 1):  # its ramps on the south and west sides (the half turn gives north and east)
        at = c - half + int(rng.integers(1, 2 * half - 3))
        for t in range(4):
            if along == 0:
                height[at:at + 2, c - half - 1 - t] = 1.2 - 0.3 * (t + 1)
                keep[at - 2:at + 4, c - half - 7:c - half + 1] = True
            else:
                height[c - half - 1 - t, at:at + 2] = 1.2 - 0.3 * (t + 1)
                keep[c - half - 7:c - half + 1, at - 2:at + 4] = True
    for _ in range(2):  # third bases on the low ground: a mineral line against the map's west edge or a pocket
        for _ in range(50):
            j = int(rng.integers(main + 6, n - 16))
            if not keep[1:6, j - 2:j + 10].any() and (height[1:6, j - 2:j + 10] == 0).all():
                walk[2, j:j + 8] = False
                keep[1:8, j - 2:j + 10] = True
                break
    lower = np.add.outer(np.arange(n), np.arange(n)) < n - 1  # the half the rest is drawn on
    doodads, wanted = 0, int(rng.integers(3, 5))
    for _ in range(400):
        if doodads == wanted:
            break
        i, j = int(rng.integers(2, n - 6)), int(rng.integers(2, n - 6))
        di, dj = int(rng.integers(2, 5)), int(rng.integers(2, 5))
        box = (slice(i - 2, i + di + 2), slice(j - 2, j + dj + 2))
        if lower[box].all() and not keep[box].any() and (height[box] == 0).all() and walk[box].all():
            walk[i:i + di, j:j + dj] = False
            doodads += 1
    target = int(rng.integers(10, 16))
    _tile_cover(rng, walk, target, 40 * target, 1,
                lambda box: lower[box].all() and not keep[box].any() and np.ptp(height[box]) == 0.0)
    floor = np.where(walk, height, np.nan)
    floor = np.where(lower | np.eye(n, dtype=bool)[:, ::-1], floor, floor[::-1, ::-1])
    floor[[0, -1], :] = floor[:, [0, -1]] = np.nan
    _tiles(s := _Solids(), floor, 2.0, 4.0)
    return s.mesh()


def _step_pyramid(height: np.ndarray, walk: np.ndarray, centre: tuple[int, int], halves: list[int], rise: float,
                  facing: tuple[int, int]) -> list[tuple[np.ndarray, np.ndarray, float, float]]:
    """A step pyramid drawn on 2 m tiles: square tiers about the tile corner ``centre`` (i, j) of half sizes
    ``halves`` (decreasing, tiles) raised ``rise`` m a tier in ``height`` (n, m), and on the top a temple made in
    ``walk``: a shell of rock one tile thick, at most 6 x 6 tiles inside, its door two tiles wide in the middle of
    the side ``facing`` (a unit step along i or j). Returns the flights up the middle of that face, one a tier, each
    (the plan point (x, z) where its top meets the tier's edge head-on, its unit heading (x, z), the height it climbs
    from, the height it climbs to), for :func:`_flight_to`. O(tiers x half^2)."""
    ci, cj = centre
    di, dj = facing
    flights = []
    for k, h in enumerate(halves):
        height[ci - h:ci + h, cj - h:cj + h] = rise * (k + 1)
        edge = np.array([ci + di * h, cj + dj * h], dtype=np.float64) * 2.0
        flights.append((edge, -np.array(facing, dtype=np.float64), rise * k, rise * (k + 1)))
    t = min(halves[-1] - 1, 3)
    walk[ci - t - 1:ci + t + 1, cj - t - 1:cj + t + 1] = False
    walk[ci - t:ci + t, cj - t:cj + t] = True
    if di:
        walk[ci + t if di > 0 else ci - t - 1, cj - 1:cj + 1] = True
    else:
        walk[ci - 1:ci + 1, cj + t if dj > 0 else cj - t - 1] = True
    return flights


def ziggurat(seed: int, across: tuple[int, int] = (74, 81)) -> trimesh.Trimesh:
    """A temple city in a jungle clearing on 2 m tiles (:func:`_tiles`), 74-80 x 70-78 tiles (148-160 x 140-156 m): a main
    step pyramid of four tiers 2.1 m apart (half sizes 14, 11, 8, 5 tiles: each terrace a ring 6 m wide, each edge a
    ledge) with a temple on its top, climbed only by four flights 4 m wide up the middle of its south face over the
    plaza (:func:`_step_pyramid`, :func:`_flight_to`: risers 0.175 m, one flight a tier, each ending head-on at the
    tier's edge); two or three smaller pyramids of two tiers (half sizes 6 and 3) west and east of the plaza, each
    climbed by one stair facing it to a temple; a ball court (two rock walls two tiles thick and 12 tiles long, a
    playing alley four tiles wide between); a causeway one riser (0.3 m) up and three tiles wide from the plaza south to
    a market square; stelae (rock, 1 x 2 tiles) on the plaza; and a jungle band round it all, rock two tiles deep and
    then four tiles of open ground among trees (rock, 1 x 2 tiles, kept a tile apart). Rock stands as walls 12 m high
    ridged at 50 degrees. Unlike round 24's :func:`king_of_hill` (each step climbed by two ramps on different sides),
    every terrace of a pyramid is reached only from its one stair: each pyramid is a chain of dead-end rings.

    Expected (written before the first run): one area. Traffic highest on the plaza between the causeway's head and
    the pyramids' stairs, on the causeway and the market square's way to it; the stairs' lower flights moderate,
    the upper terraces and the temples low (chains of dead ends), the jungle band and the ball court's far end
    lowest. A designer expects the structure to show the plaza as a net, each stair as a chain of edges up the
    terraces (a node on each), the terraces' rings as dead-end loops, a terminal in each temple, and the causeway
    as one edge.

    ``across`` bounds the clearing's width in tiles (x): a narrower one by the same rules (the same level at the
    default)."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(*across))
    m = int(rng.integers(70, 79))
    height = np.zeros((n, m))
    walk = np.ones((n, m), dtype=bool)
    walk[:2, :] = walk[-2:, :] = walk[:, :2] = walk[:, -2:] = False
    band = np.zeros_like(walk)
    band[:6, :] = band[-6:, :] = band[:, :6] = band[:, -6:] = True
    taken = np.zeros_like(walk)
    rise = 2.1
    ci, cj = n // 2 + int(rng.integers(-2, 3)), m - 6 - 15  # the main pyramid against the north jungle
    flights = _step_pyramid(height, walk, (ci, cj), [14, 11, 8, 5], rise, (0, -1))
    taken[ci - 16:ci + 16, cj - 19:] = True
    plaza_j = cj - 16  # the plaza runs from the causeway's head up to the main pyramid
    market = (n // 2 - 8, n // 2 + 8, 6, 14)  # the market square (i0, i1, j0, j1) against the south jungle
    taken[market[0]:market[1], market[2]:market[3]] = True
    cw = int(rng.integers(n // 2 - 4, n // 2 + 2))
    height[cw:cw + 3, market[3]:plaza_j - 2] = 0.3  # the causeway; its ends a riser off the ground
    taken[cw - 2:cw + 5, market[3]:plaza_j] = True
    for _ in range(40):  # the ball court, south-west of the plaza
        bi, bj = int(rng.integers(7, n // 2 - 12)), int(rng.integers(7, 12))
        if not taken[bi - 2:bi + 10, bj - 2:bj + 14].any():
            walk[bi:bi + 2, bj:bj + 12] = walk[bi + 6:bi + 8, bj:bj + 12] = False
            taken[bi - 2:bi + 10, bj - 2:bj + 14] = True
            break
    smaller, wanted = 0, int(rng.integers(2, 4))
    for _ in range(200):  # the smaller pyramids west and east of the plaza, facing it
        if smaller == wanted:
            break
        halves = [6, 3]
        h0 = halves[0]
        west = bool(rng.random() < 0.5)
        pi = int(rng.integers(7 + h0, n // 2 - h0 - 4)) if west else int(rng.integers(n // 2 + h0 + 4, n - 7 - h0))
        pj = int(rng.integers(14 + h0, m - 7 - h0))
        box = (slice(pi - h0 - 3, pi + h0 + 3), slice(pj - h0 - 3, pj + h0 + 3))
        if taken[box].any():
            continue
        taken[box] = True
        flights += _step_pyramid(height, walk, (pi, pj), halves, rise, (1, 0) if west else (-1, 0))
        smaller += 1
    inner = band.copy()
    inner[:2, :] = inner[-2:, :] = inner[:, :2] = inner[:, -2:] = False
    _tile_cover(rng, walk, 60, 2000, 1, lambda box: inner[box].all() and not taken[box].any())  # trees
    stelae = np.zeros_like(walk)
    stelae[8:-8, plaza_j - 8:plaza_j + 2] = True
    _tile_cover(rng, walk, int(rng.integers(6, 10)), 300, 2, lambda box: stelae[box].all() and not taken[box].any())
    floor = np.where(walk, height, np.nan)
    _tiles(s := _Solids(), floor, 2.0, 12.0)
    for edge, heading, y0, y1 in flights:
        _flight_to(s, edge, heading, 4.0, y0, y1)
    return s.mesh()


def _chorded_ring(s: _Solids, radius: float, width: float, top: float, sides: int) -> None:
    """A flat ring ``width`` m wide about the circle of ``radius`` m round the origin, its top at ``top`` (0.3 m
    thick): ``sides`` chords (:func:`_wall_line`), each overlapping the next at its ends."""
    corners = [radius * np.array([math.cos(2 * math.pi * k / sides), math.sin(2 * math.pi * k / sides)])
               for k in range(sides + 1)]
    for p, q in zip(corners[:-1], corners[1:]):
        along = (q - p) / np.linalg.norm(q - p) * width * math.tan(math.pi / sides) / 2
        _wall_line(s, p - along, q + along, top - 0.3, top, width, [])


def reactor(seed: int, levels: tuple[int, int] = (6, 8)) -> trimesh.Trimesh:
    """A reactor hall: a round hall 28-32 m in radius (24 wall chords, 0.5 m thick) round a core pillar 4 m in radius (16
    sides, pointed on top), with 6-7 levels 6 m apart: the ground floor (a chorded ring stopping under the core), on
    which 10-14 machines stand (ridged, 2-4 x 1.6-2.4 m, 1 m to the eaves: the ground runs on inside them, but too
    little of it under 2 m of head room to hold a floor), and on each level above a gallery 4 m wide against the wall
    and a ring 3 m wide round the core, both chorded (:func:`_chorded_ring`), joined by 2-3 radial bridges 2.4 m wide at random
    angles (at least 30 degrees apart); two stair towers outside the wall, east and west, each a switchback well
    (:func:`_switchback`) whose landing on every level opens through a doorway 1.8 m wide onto the gallery (a threshold
    under it). No earlier kind stacked round galleries over one void joined across it only by bridges at every angle:
    the levels meet only in the two towers.

    Expected (written before the first run): one area. Traffic highest in the two stair towers (every way between
    levels) and on the galleries' arcs between the towers' doorways, on the ground floor's way between the two
    towers; the bridges and the core rings low (a bridge helps only between its gallery's far sides), the machines'
    corners lowest. A designer expects the structure to show each gallery as a loop, each core ring as a loop joined
    by an edge per bridge, each tower as a chain of edges between the levels, and chokepoints at the doorways.

    ``levels`` bounds the number of levels, the ground floor counted: a lower hall by the same rules (the same level
    at the default)."""
    rng = np.random.default_rng(seed)
    radius = float(rng.uniform(28.0, 32.0))
    count = int(rng.integers(*levels))
    storey, sides = 6.0, 24
    s = _Solids()
    top = storey * (count - 1)
    chord = radius * math.cos(math.pi / sides)  # the wall chords' distance from the middle
    _chorded_ring(s, (radius + 4.0) / 2, radius - 4.0, 0.0, sides)  # the ground floor, stopping under the core
    corners = [radius * np.array([math.cos(2 * math.pi * (k + 0.5) / sides), math.sin(2 * math.pi * (k + 0.5) / sides)])
               for k in range(sides + 1)]
    for k, (p, q) in enumerate(zip(corners[:-1], corners[1:])):
        if k not in (sides - 1, sides // 2 - 1):  # the chords facing east and west are the towers' walls
            _wall_line(s, p, q, -0.5, top + 4.0, 0.5, [])
    core = [4.0 * np.array([math.cos(2 * math.pi * k / 16), math.sin(2 * math.pi * k / 16)]) for k in range(16)]
    s.hull(np.array([[p[0], y, p[1]] for p in core for y in (-0.5, top + 3.0)] + [[0.0, top + 9.0, 0.0]]))
    placed: list[np.ndarray] = []
    machines = int(rng.integers(10, 15))
    for _ in range(200):  # machines on the ground floor, between the core and the gallery's shadow
        if len(placed) == machines:
            break
        r, a = rng.uniform(8.0, radius - 7.0), rng.uniform(0.0, 2 * math.pi)
        c = r * np.array([math.cos(a), math.sin(a)])
        half = np.array([rng.uniform(1.0, 2.0), rng.uniform(0.8, 1.2)])  # too shallow along z to hold floor inside
        if abs(c[1]) < 8.0 and abs(c[0]) > radius - 12.0:
            continue  # the way to each tower's door kept clear
        if all(np.abs(c - o).max() > 6.0 for o in placed):
            _ridged(s, c[0] - half[0], c[0] + half[0], c[1] - half[1], c[1] + half[1], -0.3, 1.0)
            placed.append(c)
    for level in range(1, count):
        y = storey * level
        _chorded_ring(s, radius - 2.25, 4.0, y, sides)
        _chorded_ring(s, 5.5, 3.0, y, 16)
        angles: list[float] = []
        bridges = int(rng.integers(2, 4))
        for _ in range(100):
            if len(angles) == bridges:
                break
            a = float(rng.uniform(0.0, 2 * math.pi))
            if all(abs((a - b + math.pi) % (2 * math.pi) - math.pi) > math.radians(30.0) for b in angles):
                angles.append(a)
        for a in angles:
            u = np.array([math.cos(a), math.sin(a)])
            _wall_line(s, u * 6.5, u * (radius - 3.75), y - 0.3, y, 2.4, [])
    well = _well_length(storey)
    for east in (True, False):
        wall_x = chord if east else -chord  # the tower's side on the hall
        x0 = wall_x + 0.25 if east else wall_x - 0.25 - 4.0
        z0 = 0.5 - radius * math.sin(math.pi / sides)  # the tower's wall starts at the chord's end
        for level in range(count):
            y = storey * level
            if level < count - 1:
                _switchback(s, x0, z0, y, storey)
            s.box(x0, x0 + 4.0, y - 0.45, y, z0, z0 + 2.0)  # the landing
            a, b = (wall_x - 1.5, x0 + 1.0) if east else (x0 + 3.0, wall_x + 1.5)
            s.box(a, b, y - 0.3, y, z0 + 0.1, z0 + 1.9)  # the threshold through the doorway
            s.wall((wall_x, z0 - 0.5), (wall_x, z0 + well + 0.5), y, y + storey, [(0.6, 1.8)], thickness=0.5)
        s.box(x0 - 0.3 if not east else x0 + 4.0, x0 if not east else x0 + 4.3, -0.5, top + 4.0, z0 - 0.5,
              z0 + well + 0.5)  # the tower's outer wall
        s.box(min(x0, wall_x), max(x0 + 4.0, wall_x), -0.5, top + 4.0, z0 - 0.8, z0 - 0.5)
        s.box(min(x0, wall_x), max(x0 + 4.0, wall_x), -0.5, top + 4.0, z0 + well + 0.5, z0 + well + 0.8)
    return s.mesh()


def gorge_bridge(seed: int, span: tuple[float, float] = (180.0, 211.0)) -> trimesh.Trimesh:
    """A road bridge over a gorge (no floor below it): a deck 14 m wide and 180-210 m long, its top 20 m up, between
    parapets 1.1 m high, strewn with 20-30 wrecked cars (:func:`_car`) and 4-6 barricades (ridged, 0.9 m), holed by a
    railed blast crater 4-5 x 5-7 m; under the deck, 3.4 m below its underside, a maintenance catwalk 2.4 m wide
    along its middle, widening at each of 3-4 piers (two columns each, outside the catwalk) into a landing 8 m long;
    from 2-3 of those landings a flight (2 m wide, risers of at most 0.18 m) climbs through a railed hole in the deck
    (:func:`_flight_through`); at each end the catwalk meets a landing under the bank and a flight up through it.
    Each bank is a plateau 80-90 x 90 m at the deck's height, a checkpoint town of 10-14 houses (ridged, 6-10 m; the
    ground stops under them) and
    sandbag lines (ridged, 0.9 m) in the open ground. No earlier kind ran two parallel ways, one over the other, the
    whole length of a level, joined only at a few points.

    Expected (written before the first run): one area. Traffic highest on the deck (the shortest way between the
    banks), through the gaps between its wrecks and round the crater, and on the banks' ground between the town and
    the bridge's ends; the catwalk low but for the stretches between the flights near each end, the banks' far
    corners lowest. A designer expects the structure to show the deck as a chain of edges (two round the crater),
    the catwalk as a parallel chain joined to it by an edge up each flight, and the banks as nets round their houses.

    ``span`` bounds the deck's length (m): a shorter bridge by the same rules (the same level at the default)."""
    rng = np.random.default_rng(seed)
    length = float(rng.uniform(*span))
    deck, walk_y, half = 20.0, 16.0, 7.0
    bank = float(rng.uniform(80.0, 90.0))
    s = _Solids()
    piers = int(rng.integers(3, 5))
    pier_x = [length * (k + 1) / (piers + 1) + float(rng.uniform(-4.0, 4.0)) for k in range(piers)]
    holes: list[tuple[float, float, float, float]] = []
    climbs = set(int(k) for k in rng.choice(piers, size=int(rng.integers(2, 4)) if piers > 2 else 2, replace=False))
    for k, px in enumerate(pier_x):
        s.box(px - 4.0, px + 4.0, walk_y - 0.3, walk_y, -4.0, 4.0)  # the landing
        for side in (-1.0, 1.0):  # the pier's columns, up into the deck
            s.box(px - 1.0, px + 1.0, -10.0, deck, side * 5.0 - 1.0, side * 5.0 + 1.0)
        if k in climbs:
            heading = np.array([1.0 if rng.random() < 0.5 else -1.0, 0.0])
            _flight_through(s, np.array([px - 3.5 * heading[0], 2.5]), heading, 2.0, walk_y, deck, holes)
    cx = float(rng.uniform(0.3, 0.7)) * length
    for _ in range(100):  # 10 m or more from every pier; a short span may leave no such place in the middle
        if min(abs(cx - px) for px in pier_x) >= 10.0:
            break
        cx = float(rng.uniform(0.3, 0.7)) * length
    else:
        cx = (pier_x[0] + pier_x[1]) / 2
    cz = float(rng.uniform(-2.0, 2.0))
    cw, cd = float(rng.uniform(5.0, 7.0)), float(rng.uniform(4.0, 5.0))
    crater = (cx - cw / 2, cx + cw / 2, cz - cd / 2, cz + cd / 2)
    _rail_ring(s, crater[0] - 0.1, crater[1] + 0.1, crater[2] - 0.1, crater[3] + 0.1, deck, {})
    ends = []
    for west in (True, False):  # the catwalk's end landings under the banks and their flights up
        x0, x1 = (-12.0, 0.5) if west else (length - 0.5, length + 12.0)
        s.box(x0, x1, walk_y - 0.3, walk_y, -4.0, 4.0)
        heading = np.array([-1.0 if west else 1.0, 0.0])
        foot = np.array([(-1.0 if west else length + 1.0), 2.5])
        ends.append(_flight_through(s, foot, heading, 2.0, walk_y, deck, []))
    s.box(0.0, length, walk_y - 0.3, walk_y, -1.2, 1.2)  # the catwalk
    s.slab(0.0, length, -half, half, deck, holes + [crater], thickness=0.6)
    for side in (-1.0, 1.0):
        s.wall((0.0, side * (half - 0.15)), (length, side * (half - 0.15)), deck, deck + 1.1, [], thickness=0.3)
    blocked = [crater] + holes

    def clear(box: tuple[float, float, float, float], gap: float) -> bool:
        return all(box[1] + gap < o[0] or o[1] + gap < box[0] or box[3] + gap < o[2] or o[3] + gap < box[2]
                   for o in blocked)

    cars, wanted = 0, int(rng.integers(20, 31))
    for _ in range(600):
        if cars == wanted:
            break
        x, z = float(rng.uniform(3.0, length - 7.5)), float(rng.uniform(-half + 0.6, half - 2.6))
        box = (x, x + 4.5, z, z + 2.0) if rng.random() < 0.8 else (x, x + 2.0, z - 1.0, z + 3.5)
        if box[2] > -half + 0.3 and box[3] < half - 0.3 and clear(box, 1.5):
            _car(s, *box, deck)
            blocked.append(box)
            cars += 1
    for _ in range(int(rng.integers(4, 7))):
        for _ in range(100):
            x, z = float(rng.uniform(5.0, length - 8.0)), float(rng.uniform(-half + 0.5, 0.0))
            box = (x, x + 0.8, z, z + float(rng.uniform(3.0, 6.0)))
            if box[3] < half - 0.3 and clear(box, 1.5):
                _ridged(s, *box, deck - 0.3, deck + 0.9)
                blocked.append(box)
                break
    for west in (True, False):  # the banks, the ground stopping under the houses and open over the end flights
        bx0, bx1 = (-bank, 0.0) if west else (length, length + bank)
        houses = [ends[0 if west else 1]]
        taken = [ends[0 if west else 1], (bx0 + (bank - 16.0 if west else 0.0), bx0 + (bank if west else 16.0), -9.0,
                                          9.0)]
        placed, wanted = 0, int(rng.integers(10, 15))
        for _ in range(300):
            if placed == wanted:
                break
            w, d = float(rng.uniform(6.0, 10.0)), float(rng.uniform(6.0, 10.0))
            x, z = float(rng.uniform(bx0 + 2.0, bx1 - 2.0 - w)), float(rng.uniform(-43.0, 43.0 - d))
            box = (x, x + w, z, z + d)
            if all(box[1] + 4.0 < o[0] or o[1] + 4.0 < box[0] or box[3] + 4.0 < o[2] or o[3] + 4.0 < box[2]
                   for o in taken):
                houses.append(_ridged(s, *box, deck - 0.6, deck + 3.0))
                taken.append(box)
                placed += 1
        s.ground(bx0, bx1, -45.0, 45.0, deck, houses, thickness=0.6)
        for _ in range(int(rng.integers(3, 6))):  # sandbag lines
            for _ in range(100):
                x, z = float(rng.uniform(bx0 + 2.0, bx1 - 6.0)), float(rng.uniform(-43.0, 37.0))
                box = (x, x + 0.8, z, z + float(rng.uniform(3.0, 6.0))) if rng.random() < 0.5 else \
                    (x, x + float(rng.uniform(3.0, 6.0)), z, z + 0.8)
                if all(box[1] + 2.0 < o[0] or o[1] + 2.0 < box[0] or box[3] + 2.0 < o[2] or o[3] + 2.0 < box[2]
                       for o in taken):
                    _ridged(s, *box, deck - 0.3, deck + 0.9)
                    taken.append(box)
                    break
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "subway": subway, "archipelago": archipelago, "car_park": car_park,
    "forest": forest, "stadium": stadium, "harbour": harbour,
    "school": school, "cathedral": cathedral, "mine": mine, "ship": ship, "village": village, "market": market,
    "office": office, "airport": airport, "sewer": sewer, "lanes": lanes, "prison": prison, "museum": museum,
    "tower": tower, "hospital": hospital, "mall": mall, "canyon": canyon, "hillside": hillside, "spaceship": spaceship,
    "kart": kart, "bunker": bunker, "hall": hall, "slopes": slopes, "islets": islets, "catacombs": catacombs,
    "helix": helix, "rooftops": rooftops, "flooded": flooded, "cave": cave, "train": train, "ruins": ruins,
    "library": library, "trenches": trenches, "refinery": refinery, "cemetery": cemetery, "quarry": quarry,
    "stairhall": stairhall,
    "hotel": hotel, "theme_park": theme_park, "aqueduct": aqueduct, "warehouse": warehouse, "golf": golf,
    "scaffold": scaffold,
    "dry_dock": dry_dock, "mountain_pass": mountain_pass, "zoo": zoo, "skatepark": skatepark, "interchange": interchange,
    "stepwell": stepwell,
    "farm": farm, "cruise_ship": cruise_ship, "treetops": treetops, "beach": beach, "railyard": railyard,
    "craters": craters,
    "oil_rig": oil_rig, "monastery": monastery, "night_market": night_market, "cinema": cinema, "estate": estate,
    "dam": dam,
    "garden": garden, "lighthouse": lighthouse, "canal_locks": canal_locks, "water_park": water_park, "paddies": paddies,
    "cistern": cistern,
    "star_fort": star_fort, "glacier": glacier, "medina": medina,
    "suburb": suburb, "cloverleaf": cloverleaf, "radial_town": radial_town,
    "bazaar": bazaar, "container_port": container_port, "theatre": theatre, "stilt_village": stilt_village,
    "nursery": nursery, "cliff_dwellings": cliff_dwellings,
    "drop_downs": drop_downs, "house": house, "pitched_roofs": pitched_roofs, "kit_arena": kit_arena,
    "spiral_towers": spiral_towers, "backdrop": backdrop,
    "closed_doors": closed_doors, "paper_walls": paper_walls, "split_level": split_level, "hub_rooms": hub_rooms,
    "corridor_shooter": corridor_shooter, "roof_town": roof_town,
    "ladders": ladders, "jump_gaps": jump_gaps, "collision_hulls": collision_hulls, "thresholds": thresholds,
    "prop_pile": prop_pile, "beams": beams,
    "moba": moba, "capture_flag": capture_flag, "platform_tower": platform_tower,
    "diagonal_dungeon": diagonal_dungeon, "battle_royale": battle_royale, "arena_shooter": arena_shooter,
    "stealth_mansion": stealth_mansion, "defusal": defusal, "payload": payload, "metroidvania": metroidvania,
    "tower_defence": tower_defence, "hub_world": hub_world,
    "tavern": tavern, "military_base": military_base, "king_of_hill": king_of_hill, "favela": favela, "hive": hive,
    "western_town": western_town,
    "killhouse": killhouse, "supermarket": supermarket, "rts_map": rts_map, "ziggurat": ziggurat, "reactor": reactor,
    "gorge_bridge": gorge_bridge,
}
"""Kind name -> generator (seed -> Y-up mesh in metres)."""


def main(argv: list[str] | None = None, kinds: dict[str, Callable[[int], trimesh.Trimesh]] | None = None,
         description: str | None = None) -> None:
    """Write the OBJ files ``argv`` asks for (the command line when None) of ``kinds`` (this module's KINDS when None;
    a later round's module passes its own), ``description`` heading the help."""
    kinds = KINDS if kinds is None else kinds
    parser = argparse.ArgumentParser(description=description or __doc__.splitlines()[0])
    parser.add_argument("out", type=Path, help="directory for the OBJ files")
    parser.add_argument("--kinds", nargs="+", default=list(kinds), choices=list(kinds))
    parser.add_argument("--seeds", nargs="+", type=int, default=[0, 1, 2])
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    for kind in args.kinds:
        for seed in args.seeds:
            path = args.out / f"{kind}_s{seed}.obj"
            kinds[kind](seed).export(path)
            print(path)


if __name__ == "__main__":
    main()
