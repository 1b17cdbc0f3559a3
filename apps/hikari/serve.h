#pragma once
// `hikari serve [SCENE|MODEL] [--port 8080] [--host 127.0.0.1] [--root DIR]`: every method live
// in a browser, on one render session per scene (docs/serve.md).

#include <string>

#include <CLI/CLI.hpp>

namespace hikari::cli {

/// The options of `hikari serve`.
struct ServeOptions {
    std::string scene;  ///< relative to root; empty: the lecture's assignment
    std::string host = "127.0.0.1";
    int port = 8080;
    std::string root = ".";
    double max_memory_gib = 0;  ///< 0: the default limit
    bool quiet = false;
};

/// `hikari serve` and its options.
CLI::App* add_serve_command(CLI::App& app, ServeOptions& s);

/// Serves until SIGINT or SIGTERM; returns the exit status (130 or 143 then). Throws InputError
/// for a scene or root that cannot be served, or an address it cannot listen on.
int run_serve(const ServeOptions& s);

}  // namespace hikari::cli
