// g2s_plugins._walks: the arithmetic of one batch of the walk test round its ray casts (the probe points and rays,
// the hits' distances, the ground, head-room, gap and rise tests), for the sampling builder's edges and the mesh_los
// predicate (g2s_plugins._raycasting.walks_in_batch states the rule and the steps, and calls Embree and the crack
// rule, ground_across_crack, between them: the probes without ground of their own leave here as points and come
// back as ground distances, so the crack rule is stated once, in Python).
//
// Why C++: the simplification of the sampling route asks about 79,000 batches of a few dozen walks on the
// 100k-polygon level, and in numpy each batch ran a few hundred array operations whose cost is per call, not per
// walk (docs/performance.md, "6 December 2026, 19:20-20:50 UTC"). Here one loop per walk or per ray, each
// floating-point operation in the order and rounding of the numpy formulation it replaced (walk_segments, removed
// in walks47), so the structures are those of before, bit for bit: numpy's norm of a row of three sums
// ((x0 x0 + x1 x1) + x2 x2), its einsum "ij,ij->i" of three sums ((p0 + p2) + p1) (both checked on 200,000 random
// rows for the numpy this project pins), a sum with UP's zero components is kept (x + 0.0), and no flag of this
// build contracts a product and a sum into one rounding (-ffp-contract=off). O(rays) a batch.

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace nb = nanobind;

namespace {

using Rows3 = nb::ndarray<const double, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;
using Faces = nb::ndarray<const int64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using Rows = nb::ndarray<const int64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using Values = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using Point = nb::ndarray<const double, nb::shape<3>, nb::c_contig, nb::device::cpu>;

constexpr double INF = std::numeric_limits<double>::infinity();
constexpr double DOWN[3] = {-0.0, -1.0, -0.0};  // -UP, as numpy negates it
constexpr double UPWARD[3] = {0.0, 1.0, 0.0};

template <typename T>
nb::ndarray<nb::numpy, T> numpy_of(const std::vector<T>& values, std::initializer_list<size_t> shape) {
    auto* data = new T[values.empty() ? 1 : values.size()];
    std::copy(values.begin(), values.end(), data);
    nb::capsule owner(data, [](void* p) noexcept { delete[] static_cast<T*>(p); });
    return nb::ndarray<nb::numpy, T>(data, shape, owner);
}

nb::ndarray<nb::numpy, bool> bools_of(const std::vector<uint8_t>& values) {
    auto* data = new bool[values.empty() ? 1 : values.size()];
    for (size_t i = 0; i < values.size(); ++i) data[i] = values[i] != 0;
    nb::capsule owner(data, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
    return nb::ndarray<nb::numpy, bool>(data, {values.size()}, owner);
}

// The mesh arrays the hits read: each triangle's unit normal, first corner and centroid (local frame), its reversed
// twin or -1 (RayCaster's scene), and the walkable normals' least y (cos of the max slope, less 1e-9).
struct Scene {
    const double* normals;
    const double* plane_points;
    const double* centroids;
    const int64_t* twin;
    size_t faces;
};

// Rays cast for a batch: origins (world frame) and unit directions (R, 3), and what they hit: the face (-1: none)
// and the distance along the ray (inf: none)
struct Rays {
    std::vector<double> origins, unit, distance;
    std::vector<int64_t> face;

    void add(const double* origin, const double* direction) {  // RayCaster.first_hits' unit: d / |d|, numpy's norm
        const double norm = std::sqrt((direction[0] * direction[0] + direction[1] * direction[1]) + direction[2] * direction[2]);
        for (int a = 0; a < 3; ++a) {
            origins.push_back(origin[a]);
            unit.push_back(direction[a] / norm);
        }
        face.push_back(-1);
        distance.push_back(INF);
    }
    size_t size() const { return face.size(); }

    nb::tuple local(std::optional<Point> shift) const {  // (origins shifted by -shift unless None, unit)
        std::vector<double> shifted = origins;
        if (shift) {
            const double* o = shift->data();
            for (size_t r = 0; r < shifted.size(); ++r) shifted[r] = shifted[r] - o[r % 3];
        }
        return nb::make_tuple(numpy_of(shifted, {size(), 3}), numpy_of(unit, {size(), 3}));
    }

    // RayCaster._cast's answer for the intersector's faces (R,): the faces (a two-sided floor's up-facing twin), the
    // distances along the rays; the rows of the rays grazing their triangle, which the caller casts again aside
    nb::ndarray<nb::numpy, int64_t> hit(const Faces& faces, const Rows3& local, const Rows3& normals,
                                        const Rows3& plane_points, const Rows3& centroids, const Faces& twin) {
        const size_t rays = size();
        if (faces.shape(0) != rays || local.shape(0) != rays) throw nb::value_error("WalkBatch: one face per ray");
        const size_t m = normals.shape(0);
        if (plane_points.shape(0) != m || centroids.shape(0) != m || twin.shape(0) != m)
            throw nb::value_error("WalkBatch: one normal, plane point, centroid and twin per triangle");
        std::vector<int64_t> grazing;
        for (size_t r = 0; r < rays; ++r) {
            const int64_t f = faces.data()[r];
            if (f < 0) continue;
            if (static_cast<size_t>(f) >= m) throw nb::value_error("WalkBatch: face out of range");
            const double* n = normals.data() + 3 * f;
            const double* o = local.data() + 3 * r;
            const double* d = &unit[3 * r];
            const double* q = plane_points.data() + 3 * f;
            const double denominator = (d[0] * n[0] + d[2] * n[2]) + d[1] * n[1];
            const double to[3] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]};
            const double along_plane = (to[0] * n[0] + to[2] * n[2]) + to[1] * n[1];
            double t;
            if (std::fabs(denominator) < 1e-9) {  // in the triangle's plane: to its centroid
                const double* c = centroids.data() + 3 * f;
                const double toc[3] = {c[0] - o[0], c[1] - o[1], c[2] - o[2]};
                t = (toc[0] * d[0] + toc[2] * d[2]) + toc[1] * d[1];
                grazing.push_back(static_cast<int64_t>(r));
            } else {
                t = along_plane / denominator;
            }
            distance[r] = std::isnan(t) ? t : std::max(t, 0.0);
            face[r] = twin.data()[f] >= 0 ? twin.data()[f] : f;
        }
        return numpy_of(grazing, {grazing.size()});
    }

