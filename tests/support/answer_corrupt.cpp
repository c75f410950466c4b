// Step 3 of the answer trials: one corruption. The verdict the checker
// must give is the oracle's (oracles/answer_meaning.hpp) on the result,
// never this code's. Each corruption is chosen to change the meaning, and
// the comments say why it does; where that holds only mostly (a
// degenerate hole dropped, a lone edge's cycle [u, v] reversed), the oracle
// finds the answer still right and the checker must agree with it.
// Before step 3 every polygon is one reference face's (meaning 1 on that
// face, 0 elsewhere, never nothing: a bounded face's boundary has an edge
// with another face across) and every cycle one reference cycle.
#include <cmath>
#include <string>
#include <vector>

#include "support/answer_steps.hpp"

namespace dcel::test_support::spell {
namespace {

HalfEdgeId any_half_edge(const DcelDump& d, Choices& c) {
    return HalfEdgeId(static_cast<Index>(c.below(d.half_edges.size() + 1)));
}
FaceId any_face(const DcelDump& d, Choices& c) { return FaceId(static_cast<Index>(c.below(d.faces.size() + 1))); }

}  // namespace

void corrupt_regions(const Facts& f, std::vector<IdPolygon>& polygons, bool rings_kind, bool oriented, Choices& c,
                     std::string& story) {
    auto any_polygon = [&]() -> IdPolygon& { return polygons[c.below(polygons.size())]; };
    const std::size_t what = polygons.empty() ? 7 : c.below(11);
    switch (what) {
        case 0:
            // One face's meaning is gone from the multiset: always wrong.
            story += "dropped a polygon\n";
            polygons.erase(polygons.begin() + static_cast<std::ptrdiff_t>(c.below(polygons.size())));
            return;
        case 1:
            // One face's meaning twice: always wrong.
            story += "repeated a polygon\n";
            polygons.push_back(any_polygon());
            return;
        case 2: {
            IdPolygon& p = any_polygon();
            if (p.size() < 2 || rings_kind) break;
            // The polygon loses the hole's winding numbers: wrong unless the
            // hole bounds nothing (a degenerate one).
            story += "dropped a hole\n";
            p.erase(p.begin() + 1 + static_cast<std::ptrdiff_t>(c.below(p.size() - 1)));
            return;
        }
        case 3: {
            // The ring's winding numbers twice: wrong unless it bounds
            // nothing. A hole listed twice crashed dcel check (d76fb2d). (A
            // rings answer has one ring per polygon: case 1 repeats one.)
            IdPolygon& p = any_polygon();
            if (p.empty() || rings_kind) break;
            story += "listed a ring twice\n";
            p.push_back(p[c.below(p.size())]);
            return;
        }
        case 4: {
            IdPolygon& p = any_polygon();
            if (p.empty()) break;
            IdRing& ring = p[c.below(p.size())];
            if (ring.empty()) break;
            // Mostly a step along no edge, or an id past the last; but the
            // same id again, or [u, v] made [u, w] along another edge,
            // mean what they meant.
            const std::size_t i = c.below(ring.size());
            const Index was = ring[i];
            ring[i] = f.any_id(c);
            story += "replaced vertex " + std::to_string(was) + " by " + std::to_string(ring[i]) + "\n";
            return;
        }
        case 5: {
            // One polygon loses the hole's winding numbers and another gains
            // them: wrong unless the hole bounds nothing.
            if (polygons.size() < 2 || rings_kind) break;
            IdPolygon& from = any_polygon();
            IdPolygon& to = any_polygon();
            if (&from == &to || from.size() < 2) break;
            story += "moved a hole to another polygon\n";
            const std::size_t h = 1 + c.below(from.size() - 1);
            to.push_back(from[h]);
            from.erase(from.begin() + static_cast<std::ptrdiff_t>(h));
            return;
        }
        case 6: {
            IdPolygon& p = any_polygon();
            if (p.empty()) break;
            const std::size_t r = c.below(p.size());
            // Oriented polygons: a ring with an area, reversed, runs against
            // its role: always wrong. Where the direction is free only a
            // ring without area that is no there-and-back walk (a figure
            // eight) changes meaning when reversed.
            if (oriented && f.judge.area_sign(p[r]) == 0) break;
            story += "reversed ring " + list_text(p[r]) + "\n";
            std::reverse(p[r].begin(), p[r].end());
            return;
        }
        case 7: {
            if (f.edges.empty()) break;
            // Winding number 0 everywhere is no face's: always wrong.
            const auto [u, v] = pick(f.edges, c);
            story += "added a polygon [u, v] that bounds nothing\n";
            polygons.push_back({{u, v}});
            return;
        }
        case 8: {
            if (polygons.size() < 2 || rings_kind) break;
            const std::size_t a = c.below(polygons.size()), b = c.below(polygons.size());
            if (a == b) break;
            // 1 on two faces is no one face's, and one polygon fewer: always
            // wrong.
            story += "merged two polygons\n";
            polygons[a].insert(polygons[a].end(), polygons[b].begin(), polygons[b].end());
            polygons.erase(polygons.begin() + static_cast<std::ptrdiff_t>(b));
            return;
        }
        case 9: {
            IdPolygon& p = any_polygon();
            if (p.size() < 2) break;
            // The hole now turned counterclockwise and the shell clockwise
            // (or, oriented, both running against their new roles): wrong
            // unless both bound nothing.
            story += "swapped a shell and a hole\n";
            std::swap(p[0], p[1 + c.below(p.size() - 1)]);
            return;
        }
        default: {
            IdPolygon& p = any_polygon();
            if (p.empty() || p[0].size() < 2) break;
            IdRing& ring = p[c.below(p.size())];
            if (ring.empty()) break;
            // A step along no edge, mostly; the oracle says when not (a
            // vertex dropped from an excursion there and back).
            const std::size_t i = c.below(ring.size());
            if (c.one_in(2)) {
                story += "dropped vertex " + std::to_string(ring[i]) + " from a ring\n";
                ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
            } else {
                const Index v = f.any_id(c);
                story += "inserted vertex " + std::to_string(v) + " into a ring\n";
                ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(i), v);
            }
            return;
        }
    }
    // The corruption chosen did not fit this answer: a polygon that bounds
    // nothing, [v] alone, always fits, and is always wrong.
    story += "added a polygon [v] that bounds nothing\n";
    polygons.push_back({{f.any_id(c)}});
}

