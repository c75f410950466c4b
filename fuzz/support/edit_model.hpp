// The edit harness's own model of what an accepted edit does to the graph:
// the vertex and edge arrays, and the vertex and edge ids its Change must
// report, worked out from the id rules in docs/editing.md and dcel/edit.hpp
// alone (additions take the next id, a removal moves the last element into
// the freed id, a merge keeps the smaller edge id and the survivor's
// half-edge into v keeps its origin). It shares no code with the editor, so
// a DCEL that is sound but has the wrong vertices or edges, or ids renamed
// other than as documented, is caught.
#pragma once

#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dcel/change.hpp"
#include "dcel/graph.hpp"
#include "support/edit_oracle.hpp"

namespace dcel::fuzz {

struct ExpectedEdit {
    PlanarGraph graph;
    IdChange<VertexId> vertices;
    IdChange<EdgeId> edges;
};

namespace model_detail {

template <class Id>
IdChange<Id> removal(Index removed, std::size_t count_before) {
    IdChange<Id> c;
    c.removed = Id(removed);
    if (removed + 1 != count_before) c.moved = Id(static_cast<Index>(count_before - 1));
    return c;
}

inline void remove_edge(PlanarGraph& g, Index e) {
    g.edges[e] = g.edges.back();
    g.edges.pop_back();
}

// Swap with last: the last vertex takes id v, and the edges follow it.
inline void remove_vertex(PlanarGraph& g, Index v) {
    const auto last = static_cast<Index>(g.vertices.size() - 1);
    g.vertices[v] = g.vertices.back();
    g.vertices.pop_back();
    for (GraphEdge& e : g.edges) {
        if (e.u.index() == last) e.u = VertexId(v);
        if (e.v.index() == last) e.v = VertexId(v);
    }
}

}  // namespace model_detail

// What an accepted step must leave, given the graph before it.
inline ExpectedEdit expected_after(const PlanarGraph& before, const test_support::Step& s, const test_support::Resolved& r) {
    using test_support::Op;
    ExpectedEdit out{before, {}, {}};
    PlanarGraph& g = out.graph;
    const auto nv = static_cast<Index>(g.vertices.size());
    const auto ne = static_cast<Index>(g.edges.size());
    switch (s.op) {
        case Op::AddVertex:
            g.vertices.push_back(r.p);
            out.vertices.added = VertexId(nv);
            break;
        case Op::AddEdge:
            g.edges.push_back({r.u, r.v});
            out.edges.added = EdgeId(ne);
            break;
        case Op::AddEdgeToPoint:
            g.vertices.push_back(r.p);
            g.edges.push_back({r.u, VertexId(nv)});
            out.vertices.added = VertexId(nv);
            out.edges.added = EdgeId(ne);
            break;
        case Op::SplitEdge: {  // e keeps its first end; the new edge continues to the old second end
            const VertexId end = g.edges[r.e.index()].v;
            g.vertices.push_back(r.p);
            g.edges[r.e.index()].v = VertexId(nv);
            g.edges.push_back({VertexId(nv), end});
            out.vertices.added = VertexId(nv);
            out.edges.added = EdgeId(ne);
            out.edges.added_from = r.e;
            break;
        }
        case Op::RemoveEdge:
            model_detail::remove_edge(g, r.e.index());
            out.edges = model_detail::removal<EdgeId>(r.e.index(), ne);
            break;
        case Op::RemoveVertex:
            model_detail::remove_vertex(g, r.u.index());
            out.vertices = model_detail::removal<VertexId>(r.u.index(), nv);
            break;
        case Op::MergeEdges: {
            std::vector<Index> at;  // the two edges at u, in id order
            for (Index k = 0; k < ne; ++k) {
                if (g.edges[k].u == r.u || g.edges[k].v == r.u) at.push_back(k);
            }
            const Index kept = at[0], gone = at[1];
            const GraphEdge other = g.edges[gone];
            const VertexId far = other.u == r.u ? other.v : other.u;
            GraphEdge& survivor = g.edges[kept];  // u replaced in place: its half-edge into u keeps its origin
            (survivor.u == r.u ? survivor.u : survivor.v) = far;
            model_detail::remove_edge(g, gone);
            model_detail::remove_vertex(g, r.u.index());
            out.edges = model_detail::removal<EdgeId>(gone, ne);
            out.edges.merged_into = EdgeId(kept);
            out.vertices = model_detail::removal<VertexId>(r.u.index(), nv);
            break;
        }
    }
    return out;
}

// Bit-for-bit (so -0.0 and 0.0 differ), edge directions included.
inline std::optional<std::string> graph_difference(const PlanarGraph& got, const PlanarGraph& want) {
    if (got.vertices.size() != want.vertices.size() || got.edges.size() != want.edges.size()) {
        return std::to_string(got.vertices.size()) + " vertices and " + std::to_string(got.edges.size()) +
               " edges, the model has " + std::to_string(want.vertices.size()) + " and " + std::to_string(want.edges.size());
    }
    for (std::size_t i = 0; i < got.vertices.size(); ++i) {
        const Point a = got.vertices[i], b = want.vertices[i];
        if (std::bit_cast<std::uint64_t>(a.x) != std::bit_cast<std::uint64_t>(b.x) ||
            std::bit_cast<std::uint64_t>(a.y) != std::bit_cast<std::uint64_t>(b.y)) {
            return "vertex v" + std::to_string(i) + " is not where the model has it";
        }
    }
    for (std::size_t k = 0; k < got.edges.size(); ++k) {
        if (!(got.edges[k] == want.edges[k])) {
            return "edge e" + std::to_string(k) + " is v" + std::to_string(got.edges[k].u.index()) + "-v" +
                   std::to_string(got.edges[k].v.index()) + ", the model has v" + std::to_string(want.edges[k].u.index()) +
                   "-v" + std::to_string(want.edges[k].v.index());
        }
    }
    return std::nullopt;
}

}  // namespace dcel::fuzz
