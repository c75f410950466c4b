// The HTML page of a JSON report (report_html.hpp), read from the report's
// tree (json_value.hpp). The picture is the --svg drawing made again from
// the counterexample's exact bytes and the answer the report keeps, read
// under the report's answer kind and conventions.
#include "dcel/diff/report_html.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/check/answer_drawing.hpp"
#include "dcel/check/counterexample_svg.hpp"
#include "dcel/check/session.hpp"
#include "dcel/diff/failure_class.hpp"
#include "dcel/diff/html_text.hpp"
#include "dcel/diff/report.hpp"
#include "dcel/diff/report_html_assets.hpp"
#include "dcel/diff/sha256.hpp"
#include "dcel/error.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::diff {
namespace {

constexpr std::size_t kMaxListed = 60;      // cycles or polygons listed per answer
constexpr std::size_t kMaxListedIds = 120;  // ids shown of one cycle
constexpr std::size_t kShownCases = 20;     // case numbers listed per failure

// ---- The report's tree, read leniently: a missing field reads as empty.

const JsonValue& at(const JsonValue& v, std::string_view key) {
    static const JsonValue kMissing{};
    const JsonValue* p = v.find(key);
    return p != nullptr ? *p : kMissing;
}
std::string str(const JsonValue& v, std::string_view key) { return at(v, key).string_or(); }
std::uint64_t num(const JsonValue& v, std::string_view key) { return at(v, key).count().value_or(0); }
bool flag(const JsonValue& v, std::string_view key) { return at(v, key).bool_or(false); }
std::string text(const JsonValue& v, std::string_view key) { return html_text(str(v, key)); }

std::string plural(std::uint64_t n, const std::string& noun) { return count(static_cast<std::size_t>(n), noun); }
std::string ms_text(std::uint64_t ms) { return seconds(std::chrono::milliseconds(static_cast<std::int64_t>(ms))); }
bool starts_with(const std::string& s, std::string_view prefix) { return s.rfind(prefix, 0) == 0; }
std::string sentence(std::string s) {
    if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
    return s;
}

std::string size_text(const JsonValue& v) {
    const std::uint64_t vertices = num(v, "vertices"), edges = num(v, "edges");
    return std::to_string(vertices) + (vertices == 1 ? " vertex, " : " vertices, ") + plural(edges, "edge");
}

// "small-integers, normal and huge coordinates".
std::string classes_text(const JsonValue& classes) {
    std::string s;
    for (std::size_t i = 0; i < classes.items.size(); ++i) {
        s += i == 0 ? "" : (i + 1 == classes.items.size() ? " and " : ", ");
        s += classes.items[i].string_or();
    }
    return s + " coordinates";
}

check::Conventions conventions_of(const JsonValue& report) {
    const JsonValue& c = at(report, "conventions");
    check::Conventions out;
    out.face_on_right = flag(c, "face_on_right");
    out.one_based = flag(c, "one_based");
    out.unoriented = flag(c, "unoriented");
    out.isolated_cycles = flag(c, "isolated_cycles");
    out.holes_unattached = flag(c, "holes_unattached");
    return out;
}

// A crash's or an exit's label with the error line of its stderr, as the
// text report's summary has it.
std::string label_with_error_line(const JsonValue& outcome) {
    std::string label = str(outcome, "label");
    if (starts_with(label, "crash") || starts_with(label, "non-zero exit")) {
        const std::string line = meaningful_line(str(outcome, "stderr_tail"));
        if (!line.empty()) label += ": " + line;
    }
    return label;
}

// ---- Walks: what the script draws when a list item is hovered.

std::string ids_text(const std::vector<Index>& ids) {
    std::string s = "[";
    for (std::size_t i = 0; i < ids.size() && i < kMaxListedIds; ++i) {
        s += (i == 0 ? "" : ", ") + (ids[i] == kNoIndex ? std::string("null") : std::to_string(ids[i]));
    }
    if (ids.size() > kMaxListedIds) s += ", ... (" + std::to_string(ids.size()) + " in all)";
    return s + "]";
}

// Attributes that make an element a walk: its vertices (a null id left out),
// closed or not, and its ink ("walk", "answer" or "reference").
std::string walk_attributes(const std::vector<Index>& ids, bool closed, const char* ink) {
    std::string walk;
    for (const Index v : ids) {
        if (v != kNoIndex) walk += (walk.empty() ? "" : " ") + std::to_string(v);
    }
    if (walk.empty()) return "";
    return std::string(" class=\"walk\" tabindex=\"0\" data-ink=\"") + ink + "\" data-walk=\"" + walk + "\"" +
           (closed ? " data-closed" : "");
}

// An answer as the picture draws it: cycles, or polygons of vertex rings.
struct Shapes {
    std::vector<std::vector<Index>> cycles;
    std::vector<std::vector<std::vector<Index>>> polygons;
};

std::optional<Shapes> shapes_of(const std::string& answer, std::optional<check::AnswerKind> kind, const Dcel& reference,
                                const check::Conventions& conventions, std::string& why_not) {
    if (!kind) {
        why_not = "the report names no answer kind";
        return std::nullopt;
    }
    try {
        const check::Answer a = check::read_answer(answer, kind);
        return Shapes{check::drawn_cycles(a, conventions), check::drawn_regions(a, reference, conventions)};
    } catch (const InvalidInput& e) {
        why_not = e.what();
        return std::nullopt;
    }
}

bool region_kind(check::AnswerKind k) {
    return k == check::AnswerKind::Polygons || k == check::AnswerKind::Rings || k == check::AnswerKind::EvenOdd;
}

std::string shapes_html(const Shapes& s, check::AnswerKind kind, const char* ink) {
    const std::size_t n = region_kind(kind) ? s.polygons.size() : s.cycles.size();
    if (n == 0) return region_kind(kind) ? "<p class=\"quiet\">no polygons</p>\n" : "<p class=\"quiet\">no cycles</p>\n";
    std::string out = "<ol class=\"walks\" start=\"0\">\n";
    for (std::size_t i = 0; i < n && i < kMaxListed; ++i) {
        if (!region_kind(kind)) {
            out += "<li" + walk_attributes(s.cycles[i], true, ink) + "><code>" + html_text(ids_text(s.cycles[i])) +
                   "</code></li>\n";
            continue;
        }
        out += "<li>";
        for (std::size_t r = 0; r < s.polygons[i].size(); ++r) {
            out += r == 0 ? "shell " : (r == 1 ? "; holes " : ", ");
            out += "<span" + walk_attributes(s.polygons[i][r], true, ink) + "><code>" +
                   html_text(ids_text(s.polygons[i][r])) + "</code></span>";
        }
        out += "</li>\n";
    }
    out += "</ol>\n";
    if (n > kMaxListed) out += "<p class=\"cut\">[" + std::to_string(n - kMaxListed) + " more not listed]</p>\n";
    return out;
}

// ---- The run

std::string verdict_line(const JsonValue& report) {
    const std::uint64_t cases = num(report, "cases_run"), first = num(report, "first_case");
    const std::size_t failures = at(report, "failures").items.size();
    const std::string range = cases == 0 ? ""
                                         : " (" + std::to_string(first) + " to " + std::to_string(first + cases - 1) +
                                               ", seed " + at(report, "seed").text + ")";
    const std::string elapsed = " in " + ms_text(num(report, "elapsed_ms"));
    if (failures > 0)
        return "dcel diff: " + plural(failures, "distinct failure") + " in " + plural(cases, "case") + range + elapsed;
    if (!flag(report, "agrees")) return "dcel diff: no case was checked in " + plural(cases, "case") + range + ": no pass";
    return "dcel diff: agrees on " + plural(num(report, "checked"), "case") + range + elapsed;
}

std::string fact(const std::string& name, const std::string& value_html) {
    return "<dt>" + html_text(name) + "</dt><dd>" + value_html + "</dd>\n";
}

std::string run_html(const JsonValue& report) {
    const std::string kind = str(report, "answer_kind");
    const std::string stopped = str(report, "stopped_by");
    std::string out = "<dl>\n";
    out += fact("command", "<code>" + text(report, "command") + "</code>");
    if (const std::uint64_t shards = num(report, "shards"); shards > 0) {
        out += fact("shards", html_text(std::to_string(shards) + " reports of --shard K/" + std::to_string(shards) +
                                        ", joined by dcel diff-merge (the time is the longest shard's)"));
    } else if (const std::string shard = str(report, "shard"); !shard.empty()) {
        out += fact("shard", html_text(shard + ": the cases i with i mod N = K - 1"));
    }
    out += fact("answer kind", kind.empty() ? "detected from each answer" : html_text(kind));
    out += fact("cases",
                html_text(std::to_string(num(report, "cases_run")) + " run, " + std::to_string(num(report, "checked")) +
                          " checked, " + std::to_string(num(report, "skipped")) + " skipped (no graph in the classes), " +
                          std::to_string(num(report, "skipped_by_impl")) + " skipped by the implementation"));
    out += fact("stopped by", html_text(stopped == "cases" ? "the cases ran out" : stopped));
    out += fact("time", html_text(ms_text(num(report, "elapsed_ms")) + " (the reference's CPU time " +
                                  ms_text(num(report, "reference_cpu_ms")) + ")"));
    return out + "</dl>\n";
}

// The cases the implementation skipped, by reason, and the slow ones.
std::string skips_and_slow_html(const JsonValue& report) {
    std::string out;
    const std::vector<JsonValue>& reasons = at(report, "skip_reasons").items;
    if (!reasons.empty()) {
        out += "<section class=\"card\" id=\"skips\">\n<h2>Skipped by the implementation (never a pass)</h2>\n<ul>\n";
        for (const JsonValue& r : reasons) {
            out += "<li>" + html_text(plural(num(r, "cases"), "case")) + ": " + text(r, "reason") + "</li>\n";
        }
        out += "</ul>\n</section>\n";
    }
    const JsonValue& slow = at(report, "slow");
    if (num(slow, "count") > 0) {
        out += "<section class=\"card\" id=\"performance\">\n<h2>Performance notes: " +
               html_text(plural(num(slow, "count"), "slow case")) + ", each within its limit</h2>\n<ul>\n";
        for (const JsonValue& c : at(slow, "cases").items) {
            out += "<li>" +
                   html_text("case " + std::to_string(num(c, "number")) + " (family " + str(c, "family") + ", " +
                             size_text(c) + "): " + ms_text(num(c, "ms")) + ", limit " + ms_text(num(c, "limit_ms"))) +
                   "</li>\n";
        }
        out += "</ul>\n</section>\n";
    }
    return out;
}

std::string summary_html(const JsonValue& report) {
    const std::vector<JsonValue>& failures = at(report, "failures").items;
    if (failures.empty()) return "";
    std::string out = "<section class=\"card\" id=\"summary\">\n<h2>Summary: " +
                      html_text(plural(failures.size(), "distinct failure")) + "</h2>\n<ol>\n";
    for (const JsonValue& f : failures) {
        out += "<li><a href=\"#failure-" + std::to_string(num(f, "id")) + "\">" +
               html_text(label_with_error_line(at(f, "outcome"))) + "</a>: " +
               html_text(plural(num(f, "occurrences"), "case") + " in " + classes_text(at(f, "classes")) + ", shrunk to " +
                         size_text(at(f, "counterexample"))) +
               "</li>\n";
    }
    return out + "</ol>\n</section>\n";
}

// ---- One failure

// How shrinking went, in the text report's words.
std::string shrink_text(const JsonValue& f) {
    const JsonValue& s = at(f, "shrinking");
    const std::string budget = flag(s, "budget_spent") ? ", stopped by the shrink budget" : "";
    if (!flag(f, "reproduced")) return "not shrunk: run again afresh, the case did not fail the same way";
    if (num(s, "steps") == 0) {
        return "no smaller graph fails the same way (" + plural(num(s, "attempts"), "attempt") + " in " +
               ms_text(num(s, "elapsed_ms")) + budget + ")";
    }
    return "shrunk in " + ms_text(num(s, "elapsed_ms")) + " (" + plural(num(s, "attempts"), "attempt") + ", " +
           plural(num(s, "steps"), "smaller failing graph") + " kept" + budget + ")" +
           (flag(s, "minimal") ? "; no single vertex, edge or coordinate simplification of it fails the same way" : "");
}

// The drawing, inlined: its ids become data-id (a page holds many drawings,
// and the drawing refers to none of its ids).
std::string inline_svg(const std::string& svg) {
    std::string out;
    const std::string_view from = " id=\"";
    std::size_t begin = 0;
    for (std::size_t found = svg.find(from); found != std::string::npos; found = svg.find(from, begin)) {
        out.append(svg, begin, found - begin);
        out += " data-id=\"";
        begin = found + from.size();
    }
    out.append(svg, begin);
    return out;
}

// What one failure section needs, read once.
struct FailureView {
    const JsonValue& report;
    const JsonValue& f;
    const JsonValue& outcome;
    std::optional<PlanarGraph> graph;
    std::optional<Dcel> reference;
    std::optional<check::AnswerKind> kind;
    std::optional<Shapes> answer;  // when the implementation's answer could be read
    std::string why_not_drawn;
    // A session run's counterexample, drawn at its first wrong step instead.
    std::optional<check::Session> session;
    std::size_t step = 0;
};

// The reference's state before the first wrong step, the step in red, as
// dcel diff --svg draws it.
std::string session_picture_html(const FailureView& v) {
    const std::string title = "dcel diff: " + str(v.outcome, "label") + ", case " +
                              std::to_string(num(at(v.f, "case"), "number")) + ", seed " + at(v.report, "seed").text;
    try {
        const std::string svg = check::render_session_step_svg(*v.session, v.step, title);
        const std::string caption =
            v.step < v.session->steps.size()
                ? "The reference's state before step " + std::to_string(v.step) + ", the first answered wrongly (" +
                      check::describe_step(v.session->steps[v.step]) + "), the step in red; vertices by session id."
                : "The reference's state at the end, which the answer gives otherwise; vertices by session id.";
        return "<figure>\n" + inline_svg(svg) + "<figcaption>" + html_text(caption) + "</figcaption>\n</figure>\n";
    } catch (const InvalidInput&) {
        return "<figure><p class=\"cut\">no picture: the session's start graph is no valid graph</p></figure>\n";
    }
}

std::string picture_html(const FailureView& v) {
    if (v.session) return session_picture_html(v);
    if (!v.reference) return "<figure><p class=\"cut\">no picture: the counterexample is no valid graph</p></figure>\n";
    check::CounterexampleDrawing drawing{&*v.graph, &*v.reference};
    drawing.title = "dcel diff: " + str(v.outcome, "label") + ", case " + std::to_string(num(at(v.f, "case"), "number")) +
                    ", seed " + at(v.report, "seed").text;
    drawing.answer_name = "the command: " + str(v.report, "impl");
    if (v.answer) {
        drawing.answer_cycles = v.answer->cycles;
        drawing.answer_polygons = v.answer->polygons;
    }
    return "<figure>\n" + inline_svg(check::render_counterexample_svg(drawing)) +
           "<figcaption>Left the reference, right the implementation's answer. Hover a vertex for its id and exact "
           "coordinates; hover a difference or a cycle to draw it here, click to keep it.</figcaption>\n</figure>\n";
}

// Each difference drawable: a wrong-next as the answer's turn (red) and the
// reference's (blue), anything else as the walk of its vertices.
std::string differences_html(const JsonValue& outcome) {
    const std::vector<JsonValue>& diffs = at(outcome, "differences").items;
    if (diffs.empty()) return "";
    std::string out = "<h3>Differences</h3>\n<ol class=\"differences\">\n";
    for (const JsonValue& d : diffs) {
        std::vector<Index> vs;
        for (const JsonValue& x : at(d, "vertices").items) {
            const std::optional<std::uint64_t> n = x.count();
            vs.push_back(n && *n < kNoIndex ? static_cast<Index>(*n) : kNoIndex);
        }
        const std::string kind = str(d, "kind");
        std::string attributes;
        if (kind == "wrong-next" && vs.size() == 4) {
            attributes = walk_attributes({vs[0], vs[1], vs[2]}, false, "answer") + " data-walk2=\"" + std::to_string(vs[0]) +
                         " " + std::to_string(vs[1]) + " " + std::to_string(vs[3]) + "\"";
        } else {
            attributes = walk_attributes(vs, vs.size() >= 3, "walk");
        }
        out += "<li" + attributes + "><span class=\"kind\">" + html_text(kind) + "</span> " + text(d, "message") + "</li>\n";
    }
    return out + "</ol>\n";
}

std::string answers_html(const FailureView& v) {
    const std::string label = str(v.outcome, "label");
    const std::string reference = str(v.f, "reference");
    std::string out = "<div class=\"cols\">\n<div class=\"ref\">\n<h3>The reference's answer (" +
                      text(v.outcome, "answer_kind") + ")</h3>\n" + html_block(reference);
    if (v.reference && v.kind) {
        std::string ignored;
        if (const auto shapes = shapes_of(reference, v.kind, *v.reference, {}, ignored)) {
            out += shapes_html(*shapes, *v.kind, "reference");
        }
    }
    out += "</div>\n<div class=\"ans\">\n<h3>The implementation's: " + html_text(label) + "</h3>\n";
    if (!starts_with(label, "wrong answer")) out += "<p>" + text(v.outcome, "what") + "</p>\n";
    const std::string out_text = str(v.outcome, "stdout");
    if (!out_text.empty()) out += "<p class=\"quiet\">stdout:</p>\n" + html_block(out_text);
    const std::string err = str(v.outcome, "stderr_tail");
    if (!err.empty()) out += "<p class=\"quiet\">stderr (the end):</p>\n" + html_block(err);
    if (starts_with(label, "wrong answer") && v.kind) {
        if (v.answer) {
            out += "<p class=\"quiet\">as read:</p>\n" + shapes_html(*v.answer, *v.kind, "answer");
        } else {
            out += "<p class=\"quiet\">(not drawn: " + html_text(v.why_not_drawn) + ")</p>\n";
        }
    }
    return out + "</div>\n</div>\n";
}

std::string replay_html(const FailureView& v) {
    const std::string impl = str(v.report, "impl");
    const std::string graph_text = without_newline(str(at(v.f, "counterexample"), "text"));
    std::string out = "<h3>The graph (the command's stdin, its exact bytes)</h3>\n";
    const JsonValue& prefix = at(v.f, "prefix");
    if (!prefix.items.empty()) {
        out += "<p>It fails only after " + html_text(plural(prefix.items.size(), "other graph")) +
               " in the same --stream process; first:</p>\n";
        for (const JsonValue& p : prefix.items) out += html_block(without_newline(p.string_or()), "out", {20, 1000});
        out += "<p>then:</p>\n";
    }
    out += html_block(graph_text, "out", {40, 1000});
    out += "<h3>Replay</h3>\n<p class=\"quiet\">the case (it is shrunk again):</p>\n" +
           html_block(str(v.f, "replay"), "cmd", {5, 1000});
    out += "<p class=\"quiet\">the command on the counterexample:</p>\n" +
           html_block("printf '%s\\n' " + shell_quote(graph_text) + " | " + impl, "cmd", {40, 1000});
    return out;
}

std::string failure_html(const JsonValue& report, const JsonValue& f, std::size_t total) {
    FailureView v{report, f, at(f, "outcome"), std::nullopt, std::nullopt, std::nullopt, std::nullopt, {}, {}, 0};
    const JsonValue* sessions = report.find("sessions");
    try {
        if (sessions != nullptr && sessions->type == io::JsonType::True) {
            v.session = check::read_session(str(at(f, "counterexample"), "text"));
            const JsonValue* k = v.outcome.find("first_wrong_step");
            v.step = std::min<std::size_t>(k != nullptr ? num(v.outcome, "first_wrong_step") : v.session->steps.size(),
                                           v.session->steps.size());
        } else {
            v.graph = io::read_graph(str(at(f, "counterexample"), "text"));
            v.reference.emplace(build(*v.graph));
        }
    } catch (const InvalidInput&) {  // a hand-made or damaged report: the page says there is no picture
        v.graph.reset();
        v.session.reset();
    }
    v.kind = check::answer_kind_from_name(str(v.outcome, "answer_kind"));
    if (v.reference && starts_with(str(v.outcome, "label"), "wrong answer")) {
        v.answer = shapes_of(str(v.outcome, "stdout"), v.kind, *v.reference, conventions_of(report), v.why_not_drawn);
    }

    const std::string id = std::to_string(num(f, "id"));
    std::string out = "<section class=\"card failure\" id=\"failure-" + id + "\"";
    if (v.reference) {
        std::string edges;  // the drawing's edges, in its order: DCEL edge e is half-edges 2e and 2e + 1
        for (Index e = 0; e < v.reference->num_edges(); ++e) {
            const HalfEdgeId h(2 * e);
            edges += (e == 0 ? "" : " ") + std::to_string(v.reference->origin(h).index()) + " " +
                     std::to_string(v.reference->target(h).index());
        }
        out += " data-edges=\"" + edges + "\"";
    }
    out += ">\n<h2>Failure " + id + " of " + std::to_string(total) + ": " + html_text(label_with_error_line(v.outcome)) +
           "</h2>\n";
    const JsonValue& c = at(f, "case");
    std::string cases;
    for (std::size_t i = 0; i < f.find("cases")->items.size() && i < kShownCases; ++i) {
        cases += (i == 0 ? "" : ", ") + at(f, "cases").items[i].text;
    }
    if (num(f, "occurrences") > kShownCases) cases += ", ...";
    out += "<p>" +
           html_text("First on case " + std::to_string(num(c, "number")) + " (family " + str(c, "family") + ", " +
                     size_text(c) + ", " + str(c, "coordinates") + " coordinates), found after " +
                     ms_text(num(f, "found_after_ms")) + "; " + plural(num(f, "occurrences"), "case") +
                     " failed this way (" + cases + "), in " + classes_text(at(f, "classes")) + ".") +
           "</p>\n<p>" + html_text(sentence(shrink_text(f))) +
           ". <strong>Counterexample: " + html_text(size_text(at(f, "counterexample"))) + ".</strong></p>\n";
    out += "<div class=\"grid\">\n" + picture_html(v) + "<div>\n" + differences_html(v.outcome);
    const JsonValue& notes = at(v.outcome, "notes");
    if (!notes.items.empty()) {
        out += "<h3>Notes</h3>\n<ul>\n";
        for (const JsonValue& n : notes.items) out += "<li>" + html_text(n.string_or()) + "</li>\n";
        out += "</ul>\n";
    }
    out += "</div>\n</div>\n" + answers_html(v) + replay_html(v) + "</section>\n";
    return out;
}

}  // namespace

