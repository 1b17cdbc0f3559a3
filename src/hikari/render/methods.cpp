#include "hikari/render/methods.h"

#include <array>

#include "hikari/ray/whitted.h"

namespace hikari {

namespace {

constexpr std::array k_methods = {
    Method{"raytrace",
           "Whitted ray tracing (Alg 4.3): nearest hit, shadow rays, reflection, refraction",
           &render_whitted},
};

}  // namespace

std::span<const Method> methods() { return k_methods; }

const Method* find_method(std::string_view name) {
    for (const Method& m : k_methods)
        if (m.name == name) return &m;
    return nullptr;
}

}  // namespace hikari
