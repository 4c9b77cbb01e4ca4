#pragma once
// Long work (import, sampling, tree building) looks at its caller's cancel flag between steps
// and stops by throwing Cancelled, so that an editor's Cancel button is answered within a step.
#include "spt/error.hpp"
#include <atomic>
#include <string>

namespace spt::detail {

/// True once the caller has asked the work to stop (a null flag never asks).
inline bool cancel_requested(const std::atomic<bool>* flag) {
    return flag && flag->load(std::memory_order_relaxed);
}

/// Throws Cancelled("<doing> <name>: cancelled") once the caller has asked the work to stop.
inline void stop_if_cancelled(const std::atomic<bool>* flag, const char* doing, const std::string& name) {
    if (cancel_requested(flag)) throw Cancelled(std::string(doing) + " " + name + ": cancelled");
}

} // namespace spt::detail
