// The generators of dcel::gen (dcel/gen/generate.hpp) with explicit seeds:
// the same family, seed and size give the same graph on every platform, so
// a caller that controls the seed (Hypothesis) controls the graph.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "binding.hpp"
#include "dcel/error.hpp"
#include "dcel/gen/generate.hpp"

namespace dcel::python {
namespace {

// As `dcel gen`: some families check candidate edges by brute force.
constexpr std::size_t kMaxVertices = 10000;

std::string family_list() {
    std::string s;
    for (const gen::Family f : gen::all_families()) s += (s.empty() ? "" : ", ") + std::string(gen::family_name(f));
    return s;
}

std::uint64_t seed_from(const py::int_& seed) {
    const py::int_ limit(py::reinterpret_steal<py::object>(PyLong_FromUnsignedLongLong(~std::uint64_t{0})));
    if (seed < py::int_(0) || seed > limit) {
        throw InvalidInput(InputErrorKind::BadIndex,
                           "seed " + py::repr(seed).cast<std::string>() + " is not an unsigned 64-bit integer");
    }
    return seed.cast<std::uint64_t>();
}

py::object optional_graph(const std::optional<PlanarGraph>& g) { return g ? graph_to_python(*g) : py::none(); }

}  // namespace

void bind_gen(py::module_& m) {
    m.def(
        "families",
        [] {
            std::vector<std::string> out;
            for (const gen::Family f : gen::all_families()) out.emplace_back(gen::family_name(f));
            return out;
        },
        "The generator families: random-segments, triangulation, grid-with-holes, nested-polygons, tree, comb,\n"
        "star, collinear-chain, components, near-degenerate.");
    m.def(
        "generate",
        [](const std::string& family, const py::int_& seed, std::size_t vertices) {
            const auto f = gen::family_from_name(family);
            if (!f)
                throw InvalidInput(InputErrorKind::Shape,
                                   "generate: unknown family \"" + family + "\"; the families are " + family_list());
            if (vertices > kMaxVertices) {
                throw InvalidInput(InputErrorKind::TooLarge, "generate: " + std::to_string(vertices) +
                                                                 " vertices is more than " + std::to_string(kMaxVertices));
            }
            return graph_to_python(gen::generate({*f, seed_from(seed), vertices}));
        },
        py::arg("family"), py::arg("seed"), py::arg("vertices") = 16,
        "A random valid graph (a Graph of lists) from the library's generators, as `dcel gen` makes it: the same\n"
        "family, seed and size give the same graph everywhere, with exactly that many vertices.");
    m.def(
        "shrink_candidates",
        [](const py::object& graph) {
            py::list out;
            for (const PlanarGraph& c : gen::shrink_candidates(graph_from(graph))) out.append(graph_to_python(c));
            return out;
        },
        py::arg("graph"),
        "Smaller valid graphs derived from graph, most aggressive first: without edges, without a vertex,\n"
        "coordinates snapped to small integers where that stays valid.");
    m.def(
        "shrink",
        [](const py::object& graph, const std::function<bool(py::object)>& still_fails, std::size_t max_steps) {
            const auto test = [&](const PlanarGraph& g) { return still_fails(graph_to_python(g)); };
            return graph_to_python(gen::shrink(graph_from(graph), test, max_steps));
        },
        py::arg("graph"), py::arg("still_fails"), py::arg("max_steps") = 20000,
        "Greedy shrinking (what `dcel diff` does): moves to the first shrink candidate for which still_fails(g)\n"
        "is true, until none is or max_steps calls are spent. Returns the smallest failing graph found.");
    m.def(
        "transform",
        [](const py::object& graph, const std::string& kind, std::int64_t amount) {
            gen::Transform t{};
            if (kind == "translate") t = gen::Transform::Translate;
            else if (kind == "rotate90") t = gen::Transform::Rotate90;
            else if (kind == "mirror") t = gen::Transform::Mirror;
            else if (kind == "scale-pow2") t = gen::Transform::ScalePow2;
            else
                throw InvalidInput(InputErrorKind::Shape, "transform: unknown kind \"" + kind +
                                                              "\"; the kinds are translate, rotate90, mirror, scale-pow2");
            return optional_graph(gen::apply(graph_from(graph), t, amount));
        },
        py::arg("graph"), py::arg("kind"), py::arg("amount") = 0,
        "An exact transform of graph: \"translate\" by (amount, -amount), \"rotate90\", \"mirror\" (x -> -x, every\n"
        "cycle reversed), \"scale-pow2\" by 2**amount. None when a coordinate would round, overflow or underflow.");
    m.def(
        "plant",
        [](const py::object& graph, const std::string& defect, const py::int_& seed) {
            gen::Defect d{};
            if (defect == "crossing") d = gen::Defect::Crossing;
            else if (defect == "touch") d = gen::Defect::Touch;
            else if (defect == "overlap") d = gen::Defect::Overlap;
            else
                throw InvalidInput(InputErrorKind::Shape,
                                   "plant: unknown defect \"" + defect + "\"; the defects are crossing, touch, overlap");
            return optional_graph(gen::plant(graph_from(graph), d, seed_from(seed)));
        },
        py::arg("graph"), py::arg("defect"), py::arg("seed") = 0,
        "graph with one defect planted, an invalid graph that build() refuses: \"crossing\", \"touch\" (a vertex\n"
        "inside an edge) or \"overlap\" (collinear edges sharing more than a point). None when there is no place.");
}

}  // namespace dcel::python
