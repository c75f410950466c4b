// dcel render GRAPH [-o out.svg] [--title T]: an SVG picture of the graph's
// DCEL (faces tinted, half-edges as arrows on their face's side, vertex ids).
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/io/svg.hpp"

namespace dcel::cli {

namespace {

void write_file(const std::string& path, const std::string& text) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) throw UsageError("cannot open " + path + " for writing: " + std::strerror(errno));
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !ok) throw UsageError("cannot write " + path);
}

}  // namespace

void add_render_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("render", "Draw the graph's DCEL as SVG: faces tinted, half-edges as arrows");
    cmd->footer(
        "Each bounded face gets its own tint (the unbounded face stays white); every half-edge\n"
        "is an arrow just to the left of its edge, in its face's colour, so each face's\n"
        "boundary reads as a counterclockwise loop of arrows (holes clockwise). Vertex ids\n"
        "are labelled; isolated vertices are rings.\n"
        "Example:\n"
        "  dcel gen --family nested-polygons --seed 3 --vertices 20 | dcel render - -o nested.svg");
    auto path = std::make_shared<std::string>("-");
    auto output = std::make_shared<std::string>();
    auto title = std::make_shared<std::string>();
    cmd->add_option("GRAPH", *path, "Graph JSON file, or - for stdin (the default)");
    cmd->add_option("-o,--output", *output, "Write the SVG to this file (default: stdout)");
    cmd->add_option("--title", *title, "A title drawn above the picture (default: the graph's file name)");
    cmd->callback([&action, path, output, title] {
        action = [path, output, title] {
            const PlanarGraph g = load_graph(*path);
            const Dcel d = with_source(*path, [&] { return build(g); });
            const std::string svg = io::render_svg(d, {title->empty() ? display_name(*path) : *title, {}});
            if (output->empty()) {
                write_stdout(svg);
            } else {
                write_file(*output, svg);
            }
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
