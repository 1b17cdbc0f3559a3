#include "hikari/io/models/mtl_scan.h"

#include <algorithm>
#include <charconv>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/models/text_number.h"

namespace hikari {

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, uint32_t line, std::string_view what) {
    throw InputError(printable_text(fmt::format("{}:{}: {}", file.string(), line, what)));
}

bool is_blank(char c) { return c == ' ' || c == '\t'; }

/// The whitespace-separated words of `line`.
std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> words;
    for (size_t i = 0; i < line.size();) {
        while (i < line.size() && is_blank(line[i])) ++i;
        const size_t begin = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        if (i > begin) words.push_back(line.substr(begin, i - begin));
    }
    return words;
}

/// Checks `count_min` to `count_max` numbers after the keyword (words[0]).
void check_floats(const std::filesystem::path& file, uint32_t line,
                  const std::vector<std::string_view>& words, size_t count_min, size_t count_max) {
    const size_t count = words.size() - 1;
    if (count < count_min || count > count_max)
        fail(file, line,
             count_min == count_max
                 ? fmt::format("{} needs {} number, found {}", quote_token(words[0]), count_min,
                               count)
                 : fmt::format("{} needs {} to {} numbers, found {}", quote_token(words[0]),
                               count_min, count_max, count));
    for (size_t k = 1; k < words.size(); ++k) {
        std::string why;
        if (!parse_float_token(words[k], &why))
            fail(file, line, fmt::format("{}: {}", quote_token(words[0]), why));
    }
}

void check_illum(const std::filesystem::path& file, uint32_t line,
                 const std::vector<std::string_view>& words) {
    int value = -1;
    const std::string_view word = words.size() == 2 ? words[1] : std::string_view{};
    const auto [stop, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || ec != std::errc() || stop != word.data() + word.size() || value < 0 ||
        value > 10)
        fail(file, line,
             fmt::format("'illum' needs one integer from 0 to 10, found {}",
                         quote_token(words.size() > 1 ? words[1] : std::string_view{})));
}

}  // namespace

uint32_t MtlMaterialLines::line_of(std::string_view keyword) const {
    const auto found = std::find_if(statements.rbegin(), statements.rend(),
                                    [&](const auto& s) { return s.first == keyword; });
    return found != statements.rend() ? found->second : line;
}

std::vector<MtlMaterialLines> scan_mtl_text(const std::filesystem::path& file,
                                            std::string_view text) {
    std::vector<MtlMaterialLines> materials;
    size_t pos = 0;
    for (uint32_t line = 1; pos < text.size(); ++line) {
        size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view s = text.substr(pos, end - pos);
        pos = end + ((end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ? 2 : 1);
        s = s.substr(0, s.find('\0'));  // tinyobjloader parses C strings
        const std::vector<std::string_view> words = words_of(s);
        if (words.empty() || words[0].starts_with('#')) continue;
        const std::string_view keyword = words[0];
        if (keyword == "newmtl") {
            // tinyobjloader takes the rest of the line as the name.
            const size_t name_start = s.find_first_not_of(" \t", s.find("newmtl") + 6);
            materials.push_back(
                {std::string(name_start == std::string_view::npos ? "" : s.substr(name_start)),
                 line,
                 {}});
            continue;
        }
        if (keyword == "Ka" || keyword == "Kd" || keyword == "Ks" || keyword == "Ke" ||
            keyword == "Tf" || keyword == "Kt") {
            check_floats(file, line, words, 1, 3);
        } else if (keyword == "Ns" || keyword == "Ni" || keyword == "Tr") {
            check_floats(file, line, words, 1, 1);
        } else if (keyword == "d") {
            // "d -halo FACTOR" (the MTL specification's halo dissolve) reads FACTOR.
            std::vector<std::string_view> rest = words;
            if (rest.size() > 1 && rest[1] == "-halo") rest.erase(rest.begin() + 1);
            check_floats(file, line, rest, 1, 1);
        } else if (keyword == "illum") {
            check_illum(file, line, words);
        }
        if (!materials.empty()) materials.back().statements.emplace_back(keyword, line);
    }
    return materials;
}

}  // namespace hikari
