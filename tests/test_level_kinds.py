"""The level kinds of rounds 9-39 (``benchmarks/level_kinds.py``, ``level_kinds26.py`` ... ``level_kinds39.py``) build
the levels they describe.

Smoke tests of quick generators (most well under a second each to build and to give a navmesh; the theatre's and
the cliff dwellings' thousands of hulls take about 5 s of CPU, the metroidvania's flights 1-2 s a build): the connected
areas the presets' agent finds are the ones each level is made to have, so a door that closes or a crawlway that opens
shows here before a benchmark figure moves.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from types import SimpleNamespace

import numpy as np
import pytest
import scipy.sparse as sp
import trimesh
from scipy.sparse.csgraph import connected_components

from g2s_plugins.recast import RecastParams, build_navmesh
from tests.conftest import benchmark

AGENT = SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)  # the presets' agent (configs/base.yaml)


# The kinds whose generator must give the same level for the same seed (and another for another seed); a new kind
# is added here, one case of test_the_same_seed_gives_the_same_level each.
SAME_SEED_KINDS = (
    "hall", "islets", "helix", "flooded", "stairhall", "quarry", "theme_park", "golf", "skatepark", "stepwell",
    "railyard", "craters", "monastery", "estate", "dam", "garden", "cistern", "glacier", "medina", "radial_town",
    "bazaar", "stilt_village", "nursery", "drop_downs", "house", "kit_arena", "backdrop", "paper_walls",
    "corridor_shooter", "moba", "capture_flag", "platform_tower", "diagonal_dungeon", "battle_royale", "arena_shooter",
    "stealth_mansion", "defusal", "payload", "metroidvania", "tower_defence", "hub_world",
    "tavern", "military_base", "king_of_hill", "favela", "hive", "western_town",
    "killhouse", "supermarket", "rts_map", "ziggurat", "reactor", "gorge_bridge",
)


# Keyword arguments that build a kind's same-seed case smaller by the same rules (each named in its generator's
# docstring): the case checks the generator's determinism, which does not need the benchmark's size, and three builds
# of a full level are most of the module's time for a slow generator.
SAME_SEED_SIZES: dict[str, dict[str, object]] = {
    "metroidvania": {"across": (3, 4)}, "payload": {"along": (60, 61)}, "western_town": {"street": (50, 51)},
    "tavern": {"wide": (24, 27)}, "military_base": {"scale": 0.5}, "favela": {"along": (40, 45)},
    "hive": {"columns": (4, 6)}, "reactor": {"levels": (3, 4)},
}


@pytest.fixture(scope="module")
def generators() -> dict[str, Callable[[int], trimesh.Trimesh]]:
    """``benchmarks/level_kinds.py``'s KINDS: each call builds its level anew."""
    return benchmark("level_kinds").KINDS


@pytest.fixture(scope="module")
def kinds(generators) -> dict[str, Callable[[int], trimesh.Trimesh]]:
    """``kinds[kind](seed)``: the level ``generators[kind](seed)``, built once in this module and copied for each
    call (a test that changes its level changes no other test's)."""
    built: dict[tuple[str, int], trimesh.Trimesh] = {}

    def once(kind: str) -> Callable[[int], trimesh.Trimesh]:
        def level(seed: int) -> trimesh.Trimesh:
            if (kind, seed) not in built:
                built[kind, seed] = generators[kind](seed)
            return built[kind, seed].copy()
        return level

    return {kind: once(kind) for kind in generators}


def areas(mesh, params: RecastParams | None = None) -> tuple[np.ndarray, object]:
    """The connected area of every navmesh polygon (P,) and the navmesh (Recast's defaults, or ``params``)."""
    nav = build_navmesh(mesh.vertices, mesh.faces, AGENT, params)
    rows = np.repeat(np.arange(nav.polygon_count), nav.neighbours.shape[1])
    cols = nav.neighbours.ravel()
    ok = cols >= 0
    graph = sp.coo_matrix((np.ones(ok.sum()), (rows[ok], cols[ok])), shape=(nav.polygon_count,) * 2)
    return connected_components(graph, directed=False)[1], nav


@pytest.mark.parametrize("kind", SAME_SEED_KINDS)
def test_the_same_seed_gives_the_same_level(generators, kinds, kind):
    """Two builds of seed 0, each its own run of the generator (one of them shared with the other tests of this
    module, or both at the smaller size of SAME_SEED_SIZES), are the same level; seed 1 gives another."""
    size = SAME_SEED_SIZES.get(kind)
    if size is None:
        a, b, other = kinds[kind](0), generators[kind](0), kinds[kind](1)
    else:
        a, b, other = (generators[kind](seed, **size) for seed in (0, 0, 1))
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.faces, b.faces)
    assert len(a.vertices) != len(other.vertices) or not np.array_equal(a.vertices, other.vertices)


def test_the_bunkers_three_levels_are_one_area(kinds):
    """Every room opens through its blast door, the tunnel through the last room, and the stairwells join the
    levels: one area, with floor on each of the three levels (0, -6 and -12 m)."""
    label, nav = areas(kinds["bunker"](0))
    assert label.max() == 0
    floors = np.round(nav.centres[:, 1] - 0.2, 1)
    for level in (0.0, -6.0, -12.0):
        assert (floors == level).sum() > 100, level


def test_the_hall_is_one_area(kinds):
    label, _ = areas(kinds["hall"](0))
    assert label.max() == 0


def test_islets_out_of_reach_are_areas_of_their_own(kinds):
    """The main island with its cluster, 13 more clusters and 60-80 lone islets: scores of areas."""
    label, _ = areas(kinds["islets"](0))
    assert 75 <= label.max() + 1 <= 95


def test_slopes_crests_are_reached_through_the_flanks_under_45_degrees(kinds):
    """The crests (9 m up) are in the valleys' area: joined where the flanks are under the limit (the south);
    the rest of the areas are flank patches the ripples cut off, each a few square metres."""
    label, nav = areas(kinds["slopes"](0))
    main = np.bincount(label).argmax()
    assert nav.centres[label == main, 1].max() > 9.0
    small = [nav.areas[label == k].sum() for k in range(label.max() + 1) if k != main]
    assert small and max(small) < 30.0


def test_the_helix_is_one_area_from_the_plaza_to_the_roof(kinds):
    """Six turns of one ramp: the plaza (0 m), every turn and the roof (19.2 m) are one area, walked round the
    whole spiral."""
    label, nav = areas(kinds["helix"](0))
    assert label.max() == 0
    heights = nav.centres[:, 1]
    assert heights.min() < 0.5 and heights.max() > 19.0
    assert np.histogram(heights, bins=np.arange(0.0, 19.3, 3.2))[0].min() > 10  # floor on every turn


def test_flooded_shops_open_on_their_pavement(kinds):
    """Each shop's floor (0.3 m above the pavement) is in an area with pavement in it: its door is open (a first
    draft closed every shop behind a strip of the building's mass)."""
    for seed in (0, 2):
        label, nav = areas(kinds["flooded"](seed))
        shops = set(label[nav.centres[:, 1] > 0.5])
        assert shops, seed
        for area in shops:
            assert (nav.centres[label == area, 1] < 0.5).any(), (seed, area)


def test_the_cave_is_one_area_with_no_floor_on_the_rock(kinds):
    """Chambers and tunnels are one area (stalagmites, columns and boulders close nothing); the rock's top and the
    columns' tops, 1 m under the lid, hold no floor."""
    label, nav = areas(kinds["cave"](1))
    assert label.max() == 0
    assert nav.centres[:, 1].max() < 4.0


def test_the_train_joins_platforms_carriages_and_footbridge(kinds):
    """One area: both trains' carriages (over the track beds, which have no floor of their own), the three
    platforms, the concourse and the footbridge 5.6 m over the platforms."""
    label, nav = areas(kinds["train"](0))
    assert label.max() == 0
    x, y, z = nav.centres.T
    for z0, z1 in ((0.0, 3.4), (11.4, 14.8)):  # inside each train
        assert ((z > z0) & (z < z1) & (x > 0.0)).sum() > 20, (z0, z1)
    assert (y > 6.0).any()


def test_the_ruins_three_storeys_are_one_area(kinds):
    """The storeys are joined by the fallen slabs (two of them walkable on each) and one stairwell: one area with
    floor on each storey (0, 3.6 and 7.2 m)."""
    label, nav = areas(kinds["ruins"](0))
    assert label.max() == 0
    for level in (0.0, 3.6, 7.2):
        assert (np.abs(nav.centres[:, 1] - 0.2 - level) < 0.3).sum() > 30, level


def test_the_librarys_three_storeys_are_one_area(kinds):
    """The grand flight and two stairwells join the storeys, and every aisle between shelves opens at both ends (a
    first draft shut the top storey's stairwell landings in behind a row of shelves): one area, floor on each
    storey (0, 4.5 and 9 m)."""
    label, nav = areas(kinds["library"](0))
    assert label.max() == 0
    for level in (0.0, 4.5, 9.0):
        assert (np.abs(nav.centres[:, 1] - 0.2 - level) < 0.3).sum() > 50, level


def test_the_trenches_and_the_field_are_one_area(kinds):
    """Exits join the trenches (2.5 m down) to the field, and footbridges over the communication trenches join the
    fields they cut off (a first draft left two pieces of field, 318 and 602 m², out of reach)."""
    label, nav = areas(kinds["trenches"](1))
    assert label.max() == 0
    assert (nav.centres[:, 1] < -2.0).sum() > 100 and (nav.centres[:, 1] > -0.5).sum() > 100


def test_every_tank_roof_of_the_refinery_is_reached(kinds):
    """One area: the stairs wound round the tanks reach their roofs (8-12 m up; a first draft's stairs ended
    without a landing and joined none), and no floor is left inside a tank or a column."""
    label, nav = areas(kinds["refinery"](0))
    assert label.max() == 0
    assert np.unique(np.round(nav.centres[nav.centres[:, 1] > 8.0, 1], 0)).size >= 4  # roofs at several heights


def test_the_cemeterys_crypt_is_reached_from_the_chapel(kinds):
    """The lanes between grave rows, the mausoleums and the crypt 3.5 m down are one area."""
    label, nav = areas(kinds["cemetery"](2))
    assert label.max() == 0
    assert (nav.centres[:, 1] < -3.0).sum() > 5


def test_the_quarrys_benches_are_one_area_down_the_haul_road(kinds):
    """Rim and five benches (0 to -20 m, 4 m apart) are one area, joined by the ramps only; no floor inside a
    ramp, a machine or a stockpile."""
    label, nav = areas(kinds["quarry"](0))
    assert label.max() == 0
    for level in range(6):
        assert (np.abs(nav.centres[:, 1] - 0.2 + 4.0 * level) < 0.3).sum() > 10, level


def test_every_landing_of_the_stairhall_is_reached(kinds):
    """The landings (3, 6, 9 and 12 m) grow as a spanning tree from the ones reached from the floor: one area."""
    label, nav = areas(kinds["stairhall"](1))
    assert label.max() == 0
    for level in (3.0, 6.0, 9.0, 12.0):
        assert (np.abs(nav.centres[:, 1] - 0.2 - level) < 0.3).any(), level


def test_the_hotels_six_storeys_are_one_area(kinds):
    """The stair core and the fire stair join the lobby to the five storeys of rooms, every room opens on its corridor,
    and the closets behind the fire stair, the lifts and the core's well hold no floor (a first draft left each an
    area of its own on every storey): one area, floor on each storey (0 to 16 m, 3.2 m apart)."""
    label, nav = areas(kinds["hotel"](1))
    assert label.max() == 0
    for storey in range(6):
        assert (np.abs(nav.centres[:, 1] - 0.2 - 3.2 * storey) < 0.3).sum() > 50, storey


def test_the_theme_parks_queues_open_on_its_paths(kinds):
    """Every queue maze is entered from the paths and the fenced rides hold no floor: one area, all of it on the
    ground."""
    label, nav = areas(kinds["theme_park"](0))
    assert label.max() == 0
    assert nav.centres[:, 1].max() < 0.5


def test_the_aqueducts_towns_are_joined_by_stairs_and_ramp(kinds):
    """The lower town (0 m) and the bridge's street and upper towns (8 m) are one area through the pier stairs and
    the ramp; the piers' tops under the deck hold no floor (a first draft's were areas of their own)."""
    label, nav = areas(kinds["aqueduct"](0))
    assert label.max() == 0
    assert (nav.centres[:, 1] < 0.5).sum() > 100 and (nav.centres[:, 1] > 7.5).sum() > 100


def test_the_warehouses_dock_floor_yard_and_mezzanine_are_one_area(kinds):
    """The yard (0 m), the dock floor (1.2 m, up the apron's ramp or the personnel door's steps) and the mezzanine
    (5.4 m) are one area; no floor inside the racks (the floor stops under them) or between pallet stacks."""
    label, nav = areas(kinds["warehouse"](0))
    assert label.max() == 0
    for level in (0.0, 1.2, 5.4):
        assert (np.abs(nav.centres[:, 1] - 0.2 - level) < 0.3).sum() > 10, level


def test_the_golf_courses_halves_are_joined_by_its_footbridges(kinds):
    """The creek cuts the course in two and three footbridges join the halves: one area."""
    label, _ = areas(kinds["golf"](2))
    assert label.max() == 0


def test_every_slab_of_the_building_site_is_reached(kinds):
    """The core stair and the scaffold's stair tower join the ground to the four slabs (3.5 to 14 m) and the
    scaffold decks round them: one area."""
    label, nav = areas(kinds["scaffold"](1))
    assert label.max() == 0
    for storey in range(5):
        assert (np.abs(nav.centres[:, 1] - 0.2 - 3.5 * storey) < 0.3).sum() > 20, storey


def test_the_dry_docks_floor_altars_deck_and_girder_walk_are_reached(kinds):
    """The flights down the dock's walls (each ending on a landing) and the head flight join the quays (0 m) to the
    altars (-5 m) and the floor (-10 m), the gangways join the ship's deck (2 m) and the stair tower the girder walk
    (14 m): one area but for scraps under 2 m², no floor inside the superstructure or the hatches."""
    label, nav = areas(kinds["dry_dock"](0))
    main = np.bincount(label).argmax()
    assert all(nav.areas[label == k].sum() < 2.0 for k in range(label.max() + 1) if k != main)
    y = nav.centres[label == main, 1] - 0.2
    for level in (-10.0, -5.0, 0.0, 2.0, 14.0):
        assert (np.abs(y - level) < 0.3).sum() >= 3, level


def test_the_mountain_pass_switchback_climbs_the_cliff(kinds):
    """One area; on the cliff (x 20-90 m, over 45 degrees) the floor 1.5-20 m up lies at three or more heights about
    6 m apart: the switchback's legs, one above another (the cliff itself holds none)."""
    label, nav = areas(kinds["mountain_pass"](0))
    assert label.max() == 0
    x, y, z = nav.centres.T
    on_cliff = (x > 20.0) & (x < 90.0) & (y > 1.5) & (y < 20.0)
    assert on_cliff.sum() > 10
    heights = np.unique(np.round(y[on_cliff] / 6.0))
    assert heights.size >= 3  # several legs, one above another


def test_the_zoos_aviary_opens_through_its_airlocks_only(kinds):
    """One area, all of it on the ground, no floor inside the enclosures, the tanks or the beds; the aviary's inside
    is reached through either airlock, and through nothing else: with both airlocks filled by solids (the hull of
    each one's walls, the only tops 3 m high; the net walls are the only tops 6 m high) the inside is cut off, with
    either one filled it is not (a first draft's outer doors, 1.6 m wide at an angle to the axes, closed one airlock
    on seeds 1 and 2)."""
    for seed in (1, 2):
        _aviary_is_entered_through_either_airlock_only(kinds["zoo"](seed))


