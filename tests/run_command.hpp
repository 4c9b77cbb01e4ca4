#pragma once
// Runs a shell command for command-line tests: exit code, whether it crashed, output.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace spt::test {

/// Whether this build (and so the binaries the tests run) has AddressSanitizer: GCC defines
/// __SANITIZE_ADDRESS__, clang answers __has_feature.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

struct CommandResult {
    int exit_code = -1;  ///< exit status, or -1 if the process died from a signal
    bool crashed = false;
    std::string output;  ///< stdout and stderr together
};

/// Runs `command` through /bin/sh with stderr merged into stdout.
inline CommandResult run_command(const std::string& command) {
    CommandResult r;
    std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    const int status = ::pclose(pipe);
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    // The shell reports a child killed by a signal as 128 + signal.
    r.crashed = WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) > 128);
    return r;
}

/// Path of the spt binary in the build tree.
inline std::string spt_binary() { return std::string(SPT_BINARY_DIR) + "/cli/spt"; }

/// Quotes a path for the shell.
inline std::string q(const std::string& s) { return "'" + s + "'"; }

} // namespace spt::test
