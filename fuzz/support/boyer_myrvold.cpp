#include "support/boyer_myrvold.hpp"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boyer_myrvold_planar_test.hpp>

namespace dcel::fuzz {

bool boost_is_planar(std::size_t n, const std::vector<std::pair<Index, Index>>& edges) {
    using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
    std::vector<std::pair<Index, Index>> simple;
    for (const auto& [u, v] : edges) {
        if (u == v || u >= n || v >= n) continue;
        simple.emplace_back(std::min(u, v), std::max(u, v));
    }
    std::sort(simple.begin(), simple.end());
    simple.erase(std::unique(simple.begin(), simple.end()), simple.end());
    Graph g(n);
    for (const auto& [u, v] : simple) boost::add_edge(u, v, g);
    return boost::boyer_myrvold_planarity_test(g);
}

}  // namespace dcel::fuzz
