#include "diff_cases.hpp"

#include <algorithm>

namespace dcel::cli {
namespace {

// splitmix64's finaliser: neighbouring (seed, i) give unrelated seeds.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30U)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27U)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31U);
}

}  // namespace

CaseSpec case_spec(std::uint64_t run_seed, std::size_t i, std::size_t max_vertices) {
    const auto families = gen::all_families();
    const std::size_t round = i / families.size();
    CaseSpec spec;
    spec.number = i;
    spec.params.family = families[i % families.size()];
    // Small graphs first: most bugs show on a handful of vertices, and a
    // failure found small needs little shrinking.
    spec.params.vertices = std::clamp<std::size_t>(2 + 3 * round, 1, std::max<std::size_t>(max_vertices, 1));
    spec.params.seed = mix(mix(run_seed) ^ i);
    return spec;
}

}  // namespace dcel::cli
