// Test support: is a DCEL exactly the one build() makes from its own graph?
//
// to_graph() keeps vertex and edge ids, so half-edge ids agree too, and
// origin, next and prev must match exactly (the next rule is geometry). Face
// ids may differ: the faces must correspond one to one through the
// half-edges (face 0 to face 0), with the same outer cycle, the same hole
// cycles and the same isolated vertices. Representatives (which half-edge a
// record names, out(v)) may differ. This is the oracle for every edit: it
// shares no code with the editor.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/dcel.hpp"
#include "dcel/dump.hpp"
#include "dcel/error.hpp"
#include "dcel/to_graph.hpp"
#include "dcel/validate.hpp"

namespace dcel::test_support {

// The smallest half-edge of the cycle through each half-edge.
inline std::vector<Index> cycle_ids(const Dcel& d) {
    std::vector<Index> id(d.num_half_edges(), kNoIndex);
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        if (id[h] != kNoIndex) continue;
        for (const HalfEdgeId x : d.cycle(HalfEdgeId(h))) id[x.index()] = h;
    }
    return id;
}

// How d differs from r, a DCEL that build() made from d's graph (same vertex
// and edge ids); empty when they are the same up to face numbering.
inline std::optional<std::string> difference_between(const Dcel& d, const Dcel& r) {
    if (d.num_vertices() != r.num_vertices() || d.num_half_edges() != r.num_half_edges() || d.num_faces() != r.num_faces()) {
        return "sizes differ: " + std::to_string(d.num_faces()) + " faces, rebuilt " + std::to_string(r.num_faces());
    }
    for (Index i = 0; i < d.num_half_edges(); ++i) {
        const HalfEdgeId h(i);
        if (d.origin(h) != r.origin(h) || d.next(h) != r.next(h) || d.prev(h) != r.prev(h)) {
            return "half-edge " + h.str() + ": next " + d.next(h).str() + " prev " + d.prev(h).str() + ", rebuilt next " +
                   r.next(h).str() + " prev " + r.prev(h).str();
        }
    }
    for (Index v = 0; v < d.num_vertices(); ++v) {
        if (d.out(VertexId(v)).is_null() != r.out(VertexId(v)).is_null())
            return "out(v" + std::to_string(v) + ") null-ness differs";
    }
    // Faces, matched through the half-edges.
    std::vector<FaceId> to_rebuilt(d.num_faces());
    std::vector<char> hit(r.num_faces(), 0);
    to_rebuilt[0] = Dcel::kUnboundedFace;
    hit[0] = 1;
    for (Index i = 0; i < d.num_half_edges(); ++i) {
        const HalfEdgeId h(i);
        FaceId& m = to_rebuilt[d.face(h).index()];
        if (m.is_null()) {
            if (hit[r.face(h).index()] != 0) return "two faces map to rebuilt " + r.face(h).str();
            m = r.face(h);
            hit[m.index()] = 1;
        } else if (m != r.face(h)) {
            return "face " + d.face(h).str() + " of " + h.str() + " matches both " + m.str() + " and " + r.face(h).str();
        }
    }
    const std::vector<Index> cd = cycle_ids(d);
    const std::vector<Index> cr = cycle_ids(r);
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        const FaceId g = to_rebuilt[i];
        if (g.is_null()) return f.str() + " has no half-edges and is not the unbounded face";
        if (d.outer(f).is_null() != r.outer(g).is_null() ||
            (!d.outer(f).is_null() && cd[d.outer(f).index()] != cr[r.outer(g).index()])) {
            return "the outer cycle of " + f.str() + " differs from that of rebuilt " + g.str();
        }
        std::vector<Index> holes_d;
        std::vector<Index> holes_r;
        for (const HalfEdgeId h : d.inner(f)) holes_d.push_back(cd[h.index()]);
        for (const HalfEdgeId h : r.inner(g)) holes_r.push_back(cr[h.index()]);
        std::sort(holes_d.begin(), holes_d.end());
        std::sort(holes_r.begin(), holes_r.end());
        if (holes_d != holes_r) return "the holes of " + f.str() + " differ from those of rebuilt " + g.str();
        std::vector<VertexId> iso_d = d.isolated(f);
        std::vector<VertexId> iso_r = r.isolated(g);
        std::sort(iso_d.begin(), iso_d.end());
        std::sort(iso_r.begin(), iso_r.end());
        if (iso_d != iso_r) return "the isolated vertices of " + f.str() + " differ from those of rebuilt " + g.str();
    }
    return std::nullopt;
}

inline std::optional<std::string> difference_from_rebuild(const Dcel& d) {
    Dcel r;
    try {
        r = build(to_graph(d));
    } catch (const InvalidInput& e) {
        return std::string("build() refuses the graph: ") + e.what();
    }
    return difference_between(d, r);
}

// Every array equal: what a refused edit must leave behind.
inline bool same_dump(const DcelDump& a, const DcelDump& b) {
    return a.vertices == b.vertices && a.vertex_out == b.vertex_out && a.half_edges == b.half_edges && a.faces == b.faces;
}

// Everything an edited DCEL must satisfy: validate() accepts it, and it is
// the rebuild of its own graph. Empty when sound.
inline std::optional<std::string> soundness_problem(const Dcel& d) {
    if (auto v = validate(d)) return std::string("validate: [") + to_string(v->invariant) + "] " + v->message;
    if (!d.is_unbounded(Dcel::kUnboundedFace)) return std::string("face 0 is not the unbounded face");
    return difference_from_rebuild(d);
}

}  // namespace dcel::test_support
