// The hikari command line: `hikari render [SCENE] [options]`, `hikari bench B1|B2 --mesh FILE`,
// `hikari bench B5`, `hikari gallery`, `hikari compare A B`, `hikari explain SCENE -m METHOD`,
// `hikari info FILE`, `hikari serve [SCENE]`. Each subcommand lives in its own file (render.cpp,
// bench.cpp, gallery.cpp, compare.cpp, explain.cpp, info.cpp, serve.cpp); this one only wires them:
// it parses, runs the one asked for, and turns what goes wrong into one line on stderr and an exit
// status (signals.h).

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "bench.h"
#include "cli_options.h"
#include "compare.h"
#include "console.h"
#include "explain.h"
#include "gallery_command.h"
#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/version.h"
#include "info.h"
#include "mpi_frames.h"
#include "render.h"
#include "render_command.h"
#include "serve.h"
#include "signals.h"

namespace {

using namespace hikari;
using namespace hikari::cli;

/// Every subcommand's options, as the parser fills them.
struct CommandLine {
    RenderOptions render;
    BenchOptions bench;
    GalleryOptions gallery;
    CompareOptions compare;
    ExplainOptions explain;
    std::string info_file;
    bool info_devices = false;
    ServeOptions serve;
};

/// A subcommand: its parser, its usage checks once parsed (none: empty), and what runs it.
struct Subcommand {
    const CLI::App* app;
    std::function<void()> check;
    std::function<int()> run;
};

/// Ends the process once a render's work is done: the streams are flushed, then the system
/// takes back the memory and TBB's worker threads at once (running every destructor first,
/// TBB's joining its workers among them, costs milliseconds and changes nothing).
[[noreturn]] void exit_after_render(int code) {
    std::fflush(nullptr);
    std::_Exit(code);
}

/// Keeps freed memory in the process for reuse instead of handing it back to the system: a
/// loader's or a tracer's growing arrays then refill pages that are already mapped, where each
/// fresh page costs a fault (some 13 us on a virtual machine). Big blocks come from the heap up
/// to glibc's limit for the mmap threshold (32 MiB); bigger ones, and the arrays of
/// core/huge_page_allocator.h, are mapped as before. The OBJ loader's reserve_heap relies on
/// both settings.
void keep_freed_memory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

/// This program's own path, to run `hikari render` for each figure.
std::string own_program(const char* argv0) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string(argv0) : self.string();
}

/// The subcommands in --help's order, their options bound to `c`.
std::vector<Subcommand> add_subcommands(CLI::App& app, CommandLine& c, std::string program) {
    const CLI::App* render = add_render_command(app, c.render);
    return {
        {render, [render, &c] { check_render_command(*render, c.render); },
         [&c]() -> int { exit_after_render(finish_standard_output(run_render(c.render))); }},
        {add_bench_command(app, c.bench), [&c] { check_bench_command(c.bench); },
         [&c] { return run_bench_command(c.bench); }},
        {add_gallery_command(app, c.gallery),
         {},
         [&c, program] { return run_gallery(c.gallery, program); }},
        {add_compare_command(app, c.compare), {}, [&c] { return run_compare(c.compare); }},
        {add_explain_command(app, c.explain), {}, [&c] { return run_explain(c.explain); }},
        {add_info_command(app, c.info_file, c.info_devices),
         {},
         [&c] { return run_info(c.info_file, c.info_devices); }},
        {add_serve_command(app, c.serve), {}, [&c] { return run_serve(c.serve); }},
    };
}

/// Parses the command line and checks the parsed subcommand's options; returns the exit status
/// when the program ends there: after --help or --version, or on a usage error.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv,
                                      std::span<const Subcommand> subcommands) {
    try {
        app.parse(argc, argv);
        for (const Subcommand& s : subcommands)
            if (s.app->parsed() && s.check) s.check();
        return std::nullopt;
    } catch (const CLI::CallForHelp& e) {
        return finish_standard_output(app.exit(e));
    } catch (const CLI::CallForAllHelp& e) {
        return finish_standard_output(app.exit(e));
    } catch (const CLI::CallForVersion& e) {
        return finish_standard_output(app.exit(e));
    } catch (const CLI::ParseError& e) {
        // Under mpirun every rank parses the same command line: the first says what is wrong.
        // (Errors that can differ between machines, a missing folder, are said by every rank.)
        if (rank_in_environment() != 0) return k_exit_usage_error;
        print_err("hikari: error: {}\nRun `hikari --help` for usage.\n", printable_text(e.what()));
        return k_exit_usage_error;
    }
}

/// Runs the parsed subcommand; an error becomes one line on stderr and an exit status.
int run_command(std::span<const Subcommand> subcommands) {
    try {
        for (const Subcommand& s : subcommands)
            if (s.app->parsed()) return finish_standard_output(s.run());
    } catch (const UsageError& e) {
        // Escaped here once more, so no message, whatever it quotes, writes control characters.
        print_err("hikari: error: {}\n", printable_text(e.what()));
        return k_exit_usage_error;
    } catch (const std::exception& e) {
        // After SIGINT / SIGTERM, whatever unwound the stage (Interrupted, or a read cut short
        // by the signal) is the interruption, not an error of the input.
        if (cancel_requested() || dynamic_cast<const Interrupted*>(&e)) {
            report_interrupted();
            return interrupted_status();
        }
        const bool out_of_memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
        print_err("hikari: error: {}\n",
                  out_of_memory ? "out of memory" : printable_text(e.what()));
        return k_exit_input_error;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    reserve_standard_streams();
    install_signal_handlers();
    keep_freed_memory();
    CLI::App app{"hikari: every classic rendering method of the lecture, in one renderer.",
                 "hikari"};
    app.set_version_flag("--version", fmt::format("hikari {}", k_version));
    app.require_subcommand(1);
    app.footer("Run `hikari render --help` for the render options.");
    CommandLine c;
    const std::vector<Subcommand> subcommands = add_subcommands(app, c, own_program(argv[0]));
    if (const std::optional<int> status = parse_command_line(app, argc, argv, subcommands))
        return *status;
    return run_command(subcommands);
}
