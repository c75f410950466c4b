#include "edit_script.hpp"

#include <array>
#include <unordered_set>

#include "dcel/format.hpp"
#include "dcel/io/json_reader.hpp"
#include "dcel/io/limited_readers.hpp"

namespace dcel::cli {
namespace {

using io::JsonReader;
using io::detail::read_point;

constexpr std::string_view kOps[] = {"name",       "split_edge",  "add_edge",      "add_edge_to_point",
                                     "add_vertex", "remove_edge", "remove_vertex", "merge_edges",
                                     "locate",     "stab"};

// {"name": [x, y], ...} at a value position; a name given twice is refused
// like any duplicate key.
std::vector<NamedPoint> read_names(JsonReader& r) {
    std::vector<NamedPoint> out;
    std::unordered_set<std::string> seen;
    r.begin_object(R"(face names {"name": [x, y], ...})");
    while (r.next_member()) {
        std::string name(r.key());
        if (!seen.insert(name).second) r.fail_duplicate_key();
        out.push_back({std::move(name), read_point(r)});
    }
    return out;
}

// The arguments of one operation: an object with the given keys, all required.
template <std::size_t N>
void read_arguments(JsonReader& r, ScriptStep::Op op, const std::array<std::string_view, N>& keys, std::string_view form,
                    ScriptStep& step) {
    r.begin_object(form);
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(keys, seen)) >= 0;) {
        const std::string_view key = keys[static_cast<std::size_t>(k)];
        if (key == "edge") step.first = r.read_index("edge id");
        if (key == "vertex") step.first = r.read_index("vertex id");
        if (key == "at") step.p = read_point(r);
        if (key == "from") {
            if (op == ScriptStep::Op::Stab) {
                step.p = read_point(r);
            } else {
                step.first = r.read_index("vertex id");
            }
        }
        if (key == "to") {
            if (op == ScriptStep::Op::AddEdge) step.second = r.read_index("vertex id");
            if (op == ScriptStep::Op::AddEdgeToPoint) step.p = read_point(r);
            if (op == ScriptStep::Op::Stab) step.q = read_point(r);
        }
    }
    for (std::size_t i = 0; i < N; ++i) {
        if ((seen & (std::uint64_t{1} << i)) == 0) r.fail_missing_key(keys[i], form);
    }
}

ScriptStep read_step(JsonReader& r) {
    ScriptStep step;
    step.where = r.path();
    constexpr std::string_view kStep = R"(a step {"<operation>": {<arguments>}})";
    r.begin_object(kStep);
    if (!r.next_member()) r.fail(InputErrorKind::Shape, "expected a step with one operation, found an empty object");
    const std::string_view key = r.key();
    std::size_t op = 0;
    while (op < std::size(kOps) && kOps[op] != key) ++op;
    if (op == std::size(kOps)) {
        r.fail(InputErrorKind::Shape, "unknown operation " + quote_for_message(key) +
                                          ": expected one of name, split_edge, add_edge, add_edge_to_point, "
                                          "add_vertex, remove_edge, remove_vertex, merge_edges, locate, stab");
    }
    step.op = static_cast<ScriptStep::Op>(op);
    using Op = ScriptStep::Op;
    switch (step.op) {
        case Op::Name: step.names = read_names(r); break;
        case Op::SplitEdge:
            read_arguments(r, step.op, std::array<std::string_view, 2>{"edge", "at"}, R"({"edge": e, "at": [x, y]})", step);
            break;
        case Op::AddEdge:
            read_arguments(r, step.op, std::array<std::string_view, 2>{"from", "to"}, R"({"from": u, "to": v})", step);
            break;
        case Op::AddEdgeToPoint:
            read_arguments(r, step.op, std::array<std::string_view, 2>{"from", "to"}, R"({"from": u, "to": [x, y]})", step);
            break;
        case Op::AddVertex:
        case Op::Locate: read_arguments(r, step.op, std::array<std::string_view, 1>{"at"}, R"({"at": [x, y]})", step); break;
        case Op::RemoveEdge:
            read_arguments(r, step.op, std::array<std::string_view, 1>{"edge"}, R"({"edge": e})", step);
            break;
        case Op::RemoveVertex:
        case Op::MergeEdges:
            read_arguments(r, step.op, std::array<std::string_view, 1>{"vertex"}, R"({"vertex": v})", step);
            break;
        case Op::Stab:
            read_arguments(r, step.op, std::array<std::string_view, 2>{"from", "to"}, R"({"from": [x, y], "to": [x, y]})",
                           step);
            break;
    }
    if (r.next_member()) r.fail(InputErrorKind::Shape, "a step holds one operation; split it into several steps");
    return step;
}

}  // namespace

const char* op_name(ScriptStep::Op op) { return kOps[static_cast<std::size_t>(op)].data(); }

std::vector<NamedPoint> read_face_names(std::string_view text) {
    JsonReader r(text);
    std::vector<NamedPoint> names = read_names(r);
    r.end_document();
    return names;
}

EditScript read_edit_script(std::string_view text) {
    JsonReader r(text);
    EditScript script;
    static constexpr std::array<std::string_view, 2> kKeys{"names", "steps"};
    constexpr std::string_view kForm = R"(an edit script {"names": {...}, "steps": [...]})";
    r.begin_object(kForm);
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        if (k == 0) {
            script.names = read_names(r);
        } else {
            r.begin_array("an array of steps");
            while (r.next_element()) script.steps.push_back(read_step(r));
        }
    }
    if ((seen & 2U) == 0) r.fail_missing_key("steps", kForm);
    r.end_document();
    return script;
}

}  // namespace dcel::cli
