// The generator library's own contracts: shrinking yields only valid, smaller
// graphs; transforms are exact or refused; generation is deterministic.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstring>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "oracles/brute_force.hpp"
#include "oracles/exact.hpp"
#include "support/graph_case.hpp"

namespace dcel::props {
namespace {

using oracle::exact;
using oracle::find_defects;
using oracle::Rational;

std::size_t fractional_coordinates(const PlanarGraph& g) {
    std::size_t n = 0;
    for (const Point& p : g.vertices) n += (std::trunc(p.x) != p.x) + (std::trunc(p.y) != p.y);
    return n;
}

RC_GTEST_PROP(Generator, prop_shrink_candidates_are_valid_and_smaller, ()) {
    const GraphCase c = *rc::gen::scale(0.3, graphs());
    const PlanarGraph& g = c.graph;
    for (const PlanarGraph& s : gen::shrink_candidates(g)) {
        RC_ASSERT(find_defects(s).empty());
        try {
            (void)build(s);
        } catch (const InvalidInput& e) {
            RC_FAIL(std::string("a shrink candidate is invalid: ") + e.what());
        }
        // Smaller in (edges, vertices, fractional coordinates, magnitudes).
        const bool fewer_elements = s.edges.size() < g.edges.size() || s.vertices.size() < g.vertices.size();
        if (fewer_elements) {
            RC_ASSERT(s.edges.size() <= g.edges.size());
            continue;
        }
        RC_ASSERT(s.edges.size() == g.edges.size() && s.vertices.size() == g.vertices.size());
        if (fractional_coordinates(s) < fractional_coordinates(g)) continue;
        RC_ASSERT(fractional_coordinates(s) == fractional_coordinates(g));
        bool shrank = false;
        for (std::size_t v = 0; v < g.vertices.size(); ++v) {
            for (const auto& [before, after] :
                 {std::pair{g.vertices[v].x, s.vertices[v].x}, std::pair{g.vertices[v].y, s.vertices[v].y}}) {
                RC_ASSERT(std::fabs(after) <= std::fabs(before));
                shrank = shrank || std::fabs(after) < std::fabs(before);
            }
        }
        RC_ASSERT(shrank);
    }
}

Rational power_of_two(int k) {
    const oracle::BigInt p = oracle::BigInt(1) << static_cast<unsigned>(k >= 0 ? k : -k);
    return k >= 0 ? Rational(p) : Rational(oracle::BigInt(1), p);
}

RC_GTEST_PROP(Generator, prop_transforms_are_exact_or_refused, ()) {
    const GraphCase c = *graphs();
    const auto t = *rc::gen::element(gen::Transform::Translate, gen::Transform::Rotate90, gen::Transform::Mirror,
                                     gen::Transform::ScalePow2);
    const std::int64_t amount = t == gen::Transform::ScalePow2
                                    ? *rc::gen::inRange<std::int64_t>(-1100, 1101)
                                    : *rc::gen::oneOf(
                                          rc::gen::inRange<std::int64_t>(-1024, 1025),
                                          rc::gen::inRange<std::int64_t>(-(std::int64_t{1} << 56), std::int64_t{1} << 56));
    const std::optional<PlanarGraph> out = gen::apply(c.graph, t, amount);
    // The exact image of each coordinate, and whether a double holds it.
    bool representable = t != gen::Transform::Translate || std::llabs(amount) <= (std::int64_t{1} << 53);
    std::vector<std::pair<Rational, Rational>> image;
    for (const Point& p : c.graph.vertices) {
        const Rational x = exact(p.x), y = exact(p.y);
        switch (t) {
            case gen::Transform::Translate: {
                const Rational a(static_cast<long long>(amount));
                image.emplace_back(x + a, y - a);
                // IEEE addition is correctly rounded: exact iff the rounded sum equals the true one.
                const double fx = p.x + static_cast<double>(amount), fy = p.y - static_cast<double>(amount);
                representable = representable && std::isfinite(fx) && std::isfinite(fy) && exact(fx) == x + a &&
                                exact(fy) == y - a;
                break;
            }
            case gen::Transform::Rotate90: image.emplace_back(-y, x); break;
            case gen::Transform::Mirror: image.emplace_back(-x, y); break;
            case gen::Transform::ScalePow2: {
                const Rational s = power_of_two(static_cast<int>(amount));
                image.emplace_back(x * s, y * s);
                const double fx = std::ldexp(p.x, static_cast<int>(amount)), fy = std::ldexp(p.y, static_cast<int>(amount));
                representable = representable && std::isfinite(fx) && std::isfinite(fy) && exact(fx) == x * s &&
                                exact(fy) == y * s;
                break;
            }
        }
    }
    RC_ASSERT(out.has_value() == representable);
    if (!out) return;
    RC_ASSERT(out->edges == c.graph.edges);
    for (std::size_t v = 0; v < image.size(); ++v) {
        RC_ASSERT(exact(out->vertices[v].x) == image[v].first);
        RC_ASSERT(exact(out->vertices[v].y) == image[v].second);
    }
}

RC_GTEST_PROP(Generator, prop_generation_is_deterministic, ()) {
    const GraphCase c = *graphs();
    const PlanarGraph again = gen::generate(c.params);
    const PlanarGraph first = gen::generate(c.params);
    RC_ASSERT(again.edges == first.edges);
    RC_ASSERT(again.vertices.size() == first.vertices.size());
    // Bit for bit, so that -0.0 and 0.0 count as different here. memcmp
    // must not see the null data() of an empty vector, even for 0 bytes, and
    // inside RC_ASSERT `||` is captured as an overloaded operator that does
    // not short-circuit (UBSan caught that), so the test is done outside it.
    const bool same_bits = first.vertices.empty() || std::memcmp(again.vertices.data(), first.vertices.data(),
                                                                 first.vertices.size() * sizeof(Point)) == 0;
    RC_ASSERT(same_bits);
}

}  // namespace
}  // namespace dcel::props
