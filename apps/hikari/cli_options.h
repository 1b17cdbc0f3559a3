#pragma once
// What several subcommands share on the command line: the checks of numeric options (finite, in
// range, with short messages), options that take one of a few words, `--set`, and the usage error
// found after parsing.

#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "hikari/io/scene/scene_overrides.h"
#include "hikari/methods/method_options.h"

namespace hikari::cli {

/// A command-line mistake found after parsing (an output that cannot be written): printed as
/// `hikari: error: <message>`, exit status 2.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// The largest value a real option takes: a float's, so that the value stays finite.
constexpr double k_max_real = std::numeric_limits<float>::max();
/// The smallest positive value, for options that must be above 0.
constexpr double k_least_positive = std::numeric_limits<double>::denorm_min();

/// A real option's check: a finite number in [min, max], else the short usage error
/// "--flag: expected <words>" (CLI11's Range lets NaN through and prints its bounds with all
/// 309 digits of a double's largest value). `words` defaults to the range said in words.
CLI::Validator real_in(double min, double max, std::string words = {});

/// An integer option's check: a whole number in [min, max], else "--flag: expected a whole
/// number from MIN to MAX".
CLI::Validator whole_in(int min, int max);

/// `flag`, taking one of the words of `choices` (the one table that both checks and converts
/// them) into `target`, whose value now is shown as the default.
template <class T>
CLI::Option* add_choice_option(CLI::App& app, std::string_view flag, std::string_view help,
                               std::span<const Choice<T>> choices, T& target) {
    std::vector<std::string> names;
    for (const Choice<T>& c : choices) names.emplace_back(c.name);
    return app
        .add_option_function<std::string>(
            std::string(flag),
            [choices, &target](const std::string& name) {
                target = choice_value(choices, name).value();
            },
            std::string(help))
        ->check(CLI::IsMember(names))
        ->default_str(std::string(choice_name(choices, target)));
}

/// `--max-memory GIB`, set as the process's memory limit (core/memory_budget.h) as it is parsed:
/// the subcommands that read or build large things besides `render` (explain, compare, info).
/// `what` names what it refuses in the help ("inputs and buffers").
void add_max_memory_option(CLI::App& app, std::string_view what);

/// `--set PATH=VALUE` (repeatable) into `overrides`, in order.
void add_set_option(CLI::App& app, std::vector<SceneOverride>& overrides);

}  // namespace hikari::cli
