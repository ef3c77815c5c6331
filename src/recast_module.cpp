// g2s_plugins.recast._recast: Recast navmesh builds (solo or tiled) and Detour queries.
//
// A solo build runs Recast's single-tile pipeline over the whole grid. A tiled
// build cuts the grid into square tiles of `tile_size` cells, rasterises each
// tile (plus a border of walkableRadius + 3 cells) from the triangles whose
// bounding boxes overlap it, builds a poly mesh + detail mesh per tile, and adds
// every tile to one dtNavMesh. Tiles are built in parallel worker threads.
//
// The mesh data (polygons, detail triangles) is copied out of the Recast
// structures into plain vectors with global indices (tiles in row-major order,
// polygons in tile order); neighbours and portals come from Detour's links, so
// they include tile-border adjacency. The Detour navmesh + query object are
// kept for raycasts and nearest-polygon look-ups.

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/array.h>
#include <nanobind/stl/optional.h>

#include <Recast.h>
#include <RecastAlloc.h>
#include <DetourAlloc.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshBuilder.h>
#include <DetourNavMeshQuery.h>
#include <DetourStatus.h>

#include "forest_simplify.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cfloat>
#include <climits>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace nb = nanobind;

namespace {

// ---------------------------------------------------------------- helpers

// rcContext that keeps the error messages Recast logs, so exceptions can show them.
class LogContext : public rcContext {
public:
    LogContext() : rcContext(true) {}
    std::string errors;

protected:
    void doLog(const rcLogCategory category, const char* msg, const int len) override {
        if (category == RC_LOG_ERROR) {
            if (!errors.empty()) errors += "; ";
            errors.append(msg, static_cast<size_t>(len));
        }
    }
};

// A solo build failed at a step limited by one tile's 16-bit indices (regions,
// poly-mesh vertices, Detour tile data): the automatic mode retries with tiles.
struct TooBigForSolo : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string message(const std::string& step, const std::string& where, const LogContext* ctx) {
    std::string msg = "Recast: " + step + where;
    if (ctx && !ctx->errors.empty()) msg += " (" + ctx->errors + ")";
    return msg;
}

[[noreturn]] void fail(const std::string& step, const LogContext* ctx = nullptr, const std::string& where = "") {
    throw std::runtime_error(message(step, where, ctx));
}

struct HeightfieldDel { void operator()(rcHeightfield* p) const { rcFreeHeightField(p); } };
struct CompactDel { void operator()(rcCompactHeightfield* p) const { rcFreeCompactHeightfield(p); } };
struct ContourDel { void operator()(rcContourSet* p) const { rcFreeContourSet(p); } };
struct PolyMeshDel { void operator()(rcPolyMesh* p) const { rcFreePolyMesh(p); } };
struct DetailDel { void operator()(rcPolyMeshDetail* p) const { rcFreePolyMeshDetail(p); } };
struct NavMeshDel { void operator()(dtNavMesh* p) const { dtFreeNavMesh(p); } };
struct QueryDel { void operator()(dtNavMeshQuery* p) const { dtFreeNavMeshQuery(p); } };
struct DtFreeDel { void operator()(unsigned char* p) const { dtFree(p); } };

template <typename T>
nb::object to_numpy(const std::vector<T>& src, size_t rows, size_t cols, size_t depth = 0) {
    auto* copy = new std::vector<T>(src);
    if (copy->empty()) copy->resize(1);  // keep a valid data pointer for empty arrays
    nb::capsule owner(copy, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
    if (depth != 0)
        return nb::cast(nb::ndarray<nb::numpy, T>(copy->data(), {rows, cols, depth}, owner), nb::rv_policy::move);
    if (cols == 0) return nb::cast(nb::ndarray<nb::numpy, T>(copy->data(), {rows}, owner), nb::rv_policy::move);
    return nb::cast(nb::ndarray<nb::numpy, T>(copy->data(), {rows, cols}, owner), nb::rv_policy::move);
}

unsigned int bits_for(unsigned int n) {  // Detour's dtIlog2(dtNextPow2(n))
    unsigned int p = 1, b = 0;
    while (p < n) { p <<= 1; ++b; }
    return b;
}

// ---------------------------------------------------------------- settings

// Automatic tiling: solo when both grid sides are at most this many cells
// (and the solo build fits one tile), otherwise tiles of AUTO_TILE_SIZE cells.
constexpr int AUTO_SOLO_MAX_CELLS = 512;
constexpr int AUTO_TILE_SIZE = 256;
constexpr int MIN_TILE_SIZE = 16;

// Recast's region partitions (step 4 of build_tile). automatic: watershed, redone
// with AUTO_FALLBACK in a tile where a watershed region overlaps itself in plan or
// where one region's contours total more than AUTO_MAX_REGION_CONTOUR_VERTS vertices.
enum class Partition { automatic, watershed, monotone, layers };
constexpr Partition AUTO_FALLBACK = Partition::monotone;

// rcBuildPolyMesh triangulates each region's contour, its holes joined to its outline,
// in time about cubic in the contour's vertices. Watershed makes one region of a maze's
// winding corridors or of a floor round a pillar field: 303-1483 vertices on mazes of
// 16-32 cells (0.16-14 s in rcBuildPolyMesh), 630-761 in the 256-cell tiles of 48-cell
// mazes, 1754 in a tile and 3394 solo on a 112 m pillar floor (22 s, 202 s). Every level
// of the structure-hash set (nav_test, the pieces, the samples, dungeons of up to 12,000
// rooms) with every preset's agent has at most 54 (docs/navmesh.md, "Slow case", measured
// 3 December 2026). 128 sits 2.4 times above the one and 2.4 times below the other.
constexpr int AUTO_MAX_REGION_CONTOUR_VERTS = 128;

// Which ledge filter runs after rasterisation: Recast's rcFilterLedgeSpans, our drop_ledge_spans (its first rule
// alone), or none.
enum class LedgeFilter { recast, drops, off };

LedgeFilter parse_ledge_filter(const std::string& name) {
    if (name == "recast") return LedgeFilter::recast;
    if (name == "drops") return LedgeFilter::drops;
    if (name == "off") return LedgeFilter::off;
    throw nb::value_error(
        ("Recast: ledge_filter must be 'recast', 'drops' or 'off', got '" + name + "'").c_str());
}

Partition parse_partition(const std::string& name) {
    if (name == "auto") return Partition::automatic;
    if (name == "watershed") return Partition::watershed;
    if (name == "monotone") return Partition::monotone;
    if (name == "layers") return Partition::layers;
    throw nb::value_error(
        ("Recast: partition must be 'auto', 'watershed', 'monotone' or 'layers', got '" + name + "'").c_str());
}

struct Settings {
    double cell_size, cell_height;
    double agent_height, agent_radius, agent_max_climb, agent_max_slope;
    double region_min_size, region_merge_size;
    double edge_max_len, edge_max_error;
    int verts_per_poly;
    double detail_sample_dist, detail_sample_max_error;
    long long max_cells;  // most xz cells rasterised at once (the solo grid, or one tile with its border)
    int tile_size;  // -1: automatic, 0: solo, > 0: tiles of this many cells
    int threads;    // worker threads of a tiled build; 0: hardware concurrency
    bool filter_low_hanging_obstacles, filter_low_height_spans;
    LedgeFilter ledge_filter;
    Partition partition;
    bool recast_head_room;  // the low-height filter as Recast ships it: one cell more head room than the agent's
    bool join_corners;      // put back the eroded spans that join two kept ones touching only at a corner, or across a door
};

// Limits of Recast 1.5.1's voxel settings: compact spans store their height in
// 8 bits (an agent taller than 255 cells never fits), erosion compares twice the
// radius as an unsigned char, contour simplification squares maxEdgeLen in an
// int, span heights have 13 bits; tiles are addressed with at most 22 bits.
constexpr long long MAX_WALKABLE_HEIGHT = 255;
constexpr long long MAX_WALKABLE_CLIMB = 255;
constexpr long long MAX_WALKABLE_RADIUS = 127;
constexpr long long MAX_EDGE_LEN_CELLS = 46340;
constexpr long long MAX_GRID_SIDE = (1LL << 24) - 1;  // also the vertex-key limit of tiled builds
constexpr long long MAX_TILES = 1LL << 22;

void check_settings(const Settings& s) {
    auto positive = [](double v, const char* name) {
        if (!(v > 0.0) || !std::isfinite(v))
            throw nb::value_error((std::string("Recast: ") + name + " must be > 0").c_str());
    };
    auto non_negative = [](double v, const char* name) {
        if (!(v >= 0.0) || !std::isfinite(v))
            throw nb::value_error((std::string("Recast: ") + name + " must be >= 0").c_str());
    };
    positive(s.cell_size, "cell_size");
    positive(s.cell_height, "cell_height");
    positive(s.agent_height, "agent_height");
    non_negative(s.agent_radius, "agent_radius");
    non_negative(s.agent_max_climb, "agent_max_climb");
    if (!(s.agent_max_slope >= 0.0 && s.agent_max_slope < 90.0))
        throw nb::value_error("Recast: agent_max_slope must be in [0, 90) degrees");
    non_negative(s.region_min_size, "region_min_size");
    non_negative(s.region_merge_size, "region_merge_size");
    non_negative(s.edge_max_len, "edge_max_len");
    non_negative(s.edge_max_error, "edge_max_error");
    non_negative(s.detail_sample_dist, "detail_sample_dist");
    non_negative(s.detail_sample_max_error, "detail_sample_max_error");
    if (s.verts_per_poly < 3 || s.verts_per_poly > DT_VERTS_PER_POLYGON)
        throw nb::value_error("Recast: verts_per_poly must be in [3, 6] (Detour's DT_VERTS_PER_POLYGON)");
    if (s.tile_size != -1 && s.tile_size != 0 && s.tile_size < MIN_TILE_SIZE)
        throw nb::value_error("Recast: tile_size must be None (automatic), 0 (solo) or >= 16 cells");
    if (s.threads < 0) throw nb::value_error("Recast: threads must be >= 0");
    if (s.max_cells <= 0) throw nb::value_error("Recast: max_cells must be > 0");
}

// ---------------------------------------------------------------- one tile

// A span at a tile's edge as drop_border_islands matches it with the next tile's: its global grid cell (z << 32 | x,
// each as 32 bits), its floor (cells of ch) and the tile's region it belongs to (for a link: the region linking out).
struct SeamSpan {
    uint64_t cell;
    int y;
    unsigned short reg;
};

// The Recast output of one tile, copied out in Recast's own layout (what dtCreateNavMeshData reads, so that the
// tile's Detour data can be made again without some polygons: drop_border_islands), plus its Detour tile data.
struct TileMesh {
    int tx = 0, ty = 0;
    int gx0 = 0, gz0 = 0;                 // global grid cell of the tile's first (non-border) cell
    int nverts = 0, npolys = 0;
    float bmin[3] = {0, 0, 0}, bmax[3] = {0, 0, 0};  // the poly mesh's bounds, world
    std::vector<unsigned short> verts;    // (nverts,3) as rcPolyMesh: grid x, y, z cells from bmin
    std::vector<unsigned short> polys;    // (npolys,2 nvp) as rcPolyMesh: vertex indices, then neighbours / portal flags
    std::vector<unsigned char> areas;     // (npolys,)
    std::vector<unsigned short> regs;     // (npolys,) local region ids
    std::vector<unsigned int> dmeshes;    // (npolys,4) as rcPolyMeshDetail: vertex base, count, triangle base, count
    std::vector<float> dverts;            // (DV,3) world
    std::vector<unsigned char> dtris;     // (DT,4) as rcPolyMeshDetail: vertex indices from the base, edge flags
    std::vector<int> region_cells;        // tiled builds: each region's cells (spans) inside the tile, by region id
    std::vector<uint32_t> region_pairs;   // tiled builds: regions (a << 16 | b, a < b) with linked spans in the tile
    std::vector<SeamSpan> seam_spans;     // tiled builds: the spans of the tile's outermost cells, by cell and floor
    std::vector<SeamSpan> seam_links;     // tiled builds: the walkable spans of the tile's border that those link to
    std::unique_ptr<unsigned char, DtFreeDel> data;  // dtCreateNavMeshData output
    int data_size = 0;
    std::string empty_reason;             // why the tile has no polygons (npolys == 0)
    std::vector<float> overlaps;          // (K,3) world: a span of each region that overlaps itself in plan
    std::vector<unsigned short> overlap_regions;  // (K,) the region of each of those spans
    bool repartitioned = false;           // automatic partition: watershed regions overlapped or too long, redone
    std::vector<int32_t> detail_redone;   // local polygons whose detail read another storey, rebuilt
    std::vector<int32_t> detail_resampled; // local polygons whose detail left the floor, rebuilt with finer samples
};

// One span (world x, floor y, z) of each region of `chf` that holds two spans of one
// column: a region overlapping itself in plan, which Recast's contours (traced in
// plan) cannot describe; `regions` gets their ids. Regions in order of first sight, scanning rows of columns.
// O(spans + pairs of spans in a column): a column of one span is passed at once, and the set
// is asked only about a region found twice (asked for every span, it took twice the time).
std::vector<float> self_overlapping_regions(const rcCompactHeightfield& chf, std::vector<unsigned short>& regions) {
    std::vector<float> found;
    regions.clear();
    std::unordered_set<unsigned short> seen;
    for (int z = 0; z < chf.height; ++z) {
        for (int x = 0; x < chf.width; ++x) {
            const rcCompactCell& cell = chf.cells[x + z * chf.width];
            if (cell.count < 2) continue;
            const int end = static_cast<int>(cell.index + cell.count);
            for (int i = static_cast<int>(cell.index); i < end; ++i) {
                const unsigned short reg = chf.spans[i].reg;
                if (reg == 0 || (reg & RC_BORDER_REG)) continue;
                int j = i + 1;
                while (j < end && chf.spans[j].reg != reg) ++j;
                if (j == end || !seen.insert(reg).second) continue;
                regions.push_back(reg);
                found.insert(found.end(), {chf.bmin[0] + (static_cast<float>(x) + 0.5f) * chf.cs,
                                           chf.bmin[1] + static_cast<float>(chf.spans[i].y) * chf.ch,
                                           chf.bmin[2] + (static_cast<float>(z) + 0.5f) * chf.cs});
            }
        }
    }
    return found;
}

// The most contour vertices of one region of `cset`: its outline and its holes, which
// rcBuildPolyMesh triangulates as one polygon.
int largest_region_contour(const rcContourSet& cset) {
    std::unordered_map<unsigned short, int> per_region;
    int largest = 0;
    for (int i = 0; i < cset.nconts; ++i)
        largest = std::max(largest, per_region[cset.conts[i].reg] += cset.conts[i].nverts);
    return largest;
}

// ---------------------------------------------------------------- detail heights off the storey

// Recast's detail mesh (rcBuildPolyMeshDetail; getHeightData in RecastMeshDetail.cpp) reads each
// polygon's heights over its bounding box, one cell wider, from the spans of the polygon's region,
// one per column, then floods the columns left by connection from the region's edge spans. The
// region is its only storey filter: a region overlapping itself (watershed) holds two storeys in
// one column, and even one that never does (auto, monotone, layers) can wind round a spiral stair
// and come back one turn higher in the next columns. The box then holds the region on two storeys,
// and the samples read there (inside the polygon or on its edges) take the other storey's heights.
// Recast has its own path for a polygon that may lie over its region elsewhere (a polygon of
// several regions: seed at its vertices' spans, flood by connection); here the region's spans on
// the other storey are hidden from the one polygon's rebuild instead, so that it still reads its
// own storey's spans directly, as Recast does for every other polygon.

// The detail of polygon `i` of `pm` alone: rcBuildPolyMeshDetail on a one-polygon view of pm.
bool polygon_detail(rcContext& ctx, const rcPolyMesh& pm, int i, const rcCompactHeightfield& chf,
                    const rcConfig& c, rcPolyMeshDetail& out) {
    rcPolyMesh one;  // borrows pm's arrays; released below, before its destructor would free them
    one.verts = pm.verts;
    one.polys = pm.polys + static_cast<size_t>(i) * 2 * pm.nvp;
    one.regs = pm.regs + i;
    one.flags = pm.flags + i;
    one.areas = pm.areas + i;
    one.nverts = pm.nverts;
    one.npolys = one.maxpolys = 1;
    one.nvp = pm.nvp;
    rcVcopy(one.bmin, pm.bmin);
    rcVcopy(one.bmax, pm.bmax);
    one.cs = pm.cs;
    one.ch = pm.ch;
    one.borderSize = pm.borderSize;
    one.maxEdgeError = pm.maxEdgeError;
    const bool ok = rcBuildPolyMeshDetail(&ctx, one, chf, c.detailSampleDist, c.detailSampleMaxError, out);
    one.verts = one.polys = one.regs = one.flags = nullptr;
    one.areas = nullptr;
    return ok;
}

// The least-squares plane y = a x + b z + d through polygon `i`'s vertices, in cells of the poly
// mesh (x, z from its origin, y in cell heights); flat at their mean height if degenerate.
std::array<double, 3> vertex_plane(const rcPolyMesh& pm, int i) {
    const unsigned short* p = &pm.polys[static_cast<size_t>(i) * 2 * pm.nvp];
    double m[3][3] = {}, r[3] = {};
    for (int k = 0; k < pm.nvp && p[k] != RC_MESH_NULL_IDX; ++k) {
        const unsigned short* v = &pm.verts[p[k] * 3];
        const double row[3] = {static_cast<double>(v[0]), static_cast<double>(v[2]), 1.0};
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) m[a][b] += row[a] * row[b];
            r[a] += row[a] * v[1];
        }
    }
    auto det = [](const double a[3][3]) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double d = det(m);
    std::array<double, 3> plane = {0.0, 0.0, r[2] / m[2][2]};
    if (std::fabs(d) <= 1e-9) return plane;
    for (int col = 0; col < 3; ++col) {  // Cramer's rule
        double mc[3][3];
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) mc[a][b] = b == col ? r[a] : m[a][b];
        plane[col] = det(mc) / d;
    }
    return plane;
}

// How far (cell heights) the farthest vertex of detail mesh `mesh` lies from `plane`.
double detail_plane_offset(const rcPolyMesh& pm, const rcPolyMeshDetail& dm, int mesh, const std::array<double, 3>& plane) {
    const unsigned int vb = dm.meshes[mesh * 4 + 0], nv = dm.meshes[mesh * 4 + 1];
    double farthest = 0.0;
    for (unsigned int k = vb; k < vb + nv; ++k) {
        const float* v = &dm.verts[k * 3];
        // Recast sets a detail vertex one cell height above the span it read
        const double y = (v[1] - pm.bmin[1]) / pm.ch - 1.0;
        const double at = plane[0] * (v[0] - pm.bmin[0]) / pm.cs + plane[1] * (v[2] - pm.bmin[2]) / pm.cs + plane[2];
        farthest = std::max(farthest, std::fabs(y - at));
    }
    return farthest;
}

// Whether a vertex of detail mesh `mesh` lies more than the agent's height from `plane`.
bool detail_leaves_plane(const rcPolyMesh& pm, const rcPolyMeshDetail& dm, int mesh, const std::array<double, 3>& plane,
                         int walkable_height) {
    return detail_plane_offset(pm, dm, mesh, plane) > walkable_height;
}

// The spans of polygon `i`'s region that its detail must not read: in the columns Recast reads for
// it, the pieces of the region (spans joined by connections within those columns) that no polygon
// vertex stands on (a span of a cell at the vertex within the climb of its height) and that hold a
// span more than the agent's height from the plane through the vertices: another storey.
std::vector<int> other_storey_spans(const rcPolyMesh& pm, int i, const std::array<double, 3>& plane,
                                    const rcCompactHeightfield& chf, const rcConfig& c, std::vector<int>& piece) {
    const unsigned short reg = pm.regs[i];
    if (reg == RC_MULTIPLE_REGS) return {};  // Recast seeds such a polygon at its vertices already
    const unsigned short* p = &pm.polys[static_cast<size_t>(i) * 2 * pm.nvp];
    int n = 0;
    int x0 = chf.width, x1 = 0, z0 = chf.height, z1 = 0;
    for (; n < pm.nvp && p[n] != RC_MESH_NULL_IDX; ++n) {
        const unsigned short* v = &pm.verts[p[n] * 3];
        x0 = std::min(x0, static_cast<int>(v[0])); x1 = std::max(x1, static_cast<int>(v[0]));
        z0 = std::min(z0, static_cast<int>(v[2])); z1 = std::max(z1, static_cast<int>(v[2]));
    }
    // Recast's box (rcBuildPolyMeshDetail), in the compact heightfield's columns.
    const int bs = pm.borderSize;
    x0 = std::max(0, x0 - 1) + bs; x1 = std::min(chf.width, x1 + 1) + bs;
    z0 = std::max(0, z0 - 1) + bs; z1 = std::min(chf.height, z1 + 1) + bs;
    x1 = std::min(x1, chf.width); z1 = std::min(z1, chf.height);
    auto column = [&](int x, int z) -> const rcCompactCell& { return chf.cells[x + z * chf.width]; };

    // Pieces of the region in the box (flood by connection).
    std::vector<int> spans, queue;
    int pieces = 0;
    for (int z = z0; z < z1; ++z)
        for (int x = x0; x < x1; ++x) {
            const rcCompactCell& cell = column(x, z);
            for (int s = static_cast<int>(cell.index); s < static_cast<int>(cell.index + cell.count); ++s) {
                if (chf.spans[s].reg != reg || piece[s] >= 0) continue;
                piece[s] = pieces;
                spans.push_back(s);
                queue.assign({x, z, s});
                for (size_t q = 0; q < queue.size(); q += 3) {
                    const rcCompactSpan& cs = chf.spans[queue[q + 2]];
                    for (int dir = 0; dir < 4; ++dir) {
                        if (rcGetCon(cs, dir) == RC_NOT_CONNECTED) continue;
                        const int ax = queue[q] + rcGetDirOffsetX(dir), az = queue[q + 1] + rcGetDirOffsetY(dir);
                        if (ax < x0 || ax >= x1 || az < z0 || az >= z1) continue;
                        const int as = static_cast<int>(column(ax, az).index) + rcGetCon(cs, dir);
                        if (chf.spans[as].reg != reg || piece[as] >= 0) continue;
                        piece[as] = pieces;
                        spans.push_back(as);
                        queue.insert(queue.end(), {ax, az, as});
                    }
                }
                ++pieces;
            }
        }
    std::vector<int> hidden;
    if (pieces > 1) {
        std::vector<char> own(pieces, 0), far(pieces, 0);
        for (int k = 0; k < n; ++k) {
            const unsigned short* v = &pm.verts[p[k] * 3];
            for (int z = v[2] - 1 + bs; z <= v[2] + bs; ++z)
                for (int x = v[0] - 1 + bs; x <= v[0] + bs; ++x) {
                    if (x < x0 || x >= x1 || z < z0 || z >= z1) continue;
                    const rcCompactCell& cell = column(x, z);
                    for (int s = static_cast<int>(cell.index); s < static_cast<int>(cell.index + cell.count); ++s)
                        if (piece[s] >= 0 && std::abs(static_cast<int>(chf.spans[s].y) - v[1]) <= c.walkableClimb)
                            own[piece[s]] = 1;
                }
        }
        for (int z = z0; z < z1; ++z)
            for (int x = x0; x < x1; ++x) {
                const double at = plane[0] * (x - bs + 0.5) + plane[1] * (z - bs + 0.5) + plane[2];
                const rcCompactCell& cell = column(x, z);
                for (int s = static_cast<int>(cell.index); s < static_cast<int>(cell.index + cell.count); ++s)
                    if (piece[s] >= 0 && std::fabs(chf.spans[s].y - at) > c.walkableHeight) far[piece[s]] = 1;
            }
        if (std::find(own.begin(), own.end(), 1) != own.end())
            for (int s : spans)
                if (!own[piece[s]] && far[piece[s]]) hidden.push_back(s);
    }
    for (int s : spans) piece[s] = -1;
    return hidden;
}

