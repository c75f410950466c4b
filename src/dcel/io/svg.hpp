// A picture of a DCEL as SVG text, for people (`dcel render`): each bounded
// face tinted in its own colour and labelled with its id inside it (f1, f2,
// ...; f0, the unbounded face, beside the drawing), every half-edge an arrow
// on its face's side (the left) in that face's colour, vertices with their
// ids (labels never overlap: moved aside, with a leader line when far), the
// true coordinates as tooltips and, for small graphs, in a table, and a note
// on the frame and its scale. Highlighted cycles (vertex cycles, e.g. a wrong
// answer's) are drawn over everything in red.
//
// The frame (svg_frame.hpp): exact (one scale) or normalised (each axis
// stretched monotonically, so that inputs near 1e15 that differ by 1, or
// subnormals, do not collapse onto one pixel); Auto picks normalised only
// when the exact frame would draw two distinct points within a few px. Where
// two edges of a vertex would be drawn in nearly one direction, they leave
// it spread apart in their exact order and bend towards their other end, so
// the rotation at every vertex is the DCEL's. The drawing is approximate
// (doubles); no decision is taken from it. No file I/O here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/geometry/point.hpp"
#include "dcel/ids.hpp"

namespace dcel::io {

enum class SvgFrame : std::uint8_t { Auto, Exact, Normalised };

// Something drawn over the DCEL in red, e.g. an edit about to be made: a
// point (a ring) or a segment from a to b (dashed, an arrowhead at b), with
// a label beside it.
struct SvgMark {
    Point a;
    std::optional<Point> b;
    std::string label;
};

struct SvgOptions {
    std::string title;                                 // shown on top and as <title>; escaped
    std::vector<std::vector<Index>> highlight_cycles;  // vertex cycles in red; bad ids skipped
    SvgFrame frame = SvgFrame::Auto;
    bool face_ids = true;                   // label the faces f0, f1, ...
    std::size_t max_table_vertices = 40;    // the coordinate table for graphs up to this size
    std::vector<std::string> vertex_names;  // labels instead of the vertex ids (e.g. a session's ids); may be empty
    std::vector<SvgMark> marks;             // drawn in red over everything
    std::string marks_caption;              // what the marks are, for the caption
};

[[nodiscard]] std::string render_svg(const Dcel& dcel, const SvgOptions& options = {});

}  // namespace dcel::io
