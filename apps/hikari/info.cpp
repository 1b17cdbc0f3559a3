#include "info.h"

#include <fmt/format.h>

#include <chrono>
#include <set>
#include <span>
#include <thread>
#include <variant>
#include <vector>

#include "cli_options.h"
#include "console.h"
#include "hikari/core/cuda_devices.h"
#include "hikari/io/models/model_file.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari {
namespace {

std::string vec(Vec3 v) { return fmt::format("({:.4g}, {:.4g}, {:.4g})", v.x, v.y, v.z); }

std::string bounds_line(std::span<const Vec3> points) {
    if (points.empty()) return "  bounds      none\n";
    Vec3 lo(INFINITY), hi(-INFINITY);
    for (const Vec3& p : points) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    return fmt::format("  bounds      {} to {}, size {}\n", vec(lo), vec(hi), vec(hi - lo));
}

/// The image files the materials' textures read, each once.
std::set<std::string> texture_files(std::span<const Material> materials) {
    std::set<std::string> files;
    for (const Material& m : materials)
        for (const std::optional<Texture>* t : {&m.texture, &m.ambient_texture})
            if (*t)
                if (const auto* image = std::get_if<ImageTexture>(&**t)) files.insert(image->file);
    return files;
}

std::string materials_lines(std::span<const Material> materials) {
    std::string text = fmt::format("  materials   {}\n", materials.size());
    for (const Material& m : materials)
        text += fmt::format("    {:<20} kd {}  ks {}  shininess {:g}{}\n",
                            m.name.empty() ? "(unnamed)" : m.name, vec(m.kd), vec(m.ks),
                            m.shininess, m.texture ? "  textured" : "");
    const std::set<std::string> files = texture_files(materials);
    text += fmt::format("  textures    {}\n", files.size());
    for (const std::string& f : files) text += fmt::format("    {}\n", f);
    return text;
}

std::string lights_lines(std::span<const Light> lights) {
    std::string text = fmt::format("  lights      {}\n", lights.size());
    for (const Light& light : lights)
        text += visit_light(
            light, Overloaded{
                       [](const PointLight& p) {
                           return fmt::format("    point at {}, intensity {}\n", vec(p.position),
                                              vec(p.intensity));
                       },
                       [](const SpotLight& s) {
                           return fmt::format(
                               "    spot at {} toward {}, intensity {}, cone {:g}°–{:g}°\n",
                               vec(s.position), vec(s.direction), vec(s.intensity), s.inner_angle,
                               s.outer_angle);
                       },
                       [](const DirectionalLight& d) {
                           return fmt::format("    directional toward {}, intensity {}\n",
                                              vec(d.direction), vec(d.intensity));
                       },
                       [](const AreaLight& a) {
                           return fmt::format("    area at {}, radiance {}\n", vec(a.centre()),
                                              vec(a.radiance));
                       },
                       [](const EnvironmentLight&) { return std::string("    environment\n"); },
                   });
    return text;
}

std::string camera_line(const Camera& c) {
    return fmt::format("    eye {} looking at {}, fov_y {:g}°, {}x{}\n", vec(c.eye), vec(c.look_at),
                       c.fov_y_degrees, c.width, c.height);
}

}  // namespace

std::string info_report(const std::filesystem::path& file) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    std::string text;
    if (is_model_file(file)) {
        const MeshData mesh = load_model(file);
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        text += fmt::format("{}: model, loaded in {:.1f} ms\n", file.string(), ms);
        text += fmt::format("  triangles   {}", mesh.indices.size());
        if (mesh.degenerate_skipped > 0)
            text += fmt::format(" ({} degenerate skipped)", mesh.degenerate_skipped);
        text += fmt::format("\n  vertices    {}{}\n", mesh.positions.size(),
                            mesh.uvs.empty() ? "" : ", with texture coordinates");
        text += bounds_line(mesh.positions);
        text += materials_lines(mesh.materials);
        text += lights_lines(mesh.lights);
        text += fmt::format("  cameras     {}\n", mesh.cameras.size());
        for (const ModelCamera& c : mesh.cameras) text += camera_line(c.camera);
        for (const std::string& w : mesh.warnings) text += fmt::format("  warning: {}\n", w);
        return text;
    }
    std::vector<std::string> warnings;
    const Scene scene = load_scene_file(file, warnings);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    text += fmt::format("{}: scene, loaded in {:.1f} ms\n", file.string(), ms);
    text += fmt::format("  triangles   {}\n  vertices    {}\n  spheres     {}\n  planes      {}\n",
                        scene.triangles.indices.size(), scene.triangles.positions.size(),
                        scene.spheres.size(), scene.planes.size());
    text += bounds_line(scene.triangles.positions);
    text += materials_lines(scene.materials);
    text += lights_lines(scene.lights);
    text += "  camera\n" + camera_line(scene.camera);
    for (const std::string& w : warnings) text += fmt::format("  warning: {}\n", w);
    return text;
}

std::string devices_report() {
    std::string text = fmt::format("cpu: {} threads (--device cpu, the default)\n",
                                   std::thread::hardware_concurrency());
    const CudaDevices cuda = find_cuda_devices();
    for (size_t d = 0; d < cuda.devices.size(); ++d) {
        const CudaDevice& device = cuda.devices[d];
        text += fmt::format(
            "cuda {}: {}, compute capability {}.{}, {} multiprocessors, {:.1f} GiB "
            "(--device cuda)\n",
            d, device.name, device.compute_major, device.compute_minor, device.multiprocessors,
            static_cast<double>(device.memory_bytes) / (1024.0 * 1024.0 * 1024.0));
    }
    if (!cuda.problem.empty()) text += fmt::format("cuda: {}\n", cuda.problem);
    return text;
}

namespace cli {

CLI::App* add_info_command(CLI::App& app, std::string& file, bool& devices) {
    CLI::App* info = app.add_subcommand(
        "info",
        "Print what a model or scene file holds: triangles, vertices, bounds, materials, "
        "textures, lights, cameras, and the load time; or, with --devices, the devices a render "
        "can run on.");
    info->add_option("file", file, "Model (.obj, .ply, .gltf, .glb) or scene (.json) file");
    info->add_flag("--devices", devices,
                   "List the devices --device can name: the CPU, and the CUDA GPUs found (or why "
                   "there are none)");
    add_max_memory_option(*info, "files");
    return info;
}

int run_info(const std::string& file, bool devices) {
    if (devices) print_out("{}", devices_report());
    if (!file.empty()) print_out("{}", info_report(file));
    if (!devices && file.empty())
        throw UsageError("info: give a model or scene FILE, or --devices");
    return 0;
}

}  // namespace cli

}  // namespace hikari
