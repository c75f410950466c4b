// User data follows the edits: the countries of the bundled map keep their
// names through splits, merges and renumbering. Expected names are derived
// by hand from the documented rules (user_data.hpp, change.hpp).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "dcel/edit.hpp"
#include "dcel/locate.hpp"
#include "dcel/user_data.hpp"
#include "support/edit_helpers.hpp"

namespace dcel {
namespace {

using test_support::countries;
using test_support::kEast;
using test_support::kEnclave;
using test_support::kWest;

FaceId face_at(const Dcel& d, Point p) {
    const Location l = locate_by_scan(d, p);
    EXPECT_EQ(l.kind, Location::Kind::Face);
    return l.face;
}

TEST(UserData, CountryNamesFollowSplitsMergesAndRenumbering) {
    Dcel d = build(countries());
    FaceData<std::string> names(d, "sea");
    VertexData<std::string> places(d);
    EdgeData<int> border(d, 0);
    names[kWest] = "West";
    names[kEast] = "East";
    names[kEnclave] = "Enclave";
    places[VertexId(10)] = "Capital";
    border[EdgeId(6)] = 1;  // the West/East border
    auto follow = [&](const Change& c) {
        names.follow(c);
        places.follow(c);
        border.follow(c);
    };

    follow(split_edge(d, EdgeId(5), {0, 4}));  // v11 on the coast
    follow(split_edge(d, EdgeId(6), {4, 4}));  // v12 on the border: e12 is border too
    EXPECT_EQ(border[EdgeId(12)], 1);
    EXPECT_EQ(places[VertexId(12)], "");
    places[VertexId(12)] = "Border post";
    follow(add_edge(d, VertexId(11), VertexId(12)));  // West splits: f4 (north) copies "West"
    EXPECT_EQ(names[FaceId(4)], "West");
    EXPECT_EQ(border[EdgeId(13)], 0);
    names[FaceId(4)] = "Northwest";
    EXPECT_EQ(names[face_at(d, {1, 5})], "Northwest");
    EXPECT_EQ(names[face_at(d, {1, 1})], "West");

    // Removing the lower border e6 (1-12) merges East (f2) into West (f1);
    // Northwest, the last face, moves into id 2.
    const Change merge = remove_edge(d, EdgeId(6));
    follow(merge);
    EXPECT_EQ(merge.faces.moved, FaceId(4));
    EXPECT_EQ(names[FaceId(2)], "Northwest");
    EXPECT_EQ(names[face_at(d, {6, 1})], "West");
    EXPECT_EQ(names[face_at(d, {6, 3})], "Enclave");
    EXPECT_EQ(names[face_at(d, {1, 5})], "Northwest");
    EXPECT_EQ(names[face_at(d, {20, 20})], "sea");
    EXPECT_EQ(border[EdgeId(12)], 1);  // the upper border piece keeps its value

    // Removing the capital moves the last vertex (the border post) into v10.
    follow(remove_isolated_vertex(d, VertexId(10)));
    EXPECT_EQ(places[VertexId(10)], "Border post");
    EXPECT_TRUE(names.in_step(d) && places.in_step(d) && border.in_step(d));
}

TEST(UserData, MergeFunctionsCombineValues) {
    Dcel d = build(countries());
    FaceData<std::string> names(d, "", [](std::string& kept, std::string&& absorbed) { kept += "+" + absorbed; });
    names[kWest] = "West";
    names[kEast] = "East";
    EdgeData<double> length(d, 0, [](double& kept, double&& absorbed) { kept += absorbed; });
    length[EdgeId(0)] = 4;
    length[EdgeId(1)] = 4;
    length.follow(split_edge(d, EdgeId(0), {1, 0}));  // both halves copy 4: the caller fixes them
    length[EdgeId(0)] = 1;
    length[EdgeId(11)] = 3;
    names.follow(Change{});  // an empty change is harmless
    const Change c = merge_collinear_edges(d, VertexId(11));
    length.follow(c);
    EXPECT_EQ(length[EdgeId(0)], 4);
    const Change m = remove_edge(d, EdgeId(6));
    names.follow(m);
    EXPECT_EQ(names[kWest], "West+East");
}

TEST(UserData, AMissedFollowIsCaughtAtTheNextEdit) {
    Dcel d = build(countries());
    FaceData<int> data(d, 0);
    (void)add_edge(d, VertexId(7), VertexId(2));  // no new face: nothing to miss yet
    data.follow(add_edge(d, VertexId(8), VertexId(3)));
    data.follow(add_edge(d, VertexId(0), VertexId(10)));  // a dangling edge: no face change
    Dcel e = build(countries());
    FaceData<int> stale(e, 0);
    (void)remove_edge(e, EdgeId(6));  // missed: stale still has 4 faces
    const Change next = remove_edge(e, EdgeId(0));
    EXPECT_THROW(stale.follow(next), std::logic_error);
    FaceData<int> twice(d, 0);
    const Change c = remove_edge(d, EdgeId(7));
    twice.follow(c);
    EXPECT_THROW(twice.follow(c), std::logic_error);
}

}  // namespace
}  // namespace dcel
