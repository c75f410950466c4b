#include "dcel/build/status_list.hpp"

#include "dcel/build/huge_pages.hpp"

namespace dcel::detail {
namespace {

// splitmix64: a fixed hash, so node levels do not depend on a seed.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27U)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31U);
}

}  // namespace

StatusList::StatusList(Index capacity) {
    // Reserved, so ids never move and no array is copied as the list grows;
    // pages are touched only as nodes are made.
    const std::size_t nodes = capacity + std::size_t{1};
    reserve_huge(next0_, nodes);
    reserve_huge(prev0_, nodes);
    reserve_huge(level_, nodes);
    reserve_huge(upper_index_, nodes);
    reserve_huge(upper_, 2 * static_cast<std::size_t>(kMaxLevel) + nodes + 64);  // 2/3 of a link a node expected
    next0_.push_back(kHead);
    prev0_.push_back(kHead);
    level_.push_back(kMaxLevel);
    upper_index_.push_back(0);
    upper_.assign(2 * static_cast<std::size_t>(kMaxLevel), kHead);
}

Index StatusList::take_id() {
    if (free_ != kNone) {
        const Index node = free_;
        free_ = next0_[node];
        return node;
    }
    const auto node = static_cast<Index>(prev0_.size());
    std::uint64_t bits = mix(node);
    int level = 0;
    while (level < kMaxLevel && (bits & 3U) == 0) {  // each level with probability 1/4
        ++level;
        bits >>= 2U;
    }
    next0_.push_back(kNone);
    prev0_.push_back(kNone);
    level_.push_back(static_cast<std::uint8_t>(level));
    upper_index_.push_back(static_cast<Index>(upper_.size()));
    upper_.resize(upper_.size() + 2 * static_cast<std::size_t>(level), kNone);
    return node;
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

Index StatusList::insert_above(Index below) {
    const Index node = take_id();
    Index p = below == kNone ? kHead : below;
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
    return node;
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
    next0_[node] = free_;
    free_ = node;
}

}  // namespace dcel::detail
