// dcel check GRAPH ANSWER: compares another implementation's answer for GRAPH
// with the reference. Exit 0 agrees, 1 differs (an unreadable ANSWER is a
// difference), 2 usage error or an unreadable or invalid GRAPH.
#include <algorithm>

#include "answer_options.hpp"
#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/check/answer.hpp"
#include "dcel/check/report.hpp"
#include "dcel/error.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::cli {

namespace {

constexpr const char* kCheckHelp =
    "Compare ANSWER, another implementation's output for GRAPH, with the reference.\n"
    "ANSWER is one of these kinds (--answer; detected from its shape when not given):\n"
    "  faces     {\"faces\": [[v, ...], ...]} or [[v, ...], ...]: every boundary cycle as\n"
    "            vertex ids in next order, as `dcel faces` prints (cycle order and\n"
    "            rotation do not matter, direction does)\n"
    "  dump      a whole DCEL in the `dcel build` format (validated, then compared up to\n"
    "            the numbering of half-edges and faces)\n"
    "  polygons  the bounded faces, each a shell and its holes, as vertex-id or [x, y]\n"
    "            rings: {\"polygons\": [[shell, hole, ...], ...]} or GeoJSON\n"
    "  rings     one ring per bounded face, no holes: {\"rings\": [ring, ...]}\n"
    "docs/checking.md says what each kind is compared with. Either file may be - for\n"
    "stdin, not both.\n"
    "Exit: 0 agrees, 1 differs (the report: the count, then one line per difference;\n"
    "an ANSWER that cannot be read or parsed is a difference too), 2 usage error or an\n"
    "unreadable or invalid GRAPH. --json prints the report as one JSON object.\n"
    "Example:\n"
    "  dcel faces graph.json > mine.json && dcel check graph.json mine.json\n"
    "  agrees: the answer has the 2 boundary cycles of the reference";

// The graph, or UsageError: a bad GRAPH is the caller's mistake, not a difference.
Dcel load_reference(const std::string& path) {
    std::string text;
    try {
        text = read_input(path);
    } catch (const UsageError& e) {
        throw UsageError(std::string("GRAPH: ") + e.what());
    }
    try {
        return build(io::read_graph(text));
    } catch (const InvalidInput& e) {
        throw UsageError("GRAPH " + display_name(path) + " is not a valid graph: " + e.what());
    }
}

std::string agreement(const Dcel& d, check::AnswerKind kind) {
    if (kind == check::AnswerKind::EvenOdd) {
        const std::vector<char> odd = check::odd_faces(d);
        const auto regions = static_cast<std::size_t>(std::count(odd.begin(), odd.end(), char{1}));
        return "agrees: the answer has the " + std::to_string(regions) + " even-odd regions of the reference as polygons\n";
    }
    if (kind == check::AnswerKind::Polygons || kind == check::AnswerKind::Rings) {
        std::size_t bounded = d.num_faces() - 1;
        return "agrees: the answer has the " + std::to_string(bounded) + " bounded faces of the reference as " +
               std::string(check::answer_kind_name(kind)) + "\n";
    }
    if (kind == check::AnswerKind::Dump) {
        return "agrees: the dump is the reference DCEL (" + std::to_string(d.num_vertices()) + " vertices, " +
               std::to_string(d.num_half_edges()) + " half-edges, " + std::to_string(d.num_faces()) +
               " faces) up to numbering\n";
    }
    std::size_t cycles = 0;
    std::vector<char> seen(d.num_half_edges(), 0);
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        if (seen[h] != 0) continue;
        ++cycles;
        for (const HalfEdgeId x : d.cycle(HalfEdgeId(h))) seen[x.index()] = 1;
    }
    return "agrees: the answer has the " + std::to_string(cycles) + " boundary cycles of the reference\n";
}

}  // namespace

void add_check_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("check", "Compare another implementation's answer for a graph with the reference");
    cmd->footer(kCheckHelp);
    auto graph = std::make_shared<std::string>();
    auto answer = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    auto options = std::make_shared<AnswerOptions>();
    cmd->add_option("GRAPH", *graph, "Graph JSON file, or - for stdin")->required();
    cmd->add_option("ANSWER", *answer, "The answer (see --answer), or - for stdin")->required();
    add_answer_options(*cmd, options);
    cmd->add_flag("--json", *json,
                  "Print the report as JSON: {\"agrees\": ..., \"count\": ..., \"differences\": [...], \"notes\": [...]}");
    cmd->callback([&action, graph, answer, json, options] {
        action = [graph, answer, json, options] {
            if (*graph == "-" && *answer == "-") throw UsageError("check: GRAPH and ANSWER cannot both be - (stdin)");
            const Dcel reference = load_reference(*graph);
            check::Report report;
            check::AnswerKind kind = options->kind.value_or(check::AnswerKind::Faces);
            try {
                const std::string text = read_input(*answer);
                const check::Answer parsed = check::read_answer(text, options->kind);
                kind = parsed.kind;
                report = check::compare(reference, parsed, options->conventions);
            } catch (const InvalidInput& e) {
                report = check::unreadable_answer("ANSWER " + display_name(*answer) + ": " + e.what());
            } catch (const UsageError& e) {
                report = check::unreadable_answer(std::string("ANSWER: ") + e.what());
            }
            if (*json) {
                write_stdout(check::report_json(report));
            } else {
                std::string text = check::report_text(report);
                if (report.agrees()) text.replace(0, text.find('\n') + 1, agreement(reference, kind));
                write_stdout(text);
            }
            return report.agrees() ? kExitOk : kExitInvalid;
        };
    });
}

}  // namespace dcel::cli
