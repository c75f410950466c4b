#include "dcel/diff/schedule.hpp"
#include "dcel/gen/session.hpp"

#include <algorithm>
#include <array>

namespace dcel::diff {
namespace {

// splitmix64's finaliser: neighbouring (seed, i) give unrelated seeds.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30U)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27U)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31U);
}

constexpr std::size_t kLargeEvery = 50;

// The families whose large graphs have large shapes, in the order large cases
// take them: degree, long cycles, many faces, many components.
constexpr std::array<gen::Family, 9> kLarge{
    gen::Family::Star,           gen::Family::Tree,           gen::Family::Triangulation,
    gen::Family::NestedPolygons, gen::Family::CollinearChain, gen::Family::Comb,
    gen::Family::GridWithHoles,  gen::Family::RandomSegments, gen::Family::Components,
};

// Small integers 4, normal 3, huge 1, tiny 1, subnormal 1, among the allowed.
gen::CoordinateClass draw_class(const Schedule& s, std::uint64_t seed) {
    static constexpr std::array<std::uint64_t, 5> kWeight{4, 3, 1, 1, 1};
    std::uint64_t total = 0;
    for (const gen::CoordinateClass c : gen::all_coordinate_classes()) {
        if (s.allows(c)) total += kWeight[static_cast<std::size_t>(c)];
    }
    std::uint64_t pick = mix(seed) % std::max<std::uint64_t>(total, 1);
    for (const gen::CoordinateClass c : gen::all_coordinate_classes()) {
        if (!s.allows(c)) continue;
        const std::uint64_t w = kWeight[static_cast<std::size_t>(c)];
        if (pick < w) return c;
        pick -= w;
    }
    return gen::CoordinateClass::SmallIntegers;
}

}  // namespace

std::vector<gen::Family> Schedule::chosen_families() const {
    if (!families.empty()) return families;
    const auto all = gen::all_families();
    return {all.begin(), all.end()};
}

bool Schedule::allows(gen::CoordinateClass c) const {
    return classes.empty() || std::find(classes.begin(), classes.end(), c) != classes.end();
}

CaseSpec case_spec(const Schedule& s, std::size_t i) {
    const std::vector<gen::Family> families = s.chosen_families();
    const std::size_t round = i / families.size();
    const std::uint64_t seed = mix(mix(s.seed) ^ i);
    CaseSpec spec;
    spec.number = i;
    spec.params.seed = seed;
    spec.params.family = families[i % families.size()];
    // Small graphs first: most bugs show on a handful of vertices, and a
    // failure found small needs little shrinking.
    spec.params.vertices = std::clamp<std::size_t>(2 + 3 * round, 1, std::max<std::size_t>(s.max_vertices, 1));
    if (s.large_vertices > 0 && i % kLargeEvery == kLargeEvery - 1) {
        std::vector<gen::Family> large;
        for (const gen::Family f : kLarge) {
            if (std::find(families.begin(), families.end(), f) != families.end()) large.push_back(f);
        }
        if (!large.empty()) {
            spec.large = true;
            spec.params.family = large[(i / kLargeEvery) % large.size()];
            spec.params.vertices = s.large_vertices;
        }
    }
    spec.coordinate_seed = mix(seed ^ 0xc00dULL);
    const bool first_round = i < families.size();
    spec.coordinates = first_round && s.allows(gen::CoordinateClass::SmallIntegers) ? gen::CoordinateClass::SmallIntegers
                                                                                    : draw_class(s, spec.coordinate_seed);
    const std::uint64_t spelling_seed = mix(seed ^ 0x5be11ULL);
    spec.spelling = first_round || mix(spelling_seed) % 10 < 4 ? gen::Spelling::plain()
                                                               : gen::Spelling::random(spelling_seed, s.one_line);
    // The positional form only when asked for: many programs read the object
    // form alone, which is what the protocol promises by default. Dropped
    // after the draw, so that every case is the same with and without it.
    if (!s.positional) spec.spelling.positional = false;
    return spec;
}

namespace {

// A session case: the case's graph (its family, size and coordinate class)
// as the start, and steps drawn against the reference.
std::optional<Case> make_session_case(const Schedule& s, Case c) {
    const std::size_t round = c.spec.number / s.chosen_families().size();
    gen::SessionParams p;
    p.graph = c.spec.params;
    p.seed = mix(c.spec.params.seed ^ 0x5e55ULL);
    p.steps = c.spec.large ? s.large_steps : std::min<std::size_t>(1 + 2 * round, std::max<std::size_t>(s.max_steps, 1));
    if (c.spec.params.family != gen::Family::NearDegenerate) p.coordinates = c.spec.coordinates;
    check::Session session = gen::generate_session(p);
    session.each_step = s.each_step;
    c.coordinates = gen::classify(session.start);
    if (!s.allows(c.coordinates)) return std::nullopt;
    c.graph = session.start;
    c.text = spell(session);
    c.session = std::move(session);
    return c;
}

}  // namespace

std::optional<Case> make_case(const Schedule& s, std::size_t i) {
    Case c;
    c.spec = case_spec(s, i);
    if (s.sessions) return make_session_case(s, std::move(c));
    gen::Params p = c.spec.params;
    // Near-degenerate graphs come with their own coordinates: a few tries for
    // one in an allowed class. Every other family gives small integers, which
    // are then mapped into the class the case asks for.
    for (int attempt = 0; attempt < 16; ++attempt) {
        PlanarGraph g = gen::generate(p);
        if (std::optional<PlanarGraph> mapped = gen::to_coordinate_class(g, c.spec.coordinates, c.spec.coordinate_seed)) {
            g = std::move(*mapped);
        }
        c.coordinates = gen::classify(g);
        if (s.allows(c.coordinates)) {
            c.spec.params = p;
            c.graph = std::move(g);
            c.text = spell(c.graph, c.spec);
            return c;
        }
        p.seed = mix(p.seed);
    }
    return std::nullopt;
}

std::string spell(const PlanarGraph& g, const CaseSpec& spec) { return gen::write_spelled(g, spec.spelling); }

std::string spell(const check::Session& s) { return check::write_session(s); }

}  // namespace dcel::diff
