#include "oracles/answer_meaning.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>

#include "oracles/dump_judge.hpp"
#include "oracles/exact.hpp"
#include "oracles/shapes.hpp"

namespace dcel::oracle {
namespace {

std::string ring_text(const IdRing& r) {
    std::string s = "[";
    for (std::size_t i = 0; i < r.size(); ++i) s += (i == 0 ? "" : ", ") + std::to_string(r[i]);
    return s + "]";
}

std::string meaning_text(const std::vector<long>& w) {
    std::string s = "{";
    bool first = true;
    for (std::size_t f = 0; f < w.size(); ++f) {
        if (w[f] == 0) continue;
        s += (first ? "f" : ", f") + std::to_string(f) + ": " + std::to_string(w[f]);
        first = false;
    }
    return s + "}";
}

}  // namespace

AnswerJudge::AnswerJudge(const PlanarGraph& g) : g_(g), h_(half_edges_of(g)), reference_(reference_dcel(h_)) {
    const auto halves = static_cast<Index>(h_.origin.size());
    for (Index h = 0; h < halves; ++h) by_ends_.emplace(std::pair{h_.origin[h], h_.origin[h_.twin[h]]}, h);
    left_.resize(halves);
    for (Index h = 0; h < halves; ++h) left_[h] = reference_.face_of_cycle[reference_.cycle_of[h]];
    // The unbounded face's hole cycles are clockwise and carry face 0.
    dual_.assign(face_count(), {});
    for (Index k = 0; k < halves / 2; ++k) {
        const Index a = left_[2 * k], b = left_[2 * k + 1];
        dual_[a].emplace_back(k, b);
        dual_[b].emplace_back(k, a);
    }
    for (Index f = 1; f < face_count(); ++f) {
        std::vector<long> one(face_count(), 0);
        one[f] = 1;
        polygon_meanings_.push_back(std::move(one));
        ring_meanings_.push_back(filled(f));
    }
    std::sort(polygon_meanings_.begin(), polygon_meanings_.end());
    std::sort(ring_meanings_.begin(), ring_meanings_.end());
    for (const std::vector<Index>& cycle : reference_.cycles) {
        IdRing vs;
        for (const Index h : cycle) vs.push_back(h_.origin[h]);
        cycles_.push_back(canonical(vs));
    }
    std::sort(cycles_.begin(), cycles_.end());
}

Index AnswerJudge::half_edge(Index u, Index v) const {
    const auto it = by_ends_.find({u, v});
    return it == by_ends_.end() ? kNoIndex : it->second;
}

int AnswerJudge::area_sign(const IdRing& ring) const {
    std::vector<Point> points;
    points.reserve(ring.size());
    for (const Index v : ring) points.push_back(g_.vertices[v]);
    return sign_of(twice_area(points));
}

// Breadth first from the unbounded face; crossing edge k from the face on
// the right of 2k to the one on its left adds chain[k]. An edge with one
// face on both sides must carry 0, and every other edge met twice must
// agree: a sum of closed walks is a cycle, so anything else is a bug here.
std::vector<long> AnswerJudge::winding(const std::vector<long>& chain) const {
    std::vector<long> w(face_count(), 0);
    std::vector<char> known(face_count(), 0);
    std::deque<Index> queue{0};
    known[0] = 1;
    while (!queue.empty()) {
        const Index f = queue.front();
        queue.pop_front();
        for (const auto& [k, g] : dual_[f]) {
            // Across k from f to g: + chain[k] when g is on the left of 2k.
            const long step = (left_[2 * k] == g ? chain[k] : 0) - (left_[2 * k] == f ? chain[k] : 0);
            if (known[g] == 0) {
                known[g] = 1;
                w[g] = w[f] + step;
                queue.push_back(g);
            } else if (w[g] != w[f] + step) {
                throw std::logic_error("answer_meaning: a sum of closed walks that is no cycle");
            }
        }
    }
    return w;
}

// The faces f's outer boundary encloses, f included: those the unbounded
// face cannot reach across edges that do not have f on exactly one side.
std::vector<long> AnswerJudge::filled(Index f) const {
    std::vector<long> in(face_count(), 1);
    std::deque<Index> queue{0};
    in[0] = 0;
    while (!queue.empty()) {
        const Index a = queue.front();
        queue.pop_front();
        for (const auto& [k, b] : dual_[a]) {
            if ((left_[2 * k] == f) != (left_[2 * k + 1] == f) || in[b] == 0) continue;
            in[b] = 0;
            queue.push_back(b);
        }
    }
    return in;
}

AnswerVerdict AnswerJudge::faces(const std::vector<IdRing>& cycles) const {
    std::vector<IdRing> given;
    given.reserve(cycles.size());
    for (const IdRing& c : cycles) given.push_back(canonical(c));
    std::sort(given.begin(), given.end());
    if (given == cycles_) return {};
    std::vector<IdRing> extra, missing;
    std::set_difference(given.begin(), given.end(), cycles_.begin(), cycles_.end(), std::back_inserter(extra));
    std::set_difference(cycles_.begin(), cycles_.end(), given.begin(), given.end(), std::back_inserter(missing));
    return {false, "cycles not in the reference: " + std::to_string(extra.size()) +
                       (extra.empty() ? "" : " (" + ring_text(extra.front()) + ")") + "; reference cycles missing: " +
                       std::to_string(missing.size()) + (missing.empty() ? "" : " (" + ring_text(missing.front()) + ")")};
}

AnswerVerdict AnswerJudge::regions(const std::vector<IdPolygon>& polygons, RegionKind kind, bool oriented) const {
    const std::size_t vertices = g_.vertices.size();
    std::vector<std::vector<long>> meanings;
    for (std::size_t p = 0; p < polygons.size(); ++p) {
        std::vector<long> chain(h_.origin.size() / 2, 0);
        for (std::size_t r = 0; r < polygons[p].size(); ++r) {
            const IdRing& ring = polygons[p][r];
            const std::string where = "polygon " + std::to_string(p) + " ring " + std::to_string(r) + " " + ring_text(ring);
            for (const Index v : ring) {
                if (v >= vertices) return {false, where + " names no vertex"};
            }
            // A ring of one point (or none) walks nothing.
            if (ring.size() < 2) continue;
            std::vector<Index> walk;
            for (std::size_t i = 0; i < ring.size(); ++i) {
                const Index h = half_edge(ring[i], ring[(i + 1) % ring.size()]);
                if (h == kNoIndex) return {false, where + " steps along no edge"};
                walk.push_back(h);
            }
            const bool shell = kind == RegionKind::Rings || r == 0;
            const int sign = area_sign(ring);
            const bool backwards = sign != 0 && (sign > 0) != shell;
            if (backwards && oriented) return {false, where + " runs against its role's direction"};
            for (const Index h : walk) chain[h / 2] += ((h % 2 == 0) != backwards) ? 1 : -1;
        }
        meanings.push_back(winding(chain));
    }
    std::sort(meanings.begin(), meanings.end());
    const auto& want = kind == RegionKind::Polygons ? polygon_meanings_ : ring_meanings_;
    if (meanings == want) return {};
    std::vector<std::vector<long>> extra;
    std::set_difference(meanings.begin(), meanings.end(), want.begin(), want.end(), std::back_inserter(extra));
    return {false, std::to_string(meanings.size()) + " polygons for " + std::to_string(want.size()) + " bounded faces" +
                       (extra.empty() ? "" : "; one means " + meaning_text(extra.front()))};
}

AnswerVerdict AnswerJudge::dump(const DcelDump& d) const {
    if (d.vertices.size() != g_.vertices.size()) return {false, "the wrong number of vertices"};
    for (std::size_t v = 0; v < d.vertices.size(); ++v) {
        const Point p = g_.vertices[v];
        if (!(d.vertices[v].x == p.x && d.vertices[v].y == p.y)) return {false, "v" + std::to_string(v) + " moved"};
    }
    // The edges (one per twin pair) first: cheap, and judge_dump's brute
    // force then only ever sees the graph's own edges.
    const std::size_t n = d.half_edges.size();
    std::vector<std::pair<Index, Index>> given, want;
    for (std::size_t h = 0; h < n; ++h) {
        const Index t = d.half_edges[h].twin.index();
        if (t >= n || d.half_edges[t].twin.index() != h || t == h) return {false, "twin is no involution"};
        if (h > t) continue;
        const Index a = d.half_edges[h].origin.index(), b = d.half_edges[t].origin.index();
        given.emplace_back(std::min(a, b), std::max(a, b));
    }
    for (const GraphEdge& e : g_.edges)
        want.emplace_back(std::min(e.u.index(), e.v.index()), std::max(e.u.index(), e.v.index()));
    std::sort(given.begin(), given.end());
    std::sort(want.begin(), want.end());
    if (given != want) return {false, "the dump's edges are not the graph's"};
    const Judgement j = judge_dump(d);
    if (!j.valid) return {false, "the dump judge: " + j.reason};
    return {};
}

}  // namespace dcel::oracle
