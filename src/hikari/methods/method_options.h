#pragma once
// The settings that only some rendering methods take, and the command-line options that set them
// (`--spp`, `--interp`, ...): each option is declared once, in the registry (methods/registry.cpp),
// with its help line, the values it takes and the setting it fills, and every method lists the
// options it understands.

#include <optional>
#include <span>
#include <string_view>
#include <variant>

#include "hikari/core/cuda_devices.h"
#include "hikari/core/vec.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/tone_map.h"
#include "hikari/integrators/path/path_tracer.h"
#include "hikari/integrators/whitted/whitted.h"
#include "hikari/io/images/image_write.h"
#include "hikari/raster/lines/line_settings.h"
#include "hikari/raster/raster_settings.h"

namespace hikari {

/// The most samples per pixel `--spp` accepts.
inline constexpr int k_max_samples_per_pixel = 1 << 20;

/// Every method's own settings; each method reads its part.
struct MethodSettings {
    WhittedSettings whitted;  ///< raytrace
    PathSettings path;        ///< path
    /// `--spp` and `--max-depth` when given (raytrace and path read them, each with its own
    /// default and meaning).
    std::optional<int> samples_per_pixel, max_depth;
    RasterSettings raster;  ///< zbuffer, scanline, depthsort, depthsort-naive (and --cull for
                            ///< the line methods)
    LineSettings lines;     ///< wireframe, hiddenline
    /// `--shadows` when given; otherwise each method's default (Method::shadow_modes).
    std::optional<ShadowMode> shadows;
    /// `--light-samples`: samples per area or environment light per point, for every method.
    int light_samples = k_default_light_samples;
    /// `--device`: where raytrace, path and zbuffer run (docs/gpu.md).
    ExecutionDevice device = ExecutionDevice::cpu;
};

/// A word an option takes and the value it stands for (`--interp gouraud`).
template <class T>
struct Choice {
    std::string_view name;  ///< as typed on the command line
    T value;                ///< what it sets
};

/// The value `name` stands for among `choices`, or nullopt.
template <class T>
std::optional<T> choice_value(std::span<const Choice<T>> choices, std::string_view name) {
    for (const Choice<T>& c : choices)
        if (c.name == name) return c.value;
    return std::nullopt;
}

/// The word for `value` among `choices`, or "" when none stands for it.
template <class T>
std::string_view choice_name(std::span<const Choice<T>> choices, T value) {
    for (const Choice<T>& c : choices)
        if (c.value == value) return c.name;
    return {};
}

/// `--aov`'s words (every front end names buffers by them).
inline constexpr Choice<Aov> k_aov_choices[] = {
    {"color", Aov::color},       {"depth", Aov::depth},       {"id", Aov::id},
    {"normal", Aov::normal},     {"ambient", Aov::ambient},   {"diffuse", Aov::diffuse},
    {"specular", Aov::specular}, {"overdraw", Aov::overdraw}, {"paint-order", Aov::paint_order},
    {"spans", Aov::spans},       {"culled", Aov::culled}};

/// The word of `aov` ("paint-order").
inline std::string_view aov_name(Aov aov) { return choice_name<Aov>(k_aov_choices, aov); }

/// `--tonemap`'s words.
inline constexpr Choice<ToneMap> k_tone_map_choices[] = {
    {"clamp", ToneMap::clamp}, {"reinhard", ToneMap::reinhard}, {"aces", ToneMap::aces}};

/// `--encoding`'s words: how 8- and 16-bit files hold linear values.
inline constexpr Choice<SampleEncoding> k_sample_encoding_choices[] = {
    {"srgb", SampleEncoding::srgb}, {"linear", SampleEncoding::linear}};

/// `--interp`: the lecture's three ways to shade a polygon.
inline constexpr Choice<Interpolation> k_interpolation_choices[] = {
    {"flat", Interpolation::flat},
    {"gouraud", Interpolation::gouraud},
    {"phong", Interpolation::phong},
};

/// `--shadows`: how a method decides whether a light reaches a point (Fig 4.24). Which of them
/// a method can do is in its Method::shadow_modes.
inline constexpr Choice<std::optional<ShadowMode>> k_shadow_choices[] = {
    {"none", ShadowMode::none},         {"ray", ShadowMode::ray}, {"map", ShadowMode::map},
    {"volume", ShadowMode::volume},     {"pcf", ShadowMode::pcf}, {"pcss", ShadowMode::pcss},
    {"analytic", ShadowMode::analytic},
};

/// `--filter`: the path tracer's pixel filter.
inline constexpr Choice<PixelFilterKind> k_filter_choices[] = {
    {"box", PixelFilterKind::box},
    {"gaussian", PixelFilterKind::gaussian},
    {"blackman-harris", PixelFilterKind::blackman_harris},
};

/// `--cull`: RasterSettings::cull_back_faces.
inline constexpr Choice<bool> k_cull_choices[] = {{"back", true}, {"none", false}};
/// `--caustics`: light (traced from the lights, integrators/path/caustic_light_tracer.h) or
/// path (found by the path tracer alone).
inline constexpr Choice<bool> k_caustic_choices[] = {{"light", true}, {"path", false}};

/// `--device`: the CPU's threads, or a CUDA GPU (core/device_launch.h).
inline constexpr Choice<ExecutionDevice> k_device_choices[] = {{"cpu", ExecutionDevice::cpu},
                                                               {"cuda", ExecutionDevice::cuda}};

/// Where an option's value goes: one field of MethodSettings.
template <class T>
using SettingsField = T& (*)(MethodSettings&);

/// An option whose value is an integer in [min, max].
struct IntegerOption {
    int min;                   ///< smallest value accepted
    int max;                   ///< largest value accepted
    SettingsField<int> field;  ///< where the value goes
};

/// An option whose value is an integer in [min, max], unset unless given (each method that
/// reads it has its own default).
struct OptionalIntegerOption {
    int min;                                  ///< smallest value accepted
    int max;                                  ///< largest value accepted
    SettingsField<std::optional<int>> field;  ///< where the value goes
};

/// An option whose value is a real number in [min, max].
struct RealOption {
    float min;                   ///< smallest value accepted
    float max;                   ///< largest value accepted
    SettingsField<float> field;  ///< where the value goes
};

/// An option whose value is a linear RGB colour, R,G,B, each ≥ 0.
struct ColorOption {
    SettingsField<std::optional<Vec3>> field;  ///< where the value goes
};

/// An option whose value is one of a few words.
template <class T>
struct ChoiceOption {
    std::span<const Choice<T>> choices;  ///< the words accepted and what each sets
    SettingsField<T> field;              ///< where the value goes
};

/// A command-line option that only some methods understand.
struct MethodOption {
    std::string_view flag;  ///< its one name, e.g. "--spp"
    std::string_view help;  ///< one line for --help
    /// The values it takes and the field they go to.
    std::variant<IntegerOption, OptionalIntegerOption, RealOption, ColorOption,
                 ChoiceOption<Interpolation>, ChoiceOption<bool>,
                 ChoiceOption<std::optional<ShadowMode>>, ChoiceOption<PixelFilterKind>,
                 ChoiceOption<ExecutionDevice>>
        value;
};

}  // namespace hikari
