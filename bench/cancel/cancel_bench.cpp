// How long opening a mesh takes to stop after its cancel flag is set: the editor's Open does
// import_mesh then make_document with one flag. The flag is set from another thread at every
// STEP milliseconds of the opening, one opening each, until an opening ends before its flag.
// Prints a Markdown table; docs/benchmarks.md quotes it with this command.
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

int usage(const char* why) {
    std::fprintf(stderr, "spt-bench-cancel: %s\nUsage: spt-bench-cancel MESH [STEP_MS]  (STEP_MS: 10 to 10000, default 100)\n", why);
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3 || std::string(argv[1]) == "--help") return usage("a mesh file is needed");
    const std::string mesh = argv[1];
    char* end = nullptr;
    const long step = argc == 3 ? std::strtol(argv[2], &end, 10) : 100;
    if ((argc == 3 && (*end != '\0' || end == argv[2])) || step < 10 || step > 10000) return usage("STEP_MS must be 10 to 10000");
    std::printf("| flag set at (ms) | stopped after (ms) | in stage |\n|---:|---:|---|\n");
    double worst = 0;
    for (long at = 0;; at += step) {
        std::atomic<bool> cancel{false};
        Clock::time_point set_at{};
        std::string stage = "reading and preparing the mesh";
        std::thread canceller([&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(at));
            set_at = Clock::now();
            cancel = true;
        });
        try {
            spt::ImportOptions reading;
            reading.cancel = &cancel;
            const spt::TriangleMesh m = spt::import_mesh(mesh, reading).mesh;
            spt::ConvertOptions o;
            o.cancel = &cancel;
            o.on_stage = [&](const std::string& s) { stage = s; };
            spt::make_document(m, o);
            canceller.join();
            std::printf("\nThe opening ended %ld ms in, before its flag. Worst wait: %.0f ms.\n", at, worst);
            return 0;
        } catch (const spt::Cancelled&) {
            const Clock::time_point stopped = Clock::now();
            canceller.join();
            const double waited = ms_between(set_at, stopped);
            worst = std::max(worst, waited);
            std::printf("| %ld | %.1f | %s |\n", at, waited, stage.c_str());
            std::fflush(stdout);
        } catch (const std::exception& e) {
            canceller.join();
            std::fprintf(stderr, "spt-bench-cancel: %s\n", e.what());
            return 1;
        }
    }
}
