// Random edit sessions (check/session.hpp) that reach the hard cases of a
// DCEL's operations on purpose, and shrinking a failing one. Deterministic in
// their arguments, like every generator here.
//
// A session starts from a generated graph and draws its steps one at a time
// against the reference running it, so most edits are accepted and the
// interesting ones are likely: an edge between two vertices of one face
// (which may close a cycle around holes and isolated vertices, that must
// then move into the new face), the removal of any edge (bridges and dangling
// edges included: a new hole or new isolated vertices), splits at exact
// dyadic points of long edges, vertices next to vertical and horizontal
// edges, and queries at vertices, on edges (vertical ones too), inside holes,
// in faces and far out in the unbounded face. About one step in eight is one
// the reference refuses (a crossing, a point off the edge, an edge that
// exists, a removed vertex).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "dcel/check/session.hpp"
#include "dcel/gen/coordinates.hpp"
#include "dcel/gen/generate.hpp"

namespace dcel::gen {

struct SessionParams {
    Params graph;                                // the start graph
    std::uint64_t seed = 0;                      // the steps
    std::size_t steps = 8;                       // how many
    std::optional<CoordinateClass> coordinates;  // the start graph mapped into a class, when it maps
};

[[nodiscard]] check::Session generate_session(const SessionParams& params);

// Smaller sessions derived from s, most aggressive first: fewer steps (the
// steps after a prefix dropped, runs of steps dropped: a vertex a dropped
// step would have created is gone, and so are the later steps that name it,
// the later ids renumbered), the first steps folded into the start graph
// (the reference's state after them as the start, the protocol ids kept: what
// they built can then be dropped like any start edge or vertex), the start
// graph smaller (its isolated vertices,
// runs of its edges, single vertices dropped, ids renumbered, steps naming a
// dropped vertex dropped; vertices of degree two smoothed away, their
// neighbours joined), and the coordinates snapped towards small
// integers by exact maps (a power-of-two scaling, a translation) of every
// point, the start graph's and the steps'. Every candidate's start graph is
// valid; its steps may be refused, which a session allows.
// One candidate at a time (a session's candidates may be many copies of a
// large start graph): next() builds the next valid one, or gives nothing.
class SessionShrinkCandidates {
public:
    explicit SessionShrinkCandidates(check::Session s);
    [[nodiscard]] std::optional<check::Session> next();

private:
    [[nodiscard]] std::optional<check::Session> candidate();
    bool run_at(std::size_t n, std::size_t& begin, std::size_t& end) const;

    check::Session s_;
    std::vector<Index> created_;  // per step: the protocol id it created, or kNoIndex
    int stage_ = 0;
    std::size_t index_ = 0;
    std::size_t keep_ = 0;
    std::vector<check::Session> maps_;
};

// All of them at once (for small sessions and tests).
[[nodiscard]] std::vector<check::Session> session_shrink_candidates(const check::Session& s);

struct GreedySessionShrink {
    check::Session session;
    std::size_t tried = 0;
    std::size_t taken = 0;
    bool stopped = false;  // stop() ended it before a pass took nothing
};
// gen::shrink_greedily's loop over session_shrink_candidates.
[[nodiscard]] GreedySessionShrink shrink_session_greedily(check::Session s,
                                                          const std::function<bool(const check::Session&)>& still_fails,
                                                          const std::function<bool()>& stop);

}  // namespace dcel::gen
