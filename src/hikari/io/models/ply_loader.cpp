#include "hikari/io/models/ply_loader.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

#include "hikari/core/cancel.h"
#include "hikari/core/color.h"
#include "hikari/core/error.h"
#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/memory_budget.h"
#include "hikari/core/parallel.h"
#include "hikari/core/parallel_pages.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/models/text_number.h"

namespace hikari {

namespace {

namespace fs = std::filesystem;

// --- Types of the PLY format ---------------------------------------------------------------------

enum class PlyType : uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct PlyTypeName {
    std::string_view name;
    PlyType type;
};

/// The original names (Turk 1994) and the sized ones later writers use.
constexpr std::array<PlyTypeName, 16> k_type_names = {{
    {"char", PlyType::int8},
    {"uchar", PlyType::uint8},
    {"short", PlyType::int16},
    {"ushort", PlyType::uint16},
    {"int", PlyType::int32},
    {"uint", PlyType::uint32},
    {"float", PlyType::float32},
    {"double", PlyType::float64},
    {"int8", PlyType::int8},
    {"uint8", PlyType::uint8},
    {"int16", PlyType::int16},
    {"uint16", PlyType::uint16},
    {"int32", PlyType::int32},
    {"uint32", PlyType::uint32},
    {"float32", PlyType::float32},
    {"float64", PlyType::float64},
}};

std::optional<PlyType> parse_type(std::string_view name) {
    for (const auto& [n, type] : k_type_names)
        if (n == name) return type;
    return std::nullopt;
}

std::string_view type_name(PlyType type) { return k_type_names[static_cast<size_t>(type)].name; }

constexpr size_t size_of(PlyType type) {
    constexpr std::array<size_t, 8> k_sizes = {1, 1, 2, 2, 4, 4, 4, 8};
    return k_sizes[static_cast<size_t>(type)];
}

constexpr bool is_integer(PlyType type) {
    return type != PlyType::float32 && type != PlyType::float64;
}

/// The largest value of an integer type (colours are fractions of it).
double max_of(PlyType type) {
    constexpr std::array<double, 6> k_max = {127.0,   255.0,        32767.0,
                                             65535.0, 2147483647.0, 4294967295.0};
    return k_max[static_cast<size_t>(type)];
}

double min_of(PlyType type) {
    constexpr std::array<double, 6> k_min = {-128.0, 0.0, -32768.0, 0.0, -2147483648.0, 0.0};
    return k_min[static_cast<size_t>(type)];
}

// --- Header ------------------------------------------------------------------------------------

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::float32;    ///< the value's type; for a list, its items' type
    std::optional<PlyType> count_type;  ///< set for a list: the type of its length
    bool is_list() const { return count_type.has_value(); }
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
    uint32_t line = 0;  ///< the header line declaring it, for messages

    /// The index of the property called `property_name`, or -1.
    int find(std::string_view property_name) const {
        for (size_t i = 0; i < properties.size(); ++i)
            if (properties[i].name == property_name) return static_cast<int>(i);
        return -1;
    }
    bool has_lists() const {
        return std::any_of(properties.begin(), properties.end(),
                           [](const PlyProperty& p) { return p.is_list(); });
    }
    /// Bytes of one item when it has no lists; the least it can take in binary otherwise.
    size_t min_binary_size() const {
        size_t size = 0;
        for (const auto& p : properties) size += size_of(p.is_list() ? *p.count_type : p.type);
        return size;
    }
};

struct PlyHeader {
    PlyFormat format = PlyFormat::ascii;
    std::vector<PlyElement> elements;
    size_t body_offset = 0;  ///< the byte where the body starts
    uint32_t body_line = 0;  ///< the line where the body starts (ascii)
    uint32_t end_line = 0;   ///< the line of end_header
    const PlyElement* find(std::string_view name) const {
        for (const auto& e : elements)
            if (e.name == name) return &e;
        return nullptr;
    }
};

[[noreturn]] void fail_at_line(const fs::path& file, size_t line, std::string_view what) {
    throw InputError(printable_text(fmt::format("{}:{}: {}", file.string(), line, what)));
}

[[noreturn]] void fail_at_byte(const fs::path& file, size_t byte, std::string_view what) {
    throw InputError(printable_text(fmt::format("{}: byte {}: {}", file.string(), byte, what)));
}

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const size_t begin = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > begin) words.push_back(line.substr(begin, i - begin));
    }
    return words;
}

/// `word` as a count: decimal digits only (no sign, exponent or fraction), fitting in 64 bits.
std::optional<uint64_t> parse_count(std::string_view word) {
    uint64_t value = 0;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || ec != std::errc() || end != word.data() + word.size()) return std::nullopt;
    return value;
}

/// One `property ...` line (its words after `property`).
PlyProperty parse_property(const fs::path& file, uint32_t line,
                           const std::vector<std::string_view>& words) {
    const auto type_of = [&](std::string_view word) {
        const auto type = parse_type(word);
        if (!type)
            fail_at_line(file, line, fmt::format("unknown property type {}", quote_token(word)));
        return *type;
    };
    PlyProperty property;
    if (words.size() == 3 && words[1] != "list") {
        property.type = type_of(words[1]);
        property.name = words[2];
    } else if (words.size() == 5 && words[1] == "list") {
        property.count_type = type_of(words[2]);
        if (!is_integer(*property.count_type))
            fail_at_line(file, line, "a list's length must have an integer type");
        property.type = type_of(words[3]);
        property.name = words[4];
    } else {
        fail_at_line(file, line,
                     "expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME'");
    }
    return property;
}

