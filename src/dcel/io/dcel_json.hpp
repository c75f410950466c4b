// Reading and writing DCEL dumps and face answers as JSON.
//
// A dump (what `dcel build` prints, and what a foreign implementation hands to
// `dcel check`):
//   {"vertices": [[x, y], ...],
//    "vertex_out": [h or null, ...],                                   (optional)
//    "half_edges": [{"origin": v, "twin": h, "next": h, "prev": h, "face": f}, ...],
//    "faces": [{"outer": h or null, "inner": [h, ...], "isolated": [v, ...]}, ...]}
// In a face, "outer" is required and "inner"/"isolated" default to empty.
// A faces answer (the boundary cycles of the faces, as vertex lists):
//   {"faces": [[v, ...], ...]}   or bare   [[v, ...], ...]
// Empty cycles are allowed. Unknown keys are ignored everywhere.
//
// Ids are non-negative integers below 2^32 - 1 (null where the form says so),
// but the readers do not check them against the element counts: a dump may be
// arbitrarily broken, and validate() is what reports out-of-range references.
// Errors are InvalidInput with a one-line message naming the place ("line L,
// column C: ..." or a JSON path such as "half_edges[7].next: ...").
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/dump.hpp"
#include "dcel/ids.hpp"
#include "dcel/io/text_sink.hpp"

namespace dcel::io {

// Every writer's text ends in "\n". The forms taking a TextSink
// (text_sink.hpp) stream the same text as the string forms return, a piece
// of at most 16 KiB at a time, holding no more than that of it.

// Faces: one line, {"faces": [[0, 1, 2], [0, 2, 1]]}; a null id is written
// as null.
[[nodiscard]] std::string write_faces(const std::vector<std::vector<VertexId>>& cycles);
// The same text as write_faces(boundary_cycles(d)), written straight from the
// DCEL without building the lists (what `dcel faces` prints). O(E).
[[nodiscard]] std::string write_faces_of(const Dcel& d);
void write_faces_of(const Dcel& d, const TextSink& sink);

// Lines: one vertex, vertex_out entry, half-edge or face per line (readable,
// and diffs show exactly the records that changed). Compact: one line.
// Numbers are in their shortest round-trip form; null ids are written as null.
// Throws InvalidInput(BadCoordinate) for a NaN or infinite coordinate (when
// streaming, after the sink took the text before that coordinate).
enum class DumpStyle { Lines, Compact };
[[nodiscard]] std::string write_dump(const DcelDump& dump, DumpStyle style = DumpStyle::Lines);
void write_dump(const DcelDump& dump, DumpStyle style, const TextSink& sink);
// The text of write_dump(to_dump(d), style), streamed straight from the DCEL
// without the copy to_dump makes (what `dcel build` prints). O(V + E + F).
void write_dump_of(const Dcel& d, DumpStyle style, const TextSink& sink);

// The inverse of write_dump (either style); "vertex_out" absent reads as empty.
[[nodiscard]] DcelDump read_dump(std::string_view text);

// {"faces": [[v, ...], ...]} or [[v, ...], ...].
[[nodiscard]] std::vector<std::vector<Index>> read_faces_answer(std::string_view text);

// A dump when the top-level value is an object with a "half_edges" key,
// otherwise a faces answer.
[[nodiscard]] std::variant<std::vector<std::vector<Index>>, DcelDump> read_answer(std::string_view text);

}  // namespace dcel::io
