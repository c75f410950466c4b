// dcel render GRAPH [-o out.svg] [--title T] [--frame F] [--no-face-ids]: an
// SVG picture of the graph's DCEL (faces tinted and labelled, half-edges as
// arrows on their face's side, vertex ids, a frame note; io/svg.hpp).
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
        "Each bounded face gets its own tint and its id inside it (f1, f2, ...; f0, the\n"
        "unbounded face, stays white); every half-edge is an arrow just to the left of its\n"
        "edge, in its face's colour, so each face's boundary reads as a counterclockwise\n"
        "loop of arrows (holes clockwise). Vertex ids are labelled (moved aside, never over\n"
        "each other); isolated vertices are rings; hovering a vertex shows its coordinates,\n"
        "and graphs of up to 40 vertices get a table of them.\n"
        "Frames: exact keeps proportions (one scale); normalised stretches each axis on its\n"
        "own, keeping the order of the x's and of the y's, so that points 1 apart near 1e15\n"
        "stay apart; auto (the default) is exact unless that would draw two points within\n"
        "6 px. Edges that would leave a vertex in nearly one direction are\n"
        "drawn spread apart in their exact order, bending towards their other end.\n"
        "Example:\n"
        "  dcel gen --family nested-polygons --seed 3 --vertices 20 | dcel render - -o nested.svg");
    auto path = std::make_shared<std::string>("-");
    auto output = std::make_shared<std::string>();
    auto title = std::make_shared<std::string>();
    auto frame = std::make_shared<std::string>("auto");
    auto no_face_ids = std::make_shared<bool>(false);
    cmd->add_option("GRAPH", *path, "Graph JSON file, or - for stdin (the default)");
    cmd->add_option("-o,--output", *output, "Write the SVG to this file (default: stdout)");
    cmd->add_option("--title", *title, "A title drawn above the picture (default: the graph's file name)");
    cmd->add_option("--frame", *frame, "auto (the default), exact or normalised")
        ->check(CLI::IsMember({"auto", "exact", "normalised"}))
        ->type_name("F");
    cmd->add_flag("--no-face-ids", *no_face_ids, "Leave out the face ids");
    cmd->callback([&action, path, output, title, frame, no_face_ids] {
        action = [path, output, title, frame, no_face_ids] {
            const PlanarGraph g = load_graph(*path);
            const Dcel d = with_source(*path, [&] { return build(g); });
            io::SvgOptions options;
            options.title = title->empty() ? display_name(*path) : *title;
            options.frame = *frame == "exact"        ? io::SvgFrame::Exact
                            : *frame == "normalised" ? io::SvgFrame::Normalised
                                                     : io::SvgFrame::Auto;
            options.face_ids = !*no_face_ids;
            const std::string svg = io::render_svg(d, options);
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
