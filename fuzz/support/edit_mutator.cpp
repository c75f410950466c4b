#include "support/edit_mutator.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "dcel/gen/rng.hpp"
#include "support/edit_input.hpp"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace dcel::fuzz {
namespace {

constexpr std::size_t kMaxSteps = 64;  // the harness runs no more

double ulps(double v, std::int64_t k) {
    for (; k > 0; --k) v = std::nextafter(v, HUGE_VAL);
    for (; k < 0; ++k) v = std::nextafter(v, -HUGE_VAL);
    return v;
}

void put_point(ByteString& step, Point p) {
    step.resize(kStepBytes + kRawBytes);
    step[5] = static_cast<std::uint8_t>(step[5] | kRawFlag);
    std::memcpy(step.data() + kStepBytes, &p.x, sizeof p.x);
    std::memcpy(step.data() + kStepBytes + sizeof p.x, &p.y, sizeof p.y);
}

Point get_point(const ByteString& step) {
    Point p{0, 0};
    std::memcpy(&p.x, step.data() + kStepBytes, sizeof p.x);
    std::memcpy(&p.y, step.data() + kStepBytes + sizeof p.y, sizeof p.y);
    return p;
}

// A point near the start map's geometry: a vertex a few ulps off, or a
// point on or within rounding of the line through two vertices.
Point near_point(const PlanarGraph& g, gen::Rng& rng) {
    if (g.vertices.empty()) return {static_cast<double>(rng.between(-1, 7)), static_cast<double>(rng.between(-1, 7))};
    const Point a = g.vertices[rng.below(g.vertices.size())];
    const Point b = g.vertices[rng.below(g.vertices.size())];
    if (rng.chance(1, 2)) return {ulps(a.x, rng.between(-2, 2)), ulps(a.y, rng.between(-2, 2))};
    static constexpr double kFractions[] = {0.5, 1.0 / 3, 2.0 / 3, 0.25, -1, 2};
    const double t = kFractions[rng.below(std::size(kFractions))];
    return {ulps(a.x + t * (b.x - a.x), rng.between(-1, 1)), a.y + t * (b.y - a.y)};
}

ByteString random_step(const PlanarGraph& g, gen::Rng& rng) {
    ByteString s(kStepBytes);
    for (std::uint8_t& b : s) b = static_cast<std::uint8_t>(rng.next());
    s[5] = static_cast<std::uint8_t>(s[5] & ~kRawFlag);
    if (rng.chance(1, 2)) put_point(s, near_point(g, rng));
    return s;
}

void mutate_steps(EditInput& e, const PlanarGraph& start, gen::Rng& rng) {
    const std::size_t n = e.steps.size();
    auto at = [&](std::size_t bound) { return static_cast<std::ptrdiff_t>(rng.below(bound)); };
    switch (n == 0 ? 0 : rng.below(7)) {
        case 0:
            if (n < kMaxSteps) e.steps.insert(e.steps.begin() + at(n + 1), random_step(start, rng));
            break;
        case 1: e.steps.erase(e.steps.begin() + at(n)); break;
        case 2:
            if (n < kMaxSteps) e.steps.insert(e.steps.begin() + at(n + 1), e.steps[rng.below(n)]);
            break;
        case 3: std::swap(e.steps[rng.below(n)], e.steps[rng.below(n)]); break;
        case 4: {
            ByteString& s = e.steps[rng.below(n)];
            s[rng.below(kStepBytes - 1)] = static_cast<std::uint8_t>(rng.next());  // op, a, b, x or y
            break;
        }
        case 5: {
            ByteString& s = e.steps[rng.below(n)];
            if (s.size() > kStepBytes) {
                const Point p = get_point(s);
                put_point(s, rng.chance(1, 2) ? Point{ulps(p.x, rng.between(-2, 2)), p.y}
                                              : Point{p.x, ulps(p.y, rng.between(-2, 2))});
            } else {
                put_point(s, near_point(start, rng));
            }
            break;
        }
        default: {
            ByteString& s = e.steps[rng.below(n)];
            s[5] = static_cast<std::uint8_t>((s[5] & kRawFlag) | (rng.next() & ~std::uint64_t{kRawFlag} & 0xFFU));
        }
    }
}

std::size_t emit(const ByteString& bytes, std::uint8_t* out, std::size_t max_size) {
    if (bytes.empty() || bytes.size() > max_size) return 0;
    std::memcpy(out, bytes.data(), bytes.size());
    return bytes.size();
}

// The start map of e, kept for the next call: inputs that share a start
// (most, in one campaign) generate it once.
const PlanarGraph& start_of(const EditInput& e) {
    thread_local ByteString start;
    thread_local PlanarGraph graph;
    if (start.empty() || start != e.start) {
        Bytes b(e.start.data(), e.start.size());
        graph = start_graph(b);
        start = e.start;
    }
    return graph;
}

}  // namespace

std::size_t mutate_edit_input(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned int seed) {
    gen::Rng rng(seed);
    if (size == 0 || rng.chance(1, 8)) return LLVMFuzzerMutate(data, size, max_size);
    EditInput e = split_edit_input(data, size);
    if (rng.chance(1, 16)) {
        // Another start map: a generated one takes three more bytes.
        e.start.assign(1, static_cast<std::uint8_t>(rng.next()));
        if (e.start[0] % 8 >= 3) {
            for (int i = 0; i < 3; ++i) e.start.push_back(static_cast<std::uint8_t>(rng.next()));
        }
    }
    const PlanarGraph& start = start_of(e);
    for (std::uint64_t k = 1 + rng.below(3); k > 0; --k) mutate_steps(e, start, rng);
    if (const std::size_t n = emit(join_edit_input(e), data, max_size)) return n;
    return LLVMFuzzerMutate(data, size, max_size);
}

std::size_t cross_over_edit_inputs(const std::uint8_t* data1, std::size_t size1, const std::uint8_t* data2,
                                   std::size_t size2, std::uint8_t* out, std::size_t max_out, unsigned int seed) {
    gen::Rng rng(seed);
    EditInput a = split_edit_input(data1, size1);
    const EditInput b = split_edit_input(data2, size2);
    // a's start and first steps, then the last steps of b.
    a.steps.resize(rng.below(a.steps.size() + 1));
    const auto from = static_cast<std::ptrdiff_t>(rng.below(b.steps.size() + 1));
    a.steps.insert(a.steps.end(), b.steps.begin() + from, b.steps.end());
    if (a.steps.size() > kMaxSteps) a.steps.resize(kMaxSteps);
    return emit(join_edit_input(a), out, max_out);
}

}  // namespace dcel::fuzz
