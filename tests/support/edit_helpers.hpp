// Test support for the edit, locate and stab tests: small builders and the
// bundled countries map, with its ids spelled out once.
#pragma once

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/dump.hpp"
#include "rebuild_compare.hpp"

namespace dcel::test_support {

inline PlanarGraph graph(std::vector<Point> points, const std::vector<std::pair<Index, Index>>& edges) {
    PlanarGraph g;
    g.vertices = std::move(points);
    for (const auto& [u, v] : edges) g.edges.push_back({VertexId(u), VertexId(v)});
    return g;
}

// examples/map/countries.json: West (f1) = 0 1 4 5 with the capital v10
// inside; East (f2) = 1 2 3 4 holding the Enclave (f3) = 6 7 8 9. Face ids as
// build() numbers them (by the smallest half-edge of each face's outer cycle).
inline PlanarGraph countries() {
    return graph({{0, 0}, {4, 0}, {8, 0}, {8, 6}, {4, 6}, {0, 6}, {5, 2}, {7, 2}, {7, 4}, {5, 4}, {2, 3}},
                 {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {1, 4}, {6, 7}, {7, 8}, {8, 9}, {9, 6}});
}
inline constexpr FaceId kWest{1};
inline constexpr FaceId kEast{2};
inline constexpr FaceId kEnclave{3};

// The half-edge u -> v, or null.
inline HalfEdgeId half_edge(const Dcel& d, Index u, Index v) {
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        if (d.origin(HalfEdgeId(h)) == VertexId(u) && d.target(HalfEdgeId(h)) == VertexId(v)) return HalfEdgeId(h);
    }
    return {};
}

}  // namespace dcel::test_support

// validate() passes and the DCEL equals the rebuild of its graph.
#define EXPECT_SOUND(d)                                                   \
    do {                                                                  \
        const auto problem_ = ::dcel::test_support::soundness_problem(d); \
        EXPECT_FALSE(problem_.has_value()) << *problem_;                  \
    } while (false)

// The statement throws the exception type and leaves d exactly as it was.
#define EXPECT_REFUSED_UNCHANGED(d, statement, exception, text)                                              \
    do {                                                                                                     \
        const ::dcel::DcelDump before_ = ::dcel::to_dump(d);                                                 \
        try {                                                                                                \
            (void)(statement);                                                                               \
            ADD_FAILURE() << "not refused: " #statement;                                                     \
        } catch (const exception& e_) {                                                                      \
            EXPECT_NE(std::string(e_.what()).find(text), std::string::npos) << e_.what();                    \
            EXPECT_EQ(std::string(e_.what()).find('\n'), std::string::npos) << e_.what();                    \
        }                                                                                                    \
        EXPECT_TRUE(::dcel::test_support::same_dump(before_, ::dcel::to_dump(d))) << "changed: " #statement; \
    } while (false)
