#pragma once
/// Errors raised by the spt library. Every error names what failed and why; a front end decides
/// what each kind means to its user (the `spt` command's exit codes: cli/exit_code.hpp).
#include <stdexcept>
#include <string>

namespace spt {

/// What kind of failure an Error is: the caller asked for something impossible (Usage), an input
/// is unreadable or wrong (BadInput), or an output cannot be written (CannotWrite).
enum class ErrorKind { Usage, BadInput, CannotWrite };

/// Exception carrying a kind and a message that names the file and the problem.
class Error : public std::runtime_error {
public:
    /// Makes an error of `kind` with a complete, user-facing message.
    Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    /// The kind of failure.
    ErrorKind kind() const { return kind_; }

private:
    ErrorKind kind_;
};

/// Thrown when long work (an import, a conversion, a tree build) was stopped by its caller's
/// cancel flag: nothing was made and nothing the caller owns was changed.
class Cancelled : public std::runtime_error {
public:
    /// Makes the exception; `what` says which work stopped.
    explicit Cancelled(const std::string& what) : std::runtime_error(what) {}
};

/// Throws Error(BadInput) with "path: message".
[[noreturn]] inline void throw_bad_input(const std::string& path, const std::string& message) {
    throw Error(ErrorKind::BadInput, path.empty() ? message : path + ": " + message);
}

} // namespace spt
