#pragma once
// The number types that shading code is written over: `float` for one point, or `LaneFloat`, a
// pack of 4, 8 or 16 floats that SIMD code computes together. Code templated on its number type F
// (shading/, integrators/) then runs the same source for one ray or for a block of rays, as
// Mitsuba 3's `Float` and Embree's templated kernels do; the pack's operations are the float
// operations lane by lane, so both give bit-identical results (no FMA contraction anywhere).
//
// The packs are GCC vector extensions, which the compiler lowers to SSE, AVX2 or AVX-512 by the
// target of the function it inlines them into. `Isa` is a tag type that each SIMD kernel file
// declares in an anonymous namespace: every template instantiated on its packs then has internal
// linkage, so the AVX-512 build of a function can never be merged with (and replace) the
// portable one of the same name.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "hikari/core/host_device.h"

#define HIKARI_INLINE [[gnu::always_inline]] inline

namespace hikari {

/// The most lanes in a pack (AVX-512's sixteen floats): one chunk of a block of rays
/// (core/block_lanes.h) is one pack or several narrower ones.
inline constexpr int k_max_lanes = 16;

namespace detail {
// The vector types of the packs, by width. They are spelled out one width at a time because GCC
// ignores vector_size on a dependent type.
template <int Width>
struct LaneVectors;
#define HIKARI_LANE_VECTORS(width)                                     \
    template <>                                                        \
    struct LaneVectors<width> {                                        \
        using Float = float __attribute__((vector_size(4 * (width)))); \
        using Int = int32_t __attribute__((vector_size(4 * (width)))); \
    };
HIKARI_LANE_VECTORS(16)
HIKARI_LANE_VECTORS(8)
HIKARI_LANE_VECTORS(4)
#undef HIKARI_LANE_VECTORS
template <>
struct LaneVectors<2> {
    using Int = int32_t __attribute__((vector_size(8)));
};
}  // namespace detail

/// A pack of values, lane by lane: `V` is one of detail::LaneVectors' types. `Isa` is the tag
/// of the kernel file that uses it; its k_width (16, 8 or 4) is the width of the target's vector
/// registers, which the compiler then uses whole (a pack wider than the registers would be
/// split, and some of its operations done one lane at a time).
template <class V, class Isa>
struct LaneVector {
    using Vector = V;
    using Element = std::remove_cvref_t<decltype(V{}[0])>;
    static constexpr int k_width = sizeof(V) / sizeof(Element);
    Vector v;

    /// Uninitialised, as a float local is: a pack built to be assigned costs no stores.
    HIKARI_INLINE LaneVector() {}  // NOLINT(modernize-use-equals-default): must stay user-provided
    HIKARI_INLINE constexpr LaneVector(Element s) : v(Vector{} + s) {}  // NOLINT: a broadcast
    HIKARI_INLINE constexpr explicit LaneVector(Vector w) : v(w) {}

    /// The lanes of an array of k_width values aligned to the pack's size.
    HIKARI_INLINE static LaneVector load(const Element* p) {
        LaneVector r;
        std::memcpy(&r.v, p, sizeof r.v);
        return r;
    }
    HIKARI_INLINE void store(Element* p) const { std::memcpy(p, &v, sizeof v); }
    HIKARI_INLINE Element operator[](int i) const { return v[i]; }
};

/// Isa::k_width floats.
template <class Isa>
using LaneFloat = LaneVector<typename detail::LaneVectors<Isa::k_width>::Float, Isa>;
/// Isa::k_width 32-bit integers.
template <class Isa>
using LaneInt = LaneVector<typename detail::LaneVectors<Isa::k_width>::Int, Isa>;

/// Isa::k_width booleans, each all ones (true) or all zeros (false), as vector compares give.
template <class Isa>
struct LaneMask {
    using Vector = typename detail::LaneVectors<Isa::k_width>::Int;
    static constexpr int k_width = Isa::k_width;
    Vector v;

