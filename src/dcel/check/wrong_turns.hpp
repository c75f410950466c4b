// Where an answer's next differs from the reference's, read from the
// answer's own cycles: in a cycle ... u, v, x ... the answer continues u->v by
// v->x; the reference continues it by next(u->v) = v->w. A wrong turn is such
// a step with x != w (u->v an edge of the graph). Independent of the
// comparison's report (check/compare.hpp), so that a picture can be checked
// against it. Internal to the counterexample drawing.
#pragma once

#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/ids.hpp"

namespace dcel::check {

struct WrongTurn {
    Index from;          // u
    Index at;            // v, where the two disagree
    Index reference_to;  // w: next(u->v) = v->w in the reference
    Index answer_to;     // x: the answer's v->x (x need not be a neighbour of v)
    std::size_t cycle;   // the answer cycle it was read from
};

// Every wrong turn, in answer order; a turn (u, v) listed once even when the
// answer repeats it. Ids out of range and steps along non-edges are skipped.
[[nodiscard]] std::vector<WrongTurn> wrong_turns(const Dcel& reference,
                                                 const std::vector<std::vector<Index>>& answer_cycles);

}  // namespace dcel::check
