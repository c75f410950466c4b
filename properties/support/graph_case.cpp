#include "support/graph_case.hpp"

#include <cmath>

#include "dcel/io/graph_json.hpp"

namespace dcel::props {

void showValue(const GraphCase& c, std::ostream& os) {
    os << "family " << gen::family_name(c.params.family) << ", seed " << c.params.seed << ", " << c.params.vertices
       << " vertices asked; " << c.graph.vertices.size() << " vertices, " << c.graph.edges.size()
       << " edges after shrinking. Paste into `dcel faces -`:\n"
       << io::write_graph(c.graph);
}

rc::Gen<GraphCase> graphs(std::vector<gen::Family> families) {
    const rc::Gen<gen::Params> params = rc::gen::withSize([families](int size) {
        return rc::gen::apply(
            [](gen::Family f, std::uint64_t seed, int n) {
                return gen::Params{f, seed, static_cast<std::size_t>(n)};
            },
            rc::gen::elementOf(families), rc::gen::arbitrary<std::uint64_t>(), rc::gen::inRange(0, 3 * size + 4));
    });
    return rc::gen::mapcat(rc::gen::noShrink(params), [](const gen::Params& p) {
        return rc::Gen<GraphCase>([p](const rc::Random&, int) {
            return rc::shrinkable::shrinkRecur(GraphCase{p, gen::generate(p)}, [](const GraphCase& c) {
                return rc::seq::map(rc::seq::fromContainer(gen::shrink_candidates(c.graph)),
                                    [params = c.params](PlanarGraph g) {
                                        return GraphCase{params, std::move(g)};
                                    });
            });
        });
    });
}

rc::Gen<GraphCase> graphs() {
    const auto all = gen::all_families();
    return graphs(std::vector<gen::Family>(all.begin(), all.end()));
}

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
