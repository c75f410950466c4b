// dcel faces [GRAPH|-]: every boundary cycle of the graph's DCEL, as origin
// vertex ids in next order, in {"faces": [[...], ...]}.
#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/io/dcel_json.hpp"

namespace dcel::cli {

void add_faces_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("faces", "Print every boundary cycle: {\"faces\": [[v0, v1, ...], ...]}");
    auto path = std::make_shared<std::string>("-");
    cmd->add_option("GRAPH", *path, "Graph JSON file, or - for stdin (the default)");
    cmd->callback([&action, path] {
        action = [path] {
            const PlanarGraph g = load_graph(*path);
            const Dcel d = build_dcel(*path, g);
            write_stdout(io::write_faces_of(d));
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
