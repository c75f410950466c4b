#include "dcel/check/answer_drawing.hpp"

#include <algorithm>
#include <span>

namespace dcel::check {
namespace {

constexpr std::size_t kMaxDrawnIds = 100000;  // a drawing of more says nothing; keep memory small

// A dump's next-cycles as vertex cycles, where its references allow a walk.
std::vector<std::vector<Index>> dump_cycles(const DcelDump& d) {
    std::vector<std::vector<Index>> out;
    const std::size_t n = d.half_edges.size();
    if (n > kMaxDrawnIds) return out;
    std::vector<char> seen(n, 0);
    for (std::size_t h = 0; h < n; ++h) {
        std::vector<Index> cycle;
        for (std::size_t x = h, steps = 0; x < n && seen[x] == 0 && steps < n; ++steps) {
            seen[x] = 1;
            if (d.half_edges[x].origin.is_null()) break;
            cycle.push_back(d.half_edges[x].origin.index());
            x = d.half_edges[x].next.index();
        }
        if (!cycle.empty()) out.push_back(std::move(cycle));
    }
    return out;
}

}  // namespace

std::vector<std::vector<std::vector<Index>>> drawn_regions(const Answer& a, const Dcel& reference, const Conventions& c) {
    std::vector<std::vector<std::vector<Index>>> out;
    const RegionAnswer& r = a.regions;
    if (a.kind != AnswerKind::Polygons && a.kind != AnswerKind::Rings && a.kind != AnswerKind::EvenOdd) {
        return out;
    }
    if (r.ids.size() + r.points.size() > kMaxDrawnIds) return out;
    auto vertex_at = [&](Point p) {
        for (Index v = 0; v < reference.num_vertices(); ++v) {
            if (reference.point(VertexId(v)) == p) return v;
        }
        return kNoIndex;
    };
    for (std::size_t p = 0; p < r.polygon_count(); ++p) {
        std::vector<std::vector<Index>> polygon;
        for (std::size_t k = r.polygon_begin[p]; k < r.polygon_begin[p + 1]; ++k) {
            std::vector<Index> ring;
            bool known = true;
            for (std::size_t i = r.ring_begin[k]; i < r.ring_begin[k + 1]; ++i) {
                Index v = r.by_points ? vertex_at(r.points[i]) : r.ids[i];
                if (!r.by_points && c.one_based) v = v == 0 ? kNoIndex : v - 1;
                known = known && v < reference.num_vertices();
                ring.push_back(v);
            }
            if (ring.size() >= 2 && ring.front() == ring.back()) ring.pop_back();
            if (known) polygon.push_back(std::move(ring));
        }
        if (!polygon.empty()) out.push_back(std::move(polygon));
    }
    return out;
}

std::vector<std::vector<Index>> drawn_cycles(const Answer& a, const Conventions& c) {
    std::vector<std::vector<Index>> out;
    if (a.kind == AnswerKind::Dump) return dump_cycles(a.dump);
    if (a.kind != AnswerKind::Faces || a.cycles.ids.size() > kMaxDrawnIds) return out;
    for (std::size_t i = 0; i < a.cycles.size(); ++i) {
        const std::span<const Index> given = a.cycles[i];
        std::vector<Index> vs(given.begin(), given.end());
        if (c.one_based) {
            for (Index& v : vs) v = v == 0 ? kNoIndex : v - 1;
        }
        if (vs.size() >= 2 && vs.front() == vs.back()) vs.pop_back();
        if (c.face_on_right && !vs.empty()) std::reverse(vs.begin() + 1, vs.end());
        out.push_back(std::move(vs));
    }
    return out;
}

}  // namespace dcel::check
