#include "hikari/io/images/xlsx_formulas_write.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <string_view>

#include <fmt/format.h>

#include "hikari/core/color.h"
#include "hikari/core/error.h"
#include "hikari/io/images/xlsx_workbook.h"
#include "hikari/io/images/xlsx_write.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

/// Picture cells: 24 pixels, 18 points, square in Excel and in LibreOffice (set_square_cells).
constexpr uint32_t k_picture_cell_pixels = 24;

/// One labelled row of the parameter sheet: up to three values, each a defined name the
/// formulas read (`eye_x`, `kd_red`, `shininess_n`), given as numbers or derived by formulas.
struct ParameterRow {
    std::string_view label;
    std::string_view name;  ///< the names' stem: `eye` gives eye_x, eye_y, eye_z
    std::array<std::string_view, 3> suffixes;
    std::array<std::string, 3> values;  ///< numbers, or formulas starting with '='
    int count = 3;
    std::array<double, 3> cached{};  ///< a formula's result, stored with it
};

constexpr std::array<std::string_view, 3> k_xyz{"_x", "_y", "_z"};
constexpr std::array<std::string_view, 3> k_rgb{"_red", "_green", "_blue"};

std::array<std::string, 3> numbers(Vec3 v) {
    return {fmt::format("{}", v.x), fmt::format("{}", v.y), fmt::format("{}", v.z)};
}

ParameterRow vec_row(std::string_view label, std::string_view name, Vec3 v) {
    return {label, name, k_xyz, numbers(v), 3};
}

ParameterRow colour_row(std::string_view label, std::string_view name, Vec3 v) {
    return {label, name, k_rgb, numbers(v), 3};
}

ParameterRow scalar_row(std::string_view label, std::string_view name, std::string value) {
    return {label, name, {""}, {std::move(value), "", ""}, 1};
}

using D3 = std::array<double, 3>;

D3 d3(Vec3 v) { return {v.x, v.y, v.z}; }
double dot(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
D3 axpy(double s, const D3& a, const D3& b) {
    return {s * a[0] + b[0], s * a[1] + b[1], s * a[2] + b[2]};
}
D3 unit(const D3& a) { return axpy(1.0 / std::sqrt(dot(a, a)) - 1.0, a, a); }

/// The parameter sheet's derived cells, worked out as its formulas do.
struct DerivedParameters {
    D3 fwd, right, upv, l;
    double tan_half = 0, c = 0;
};

DerivedParameters derived_parameters(const Scene& scene) {
    const Camera& cam = scene.camera;
    DerivedParameters p;
    p.fwd = unit(axpy(-1.0, d3(cam.eye), d3(cam.look_at)));
    const D3 up = d3(cam.up), f = p.fwd;
    p.right = unit(
        {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]});
    const D3 r = p.right;
    p.upv = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
    p.tan_half = std::tan(double(cam.fov_y_degrees) * std::numbers::pi / 360.0);
    p.l = unit(d3(std::get<DirectionalLight>(scene.lights.front()).direction));
    const Sphere& s = scene.spheres.front();
    const D3 m = axpy(-1.0, d3(s.center), d3(cam.eye));
    p.c = dot(m, m) - double(s.radius) * s.radius;
    return p;
}

/// One pixel's quantities as the pixel sheets' formulas compute them, in double precision: the
/// results stored with the formulas, so a spreadsheet that keeps stored results on opening
/// (LibreOffice's default for .xlsx) shows the picture, and one that recalculates (Excel) finds
/// the same.
struct PixelQuantities {
    D3 e{}, n{};
    double d = 0, t = -1, cos_alpha = 0, cos_gamma = 0, image = -1;
    D3 code{};
};

double file_code(double v, SampleEncoding encoding) {
    v = std::clamp(v, 0.0, 1.0);
    if (encoding == SampleEncoding::srgb)
        v = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    return std::round(255 * v);  // the spreadsheets' ROUND: halves away from zero
}