    void set(const Rows& rows, const Faces& faces, const Values& distances) {  // rows cast again
        if (faces.shape(0) != rows.shape(0) || distances.shape(0) != rows.shape(0))
            throw nb::value_error("WalkBatch: one face and distance per row");
        for (size_t k = 0; k < rows.shape(0); ++k) {
            const int64_t r = rows.data()[k];
            if (r < 0 || static_cast<size_t>(r) >= size()) throw nb::value_error("WalkBatch: row out of range");
            face[r] = faces.data()[k];
            distance[r] = distances.data()[k];
        }
    }
};

// The rays over the steps of some walks of a batch (WalkBatch::steps): between each two neighbouring probes of a
// walk, a horizontal ray from the first to the second at a height over the lower one's ground; a steep face across
// one (a sill thinner than the probe step, which no probe lands on) stops the walk. Their casts as WalkBatch's.
class StepRays {
  public:
    Rays rays;
    std::vector<int64_t> walk;      // the row (of the walks asked) of each ray
    std::vector<double> length;     // the horizontal distance between the ray's two probes
    size_t walks = 0;

    nb::tuple local(std::optional<Point> shift) const { return rays.local(shift); }
    nb::ndarray<nb::numpy, int64_t> hit(Faces faces, Rows3 local, Rows3 normals, Rows3 plane_points, Rows3 centroids,
                                        Faces twin) {
        return rays.hit(faces, local, normals, plane_points, centroids, twin);
    }
    void set_hits(Rows rows, Faces faces, Values distances) { rays.set(rows, faces, distances); }

    // (walks,) bool: a ray of the walk meets a face steeper than the max slope (normal's y under `least_y`) short
    // of the next probe
    nb::ndarray<nb::numpy, bool> blocked(Values normal_y, double least_y) const {
        std::vector<uint8_t> out(walks, 0);
        for (size_t r = 0; r < rays.size(); ++r) {
            const int64_t f = rays.face[r];
            if (rays.distance[r] < length[r] && !(f >= 0 && normal_y.data()[f] >= least_y)) out[walk[r]] = 1;
        }
        return bools_of(out);
    }
};

