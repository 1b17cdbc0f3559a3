#pragma once
// Which frames of an animation one process renders: a range of frame numbers (`--frames A-B`),
// shared among the jobs of an array (`--shard I/N`, one job per shard, as Slurm's job arrays and
// Blender's render farms split an animation), so that the shards together render every frame of
// the range exactly once.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hikari {

/// Frames `first` to `last`, both included, numbered from 0.
struct FrameRange {
    int first = 0;
    int last = 0;
};

/// Shard `index` of `count` (0 ≤ index < count): the frames at positions index, index + count,
/// index + 2·count, ... of a range.
struct FrameShard {
    int index = 0;
    int count = 1;
};

/// `A-B` (or `A` alone: one frame) parsed; nullopt with `why` when it is not two whole numbers
/// from 0 with A ≤ B.
std::optional<FrameRange> parse_frame_range(std::string_view text, std::string& why);

/// `I/N` parsed; nullopt with `why` unless 0 ≤ I < N.
std::optional<FrameShard> parse_frame_shard(std::string_view text, std::string& why);

/// The frames of `range` that `shard` renders, in increasing order.
std::vector<int> shard_frames(FrameRange range, FrameShard shard);

}  // namespace hikari