PixelQuantities pixel_quantities(const Scene& scene, const DerivedParameters& p, int x, int y,
                                 SampleEncoding encoding) {
    const Camera& cam = scene.camera;
    const Sphere& s = scene.spheres.front();
    const Material& m = scene.materials[s.material];
    const double w = cam.width, h = cam.height;
    const double xs = (2 * (x + 0.5) / w - 1) * p.tan_half * w / h;
    const double ys = (1 - 2 * (y + 0.5) / h) * p.tan_half;
    PixelQuantities q;
    q.e = unit(axpy(ys, p.upv, axpy(xs, p.right, p.fwd)));
    const double a = dot(q.e, q.e), b = 2 * dot(q.e, axpy(-1.0, d3(s.center), d3(cam.eye)));
    q.d = b * b - 4 * a * p.c;
    const double root = q.d < 0 ? -1 : (-b - std::sqrt(q.d)) / (2 * a);
    q.t = root > 0 ? root : -1;
    double specular = 0;
    if (q.t > 0) {
        const D3 point = axpy(q.t, q.e, d3(cam.eye));
        q.n = axpy(1.0 / s.radius - 1.0, axpy(-1.0, d3(s.center), point),
                   axpy(-1.0, d3(s.center), point));
        q.cos_alpha = -dot(p.l, q.n);
        q.cos_gamma = -dot(axpy(2 * q.cos_alpha, q.n, p.l), q.e);
        specular = m.shininess == 0 ? 1 : std::pow(std::max(0.0, q.cos_gamma), double(m.shininess));
        q.image = std::max(0.0, q.cos_alpha) + (q.cos_alpha > 0 ? specular : 0);
    }
    const Vec3 i0 = std::get<DirectionalLight>(scene.lights.front()).intensity;
    for (int c = 0; c < 3; ++c) {
        double v = scene.background[c];
        if (q.t > 0) {
            v = double(scene.ambient[c]) * m.ka[c];
            if (q.cos_alpha > 0)
                v += double(i0[c]) * (double(m.kd[c]) * q.cos_alpha + double(m.ks[c]) * specular);
        }
        q.code[static_cast<size_t>(c)] = file_code(v, encoding);
    }
    return q;
}

