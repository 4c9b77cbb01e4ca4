// spt's programs start once, as they are, however they are started: through the dynamic loader,
// setuid by another user, or under a preloaded library (a debugger's or profiler's view). They
// once re-executed themselves through /proc/self/exe to change glibc's malloc, which ran the
// loader instead of spt, looped forever where glibc drops GLIBC_TUNABLES (secure mode), and
// stopped twice at `break main`.
#include "run_command.hpp"
#include "spt/version.hpp"
#include <gtest/gtest.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <sys/stat.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using spt::test::q;
using spt::test::run_command;
using spt::test::spt_binary;

const std::string kVersionLine = "spt " SPT_VERSION_STRING "\n";

// A hang must end the test, not CI: the failures this file pins never return at all, so the
// limit only has to be far above a start's few milliseconds on a loaded machine.
const std::string kHangLimit = "timeout 30 ";

// The programs this build has; the Qt apps answer --help without a display.
std::vector<std::string> programs() {
    std::vector<std::string> found = {spt_binary() + " --version"};
    for (const char* app : {"/editor/app/spt-editor", "/editor/viewer/spt-viewer"}) {
        const std::string path = std::string(SPT_BINARY_DIR) + app;
        if (fs::exists(path)) found.push_back(path + " --help");
    }
    return found;
}

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::path(SPT_BINARY_DIR) / "test-tmp" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

int count_lines(const fs::path& file) {
    std::ifstream in(file);
    int n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
}

TEST(ProgramStart, ThroughTheDynamicLoaderPrintsSptsVersion) {
    const std::string loader = "/lib64/ld-linux-x86-64.so.2";
    if (!fs::exists(loader)) GTEST_SKIP() << "no " << loader << " on this machine";
    const auto r = run_command(kHangLimit + q(loader) + " " + q(spt_binary()) + " --version");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output, kVersionLine);
}

TEST(ProgramStart, EachProgramStartsOnce) {
    const fs::path dir = fresh_dir("program_start");
    // AddressSanitizer wants its runtime first in the list of libraries; the counter needs none of it.
    // Set by env after timeout, so that only the program loads the counter.
    const std::string env = kHangLimit + "env ASAN_OPTIONS=verify_asan_link_order=0:detect_leaks=0 LD_PRELOAD=" +
                            q(std::string(SPT_BINARY_DIR) + "/tests/cli/libspt_start_counter.so") + " ";
    int k = 0;
    for (const std::string& program : programs()) {
        const fs::path log = dir / ("starts" + std::to_string(k++) + ".log");
        const auto r = run_command(env + "SPT_START_LOG=" + q(log.string()) + " " + program);
        EXPECT_EQ(r.exit_code, 0) << program << ": " << r.output;
        EXPECT_EQ(count_lines(log), 1) << program << " started this many times";
    }
}

TEST(ProgramStart, ASetuidCopyRunByAnotherUserAnswersVersion) {
    if (::geteuid() != 0) GTEST_SKIP() << "needs root to make a setuid copy and to run it as nobody";
    // A setuid process is not dumpable, and LeakSanitizer cannot stop the world in one.
    if (spt::test::kAddressSanitizer) GTEST_SKIP() << "sanitizers do not run setuid";
    // Under /tmp, not the build tree: a clone in root's home is out of nobody's reach.
    std::string name = (fs::temp_directory_path() / "spt-setuid-XXXXXX").string();
    ASSERT_NE(::mkdtemp(name.data()), nullptr);
    const fs::path dir = name;
    const fs::path copy = dir / "spt";
    fs::copy_file(spt_binary(), copy);
    ASSERT_EQ(::chmod(dir.c_str(), 0755), 0);
    ASSERT_EQ(::chmod(copy.c_str(), 04755), 0);
    // nobody must reach the copy: every folder above it must be searchable by others.
    for (fs::path p = dir.parent_path(); p != p.root_path(); p = p.parent_path()) {
        struct stat st {};
        if (::stat(p.c_str(), &st) == 0 && !(st.st_mode & S_IXOTH))
            GTEST_SKIP() << p << " is not searchable by other users";
    }
    const auto r = run_command(kHangLimit + "setpriv --reuid=65534 --regid=65534 --clear-groups " + q(copy.string()) +
                               " --version");
    fs::remove_all(dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output, kVersionLine);
}

} // namespace
