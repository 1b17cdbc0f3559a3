#include "hikari/io/scene/scene_json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <string_view>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/core/mat4.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_read.h"
#include "hikari/io/images/texture_files.h"
#include "hikari/io/models/material_rules.h"
#include "hikari/io/models/model_file.h"
#include "hikari/io/scene/animation_json.h"
#include "hikari/io/scene/default_scene.h"
#include "hikari/io/scene/json_reader.h"
#include "hikari/io/scene/scene_document_rebase.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

/// State while a scene is being built: material names, where mesh and texture files are found,
/// and the texture images read so far.
struct SceneBuilder {
    Scene scene;
    std::map<std::string, uint32_t, std::less<>> material_index;
    std::filesystem::path base_dir;
    std::vector<std::string>& warnings;
    TextureFiles textures;
    const SceneLoadOptions& options;
    /// The first camera a model file (glTF) holds, in world space.
    std::optional<Camera> file_camera;
    /// The models the mesh objects have loaded, by file and crease angle: a file that many
    /// objects name is read and built once, not once per object.
    std::map<std::pair<std::filesystem::path, float>, MeshData> models;
};

CheckerTexture parse_checker_texture(const JsonNode& node) {
    node.expect_object({"type", "size", "color_a", "color_b", "offset"});
    CheckerTexture t;
    if (node.has("size")) t.size = node.at("size").as_positive();
    if (node.has("color_a")) t.color_a = node.at("color_a").as_colour();
    if (node.has("color_b")) t.color_b = node.at("color_b").as_colour();
    if (node.has("offset")) t.offset = node.at("offset").as_vec3();
    return t;
}

/// One name of a closed set of words (an enum's values) and its value.
template <class Value>
struct Choice {
    std::string_view name;
    Value value;
};

/// The value whose name `node` (a string) holds; any other word is an error listing the names.
template <class Value, size_t N>
Value parse_choice(const JsonNode& node, std::string_view what,
                   const std::array<Choice<Value>, N>& choices) {
    const std::string word = node.as_string();
    std::string known;
    for (size_t k = 0; k < N; ++k) {
        if (choices[k].name == word) return choices[k].value;
        known += fmt::format("{}\"{}\"", k == 0 ? "" : k + 1 == N ? " or " : ", ", choices[k].name);
    }
    node.fail(fmt::format("unknown {} {} (expected {})", what, quote_token(word, '"'), known));
}

constexpr std::array<Choice<Projection>, 2> k_projections = {{
    {"perspective", Projection::perspective},
    {"orthographic", Projection::orthographic},
}};

}  // namespace

Camera parse_camera(const JsonNode& node) {
    node.expect_object(
        {"eye", "look_at", "up", "projection", "fov_y", "view_height", "width", "height"});
    Camera c;
    if (node.has("projection"))
        c.projection = parse_choice(node.at("projection"), "projection", k_projections);
    if (node.has("eye")) c.eye = node.at("eye").as_vec3();
    if (node.has("look_at")) c.look_at = node.at("look_at").as_vec3();
    if (node.has("up")) c.up = node.at("up").as_direction();
    if (node.has("fov_y")) {
        c.fov_y_degrees = node.at("fov_y").as_number();
        if (!(c.fov_y_degrees > 0 && c.fov_y_degrees < 180))
            node.at("fov_y").fail("expected an angle in degrees between 0 and 180 (exclusive)");
    }
    if (node.has("width")) c.width = node.at("width").as_int(1, k_max_image_side);
    if (node.has("height")) c.height = node.at("height").as_int(1, k_max_image_side);
    const Vec3 view = c.look_at - c.eye;
    if (dot(view, view) == 0.0f) node.fail(camera_view_fault(c));
    // Each projection reads its own key, so that switching one (--set camera.projection=...)
    // needs no other change. Without view_height, the parallel view shows what the pinhole
    // shows at the look_at point: 2 |look_at − eye| tan(fov_y / 2).
    if (node.has("view_height"))
        c.view_height = node.at("view_height").as_positive();
    else
        c.view_height = static_cast<float>(2.0 * length(view) *
                                           std::tan(c.fov_y_degrees * std::numbers::pi / 360.0));
    if (!std::isfinite(c.view_height) || !(c.view_height > 0.0f))
        node.fail("the view height (from fov_y and the distance to look_at) is out of range");
    if (const char* fault = camera_view_fault(c)) node.at("up").fail(fault);
    return c;
}