/// The rows the user edits, then the camera frame, L and C derived from them by formulas.
std::vector<ParameterRow> parameter_rows(const Scene& scene) {
    const Camera& c = scene.camera;
    const auto& light = std::get<DirectionalLight>(scene.lights.front());
    const Sphere& s = scene.spheres.front();
    const Material& m = scene.materials[s.material];
    std::vector<ParameterRow> rows = {
        vec_row("eye P_E", "eye", c.eye),
        vec_row("look at", "look", c.look_at),
        vec_row("up", "upin", c.up),
        scalar_row("fov_y (degrees)", "fov_y", fmt::format("{}", c.fov_y_degrees)),
        scalar_row("width W (the sheets' columns)", "width_W", fmt::format("{}", c.width)),
        scalar_row("height H (the sheets' rows)", "height_H", fmt::format("{}", c.height)),
        vec_row("sphere centre S", "centre", s.center),
        scalar_row("sphere radius r", "radius", fmt::format("{}", s.radius)),
        vec_row("light direction (the way it travels)", "light", light.direction),
        colour_row("light intensity I0", "I0", light.intensity),
        colour_row("k_a (ambient)", "ka", m.ka),
        colour_row("k_d (diffuse, Lambert)", "kd", m.kd),
        colour_row("k_s (specular, Phong)", "ks", m.ks),
        scalar_row("n (Phong exponent)", "shininess_n", fmt::format("{}", m.shininess)),
        colour_row("ambient light I_a", "Ia", scene.ambient),
        colour_row("background", "bg", scene.background),
    };
    const DerivedParameters d = derived_parameters(scene);
    const auto derived = [](std::string_view label, std::string_view name,
                            std::array<std::string, 3> f, D3 cached) {
        return ParameterRow{label, name, k_xyz, std::move(f), 3, cached};
    };
    const std::string to_look = "(look{0}-eye{0})", side = "(fwd{1}*upin{2}-fwd{2}*upin{1})";
    const auto norm = [](std::string_view term) {
        return fmt::format("SQRT({}^2+{}^2+{}^2)", fmt::format(fmt::runtime(term), "_x"),
                           fmt::format(fmt::runtime(term), "_y"),
                           fmt::format(fmt::runtime(term), "_z"));
    };
    const std::string look_norm = norm(to_look);
    const std::string side_norm =
        fmt::format("SQRT({}^2+{}^2+{}^2)", fmt::format(fmt::runtime(side), "", "_y", "_z"),
                    fmt::format(fmt::runtime(side), "", "_z", "_x"),
                    fmt::format(fmt::runtime(side), "", "_x", "_y"));
    rows.push_back(derived("forward = (look at − eye) / |…|", "fwd",
                           {"=(look_x-eye_x)/" + look_norm, "=(look_y-eye_y)/" + look_norm,
                            "=(look_z-eye_z)/" + look_norm},
                           d.fwd));
    rows.push_back(derived(
        "right = forward × up / |…|", "right",
        {"=(fwd_y*upin_z-fwd_z*upin_y)/" + side_norm, "=(fwd_z*upin_x-fwd_x*upin_z)/" + side_norm,
         "=(fwd_x*upin_y-fwd_y*upin_x)/" + side_norm},
        d.right));
    rows.push_back(derived("camera up = right × forward", "upv",
                           {"=right_y*fwd_z-right_z*fwd_y", "=right_z*fwd_x-right_x*fwd_z",
                            "=right_x*fwd_y-right_y*fwd_x"},
                           d.upv));
    rows.push_back(scalar_row("tan(fov_y / 2)", "tan_half", "=TAN(RADIANS(fov_y)/2)"));
    rows.back().cached[0] = d.tan_half;
    const std::string light_norm = "SQRT(light_x^2+light_y^2+light_z^2)";
    rows.push_back(derived(
        "L = light direction / |…|", "L",
        {"=light_x/" + light_norm, "=light_y/" + light_norm, "=light_z/" + light_norm}, d.l));
    rows.push_back(
        scalar_row("C = ||P_E − S||² − r²", "C_coef",
                   "=(eye_x-centre_x)^2+(eye_y-centre_y)^2+(eye_z-centre_z)^2-radius^2"));
    rows.back().cached[0] = d.c;
    return rows;
}

/// "A1"-style name of cell (row, column), both from 0.
std::string cell_name(int row, int column) {
    std::string letters;
    for (int c = column + 1; c > 0; c = (c - 1) / 26)
        letters.insert(letters.begin(), static_cast<char>('A' + (c - 1) % 26));
    return letters + std::to_string(row + 1);
}

/// `formula` with every '@' replaced by `cell`: each pixel sheet's cell reads the same cell of
/// the sheets before it.
std::string at_cell(std::string_view formula, const std::string& cell) {
    std::string out;
    for (const char ch : formula) out += ch == '@' ? cell : std::string(1, ch);
    return out;
}

/// The pixel sheets' formulas, '@' standing for the cell's own address (the lecture's
/// quantities, Fig 4.16 and 4.29).
struct PixelFormulas {
    std::string name, formula;
    std::function<double(const PixelQuantities&)> value;  ///< its stored result
};

std::string ray_component(std::string_view c) {
    const std::string xs = "(2*(COLUMN()-0.5)/width_W-1)*tan_half*width_W/height_H";
    const std::string ys = "(1-2*(ROW()-0.5)/height_H)*tan_half";
    return fmt::format("(fwd{0}+{1}*right{0}+{2}*upv{0})", c, xs, ys);
}

