// The reference's own answer of each kind, spelled in one of the many
// equivalent ways docs/checking.md allows, and optionally corrupted: the
// trials behind the answer-spelling property (properties/
// prop_answer_spellings.cpp) and the answer fuzz harness's mode B
// (fuzz/answer.cpp), which share every decision through Choices.
//
// A trial is made in four steps:
//   1. the reference's answer of the setup's kind in its plain spelling
//      (check::reference_regions for polygons and rings, the DCEL's cycles
//      for faces, to_dump for the dump);
//   2. changes that keep its meaning, on that plain spelling: cycle, ring,
//      polygon, hole and record order; rotations; a ring split or joined at
//      a vertex it touches itself at (when each piece keeps its role's
//      direction), there-and-back excursions along an edge, degenerate holes
//      [u, v] and one-point holes [v]; rings reversed where the kind or
//      --unoriented lets them run either way; a dump's outer, inner and
//      vertex_out naming other half-edges of the same cycle or vertex,
//      vertex_out left out;
//   3. with setup.corrupt, one corruption (a cycle, ring or polygon dropped,
//      repeated, reversed, moved or rewired, a vertex id replaced, a dump
//      field or record changed); what it does to the meaning is the oracle's
//      to say (oracles/answer_meaning.hpp), never this code's;
//   4. the text, in the conventions (ids from 1, everything reversed for
//      faces on the right, a dump turned around and renumbered) and in one
//      of the forms: object or bare list, [shell, hole...] lists or
//      {"shell", "holes"} objects in any key order, GeoJSON Polygon,
//      MultiPolygon, FeatureCollection of Features (some without geometry)
//      or GeometryCollection, ids or coordinates (-0.0 for 0, an altitude),
//      numbers as 3, 3.0, 3e0, 0.3e1, closing repeats, members that are
//      ignored, a byte order mark, any JSON whitespace. Each step of 4 is a
//      bijection on what the checker reads, so the oracle's verdict on the
//      plain spelling after step 3 is the verdict on the text.
// Only forms that detection reads unambiguously are used when the kind is
// to be detected (docs/checking.md, "Detection").
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "dcel/check/answer.hpp"
#include "dcel/dcel.hpp"
#include "oracles/answer_meaning.hpp"

namespace dcel::test_support {

// Decisions read from bytes, one at a time. Every decision's 0 is the
// plainest choice, and once the bytes run out every decision is 0, so
// fewer and smaller bytes (what RapidCheck shrinks towards and libFuzzer
// starts from) mean a plainer trial.
class Choices {
public:
    explicit Choices(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
    // A number in [0, n), n >= 1: one byte, two when n > 256.
    [[nodiscard]] std::size_t below(std::size_t n);
    // True one time in n (false once the bytes run out).
    [[nodiscard]] bool one_in(std::size_t n) { return n != 0 && below(n) == n - 1; }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t at_ = 0;
};

struct TrialSetup {
    check::AnswerKind kind = check::AnswerKind::Faces;
    bool give_kind = true;  // --answer KIND; false: detected from the text
    check::Conventions conventions;
    bool corrupt = false;
};

struct Trial {
    TrialSetup setup;
    std::string text;                // the answer as another program would print it
    std::string story;               // what steps 2 to 4 did, for failure messages
    oracle::AnswerVerdict expected;  // the oracle's verdict on the answer (after any corruption)
};

[[nodiscard]] Trial make_trial(const Dcel& reference, const oracle::AnswerJudge& judge, const TrialSetup& setup,
                               Choices& choices);

// dcel check's verdict on the trial (read_answer with the setup's kind, or
// detection, then compare under its conventions), set against the expected
// one: empty when they agree, otherwise a failure message with the text,
// the story and the report. An answer that cannot be read counts as a
// difference, as in `dcel check`.
[[nodiscard]] std::string judge_trial(const Dcel& reference, const Trial& trial);

}  // namespace dcel::test_support
