#include "gradient_cases.h"

#include "base/prng.h"
#include "scene/board_scene.h"
#include "soak_stream.h"

namespace qt::vec {

namespace {

io::GreyImage noise(int w, int h, Pcg32& rng) {
    io::GreyImage img(w, h);
    for (uint8_t& p : img.pixels) p = static_cast<uint8_t>(rng.next() & 0xFF);
    return img;
}

// 0/255 checks of 2×2 pixels: x-1 and x+1 fall in different checks on every other column,
// so gx and gy reach ±255 and the magnitude 510.
io::GreyImage checkerboard(int w, int h) {
    io::GreyImage img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img.at(x, y) = ((x / 2 + y / 2) & 1) ? 255 : 0;
    return img;
}

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

GradientCase single(const std::string& name, uint64_t seed, const io::GreyImage& img) {
    GradientCase c{name, seed, size_text(img.width, img.height), 1, {}};
    append_frame(img, c.in);
    return c;
}

GradientCase noise_case(const std::string& name, uint64_t seed, int w, int h) {
    Pcg32 rng(seed);
    return single(name, seed, noise(w, h, rng));
}

void append_beats(const io::GreyImage& img, int rows, std::vector<InBeat>& beats,
                  uint16_t declared_height) {
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < img.width; ++x) {
            InBeat b;
            b.pixel = img.at(x, y);
            b.tuser = x == 0 && y == 0;
            b.tlast = x == img.width - 1;
            b.height = b.tuser ? declared_height : 0;
            beats.push_back(b);
        }
}

// A stream with every framing fault of docs/gradient.md between good frames; the block must
// report 5 errors and get every good frame right.
GradientCase torn_stream(uint64_t seed) {
    Pcg32 rng(seed);
    GradientCase c{"torn_stream", seed, "", 0, {}};
    auto& s = c.in;
    auto good = [&](int w, int h) {
        append_frame(noise(w, h, rng), s);
        c.sizes += (c.sizes.empty() ? "" : "+") + size_text(w, h);
        ++c.frames;
    };
    auto bad = [&](int w, int h) {
        c.sizes += (c.sizes.empty() ? "" : "+") + size_text(w, h);
        ++c.frames;
        return noise(w, h, rng);
    };
    for (int i = 0; i < 3; ++i)
        s.push_back(InBeat{static_cast<uint8_t>(i), false, false, 0});  // stray beats
    good(6, 4);
    {  // short row 2: error, the rest of the frame is dropped
        const auto img = bad(6, 5);
        append_beats(img, 2, s, 5);
        for (int x = 0; x < 4; ++x) s.push_back(InBeat{img.at(x, 2), false, x == 3, 0});
        for (int y = 3; y < 5; ++y)
            for (int x = 0; x < 6; ++x) s.push_back(InBeat{img.at(x, y), false, x == 5, 0});
    }
    good(5, 3);
    append_beats(bad(7, 6), 3, s, 6);  // ends after 3 of 6 rows: the next start is an error
    good(4, 3);
    append_beats(bad(5, 2), 2, s, 0);  // declared height 0: error, beats dropped
    {  // row 0 of 700 pixels without an end of line: error at column MAX_WIDTH - 1
        const auto img = bad(700, 1);
        for (int x = 0; x < 700; ++x)
            s.push_back(InBeat{img.at(x, 0), x == 0, false, static_cast<uint16_t>(x == 0 ? 1 : 0)});
    }
    {  // row 1 runs past the width learnt from row 0: error at column 7
        const auto img = bad(9, 2);
        for (int x = 0; x < 8; ++x)
            s.push_back(
                InBeat{img.at(x, 0), x == 0, x == 7, static_cast<uint16_t>(x == 0 ? 2 : 0)});
        for (int x = 0; x < 9; ++x) s.push_back(InBeat{img.at(x, 1), false, x == 8, 0});
    }
    good(3, 3);
    return c;
}

// Every error path of docs/gradient.md, each between good frames: two errors on one beat (a
// start of frame with height 0 while a frame is in progress, in its row 0 and after it), errors
// in the last row (short and long), at the first and second beat of row 1 (the whole of output
// row 0 is fill), a frame that ends right after its row 0, a one-pixel-wide frame's long row.
GradientCase error_paths(uint64_t seed) {
    Pcg32 rng(seed);
    GradientCase c{"error_paths", seed, "", 0, {}};
    auto& s = c.in;
    auto add_size = [&](int w, int h) {
        c.sizes += (c.sizes.empty() ? "" : "+") + size_text(w, h);
        ++c.frames;
    };
    auto good = [&](int w, int h) {
        append_frame(noise(w, h, rng), s);
        add_size(w, h);
    };
    auto rows = [&](const io::GreyImage& img, int from, int to, uint16_t height) {
        for (int y = from; y < to; ++y)
            for (int x = 0; x < img.width; ++x) {
                const bool sof = x == 0 && y == 0;
                s.push_back(InBeat{img.at(x, y), sof, x == img.width - 1,
                                   static_cast<uint16_t>(sof ? height : 0)});
            }
    };
    auto part = [&](const io::GreyImage& img, int y, int n, int tlast_at = -1) {
        for (int x = 0; x < n; ++x) {
            const bool sof = x == 0 && y == 0;
            s.push_back(InBeat{img.at(x, y), sof, x == tlast_at,
                               static_cast<uint16_t>(sof ? img.height : 0)});
        }
    };
    good(6, 4);
    {  // rows 0, 1 and 3 beats of row 2, then a start of frame with height 0: two errors on one
        // beat (the frame ended early, the height is 0); the zero-height frame's beats follow
        const auto img = noise(6, 5, rng);
        add_size(6, 5);
        rows(img, 0, 2, 5);
        part(img, 2, 3);
        const auto zero = noise(6, 1, rng);
        add_size(6, 0);
        for (int x = 0; x < 6; ++x) s.push_back(InBeat{zero.at(x, 0), x == 0, x == 5, 0});
    }
    good(5, 3);
    {  // the last row ends early (tlast at column 4 of 7): its output row is completed with fill
        const auto img = noise(7, 4, rng);
        add_size(7, 4);
        rows(img, 0, 3, 4);
        part(img, 3, 5, 4);
    }
    good(4, 2);
    {  // the last row runs on past its end (no tlast at column 4 of 5), two more beats
        const auto img = noise(7, 3, rng);
        add_size(5, 3);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 5; ++x)
                s.push_back(InBeat{img.at(x, y), x == 0 && y == 0, x == 4,
                                   static_cast<uint16_t>(x == 0 && y == 0 ? 3 : 0)});
        part(img, 2, 7, 6);
    }
    {  // tlast on the first beat of row 1: output row 0 is all fill, with the start of frame
        const auto img = noise(6, 4, rng);
        add_size(6, 4);
        rows(img, 0, 1, 4);
        part(img, 1, 1, 0);
    }
    {  // tlast on the second beat of row 1: no word out yet, output row 0 all fill again
        const auto img = noise(6, 4, rng);
        add_size(6, 4);
        rows(img, 0, 1, 4);
        part(img, 1, 2, 1);
    }
    {  // the frame stops after its row 0; the next frame's start is the error (output row 0 fill)
        const auto img = noise(6, 3, rng);
        add_size(6, 3);
        rows(img, 0, 1, 3);
    }
    good(6, 3);
    {  // two beats of row 0, then a start of frame with height 0: two errors, nothing to fill
        const auto img = noise(4, 3, rng);
        add_size(4, 3);
        part(img, 0, 2);
        add_size(4, 0);
        s.push_back(InBeat{7, true, false, 0});
    }
    {  // one pixel wide: row 2 without tlast (its beat is the error), one fill word
        const auto img = noise(1, 4, rng);
        add_size(1, 4);
        rows(img, 0, 2, 4);
        s.push_back(InBeat{img.at(0, 2), false, false, 0});
    }
    good(3, 3);
    return c;
}

