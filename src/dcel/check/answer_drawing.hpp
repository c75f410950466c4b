// An answer as the counterexample picture takes it (counterexample_svg.hpp):
// its cycles and its polygons by vertex id. Internal to dcel::check: the diff
// engine prepares a wrong answer's picture with it, and the answer fuzz
// harness draws every answer it reads through it, so the two draw alike.
#pragma once

#include <vector>

#include "dcel/check/answer.hpp"
#include "dcel/dcel.hpp"

namespace dcel::check {

// The answer's cycles, for drawing: faces as given (1-based ids shifted, a 0
// left as kNoIndex, a repeated first vertex dropped, reversed for faces on
// the right), a dump's next-cycles where its references allow a walk.
// Nothing for an answer of more than 100,000 ids: its drawing says nothing.
[[nodiscard]] std::vector<std::vector<Index>> drawn_cycles(const Answer& a, const Conventions& c);

// Polygons and rings by vertex id (coordinates matched exactly; a ring with
// a point that is no vertex, or an id out of range, is left out).
[[nodiscard]] std::vector<std::vector<std::vector<Index>>> drawn_regions(const Answer& a, const Dcel& reference,
                                                                         const Conventions& c);

}  // namespace dcel::check
