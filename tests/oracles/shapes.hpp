// Cycles and faces as plain vertex lists, independent of half-edge and face
// numbering, so that two DCELs (or a DCEL and an oracle, or an expected
// answer written by hand) can be compared.
#pragma once

#include <algorithm>
#include <cstddef>
#include <ostream>
#include <tuple>
#include <vector>

#include "dcel/ids.hpp"

namespace dcel::oracle {

using Cycle = std::vector<Index>;  // origin vertices in walk order

// The lexicographically smallest rotation: a cycle's canonical form. It
// starts at the smallest vertex id; a cycle that visits that vertex more
// than once starts at the visit that gives the smallest sequence.
[[nodiscard]] inline Cycle canonical(const Cycle& c) {
    if (c.empty()) return c;
    const Index least = *std::min_element(c.begin(), c.end());
    auto rotation = [&](std::size_t start) {
        Cycle r(c.begin() + static_cast<std::ptrdiff_t>(start), c.end());
        r.insert(r.end(), c.begin(), c.begin() + static_cast<std::ptrdiff_t>(start));
        return r;
    };
    Cycle best;
    for (std::size_t k = 0; k < c.size(); ++k) {
        if (c[k] != least) continue;
        Cycle r = rotation(k);
        if (best.empty() || r < best) best = std::move(r);
    }
    return best;
}

struct FaceShape {
    Cycle outer;               // empty for the unbounded face
    std::vector<Cycle> holes;  // canonical, sorted
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

[[nodiscard]] inline FaceShape normalized(FaceShape f) {
    f.outer = canonical(f.outer);
    for (Cycle& h : f.holes) h = canonical(h);
    std::sort(f.holes.begin(), f.holes.end());
    std::sort(f.isolated.begin(), f.isolated.end());
    return f;
}

// Every face normalized, then sorted: the unbounded face is the one with an
// empty outer cycle.
[[nodiscard]] inline std::vector<FaceShape> sorted_shapes(std::vector<FaceShape> v) {
    for (FaceShape& f : v) f = normalized(std::move(f));
    std::sort(v.begin(), v.end());
    return v;
}

}  // namespace dcel::oracle