/// Reads the header up to and including its end_header line.
PlyHeader parse_header(const fs::path& file, std::string_view bytes,
                       std::vector<std::string>& warnings) {
    PlyHeader header;
    bool have_format = false;
    // Names seen, so that a header of a million elements or properties is not checked in
    // quadratic time. The views point into `bytes`.
    std::unordered_set<std::string_view> element_names, property_names;
    size_t unknown_lines = 0;
    size_t pos = 0;
    for (uint32_t line = 1;; ++line) {
        if (line > 1 && pos == bytes.size())
            fail_at_line(file, line - 1, "the file ends inside the header (no end_header)");
        // Lines end at \n; a \r before it is dropped (files written on Windows).
        const size_t newline = bytes.find('\n', pos);
        std::string_view text = bytes.substr(
            pos, newline == std::string_view::npos ? std::string_view::npos : newline - pos);
        if (text.ends_with('\r')) text.remove_suffix(1);
        const bool last = newline == std::string_view::npos;
        pos = last ? bytes.size() : newline + 1;

        if (line == 1) {
            if (text != "ply")
                fail_at_line(file, 1, "not a PLY file (the first line is not 'ply')");
            continue;
        }
        const auto words = split_words(text);
        const std::string_view keyword = words.empty() ? std::string_view() : words[0];
        if (keyword == "end_header" && words.size() == 1) {
            header.body_offset = pos;
            header.body_line = line + 1;
            header.end_line = line;
            break;
        }
        if (keyword == "format") {
            if (have_format) fail_at_line(file, line, "a second 'format' line");
            if (words.size() != 3 || (words[2] != "1.0" && words[2] != "1"))
                fail_at_line(file, line,
                             "expected 'format ascii|binary_little_endian|"
                             "binary_big_endian 1.0'");
            if (words[1] == "ascii") {
                header.format = PlyFormat::ascii;
            } else if (words[1] == "binary_little_endian") {
                header.format = PlyFormat::binary_little_endian;
            } else if (words[1] == "binary_big_endian") {
                header.format = PlyFormat::binary_big_endian;
            } else {
                fail_at_line(file, line, fmt::format("unknown format {}", quote_token(words[1])));
            }
            have_format = true;
        } else if (keyword == "element") {
            if (!have_format) fail_at_line(file, line, "'element' before the 'format' line");
            if (words.size() != 3) fail_at_line(file, line, "expected 'element NAME COUNT'");
            if (!element_names.insert(words[1]).second)
                fail_at_line(file, line, fmt::format("a second element {}", quote_token(words[1])));
            const auto count = parse_count(words[2]);
            if (!count)
                fail_at_line(
                    file, line,
                    fmt::format("element count {} is not a whole number", quote_token(words[2])));
            header.elements.push_back({std::string(words[1]), *count, {}, line});
            property_names.clear();
        } else if (keyword == "property") {
            if (header.elements.empty()) fail_at_line(file, line, "'property' before any element");
            PlyElement& element = header.elements.back();
            PlyProperty property = parse_property(file, line, words);
            if (!property_names.insert(words.back()).second)
                fail_at_line(file, line,
                             fmt::format("a second property {} in element {}",
                                         quote_token(property.name), quote_token(element.name)));
            element.properties.push_back(std::move(property));
        } else if (keyword != "comment" && keyword != "obj_info" && !words.empty()) {
            // Some exporters (Blender 2.4) write a free-text line without `comment`.
            if (++unknown_lines == 1)
                warnings.push_back(fmt::format("{}:{}: unknown header line ignored: {}",
                                               file.string(), line, quote_token(text)));
        }
    }
    if (unknown_lines > 1)
        warnings.push_back(fmt::format("{}: {} more unknown header lines ignored", file.string(),
                                       unknown_lines - 1));
    if (!have_format) fail_at_line(file, header.end_line, "the header has no 'format' line");
    return header;
}

/// Refuses element counts the file cannot hold, before anything is allocated for them: every
/// item takes at least its fixed-size values and list lengths (binary), or a character and a
/// separator per property (ascii).
void check_counts_fit(const fs::path& file, const PlyHeader& header, size_t body_bytes) {
    const bool ascii = header.format == PlyFormat::ascii;
    // The last ascii value needs no separator after it.
    uint64_t remaining = ascii ? body_bytes + 1 : body_bytes;
    for (const PlyElement& e : header.elements) {
        const uint64_t min_size = ascii ? 2 * e.properties.size() : e.min_binary_size();
        if (min_size == 0) continue;
        if (e.count > remaining / min_size)
            fail_at_line(file, e.line,
                         fmt::format("element {} declares {} items, more than the {} bytes "
                                     "after the header can hold",
                                     quote_token(e.name), e.count, body_bytes));
        remaining -= e.count * min_size;
    }
}

