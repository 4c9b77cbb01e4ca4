#pragma once
// The command line of the generators (spt-make-resources, spt-make-hard-meshes,
// spt-make-scenes): an output folder, never an option taken for one.
#include <cstring>
#include <iostream>

namespace spt::meshgen {

/// Whether argv[1] is an output folder; if not (no argument, or an option such as --help that
/// would otherwise have been made into a folder), prints `usage` and sets `exit_code` (0 for
/// -h and --help, 1 otherwise). `extra`: how many arguments may follow the folder.
inline bool out_dir_argument(int argc, char** argv, const char* usage, int& exit_code, int extra = 0) {
    if (argc >= 2 && argc <= 2 + extra && argv[1][0] != '-') return true;
    const bool help = argc >= 2 && (!std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "--help"));
    (help ? std::cout : std::cerr) << usage << '\n';
    exit_code = help ? 0 : 1;
    return false;
}

} // namespace spt::meshgen
