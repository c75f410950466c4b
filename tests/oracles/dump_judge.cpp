#include "oracles/dump_judge.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "oracles/brute_force.hpp"
#include "oracles/reference_dcel.hpp"

namespace dcel::oracle {
namespace {

using Verdict = std::optional<Judgement>;  // a defect, or nothing

Judgement defect(std::string reason) { return {false, std::move(reason)}; }

std::string h_(Index h) { return "h" + std::to_string(h); }

// Every id in range (null only where a dump may hold it), twin a fixed-point
// free involution.
Verdict check_ids(const DcelDump& d) {
    const std::size_t nv = d.vertices.size();
    const std::size_t nh = d.half_edges.size();
    const std::size_t nf = d.faces.size();
    if (nf == 0) return defect("no faces");
    if (!d.vertex_out.empty() && d.vertex_out.size() != nv) return defect("vertex_out has the wrong size");
    for (const HalfEdgeId h : d.vertex_out) {
        if (!h.is_null() && h.index() >= nh) return defect("vertex_out names " + h.str());
    }
    for (Index h = 0; h < nh; ++h) {
        const HalfEdgeRecord& r = d.half_edges[h];
        if (r.origin.index() >= nv || r.twin.index() >= nh || r.next.index() >= nh || r.prev.index() >= nh ||
            r.face.index() >= nf) {
            return defect("a field of " + h_(h) + " is out of range");
        }
    }
    for (const FaceDump& f : d.faces) {
        if (!f.outer.is_null() && f.outer.index() >= nh) return defect("a face's outer is out of range");
        for (const HalfEdgeId h : f.inner) {
            if (h.index() >= nh) return defect("a face's inner is out of range");
        }
        for (const VertexId v : f.isolated) {
            if (v.index() >= nv) return defect("a face's isolated vertex is out of range");
        }
    }
    for (Index h = 0; h < nh; ++h) {
        const Index t = d.half_edges[h].twin.index();
        if (t == h || d.half_edges[t].twin.index() != h) return defect("twin is not an involution at " + h_(h));
    }
    return std::nullopt;
}

// The dump's half-edges over its points, and the graph under them.
HalfEdgeGraph half_edges_of(const DcelDump& d) {
    HalfEdgeGraph h;
    h.points = d.vertices;
    for (const HalfEdgeRecord& r : d.half_edges) {
        h.origin.push_back(r.origin.index());
        h.twin.push_back(r.twin.index());
    }
    return h;
}

PlanarGraph graph_of(const HalfEdgeGraph& h) {
    PlanarGraph g;
    g.vertices = h.points;
    for (Index e = 0; e < h.origin.size(); ++e) {
        if (e < h.twin[e]) g.edges.push_back({VertexId(h.origin[e]), VertexId(h.origin[h.twin[e]])});
    }
    return g;
}

Verdict check_next_and_prev(const DcelDump& d, const ReferenceDcel& x) {
    for (Index h = 0; h < d.half_edges.size(); ++h) {
        if (d.half_edges[h].next.index() != x.next[h]) {
            return defect("next(" + h_(h) + ") = " + d.half_edges[h].next.str() + ", expected " + h_(x.next[h]));
        }
        if (d.half_edges[x.next[h]].prev.index() != h) return defect("prev(" + h_(x.next[h]) + ") is not " + h_(h));
    }
    return std::nullopt;
}

// The dump's face id of every reference face, through the half-edges' face
// fields (which must name one face per reference face and vice versa); the
// unbounded face of a graph without edges, which no half-edge names, takes
// the one face left.
std::variant<std::vector<Index>, Judgement> match_faces(const DcelDump& d, const ReferenceDcel& x) {
    const std::size_t nfaces = x.outer_cycle.size();
    if (d.faces.size() != nfaces)
        return defect(std::to_string(d.faces.size()) + " faces, expected " + std::to_string(nfaces));
    std::vector<Index> dump_face(nfaces, kNoIndex);
    std::vector<Index> expected_face(nfaces, kNoIndex);
    for (Index h = 0; h < d.half_edges.size(); ++h) {
        const Index e = x.face_of_cycle[x.cycle_of[h]];
        const Index f = d.half_edges[h].face.index();
        if (dump_face[e] == kNoIndex && expected_face[f] == kNoIndex) {
            dump_face[e] = f;
            expected_face[f] = e;
        }
        if (dump_face[e] != f || expected_face[f] != e) return defect("face(" + h_(h) + ") is not its face's id");
    }
    for (Index e = 0; e < nfaces; ++e) {
        if (dump_face[e] != kNoIndex) continue;
        const auto left = std::find(expected_face.begin(), expected_face.end(), kNoIndex);
        dump_face[e] = static_cast<Index>(left - expected_face.begin());
        *left = e;
    }
    return dump_face;
}

Verdict check_face_records(const DcelDump& d, const ReferenceDcel& x, const std::vector<Index>& dump_face) {
    for (Index e = 0; e < dump_face.size(); ++e) {
        const FaceDump& r = d.faces[dump_face[e]];
        const std::string name = "f" + std::to_string(dump_face[e]);
        if (x.outer_cycle[e] == kNoIndex) {
            if (!r.outer.is_null()) return defect(name + " is the unbounded face but has an outer cycle");
        } else if (r.outer.is_null() || x.cycle_of[r.outer.index()] != x.outer_cycle[e]) {
            return defect(name + "'s outer names the wrong cycle");
        }
        std::vector<Index> inner;
        for (const HalfEdgeId h : r.inner) inner.push_back(x.cycle_of[h.index()]);
        std::sort(inner.begin(), inner.end());
        if (inner != x.inner[e]) return defect(name + "'s inner cycles are wrong");
        std::vector<Index> isolated;
        for (const VertexId v : r.isolated) isolated.push_back(v.index());
        std::sort(isolated.begin(), isolated.end());
        if (isolated != x.isolated[e]) return defect(name + "'s isolated vertices are wrong");
    }
    return std::nullopt;
}

Verdict check_vertex_out(const DcelDump& d) {
    if (d.vertex_out.empty()) return std::nullopt;
    std::vector<char> has_out(d.vertices.size(), 0);
    for (const HalfEdgeRecord& r : d.half_edges) has_out[r.origin.index()] = 1;
    for (Index v = 0; v < d.vertices.size(); ++v) {
        const HalfEdgeId h = d.vertex_out[v];
        const bool ok = h.is_null() ? has_out[v] == 0 : d.half_edges[h.index()].origin == VertexId(v);
        if (!ok) return defect("vertex_out of v" + std::to_string(v) + " is wrong");
    }
    return std::nullopt;
}

}  // namespace

Judgement judge_dump(const DcelDump& d) {
    if (Verdict bad = check_ids(d)) return *bad;
    const HalfEdgeGraph h = half_edges_of(d);
    const Defects defects = find_defects(graph_of(h));
    if (!defects.empty()) return defect("the underlying graph has defects: " + describe(defects.kinds()));
    const ReferenceDcel x = reference_dcel(h);
    if (Verdict bad = check_next_and_prev(d, x)) return *bad;
    auto matched = match_faces(d, x);
    if (const Judgement* bad = std::get_if<Judgement>(&matched)) return *bad;
    if (Verdict bad = check_face_records(d, x, std::get<std::vector<Index>>(matched))) return *bad;
    if (Verdict bad = check_vertex_out(d)) return *bad;
    return {};
}

}  // namespace dcel::oracle
