// A DCEL laid out in a frame, and painted: faces tinted, edges, half-edges
// as arrows on their face's side, vertices, labels for vertex and face ids.
//
// The rotation around each vertex is the DCEL's (exact), and the drawing
// shows it: where the frame would draw two edges of a vertex in nearly one
// direction (or in the wrong order), they leave the vertex spread apart, in
// the exact order, and bend towards their other end. Elsewhere edges are
// straight. Internal to the pictures (io/svg.cpp, check/counterexample_svg.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/io/svg_canvas.hpp"
#include "dcel/io/svg_frame.hpp"

namespace dcel::io::svg {

// Directions (radians, counterclockwise from east, y up) for rays given in
// clockwise order around a point, from the directions the frame draws them
// in: unchanged when they are in that order and at least min_gap apart,
// otherwise moved as little as the order and the gap allow.
[[nodiscard]] std::vector<double> spread_clockwise(const std::vector<double>& drawn, double min_gap);

class DrawnDcel {
public:
    DrawnDcel(const Dcel& d, const Frame& frame);

    [[nodiscard]] const Dcel& dcel() const { return *d_; }
    [[nodiscard]] Xy at(VertexId v) const { return at_[v.index()]; }
    // The drawn line of a half-edge, from its origin to its target.
    [[nodiscard]] Polyline line(HalfEdgeId h) const;
    // The boundary rings of a bounded face (outer, then holes), as drawn.
    [[nodiscard]] std::vector<Polyline> rings(FaceId f) const;
    // How many edges are drawn bent.
    [[nodiscard]] std::size_t bent_edges() const { return bent_; }

private:
    const Dcel* d_;
    std::vector<Xy> at_;
    std::vector<Polyline> edge_line_;  // edge e: from origin(2e) to target(2e)
    std::size_t bent_ = 0;
};

// The steps of walks given as vertex ids (an answer's cycles, highlighted
// cycles), as drawn: a step u -> v along the half-edge u -> v when the DCEL
// has one, else a straight line between the two dots (a wrong answer may
// step where there is no edge).
struct DrawnStep {
    Polyline line;
    bool along_edge;
};
class StepLines {
public:
    explicit StepLines(const DrawnDcel& g);
    // Nothing for a vertex id out of range.
    [[nodiscard]] std::optional<DrawnStep> operator()(Index u, Index v) const;

private:
    const DrawnDcel* g_;
    std::unordered_map<std::uint64_t, HalfEdgeId> by_ends_;  // (origin << 32 | target) -> half-edge
};

// Painting, in this order: faces, edges, half-edges, vertices.
void paint_faces(std::string& out, const DrawnDcel& g);
void paint_edges(std::string& out, const DrawnDcel& g);
// style(h): how half-edge h is drawn, or nothing to leave it out.
using HalfEdgeStyle = std::function<std::optional<ArrowStyle>(HalfEdgeId)>;
void paint_half_edges(std::string& out, const DrawnDcel& g, const HalfEdgeStyle& style);
[[nodiscard]] HalfEdgeStyle by_face_colour(const DrawnDcel& g);
// Dots (rings for isolated vertices), each with its true coordinates as a tooltip.
void paint_vertices(std::string& out, const DrawnDcel& g);

// Tells the layout where the dots and edges are, then places the vertex ids
// and the face ids ("f3", inside its face where it fits, "f0" beside the
// drawing). Returns the ids that found no room (for a note).
void block_drawing(LabelLayout& labels, const DrawnDcel& g);
// `names`, when not empty, are the vertices' labels instead of their ids.
[[nodiscard]] std::vector<std::string> label_vertices(LabelLayout& labels, const DrawnDcel& g, const Box& allowed,
                                                      const std::vector<std::string>& names = {});
[[nodiscard]] std::vector<std::string> label_faces(LabelLayout& labels, const DrawnDcel& g, const Box& allowed);

// Points deep inside a face's drawn rings, deepest first (for its label).
[[nodiscard]] std::vector<Xy> inner_points(const std::vector<Polyline>& rings, std::size_t count);

// The true coordinates, a row per vertex, at `top_left`; returns its size.
// `names`, when not empty, labels the rows instead of the vertex ids.
Xy coordinate_table(std::string& out, Xy top_left, const std::vector<Point>& points, double font = 11,
                    const std::vector<std::string>& names = {});
[[nodiscard]] Xy coordinate_table_size(const std::vector<Point>& points, double font = 11,
                                       const std::vector<std::string>& names = {});

}  // namespace dcel::io::svg
