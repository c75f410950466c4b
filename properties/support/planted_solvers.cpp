#include "support/planted_solvers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "oracles/exact.hpp"
#include "oracles/union_find.hpp"

namespace dcel::props::planted {
namespace {

using oracle::angle_order;
using oracle::component_labels;
using oracle::Rational;
using oracle::twice_area;

using check::FacesAnswer;

// Edge k owns half-edges 2k (u->v) and 2k+1 (v->u).
Index origin(const PlanarGraph& g, Index h) {
    const GraphEdge& e = g.edges[h >> 1U];
    return (h & 1U) == 0 ? e.u.index() : e.v.index();
}
Index target(const PlanarGraph& g, Index h) { return origin(g, h ^ 1U); }
Index half_edges(const PlanarGraph& g) { return static_cast<Index>(2 * g.edges.size()); }

enum class Order { Exact, Atan2 };

// Each vertex's outgoing half-edges, counterclockwise from east.
std::vector<std::vector<Index>> rings(const PlanarGraph& g, Order order) {
    std::vector<std::vector<Index>> around(g.vertices.size());
    for (Index h = 0; h < half_edges(g); ++h) around[origin(g, h)].push_back(h);
    for (std::size_t v = 0; v < around.size(); ++v) {
        const Point c = g.vertices[v];
        if (order == Order::Exact) {
            // An edge of length zero (only tiny_faces makes one) sorts first,
            // so that the order stays a strict weak order for std::sort.
            std::sort(around[v].begin(), around[v].end(), [&](Index a, Index b) {
                const Point pa = g.vertices[target(g, a)], pb = g.vertices[target(g, b)];
                const bool za = pa.x == c.x && pa.y == c.y, zb = pb.x == c.x && pb.y == c.y;
                if (za || zb) return za && !zb;
                return angle_order(c, pa, pb) < 0;
            });
        } else {
            // The textbook way: an angle per direction, in floating point.
            auto angle = [&](Index h) {
                const Point p = g.vertices[target(g, h)];
                return std::atan2(p.y - c.y, p.x - c.x);
            };
            std::sort(around[v].begin(), around[v].end(), [&](Index a, Index b) { return angle(a) < angle(b); });
        }
    }
    return around;
}

enum class Turn { Clockwise, Counterclockwise };

// next(u->v): the half-edge leaving v next to v->u, clockwise (the rule) or
// counterclockwise (the bug).
std::vector<Index> next_of(const PlanarGraph& g, const std::vector<std::vector<Index>>& around, Turn turn) {
    std::vector<Index> position(half_edges(g));
    for (const auto& ring : around) {
        for (std::size_t i = 0; i < ring.size(); ++i) position[ring[i]] = static_cast<Index>(i);
    }
    std::vector<Index> next(half_edges(g));
    for (Index h = 0; h < half_edges(g); ++h) {
        const auto& ring = around[target(g, h)];
        const std::size_t i = position[h ^ 1U];
        next[h] = ring[turn == Turn::Clockwise ? (i + ring.size() - 1) % ring.size() : (i + 1) % ring.size()];
    }
    return next;
}

// The orbits of next, as half-edges.
std::vector<std::vector<Index>> orbits(const std::vector<Index>& next) {
    std::vector<std::vector<Index>> out;
    std::vector<char> seen(next.size(), 0);
    for (Index h = 0; h < next.size(); ++h) {
        if (seen[h] != 0) continue;
        auto& cycle = out.emplace_back();
        for (Index x = h; seen[x] == 0; x = next[x]) {
            seen[x] = 1;
            cycle.push_back(x);
        }
    }
    return out;
}

FacesAnswer as_vertices(const PlanarGraph& g, const std::vector<std::vector<Index>>& cycles) {
    FacesAnswer out;
    for (const auto& cycle : cycles) {
        auto& c = out.emplace_back();
        for (const Index h : cycle) c.push_back(origin(g, h));
    }
    return out;
}

FacesAnswer faces(const PlanarGraph& g, Order order, Turn turn) {
    return as_vertices(g, orbits(next_of(g, rings(g, order), turn)));
}

std::vector<Point> ring_points(const PlanarGraph& g, const std::vector<Index>& cycle) {
    std::vector<Point> out;
    for (const Index h : cycle) out.push_back(g.vertices[origin(g, h)]);
    return out;
}

__extension__ typedef __int128 Wide;  // __extension__: no -Wpedantic warning

// Twice the signed area of each cycle, exactly: in 128-bit integers when
// every coordinate is an integer below 2^40 in magnitude (each product is
// below 2^81, so sums of a few million stay far below 2^127), in rationals
// otherwise. Small integer graphs are what shrinking ends with, and it asks
// for thousands of them.
std::vector<Rational> twice_areas(const PlanarGraph& g, const std::vector<std::vector<Index>>& cycles) {
    const bool small_integers = std::all_of(g.vertices.begin(), g.vertices.end(), [](Point p) {
        return std::trunc(p.x) == p.x && std::trunc(p.y) == p.y && std::fabs(p.x) < 0x1p40 && std::fabs(p.y) < 0x1p40;
    });
    std::vector<Rational> out;
    for (const auto& cycle : cycles) {
        if (!small_integers) {
            out.push_back(twice_area(ring_points(g, cycle)));
            continue;
        }
        Wide sum = 0;
        for (const Index h : cycle) {
            const Point a = g.vertices[origin(g, h)], b = g.vertices[target(g, h)];
            sum += static_cast<Wide>(static_cast<std::int64_t>(a.x)) * static_cast<std::int64_t>(b.y) -
                   static_cast<Wide>(static_cast<std::int64_t>(b.x)) * static_cast<std::int64_t>(a.y);
        }
        // At most 2^81 times the cycle length: within 2^100, exact in two halves.
        const auto high = static_cast<std::int64_t>(sum / (Wide{1} << 50));
        const auto low = static_cast<std::int64_t>(sum % (Wide{1} << 50));
        out.push_back(Rational(high) * Rational(std::int64_t{1} << 50) + Rational(low));
    }
    return out;
}

enum class Nesting { Innermost, Outermost };

// The whole DCEL. Each positive-area cycle bounds a face of its own; each
// component's one cycle of area <= 0 (its outside) is a hole of the face
// around the component, found by point-in-polygon against the other
// components' positive cycles; isolated vertices likewise.
DcelDump dump(const PlanarGraph& g, Nesting nesting) {
    const std::vector<Index> next = next_of(g, rings(g, Order::Exact), Turn::Clockwise);
    const std::vector<std::vector<Index>> cycles = orbits(next);
    const std::vector<Index> component = component_labels(g);

    const std::vector<Rational> area = twice_areas(g, cycles);
    std::vector<std::optional<Index>> face_of_cycle(cycles.size());
    DcelDump out;
    out.vertices = g.vertices;
    out.faces.push_back({});  // the unbounded face
    for (std::size_t c = 0; c < cycles.size(); ++c) {
        if (area[c] > 0) {
            face_of_cycle[c] = static_cast<Index>(out.faces.size());
            out.faces.push_back({HalfEdgeId(cycles[c].front()), {}, {}});
        }
    }
    // The face around the component holding vertex v.
    auto face_around = [&](Index v) {
        std::optional<std::size_t> best;
        for (std::size_t c = 0; c < cycles.size(); ++c) {
            if (!face_of_cycle[c] || component[origin(g, cycles[c].front())] == component[v]) continue;
            if (oracle::winding_number(g.vertices[v], ring_points(g, cycles[c])) == 0) continue;
            const bool better = !best || (nesting == Nesting::Innermost ? area[c] < area[*best] : area[c] > area[*best]);
            if (better) best = c;
        }
        return best ? *face_of_cycle[*best] : Index{0};
    };
    std::vector<FaceId> face(half_edges(g));
    for (std::size_t c = 0; c < cycles.size(); ++c) {
        Index f = 0;
        if (face_of_cycle[c]) {
            f = *face_of_cycle[c];
        } else {
            f = face_around(origin(g, cycles[c].front()));
            out.faces[f].inner.push_back(HalfEdgeId(cycles[c].front()));
        }
        for (const Index h : cycles[c]) face[h] = FaceId(f);
    }
    std::vector<Index> prev(next.size());
    for (Index h = 0; h < next.size(); ++h) prev[next[h]] = h;
    for (Index h = 0; h < half_edges(g); ++h) {
        out.half_edges.push_back(
            {VertexId(origin(g, h)), HalfEdgeId(h ^ 1U), HalfEdgeId(next[h]), HalfEdgeId(prev[h]), face[h]});
    }
    out.vertex_out.assign(g.vertices.size(), HalfEdgeId());
    for (Index h = 0; h < half_edges(g); ++h) {
        if (out.vertex_out[origin(g, h)].is_null()) out.vertex_out[origin(g, h)] = HalfEdgeId(h);
    }
    for (Index v = 0; v < g.vertices.size(); ++v) {
        if (out.vertex_out[v].is_null()) out.faces[face_around(v)].isolated.push_back(VertexId(v));
    }
    return out;
}

}  // namespace

FacesAnswer right_faces(const PlanarGraph& g) { return faces(g, Order::Exact, Turn::Clockwise); }
FacesAnswer atan2_faces(const PlanarGraph& g) { return faces(g, Order::Atan2, Turn::Clockwise); }
FacesAnswer ccw_faces(const PlanarGraph& g) { return faces(g, Order::Exact, Turn::Counterclockwise); }

FacesAnswer isolated_crash_faces(const PlanarGraph& g) {
    const auto around = rings(g, Order::Exact);
    std::vector<Index> first_edge;
    for (const auto& ring : around) first_edge.push_back(ring.at(0));  // the bug: no edge at an isolated vertex
    return as_vertices(g, orbits(next_of(g, around, Turn::Clockwise)));
}

FacesAnswer tiny_faces(const PlanarGraph& g) {
    PlanarGraph snapped = g;
    for (Point& p : snapped.vertices) {  // the bug: a "snap tiny values" tolerance
        if (std::fabs(p.x) < 1e-200) p.x = 0;
        if (std::fabs(p.y) < 1e-200) p.y = 0;
    }
    return faces(snapped, Order::Exact, Turn::Clockwise);
}

FacesAnswer huge_faces(const PlanarGraph& g) {
    PlanarGraph clamped = g;
    for (Point& p : clamped.vertices) {  // the bug: a "world box" of +-1e200 that the points are clamped to
        p.x = std::clamp(p.x, -1e200, 1e200);
        p.y = std::clamp(p.y, -1e200, 1e200);
    }
    return faces(clamped, Order::Exact, Turn::Clockwise);
}

DcelDump right_dump(const PlanarGraph& g) { return dump(g, Nesting::Innermost); }
DcelDump outer_hole_dump(const PlanarGraph& g) { return dump(g, Nesting::Outermost); }

}  // namespace dcel::props::planted
