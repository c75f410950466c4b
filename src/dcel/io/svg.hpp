// A picture of a DCEL as SVG text, for people: each bounded face tinted in
// its own colour (the unbounded face left white), every half-edge an arrow on
// its face's side (the left) in that face's colour, vertices with their ids,
// isolated vertices as rings. Highlighted cycles (e.g. a counterexample's
// wrong cycle) are drawn over everything in a warning colour.
//
// Coordinates are normalised into a fixed frame, so inputs near 1e15 that
// differ by 1, or near 1e-300, draw as well as small integers. The drawing is
// approximate (doubles); no decision is taken from it. No file I/O here.
#pragma once

#include <string>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/ids.hpp"

namespace dcel::io {

struct SvgOptions {
    std::string title;                                 // shown on top and as <title>; escaped
    std::vector<std::vector<Index>> highlight_cycles;  // vertex cycles in a warning colour; bad ids skipped
};

[[nodiscard]] std::string render_svg(const Dcel& dcel, const SvgOptions& options = {});

}  // namespace dcel::io
