// spt-viewer's command line: what it accepts and how it refuses.
#include "viewer_options.hpp"
#include <gtest/gtest.h>

using spt::editor::parse_viewer_arguments;

TEST(ViewerOptions, AcceptsEveryOption) {
    const auto c = parse_viewer_arguments({"scene.json", "--step", "12", "--view", "front", "--overlay",
                                           "contacts,trails,broad,manifold", "--speed", "2.5", "--play", "--size", "640x480"});
    ASSERT_TRUE(c.error.isEmpty()) << c.error.toStdString();
    EXPECT_EQ(c.start.file, "scene.json");
    EXPECT_EQ(c.start.step, 12);
    EXPECT_EQ(c.start.view, spt::render::View::Front);
    EXPECT_TRUE(c.start.overlays.scene.contacts && c.start.overlays.scene.trails && c.start.overlays.scene.broad);
    EXPECT_TRUE(c.start.overlays.scene.manifold);
    EXPECT_FALSE(c.start.overlays.grid) << "an --overlay list replaces the default grid,axes";
    EXPECT_DOUBLE_EQ(c.start.speed, 2.5);
    EXPECT_TRUE(c.start.play);
    EXPECT_EQ(c.view_size, QSize(640, 480));
}

TEST(ViewerOptions, DefaultsWithoutArguments) {
    const auto c = parse_viewer_arguments({});
    EXPECT_TRUE(c.error.isEmpty());
    EXPECT_TRUE(c.start.file.isEmpty());
    EXPECT_TRUE(c.start.overlays.grid && c.start.overlays.axes);
    EXPECT_EQ(c.start.view, spt::render::View::Camera);
}

TEST(ViewerOptions, BadValuesAreRefusedNamingTheOption) {
    const std::pair<QStringList, const char*> cases[] = {
        {{"--step", "-3"}, "--step"},          {{"--step"}, "--step"},
        {{"--view", "quad"}, "--view"},        {{"--overlay", "contacts,sparkles"}, "sparkles"},
        {{"--speed", "nan"}, "--speed"},       {{"--speed", "1e9"}, "--speed"},
        {{"--size", "10x10"}, "--size"},       {{"--size", "axb"}, "--size"},
        {{"--frobnicate"}, "--frobnicate"},    {{"a.json", "b.json"}, "one SCENE.json"},
    };
    for (const auto& [args, needle] : cases) {
        const auto c = parse_viewer_arguments(args);
        EXPECT_TRUE(c.error.contains(needle)) << args.join(' ').toStdString() << " -> " << c.error.toStdString();
    }
}
