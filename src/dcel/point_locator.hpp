// PointLocator: a trapezoidal map with its search DAG (de Berg et al., ch. 6),
// built by randomized incremental insertion in O(E log E) expected time and
// O(E) expected memory; each query then takes O(log E) expected time (plus
// O(log V) for the vertex check). Ties in x are broken by y (the symbolic
// shear x' = x + eps * y, i.e. lex order), so vertical edges and shared
// x-coordinates need no special cases. The shuffle uses its own seeded
// generator: the same seed gives the same structure everywhere. A
// PointLocator is a snapshot: it copies what it needs and does not see later
// edits of the DCEL; build a new one after editing. Implemented in
// query/point_locator.cpp; the O(V + E) scan is locate_by_scan (locate.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/location.hpp"

namespace dcel {

class PointLocator {
public:
    static constexpr std::uint64_t kDefaultSeed = 0x5eed'dce1'0000'0001ULL;

    explicit PointLocator(const Dcel& d, std::uint64_t seed = kDefaultSeed);

    // O(log E) expected. Requires finite coordinates.
    [[nodiscard]] Location locate(Point p) const;

    // For measurements: nodes in the search DAG, and its depth (longest path).
    [[nodiscard]] std::size_t num_nodes() const { return nodes_.size(); }
    [[nodiscard]] std::size_t depth() const;

private:
    struct Segment {
        VertexId left;   // lex-smaller end
        VertexId right;  // lex-larger end
        EdgeId edge;
        FaceId above;  // the face on the left of left -> right
        FaceId below;
    };
    struct Trapezoid {
        Index top = kNoIndex;     // segment, or kNoIndex: unbounded above
        Index bottom = kNoIndex;  // segment, or kNoIndex: unbounded below
        VertexId leftp;           // the vertex on its left wall, or null: unbounded
        VertexId rightp;
        Index leaf = kNoIndex;  // its leaf node in the DAG
    };
    enum class NodeKind : unsigned char { X, Y, Leaf };
    struct Node {
        NodeKind kind = NodeKind::Leaf;
        Index item = 0;           // X: vertex index; Y: segment; Leaf: trapezoid
        Index first = kNoIndex;   // X: left child; Y: child above
        Index second = kNoIndex;  // X: right child; Y: child below
    };

    // The trapezoids just above and just below a new segment, one of each
    // per trapezoid it crosses (neighbours may share one).
    struct Sides {
        std::vector<Index> upper;
        std::vector<Index> lower;
    };

    [[nodiscard]] Point point(VertexId v) const { return points_[v.index()]; }
    void insert(Index s);
    // The steps of insert: the trapezoids segment s crosses, left to right;
    // the new ones above and below it; the DAG's leaves replaced.
    [[nodiscard]] std::vector<Index> crossed_by(Index s) const;
    [[nodiscard]] Sides cut_along(Index s, const std::vector<Index>& crossed);
    void replace_leaves(Index s, const std::vector<Index>& crossed, const Sides& sides, Index left_part, Index right_part);
    // The trapezoid that segment s enters just after passing the vertex `after`.
    [[nodiscard]] Index find_along(Index s, VertexId after) const;
    // Is segment s above segment t just to the right of the point `after`,
    // where both span it?
    [[nodiscard]] bool above(const Segment& s, const Segment& t) const;
    [[nodiscard]] Index new_trapezoid(Index top, Index bottom, VertexId leftp, VertexId rightp);
    [[nodiscard]] Index leaf_of(Index trapezoid);
    [[nodiscard]] FaceId face_of(const Trapezoid& t) const;

    std::vector<Point> points_;          // by vertex id
    std::vector<VertexId> by_position_;  // all vertices in lex order, for vertex hits
    std::vector<Segment> segments_;
    std::vector<Trapezoid> trapezoids_;      // some are dead (replaced); only leaves matter
    std::vector<Node> nodes_;                // nodes_[0] is the root
    std::vector<FaceId> face_of_trapezoid_;  // filled once the map is complete
};

}  // namespace dcel
