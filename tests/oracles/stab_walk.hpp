// Independent checks of one stabbing walk (dcel/stab.hpp) over a DCEL taken
// as right: the vertices and edges it meets must be those a brute-force scan
// finds (exact.hpp's meeting and orientation); they must come in strictly
// increasing order along the segment or line (exact rational positions,
// independent of the library's line order); each face must sit between
// things on its boundary; and a segment's walk must start and end where the
// point location below says, a line's in the unbounded face.
#pragma once

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/location.hpp"
#include "dcel/stab.hpp"
#include "oracles/exact.hpp"
#include "oracles/nested_rings.hpp"

namespace dcel::oracle {

// Where a point lies in d, by geometry alone: at a vertex, inside an edge,
// or in the face whose outer cycle is the innermost around it (exact
// winding numbers and areas; the unbounded face when none is). The outer
// cycles are gathered once, for many queries.
class ExactLocator {
public:
    explicit ExactLocator(const Dcel& d) : d_(d) {
        for (Index f = 0; f < d.num_faces(); ++f) {
            if (d.is_unbounded(FaceId(f))) continue;
            std::vector<Point> ring;
            for (const HalfEdgeId h : d.cycle(d.outer(FaceId(f)))) ring.push_back(d.point(d.origin(h)));
            outer_cycles_.add(std::move(ring), f, 0);
        }
    }

    // The face around p, a point on no edge.
    [[nodiscard]] FaceId face_around(Point p) const {
        const Index f = outer_cycles_.innermost_around(p);
        return f == kNoIndex ? Dcel::kUnboundedFace : FaceId(f);
    }

    [[nodiscard]] Location locate(Point p) const {
        for (Index v = 0; v < d_.num_vertices(); ++v) {
            if (d_.point(VertexId(v)) == p) return Location::at_vertex(VertexId(v));
        }
        for (Index e = 0; e < d_.num_edges(); ++e) {
            const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
            if (strictly_on_segment(d_.point(d_.origin(h)), d_.point(d_.target(h)), p)) return Location::on_edge(EdgeId(e));
        }
        return Location::in_face(face_around(p));
    }

    // The faces that have v on their boundary, or the face an isolated v lies in.
    [[nodiscard]] std::vector<FaceId> faces_at(VertexId v) const {
        std::vector<FaceId> out;
        for (Index h = 0; h < d_.num_half_edges(); ++h) {
            if (d_.origin(HalfEdgeId(h)) == v) out.push_back(d_.face(HalfEdgeId(h)));
        }
        if (out.empty()) out.push_back(face_around(d_.point(v)));
        return out;
    }

private:
    const Dcel& d_;
    NestedRings outer_cycles_;
};

inline Location locate_exactly(const Dcel& d, Point p) { return ExactLocator(d).locate(p); }

namespace detail {

// What a walk must meet, by brute force: vertex, edge crossed and edge run
// along ids.
struct Contacts {
    std::set<Index> vertices, across, along;
};

// The pieces meet exactly `want`, each once, in strictly increasing order
// along a->b (exact positions, t = 0 at a and 1 at b, any t for a line),
// and every face sits between things on its boundary.
inline std::string check_pieces(const Dcel& d, const ExactLocator& locator, Point a, Point b,
                                const std::vector<StabPiece>& pieces, const Contacts& want) {
    Contacts got;
    for (const StabPiece& p : pieces) {
        if (p.kind == StabPiece::Kind::Vertex && !got.vertices.insert(p.vertex.index()).second) return "vertex twice";
        if (p.kind == StabPiece::Kind::Edge && !(p.along ? got.along : got.across).insert(p.edge.index()).second) {
            return "edge twice";
        }
    }
    if (got.vertices != want.vertices) return "wrong vertices";
    if (got.across != want.across) return "wrong edges crossed";
    if (got.along != want.along) return "wrong edges run along";
    std::optional<Rational> last;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const StabPiece& p = pieces[i];
        if (p.kind == StabPiece::Kind::Vertex || (p.kind == StabPiece::Kind::Edge && !p.along)) {
            Rational t;
            if (p.kind == StabPiece::Kind::Vertex) {
                t = parameter_of_point(a, b, d.point(p.vertex));
            } else {
                const HalfEdgeId h = half_edge_of(p.edge, 0);
                t = parameter_of_crossing(a, b, d.point(d.origin(h)), d.point(d.target(h)));
            }
            if (last && t <= *last) return "out of order at piece " + std::to_string(i);
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
                const std::vector<FaceId> around = locator.faces_at(n.vertex);
                if (std::find(around.begin(), around.end(), p.face) == around.end())
                    return "a face next to a vertex not on it";
            }
        }
    }
    return "";
}

}  // namespace detail

