#pragma once
// Low-discrepancy samples for the path tracer: the first two dimensions of Sobol' (1967)
// sequence, Owen-scrambled and shuffled by hashing (Burley 2020, "Practical Hash-based Owen
// Scrambling", JCGT 9(4)). Every pair of dimensions a path consumes (pixel position, light
// choice, BSDF direction, ...) is its own scrambled (0, 2)-sequence, decorrelated from the
// others by a seed: the first 2^k samples of a pixel stratify the square in every elementary
// interval of area 2^-k, and each pixel's sequence is independent of the others'. Samples
// depend only on (pixel, sample index, dimension), never on the thread that draws them.

#include <cstdint>

#include "hikari/core/vec.h"

namespace hikari {

/// A 32-bit integer hash with good avalanche (Wellons' "lowbias32", 2020).
constexpr uint32_t hash_u32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

/// Two values hashed into one.
constexpr uint32_t hash_combine(uint32_t seed, uint32_t value) {
    return hash_u32(seed ^ (value + 0x9e3779b9U + (seed << 6) + (seed >> 2)));
}

/// The bits of x in reverse order (bit 0 becomes bit 31).
constexpr uint32_t reverse_bits(uint32_t x) {
    x = ((x >> 1) & 0x55555555U) | ((x & 0x55555555U) << 1);
    x = ((x >> 2) & 0x33333333U) | ((x & 0x33333333U) << 2);
    x = ((x >> 4) & 0x0f0f0f0fU) | ((x & 0x0f0f0f0fU) << 4);
    x = ((x >> 8) & 0x00ff00ffU) | ((x & 0x00ff00ffU) << 8);
    return (x >> 16) | (x << 16);
}

/// The Laine–Karras permutation with Burley's constants: a hash in which each bit depends only
/// on the bits below it. Applied to a bit-reversed fraction it flips each bit by a hash of the
/// bits above it: Owen's nested uniform scramble.
constexpr uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cU;
    x ^= x * 0xb82f1e52U;
    x ^= x * 0xc7afe638U;
    x ^= x * 0x8d22f6e6U;
    return x;
}

/// Owen's nested uniform scramble of a 32-bit fraction, bits read from the most significant.
constexpr uint32_t owen_scramble(uint32_t x, uint32_t seed) {
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

/// Sobol' dimension 0 (van der Corput in base 2): the index's bits mirrored into a fraction.
constexpr uint32_t sobol_dimension0(uint32_t index) { return reverse_bits(index); }

/// Sobol' dimension 1 (primitive polynomial x + 1), bit-reversed: its direction numbers
/// v_k = v_{k−1} ^ (v_{k−1} >> 1), v_0 = 2^31 (the columns of the Pascal matrix mod 2), read
/// from the other end.
constexpr uint32_t sobol_dimension1_reversed(uint32_t index) {
    uint32_t result = 0;
    for (uint32_t v = 1U; index != 0; index >>= 1, v ^= v << 1)
        if ((index & 1U) != 0) result ^= v;
    return result;
}

/// Sobol' dimension 1 as a fraction.
constexpr uint32_t sobol_dimension1(uint32_t index) {
    return reverse_bits(sobol_dimension1_reversed(index));
}

/// A 32-bit fraction as a float in [0, 1) (its top 24 bits).
constexpr float fraction_to_float(uint32_t x) {
    return static_cast<float>(x >> 8) * (1.0f / 16777216.0f);
}

/// The samples of one pixel: sample `index` of the pixel seeded `pixel_seed`, each dimension
/// pair its own scrambled sequence. The index is itself Owen-scrambled per pair (Burley's
/// shuffling), so pairs do not line up with each other.
/// The scrambles are written in the bit-reversed domain, where owen_scramble(sobol_dimension0(i))
/// is reverse_bits(laine_karras_permutation(i)): three bit reversals per pair instead of seven.
class SobolSampler {
  public:
    constexpr SobolSampler(uint32_t pixel_seed, uint32_t index)
        : m_seed(pixel_seed), m_reversed_index(reverse_bits(index)) {}

    /// The next pair of dimensions: a point of the unit square.
    constexpr Vec2 next_2d() {
        const uint32_t seed = hash_combine(m_seed, m_dimension++);
        const uint32_t shuffled = shuffled_index(seed);
        const uint32_t x =
            reverse_bits(laine_karras_permutation(shuffled, hash_u32(seed ^ 0x63d83595U)));
        const uint32_t y = reverse_bits(laine_karras_permutation(
            sobol_dimension1_reversed(shuffled), hash_u32(seed ^ 0x8f2a1d47U)));
        return {fraction_to_float(x), fraction_to_float(y)};
    }

    /// The next single dimension: a number in [0, 1).
    constexpr float next_1d() {
        const uint32_t seed = hash_combine(m_seed, m_dimension++);
        return fraction_to_float(
            reverse_bits(laine_karras_permutation(shuffled_index(seed), hash_u32(seed))));
    }

  private:
    /// owen_scramble(index) for the pair seeded `seed`.
    constexpr uint32_t shuffled_index(uint32_t seed) const {
        return reverse_bits(
            laine_karras_permutation(m_reversed_index, hash_u32(seed ^ 0xa511e9b3U)));
    }

    uint32_t m_seed;
    uint32_t m_reversed_index;
    uint32_t m_dimension = 0;
};

}  // namespace hikari
