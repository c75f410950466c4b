// Decodes a planar straight-line graph (not necessarily a valid one) from
// readable fuzz text:
//
//   [scale S] [offset X Y] [points] x y, x y, ..., on i j t, ...  edges u v, ...
//
// Numbers before "edges" pair up into points, numbers after it into index
// pairs (a leftover odd number is dropped). Each point is (X + x*S, Y + y*S)
// in double arithmetic, so "offset 1e15 1e15" with small integers gives
// near-degenerate coordinates, "scale 5e-324" subnormals, and "nan"/"inf"
// bad coordinates. "on i j t" adds the point p_i + t (p_j - p_i), rounded:
// within rounding of the line through p_i and p_j (i and j modulo the points
// so far), which is where exact and floating-point orientation disagree. An index that is not an integer in [0, 2^32 - 2]
// becomes the null id, which build() rejects like any out-of-range index. Decoding stops at the first other word, which is
// left in the reader for the harness (check reads its corruption commands from there).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

#include "dcel/graph.hpp"
#include "support/token_reader.hpp"

namespace dcel::fuzz {

struct GraphCaps {
    std::size_t vertices;
    std::size_t edges;
};

inline VertexId index_from(double v) {
    if (!(v >= 0 && v < static_cast<double>(kNoIndex)) || std::floor(v) != v) return VertexId();
    return VertexId(static_cast<Index>(v));
}

// Reads up to caps.vertices points and caps.edges edges; anything beyond the
// caps is read and ignored.
inline PlanarGraph decode_graph(TokenReader& in, GraphCaps caps) {
    PlanarGraph g;
    double scale = 1;
    double offset_x = 0;
    double offset_y = 0;
    bool edges = false;
    bool have_half = false;  // a first number waiting for its partner
    double half = 0;
    while (!in.at_end()) {
        const Token t = in.peek();
        if (t.kind == Token::Kind::Word) {
            if (t.is_word("points")) {
                edges = false;
            } else if (t.is_word("edges")) {
                edges = true;
            } else if (t.is_word("scale")) {
                in.next();
                scale = in.number_or(scale);
                continue;
            } else if (t.is_word("on")) {
                in.next();
                const double i = in.number_or(0);
                const double j = in.number_or(0);
                const double along = in.number_or(0.5);
                if (!edges && !g.vertices.empty() && g.vertices.size() < caps.vertices) {
                    const Point a = g.vertices[wrap_index(i, g.vertices.size())];
                    const Point b = g.vertices[wrap_index(j, g.vertices.size())];
                    g.vertices.push_back({a.x + along * (b.x - a.x), a.y + along * (b.y - a.y)});
                }
                have_half = false;
                continue;
            } else if (t.is_word("offset")) {
                in.next();
                offset_x = in.number_or(offset_x);
                offset_y = in.number_or(offset_y);
                continue;
            } else {
                break;  // the harness's part of the input
            }
            in.next();
            have_half = false;
            continue;
        }
        const double v = in.next().number;
        if (!have_half) {
            half = v;
            have_half = true;
            continue;
        }
        have_half = false;
        if (edges) {
            if (g.edges.size() < caps.edges) g.edges.push_back({index_from(half), index_from(v)});
        } else if (g.vertices.size() < caps.vertices) {
            // Without an offset, keep x*S as is: 0 + -0.0 would lose the sign of -0.0.
            const double x = half * scale;
            const double y = v * scale;
            g.vertices.push_back({offset_x == 0 ? x : offset_x + x, offset_y == 0 ? y : offset_y + y});
        }
    }
    return g;
}

// g as text that decode_graph reads back exactly: every coordinate with 17
// significant digits (which round-trips any double, -0 included), a null
// index as -1 (which decodes as the null id).
inline std::string encode_graph(const PlanarGraph& g) {
    std::string out = "points";
    char buffer[64];
    for (const Point& p : g.vertices) {
        std::snprintf(buffer, sizeof buffer, " %.17g %.17g,", p.x, p.y);
        out += buffer;
    }
    out += "\nedges";
    for (const GraphEdge& e : g.edges) {
        out += e.u.is_null() ? " -1" : " " + std::to_string(e.u.index());
        out += e.v.is_null() ? " -1," : " " + std::to_string(e.v.index()) + ",";
    }
    out += "\n";
    return out;
}

}  // namespace dcel::fuzz
