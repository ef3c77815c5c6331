// g2s_plugins._trees: shortest-path trees from many sources, and the weight each node carries in them; the
// same weight with every pair's value split evenly over all its shortest paths (split_path_flow, below); either
// linearly scaled by how far along its path a node lies (linear_path_flow).
// Also here, each described where it is defined: the coverage selector's cover (cover_paths), the loop
// adder's greedy loop (greedy_loops) and the Steiner solvers' spanning forest (spanning_forest).
//
// The `flow` analyzer and area-weighted betweenness walk the initial graph from
// hundreds of sources: one shortest-path tree per source, then each node's
// value summed up its tree. scipy.sparse.csgraph.dijkstra builds the trees but
// holds the GIL, so it cannot use a second core (two Python threads: 1.02-1.07x,
// docs/performance.md); here both steps run in C++ on up to two threads, each
// tree one search and one sweep back up it.
//
// The trees are scipy's to the last tie. Where two paths have exactly the same
// length (common on generated, grid-aligned levels) the predecessor a node keeps
// is the first node settled that reaches it that short, so it depends on the
// order in which the search settles nodes at equal distances. scipy (from 1.15;
// sparse/csgraph/_shortest_path.pyx) queues (-distance, index) pairs in a
// std::priority_queue, skips stale entries, and replaces a predecessor only on
// a strictly shorter path: equal distances settle highest index first. That
// order is total, so any correct heap with the same order settles the nodes in
// the same sequence; the search below keeps it, and tests/test_analysis_quality.py
// checks the predecessors against scipy's on tie-rich grids and random graphs.
// (Before 1.15 scipy used a Fibonacci heap with another tie order; from this
// module the flow no longer depends on the scipy version.)
//
// Corridors. Most nodes of a navmesh graph are *passages*: exactly two
// neighbours, linked both ways, and no other edge (70 % of the 100k-polygon
// level's nodes). The search queues only the other nodes; a settled node walks
// each corridor it opens onto to its far end, adding the lengths one by one as
// the plain search would, so every distance is the same float. What the walk
// changes is when a node is reached, not by how much, so the tie rule is
// applied explicitly instead of by the order of arrival: a node reached as
// short again takes the new predecessor when that one settles first in scipy's
// order (nearer, or as near with a higher index). Then every node keeps, of the
// neighbours that reach it shortest, the one settled first, as in scipy's
// search: the same tree. The walk stops where it arrives longer than the node
// already is (the corridor beyond is nearer from its other end). The sweep up
// the tree takes its nodes in breadth-first order from the source (parents
// before children) instead of the order they settled in. That settling order
// is scipy's (distance, higher index) order only when every edge lengthens the
// path: a length that vanishes beside a distance (0, or 1e-12 m beside 10 km)
// lets a node settle after a node as near with a lower index, the one that
// reached it. A graph with such a length is searched without corridors and
// without the explicit tie rule, node by node as scipy does.
//
// The sums are the same bits as numpy: a node's children are added in
// increasing index order as numpy's `np.add.reduceat` adds a segment (the first
// child, plus numpy's pairwise sum of the others), and that total is then added
// to the node's own value.

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <limits>
#include <optional>
#include <thread>
#include <vector>

namespace nb = nanobind;

namespace {

constexpr int32_t NO_PREDECESSOR = -9999;  // scipy's mark for a source or an unreached node

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

// An entry of the search's queue. Queued earlier than `other` means: nearer, or as near with a higher
// index (scipy's order, see the file comment) in the caller's numbering: `key`, the node's index there (Graph::key;
// it fills the padding, so an entry is 16 bytes as without it).
struct Entry {
    double distance;
    int32_t node;
    int32_t key;
};
// "a is served after b": the queue keeps the first-served entry on top.
struct ServedAfter {
    bool operator()(const Entry& a, const Entry& b) const {
        return a.distance > b.distance || (a.distance == b.distance && a.key < b.key);
    }
};

// Dijkstra's search from one source in scipy's order (see the file comment), its buffers kept from source to
// source: run(source, key, settle) calls settle(v) once for each node v = {distance, node, key} as the search
// settles it, nearest first and, as near, highest key (index in the caller's numbering) first; settle looks along
// v's edges, lowers `distance` of each node it reaches nearer and queues it with its key (queue). O(m log m) with a
// settle that queues each node reached nearer.
//
// The queue is a 4-ary heap (D. B. Johnson, "Priority queues with update and finding minimum spanning trees",
// Inf. Process. Lett. 4(3):53-57, 1975): half the levels of a binary heap, a node's four children side by side,
// so a pop waits on memory half as often for two more comparisons a level: 4.2-7.1 % less CPU a source than
// std::push_heap/pop_heap's binary heap on the 100k-polygon level's navmesh graph (three replays, 10 of 11 rounds
// lower; an 8-ary heap 2.2 %: docs/performance.md, navtime49). Two entries ServedAfter ranks alike are equal (the
// same distance and key, so the same node), so any correct heap serves the same sequence of entries. O(log q) a
// push or pop for q queued entries.
class Search {
  public:
    explicit Search(int32_t n) : distance(static_cast<size_t>(n)) {}

    template <typename Settle>
    void run(int32_t source, int32_t key, Settle settle) {
        std::fill(distance.begin(), distance.end(), std::numeric_limits<double>::infinity());
        queue_.clear();
        distance[source] = 0.0;
        queue_.push_back({0.0, source, key});
        while (!queue_.empty()) {
            const Entry v = pop();
            // a stale entry: v was queued again nearer (a node is queued only nearer than before, so the entry
            // as near as the node is its last, and the node settles once)
            if (distance[v.node] < v.distance) continue;
            settle(v);
        }
    }
    // always inlined, as the kernels' settle lambdas are: at -Os (nanobind's default flags, the module's then) a
    // call per queued node cost 2 % more instructions in both kernels, and an outlined settle up to 0.9 %
    // (callgrind, 20k dungeon)
    __attribute__((always_inline)) void queue(double d, int32_t u, int32_t key) {
        const Entry entry{d, u, key};
        size_t hole = queue_.size();
        queue_.push_back(entry);
        Entry* heap = queue_.data();
        while (hole > 0) {  // up from the new leaf while its parent is served after it
            const size_t parent = (hole - 1) / ARITY;
            if (!ServedAfter()(heap[parent], entry)) break;
            heap[hole] = heap[parent];
            hole = parent;
        }
        heap[hole] = entry;
    }

    // The node on top of the queue, -1 when it is empty: the next to settle unless a nearer one is queued first.
    int32_t next() const { return queue_.empty() ? -1 : queue_.front().node; }

    std::vector<double> distance;  // (n,) from the source, m; infinity: not reached (yet)

  private:
    static constexpr size_t ARITY = 4;

    // The first-served entry, taken off the queue: the last leaf goes down from the top while a child is served
    // before it.
    Entry pop() {
        Entry* heap = queue_.data();
        const Entry top = heap[0], last = queue_.back();
        queue_.pop_back();
        const size_t size = queue_.size();
        if (size == 0) return top;
        size_t hole = 0;
        for (size_t first = 1; first < size; first = hole * ARITY + 1) {
            size_t best = first;
            for (size_t child = first + 1; child < std::min(first + ARITY, size); ++child)
                if (ServedAfter()(heap[best], heap[child])) best = child;
            if (!ServedAfter()(last, heap[best])) break;
            heap[hole] = heap[best];
            hole = best;
        }
        heap[hole] = last;
        return top;
    }