// Replaces the detail of polygons `changed` (ascending) in `dmesh` by `redone` (one single-polygon
// detail each): every polygon's detail in order, the changed ones from their rebuild.
void splice_detail(const rcPolyMesh& pm, std::unique_ptr<rcPolyMeshDetail, DetailDel>& dmesh,
                   const std::vector<int32_t>& changed,
                   const std::vector<std::unique_ptr<rcPolyMeshDetail, DetailDel>>& redone) {
    if (changed.empty()) return;
    const rcPolyMeshDetail& dm = *dmesh;
    std::unique_ptr<rcPolyMeshDetail, DetailDel> spliced(rcAllocPolyMeshDetail());
    if (!spliced) fail("rcAllocPolyMeshDetail failed (out of memory)");
    auto source = [&](int i, unsigned int& mesh_index) -> const rcPolyMeshDetail& {
        const auto it = std::lower_bound(changed.begin(), changed.end(), i);
        if (it != changed.end() && *it == i) {
            mesh_index = 0;
            return *redone[static_cast<size_t>(it - changed.begin())];
        }
        mesh_index = static_cast<unsigned int>(i);
        return dm;
    };
    int nverts = 0, ntris = 0;
    for (int i = 0; i < pm.npolys; ++i) {
        unsigned int k;
        const rcPolyMeshDetail& from = source(i, k);
        nverts += static_cast<int>(from.meshes[k * 4 + 1]);
        ntris += static_cast<int>(from.meshes[k * 4 + 3]);
    }
    spliced->meshes = static_cast<unsigned int*>(rcAlloc(sizeof(unsigned int) * 4 * pm.npolys, RC_ALLOC_PERM));
    spliced->verts = static_cast<float*>(rcAlloc(sizeof(float) * 3 * std::max(nverts, 1), RC_ALLOC_PERM));
    spliced->tris = static_cast<unsigned char*>(rcAlloc(4 * std::max(ntris, 1), RC_ALLOC_PERM));
    if (!spliced->meshes || !spliced->verts || !spliced->tris) fail("rcAlloc failed (out of memory)");
    spliced->nmeshes = pm.npolys;
    for (int i = 0; i < pm.npolys; ++i) {
        unsigned int k;
        const rcPolyMeshDetail& from = source(i, k);
        const unsigned int* mesh = &from.meshes[k * 4];
        unsigned int* to = &spliced->meshes[i * 4];
        to[0] = static_cast<unsigned int>(spliced->nverts);
        to[1] = mesh[1];
        to[2] = static_cast<unsigned int>(spliced->ntris);
        to[3] = mesh[3];
        std::copy(from.verts + mesh[0] * 3, from.verts + (mesh[0] + mesh[1]) * 3, spliced->verts + spliced->nverts * 3);
        std::copy(from.tris + mesh[2] * 4, from.tris + (mesh[2] + mesh[3]) * 4, spliced->tris + spliced->ntris * 4);
        spliced->nverts += static_cast<int>(mesh[1]);
        spliced->ntris += static_cast<int>(mesh[3]);
    }
    dmesh = std::move(spliced);
}

// Rebuilds the detail of each polygon that Recast lifted or sank to another storey: a detail vertex
// more than the agent's height from the plane through the polygon's vertices, where the polygon's
// box holds its region on another storey (other_storey_spans); the rebuild hides those spans and
// replaces the polygon's detail in `dmesh` if it then stays within that height of the plane.
// Returns the polygons replaced (local indices, ascending); the others keep Recast's detail exactly.
std::vector<int32_t> redo_detail_off_storey(LogContext& ctx, const rcPolyMesh& pm, rcCompactHeightfield& chf,
                                            const rcConfig& c, std::unique_ptr<rcPolyMeshDetail, DetailDel>& dmesh,
                                            const std::function<void(const std::string&)>& too_big) {
    const rcPolyMeshDetail& dm = *dmesh;
    std::vector<int> piece(static_cast<size_t>(chf.spanCount), -1);
    std::vector<int32_t> changed;
    std::vector<std::unique_ptr<rcPolyMeshDetail, DetailDel>> redone;
    for (int i = 0; i < pm.npolys; ++i) {
        const std::array<double, 3> plane = vertex_plane(pm, i);
        if (!detail_leaves_plane(pm, dm, i, plane, c.walkableHeight)) continue;
        const std::vector<int> hidden = other_storey_spans(pm, i, plane, chf, c, piece);
        if (hidden.empty()) continue;
        std::vector<unsigned short> regs;
        for (int s : hidden) {
            regs.push_back(chf.spans[s].reg);
            chf.spans[s].reg = 0;
        }
        std::unique_ptr<rcPolyMeshDetail, DetailDel> one(rcAllocPolyMeshDetail());
        if (!one) fail("rcAllocPolyMeshDetail failed (out of memory)");
        const bool ok = polygon_detail(ctx, pm, i, chf, c, *one);
        for (size_t k = 0; k < hidden.size(); ++k) chf.spans[hidden[k]].reg = regs[k];
        if (!ok) too_big("rcBuildPolyMeshDetail failed");
        if (detail_leaves_plane(pm, *one, 0, plane, c.walkableHeight)) continue;
        changed.push_back(i);
        redone.push_back(std::move(one));
    }
    splice_detail(pm, dmesh, changed, redone);
    return changed;
}

// ---------------------------------------------------------------- detail chords off the floor

// Recast triangulates each polygon's detail from samples on its edges and, every detailSampleDist,
// inside it, and checks its triangles against the inside samples only. Those must lie half the
// spacing inside the edges, so a polygon narrower than about detailSampleDist gets none; where such
// a polygon bends (a long thin polygon along the foot or the crest of a ramp), its triangles join
// edge samples far apart across the bend and their insides pass over the trough or under the crest,
// and nothing checks them.

// Detail vertex k of `dm` in `chf`'s grid: (x, y, z) in columns and cell heights, y one cell height down (Recast puts
// a detail vertex one cell height up).
std::array<double, 3> detail_vertex_cells(const rcPolyMeshDetail& dm, unsigned int k, const rcCompactHeightfield& chf) {
    const float* v = &dm.verts[k * 3];
    return {(v[0] - chf.bmin[0]) / chf.cs, (v[1] - chf.bmin[1]) / chf.ch - 1.0, (v[2] - chf.bmin[2]) / chf.cs};
}

// The largest distance (cell heights) of polygon `i`'s detail (mesh `mesh` of `dm`) from the floor
// under it: at points of each detail triangle (along its edges half a column apart, and over the
// centre of each column inside it), the triangle's height against the span of the polygon's region
// (of any walkable region for a polygon of several) in that point's column nearest `plane` (the
// polygon's storey, vertex_plane: not the region's turn above on a spiral stair); 0 if none has one.
double detail_floor_gap(const rcPolyMesh& pm, const rcPolyMeshDetail& dm, int mesh, int i,
                        const std::array<double, 3>& plane, const rcCompactHeightfield& chf) {
    const unsigned short reg = pm.regs[i];
    double worst = 0.0;
    // The floor gap at plan point (px, pz) (columns) of height h (cell heights).
    auto probe = [&](double px, double pz, double h) {
        const int cx = static_cast<int>(std::floor(px)), cz = static_cast<int>(std::floor(pz));
        if (cx < 0 || cz < 0 || cx >= chf.width || cz >= chf.height) return;
        const rcCompactCell& cell = chf.cells[cx + cz * chf.width];
        const double storey = plane[0] * (px - pm.borderSize) + plane[1] * (pz - pm.borderSize) + plane[2];
        int floor = -1;
        for (int s = static_cast<int>(cell.index); s < static_cast<int>(cell.index + cell.count); ++s) {
            if (chf.areas[s] == RC_NULL_AREA || (reg != RC_MULTIPLE_REGS && chf.spans[s].reg != reg)) continue;
            if (floor < 0 || std::fabs(chf.spans[s].y - storey) < std::fabs(chf.spans[floor].y - storey)) floor = s;
        }
        if (floor >= 0) worst = std::max(worst, std::fabs(h - chf.spans[floor].y));
    };
    const unsigned int vb = dm.meshes[mesh * 4 + 0], tb = dm.meshes[mesh * 4 + 2], nt = dm.meshes[mesh * 4 + 3];
    for (unsigned int t = tb; t < tb + nt; ++t) {
        double x[3], z[3], y[3];  // columns and cell heights
        for (int k = 0; k < 3; ++k) {
            const std::array<double, 3> cells = detail_vertex_cells(dm, vb + dm.tris[t * 4 + k], chf);
            x[k] = cells[0];
            y[k] = cells[1];
            z[k] = cells[2];
        }
        // Along the edges, half a column apart (a sliver may cover no column's centre) ...
        for (int k = 0; k < 3; ++k) {
            const int l = (k + 1) % 3;
            const int steps = 1 + static_cast<int>(2.0 * std::hypot(x[l] - x[k], z[l] - z[k]));
            for (int q = 0; q <= steps; ++q) {
                const double f = static_cast<double>(q) / steps;
                probe(x[k] + f * (x[l] - x[k]), z[k] + f * (z[l] - z[k]), y[k] + f * (y[l] - y[k]));
            }
        }
        // ... and at the centre of each column inside.
        const double det = (x[1] - x[0]) * (z[2] - z[0]) - (x[2] - x[0]) * (z[1] - z[0]);
        if (std::fabs(det) < 1e-12) continue;
        const int x0 = static_cast<int>(std::floor(std::min({x[0], x[1], x[2]})));
        const int x1 = static_cast<int>(std::floor(std::max({x[0], x[1], x[2]})));
        const int z0 = static_cast<int>(std::floor(std::min({z[0], z[1], z[2]})));
        const int z1 = static_cast<int>(std::floor(std::max({z[0], z[1], z[2]})));
        for (int cz = z0; cz <= z1; ++cz)
            for (int cx = x0; cx <= x1; ++cx) {
                const double px = cx + 0.5 - x[0], pz = cz + 0.5 - z[0];
                const double u = (px * (z[2] - z[0]) - (x[2] - x[0]) * pz) / det;
                const double w = ((x[1] - x[0]) * pz - px * (z[1] - z[0])) / det;
                if (u < 0.0 || w < 0.0 || u + w > 1.0) continue;
                probe(cx + 0.5, cz + 0.5, y[0] + u * (y[1] - y[0]) + w * (y[2] - y[0]));
            }
    }
    return worst;
}

// The lowest and highest walkable span (cell heights) of each region of `chf`, by region id up to
// chf.maxRegions ({INT_MAX, INT_MIN}: none). O(spans).
std::vector<std::array<int, 2>> region_floor_ranges(const rcCompactHeightfield& chf) {
    std::vector<std::array<int, 2>> range(static_cast<size_t>(chf.maxRegions) + 1, {INT_MAX, INT_MIN});
    for (int s = 0; s < chf.spanCount; ++s) {
        const unsigned short reg = chf.spans[s].reg;
        if (chf.areas[s] == RC_NULL_AREA || reg > chf.maxRegions) continue;
        range[reg][0] = std::min(range[reg][0], static_cast<int>(chf.spans[s].y));
        range[reg][1] = std::max(range[reg][1], static_cast<int>(chf.spans[s].y));
    }
    return range;
}

// Whether detail_floor_gap(pm, dm, mesh, i, plane, chf) is certainly at most `limit` (whatever the
// plane), read without probing: each height it reads on a triangle is a weighted mean of the
// triangle's corners (to a few ulps), so between the mesh's lowest and highest vertex, and each floor
// it compares one with is a walkable span of the polygon's region (of any walkable region for a
// polygon of several) in a column of the mesh's plan box. No gap then exceeds max(highest vertex -
// lowest span, highest span - lowest vertex) over those spans: first over all the region's spans
// (`ranges`, region_floor_ranges of chf), then over those in the box, taken a column wider each way
// for rounding. O(detail vertices), then O(columns of the box x their spans), against
// detail_floor_gap's probes along and inside every triangle; on the 100k-polygon level the region's
// range answers for all but a few polygons.
bool detail_floor_gap_within(const rcPolyMesh& pm, const rcPolyMeshDetail& dm, int mesh, int i,
                             const rcCompactHeightfield& chf, const std::vector<std::array<int, 2>>& ranges,
                             double limit) {
    const unsigned short reg = pm.regs[i];
    const unsigned int vb = dm.meshes[mesh * 4 + 0], nv = dm.meshes[mesh * 4 + 1];
    if (nv == 0) return true;
    double lo_x = DBL_MAX, hi_x = -DBL_MAX, lo_z = DBL_MAX, hi_z = -DBL_MAX, lo_y = DBL_MAX, hi_y = -DBL_MAX;
    for (unsigned int k = vb; k < vb + nv; ++k) {  // as detail_floor_gap converts them
        const auto [x, y, z] = detail_vertex_cells(dm, k, chf);
        lo_x = std::min(lo_x, x); hi_x = std::max(hi_x, x);
        lo_y = std::min(lo_y, y); hi_y = std::max(hi_y, y);
        lo_z = std::min(lo_z, z); hi_z = std::max(hi_z, z);
    }
    auto within = [&](int lo_floor, int hi_floor) {
        constexpr double rounding = 1e-6;  // far above a few ulps of heights under Recast's 2^13 cell heights
        return lo_floor > hi_floor ||  // no floor: detail_floor_gap is 0
               std::max(hi_y - lo_floor, hi_floor - lo_y) + rounding <= limit;
    };
    if (reg != RC_MULTIPLE_REGS && reg < ranges.size() && within(ranges[reg][0], ranges[reg][1])) return true;
    const int x0 = std::max(0, static_cast<int>(std::floor(lo_x)) - 1);
    const int x1 = std::min(chf.width - 1, static_cast<int>(std::floor(hi_x)) + 1);
    const int z0 = std::max(0, static_cast<int>(std::floor(lo_z)) - 1);
    const int z1 = std::min(chf.height - 1, static_cast<int>(std::floor(hi_z)) + 1);
    int lo_floor = INT_MAX, hi_floor = INT_MIN;
    for (int cz = z0; cz <= z1; ++cz)
        for (int cx = x0; cx <= x1; ++cx) {
            const rcCompactCell& cell = chf.cells[cx + cz * chf.width];
            for (int s = static_cast<int>(cell.index); s < static_cast<int>(cell.index + cell.count); ++s) {
                if (chf.areas[s] == RC_NULL_AREA || (reg != RC_MULTIPLE_REGS && chf.spans[s].reg != reg)) continue;
                lo_floor = std::min(lo_floor, static_cast<int>(chf.spans[s].y));
                hi_floor = std::max(hi_floor, static_cast<int>(chf.spans[s].y));
            }
        }
    return within(lo_floor, hi_floor);
}

// Twice the signed plan area of triangle (a, k, b): positive when counter-clockwise (x right, second
// coordinate up).
template <typename T>
T twice_area(const std::array<T, 2>& a, const std::array<T, 2>& k, const std::array<T, 2>& b) {
    return (k[0] - a[0]) * (b[1] - a[1]) - (b[0] - a[0]) * (k[1] - a[1]);
}

// The triangulation of a convex polygon (`outline`: its plan points in order round it, either way)
// whose diagonals have the least total length: dynamic programming over the chain (minimum weight
// triangulation of a convex polygon; Gilbert 1979, Klincsek 1980), O(n^3) time, O(n^2) memory.
// A triangle whose doubled area is under `flat_area` (collinear points) is never used. Returns the
// n - 2 triangles as outline positions (a, k, b), a < k < b, so wound as the outline is; empty for
// fewer than 3 points or when no triangulation avoids flat triangles. T (float or double) is the
// precision of the areas and lengths.
template <typename T>
std::vector<std::array<int, 3>> least_diagonal_triangulation(const std::vector<std::array<T, 2>>& outline,
                                                              double flat_area) {
    const int n = static_cast<int>(outline.size());
    std::vector<std::array<int, 3>> triangles;
    if (n < 3) return triangles;
    auto plan = [&](int a, int b) {
        return std::hypot(outline[a][0] - outline[b][0], outline[a][1] - outline[b][1]);
    };
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> cost(static_cast<size_t>(n) * n, inf);
    std::vector<int> apex(static_cast<size_t>(n) * n, -1);
    for (int a = 0; a + 1 < n; ++a) cost[a * n + a + 1] = 0.0;
    for (int gap = 2; gap < n; ++gap)
        for (int a = 0; a + gap < n; ++a) {
            const int b = a + gap;
            for (int k = a + 1; k < b; ++k) {
                if (std::fabs(twice_area(outline[a], outline[k], outline[b])) < flat_area) continue;
                const double c = cost[a * n + k] + cost[k * n + b] + (k > a + 1 ? plan(a, k) : 0.0) +
                                 (b > k + 1 ? plan(k, b) : 0.0);
                if (c < cost[a * n + b]) {
                    cost[a * n + b] = c;
                    apex[a * n + b] = k;
                }
            }
        }
    if (cost[n - 1] == inf) return triangles;
    std::vector<std::pair<int, int>> todo = {{0, n - 1}};
    while (!todo.empty()) {
        const auto [a, b] = todo.back();
        todo.pop_back();
        if (b - a < 2) continue;
        const int k = apex[a * n + b];
        triangles.push_back({a, k, b});
        todo.push_back({a, k});
        todo.push_back({k, b});
    }
    return triangles;
}

// The number of vertices of polygon `i` of `pm` (its unused slots hold RC_MESH_NULL_IDX).
int polygon_vertex_count(const rcPolyMesh& pm, int i) {
    const unsigned short* p = &pm.polys[static_cast<size_t>(i) * 2 * pm.nvp];
    int nin = 0;
    while (nin < pm.nvp && p[nin] != RC_MESH_NULL_IDX) ++nin;
    return nin;
}

// How far in plan a detail vertex may lie from a polygon's outline and still count as on it: a thousandth
// of a cell (detail_on_outline, and the same tolerance for shortest_hull_triangulation's collinear samples).
double outline_tolerance(const rcPolyMesh& pm) { return 1e-3 * pm.cs; }

// Whether the `n` detail vertices `v` (x, y, z each; the polygon's own vertices first, as Recast puts them) of
// polygon `i` of `pm` are at least 4 and all lie on its outline (within outline_tolerance in plan): the
// details shortest_hull_triangulation retriangulates. O(n x the polygon's vertices).
bool detail_on_outline(const rcPolyMesh& pm, int i, const float* v, int n) {
    const int nin = polygon_vertex_count(pm, i);
    if (n < 4) return false;
    const double on_outline = outline_tolerance(pm);
    for (int k = nin; k < n; ++k) {
        bool on_edge = false;
        for (int a = 0, b = nin - 1; a < nin && !on_edge; b = a++) {
            const double ex = v[a * 3] - v[b * 3], ez = v[a * 3 + 2] - v[b * 3 + 2];
            const double len = std::hypot(ex, ez);
            const double across = ((v[k * 3] - v[b * 3]) * ez - (v[k * 3 + 2] - v[b * 3 + 2]) * ex) / len;
            const double along = ((v[k * 3] - v[b * 3]) * ex + (v[k * 3 + 2] - v[b * 3 + 2]) * ez) / len;
            on_edge = std::fabs(across) <= on_outline && along >= -on_outline && along <= len + on_outline;
        }
        if (!on_edge) return false;
    }
    return true;
}

// Recast triangulates a polygon that gets no inside samples with triangulateHull, which walks round
// the hull greedily and, on a long sliver, fans out from one hull sample: the fan's inner edges run
// along the polygon, over its bends. This retriangulates the detail `one` (polygon `i` of `pm` alone)
// when every vertex of it lies on the polygon's outline: the samples in order round the convex polygon,
// joined by least_diagonal_triangulation (Recast's n <= 127 samples), whose diagonals cross the sliver
// instead. Returns false, leaving `one` as it was, if a vertex lies inside or no such triangulation exists.
bool shortest_hull_triangulation(const rcPolyMesh& pm, int i, rcPolyMeshDetail& one) {
    const int nin = polygon_vertex_count(pm, i);
    const int n = static_cast<int>(one.meshes[1]);
    const float* v = one.verts;  // Recast puts the polygon's own vertices first
    if (one.meshes[0] != 0 || !detail_on_outline(pm, i, v, n)) return false;
    double cx = 0.0, cz = 0.0;
    for (int k = 0; k < nin; ++k) {
        cx += v[k * 3] / nin;
        cz += v[k * 3 + 2] / nin;
    }
    const double on_outline = outline_tolerance(pm);
    std::vector<int> hull(n);
    std::vector<double> angle(n);
    for (int k = 0; k < n; ++k) {
        hull[k] = k;
        angle[k] = std::atan2(v[k * 3 + 2] - cz, v[k * 3] - cx);
    }
    std::sort(hull.begin(), hull.end(), [&](int a, int b) { return angle[a] < angle[b]; });
    std::vector<std::array<float, 2>> outline(n);
    for (int k = 0; k < n; ++k) outline[k] = {v[hull[k] * 3], v[hull[k] * 3 + 2]};
    const std::vector<std::array<int, 3>> triangles = least_diagonal_triangulation(outline, on_outline * on_outline);
    if (triangles.empty()) return false;
    // Recast's winding (its first triangle's), and its edge flags: 1 for an edge on the outline.
    const unsigned char* t0 = one.tris;
    const float *a0 = &v[t0[0] * 3], *b0 = &v[t0[1] * 3], *c0 = &v[t0[2] * 3];
    const bool clockwise = (b0[0] - a0[0]) * (c0[2] - a0[2]) - (c0[0] - a0[0]) * (b0[2] - a0[2]) < 0;
    unsigned char* tris = static_cast<unsigned char*>(rcAlloc(4 * (n - 2), RC_ALLOC_PERM));
    if (!tris) fail("rcAlloc failed (out of memory)");
    int ntris = 0;
    for (std::array<int, 3> corner : triangles) {
        if ((twice_area(outline[corner[0]], outline[corner[1]], outline[corner[2]]) < 0) != clockwise)
            std::swap(corner[1], corner[2]);
        unsigned char* t = &tris[ntris++ * 4];
        t[3] = 0;
        for (int e = 0; e < 3; ++e) {
            t[e] = static_cast<unsigned char>(hull[corner[e]]);
            const int d = std::abs(corner[e] - corner[(e + 1) % 3]);
            if (d == 1 || d == n - 1) t[3] |= static_cast<unsigned char>(1 << (2 * e));
        }
    }
    rcFree(one.tris);
    one.tris = tris;
    one.ntris = ntris;
    one.meshes[3] = static_cast<unsigned int>(ntris);
    return true;
}

