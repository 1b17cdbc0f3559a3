// hikari.Scene: a render session (session/session.h) for Python. A render runs on its own
// thread while the calling thread waits with the GIL released, so other Python threads run,
// Ctrl-C (KeyboardInterrupt) stops it within a tenth of a second, and the progress callback is
// called on the caller's thread. Python threads sharing a Scene take turns (SharedSession).
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <future>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include "bindings.h"
#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/methods/method_option_text.h"
#include "hikari/session/scene_document.h"
#include "hikari/session/session.h"
#include "python_json.h"
#include "scene_words.h"

namespace hikari::python {

namespace {

/// A session as Python threads share it: one call at a time, since a render reads what set()
/// replaces. A second thread waits its turn without the GIL (and still hears Ctrl-C).
struct SharedSession {
    explicit SharedSession(std::unique_ptr<Session> s) : session(std::move(s)) {}
    std::unique_ptr<Session> session;
    std::timed_mutex busy;
    std::atomic<std::thread::id> holder{};
};

/// The calling thread's turn on a SharedSession, for the lifetime of the object. A call from
/// the thread already holding it (a progress callback rendering the scene it reports on) is
/// refused rather than left waiting for itself.
class SessionTurn {
  public:
    explicit SessionTurn(SharedSession& shared) : m_shared(shared) {
        if (shared.holder.load() == std::this_thread::get_id())
            throw InputError(
                "this scene is busy with a call on the same thread (a progress callback "
                "cannot render, change or explain the scene it reports on)");
        while (true) {
            {
                py::gil_scoped_release unlocked;
                if (shared.busy.try_lock_for(std::chrono::milliseconds(20))) break;
            }
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        }
        shared.holder.store(std::this_thread::get_id());
    }
    ~SessionTurn() {
        m_shared.holder.store(std::thread::id{});
        m_shared.busy.unlock();
    }
    SessionTurn(const SessionTurn&) = delete;
    SessionTurn& operator=(const SessionTurn&) = delete;
    Session& session() const { return *m_shared.session; }

  private:
    SharedSession& m_shared;
};

/// `--set PATH=VALUE` from a Python path and value.
SceneOverride scene_edit(const std::string& path, const py::handle& value) {
    if (path.empty()) throw InputError("set: the path is empty");
    SceneOverride edit{path + "=" + py::str(value).cast<std::string>(), path,
                       json_of_python(value, "set", path)};
    return edit;
}

/// A method option's value as the command line writes it: 16, 0.5, map, 0.1,0.2,0.3.
std::string option_text(const std::string& name, const py::handle& value) {
    if (py::isinstance<py::bool_>(value))
        throw InputError(name + ": a method option is not a bool");
    return option_text_of_json(json_of_python(value, name));
}

/// `count` numbers from a Python sequence, or InputError naming `what`.
template <class Number>
std::vector<Number> numbers_of(const py::handle& value, size_t count, const std::string& what) {
    std::vector<Number> numbers;
    if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value))
        for (const py::handle item : value.cast<py::sequence>()) {
            const bool integral =
                py::isinstance<py::int_>(item) && !py::isinstance<py::bool_>(item);
            if (!integral &&
                !(std::is_floating_point_v<Number> && py::isinstance<py::float_>(item)))
                break;
            const Number number = item.cast<Number>();
            if constexpr (std::is_floating_point_v<Number>)
                if (!std::isfinite(number)) break;
            numbers.push_back(number);
        }
    if (numbers.size() != count || py::len(value) != count)
        throw InputError(
            fmt::format("{}: expected {} {}", what, count,
                        std::is_floating_point_v<Number> ? "finite numbers" : "whole numbers"));
    return numbers;
}

Vec3 vec3_of(const py::handle& value, const char* what) {
    const auto v = numbers_of<float>(value, 3, std::string("camera.") + what);
    return {v[0], v[1], v[2]};
}

