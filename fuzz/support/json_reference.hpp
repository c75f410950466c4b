// What an independent JSON parser (nlohmann/json, fuzz build only) reads
// in a document, for the parse harness's differential: whether it is JSON
// at all, how deep it nests, and the graph or faces answer it holds by the
// rules of docs/formats.md, worked out from nlohmann's values alone.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dcel/dump.hpp"
#include "dcel/graph.hpp"

namespace dcel::fuzz {

struct JsonFacts {
    bool has_nul = false;             // a NUL byte, which nlohmann takes for the end of the text;
                                      // then nothing else is filled in (RFC 8259 allows none)
    bool accepted = false;            // one JSON value (RFC 8259), as nlohmann reads it
    bool number_overflow = false;     // refused for a number beyond the range of a double
    bool rounded_to_integer = false;  // a number that is no integer but reads as one (5e-3241,
                                      // 1.00000000000000001): nlohmann's double cannot tell
                                      // an index the reader must refuse
    std::size_t depth = 0;            // the deepest nesting of arrays and objects
    bool duplicate_key = false;       // a key given twice in one object, at any depth
                                      // (which the reader refuses, RFC 8259 leaving it open)
    std::string error;                // nlohmann's message when refused
};

[[nodiscard]] JsonFacts json_facts(std::string_view text);

// The graph the document holds, or nothing when a graph reader must refuse
// it: {"vertices": [[x, y], ...], "edges": [[u, v], ...]} (other keys
// ignored) or [[[x, y], ...], [[u, v], ...]]; every coordinate a number,
// every index a non-negative integer below 2^32 - 1. Only for accepted
// documents the reader can hold (JsonReader::kMaxDepth) without a duplicate key.
[[nodiscard]] std::optional<PlanarGraph> expected_graph(std::string_view text);

// The points of a document that is one array of them, [[x, y], ...] (what
// `dcel locate --points` reads), or nothing.
[[nodiscard]] std::optional<std::vector<Point>> expected_points(std::string_view text);

// The cycles of a faces answer, {"faces": [[v, ...], ...]} or bare.
[[nodiscard]] std::optional<std::vector<std::vector<Index>>> expected_faces(std::string_view text);

// Does the dump hold, field by field, the values nlohmann reads in text?
// (For a dump the library's reader accepted.)
[[nodiscard]] bool dump_matches(std::string_view text, const DcelDump& d);

}  // namespace dcel::fuzz
