#pragma once
// The fixture of the loaders' hostile-input tests (issues 26 and 41): a fresh folder for the
// files a test writes, and the process-wide limits a test lowers (--max-memory,
// --max-input-size) put back after it, so later tests run under the defaults.

#include <gtest/gtest.h>

#include "../io/temp_dir.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/input_limits.h"

namespace hikari::testing {

class LimitsRestored : public ::testing::Test {
  protected:
    void TearDown() override {
        set_memory_limit(m_memory);
        set_max_input_size(0);
    }
    TempDir m_dir;

  private:
    double m_memory = memory_limit();
};

}  // namespace hikari::testing
