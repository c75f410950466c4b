// The sweep status: the active edges, bottom to top, as a doubly linked skip
// list over node ids 0..capacity-1 (the sweep uses edge ids).
//
// Why a skip list: the sweep knows where most insertions go (next to an
// edge it just removed, or to one inserted at the same vertex), so linking
// at a known place must be O(1) expected with no comparisons; only a vertex
// with no edge coming from the left needs a search, O(log n) expected.
// Every level is a circular list through a head sentinel. Node levels come
// from a fixed hash of the id (p = 1/4), so runs are deterministic.
// Memory: about 14 bytes a node.
#pragma once

#include <cstdint>
#include <vector>

#include "dcel/ids.hpp"

namespace dcel {

class StatusList {
public:
    static constexpr Index kNone = kNoIndex;

    explicit StatusList(Index capacity);

    [[nodiscard]] bool contains(Index node) const { return prev0_[node] != kNone; }
    // Neighbours in the order (kNone past either end).
    [[nodiscard]] Index next(Index node) const { return visible(next0_[node]); }
    [[nodiscard]] Index prev(Index node) const { return visible(prev0_[node]); }
    [[nodiscard]] Index first() const { return visible(next0_[head_]); }
    [[nodiscard]] Index last() const { return visible(prev0_[head_]); }

    // Links node just above `below` (kNone: at the bottom). O(1) expected.
    void insert_above(Index below, Index node);
    // Unlinks node. O(1) expected.
    void erase(Index node);

    // The first node (bottom up) for which is_below(node) is false, or kNone;
    // the list must be partitioned by is_below (true, then false).
    // O(log n) expected calls to is_below.
    template <class IsBelow>
    [[nodiscard]] Index first_not_below(IsBelow&& is_below) const {
        Index x = head_;
        for (int level = kMaxLevel; level >= 0; --level) {
            for (Index n = next_at(x, level); n != head_ && is_below(n); n = next_at(x, level)) x = n;
        }
        return visible(next0_[x]);
    }

private:
    static constexpr int kMaxLevel = 15;  // 4^16 nodes before levels run out

    [[nodiscard]] Index visible(Index node) const { return node == head_ ? kNone : node; }
    [[nodiscard]] Index next_at(Index node, int level) const {
        return level == 0 ? next0_[node] : upper_[upper_index_[node] + 2 * static_cast<std::size_t>(level - 1)];
    }
    [[nodiscard]] Index prev_at(Index node, int level) const {
        return level == 0 ? prev0_[node] : upper_[upper_index_[node] + 2 * static_cast<std::size_t>(level - 1) + 1];
    }
    void set_next(Index node, int level, Index to);
    void set_prev(Index node, int level, Index to);

    Index head_;                // the sentinel, node id == capacity
    std::vector<Index> next0_;  // level 0 links; prev0_ is kNone when not in the list
    std::vector<Index> prev0_;
    std::vector<std::uint8_t> level_;  // highest level of each node (0 for 3 nodes in 4)
    std::vector<Index> upper_index_;   // where a node's links for levels >= 1 start in upper_
    std::vector<Index> upper_;         // (next, prev) pairs for levels 1..level_
};

}  // namespace dcel
