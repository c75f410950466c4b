#include "support/face_locator.hpp"

#include <algorithm>

#include "support/dcel_views.hpp"

namespace dcel::props {

FaceLocator::FaceLocator(const Dcel& d, const std::vector<Index>& component) {
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        if (d.is_unbounded(f)) continue;
        OuterRing r{f, component[d.origin(d.outer(f)).index()], cycle_points(d, d.outer(f)), 0, 0, 0, 0, 0};
        r.twice_area = twice_area(r.ring);
        const auto [xl, xh] = std::minmax_element(r.ring.begin(), r.ring.end(), [](Point a, Point b) { return a.x < b.x; });
        const auto [yl, yh] = std::minmax_element(r.ring.begin(), r.ring.end(), [](Point a, Point b) { return a.y < b.y; });
        r.x0 = xl->x, r.x1 = xh->x, r.y0 = yl->y, r.y1 = yh->y;
        rings_.push_back(std::move(r));
    }
}

FaceId FaceLocator::face_containing(Point p, Index component) const {
    const OuterRing* best = nullptr;
    for (const OuterRing& r : rings_) {
        if (r.component == component || p.x < r.x0 || p.x > r.x1 || p.y < r.y0 || p.y > r.y1) continue;
        if (!strictly_inside(p, r.ring)) continue;
        if (best == nullptr || r.twice_area < best->twice_area) best = &r;
    }
    return best == nullptr ? Dcel::kUnboundedFace : best->face;
}

}  // namespace dcel::props
