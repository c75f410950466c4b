// Comparing another implementation's answer with the reference DCEL.
//
// Two forms of answer here (answer.hpp adds the region kinds, polygons and
// rings, reading any kind from JSON, and the conventions real code uses):
//  - faces: every boundary cycle as its vertex ids in next order, as
//    `dcel faces` prints. Cycle order and rotation do not matter,
//    orientation does; the multiset of cycles must equal the reference's.
//  - a whole dump (DcelDump, the `dcel build` format). It is validated first
//    (each broken invariant is a difference), then compared modulo the
//    numbering of half-edges and faces: a half-edge is its (origin, target)
//    pair, a face is its cycles. Vertex ids are fixed by the input.
//
// Nothing in an answer is trusted: ids may be huge, cycles empty or repeated.
// The work is O(A log E) for an answer of total size A on a graph of E edges
// (plus validation for a dump), and the report is capped (kMaxListedPerKind).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/dump.hpp"
#include "dcel/ids.hpp"

namespace dcel::check {

enum class DifferenceKind : std::uint8_t {
    VertexCount,          // an answer names a vertex id >= V, or a dump has the wrong number of points
    NotAnEdge,            // consecutive cycle vertices u, v that are not an edge of the graph
    BrokenInvariant,      // a dump fails a validate.hpp checker (message names the checker and ids)
    MissingCycle,         // a reference cycle the answer does not have
    ExtraCycle,           // an answer cycle the reference does not have (or has fewer times)
    ReversedCycle,        // an answer cycle that is a missing reference cycle walked backwards
    WrongNext,            // at u->v the answer continues to v->x, the reference to v->w
    WrongHole,            // a hole in the wrong face, or in none (dumps)
    WrongOuterBoundary,   // a face's outer boundary listed as a hole, or the other way round (dumps)
    WrongIsolatedVertex,  // an isolated vertex in the wrong face, in none, or not isolated (dumps)
    WrongPoint,           // a dump's coordinates differ from the graph's (dumps)
    UnreadableAnswer,     // the answer could not be read or parsed (never from compare_*: for callers
                          // such as `dcel check` and `dcel diff`, which report it like any difference)
    NotAVertex,           // a ring point given by coordinates that are no vertex of the graph (region kinds)
    WrongOrientation,     // a ring walked against the orientation its kind fixes (polygons)
    MissingFace,          // a bounded face of the reference that no polygon or ring describes (region kinds)
    ExtraPolygon,         // a polygon or ring that describes no bounded face, or one already described
    WrongRefusal,         // a session step refused where the reference accepts it, or the other way round
    WrongQueryAnswer,     // a session query (locate, face_boundary, neighbours, stab) answered otherwise
};

// "vertex-count", "not-an-edge", "broken-invariant", "missing-cycle",
// "extra-cycle", "reversed-cycle", "wrong-next", "wrong-hole",
// "wrong-outer-boundary", "wrong-isolated-vertex", "wrong-point",
// "unreadable-answer", "not-a-vertex", "wrong-orientation", "missing-face",
// "extra-polygon", "wrong-refusal", "wrong-query-answer".
[[nodiscard]] std::string_view kind_name(DifferenceKind k);

struct Difference {
    DifferenceKind kind;
    std::string message;          // one line, in words, naming the ids (and vertices u->v)
    std::vector<Index> vertices;  // the vertices involved, e.g. the cycle, for drawing
};

// At most this many differences of one kind are listed; the rest are counted
// in Report::unlisted. Bounds the report on a hostile answer.
inline constexpr std::size_t kMaxListedPerKind = 100;

struct Report {
    // Deterministic order, the most telling first: by kind in the order
    // unreadable-answer, vertex-count, not-a-vertex, wrong-point,
    // broken-invariant, wrong-refusal, wrong-query-answer, not-an-edge,
    // wrong-next, reversed-cycle,
    // wrong-orientation, missing-cycle, extra-cycle, missing-face,
    // extra-polygon, wrong-outer-boundary, wrong-hole, wrong-isolated-vertex;
    // within a kind, in answer order.
    std::vector<Difference> differences;
    std::size_t unlisted = 0;  // differences found beyond kMaxListedPerKind
    // Not differences: what the comparison assumed or noticed, one line each
    // ("the answer kind was detected as ...", "every cycle is reversed: the
    // answer may keep faces on the right (--face-on right)").
    std::vector<std::string> notes;
    // Sessions: the first step whose answer, or the state after it, differs
    // (the number of steps when only the final state does).
    std::optional<std::size_t> first_wrong_step;
    [[nodiscard]] bool agrees() const { return differences.empty(); }
};

using FacesAnswer = std::vector<std::vector<Index>>;

// Cycles of vertex ids stored flat (one allocation however many cycles):
// cycle i is ids[begin[i] .. begin[i+1]). What the readers produce, so that an
// answer of millions of tiny cycles costs a few bytes per id.
struct CycleList {
    std::vector<Index> ids;
    std::vector<std::size_t> begin{0};

    [[nodiscard]] std::size_t size() const { return begin.size() - 1; }
    [[nodiscard]] std::span<const Index> operator[](std::size_t i) const {
        return std::span<const Index>(ids).subspan(begin[i], begin[i + 1] - begin[i]);
    }
    void end_cycle() { begin.push_back(ids.size()); }  // the ids pushed since the last end_cycle form a cycle
    [[nodiscard]] static CycleList from(const FacesAnswer& faces);
};

[[nodiscard]] Report compare_faces(const Dcel& reference, const FacesAnswer& answer);
[[nodiscard]] Report compare_dump(const Dcel& reference, const DcelDump& answer);

// The report for an answer that could not be read: one unreadable-answer
// difference carrying `message` (e.g. the parser's "line 1, column 3: ...").
[[nodiscard]] Report unreadable_answer(std::string message);

}  // namespace dcel::check
