#include "oracles/brute_force.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace dcel::oracle {
namespace {

constexpr const char* kNames[] = {"bad-index",      "bad-coordinate", "duplicate-point", "self-loop",
                                  "duplicate-edge", "crossing",       "touch",           "overlap"};

struct Segment {
    Index edge;
    Index u, v;  // the end vertices
    Point a, b;
    double x0, x1, y0, y1;  // bounding box
};

bool boxes_meet(const Segment& s, const Segment& t) { return s.x0 <= t.x1 && t.x0 <= s.x1 && s.y0 <= t.y1 && t.y0 <= s.y1; }

// Two segments with one end vertex w in common, w-x and w-y, meet only at
// w unless x, w and y are collinear: then one orientation settles most
// pairs of a graph's neighbouring edges.
bool apart_but_for_shared_end(const ExactPoints& geometry, const Segment& s, const Segment& t) {
    const bool shares_u = s.u == t.u || s.u == t.v, shares_v = s.v == t.u || s.v == t.v;
    if (shares_u == shares_v) return false;  // none, or the same two vertices
    const Index w = shares_u ? s.u : s.v, x = shares_u ? s.v : s.u;
    const Index y = t.u == w ? t.v : t.u;
    return geometry.orientation(w, x, y) != 0;
}

void check_pair(const ExactPoints& geometry, const Segment& s, const Segment& t, Defects& out) {
    if (apart_but_for_shared_end(geometry, s, t)) return;
    const Meeting m = geometry.meeting(s.u, s.v, t.u, t.v);
    if (m != Meeting::None && m != Meeting::SharedEndpoint) {
        out.edge_pairs.push_back({std::min(s.edge, t.edge), std::max(s.edge, t.edge), m});
    }
}

// Every pair of segments, every vertex against every segment.
void all_pairs(const ExactPoints& geometry, const std::vector<Segment>& segments, const std::vector<Index>& vertices,
               Defects& out) {
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Segment& s = segments[i];
        for (std::size_t j = i + 1; j < segments.size(); ++j) check_pair(geometry, s, segments[j], out);
        for (const Index v : vertices) {
            if (geometry.strictly_on_segment(s.u, s.v, v)) out.vertex_in_edge.emplace_back(v, s.edge);
        }
    }
}

// Only the pairs whose bounding boxes meet: segments in order of their left
// ends, each against those that start before it ends; vertices in order of
// x, each segment against those within its x range.
void box_pairs(const ExactPoints& geometry, std::vector<Segment> segments, std::vector<Index> vertices, const PlanarGraph& g,
               Defects& out) {
    std::sort(segments.begin(), segments.end(), [](const Segment& s, const Segment& t) { return s.x0 < t.x0; });
    for (std::size_t i = 0; i < segments.size(); ++i) {
        for (std::size_t j = i + 1; j < segments.size() && segments[j].x0 <= segments[i].x1; ++j) {
            if (boxes_meet(segments[i], segments[j])) check_pair(geometry, segments[i], segments[j], out);
        }
    }
    auto x_of = [&](Index v) { return g.vertices[v].x; };
    std::sort(vertices.begin(), vertices.end(), [&](Index a, Index b) { return x_of(a) < x_of(b); });
    for (const Segment& s : segments) {
        auto it = std::lower_bound(vertices.begin(), vertices.end(), s.x0, [&](Index v, double x) { return x_of(v) < x; });
        for (; it != vertices.end() && x_of(*it) <= s.x1; ++it) {
            const Point p = g.vertices[*it];
            if (s.y0 <= p.y && p.y <= s.y1 && geometry.strictly_on_segment(s.u, s.v, *it)) {
                out.vertex_in_edge.emplace_back(*it, s.edge);
            }
        }
    }
}

