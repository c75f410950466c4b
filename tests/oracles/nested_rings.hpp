// Which of a set of nested or disjoint counterclockwise rings (the outer
// cycles of bounded faces) is the innermost around a point: the smallest
// by exact area among those whose winding number around it is not zero.
// Regions around one point are nested, so the smallest is the innermost.
// The point must lie on none of the rings.
#pragma once

#include <vector>

#include "dcel/geometry/point.hpp"
#include "dcel/ids.hpp"
#include "oracles/exact.hpp"

namespace dcel::oracle {

class NestedRings {
public:
    // `label` is what innermost_around returns for this ring; `group` lets
    // a query skip the rings of its own component. twice_area, when known,
    // saves computing it again.
    void add(std::vector<Point> ring, Index label, Index group);
    void add(std::vector<Point> ring, Index label, Index group, Rational twice_area);

    // The label of the innermost ring around p, ignoring rings whose group
    // is skip_group; kNoIndex when no ring winds around p.
    [[nodiscard]] Index innermost_around(Point p, Index skip_group = kNoIndex) const;

private:
    struct Ring {
        std::vector<Point> points;
        Index label;
        Index group;
        Rational twice_area;
        double x0, x1, y0, y1;  // bounding box: a cheap exact first test
    };
    std::vector<Ring> rings_;
};

}  // namespace dcel::oracle
