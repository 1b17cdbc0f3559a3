#include "hikari/session/frame_selection.h"

#include <charconv>
#include <limits>

namespace hikari {

namespace {

/// A whole number from 0 filling all of `text`.
std::optional<int> whole_number(std::string_view text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0)
        return std::nullopt;
    return value;
}

}  // namespace

std::optional<FrameRange> parse_frame_range(std::string_view text, std::string& why) {
    const size_t dash = text.find('-');
    const std::optional<int> first = whole_number(text.substr(0, dash));
    const std::optional<int> last =
        dash == std::string_view::npos ? first : whole_number(text.substr(dash + 1));
    if (!first || !last) {
        why = "expected frame numbers A-B (whole numbers from 0, such as 0-119), or one frame A";
        return std::nullopt;
    }
    if (*last < *first) {
        why = "the last frame comes before the first";
        return std::nullopt;
    }
    return FrameRange{*first, *last};
}

std::optional<FrameShard> parse_frame_shard(std::string_view text, std::string& why) {
    const size_t slash = text.find('/');
    const std::optional<int> index = whole_number(text.substr(0, slash));
    const std::optional<int> count =
        slash == std::string_view::npos ? std::nullopt : whole_number(text.substr(slash + 1));
    if (!index || !count || *count == 0) {
        why = "expected I/N, shard I of N (whole numbers, N at least 1), such as 0/4";
        return std::nullopt;
    }
    if (*index >= *count) {
        why = "shards are numbered 0 to N-1";
        return std::nullopt;
    }
    return FrameShard{*index, *count};
}

std::vector<int> shard_frames(FrameRange range, FrameShard shard) {
    std::vector<int> frames;
    for (long long f = static_cast<long long>(range.first) + shard.index; f <= range.last;
         f += shard.count)
        frames.push_back(static_cast<int>(f));
    return frames;
}

}  // namespace hikari
