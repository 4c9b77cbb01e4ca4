// `spt render` where this spt was configured with SPT_BUILD_RENDER=OFF: the command is named in
// every document, so a user who types it learns why it is missing rather than "not expected".
#include "commands.hpp"
#include <iostream>

namespace spt::cli {

Action add_render_left_out(CLI::App& app) {
    CLI::App* c = app.add_subcommand("render", "(not in this build: configured with SPT_BUILD_RENDER=OFF)");
    c->allow_extras();
    return [] {
        std::cerr << "spt render: this spt was built without rendering (SPT_BUILD_RENDER=OFF); "
                     "build it with render/ to draw, see docs/library.md\n";
        return 1;
    };
}

} // namespace spt::cli
