#include "cli_options.h"

#include <cmath>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"

namespace hikari::cli {

namespace {

/// What a real option in [min, max] expects, in words for its error message.
std::string real_range_words(double min, double max) {
    if (min <= -k_max_real && max >= k_max_real) return "a finite number";
    if (max >= k_max_real) return fmt::format("a number of at least {:g}", min);
    return fmt::format("a number from {:g} to {:g}", min, max);
}

/// The same for --help, after the value's type: `FLOAT:in [0, 180]`.
std::string real_range_label(double min, double max) {
    if (min <= -k_max_real && max >= k_max_real) return "finite";
    if (min > 0 && min < 1e-30) return "> 0";
    if (max >= k_max_real) return fmt::format(">= {:g}", min);
    return fmt::format("in [{:g}, {:g}]", min, max);
}

}  // namespace

CLI::Validator real_in(double min, double max, std::string words) {
    if (words.empty()) words = real_range_words(min, max);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            double value = 0;
            if (CLI::detail::lexical_cast(text, value) && std::isfinite(value) && value >= min &&
                value <= max)
                return {};
            return "expected " + words;
        },
        real_range_label(min, max));
}

CLI::Validator whole_in(int min, int max) {
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            int value = 0;
            if (CLI::detail::lexical_cast(text, value) && value >= min && value <= max) return {};
            return fmt::format("expected a whole number from {} to {}", min, max);
        },
        fmt::format("in [{}, {}]", min, max));
}

void add_set_option(CLI::App& app, std::vector<SceneOverride>& overrides) {
    app.add_option_function<std::vector<std::string>>(
           "--set",
           [&overrides](const std::vector<std::string>& args) {
               for (const std::string& a : args) {
                   try {
                       overrides.push_back(parse_scene_override(a));
                   } catch (const InputError& e) {
                       throw CLI::ValidationError(e.what());
                   }
               }
           },
           "Override a scene value by its JSON path, as scene errors name it "
           "(--set materials.clay.shininess=5, --set camera.fov_y=30, --set "
           "objects[0].center=[0,1,0]); VALUE is JSON or a bare word (a string); repeatable")
        ->type_name("PATH=VALUE")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

void add_max_memory_option(CLI::App& app, std::string_view what) {
    app.add_option_function<double>(
           "--max-memory", [](double gib) { set_memory_limit(gib * (1 << 30)); },
           fmt::format("Refuse {} that need more than this many GiB (default: half the "
                       "machine's memory)",
                       what))
        ->check(real_in(k_least_positive, k_max_real, "a positive number of GiB"));
}

}  // namespace hikari::cli
