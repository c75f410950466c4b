// compare_polygons and compare_rings: region answers against the bounded
// faces of the reference, as oriented boundary chains (answer.hpp); and the
// reference's own region answers, listed (reference_regions) or written a
// face at a time (write_reference_answer).
//
// A chain is a sorted list of half-edge ids: a ring contributes the
// half-edges it walks (after orienting it), and a half-edge cancels against
// its twin. The reference chains:
//   polygons: face f is every half-edge with f on its left and another face
//             on its right (its outer cycle and holes, minus dangling edges
//             and bridges, which have f on both sides);
//   rings:    face f is the boundary of f with everything its outer boundary
//             encloses filled in: of the outer cycle's half-edges with another
//             face on the right, those on the outside of the region they
//             bound. Found by building the DCEL of those edges alone and
//             taking its unbounded face's boundary, reversed.
// Two chains are the same region exactly when the lists are equal.
#include <algorithm>
#include <cstring>
#include <map>
#include <numeric>
#include <string>
#include <unordered_map>

#include "dcel/build.hpp"
#include "dcel/check/answer.hpp"
#include "dcel/check/collector.hpp"
#include "dcel/check/cycles.hpp"
#include "dcel/contracts.hpp"
#include "dcel/format.hpp"
#include "dcel/geometry/area.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/json_writer.hpp"

namespace dcel::check {

// From the internals of the core (dcel::detail).
using dcel::detail::polygon_area_sign;

namespace {

using Chain = std::vector<Index>;  // sorted half-edge ids

// Adds the half-edges of `walk` to `counts` (+1 each, -1 for the twin).
void add_walk(std::map<Index, int>& counts, const std::vector<HalfEdgeId>& walk) {
    for (const HalfEdgeId h : walk) {
        if (auto it = counts.find(twin(h).index()); it != counts.end() && it->second > 0) {
            if (--it->second == 0) counts.erase(it);
        } else {
            ++counts[h.index()];
        }
    }
}

Chain to_chain(const std::map<Index, int>& counts) {
    Chain c;
    for (const auto& [h, n] : counts) c.insert(c.end(), static_cast<std::size_t>(n), h);
    return c;
}

std::string face_text(const detail::Reference& ref, FaceId f) {
    const Dcel& d = ref.dcel();
    return "face " + f.str() + " (outer boundary " + detail::cycle_text(ref.cycle_vertices(ref.cycle_of(d.outer(f)))) + ")";
}

// The reference's chain for every bounded face (index: face id; face 0, the
// unbounded face, has none).
std::vector<Chain> polygon_chains(const Dcel& d) {
    std::vector<Chain> chains(d.num_faces());
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        const FaceId f = d.face(HalfEdgeId(h));
        if (f != Dcel::kUnboundedFace && d.face(twin(HalfEdgeId(h))) != f) chains[f.index()].push_back(h);
    }
    return chains;  // sorted: pushed in increasing order
}

// The filled region's boundary of bounded face f (see the file comment).
Chain ring_chain(const Dcel& d, FaceId f) {
    std::vector<HalfEdgeId> kept;
    for (const HalfEdgeId h : d.cycle(d.outer(f))) {
        if (d.face(twin(h)) != f) kept.push_back(h);
    }
    // The kept edges alone, renumbered: edge k of `sub` is kept[k], same direction.
    PlanarGraph sub;
    std::unordered_map<Index, Index> local;
    std::vector<Index> global;
    auto vertex = [&](VertexId v) {
        auto [it, fresh] = local.try_emplace(v.index(), static_cast<Index>(global.size()));
        if (fresh) {
            global.push_back(v.index());
            sub.vertices.push_back(d.point(v));
        }
        return VertexId(it->second);
    };
    for (const HalfEdgeId h : kept) sub.edges.push_back({vertex(d.origin(h)), vertex(d.target(h))});
    const Dcel s = build(sub);  // a subset of a valid graph's edges is valid
    Chain c;
    for (const HalfEdgeId hole : s.inner(Dcel::kUnboundedFace)) {
        for (const HalfEdgeId x : s.cycle(hole)) {
            // x runs clockwise around the region; its twin is the ring's half-edge.
            const HalfEdgeId in_sub = twin(x);
            const HalfEdgeId original = kept[in_sub.index() >> 1U];
            c.push_back(((in_sub.index() & 1U) == 0 ? original : twin(original)).index());
        }
    }
    std::sort(c.begin(), c.end());
    return c;
}

// One answer ring, mapped to reference half-edges, or the reason it cannot be.
struct MappedRing {
    std::vector<HalfEdgeId> walk;
    Sign area = Sign::Zero;
    bool ok = false;
};

// What the answer's regions are compared with, and what they are called.
enum class Regions : std::uint8_t {
    Polygons,         // every bounded face, with holes
    Rings,            // every bounded face, filled in
    UnattachedHoles,  // polygons with --holes-unattached: compared as rings, called polygons
    EvenOdd,          // the bounded faces inside an odd number of boundaries, with holes
};

class RegionComparison {
public:
    RegionComparison(const Dcel& reference, const RegionAnswer& answer, const Conventions& conventions, Regions regions)
        : d_(reference),
          ref_(reference),
          answer_(answer),
          conventions_(conventions),
          rings_(regions == Regions::Rings || regions == Regions::UnattachedHoles),
          named_rings_(regions == Regions::Rings),
          unattached_(regions == Regions::UnattachedHoles),
          even_odd_(regions == Regions::EvenOdd) {
        if (even_odd_) odd_ = odd_faces(reference);
        if (answer.by_points) {
            for (Index v = 0; v < d_.num_vertices(); ++v) vertex_at_.emplace(key(d_.point(VertexId(v))), v);
        }
    }

