#include "peers/atan2_solver.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dcel::bench {

Cycles atan2_cycles(const PlanarGraph& g) {
    const auto n = static_cast<int>(g.vertices.size());
    std::vector<int> he_origin;
    std::vector<int> he_twin;
    for (const GraphEdge& e : g.edges) {
        const int a = static_cast<int>(he_origin.size());
        he_origin.push_back(static_cast<int>(e.u.index()));
        he_twin.push_back(a + 1);
        he_origin.push_back(static_cast<int>(e.v.index()));
        he_twin.push_back(a);
    }
    const int m = static_cast<int>(he_origin.size());
    std::vector<std::vector<std::pair<double, int>>> out(static_cast<std::size_t>(n));
    for (int h = 0; h < m; ++h) {
        const Point u = g.vertices[static_cast<std::size_t>(he_origin[h])];
        const Point v = g.vertices[static_cast<std::size_t>(he_origin[he_twin[h]])];
        out[static_cast<std::size_t>(he_origin[h])].push_back({std::atan2(v.y - u.y, v.x - u.x), h});
    }
    for (auto& ring : out) std::sort(ring.begin(), ring.end());
    std::vector<int> he_next(static_cast<std::size_t>(m), 0);
    for (int h = 0; h < m; ++h) {
        const int t = he_twin[h];
        const auto& ring = out[static_cast<std::size_t>(he_origin[t])];
        const int d = static_cast<int>(ring.size());
        int idx = 0;
        for (int i = 0; i < d; ++i) {
            if (ring[static_cast<std::size_t>(i)].second == t) {
                idx = i;
                break;
            }
        }
        he_next[h] = ring[static_cast<std::size_t>((idx - 1 + d) % d)].second;  // the fixed rule
    }
    std::vector<char> seen(static_cast<std::size_t>(m), 0);
    Cycles faces;
    for (int start = 0; start < m; ++start) {
        if (seen[start] != 0) continue;
        std::vector<std::uint32_t> cycle;
        for (int h = start; seen[h] == 0; h = he_next[h]) {
            seen[h] = 1;
            cycle.push_back(static_cast<std::uint32_t>(he_origin[h]));
        }
        faces.push_back(std::move(cycle));
    }
    return faces;
}

}  // namespace dcel::bench
