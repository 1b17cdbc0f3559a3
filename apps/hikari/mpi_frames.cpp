#include "mpi_frames.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "cli_options.h"
#include "console.h"
#include "hikari/core/error.h"
#include "hikari/frame/tile_exchange.h"
#include "hikari/io/files/printable_text.h"
#include "signals.h"

#if HIKARI_MPI
#include <mpi.h>
#endif

namespace hikari::cli {

bool launched_among_ranks() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
        if (const char* v = std::getenv(name); v && std::atoi(v) > 1) return true;
    return false;
}

int rank_in_environment() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
        if (const char* v = std::getenv(name)) return std::atoi(v);
    return 0;
}

namespace {

#if HIKARI_MPI

/// Message tags: a rank asks for a frame (or says it failed), rank 0 answers with one (−1: no
/// more), a failed rank's message follows its notice.
constexpr int k_tag_ask = 1, k_tag_frame = 2, k_tag_failure = 3;
constexpr int k_ask_frame = 0, k_ask_failed = 1;

/// Rank 0's dispatcher: answers every other rank's asks with the next frame until each has
/// been told there are none left or has failed; collects the failures, one line each.
void hand_out(std::atomic<size_t>& next, const std::vector<int>& frames, int size,
              std::vector<std::string>& failures) {
    for (int active = size - 1; active > 0;) {
        int kind = 0;
        MPI_Status status;
        // Polled with a pause, not MPI_Recv: Open MPI's blocking receive spins, and this
        // thread would take a core from rank 0's own rendering.
        MPI_Request request;
        MPI_Irecv(&kind, 1, MPI_INT, MPI_ANY_SOURCE, k_tag_ask, MPI_COMM_WORLD, &request);
        for (int done = 0; MPI_Test(&request, &done, &status), !done;)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        const int source = status.MPI_SOURCE;
        if (kind == k_ask_failed) {
            MPI_Probe(source, k_tag_failure, MPI_COMM_WORLD, &status);
            int length = 0;
            MPI_Get_count(&status, MPI_CHAR, &length);
            std::string message(static_cast<size_t>(length), '\0');
            MPI_Recv(message.data(), length, MPI_CHAR, source, k_tag_failure, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE);
            failures.push_back(fmt::format("rank {} failed: {}", source, message));
            --active;
            continue;
        }
        const size_t i = next++;
        int frame = i < frames.size() ? frames[i] : -1;
        MPI_Send(&frame, 1, MPI_INT, source, k_tag_frame, MPI_COMM_WORLD);
        if (frame < 0) --active;
    }
}

/// A rank other than 0: asks for frames and renders them until none are left; a failure is
/// sent to rank 0, which reports it.
void ask_for_frames(const std::function<void(int)>& render) {
    try {
        for (;;) {
            int ask = k_ask_frame, frame = -1;
            MPI_Send(&ask, 1, MPI_INT, 0, k_tag_ask, MPI_COMM_WORLD);
            MPI_Recv(&frame, 1, MPI_INT, 0, k_tag_frame, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (frame < 0) return;
            render(frame);
        }
    } catch (const std::exception& e) {
        int failed = k_ask_failed;
        const std::string message = e.what();
        MPI_Send(&failed, 1, MPI_INT, 0, k_tag_ask, MPI_COMM_WORLD);
        MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, k_tag_failure,
                 MPI_COMM_WORLD);
    }
}

/// Rank 0: renders frames from the same counter as its dispatcher hands them out, then reports
/// every rank's failure.
void render_and_hand_out(const std::vector<int>& frames, int size,
                         const std::function<void(int)>& render) {
    std::atomic<size_t> next{0};
    std::vector<std::string> failures;
    std::thread dispatcher([&] { hand_out(next, frames, size, failures); });
    std::exception_ptr own;
    try {
        for (size_t i = next++; i < frames.size(); i = next++) render(frames[i]);
    } catch (...) {
        own = std::current_exception();
    }
    dispatcher.join();
    if (failures.empty() && own) std::rethrow_exception(own);
    if (own) {
        try {
            std::rethrow_exception(own);
        } catch (const std::exception& e) {
            failures.insert(failures.begin(), fmt::format("rank 0 failed: {}", e.what()));
        }
    }
    if (failures.empty()) return;
    std::string lines;
    for (const std::string& f : failures) lines += fmt::format("\n  {}", f);
    throw InputError(fmt::format(
        "{} of {} MPI ranks failed (the frames the others wrote stay; rerun to resume):{}",
        failures.size(), size, lines));
}

/// Bytes per MPI message: MPI counts are ints, and a 16K float image with AOVs is larger.
constexpr size_t k_message_bytes = size_t{1} << 30;
/// A shared image's tiles: their size, then the bytes (tags after the frames' above).
constexpr int k_tag_tile_bytes = 4, k_tag_tiles = 5;

void send_bytes(const std::vector<std::byte>& bytes, int to) {
    const unsigned long long size = bytes.size();
    MPI_Send(&size, 1, MPI_UNSIGNED_LONG_LONG, to, k_tag_tile_bytes, MPI_COMM_WORLD);
    for (size_t at = 0; at < bytes.size(); at += k_message_bytes)
        MPI_Send(bytes.data() + at, static_cast<int>(std::min(k_message_bytes, bytes.size() - at)),
                 MPI_BYTE, to, k_tag_tiles, MPI_COMM_WORLD);
}

std::vector<std::byte> receive_bytes(int from) {
    unsigned long long size = 0;
    MPI_Recv(&size, 1, MPI_UNSIGNED_LONG_LONG, from, k_tag_tile_bytes, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    std::vector<std::byte> bytes(size);
    for (size_t at = 0; at < bytes.size(); at += k_message_bytes)
        MPI_Recv(bytes.data() + at, static_cast<int>(std::min(k_message_bytes, bytes.size() - at)),
                 MPI_BYTE, from, k_tag_tiles, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return bytes;
}

#endif

}  // namespace

MpiJob::MpiJob() {
#if HIKARI_MPI
    if (!launched_among_ranks()) return;
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided);
    m_started = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &m_size);
    // Rank 0's dispatcher thread calls MPI while its main thread renders.
    if (provided < MPI_THREAD_SERIALIZED)
        throw InputError(
            "this MPI library cannot be called from a second thread "
            "(MPI_THREAD_SERIALIZED), which rank 0's frame dispatcher needs");
#else
    if (launched_among_ranks())
        throw UsageError(
            "this hikari was built without MPI, so its ranks would each render every frame: "
            "install libopenmpi-dev and rebuild (HIKARI_MPI), or use --shard I/N");
#endif
}