    Report run() {
        reference_chains();
        std::vector<char> explained(d_.num_faces(), 0);
        std::vector<Index> polygon_of_face(d_.num_faces(), kNoIndex);
        std::size_t closed = 0;
        for (std::size_t p = 0; p < answer_.polygon_count(); ++p) {
            if (unattached_ && has_holes(p)) continue;
            std::map<Index, int> counts;
            bool ok = true;
            std::vector<Index> shell_vertices;
            for (std::size_t r = answer_.polygon_begin[p]; r < answer_.polygon_begin[p + 1]; ++r) {
                const bool shell = r == answer_.polygon_begin[p];
                std::vector<Index> vs = ring_vertices(p, r, closed, ok);
                if (!ok) break;
                if (shell) shell_vertices = vs;
                MappedRing m = map_ring(p, r, vs);
                if (!m.ok) {
                    ok = false;
                    break;
                }
                orient(p, r, shell, vs, m);
                add_walk(counts, m.walk);
            }
            if (!ok) continue;
            match(p, to_chain(counts), shell_vertices, explained, polygon_of_face);
        }
        for (Index f = 1; f < d_.num_faces(); ++f) {
            if (even_odd_ && odd_[f] == 0) continue;  // not a region of the even-odd rule
            if (explained[f] != 0 || !out_.wants(DifferenceKind::MissingFace)) continue;
            const std::vector<Index> vs = ref_.cycle_vertices(ref_.cycle_of(d_.outer(FaceId(f))));
            out_.add(DifferenceKind::MissingFace,
                     "the reference's " + face_text(ref_, FaceId(f)) + " has no " +
                         std::string(named_rings_ ? "ring" : "polygon") + " in the answer",
                     vs);
        }
        Report report = std::move(out_).finish();
        if (unattached_) {
            report.notes.emplace_back(
                "holes read as never attached (--holes-unattached): each polygon is a face's outer boundary, filled in");
        }
        if (closed != 0) {
            report.notes.push_back(std::to_string(closed) + (closed == 1 ? " ring repeats its" : " rings repeat their") +
                                   " first point at the end: read as closed");
        }
        return report;
    }

private:
    static std::pair<std::uint64_t, std::uint64_t> key(Point p) {
        // -0.0 and 0.0 are one point: add 0.0, which turns -0.0 into +0.0.
        const double x = p.x + 0.0, y = p.y + 0.0;
        std::uint64_t a = 0, b = 0;
        std::memcpy(&a, &x, sizeof a);
        std::memcpy(&b, &y, sizeof b);
        return {a, b};
    }
    struct KeyHash {
        std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& k) const {
            return std::hash<std::uint64_t>{}(k.first * 0x9e3779b97f4a7c15ULL ^ k.second);
        }
    };

