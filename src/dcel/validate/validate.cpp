#include "dcel/validate.hpp"

#include <algorithm>
#include <span>
#include <string>

#include "dcel/core/union_find.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/geometry/area.hpp"
#include "dcel/geometry/predicates.hpp"
#include "dcel/validate/embedding.hpp"
#include "dcel/validate/segment_sweep.hpp"

namespace dcel {

// From the internals of the core (dcel::detail): the geometry's exact
// predicates, and validate()'s own drawing checks and sweep, which share no
// code with build()'s (see validate/embedding.hpp).
using detail::DrawingProblem;
using detail::find_drawing_problem;
using detail::polygon_area_sign;
using detail::sweep_order;
using detail::sweep_segments;
using detail::SweepAnswers;
namespace {

// Sizes as 32-bit counts (references() checks they fit before anything else).
struct Sizes {
    Index vertices;
    Index half_edges;
    Index faces;
    explicit Sizes(const DcelDump& d)
        : vertices(static_cast<Index>(d.vertices.size())),
          half_edges(static_cast<Index>(d.half_edges.size())),
          faces(static_cast<Index>(d.faces.size())) {}
};

Violation violation(Invariant inv, std::string message, std::vector<VertexId> vs = {}, std::vector<HalfEdgeId> hs = {},
                    std::vector<FaceId> fs = {}) {
    return {inv, std::move(message), std::move(vs), std::move(hs), std::move(fs)};
}

const HalfEdgeRecord& rec(const DcelDump& d, HalfEdgeId h) { return d.half_edges[h.index()]; }
VertexId target_of(const DcelDump& d, HalfEdgeId h) { return rec(d, rec(d, h).twin).origin; }
Point point_of(const DcelDump& d, VertexId v) { return d.vertices[v.index()]; }

// Cycle number of every half-edge under next (valid once NextPrev holds),
// numbered in order of their smallest half-edge.
struct Cycles {
    std::vector<Index> of;             // per half-edge
    std::vector<HalfEdgeId> smallest;  // per cycle
};
Cycles find_cycles(const DcelDump& d) {
    Cycles c;
    c.of.assign(d.half_edges.size(), kNoIndex);
    for (Index h = 0; h < d.half_edges.size(); ++h) {
        if (c.of[h] != kNoIndex) continue;
        const auto id = static_cast<Index>(c.smallest.size());
        c.smallest.push_back(HalfEdgeId(h));
        for (Index x = h; c.of[x] == kNoIndex; x = d.half_edges[x].next.index()) c.of[x] = id;
    }
    return c;
}

std::vector<Index> out_degrees(const DcelDump& d) {
    std::vector<Index> degree(d.vertices.size(), 0);
    for (const HalfEdgeRecord& r : d.half_edges) ++degree[r.origin.index()];
    return degree;
}

// The graph underlying a dump: edge k joins the two half-edges of the k-th
// twin pair (counting pairs by their smaller half-edge). to_dump_half_edge
// maps the graph's half-edge 2k / 2k+1 back to the dump's.
struct UnderlyingGraph {
    PlanarGraph graph;
    std::vector<HalfEdgeId> to_dump_half_edge;
};
UnderlyingGraph underlying_graph(const DcelDump& d) {
    UnderlyingGraph u;
    u.graph.vertices = d.vertices;
    for (Index h = 0; h < d.half_edges.size(); ++h) {
        const HalfEdgeId t = d.half_edges[h].twin;
        if (h > t.index()) continue;
        u.graph.edges.push_back({d.half_edges[h].origin, d.half_edges[t.index()].origin});
        u.to_dump_half_edge.push_back(HalfEdgeId(h));
        u.to_dump_half_edge.push_back(t);
    }
    return u;
}

std::string cycle_name(HalfEdgeId smallest) { return "the cycle through " + smallest.str(); }

}  // namespace

const char* to_string(Invariant invariant) {
    switch (invariant) {
        case Invariant::References: return "references";
        case Invariant::Twin: return "twin";
        case Invariant::NextPrev: return "next-prev";
        case Invariant::NextOrigin: return "next-origin";
        case Invariant::FaceOnCycle: return "face-on-cycle";
        case Invariant::VertexOut: return "vertex-out";
        case Invariant::FaceRecords: return "face-records";
        case Invariant::IsolatedVertices: return "isolated-vertices";
        case Invariant::Embedding: return "embedding";
        case Invariant::Rotation: return "rotation";
        case Invariant::Orientation: return "orientation";
        case Invariant::HolePlacement: return "hole-placement";
    }
    return "unknown";
}

CheckResult check_references(const DcelDump& d) {
    if (d.vertices.size() >= kNoIndex || d.half_edges.size() >= kNoIndex || d.faces.size() >= kNoIndex) {
        return violation(Invariant::References, "too many elements for 32-bit ids");
    }
    const Sizes n(d);
    if (n.faces == 0) return violation(Invariant::References, "no faces: there must be at least the unbounded face");
    if (!d.vertex_out.empty() && d.vertex_out.size() != d.vertices.size()) {
        return violation(Invariant::References, "vertex_out has " + std::to_string(d.vertex_out.size()) + " entries for " +
                                                    std::to_string(n.vertices) + " vertices");
    }
    for (Index v = 0; v < d.vertex_out.size(); ++v) {
        const HalfEdgeId h = d.vertex_out[v];
        if (!h.is_null() && h.index() >= n.half_edges) {
            return violation(Invariant::References,
                             "out(v" + std::to_string(v) + ") = " + h.str() + " is out of range (" +
                                 std::to_string(n.half_edges) + " half-edges)",
                             {VertexId(v)}, {h});
        }
    }
    for (Index i = 0; i < n.half_edges; ++i) {
        const HalfEdgeRecord& r = d.half_edges[i];
        const HalfEdgeId h(i);
        auto bad = [&](const char* field, const std::string& value, Index limit, const char* what) {
            return violation(Invariant::References,
                             std::string(field) + "(" + h.str() + ") = " + value + " is out of range (" +
                                 std::to_string(limit) + " " + what + ")",
                             {}, {h});
        };
        if (r.origin.index() >= n.vertices) return bad("origin", r.origin.str(), n.vertices, "vertices");
        if (r.twin.index() >= n.half_edges) return bad("twin", r.twin.str(), n.half_edges, "half-edges");
        if (r.next.index() >= n.half_edges) return bad("next", r.next.str(), n.half_edges, "half-edges");
        if (r.prev.index() >= n.half_edges) return bad("prev", r.prev.str(), n.half_edges, "half-edges");
        if (r.face.index() >= n.faces) return bad("face", r.face.str(), n.faces, "faces");
    }
    for (Index i = 0; i < n.faces; ++i) {
        const FaceDump& f = d.faces[i];
        const FaceId fid(i);
        auto bad = [&](const char* field, const std::string& value, Index limit, const char* what) {
            return violation(Invariant::References,
                             std::string(field) + " of " + fid.str() + " names " + value + ", out of range (" +
                                 std::to_string(limit) + " " + what + ")",
                             {}, {}, {fid});
        };
        if (!f.outer.is_null() && f.outer.index() >= n.half_edges) {
            return bad("the outer cycle", f.outer.str(), n.half_edges, "half-edges");
        }
        for (const HalfEdgeId h : f.inner) {
            if (h.index() >= n.half_edges) return bad("an inner cycle", h.str(), n.half_edges, "half-edges");
        }
        for (const VertexId v : f.isolated) {
            if (v.index() >= n.vertices) return bad("an isolated vertex", v.str(), n.vertices, "vertices");
        }
    }
    return {};
}

CheckResult check_twin(const DcelDump& d) {
    for (Index i = 0; i < d.half_edges.size(); ++i) {
        const HalfEdgeId h(i);
        const HalfEdgeId t = d.half_edges[i].twin;
        if (t == h)
            return violation(Invariant::Twin, "twin(" + h.str() + ") = " + h.str() + ": a half-edge is its own twin", {},
                             {h});
        const HalfEdgeId back = rec(d, t).twin;
        if (back != h) {
            return violation(Invariant::Twin,
                             "twin(" + h.str() + ") = " + t.str() + " but twin(" + t.str() + ") = " + back.str(), {},
                             {h, t});
        }
    }
    return {};
}

CheckResult check_next_prev(const DcelDump& d) {
    for (Index i = 0; i < d.half_edges.size(); ++i) {
        const HalfEdgeId h(i);
        const HalfEdgeId n = d.half_edges[i].next;
        const HalfEdgeId back = rec(d, n).prev;
        if (back != h) {
            return violation(Invariant::NextPrev,
                             "next(" + h.str() + ") = " + n.str() + " but prev(" + n.str() + ") = " + back.str() +
                                 ": next is not a permutation with prev as its inverse",
                             {}, {h, n});
        }
    }
    return {};
}

CheckResult check_next_origin(const DcelDump& d) {
    for (Index i = 0; i < d.half_edges.size(); ++i) {
        const HalfEdgeId h(i);
        const HalfEdgeId n = d.half_edges[i].next;
        const VertexId arrive = target_of(d, h);
        const VertexId leave = rec(d, n).origin;
        if (arrive != leave) {
            return violation(Invariant::NextOrigin,
                             h.str() + " ends at " + arrive.str() + " but next(" + h.str() + ") = " + n.str() +
                                 " starts at " + leave.str(),
                             {arrive, leave}, {h, n});
        }
    }
    return {};
}

CheckResult check_face_on_cycle(const DcelDump& d) {
    for (Index i = 0; i < d.half_edges.size(); ++i) {
        const HalfEdgeId h(i);
        const HalfEdgeId n = d.half_edges[i].next;
        if (rec(d, n).face != d.half_edges[i].face) {
            return violation(Invariant::FaceOnCycle,
                             "face(" + h.str() + ") = " + d.half_edges[i].face.str() + " but face(next(" + h.str() +
                                 ") = " + n.str() + ") = " + rec(d, n).face.str(),
                             {}, {h, n}, {d.half_edges[i].face, rec(d, n).face});
        }
    }
    return {};
}

CheckResult check_vertex_out(const DcelDump& d) {
    if (d.vertex_out.empty()) return {};  // not given: nothing to check
    const std::vector<Index> degree = out_degrees(d);
    for (Index i = 0; i < d.vertices.size(); ++i) {
        const VertexId v(i);
        const HalfEdgeId h = d.vertex_out[i];
        if (h.is_null()) {
            if (degree[i] != 0) {
                return violation(Invariant::VertexOut,
                                 "out(" + v.str() + ") is null but " + std::to_string(degree[i]) + " half-edges leave it",
                                 {v});
            }
        } else if (rec(d, h).origin != v) {
            return violation(Invariant::VertexOut,
                             "out(" + v.str() + ") = " + h.str() + " but " + h.str() + " leaves " + rec(d, h).origin.str(),
                             {v}, {h});
        }
    }
    return {};
}

CheckResult check_face_records(const DcelDump& d) {
    const Cycles cycles = find_cycles(d);
    std::vector<Index> named(cycles.smallest.size(), 0);
    std::vector<FaceId> unbounded;
    for (Index i = 0; i < d.faces.size(); ++i) {
        const FaceId f(i);
        const FaceDump& fd = d.faces[i];
        if (fd.outer.is_null()) unbounded.push_back(f);
        auto claim = [&](HalfEdgeId h, const char* role) -> CheckResult {
            const Index c = cycles.of[h.index()];
            if (rec(d, h).face != f) {
                return violation(Invariant::FaceRecords,
                                 f.str() + " lists " + h.str() + " as " + role + " cycle, but face(" + h.str() +
                                     ") = " + rec(d, h).face.str(),
                                 {}, {h}, {f, rec(d, h).face});
            }
            if (++named[c] > 1) {
                return violation(Invariant::FaceRecords,
                                 cycle_name(cycles.smallest[c]) + " is listed more than once (again by " + f.str() + " as " +
                                     role + " cycle, via " + h.str() + ")",
                                 {}, {cycles.smallest[c], h}, {f});
            }
            return {};
        };
        if (!fd.outer.is_null()) {
            if (auto v = claim(fd.outer, "its outer")) return v;
        }
        for (const HalfEdgeId h : fd.inner) {
            if (auto v = claim(h, "an inner")) return v;
        }
    }
    if (unbounded.size() != 1) {
        return violation(
            Invariant::FaceRecords,
            std::to_string(unbounded.size()) + " faces have no outer cycle; exactly one (the unbounded face) must have none",
            {}, {}, unbounded);
    }
    for (Index c = 0; c < named.size(); ++c) {
        if (named[c] == 0) {
            const HalfEdgeId h = cycles.smallest[c];
            return violation(Invariant::FaceRecords,
                             cycle_name(h) + " (face " + rec(d, h).face.str() +
                                 ") is not listed by any face as its outer or an inner cycle",
                             {}, {h}, {rec(d, h).face});
        }
    }
    return {};
}

CheckResult check_isolated_vertices(const DcelDump& d) {
    const std::vector<Index> degree = out_degrees(d);
    std::vector<Index> listed(d.vertices.size(), 0);
    for (Index i = 0; i < d.faces.size(); ++i) {
        for (const VertexId v : d.faces[i].isolated) {
            if (degree[v.index()] != 0) {
                return violation(Invariant::IsolatedVertices,
                                 "f" + std::to_string(i) + " lists " + v.str() + " as isolated, but " +
                                     std::to_string(degree[v.index()]) + " half-edges leave it",
                                 {v}, {}, {FaceId(i)});
            }
            if (++listed[v.index()] > 1) {
                return violation(
                    Invariant::IsolatedVertices,
                    "isolated vertex " + v.str() + " is listed more than once (again by f" + std::to_string(i) + ")", {v},
                    {}, {FaceId(i)});
            }
        }
    }
    for (Index v = 0; v < d.vertices.size(); ++v) {
        if (degree[v] == 0 && listed[v] == 0) {
            return violation(Invariant::IsolatedVertices,
                             "isolated vertex v" + std::to_string(v) + " is not listed in any face", {VertexId(v)});
        }
    }
    return {};
}

CheckResult check_embedding(const DcelDump& d) {
    // The graph under the dump must be a planar straight-line graph: what
    // build() requires of its input, decided by validate()'s own code.
    const UnderlyingGraph u = underlying_graph(d);
    const std::optional<DrawingProblem> problem = find_drawing_problem(u.graph);
    if (!problem) return {};
    // The message numbers edges by twin pair; say which half-edges those are.
    std::vector<HalfEdgeId> hs;
    std::string message = problem->message;
    for (const EdgeId k : problem->edges) {
        const HalfEdgeId h = u.to_dump_half_edge[half_edge_of(k, 0).index()];
        hs.push_back(h);
        message += "; edge " + std::to_string(k.index()) + " is " + h.str() + "/" + rec(d, h).twin.str();
    }
    return violation(Invariant::Embedding, message, problem->vertices, hs);
}

CheckResult check_rotation(const DcelDump& d) {
    const std::vector<Index> degree = out_degrees(d);
    std::vector<HalfEdgeId> first_out(d.vertices.size());
    for (Index i = d.half_edges.size(); i-- > 0;) first_out[d.half_edges[i].origin.index()] = HalfEdgeId(i);
    for (Index i = 0; i < d.vertices.size(); ++i) {
        if (degree[i] == 0) continue;
        const VertexId v(i);
        const Point c = point_of(d, v);
        const HalfEdgeId start = first_out[i];
        // Walk next(twin(h)): it must visit all degree[v] half-edges and come
        // back, turning clockwise, with exactly one wrap past east.
        Index steps = 0;
        Index wraps = 0;
        HalfEdgeId h = start;
        do {
            const HalfEdgeId n = rec(d, rec(d, h).twin).next;
            ++steps;
            if (steps > degree[i]) break;
            if (degree[i] > 1 && n != h) {
                const Sign s = compare_angle(c, point_of(d, target_of(d, h)), point_of(d, target_of(d, n)));
                if (s != Sign::Positive) ++wraps;
            }
            h = n;
        } while (h != start);
        if (steps != degree[i]) {
            return violation(Invariant::Rotation,
                             "around " + v.str() + ", next(twin(h)) starting at " + start.str() + " visits " +
                                 (steps > degree[i] ? "more than" : std::to_string(steps) + " of") + " the " +
                                 std::to_string(degree[i]) + " half-edges leaving it",
                             {v}, {start});
        }
        if (degree[i] > 1 && wraps != 1) {
            return violation(Invariant::Rotation,
                             "around " + v.str() +
                                 ", next(twin(h)) does not visit the outgoing half-edges in "
                                 "clockwise order (it turns the wrong way " +
                                 std::to_string(wraps) + " times)",
                             {v}, {start});
        }
    }
    return {};
}

CheckResult check_orientation(const DcelDump& d) {
    auto area_sign = [&](HalfEdgeId start) {
        return polygon_area_sign([&](auto&& f) {
            HalfEdgeId h = start;
            std::size_t steps = 0;  // capped, in case next is not a permutation
            do {
                f(point_of(d, rec(d, h).origin), point_of(d, target_of(d, h)));
                h = rec(d, h).next;
            } while (h != start && ++steps < d.half_edges.size());
        });
    };
    for (Index i = 0; i < d.faces.size(); ++i) {
        const FaceId f(i);
        const FaceDump& fd = d.faces[i];
        if (!fd.outer.is_null() && area_sign(fd.outer) != Sign::Positive) {
            return violation(Invariant::Orientation,
                             "the outer cycle of " + f.str() + " (through " + fd.outer.str() +
                                 ") is not counterclockwise: its signed area is not positive",
                             {}, {fd.outer}, {f});
        }
        for (const HalfEdgeId h : fd.inner) {
            if (area_sign(h) == Sign::Positive) {
                return violation(Invariant::Orientation,
                                 "the inner cycle of " + f.str() + " through " + h.str() +
                                     " is counterclockwise (positive area): it bounds a face of its own, not a hole",
                                 {}, {h}, {f});
            }
        }
    }
    return {};
}

namespace {

// The components of g (by union-find) and the leftmost vertex of each, its
// first in sweep order; returned in sweep order.
std::vector<VertexId> leftmost_vertices(const PlanarGraph& g, std::span<const VertexId> order) {
    const auto n = static_cast<Index>(g.vertices.size());
    detail::UnionFind sets(n);
    for (const GraphEdge& e : g.edges) sets.unite(e.u.index(), e.v.index());
    std::vector<char> root_seen(n, 0);
    std::vector<VertexId> leftmost;
    for (const VertexId v : order) {
        const Index r = sets.find(v.index());
        if (root_seen[r] == 0) {
            root_seen[r] = 1;
            leftmost.push_back(v);
        }
    }
    return leftmost;
}

// For each vertex v with wanted[v] set and edges, the half-edge leaving it
// whose left side holds the direction west: counterclockwise from east, the
// last one before west (in the upper half-plane), or when none is there, the
// last one of all. For a component's leftmost vertex it is on the
// component's outer boundary. O(H).
std::vector<HalfEdgeId> west_facing(const DcelDump& d, const std::vector<char>& wanted) {
    std::vector<HalfEdgeId> best(d.vertices.size());
    for (Index i = 0; i < d.half_edges.size(); ++i) {
        const HalfEdgeId h(i);
        const VertexId v = d.half_edges[i].origin;
        if (wanted[v.index()] == 0) continue;
        HalfEdgeId& b = best[v.index()];
        if (b.is_null()) {
            b = h;
            continue;
        }
        const Point c = point_of(d, v);
        const Point th = point_of(d, target_of(d, h));
        const Point tb = point_of(d, target_of(d, b));
        const bool h_upper = angular_half(c, th) == 0;
        const bool b_upper = angular_half(c, tb) == 0;
        if (h_upper != b_upper ? h_upper : compare_angle(c, tb, th) == Sign::Negative) b = h;
    }
    return best;
}

FaceId unbounded_face(const DcelDump& d) {
    FaceId unbounded;
    for (Index i = 0; i < d.faces.size(); ++i) {
        if (d.faces[i].outer.is_null()) unbounded = FaceId(i);
    }
    return unbounded;
}

// The face just above edge e (null: nothing, so the unbounded face): the
// face of e's half-edge that runs left to right.
FaceId face_above(const DcelDump& d, const UnderlyingGraph& u, EdgeId e, FaceId unbounded) {
    if (e.is_null()) return unbounded;
    const PlanarGraph& g = u.graph;
    const HalfEdgeId forward = half_edge_of(e, 0);
    const bool left_to_right = lex_less(g.vertices[graph_origin(g, forward).index()],
                                        g.vertices[graph_target(g, forward).index()]);
    return rec(d, u.to_dump_half_edge[(left_to_right ? forward : twin(forward)).index()]).face;
}

std::vector<FaceId> face_of_isolated(const DcelDump& d) {
    std::vector<FaceId> in(d.vertices.size());
    for (Index i = 0; i < d.faces.size(); ++i) {
        for (const VertexId v : d.faces[i].isolated) in[v.index()] = FaceId(i);
    }
    return in;
}

Violation misplaced(VertexId v, HalfEdgeId witness, FaceId actual, FaceId expected, EdgeId below) {
    const std::string what = witness.is_null() ? "isolated vertex " + v.str()
                                               : "the component whose leftmost vertex is " + v.str() +
                                                     " (outer boundary through " + witness.str() + ")";
    return violation(Invariant::HolePlacement,
                     what + " is placed in " + actual.str() + " but lies in " + expected.str() +
                         (below.is_null() ? std::string(" (nothing is below it)") : " (the face above the edge below it)"),
                     {v}, witness.is_null() ? std::vector<HalfEdgeId>{} : std::vector<HalfEdgeId>{witness},
                     {actual, expected});
}

}  // namespace

CheckResult check_hole_placement(const DcelDump& d) {
    // Each component lies in the face that holds the point just below its
    // leftmost vertex v: the face above the edge directly below v, which
    // validate()'s own sweep finds. The dump places the component by its
    // outer boundary, the cycle through the half-edge at v facing west (an
    // isolated vertex by the face listing it).
    const UnderlyingGraph u = underlying_graph(d);
    const std::vector<VertexId> order = sweep_order(u.graph);
    const std::vector<VertexId> leftmost = leftmost_vertices(u.graph, order);
    std::vector<char> wanted(d.vertices.size(), 0);
    for (const VertexId v : leftmost) wanted[v.index()] = 1;
    const SweepAnswers answers = sweep_segments(u.graph, order, wanted, false);
    const std::vector<HalfEdgeId> witness = west_facing(d, wanted);
    const std::vector<FaceId> isolated_in = face_of_isolated(d);
    const FaceId unbounded = unbounded_face(d);
    for (const VertexId v : leftmost) {
        const EdgeId below = answers.below[v.index()];
        const FaceId expected = face_above(d, u, below, unbounded);
        const HalfEdgeId w = witness[v.index()];
        const FaceId actual = w.is_null() ? isolated_in[v.index()] : rec(d, w).face;
        if (actual != expected) return misplaced(v, w, actual, expected, below);
    }
    return {};
}

namespace {

// The checkers in the order validate() runs them, each with the invariants
// it relies on: references and twin for every lookup, next-prev for every
// walk, the embedding for the geometric ones. validate() stops at the first
// violation, so for it every checker before has passed; validate_all() runs
// each checker whose prerequisites all passed.
using Checker = CheckResult (*)(const DcelDump&);
constexpr unsigned bit(Invariant i) { return 1U << static_cast<unsigned>(i); }
struct Step {
    Checker check;
    Invariant invariant;
    unsigned needs;  // bits of the invariants that must hold first
};
constexpr unsigned kWalks = bit(Invariant::NextPrev) | bit(Invariant::NextOrigin);
constexpr Step kSteps[] = {
    {check_references, Invariant::References, 0},
    {check_twin, Invariant::Twin, bit(Invariant::References)},
    {check_next_prev, Invariant::NextPrev, bit(Invariant::References)},
    {check_next_origin, Invariant::NextOrigin, bit(Invariant::Twin)},
    {check_face_on_cycle, Invariant::FaceOnCycle, bit(Invariant::Twin)},
    {check_vertex_out, Invariant::VertexOut, bit(Invariant::Twin)},
    {check_face_records, Invariant::FaceRecords,
     bit(Invariant::Twin) | bit(Invariant::NextPrev) | bit(Invariant::FaceOnCycle)},
    {check_isolated_vertices, Invariant::IsolatedVertices, bit(Invariant::Twin)},
    {check_embedding, Invariant::Embedding, bit(Invariant::Twin)},
    {check_rotation, Invariant::Rotation, bit(Invariant::Embedding) | kWalks},
    {check_orientation, Invariant::Orientation, bit(Invariant::Embedding) | kWalks | bit(Invariant::FaceRecords)},
    {check_hole_placement, Invariant::HolePlacement,
     bit(Invariant::Rotation) | bit(Invariant::Orientation) | bit(Invariant::IsolatedVertices)},
};

}  // namespace

CheckResult validate(const DcelDump& d) {
    for (const Step& step : kSteps) {
        if (auto v = step.check(d)) return v;
    }
    return {};
}

CheckResult validate(const Dcel& d) { return validate(to_dump(d)); }

std::vector<Violation> validate_all(const DcelDump& d) {
    std::vector<Violation> found;
    unsigned held = 0;
    for (const Step& step : kSteps) {
        if ((step.needs & held) != step.needs) continue;
        if (auto v = step.check(d)) {
            found.push_back(std::move(*v));
        } else {
            held |= bit(step.invariant);
        }
    }
    return found;
}

}  // namespace dcel
