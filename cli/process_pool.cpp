// Worker processes for `spt convert`: one file each, so a crashing reader fails that file alone.
#include "process_pool.hpp"
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <iostream>
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace spt::cli {
namespace {

// AddressSanitizer reserves terabytes of address space for its shadow memory; an
// address-space limit would make every worker fail at start.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressLimitWorks = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressLimitWorks = false;
#else
constexpr bool kAddressLimitWorks = true;
#endif
#else
constexpr bool kAddressLimitWorks = true;
#endif

struct Child {
    size_t job;
    pid_t pid;
    int fd;
    std::chrono::steady_clock::time_point start;
    JobOutcome outcome;
    bool pipe_open = true;
};

void drain(Child& c) {
    char buf[4096];
    for (;;) {
        const ssize_t n = ::read(c.fd, buf, sizeof buf);
        if (n > 0) {
            c.outcome.messages.append(buf, size_t(n));
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n == 0) c.pipe_open = false;
        return;
    }
}

} // namespace

void run_in_processes(size_t n, int jobs, double timeout_s, size_t memory_limit_bytes,
                      const std::function<int(size_t)>& work,
                      const std::function<void(size_t, const JobOutcome&)>& done) {
    std::vector<Child> running;
    size_t next = 0;
    std::cerr.flush();
    std::cout.flush();
    while (next < n || !running.empty()) {
        while (next < n && int(running.size()) < std::max(1, jobs)) {
            int fds[2];
            if (::pipe(fds) != 0) throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
            const pid_t pid = ::fork();
            if (pid < 0) throw std::runtime_error(std::string("cannot start a worker process: ") + std::strerror(errno));
            if (pid == 0) {
                ::close(fds[0]);
                ::dup2(fds[1], 2);
                ::close(fds[1]);
                if (memory_limit_bytes && kAddressLimitWorks) {
                    rlimit lim{memory_limit_bytes, memory_limit_bytes};
                    ::setrlimit(RLIMIT_AS, &lim);
                }
                int code = 2;
                try {
                    code = work(next);
                } catch (const std::bad_alloc&) {
                    std::cerr << "out of memory (limit " << (memory_limit_bytes >> 20) << " MiB)\n";
                } catch (const std::exception& e) {
                    std::cerr << e.what() << "\n";
                }
                std::cerr.flush();
                std::cout.flush();
                ::_exit(code);
            }
            ::close(fds[1]);
            ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
            running.push_back({next, pid, fds[0], std::chrono::steady_clock::now(), {}});
            ++next;
        }
        std::vector<pollfd> pfds;
        for (auto& c : running)
            if (c.pipe_open) pfds.push_back({c.fd, POLLIN, 0});
        ::poll(pfds.data(), pfds.size(), 50);
        for (size_t i = 0; i < running.size();) {
            Child& c = running[i];
            if (c.pipe_open) drain(c);
            const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - c.start).count();
            int status = 0;
            pid_t r = ::waitpid(c.pid, &status, WNOHANG);
            if (r == 0 && timeout_s > 0 && elapsed > timeout_s) {
                ::kill(c.pid, SIGKILL);
                ::waitpid(c.pid, &status, 0);
                c.outcome.abnormal = "gave up after " + std::to_string(int(timeout_s)) + " s (--timeout)";
                r = c.pid;
                status = 2 << 8;
            }
            if (r == c.pid) {
                while (c.pipe_open) drain(c);
                ::close(c.fd);
                c.outcome.seconds = elapsed;
                if (WIFEXITED(status)) {
                    c.outcome.exit_code = WEXITSTATUS(status);
                } else if (WIFSIGNALED(status)) {
                    c.outcome.exit_code = 2;
                    if (c.outcome.abnormal.empty())
                        c.outcome.abnormal = std::string("the reader crashed (") + ::strsignal(WTERMSIG(status)) + ")";
                }
                if (!c.outcome.abnormal.empty()) c.outcome.exit_code = 2;
                done(c.job, c.outcome);
                running.erase(running.begin() + long(i));
                continue;
            }
            ++i;
        }
    }
}

} // namespace spt::cli
