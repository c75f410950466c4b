// Disjoint sets over the indexes 0..n-1 (union-find), the one implementation:
// build() finds the graph's components with it, and dcel::gen its random
// trees (Kruskal) and the components its shrinker drops. Internal to dcel;
// header-only, so that the build's loop over every edge inlines it.
//
// find() halves paths: each step links the node it passes to its
// grandparent, which keeps the trees shallow with no recursion and no second
// pass. Two rules for which root survives a union:
//   - BySize (the default): the root of the larger set. With path halving, m
//     operations on n elements cost O(m alpha(n)).
//   - SmallestRoot: the smaller root, so every set's root is its smallest
//     element and every parent is smaller than its children. build() numbers
//     vertices in sweep order and relies on that: a component's root is its
//     leftmost vertex, one ascending pass (flatten) points every element at
//     its root, and there is no size array to allocate. The bound is then
//     O(log n) amortised per operation (path halving alone).
#pragma once

#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

#include "dcel/ids.hpp"

namespace dcel::detail {

enum class Linking : unsigned char { BySize, SmallestRoot };

template <Linking L = Linking::BySize>
class UnionFind {
public:
    // n sets of one element each. The parents are kept in `storage`, whose
    // capacity is reused (build() passes memory reserved on huge pages).
    explicit UnionFind(Index n, std::vector<Index> storage = {}) : parent_(std::move(storage)) {
        parent_.resize(n);
        std::iota(parent_.begin(), parent_.end(), Index{0});
        if constexpr (L == Linking::BySize) size_.assign(n, 1);
    }

    [[nodiscard]] Index size() const { return static_cast<Index>(parent_.size()); }

    // The root of x's set.
    Index find(Index x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }

    // Joins the sets of the roots a and b (a != b); returns the root of the
    // union. For callers that keep data on roots and must merge it.
    Index link(Index a, Index b) {
        if constexpr (L == Linking::SmallestRoot) {
            if (b < a) std::swap(a, b);
        } else {
            if (size_[a] < size_[b]) std::swap(a, b);
            size_[a] += size_[b];
        }
        parent_[b] = a;
        return a;
    }

    // Joins the sets of a and b; false when they were one set already.
    bool unite(Index a, Index b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        (void)link(a, b);
        return true;
    }

    // Points every element straight at its root, in one ascending pass: with
    // SmallestRoot a parent is smaller than its children, so it already
    // points at the root when they are reached.
    void flatten() requires(L == Linking::SmallestRoot) {
        for (Index x = 0; x < size(); ++x) parent_[x] = parent_[parent_[x]];
    }

    // The parent array, giving the structure up (after flatten(): the root of
    // each element), for a caller that goes on to reuse its memory.
    [[nodiscard]] std::vector<Index> release() && { return std::move(parent_); }

private:
    std::vector<Index> parent_;
    std::vector<Index> size_;  // BySize: the size of each root's set
};

}  // namespace dcel::detail
