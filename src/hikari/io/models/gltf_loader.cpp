#include "hikari/io/models/gltf_loader.h"

// tinygltf's implementation is compiled here and nowhere else. Its own file access and image
// decoding are switched off: buffers are read through read_file_bytes (bounded, regular files
// only) by the callbacks below, external images through TextureFiles, embedded ones by
// io/image_read.h, so one stb_image build decodes every image of hikari.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_FS
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
// tinygltf 2.7.0 writes files with std::ofstream even under TINYGLTF_NO_FS.
#include <fstream>

#include <tiny_gltf.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>

#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/mat4.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/texture_files.h"
#include "hikari/io/models/material_rules.h"
#include "hikari/shading/textures/mip_pyramid.h"

namespace hikari {

namespace {

// glTF stores numbers little-endian; they are copied out of buffers as they lie.
static_assert(std::endian::native == std::endian::little);

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& file, std::string_view what) {
    throw InputError(printable_text(fmt::format("{}: {}", file.string(), what)));
}

/// list[index], after checking that it exists; `where` ("mesh 2 primitive 0: ") and `kind`
/// ("accessor") name it in the error.
template <class T>
const T& element(const fs::path& file, const std::vector<T>& list, long long index,
                 std::string_view kind, std::string_view where) {
    if (index < 0 || static_cast<unsigned long long>(index) >= list.size()) {
        fail(file, fmt::format("{}{} {} does not exist (the file has {})", where, kind, index,
                               list.size()));
    }
    return list[static_cast<size_t>(index)];
}

// --- Before tinygltf: the GLB container and the JSON
// ---------------------------------------------- tinygltf 2.7.0 reads up to 8 bytes past a GLB
// whose BIN chunk claims the last bytes, and passes an image's bufferView to the image loader
// without checking it lies inside its buffer. Both are checked here first, as is the JSON's nesting
// (tinygltf copies `extras` recursively).

constexpr uint32_t k_glb_magic = 0x46546C67;  // "glTF"
constexpr uint32_t k_chunk_json = 0x4E4F534A;
constexpr uint32_t k_chunk_bin = 0x004E4942;
constexpr int k_max_json_depth = 64;
/// The most vertices the scene may instance in all: nodes that instance one mesh many times
/// multiply its vertices, so a small file could otherwise ask for any amount of memory.
constexpr size_t k_max_vertices = size_t{1} << 28;

uint32_t u32_at(std::string_view bytes, size_t pos) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + pos, 4);
    return v;
}

bool is_glb(std::string_view bytes) { return bytes.size() >= 4 && u32_at(bytes, 0) == k_glb_magic; }

/// Refuses, from the first bytes and the file's size, a glTF or GLB file tinygltf cannot take
/// (4 GiB or more) and a GLB whose header is not version 2 or claims more bytes than the file has.
void check_gltf_head(const fs::path& file, std::string_view head, uint64_t size) {
    if (size > UINT32_MAX) fail(file, "a glTF or GLB file must be smaller than 4 GiB");
    if (!is_glb(head)) return;
    if (head.size() < 20 || size < 20)
        fail(file, fmt::format("truncated GLB: {} bytes, the header alone takes 20", size));
    if (const uint32_t version = u32_at(head, 4); version != 2)
        fail(file, fmt::format("GLB version {} (only version 2 is read)", version));
    if (const uint64_t length = u32_at(head, 8); length > size) {
        fail(file,
             fmt::format("truncated GLB: the header says {} bytes, the file has {}", length, size));
    }
}

/// The JSON chunk of a GLB file (glTF 2.0 §4.4: a 12-byte header, then chunks of length, type
/// and data), after checking that every chunk lies inside the file.
std::string_view glb_json_chunk(const fs::path& file, std::string_view bytes) {
    if (bytes.size() < 20)
        fail(file, fmt::format("truncated GLB: {} bytes, the header alone takes 20", bytes.size()));
    if (const uint32_t version = u32_at(bytes, 4); version != 2)
        fail(file, fmt::format("GLB version {} (only version 2 is read)", version));
    const uint64_t length = u32_at(bytes, 8);
    if (length > bytes.size()) {
        fail(file, fmt::format("truncated GLB: the header says {} bytes, the file has {}", length,
                               bytes.size()));
    }
    const uint64_t json_length = u32_at(bytes, 12);
    if (u32_at(bytes, 16) != k_chunk_json) fail(file, "GLB: the first chunk is not JSON");
    if (20 + json_length > length)
        fail(file,
             fmt::format("truncated GLB: the JSON chunk of {} bytes does not fit", json_length));
    const uint64_t bin = 20 + json_length;
    if (bin < length) {
        if (bin + 8 > length) fail(file, "truncated GLB: a chunk header does not fit");
        const uint64_t bin_length = u32_at(bytes, bin);
        if (u32_at(bytes, bin + 4) == k_chunk_bin && bin + 8 + bin_length > length) {
            fail(file,
                 fmt::format("truncated GLB: the BIN chunk of {} bytes does not fit", bin_length));
        }
    }
    return bytes.substr(20, json_length);
}

/// The JSON document, parsed once here to report syntax errors with their position and to bound
/// the nesting depth.
nlohmann::json parse_json(const fs::path& file, std::string_view text) {
    const auto limit_depth = [&](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
        if (depth > k_max_json_depth)
            fail(file, fmt::format("JSON nested deeper than {} levels", k_max_json_depth));
        return true;
    };
    try {
        return nlohmann::json::parse(text.begin(), text.end(), limit_depth);
    } catch (const nlohmann::json::exception& e) {
        // nlohmann's messages start with "[json.exception.parse_error.101] ".
        std::string_view what = e.what();
        if (const size_t end = what.find("] "); what.starts_with('[') && end != what.npos)
            what.remove_prefix(end + 2);
        fail(file, fmt::format("invalid JSON: {}", what));
    }
}

