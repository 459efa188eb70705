// qt_vectors: writes or checks the golden vectors of the gradient block, the Verilog include
// generated from the gradient-word definition, and the whole chain's test frames with
// their expected results.
//   qt_vectors --write ROOT            regenerate ROOT/vectors/gradient/, ROOT/vectors/scenes/ and
//                                      ROOT/hdl/rtl/gradient_word.vh
//   qt_vectors --check ROOT            exit 1 unless every committed file equals a fresh generation
//   qt_vectors --direction-table FILE  expected direction bin of every (gx, gy), gx outer, gy
//   inner,
//                                      -255..255 each, one hex digit per line
//                                      (hdl/bench/tb_direction.v)
//   qt_vectors --soak SEED PIXELS PREFIX  a soak stream (docs/gradient.md, "Soak") of at least
//                                      PIXELS input beats: PREFIX.in.hex, PREFIX.out.hex,
//                                      PREFIX.resets.hex; prints its counts on one line
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "chain_cases.h"
#include "gradient_cases.h"
#include "gradient_model.h"
#include "soak_stream.h"

namespace {

using Files = std::map<std::string, std::string>;  // path relative to ROOT -> contents

Files generate() {
    using namespace qt::vec;
    Files files;
    std::string manifest = manifest_header();
    for (const GradientCase& c : gradient_cases()) {
        int errors = 0;
        const auto out = run_model(c.in, kVectorMaxWidth, &errors);
        const std::string in_text = format_in(c.in), out_text = format_out(out);
        const std::string dir = "vectors/gradient/";
        files[dir + c.name + ".in.hex"] = in_text;
        files[dir + c.name + ".out.hex"] = out_text;
        ManifestEntry e{c.name, c.sizes,         c.frames,
                        c.seed, c.in.size(),     out.size(),
                        errors, kVectorMaxWidth, fnv1a64(out_text, fnv1a64(in_text))};
        manifest += format_manifest_line(e);
    }
    files["vectors/gradient/manifest.txt"] = manifest;
    const std::vector<ChainCase> cases = chain_cases();
    const std::vector<std::string> texts = chain_texts(cases);
    for (size_t i = 0; i < cases.size(); ++i) {
        const ChainCase& c = cases[i];
        for (size_t k = 0; k < c.frames.size(); ++k)
            files["vectors/scenes/" + frame_name(c, k) + ".pgm"] = format_pgm(c.frames[k]);
        files["vectors/scenes/" + c.name + ".chain.txt"] = texts[i];
    }
    files["hdl/rtl/gradient_word.vh"] = verilog_header();
    return files;
}

bool read_file(const std::string& path, std::string& text) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return false;
    std::ostringstream s;
    s << f.rdbuf();
    text = s.str();
    return true;
}

int write_all(const std::string& root) {
    for (const auto& [path, text] : generate()) {
        std::ofstream f(root + "/" + path, std::ios::binary);
        if (!(f << text)) {
            std::fprintf(stderr, "qt_vectors: cannot write %s/%s\n", root.c_str(), path.c_str());
            return 1;
        }
    }
    std::printf("wrote vectors/gradient/, vectors/scenes/ and hdl/rtl/gradient_word.vh under %s\n",
                root.c_str());
    return 0;
}

int check_all(const std::string& root) {
    int bad = 0;
    size_t checked = 0;
    for (const auto& [path, text] : generate()) {
        std::string committed;
        if (!read_file(root + "/" + path, committed)) {
            std::fprintf(stderr, "MISSING %s\n", path.c_str());
            ++bad;
        } else if (committed != text) {
            size_t i = 0;
            while (i < committed.size() && i < text.size() && committed[i] == text[i]) ++i;
            std::fprintf(stderr, "STALE %s (first difference at byte %zu)\n", path.c_str(), i);
            ++bad;
        }
        ++checked;
    }
    if (bad) {
        std::fprintf(stderr,
                     "%d of %zu generated files differ from the committed ones; "
                     "regenerate with: qt_vectors --write <repo root>\n",
                     bad, checked);
        return 1;
    }
    std::printf("all %zu generated files match the committed ones\n", checked);
    return 0;
}

int direction_table(const std::string& path) {
    std::ofstream f(path);
    for (int gx = -255; gx <= 255; ++gx)
        for (int gy = -255; gy <= 255; ++gy)
            f << "0123456789abcdef"[qt::direction_bin(gx, gy)] << '\n';
    if (!f) {
        std::fprintf(stderr, "qt_vectors: cannot write %s\n", path.c_str());
        return 1;
    }
    return 0;
}

bool parse_count(const char* text, uint64_t& value) {
    char* end = nullptr;
    if (!*text || *text == '-') return false;
    value = std::strtoull(text, &end, 10);
    return *end == '\0';
}

// One line of name=value counts, for scripts (hdl/bench/run_soak.cmake, bench.sh hdl-soak).
int soak(const char* seed_text, const char* pixels_text, const std::string& prefix) {
    using namespace qt::vec;
    uint64_t seed = 0, pixels = 0;
    if (!parse_count(seed_text, seed) || !parse_count(pixels_text, pixels) || pixels == 0 ||
        pixels > 100000000) {
        std::fprintf(stderr,
                     "qt_vectors --soak: SEED must be an unsigned integer and PIXELS "
                     "1..100000000\n");
        return 2;
    }
    const SoakStream s = make_soak_stream(seed, pixels, kVectorMaxWidth);
    const std::pair<const char*, std::string> files[] = {{".in.hex", format_in(s.in)},
                                                         {".out.hex", format_out(s.out)},
                                                         {".resets.hex", format_resets(s.resets)}};
    std::vector<ResetPoint> back;
    std::string error;
    if (!parse_resets(files[2].second, back, error) || back != s.resets) {
        std::fprintf(stderr, "qt_vectors --soak: reset points do not read back: %s\n",
                     error.c_str());
        return 1;
    }
    for (const auto& [suffix, text] : files) {
        std::ofstream f(prefix + suffix, std::ios::binary);
        if (!(f << text)) {
            std::fprintf(stderr, "qt_vectors: cannot write %s%s\n", prefix.c_str(), suffix);
            return 1;
        }
    }
    int faults = 0;
    std::string kinds;
    for (int k = 0; k < kSoakFaultKinds; ++k) {
        faults += s.faults[k];
        kinds += std::string(" ") + soak_fault_name(static_cast<SoakFault>(k)) + "=" +
                 std::to_string(s.faults[k]);
    }
    std::printf(
        "soak seed=%llu max_width=%d in_beats=%zu out_beats=%zu errors=%d resets=%zu "
        "pixels=%llu frames=%d clean_frames=%d faults=%d%s\n",
        static_cast<unsigned long long>(seed), kVectorMaxWidth, s.in.size(), s.out.size(), s.errors,
        s.resets.size(), static_cast<unsigned long long>(s.pixels), s.frames, s.clean_frames,
        faults, kinds.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 5 && std::string(argv[1]) == "--soak") return soak(argv[2], argv[3], argv[4]);
    if (argc == 3) {
        const std::string mode = argv[1];
        if (mode == "--write") return write_all(argv[2]);
        if (mode == "--check") return check_all(argv[2]);
        if (mode == "--direction-table") return direction_table(argv[2]);
    }
    std::fprintf(stderr,
                 "usage: qt_vectors --write ROOT | --check ROOT | --direction-table FILE | "
                 "--soak SEED PIXELS PREFIX\n");
    return 2;
}