/// `camera` (a dict with any of eye, look_at, up, fov_y, projection, view_height, width, height)
/// over `base`.
Camera camera_of(const py::handle& camera, Camera base) {
    if (!py::isinstance<py::dict>(camera))
        throw InputError(
            "camera: expected a dict with any of eye, look_at, up, fov_y, projection, "
            "view_height, width, height");
    for (const auto& [key_handle, value] : camera.cast<py::dict>()) {
        const std::string key = py::str(key_handle);
        if (key == "eye")
            base.eye = vec3_of(value, "eye");
        else if (key == "look_at")
            base.look_at = vec3_of(value, "look_at");
        else if (key == "up")
            base.up = vec3_of(value, "up");
        else if (key == "fov_y")
            base.fov_y_degrees = value.cast<float>();
        else if (key == "view_height")
            base.view_height = value.cast<float>();
        else if (key == "width")
            base.width = value.cast<int>();
        else if (key == "height")
            base.height = value.cast<int>();
        else if (key == "projection") {
            const std::string p = py::str(value);
            if (p != "perspective" && p != "orthographic")
                throw InputError("camera.projection: expected perspective or orthographic");
            base.projection =
                p == "perspective" ? Projection::perspective : Projection::orthographic;
        } else
            throw InputError("camera: unknown key '" + key +
                             "' (keys: eye, look_at, up, fov_y, projection, view_height, width, "
                             "height)");
    }
    if (!(base.fov_y_degrees > 0.0f && base.fov_y_degrees < 180.0f))
        throw InputError("camera.fov_y: expected degrees between 0 and 180");
    if (!(base.view_height > 0.0f))
        throw InputError("camera.view_height: expected a positive number");
    if (base.width < 1 || base.height < 1 || base.width > 65536 || base.height > 65536)
        throw InputError("camera: width and height must be 1 to 65536 pixels");
    if (const char* fault = camera_view_fault(base))
        throw InputError(std::string("camera: ") + fault);
    return base;
}

py::dict camera_dict(const Camera& c) {
    py::dict d;
    d["eye"] = py::make_tuple(c.eye.x, c.eye.y, c.eye.z);
    d["look_at"] = py::make_tuple(c.look_at.x, c.look_at.y, c.look_at.z);
    d["up"] = py::make_tuple(c.up.x, c.up.y, c.up.z);
    d["projection"] = c.projection == Projection::perspective ? "perspective" : "orthographic";
    d["fov_y"] = c.fov_y_degrees;
    d["view_height"] = c.view_height;
    d["width"] = c.width;
    d["height"] = c.height;
    return d;
}

/// How work running on its own thread is asked to stop on Ctrl-C: a render through its own
/// token, and every stage (a load, a BVH build, the depth sort, an explanation) through the
/// process-wide request (core/cancel.h) that they poll, as the command line's SIGINT does. The
/// request is withdrawn once the work has ended, so that the next call runs. A progress
/// callback's exception concerns its own render alone: it stops the render by its token, and
/// other threads' work goes on.
struct Stopper {
    std::optional<CancelToken> token;
    /// Ctrl-C: everything this process runs.
    void stop() const {
        if (token) token->cancel();
        request_cancel();
    }
    /// A failed progress callback: this work alone where it has a token.
    void stop_own() const {
        if (token)
            token->cancel();
        else
            request_cancel();
    }
    /// After the stopped work has ended.
    void settle() const { clear_cancel_request(); }
};

/// Runs `work` on its own thread while this one waits without the GIL; every 20 ms it takes the
/// GIL to let Python handle signals (Ctrl-C stops the work through `stopper`) and to report
/// `fraction` to `progress` (None: no reports).
template <class Work>
auto run_interruptible(Work&& work, const Stopper& stopper, const std::atomic<double>& fraction,
                       const py::object& progress) {
    auto future = std::async(std::launch::async, std::forward<Work>(work));
    bool interrupted = false;
    double reported = -1.0;
    while (true) {
        {
            py::gil_scoped_release unlocked;
            if (future.wait_for(std::chrono::milliseconds(20)) == std::future_status::ready) break;
        }
        if (!interrupted && PyErr_CheckSignals() != 0) {
            interrupted = true;  // the pending exception (KeyboardInterrupt) is raised below
            stopper.stop();
        }
        if (!interrupted && !progress.is_none() && fraction.load() != reported &&
            fraction.load() < 1.0) {
            reported = fraction.load();
            try {
                progress(reported);
            } catch (...) {
                stopper.stop_own();
                {
                    py::gil_scoped_release unlocked;
                    future.wait();
                }
                if (!stopper.token) stopper.settle();
                throw;
            }
        }
    }
    if (interrupted) {
        try {
            future.get();
        } catch (...) {  // the work's own report of the interruption
        }
        stopper.settle();
        throw py::error_already_set();
    }
    auto result = future.get();
    // The end is always reported, however quickly the work went.
    if (!progress.is_none()) progress(1.0);
    return result;
}

/// `work` (a load, an explanation) on its own thread, stopped by Ctrl-C, without progress.
template <class Work>
auto run_interruptible(Work&& work) {
    const std::atomic<double> no_fraction{0.0};
    return run_interruptible(std::forward<Work>(work), Stopper{}, no_fraction, py::none());
}

/// A count AOV (overdraw, paint-order) as one float per pixel, (H, W), as ids are.
py::array count_array(const Image& counts) {
    py::array_t<float> out(
        {static_cast<py::ssize_t>(counts.height), static_cast<py::ssize_t>(counts.width)});
    float* values = out.mutable_data();
    for (size_t i = 0; i < counts.pixels.size(); ++i) values[i] = counts.pixels[i].x;
    return out;
}