// Checks one walk from a to b; returns a description of the first problem,
// or "" when there is none.
inline std::string check_walk(const Dcel& d, const ExactLocator& locator, Point a, Point b,
                              const std::vector<StabPiece>& pieces) {
    if (pieces.empty()) return "no pieces";
    auto matches = [&](const StabPiece& p, Location l) {
        switch (l.kind) {
            case Location::Kind::Face: return p.kind == StabPiece::Kind::Face && p.face == l.face;
            case Location::Kind::Edge: return p.kind == StabPiece::Kind::Edge && p.edge == l.edge;
            case Location::Kind::Vertex: return p.kind == StabPiece::Kind::Vertex && p.vertex == l.vertex;
        }
        return false;
    };
    if (!matches(pieces.front(), locator.locate(a))) return "does not start where a lies";
    if (a == b) return pieces.size() == 1 ? "" : "a point gives more than one piece";
    if (!matches(pieces.back(), locator.locate(b))) return "does not end where b lies";
    // The brute-force contacts.
    detail::Contacts want;
    for (Index v = 0; v < d.num_vertices(); ++v) {
        const Point p = d.point(VertexId(v));
        if (p == a || p == b || strictly_on_segment(a, b, p)) want.vertices.insert(v);
    }
    for (Index e = 0; e < d.num_edges(); ++e) {
        const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
        const Point c = d.point(d.origin(h));
        const Point dd = d.point(d.target(h));
        const Meeting m = meeting(a, b, c, dd);
        if (m == Meeting::Crossing) want.across.insert(e);
        if (m == Meeting::Overlap || m == Meeting::Same) want.along.insert(e);
        // Starting or ending inside an edge counts as crossing it there.
        if (m == Meeting::Touch && (strictly_on_segment(c, dd, a) || strictly_on_segment(c, dd, b))) want.across.insert(e);
    }
    return detail::check_pieces(d, locator, a, b, pieces, want);
}

// Checks one walk along the whole line through a and b (a != b), from a's
// side of infinity to b's: it starts and ends in the unbounded face, meets
// every vertex on the line, crosses every edge whose ends lie strictly on
// either side, and runs along every edge with both ends on the line.
inline std::string check_line_walk(const Dcel& d, const ExactLocator& locator, Point a, Point b,
                                   const std::vector<StabPiece>& pieces) {
    if (pieces.empty()) return "no pieces";
    for (const StabPiece* end : {&pieces.front(), &pieces.back()}) {
        if (end->kind != StabPiece::Kind::Face || end->face != Dcel::kUnboundedFace)
            return "an end not in the unbounded face";
    }
    detail::Contacts want;
    for (Index v = 0; v < d.num_vertices(); ++v) {
        if (orientation(a, b, d.point(VertexId(v))) == 0) want.vertices.insert(v);
    }
    for (Index e = 0; e < d.num_edges(); ++e) {
        const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
        const int oc = orientation(a, b, d.point(d.origin(h))), od = orientation(a, b, d.point(d.target(h)));
        if (oc * od < 0) want.across.insert(e);
        if (oc == 0 && od == 0) want.along.insert(e);
    }
    return detail::check_pieces(d, locator, a, b, pieces, want);
}

inline std::string check_walk(const Dcel& d, Point a, Point b, const std::vector<StabPiece>& pieces) {
    return check_walk(d, ExactLocator(d), a, b, pieces);
}

}  // namespace dcel::oracle
