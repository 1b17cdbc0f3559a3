#pragma once
// Reading a parsed JSON document with errors that name the file and the JSON path of the bad
// value (`scene.json: objects[2].radius: expected a positive number`).

#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "hikari/core/vec.h"

namespace hikari {

/// A JSON value together with where it is: the file it came from and its JSON path.
class JsonNode {
  public:
    JsonNode(const nlohmann::json& value, std::string file, std::string path)
        : m_value(value), m_file(std::move(file)), m_path(std::move(path)) {}

    const nlohmann::json& value() const { return m_value; }
    const std::string& path() const { return m_path; }
    const std::string& file() const { return m_file; }

    /// Throws InputError "<file>: <path>: <message>".
    [[noreturn]] void fail(std::string_view message) const;

    bool has(std::string_view key) const;
    /// The member `key` of this object; fails when it is missing.
    JsonNode at(std::string_view key) const;
    /// Element `i` of this array.
    JsonNode at(size_t i) const;

    /// Fails unless this is an object whose keys are all in `allowed`; names the first stranger
    /// and the closest allowed key.
    void expect_object(std::initializer_list<std::string_view> allowed) const;
    /// Fails unless this is an array (of exactly `size` elements when size is not 0).
    void expect_array(size_t size = 0) const;

    std::string as_string() const;
    /// true or false.
    bool as_bool() const;
    /// A finite number.
    float as_number() const;
    /// A finite number > 0.
    float as_positive() const;
    /// A finite number >= 0.
    float as_non_negative() const;
    /// An integer in [lo, hi].
    int as_int(int lo, int hi) const;
    /// Three finite numbers.
    Vec3 as_vec3() const;
    /// Three finite numbers, not all zero; scaled by a power of two when their squared length
    /// is not a normal float, so that normalize() gives the direction for any such input.
    Vec3 as_direction() const;
    /// An RGB colour: three numbers >= 0, or one number for grey.
    Vec3 as_colour() const;

  private:
    const nlohmann::json& m_value;
    std::string m_file;
    std::string m_path;
};

/// What kind of value `v` is, for messages: "a number", "an array", "null", ...
std::string_view json_type_name(const nlohmann::json& v);

/// Parses JSON text; a syntax error becomes InputError "<file>:<line>:<column>: <reason>".
nlohmann::json parse_json(std::string_view text, const std::string& file);

/// nlohmann's parse-error reason with the token it quotes ("last read: '...'") cut by
/// quote_token(): a 200 MB number would otherwise make a 200 MB message.
std::string bounded_parse_reason(std::string_view reason);

}  // namespace hikari
