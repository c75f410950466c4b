// Contracts (dcel/contracts.hpp): in a build that checks them (Debug,
// sanitizers, fuzzing, or DCEL_CONTRACTS=ALL), an id that names nothing stops
// the program at the accessor that received it, with a message naming the
// condition. Elsewhere the checks compile to nothing and these tests skip.
#include <gtest/gtest.h>

#include "dcel/build.hpp"
#include "dcel/contracts.hpp"

namespace dcel {
namespace {

Dcel triangle() {
    return build(PlanarGraph{{{0, 0}, {1, 0}, {0, 1}},
                             {{VertexId(0), VertexId(1)}, {VertexId(1), VertexId(2)}, {VertexId(2), VertexId(0)}}});
}

TEST(Contracts, AHalfEdgeIdOutOfRangeStopsAtTheAccessor) {
    if (DCEL_CONTRACT_LEVEL < 1) GTEST_SKIP() << "contracts are off in this build (DCEL_CONTRACT_LEVEL 0)";
    const Dcel d = triangle();
    EXPECT_DEATH((void)d.next(HalfEdgeId(6)), "precondition failed at .*dcel.hpp:[0-9]+: h.index\\(\\) < next_.size\\(\\)");
    EXPECT_DEATH((void)d.origin(HalfEdgeId()), "precondition failed");
}

TEST(Contracts, AVertexOrFaceIdOutOfRangeStopsAtTheAccessor) {
    if (DCEL_CONTRACT_LEVEL < 1) GTEST_SKIP() << "contracts are off in this build (DCEL_CONTRACT_LEVEL 0)";
    const Dcel d = triangle();
    EXPECT_DEATH((void)d.point(VertexId(3)), "v.index\\(\\) < points_.size\\(\\)");
    EXPECT_DEATH((void)d.outer(FaceId(2)), "f.index\\(\\) < faces_.size\\(\\)");
}

TEST(Contracts, ValidIdsPassInEveryBuild) {
    const Dcel d = triangle();
    for (Index h = 0; h < d.num_half_edges(); ++h) EXPECT_EQ(d.next(d.prev(HalfEdgeId(h))), HalfEdgeId(h));
    EXPECT_TRUE(d.outer(FaceId(1)).index() < d.num_half_edges());
}

}  // namespace
}  // namespace dcel