std::string render_html_report(std::string_view report_json) { return render_html_report(parse_json(report_json)); }

std::string render_html_report(const JsonValue& report) {
    if (report.type != io::JsonType::Object || !starts_with(str(report, "format"), "dcel diff report ")) {
        throw InvalidInput(InputErrorKind::Shape,
                           "not a dcel diff report: expected an object with \"format\": \"dcel diff report 1\"");
    }
    const std::string verdict = verdict_line(report);
    const std::size_t failures = at(report, "failures").items.size();
    const std::string_view script = html_report_script();
    std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    out +=
        "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; "
        "script-src 'sha256-" +
        sha256_base64(script) + "'; base-uri 'none'; form-action 'none'\">\n";
    out += "<title>" + html_text(verdict) + "</title>\n<style>" + std::string(html_report_style()) +
           "</style>\n</head>\n<body>\n";
    out += "<header class=\"card verdict" + std::string(failures > 0 ? " fail" : (flag(report, "agrees") ? "" : " empty")) +
           "\" id=\"verdict\">\n<h1>" + html_text(verdict) + "</h1>\n<p>checking <code>" + text(report, "impl") +
           "</code> against the reference DCEL</p>\n" + run_html(report) + "</header>\n";
    out += summary_html(report) + skips_and_slow_html(report);
    for (const JsonValue& f : at(report, "failures").items) out += failure_html(report, f, failures);
    out += "<div id=\"tip\" role=\"tooltip\" hidden></div>\n<script>" + std::string(script) +
           "</script>\n</body>\n</html>\n";
    return out;
}

}  // namespace dcel::diff
