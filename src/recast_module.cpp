// g2s_plugins.recast._recast: a solo Recast navmesh build and Detour queries.
//
// The build follows Recast's standard single-tile pipeline; the mesh data
// (polygons, neighbours, detail triangles) is copied out of the Recast
// structures into plain vectors, and the Detour navmesh + query object are
// kept for raycasts and nearest-polygon look-ups.

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/array.h>
#include <nanobind/stl/optional.h>

#include <Recast.h>
#include <DetourAlloc.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshBuilder.h>
#include <DetourNavMeshQuery.h>
#include <DetourStatus.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
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

[[noreturn]] void fail(const std::string& step, const LogContext* ctx = nullptr) {
    std::string msg = "Recast: " + step;
    if (ctx && !ctx->errors.empty()) msg += " (" + ctx->errors + ")";
    throw std::runtime_error(msg);
}

struct HeightfieldDel { void operator()(rcHeightfield* p) const { rcFreeHeightField(p); } };
struct CompactDel { void operator()(rcCompactHeightfield* p) const { rcFreeCompactHeightfield(p); } };
struct ContourDel { void operator()(rcContourSet* p) const { rcFreeContourSet(p); } };
struct PolyMeshDel { void operator()(rcPolyMesh* p) const { rcFreePolyMesh(p); } };
struct DetailDel { void operator()(rcPolyMeshDetail* p) const { rcFreePolyMeshDetail(p); } };
struct NavMeshDel { void operator()(dtNavMesh* p) const { dtFreeNavMesh(p); } };
struct QueryDel { void operator()(dtNavMeshQuery* p) const { dtFreeNavMeshQuery(p); } };

