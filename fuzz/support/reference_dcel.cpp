#include "support/reference_dcel.hpp"

#include <algorithm>
#include <numeric>
#include <optional>

#include "support/brute_force.hpp"
#include "support/exact_points.hpp"
#include "support/fuzz_check.hpp"

namespace dcel::fuzz {
namespace {

Judgement defect(std::string reason) { return {false, std::move(reason)}; }

std::string h_(Index h) { return "h" + std::to_string(h); }

// Every id in range (null only where a dump may hold it), twin a fixed-point
// free involution.
std::optional<Judgement> check_ids(const DcelDump& d) {
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

// 0 for directions in [0, pi) (y > 0, or y == 0 and x > 0), 1 for [pi, 2 pi).
int half_plane(const ExactPoint& c, const ExactPoint& p) { return (p.y > c.y || (p.y == c.y && p.x > c.x)) ? 0 : 1; }

struct Expected {
    std::vector<Index> next;      // per half-edge
    std::vector<Index> cycle_of;  // per half-edge
    std::vector<std::vector<Index>> cycles;
    std::vector<Index> face_of_cycle;          // expected face id (0: unbounded)
    std::vector<Index> outer_cycle;            // per expected face; kNoIndex for the unbounded face
    std::vector<std::vector<Index>> inner;     // per expected face: cycle ids, sorted
    std::vector<std::vector<Index>> isolated;  // per expected face: vertex ids, sorted
};

Expected expected_structure(const DcelDump& d, const std::vector<ExactPoint>& pt) {
    const auto nv = static_cast<Index>(d.vertices.size());
    const auto nh = static_cast<Index>(d.half_edges.size());
    auto origin = [&](Index h) { return d.half_edges[h].origin.index(); };
    auto twin = [&](Index h) { return d.half_edges[h].twin.index(); };
    Expected x;

    // Rotation system: outgoing half-edges counterclockwise from east.
    std::vector<std::vector<Index>> ring(nv);
    for (Index h = 0; h < nh; ++h) ring[origin(h)].push_back(h);
    for (Index v = 0; v < nv; ++v) {
        const ExactPoint& c = pt[v];
        std::sort(ring[v].begin(), ring[v].end(), [&](Index a, Index b) {
            const ExactPoint& pa = pt[origin(twin(a))];
            const ExactPoint& pb = pt[origin(twin(b))];
            const int ha = half_plane(c, pa);
            const int hb = half_plane(c, pb);
            if (ha != hb) return ha < hb;
            return orientation(c, pa, pb) > 0;
        });
    }
    x.next.assign(nh, kNoIndex);
    for (Index h = 0; h < nh; ++h) {
        const std::vector<Index>& r = ring[origin(twin(h))];
        const auto k = static_cast<std::size_t>(std::find(r.begin(), r.end(), twin(h)) - r.begin());
        x.next[h] = r[(k + r.size() - 1) % r.size()];  // clockwise neighbour of twin(h)
    }

    // Cycles and their doubled signed areas.
    x.cycle_of.assign(nh, kNoIndex);
    std::vector<BigInt> area;
    for (Index h = 0; h < nh; ++h) {
        if (x.cycle_of[h] != kNoIndex) continue;
        const auto c = static_cast<Index>(x.cycles.size());
        x.cycles.emplace_back();
        BigInt a = 0;
        for (Index e = h; x.cycle_of[e] == kNoIndex; e = x.next[e]) {
            x.cycle_of[e] = c;
            x.cycles.back().push_back(e);
            const ExactPoint& p = pt[origin(e)];
            const ExactPoint& q = pt[origin(twin(e))];
            a += p.x * q.y - p.y * q.x;
        }
        area.push_back(a);
    }

    // Components (union-find over edges); each vertex's representative.
    std::vector<Index> parent(nv);
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](Index v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (Index h = 0; h < nh; ++h) parent[root(origin(h))] = root(origin(twin(h)));
    auto component_of_cycle = [&](Index c) { return root(origin(x.cycles[c].front())); };

    // Expected faces: 0 is unbounded, then one per counterclockwise cycle.
    x.face_of_cycle.assign(x.cycles.size(), kNoIndex);
    x.outer_cycle.push_back(kNoIndex);
    for (Index c = 0; c < x.cycles.size(); ++c) {
        if (area[c] > 0) {
            x.face_of_cycle[c] = static_cast<Index>(x.outer_cycle.size());
            x.outer_cycle.push_back(c);
        }
    }
    x.inner.resize(x.outer_cycle.size());
    x.isolated.resize(x.outer_cycle.size());

    // The face containing point p of component k: the smallest
    // counterclockwise cycle of another component that winds around p.
    auto winding = [&](Index c, const ExactPoint& p) {
        int w = 0;
        for (const Index e : x.cycles[c]) {
            const ExactPoint& a = pt[origin(e)];
            const ExactPoint& b = pt[origin(twin(e))];
            if (a.y <= p.y) {
                if (b.y > p.y && orientation(a, b, p) > 0) ++w;
            } else if (b.y <= p.y && orientation(a, b, p) < 0) {
                --w;
            }
        }
        return w;
    };
    auto container = [&](Index k, const ExactPoint& p) {
        Index best = 0;
        for (Index f = 1; f < x.outer_cycle.size(); ++f) {
            const Index c = x.outer_cycle[f];
            if (component_of_cycle(c) == k || winding(c, p) == 0) continue;
            if (best == 0 || area[c] < area[x.outer_cycle[best]]) best = f;
        }
        return best;
    };

    std::vector<Index> outer_boundaries(nv, 0);  // per component root: cycles with area <= 0
    for (Index c = 0; c < x.cycles.size(); ++c) {
        if (area[c] > 0) continue;
        const Index k = component_of_cycle(c);
        ++outer_boundaries[k];
        const Index f = container(k, pt[origin(x.cycles[c].front())]);
        x.face_of_cycle[c] = f;
        x.inner[f].push_back(c);
    }
    for (Index v = 0; v < nv; ++v) {
        if (ring[v].empty()) {
            x.isolated[container(root(v), pt[v])].push_back(v);
        } else {
            // Euler: a connected plane graph has exactly one unbounded walk.
            FUZZ_CHECK(root(v) != v || outer_boundaries[v] == 1,
                       "reference: component of v" << v << " has " << outer_boundaries[v] << " outer boundaries");
        }
    }
    return x;
}

}  // namespace

Judgement judge_dump(const DcelDump& d) {
    if (auto bad = check_ids(d)) return *bad;
    const auto nh = static_cast<Index>(d.half_edges.size());

    // The graph under the dump must be a planar straight-line graph.
    PlanarGraph g;
    g.vertices = d.vertices;
    for (Index h = 0; h < nh; ++h) {
        const Index t = d.half_edges[h].twin.index();
        if (h < t) g.edges.push_back({d.half_edges[h].origin, d.half_edges[t].origin});
    }
    const Defects defects = find_defects(g);
    if (defects.any()) return defect("the underlying graph has defects: " + describe(defects));

    const std::vector<ExactPoint> pt = exact_points(d.vertices);
    const Expected x = expected_structure(d, pt);

    for (Index h = 0; h < nh; ++h) {
        if (d.half_edges[h].next.index() != x.next[h]) {
            return defect("next(" + h_(h) + ") = " + d.half_edges[h].next.str() + ", expected " + h_(x.next[h]));
        }
        if (d.half_edges[x.next[h]].prev.index() != h) return defect("prev(" + h_(x.next[h]) + ") is not " + h_(h));
    }

    // Map expected faces to the dump's face ids through the face fields.
    const std::size_t nfaces = x.outer_cycle.size();
    if (d.faces.size() != nfaces) {
        return defect(std::to_string(d.faces.size()) + " faces, expected " + std::to_string(nfaces));
    }
    std::vector<Index> dump_face(nfaces, kNoIndex);
    std::vector<Index> expected_face(nfaces, kNoIndex);
    for (Index h = 0; h < nh; ++h) {
        const Index e = x.face_of_cycle[x.cycle_of[h]];
        const Index f = d.half_edges[h].face.index();
        if (dump_face[e] == kNoIndex && expected_face[f] == kNoIndex) {
            dump_face[e] = f;
            expected_face[f] = e;
        }
        if (dump_face[e] != f || expected_face[f] != e) return defect("face(" + h_(h) + ") is not its face's id");
    }
    for (Index e = 0; e < nfaces; ++e) {
        if (dump_face[e] != kNoIndex) continue;  // only the unbounded face of an edgeless graph
        for (Index f = 0; f < nfaces; ++f) {
            if (expected_face[f] == kNoIndex) {
                dump_face[e] = f;
                expected_face[f] = e;
                break;
            }
        }
    }

    for (Index e = 0; e < nfaces; ++e) {
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
        std::vector<Index> want_inner = x.inner[e];
        std::sort(want_inner.begin(), want_inner.end());
        if (inner != want_inner) return defect(name + "'s inner cycles are wrong");
        std::vector<Index> isolated;
        for (const VertexId v : r.isolated) isolated.push_back(v.index());
        std::sort(isolated.begin(), isolated.end());
        if (isolated != x.isolated[e]) return defect(name + "'s isolated vertices are wrong");
    }

    if (!d.vertex_out.empty()) {
        std::vector<char> has_out(d.vertices.size(), 0);
        for (const HalfEdgeRecord& r : d.half_edges) has_out[r.origin.index()] = 1;
        for (Index v = 0; v < d.vertices.size(); ++v) {
            const HalfEdgeId h = d.vertex_out[v];
            const bool ok = h.is_null() ? !has_out[v] : d.half_edges[h.index()].origin == VertexId(v);
            if (!ok) return defect("vertex_out of v" + std::to_string(v) + " is wrong");
        }
    }
    return {};
}

}  // namespace dcel::fuzz
