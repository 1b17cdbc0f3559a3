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
              "a buffer needs about 101.0 MiB, more than the limit of 100.0 MiB (raise it with "
              "--max-memory)");
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
    EXPECT_EQ(refused.rfind("a second buffer needs about 60.0 MiB besides the ", 0), 0u) << refused;
    EXPECT_NE(refused.find("already held, more than the limit of 100.0 MiB"), std::string::npos)
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
    set_memory_limit_hint("--max-memory");
    EXPECT_NE(message.find("(raise it with max_memory=GIB)"), std::string::npos) << message;
}

}  // namespace
}  // namespace hikari
