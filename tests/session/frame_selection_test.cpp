#include "hikari/session/frame_selection.h"

#include <algorithm>

#include <gtest/gtest.h>

namespace {

using namespace hikari;

TEST(FrameSelection, ParsesRangesAndShards) {
    std::string why;
    const auto range = parse_frame_range("3-17", why);
    ASSERT_TRUE(range);
    EXPECT_EQ(range->first, 3);
    EXPECT_EQ(range->last, 17);
    const auto one = parse_frame_range("5", why);
    ASSERT_TRUE(one);
    EXPECT_EQ(one->first, 5);
    EXPECT_EQ(one->last, 5);
    const auto shard = parse_frame_shard("2/5", why);
    ASSERT_TRUE(shard);
    EXPECT_EQ(shard->index, 2);
    EXPECT_EQ(shard->count, 5);
    for (const char* bad : {"", "-", "5-3", "a-b", "1-", "-1", "1-2-3", "1.5-2"})
        EXPECT_FALSE(parse_frame_range(bad, why)) << bad;
    for (const char* bad : {"", "1", "5/5", "1/0", "-1/3", "1/3x", "/3"})
        EXPECT_FALSE(parse_frame_shard(bad, why)) << bad;
}

TEST(FrameSelection, ShardsPartitionTheRange) {
    const FrameRange range{4, 30};
    for (int count = 1; count <= 9; ++count) {
        std::vector<int> all;
        for (int index = 0; index < count; ++index) {
            const std::vector<int> frames = shard_frames(range, {index, count});
            EXPECT_TRUE(std::is_sorted(frames.begin(), frames.end()));
            all.insert(all.end(), frames.begin(), frames.end());
        }
        std::sort(all.begin(), all.end());
        ASSERT_EQ(all.size(), 27u) << count;
        for (int i = 0; i < 27; ++i) EXPECT_EQ(all[i], 4 + i) << count;
    }
    EXPECT_TRUE(shard_frames({0, 1}, {3, 4}).empty());  // more shards than frames
}

}  // namespace