// Most vertices Recast's detail gives one polygon (MAX_VERTS of buildPolyDetail, RecastMeshDetail.cpp).
constexpr unsigned int RECAST_DETAIL_MAX_VERTS = 127;

// Rebuilds the detail of each polygon whose detail leaves the floor under it by more than the
// agent's climb (detail_floor_gap): rcBuildPolyMeshDetail on the polygon alone, retriangulated by
// shortest_hull_triangulation if all its samples lie on the outline (at Recast's spacing only then: otherwise
// the rebuild would be Recast's detail again); again with detailSampleDist and
// detailSampleMaxError halved while the result is still off, the spacing stays at least one cell and
// the last detail (Recast's, then each rebuild) has fewer than RECAST_DETAIL_MAX_VERTS vertices: a full
// detail cannot take more vertices from finer samples, and Recast scans every sample for each vertex
// it adds, so each halving would cost four times the last for little (large bent polygons, as where the
// ledge filter no longer cuts a valley from its slopes: the slopes level 2.6 -> 0.8 s of CPU,
// docs/navmesh.md "A ledge filter of our own").
// It keeps the rebuild nearest the floor if that is nearer than Recast's and no vertex of it lies
// further from the plane through the polygon's vertices than the agent's height or Recast's farthest
// (finer samples on a spiral stair can read the region's turn below where the turn above is another
// region's). Polygons in `skip`
// (ascending; rebuilt from their own storey already) keep their detail. Returns the polygons
// replaced (ascending); the others keep their detail exactly. Nothing to do without detail samples.
std::vector<int32_t> resample_detail_off_floor(LogContext& ctx, const rcPolyMesh& pm, const rcCompactHeightfield& chf,
                                               const rcConfig& c, std::unique_ptr<rcPolyMeshDetail, DetailDel>& dmesh,
                                               const std::vector<int32_t>& skip,
                                               const std::function<void(const std::string&)>& too_big) {
    std::vector<int32_t> changed;
    std::vector<std::unique_ptr<rcPolyMeshDetail, DetailDel>> redone;
    if (c.detailSampleDist <= 0.0f) return changed;
    const std::vector<std::array<int, 2>> ranges = region_floor_ranges(chf);
    for (int i = 0; i < pm.npolys; ++i) {
        if (std::binary_search(skip.begin(), skip.end(), i)) continue;
        if (detail_floor_gap_within(pm, *dmesh, i, i, chf, ranges, c.walkableClimb)) continue;  // gap <= climb: kept
        const std::array<double, 3> plane = vertex_plane(pm, i);
        double gap = detail_floor_gap(pm, *dmesh, i, i, plane, chf);
        const double bend = std::max<double>(c.walkableHeight, detail_plane_offset(pm, *dmesh, i, plane));
        std::unique_ptr<rcPolyMeshDetail, DetailDel> best;
        rcConfig fine = c;
        const unsigned int* recast = &dmesh->meshes[static_cast<size_t>(i) * 4];
        bool full = recast[1] >= RECAST_DETAIL_MAX_VERTS;
        // At Recast's own spacing the rebuild is Recast's detail again (rcBuildPolyMeshDetail details each
        // polygon on its own), so only shortest_hull_triangulation could change it: start at half the
        // spacing when it would not.
        if (!detail_on_outline(pm, i, &dmesh->verts[static_cast<size_t>(recast[0]) * 3], static_cast<int>(recast[1]))) {
            fine.detailSampleDist /= 2;
            fine.detailSampleMaxError /= 2;
        }
        for (; gap > c.walkableClimb && !full && fine.detailSampleDist >= c.cs;
             fine.detailSampleDist /= 2, fine.detailSampleMaxError /= 2) {
            std::unique_ptr<rcPolyMeshDetail, DetailDel> one(rcAllocPolyMeshDetail());
            if (!one) fail("rcAllocPolyMeshDetail failed (out of memory)");
            if (!polygon_detail(ctx, pm, i, chf, fine, *one)) too_big("rcBuildPolyMeshDetail failed");
            full = static_cast<unsigned int>(one->nverts) >= RECAST_DETAIL_MAX_VERTS;
            shortest_hull_triangulation(pm, i, *one);
            const double rebuilt = detail_floor_gap(pm, *one, 0, i, plane, chf);
            if (rebuilt < gap && detail_plane_offset(pm, *one, 0, plane) <= bend) {
                gap = rebuilt;
                best = std::move(one);
            }
        }
        if (!best) continue;
        changed.push_back(i);
        redone.push_back(std::move(best));
    }
    splice_detail(pm, dmesh, changed, redone);
    return changed;
}

// The ledge filter's first rule without its second. Recast's rcFilterLedgeSpans (RecastFilter.cpp, Recast
// Navigation 1.5.1) marks a walkable span unwalkable (1) when the agent, standing on it, could step into a
// neighbouring column and find the floor there more than walkableClimb below its own, or no floor at all (open
// space below the column's first span, or beyond the grid), and (2) when the floors within walkableClimb of it in
// its four neighbours differ among themselves by more than walkableClimb. This is rule 1 alone. It keeps erosion's
// radius honest at a drop: rasterisation takes the cell a drop's edge crosses as floor, so without it erosion
// counts the radius from that cell's far side, up to a cell too close to the drop (docs/navmesh.md). Rule 2 is
// left out because it cuts what the agent may walk: a stair tread between two risers within the climb, and every
// slope whose rise across two cells exceeds the climb (36.9 degrees on the presets' 0.25 / 0.125 m grid, under
// their max_slope of 45); the agent's own limits are kept without it, the slope by rcMarkWalkableTriangles and the
// step by rcBuildCompactHeightfield, which links two spans only when their floors differ by at most
// walkableClimb. A neighbouring gap counts when the agent fits through it: the overlap of the span's free space
// (its top to the next span's bottom) and the gap is more than walkableHeight, as in Recast. Only floors below the
// span matter, and neighbours are read by shape only (their areas are not read), so the order of the spans does
// not change the result. O(spans x the spans of the four neighbouring columns up to the first floor within the
// climb of the span's own).
void drop_ledge_spans(int walkable_height, int walkable_climb, rcHeightfield& hf) {
    constexpr int open_top = std::numeric_limits<int>::max();  // free space above a column's last span
    const int w = hf.width, h = hf.height;
    // Whether a neighbour's column (nx, nz) holds a gap the agent fits into from free space [floor, ceiling)
    // whose floor is more than walkable_climb below `floor` or missing.
    auto drop_beside = [&](int floor, int ceiling, int nx, int nz) {
        if (nx < 0 || nz < 0 || nx >= w || nz >= h) return true;
        const rcSpan* below = nullptr;  // the span whose top is the gap's floor; none under the first span
        for (const rcSpan* above = hf.spans[nx + nz * w];; above = above->next) {
            const int gap_floor = below ? static_cast<int>(below->smax) : floor;  // no floor: only ours bounds it
            const int gap_ceiling = above ? static_cast<int>(above->smin) : open_top;
            const bool fits = std::min(ceiling, gap_ceiling) - std::max(floor, gap_floor) > walkable_height;
            if (fits && (!below || gap_floor < floor - walkable_climb)) return true;
            // a column's spans rise one above the other, so once a gap's floor is within the climb of ours every
            // gap above it is too: none of them is a drop, and the spans above (a ceiling, a storey) are not read
            if (!above || static_cast<int>(above->smax) >= floor - walkable_climb) return false;
            below = above;
        }
    };
    for (int z = 0; z < h; ++z)
        for (int x = 0; x < w; ++x)
            for (rcSpan* s = hf.spans[x + z * w]; s; s = s->next) {
                if (s->area == RC_NULL_AREA) continue;
                const int floor = static_cast<int>(s->smax);
                const int ceiling = s->next ? static_cast<int>(s->next->smin) : open_top;
                for (int dir = 0; dir < 4; ++dir)
                    if (drop_beside(floor, ceiling, x + rcGetDirOffsetX(dir), z + rcGetDirOffsetY(dir))) {
                        s->area = RC_NULL_AREA;
                        break;
                    }
            }
}

// A span of a compact heightfield and its cell (x, z); span -1: none.
struct At { int span, x, z; };

// The floor before Recast's erosion (`before`) and after it (chf.areas), as join_corners and join_clear_runs walk it.
// Always inlined: the module builds at -Os (nanobind's default), where these small calls stay calls and `across`
// hands its At back through the stack, a stalled load at every return; inlined, the clear runs' pass takes half the
// CPU on the 100k dungeon (docs/navmesh.md, "Doors at an angle to the grid").
struct ErodedFloor {
    const rcCompactHeightfield& chf;
    const std::vector<unsigned char>& before;

    // The span across side `dir` of a, or span -1.
    __attribute__((always_inline)) At across(const At& a, int dir) const {
        const int x = a.x + rcGetDirOffsetX(dir), z = a.z + rcGetDirOffsetY(dir);
        if (a.span < 0 || rcGetCon(chf.spans[a.span], dir) == RC_NOT_CONNECTED) return At{-1, x, z};
        return At{static_cast<int>(chf.cells[x + z * chf.width].index) + rcGetCon(chf.spans[a.span], dir), x, z};
    }
    __attribute__((always_inline)) bool kept(const At& a) const {
        return a.span >= 0 && chf.areas[a.span] != RC_NULL_AREA;
    }
    __attribute__((always_inline)) bool was_floor(const At& a) const {
        return a.span >= 0 && before[a.span] != RC_NULL_AREA;
    }
    __attribute__((always_inline)) bool eroded(const At& a) const {
        return was_floor(a) && chf.areas[a.span] == RC_NULL_AREA;
    }
};

// Triangles binned on a grid of nx x nz squares as a CSR list: square b (x + z * nx) holds
// members[start[b] .. start[b + 1]), by ascending triangle. `squares(t)` gives triangle t's squares as
// {x0, x1, z0, z1}, inclusive and within the grid. Two passes over the triangles.
struct TriangleBins {
    std::vector<size_t> start;
    std::vector<int> members;
};

template <class Squares> TriangleBins bin_triangles(int ntris, int nx, int nz, Squares&& squares) {
    TriangleBins bins{std::vector<size_t>(static_cast<size_t>(nx) * nz + 1, 0), {}};
    std::vector<std::array<int, 4>> range(static_cast<size_t>(ntris));
    for (int t = 0; t < ntris; ++t) {
        range[t] = squares(t);
        for (int z = range[t][2]; z <= range[t][3]; ++z)
            for (int x = range[t][0]; x <= range[t][1]; ++x) ++bins.start[static_cast<size_t>(z) * nx + x + 1];
    }
    for (size_t b = 1; b < bins.start.size(); ++b) bins.start[b] += bins.start[b - 1];
    bins.members.resize(bins.start.back());
    std::vector<size_t> fill(bins.start.begin(), bins.start.end() - 1);
    for (int t = 0; t < ntris; ++t)
        for (int z = range[t][2]; z <= range[t][3]; ++z)
            for (int x = range[t][0]; x <= range[t][1]; ++x) bins.members[fill[static_cast<size_t>(z) * nx + x]++] = t;
    return bins;
}

// The triangles that stand in an agent's way on a floor: those with a part between the floor's top plus the agent's
// climb and its top plus its height, clipped to that band and seen from above (x, z). Binned in squares of BIN cells
// of the compact heightfield's grid, so a question near a span reads only the triangles near it.
class PlanObstacles {
public:
    static constexpr int BIN = 8;
    PlanObstacles(const rcCompactHeightfield& chf, const float* verts, const int* tris, int ntris)
        : chf_(chf), verts_(verts), tris_(tris), bw_((chf.width + BIN - 1) / BIN), bh_((chf.height + BIN - 1) / BIN),
          bins_(bin_triangles(ntris, bw_, bh_, [&](int t) {
              float lo[2] = {FLT_MAX, FLT_MAX}, hi[2] = {-FLT_MAX, -FLT_MAX};
              for (int k = 0; k < 3; ++k)
                  for (int a = 0; a < 2; ++a) {
                      const float v = verts_[tris_[t * 3 + k] * 3 + 2 * a];
                      lo[a] = std::min(lo[a], v);
                      hi[a] = std::max(hi[a], v);
                  }
              return std::array<int, 4>{std::max(0, bin(lo[0], 0)), std::min(bw_ - 1, bin(hi[0], 0)),
                                        std::max(0, bin(lo[1], 2)), std::min(bh_ - 1, bin(hi[1], 2))};
          })) {}

    // Whether no obstacle of a floor at height y comes within `rho` of the plan point (px, pz).
    bool clear_of(double px, double pz, double y, double climb, double height, double rho) const {
        bool clear = true;
        each_near(px - rho, px + rho, pz - rho, pz + rho, y + climb, y + height, [&](const Poly& p) {
            if (clear && distance(p, px, pz) < rho) clear = false;
        });
        return clear;
    }

    // Whether an obstacle of a floor at height y overlaps the plan square [x0, x1] x [z0, z1] (more than touches it).
    bool in_square(double x0, double x1, double z0, double z1, double y, double climb, double height) const {
        bool found = false;
        each_near(x0, x1, z0, z1, y + climb, y + height, [&](const Poly& p) {
            if (!found && overlaps(p, x0, x1, z0, z1)) found = true;
        });
        return found;
    }

private:
    struct Poly { double x[5], z[5]; int n; };
    int bin(float v, int axis) const { return static_cast<int>(std::floor((v - chf_.bmin[axis]) / (chf_.cs * BIN))); }

    // Calls f with the plan shape of each triangle near [x0, x1] x [z0, z1] clipped to lo < y < hi (a triangle in two
    // bins may come twice).
    template <class F> void each_near(double x0, double x1, double z0, double z1, double lo, double hi, F&& f) const {
        const int bx0 = std::max(0, bin(static_cast<float>(x0), 0)), bx1 = std::min(bw_ - 1, bin(static_cast<float>(x1), 0));
        const int bz0 = std::max(0, bin(static_cast<float>(z0), 2)), bz1 = std::min(bh_ - 1, bin(static_cast<float>(z1), 2));
        for (int bz = bz0; bz <= bz1; ++bz)
            for (int bx = bx0; bx <= bx1; ++bx)
                for (size_t k = bins_.start[bx + bz * bw_]; k < bins_.start[bx + bz * bw_ + 1]; ++k) {
                    Poly p;
                    if (clip(bins_.members[k], lo, hi, p)) f(p);
                }
    }

    // The plan shape of triangle t's part with lo < y < hi; false when it has none.
    bool clip(int t, double lo, double hi, Poly& out) const {
        double a[5][3], b[5][3];
        int n = 3;
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) a[k][c] = verts_[tris_[t * 3 + k] * 3 + c];
        auto cut = [&](double (*in)[3], int m, double (*res)[3], double level, double sign) {
            int r = 0;
            for (int k = 0; k < m; ++k) {
                const double* p = in[k];
                const double* q = in[(k + 1) % m];
                const double dp = sign * (p[1] - level), dq = sign * (q[1] - level);
                if (dp >= 0) std::copy(p, p + 3, res[r++]);
                if ((dp >= 0) != (dq >= 0)) {
                    const double s = dp / (dp - dq);
                    for (int c = 0; c < 3; ++c) res[r][c] = p[c] + s * (q[c] - p[c]);
                    ++r;
                }
            }
            return r;
        };
        double ymin = std::min({a[0][1], a[1][1], a[2][1]}), ymax = std::max({a[0][1], a[1][1], a[2][1]});
        if (ymax <= lo || ymin >= hi) return false;
        n = cut(a, n, b, lo, 1.0);
        if (n < 2) return false;
        n = cut(b, n, a, hi, -1.0);
        if (n < 2) return false;
        out.n = std::min(n, 5);
        for (int k = 0; k < out.n; ++k) { out.x[k] = a[k][0]; out.z[k] = a[k][2]; }
        return true;
    }

    // Plan distance from (px, pz) to a convex shape (a segment when its corners lie on a line); 0 inside.
    static double distance(const Poly& p, double px, double pz) {
        double best = DBL_MAX, area = 0.0;
        bool pos = false, neg = false;
        for (int k = 0; k < p.n; ++k) {
            const int l = (k + 1) % p.n;
            const double ex = p.x[l] - p.x[k], ez = p.z[l] - p.z[k], len2 = ex * ex + ez * ez;
            const double s = len2 > 0 ? std::clamp(((px - p.x[k]) * ex + (pz - p.z[k]) * ez) / len2, 0.0, 1.0) : 0.0;
            best = std::min(best, std::hypot(px - p.x[k] - s * ex, pz - p.z[k] - s * ez));
            const double cross = ex * (pz - p.z[k]) - ez * (px - p.x[k]);
            pos = pos || cross > 0;
            neg = neg || cross < 0;
            area += p.x[k] * p.z[l] - p.x[l] * p.z[k];
        }
        return std::abs(area) > 1e-12 && !(pos && neg) ? 0.0 : best;
    }

    // Whether a convex shape and the square overlap by more than a touch: no separating axis among the square's
    // two and the shape's edge normals.
    static bool overlaps(const Poly& p, double x0, double x1, double z0, double z1) {
        constexpr double eps = 1e-6;
        auto apart = [&](double nx, double nz) {
            double plo = DBL_MAX, phi = -DBL_MAX, slo = DBL_MAX, shi = -DBL_MAX;
            for (int k = 0; k < p.n; ++k) {
                const double v = nx * p.x[k] + nz * p.z[k];
                plo = std::min(plo, v);
                phi = std::max(phi, v);
            }
            for (double x : {x0, x1})
                for (double z : {z0, z1}) {
                    const double v = nx * x + nz * z;
                    slo = std::min(slo, v);
                    shi = std::max(shi, v);
                }
            const double len = std::hypot(nx, nz);
            return phi <= slo + eps * len || shi <= plo + eps * len;
        };
        if (apart(1, 0) || apart(0, 1)) return false;
        for (int k = 0; k < p.n; ++k) {
            const int l = (k + 1) % p.n;
            const double ex = p.x[l] - p.x[k], ez = p.z[l] - p.z[k];
            if ((ex != 0 || ez != 0) && apart(-ez, ex)) return false;
        }
        return true;
    }

    const rcCompactHeightfield& chf_;
    const float* verts_;
    const int* tris_;
    int bw_, bh_;
    TriangleBins bins_;
};

