#include "hikari/io/models/model_references.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "hikari/core/memory_budget.h"
#include "hikari/io/files/input_limits.h"

namespace hikari {

namespace {

namespace fs = std::filesystem;

/// The most a referenced text file (MTL, glTF JSON) is read to find the names in it.
constexpr std::uintmax_t k_max_reference_text = 64u << 20;
/// The longest line kept across a block boundary while looking for `mtllib`.
constexpr size_t k_max_carried_line = 4096;

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// The blank-separated words of `line`.
std::vector<std::string> words_of(std::string_view line) {
    std::vector<std::string> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        const size_t start = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        if (i > start) words.emplace_back(line.substr(start, i - start));
    }
    return words;
}

/// A text file's contents, or nothing when it is missing, unreadable or too large.
std::string small_text(const fs::path& file) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec || size > k_max_reference_text) return {};
    std::ifstream in(file, std::ios::binary);
    std::string text(size, '\0');
    if (!in.read(text.data(), static_cast<std::streamsize>(size))) return {};
    return text;
}

/// Calls `line(text)` for every line of `file`, read in blocks; lines longer than
/// k_max_carried_line are cut there (no statement worth finding is longer).
template <class OnLine>
void for_each_line(const fs::path& file, OnLine&& line) {
    std::ifstream in(file, std::ios::binary);
    std::array<char, 1 << 16> block;
    std::string carried;
    while (in.read(block.data(), block.size()) || in.gcount() > 0) {
        const std::string_view data(block.data(), static_cast<size_t>(in.gcount()));
        size_t start = 0;
        for (size_t end = data.find('\n'); end != std::string_view::npos;
             start = end + 1, end = data.find('\n', start)) {
            carried.append(data.substr(start, std::min(end - start, k_max_carried_line)));
            line(std::string_view(carried));
            carried.clear();
        }
        if (carried.size() < k_max_carried_line)
            carried.append(data.substr(
                start, std::min(data.size() - start, k_max_carried_line - carried.size())));
    }
    if (!carried.empty()) line(std::string_view(carried));
}

/// MTL statements naming an image: map_Kd, map_Ka, map_Ks, map_Ns, map_d, map_bump, bump,
/// disp, decal, refl, norm (options before the name; the name last).
bool names_texture(std::string_view keyword) {
    return keyword.starts_with("map_") || keyword == "bump" || keyword == "disp" ||
           keyword == "decal" || keyword == "refl" || keyword == "norm";
}

void add_mtl_textures(const fs::path& library, std::vector<fs::path>& out) {
    const std::string text = small_text(library);
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::vector<std::string> words =
            words_of(std::string_view(text).substr(start, end - start));
        if (words.size() >= 2 && names_texture(words.front())) {
            std::string name = words.back();
            std::replace(name.begin(), name.end(), '\\', '/');  // as the OBJ loader reads it
            out.push_back(library.parent_path() / name);
        }
        start = end + 1;
    }
}

/// Whether the OBJ loader refuses `obj` from its size alone (the mesh input limit, or its text
/// and line table, twice the file, over --max-memory; obj_loader.cpp): a file it never reads
/// is not scanned for its libraries either, which for a 4 GiB file took half a minute.
bool obj_refused_by_size(const fs::path& obj) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(obj, ec);
    return !ec && (size > input_limit(InputKind::mesh) ||
                   2.0 * static_cast<double>(size) > memory_limit());
}

void add_obj_references(const fs::path& obj, std::vector<fs::path>& out) {
    if (obj_refused_by_size(obj)) return;
    std::vector<fs::path> libraries;
    for_each_line(obj, [&](std::string_view line) {
        while (!line.empty() && is_blank(line.front())) line.remove_prefix(1);
        if (!line.starts_with("mtllib") || line.size() < 7 || !is_blank(line[6])) return;
        for (const std::string& name : words_of(line.substr(7)))
            libraries.push_back(obj.parent_path() / name);
    });
    for (const fs::path& library : libraries) {
        out.push_back(library);
        add_mtl_textures(library, out);
    }
}

/// A binary glTF's JSON chunk (the first chunk after the 12-byte header), or nothing.
std::string glb_json(const fs::path& glb) {
    std::ifstream in(glb, std::ios::binary);
    uint32_t header[5] = {};
    if (!in.read(reinterpret_cast<char*>(header), sizeof(header))) return {};
    constexpr uint32_t k_magic = 0x46546C67, k_json = 0x4E4F534A;  // "glTF", "JSON"
    if (header[0] != k_magic || header[4] != k_json || header[3] > k_max_reference_text) return {};
    std::string text(header[3], '\0');
    if (!in.read(text.data(), static_cast<std::streamsize>(text.size()))) return {};
    return text;
}

void add_gltf_references(const fs::path& gltf, bool binary, std::vector<fs::path>& out) {
    const nlohmann::json json =
        nlohmann::json::parse(binary ? glb_json(gltf) : small_text(gltf), nullptr, false);
    if (!json.is_object()) return;
    for (const char* list : {"images", "buffers"}) {
        const auto found = json.find(list);
        if (found == json.end() || !found->is_array()) continue;
        for (const nlohmann::json& item : *found) {
            if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
            const std::string uri = item["uri"].get<std::string>();
            if (!uri.starts_with("data:")) out.push_back(gltf.parent_path() / uri);
        }
    }
}

}  // namespace

std::vector<fs::path> model_references(const fs::path& model) {
    std::string ext = model.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::vector<fs::path> out;
    std::error_code ec;
    if (!fs::is_regular_file(model, ec)) return out;
    if (ext == ".obj")
        add_obj_references(model, out);
    else if (ext == ".gltf" || ext == ".glb")
        add_gltf_references(model, ext == ".glb", out);
    return out;
}

}  // namespace hikari
