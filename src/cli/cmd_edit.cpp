// dcel edit GRAPH SCRIPT: runs an edit script (edit_script.hpp) on the DCEL
// built from GRAPH, with face names carried along as face data: splits copy
// a country's name to both parts, merges keep the smaller id's name.
// Prints one result line per step, then every face with its name and outer
// cycle, then the resulting graph (also written to --graph-out FILE).
// A refused edit stops the script: exit 1, the reason on stderr.
#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/edit.hpp"
#include "dcel/error.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/to_graph.hpp"
#include "dcel/validate.hpp"
#include "edit_script.hpp"
#include "face_names.hpp"
#include "json_out.hpp"

namespace dcel::cli {
namespace {

template <class Id>
std::string json_id_change(const char* kind, const IdChange<Id>& c) {
    std::string s;
    auto field = [&](const char* name, Id id) {
        if (id.is_null()) return;
        s += (s.empty() ? "" : ", ") + std::string("\"") + name + "\": " + std::to_string(id.index());
    };
    field("added", c.added);
    field("added_from", c.added_from);
    field("removed", c.removed);
    field("merged_into", c.merged_into);
    field("moved", c.moved);
    return s.empty() ? s : "\"" + std::string(kind) + "\": {" + s + "}";
}

std::string json_change(const Change& c) {
    std::string s;
    for (const std::string& part :
         {json_id_change("vertices", c.vertices), json_id_change("edges", c.edges), json_id_change("faces", c.faces)}) {
        if (!part.empty()) s += (s.empty() ? "" : ", ") + part;
    }
    return "{" + s + "}";
}

std::string json_cycle(const Dcel& d, HalfEdgeId start) {
    std::string s = "[";
    for (const HalfEdgeId h : d.cycle(start)) s += (s.size() == 1 ? "" : ", ") + std::to_string(d.origin(h).index());
    return s + "]";
}

class ScriptRun {
public:
    ScriptRun(Dcel& d, FaceNames& names, std::string source, bool check)
        : d_(d), names_(names), source_(std::move(source)), check_(check) {}

    // One step; its result as a JSON object on one line.
    std::string run(const ScriptStep& s) {
        using Op = ScriptStep::Op;
        const std::string op = std::string("{\"op\": \"") + op_name(s.op) + "\"";
        std::string out;
        try {
            switch (s.op) {
                case Op::Name: {
                    const std::vector<FaceId> named = name_faces(d_, s.names, where(s), names_);
                    std::string faces;
                    for (std::size_t i = 0; i < named.size(); ++i) {
                        faces += (faces.empty() ? "" : ", ") + json_string(s.names[i].name) + ": " +
                                 std::to_string(named[i].index());
                    }
                    return op + ", \"faces\": {" + faces + "}}";
                }
                case Op::Locate:
                    return op + ", \"at\": " + json_point(s.p) + ", " +
                           json_location_members(d_, locate_by_scan(d_, s.p), &names_) + "}";
                case Op::Stab:
                    return op + ", \"from\": " + json_point(s.p) + ", \"to\": " + json_point(s.q) + ", " +
                           json_stab_members(stab_segment(d_, s.p, s.q), &names_) + "}";
                case Op::SplitEdge:
                    out = op + ", \"edge\": " + std::to_string(s.first) + ", \"at\": " + json_point(s.p);
                    return edited(out, split_edge(d_, EdgeId(s.first), s.p));
                case Op::AddEdge:
                    out = op + ", \"from\": " + std::to_string(s.first) + ", \"to\": " + std::to_string(s.second);
                    return edited(out, add_edge(d_, VertexId(s.first), VertexId(s.second)));
                case Op::AddEdgeToPoint:
                    out = op + ", \"from\": " + std::to_string(s.first) + ", \"to\": " + json_point(s.p);
                    return edited(out, add_edge_to_point(d_, VertexId(s.first), s.p));
                case Op::AddVertex: out = op + ", \"at\": " + json_point(s.p); return edited(out, add_vertex(d_, s.p));
                case Op::RemoveEdge:
                    out = op + ", \"edge\": " + std::to_string(s.first);
                    return edited(out, remove_edge(d_, EdgeId(s.first)));
                case Op::RemoveVertex:
                    out = op + ", \"vertex\": " + std::to_string(s.first);
                    return edited(out, remove_isolated_vertex(d_, VertexId(s.first)));
                case Op::MergeEdges:
                    out = op + ", \"vertex\": " + std::to_string(s.first);
                    return edited(out, merge_collinear_edges(d_, VertexId(s.first)));
            }
        } catch (const InvalidInput& e) {
            throw InvalidInput(e.kind(), where(s) + ": " + e.what(), e.vertices(), e.edges());
        } catch (const TopologyError& e) {
            throw TopologyError(where(s) + ": " + e.what());
        }
        return out;
    }

private:
    [[nodiscard]] std::string where(const ScriptStep& s) const { return display_name(source_) + ": " + s.where; }