// Of ids keyed by value: each id whose key an earlier id has, paired with
// the first id of that key, in order of the later id. (Sorting, not a map:
// fewer allocations.)
template <class Key>
std::vector<std::pair<Index, Index>> repeats(std::vector<std::pair<Key, Index>> keyed) {
    std::sort(keyed.begin(), keyed.end());  // by key (-0.0 and 0.0 alike), then by id
    std::vector<std::pair<Index, Index>> out;
    for (std::size_t i = 1, first = 0; i < keyed.size(); ++i) {
        if (keyed[i].first == keyed[first].first) {
            out.emplace_back(keyed[first].second, keyed[i].second);
        } else {
            first = i;
        }
    }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    return out;
}

}  // namespace

bool Defects::empty() const {
    return bad_coordinates.empty() && bad_indexes.empty() && self_loops.empty() && duplicate_points.empty() &&
           duplicate_edges.empty() && edge_pairs.empty() && vertex_in_edge.empty();
}

DefectKinds Defects::kinds() const {
    DefectKinds k;
    auto set = [&](Defect d) { k.set(static_cast<std::size_t>(d)); };
    if (!bad_indexes.empty()) set(Defect::BadIndex);
    if (!bad_coordinates.empty()) set(Defect::BadCoordinate);
    if (!duplicate_points.empty()) set(Defect::DuplicatePoint);
    if (!self_loops.empty()) set(Defect::SelfLoop);
    if (!duplicate_edges.empty()) set(Defect::DuplicateEdge);
    if (!vertex_in_edge.empty()) set(Defect::Touch);
    for (const EdgePair& p : edge_pairs) {
        if (p.how == Meeting::Crossing) set(Defect::Crossing);
        if (p.how == Meeting::Touch) set(Defect::Touch);
        if (p.how == Meeting::Overlap || p.how == Meeting::Same) set(Defect::Overlap);
    }
    return k;
}

Defects find_defects(const PlanarGraph& g, PairSearch search) {
    Defects out;
    const std::size_t n = g.vertices.size();
    std::vector<char> finite(n, 1);
    std::vector<Index> usable;  // vertices with finite coordinates
    std::vector<std::pair<std::pair<double, double>, Index>> at;
    for (Index v = 0; v < n; ++v) {
        const Point p = g.vertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            finite[v] = 0;
            out.bad_coordinates.push_back(v);
            continue;
        }
        usable.push_back(v);
        at.push_back({{p.x, p.y}, v});
    }
    out.duplicate_points = repeats(std::move(at));

    std::vector<std::pair<std::pair<Index, Index>, Index>> joined;
    std::vector<Segment> segments;
    for (Index k = 0; k < g.edges.size(); ++k) {
        const Index u = g.edges[k].u.index(), v = g.edges[k].v.index();
        if (u == v) out.self_loops.push_back(k);  // whether or not the index exists
        if (u >= n || v >= n) out.bad_indexes.push_back(k);
        if (u == v || u >= n || v >= n) continue;
        joined.push_back({{std::min(u, v), std::max(u, v)}, k});
        const Point a = g.vertices[u], b = g.vertices[v];
        if (finite[u] == 0 || finite[v] == 0 || a == b) continue;
        segments.push_back({k, u, v, a, b, std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)});
    }

    out.duplicate_edges = repeats(std::move(joined));
    const ExactPoints geometry(g.vertices);
    if (search == PairSearch::AllPairs) {
        all_pairs(geometry, segments, usable, out);
    } else {
        box_pairs(geometry, std::move(segments), std::move(usable), g, out);
    }
    std::sort(out.edge_pairs.begin(), out.edge_pairs.end(), [](const Defects::EdgePair& p, const Defects::EdgePair& q) {
        return std::tie(p.e1, p.e2) < std::tie(q.e1, q.e2);
    });
    std::sort(out.vertex_in_edge.begin(), out.vertex_in_edge.end());
    return out;
}

std::string describe(const DefectKinds& d) {
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

}  // namespace dcel::oracle
