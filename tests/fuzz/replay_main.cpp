// Replays a fuzz target without libFuzzer: runs LLVMFuzzerTestOneInput once on every file of
// the directories (or files) named on the command line, in name order, and prints how many it
// ran. A violated invariant or a sanitizer report ends the process with that input's name
// printed just before it. An absent directory is skipped (a target may have no regressions
// yet), but no input at all is an error. Linked with each target as fuzz_replay_<target>.
#include <stddef.h>
#include <stdint.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace fs = std::filesystem;

namespace {

bool run_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "fuzz_replay: cannot read %s\n", file.string().c_str());
        return false;
    }
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in),
                                  std::istreambuf_iterator<char>()};
    std::printf("  %s (%zu bytes)\n", file.string().c_str(), bytes.size());
    std::fflush(stdout);
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s DIR_OR_FILE...\n", argv[0]);
        return 2;
    }
    size_t total = 0;
    for (int i = 1; i < argc; ++i) {
        const fs::path p = argv[i];
        std::error_code ec;
        if (fs::is_regular_file(p, ec)) {
            if (!run_file(p)) return 1;
            ++total;
            continue;
        }
        if (!fs::is_directory(p, ec)) {
            std::printf("%s: absent, skipped\n", p.string().c_str());
            continue;
        }
        std::vector<fs::path> files;
        for (const fs::directory_entry& e : fs::directory_iterator(p, ec))
            if (e.is_regular_file()) files.push_back(e.path());
        if (ec) {
            std::fprintf(stderr, "fuzz_replay: cannot list %s: %s\n", p.string().c_str(),
                         ec.message().c_str());
            return 1;
        }
        std::sort(files.begin(), files.end());
        std::printf("%s: %zu inputs\n", p.string().c_str(), files.size());
        for (const fs::path& f : files)
            if (!run_file(f)) return 1;
        total += files.size();
    }
    std::printf("ran %zu inputs\n", total);
    if (total == 0) {
        std::fprintf(stderr, "fuzz_replay: no input found\n");
        return 1;
    }
    return 0;
}