    // With --holes-unattached every ring is a polygon of its own: a polygon
    // with holes is reported, and not compared.
    bool has_holes(std::size_t p) {
        const std::size_t rings = answer_.polygon_begin[p + 1] - answer_.polygon_begin[p];
        if (rings <= 1) return false;
        if (out_.wants(DifferenceKind::ExtraPolygon)) {
            out_.add(DifferenceKind::ExtraPolygon, "polygon " + std::to_string(p) + " has " + std::to_string(rings - 1) +
                                                       (rings == 2 ? " hole" : " holes") +
                                                       "; with --holes-unattached every ring is a polygon of its own");
        }
        return true;
    }

    std::string ring_label(std::size_t p, std::size_t r) const {
        std::string what = named_rings_ ? "ring " + std::to_string(p) : "polygon " + std::to_string(p);
        if (rings_) return what;
        const std::size_t first = answer_.polygon_begin[p];
        return what + (r == first ? "'s shell" : "'s hole " + std::to_string(r - first - 1));
    }

    void reference_chains() {
        if (rings_) {
            chains_.assign(d_.num_faces(), {});
            for (Index f = 1; f < d_.num_faces(); ++f) chains_[f] = ring_chain(d_, FaceId(f));
        } else {
            chains_ = polygon_chains(d_);
        }
        for (Index f = 1; f < d_.num_faces(); ++f) face_of_chain_.emplace(chains_[f], f);
    }

    // The ring's vertex ids (coordinates matched, 1-based ids shifted, a
    // repeated first point dropped); ok = false after reporting why not.
    std::vector<Index> ring_vertices(std::size_t p, std::size_t r, std::size_t& closed, bool& ok) {
        std::vector<Index> vs;
        const std::size_t begin = answer_.ring_begin[r], end = answer_.ring_begin[r + 1];
        for (std::size_t i = begin; i < end; ++i) {
            if (answer_.by_points) {
                const Point q = answer_.points[i];
                const auto it = vertex_at_.find(key(q));
                if (it == vertex_at_.end()) {
                    if (out_.wants(DifferenceKind::NotAVertex)) {
                        out_.add(DifferenceKind::NotAVertex, ring_label(p, r) + " has the point " + format_point(q) +
                                                                 " (its point " + std::to_string(i - begin) +
                                                                 "), which is no vertex of the graph");
                    }
                    ok = false;
                    return {};
                }
                vs.push_back(it->second);
            } else {
                Index v = answer_.ids[i];
                if (conventions_.one_based) v = v == 0 ? kNoIndex : v - 1;
                if (v >= d_.num_vertices()) {
                    if (out_.wants(DifferenceKind::VertexCount)) {
                        const Index shown = answer_.ids[i];
                        out_.add(DifferenceKind::VertexCount,
                                 ring_label(p, r) + " names vertex " + std::to_string(shown) + ", but the graph has " +
                                     std::to_string(d_.num_vertices()) + " vertices" +
                                     (conventions_.one_based
                                          ? " (ids 1 to " + std::to_string(d_.num_vertices()) + " with --one-based)"
                                          : ""));
                    }
                    ok = false;
                    return {};
                }
                vs.push_back(v);
            }
        }
        if (vs.size() >= 2 && vs.front() == vs.back()) {
            vs.pop_back();
            ++closed;
        }
        // No minimum length: [u, v] walks u->v and back, which cancel, exactly
        // as [u, v, u, v] and a there-and-back path do; a ring of one point
        // (or none) is a closed walk of no steps. Equivalent spellings of a
        // boundary get the same verdict.
        return vs;
    }

