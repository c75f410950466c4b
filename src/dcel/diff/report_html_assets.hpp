// The HTML report's style sheet and its one script (report_html.hpp), kept
// apart from the markup that uses them.
#pragma once

#include <string_view>

namespace dcel::diff {

[[nodiscard]] std::string_view html_report_style();

// Vertex tooltips (id and exact coordinates) and walks (a cycle, a
// difference) drawn over both panels of a failure's picture. It reads what
// the markup holds: each failure's data-edges (the DCEL's edges as vertex
// pairs, in the drawing's order), each walkable item's data-walk (vertex
// ids; data-walk2 for the reference's turn of a wrong-next), the drawing's
// vertex and edge groups. "#selftest" in the address pins the first
// difference and hovers the first vertex of the first failure, then marks
// the body data-selftest="done": what the browser test checks and shows.
[[nodiscard]] std::string_view html_report_script();

}  // namespace dcel::diff
