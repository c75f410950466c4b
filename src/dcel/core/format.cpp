#include "dcel/format.hpp"

#include <charconv>
#include <cmath>

namespace dcel {

std::string format_double(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, v);
    return {buf, res.ptr};
}

// Built with append: GCC 12 at -O3 warns falsely on "(" + std::string (bug 105329).
std::string format_point(Point p) {
    std::string s = "(";
    s.append(format_double(p.x)).append(", ").append(format_double(p.y)).append(")");
    return s;
}

std::string describe_vertex(const PlanarGraph& g, VertexId v) {
    std::string s = "vertex ";
    s.append(std::to_string(v.index())).append(" ").append(format_point(g.vertices[v.index()]));
    return s;
}

std::string describe_edge(const PlanarGraph& g, EdgeId e) {
    const GraphEdge& ge = g.edges[e.index()];
    std::string s = "edge ";
    s.append(std::to_string(e.index())).append(" [").append(std::to_string(ge.u.index())).append(", ");
    s.append(std::to_string(ge.v.index())).append("] from ").append(format_point(g.vertices[ge.u.index()]));
    s.append(" to ").append(format_point(g.vertices[ge.v.index()]));
    return s;
}

}  // namespace dcel
