// adviseHugePages marks large arrays for transparent huge pages before their first write, and
// reserveInHugePages makes a vector ready without changing what it holds.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/huge_pages.h"

namespace prism {
namespace {

// The VmFlags of the mapping of /proc/self/smaps that holds `address` ("" when not found).
std::string vmFlagsAt(const void *address) {
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    auto a = reinterpret_cast<uintptr_t>(address);
    while (std::getline(smaps, line)) {
        unsigned long begin = 0, end = 0;
        bool header = !line.empty() && !std::isupper(static_cast<unsigned char>(line[0]));
        if (header && std::sscanf(line.c_str(), "%lx-%lx ", &begin, &end) == 2) {
            inside = a >= begin && a < end;
        } else if (inside && line.rfind("VmFlags:", 0) == 0) {
            return line;
        }
    }
    return "";
}

TEST(HugePages, LargeVectorIsMarkedBeforeItsFirstWrite) {
    if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled"))
        GTEST_SKIP() << "this kernel has no transparent huge pages: nothing to advise";
    std::vector<uint64_t> v;
    reserveInHugePages(v, size_t(32) << 20 >> 3); // 32 MiB
    ASSERT_GE(v.capacity(), size_t(32) << 20 >> 3);
    // The middle of the array lies in a whole 2 MiB page of the advised range.
    const void *middle = v.data() + v.capacity() / 2;
    std::string flags = vmFlagsAt(middle);
    ASSERT_FALSE(flags.empty()) << "no mapping of /proc/self/smaps holds the array";
    EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
}

TEST(HugePages, SmallOrEmptyRangesAreLeftAlone) {
    adviseHugePages(nullptr, size_t(1) << 30);
    std::vector<char> small(4096);
    adviseHugePages(small.data(), small.size());
    EXPECT_EQ(vmFlagsAt(small.data()).find(" hg"), std::string::npos);
}

TEST(HugePages, ReserveKeepsNothingAndAnEmptyVectorStaysUsable) {
    std::vector<int> v;
    reserveInHugePages(v, 10'000'000);
    EXPECT_TRUE(v.empty());
    for (int i = 0; i < 1000; ++i)
        v.push_back(i);
    EXPECT_EQ(v[999], 999);
}

} // namespace
} // namespace prism
