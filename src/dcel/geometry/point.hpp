// A point of the plane, with the coordinates the user gave (finite doubles).
#pragma once

namespace dcel {

struct Point {
    double x = 0;
    double y = 0;
};

// Coordinate equality: -0.0 and 0.0 are the same point.
[[nodiscard]] constexpr bool operator==(Point a, Point b) { return a.x == b.x && a.y == b.y; }

// The sweep order: by x, then by y. Exact (plain double comparisons).
[[nodiscard]] constexpr bool lex_less(Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

}  // namespace dcel