// --- What hikari takes from the elements --------------------------------------------------------

/// Where the vertex attributes hikari reads sit among the vertex element's properties (-1: none).
struct VertexSlots {
    std::array<int, 3> position{-1, -1, -1};
    std::array<int, 3> normal{-1, -1, -1};
    std::array<int, 2> uv{-1, -1};
    std::array<int, 3> color{-1, -1, -1};
    bool has_normals() const { return normal[0] >= 0; }
    bool has_uvs() const { return uv[0] >= 0; }
    bool has_colors() const { return color[0] >= 0; }
};

/// Finds the properties of `names` in `vertex`; all of them must be single values. Returns the
/// slots when all are present, -1s when none or (with a warning) only some are.
template <size_t N>
std::array<int, N> find_slots(const fs::path& file, const PlyElement& vertex,
                              const std::array<std::string_view, N>& names,
                              std::vector<std::string>& warnings) {
    std::array<int, N> slots;
    size_t found = 0;
    for (size_t i = 0; i < N; ++i) {
        slots[i] = vertex.find(names[i]);
        if (slots[i] < 0) continue;
        ++found;
        if (vertex.properties[slots[i]].is_list())
            fail_at_line(
                file, vertex.line,
                fmt::format("vertex property {} is a list, not a number", quote_token(names[i])));
    }
    if (found == N) return slots;
    if (found > 0)
        warnings.push_back(fmt::format("{}:{}: vertex has only some of {}: they are ignored",
                                       file.string(), vertex.line, fmt::join(names, ", ")));
    slots.fill(-1);
    return slots;
}

VertexSlots find_vertex_slots(const fs::path& file, const PlyElement& vertex,
                              std::vector<std::string>& warnings) {
    using Names3 = std::array<std::string_view, 3>;
    using Names2 = std::array<std::string_view, 2>;
    VertexSlots slots;
    for (std::string_view axis : {"x", "y", "z"})
        if (vertex.find(axis) < 0)
            fail_at_line(file, vertex.line,
                         fmt::format("element 'vertex' has no property '{}'", axis));
    slots.position = find_slots(file, vertex, Names3{"x", "y", "z"}, warnings);
    slots.normal = find_slots(file, vertex, Names3{"nx", "ny", "nz"}, warnings);
    for (const Names2& names :
         {Names2{"s", "t"}, Names2{"u", "v"}, Names2{"texture_u", "texture_v"},
          Names2{"texture_s", "texture_t"}}) {
        if (vertex.find(names[0]) < 0 && vertex.find(names[1]) < 0) continue;
        slots.uv = find_slots(file, vertex, names, warnings);
        break;
    }
    slots.color = find_slots(file, vertex, Names3{"red", "green", "blue"}, warnings);
    return slots;
}

/// The index list of a face or tristrips element: `vertex_indices` or `vertex_index`, a list of
/// integers.
int find_index_list(const fs::path& file, const PlyElement& element) {
    int slot = element.find("vertex_indices");
    if (slot < 0) slot = element.find("vertex_index");
    if (slot < 0)
        fail_at_line(file, element.line,
                     fmt::format("element {} has no list property 'vertex_indices'",
                                 quote_token(element.name)));
    const PlyProperty& p = element.properties[slot];
    if (!p.is_list() || !is_integer(p.type))
        fail_at_line(file, element.line,
                     fmt::format("{} of element {} must be a list of integers", quote_token(p.name),
                                 quote_token(element.name)));
    return slot;
}

/// A colour channel as a linear fraction: integers are sRGB-encoded fractions of their type's
/// maximum (8-bit colour is display-referred), floats are taken as linear already.
float color_channel(double value, PlyType type) {
    if (!is_integer(type)) return static_cast<float>(value);
    return srgb_to_linear(static_cast<float>(std::clamp(value / max_of(type), 0.0, 1.0)));
}

// --- Reading the body ---------------------------------------------------------------------------
// Two readers with one interface, so the element readers are written once: begin_item() names the
// item being read (for messages), scalar()/integer() read one value of a type, list_length() reads
// and checks a list's length, skip() passes over a property, fail() throws with the position.

template <class T>
T load_raw(const char* p, bool swap) {
    std::array<char, sizeof(T)> raw;
    std::memcpy(raw.data(), p, sizeof(T));
    if (swap) std::reverse(raw.begin(), raw.end());
    return std::bit_cast<T>(raw);
}

/// The value of `type` stored at `p` (byte-swapped when `swap`), as a double (exact for every
/// PLY type).
double load_value(const char* p, PlyType type, bool swap) {
    switch (type) {
        case PlyType::int8:
            return load_raw<int8_t>(p, swap);
        case PlyType::uint8:
            return load_raw<uint8_t>(p, swap);
        case PlyType::int16:
            return load_raw<int16_t>(p, swap);
        case PlyType::uint16:
            return load_raw<uint16_t>(p, swap);
        case PlyType::int32:
            return load_raw<int32_t>(p, swap);
        case PlyType::uint32:
            return load_raw<uint32_t>(p, swap);
        case PlyType::float32:
            return load_raw<float>(p, swap);
        case PlyType::float64:
            return load_raw<double>(p, swap);
    }
    return 0;
}

