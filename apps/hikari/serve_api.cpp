#include "serve_api.h"

#include <array>
#include <chrono>
#include <exception>
#include <new>
#include <thread>
#include <utility>

#include <fmt/format.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/frame/tone_map.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/scene/json_reader.h"
#include "hikari/methods/method_catalog.h"
#include "hikari/methods/method_options.h"
#include "hikari/session/developed_frame.h"
#include "hikari/session/request_json.h"
#include "hikari/session/scene_document.h"
#include "serve_page.h"

namespace hikari::cli {

namespace {

using Json = nlohmann::json;

/// A render that a newer request of the same client replaced: HTTP 409.
class Superseded : public std::runtime_error {
  public:
    Superseded() : std::runtime_error("replaced by a newer request of the same client") {}
};

/// The keys a render or explain request may hold besides the render request's own.
constexpr std::array<std::string_view, 7> k_frame_keys = {"scene",  "client", "exposure", "tonemap",
                                                          "format", "pixel",  "row"};

/// Loaded scenes kept at once; asking for one more unloads one of them.
constexpr size_t k_kept_scenes = 4;

/// Runs `handler`, turning what it throws into the status and one line of text.
template <class Handler>
void answer(httplib::Response& res, Handler&& handler) {
    try {
        handler();
        return;
    } catch (const InputError& e) {
        res.status = 400;
        res.set_content(e.what(), "text/plain; charset=utf-8");
    } catch (const ForbiddenPath& e) {
        res.status = 403;
        res.set_content(e.what(), "text/plain; charset=utf-8");
    } catch (const MissingPath& e) {
        res.status = 404;
        res.set_content(e.what(), "text/plain; charset=utf-8");
    } catch (const Superseded& e) {
        res.status = 409;
        res.set_content(e.what(), "text/plain; charset=utf-8");
    } catch (const Interrupted&) {
        res.status = 503;
        res.set_content("the server is stopping", "text/plain; charset=utf-8");
    } catch (const std::bad_alloc&) {
        res.status = 507;
        res.set_content("out of memory", "text/plain; charset=utf-8");
    } catch (const std::exception& e) {
        res.status = 500;
        res.set_content(e.what(), "text/plain; charset=utf-8");
    }
}

/// A request body as JSON, or InputError "request:LINE:COLUMN: ...".
Json request_json(const std::string& body) { return parse_json(body, "request"); }

/// The string member `key` of a request, or `fallback`.
std::string string_member(const Json& body, std::string_view key, std::string fallback) {
    const JsonNode root(body, "request", "");
    return root.has(key) ? root.at(key).as_string() : std::move(fallback);
}

/// The frame's bytes: a colour render developed as `exposure` and `tonemap` ask, an AOV as its
/// picture (PNG) or its values (PFM), as `hikari render -o frame.png|pfm` writes them.
std::string encode_frame(RenderResult& result, const RenderRequest& request, const Scene& scene,
                         const std::string& format, float exposure, ToneMap tonemap) {
    const std::filesystem::path name = "frame." + format;
    const Development how{request.aov, exposure, tonemap, std::nullopt, format == "png"};
    const DevelopedImage image = develop(std::move(result), how, scene);
    const std::vector<uint8_t> bytes =
        std::visit([&](const auto& picture) { return encode_image(name, picture); }, image);
    return {bytes.begin(), bytes.end()};
}

}  // namespace

ServeApi::ServeApi(const std::filesystem::path& root, std::string default_scene)
    : m_files(root), m_default_scene(std::move(default_scene)) {
    if (!m_default_scene.empty()) m_files.resolve(m_default_scene);
}

std::shared_ptr<ServeApi::LoadedScene> ServeApi::scene(const std::string& name) {
    // The file is checked before the lock: a bad name costs nobody a wait.
    const std::filesystem::path path = name.empty() ? "" : m_files.resolve(name);
    std::shared_ptr<LoadedScene> loaded;
    {
        const std::scoped_lock lock(m_mutex);
        auto it = m_scenes.find(name);
        if (it != m_scenes.end()) {
            loaded = it->second;
        } else {
            if (m_scenes.size() >= k_kept_scenes) m_scenes.erase(m_scenes.begin());
            loaded = m_scenes[name] = std::make_shared<LoadedScene>();
        }
    }
    const std::scoped_lock turn(loaded->turn);
    if (!loaded->session) {
        SceneSource source;
        if (!path.empty()) source.file = path;
        loaded->session = std::make_unique<Session>(std::move(source));
    }
    return loaded;
}

ServeApi::Running ServeApi::start(const std::string& client) {
    Running running;
    const std::scoped_lock lock(m_mutex);
    if (client.empty()) return running;
    auto [it, fresh] = m_running.try_emplace(client, running);
    if (!fresh) {
        it->second.cancel.cancel();
        it->second = running;
    }
    return running;
}

void ServeApi::finish(const std::string& client, const Running& running) {
    const std::scoped_lock lock(m_mutex);
    auto it = m_running.find(client);
    if (it != m_running.end() && it->second.fraction == running.fraction) m_running.erase(it);
}

std::optional<double> ServeApi::progress(const std::string& client) {
    const std::scoped_lock lock(m_mutex);
    auto it = m_running.find(client);
    if (it == m_running.end()) return std::nullopt;
    return it->second.fraction->load();
}

namespace {

/// What the page shows beside a frame: its time, size, an algorithm picture's reading, and the
/// depth sort's painting order (Fig 4.6) for the step-through: how many polygons (pieces of cut
/// ones included) the order holds, and how many cuts made them.
void frame_headers(const RenderResult& result, const Camera& camera,
                   std::map<std::string, std::string>& headers) {
    headers["X-Hikari-Seconds"] = fmt::format("{:.4f}", result.seconds);
    headers["X-Hikari-Size"] = fmt::format("{}x{}", camera.width, camera.height);
    if (!result.algorithm_summary.empty()) headers["X-Hikari-Summary"] = result.algorithm_summary;
    if (const uint64_t polygons = result.stats->depth_sort_polygons.load(); polygons > 0) {
        headers["X-Hikari-Paint-Order"] = std::to_string(polygons);
        headers["X-Hikari-Splits"] = std::to_string(result.stats->depth_sort_splits.load());
    }
}

}  // namespace

std::string ServeApi::render(const std::string& text, std::string& content_type,
                             std::map<std::string, std::string>& headers) {
    const Json body = request_json(text);
    RenderRequest request = render_request_from_json(body, "request", k_frame_keys);
    const JsonNode root(body, "request", "");
    const std::string format = string_member(body, "format", "png");
    if (format != "png" && format != "pfm" && format != "exr")
        root.at("format").fail("expected png, pfm or exr");
    const float exposure = root.has("exposure") ? root.at("exposure").as_number() : 0.0f;
    if (exposure < -100.0f || exposure > 100.0f) root.at("exposure").fail("expected -100 to 100");
    ToneMap tonemap = ToneMap::clamp;
    if (root.has("tonemap")) {
        const auto op = choice_value<ToneMap>(k_tone_map_choices, root.at("tonemap").as_string());
        if (!op) root.at("tonemap").fail("expected clamp, reinhard or aces");
        tonemap = *op;
    }
    const std::string client = string_member(body, "client", "");
    const bool pfm = format != "png";  // a float file: the values themselves
    // As `hikari render -o frame.png` does: 8-bit sRGB straight from the render when nothing
    // is developed afterwards, so that the frame is byte for byte the command line's file.
    if (!pfm && is_colour_aov(request.aov) && exposure == 0.0f && tonemap == ToneMap::clamp)
        request.film = FilmFormat::srgb8;
    request.algorithm_counts = pfm;

    // The client's older render is cancelled first: it may hold the scene's turn.
    const Running running = start(client);
    std::shared_ptr<LoadedScene> loaded;
    try {
        loaded = scene(string_member(body, "scene", m_default_scene));
    } catch (...) {
        finish(client, running);
        throw;
    }
    request.cancel = running.cancel;
    request.progress = [fraction = running.fraction](const RenderProgress& p) {
        fraction->store(p.fraction);
    };
    RenderResult result;
    try {
        const std::scoped_lock turn(loaded->turn);
        if (running.cancel.cancelled()) throw Superseded();
        result = loaded->session->render(request);
    } catch (const Interrupted&) {
        finish(client, running);
        if (running.cancel.cancelled() && !cancel_requested()) throw Superseded();
        throw;
    } catch (...) {
        finish(client, running);
        throw;
    }
    finish(client, running);
    frame_headers(result, loaded->session->camera_for(request), headers);
    content_type = format == "png"   ? "image/png"
                   : format == "exr" ? "image/x-exr"
                                     : "image/x-portable-floatmap";
    return encode_frame(result, request, loaded->session->scene(), format, exposure, tonemap);
}

std::string ServeApi::explain(const std::string& text) {
    const Json body = request_json(text);
    const RenderRequest request = render_request_from_json(body, "request", k_frame_keys);
    const ExplainStep step = explain_step_from_json(body, "request");
    const std::shared_ptr<LoadedScene> loaded =
        scene(string_member(body, "scene", m_default_scene));
    const std::scoped_lock turn(loaded->turn);
    return loaded->session->explain(request, step);
}

std::string ServeApi::scene_file(const std::string& text) {
    const Json body = request_json(text);
    const RenderRequest request = render_request_from_json(body, "request", k_frame_keys);
    const std::shared_ptr<LoadedScene> loaded =
        scene(string_member(body, "scene", m_default_scene));
    const std::scoped_lock turn(loaded->turn);
    const Session& session = *loaded->session;
    return scene_document(session.source(), session.camera_for(request)).dump(2) + "\n";
}

std::string ServeApi::scene_info(const std::string& name) {
    const std::shared_ptr<LoadedScene> loaded = scene(name);
    const std::scoped_lock turn(loaded->turn);
    const Scene& s = loaded->session->scene();
    const Camera& c = s.camera;
    Json info = {
        {"scene", name},
        {"camera",
         {{"eye", {c.eye.x, c.eye.y, c.eye.z}},
          {"look_at", {c.look_at.x, c.look_at.y, c.look_at.z}},
          {"up", {c.up.x, c.up.y, c.up.z}},
          {"fov_y", c.fov_y_degrees},
          {"projection", c.projection == Projection::perspective ? "perspective" : "orthographic"},
          {"width", c.width},
          {"height", c.height}}},
        {"triangles", s.triangles.size()},
        {"spheres", s.spheres.size()},
        {"planes", s.planes.size()},
        {"lights", s.lights.size()},
        {"warnings", loaded->session->load_warnings()}};
    return info.dump();
}

void ServeApi::route(httplib::Server& server) {
    server.Get("/", [](const httplib::Request&, httplib::Response& res) {
        res.set_content(std::string(k_serve_page), "text/html; charset=utf-8");
    });
    server.Get("/api/methods", [](const httplib::Request&, httplib::Response& res) {
        res.set_content(method_catalog().dump(), "application/json");
    });
    server.Get("/api/scenes", [this](const httplib::Request&, httplib::Response& res) {
        const Json list = {{"default", m_default_scene}, {"scenes", m_files.scene_files()}};
        res.set_content(list.dump(), "application/json");
    });
    server.Get("/api/scene", [this](const httplib::Request& req, httplib::Response& res) {
        answer(res, [&] {
            res.set_content(
                scene_info(req.has_param("scene") ? req.get_param_value("scene") : m_default_scene),
                "application/json");
        });
    });
    server.Post("/api/render", [this](const httplib::Request& req, httplib::Response& res) {
        answer(res, [&] {
            std::string type;
            std::map<std::string, std::string> headers;
            res.body = render(req.body, type, headers);
            res.set_header("Content-Type", type);
            for (const auto& [key, value] : headers) res.set_header(key.c_str(), value);
        });
    });
    server.Post("/api/scene-file", [this](const httplib::Request& req, httplib::Response& res) {
        answer(res, [&] { res.set_content(scene_file(req.body), "application/json"); });
    });
    server.Post("/api/explain", [this](const httplib::Request& req, httplib::Response& res) {
        answer(res, [&] { res.set_content(explain(req.body), "text/plain; charset=utf-8"); });
    });
    // Server-Sent Events: the progress of the client's running render as "data: 0.42" ("data:
    // idle" when none runs), sent when it changes (checked ten times a second), and a comment
    // every 15 s that keeps the connection open: an idle page costs the server no work.
    server.Get("/api/progress", [this](const httplib::Request& req, httplib::Response& res) {
        const std::string client = req.get_param_value("client");
        auto last = std::make_shared<std::pair<std::string, int>>("", 0);
        res.set_chunked_content_provider(
            "text/event-stream", [this, client, last](size_t, httplib::DataSink& sink) {
                if (cancel_requested()) return false;
                const std::optional<double> fraction = progress(client);
                const std::string event =
                    fraction ? fmt::format("data: {:.3f}\n\n", *fraction) : "data: idle\n\n";
                auto& [sent, quiet_ticks] = *last;
                if (event != sent) {
                    if (!sink.write(event.data(), event.size())) return false;
                    sent = event;
                    quiet_ticks = 0;
                } else if (++quiet_ticks == 150) {
                    const std::string_view keep_alive = ": keep-alive\n\n";
                    if (!sink.write(keep_alive.data(), keep_alive.size())) return false;
                    quiet_ticks = 0;
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
                return true;
            });
    });
}

}  // namespace hikari::cli
