#include "hikari/io/scene/json_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/io/files/printable_text.h"

namespace hikari {

std::string_view json_type_name(const nlohmann::json& v) {
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_boolean()) return "a boolean";
    if (v.is_null()) return "null";
    if (v.is_array()) return "an array";
    return "an object";
}

namespace {

size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

/// A key as a step of a JSON path: itself, or quote_token() and cut when it is too long to read.
std::string path_key(std::string_view key) {
    return key.size() > k_quoted_token_bytes ? quote_token(key, '"') : std::string(key);
}

}  // namespace

void JsonNode::fail(std::string_view message) const {
    throw InputError(printable_text(
        fmt::format("{}: {}: {}", m_file, m_path.empty() ? "(top level)" : m_path, message)));
}

bool JsonNode::has(std::string_view key) const {
    return m_value.is_object() && m_value.contains(key);
}

JsonNode JsonNode::at(std::string_view key) const {
    if (!m_value.is_object())
        fail(fmt::format("expected an object, got {}", json_type_name(m_value)));
    const std::string child =
        m_path.empty() ? path_key(key) : fmt::format("{}.{}", m_path, path_key(key));
    if (!has(key)) JsonNode(m_value, m_file, child).fail("missing (this key is required)");
    return JsonNode(m_value.find(key).value(), m_file, child);
}

JsonNode JsonNode::at(size_t i) const {
    return JsonNode(m_value.at(i), m_file, fmt::format("{}[{}]", m_path, i));
}

void JsonNode::expect_object(std::initializer_list<std::string_view> allowed) const {
    if (!m_value.is_object())
        fail(fmt::format("expected an object, got {}", json_type_name(m_value)));
    for (const auto& [key, value] : m_value.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        std::string_view closest;
        size_t best = std::numeric_limits<size_t>::max();
        for (std::string_view a : allowed) {
            const size_t d = edit_distance(key, a);
            if (d < best) best = d, closest = a;
        }
        const std::string child =
            m_path.empty() ? path_key(key) : fmt::format("{}.{}", m_path, path_key(key));
        std::string message = "unknown key";
        if (best <= 2) message += fmt::format(" (did you mean \"{}\"?)", closest);
        JsonNode(value, m_file, child).fail(message);
    }
}

void JsonNode::expect_array(size_t size) const {
    if (!m_value.is_array())
        fail(fmt::format("expected an array, got {}", json_type_name(m_value)));
    if (size != 0 && m_value.size() != size)
        fail(fmt::format("expected an array of {} elements, got {}", size, m_value.size()));
}

std::string JsonNode::as_string() const {
    if (!m_value.is_string())
        fail(fmt::format("expected a string, got {}", json_type_name(m_value)));
    return m_value.get<std::string>();
}

float JsonNode::as_number() const {
    if (!m_value.is_number())
        fail(fmt::format("expected a number, got {}", json_type_name(m_value)));
    const double v = m_value.get<double>();
    if (!std::isfinite(v)) fail("expected a finite number");
    if (std::abs(v) > std::numeric_limits<float>::max())
        fail(fmt::format("{} is too large for a 32-bit float", v));
    return static_cast<float>(v);
}

float JsonNode::as_positive() const {
    if (!m_value.is_number() || !(m_value.get<double>() > 0)) fail("expected a positive number");
    return as_number();
}

bool JsonNode::as_bool() const {
    if (!m_value.is_boolean()) fail("expected true or false");
    return m_value.get<bool>();
}

float JsonNode::as_non_negative() const {
    if (!m_value.is_number() || !(m_value.get<double>() >= 0)) fail("expected a number >= 0");
    return as_number();
}

int JsonNode::as_int(int lo, int hi) const {
    const bool integral =
        m_value.is_number_integer() ||
        (m_value.is_number_float() && std::trunc(m_value.get<double>()) == m_value.get<double>());
    if (!integral) fail(fmt::format("expected an integer from {} to {}", lo, hi));
    const double v = m_value.get<double>();
    if (v < lo || v > hi) fail(fmt::format("expected an integer from {} to {}, got {}", lo, hi, v));
    return static_cast<int>(v);
}

Vec3 JsonNode::as_vec3() const {
    if (!m_value.is_array() || m_value.size() != 3)
        fail(fmt::format("expected an array of 3 numbers, got {}", json_type_name(m_value)));
    return {at(size_t{0}).as_number(), at(1).as_number(), at(2).as_number()};
}

