// The generators' own PRNG: xoshiro256** seeded through splitmix64. The
// standard distributions are implementation-defined, so every draw here is
// built from raw 64-bit words: the same seed gives the same graph everywhere.
// That also needs one draw per statement: two draws in the arguments of one
// call, or as the operands of one operator, come in an order the compiler
// picks (gcc and clang differ), and so would the graph. The test gen.digests
// compares the generated graphs with digests recorded from another compiler.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace dcel::gen {

class Rng {
public:
    explicit Rng(std::uint64_t seed) {
        for (std::uint64_t& s : state_) s = splitmix64(seed);
    }

    std::uint64_t next() {
        const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
        const std::uint64_t t = state_[1] << 17;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= t;
        state_[3] = rotl(state_[3], 45);
        return result;
    }

    // Uniform in [0, n) for n > 0, by rejection (no modulo bias).
    std::uint64_t below(std::uint64_t n) {
        const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
        std::uint64_t x = next();
        while (x >= limit) x = next();
        return x % n;
    }

    // Uniform in [lo, hi], both included; lo <= hi, hi - lo < 2^63.
    std::int64_t between(std::int64_t lo, std::int64_t hi) {
        return lo + static_cast<std::int64_t>(below(static_cast<std::uint64_t>(hi - lo) + 1));
    }

    // True with probability num / den.
    bool chance(std::uint64_t num, std::uint64_t den) { return below(den) < num; }

    template <class T>
    void shuffle(std::vector<T>& v) {
        for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[below(i)]);
    }

    template <class T>
    const T& pick(const std::vector<T>& v) {
        return v[below(v.size())];
    }

private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    static std::uint64_t splitmix64(std::uint64_t& x) {
        std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

    std::uint64_t state_[4]{};
};

}  // namespace dcel::gen
