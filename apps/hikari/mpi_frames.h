#pragma once
// An animation's frames shared among the ranks of an MPI job (`mpirun -np N hikari render ...
// --frames A-B`; docs/distributed.md). Rank 0 hands the frames out one at a time to whichever
// rank asks next, itself included (a thread of its own answers the others), so a slow frame
// holds up one rank, not the rest: the master–worker scheme of render farms. Each rank renders
// its frames on its own session and writes them itself. One image (a still) is shared by tiles
// instead (frame/tile_share.h): every rank renders its tiles and rank 0 gathers them and writes
// the file. Without HIKARI_MPI, or run without mpirun, one process renders everything.

#include <cstdint>
#include <exception>
#include <functional>
#include <span>
#include <vector>

#include "hikari/frame/framebuffer.h"

namespace hikari::cli {

/// Whether mpirun (Open MPI's, or a PMI launcher's such as Slurm's srun) started this process
/// among more than one rank.
bool launched_among_ranks();

/// This process's rank as its launcher set it in the environment (0 without one), known before
/// MPI starts: a command-line mistake, which every rank meets alike, is said by rank 0 alone.
int rank_in_environment();

/// MPI for as long as it lives, when this process was started by mpirun among more than one
/// rank (and hikari was built with HIKARI_MPI); nothing otherwise.
class MpiJob {
  public:
    MpiJob();
    ~MpiJob();
    MpiJob(const MpiJob&) = delete;
    MpiJob& operator=(const MpiJob&) = delete;

    int rank() const { return m_rank; }
    int size() const { return m_size; }

    /// Renders `frames` among the ranks: `render(frame)` on whichever rank gets it, each frame
    /// once. Every rank calls it with the same frames. On rank 0, throws when any rank failed,
    /// naming the ranks and what they said; the frames the others finished stay written.
    void share(const std::vector<int>& frames, const std::function<void(int)>& render) const;
    /// `count` summed over the ranks, on rank 0 (every rank calls it).
    long long total(long long count) const;
    /// Every rank calls it with its framebuffer of one shared image, its own tiles rendered;
    /// rank 0's then holds every rank's tiles (frame/tile_exchange.h).
    void gather_tiles(Framebuffer& fb) const;
    /// Every rank calls it with its sums; each then holds the sums over all ranks.
    void sum_over_ranks(std::span<int64_t> sums) const;
    /// Prints `error` naming this rank and ends every rank of the job (MPI_Abort) with the exit
    /// status the error has alone: a rank cannot leave the others waiting for its tiles.
    [[noreturn]] void abort(const std::exception& error) const;

  private:
    bool m_started = false;
    int m_rank = 0, m_size = 1;
};

}  // namespace hikari::cli
