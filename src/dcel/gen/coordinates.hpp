// Coordinate classes: the magnitudes and forms of the doubles in a graph, so
// that `dcel diff` can put every generated graph into each class (and a user
// can leave a class out to look past a known failure at the rest).
//
//   small-integers  integers of magnitude below 2^31
//   normal          other normal doubles: fractions, and large offsets with
//                   small differences (3.7e15 + 1)
//   huge            some magnitude above 2^500 (1e150 and up, to 1e308)
//   tiny            some nonzero magnitude below 2^-500, all normal
//   subnormal       some nonzero magnitude below 2^-1022 (denormals)
//
// A graph's class is the most exotic class of its coordinates, in the order
// subnormal, tiny, huge, normal, small-integers. Negative zero is in every
// class: it is zero.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "dcel/graph.hpp"

namespace dcel::gen {

enum class CoordinateClass : std::uint8_t { SmallIntegers, Normal, Huge, Tiny, Subnormal };

[[nodiscard]] std::span<const CoordinateClass> all_coordinate_classes();
[[nodiscard]] std::string_view coordinate_class_name(CoordinateClass c);  // "small-integers", ...
[[nodiscard]] std::optional<CoordinateClass> coordinate_class_from_name(std::string_view name);

[[nodiscard]] CoordinateClass classify(const PlanarGraph& g);

// g (integer coordinates of magnitude below 2^31) mapped into class c by an
// exact map that keeps every orientation: a power-of-two scaling, then for
// `normal` an exact translation; some zeros become -0.0. nullopt when the
// graph is not of that form (its class is then its own). Deterministic in seed.
[[nodiscard]] std::optional<PlanarGraph> to_coordinate_class(const PlanarGraph& g, CoordinateClass c, std::uint64_t seed);

}  // namespace dcel::gen
