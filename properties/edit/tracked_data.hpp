// User data attached to a DCEL under random edits, with checks that tie each
// value to geometry, so a wrong Change (a wrong id added, merged or moved)
// shows up:
//  - each vertex carries its own point: it must still be d.point(v);
//  - each edge carries a segment that contains it (its own ends when it was
//    added; split pieces copy it; a collinear merge takes the hull of both);
//  - each face carries a set of labels (split parts copy it, a merge takes
//    the union). A point inside a face before an edit must lie, after it, in
//    a face whose labels include all the labels it had.
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "dcel/geometry/predicates.hpp"
#include "dcel/locate.hpp"
#include "dcel/user_data.hpp"

namespace dcel::props {

using Span = std::pair<Point, Point>;

class TrackedData {
public:
    explicit TrackedData(const Dcel& d)
        : where_(d),
          span_(d, Span{}, [](Span& kept, Span&& absorbed) { kept = hull(kept, absorbed); }),
          labels_(d, {},
                  [](std::set<int>& kept, std::set<int>&& absorbed) { kept.insert(absorbed.begin(), absorbed.end()); }) {
        for (Index v = 0; v < d.num_vertices(); ++v) where_[VertexId(v)] = d.point(VertexId(v));
        for (Index e = 0; e < d.num_edges(); ++e) span_[EdgeId(e)] = ends(d, EdgeId(e));
        for (Index f = 0; f < d.num_faces(); ++f) labels_[FaceId(f)] = {static_cast<int>(f)};
    }

    void follow(const Change& c, const Dcel& d) {
        where_.follow(c);
        span_.follow(c);
        labels_.follow(c);
        if (!c.vertices.added.is_null()) where_[c.vertices.added] = d.point(c.vertices.added);
        if (!c.edges.added.is_null() && c.edges.added_from.is_null()) span_[c.edges.added] = ends(d, c.edges.added);
    }

    // Empty when every value still fits its element.
    [[nodiscard]] std::string problem(const Dcel& d) const {
        if (!where_.in_step(d) || !span_.in_step(d) || !labels_.in_step(d)) return "data out of step";
        for (Index v = 0; v < d.num_vertices(); ++v) {
            if (!(where_[VertexId(v)] == d.point(VertexId(v)))) return "vertex data moved to another vertex";
        }
        for (Index e = 0; e < d.num_edges(); ++e) {
            const Span s = span_[EdgeId(e)];
            const Span own = ends(d, EdgeId(e));
            if (!on_segment(s.first, s.second, own.first) || !on_segment(s.first, s.second, own.second)) {
                return "edge data of e" + std::to_string(e) + " does not contain the edge";
            }
        }
        return "";
    }

    // Labels of the faces around sample points (points on no edge or vertex).
    [[nodiscard]] std::vector<std::pair<Point, std::set<int>>> sample(const Dcel& d) const {
        std::vector<std::pair<Point, std::set<int>>> out;
        for (int i = -1; i <= 2 * kSampleGrid + 1; ++i) {
            for (int j = -1; j <= 2 * kSampleGrid + 1; ++j) {
                const Point p{i / 2.0 + 0.25, j / 2.0 + 0.125};  // off the grid lines and diagonals
                const Location l = locate_by_scan(d, p);
                if (l.kind == Location::Kind::Face) out.emplace_back(p, labels_[l.face]);
            }
        }
        return out;
    }

    [[nodiscard]] std::string labels_problem(const Dcel& d,
                                             const std::vector<std::pair<Point, std::set<int>>>& before) const {
        for (const auto& [p, had] : before) {
            const Location l = locate_by_scan(d, p);
            if (l.kind != Location::Kind::Face) continue;  // a new edge or vertex there
            const std::set<int>& now = labels_[l.face];
            if (!std::includes(now.begin(), now.end(), had.begin(), had.end())) {
                return "face data at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ") lost a label";
            }
        }
        return "";
    }

private:
    static constexpr int kSampleGrid = 6;

    static Span ends(const Dcel& d, EdgeId e) {
        const HalfEdgeId h = half_edge_of(e, 0);
        return {d.point(d.origin(h)), d.point(d.target(h))};
    }
    // The smallest segment holding two collinear segments.
    static Span hull(const Span& a, const Span& b) {
        Point lo = a.first;
        Point hi = a.first;
        for (const Point p : {a.first, a.second, b.first, b.second}) {
            if (lex_less(p, lo)) lo = p;
            if (lex_less(hi, p)) hi = p;
        }
        return {lo, hi};
    }

    VertexData<Point> where_;
    EdgeData<Span> span_;
    FaceData<std::set<int>> labels_;
};

}  // namespace dcel::props
