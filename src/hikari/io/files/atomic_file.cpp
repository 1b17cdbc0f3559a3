#include "hikari/io/files/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "hikari/core/cancel.h"
#include "hikari/core/error.h"

namespace hikari {

namespace {

// The registry of in-flight temporaries, readable from a signal handler. A slot is claimed
// (Free -> Filling), its path copied in, then published (Filling -> Ready) BEFORE the file is
// created, so every temporary that exists on disk is visible to the handler. Lock-free atomics
// and unlink(2) are async-signal-safe (POSIX.1-2017, 2.4.3); mutexes and std::string are not.
enum SlotState : int { k_free = 0, k_filling = 1, k_ready = 2 };

constexpr size_t k_slot_count = 32;
constexpr size_t k_path_capacity = 4096;

struct TemporarySlot {
    std::atomic<int> state{k_free};
    char path[k_path_capacity] = {};
};

static_assert(std::atomic<int>::is_always_lock_free);

std::array<TemporarySlot, k_slot_count> g_slots;
std::atomic<unsigned> g_counter{0};

/// Publishes `path` in a free slot; returns the slot index, or -1 when none is free or the path
/// does not fit (the write still works, it just cannot be cleaned up by a signal handler).
int register_temporary(const std::string& path) {
    if (path.size() >= k_path_capacity) return -1;
    for (size_t i = 0; i < k_slot_count; ++i) {
        int expected = k_free;
        if (!g_slots[i].state.compare_exchange_strong(expected, k_filling)) continue;
        std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
        g_slots[i].state.store(k_ready, std::memory_order_release);
        return static_cast<int>(i);
    }
    return -1;
}

void unregister_temporary(int slot) {
    if (slot >= 0) g_slots[static_cast<size_t>(slot)].state.store(k_free);
}

/// The temporary's name beside `target`: same directory, so rename(2) stays on one file system
/// and is atomic; hidden, so a crash leaves no clutter in listings; of fixed length (at most
/// 8 + 16 + 1 + 10 + 1 + 10 + 4 = 50 bytes), so that it fits wherever the target's name fits.
std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
    return target.parent_path() / fmt::format("{}{}-{}.tmp", temporary_prefix_for(target),
                                              ::getpid(), g_counter.fetch_add(1));
}

/// The directory that holds `target`, for listing it.
std::filesystem::path directory_of(const std::filesystem::path& target) {
    return target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
}

/// The writer's pid in a temporary's `name` (`PREFIX<pid>-<n>.tmp`), or 0 when the name is not
/// one of ours.
pid_t writer_of(std::string_view name, std::string_view prefix) {
    if (!name.starts_with(prefix) || !name.ends_with(".tmp")) return 0;
    const std::string_view rest = name.substr(prefix.size());
    pid_t pid = 0;
    const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), pid);
    if (error != std::errc() || end == rest.data() || *end != '-' || pid <= 0) return 0;
    return pid;
}

/// Whether process `pid` no longer exists (kill(2) with signal 0 only checks; EPERM means it
/// runs under another user).
bool has_ended(pid_t pid) { return ::kill(pid, 0) != 0 && errno == ESRCH; }

[[noreturn]] void throw_write_error(const std::filesystem::path& target, const char* step,
                                    int error) {
    throw InputError("cannot write " + target.string() + ": " + step + ": " + std::strerror(error));
}

/// The most bytes one write(2) takes, so that a large file polls for cancellation as it goes.
constexpr size_t k_write_chunk = size_t(16) << 20;

/// write(2) until done, retrying on EINTR and short writes; returns 0 or an errno value, or
/// EINTR after request_cancel().
int write_all(int fd, std::span<const uint8_t> bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        if (cancel_requested()) return EINTR;
        const ssize_t n =
            ::write(fd, bytes.data() + done, std::min(bytes.size() - done, k_write_chunk));
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        done += static_cast<size_t>(n);
    }
    return 0;
}