Vec3 JsonNode::as_direction() const {
    const Vec3 v = as_vec3();
    if (v == Vec3(0.0f)) fail("expected a non-zero direction");
    // [0, -1e-30, 0] squares to 0 in float and [0, -1e30, 0] to infinity, so normalize() would
    // give NaN or 0. Scaling by a power of two keeps the direction exactly (and changes nothing
    // for ordinary values, whose squared length is a normal float).
    const float d = dot(v, v);
    if (d >= std::numeric_limits<float>::min() && std::isfinite(d)) return v;
    const float largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return v * std::ldexp(1.0f, -std::ilogb(largest));
}

Vec3 JsonNode::as_colour() const {
    if (m_value.is_number()) return Vec3(as_non_negative());
    if (!m_value.is_array() || m_value.size() != 3)
        fail("expected an RGB colour: an array of 3 numbers >= 0 (or one number for grey)");
    return {at(size_t{0}).as_non_negative(), at(1).as_non_negative(), at(2).as_non_negative()};
}

namespace {

/// "FILE:LINE:COLUMN" of the character just before the 1-based byte offset `byte` (where
/// nlohmann's errors point: just past the offending character).
std::string text_position(std::string_view text, const std::string& file, size_t byte) {
    const size_t end = std::min(text.size(), byte == 0 ? size_t{0} : byte - 1);
    size_t line = 1, column = 1;
    for (size_t i = 0; i < end; ++i) {
        if (text[i] == '\n')
            ++line, column = 1;
        else
            ++column;
    }
    return fmt::format("{}:{}:{}", file, line, column);
}

/// A SAX handler that builds nothing and keeps where the first error is: nlohmann's
/// out_of_range errors (a number like 1e400 that overflows a double) carry no position, the
/// parse_error event of the SAX interface does.
struct ErrorPosition final : nlohmann::json_sax<nlohmann::json> {
    size_t byte = 0;
    std::string token;
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return true; }
    bool key(string_t&) override { return true; }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool parse_error(std::size_t position, const std::string& last_token,
                     const nlohmann::json::exception&) override {
        byte = position;
        token = last_token;
        return false;
    }
};

/// Whether the character nlohmann stopped at (`byte`, 1-based, just past it) opens a `//` or
/// `/*` comment: JSON (RFC 8259) has none, and a reader who wrote one deserves to be told so
/// rather than read "invalid literal".
bool is_comment_at(std::string_view text, size_t byte) {
    if (byte == 0 || byte > text.size()) return false;
    const size_t slash = text[byte - 1] == '/' ? byte - 1 : byte >= 2 ? byte - 2 : byte - 1;
    return slash + 1 < text.size() && text[slash] == '/' &&
           (text[slash + 1] == '/' || text[slash + 1] == '*');
}

}  // namespace

std::string bounded_parse_reason(std::string_view reason) {
    constexpr std::string_view k_last_read = "last read: '";
    const size_t begin = reason.find(k_last_read);
    const size_t end = reason.rfind('\'');
    if (begin == std::string_view::npos || end < begin + k_last_read.size())
        return std::string(reason);
    const size_t token = begin + k_last_read.size();
    return fmt::format("{}last read: {}{}", reason.substr(0, begin),
                       quote_token(reason.substr(token, end - token)), reason.substr(end + 1));
}

nlohmann::json parse_json(std::string_view text, const std::string& file) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        if (is_comment_at(text, e.byte))
            throw InputError(printable_text(
                fmt::format("{}: JSON has no comments ('//' or '/* */'); remove the comment, or "
                            "keep notes in a string value such as \"note\": \"...\"",
                            text_position(text, file, e.byte))));
        std::string_view reason = e.what();
        // Drop nlohmann's "[json.exception.parse_error.101] parse error at line 3, column 5: ".
        if (const size_t colon = reason.find(": "); colon != std::string_view::npos)
            reason.remove_prefix(colon + 2);
        throw InputError(printable_text(fmt::format("{}: {}", text_position(text, file, e.byte),
                                                    bounded_parse_reason(reason))));
    } catch (const nlohmann::json::out_of_range& e) {
        // Error 406, "number overflow": a number beyond a double's range, so beyond a float's.
        // The SAX position is that of the number's last character.
        ErrorPosition where;
        nlohmann::json::sax_parse(text, &where);
        if (e.id == 406 && where.byte > 0)
            throw InputError(printable_text(
                fmt::format("{}: {} is too large for a 32-bit float",
                            text_position(text, file, where.byte + 1 - where.token.size()),
                            quote_token(where.token, '\0'))));
        throw InputError(printable_text(
            fmt::format("{}: invalid JSON: {}", file, bounded_parse_reason(e.what()))));
    } catch (const nlohmann::json::exception& e) {
        throw InputError(printable_text(
            fmt::format("{}: invalid JSON: {}", file, bounded_parse_reason(e.what()))));
    }
}

}  // namespace hikari
