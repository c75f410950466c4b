// The custom mutators' promises, checked without libFuzzer (ctest
// fuzz.mutators): from every seed of corpus/oracle and corpus/nonplanar,
// chains of Validity::Keep mutations and cross-overs give only valid
// graphs within the limits; Validity::Break mutations give graphs that
// decode back exactly from their text; the edit inputs split and join back
// to the same bytes, before and after mutation, and every step the mutator
// writes is whole. Prints what the mutations made, so a mutator that stops
// reaching something (near-degenerate points, defects) shows.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "oracles/brute_force.hpp"
#include "oracles/exact.hpp"
#include "support/edit_input.hpp"
#include "support/edit_mutator.hpp"
#include "support/graph_input.hpp"
#include "support/graph_mutator.hpp"
#include "support/text_graph.hpp"

// libFuzzer's byte mutations, which the edit mutator may call: not here.
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* /*data*/, std::size_t size, std::size_t /*max_size*/) { return size; }

namespace {

using namespace dcel;
using namespace dcel::fuzz;

int failures = 0;

void expect(bool ok, const std::string& what) {
    if (ok) return;
    std::fprintf(stderr, "FAILED: %s\n", what.c_str());
    ++failures;
}

std::vector<std::string> inputs(const char* harness) {
    std::vector<std::string> out;
    const std::filesystem::path dir = std::filesystem::path(DCEL_CORPUS_DIR) / harness;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        out.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    return out;
}

bool same_bits(const PlanarGraph& a, const PlanarGraph& b) {
    if (a.vertices.size() != b.vertices.size() || a.edges != b.edges) return false;
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
        const Point p = a.vertices[i], q = b.vertices[i];
        if (std::bit_cast<std::uint64_t>(p.x) != std::bit_cast<std::uint64_t>(q.x) ||
            std::bit_cast<std::uint64_t>(p.y) != std::bit_cast<std::uint64_t>(q.y)) {
            return false;
        }
    }
    return true;
}

PlanarGraph reread(const PlanarGraph& g, const GraphLimits& limits) {
    const std::string text = encode_graph(g);  // the reader holds a view of it
    TokenReader in(text);
    return decode_graph(in, {limits.vertices + 1, limits.edges + 1});
}

// Near-collinear triples among a graph's vertices: orientation zero or one
// whose floating-point determinant is below its rounding error.
std::size_t near_collinear(const PlanarGraph& g) {
    std::size_t n = 0;
    const std::size_t v = std::min<std::size_t>(g.vertices.size(), 24);
    for (std::size_t a = 0; a < v; ++a) {
        for (std::size_t b = a + 1; b < v; ++b) {
            for (std::size_t c = b + 1; c < v; ++c) {
                const Point p = g.vertices[a], q = g.vertices[b], r = g.vertices[c];
                const double det = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
                const double scale = std::fabs((q.x - p.x) * (r.y - p.y)) + std::fabs((q.y - p.y) * (r.x - p.x));
                n += std::fabs(det) <= 0x1p-50 * scale ? 1 : 0;
            }
        }
    }
    return n;
}

void graphs_stay_valid() {
    constexpr GraphLimits kLimits{120, 360};
    const GraphInputCaps caps{40, 32, {kLimits.vertices, kLimits.edges}};
    std::size_t mutations = 0, collinear = 0, max_vertices = 0;
    std::uint64_t seed = 1;
    std::vector<PlanarGraph> pool;
    for (const std::string& text : inputs("oracle")) {
        PlanarGraph g = decode_graph_input(text, caps).graph;
        if (!is_valid(g)) continue;  // a regression input may hold an invalid graph on purpose
        for (int round = 0; round < 60; ++round) {
            gen::Rng rng(seed++);
            const PlanarGraph before = g;
            const bool changed = round % 10 == 9 && !pool.empty()
                                     ? cross_over(g, pool[rng.below(pool.size())], rng, Validity::Keep, kLimits)
                                     : mutate_graph(g, rng, Validity::Keep, kLimits);
            mutations += changed ? 1 : 0;
            expect(is_valid(g), "a Keep mutation made an invalid graph from " + encode_graph(before));
            expect(g.vertices.size() <= kLimits.vertices && g.edges.size() <= kLimits.edges, "over the limits");
            expect(same_bits(reread(g, kLimits), g), "the text of a mutated graph does not read back exactly");
            collinear += near_collinear(g);
            max_vertices = std::max(max_vertices, g.vertices.size());
        }
        pool.push_back(g);
    }
    std::printf("keep: %zu mutations, %zu near-collinear triples seen, up to %zu vertices\n", mutations, collinear,
                max_vertices);
    expect(mutations > 500 && collinear > 100, "the Keep mutations reach too little");
}

void graphs_break() {
    constexpr GraphLimits kLimits{48, 96};
    oracle::DefectKinds seen;
    std::uint64_t seed = 1000;
    for (const std::string& text : inputs("nonplanar")) {
        TokenReader in(text);
        PlanarGraph g = decode_graph(in, {kLimits.vertices, kLimits.edges});
        for (int round = 0; round < 40; ++round) {
            gen::Rng rng(seed++);
            (void)mutate_graph(g, rng, Validity::Break, kLimits);
            expect(g.vertices.size() <= kLimits.vertices && g.edges.size() <= kLimits.edges, "over the limits (break)");
            const PlanarGraph again = reread(g, kLimits);
            expect(again.edges == g.edges && again.vertices.size() == g.vertices.size(), "break text does not read back");
            seen |= oracle::find_defects(g).kinds();
        }
    }
    std::printf("break: defect kinds made: %s\n", oracle::describe(seen).c_str());
    expect(seen.count() >= 6, "the Break mutations make too few kinds of defect");
}

void edit_inputs_keep_their_steps() {
    std::uint64_t seed = 5000;
    std::size_t raw_steps = 0;
    for (const std::string& text : inputs("edit")) {
        std::vector<std::uint8_t> bytes(text.begin(), text.end());
        for (int round = 0; round < 50; ++round) {
            std::vector<std::uint8_t> buffer = bytes;
            buffer.resize(4096);
            buffer.resize(mutate_edit_input(buffer.data(), bytes.size(), buffer.size(), static_cast<unsigned>(seed++)));
            bytes = buffer;
            const EditInput e = split_edit_input(bytes.data(), bytes.size());
            const ByteString joined = join_edit_input(e);
            expect(joined.size() >= bytes.size() && std::equal(bytes.begin(), bytes.end(), joined.begin()),
                   "splitting and joining an edit input changed it");
            for (const ByteString& s : e.steps) {
                expect(s.size() == kStepBytes || s.size() == kStepBytes + kRawBytes, "a broken step");
                raw_steps += s.size() > kStepBytes ? 1 : 0;
            }
        }
    }
    std::printf("edit: %zu raw steps written\n", raw_steps);
    expect(raw_steps > 100, "the edit mutator writes too few raw points");
}

}  // namespace

int main() {
    graphs_stay_valid();
    graphs_break();
    edit_inputs_keep_their_steps();
    std::printf("%s\n", failures == 0 ? "mutators: all promises kept" : "mutators: FAILED");
    return failures == 0 ? 0 : 1;
}