    std::vector<Entry> queue_;
};

struct Graph {
    const int32_t* indptr;
    const int32_t* indices;
    const double* weights;
    const uint8_t* passage;  // (n,) 1: a passage node (see the file comment), which the search walks through
    bool corridors;          // any passage node: the search walks corridors and applies the tie rule itself
    int32_t n;
    // (n,) each node's index in the caller's numbering, where the caller renumbered the graph for the kernel
    // (Renumbering); nullptr: the same numbering
    const int32_t* original = nullptr;

    // The node's index in the caller's numbering: the searches' tie order.
    __attribute__((always_inline)) int32_t key(int32_t v) const { return original != nullptr ? original[v] : v; }
};

// Asks the memory for node v's row of the CSR arrays (its neighbours and their lengths), which a kernel will read
// a few steps on (why: SplitSweep's comment on AHEAD_ROW_START). It changes no value.
__attribute__((always_inline)) inline void prefetch_row(const Graph& g, int32_t v) {
    __builtin_prefetch(g.indices + g.indptr[v]);
    __builtin_prefetch(g.weights + g.indptr[v]);
}
// The row of the node on top of `search`'s queue, likely the next to settle, read while a settle relaxes the
// current node's edges.
__attribute__((always_inline)) inline void prefetch_next_row(const Graph& g, const Search& search) {
    if (const int32_t next = search.next(); next >= 0) prefetch_row(g, next);
}

// Whether adding any finite length of `weights` (m,) to any distance of the graph gives a longer distance
// (see the file comment): the shortest is at least one unit in the last place of twice the sum of all.
bool lengths_always_add(const double* weights, size_t m) {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    double total = 0.0, shortest = infinity;
    for (size_t j = 0; j < m; ++j)
        if (weights[j] < infinity) {  // an infinite or NaN length reaches nothing
            total += weights[j];
            shortest = std::min(shortest, weights[j]);
        }
    const double longest = 2.0 * total;
    return shortest > 0.0 && shortest >= std::nextafter(longest, infinity) - longest;
}

// (n,) 1 for each passage node of the CSR graph: two row entries, two different neighbours other than
// itself, each listing it, and no other node listing it; all 0 when a length can vanish beside a distance
// (lengths_always_add). O(m).
std::vector<uint8_t> passages(const int32_t* indptr, const int32_t* indices, const double* weights, int32_t n) {
    std::vector<uint8_t> passage(static_cast<size_t>(n), 0);
    if (!lengths_always_add(weights, static_cast<size_t>(indptr[n]))) return passage;
    std::vector<int32_t> listed(static_cast<size_t>(n), 0);
    for (int32_t j = 0; j < indptr[n]; ++j) ++listed[indices[j]];
    auto lists = [&](int32_t from, int32_t to) {
        return std::find(indices + indptr[from], indices + indptr[from + 1], to) != indices + indptr[from + 1];
    };
    for (int32_t u = 0; u < n; ++u) {
        if (indptr[u + 1] - indptr[u] != 2 || listed[u] != 2) continue;
        const int32_t x = indices[indptr[u]], y = indices[indptr[u] + 1];
        passage[u] = x != y && x != u && y != u && lists(x, u) && lists(y, u);
    }
    return passage;
}

// One source: its shortest-path tree (scipy's predecessors) and, per node, the
// values summed over its subtree minus its own value (0 for the source).
class TreeSweep {
  public:
    explicit TreeSweep(int32_t n)
        : search_(n), sums_(static_cast<size_t>(n)), order_(static_cast<size_t>(n)),
          first_child_(static_cast<size_t>(n) + 1), next_child_(static_cast<size_t>(n)), children_(static_cast<size_t>(n)) {}

    void run(const Graph& g, int32_t source, const double* values, int32_t* predecessor, double* through) {
        search(g, source, predecessor);
        sum(g, source, values, predecessor, through);
    }

    // The tree from `source` into `predecessor` (n,) and the distances (distance()).
    void search(const Graph& g, int32_t source, int32_t* predecessor) {
        constexpr double infinity = std::numeric_limits<double>::infinity();
        std::fill(predecessor, predecessor + g.n, NO_PREDECESSOR);
        std::vector<double>& distance = search_.distance;
        // whether `a` settles before `b` in scipy's search: nearer, or as near with a higher index
        auto settles_before = [&](int32_t a, int32_t b) {
            return distance[a] < distance[b] || (distance[a] == distance[b] && a > b);
        };
        // `u` reached at `d` from `from`: shorter, or (walking corridors) as short from a node that settles first;
        // never the source
        auto reach = [&](int32_t u, double d, int32_t from) __attribute__((always_inline)) {
            if (distance[u] > d) {
                distance[u] = d;
                predecessor[u] = from;
                return true;
            }
            if (g.corridors && distance[u] == d && predecessor[u] >= 0 && settles_before(from, predecessor[u]))
                predecessor[u] = from;
            return false;
        };
        // the source is where the search starts, never a node to walk through
        auto passage = [&](int32_t u) { return g.passage[u] && u != source; };
        search_.run(source, source, [&](const Entry& v) __attribute__((always_inline)) {
            // 5-12 % less CPU a source on the 100k-polygon level's navmesh graph (docs/performance.md, 6 December
            // 2026, 15:43-15:56 UTC); a corridor's passages cannot be asked for ahead, each found from the last
            prefetch_next_row(g, search_);
            for (int32_t j = g.indptr[v.node]; j < g.indptr[v.node + 1]; ++j) {
                int32_t u = g.indices[j], from = v.node;
                double d = v.distance + g.weights[j];
                // along a corridor to its far end, or to where it arrives longer than the node already is; a NaN
                // length is no edge, as in scipy, and an infinite one reaches nothing
                while (passage(u) && d < infinity && d <= distance[u]) {
                    reach(u, d, from);
                    const int32_t k = g.indptr[u] + (g.indices[g.indptr[u]] == from ? 1 : 0);
                    from = u;
                    d += g.weights[k];
                    u = g.indices[k];
                }
                if (!passage(u) && d < infinity && reach(u, d, from)) search_.queue(d, u, u);
            }
        });
    }

