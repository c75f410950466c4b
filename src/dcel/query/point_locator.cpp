// PointLocator: a trapezoidal map and its search DAG, built by randomized
// incremental insertion (de Berg et al., "Computational Geometry", ch. 6).
//
// Points are ordered by lex order (x, then y): the symbolic shear of the
// book, so no two vertices share an "x" and a vertical edge is an ordinary
// steep segment. With that order a trapezoid's walls are single points (its
// leftp and rightp), and a query point that is not a vertex lies either
// inside a trapezoid or on a segment.
//
// Unlike the book we keep no neighbour pointers between trapezoids: the next
// trapezoid a new segment enters (past the vertex on the right wall of the
// current one) is found by searching the DAG again. Each insertion crosses
// O(1) trapezoids in expectation, so this keeps the O(E log E) expected
// construction and removes the most error-prone bookkeeping of the method.
#include <algorithm>
#include <numeric>
#include "dcel/contracts.hpp"

#include "dcel/geometry/predicates.hpp"
#include "dcel/point_locator.hpp"

namespace dcel {
namespace {

// SplitMix64: tiny, seedable, and the same on every platform.
std::uint64_t next_random(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31U);
}

}  // namespace

PointLocator::PointLocator(const Dcel& d, std::uint64_t seed) : points_(d.points()) {
    by_position_.resize(d.num_vertices());
    for (Index v = 0; v < d.num_vertices(); ++v) by_position_[v] = VertexId(v);
    std::sort(by_position_.begin(), by_position_.end(),
              [&](VertexId a, VertexId b) { return lex_less(point(a), point(b)); });

    segments_.reserve(d.num_edges());
    for (Index e = 0; e < d.num_edges(); ++e) {
        HalfEdgeId h = half_edge_of(EdgeId(e), 0);
        if (lex_less(d.point(d.target(h)), d.point(d.origin(h)))) h = Dcel::twin(h);
        segments_.push_back({d.origin(h), d.target(h), EdgeId(e), d.face(h), d.face(Dcel::twin(h))});
    }
    std::vector<Index> order(segments_.size());
    std::iota(order.begin(), order.end(), Index{0});
    std::uint64_t state = seed;
    for (std::size_t i = order.size(); i > 1; --i) {  // Fisher-Yates
        std::swap(order[i - 1], order[next_random(state) % i]);
    }

    trapezoids_.push_back(Trapezoid{});  // the whole plane
    trapezoids_[0].leaf = 0;
    nodes_.push_back(Node{NodeKind::Leaf, 0, kNoIndex, kNoIndex});
    for (const Index s : order) insert(s);

    face_of_trapezoid_.resize(trapezoids_.size());
    for (Index t = 0; t < trapezoids_.size(); ++t) face_of_trapezoid_[t] = face_of(trapezoids_[t]);
}

FaceId PointLocator::face_of(const Trapezoid& t) const {
    // A trapezoid lies just below its top segment and just above its bottom one.
    if (t.top != kNoIndex) return segments_[t.top].below;
    if (t.bottom != kNoIndex) return segments_[t.bottom].above;
    return Dcel::kUnboundedFace;
}

Index PointLocator::new_trapezoid(Index top, Index bottom, VertexId leftp, VertexId rightp) {
    trapezoids_.push_back(Trapezoid{top, bottom, leftp, rightp, kNoIndex});
    return static_cast<Index>(trapezoids_.size() - 1);
}

Index PointLocator::leaf_of(Index trapezoid) {
    if (trapezoids_[trapezoid].leaf == kNoIndex) {
        nodes_.push_back(Node{NodeKind::Leaf, trapezoid, kNoIndex, kNoIndex});
        trapezoids_[trapezoid].leaf = static_cast<Index>(nodes_.size() - 1);
    }
    return trapezoids_[trapezoid].leaf;
}

bool PointLocator::above(const Segment& s, const Segment& t) const {
    // Neither crosses the other and both span the place in question, so
    // comparing them at the later of the two left ends decides.
    if (s.left == t.left) return orient2d(point(t.left), point(t.right), point(s.right)) == Sign::Positive;
    if (lex_less(point(s.left), point(t.left))) {
        return orient2d(point(s.left), point(s.right), point(t.left)) == Sign::Negative;
    }
    return orient2d(point(t.left), point(t.right), point(s.left)) == Sign::Positive;
}

Index PointLocator::find_along(Index s, VertexId after) const {
    const Segment& seg = segments_[s];
    const Point r = point(after);
    Index n = 0;
    for (;;) {
        const Node& node = nodes_[n];
        switch (node.kind) {
            case NodeKind::Leaf: return node.item;
            case NodeKind::X: {
                // Just past `after`: right of it, and of everything not right of it.
                const VertexId x(node.item);
                n = (x != after && lex_less(r, point(x))) ? node.first : node.second;
                break;
            }
            case NodeKind::Y: n = above(seg, segments_[node.item]) ? node.first : node.second; break;
        }
    }
}

// One segment into the map: the trapezoids it crosses are cut along it,
// with new trapezoids beyond its ends where no wall stands there yet, and
// each crossed trapezoid's leaf becomes the subtree that tells the pieces
// apart.
void PointLocator::insert(Index s) {
    const Segment seg = segments_[s];
    const std::vector<Index> crossed = crossed_by(s);
    const Trapezoid first = trapezoids_[crossed.front()];
    const Trapezoid last = trapezoids_[crossed.back()];
    // The parts left of the left end and right of the right end, unless an
    // existing wall is there already.
    const Index left_part = first.leftp == seg.left ? kNoIndex
                                                    : new_trapezoid(first.top, first.bottom, first.leftp, seg.left);
    const Index right_part = last.rightp == seg.right ? kNoIndex
                                                      : new_trapezoid(last.top, last.bottom, seg.right, last.rightp);
    const Sides sides = cut_along(s, crossed);
    replace_leaves(s, crossed, sides, left_part, right_part);
}

