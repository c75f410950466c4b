// Brute-force face location: the face of a DCEL that contains a point of
// one component, found from geometry alone. It is the smallest bounded face
// whose outer cycle, belonging to another component, strictly contains the
// point (exact point in polygon); the unbounded face when there is none.
// Outer cycles of bounded faces are nested or disjoint, so "smallest" is
// well defined. Ignores the DCEL's own hole placement entirely.
#pragma once

#include <vector>

#include "dcel/dcel.hpp"
#include "support/exact_oracle.hpp"

namespace dcel::props {

class FaceLocator {
public:
    // component[v]: a component label per vertex (e.g. union-find roots).
    FaceLocator(const Dcel& d, const std::vector<Index>& component);
    [[nodiscard]] FaceId face_containing(Point p, Index component) const;

private:
    struct OuterRing {
        FaceId face;
        Index component;
        std::vector<Point> ring;
        Rational twice_area;
        double x0, x1, y0, y1;  // bounding box
    };
    std::vector<OuterRing> rings_;
};

}  // namespace dcel::props
