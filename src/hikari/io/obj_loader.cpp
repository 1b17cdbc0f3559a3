#include "hikari/io/obj_loader.h"

#include <tiny_obj_loader.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/material_rules.h"
#include "hikari/io/mesh_builder.h"
#include "hikari/io/mtl_scan.h"
#include "hikari/io/printable_text.h"
#include "hikari/io/read_file.h"
#include "hikari/io/text_number.h"
#include "hikari/io/texture_files.h"

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

// --- Pass 1: our own scan of the text ----------------------------------------------------------
// tinyobjloader 2.0.0rc10 reads a malformed number as 0 without a word, accepts faces with
// indices out of range (only a warning for the largest one), and keeps no line numbers. This scan
// checks every number strictly and records the line of each v, vt and face, so later checks can
// point at the line. It splits lines and tokens exactly as tinyobjloader does.

/// Line numbers (1-based) of each `v`, `vt` and `f` statement, in order, and the counts that
/// size what tinyobjloader and we are about to allocate.
struct LineTable {
    std::vector<uint32_t> v, vt, f;
    size_t vn_count = 0, corner_count = 0;
    /// Each `mtllib` statement: its line and the rest of the line (the library names).
    std::vector<std::pair<uint32_t, std::string_view>> mtllib;
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

/// Checks that the tokens of `rest` are at least `min_count` finite numbers.
void check_numbers(const std::filesystem::path& file, size_t line, const char* statement,
                   std::string_view rest, size_t min_count) {
    if (const size_t count = count_tokens(rest); count < min_count) {
        fail(file, line,
             fmt::format("'{}' needs {} numbers, found {}", statement, min_count, count));
    }
    for_each_token(rest, [&](std::string_view t) {
        // tinyobjloader stores floats: a finite double beyond FLT_MAX would become infinite.
        std::string why;
        if (!parse_float_token(t, &why)) fail(file, line, fmt::format("'{}': {}", statement, why));
    });
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
        if (!valid)
            fail(file, line,
                 fmt::format("'f': '{}' is not a corner (v, v/vt, v//vn or v/vt/vn, each a "
                             "nonzero index of at most 10 digits that fits in 32 bits)",
                             corner));
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

LineTable scan_obj_text(const std::filesystem::path& file, std::string_view text) {
    LineTable table;
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
            check_numbers(file, line, "v", s.substr(2), 3);
            table.v.push_back(line);
        } else if (s[0] == 'v' && s[1] == 'n' && blank2) {
            check_numbers(file, line, "vn", s.substr(3), 3);
            ++table.vn_count;
        } else if (s[0] == 'v' && s[1] == 't' && blank2) {
            check_numbers(file, line, "vt", s.substr(3), 1);
            table.vt.push_back(line);
        } else if (s[0] == 'f' && blank1) {
            const size_t corners = count_tokens(s.substr(2));
            if (corners < 3 || corners > 255) {
                fail(file, line,
                     "a face needs 3 to 255 corners, this one has " + std::to_string(corners));
            }
            check_face_corners(file, line, s.substr(2));
            table.f.push_back(line);
            table.corner_count += corners;
        } else if (s.starts_with("mtllib") && s.size() > 6 && is_blank(s[6])) {
            table.mtllib.emplace_back(line, s.substr(7));
        }
    }
    return table;
}

/// Refuses, before tinyobjloader runs, a file whose faces would take more memory than
/// --max-memory allows. Bytes per item, measured on a file of ten million triangles (1.8 GB at
/// the peak): tinyobjloader keeps each face as a vector of its own (some 90 bytes with its heap
/// block) and every corner twice (24 bytes), then our polygons and build_mesh take about as much
/// again per corner; attributes are 12 bytes each, kept about twice.
void check_obj_memory(const std::filesystem::path& file, size_t faces, size_t corners,
                      size_t attributes) {
    check_memory_need(100.0 * static_cast<double>(faces) + 40.0 * static_cast<double>(corners) +
                          24.0 * static_cast<double>(attributes),
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

// --- Pass 2: tinyobjloader ---------------------------------------------------------------------

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

ParsedObj parse_with_tinyobj(const std::filesystem::path& file, const std::string& text,
                             const LineTable& lines) {
    ParsedObj parsed;
    MtlReader mtl_reader(file.parent_path());
    std::string warn, err;
    // triangulate = false: rc10 splits quads along the shorter diagonal and ear-clips larger
    // polygons; we fan-triangulate ourselves so triangle order and shape are predictable.
    const bool loaded = run_tinyobj(text, &mtl_reader, /*triangulate=*/false, parsed, warn, err);
    if (const auto& [library, error] = mtl_reader.failure(); !library.empty())
        fail(file, mtllib_line(lines, library), fmt::format("mtllib {}: {}", library, error));
    else if (!error.empty())
        throw InputError(error);
    if (!loaded) {
        const std::vector<std::string> errors = clean_messages(file, err);
        throw InputError(errors.empty() ? where(file, 0) + "cannot parse OBJ" : errors.front());
    }
    // After a successful parse `err` holds only MTL problems: the mesh is still usable.
    parsed.warnings = clean_messages(file, warn + err);
    parsed.material_library = mtl_reader.library_of_material();
    parsed.material_library.resize(parsed.materials.size(), file);
    parsed.material_lines = mtl_reader.lines_of_material();
    parsed.material_lines.resize(parsed.materials.size());
    return parsed;
}

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
             fmt::format("{} of material '{}': cannot use texture \"{}\": {}", keyword, material,
                         texture_name, e.what()));
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
             fmt::format("material '{}', {}: {}", m.name, keyword, problem->message));
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

