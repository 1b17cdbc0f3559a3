#include "hikari/io/models/obj_loader.h"

#include <tiny_obj_loader.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <span>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include "hikari/core/cancel.h"
#include "hikari/core/color.h"
#include "hikari/core/error.h"
#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/texture_files.h"
#include "hikari/io/models/material_rules.h"
#include "hikari/io/models/mesh_builder.h"
#include "hikari/io/models/mtl_scan.h"
#include "hikari/io/models/text_number.h"

namespace hikari {

namespace {

/// The error prefix "FILE:LINE: " (or "FILE: " when `line` is 0, i.e. unknown).
std::string where(const std::filesystem::path& file, size_t line) {
    return line > 0 ? fmt::format("{}:{}: ", file.string(), line)
                    : fmt::format("{}: ", file.string());
}

[[noreturn]] void fail(const std::filesystem::path& file, size_t line, const std::string& what) {
    throw InputError(printable_text(where(file, line) + what));
}

// --- MTL libraries ------------------------------------------------------------------------------

/// Opens MTL libraries relative to the OBJ's directory. tinyobjloader's own MaterialFileReader
/// splits its base directory at ':' (a search path), which breaks directories containing ':'.
/// Remembers which library each material came from, for texture paths and messages.
class MtlReader : public tinyobj::MaterialReader {
  public:
    explicit MtlReader(std::filesystem::path dir) : m_dir(std::move(dir)) {}

    /// The MTL file of each material, in tinyobjloader's order.
    const std::vector<std::filesystem::path>& library_of_material() const { return m_library_of; }
    /// Where each material's statements are (scan_mtl_text), in tinyobjloader's order; an empty
    /// entry when the scan and tinyobjloader disagree on the materials.
    const std::vector<MtlMaterialLines>& lines_of_material() const { return m_lines_of; }
    /// Why a library that exists could not be used (a device, FIFO or directory, too large: its
    /// name as the OBJ gives it and the read error; a bad number: no name and the scan's error,
    /// which says where). Both empty when none.
    const std::pair<std::string, std::string>& failure() const { return m_failure; }

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* material_map, std::string* warn,
                    std::string* err) override {
        const std::filesystem::path mtl = m_dir / name;
        // Through read_file_bytes, which reads only regular files and bounds the read: an
        // `mtllib /dev/zero` must not run until memory is gone.
        // A library that is missing is a warning (OBJ files often travel without theirs); one
        // that exists but cannot be used is an error, reported by load_obj.
        std::string text;
        std::vector<MtlMaterialLines> lines;
        try {
            text = read_file_bytes(mtl, InputKind::mesh);
        } catch (const InputError& e) {
            std::error_code ec;
            if (m_failure.second.empty() && std::filesystem::exists(mtl, ec))
                m_failure = {name, e.what()};
            *warn += std::string("cannot open material library: ") + e.what() + "\n";
            return false;
        }
        try {
            lines = scan_mtl_text(mtl, text);
        } catch (const InputError& e) {
            if (m_failure.second.empty()) m_failure = {"", e.what()};
            return false;
        }
        const size_t before = materials->size();
        std::istringstream stream(std::move(text));
        tinyobj::LoadMtl(material_map, materials, &stream, warn, err);
        m_library_of.resize(materials->size(), mtl);
        if (materials->size() - before != lines.size())
            lines.assign(materials->size() - before, {});
        m_lines_of.insert(m_lines_of.end(), lines.begin(), lines.end());
        return true;
    }