MpiJob::~MpiJob() {
#if HIKARI_MPI
    if (m_started) MPI_Finalize();
#endif
}

void MpiJob::share(const std::vector<int>& frames, const std::function<void(int)>& render) const {
#if HIKARI_MPI
    if (m_size > 1) {
        // Each rank waits for the others at the end, so no rank's asks for the next method's
        // frames reach rank 0's dispatcher of this one.
        if (m_rank != 0) {
            ask_for_frames(render);
            MPI_Barrier(MPI_COMM_WORLD);
            return;
        }
        std::exception_ptr failure;
        try {
            render_and_hand_out(frames, m_size, render);
        } catch (...) {
            failure = std::current_exception();
        }
        MPI_Barrier(MPI_COMM_WORLD);
        if (failure) std::rethrow_exception(failure);
        return;
    }
#endif
    for (const int frame : frames) render(frame);
}

void MpiJob::gather_tiles([[maybe_unused]] Framebuffer& fb) const {
#if HIKARI_MPI
    if (m_size < 2) return;
    if (m_rank != 0) return send_bytes(pack_tiles(fb, m_rank, m_size), 0);
    // One rank's tiles at a time: rank 0 holds one rank's bytes besides the image.
    for (int rank = 1; rank < m_size; ++rank) unpack_tiles(fb, receive_bytes(rank), rank, m_size);
#endif
}

void MpiJob::sum_over_ranks([[maybe_unused]] std::span<int64_t> sums) const {
#if HIKARI_MPI
    if (m_size < 2) return;
    constexpr size_t k_per_message = k_message_bytes / sizeof(int64_t);
    for (size_t at = 0; at < sums.size(); at += k_per_message)
        MPI_Allreduce(MPI_IN_PLACE, sums.data() + at,
                      static_cast<int>(std::min(k_per_message, sums.size() - at)), MPI_INT64_T,
                      MPI_SUM, MPI_COMM_WORLD);
#endif
}

void MpiJob::abort(const std::exception& error) const {
    const bool usage = dynamic_cast<const UsageError*>(&error) != nullptr;
    print_err("hikari: error: rank {} of {}: {}\n", m_rank, m_size, printable_text(error.what()));
#if HIKARI_MPI
    if (m_started) MPI_Abort(MPI_COMM_WORLD, usage ? k_exit_usage_error : k_exit_input_error);
#endif
    std::_Exit(usage ? k_exit_usage_error : k_exit_input_error);
}

long long MpiJob::total(long long count) const {
#if HIKARI_MPI
    if (m_size > 1) {
        long long sum = 0;
        MPI_Reduce(&count, &sum, 1, MPI_LONG_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
        return sum;
    }
#endif
    return count;
}

}  // namespace hikari::cli