/// sRGB's curve (IEC 61966-2-1) or none, on a clamped linear value `v`, as an 8-bit code.
std::string code_formula(const std::string& v, SampleEncoding encoding) {
    if (encoding == SampleEncoding::linear) return "=ROUND(255*" + v + ",0)";
    return fmt::format("=ROUND(255*IF({0}<=0.0031308,12.92*{0},1.055*{0}^(1/2.4)-0.055),0)", v);
}

const std::string k_specular = "IF(shininess_n=0,1,MAX(0,cos_gamma!@)^shininess_n)";

std::vector<PixelFormulas> pixel_formulas(SampleEncoding encoding) {
    std::vector<PixelFormulas> sheets;
    const std::string norm = fmt::format("SQRT({}^2+{}^2+{}^2)", ray_component("_x"),
                                         ray_component("_y"), ray_component("_z"));
    for (size_t i = 0; i < 3; ++i)
        sheets.push_back({fmt::format("E{}", k_xyz[i]),
                          fmt::format("={}/{}", ray_component(k_xyz[i]), norm),
                          [i](const PixelQuantities& q) { return q.e[i]; }});
    const std::string a = "(E_x!@^2+E_y!@^2+E_z!@^2)";
    const std::string b =
        "2*(E_x!@*(eye_x-centre_x)+E_y!@*(eye_y-centre_y)+E_z!@*(eye_z-centre_z))";
    sheets.push_back({"D", fmt::format("=({})^2-4*{}*C_coef", b, a),
                      [](const PixelQuantities& q) { return q.d; }});
    const std::string root = fmt::format("(-({})-SQRT(D!@))/(2*{})", b, a);
    sheets.push_back({"t", fmt::format("=IF(D!@<0,-1,IF({0}>0,{0},-1))", root),
                      [](const PixelQuantities& q) { return q.t; }});
    for (size_t i = 0; i < 3; ++i)
        sheets.push_back(
            {fmt::format("N{}", k_xyz[i]),
             fmt::format("=IF(t!@>0,(eye{0}+t!@*E{0}!@-centre{0})/radius,0)", k_xyz[i]),
             [i](const PixelQuantities& q) { return q.n[i]; }});
    sheets.push_back({"cos_alpha", "=IF(t!@>0,-(L_x*N_x!@+L_y*N_y!@+L_z*N_z!@),0)",
                      [](const PixelQuantities& q) { return q.cos_alpha; }});
    sheets.push_back({"cos_gamma",
                      "=IF(t!@>0,-((L_x+2*cos_alpha!@*N_x!@)*E_x!@+(L_y+2*cos_alpha!@*N_y!@)*"
                      "E_y!@+(L_z+2*cos_alpha!@*N_z!@)*E_z!@),0)",
                      [](const PixelQuantities& q) { return q.cos_gamma; }});
    for (size_t i = 0; i < 3; ++i) {
        const std::string_view ch = k_rgb[i];
        const std::string intensity = fmt::format(
            "IF(t!@>0,Ia{0}*ka{0}+IF(cos_alpha!@>0,I0{0}*(kd{0}*cos_alpha!@+ks{0}*{1}),0),bg{0})",
            ch, k_specular);
        sheets.push_back({std::string(ch.substr(1)),
                          code_formula("MIN(1,MAX(0," + intensity + "))", encoding),
                          [i](const PixelQuantities& q) { return q.code[i]; }});
    }
    return sheets;
}

/// The colour a linear value gets in the file, as 0xRRGGBB.
uint32_t file_colour(Vec3 v, SampleEncoding encoding) {
    uint32_t rgb = 0;
    for (int c = 0; c < 3; ++c) {
        const float x = std::clamp(v[c], 0.0f, 1.0f);
        const long code =
            encoding == SampleEncoding::linear ? std::lround(255.0f * x) : long{linear_to_srgb8(x)};
        rgb = (rgb << 8) | static_cast<uint32_t>(code);
    }
    return rgb;
}