// One batch of walks from starts[i] to ends[i] (walks_in_batch's arguments), its probe points and rays, then their
// hits and the tests on them. Rays, in this order: the lifted segments of the moving walks, the probes'
// downward then upward rays, the side lines' left then right copies of the walks with sides.
class WalkBatch {
  public:
    WalkBatch(Rows3 starts, Rows3 ends, double lift, double probe_step, double half_width) : lift_(lift) {
        if (ends.shape(0) != starts.shape(0)) throw nb::value_error("WalkBatch: starts and ends (n, 3) alike");
        n_ = starts.shape(0);
        start_.assign(starts.data(), starts.data() + 3 * n_);
        end_.assign(ends.data(), ends.data() + 3 * n_);
        low_.resize(3 * n_); vectors_.resize(3 * n_); side_.resize(3 * n_, 0.0);
        lengths_.resize(n_); horizontal_.resize(n_); intervals_.resize(n_); first_.resize(n_);
        moving_.resize(n_); sideways_.resize(n_);
        size_t probes = 0;
        for (size_t i = 0; i < n_; ++i) {
            const double* s = &start_[3 * i];
            const double* e = &end_[3 * i];
            const double lifts[3] = {0.0, lift, 0.0};  // lift * UP
            for (int a = 0; a < 3; ++a) {
                low_[3 * i + a] = s[a] + lifts[a];
                vectors_[3 * i + a] = (e[a] + lifts[a]) - low_[3 * i + a];
            }
            const double* v = &vectors_[3 * i];
            lengths_[i] = std::sqrt((v[0] * v[0] + v[1] * v[1]) + v[2] * v[2]);
            moving_[i] = lengths_[i] > 1e-9;
            const double dx = e[0] - s[0], dz = e[2] - s[2];
            horizontal_[i] = std::hypot(dx, dz);
            intervals_[i] = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(horizontal_[i] / probe_step - 1e-9)));
            first_[i] = probes;
            probes += static_cast<size_t>(intervals_[i]) + 1;
            sideways_[i] = half_width > 0 && moving_[i] && horizontal_[i] > 1e-9;
            if (sideways_[i]) {
                const double scale = half_width / horizontal_[i];
                side_[3 * i] = -dz * scale;
                side_[3 * i + 1] = 0.0 * scale;
                side_[3 * i + 2] = dx * scale;
            }
        }
        line_.resize(3 * probes);
        segment_.resize(probes);
        for (size_t i = 0; i < n_; ++i) {
            const double* s = &start_[3 * i];
            const double* e = &end_[3 * i];
            const double delta[3] = {e[0] - s[0], e[1] - s[1], e[2] - s[2]};
            for (int64_t k = 0; k <= intervals_[i]; ++k) {
                const size_t p = first_[i] + static_cast<size_t>(k);
                const double t = static_cast<double>(k) / static_cast<double>(intervals_[i]);
                for (int a = 0; a < 3; ++a) line_[3 * p + a] = s[a] + t * delta[a];
                segment_[p] = i;
            }
        }
        // the rays' origins and directions, each batch in the order above
        for (size_t i = 0; i < n_; ++i)
            if (moving_[i]) rays_.add(&low_[3 * i], &vectors_[3 * i]);
        down_ = rays_.size();
        const double lifts[3] = {0.0, lift, 0.0};
        for (const double* direction : {DOWN, UPWARD})
            for (size_t p = 0; p < probes; ++p) {
                const double lifted[3] = {line_[3 * p] + lifts[0], line_[3 * p + 1] + lifts[1], line_[3 * p + 2] + lifts[2]};
                rays_.add(lifted, direction);
            }
        up_ = down_ + probes;
        left_ = up_ + probes;
        for (const double sign : {1.0, -1.0}) {
            for (size_t i = 0; i < n_; ++i)
                if (sideways_[i]) {
                    double origin[3];
                    for (int a = 0; a < 3; ++a)
                        origin[a] = sign > 0 ? low_[3 * i + a] + side_[3 * i + a] : low_[3 * i + a] - side_[3 * i + a];
                    rays_.add(origin, &vectors_[3 * i]);
                }
            if (sign > 0) right_ = rays_.size();
        }
    }

    // The walks' rays: (R, 3) origins in the frame shifted by `shift` (RayCaster.frame.to_local; None: not
    // shifted), (R, 3) unit directions
    nb::tuple rays(std::optional<Point> shift) const { return rays_.local(shift); }

    // The intersector's faces (R,) of rays() -> rows of the rays grazing their triangle
    nb::ndarray<nb::numpy, int64_t> hit(Faces faces, Rows3 local, Rows3 normals, Rows3 plane_points, Rows3 centroids,
                                        Faces twin) {
        return rays_.hit(faces, local, normals, plane_points, centroids, twin);
    }

    // The grazing rays' answers cast again aside (RayCaster.first_hits): rows of rays(), their faces and distances
    void set_hits(Rows rows, Faces faces, Values distances) { rays_.set(rows, faces, distances); }

    // The probes with walkable ground within `reach` below (walkable: a face whose normal's y is at least
    // `least_y`); the rows (of the probes) of those without, which the caller tries across a crack
    nb::ndarray<nb::numpy, int64_t> ground(double reach, Values normal_y, double least_y) {
        const size_t probes = segment_.size();
        good_.assign(probes, 0);
        ground_distance_.assign(probes, 0.0);
        std::vector<int64_t> missing;
        for (size_t p = 0; p < probes; ++p) {
            const size_t r = down_ + p;
            const bool good = rays_.distance[r] <= reach && walkable(rays_.face[r], normal_y, least_y);
            good_[p] = good;
            if (good) ground_distance_[p] = rays_.distance[r];
            else missing.push_back(static_cast<int64_t>(p));
        }
        return numpy_of(missing, {missing.size()});
    }

    // The lifted probe points (world frame, (k, 3): the origins of their downward rays) of
    // `rows`, the probes ground() found without ground, which the caller tries across a crack (ground_across_crack)
    nb::ndarray<nb::numpy, double> probe_points(Rows rows) const {
        std::vector<double> points;
        points.reserve(3 * rows.shape(0));
        for (size_t k = 0; k < rows.shape(0); ++k) {
            const double* o = &rays_.origins[3 * (down_ + checked(rows.data()[k], segment_.size()))];
            points.insert(points.end(), o, o + 3);
        }
        return numpy_of(points, {rows.shape(0), 3});
    }

    // The probes `rows` stand on ground across a crack, `distances` (metres) below their lifted points
    void set_ground(Rows rows, Values distances) {
        if (distances.shape(0) != rows.shape(0)) throw nb::value_error("WalkBatch: one distance per row");
        for (size_t k = 0; k < rows.shape(0); ++k) {
            const size_t p = checked(rows.data()[k], segment_.size());
            good_[p] = 1;
            ground_distance_[p] = distances.data()[k];
        }
    }

    // The walk test after the ground: the lifted and side lines, head room, the gap and the rise between
    // neighbouring probes. (ok (n,) bool before the band test, rise (n,) float64, the rows of the walks the band
    // test is still to ask about, and their low (k, 3), along (k, 3), side (k, 3) and, with `body`, heights (k, 2))
    nb::tuple verdict(Values normal_y, double least_y, double height, double max_climb, double tan_slope,
                      double height_tolerance, std::optional<double> max_gap, double knee, double head, bool body) {
        std::vector<uint8_t> ok(n_, 1);
        size_t at = across_;
        for (size_t i = 0; i < n_; ++i)
            if (moving_[i]) ok[i] = rays_.distance[at++] >= lengths_[i];
        for (const size_t begin : {left_, right_}) {
            at = begin;
            for (size_t i = 0; i < n_; ++i)
                if (sideways_[i]) {
                    ok[i] = ok[i] && (rays_.distance[at] >= lengths_[i] || walkable(rays_.face[at], normal_y, least_y));
                    ++at;
                }
        }
        const size_t probes = segment_.size();
        std::vector<double>& ground_y = ground_y_;
        ground_y.assign(probes, 0.0);
        for (size_t p = 0; p < probes; ++p) {
            const double y = line_[3 * p + 1];
            ground_y[p] = good_[p] ? (y + lift_) - ground_distance_[p] : y;
            if (good_[p]) {
                const double above = height - ((y + lift_) - ground_y[p]);
                good_[p] = rays_.distance[up_ + p] >= above - height_tolerance;
            }
            if (max_gap) good_[p] = good_[p] && std::fabs(ground_y[p] - y) <= *max_gap;
        }
        std::vector<double> rise(n_);
        for (size_t i = 0; i < n_; ++i) {
            const size_t begin = first_[i], end = begin + static_cast<size_t>(intervals_[i]) + 1;
            bool has_ground = true, steep = false;
            double largest = 0.0;
            const double dh = horizontal_[i] / static_cast<double>(intervals_[i]);
            const double max_rise = std::max(max_climb, tan_slope * dh);
            for (size_t p = begin; p < end; ++p) {
                has_ground = has_ground && good_[p];
                if (p + 1 < end) {
                    const double dy = std::fabs(ground_y[p + 1] - ground_y[p]);
                    steep = steep || dy > max_rise + 1e-6;
                    largest = std::max(largest, dy);
                }
            }
            ok[i] = ok[i] && has_ground && !steep;
            rise[i] = has_ground ? largest : INF;
        }
        std::vector<int64_t> rows;
        std::vector<double> low, along, side, heights;
        for (size_t i = 0; i < n_; ++i) {
            if (!sideways_[i] || !ok[i]) continue;
            rows.push_back(static_cast<int64_t>(i));
            low.insert(low.end(), &low_[3 * i], &low_[3 * i] + 3);
            along.insert(along.end(), &vectors_[3 * i], &vectors_[3 * i] + 3);
            side.insert(side.end(), &side_[3 * i], &side_[3 * i] + 3);
            if (body) heights.insert(heights.end(), {std::min(knee + std::fabs(vectors_[3 * i + 1]), lift_) - lift_,
                                                     head - lift_});
        }
        const size_t k = rows.size();
        nb::object band_heights = body ? nb::cast(numpy_of(heights, {k, 2})) : nb::none();
        return nb::make_tuple(bools_of(ok), numpy_of(rise, {n_}), numpy_of(rows, {k}), numpy_of(low, {k, 3}),
                              numpy_of(along, {k, 3}), numpy_of(side, {k, 3}), band_heights);
    }

    // The rays over the steps of the walks `rows` (after verdict(), whose ground they read): from each probe to the
    // next, horizontally, `climb` over the lower of the two probes' ground or at the higher one's, whichever is
    // higher, plus `tolerance`: where the slope test lets two probes differ by more than the climb (a probe step over
    // two risers of a steep stair), a ray at the climb would meet the upper riser of a stair the agent climbs
    StepRays steps(Rows rows, double climb, double tolerance) const {
        if (ground_y_.size() != segment_.size()) throw nb::value_error("WalkBatch: steps() after verdict()");
        StepRays out;
        out.walks = rows.shape(0);
        for (size_t k = 0; k < rows.shape(0); ++k) {
            const size_t i = checked(rows.data()[k], n_);
            const size_t begin = first_[i], end = begin + static_cast<size_t>(intervals_[i]);
            for (size_t p = begin; p < end; ++p) {
                const double* a = &line_[3 * p];
                const double* b = &line_[3 * (p + 1)];
                const double low = std::min(ground_y_[p], ground_y_[p + 1]);
                const double high = std::max(ground_y_[p], ground_y_[p + 1]);
                const double origin[3] = {a[0], std::max(low + climb, high) + tolerance, a[2]};
                const double direction[3] = {b[0] - a[0], 0.0, b[2] - a[2]};
                const double horizontal = std::hypot(direction[0], direction[2]);
                if (horizontal <= 1e-9) continue;  // a vertical walk: no step between its probes
                out.rays.add(origin, direction);
                out.walk.push_back(static_cast<int64_t>(k));
                out.length.push_back(horizontal);
            }
        }
        return out;
    }

  private:
    static bool walkable(int64_t face, const Values& normal_y, double least_y) {
        return face >= 0 && normal_y.data()[face] >= least_y;
    }
    static size_t checked(int64_t row, size_t size) {
        if (row < 0 || static_cast<size_t>(row) >= size) throw nb::value_error("WalkBatch: row out of range");
        return static_cast<size_t>(row);
    }

    double lift_;
    size_t n_ = 0;
    std::vector<double> start_, end_, low_, vectors_, side_, lengths_, horizontal_, line_;
    std::vector<int64_t> intervals_;
    std::vector<size_t> first_, segment_;
    std::vector<uint8_t> moving_, sideways_, good_;
    std::vector<double> ground_distance_, ground_y_;
    Rays rays_;
    size_t across_ = 0, down_ = 0, up_ = 0, left_ = 0, right_ = 0;
};

}  // namespace

