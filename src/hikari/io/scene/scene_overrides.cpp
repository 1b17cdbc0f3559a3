#include "hikari/io/scene/scene_overrides.h"

#include <cctype>
#include <charconv>
#include <optional>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/scene/json_reader.h"

namespace hikari {

namespace {

/// One step of a path: an object key or an array index.
using PathStep = std::variant<std::string, size_t>;

[[noreturn]] void fail(const SceneOverride& o, std::string_view where, std::string_view message) {
    throw InputError(printable_text(fmt::format("--set {}: {}{}{}", quote_token(o.argument, '\0'),
                                                where, where.empty() ? "" : ": ", message)));
}

bool is_bare_word(std::string_view v) {
    if (v.empty() || !std::isalpha(static_cast<unsigned char>(v[0]))) return false;
    for (const char c : v)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
            return false;
    return v != "true" && v != "false" && v != "null";
}

/// A whole string of decimal digits as an index; nullopt for anything else (or an overflow).
std::optional<size_t> parse_index(std::string_view digits) {
    size_t value = 0;
    if (digits.empty()) return std::nullopt;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
    return value;
}

/// The steps of `o.path`: "a.b[2].c" → a, b, 2, c. A '.'-separated all-digit component is an
/// index too ("objects.2.radius").
std::vector<PathStep> split_path(const SceneOverride& o) {
    std::vector<PathStep> steps;
    const std::string_view p = o.path;
    size_t i = 0;
    while (i < p.size()) {
        if (p[i] == '[') {
            const size_t close = p.find(']', i);
            const std::optional<size_t> index = close == std::string_view::npos
                                                    ? std::nullopt
                                                    : parse_index(p.substr(i + 1, close - i - 1));
            if (!index)
                fail(o, "",
                     fmt::format("{}: expected [index] at character {}", quote_token(p, '\0'),
                                 i + 1));
            steps.emplace_back(*index);
            i = close + 1;
        } else {
            const size_t end = p.find_first_of(".[", i);
            const std::string_view key =
                p.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i);
            if (key.empty())
                fail(o, "",
                     fmt::format("{}: empty key at character {}", quote_token(p, '\0'), i + 1));
            if (const std::optional<size_t> index = parse_index(key))
                steps.emplace_back(*index);
            else
                steps.emplace_back(std::string(key));
            i += key.size();
        }
        if (i < p.size() && p[i] == '.') {
            ++i;
            if (i == p.size()) fail(o, "", fmt::format("{}: ends with '.'", quote_token(p, '\0')));
        }
    }
    return steps;
}

std::string step_text(const std::string& path_so_far, const PathStep& step) {
    if (const auto* key = std::get_if<std::string>(&step))
        return path_so_far.empty() ? quote_token(*key, '\0')
                                   : path_so_far + "." + quote_token(*key, '\0');
    return fmt::format("{}[{}]", path_so_far, std::get<size_t>(step));
}

void apply_one(nlohmann::json& doc, const SceneOverride& o) {
    const std::vector<PathStep> steps = split_path(o);
    nlohmann::json* node = &doc;
    std::string where;
    for (const PathStep& step : steps) {
        if (const auto* key = std::get_if<std::string>(&step)) {
            if (node->is_null()) *node = nlohmann::json::object();
            if (!node->is_object())
                fail(o, where.empty() ? "(top level)" : where,
                     fmt::format("is {}, so it has no key {}", json_type_name(*node),
                                 quote_token(*key, '"')));
            // A missing key is added, but not a new material: a misspelt material name would
            // otherwise define an unused one and change nothing.
            if (where == "materials" && !node->contains(*key)) {
                std::string names;
                for (const auto& [name, value] : node->items())
                    names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", name);
                fail(o, where,
                     fmt::format("the scene has no material {} (it has: {})",
                                 quote_token(*key, '"'), names.empty() ? "none" : names));
            }
            node = &(*node)[*key];  // added (null) when missing
        } else {
            const size_t index = std::get<size_t>(step);
            if (!node->is_array())
                fail(o, where.empty() ? "(top level)" : where,
                     fmt::format("is {}, not an array, so [{}] names nothing",
                                 json_type_name(*node), index));
            if (index >= node->size())
                fail(o, where,
                     fmt::format("has {} element{}, so [{}] names nothing", node->size(),
                                 node->size() == 1 ? "" : "s", index));
            node = &(*node)[index];
        }
        where = step_text(where, step);
    }
    *node = o.value;
}

}  // namespace

SceneOverride parse_scene_override(std::string_view argument) {
    SceneOverride o;
    o.argument = std::string(argument);
    const size_t equals = argument.find('=');
    if (equals == std::string_view::npos) fail(o, "", "expected PATH=VALUE");
    o.path = std::string(argument.substr(0, equals));
    if (o.path.empty()) fail(o, "", "the PATH before '=' is empty");
    split_path(o);  // a malformed path is reported before any file is read
    const std::string_view value = argument.substr(equals + 1);
    if (is_bare_word(value)) {
        o.value = std::string(value);
        return o;
    }
    try {
        o.value = nlohmann::json::parse(value);
    } catch (const nlohmann::json::exception& e) {
        std::string_view reason = e.what();
        if (const size_t colon = reason.find(": "); colon != std::string_view::npos)
            reason.remove_prefix(colon + 2);
        fail(o, "",
             fmt::format("VALUE is not JSON ({}); quote a string as '\"text\"'",
                         bounded_parse_reason(reason)));
    }
    return o;
}

void apply_scene_overrides(nlohmann::json& doc, std::span<const SceneOverride> overrides) {
    for (const SceneOverride& o : overrides) apply_one(doc, o);
}

}  // namespace hikari
