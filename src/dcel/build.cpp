#include "dcel/build.hpp"

#include <algorithm>
#include <numeric>

#include "dcel/geometry/predicates.hpp"
#include "dcel/input_checks.hpp"
#include "dcel/sweep.hpp"

namespace dcel {

// Friend of Dcel: fills its arrays. One member function per step, in order.
class DcelBuilder {
public:
    DcelBuilder(const PlanarGraph& g, const BuildOptions& options) : g_(g), options_(options) {}

    Dcel run() {
        check_elements(g_);
        lex_order_ = sort_vertices_checked(g_);
        rings_ = sort_rings_checked(g_);
        link_next();
        find_cycles();
        find_components();
        place_faces();
        fill_vertices();
        d_.points_ = g_.vertices;
        return std::move(d_);
    }

private:
    [[nodiscard]] Index num_vertices() const { return static_cast<Index>(g_.vertices.size()); }
    [[nodiscard]] Index num_half_edges() const { return static_cast<Index>(2 * g_.edges.size()); }
    [[nodiscard]] Point point(VertexId v) const { return g_.vertices[v.index()]; }
    [[nodiscard]] VertexId origin(HalfEdgeId h) const { return graph_origin(g_, h); }
    [[nodiscard]] VertexId target(HalfEdgeId h) const { return graph_target(g_, h); }

    // next(u->v) = the half-edge leaving v just clockwise of v->u.
    void link_next() {
        std::vector<Index> ring_position(num_half_edges());
        for (Index v = 0; v < num_vertices(); ++v) {
            for (Index i = rings_.offset[v]; i < rings_.offset[v + 1]; ++i) {
                ring_position[rings_.ring[i].index()] = i - rings_.offset[v];
            }
        }
        d_.origin_.resize(num_half_edges());
        d_.next_.resize(num_half_edges());
        d_.prev_.resize(num_half_edges());
        for (Index h = 0; h < num_half_edges(); ++h) {
            const HalfEdgeId he(h);
            d_.origin_[h] = origin(he);
            const HalfEdgeId back = twin(he);
            const Index v = origin(back).index();
            const Index degree = rings_.offset[v + 1] - rings_.offset[v];
            const Index i = ring_position[back.index()];
            const HalfEdgeId n = rings_.ring[rings_.offset[v] + (i + degree - 1) % degree];
            d_.next_[h] = n;
            d_.prev_[n.index()] = he;
        }
    }

    // Cycles are numbered in order of their smallest half-edge.
    void find_cycles() {
        cycle_of_.assign(num_half_edges(), kNoIndex);
        for (Index h = 0; h < num_half_edges(); ++h) {
            if (cycle_of_[h] != kNoIndex) continue;
            const auto c = static_cast<Index>(cycle_rep_.size());
            cycle_rep_.push_back(HalfEdgeId(h));
            for (Index x = h; cycle_of_[x] == kNoIndex; x = d_.next_[x].index()) cycle_of_[x] = c;
        }
    }