/// An unsigned integer member of a JSON object, or `fallback` when absent; fails when present but
/// not an unsigned integer.
uint64_t json_unsigned(const fs::path& file, const nlohmann::json& object, const char* key,
                       std::optional<uint64_t> fallback, std::string_view where) {
    const auto it = object.find(key);
    if (it == object.end() && fallback) return *fallback;
    if (it == object.end() || !it->is_number_unsigned())
        fail(file,
             fmt::format("{}{} must be a non-negative integer", where, quote_token(key, '"')));
    return it->get<uint64_t>();
}

/// Checks that every image stored in a bufferView names one that lies inside its buffer's
/// declared byteLength (which tinygltf makes the buffer's actual size).
void check_image_buffer_views(const fs::path& file, const nlohmann::json& doc) {
    if (!doc.is_object()) fail(file, "the glTF JSON is not an object");
    const auto images = doc.find("images");
    if (images == doc.end() || !images->is_array()) return;
    const nlohmann::json empty = nlohmann::json::array();
    const auto array_of = [&](const char* key) -> const nlohmann::json& {
        const auto it = doc.find(key);
        return it != doc.end() && it->is_array() ? *it : empty;
    };
    const nlohmann::json& views = array_of("bufferViews");
    const nlohmann::json& buffers = array_of("buffers");
    for (size_t i = 0; i < images->size(); ++i) {
        const nlohmann::json& image = (*images)[i];
        if (!image.is_object() || !image.contains("bufferView")) continue;
        const std::string at = fmt::format("image {}: ", i);
        const uint64_t v = json_unsigned(file, image, "bufferView", std::nullopt, at);
        if (v >= views.size() || !views[v].is_object())
            fail(file, fmt::format("{}bufferView {} does not exist", at, v));
        const std::string view_at = fmt::format("{}bufferView {}: ", at, v);
        const uint64_t b = json_unsigned(file, views[v], "buffer", std::nullopt, view_at);
        if (b >= buffers.size() || !buffers[b].is_object())
            fail(file, fmt::format("{}buffer {} does not exist", view_at, b));
        const uint64_t offset = json_unsigned(file, views[v], "byteOffset", 0, view_at);
        const uint64_t length = json_unsigned(file, views[v], "byteLength", std::nullopt, view_at);
        const uint64_t size = json_unsigned(file, buffers[b], "byteLength", std::nullopt,
                                            fmt::format("buffer {}: ", b));
        if (offset > size || length > size - offset) {
            fail(file, fmt::format("{}bytes {} to {} lie outside buffer {} ({} bytes)", view_at,
                                   offset, offset + length, b, size));
        }
    }
}

/// Refuses a file that requires an extension hikari does not read (glTF 2.0 §3.12).
void check_required_extensions(const fs::path& file, const tinygltf::Model& model) {
    static constexpr std::array<std::string_view, 3> k_read = {
        "KHR_lights_punctual", "KHR_materials_ior", "KHR_materials_emissive_strength"};
    for (const std::string& name : model.extensionsRequired) {
        if (std::find(k_read.begin(), k_read.end(), name) == k_read.end())
            fail(file, fmt::format("requires the extension {}, which hikari does not read", name));
    }
}

// --- tinygltf's callbacks
// ---------------------------------------------------------------------------

/// What the file callbacks share: the first error read_file_bytes gave, which names the file.
struct FileAccess {
    std::string first_error;
};

// Every candidate "exists", so tinygltf reads the first one (the URI relative to the model's
// directory) and its failure is reported, rather than looking in the working directory next.
bool file_exists(const std::string&, void*) { return true; }

std::string expand_file_path(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user_data) {
    try {
        const std::string bytes = read_file_bytes(path, InputKind::mesh);
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputError& e) {
        auto* access = static_cast<FileAccess*>(user_data);
        if (access->first_error.empty()) access->first_error = e.what();
        if (err) *err += e.what();
        return false;
    }
}

/// The image loader: keeps an embedded image's encoded bytes, decoded later only when a
/// material uses it.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
    if (size < 0) return false;
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

/// The first line of a tinygltf message, without trailing blanks.
std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    return line;
}

tinygltf::Model parse_with_tinygltf(const fs::path& file, const std::string& bytes,
                                    std::vector<std::string>& warnings) {
    std::string_view json_text = bytes;
    const bool binary = is_glb(bytes);
    // tinygltf takes sizes as unsigned int.
    if (bytes.size() > UINT32_MAX) fail(file, "a glTF or GLB file must be smaller than 4 GiB");
    if (binary) json_text = glb_json_chunk(file, bytes);
    check_image_buffer_views(file, parse_json(file, json_text));

    tinygltf::TinyGLTF gltf;
    FileAccess access;
    gltf.SetFsCallbacks({&file_exists, &expand_file_path, &read_whole_file, nullptr, &access});
    gltf.SetImageLoader(&keep_encoded_image, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const std::string base_dir = file.parent_path().string();
    bool loaded = false;
    try {
        loaded =
            binary ? gltf.LoadBinaryFromMemory(&model, &err, &warn,
                                               reinterpret_cast<const unsigned char*>(bytes.data()),
                                               static_cast<unsigned int>(bytes.size()), base_dir)
                   : gltf.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                              static_cast<unsigned int>(bytes.size()), base_dir);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        // nlohmann's type errors and std::out_of_range from tinygltf's vector accesses.
        fail(file, fmt::format("malformed glTF: {}", e.what()));
    }
    if (!access.first_error.empty()) fail(file, access.first_error);
    if (!loaded) fail(file, err.empty() ? "cannot read glTF" : first_line(err));
    for (size_t begin = 0; begin < warn.size();) {
        const size_t end = std::min(warn.find('\n', begin), warn.size());
        if (end > begin)
            warnings.push_back(
                fmt::format("{}: {}", file.string(), warn.substr(begin, end - begin)));
        begin = end + 1;
    }
    return model;
}

