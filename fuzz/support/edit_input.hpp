// The edit harness's input (fuzz/edit.cpp) as a structure: the start map's
// bytes, then the steps, each 6 bytes (op, a, b, x, y, flags) and, when
// flags bit 2 is set, 16 more (the point as two raw doubles). The harness
// reads it with Bytes; the custom mutator (edit_mutator.hpp) splits it with
// split_edit_input, changes whole steps and joins it again.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "dcel/gen/generate.hpp"
#include "support/edit_oracle.hpp"

namespace dcel::fuzz {

// A generated start map has at most this many vertices.
constexpr std::size_t kMaxGeneratedVertices = 24;
constexpr std::uint8_t kRawFlag = 4;  // flags bit 2: 16 raw bytes follow
// flags bits 3-5 all set (one random flags byte in 8): a and b are wild ids
// (test_support::wild_id), any 32-bit id rather than one modulo the count.
constexpr std::uint8_t kWildFlags = 0x38;
constexpr std::size_t kStepBytes = 6;
constexpr std::size_t kRawBytes = 16;

// Hands out bytes, then zeros once the input is used up (empty() says so).
class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    [[nodiscard]] bool empty() const { return at_ >= size_; }
    std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
    double number() {
        double v = 0;
        std::uint8_t raw[8] = {};
        for (std::uint8_t& b : raw) b = byte();
        std::memcpy(&v, raw, sizeof v);
        return std::isfinite(v) ? v : 0.0;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

// Byte 0 picks the start map: 0 empty, 1 the countries, 2 nested squares
// (mod 8; 3..7 a generated graph: family byte, seed byte, size byte).
inline PlanarGraph start_graph(Bytes& in) {
    const int which = in.byte() % 8;
    if (which < 3) return test_support::start_map(which);
    const auto families = gen::all_families();
    gen::Params p;
    p.family = families[in.byte() % families.size()];
    p.seed = in.byte();
    p.vertices = in.byte() % (kMaxGeneratedVertices + 1);
    return gen::generate(p);
}

inline test_support::Step read_step(Bytes& in) {
    test_support::Step s;
    s.op = static_cast<test_support::Op>(in.byte() % 7);
    s.a = in.byte();
    s.b = in.byte();
    s.x = in.byte() % 9 - 1;
    s.y = in.byte() % 9 - 1;
    const std::uint8_t flags = in.byte();
    s.at = flags % 3;
    s.wild = (flags & kWildFlags) == kWildFlags;
    if ((flags & kRawFlag) != 0) {
        s.raw = true;
        s.exact = {in.number(), in.number()};
    }
    return s;
}

using ByteString = std::vector<std::uint8_t>;

struct EditInput {
    ByteString start;               // 1 or 4 bytes
    std::vector<ByteString> steps;  // 6 or 22 bytes each
};

// Splits an input the way the harness reads it (missing bytes are zeros).
inline EditInput split_edit_input(const std::uint8_t* data, std::size_t size) {
    std::size_t at = 0;
    auto take = [&](std::size_t n) {
        ByteString out(n, 0);
        for (std::size_t i = 0; i < n && at < size; ++i) out[i] = data[at++];
        return out;
    };
    EditInput e;
    e.start = take(1);
    if (e.start[0] % 8 >= 3) {
        const ByteString rest = take(3);
        e.start.insert(e.start.end(), rest.begin(), rest.end());
    }
    while (at < size) {
        ByteString step = take(kStepBytes);
        if ((step[5] & kRawFlag) != 0) {
            const ByteString raw = take(kRawBytes);
            step.insert(step.end(), raw.begin(), raw.end());
        }
        e.steps.push_back(std::move(step));
    }
    return e;
}

inline ByteString join_edit_input(const EditInput& e) {
    ByteString out = e.start;
    for (const ByteString& s : e.steps) out.insert(out.end(), s.begin(), s.end());
    return out;
}

}  // namespace dcel::fuzz
