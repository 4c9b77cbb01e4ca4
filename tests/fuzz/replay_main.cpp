// Replays fuzz inputs without libFuzzer: each argument is a file or a directory of files,
// each file passed once to LLVMFuzzerTestOneInput. Built with the ordinary compiler so the
// Release suite replays the committed corpus (tests/fuzz/corpus/TARGET/) as a test.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

int replay(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "%s: cannot read\n", file.c_str());
        return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    size_t files = 0;
    int failures = 0;
    for (int i = 1; i < argc; ++i) {
        const std::filesystem::path p(argv[i]);
        if (std::filesystem::is_directory(p)) {
            std::vector<std::filesystem::path> all;
            for (const auto& e : std::filesystem::directory_iterator(p))
                if (e.is_regular_file()) all.push_back(e.path());
            std::sort(all.begin(), all.end()); // same order every run
            for (const auto& f : all) failures += replay(f), ++files;
        } else {
            failures += replay(p), ++files;
        }
    }
    std::printf("replayed %zu inputs\n", files);
    if (files == 0) {
        std::fprintf(stderr, "no inputs: give files or corpus directories\n");
        return 1;
    }
    return failures ? 1 : 0;
}