    // The sums up the tree search() left in `predecessor`: `values` (n,) summed over each node's subtree minus its
    // own value, into `through` (n,).
    void sum(const Graph& g, int32_t source, const double* values, const int32_t* predecessor, double* through) {
        for (int32_t v = 0; v < g.n; ++v) through[v] = values[v] - values[v];  // unreached nodes carry nothing
        // every node's children in increasing index order, by one counting sort of the predecessors: two
        // passes in index order instead of rescanning each settled node's edges (15 % of the whole call on
        // the 100k-polygon level, docs/performance.md)
        std::fill(first_child_.begin(), first_child_.end(), 0);
        for (int32_t v = 0; v < g.n; ++v)
            if (predecessor[v] >= 0) ++first_child_[predecessor[v] + 1];
        for (int32_t v = 0; v < g.n; ++v) first_child_[v + 1] += first_child_[v];
        std::copy(first_child_.begin(), first_child_.end() - 1, next_child_.begin());
        for (int32_t v = 0; v < g.n; ++v)
            if (predecessor[v] >= 0) children_[next_child_[predecessor[v]]++] = v;
        // breadth first from the source, parents before children: in reverse every subtree is complete when
        // its root comes
        // (each node's children copied by a plain loop: most nodes have one child or none, for which a call to
        // vector::insert cost more than the copy)
        int32_t* order = order_.data();
        int32_t size = 1;
        order[0] = source;
        for (int32_t i = 0; i < size; ++i)
            for (int32_t c = first_child_[order[i]]; c < first_child_[order[i] + 1]; ++c) order[size++] = children_[c];
        for (int32_t i = size - 1; i >= 0; --i) {
            const int32_t v = order[i];
            const int32_t first = first_child_[v], count = first_child_[v + 1] - first;
            double total = values[v];
            if (count == 1) {
                total += sums_[children_[first]];  // the branch of one child is that child's sum
            } else if (count > 1) {
                buffer_.resize(static_cast<size_t>(count));
                for (int32_t c = 0; c < count; ++c) buffer_[c] = sums_[children_[first + c]];
                total += buffer_[0] + pairwise_sum(buffer_.data() + 1, static_cast<int64_t>(count) - 1);
            }
            sums_[v] = total;
            through[v] = total - values[v];
        }
        through[source] = 0.0;
    }

    // (n,) the last search's distances from its source, m (infinity: unreached): scipy's, bit for bit
    const std::vector<double>& distance() const { return search_.distance; }

  private:
    Search search_;
    std::vector<double> sums_, buffer_;
    std::vector<int32_t> order_, first_child_, next_child_, children_;
};

// x 2^k, std::ldexp(x, k) bit for bit without its library call (a fifth of split_path_flow's instructions went to
// ldexp, callgrind on a grid of samples): where the result is a normal number, as it is for the path counts' x in
// [0.5, 2) and |k| <= 1000, it is exact, and so is one product by 2^k; other k go to ldexp.
double times_power_of_two(double x, int k) {
    if (k < -1000 || k > 1000) return std::ldexp(x, k);
    const uint64_t bits = static_cast<uint64_t>(k + 1023) << 52;  // 2^k: biased exponent, zero fraction
    double factor;
    std::memcpy(&factor, &bits, sizeof factor);
    return x * factor;
}

// A number of shortest paths, mantissa x 2^exponent (mantissa in [0.5, 1), or 0): on a grid the count of
// equally short paths between two places grows like a binomial coefficient, which passes a double's largest
// value (1.8e308) across a few tens of rooms of tied paths; only ratios of counts are used, and those this
// form gives without overflow.
struct PathCount {
    double mantissa = 0.0;
    int64_t exponent = 0;

    void add(const PathCount& other) {
        if (other.mantissa == 0.0) return;
        if (mantissa == 0.0) {
            *this = other;
            return;
        }
        const int64_t top = std::max(exponent, other.exponent);
        // both terms scaled to the larger exponent: the smaller one loses only bits below the sum's last place
        const double sum = times_power_of_two(mantissa, static_cast<int>(std::max<int64_t>(exponent - top, -1100))) +
                           times_power_of_two(other.mantissa, static_cast<int>(std::max<int64_t>(other.exponent - top, -1100)));
        // std::frexp's split of the sum: the term at the top exponent is in [0.5, 1) and the other in [0, 1), so
        // the sum is in [0.5, 2), and halving it when it is 1 or more is exact
        if (sum >= 1.0) {
            mantissa = sum * 0.5;
            exponent = top + 1;
        } else {
            mantissa = sum;
            exponent = top;
        }
    }
    // this / other (other not 0)
    double over(const PathCount& other) const {
        return times_power_of_two(mantissa / other.mantissa,
                                  static_cast<int>(std::clamp<int64_t>(exponent - other.exponent, -1100, 1100)));
    }
};

// How many settled nodes ahead split_path_flow's sweeps ask the memory for what they will read (the prefetches
// of SplitSweep; they change no value). A search settles nodes ring by ring round its source, so consecutive nodes
// lie far apart in the arrays and nearly every node's row of the CSR arrays, and its neighbours' entries, is a
// cache miss (on the sampling route's 100k level, 680k nodes and 5.6M edges, some 100 MB read per source); the
// passes over the settled nodes know their order in advance and ask for a node's row, then its neighbours'
// entries, this many nodes before they need them. Measured on that level (docs/performance.md, 6 December
// 2026, 14:29-14:47 UTC): a third less CPU a source (about 375 -> 255 ms); 32, 16 and 8 are the only distances
// tried.
constexpr int32_t AHEAD_ROW_START = 32, AHEAD_ROW = 16, AHEAD_NEIGHBOURS = 8;

// One source, every pair's value split evenly over all its shortest paths: Brandes's accumulation (U. Brandes,
// "A faster algorithm for betweenness centrality", J. Mathematical Sociology 25(2):163-177, 2001) with a value
// per target (U. Brandes, "On variants of shortest-path betweenness centrality and their generic
// computation", Social Networks 30(2):136-145, 2008, the weighted-endpoint form):
//
//   through(v) = sum over targets t != v of values[t] sigma(v) sigma(v -> t) / sigma(t)
//              = sum over w with v a predecessor of w of sigma(v) / sigma(w) (values[w] + through(w))
//
// sigma(x) the number of shortest paths from the source to x. The distances are a plain Dijkstra search's (the
// same floats as scipy's); the nodes it settles, in the order it settles them, form a list in which an edge
// v -> w is a *shortest-path edge* when v comes before w and distance(v) + length <= distance(w) (1 +
// tolerance): path lengths equal within the relative tolerance tie. Each shortest-path edge points forward in
// the list, so they form a DAG whatever the tolerance and even with lengths of 0; one pass forward over the
// list adds up the path counts, one pass back the values, each node's edges in CSR order: the same bits on
// any thread. O(m log m) for the search, O(m) for each pass.
class SplitSweep {
  public:
    explicit SplitSweep(int32_t n)
        : search_(n), count_(static_cast<size_t>(n)), position_(static_cast<size_t>(n)), order_(static_cast<size_t>(n)),
          first_head_(static_cast<size_t>(n) + 1) {}

    void run(const Graph& g, int32_t source, const double* values, double tolerance, double* through) {
        search(g, source);
        sum(g, source, values, tolerance, through);
    }

    // The search from `source`: the distances (distance()) and the order the nodes settle in.
    void search(const Graph& g, int32_t source) {
        std::vector<double>& distance = search_.distance;
        std::fill(position_.begin(), position_.end(), -1);
        int32_t settled = 0;
        search_.run(source, g.key(source), [&](const Entry& v) __attribute__((always_inline)) {
            prefetch_next_row(g, search_);
            position_[v.node] = settled;
            order_[settled++] = v.node;
            for (int32_t j = g.indptr[v.node]; j < g.indptr[v.node + 1]; ++j) {
                const int32_t u = g.indices[j];
                const double d = v.distance + g.weights[j];  // a NaN length is no edge, as in scipy
                if (d < distance[u]) {
                    distance[u] = d;
                    search_.queue(d, u, g.key(u));
                }
            }
        });
        settled_ = settled;
    }