// --- Accessors (glTF 2.0 §3.6.2)
// --------------------------------------------------------------------

/// Where an accessor's elements lie, after every range has been checked.
struct AccessorData {
    const unsigned char* first = nullptr;  ///< element 0
    size_t count = 0;
    size_t stride = 0;  ///< bytes from one element to the next
    int component_type = 0;
    int components = 0;
    bool normalized = false;
};

size_t component_bytes(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

int type_components(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        default:
            return 0;  // matrices: no vertex attribute hikari reads is one
    }
}

AccessorData accessor_data(const fs::path& file, const tinygltf::Model& model, int index,
                           const std::string& where) {
    const tinygltf::Accessor& a = element(file, model.accessors, index, "accessor", where);
    const std::string at = fmt::format("{}accessor {}: ", where, index);
    if (a.sparse.isSparse) fail(file, at + "sparse accessors are not supported");
    if (a.bufferView == -1)
        fail(file, at + "has no bufferView (only sparse accessors may omit it, unsupported)");
    const tinygltf::BufferView& view =
        element(file, model.bufferViews, a.bufferView, "bufferView", at);
    const std::string view_at = fmt::format("{}bufferView {}: ", at, a.bufferView);
    const tinygltf::Buffer& buffer = element(file, model.buffers, view.buffer, "buffer", view_at);
    const size_t component_size = component_bytes(a.componentType);
    const int components = type_components(a.type);
    if (component_size == 0 || components == 0)
        fail(file,
             fmt::format("{}unsupported componentType {} or type {}", at, a.componentType, a.type));
    const size_t element_size = component_size * static_cast<size_t>(components);
    const size_t stride = view.byteStride != 0 ? view.byteStride : element_size;
    if (stride < element_size)
        fail(file, fmt::format("{}byteStride {} is less than the element size {}", view_at,
                               view.byteStride, element_size));
    const size_t size = buffer.data.size();
    if (view.byteOffset > size || view.byteLength > size - view.byteOffset) {
        fail(file, fmt::format("{}bytes {} + {} lie outside buffer {} ({} bytes)", view_at,
                               view.byteOffset, view.byteLength, view.buffer, size));
    }
    AccessorData data{nullptr, a.count, stride, a.componentType, components, a.normalized};
    if (a.count == 0) return data;
    // The last element ends at byteOffset + stride (count - 1) + element_size: checked without
    // overflow against the view's length.
    if (a.byteOffset > view.byteLength || element_size > view.byteLength - a.byteOffset ||
        (a.count - 1) > (view.byteLength - a.byteOffset - element_size) / stride) {
        fail(file, fmt::format("{}{} elements of {} bytes, {} bytes apart from byte {}, do not fit "
                               "in bufferView {} ({} bytes)",
                               at, a.count, element_size, stride, a.byteOffset, a.bufferView,
                               view.byteLength));
    }
    data.first = buffer.data.data() + view.byteOffset + a.byteOffset;
    return data;
}

template <class T>
T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

/// Component `c` of element `i`, as a float; normalized integers map to [0, 1] or [-1, 1]
/// (glTF 2.0 §3.11, "Animations": c / (2^n - 1), signed ones clamped at -1).
float component(const AccessorData& d, size_t i, int c) {
    const unsigned char* p =
        d.first + i * d.stride + static_cast<size_t>(c) * component_bytes(d.component_type);
    switch (d.component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return load<float>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return d.normalized ? p[0] / 255.0f : p[0];
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return d.normalized ? std::max(load<int8_t>(p) / 127.0f, -1.0f) : load<int8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return d.normalized ? load<uint16_t>(p) / 65535.0f : load<uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return d.normalized ? std::max(load<int16_t>(p) / 32767.0f, -1.0f) : load<int16_t>(p);
        default:
            return static_cast<float>(load<uint32_t>(p));
    }
}

