#include "hikari/io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

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

/// `.NAME.tmp-<pid>-<n>` beside `target`: same directory, so rename(2) stays on one file system
/// and is atomic; hidden, so a crash leaves no clutter in listings.
std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
    std::string name = ".";  // appended piecewise: GCC 12 warns falsely on "." + string
    name += target.filename().string();
    name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(g_counter.fetch_add(1));
    return target.parent_path() / name;
}

[[noreturn]] void throw_write_error(const std::filesystem::path& target, const char* step,
                                    int error) {
    throw InputError("cannot write " + target.string() + ": " + step + ": " + std::strerror(error));
}

/// write(2) until done, retrying on EINTR and short writes; returns 0 or an errno value.
int write_all(int fd, std::span<const uint8_t> bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
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

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> bytes) {
    const std::string temporary = temporary_path_for(path).string();
    const int slot = register_temporary(temporary);
    Outcome out = fill_temporary(temporary, bytes);
    if (out.error == 0 && std::rename(temporary.c_str(), path.c_str()) != 0) {
        out = {errno, "cannot rename temporary file over it", true};
    }
    if (out.error != 0 && out.created) ::unlink(temporary.c_str());
    unregister_temporary(slot);
    if (out.error != 0) throw_write_error(path, out.step, out.error);
}

void remove_pending_temporary_files() noexcept {
    for (TemporarySlot& slot : g_slots) {
        if (slot.state.load(std::memory_order_acquire) == k_ready) ::unlink(slot.path);
    }
}

}  // namespace hikari
