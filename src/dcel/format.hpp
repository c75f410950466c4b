// Formatting of numbers, ids and user-controlled text for messages and
// output. Doubles are written in the shortest form that reads back to the
// same value.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "dcel/geometry/point.hpp"
#include "dcel/graph.hpp"

namespace dcel {

[[nodiscard]] std::string format_double(double v);
[[nodiscard]] std::string format_point(Point p);  // "(x, y)"
// "edge 3 [u, v] from (ux, uy) to (vx, vy)"
[[nodiscard]] std::string describe_edge(const PlanarGraph& g, EdgeId e);
// "vertex 4 (x, y)"
[[nodiscard]] std::string describe_vertex(const PlanarGraph& g, VertexId v);

// ---- User-controlled text in messages (names, paths, command-line words,
// JSON strings and keys). Every such piece goes through escape_for_message
// or quote_for_message, so that a message stays one line of printable text
// whatever the user gave: no newline splits it, no ESC or BEL sequence
// reaches the terminal, no NUL cuts it short.

// The longest piece of user text shown in a message, in input bytes; longer
// text is cut at a character boundary and "..." appended.
inline constexpr std::size_t kMaxShownBytes = 256;

// The text with these written as escapes, everything else (printable ASCII
// and valid UTF-8) kept as is:
//  - backslash as \\ (so that every escape below is unambiguous);
//  - \n, \r, \t as themselves; other control characters (C0, DEL, and the
//    C1 controls U+0080-U+009F) as \u001B-style JSON escapes;
//  - U+2028/U+2029 (line and paragraph separators) and the bidirectional
//    controls U+200E/U+200F, U+202A-U+202E, U+2066-U+2069, which reorder
//    or break a line on the terminal, as \u2028-style escapes;
//  - a byte that does not start or continue well-formed UTF-8 as \xFF.
[[nodiscard]] std::string escape_for_message(std::string_view text, std::size_t max_bytes = kMaxShownBytes);

// The same between double quotes, with '"' escaped as \": "West", "a\nb".
// For JSON strings and keys this is their JSON spelling (plus \xFF for bytes
// that are not UTF-8, which JSON cannot hold).
[[nodiscard]] std::string quote_for_message(std::string_view text, std::size_t max_bytes = kMaxShownBytes);

// Whether escape_for_message would change anything but backslashes: true
// when the text holds a control character, a separator or bidirectional
// control, or invalid UTF-8. (A last check on whole messages.)
[[nodiscard]] bool needs_escaping(std::string_view text);

}  // namespace dcel
