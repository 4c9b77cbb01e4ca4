// In a build without render/ (SPT_BUILD_RENDER=OFF), `spt render` says why it is missing.
#include "run_command.hpp"
#include <gtest/gtest.h>

#ifdef SPT_RENDER_LEFT_OUT
TEST(RenderLeftOut, RenderSaysItWasLeftOutAndExitsOne) {
    const auto r = spt::test::run_command(spt::test::spt_binary() + " render mesh.obj -o out.png --size 64x64");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("SPT_BUILD_RENDER=OFF"), std::string::npos) << r.output;
}
#endif
