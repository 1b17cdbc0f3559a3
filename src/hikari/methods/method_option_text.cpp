#include "hikari/methods/method_option_text.h"

#include <charconv>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "hikari/core/error.h"

namespace hikari {

namespace {

/// `text` as a whole number, or nullopt.
std::optional<long long> whole_number(std::string_view text) {
    long long value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

/// `text` as a finite real number, or nullopt.
std::optional<double> real_number(std::string_view text) {
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

/// Fills the option's field from `text`, or throws InputError "OPTION: ...".
struct OptionSetter {
    MethodSettings& settings;
    std::string_view flag, text;

    [[noreturn]] void refuse(std::string_view takes) const {
        throw InputError(fmt::format("{}: '{}' is not {}", flag, text, takes));
    }
    int whole_in(int min, int max) const {
        const std::optional<long long> v = whole_number(text);
        if (!v || *v < min || *v > max)
            refuse(fmt::format("a whole number from {} to {}", min, max));
        return static_cast<int>(*v);
    }
    void operator()(const IntegerOption& o) const { o.field(settings) = whole_in(o.min, o.max); }
    void operator()(const OptionalIntegerOption& o) const {
        o.field(settings) = whole_in(o.min, o.max);
    }
    void operator()(const RealOption& o) const {
        const std::optional<double> v = real_number(text);
        if (!v || *v < o.min || *v > o.max)
            refuse(fmt::format("a number from {} to {}", o.min, o.max));
        o.field(settings) = static_cast<float>(*v);
    }
    void operator()(const ColorOption& o) const {
        Vec3 colour;
        std::string_view rest = text;
        for (int c = 0; c < 3; ++c) {
            const size_t comma = c < 2 ? rest.find(',') : std::string_view::npos;
            if (c < 2 && comma == std::string_view::npos) refuse("a colour R,G,B");
            const std::optional<double> v = real_number(rest.substr(0, comma));
            if (!v || *v < 0.0) refuse("a colour R,G,B of numbers >= 0");
            colour[c] = static_cast<float>(*v);
            rest = c < 2 ? rest.substr(comma + 1) : std::string_view{};
        }
        o.field(settings) = colour;
    }
    template <class T>
    void operator()(const ChoiceOption<T>& o) const {
        if (const std::optional<T> v = choice_value(o.choices, text)) {
            o.field(settings) = *v;
            return;
        }
        std::string words;
        for (const Choice<T>& c : o.choices)
            words += fmt::format("{}{}", words.empty() ? "" : ", ", c.name);
        refuse(fmt::format("one of {}", words));
    }
};

}  // namespace

std::string option_keyword(std::string_view flag) {
    while (!flag.empty() && flag.front() == '-') flag.remove_prefix(1);
    std::string keyword(flag);
    for (char& c : keyword)
        if (c == '-') c = '_';
    return keyword;
}

void set_method_option(MethodSettings& settings, const Method& method, std::string_view name,
                       std::string_view text) {
    const std::string keyword = option_keyword(name);
    std::string names;
    for (const MethodOption& option : method.options) {
        if (option_keyword(option.flag) == keyword)
            return std::visit(OptionSetter{settings, option.flag, text}, option.value);
        names += fmt::format("{}{}", names.empty() ? "" : ", ", option_keyword(option.flag));
    }
    throw InputError(
        fmt::format("method {} has no option '{}' (its options: {})", method.name, keyword, names));
}

std::string option_text_of_json(const nlohmann::json& value) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_number()) return value.dump();
    if (value.is_array()) {
        std::string text;
        for (const nlohmann::json& item : value) {
            if (!item.is_number()) throw InputError("expected a list of numbers");
            text += (text.empty() ? "" : ",") + item.dump();
        }
        return text;
    }
    throw InputError("expected a number, a word or a list of numbers");
}

}  // namespace hikari
