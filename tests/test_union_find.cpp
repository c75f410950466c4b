// The union-find of the core (core/union_find.hpp) against a plain
// reference: a label per element, relabelled in full on every union.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "dcel/core/union_find.hpp"

namespace dcel {

using detail::Linking;
using detail::UnionFind;
namespace {

// Sets as labels: a union relabels every element of one set. O(n) a union,
// obviously right.
class LabelSets {
public:
    explicit LabelSets(Index n) : label_(n) {
        for (Index x = 0; x < n; ++x) label_[x] = x;
    }
    [[nodiscard]] bool same(Index a, Index b) const { return label_[a] == label_[b]; }
    bool unite(Index a, Index b) {
        const Index from = label_[b];
        const Index to = label_[a];
        if (from == to) return false;
        std::replace(label_.begin(), label_.end(), from, to);
        return true;
    }
    [[nodiscard]] Index smallest_with_label_of(Index x) const {
        for (Index y = 0;; ++y) {
            if (label_[y] == label_[x]) return y;
        }
    }

private:
    std::vector<Index> label_;
};

TEST(UnionFind, StartsWithSingletons) {
    UnionFind sets(5);
    EXPECT_EQ(sets.size(), 5U);
    for (Index x = 0; x < 5; ++x) EXPECT_EQ(sets.find(x), x);
    UnionFind empty(0);
    EXPECT_EQ(empty.size(), 0U);
}

TEST(UnionFind, UniteReportsWhetherItJoined) {
    UnionFind sets(4);
    EXPECT_TRUE(sets.unite(0, 1));
    EXPECT_TRUE(sets.unite(2, 3));
    EXPECT_FALSE(sets.unite(1, 0));
    EXPECT_TRUE(sets.unite(1, 3));
    EXPECT_FALSE(sets.unite(0, 2));
    EXPECT_FALSE(sets.unite(3, 3));
    for (Index x = 1; x < 4; ++x) EXPECT_EQ(sets.find(x), sets.find(0));
}

TEST(UnionFind, BySizeKeepsTheLargerSetsRoot) {
    UnionFind sets(6);
    (void)sets.unite(1, 2);
    (void)sets.unite(1, 3);  // {1, 2, 3}
    const Index big = sets.find(1);
    EXPECT_EQ(sets.link(sets.find(0), big), big);  // {0} joins it, not the other way round
    EXPECT_EQ(sets.find(0), big);
    // Equal sizes: the first root stays.
    EXPECT_EQ(sets.link(4, 5), 4U);
}

TEST(UnionFind, SmallestRootKeepsTheSmallestElementAsRoot) {
    UnionFind<Linking::SmallestRoot> sets(6);
    EXPECT_EQ(sets.link(5, 3), 3U);
    (void)sets.unite(4, 5);
    EXPECT_EQ(sets.find(4), 3U);
    (void)sets.unite(5, 1);
    for (const Index x : {1U, 3U, 4U, 5U}) EXPECT_EQ(sets.find(x), 1U);
    EXPECT_EQ(sets.find(0), 0U);
    EXPECT_EQ(sets.find(2), 2U);
}

TEST(UnionFind, FlattenPointsEveryElementAtItsRoot) {
    UnionFind<Linking::SmallestRoot> sets(7);
    (void)sets.unite(6, 5);
    (void)sets.unite(5, 4);
    (void)sets.unite(4, 2);
    (void)sets.unite(3, 1);
    sets.flatten();
    const std::vector<Index> parent = std::move(sets).release();
    EXPECT_EQ(parent, (std::vector<Index>{0, 1, 2, 1, 2, 2, 2}));
}

TEST(UnionFind, ReusesTheStorageItIsGiven) {
    std::vector<Index> storage;
    storage.reserve(100);
    const Index* memory = storage.data();
    UnionFind<Linking::SmallestRoot> sets(50, std::move(storage));
    (void)sets.unite(10, 20);
    const std::vector<Index> parent = std::move(sets).release();
    EXPECT_EQ(parent.data(), memory);
    EXPECT_EQ(parent.size(), 50U);
    EXPECT_EQ(parent[20], 10U);
}

template <Linking L>
void check_against_labels(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const Index n = std::uniform_int_distribution<Index>(1, 200)(rng);
    std::uniform_int_distribution<Index> element(0, n - 1);
    UnionFind<L> sets(n);
    LabelSets reference(n);
    for (Index step = 0; step < 2 * n; ++step) {
        const Index a = element(rng);
        const Index b = element(rng);
        ASSERT_EQ(sets.unite(a, b), reference.unite(a, b)) << "seed " << seed << " step " << step;
        const Index x = element(rng);
        const Index y = element(rng);
        ASSERT_EQ(sets.find(x) == sets.find(y), reference.same(x, y)) << "seed " << seed << " step " << step;
    }
    for (Index x = 0; x < n; ++x) {
        if constexpr (L == Linking::SmallestRoot) {
            ASSERT_EQ(sets.find(x), reference.smallest_with_label_of(x));
        }
        // Path halving keeps every find on a set's elements at one root.
        ASSERT_EQ(sets.find(x), sets.find(reference.smallest_with_label_of(x)));
    }
    if constexpr (L == Linking::SmallestRoot) {
        sets.flatten();
        const std::vector<Index> parent = std::move(sets).release();
        for (Index x = 0; x < n; ++x) ASSERT_EQ(parent[x], reference.smallest_with_label_of(x));
    }
}

TEST(UnionFind, BySizeAgreesWithLabels) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) check_against_labels<Linking::BySize>(seed);
}

TEST(UnionFind, SmallestRootAgreesWithLabels) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) check_against_labels<Linking::SmallestRoot>(seed);
}

// Union by size bounds every element's depth by log2(n) (path halving only
// shortens paths): the parents left after random unions say so.
TEST(UnionFind, BySizeStaysShallow) {
    const Index n = 1024;
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<Index> element(0, n - 1);
    UnionFind sets(n);
    for (Index step = 0; step < 4 * n; ++step) (void)sets.unite(element(rng), element(rng));
    const std::vector<Index> parent = std::move(sets).release();
    for (Index x = 0; x < n; ++x) {
        int depth = 0;
        for (Index y = x; parent[y] != y; y = parent[y]) ++depth;
        EXPECT_LE(depth, 10) << "element " << x;
    }
}

}  // namespace
}  // namespace dcel
