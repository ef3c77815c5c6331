// g2s_plugins._slabs: whether triangles pass through slabs, the walk test's exact test of the agent's body
// (g2s_plugins._raycasting.SteepFaces.slab_grid, asked by walks_in_batch): broad phase (WallGrid) and narrow phase
// (slab_meets_triangle) in one call.
//
// Why C++: mesh_los's walk test asks it once per batch of walks, a few hundred (triangle, slab) pairs at a time,
// about 79,000 times on the 100k-polygon level; in numpy each call ran about 250 array operations, whose cost per
// call (not per pair) was 16 % of the simplification's time (docs/performance.md, "6 December 2026, 08:57-10:15
// UTC"). Here one loop per pair, each operation in numpy's order and rounding: a product of two terms then their
// sum (numpy's einsum and norm over an axis of two or three), a quotient then a product, so the answers are the
// numpy formulation's bit for bit (no flag of this build contracts a product and a sum into one rounding). Pairs
// are independent: O(k), no allocation beyond the answer.

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace nb = nanobind;

namespace {

using Corners = nb::ndarray<const double, nb::shape<-1, 3, 3>, nb::c_contig, nb::device::cpu>;
using Rows3 = nb::ndarray<const double, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;
using Rows2 = nb::ndarray<const double, nb::shape<-1, 2>, nb::c_contig, nb::device::cpu>;

constexpr double SLACK = 1e-9;  // metres a value may lie outside the slab's bounds and count as inside

// The bounds of one slab in its frame (a: metres along the walk's plan, h: metres up from the walk's line).
struct Bounds {
    double lowest[2], highest[2];  // [0]: a, [1]: h
    bool inside(int axis, double value) const {
        return value >= lowest[axis] - SLACK && value <= highest[axis] + SLACK;
    }
};

// One pair: whether triangle `corner` (3 corners x 3, m) passes through the slab origin + s along + t side + h UP
// (s in (0, 1), t in (-1, 1), h from heights[0] to heights[1] (m); `side` horizontal and at right angles to
// `along`'s plan), shrunk by `inset` (m) on every side: a box sheared along a sloping walk.
// In the frame (a, t, h) (metres along `along`'s plan, along `side`, and up from the line origin + s along), an
// affine image of the space, the slab is the box a in [0, plan length], h in `heights`, |t| <= |side|. The part of
// the triangle in the prism a, h in range (any t) is a convex polygon whose corners, and so the ends of its span
// along t, are among: the triangle's corners inside; its edges' crossings of the prism's four faces; the crossings
// of the prism's four edges (lines along t) with the triangle, by barycentric coordinates in the (a, h) plane (a
// triangle parallel to t has its span's ends on its edges). The triangle meets the slab when that span reaches
// within |side| - inset of the middle. O(1).
bool slab_meets_triangle(const double* corner, const double* origin, const double* along, const double* side,
                         const double* heights, double inset) {
    const double length = std::sqrt(along[0] * along[0] + along[2] * along[2]);
    const double along_x = along[0] / length, along_z = along[2] / length;
    const double side_plan = std::sqrt(side[0] * side[0] + side[2] * side[2]);
    const double side_x = side[0] / side_plan, side_z = side[2] / side_plan;
    double frame[2][3], t[3];  // frame[0]: a, frame[1]: h, of each corner; t: across the walk
    for (int c = 0; c < 3; ++c) {
        const double x = corner[3 * c] - origin[0], y = corner[3 * c + 1] - origin[1], z = corner[3 * c + 2] - origin[2];
        frame[0][c] = x * along_x + z * along_z;
        t[c] = x * side_x + z * side_z;
        frame[1][c] = y - frame[0][c] / length * along[1];
    }
    const Bounds bounds{{inset, heights[0] + inset}, {length - inset, heights[1] - inset}};
    double low = std::numeric_limits<double>::infinity(), high = -low;
    bool undefined = false;  // a NaN end: numpy's minimum and maximum are NaN then, and the answer is no
    auto span = [&](double value) {
        undefined |= std::isnan(value);
        low = std::min(low, value);
        high = std::max(high, value);
    };
    for (int c = 0; c < 3; ++c)
        if (bounds.inside(0, frame[0][c]) && bounds.inside(1, frame[1][c])) span(t[c]);
    constexpr int EDGES[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    for (const auto& edge : EDGES) {
        const int i = edge[0], j = edge[1];
        for (int axis = 0; axis < 2; ++axis) {
            const int other = 1 - axis;
            const double run = frame[axis][j] - frame[axis][i];
            if (run == 0.0) continue;
            for (const double plane : {bounds.lowest[axis], bounds.highest[axis]}) {
                const double u = (plane - frame[axis][i]) / run;
                if (!(u >= 0.0 && u <= 1.0)) continue;
                if (bounds.inside(other, frame[other][i] + u * (frame[other][j] - frame[other][i])))
                    span(t[i] + u * (t[j] - t[i]));
            }
        }
    }
    const double first_a = frame[0][1] - frame[0][0], first_h = frame[1][1] - frame[1][0];
    const double second_a = frame[0][2] - frame[0][0], second_h = frame[1][2] - frame[1][0];
    const double determinant = first_a * second_h - first_h * second_a;
    const bool flat = std::fabs(determinant) <=
                      1e-12 * (std::fabs(first_a * second_h) + std::fabs(first_h * second_a) + 1e-300);
    if (!flat)
        for (const double corner_a : {bounds.lowest[0], bounds.highest[0]})
            for (const double corner_h : {bounds.lowest[1], bounds.highest[1]}) {
                const double to_a = corner_a - frame[0][0], to_h = corner_h - frame[1][0];
                const double u = (to_a * second_h - to_h * second_a) / determinant;
                const double v = (first_a * to_h - first_h * to_a) / determinant;
                if (u >= 0.0 && v >= 0.0 && u + v <= 1.0) span(t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]));
            }
    const double reach = std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]) - inset;
    return !undefined && low < reach && high > -reach;
}

