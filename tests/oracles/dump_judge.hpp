// An independent judge of DCEL dumps: is a dump exactly the correct DCEL of
// its own geometry, up to the choices a DCEL leaves free?
//
// It shares no code with build() or validate():
//   - every id is in range and twin is a fixed-point-free involution;
//   - the graph under the dump (one edge per twin pair) must be a planar
//     straight-line graph (brute_force.hpp);
//   - next, prev and the faces must be those of the reference DCEL of that
//     graph under the dump's own half-edge numbering (reference_dcel.hpp);
//   - the dump's faces must be the reference's under some renumbering:
//     every half-edge's face field agrees with it, a bounded face names its
//     outer cycle by any of its half-edges, inner cycles and isolated
//     vertices are listed once each in any order, and vertex_out, when
//     given, names some half-edge leaving each vertex (null exactly for
//     isolated ones).
// Free choices (face numbering, which half-edge names a cycle, list order,
// which outgoing half-edge) are accepted; anything else is a defect.
#pragma once

#include <string>

#include "dcel/dump.hpp"

namespace dcel::oracle {

struct Judgement {
    bool valid = true;
    std::string reason;  // why not, naming ids; empty when valid
};

[[nodiscard]] Judgement judge_dump(const DcelDump& d);

}  // namespace dcel::oracle
