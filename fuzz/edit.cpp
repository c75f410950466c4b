// Fuzz target edit_sequence: compares the editor with build().
//
// Decodes the input into a start map and a sequence of edit steps. For each
// step, the oracle (tests/support/edit_oracle.hpp: build() on the graph the
// edit would make) decides whether it must succeed. If so, the edit must
// succeed and leave a DCEL that validate() accepts and that equals the
// rebuild of its own graph; if not, it must be refused with TopologyError or
// InvalidInput and leave every array as it was. Any disagreement traps.
//
// Input: byte 0 picks the start map (empty, the countries, nested squares).
// Each step then takes 6 bytes: op, a, b, x, y, flags. x and y are small
// grid coordinates (-1 .. 7); flags bits 0-1 give `at` (the new point at a
// vertex or an edge's middle), and bit 2 says 16 raw bytes follow: the point
// as two doubles (non-finite ones become 0), so exactness is fuzzed too.
// At most 64 steps: each costs a rebuild and a validation of a graph of at
// most a few hundred elements, which keeps an input well under a second.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "dcel/dump.hpp"
#include "support/edit_oracle.hpp"
#include "support/rebuild_compare.hpp"

namespace {

using namespace dcel;
using namespace dcel::testing;

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

[[noreturn]] void fail(const Step& s, const char* what, const std::string& detail) {
    std::fprintf(stderr, "edit_sequence: %s at step op=%d a=%u b=%u x=%d y=%d: %s\n", what, static_cast<int>(s.op), s.a,
                 s.b, s.x, s.y, detail.c_str());
    __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Bytes in(data, size);
    Dcel d = build(start_map(in.byte() % 3));
    for (int step = 0; step < 64 && !in.empty(); ++step) {
        Step s;
        s.op = static_cast<Op>(in.byte() % 7);
        s.a = in.byte();
        s.b = in.byte();
        s.x = in.byte() % 9 - 1;
        s.y = in.byte() % 9 - 1;
        const std::uint8_t flags = in.byte();
        s.at = flags % 3;
        if ((flags & 4U) != 0) {
            s.raw = true;
            s.exact = {in.number(), in.number()};
        }
        const Resolved r = resolve(d, s);
        if (!r.applicable) continue;
        const bool valid = expected_valid(d, s, r);
        const DcelDump before = to_dump(d);
        bool refused = false;
        std::string reason;
        try {
            (void)apply(d, s, r);
        } catch (const TopologyError& e) {
            refused = true;
            reason = e.what();
        } catch (const InvalidInput& e) {
            refused = true;
            reason = e.what();
        }
        if (refused && valid) fail(s, "refused a valid edit", reason);
        if (!refused && !valid) fail(s, "accepted an edit that build() rejects", "");
        if (refused && !same_dump(before, to_dump(d))) fail(s, "a refusal changed the DCEL", reason);
        if (!refused) {
            if (const auto problem = soundness_problem(d)) fail(s, "unsound after the edit", *problem);
        }
    }
    return 0;
}
