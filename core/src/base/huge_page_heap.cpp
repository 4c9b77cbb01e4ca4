#include "spt/huge_page_heap.hpp"
#include "base/huge_page_heap_rule.hpp"
#include <cstdlib>
#include <cstring>
#include <fstream>
#if defined(__linux__)
#include <unistd.h>
#endif

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SPT_MALLOC_REPLACED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define SPT_MALLOC_REPLACED 1
#endif
#endif

#if defined(__linux__) && defined(__GLIBC__) && !defined(SPT_MALLOC_REPLACED)
#if __GLIBC_PREREQ(2, 35)
#define SPT_HUGE_PAGE_RESTART 1
#endif
#endif

namespace spt {

namespace detail {

std::optional<std::string> huge_page_tunables(const HeapEnvironment& env) {
    constexpr const char* kTunable = "glibc.malloc.hugetlb";
    if (env.opt_out && std::strcmp(env.opt_out, "0") == 0) return std::nullopt;
    // Present: this is the second start, or the user chose; either way, no loop and no override.
    if (env.glibc_tunables && std::strstr(env.glibc_tunables, kTunable)) return std::nullopt;
    // Valgrind's /proc/self/exe is valgrind itself, and its malloc is its own.
    if (env.ld_preload && std::strstr(env.ld_preload, "vgpreload")) return std::nullopt;
    if (!env.kernel_offers_huge_pages || !env.kernel_offers_huge_pages()) return std::nullopt;
    const std::string before = env.glibc_tunables ? env.glibc_tunables : "";
    return (before.empty() ? "" : before + ":") + kTunable + "=1";
}

bool huge_page_restart_built_in() {
#if defined(SPT_HUGE_PAGE_RESTART)
    return true;
#else
    return false;
#endif
}

} // namespace detail

#if defined(SPT_HUGE_PAGE_RESTART)
namespace {

// "[never]", or no file (no THP in this kernel): madvise would be refused.
bool kernel_offers_huge_pages() {
    std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    return std::getline(f, line) && line.find("[never]") == std::string::npos;
}

} // namespace
#endif

void reexec_with_huge_page_heap(char** argv) {
#if defined(SPT_HUGE_PAGE_RESTART)
    if (!argv || !argv[0]) return;
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    const auto with = detail::huge_page_tunables(
        {tunables, std::getenv("SPT_HUGE_PAGE_HEAP"), std::getenv("LD_PRELOAD"), kernel_offers_huge_pages});
    if (!with) return;
    const std::string before = tunables ? tunables : "";
    if (setenv("GLIBC_TUNABLES", with->c_str(), 1) != 0) return;
    execv("/proc/self/exe", argv);
    // Still here: the exec failed (no /proc, the binary replaced on disk); run on as we are.
    if (tunables) setenv("GLIBC_TUNABLES", before.c_str(), 1);
    else unsetenv("GLIBC_TUNABLES");
#else
    (void)argv;
#endif
}

} // namespace spt