void corrupt_faces(const Facts& f, std::vector<IdRing>& cycles, Choices& c, std::string& story) {
    const std::size_t what = cycles.empty() ? 8 : c.below(9);
    IdRing* one = cycles.empty() ? nullptr : &cycles[c.below(cycles.size())];
    switch (what) {
        case 0:
            // A reference cycle missing from the multiset: always wrong.
            story += "dropped cycle " + list_text(*one) + "\n";
            cycles.erase(cycles.begin() + (one - cycles.data()));
            return;
        case 1:
            // A reference cycle twice: always wrong.
            story += "repeated cycle " + list_text(*one) + "\n";
            cycles.push_back(*one);
            return;
        case 2:
            // Wrong, but for a cycle that is its own reverse (a lone edge's
            // [u, v]).
            story += "reversed cycle " + list_text(*one) + "\n";
            std::reverse(one->begin(), one->end());
            return;
        case 3: {
            // Wrong, but for the same id again.
            const std::size_t i = c.below(one->size());
            const Index was = (*one)[i];
            (*one)[i] = f.any_id(c);
            story += "replaced vertex " + std::to_string(was) + " by " + std::to_string((*one)[i]) + "\n";
            return;
        }
        case 4: {
            // Two cycles through one vertex rewired there: each takes the
            // other's way on (a wrong next), or one cycle through a vertex
            // twice split into two. One cycle more or fewer than the
            // reference has: always wrong.
            IdRing& other = cycles[c.below(cycles.size())];
            std::vector<std::pair<std::size_t, std::size_t>> shared;
            for (std::size_t i = 0; i < one->size(); ++i) {
                for (std::size_t j = 0; j < other.size(); ++j) {
                    if ((*one)[i] == other[j] && (&other != one || i < j)) shared.emplace_back(i, j);
                }
            }
            if (shared.empty()) break;
            const auto [i, j] = pick(shared, c);
            if (&other == one) {
                IdRing a(one->begin() + static_cast<std::ptrdiff_t>(i), one->begin() + static_cast<std::ptrdiff_t>(j));
                IdRing b = rotated_to(*one, j);
                b.resize(one->size() - (j - i));
                story += "split cycle " + list_text(*one) + " at vertex " + std::to_string((*one)[i]) + "\n";
                *one = std::move(a);
                cycles.push_back(std::move(b));
            } else {
                IdRing joined = rotated_to(*one, i);
                const IdRing tail = rotated_to(other, j);
                joined.insert(joined.end(), tail.begin(), tail.end());
                story += "joined cycles " + list_text(*one) + " and " + list_text(other) + "\n";
                *one = std::move(joined);
                cycles.erase(cycles.begin() + (&other - cycles.data()));
            }
            return;
        }
        case 5: {
            // A step along no edge, or a cycle of another length: wrong
            // (the oracle says when it happens to be another reference
            // cycle's rotation).
            const std::size_t i = c.below(one->size() + 1);
            const Index v = f.any_id(c);
            story += "inserted vertex " + std::to_string(v) + " into cycle " + list_text(*one) + "\n";
            one->insert(one->begin() + static_cast<std::ptrdiff_t>(i), v);
            return;
        }
        case 6: {
            // As case 5.
            const std::size_t i = c.below(one->size());
            story += "dropped a vertex from cycle " + list_text(*one) + "\n";
            one->erase(one->begin() + static_cast<std::ptrdiff_t>(i));
            if (one->empty()) one->push_back(f.any_id(c));  // an empty cycle could not be read by detection first
            return;
        }
        case 7: {
            if (cycles.size() < 2) break;
            IdRing& other = cycles[c.below(cycles.size())];
            if (&other == one) break;
            // Wrong, but for two equal ids exchanged.
            story += "exchanged vertices between two cycles\n";
            std::swap((*one)[c.below(one->size())], other[c.below(other.size())]);
            return;
        }
        default: break;
    }
    // A boundary cycle has two vertices at least: always wrong.
    story += "added a cycle of one vertex\n";
    cycles.push_back({f.any_id(c)});
}

