// The input of the oracle harness, and what its custom mutator reads: a
// recipe for a generated graph (generated_graph.hpp), or a graph written
// point by point (text_graph.hpp), which is what the mutator writes. A
// text whose first word is "points", "edges", "scale" or "offset" is the
// second kind.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "dcel/gen/generate.hpp"
#include "support/generated_graph.hpp"
#include "support/text_graph.hpp"
#include "support/token_reader.hpp"

namespace dcel::fuzz {

struct GraphInput {
    bool generated = true;  // from a recipe; else point by point
    GeneratedGraph recipe;  // what the recipe said, when generated
    PlanarGraph graph;
};

struct GraphInputCaps {
    std::size_t generated_vertices;  // the recipe's size, modulo this plus one
    std::size_t steps;               // the recipe's transforms and deletions
    GraphCaps explicit_graph;        // a graph given point by point
};

inline bool written_point_by_point(std::string_view text) {
    TokenReader in(text);
    while (!in.at_end() && in.peek().kind != Token::Kind::Word) in.next();
    const Token t = in.peek();
    return t.is_word("points") || t.is_word("edges") || t.is_word("scale") || t.is_word("offset");
}

inline GraphInput decode_graph_input(std::string_view text, const GraphInputCaps& caps) {
    GraphInput out;
    TokenReader in(text);
    if (written_point_by_point(text)) {
        out.generated = false;
        out.graph = decode_graph(in, caps.explicit_graph);
    } else {
        out.recipe = decode_generated_graph(in, caps.generated_vertices, caps.steps);
        out.graph = out.recipe.graph;
    }
    return out;
}

inline std::string describe(const GraphInput& in) {
    const std::string size = std::to_string(in.graph.vertices.size()) + " vertices, " +
                             std::to_string(in.graph.edges.size()) + " edges";
    if (!in.generated) return "a graph given point by point (" + size + ")";
    const GeneratedGraph& c = in.recipe;
    return std::string(gen::family_name(c.params.family)) + " seed " + std::to_string(c.params.seed) + " vertices " +
           std::to_string(c.params.vertices) + " (" + size + " after " + std::to_string(c.transforms) + " transforms)";
}

}  // namespace dcel::fuzz