/// The item being read, for messages: "vertex 12: ".
struct ItemName {
    std::string_view element;
    uint64_t index = 0;
};

/// A binary body: values at byte offsets, byte-swapped when the file's order is not the
/// machine's; messages name the byte where the item starts.
class BinaryBody {
  public:
    BinaryBody(const fs::path& file, std::string_view bytes, size_t offset, bool swap)
        : m_file(file), m_bytes(bytes), m_pos(offset), m_swap(swap) {}

    void begin_item(std::string_view element, uint64_t index) {
        if (index % 65536 == 0) throw_if_cancelled();  // SIGINT / SIGTERM
        point_at(element, index, m_pos);
    }
    /// Names an item already taken, at `byte`, for fail().
    void point_at(std::string_view element, uint64_t index, size_t byte) {
        m_item = {element, index};
        m_item_pos = byte;
    }
    /// Returns the next `n` bytes and moves past them; fails if the file ends first.
    const char* take(uint64_t n) {
        if (n > m_bytes.size() - m_pos)
            fail(fmt::format("the file ends in the middle of it ({} bytes left, {} needed)",
                             m_bytes.size() - m_pos, n));
        const char* p = m_bytes.data() + m_pos;
        m_pos += n;
        return p;
    }
    double scalar(PlyType type) { return load_value(take(size_of(type)), type, m_swap); }
    int64_t integer(PlyType type) { return static_cast<int64_t>(scalar(type)); }
    uint64_t list_length(const PlyProperty& list) {
        const int64_t length = integer(*list.count_type);
        const uint64_t room = (m_bytes.size() - m_pos) / size_of(list.type);
        if (length < 0)
            fail(fmt::format("list {} has a negative length {}", quote_token(list.name), length));
        if (static_cast<uint64_t>(length) > room)
            fail(fmt::format("list {} has length {}, more than the {} bytes left can hold",
                             quote_token(list.name), length, m_bytes.size() - m_pos));
        return static_cast<uint64_t>(length);
    }
    void skip(const PlyProperty& p) {
        take(p.is_list() ? list_length(p) * size_of(p.type) : size_of(p.type));
    }
    [[noreturn]] void fail(std::string_view what) const {
        fail_at_byte(m_file, m_item_pos,
                     fmt::format("{} {}: {}", m_item.element, m_item.index, what));
    }
    uint32_t line() const { return 0; }
    bool swap() const { return m_swap; }
    size_t pos() const { return m_pos; }
    const char* data() const { return m_bytes.data(); }
    size_t left() const { return m_bytes.size() - m_pos; }

  private:
    const fs::path& m_file;
    std::string_view m_bytes;
    size_t m_pos;
    bool m_swap;
    ItemName m_item;
    size_t m_item_pos = 0;
};

/// An ascii body: values as whitespace-separated words (line breaks carry no meaning), read
/// with std::from_chars; messages name the line where the item starts.
class AsciiBody {
  public:
    AsciiBody(const fs::path& file, std::string_view bytes, size_t offset, uint32_t line)
        : m_file(file), m_bytes(bytes), m_pos(offset), m_line(line) {}

    void begin_item(std::string_view element, uint64_t index) {
        if (index % 65536 == 0) throw_if_cancelled();  // SIGINT / SIGTERM
        m_item = {element, index};
        skip_blanks();
        m_item_line = m_line;
    }
    double scalar(PlyType type) {
        const std::string_view word = next();
        std::string_view digits = word.starts_with('+') ? word.substr(1) : word;
        const char* const end = digits.data() + digits.size();
        if (is_integer(type)) {
            int64_t value = 0;
            const auto [stop, ec] = std::from_chars(digits.data(), end, value);
            if (digits.empty() || ec != std::errc() || stop != end || value < min_of(type) ||
                value > max_of(type))
                fail(fmt::format("{} is not a whole number of type {}", quote_token(word),
                                 type_name(type)));
            return static_cast<double>(value);
        }
        double value = 0;
        const auto [stop, ec] = std::from_chars(digits.data(), end, value);
        if (type == PlyType::float32 && !digits.empty() && stop == end &&
            (ec == std::errc() || ec == std::errc::result_out_of_range)) {
            // The text form of a float property: its range is a float's (nan and inf pass, to be
            // refused where the value is used, with its meaning).
            std::string why;
            if (std::isfinite(value) || ec != std::errc()) {
                if (const auto f = parse_float_token(word, &why)) return *f;
                fail(why);
            }
        }
        if (digits.empty() || ec != std::errc() || stop != end)
            fail(fmt::format("{} is not a number", quote_token(word)));
        return value;
    }
    int64_t integer(PlyType type) { return static_cast<int64_t>(scalar(type)); }
    uint64_t list_length(const PlyProperty& list) {
        const int64_t length = integer(*list.count_type);
        // Each item takes at least a character and a separator.
        if (length < 0)
            fail(fmt::format("list {} has a negative length {}", quote_token(list.name), length));
        if (static_cast<uint64_t>(length) > (m_bytes.size() - m_pos + 1) / 2)
            fail(fmt::format("list {} has length {}, more than the rest of the file holds",
                             quote_token(list.name), length));
        return static_cast<uint64_t>(length);
    }
    void skip(const PlyProperty& p) {
        const uint64_t count = p.is_list() ? list_length(p) : 1;
        for (uint64_t i = 0; i < count; ++i) scalar(p.type);
    }
    [[noreturn]] void fail(std::string_view what) const {
        fail_at_line(m_file, m_item_line,
                     fmt::format("{} {}: {}", m_item.element, m_item.index, what));
    }
    uint32_t line() const { return m_item_line; }
    /// The line the reader is at now.
    uint32_t current_line() const { return m_line; }
    /// Moves past blanks and line ends; true when nothing else is left.
    bool at_end() {
        skip_blanks();
        return m_pos == m_bytes.size();
    }

