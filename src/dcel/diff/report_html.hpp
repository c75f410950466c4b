// The HTML report of `dcel diff --html FILE`: one self-contained page (inline
// CSS, SVG and one script; no network, no external script, font or image)
// rendered from the JSON report alone (report_json, docs/diff-report.schema.json),
// so any report renders the same page, whoever wrote it.
//
// The page: the verdict and the run's figures, the cases the implementation
// skipped and the performance notes, a summary that links to each failure,
// and per distinct failure its counterexample picture (the --svg drawing,
// made again from the report's graph and answer), the graph, the reference's
// answer beside the implementation's (stdout, or how it ended and its
// stderr), the differences, the notes and the commands that replay it.
// Hovering a vertex shows its id and exact coordinates; hovering or clicking
// a difference or a cycle draws it on the picture (report_html_assets.hpp).
//
// Everything from the report is escaped (html_text.hpp), and a Content
// Security Policy allows no network and no script but the page's own.
#pragma once

#include <string>
#include <string_view>

#include "dcel/diff/json_value.hpp"

namespace dcel::diff {

// The page for a JSON report. Throws InvalidInput when the text is not JSON
// or not a dcel diff report (its "format" is checked); fields missing from a
// report (an older writer, a hand-made one) are left out of the page.
[[nodiscard]] std::string render_html_report(std::string_view report_json);
[[nodiscard]] std::string render_html_report(const JsonValue& report);

}  // namespace dcel::diff
