// The case schedule of `dcel diff`: case i is a graph from dcel::gen, put
// into a coordinate class and written in a JSON spelling, all determined by
// (run seed, i, the schedule options). So a case replays byte for byte from
// its number alone, whatever --cases or --time the run had.
//
// The schedule: the family cycles through the chosen families; the size
// starts at 2 and grows by 3 every round of families, up to --max-vertices;
// every 50th case (49, 99, ...) is a large one of --large-vertices vertices
// from the families with large shapes (a star of high degree, trees and
// chains with boundary cycles of thousands of half-edges, ...). The first
// round uses small integers written plainly; after that each case draws a
// coordinate class (small integers 4 in 10, normal 3, huge, tiny and
// subnormal 1 each) and, 6 times in 10, a varied spelling.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dcel/check/session.hpp"
#include "dcel/gen/coordinates.hpp"
#include "dcel/gen/generate.hpp"
#include "dcel/gen/spelling.hpp"

namespace dcel::diff {

struct Schedule {
    std::uint64_t seed = 1;
    std::size_t max_vertices = 60;              // the ramp's cap
    std::size_t large_vertices = 2000;          // the size of every 50th case; 0: no large cases
    std::vector<gen::Family> families;          // in schedule order; empty: all
    std::vector<gen::CoordinateClass> classes;  // allowed; empty: all
    bool one_line = false;                      // --stream: no newlines inside a graph
    bool positional = false;                    // some graphs in the positional form (--positional)
    // Sessions (--sessions): each case is an edit session on the case's
    // graph, of 1 + 2 * (i / F) steps up to max_steps (large cases:
    // large_steps), with states after every edit asked for when each_step.
    bool sessions = false;
    bool each_step = false;
    std::size_t max_steps = 24;
    std::size_t large_steps = 200;
    [[nodiscard]] std::vector<gen::Family> chosen_families() const;
    [[nodiscard]] bool allows(gen::CoordinateClass c) const;
};

struct CaseSpec {
    std::size_t number = 0;  // i, counted from 0
    gen::Params params;      // family, seed and target size handed to gen::generate
    bool large = false;
    gen::CoordinateClass coordinates = gen::CoordinateClass::SmallIntegers;  // asked for
    std::uint64_t coordinate_seed = 0;
    gen::Spelling spelling;
};

[[nodiscard]] CaseSpec case_spec(const Schedule& s, std::size_t i);

struct Case {
    CaseSpec spec;
    PlanarGraph graph;                                                       // a session's start graph
    std::optional<check::Session> session;                                   // --sessions
    gen::CoordinateClass coordinates = gen::CoordinateClass::SmallIntegers;  // what it has
    std::string text;                                                        // the exact bytes the command reads
};

// The case's graph, in its class and spelling; nothing when the schedule's
// classes exclude every graph the near-degenerate family offered for it.
[[nodiscard]] std::optional<Case> make_case(const Schedule& s, std::size_t i);

// A graph written in a case's spelling (shrunk graphs keep the spelling of
// the case they came from, so a reader's bug stays visible).
[[nodiscard]] std::string spell(const PlanarGraph& g, const CaseSpec& spec);
// A session's document, one line.
[[nodiscard]] std::string spell(const check::Session& s);

}  // namespace dcel::diff
