#include "hikari/core/huge_page_allocator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "hikari/core/thread_scratch.h"

namespace hikari {
namespace {

/// Population maps pages and writes nothing: data already there survives, whatever the range's
/// alignment, including ranges that share their first or last page with other data.
TEST(PopulatePages, KeepsTheDataOfEveryPageItTouches) {
    std::vector<uint32_t> data(5 * 4096);
    std::iota(data.begin(), data.end(), 7u);
    const std::vector<uint32_t> expected = data;
    populate_pages(data.data() + 3, 0);
    populate_pages(data.data() + 1, 1);
    populate_pages(data.data() + 1000, 5000 * sizeof(uint32_t));
    populate_pages(data.data(), data.size() * sizeof(uint32_t));
    EXPECT_EQ(data, expected);
}

/// A fresh, never written buffer reads as zeros after population (fresh anonymous pages).
TEST(PopulatePages, FreshPagesReadAsZero) {
    HugePageVector<uint8_t> buffer(size_t{3} << 20);  // huge-page path, zero-initialised
    populate_pages(buffer.data(), buffer.size());
    EXPECT_EQ(std::count(buffer.begin(), buffer.end(), uint8_t{0}),
              static_cast<std::ptrdiff_t>(buffer.size()));
    EXPECT_EQ(reinterpret_cast<uintptr_t>(buffer.data()) % (uintptr_t{2} << 20), 0u);
}

struct FirstTag {};
struct SecondTag {};

/// A thread's scratch buffer is reused for requests that fit, grows for those that do not, and
/// differs per tag.
TEST(ThreadScratch, ReusedPerTagAndGrown) {
    int* const a = thread_scratch<int, FirstTag>(1000);
    a[999] = 42;
    EXPECT_EQ((thread_scratch<int, FirstTag>(10)), a);
    EXPECT_EQ(a[999], 42);
    int* const b = thread_scratch<int, SecondTag>(1000);
    EXPECT_NE(a, b);
    int* const grown = thread_scratch<int, FirstTag>(100000);
    grown[99999] = 1;  // the whole new size is usable
    EXPECT_EQ((thread_scratch<int, FirstTag>(100000)), grown);
}

}  // namespace
}  // namespace hikari
