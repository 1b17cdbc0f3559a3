#pragma once
// A render session (ARCHITECTURE.md, "Data flow"): one scene loaded once, rendered any number of
// times with any method, camera, image size, AOV and method options. What does not depend on the
// camera (the BVHs, the occluders of analytic soft shadows) is built by the first render that
// needs it and kept until the scene changes (core/build_cache.h). A session never prints, exits
// or writes a file: every front end (the command line, and the viewer, Python module and
// animation frames to come) is a thin client of it, and writes images with io/images/.

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hikari/core/build_cache.h"
#include "hikari/core/image.h"
#include "hikari/core/memory_budget.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/frame/line_drawing.h"
#include "hikari/frame/render_settings.h"
#include "hikari/frame/tile_share.h"
#include "hikari/io/scene/scene_overrides.h"
#include "hikari/methods/registry.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// What a session loads: a scene file, a model file framed as a scene, or the built-in default
/// scene (the lecture's assignment); the command line's load options beside it.
struct SceneSource {
    /// A scene (.json) or model file (.obj .ply .gltf .glb); empty: the default scene.
    std::string file;
    /// Scene JSON text instead of a file (`file` then only names it in messages); relative
    /// paths in it are read from `base_dir`.
    std::optional<std::string> json_text;
    std::string base_dir = ".";            ///< for json_text
    std::vector<SceneOverride> overrides;  ///< `--set PATH=VALUE`, applied in order
    bool ground = false;                   ///< a model file: a checkered plane under it
    std::optional<float> crease_angle;     ///< meshes without normals, in degrees
};

/// A request to stop one render, shared between whoever may cancel it (a signal handler, a
/// newer request of a viewer, Ctrl-C in Python) and the render. Copies share the flag.
class CancelToken {
  public:
    /// Asks the render to stop at its next poll (within a tile or a pass). Async-signal-safe.
    void cancel() const noexcept { m_flag->store(true); }
    bool cancelled() const noexcept { return m_flag->load(); }
    /// The flag itself, for a signal handler that may not touch a shared_ptr.
    std::atomic<bool>* flag() const noexcept { return m_flag.get(); }

  private:
    std::shared_ptr<std::atomic<bool>> m_flag = std::make_shared<std::atomic<bool>>(false);
};

/// How far a render has come, for a progress callback.
struct RenderProgress {
    double fraction = 0;  ///< of the render's work units done, 0 to 1 (0 until it knows)
    double seconds = 0;   ///< since the render started
};

/// One render of a session's scene. Everything left unset is the scene's own.
struct RenderRequest {
    std::string method{methods().front().name};  ///< a name of methods(); the default first
    std::optional<Camera> camera;                ///< another camera (its width and height included)
    int width = 0, height = 0;  ///< image size; one alone keeps the camera's aspect ratio
    Aov aov = Aov::color;       ///< the buffer asked for (frame/framebuffer.h)
    MethodSettings options;     ///< the method's own settings (`--spp`, `--shadows`, ...)
    /// FilmFormat::srgb8: the colour developed to 8-bit sRGB as it is rendered (what an 8-bit
    /// picture file keeps, at a quarter of the memory); linear otherwise.
    FilmFormat film = FilmFormat::linear;
    int tessellation = 0;  ///< every sphere's polygons around the equator; 0: the scene's
    /// Depth cueing's near and far distances (`--depth-cue`), over the scene's own.
    std::optional<std::pair<float, float>> depth_cue;
    bool wireframe_overlay = false;  ///< the triangles' edges drawn over the colour, near black
    /// An algorithm AOV as its counts and positions (for float files) instead of a picture.
    bool algorithm_counts = false;
    int threads = 0;  ///< worker threads; 0: every core. Images do not depend on it
    /// Called about ten times a second from another thread while the render runs.
    std::function<void(const RenderProgress&)> progress;
    std::optional<CancelToken> cancel;  ///< stops the render early: render() throws Interrupted
    /// Processes sharing this image (MPI ranks): this one renders its tiles and the share's
    /// combine gathers them (frame/tile_share.h). Not owned; null: the whole image. Only methods
    /// that declare Method::shares_tiles take it; the others render the whole image.
    const TileShare* tile_share = nullptr;
};

/// The step of an algorithm `hikari explain` prints: a pixel (the Z-buffer's fragments, the ray
/// tracer's ray tree), a row (the scanline method's lists) or, with neither, the whole run (the
/// depth sort).
struct ExplainStep {
    std::optional<std::pair<int, int>> pixel;  ///< x, y (0, 0 at the top left)
    std::optional<int> row;                    ///< 0 at the top
};

