#include "oracles/nested_rings.hpp"

#include <algorithm>

namespace dcel::oracle {

void NestedRings::add(std::vector<Point> ring, Index label, Index group) {
    Rational area = twice_area(ring);
    add(std::move(ring), label, group, std::move(area));
}

void NestedRings::add(std::vector<Point> ring, Index label, Index group, Rational area) {
    const auto [xl, xh] = std::minmax_element(ring.begin(), ring.end(), [](Point a, Point b) { return a.x < b.x; });
    const auto [yl, yh] = std::minmax_element(ring.begin(), ring.end(), [](Point a, Point b) { return a.y < b.y; });
    const double x0 = xl->x, x1 = xh->x, y0 = yl->y, y1 = yh->y;
    rings_.push_back({std::move(ring), label, group, std::move(area), x0, x1, y0, y1});
}

Index NestedRings::innermost_around(Point p, Index skip_group) const {
    const Ring* best = nullptr;
    for (const Ring& r : rings_) {
        if (r.group == skip_group || p.x < r.x0 || p.x > r.x1 || p.y < r.y0 || p.y > r.y1) continue;
        if (winding_number(p, r.points) == 0) continue;
        if (best == nullptr || r.twice_area < best->twice_area) best = &r;
    }
    return best == nullptr ? kNoIndex : best->label;
}

}  // namespace dcel::oracle
