// dcel check GRAPH ANSWER: compares another implementation's answer for GRAPH
// with the reference. Exit 0 agrees, 1 differs (an unreadable ANSWER is a
// difference), 2 usage error or an unreadable or invalid GRAPH.
#include <variant>

#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/report.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::cli {

namespace {

constexpr const char* kCheckHelp =
    "Compare ANSWER, another implementation's output for GRAPH, with the reference.\n"
    "ANSWER is either the faces form, {\"faces\": [[v, ...], ...]} or a bare [[v, ...], ...]\n"
    "(every boundary cycle as vertex ids in next order, as `dcel faces` prints; cycle\n"
    "order and rotation do not matter, orientation does), or a whole DCEL dump in the\n"
    "`dcel build` format (validated, then compared up to the numbering of half-edges\n"
    "and faces). Either file may be - for stdin, not both. See docs/formats.md.\n"
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

std::string agreement(const Dcel& d, bool dump) {
    if (dump) {
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
    cmd->add_option("GRAPH", *graph, "Graph JSON file, or - for stdin")->required();
    cmd->add_option("ANSWER", *answer, "The answer: faces form or DCEL dump, or - for stdin")->required();
    cmd->add_flag("--json", *json, "Print the report as JSON: {\"agrees\": ..., \"count\": ..., \"differences\": [...]}");
    cmd->callback([&action, graph, answer, json] {
        action = [graph, answer, json] {
            if (*graph == "-" && *answer == "-") throw UsageError("check: GRAPH and ANSWER cannot both be - (stdin)");
            const Dcel reference = load_reference(*graph);
            check::Report report;
            bool dump = false;
            try {
                const std::string text = read_input(*answer);
                auto parsed = io::read_answer(text);
                if (auto* faces = std::get_if<check::FacesAnswer>(&parsed)) {
                    report = check::compare_faces(reference, *faces);
                } else {
                    dump = true;
                    report = check::compare_dump(reference, std::get<DcelDump>(parsed));
                }
            } catch (const InvalidInput& e) {
                report = check::unreadable_answer("ANSWER " + display_name(*answer) + ": " + e.what());
            } catch (const UsageError& e) {
                report = check::unreadable_answer(std::string("ANSWER: ") + e.what());
            }
            if (*json) {
                write_stdout(check::report_json(report));
            } else {
                write_stdout(report.agrees() ? agreement(reference, dump) : check::report_text(report));
            }
            return report.agrees() ? kExitOk : kExitInvalid;
        };
    });
}

}  // namespace dcel::cli
