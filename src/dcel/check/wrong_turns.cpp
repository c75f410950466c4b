#include "dcel/check/wrong_turns.hpp"

#include <cstdint>
#include <unordered_map>
#include <unordered_set>

namespace dcel::check {

std::vector<WrongTurn> wrong_turns(const Dcel& reference, const std::vector<std::vector<Index>>& answer_cycles) {
    const auto key = [](Index u, Index v) { return (std::uint64_t{u} << 32) | v; };
    std::unordered_map<std::uint64_t, HalfEdgeId> half_edge;
    for (Index h = 0; h < reference.num_half_edges(); ++h) {
        half_edge.emplace(key(reference.origin(HalfEdgeId(h)).index(), reference.target(HalfEdgeId(h)).index()),
                          HalfEdgeId(h));
    }
    std::vector<WrongTurn> out;
    std::unordered_set<std::uint64_t> seen;
    for (std::size_t c = 0; c < answer_cycles.size(); ++c) {
        const auto& cycle = answer_cycles[c];
        const std::size_t n = cycle.size();
        if (n < 2) continue;
        for (std::size_t i = 0; i < n; ++i) {
            const Index u = cycle[i], v = cycle[(i + 1) % n], x = cycle[(i + 2) % n];
            const auto it = half_edge.find(key(u, v));
            if (it == half_edge.end()) continue;  // not an edge: no next to compare
            const Index w = reference.target(reference.next(it->second)).index();
            if (w != x && seen.insert(key(u, v)).second) out.push_back({u, v, w, x, c});
        }
    }
    return out;
}

}  // namespace dcel::check