lxw_worksheet* add_sheet(lxw_workbook* book, const std::string& name,
                         const std::filesystem::path& path) {
    lxw_worksheet* sheet = workbook_add_worksheet(book, name.c_str());
    if (!sheet) fail_workbook(path, "libxlsxwriter could not add a worksheet");
    return sheet;
}

void write_parameters(lxw_workbook* book, const Scene& scene, const std::filesystem::path& path) {
    lxw_worksheet* sheet = add_sheet(book, "parameters", path);
    check_workbook(worksheet_set_column(sheet, 0, 0, 40, nullptr), path);
    check_workbook(worksheet_write_string(sheet, 0, 0,
                                          "The lecture's assignment, computed by the cells: "
                                          "change a value in B-D and every sheet follows",
                                          nullptr),
                   path);
    lxw_row_t row = 1;
    for (const ParameterRow& p : parameter_rows(scene)) {
        check_workbook(worksheet_write_string(sheet, row, 0, std::string(p.label).c_str(), nullptr),
                       path);
        for (int i = 0; i < p.count; ++i) {
            const auto column = static_cast<lxw_col_t>(1 + i);
            const std::string& v = p.values[static_cast<size_t>(i)];
            check_workbook(v.starts_with('=')
                               ? worksheet_write_formula_num(sheet, row, column, v.c_str(), nullptr,
                                                             p.cached[static_cast<size_t>(i)])
                               : worksheet_write_number(sheet, row, column, std::stod(v), nullptr),
                           path);
            const std::string name =
                fmt::format("{}{}", p.name, p.suffixes[static_cast<size_t>(i)]);
            check_workbook(workbook_define_name(book, name.c_str(),
                                                ("=parameters!$" + std::string(1, char('B' + i)) +
                                                 "$" + std::to_string(row + 1))
                                                    .c_str()),
                           path);
        }
        ++row;
    }
}

/// `f.formula` in every pixel cell of `sheet`, row by row (the constant-memory mode's order).
/// `pixels`: each pixel's quantities, row by row.
void fill_pixel_sheet(lxw_worksheet* sheet, const PixelFormulas& f,
                      const std::vector<PixelQuantities>& pixels, const Camera& camera,
                      const std::filesystem::path& path) {
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x)
            check_workbook(worksheet_write_formula_num(
                               sheet, static_cast<lxw_row_t>(y), static_cast<lxw_col_t>(x),
                               at_cell(f.formula, cell_name(y, x)).c_str(), nullptr,
                               f.value(pixels[static_cast<size_t>(y) * camera.width + x])),
                           path);
}

/// The picture: cos α + cosⁿγ per cell, a colour scale from the unlit colour (0) to the fully
/// lit diffuse colour (1) to diffuse plus the whole highlight (2), background where t < 0.
void colour_picture(lxw_workbook* book, lxw_worksheet* sheet, const Scene& scene,
                    SampleEncoding encoding, const std::filesystem::path& path) {
    const Material& m = scene.materials[scene.spheres.front().material];
    const Vec3 i0 = std::get<DirectionalLight>(scene.lights.front()).intensity;
    const Vec3 unlit = scene.ambient * m.ka, lit = unlit + i0 * m.kd, shiny = lit + i0 * m.ks;
    const auto last_row = static_cast<lxw_row_t>(scene.camera.height - 1);
    const auto last_column = static_cast<lxw_col_t>(scene.camera.width - 1);
    lxw_format* background = workbook_add_format(book);
    format_set_bg_color(background, file_colour(scene.background, encoding));
    format_set_pattern(background, LXW_PATTERN_SOLID);
    lxw_conditional_format miss{};
    miss.type = LXW_CONDITIONAL_TYPE_CELL;
    miss.criteria = LXW_CONDITIONAL_CRITERIA_LESS_THAN;
    miss.value = 0;
    miss.format = background;
    miss.stop_if_true = LXW_TRUE;
    check_workbook(worksheet_conditional_format_range(sheet, 0, 0, last_row, last_column, &miss),
                   path);
    lxw_conditional_format scale{};
    scale.type = LXW_CONDITIONAL_3_COLOR_SCALE;
    scale.min_rule_type = scale.mid_rule_type = scale.max_rule_type =
        LXW_CONDITIONAL_RULE_TYPE_NUMBER;
    scale.min_value = 0, scale.mid_value = 1, scale.max_value = 2;
    scale.min_color = file_colour(unlit, encoding);
    scale.mid_color = file_colour(lit, encoding);
    scale.max_color = file_colour(shiny, encoding);
    check_workbook(worksheet_conditional_format_range(sheet, 0, 0, last_row, last_column, &scale),
                   path);
}

