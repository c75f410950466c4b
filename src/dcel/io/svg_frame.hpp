// Where each input point goes in a picture. Two frames:
//  - exact: one scale for both axes, so shapes keep their proportions; points
//    that differ by 1 near 1e15, or by a few units in the last place, fall on
//    one pixel;
//  - normalised: each axis on its own, by a monotone stretch: the distinct
//    values of an axis keep their order, and a gap between neighbouring values
//    is drawn at least half as wide as in an even spacing of them, gaps above
//    the mean wider in proportion to their size. No two distinct points share
//    a pixel, left and right, above and below are kept; lengths and angles
//    are not.
// Auto picks exact unless it would put two distinct points within a few px.
// The drawing is approximate (doubles); nothing is decided from it.
#pragma once

#include <string>
#include <vector>

#include "dcel/geometry/point.hpp"
#include "dcel/io/svg_canvas.hpp"

namespace dcel::io::svg {

enum class FrameKind { Exact, Normalised };

class Frame {
public:
    Frame(const std::vector<Point>& points, FrameKind kind);

    [[nodiscard]] FrameKind kind() const { return kind_; }
    // The drawing's size when its longer side is `longest` px.
    [[nodiscard]] Xy size(double longest) const;
    // Puts the drawing into `box` (of the size above).
    void place(const Box& box) { box_ = box; }
    [[nodiscard]] const Box& box() const { return box_; }
    [[nodiscard]] Xy at(std::size_t i) const;  // point i of the input
    // One or two lines saying what the frame keeps and its scale.
    [[nodiscard]] std::vector<std::string> note() const;

private:
    FrameKind kind_;
    std::vector<Xy> unit_;  // each point in [0, w] x [0, h], y up
    double w_ = 0, h_ = 0;  // the unit box (the longer side is 1)
    double span_ = 0;       // exact frame: input units per unit of the box
    double min_x_ = 0, max_x_ = 0, min_y_ = 0, max_y_ = 0;
    Box box_;
};

// Exact, unless at `longest` px two distinct points would be drawn closer
// than min_px.
[[nodiscard]] FrameKind choose_frame(const std::vector<Point>& points, double longest, double min_px = 6);

}  // namespace dcel::io::svg
