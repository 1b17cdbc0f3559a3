#pragma once
// The HTTP API of `hikari serve` (docs/serve.md): the page, the registry, the scene list, renders
// as PNG or PFM frames, explain text and progress events, each request a render session's call.
// Bad requests are answered 400 with the message the command line would print; paths outside
// --root 403; a render a newer request of the same client replaced 409.

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "hikari/session/session.h"
#include "serve_files.h"

namespace httplib {
class Server;
}

namespace hikari::cli {

/// The scenes the server has loaded and the renders its clients are waiting for.
class ServeApi {
  public:
    /// Serves the files under `root`; `default_scene` (a path under it, or empty for the
    /// lecture's assignment) is what requests without "scene" render.
    ServeApi(const std::filesystem::path& root, std::string default_scene);

    /// Adds every route to `server`.
    void route(httplib::Server& server);

  private:
    /// One loaded scene; renders of it take turns (a session renders one request at a time).
    struct LoadedScene {
        std::mutex turn;
        std::unique_ptr<Session> session;
    };
    /// A client's running render: cancelled when the same client asks for another.
    struct Running {
        CancelToken cancel;
        std::shared_ptr<std::atomic<double>> fraction = std::make_shared<std::atomic<double>>(0.0);
    };

    std::shared_ptr<LoadedScene> scene(const std::string& name);
    /// Registers `client`'s new render, cancelling its previous one.
    Running start(const std::string& client);
    void finish(const std::string& client, const Running& running);
    /// The progress of `client`'s running render (0..1), or nullopt when none runs.
    std::optional<double> progress(const std::string& client);

    std::string render(const std::string& body, std::string& content_type,
                       std::map<std::string, std::string>& headers);
    std::string explain(const std::string& body);
    /// The scene file of the request's scene with its camera (session/scene_document.h).
    std::string scene_file(const std::string& body);
    std::string scene_info(const std::string& name);

    ServedFiles m_files;
    std::string m_default_scene;
    std::mutex m_mutex;  ///< guards the two maps
    std::map<std::string, std::shared_ptr<LoadedScene>> m_scenes;
    std::map<std::string, Running> m_running;
};

}  // namespace hikari::cli
