// The memory limit (issue 41): what a load or render already holds counts with every need it
// checks, so buffers that each fit are refused when together they would not.

#include "hikari/core/memory_budget.h"

#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/input_error.h"

namespace hikari {
namespace {

using testing::input_error_of;

constexpr double k_mib = double(1 << 20);
constexpr double k_gib = double(1 << 30);

/// Sets the limit for one test and puts the one before back.
class MemoryLimit : public ::testing::Test {
  protected:
    void TearDown() override { set_memory_limit(m_saved); }

  private:
    double m_saved = memory_limit();
};

TEST_F(MemoryLimit, ANeedAloneIsCheckedAgainstTheLimit) {
    set_memory_limit(100 * k_mib);
    EXPECT_EQ(input_error_of([] { check_memory_need(60 * k_mib, "a buffer"); }), "");
    EXPECT_EQ(input_error_of([] { check_memory_need(90 * k_mib + 1, "a buffer"); }), "");
    EXPECT_EQ(input_error_of([] { check_memory_need(101 * k_mib, "a buffer"); }),
              "a buffer needs about 101 MiB, more than the limit of 100 MiB (raise it with "
              "--max-memory 0.099 or more)");
}

TEST_F(MemoryLimit, WhatAScopeHasGrownCountsWithTheNextNeed) {
    set_memory_limit(100 * k_mib);
    std::string refused;
    {
        const MemoryScope scope;
        std::vector<char> first(64 << 20);
        std::memset(first.data(), 1, first.size());  // resident, not only reserved
        EXPECT_GE(MemoryScope::grown_bytes(), 60 * k_mib);
        refused = input_error_of([] { check_memory_need(60 * k_mib, "a second buffer"); });
        EXPECT_EQ(first[first.size() / 2], 1);
    }
    EXPECT_EQ(refused.rfind("a second buffer needs about 60 MiB besides the ", 0), 0u) << refused;
    EXPECT_NE(refused.find("already held, more than the limit of 100 MiB"), std::string::npos)
        << refused;
    // Outside any scope the same need fits again.
    EXPECT_EQ(MemoryScope::grown_bytes(), 0.0);
    EXPECT_EQ(input_error_of([] { check_memory_need(60 * k_mib, "a second buffer"); }), "");
}

TEST_F(MemoryLimit, HeldBytesCountUntilReleased) {
    set_memory_limit(100 * k_mib);
    {
        const MemoryHeld scene(50 * k_mib);
        EXPECT_NE(input_error_of([] { check_memory_need(60 * k_mib, "an image"); }), "");
    }
    EXPECT_EQ(input_error_of([] { check_memory_need(60 * k_mib, "an image"); }), "");
}

TEST_F(MemoryLimit, TheHintSaysHowToRaiseIt) {
    set_memory_limit(k_mib);
    set_memory_limit_hint("max_memory=GIB");
    const std::string message = input_error_of([] { check_memory_need(2 * k_mib, "x"); });
    set_memory_limit_hint("--max-memory GIB");
    EXPECT_NE(message.find("(raise it with max_memory=0.002 or more)"), std::string::npos)
        << message;
}

TEST_F(MemoryLimit, TheLimitReadsAsGivenAndTheNeedIsNeverRoundedDown) {
    // --max-memory 0.25 once read "0.2 GiB", and a need of 0.24 GiB beside it "0.2 GiB" too.
    set_memory_limit(0.25 * k_gib);
    EXPECT_EQ(input_error_of([] { check_memory_need(0.2501 * k_gib, "x"); }),
              "x needs about 0.251 GiB, more than the limit of 0.25 GiB (raise it with "
              "--max-memory 0.26 or more)");
    set_memory_limit(1.75 * k_gib);
    EXPECT_EQ(input_error_of([] { check_memory_need(3.0001 * k_gib, "x"); }),
              "x needs about 3.01 GiB, more than the limit of 1.75 GiB (raise it with "
              "--max-memory 3.1 or more)");
}

TEST(MemorySizeText, RoundsUpToThreeDigits) {
    EXPECT_EQ(memory_size_text(12.0 * (1 << 20)), "12 MiB");
    EXPECT_EQ(memory_size_text(12.01 * (1 << 20)), "12.1 MiB");
    EXPECT_EQ(memory_size_text(0.2 * (1 << 30) + 1), "0.201 GiB");
    EXPECT_EQ(memory_size_text(7.0 * (1 << 30)), "7 GiB");
}

}  // namespace
}  // namespace hikari