    MappedRing map_ring(std::size_t p, std::size_t r, const std::vector<Index>& vs) {
        MappedRing m;
        if (vs.size() < 2) {  // a closed walk of no steps: no half-edges, no area
            m.ok = true;
            return m;
        }
        for (std::size_t j = 0; j < vs.size(); ++j) {
            const Index u = vs[j], v = vs[(j + 1) % vs.size()];
            const HalfEdgeId h = ref_.find(u, v);
            if (h.is_null()) {
                if (out_.wants(DifferenceKind::NotAnEdge)) {
                    out_.add(DifferenceKind::NotAnEdge,
                             ring_label(p, r) + " " + detail::cycle_text(vs) + " steps from v" + std::to_string(u) +
                                 " to v" + std::to_string(v) + ", which is not an edge of the graph",
                             {u, v});
                }
                return m;
            }
            m.walk.push_back(h);
        }
        m.area = polygon_area_sign([&](auto&& edge) {
            for (const HalfEdgeId h : m.walk) edge(d_.point(d_.origin(h)), d_.point(d_.target(h)));
        });
        m.ok = true;
        return m;
    }

    // Shells run counterclockwise and holes clockwise (the other way with
    // --face-on right): a polygon ring that does not is reported, unless
    // --unoriented. Then every ring is turned to the reference's direction
    // (face on the left: shells counterclockwise, holes clockwise), so the
    // chains compare. A ring of zero area has no direction to read off its
    // area: it is the walk as written, in the answer's convention (with
    // --face-on right, backwards). Most such rings go back over themselves
    // and cancel, but a figure eight of two lobes of equal area, one each
    // way, is a sum like any other, and other rings of the polygon may make
    // it a face's boundary.
    void orient(std::size_t p, std::size_t r, bool shell, const std::vector<Index>& vs, MappedRing& m) {
        if (m.area == Sign::Zero) {
            if (conventions_.face_on_right) reverse(m);
            return;
        }
        const bool ccw = m.area == Sign::Positive;
        const bool want_ccw = shell != conventions_.face_on_right;
        if (!rings_ && !conventions_.unoriented && ccw != want_ccw && out_.wants(DifferenceKind::WrongOrientation)) {
            out_.add(DifferenceKind::WrongOrientation,
                     ring_label(p, r) + " " + detail::cycle_text(vs) + " runs " +
                         (want_ccw ? "clockwise" : "counterclockwise") + "; a " + (shell ? "shell" : "hole") + " runs " +
                         (want_ccw ? "counterclockwise" : "clockwise") +
                         (conventions_.face_on_right ? " with --face-on right" : " (GeoJSON's right-hand rule)"),
                     vs);
        }
        if (ccw != (rings_ || shell)) reverse(m);
    }

    static void reverse(MappedRing& m) {
        std::reverse(m.walk.begin(), m.walk.end());
        for (HalfEdgeId& h : m.walk) h = twin(h);
    }

    // Polygon (or ring) p, summed to `chain`, against the reference's faces:
    // a face it is, a face with part of its boundary missing, or a
    // difference.
    void match(std::size_t p, const Chain& chain, const std::vector<Index>& shell, std::vector<char>& explained,
               std::vector<Index>& polygon_of_face) {
        const std::string what = named_rings_ ? "ring " + std::to_string(p) : "polygon " + std::to_string(p);
        const std::string shown = what + " " + detail::cycle_text(shell);
        if (chain.empty()) {
            if (out_.wants(DifferenceKind::ExtraPolygon)) {
                out_.add(DifferenceKind::ExtraPolygon, shown + " bounds no area (it goes back over every edge it walks)",
                         shell);
            }
            return;
        }
        // A face's boundary walks each half-edge once; a sum that walks one
        // twice (a ring listed twice, rings that overlap) is no face, and
        // none of the comparisons below, which treat chains as sets, applies.
        if (const std::string twice = repeated_text(chain); !twice.empty()) {
            if (out_.wants(DifferenceKind::ExtraPolygon)) {
                out_.add(DifferenceKind::ExtraPolygon,
                         shown + " walks " + twice +
                             " more than once (a ring listed twice, or rings that overlap); "
                             "a face's boundary walks each half-edge once",
                         shell);
            }
            return;
        }
        if (const auto it = face_of_chain_.find(chain); it != face_of_chain_.end()) {
            const Index f = it->second;
            if (even_odd_ && odd_[f] == 0) {
                if (out_.wants(DifferenceKind::ExtraPolygon)) {
                    out_.add(DifferenceKind::ExtraPolygon,
                             shown + " is " + face_text(ref_, FaceId(f)) +
                                 ", which lies inside an even number of boundaries: no even-odd region",
                             shell);
                }
                return;
            }
            match_face(p, f, shown, shell, explained, polygon_of_face);
            return;
        }
        // Not a face. When every half-edge lies on one face's chain, the
        // answer has that face with part of its boundary missing.
        const FaceId only = face_holding(chain);
        if (!only.is_null() && !rings_ && (!even_odd_ || odd_[only.index()] != 0)) {
            explained[only.index()] = 1;
            if (out_.wants(DifferenceKind::WrongHole)) {
                out_.add(DifferenceKind::WrongHole,
                         shown + " is " + face_text(ref_, only) + " without " + missing_text(chains_[only.index()], chain),
                         shell);
            }
            return;
        }
        if (out_.wants(DifferenceKind::ExtraPolygon)) {
            out_.add(DifferenceKind::ExtraPolygon,
                     shown + " is no bounded face of the reference" +
                         (rings_ ? " (a ring is the boundary of a bounded face with what it encloses filled in)" : ""),
                     shell);
        }
    }

