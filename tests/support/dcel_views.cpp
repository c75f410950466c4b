#include "support/dcel_views.hpp"

#include <algorithm>

namespace dcel::test_support {

std::vector<oracle::Cycle> dcel_cycles(const Dcel& d) {
    std::vector<oracle::Cycle> cycles;
    std::vector<char> seen(d.num_half_edges(), 0);
    for (Index i = 0; i < d.num_half_edges(); ++i) {
        if (seen[i] != 0) continue;
        oracle::Cycle c;
        for (const HalfEdgeId h : d.cycle(HalfEdgeId(i))) {
            seen[h.index()] = 1;
            c.push_back(d.origin(h).index());
        }
        cycles.push_back(oracle::canonical(c));
    }
    std::sort(cycles.begin(), cycles.end());
    return cycles;
}

std::vector<oracle::FaceShape> face_shapes_renamed(const Dcel& d, const std::vector<Index>& rename, bool reverse) {
    auto convert = [&](HalfEdgeId start) {
        oracle::Cycle c;
        for (const HalfEdgeId h : d.cycle(start)) c.push_back(rename[d.origin(h).index()]);
        if (reverse) std::reverse(c.begin(), c.end());
        return c;
    };
    std::vector<oracle::FaceShape> out;
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        oracle::FaceShape s;
        if (!d.is_unbounded(f)) s.outer = convert(d.outer(f));
        for (const HalfEdgeId h : d.inner(f)) s.holes.push_back(convert(h));
        for (const VertexId v : d.isolated(f)) s.isolated.push_back(rename[v.index()]);
        out.push_back(s);
    }
    return oracle::sorted_shapes(std::move(out));
}

std::vector<Point> cycle_points(const Dcel& d, HalfEdgeId start) {
    std::vector<Point> ring;
    for (const HalfEdgeId h : d.cycle(start)) ring.push_back(d.point(d.origin(h)));
    return ring;
}

}  // namespace dcel::test_support