    static Index find_root(std::vector<Index>& parent, Index x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];  // path halving
            x = parent[x];
        }
        return x;
    }

    // Components are numbered in sweep order of their leftmost vertex. The
    // outer cycle of a component passes through that vertex, on the side of
    // the wedge that contains the direction west.
    void find_components() {
        std::vector<Index> parent(num_vertices());
        std::iota(parent.begin(), parent.end(), 0);
        for (const GraphEdge& e : g_.edges) {
            const Index a = find_root(parent, e.u.index());
            const Index b = find_root(parent, e.v.index());
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
        std::vector<Index> component_of_root(num_vertices(), kNoIndex);
        component_of_.resize(num_vertices());
        for (const VertexId v : lex_order_) {
            const Index root = find_root(parent, v.index());
            if (component_of_root[root] == kNoIndex) {
                component_of_root[root] = static_cast<Index>(leftmost_.size());
                leftmost_.push_back(v);
            }
            component_of_[v.index()] = component_of_root[root];
        }
        is_outer_cycle_.assign(cycle_rep_.size(), 0);
        outer_cycle_.assign(leftmost_.size(), kNoIndex);
        for (Index c = 0; c < leftmost_.size(); ++c) {
            const VertexId v = leftmost_[c];
            const Index first = rings_.offset[v.index()];
            const Index degree = rings_.offset[v.index() + 1] - first;
            if (degree == 0) continue;  // an isolated vertex
            // All directions at the leftmost vertex point into the half-plane
            // x >= 0; the last one in [0, pi) (or the very last) borders the
            // wedge through west.
            Index k = 0;
            while (k < degree && angular_half(point(v), point(target(rings_.ring[first + k]))) == 0) ++k;
            const HalfEdgeId h = rings_.ring[first + (k + degree - 1) % degree];
            outer_cycle_[c] = cycle_of_[h.index()];
            is_outer_cycle_[outer_cycle_[c]] = 1;
        }
    }

    void place_faces() {
        std::vector<EdgeId> below;
        if (options_.check_crossings || leftmost_.size() > 1) {
            std::vector<char> wanted(num_vertices(), 0);
            for (const VertexId v : leftmost_) wanted[v.index()] = 1;
            below = sweep(SweepInput{g_, lex_order_, rings_.offset, rings_.ring, wanted}, options_.check_crossings);
        }
        // Every cycle that is not the outer boundary of its component bounds a
        // face of its own, numbered in cycle order after the unbounded face.
        std::vector<FaceId> face_of_cycle(cycle_rep_.size());
        d_.faces_.assign(1, FaceRecord{});
        for (Index c = 0; c < cycle_rep_.size(); ++c) {
            if (is_outer_cycle_[c] != 0) continue;
            face_of_cycle[c] = FaceId(static_cast<Index>(d_.faces_.size()));
            d_.faces_.push_back(FaceRecord{cycle_rep_[c], {}, {}});
        }
        // A component lies in the face just above the edge below its leftmost
        // vertex. If that edge's upper side is the outer boundary of another
        // component, that component's container is ours too; it has a smaller
        // leftmost vertex, so it was placed already.
        std::vector<FaceId> container(leftmost_.size(), Dcel::kUnboundedFace);
        for (Index c = 0; c < leftmost_.size(); ++c) {
            const VertexId v = leftmost_[c];
            const EdgeId e = below.empty() ? EdgeId() : below[v.index()];
            if (!e.is_null()) {
                const HalfEdgeId forward = half_edge_of(e, 0);
                const HalfEdgeId upper = lex_less(point(origin(forward)), point(target(forward))) ? forward : twin(forward);
                const Index cycle = cycle_of_[upper.index()];
                container[c] = is_outer_cycle_[cycle] != 0 ? container[component_of_[origin(upper).index()]]
                                                           : face_of_cycle[cycle];
            }
            FaceRecord& f = d_.faces_[container[c].index()];
            if (outer_cycle_[c] == kNoIndex) {
                f.isolated.push_back(v);
            } else {
                face_of_cycle[outer_cycle_[c]] = container[c];
                f.inner.push_back(cycle_rep_[outer_cycle_[c]]);
            }
        }
        for (FaceRecord& f : d_.faces_) {
            std::sort(f.inner.begin(), f.inner.end());
            std::sort(f.isolated.begin(), f.isolated.end());
        }
        d_.face_.resize(num_half_edges());
        for (Index h = 0; h < num_half_edges(); ++h) d_.face_[h] = face_of_cycle[cycle_of_[h]];
    }

    void fill_vertices() {
        d_.out_.assign(num_vertices(), HalfEdgeId());
        for (Index v = 0; v < num_vertices(); ++v) {
            for (Index i = rings_.offset[v]; i < rings_.offset[v + 1]; ++i) {
                d_.out_[v] = std::min(d_.out_[v], rings_.ring[i]);
            }
        }
    }

    const PlanarGraph& g_;
    BuildOptions options_;
    Dcel d_;

    std::vector<VertexId> lex_order_;
    Rings rings_;
    std::vector<Index> cycle_of_;
    std::vector<HalfEdgeId> cycle_rep_;
    std::vector<Index> component_of_;   // per vertex
    std::vector<VertexId> leftmost_;    // per component
    std::vector<Index> outer_cycle_;    // per component; kNoIndex when isolated
    std::vector<char> is_outer_cycle_;  // per cycle
};

Dcel build(const PlanarGraph& graph, const BuildOptions& options) { return DcelBuilder(graph, options).run(); }

}  // namespace dcel