    // The two passes over the nodes search() settled: `values` (n,) split over the shortest paths, into `through`.
    void sum(const Graph& g, int32_t source, const double* values, double tolerance, double* through) {
        const std::vector<double>& distance = search_.distance;
        const int32_t settled = settled_;
        // whether the edge j leaving settled v is a shortest-path edge
        auto shortest = [&](int32_t v, int32_t j) __attribute__((always_inline)) {
            const int32_t w = g.indices[j];
            return position_[w] > position_[v] &&
                   distance[v] + g.weights[j] <= distance[w] + tolerance * distance[w];
        };
        for (int32_t i = 0; i < settled; ++i) count_[order_[i]] = PathCount{};
        count_[source] = PathCount{0.5, 1};
        // the forward pass keeps the shortest-path edges it finds, each node's in CSR order, so that the pass back
        // reads them instead of testing every edge again (half the kernel's instructions went to that test)
        heads_.clear();
        for (int32_t i = 0; i < settled; ++i) {
            const int32_t v = order_[i];
            prefetch_ahead(g, i, settled);
            first_head_[i] = heads_.size();
            for (int32_t j = g.indptr[v]; j < g.indptr[v + 1]; ++j)
                if (shortest(v, j)) {
                    heads_.push_back(g.indices[j]);
                    count_[g.indices[j]].add(count_[v]);
                }
        }
        first_head_[settled] = heads_.size();
        for (int32_t v = 0; v < g.n; ++v) through[v] = 0.0;  // unreached nodes carry nothing
        for (int32_t i = settled - 1; i >= 0; --i) {  // each w a shortest-path edge leads to comes later: done
            const int32_t v = order_[i];
            if (i >= AHEAD_NEIGHBOURS) {  // the entries the node this many places back will read
                const int32_t back = i - AHEAD_NEIGHBOURS;
                __builtin_prefetch(&count_[order_[back]]);
                __builtin_prefetch(&through[order_[back]], 1);
                for (size_t k = first_head_[back]; k < first_head_[back + 1]; ++k) {
                    __builtin_prefetch(&count_[heads_[k]]);
                    __builtin_prefetch(&values[heads_[k]]);
                    __builtin_prefetch(&through[heads_[k]]);
                }
            }
            double total = 0.0;
            for (size_t k = first_head_[i]; k < first_head_[i + 1]; ++k) {
                const int32_t w = heads_[k];
                total += count_[v].over(count_[w]) * (values[w] + through[w]);
            }
            through[v] = total;
        }
        through[source] = 0.0;
    }

    // (n,) the last search's distances from its source, m (infinity: unreached): scipy's, bit for bit
    const std::vector<double>& distance() const { return search_.distance; }

  private:
    // For the forward pass at settled place i (of `settled`): the memory the nodes AHEAD_ROW_START, AHEAD_ROW and
    // AHEAD_NEIGHBOURS places on will read (their row's start, their row, their neighbours' entries), each asked for
    // when the step before has brought in what its address needs. Always inlined: as a call, the pass lost most of
    // the gain (322 against 260 ms of CPU a source on that level).
    __attribute__((always_inline)) void prefetch_ahead(const Graph& g, int32_t i, int32_t settled) {
        if (i + AHEAD_ROW_START < settled) __builtin_prefetch(g.indptr + order_[i + AHEAD_ROW_START]);
        if (i + AHEAD_ROW < settled) prefetch_row(g, order_[i + AHEAD_ROW]);
        if (i + AHEAD_NEIGHBOURS < settled) {
            const int32_t ahead = order_[i + AHEAD_NEIGHBOURS];
            for (int32_t j = g.indptr[ahead]; j < g.indptr[ahead + 1]; ++j) {
                __builtin_prefetch(&position_[g.indices[j]]);
                __builtin_prefetch(&search_.distance[g.indices[j]]);
                __builtin_prefetch(&count_[g.indices[j]]);
            }
        }
    }

