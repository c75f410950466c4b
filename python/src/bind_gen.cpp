// The generators of dcel::gen (dcel/gen/generate.hpp) with explicit seeds:
// the same family, seed and size give the same graph on every platform, so
// a caller that controls the seed (Hypothesis) controls the graph.
#include <limits>

#include <pybind11/stl.h>

#include "binding.hpp"
#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
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

py::object optional_graph(const std::optional<PlanarGraph>& g) { return g ? graph_to_python(*g) : py::none(); }

// A graph argument of plant and the shrinkers, which take it as valid (they
// index points by the edges' vertex ids, and keep it free of crossings): an
// invalid one read out of bounds. Refused as build() refuses it.
PlanarGraph valid_graph_from(py::handle graph) {
    PlanarGraph g = graph_from(graph);
    {
        const py::gil_scoped_release unlocked;
        static_cast<void>(build(g));  // InvalidInput, naming the offending vertices and edges
    }
    return g;
}

// families() and generate(): the generators.
void bind_generators(py::module_& m) {
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
        [](const TextArg& family_arg, const IntArg& seed_arg, const IntArg& vertices_arg) {
            const std::string family = text_from(family_arg, "generate: family");
            const auto f = gen::family_from_name(family);
            if (!f) {
                throw InvalidInput(InputErrorKind::Shape, "generate: unknown family " + quote_for_message(family) +
                                                              "; the families are " + family_list());
            }
            const std::uint64_t seed = seed_from(seed_arg, "seed");
            const std::size_t vertices = count_from(vertices_arg, std::numeric_limits<std::uint32_t>::max(),
                                                    "generate: vertices");
            if (vertices > kMaxVertices) {
                throw InvalidInput(InputErrorKind::TooLarge, "generate: " + std::to_string(vertices) +
                                                                 " vertices is more than " + std::to_string(kMaxVertices));
            }
            return graph_to_python(gen::generate({*f, seed, vertices}));
        },
        py::arg("family"), py::arg("seed"), py::arg("vertices") = 16,
        "A random valid graph (a Graph of lists) from the library's generators, as `dcel gen` makes it: the same\n"
        "family, seed and size give the same graph everywhere, with exactly that many vertices.");
}

// shrink_candidates() and shrink(): shrinking a failing graph.
void bind_shrinking(py::module_& m) {
    m.def(
        "shrink_candidates",
        [](const py::object& graph) {
            py::list out;
            for (const PlanarGraph& c : gen::shrink_candidates(valid_graph_from(graph))) out.append(graph_to_python(c));
            return out;
        },
        py::arg("graph"),
        "Smaller valid graphs derived from graph, most aggressive first: without edges, without a vertex,\n"
        "coordinates snapped to small integers where that stays valid. graph must be valid (InvalidInput as\n"
        "from build() when not).");
    m.def(
        "shrink",
        [](const py::object& graph, const py::object& still_fails, const IntArg& max_steps_arg) {
            if (PyCallable_Check(still_fails.ptr()) == 0) {
                throw py::type_error("shrink: still_fails: expected a function of a Graph, found " + shown(still_fails));
            }
            const std::size_t max_steps = count_from(max_steps_arg, std::numeric_limits<std::uint32_t>::max(),
                                                     "shrink: max_steps");
            const PlanarGraph start = valid_graph_from(graph);
            // Truth as `if still_fails(g):` takes it; an exception the
            // predicate raises is its own, and goes on as it is.
            const auto test = [&](const PlanarGraph& g) {
                const py::object verdict = still_fails(graph_to_python(g));
                const int truth = PyObject_IsTrue(verdict.ptr());
                if (truth < 0) throw py::error_already_set();
                return truth != 0;
            };
            return graph_to_python(gen::shrink(start, test, max_steps));
        },
        py::arg("graph"), py::arg("still_fails"), py::arg("max_steps") = 20000,
        "Greedy shrinking (what `dcel diff` does): moves to the first shrink candidate for which still_fails(g)\n"
        "is true, until none is or max_steps calls are spent. Returns the smallest failing graph found. graph\n"
        "must be valid (InvalidInput as from build() when not); an exception still_fails raises goes on as it is.");
}

// transform() and plant(): exact transforms and planted defects.
void bind_transforms(py::module_& m) {
    m.def(
        "transform",
        [](const py::object& graph, const TextArg& kind_arg, const IntArg& amount_arg) {
            const std::string kind = text_from(kind_arg, "transform: kind");
            // Symmetric, so that the library may negate it or take its absolute value.
            constexpr std::int64_t kLimit = std::numeric_limits<std::int64_t>::max();
            const std::int64_t amount = int_from(amount_arg, -kLimit, kLimit, "transform: amount");
            gen::Transform t{};
            if (kind == "translate") t = gen::Transform::Translate;
            else if (kind == "rotate90") t = gen::Transform::Rotate90;
            else if (kind == "mirror") t = gen::Transform::Mirror;
            else if (kind == "scale-pow2") t = gen::Transform::ScalePow2;
            else
                throw InvalidInput(InputErrorKind::Shape, "transform: unknown kind " + quote_for_message(kind) +
                                                              "; the kinds are translate, rotate90, mirror, scale-pow2");
            return optional_graph(gen::apply(graph_from(graph), t, amount));
        },
        py::arg("graph"), py::arg("kind"), py::arg("amount") = 0,
        "An exact transform of graph: \"translate\" by (amount, -amount), \"rotate90\", \"mirror\" (x -> -x, every\n"
        "cycle reversed), \"scale-pow2\" by 2**amount. None when a coordinate would round, overflow or underflow.");
    m.def(
        "plant",
        [](const py::object& graph, const TextArg& defect_arg, const IntArg& seed_arg) {
            const std::string defect = text_from(defect_arg, "plant: defect");
            const std::uint64_t seed = seed_from(seed_arg, "seed");
            gen::Defect d{};
            if (defect == "crossing") d = gen::Defect::Crossing;
            else if (defect == "touch") d = gen::Defect::Touch;
            else if (defect == "overlap") d = gen::Defect::Overlap;
            else
                throw InvalidInput(InputErrorKind::Shape, "plant: unknown defect " + quote_for_message(defect) +
                                                              "; the defects are crossing, touch, overlap");
            return optional_graph(gen::plant(valid_graph_from(graph), d, seed));
        },
        py::arg("graph"), py::arg("defect"), py::arg("seed") = 0,
        "graph with one defect planted, an invalid graph that build() refuses: \"crossing\", \"touch\" (a vertex\n"
        "inside an edge) or \"overlap\" (collinear edges sharing more than a point). None when there is no place.\n"
        "graph must be valid (InvalidInput as from build() when not).");
}

}  // namespace

void bind_gen(py::module_& m) {
    bind_generators(m);
    bind_shrinking(m);
    bind_transforms(m);
}

}  // namespace dcel::python