template <typename T>
nb::object to_numpy(const std::vector<T>& src, size_t rows, size_t cols) {
    auto* copy = new std::vector<T>(src);
    if (copy->empty()) copy->resize(1);  // keep a valid data pointer for empty arrays
    nb::capsule owner(copy, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
    if (cols == 0) return nb::cast(nb::ndarray<nb::numpy, T>(copy->data(), {rows}, owner), nb::rv_policy::move);
    return nb::cast(nb::ndarray<nb::numpy, T>(copy->data(), {rows, cols}, owner), nb::rv_policy::move);
}

// ---------------------------------------------------------------- settings

struct Settings {
    double cell_size, cell_height;
    double agent_height, agent_radius, agent_max_climb, agent_max_slope;
    double region_min_size, region_merge_size;
    double edge_max_len, edge_max_error;
    int verts_per_poly;
    double detail_sample_dist, detail_sample_max_error;
    long long max_cells;
};

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
    int npolys = 0;

    // Resolved Recast configuration.
    rcConfig cfg{};
    double build_seconds = 0.0;
    float climb_tolerance = 0.0f;
    float default_ext[3] = {0, 0, 0};

    std::unique_ptr<dtNavMesh, NavMeshDel> nav;
    std::unique_ptr<dtNavMeshQuery, QueryDel> query;
    dtQueryFilter filter;  // default: all areas, include all flags
    dtPolyRef ref_base = 0;
    mutable std::mutex mutex;

    void build(const float* vin, int nv, const int* tin, int nt, const Settings& s);

    // Index <-> reference for the single tile.
    int ref_to_index(dtPolyRef ref) const {
        if (ref == 0) return -1;
        return static_cast<int>(nav->decodePolyIdPoly(ref));
    }
    dtPolyRef index_to_ref(int index) const {
        if (index < 0 || index >= npolys) throw nb::index_error("polygon index out of range");
        return ref_base | static_cast<dtPolyRef>(index);
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
        for (;;) {
            dtRaycastHit hit{};
            hit.path = path.data();
            hit.maxPath = static_cast<int>(path.size());
            st = query->raycast(startRef, start, b, &filter, 0, &hit);
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
};

void NavMeshCore::build(const float* vin, int nv, const int* tin, int nt, const Settings& s) {
    const auto t0 = std::chrono::steady_clock::now();
    LogContext ctx;

    // Configuration, derived from the world-unit settings as Recast's demo does.
    rcConfig& c = cfg;
    std::memset(&c, 0, sizeof(c));
    c.cs = static_cast<float>(s.cell_size);
    c.ch = static_cast<float>(s.cell_height);
    c.walkableSlopeAngle = static_cast<float>(s.agent_max_slope);
    c.walkableHeight = static_cast<int>(std::ceil(s.agent_height / c.ch));
    c.walkableClimb = static_cast<int>(std::floor(s.agent_max_climb / c.ch));
    c.walkableRadius = static_cast<int>(std::ceil(s.agent_radius / c.cs));
    c.maxEdgeLen = static_cast<int>(s.edge_max_len / s.cell_size);
    c.maxSimplificationError = static_cast<float>(s.edge_max_error);
    c.minRegionArea = static_cast<int>(s.region_min_size * s.region_min_size);
    c.mergeRegionArea = static_cast<int>(s.region_merge_size * s.region_merge_size);
    c.maxVertsPerPoly = s.verts_per_poly;
    c.detailSampleDist = s.detail_sample_dist < 0.9 ? 0.0f : static_cast<float>(s.cell_size * s.detail_sample_dist);
    c.detailSampleMaxError = static_cast<float>(s.cell_height * s.detail_sample_max_error);
    c.borderSize = 0;
    if (c.walkableHeight < 3) c.walkableHeight = 3;  // Recast's lower limit
    rcCalcBounds(vin, nv, c.bmin, c.bmax);
    rcCalcGridSize(c.bmin, c.bmax, c.cs, &c.width, &c.height);
    const long long cells = static_cast<long long>(c.width) * c.height;
    if (c.width <= 0 || c.height <= 0) fail("empty grid (degenerate bounds)");
    if (s.max_cells > 0 && cells > s.max_cells)
        fail("grid of " + std::to_string(c.width) + " x " + std::to_string(c.height) +
             " cells exceeds max_cells=" + std::to_string(s.max_cells) + "; use a larger cell_size");

    climb_tolerance = std::max(static_cast<float>(s.agent_max_climb), 2.0f * c.ch);
    const float r = std::max(static_cast<float>(2.0 * s.agent_radius), 2.0f * c.cs);
    default_ext[0] = r;
    default_ext[1] = std::max(static_cast<float>(s.agent_height), 2.0f * c.ch);
    default_ext[2] = r;

    // 1. Rasterize the walkable triangles.
    std::unique_ptr<rcHeightfield, HeightfieldDel> solid(rcAllocHeightfield());
    if (!solid) fail("rcAllocHeightfield failed (out of memory)");
    if (!rcCreateHeightfield(&ctx, *solid, c.width, c.height, c.bmin, c.bmax, c.cs, c.ch))
        fail("rcCreateHeightfield failed", &ctx);
    std::vector<unsigned char> tri_areas(static_cast<size_t>(nt), 0);
    rcMarkWalkableTriangles(&ctx, c.walkableSlopeAngle, vin, nv, tin, nt, tri_areas.data());
    if (!rcRasterizeTriangles(&ctx, vin, nv, tin, tri_areas.data(), nt, *solid, c.walkableClimb))
        fail("rcRasterizeTriangles failed", &ctx);
    tri_areas.clear();
    tri_areas.shrink_to_fit();

    // 2. Filter walkable surfaces.
    rcFilterLowHangingWalkableObstacles(&ctx, c.walkableClimb, *solid);
    rcFilterLedgeSpans(&ctx, c.walkableHeight, c.walkableClimb, *solid);
    rcFilterWalkableLowHeightSpans(&ctx, c.walkableHeight, *solid);

    // 3. Compact heightfield, erosion by the agent radius.
    std::unique_ptr<rcCompactHeightfield, CompactDel> chf(rcAllocCompactHeightfield());
    if (!chf) fail("rcAllocCompactHeightfield failed (out of memory)");
    if (!rcBuildCompactHeightfield(&ctx, c.walkableHeight, c.walkableClimb, *solid, *chf))
        fail("rcBuildCompactHeightfield failed", &ctx);
    solid.reset();
    if (!rcErodeWalkableArea(&ctx, c.walkableRadius, *chf))
        fail("rcErodeWalkableArea failed", &ctx);
    int walkable_spans = 0;
    for (int i = 0; i < chf->spanCount; ++i)
        if (chf->areas[i] != RC_NULL_AREA) ++walkable_spans;
    if (walkable_spans == 0) fail("no walkable polygons (no walkable surface left after filtering and erosion)");

    // 4. Watershed regions.
    if (!rcBuildDistanceField(&ctx, *chf)) fail("rcBuildDistanceField failed", &ctx);
    if (!rcBuildRegions(&ctx, *chf, c.borderSize, c.minRegionArea, c.mergeRegionArea))
        fail("rcBuildRegions failed", &ctx);

    // 5. Contours, polygons, detail.
    std::unique_ptr<rcContourSet, ContourDel> cset(rcAllocContourSet());
    if (!cset) fail("rcAllocContourSet failed (out of memory)");
    if (!rcBuildContours(&ctx, *chf, c.maxSimplificationError, c.maxEdgeLen, *cset))
        fail("rcBuildContours failed", &ctx);
    if (cset->nconts == 0) fail("no walkable polygons (no contours; regions too small?)");
    std::unique_ptr<rcPolyMesh, PolyMeshDel> pmesh(rcAllocPolyMesh());
    if (!pmesh) fail("rcAllocPolyMesh failed (out of memory)");
    if (!rcBuildPolyMesh(&ctx, *cset, c.maxVertsPerPoly, *pmesh)) fail("rcBuildPolyMesh failed", &ctx);
    if (pmesh->npolys == 0) fail("no walkable polygons");
    std::unique_ptr<rcPolyMeshDetail, DetailDel> dmesh(rcAllocPolyMeshDetail());
    if (!dmesh) fail("rcAllocPolyMeshDetail failed (out of memory)");
    if (!rcBuildPolyMeshDetail(&ctx, *pmesh, *chf, c.detailSampleDist, c.detailSampleMaxError, *dmesh))
        fail("rcBuildPolyMeshDetail failed", &ctx);
    chf.reset();
    cset.reset();

    // 6. Copy the mesh data out.
    const rcPolyMesh& pm = *pmesh;
    nvp = pm.nvp;
    npolys = pm.npolys;
    verts.resize(static_cast<size_t>(pm.nverts) * 3);
    for (int i = 0; i < pm.nverts; ++i) {
        const unsigned short* v = &pm.verts[i * 3];
        verts[i * 3 + 0] = static_cast<double>(pm.bmin[0] + v[0] * pm.cs);
        verts[i * 3 + 1] = static_cast<double>(pm.bmin[1] + v[1] * pm.ch);
        verts[i * 3 + 2] = static_cast<double>(pm.bmin[2] + v[2] * pm.cs);
    }
    polys.assign(static_cast<size_t>(npolys) * nvp, -1);
    neis.assign(static_cast<size_t>(npolys) * nvp, -1);
    areas.resize(npolys);
    regions.resize(npolys);
    for (int i = 0; i < npolys; ++i) {
        const unsigned short* p = &pm.polys[i * 2 * nvp];
        for (int j = 0; j < nvp; ++j) {
            if (p[j] == RC_MESH_NULL_IDX) break;
            polys[i * nvp + j] = p[j];
            const unsigned short n = p[nvp + j];
            // Solo mesh (borderSize 0): a neighbour is a polygon index, or
            // RC_MESH_NULL_IDX; portal-flagged values (0x8000) only occur in tiles.
            neis[i * nvp + j] = (n == RC_MESH_NULL_IDX || (n & 0x8000)) ? -1 : static_cast<int32_t>(n);
        }
        areas[i] = pm.areas[i];
        regions[i] = pm.regs[i];
        pm.flags[i] = 1;  // Detour's default filter needs a non-zero flag
    }
    const rcPolyMeshDetail& dm = *dmesh;
    dverts.assign(dm.verts, dm.verts + static_cast<size_t>(dm.nverts) * 3);
    dtris.reserve(static_cast<size_t>(dm.ntris) * 3);
    dtri_poly.reserve(dm.ntris);
    for (int i = 0; i < dm.nmeshes; ++i) {
        const unsigned int vbase = dm.meshes[i * 4 + 0];
        const unsigned int tbase = dm.meshes[i * 4 + 2];
        const unsigned int tcount = dm.meshes[i * 4 + 3];
        for (unsigned int k = 0; k < tcount; ++k) {
            const unsigned char* t = &dm.tris[(tbase + k) * 4];
            dtris.push_back(static_cast<int32_t>(vbase + t[0]));
            dtris.push_back(static_cast<int32_t>(vbase + t[1]));
            dtris.push_back(static_cast<int32_t>(vbase + t[2]));
            dtri_poly.push_back(i);
        }
    }

    // 7. Detour navmesh and query.
    dtNavMeshCreateParams params;
    std::memset(&params, 0, sizeof(params));
    params.verts = pm.verts;
    params.vertCount = pm.nverts;
    params.polys = pm.polys;
    params.polyAreas = pm.areas;
    params.polyFlags = pm.flags;
    params.polyCount = pm.npolys;
    params.nvp = pm.nvp;
    params.detailMeshes = dm.meshes;
    params.detailVerts = dm.verts;
    params.detailVertsCount = dm.nverts;
    params.detailTris = dm.tris;
    params.detailTriCount = dm.ntris;
    params.walkableHeight = static_cast<float>(s.agent_height);
    params.walkableRadius = static_cast<float>(s.agent_radius);
    params.walkableClimb = static_cast<float>(s.agent_max_climb);
    rcVcopy(params.bmin, pm.bmin);
    rcVcopy(params.bmax, pm.bmax);
    params.cs = c.cs;
    params.ch = c.ch;
    params.buildBvTree = true;
    unsigned char* data = nullptr;
    int data_size = 0;
    if (!dtCreateNavMeshData(&params, &data, &data_size))
        fail("dtCreateNavMeshData failed (too many vertices or polygons for one tile?)");
    pmesh.reset();
    dmesh.reset();

    nav.reset(dtAllocNavMesh());
    if (!nav) { dtFree(data); fail("dtAllocNavMesh failed (out of memory)"); }
    if (dtStatusFailed(nav->init(data, data_size, DT_TILE_FREE_DATA))) {
        dtFree(data);
        fail("dtNavMesh::init failed");
    }
    query.reset(dtAllocNavMeshQuery());
    if (!query) fail("dtAllocNavMeshQuery failed (out of memory)");
    if (dtStatusFailed(query->init(nav.get(), 2048))) fail("dtNavMeshQuery::init failed");
    const dtNavMesh* cnav = nav.get();
    ref_base = cnav->getPolyRefBase(cnav->getTile(0));

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
                           long long max_cells) {
    Settings s{cell_size, cell_height, agent_height, agent_radius, agent_max_climb, agent_max_slope,
               region_min_size, region_merge_size, edge_max_len, edge_max_error, verts_per_poly,
               detail_sample_dist, detail_sample_max_error, max_cells};
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
          nb::arg("max_cells") = 400000000LL, nb::rv_policy::take_ownership,
          "Build a solo navmesh from (N,3) vertices and (M,3) triangle faces. World-unit settings, "
          "derived into Recast's voxel configuration as Recast's demo does.");
}

using Vec3In = std::array<double, 3>;
using ExtIn = std::optional<std::array<double, 3>>;
using PointsIn = nb::ndarray<const double, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;

void get3(const Vec3In& a, float* out) {
    for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(a[i]);
}

}  // namespace