// Frames one after the other with no gap, all as wide: the blocks must not stall their input
// between them (each frame's last row goes out during the next one's row 0).
GradientCase back_to_back(uint64_t seed) {
    Pcg32 rng(seed);
    GradientCase c{"back_to_back", seed, "", 0, {}};
    for (int h : {3, 2, 5, 2, 4, 2}) {
        append_frame(noise(24, h, rng), c.in);
        c.sizes += (c.sizes.empty() ? "" : "+") + size_text(24, h);
        ++c.frames;
    }
    return c;
}

GradientCase soak_case(const std::string& name, uint64_t seed, uint64_t pixels, int max_width) {
    const SoakStream s = make_soak_stream(seed, pixels, max_width);
    GradientCase c{name, seed, "soak", s.frames, s.in};
    c.max_width = max_width;
    c.threshold = s.threshold;
    for (const ResetPoint& r : s.expected.resets) c.reset_before.push_back(r.in_beat);
    return c;
}

}  // namespace

void append_frame(const io::GreyImage& img, std::vector<InBeat>& beats) {
    append_beats(img, img.height, beats, static_cast<uint16_t>(img.height));
}

std::vector<GradientCase> gradient_cases() {
    std::vector<GradientCase> cases;
    cases.push_back(noise_case("size_1x1", 11, 1, 1));
    cases.push_back(noise_case("size_1x17", 12, 1, 17));
    cases.push_back(noise_case("size_23x1", 13, 23, 1));
    cases.push_back(noise_case("size_2x2", 14, 2, 2));
    cases.push_back(noise_case("size_3x3", 15, 3, 3));
    cases.push_back(noise_case("noise_37x23", 16, 37, 23));
    cases.push_back(noise_case("noise_64x48", 17, 64, 48));
    cases.push_back(single("const0_64x48", 0, io::GreyImage(64, 48, 0)));
    cases.push_back(single("const255_64x48", 0, io::GreyImage(64, 48, 255)));
    cases.push_back(single("checker_64x48", 0, checkerboard(64, 48)));
    {
        const scene::BoardScene board = scene::default_board_scene();
        cases.push_back(single("board_640x480", board.seed, scene::render_board(board)));
    }
    {  // back-to-back frames of different sizes, including the widest and a 1-wide one
        const uint64_t seed = 18;
        Pcg32 rng(seed);
        GradientCase c{"multi_sizes", seed, "", 0, {}};
        const int sizes[][2] = {{5, 4}, {17, 9}, {1, 3}, {8, 1}, {31, 7}, {640, 2}, {2, 5}};
        for (const auto& wh : sizes) {
            append_frame(noise(wh[0], wh[1], rng), c.in);
            c.sizes += (c.sizes.empty() ? "" : "+") + size_text(wh[0], wh[1]);
            ++c.frames;
        }
        cases.push_back(c);
    }
    cases.push_back(torn_stream(19));
    cases.push_back(error_paths(20));
    cases.push_back(back_to_back(21));
    {  // the edge stage's threshold at its ends
        GradientCase lo = noise_case("threshold_1", 22, 37, 9);
        lo.threshold = 1;
        GradientCase hi = single("threshold_510", 0, checkerboard(16, 12));
        hi.threshold = 510;
        cases.push_back(lo);
        cases.push_back(hi);
    }
    // Random frames with faults and resets (the soak's generator), for MAX_WIDTH 640 and the
    // sweep of MAX_WIDTH the HDL benches run.
    // (Seeds picked for short streams: every kind of fault and reset must occur in each.)
    cases.push_back(soak_case("soak_640", 114, 20000, 640));
    cases.push_back(soak_case("sweep_w1", 102, 4000, 1));
    cases.push_back(soak_case("sweep_w2", 103, 4000, 2));
    cases.push_back(soak_case("sweep_w3", 104, 6000, 3));
    cases.push_back(soak_case("sweep_w37", 123, 8000, 37));
    cases.push_back(soak_case("sweep_w1920", 109, 20000, 1920));
    return cases;
}

}  // namespace qt::vec