std::vector<Index> PointLocator::crossed_by(Index s) const {
    const Segment& seg = segments_[s];
    std::vector<Index> crossed{find_along(s, seg.left)};
    while (!trapezoids_[crossed.back()].rightp.is_null() &&
           lex_less(point(trapezoids_[crossed.back()].rightp), point(seg.right))) {
        const VertexId wall = trapezoids_[crossed.back()].rightp;
        crossed.push_back(find_along(s, wall));
        // The wall reaches the segment, so the next trapezoid starts at it:
        // the walk always moves right.
        DCEL_ASSERT(trapezoids_[crossed.back()].leftp == wall);
    }
    return crossed;
}

// Above and below the segment: a wall at a crossed trapezoid's right vertex
// survives only on the side of the segment where that vertex is; on the
// other side the pieces merge across it.
PointLocator::Sides PointLocator::cut_along(Index s, const std::vector<Index>& crossed) {
    const Segment seg = segments_[s];
    const std::size_t k = crossed.size() - 1;
    Sides sides{std::vector<Index>(k + 1), std::vector<Index>(k + 1)};
    Index up = new_trapezoid(trapezoids_[crossed[0]].top, s, seg.left, {});
    Index down = new_trapezoid(s, trapezoids_[crossed[0]].bottom, seg.left, {});
    for (std::size_t j = 0; j <= k; ++j) {
        sides.upper[j] = up;
        sides.lower[j] = down;
        if (j == k) break;
        const VertexId wall = trapezoids_[crossed[j]].rightp;
        const Index next_top = trapezoids_[crossed[j + 1]].top;
        const Index next_bottom = trapezoids_[crossed[j + 1]].bottom;
        if (orient2d(point(seg.left), point(seg.right), point(wall)) == Sign::Positive) {
            trapezoids_[up].rightp = wall;
            up = new_trapezoid(next_top, s, wall, {});
        } else {
            trapezoids_[down].rightp = wall;
            down = new_trapezoid(s, next_bottom, wall, {});
        }
    }
    trapezoids_[up].rightp = seg.right;
    trapezoids_[down].rightp = seg.right;
    return sides;
}

// Each crossed trapezoid's leaf becomes a small subtree: a Y-node for the
// segment, under X-nodes for the ends that fall inside it. The old leaf's
// node is overwritten in place, so every parent now reaches the subtree.
void PointLocator::replace_leaves(Index s, const std::vector<Index>& crossed, const Sides& sides, Index left_part,
                                  Index right_part) {
    const Segment seg = segments_[s];
    const std::size_t k = crossed.size() - 1;
    for (std::size_t j = 0; j <= k; ++j) {
        const Index old_leaf = trapezoids_[crossed[j]].leaf;
        Node root{NodeKind::Y, s, leaf_of(sides.upper[j]), leaf_of(sides.lower[j])};
        if (j == k && right_part != kNoIndex) {
            nodes_.push_back(root);
            root = Node{NodeKind::X, seg.right.index(), static_cast<Index>(nodes_.size() - 1), leaf_of(right_part)};
        }
        if (j == 0 && left_part != kNoIndex) {
            nodes_.push_back(root);
            const auto inner = static_cast<Index>(nodes_.size() - 1);
            root = Node{NodeKind::X, seg.left.index(), leaf_of(left_part), inner};
        }
        nodes_[old_leaf] = root;
        trapezoids_[crossed[j]].leaf = kNoIndex;  // dead
    }
}

Location PointLocator::locate(Point p) const {
    const auto hit = std::lower_bound(by_position_.begin(), by_position_.end(), p,
                                      [&](VertexId v, Point q) { return lex_less(point(v), q); });
    if (hit != by_position_.end() && point(*hit) == p) return Location::at_vertex(*hit);
    Index n = 0;
    for (;;) {
        const Node& node = nodes_[n];
        switch (node.kind) {
            case NodeKind::Leaf: return Location::in_face(face_of_trapezoid_[node.item]);
            case NodeKind::X: n = lex_less(p, point(VertexId(node.item))) ? node.first : node.second; break;
            case NodeKind::Y: {
                const Segment& seg = segments_[node.item];
                const Sign side = orient2d(point(seg.left), point(seg.right), p);
                // A Y-node is reached only between its segment's ends, so on
                // its line means inside the edge.
                if (side == Sign::Zero) return Location::on_edge(seg.edge);
                n = side == Sign::Positive ? node.first : node.second;
                break;
            }
        }
    }
}

std::size_t PointLocator::depth() const {
    // Longest path from the root, by dynamic programming over the DAG in
    // reverse creation order is not valid (nodes are overwritten in place),
    // so use an explicit stack with memoisation.
    std::vector<std::size_t> memo(nodes_.size(), 0);
    std::vector<char> done(nodes_.size(), 0);
    std::vector<std::pair<Index, bool>> stack{{0, false}};
    while (!stack.empty()) {
        const auto [n, expanded] = stack.back();
        stack.pop_back();
        if (done[n] != 0) continue;
        const Node& node = nodes_[n];
        if (node.kind == NodeKind::Leaf) {
            memo[n] = 1;
            done[n] = 1;
            continue;
        }
        if (expanded) {
            memo[n] = 1 + std::max(memo[node.first], memo[node.second]);
            done[n] = 1;
            continue;
        }
        stack.push_back({n, true});
        if (done[node.first] == 0) stack.push_back({node.first, false});
        if (done[node.second] == 0) stack.push_back({node.second, false});
    }
    return memo[0];
}

}  // namespace dcel
