// qt_vectors: writes or checks the golden vectors of the gradient block, the Verilog include
// generated from the gradient-word definition, and the whole chain's test frames with
// their expected results.
//   qt_vectors --write ROOT            regenerate ROOT/vectors/gradient/, ROOT/vectors/scenes/ and
//                                      ROOT/hdl/gradient_word.vh
//   qt_vectors --check ROOT            exit 1 unless every committed file equals a fresh generation
//   qt_vectors --direction-table FILE  expected direction bin of every (gx, gy), gx outer, gy inner,
//                                      -255..255 each, one hex digit per line (hdl/tb_direction.v)
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "gradient_cases.h"
#include "gradient_model.h"
#include "chain_cases.h"

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
        ManifestEntry e{c.name, c.sizes, c.frames, c.seed, c.in.size(), out.size(), errors,
                        kVectorMaxWidth, fnv1a64(out_text, fnv1a64(in_text))};
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
    files["hdl/gradient_word.vh"] = verilog_header();
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
    std::printf("wrote vectors/gradient/, vectors/scenes/ and hdl/gradient_word.vh under %s\n", root.c_str());
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
        std::fprintf(stderr, "%d of %zu generated files differ from the committed ones; "
                             "regenerate with: qt_vectors --write <repo root>\n", bad, checked);
        return 1;
    }
    std::printf("all %zu generated files match the committed ones\n", checked);
    return 0;
}

int direction_table(const std::string& path) {
    std::ofstream f(path);
    for (int gx = -255; gx <= 255; ++gx)
        for (int gy = -255; gy <= 255; ++gy) f << "0123456789abcdef"[qt::direction_bin(gx, gy)] << '\n';
    if (!f) {
        std::fprintf(stderr, "qt_vectors: cannot write %s\n", path.c_str());
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3) {
        const std::string mode = argv[1];
        if (mode == "--write") return write_all(argv[2]);
        if (mode == "--check") return check_all(argv[2]);
        if (mode == "--direction-table") return direction_table(argv[2]);
    }
    std::fprintf(stderr, "usage: qt_vectors --write ROOT | --check ROOT | --direction-table FILE\n");
    return 2;
}
