#include "answer_options.hpp"

#include <string>

namespace dcel::cli {

void add_answer_options(CLI::App& cmd, const std::shared_ptr<AnswerOptions>& out) {
    cmd.add_option_function<std::string>(
           "--answer",
           [out](const std::string& name) {
               if (name != "auto") out->kind = check::answer_kind_from_name(name);
           },
           "What the answer holds: faces (every boundary cycle), dump (a whole DCEL), polygons (bounded faces "
           "with holes; GeoJSON too), rings (one ring per bounded face), even-odd (polygons of the faces inside an "
           "odd number of boundaries); default: detected from its shape")
        ->check(CLI::IsMember({"auto", "faces", "dump", "polygons", "rings", "even-odd"}))
        ->type_name("KIND");
    cmd.add_option_function<std::string>(
           "--face-on", [out](const std::string& side) { out->conventions.face_on_right = side == "right"; },
           "The side of each half-edge its face is on in the answer (default left, as in the reference)")
        ->check(CLI::IsMember({"left", "right"}))
        ->type_name("SIDE");
    cmd.add_flag_callback(
        "--one-based", [out] { out->conventions.one_based = true; }, "The answer's ids count from 1");
    cmd.add_flag_callback(
        "--unoriented", [out] { out->conventions.unoriented = true; },
        "Polygons: rings may run either way (the shell is still the first ring of each polygon)");
    cmd.add_flag_callback(
        "--isolated-as-cycles", [out] { out->conventions.isolated_cycles = true; },
        "Faces: each isolated vertex is written as the one-vertex cycle [v]");
    cmd.add_flag_callback(
        "--holes-unattached", [out] { out->conventions.holes_unattached = true; },
        "Polygons: holes are never attached, every ring is a polygon of its own (GEOS/JTS polygonize without "
        "holes, Turf)");
}

}  // namespace dcel::cli
