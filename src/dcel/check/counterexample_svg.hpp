// A counterexample drawn so that a person can see what differs: the graph in
// one frame (exact, or normalised where exact would collapse points; see
// io/svg.hpp), twice side by side, the reference's DCEL on the left and the
// answer on the right, each named in a panel header and the legend; and for
// each vertex where the answer's next differs from the reference's, an inset
// with the vertex's edges as a fan in their exact clockwise order, the edge
// the answer arrived along, the reference's next (blue) and the answer's
// (red). Vertex and face ids are labelled and never overlap; the true
// coordinates are in a table.
//
// The wrong turns come from the answer's cycles against the reference's next
// (check/wrong_turns.hpp), not from a comparison report. No file I/O.
#pragma once

#include <string>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/graph.hpp"
#include "dcel/ids.hpp"

namespace dcel::check {

struct CounterexampleDrawing {
    const PlanarGraph* graph = nullptr;  // the counterexample
    const Dcel* reference = nullptr;     // build(*graph)
    // The answer as vertex cycles, each in its next order (faces and dump
    // answers); may be empty.
    std::vector<std::vector<Index>> answer_cycles = {};
    // The answer as regions (polygons: shell then holes; rings: one ring
    // each), vertex ids; may be empty.
    std::vector<std::vector<std::vector<Index>>> answer_polygons = {};
    std::string answer_name = "the answer";  // e.g. "the command: python3 mine.py"
    std::string reference_name = "the reference (dcel)";
    std::string title = {};
};

// The picture, or a picture saying what is missing when graph or reference
// is null. At most 6 insets; the note names the further vertices.
[[nodiscard]] std::string render_counterexample_svg(const CounterexampleDrawing& drawing);

}  // namespace dcel::check
