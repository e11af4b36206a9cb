#include "casteljau/paint/large_buffer.h"

#include <cstdint>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

namespace casteljau {
namespace {

// The VmFlags of the mapping that holds address p (proc(5): /proc/self/smaps),
// or "" when it cannot be read (not Linux).
std::string vm_flags_at(const void* p) {
    std::ifstream smaps("/proc/self/smaps");
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    bool inside = false;
    for (std::string line; std::getline(smaps, line);) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream range(line);
        if (range >> std::hex >> lo >> dash >> hi && dash == '-') inside = lo <= at && at < hi;
        if (inside && line.rfind("VmFlags:", 0) == 0) return line;
    }
    return "";
}

// Whether the kernel gives huge pages to regions that ask (Linux's
// transparent_hugepage/enabled reads "[always]" or "[madvise]").
bool huge_pages_on_request() {
    std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string mode;
    std::getline(f, mode);
    return mode.find("[always]") != std::string::npos ||
           mode.find("[madvise]") != std::string::npos;
}

TEST(LargeBuffer, AFrameSizedBufferIsWholeHugePagesMarkedForTheKernel) {
    const std::size_t bytes = 4 * 1024 * 1024 + 12345; // a 1024 px frame and a bit
    const LargeBytes b = large_bytes(bytes);
    ASSERT_NE(b.get(), nullptr);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(b.get()) % kHugePageBytes, 0u);
    for (std::size_t i = 0; i < bytes; i += 4096) b[i] = static_cast<unsigned char>(i >> 12);
    b[bytes - 1] = 7; // every byte asked for is there
    for (std::size_t i = 0; i < bytes; i += 4096)
        ASSERT_EQ(b[i], static_cast<unsigned char>(i >> 12)) << "byte " << i;
    if (!huge_pages_on_request()) GTEST_SKIP() << "the kernel gives no transparent huge pages";
    // "hg": the range was marked with madvise(MADV_HUGEPAGE) (proc(5)).
    EXPECT_NE(vm_flags_at(b.get()).find(" hg"), std::string::npos) << vm_flags_at(b.get());
}

TEST(LargeBuffer, SmallBuffersAreOrdinaryOnes) {
    for (const std::size_t bytes :
         {std::size_t(0), std::size_t(1), std::size_t(4096), kHugePageBytes - 1}) {
        const LargeBytes b = large_bytes(bytes);
        ASSERT_NE(b.get(), nullptr) << bytes;
        if (bytes > 0) b[bytes - 1] = 1;
    }
}

TEST(LargeBuffer, VectorsGrowShrinkAndCopyThroughTheAllocator) {
    std::vector<std::uint32_t, LargeAllocator<std::uint32_t>> v(1024 * 1024, 5u); // 4 MiB
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % kHugePageBytes, 0u);
    v.push_back(9);
    v.resize(10);
    const auto copy = v;
    ASSERT_EQ(copy.size(), 10u);
    EXPECT_EQ(copy[0], 5u);
    EXPECT_EQ(copy[9], 5u);
}

// A size whose rounding up to whole huge pages would wrap around. (Not a
// merely huge one: the sanitizers report those as errors, before malloc
// can return its null.)
TEST(LargeBuffer, ASizeThatRoundingWouldWrapThrowsBadAlloc) {
    EXPECT_THROW(large_bytes(~std::size_t(0) - 100), std::bad_alloc);
}

} // namespace
} // namespace casteljau
