#include "hikari/io/files/frame_pattern.h"

#include <fmt/format.h>

namespace hikari {

namespace {

/// The width N of a frame number spec at `spec` (just after its `%`): `d` (0) or `0Nd`; -1 if it
/// is neither. `length` gets the characters it takes after the `%`.
int spec_digits(std::string_view spec, size_t& length) {
    if (spec.starts_with("d")) {
        length = 1;
        return 0;
    }
    if (spec.size() >= 3 && spec[0] == '0' && spec[1] >= '1' && spec[1] <= '9' && spec[2] == 'd') {
        length = 3;
        return spec[1] - '0';
    }
    return -1;
}

}  // namespace

std::string FramePattern::file_name(int frame) const {
    return fmt::format("{}{:0{}d}{}", before, frame, digits, after);
}

std::optional<FramePattern> parse_frame_pattern(std::string_view pattern, std::string& why) {
    FramePattern parsed;
    bool found = false;
    std::string* text = &parsed.before;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            *text += pattern[i];
            continue;
        }
        const std::string_view rest = pattern.substr(i + 1);
        if (rest.starts_with("%")) {
            *text += '%';
            ++i;
            continue;
        }
        size_t length = 0;
        const int digits = spec_digits(rest, length);
        if (digits < 0 || found) {
            why = digits < 0 ? fmt::format(
                                   "'%' at character {} is not %d, %0Nd (N from 1 to 9) "
                                   "or %% (a literal %)",
                                   i + 1)
                             : "it has two frame numbers; give one, such as %04d";
            return std::nullopt;
        }
        found = true;
        parsed.digits = digits;
        text = &parsed.after;
        i += length;
    }
    if (!found) {
        why =
            "it has no frame number; put %04d (or %d) where each frame's number goes, as in "
            "out/frame_%04d.png";
        return std::nullopt;
    }
    return parsed;
}

}  // namespace hikari
