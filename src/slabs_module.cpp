// g2s_plugins._slabs: whether triangles pass through slabs, the exact (narrow-phase) test of
// g2s_plugins._raycasting.bands_meet_walls with the agent's body (src/slabs_module.cpp; the Python function
// _slabs_meet_triangles states the geometry).
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

// One pair: triangle `corner` (3 corners x 3) against the slab origin + s along + t side + h UP (see
// _slabs_meet_triangles), its floor and ceiling `heights` (2,), shrunk by `inset`.
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

nb::ndarray<nb::numpy, bool, nb::ndim<1>> slabs_meet_triangles(Corners triangles, Rows3 origin, Rows3 along,
                                                               Rows3 side, Rows2 heights, double inset) {
    const size_t k = triangles.shape(0);
    if (origin.shape(0) != k || along.shape(0) != k || side.shape(0) != k || heights.shape(0) != k)
        throw nb::value_error("slabs_meet_triangles: triangles (k, 3, 3), origin, along and side (k, 3), heights (k, 2)");
    auto* meets = new bool[k > 0 ? k : 1];
    nb::capsule owner(meets, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
    {
        nb::gil_scoped_release release;
        for (size_t i = 0; i < k; ++i)
            meets[i] = slab_meets_triangle(triangles.data() + 9 * i, origin.data() + 3 * i, along.data() + 3 * i,
                                           side.data() + 3 * i, heights.data() + 2 * i, inset);
    }
    return nb::ndarray<nb::numpy, bool, nb::ndim<1>>(meets, {k}, owner);
}

}  // namespace

NB_MODULE(_slabs, m) {
    m.doc() = "The body slab's exact test against triangles of g2s_plugins._raycasting (see src/slabs_module.cpp).";
    m.def("slabs_meet_triangles", &slabs_meet_triangles, nb::arg("triangles"), nb::arg("origin"), nb::arg("along"),
          nb::arg("side"), nb::arg("heights"), nb::arg("inset"),
          "slabs_meet_triangles(triangles, origin, along, side, heights, inset) -> meets.\n\n"
          "meets (k,) bool: triangle i (float64 (k, 3, 3) corners, m) passes through the slab origin[i] +\n"
          "s along[i] + t side[i] + h UP (s in (0, 1), t in (-1, 1), h in heights[i] (k, 2); origin, along, side\n"
          "float64 (k, 3), side horizontal and at right angles to along's plan), shrunk by inset (m) on every side.");
}
