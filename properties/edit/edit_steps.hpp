// RapidCheck generators for edit steps (tests/support/edit_oracle.hpp holds
// the steps and the oracle, shared with the fuzz harness). Steps are built
// from combinators, so a failing script shrinks step by step and field by
// field.
#pragma once

#include <rapidcheck.h>

#include <cstdlib>
#include <ostream>
#include <vector>

#include "support/edit_oracle.hpp"

namespace dcel::test_support {
inline void showValue(const Step& s, std::ostream& os) { os << s; }
}  // namespace dcel::test_support

namespace dcel::props {

using test_support::apply;
using test_support::expected_valid;
using test_support::kGrid;
using test_support::Op;
using test_support::resolve;
using test_support::Resolved;
using test_support::start_map;
using test_support::Step;

// RapidCheck reads RC_PARAMS on first use; give it a fixed seed unless the
// caller set one (RC_PARAMS="seed=..." reproduces or varies a run).
inline const bool kSeedFixed = ::setenv("RC_PARAMS", "seed=6021 max_success=200", 0) == 0;

// Steps that mostly succeed: they grow maps with faces, holes and isolated
// vertices. Splits pick a point exactly on the edge (1/4, 1/2 or 3/4 of the
// way: exact for the dyadic coordinates that arise).
inline rc::Gen<Step> growing_step() {
    return rc::gen::build<Step>(rc::gen::set(&Step::op, rc::gen::weightedElement<Op>({{4, Op::AddVertex},
                                                                                      {8, Op::AddEdge},
                                                                                      {3, Op::AddEdgeToPoint},
                                                                                      {3, Op::SplitEdge},
                                                                                      {2, Op::RemoveEdge},
                                                                                      {1, Op::RemoveVertex},
                                                                                      {2, Op::MergeEdges}})),
                                rc::gen::set(&Step::a, rc::gen::inRange<std::uint32_t>(0, 64)),
                                rc::gen::set(&Step::b, rc::gen::inRange<std::uint32_t>(0, 64)),
                                rc::gen::set(&Step::x, rc::gen::inRange(0, kGrid + 1)),
                                rc::gen::set(&Step::y, rc::gen::inRange(0, kGrid + 1)));
}

// Steps that are often refused: new edges in dense maps, new points at
// vertices or on edges, splits off the edge, removals of vertices with edges,
// merges at corners.
inline rc::Gen<Step> hostile_step() {
    return rc::gen::build<Step>(rc::gen::set(&Step::op, rc::gen::weightedElement<Op>({{3, Op::AddVertex},
                                                                                      {6, Op::AddEdge},
                                                                                      {3, Op::AddEdgeToPoint},
                                                                                      {3, Op::SplitEdge},
                                                                                      {2, Op::RemoveVertex},
                                                                                      {2, Op::MergeEdges}})),
                                rc::gen::set(&Step::a, rc::gen::inRange<std::uint32_t>(0, 64)),
                                rc::gen::set(&Step::b, rc::gen::inRange<std::uint32_t>(0, 64)),
                                rc::gen::set(&Step::x, rc::gen::inRange(-1, kGrid + 2)),
                                rc::gen::set(&Step::y, rc::gen::inRange(-1, kGrid + 2)),
                                rc::gen::set(&Step::at, rc::gen::inRange(0, 3)));
}

// A script of up to about 3 * RapidCheck's size (100 at most) steps: long
// enough to build maps with a dozen faces, holes in holes, and merges.
inline rc::Gen<std::vector<Step>> script(rc::Gen<Step> step) {
    return rc::gen::scale(3.0, rc::gen::container<std::vector<Step>>(std::move(step)));
}

}  // namespace dcel::props
