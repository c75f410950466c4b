// dcel faces [GRAPH|-]: every boundary cycle of the graph's DCEL, as origin
// vertex ids in next order, in {"faces": [[...], ...]}; with --answer KIND,
// the reference's answer of another kind (what `dcel check --answer KIND`
// compares with).
#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/check/answer.hpp"

namespace dcel::cli {

void add_faces_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("faces", "Print every boundary cycle: {\"faces\": [[v0, v1, ...], ...]}");
    auto path = std::make_shared<std::string>("-");
    auto kind = std::make_shared<std::string>("faces");
    cmd->add_option("GRAPH", *path, "Graph JSON file, or - for stdin (the default)");
    cmd->add_option("--answer", *kind,
                    "Print the answer of this kind instead: faces (the default), dump (as dcel build), polygons "
                    "(bounded faces with holes), rings (one ring per bounded face), even-odd (polygons of the faces "
                    "inside an odd number of boundaries)")
        ->check(CLI::IsMember({"faces", "dump", "polygons", "rings", "even-odd"}))
        ->type_name("KIND");
    cmd->callback([&action, path, kind] {
        action = [path, kind] {
            const Dcel d = build_dcel(*path, load_graph(*path));
            const check::AnswerKind k = *check::answer_kind_from_name(*kind);
            stream_stdout([&](const io::TextSink& sink) { check::write_reference_answer(d, k, sink); });
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
