// Test support for dcel::check: answers derived from the reference by known
// transformations (so what the comparison must say is known without asking
// it), shared by tests/test_check_*.cpp and properties/prop_check.cpp.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "dcel/check/compare.hpp"
#include "dcel/dcel.hpp"
#include "dcel/dump.hpp"
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

// Shuffles the cycles and rotates each: the same answer in other words.
inline FacesAnswer shuffled(FacesAnswer a, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    for (auto& c : a) {
        if (!c.empty()) std::rotate(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(rng() % c.size()), c.end());
    }
    std::shuffle(a.begin(), a.end(), rng);
    return a;
}

// The same DCEL with half-edges and faces renumbered at random, record lists
// shuffled, and each face record naming another half-edge of its cycles:
// equal to the original modulo numbering.
inline DcelDump renumbered(const DcelDump& d, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const auto halves = static_cast<Index>(d.half_edges.size());
    const auto faces = static_cast<Index>(d.faces.size());
    std::vector<Index> ph(halves), pf(faces);
    std::iota(ph.begin(), ph.end(), Index{0});
    std::iota(pf.begin(), pf.end(), Index{0});
    std::shuffle(ph.begin(), ph.end(), rng);
    std::shuffle(pf.begin(), pf.end(), rng);
    auto h_of = [&](HalfEdgeId h) { return h.is_null() ? h : HalfEdgeId(ph[h.index()]); };
    // Another half-edge on the cycle through h, a few steps along next.
    auto elsewhere = [&](HalfEdgeId h) {
        for (auto k = rng() % 4; k > 0; --k) h = d.half_edges[h.index()].next;
        return h;
    };
    DcelDump out;
    out.vertices = d.vertices;
    for (const HalfEdgeId h : d.vertex_out) out.vertex_out.push_back(h_of(h));
    out.half_edges.resize(halves);
    for (Index h = 0; h < halves; ++h) {
        const HalfEdgeRecord& r = d.half_edges[h];
        out.half_edges[ph[h]] = {r.origin, h_of(r.twin), h_of(r.next), h_of(r.prev), FaceId(pf[r.face.index()])};
    }
    out.faces.resize(faces);
    for (Index f = 0; f < faces; ++f) {
        const FaceDump& r = d.faces[f];
        FaceDump& n = out.faces[pf[f]];
        n.outer = r.outer.is_null() ? r.outer : h_of(elsewhere(r.outer));
        for (const HalfEdgeId h : r.inner) n.inner.push_back(h_of(elsewhere(h)));
        n.isolated = r.isolated;
        std::shuffle(n.inner.begin(), n.inner.end(), rng);
        std::shuffle(n.isolated.begin(), n.isolated.end(), rng);
    }
    return out;
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

}  // namespace dcel::test_support