// Where the floor a door or a gap leaves an agent is a cell or two wide and at an angle to the grid, Recast's erosion
// closes it although the agent passes: the cells a jamb's face crosses hold no floor, so the erosion counts the
// radius from up to a cell's diagonal nearer than the jamb itself (docs/navmesh.md, "Doors at an angle to the
// grid"). No rule on the cells alone tells such a cell from one a jamb really stands in (a distance to the cells
// without floor, however exact, closed all 19 doors traced there), so this reads the level's triangles: a floor span
// Recast eroded is clear when no obstacle (a triangle's part between its floor plus the agent's climb and its floor
// plus its height, seen from above) comes within rho = sqrt(radius^2 + (cs / 2)^2) of its centre, and every cell
// without floor within rho of its centre, along its floor's links, holds such an obstacle (a drop's edge is none:
// there Recast's count stands). Any point of a side step between two clear spans then stands at least the radius
// from every obstacle (the worst case, a jamb's corner half-way along the step), and so does a span Recast kept, so
// no gap narrower than the agent opens. A run of clear spans is put back when it joins two spans Recast kept along
// x, z or a diagonal (each diagonal step through a clear or kept side neighbour), at most `reach` spans long, and
// those two are not already joined by kept floor within a cell of the box round them: the floor across a door or a
// break in a corridor, not the strip along a wall nor the corner of a corridor's mouth. Reads only the state before
// the erosion and after Recast's, so the order of the spans does not count; spans within walkableRadius + 1 cells
// of the grid's edge, where a tile's erosion differs from a solo build's, are never clear. Appends to `back`.
// O(spans): a pass over the eroded floor, 8 lookups each; the triangles are read only for a run's spans.
void join_clear_runs(const rcCompactHeightfield& chf, const std::vector<unsigned char>& before, const float* verts,
                     const int* tris, int ntris, double radius, double climb, double height, int walkable_radius,
                     int reach, std::vector<int>& back) {
    const ErodedFloor floor{chf, before};
    const int w = chf.width;
    const double cs = chf.cs, rho = std::sqrt(radius * radius + cs * cs / 4.0);
    const int margin = walkable_radius + 1;

    std::optional<PlanObstacles> obstacles;  // built at the first span asked about
    std::vector<signed char> clear(static_cast<size_t>(chf.spanCount), -1);  // -1: not asked yet
    std::vector<At> seen;
    auto is_clear = [&](const At& m) {
        if (clear[m.span] >= 0) return clear[m.span] == 1;
        bool ok = m.x >= margin && m.z >= margin && m.x < w - margin && m.z < chf.height - margin;
        const double px = chf.bmin[0] + (m.x + 0.5) * cs, pz = chf.bmin[2] + (m.z + 0.5) * cs;
        const double y = chf.bmin[1] + chf.spans[m.span].y * static_cast<double>(chf.ch);
        auto near = [&](int x, int z) {  // whether cell (x, z)'s square comes within rho of the span's centre
            const double dx = std::max(std::abs(x - m.x) - 0.5, 0.0), dz = std::max(std::abs(z - m.z) - 0.5, 0.0);
            return std::hypot(dx, dz) * cs < rho;
        };
        if (ok) {
            if (!obstacles) obstacles.emplace(chf, verts, tris, ntris);
            ok = obstacles->clear_of(px, pz, y, climb, height, rho);
        }
        seen.assign(1, m);  // the floor within rho, along its links: every cell without floor beside it needs an obstacle
        for (size_t q = 0; ok && q < seen.size(); ++q)
            for (int dir = 0; ok && dir < 4; ++dir) {
                const At b = floor.across(seen[q], dir);
                if (!near(b.x, b.z)) continue;
                if (!floor.was_floor(b)) {
                    const double x0 = chf.bmin[0] + b.x * cs, z0 = chf.bmin[2] + b.z * cs;
                    ok = obstacles->in_square(x0, x0 + cs, z0, z0 + cs, y, climb, height);
                } else if (std::none_of(seen.begin(), seen.end(), [&](const At& c) { return c.span == b.span; })) {
                    seen.push_back(b);
                }
            }
        clear[m.span] = ok ? 1 : 0;
        return ok;
    };

    // Whether kept spans a and b are joined by kept floor within a cell of the box round them.
    std::vector<char> visited(static_cast<size_t>(chf.spanCount), 0);
    std::vector<At> queue;
    auto joined_nearby = [&](const At& a, const At& b) {
        const int x0 = std::min(a.x, b.x) - 1, x1 = std::max(a.x, b.x) + 1;
        const int z0 = std::min(a.z, b.z) - 1, z1 = std::max(a.z, b.z) + 1;
        queue.assign(1, a);
        visited[a.span] = 1;
        bool found = false;
        for (size_t q = 0; q < queue.size() && !found; ++q)
            for (int dir = 0; dir < 4; ++dir) {
                const At c = floor.across(queue[q], dir);
                if (!floor.kept(c) || visited[c.span] || c.x < x0 || c.x > x1 || c.z < z0 || c.z > z1) continue;
                found = found || c.span == b.span;
                visited[c.span] = 1;
                queue.push_back(c);
            }
        for (const At& c : queue) visited[c.span] = 0;
        return found;
    };

    // A run from kept span `start` along x (dir 2), z (dir 1) or a diagonal (x then z, x then -z; a diagonal step
    // passes through a side neighbour, either one, both meeting on one span): first on the cells' state alone (spans
    // eroded from floor, up to `reach` of them, then a kept one), then the clearance of its spans, the triangles read
    // only there (along a wall a run meets the wall, not a kept span).
    constexpr std::array<std::array<int, 2>, 4> STEPS{{{2, -1}, {1, -1}, {2, 1}, {2, 3}}};
    std::vector<unsigned char> walked(static_cast<size_t>(chf.spanCount), 0);  // a bit per step already walked
    std::vector<At> run, sides;  // the run's spans; the diagonal steps' side neighbours that are not kept
    std::vector<size_t> step_sides;  // per diagonal step: where its sides start in `sides`
    auto walk = [&](const At& start, int which) {
        if (!floor.kept(start) || (walked[start.span] >> which & 1)) return;
        walked[start.span] |= static_cast<unsigned char>(1 << which);
        const std::array<int, 2>& step = STEPS[which];
        run.clear();
        sides.clear();
        step_sides.clear();
        At at = start, end{-1, 0, 0};
        for (int k = 0; k <= reach; ++k) {
            At next{-1, 0, 0};
            if (step[1] < 0) {
                next = floor.across(at, step[0]);
            } else {
                step_sides.push_back(sides.size());
                bool kept_side = false, mismatch = false;
                for (int order = 0; order < 2; ++order) {
                    const At side = floor.across(at, order ? step[1] : step[0]);
                    const At corner = floor.across(side, order ? step[0] : step[1]);
                    if (corner.span < 0 || !(floor.kept(side) || floor.eroded(side))) continue;
                    mismatch = mismatch || (next.span >= 0 && corner.span != next.span);
                    next = corner;
                    if (floor.kept(side)) kept_side = true; else sides.push_back(side);
                }
                if (mismatch) break;
                if (kept_side) sides.resize(step_sides.back());  // a kept side joins this step already
            }
            if (next.span < 0) break;
            if (floor.kept(next)) {
                if (!run.empty() || !sides.empty()) end = next;
                break;
            }
            if (!floor.eroded(next)) break;
            run.push_back(next);
            at = next;
        }
        if (end.span < 0 || joined_nearby(start, end)) return;
        bool ok = std::all_of(run.begin(), run.end(), is_clear);
        for (size_t k = 0; ok && k < step_sides.size(); ++k) {  // each diagonal step needs a clear side, or a kept one
            const size_t from = step_sides[k], to = k + 1 < step_sides.size() ? step_sides[k + 1] : sides.size();
            bool any = from == to;
            for (size_t q = from; q < to; ++q) any = is_clear(sides[q]) || any;
            ok = any;
        }
        if (!ok) return;
        for (const At& m : run) back.push_back(m.span);
        for (const At& m : sides)
            if (is_clear(m)) back.push_back(m.span);
    };
    // A run's first step enters eroded floor: so walk from the kept spans before each eroded span, each run from its
    // end of lower x (or z), over a side (dir 0: -x, 3: -z, 1: +z) or a corner.
    auto corner = [&](const At& a, int d1, int d2) {  // the span diagonal from a through a floor side, or span -1
        for (const At& side : {floor.across(a, d1), floor.across(a, d2)}) {
            const At c = floor.across(side, side.x == a.x ? d1 : d2);
            if (floor.was_floor(side) && c.span >= 0) return c;
        }
        return At{-1, 0, 0};
    };
    for (int z = 0; z < chf.height; ++z)
        for (int x = 0; x < w; ++x) {
            const rcCompactCell& cell = chf.cells[x + z * w];
            for (int i = static_cast<int>(cell.index), e = static_cast<int>(cell.index + cell.count); i < e; ++i) {
                const At here{i, x, z};
                if (!floor.eroded(here)) continue;
                const At minus_x = floor.across(here, 0), minus_z = floor.across(here, 3), plus_z = floor.across(here, 1);
                walk(minus_x, 0);
                walk(minus_z, 1);
                walk(corner(here, 0, 3), 2);  // x then z: from the corner at -x, -z
                walk(minus_x, 2);             // here its +x side
                walk(minus_z, 2);             // here its +z side
                walk(corner(here, 0, 1), 3);  // x then -z: from the corner at -x, +z
                walk(minus_x, 3);             // here its +x side
                walk(plus_z, 3);              // here its -z side
            }
        }
}

// Recast's erosion (rcErodeWalkableArea, Recast Navigation 1.5.1) keeps a span when its chamfer distance (2 a side
// step, 3 a corner step) to the nearest span at the floor's edge is at least twice walkableRadius. Counted from the
// edge span's centre, which lies up to a cell inside the floor Recast rasterised, that keeps the agent 0.125-0.375 m
// further from a wall than its radius along the grid, and more at an angle to it (0.18-0.23 m more in the middle of
// the ring corridors of benchmarks/curved_corridors.py). A corridor whose kept floor narrows to one cell then holds
// spans that touch only at their corners, which Recast's regions never join (they follow side steps alone): a
// corridor 1.75 m wide at 20-60 degrees to the grid breaks into pieces, and those under minRegionArea are dropped
// (docs/navmesh.md, "Curved corridors"). This puts back, of the two side neighbours two such kept spans share, each
// that was floor before the erosion and that no edge span comes within `reach` - 1 side steps of (a search along
// its floor's links). Then every cell within `reach` side steps of it was floor, so a straight wall, which meets
// every cell it crosses, stands at least (reach + 1) / sqrt(2) cells from its centre (nearest at 45 degrees): reach
// = ceil(sqrt(2) * radius / cs - 1) keeps the agent's centre its radius from every straight wall (the cell's square,
// which the polygons cover, up to half its diagonal nearer: 0.40 m of 0.5 at worst measured). Reads only the spans'
// state before and after Recast's erosion, so the result does not depend on the order of the spans; a tile's
// border (walkableRadius + 3 cells) holds every span the search reads while the radius is under 10 cells (a finer
// grid's search may meet the border, where no floor is, and keep the cell eroded: never nearer a wall, but a tiled
// build may then differ from a solo one at a seam). O(spans), and O(reach^4) a candidate. join_clear_runs then adds
// the floor across doors and gaps that the level's triangles show clear (a run of up to 3 walkableRadius spans).
void join_corners(rcCompactHeightfield& chf, const std::vector<unsigned char>& before, int reach,
                  const float* verts, const int* tris, int ntris, const Settings& s, int walkable_radius) {
    const ErodedFloor floor{chf, before};
    const int w = chf.width;
    auto at_edge = [&](const At& a) {  // a floor span with a side that is not floor: where Recast's distances start
        for (int dir = 0; dir < 4; ++dir)
            if (!floor.was_floor(floor.across(a, dir))) return true;
        return false;
    };
    std::vector<At> queue;  // a search reads at most 2 reach^2 spans: a list beats a mark per span of the tile
    auto clear_all_round = [&](const At& m) {  // no edge span within reach - 1 side steps along m's floor
        queue.assign(1, m);
        for (size_t q = 0, end = 1, depth = 0;; ++depth) {
            for (; q < end; ++q) {
                const At a = queue[q];
                if (at_edge(a)) return false;
                if (static_cast<int>(depth) + 1 >= reach) continue;
                for (int dir = 0; dir < 4; ++dir) {
                    const At b = floor.across(a, dir);  // floor: a is no edge span
                    bool seen = false;
                    for (const At& c : queue) seen = seen || c.span == b.span;
                    if (!seen) queue.push_back(b);
                }
            }
            if (end == queue.size()) return true;
            end = queue.size();
        }
    };
    std::vector<int> back;
    for (int z = 0; z < chf.height; ++z)
        for (int x = 0; x < w; ++x) {
            const rcCompactCell& cell = chf.cells[x + z * w];
            for (int i = static_cast<int>(cell.index), e = static_cast<int>(cell.index + cell.count); i < e; ++i) {
                const At here{i, x, z};
                if (!floor.kept(here)) continue;
                const At b = floor.across(here, 1);  // +z, then -x or +x: each corner pair once, from its lower-z span
                if (floor.kept(b)) continue;  // inside the kept floor, where most spans are: no corner pair to join
                for (int side : {0, 2}) {
                    const At a = floor.across(here, side);
                    if (floor.kept(a)) continue;
                    if (floor.kept(floor.across(a, 1)) && floor.was_floor(a) && clear_all_round(a)) back.push_back(a.span);
                    if (floor.kept(floor.across(b, side)) && floor.was_floor(b) && clear_all_round(b)) back.push_back(b.span);
                }
            }
        }
    join_clear_runs(chf, before, verts, tris, ntris, s.agent_radius, s.agent_max_climb, s.agent_height,
                    walkable_radius, 3 * walkable_radius, back);
    for (int m : back) chf.areas[m] = before[m];
}

// Input shared by every tile of a build.
struct Input {
    const float* verts;
    int nv;
    const int* tris;
    int nt;
};

// What drop_border_islands reads of a tiled build's tile to weigh the navmesh's parts as Recast weighs a solo build's
// regions, the regions that made no polygon too (such as a strip one cell wide along the tile's edge):
// - each region's cells (spans) inside the tile, by region id, which Recast's rcBuildRegions counts of a region when
//   it weighs it against minRegionArea (the border's spans, painted RC_BORDER_REG, belong to no region);
// - the pairs of regions with linked spans inside the tile, one of them without polygons (`pm`'s regions; no `pm`:
//   none has any), since Detour's links already join the polygons of two regions that meet;
// - the spans of the tile's outermost cells, and their links to walkable spans of the border (the next tile's own
//   spans there).
// `border`: the tile's border in cells; `gx0`, `gz0`: the global grid cell of its first own cell. O(spans), one
// lookup each, and four for a span of a region without polygons or of an outermost cell.
void region_links(const rcCompactHeightfield& chf, int border, int gx0, int gz0, const rcPolyMesh* pm, TileMesh& out) {
    const int w = chf.width, h = chf.height;
    auto in_region = [](unsigned short reg) { return reg != 0 && !(reg & RC_BORDER_REG); };
    auto own = [&](int x, int z) { return x >= border && z >= border && x < w - border && z < h - border; };
    auto global = [&](int x, int z) {  // the order of a scan by rows (z, then x) for the tile's own cells
        return (static_cast<uint64_t>(static_cast<uint32_t>(gz0 + z - border)) << 32) |
               static_cast<uint32_t>(gx0 + x - border);
    };
    std::vector<char> has_polygon(static_cast<size_t>(chf.maxRegions) + 1, 0);
    for (int i = 0; pm && i < pm->npolys; ++i)
        if (pm->regs[i] < has_polygon.size()) has_polygon[pm->regs[i]] = 1;
    out.region_cells.assign(static_cast<size_t>(chf.maxRegions) + 1, 0);
    out.region_pairs.clear();
    out.seam_spans.clear();
    out.seam_links.clear();
    for (int z = border; z < h - border; ++z)
        for (int x = border; x < w - border; ++x) {
            const rcCompactCell& cell = chf.cells[x + z * w];
            const bool edge = x == border || z == border || x == w - border - 1 || z == h - border - 1;
            for (int i = static_cast<int>(cell.index), e = static_cast<int>(cell.index + cell.count); i < e; ++i) {
                const rcCompactSpan& sp = chf.spans[i];
                if (!in_region(sp.reg)) continue;
                if (sp.reg >= out.region_cells.size()) out.region_cells.resize(static_cast<size_t>(sp.reg) + 1, 0);
                ++out.region_cells[sp.reg];
                const bool polygonless = sp.reg >= has_polygon.size() || !has_polygon[sp.reg];
                if (!edge && !polygonless) continue;
                if (edge) out.seam_spans.push_back({global(x, z), sp.y, sp.reg});
                for (int dir = 0; dir < 4; ++dir) {
                    if (rcGetCon(sp, dir) == RC_NOT_CONNECTED) continue;
                    const int nx = x + rcGetDirOffsetX(dir), nz = z + rcGetDirOffsetY(dir);
                    const int ni = static_cast<int>(chf.cells[nx + nz * w].index) + rcGetCon(sp, dir);
                    const unsigned short nreg = chf.spans[ni].reg;
                    if (!own(nx, nz)) {
                        if (chf.areas[ni] != RC_NULL_AREA) out.seam_links.push_back({global(nx, nz), chf.spans[ni].y, sp.reg});
                    } else if (polygonless && in_region(nreg) && nreg != sp.reg) {
                        out.region_pairs.push_back((static_cast<uint32_t>(std::min(sp.reg, nreg)) << 16) | std::max(sp.reg, nreg));
                    }
                }
            }
        }
    std::sort(out.region_pairs.begin(), out.region_pairs.end());
    out.region_pairs.erase(std::unique(out.region_pairs.begin(), out.region_pairs.end()), out.region_pairs.end());
}

// The tile's Detour data (t.data) from its copied-out Recast arrays; false when dtCreateNavMeshData fails.
bool make_tile_data(TileMesh& t, int nvp, const rcConfig& c, const Settings& s) {
    const std::vector<unsigned short> flags(static_cast<size_t>(t.npolys), 1);  // Detour's default filter needs a non-zero flag
    dtNavMeshCreateParams params;
    std::memset(&params, 0, sizeof(params));
    params.verts = t.verts.data();
    params.vertCount = t.nverts;
    params.polys = t.polys.data();
    params.polyAreas = t.areas.data();
    params.polyFlags = flags.data();
    params.polyCount = t.npolys;
    params.nvp = nvp;
    params.detailMeshes = t.dmeshes.data();
    params.detailVerts = t.dverts.data();
    params.detailVertsCount = static_cast<int>(t.dverts.size() / 3);
    params.detailTris = t.dtris.data();
    params.detailTriCount = static_cast<int>(t.dtris.size() / 4);
    params.walkableHeight = static_cast<float>(s.agent_height);
    params.walkableRadius = static_cast<float>(s.agent_radius);
    params.walkableClimb = static_cast<float>(s.agent_max_climb);
    params.tileX = t.tx;
    params.tileY = t.ty;
    params.tileLayer = 0;
    rcVcopy(params.bmin, t.bmin);
    rcVcopy(params.bmax, t.bmax);
    params.cs = c.cs;
    params.ch = c.ch;
    params.buildBvTree = true;
    unsigned char* data = nullptr;
    int data_size = 0;
    if (!dtCreateNavMeshData(&params, &data, &data_size)) return false;
    t.data.reset(data);
    t.data_size = data_size;
    return true;
}

// Keeps only the polygons of `t` whose `keep` is set: their vertices, neighbours (renumbered), detail meshes and the
// lists of polygons whose detail was redone. A kept polygon's neighbour is kept too (drop_border_islands drops whole
// connected parts); `t.data` is stale until make_tile_data makes it again.
void keep_tile_polygons(TileMesh& t, const std::vector<char>& keep, int nvp) {
    std::vector<int> new_poly(static_cast<size_t>(t.npolys), -1), new_vert(static_cast<size_t>(t.nverts), -1);
    int npolys = 0, nverts = 0;
    for (int i = 0; i < t.npolys; ++i) {
        if (!keep[i]) continue;
        new_poly[i] = npolys++;
        for (int j = 0; j < nvp; ++j) {
            const unsigned short v = t.polys[static_cast<size_t>(i) * 2 * nvp + j];
            if (v != RC_MESH_NULL_IDX && new_vert[v] < 0) new_vert[v] = nverts++;
        }
    }
    std::vector<unsigned short> verts(static_cast<size_t>(nverts) * 3), polys;
    for (int v = 0; v < t.nverts; ++v)
        if (new_vert[v] >= 0) std::copy(&t.verts[v * 3], &t.verts[v * 3] + 3, &verts[new_vert[v] * 3]);
    std::vector<unsigned char> areas, dtris;
    std::vector<unsigned short> regs;
    std::vector<unsigned int> dmeshes;
    std::vector<float> dverts;
    polys.reserve(static_cast<size_t>(npolys) * 2 * nvp);
    for (int i = 0; i < t.npolys; ++i) {
        if (!keep[i]) continue;
        const unsigned short* p = &t.polys[static_cast<size_t>(i) * 2 * nvp];
        for (int j = 0; j < nvp; ++j) polys.push_back(p[j] == RC_MESH_NULL_IDX ? p[j] : static_cast<unsigned short>(new_vert[p[j]]));
        for (int j = nvp; j < 2 * nvp; ++j) {  // a neighbour's index, or RC_MESH_NULL_IDX, or 0x8000 | a portal's side
            const unsigned short n = p[j];
            polys.push_back(n == RC_MESH_NULL_IDX || (n & 0x8000) || new_poly[n] < 0 ? (n & 0x8000 ? n : RC_MESH_NULL_IDX)
                                                                                  : static_cast<unsigned short>(new_poly[n]));
        }
        areas.push_back(t.areas[i]);
        regs.push_back(t.regs[i]);
        const unsigned int* m = &t.dmeshes[static_cast<size_t>(i) * 4];
        dmeshes.insert(dmeshes.end(), {static_cast<unsigned int>(dverts.size() / 3), m[1],
                                       static_cast<unsigned int>(dtris.size() / 4), m[3]});
        dverts.insert(dverts.end(), &t.dverts[static_cast<size_t>(m[0]) * 3], &t.dverts[static_cast<size_t>(m[0] + m[1]) * 3]);
        dtris.insert(dtris.end(), &t.dtris[static_cast<size_t>(m[2]) * 4], &t.dtris[static_cast<size_t>(m[2] + m[3]) * 4]);
    }
    auto renumber = [&](std::vector<int32_t>& list) {
        std::vector<int32_t> kept;
        for (int32_t i : list)
            if (new_poly[i] >= 0) kept.push_back(new_poly[i]);
        list.swap(kept);
    };
    renumber(t.detail_redone);
    renumber(t.detail_resampled);
    t.nverts = nverts;
    t.npolys = npolys;
    t.verts.swap(verts);
    t.polys.swap(polys);
    t.areas.swap(areas);
    t.regs.swap(regs);
    t.dmeshes.swap(dmeshes);
    t.dverts.swap(dverts);
    t.dtris.swap(dtris);
}

