#include "hikari/io/models/material_rules.h"

#include <cmath>

#include <fmt/format.h>

namespace hikari {

std::string_view material_field_name(MaterialField field) {
    switch (field) {
        case MaterialField::ka:
            return "ka";
        case MaterialField::kd:
            return "kd";
        case MaterialField::ks:
            return "ks";
        case MaterialField::shininess:
            return "shininess";
        case MaterialField::reflectivity:
            return "reflectivity";
        case MaterialField::transparency:
            return "transparency";
        case MaterialField::ior:
            return "ior";
        case MaterialField::emission:
            return "emission";
    }
    return "?";
}

std::optional<MaterialProblem> find_material_problem(const Material& m) {
    const auto problem = [](MaterialField field, std::string_view rule, auto value) {
        return MaterialProblem{
            field, fmt::format("{} must be {}, got {}", material_field_name(field), rule, value)};
    };
    const std::pair<MaterialField, const Vec3*> colours[] = {
        {MaterialField::ka, &m.ka},
        {MaterialField::kd, &m.kd},
        {MaterialField::ks, &m.ks},
        {MaterialField::emission, &m.emission}};
    for (const auto& [field, c] : colours)
        if (!is_finite(*c) || min_component(*c) < 0.0f)
            return problem(field, "finite and not negative",
                           fmt::format("({}, {}, {})", c->x, c->y, c->z));
    if (!std::isfinite(m.shininess) || m.shininess < 0.0f)
        return problem(MaterialField::shininess, "a finite number >= 0", m.shininess);
    if (!(m.reflectivity >= 0.0f && m.reflectivity <= 1.0f))
        return problem(MaterialField::reflectivity, "from 0 to 1", m.reflectivity);
    if (!(m.transparency >= 0.0f && m.transparency <= 1.0f))
        return problem(MaterialField::transparency, "from 0 to 1", m.transparency);
    if (!std::isfinite(m.ior) || !(m.ior > 0.0f))
        return problem(MaterialField::ior, "a finite number > 0", m.ior);
    return std::nullopt;
}

}  // namespace hikari