  private:
    static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
    void skip_blanks() {
        while (m_pos < m_bytes.size() && is_blank(m_bytes[m_pos])) {
            if (m_bytes[m_pos] == '\n') ++m_line;
            ++m_pos;
        }
    }
    std::string_view next() {
        skip_blanks();
        if (m_pos == m_bytes.size()) fail("the file ends in the middle of it");
        const size_t begin = m_pos;
        while (m_pos < m_bytes.size() && !is_blank(m_bytes[m_pos])) ++m_pos;
        return m_bytes.substr(begin, m_pos - begin);
    }

    const fs::path& m_file;
    std::string_view m_bytes;
    size_t m_pos;
    uint32_t m_line;
    ItemName m_item;
    uint32_t m_item_line = 0;
};

/// Appends one vertex from its property values (`values[k]` for property k).
template <class Body>
void add_vertex(Body& body, const PlyElement& e, const VertexSlots& s, const double* values,
                PolygonMesh& mesh) {
    const auto vec3 = [&](const std::array<int, 3>& slot) {
        return Vec3(static_cast<float>(values[slot[0]]), static_cast<float>(values[slot[1]]),
                    static_cast<float>(values[slot[2]]));
    };
    const Vec3 p = vec3(s.position);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        body.fail(fmt::format("position ({}, {}, {}) is not finite", values[s.position[0]],
                              values[s.position[1]], values[s.position[2]]));
    mesh.positions.push_back(p);
    if (s.has_normals()) mesh.normals.push_back(vec3(s.normal));
    if (s.has_uvs()) {
        const Vec2 uv{static_cast<float>(values[s.uv[0]]), static_cast<float>(values[s.uv[1]])};
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
            body.fail(fmt::format("texture coordinates ({}, {}) are not finite", values[s.uv[0]],
                                  values[s.uv[1]]));
        mesh.uvs.push_back(uv);
    }
    if (s.has_colors()) {
        Vec3 c;
        float* channels[3] = {&c.x, &c.y, &c.z};
        for (int k = 0; k < 3; ++k) {
            *channels[k] = color_channel(values[s.color[k]], e.properties[s.color[k]].type);
            if (!std::isfinite(*channels[k])) body.fail("its colour is not finite");
        }
        mesh.colors.push_back(c);
    }
}

template <class Body>
void read_vertices(Body& body, const PlyElement& e, const VertexSlots& slots, PolygonMesh& mesh) {
    std::vector<double> values(e.properties.size());
    for (uint64_t i = 0; i < e.count; ++i) {
        body.begin_item("vertex", i);
        for (size_t k = 0; k < e.properties.size(); ++k) {
            if (e.properties[k].is_list())
                body.skip(e.properties[k]);
            else
                values[k] = body.scalar(e.properties[k].type);
        }
        add_vertex(body, e, slots, values.data(), mesh);
    }
}

/// Binary vertices of fixed size (no list properties): every property's offset in the record is
/// known, so the whole element is bounds-checked once and each value is one memcpy. Positions and
/// normals stored as three consecutive native floats (the common case) are copied whole.
void read_fixed_vertices(BinaryBody& body, const PlyElement& e, const VertexSlots& slots,
                         PolygonMesh& mesh) {
    const size_t record = e.min_binary_size();
    std::vector<size_t> offsets(e.properties.size());
    for (size_t k = 1; k < offsets.size(); ++k)
        offsets[k] = offsets[k - 1] + size_of(e.properties[k - 1].type);
    const auto packed_floats = [&](const std::array<int, 3>& slot) {
        if (slot[0] < 0 || body.swap()) return false;
        for (int k = 0; k < 3; ++k)
            if (e.properties[slot[k]].type != PlyType::float32 ||
                offsets[slot[k]] != offsets[slot[0]] + 4 * k)
                return false;
        return true;
    };
    static_assert(sizeof(Vec3) == 12 && std::is_trivially_copyable_v<Vec3>);
    const bool packed_position = packed_floats(slots.position);
    const bool packed_normal = packed_floats(slots.normal);
    const bool only_position_normal = !slots.has_uvs() && !slots.has_colors() && packed_position &&
                                      (packed_normal || !slots.has_normals());

    const size_t start = body.pos();
    body.begin_item("vertex", 0);
    const char* data = body.take(e.count * record);  // one check for the whole element
    if (only_position_normal) {
        // Fast path: memcpy straight into the mesh, checking finiteness as we go.
        mesh.positions.resize(e.count);
        if (slots.has_normals()) mesh.normals.resize(e.count);
        // in parallel chunks; the first vertex that is not finite, in file order, is reported
        parallel_chunks(e.count, 65536, [&](size_t, size_t i0, size_t i1) {
            throw_if_cancelled();  // SIGINT / SIGTERM
            for (size_t i = i0; i < i1; ++i) {
                const char* r = data + i * record;
                Vec3& p = mesh.positions[i];
                std::memcpy(&p, r + offsets[slots.position[0]], sizeof(Vec3));
                if (slots.has_normals())
                    std::memcpy(&mesh.normals[i], r + offsets[slots.normal[0]], sizeof(Vec3));
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                    BinaryBody at = body;  // each chunk names its own item
                    at.point_at("vertex", i, start + i * record);
                    at.fail(fmt::format("position ({}, {}, {}) is not finite", p.x, p.y, p.z));
                }
            }
        });
        return;
    }
    std::vector<double> values(e.properties.size());
    for (uint64_t i = 0; i < e.count; ++i) {
        if (i % 65536 == 0) throw_if_cancelled();  // SIGINT / SIGTERM
        const char* r = data + i * record;
        body.point_at("vertex", i, start + i * record);
        for (size_t k = 0; k < values.size(); ++k)
            values[k] = load_value(r + offsets[k], e.properties[k].type, body.swap());
        add_vertex(body, e, slots, values.data(), mesh);
    }
}

