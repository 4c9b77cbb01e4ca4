// Cost of one detail::parallel_for call of 64 trivial items on 2 threads: what starting the
// work costs, without the work (docs/benchmarks.md, "Threads"); 30bdfeb's parallel.hpp was header-only, so
// the same file compiled against it gives the figure from before the pool.
#include "base/parallel.hpp"
#include <chrono>
#include <cstdio>
#include <vector>
int main() {
    std::vector<double> v(64);
    for (int round = 0; round < 3; ++round) {
        const int calls = 20000;
        auto t0 = std::chrono::steady_clock::now();
        for (int c = 0; c < calls; ++c)
            spt::detail::parallel_for(v.size(), 2, [&](size_t i, int) { v[i] += 1; });
        double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / calls;
        std::printf("%.2f us a call\n", us);
    }
}