// Runs Recast's pipeline for one tile (`c` holds its grid, bounds and border)
// over the triangles `tris` (ntris), and fills `out`. `gx0`, `gz0`: the global
// grid cell of the tile's first (non-border) cell. `solo` marks the whole-grid
// build, whose size-limited failures throw TooBigForSolo. `where` is appended
// to error messages (" in tile (x, y)" for tiled builds).
void build_tile(const Input& in, const int* tris, int ntris, const rcConfig& c, const Settings& s,
                int gx0, int gz0, bool solo, const std::string& where, TileMesh& out) {
    LogContext ctx;
    auto too_big = [&](const std::string& step) {
        if (solo) throw TooBigForSolo(message(step, where, &ctx));
        fail(step, &ctx, where);
    };

    // 1. Rasterize the walkable triangles.
    std::unique_ptr<rcHeightfield, HeightfieldDel> solid(rcAllocHeightfield());
    if (!solid) fail("rcAllocHeightfield failed (out of memory)", nullptr, where);
    if (!rcCreateHeightfield(&ctx, *solid, c.width, c.height, c.bmin, c.bmax, c.cs, c.ch))
        fail("rcCreateHeightfield failed", &ctx, where);
    {
        std::vector<unsigned char> tri_areas(static_cast<size_t>(ntris), 0);
        rcMarkWalkableTriangles(&ctx, c.walkableSlopeAngle, in.verts, in.nv, tris, ntris, tri_areas.data());
        if (!rcRasterizeTriangles(&ctx, in.verts, in.nv, tris, tri_areas.data(), ntris, *solid, c.walkableClimb))
            fail("rcRasterizeTriangles failed", &ctx, where);
    }

    // 2. Filter walkable surfaces.
    if (s.filter_low_hanging_obstacles) rcFilterLowHangingWalkableObstacles(&ctx, c.walkableClimb, *solid);
    if (s.ledge_filter == LedgeFilter::recast) rcFilterLedgeSpans(&ctx, c.walkableHeight, c.walkableClimb, *solid);
    if (s.ledge_filter == LedgeFilter::drops) drop_ledge_spans(c.walkableHeight, c.walkableClimb, *solid);
    // Recast documents walkableHeight as the least head room an agent stands under, and rcBuildCompactHeightfield
    // links two spans whose shared gap is at least that, but rcFilterWalkableLowHeightSpans (RecastFilter.cpp, 1.5.1)
    // drops a span whose gap is at most walkableHeight cells: one cell more than the agent's height was needed, on
    // top of the rounding (a floor's top rounded up, a flat one by a whole cell, a ceiling's underside down). Passed
    // one cell less, it keeps gaps of walkableHeight cells: a ceiling less than the agent's height over a flat floor
    // still never holds floor, and one cell height over it always does (docs/navmesh.md, "Head room under an edge").
    if (s.filter_low_height_spans)
        rcFilterWalkableLowHeightSpans(&ctx, s.recast_head_room ? c.walkableHeight : c.walkableHeight - 1, *solid);

    // 3. Compact heightfield, erosion by the agent radius.
    std::unique_ptr<rcCompactHeightfield, CompactDel> chf(rcAllocCompactHeightfield());
    if (!chf) fail("rcAllocCompactHeightfield failed (out of memory)", nullptr, where);
    if (!rcBuildCompactHeightfield(&ctx, c.walkableHeight, c.walkableClimb, *solid, *chf))
        fail("rcBuildCompactHeightfield failed", &ctx, where);
    solid.reset();
    std::vector<unsigned char> before;
    if (s.join_corners) before.assign(chf->areas, chf->areas + chf->spanCount);
    if (!rcErodeWalkableArea(&ctx, c.walkableRadius, *chf)) fail("rcErodeWalkableArea failed", &ctx, where);
    if (s.join_corners && c.walkableRadius > 0)
        join_corners(*chf, before,
                     std::max(1, static_cast<int>(std::ceil(std::sqrt(2.0) * s.agent_radius / static_cast<double>(c.cs) - 1.0))),
                     in.verts, tris, ntris, s, c.walkableRadius);
    int walkable_spans = 0;
    for (int i = 0; i < chf->spanCount; ++i)
        if (chf->areas[i] != RC_NULL_AREA) ++walkable_spans;
    if (walkable_spans == 0) {
        out.empty_reason = "no walkable surface left after filtering and erosion";
        return;
    }

    // 4. Regions. Only watershed reads the distance field; layer regions have no merge step.
    // Every partition labels all spans afresh (the region of each span, the region count,
    // the border), so the automatic fallback on the same compact heightfield gives what a
    // build with the fallback alone gives (tested); only the unused distance field stays.
    auto build_regions = [&](Partition partition) {
        switch (partition) {
        case Partition::automatic:
        case Partition::watershed:
            if (!rcBuildDistanceField(&ctx, *chf)) fail("rcBuildDistanceField failed", &ctx, where);
            if (!rcBuildRegions(&ctx, *chf, c.borderSize, c.minRegionArea, c.mergeRegionArea))
                too_big("rcBuildRegions failed");
            break;
        case Partition::monotone:
            if (!rcBuildRegionsMonotone(&ctx, *chf, c.borderSize, c.minRegionArea, c.mergeRegionArea))
                too_big("rcBuildRegionsMonotone failed");
            break;
        case Partition::layers:
            if (!rcBuildLayerRegions(&ctx, *chf, c.borderSize, c.minRegionArea))
                too_big("rcBuildLayerRegions failed");
            break;
        }
    };
    build_regions(s.partition);
    out.overlaps = self_overlapping_regions(*chf, out.overlap_regions);
    if (s.partition == Partition::automatic && !out.overlaps.empty()) {
        ctx.errors.clear();  // Recast logs the overlap as an error; it is repaired here
        build_regions(AUTO_FALLBACK);
        out.overlaps = self_overlapping_regions(*chf, out.overlap_regions);
        out.repartitioned = true;
    }

    // 5. Contours, polygons, detail. Contours only read the compact heightfield, so
    // the automatic fallback after them is again exactly the fallback partition's build.
    std::unique_ptr<rcContourSet, ContourDel> cset;
    auto build_contours = [&] {
        cset.reset(rcAllocContourSet());
        if (!cset) fail("rcAllocContourSet failed (out of memory)", nullptr, where);
        if (!rcBuildContours(&ctx, *chf, c.maxSimplificationError, c.maxEdgeLen, *cset))
            fail("rcBuildContours failed", &ctx, where);
    };
    build_contours();
    if (s.partition == Partition::automatic && !out.repartitioned &&
        largest_region_contour(*cset) > AUTO_MAX_REGION_CONTOUR_VERTS) {
        ctx.errors.clear();  // what Recast logged belongs to the watershed contours, dropped here
        build_regions(AUTO_FALLBACK);
        out.overlaps = self_overlapping_regions(*chf, out.overlap_regions);
        out.repartitioned = true;
        build_contours();
    }
    if (cset->nconts == 0) {
        if (c.borderSize > 0) region_links(*chf, c.borderSize, gx0, gz0, nullptr, out);
        out.empty_reason = "no contours; regions too small?";
        return;
    }
    std::unique_ptr<rcPolyMesh, PolyMeshDel> pmesh(rcAllocPolyMesh());
    if (!pmesh) fail("rcAllocPolyMesh failed (out of memory)", nullptr, where);
    if (!rcBuildPolyMesh(&ctx, *cset, c.maxVertsPerPoly, *pmesh)) too_big("rcBuildPolyMesh failed");
    if (c.borderSize > 0) region_links(*chf, c.borderSize, gx0, gz0, pmesh.get(), out);
    if (pmesh->npolys == 0) {
        if (!out.overlaps.empty())
            out.empty_reason = std::to_string(out.overlaps.size() / 3) +
                               " region(s) overlap themselves in plan and Recast made no polygon of them; "
                               "partition 'auto' rebuilds such regions";
        return;
    }
    std::unique_ptr<rcPolyMeshDetail, DetailDel> dmesh(rcAllocPolyMeshDetail());
    if (!dmesh) fail("rcAllocPolyMeshDetail failed (out of memory)", nullptr, where);
    if (!rcBuildPolyMeshDetail(&ctx, *pmesh, *chf, c.detailSampleDist, c.detailSampleMaxError, *dmesh))
        too_big("rcBuildPolyMeshDetail failed");
    out.detail_redone = redo_detail_off_storey(ctx, *pmesh, *chf, c, dmesh, too_big);
    out.detail_resampled = resample_detail_off_floor(ctx, *pmesh, *chf, c, dmesh, out.detail_redone, too_big);
    chf.reset();
    cset.reset();

    // 6. Copy the mesh data out, as Recast lays it out.
    const rcPolyMesh& pm = *pmesh;
    const rcPolyMeshDetail& dm = *dmesh;
    out.gx0 = gx0;
    out.gz0 = gz0;
    out.nverts = pm.nverts;
    out.npolys = pm.npolys;
    rcVcopy(out.bmin, pm.bmin);
    rcVcopy(out.bmax, pm.bmax);
    out.verts.assign(pm.verts, pm.verts + static_cast<size_t>(pm.nverts) * 3);
    out.polys.assign(pm.polys, pm.polys + static_cast<size_t>(pm.npolys) * 2 * pm.nvp);
    out.areas.assign(pm.areas, pm.areas + pm.npolys);
    out.regs.assign(pm.regs, pm.regs + pm.npolys);
    out.dmeshes.assign(dm.meshes, dm.meshes + static_cast<size_t>(dm.nmeshes) * 4);
    out.dverts.assign(dm.verts, dm.verts + static_cast<size_t>(dm.nverts) * 3);
    out.dtris.assign(dm.tris, dm.tris + static_cast<size_t>(dm.ntris) * 4);

    // 7. Detour tile data.
    if (!make_tile_data(out, pm.nvp, c, s)) too_big("dtCreateNavMeshData failed (too many vertices or polygons for one tile?)");
}

// ---------------------------------------------------------------- navmesh

class NavMeshCore {
public:
    // Copied-out mesh data (see the Python docstrings for the layout).
    int nvp = 0;
    std::vector<double> verts;          // (V,3) world
    std::vector<int32_t> polys;         // (P,nvp), -1 padded
    std::vector<int32_t> neis;          // (P,nvp), -1 at boundary
    std::vector<int32_t> areas;         // (P,)
    std::vector<int32_t> regions;       // (P,)
    std::vector<double> dverts;         // (DV,3) world
    std::vector<int32_t> dtris;         // (DT,3) global detail vertex indices
    std::vector<int32_t> dtri_poly;     // (DT,)
    std::vector<int64_t> portal_pairs;  // (E,2) a < b, sorted
    std::vector<double> portal_ends;    // (E,2,3) shared segment end points, along a's edge
    std::vector<double> overlaps;       // (K,3) a span of each region overlapping itself, tile by tile
    std::vector<int32_t> repartitioned; // (R,2) tile x, z of the tiles the automatic partition redid
    std::vector<int32_t> detail_redone; // (N,) polygons whose detail read another storey, rebuilt
    std::vector<int32_t> detail_resampled; // (N,) polygons whose detail left the floor, rebuilt with finer samples
    int npolys = 0;

    // Resolved Recast configuration and tiling.
    rcConfig cfg{};
    int tile_size = 0;                  // 0: solo
    int tiles_x = 1, tiles_y = 1;       // tile grid
    int border_size = 0;
    bool auto_fallback = false;         // automatic mode: solo was too big, built with tiles
    int border_island_polygons = 0;     // polygons of the small parts at tile borders taken out (drop_border_islands)
    double build_seconds = 0.0;
    float climb_tolerance = 0.0f;
    float default_ext[3] = {0, 0, 0};

    std::unique_ptr<dtNavMesh, NavMeshDel> nav;
    std::unique_ptr<dtNavMeshQuery, QueryDel> query;
    dtQueryFilter filter;  // default: all areas, include all flags
    // Global polygon index <-> dtPolyRef: for the k-th added tile (row-major
    // order), its first global index and its Detour poly-ref base; and the
    // first global index by Detour tile index.
    std::vector<int> tile_first;
    std::vector<dtPolyRef> tile_ref_base;
    std::vector<int> first_by_tile_index;
    mutable std::mutex mutex;

    void build(const float* vin, int nv, const int* tin, int nt, const Settings& s);

    int ref_to_index(dtPolyRef ref) const {
        if (ref == 0) return -1;
        const unsigned int it = nav->decodePolyIdTile(ref);
        if (it >= first_by_tile_index.size() || first_by_tile_index[it] < 0) return -1;
        return first_by_tile_index[it] + static_cast<int>(nav->decodePolyIdPoly(ref));
    }
    dtPolyRef index_to_ref(int index) const {
        if (index < 0 || index >= npolys) throw nb::index_error("polygon index out of range");
        const size_t k = static_cast<size_t>(
            std::upper_bound(tile_first.begin(), tile_first.end(), index) - tile_first.begin() - 1);
        return tile_ref_base[k] | static_cast<dtPolyRef>(index - tile_first[k]);
    }

    // Nearest polygon (index or -1) and nearest point.
    int nearest(const float* p, const float* ext, float* out) const {
        dtPolyRef ref = 0;
        out[0] = p[0]; out[1] = p[1]; out[2] = p[2];
        dtStatus st = query->findNearestPoly(p, ext, &filter, &ref, out);
        if (dtStatusFailed(st) || ref == 0) {
            out[0] = p[0]; out[1] = p[1]; out[2] = p[2];
            return -1;
        }
        return ref_to_index(ref);
    }

    // The raycast test described in the module docs; returns (clear, t).
    std::pair<bool, float> ray(const float* a, const float* b, const float* ext,
                               std::vector<dtPolyRef>& path) const {
        float start[3];
        dtPolyRef startRef = 0;
        dtStatus st = query->findNearestPoly(a, ext, &filter, &startRef, start);
        if (dtStatusFailed(st) || startRef == 0) return {false, 0.0f};
        return ray_from(startRef, start, b, path);
    }

    // ray's test once the polygon nearest a (startRef, start: the point on it) is found.
    std::pair<bool, float> ray_from(dtPolyRef startRef, const float* start, const float* b,
                                    std::vector<dtPolyRef>& path) const {
        for (;;) {
            dtRaycastHit hit{};
            hit.path = path.data();
            hit.maxPath = static_cast<int>(path.size());
            const dtStatus st = query->raycast(startRef, start, b, &filter, 0, &hit);
            if (dtStatusFailed(st)) return {false, 0.0f};
            if (dtStatusDetail(st, DT_BUFFER_TOO_SMALL)) {
                path.resize(path.size() * 2);
                continue;
            }
            if (hit.t != FLT_MAX) return {false, hit.t};
            if (hit.pathCount <= 0) return {false, hit.t};
            const dtPolyRef endRef = path[hit.pathCount - 1];
            float closest[3];
            bool over = false;
            if (dtStatusFailed(query->closestPointOnPoly(endRef, b, closest, &over)))
                return {false, hit.t};
            const bool ok = std::fabs(closest[1] - b[1]) <= climb_tolerance;
            return {ok, hit.t};
        }
    }

    // The surface_los predicate's line of sight from a to b (world coordinates, float64), once the polygon nearest a
    // is found (startRef, 0 for none; start: the point on it): ray_from's raycast reaches b and, unless max_gap is
    // none, segment_gap along a -> b stays within max_gap.
    bool sees(dtPolyRef startRef, const float* start, const double* a, const double* b, double step, float horizontal,
              std::optional<double> max_gap, std::vector<dtPolyRef>& path) const {
        const float fb[3] = {static_cast<float>(b[0]), static_cast<float>(b[1]), static_cast<float>(b[2])};
        if (startRef == 0 || !ray_from(startRef, start, fb, path).first) return false;
        return !max_gap || segment_gap(a, b, step, horizontal, static_cast<float>(*max_gap)) <= *max_gap;
    }

    // Vertical distance from p to the walkable surface, FLT_MAX when there is none within `reach`:
    // to the detail surface straight above or below p on the polygons p lies over (the nearest
    // in height); over none of them (p beside a polygon's edge), to the nearest boundary point
    // of the polygons within `horizontal` of p.
    float surface_gap(const float* p, float horizontal, float reach) const {
        const float ext[3] = {horizontal, reach, horizontal};
        dtPolyRef refs[128];
        int count = 0;
        if (dtStatusFailed(query->queryPolygons(p, ext, &filter, refs, &count, 128))) return FLT_MAX;
        float over_gap = FLT_MAX, beside_gap = FLT_MAX;
        for (int i = 0; i < count; ++i) {
            float closest[3];
            bool over = false;
            if (dtStatusFailed(query->closestPointOnPoly(refs[i], p, closest, &over))) continue;
            const float gap = std::fabs(closest[1] - p[1]);
            if (over) {
                over_gap = std::min(over_gap, gap);
            } else {
                const float dx = closest[0] - p[0], dz = closest[2] - p[2];
                if (dx * dx + dz * dz <= horizontal * horizontal) beside_gap = std::min(beside_gap, gap);
            }
        }
        const float gap = over_gap != FLT_MAX ? over_gap : beside_gap;
        return gap <= reach ? gap : FLT_MAX;
    }

    // The largest surface_gap over points at most `step` apart horizontally along a -> b, ends
    // included, stopping at the first point with no surface within `reach` (then +inf).
    double segment_gap(const double* a, const double* b, double step, float horizontal, float reach) const {
        const double length = std::hypot(b[0] - a[0], b[2] - a[2]);
        const long pieces = std::max(1L, static_cast<long>(std::ceil(length / step - 1e-9)));
        float worst = 0.0f;
        for (long i = 0; i <= pieces && worst != FLT_MAX; ++i) {
            const double t = static_cast<double>(i) / static_cast<double>(pieces);
            const float p[3] = {static_cast<float>(a[0] + t * (b[0] - a[0])),
                                static_cast<float>(a[1] + t * (b[1] - a[1])),
                                static_cast<float>(a[2] + t * (b[2] - a[2]))};
            worst = std::max(worst, surface_gap(p, horizontal, reach));
        }
        return worst == FLT_MAX ? std::numeric_limits<double>::infinity() : static_cast<double>(worst);
    }

private:
    std::vector<std::unique_ptr<TileMesh>> build_solo(const Input& in, const Settings& s);
    std::vector<std::unique_ptr<TileMesh>> build_tiled(const Input& in, const Settings& s, int ts);
    void assemble(std::vector<std::unique_ptr<TileMesh>>& tiles);
    std::unique_ptr<dtNavMesh, NavMeshDel> new_navmesh(const std::vector<std::unique_ptr<TileMesh>>& tiles) const;
    int drop_border_islands(std::vector<std::unique_ptr<TileMesh>>& tiles, const Settings& s);
    void keep_records(const std::vector<std::unique_ptr<TileMesh>>& tiles);
    void link_topology();
};

std::vector<std::unique_ptr<TileMesh>> NavMeshCore::build_solo(const Input& in, const Settings& s) {
    tile_size = 0;
    tiles_x = tiles_y = 1;
    border_size = 0;
    rcConfig c = cfg;
    c.borderSize = 0;
    c.tileSize = 0;
    auto tile = std::make_unique<TileMesh>();
    build_tile(in, in.tris, in.nt, c, s, 0, 0, true, "", *tile);
    if (tile->npolys == 0) {
        if (tile->empty_reason.empty()) fail("no walkable polygons");
        fail("no walkable polygons (" + tile->empty_reason + ")");
    }
    std::vector<std::unique_ptr<TileMesh>> out;
    out.push_back(std::move(tile));
    return out;
}

std::vector<std::unique_ptr<TileMesh>> NavMeshCore::build_tiled(const Input& in, const Settings& s, int ts) {
    const rcConfig& g = cfg;
    tile_size = ts;
    border_size = g.walkableRadius + 3;
    tiles_x = (g.width + ts - 1) / ts;
    tiles_y = (g.height + ts - 1) / ts;
    const int ntiles = tiles_x * tiles_y;
    const int border = border_size;
    const float tw = static_cast<float>(ts) * g.cs;     // tile width, world
    const float bw = static_cast<float>(border) * g.cs;  // border width, world

    // Bin the triangles into the tiles their xz bounding box (widened by the
    // border) overlaps.
    const TriangleBins bins = bin_triangles(in.nt, tiles_x, tiles_y, [&](int t) {
        const float* a = &in.verts[in.tris[t * 3 + 0] * 3];
        const float* b = &in.verts[in.tris[t * 3 + 1] * 3];
        const float* d = &in.verts[in.tris[t * 3 + 2] * 3];
        const float minx = std::min({a[0], b[0], d[0]}), maxx = std::max({a[0], b[0], d[0]});
        const float minz = std::min({a[2], b[2], d[2]}), maxz = std::max({a[2], b[2], d[2]});
        // tile tx spans [orig + tx*tw - bw, orig + (tx+1)*tw + bw]; a cell of slack either side
        const float slack = g.cs;
        // (first tile: the one whose own span holds min - bw; last: the one holding max + bw)
        int x0 = static_cast<int>(std::floor((minx - g.bmin[0] - bw - slack) / tw));
        int x1 = static_cast<int>(std::floor((maxx - g.bmin[0] + bw + slack) / tw));
        int z0 = static_cast<int>(std::floor((minz - g.bmin[2] - bw - slack) / tw));
        int z1 = static_cast<int>(std::floor((maxz - g.bmin[2] + bw + slack) / tw));
        return std::array<int, 4>{std::max(x0, 0), std::min(x1, tiles_x - 1), std::max(z0, 0), std::min(z1, tiles_y - 1)};
    });
    const std::vector<size_t>& start = bins.start;
    const std::vector<int>& members = bins.members;

    // Build the tiles in worker threads; results by tile (row-major).
    std::vector<std::unique_ptr<TileMesh>> results(ntiles);
    std::vector<std::string> errors(ntiles);
    std::atomic<int> next{0};
    std::atomic<bool> stop{false};
    auto worker = [&]() {
        std::vector<int> sub;
        for (;;) {
            const int k = next.fetch_add(1);
            if (k >= ntiles || stop.load()) return;
            const int tx = k % tiles_x, ty = k / tiles_x;
            const size_t m0 = start[k], m1 = start[k + 1];
            if (m0 == m1) continue;  // no triangle here: empty tile
            try {
                sub.resize((m1 - m0) * 3);
                for (size_t m = m0; m < m1; ++m) {
                    const int t = members[m];
                    sub[(m - m0) * 3 + 0] = in.tris[t * 3 + 0];
                    sub[(m - m0) * 3 + 1] = in.tris[t * 3 + 1];
                    sub[(m - m0) * 3 + 2] = in.tris[t * 3 + 2];
                }
                rcConfig c = g;
                c.tileSize = ts;
                c.borderSize = border;
                c.width = ts + 2 * border;
                c.height = ts + 2 * border;
                c.bmin[0] = g.bmin[0] + static_cast<float>(tx * ts - border) * g.cs;
                c.bmin[2] = g.bmin[2] + static_cast<float>(ty * ts - border) * g.cs;
                c.bmax[0] = g.bmin[0] + static_cast<float>((tx + 1) * ts + border) * g.cs;
                c.bmax[2] = g.bmin[2] + static_cast<float>((ty + 1) * ts + border) * g.cs;
                auto tile = std::make_unique<TileMesh>();
                tile->tx = tx;
                tile->ty = ty;
                const std::string where = " in tile (" + std::to_string(tx) + ", " + std::to_string(ty) +
                                          ") of " + std::to_string(tiles_x) + " x " + std::to_string(tiles_y);
                build_tile(in, sub.data(), static_cast<int>(m1 - m0), c, s, tx * ts, ty * ts, false, where, *tile);
                // a tile without polygons is kept while its regions can join or weigh the parts of the next tiles
                // (drop_border_islands), or it holds a region that overlaps itself (the navmesh's records)
                if (tile->npolys > 0 || !tile->seam_spans.empty() || !tile->overlaps.empty()) results[k] = std::move(tile);
            } catch (const std::bad_alloc&) {
                errors[k] = "Recast: out of memory in tile (" + std::to_string(tx) + ", " + std::to_string(ty) + ")";
                stop.store(true);
            } catch (const std::exception& e) {
                errors[k] = e.what();
                stop.store(true);
            }
        }
    };
    int nthreads = s.threads > 0 ? s.threads : static_cast<int>(std::thread::hardware_concurrency());
    nthreads = std::max(1, std::min({nthreads, ntiles, 64}));
    if (nthreads == 1) {
        worker();
    } else {
        std::vector<std::thread> pool;
        pool.reserve(nthreads);
        for (int i = 0; i < nthreads; ++i) pool.emplace_back(worker);
        for (auto& th : pool) th.join();
    }
    for (int k = 0; k < ntiles; ++k)
        if (!errors[k].empty()) throw std::runtime_error(errors[k]);

    std::vector<std::unique_ptr<TileMesh>> out;
    bool any_polygon = false;
    for (auto& t : results)
        if (t) {
            any_polygon = any_polygon || t->npolys > 0;
            out.push_back(std::move(t));
        }
    if (!any_polygon) fail("no walkable polygons (no tile has any)");
    return out;
}

