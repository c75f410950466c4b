// Fuzzing a C++ DCEL implementation against the reference: fuzzer bytes
// become a valid planar straight-line graph, the solver's answer for it is
// compared with the reference, and a difference stops the process (abort)
// after printing the graph, shrunk, and the report, so libFuzzer, AFL++ or
// ClusterFuzzLite keep the input as a crash. The whole harness:
//
//   #include "dcel/testing/fuzz_solver.hpp"
//   extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
//       return dcel::testing::fuzz_faces_solver(data, size, my_faces);  // or fuzz_dump_solver
//   }
//
// Header-only, standard library and dcel only (no engine header): link
// dcel::testing, and the engine the usual way (-fsanitize=fuzzer, or
// $LIB_FUZZING_ENGINE). examples/downstream-fuzzing/ is a template with a
// build script and a ClusterFuzzLite set-up.
//
// The bytes (graph_from_fuzz_bytes): byte 0 picks the generator family
// (dcel::gen, modulo 10), bytes 1-8 the seed, byte 9 the size (modulo
// max_vertices + 1; 16 when absent); the bytes after that are edits in pairs
// (kind, amount): an exact rotation by 90 degrees, a mirror image, a
// translation, a scaling by a power of two, or deleting an edge or a vertex.
// Every input gives a valid graph (a subgraph or an exact transform of a
// valid graph is valid), so no execution is wasted on refusals, and one byte
// changes the family, a few the whole graph.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/report.hpp"
#include "dcel/dump.hpp"
#include "dcel/gen/generate.hpp"
#include "dcel/graph.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::testing {

// The answer types and the comparison are dcel::check's; the helpers here
// run it on the graphs of graph_cases.hpp.
using check::compare_dump;
using check::compare_faces;
using check::FacesAnswer;
using check::Report;
using check::report_text;

struct FuzzOptions {
    // Larger graphs find no more bugs per second: the reference and most
    // solvers are superlinear somewhere, and the executions per second drop.
    std::size_t max_vertices = 64;
    std::size_t max_edits = 16;
    std::size_t max_shrink_steps = 5000;  // solver runs spent shrinking a failing graph
};

namespace fuzz_detail {

class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    [[nodiscard]] bool empty() const { return at_ >= size_; }
    // The next n bytes, little-endian; missing bytes read as 0.
    std::uint64_t take(std::size_t n) {
        std::uint64_t v = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (at_ < size_) v |= std::uint64_t{data_[at_]} << (8 * i);
            ++at_;
        }
        return v;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

inline void erase_edge(PlanarGraph& g, std::size_t e) { g.edges.erase(g.edges.begin() + static_cast<std::ptrdiff_t>(e)); }

// Removes vertex v and its edges; later vertices shift down by one.
inline void erase_vertex(PlanarGraph& g, Index v) {
    std::erase_if(g.edges, [&](const GraphEdge& e) { return e.u.index() == v || e.v.index() == v; });
    for (GraphEdge& e : g.edges) {
        if (e.u.index() > v) e.u = VertexId(e.u.index() - 1);
        if (e.v.index() > v) e.v = VertexId(e.v.index() - 1);
    }
    g.vertices.erase(g.vertices.begin() + static_cast<std::ptrdiff_t>(v));
}

inline void edit(PlanarGraph& g, std::uint8_t kind, Bytes& in) {
    switch (kind % 6) {
        case 0:
            if (auto t = gen::apply(g, gen::Transform::Rotate90)) g = std::move(*t);
            break;
        case 1:
            if (auto t = gen::apply(g, gen::Transform::Mirror)) g = std::move(*t);
            break;
        case 2: {  // by a signed 32-bit amount; skipped when it would round
            const auto amount = static_cast<std::int32_t>(static_cast<std::uint32_t>(in.take(4)));
            if (auto t = gen::apply(g, gen::Transform::Translate, amount)) g = std::move(*t);
            break;
        }
        case 3: {  // by 2^k, k in -128 .. 127; skipped when it would round or overflow
            const auto k = static_cast<std::int8_t>(static_cast<std::uint8_t>(in.take(1)));
            if (auto t = gen::apply(g, gen::Transform::ScalePow2, k)) g = std::move(*t);
            break;
        }
        case 4: {
            const std::uint64_t e = in.take(2);
            if (!g.edges.empty()) erase_edge(g, e % g.edges.size());
            break;
        }
        default: {
            const std::uint64_t v = in.take(2);
            if (!g.vertices.empty()) erase_vertex(g, static_cast<Index>(v % g.vertices.size()));
            break;
        }
    }
}

// What is wrong with the solver's answer for g: empty when it agrees.
template <class Answer, class Solver, class Compare>
std::string failure(const PlanarGraph& g, const Solver& solver, Compare compare) {
    const Dcel reference = build(g);  // valid by construction; a throw here is a dcel bug
    try {
        const Answer answer = solver(g);
        const Report report = compare(reference, answer);
        return report.agrees() ? std::string() : report_text(report);
    } catch (const std::exception& e) {
        return std::string("the solver threw: ") + e.what() + "\n";
    } catch (...) {
        return "the solver threw something that is not a std::exception\n";
    }
}

}  // namespace fuzz_detail