    // Polygon p is face f: the first polygon to be it explains it, a later
    // one is a repeat.
    void match_face(std::size_t p, Index f, const std::string& shown, const std::vector<Index>& shell,
                    std::vector<char>& explained, std::vector<Index>& polygon_of_face) {
        if (polygon_of_face[f] == kNoIndex) {
            polygon_of_face[f] = static_cast<Index>(p);
            explained[f] = 1;
        } else if (out_.wants(DifferenceKind::ExtraPolygon)) {
            out_.add(DifferenceKind::ExtraPolygon,
                     shown + " repeats " + (named_rings_ ? "ring " : "polygon ") + std::to_string(polygon_of_face[f]) +
                         ": the reference has " + face_text(ref_, FaceId(f)) + " once",
                     shell);
        }
    }

    // The bounded face whose chain holds every half-edge of `chain` (a
    // non-empty chain of distinct half-edges), or null when there is none.
    [[nodiscard]] FaceId face_holding(const Chain& chain) const {
        FaceId only;
        for (const Index h : chain) {
            const FaceId f = d_.face(HalfEdgeId(h));
            const bool on_chain = f != Dcel::kUnboundedFace &&
                                  std::binary_search(chains_[f.index()].begin(), chains_[f.index()].end(), h);
            if (!on_chain || (!only.is_null() && f != only)) return {};
            only = f;
        }
        return only;
    }

    // The half-edges a sorted chain holds more than once ("v5->v4, v4->v6"),
    // or "" when it holds each once.
    std::string repeated_text(const Chain& chain) const {
        constexpr std::size_t kShown = 12;
        std::string s;
        std::size_t shown = 0, repeated = 0;
        for (std::size_t i = 1; i < chain.size(); ++i) {
            if (chain[i] != chain[i - 1] || (i >= 2 && chain[i - 2] == chain[i])) continue;
            ++repeated;
            if (shown++ < kShown) s += (s.empty() ? "" : ", ") + half_edge_text(HalfEdgeId(chain[i]));
        }
        if (repeated > kShown) s += ", ... (" + std::to_string(repeated) + " half-edges)";
        return s;
    }

    std::string half_edge_text(HalfEdgeId h) const {
        return "v" + std::to_string(d_.origin(h).index()) + "->v" + std::to_string(d_.target(h).index());
    }

