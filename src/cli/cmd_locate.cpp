// dcel locate GRAPH X Y: which face, edge or vertex holds the point, decided
// exactly. With --points FILE, every point of a JSON array, answered by the
// trapezoidal map (O(E log E) expected to build, O(log E) per point).
#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/locate.hpp"
#include "face_names.hpp"
#include "json_out.hpp"

namespace dcel::cli {
namespace {

std::vector<Point> load_points(const std::string& path) {
    const std::string text = read_input(path);
    return with_source(path, [&] { return io::read_points(text); });
}

}  // namespace

void add_locate_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("locate", "Which face, edge or vertex holds a point: {\"point\": [x, y], \"face\": f}");
    auto path = std::make_shared<std::string>();
    auto xy = std::make_shared<std::vector<std::string>>();
    auto names_path = std::make_shared<std::string>();
    auto points_path = std::make_shared<std::string>();
    cmd->add_option("GRAPH", *path, "Graph JSON file, or - for stdin")->required();
    cmd->add_option("X Y", *xy, "The point's coordinates")->expected(2);
    cmd->add_option("--names", *names_path, "Face names: a JSON object {\"name\": [x, y], ...}, a point inside each face");
    cmd->add_option("--points", *points_path, "Locate every point of a JSON array [[x, y], ...] instead");
    cmd->callback([&action, path, xy, names_path, points_path] {
        if (xy->empty() == points_path->empty()) throw CLI::ValidationError("give either X Y or --points FILE");
        action = [path, xy, names_path, points_path] {
            require_one_stdin({{"GRAPH", path.get()}, {"--names", names_path.get()}, {"--points", points_path.get()}});
            const Point p = xy->empty() ? Point{} : Point{parse_coordinate((*xy)[0], "X"), parse_coordinate((*xy)[1], "Y")};
            const PlanarGraph g = load_graph(*path);
            const Dcel d = build_dcel(*path, g);
            FaceNames names(d);
            const std::vector<NamedPoint> named = load_face_names(*names_path);
            name_faces(d, named, display_name(*names_path), names);
            const FaceNames* shown = named.empty() ? nullptr : &names;
            if (!xy->empty()) {
                write_stdout("{\"point\": " + json_point(p) + ", " + json_location_members(d, locate_by_scan(d, p), shown) +
                             "}\n");
                return kExitOk;
            }
            const std::vector<Point> points = load_points(*points_path);
            const PointLocator locator(d);
            std::string out = "{\"locations\": [";
            for (std::size_t i = 0; i < points.size(); ++i) {
                out += i == 0 ? "\n  " : ",\n  ";
                out += "{\"point\": " + json_point(points[i]) + ", " +
                       json_location_members(d, locator.locate(points[i]), shown) + "}";
            }
            write_stdout(out + "\n]}\n");
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
