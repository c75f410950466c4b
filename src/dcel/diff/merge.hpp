// `dcel diff-merge`: the JSON reports of the shards of one campaign
// (`dcel diff --shard K/N`) joined into the report one run of all the cases
// would have written. The run's counts are summed; the failures are grouped
// as one run groups them (docs/checking.md, "Grouping"): each case key is
// taken in the order of its first case over all shards, and joins the
// failure of the same signature or makes a new one, whose counterexample is
// the one its shard shrank. So for runs that end by --cases, the merged
// report equals the unsharded one but for times and the command line.
#pragma once

#include <string>
#include <vector>

#include "dcel/diff/json_value.hpp"

namespace dcel::diff {

struct ShardReport {
    std::string name;  // for messages: the file it came from
    JsonValue report;
};

// The merged report as JSON (docs/diff-report.schema.json, with "shards").
// InvalidInput, naming the file, when a report is not a shard report of the
// same campaign as the others (another command, seed or N), a shard is
// given twice or missing, or a report contradicts itself.
[[nodiscard]] JsonValue merge_reports(const std::vector<ShardReport>& shards);

// The document as JSON text, a member or an element per line at the top
// two levels.
[[nodiscard]] std::string write_json(const JsonValue& value);

// What `dcel diff-merge` prints: a line for the whole campaign, then one per
// distinct failure with its replay line.
[[nodiscard]] std::string merged_summary(const JsonValue& merged);

// JUnit XML of a merged report: one test case for the campaign, one failing
// test case per distinct failure.
[[nodiscard]] std::string merged_junit(const JsonValue& merged);

}  // namespace dcel::diff
