// An answer as read (check::Answer) put back into its plain spelling, by the
// reading rules docs/checking.md states and written here from them alone,
// for the independent oracle (oracles/answer_meaning.hpp) to judge: ids from
// 0 (with --one-based a 0 names no vertex), a last vertex equal to the
// first dropped once, every cycle and ring reversed and a dump turned
// around with --face-on right, coordinates matched to the graph's vertices
// as doubles (so -0.0 is 0.0). Lets the answer harness judge every answer
// it reads twice, by the checker and by the oracle.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "dcel/check/answer.hpp"
#include "oracles/answer_meaning.hpp"

namespace dcel::fuzz {

namespace answer_plain_detail {

// The plain walk of one cycle or ring; an id >= V names no vertex.
inline oracle::IdRing plain_walk(std::vector<Index> vs, bool one_based, bool reverse, Index vertices) {
    if (one_based) {
        for (Index& v : vs) v = v == 0 ? vertices : v - 1;
    }
    if (vs.size() >= 2 && vs.front() == vs.back()) vs.pop_back();
    if (reverse) std::reverse(vs.begin(), vs.end());
    for (Index& v : vs) v = std::min(v, vertices);
    return vs;
}

// A dump with faces on the right, or counted from 1, as one with faces on
// the left counted from 0: each half-edge starts where its twin does and
// next and prev swap (where the twin is in range: elsewhere the dump is
// broken either way), vertex_out names the twin; a 0 in a 1-based dump is
// null.
inline DcelDump plain_dump(DcelDump d, const check::Conventions& c) {
    if (c.one_based) {
        auto down = [](auto& id) {
            using Id = std::decay_t<decltype(id)>;
            if (!id.is_null()) id = id.index() == 0 ? Id() : Id(id.index() - 1);
        };
        for (HalfEdgeId& h : d.vertex_out) down(h);
        for (HalfEdgeRecord& r : d.half_edges) {
            down(r.origin);
            down(r.twin);
            down(r.next);
            down(r.prev);
            down(r.face);
        }
        for (FaceDump& f : d.faces) {
            down(f.outer);
            for (HalfEdgeId& h : f.inner) down(h);
            for (VertexId& v : f.isolated) down(v);
        }
    }
    if (c.face_on_right) {
        const std::size_t n = d.half_edges.size();
        std::vector<HalfEdgeRecord> turned = d.half_edges;
        for (std::size_t h = 0; h < n; ++h) {
            const Index t = d.half_edges[h].twin.index();
            if (t < n) turned[h].origin = d.half_edges[t].origin;
            std::swap(turned[h].next, turned[h].prev);
        }
        for (HalfEdgeId& h : d.vertex_out) {
            if (h.index() < n) h = d.half_edges[h.index()].twin;
        }
        d.half_edges = std::move(turned);
    }
    return d;
}

}  // namespace answer_plain_detail

inline oracle::AnswerVerdict oracle_verdict(const oracle::AnswerJudge& judge, const check::Answer& a,
                                            const check::Conventions& c) {
    using answer_plain_detail::plain_walk;
    const PlanarGraph& g = judge.graph();
    const auto vertices = static_cast<Index>(g.vertices.size());
    switch (a.kind) {
        case check::AnswerKind::Faces: {
            std::vector<oracle::IdRing> cycles;
            for (std::size_t i = 0; i < a.cycles.size(); ++i) {
                const std::span<const Index> cycle = a.cycles[i];
                cycles.push_back(plain_walk({cycle.begin(), cycle.end()}, c.one_based, c.face_on_right, vertices));
            }
            return judge.faces(cycles);
        }
        case check::AnswerKind::Dump: return judge.dump(answer_plain_detail::plain_dump(a.dump, c));
        case check::AnswerKind::Polygons:
        case check::AnswerKind::Rings: break;
        // Read only when asked for by name, which the harness's kind byte
        // never does (it covers what detection can find): no oracle yet.
        case check::AnswerKind::EvenOdd: std::abort();
    }
    const check::RegionAnswer& r = a.regions;
    auto vertex_at = [&](Point p) {
        for (Index v = 0; v < vertices; ++v) {
            if (g.vertices[v].x == p.x && g.vertices[v].y == p.y) return v;
        }
        return vertices;
    };
    std::vector<oracle::IdPolygon> polygons;
    for (std::size_t p = 0; p < r.polygon_count(); ++p) {
        oracle::IdPolygon& polygon = polygons.emplace_back();
        for (std::size_t k = r.polygon_begin[p]; k < r.polygon_begin[p + 1]; ++k) {
            std::vector<Index> ids;
            for (std::size_t i = r.ring_begin[k]; i < r.ring_begin[k + 1]; ++i) {
                ids.push_back(r.by_points ? vertex_at(r.points[i]) : r.ids[i]);
            }
            polygon.push_back(plain_walk(std::move(ids), c.one_based && !r.by_points, c.face_on_right, vertices));
        }
    }
    const bool rings = a.kind == check::AnswerKind::Rings;
    return judge.regions(polygons, rings ? oracle::RegionKind::Rings : oracle::RegionKind::Polygons,
                         !rings && !c.unoriented);
}

}  // namespace dcel::fuzz
