// Test support: a DCEL's faces as plain vertex lists, independent of half-edge
// and face numbering, so expected answers can be written down by hand.
#pragma once

#include <algorithm>
#include <ostream>
#include <tuple>
#include <vector>

#include "dcel/dcel.hpp"

namespace dcel::testing {

using Cycle = std::vector<Index>;  // origin vertices in next order

// The lexicographically smallest rotation: a cycle's canonical form.
inline Cycle canonical(Cycle c) {
    Cycle best = c;
    for (std::size_t k = 1; k < c.size(); ++k) {
        std::rotate(c.begin(), c.begin() + 1, c.end());
        best = std::min(best, c);
    }
    return best;
}

inline Cycle cycle_vertices(const Dcel& d, HalfEdgeId start) {
    Cycle c;
    for (const HalfEdgeId h : d.cycle(start)) c.push_back(d.origin(h).index());
    return canonical(c);
}

struct FaceShape {
    Cycle outer;               // empty for the unbounded face
    std::vector<Cycle> holes;  // sorted
    std::vector<Index> isolated;
    friend bool operator==(const FaceShape&, const FaceShape&) = default;
    // Not a defaulted <=>: libc++ before 16 gives std::vector no <=>, and the
    // fuzz harnesses are also built against libc++ (OSS-Fuzz).
    friend bool operator<(const FaceShape& a, const FaceShape& b) {
        return std::tie(a.outer, a.holes, a.isolated) < std::tie(b.outer, b.holes, b.isolated);
    }
};

inline std::ostream& operator<<(std::ostream& os, const Cycle& c) {
    os << "[";
    for (std::size_t i = 0; i < c.size(); ++i) os << (i ? " " : "") << c[i];
    return os << "]";
}
inline std::ostream& operator<<(std::ostream& os, const FaceShape& f) {
    os << "{outer " << f.outer << " holes";
    for (const Cycle& h : f.holes) os << " " << h;
    os << " isolated";
    for (const Index v : f.isolated) os << " " << v;
    return os << "}";
}

inline FaceShape normalized(FaceShape f) {
    f.outer = f.outer.empty() ? f.outer : canonical(f.outer);
    for (Cycle& h : f.holes) h = canonical(h);
    std::sort(f.holes.begin(), f.holes.end());
    std::sort(f.isolated.begin(), f.isolated.end());
    return f;
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

inline std::vector<FaceShape> sorted_shapes(std::vector<FaceShape> v) {
    for (FaceShape& f : v) f = normalized(f);
    std::sort(v.begin(), v.end());
    return v;
}

}  // namespace dcel::testing
