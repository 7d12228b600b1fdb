#pragma once
#include <cstdint>

namespace polar::game {

// A small deterministic random number generator (PCG32: a 64-bit LCG with a permuted 32-bit output).
//
// Why not <random>? The standard distributions are implementation-defined, so the same seed gives
// different games under libstdc++ and libc++. Everything here is integer arithmetic, and the doubles
// are built from integers exactly, so a seed means the same game everywhere.
class Rng {
  public:
    explicit Rng(std::uint64_t seed = 1) { reseed(seed); }

    void reseed(std::uint64_t seed) {
        state_ = 0;
        next();
        state_ += seed;
        next();
    }

    std::uint32_t next() {
        std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + kIncrement;
        auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, 1), 32 bits of resolution.
    double uniform() { return next() * (1.0 / 4294967296.0); }
    // Uniform in [lo, hi).
    double range(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; the tiny bias is irrelevant here).
    std::uint32_t below(std::uint32_t n) {
        return static_cast<std::uint32_t>((std::uint64_t{next()} * n) >> 32);
    }
    bool chance(double p) { return uniform() < p; }

    std::uint64_t state() const { return state_; }
    // Puts back a state() read earlier (snapshots).
    void restore(std::uint64_t state) { state_ = state; }

  private:
    static constexpr std::uint64_t kIncrement = 1442695040888963407ull;
    std::uint64_t state_ = 0;
};

}  // namespace polar::game
