// Test support for dcel::check: answers derived from the reference by known
// transformations (so what the comparison must say is known without asking
// it), shared by tests/test_check_*.cpp and properties/prop_check.cpp.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "dcel/check/compare.hpp"
#include "dcel/dcel.hpp"
#include "dcel/dump.hpp"
#include "dcel/graph.hpp"
#include "oracles/shapes.hpp"

namespace dcel::test_support {

using check::FacesAnswer;

// The boundary cycles read straight off the arrays: every next-orbit, as
// origins, in order of the smallest half-edge (what `dcel faces` prints).
inline FacesAnswer faces_answer(const Dcel& d) {
    FacesAnswer out;
    std::vector<char> seen(d.num_half_edges(), 0);
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        if (seen[h] != 0) continue;
        std::vector<Index>& c = out.emplace_back();
        Index x = h;
        do {
            seen[x] = 1;
            c.push_back(d.origin(HalfEdgeId(x)).index());
            x = d.next(HalfEdgeId(x)).index();
        } while (x != h);
    }
    return out;
}

// The cycles of an arbitrary next permutation given as an array (origins of
// the reference), for answers built from a rewired next.
inline FacesAnswer cycles_of_permutation(const Dcel& d, const std::vector<Index>& next) {
    FacesAnswer out;
    std::vector<char> seen(next.size(), 0);
    for (Index h = 0; h < next.size(); ++h) {
        if (seen[h] != 0) continue;
        std::vector<Index>& c = out.emplace_back();
        for (Index x = h; seen[x] == 0; x = next[x]) {
            seen[x] = 1;
            c.push_back(d.origin(HalfEdgeId(x)).index());
        }
    }
    return out;
}

inline std::vector<Index> next_array(const Dcel& d) {
    std::vector<Index> next(d.num_half_edges());
    for (Index h = 0; h < next.size(); ++h) next[h] = d.next(HalfEdgeId(h)).index();
    return next;
}

// The same answer in other words: each cycle rotated to start turns[k]
// places on (k its old position), then the cycles reordered (new position i
// holds old cycle order[i]).
inline FacesAnswer shuffled(const FacesAnswer& a, const std::vector<Index>& order, const std::vector<std::size_t>& turns) {
    FacesAnswer out;
    out.reserve(a.size());
    for (const Index k : order) {
        std::vector<Index> c = a[k];
        if (!c.empty()) std::rotate(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(turns[k] % c.size()), c.end());
        out.push_back(std::move(c));
    }
    return out;
}

// The same, with the rotations and the order drawn from a seed.
inline FacesAnswer shuffled(const FacesAnswer& a, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<std::size_t> turns(a.size(), 0);
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (!a[k].empty()) turns[k] = static_cast<std::size_t>(rng() % a[k].size());
    }
    std::vector<Index> order(a.size());
    std::iota(order.begin(), order.end(), Index{0});
    std::shuffle(order.begin(), order.end(), rng);
    return shuffled(a, order, turns);
}

// How renumbered() rewrites a dump: old half-edge h becomes half_edges[h]
// and old face f becomes faces[f]; face f's k-th boundary half-edge (its
// outer one first, when it has one, then its inner ones) moves steps[f][k]
// places along next, to another half-edge of the same cycle; and its inner
// and isolated lists are reordered (new position i holds old entry
// inner_order[f][i], isolated_order[f][i]).
struct DumpRenumbering {
    std::vector<Index> half_edges, faces;
    std::vector<std::vector<unsigned>> steps;
    std::vector<std::vector<Index>> inner_order, isolated_order;
};

