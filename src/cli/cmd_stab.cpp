// dcel stab GRAPH X1 Y1 X2 Y2: the faces, edges and vertices the segment
// meets, in order from (X1, Y1); with --line, the whole line through the two
// points.
#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/stab.hpp"
#include "face_names.hpp"
#include "json_out.hpp"

namespace dcel::cli {

void add_stab_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand(
        "stab", "The faces (and edges, vertices) a segment or line meets, in order: {\"faces\": [...], \"pieces\": [...]}");
    auto path = std::make_shared<std::string>();
    auto coords = std::make_shared<std::vector<std::string>>();
    auto names_path = std::make_shared<std::string>();
    auto line = std::make_shared<bool>(false);
    cmd->add_option("GRAPH", *path, "Graph JSON file, or - for stdin")->required();
    cmd->add_option("X1 Y1 X2 Y2", *coords, "The segment's ends")->expected(4)->required();
    cmd->add_option("--names", *names_path, "Face names: a JSON object {\"name\": [x, y], ...}, a point inside each face");
    cmd->add_flag("--line", *line, "The whole line through the two points (they must differ)");
    cmd->callback([&action, path, coords, names_path, line] {
        action = [path, coords, names_path, line] {
            require_one_stdin({{"GRAPH", path.get()}, {"--names", names_path.get()}});
            const Point a{parse_coordinate((*coords)[0], "X1"), parse_coordinate((*coords)[1], "Y1")};
            const Point b{parse_coordinate((*coords)[2], "X2"), parse_coordinate((*coords)[3], "Y2")};
            if (*line && a == b) throw UsageError("--line needs two different points");
            const PlanarGraph g = load_graph(*path);
            const Dcel d = build_dcel(*path, g);
            FaceNames names(d);
            const std::vector<NamedPoint> named = load_face_names(*names_path);
            name_faces(d, named, display_name(*names_path), names);
            const std::vector<StabPiece> pieces = *line ? stab_line(d, a, b) : stab_segment(d, a, b);
            const std::string head = *line ? "{\"line\": [" + json_point(a) + ", " + json_point(b) + "], "
                                           : "{\"from\": " + json_point(a) + ", \"to\": " + json_point(b) + ", ";
            write_stdout(head + json_stab_members(pieces, named.empty() ? nullptr : &names) + "}\n");
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
