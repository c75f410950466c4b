// C++ session implementations (dcel/testing/check_testing_sessions.hpp)
// written the way a user would write one, one right and six with a bug each,
// to show that the in-process session helpers catch what they should. None
// of them uses the reference's incremental edit code or its queries: each
// keeps the graph by protocol ids, checks every edit by brute force with the
// independent exact oracles (tests/oracles/exact.hpp), rebuilds the faces
// from scratch with dcel::build after each edit, and answers queries by
// brute force (exact winding numbers and areas, a stab cut at every vertex
// and crossing). The bugs are those of docs/checking.md's planted table
// (tests/data/impls/session_*.py), as small variations of the right one:
//
//   right_session                 right
//   holes_stay_session            an add_edge that splits a face leaves its
//                                 holes and isolated vertices in the old face
//   stale_outer_session           after removing a bridge, the face's outer
//                                 boundary and the new hole are swapped
//   locate_vertical_session       a point on a vertical edge is answered with
//                                 the face on the edge's left
//   locate_ignores_holes_session  a point in a face is answered with the
//                                 largest face whose outer boundary winds
//                                 around it, holes never looked at
//   split_twin_session            a split updates one side of the edge only:
//                                 the cycle through v -> u still skips the
//                                 new vertex
//   refuses_collinear_session     refuses horizontal and vertical edges
#pragma once

#include <memory>

#include "dcel/graph.hpp"
#include "dcel/testing/session_implementation.hpp"

namespace dcel::props::planted {

using SessionPtr = std::unique_ptr<testing::SessionImplementation>;

[[nodiscard]] SessionPtr right_session(const PlanarGraph& start);
[[nodiscard]] SessionPtr holes_stay_session(const PlanarGraph& start);
[[nodiscard]] SessionPtr stale_outer_session(const PlanarGraph& start);
[[nodiscard]] SessionPtr locate_vertical_session(const PlanarGraph& start);
[[nodiscard]] SessionPtr locate_ignores_holes_session(const PlanarGraph& start);
[[nodiscard]] SessionPtr split_twin_session(const PlanarGraph& start);
[[nodiscard]] SessionPtr refuses_collinear_session(const PlanarGraph& start);

}  // namespace dcel::props::planted