NB_MODULE(_walks, m) {
    m.doc() = "One batch of the walk test's arithmetic round its ray casts (see src/walks_module.cpp).";
    nb::class_<StepRays>(m, "StepRays", "the horizontal rays between neighbouring probes over the lower's ground")
        .def("rays", &StepRays::local, nb::arg("shift").none(),
             "(origins (R, 3) float64, shifted by -shift unless None; unit directions (R, 3) float64)")
        .def("hit", &StepRays::hit, nb::arg("faces"), nb::arg("local"), nb::arg("normals"), nb::arg("plane_points"),
             nb::arg("centroids"), nb::arg("twin"), "the intersector's faces (R,) -> rows of the grazing rays")
        .def("set_hits", &StepRays::set_hits, nb::arg("rows"), nb::arg("faces"), nb::arg("distances"))
        .def("blocked", &StepRays::blocked, nb::arg("normal_y"), nb::arg("least_y"),
             "(walks,) bool: a steep face across a ray short of its next probe");
    nb::class_<WalkBatch>(m, "WalkBatch", "the walk test's probe points, rays and tests of one batch of walks")
        .def(nb::init<Rows3, Rows3, double, double, double>(), nb::arg("starts"), nb::arg("ends"), nb::arg("lift"),
             nb::arg("probe_step"), nb::arg("half_width"))
        .def("rays", &WalkBatch::rays, nb::arg("shift").none(),
             "(origins (R, 3) float64, shifted by -shift unless None; unit directions (R, 3) float64)")
        .def("hit", &WalkBatch::hit, nb::arg("faces"), nb::arg("local"), nb::arg("normals"), nb::arg("plane_points"),
             nb::arg("centroids"), nb::arg("twin"), "the intersector's faces (R,) -> rows of the grazing rays")
        .def("set_hits", &WalkBatch::set_hits, nb::arg("rows"), nb::arg("faces"), nb::arg("distances"))
        .def("ground", &WalkBatch::ground, nb::arg("reach"), nb::arg("normal_y"), nb::arg("least_y"),
             "rows of the probes without walkable ground within reach")
        .def("probe_points", &WalkBatch::probe_points, nb::arg("rows"),
             "the lifted probe points (k, 3) of rows, world frame, for ground_across_crack")
        .def("set_ground", &WalkBatch::set_ground, nb::arg("rows"), nb::arg("distances"),
             "the probes rows stand on ground across a crack, distances below their lifted points")
        .def("verdict", &WalkBatch::verdict, nb::arg("normal_y"), nb::arg("least_y"), nb::arg("height"),
             nb::arg("max_climb"), nb::arg("tan_slope"), nb::arg("height_tolerance"), nb::arg("max_gap").none(),
             nb::arg("knee"), nb::arg("head"), nb::arg("body"),
             "(ok (n,), rise (n,), band rows (k,), low, along, side (k, 3), heights (k, 2) or None)")
        .def("steps", &WalkBatch::steps, nb::arg("rows"), nb::arg("climb"), nb::arg("tolerance"),
             "the rays over the steps of the walks rows (after verdict): at the climb over the lower probe's ground or "
             "the higher's ground, whichever is higher, plus tolerance");
}
