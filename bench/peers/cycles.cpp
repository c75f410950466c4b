#include "peers/cycles.hpp"

#include <algorithm>
#include <utility>

namespace dcel::bench {

Cycles canonical(Cycles cycles) {
    for (auto& c : cycles) {
        if (c.empty()) continue;
        // Rotate so the smallest directed edge (c[i], c[i+1]) comes first.
        std::size_t best = 0;
        auto edge = [&](std::size_t i) { return std::pair(c[i], c[(i + 1) % c.size()]); };
        for (std::size_t i = 1; i < c.size(); ++i) {
            if (edge(i) < edge(best)) best = i;
        }
        std::rotate(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(best), c.end());
    }
    std::sort(cycles.begin(), cycles.end());
    return cycles;
}

}  // namespace dcel::bench