// The same DCEL renumbered as r says: equal to the original modulo numbering.
inline DcelDump renumbered(const DcelDump& d, const DumpRenumbering& r) {
    const auto halves = static_cast<Index>(d.half_edges.size());
    const auto faces = static_cast<Index>(d.faces.size());
    auto h_of = [&](HalfEdgeId h) { return h.is_null() ? h : HalfEdgeId(r.half_edges[h.index()]); };
    auto along = [&](HalfEdgeId h, unsigned steps) {
        for (; steps > 0; --steps) h = d.half_edges[h.index()].next;
        return h;
    };
    DcelDump out;
    out.vertices = d.vertices;
    for (const HalfEdgeId h : d.vertex_out) out.vertex_out.push_back(h_of(h));
    out.half_edges.resize(halves);
    for (Index h = 0; h < halves; ++h) {
        const HalfEdgeRecord& e = d.half_edges[h];
        out.half_edges[r.half_edges[h]] = {e.origin, h_of(e.twin), h_of(e.next), h_of(e.prev),
                                           FaceId(r.faces[e.face.index()])};
    }
    out.faces.resize(faces);
    for (Index f = 0; f < faces; ++f) {
        const FaceDump& old = d.faces[f];
        FaceDump& n = out.faces[r.faces[f]];
        std::size_t k = 0;
        n.outer = old.outer.is_null() ? old.outer : h_of(along(old.outer, r.steps[f][k++]));
        for (const Index i : r.inner_order[f]) n.inner.push_back(h_of(along(old.inner[i], r.steps[f][k + i])));
        for (const Index i : r.isolated_order[f]) n.isolated.push_back(old.isolated[i]);
    }
    return out;
}

// A renumbering drawn from a seed: half-edges and faces renumbered at
// random, record lists shuffled, and each face record naming a half-edge up
// to three steps further along its cycles.
inline DcelDump renumbered(const DcelDump& d, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    DumpRenumbering r;
    auto shuffled_ids = [&](std::size_t n) {
        std::vector<Index> p(n);
        std::iota(p.begin(), p.end(), Index{0});
        std::shuffle(p.begin(), p.end(), rng);
        return p;
    };
    r.half_edges = shuffled_ids(d.half_edges.size());
    r.faces = shuffled_ids(d.faces.size());
    for (const FaceDump& f : d.faces) {
        std::vector<unsigned>& steps = r.steps.emplace_back();
        if (!f.outer.is_null()) steps.push_back(static_cast<unsigned>(rng() % 4));
        for (std::size_t i = 0; i < f.inner.size(); ++i) steps.push_back(static_cast<unsigned>(rng() % 4));
        r.inner_order.push_back(shuffled_ids(f.inner.size()));
        r.isolated_order.push_back(shuffled_ids(f.isolated.size()));
    }
    return renumbered(d, r);
}

// The dump's half-edge u->v, or null.
inline HalfEdgeId dump_half_edge(const DcelDump& d, Index u, Index v) {
    for (Index h = 0; h < d.half_edges.size(); ++h) {
        const HalfEdgeRecord& r = d.half_edges[h];
        if (r.origin.index() == u && d.half_edges[r.twin.index()].origin.index() == v) return HalfEdgeId(h);
    }
    return {};
}

inline std::size_t count_kind(const check::Report& r, check::DifferenceKind k) {
    return static_cast<std::size_t>(
        std::count_if(r.differences.begin(), r.differences.end(), [&](const check::Difference& d) { return d.kind == k; }));
}

inline const check::Difference* find_kind(const check::Report& r, check::DifferenceKind k) {
    for (const check::Difference& d : r.differences) {
        if (d.kind == k) return &d;
    }
    return nullptr;
}

// A cycle's canonical form (its smallest rotation), to compare cycles as cycles.
using oracle::canonical;

// A dump that only carries a graph: edge k is half-edges 2k (from u) and
// 2k + 1, next = twin, one face. Enough for validate()'s check_embedding,
// which looks at the points and the twin pairs alone (the underlying graph
// then numbers its edges as g does).
inline DcelDump edges_only_dump(const PlanarGraph& g) {
    DcelDump d;
    d.vertices = g.vertices;
    for (Index k = 0; k < g.edges.size(); ++k) {
        const HalfEdgeId h(2 * k);
        const HalfEdgeId t(2 * k + 1);
        d.half_edges.push_back({g.edges[k].u, t, t, t, FaceId(0)});
        d.half_edges.push_back({g.edges[k].v, h, h, h, FaceId(0)});
    }
    d.faces.push_back({});
    return d;
}

}  // namespace dcel::test_support