/// Appends a face's corner count to face_start, refusing a mesh whose corners overflow 32 bits.
template <class Body>
void end_face(Body& body, PolygonMesh& mesh) {
    if (mesh.corners.size() > std::numeric_limits<uint32_t>::max())
        body.fail("more than 2^32 - 1 face corners in all");
    mesh.face_start.push_back(static_cast<uint32_t>(mesh.corners.size()));
}

template <class Body>
uint32_t read_index(Body& body, PlyType type, uint64_t vertex_count) {
    const int64_t index = body.integer(type);
    if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
        body.fail(fmt::format("corner index {} is out of range (the file has {} vertices)", index,
                              vertex_count));
    return static_cast<uint32_t>(index);
}

/// Faces: polygons of any length, each kept whole (build_mesh triangulates).
template <class Body>
void read_faces(Body& body, const PlyElement& e, int list, uint64_t vertex_count, bool keep_lines,
                PolygonMesh& mesh) {
    for (uint64_t i = 0; i < e.count; ++i) {
        body.begin_item("face", i);
        if (keep_lines) mesh.face_line.push_back(body.line());
        for (size_t k = 0; k < e.properties.size(); ++k) {
            const PlyProperty& p = e.properties[k];
            if (static_cast<int>(k) != list) {
                body.skip(p);
                continue;
            }
            const uint64_t n = body.list_length(p);
            if (n < 3 || n > k_max_face_corners)
                body.fail(
                    fmt::format("it has {} corners; a face needs 3 to {}", n, k_max_face_corners));
            for (uint64_t j = 0; j < n; ++j)
                mesh.corners.push_back(read_index(body, p.type, vertex_count));
        }
        end_face(body, mesh);
    }
}