/// What render() and explain() ask of the session: method, size, camera and method options.
RenderRequest request_of(const Session& session, const std::string& method,
                         std::optional<int> width, std::optional<int> height,
                         const py::object& camera, const py::kwargs& options) {
    RenderRequest request;
    request.method = method;
    const Method& chosen = method_named(method);
    if (!camera.is_none()) request.camera = camera_of(camera, session.scene().camera);
    if (width && *width < 1) throw InputError("width: expected a positive number of pixels");
    if (height && *height < 1) throw InputError("height: expected a positive number of pixels");
    request.width = width.value_or(0);
    request.height = height.value_or(0);
    for (const auto& [name, value] : options)
        set_method_option(request.options, chosen, py::str(name).cast<std::string>(),
                          option_text(py::str(name).cast<std::string>(), value));
    return request;
}

py::object render(SharedSession& shared, const std::string& method, std::optional<int> width,
                  std::optional<int> height, const std::string& aov, const py::object& camera,
                  std::optional<int> threads, const py::object& progress,
                  const py::kwargs& options) {
    if (!progress.is_none() && PyCallable_Check(progress.ptr()) == 0)
        throw py::type_error("progress: expected a callable, called with the fraction done");
    const SessionTurn turn(shared);
    Session& session = turn.session();
    RenderRequest request = request_of(session, method, width, height, camera, options);
    const std::optional<Aov> buffer = aov_named(aov);
    if (!buffer) throw InputError("aov: '" + aov + "' is not an AOV (see hikari.methods())");
    request.aov = *buffer;
    request.algorithm_counts = true;
    if (threads && *threads < 0) throw InputError("threads: expected 0 (every core) or more");
    request.threads = threads.value_or(0);
    const CancelToken token;
    request.cancel = token;
    std::atomic<double> fraction{0.0};
    request.progress = [&fraction](const RenderProgress& p) { fraction.store(p.fraction); };
    RenderResult result = run_interruptible([&] { return session.render(request); }, Stopper{token},
                                            fraction, progress);
    if (result.algorithm_picture && is_count_aov(request.aov))
        return count_array(*result.algorithm_picture);
    if (result.algorithm_picture) return image_array(std::move(*result.algorithm_picture));
    return framebuffer_array(std::move(result.framebuffer), request.aov);
}

/// `hikari explain`'s text for one step of a method's algorithm (Session::explain).
std::string explain(SharedSession& shared, const std::string& method, const py::object& pixel,
                    std::optional<int> row, std::optional<int> width, std::optional<int> height,
                    const py::object& camera, const py::kwargs& options) {
    const SessionTurn turn(shared);
    Session& session = turn.session();
    const RenderRequest request = request_of(session, method, width, height, camera, options);
    ExplainStep step;
    if (!pixel.is_none()) {
        const auto xy = numbers_of<int>(pixel, 2, "pixel");
        step.pixel = std::pair{xy[0], xy[1]};
    }
    step.row = row;
    return run_interruptible([&] { return session.explain(request, step); });
}

/// The scene as a scene file with the view `camera` (a dict, as render takes) at the size asked
/// (session/scene_document.h): `hikari render` of that file renders what render() gives.
std::string scene_json(SharedSession& shared, std::optional<int> width, std::optional<int> height,
                       const py::object& camera) {
    const SessionTurn turn(shared);
    const Session& session = turn.session();
    const RenderRequest request = request_of(session, "raytrace", width, height, camera, {});
    return scene_document(session.source(), session.camera_for(request)).dump(2) + "\n";
}

SceneSource file_source(const std::string& path, const py::object& set, bool ground,
                        std::optional<float> crease_angle, const py::object& camera_from,
                        const py::object& look_at) {
    SceneSource source;
    source.file = path;
    source.ground = ground;
    source.crease_angle = crease_angle;
    if (py::isinstance<py::dict>(set))
        for (const auto& [p, v] : set.cast<py::dict>())
            source.overrides.push_back(scene_edit(py::str(p), v));
    else if (!set.is_none())
        for (const py::handle item : set.cast<py::sequence>())
            source.overrides.push_back(parse_scene_override(py::str(item).cast<std::string>()));
    if (!camera_from.is_none()) source.overrides.push_back(scene_edit("camera.eye", camera_from));
    if (!look_at.is_none()) source.overrides.push_back(scene_edit("camera.look_at", look_at));
    return source;
}

/// A session loaded with the GIL released (a large model takes a while); Ctrl-C stops it.
std::unique_ptr<SharedSession> load_session(SceneSource source) {
    return std::make_unique<SharedSession>(
        run_interruptible([&] { return std::make_unique<Session>(std::move(source)); }));
}

