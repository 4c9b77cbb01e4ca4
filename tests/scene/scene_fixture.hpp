#pragma once
// Scenes for tests: small meshes written to a temporary folder and scene JSON beside them.
#include "meshgen.hpp"
#include "spt/error.hpp"
#include "spt/scene.hpp"
#include <gtest/gtest.h>
#include "test_support.hpp"
#include <fstream>
#include <string>

namespace spt::test {

/// A folder holding box.obj (unit cube), ball.obj (sphere of radius 0.5), plate.obj
/// (4 x 4 x 0.02 slab), ball.spt (ball.obj sampled at its vertices only: a cheap model for
/// scenes of many objects) and the scenes written into it.
class SceneDir {
public:
    SceneDir() : dir_("scene") {
        meshgen::write_obj(meshgen::box(1, 1, 1, 2), dir_.file("box.obj"));
        meshgen::write_obj(meshgen::icosphere(0.5, 2), dir_.file("ball.obj"));
        meshgen::write_obj(meshgen::box(4, 0.02, 4, 8), dir_.file("plate.obj"));
        ConvertOptions vertices_only;
        vertices_only.auto_tolerance = false;
        save_spt(make_document(meshgen::prepare(meshgen::icosphere(0.5, 2), "ball").mesh, vertices_only),
                 dir_.file("ball.spt"));
    }
    /// Writes `json` as NAME and returns its path.
    std::string write(const std::string& name, const std::string& json) const {
        std::ofstream(dir_.file(name)) << json;
        return dir_.file(name);
    }
    std::string file(const std::string& name) const { return dir_.file(name); }

private:
    TempDir dir_;
};

/// The message of the Error(BadInput) that parsing scene `text` (as "bad.json") throws; empty if it parses.
inline std::string parse_refusal(const std::string& text) {
    try {
        parse_scene(text, "bad.json", ".");
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        return e.what();
    }
    return {};
}

} // namespace spt::test