/// Binary faces stored as the common `property list uchar int|uint vertex_indices` and nothing
/// else, in the machine's byte order. A first pass walks the list lengths (each face's place in
/// the file and in `corners`); then chunks of faces copy and check their indices in parallel.
/// The first bad index in file order is the one reported.
bool read_packed_faces(BinaryBody& body, const PlyElement& e, uint64_t vertex_count,
                       PolygonMesh& mesh) {
    if (e.properties.size() != 1 || body.swap()) return false;
    const PlyProperty& p = e.properties[0];
    if (p.count_type != PlyType::uint8 || (p.type != PlyType::int32 && p.type != PlyType::uint32))
        return false;
    const size_t first_face = mesh.face_start.size() - 1;
    const char* const base = body.data() + body.pos();
    // Where every face is a triangle (a 3 before every 12 bytes, checked in parallel: the common
    // case), each face's place in the file is known at once; otherwise a first pass walks the
    // list lengths.
    const bool all_triangles =
        e.count <= body.left() / 13 &&
        mesh.face_start.back() + 3 * e.count <= std::numeric_limits<uint32_t>::max() &&
        hikari::parallel_reduce(
            tbb::blocked_range<size_t>(0, e.count, 65536), true,
            [&](const tbb::blocked_range<size_t>& r, bool all) {
                for (size_t i = r.begin(); all && i != r.end(); ++i) all = base[13 * i] == 3;
                return all;
            },
            [](bool a, bool b) { return a && b; });
    std::vector<const char*> indices;
    // A face the first pass cannot take (too few corners, the file ends) is reported after the
    // faces before it are checked: an earlier bad index comes first, as in file order.
    std::exception_ptr stopped;
    size_t taken = e.count;
    if (all_triangles) {
        const uint32_t start = mesh.face_start.back();
        mesh.face_start.resize(first_face + 1 + e.count);
        hikari::parallel_for(size_t{0}, size_t(e.count), [&](size_t i) {
            mesh.face_start[first_face + 1 + i] = start + 3 * uint32_t(i + 1);
        });
        body.begin_item("face", 0);
        body.take(13 * e.count);
    } else {
        indices.reserve(e.count);
        try {
            for (uint64_t i = 0; i < e.count; ++i) {
                body.begin_item("face", i);
                const auto n = static_cast<uint8_t>(*body.take(1));
                if (n < 3) body.fail(fmt::format("it has {} corners; a face needs at least 3", n));
                const char* face_indices = body.take(4 * size_t{n});
                if (mesh.face_start.back() + uint64_t{n} > std::numeric_limits<uint32_t>::max())
                    body.fail("more than 2^32 - 1 face corners in all");
                indices.push_back(face_indices);
                mesh.face_start.push_back(mesh.face_start.back() + n);
            }
        } catch (...) {
            stopped = std::current_exception();
        }
        taken = indices.size();
    }
    const auto face_bytes = [&](size_t i) {
        return all_triangles ? base + 13 * i + 1 : indices[i];
    };
    const size_t corner0 = mesh.corners.size();
    mesh.corners.resize(mesh.face_start.back());
    parallel_chunks(taken, 65536, [&](size_t, size_t f0, size_t f1) {
        throw_if_cancelled();  // SIGINT / SIGTERM
        for (size_t i = f0; i < f1; ++i) {
            const size_t n = mesh.face_start[first_face + i + 1] - mesh.face_start[first_face + i];
            uint32_t* out = mesh.corners.data() + corner0 +
                            (mesh.face_start[first_face + i] - mesh.face_start[first_face]);
            // One fixed-size memcpy per corner: a variable-length one compiles to `rep movs`,
            // whose start-up cost is several times that of copying 12 bytes.
            for (size_t j = 0; j < n; ++j) {
                uint32_t corner;
                std::memcpy(&corner, face_bytes(i) + 4 * j, 4);
                if (corner >= vertex_count) {
                    const int64_t index = p.type == PlyType::int32
                                              ? int64_t{std::bit_cast<int32_t>(corner)}
                                              : int64_t{corner};
                    BinaryBody at = body;  // each chunk names its own item
                    at.point_at("face", i, static_cast<size_t>(face_bytes(i) - 1 - body.data()));
                    at.fail(
                        fmt::format("corner index {} is out of range (the file has {} "
                                    "vertices)",
                                    index, vertex_count));
                }
                out[j] = corner;
            }
        }
    });
    if (stopped) std::rethrow_exception(stopped);
    return true;
}

/// Triangle strips: a strip's vertices a b c d e ... give the triangles (a b c), (c b d),
/// (c d e), ...: every odd triangle's first two corners are swapped so that all keep the strip's
/// orientation. -1 ends a strip; triangles with a repeated corner (used to join strips) are
/// skipped. Each triangle becomes a face.
template <class Body>
void read_tristrips(Body& body, const PlyElement& e, int list, uint64_t vertex_count,
                    bool keep_lines, PolygonMesh& mesh) {
    for (uint64_t i = 0; i < e.count; ++i) {
        body.begin_item("tristrips", i);
        for (size_t k = 0; k < e.properties.size(); ++k) {
            const PlyProperty& p = e.properties[k];
            if (static_cast<int>(k) != list) {
                body.skip(p);
                continue;
            }
            const uint64_t n = body.list_length(p);
            uint32_t a = 0, b = 0;
            uint64_t in_strip = 0;  // vertices of the current strip so far
            for (uint64_t j = 0; j < n; ++j) {
                const int64_t raw = body.integer(p.type);
                if (raw == -1) {
                    in_strip = 0;
                    continue;
                }
                if (raw < 0 || static_cast<uint64_t>(raw) >= vertex_count)
                    body.fail(
                        fmt::format("corner index {} is out of range (the file has {} "
                                    "vertices)",
                                    raw, vertex_count));
                const auto c = static_cast<uint32_t>(raw);
                if (in_strip >= 2 && a != b && b != c && a != c) {
                    const bool odd = (in_strip - 2) % 2 == 1;
                    mesh.corners.insert(mesh.corners.end(), {odd ? b : a, odd ? a : b, c});
                    if (keep_lines) mesh.face_line.push_back(body.line());
                    end_face(body, mesh);
                }
                a = b;
                b = c;
                ++in_strip;
            }
        }
    }
}

template <class Body>
void skip_element(Body& body, const PlyElement& e) {
    if (e.properties.empty()) return;  // nothing stored, whatever the count
    if constexpr (std::is_same_v<Body, BinaryBody>) {
        if (!e.has_lists()) {
            body.begin_item(e.name, 0);
            body.take(e.count * e.min_binary_size());  // checked to fit by check_counts_fit
            return;
        }
    }
    for (uint64_t i = 0; i < e.count; ++i) {
        body.begin_item(e.name, i);
        for (const PlyProperty& p : e.properties) body.skip(p);
    }
}

/// What the header says hikari reads, checked before the body is.
struct PlyPlan {
    uint64_t vertex_count = 0;
    VertexSlots slots;
    int face_list = -1;       ///< the index list of `face`
    int tristrips_list = -1;  ///< the index list of `tristrips`
};

