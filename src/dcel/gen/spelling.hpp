// The many ways one graph can be written as valid JSON, for checking that
// other implementations read every one: numbers with exponents (1e+16,
// 5E-324, 12345e12), integral values as 3.0, negative zero as -0.0, spacing,
// key order and the positional form. Every spelling reads back to exactly
// the same doubles (each is the same decimal value written another way), so
// the graph, and the reference's answer, are the same whatever the spelling.
//
// Deterministic: the same (graph, spelling) gives the same bytes everywhere,
// which is what lets `dcel diff --case N` replay a case byte for byte.
#pragma once

#include <cstdint>
#include <string>

#include "dcel/graph.hpp"

namespace dcel::gen {

struct Spelling {
    enum class Numbers : std::uint8_t {
        Shortest,        // std::to_chars' shortest form, as `dcel faces` writes: 3, -0, 1e+16, 5e-324
        Scientific,      // 3e0, -0e0, 1e16, 4.9406564584124654e-324 -> 5e-324 (shortest digits, no '+')
        ScientificPlus,  // 3E+00 style: capital E, explicit sign, as C's printf("%E") writes
        Decimal,         // integral values as 3.0, -0 as -0.0, others shortest
        Mixed,           // each number in one of the forms above, chosen per number
    };
    Numbers numbers = Numbers::Shortest;
    bool positional = false;   // [[[x, y], ...], [[u, v], ...]] instead of the object form
    bool edges_first = false;  // object form: "edges" before "vertices"
    bool compact = false;      // no spaces at all
    bool newlines = false;     // one vertex and one edge per line (never in a --stream line)
    std::uint64_t seed = 0;    // for Mixed: which form each value takes (the same value, the same form)

    // The spelling `dcel faces` and `dcel gen` use: shortest numbers, object form, spaces.
    [[nodiscard]] static Spelling plain() { return {}; }
    // A spelling drawn from `seed`; one_line forbids newlines (a --stream line).
    [[nodiscard]] static Spelling random(std::uint64_t seed, bool one_line);
    // "shortest numbers, object form" style text for reports.
    [[nodiscard]] std::string describe() const;
};

// The graph as JSON in this spelling, ending in "\n". Coordinates must be finite.
[[nodiscard]] std::string write_spelled(const PlanarGraph& g, const Spelling& s);

}  // namespace dcel::gen
