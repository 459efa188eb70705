// qt_vectors: writes or checks the golden vectors of the gradient block and the FPGA front end,
// the Verilog includes generated from the gradient-word and edge-beat definitions, and the whole
// chain's test frames with their expected results.
//   qt_vectors --write ROOT            regenerate ROOT/vectors/gradient/, ROOT/vectors/scenes/,
//                                      ROOT/hdl/rtl/gradient_word.vh and ROOT/hdl/rtl/edge_beat.vh
//   qt_vectors --check ROOT            exit 1 unless every committed file equals a fresh generation
//   qt_vectors --direction-table FILE  expected direction bin of every (gx, gy), gx outer, gy
//                                      inner, -255..255 each, one hex digit per line
//                                      (hdl/bench/tb_direction.v; also committed as
//                                      vectors/gradient/direction_table.hex)
//   qt_vectors --soak SEED PIXELS PREFIX [MAX_WIDTH]  a soak stream (docs/gradient.md, "Soak") of
//                                      at least PIXELS input beats for MAX_WIDTH (640):
//                                      PREFIX.in.hex, .out.hex, .edges.hex, .resets.hex; prints
//                                      its counts on one line
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "chain_cases.h"
#include "edge_model.h"
#include "gradient_cases.h"
#include "gradient_model.h"
#include "io/image_io.h"
#include "soak_stream.h"

namespace {

using Files = std::map<std::string, std::string>;  // path relative to ROOT -> contents

std::string direction_text() {
    std::string s;
    s.reserve(511 * 511 * 2);
    for (int gx = -255; gx <= 255; ++gx)
        for (int gy = -255; gy <= 255; ++gy) {
            s += "0123456789abcdef"[qt::direction_bin(gx, gy)];
            s += '\n';
        }
    return s;
}

Files generate() {
    using namespace qt::vec;
    Files files;
    std::string manifest = manifest_header();
    const std::string dir = "vectors/gradient/";
    for (const GradientCase& c : gradient_cases()) {
        const Expected x = expected_outputs(c.in, c.reset_before, c.max_width, c.threshold);
        const std::string in_text = format_in(c.in), out_text = format_out(x.out);
        const std::string edge_text = format_edges(x.edges), reset_text = format_resets(x.resets);
        files[dir + c.name + ".in.hex"] = in_text;
        files[dir + c.name + ".out.hex"] = out_text;
        files[dir + c.name + ".edges.hex"] = edge_text;
        if (!x.resets.empty()) files[dir + c.name + ".resets.hex"] = reset_text;
        ManifestEntry e;
        e.name = c.name;
        e.sizes = c.sizes;
        e.frames = c.frames;
        e.seed = c.seed;
        e.in_beats = c.in.size();
        e.out_beats = x.out.size();
        e.edge_beats = x.edges.size();
        e.errors = x.errors;
        e.resets = x.resets.size();
        e.threshold = c.threshold;
        e.max_width = c.max_width;
        e.hash = fnv1a64(out_text, fnv1a64(in_text));
        manifest += format_manifest_line(e);
    }
    files[dir + "manifest.txt"] = manifest;
    files[dir + "direction_table.hex"] = direction_text();
    const std::vector<ChainCase> cases = chain_cases();
    for (const bool tracking_mode : {false, true}) {
        const std::vector<std::string> texts = chain_texts(cases, tracking_mode);
        for (size_t i = 0; i < cases.size(); ++i) {
            const ChainCase& c = cases[i];
            for (size_t k = 0; k < c.frames.size(); ++k)
                files["vectors/scenes/" + frame_name(c, k) + ".pgm"] = format_pgm(c.frames[k]);
            files["vectors/scenes/" + text_name(c, tracking_mode) + ".chain.txt"] = texts[i];
        }
    }
    files["hdl/rtl/gradient_word.vh"] = verilog_header();
    files["hdl/rtl/edge_beat.vh"] = verilog_edge_header();
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
    std::printf(
        "wrote vectors/gradient/, vectors/scenes/, hdl/rtl/gradient_word.vh and "
        "hdl/rtl/edge_beat.vh under %s\n",
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
    std::ofstream f(path, std::ios::binary);
    f << direction_text();
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
int soak(const char* seed_text, const char* pixels_text, const std::string& prefix,
         const char* width_text) {
    using namespace qt::vec;
    uint64_t seed = 0, pixels = 0, max_width = kVectorMaxWidth;
    if (!parse_count(seed_text, seed) || !parse_count(pixels_text, pixels) || pixels == 0 ||
        pixels > 100000000 || (width_text && !parse_count(width_text, max_width)) ||
        max_width < 1 || max_width > qt::ep::kMaxCoordinate + 1) {
        std::fprintf(stderr,
                     "qt_vectors --soak: SEED must be an unsigned integer, PIXELS "
                     "1..100000000 and MAX_WIDTH 1..2048\n");
        return 2;
    }
    const SoakStream s = make_soak_stream(seed, pixels, static_cast<int>(max_width));
    const Expected& x = s.expected;
    const std::pair<const char*, std::string> files[] = {{".in.hex", format_in(s.in)},
                                                         {".out.hex", format_out(x.out)},
                                                         {".edges.hex", format_edges(x.edges)},
                                                         {".resets.hex", format_resets(x.resets)}};
    std::vector<ResetPoint> back;
    std::string error;
    if (!parse_resets(files[3].second, back, error) || back != x.resets) {
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
        "soak seed=%llu max_width=%llu threshold=%d in_beats=%zu out_beats=%zu edge_beats=%zu "
        "errors=%d resets=%zu pixels=%llu frames=%d clean_frames=%d core_frames=%d faults=%d%s\n",
        static_cast<unsigned long long>(seed), static_cast<unsigned long long>(max_width),
        s.threshold, s.in.size(), x.out.size(), x.edges.size(), x.errors, x.resets.size(),
        static_cast<unsigned long long>(s.pixels), s.frames, s.clean_frames, s.core_frames, faults,
        kinds.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if ((argc == 5 || argc == 6) && std::string(argv[1]) == "--soak")
        return soak(argv[2], argv[3], argv[4], argc == 6 ? argv[5] : nullptr);
    if (argc == 3) {
        const std::string mode = argv[1];
        if (mode == "--write") return write_all(argv[2]);
        if (mode == "--check") return check_all(argv[2]);
        if (mode == "--direction-table") return direction_table(argv[2]);
    }
    std::fprintf(stderr,
                 "usage: qt_vectors --write ROOT | --check ROOT | --direction-table FILE | "
                 "--soak SEED PIXELS PREFIX [MAX_WIDTH]\n");
    return 2;
}
