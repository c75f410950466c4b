// Step 2 of the answer trials: the reference's answer in other words,
// each change keeping what the checker must read (answer_spellings.hpp).
#include <string>
#include <utility>
#include <vector>

#include "support/answer_steps.hpp"

namespace dcel::test_support::spell {
namespace {

// The direction a ring of this role runs in when faces are on the left:
// +1 counterclockwise (shells, the rings kind), -1 clockwise (holes).
int wanted(bool shell) { return shell ? 1 : -1; }

// A ring may stand in its role when it runs that way, or has no area (then
// the checker and the oracle take it as written).
bool fits_role(const Facts& f, const IdRing& ring, bool shell) {
    const int s = f.judge.area_sign(ring);
    return s == 0 || s == wanted(shell);
}

// Split ring r at a vertex it visits twice: the two closed walks it is made
// of, one in its place, the other as a hole. Their half-edges are the
// ring's, so the sum is unchanged, provided each piece runs its role's way
// (or has no area): a shell pinched around a clockwise pocket splits into
// the shell and a hole touching it; two counterclockwise lobes do not split.
bool split_ring(const Facts& f, IdPolygon& polygon, std::size_t r, bool rings_kind, Choices& c, std::string& story) {
    if (rings_kind) return false;  // a rings answer has one ring per face: no holes to split into
    const IdRing& ring = polygon[r];
    std::vector<std::pair<std::size_t, std::size_t>> pinches;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        for (std::size_t j = i + 1; j < ring.size(); ++j) {
            if (ring[i] == ring[j]) pinches.emplace_back(i, j);
        }
    }
    if (pinches.empty()) return false;
    const auto [i, j] = pick(pinches, c);
    const IdRing a(ring.begin() + static_cast<std::ptrdiff_t>(i), ring.begin() + static_cast<std::ptrdiff_t>(j));
    IdRing b = rotated_to(ring, j);
    b.resize(ring.size() - (j - i));
    const bool shell = r == 0;
    for (const auto& [stay, leave] : {std::pair{a, b}, std::pair{b, a}}) {
        if (fits_role(f, stay, shell) && fits_role(f, leave, false)) {
            story += "split ring " + list_text(ring) + " into " + list_text(stay) + " and the hole " + list_text(leave) +
                     "\n";
            polygon[r] = stay;
            polygon.push_back(leave);
            return true;
        }
    }
    return false;
}

// Join rings a < b of a polygon at a vertex both visit: one closed walk
// with the half-edges of both, in a's place (the shell stays first), when
// it runs a's way (or has no area).
bool join_rings(const Facts& f, IdPolygon& polygon, std::size_t a, std::size_t b, Choices& c, std::string& story) {
    std::vector<std::pair<std::size_t, std::size_t>> shared;
    for (std::size_t i = 0; i < polygon[a].size(); ++i) {
        for (std::size_t j = 0; j < polygon[b].size(); ++j) {
            if (polygon[a][i] == polygon[b][j]) shared.emplace_back(i, j);
        }
    }
    if (shared.empty()) return false;
    const auto [i, j] = pick(shared, c);
    IdRing joined = rotated_to(polygon[a], i);
    const IdRing tail = rotated_to(polygon[b], j);
    // A ring of one point walks nothing: joined, it leaves the other as it is.
    if (joined.size() == 1) joined.clear();
    if (tail.size() > 1) joined.insert(joined.end(), tail.begin(), tail.end());
    if (joined.empty()) joined = tail;
    if (!fits_role(f, joined, a == 0)) return false;
    story += "joined rings " + list_text(polygon[a]) + " and " + list_text(polygon[b]) + " into " + list_text(joined) + "\n";
    polygon[a] = std::move(joined);
    polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(b));
    return true;
}

// A there-and-back step u -> w -> u inserted after some u: the two
// half-edges cancel, and the area is unchanged. (A ring [u] becomes [u, w].)
bool excursion(const Facts& f, IdRing& ring, Choices& c, std::string& story) {
    if (ring.empty()) return false;
    const std::size_t at = c.below(ring.size());
    const Index u = ring[at];
    if (f.neighbours[u].empty()) return false;
    const Index w = pick(f.neighbours[u], c);
    if (ring.size() == 1) {
        ring.push_back(w);  // [u] walks nothing, [u, w] there and back
    } else {
        ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(at) + 1, {w, u});
    }
    story += "went out and back along " + std::to_string(u) + "-" + std::to_string(w) + "\n";
    return true;
}