// Recast removes a connected group of regions smaller than minRegionArea cells from a tile, but not one that
// touches the tile's border, whose size one tile cannot tell; so a tiled navmesh keeps small parts that a tile border
// cuts or grazes (a plinth's top, a sliver of floor) where a solo build of the same level drops them
// (docs/navmesh.md, "Islands at tile borders"). Across the tiles a group's size is known. The tiles' regions are
// joined where their spans link (inside a tile, and across a tile border: a tile's outermost span and the next tile's
// span it links to) and where Detour links their polygons; a group that reaches a tile border and has fewer than
// minRegionArea cells in all (its regions' cells summed over its tiles, the regions that made no polygon counted
// too, such as a strip one cell wide along a tile's edge) is a group Recast would have removed, and its polygons are
// taken out of their tiles, whose Detour data is made again, so that no query of the navmesh meets them; so are the
// tiles' overlap records of its regions. Every other group stays as Recast built it. A tile left without polygons
// stays in `tiles` (keep_records reads it). Returns the number of polygons taken out.
int NavMeshCore::drop_border_islands(std::vector<std::unique_ptr<TileMesh>>& tiles, const Settings& s) {
    const int min_cells = cfg.minRegionArea, max_verts = cfg.maxVertsPerPoly;
    if (min_cells <= 0 || tiles.empty()) return 0;
    // One node per tile and region, joined into groups by a union-find whose roots are the lowest nodes.
    std::vector<int> node0(tiles.size() + 1, 0);
    for (size_t k = 0; k < tiles.size(); ++k) node0[k + 1] = node0[k] + static_cast<int>(tiles[k]->region_cells.size());
    std::vector<int> group(static_cast<size_t>(node0.back()));
    for (size_t i = 0; i < group.size(); ++i) group[i] = static_cast<int>(i);
    auto root = [&](int i) {
        while (group[i] != i) i = group[i] = group[group[i]];
        return i;
    };
    auto join = [&](int a, int b) {
        a = root(a);
        b = root(b);
        if (a != b) group[std::max(a, b)] = std::min(a, b);
    };
    auto node = [&](size_t k, unsigned short reg) {  // -1: a region no cell was counted of
        return reg < tiles[k]->region_cells.size() ? node0[k] + reg : -1;
    };
    std::vector<char> at_border(group.size(), 0), keep_all(group.size(), 0);
    for (size_t k = 0; k < tiles.size(); ++k)
        for (uint32_t pair : tiles[k]->region_pairs) join(node0[k] + static_cast<int>(pair >> 16), node0[k] + static_cast<int>(pair & 0xffff));
    {
        // The span a tile's outermost span links to is the next tile's span in the same global cell, at the same floor
        // (a cell of rounding allowed: each tile rasterises the triangles from its own corner).
        std::vector<int> tile_at(static_cast<size_t>(tiles_x) * tiles_y, -1);
        for (size_t k = 0; k < tiles.size(); ++k) tile_at[static_cast<size_t>(tiles[k]->ty) * tiles_x + tiles[k]->tx] = static_cast<int>(k);
        for (size_t k = 0; k < tiles.size(); ++k)
            for (const SeamSpan& link : tiles[k]->seam_links) {
                const int from = node0[k] + link.reg;
                at_border[from] = 1;
                const int gx = static_cast<int32_t>(link.cell & 0xffffffffu), gz = static_cast<int32_t>(link.cell >> 32);
                if (gx < 0 || gz < 0 || gx / tile_size >= tiles_x || gz / tile_size >= tiles_y) continue;  // off the grid
                const int kk = tile_at[static_cast<size_t>(gz / tile_size) * tiles_x + gx / tile_size];
                if (kk < 0) continue;  // a tile with no triangle
                const std::vector<SeamSpan>& spans = tiles[kk]->seam_spans;
                auto it = std::lower_bound(spans.begin(), spans.end(), link.cell,
                                           [](const SeamSpan& a, uint64_t cell) { return a.cell < cell; });
                for (; it != spans.end() && it->cell == link.cell; ++it)
                    if (std::abs(it->y - link.y) <= 1) join(from, node0[kk] + it->reg);
            }
    }
    {
        // Detour's links (the navmesh's neighbours and portals come from them), from a navmesh of the tiles as they
        // are that reads their data without owning it (no DT_TILE_FREE_DATA): a dropped polygon is never linked to a
        // kept one.
        std::unique_ptr<dtNavMesh, NavMeshDel> probe = new_navmesh(tiles);
        std::vector<dtTileRef> refs(tiles.size(), 0);
        std::vector<int> tile_of_index(static_cast<size_t>(probe->getMaxTiles()), -1);
        for (size_t k = 0; k < tiles.size(); ++k) {
            if (tiles[k]->npolys == 0) continue;
            if (dtStatusFailed(probe->addTile(tiles[k]->data.get(), tiles[k]->data_size, 0, 0, &refs[k])))
                fail("dtNavMesh::addTile failed in tile (" + std::to_string(tiles[k]->tx) + ", " +
                     std::to_string(tiles[k]->ty) + ")");
            tile_of_index[probe->decodePolyIdTile(static_cast<dtPolyRef>(refs[k]))] = static_cast<int>(k);
        }
        for (size_t k = 0; k < tiles.size(); ++k) {
            if (tiles[k]->npolys == 0) continue;
            const dtMeshTile* tile = probe->getTileByRef(refs[k]);
            for (int ip = 0; ip < tile->header->polyCount; ++ip) {
                const dtPoly& p = tile->polys[ip];
                const int a = node(k, tiles[k]->regs[ip]);
                for (int j = 0; j < p.vertCount; ++j)
                    if ((p.neis[j] & DT_EXT_LINK) && a >= 0) at_border[a] = 1;
                for (unsigned int l = p.firstLink; l != DT_NULL_LINK; l = tile->links[l].next) {
                    const dtPolyRef ref = tile->links[l].ref;
                    const size_t kk = static_cast<size_t>(tile_of_index[probe->decodePolyIdTile(ref)]);
                    const int b = node(kk, tiles[kk]->regs[probe->decodePolyIdPoly(ref)]);
                    if (a >= 0 && b >= 0) {
                        join(a, b);
                    } else {  // a polygon of an uncounted region keeps whatever it is linked to
                        if (a >= 0) keep_all[a] = 1;
                        if (b >= 0) keep_all[b] = 1;
                    }
                }
            }
        }
    }
    // Each group's cells, whether it reaches a tile border, whether it must stay.
    std::vector<long long> cells(group.size(), 0);
    for (size_t k = 0; k < tiles.size(); ++k)
        for (size_t reg = 0; reg < tiles[k]->region_cells.size(); ++reg) {
            const int n = node0[k] + static_cast<int>(reg), r = root(n);
            cells[r] += tiles[k]->region_cells[reg];
            at_border[r] = at_border[r] || at_border[n];
            keep_all[r] = keep_all[r] || keep_all[n];
        }
    auto dropped_region = [&](size_t k, unsigned short reg) {
        const int n = node(k, reg);
        if (n < 0) return false;
        const int r = root(n);
        return at_border[r] && !keep_all[r] && cells[r] < min_cells;
    };
    int dropped = 0;
    for (size_t k = 0; k < tiles.size(); ++k) {
        TileMesh& t = *tiles[k];
        std::vector<char> keep(static_cast<size_t>(t.npolys), 1);
        for (int ip = 0; ip < t.npolys; ++ip) keep[ip] = !dropped_region(k, t.regs[ip]);
        const int gone = static_cast<int>(std::count(keep.begin(), keep.end(), 0));
        if (gone > 0) {
            dropped += gone;
            keep_tile_polygons(t, keep, max_verts);
            t.data.reset();
            t.data_size = 0;
            if (t.npolys > 0 && !make_tile_data(t, max_verts, cfg, s))
                fail("dtCreateNavMeshData failed in tile (" + std::to_string(t.tx) + ", " + std::to_string(t.ty) + ")");
        }
        size_t left = 0;
        for (size_t q = 0; q < t.overlap_regions.size(); ++q) {
            if (dropped_region(k, t.overlap_regions[q])) continue;
            std::copy(&t.overlaps[q * 3], &t.overlaps[q * 3] + 3, &t.overlaps[left * 3]);
            t.overlap_regions[left++] = t.overlap_regions[q];
        }
        t.overlaps.resize(left * 3);
        t.overlap_regions.resize(left);
    }
    return dropped;
}

// The navmesh's records of how its tiles were partitioned, of the floor it holds: every overlap span left in the
// tiles (one of a tile without polygons too: a region a solo build would keep, whose floor the overlap lost) and the
// tiles that the automatic partition redid and that hold polygons.
void NavMeshCore::keep_records(const std::vector<std::unique_ptr<TileMesh>>& tiles) {
    overlaps.clear();
    repartitioned.clear();
    for (const auto& t : tiles) {
        overlaps.insert(overlaps.end(), t->overlaps.begin(), t->overlaps.end());
        if (t->repartitioned && t->npolys > 0) repartitioned.insert(repartitioned.end(), {t->tx, t->ty});
    }
}

// An empty Detour navmesh for `tiles` (its origin and tile width from the build's grid and tiling).
std::unique_ptr<dtNavMesh, NavMeshDel> NavMeshCore::new_navmesh(const std::vector<std::unique_ptr<TileMesh>>& tiles) const {
    const rcConfig& g = cfg;
    // Detour's 32-bit polygon references: salt + tile + poly bits, salt >= 10.
    int max_polys = 0;
    for (const auto& t : tiles) max_polys = std::max(max_polys, t->npolys);
    const unsigned int tile_bits = bits_for(static_cast<unsigned int>(tiles.size()));
    const unsigned int poly_bits = bits_for(static_cast<unsigned int>(max_polys));
    if (tile_bits + poly_bits > 22)
        fail("dtNavMesh::init: " + std::to_string(tiles.size()) + " tiles with up to " +
             std::to_string(max_polys) + " polygons each need " + std::to_string(tile_bits + poly_bits) +
             " bits of Detour's 32-bit polygon reference (at most 22 besides the 10-bit salt); "
             "use a different tile_size or a larger cell_size");

    dtNavMeshParams np;
    std::memset(&np, 0, sizeof(np));
    rcVcopy(np.orig, g.bmin);
    if (tile_size == 0) {  // as dtNavMesh::init(data) does for a single tile
        np.tileWidth = g.bmax[0] - g.bmin[0];
        np.tileHeight = g.bmax[2] - g.bmin[2];
    } else {
        np.tileWidth = static_cast<float>(tile_size) * g.cs;
        np.tileHeight = static_cast<float>(tile_size) * g.cs;
    }
    np.maxTiles = static_cast<int>(tiles.size());
    np.maxPolys = max_polys;
    std::unique_ptr<dtNavMesh, NavMeshDel> navmesh(dtAllocNavMesh());
    if (!navmesh) fail("dtAllocNavMesh failed (out of memory)");
    if (dtStatusFailed(navmesh->init(&np))) fail("dtNavMesh::init failed");
    return navmesh;
}

void NavMeshCore::assemble(std::vector<std::unique_ptr<TileMesh>>& tiles) {
    const rcConfig& g = cfg;
    nvp = g.maxVertsPerPoly;

    long long total = 0, total_dverts = 0, total_dtris = 0, total_verts = 0;
    for (const auto& t : tiles) {
        total += t->npolys;
        total_verts += t->nverts;
        total_dverts += static_cast<long long>(t->dverts.size() / 3);
        total_dtris += static_cast<long long>(t->dtris.size() / 4);
    }
    if (total > INT32_MAX || total_dverts > INT32_MAX || total_verts > INT32_MAX)
        fail("navmesh too large (more than 2^31 polygons or vertices)");
    nav = new_navmesh(tiles);
    first_by_tile_index.assign(static_cast<size_t>(nav->getMaxTiles()), -1);

    // Copy-out buffers.
    const bool dedup = tiles.size() > 1;
    if (dedup && (g.width >= (1 << 24) || g.height >= (1 << 24))) fail("grid too large for vertex keys");
    std::unordered_map<uint64_t, int32_t> vkey;
    if (dedup) vkey.reserve(static_cast<size_t>(total_verts));
    verts.clear();
    verts.reserve(static_cast<size_t>(total_verts) * 3);
    polys.assign(static_cast<size_t>(total) * nvp, -1);
    areas.resize(static_cast<size_t>(total));
    regions.resize(static_cast<size_t>(total));
    dverts.clear();
    detail_redone.clear();
    detail_resampled.clear();
    dverts.reserve(static_cast<size_t>(total_dverts) * 3);
    dtris.clear();
    dtris.reserve(static_cast<size_t>(total_dtris) * 3);
    dtri_poly.clear();
    dtri_poly.reserve(static_cast<size_t>(total_dtris));
    tile_first.clear();
    tile_ref_base.clear();

    int first = 0, region_offset = 0;
    std::vector<int32_t> vmap;
    for (auto& tp : tiles) {
        TileMesh& t = *tp;
        const std::string where =
            tile_size == 0 ? std::string() : " in tile (" + std::to_string(t.tx) + ", " + std::to_string(t.ty) + ")";
        // Detour tile.
        dtTileRef tref = 0;
        unsigned char* data = t.data.release();
        if (dtStatusFailed(nav->addTile(data, t.data_size, DT_TILE_FREE_DATA, 0, &tref))) {
            dtFree(data);
            fail("dtNavMesh::addTile failed" + where);
        }
        const dtMeshTile* mt = nav->getTileByRef(tref);
        tile_first.push_back(first);
        tile_ref_base.push_back(nav->getPolyRefBase(mt));
        first_by_tile_index[nav->decodePolyIdTile(static_cast<dtPolyRef>(tref))] = first;

        // Vertices: world coordinates from global grid cells; tiles share equal ones.
        vmap.resize(static_cast<size_t>(t.nverts));
        for (int i = 0; i < t.nverts; ++i) {
            const int32_t gx = t.gx0 + t.verts[i * 3 + 0], gy = t.verts[i * 3 + 1], gz = t.gz0 + t.verts[i * 3 + 2];
            if (dedup) {
                const uint64_t key = (static_cast<uint64_t>(gx) << 40) | (static_cast<uint64_t>(gz) << 16) |
                                     static_cast<uint64_t>(gy & 0xffff);
                auto ins = vkey.emplace(key, static_cast<int32_t>(verts.size() / 3));
                if (!ins.second) {
                    vmap[i] = ins.first->second;
                    continue;
                }
            }
            vmap[i] = static_cast<int32_t>(verts.size() / 3);
            verts.push_back(static_cast<double>(g.bmin[0] + static_cast<float>(gx) * g.cs));
            verts.push_back(static_cast<double>(g.bmin[1] + static_cast<float>(gy) * g.ch));
            verts.push_back(static_cast<double>(g.bmin[2] + static_cast<float>(gz) * g.cs));
        }
        // Polygons, areas, regions (offset so that ids stay unique across tiles).
        int max_region = 0;
        for (int i = 0; i < t.npolys; ++i) {
            const unsigned short* p = &t.polys[static_cast<size_t>(i) * 2 * nvp];
            int32_t* out = &polys[static_cast<size_t>(first + i) * nvp];
            for (int j = 0; j < nvp; ++j) {
                if (p[j] == RC_MESH_NULL_IDX) break;
                out[j] = vmap[p[j]];
            }
            areas[first + i] = t.areas[i];
            regions[first + i] = t.regs[i] + region_offset;
            max_region = std::max(max_region, static_cast<int>(t.regs[i]));
        }
        region_offset += max_region;
        // Detail mesh.
        const int32_t dbase = static_cast<int32_t>(dverts.size() / 3);
        for (float v : t.dverts) dverts.push_back(static_cast<double>(v));
        for (int i = 0; i < t.npolys; ++i) {
            const unsigned int vbase = t.dmeshes[i * 4 + 0], tbase = t.dmeshes[i * 4 + 2], tcount = t.dmeshes[i * 4 + 3];
            for (unsigned int k = tbase; k < tbase + tcount; ++k) {
                for (int q = 0; q < 3; ++q) dtris.push_back(dbase + static_cast<int32_t>(vbase + t.dtris[k * 4 + q]));
                dtri_poly.push_back(first + i);
            }
        }
        for (int32_t p : t.detail_redone) detail_redone.push_back(p + first);
        for (int32_t p : t.detail_resampled) detail_resampled.push_back(p + first);
        first += t.npolys;
        tp.reset();  // free the tile's copy as we go
    }
    npolys = first;

    query.reset(dtAllocNavMeshQuery());
    if (!query) fail("dtAllocNavMeshQuery failed (out of memory)");
    if (dtStatusFailed(query->init(nav.get(), 2048))) fail("dtNavMeshQuery::init failed");

    link_topology();
}

// Neighbours and portals from Detour's links (internal and tile-border alike).
void NavMeshCore::link_topology() {
    const dtNavMesh* cnav = nav.get();
    neis.assign(static_cast<size_t>(npolys) * nvp, -1);
    std::vector<double> best(static_cast<size_t>(npolys) * nvp, -1.0);
    struct Portal {
        int64_t a, b;
        int edge;
        double e[6];
    };
    std::vector<Portal> found;
    found.reserve(static_cast<size_t>(npolys) * 2);
    const double inf = std::numeric_limits<double>::infinity();
    auto V = [&](int32_t v) { return &verts[static_cast<size_t>(v) * 3]; };

    for (size_t k = 0; k < tile_first.size(); ++k) {
        // a tile's reference is its polygon-reference base
        const dtMeshTile* tile = cnav->getTileByRef(static_cast<dtTileRef>(tile_ref_base[k]));
        const int count = tile->header->polyCount;
        for (int ip = 0; ip < count; ++ip) {
            const int gi = tile_first[k] + ip;
            const dtPoly& p = tile->polys[ip];
            const int nv = p.vertCount;
            const dtPolyRef my_ref = tile_ref_base[k] | static_cast<dtPolyRef>(ip);
            for (unsigned int l = p.firstLink; l != DT_NULL_LINK; l = tile->links[l].next) {
                const dtLink& L = tile->links[l];
                const int j = L.edge;
                if (j >= nv) continue;
                const int gk = ref_to_index(L.ref);
                if (gk < 0 || gk == gi) continue;
                const int32_t A = polys[static_cast<size_t>(gi) * nvp + j];
                const int32_t B = polys[static_cast<size_t>(gi) * nvp + (j + 1) % nv];
                double score;
                const double* e0;
                const double* e1;
                double lerp[6];
                bool reverse_found = true;
                if (L.side == 0xff) {  // internal: the whole edge
                    score = inf;
                    e0 = V(A);
                    e1 = V(B);
                } else {
                    // Tile border: the shared part is the overlap of this edge and
                    // the neighbour's edge that links back (along the border line).
                    const dtMeshTile* ntile = nullptr;
                    const dtPoly* npoly = nullptr;
                    cnav->getTileAndPolyByRefUnsafe(L.ref, &ntile, &npoly);
                    int m = -1;
                    for (unsigned int l2 = npoly->firstLink; l2 != DT_NULL_LINK; l2 = ntile->links[l2].next) {
                        const dtLink& R = ntile->links[l2];
                        if (R.ref == my_ref && R.side != 0xff && R.edge < npoly->vertCount) {
                            m = R.edge;
                            break;
                        }
                    }
                    const int u = (L.side == 0 || L.side == 4) ? 2 : 0;
                    const bool forward = V(A)[u] <= V(B)[u];
                    if (m >= 0) {
                        const int32_t C = polys[static_cast<size_t>(gk) * nvp + m];
                        const int32_t D = polys[static_cast<size_t>(gk) * nvp + (m + 1) % npoly->vertCount];
                        const int32_t alo = forward ? A : B, ahi = forward ? B : A;
                        const int32_t clo = V(C)[u] <= V(D)[u] ? C : D, chi = V(C)[u] <= V(D)[u] ? D : C;
                        const int32_t lo = V(alo)[u] >= V(clo)[u] ? alo : clo;  // larger start, this edge's on ties
                        const int32_t hi = V(ahi)[u] <= V(chi)[u] ? ahi : chi;  // smaller end, this edge's on ties
                        score = V(hi)[u] - V(lo)[u];
                        e0 = V(forward ? lo : hi);
                        e1 = V(forward ? hi : lo);
                    } else {
                        // no link back (Detour keeps at most 4 links per edge): its byte-quantised sub-edge
                        reverse_found = false;
                        const double t0 = L.bmin / 255.0, t1 = L.bmax / 255.0;
                        for (int q = 0; q < 3; ++q) {
                            lerp[q] = V(A)[q] + t0 * (V(B)[q] - V(A)[q]);
                            lerp[3 + q] = V(A)[q] + t1 * (V(B)[q] - V(A)[q]);
                        }
                        e0 = lerp;
                        e1 = lerp + 3;
                        score = std::fabs(lerp[3 + u] - lerp[u]);
                    }
                }
                const size_t slot = static_cast<size_t>(gi) * nvp + j;
                if (score > best[slot] || (score == best[slot] && gk < neis[slot])) {
                    best[slot] = score;
                    neis[slot] = gk;
                }
                // Each pair once: from the lower index, or from the upper one when
                // the lower one has no link back.
                if (gi < gk || !reverse_found) {
                    Portal P{std::min(gi, gk), std::max(gi, gk), gi < gk ? j : DT_VERTS_PER_POLYGON + j, {}};
                    std::copy(e0, e0 + 3, P.e);
                    std::copy(e1, e1 + 3, P.e + 3);
                    found.push_back(P);
                }
            }
        }
    }
    std::sort(found.begin(), found.end(), [](const Portal& x, const Portal& y) {
        if (x.a != y.a) return x.a < y.a;
        if (x.b != y.b) return x.b < y.b;
        return x.edge < y.edge;
    });
    portal_pairs.clear();
    portal_ends.clear();
    for (size_t i = 0; i < found.size(); ++i) {
        if (i > 0 && found[i].a == found[i - 1].a && found[i].b == found[i - 1].b) continue;
        portal_pairs.push_back(found[i].a);
        portal_pairs.push_back(found[i].b);
        portal_ends.insert(portal_ends.end(), found[i].e, found[i].e + 6);
    }
}

