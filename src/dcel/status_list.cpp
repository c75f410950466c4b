#include "dcel/status_list.hpp"

namespace dcel {
namespace {

// splitmix64: a fixed hash, so node levels do not depend on a seed.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27U)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31U);
}

}  // namespace

StatusList::StatusList(Index capacity)
    : head_(capacity),
      next0_(capacity + std::size_t{1}),
      prev0_(capacity + std::size_t{1}, kNone),
      level_(capacity + std::size_t{1}),
      upper_index_(capacity + std::size_t{1}, 0) {
    std::size_t upper_size = 0;
    for (Index i = 0; i < capacity; ++i) {
        std::uint64_t bits = mix(i);
        int level = 0;
        while (level < kMaxLevel && (bits & 3U) == 0) {  // each level with probability 1/4
            ++level;
            bits >>= 2U;
        }
        level_[i] = static_cast<std::uint8_t>(level);
        upper_index_[i] = static_cast<Index>(upper_size);
        upper_size += 2 * static_cast<std::size_t>(level);
    }
    level_[head_] = kMaxLevel;
    upper_index_[head_] = static_cast<Index>(upper_size);
    upper_size += 2 * static_cast<std::size_t>(kMaxLevel);
    upper_.assign(upper_size, head_);
    next0_[head_] = head_;
    prev0_[head_] = head_;
}

void StatusList::set_next(Index node, int level, Index to) {
    if (level == 0) {
        next0_[node] = to;
    } else {
        upper_[upper_index_[node] + 2 * static_cast<std::size_t>(level - 1)] = to;
    }
}

void StatusList::set_prev(Index node, int level, Index to) {
    if (level == 0) {
        prev0_[node] = to;
    } else {
        upper_[upper_index_[node] + 2 * static_cast<std::size_t>(level - 1) + 1] = to;
    }
}

void StatusList::insert_above(Index below, Index node) {
    Index p = below == kNone ? head_ : below;
    const int top = level_[node];
    for (int level = 0; level <= top; ++level) {
        // p becomes the nearest node at or below `below` that reaches this
        // level: walk down the level beneath (expected 4 steps; the head
        // reaches every level).
        while (level_[p] < level) p = prev_at(p, level - 1);
        const Index n = next_at(p, level);
        set_next(p, level, node);
        set_prev(node, level, p);
        set_next(node, level, n);
        set_prev(n, level, node);
    }
}

void StatusList::erase(Index node) {
    const int top = level_[node];
    for (int level = 0; level <= top; ++level) {
        const Index p = prev_at(node, level);
        const Index n = next_at(node, level);
        set_next(p, level, n);
        set_prev(n, level, p);
    }
    prev0_[node] = kNone;
}

}  // namespace dcel
