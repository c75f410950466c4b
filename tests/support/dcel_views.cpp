#include "support/dcel_views.hpp"

#include <algorithm>

namespace dcel::props {

std::vector<VertexCycle> dcel_cycles(const Dcel& d) {
    std::vector<VertexCycle> cycles;
    std::vector<char> seen(d.num_half_edges(), 0);
    for (Index i = 0; i < d.num_half_edges(); ++i) {
        if (seen[i] != 0) continue;
        VertexCycle c;
        for (const HalfEdgeId h : d.cycle(HalfEdgeId(i))) {
            seen[h.index()] = 1;
            c.push_back(d.origin(h).index());
        }
        cycles.push_back(canonical_cycle(std::move(c)));
    }
    std::sort(cycles.begin(), cycles.end());
    return cycles;
}

std::vector<testing::FaceShape> face_shapes_renamed(const Dcel& d, const std::vector<Index>& rename, bool reverse) {
    auto convert = [&](HalfEdgeId start) {
        testing::Cycle c;
        for (const HalfEdgeId h : d.cycle(start)) c.push_back(rename[d.origin(h).index()]);
        if (reverse) std::reverse(c.begin(), c.end());
        return c;
    };
    std::vector<testing::FaceShape> out;
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        testing::FaceShape s;
        if (!d.is_unbounded(f)) s.outer = convert(d.outer(f));
        for (const HalfEdgeId h : d.inner(f)) s.holes.push_back(convert(h));
        for (const VertexId v : d.isolated(f)) s.isolated.push_back(rename[v.index()]);
        out.push_back(testing::normalized(std::move(s)));
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<Point> cycle_points(const Dcel& d, HalfEdgeId start) {
    std::vector<Point> ring;
    for (const HalfEdgeId h : d.cycle(start)) ring.push_back(d.point(d.origin(h)));
    return ring;
}

}  // namespace dcel::props