/// What a render gives back.
struct RenderResult {
    /// Colour (RenderRequest::film) and the AOV buffers; empty for an algorithm AOV.
    Framebuffer framebuffer;
    /// An algorithm AOV's picture (explain/algorithm_aovs.h) and its one-line reading.
    std::optional<Image> algorithm_picture;
    std::string algorithm_summary;
    std::unique_ptr<RenderStats> stats = std::make_unique<RenderStats>();
    std::vector<std::string> warnings;  ///< what the method says about the scene
    double seconds = 0;                 ///< wall time of the render
};

/// One scene and what is built from it, rendered many times. Not for two renders at once (the
/// viewer serializes them); every call may throw InputError with the message the command line
/// prints.
class Session {
  public:
    /// Loads `source` (the command line's loaders, overrides, errors and limits). Throws
    /// InputError, or Interrupted when request_cancel() stops the load.
    explicit Session(SceneSource source);
    /// A session over a scene built elsewhere (tests, generated scenes).
    explicit Session(Scene scene);

    const Scene& scene() const { return *m_scene; }
    const SceneSource& source() const { return m_source; }
    /// What the load had to say (skipped triangles, unsupported features), one line each.
    const std::vector<std::string>& load_warnings() const { return m_warnings; }
    /// Wall time of the last load, seconds.
    double load_seconds() const { return m_load_seconds; }

    /// Changes one scene value by its JSON path (`materials.clay.shininess`, as `--set`) and
    /// reloads; what was built from parts the change left alone is kept. Throws InputError
    /// naming the path, leaving the session as it was.
    void set(const SceneOverride& edit);
    /// Replaces the scene; what was built from parts equal in both is kept.
    void replace_scene(Scene scene);

    /// A copy of the scene as `request` renders it: its camera and size, depth cue,
    /// tessellation and shading term (for views of the scene such as `hikari explain`).
    Scene scene_as_rendered(const RenderRequest& request);
    /// The camera `request` renders with: its own or the scene's, at its image size.
    Camera camera_for(const RenderRequest& request) const;
    /// Renders the scene as `request` asks. Throws InputError for an unknown method, a buffer
    /// the method has no picture of, or an image over the memory limit; Interrupted when the
    /// request's token (or request_cancel()) stopped it.
    RenderResult render(const RenderRequest& request);
    /// The line segments a line method draws (what `-o drawing.svg` writes).
    LineDrawing draw(const RenderRequest& request);
    /// One step of `request.method`'s algorithm as `hikari explain` prints it (explain/explain.h),
    /// on the scene as `request` renders it. Throws InputError for a method without that view,
    /// a missing --pixel/--row it needs, or a pixel or row outside the image.
    std::string explain(const RenderRequest& request, const ExplainStep& step);

    /// How many structures the session keeps built (for tests and `--stats`).
    size_t kept_structures() const { return m_cache->size(); }

  private:
    /// The scene a request renders: the session's own with the request's camera and depth cue,
    /// or a copy changed further (tessellation, one shading term), which builds for itself.
    const Scene& scene_for(const RenderRequest& request, std::optional<Scene>& changed);
    void adopt(Scene fresh);

    SceneSource m_source;
    std::unique_ptr<Scene> m_scene;       ///< stable address: kept structures refer to it
    std::unique_ptr<BuildCache> m_cache;  ///< bound to *m_scene
    Camera m_camera;                      ///< the scene's own camera
    std::optional<DepthCue> m_depth_cue;  ///< the scene's own depth cue
    std::vector<std::string> m_warnings;
    double m_load_seconds = 0;
    /// What loading the scene grew the process by: held while the session lives, so every
    /// render's buffers count against the memory limit together with the scene.
    std::optional<MemoryHeld> m_scene_memory;
};

/// The scene `source` names, loaded as a session loads it, appending the loaders' warnings (for
/// front ends that need the scene alone, such as `hikari explain`).
Scene load_scene_source(const SceneSource& source, std::vector<std::string>& warnings);

/// The method called `name`, or InputError listing the methods.
const Method& method_named(std::string_view name);

/// Refuses (InputError) an image whose buffers would not fit in the memory limit
/// (core/memory_budget.h), before any is allocated. Session::render checks it first.
void check_image_memory(const Camera& camera);

/// `camera` at `width` × `height`; one of them 0 keeps the aspect ratio, both 0 keep the size.
Camera resized_camera(Camera camera, int width, int height);

}  // namespace hikari