py::dict scene_info(SharedSession& shared) {
    const SessionTurn turn(shared);
    const Scene& s = turn.session().scene();
    py::dict d;
    d["triangles"] = s.triangles.size();
    d["spheres"] = s.spheres.size();
    d["planes"] = s.planes.size();
    d["lights"] = s.lights.size();
    py::list materials;
    for (const Material& m : s.materials) materials.append(m.name);
    d["materials"] = materials;
    return d;
}

}  // namespace

void bind_scene(py::module_& m) {
    py::class_<SharedSession>(
        m, "Scene",
        "A scene loaded once and rendered many times: later renders reuse its BVH "
        "and what else does not depend on the camera.")
        .def_static(
            "load",
            [](const std::string& path, const py::object& set, bool ground,
               std::optional<float> crease_angle, const py::object& camera_from,
               const py::object& look_at) {
                return load_session(
                    file_source(path, set, ground, crease_angle, camera_from, look_at));
            },
            py::arg("path"), py::kw_only(), py::arg("set") = py::none(), py::arg("ground") = false,
            py::arg("crease_angle") = py::none(), py::arg("camera_from") = py::none(),
            py::arg("look_at") = py::none(),
            "Loads a scene file (.json) or a model (.obj .ply .gltf .glb, framed with default "
            "lights), as `hikari render` does; `set` takes {'path': value} or ['PATH=VALUE'].")
        .def_static(
            "from_json",
            [](const std::string& text, const std::string& base_dir, const std::string& name) {
                SceneSource source;
                source.file = name;
                source.json_text = text;
                source.base_dir = base_dir;
                return load_session(std::move(source));
            },
            py::arg("text"), py::arg("base_dir") = ".", py::arg("name") = "scene",
            "A scene from scene-format JSON text (docs/scene-format.md); relative file paths are "
            "read from base_dir.")
        .def_static(
            "from_data",
            [](const py::object& data, const std::string& base_dir, const std::string& name) {
                SceneSource source;
                source.file = name;
                source.json_text = json_of_python(data, name).dump();
                source.base_dir = base_dir;
                return load_session(std::move(source));
            },
            py::arg("data"), py::arg("base_dir") = ".", py::arg("name") = "scene",
            "A scene from the scene format as Python data (dicts, lists, numbers, strings); a "
            "value JSON cannot hold (NaN, a set, an object) is an InputError naming its path.")
        .def_static(
            "default", [] { return load_session({}); },
            "The default scene: the lecture's assignment, a Phong-shaded sphere.")
        .def(
            "set",
            [](SharedSession& shared, const std::string& path, const py::object& value) {
                const SceneOverride edit = scene_edit(path, value);
                const SessionTurn turn(shared);
                run_interruptible([&] {  // a reload: a large model takes a while
                    turn.session().set(edit);
                    return true;
                });
            },
            py::arg("path"), py::arg("value"),
            "Changes one value by its JSON path, as --set does (`materials.clay.shininess`, 5).")
        .def("render", &render, py::arg("method") = "raytrace", py::arg("width") = py::none(),
             py::arg("height") = py::none(), py::arg("aov") = "color",
             py::arg("camera") = py::none(), py::arg("threads") = py::none(),
             py::arg("progress") = py::none(),
             "Renders the scene: float32 linear values, (H, W, 3) for colour, normals, spans and "
             "culled, (H, W) for depth, ids, overdraw and paint-order. Method options as keywords "
             "(spp=16, shadows='pcf').")
        .def("explain", &explain, py::arg("method"), py::arg("pixel") = py::none(),
             py::arg("row") = py::none(), py::arg("width") = py::none(),
             py::arg("height") = py::none(), py::arg("camera") = py::none(),
             "One step of a method's algorithm as `hikari explain` prints it: pixel=(x, y) for "
             "zbuffer and raytrace, row=y for scanline, neither for the depth sort.")
        .def("to_json", &scene_json, py::arg("width") = py::none(), py::arg("height") = py::none(),
             py::arg("camera") = py::none(),
             "The scene as scene-format JSON with this camera and size: `hikari render` of the "
             "file renders what render() gives (files named by absolute paths, `set` applied).")
        .def_property_readonly("camera",
                               [](SharedSession& shared) {
                                   const SessionTurn turn(shared);
                                   return camera_dict(turn.session().scene().camera);
                               })
        .def_property_readonly("warnings",
                               [](SharedSession& shared) {
                                   const SessionTurn turn(shared);
                                   return turn.session().load_warnings();
                               })
        .def_property_readonly("load_seconds",
                               [](SharedSession& shared) {
                                   const SessionTurn turn(shared);
                                   return turn.session().load_seconds();
                               })
        .def_property_readonly("kept_structures",
                               [](SharedSession& shared) {
                                   const SessionTurn turn(shared);
                                   return turn.session().kept_structures();
                               })
        .def_property_readonly("info", &scene_info);
}

}  // namespace hikari::python
