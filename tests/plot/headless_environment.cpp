// One offscreen QGuiApplication for every plot test, made as a program without a display would make it.
#include "spt/plot/headless_gui.hpp"
#include <cstdlib>
#include <gtest/gtest.h>
#include <memory>

namespace {

class HeadlessEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        // The worst case a command-line user can hand us: an environment naming the X11 plugin and no X server.
        // HeadlessGui must still come up (on offscreen); if it did not, Qt would abort this whole binary.
        ::setenv("QT_QPA_PLATFORM", "xcb", 1);
        ::unsetenv("DISPLAY");
        ::unsetenv("WAYLAND_DISPLAY");
        gui_ = std::make_unique<spt::plot::HeadlessGui>();
    }
    void TearDown() override { gui_.reset(); }

private:
    std::unique_ptr<spt::plot::HeadlessGui> gui_;
};

[[maybe_unused]] ::testing::Environment* const g_env = ::testing::AddGlobalTestEnvironment(new HeadlessEnvironment);

} // namespace
