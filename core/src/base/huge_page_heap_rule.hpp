#pragma once
// The decision behind spt::reexec_with_huge_page_heap, apart from the exec, so that tests can
// pin it for every environment.
#include <optional>
#include <string>

namespace spt::detail {

/// What the environment says; a null pointer is an unset variable.
struct HeapEnvironment {
    const char* glibc_tunables = nullptr; ///< GLIBC_TUNABLES
    const char* opt_out = nullptr;        ///< SPT_HUGE_PAGE_HEAP ("0" turns the restart off)
    const char* ld_preload = nullptr;     ///< LD_PRELOAD
    /// Whether transparent huge pages are not "[never]"; asked last, so that a second start, which
    /// the tunable already tells apart, reads no file.
    bool (*kernel_offers_huge_pages)() = nullptr;
};

/// The GLIBC_TUNABLES value to start again with (the user's settings kept, the huge-page one
/// appended), or nothing where the program should run on as it is.
std::optional<std::string> huge_page_tunables(const HeapEnvironment& env);

/// Whether this build can restart at all: Linux, glibc 2.35 or later, malloc not replaced by a
/// sanitizer.
bool huge_page_restart_built_in();

} // namespace spt::detail
