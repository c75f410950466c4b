// C++ DCEL solvers written the way a user would write them, one right and
// six with a textbook bug each, to show that the in-process checking helpers
// (dcel/testing/check_testing.hpp) catch what they should. None of them uses
// the library's algorithms: angular order, areas and point-in-polygon come
// from the independent exact oracles (tests/oracles/).
//
//   right_faces / right_dump   exact angular order, next(u->v) = the half-edge
//                              leaving v clockwise after v->u; each hole in the
//                              innermost face around it
//   atan2_faces                the angular order from std::atan2 of the
//                              coordinate differences: directions 1e-17 rad
//                              apart get one angle, and sort in any order
//   ccw_faces                  the counterclockwise neighbour instead
//   tiny_faces                 coordinates below 1e-200 in magnitude read as 0,
//                              as a "snap tiny values" tolerance would
//   huge_faces                 coordinates clamped to [-1e200, 1e200], as a
//                              "world box" would
//   isolated_crash_faces       reads every vertex's first edge with .at(0),
//                              which throws on an isolated vertex
//   outer_hole_dump            each hole in the outermost face around it
#pragma once

#include "dcel/check/compare.hpp"
#include "dcel/dump.hpp"
#include "dcel/graph.hpp"

namespace dcel::props::planted {

[[nodiscard]] check::FacesAnswer right_faces(const PlanarGraph& g);
[[nodiscard]] check::FacesAnswer atan2_faces(const PlanarGraph& g);
[[nodiscard]] check::FacesAnswer ccw_faces(const PlanarGraph& g);
[[nodiscard]] check::FacesAnswer isolated_crash_faces(const PlanarGraph& g);
[[nodiscard]] check::FacesAnswer tiny_faces(const PlanarGraph& g);
[[nodiscard]] check::FacesAnswer huge_faces(const PlanarGraph& g);

[[nodiscard]] DcelDump right_dump(const PlanarGraph& g);
[[nodiscard]] DcelDump outer_hole_dump(const PlanarGraph& g);

}  // namespace dcel::props::planted
