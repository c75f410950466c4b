// The HTML page of a JSON report (src/dcel/diff/report_html.hpp): rendered
// from hand-made reports (hostile output escaped, a run that agrees, skips
// and performance notes, what is not a report) and from the engine's own
// report of a run with two bugs (fakes.hpp). html_browser_test.py loads a
// real run's page in Chromium.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include "dcel/diff/html_text.hpp"
#include "dcel/diff/json_value.hpp"
#include "dcel/diff/report.hpp"
#include "dcel/diff/report_html.hpp"
#include "dcel/diff/session.hpp"
#include "dcel/diff/sha256.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/queries.hpp"
#include "fakes.hpp"

namespace dcel::diff {
namespace {

std::size_t occurrences(std::string_view text, std::string_view part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string_view::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

bool has(std::string_view text, std::string_view part) { return text.find(part) != std::string_view::npos; }

// What breaks out of a <script> or an attribute, and starts one of its own.
constexpr const char* kHostile = R"(</script><img src=x onerror=alert(1)>\"'&)";

// A report of one run, every field there, with `failures` spliced in.
std::string report(const std::string& run_fields, const std::string& failures, const std::string& impl = "python3 mine.py") {
    return R"({"format": "dcel diff report 1", "command": "dcel diff --impl ')" + impl +
           R"(' --seed 1 --timeout-ms 5000 --cases 200",
  "impl": ")" +
           impl +
           R"(", "seed": 18446744073709551615, "answer_kind": null,
  "conventions": {"face_on_right": false, "one_based": false, "unoriented": false, "isolated_cycles": false, "holes_unattached": false},
  )" + run_fields +
           R"(, "large_cases": 4, "stopped_by": "cases", "elapsed_ms": 2345, "reference_cpu_ms": 120,
  "failures": [)" +
           failures + "]}\n";
}

constexpr const char* kAgreeing =
    R"("cases_run": 200, "first_case": 0, "skipped": 0, "skipped_by_impl": 0, "skip_reasons": [], "checked": 200,
  "slow": {"count": 0, "cases": []}, "agrees": true)";
constexpr const char* kFailing =
    R"("cases_run": 200, "first_case": 0, "skipped": 0, "skipped_by_impl": 0, "skip_reasons": [], "checked": 200,
  "slow": {"count": 0, "cases": []}, "agrees": false)";

// A failure whose answer and stderr are hostile: markup, control characters,
// a bidirectional override, a very long line.
std::string hostile_failure(int id, const std::string& label) {
    return R"({"id": )" + std::to_string(id) + R"(, "label": ")" + label + R"(", "kind": "unparsable answer",
  "signature": "unparsable/3v3e", "classes": ["small-integers"], "occurrences": 3, "cases": [4, 9, 11], "found_after_ms": 50,
  "case": {"number": 4, "family": "triangulation", "coordinates": "small-integers", "spelling": "shortest numbers",
           "vertices": 5, "edges": 7},
  "reproduced": true, "prefix": [],
  "counterexample": {"vertices": 3, "edges": 3, "text": "{\"vertices\": [[0, 0], [1, 0], [0, 1]], \"edges\": [[0, 1], [1, 2], [2, 0]]}\n",
                     "graph": {"vertices": [[0, 0], [1, 0], [0, 1]], "edges": [[0, 1], [1, 2], [2, 0]]}},
  "shrinking": {"attempts": 12, "steps": 2, "elapsed_ms": 30, "budget_spent": false, "minimal": true},
  "outcome": {"label": ")" +
           label + R"(", "what": "not an answer: line 1, column 1: unexpected '<'",
              "answer_kind": "faces", "stdout": "</script><img src=x onerror=alert(1)>\u0000\u001b[31m\u202egnp.exe",
              "stderr_tail": "</pre><img src=x onerror=alert(2)>\n)" +
           std::string(5000, 'x') + R"(\n",
              "differences": [{"kind": "extra-cycle", "message": "<b>bold</b>", "vertices": [0, 1, 2]}], "notes": []},
  "reference": "{\"faces\": [[0, 1, 2], [1, 0, 2]]}",
  "replay": "dcel diff --impl 'python3 mine.py' --seed 18446744073709551615 --case 4 --timeout-ms 5000"})";
}

