#include "dcel/validate/embedding.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "dcel/format.hpp"
#include "dcel/geometry/predicates.hpp"
#include "dcel/validate/segment_sweep.hpp"

namespace dcel::detail {
namespace {

using Problem = std::optional<DrawingProblem>;

// The half-edges leaving each vertex (2k runs along edge k from u to v,
// 2k + 1 back): out[offset[v] .. offset[v + 1]), by half-edge id.
struct Incidence {
    std::vector<Index> offset;
    std::vector<HalfEdgeId> out;

    explicit Incidence(const PlanarGraph& g) : offset(g.vertices.size() + 1, 0), out(2 * g.edges.size()) {
        const auto half_edges = static_cast<Index>(out.size());
        for (Index h = 0; h < half_edges; ++h) ++offset[graph_origin(g, HalfEdgeId(h)).index() + 1];
        for (std::size_t v = 0; v + 1 < offset.size(); ++v) offset[v + 1] += offset[v];
        std::vector<Index> fill(offset.begin(), offset.end() - 1);
        for (Index h = 0; h < half_edges; ++h) out[fill[graph_origin(g, HalfEdgeId(h)).index()]++] = HalfEdgeId(h);
    }
    [[nodiscard]] std::span<const HalfEdgeId> leaving(VertexId v) const {
        return std::span(out).subspan(offset[v.index()], offset[v.index() + 1] - offset[v.index()]);
    }
};

Problem non_finite_coordinate(const PlanarGraph& g) {
    for (Index v = 0; v < g.vertices.size(); ++v) {
        const Point p = g.vertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            return DrawingProblem{InputErrorKind::BadCoordinate,
                                  "vertex " + std::to_string(v) + " has a non-finite coordinate " + format_point(p) +
                                      "; coordinates must be finite numbers",
                                  {VertexId(v)},
                                  {}};
        }
    }
    return {};
}

Problem self_loop(const PlanarGraph& g) {
    for (Index k = 0; k < g.edges.size(); ++k) {
        const GraphEdge& e = g.edges[k];
        if (e.u == e.v) {
            return DrawingProblem{InputErrorKind::SelfLoop,
                                  "edge " + std::to_string(k) + " [" + std::to_string(e.u.index()) + ", " +
                                      std::to_string(e.v.index()) + "] is a self-loop; remove it",
                                  {e.u},
                                  {EdgeId(k)}};
        }
    }
    return {};
}

// Equal points are next to each other in the sweep order.
Problem shared_point(const PlanarGraph& g, std::span<const VertexId> order) {
    for (std::size_t i = 1; i < order.size(); ++i) {
        const VertexId a = order[i - 1];
        const VertexId b = order[i];
        if (g.vertices[a.index()] == g.vertices[b.index()]) {
            return DrawingProblem{InputErrorKind::DuplicatePoint,
                                  "vertices " + std::to_string(a.index()) + " and " + std::to_string(b.index()) +
                                      " are at the same point " + format_point(g.vertices[b.index()]) +
                                      "; merge them into one vertex",
                                  {a, b},
                                  {}};
        }
    }
    return {};
}

DrawingProblem same_direction_problem(const PlanarGraph& g, VertexId v, HalfEdgeId a, HalfEdgeId b) {
    const EdgeId lo = std::min(edge_of(a), edge_of(b));
    const EdgeId hi = std::max(edge_of(a), edge_of(b));
    const VertexId ta = graph_target(g, a);
    if (ta == graph_target(g, b)) {
        return DrawingProblem{InputErrorKind::DuplicateEdge,
                              "edges " + std::to_string(lo.index()) + " and " + std::to_string(hi.index()) +
                                  " both join vertices " + std::to_string(std::min(v, ta).index()) + " and " +
                                  std::to_string(std::max(v, ta).index()) + "; remove one of them",
                              {v, ta},
                              {lo, hi}};
    }
    return DrawingProblem{InputErrorKind::Overlap,
                          describe_edge(g, lo) + " and " + describe_edge(g, hi) + " overlap: both leave vertex " +
                              std::to_string(v.index()) + " in the same direction; merge them into one chain of edges",
                          {v},
                          {lo, hi}};
}

// Around each vertex, by vertex id: its half-edges sorted counterclockwise
// from east (equal directions by id); two in a row pointing the same way
// are the problem. O(E log d) for maximum degree d.
Problem same_direction(const PlanarGraph& g, const Incidence& incidence) {
    std::vector<HalfEdgeId> ring;
    for (Index i = 0; i < g.vertices.size(); ++i) {
        const VertexId v(i);
        const Point centre = g.vertices[i];
        auto target = [&](HalfEdgeId h) { return g.vertices[graph_target(g, h).index()]; };
        const std::span<const HalfEdgeId> out = incidence.leaving(v);
        if (out.size() < 2) continue;
        ring.assign(out.begin(), out.end());
        std::sort(ring.begin(), ring.end(), [&](HalfEdgeId a, HalfEdgeId b) {
            const Sign s = compare_angle(centre, target(a), target(b));
            return s == Sign::Zero ? a < b : s == Sign::Negative;
        });
        for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
            if (compare_angle(centre, target(ring[k]), target(ring[k + 1])) == Sign::Zero) {
                return same_direction_problem(g, v, ring[k], ring[k + 1]);
            }
        }
    }
    return {};
}

