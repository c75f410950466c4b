// An independent judge of DCEL dumps: is a dump exactly the correct DCEL of
// its own geometry, up to the choices a DCEL leaves free?
//
// It rebuilds the expected structure from scratch with exact integer
// geometry (exact_points.hpp), sharing no code with build() or validate():
//   - the graph under the dump (one edge per twin pair) must be a planar
//     straight-line graph (brute_force.hpp);
//   - next(u->v) must be the half-edge leaving v just clockwise of v->u, in
//     the exact angular order, and prev its inverse;
//   - the faces are the unbounded one plus one per counterclockwise cycle;
//     each component's clockwise outer cycle and each isolated vertex belong
//     to the smallest counterclockwise cycle of another component whose
//     winding number around it is not zero (or to the unbounded face);
//   - the dump's faces must be these under some renumbering: every
//     half-edge's face field agrees with it, a bounded face names its outer
//     cycle by any of its half-edges, inner cycles and isolated vertices are
//     listed once each in any order, and vertex_out, when given, names some
//     half-edge leaving each vertex (null exactly for isolated ones).
// Free choices (face numbering, which half-edge names a cycle, list order,
// which outgoing half-edge) are accepted; anything else is a defect.
#pragma once

#include <string>

#include "dcel/dump.hpp"

namespace dcel::fuzz {

struct Judgement {
    bool valid = true;
    std::string reason;  // why not, naming ids; empty when valid
};

[[nodiscard]] Judgement judge_dump(const DcelDump& d);

}  // namespace dcel::fuzz