def _aviary_is_entered_through_either_airlock_only(mesh) -> None:
    label, nav = areas(mesh)
    assert label.max() == 0
    assert nav.centres[:, 1].max() < 0.6
    net = mesh.vertices[np.isclose(mesh.vertices[:, 1], 6.0)][:, [0, 2]]
    centre = net.mean(axis=0)
    radius = np.median(np.linalg.norm(net - centre, axis=1))
    lock = mesh.vertices[np.isclose(mesh.vertices[:, 1], 3.0)][:, [0, 2]]
    lock = lock[np.linalg.norm(lock - centre, axis=1) < radius + 5.0]
    first = np.linalg.norm(lock - lock[0], axis=1) < 8.0
    assert 4 <= first.sum() < len(lock) - 3  # two airlocks, apart
    plugs = [trimesh.convex.convex_hull(np.concatenate([np.insert(group, 1, y, axis=1) for y in (-0.3, 3.0)]))
             for group in (lock[first], lock[~first])]

    def cut_off(filled: list) -> bool:
        label, nav = areas(trimesh.util.concatenate([mesh, *filled]))
        x, y, z = nav.centres.T
        far = np.hypot(x - centre[0], z - centre[1])
        inside, outside = set(label[(y < 0.6) & (far < radius - 1.0)]), set(label[(y < 0.6) & (far > radius + 5.0)])
        assert inside and outside
        return not inside & outside

    assert cut_off(plugs)
    assert not cut_off(plugs[:1]) and not cut_off(plugs[1:])


def test_the_skateparks_bowls_are_out_of_reach_but_the_channelled_one(kinds):
    """The plaza is one area with the channelled bowl's bottom in it (y under -2 m); every other bowl's bottom is an
    area of its own: the wall turns past 45 degrees at 29 % of its height."""
    label, nav = areas(kinds["skatepark"](0))
    main = np.bincount(label).argmax()
    low = nav.centres[:, 1] < -1.5
    assert (low & (label == main)).any()
    assert len(set(label[low]) - {main}) >= 2


def test_the_interchanges_three_lines_are_reached_from_the_concourse(kinds):
    """The escalator banks (and the fixed flight A-B) join the concourse (0 m) to lines A (-8 m), B (-16 m) and C
    (-24 m): one area, floor on each."""
    label, nav = areas(kinds["interchange"](2))
    assert label.max() == 0
    for level in (0.0, -8.0, -16.0, -24.0):
        assert (np.abs(nav.centres[:, 1] - 0.2 - level) < 0.3).sum() > 30, level


def test_the_stepwells_terraces_are_one_area_down_its_flights(kinds):
    """Every terrace (1.8 m below the one above: walls, not steps) is reached from the plaza down the flights: one
    area with floor on the plaza and on each terrace."""
    label, nav = areas(kinds["stepwell"](1))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    rings = int(round(-y.min() / 1.8))
    assert rings >= 4
    for k in range(rings + 1):
        assert (np.abs(y + 1.8 * k) < 0.3).sum() > 10, k


def test_the_farms_fields_are_one_area_and_its_lofts_apart(kinds):
    """Gates, gaps in hedges and stiles (0.9 m up over a fence) join every field to the yard: one area with floor in
    each of the nine fields; the two barn lofts (3.2 m up, reached by ladders only) are areas of their own."""
    label, nav = areas(kinds["farm"](0))
    main = np.bincount(label, weights=nav.areas).argmax()
    x, y, z = nav.centres[label == main].T
    for x0, x1 in ((0.0, 60.0), (80.0, 130.0), (150.0, 210.0)):
        for z0, z1 in ((0.0, 48.0), (62.0, 98.0), (112.0, 160.0)):
            assert ((x > x0) & (x < x1) & (z > z0) & (z < z1)).sum() > 5, (x0, z0)
    lofts = [k for k in range(label.max() + 1) if k != main]
    assert len(lofts) == 2
    for k in lofts:
        assert nav.areas[label == k].sum() > 50.0 and np.allclose(nav.centres[label == k, 1], 3.4, atol=0.3)


def test_the_cruise_ships_five_decks_are_one_area(kinds):
    """The stern and bow flights join the five decks (0 to 12 m, 3 m apart): one area, floor on each deck; no floor
    inside the cabin block, the funnel or the pools."""
    label, nav = areas(kinds["cruise_ship"](1))
    assert label.max() == 0
    for deck in range(5):
        assert (np.abs(nav.centres[:, 1] - 0.2 - 3.0 * deck) < 0.3).sum() > 20, deck


def test_the_treetop_platforms_are_reached_from_the_floor_but_the_hides(kinds):
    """The forest floor, the flights and the platforms joined by bridges are one area; every other area is a hide
    (up a ladder only): a platform or two over 3.5 m up, under 100 m²."""
    label, nav = areas(kinds["treetops"](2))
    main = np.bincount(label, weights=nav.areas).argmax()
    y = nav.centres[:, 1]
    assert ((label == main) & (y > 4.0)).sum() > 50 and ((label == main) & (y < 2.0)).sum() > 100
    for k in set(range(label.max() + 1)) - {main}:
        assert y[label == k].min() > 3.5 and nav.areas[label == k].sum() < 100.0, k


def test_the_beachs_bays_are_reached_down_their_flights(kinds):
    """Each bay between groynes is a dead end reached from the promenade (4.5 m) only by its own flights: one
    area with floor in every bay, on the promenade and on the pier's head out over the sea."""
    label, nav = areas(kinds["beach"](0))
    assert label.max() == 0
    x, y, z = nav.centres.T
    assert (np.abs(y - 4.7) < 0.3).sum() > 20 and ((z < -10.0) & (y > 4.0)).sum() > 3
    for x0 in range(0, 240, 40):  # sand all along the front
        assert ((x > x0) & (x < x0 + 40) & (y < 3.0)).sum() > 5, x0


@pytest.mark.parametrize("seed", [0, 1])
def test_no_dune_reaches_over_a_groyne(kinds, seed):
    """Without the promenade and the pier (over 4 m) the sand falls apart into one area per bay (over 100 m²): no
    dune rises within the climb of a groyne's top (3 m), which seed 0's did twice."""
    mesh = kinds["beach"](seed)
    groynes = np.unique(np.round(mesh.vertices[np.isclose(mesh.vertices[:, 1], 3.0), 0] - 0.2, 1))[::2]
    nav = build_navmesh(mesh.vertices, mesh.faces, AGENT)
    low = np.flatnonzero(nav.centres[:, 1] < 4.0)
    inside = np.isin(nav.neighbours, low) & np.isin(np.arange(nav.polygon_count), low)[:, None]
    rows, slots = np.nonzero(inside)
    index = np.searchsorted(low, [rows, nav.neighbours[rows, slots]])
    graph = sp.coo_matrix((np.ones(len(rows)), (index[0], index[1])), shape=(len(low),) * 2)
    label = connected_components(graph, directed=False)[1]
    sizes = np.bincount(label, weights=nav.areas[low])
    assert (sizes > 100.0).sum() == len(groynes) + 1  # (and a few square metres shut in behind a hut)


def test_the_railyard_is_one_area_over_its_footbridge(kinds):
    """The gaps between wagons, the roads, the shed and the footbridge (6.5 m) are one area; no floor on a wagon,
    under the footbridge or away from it: over the tracks (between the 10 m roads) the only floor over 1 m up is the
    footbridge's deck, over the roads its flights."""
    label, nav = areas(kinds["railyard"](0))
    assert label.max() == 0
    x, y, z = nav.centres.T
    deck = np.abs(y - 6.7) < 0.3
    assert deck.sum() > 3
    bridge_x = x[deck].mean()
    tracks = (z > z.min() + 10.0) & (z < z.max() - 10.0)
    assert (deck & tracks).sum() > 3
    assert (deck[(y > 1.0) & tracks] & (np.abs(x[(y > 1.0) & tracks] - bridge_x) < 2.0)).all()
    assert (np.abs(x[(y > 1.0) & ~tracks] - bridge_x) < 14.0).all()  # the flights, 10.4 m long, along x


def test_the_craters_are_one_area_down_to_their_bottoms(kinds):
    """The shelled ground, crater bottoms and all, is one area between the sandbag lines' gaps."""
    label, nav = areas(kinds["craters"](1))
    assert label.max() == 0
    assert nav.centres[:, 1].min() < -1.5


