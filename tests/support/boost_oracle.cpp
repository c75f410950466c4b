#include "support/boost_oracle.hpp"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boyer_myrvold_planar_test.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/planar_face_traversal.hpp>
#include <boost/property_map/property_map.hpp>

#include "support/exact_oracle.hpp"
#include "support/face_shapes.hpp"

namespace dcel::props {
namespace {

using BoostGraph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::property<boost::vertex_index_t, int>,
                          boost::property<boost::edge_index_t, int>>;
using BoostEdge = boost::graph_traits<BoostGraph>::edge_descriptor;
using Embedding = std::vector<std::vector<BoostEdge>>;
using EmbeddingMap =
    boost::iterator_property_map<Embedding::iterator, boost::property_map<BoostGraph, boost::vertex_index_t>::type>;

BoostGraph to_boost(const PlanarGraph& g) {
    BoostGraph b(g.vertices.size());
    for (std::size_t k = 0; k < g.edges.size(); ++k) {
        const auto [e, added] = boost::add_edge(g.edges[k].u.index(), g.edges[k].v.index(), b);
        (void)added;
        boost::put(boost::edge_index, b, e, static_cast<int>(k));  // Boost requires it, and does not fill it
    }
    return b;
}

// Records the vertex sequence of every face.
struct CycleCollector : boost::planar_face_traversal_visitor {
    std::vector<VertexCycle>* out;
    explicit CycleCollector(std::vector<VertexCycle>* o) : out(o) {}
    void begin_face() { out->emplace_back(); }
    template <class Vertex>
    void next_vertex(Vertex v) {
        out->back().push_back(static_cast<Index>(v));
    }
};

struct FaceCounter : boost::planar_face_traversal_visitor {
    std::size_t faces = 0;
    void begin_face() { ++faces; }
};

}  // namespace

VertexCycle canonical_cycle(VertexCycle c) { return testing::canonical(std::move(c)); }

std::vector<VertexCycle> boost_face_cycles(const PlanarGraph& g) {
    BoostGraph b = to_boost(g);
    Embedding embedding(g.vertices.size());
    for (std::size_t v = 0; v < g.vertices.size(); ++v) {
        const Point centre = g.vertices[v];
        auto other = [&](const BoostEdge& e) {
            const auto s = boost::source(e, b), t = boost::target(e, b);
            return g.vertices[s == v ? t : s];
        };
        auto [it, end] = boost::out_edges(v, b);
        std::vector<BoostEdge> ring(it, end);
        // Clockwise: the reverse of the counterclockwise angle order.
        std::sort(ring.begin(), ring.end(),
                  [&](const BoostEdge& x, const BoostEdge& y) { return angle_order(centre, other(x), other(y)) > 0; });
        embedding[v] = std::move(ring);
    }
    std::vector<VertexCycle> cycles;
    CycleCollector collector(&cycles);
    boost::planar_face_traversal(b, EmbeddingMap(embedding.begin(), boost::get(boost::vertex_index, b)), collector);
    for (VertexCycle& c : cycles) c = canonical_cycle(std::move(c));
    std::sort(cycles.begin(), cycles.end());
    return cycles;
}

BoyerMyrvoldAnswer boyer_myrvold(const PlanarGraph& g) {
    BoostGraph b = to_boost(g);
    BoyerMyrvoldAnswer answer;
    Embedding embedding(g.vertices.size());
    const EmbeddingMap map(embedding.begin(), boost::get(boost::vertex_index, b));
    answer.planar = boost::boyer_myrvold_planarity_test(boost::boyer_myrvold_params::graph = b,
                                                        boost::boyer_myrvold_params::embedding = map);
    if (!answer.planar) return answer;
    FaceCounter counter;
    boost::planar_face_traversal(b, map, counter);
    answer.faces = counter.faces;
    std::vector<int> component(g.vertices.size());
    const int all = g.vertices.empty() ? 0 : boost::connected_components(b, component.data());
    std::vector<char> has_edge(static_cast<std::size_t>(all), 0);
    for (const GraphEdge& e : g.edges) has_edge[static_cast<std::size_t>(component[e.u.index()])] = 1;
    answer.components = static_cast<std::size_t>(std::count(has_edge.begin(), has_edge.end(), 1));
    return answer;
}

}  // namespace dcel::props
