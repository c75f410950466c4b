// dcel diff-merge REPORT...: the JSON reports of the shards of one campaign
// (dcel diff --shard K/N --report FILE) joined into one report
// (dcel/diff/merge.hpp). Exit 0 when the campaign agrees, 1 when it found
// failures, 2 when the reports cannot be merged (unreadable, not a shard
// report, another campaign, a shard given twice or missing): a merge that
// fails must not read as "failures found".
#include "commands.hpp"
#include "dcel/diff/merge.hpp"
#include "dcel/diff/report_html.hpp"
#include "dcel/error.hpp"

namespace dcel::cli {
namespace {

struct MergeOptions {
    std::vector<std::string> reports;
    std::string report, junit, html;
};

int run_merge(const MergeOptions& o) {
    diff::JsonValue merged;
    try {
        std::vector<diff::ShardReport> shards;
        for (const std::string& path : o.reports) {
            const std::string text = read_input(path);
            try {
                shards.push_back({path, diff::parse_json(text)});
            } catch (const InvalidInput& e) {
                throw UsageError(path + ": not a JSON report: " + e.what());
            }
        }
        merged = diff::merge_reports(shards);
    } catch (const InvalidInput& e) {
        throw UsageError(std::string("diff-merge: ") + e.what());
    } catch (const UsageError& e) {
        throw UsageError(std::string("diff-merge: ") + e.what());
    }
    write_stdout(diff::merged_summary(merged));
    if (!o.report.empty()) write_file(o.report, diff::write_json(merged));
    if (!o.junit.empty()) write_file(o.junit, diff::merged_junit(merged));
    if (!o.html.empty()) write_file(o.html, diff::render_html_report(merged));
    const diff::JsonValue* agrees = merged.find("agrees");
    return agrees != nullptr && agrees->bool_or(false) ? kExitOk : kExitInvalid;
}

}  // namespace

void add_diff_merge_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("diff-merge",
                                   "Join the JSON reports of the shards of one dcel diff campaign (--shard K/N) into "
                                   "the report of the whole");
    auto o = std::make_shared<MergeOptions>();
    cmd->add_option("REPORT", o->reports, "The shards' reports (dcel diff --shard K/N --report FILE), all N of them")
        ->required();
    cmd->add_option("--report", o->report, "Write the merged report as JSON to FILE")->type_name("FILE");
    cmd->add_option("--junit", o->junit, "Write JUnit XML to FILE: one test case per distinct failure")->type_name("FILE");
    cmd->add_option("--html", o->html, "Write the merged report as one self-contained HTML page to FILE")->type_name("FILE");
    cmd->callback([&action, o] { action = [o] { return run_merge(*o); }; });
}

}  // namespace dcel::cli