  private:
    std::filesystem::path m_dir;
    std::vector<std::filesystem::path> m_library_of;
    std::vector<MtlMaterialLines> m_lines_of;
    std::pair<std::string, std::string> m_failure;
};

// --- Pass 1: our own scan of the text ----------------------------------------------------------
// tinyobjloader 2.0.0rc10 reads a malformed number as 0 without a word, accepts faces with
// indices out of range (only a warning for the largest one), and keeps no line numbers. This scan
// checks every number strictly and records the line of each face, so later checks can point at
// the line. It splits lines and tokens exactly as tinyobjloader does. It also carries out the
// statements that set state (mtllib, usemtl, s, g), as tinyobjloader's LoadObj does, since its
// streaming parser (pass 2) ignores `s` and reads `usemtl` differently.

/// The material and smoothing group of faces from `first_face` on (until the next change).
struct FaceState {
    uint32_t first_face = 0;
    int32_t material = -1;
    uint32_t smoothing = 0;
};

/// What the scan found: the line (1-based) of each face, the counts that size what pass 2
/// allocates, the state each face is drawn with, and tinyobjloader's messages about them.
struct LineTable {
    std::vector<uint32_t> f;
    size_t v_count = 0, vt_count = 0, vn_count = 0, corner_count = 0;
    /// Empty, or one per `v` from the first one that has a colour on: `v x y z r g b`, the
    /// extension MeshLab and scanners write, sRGB-decoded; white for a `v` without one.
    std::vector<Vec3> v_colors;
    /// Each `mtllib` statement: its line and the rest of the line (the library names).
    std::vector<std::pair<uint32_t, std::string_view>> mtllib;
    /// State changes in face order; the first applies from face 0.
    std::vector<FaceState> states{FaceState{}};
    /// The materials of the libraries loaded, in tinyobjloader's order.
    std::vector<tinyobj::material_t> materials;
    /// Warnings and errors in tinyobjloader's words (for clean_messages), in line order.
    std::string warn, err;
    /// tinyobjloader's LoadObj fails at an `l` or `p` statement with a zero index; its message,
    /// else empty. Statements after it set no state (LoadObj stops there).
    std::string load_failure;
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Calls f(token) for each whitespace-separated token of `rest`, in order. No list is built:
/// a million-line file would otherwise cost a million allocations.
template <typename F>
void for_each_token(std::string_view rest, F&& f) {
    size_t i = 0;
    while (i < rest.size()) {
        while (i < rest.size() && is_blank(rest[i])) ++i;
        const size_t begin = i;
        while (i < rest.size() && !is_blank(rest[i])) ++i;
        if (i > begin) f(rest.substr(begin, i - begin));
    }
}

size_t count_tokens(std::string_view rest) {
    size_t count = 0;
    for_each_token(rest, [&count](std::string_view) { ++count; });
    return count;
}

/// Checks that the tokens of `rest` are at least `min_count` finite numbers; returns how many
/// there are.
size_t check_numbers(const std::filesystem::path& file, size_t line, const char* statement,
                     std::string_view rest, size_t min_count) {
    const size_t count = count_tokens(rest);
    if (count < min_count) {
        fail(
            file, line,
            fmt::format("{} needs {} numbers, found {}", quote_token(statement), min_count, count));
    }
    for_each_token(rest, [&](std::string_view t) {
        // tinyobjloader stores floats: a finite double beyond FLT_MAX would become infinite.
        std::string why;
        if (!parse_float_token(t, &why))
            fail(file, line, fmt::format("{}: {}", quote_token(statement), why));
    });
    return count;
}

/// Records the colour of a `v` statement (`v x y z r g b`, components from 0 to 1, taken as
/// sRGB-encoded like the 8-bit colours they usually come from; a 7th number, alpha, is ignored).
/// `v x y z` and `v x y z w` have none: white once an earlier vertex had one. `count` is the
/// statement's number of numbers (check_numbers has checked them all); only a coloured one is
/// read again.
void scan_vertex_colour(const std::filesystem::path& file, size_t line, std::string_view rest,
                        size_t count, LineTable& table) {
    if (count < 6) {
        if (!table.v_colors.empty()) table.v_colors.emplace_back(1.0f);
        return;
    }
    float rgb[3] = {};
    size_t index = 0;
    for_each_token(rest, [&](std::string_view t) {
        if (index >= 3 && index < 6) rgb[index - 3] = parse_float_token(t).value_or(0.0f);
        ++index;
    });
    Vec3 colour;
    for (int k = 0; k < 3; ++k) {
        const float c = rgb[k];
        if (!(c >= 0.0f && c <= 1.0f)) {
            fail(file, line,
                 fmt::format("'v': colour component {} is outside 0..1 (v x y z r g b)", c));
        }
        colour[k] = srgb_to_linear(c);
    }
    if (table.v_colors.empty()) table.v_colors.assign(table.v_count, Vec3(1.0f));
    table.v_colors.push_back(colour);
}

/// Whether `part` is an OBJ index: an optional '-' and decimal digits, nonzero, of magnitude at
/// most 2^31 − 1 (tinyobjloader reads them with atoi, which wraps or overflows silently).
bool is_obj_index(std::string_view part) {
    const std::string_view digits = part.starts_with('-') ? part.substr(1) : part;
    if (digits.empty() || digits.size() > 10) return false;
    int64_t value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return ec == std::errc() && end == digits.data() + digits.size() && value > 0 &&
           value <= std::numeric_limits<int32_t>::max();
}

/// Whether one of a corner's parts is a zero (`0`, `-0`, `00`): the mistake of a 0-based writer.
bool has_zero_index(std::span<const std::string_view> parts) {
    return std::ranges::any_of(parts, [](std::string_view part) {
        const std::string_view digits = part.starts_with('-') ? part.substr(1) : part;
        return !digits.empty() && digits.find_first_not_of('0') == std::string_view::npos;
    });
}

/// Checks every corner of a face: `v`, `v/vt`, `v//vn` or `v/vt/vn`, each an OBJ index.
void check_face_corners(const std::filesystem::path& file, size_t line, std::string_view rest) {
    for_each_token(rest, [&](std::string_view corner) {
        std::string_view parts[3];
        size_t count = 0;  // parts found; 4 stands for "more than three"
        for (size_t start = 0;;) {
            if (count == 3) {
                count = 4;
                break;
            }
            const size_t slash = corner.find('/', start);
            parts[count++] = corner.substr(
                start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        const bool valid = count <= 3 && is_obj_index(parts[0]) &&
                           (count < 2 || parts[1].empty() || is_obj_index(parts[1])) &&
                           (count < 3 || is_obj_index(parts[2])) &&
                           !(count == 2 && parts[1].empty());
        if (!valid && has_zero_index(std::span(parts, std::min<size_t>(count, 3))))
            fail(file, line,
                 fmt::format("'f': '{}' uses index 0; OBJ indices start at 1 (the first 'v' line "
                             "is 1, and -1 is the last one read so far)",
                             corner));
        if (!valid)
            fail(file, line,
                 fmt::format("'f': {} is not a corner (v, v/vt, v//vn or v/vt/vn, each a "
                             "nonzero index of at most 10 digits that fits in 32 bits)",
                             quote_token(corner)));
    });
}

/// Where the line that starts at `pos` ends: its first \r or \n, or the end of the text. Two
/// memchr calls, not find_first_of, which libstdc++ runs as a search of the set per character
/// (6% of a million-triangle render's process time).
size_t line_end(std::string_view text, size_t pos) {
    const char* const begin = text.data() + pos;
    const size_t rest = text.size() - pos;
    const auto* newline = static_cast<const char*>(std::memchr(begin, '\n', rest));
    const size_t length = newline ? size_t(newline - begin) : rest;
    const auto* carriage_return = static_cast<const char*>(std::memchr(begin, '\r', length));
    return pos + (carriage_return ? size_t(carriage_return - begin) : length);
}

/// tinyobjloader's parseString: the word at `*token` (after blanks), up to a blank, \r or the end.
std::string parse_word(const char** token) {
    *token += std::strspn(*token, " \t");
    const size_t length = std::strcspn(*token, " \t\r");
    std::string word(*token, length);
    *token += length;
    return word;
}

/// Whether tinyobjloader's parseTriple accepts every corner of an `l` or `p` statement (`rest`,
/// NUL-terminated): it fails on an index that atoi reads as 0.
bool tinyobj_reads_indices(const char* t) {
    const auto part = [&t] {
        const bool nonzero = std::atoi(t) != 0;
        t += std::strcspn(t, "/ \t\r");
        return nonzero;
    };
    while (t[0] != '\0' && t[0] != '\r' && t[0] != '\n') {
        if (!part()) return false;
        if (t[0] == '/') {
            ++t;
            if (t[0] == '/') {
                ++t;
                if (!part()) return false;
            } else {
                if (!part()) return false;
                if (t[0] == '/') {
                    ++t;
                    if (!part()) return false;
                }
            }
        }
        t += std::strspn(t, " \t\r");
    }
    return true;
}

/// tinyobjloader's SplitString(names, ' ', '\\'): words separated by spaces, a backslash escaping
/// the next character; the last word is kept even when empty.
std::vector<std::string> split_library_names(std::string_view names) {
    std::vector<std::string> out;
    std::string word;
    bool escaping = false;
    for (const char c : names) {
        if (escaping) {
            escaping = false;
        } else if (c == '\\') {
            escaping = true;
            continue;
        } else if (c == ' ') {
            if (!word.empty()) out.push_back(word);
            word.clear();
            continue;
        }
        word += c;
    }
    out.push_back(word);
    return out;
}

/// Carries out the statements that set the state of the faces after them, as LoadObj does
/// (tiny_obj_loader.h, LoadObj: "use mtl", "load mtl", "group name", "smoothing group id"):
/// `s` is the line after its leading blanks, NUL-free.
class StatementState {
  public:
    StatementState(LineTable& table, MtlReader& mtl_reader)
        : m_table(table), m_mtl_reader(mtl_reader) {}

    /// Handles `s` if it is one of these statements; `faces` is the number of faces before it.
    void statement(std::string_view s, size_t line, size_t faces) {
        if (!m_table.load_failure.empty()) return;
        const bool blank1 = s.size() > 1 && (s[1] == ' ' || s[1] == '\t');
        if (s.starts_with("usemtl")) {
            use_material(std::string(s.substr(6)), faces);
        } else if (s.starts_with("mtllib") && s.size() > 6 && (s[6] == ' ' || s[6] == '\t')) {
            load_libraries(s.substr(7));
        } else if (s[0] == 'g' && blank1) {
            // LoadObj's names[0] is the 'g' itself: a group statement without a name.
            if (count_tokens(s) < 2)
                m_table.warn += fmt::format("Empty group name. line: {}\n", line);
        } else if (s[0] == 's' && blank1) {
            set_smoothing(std::string(s.substr(2)), faces);
        } else if ((s[0] == 'l' || s[0] == 'p') && blank1) {
            if (!tinyobj_reads_indices(std::string(s.substr(2)).c_str()))
                m_table.load_failure = fmt::format(
                    "Failed parse `{}' line(e.g. zero value for vertex index. line {}.)\n", s[0],
                    line);
        }
    }

    /// The material_map lookups that found nothing, beyond the first k_max_missing (a file of
    /// ten million `usemtl` lines must not make ten million warnings).
    size_t missing_not_reported() const {
        return m_missing > k_max_missing ? m_missing - k_max_missing : 0;
    }

  private:
    static constexpr size_t k_max_missing = 100;

    void set_state(size_t faces, int32_t material, uint32_t smoothing) {
        FaceState& last = m_table.states.back();
        if (last.material == material && last.smoothing == smoothing) return;
        const FaceState next{static_cast<uint32_t>(faces), material, smoothing};
        if (last.first_face == next.first_face)
            last = next;
        else
            m_table.states.push_back(next);
    }

    void use_material(const std::string& rest, size_t faces) {
        const char* token = rest.c_str();
        const std::string name = parse_word(&token);
        int32_t material = -1;
        if (const auto it = m_material_map.find(name); it != m_material_map.end()) {
            material = it->second;
        } else if (++m_missing <= k_max_missing) {
            m_table.warn += "material [ '" + name + "' ] not found in .mtl\n";
        }
        set_state(faces, material, m_table.states.back().smoothing);
    }

    void load_libraries(std::string_view names) {
        const std::vector<std::string> files = split_library_names(names);
        bool found = false;
        for (const std::string& name : files) {
            if (m_loaded.count(name) > 0) {
                found = true;
                continue;
            }
            std::string warn, err;
            const bool ok = m_mtl_reader(name, &m_table.materials, &m_material_map, &warn, &err);
            m_table.warn += warn;
            m_table.err += err;
            if (ok) {
                found = true;
                m_loaded.insert(name);
                break;
            }
        }
        if (!found) m_table.warn += "Failed to load material file(s). Use default material.\n";
    }

    void set_smoothing(const std::string& rest, size_t faces) {
        const char* token = rest.c_str();
        token += std::strspn(token, " \t");
        if (token[0] == '\0' || token[0] == '\r' || token[1] == '\n') return;
        uint32_t group = 0;
        if (!(std::strlen(token) >= 3 && std::strncmp(token, "off", 3) == 0)) {
            const int id = std::atoi(token);  // LoadObj's parseInt; negative means off
            group = id < 0 ? 0u : static_cast<uint32_t>(id);
        }
        set_state(faces, m_table.states.back().material, group);
    }

    LineTable& m_table;
    MtlReader& m_mtl_reader;
    std::map<std::string, int> m_material_map;
    std::set<std::string> m_loaded;
    size_t m_missing = 0;
};

LineTable scan_obj_text(const std::filesystem::path& file, std::string_view text,
                        MtlReader& mtl_reader) {
    LineTable table;
    StatementState state(table, mtl_reader);
    size_t pos = 0;
    for (uint32_t line = 1; pos < text.size(); ++line) {
        if (line % 65536 == 0) throw_if_cancelled();  // SIGINT / SIGTERM
        // Lines end at \n, \r\n or a lone \r, as in tinyobjloader's safeGetline.
        const size_t end = line_end(text, pos);
        std::string_view s = text.substr(pos, end - pos);
        pos = end + ((end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ? 2 : 1);

        s = s.substr(0, s.find('\0'));  // tinyobjloader parses C strings
        const size_t first = s.find_first_not_of(" \t");
        if (first == std::string_view::npos) continue;
        s.remove_prefix(first);
        if (s.size() < 2) continue;
        const bool blank1 = s[1] == ' ' || s[1] == '\t';
        const bool blank2 = s.size() > 2 && (s[2] == ' ' || s[2] == '\t');
        if (s[0] == 'v' && blank1) {
            const size_t count = check_numbers(file, line, "v", s.substr(2), 3);
            scan_vertex_colour(file, line, s.substr(2), count, table);
            ++table.v_count;
        } else if (s[0] == 'v' && s[1] == 'n' && blank2) {
            check_numbers(file, line, "vn", s.substr(3), 3);
            ++table.vn_count;
        } else if (s[0] == 'v' && s[1] == 't' && blank2) {
            check_numbers(file, line, "vt", s.substr(3), 1);
            ++table.vt_count;
        } else if (s[0] == 'f' && blank1) {
            const size_t corners = count_tokens(s.substr(2));
            if (corners < 3 || corners > k_max_face_corners) {
                fail(file, line,
                     fmt::format("a face needs 3 to {} corners, this one has {}",
                                 k_max_face_corners, corners));
            }
            check_face_corners(file, line, s.substr(2));
            table.f.push_back(line);
            table.corner_count += corners;
        } else if (s[0] != '#') {
            if (s.starts_with("mtllib") && s.size() > 6 && is_blank(s[6]))
                table.mtllib.emplace_back(line, s.substr(7));
            state.statement(s, line, table.f.size());
        }
    }
    if (const size_t more = state.missing_not_reported(); more > 0)
        table.warn +=
            fmt::format("{} more usemtl statements name materials not found in .mtl\n", more);
    return table;
}

/// Refuses, before pass 2 runs, a file whose faces would take more memory than --max-memory
/// allows, with every face kept. Bytes per item: a face takes its line (scan), its state change
/// at worst, its start, material, smoothing group and line (pass 2, 4 bytes each); a corner its
/// resolved (v, vn, vt) indices and its vertex in the polygons (4 bytes each); an attribute its
/// value, read once and copied once into the polygons' vertices. build_mesh runs while all of
/// that is held, so its own need for the triangles and the `vertices` (at most one per corner)
/// is counted with it, as the PLY and glTF loaders count theirs: a file that could not be built
/// is refused before the seconds spent reading it.
void check_obj_memory(const std::filesystem::path& file, size_t faces, size_t corners,
                      size_t attributes, size_t vertices) {
    const double triangles = corners >= 2 * faces ? static_cast<double>(corners - 2 * faces) : 0.0;
    check_memory_need(32.0 * static_cast<double>(faces) + 16.0 * static_cast<double>(corners) +
                          24.0 * static_cast<double>(attributes) +
                          mesh_build_bytes(triangles, static_cast<double>(vertices)),
                      fmt::format("{}: loading {} faces", file.string(), faces));
}

/// The number of lines that start with "f " (no leading blanks): a lower bound on the faces,
/// counted with memchr in a few milliseconds, so that a file of ten million faces is refused
/// before the strict scan spends seconds on it.
size_t count_face_lines(std::string_view text) {
    size_t count = text.starts_with("f ") ? 1 : 0;
    const char* const end = text.data() + text.size();
    const char* p = text.data();
    while ((p = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p))))) {
        if (end - p > 2 && p[1] == 'f' && p[2] == ' ') ++count;
        ++p;
    }
    return count;
}

// --- Pass 2: tinyobjloader's streaming parser ---------------------------------------------------

/// tinyobjloader's messages, one per line, as "FILE:LINE: message" (its "(line N.)" moved to the
/// front). Lines that are only punctuation (it writes "Degenerated face found\n.") are dropped.
std::vector<std::string> clean_messages(const std::filesystem::path& file,
                                        const std::string& text) {
    static const std::regex line_number(R"(\.?\s*\(?line:?\s*(\d+)\.?\)?)", std::regex::icase);
    std::vector<std::string> out;
    std::istringstream lines(text);
    std::string message;
    while (std::getline(lines, message)) {
        size_t line = 0;
        std::smatch match;
        if (std::regex_search(message, match, line_number)) {
            line = std::stoul(match[1].str());
            message = match.prefix().str() + match.suffix().str();
            if (std::count(message.begin(), message.end(), '(') >
                std::count(message.begin(), message.end(), ')')) {
                message += ')';
            }
        }
        const size_t b = message.find_first_not_of(" \t\r.");
        if (b == std::string::npos) continue;
        const size_t e = message.find_last_not_of(" \t\r");
        out.push_back(printable_text(where(file, line) + message.substr(b, e - b + 1)));
    }
    return out;
}

struct ParsedObj {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::vector<std::filesystem::path> material_library;  ///< the MTL file of each material
    std::vector<MtlMaterialLines> material_lines;         ///< where each material's lines are
    std::vector<std::string> warnings;
};

/// A read-only stream buffer over text that outlives it: tinyobjloader reads from a stream, and
/// an istringstream would first copy the whole file.
class TextStreambuf : public std::streambuf {
  public:
    explicit TextStreambuf(const std::string& text) {
        // The get area only: nothing is ever written through these pointers.
        char* const begin = const_cast<char*>(text.data());
        setg(begin, begin, begin + text.size());
    }
};

/// Runs tinyobjloader over `text`, opening MTL libraries through `mtl_reader` (none when null),
/// with its own triangulation or without. Returns false when it fails; `warn` and `err` get its
/// messages.
bool run_tinyobj(const std::string& text, tinyobj::MaterialReader* mtl_reader, bool triangulate,
                 ParsedObj& parsed, std::string& warn, std::string& err) {
    // tinyobjloader keeps every face in an array of its own, then copies them into its shapes:
    // its heap grows by some 3.6 to 7 times the text (bumpy1m, the bunny), page by page. Mapping
    // 6 times the text at once took the bunny's load from 116 to 61 ms and bumpy1m's from 1.15
    // to 0.67 s (medians, docs/performance.md).
    constexpr size_t k_max_reserve = size_t{1} << 30;
    reserve_heap(std::min(6 * text.size(), k_max_reserve));
    TextStreambuf text_buffer(text);
    std::istream stream(&text_buffer);
    return tinyobj::LoadObj(&parsed.attrib, &parsed.shapes, &parsed.materials, &warn, &err, &stream,
                            mtl_reader, triangulate, /*default_vcols_fallback=*/false);
}

/// The line of the `mtllib` statement that names `library`, or 0.
size_t mtllib_line(const LineTable& lines, std::string_view library) {
    for (const auto& [line, names] : lines.mtllib) {
        bool found = false;
        for_each_token(names, [&](std::string_view name) { found |= name == library; });
        if (found) return line;
    }
    return 0;
}

/// One face corner, resolved to 0-based indices (-1 = absent).
struct Corner {
    int v = -1, vn = -1, vt = -1;
    bool operator==(const Corner&) const = default;
};

struct CornerHash {
    size_t operator()(const Corner& c) const {
        size_t h = std::hash<int>()(c.v);
        h = h * 0x9E3779B97F4A7C15ull + std::hash<int>()(c.vn);
        return h * 0x9E3779B97F4A7C15ull + std::hash<int>()(c.vt);
    }
};

/// The scan's state statements, checked as LoadObj checked them: a library that exists but cannot
/// be used, then an `l` or `p` statement LoadObj fails on, is an error. Returns the warnings.
std::vector<std::string> check_statements(const std::filesystem::path& file, const LineTable& lines,
                                          const MtlReader& mtl_reader) {
    if (const auto& [library, error] = mtl_reader.failure(); !library.empty())
        fail(file, mtllib_line(lines, library), fmt::format("mtllib {}: {}", library, error));
    else if (!error.empty())
        throw InputError(error);
    if (!lines.load_failure.empty()) {
        const std::vector<std::string> errors = clean_messages(file, lines.load_failure);
        throw InputError(errors.empty() ? where(file, 0) + "cannot parse OBJ" : errors.front());
    }
    // `err` holds only MTL problems: the mesh is still usable.
    return clean_messages(file, lines.warn + lines.err);
}

/// What pass 2 keeps of the file: its attributes, and the faces that may be drawn, in file order,
/// as polygons of resolved corners. Nothing per face beyond that: tinyobjloader's LoadObj keeps
/// each face in a vector of its own (1.8 GB for ten million triangles).
struct StreamedObj {
    std::vector<Vec3> positions, normals;
    std::vector<Vec2> texcoords;
    std::vector<Vec3> colors;  ///< empty, or one per position (LineTable::v_colors)
    /// The kept faces' corners, 0-based as tinyobjloader resolves them (-1: absent), unchecked.
    std::vector<Corner> corners;
    /// Per kept face: face_start (into `corners`), face_material, smoothing_group, face_line.
    PolygonMesh faces;
    bool has_normals = false, has_uvs = false;  ///< whether any corner, kept or not, names one
    /// Triangles dropped as they came because build_mesh would drop them: zero area.
    size_t degenerate_dropped = 0;
};

/// Pass 2: tinyobjloader's streaming parser (LoadObjWithCallback), which reads the numbers as
/// LoadObj does but keeps nothing itself, feeding StreamedObj directly. Degenerate triangles are
/// dropped as they come, so a flood of them costs no memory, and the cancel flag is polled.
class ObjStreamer {
  public:
    ObjStreamer(const LineTable& lines) : m_lines(lines) {
        // Exact counts from the scan, accounted for by check_obj_memory; the face arrays only up
        // to a few million faces, since a flood of degenerate ones keeps nothing.
        constexpr size_t k_max_face_reserve = size_t{1} << 22;
        m_out.positions.reserve(lines.v_count);
        m_out.normals.reserve(lines.vn_count);
        m_out.texcoords.reserve(lines.vt_count);
        const size_t faces = std::min(lines.f.size(), k_max_face_reserve);
        m_out.corners.reserve(std::min(lines.corner_count, 3 * k_max_face_reserve));
        m_out.faces.face_start.reserve(faces + 1);
        m_out.faces.face_material.reserve(faces);
        m_out.faces.smoothing_group.reserve(faces);
        m_out.faces.face_line.reserve(faces);
    }