// (n,) bool: answer(i) for each i, computed without the GIL into an array numpy owns
template <typename Answer>
nb::ndarray<nb::numpy, bool, nb::ndim<1>> answers(size_t n, const Answer& answer) {
    auto* out = new bool[n > 0 ? n : 1];
    nb::capsule owner(out, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
    {
        nb::gil_scoped_release release;
        for (size_t i = 0; i < n; ++i) out[i] = answer(i);
    }
    return nb::ndarray<nb::numpy, bool, nb::ndim<1>>(out, {n}, owner);
}

// The steep triangles of a mesh binned in a 3-D grid of cubes (BoxGrid's origin and cell), for the body's slab
// test in one call: each slab's box (its eight corners'), the triangles of the cells
// it covers whose boxes overlap it (each pair once: in the cell that is, along each axis, the later of the two
// boxes' first cells), and the exact test above on those. Two closed boxes that overlap share a cell (a cell's index
// is the floor of a monotone function of the coordinate), so the pairs tested are exactly the overlapping ones (as
// bands_meet_walls' BoxGrid.pairs and box filter find its bands'), and a slab's answer (whether any pair meets) is
// that of every pair. Built in O(E) for the E (triangle, cell) entries; a call O(C + P) for the C cells the slabs cover and the P
// (slab, triangle) entries sharing a cell.
class WallGrid {
  public:
    WallGrid(Corners triangles, Rows3 lo, Rows3 hi, nb::ndarray<const double, nb::shape<3>, nb::c_contig, nb::device::cpu> origin,
             double cell)
        : cell_(cell) {
        const size_t k = triangles.shape(0);
        if (lo.shape(0) != k || hi.shape(0) != k) throw nb::value_error("WallGrid: triangles (k, 3, 3), lo and hi (k, 3)");
        if (!(cell > 0.0)) throw nb::value_error("WallGrid: cell must be positive");
        triangles_.assign(triangles.data(), triangles.data() + 9 * k);
        lo_.assign(lo.data(), lo.data() + 3 * k);
        hi_.assign(hi.data(), hi.data() + 3 * k);
        for (int a = 0; a < 3; ++a) origin_[a] = origin.data()[a];
        first_.resize(3 * k);
        std::vector<int64_t> last(3 * k);
        for (size_t w = 0; w < k; ++w)
            for (int a = 0; a < 3; ++a) {
                first_[3 * w + a] = index(lo_[3 * w + a], a);
                last[3 * w + a] = index(hi_[3 * w + a], a);
                shape_[a] = std::max(shape_[a], last[3 * w + a] + 1);
            }
        for (size_t w = 0; w < k; ++w)
            for (int64_t x = first_[3 * w]; x <= last[3 * w]; ++x)
                for (int64_t y = first_[3 * w + 1]; y <= last[3 * w + 1]; ++y)
                    for (int64_t z = first_[3 * w + 2]; z <= last[3 * w + 2]; ++z)
                        cells_[key(x, y, z)].push_back(static_cast<int64_t>(w));
    }

    // (n,) bool: a triangle passes through slab i (slab_meets_triangle's slab: low (n, 3), along, side, heights
    // (n, 2), shrunk by inset)
    nb::ndarray<nb::numpy, bool, nb::ndim<1>> meets(Rows3 low, Rows3 along, Rows3 side, Rows2 heights, double inset) const {
        const size_t n = low.shape(0);
        if (along.shape(0) != n || side.shape(0) != n || heights.shape(0) != n)
            throw nb::value_error("WallGrid.meets: low, along and side (n, 3), heights (n, 2)");
        return answers(n, [&](size_t i) {
            return slab_meets_any(low.data() + 3 * i, along.data() + 3 * i, side.data() + 3 * i,
                                  heights.data() + 2 * i, inset);
        });
    }

  private:
    int64_t index(double value, int axis) const {
        return static_cast<int64_t>(std::floor((value - origin_[axis]) / cell_));
    }
    int64_t key(int64_t x, int64_t y, int64_t z) const { return (x * shape_[1] + y) * shape_[2] + z; }

    bool slab_meets_any(const double* low, const double* along, const double* side, const double* heights,
                        double inset) const {
        if (triangles_.empty()) return false;
        // the slab's corners: low -/+ side, low + along +/- side, each at both heights
        double box_lo[3], box_hi[3];
        std::fill(box_lo, box_lo + 3, std::numeric_limits<double>::infinity());
        std::fill(box_hi, box_hi + 3, -std::numeric_limits<double>::infinity());
        for (int level = 0; level < 2; ++level) {
            const double lifts[3] = {heights[level] * 0.0, heights[level] * 1.0, heights[level] * 0.0};
            for (int corner = 0; corner < 4; ++corner)
                for (int a = 0; a < 3; ++a) {
                    const double base = corner < 2 ? low[a] : low[a] + along[a];
                    const double plan = (corner == 0 || corner == 3) ? base - side[a] : base + side[a];
                    const double value = plan + lifts[a];
                    box_lo[a] = std::min(box_lo[a], value);
                    box_hi[a] = std::max(box_hi[a], value);
                }
        }
        int64_t first[3], last[3];
        for (int a = 0; a < 3; ++a) {
            first[a] = index(box_lo[a], a);
            last[a] = index(box_hi[a], a);
            if (last[a] < 0 || first[a] >= shape_[a]) return false;  // no triangle's box reaches it
            first[a] = std::max<int64_t>(first[a], 0);
            last[a] = std::min<int64_t>(last[a], shape_[a] - 1);
        }
        for (int64_t x = first[0]; x <= last[0]; ++x)
            for (int64_t y = first[1]; y <= last[1]; ++y)
                for (int64_t z = first[2]; z <= last[2]; ++z) {
                    const auto cell = cells_.find(key(x, y, z));
                    if (cell == cells_.end()) continue;
                    const int64_t at[3] = {x, y, z};
                    for (const int64_t w : cell->second) {
                        const int64_t* own = &first_[3 * w];
                        bool once = true;
                        for (int a = 0; a < 3; ++a) once = once && at[a] == std::max(first[a], own[a]);
                        if (!once) continue;
                        const double* lo = &lo_[3 * w];
                        const double* hi = &hi_[3 * w];
                        bool overlap = true;
                        for (const int a : {0, 2, 1}) overlap = overlap && box_lo[a] <= hi[a] && lo[a] <= box_hi[a];
                        if (overlap && slab_meets_triangle(&triangles_[9 * w], low, along, side, heights, inset)) return true;
                    }
                }
        return false;
    }

    double cell_;
    double origin_[3];
    int64_t shape_[3] = {0, 0, 0};
    std::vector<double> triangles_, lo_, hi_;
    std::vector<int64_t> first_;
    std::unordered_map<int64_t, std::vector<int64_t>> cells_;
};

}  // namespace

NB_MODULE(_slabs, m) {
    m.doc() = "The body slab's exact test against triangles of g2s_plugins._raycasting (see src/slabs_module.cpp).";
    nb::class_<WallGrid>(m, "WallGrid", "steep triangles binned for the body slab's test in one call")
        .def(nb::init<Corners, Rows3, Rows3, nb::ndarray<const double, nb::shape<3>, nb::c_contig, nb::device::cpu>,
                      double>(),
             nb::arg("triangles"), nb::arg("lo"), nb::arg("hi"), nb::arg("origin"), nb::arg("cell"))
        .def("meets", &WallGrid::meets, nb::arg("low"), nb::arg("along"), nb::arg("side"), nb::arg("heights"),
             nb::arg("inset"), "(n,) bool: a triangle passes through slab i (low + s along + t side + h UP, h in heights[i], shrunk by inset)");
}
