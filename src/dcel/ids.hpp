// Strongly typed 32-bit element ids. A VertexId cannot be passed where a
// HalfEdgeId is expected, so a whole class of index mix-ups fails to compile.
// Each id prints with a one-letter prefix (v12, h7, f3) in every diagnostic.
#pragma once

#include <compare>
#include <cstdint>
#include <functional>
#include <limits>
#include <ostream>
#include <string>

namespace dcel {

using Index = std::uint32_t;
inline constexpr Index kNoIndex = std::numeric_limits<Index>::max();

// Tag carries the printed prefix; Id<Tag> is a value type of 4 bytes.
template <class Tag>
class Id {
public:
    constexpr Id() = default;  // the null id
    constexpr explicit Id(Index index) : index_(index) {}

    [[nodiscard]] constexpr Index index() const { return index_; }
    // "is_null" rather than "is_valid": a non-null id may still be out of range.
    [[nodiscard]] constexpr bool is_null() const { return index_ == kNoIndex; }
    // clang-tidy 14 takes the defaulted <=> for a comparison with literal 0.
    constexpr auto operator<=>(const Id&) const = default;  // NOLINT(modernize-use-nullptr)

    [[nodiscard]] std::string str() const {
        return is_null() ? std::string(1, Tag::prefix) + "-" : Tag::prefix + std::to_string(index_);
    }
    friend std::ostream& operator<<(std::ostream& os, Id id) { return os << id.str(); }

private:
    Index index_ = kNoIndex;
};

struct VertexTag {
    static constexpr char prefix = 'v';
};
struct HalfEdgeTag {
    static constexpr char prefix = 'h';
};
struct FaceTag {
    static constexpr char prefix = 'f';
};
struct EdgeTag {
    static constexpr char prefix = 'e';
};

using VertexId = Id<VertexTag>;
using HalfEdgeId = Id<HalfEdgeTag>;
using FaceId = Id<FaceTag>;
// Undirected edge k is the input edge k; it owns half-edges 2k (u->v) and 2k+1 (v->u).
using EdgeId = Id<EdgeTag>;

// Half-edges are allocated in twin pairs, so these are definitions, not lookups.
[[nodiscard]] constexpr HalfEdgeId twin(HalfEdgeId h) { return HalfEdgeId(h.index() ^ 1U); }
[[nodiscard]] constexpr EdgeId edge_of(HalfEdgeId h) { return EdgeId(h.index() >> 1U); }
[[nodiscard]] constexpr HalfEdgeId half_edge_of(EdgeId e, unsigned side) {
    return HalfEdgeId((e.index() << 1U) | (side & 1U));
}

}  // namespace dcel

template <class Tag>
struct std::hash<dcel::Id<Tag>> {
    std::size_t operator()(dcel::Id<Tag> id) const noexcept { return std::hash<dcel::Index>{}(id.index()); }
};
