#include "serve.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include <fmt/format.h>
#include <httplib.h>

#include "cli_options.h"
#include "console.h"
#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "serve_api.h"
#include "signals.h"

namespace hikari::cli {

namespace {

/// Threads answering requests: enough for a class of clients each holding a progress stream
/// open beside its render requests.
constexpr size_t k_request_threads = 64;
/// The largest request body: a render request is a few hundred bytes.
constexpr size_t k_max_request_bytes = 1 << 20;

bool is_loopback(const std::string& host) {
    return host == "127.0.0.1" || host == "localhost" || host == "::1";
}

}  // namespace

CLI::App* add_serve_command(CLI::App& app, ServeOptions& s) {
    CLI::App* serve = app.add_subcommand(
        "serve",
        "Serve a page that renders the scene live in a browser: orbit the camera, switch "
        "methods and buffers, compare two methods, click a pixel to see the algorithm at work "
        "(docs/serve.md).");
    serve->add_option("scene", s.scene,
                      "Scene or model file under --root shown first (default: the lecture's "
                      "assignment)");
    serve->add_option("--port", s.port, "TCP port to listen on (0: any free port)")
        ->check(whole_in(0, 65535))
        ->capture_default_str();
    serve
        ->add_option("--host", s.host,
                     "Address to listen on; anything but loopback lets other machines use it")
        ->capture_default_str();
    serve
        ->add_option("--root", s.root,
                     "Folder whose scene and model files the page may open (nothing outside it)")
        ->capture_default_str();
    serve
        ->add_option("--max-memory", s.max_memory_gib,
                     "Refuse renders whose buffers need more than this many GiB (default: half "
                     "the machine's memory)")
        ->check(real_in(k_least_positive, k_max_real, "a positive number of GiB"));
    serve->add_flag("-q,--quiet", s.quiet, "Print nothing but errors");
    return serve;
}

int run_serve(const ServeOptions& s) {
    if (s.max_memory_gib > 0) set_memory_limit(s.max_memory_gib * (1 << 30));
    std::string scene = s.scene;
    // A scene named from the current folder, as `hikari render` takes it, is found under root.
    if (!scene.empty() && std::filesystem::exists(scene)) {
        std::error_code ec;
        const auto relative = std::filesystem::relative(std::filesystem::canonical(scene, ec),
                                                        std::filesystem::canonical(s.root, ec), ec);
        if (!ec && !relative.empty()) scene = relative.generic_string();
    }
    ServeApi api(s.root, scene);
    httplib::Server server;
    server.new_task_queue = [] { return new httplib::ThreadPool(k_request_threads); };
    server.set_payload_max_length(k_max_request_bytes);
    api.route(server);
    const int port = s.port == 0 ? server.bind_to_any_port(s.host)
                                 : (server.bind_to_port(s.host, s.port) ? s.port : -1);
    if (port < 0)
        throw InputError(
            fmt::format("cannot listen on {}:{} (in use, or not an address here)", s.host, s.port));
    if (!is_loopback(s.host))
        print_err(
            "hikari: warning: listening on {}: anyone who can reach this machine on that "
            "network can use the server\n",
            s.host);
    const std::string shown_host = s.host.find(':') != std::string::npos ? "[" + s.host + "]"
                                   : s.host == "0.0.0.0"                 ? "127.0.0.1"
                                                                         : s.host;
    if (!s.quiet) print_out("hikari serve: open http://{}:{}/ (Ctrl-C stops)\n", shown_host, port);
    std::fflush(stdout);  // a script waiting for the address reads it now
    // SIGINT / SIGTERM set the cancel flag (signals.h); this thread turns it into a stop.
    std::jthread watcher([&server](std::stop_token stop) {
        while (!stop.stop_requested() && !cancel_requested())
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        server.stop();
    });
    server.listen_after_bind();
    watcher.request_stop();
    if (cancel_requested()) {
        report_interrupted();
        return interrupted_status();
    }
    return 0;
}

}  // namespace hikari::cli
