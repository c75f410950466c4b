#include "oracles/reference_dcel.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "oracles/nested_rings.hpp"
#include "oracles/union_find.hpp"

namespace dcel::oracle {
namespace {

// next(e): the half-edge just clockwise of twin(e) around twin(e)'s origin.
std::vector<Index> next_from_rotations(const HalfEdgeGraph& h, const Rotations& r) {
    std::vector<Index> next(h.origin.size());
    for (Index e = 0; e < next.size(); ++e) {
        const Index t = h.twin[e];
        const std::vector<Index>& ring = r.ring[h.origin[t]];
        next[e] = ring[(r.position[t] + ring.size() - 1) % ring.size()];
    }
    return next;
}

std::vector<Point> cycle_points(const HalfEdgeGraph& h, const std::vector<Index>& cycle) {
    std::vector<Point> ring;
    ring.reserve(cycle.size());
    for (const Index e : cycle) ring.push_back(h.points[h.origin[e]]);
    return ring;
}

// The orbits of next, each from its smallest half-edge, with their areas.
void walk_cycles(const HalfEdgeGraph& h, ReferenceDcel& r) {
    r.cycle_of.assign(r.next.size(), kNoIndex);
    for (Index e = 0; e < r.next.size(); ++e) {
        if (r.cycle_of[e] != kNoIndex) continue;
        const auto c = static_cast<Index>(r.cycles.size());
        std::vector<Index>& cycle = r.cycles.emplace_back();
        for (Index x = e; r.cycle_of[x] == kNoIndex; x = r.next[x]) {
            r.cycle_of[x] = c;
            cycle.push_back(x);
        }
        r.twice_area.push_back(twice_area(cycle_points(h, cycle)));
    }
}

// Face 0 is unbounded; every counterclockwise cycle bounds a face of its own.
void number_faces(ReferenceDcel& r) {
    r.face_of_cycle.assign(r.cycles.size(), kNoIndex);
    r.outer_cycle.assign(1, kNoIndex);
    for (Index c = 0; c < r.cycles.size(); ++c) {
        if (r.twice_area[c] > 0) {
            r.face_of_cycle[c] = static_cast<Index>(r.outer_cycle.size());
            r.outer_cycle.push_back(c);
        }
    }
    r.inner.assign(r.outer_cycle.size(), {});
    r.isolated.assign(r.outer_cycle.size(), {});
}

// Each component's outer boundary (its one cycle that is not
// counterclockwise) and each isolated vertex, into the face around it.
void place_components(const HalfEdgeGraph& h, ReferenceDcel& r) {
    UnionFind uf(h.points.size());
    for (Index e = 0; e < h.origin.size(); ++e) uf.unite(h.origin[e], h.origin[h.twin[e]]);
    std::vector<Index> component(h.points.size());
    for (Index v = 0; v < component.size(); ++v) component[v] = uf.find(v);
    // The face around a point of one component: the innermost
    // counterclockwise cycle of another component around it, else face 0.
    NestedRings outer_cycles;
    for (Index f = 1; f < r.outer_cycle.size(); ++f) {
        const std::vector<Index>& cycle = r.cycles[r.outer_cycle[f]];
        outer_cycles.add(cycle_points(h, cycle), f, component[h.origin[cycle.front()]], r.twice_area[r.outer_cycle[f]]);
    }
    auto face_around = [&](Index v) {
        const Index f = outer_cycles.innermost_around(h.points[v], component[v]);
        return f == kNoIndex ? 0 : f;
    };

    std::vector<Index> outer_boundaries(h.points.size(), 0);  // per component
    for (Index c = 0; c < r.cycles.size(); ++c) {
        if (r.twice_area[c] > 0) continue;
        const Index v = h.origin[r.cycles[c].front()];
        ++outer_boundaries[component[v]];
        r.face_of_cycle[c] = face_around(v);
        r.inner[r.face_of_cycle[c]].push_back(c);
    }
    std::vector<char> has_edge(h.points.size(), 0);
    for (const Index v : h.origin) has_edge[v] = 1;
    r.face_of_vertex.assign(h.points.size(), kNoIndex);
    for (Index v = 0; v < h.points.size(); ++v) {
        if (has_edge[v] == 0) {
            r.face_of_vertex[v] = face_around(v);
            r.isolated[r.face_of_vertex[v]].push_back(v);
        } else if (component[v] == v && outer_boundaries[v] != 1) {
            // Euler: a connected plane graph has exactly one unbounded walk.
            throw std::logic_error("reference DCEL: the component of v" + std::to_string(v) + " has " +
                                   std::to_string(outer_boundaries[v]) + " outer boundaries (not a plane graph)");
        }
    }
}

}  // namespace

HalfEdgeGraph half_edges_of(const PlanarGraph& g) {
    HalfEdgeGraph h;
    h.points = g.vertices;
    for (Index k = 0; k < g.edges.size(); ++k) {
        h.origin.push_back(g.edges[k].u.index());
        h.origin.push_back(g.edges[k].v.index());
        h.twin.push_back(2 * k + 1);
        h.twin.push_back(2 * k);
    }
    return h;
}

ReferenceDcel reference_dcel(const HalfEdgeGraph& h) { return reference_dcel(h, rotation_system(h)); }

ReferenceDcel reference_dcel(const HalfEdgeGraph& h, const Rotations& rotations) {
    ReferenceDcel r;
    r.next = next_from_rotations(h, rotations);
    walk_cycles(h, r);
    number_faces(r);
    place_components(h, r);
    return r;
}

ReferenceDcel reference_dcel(const PlanarGraph& g) { return reference_dcel(half_edges_of(g)); }

std::vector<FaceShape> face_shapes(const HalfEdgeGraph& h, const ReferenceDcel& r) {
    auto vertices = [&](Index c) {
        Cycle out;
        for (const Index e : r.cycles[c]) out.push_back(h.origin[e]);
        return out;
    };
    std::vector<FaceShape> faces(r.outer_cycle.size());
    for (Index f = 0; f < faces.size(); ++f) {
        if (r.outer_cycle[f] != kNoIndex) faces[f].outer = vertices(r.outer_cycle[f]);
        for (const Index c : r.inner[f]) faces[f].holes.push_back(vertices(c));
        faces[f].isolated = r.isolated[f];
    }
    return sorted_shapes(std::move(faces));
}

std::vector<FaceShape> reference_faces(const PlanarGraph& g) {
    const HalfEdgeGraph h = half_edges_of(g);
    return face_shapes(h, reference_dcel(h));
}

}  // namespace dcel::oracle
