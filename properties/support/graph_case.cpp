#include "support/graph_case.hpp"

#include <cmath>

#include <utility>

namespace dcel::props {

rc::Gen<GraphCase> graphs(std::vector<gen::Family> families) {
    return testing::graph_cases({.families = std::move(families), .vertices_per_size = 3, .targeted = false});
}

rc::Gen<GraphCase> graphs() { return graphs({}); }

bool has_integer_coordinates(const PlanarGraph& g) {
    for (const Point& p : g.vertices) {
        if (std::trunc(p.x) != p.x || std::trunc(p.y) != p.y) return false;
    }
    return true;
}

}  // namespace dcel::props

namespace dcel::gen {

void showValue(Defect d, std::ostream& os) {
    static const char* const kNames[] = {"crossing", "touch", "overlap"};
    os << kNames[static_cast<int>(d)];
}

void showValue(Transform t, std::ostream& os) {
    static const char* const kNames[] = {"translate", "rotate90", "mirror", "scale-pow2"};
    os << kNames[static_cast<int>(t)];
}

}  // namespace dcel::gen