void NavMeshCore::build(const float* vin, int nv, const int* tin, int nt, const Settings& s) {
    const auto t0 = std::chrono::steady_clock::now();

    // Configuration, derived from the world-unit settings as Recast's demo does.
    rcConfig& c = cfg;
    std::memset(&c, 0, sizeof(c));
    // Single-precision arithmetic throughout, as Recast's demo computes it
    // (e.g. floorf(0.4f / 0.05f) is 8 where floor(0.4 / 0.05f) is 7).
    const float cs = static_cast<float>(s.cell_size), ch = static_cast<float>(s.cell_height);
    const float cells_height = std::ceil(static_cast<float>(s.agent_height) / ch);
    const float cells_climb = std::floor(static_cast<float>(s.agent_max_climb) / ch);
    const float cells_radius = std::ceil(static_cast<float>(s.agent_radius) / cs);
    const float cells_edge = static_cast<float>(s.edge_max_len) / cs;
    const float min_area = static_cast<float>(s.region_min_size) * static_cast<float>(s.region_min_size);
    const float merge_area = static_cast<float>(s.region_merge_size) * static_cast<float>(s.region_merge_size);
    auto at_most = [](float v, long long limit, const char* what) {
        if (!(v <= static_cast<float>(limit)))
            throw nb::value_error((std::string("Recast: ") + what + " exceeds " + std::to_string(limit)).c_str());
    };
    at_most(cells_height, MAX_WALKABLE_HEIGHT, "agent_height / cell_height (cells)");
    at_most(cells_climb, MAX_WALKABLE_CLIMB, "agent_max_climb / cell_height (cells)");
    at_most(cells_radius, MAX_WALKABLE_RADIUS, "agent_radius / cell_size (cells)");
    at_most(cells_edge, MAX_EDGE_LEN_CELLS, "edge_max_len / cell_size (cells)");
    at_most(min_area, INT32_MAX, "region_min_size squared");
    at_most(merge_area, INT32_MAX, "region_merge_size squared");
    c.cs = cs;
    c.ch = ch;
    c.walkableSlopeAngle = static_cast<float>(s.agent_max_slope);
    c.walkableHeight = static_cast<int>(cells_height);
    c.walkableClimb = static_cast<int>(cells_climb);
    c.walkableRadius = static_cast<int>(cells_radius);
    c.maxEdgeLen = static_cast<int>(cells_edge);
    c.maxSimplificationError = static_cast<float>(s.edge_max_error);
    c.minRegionArea = static_cast<int>(min_area);
    c.mergeRegionArea = static_cast<int>(merge_area);
    c.maxVertsPerPoly = s.verts_per_poly;
    const float sample_dist = static_cast<float>(s.detail_sample_dist);
    c.detailSampleDist = sample_dist < 0.9f ? 0.0f : cs * sample_dist;
    c.detailSampleMaxError = ch * static_cast<float>(s.detail_sample_max_error);
    c.borderSize = 0;
    if (c.walkableHeight < 3) c.walkableHeight = 3;  // Recast's lower limit
    rcCalcBounds(vin, nv, c.bmin, c.bmax);
    // rcCalcGridSize's formula, in double so that no size overflows int
    const double grid_w = std::floor(static_cast<double>(c.bmax[0] - c.bmin[0]) / cs + 0.5);
    const double grid_h = std::floor(static_cast<double>(c.bmax[2] - c.bmin[2]) / cs + 0.5);
    if (!(grid_w >= 1.0 && grid_h >= 1.0)) fail("empty grid (degenerate bounds)");
    if (!(grid_w <= MAX_GRID_SIDE && grid_h <= MAX_GRID_SIDE))
        throw nb::value_error(("Recast: grid sides exceed " + std::to_string(MAX_GRID_SIDE) + " cells").c_str());
    if (!(static_cast<double>(c.bmax[1] - c.bmin[1]) / ch <= RC_SPAN_MAX_HEIGHT))
        throw nb::value_error(("Recast: level height exceeds " + std::to_string(RC_SPAN_MAX_HEIGHT) +
                               " cell heights").c_str());
    c.width = static_cast<int>(grid_w);
    c.height = static_cast<int>(grid_h);

    climb_tolerance = std::max(static_cast<float>(s.agent_max_climb), 2.0f * c.ch);
    const float r = std::max(static_cast<float>(2.0 * s.agent_radius), 2.0f * c.cs);
    default_ext[0] = r;
    default_ext[1] = std::max(static_cast<float>(s.agent_height), 2.0f * c.ch);
    default_ext[2] = r;

    // max_cells bounds what one rasterisation allocates: the solo grid, or one
    // tile with its border; a tiled build's tile grid is bounded by Detour's tile bits.
    const long long border = c.walkableRadius + 3;
    auto check_solo = [&]() {
        const long long cells = static_cast<long long>(c.width) * c.height;
        if (cells > s.max_cells)
            fail("grid of " + std::to_string(c.width) + " x " + std::to_string(c.height) +
                 " cells exceeds max_cells=" + std::to_string(s.max_cells) + "; use tiles or a larger cell_size");
    };
    auto check_tiled = [&](long long ts) {
        const long long side = ts + 2 * border;
        if (side * side > s.max_cells)
            fail("tiles of " + std::to_string(side) + " x " + std::to_string(side) +
                 " cells (with border) exceed max_cells=" + std::to_string(s.max_cells));
        const long long count = ((c.width + ts - 1) / ts) * ((c.height + ts - 1) / ts);
        if (count > MAX_TILES)
            fail("grid of " + std::to_string(c.width) + " x " + std::to_string(c.height) + " cells needs " +
                 std::to_string(count) + " tiles of " + std::to_string(ts) + " cells, more than " +
                 std::to_string(MAX_TILES));
    };
    const bool auto_solo = c.width <= AUTO_SOLO_MAX_CELLS && c.height <= AUTO_SOLO_MAX_CELLS &&
                           static_cast<long long>(c.width) * c.height <= s.max_cells;
    if (s.tile_size == 0 || (s.tile_size < 0 && auto_solo)) check_solo();
    if (s.tile_size > 0) check_tiled(s.tile_size);
    if (s.tile_size < 0 && !auto_solo) check_tiled(AUTO_TILE_SIZE);

    const Input in{vin, nv, tin, nt};
    std::vector<std::unique_ptr<TileMesh>> tiles;
    if (s.tile_size == 0) {
        try {
            tiles = build_solo(in, s);
        } catch (const TooBigForSolo& e) {
            throw std::runtime_error(std::string(e.what()) +
                                     "; the level is too big for a solo navmesh: use tiles "
                                     "(tile_size=None or > 0) or a larger cell_size");
        }
    } else if (s.tile_size > 0) {
        tiles = build_tiled(in, s, s.tile_size);
    } else if (auto_solo) {
        try {
            tiles = build_solo(in, s);
        } catch (const TooBigForSolo&) {
            auto_fallback = true;
        }
        if (auto_fallback) {
            check_tiled(AUTO_TILE_SIZE);
            tiles = build_tiled(in, s, AUTO_TILE_SIZE);
        }
    } else {
        tiles = build_tiled(in, s, AUTO_TILE_SIZE);
    }
    if (tile_size > 0) border_island_polygons = drop_border_islands(tiles, s);
    keep_records(tiles);
    tiles.erase(std::remove_if(tiles.begin(), tiles.end(), [](const auto& t) { return t->npolys == 0; }), tiles.end());
    if (tiles.empty()) fail("no walkable polygons (every part is smaller than region_min_size and at a tile border)");
    assemble(tiles);

    build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// ---------------------------------------------------------------- bindings

template <typename V, typename F>
NavMeshCore* build_navmesh(nb::ndarray<const V, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu> vertices,
                           nb::ndarray<const F, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu> faces,
                           double cell_size, double cell_height, double agent_height, double agent_radius,
                           double agent_max_climb, double agent_max_slope, double region_min_size,
                           double region_merge_size, double edge_max_len, double edge_max_error,
                           int verts_per_poly, double detail_sample_dist, double detail_sample_max_error,
                           long long max_cells, std::optional<int> tile_size, int threads,
                           bool filter_low_hanging_obstacles, const std::string& ledge_filter,
                           bool filter_low_height_spans, const std::string& partition,
                           bool recast_head_room, bool join_corners) {
    Settings s{cell_size, cell_height, agent_height, agent_radius, agent_max_climb, agent_max_slope,
               region_min_size, region_merge_size, edge_max_len, edge_max_error, verts_per_poly,
               detail_sample_dist, detail_sample_max_error, max_cells,
               tile_size ? *tile_size : -1, threads,
               filter_low_hanging_obstacles, filter_low_height_spans, parse_ledge_filter(ledge_filter),
               parse_partition(partition), recast_head_room, join_corners};
    if (tile_size && *tile_size < 0) throw nb::value_error("Recast: tile_size must be None (automatic), 0 (solo) or >= 16 cells");
    check_settings(s);
    const size_t nv = vertices.shape(0), nt = faces.shape(0);
    if (nv < 3 || nt < 1) throw nb::value_error("Recast: the mesh needs at least 3 vertices and 1 face");
    if (nv > static_cast<size_t>(INT32_MAX) || nt > static_cast<size_t>(INT32_MAX))
        throw nb::value_error("Recast: mesh too large");
    std::vector<float> vf(nv * 3);
    const V* vp = vertices.data();
    for (size_t i = 0; i < nv * 3; ++i) {
        if (!std::isfinite(static_cast<double>(vp[i]))) throw nb::value_error("Recast: vertices must be finite");
        vf[i] = static_cast<float>(vp[i]);
    }
    std::vector<int> tf(nt * 3);
    const F* fp = faces.data();
    for (size_t i = 0; i < nt * 3; ++i) {
        if (fp[i] < 0 || static_cast<size_t>(fp[i]) >= nv)
            throw nb::value_error("Recast: face index out of range");
        tf[i] = static_cast<int>(fp[i]);
    }
    auto core = std::make_unique<NavMeshCore>();
    {
        nb::gil_scoped_release release;
        core->build(vf.data(), static_cast<int>(nv), tf.data(), static_cast<int>(nt), s);
    }
    return core.release();
}

template <typename V, typename F>
void def_build(nb::module_& m) {
    m.def("build", &build_navmesh<V, F>, nb::arg("vertices"), nb::arg("faces"), nb::kw_only(),
          nb::arg("cell_size"), nb::arg("cell_height"), nb::arg("agent_height"), nb::arg("agent_radius"),
          nb::arg("agent_max_climb"), nb::arg("agent_max_slope"), nb::arg("region_min_size") = 8.0,
          nb::arg("region_merge_size") = 20.0, nb::arg("edge_max_len") = 12.0,
          nb::arg("edge_max_error") = 1.3, nb::arg("verts_per_poly") = 6,
          nb::arg("detail_sample_dist") = 6.0, nb::arg("detail_sample_max_error") = 1.0,
          nb::arg("max_cells") = 100000000LL, nb::arg("tile_size") = nb::none(), nb::arg("threads") = 0,
          nb::arg("filter_low_hanging_obstacles") = true, nb::arg("ledge_filter") = "recast",
          nb::arg("filter_low_height_spans") = true, nb::arg("partition") = "auto",
          nb::arg("recast_head_room") = false, nb::arg("join_corners") = true,
          nb::rv_policy::take_ownership,
          "Build a navmesh from (N,3) vertices and (M,3) triangle faces. World-unit settings, "
          "derived into Recast's voxel configuration as Recast's demo does. tile_size: None "
          "(automatic: solo when both grid sides are <= 512 cells and the solo mesh fits, "
          "else tiles of 256 cells), 0 (solo) or the tile side in cells (>= 16). threads: "
          "worker threads of a tiled build (0: hardware concurrency). max_cells: most xz cells "
          "rasterised at once (the solo grid, or one tile with its border). filter_*: run Recast's "
          "rcFilterLowHangingWalkableObstacles / rcFilterWalkableLowHeightSpans. ledge_filter: 'recast' "
          "(rcFilterLedgeSpans), 'drops' (only its first rule: drop a span beside a drop deeper than the "
          "climb) or 'off'. "
          "partition: Recast's region partition, 'auto' (watershed; a tile where a region overlaps "
          "itself in plan is redone with monotone), 'watershed' (rcBuildRegions), 'monotone' "
          "(rcBuildRegionsMonotone) or 'layers' (rcBuildLayerRegions).");
}

using Vec3In = std::array<double, 3>;
using ExtIn = std::optional<std::array<double, 3>>;
using PointsIn = nb::ndarray<const double, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;

// Rows a worker takes at a time when map_row_pairs shares them out, and the fewest rows worth a second thread
// (a thread costs tens of microseconds; the portal-node routes probe a few rows per call).
constexpr size_t PARALLEL_CHUNK = 256;

// fn(a, b) for every row pair of the (N,3) A and B (float64 rows), with the GIL released and the query lock held
// (Detour's query object is not reentrant). `parallel`, for an fn that only reads the navmesh (Detour's const
// queries queryPolygons and closestPointOnPoly, which keep no state in the query object): the rows are shared out
// in chunks between one thread per core, each writing its own rows, so the result does not depend on the count.
template <typename T, typename Fn>
std::vector<T> map_row_pairs(const NavMeshCore& n, const PointsIn& A, const PointsIn& B, Fn fn, bool parallel = false) {
    if (A.shape(0) != B.shape(0)) throw nb::value_error("A and B must have the same length");
    const size_t rows = A.shape(0);
    std::vector<T> out(rows);
    const double* a = A.data();
    const double* b = B.data();
    nb::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(n.mutex);
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t lo = next.fetch_add(PARALLEL_CHUNK); lo < rows; lo = next.fetch_add(PARALLEL_CHUNK))
            for (size_t i = lo; i < std::min(rows, lo + PARALLEL_CHUNK); ++i) out[i] = fn(a + i * 3, b + i * 3);
    };
    const size_t cores = parallel ? std::max(1u, std::thread::hardware_concurrency()) : 1;
    const size_t helpers = std::min(cores, rows / PARALLEL_CHUNK + 1) - 1;
    std::vector<std::thread> pool;
    for (size_t t = 0; t < helpers; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    return out;
}

void get3(const Vec3In& a, float* out) {
    for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(a[i]);
}

using IdsIn = nb::ndarray<const int64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using MaskIn = nb::ndarray<const bool, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using ValuesIn = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using PairsIn = nb::ndarray<const int64_t, nb::shape<-1, 2>, nb::c_contig, nb::device::cpu>;

// Algorithm 5's collapse rule as g2s_plugins/_surface.py's collapse_rule states it, on the forest's arrays (node
// indices), with `Sight` as its line of sight: sight(a, c) -> forest_simplify::Answer, asked only when the other
// tests let b go, and sight.resolve() (forest_simplify's "Batches").
// The same floating-point steps as the Python rule, so the same answers: the normals' lengths come from Python's
// math.hypot, the angle is acos of the clamped cosine times 180 / pi (math.degrees), the traffic test the
// difference of two percentiles.
template <typename Sight>
struct CollapseRule {
    const bool* on_navmesh;        // (n,)
    const double* rank;            // (n,) walking-flow percentile, NaN for a node without one
    std::optional<double> max_step;
    const double* normals;         // (n,3)
    const double* normal_length;   // (n,) math.hypot of each normal
    double tolerance_deg;
    bool whole_chain;
    Sight sight;
    static constexpr bool batches = Sight::batches;

    bool bent(int64_t u, int64_t v) const {
        const double lengths = normal_length[u] * normal_length[v];
        if (!(lengths > 0)) return true;  // the Python rule's infinite angle
        const double* p = normals + 3 * u;
        const double* q = normals + 3 * v;
        const double cosine = (p[0] * q[0] + p[1] * q[1] + p[2] * q[2]) / lengths;
        return std::acos(std::min(1.0, std::max(-1.0, cosine))) * (180.0 / M_PI) > tolerance_deg;
    }

    bool step_too_large(int64_t a, int64_t b, int64_t c) const {
        const double rb = rank[b];
        if (!max_step || std::isnan(rb)) return false;
        const double ra = std::isnan(rank[a]) ? rb : rank[a], rc = std::isnan(rank[c]) ? rb : rank[c];
        return std::fabs(ra - rb) > *max_step || std::fabs(rc - rb) > *max_step;
    }

    forest_simplify::Answer operator()(int64_t a, int64_t b, int64_t c, bool c_is_leaf) {
        if (!on_navmesh[c] && c_is_leaf) return forest_simplify::Answer::no;
        if (step_too_large(a, b, c) || bent(a, b) || (whole_chain && (bent(b, c) || bent(a, c))))
            return forest_simplify::Answer::no;
        return sight(a, c);
    }

    void resolve() const { sight.resolve(); }
};

// Lines of sight NavMeshSight answered before, kept between collapse_forest calls of one navmesh and one probe
// setting (the heat guarantee's later rounds ask about 98 % of their chains again on the 100k-polygon level): the
// answer for a segment depends on its two end points alone, so a segment's six coordinates (their bits) key it.
// During a call the threads only read `known` and add what they test to `found` (under `mutex`); the call then
// moves `found` into `known` (under `mutex` too: len() may be asked from another Python thread).
struct SightMemo {
    using Segment = std::array<double, 6>;
    struct Hash {
        size_t operator()(const Segment& s) const {
            uint64_t h = 1469598103934665603ull;  // FNV-1a over the coordinates' bits
            for (double x : s) {
                uint64_t bits;
                std::memcpy(&bits, &x, sizeof bits);
                h = (h ^ bits) * 1099511628211ull;
            }
            return static_cast<size_t>(h ^ (h >> 32));
        }
    };
    struct Same {
        bool operator()(const Segment& x, const Segment& y) const { return std::memcmp(x.data(), y.data(), sizeof x) == 0; }
    };
    std::unordered_map<Segment, bool, Hash, Same> known;
    std::vector<std::pair<Segment, bool>> found;
    std::atomic<size_t> hits{0};  // tests answered from `known`
    std::optional<std::tuple<const NavMeshCore*, double, float, std::optional<double>>> setting;  // of the first call
    std::mutex mutex;

    void keep_found() {
        std::lock_guard<std::mutex> lock(mutex);
        known.reserve(known.size() + found.size());
        for (const auto& [segment, clear] : found) known.emplace(segment, clear);
        found.clear();
    }
};

// The surface_los predicate's line of sight (NavMeshCore::sees, the line_of_sight binding's test) between the
// points of two nodes; with a memo, each segment's answer is looked up there first and kept there once found.
struct NavMeshSight {
    const NavMeshCore& nav;
    const double* points;          // (n,3) positions, the navmesh's local frame
    double step;
    float horizontal;
    std::optional<double> max_gap;
    SightMemo* memo = nullptr;
    std::vector<dtPolyRef> path = std::vector<dtPolyRef>(256);
    // the polygon nearest the last A asked (Algorithm 4 asks every chain from one A in a row): Detour's answer for
    // a point depends on the point alone
    int64_t from = -1;
    dtPolyRef start_ref = 0;
    float start[3] = {0, 0, 0};
    static constexpr bool batches = false;

    forest_simplify::Answer operator()(int64_t a, int64_t c) {
        const double* pa = points + 3 * a;
        const double* pc = points + 3 * c;
        const SightMemo::Segment segment{pa[0], pa[1], pa[2], pc[0], pc[1], pc[2]};
        if (memo != nullptr) {
            const auto it = memo->known.find(segment);
            if (it != memo->known.end()) {
                ++memo->hits;
                return it->second ? forest_simplify::Answer::yes : forest_simplify::Answer::no;
            }
        }
        if (a != from) {
            const float fa[3] = {static_cast<float>(pa[0]), static_cast<float>(pa[1]), static_cast<float>(pa[2])};
            from = a;
            if (dtStatusFailed(nav.query->findNearestPoly(fa, nav.default_ext, &nav.filter, &start_ref, start))) start_ref = 0;
        }
        const bool clear = nav.sees(start_ref, start, pa, pc, step, horizontal, max_gap, path);
        if (memo != nullptr) {
            std::lock_guard<std::mutex> lock(memo->mutex);
            memo->found.emplace_back(segment, clear);
        }
        return clear ? forest_simplify::Answer::yes : forest_simplify::Answer::no;
    }

    void resolve() const {}  // every answer given at once
};

// Lines of sight asked of Python in batches (the mesh_los predicate's walk test): the pairs of node indices asked
// and not answered yet, and the answers so far, for one simplification; with a memo, the answers sees() gave in
// earlier calls too, by segment (the forest's points of a and c), both ways round.
struct AskedSights {
    PyObject* sees;  // sees(pairs (k,2) int64) -> (k,) bool; borrowed: the binding's argument keeps it alive
    std::vector<int64_t> asked;  // (k,2) flattened
    std::unordered_map<uint64_t, bool> known;  // a * n + c
    uint64_t n;
    const double* points = nullptr;  // (n,3), the memo's keys
    SightMemo* memo = nullptr;

    SightMemo::Segment segment(int64_t from, int64_t to) const {
        const double* p = points + 3 * from;
        const double* q = points + 3 * to;
        return {p[0], p[1], p[2], q[0], q[1], q[2]};
    }
};

// The line of sight of AskedSights: a pair not answered yet is `later`, and resolve() asks sees() about every such
// pair in one call. On one thread, with the GIL held (the copies forest_simplify makes share the one AskedSights).
// The memo serves the heat guarantee's later rounds, which ask about most of their chains again (a pair answered
// before waits for no batch, and a batch of such pairs alone costs no call): it holds an answer both ways round,
// as the predicate's own cache does (g2s_plugins/predicates/mesh_los.py), so it answers what sees() would.
struct PythonSight {
    AskedSights* sights;
    static constexpr bool batches = true;

    forest_simplify::Answer operator()(int64_t a, int64_t c) const {
        const uint64_t key = static_cast<uint64_t>(a) * sights->n + static_cast<uint64_t>(c);
        auto it = sights->known.find(key);
        if (it == sights->known.end() && sights->memo != nullptr) {
            const auto remembered = sights->memo->known.find(sights->segment(a, c));
            if (remembered != sights->memo->known.end()) {
                ++sights->memo->hits;
                it = sights->known.emplace(key, remembered->second).first;
            }
        }
        if (it != sights->known.end()) return it->second ? forest_simplify::Answer::yes : forest_simplify::Answer::no;
        sights->asked.insert(sights->asked.end(), {a, c});
        return forest_simplify::Answer::later;
    }

    void resolve() const {
        std::vector<int64_t>& asked = sights->asked;
        const size_t count = asked.size() / 2;
        const nb::object answers = nb::handle(sights->sees)(to_numpy(asked, count, 2));
        const auto ok = nb::cast<nb::ndarray<const bool, nb::ndim<1>, nb::c_contig, nb::device::cpu>>(answers);
        if (ok.shape(0) != count) throw nb::value_error("sees must answer every pair it is given");
        for (size_t k = 0; k < count; ++k) {
            const int64_t a = asked[2 * k], c = asked[2 * k + 1];
            sights->known[static_cast<uint64_t>(a) * sights->n + static_cast<uint64_t>(c)] = ok.data()[k];
            if (sights->memo != nullptr) {
                std::lock_guard<std::mutex> lock(sights->memo->mutex);
                sights->memo->known.emplace(sights->segment(a, c), ok.data()[k]);
                sights->memo->known.emplace(sights->segment(c, a), ok.data()[k]);
            }
        }
        asked.clear();
    }
};

