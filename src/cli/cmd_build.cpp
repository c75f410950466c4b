// dcel build [GRAPH|-]: the whole DCEL as a dump (see docs/formats.md).
#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/dump.hpp"
#include "dcel/io/dcel_json.hpp"

namespace dcel::cli {

void add_build_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("build", "Print the whole DCEL: vertices, half-edges and faces");
    auto path = std::make_shared<std::string>("-");
    auto compact = std::make_shared<bool>(false);
    cmd->add_option("GRAPH", *path, "Graph JSON file, or - for stdin (the default)");
    cmd->add_flag("--compact", *compact, "Print the dump on one line");
    cmd->callback([&action, path, compact] {
        action = [path, compact] {
            const PlanarGraph g = load_graph(*path);
            const Dcel d = build_dcel(*path, g);
            write_stdout(io::write_dump(to_dump(d), *compact ? io::DumpStyle::Compact : io::DumpStyle::Lines));
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
