// The brute-force oracle for "is this a planar straight-line graph?": every
// pair of elements that could meet is compared in exact arithmetic
// (exact.hpp). It shares nothing with the library's checks or its sweep,
// and it reports every defect present, not just the first, because build()
// may meet any of them first.
//
// Two ways to pick the pairs, with the same answer: every pair (O(V E + E^2),
// obviously complete), or only the pairs whose bounding boxes meet, found by
// sorting on x (a box test is exact, since doubles compare exactly, and
// elements whose boxes are apart cannot meet). The second is what large
// inputs use; tests/test_oracles.cpp checks that the two agree.
#pragma once

#include <bitset>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "dcel/error.hpp"
#include "dcel/graph.hpp"
#include "oracles/exact.hpp"

namespace dcel::oracle {

enum class Defect {
    BadIndex,        // an edge names a vertex that does not exist
    BadCoordinate,   // NaN or infinite
    DuplicatePoint,  // two vertices at one point (-0.0 == 0.0)
    SelfLoop,        // an edge from a vertex to itself
    DuplicateEdge,   // two edges joining the same two vertices, either way round
    Crossing,        // two edges cross at a point inside both
    Touch,           // a vertex lies inside an edge
    Overlap,         // two collinear edges share more than a point
    Count
};
using DefectKinds = std::bitset<static_cast<std::size_t>(Defect::Count)>;

struct Defects {
    std::vector<Index> bad_coordinates;                     // vertices
    std::vector<Index> bad_indexes;                         // edges
    std::vector<Index> self_loops;                          // edges
    std::vector<std::pair<Index, Index>> duplicate_points;  // (vertex, a later vertex at the same point)
    std::vector<std::pair<Index, Index>> duplicate_edges;   // (edge, a later edge joining the same vertices)
    struct EdgePair {
        Index e1, e2;  // e1 < e2
        Meeting how;   // Crossing, Touch, Overlap or Same (ends at duplicate points)
        friend bool operator==(const EdgePair&, const EdgePair&) = default;
    };
    std::vector<EdgePair> edge_pairs;                     // sorted
    std::vector<std::pair<Index, Index>> vertex_in_edge;  // (vertex, edge), sorted

    [[nodiscard]] bool empty() const;
    // The kinds present. Collinear edges that share more than a point
    // (Overlap or Same) count as an overlap.
    [[nodiscard]] DefectKinds kinds() const;
    friend bool operator==(const Defects&, const Defects&) = default;
};

enum class PairSearch { AllPairs, BoundingBoxes };

// Segments take part in the geometry when both ends exist, are finite and
// are at two different points.
[[nodiscard]] Defects find_defects(const PlanarGraph& g, PairSearch search = PairSearch::BoundingBoxes);

[[nodiscard]] inline bool has(const DefectKinds& d, Defect k) { return d.test(static_cast<std::size_t>(k)); }
[[nodiscard]] std::string describe(const DefectKinds& d);  // "crossing touch", or "none"

// The defect an InvalidInput kind from build() stands for; Count for kinds
// build() never reports on a graph (Syntax, Shape, TooLarge).
[[nodiscard]] Defect defect_of(InputErrorKind kind);

}  // namespace dcel::oracle
