// g2s_plugins._trees: sums over the subtrees of many rooted trees at once.
//
// The flow of area-weighted betweenness and of the `flow` analyzer pushes each
// node's value up a shortest-path tree (one tree per source, given as parent
// rows): a node's sum is its value plus its children's sums. numpy did this
// one depth level at a time after pointer jumping, O(b n log depth) with many
// passes over b x n arrays; here each tree is one O(n) pass.
//
// The sums are the same bits as that numpy formulation: a node's children are
// added in increasing index order exactly as numpy's `np.add.reduceat` adds a
// segment (the first child, plus numpy's pairwise sum of the others), and that
// total is then added to the node's own value.

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <cstdint>
#include <vector>

namespace nb = nanobind;

namespace {

// numpy's pairwise summation of n doubles (its add reduction; blocks of 128, 8 accumulators).
double pairwise_sum(const double* a, int64_t n) {
    if (n < 8) {
        double res = -0.0;
        for (int64_t i = 0; i < n; ++i) res += a[i];
        return res;
    }
    if (n <= 128) {
        double r[8];
        for (int j = 0; j < 8; ++j) r[j] = a[j];
        int64_t i = 8;
        for (; i < n - (n % 8); i += 8)
            for (int j = 0; j < 8; ++j) r[j] += a[i + j];
        double res = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
        for (; i < n; ++i) res += a[i];
        return res;
    }
    int64_t half = n / 2;
    half -= half % 8;
    return pairwise_sum(a, half) + pairwise_sum(a + half, n - half);
}

// One tree: children of each node in increasing index order (a CSR built by
// counting), then nodes in an order that finishes every child before its parent.
// Returns false when the row is not a forest.
template <typename P>
bool one_tree(const P* parent, const double* values, int64_t n, double* sums, std::vector<int64_t>& first,
              std::vector<int64_t>& children, std::vector<int64_t>& pending, std::vector<int64_t>& ready,
              std::vector<double>& buffer) {
    first.assign(static_cast<size_t>(n) + 1, 0);
    for (int64_t i = 0; i < n; ++i)
        if (parent[i] >= 0) ++first[static_cast<size_t>(parent[i]) + 1];
    for (int64_t i = 0; i < n; ++i) first[i + 1] += first[i];
    children.resize(static_cast<size_t>(first[n]));
    pending.assign(first.begin(), first.end() - 1);  // next free slot per node
    for (int64_t i = 0; i < n; ++i)
        if (parent[i] >= 0) children[pending[parent[i]]++] = i;
    for (int64_t i = 0; i < n; ++i) pending[i] = first[i + 1] - first[i];  // children not yet summed
    ready.clear();
    for (int64_t i = 0; i < n; ++i)
        if (pending[i] == 0) ready.push_back(i);
    for (size_t k = 0; k < ready.size(); ++k) {
        const int64_t v = ready[k];
        const int64_t lo = first[v], count = first[v + 1] - lo;
        double total = values[v];
        if (count > 0) {
            buffer.resize(static_cast<size_t>(count));
            for (int64_t c = 0; c < count; ++c) buffer[c] = sums[children[lo + c]];
            double branch = buffer[0];
            if (count > 1) branch += pairwise_sum(buffer.data() + 1, count - 1);
            total += branch;
        }
        sums[v] = total;
        const int64_t p = parent[v];
        if (p >= 0 && --pending[p] == 0) ready.push_back(p);
    }
    return static_cast<int64_t>(ready.size()) == n;  // nodes on a cycle never become ready
}

template <typename P>
nb::ndarray<nb::numpy, double, nb::ndim<2>> subtree_sums(
    nb::ndarray<const P, nb::ndim<2>, nb::c_contig, nb::device::cpu> parent,
    nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu> values) {
    const int64_t b = static_cast<int64_t>(parent.shape(0)), n = static_cast<int64_t>(parent.shape(1));
    if (static_cast<int64_t>(values.shape(0)) != n)
        throw nb::value_error("subtree_sums: parent must be (b, n) and values (n,)");
    const P* pp = parent.data();
    for (int64_t i = 0; i < b * n; ++i)
        if (pp[i] >= n) throw nb::value_error("subtree_sums: a parent row is out of range");
    auto* out = new double[static_cast<size_t>(b * n > 0 ? b * n : 1)];
    nb::capsule owner(out, [](void* p) noexcept { delete[] static_cast<double*>(p); });
    bool forests = true;
    {
        nb::gil_scoped_release release;
        std::vector<int64_t> first, children, pending, ready;
        std::vector<double> buffer;
        for (int64_t row = 0; row < b && forests; ++row)
            forests = one_tree(pp + row * n, values.data(), n, out + row * n, first, children, pending, ready, buffer);
    }
    if (!forests) throw nb::value_error("subtree_sums: a parent row has a cycle");
    return nb::ndarray<nb::numpy, double, nb::ndim<2>>(out, {static_cast<size_t>(b), static_cast<size_t>(n)}, owner);
}

}  // namespace

NB_MODULE(_trees, m) {
    m.doc() = "Sums over the subtrees of many rooted trees (see src/trees_module.cpp).";
    const char* doc =
        "subtree_sums(parent, values) -> (b, n) float64: for b trees over the same n nodes, "
        "given as (b, n) parent rows (negative: a root or an unreached node), each node's value "
        "plus its descendants' values. Every row must be a forest (no parent cycles).";
    m.def("subtree_sums", &subtree_sums<int32_t>, nb::arg("parent"), nb::arg("values"), doc);
    m.def("subtree_sums", &subtree_sums<int64_t>, nb::arg("parent"), nb::arg("values"), doc);
}
