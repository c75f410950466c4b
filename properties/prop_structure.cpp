// Combinatorial laws of every built DCEL, checked on its dump (the plain
// arrays `dcel build` prints) against the input graph: twin, next/prev,
// and how boundary cycles and face records correspond.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <set>

#include "dcel/build.hpp"
#include "dcel/dump.hpp"
#include "support/graph_case.hpp"

namespace dcel::props {
namespace {

// Half-edge 2k runs u -> v along input edge k: its destination is v.
VertexId destination(const PlanarGraph& g, Index h) {
    const GraphEdge& e = g.edges[h / 2];
    return h % 2 == 0 ? e.v : e.u;
}

RC_GTEST_PROP(Structure, prop_twin_involution_without_fixed_points, ()) {
    const GraphCase c = *graphs();
    const DcelDump d = to_dump(build(c.graph));
    const auto n = static_cast<Index>(d.half_edges.size());
    RC_ASSERT(n == 2 * c.graph.edges.size());
    for (Index h = 0; h < n; ++h) {
        const HalfEdgeId t = d.half_edges[h].twin;
        RC_ASSERT(t.index() < n);
        RC_ASSERT(t != HalfEdgeId(h));
        RC_ASSERT(d.half_edges[t.index()].twin == HalfEdgeId(h));
        RC_ASSERT(d.half_edges[t.index()].origin == destination(c.graph, h));
    }
}

RC_GTEST_PROP(Structure, prop_next_permutation_prev_inverse_origin_and_face_follow, ()) {
    const GraphCase c = *graphs();
    const DcelDump d = to_dump(build(c.graph));
    const auto n = static_cast<Index>(d.half_edges.size());
    std::vector<int> arrivals(n, 0);
    for (Index h = 0; h < n; ++h) {
        const HalfEdgeRecord& r = d.half_edges[h];
        RC_ASSERT(r.next.index() < n);
        RC_ASSERT(r.prev.index() < n);
        ++arrivals[r.next.index()];
        RC_ASSERT(d.half_edges[r.next.index()].prev == HalfEdgeId(h));
        RC_ASSERT(d.half_edges[r.prev.index()].next == HalfEdgeId(h));
        RC_ASSERT(d.half_edges[r.next.index()].origin == destination(c.graph, h));
        RC_ASSERT(d.half_edges[r.next.index()].face == r.face);
    }
    for (Index h = 0; h < n; ++h) RC_ASSERT(arrivals[h] == 1);  // next is a permutation
}

RC_GTEST_PROP(Structure, prop_cycles_partition_half_edges_and_match_face_records, ()) {
    const GraphCase c = *graphs();
    const DcelDump d = to_dump(build(c.graph));
    const auto n = static_cast<Index>(d.half_edges.size());
    // Walk every cycle once: each must close without meeting a half-edge
    // already placed in another cycle, within n steps.
    std::vector<Index> cycle_of(n, kNoIndex);
    Index cycles = 0;
    for (Index h = 0; h < n; ++h) {
        if (cycle_of[h] != kNoIndex) continue;
        Index x = h, steps = 0;
        do {
            RC_ASSERT(cycle_of[x] == kNoIndex);
            cycle_of[x] = cycles;
            x = d.half_edges[x].next.index();
            RC_ASSERT(++steps <= n);
        } while (x != h);
        ++cycles;
    }
    // Each face lists exactly the cycles that carry it, each once; only
    // face 0 has no outer cycle.
    std::vector<std::set<Index>> carried(d.faces.size());
    for (Index h = 0; h < n; ++h) {
        RC_ASSERT(d.half_edges[h].face.index() < d.faces.size());
        carried[d.half_edges[h].face.index()].insert(cycle_of[h]);
    }
    std::vector<int> listed(cycles, 0);
    for (Index f = 0; f < d.faces.size(); ++f) {
        const FaceDump& face = d.faces[f];
        RC_ASSERT(face.outer.is_null() == (f == 0));
        std::set<Index> named;
        if (!face.outer.is_null()) named.insert(cycle_of[face.outer.index()]);
        for (const HalfEdgeId h : face.inner) named.insert(cycle_of[h.index()]);
        RC_ASSERT(named.size() == face.inner.size() + (face.outer.is_null() ? 0 : 1));  // no cycle named twice
        RC_ASSERT(named == carried[f]);
        for (const Index cy : named) ++listed[cy];
    }
    for (Index cy = 0; cy < cycles; ++cy) RC_ASSERT(listed[cy] == 1);
}

// docs/formats.md: faces after the unbounded one are numbered in order of
// the smallest half-edge of their outer boundary, and vertex_out, outer and
// inner name the smallest half-edge they can (holes and isolated vertices
// listed in increasing order). Checked against a walk of every cycle from
// its smallest half-edge, in both build modes: the unchecked one labels a
// tree's cycle without walking it.
RC_GTEST_PROP(Structure, prop_every_name_is_the_smallest_half_edge, ()) {
    const GraphCase c = *graphs();
    for (const bool checked : {true, false}) {
        const DcelDump d = to_dump(build(c.graph, BuildOptions{.check_crossings = checked}));
        const auto n = static_cast<Index>(d.half_edges.size());
        std::vector<Index> smallest_on_cycle(n, kNoIndex);  // walks start at increasing h: each at its cycle's smallest
        for (Index h = 0; h < n; ++h) {
            for (Index x = h; smallest_on_cycle[x] == kNoIndex; x = d.half_edges[x].next.index()) smallest_on_cycle[x] = h;
        }
        for (Index f = 0; f < d.faces.size(); ++f) {
            const FaceDump& face = d.faces[f];
            if (f >= 2) RC_ASSERT(d.faces[f - 1].outer < face.outer);
            if (!face.outer.is_null()) RC_ASSERT(smallest_on_cycle[face.outer.index()] == face.outer.index());
            for (const HalfEdgeId h : face.inner) RC_ASSERT(smallest_on_cycle[h.index()] == h.index());
            RC_ASSERT(std::is_sorted(face.inner.begin(), face.inner.end()));
            RC_ASSERT(std::is_sorted(face.isolated.begin(), face.isolated.end()));
        }
        std::vector<HalfEdgeId> smallest_out(d.vertices.size());  // null: none yet
        for (Index h = 0; h < n; ++h) {
            HalfEdgeId& out = smallest_out[d.half_edges[h].origin.index()];
            if (out.is_null()) out = HalfEdgeId(h);
        }
        RC_ASSERT(d.vertex_out == smallest_out);
    }
}

}  // namespace
}  // namespace dcel::props
