// Test support: independent checks of one stabbing walk. The vertices and
// edges it meets must be those a brute-force scan finds (segment_contact);
// they must come in strictly increasing order along the segment by exact
// rational arithmetic (boost cpp_rational, independent of line_order.cpp);
// each face must sit between things on its boundary; and the walk must start
// and end where locate_by_scan says.
#pragma once

#include <algorithm>
#include <boost/multiprecision/cpp_int.hpp>
#include <set>
#include <string>
#include <vector>

#include "dcel/geometry/predicates.hpp"
#include "dcel/geometry/segments.hpp"
#include "dcel/locate.hpp"
#include "dcel/queries.hpp"
#include "dcel/stab.hpp"

namespace dcel::testing {

using Rational = boost::multiprecision::cpp_rational;
inline Rational q(double v) { return Rational(v); }

// Position along a -> b, as a fraction of the segment (exact).
inline Rational position_of_point(Point a, Point b, Point p) {
    const Rational wx = q(b.x) - q(a.x), wy = q(b.y) - q(a.y);
    return ((q(p.x) - q(a.x)) * wx + (q(p.y) - q(a.y)) * wy) / (wx * wx + wy * wy);
}
inline Rational position_of_crossing(Point a, Point b, Point c, Point d) {
    const Rational wx = q(b.x) - q(a.x), wy = q(b.y) - q(a.y);
    const Rational ex = q(d.x) - q(c.x), ey = q(d.y) - q(c.y);
    const Rational cx = q(c.x) - q(a.x), cy = q(c.y) - q(a.y);
    return (cx * ey - cy * ex) / (wx * ey - wy * ex);
}

// Checks one walk; returns a description of the first problem.
inline std::string check_walk(const Dcel& d, Point a, Point b, const std::vector<StabPiece>& pieces) {
    if (pieces.empty()) return "no pieces";
    auto matches = [&](const StabPiece& p, Location l) {
        switch (l.kind) {
            case Location::Kind::Face: return p.kind == StabPiece::Kind::Face && p.face == l.face;
            case Location::Kind::Edge: return p.kind == StabPiece::Kind::Edge && p.edge == l.edge;
            case Location::Kind::Vertex: return p.kind == StabPiece::Kind::Vertex && p.vertex == l.vertex;
        }
        return false;
    };
    if (!matches(pieces.front(), locate_by_scan(d, a))) return "does not start where a lies";
    if (a == b) return pieces.size() == 1 ? "" : "a point gives more than one piece";
    if (!matches(pieces.back(), locate_by_scan(d, b))) return "does not end where b lies";
    // The brute-force contacts.
    std::set<Index> want_vertices, want_across, want_along, got_vertices, got_across, got_along;
    for (Index v = 0; v < d.num_vertices(); ++v) {
        if (on_segment(a, b, d.point(VertexId(v)))) want_vertices.insert(v);
    }
    for (Index e = 0; e < d.num_edges(); ++e) {
        const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
        const Point c = d.point(d.origin(h));
        const Point dd = d.point(d.target(h));
        const Contact k = segment_contact(a, b, c, dd);
        if (k == Contact::Crossing) want_across.insert(e);
        if (k == Contact::Overlap) want_along.insert(e);
        if (k == Contact::Touch && (strictly_inside_segment(c, dd, a) || strictly_inside_segment(c, dd, b))) {
            want_across.insert(e);
        }
    }
    for (const StabPiece& p : pieces) {
        if (p.kind == StabPiece::Kind::Vertex && !got_vertices.insert(p.vertex.index()).second) return "vertex twice";
        if (p.kind == StabPiece::Kind::Edge && !(p.along ? got_along : got_across).insert(p.edge.index()).second) {
            return "edge twice";
        }
    }
    if (got_vertices != want_vertices) return "wrong vertices";
    if (got_across != want_across) return "wrong edges crossed";
    if (got_along != want_along) return "wrong edges run along";
    // Order, and what sits next to what.
    Rational last = -1;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const StabPiece& p = pieces[i];
        if (p.kind == StabPiece::Kind::Vertex || (p.kind == StabPiece::Kind::Edge && !p.along)) {
            Rational t;
            if (p.kind == StabPiece::Kind::Vertex) {
                t = position_of_point(a, b, d.point(p.vertex));
            } else {
                const HalfEdgeId h = half_edge_of(p.edge, 0);
                t = position_of_crossing(a, b, d.point(d.origin(h)), d.point(d.target(h)));
            }
            if (t <= last) return "out of order at piece " + std::to_string(i);
            last = t;
        }
        if (p.kind != StabPiece::Kind::Face) continue;
        for (const std::size_t j : {i - 1, i + 1}) {
            if (j >= pieces.size()) continue;  // i - 1 wraps for i == 0
            const StabPiece& n = pieces[j];
            if (n.kind == StabPiece::Kind::Face) return "two faces in a row";
            if (n.kind == StabPiece::Kind::Edge) {
                if (n.along) return "a face next to a stretch along an edge";
                const HalfEdgeId h = half_edge_of(n.edge, 0);
                if (d.face(h) != p.face && d.face(Dcel::twin(h)) != p.face) return "a face next to an edge it is not beside";
            } else {
                const std::vector<FaceId> around = faces_around(d, n.vertex);
                if (std::find(around.begin(), around.end(), p.face) == around.end())
                    return "a face next to a vertex not on it";
            }
        }
    }
    return "";
}

}  // namespace dcel::testing