// A degenerate hole: [u, v] walks the edge both ways, which cancel (an edge
// with the face on both sides, a lone edge or a dangle, when there is one);
// [v] walks nothing.
bool degenerate_hole(const Facts& f, IdPolygon& polygon, Choices& c, std::string& story) {
    if (f.vertex_count() == 0) return false;
    IdRing hole;
    if (c.one_in(4) || f.edges.empty()) {
        hole = {static_cast<Index>(c.below(f.vertex_count()))};
    } else {
        const auto [u, v] = pick(f.lone_edges.empty() ? f.edges : f.lone_edges, c);
        hole = c.one_in(2) ? IdRing{v, u} : IdRing{u, v};
    }
    story += "added the degenerate hole " + list_text(hole) + "\n";
    polygon.push_back(std::move(hole));
    return true;
}

}  // namespace

void respell_regions(const Facts& f, std::vector<IdPolygon>& polygons, bool rings_kind, bool any_direction, Choices& c,
                     std::string& story) {
    for (std::size_t n = c.below(5); n > 0 && !polygons.empty(); --n) {
        IdPolygon& polygon = polygons[c.below(polygons.size())];
        if (polygon.empty()) continue;
        const std::size_t r = c.below(polygon.size());
        switch (c.below(4)) {
            case 0: (void)excursion(f, polygon[r], c, story); break;
            case 1: (void)split_ring(f, polygon, r, rings_kind, c, story); break;
            case 2:
                if (polygon.size() >= 2) {
                    const std::size_t b = c.below(polygon.size());
                    if (b != r) (void)join_rings(f, polygon, std::min(r, b), std::max(r, b), c, story);
                }
                break;
            default:
                if (!rings_kind) (void)degenerate_hole(f, polygon, c, story);
                break;
        }
    }
    for (IdPolygon& polygon : polygons) {
        if (polygon.size() > 2 && c.one_in(2)) {  // the holes in another order; the shell stays first
            std::vector<IdRing> holes(polygon.begin() + 1, polygon.end());
            shuffle(holes, c);
            std::copy(holes.begin(), holes.end(), polygon.begin() + 1);
        }
        for (IdRing& ring : polygon) {
            rotate(ring, c);
            // Reversed where the direction is free (and the ring has an
            // area: one without keeps the direction it is written in).
            if (any_direction && f.judge.area_sign(ring) != 0 && c.one_in(2)) std::reverse(ring.begin(), ring.end());
        }
    }
    if (c.one_in(2)) shuffle(polygons, c);
}

namespace {

// The half-edges of h's next-cycle in the reference (valid) dump.
std::vector<HalfEdgeId> cycle_of(const DcelDump& d, HalfEdgeId h) {
    std::vector<HalfEdgeId> out;
    HalfEdgeId x = h;
    do {
        out.push_back(x);
        x = d.half_edges[x.index()].next;
    } while (x != h && out.size() <= d.half_edges.size());
    return out;
}

}  // namespace

void respell_dump(DcelDump& d, Choices& c, std::string& story) {
    for (FaceDump& face : d.faces) {
        if (!face.outer.is_null() && c.one_in(2)) face.outer = pick(cycle_of(d, face.outer), c);
        for (HalfEdgeId& h : face.inner) {
            if (c.one_in(2)) h = pick(cycle_of(d, h), c);
        }
        if (c.one_in(2)) shuffle(face.inner, c);
        if (c.one_in(2)) shuffle(face.isolated, c);
    }
    // vertex_out: any half-edge leaving the vertex, or none given at all.
    std::vector<std::vector<HalfEdgeId>> leaving(d.vertices.size());
    for (Index h = 0; h < d.half_edges.size(); ++h) leaving[d.half_edges[h].origin.index()].emplace_back(h);
    for (std::size_t v = 0; v < d.vertex_out.size(); ++v) {
        if (!leaving[v].empty() && c.one_in(2)) d.vertex_out[v] = pick(leaving[v], c);
    }
    if (c.one_in(4)) {
        story += "left vertex_out out\n";
        d.vertex_out.clear();
    }
}

}  // namespace dcel::test_support::spell