NB_MODULE(_recast, m) {
    m.doc() = "Recast/Detour (solo navmesh) bindings for g2s; see g2s_plugins.recast.";

    nb::class_<NavMeshCore>(m, "NavMeshCore",
                            "A built solo navmesh: copied mesh arrays and Detour queries.")
        .def_prop_ro("nvp", [](const NavMeshCore& n) { return n.nvp; }, "max vertices per polygon")
        .def_prop_ro("polygon_count", [](const NavMeshCore& n) { return n.npolys; })
        .def_prop_ro("vertices", [](const NavMeshCore& n) { return to_numpy(n.verts, n.verts.size() / 3, 3); },
                     "(V,3) float64 polygon vertices, world coordinates")
        .def_prop_ro("polygons", [](const NavMeshCore& n) { return to_numpy(n.polys, n.npolys, n.nvp); },
                     "(P,nvp) int32 vertex indices, padded with -1")
        .def_prop_ro("neighbours", [](const NavMeshCore& n) { return to_numpy(n.neis, n.npolys, n.nvp); },
                     "(P,nvp) int32: polygon across edge j (vertex j -> j+1, wrapping), -1 at the boundary")
        .def_prop_ro("area_ids", [](const NavMeshCore& n) { return to_numpy(n.areas, n.npolys, 0); },
                     "(P,) int32 Recast area ids (63 = walkable)")
        .def_prop_ro("region_ids", [](const NavMeshCore& n) { return to_numpy(n.regions, n.npolys, 0); },
                     "(P,) int32 Recast region ids")
        .def_prop_ro("detail_vertices",
                     [](const NavMeshCore& n) { return to_numpy(n.dverts, n.dverts.size() / 3, 3); },
                     "(DV,3) float64 detail mesh vertices, world coordinates")
        .def_prop_ro("detail_triangles",
                     [](const NavMeshCore& n) { return to_numpy(n.dtris, n.dtris.size() / 3, 3); },
                     "(DT,3) int32 indices into detail_vertices")
        .def_prop_ro("detail_polygon", [](const NavMeshCore& n) { return to_numpy(n.dtri_poly, n.dtri_poly.size(), 0); },
                     "(DT,) int32 polygon owning each detail triangle")
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
                 return d;
             },
             "the resolved rcConfig (voxel units) as a dict")
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
                 if (A.shape(0) != B.shape(0)) throw nb::value_error("A and B must have the same length");
                 float ext[3] = {n.default_ext[0], n.default_ext[1], n.default_ext[2]};
                 if (extents) get3(*extents, ext);
                 const size_t N = A.shape(0);
                 std::vector<uint8_t> out(N, 0);
                 const double* pa = A.data();
                 const double* pb = B.data();
                 {
                     nb::gil_scoped_release release;
                     std::lock_guard<std::mutex> lock(n.mutex);
                     std::vector<dtPolyRef> path(256);
                     for (size_t i = 0; i < N; ++i) {
                         float a[3], b[3];
                         for (int k = 0; k < 3; ++k) {
                             a[k] = static_cast<float>(pa[i * 3 + k]);
                             b[k] = static_cast<float>(pb[i * 3 + k]);
                         }
                         out[i] = n.ray(a, b, ext, path).first ? 1 : 0;
                     }
                 }
                 auto* buf = new uint8_t[N ? N : 1];
                 std::copy(out.begin(), out.end(), buf);
                 nb::capsule owner(buf, [](void* p) noexcept { delete[] static_cast<uint8_t*>(p); });
                 return nb::cast(nb::ndarray<nb::numpy, bool>(reinterpret_cast<bool*>(buf), {N}, owner),
                                 nb::rv_policy::move);
             },
             nb::arg("A"), nb::arg("B"), nb::arg("extents") = nb::none(),
             "(N,) bool: raycast(A[i], B[i]).clear for every row, GIL released")
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
                 if (!n.nav->isValidPolyRef(static_cast<dtPolyRef>(ref))) throw nb::value_error("invalid dtPolyRef");
                 return n.ref_to_index(static_cast<dtPolyRef>(ref));
             },
             nb::arg("ref"), "polygon index of a Detour dtPolyRef (decodePolyIdPoly); -1 for 0");

    def_build<float, int32_t>(m);
    def_build<double, int32_t>(m);
    def_build<float, int64_t>(m);
    def_build<double, int64_t>(m);
    m.attr("DT_VERTS_PER_POLYGON") = DT_VERTS_PER_POLYGON;
}
