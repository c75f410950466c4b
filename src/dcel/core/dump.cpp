#include "dcel/dump.hpp"

namespace dcel {

DcelDump to_dump(const Dcel& d) {
    DcelDump out;
    out.vertices = d.points();
    out.vertex_out.reserve(d.num_vertices());
    for (Index v = 0; v < d.num_vertices(); ++v) out.vertex_out.push_back(d.out(VertexId(v)));
    out.half_edges.reserve(d.num_half_edges());
    for (Index i = 0; i < d.num_half_edges(); ++i) {
        const HalfEdgeId h(i);
        out.half_edges.push_back({d.origin(h), Dcel::twin(h), d.next(h), d.prev(h), d.face(h)});
    }
    out.faces.reserve(d.num_faces());
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        out.faces.push_back({d.outer(f), d.inner(f), d.isolated(f)});
    }
    return out;
}

}  // namespace dcel