PlyPlan plan_reading(const fs::path& file, const PlyHeader& header,
                     std::vector<std::string>& warnings) {
    PlyPlan plan;
    const PlyElement* vertex = header.find("vertex");
    if (!vertex) fail_at_line(file, header.end_line, "the header declares no 'vertex' element");
    plan.vertex_count = vertex->count;
    plan.slots = find_vertex_slots(file, *vertex, warnings);
    if (const PlyElement* face = header.find("face")) plan.face_list = find_index_list(file, *face);
    if (const PlyElement* strips = header.find("tristrips"))
        plan.tristrips_list = find_index_list(file, *strips);
    return plan;
}

template <class Body>
void read_elements(Body& body, const PlyHeader& header, const PlyPlan& plan, PolygonMesh& mesh) {
    constexpr bool binary = std::is_same_v<Body, BinaryBody>;
    for (const PlyElement& e : header.elements) {
        if (e.name == "vertex") {
            if constexpr (binary) {
                if (!e.has_lists()) {
                    read_fixed_vertices(body, e, plan.slots, mesh);
                    continue;
                }
            }
            read_vertices(body, e, plan.slots, mesh);
        } else if (e.name == "face") {
            if constexpr (binary) {
                if (read_packed_faces(body, e, plan.vertex_count, mesh)) continue;
            }
            read_faces(body, e, plan.face_list, plan.vertex_count, !binary, mesh);
        } else if (e.name == "tristrips") {
            read_tristrips(body, e, plan.tristrips_list, plan.vertex_count, !binary, mesh);
        } else {
            skip_element(body, e);
        }
    }
}

/// Room for what the header declares (counts already checked against the file's size), after
/// checking it against --max-memory: per vertex its attributes (up to 44 bytes) and per face a
/// start and three corners (16 bytes), each about twice over once build_mesh has made its
/// triangles.
void reserve(const fs::path& file, const PlyHeader& header, const PlyPlan& plan,
             PolygonMesh& mesh) {
    const PlyElement* face = header.find("face");
    const double faces = face ? static_cast<double>(face->count) : 0.0;
    check_memory_need(2.0 * (44.0 * static_cast<double>(plan.vertex_count) + 16.0 * faces),
                      fmt::format("{}: loading {} vertices and {} faces", file.string(),
                                  plan.vertex_count, face ? face->count : 0));
    // Each array's pages mapped in one call (populate_pages), not faulted in one by one as they
    // are filled: on a virtual machine a fault costs several times more.
    auto reserve_mapped = [](auto& v, size_t n) {
        v.reserve(n);
        populate_pages_in_parallel(v.data(), n * sizeof(v[0]));
    };
    reserve_mapped(mesh.positions, plan.vertex_count);
    if (plan.slots.has_normals()) reserve_mapped(mesh.normals, plan.vertex_count);
    if (plan.slots.has_uvs()) reserve_mapped(mesh.uvs, plan.vertex_count);
    if (plan.slots.has_colors()) reserve_mapped(mesh.colors, plan.vertex_count);
    if (face) {
        reserve_mapped(mesh.face_start, face->count + 1);
        reserve_mapped(mesh.corners, 3 * face->count);
    }
}

}  // namespace

PolygonMesh read_ply(const fs::path& file, std::string_view bytes) {
    PolygonMesh mesh;
    const PlyHeader header = parse_header(file, bytes, mesh.warnings);
    const PlyPlan plan = plan_reading(file, header, mesh.warnings);
    check_counts_fit(file, header, bytes.size() - header.body_offset);
    if (plan.vertex_count > std::numeric_limits<uint32_t>::max())
        fail_at_line(file, header.find("vertex")->line, "more than 2^32 - 1 vertices");
    reserve(file, header, plan, mesh);

    if (header.format == PlyFormat::ascii) {
        AsciiBody body(file, bytes, header.body_offset, header.body_line);
        read_elements(body, header, plan, mesh);
        if (!body.at_end())
            mesh.warnings.push_back(fmt::format("{}:{}: text after the last element is ignored",
                                                file.string(), body.current_line()));
    } else {
        const bool big_endian = header.format == PlyFormat::binary_big_endian;
        const bool swap = big_endian != (std::endian::native == std::endian::big);
        BinaryBody body(file, bytes, header.body_offset, swap);
        read_elements(body, header, plan, mesh);
        if (body.left() > 0)
            mesh.warnings.push_back(
                fmt::format("{}: byte {}: {} bytes after the last element are "
                            "ignored",
                            file.string(), body.pos(), body.left()));
    }
    return mesh;
}

MeshData load_ply(const fs::path& file, const MeshOptions& options) {
    // The magic line is checked from the first bytes: a 4 GiB file that is not a PLY is refused
    // before it is read.
    FileFormatCheck check;
    check.check_head = [&](std::string_view head, std::uintmax_t) {
        if (!head.starts_with("ply\n") && !head.starts_with("ply\r\n") && head != "ply")
            fail_at_line(file, 1, "not a PLY file (the first line is not 'ply')");
    };
    const std::string bytes = read_file_bytes(file, InputKind::mesh, check);
    return build_mesh(file, read_ply(file, bytes), options);
}

}  // namespace hikari