TEST(ReportHtml, EscapesEverythingTheImplementationPrinted) {
    const std::string page = render_html_report(
        report(kFailing, hostile_failure(1, "unparsable answer") + ", " + hostile_failure(2, "wrong answer (extra-cycle)"),
               kHostile));
    EXPECT_EQ(occurrences(page, "<script"), 1U);  // the page's own, and nothing else
    EXPECT_EQ(occurrences(page, "</script>"), 1U);
    EXPECT_FALSE(has(page, "<img"));
    EXPECT_FALSE(has(page, "<b>"));
    EXPECT_TRUE(has(page, "&lt;/script&gt;&lt;img src=x onerror=alert(1)&gt;"));
    EXPECT_TRUE(has(page, "&lt;/pre&gt;&lt;img src=x onerror=alert(2)&gt;"));
    EXPECT_TRUE(has(page, "&lt;/script&gt;&lt;img src=x onerror=alert(1)&gt;&quot;&#39;&amp;"));  // the impl
    EXPECT_TRUE(has(page, "&lt;b&gt;bold&lt;/b&gt;"));
    // Control and bidirectional characters are shown, not obeyed.
    EXPECT_TRUE(has(page, "<span class=\"esc\">\\x00</span>"));
    EXPECT_TRUE(has(page, "<span class=\"esc\">\\x1B</span>[31m"));
    EXPECT_TRUE(has(page, "<span class=\"esc\">\\u202E</span>gnp.exe"));
    EXPECT_FALSE(has(page, "\x1b"));
    EXPECT_FALSE(has(page, "\xe2\x80\xae"));
    // A long line is cut, and the page says so.
    EXPECT_TRUE(has(page, "[cut: the line has 5000 characters; the first 1000 are shown]"));
    EXPECT_FALSE(has(page, std::string(1001, 'x')));
    // The seed is kept exactly (beyond a double's integers); each failure has its picture.
    EXPECT_TRUE(has(page, "seed 18446744073709551615"));
    EXPECT_EQ(occurrences(page, "<svg "), 2U);
    EXPECT_TRUE(has(page, "(not drawn: "));  // the wrong answer that cannot be read
}

TEST(ReportHtml, EscapesInAttributesAndCutsLongBlocks) {
    EXPECT_EQ(html_attribute("a\"b'<c>&\x01"), "a&quot;b&#39;&lt;c&gt;&amp;\\x01");
    EXPECT_EQ(html_text("\xff\xc3\xa9"), "\xef\xbf\xbd\xc3\xa9");  // a stray byte as U+FFFD, UTF-8 kept
    EXPECT_EQ(html_block("1\n2\n3\n4\n", "out", {2, 10}),
              "<pre class=\"out\">1\n2\n<span class=\"cut\">[cut: 2 more lines not shown]</span></pre>\n");
}

TEST(ReportHtml, NoNetworkAndOnlyItsOwnScript) {
    const std::string page = render_html_report(report(kAgreeing, ""));
    const std::size_t open = page.find("<script>") + 8;
    const std::string script = page.substr(open, page.find("</script>") - open);
    EXPECT_TRUE(has(
        page, "content=\"default-src 'none'; style-src 'unsafe-inline'; script-src 'sha256-" + sha256_base64(script) + "'"));
    // Nothing to fetch: no source, and every link within the page (the
    // only "http" is the SVG namespace's name).
    EXPECT_FALSE(has(page, "src="));
    EXPECT_EQ(occurrences(page, "href="), occurrences(page, "href=\"#"));
    EXPECT_EQ(occurrences(page, "http:"), occurrences(page, "\"http://www.w3.org/2000/svg\""));
    EXPECT_FALSE(has(page, "url("));
    EXPECT_FALSE(has(page, "@import"));
}

TEST(ReportHtml, ARunThatAgreesIsOneVerdict) {
    const std::string page = render_html_report(report(kAgreeing, ""));
    EXPECT_TRUE(has(page, "<h1>dcel diff: agrees on 200 cases (0 to 199, seed 18446744073709551615) in 2.3 s</h1>"));
    EXPECT_TRUE(has(page, "<header class=\"card verdict\""));
    EXPECT_FALSE(has(page, "class=\"card failure\""));
    EXPECT_FALSE(has(page, "id=\"summary\""));
    EXPECT_FALSE(has(page, "id=\"skips\""));
    EXPECT_FALSE(has(page, "id=\"performance\""));
    EXPECT_TRUE(has(page, "<code>python3 mine.py</code>"));
}

TEST(ReportHtml, SkipsAndPerformanceNotesAreShown) {
    const std::string run = R"("cases_run": 100, "first_case": 0, "skipped": 0, "skipped_by_impl": 67,
  "skip_reasons": [{"reason": "negative <coordinates>", "cases": 60}, {"reason": "odd degree", "cases": 7}], "checked": 33,
  "slow": {"count": 2, "cases": [{"number": 49, "family": "star", "vertices": 600, "edges": 599, "ms": 1500, "limit_ms": 9000}]},
  "agrees": true)";
    const std::string page = render_html_report(report(run, ""));
    EXPECT_TRUE(has(page, "<li>60 cases: negative &lt;coordinates&gt;</li>"));
    EXPECT_TRUE(has(page, "<li>7 cases: odd degree</li>"));
    EXPECT_TRUE(has(page, "Performance notes: 2 slow cases"));
    EXPECT_TRUE(has(page, "<li>case 49 (family star, 600 vertices, 599 edges): 1.5 s, limit 9.0 s</li>"));
}

TEST(ReportHtml, ARunThatChecksNothingIsNoPass) {
    const std::string run = R"("cases_run": 20, "first_case": 0, "skipped": 0, "skipped_by_impl": 20,
  "skip_reasons": [{"reason": "everything", "cases": 20}], "checked": 0, "slow": {"count": 0, "cases": []}, "agrees": false)";
    const std::string page = render_html_report(report(run, ""));
    EXPECT_TRUE(has(page, "verdict empty"));
    EXPECT_TRUE(has(page, "no case was checked in 20 cases"));
}

