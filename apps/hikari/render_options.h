#pragma once
// The options of `hikari render` (and the scene options `explain` shares with it).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frame_options.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/tone_map.h"
#include "hikari/io/scene/scene_overrides.h"
#include "hikari/methods/method_options.h"
#include "hikari/methods/registry.h"
#include "hikari/shading/shading_terms.h"

namespace hikari::cli {

/// Everything `hikari render` was asked; the load, render and write steps read their parts.
struct RenderOptions {
    std::string scene_file;  ///< empty: the built-in assignment scene
    std::string output;
    /// -m a,b,c: each in turn, one scene load; default: the registry's first (raytrace).
    std::vector<std::string> methods{std::string(hikari::methods().front().name)};
    Aov aov = Aov::color;
    int width = 0, height = 0;
    int threads = 0;
    double max_memory_gib = 0;
    double max_input_gib = 0;  ///< --max-input-size; 0 = each kind's default
    bool quiet = false;
    bool stats = false;
    bool print_matrices = false;
    bool wireframe_overlay = false;
    int tessellation = 0;            ///< --tessellation N: every sphere's segments; 0: the scene's
    std::vector<float> depth_cue;    ///< --depth-cue NEAR,FAR; empty: the scene's own, if any
    std::vector<float> depth_range;  ///< --depth-range NEAR,FAR; empty: the visible range
    std::vector<SceneOverride> overrides;  ///< --set PATH=VALUE, in order
    bool ground = false;                   ///< --ground: a plane under a model file
    std::vector<float> camera_from;        ///< --camera-from X,Y,Z; empty: the scene's or framing
    std::vector<float> look_at;            ///< --look-at X,Y,Z
    float crease_angle = -1;               ///< --crease-angle DEG; negative: each mesh's own
    MethodSettings own;                 ///< every method option; the chosen method reads its part
    std::vector<std::string> notes;     ///< warnings found while checking the command line
    float exposure = 0.0f;              ///< --exposure EV: colour × 2^EV in every format
    ToneMap tone_map = ToneMap::clamp;  ///< --tonemap: for the formats of display values
    int bit_depth = 8;                  ///< --bit-depth: 16 for .png and .ppm
    SampleEncoding encoding = SampleEncoding::srgb;  ///< --encoding of the integer formats
    bool formulas = false;  ///< --formulas: an .xlsx that computes the picture itself
    FrameOptions frames;    ///< --turntable, --frames, --shard: an animation
};

/// --bit-depth and --encoding, as the image writer takes them.
inline ImageWriteSettings image_write_settings(const RenderOptions& o) {
    return ImageWriteSettings{o.bit_depth, o.encoding};
}

}  // namespace hikari::cli
