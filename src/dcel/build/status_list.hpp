// The sweep status: the active edges, bottom to top, as a doubly linked skip
// list of nodes.
//
// Why a skip list: the sweep knows where most insertions go (next to an
// edge it just removed, or to one inserted at the same vertex), so linking
// at a known place must be O(1) expected with no comparisons; only a vertex
// with no edge coming from the left needs a search, O(log n) expected.
// Every level is a circular list through a head sentinel. Node levels come
// from a fixed hash of the node id (p = 1/4), so runs are deterministic.
//
// Node ids are handed out by the list, and the id of an erased node is
// reused by the next insertion (last erased, first reused). So the memory
// touched is proportional to the most edges active at once, not to all the
// edges the sweep ever sees: a few thousand for a triangulation of a
// million points. Memory: about 14 bytes a node, reserved up front for the
// capacity and touched only as nodes are made.
#pragma once

#include <cstdint>
#include <vector>

#include "dcel/ids.hpp"

namespace dcel::detail {

class StatusList {
public:
    static constexpr Index kNone = kNoIndex;

    // At most `capacity` nodes in the list at once.
    explicit StatusList(Index capacity);

    // Whether node is in the list now (false for ids never handed out and
    // for erased ones until they are reused).
    [[nodiscard]] bool contains(Index node) const { return node < prev0_.size() && prev0_[node] != kNone; }
    // Neighbours in the order (kNone past either end).
    [[nodiscard]] Index next(Index node) const { return visible(next0_[node]); }
    [[nodiscard]] Index prev(Index node) const { return visible(prev0_[node]); }
    [[nodiscard]] Index first() const { return visible(next0_[kHead]); }
    [[nodiscard]] Index last() const { return visible(prev0_[kHead]); }

    // Links a node just above `below` (kNone: at the bottom) and returns its
    // id: the last erased one if any, else a new one. O(1) expected.
    [[nodiscard]] Index insert_above(Index below);
    // Unlinks node; its id may be handed out again. O(1) expected.
    void erase(Index node);

    // The most ids ever handed out at once (at least the most nodes ever in
    // the list): what the list's memory grew to.
    [[nodiscard]] Index ids_made() const { return static_cast<Index>(prev0_.size() - 1); }

    // The first node (bottom up) for which is_below(node) is false, or kNone;
    // the list must be partitioned by is_below (true, then false).
    // O(log n) expected calls to is_below.
    template <class IsBelow>
    [[nodiscard]] Index first_not_below(IsBelow&& is_below) const {
        Index x = kHead;
        for (int level = kMaxLevel; level >= 0; --level) {
            for (Index n = next_at(x, level); n != kHead && is_below(n); n = next_at(x, level)) x = n;
        }
        return visible(next0_[x]);
    }

private:
    static constexpr int kMaxLevel = 15;  // 4^16 nodes before levels run out
    static constexpr Index kHead = 0;     // the sentinel; it reaches every level

    [[nodiscard]] static Index visible(Index node) { return node == kHead ? kNone : node; }
    [[nodiscard]] Index next_at(Index node, int level) const {
        return level == 0 ? next0_[node] : upper_[upper_index_[node] + 2 * static_cast<std::size_t>(level - 1)];
    }
    [[nodiscard]] Index prev_at(Index node, int level) const {
        return level == 0 ? prev0_[node] : upper_[upper_index_[node] + 2 * static_cast<std::size_t>(level - 1) + 1];
    }
    void set_next(Index node, int level, Index to);
    void set_prev(Index node, int level, Index to);
    // An id for a node about to be linked: a reused one, or a new one with
    // its level drawn and its upper links allocated.
    [[nodiscard]] Index take_id();

    std::vector<Index> next0_;         // level 0 links; for a node not in the list, next0_ chains the free ids
    std::vector<Index> prev0_;         // level 0 links; kNone when not in the list
    std::vector<std::uint8_t> level_;  // highest level of each node (0 for 3 nodes in 4)
    std::vector<Index> upper_index_;   // where a node's links for levels >= 1 start in upper_
    std::vector<Index> upper_;         // (next, prev) pairs for levels 1..level_
    Index free_ = kNone;               // the last erased id, heading the chain of free ids
};

}  // namespace dcel::detail
