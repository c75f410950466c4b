#include "dcel/query/rotation.hpp"

namespace dcel::detail {

HalfEdgeId outgoing_in_direction(const Dcel& d, VertexId v, const Direction& dir) {
    const HalfEdgeId start = d.out(v);
    if (start.is_null()) return {};
    for (const HalfEdgeId h : d.around_origin_cw(start)) {
        if (compare_direction(d.point(v), d.point(d.target(h)), dir.from, dir.to) == Sign::Zero) return h;
    }
    return {};
}

HalfEdgeId wedge_after(const Dcel& d, VertexId v, const Direction& dir) {
    const Point c = d.point(v);
    for (const HalfEdgeId r : d.around_origin_cw(d.out(v))) {
        const HalfEdgeId s = d.next(Dcel::twin(r));  // clockwise of r
        if (strictly_between_ccw({c, d.point(d.target(s))}, dir, {c, d.point(d.target(r))})) return r;
    }
    return {};  // only when some edge takes dir, or the rotation is broken
}

}  // namespace dcel::detail
