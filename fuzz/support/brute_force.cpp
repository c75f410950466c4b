#include "support/brute_force.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "support/exact_points.hpp"

namespace dcel::fuzz {
namespace {

constexpr const char* kNames[] = {"bad-index",      "bad-coordinate", "duplicate-point", "self-loop",
                                  "duplicate-edge", "crossing",       "touch",           "overlap"};

void set(Defects& d, Defect k) { d.set(static_cast<std::size_t>(k)); }

// Collinear segments ab and cd (a != b, c != d): do they share more than a
// point? Compare their extents along an axis on which ab is not constant.
bool collinear_overlap(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c, const ExactPoint& d) {
    const bool use_x = a.x != b.x;
    const BigInt& a1 = use_x ? a.x : a.y;
    const BigInt& b1 = use_x ? b.x : b.y;
    const BigInt& c1 = use_x ? c.x : c.y;
    const BigInt& d1 = use_x ? d.x : d.y;
    const BigInt lo = std::max(std::min(a1, b1), std::min(c1, d1));
    const BigInt hi = std::min(std::max(a1, b1), std::max(c1, d1));
    return lo < hi;
}

}  // namespace

std::string describe(const Defects& d) {
    std::string s;
    for (std::size_t k = 0; k < d.size(); ++k) {
        if (d.test(k)) s += (s.empty() ? "" : " ") + std::string(kNames[k]);
    }
    return s.empty() ? "none" : s;
}

Defect defect_of(InputErrorKind kind) {
    switch (kind) {
        case InputErrorKind::BadIndex: return Defect::BadIndex;
        case InputErrorKind::BadCoordinate: return Defect::BadCoordinate;
        case InputErrorKind::DuplicatePoint: return Defect::DuplicatePoint;
        case InputErrorKind::SelfLoop: return Defect::SelfLoop;
        case InputErrorKind::DuplicateEdge: return Defect::DuplicateEdge;
        case InputErrorKind::Crossing: return Defect::Crossing;
        case InputErrorKind::VertexOnEdge: return Defect::Touch;
        case InputErrorKind::Overlap: return Defect::Overlap;
        case InputErrorKind::Syntax:
        case InputErrorKind::Shape:
        case InputErrorKind::TooLarge: break;
    }
    return Defect::Count;
}

Defects find_defects(const PlanarGraph& g) {
    Defects found;
    const std::size_t n = g.vertices.size();

    // Coordinates: geometry below only involves finite vertices.
    std::vector<char> finite(n, 1);
    std::vector<Point> usable;
    for (std::size_t v = 0; v < n; ++v) {
        const Point p = g.vertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            finite[v] = 0;
            set(found, Defect::BadCoordinate);
            usable.push_back({0, 0});  // placeholder, never used
        } else {
            usable.push_back(p);
        }
    }
    const std::vector<ExactPoint> pt = exact_points(usable);

    for (std::size_t a = 0; a < n; ++a) {
        for (std::size_t b = a + 1; b < n; ++b) {
            if (finite[a] && finite[b] && pt[a] == pt[b]) set(found, Defect::DuplicatePoint);
        }
    }

    // Edges whose ends exist, are finite and distinct take part in geometry.
    std::vector<std::pair<Index, Index>> keys;  // every existing non-loop edge, as (min, max)
    std::vector<std::pair<std::size_t, std::size_t>> segments;
    for (const GraphEdge& e : g.edges) {
        if (e.u == e.v) set(found, Defect::SelfLoop);  // whether or not the index exists
        if (e.u.index() >= n || e.v.index() >= n) {
            set(found, Defect::BadIndex);
            continue;
        }
        if (e.u == e.v) continue;
        const std::pair<Index, Index> key{std::min(e.u.index(), e.v.index()), std::max(e.u.index(), e.v.index())};
        if (std::find(keys.begin(), keys.end(), key) != keys.end()) set(found, Defect::DuplicateEdge);
        keys.push_back(key);
        if (finite[e.u.index()] && finite[e.v.index()]) segments.emplace_back(e.u.index(), e.v.index());
    }

    for (const auto& [u, v] : segments) {
        if (pt[u] == pt[v]) continue;  // duplicate points, reported above
        for (std::size_t p = 0; p < n; ++p) {
            if (finite[p] && strictly_between(pt[u], pt[v], pt[p])) set(found, Defect::Touch);
        }
    }
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const ExactPoint& a = pt[segments[i].first];
        const ExactPoint& b = pt[segments[i].second];
        if (a == b) continue;
        for (std::size_t j = i + 1; j < segments.size(); ++j) {
            const ExactPoint& c = pt[segments[j].first];
            const ExactPoint& d = pt[segments[j].second];
            if (c == d) continue;
            const int o1 = orientation(a, b, c);
            const int o2 = orientation(a, b, d);
            const int o3 = orientation(c, d, a);
            const int o4 = orientation(c, d, b);
            if (o1 == 0 && o2 == 0) {
                if (collinear_overlap(a, b, c, d)) set(found, Defect::Overlap);
            } else if (o1 * o2 < 0 && o3 * o4 < 0) {
                set(found, Defect::Crossing);
            }
            // Any other contact puts an endpoint on the other segment: a
            // touch (found above) or a shared endpoint (allowed).
        }
    }
    return found;
}

}  // namespace dcel::fuzz
