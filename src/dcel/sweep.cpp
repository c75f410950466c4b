#include "dcel/sweep.hpp"

#include <algorithm>
#include <iterator>
#include <set>
#include <utility>

#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/geometry/predicates.hpp"
#include "dcel/geometry/segments.hpp"

namespace dcel {
namespace {

// An edge as the sweep sees it: from its left (lexicographically smaller)
// endpoint to its right one. Points are copied so comparisons stay local.
struct Segment {
    Point left;
    Point right;
    VertexId left_vertex;
    VertexId right_vertex;
};

struct QueryPoint {
    Point p;
};

// Orders the segments cut by the sweep line from bottom to top. Two active
// segments never meet except at a shared endpoint (the sweep stops at the
// first violation), so comparing at the later of the two left endpoints is
// consistent for as long as both stay active.
struct StatusLess {
    using is_transparent = void;
    const Segment* segments;

    bool operator()(Index s, Index t) const {
        if (s == t) return false;
        const Segment& a = segments[s];
        const Segment& b = segments[t];
        if (a.left_vertex == b.left_vertex) {
            const Sign o = orient2d(a.left, a.right, b.right);
            return o == Sign::Zero ? s < t : o == Sign::Positive;
        }
        if (lex_less(b.left, a.left)) {
            // a starts later: a is below b when a's start is below b.
            Sign o = orient2d(b.left, b.right, a.left);
            if (o == Sign::Zero) o = orient2d(b.left, b.right, a.right);
            return o == Sign::Zero ? s < t : o == Sign::Negative;
        }
        Sign o = orient2d(a.left, a.right, b.left);
        if (o == Sign::Zero) o = orient2d(a.left, a.right, b.right);
        return o == Sign::Zero ? s < t : o == Sign::Positive;
    }
    // A segment is below a point when the point is to the left of it.
    bool operator()(Index s, QueryPoint q) const {
        return orient2d(segments[s].left, segments[s].right, q.p) == Sign::Positive;
    }
    bool operator()(QueryPoint q, Index s) const {
        return orient2d(segments[s].left, segments[s].right, q.p) == Sign::Negative;
    }
};

[[noreturn]] void throw_vertex_on_edge(const PlanarGraph& g, VertexId v, EdgeId e) {
    // A vertex inside an edge is an overlap when one of its own edges runs
    // along that edge; otherwise it is a T-junction.
    const GraphEdge& ge = g.edges[e.index()];
    const Point a = g.vertices[ge.u.index()];
    const Point b = g.vertices[ge.v.index()];
    for (Index k = 0; k < g.edges.size(); ++k) {
        const GraphEdge& other = g.edges[k];
        if (k == e.index() || (other.u != v && other.v != v)) continue;
        const VertexId w = other.u == v ? other.v : other.u;
        const Point pw = g.vertices[w.index()];
        if (orient2d(a, b, pw) == Sign::Zero &&
            segment_contact(a, b, g.vertices[v.index()], pw) == Contact::Overlap) {
            const EdgeId lo = EdgeId(std::min(k, e.index()));
            const EdgeId hi = EdgeId(std::max(k, e.index()));
            throw InvalidInput(InputErrorKind::Overlap,
                               describe_edge(g, lo) + " and " + describe_edge(g, hi) +
                                   " overlap along a collinear stretch; merge them into one chain of edges",
                               {v}, {lo, hi});
        }
    }
    throw InvalidInput(InputErrorKind::VertexOnEdge,
                       describe_vertex(g, v) + " lies inside " + describe_edge(g, e) + "; split edge " +
                           std::to_string(e.index()) + " at vertex " + std::to_string(v.index()),
                       {v}, {e});
}

// Throws when segments s and t meet other than at a shared endpoint.
void check_pair(const PlanarGraph& g, const std::vector<Segment>& segs, Index s, Index t) {
    const Segment& a = segs[s];
    const Segment& b = segs[t];
    switch (segment_contact(a.left, a.right, b.left, b.right)) {
        case Contact::None:
        case Contact::SharedEndpoint: return;
        case Contact::Crossing: {
            const EdgeId lo = EdgeId(std::min(s, t));
            const EdgeId hi = EdgeId(std::max(s, t));
            throw InvalidInput(InputErrorKind::Crossing,
                               describe_edge(g, lo) + " and " + describe_edge(g, hi) +
                                   " cross; split both at their crossing point",
                               {}, {lo, hi});
        }
        case Contact::Touch:
        case Contact::Overlap: {
            // Name a vertex that lies inside the other segment.
            const std::pair<const Segment*, Index> cases[] = {{&a, t}, {&b, s}};
            for (const auto& [seg, other] : cases) {
                const Segment& o = segs[other];
                for (const VertexId v : {seg->left_vertex, seg->right_vertex}) {
                    if (strictly_inside_segment(o.left, o.right, g.vertices[v.index()])) {
                        throw_vertex_on_edge(g, v, EdgeId(other));
                    }
                }
            }
            throw InvalidInput(InputErrorKind::Overlap,
                               describe_edge(g, EdgeId(s)) + " and " + describe_edge(g, EdgeId(t)) + " overlap", {},
                               {EdgeId(s), EdgeId(t)});
        }
    }
}

}  // namespace

std::vector<EdgeId> sweep(const SweepInput& in, bool check_intersections) {
    const PlanarGraph& g = in.graph;
    std::vector<Segment> segs(g.edges.size());
    for (Index k = 0; k < g.edges.size(); ++k) {
        VertexId a = g.edges[k].u;
        VertexId b = g.edges[k].v;
        if (lex_less(g.vertices[b.index()], g.vertices[a.index()])) std::swap(a, b);
        segs[k] = {g.vertices[a.index()], g.vertices[b.index()], a, b};
    }

    using Status = std::set<Index, StatusLess>;
    Status status(StatusLess{segs.data()});
    std::vector<Status::iterator> where(g.edges.size(), status.end());
    std::vector<EdgeId> below(g.vertices.size());

    for (const VertexId v : in.lex_order) {
        const Point p = g.vertices[v.index()];
        const Index ring_begin = in.ring_offset[v.index()];
        const Index ring_end = in.ring_offset[v.index() + 1];

        // Edges ending here leave the status first (by stored position, so a
        // comparator made inconsistent by unchecked crossings cannot misfire).
        bool any_ending = false;
        for (Index i = ring_begin; i < ring_end; ++i) {
            const Index e = edge_of(in.ring[i]).index();
            if (segs[e].right_vertex == v && where[e] != status.end()) {
                status.erase(where[e]);
                where[e] = status.end();
                any_ending = true;
            }
        }

        // `above` is the first active segment not below p.
        const auto above = status.lower_bound(QueryPoint{p});
        const auto below_it = above == status.begin() ? status.end() : std::prev(above);
        if (check_intersections && above != status.end() &&
            orient2d(segs[*above].left, segs[*above].right, p) == Sign::Zero) {
            throw_vertex_on_edge(g, v, EdgeId(*above));
        }
        if (in.wanted[v.index()] != 0 && below_it != status.end()) below[v.index()] = EdgeId(*below_it);

        // Edges starting here enter bottom to top: the ring lists directions
        // counterclockwise from east, so those in the lower half-plane (the
        // ring's second half) come first, then those in the upper one.
        Index split = ring_begin;
        while (split < ring_end) {
            const HalfEdgeId h = in.ring[split];
            const Segment& s = segs[edge_of(h).index()];
            const Point target = s.left_vertex == v ? s.right : s.left;
            if (angular_half(p, target) == 1) break;
            ++split;
        }
        Status::iterator lowest_new = status.end();
        Status::iterator highest_new = status.end();
        auto insert_starting = [&](Index i) {
            const Index e = edge_of(in.ring[i]).index();
            if (segs[e].left_vertex != v) return;
            where[e] = status.insert(above, e);
            if (lowest_new == status.end()) lowest_new = where[e];
            highest_new = where[e];
        };
        for (Index i = split; i < ring_end; ++i) insert_starting(i);
        for (Index i = ring_begin; i < split; ++i) insert_starting(i);

        if (!check_intersections) continue;
        if (lowest_new == status.end()) {
            if (any_ending && below_it != status.end() && above != status.end()) check_pair(g, segs, *below_it, *above);
        } else {
            if (below_it != status.end()) check_pair(g, segs, *below_it, *lowest_new);
            if (above != status.end()) check_pair(g, segs, *highest_new, *above);
        }
    }
    return below;
}

}  // namespace dcel
