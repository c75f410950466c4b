// Reading the documents of `dcel edit` and of --names:
//
// Face names: a JSON object from each name to a point inside its face,
//   {"West": [1, 1], "East": [6, 1]}
//
// An edit script: optional names, then the steps, run in order:
//   {"names": {"West": [1, 1], ...},
//    "steps": [{"split_edge": {"edge": 6, "at": [4, 4]}},
//              {"add_edge": {"from": 11, "to": 12}},
//              {"add_edge_to_point": {"from": 4, "to": [6, 5]}},
//              {"add_vertex": {"at": [1, 1]}},
//              {"remove_edge": {"edge": 3}},
//              {"remove_vertex": {"vertex": 10}},
//              {"merge_edges": {"vertex": 7}},
//              {"name": {"Northwest": [1, 5]}},
//              {"locate": {"at": [6, 5]}},
//              {"stab": {"from": [1, 3], "to": [7, 3]}}]}
// Each step is an object with one member: the operation, and its arguments.
// Errors are InvalidInput with a JSON path, like the graph reader's.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dcel/geometry/point.hpp"
#include "dcel/ids.hpp"

namespace dcel::cli {

struct NamedPoint {
    std::string name;
    Point at;
};

struct ScriptStep {
    enum class Op {
        Name,
        SplitEdge,
        AddEdge,
        AddEdgeToPoint,
        AddVertex,
        RemoveEdge,
        RemoveVertex,
        MergeEdges,
        Locate,
        Stab
    };
    Op op = Op::Locate;
    std::string where;              // "steps[3]", for messages
    std::vector<NamedPoint> names;  // Name: the names to set
    Index first = kNoIndex;         // edge, vertex, or "from" vertex
    Index second = kNoIndex;        // "to" vertex
    Point p;                        // "at", or the "to"/"from" point
    Point q;                        // Stab: "to"
};

struct EditScript {
    std::vector<NamedPoint> names;
    std::vector<ScriptStep> steps;
};

[[nodiscard]] const char* op_name(ScriptStep::Op op);
[[nodiscard]] std::vector<NamedPoint> read_face_names(std::string_view text);
[[nodiscard]] EditScript read_edit_script(std::string_view text);

}  // namespace dcel::cli
