// Union-find over vertex ids: the oracles' own count of connected
// components (isolated vertices included), independent of build(). The
// generators' Kruskal forest (src/dcel/gen/family_random.cpp) stays a
// separate copy on purpose: this one checks what that one builds (a tree
// family's edges + components == vertices).
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

#include "dcel/graph.hpp"

namespace dcel::oracle {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), Index{0}); }
    Index find(Index x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(Index a, Index b) { parent_[find(a)] = find(b); }

private:
    std::vector<Index> parent_;
};

// The component label (a root vertex id) of every vertex.
[[nodiscard]] inline std::vector<Index> component_labels(const PlanarGraph& g) {
    UnionFind uf(g.vertices.size());
    for (const GraphEdge& e : g.edges) uf.unite(e.u.index(), e.v.index());
    std::vector<Index> label(g.vertices.size());
    for (Index v = 0; v < label.size(); ++v) label[v] = uf.find(v);
    return label;
}

[[nodiscard]] inline std::size_t count_components(const PlanarGraph& g) {
    const std::vector<Index> label = component_labels(g);
    std::size_t roots = 0;
    for (Index v = 0; v < label.size(); ++v) roots += label[v] == v;
    return roots;
}

}  // namespace dcel::oracle
