#pragma once
// The `spt` command's exit codes (docs/cli.md), shared with the project's other command-line
// programs (tools/, bench/): the library's error kinds carry no numbers of their own.
#include "spt/error.hpp"

namespace spt::cli {

/// The documented exit code of an error of `kind`: 1 usage, 2 bad input, 3 cannot write.
inline int exit_code(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::Usage: return 1;
    case ErrorKind::BadInput: return 2;
    case ErrorKind::CannotWrite: return 3;
    }
    return 2;
}

} // namespace spt::cli