// The forest of the collapse_forest bindings' arrays, once every per-node array (`rows`: the others' row counts)
// has a row per node and parent, loops and roots hold node indices.
forest_simplify::Forest checked_forest(const IdsIn& ids, const IdsIn& parent, const IdsIn& depth, const MaskIn& fixed,
                                       const PairsIn& loops, const IdsIn& roots, std::initializer_list<size_t> rows) {
    const size_t count = ids.shape(0);
    if (parent.shape(0) != count || depth.shape(0) != count || fixed.shape(0) != count ||
        std::any_of(rows.begin(), rows.end(), [&](size_t other) { return other != count; }))
        throw nb::value_error("every per-node array must have one row per node");
    const int64_t size = static_cast<int64_t>(count);
    auto inside = [&](const int64_t* first, size_t length, int64_t low) {
        return std::all_of(first, first + length, [&](int64_t i) { return i >= low && i < size; });
    };
    if (!inside(parent.data(), count, -1) || !inside(loops.data(), 2 * loops.shape(0), 0) ||
        !inside(roots.data(), roots.shape(0), 0))
        throw nb::value_error("parent, loops and roots must hold node indices");
    forest_simplify::Forest f;
    f.n = count; f.ids = ids.data(); f.parent = parent.data(); f.depth = depth.data(); f.fixed = fixed.data();
    f.m = loops.shape(0); f.loops = loops.data(); f.r = roots.shape(0); f.roots = roots.data();
    return f;
}

nb::object bool_numpy(const std::vector<uint8_t>& src) {  // (N,) numpy bool of 0/1 bytes
    auto* buf = new uint8_t[src.empty() ? 1 : src.size()];
    std::copy(src.begin(), src.end(), buf);
    nb::capsule owner(buf, [](void* p) noexcept { delete[] static_cast<uint8_t*>(p); });
    return nb::cast(nb::ndarray<nb::numpy, bool>(reinterpret_cast<bool*>(buf), {src.size()}, owner), nb::rv_policy::move);
}

// (kept (n,) bool, added (k,2) int64, loop (k,) bool) as numpy arrays: the collapse_forest bindings' answer
nb::object simplified_numpy(const forest_simplify::Simplified& s) {
    return nb::make_tuple(bool_numpy(s.kept), to_numpy(s.added, s.loop.size(), 2), bool_numpy(s.loop));
}

}  // namespace

NB_MODULE(_recast, m) {
    m.doc() = "Recast/Detour (solo or tiled navmesh) bindings for g2s; see g2s_plugins.recast.";

    nb::class_<SightMemo>(m, "SightMemo",
                          "Lines of sight collapse_forest answered, by segment, kept for its later calls with the "
                          "same navmesh, step, horizontal and max_gap")
        .def(nb::init<>())
        .def("__len__", [](SightMemo& memo) {
            std::lock_guard<std::mutex> lock(memo.mutex);
            return memo.known.size();
        }, "segments answered")
        .def_prop_ro("hits", [](const SightMemo& memo) { return memo.hits.load(); },
                     "tests answered from the memo instead of Detour");

    nb::class_<NavMeshCore>(m, "NavMeshCore",
                            "A built navmesh (solo or tiled): copied mesh arrays and Detour queries.")
        .def_prop_ro("nvp", [](const NavMeshCore& n) { return n.nvp; }, "max vertices per polygon")
        .def_prop_ro("polygon_count", [](const NavMeshCore& n) { return n.npolys; })
        .def_prop_ro("vertices", [](const NavMeshCore& n) { return to_numpy(n.verts, n.verts.size() / 3, 3); },
                     "(V,3) float64 polygon vertices, world coordinates")
        .def_prop_ro("polygons", [](const NavMeshCore& n) { return to_numpy(n.polys, n.npolys, n.nvp); },
                     "(P,nvp) int32 vertex indices, padded with -1")
        .def_prop_ro("neighbours", [](const NavMeshCore& n) { return to_numpy(n.neis, n.npolys, n.nvp); },
                     "(P,nvp) int32: polygon across edge j (vertex j -> j+1, wrapping), -1 at the boundary; "
                     "on a tile border edge touching several polygons, the one sharing the longest part")
        .def_prop_ro("area_ids", [](const NavMeshCore& n) { return to_numpy(n.areas, n.npolys, 0); },
                     "(P,) int32 Recast area ids (63 = walkable)")
        .def_prop_ro("region_ids", [](const NavMeshCore& n) { return to_numpy(n.regions, n.npolys, 0); },
                     "(P,) int32 Recast region ids (offset per tile so that they are unique)")
        .def_prop_ro("detail_vertices",
                     [](const NavMeshCore& n) { return to_numpy(n.dverts, n.dverts.size() / 3, 3); },
                     "(DV,3) float64 detail mesh vertices, world coordinates")
        .def_prop_ro("detail_triangles",
                     [](const NavMeshCore& n) { return to_numpy(n.dtris, n.dtris.size() / 3, 3); },
                     "(DT,3) int32 indices into detail_vertices")
        .def_prop_ro("detail_polygon", [](const NavMeshCore& n) { return to_numpy(n.dtri_poly, n.dtri_poly.size(), 0); },
                     "(DT,) int32 polygon owning each detail triangle")
        .def_prop_ro("portal_pairs",
                     [](const NavMeshCore& n) { return to_numpy(n.portal_pairs, n.portal_pairs.size() / 2, 2); },
                     "(E,2) int64: every pair of adjacent polygons a < b once, sorted")
        .def_prop_ro("portal_endpoints",
                     [](const NavMeshCore& n) { return to_numpy(n.portal_ends, n.portal_ends.size() / 6, 2, 3); },
                     "(E,2,3) float64: end points of the segment the pair shares, along a's edge")
        .def_prop_ro("region_overlaps",
                     [](const NavMeshCore& n) { return to_numpy(n.overlaps, n.overlaps.size() / 3, 3); },
                     "(K,3) float64: a span (world x, floor y, z) of each Recast region that overlaps itself "
                     "in plan, tile by tile (left in the built navmesh: none with partition 'auto'); in a tiled "
                     "build not those of the small parts at tile borders that are dropped")
        .def_prop_ro("repartitioned_tiles",
                     [](const NavMeshCore& n) { return to_numpy(n.repartitioned, n.repartitioned.size() / 2, 2); },
                     "(R,2) int32: tile (x, z) of each tile whose watershed regions overlapped and were redone "
                     "by the 'auto' partition and that holds polygons, row-major order; (0, 0) for a solo navmesh")
        .def_prop_ro("detail_redone_polygons",
                     [](const NavMeshCore& n) { return to_numpy(n.detail_redone, n.detail_redone.size(), 0); },
                     "(N,) int32: polygons whose detail heights Recast read from their region on another "
                     "storey (a region winding back over itself, e.g. round a spiral stair), rebuilt from "
                     "their own storey; ascending")
        .def_prop_ro("detail_resampled_polygons",
                     [](const NavMeshCore& n) { return to_numpy(n.detail_resampled, n.detail_resampled.size(), 0); },
                     "(N,) int32: polygons whose detail triangles left the floor under them by more than the "
                     "agent's climb (too narrow for Recast's inside samples, bent along a ramp's foot or crest), "
                     "rebuilt with finer samples; ascending")
        .def_prop_ro("tile_size", [](const NavMeshCore& n) { return n.tile_size; },
                     "tile side in cells; 0 for a solo navmesh")
        .def_prop_ro("tile_count", [](const NavMeshCore& n) { return static_cast<int>(n.tile_first.size()); },
                     "number of Detour tiles (tiles with polygons)")
        .def_prop_ro("tile_first_polygon",
                     [](const NavMeshCore& n) {
                         std::vector<int32_t> v(n.tile_first.begin(), n.tile_first.end());
                         return to_numpy(v, v.size(), 0);
                     },
                     "(T,) int32 global index of each tile's first polygon (tiles in row-major order)")
        .def_prop_ro("build_seconds", [](const NavMeshCore& n) { return n.build_seconds; })
        .def_prop_ro("climb_tolerance", [](const NavMeshCore& n) { return n.climb_tolerance; },
                     "vertical tolerance of raycast's end check: max(agent_max_climb, 2*cell_height)")
        .def_prop_ro("default_extents",
                     [](const NavMeshCore& n) {
                         return nb::make_tuple(n.default_ext[0], n.default_ext[1], n.default_ext[2]);
                     },
                     "half extents used when none are given: (max(2r, 2cs), max(h, 2ch), max(2r, 2cs))")
        .def("config",
             [](const NavMeshCore& n) {
                 const rcConfig& c = n.cfg;
                 nb::dict d;
                 d["cs"] = c.cs; d["ch"] = c.ch; d["width"] = c.width; d["height"] = c.height;
                 d["bmin"] = nb::make_tuple(c.bmin[0], c.bmin[1], c.bmin[2]);
                 d["bmax"] = nb::make_tuple(c.bmax[0], c.bmax[1], c.bmax[2]);
                 d["walkableSlopeAngle"] = c.walkableSlopeAngle;
                 d["walkableHeight"] = c.walkableHeight; d["walkableClimb"] = c.walkableClimb;
                 d["walkableRadius"] = c.walkableRadius; d["maxEdgeLen"] = c.maxEdgeLen;
                 d["maxSimplificationError"] = c.maxSimplificationError;
                 d["minRegionArea"] = c.minRegionArea; d["mergeRegionArea"] = c.mergeRegionArea;
                 d["maxVertsPerPoly"] = c.maxVertsPerPoly; d["detailSampleDist"] = c.detailSampleDist;
                 d["detailSampleMaxError"] = c.detailSampleMaxError;
                 d["tileSize"] = n.tile_size; d["borderSize"] = n.border_size;
                 d["tileGrid"] = nb::make_tuple(n.tiles_x, n.tiles_y);
                 d["tiles"] = static_cast<int>(n.tile_first.size());
                 d["autoTiled"] = n.auto_fallback;
                 d["borderIslandPolygons"] = n.border_island_polygons;
                 return d;
             },
             "the resolved rcConfig (voxel units; width/height: the whole grid) as a dict, plus the "
             "tiling: tileSize (0: solo), borderSize, tileGrid (x, z tile counts), tiles (non-empty), "
             "autoTiled (automatic mode fell back to tiles because the solo build was too big), "
             "borderIslandPolygons (polygons of parts under minRegionArea cells at tile borders taken out)")
        .def("raycast",
             [](const NavMeshCore& n, Vec3In a, Vec3In b, ExtIn extents) {
                 float pa[3], pb[3], ext[3] = {n.default_ext[0], n.default_ext[1], n.default_ext[2]};
                 get3(a, pa); get3(b, pb);
                 if (extents) get3(*extents, ext);
                 std::vector<dtPolyRef> path(256);
                 std::pair<bool, float> r;
                 {
                     nb::gil_scoped_release release;
                     std::lock_guard<std::mutex> lock(n.mutex);
                     r = n.ray(pa, pb, ext, path);
                 }
                 return nb::make_tuple(r.first, r.second);
             },
             nb::arg("a"), nb::arg("b"), nb::arg("extents") = nb::none(),
             "(clear, t): Detour raycast from the polygon nearest a towards b, plus the height check at b")
        .def("raycast_many",
             [](const NavMeshCore& n, PointsIn A, PointsIn B, ExtIn extents) {
                 float ext[3] = {n.default_ext[0], n.default_ext[1], n.default_ext[2]};
                 if (extents) get3(*extents, ext);
                 std::vector<dtPolyRef> path(256);
                 const std::vector<uint8_t> out = map_row_pairs<uint8_t>(n, A, B, [&](const double* pa, const double* pb) {
                     const float a[3] = {static_cast<float>(pa[0]), static_cast<float>(pa[1]), static_cast<float>(pa[2])};
                     const float b[3] = {static_cast<float>(pb[0]), static_cast<float>(pb[1]), static_cast<float>(pb[2])};
                     return static_cast<uint8_t>(n.ray(a, b, ext, path).first ? 1 : 0);
                 });
                 return bool_numpy(out);
             },
             nb::arg("A"), nb::arg("B"), nb::arg("extents") = nb::none(),
             "(N,) bool: raycast(A[i], B[i]).clear for every row, GIL released")
        .def("segment_surface_gaps",
             [](const NavMeshCore& n, PointsIn A, PointsIn B, double step, float horizontal, float reach) {
                 if (!(step > 0)) throw nb::value_error("step must be positive");
                 const std::vector<double> out = map_row_pairs<double>(n, A, B, [&](const double* a, const double* b) {
                     return n.segment_gap(a, b, step, horizontal, reach);
                 }, true);
                 return to_numpy(out, out.size(), 0);
             },
             nb::arg("A"), nb::arg("B"), nb::arg("step"), nb::arg("horizontal"), nb::arg("reach"),
             "(S,) float64: the largest vertical distance to the walkable surface (see surface_gap) over "
             "points at most `step` apart horizontally along each segment A[i] -> B[i], ends included; "
             "inf when a point has none within `reach`; GIL released, rows shared between the cores")
        .def("segment_surface_gap",
             [](const NavMeshCore& n, Vec3In a, Vec3In b, double step, float horizontal, float reach) {
                 if (!(step > 0)) throw nb::value_error("step must be positive");
                 std::lock_guard<std::mutex> lock(n.mutex);
                 return n.segment_gap(a.data(), b.data(), step, horizontal, reach);
             },
             nb::arg("a"), nb::arg("b"), nb::arg("step"), nb::arg("horizontal"), nb::arg("reach"),
             "segment_surface_gaps for one segment a -> b, as a float: no array in or out (one call per "
             "predicate test)")
        .def("line_of_sight",
             [](const NavMeshCore& n, Vec3In a, Vec3In b, double step, float horizontal, std::optional<double> max_gap) {
                 if (!(step > 0)) throw nb::value_error("step must be positive");
                 float pa[3], start[3];
                 get3(a, pa);
                 thread_local std::vector<dtPolyRef> path(256);  // raycast's corridor, kept between the calls
                 nb::gil_scoped_release release;
                 std::lock_guard<std::mutex> lock(n.mutex);
                 dtPolyRef start_ref = 0;
                 if (dtStatusFailed(n.query->findNearestPoly(pa, n.default_ext, &n.filter, &start_ref, start))) start_ref = 0;
                 return n.sees(start_ref, start, a.data(), b.data(), step, horizontal, max_gap, path);
             },
             nb::arg("a"), nb::arg("b"), nb::arg("step"), nb::arg("horizontal"), nb::arg("max_gap").none(),
             "raycast(a, b) is clear and, unless max_gap is None, segment_surface_gap(a, b, step, horizontal, "
             "reach=max_gap) <= max_gap: both tests in one call, GIL released (the surface_los predicate's)")
        .def("collapse_forest",
             [](const NavMeshCore& n, IdsIn ids, IdsIn parent, IdsIn depth, MaskIn fixed, PairsIn loops, IdsIn roots,
                PointsIn points, MaskIn on_navmesh, ValuesIn rank, std::optional<double> max_step, PointsIn normals,
                ValuesIn normal_length, double tolerance_deg, bool whole_chain, double step, float horizontal,
                std::optional<double> max_gap, SightMemo* memo) {
                 if (!(step > 0)) throw nb::value_error("step must be positive");
                 const forest_simplify::Forest f = checked_forest(
                     ids, parent, depth, fixed, loops, roots,
                     {points.shape(0), on_navmesh.shape(0), rank.shape(0), normals.shape(0), normal_length.shape(0)});
                 if (memo != nullptr) {
                     const auto setting = std::make_tuple(&n, step, horizontal, max_gap);
                     if (!memo->setting) memo->setting = setting;
                     if (*memo->setting != setting)
                         throw nb::value_error("a sight memo holds the answers of one navmesh, step, horizontal and max_gap");
                 }
                 CollapseRule<NavMeshSight> rule{on_navmesh.data(), rank.data(), max_step, normals.data(),
                                                 normal_length.data(), tolerance_deg, whole_chain,
                                                 NavMeshSight{n, points.data(), step, horizontal, max_gap, memo}};
                 forest_simplify::Simplified s;
                 {
                     nb::gil_scoped_release release;
                     std::lock_guard<std::mutex> lock(n.mutex);
                     s = forest_simplify::simplify(f, rule, std::max(1u, std::thread::hardware_concurrency()));
                     if (memo != nullptr) memo->keep_found();
                 }
                 return simplified_numpy(s);
             },
             nb::arg("ids"), nb::arg("parent"), nb::arg("depth"), nb::arg("fixed"), nb::arg("loops"), nb::arg("roots"),
             nb::arg("points"), nb::arg("on_navmesh"), nb::arg("rank"), nb::arg("max_step").none(), nb::arg("normals"),
             nb::arg("normal_length"), nb::arg("tolerance_deg"), nb::arg("whole_chain"), nb::arg("step"),
             nb::arg("horizontal"), nb::arg("max_gap").none(), nb::arg("memo").none() = nb::none(),
             "(kept (n,) bool, added (k,2) int64, loop (k,) bool): the paper's Algorithm 4 and the loop pass of "
             "g2s_core/simplify.py on a rooted forest of n nodes (ids, tree parent index or -1, depth, fixed: never "
             "removed, loop edges (m,2), root indices), with Algorithm 5's collapse rule (g2s_plugins/_surface.py) "
             "and line_of_sight(points[a], points[c], step, horizontal, max_gap) as the predicate; the edges added, "
             "in the order they were added; GIL released, the walks below different kept nodes shared between the "
             "cores (the same answer on any number). memo (a SightMemo or None): lines of sight answered by earlier "
             "calls with the same navmesh, step, horizontal and max_gap, looked up before each test and added to "
             "(ValueError for a memo of other settings)")
        .def("nearest_poly",
             [](const NavMeshCore& n, Vec3In p, ExtIn extents) {
                 float pp[3], out[3], ext[3] = {n.default_ext[0], n.default_ext[1], n.default_ext[2]};
                 get3(p, pp);
                 if (extents) get3(*extents, ext);
                 int idx;
                 {
                     std::lock_guard<std::mutex> lock(n.mutex);
                     idx = n.nearest(pp, ext, out);
                 }
                 std::vector<double> o{out[0], out[1], out[2]};
                 return nb::make_tuple(idx, to_numpy(o, 3, 0));
             },
             nb::arg("p"), nb::arg("extents") = nb::none(),
             "(polygon index or -1, (3,) nearest point) within the half extents")
        .def("poly_ref", [](const NavMeshCore& n, int index) { return static_cast<uint64_t>(n.index_to_ref(index)); },
             nb::arg("index"), "Detour dtPolyRef of a polygon index")
        .def("poly_index",
             [](const NavMeshCore& n, uint64_t ref) {
                 if (ref == 0) return -1;
                 if (ref > std::numeric_limits<dtPolyRef>::max() || !n.nav->isValidPolyRef(static_cast<dtPolyRef>(ref)))
                     throw nb::value_error("invalid dtPolyRef");
                 return n.ref_to_index(static_cast<dtPolyRef>(ref));
             },
             nb::arg("ref"), "global polygon index of a Detour dtPolyRef (tile's first index + decodePolyIdPoly); -1 for 0");

    m.def("collapse_forest",
          [](IdsIn ids, IdsIn parent, IdsIn depth, MaskIn fixed, PairsIn loops, IdsIn roots, MaskIn on_navmesh,
             ValuesIn rank, std::optional<double> max_step, PointsIn normals, ValuesIn normal_length,
             double tolerance_deg, bool whole_chain, nb::callable sees, PointsIn points, SightMemo* memo) {
              const forest_simplify::Forest f = checked_forest(
                  ids, parent, depth, fixed, loops, roots,
                  {on_navmesh.shape(0), rank.shape(0), normals.shape(0), normal_length.shape(0), points.shape(0)});
              if (memo != nullptr) {  // a navmesh's memo names its navmesh; one of sees() answers, none
                  const decltype(memo->setting) none_setting{std::make_tuple(nullptr, 0.0, 0.0f, std::nullopt)};
                  if (!memo->setting) memo->setting = none_setting;
                  if (memo->setting != none_setting)
                      throw nb::value_error("a sight memo of a navmesh's collapse_forest holds no answers of sees");
              }
              AskedSights sights{sees.ptr(), {}, {}, f.n, points.data(), memo};
              CollapseRule<PythonSight> rule{on_navmesh.data(), rank.data(), max_step, normals.data(),
                                             normal_length.data(), tolerance_deg, whole_chain, PythonSight{&sights}};
              return simplified_numpy(forest_simplify::simplify(f, rule, 1));
          },
          nb::arg("ids"), nb::arg("parent"), nb::arg("depth"), nb::arg("fixed"), nb::arg("loops"), nb::arg("roots"),
          nb::arg("on_navmesh"), nb::arg("rank"), nb::arg("max_step").none(), nb::arg("normals"),
          nb::arg("normal_length"), nb::arg("tolerance_deg"), nb::arg("whole_chain"), nb::arg("sees"),
          nb::arg("points"), nb::arg("memo").none() = nb::none(),
          "NavMesh.collapse_forest's answer with the line of sight sees(pairs) -> (k,) bool, a Python callable of "
          "(k,2) int64 rows (a, c) of node indices, instead of the navmesh's: Algorithm 4 and Algorithm 5's other "
          "tests in C++ on one thread, the callable asked only for the chains those let b go, in batches: every "
          "walk below a kept node goes on until it is done or needs an answer not given yet, and then the pairs "
          "they all asked for are given in one call (src/forest_simplify.hpp, \"Batches\"). points (n,3): the nodes' "
          "positions; memo (a SightMemo or None): what sees answered in earlier calls for the same segments (points "
          "of a and c, either way round), looked up before a pair is asked and added to; ValueError for a navmesh's");

    def_build<float, int32_t>(m);
    def_build<double, int32_t>(m);
    def_build<float, int64_t>(m);
    def_build<double, int64_t>(m);
    m.attr("DT_VERTS_PER_POLYGON") = DT_VERTS_PER_POLYGON;
    m.def("least_diagonal_triangulation",
          [](nb::ndarray<const double, nb::shape<-1, 2>, nb::c_contig, nb::device::cpu> points, double flat_area) {
              std::vector<std::array<double, 2>> outline(points.shape(0));
              for (size_t k = 0; k < outline.size(); ++k) outline[k] = {points(k, 0), points(k, 1)};
              std::vector<int32_t> flat;
              for (const auto& t : least_diagonal_triangulation(outline, flat_area)) flat.insert(flat.end(), t.begin(), t.end());
              return to_numpy(flat, flat.size() / 3, 3);
          },
          nb::arg("points"), nb::arg("flat_area") = 1e-12,
          "(n-2,3) int32: the triangulation of least total diagonal length of the convex polygon whose "
          "(n,2) float64 plan points are given in order round it (the rule that retriangulates a detail "
          "polygon with no inside samples), as rows (a, k, b) of point indices, a < k < b, so wound as "
          "the points are; dynamic programming, O(n^3). Triangles whose doubled area is under "
          "flat_area (collinear points) are never used. (0,3) for fewer than 3 points or when every "
          "triangulation needs such a triangle.");
}