    Search search_;
    std::vector<PathCount> count_;
    std::vector<int32_t> position_, order_;
    int32_t settled_ = 0;  // nodes the last search settled, order_'s first entries
    // the shortest-path edges' heads, those leaving order_[i] at heads_[first_head_[i] .. first_head_[i + 1])
    std::vector<int32_t> heads_;
    std::vector<size_t> first_head_;
};

// Set by the Python thread that starts to wait for a flow computed on one worker (g2s_plugins.traffic's flow begun
// ahead): the call under way reads it between sources, without the GIL, and takes a second worker from its next
// source on, so that the rest of its block does not run on one core while the other idles (up to a block of 39
// sources, about 0.4 s of CPU, at 100k polygons: docs/performance.md).
struct Waiting {
    std::atomic<bool> set{false};
};

// Runs work(worker, row) for rows 0 .. b-1 on `threads` threads (1 or 2), each worker taking whole rows in
// turn; `make` builds each thread's worker (its buffers). With one thread and a `waiting` flag, a second worker
// starts once the flag is set, before the first takes its next row. Which thread takes a row changes no value.
template <typename Make, typename Work>
void for_each_source(size_t b, int threads, const Waiting* waiting, Make make, Work work) {
    nb::gil_scoped_release release;
    std::atomic<size_t> next{0};
    std::vector<std::thread> pool;
    auto run = [&] {
        auto worker = make();
        for (size_t row = next++; row < b; row = next++) work(worker, row);
    };
    auto run_until_waited_for = [&] {
        auto worker = make();
        for (size_t row = next++; row < b; row = next++) {
            if (pool.empty() && row + 1 < b && waiting->set.load(std::memory_order_acquire)) pool.emplace_back(run);
            work(worker, row);
        }
    };
    const size_t helpers = std::min<size_t>(static_cast<size_t>(threads), std::max<size_t>(b, 1)) - 1;
    for (size_t t = 0; t < helpers; ++t) pool.emplace_back(run);
    if (waiting != nullptr && helpers == 0)
        run_until_waited_for();
    else
        run();
    for (std::thread& t : pool) t.join();
}

using Int32Array = nb::ndarray<const int32_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using DoubleArray = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

template <typename T>
nb::ndarray<nb::numpy, T, nb::ndim<2>> owned(T* data, size_t rows, size_t cols) {
    nb::capsule owner(data, [](void* p) noexcept { delete[] static_cast<T*>(p); });
    return nb::ndarray<nb::numpy, T, nb::ndim<2>>(data, {rows, cols}, owner);
}

// The number of nodes n of a CSR graph, after checking its arrays (`what` names the caller in errors).
int64_t checked_nodes(const char* what, const Int32Array& indptr, const Int32Array& indices, const DoubleArray& weights) {
    const std::string name(what);
    const int64_t n = static_cast<int64_t>(indptr.shape(0)) - 1;
    if (n < 0 || indices.shape(0) != weights.shape(0))
        throw nb::value_error((name + ": indptr must be (n + 1,), indices and weights alike").c_str());
    const int32_t* ptr = indptr.data();
    if (ptr[0] != 0 || ptr[n] != static_cast<int64_t>(indices.shape(0)))
        throw nb::value_error((name + ": indptr does not match indices").c_str());
    for (int64_t i = 0; i < n; ++i)
        if (ptr[i + 1] < ptr[i]) throw nb::value_error((name + ": indptr decreases").c_str());
    for (size_t j = 0; j < indices.shape(0); ++j)
        if (indices.data()[j] < 0 || indices.data()[j] >= n) throw nb::value_error((name + ": an index is out of range").c_str());
    for (size_t j = 0; j < weights.shape(0); ++j)
        if (weights.data()[j] < 0) throw nb::value_error((name + ": a weight is negative").c_str());
    return n;
}

// The number of nodes n of a CSR graph, after checking it, (n,) `values`, the sources and the thread count of
// one of the flows (`what` names it in errors).
int64_t checked_flow(const char* what, const Int32Array& indptr, const Int32Array& indices, const DoubleArray& weights,
                     const Int32Array& sources, const DoubleArray& values, int threads) {
    const std::string name(what);
    const int64_t n = checked_nodes(what, indptr, indices, weights);
    if (static_cast<int64_t>(values.shape(0)) != n)
        throw nb::value_error((name + ": indptr must be (n + 1,), values (n,), indices and weights alike").c_str());
    for (size_t i = 0; i < sources.shape(0); ++i)
        if (sources.data()[i] < 0 || sources.data()[i] >= n) throw nb::value_error((name + ": a source is out of range").c_str());
    if (threads < 1 || threads > 2) throw nb::value_error((name + ": threads must be 1 or 2").c_str());
    return n;
}

nb::tuple shortest_path_flow(Int32Array indptr, Int32Array indices, DoubleArray weights, Int32Array sources,
                             DoubleArray values, int threads, const Waiting* waiting) {
    const int64_t n = checked_flow("shortest_path_flow", indptr, indices, weights, sources, values, threads);
    const int32_t* ptr = indptr.data();
    const size_t b = sources.shape(0);

    const size_t cells = std::max<size_t>(b * static_cast<size_t>(n), 1);
    auto* predecessors = new int32_t[cells];
    auto* through = new double[cells];
    auto pred_out = owned(predecessors, b, static_cast<size_t>(n));
    auto through_out = owned(through, b, static_cast<size_t>(n));
    const std::vector<uint8_t> passage = passages(ptr, indices.data(), weights.data(), static_cast<int32_t>(n));
    const bool corridors = std::find(passage.begin(), passage.end(), 1) != passage.end();
    const Graph g{ptr, indices.data(), weights.data(), passage.data(), corridors, static_cast<int32_t>(n)};
    for_each_source(b, threads, waiting, [&] { return TreeSweep(g.n); }, [&](TreeSweep& sweep, size_t row) {
        sweep.run(g, sources.data()[row], values.data(), predecessors + row * n, through + row * n);
    });
    return nb::make_tuple(pred_out, through_out);
}

nb::ndarray<nb::numpy, double, nb::ndim<2>> split_path_flow(Int32Array indptr, Int32Array indices, DoubleArray weights,
                                                            Int32Array sources, DoubleArray values, double tolerance,
                                                            int threads, const Waiting* waiting) {
    const int64_t n = checked_flow("split_path_flow", indptr, indices, weights, sources, values, threads);
    const size_t b = sources.shape(0);
    if (!(tolerance >= 0.0 && tolerance < 1.0)) throw nb::value_error("split_path_flow: tolerance must be in [0, 1)");
    auto* through = new double[std::max<size_t>(b * static_cast<size_t>(n), 1)];
    auto through_out = owned(through, b, static_cast<size_t>(n));
    const Graph g{indptr.data(), indices.data(), weights.data(), nullptr, false, static_cast<int32_t>(n)};
    for_each_source(b, threads, waiting, [&] { return SplitSweep(g.n); }, [&](SplitSweep& sweep, size_t row) {
        sweep.run(g, sources.data()[row], values.data(), tolerance, through + row * n);
    });
    return through_out;
}

// The linearly scaled flow (R. Geisberger, P. Sanders and D. Schultes, "Better approximation of betweenness
// centrality", ALENEX 2008, 90-100; g2s_plugins.traffic.linear_through): per source s and node v,
//
//   2 d(s, v) x (the plain flow of the values divided by their distance: values[t] / d(s, t))
//
// the plain flow of shortest_path_flow (ties "first") or split_path_flow ("split"). Each source is one search,
// whose distances scale its values before the sums run over its tree or path counts and weigh the sums after;
// the searches' distances are scipy's (the same float sums, each the least over a node's in-edges however the
// ties settle). Each value divided and each sum multiplied as numpy does it elementwise:
// values[t] / d(t) where 0 < d(t) < infinity, else 0; then (2 x (d(v), or 0 where that fails)) x sum(v).
void scale_by_distance(const std::vector<double>& distance, const double* values, double* scaled, int32_t n) {
    for (int32_t v = 0; v < n; ++v)
        scaled[v] = distance[v] > 0.0 && distance[v] < std::numeric_limits<double>::infinity() ? values[v] / distance[v] : 0.0;
}
// `sums` (n,) weighed into `through`, node v's into column original[v] (v's own with no renumbering, where `sums`
// may be `through`).
void weigh_by_distance(const std::vector<double>& distance, const double* sums, int32_t n, const int32_t* original,
                       double* through) {
    for (int32_t v = 0; v < n; ++v) {
        const double d = distance[v] > 0.0 && distance[v] < std::numeric_limits<double>::infinity() ? distance[v] : 0.0;
        through[original != nullptr ? original[v] : v] = (2.0 * d) * sums[v];
    }
}

// A graph the caller renumbered for the split flow's kernel (g2s_plugins.traffic.flow_layout): node v of its CSR
// arrays is node original[v] of the caller's numbering, in which the sources, the values and the result's columns
// stay. Why: a search settles nodes ring by ring round its source, and where the numbering keeps the nodes of a
// neighbourhood apart (a sampled graph's x-major rows) the kernel waits on memory; renumbered along a space-filling
// curve they lie close together: 10 % less CPU a source on the sampling route's 100k level (docs/performance.md,
// locality48), the renumbering's own O(n) a call spread over a block of sources. Same bits: the search breaks ties
// by the caller's index (Graph::key), each renumbered row keeps its entries' order, so every node settles, every
// shortest-path edge is found and every sum is added in the same order as in the caller's numbering. O(n) a call.
class Renumbering {
  public:
    Renumbering(const char* what, const std::optional<Int32Array>& original, int64_t n, const double* values) {
        if (!original) {
            values_ = values;
            return;
        }
        const std::string name(what);
        if (static_cast<int64_t>(original->shape(0)) != n) throw nb::value_error((name + ": original must be (n,)").c_str());
        original_ = original->data();
        node_.assign(static_cast<size_t>(n), -1);
        renumbered_values_.resize(static_cast<size_t>(n));
        for (int32_t v = 0; v < n; ++v) {
            const int32_t caller = original_[v];
            if (caller < 0 || caller >= n || node_[caller] >= 0)
                throw nb::value_error((name + ": original must hold every node once").c_str());
            node_[caller] = v;
            renumbered_values_[v] = values[caller];
        }
        values_ = renumbered_values_.data();
    }

    bool renumbered() const { return original_ != nullptr; }
    // (n,) each node's index in the caller's numbering, or nullptr: not renumbered
    const int32_t* original() const { return original_; }
    // The kernel's number of the caller's node `caller`.
    int32_t node(int32_t caller) const { return original_ != nullptr ? node_[caller] : caller; }
    // (n,) the values in the kernel's numbering.
    const double* values() const { return values_; }

