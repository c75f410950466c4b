// Where a point lies in a subdivision: at a vertex, inside an edge, or inside
// a face. The answer type of locate_by_scan (locate.hpp) and PointLocator
// (point_locator.hpp).
#pragma once

#include <ostream>

#include "dcel/ids.hpp"

namespace dcel {

struct Location {
    enum class Kind : unsigned char { Face, Edge, Vertex };
    Kind kind = Kind::Face;
    FaceId face;      // Kind::Face: the face whose interior holds the point
    EdgeId edge;      // Kind::Edge: the edge whose interior holds the point
    VertexId vertex;  // Kind::Vertex: the vertex at the point

    [[nodiscard]] static Location in_face(FaceId f) { return {Kind::Face, f, {}, {}}; }
    [[nodiscard]] static Location on_edge(EdgeId e) { return {Kind::Edge, {}, e, {}}; }
    [[nodiscard]] static Location at_vertex(VertexId v) { return {Kind::Vertex, {}, {}, v}; }
    friend bool operator==(const Location&, const Location&) = default;
    // "in f2", "on e6", "at v1"
    friend std::ostream& operator<<(std::ostream& os, const Location& l) {
        switch (l.kind) {
            case Kind::Face: return os << "in " << l.face;
            case Kind::Edge: return os << "on " << l.edge;
            case Kind::Vertex: return os << "at " << l.vertex;
        }
        return os;
    }
};

}  // namespace dcel
