// The paper's Algorithm 4 and the loop pass of g2s_core/simplify.py on arrays, for a predicate in native code.
//
// g2s_core/simplify.py is the reference: this walks the same nodes in the same order and asks the predicate
// the same chains (A, B, C), so with the same answers it removes the same nodes and adds the same edges, in the
// same order (tests/test_simplify_arrays.py compares the two). Nodes are indices 0..n-1 of the arrays; ids only
// order them (children by ascending id, the loop pass's candidates by ascending id).
//
// Complexity: O(n + k) predicate calls, k = removals, as the reference; each removal also sorts the removed
// node's children, O(d log d) for d children, and looks a node up in its parent's children, O(d).
//
// Threads: Algorithm 4 walks the chains below one kept node A at a time, and what it finds there (the nodes it
// removes, the edges (A, C) it adds, the children it keeps, each of which is the next such A) reads and writes
// only the nodes below A, which no other walk touches until A's walk is over: it keeps A's children for later
// walks, and the predicate's answers depend on the chain alone. So the walks below different kept nodes run
// on `threads` threads, each with its own copy of the predicate (its caches), a kept node's walk starting once
// the walk that kept it has stopped (done, or waiting as below: it never goes below a child it kept); the edges
// are then read back in the reference's order. The loop pass, a heap whose every step may change the next, runs
// on one thread after them.
//
// Batches: for the same reason a walk may wait for an answer (the predicate answers `later`, a line of sight it
// asks in batches) while the others go on: once every walk is done or waits, allows.resolve() answers what they
// asked, and the waiting walks go on from the chain they asked about. The loop pass asks its candidates' first
// chains in one batch, then resolves each `later` at once.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <queue>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace forest_simplify {

// A rooted forest (g2s_core.rooted) as the core hands it over: n nodes, m loop edges.
struct Forest {
    size_t n = 0;
    const int64_t* ids = nullptr;     // (n,) node ids
    const int64_t* parent = nullptr;  // (n,) index of the tree parent, -1 for a root
    const int64_t* depth = nullptr;   // (n,) depth in the forest (orients the loop edges the loop pass adds)
    const bool* fixed = nullptr;      // (n,) never removed (terminals; the nodes a later round must keep)
    size_t m = 0;
    const int64_t* loops = nullptr;   // (m,2) loop edges u -> v
    size_t r = 0;
    const int64_t* roots = nullptr;   // (r,) root indices
};

// Which nodes stay and the edges added, in the order they were added (loop: an edge the loop pass added).
struct Simplified {
    std::vector<uint8_t> kept;
    std::vector<int64_t> added;  // (k,2) flattened
    std::vector<uint8_t> loop;   // (k,)
};

// A node's partner along loop edges: bit OUT set for the edge node -> partner, IN for partner -> node.
struct Partner {
    int64_t node;
    uint8_t ways;
};
constexpr uint8_t OUT = 1, IN = 2;

// What Algorithm 4 does below one kept node A: the edges (A, C) it adds, flattened, in order, and the children of
// A it keeps, in order (each walked next, the first first).
struct Walk {
    std::vector<int64_t> added;
    std::vector<int64_t> kept;
};

// The predicate's answer: `later` when it answers in batches and has not yet (see "Batches" above).
enum class Answer : uint8_t { no, yes, later };

// Where Algorithm 4 stands below the kept node a: the children of a still to examine, and the child b being
// examined (`examining`: its own tests passed), with its children, sorted, of which the first `asked` let it go;
// `handed`: how many of the children it kept so far have been handed on to walks of their own.
struct Cursor {
    int64_t a = -1;
    bool started = false;
    size_t handed = 0;
    std::deque<int64_t> queue;
    bool examining = false;
    int64_t b = -1;
    std::vector<int64_t> grandchildren;
    size_t asked = 0;
};