/// Checks a corner's indices against the attribute counts; `line` is 0 when unknown.
void check_corner(const std::filesystem::path& file, size_t line, const tinyobj::index_t& idx,
                  const tinyobj::attrib_t& attrib) {
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
    check(idx.vertex_index, attrib.vertices.size() / 3, "vertex");
    if (idx.normal_index != -1) check(idx.normal_index, attrib.normals.size() / 3, "normal");
    if (idx.texcoord_index != -1) {
        check(idx.texcoord_index, attrib.texcoords.size() / 2, "texture coordinate");
    }
}

/// The file's normal for a corner, or -1 when it has none or it cannot be normalized.
int usable_normal(const tinyobj::attrib_t& attrib, int vn) {
    if (vn < 0) return -1;
    const Vec3 n = vec3_at(attrib.normals, vn);
    const float len = length(n);
    return std::isfinite(len) && len > 0.0f ? vn : -1;
}

/// The faces as polygons over vertices made of unique (v, vn, vt) corners, numbered in order of
/// first use; indices checked, with the face's line. Triangulation and missing normals are left to
/// build_mesh, as for every format.
PolygonMesh to_polygons(const std::filesystem::path& file, const ParsedObj& parsed,
                        const LineTable& lines) {
    const tinyobj::attrib_t& attrib = parsed.attrib;
    size_t face_count = 0, corner_count = 0;
    bool has_normals = false, has_uvs = false;
    for (const auto& shape : parsed.shapes) {
        face_count += shape.mesh.num_face_vertices.size();
        corner_count += shape.mesh.indices.size();
        for (const tinyobj::index_t& idx : shape.mesh.indices) {
            has_normals |= idx.normal_index >= 0;
            has_uvs |= idx.texcoord_index >= 0;
        }
    }
    const bool know_lines = face_count == lines.f.size();
    PolygonMesh mesh;
    mesh.face_start.reserve(face_count + 1);
    mesh.corners.reserve(corner_count);
    mesh.face_material.reserve(face_count);
    mesh.smoothing_group.reserve(face_count);
    if (know_lines) mesh.face_line.assign(lines.f.begin(), lines.f.end());
    // A corner with neither vn nor vt is its position alone: a flat table finds its vertex
    // (the common case, and a hash map's node per vertex costs a million allocations on a big
    // mesh). Corners with either go through the map.
    constexpr uint32_t k_none = UINT32_MAX;
    std::vector<uint32_t> vertex_of_position(attrib.vertices.size() / 3, k_none);
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
            mesh.positions.push_back(vec3_at(attrib.vertices, c.v));
            if (has_normals)
                mesh.normals.push_back(c.vn >= 0 ? vec3_at(attrib.normals, c.vn) : Vec3(0.0f));
            if (has_uvs)
                mesh.uvs.push_back(c.vt >= 0
                                       ? Vec2{static_cast<float>(attrib.texcoords[2 * c.vt]),
                                              static_cast<float>(attrib.texcoords[2 * c.vt + 1])}
                                       : Vec2{});
        }
        return found;
    };
    size_t face = 0;
    for (const auto& shape : parsed.shapes) {
        const bool has_groups =
            shape.mesh.smoothing_group_ids.size() == shape.mesh.num_face_vertices.size();
        size_t offset = 0;
        for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++face) {
            const size_t n = shape.mesh.num_face_vertices[f];
            const size_t line = know_lines ? lines.f[face] : 0;
            for (size_t k = 0; k < n; ++k) {
                const tinyobj::index_t& idx = shape.mesh.indices[offset + k];
                check_corner(file, line, idx, attrib);
                mesh.corners.push_back(
                    vertex({idx.vertex_index, usable_normal(attrib, idx.normal_index),
                            idx.texcoord_index}));
            }
            offset += n;
            mesh.face_start.push_back(static_cast<uint32_t>(mesh.corners.size()));
            int32_t material = shape.mesh.material_ids[f];
            if (material < -1 || material >= static_cast<int32_t>(parsed.materials.size()))
                material = -1;
            mesh.face_material.push_back(material);
            mesh.smoothing_group.push_back(has_groups ? shape.mesh.smoothing_group_ids[f] : 0);
        }
    }
    return mesh;
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
    const std::string text = read_file_bytes(file, InputKind::mesh);
    const size_t face_lines = count_face_lines(text);
    check_obj_memory(file, face_lines, 3 * face_lines, 0);
    const LineTable lines = scan_obj_text(file, text);
    check_obj_memory(file, lines.f.size(), lines.corner_count,
                     lines.v.size() + lines.vt.size() + lines.vn_count);
    const ParsedObj parsed = parse_with_tinyobj(file, text, lines);

    PolygonMesh mesh = to_polygons(file, parsed, lines);
    mesh.warnings = parsed.warnings;
    TextureFiles textures;
    for (size_t k = 0; k < parsed.materials.size(); ++k)
        mesh.materials.push_back(to_material(parsed.materials[k], parsed.material_library[k],
                                             parsed.material_lines[k], textures));
    return build_mesh(file, std::move(mesh), options);
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
