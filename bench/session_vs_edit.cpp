// The reference side of a session against `dcel edit` on the same steps
// (bench/session_vs_edit.sh times both). A generated session is cut down to
// the steps both can run: the edits the reference accepts (`dcel edit` stops
// at the first refusal) and the locate queries (it has no face_boundary or
// neighbours, and its stab answers differently). The same steps are written
// twice: as a session, in protocol names (vertex ids that never change, edges
// by their ends), and as an edit script, in the DCEL's own ids at each step
// (which renumber on removal), read from a reference running the session.
//
//   dcel_session_vs_edit FAMILY VERTICES STEPS SEED DIR
//     writes DIR/session.json, DIR/graph.json and DIR/script.json, and prints
//     how many steps each holds.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include "dcel/check/session.hpp"
#include "dcel/check/session_reference.hpp"
#include "dcel/gen/session.hpp"
#include "dcel/io/graph_json.hpp"

namespace {

using dcel::check::SessionStep;
using dcel::check::StepOp;

std::string point_text(const dcel::Point& p) {
    char buf[80];
    std::snprintf(buf, sizeof buf, "[%.17g, %.17g]", p.x, p.y);
    return buf;
}

// The DCEL's edge id of the edge between two protocol vertices.
std::optional<std::uint32_t> edge_id(const dcel::check::detail::ReferenceSession& ref, dcel::Index u, dcel::Index v) {
    const auto a = ref.vertex_of(u), b = ref.vertex_of(v);
    if (!a || !b) return std::nullopt;
    const dcel::Dcel& d = ref.dcel();
    for (const dcel::HalfEdgeId h : d.around_origin_cw(d.out(*a))) {
        if (d.target(h) == *b) return h.index() / 2;
    }
    return std::nullopt;
}

// The step in the edit script's form, in the DCEL's ids as they are before
// it; "" when it names a vertex or edge that is not there (the reference
// refuses it).
std::string script_step(const dcel::check::detail::ReferenceSession& ref, const SessionStep& s) {
    const auto vertex = [&](dcel::Index p) {
        const auto v = ref.vertex_of(p);
        return v ? std::optional<std::string>(std::to_string(v->index())) : std::nullopt;
    };
    const auto edge = [&]() {
        const auto e = edge_id(ref, s.u, s.v);
        return e ? std::optional<std::string>(std::to_string(*e)) : std::nullopt;
    };
    std::optional<std::string> a, b;
    switch (s.op) {
        case StepOp::SplitEdge:
            if (!(a = edge())) return "";
            return R"({"split_edge": {"edge": )" + *a + R"(, "at": )" + point_text(s.p) + "}}";
        case StepOp::AddVertex: return R"({"add_vertex": {"at": )" + point_text(s.p) + "}}";
        case StepOp::AddEdge:
            if (!(a = vertex(s.u)) || !(b = vertex(s.v))) return "";
            return R"({"add_edge": {"from": )" + *a + R"(, "to": )" + *b + "}}";
        case StepOp::AddEdgeToPoint:
            if (!(a = vertex(s.u))) return "";
            return R"({"add_edge_to_point": {"from": )" + *a + R"(, "to": )" + point_text(s.p) + "}}";
        case StepOp::RemoveEdge:
            if (!(a = edge())) return "";
            return R"({"remove_edge": {"edge": )" + *a + "}}";
        case StepOp::RemoveIsolatedVertex:
            if (!(a = vertex(s.u))) return "";
            return R"({"remove_vertex": {"vertex": )" + *a + "}}";
        case StepOp::MergeCollinearEdges:
            if (!(a = vertex(s.u))) return "";
            return R"({"merge_edges": {"vertex": )" + *a + "}}";
        case StepOp::Locate: return R"({"locate": {"at": )" + point_text(s.p) + "}}";
        default: return "";
    }
}

bool write_file(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    return static_cast<bool>(out.flush());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 6) {
        std::fprintf(stderr, "usage: dcel_session_vs_edit FAMILY VERTICES STEPS SEED DIR\n");
        return 2;
    }
    const auto family = dcel::gen::family_from_name(argv[1]);
    if (!family) {
        std::fprintf(stderr, "dcel_session_vs_edit: no family '%s'\n", argv[1]);
        return 2;
    }
    dcel::gen::SessionParams params;
    params.graph = {
        .family = *family, .seed = std::strtoull(argv[4], nullptr, 10), .vertices = std::strtoull(argv[2], nullptr, 10)};
    params.seed = params.graph.seed;
    params.steps = std::strtoull(argv[3], nullptr, 10);
    const dcel::check::Session generated = dcel::gen::generate_session(params);
    const std::string dir = argv[5];

    dcel::check::Session kept{.start = generated.start, .steps = {}, .each_step = false};
    std::string script = R"({"steps": [)";
    dcel::check::detail::ReferenceSession ref(generated.start);
    for (const SessionStep& s : generated.steps) {
        if (dcel::check::is_query(s.op) && s.op != StepOp::Locate) continue;
        const std::string line = script_step(ref, s);  // before the step: the ids it names are the current ones
        // Only edits the reference accepts (a refused one is not run at all).
        if (!dcel::check::is_query(s.op) && ref.apply(s).kind == dcel::check::StepAnswer::Kind::Error) continue;
        if (line.empty()) continue;
        script += (kept.steps.empty() ? "\n  " : ",\n  ") + line;
        kept.steps.push_back(s);
    }
    script += "\n]}\n";
    if (!write_file(dir + "/session.json", dcel::check::write_session(kept) + "\n") ||
        !write_file(dir + "/graph.json", dcel::io::write_graph(generated.start) + "\n") ||
        !write_file(dir + "/script.json", script)) {
        std::fprintf(stderr, "dcel_session_vs_edit: cannot write into %s\n", dir.c_str());
        return 2;
    }
    std::printf("%zu vertices, %zu edges; %zu of %zu steps kept (accepted edits and locates)\n",
                generated.start.vertices.size(), generated.start.edges.size(), kept.steps.size(), generated.steps.size());
    return 0;
}
