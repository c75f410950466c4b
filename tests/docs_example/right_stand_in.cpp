// my_dcel::faces answered by the reference itself, so that the docs example's
// tests have a solver to pass (the example is what is under test here).
#include "dcel/build.hpp"
#include "my_dcel.hpp"

namespace my_dcel {

std::vector<std::vector<int>> faces(const std::vector<Point>& points, const std::vector<Edge>& edges) {
    dcel::PlanarGraph g;
    for (const Point& p : points) g.vertices.push_back({p.x, p.y});
    for (const Edge& e : edges) {
        g.edges.push_back({dcel::VertexId(static_cast<dcel::Index>(e.u)), dcel::VertexId(static_cast<dcel::Index>(e.v))});
    }
    const dcel::Dcel d = dcel::build(g);
    std::vector<std::vector<int>> out;
    std::vector<bool> seen(d.num_half_edges(), false);
    for (dcel::Index h = 0; h < d.num_half_edges(); ++h) {
        if (seen[h]) continue;
        auto& cycle = out.emplace_back();
        for (const dcel::HalfEdgeId x : d.cycle(dcel::HalfEdgeId(h))) {
            seen[x.index()] = true;
            cycle.push_back(static_cast<int>(d.origin(x).index()));
        }
    }
    return out;
}

}  // namespace my_dcel