// allows(a, b, c, c_is_leaf) -> Answer: whether b may go, c then joined to a; c_is_leaf: c has no outgoing edge
// (tree or loop) in the current structure, the leaf test of Algorithm 5's first rule. allows.resolve(): answer
// what was answered `later` (a predicate that never says `later` does nothing). Allows::batches: whether it may
// say `later` (the loop pass then asks every candidate's first chain before it starts). Copied once per thread
// (`threads` of them, at least one) and once for the loop pass; its answers must not depend on the copy or the
// order of the calls.
template <typename Allows>
Simplified simplify(const Forest& f, const Allows& allows, unsigned threads = 1) {
    const size_t n = f.n;
    std::vector<std::vector<int64_t>> children(n);
    std::vector<std::vector<Partner>> loops(n);
    std::vector<int64_t> parent(f.parent, f.parent + n), out(n, 0);
    for (size_t i = 0; i < n; ++i)
        if (parent[i] >= 0) { children[parent[i]].push_back(static_cast<int64_t>(i)); ++out[parent[i]]; }
    auto find = [&](int64_t node, int64_t partner) {
        return std::find_if(loops[node].begin(), loops[node].end(), [&](const Partner& p) { return p.node == partner; });
    };
    auto join = [&](int64_t u, int64_t v) {  // the loop edge u -> v (a DiGraph holds it once)
        auto it = find(u, v);
        if (it == loops[u].end()) loops[u].push_back({v, OUT}); else if (!(it->ways & OUT)) { it->ways |= OUT; } else return;
        it = find(v, u);
        if (it == loops[v].end()) loops[v].push_back({u, IN}); else it->ways |= IN;
        ++out[u];
    };
    for (size_t e = 0; e < f.m; ++e) join(f.loops[2 * e], f.loops[2 * e + 1]);
    auto by_id = [&](int64_t x, int64_t y) { return f.ids[x] < f.ids[y]; };

    Simplified s;
    s.kept.assign(n, 1);
    std::vector<Walk> walks(n);
    // Algorithm 4 below the kept node at.a (the rows of a, its children and the nodes below them only), from where
    // `at` stands: true when done, false when the rule answered `later` (then `at` stands at that chain)
    auto walk = [&](Cursor& at, Allows& rule) {
        const int64_t a = at.a;
        Walk& done = walks[a];
        if (!at.started) {
            at.queue.assign(children[a].begin(), children[a].end());
            std::sort(at.queue.begin(), at.queue.end(), by_id);
            at.started = true;
        }
        for (;;) {
            if (!at.examining) {
                if (at.queue.empty()) return true;
                at.b = at.queue.front();
                at.queue.pop_front();
                at.grandchildren = children[at.b];
                std::sort(at.grandchildren.begin(), at.grandchildren.end(), by_id);
                // the reference's rule: a leaf, a terminal, the end of a loop edge, or the parent of a node with a
                // loop edge to a stays
                bool removable = !at.grandchildren.empty() && !f.fixed[at.b] && loops[at.b].empty();
                for (const int64_t c : at.grandchildren) removable = removable && find(a, c) == loops[a].end();
                if (!removable) { done.kept.push_back(at.b); continue; }
                at.examining = true;
                at.asked = 0;
            }
            const int64_t b = at.b;
            const std::vector<int64_t>& grandchildren = at.grandchildren;
            for (; at.asked < grandchildren.size(); ++at.asked) {
                const int64_t c = grandchildren[at.asked];
                const Answer answer = rule(a, b, c, out[c] == 0);
                if (answer == Answer::later) return false;
                if (answer == Answer::no) break;
            }
            at.examining = false;
            if (at.asked < grandchildren.size()) { done.kept.push_back(b); continue; }
            s.kept[b] = 0;
            auto& below = children[a];
            below.erase(std::find(below.begin(), below.end(), b));
            for (const int64_t c : grandchildren) {
                below.push_back(c);
                parent[c] = a;
                done.added.insert(done.added.end(), {a, c});
                at.queue.push_back(c);
            }
            out[a] += static_cast<int64_t>(grandchildren.size()) - 1;
            children[b].clear();
        }
    };
    // the walks, each kept node's once the walk that kept it has stopped, on `threads` threads, until each is done
    // or waits; then the answers the waiting ones asked for, and they go on
    std::mutex lock;
    std::condition_variable ready;
    std::vector<Cursor> todo(f.r), waiting;
    for (size_t k = 0; k < f.r; ++k) todo[k].a = f.roots[k];
    size_t open = f.r;  // walks to do, in progress or waiting
    bool failed = false;
    std::exception_ptr failure;
    auto worker = [&] {
        Allows rule = allows;
        std::unique_lock<std::mutex> hold(lock);
        for (;;) {
            ready.wait(hold, [&] { return failed || open == waiting.size() || !todo.empty(); });
            if (failed || open == waiting.size()) return;
            Cursor at = std::move(todo.back());
            todo.pop_back();
            hold.unlock();
            bool finished = false;
            try {
                finished = walk(at, rule);
            } catch (...) {
                hold.lock();
                if (!failed) failure = std::current_exception();
                failed = true;
                ready.notify_all();
                return;
            }
            hold.lock();
            // a kept child's walk may start at once: nothing below it is the walk's that kept it any more
            const std::vector<int64_t>& kept = walks[at.a].kept;
            for (size_t k = kept.size(); k-- > at.handed;) todo.emplace_back().a = kept[k];
            open += kept.size() - at.handed;
            at.handed = kept.size();
            if (finished) --open; else waiting.push_back(std::move(at));
            ready.notify_all();
        }
    };
    for (;;) {
        std::vector<std::thread> pool;
        for (unsigned t = 1; t < threads; ++t) {
            try {
                pool.emplace_back(worker);
            } catch (const std::system_error&) {  // no thread to be had: the walks on fewer, the same answer
                break;
            }
        }
        worker();
        for (std::thread& t : pool) t.join();
        if (failure) std::rethrow_exception(failure);
        if (waiting.empty()) break;
        allows.resolve();
        todo.swap(waiting);
        std::reverse(todo.begin(), todo.end());  // the first to wait goes on first
    }
    // the edges in the reference's order: roots in turn, each kept node's walk, then its kept children's, first first
    std::vector<int64_t> pending;
    for (size_t k = 0; k < f.r; ++k) {
        pending.assign(1, f.roots[k]);
        while (!pending.empty()) {
            const Walk& done = walks[pending.back()];
            pending.pop_back();
            s.added.insert(s.added.end(), done.added.begin(), done.added.end());
            pending.insert(pending.end(), done.kept.rbegin(), done.kept.rend());
        }
    }
    s.loop.assign(s.added.size() / 2, 0);
    std::vector<Walk>().swap(walks);

    // the loop pass: a non-terminal tree leaf b whose only other edge is a loop edge b - q goes when
    // allows(parent, b, q), and the loop edge parent - q replaces both
    Allows rule = allows;
    auto allowed = [&](int64_t a, int64_t b, int64_t c) {
        Answer answer;
        while ((answer = rule(a, b, c, out[c] == 0)) == Answer::later) rule.resolve();
        return answer == Answer::yes;
    };
    auto candidate = [&](int64_t b) { return s.kept[b] && !f.fixed[b] && children[b].empty() && loops[b].size() == 1; };
    auto later = [&](int64_t x, int64_t y) { return f.ids[x] > f.ids[y]; };
    std::priority_queue<int64_t, std::vector<int64_t>, decltype(later)> heap(later);
    for (size_t i = 0; i < n; ++i) if (candidate(static_cast<int64_t>(i))) heap.push(static_cast<int64_t>(i));
    if constexpr (Allows::batches) {  // the candidates' first chains asked in one batch, not one by one
        for (size_t i = 0; i < n; ++i) {
            const int64_t b = static_cast<int64_t>(i), a = parent[b];
            if (candidate(b) && a >= 0) rule(a, b, loops[b].front().node, out[loops[b].front().node] == 0);
        }
        rule.resolve();
    }
    while (!heap.empty()) {
        const int64_t b = heap.top();
        heap.pop();
        if (!candidate(b)) continue;
        const int64_t a = parent[b], q = loops[b].front().node;
        if (a < 0 || parent[q] == a || parent[a] == q || find(a, q) != loops[a].end() || !allowed(a, b, q))
            continue;
        s.kept[b] = 0;
        auto& below = children[a];
        below.erase(std::find(below.begin(), below.end(), b));
        --out[a];
        const auto partner = find(q, b);
        if (partner->ways & OUT) --out[q];
        loops[q].erase(partner);
        loops[b].clear();
        const bool a_first = std::make_pair(f.depth[a], f.ids[a]) < std::make_pair(f.depth[q], f.ids[q]);
        const int64_t first = a_first ? a : q, second = a_first ? q : a;
        join(first, second);
        s.added.insert(s.added.end(), {first, second});
        s.loop.push_back(1);
        heap.push(a);
        heap.push(q);
    }
    return s;
}

}  // namespace forest_simplify
