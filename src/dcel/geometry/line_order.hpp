// The order of events along a directed line, decided exactly without
// computing any intersection point.
//
// The line L runs through a and b (a != b), directed from a to b. An event
// is either a point on L, or the crossing of L with a segment c-d whose ends
// lie strictly on opposite sides of L. Crossing points are rational, so they
// are never computed: a point P is before the crossing with c-d when P lies
// on the side of line(c, d) that L comes from; two crossings are ordered by
// the same test, made against whichever of the two segments has the other
// entirely on one side of its line (one of them always does, when the two
// segments do not cross each other, as edges of a DCEL never do).
#pragma once

#include "dcel/geometry/point.hpp"
#include "dcel/geometry/sign.hpp"

namespace dcel::detail {

struct LineEvent {
    bool crossing = false;
    Point p;     // the point on L (when !crossing)
    Point c, d;  // the crossing segment (when crossing)

    [[nodiscard]] static LineEvent at(Point p) { return {false, p, {}, {}}; }
    [[nodiscard]] static LineEvent cut(Point c, Point d) { return {true, {}, c, d}; }
};

class DirectedLine {
public:
    DirectedLine(Point a, Point b);  // requires a != b

    [[nodiscard]] Point a() const { return a_; }
    [[nodiscard]] Point b() const { return b_; }
    // Which side of L a point is on: Positive left (counterclockwise), Zero on L.
    [[nodiscard]] Sign side(Point p) const;
    // Negative when x comes before y along L, Zero when they are the same
    // point. Two crossings must be of segments that do not cross each other.
    [[nodiscard]] Sign compare(const LineEvent& x, const LineEvent& y) const;
    // For a segment c-d that L crosses: the side of line(c, d) (Positive:
    // left of c -> d) on which the points of L after the crossing lie.
    [[nodiscard]] Sign ahead_side(Point c, Point d) const;

private:
    [[nodiscard]] Sign point_vs_crossing(Point p, Point c, Point d) const;

    Point a_;
    Point b_;
    bool lex_forward_;  // points on L come in lex order (a before b in lex order)
};

}  // namespace dcel::detail