// A field or record of the dump changed. Mostly broken invariants, for
// validate() to find; judge_dump (and the points and edges) decides. Moves
// that keep the DCEL valid are the oracle's to recognise: vertex_out set
// to another half-edge out of the same vertex, a next exchanged with
// itself.
void corrupt_dump(DcelDump& d, Choices& c, std::string& story) {
    const bool halves = !d.half_edges.empty();
    const std::size_t what = c.below(12);
    HalfEdgeRecord* r = halves ? &d.half_edges[c.below(d.half_edges.size())] : nullptr;
    switch (what) {
        case 0:
            if (!r) break;
            r->next = any_half_edge(d, c);
            story += "set a next\n";
            return;
        case 1: {
            // Rewired: next of a and b exchanged, prev kept the inverse.
            if (!r) break;
            HalfEdgeRecord& b = d.half_edges[c.below(d.half_edges.size())];
            std::swap(r->next, b.next);
            d.half_edges[r->next.index()].prev = HalfEdgeId(static_cast<Index>(r - d.half_edges.data()));
            d.half_edges[b.next.index()].prev = HalfEdgeId(static_cast<Index>(&b - d.half_edges.data()));
            story += "exchanged two nexts\n";
            return;
        }
        case 2:
            if (!r) break;
            r->twin = any_half_edge(d, c);
            story += "set a twin\n";
            return;
        case 3:
            if (!r) break;
            r->face = any_face(d, c);
            story += "set a face\n";
            return;
        case 4:
            if (!r) break;
            r->origin = VertexId(static_cast<Index>(c.below(d.vertices.size() + 1)));
            story += "set an origin\n";
            return;
        case 5: {
            FaceDump& face = d.faces[c.below(d.faces.size())];
            face.outer = c.one_in(4) ? HalfEdgeId() : any_half_edge(d, c);
            story += "set an outer\n";
            return;
        }
        case 6: {
            FaceDump& face = d.faces[c.below(d.faces.size())];
            if (!face.inner.empty() && c.one_in(2)) {
                const std::size_t i = c.below(face.inner.size());
                FaceDump& to = d.faces[c.below(d.faces.size())];
                to.inner.push_back(face.inner[i]);
                face.inner.erase(face.inner.begin() + static_cast<std::ptrdiff_t>(i));
                story += "moved an inner\n";
            } else {
                face.inner.push_back(any_half_edge(d, c));
                story += "added an inner\n";
            }
            return;
        }
        case 7: {
            FaceDump& face = d.faces[c.below(d.faces.size())];
            if (!face.isolated.empty() && c.one_in(2)) {
                const std::size_t i = c.below(face.isolated.size());
                FaceDump& to = d.faces[c.below(d.faces.size())];
                to.isolated.push_back(face.isolated[i]);
                face.isolated.erase(face.isolated.begin() + static_cast<std::ptrdiff_t>(i));
                story += "moved an isolated vertex\n";
            } else {
                face.isolated.push_back(VertexId(static_cast<Index>(c.below(d.vertices.size() + 1))));
                story += "added an isolated vertex\n";
            }
            return;
        }
        case 8:
            if (d.vertex_out.empty()) break;
            if (c.one_in(4)) {
                // One entry per vertex, or none given at all: wrong, but for
                // one vertex's entry dropped (then none is given).
                if (c.one_in(2)) {
                    d.vertex_out.pop_back();
                } else {
                    d.vertex_out.push_back(any_half_edge(d, c));
                }
                story += "vertex_out of the wrong length\n";
                return;
            }
            d.vertex_out[c.below(d.vertex_out.size())] = c.one_in(3) ? HalfEdgeId() : any_half_edge(d, c);
            story += "set a vertex_out\n";
            return;
        case 9: {
            // Wrong, but for x + 1 == x (|x| >= 2^53).
            if (d.vertices.empty()) break;
            Point& p = d.vertices[c.below(d.vertices.size())];
            p.x = c.one_in(2) ? p.x + 1 : std::nextafter(p.x, 1e300);
            story += "moved a vertex\n";
            return;
        }
        case 10:
            // A face more or fewer than the reference: always wrong.
            if (c.one_in(2)) {
                d.faces.push_back({any_half_edge(d, c), {}, {}});
                story += "added a face record\n";
            } else {
                d.faces.pop_back();
                story += "dropped a face record\n";
            }
            return;
        default:
            if (!r) break;
            r->prev = any_half_edge(d, c);
            story += "set a prev\n";
            return;
    }
    story += "dropped the last face record\n";
    d.faces.pop_back();
}

}  // namespace dcel::test_support::spell
