// Every shape of answer another implementation may give, read from JSON and
// compared with the reference, with the conventions real code uses. The
// kinds, and exactly which projection of the reference each is compared
// with, are in docs/checking.md ("Answer kinds"):
//
//   faces     every boundary cycle, as vertex ids in next order (compare.hpp)
//   dump      a whole DCEL, the `dcel build` format (compare.hpp)
//   polygons  the bounded faces only, each a shell and its holes, as vertex-id
//             or coordinate rings; GeoJSON Polygon, MultiPolygon, Feature,
//             FeatureCollection and GeometryCollection too
//   rings     one ring per bounded face, no holes: the boundary of the face
//             with everything it encloses filled in
//
// Polygons and rings are compared as oriented boundary chains: a ring is the
// set of half-edges it walks, with the face on its left once it is oriented;
// a half-edge and its twin both present cancel (a dangling edge or a bridge
// walked there and back bounds nothing). So a shell that touches itself, a
// hole that touches its shell, and a ring split at a pinch point all mean what
// they mean as point sets, however the answer cut them into rings.
//
// Nothing in an answer is trusted; reading is O(size), comparing
// O((A + E) log E) for an answer of size A.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dcel/check/compare.hpp"
#include "dcel/dcel.hpp"
#include "dcel/dump.hpp"
#include "dcel/geometry/point.hpp"
#include "dcel/io/text_sink.hpp"

namespace dcel::check {

// EvenOdd: polygons of the even-odd regions only (the bounded faces inside
// an odd number of boundaries), as polygonizers that fill by the even-odd
// rule return them; read like polygons, never detected from a shape alone.
enum class AnswerKind : std::uint8_t { Faces, Dump, Polygons, Rings, EvenOdd };
inline constexpr std::size_t kAnswerKindCount = 5;

[[nodiscard]] std::string_view answer_kind_name(AnswerKind k);  // "faces", "dump", "polygons", "rings", "even-odd"
[[nodiscard]] std::optional<AnswerKind> answer_kind_from_name(std::string_view name);

// How an answer's numbers and directions are to be read.
struct Conventions {
    // Faces on the right of their half-edges: every cycle and ring walks the
    // other way, and a dump's next runs with the face on the right.
    bool face_on_right = false;
    // Ids count from 1: vertices (and a dump's half-edges and faces).
    bool one_based = false;
    // Polygons: each ring may run either way (the shell is still the first
    // ring). Rings are always compared this way: the kind fixes no direction.
    bool unoriented = false;
    // Faces: each isolated vertex is written as the one-vertex cycle [v]
    // (face enumerators that list every vertex's cycles do).
    bool isolated_cycles = false;
    // Polygons: holes are never attached, every ring is its own polygon
    // (GEOS/JTS polygonize without hole assignment, Turf): each polygon is a
    // bounded face's outer boundary filled in, compared as the rings kind.
    bool holes_unattached = false;
};

// The polygons and rings kinds, flat: ring r is points [ring_begin[r],
// ring_begin[r+1]) of `ids` (vertex ids) or `points` (coordinates, matched to
// the graph's vertices exactly); polygon p is rings [polygon_begin[p],
// polygon_begin[p+1]), its shell first. The rings kind has one ring per
// polygon. A ring may repeat its first point at the end.
struct RegionAnswer {
    bool by_points = false;
    std::vector<Index> ids;
    std::vector<Point> points;
    std::vector<std::size_t> ring_begin{0};
    std::vector<std::size_t> polygon_begin{0};

    [[nodiscard]] std::size_t polygon_count() const { return polygon_begin.size() - 1; }
    [[nodiscard]] std::size_t ring_count() const { return ring_begin.size() - 1; }
};

struct Answer {
    AnswerKind kind = AnswerKind::Faces;
    CycleList cycles;      // faces
    DcelDump dump;         // dump
    RegionAnswer regions;  // polygons, rings
    // When the kind was detected rather than given: how ("an object with a
    // \"faces\" key"); compare() turns it into a note.
    std::string detected_from;
    // Every kind the text's shape fits, `kind` first: one kind, except for a
    // bare list of id lists (faces or rings) and an empty list (any kind but
    // dump), where the shape alone cannot tell.
    std::vector<AnswerKind> fits;
};

// Reads `text` as an answer of `kind`, or of the kind its shape shows when
// `kind` is empty (an object with "faces", "half_edges", "polygons" or
// "rings", a GeoJSON object, or bare arrays by their depth; a bare list of
// id lists is read as faces, and the note says so). Throws InvalidInput with
// the JSON path of what is wrong.
[[nodiscard]] Answer read_answer(std::string_view text, std::optional<AnswerKind> kind = std::nullopt);

// The answer against the reference, under the conventions. Notes say what
// was assumed, and what the differences suggest (every cycle reversed:
// perhaps --face-on right; vertex 0 never named but V named: perhaps
// --one-based).
[[nodiscard]] Report compare(const Dcel& reference, const Answer& answer, const Conventions& conventions = {});

// The note compare() adds when another convention (--face-on right,
// --one-based, --unoriented, or dropping one of them) makes a disagreeing
// answer agree; nothing when none does.
[[nodiscard]] std::optional<std::string> convention_hint(const Dcel& reference, const Answer& answer,
                                                         const Conventions& conventions);

// The reference's own answer of a kind, as the JSON another implementation
// would print: faces as `dcel faces` writes them, the dump as `dcel build`
// writes it, {"polygons": [[shell, hole, ...], ...]} and {"rings": [ring,
// ...]} with vertex-id rings, one polygon or ring per bounded face in face
// order. A ring that touches itself is written as one ring.
[[nodiscard]] std::string reference_answer(const Dcel& reference, AnswerKind kind);
// The same text, streamed to `sink` a piece of at most 16 KiB at a time
// (dcel/io/text_sink.hpp), as `dcel faces` prints it: the faces and the dump
// straight from the DCEL, the regions a face at a time.
void write_reference_answer(const Dcel& reference, AnswerKind kind, const io::TextSink& sink);

// The bounded faces as polygons (shell first, then holes) or as rings (one
// ring each), by vertex id: what reference_answer writes.
[[nodiscard]] std::vector<std::vector<std::vector<Index>>> reference_regions(const Dcel& reference, AnswerKind kind);

[[nodiscard]] Report compare_polygons(const Dcel& reference, const RegionAnswer& answer,
                                      const Conventions& conventions = {});
[[nodiscard]] Report compare_rings(const Dcel& reference, const RegionAnswer& answer, const Conventions& conventions = {});
[[nodiscard]] Report compare_even_odd(const Dcel& reference, const RegionAnswer& answer,
                                      const Conventions& conventions = {});

// Which bounded faces are even-odd regions: inside an odd number of
// boundaries, i.e. across an odd number of edges from the unbounded face
// (dangling edges and bridges, with one face on both sides, count twice).
// Index: face id; the unbounded face is even.
[[nodiscard]] std::vector<char> odd_faces(const Dcel& reference);

}  // namespace dcel::check