    // What `full` has that `part` lacks: the half-edges, and whether they lie
    // on the face's outer cycle or on its holes. `part` is a proper subset of
    // `full` (match() calls it for a chain of distinct half-edges, all on
    // `full`, that is not `full`), so something is lacking.
    std::string missing_text(const Chain& full, const Chain& part) const {
        constexpr std::size_t kShown = 12;
        Chain lacking;
        std::set_difference(full.begin(), full.end(), part.begin(), part.end(), std::back_inserter(lacking));
        DCEL_ASSERT(!lacking.empty());
        const Index outer = ref_.cycle_of(d_.outer(d_.face(HalfEdgeId(lacking.front()))));
        const bool on_outer = std::any_of(lacking.begin(), lacking.end(),
                                          [&](Index h) { return ref_.cycle_of(HalfEdgeId(h)) == outer; });
        const bool on_holes = std::any_of(lacking.begin(), lacking.end(),
                                          [&](Index h) { return ref_.cycle_of(HalfEdgeId(h)) != outer; });
        // "Outer cycle" in the DCEL's sense: a triangle joined to the shell by
        // a bridge is on it, though a polygonizer makes it a hole.
        std::string s = on_outer && on_holes ? "edges of its outer cycle and of its holes"
                        : on_outer           ? "edges of its outer cycle"
                                             : "edges of its holes";
        s += ": ";
        for (std::size_t i = 0; i < std::min(kShown, lacking.size()); ++i) {
            s += (i == 0 ? "" : ", ") + half_edge_text(HalfEdgeId(lacking[i]));
        }
        if (lacking.size() > kShown) s += ", ... (" + std::to_string(lacking.size()) + " half-edges)";
        return s;
    }

    const Dcel& d_;
    detail::Reference ref_;
    const RegionAnswer& answer_;
    const Conventions& conventions_;
    bool rings_;        // compared as filled-in outer boundaries
    bool named_rings_;  // and called rings in messages (the rings kind)
    bool unattached_;   // polygons with --holes-unattached
    bool even_odd_;     // only the odd faces are regions
    std::vector<char> odd_;
    detail::Collector out_;
    std::vector<Chain> chains_;
    std::map<Chain, Index> face_of_chain_;
    std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, Index, KeyHash> vertex_at_;
};

// The loops of a chain of face f: from a half-edge of the chain, the next is
// the first chain half-edge clockwise around its target, starting from the
// reference's next (the half-edges in between, dangling edges and bridges,
// are skipped). Shells (counterclockwise) first.
//
// The marks are one per half-edge, all 0 between calls: made once for all
// the faces of a reference (two arrays per face made the regions of the
// 1000x1000 grid take 93 s), and put back to 0 here for what this call set.
struct LoopMarks {
    explicit LoopMarks(const Dcel& d) : in_chain(d.num_half_edges(), 0), seen(d.num_half_edges(), 0) {}
    std::vector<char> in_chain, seen;
    std::vector<Index> seen_list;  // the half-edges seen set, to clear
};

std::vector<std::vector<Index>> loops(const Dcel& d, const Chain& chain, LoopMarks& marks) {
    std::vector<std::vector<Index>> out;
    std::vector<char>& in_chain = marks.in_chain;
    std::vector<char>& seen = marks.seen;
    for (const Index h : chain) in_chain[h] = 1;
    for (const Index start : chain) {
        if (seen[start] != 0) continue;
        std::vector<Index> ring;
        HalfEdgeId h(start);
        for (std::size_t guard = 0; guard <= chain.size() && seen[h.index()] == 0; ++guard) {
            seen[h.index()] = 1;
            marks.seen_list.push_back(h.index());
            ring.push_back(d.origin(h).index());
            HalfEdgeId x = d.next(h);
            for (std::size_t turn = 0; in_chain[x.index()] == 0 && turn < d.num_half_edges(); ++turn) {
                x = d.next(twin(x));
            }
            h = x;
        }
        const Sign s = polygon_area_sign([&](auto&& edge) {
            for (std::size_t i = 0; i < ring.size(); ++i) {
                edge(d.point(VertexId(ring[i])), d.point(VertexId(ring[(i + 1) % ring.size()])));
            }
        });
        if (s == Sign::Positive) {
            out.insert(out.begin(), std::move(ring));
        } else {
            out.push_back(std::move(ring));
        }
    }
    for (const Index h : chain) in_chain[h] = 0;
    for (const Index h : marks.seen_list) seen[h] = 0;
    marks.seen_list.clear();
    return out;
}

}  // namespace

