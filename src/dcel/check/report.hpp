// A check Report as text (what `dcel check` prints) and as JSON (--json).
//
// Text: "agrees", or the count ("1 difference", "7 differences") and then one
// line per listed difference, "<kind>: <message>", and a line
// "... and N more not listed" when the report was capped; then one line
// "note: ..." per note.
//
// JSON, one difference per line:
//   {"agrees": false, "count": 7, "unlisted": 0, "differences": [
//     {"kind": "wrong-next", "message": "...", "vertices": [0, 1, 0, 2]},
//     ...
//   ], "notes": ["..."]}
// "count" is the number of differences found, listed or not.
#pragma once

#include <string>

#include "dcel/check/compare.hpp"

namespace dcel::check {

[[nodiscard]] std::string report_text(const Report& report);  // ends in "\n"
[[nodiscard]] std::string report_json(const Report& report);  // ends in "\n"

}  // namespace dcel::check
