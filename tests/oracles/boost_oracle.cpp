#include "oracles/boost_oracle.hpp"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boyer_myrvold_planar_test.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/planar_face_traversal.hpp>
#include <boost/property_map/property_map.hpp>
#include <utility>

#include "oracles/reference_dcel.hpp"

namespace dcel::oracle {
namespace {

// vecS vertex storage gives Boost its vertex index for free; the edge
// index (which the traversal needs and Boost does not fill) is ours.
using EdgeIndex = boost::property<boost::edge_index_t, int>;
// (The edge list in a vector too: fewer allocations than the default list.)
using BoostGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property, EdgeIndex,
                                         boost::no_property, boost::vecS>;
using BoostEdge = boost::graph_traits<BoostGraph>::edge_descriptor;
using Embedding = std::vector<std::vector<BoostEdge>>;  // per vertex, its edges in clockwise order
using EmbeddingMap =
    boost::iterator_property_map<Embedding::iterator, boost::property_map<BoostGraph, boost::vertex_index_t>::type>;

// Boost requires an edge index and does not fill it.
BoostGraph to_boost(std::size_t n, const std::vector<std::pair<Index, Index>>& edges) {
    BoostGraph b(n);
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const auto [e, added] = boost::add_edge(edges[k].first, edges[k].second, b);
        (void)added;
        boost::put(boost::edge_index, b, e, static_cast<int>(k));
    }
    return b;
}

// Each edge's descriptor by its index, read once the graph is complete (a
// descriptor points into the edge list, which moves as edges are added).
std::vector<BoostEdge> descriptors(const BoostGraph& b) {
    std::vector<BoostEdge> out(boost::num_edges(b));
    for (auto [it, end] = boost::edges(b); it != end; ++it) {
        out[static_cast<std::size_t>(boost::get(boost::edge_index, b, *it))] = *it;
    }
    return out;
}

std::vector<std::pair<Index, Index>> edge_pairs(const PlanarGraph& g) {
    std::vector<std::pair<Index, Index>> pairs;
    for (const GraphEdge& e : g.edges) pairs.emplace_back(e.u.index(), e.v.index());
    return pairs;
}

// In range, no self-loops, each pair once.
std::vector<std::pair<Index, Index>> simple_edges(const PlanarGraph& g) {
    std::vector<std::pair<Index, Index>> simple;
    for (const auto& [u, v] : edge_pairs(g)) {
        if (u == v || u >= g.vertices.size() || v >= g.vertices.size()) continue;
        simple.emplace_back(std::min(u, v), std::max(u, v));
    }
    std::sort(simple.begin(), simple.end());
    simple.erase(std::unique(simple.begin(), simple.end()), simple.end());
    return simple;
}

// Each face as the vertex sequence Boost walks.
struct FaceWalks : boost::planar_face_traversal_visitor {
    std::vector<Cycle> faces;
    void begin_face() { faces.emplace_back(); }
    template <class Vertex>
    void next_vertex(Vertex v) {
        faces.back().push_back(static_cast<Index>(v));
    }
};

struct FaceCounter : boost::planar_face_traversal_visitor {
    std::size_t faces = 0;
    void begin_face() { ++faces; }
};

}  // namespace

std::vector<Cycle> boost_face_cycles(const PlanarGraph& g) {
    return boost_face_cycles(g, rotation_system(half_edges_of(g)));
}

std::vector<Cycle> boost_face_cycles(const PlanarGraph& g, const Rotations& rotations) {
    const BoostGraph b = to_boost(g.vertices.size(), edge_pairs(g));
    const std::vector<BoostEdge> edges = descriptors(b);
    // Clockwise: each counterclockwise ring reversed; half-edge e is edge e / 2.
    Embedding embedding(g.vertices.size());
    for (std::size_t v = 0; v < g.vertices.size(); ++v) {
        const std::vector<Index>& ring = rotations.ring[v];
        for (auto e = ring.rbegin(); e != ring.rend(); ++e) embedding[v].push_back(edges[*e / 2]);
    }
    FaceWalks walks;
    boost::planar_face_traversal(b, EmbeddingMap(embedding.begin(), boost::get(boost::vertex_index, b)), walks);
    std::vector<Cycle> cycles;
    cycles.reserve(walks.faces.size());
    for (const Cycle& c : walks.faces) cycles.push_back(canonical(c));
    std::sort(cycles.begin(), cycles.end());
    return cycles;
}

BoyerMyrvoldAnswer boyer_myrvold(const PlanarGraph& g) {
    const std::vector<std::pair<Index, Index>> edges = simple_edges(g);
    BoostGraph b = to_boost(g.vertices.size(), edges);
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
    for (const auto& [u, v] : edges) has_edge[static_cast<std::size_t>(component[u])] = 1;
    answer.components = static_cast<std::size_t>(std::count(has_edge.begin(), has_edge.end(), 1));
    return answer;
}

}  // namespace dcel::oracle
