// One inset of the counterexample drawing: a vertex where the answer's next
// differs from the reference's, as a fan of its edges in their exact
// clockwise order (the DCEL's rotation), with the edge the answer arrived
// along, the reference's next (blue) and the answer's (red), and the two
// orders in words. Above 12 edges only the edges that matter and their
// neighbours are drawn, the others counted. Internal to counterexample_svg.
#pragma once

#include <string>
#include <vector>

#include "dcel/check/wrong_turns.hpp"
#include "dcel/io/svg_canvas.hpp"
#include "dcel/io/svg_drawing.hpp"

namespace dcel::check {

struct Inset {
    Index vertex;
    char tag;                      // A, B, ...: marks the vertex in the panels
    std::vector<WrongTurn> turns;  // all at this vertex, the first drawn
};

inline constexpr double kInsetWidth = 330;

// "v12": a vertex as the drawing names it.
inline std::string vertex_name(Index v) { return "v" + std::to_string(v); }

// Paints the inset with its top left corner at `at` (kInsetWidth wide) and
// returns its height. The fan's directions follow the panel drawing `g`;
// labels that find no room are appended to left_out.
double paint_inset(std::string& out, io::svg::LabelLayout& labels, const Inset& inset, const io::svg::DrawnDcel& g,
                   const std::vector<std::vector<Index>>& answer_cycles, io::svg::Xy at, std::vector<std::string>& left_out);

}  // namespace dcel::check
