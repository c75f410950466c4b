#include "oracles/rotations.hpp"

#include <algorithm>

#include "oracles/exact.hpp"

namespace dcel::oracle {

Rotations rotation_system(const HalfEdgeGraph& h) {
    Rotations r;
    r.ring.resize(h.points.size());
    r.position.resize(h.origin.size());
    for (Index e = 0; e < h.origin.size(); ++e) r.ring[h.origin[e]].push_back(e);
    const ExactPoints geometry(h.points);
    auto head = [&](Index e) { return h.origin[h.twin[e]]; };
    for (Index v = 0; v < r.ring.size(); ++v) {
        std::sort(r.ring[v].begin(), r.ring[v].end(),
                  [&](Index a, Index b) { return geometry.angle_order(v, head(a), head(b)) < 0; });
        for (Index k = 0; k < r.ring[v].size(); ++k) r.position[r.ring[v][k]] = k;
    }
    return r;
}

}  // namespace dcel::oracle
