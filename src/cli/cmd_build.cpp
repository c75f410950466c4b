// dcel build [GRAPH|-]: the whole DCEL as a dump (see docs/formats.md),
// streamed from the DCEL as it is written: the dump is about 10 times the
// input, too large to hold whole on top of the DCEL.
#include "commands.hpp"
#include "dcel/build.hpp"
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
            const Dcel d = build_dcel(*path, load_graph(*path));
            const io::DumpStyle style = *compact ? io::DumpStyle::Compact : io::DumpStyle::Lines;
            stream_stdout([&](const io::TextSink& sink) { io::write_dump_of(d, style, sink); });
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
