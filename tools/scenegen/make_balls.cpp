// Writes a benchmark scene of many small colliding balls (docs/benchmarks.md, "Threads"): a
// UV-sphere mesh and a scene of N copies, radius 0.1, on a cubic lattice 0.25 apart, each moved
// at random by up to 0.02 along each axis (none overlaps at the start: a deep first overlap is
// another benchmark's), with uniform random velocities up to 0.5 a component, the same for the
// same seed on every standard library.
// Usage: spt-make-balls OUT_DIR [N=1000] [SEED=1]. Writes OUT_DIR/ball.obj and OUT_DIR/balls.json.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>

namespace {

// Uniform in [lo, hi) from the raw generator output (std::uniform_real_distribution is not
// specified bit for bit).
double uniform(std::mt19937& rng, double lo, double hi) { return lo + (hi - lo) * (double(rng()) / 4294967296.0); }

// Radius 0.1, 16 slices by 8 stacks: small enough that a step's contacts are many and cheap.
void write_ball(const std::filesystem::path& file) {
    const double r = 0.1, pi = std::acos(-1.0);
    const int slices = 16, stacks = 8;
    std::ofstream out(file);
    out << "v 0 " << r << " 0\n";
    for (int i = 1; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const double t = pi * i / stacks, p = 2 * pi * j / slices;
            out << "v " << r * std::sin(t) * std::cos(p) << ' ' << r * std::cos(t) << ' ' << r * std::sin(t) * std::sin(p) << '\n';
        }
    out << "v 0 " << -r << " 0\n";
    const int bottom = 2 + (stacks - 1) * slices; // OBJ indices count from 1
    auto ring = [&](int i, int j) { return 2 + (i - 1) * slices + (j % slices); };
    for (int j = 0; j < slices; ++j) out << "f 1 " << ring(1, j + 1) << ' ' << ring(1, j) << '\n';
    for (int i = 1; i + 1 < stacks; ++i)
        for (int j = 0; j < slices; ++j)
            out << "f " << ring(i, j) << ' ' << ring(i, j + 1) << ' ' << ring(i + 1, j + 1) << ' ' << ring(i + 1, j) << '\n';
    for (int j = 0; j < slices; ++j) out << "f " << bottom << ' ' << ring(stacks - 1, j) << ' ' << ring(stacks - 1, j + 1) << '\n';
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: spt-make-balls OUT_DIR [N=1000] [SEED=1]\n";
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    const int n = argc > 2 ? std::atoi(argv[2]) : 1000;
    const unsigned seed = argc > 3 ? unsigned(std::atoi(argv[3])) : 1u;
    std::filesystem::create_directories(dir);
    write_ball(dir / "ball.obj");
    std::mt19937 rng(seed);
    std::ofstream out(dir / "balls.json");
    out << "{\n  \"spt_scene\": 1,\n  \"dt\": 0.01,\n  \"steps\": 100,\n"
        << "  \"effects\": [\"motion\",\"contacts\",\"depth\",\"response\"],\n"
        << "  \"response\": {\"rule\":\"backtrack\",\"restitution\":0.5},\n  \"objects\": [\n";
    out.precision(17);
    const int side = int(std::ceil(std::cbrt(double(n))));
    for (int i = 0; i < n; ++i) {
        double v[6]; // one draw a statement: the order is fixed
        for (double& x : v) x = uniform(rng, -1, 1);
        const double x = 0.25 * (i % side) + 0.02 * v[0], y = 0.25 * (i / side % side) + 0.02 * v[1],
                     z = 0.25 * (i / side / side) + 0.02 * v[2];
        out << "    {\"name\":\"b" << i << "\",\"model\":\"ball.obj\",\"position\":[" << x << ',' << y << ',' << z
            << "],\"velocity\":[" << v[3] / 2 << ',' << v[4] / 2 << ',' << v[5] / 2 << "]}" << (i + 1 < n ? ",\n" : "\n");
    }
    out << "  ]\n}\n";
    if (!out) {
        std::cerr << (dir / "balls.json").string() << ": write failed\n";
        return 3;
    }
    return 0;
}