def test_the_oil_rigs_decks_are_one_area_with_the_accommodation_platform(kinds):
    """The flights join the boat landing (3 m) and the three decks (12, 19 and 26 m), the bridge the accommodation
    platform's deck (19 m), its flight the helideck (26 m): one area with floor at each height."""
    label, nav = areas(kinds["oil_rig"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for level in (3.0, 12.0, 19.0, 26.0):
        assert (np.abs(y - level) < 0.3).sum() > (1 if level == 3.0 else 20), level


def test_the_monasterys_top_is_reached_only_by_its_stair(kinds):
    """One area from the hamlet to the top (32.4 or 35.6 m); every floor between 1 m and 1 m under the top lies in
    the stair's lane (2.4 m wide) along the rock's south face or its east face: no other way up."""
    label, nav = areas(kinds["monastery"](0))
    assert label.max() == 0
    x, y, z = nav.centres.T
    top = y.max()
    assert top > 32.0
    on_top = y > top - 0.5
    x1, z0 = x[on_top].max(), z[on_top].min()  # the rock's top, walls off: its east and south edges
    between = (y > 1.0) & (y < top - 1.0)
    assert between.sum() > 10
    south = (z[between] < z0) & (z[between] > z0 - 3.5)
    east = (x[between] > x1) & (x[between] < x1 + 3.5)
    assert (south | east).all()


def test_the_night_markets_halves_meet_only_round_or_through_the_viaduct(kinds):
    """No floor over 1 m (the viaduct's top, its piers and the stalls are ridged); the halves either side are one
    area through the arches, and two with the viaduct's band filled (1.5 m high) from street to street."""
    mesh = kinds["night_market"](1)
    label, nav = areas(mesh)
    assert label.max() == 0 and nav.centres[:, 1].max() < 1.0
    eaves = mesh.vertices[np.isclose(mesh.vertices[:, 1], 9.0)]
    z0, z1, length = eaves[:, 2].min(), eaves[:, 2].max(), eaves[:, 0].max()
    assert np.isclose(z1 - z0, 12.0)
    band = trimesh.creation.box(bounds=[[-9.0, -1.0, z0], [length + 9.0, 1.5, z1]])  # 1.5 m: no head room in it
    label, nav = areas(trimesh.util.concatenate([mesh, band]))
    assert len(set(label[nav.centres[:, 1] < 1.0])) == 2  # the ground only: the band's top (1.5 m) is floor too


def test_the_cinemas_foyer_and_lobby_are_one_area(kinds):
    """The lobby (0 m) and the foyer (6 m) are one area through the foyer's flights and the auditoria's aisles, with
    floor at both heights."""
    label, nav = areas(kinds["cinema"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert (np.abs(y) < 0.3).sum() > 100 and (np.abs(y - 6.0) < 0.3).sum() > 10


def test_the_estates_galleries_are_one_area_with_the_courtyards(kinds):
    """Stairs, pends and bridges join the courtyards (0 m) and the galleries on the three storeys (3, 6 and 9 m):
    one area with floor on each and none over the top galleries (the blocks' roofs are ridged)."""
    label, nav = areas(kinds["estate"](1))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for level in (0.0, 3.0, 6.0, 9.0):
        assert (np.abs(y - level) < 0.3).sum() > 20, level
    assert y.max() < 9.5


def test_the_dams_crest_and_valley_are_one_area(kinds):
    """The face stairs join the valley floor (0 m) to the crest and the hilltops (24 or 27 m): one area, floor at
    both heights, none up stream of the dam but on the hilltops."""
    label, nav = areas(kinds["dam"](2))
    assert label.max() == 0
    x, y, z = nav.centres.T
    top = y.max()
    assert top > 24.0 and (y < 0.5).sum() > 100 and (y > top - 0.3).sum() > 20
    hills = (x < 40.0) | (x > x[y < 0.5].max() + 1.0)
    assert (hills | (z < 68.0)).all()


def test_the_gardens_terrace_belvedere_and_grotto_are_one_area_with_the_parterre(kinds):
    """The terrace (1.5 m) up its flights, the belvedere (2.5 m) up its own, the maze and the grotto under its lid:
    one area, and no floor on a bed, the fountain or the house (all ridged)."""
    label, nav = areas(kinds["garden"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert (np.abs(y - 1.5) < 0.3).sum() > 20 and (np.abs(y - 2.5) < 0.3).sum() >= 1 and y.max() < 3.0


def test_the_lighthouses_gallery_is_reached_up_the_tower_from_the_mainland(kinds):
    """Mainland, causeway, shelf (0 m), plinth (3 m), the tower's landings (7, 11, 15, 19 m) and the gallery (23 m):
    one area, with floor at each height."""
    label, nav = areas(kinds["lighthouse"](1))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for level in (0.0, 3.0, 7.0, 11.0, 15.0, 19.0, 23.0):
        assert (np.abs(y - level) < 0.3).sum() >= 1, level
    assert y.max() < 23.5


def test_the_canals_banks_meet_only_on_its_bridges(kinds):
    """Both banks at every pound's height (0, 2, ... m) are one area; over the water (the canal's 7 m) there is
    floor only on the gates' footbridges (2 m wide, two a lock) and the road bridge (6 m wide)."""
    mesh = kinds["canal_locks"](2)
    label, nav = areas(mesh)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    top = int(round(y.max() / 2.0))
    assert 7 <= top <= 9
    for k in range(top + 1):
        assert (np.abs(y - 2.0 * k) < 0.3).sum() > 10, k
    over = np.abs(nav.centres[:, 2]) < 3.0
    assert nav.areas[over].sum() < (2 * top * 2.0 + 6.0) * 7.0


def test_the_water_parks_slide_towers_are_reached_up_their_wells(kinds):
    """The deck, the island over its bridges, the cubicles and both towers' tops (12 m, up the switchback wells) are
    one area, with floor on each top and none above."""
    label, nav = areas(kinds["water_park"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert (np.abs(y - 12.0) < 0.3).sum() >= 2 and y.max() < 12.5


def test_the_paddies_bunds_climb_to_the_shrine(kinds):
    """The village (0 m) and the shrine's yard at the top are one area through the bunds and flights; the paddies
    hold no floor, so the terraces' floor is narrow: the bunds' 1.8 m (0.8 m of navmesh)."""
    label, nav = areas(kinds["paddies"](1))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert (np.abs(y) < 0.3).sum() > 20 and y.max() > 12.0
    terraces = (y > 0.5) & (nav.centres[:, 2] < nav.centres[np.argmax(y), 2] - 20.0)
    assert nav.areas[terraces].sum() < 0.25 * np.ptp(nav.centres[terraces, 0]) * np.ptp(nav.centres[terraces, 2])


def test_the_cisterns_walkways_join_its_two_streets(kinds):
    """The two streets (6 m) are one area with the walkways (0 m) through the stair wells; the walkways, 2.2 m wide
    on a 5 m grid, cover under half the hall between the streets."""
    label, nav = areas(kinds["cistern"](2))
    assert label.max() == 0
    x, y, _ = nav.centres.T
    low = y < 0.5
    assert (y > 6.0).sum() > 20 and low.sum() > 100
    assert (x[y > 6.0] < 0.0).any() and (x[y > 6.0] > x[low].max()).any()
    assert nav.areas[low].sum() < 0.5 * np.ptp(x[low]) * np.ptp(nav.centres[low, 2])


def test_the_gardens_canal_is_crossed_only_on_its_bridges(kinds):
    """The canal runs from wall to wall: over its 6 m of water there is floor only on the axis bridge (6 m wide) and
    the second one (3 m)."""
    mesh = kinds["garden"](1)
    _, nav = areas(mesh)
    rails = mesh.vertices[np.isclose(mesh.vertices[:, 1], 1.1)]  # the bridges' rails, 0.5 m past the canal's banks
    z0, z1 = rails[:, 2].min() + 0.5, rails[:, 2].max() - 0.5
    over = (nav.centres[:, 2] > z0 + 0.5) & (nav.centres[:, 2] < z1 - 0.5)
    assert over.any() and nav.areas[over].sum() < (6.0 + 3.0) * (z1 - z0)
    # the floor over the water lies in at most two runs along the canal, each no wider than a bridge
    along = np.sort(nav.centres[over, 0])
    assert 1 + np.count_nonzero(np.diff(along) > 6.0) <= 2


def test_the_forts_courtyard_walk_and_moat_are_one_area(kinds):
    """The courtyard and glacis (0 m), the ramparts' walk (4.5 m, up the ramps) and the moat's floor (-5 m, down its
    flights) are one area; at the ground's height the courtyard meets the glacis only over the ravelin's bridges."""
    label, nav = areas(kinds["star_fort"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for level in (-5.0, 0.0, 4.5):
        assert (np.abs(y - level) < 0.3).sum() > 20, level
    ground = np.flatnonzero(np.abs(y) < 0.3)
    x, z = nav.centres[ground, 0], nav.centres[ground, 2]
    walk = np.abs(y - 4.5) < 0.3
    x0, x1, z0 = nav.centres[walk, 0].min(), nav.centres[walk, 0].max(), nav.centres[walk, 2].min()
    assert ((x > x0) & (x < x1) & (z > 0.0) & (z < nav.centres[walk, 2].max())).sum() > 20  # the courtyard
    front = (x > x0) & (x < x1) & (z > z0) & (z < 0.0)  # between the bastions' points and the south curtain
    assert front.any() and (np.abs(x[front] - (x0 + x1) / 2) < 13.0).all()  # the ravelin and drawbridge only


def test_the_glacier_is_one_area_holed_by_its_crevasses(kinds):
    """The lower and upper glacier are one area through the icefall's ramps, its floor climbing over 25 m, and the
    crevasses hold no floor: the navmesh covers under nine tenths of its plan."""
    label, nav = areas(kinds["glacier"](1))
    assert label.max() == 0
    x, y, z = nav.centres.T
    assert np.ptp(y) > 25.0
    assert nav.areas.sum() < 0.9 * np.ptp(x) * np.ptp(z)


def test_the_medinas_alleys_and_courtyards_are_one_area_with_the_road_outside(kinds):
    """The alleys, the courtyard houses (by their doors), the mosque's courtyard and the road outside the wall (by
    its gates) are one area on the ground, and houses fill most of the walled town: alleys 2.6 m wide on a 9 m
    lattice leave it under half its plan."""
    label, nav = areas(kinds["medina"](2))
    assert label.max() == 0
    x, y, z = nav.centres.T
    assert np.ptp(y) < 0.3
    town = (x > x.min() + 15.0) & (x < x.max() - 15.0) & (z > z.min() + 15.0) & (z < z.max() - 15.0)
    assert nav.areas[town].sum() < 0.5 * np.ptp(x[town]) * np.ptp(z[town])


def test_the_suburbs_gardens_roads_and_green_are_one_area(kinds):
    """Every back garden opens on its close through its gate, the closes on the distributor road and (some) on the
    green: one area on the ground, and nothing on a roof, a car or a play frame."""
    label, nav = areas(kinds["suburb"](1))
    assert label.max() == 0
    assert np.ptp(nav.centres[:, 1]) < 0.3


def test_the_cloverleafs_roads_meet_only_through_its_loops(kinds):
    """Motorway A (0 m) and the viaduct B (7.5-8.5 m) are one area through the four loops, the only floor between
    their heights; no floor on A's barrier (its carriageways meet only through the loops and B)."""
    label, nav = areas(kinds["cloverleaf"](2))
    assert label.max() == 0
    x, y, z = (nav.centres - np.array([0.0, 0.2, 0.0])).T
    top = y.max()
    assert 7.5 <= top <= 8.5 and (np.abs(y) < 0.3).sum() > 20
    between = (y > 0.5) & (y < top - 0.5)
    assert between.sum() >= 8 and (np.hypot(np.abs(x[between]) - 9.5, np.abs(z[between]) - 9.5) > 9.5).all()
    assert not ((np.abs(y) < 0.3) & (np.abs(z) < 0.5)).any()


def test_the_radial_towns_streets_are_its_only_floor(kinds):
    """The place, avenues, lanes, rings and the gardens are one area at 0 m, and the blocks (ridged) hold no floor:
    the streets cover under half the town's disc."""
    label, nav = areas(kinds["radial_town"](0))
    assert label.max() == 0
    x, y, z = nav.centres.T
    assert np.ptp(y) < 0.3
    radius = np.hypot(x, z).max()
    assert nav.areas.sum() < 0.5 * math.pi * radius**2


def test_the_bazaars_alleys_run_at_every_angle_and_join_the_street(kinds):
    """The alleys, courtyards and the street outside (by the four gates) are one area on the ground, the stalls hold
    no floor (the alleys cover under half the walled plan), and the alleys' polygons face every way: a fifth of
    their edges at least 15 degrees off both axes (the Voronoi cells' walls)."""
    label, nav = areas(kinds["bazaar"](0))
    assert label.max() == 0
    x, y, z = nav.centres.T
    assert np.ptp(y) < 0.3
    inside = (x > 1.0) & (x < x.max() - 13.0) & (z > 1.0) & (z < z.max() - 13.0)
    assert nav.areas[inside].sum() < 0.5 * (x.max() - 13.0) * (z.max() - 13.0)
    ends = [(nav.vertices[p[k]], nav.vertices[p[(k + 1) % np.count_nonzero(p >= 0)]])
            for p in nav.polygons[inside] for k in range(np.count_nonzero(p >= 0))]
    angles = np.array([math.degrees(math.atan2(b[2] - a[2], b[0] - a[0])) % 90.0 for a, b in ends])
    assert np.mean((angles > 15.0) & (angles < 75.0)) > 0.2


def test_the_container_ports_tops_are_out_of_reach(kinds):
    """The ground (apron, straddle lanes, road, gate) is one area; every other area is a container top at 2.6, 5.2
    or 7.8 m, a hundred and more of them."""
    label, nav = areas(kinds["container_port"](1))
    main = np.bincount(label, weights=nav.areas).argmax()
    y = nav.centres[:, 1] - 0.2
    assert np.ptp(y[label == main]) < 0.3
    tops = y[label != main]
    assert label.max() >= 100 and (np.min(np.abs(tops[:, None] - np.array([2.6, 5.2, 7.8])), axis=1) < 0.2).all()


def test_the_theatres_aisles_climb_off_the_axes_to_the_terrace(kinds):
    """The orchestra and plain (0 m), the diazoma and the terrace (16-18 m) are one area through the radial aisles
    and the two flights; aisle steps stand at every angle between the axes; the seats hold no floor but pieces of a
    few square metres at most (where Recast's erosion leaves a sliver on a tier 0.84 m deep at about 45 degrees; those
    under region_min_size² cells at a tile border are dropped as a solo build drops them: none is left on seed 1)."""
    label, nav = areas(kinds["theatre"](1))
    sizes = np.bincount(label, weights=nav.areas)
    main = sizes.argmax()
    x, y, z = nav.centres[label == main].T
    assert y.min() < 0.5 and y.max() > 16.0
    aisles = (y > 1.0) & (y < y.max() - 1.0) & (z > 1.0)
    angles = np.degrees(np.arctan2(z[aisles], x[aisles]))
    assert all(((angles > a) & (angles < a + 30.0)).any() for a in (0.0, 30.0, 60.0, 90.0, 120.0, 150.0))
    assert np.delete(sizes, main).size == 0


def test_the_stilt_village_is_one_area_of_decks_over_the_water(kinds):
    """Platforms, houses, boardwalks at every angle, pontoons (0.4 m) and the bank (2.4 m) are one area, with no
    floor at the water's level."""
    label, nav = areas(kinds["stilt_village"](2))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert y.min() > 0.3 and ((y > 0.3) & (y < 0.6)).sum() >= 5 and y.max() < 2.7


def test_the_nurserys_bench_aisles_and_tunnels_open_on_the_yard(kinds):
    """Every bench aisle, glasshouse, polytunnel and path between beds is one area with the yard (a first draft's
    tunnel beds, ridged across, closed each tunnel's path)."""
    label, nav = areas(kinds["nursery"](0))
    assert label.max() == 0
    assert np.ptp(nav.centres[:, 1]) < 0.3


def test_the_cliff_dwellings_storeys_are_one_area_through_the_rock(kinds):
    """The valley, the five storeys' ledges and rooms (a first draft's doors, 1.6 m through 0.6 m of rock, shut every
    room) and the plateau (25 m) are one area, joined by the stair wells and the face's flight."""
    label, nav = areas(kinds["cliff_dwellings"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for level in (0.0, 5.0, 10.0, 15.0, 20.0, 25.0):
        assert (np.abs(y - level) < 0.3).sum() > 10, level


def test_the_drop_downs_terraces_are_joined_by_flights_but_the_one_reached_by_dropping(kinds):
    """The terraces and their flights are one area; the block with no flight, reached in a game only by dropping onto
    it, is an area of its own, a whole block's top (15-18 m square less its cover) between 1 and 17.4 m up."""
    label, nav = areas(kinds["drop_downs"](1))
    sizes = np.bincount(label, weights=nav.areas)
    assert label.max() == 1
    assert 150.0 < sizes.min() < 324.0
    y = nav.centres[label == sizes.argmin(), 1] - 0.2
    assert np.ptp(y) < 0.3 and 1.0 < y.min() < 17.4


def test_the_houses_storeys_rooms_and_garden_are_one_area_through_doors_just_wide_enough(kinds):
    """Both houses' two storeys (up their narrow stairs), the rooms (through doors 1.5-1.6 m wide) and the garden are
    one area; the rest are pockets behind furniture of under 15 m² (with doors of 0.9-1.0 m, a real house's, every
    room is such an island for the presets' agent)."""
    label, nav = areas(kinds["house"](0))
    sizes = np.bincount(label, weights=nav.areas)
    main = sizes.argmax()
    assert np.delete(sizes, main).max() < 15.0
    y, area = nav.centres[label == main, 1] - 0.2, nav.areas[label == main]
    assert area[np.abs(y) < 0.3].sum() > 1000.0 and area[np.abs(y - 3.0) < 0.3].sum() > 150.0


def test_the_pitched_roofs_are_floor_reached_from_their_balconies(kinds):
    """With the presets' ledge filter (``drops``) the streets, yards, flights, balconies and roofs at 30-40 degrees
    are one area, with floor up to the ridges (5.5-7.5 m eaves, 2.6-4.6 m more to the ridge); Recast's own ledge rule
    cuts the roofs steeper than about 38.7 degrees (atan(0.4 / 0.5)) into pieces."""
    mesh = kinds["pitched_roofs"](0)
    label, nav = areas(mesh, RecastParams(ledge_filter="drops"))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[y > 6.0].sum() > 1500.0 and y.max() > 9.0
    assert areas(mesh)[0].max() > 10


def test_the_kit_arenas_seams_leave_one_symmetric_area(kinds):
    """Floor, platforms 2 and 4 m up and stair tiles are one area although no two tiles meet (seams of up to 3 cm);
    the arena is symmetric under a half turn, so the walkable area on either side of its centre line is within a few
    per cent."""
    label, nav = areas(kinds["kit_arena"](1))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for level in (0.0, 2.0, 4.0):
        assert nav.areas[np.abs(y - level) < 0.3].sum() > 50.0, level
    low = nav.centres[:, 2] < 40.0
    assert abs(nav.areas[low].sum() / nav.areas[~low].sum() - 1.0) < 0.05


def test_the_spiral_towers_are_climbed_up_their_helices(kinds):
    """The bailey, both towers' storeys and roofs and the wall walk are one area; the helices hold floor at every
    height between the storeys (polygon centres inside a shaft, 1.0-2.3 m from its axis)."""
    label, nav = areas(kinds["spiral_towers"](0))
    assert label.max() == 0
    x, y, z = nav.centres.T
    shaft = np.hypot(x, z) < 2.8  # the first tower's shaft, about the origin
    assert y.max() > 16.0 and len(np.unique(np.round(y[shaft]))) > 10


def test_the_backdrops_square_is_apart_from_the_background_and_the_skybox_holds_no_floor(kinds):
    """The square (its terrace and flights) is one area with nothing of the background; the background's walkable
    hillsides are areas of their own, dozens of them; no floor lies on the skybox (its walls and ceiling face in)."""
    label, nav = areas(kinds["backdrop"](1))
    x, y, z = nav.centres.T
    square = (y < 3.0) & (x > 0.0) & (x < 80.0) & (z > 0.0) & (z < 80.0)
    inside = np.unique(label[square])
    assert len(inside) == 1 and (label == inside[0]).sum() == square.sum()
    assert label.max() > 20 and np.abs(x - 40.0).max() < 200.0 and y.max() < 180.0


def test_rooms_behind_closed_leaves_are_islands_and_the_rest_one_area(kinds):
    """A closed door's leaf is a wall for Recast: the rooms whose every door is closed are islands on the ground (each
    a room's floor, under 60 m²), five or more on seed 0; the yard, corridors and the other rooms are one area."""
    label, nav = areas(kinds["closed_doors"](0))
    sizes = np.bincount(label, weights=nav.areas)
    main = sizes.argmax()
    assert sizes[main] > 5000.0 and len(sizes) >= 6
    assert np.delete(sizes, main).max() < 60.0 and np.ptp(nav.centres[:, 1]) < 0.3


def test_paper_walls_stop_the_agent_as_solid_walls_do(kinds, monkeypatch):
    """Quads with no thickness, one-sided, as walls, fences and railings give the areas that walls 0.2 m thick in their
    place give, and a walkable area within 3 % of theirs (the walls' thickness); the paper deck (one quad facing up,
    3 m up) is floor joined by its flights."""
    module = benchmark("level_kinds")
    label, nav = areas(module.paper_walls(2))
    main = np.bincount(label, weights=nav.areas).argmax()
    assert (nav.centres[label == main, 1] > 3.0).any()

    def solid(s, a, b, y0, y1, flip):
        s.prism(module._strip(a, b, 0.2), y0, y1)

    monkeypatch.setattr(module, "_paper", solid)
    solid_label, solid_nav = areas(module.paper_walls(2))
    assert label.max() == solid_label.max()
    assert abs(nav.areas.sum() / solid_nav.areas.sum() - 1.0) < 0.03


def test_the_split_level_houses_half_storeys_are_one_area(kinds):
    """Garden, both houses' six half storeys (the front wing's at 0, 2h, 4h, the back wing's at h, 3h, 5h, h 1.4-1.6 m)
    are one area through the short flights, with floor up to the top back storey (at least 7 m up)."""
    label, nav = areas(kinds["split_level"](2))
    assert label.max() == 0
    assert nav.centres[:, 1].max() > 7.0


def test_the_hub_rooms_open_only_on_the_courtyard_and_gallery(kinds):
    """Street, courtyard, both storeys' rooms (doors 1.6 m wide under lintels 2.3 m up) and the gallery 4 m up are one
    area (seed 0)."""
    label, nav = areas(kinds["hub_rooms"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y - 4.0) < 0.3].sum() > 400.0


def test_the_corridor_shooter_is_one_path_hundreds_of_metres_long(kinds):
    """Start, corridors, alcoves, arenas and their platforms are one area running east over 250 m."""
    label, nav = areas(kinds["corridor_shooter"](1))
    assert label.max() == 0
    assert np.ptp(nav.centres[:, 0]) > 250.0 and (nav.centres[:, 1] > 1.5).any()


def test_the_roof_towns_roofs_are_islands_over_one_town_of_streets(kinds):
    """The streets and courtyards are one area on the ground; the other areas (scores) are roofs at 3.5, 7, 10.5 or
    14 m."""
    label, nav = areas(kinds["roof_town"](1))
    sizes = np.bincount(label, weights=nav.areas)
    main = sizes.argmax()
    y = nav.centres[:, 1] - 0.2
    assert np.abs(y[label == main]).max() < 10.7 and (np.abs(y[label == main]) < 0.3).mean() > 0.5
    assert label.max() >= 50
    roofs = y[label != main]
    assert (np.min(np.abs(roofs[:, None] - np.array([3.5, 7.0, 10.5, 14.0])), axis=1) < 0.3).all()


def test_the_ladders_storeys_are_three_areas_no_ladder_or_lift_joins(kinds):
    """Ladders and lift shafts are the only links between the storeys (0, 4.5 and 9 m): three areas, one a storey,
    each over 1,500 m², the ground's with the yard."""
    label, nav = areas(kinds["ladders"](1))
    assert label.max() == 2
    for k in range(3):
        y = nav.centres[label == k, 1] - 0.2
        assert np.ptp(y) < 0.3 and nav.areas[label == k].sum() > 1500.0
    storeys = np.sort([np.median(nav.centres[label == k, 1]) - 0.2 for k in range(3)])
    assert np.abs(storeys - np.array([0.0, 4.5, 9.0])).max() < 0.2


def test_the_jump_gaps_part_the_walkways_into_areas_over_the_void(kinds):
    """Every floor is a platform's or a walkway's top 8 m up or a dais's flight and top (nothing below); gaps 0.8-2 m
    part the walkways, so the level is several areas, none a sliver (each a platform or more, over 100 m²)."""
    label, nav = areas(kinds["jump_gaps"](1))
    y = nav.centres[:, 1] - 0.2
    assert (y > 7.8).all() and (y < 9.9).all() and (np.abs(y - 8.0) < 0.3).mean() > 0.9
    sizes = np.bincount(label, weights=nav.areas)
    assert len(sizes) >= 3 and sizes.min() > 100.0


def test_collision_hulls_hold_floor_on_their_tops_and_inside(kinds):
    """The square is one area holding nearly all the floor; Recast reads each hull as a solid, so the bandstand's hull
    holds floor on its top (5 m up) and its deck inside (1 m up), each an area of its own."""
    label, nav = areas(kinds["collision_hulls"](1))
    sizes = np.bincount(label, weights=nav.areas)
    main = sizes.argmax()
    assert sizes[main] > 0.95 * sizes.sum() and len(sizes) > 5
    y = nav.centres[:, 1] - 0.2
    for height in (5.0, 1.0):
        on = (np.abs(y - height) < 0.1) & (label != main)
        assert nav.areas[on].sum() > 50.0, height


def test_the_thresholds_kerbs_and_sills_are_climbed_into_one_area(kinds):
    """Kerbs of 0.10-0.30 m, door steps of 0.05-0.30 m and sills 0.05-0.15 m high, all under the 0.4 m climb: the
    roads, pavements and every shop's rooms are one area at floors from 0 to 0.6 m."""
    label, nav = areas(kinds["thresholds"](2))
    assert label.max() == 0
    assert (nav.centres[:, 1] - 0.2 > 0.3).sum() > 100


def test_the_prop_piles_containers_hold_floor_inside_and_on_top(kinds):
    """The yard round the interpenetrating props is one area; every other area is a container's top (2.5 m up) or the
    floor inside a container (a closed box sunk into the floor), each under 10 m²."""
    label, nav = areas(kinds["prop_pile"](1))
    sizes = np.bincount(label, weights=nav.areas)
    main = sizes.argmax()
    others = np.delete(np.arange(len(sizes)), main)
    assert len(others) >= 4 and sizes[others].max() < 10.0
    heights = np.array([nav.centres[label == k, 1].mean() - 0.2 for k in others])
    assert (np.abs(heights - 2.5) < 0.2).any() and (np.abs(heights) < 0.2).any()
    assert ((np.abs(heights - 2.5) < 0.2) | (np.abs(heights) < 0.2)).all()


def test_the_beams_hold_no_floor_so_the_roofs_stand_apart(kinds):
    """The street and the start roof (4 m up, by its flight) are one area; beams 0.4-0.8 m wide hold no floor for the
    presets' agent, so roofs joined only by beams are areas of their own (more than five roofs apart)."""
    label, nav = areas(kinds["beams"](0))
    sizes = np.bincount(label, weights=nav.areas)
    main = sizes.argmax()
    y = nav.centres[:, 1] - 0.2
    assert (np.abs(y[label == main] - 4.0) < 0.1).any()
    assert len({int(k) for k in label[y > 3.0]} - {int(main)}) > 5


def test_a_tile_run_at_45_degrees_is_a_staircase_of_tiles_sharing_edges():
    """``_paint`` with no brush marks, from tile (0, 0) to (2, 2), the five tiles of a staircase: each shares an edge
    with the one before it, steps along i and j alternating."""
    paint = benchmark("level_kinds")._paint
    mask = np.zeros((4, 4), dtype=bool)
    paint(mask, np.array([0, 0]), np.array([2, 2]), 0)
    assert sorted(zip(*np.nonzero(mask))) == [(0, 0), (1, 0), (1, 1), (2, 1), (2, 2)]


def test_the_mobas_lanes_river_and_jungle_are_one_area_symmetric_under_a_half_turn(kinds):
    """One area with floor on the river (0.3 m under the lanes); the map's solids map onto themselves under a half
    turn about the centre of its square."""
    mesh = kinds["moba"](0)
    label, nav = areas(mesh)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert (np.abs(y + 0.3) < 0.1).sum() > 10 and (np.abs(y) < 0.1).sum() > 100
    side = mesh.vertices[:, 0].max() + mesh.vertices[:, 0].min()
    points = {tuple(v) for v in np.round(mesh.vertices, 3)}
    turned = {tuple(v) for v in np.round(mesh.vertices * [-1.0, 1.0, -1.0] + [side, 0.0, side], 3)}
    assert points == turned


def test_the_capture_flag_bases_meet_over_the_field_and_through_both_tunnels(kinds):
    """One area: the field, both bases' halls and flag rooms (4 m up) and the two tunnels 4.5 m under the field, each
    floor over 90 m long."""
    label, nav = areas(kinds["capture_flag"](1))
    assert label.max() == 0
    x, y, z = nav.centres.T
    tunnel = np.abs(y - 0.2 + 4.5) < 0.2
    for half in (z < z.mean(), z > z.mean()):
        assert np.ptp(x[tunnel & half]) > 90.0
    upper = np.abs(y - 0.2 - 4.0) < 0.2
    assert (upper & (x < x.mean())).sum() > 3 and (upper & (x > x.mean())).sum() > 3


def test_the_platform_towers_spiral_is_one_area_over_the_void(kinds):
    """Every join (ramp or flight) lands on the next platform: one area climbing over 100 m from the plaza."""
    label, nav = areas(kinds["platform_tower"](0))
    assert label.max() == 0 and nav.centres[:, 1].max() > 100.0


def test_the_diagonal_dungeons_staircase_corridors_join_every_room(kinds):
    """Corridors one 2 m tile wide, at 45 degrees a staircase of tiles, pass the presets' agent: one area."""
    label, _ = areas(kinds["diagonal_dungeon"](1))
    assert label.max() == 0


def test_the_battle_royale_field_and_houses_are_one_area_but_rock_tops(kinds):
    """The rolling field and every house (floors 0.15 m up through doors 1.6 m wide) are one area of nearly all the
    floor; any other area is a rock's top, under 10 m²."""
    label, nav = areas(kinds["battle_royale"](0))
    sizes = np.bincount(label, weights=nav.areas)
    assert sizes.max() > 50000.0 and np.sort(sizes)[:-1].max(initial=0.0) < 10.0


def test_the_arena_shooters_three_storeys_are_one_area_up_its_ramps(kinds):
    """Ramps through holes in the slabs join the ground (0), the middle storey (4.5 m) and the top (9 m): one area with
    over 5,000 m² on each storey."""
    label, nav = areas(kinds["arena_shooter"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for storey in (0.0, 4.5, 9.0):
        assert nav.areas[np.abs(y - storey) < 0.2].sum() > 5000.0, storey


def test_the_mansions_grounds_and_two_storeys_are_one_area_and_its_crawlspace_holds_no_floor(kinds):
    """One area: the grounds, the ground floor (1.08 m) and the upper storey (5.08 m, up the grand and servants'
    stairs); the crawlspace under the house (0.78 m high) and the vents (0.9 m) hold no floor, so no polygon lies
    under the ground floor inside the house's plan."""
    label, nav = areas(kinds["stealth_mansion"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y - 1.08) < 0.15].sum() > 600.0 and nav.areas[np.abs(y - 5.08) < 0.15].sum() > 600.0
    house = np.abs(y - 5.08) < 0.15
    x, z = nav.centres[:, 0], nav.centres[:, 2]
    inside = (x > x[house].min()) & (x < x[house].max()) & (z > z[house].min()) & (z < z[house].max())
    assert not (inside & (y < 0.5)).any()


def test_the_defusal_maps_routes_sites_and_side_rooms_are_one_area(kinds):
    """One area with floor on bombsite A's plateau (0.9 m up six risers of 0.15 m) and on the ground: no side room
    opens onto a doorway's frame."""
    label, nav = areas(kinds["defusal"](1))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y - 0.9) < 0.1].sum() > 300.0


def test_the_payload_road_winds_over_300_m_as_one_area(kinds):
    """The road, its side alleys, flanking buildings and shops are one area from the spawn yard to the base over 300 m
    apart, on rolling ground whose tiles differ by at most a riser of 0.15 m."""
    label, nav = areas(kinds["payload"](0))
    assert label.max() == 0 and np.ptp(nav.centres[:, 0]) > 300.0


def test_the_metroidvanias_cells_are_one_area_on_every_storey(kinds):
    """Doors, flights and ramps join every cell: one area with floor on each storey 5 m apart."""
    label, nav = areas(kinds["metroidvania"](1))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for storey in range(5):
        assert nav.areas[np.abs(y - 5.0 * storey) < 0.2].sum() > 500.0, storey


def test_the_tower_defence_lane_is_one_area_with_its_pads(kinds):
    """One lane switching back between wall strips: one area, and the build pads (0.3 m up, one step) in it."""
    label, nav = areas(kinds["tower_defence"](0))
    assert label.max() == 0
    assert (np.abs(nav.centres[:, 1] - 0.2 - 0.3) < 0.05).sum() > 20


def test_the_hub_worlds_plaza_and_zones_are_one_area(kinds):
    """The plaza, four wings through their portals (lintels 2.6 m up) and four dead-end zones: one area."""
    label, _ = areas(kinds["hub_world"](1))
    assert label.max() == 0


def test_the_taverns_taproom_cellar_and_two_upper_storeys_are_one_area(kinds):
    """One area: the taproom (0.15 m), the cellar (3 m under it, down the kitchen's flight) and both galleries with
    their bedrooms (3.75 and 7.35 m, up the two flights); no table, bench or counter top holds an area of its own."""
    label, nav = areas(kinds["tavern"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for floor, least in ((-2.85, 50.0), (0.15, 1000.0), (3.75, 300.0), (7.35, 300.0)):
        assert nav.areas[np.abs(y - floor) < 0.15].sum() > least, floor


def test_the_military_bases_field_compound_and_buildings_are_one_area(kinds):
    """The field (0 m) and the compound's yard (0.15 m, inside the fence) are one area through its gates, every building
    and loot room entered through one-tile doors."""
    label, nav = areas(kinds["military_base"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y - 0.15) < 0.05].sum() > 3000.0 and nav.areas[np.abs(y) < 0.05].sum() > 10000.0


def test_the_king_of_the_hills_four_terraces_are_one_area_up_their_ramps(kinds):
    """Ramps of three 0.3 m risers climb each 1.2 m step: one area with floor on the field and every terrace, the
    capture point 4.8 m up."""
    label, nav = areas(kinds["king_of_hill"](1))
    assert label.max() == 0
    held = [nav.areas[np.abs(nav.centres[:, 1] - 0.2 - 1.2 * terrace) < 0.1].sum() for terrace in range(5)]
    assert min(held) > 100.0, held


def test_the_favelas_alleys_and_roofs_are_one_area_up_its_stair_lanes(kinds):
    """Each band's roofs are floor at the alley above's height, and the stair lanes join the alleys: one area from the
    road (0 m) to the top alley (18 m or more)."""
    label, nav = areas(kinds["favela"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y) < 0.1].sum() > 300.0 and y.max() > 17.5


def test_the_hives_cells_are_one_area_through_doorways_at_60_degrees(kinds):
    """Doorways 2.2 m wide in walls at 60 degrees to the axes pass the presets' agent: every cell is one area, and no
    pod, pillar nor egg holds floor of its own."""
    label, nav = areas(kinds["hive"](2))
    assert label.max() == 0 and (nav.centres[:, 1] < 0.5).all()


def test_the_western_towns_street_yards_and_balconies_are_one_area(kinds):
    """The street, the boardwalks (0.3 m), the yards and corrals and the upper storeys with their balconies (3.8 m, up
    flights 2 m wide inside and up the alleys) are one area."""
    label, nav = areas(kinds["western_town"](1))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y - 3.8) < 0.1].sum() > 300.0 and nav.areas[np.abs(y - 0.3) < 0.05].sum() > 300.0


def test_the_killhouses_rooms_aisle_and_catwalk_are_one_area(kinds):
    """Doors 1.8 m wide in plywood walls 0.2 m thick join every room to the aisle, and the two flights join the
    catwalk over the walls (4.2 m): one area, with floor on the catwalk and none on a wall's top (2.4 m)."""
    label, nav = areas(kinds["killhouse"](0))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y - 4.2) < 0.15].sum() > 150.0 and not (np.abs(y - 2.4) < 0.3).any()


def test_the_supermarkets_shop_floor_storeroom_and_car_park_are_one_area(kinds):
    """The shop floor and storeroom (0.15 m), through the checkout lanes and the entry gap, and the car park and
    service yard (0 m) are one area."""
    label, nav = areas(kinds["supermarket"](1))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y - 0.15) < 0.05].sum() > 2000.0 and nav.areas[np.abs(y) < 0.05].sum() > 2000.0


def test_the_rts_maps_mains_naturals_and_low_ground_are_one_area_down_their_ramps(kinds):
    """Each main (2.4 m) is left only down one ramp to its natural (1.2 m), each natural down one more to the low
    ground: one area, with floor on all three heights."""
    label, nav = areas(kinds["rts_map"](2))
    assert label.max() == 0
    held = [nav.areas[np.abs(nav.centres[:, 1] - 0.2 - height) < 0.1].sum() for height in (0.0, 1.2, 2.4)]
    assert min(held) > 500.0, held


def test_the_ziggurats_terraces_and_temples_are_one_area_up_their_stairs(kinds):
    """One flight a tier (risers 0.175 m) climbs each pyramid's face: one area, with floor on each of the main
    pyramid's four terraces (2.1-8.4 m)."""
    label, nav = areas(kinds["ziggurat"](0))
    assert label.max() == 0
    held = [nav.areas[np.abs(nav.centres[:, 1] - 0.2 - 2.1 * tier) < 0.1].sum() for tier in range(1, 5)]
    assert min(held) > 50.0, held


def test_the_reactors_levels_are_one_area_through_its_stair_towers(generators):
    """The galleries, bridges and core rings of each level meet the others only in the two stair towers: one area,
    with floor on every level 6 m apart (a hall of three levels, the same rules)."""
    label, nav = areas(generators["reactor"](1, levels=(3, 4)))
    assert label.max() == 0
    held = [nav.areas[np.abs(nav.centres[:, 1] - 0.2 - 6.0 * level) < 0.3].sum() for level in range(3)]
    assert min(held) > 200.0, held


def test_the_gorge_bridges_deck_catwalk_and_banks_are_one_area(kinds):
    """The catwalk under the deck (16 m) meets the deck and the banks (20 m) only up the flights at its piers and
    ends: one area, with floor on both."""
    label, nav = areas(kinds["gorge_bridge"](2))
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y - 16.0) < 0.1].sum() > 300.0 and nav.areas[np.abs(y - 20.0) < 0.1].sum() > 5000.0


def test_recursive_division_cuts_a_region_six_cells_long_once_in_its_middle():
    """By hand: a region 6 x 3 cells is cut once, across its longer side at cell 3 (the only line 3 or more cells from
    both ends), by a wall with one or two doors in distinct cells of its span; a region 5 x 5 is not cut."""
    divide = benchmark("level_kinds")._divide
    walls: list[list] = []
    divide(np.random.default_rng(0), (0, 6, 0, 3), walls, 0.5)
    assert len(walls) == 1 and walls[0][:4] == [0, 3, 0, 3]
    assert 1 <= len(walls[0][4]) == len(set(walls[0][4])) <= 2 and all(0 <= c < 3 for c in walls[0][4])
    walls = []
    divide(np.random.default_rng(0), (0, 5, 0, 5), walls, 0.5)
    assert walls == []


@pytest.fixture(scope="module")
def round_26() -> dict[str, Callable[[int], trimesh.Trimesh]]:
    """``benchmarks/level_kinds26.py``'s KINDS (the twenty-sixth round): each call builds its level anew."""
    return benchmark("level_kinds26").KINDS


def test_the_paintball_fields_low_cover_is_walked_over_and_no_bunker_holds_floor(round_26):
    """Hundreds of pieces of low cover (0.15-0.38 m, under the 0.4 m climb) leave the field one area, and no tall
    bunker's top (pyramids, cones, ridges over 45 degrees) holds floor: nothing walkable over 0.5 m."""
    label, nav = areas(round_26["paintball"](0))
    assert label.max() == 0
    assert (nav.centres[:, 1] - 0.2 < 0.5).all() and nav.areas.sum() > 12000.0


def test_the_holed_mills_three_storeys_are_one_area_through_its_stair_towers(round_26):
    """The upper floors, holed by 24-34 collapses each, are reached only up the two stair towers: one area, with floor
    on every storey (0, 4, 8 m)."""
    label, nav = areas(round_26["holed_mill"](1))
    assert label.max() == 0
    held = [nav.areas[np.abs(nav.centres[:, 1] - 0.2 - 4.0 * k) < 0.1].sum() for k in range(3)]
    assert min(held) > 1000.0, held


def test_the_vineyards_risers_are_walked_with_the_presets_ledge_filter(round_26):
    """Risers at 33-42 degrees: with the presets' ``ledge_filter: drops`` the valley is one area from its floor to the
    top terraces (over 15 m up); Recast's own ledge rule, which cuts slopes of about 37 degrees and over on this grid,
    parts the terraces."""
    mesh = round_26["vineyard"](2)
    label, nav = areas(mesh, RecastParams(ledge_filter="drops"))
    assert label.max() == 0 and np.ptp(nav.centres[:, 1]) > 15.0
    assert areas(mesh)[0].max() > 0


def test_the_catwalk_halls_three_heights_are_one_area_over_no_floor(round_26):
    """Railed catwalks 1.8 m wide hold floor at each height (6, 10, 14 m), joined by the stair towers: one area, and
    no floor under 5 m (the hall has none)."""
    label, nav = areas(round_26["catwalk_hall"](0))
    assert label.max() == 0 and (nav.centres[:, 1] > 5.0).all()
    held = [nav.areas[np.abs(nav.centres[:, 1] - 0.2 - height) < 0.1].sum() for height in (6.0, 10.0, 14.0)]
    assert min(held) > 150.0, held


def test_the_double_door_rooms_are_one_area_through_their_open_doors(round_26):
    """Every room is joined along a spanning tree by a double door whose leaves stand open at 90 degrees, and beds
    stand only along walls with no doorway: one area of rooms and yard."""
    label, nav = areas(round_26["double_doors"](1))
    assert label.max() == 0 and nav.areas.sum() > 1500.0


def test_the_split_decks_are_one_area_up_the_ramps_spiralling_round_the_well(round_26):
    """The two halves' decks, 1.5 m apart, meet only by ramps across the light well: one area, with floor on every
    deck (0-10.5 m on seed 2)."""
    label, nav = areas(round_26["split_decks"](2))
    assert label.max() == 0
    held = [nav.areas[np.abs(nav.centres[:, 1] - 0.2 - 1.5 * k) < 0.1].sum() for k in range(8)]
    assert min(held) > 400.0, held


DROPS = RecastParams(ledge_filter="drops")  # the presets' ledge rule (configs/map_analysis.yaml), as the benchmark builds
PRESET_GRID = RecastParams(ledge_filter="drops", climb="agent")  # map_analysis's graph params since "The climb at every alignment"


@pytest.fixture(scope="module")
def round_27() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds27.py``'s KINDS (the twenty-seventh round): each call builds its level anew."""
    return benchmark("level_kinds27").KINDS


def test_the_container_maze_is_one_area_through_its_open_containers_and_over_its_roofs(round_27):
    """Containers walked through (never shut at both ends), the roofs joined by planks and reached by two flights:
    one area, with floor inside the containers (under 2.5 m, in their plan) and on the roofs (2.59 m up)."""
    label, nav = areas(round_27["container_maze"](0), DROPS)
    assert label.max() == 0
    roofs = nav.areas[np.abs(nav.centres[:, 1] - 0.2 - 2.59) < 0.15].sum()
    assert roofs > 300.0, roofs


def test_the_listing_ferrys_three_decks_are_one_area_rolled_and_upright(round_27):
    """Rolled 8-14 degrees and pitched 1-3, every floor sloped and every wall leaning, the car deck, cabin deck and open
    deck stay one area through the stair towers (seed 1; as the same ship built upright), over 8 m of height."""
    for roll in ((8.0, 14.0), (0.0, 0.0)):
        label, nav = areas(round_27["listing_ferry"](1, roll=roll), DROPS)
        assert label.max() == 0 and np.ptp(nav.centres[:, 1]) > 8.0, roll


def test_the_pipe_networks_pipes_chambers_and_street_are_one_area(round_27):
    """Round pipes whose curved floors hold the walk, chambers, the outfall yard and the street over them (reached by
    the ramp): one area, with over 1,500 m² under the street (pipes and chambers, under 1 m) and over 5,000 on it."""
    label, nav = areas(round_27["pipe_network"](0), DROPS)
    assert label.max() == 0
    low, street = nav.areas[nav.centres[:, 1] < 1.0].sum(), nav.areas[nav.centres[:, 1] > 4.5].sum()
    assert low > 1500.0 and street > 5000.0, (low, street)


def test_the_boardwalks_planks_with_gaps_are_one_deck(round_27):
    """Thousands of planks 1-3 cm apart, walks at every angle over no ground: one area (a half-size marsh, seed 0), all
    its floor on the decks (0.5-1.2 m up) but the forecourt's (0.3 m, at the south shore, z under 15 m) and the foot
    of the walk rising from it."""
    label, nav = areas(round_27["boardwalk"](0, scale=0.5), DROPS)
    assert label.max() == 0
    low = nav.centres[:, 1] - 0.2 < 0.45
    assert (nav.centres[low, 2] < 20.0).all() and nav.areas[~low].sum() > 200.0


def test_the_car_lots_rows_of_cars_leave_one_area(round_27):
    """Cars with gaps of 0.3-1.3 m between them part no aisle from the footway: one area of over 5,000 m²."""
    label, nav = areas(round_27["car_lot"](0), DROPS)
    assert label.max() == 0 and nav.areas.sum() > 5000.0


def test_the_festival_camps_marquees_are_entered_through_their_angled_doors(round_27):
    """40-50 marquees at random angles, each a room whose ground is floor: one area, so every marquee is entered
    through its door 2.2 m wide (a marquee whose door shut would be an area of its own)."""
    label, nav = areas(round_27["festival_camp"](0), DROPS)
    assert label.max() == 0 and nav.areas.sum() > 9000.0


@pytest.fixture(scope="module")
def round_28() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds28.py``'s KINDS (the twenty-eighth round): each call builds its level anew."""
    return benchmark("level_kinds28").KINDS


def test_the_double_helix_reaches_every_deck_up_both_ramps(round_28):
    """Two helical ramps interleaved in one well, a storey a half turn: one area with floor on the ground and on each of
    the 5 decks (seed 0), and ramp floor inside the well at heights between the decks on both its east and west
    halves."""
    label, nav = areas(round_28["double_helix"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for deck in range(6):
        assert nav.areas[np.abs(y - 3.0 * deck) < 0.1].sum() > 500.0, deck
    well = np.abs(nav.centres[:, 0] - np.median(nav.centres[:, 0])) < 20.0
    between = well & (np.abs(y / 3.0 - np.round(y / 3.0)) > 0.2)
    assert between.sum() > 20


def test_the_low_stations_modules_are_one_area_through_hatches_under_low_ceilings(round_28):
    """Modules joined by corridors whose ceilings stand 2.3-2.4 m up, through hatches with sills: one area, every
    polygon on the floor (none on a ridged roof), over 2,000 m²."""
    label, nav = areas(round_28["low_station"](0), DROPS)
    assert label.max() == 0 and nav.centres[:, 1].max() < 0.5 and nav.areas.sum() > 2000.0


def test_the_fallen_giants_cross_the_gorge_and_climb_the_plateau(round_28):
    """The gorge crossed only by fallen trunks and the plateau reached only up leaning ones: one area, with floor on
    the plateau (over 3.5 m up) of over 500 m²."""
    label, nav = areas(round_28["fallen_giants"](0), DROPS)
    assert label.max() == 0 and nav.areas[nav.centres[:, 1] > 3.5].sum() > 500.0


def test_the_canal_citys_blocks_are_one_area_over_its_step_bridges(round_28):
    """Blocks between canals, quays along both banks, joined only by humped bridges (decks 2 m up): one area, and floor
    on the bridges' decks."""
    label, nav = areas(round_28["canal_city"](0), DROPS)
    assert label.max() == 0 and (nav.centres[:, 1] > 1.9).any()


def test_the_grand_stairs_two_mirrored_flights_both_reach_the_gallery(round_28):
    """An imperial staircase: one area with over 300 m² upstairs (4.5 m), and floor on the side flights' steps (between
    the half landing's 2.25 m and the gallery's 4.5 m) west and east of the hall's middle alike."""
    label, nav = areas(round_28["grand_stair"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[np.abs(y - 4.5) < 0.1].sum() > 300.0
    flights = (y > 2.5) & (y < 4.3) & (nav.centres[:, 2] > 5.0)
    middle = np.median(nav.centres[np.abs(y - 4.5) < 0.1, 0])
    west = nav.areas[flights & (nav.centres[:, 0] < middle)].sum()
    east = nav.areas[flights & (nav.centres[:, 0] > middle)].sum()
    assert west > 3.0 and east > 3.0 and abs(west - east) < 0.25 * max(west, east), (west, east)


def test_the_data_halls_cold_aisles_hold_floor_between_the_rack_rows(round_28):
    """Rows of racks 1.2 m deep with cold aisles 1.8-2.4 m wide between them: one area, and over 2,000 m² on the raised
    floor (0.6 m up) of both halls."""
    label, nav = areas(round_28["data_hall"](0), DROPS)
    assert label.max() == 0 and nav.areas[nav.centres[:, 1] > 0.7].sum() > 2000.0


@pytest.fixture(scope="module")
def round_29() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds29.py``'s KINDS (the twenty-ninth round): each call builds its level anew."""
    return benchmark("level_kinds29").KINDS


def test_the_lava_tubes_chambers_at_several_heights_are_one_area(round_29):
    """Chambers joined by tubes whose floors climb at most 0.2 m a 2 m tile: one area, its floor spanning over 5 m of
    height (the chambers at several heights all reached up and down the tubes)."""
    label, nav = areas(round_29["lava_tubes"](0), DROPS)
    assert label.max() == 0 and np.ptp(nav.centres[:, 1]) > 5.0


def test_the_cubicle_farms_cubicles_open_onto_the_aisles(round_29):
    """Cubicles behind partitions 1.5 m high, each entered through an opening 1.6-2.0 m wide: one area (a cubicle whose
    opening closed for the agent would be an area apart), over 1,800 m² on the floor and none on a desk or partition."""
    label, nav = areas(round_29["cubicle_farm"](0), DROPS)
    assert label.max() == 0 and nav.areas.sum() > 1800.0 and nav.centres[:, 1].max() < 0.5


def test_the_football_terraces_risers_under_the_climb_are_walked_on_all_four_stands(round_29):
    """Terraces whose risers are 0.30-0.38 m (under the 0.4 m climb): one area, and over 150 m² of floor between 1 and 4
    m up on each of the four stands (a stand whose risers the agent could not climb would hold none: its treads are
    under the agent's width)."""
    label, nav = areas(round_29["football_terrace"](0), DROPS)
    assert label.max() == 0
    x, y, z = nav.centres.T
    raised = (y > 1.0) & (y < 4.0)
    x0, x1, z0, z1 = x[raised].min(), x[raised].max(), z[raised].min(), z[raised].max()
    along_x, along_z = (x > x0 + 20.0) & (x < x1 - 20.0), (z > z0 + 20.0) & (z < z1 - 20.0)
    for side in (along_x & (z < z0 + 12.0), along_x & (z > z1 - 12.0), along_z & (x < x0 + 12.0),
                 along_z & (x > x1 - 12.0)):
        assert nav.areas[raised & side].sum() > 150.0


def test_the_hypostyle_halls_floor_runs_between_its_columns(round_29):
    """A hall of a dense grid of columns (gaps 1.2-2.4 m): one area, and floor among the columns on both sides of the
    processional way, over 300 m² a side (the way's 6 m left out)."""
    label, nav = areas(round_29["hypostyle_hall"](0), DROPS)
    assert label.max() == 0
    hall = (nav.centres[:, 2] > 1.0) & (nav.centres[:, 1] < 0.5)
    mid = np.median(nav.centres[hall & (nav.centres[:, 2] < 20.0), 0])
    assert nav.areas[hall & (nav.centres[:, 0] < mid - 6.0)].sum() > 300.0
    assert nav.areas[hall & (nav.centres[:, 0] > mid + 6.0)].sum() > 300.0


def test_the_opera_houses_boxes_on_every_tier_are_reached(round_29):
    """Tiers of boxes 3.5 m apart round the void, each off its tier's corridor, joined by two stair towers: one area,
    and over 120 m² of floor on each tier (seed 0: three tiers and the gallery over them, 3.5-14 m)."""
    label, nav = areas(round_29["opera_house"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for tier in range(1, 4):
        assert nav.areas[np.abs(y - 3.5 * tier) < 0.15].sum() > 120.0, tier


def test_the_dune_seas_backs_and_crests_are_walked(round_29):
    """Crescent dunes whose backs rise at 10-16 degrees to crests 3-9 m up: one area (each dune walked round its horns
    and over its back), with over 1,000 m² of floor over 3 m up."""
    label, nav = areas(round_29["dune_sea"](0), DROPS)
    assert label.max() == 0 and nav.areas[nav.centres[:, 1] > 3.0].sum() > 1000.0


@pytest.fixture(scope="module")
def round_30() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds30.py``'s KINDS (the thirtieth round): each call builds its level anew."""
    return benchmark("level_kinds30").KINDS


def test_the_aircraft_carriers_hangar_and_flight_deck_are_one_area_through_the_trunks(round_30):
    """A flight deck 8 m over a hangar, joined only by two stair trunks (the lifts are floor at one level each): one
    area, with over 3,000 m² on the hangar deck (under 0.5 m) and over 6,000 m² on the flight deck (7.5-8.5 m)."""
    label, nav = areas(round_30["aircraft_carrier"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[y < 0.5].sum() > 3000.0 and nav.areas[(y > 7.5) & (y < 8.5)].sum() > 6000.0


def test_the_submarines_hatches_join_its_compartments_on_all_three_decks(round_30):
    """Compartments in a line whose bulkheads are crossed through hatches (sills 0.30-0.36 m, 2.15-2.30 m clear over
    them), three decks joined by steep flights: one area, with floor along more than 100 m of each deck."""
    label, nav = areas(round_30["submarine"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    for floor in (0.0, 2.9, 5.8):
        on = np.abs(y - floor) < 0.1
        assert np.ptp(nav.centres[on, 0]) > 100.0, floor


def test_the_velodromes_bends_banked_under_the_limit_are_walked(round_30):
    """A banked track whose bends stand at 40-44 degrees, reached through a tunnel under it: one area, floor in the
    tunnel (over 2 m down) and high on the banking of both bends (polygons whose middles stand over 4 m up, west and
    east of the middle; the straights' banking reaches under 2 m)."""
    label, nav = areas(round_30["velodrome"](0), DROPS)
    assert label.max() == 0
    x, y = nav.centres[:, 0], nav.centres[:, 1] - 0.2
    assert (y < -2.0).any() and (y[x < 0.0] > 4.0).any() and (y[x > 0.0] > 4.0).any()


def test_the_drained_pools_floors_are_reached_down_their_steps(round_30):
    """Pools sunk into the deck, each entered only by its steps or ramp: one area, floor on the diving pool's bottom
    (4.5 m down) and on the main pool's break between 1.6 and 3.4 m down."""
    label, nav = areas(round_30["drained_pools"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[y < -4.0].sum() > 30.0 and ((y > -3.4) & (y < -1.6)).any()


def test_the_mogul_pistes_slopes_under_the_limit_join_its_terraces(round_30):
    """Two pitches at 36-41 degrees between three terraces: one area, holding floor on the top terrace (over 60 m up)
    and on the base terrace."""
    label, nav = areas(round_30["mogul_piste"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[y > 60.0].sum() > 500.0 and nav.areas[y < 0.1].sum() > 1000.0


def test_the_marinas_five_pontoons_are_reached_down_their_gangways(round_30):
    """Five pontoons 0.4 m over the water, each reached down a gangway from a quay 2.2 m up: one area, with floor on
    each pontoon (five runs of floor 0.4 m up more than 20 m out from the quay, apart along x)."""
    label, nav = areas(round_30["marina"](0), DROPS)
    assert label.max() == 0
    x, y, z = nav.centres.T
    out = np.sort(x[(np.abs(y - 0.2 - 0.4) < 0.1) & (z < -20.0)])
    assert 1 + (np.diff(out) > 15.0).sum() == 5, out


@pytest.fixture(scope="module")
def round_31() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds31.py``'s KINDS (the thirty-first round): each call builds its level anew."""
    return benchmark("level_kinds31").KINDS


def flat_steps_over_climb(nav) -> int:
    """How many pairs of neighbouring flat polygons (their corners within 5 cm of one height) stand more than 0.3 m
    apart in height: a step between two floors that the navmesh walks straight up."""
    heights, flat = [], []
    for p in range(nav.polygon_count):
        corners = nav.polygons[p]
        y = nav.vertices[corners[corners >= 0], 1]
        heights.append(y.mean())
        flat.append(np.ptp(y) < 0.05)
    return sum(1 for p in range(nav.polygon_count) for q in nav.neighbours[p]
               if q > p and flat[p] and flat[q] and abs(heights[p] - heights[q]) > 0.3)


def test_the_crypts_vaults_leave_a_lattice_of_lanes_one_area_with_the_nave(round_31):
    """Groin vaults whose crowns stand 2.15-2.35 m over the floor (springing 1.3 m): one area with the nave above (3.3
    m up, down two flights), and the crypt's floor only on lanes under the vaults' middle lines, 25-65 % of its plan
    (a 4 x 3 crypt, :func:`crypt`'s ``bays``)."""
    label, nav = areas(round_31["crypt"](0, bays=(4, 5, 3, 4)), DROPS)
    assert label.max() == 0
    y, x = nav.centres[:, 1] - 0.2, nav.centres[:, 0]
    assert nav.areas[y > 3.0].sum() > 200.0
    crypt = (y < 0.5) & (x > 0.0)
    plan = np.ptp(nav.vertices[nav.vertices[:, 1] < 0.5, 2]) * (x[crypt].max() - x[crypt].min() + 2.0)
    assert 0.25 < nav.areas[crypt].sum() / plan < 0.65, nav.areas[crypt].sum() / plan


def test_the_solar_farm_is_walked_under_the_tables_high_sides_only(round_31):
    """Tables tilted at 50 degrees, low edges 0.6-1.2 m over the ground: one area, and its floor under 80 % of the
    fenced ground (no floor under a low side, nor on a panel)."""
    mesh = round_31["solar_farm"](0)
    label, nav = areas(mesh, DROPS)
    assert label.max() == 0
    lo, hi = mesh.bounds
    assert 0.5 < nav.areas.sum() / ((hi[0] - lo[0]) * (hi[2] - lo[2])) < 0.8
    assert nav.centres[:, 1].max() < 0.5


def test_the_mirror_maze_is_one_area_to_its_far_row(round_31):
    """A maze of mirrors on a triangular lattice (corridors at 0, 60 and 120 degrees, triangles 3.0-3.3 m a side): one
    area reaching the far row of triangles, more than 800 m² of floor."""
    mesh = round_31["mirror_maze"](0)
    label, nav = areas(mesh, DROPS)
    assert label.max() == 0 and nav.areas.sum() > 800.0
    assert nav.centres[:, 2].max() > mesh.bounds[1][2] - 8.0


def test_the_temples_tall_steps_are_not_climbed_but_their_flights_are(round_31):
    """Platforms of three steps of 0.42-0.50 m (over the 0.4 m climb), each climbed by one flight: one area, more than
    500 m² of floor on the platforms (over 1.2 m up) and no two flat floors joined across a step over 0.3 m."""
    label, nav = areas(round_31["temple_steps"](0), DROPS)
    assert label.max() == 0
    assert nav.areas[nav.centres[:, 1] - 0.2 > 1.2].sum() > 500.0
    assert flat_steps_over_climb(nav) == 0


def test_the_ice_floes_wide_cracks_part_the_lake(round_31):
    """Floes between cracks 0.05-0.6 m wide: the lake falls into more than five areas, and the west and east shores
    (0.2 m over the ice) are apart on seed 0 (no crack there under a cell's width joins them)."""
    mesh = round_31["ice_floes"](0)
    label, nav = areas(mesh, DROPS)
    assert label.max() + 1 > 5
    shore = np.abs(nav.centres[:, 1] - 0.2 - 0.2) < 0.05
    west, east = shore & (nav.centres[:, 0] < 0.0), shore & (nav.centres[:, 0] > mesh.bounds[1][0] - 30.0)
    assert west.any() and east.any() and not set(label[west]) & set(label[east])


def test_the_bell_towers_wide_turret_stairs_reach_their_bell_chambers(round_31):
    """Seed 0's towers, whose turret stairs are 1.6 m or more clear: one area with floor on the stairs between the
    storeys and more than 50 m² in the bell chambers 9.6 m or more up."""
    label, nav = areas(round_31["bell_towers"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[y > 9.5].sum() > 50.0
    assert ((y > 0.5) & (y < 2.7)).any()


@pytest.fixture(scope="module")
def round_32() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds32.py``'s KINDS (the thirty-second round): each call builds its level anew."""
    return benchmark("level_kinds32").KINDS


def plan_points_on_floor(nav, points: np.ndarray) -> np.ndarray:
    """Which plan points (k, 2) of x, z lie inside a navmesh polygon's plan (k,): each polygon is convex, so a point is
    inside when it lies on one side of all its edges. O(P x k)."""
    inside = np.zeros(len(points), dtype=bool)
    for p in range(nav.polygon_count):
        corners = nav.vertices[nav.polygons[p][nav.polygons[p] >= 0]][:, [0, 2]]
        edges = np.roll(corners, -1, axis=0) - corners
        cross = edges[:, 0, None] * (points[None, :, 1] - corners[:, 1, None]) \
            - edges[:, 1, None] * (points[None, :, 0] - corners[:, 0, None])
        inside |= (cross >= 0).all(axis=0) | (cross <= 0).all(axis=0)
    return inside


def test_the_sewers_walkways_are_one_area_and_some_beds_are_apart_under_the_planks(round_32):
    """Walkways beside channels whose beds lie 1.0-2.0 m lower, crossed by planks that leave the beds 0.9-1.9 m of
    head room: the walkways joined from one end gallery to the other and down flights to beds (floor over 0.9 m down in
    the largest area), and more than five areas (stretches of bed without a flight, apart under their planks)."""
    mesh = round_32["sewer_planks"](0)
    label, nav = areas(mesh, DROPS)
    largest = label == np.argmax(np.bincount(label, weights=nav.areas))
    x, y = nav.centres[:, 0], nav.centres[:, 1] - 0.2
    assert (largest & (x < 0.0)).any() and (largest & (x > mesh.bounds[1][0] - 4.0)).any()
    assert (largest & (y < -0.9)).any()
    assert label.max() + 1 > 5


def test_the_caves_low_stalactites_leave_no_floor_under_their_tips(round_32):
    """Stalactites hanging to tips about the agent's height: one area, and no floor under a tip (or a stalagmite's)
    that stands 1.4-1.95 m over the floor, the only vertices of the level at those heights."""
    mesh = round_32["stalactite_cave"](0)
    label, nav = areas(mesh, DROPS)
    assert label.max() == 0
    tips = mesh.vertices[(mesh.vertices[:, 1] > 1.4) & (mesh.vertices[:, 1] < 1.95)][:, [0, 2]]
    assert len(tips) > 10 and not plan_points_on_floor(nav, tips).any()


def test_the_ring_is_one_area_round_an_empty_middle(round_32):
    """Four straight tunnels 150-190 m long joined by bends: one area reaching all four straights, no floor inside
    the ring (more than 20 m from the tunnels' inner walls)."""
    mesh = round_32["ring_tunnels"](0)
    label, nav = areas(mesh, DROPS)
    assert label.max() == 0
    x, z = nav.centres[:, 0], nav.centres[:, 2]
    assert x.min() < -75.0 and x.max() > 75.0 and z.min() < -70.0 and z.max() > 70.0
    lo, hi = mesh.bounds
    inner_x, inner_z = (hi[0] - lo[0]) / 2 - 16.0 - 25.0, (hi[2] - lo[2]) / 2 - 16.0 - 25.0
    assert not ((np.abs(x) < inner_x) & (np.abs(z) < inner_z)).any()


def test_the_hangars_mezzanine_is_reached_by_its_flights_and_not_its_lift_shaft(round_32):
    """A mezzanine 4.5 m up reached by two flights, a lift shaft with no floor but its pit's, 1.4 m down: the floor and
    the mezzanine one area (more than 300 m² over 4 m up), the pit's floor, if any, outside it."""
    label, nav = areas(round_32["hangar"](0), DROPS)
    largest = label == np.argmax(np.bincount(label, weights=nav.areas))
    y = nav.centres[:, 1] - 0.2
    assert nav.areas[largest & (y > 4.0)].sum() > 300.0
    assert not (largest & (y < -0.5)).any()


def test_the_domus_gardens_are_entered_down_their_steps_only(round_32):
    """Peristyle gardens 0.45-0.6 m under their colonnades, entered down two half steps: one area with floor in the
    gardens (more than 300 m² over 0.4 m down), and no two flat floors joined across a step over 0.3 m."""
    label, nav = areas(round_32["domus"](0), DROPS)
    assert label.max() == 0
    assert nav.areas[nav.centres[:, 1] - 0.2 < -0.4].sum() > 300.0
    assert flat_steps_over_climb(nav) == 0


def test_every_bamboo_culm_narrower_than_a_cell_is_a_hole_in_the_floor(round_32):
    """Culms 0.06-0.14 m across (Recast's cell is 0.25 m): one area, and no culm's top corner (the only vertices over
    5.9 m) over floor."""
    mesh = round_32["bamboo_grove"](0)
    label, nav = areas(mesh, DROPS)
    assert label.max() == 0
    culms = mesh.vertices[mesh.vertices[:, 1] > 5.9][:, [0, 2]]
    assert len(culms) > 1000 and not plan_points_on_floor(nav, culms).any()


@pytest.fixture(scope="module")
def round_33() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds33.py``'s KINDS (the thirty-third round): each call builds its level anew."""
    return benchmark("level_kinds33").KINDS


def head_room(mesh, nav) -> np.ndarray:
    """The height (P,) from each navmesh polygon's centre up to the first face of ``mesh`` over it (inf when none):
    a ray from 5 cm over the centre straight up, trimesh's ray test."""
    origins = nav.centres + np.array([0.0, 0.05, 0.0])
    hits, rays, _ = mesh.ray.intersects_location(origins, np.tile([0.0, 1.0, 0.0], (len(origins), 1)))
    room = np.full(len(origins), np.inf)
    np.minimum.at(room, rays, hits[:, 1] - origins[rays, 1])
    return room


def test_the_attic_rows_lofts_hold_floor_only_where_the_roof_leaves_head_room(round_33):
    """Lofts under roofs pitched at 38-45 degrees, reached by a flight each: the street, houses and lofts one area
    with more than 60 m² of loft floor (2.5 m up or more) on it, and no floor anywhere with under 1.7 m over the
    polygon's centre (the centre stands up to 0.2 m over the floor): none under the eaves."""
    mesh = round_33["attic_row"](0)
    label, nav = areas(mesh, DROPS)
    largest = label == np.argmax(np.bincount(label, weights=nav.areas))
    assert nav.areas[largest & (nav.centres[:, 1] - 0.2 > 2.5)].sum() > 60.0
    assert head_room(mesh, nav).min() > 1.7


def test_the_labyrinth_is_one_area_with_floor_in_every_ring(round_33):
    """Eight to ten ring corridors 1.9-2.5 m wide joined by one opening each: one area, with floor in every band of
    2.4 m of radius from the court to the outer hedge (a ring that held none would leave a band empty)."""
    mesh = round_33["labyrinth"](0)
    label, nav = areas(mesh, DROPS)
    assert label.max() == 0
    radius = np.hypot(nav.centres[:, 0], nav.centres[:, 2])
    outer = mesh.vertices[mesh.vertices[:, 1] > 2.3][:, [0, 2]]  # the hedges' tops
    bands = np.arange(5.0, np.hypot(outer[:, 0], outer[:, 1]).max() - 2.4, 2.4)
    assert all(((radius > b) & (radius < b + 2.4)).any() for b in bands)


def test_the_hill_fort_is_one_area_from_its_foot_to_its_top(round_33):
    """Three ramparts whose outer faces fall steeper than the slope limit, entered through staggered gates: one
    area reaching the foot of the hill (under 1 m) and its top (over 8 m)."""
    label, nav = areas(round_33["hill_fort"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert y.min() < 1.0 and y.max() > 8.0


def test_the_roundabouts_garden_reaches_the_streets_under_a_carriageway_railed_apart(round_33):
    """A garden 4 m under a roundabout, left by subways under its carriageway: the garden's floor in the same area as
    the streets 50 m out, and the carriageway (10 m wide at the street's level, railed on both edges) an area apart
    of 1,000-1,500 m²."""
    label, nav = areas(round_33["subway_roundabout"](0), DROPS)
    y, radius = nav.centres[:, 1] - 0.2, np.hypot(nav.centres[:, 0], nav.centres[:, 2])
    garden = set(label[y < -3.5])
    assert garden & set(label[(radius > 50.0) & (np.abs(y) < 0.2)])
    sizes = np.bincount(label, weights=nav.areas)
    assert any(1000.0 < sizes[k] < 1500.0 and not k in garden for k in range(len(sizes)))


def test_the_concourse_is_reached_up_the_ramp_towers(round_33):
    """Zigzag ramps whose runs are parted by rails 0.06 m thick: one area with over 1,000 m² of concourse (5.9 m up
    or more) and floor at every height on the way up (no gap of a metre between the polygons' heights)."""
    label, nav = areas(round_33["ramp_towers"](0), DROPS)
    assert label.max() == 0
    y = np.sort(nav.centres[:, 1] - 0.2)
    assert nav.areas[nav.centres[:, 1] - 0.2 > 5.9].sum() > 1000.0 and np.diff(y).max() < 1.0


def test_the_cenotes_ledge_joins_the_rim_to_the_beach_under_its_overhangs(round_33):
    """A ledge spiralling 18-24 m down under rock overhangs 2.3-2.8 m over it: one area from the rim (y = 0) to the
    beach (17 m down or more), and no floor with under 1.7 m over the polygon's centre."""
    mesh = round_33["cenote"](0)
    label, nav = areas(mesh, DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert y.max() > -0.3 and y.min() < -17.0
    assert head_room(mesh, nav).min() > 1.7


@pytest.fixture(scope="module")
def round_34() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds34.py``'s KINDS (the thirty-fourth round): each call builds its level anew."""
    return benchmark("level_kinds34").KINDS


def test_the_turned_houses_lose_only_rooms_behind_their_doors(round_34):
    """Houses turned 10-40 degrees off the grid, doors 1.5-1.7 m wide: the yard and most rooms one area holding over
    98 % of the floor; every area apart stands on a house's floor slab (0.15 m over the yard: centres over 0.3 m),
    a room behind a door the navmesh closes (docs/analysis_quality.md, "A thirty-fourth round of level kinds")."""
    label, nav = areas(round_34["turned_wings"](0), DROPS)
    sizes = np.bincount(label, weights=nav.areas)
    largest = int(np.argmax(sizes))
    assert sizes[largest] > 0.98 * sizes.sum()
    assert (nav.centres[label != largest, 1] > 0.3).all()


def test_the_gap_roofs_are_joined_only_across_gaps_under_two_cells(round_34):
    """Roofs 0.3-0.6 m apart or sharing a wall (:func:`gap_roofs_plan`): the street in one area with the roofs of the
    flights' runs, no more areas than the plan's (whose runs cross no gap), and no polygon of a roof a neighbour of
    one on the next roof of its row across a gap of 0.5 m or more (two of Recast's 0.25 m cells: a free column of
    cells always falls inside it)."""
    plan = benchmark("level_kinds34").gap_roofs_plan(0)
    label, nav = areas(round_34["gap_roofs"](0), DROPS)
    assert label.max() + 1 <= len(plan["areas"])

    def on_roof(r: int, k: int) -> np.ndarray:
        """(P,) bool: the polygon's centre or a corner lies on roof k of row r (a polygon may span a shared wall)."""
        x0, x1, h = plan["rows"][r][k]
        z0, z1 = plan["spans"][r]
        corners = np.where(nav.polygons[..., None] >= 0, nav.vertices[np.maximum(nav.polygons, 0)], np.nan)
        points = np.concatenate([corners, nav.centres[:, None]], axis=1)  # (P, corners + 1, 3)
        on = ((points[..., 0] >= x0) & (points[..., 0] <= x1) & (points[..., 2] >= z0) & (points[..., 2] <= z1)
              & (np.abs(points[..., 1] - h) < 0.5))
        return on.any(axis=1)

    street = set(label[np.abs(nav.centres[:, 1]) < 0.3])
    assert all(set(label[on_roof(*f)]) & street for f in plan["flights"])
    wide = 0
    for r, roofs in enumerate(plan["rows"]):
        for k in range(1, len(roofs)):
            if roofs[k][0] - roofs[k - 1][1] >= 0.5:
                wide += 1
                one, other = on_roof(r, k - 1), on_roof(r, k)
                beside = nav.neighbours[one].ravel()
                assert not (one & other).any() and not other[beside[beside >= 0]].any()
    assert wide > 0


def test_the_quay_reaches_every_ship_and_foredeck_up_its_gangway(round_34):
    """Four ships moored at 15-30 degrees, boarded by gangways at 15-30 degrees to the quay's normal: one area but
    parts under 4 m², with floor on the quay (y under 0.3), the main decks (1.5-2.6 m) and the foredecks (1.4 m
    higher: over 3.1 m on every seed's decks of 1.7 m or more)."""
    label, nav = areas(round_34["gangway_quay"](0), DROPS)
    sizes = np.bincount(label, weights=nav.areas)
    assert (sizes > 4.0).sum() == 1
    main = label == int(np.argmax(sizes))
    y = nav.centres[main, 1] - 0.2
    assert y.min() < 0.3 and ((y > 1.4) & (y < 2.7)).any() and y.max() > 3.1


def test_the_scree_cave_is_one_area_on_its_slopes(round_34):
    """Chambers on floors tilted 5-20 degrees joined by passages sloping 10-30 degrees, one shortcut cut by a scree
    at 50-55 degrees: one area whose floor spans more than 10 m of height."""
    label, nav = areas(round_34["scree_cave"](0), DROPS)
    assert label.max() == 0
    assert np.ptp(nav.centres[:, 1]) > 10.0


def test_the_track_beds_are_reached_down_the_platforms_ramps(round_34):
    """Track beds of ballast 1.2 m under the platforms, reached only down ramps at the platforms' west ends: one area
    with floor on the beds (about -1.2 m), the platforms (about 0) and the footbridge (about 6 m)."""
    label, nav = areas(round_34["track_beds"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1] - 0.2
    assert (np.abs(y + 1.2) < 0.2).any() and (np.abs(y) < 0.2).any() and (np.abs(y - 6.0) < 0.3).any()


def test_the_expo_halls_booths_and_open_floor_are_one_area(round_34):
    """Booths 3 m wide and 3 m deep (more than 200 wall-top corners 2.5 m up), open to their aisles, beside an open
    floor: one area whose floor covers more than half the hall's plan (a booth lost behind its opening would leave
    an island or less floor)."""
    mesh = round_34["expo_hall"](0)
    label, nav = areas(mesh, DROPS)
    assert label.max() == 0
    assert (np.abs(mesh.vertices[:, 1] - 2.5) < 1e-6).sum() > 200
    assert nav.areas.sum() > 0.5 * np.ptp(mesh.vertices[:, 0]) * np.ptp(mesh.vertices[:, 2])


@pytest.fixture(scope="module")
def round_35() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds35.py``'s KINDS (the thirty-fifth round): each call builds its level anew."""
    return benchmark("level_kinds35").KINDS


def test_the_kit_flights_join_their_storeys_only_where_the_last_step_is_climbed(round_35):
    """Kit flights of 20 risers in storeys 3.45-3.95 m high (:func:`kit_flights_plan`, seed 1): a walk straight up
    each flight's last tread onto the floor above is clear on the navmesh where the step left is at most 0.37 m and
    blocked where it is 0.44-0.46 m, and the block is one area, as the plan's (docs/analysis_quality.md, "A
    thirty-fifth round of level kinds")."""
    module = benchmark("level_kinds35")
    plan = module.kit_flights_plan(1)
    label, nav = areas(round_35["kit_flights"](1), DROPS)
    assert label.max() + 1 == len(plan["areas"]) == 1
    size_x = float(np.random.default_rng(1001).uniform(48.0, 56.0))
    run = 20 * 0.28
    cores = [(6.0, 3.0), (size_x - 6.0 - run, 3.0)]  # the southern two: the lanes' z do not depend on size_z
    seen = set()
    for k in range(3):
        y, lane = plan["floors"][k], 3.2 * (k % 2)
        for c, (x0, z0) in enumerate(cores):
            step, rise = plan["steps"][c][k], plan["cores"][c][2]
            zc = z0 + lane + 1.5
            clear, _ = nav.raycast([x0 + run - 0.3, y + rise, zc], [x0 + run + 0.8, plan["floors"][k + 1], zc])
            assert clear == (step <= 0.37), (k, c, step)
            seen.add(clear)
    assert seen == {True, False}


def test_the_silo_stairs_are_lost_on_the_navmesh_but_the_floors_are_one_area(round_35):
    """Stairs of wedge treads 1.1-1.4 m wide round an open well: the navmesh's erosion (two cells from the wall, the
    ledge rule's cell and two more from the drop) keeps none of the band, so the yard and the silos' floors are one
    area and every area apart is the gallery over the silos' tops (floor 9 m or more up)."""
    label, nav = areas(round_35["silo_stair"](0), DROPS)
    sizes = np.bincount(label, weights=nav.areas)
    ground = int(np.argmax(sizes))
    assert label.max() > 0
    assert (nav.centres[label == ground, 1] < 1.0).all()
    assert (nav.centres[label != ground, 1] > 9.0).all()


def test_the_ring_seating_reaches_every_ring(round_35):
    """Concentric rings with risers of 0.30-0.50 m and radial aisles of half steps (:func:`ring_seating_plan`): one
    area holding floor on every ring's tread."""
    plan = benchmark("level_kinds35").ring_seating_plan(0)
    label, nav = areas(round_35["ring_seating"](0), DROPS)
    assert label.max() == 0
    for r0, tread, _, top in plan["rings"]:  # a polygon under the tread's middle somewhere along its arc
        mid = r0 + tread / 2
        found = [nav.nearest_poly([mid * math.cos(a), top, mid * math.sin(a)], [0.3, 0.3, 0.3])[0]
                 for a in np.linspace(0.1, math.pi - 0.1, 40)]
        assert max(found) >= 0, (r0, top)


def test_the_terraces_seams_and_racks_are_one_area_each(round_35):
    """The terrace village (walls 5-25 degrees off the grid, flights at any heading), the seam plaza (plates 1-3 cm
    apart at 10-40 degrees, over water) and the rack aisles (aisles 1.05-1.75 m): one area each; the village's floor
    on 5 heights or more, the plaza's deck over 85 % covered."""
    label, nav = areas(round_35["terrace_village"](0), DROPS)
    assert label.max() == 0
    assert len({round(float(y), 1) for y in nav.centres[:, 1]}) >= 5  # the street and 4-5 terraces over it
    label, nav = areas(round_35["seam_plaza"](0), DROPS)
    rng = np.random.default_rng(0)
    size_x, size_z = float(rng.uniform(60.0, 70.0)), float(rng.uniform(40.0, 46.0))
    deck = nav.areas[nav.centres[:, 2] > 0.0].sum()
    assert label.max() == 0 and deck > 0.85 * size_x * size_z
    label, _ = areas(round_35["rack_aisles"](0), DROPS)
    assert label.max() == 0


@pytest.fixture(scope="module")
def round_36() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds36.py``'s KINDS (the thirty-sixth round): each call builds its level anew."""
    return benchmark("level_kinds36").KINDS


def test_the_grating_plants_gratings_are_floor_at_both_levels(round_36):
    """Bar gratings (bars 30-50 mm, gaps 25-60 mm, over a 4.5 m drop) are floor to Recast, each of its 0.25 m cells
    holding bars: one area with floor at 4.5 m and at 9 m (docs/analysis_quality.md, "A thirty-sixth round of level
    kinds")."""
    label, nav = areas(round_36["grating_plant"](0), DROPS)
    assert label.max() == 0
    y = nav.centres[:, 1]
    assert nav.areas[np.abs(y - 4.6) < 0.3].sum() > 200.0 and nav.areas[np.abs(y - 9.1) < 0.3].sum() > 100.0


def test_the_stepping_stones_join_nothing_on_the_navmesh(round_36):
    """Stones 0.8-2.2 m across with gaps of 0.15-0.5 m: Recast keeps the agent's centre two cells from every gap, so
    no stone path is crossed; the lawns are one area by the footbridge and the islet, reached by stones only, is an
    area apart."""
    plan = benchmark("level_kinds36").stepping_stones_plan(0)
    label, nav = areas(round_36["stepping_stones"](0), DROPS)
    band, (islet, _) = plan["band"], plan["islet"]
    south = nav.nearest_poly([3.0, 0.0, band[0] - 3.0], [1.0, 1.0, 1.0])[0]
    north = nav.nearest_poly([3.0, 0.0, band[1] + 3.0], [1.0, 1.0, 1.0])[0]
    on_islet = nav.nearest_poly([islet[0], 0.0, islet[1]], [1.5, 1.0, 1.5])[0]
    assert min(south, north, on_islet) >= 0
    assert label[south] == label[north] != label[on_islet]


def test_the_bridge_arenas_jump_pad_platforms_are_apart(round_36):
    """Platforms reached only by jump pads (6-8 m over the one in front) are areas apart for a walker."""
    plan = benchmark("level_kinds36").bridge_arena_plan(0)
    label, nav = areas(round_36["bridge_arena"](0), DROPS)
    main = int(np.argmax(np.bincount(label, weights=nav.areas)))
    for pad in plan["pads"]:
        high, _, top = pad["high"]
        poly = nav.nearest_poly([high[0], top, high[1]], [1.5, 1.0, 1.5])[0]
        assert poly >= 0 and label[poly] != main


def test_the_queue_halls_belts_are_walls_and_low_shutters_close_their_shops(round_36):
    """Belts hanging 0.85-0.95 m over an open floor: a walk straight across a belt line from one lane's middle to the
    next is blocked on the navmesh; a shop behind a shutter whose lower edge is under 1.9 m is an area apart, one
    at 2.3 m or more joined to the hall (seed 0: edges 1.89, 2.05, 1.81 and 2.32 m)."""
    plan = benchmark("level_kinds36").queue_hall_plan(0)
    label, nav = areas(round_36["queue_hall"](0), DROPS)
    (qx0, qx1), z0, width = plan["x"], plan["z0"], plan["width"]
    x = (qx0 + qx1) / 2
    for k in range(plan["lanes"] - 1):
        clear, _ = nav.raycast([x, 0.0, z0 + (k + 0.5) * width], [x, 0.0, z0 + (k + 1.5) * width])
        assert not clear, k
    main = int(np.argmax(np.bincount(label, weights=nav.areas)))
    size_z = plan["size"][1]
    for (sx0, sx1), edge in plan["shops"]:
        poly = nav.nearest_poly([(sx0 + sx1) / 2, 0.0, size_z - 3.0], [1.0, 1.0, 1.0])[0]
        if edge < 1.9:
            assert poly >= 0 and label[poly] != main, edge
        elif edge >= 2.3:
            assert poly >= 0 and label[poly] == main, edge


def test_the_far_outpost_is_its_twin_at_the_origin(round_36):
    """The outpost 35-55 km from the origin and 1.5-3 km up gives the navmesh of its twin built at the origin: as
    many polygons and areas, the same walkable area to 0.1 %."""
    far_label, far = areas(round_36["far_outpost"](0), DROPS)
    near_label, near = areas(round_36["far_outpost"](0, far=False), DROPS)
    assert far.polygon_count == near.polygon_count and far_label.max() == near_label.max()
    assert abs(far.areas.sum() - near.areas.sum()) < 1e-3 * near.areas.sum()


def test_the_canteens_tables_hold_no_floor_under_them_and_no_floor_reached_on_them(round_36):
    """Table tops on thin legs, 0.74-0.77 m up: no navmesh polygon (a convex polygon holds its centre) stands under a
    block's top (0.7 m of head room). The benches' seats, 0.45 m up, are over the 0.4 m climb: on map_analysis's
    cells (``climb: agent``) the hall's main area holds no floor on seats or tops; read in Recast's 0.125 m cells the
    navmesh climbed them and held over 150 m² there (docs/navmesh.md, "The climb at every alignment")."""
    plan = benchmark("level_kinds36").canteen_plan(0)
    for params, climbed in ((PRESET_GRID, False), (DROPS, True)):
        label, nav = areas(round_36["canteen"](0), params)
        x, y, z = nav.centres.T
        for block in plan["blocks"]:
            x0, x1, z0, z1 = block["rect"]
            inside = (x > x0 + 0.1) & (x < x1 - 0.1) & (z > z0 + 0.1) & (z < z1 - 0.1)
            assert not (inside & (y < 0.5)).any(), block
        main = int(np.argmax(np.bincount(label, weights=nav.areas)))
        up_there = nav.areas[(label == main) & (y > 0.55)].sum()
        assert (up_there > 150.0) if climbed else (up_there == 0.0), (params, up_there)


@pytest.fixture(scope="module")
def round_37() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds37.py``'s KINDS (the thirty-seventh round): each call builds its level anew."""
    return benchmark("level_kinds37").KINDS


def test_the_skirted_mazes_panels_are_walls_though_the_floor_runs_under_them(round_37):
    """Panels standing 0.2-0.5 m over the floor: the maze is one area, and a walk from a cell's middle straight to
    its neighbour's across a panel is blocked on the navmesh (no way under a panel)."""
    plan = benchmark("level_kinds37").skirted_maze_plan(0)
    label, nav = areas(round_37["skirted_maze"](0), DROPS)
    assert label.max() == 0
    cols, rows, cell, (ox, oz) = plan["grid"]
    crossed = 0
    for panel in plan["panels"][:60]:
        (x0, z0), (x1, z1) = panel["ends"]
        mx, mz = (x0 + x1) / 2, (z0 + z1) / 2
        side = np.array([0.0, cell / 2]) if z0 == z1 else np.array([cell / 2, 0.0])
        a, b = np.array([mx, mz]) - side, np.array([mx, mz]) + side
        if not (ox < min(a[0], b[0]) and max(a[0], b[0]) < ox + cols * cell
                and oz < min(a[1], b[1]) and max(a[1], b[1]) < oz + rows * cell):
            continue  # a panel of the maze's side: one end in the aisle
        clear, _ = nav.raycast([a[0], 0.0, a[1]], [b[0], 0.0, b[1]])
        crossed += bool(clear)
    assert crossed == 0


def test_the_awning_markets_aisle_loses_its_floor_under_awnings_a_little_over_the_agent(round_37):
    """Head room read in Recast's 0.125 m cells: seed 0's aisle between the rows at z 16.9 and 19.8 m, under awnings
    whose lower edges hang 2.07 and 2.09 m up (a 2 m agent walks under them) with 0.6 m of open sky between them,
    has no floor at x 49.5-52.5 m; a stretch under edges of 2.18-2.29 m has (docs/analysis_quality.md, "A
    thirty-seventh round of level kinds")."""
    _, nav = areas(round_37["awning_market"](0), DROPS)
    for x in (50.0, 51.0, 52.0):
        assert nav.nearest_poly([x, 0.0, 18.37], [0.1, 0.3, 0.1])[0] < 0, x
    for x in (59.0, 60.0, 61.0):
        assert nav.nearest_poly([x, 0.0, 18.37], [0.1, 0.3, 0.1])[0] >= 0, x


def test_the_arcade_cloisters_closed_garth_is_apart_and_the_open_one_joined(round_37):
    """A garth behind piers 0.54-0.79 m apart (under the agent's 1 m) is an area apart; one with a side of 1.19 m
    gaps is joined to the walk on the navmesh (seed 0)."""
    plan = benchmark("level_kinds37").arcade_cloister_plan(0)
    label, nav = areas(round_37["arcade_cloister"](0), DROPS)
    main = int(np.argmax(np.bincount(label, weights=nav.areas)))
    first, second = ([(g[0] + g[1]) / 2, 0.0, g[2] + 2.0] for g in (c["garth"] for c in plan["cloisters"]))
    p_first, p_second = (nav.nearest_poly(p, [1.0, 0.5, 1.0])[0] for p in (first, second))
    assert p_first >= 0 and p_second >= 0
    assert label[p_first] == main != label[p_second]


def test_the_tilt_docks_ramps_and_rolled_pontoons_are_one_area(round_37):
    """Gangways and ramps of 10-25 degrees, hinge plates of 0.05 m, decks rolled 0-5 degrees: one area, with floor on
    every head pontoon."""
    plan = benchmark("level_kinds37").tilt_dock_plan(0)
    label, nav = areas(round_37["tilt_dock"](0), DROPS)
    assert label.max() == 0
    for pier in plan["piers"]:
        z = pier["z"][0] - pier["head"]["run"] - 3.0
        assert nav.nearest_poly([pier["x"], pier["head"]["deck"], z], [1.0, 0.5, 1.0])[0] >= 0


def test_the_bump_parks_steep_flanked_bumps_do_not_cut_its_aisles(round_37):
    """Speed bumps 0.08-0.15 m high whose flanks slope up to 60 degrees (over the 45 degree slope): a walk along each
    aisle's middle over every bump is clear on the navmesh, and the lot is one area."""
    plan = benchmark("level_kinds37").bump_park_plan(0)
    label, nav = areas(round_37["bump_park"](0), DROPS)
    assert label.max() == 0
    for aisle in plan["aisles"]:
        z = sum(aisle["z"]) / 2
        for bump in aisle["bumps"]:
            clear, _ = nav.raycast([bump["x"] - 2.0, 0.0, z], [bump["x"] + 2.0, 0.0, z])
            assert clear, bump


def test_the_parapet_roofs_parapets_are_climbed_by_the_agents_climb(round_37):
    """Roofs behind parapets: on map_analysis's cells (``climb: agent``) every roof with a parapet under 0.4 m on an
    eave side is joined to the walkways, every roof whose lowest parapet is over 0.425 m apart. Read in Recast's
    0.125 m cells, roofs whose lowest parapet is 0.41-0.48 m were joined too (docs/analysis_quality.md, "A
    thirty-seventh round of level kinds"; docs/navmesh.md, "The climb at every alignment"; seed 0)."""
    plan = benchmark("level_kinds37").parapet_roofs_plan(0)
    for params, agent_climb in ((PRESET_GRID, True), (DROPS, False)):
        label, nav = areas(round_37["parapet_roofs"](0), params)
        main = int(np.argmax(np.bincount(label, weights=nav.areas)))
        cols, rows, (bx, bz), w = plan["grid"]
        over_climb_joined = 0
        for b in plan["bays"]:
            if b["kind"] != "pitched":
                continue
            c, r = b["cell"]
            x0, z0 = w + c * (bx + w), w + r * (bz + w)
            eaves = ("south", "north") if b["along_x"] else ("west", "east")
            y = plan["height"] + 0.3  # on the roof's slope 0.8 m inside its first eave
            point = [x0 + bx / 2, y, z0 + 0.8] if b["along_x"] else [x0 + 0.8, y, z0 + bz / 2]
            poly = nav.nearest_poly(point, [0.6, 1.0, 0.6])[0]
            assert poly >= 0
            joined = label[poly] == main
            lowest = min(b["parapets"].values())
            if min(b["parapets"][s] for s in eaves) < (0.4 if agent_climb else 0.375):
                assert joined, b["parapets"]
            elif lowest > (0.425 if agent_climb else 0.5):
                assert not joined, b["parapets"]
            elif lowest > 0.4:  # on the agent's cells the band 0.40-0.425 m is the grid's own
                over_climb_joined += joined
        assert agent_climb or over_climb_joined >= 3, over_climb_joined


@pytest.fixture(scope="module")
def round_38() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds38.py``'s KINDS (the thirty-eighth round): each call builds its level anew."""
    return benchmark("level_kinds38").KINDS


def _main_area(label: np.ndarray, nav) -> int:
    """The connected area holding the most walkable area."""
    return int(np.argmax(np.bincount(label, weights=nav.areas)))


def test_the_headstone_yards_plots_are_entered_only_between_stones_a_metre_apart(round_38):
    """Plots ringed by thin headstones (seed 0): every plot whose widest gap is 0.81 m or less has no floor joined to
    the paths, every plot with a gap of 1.1 m or more has (docs/analysis_quality.md, "A thirty-eighth round of level
    kinds")."""
    plan = benchmark("level_kinds38").headstone_yard_plan(0)
    label, nav = areas(round_38["headstone_yard"](0), PRESET_GRID)
    main = _main_area(label, nav)
    cols, rows, (px, pz), path, (ox, oz) = plan["grid"]
    for plot in plan["plots"]:
        c, r = plot["cell"]
        x0, z0 = ox + c * (px + path), oz + r * (pz + path)
        inside = ((nav.centres[:, 0] > x0) & (nav.centres[:, 0] < x0 + px)
                  & (nav.centres[:, 2] > z0) & (nav.centres[:, 2] < z0 + pz))
        widest = max(gap for _, gap in plot["gaps"].values())
        joined = bool((label[inside] == main).any())
        if widest <= 0.81:
            assert not joined, plot["cell"]
        elif widest >= 1.1:
            assert joined, plot["cell"]


def test_the_coaming_decks_coamings_read_by_the_climb_and_its_tween_companionways_cut(round_38):
    """Seed 0: cabins behind coamings of 0.25-0.34 m and hatch covers 0.33-0.38 m up are joined to the deck, those
    of 0.435 m and more apart. The companionways to the tween deck (open treads 0.13-0.16 m deep, risers 0.21-0.22
    m) are cut on the navmesh: a 0.25 m cell holds two tread edges, two risers over the climb, though each riser is
    under it (the same on the sampling route's 0.25 m probes; docs/analysis_quality.md, "A thirty-eighth round of
    level kinds")."""
    plan = benchmark("level_kinds38").coaming_deck_plan(0)
    label, nav = areas(round_38["coaming_deck"](0), PRESET_GRID)
    main, beam = _main_area(label, nav), plan["beam"]
    for cabin in plan["cabins"]:
        z = 3.5 if cabin["side"] == "port" else beam - 3.5
        poly = nav.nearest_poly([sum(cabin["x"]) / 2 + 0.5, 0.0, z], [0.6, 0.5, 0.6])[0]
        assert poly >= 0
        assert (label[poly] == main) == (cabin["coaming"] < 0.4), cabin
    for hatch in plan["hatches"]:
        poly = nav.nearest_poly([sum(hatch["x"]) / 2, hatch["coaming"], beam / 2], [0.6, 0.3, 0.6])[0]
        assert poly >= 0
        assert (label[poly] == main) == (hatch["coaming"] < 0.4), hatch
    tween = nav.nearest_poly([30.0, -3.0, beam / 2], [0.6, 0.5, 0.6])[0]
    assert tween >= 0 and label[tween] != main


def test_the_rubble_naves_galleries_are_reached_up_heaps_under_the_slope_limit(round_38):
    """Seed 0's south gallery is reached up a heap of 42.6 degrees, its north one (heaps of 50.4 and 47.6) apart;
    seed 1's north gallery, up a heap of 41.2 degrees strewn with rocks 0.1-0.3 m proud, is apart on the navmesh too
    (the rocks' steep faces and the erosion round them cut the heap's 1.3 m of walkable middle; without them it is
    joined: docs/analysis_quality.md, "A thirty-eighth round of level kinds")."""
    module = benchmark("level_kinds38")
    for seed, joined in ((0, {"south": True, "north": False}), (1, {"south": True, "north": False})):
        plan = module.rubble_nave_plan(seed)
        label, nav = areas(round_38["rubble_nave"](seed), PRESET_GRID)
        main = _main_area(label, nav)
        width = plan["nave"] + 2 * plan["aisle"]
        for name, z in (("south", 13.5), ("north", 12.0 + width - 1.5)):
            poly = nav.nearest_poly([15.0, plan["gallery"], z], [0.6, 0.3, 0.6])[0]
            assert poly >= 0
            assert (label[poly] == main) == joined[name], (seed, name)


def test_the_raised_beds_high_tops_keep_no_area(round_38):
    """Beds 0.41-0.7 m high, tops 1.6-2.0 m across: the navmesh keeps no floor on them that is an area of its own
    (the ledge rule's cell and the agent's radius off each edge leave under Recast's smallest region), so the
    glasshouses are one area; no bed top joins the aisles over a step over 0.425 m (seed 0)."""
    plan = benchmark("level_kinds38").raised_beds_plan(0)
    label, nav = areas(round_38["raised_beds"](0), PRESET_GRID)
    assert label.max() == 0
    for house in plan["houses"]:
        for half in house["halves"].values():
            for (c, r), h in half["heights"].items():
                (bx0, bx1), (bz0, bz1) = house["columns"][c], half["rows"][r]
                on_top = ((nav.centres[:, 0] > bx0 + 0.3) & (nav.centres[:, 0] < bx1 - 0.3)
                          & (nav.centres[:, 2] > bz0 + 0.3) & (nav.centres[:, 2] < bz1 - 0.3)
                          & (np.abs(nav.centres[:, 1] - h) < 0.1))
                assert h <= 0.425 or not on_top.any(), (c, r, h)


def test_the_open_stairs_storeys_are_one_area(round_38):
    """Floating open-riser treads (overlaps of -0.05 to +0.04 m, risers 0.17-0.20 m): all three storeys one area."""
    for seed in (0, 1):
        label, _ = areas(round_38["open_stairs"](seed), PRESET_GRID)
        assert label.max() == 0, seed


def test_the_stile_fields_areas_are_the_plans(round_38):
    """Gates and step stiles of risers up to 0.4 m join fields, squeeze stiles (slots 0.25-0.45 m at the ground) and
    stiles of risers over 0.425 m do not: seed 0's navmesh areas are the plan's groups of fields
    (``stile_fields_areas``)."""
    module = benchmark("level_kinds38")
    plan = module.stile_fields_plan(0)
    label, nav = areas(round_38["stile_fields"](0), PRESET_GRID)
    xs = np.concatenate([[0.0], np.cumsum(plan["widths"])]) + 4.0
    zs = np.concatenate([[0.0], np.cumsum(plan["depths"])]) + 9.0
    field_area: dict = {}
    for c in range(len(plan["widths"])):
        for r in range(len(plan["depths"])):
            for dx, dz in ((0.0, 0.0), (3.0, 0.0), (-3.0, 0.0), (0.0, 3.0), (0.0, -3.0)):
                poly = nav.nearest_poly([(xs[c] + xs[c + 1]) / 2 + dx, 0.0, (zs[r] + zs[r + 1]) / 2 + dz],
                                        [0.5, 0.5, 0.5])[0]
                if poly >= 0:
                    field_area[(c, r)] = int(label[poly])
                    break
    field_area[(-1, -1)] = int(label[nav.nearest_poly([xs[0] + 5.0, 0.0, 6.5], [0.5, 0.5, 0.5])[0]])
    groups: dict = {}
    for field, area in field_area.items():
        groups.setdefault(area, set()).add(field)
    assert sorted(map(sorted, groups.values())) == sorted(map(sorted, module.stile_fields_areas(plan)))
    assert label.max() + 1 == len(groups)


@pytest.fixture(scope="module")
def round_39() -> dict[str, Callable[..., trimesh.Trimesh]]:
    """``benchmarks/level_kinds39.py``'s KINDS (the thirty-ninth round): each call builds its level anew."""
    return benchmark("level_kinds39").KINDS


def test_the_round_39_plans_answers():
    """The answers the round's docstrings give from the plans (written before any pipeline run): traps (bowls steeper
    than 45 degrees) 12 / 8 / 10, path pieces between pinches 4 / 3 / 4, cellars under 2.0 m of head room 4 / 3 / 4
    on seeds 0-2."""
    module = benchmark("level_kinds39")
    assert [len(module.shell_bowls_traps(module.shell_bowls_plan(s))) for s in range(3)] == [12, 8, 10]
    assert [len(module.cliff_path_areas(module.cliff_path_plan(s))) for s in range(3)] == [4, 3, 4]
    assert [len(module.cellar_stairs_cut(module.cellar_stairs_plan(s))) for s in range(3)] == [4, 3, 4]


def test_the_shell_bowls_traps_are_areas_apart(round_39):
    """Seed 0: each bowl whose wall stands over 45 degrees (45.1-52.8) holds an area of its own, every other bowl
    (25.3-44.7 degrees) is joined to the field: 13 areas, as the plan says (docs/analysis_quality.md, "A thirty-ninth
    round of level kinds")."""
    module = benchmark("level_kinds39")
    plan = module.shell_bowls_plan(0)
    label, nav = areas(round_39["shell_bowls"](0), PRESET_GRID)
    main, traps = _main_area(label, nav), set(module.shell_bowls_traps(plan))
    for i, bowl in enumerate(plan["bowls"]):
        cx, cz = bowl["centre"]
        poly = nav.nearest_poly([cx, -bowl["depth"], cz], [0.5, 0.3, 0.5])[0]
        assert poly >= 0
        assert (label[poly] != main) == (i in traps), (i, bowl["slope"])
    assert label.max() + 1 == 1 + len(traps)


def test_the_ski_lodges_open_flights_are_kept_from_about_1_4_m(round_39):
    """Seed 0's half-flights between split-level plates, open on both sides: the navmesh joins the plates across every
    flight of 1.48 m or more and none of 1.14-1.34 m (a player 1 m across walks them all: the round's first miss)."""
    plan = benchmark("level_kinds39").ski_lodge_plan(0)
    label, nav = areas(round_39["ski_lodge"](0), PRESET_GRID)
    xs = plan["xs"]

    def plate(i: int) -> int:
        poly = nav.nearest_poly([(xs[i] + xs[i + 1]) / 2, plan["heights"][i], 1.2], [2.0, 0.2, 1.0])[0]
        assert poly >= 0, i
        return int(label[poly])
    for b, flight in enumerate(plan["flights"]):
        if flight["width"] >= 1.48:
            assert plate(b) == plate(b + 1), flight
        elif flight["width"] <= 1.34:
            assert plate(b) != plate(b + 1), flight


def test_the_cellar_stairs_need_more_head_room_on_the_navmesh_than_the_agent(round_39):
    """Seed 0: every cellar is apart on the navmesh, those under 1.66-1.99 m of head room over the overhung tread
    (a player 2 m tall does not pass) and those under 2.08-2.26 m (a player passes): Recast links two neighbouring
    cells by the higher floor under the lower ceiling, so a stair under an edge loses a riser and the rounding
    (docs/analysis_quality.md, "A thirty-ninth round of level kinds"; docs/navmesh.md, "Head room a little over the
    agent's height")."""
    plan = benchmark("level_kinds39").cellar_stairs_plan(0)
    label, nav = areas(round_39["cellar_stairs"](0), PRESET_GRID)
    street = label[nav.nearest_poly([2.0, 0.0, -5.0], [1.0, 0.3, 1.0])[0]]
    for house in plan["houses"]:
        x0, x1 = house["x"]
        poly = nav.nearest_poly([x1 - 1.5, -house["cellar"], 9.0], [1.0, 0.3, 1.5])[0]
        assert poly >= 0
        assert label[poly] != street, house["clearance"]
