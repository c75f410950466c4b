// Decodes a valid planar straight-line graph from readable fuzz text, through
// the shared generators (dcel::gen), then exact transforms and deletions:
//
//   [FAMILY | family N] [seed S] [vertices N] [rotate | mirror | translate A
//   | scale K | drop E | remove V]...
//
// FAMILY is a family name with '_' for '-' (triangulation, near_degenerate,
// grid_with_holes, ...); "family N" picks family N modulo 10, so every family
// is one number away for the fuzzer. Generation happens at the first
// transform or deletion (or at the end). rotate, mirror, translate A (an
// integer) and scale K (by 2^K) are gen::apply's exact transforms; one that
// would round is skipped. "drop E" deletes edge E and "remove V" vertex V
// with its edges (indices modulo the counts): a subgraph of a valid graph is
// valid, and deletions give the fuzzer direct control over the shape. Other
// words and stray numbers are ignored.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "dcel/gen/generate.hpp"
#include "dcel/graph.hpp"
#include "support/token_reader.hpp"

namespace dcel::fuzz {

struct GeneratedGraph {
    gen::Params params;
    PlanarGraph graph;
    std::size_t transforms = 0;  // applied (skipped ones not counted)
};

inline std::uint64_t whole_number(double v) {
    if (!std::isfinite(v) || std::fabs(v) >= 0x1p63) return 0;
    return static_cast<std::uint64_t>(std::llabs(static_cast<long long>(v)));
}

inline std::int64_t signed_whole_number(double v) {
    if (!std::isfinite(v) || std::fabs(v) >= 0x1p62) return 0;
    return static_cast<std::int64_t>(v);
}

inline void erase_edge(PlanarGraph& g, std::size_t e) { g.edges.erase(g.edges.begin() + static_cast<long>(e)); }

// Removes vertex v and its edges; later vertices shift down by one.
inline void erase_vertex(PlanarGraph& g, Index v) {
    std::erase_if(g.edges, [&](const GraphEdge& e) { return e.u.index() == v || e.v.index() == v; });
    for (GraphEdge& e : g.edges) {
        if (e.u.index() > v) e.u = VertexId(e.u.index() - 1);
        if (e.v.index() > v) e.v = VertexId(e.v.index() - 1);
    }
    g.vertices.erase(g.vertices.begin() + static_cast<long>(v));
}

// max_vertices caps the generator's size argument (the oracles are
// superlinear); max_steps caps transforms and deletions.
inline GeneratedGraph decode_generated_graph(TokenReader& in, std::size_t max_vertices, std::size_t max_steps) {
    GeneratedGraph out;
    bool generated = false;
    auto generate = [&] {
        if (!generated) out.graph = gen::generate(out.params);
        generated = true;
    };
    std::size_t steps = 0;
    while (!in.at_end() && steps < max_steps) {
        const Token t = in.next();
        if (t.kind != Token::Kind::Word) continue;
        std::string name(t.word);
        for (char& c : name) c = c == '_' ? '-' : c;
        if (const auto family = gen::family_from_name(name); family && !generated) {
            out.params.family = *family;
        } else if (t.is_word("family") && !generated) {
            const auto all = gen::all_families();
            out.params.family = all[whole_number(in.number_or(0)) % all.size()];
        } else if (t.is_word("seed") && !generated) {
            out.params.seed = whole_number(in.number_or(0));
        } else if (t.is_word("vertices") && !generated) {
            out.params.vertices = whole_number(in.number_or(16)) % (max_vertices + 1);
        } else if (t.is_word("rotate") || t.is_word("mirror") || t.is_word("translate") || t.is_word("scale")) {
            generate();
            ++steps;
            const gen::Transform kind = t.is_word("rotate")   ? gen::Transform::Rotate90
                                        : t.is_word("mirror") ? gen::Transform::Mirror
                                        : t.is_word("scale")  ? gen::Transform::ScalePow2
                                                              : gen::Transform::Translate;
            const std::int64_t amount = kind == gen::Transform::Rotate90 || kind == gen::Transform::Mirror
                                            ? 0
                                            : signed_whole_number(in.number_or(0));
            if (auto moved = gen::apply(out.graph, kind, amount)) {
                out.graph = std::move(*moved);
                ++out.transforms;
            }
        } else if (t.is_word("drop") || t.is_word("remove")) {
            generate();
            ++steps;
            const double which = in.number_or(0);
            if (t.is_word("drop") && !out.graph.edges.empty()) {
                erase_edge(out.graph, wrap_index(which, out.graph.edges.size()));
            } else if (t.is_word("remove") && !out.graph.vertices.empty()) {
                erase_vertex(out.graph, static_cast<Index>(wrap_index(which, out.graph.vertices.size())));
            }
        }
    }
    generate();
    return out;
}

}  // namespace dcel::fuzz