/// The outcome of one step: `error` is 0 or an errno value, `step` says what failed.
struct Outcome {
    int error = 0;
    const char* step = nullptr;
    bool created = false;  ///< the temporary exists on disk and is ours to remove
};

/// Creates `temporary`, fills it and closes it. No fsync: the rename already keeps readers from
/// a partial file while the system runs, which is what an image writer owes them. Waiting for
/// the disk as well cost B3's process 2-3 ms (median of 25 runs, each after a POV-Ray render
/// had written its own PNG: the fsync commits the file system's journal, with other programs'
/// pending writes in it). POV-Ray does not sync its output either.
Outcome fill_temporary(const std::string& temporary, std::span<const uint8_t> bytes) {
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return {errno, "cannot create temporary file", false};
    Outcome out{write_all(fd, bytes), "write failed", true};
    if (::close(fd) != 0 && out.error == 0) out = {errno, "close failed", true};
    return out;
}

/// Blocks SIGINT, SIGTERM and SIGALRM in this thread for its lifetime: between the last check
/// for cancellation and the rename, a signal handler that exits must not run, or an interrupted
/// run could leave the complete file behind.
class SignalBlock {
  public:
    SignalBlock() {
        sigset_t set;
        sigemptyset(&set);
        sigaddset(&set, SIGINT);
        sigaddset(&set, SIGTERM);
        sigaddset(&set, SIGALRM);
        pthread_sigmask(SIG_BLOCK, &set, &m_old);
    }
    ~SignalBlock() { pthread_sigmask(SIG_SETMASK, &m_old, nullptr); }
    SignalBlock(const SignalBlock&) = delete;
    SignalBlock& operator=(const SignalBlock&) = delete;

  private:
    sigset_t m_old;
};

/// Renames the filled temporary over `path` unless the run was cancelled meanwhile.
Outcome rename_unless_cancelled(const std::string& temporary, const std::filesystem::path& path) {
    const SignalBlock block;
    if (cancel_requested()) return {EINTR, "interrupted", true};
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
        return {errno, "cannot rename temporary file over it", true};
    return {};
}

}  // namespace

std::string temporary_prefix_for(const std::filesystem::path& target) {
    uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a, 64-bit (Fowler, Noll, Vo)
    for (const char c : target.filename().string()) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ull;
    }
    return fmt::format(".hikari-{:016x}-", hash);
}

size_t remove_stale_temporary_files(const std::filesystem::path& target) noexcept {
    try {
        const std::string prefix = temporary_prefix_for(target);
        size_t removed = 0;
        std::error_code ec;
        for (const auto& entry : std::filesystem::directory_iterator(directory_of(target), ec)) {
            const pid_t pid = writer_of(entry.path().filename().string(), prefix);
            if (pid > 0 && has_ended(pid) && ::unlink(entry.path().c_str()) == 0) ++removed;
        }
        return removed;
    } catch (...) {  // a name that cannot be converted, out of memory: leave the rest
        return 0;
    }
}

void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> bytes) {
    remove_stale_temporary_files(path);
    const std::string temporary = temporary_path_for(path).string();
    const int slot = register_temporary(temporary);
    Outcome out = fill_temporary(temporary, bytes);
    if (out.error == 0) out = rename_unless_cancelled(temporary, path);
    if (out.error != 0 && out.created) ::unlink(temporary.c_str());
    unregister_temporary(slot);
    if (cancel_requested() && out.error == EINTR) throw Interrupted();
    if (out.error != 0) throw_write_error(path, out.step, out.error);
}

TemporaryFile::TemporaryFile(const std::filesystem::path& target) {
    remove_stale_temporary_files(target);
    m_path = temporary_path_for(target).string();
    m_slot = register_temporary(m_path);
}

TemporaryFile::~TemporaryFile() {
    ::unlink(m_path.c_str());
    unregister_temporary(m_slot);
}

void remove_pending_temporary_files() noexcept {
    for (TemporarySlot& slot : g_slots) {
        if (slot.state.load(std::memory_order_acquire) == k_ready) ::unlink(slot.path);
    }
}

}  // namespace hikari
