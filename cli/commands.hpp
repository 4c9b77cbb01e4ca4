#pragma once
// Subcommands of `spt`. Each registers its options and returns the action to run;
// the action returns the process exit code (see docs/cli.md).
#include <CLI/CLI.hpp>
#include <functional>

namespace spt::cli {

using Action = std::function<int()>;

/// `spt convert`: meshes to .spt files, in parallel.
Action add_convert_command(CLI::App& app);
/// `spt info`: what a .spt file holds, and whether it is valid.
Action add_info_command(CLI::App& app);
/// `spt render`: off-screen renders of a mesh and its sampling tree to PNG.
Action add_render_command(CLI::App& app);
/// `spt render` in a build without render/ (SPT_BUILD_RENDER=OFF): says so, exit 1.
Action add_render_left_out(CLI::App& app);
/// `spt simulate`: steps a scene with the effects asked for, per-step counters as CSV.
Action add_simulate_command(CLI::App& app);
/// `spt query`: collision queries of B against A at poses from a file, CSV out.
Action add_query_command(CLI::App& app);

} // namespace spt::cli