    std::string edited(const std::string& head, const Change& c) {
        names_.follow(c);
        if (check_) {
            if (const auto v = validate(d_)) {
                throw TopologyError(std::string("internal error: the DCEL is invalid after this edit: [") +
                                    to_string(v->invariant) + "] " + v->message);
            }
        }
        return head + ", \"change\": " + json_change(c) + "}";
    }

    Dcel& d_;
    FaceNames& names_;
    std::string source_;
    bool check_;
};

}  // namespace

void add_edit_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("edit", "Run an edit script on a graph's DCEL, carrying face names along");
    auto path = std::make_shared<std::string>();
    auto script_path = std::make_shared<std::string>();
    auto graph_out = std::make_shared<std::string>();
    auto check = std::make_shared<bool>(false);
    cmd->add_option("GRAPH", *path, "Graph JSON file, or - for stdin")->required();
    cmd->add_option("SCRIPT", *script_path, "Edit script JSON file (see docs/editing.md)")->required();
    cmd->add_option("--graph-out", *graph_out, "Also write the resulting graph to this file");
    cmd->add_flag("--check", *check, "Run validate() after every edit (O(n log n) each)");
    cmd->callback([&action, path, script_path, graph_out, check] {
        action = [path, script_path, graph_out, check] {
            require_one_stdin({{"GRAPH", path.get()}, {"SCRIPT", script_path.get()}});
            const PlanarGraph g = load_graph(*path);
            Dcel d = build_dcel(*path, g);
            const std::string text = read_input(*script_path);
            const EditScript script = with_source(*script_path, [&] { return read_edit_script(text); });
            FaceNames names(d);
            name_faces(d, script.names, display_name(*script_path) + ": names", names);
            ScriptRun run(d, names, *script_path, *check);
            std::string out = "{\"steps\": [";
            for (std::size_t i = 0; i < script.steps.size(); ++i) {
                out += (i == 0 ? "\n  " : ",\n  ") + run.run(script.steps[i]);
            }
            out += "\n],\n\"faces\": [";
            for (Index f = 0; f < d.num_faces(); ++f) {
                const FaceId id(f);
                out += (f == 0 ? "\n  " : ",\n  ") + std::string("{\"face\": ") + std::to_string(f) +
                       ", \"name\": " + json_name(&names, id) +
                       ", \"outer\": " + (d.is_unbounded(id) ? std::string("null") : json_cycle(d, d.outer(id))) +
                       ", \"holes\": " + std::to_string(d.inner(id).size()) + ", \"isolated\": [";
                for (std::size_t k = 0; k < d.isolated(id).size(); ++k) {
                    out += (k == 0 ? "" : ", ") + std::to_string(d.isolated(id)[k].index());
                }
                out += "]}";
            }
            std::string graph = io::write_graph(to_graph(d));
            out += "\n],\n\"graph\": " + graph.substr(0, graph.size() - 1) + "}\n";
            if (!graph_out->empty()) write_file(*graph_out, graph);
            write_stdout(out);
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