// Vertex v lies inside edge e: an overlap when one of v's own edges runs
// along e (the first such by edge id), else a T-junction.
DrawingProblem vertex_inside(const PlanarGraph& g, const Incidence& incidence, VertexId v, EdgeId e) {
    const Point a = g.vertices[g.edges[e.index()].u.index()];
    const Point b = g.vertices[g.edges[e.index()].v.index()];
    for (const HalfEdgeId h : incidence.leaving(v)) {
        const EdgeId k = edge_of(h);
        if (k == e || orient2d(a, b, g.vertices[graph_target(g, h).index()]) != Sign::Zero) continue;
        const EdgeId lo = std::min(k, e);
        const EdgeId hi = std::max(k, e);
        return DrawingProblem{InputErrorKind::Overlap,
                              describe_edge(g, lo) + " and " + describe_edge(g, hi) +
                                  " overlap along a collinear stretch; merge them into one chain of edges",
                              {v},
                              {lo, hi}};
    }
    return DrawingProblem{InputErrorKind::VertexOnEdge,
                          describe_vertex(g, v) + " lies inside " + describe_edge(g, e) + "; split edge " +
                              std::to_string(e.index()) + " at vertex " + std::to_string(v.index()),
                          {v},
                          {e}};
}

DrawingProblem contact_problem(const PlanarGraph& g, const Incidence& incidence, const SweepContact& c) {
    switch (c.kind) {
        case SweepContact::Kind::Crossing: {
            const EdgeId lo = std::min(c.edge, c.other);
            const EdgeId hi = std::max(c.edge, c.other);
            return DrawingProblem{
                InputErrorKind::Crossing,
                describe_edge(g, lo) + " and " + describe_edge(g, hi) + " cross; split both at their crossing point",
                {},
                {lo, hi}};
        }
        case SweepContact::Kind::VertexInside: return vertex_inside(g, incidence, c.vertex, c.edge);
        case SweepContact::Kind::SameSegment: break;
    }
    return DrawingProblem{InputErrorKind::Overlap,
                          describe_edge(g, c.edge) + " and " + describe_edge(g, c.other) + " overlap",
                          {},
                          {c.edge, c.other}};
}

}  // namespace

std::optional<DrawingProblem> find_drawing_problem(const PlanarGraph& g) {
    if (Problem p = non_finite_coordinate(g)) return p;
    if (Problem p = self_loop(g)) return p;
    const std::vector<VertexId> order = sweep_order(g);
    if (Problem p = shared_point(g, order)) return p;
    const Incidence incidence(g);
    if (Problem p = same_direction(g, incidence)) return p;
    const SweepAnswers answers = sweep_segments(g, order, {}, true);
    if (answers.contact) return contact_problem(g, incidence, *answers.contact);
    return {};
}

}  // namespace dcel::detail
