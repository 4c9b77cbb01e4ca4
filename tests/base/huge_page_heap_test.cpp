// The restart with a huge-page heap: the rule for every environment, then the real exec.
#include "base/huge_page_heap_rule.hpp"
#include "run_command.hpp"
#include <gtest/gtest.h>

using spt::detail::HeapEnvironment;
using spt::detail::huge_page_tunables;

namespace {
bool offers() { return true; }
bool refuses() { return false; }
bool g_kernel_asked = false;
bool offers_and_counts() { g_kernel_asked = true; return true; }
} // namespace

TEST(HugePageHeap, CleanEnvironmentStartsAgainWithTheTunable) {
    EXPECT_EQ(huge_page_tunables({nullptr, nullptr, nullptr, offers}), "glibc.malloc.hugetlb=1");
    EXPECT_EQ(huge_page_tunables({"", nullptr, nullptr, offers}), "glibc.malloc.hugetlb=1");
}

TEST(HugePageHeap, UserTunablesAreKeptAndTheHugePageOneAppended) {
    EXPECT_EQ(huge_page_tunables({"glibc.malloc.arena_max=2", nullptr, nullptr, offers}),
              "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
}

TEST(HugePageHeap, SecondStartOrUserChoiceIsNotOverriddenSoNoLoop) {
    EXPECT_EQ(huge_page_tunables({"glibc.malloc.hugetlb=1", nullptr, nullptr, offers_and_counts}), std::nullopt);
    EXPECT_FALSE(g_kernel_asked) << "the second start read the kernel's setting";
    EXPECT_EQ(huge_page_tunables({"glibc.malloc.hugetlb=0", nullptr, nullptr, offers}), std::nullopt);
    EXPECT_EQ(huge_page_tunables({"glibc.malloc.arena_max=2:glibc.malloc.hugetlb=2", nullptr, nullptr, offers}),
              std::nullopt);
}

TEST(HugePageHeap, OptOutKernelWithoutHugePagesAndValgrindRunAsTheyAre) {
    EXPECT_EQ(huge_page_tunables({nullptr, "0", nullptr, offers}), std::nullopt);
    EXPECT_EQ(huge_page_tunables({nullptr, nullptr, nullptr, refuses}), std::nullopt);
    EXPECT_EQ(huge_page_tunables({nullptr, nullptr, "/usr/libexec/valgrind/vgpreload_core-amd64-linux.so", offers}),
              std::nullopt);
    // Anything but "0" leaves it on; another preload (heaptrack, a profiler) is started again with it.
    EXPECT_EQ(huge_page_tunables({nullptr, "1", "libheaptrack_preload.so", offers}), "glibc.malloc.hugetlb=1");
}

namespace {

std::string probe() { return std::string(SPT_BINARY_DIR) + "/tests/base/huge_page_heap_probe"; }

bool kernel_offers_huge_pages() {
    const auto r = spt::test::run_command("cat /sys/kernel/mm/transparent_hugepage/enabled");
    return r.exit_code == 0 && r.output.find("[never]") == std::string::npos;
}

} // namespace

TEST(HugePageHeap, RealStartKeepsArgumentsAndGainsTheTunableOnce) {
    const bool restarts = spt::detail::huge_page_restart_built_in() && kernel_offers_huge_pages();
    const auto r = spt::test::run_command("env -u GLIBC_TUNABLES -u SPT_HUGE_PAGE_HEAP -u LD_PRELOAD " +
                                          spt::test::q(probe()) + " 'a b' '' --c");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output, std::string(restarts ? "glibc.malloc.hugetlb=1" : "unset") + "\na b\n\n--c\n");

    const auto user = spt::test::run_command("env -u SPT_HUGE_PAGE_HEAP -u LD_PRELOAD "
                                             "GLIBC_TUNABLES=glibc.malloc.arena_max=2 " + spt::test::q(probe()));
    EXPECT_EQ(user.output, std::string(restarts ? "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1"
                                                : "glibc.malloc.arena_max=2") + "\n");

    const auto off = spt::test::run_command("env -u GLIBC_TUNABLES SPT_HUGE_PAGE_HEAP=0 " + spt::test::q(probe()));
    EXPECT_EQ(off.output, "unset\n");
}