namespace {

constexpr std::array<Choice<TextureWrap>, 2> k_texture_wraps = {{
    {"repeat", TextureWrap::repeat},
    {"clamp", TextureWrap::clamp},
}};

constexpr std::array<Choice<TextureFilter>, 3> k_texture_filters = {{
    {"nearest", TextureFilter::nearest},
    {"bilinear", TextureFilter::bilinear},
    {"trilinear", TextureFilter::trilinear},
}};

/// An image texture: {"type": "image", "file", "wrap", "filter"}, the file relative to the
/// scene file. A file that cannot be read as an image fails at "file", naming it.
ImageTexture parse_image_texture(const JsonNode& node, SceneBuilder& b) {
    node.expect_object({"type", "file", "wrap", "filter"});
    ImageTexture t;
    const JsonNode file_node = node.at("file");
    t.file = file_node.as_string();
    try {
        t.pyramid = b.textures.pyramid(b.base_dir / t.file);
    } catch (const InputError& e) {
        file_node.fail(fmt::format("cannot use texture {}: {}",
                                   quote_token(t.file, '"', k_quoted_path_bytes), e.what()));
    }
    if (node.has("wrap")) t.wrap = parse_choice(node.at("wrap"), "wrap", k_texture_wraps);
    if (node.has("filter")) t.filter = parse_choice(node.at("filter"), "filter", k_texture_filters);
    return t;
}

/// A parser for each kind of a closed set (lights, textures), by its "type" name; `Context`
/// is what parsers of that set need besides the node (the scene builder, for textures' files).
template <class Kind, class... Context>
struct KindParser {
    std::string_view type;
    Kind (*parse)(const JsonNode& node, Context&... context);
};

/// The kind `node`'s "type" names, parsed by its entry of `parsers`; an unknown type is an
/// error that lists the known ones.
template <class Kind, size_t N, class... Context>
Kind parse_kind(const JsonNode& node, std::string_view what,
                const std::array<KindParser<Kind, Context...>, N>& parsers, Context&... context) {
    const std::string type = node.at("type").as_string();
    std::string known;
    for (const KindParser<Kind, Context...>& p : parsers) {
        if (p.type == type) return p.parse(node, context...);
        known += fmt::format("{}\"{}\"", known.empty() ? "" : " or ", p.type);
    }
    node.at("type").fail(
        fmt::format("unknown {} type {} (expected {})", what, quote_token(type, '"'), known));
}

/// Every texture kind's parser (scene/texture.h): one line per kind.
constexpr std::array<KindParser<Texture, SceneBuilder>, 2> k_texture_parsers = {{
    {"checker",
     [](const JsonNode& n, SceneBuilder&) -> Texture { return parse_checker_texture(n); }},
    {"image",
     [](const JsonNode& n, SceneBuilder& b) -> Texture { return parse_image_texture(n, b); }},
}};

Sky parse_sky(const JsonNode& node) {
    const std::string type = node.at("type").as_string();
    if (type != "gradient")
        node.at("type").fail(
            fmt::format("unknown sky type {} (expected \"gradient\")", quote_token(type, '"')));
    node.expect_object({"type", "horizon", "zenith"});
    return {true, node.at("horizon").as_colour(), node.at("zenith").as_colour()};
}

DepthCue parse_depth_cue(const JsonNode& node) {
    node.expect_object({"near", "far", "color", "blur"});
    DepthCue cue;
    cue.near = node.at("near").as_non_negative();
    cue.far = node.at("far").as_non_negative();
    if (!(cue.far > cue.near)) node.at("far").fail("far must be greater than near");
    if (node.has("color")) cue.color = node.at("color").as_colour();
    if (node.has("blur")) cue.blur = node.at("blur").as_non_negative();
    return cue;
}

/// An object's optional "casts_shadow" (default true).
bool casts_shadow(const JsonNode& object) {
    return !object.has("casts_shadow") || object.at("casts_shadow").as_bool();
}

Material parse_material(const JsonNode& node, std::string name, SceneBuilder& b) {
    node.expect_object({"ka", "kd", "ks", "shininess", "reflectivity", "transparency", "ior",
                        "texture", "emission"});
    Material m;
    m.name = std::move(name);
    if (node.has("ka")) m.ka = node.at("ka").as_colour();
    if (node.has("kd")) m.kd = node.at("kd").as_colour();
    if (node.has("ks")) m.ks = node.at("ks").as_colour();
    if (node.has("shininess")) m.shininess = node.at("shininess").as_non_negative();
    if (node.has("reflectivity")) m.reflectivity = node.at("reflectivity").as_non_negative();
    if (node.has("transparency")) m.transparency = node.at("transparency").as_non_negative();
    if (node.has("ior")) m.ior = node.at("ior").as_positive();
    if (node.has("emission")) m.emission = node.at("emission").as_colour();
    if (node.has("texture"))
        m.texture = parse_kind(node.at("texture"), "texture", k_texture_parsers, b);
    // The rule every format shares (an MTL or glTF material is held to the same ranges).
    if (const auto problem = find_material_problem(m)) {
        const std::string_view key = material_field_name(problem->field);
        (node.has(key) ? node.at(key) : node).fail(problem->message);
    }
    return m;
}

PointLight parse_point_light(const JsonNode& node) {
    node.expect_object({"type", "position", "intensity", "falloff"});
    bool inverse_square = true;
    if (node.has("falloff")) {
        const std::string f = node.at("falloff").as_string();
        if (f != "inverse_square" && f != "none")
            node.at("falloff").fail(
                fmt::format("unknown falloff {} (expected \"inverse_square\" or \"none\")",
                            quote_token(f, '"')));
        inverse_square = f == "inverse_square";
    }
    return {node.at("position").as_vec3(), node.at("intensity").as_colour(), inverse_square};
}

DirectionalLight parse_directional_light(const JsonNode& node) {
    node.expect_object({"type", "direction", "intensity"});
    return {normalize(node.at("direction").as_direction()), node.at("intensity").as_colour()};
}

/// A half-angle of a spot light's cone, in degrees: in (0, 90].
float parse_cone_angle(const JsonNode& node) {
    const float degrees = node.as_number();
    if (!(degrees > 0.0f && degrees <= 90.0f))
        node.fail(
            fmt::format("a spot light's half-angle must be in (0, 90] degrees, not {:g}", degrees));
    return degrees;
}

SpotLight parse_spot_light(const JsonNode& node) {
    node.expect_object(
        {"type", "position", "direction", "intensity", "inner_angle", "outer_angle"});
    SpotLight light{node.at("position").as_vec3(), normalize(node.at("direction").as_direction()),
                    node.at("intensity").as_colour()};
    light.inner_angle = parse_cone_angle(node.at("inner_angle"));
    light.outer_angle = parse_cone_angle(node.at("outer_angle"));
    if (light.outer_angle < light.inner_angle)
        node.at("outer_angle")
            .fail(fmt::format("outer_angle ({:g}) must be at least inner_angle ({:g})",
                              light.outer_angle, light.inner_angle));
    return light;
}

AreaLight parse_area_light(const JsonNode& node) {
    node.expect_object({"type", "corner", "edge1", "edge2", "radiance", "two_sided"});
    AreaLight light{node.at("corner").as_vec3(), node.at("edge1").as_vec3(),
                    node.at("edge2").as_vec3(), node.at("radiance").as_colour()};
    if (node.has("two_sided")) light.two_sided = node.at("two_sided").as_bool();
    // Parallel or zero edges span no area: no light could leave it.
    const Vec3 n = light.area_normal();
    const float scale = length(light.edge1) * length(light.edge2);
    if (!(length(n) > 1e-6f * scale) || !(scale > 0.0f) || !is_finite(n))
        node.fail("degenerate area light: edge1 and edge2 must be nonzero and not parallel");
    return light;
}

/// An environment light: a constant "radiance", or a latitude–longitude map "file" (.hdr or
/// .exr, relative to the scene) times "scale", turned by "rotation_degrees" about +y.
EnvironmentLight parse_environment_light(const JsonNode& node, SceneBuilder& b) {
    node.expect_object({"type", "radiance", "file", "scale", "rotation_degrees"});
    EnvironmentLight light;
    if (node.has("radiance") == node.has("file"))
        node.fail(
            "an environment light needs exactly one of \"radiance\" (constant) or \"file\" (a "
            "map)");
    if (node.has("radiance")) {
        for (const char* key : {"scale", "rotation_degrees"})
            if (node.has(key)) node.at(key).fail("only a map (\"file\") takes this");
        light.radiance = node.at("radiance").as_colour();
        return light;
    }
    if (node.has("scale")) light.radiance = node.at("scale").as_colour();
    const float rotation =
        node.has("rotation_degrees") ? node.at("rotation_degrees").as_number() : 0.0f;
    const JsonNode file_node = node.at("file");
    const std::string file = file_node.as_string();
    Image image;
    try {
        image = read_image(b.base_dir / file);
    } catch (const InputError& e) {
        file_node.fail(fmt::format("cannot read environment map {}: {}",
                                   quote_token(file, '"', k_quoted_path_bytes), e.what()));
    }
    if (image.width != 2 * image.height)
        file_node.fail(fmt::format(
            "environment map {} is {}x{}: a latitude-longitude map is twice as wide as high",
            quote_token(file, '"', k_quoted_path_bytes), image.width, image.height));
    for (const Vec3& texel : image.pixels)
        if (!is_finite(texel) || min_component(texel) < 0.0f)
            file_node.fail(fmt::format("environment map {} has a negative or non-finite texel",
                                       quote_token(file, '"', k_quoted_path_bytes)));
    light.map = std::make_shared<const EnvironmentMap>(std::move(image), rotation);
    return light;
}

/// Every light kind's parser (scene/light.h): one line per kind.
constexpr std::array<KindParser<Light, SceneBuilder>, 5> k_light_parsers = {{
    {"point", [](const JsonNode& n, SceneBuilder&) -> Light { return parse_point_light(n); }},
    {"spot", [](const JsonNode& n, SceneBuilder&) -> Light { return parse_spot_light(n); }},
    {"directional",
     [](const JsonNode& n, SceneBuilder&) -> Light { return parse_directional_light(n); }},
    {"area", [](const JsonNode& n, SceneBuilder&) -> Light { return parse_area_light(n); }},
    {"environment",
     [](const JsonNode& n, SceneBuilder& b) -> Light { return parse_environment_light(n, b); }},
}};

/// The material an object names, or a neutral grey one shared by objects that name none.
uint32_t resolve_material(SceneBuilder& b, const JsonNode& object) {
    if (object.has("material")) {
        const JsonNode node = object.at("material");
        const std::string name = node.as_string();
        const auto it = b.material_index.find(name);
        if (it == b.material_index.end())
            node.fail(
                fmt::format("unknown material {} (not in \"materials\")", quote_token(name, '"')));
        return it->second;
    }
    constexpr std::string_view k_default = "(default)";
    if (const auto it = b.material_index.find(k_default); it != b.material_index.end())
        return it->second;
    Material grey;
    grey.name = k_default;
    grey.ka = grey.kd = Vec3(0.7f);
    b.scene.materials.push_back(grey);
    return b.material_index[std::string(k_default)] =
               static_cast<uint32_t>(b.scene.materials.size() - 1);
}

/// world_from_model for a list of steps applied to the object in order.
Mat4 parse_transform(const JsonNode& node) {
    node.expect_array();
    Mat4 m = Mat4::identity();
    for (size_t i = 0; i < node.value().size(); ++i) {
        const JsonNode step = node.at(i);
        step.expect_object({"scale", "rotate", "translate", "matrix"});
        if (step.value().size() != 1)
            step.fail("expected exactly one of \"scale\", \"rotate\", \"translate\", \"matrix\"");
        Mat4 s;
        if (step.has("scale")) {
            const JsonNode v = step.at("scale");
            s = scale(v.value().is_number() ? Vec3(v.as_number()) : v.as_vec3());
        } else if (step.has("rotate")) {
            const JsonNode r = step.at("rotate");
            r.expect_object({"axis", "degrees"});
            s = rotate(r.at("axis").as_direction(), r.at("degrees").as_number());
        } else if (step.has("translate")) {
            s = translate(step.at("translate").as_vec3());
        } else {
            const JsonNode v = step.at("matrix");
            v.expect_array(16);
            std::array<float, 16> rows{};
            for (size_t k = 0; k < 16; ++k) rows[k] = v.at(k).as_number();
            s = Mat4::from_rows(rows);
        }
        m = s * m;
    }
    Mat4 inverse;
    if (flattens_space(m) || !invert(m, inverse))
        node.fail("the transform is singular (it flattens the object)");
    return m;
}

PrimitiveId next_id(SceneBuilder& b) { return b.scene.primitive_count++; }

/// Appends one triangle with vertex positions `p` and normals `n` to the scene.
void add_triangle(SceneBuilder& b, const std::array<Vec3, 3>& p, const std::array<Vec3, 3>& n,
                  uint32_t material, PrimitiveId id, bool shadow) {
    TriangleSet& t = b.scene.triangles;
    const auto base = static_cast<uint32_t>(t.positions.size());
    for (int k = 0; k < 3; ++k) {
        t.positions.push_back(p[k]);
        t.normals.push_back(n[k]);
    }
    t.indices.push_back({base, base + 1, base + 2});
    t.material.push_back(material);
    t.id.push_back(id);
    t.casts_shadow.push_back(shadow ? 1 : 0);
    t.edge_flags.push_back(k_all_edges);
}

/// The lecture's face normal N = (P2 − P1) × (P3 − P2) (Fig 4.5), not normalized.
Vec3 face_normal(Vec3 p1, Vec3 p2, Vec3 p3) { return cross(p2 - p1, p3 - p2); }

/// Appends `uvs` for the vertices from `base` on (the object just added), keeping
/// TriangleSet::uvs empty until some object has texture coordinates and, from then on, one per
/// vertex: earlier vertices without any get (0, 0).
void add_uvs(TriangleSet& t, size_t base, const std::vector<Vec2>& uvs) {
    if (uvs.empty() && t.uvs.empty()) return;
    t.uvs.resize(base);
    t.uvs.insert(t.uvs.end(), uvs.begin(), uvs.end());
    t.uvs.resize(t.positions.size());
}

/// Appends `colors` for the vertices from `base` on (the object just added): TriangleSet::colors
/// stays empty until some object has vertex colours; the vertices before it, and those of objects
/// without, are white (parse_scene pads the end).
void add_colors(TriangleSet& t, size_t base, const std::vector<Vec3>& colors) {
    if (colors.empty()) return;
    t.colors.resize(base, Vec3(1.0f));
    t.colors.insert(t.colors.end(), colors.begin(), colors.end());
}

/// A triangle object's optional "uvs": three [u, v] pairs.
std::vector<Vec2> parse_triangle_uvs(const JsonNode& node) {
    if (!node.has("uvs")) return {};
    const JsonNode uvs = node.at("uvs");
    uvs.expect_array(3);
    std::vector<Vec2> out;
    for (size_t k = 0; k < 3; ++k) {
        const JsonNode uv = uvs.at(k);
        uv.expect_array(2);
        out.push_back({uv.at(size_t{0}).as_number(), uv.at(1).as_number()});
    }
    return out;
}

void parse_triangle(SceneBuilder& b, const JsonNode& node) {
    node.expect_object(
        {"type", "name", "vertices", "uvs", "material", "transform", "casts_shadow"});
    const JsonNode v = node.at("vertices");
    v.expect_array(3);
    std::array<Vec3, 3> p{v.at(size_t{0}).as_vec3(), v.at(1).as_vec3(), v.at(2).as_vec3()};
    if (node.has("transform")) {
        const Mat4 m = parse_transform(node.at("transform"));
        for (Vec3& q : p) q = transform_point(m, q);
    }
    const Vec3 n = face_normal(p[0], p[1], p[2]);
    if (!(dot(n, n) > 0.0f) || !is_finite(n)) v.fail("degenerate triangle (zero area)");
    const Vec3 unit = normalize(n);
    const std::vector<Vec2> uvs = parse_triangle_uvs(node);
    const size_t base = b.scene.triangles.positions.size();
    add_triangle(b, p, {unit, unit, unit}, resolve_material(b, node), next_id(b),
                 casts_shadow(node));
    add_uvs(b.scene.triangles, base, uvs);
}

/// The model `file` loaded with `options` (once per scene: b.models keeps it); `first` is set
/// when this call loaded it. A load error is reported at `file_node`.
const MeshData& loaded_model(SceneBuilder& b, const JsonNode& file_node,
                             const std::filesystem::path& file, const MeshOptions& options,
                             bool& first) {
    const auto key = std::pair{file.lexically_normal(), options.crease_angle_degrees};
    first = false;
    if (const auto it = b.models.find(key); it != b.models.end()) return it->second;
    try {
        first = true;
        return b.models.emplace(key, load_model(file, options)).first->second;
    } catch (const InputError& e) {
        file_node.fail(e.what());
    }
}

/// Makes room in `t` for a mesh object of `vertices` and `triangles` (with uvs, colours), its
/// memory checked first: a model many objects name is stored once per object, so 300 objects of
/// one scan grow the scene's arrays without any file being large. The arrays grow by at least
/// half their size each time (no quadratic copying); the need is what the grown arrays take
/// (the current ones count as held while they are copied).
void reserve_mesh_object(TriangleSet& t, size_t vertices, size_t triangles, bool uvs, bool colours,
                         const std::string& what) {
    double need = 0;
    const auto grown = [&need](auto& array, size_t more) {
        const size_t wanted = array.size() + more;
        if (wanted <= array.capacity()) return size_t{0};
        const size_t capacity = std::max(wanted, array.capacity() + array.capacity() / 2);
        need += static_cast<double>(capacity) * sizeof(array[0]);
        return capacity;
    };
    const std::array<size_t, 4> vertex_capacity = {
        grown(t.positions, vertices), grown(t.normals, vertices),
        uvs ? grown(t.uvs, vertices + t.positions.size() - t.uvs.size()) : 0,
        colours ? grown(t.colors, vertices + t.positions.size() - t.colors.size()) : 0};
    const std::array<size_t, 5> triangle_capacity = {
        grown(t.indices, triangles), grown(t.material, triangles), grown(t.id, triangles),
        grown(t.casts_shadow, triangles), grown(t.edge_flags, triangles)};
    check_memory_need(need, what);
    if (vertex_capacity[0]) t.positions.reserve(vertex_capacity[0]);
    if (vertex_capacity[1]) t.normals.reserve(vertex_capacity[1]);
    if (vertex_capacity[2]) t.uvs.reserve(vertex_capacity[2]);
    if (vertex_capacity[3]) t.colors.reserve(vertex_capacity[3]);
    if (triangle_capacity[0]) t.indices.reserve(triangle_capacity[0]);
    if (triangle_capacity[1]) t.material.reserve(triangle_capacity[1]);
    if (triangle_capacity[2]) t.id.reserve(triangle_capacity[2]);
    if (triangle_capacity[3]) t.casts_shadow.reserve(triangle_capacity[3]);
    if (triangle_capacity[4]) t.edge_flags.reserve(triangle_capacity[4]);
}

void parse_mesh(SceneBuilder& b, const JsonNode& node) {
    node.expect_object(
        {"type", "name", "file", "material", "transform", "casts_shadow", "crease_angle"});
    const bool shadow = casts_shadow(node);
    const JsonNode file_node = node.at("file");
    const std::filesystem::path file = b.base_dir / file_node.as_string();
    MeshOptions mesh_options;
    if (node.has("crease_angle")) {
        const JsonNode crease = node.at("crease_angle");
        mesh_options.crease_angle_degrees = crease.as_non_negative();
        if (mesh_options.crease_angle_degrees > 180.0f)
            crease.fail("expected an angle from 0 to 180 degrees");
    }
    if (b.options.crease_angle) mesh_options.crease_angle_degrees = *b.options.crease_angle;
    const bool preloaded = b.options.preloaded && file == b.options.preloaded_file;
    bool first = preloaded;
    const MeshData& mesh =
        preloaded ? *b.options.preloaded : loaded_model(b, file_node, file, mesh_options, first);
    if (first) {  // said once, however many objects name the file
        for (const std::string& w : mesh.warnings) b.warnings.push_back(w);
        if (mesh.degenerate_skipped > 0)
            b.warnings.push_back(fmt::format("{}: skipped {} degenerate triangle(s)", file.string(),
                                             mesh.degenerate_skipped));
    }

    const Mat4 world_from_model =
        node.has("transform") ? parse_transform(node.at("transform")) : Mat4::identity();
    Mat4 model_from_world;
    invert(world_from_model, model_from_world);
    const Mat4 normal_matrix = transpose(model_from_world);
    // A mirroring transform turns counter-clockwise faces clockwise; swap to keep fronts in front.
    const bool mirrored = determinant(world_from_model) < 0.0f;

    // Materials: the scene's when the object names one, else the OBJ's own MTL materials.
    std::vector<uint32_t> material_of(mesh.materials.size());
    const bool named = node.has("material");
    const bool any_unassigned =
        std::find(mesh.material.begin(), mesh.material.end(), -1) != mesh.material.end();
    uint32_t fallback = named || any_unassigned ? resolve_material(b, node) : 0;
    // A mesh with vertex colours gets its own copies of its materials that read them.
    const bool coloured = !mesh.colors.empty();
    if (coloured && (named || any_unassigned)) {
        Material m = b.scene.materials[fallback];
        m.name += fmt::format(" (vertex colours of {})", file.filename().string());
        m.vertex_colours = true;
        b.scene.materials.push_back(std::move(m));
        fallback = static_cast<uint32_t>(b.scene.materials.size() - 1);
    }
    if (!named)
        for (size_t k = 0; k < mesh.materials.size(); ++k) {
            Material m = mesh.materials[k];
            m.name = fmt::format("{}:{}", file.filename().string(), m.name);
            m.vertex_colours = coloured;
            b.scene.materials.push_back(std::move(m));
            material_of[k] = static_cast<uint32_t>(b.scene.materials.size() - 1);
        }

    TriangleSet& t = b.scene.triangles;
    try {
        reserve_mesh_object(
            t, mesh.positions.size(), mesh.indices.size(), !mesh.uvs.empty() || !t.uvs.empty(),
            !mesh.colors.empty(),
            fmt::format("{} triangles of {} after the scene's {}", mesh.indices.size(),
                        quote_token(file.filename().string(), '"'), t.size()));
    } catch (const InputError& e) {
        file_node.fail(e.what());
    }
    const auto base = static_cast<uint32_t>(t.positions.size());
    for (size_t k = 0; k < mesh.positions.size(); ++k) {
        t.positions.push_back(transform_point(world_from_model, mesh.positions[k]));
        const Vec3 n = transform_normal(normal_matrix, mesh.normals[k]);
        t.normals.push_back(dot(n, n) > 0.0f ? normalize(n) : mesh.normals[k]);
    }
    add_uvs(t, base, mesh.uvs);
    add_colors(t, base, mesh.colors);
    for (size_t k = 0; k < mesh.indices.size(); ++k) {
        auto tri = mesh.indices[k];
        uint8_t edges = mesh.edge_flags[k];
        if (mirrored) {
            std::swap(tri[1], tri[2]);
            edges = mirrored_edge_flags(edges);
        }
        t.indices.push_back({base + tri[0], base + tri[1], base + tri[2]});
        t.edge_flags.push_back(edges);
        const int32_t own = mesh.material[k];
        t.material.push_back(named || own < 0 ? fallback : material_of[static_cast<size_t>(own)]);
        t.id.push_back(next_id(b));
        t.casts_shadow.push_back(shadow ? 1 : 0);
    }
    // A glTF file's lights light the scene from where the transform puts them; its first camera
    // is the scene's when the scene names none.
    const LightMove move{
        [&](Vec3 p) { return transform_point(world_from_model, p); },
        [&](Vec3 v) { return transform_direction(world_from_model, v); },
        [&](Vec3 d) { return normalize(transform_direction(world_from_model, d)); }};
    for (Light light : mesh.lights) {
        move_light(light, move);
        b.scene.lights.push_back(light);
    }
    if (!mesh.cameras.empty() && !b.file_camera) {
        Camera c = mesh.cameras.front().camera;
        c.eye = transform_point(world_from_model, c.eye);
        c.look_at = transform_point(world_from_model, c.look_at);
        c.up = normalize(transform_direction(world_from_model, c.up));
        b.file_camera = c;
    }
}

void parse_object(SceneBuilder& b, const JsonNode& node) {
    const std::string type = node.at("type").as_string();
    if (type == "sphere") {
        node.expect_object(
            {"type", "name", "center", "radius", "material", "casts_shadow", "segments"});
        b.scene.spheres.push_back({node.at("center").as_vec3(), node.at("radius").as_positive(),
                                   resolve_material(b, node), next_id(b), casts_shadow(node)});
        if (node.has("segments"))
            b.scene.spheres.back().segments = static_cast<uint32_t>(
                node.at("segments").as_int(k_min_sphere_segments, k_max_sphere_segments));
    } else if (type == "plane") {
        node.expect_object(
            {"type", "name", "point", "normal", "uv_scale", "material", "casts_shadow"});
        b.scene.planes.push_back({node.at("point").as_vec3(),
                                  normalize(node.at("normal").as_direction()),
                                  resolve_material(b, node), next_id(b), casts_shadow(node),
                                  node.has("uv_scale") ? node.at("uv_scale").as_positive() : 1.0f});
    } else if (type == "triangle") {
        parse_triangle(b, node);
    } else if (type == "mesh") {
        parse_mesh(b, node);
    } else {
        node.at("type").fail(fmt::format(
            "unknown object type {} (expected \"sphere\", \"plane\", \"triangle\" or \"mesh\")",
            quote_token(type, '"')));
    }
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& file,
                  const std::filesystem::path& base_dir, std::vector<std::string>& warnings,
                  const SceneLoadOptions& options) {
    nlohmann::json doc = parse_json(text, file);
    apply_scene_overrides(doc, options.overrides);
    return parse_scene_document(std::move(doc), file, base_dir, warnings, options);
}

Scene parse_scene_document(nlohmann::json doc, const std::string& file,
                           const std::filesystem::path& base_dir,
                           std::vector<std::string>& warnings, const SceneLoadOptions& options) {
    const std::optional<WorldOrigin> origin = rebase_scene_document(doc);
    const JsonNode root(doc, file, "");
    root.expect_object({"description", "camera", "background", "sky", "ambient", "depth_cue",
                        "materials", "lights", "objects", "animation"});
    SceneBuilder b{Scene{}, {}, base_dir, warnings, {}, options, std::nullopt, {}};
    if (root.has("description")) root.at("description").as_string();
    if (root.has("camera")) b.scene.camera = parse_camera(root.at("camera"));
    if (root.has("background")) b.scene.background = root.at("background").as_colour();
    if (root.has("sky")) b.scene.sky = parse_sky(root.at("sky"));
    if (root.has("ambient")) b.scene.ambient = root.at("ambient").as_colour();
    if (root.has("depth_cue")) b.scene.depth_cue = parse_depth_cue(root.at("depth_cue"));
    if (root.has("materials")) {
        const JsonNode materials = root.at("materials");
        if (!materials.value().is_object()) materials.fail("expected an object: name -> material");
        for (const auto& [name, value] : materials.value().items()) {
            b.scene.materials.push_back(
                parse_material(JsonNode(value, file, "materials." + name), name, b));
            b.material_index[name] = static_cast<uint32_t>(b.scene.materials.size() - 1);
        }
    }
    if (root.has("lights")) {
        const JsonNode lights = root.at("lights");
        lights.expect_array();
        bool environment = false;
        for (size_t i = 0; i < lights.value().size(); ++i) {
            b.scene.lights.push_back(parse_kind(lights.at(i), "light", k_light_parsers, b));
            if (!light_as<EnvironmentLight>(b.scene.lights.back())) continue;
            if (environment) lights.at(i).fail("a scene has at most one environment light");
            environment = true;
        }
    }
    const JsonNode objects = root.at("objects");
    objects.expect_array();
    for (size_t i = 0; i < objects.value().size(); ++i) parse_object(b, objects.at(i));
    // A still is the scene as written; the block is checked here so that every load reports
    // its errors (its frames are session/scene_animation.h's).
    if (root.has("animation")) parse_animation(root);
    if (!b.scene.triangles.colors.empty())
        b.scene.triangles.colors.resize(b.scene.triangles.positions.size(), Vec3(1.0f));
    if (origin) keep_checkers_in_place(b.scene, *origin);
    if (!root.has("camera") && b.file_camera) {
        const Camera& c = *b.file_camera;
        b.scene.camera.eye = c.eye;
        b.scene.camera.look_at = c.look_at;
        b.scene.camera.up = c.up;
        b.scene.camera.fov_y_degrees = c.fov_y_degrees;
    }
    return std::move(b.scene);
}

Scene load_scene_file(const std::filesystem::path& path, std::vector<std::string>& warnings,
                      const SceneLoadOptions& options) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(fmt::format("{}: is a directory, not a scene file", path.string()));
    // stdio, not iostreams: a render that loads no other file then never pays for iostreams'
    // locale set-up (some 15 page faults, 0.3 ms on a virtual machine).
    return parse_scene(read_file_bytes(path, InputKind::scene), path.string(), path.parent_path(),
                       warnings, options);
}

Scene load_default_scene(const SceneLoadOptions& options) {
    std::vector<std::string> warnings;
    return parse_scene(default_scene_json(), "scenes/assignment.json (built in)", ".", warnings,
                       options);
}

}  // namespace hikari
