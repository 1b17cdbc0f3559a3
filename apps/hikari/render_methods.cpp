#include "render_methods.h"

#include <algorithm>
#include <optional>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli_options.h"

namespace hikari::cli {

namespace {

/// A method option whose value is an integer in a range.
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option,
                               const IntegerOption& integer, MethodSettings& own) {
    return app.add_option(std::string(option.flag), integer.field(own), std::string(option.help))
        ->check(whole_in(integer.min, integer.max))
        ->capture_default_str();
}

/// A method option whose value is an integer in a range, unset unless given.
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option,
                               const OptionalIntegerOption& integer, MethodSettings& own) {
    std::optional<int>& target = integer.field(own);
    return app
        .add_option_function<int>(
            std::string(option.flag), [&target](int value) { target = value; },
            std::string(option.help))
        ->check(whole_in(integer.min, integer.max));
}

/// A method option whose value is a real number in a range.
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option, const RealOption& real,
                               MethodSettings& own) {
    return app.add_option(std::string(option.flag), real.field(own), std::string(option.help))
        ->check(real_in(real.min, real.max))
        ->capture_default_str();
}

/// A method option whose value is a colour R,G,B.
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option, const ColorOption& color,
                               MethodSettings& own) {
    std::optional<Vec3>& target = color.field(own);
    return app
        .add_option_function<std::vector<float>>(
            std::string(option.flag),
            [&target](const std::vector<float>& rgb) { target = Vec3(rgb[0], rgb[1], rgb[2]); },
            std::string(option.help))
        ->delimiter(',')
        ->expected(3)
        ->type_name("R,G,B")
        ->check(real_in(0, k_max_real, "a colour component of at least 0"));
}

/// A method option whose value is one of a few words.
template <class T>
CLI::Option* add_method_option(CLI::App& app, const MethodOption& option,
                               const ChoiceOption<T>& choice, MethodSettings& own) {
    return add_choice_option(app, option.flag, option.help, choice.choices, choice.field(own));
}

/// The methods that understand the option `flag`, e.g. "zbuffer, scanline".
std::string methods_taking(std::string_view flag) {
    std::vector<std::string_view> names;
    for (const Method& m : methods())
        if (takes_option(m, flag)) names.push_back(m.name);
    return fmt::format("{}", fmt::join(names, ", "));
}

/// The options of `method`, e.g. "--spp, --max-depth".
std::string option_list(const Method& method) {
    std::vector<std::string_view> flags;
    for (const MethodOption& option : method.options) flags.push_back(option.flag);
    return fmt::format("{}", fmt::join(flags, ", "));
}

/// A usage error (CLI::ValidationError) when an option's value is one `method` cannot take (a
/// shadow mode it cannot do, no camera ray).
void check_method_values(const Method& method, const MethodSettings& own) {
    if (method.refuse_values)
        if (const std::string refusal = method.refuse_values(own); !refusal.empty())
            throw CLI::ValidationError(refusal);
    if (own.shadows && takes_option(method, "--shadows") && !does_shadows(method, *own.shadows))
        throw CLI::ValidationError(
            fmt::format("--shadows {}: method {} cannot draw shadows that way (it can: {})",
                        choice_name<std::optional<ShadowMode>>(k_shadow_choices, own.shadows),
                        method.name, shadow_mode_list(method)));
}

/// A usage error (CLI::ValidationError) when the command line gives an option that `method`
/// does not understand, or a value it cannot take.
void check_method_options(const CLI::App& render, const Method& method, const MethodSettings& own) {
    for (const MethodOption* option : method_options()) {
        if (render.count(std::string(option->flag)) == 0 || takes_option(method, option->flag))
            continue;
        throw CLI::ValidationError(fmt::format(
            "{} is not an option of method {} ({})", option->flag, method.name,
            method.options.empty() ? "it takes none" : "it understands: " + option_list(method)));
    }
    check_method_values(method, own);
}

/// Refuses, before any work is done, an algorithm AOV of a method that does not have it, and a
/// shading term of a method whose colour is not the lecture's sum of terms (path tracing, the
/// line drawings).
void check_aov_method(const Method& method, Aov aov) {
    if (is_algorithm_aov(aov) && !has_algorithm_aov(method, aov))
        throw CLI::ValidationError(fmt::format("--aov {} shows the work of {}, not of method {}",
                                               aov_name(aov), methods_with_algorithm_aov(aov),
                                               method.name));
    if (!shading_term_of(aov) || method.shading_terms) return;
    throw CLI::ValidationError(
        fmt::format("--aov {}: method {} does not shade by ambient + diffuse + specular (Fig "
                    "4.29), so it has no such term (methods that do: {})",
                    aov_name(aov), method.name, shading_term_methods()));
}

/// With several methods: an option none of them takes is a usage error; one that some do not
/// take is a note, as they render without it.
void check_shared_options(const CLI::App& render, RenderOptions& o) {
    for (const MethodOption* option : method_options()) {
        if (render.count(std::string(option->flag)) == 0) continue;
        std::vector<std::string_view> ignoring;
        for (const std::string& name : o.methods)
            if (!takes_option(*find_method(name), option->flag)) ignoring.push_back(name);
        if (ignoring.size() == o.methods.size())
            throw CLI::ValidationError(
                fmt::format("{} is not an option of any method asked for "
                            "(it is for: {})",
                            option->flag, methods_taking(option->flag)));
        if (!ignoring.empty())
            o.notes.push_back(fmt::format("{} is not an option of {}, which render without it",
                                          option->flag, fmt::join(ignoring, ", ")));
    }
}

}  // namespace

void add_method_options(CLI::App& render, MethodSettings& own) {
    for (const MethodOption* option : method_options())
        std::visit(
            [&](const auto& value) {
                add_method_option(render, *option, value, own)
                    ->group("Options of " + methods_taking(option->flag));
            },
            option->value);
}

std::string method_list() {
    std::string text = "Methods (and the options each understands beside the common ones):\n";
    for (const Method& m : methods()) {
        text += fmt::format("  {:<16}{}\n", m.name, m.summary);
        if (!m.options.empty()) text += fmt::format("  {:<16}options: {}\n", "", option_list(m));
    }
    return text;
}

void check_render_methods(const CLI::App& render, RenderOptions& o) {
    for (const std::string& name : o.methods) {
        if (std::count(o.methods.begin(), o.methods.end(), name) > 1)
            throw CLI::ValidationError(fmt::format("-m: method {} is named twice", name));
        check_aov_method(*find_method(name), o.aov);
        if (o.wireframe_overlay && find_method(name)->draw)
            throw CLI::ValidationError(fmt::format(
                "--wireframe-overlay draws over a shaded image; {} draws lines already", name));
    }
    if (o.methods.size() == 1) {
        check_method_options(render, *find_method(o.methods.front()), o.own);
        return;
    }
    check_shared_options(render, o);
    for (const std::string& name : o.methods) check_method_values(*find_method(name), o.own);
}

}  // namespace hikari::cli