  private:
    const int32_t* original_ = nullptr;
    const double* values_ = nullptr;
    std::vector<int32_t> node_;
    std::vector<double> renumbered_values_;
};

nb::ndarray<nb::numpy, double, nb::ndim<2>> linear_path_flow(Int32Array indptr, Int32Array indices, DoubleArray weights,
                                                             Int32Array sources, DoubleArray values, const std::string& ties,
                                                             double tolerance, int threads, const Waiting* waiting,
                                                             const std::optional<Int32Array>& original) {
    const int64_t n = checked_flow("linear_path_flow", indptr, indices, weights, sources, values, threads);
    if (ties != "first" && ties != "split") throw nb::value_error("linear_path_flow: ties must be 'first' or 'split'");
    if (!(tolerance >= 0.0 && tolerance < 1.0)) throw nb::value_error("linear_path_flow: tolerance must be in [0, 1)");
    if (original && ties != "split") throw nb::value_error("linear_path_flow: original is taken with ties 'split' only");
    const Renumbering renumbering("linear_path_flow", original, n, values.data());
    const size_t b = sources.shape(0);
    auto* through = new double[std::max<size_t>(b * static_cast<size_t>(n), 1)];
    auto through_out = owned(through, b, static_cast<size_t>(n));
    const size_t nodes = static_cast<size_t>(n);
    if (ties == "split") {
        const Graph g{indptr.data(), indices.data(), weights.data(), nullptr, false, static_cast<int32_t>(n),
                      renumbering.original()};
        struct SplitWorker {
            SplitSweep sweep;
            std::vector<double> scaled, sums;  // sums: the kernel's numbering's, when renumbered
        };
        const size_t sums = renumbering.renumbered() ? nodes : 0;
        for_each_source(b, threads, waiting, [&] { return SplitWorker{SplitSweep(g.n), std::vector<double>(nodes), std::vector<double>(sums)}; },
                        [&](SplitWorker& worker, size_t row) {
            const int32_t source = renumbering.node(sources.data()[row]);
            double* out = through + row * nodes;
            double* summed = renumbering.renumbered() ? worker.sums.data() : out;
            worker.sweep.search(g, source);
            scale_by_distance(worker.sweep.distance(), renumbering.values(), worker.scaled.data(), g.n);
            worker.sweep.sum(g, source, worker.scaled.data(), tolerance, summed);
            weigh_by_distance(worker.sweep.distance(), summed, g.n, g.original, out);
        });
        return through_out;
    }
    const std::vector<uint8_t> passage = passages(indptr.data(), indices.data(), weights.data(), static_cast<int32_t>(n));
    const bool corridors = std::find(passage.begin(), passage.end(), 1) != passage.end();
    const Graph g{indptr.data(), indices.data(), weights.data(), passage.data(), corridors, static_cast<int32_t>(n)};
    struct TreeWorker {
        TreeSweep sweep;
        std::vector<double> scaled;
        std::vector<int32_t> predecessor;
    };
    for_each_source(b, threads, waiting, [&] { return TreeWorker{TreeSweep(g.n), std::vector<double>(nodes), std::vector<int32_t>(nodes)}; },
                    [&](TreeWorker& worker, size_t row) {
        const int32_t source = sources.data()[row];
        double* out = through + row * nodes;
        worker.sweep.search(g, source, worker.predecessor.data());
        scale_by_distance(worker.sweep.distance(), values.data(), worker.scaled.data(), g.n);
        worker.sweep.sum(g, source, worker.scaled.data(), worker.predecessor.data(), out);
        weigh_by_distance(worker.sweep.distance(), out, g.n, nullptr, out);
    });
    return through_out;
}

// Python's heapq on a list of (float, int) items, step for step (heappush, heappop and their sifts): the
// cover's searches start from a list that is not a heap, so the order its items come out in, and with it
// which of two equally short ways a node keeps, is heapq's own.
class PyHeap {
  public:
    using Item = std::pair<double, int64_t>;
    std::vector<Item> items;

    void push(const Item& item) {
        items.push_back(item);
        sift_down(0, items.size() - 1);
    }
    Item pop() {
        const Item last = items.back();
        items.pop_back();
        if (items.empty()) return last;
        const Item top = items[0];
        items[0] = last;
        sift_up(0);
        return top;
    }