// The graph the bytes stand for (see the top of this file). Deterministic,
// never throws on any bytes, always a valid planar straight-line graph.
[[nodiscard]] inline PlanarGraph graph_from_fuzz_bytes(const std::uint8_t* data, std::size_t size,
                                                       const FuzzOptions& options = {}) {
    fuzz_detail::Bytes in(data, size);
    const auto families = gen::all_families();
    gen::Params params;
    params.family = families[in.take(1) % families.size()];
    params.seed = in.take(8);
    params.vertices = size > 9 ? in.take(1) % (options.max_vertices + 1) : std::min<std::size_t>(16, options.max_vertices);
    PlanarGraph g = gen::generate(params);
    for (std::size_t i = 0; i < options.max_edits && !in.empty(); ++i) {
        fuzz_detail::edit(g, static_cast<std::uint8_t>(in.take(1)), in);
    }
    return g;
}

namespace fuzz_detail {

template <class Answer, class Solver, class Compare>
int fuzz(const std::uint8_t* data, std::size_t size, const Solver& solver, Compare compare, const FuzzOptions& options) {
    const PlanarGraph graph = graph_from_fuzz_bytes(data, size, options);
    const std::string what = failure<Answer>(graph, solver, compare);
    if (what.empty()) return 0;
    // Before stopping, the graph is shrunk (dcel::gen's shrinking: only valid
    // graphs) to one that fails the same way, a throw or a wrong answer: the
    // engine's own minimisation works on bytes, which here mostly means
    // another graph of the same size.
    const bool threw = what.starts_with("the solver threw");
    const PlanarGraph small = gen::shrink(
        graph,
        [&](const PlanarGraph& g) {
            const std::string w = failure<Answer>(g, solver, compare);
            return !w.empty() && w.starts_with("the solver threw") == threw;
        },
        options.max_shrink_steps);
    std::fprintf(stderr,
                 "dcel fuzz: the solver %s\n"
                 "the input's graph (%zu vertices, %zu edges):\n  %s"
                 "shrunk to a graph that fails the same way (%zu vertices, %zu edges; paste into `dcel faces -`,\n"
                 "`dcel check - answer.json` or `dcel render -`):\n  %s%s",
                 threw ? "threw" : "disagrees with the reference DCEL", graph.vertices.size(), graph.edges.size(),
                 io::write_graph(graph).c_str(), small.vertices.size(), small.edges.size(), io::write_graph(small).c_str(),
                 failure<Answer>(small, solver, compare).c_str());
    std::abort();
}

}  // namespace fuzz_detail

// One fuzzer input: 0 when the solver's faces (every boundary cycle as
// vertex ids in next order, FacesAnswer) agree with the reference; otherwise
// prints the graph and the report on stderr and aborts. Solver: any callable
// taking const PlanarGraph& and returning FacesAnswer.
template <class Solver>
int fuzz_faces_solver(const std::uint8_t* data, std::size_t size, const Solver& solver, const FuzzOptions& options = {}) {
    return fuzz_detail::fuzz<FacesAnswer>(data, size, solver, compare_faces, options);
}

// The same for a solver returning a whole DCEL (DcelDump, the `dcel build`
// format): half-edges, faces with their holes, isolated vertices.
template <class Solver>
int fuzz_dump_solver(const std::uint8_t* data, std::size_t size, const Solver& solver, const FuzzOptions& options = {}) {
    return fuzz_detail::fuzz<DcelDump>(data, size, solver, compare_dump, options);
}

}  // namespace dcel::testing