TEST(ReportHtml, WhatIsNotAReportIsRefused) {
    EXPECT_THROW((void)render_html_report("not json"), InvalidInput);
    EXPECT_THROW((void)render_html_report("[]"), InvalidInput);
    EXPECT_THROW((void)render_html_report(R"({"format": "something else"})"), InvalidInput);
    EXPECT_THROW((void)render_html_report(R"({"format": "dcel diff report 1", "format": "x"})"), InvalidInput);
    // A bare report with nothing but its format still renders.
    EXPECT_TRUE(has(render_html_report(R"({"format": "dcel diff report 1"})"), "</html>"));
}

TEST(ReportHtml, Sha256OfKnownTexts) {
    EXPECT_EQ(sha256_base64(""), "47DEQpj8HBSa+/TImW+5JCeuQeRkm5NMpJWZG3hSuFU=");
    EXPECT_EQ(sha256_base64("abc"), "ungWv48Bz+pBQUDeXa4iI7ADYaOWF3qctBD/YfIAFa0=");
    EXPECT_EQ(sha256_base64(std::string(1000, 'a')), "Qe3s5C1j6Nm/UVqbppMuHCDLyfWl0TRkWttdsblzfqM=");
}

TEST(ReportHtml, JsonValueKeepsNumbersAsWritten) {
    const JsonValue v = parse_json(R"({"seed": 18446744073709551615, "x": -0.0, "tiny": 5e-324, "s": "a\u00e9"})");
    EXPECT_EQ(v.find("seed")->count(), 18446744073709551615ULL);
    EXPECT_EQ(v.find("x")->text, "-0.0");
    EXPECT_TRUE(std::signbit(*v.find("x")->number()));
    EXPECT_EQ(*v.find("tiny")->number(), 4.9406564584124654e-324);
    EXPECT_EQ(v.find("s")->string_or(), "a\xc3\xa9");
    EXPECT_EQ(v.find("missing"), nullptr);
    EXPECT_FALSE(v.find("x")->count().has_value());
}

// The engine's own report of a run with two bugs: the summary, and each
// failure a section with its picture and drawable differences and cycles.
TEST(ReportHtml, TheEnginesReportRendersEachFailure) {
    fake::FakeClock clock;
    fake::Counters counters;
    DiffOptions options;
    options.impl = "fake <impl>";
    options.cases = 120;
    options.keep_going = true;
    options.schedule.large_vertices = 0;
    const fake::Behaviour two_bugs = [](const fake::Call& run) {
        if (run.graph.edges.empty() && !run.graph.vertices.empty()) {
            return fake::exited(3, "Traceback (most recent call last):\nValueError: <no edges>\n");
        }
        if (run.graph.edges.size() < 3) return fake::answer(fake::right_faces(run.graph));
        std::vector<std::vector<VertexId>> cycles = boundary_cycles(build(run.graph));
        for (auto& c : cycles) std::reverse(c.begin() + 1, c.end());
        return fake::answer(io::write_faces(cycles));
    };
    const DiffResult result = run_diff(options, {}, fake::factory(two_bugs, clock, counters), clock);
    ASSERT_EQ(result.failures.size(), 2U);
    const std::string json = report_json(options, result);
    EXPECT_TRUE(has(json, R"("conventions": {"face_on_right": false, "one_based": false,)"));
    EXPECT_TRUE(has(json, R"("vertices": [)"));
    const std::string page = render_html_report(json);
    EXPECT_TRUE(has(page, "<h2>Summary: 2 distinct failures</h2>"));
    EXPECT_EQ(occurrences(page, "<li><a href=\"#failure-"), 2U);
    EXPECT_EQ(occurrences(page, "<section class=\"card failure\""), 2U);
    EXPECT_EQ(occurrences(page, "<svg "), 2U);
    EXPECT_FALSE(has(page, " id=\"edges\""));  // the pictures' ids are data-id on the page
    EXPECT_TRUE(has(page, "data-id=\"edges\""));
    EXPECT_TRUE(has(page, "the command: fake &lt;impl&gt;"));
    EXPECT_TRUE(has(page, "non-zero exit (status 3): ValueError: &lt;no edges&gt;"));
    EXPECT_TRUE(has(page, "<span class=\"kind\">reversed-cycle</span>"));
    EXPECT_TRUE(has(page, "class=\"walk\" tabindex=\"0\" data-ink=\"walk\" data-walk=\""));
    EXPECT_TRUE(has(page, "data-ink=\"reference\""));  // the reference's cycles
    EXPECT_TRUE(has(page, "data-ink=\"answer\""));     // the answer's, as read
    EXPECT_TRUE(has(page, "<title>v0 ("));             // each vertex's exact coordinates
    EXPECT_TRUE(has(page, " data-edges=\""));
}

}  // namespace
}  // namespace dcel::diff
