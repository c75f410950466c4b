// A textbook faces solver, with the textbook bug left in so that the harness
// has something to find: each vertex's edges are sorted by std::atan2 of the
// coordinate differences. Directions about 1e-17 rad apart (points near
// (268947842, 268947843) and (268947845, 268947846) seen from the origin) get
// the same angle and sort in either order, so next goes to the wrong edge.
// An exact angular order (half-planes, then the sign of a cross product in
// exact arithmetic) has no such inputs.
#include "my_dcel.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace my_dcel {

std::vector<std::vector<int>> faces(const std::vector<Point>& points, const std::vector<Edge>& edges) {
    // Half-edge 2k runs u->v along edge k, 2k+1 runs v->u.
    const int halves = static_cast<int>(2 * edges.size());
    auto origin = [&](int h) { return (h % 2 == 0) ? edges[h / 2].u : edges[h / 2].v; };
    auto angle = [&](int h) {
        const Point a = points[origin(h)], b = points[origin(h ^ 1)];
        return std::atan2(b.y - a.y, b.x - a.x);
    };
    std::vector<std::vector<int>> around(points.size());
    for (int h = 0; h < halves; ++h) around[origin(h)].push_back(h);
    std::vector<int> position(halves);
    for (auto& ring : around) {
        std::sort(ring.begin(), ring.end(), [&](int a, int b) { return angle(a) < angle(b); });  // counterclockwise
        for (std::size_t i = 0; i < ring.size(); ++i) position[ring[i]] = static_cast<int>(i);
    }
    auto next = [&](int h) {  // clockwise after the twin: one step back in counterclockwise order
        const auto& ring = around[origin(h ^ 1)];
        return ring[(position[h ^ 1] + ring.size() - 1) % ring.size()];
    };
    std::vector<std::vector<int>> out;
    std::vector<bool> seen(halves, false);
    for (int h = 0; h < halves; ++h) {
        if (seen[h]) continue;
        auto& cycle = out.emplace_back();
        for (int x = h; !seen[x]; x = next(x)) {
            seen[x] = true;
            cycle.push_back(origin(x));
        }
    }
    return out;
}

}  // namespace my_dcel
