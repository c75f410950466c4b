#include "peers/boost_traversal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boyer_myrvold_planar_test.hpp>
#include <boost/graph/planar_face_traversal.hpp>

namespace dcel::bench {
namespace {

using BoostGraph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::property<boost::vertex_index_t, int>,
                          boost::property<boost::edge_index_t, int>>;
using BoostEdge = boost::graph_traits<BoostGraph>::edge_descriptor;
using Embedding = std::vector<std::vector<BoostEdge>>;

BoostGraph make_graph(const PlanarGraph& g) {
    BoostGraph bg(g.vertices.size());
    int index = 0;
    for (const GraphEdge& e : g.edges) {
        boost::add_edge(e.u.index(), e.v.index(), boost::property<boost::edge_index_t, int>(index++), bg);
    }
    return bg;
}

// Records each face as the vertices it passes, in traversal order.
struct Recorder : boost::planar_face_traversal_visitor {
    Cycles* out;
    explicit Recorder(Cycles* o) : out(o) {}
    void begin_face() { out->emplace_back(); }
    template <class Vertex>
    void next_vertex(Vertex v) {
        out->back().push_back(static_cast<std::uint32_t>(v));
    }
};

struct Counter : boost::planar_face_traversal_visitor {
    std::size_t faces = 0;
    void begin_face() { ++faces; }
};

PeerResult traverse(const BoostGraph& bg, Embedding& embedding, bool want_cycles) {
    PeerResult result;
    if (want_cycles) {
        Recorder visitor(&result.cycles);
        boost::planar_face_traversal(bg, &embedding[0], visitor, boost::get(boost::edge_index, bg));
        result.count = result.cycles.size();
    } else {
        Counter visitor;
        boost::planar_face_traversal(bg, &embedding[0], visitor, boost::get(boost::edge_index, bg));
        result.count = visitor.faces;
    }
    return result;
}

}  // namespace

PeerResult boost_geometric_cycles(const PlanarGraph& g, bool want_cycles) {
    const BoostGraph bg = make_graph(g);
    Embedding embedding(g.vertices.size());
    std::vector<std::pair<double, BoostEdge>> ring;
    for (std::size_t v = 0; v < g.vertices.size(); ++v) {
        ring.clear();
        const Point c = g.vertices[v];
        for (const BoostEdge e : boost::make_iterator_range(boost::out_edges(v, bg))) {
            const Point t = g.vertices[boost::target(e, bg)];
            ring.emplace_back(std::atan2(t.y - c.y, t.x - c.x), e);
        }
        // Clockwise: decreasing angle.
        std::sort(ring.begin(), ring.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        for (const auto& [angle, e] : ring) embedding[v].push_back(e);
    }
    return traverse(bg, embedding, want_cycles);
}

PeerResult boost_bm_cycles(const PlanarGraph& g, bool want_cycles) {
    const BoostGraph bg = make_graph(g);
    Embedding embedding(g.vertices.size());
    if (!boost::boyer_myrvold_planarity_test(boost::boyer_myrvold_params::graph = bg,
                                             boost::boyer_myrvold_params::embedding = &embedding[0])) {
        throw std::runtime_error("Boyer-Myrvold: not planar");
    }
    return traverse(bg, embedding, want_cycles);
}

}  // namespace dcel::bench
