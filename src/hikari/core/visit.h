#pragma once
// std::visit for the closed sets of plain structs (lights, textures): a chain of index tests the
// compiler turns into a switch, with no function-pointer table and no exception path, so SIMD
// kernels may use it per chunk of lanes.

#include <cstddef>
#include <type_traits>
#include <utility>
#include <variant>

#include "hikari/core/lanes.h"

namespace hikari {

namespace detail {
template <class Variant, class Function, size_t... Kind>
HIKARI_INLINE HIKARI_HD decltype(auto) visit_kind(const Variant& v, Function&& f,
                                                  std::index_sequence<Kind...>) {
    using Result = decltype(f(*std::get_if<0>(&v)));
    if constexpr (std::is_void_v<Result>) {
        ((v.index() == Kind ? (f(*std::get_if<Kind>(&v)), 0) : 0), ...);
    } else {
        Result result{};
        ((v.index() == Kind ? (result = f(*std::get_if<Kind>(&v)), 0) : 0), ...);
        return result;
    }
}
}  // namespace detail

/// `f(alternative)` for the alternative `v` holds; every alternative must give the same type.
template <class Variant, class Function>
HIKARI_INLINE HIKARI_HD decltype(auto) visit_kind(const Variant& v, Function&& f) {
    return detail::visit_kind(v, std::forward<Function>(f),
                              std::make_index_sequence<std::variant_size_v<Variant>>());
}

/// One callable made of several lambdas, one per alternative: `Overloaded{[](const A&) {...},
/// [](const B&) {...}}`. Visiting with it fails to compile when an alternative has no lambda.
template <class... Lambdas>
struct Overloaded : Lambdas... {
    using Lambdas::operator()...;
};
template <class... Lambdas>
Overloaded(Lambdas...) -> Overloaded<Lambdas...>;

}  // namespace hikari
