#include "hikari/io/models/text_number.h"
#include "hikari/io/files/printable_text.h"

#include <charconv>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace hikari {

std::optional<float> parse_float_token(std::string_view token, std::string* why) {
    const std::string_view digits = token.starts_with('+') ? token.substr(1) : token;
    double value = 0;
    const char* const end = digits.data() + digits.size();
    const auto [stop, ec] = std::from_chars(digits.data(), end, value);
    const bool number = !digits.empty() && stop == end;
    if (number && ec == std::errc::result_out_of_range) {
        // Beyond a double's range, overflow or underflow: a negative exponent is the latter,
        // a number too small to tell from 0.
        const size_t e = digits.find_first_of("eE");
        if (e != std::string_view::npos && e + 1 < digits.size() && digits[e + 1] == '-')
            return 0.0f;
    } else if (number && ec == std::errc() && std::isfinite(value) &&
               std::abs(value) <= std::numeric_limits<float>::max()) {
        return static_cast<float>(value);
    }
    if (why) {
        const bool too_large = number && (ec == std::errc::result_out_of_range ||
                                          (std::isfinite(value) && ec == std::errc()));
        *why = too_large
                   ? fmt::format("{} is too large for a 32-bit float", quote_token(token, '\0'))
                   : fmt::format("{} is not a finite number", quote_token(token));
    }
    return std::nullopt;
}

}  // namespace hikari
