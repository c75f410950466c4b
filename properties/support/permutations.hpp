// RapidCheck generators of permutations, and of the rewordings of an answer
// built from them, that shrink towards the identity: a failing case shrinks
// to a permutation with as few and as short swaps as the failure needs,
// where a permutation drawn from a seed could only shrink its seed.
#pragma once

#include <rapidcheck.h>

#include <cstddef>
#include <vector>

#include "dcel/dump.hpp"
#include "dcel/ids.hpp"
#include "support/check_helpers.hpp"

namespace dcel::props {

// A permutation of 0 .. n-1, uniform over all n! at every RapidCheck size.
// It is drawn as Fisher–Yates swaps, the i-th between place i and a place
// d_i >= 0 further on; each d_i shrinks towards 0, no swap, so shrinking
// undoes every swap the failure does not need.
[[nodiscard]] rc::Gen<std::vector<Index>> permutations(std::size_t n);

// The faces answer in other words: each cycle rotated, the cycles
// reordered (test_support::shuffled); shrinks towards the answer as it was.
[[nodiscard]] rc::Gen<check::FacesAnswer> rewordings(const check::FacesAnswer& a);

// The dump renumbered (test_support::renumbered): half-edges and faces
// permuted, each face record naming a half-edge up to three steps further
// along its cycle, inner and isolated lists reordered; shrinks towards the
// dump as it was.
[[nodiscard]] rc::Gen<DcelDump> renumberings(const DcelDump& d);

}  // namespace dcel::props
