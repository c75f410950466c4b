// The custom mutator and cross-over of the graph harnesses (oracle,
// nonplanar), which read a graph from text: libFuzzer calls
// LLVMFuzzerCustomMutator and LLVMFuzzerCustomCrossOver instead of its byte
// mutations; these decode the input, change the graph itself
// (graph_mutator.hpp) and write it back as text (text_graph.hpp). Now and
// then, and whenever the input does not decode, they hand over to
// libFuzzer's own byte mutations (LLVMFuzzerMutate), which keep exploring
// the text: recipe words, numbers, comments.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

#include "dcel/gen/rng.hpp"
#include "support/graph_mutator.hpp"
#include "support/text_graph.hpp"

// libFuzzer's byte mutations (a replay build links a stand-in that never runs).
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace dcel::fuzz {

// Reads a harness input as a graph the mutator may change; nothing when
// the input is not one (the byte mutations take over).
using GraphDecoder = std::optional<PlanarGraph> (*)(std::string_view text);

struct GraphFuzzing {
    GraphDecoder decode;
    Validity validity;
    GraphLimits limits;
};

// Copies text into the output buffer if it fits; its size, or 0.
inline std::size_t emit(const std::string& text, std::uint8_t* out, std::size_t max_size) {
    if (text.empty() || text.size() > max_size) return 0;
    std::memcpy(out, text.data(), text.size());
    return text.size();
}

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// DCEL_FUZZ_BYTE_MUTATIONS=1 in the environment turns the structural
// mutations off (libFuzzer's own only), to measure what they bring on the
// same binary.
inline bool byte_mutations_only() {
    static const bool only = [] {
        const char* v = std::getenv("DCEL_FUZZ_BYTE_MUTATIONS");
        return v != nullptr && std::string_view(v) == "1";
    }();
    return only;
}

// The body of LLVMFuzzerCustomMutator: one to four structural mutations.
inline std::size_t mutate_input(const GraphFuzzing& f, std::uint8_t* data, std::size_t size, std::size_t max_size,
                                unsigned int seed) {
    gen::Rng rng(seed);
    if (!byte_mutations_only() && !rng.chance(1, 8)) {
        if (std::optional<PlanarGraph> g = f.decode(as_text(data, size))) {
            bool changed = false;
            for (std::uint64_t n = 1 + rng.below(4); n > 0; --n)
                changed = mutate_graph(*g, rng, f.validity, f.limits) || changed;
            if (changed) {
                if (const std::size_t written = emit(encode_graph(*g), data, max_size)) return written;
            }
        }
    }
    return LLVMFuzzerMutate(data, size, max_size);
}

// The body of LLVMFuzzerCustomCrossOver: a component of the second input
// copied into the first.
inline std::size_t cross_over_inputs(const GraphFuzzing& f, const std::uint8_t* data1, std::size_t size1,
                                     const std::uint8_t* data2, std::size_t size2, std::uint8_t* out, std::size_t max_out,
                                     unsigned int seed) {
    if (byte_mutations_only()) return 0;
    gen::Rng rng(seed);
    std::optional<PlanarGraph> a = f.decode(as_text(data1, size1));
    const std::optional<PlanarGraph> b = f.decode(as_text(data2, size2));
    if (a && b && cross_over(*a, *b, rng, f.validity, f.limits)) return emit(encode_graph(*a), out, max_out);
    return 0;  // no cross-over: libFuzzer tries another mutation
}

}  // namespace dcel::fuzz

// Defines libFuzzer's two hooks for a harness, with its GraphFuzzing.
#define DCEL_GRAPH_FUZZER_HOOKS(fuzzing)                                                                              \
    extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,        \
                                                   unsigned int seed) {                                               \
        return dcel::fuzz::mutate_input(fuzzing, data, size, max_size, seed);                                         \
    }                                                                                                                 \
    extern "C" std::size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* data1, std::size_t size1,                    \
                                                     const std::uint8_t* data2, std::size_t size2, std::uint8_t* out, \
                                                     std::size_t max_out, unsigned int seed) {                        \
        return dcel::fuzz::cross_over_inputs(fuzzing, data1, size1, data2, size2, out, max_out, seed);                \
    }
