// DcelDump: a DCEL as plain arrays, exactly what `dcel build` prints and what
// a foreign implementation may hand to `dcel check`. Unlike Dcel, nothing
// here is trusted: twins are explicit, any field may be out of range, and
// validate() (validate.hpp) is what decides whether it is a DCEL at all.
#pragma once

#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/geometry/point.hpp"
#include "dcel/ids.hpp"

namespace dcel {

struct HalfEdgeRecord {
    VertexId origin;
    HalfEdgeId twin;
    HalfEdgeId next;
    HalfEdgeId prev;
    FaceId face;
    friend bool operator==(const HalfEdgeRecord&, const HalfEdgeRecord&) = default;
};

struct FaceDump {
    HalfEdgeId outer;  // null for the unbounded face
    std::vector<HalfEdgeId> inner;
    std::vector<VertexId> isolated;
    friend bool operator==(const FaceDump&, const FaceDump&) = default;
};

struct DcelDump {
    std::vector<Point> vertices;
    // One outgoing half-edge per vertex, null for an isolated one. Optional in
    // a foreign dump: empty means "not given".
    std::vector<HalfEdgeId> vertex_out;
    std::vector<HalfEdgeRecord> half_edges;
    std::vector<FaceDump> faces;
};

[[nodiscard]] DcelDump to_dump(const Dcel& d);

}  // namespace dcel
