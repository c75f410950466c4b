// Test support: a DCEL's faces as plain vertex lists (oracles/shapes.hpp),
// independent of half-edge and face numbering, so expected answers can be
// written down by hand or taken from the reference DCEL.
#pragma once

#include <algorithm>
#include <vector>

#include "dcel/dcel.hpp"
#include "oracles/shapes.hpp"

namespace dcel::test_support {

using oracle::canonical;
using oracle::Cycle;
using oracle::FaceShape;
using oracle::normalized;
using oracle::sorted_shapes;
using oracle::operator<<;

inline Cycle cycle_vertices(const Dcel& d, HalfEdgeId start) {
    Cycle c;
    for (const HalfEdgeId h : d.cycle(start)) c.push_back(d.origin(h).index());
    return canonical(c);
}

// All faces, sorted; the unbounded face is the one with an empty outer.
inline std::vector<FaceShape> face_shapes(const Dcel& d) {
    std::vector<FaceShape> out;
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        FaceShape s;
        if (!d.is_unbounded(f)) s.outer = cycle_vertices(d, d.outer(f));
        for (const HalfEdgeId h : d.inner(f)) s.holes.push_back(cycle_vertices(d, h));
        for (const VertexId v : d.isolated(f)) s.isolated.push_back(v.index());
        out.push_back(normalized(s));
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace dcel::test_support