uint32_t index_at(const AccessorData& d, size_t i) {
    const unsigned char* p = d.first + i * d.stride;
    switch (d.component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return p[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return load<uint16_t>(p);
        default:
            return load<uint32_t>(p);
    }
}

Vec3 vec3_at(const AccessorData& d, size_t i) {
    return {component(d, i, 0), component(d, i, 1), component(d, i, 2)};
}

// --- The reader
// ---------------------------------------------------------------------------------------

/// The Blinn-Phong exponent that matches a microfacet lobe of glTF roughness r: Walter et al. 2007
/// ("Microfacet Models for Refraction through Rough Surfaces", §5.2) relate the Phong exponent to
/// the Beckmann width α as n = 2/α² − 2, and glTF's α is r² (glTF 2.0 Appendix B).
float shininess_from_roughness(float roughness) {
    const float alpha = roughness * roughness;
    if (alpha <= 0.0f) return 10000.0f;
    return std::clamp(2.0f / (alpha * alpha) - 2.0f, 1.0f, 10000.0f);
}

float clamp01(double v) { return std::clamp(static_cast<float>(v), 0.0f, 1.0f); }

/// A numeric member of an extension object (KHR_materials_ior's "ior"), when present.
std::optional<double> extension_number(const tinygltf::ExtensionMap& extensions,
                                       const char* extension, const char* key) {
    const auto it = extensions.find(extension);
    if (it == extensions.end() || !it->second.IsObject() || !it->second.Has(key))
        return std::nullopt;
    const tinygltf::Value& v = it->second.Get(key);
    if (!v.IsNumber()) return std::nullopt;
    return v.GetNumberAsDouble();
}

class GltfReader {
  public:
    GltfReader(const fs::path& file, const tinygltf::Model& model) : m_file(file), m_model(model) {}

    GltfContent read() {
        check_required_extensions(m_file, m_model);
        for (size_t i = 0; i < m_model.materials.size(); ++i)
            m_out.mesh.materials.push_back(to_material(m_model.materials[i], i));
        walk_scene();
        finish();
        return std::move(m_out);
    }

  private:
    // --- Materials (docs/scene-format.md, "glTF models", states the mapping) ---

    Material to_material(const tinygltf::Material& m, size_t index) {
        const std::string at = fmt::format("material {} {}: ", index, quote_token(m.name, '"'));
        const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
        const std::vector<double>& base = pbr.baseColorFactor;
        if (base.size() != 4 ||
            !std::all_of(base.begin(), base.end(), [](double v) { return std::isfinite(v); }))
            fail(m_file, at + "baseColorFactor must be 4 finite numbers");
        const Vec3 base_rgb{clamp01(base[0]), clamp01(base[1]), clamp01(base[2])};
        const float metallic = clamp01(pbr.metallicFactor);
        const float roughness = clamp01(pbr.roughnessFactor);
        if (!std::isfinite(pbr.metallicFactor) || !std::isfinite(pbr.roughnessFactor))
            fail(m_file, at + "metallicFactor and roughnessFactor must be finite");

        Material out;
        out.name = m.name.empty() ? fmt::format("material {}", index) : m.name;
        out.kd = base_rgb;
        out.ka = base_rgb;
        // Specular colour: the Fresnel reflectance at normal incidence, 0.04 for dielectrics and
        // the base colour for metals (glTF 2.0 Appendix B), dimmed as the highlight spreads.
        const Vec3 f0 = Vec3(0.04f) * (1.0f - metallic) + base_rgb * metallic;
        out.ks = f0 * ((1.0f - roughness) * (1.0f - roughness));
        out.shininess = shininess_from_roughness(roughness);
        out.ior = 1.5f;  // glTF's default index of refraction (KHR_materials_ior)
        if (const auto ior = extension_number(m.extensions, "KHR_materials_ior", "ior")) {
            if (std::isfinite(*ior) && *ior >= 1.0) out.ior = static_cast<float>(*ior);
        }
        if (m.alphaMode == "BLEND" && base[3] < 1.0) out.transparency = 1.0f - clamp01(base[3]);

        const std::vector<double>& e = m.emissiveFactor;
        if (e.size() != 3 ||
            !std::all_of(e.begin(), e.end(), [](double v) { return std::isfinite(v) && v >= 0; }))
            fail(m_file, at + "emissiveFactor must be 3 finite numbers, not negative");
        double strength = 1.0;
        if (const auto s = extension_number(m.extensions, "KHR_materials_emissive_strength",
                                            "emissiveStrength")) {
            if (std::isfinite(*s) && *s >= 0) strength = *s;
        }
        out.emission =
            Vec3(static_cast<float>(e[0] * strength), static_cast<float>(e[1] * strength),
                 static_cast<float>(e[2] * strength));
        if (!is_finite(out.emission)) fail(m_file, at + "emission is not finite");
        if (const auto problem = find_material_problem(out)) fail(m_file, at + problem->message);
        out.texture = base_color_texture(pbr.baseColorTexture, at + "baseColorTexture: ");
        return out;
    }

    std::optional<Texture> base_color_texture(const tinygltf::TextureInfo& info,
                                              const std::string& at) {
        if (info.index == -1) return std::nullopt;
        const tinygltf::Texture& texture =
            element(m_file, m_model.textures, info.index, "texture", at);
        const std::string texture_at = fmt::format("{}texture {}: ", at, info.index);
        if (texture.source == -1) {
            // The image is given by an extension hikari does not read (KHR_texture_basisu, ...).
            m_out.mesh.warnings.push_back(fmt::format("{}: {}no image hikari can read; ignored",
                                                      m_file.string(), texture_at));
            return std::nullopt;
        }
        if (info.texCoord != 0) {
            m_out.mesh.warnings.push_back(
                fmt::format("{}: {}uses TEXCOORD_{}; hikari reads TEXCOORD_0 only", m_file.string(),
                            at, info.texCoord));
        }
        ImageTexture out;
        out.pyramid = image_pyramid(texture.source, texture_at);
        const tinygltf::Image& image = m_model.images[static_cast<size_t>(texture.source)];
        out.file = image.uri.empty()
                       ? fmt::format("{}#image{}", m_file.filename().string(), texture.source)
                       : image.uri;
        if (texture.sampler != -1) {
            const tinygltf::Sampler& s =
                element(m_file, m_model.samplers, texture.sampler, "sampler", texture_at);
            apply_sampler(s, out, texture_at);
        }
        return out;
    }

    /// glTF's sampler as far as hikari's textures follow it: one wrap mode for both axes and a
    /// filter (mirrored repeat becomes repeat).
    void apply_sampler(const tinygltf::Sampler& s, ImageTexture& out, const std::string& at) {
        const bool clamp_s = s.wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        const bool clamp_t = s.wrapT == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        out.wrap = clamp_s && clamp_t ? TextureWrap::clamp : TextureWrap::repeat;
        if (clamp_s != clamp_t || s.wrapS == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ||
            s.wrapT == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) {
            m_out.mesh.warnings.push_back(fmt::format(
                "{}: {}wrap modes {} and {} are read as {} on both axes", m_file.string(), at,
                s.wrapS, s.wrapT, out.wrap == TextureWrap::clamp ? "clamp" : "repeat"));
        }
        const bool mip = s.minFilter >= TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST &&
                         s.minFilter <= TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
        if (s.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST &&
            s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST)
            out.filter = TextureFilter::nearest;
        else if (s.minFilter != -1 && !mip)
            out.filter = TextureFilter::bilinear;
        else
            out.filter = TextureFilter::trilinear;
    }

    /// The mipmap pyramid of image `index`: an external file through TextureFiles (read once),
    /// an embedded one (data: URI or bufferView) decoded from memory once.
    std::shared_ptr<const MipPyramid> image_pyramid(int index, const std::string& at) {
        const tinygltf::Image& image = element(m_file, m_model.images, index, "image", at);
        const std::string image_at = fmt::format("{}image {}: ", at, index);
        if (!image.image.empty()) {
            auto& cached = m_embedded[index];
            if (!cached) {
                const fs::path name = fmt::format("{} image {}", m_file.string(), index);
                const std::string bytes(image.image.begin(), image.image.end());
                cached = std::make_shared<const MipPyramid>(
                    build_mip_pyramid(decode_png_or_jpeg(name, bytes)));
            }
            return cached;
        }
        if (image.uri.empty()) fail(m_file, image_at + "has no image data");
        try {
            return m_textures.pyramid(m_file.parent_path() / tinygltf::dlib::urldecode(image.uri));
        } catch (const InputError& e) {
            fail(m_file, image_at + e.what());
        }
    }

    // --- The node hierarchy (glTF 2.0 §3.5) ---

    void walk_scene() {
        std::vector<int> roots;
        if (m_model.defaultScene != -1) {
            roots = element(m_file, m_model.scenes, m_model.defaultScene, "scene", "").nodes;
        } else if (!m_model.scenes.empty()) {
            roots = m_model.scenes[0].nodes;
        } else {
            // No scene: every node that is no other's child.
            std::vector<bool> is_child(m_model.nodes.size(), false);
            for (const tinygltf::Node& node : m_model.nodes)
                for (int c : node.children)
                    if (c >= 0 && static_cast<size_t>(c) < is_child.size()) is_child[c] = true;
            for (size_t i = 0; i < is_child.size(); ++i)
                if (!is_child[i]) roots.push_back(static_cast<int>(i));
        }
        // Depth first with an explicit stack: a chain of a million nodes must not overflow the call
        // stack. Each node may be reached once; the hierarchy is a forest (§3.5.1), so a cycle or a
        // shared child is an error rather than an endless or exponential walk.
        std::vector<bool> seen(m_model.nodes.size(), false);
        std::vector<std::pair<int, Mat4>> stack;
        // Pushed last to first, so nodes are visited in file order.
        for (size_t i = roots.size(); i-- > 0;) stack.emplace_back(roots[i], Mat4::identity());
        while (!stack.empty()) {
            const auto [n, parent] = stack.back();
            stack.pop_back();
            const tinygltf::Node& node = element(m_file, m_model.nodes, n, "node", "scene: ");
            if (seen[static_cast<size_t>(n)])
                fail(m_file,
                     fmt::format("node {} is reached twice (the nodes must form trees)", n));
            seen[static_cast<size_t>(n)] = true;
            const Mat4 world = parent * local_matrix(node, n);
            const std::string at = fmt::format("node {}: ", n);
            if (node.mesh != -1) add_mesh(node.mesh, world, at);
            if (node.camera != -1) add_camera(node, n, world);
            add_light(node, world, at);
            for (size_t i = node.children.size(); i-- > 0;)
                stack.emplace_back(node.children[i], world);
        }
    }

    /// The node's matrix, or T · R · S from its translation, rotation (a unit quaternion x, y, z,
    /// w) and scale (§3.5.2). glTF stores matrices column by column.
    Mat4 local_matrix(const tinygltf::Node& node, int n) {
        const std::string at = fmt::format("node {}: ", n);
        Mat4 m = Mat4::identity();
        if (!node.matrix.empty()) {
            if (node.matrix.size() != 16) fail(m_file, at + "matrix must have 16 numbers");
            for (int col = 0; col < 4; ++col)
                for (int row = 0; row < 4; ++row)
                    m(row, col) = static_cast<float>(node.matrix[col * 4 + row]);
        } else {
            const auto& t = node.translation;
            const auto& r = node.rotation;
            const auto& s = node.scale;
            if ((!t.empty() && t.size() != 3) || (!r.empty() && r.size() != 4) ||
                (!s.empty() && s.size() != 3))
                fail(m_file, at + "translation, rotation and scale need 3, 4 and 3 numbers");
            Mat4 rotation = Mat4::identity();
            if (!r.empty()) {
                const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
                if (!(len > 0) || !std::isfinite(len))
                    fail(m_file, at + "rotation is not a unit quaternion");
                const double x = r[0] / len, y = r[1] / len, z = r[2] / len, w = r[3] / len;
                rotation =
                    Mat4::from_rows({float(1 - 2 * (y * y + z * z)), float(2 * (x * y - z * w)),
                                     float(2 * (x * z + y * w)), 0, float(2 * (x * y + z * w)),
                                     float(1 - 2 * (x * x + z * z)), float(2 * (y * z - x * w)), 0,
                                     float(2 * (x * z - y * w)), float(2 * (y * z + x * w)),
                                     float(1 - 2 * (x * x + y * y)), 0, 0, 0, 0, 1});
            }
            const Vec3 tv = t.empty() ? Vec3(0.0f) : Vec3(float(t[0]), float(t[1]), float(t[2]));
            const Vec3 sv = s.empty() ? Vec3(1.0f) : Vec3(float(s[0]), float(s[1]), float(s[2]));
            m = translate(tv) * rotation * scale(sv);
        }
        for (const auto& row : m.m)
            for (float v : row)
                if (!std::isfinite(v)) fail(m_file, at + "the transform is not finite");
        return m;
    }

    // --- Meshes (§3.7.2) ---

    void add_mesh(int mesh_index, const Mat4& world, const std::string& node_at) {
        const tinygltf::Mesh& mesh = element(m_file, m_model.meshes, mesh_index, "mesh", node_at);
        Mat4 inverse;
        // A singular transform flattens the mesh: its file normals are dropped (zero), to be made
        // anew.
        const bool invertible = invert(world, inverse);
        const Mat4 normal_matrix = transpose(inverse);
        // A mirroring transform turns counter-clockwise corners clockwise: swap two back.
        const bool mirrored = determinant(world) < 0.0f;
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            throw_if_cancelled();  // SIGINT / SIGTERM: once per primitive instance
            const std::string at = fmt::format("mesh {} primitive {}: ", mesh_index, p);
            add_primitive(mesh.primitives[p], world, invertible ? &normal_matrix : nullptr,
                          mirrored, at);
        }
    }

    void add_primitive(const tinygltf::Primitive& prim, const Mat4& world,
                       const Mat4* normal_matrix, bool mirrored, const std::string& at) {
        const int mode = prim.mode == -1 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
            ++m_skipped_points_and_lines;
            return;
        }
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN)
            fail(m_file, fmt::format("{}unknown mode {}", at, prim.mode));
        const auto attribute = [&](const char* name) -> std::optional<AccessorData> {
            const auto it = prim.attributes.find(name);
            if (it == prim.attributes.end()) return std::nullopt;
            return accessor_data(m_file, m_model, it->second, fmt::format("{}{}: ", at, name));
        };
        const std::optional<AccessorData> positions = attribute("POSITION");
        if (!positions) {
            ++m_skipped_without_positions;
            return;
        }
        const auto require = [&](const AccessorData& d, const char* name, int components,
                                 bool texcoord) {
            const bool float_type = d.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT;
            const bool unorm =
                d.normalized && (d.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                 d.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
            if (d.components != components || !(float_type || (texcoord && unorm)))
                fail(m_file, fmt::format("{}{} must be VEC{} of {}", at, name, components,
                                         texcoord ? "floats or normalized unsigned bytes or shorts"
                                                  : "floats"));
            if (d.count != positions->count)
                fail(m_file, fmt::format("{}{} has {} elements, POSITION {}", at, name, d.count,
                                         positions->count));
        };
        require(*positions, "POSITION", 3, false);
        const std::optional<AccessorData> normals = attribute("NORMAL");
        if (normals) require(*normals, "NORMAL", 3, false);
        const std::optional<AccessorData> uvs = attribute("TEXCOORD_0");
        if (uvs) require(*uvs, "TEXCOORD_0", 2, true);
        // Vertex colours (linear RGB, alpha ignored) multiply the base colour (§3.7.2.1).
        const std::optional<AccessorData> colours = attribute("COLOR_0");
        if (colours) require(*colours, "COLOR_0", colours->components == 4 ? 4 : 3, true);

        int32_t material = -1;
        if (prim.material != -1) {
            element(m_file, m_model.materials, prim.material, "material", at);
            material = prim.material;
        }
        const size_t n = positions->count;
        PolygonMesh& mesh = m_out.mesh;
        const size_t base = mesh.positions.size();
        if (n > k_max_vertices - base) {
            fail(m_file, fmt::format("{}the scene's nodes instance more than {} vertices in all",
                                     at, k_max_vertices));
        }

        // Every instance of a primitive adds its vertices again: the memory they will take (44
        // bytes of attributes each, about twice over once build_mesh has run) is checked as
        // the instances accumulate.
        check_memory_need(88.0 * static_cast<double>(base + n),
                          fmt::format("{}: {}loading {} vertices", m_file.string(), at, base + n));

        // Vertices, in world space.
        if (normals && mesh.normals.size() < base) mesh.normals.resize(base, Vec3(0.0f));
        if (uvs && mesh.uvs.size() < base) mesh.uvs.resize(base, Vec2{});
        if (colours && mesh.colors.size() < base) mesh.colors.resize(base, Vec3(1.0f));
        for (size_t i = 0; i < n; ++i) {
            mesh.positions.push_back(transform_point(world, vec3_at(*positions, i)));
            if (normals) {
                Vec3 normal(0.0f);
                if (normal_matrix) {
                    normal = transform_normal(*normal_matrix, vec3_at(*normals, i));
                    const float len = length(normal);
                    normal = len > 0.0f && std::isfinite(len) ? normal / len : Vec3(0.0f);
                }
                mesh.normals.push_back(normal);
            } else if (!mesh.normals.empty()) {
                mesh.normals.emplace_back(0.0f);
            }
            if (uvs) {
                const float u = component(*uvs, i, 0), v = component(*uvs, i, 1);
                if (!std::isfinite(u) || !std::isfinite(v))
                    fail(m_file, fmt::format("{}TEXCOORD_0 {} is not finite", at, i));
                // glTF's (0, 0) is the image's top-left corner, hikari's its bottom-left.
                mesh.uvs.push_back(Vec2{u, 1.0f - v});
            } else if (!mesh.uvs.empty()) {
                mesh.uvs.push_back(Vec2{});
            }
            if (colours) {
                const Vec3 c{component(*colours, i, 0), component(*colours, i, 1),
                             component(*colours, i, 2)};
                if (!is_finite(c) || c.x < 0.0f || c.y < 0.0f || c.z < 0.0f)
                    fail(m_file,
                         fmt::format("{}COLOR_0 {} is not a finite, non-negative colour", at, i));
                mesh.colors.push_back(c);
            } else if (!mesh.colors.empty()) {
                mesh.colors.emplace_back(1.0f);
            }
        }

        // The corner list: the indices, or the vertices in order.
        std::vector<uint32_t> corners;
        if (prim.indices != -1) {
            const AccessorData indices =
                accessor_data(m_file, m_model, prim.indices, at + "indices: ");
            const int type = indices.component_type;
            if (indices.components != 1 || indices.normalized ||
                (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                 type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                 type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail(m_file, at + "indices must be SCALAR unsigned bytes, shorts or ints");
            // 4 bytes a corner here and in the mesh, and a third of a triangle's 48 in build_mesh.
            check_memory_need(
                24.0 * static_cast<double>(mesh.corners.size() + indices.count),
                fmt::format("{}: {}loading {} corners", m_file.string(), at, indices.count));
            corners.resize(indices.count);
            for (size_t i = 0; i < indices.count; ++i) {
                corners[i] = index_at(indices, i);
                if (corners[i] >= n)
                    fail(m_file,
                         fmt::format("{}index {} out of range (the primitive has {} vertices)", at,
                                     corners[i], n));
            }
        } else {
            corners.resize(n);
            for (size_t i = 0; i < n; ++i) corners[i] = static_cast<uint32_t>(i);
        }

        // Triangles (§3.7.2.1): a list, a strip (every other triangle reversed to keep its
        // winding) or a fan around the first corner.
        const auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
            const uint32_t v0 = static_cast<uint32_t>(base) + a;
            const uint32_t v1 = static_cast<uint32_t>(base) + b;
            const uint32_t v2 = static_cast<uint32_t>(base) + c;
            if (mirrored)
                mesh.add_face({v0, v2, v1});
            else
                mesh.add_face({v0, v1, v2});
            mesh.face_material.push_back(material);
        };
        const size_t k = corners.size();
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            for (size_t i = 0; i + 2 < k; i += 3) add(corners[i], corners[i + 1], corners[i + 2]);
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (size_t i = 0; i + 2 < k; ++i) {
                if (i % 2 == 0)
                    add(corners[i], corners[i + 1], corners[i + 2]);
                else
                    add(corners[i + 1], corners[i], corners[i + 2]);
            }
        } else {
            for (size_t i = 1; i + 1 < k; ++i) add(corners[i], corners[i + 1], corners[0]);
        }
    }

    // --- Cameras (§3.10) and lights (KHR_lights_punctual) ---

    void add_camera(const tinygltf::Node& node, int n, const Mat4& world) {
        const std::string at = fmt::format("node {}: ", n);
        const tinygltf::Camera& c = element(m_file, m_model.cameras, node.camera, "camera", at);
        if (c.type == "orthographic") {
            ++m_skipped_orthographic;
            return;
        }
        const std::string camera_at = fmt::format("{}camera {}: ", at, node.camera);
        if (c.type != "perspective")
            fail(m_file, fmt::format("{}unknown type {}", camera_at, quote_token(c.type, '"')));
        const double yfov = c.perspective.yfov;
        if (!(yfov > 0.0 && yfov < std::numbers::pi))
            fail(m_file, fmt::format("{}yfov {} is not between 0 and π", camera_at, yfov));
        // The camera looks down its node's −Z with +Y up (§3.10.1).
        const Vec3 eye = transform_point(world, Vec3(0.0f));
        const Vec3 forward = transform_direction(world, Vec3(0.0f, 0.0f, -1.0f));
        const Vec3 up = transform_direction(world, Vec3(0.0f, 1.0f, 0.0f));
        const float fl = length(forward), ul = length(up);
        if (!(fl > 0.0f) || !(ul > 0.0f) || !std::isfinite(fl) || !std::isfinite(ul) ||
            !is_finite(eye))
            fail(m_file, camera_at + "its node's transform is singular");
        ModelCamera out;
        out.name = !c.name.empty()      ? c.name
                   : !node.name.empty() ? node.name
                                        : fmt::format("camera {}", node.camera);
        out.camera.eye = eye;
        out.camera.look_at = eye + forward / fl;
        out.camera.up = up / ul;
        out.camera.fov_y_degrees = static_cast<float>(yfov * 180.0 / std::numbers::pi);
        if (c.perspective.aspectRatio > 0.0 && std::isfinite(c.perspective.aspectRatio))
            out.aspect = static_cast<float>(c.perspective.aspectRatio);
        m_out.cameras.push_back(std::move(out));
    }

    /// A KHR_lights_punctual spot light: its cone about the node's −Z, half-angles in radians
    /// (0 ≤ inner < outer ≤ π/2) turned into hikari's degrees; glTF's falloff between them is
    /// left to the implementation, and hikari's is a smoothstep (scene/light.h).
    SpotLight spot_light(const tinygltf::Light& light, const Mat4& world, Vec3 intensity,
                         const std::string& light_at) const {
        const double inner = light.spot.innerConeAngle, outer = light.spot.outerConeAngle;
        if (!(inner >= 0.0 && inner < outer && outer <= std::numbers::pi / 2.0 + 1e-9))
            fail(m_file, fmt::format("{}spot cone angles must satisfy 0 <= innerConeAngle < "
                                     "outerConeAngle <= pi/2 (got {:g} and {:g})",
                                     light_at, inner, outer));
        const Vec3 d = transform_direction(world, Vec3(0.0f, 0.0f, -1.0f));
        const float len = length(d);
        if (!(len > 0.0f) || !std::isfinite(len))
            fail(m_file, light_at + "its node's transform is singular");
        SpotLight spot{transform_point(world, Vec3(0.0f)), d / len, intensity};
        spot.inner_angle = static_cast<float>(inner * 180.0 / std::numbers::pi);
        spot.outer_angle = std::min(static_cast<float>(outer * 180.0 / std::numbers::pi), 90.0f);
        return spot;
    }

    void add_light(const tinygltf::Node& node, const Mat4& world, const std::string& at) {
        const auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext == node.extensions.end()) return;
        const tinygltf::Value& v = ext->second;
        if (!v.IsObject() || !v.Has("light") || !v.Get("light").IsInt())
            fail(m_file, at + "KHR_lights_punctual needs a \"light\" index");
        const int index = v.Get("light").GetNumberAsInt();
        const tinygltf::Light& light =
            element(m_file, m_model.lights, index, "KHR_lights_punctual light", at);
        const std::string light_at = fmt::format("{}light {}: ", at, index);
        const std::vector<double>& c = light.color;
        if (!c.empty() && c.size() != 3) fail(m_file, light_at + "color needs 3 numbers");
        const Vec3 color = c.empty() ? Vec3(1.0f) : Vec3(float(c[0]), float(c[1]), float(c[2]));
        // hikari's units are glTF's photometric ones, unconverted: a point light of I candela gives
        // I / d² (lux) at distance d, as hikari's point light does; a directional light's lux is
        // its irradiance.
        const Vec3 intensity = color * static_cast<float>(light.intensity);
        if (!is_finite(intensity) || intensity.x < 0 || intensity.y < 0 || intensity.z < 0)
            fail(m_file, light_at + "color × intensity must be finite and not negative");
        if (light.type == "point") {
            m_out.lights.emplace_back(PointLight{transform_point(world, Vec3(0.0f)), intensity});
        } else if (light.type == "spot") {
            m_out.lights.emplace_back(spot_light(light, world, intensity, light_at));
        } else if (light.type == "directional") {
            const Vec3 d = transform_direction(world, Vec3(0.0f, 0.0f, -1.0f));
            const float len = length(d);
            if (!(len > 0.0f) || !std::isfinite(len))
                fail(m_file, light_at + "its node's transform is singular");
            m_out.lights.emplace_back(DirectionalLight{d / len, intensity});
        } else {
            fail(m_file, fmt::format("{}unknown type {}", light_at, quote_token(light.type, '"')));
        }
    }

    // --- Completion ---

    void finish() {
        PolygonMesh& mesh = m_out.mesh;
        if (!mesh.normals.empty()) mesh.normals.resize(mesh.positions.size(), Vec3(0.0f));
        if (!mesh.uvs.empty()) mesh.uvs.resize(mesh.positions.size(), Vec2{});
        const auto warn = [&](size_t count, std::string_view what) {
            if (count > 0)
                mesh.warnings.push_back(fmt::format("{}: {} {}", m_file.string(), count, what));
        };
        warn(m_skipped_points_and_lines,
             "point or line primitives skipped (hikari draws triangles)");
        warn(m_skipped_without_positions, "primitives without POSITION skipped");
        warn(m_skipped_orthographic, "orthographic cameras skipped");
    }

    const fs::path& m_file;
    const tinygltf::Model& m_model;
    GltfContent m_out;
    TextureFiles m_textures;
    std::map<int, std::shared_ptr<const MipPyramid>> m_embedded;
    size_t m_skipped_points_and_lines = 0;
    size_t m_skipped_without_positions = 0;
    size_t m_skipped_orthographic = 0;
};

}  // namespace

GltfContent read_gltf(const std::filesystem::path& file) {
    FileFormatCheck check;
    check.check_head = [&](std::string_view head, std::uintmax_t size) {
        check_gltf_head(file, head, size);
    };
    const std::string bytes = read_file_bytes(file, InputKind::mesh, check);
    if (bytes.empty()) fail(file, "the file is empty");
    std::vector<std::string> warnings;
    const tinygltf::Model model = parse_with_tinygltf(file, bytes, warnings);
    GltfContent content = GltfReader(file, model).read();
    content.mesh.warnings.insert(content.mesh.warnings.begin(), warnings.begin(), warnings.end());
    return content;
}

MeshData load_gltf(const std::filesystem::path& file, const MeshOptions& options) {
    GltfContent content = read_gltf(file);
    MeshData mesh = build_mesh(file, std::move(content.mesh), options);
    mesh.cameras = std::move(content.cameras);
    mesh.lights = std::move(content.lights);
    return mesh;
}

}  // namespace hikari
