#pragma once
// Deterministic random numbers: each pixel seeds its own stream, so images do not depend on
// the thread count or the order in which tiles are rendered.

#include <cstdint>

namespace hikari {

/// PCG32 (O'Neill 2014, PCG-XSH-RR 64/32): small, fast, statistically good.
class Pcg32 {
  public:
    /// A stream selected by `sequence`, started at `seed` (pcg32_srandom_r).
    constexpr Pcg32(uint64_t seed, uint64_t sequence) : m_inc((sequence << 1u) | 1u) {
        next_u32();
        m_state += seed;
        next_u32();
    }

    constexpr uint32_t next_u32() {
        const uint64_t old = m_state;
        m_state = old * 6364136223846793005ULL + m_inc;
        const auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
    }

    /// A float uniformly distributed in [0, 1), with 24 random bits.
    constexpr float next_float() {
        return static_cast<float>(next_u32() >> 8) * (1.0f / 16777216.0f);
    }

  private:
    uint64_t m_state = 0;
    uint64_t m_inc;
};

}  // namespace hikari