  private:
    void sift_down(size_t start, size_t pos) {
        const Item item = items[pos];
        while (pos > start) {
            const size_t parent = (pos - 1) >> 1;
            if (!(item < items[parent])) break;
            items[pos] = items[parent];
            pos = parent;
        }
        items[pos] = item;
    }
    void sift_up(size_t pos) {
        const size_t end = items.size(), start = pos;
        const Item item = items[pos];
        for (size_t child = 2 * pos + 1; child < end; child = 2 * pos + 1) {
            if (child + 1 < end && !(items[child] < items[child + 1])) ++child;
            items[pos] = items[child];
            pos = child;
        }
        items[pos] = item;
        sift_down(start, pos);
    }
};

using Int64Array = nb::ndarray<const int64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

nb::ndarray<nb::numpy, int64_t, nb::ndim<1>> cover_paths(Int32Array indptr, Int32Array indices, DoubleArray lengths,
                                                          DoubleArray start, Int32Array predecessor, Int64Array far,
                                                          double radius) {
    const int64_t n = checked_nodes("cover_paths", indptr, indices, lengths);
    if (static_cast<int64_t>(start.shape(0)) != n || static_cast<int64_t>(predecessor.shape(0)) != n)
        throw nb::value_error("cover_paths: start and predecessor must be (n,)");
    for (size_t i = 0; i < far.shape(0); ++i)
        if (far.data()[i] < 0 || far.data()[i] >= n) throw nb::value_error("cover_paths: a far node is out of range");
    for (int64_t v = 0; v < n; ++v)
        if (predecessor.data()[v] >= n) throw nb::value_error("cover_paths: a predecessor is out of range");
    const int32_t* ptr = indptr.data();
    std::vector<double> distance(start.data(), start.data() + n);
    std::vector<int32_t> parent(predecessor.data(), predecessor.data() + n);
    std::vector<int64_t> added;
    {
        nb::gil_scoped_release release;
        size_t queued = far.shape(0);  // far nodes not yet taken, from the end
        auto far_item = [&](size_t i) { return PyHeap::Item{-start.data()[far.data()[i]], far.data()[i]}; };
        PyHeap again, pending;
        while (queued > 0 || !again.items.empty()) {
            const PyHeap::Item item = !again.items.empty() && (queued == 0 || again.items[0] < far_item(queued - 1))
                                          ? again.pop() : far_item(--queued);
            const int64_t node = item.second;
            if (distance[node] <= radius) continue;
            if (-item.first > distance[node]) {  // stale: the node came closer since
                again.push({-distance[node], node});
                continue;
            }
            const size_t first = added.size();
            for (int64_t v = node; parent[v] >= 0; v = parent[v]) added.push_back(v);  // the last is in the set
            pending.items.clear();
            for (size_t i = first; i < added.size(); ++i) {
                distance[added[i]] = 0.0;
                parent[added[i]] = -1;
                pending.items.push_back({0.0, added[i]});
            }
            while (!pending.items.empty()) {
                const auto [reached, here] = pending.pop();
                if (reached > distance[here]) continue;
                for (int32_t k = ptr[here]; k < ptr[here + 1]; ++k) {
                    const int32_t other = indices.data()[k];
                    const double through = reached + lengths.data()[k];
                    if (through < distance[other]) {
                        distance[other] = through;
                        parent[other] = static_cast<int32_t>(here);
                        pending.push({through, other});
                    }
                }
            }
        }
    }
    auto* out = new int64_t[std::max<size_t>(added.size(), 1)];
    std::copy(added.begin(), added.end(), out);
    nb::capsule owner(out, [](void* p) noexcept { delete[] static_cast<int64_t*>(p); });
    return nb::ndarray<nb::numpy, int64_t, nb::ndim<1>>(out, {added.size()}, owner);
}

// The greedy spanner of g2s_plugins.loops.spanner.add_loops (Althoefer et al. 1993; see there), its loop
// over the candidates in C++. Each candidate k joins structure nodes a[k], b[k] by the path a ~> x[k] - y[k]
// ~> b along the Voronoi search's predecessors; it is added unless b is already within bounds[k] of a along
// the structure's edges (`s_*`, edges of the graph) and the paths added before it (their lengths from the
// graph, `g_*`). The first candidate is added unchecked. The bounded search is a Dijkstra that never queues
// a node further than the bound; whether it reaches b does not depend on the order it settles equal
// distances or takes a node's neighbours in, since with lengths >= 0 every node's distance is the least of
// the sums along its paths, each added in path order. O(v b log b) for v candidates and b nodes within a bound.
nb::tuple greedy_loops(Int32Array s_indptr, Int32Array s_indices, DoubleArray s_lengths, Int32Array g_indptr,
                       Int32Array g_indices, DoubleArray g_lengths, Int32Array predecessor, Int64Array a, Int64Array b,
                       Int64Array x, Int64Array y, DoubleArray bounds) {
    const int64_t n = checked_nodes("greedy_loops", s_indptr, s_indices, s_lengths);
    if (checked_nodes("greedy_loops", g_indptr, g_indices, g_lengths) != n || static_cast<int64_t>(predecessor.shape(0)) != n)
        throw nb::value_error("greedy_loops: the structure, the graph and predecessor must have the same n nodes");
    const size_t k = bounds.shape(0);
    for (const Int64Array* ends : {&a, &b, &x, &y}) {
        if (ends->shape(0) != k) throw nb::value_error("greedy_loops: a, b, x, y and bounds must be (k,)");
        for (size_t i = 0; i < k; ++i)
            if (ends->data()[i] < 0 || ends->data()[i] >= n) throw nb::value_error("greedy_loops: a node is out of range");
    }
    for (int64_t v = 0; v < n; ++v)
        if (predecessor.data()[v] >= n) throw nb::value_error("greedy_loops: a predecessor is out of range");
    const int32_t *sp = s_indptr.data(), *gp = g_indptr.data(), *pred = predecessor.data();
    std::vector<int64_t> accepted, paths, offsets{0};
    {
        nb::gil_scoped_release release;
        std::vector<std::vector<std::pair<int64_t, double>>> joined(static_cast<size_t>(n));
        std::vector<double> best(static_cast<size_t>(n));
        std::vector<uint32_t> seen(static_cast<size_t>(n), 0);  // best[v] holds for this search when seen[v] == search
        uint32_t search = 0;
        PyHeap heap;
        auto within = [&](int64_t source, int64_t target, double limit) {
            ++search;
            best[source] = 0.0;
            seen[source] = search;
            heap.items.clear();
            heap.push({0.0, source});
            auto relax = [&](double distance, int64_t other, double length) {
                const double through = distance + length;
                if (through <= limit && (seen[other] != search || through < best[other])) {
                    best[other] = through;
                    seen[other] = search;
                    heap.push({through, other});
                }
            };
            while (!heap.items.empty()) {
                const auto [distance, node] = heap.pop();
                if (node == target) return true;
                if (distance > best[node]) continue;
                for (int32_t e = sp[node]; e < sp[node + 1]; ++e) relax(distance, s_indices.data()[e], s_lengths.data()[e]);
                for (const auto& [other, length] : joined[node]) relax(distance, other, length);
            }
            return false;
        };
        auto length_of = [&](int64_t p, int64_t q) {  // the graph's edge p - q (a path edge: it is there)
            for (int32_t e = gp[p]; e < gp[p + 1]; ++e)
                if (g_indices.data()[e] == q) return g_lengths.data()[e];
            return std::numeric_limits<double>::quiet_NaN();
        };
        for (size_t i = 0; i < k; ++i) {
            if (!accepted.empty() && within(a.data()[i], b.data()[i], bounds.data()[i])) continue;
            accepted.push_back(static_cast<int64_t>(i));
            const size_t first = paths.size();
            for (int64_t v = x.data()[i]; ; v = pred[v]) {  // x back to a, then reversed: a ~> x
                paths.push_back(v);
                if (pred[v] < 0) break;
            }
            std::reverse(paths.begin() + static_cast<std::ptrdiff_t>(first), paths.end());
            for (int64_t v = y.data()[i]; ; v = pred[v]) {  // y ~> b
                paths.push_back(v);
                if (pred[v] < 0) break;
            }
            for (size_t j = first + 1; j < paths.size(); ++j) {
                const int64_t p = paths[j - 1], q = paths[j];
                const double length = length_of(p, q);
                joined[p].push_back({q, length});
                joined[q].push_back({p, length});
            }
            offsets.push_back(static_cast<int64_t>(paths.size()));
        }
    }
    auto out = [](const std::vector<int64_t>& values) {
        auto* data = new int64_t[std::max<size_t>(values.size(), 1)];
        std::copy(values.begin(), values.end(), data);
        nb::capsule owner(data, [](void* p) noexcept { delete[] static_cast<int64_t*>(p); });
        return nb::ndarray<nb::numpy, int64_t, nb::ndim<1>>(data, {values.size()}, owner);
    };
    return nb::make_tuple(out(accepted), out(paths), out(offsets));
}

// Kruskal's minimum spanning forest (J. B. Kruskal, "On the shortest spanning subtree of a graph and the
// traveling salesman problem", Proc. AMS 7(1):48-50, 1956) under the total order (weight, lower end, higher end,
// position): the unique forest g2s_plugins.steiner._paths.spanning_tree documents. Of parallel edges the first
// in that order is the one it can take (the others join ends already joined); self-loops never join anything.
// One sort of the m edges and a union-find with path halving: O(m log m).
nb::ndarray<nb::numpy, int64_t, nb::ndim<1>> spanning_forest(int64_t size, Int64Array a, Int64Array b, DoubleArray w) {
    const size_t m = w.shape(0);
    if (a.shape(0) != m || b.shape(0) != m) throw nb::value_error("spanning_forest: a, b and w must be (m,)");
    if (size < 0) throw nb::value_error("spanning_forest: size must be >= 0");
    struct Edge {
        double weight;
        int64_t lo, hi, position;
    };
    std::vector<Edge> edges;
    edges.reserve(m);
    for (size_t i = 0; i < m; ++i) {
        const int64_t u = a.data()[i], v = b.data()[i];
        if (u < 0 || u >= size || v < 0 || v >= size) throw nb::value_error("spanning_forest: an end is out of range");
        if (std::isnan(w.data()[i])) throw nb::value_error("spanning_forest: a weight is NaN");
        if (u != v) edges.push_back({w.data()[i], std::min(u, v), std::max(u, v), static_cast<int64_t>(i)});
    }
    std::vector<int64_t> chosen;
    {
        nb::gil_scoped_release release;
        std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
            if (x.weight != y.weight) return x.weight < y.weight;
            if (x.lo != y.lo) return x.lo < y.lo;
            if (x.hi != y.hi) return x.hi < y.hi;
            return x.position < y.position;
        });
        std::vector<int64_t> up(static_cast<size_t>(size));
        for (int64_t i = 0; i < size; ++i) up[i] = i;
        auto find = [&](int64_t x) {
            while (up[x] != x) x = up[x] = up[up[x]];
            return x;
        };
        for (const Edge& e : edges) {
            const int64_t ru = find(e.lo), rv = find(e.hi);
            if (ru == rv) continue;
            up[std::max(ru, rv)] = std::min(ru, rv);
            chosen.push_back(e.position);
        }
        std::sort(chosen.begin(), chosen.end());
    }
    auto* out = new int64_t[std::max<size_t>(chosen.size(), 1)];
    std::copy(chosen.begin(), chosen.end(), out);
    nb::capsule owner(out, [](void* p) noexcept { delete[] static_cast<int64_t*>(p); });
    return nb::ndarray<nb::numpy, int64_t, nb::ndim<1>>(out, {chosen.size()}, owner);
}

}  // namespace

