// Test support: edit steps and the oracle that says whether each must
// succeed, shared by the RapidCheck properties (properties/edit) and the
// fuzz harness (fuzz/edit.cpp).
//
// A step names its operation and small numbers that pick elements (modulo
// the current counts) and points, so every sequence of steps applies to
// every DCEL. expected_valid() asks build() about the graph the step would
// produce (or, for a split, whether build() refuses the point as a vertex on
// that edge); it shares no code with the editor.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <ostream>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/change.hpp"
#include "dcel/edit.hpp"
#include "dcel/error.hpp"
#include "dcel/to_graph.hpp"

namespace dcel::test_support {

enum class Op : std::uint8_t { AddVertex, AddEdge, AddEdgeToPoint, SplitEdge, RemoveEdge, RemoveVertex, MergeEdges };

struct Step {
    Op op = Op::AddVertex;
    std::uint32_t a = 0;  // picks a vertex or an edge
    std::uint32_t b = 0;  // picks a second vertex
    int x = 0;            // a point (x, y), or (for a split, x < 3) which point on the edge
    int y = 0;
    int at = 0;   // for a new point: 0 the point (x, y); 1 vertex b's point; 2 the middle of edge b
    Point exact;  // when `raw` is set, the point itself, overriding (x, y) (used by the fuzzer)
    bool raw = false;
    // a and b name ids as they are, not modulo the count: any 32-bit id,
    // out of range ones included (wild_id), so that refusals of bad ids are
    // exercised too (used by the fuzzer).
    bool wild = false;
};

// A wild step's id from its byte: ids just past the end, far past it, the
// null id and its neighbours, the 31-bit edge limit, or the byte itself.
inline std::uint32_t wild_id(std::uint32_t byte, std::uint32_t count) {
    switch (byte % 8) {
        case 0: return count;
        case 1: return count + byte / 8;
        case 2: return kNoIndex;
        case 3: return kNoIndex - 1;
        case 4: return std::uint32_t{1} << 31U;
        case 5: return (std::uint32_t{1} << 31U) - 1;
        case 6: return kNoIndex - byte / 8;
        default: return byte / 8;
    }
}

inline std::ostream& operator<<(std::ostream& os, const Step& s) {
    static constexpr const char* kNames[] = {"add_vertex",  "add_edge",      "add_edge_to_point", "split_edge",
                                             "remove_edge", "remove_vertex", "merge_edges"};
    os << kNames[static_cast<int>(s.op)] << "(a=" << s.a << " b=" << s.b << " x=" << s.x << " y=" << s.y << " at=" << s.at;
    if (s.raw) os << " exact=(" << s.exact.x << ", " << s.exact.y << ")";
    if (s.wild) os << " wild";
    return os << ")";
}

constexpr int kGrid = 6;  // the start maps and grown maps live on the grid 0..kGrid

// Where a split step puts its point: on the edge, or (x >= 3) at a grid point.
inline Point split_point(const Dcel& d, EdgeId e, const Step& s) {
    const HalfEdgeId h = half_edge_of(e, 0);
    const Point a = d.point(d.origin(h));
    const Point b = d.point(d.target(h));
    switch (s.x) {
        case 0: return {(a.x + b.x) / 2, (a.y + b.y) / 2};
        case 1: return {(3 * a.x + b.x) / 4, (3 * a.y + b.y) / 4};
        case 2: return {(a.x + 3 * b.x) / 4, (a.y + 3 * b.y) / 4};
        default: return s.raw ? s.exact : Point{static_cast<double>(s.x), static_cast<double>(s.y)};
    }
}

// A step made concrete against the current DCEL: null when the DCEL has no
// element of the kind the step needs.
struct Resolved {
    bool applicable = false;
    bool ids_in_range = true;  // false only for a wild step naming an id past the end
    VertexId u;
    VertexId v;
    EdgeId e;
    Point p;
};

inline Resolved resolve(const Dcel& d, const Step& s) {
    Resolved r;
    const auto nv = static_cast<std::uint32_t>(d.num_vertices());
    const auto ne = static_cast<std::uint32_t>(d.num_edges());
    r.p = s.raw ? s.exact : Point{static_cast<double>(s.x), static_cast<double>(s.y)};
    if (s.at == 1 && nv > 0) r.p = d.point(VertexId(s.b % nv));
    if (s.at == 2 && ne > 0) {
        const HalfEdgeId h = half_edge_of(EdgeId(s.b % ne), 0);
        const Point a = d.point(d.origin(h));
        const Point b = d.point(d.target(h));
        r.p = {(a.x + b.x) / 2, (a.y + b.y) / 2};
    }
    switch (s.op) {
        case Op::AddVertex: r.applicable = true; break;
        case Op::AddEdge:
        case Op::AddEdgeToPoint:
        case Op::RemoveVertex:
        case Op::MergeEdges:
            if (s.wild) {
                r.u = VertexId(wild_id(s.a, nv));
                r.v = VertexId(wild_id(s.b, nv));
                r.ids_in_range = r.u.index() < nv && (s.op != Op::AddEdge || r.v.index() < nv);
                r.applicable = true;
                break;
            }
            if (nv == 0) return r;
            r.u = VertexId(s.a % nv);
            r.v = VertexId(s.b % nv);
            r.applicable = true;
            break;
        case Op::SplitEdge:
        case Op::RemoveEdge:
            if (s.wild) {
                r.e = EdgeId(wild_id(s.a, ne));
                r.ids_in_range = r.e.index() < ne;
                r.applicable = true;
                if (s.op == Op::SplitEdge && r.ids_in_range) r.p = split_point(d, r.e, s);
                break;
            }
            if (ne == 0) return r;
            r.e = EdgeId(s.a % ne);
            if (s.op == Op::SplitEdge) r.p = split_point(d, r.e, s);
            r.applicable = true;
            break;
    }
    return r;
}

inline bool builds(const PlanarGraph& g) {
    try {
        (void)build(g);
        return true;
    } catch (const InvalidInput&) {
        return false;
    }
}

// Would build() put a vertex at p inside edge e (and nowhere else wrong)?
inline bool inside_edge_by_build(const PlanarGraph& g, Point p, EdgeId e) {
    PlanarGraph with = g;
    with.vertices.push_back(p);
    try {
        (void)build(with);
        return false;
    } catch (const InvalidInput& err) {
        return err.kind() == InputErrorKind::VertexOnEdge && err.edges().size() == 1 && err.edges()[0] == e;
    }
}

// The oracle: must this step succeed on d?
inline bool expected_valid(const Dcel& d, const Step& s, const Resolved& r) {
    if (!r.ids_in_range) return false;  // an id past the end is refused, whatever the edit
    const PlanarGraph g = to_graph(d);
    switch (s.op) {
        case Op::AddVertex: {
            PlanarGraph with = g;
            with.vertices.push_back(r.p);
            return builds(with);
        }
        case Op::AddEdge: {
            PlanarGraph with = g;
            with.edges.push_back({r.u, r.v});
            return builds(with);  // refuses self-loops, duplicates, crossings, touches, overlaps
        }
        case Op::AddEdgeToPoint: {
            PlanarGraph with = g;
            with.vertices.push_back(r.p);
            with.edges.push_back({r.u, VertexId(static_cast<Index>(g.vertices.size()))});
            return builds(with);
        }
        case Op::SplitEdge: return inside_edge_by_build(g, r.p, r.e);
        case Op::RemoveEdge: return true;
        case Op::RemoveVertex:
            for (const GraphEdge& e : g.edges) {
                if (e.u == r.u || e.v == r.u) return false;
            }
            return true;
        case Op::MergeEdges: {
            // Exactly two edges at u, to a and b, and u inside the segment a-b:
            // build() refuses u as a vertex on a new edge a-b.
            std::vector<VertexId> ends;
            for (const GraphEdge& e : g.edges) {
                if (e.u == r.u) ends.push_back(e.v);
                if (e.v == r.u) ends.push_back(e.u);
            }
            if (ends.size() != 2) return false;
            PlanarGraph probe;
            probe.vertices = {g.vertices[ends[0].index()], g.vertices[ends[1].index()]};
            probe.edges = {{VertexId(0), VertexId(1)}};
            return inside_edge_by_build(probe, g.vertices[r.u.index()], EdgeId(0));
        }
    }
    return false;
}

// Applies a resolved step; throws what the edit throws.
inline Change apply(Dcel& d, const Step& s, const Resolved& r) {
    switch (s.op) {
        case Op::AddVertex: return add_vertex(d, r.p);
        case Op::AddEdge: return add_edge(d, r.u, r.v);
        case Op::AddEdgeToPoint: return add_edge_to_point(d, r.u, r.p);
        case Op::SplitEdge: return split_edge(d, r.e, r.p);
        case Op::RemoveEdge: return remove_edge(d, r.e);
        case Op::RemoveVertex: return remove_isolated_vertex(d, r.u);
        case Op::MergeEdges: return merge_collinear_edges(d, r.u);
    }
    return {};
}

// Starting maps: empty, the bundled countries, and nested squares with
// holes inside holes and isolated vertices.
inline PlanarGraph start_map(int which) {
    PlanarGraph g;
    auto add = [&](std::initializer_list<Point> ps, bool closed) {
        const auto first = static_cast<Index>(g.vertices.size());
        for (const Point p : ps) g.vertices.push_back(p);
        const auto n = static_cast<Index>(ps.size());
        for (Index i = 0; i + 1 < n; ++i) g.edges.push_back({VertexId(first + i), VertexId(first + i + 1)});
        if (closed) g.edges.push_back({VertexId(first + n - 1), VertexId(first)});
    };
    if (which == 1) {  // examples/map/countries.json, scaled to the grid by 0.75
        add({{0, 0}, {3, 0}, {6, 0}, {6, 4.5}, {3, 4.5}, {0, 4.5}}, true);
        g.edges.push_back({VertexId(1), VertexId(4)});
        add({{3.75, 1.5}, {5.25, 1.5}, {5.25, 3}, {3.75, 3}}, true);
        g.vertices.push_back({1.5, 2.25});
    } else if (which == 2) {
        add({{0, 0}, {6, 0}, {6, 6}, {0, 6}}, true);
        add({{1, 1}, {5, 1}, {5, 5}, {1, 5}}, true);
        add({{2, 2}, {4, 2}, {4, 4}, {2, 4}}, true);
        add({{2.5, 2.5}, {3.5, 2.5}}, false);
        g.vertices.push_back({3, 3.5});
        g.vertices.push_back({0.5, 3});
    }
    return g;
}

}  // namespace dcel::test_support
