#include "dcel/edit/edit_checks.hpp"

#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/geometry/segments.hpp"

namespace dcel::detail {

std::string describe(const Dcel& d, VertexId v) {
    std::string s = v.str();
    s.append(" ").append(format_point(d.point(v)));
    return s;
}

std::string describe(const Dcel& d, EdgeId e) {
    const HalfEdgeId h = half_edge_of(e, 0);
    std::string s = e.str();
    s.append(" [").append(describe(d, d.origin(h))).append(", ").append(describe(d, d.target(h))).append("]");
    return s;
}

void refuse(std::string_view edit, const std::string& reason) {
    std::string s(edit);
    s.append(": ").append(reason);
    throw TopologyError(s);
}

void require_vertex(const Dcel& d, VertexId v, std::string_view edit) {
    if (v.is_null() || v.index() >= d.num_vertices()) {
        std::string s(edit);
        s.append(": there is no vertex ").append(v.str()).append(" (the DCEL has ");
        s.append(std::to_string(d.num_vertices())).append(" vertices)");
        throw InvalidInput(InputErrorKind::BadIndex, s, {v});
    }
}

void require_edge(const Dcel& d, EdgeId e, std::string_view edit) {
    if (e.is_null() || e.index() >= d.num_edges()) {
        std::string s(edit);
        s.append(": there is no edge ").append(e.str()).append(" (the DCEL has ");
        s.append(std::to_string(d.num_edges())).append(" edges)");
        throw InvalidInput(InputErrorKind::BadIndex, s, {}, {e});
    }
}

void require_point_free(const Dcel& d, Point p, std::string_view edit) {
    for (Index v = 0; v < d.num_vertices(); ++v) {
        if (d.point(VertexId(v)) == p) {
            refuse(edit, "the point " + format_point(p) + " is vertex " + describe(d, VertexId(v)) + " already");
        }
    }
    for (Index e = 0; e < d.num_edges(); ++e) {
        const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
        if (strictly_inside_segment(d.point(d.origin(h)), d.point(d.target(h)), p)) {
            refuse(edit, "the point " + format_point(p) + " lies inside edge " + describe(d, EdgeId(e)) +
                             "; split that edge there first (split_edge)");
        }
    }
}

void require_segment_clear(const Dcel& d, VertexId u, Point to, VertexId v, std::string_view edit) {
    const Point from = d.point(u);
    auto segment = [&] { return "the segment from " + format_point(from) + " to " + format_point(to); };
    for (Index i = 0; i < d.num_edges(); ++i) {
        const EdgeId e(i);
        const HalfEdgeId h = half_edge_of(e, 0);
        const Point a = d.point(d.origin(h));
        const Point b = d.point(d.target(h));
        switch (segment_contact(from, to, a, b)) {
            case Contact::None:
            case Contact::SharedEndpoint: break;
            case Contact::Crossing: refuse(edit, segment() + " crosses edge " + describe(d, e));
            case Contact::Overlap: refuse(edit, segment() + " overlaps edge " + describe(d, e));
            case Contact::Touch: {
                const VertexId w = strictly_inside_segment(from, to, a) ? d.origin(h) : d.target(h);
                if (strictly_inside_segment(from, to, d.point(w))) {
                    refuse(edit, segment() + " passes through vertex " + describe(d, w));
                }
                refuse(edit, segment() + " ends inside edge " + describe(d, e));
            }
        }
    }
    for (Index i = 0; i < d.num_vertices(); ++i) {
        const VertexId w(i);
        if (w == u || w == v || !d.out(w).is_null()) continue;  // vertices with edges: checked above
        if (strictly_inside_segment(from, to, d.point(w))) {
            refuse(edit, segment() + " passes through isolated vertex " + describe(d, w));
        }
    }
}

}  // namespace dcel::detail