void write_workbook(lxw_workbook* book, const Scene& scene, SampleEncoding encoding,
                    const std::filesystem::path& path) {
    const Camera& camera = scene.camera;
    const PixelFormulas picture{
        "image", "=IF(t!@>0,MAX(0,cos_alpha!@)+IF(cos_alpha!@>0," + k_specular + ",0),-1)",
        [](const PixelQuantities& q) { return q.image; }};
    const DerivedParameters derived = derived_parameters(scene);
    std::vector<PixelQuantities> pixels;
    pixels.reserve(static_cast<size_t>(camera.width) * camera.height);
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x)
            pixels.push_back(pixel_quantities(scene, derived, x, y, encoding));
    lxw_worksheet* image = add_sheet(book, picture.name, path);
    set_square_cells(image, 0, static_cast<lxw_col_t>(camera.width - 1), k_picture_cell_pixels,
                     path);
    worksheet_gridlines(image, LXW_HIDE_ALL_GRIDLINES);
    colour_picture(book, image, scene, encoding, path);
    fill_pixel_sheet(image, picture, pixels, camera, path);
    write_parameters(book, scene, path);
    for (const PixelFormulas& f : pixel_formulas(encoding))
        fill_pixel_sheet(add_sheet(book, f.name, path), f, pixels, camera, path);
}

}  // namespace

std::string formula_workbook_obstacle(const Scene& scene) {
    if (scene.spheres.size() != 1 || !scene.planes.empty() || scene.triangles.size() != 0)
        return "it computes one sphere and nothing else";
    if (scene.lights.size() != 1 || !light_as<DirectionalLight>(scene.lights[0]))
        return "it computes one directional light";
    const Sphere& s = scene.spheres.front();
    const Material& m = scene.materials[s.material];
    if (m.texture || m.ambient_texture || m.vertex_colours || m.reflectivity > 0 ||
        m.transparency > 0 || m.emission != Vec3(0.0f))
        return "it computes a plain Phong material (no texture, mirror, glass or emission)";
    if (scene.camera.projection != Projection::perspective)
        return "it computes a perspective camera";
    if (length(scene.camera.eye - s.center) <= s.radius)
        return "the eye must be outside the sphere";
    if (scene.sky.gradient || !scene.show_background || scene.depth_cue)
        return "it computes a plain background without depth cueing";
    if (scene.camera.width > k_xlsx_max_columns || scene.camera.height > k_xlsx_max_rows)
        return "the image is larger than a sheet";
    return {};
}

std::vector<uint8_t> encode_xlsx_formulas(const std::filesystem::path& path, const Scene& scene,
                                          SampleEncoding encoding) {
    if (const std::string why = formula_workbook_obstacle(scene); !why.empty())
        fail_workbook(path, "--formulas cannot express this scene: " + why);
    return build_workbook(path,
                          [&](lxw_workbook* book) { write_workbook(book, scene, encoding, path); });
}

}  // namespace hikari