    HIKARI_INLINE LaneMask() {}  // NOLINT(modernize-use-equals-default): uninitialised
    HIKARI_INLINE constexpr LaneMask(bool s) : v(Vector{} + (s ? -1 : 0)) {}  // NOLINT
    HIKARI_INLINE constexpr explicit LaneMask(Vector w) : v(w) {}

    /// The lanes of an array of k_width ints: true where nonzero.
    HIKARI_INLINE static LaneMask load(const int32_t* p) {
        return LaneMask(LaneInt<Isa>::load(p).v != 0);
    }
    /// 1 where true, 0 where false, into an array of k_width ints.
    HIKARI_INLINE void store(int32_t* p) const { LaneInt<Isa>(v & 1).store(p); }
    HIKARI_INLINE bool operator[](int i) const { return v[i] != 0; }
};

// Arithmetic, lane by lane. (The macro names templates, which cannot be parenthesised.)
// NOLINTBEGIN(bugprone-macro-parentheses)
#define HIKARI_LANE_BINARY(Type, Result, op)                                        \
    template <class Isa>                                                            \
    HIKARI_INLINE Result<Isa> operator op(const Type<Isa>& a, const Type<Isa>& b) { \
        return Result<Isa>(a.v op b.v);                                             \
    }                                                                               \
    template <class Isa, class S>                                                   \
    requires std::is_arithmetic_v<S> HIKARI_INLINE Result<Isa>                      \
    operator op(const Type<Isa>& a, S b) { return a op Type<Isa>(b); }              \
    template <class Isa, class S>                                                   \
    requires std::is_arithmetic_v<S> HIKARI_INLINE Result<Isa>                      \
    operator op(S a, const Type<Isa>& b) { return Type<Isa>(a) op b; }
HIKARI_LANE_BINARY(LaneFloat, LaneFloat, +)
HIKARI_LANE_BINARY(LaneFloat, LaneFloat, -)
HIKARI_LANE_BINARY(LaneFloat, LaneFloat, *)
HIKARI_LANE_BINARY(LaneFloat, LaneFloat, /)
HIKARI_LANE_BINARY(LaneFloat, LaneMask, <)
HIKARI_LANE_BINARY(LaneFloat, LaneMask, <=)
HIKARI_LANE_BINARY(LaneFloat, LaneMask, >)
HIKARI_LANE_BINARY(LaneFloat, LaneMask, >=)
HIKARI_LANE_BINARY(LaneFloat, LaneMask, ==)
HIKARI_LANE_BINARY(LaneFloat, LaneMask, !=)
HIKARI_LANE_BINARY(LaneInt, LaneInt, +)
HIKARI_LANE_BINARY(LaneInt, LaneInt, -)
HIKARI_LANE_BINARY(LaneInt, LaneInt, &)
HIKARI_LANE_BINARY(LaneInt, LaneInt, |)
HIKARI_LANE_BINARY(LaneInt, LaneInt, ^)
HIKARI_LANE_BINARY(LaneInt, LaneMask, <)
HIKARI_LANE_BINARY(LaneInt, LaneMask, ==)
HIKARI_LANE_BINARY(LaneInt, LaneMask, !=)
HIKARI_LANE_BINARY(LaneMask, LaneMask, &)
HIKARI_LANE_BINARY(LaneMask, LaneMask, |)
HIKARI_LANE_BINARY(LaneMask, LaneMask, ^)
#undef HIKARI_LANE_BINARY
// NOLINTEND(bugprone-macro-parentheses)

/// Each lane shifted right by the same count (one instruction; a pack of counts would be built
/// lane by lane).
template <class Isa>
HIKARI_INLINE LaneInt<Isa> operator>>(const LaneInt<Isa>& a, int count) {
    return LaneInt<Isa>(a.v >> count);
}

template <class Isa>
HIKARI_INLINE LaneFloat<Isa> operator-(const LaneFloat<Isa>& a) {
    return LaneFloat<Isa>(-a.v);
}
template <class Isa>
HIKARI_INLINE LaneMask<Isa> operator!(const LaneMask<Isa>& a) {
    return LaneMask<Isa>(~a.v);
}
template <class Isa>
HIKARI_INLINE LaneFloat<Isa>& operator+=(LaneFloat<Isa>& a, const LaneFloat<Isa>& b) {
    return a = a + b;
}
template <class Isa>
HIKARI_INLINE LaneInt<Isa>& operator+=(LaneInt<Isa>& a, const LaneInt<Isa>& b) {
    return a = a + b;
}

// What shading code needs besides arithmetic, for each number type: the scalar forms first.

/// The integer and boolean types that go with number type F.
template <class F>
struct NumberTypes {
    using Int = int32_t;
    using Mask = bool;
};
template <class Isa>
struct NumberTypes<LaneFloat<Isa>> {
    using Int = LaneInt<Isa>;
    using Mask = LaneMask<Isa>;
};
template <class F>
using IntOf = typename NumberTypes<F>::Int;
template <class F>
using MaskOf = typename NumberTypes<F>::Mask;

/// True for float (one point at a time), false for packs.
template <class F>
inline constexpr bool k_is_scalar = std::is_same_v<F, float>;

/// `a` where `m`, else `b`.
HIKARI_INLINE HIKARI_HD float select(bool m, float a, float b) { return m ? a : b; }
HIKARI_INLINE HIKARI_HD int32_t select(bool m, int32_t a, int32_t b) { return m ? a : b; }
HIKARI_INLINE HIKARI_HD bool select(bool m, bool a, bool b) { return m ? a : b; }
template <class Isa>
HIKARI_INLINE LaneFloat<Isa> select(const LaneMask<Isa>& m, const LaneFloat<Isa>& a,
                                    const LaneFloat<Isa>& b) {
    return LaneFloat<Isa>(m.v ? a.v : b.v);
}
template <class Isa>
HIKARI_INLINE LaneInt<Isa> select(const LaneMask<Isa>& m, const LaneInt<Isa>& a,
                                  const LaneInt<Isa>& b) {
    return LaneInt<Isa>(m.v ? a.v : b.v);
}
template <class Isa>
HIKARI_INLINE LaneMask<Isa> select(const LaneMask<Isa>& m, const LaneMask<Isa>& a,
                                   const LaneMask<Isa>& b) {
    return LaneMask<Isa>(m.v ? a.v : b.v);
}

namespace detail {
/// The two halves of `v` OR-ed together.
template <class Half, class Vector>
HIKARI_INLINE Half fold_halves(const Vector& v) {
    Half low, high;
    std::memcpy(&low, &v, sizeof low);
    std::memcpy(&high, reinterpret_cast<const char*>(&v) + sizeof low, sizeof high);
    return low | high;
}
}  // namespace detail

/// The lanes of an integer vector OR-ed together: halves folded onto each other (a few
/// shuffles, where a loop over the lanes extracts them one by one).
template <int Width>
HIKARI_INLINE int32_t or_lanes(const typename detail::LaneVectors<Width>::Int& v) {
    if constexpr (Width == 2)
        return v[0] | v[1];
    else
        return or_lanes<Width / 2>(
            detail::fold_halves<typename detail::LaneVectors<Width / 2>::Int>(v));
}

/// Whether any lane is true.
HIKARI_INLINE HIKARI_HD bool any(bool m) { return m; }
template <class Isa>
HIKARI_INLINE bool any(const LaneMask<Isa>& m) {
    return or_lanes<Isa::k_width>(m.v) != 0;
}

/// The correctly rounded square root (the SIMD instruction rounds as sqrtf does).
HIKARI_INLINE HIKARI_HD float sqrt_of(float a) { return std::sqrt(a); }
template <class Isa>
HIKARI_INLINE LaneFloat<Isa> sqrt_of(const LaneFloat<Isa>& a) {
    LaneFloat<Isa> r;
    for (int i = 0; i < Isa::k_width; ++i) r.v[i] = __builtin_sqrtf(a.v[i]);
    return r;
}

/// |a|.
HIKARI_INLINE HIKARI_HD float abs_of(float a) { return std::fabs(a); }
template <class Isa>
HIKARI_INLINE LaneFloat<Isa> abs_of(const LaneFloat<Isa>& a) {
    using Bits = typename LaneInt<Isa>::Vector;
    return LaneFloat<Isa>(reinterpret_cast<typename LaneFloat<Isa>::Vector>(
        reinterpret_cast<Bits>(a.v) & 0x7fffffff));
}

/// static_cast<int32_t>(a): truncation toward zero (a must be in int32_t's range).
HIKARI_INLINE HIKARI_HD int32_t truncate_to_int(float a) { return static_cast<int32_t>(a); }
template <class Isa>
HIKARI_INLINE LaneInt<Isa> truncate_to_int(const LaneFloat<Isa>& a) {
    return LaneInt<Isa>(__builtin_convertvector(a.v, typename LaneInt<Isa>::Vector));
}
/// static_cast<float>(a).
HIKARI_INLINE HIKARI_HD float to_float(int32_t a) { return static_cast<float>(a); }
template <class Isa>
HIKARI_INLINE LaneFloat<Isa> to_float(const LaneInt<Isa>& a) {
    return LaneFloat<Isa>(__builtin_convertvector(a.v, typename LaneFloat<Isa>::Vector));
}

/// The bits of a float as an integer, and back (std::bit_cast, lane by lane).
HIKARI_INLINE HIKARI_HD int32_t float_bits(float a) {
#if HIKARI_DEVICE_PASS
    return __float_as_int(a);
#else
    return __builtin_bit_cast(int32_t, a);
#endif
}
template <class Isa>
HIKARI_INLINE LaneInt<Isa> float_bits(const LaneFloat<Isa>& a) {
    return LaneInt<Isa>(reinterpret_cast<typename LaneInt<Isa>::Vector>(a.v));
}
HIKARI_INLINE HIKARI_HD float bits_float(int32_t a) {
#if HIKARI_DEVICE_PASS
    return __int_as_float(a);
#else
    return __builtin_bit_cast(float, a);
#endif
}
template <class Isa>
HIKARI_INLINE LaneFloat<Isa> bits_float(const LaneInt<Isa>& a) {
    return LaneFloat<Isa>(reinterpret_cast<typename LaneFloat<Isa>::Vector>(a.v));
}

/// A mask as the integer 1 (true) or 0 (false) in each lane.
HIKARI_INLINE HIKARI_HD int32_t mask_to_int(bool m) { return m ? 1 : 0; }
template <class Isa>
HIKARI_INLINE LaneInt<Isa> mask_to_int(const LaneMask<Isa>& m) {
    return LaneInt<Isa>(m.v & 1);
}

/// Calls `f(value, lanes, first)` once for each distinct value of `index` (in order of first
/// appearance), with the mask of the lanes that hold it (`first` for the first value): a
/// uniform value (a material, a light) can then be read once and broadcast into its lanes. For
/// a scalar, once with `true, true`. GCC vectorises such selects but emulates table lookups one
/// lane at a time.
template <class Function>
HIKARI_INLINE HIKARI_HD void for_each_distinct(int32_t index, Function&& f) {
    f(index, true, true);
}
/// Bit i set where lane i is true.
template <class Isa>
HIKARI_INLINE uint32_t lane_bits(const LaneMask<Isa>& m) {
    typename LaneMask<Isa>::Vector bit;
    for (int i = 0; i < Isa::k_width; ++i) bit[i] = 1 << i;
    return static_cast<uint32_t>(or_lanes<Isa::k_width>(m.v & bit));
}

template <class Isa, class Function>
HIKARI_INLINE void for_each_distinct(const LaneInt<Isa>& index, Function&& f) {
    uint32_t left = (1u << Isa::k_width) - 1;
    for (bool first = true; left != 0; first = false) {
        const int32_t value = index.v[__builtin_ctz(left)];
        const LaneMask<Isa> mine = index == value;
        f(value, mine, first);
        left &= ~lane_bits(mine);
    }
}

}  // namespace hikari
