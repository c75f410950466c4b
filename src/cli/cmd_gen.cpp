// dcel gen [--family F] [--seed S] [--vertices N]: a random valid graph from
// the shared generators (dcel::gen), as graph JSON on one line. The same
// arguments give the same graph on every platform.
#include "commands.hpp"
#include "dcel/format.hpp"
#include "dcel/gen/generate.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::cli {

namespace {

// Some families check candidate edges by brute force (quadratic): 10000
// vertices take up to about 8 s here, 100000 took minutes.
constexpr std::size_t kMaxVertices = 10000;

std::string family_list() {
    std::string s;
    for (const gen::Family f : gen::all_families()) {
        if (!s.empty()) s += ", ";
        s += gen::family_name(f);
    }
    return s;
}

}  // namespace

void add_gen_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("gen", "Print a random valid graph (JSON) from the shared generators");
    cmd->footer("Families: " + family_list() +
                ".\nThe same family, seed and size give the same graph on every machine and\n"
                "compiler, with exactly the vertices asked.\n"
                "Example:\n"
                "  dcel gen --family nested-polygons --seed 7 --vertices 30 | dcel faces");
    auto family = std::make_shared<std::string>("random-segments");
    auto seed = std::make_shared<std::uint64_t>(0);
    auto vertices = std::make_shared<std::size_t>(16);
    cmd->add_option("--family", *family, "Graph family (see below)")->capture_default_str();
    cmd->add_option("--seed", *seed, "Seed (unsigned 64-bit)")
        ->type_name("UINT")
        ->transform(unsigned_in())
        ->capture_default_str();
    cmd->add_option("--vertices", *vertices, "Target number of vertices, at most 10000")
        ->type_name("N")
        ->transform(unsigned_in(0, kMaxVertices))
        ->capture_default_str();
    cmd->callback([&action, family, seed, vertices] {
        action = [family, seed, vertices] {
            const auto f = gen::family_from_name(*family);
            if (!f)
                throw UsageError("gen: unknown family " + quote_for_message(*family) + "; the families are " +
                                 family_list());
            const PlanarGraph g = gen::generate({*f, *seed, *vertices});
            stream_stdout([&](const io::TextSink& sink) { io::write_graph(g, sink); });
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