    StreamedObj run(const std::string& text) {
        tinyobj::callback_t callback;
        callback.vertex_cb = [](void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z,
                                tinyobj::real_t) {
            static_cast<ObjStreamer*>(self)->poll();
            static_cast<ObjStreamer*>(self)->m_out.positions.emplace_back(
                static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
        };
        callback.normal_cb = [](void* self, tinyobj::real_t x, tinyobj::real_t y,
                                tinyobj::real_t z) {
            static_cast<ObjStreamer*>(self)->poll();
            static_cast<ObjStreamer*>(self)->m_out.normals.emplace_back(
                static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
        };
        callback.texcoord_cb = [](void* self, tinyobj::real_t u, tinyobj::real_t v,
                                  tinyobj::real_t) {
            static_cast<ObjStreamer*>(self)->poll();
            static_cast<ObjStreamer*>(self)->m_out.texcoords.push_back(
                Vec2{static_cast<float>(u), static_cast<float>(v)});
        };
        callback.index_cb = [](void* self, tinyobj::index_t* corners, int count) {
            static_cast<ObjStreamer*>(self)->face(corners, static_cast<size_t>(count));
        };
        // No MTL reader and no usemtl callback: the scan carried those statements out.
        TextStreambuf text_buffer(text);
        std::istream stream(&text_buffer);
        tinyobj::LoadObjWithCallback(stream, callback, this, nullptr, nullptr, nullptr);
        return std::move(m_out);
    }

  private:
    /// SIGINT / SIGTERM, every 65536 statements.
    void poll() {
        if ((++m_records & 0xFFFF) == 0) throw_if_cancelled();
    }

    /// tinyobjloader's fixIndex over a raw index (0: absent, as parseRawTriple gives it): 1-based
    /// from the front, or relative to the `count` defined so far when negative.
    static int resolve(int raw, size_t count) {
        if (raw > 0) return raw - 1;
        if (raw == 0) return -1;
        return static_cast<int>(static_cast<int64_t>(count) + raw);
    }

    static bool within(int i, size_t count) { return i >= 0 && static_cast<size_t>(i) < count; }

    void face(const tinyobj::index_t* raw, size_t count) {
        poll();
        const size_t face = m_face++;
        while (m_next_state < m_lines.states.size() &&
               m_lines.states[m_next_state].first_face <= face)
            m_state = m_lines.states[m_next_state++];
        m_corners.clear();
        for (size_t k = 0; k < count; ++k) {
            const Corner c{resolve(raw[k].vertex_index, m_out.positions.size()),
                           resolve(raw[k].normal_index, m_out.normals.size()),
                           resolve(raw[k].texcoord_index, m_out.texcoords.size())};
            m_out.has_normals |= c.vn >= 0;
            m_out.has_uvs |= c.vt >= 0;
            m_corners.push_back(c);
        }
        if (is_degenerate_triangle()) {
            ++m_out.degenerate_dropped;
            return;
        }
        m_out.corners.insert(m_out.corners.end(), m_corners.begin(), m_corners.end());
        PolygonMesh& faces = m_out.faces;
        faces.face_start.push_back(static_cast<uint32_t>(m_out.corners.size()));
        faces.face_material.push_back(m_state.material);
        faces.smoothing_group.push_back(m_state.smoothing);
        faces.face_line.push_back(face < m_lines.f.size() ? m_lines.f[face] : 0);
    }

    /// Whether the face in m_corners is a triangle that build_mesh would drop for its zero (or
    /// non-finite) area, computed as it does (mesh_builder.cpp: doubled_area), from points already
    /// defined. A corner that names anything not yet defined keeps the face, for pass 3 to judge
    /// (a forward index is valid OBJ; an index out of range must still be an error).
    bool is_degenerate_triangle() const {
        if (m_corners.size() != 3) return false;
        for (const Corner& c : m_corners) {
            if (!within(c.v, m_out.positions.size()) ||
                (c.vn != -1 && !within(c.vn, m_out.normals.size())) ||
                (c.vt != -1 && !within(c.vt, m_out.texcoords.size())))
                return false;
        }
        const Vec3 p1 = m_out.positions[static_cast<size_t>(m_corners[0].v)];
        const Vec3 p2 = m_out.positions[static_cast<size_t>(m_corners[1].v)];
        const Vec3 p3 = m_out.positions[static_cast<size_t>(m_corners[2].v)];
        const float area2 = length(cross(p2 - p1, p3 - p2));
        return !(area2 > 0.0f) || !std::isfinite(area2);
    }

    const LineTable& m_lines;
    StreamedObj m_out;
    std::vector<Corner> m_corners;  ///< the current face's, reused
    FaceState m_state;
    size_t m_next_state = 0, m_face = 0, m_records = 0;
};

// --- Pass 3: checks and flattening -------------------------------------------------------------

Vec3 vec3_at(const std::vector<tinyobj::real_t>& a, int i) {
    const size_t k = 3 * static_cast<size_t>(i);
    return {static_cast<float>(a[k]), static_cast<float>(a[k + 1]), static_cast<float>(a[k + 2])};
}

Vec3 to_vec3(const tinyobj::real_t c[3]) {
    return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

/// A material's MTL texture statement (`keyword` naming `texture_name`, at `line` of `library`)
/// as an image texture, the file relative to the MTL library. Fails with the library's file:line
/// when the image cannot be used.
ImageTexture mtl_texture(const std::filesystem::path& library, size_t line,
                         const std::string& material, std::string_view keyword,
                         std::string texture_name, TextureFiles& textures) {
    // MTL files written on Windows separate directories with backslashes.
    std::replace(texture_name.begin(), texture_name.end(), '\\', '/');
    ImageTexture t;
    t.file = texture_name;
    try {
        t.pyramid = textures.pyramid(library.parent_path() / texture_name);
    } catch (const InputError& e) {
        fail(library, line,
             fmt::format("{} of material {}: cannot use texture {}: {}", keyword,
                         quote_token(material), quote_token(texture_name, '"', k_quoted_path_bytes),
                         e.what()));
    }
    return t;
}

/// The MTL statement that sets a Material field, for messages.
std::string_view mtl_keyword(MaterialField field, const MtlMaterialLines& lines) {
    switch (field) {
        case MaterialField::ka:
            return "Ka";
        case MaterialField::kd:
            return "Kd";
        case MaterialField::ks:
        case MaterialField::reflectivity:
            return "Ks";
        case MaterialField::shininess:
            return "Ns";
        case MaterialField::transparency:
            return lines.line_of("Tr") > lines.line_of("d") ? "Tr" : "d";
        case MaterialField::ior:
            return "Ni";
        case MaterialField::emission:
            return "Ke";
    }
    return "";
}

Material to_material(const tinyobj::material_t& m, const std::filesystem::path& library,
                     const MtlMaterialLines& lines, TextureFiles& textures) {
    Material out;
    out.name = m.name;
    out.ka = to_vec3(m.ambient);
    out.kd = to_vec3(m.diffuse);
    out.ks = to_vec3(m.specular);
    out.shininess = static_cast<float>(m.shininess);
    out.ior = static_cast<float>(m.ior);
    // Not clamped: `d 2` is out of range, refused below as the scene JSON refuses it.
    out.transparency = 1.0f - static_cast<float>(m.dissolve);
    // illum 3, 5, 6 and 7 ask for ray-traced reflection weighted by Ks (the MTL specification);
    // hikari's mirror weight is one number, so it takes Ks's mean.
    const bool mirror = m.illum == 3 || m.illum == 5 || m.illum == 6 || m.illum == 7;
    out.reflectivity =
        mirror ? std::clamp((out.ks.x + out.ks.y + out.ks.z) / 3.0f, 0.0f, 1.0f) : 0.0f;
    out.emission = to_vec3(m.emission);
    if (const auto problem = find_material_problem(out)) {
        const std::string_view keyword = mtl_keyword(problem->field, lines);
        fail(library, lines.line_of(keyword),
             fmt::format("material {}, {}: {}", quote_token(m.name), keyword, problem->message));
    }
    // map_Kd colours ka and kd alike, as a scene material's texture does; map_Ka, when present,
    // takes over ka.
    if (!m.diffuse_texname.empty())
        out.texture = mtl_texture(library, lines.line_of("map_Kd"), m.name, "map_Kd",
                                  m.diffuse_texname, textures);
    if (!m.ambient_texname.empty())
        out.ambient_texture = mtl_texture(library, lines.line_of("map_Ka"), m.name, "map_Ka",
                                          m.ambient_texname, textures);
    return out;
}

/// Checks a corner's indices against the attribute counts; `line` is 0 when unknown.
void check_corner(const std::filesystem::path& file, size_t line, const Corner& c,
                  const StreamedObj& obj) {
    auto check = [&](int i, size_t count, const char* kind) {
        if (i >= 0 && static_cast<size_t>(i) < count) return;
        if (i < 0) {
            fail(file, line,
                 std::string("a relative ") + kind + " index points before the first " + kind);
        }
        fail(file, line,
             std::string("face refers to ") + kind + " " + std::to_string(i + 1) +
                 ", but the file defines only " + std::to_string(count));
    };
    check(c.v, obj.positions.size(), "vertex");
    if (c.vn != -1) check(c.vn, obj.normals.size(), "normal");
    if (c.vt != -1) check(c.vt, obj.texcoords.size(), "texture coordinate");
}

/// The file's normal for a corner, or -1 when it has none or it cannot be normalized.
int usable_normal(const StreamedObj& obj, int vn) {
    if (vn < 0) return -1;
    const float len = length(obj.normals[static_cast<size_t>(vn)]);
    return std::isfinite(len) && len > 0.0f ? vn : -1;
}

/// The kept faces as polygons over vertices made of unique (v, vn, vt) corners, numbered in order
/// of first use; indices checked, with the face's line. Triangulation and missing normals are left
/// to build_mesh, as for every format.
PolygonMesh to_polygons(const std::filesystem::path& file, StreamedObj& obj,
                        size_t material_count) {
    PolygonMesh mesh = std::move(obj.faces);
    mesh.corners.reserve(obj.corners.size());
    for (int32_t& material : mesh.face_material)
        if (material < -1 || material >= static_cast<int32_t>(material_count)) material = -1;
    // A corner with neither vn nor vt is its position alone: a flat table finds its vertex
    // (the common case, and a hash map's node per vertex costs a million allocations on a big
    // mesh). Corners with either go through the map.
    constexpr uint32_t k_none = UINT32_MAX;
    std::vector<uint32_t> vertex_of_position(obj.positions.size(), k_none);
    std::unordered_map<Corner, uint32_t, CornerHash> vertex_of;
    auto vertex = [&](const Corner& c) {
        const auto next = static_cast<uint32_t>(mesh.positions.size());
        bool inserted = false;
        uint32_t found = 0;
        if (c.vn < 0 && c.vt < 0) {
            uint32_t& v = vertex_of_position[static_cast<size_t>(c.v)];
            inserted = v == k_none;
            if (inserted) v = next;
            found = v;
        } else {
            const auto it = vertex_of.try_emplace(c, next);
            inserted = it.second;
            found = it.first->second;
        }
        if (inserted) {
            mesh.positions.push_back(obj.positions[static_cast<size_t>(c.v)]);
            if (obj.has_normals)
                mesh.normals.push_back(c.vn >= 0 ? obj.normals[static_cast<size_t>(c.vn)]
                                                 : Vec3(0.0f));
            if (obj.has_uvs)
                mesh.uvs.push_back(c.vt >= 0 ? obj.texcoords[static_cast<size_t>(c.vt)] : Vec2{});
            if (!obj.colors.empty()) mesh.colors.push_back(obj.colors[static_cast<size_t>(c.v)]);
        }
        return found;
    };
    for (size_t f = 0; f < mesh.face_count(); ++f) {
        if (f % 65536 == 0) throw_if_cancelled();  // SIGINT / SIGTERM
        for (uint32_t k = mesh.face_start[f]; k < mesh.face_start[f + 1]; ++k) {
            const Corner& c = obj.corners[k];
            check_corner(file, mesh.face_line[f], c, obj);
            mesh.corners.push_back(vertex({c.v, usable_normal(obj, c.vn), c.vt}));
        }
    }
    return mesh;
}

/// build_mesh over `mesh`, counting the `dropped` triangles pass 2 left out as if build_mesh had
/// dropped them itself: in degenerate_skipped, and in the error for a mesh of nothing else.
MeshData build_mesh_counting(const std::filesystem::path& file, PolygonMesh mesh,
                             const MeshOptions& options, size_t dropped) {
    const auto all_degenerate = [&](size_t count) {
        return InputError(
            fmt::format("{}: no usable triangles: all {} are degenerate", file.string(), count));
    };
    if (dropped > 0 && mesh.face_count() == 0) throw all_degenerate(dropped);
    try {
        MeshData out = build_mesh(file, std::move(mesh), options);
        out.degenerate_skipped += dropped;
        return out;
    } catch (const InputError& e) {
        const std::string prefix = file.string() + ": no usable triangles: all ";
        const std::string_view message = e.what();
        size_t count = 0;
        if (dropped == 0 || !message.starts_with(prefix)) throw;
        const auto [end, ec] =
            std::from_chars(message.data() + prefix.size(), message.data() + message.size(), count);
        if (ec != std::errc() || std::string_view(end) != " are degenerate") throw;
        throw all_degenerate(count + dropped);
    }
}

/// The triangles tinyobjloader made of the faces, in file order, as position indices. It passes
/// a triangle's indices through unchecked, so one naming a vertex the file does not define (a
/// relative index before the first one, too) is refused here, by its number.
std::vector<std::array<uint32_t, 3>> triangle_positions(const std::filesystem::path& file,
                                                        const ParsedObj& parsed) {
    const size_t vertex_count = parsed.attrib.vertices.size() / 3;
    std::vector<std::array<uint32_t, 3>> triangles;
    for (const auto& shape : parsed.shapes) {
        const std::vector<tinyobj::index_t>& corners = shape.mesh.indices;
        for (size_t f = 0; f + 2 < corners.size(); f += 3) {
            std::array<uint32_t, 3> tri{};
            for (size_t c = 0; c < 3; ++c) {
                const int v = corners[f + c].vertex_index;
                if (v < 0 || static_cast<size_t>(v) >= vertex_count)
                    fail(file, 0,
                         fmt::format("triangle {} refers to a vertex out of range (the file has {} "
                                     "vertices)",
                                     triangles.size() + 1, vertex_count));
                tri[c] = static_cast<uint32_t>(v);
            }
            triangles.push_back(tri);
        }
    }
    return triangles;
}

}  // namespace

MeshData load_obj(const std::filesystem::path& file, const MeshOptions& options) {
    // The text and its line table (an offset a line, as long as the shortest lines) are held
    // together: twice the file, checked against --max-memory before a byte is read.
    const std::string text =
        read_file_bytes(file, InputKind::mesh,
                        {.memory_per_byte = 2, .what = "reading the OBJ file", .check_head = {}});
    const size_t face_lines = count_face_lines(text);
    check_obj_memory(file, face_lines, 3 * face_lines, 0, 0);
    MtlReader mtl_reader(file.parent_path());
    LineTable lines = scan_obj_text(file, text, mtl_reader);
    const bool corners_share_positions = lines.vt_count == 0 && lines.vn_count == 0;
    check_obj_memory(
        file, lines.f.size(), lines.corner_count,
        lines.v_count + lines.vt_count + lines.vn_count +
            (lines.v_colors.empty() ? 0 : lines.v_count),
        corners_share_positions ? std::min(lines.v_count, lines.corner_count) : lines.corner_count);
    std::vector<std::string> warnings = check_statements(file, lines, mtl_reader);

    StreamedObj streamed = ObjStreamer(lines).run(text);
    streamed.colors = std::move(lines.v_colors);
    if (!streamed.colors.empty()) streamed.colors.resize(streamed.positions.size(), Vec3(1.0f));
    const std::vector<tinyobj::material_t>& materials = lines.materials;
    PolygonMesh mesh = to_polygons(file, streamed, materials.size());
    const size_t dropped = streamed.degenerate_dropped;
    streamed = {};  // the attributes are in the polygons now
    mesh.warnings = std::move(warnings);
    std::vector<std::filesystem::path> library = mtl_reader.library_of_material();
    library.resize(materials.size(), file);
    std::vector<MtlMaterialLines> material_lines = mtl_reader.lines_of_material();
    material_lines.resize(materials.size());
    TextureFiles textures;
    for (size_t k = 0; k < materials.size(); ++k)
        mesh.materials.push_back(
            to_material(materials[k], library[k], material_lines[k], textures));
    return build_mesh_counting(file, std::move(mesh), options, dropped);
}

ObjTriangles load_obj_triangles(const std::filesystem::path& file) {
    // No line table, no number check, and tinyobjloader's own triangulation: the peers read the
    // file with tinyobjloader alone.
    const std::string text = read_file_bytes(file, InputKind::mesh);
    ParsedObj parsed;
    std::string warn, err;
    if (!run_tinyobj(text, nullptr, /*triangulate=*/true, parsed, warn, err)) {
        const size_t end = err.find_last_not_of(" \t\r\n");
        fail(file, 0, end == std::string::npos ? "cannot parse OBJ" : err.substr(0, end + 1));
    }
    ObjTriangles mesh;
    mesh.indices = triangle_positions(file, parsed);
    if (mesh.indices.empty()) fail(file, 0, "no triangles");
    const std::vector<tinyobj::real_t>& v = parsed.attrib.vertices;
    mesh.positions.resize(v.size() / 3);
    for (size_t i = 0; i < mesh.positions.size(); ++i) mesh.positions[i] = vec3_at(v, int(i));
    return mesh;
}

}  // namespace hikari