std::vector<char> odd_faces(const Dcel& reference) {
    // Breadth first over the faces, from the unbounded one: crossing an edge
    // with different faces on its sides flips the parity. Every such crossing
    // agrees (the parity of a point is that of the edges a ray from it
    // crosses), so the first one found decides.
    const std::size_t n = reference.num_faces();
    std::vector<std::vector<Index>> across(n);
    for (Index h = 0; h < reference.num_half_edges(); ++h) {
        const FaceId f = reference.face(HalfEdgeId(h)), g = reference.face(twin(HalfEdgeId(h)));
        if (f != g) across[f.index()].push_back(g.index());
    }
    std::vector<char> odd(n, 0), seen(n, 0);
    std::vector<Index> queue{Dcel::kUnboundedFace.index()};
    seen[Dcel::kUnboundedFace.index()] = 1;
    for (std::size_t i = 0; i < queue.size(); ++i) {
        for (const Index g : across[queue[i]]) {
            if (seen[g] != 0) continue;
            seen[g] = 1;
            odd[g] = static_cast<char>(odd[queue[i]] == 0 ? 1 : 0);
            queue.push_back(g);
        }
    }
    return odd;
}

namespace {

// Calls f with each region reference_regions lists, in its order: a bounded
// face's shell and holes (rings: its one ring), as vertex-id loops, one
// face at a time. f may move the region away.
template <class F>
void for_each_reference_region(const Dcel& reference, AnswerKind kind, F&& f) {
    const std::vector<Chain> polygons = kind == AnswerKind::Rings ? std::vector<Chain>{} : polygon_chains(reference);
    const std::vector<char> odd = kind == AnswerKind::EvenOdd ? odd_faces(reference) : std::vector<char>{};
    LoopMarks marks(reference);
    for (Index face = 1; face < reference.num_faces(); ++face) {
        if (kind == AnswerKind::EvenOdd && odd[face] == 0) continue;
        std::vector<std::vector<Index>> region = loops(
            reference, kind == AnswerKind::Rings ? ring_chain(reference, FaceId(face)) : polygons[face], marks);
        f(region);
    }
}

}  // namespace

void write_reference_answer(const Dcel& reference, AnswerKind kind, const io::TextSink& sink) {
    switch (kind) {
        case AnswerKind::Faces: io::write_faces_of(reference, sink); return;
        case AnswerKind::Dump: io::write_dump_of(reference, io::DumpStyle::Compact, sink); return;
        case AnswerKind::Polygons:
        case AnswerKind::Rings:
        case AnswerKind::EvenOdd: break;
    }
    const bool rings = kind == AnswerKind::Rings;
    io::JsonWriter w(sink);
    w.raw(rings ? "{\"rings\": [" : "{\"polygons\": [");
    bool first = true;
    for_each_reference_region(reference, kind, [&](std::vector<std::vector<Index>>& region) {
        if (!first) w.raw(", ");
        first = false;
        if (!rings) w.raw("[");
        for (std::size_t r = 0; r < region.size(); ++r) {
            if (rings && r != 0) break;  // one ring per face
            if (r != 0) w.raw(", ");
            w.raw("[");
            for (std::size_t i = 0; i < region[r].size(); ++i) {
                if (i != 0) w.raw(", ");
                w.index(region[r][i]);
            }
            w.raw("]");
        }
        if (!rings) w.raw("]");
    });
    w.raw("]}\n");
    w.flush();
}

std::vector<std::vector<std::vector<Index>>> reference_regions(const Dcel& reference, AnswerKind kind) {
    std::vector<std::vector<std::vector<Index>>> out;
    for_each_reference_region(reference, kind,
                              [&](std::vector<std::vector<Index>>& region) { out.push_back(std::move(region)); });
    return out;
}

Report compare_polygons(const Dcel& reference, const RegionAnswer& answer, const Conventions& conventions) {
    return RegionComparison(reference, answer, conventions,
                            conventions.holes_unattached ? Regions::UnattachedHoles : Regions::Polygons)
        .run();
}

Report compare_rings(const Dcel& reference, const RegionAnswer& answer, const Conventions& conventions) {
    return RegionComparison(reference, answer, conventions, Regions::Rings).run();
}

Report compare_even_odd(const Dcel& reference, const RegionAnswer& answer, const Conventions& conventions) {
    return RegionComparison(reference, answer, conventions, Regions::EvenOdd).run();
}

}  // namespace dcel::check