NB_MODULE(_trees, m) {
    m.doc() = "Shortest-path trees from many sources and the weight passing through each node, the coverage cover, the loop "
              "adder's greedy loop and Kruskal's spanning forest (see src/trees_module.cpp).";
    nb::class_<Waiting>(m, "Waiting",
                        "Waiting(): a flag the flows below read between sources; set() once a caller waits for a call\n"
                        "running on one thread, which then takes a second worker from its next source on.")
        .def(nb::init<>())
        .def("set", [](Waiting& w) { w.set.store(true, std::memory_order_release); })
        .def("is_set", [](const Waiting& w) { return w.set.load(std::memory_order_acquire); });
    m.def("shortest_path_flow", &shortest_path_flow, nb::arg("indptr"), nb::arg("indices"), nb::arg("weights"),
          nb::arg("sources"), nb::arg("values"), nb::arg("threads"), nb::arg("waiting").none() = nb::none(),
          "shortest_path_flow(indptr, indices, weights, sources, values, threads, waiting=None) -> (predecessors, through).\n\n"
          "For a graph in CSR form (int32 indptr (n + 1,), int32 indices and float64 weights (m,); edge i -> j)\n"
          "and b source nodes: predecessors (b, n) int32, scipy.sparse.csgraph.dijkstra's (directed=True)\n"
          "exactly, -9999 for the source and unreached nodes; through (b, n) float64, the values summed over\n"
          "each node's subtree of that source's tree minus the node's own value (0 for the source).\n"
          "threads: 1 or 2 worker threads, each running whole sources (the result does not depend on it); waiting:\n"
          "None or a Waiting flag, with which one thread becomes two from the next source on once it is set.");
    m.def("split_path_flow", &split_path_flow, nb::arg("indptr"), nb::arg("indices"), nb::arg("weights"),
          nb::arg("sources"), nb::arg("values"), nb::arg("tolerance"), nb::arg("threads"),
          nb::arg("waiting").none() = nb::none(),
          "split_path_flow(indptr, indices, weights, sources, values, tolerance, threads, waiting=None) -> through.\n\n"
          "For a graph in CSR form (as shortest_path_flow) and b source nodes: through (b, n) float64, per source\n"
          "and node v, the sum over targets t != v of values[t] times the share of the source's shortest paths to\n"
          "t that pass through v (Brandes's dependency; path lengths within the relative tolerance tie); 0 for the\n"
          "source and unreached nodes. threads and waiting: as shortest_path_flow's.");
    m.def("linear_path_flow", &linear_path_flow, nb::arg("indptr"), nb::arg("indices"), nb::arg("weights"),
          nb::arg("sources"), nb::arg("values"), nb::arg("ties"), nb::arg("tolerance"), nb::arg("threads"),
          nb::arg("waiting").none() = nb::none(), nb::arg("original").none() = nb::none(),
          "linear_path_flow(indptr, indices, weights, sources, values, ties, tolerance, threads, waiting=None,\n"
          "original=None) -> through.\n\n"
          "For a graph in CSR form (as shortest_path_flow) and b source nodes: through (b, n) float64, per source s\n"
          "and node v, 2 d(s, v) times the flow through v of shortest_path_flow (ties 'first') or split_path_flow\n"
          "('split', with the relative tolerance) of the values each divided by its distance d(s, t) (0 where t is\n"
          "the source, at distance 0 or unreached); 0 for the source and unreached nodes. threads and waiting: as\n"
          "shortest_path_flow's. original: None, or (n,) int32 for a graph renumbered (ties 'split' only): node v of\n"
          "the CSR arrays is node original[v] of the sources, values and through, whose bits do not depend on it.");
    m.def("cover_paths", &cover_paths, nb::arg("indptr"), nb::arg("indices"), nb::arg("lengths"), nb::arg("start"),
          nb::arg("predecessor"), nb::arg("far"), nb::arg("radius"),
          "cover_paths(indptr, indices, lengths, start, predecessor, far, radius) -> added.\n\n"
          "The loop of g2s_plugins.terminals.coverage.cover_paths (see there) on a CSR graph (int32 indptr,\n"
          "int32 indices, float64 lengths), from the distances `start` (n,) float64 to the seeds and their\n"
          "predecessors (n,) int32 (negative: none), the far nodes `far` (int64) in the order they are taken\n"
          "from the end: added (k,) int64, the nodes of the paths added, path by path.");
    m.def("greedy_loops", &greedy_loops, nb::arg("s_indptr"), nb::arg("s_indices"), nb::arg("s_lengths"),
          nb::arg("g_indptr"), nb::arg("g_indices"), nb::arg("g_lengths"), nb::arg("predecessor"), nb::arg("a"),
          nb::arg("b"), nb::arg("x"), nb::arg("y"), nb::arg("bounds"),
          "greedy_loops(s_indptr, s_indices, s_lengths, g_indptr, g_indices, g_lengths, predecessor, a, b, x, y,\n"
          "bounds) -> (accepted, paths, offsets).\n\n"
          "The loop of g2s_plugins.loops.spanner.add_loops (see there) over k candidates (int64 (k,) each:\n"
          "structure nodes a, b, graph edge x - y; float64 bounds), on the structure and the graph in CSR form\n"
          "over the same n nodes (int32 indptr and indices, float64 lengths >= 0) and the Voronoi search's\n"
          "predecessors (n,) int32 (negative: a structure node): accepted (j,) int64, the candidates added in\n"
          "order; the nodes of their paths (a ~> x, y ~> b) in `paths`, path i at offsets[i]:offsets[i + 1].");
    m.def("spanning_forest", &spanning_forest, nb::arg("size"), nb::arg("a"), nb::arg("b"), nb::arg("w"),
          "spanning_forest(size, a, b, w) -> chosen.\n\n"
          "The minimum spanning forest of the edges (a[i], b[i]) (int64, vertices 0 .. size-1) weighing w[i]\n"
          "(float64, no NaN) under the total order (w, min(a, b), max(a, b), i), Kruskal's: chosen (k,) int64,\n"
          "the indices of its edges, ascending (self-loops never chosen).");
}
