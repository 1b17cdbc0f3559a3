#pragma once
// Numbers written as text in OBJ and MTL files, checked strictly: tinyobjloader reads a
// malformed number as 0 without a word and overflows silently.

#include <optional>
#include <string>
#include <string_view>

namespace hikari {

/// `token` as a 32-bit float: an optional '+' or '-', then a decimal number (std::from_chars),
/// with nothing after it, finite and within a float's range. Otherwise nothing, and `why` (when
/// given) says "'abc' is not a number" or "1e400 is too large for a 32-bit float".
std::optional<float> parse_float_token(std::string_view token, std::string* why = nullptr);

}  // namespace hikari
