#include "soak_stream.h"

#include <stdexcept>
#include <string>

#include "base/prng.h"
#include "core_edges.h"
#include "edge_model.h"

namespace qt::vec {

const char* soak_fault_name(SoakFault f) {
    switch (f) {
        case SoakFault::short_row: return "short_row";
        case SoakFault::long_row: return "long_row";
        case SoakFault::early_end: return "early_end";
        case SoakFault::height_zero: return "height_zero";
        case SoakFault::wide_row0: return "wide_row0";
        case SoakFault::stray: return "stray";
        case SoakFault::reset_mid: return "reset_mid";
        case SoakFault::reset_after_error: return "reset_after_error";
        case SoakFault::reset_last_row: return "reset_last_row";
        case SoakFault::reset_flush: return "reset_flush";
        case SoakFault::reset_between: return "reset_between";
        case SoakFault::count: break;
    }
    return "?";
}

namespace {

struct Cut {
    size_t in_beat;
    bool after_error;  // the beat before it must be one the model reports an error on
};

struct CleanFrame {
    size_t first_beat;
    int width, height;
};

class Generator {
public:
    Generator(uint64_t seed, int max_width) : rng_(seed), max_width_(max_width) {}

    void item(SoakStream& s);
    const std::vector<Cut>& cuts() const { return cuts_; }
    const std::vector<CleanFrame>& clean() const { return clean_; }

private:
    uint32_t below(uint32_t n) { return rng_.below(n); }
    int pick_width();
    int pick_height();
    uint8_t pixel();
    void beat(SoakStream& s, int x, int y, bool tlast, uint16_t height = 0);
    void row(SoakStream& s, int y, int width) {
        for (int x = 0; x < width; ++x) beat(s, x, y, x == width - 1);
    }
    void cut(SoakStream& s, SoakFault kind, bool after_error = false) {
        cuts_.push_back(Cut{s.in.size(), after_error});
        ++s.faults[static_cast<int>(kind)];
    }
    void frame(SoakStream& s);

    Pcg32 rng_;
    int max_width_;
    int mode_ = 0;  // pixel statistics of the current frame
    uint8_t level_ = 0;
    std::vector<Cut> cuts_;
    std::vector<CleanFrame> clean_;
};

// 1, 2 and MAX_WIDTH often; otherwise uniform below a random power of two, so that most frames
// are narrow (many frames, many starts and ends) and every width occurs.
int Generator::pick_width() {
    const uint32_t r = below(100);
    if (r < 8) return 1;
    if (r < 13) return max_width_ < 2 ? max_width_ : 2;
    if (r < 16) return max_width_;
    const int span = 2 << below(10);  // 2..1024
    return 1 +
           static_cast<int>(below(static_cast<uint32_t>(span < max_width_ ? span : max_width_)));
}

int Generator::pick_height() {
    const uint32_t r = below(100);
    if (r < 8) return 1;
    if (r < 13) return 2;
    return 1 + static_cast<int>(below(1 + below(64)));  // 1..64, small ones more often
}

// Noise, 0/255 (gx and gy reach +-255) or small steps around a level.
uint8_t Generator::pixel() {
    switch (mode_) {
        case 0: return static_cast<uint8_t>(rng_.next() & 0xFF);
        case 1: return (rng_.next() & 1) ? 255 : 0;
        default: return static_cast<uint8_t>(level_ + (rng_.next() & 7));
    }
}

void Generator::beat(SoakStream& s, int x, int y, bool tlast, uint16_t height) {
    InBeat b;
    b.pixel = pixel();
    b.tuser = x == 0 && y == 0;
    b.tlast = tlast;
    b.height = b.tuser ? height : 0;
    s.in.push_back(b);
    ++s.pixels;
}

void Generator::item(SoakStream& s) {
    const uint32_t r = below(100);
    if (r < 5) {  // stray beats: dropped unless a frame is still in progress
        const int n = 1 + static_cast<int>(below(16));
        for (int i = 0; i < n; ++i) {
            InBeat b;
            b.pixel = static_cast<uint8_t>(rng_.next() & 0xFF);
            b.tlast = below(4) == 0;
            s.in.push_back(b);
        }
        ++s.faults[static_cast<int>(SoakFault::stray)];
        return;
    }
    if (r < 7) {  // reset between frames, sometimes twice in a row
        cut(s, SoakFault::reset_between);
        if (below(2)) cut(s, SoakFault::reset_between);
        return;
    }
    frame(s);
}

void Generator::frame(SoakStream& s) {
    const int w = pick_width(), h = pick_height();
    mode_ = static_cast<int>(below(4)) % 3;  // noise twice as often as the others
    level_ = static_cast<uint8_t>(below(249));
    ++s.frames;
    const uint16_t height = static_cast<uint16_t>(h);

    const uint32_t r = below(100);
    // The rows after a faulty beat are sent half of the time: the block must drop them.
    const bool send_rest = below(2) == 0;

    if (r < 5 && h >= 2 && w >= 2) {  // short row y: tlast at column c < W - 1
        const int y = 1 + static_cast<int>(below(static_cast<uint32_t>(h - 1)));
        const int c = static_cast<int>(below(static_cast<uint32_t>(w - 1)));
        const bool reset = below(3) == 0;
        for (int yy = 0; yy < y; ++yy)
            for (int x = 0; x < w; ++x) beat(s, x, yy, x == w - 1, height);
        for (int x = 0; x <= c; ++x) beat(s, x, y, x == c);
        ++s.faults[static_cast<int>(SoakFault::short_row)];
        if (reset) cut(s, SoakFault::reset_after_error, true);
        if (send_rest)
            for (int yy = y + 1; yy < h; ++yy) row(s, yy, w);
        return;
    }
    if (r < 10 && h >= 2) {  // long row y: no tlast at column W - 1, 1..8 extra pixels
        const int y = 1 + static_cast<int>(below(static_cast<uint32_t>(h - 1)));
        const int extra = 1 + static_cast<int>(below(8));
        const bool reset = below(3) == 0;
        for (int yy = 0; yy < y; ++yy)
            for (int x = 0; x < w; ++x) beat(s, x, yy, x == w - 1, height);
        for (int x = 0; x < w; ++x) beat(s, x, y, false);  // column W - 1 is the error
        ++s.faults[static_cast<int>(SoakFault::long_row)];
        if (reset) cut(s, SoakFault::reset_after_error, true);
        for (int x = w; x < w + extra; ++x) beat(s, x, y, x == w + extra - 1);
        if (send_rest)
            for (int yy = y + 1; yy < h; ++yy) row(s, yy, w);
        return;
    }
    if (r < 14 && w * h >= 2) {  // ends early: stops after k of its W*H beats
        const int k = 1 + static_cast<int>(below(static_cast<uint32_t>(w * h - 1)));
        for (int i = 0; i < k; ++i) beat(s, i % w, i / w, i % w == w - 1, height);
        ++s.faults[static_cast<int>(SoakFault::early_end)];
        return;
    }
    if (r < 17) {  // declared height 0: the start beat is an error and dropped, the rest too
        const bool reset = below(3) == 0;
        beat(s, 0, 0, w == 1, 0);
        ++s.faults[static_cast<int>(SoakFault::height_zero)];
        if (reset) cut(s, SoakFault::reset_after_error, true);
        if (send_rest) {
            for (int x = 1; x < w; ++x) beat(s, x, 0, x == w - 1);
            for (int y = 1; y < h; ++y) row(s, y, w);
        }
        return;
    }
    if (r < 19) {  // row 0 without tlast up to column MAX_WIDTH - 1 (the error), then 1..8 more
        const int n = max_width_ + 1 + static_cast<int>(below(8));
        for (int x = 0; x < n; ++x) beat(s, x, 0, x == n - 1, height);
        ++s.faults[static_cast<int>(SoakFault::wide_row0)];
        return;
    }
    const int total = w * h;
    if (r < 23 && total >= 2) {  // reset before beat k of the frame, 1 <= k < W*H:
        // anywhere, in row 0 or right after it (width learnt, nothing emitted), or at the
        // start of a row
        const uint32_t where = below(3);
        int k = 1 + static_cast<int>(below(static_cast<uint32_t>(total - 1)));
        if (where == 1)
            k = 1 + static_cast<int>(below(static_cast<uint32_t>(w < total - 1 ? w : total - 1)));
        else if (where == 2 && h >= 2)
            k = w * (1 + static_cast<int>(below(static_cast<uint32_t>(h - 1))));
        for (int i = 0; i < total; ++i) {
            if (i == k) cut(s, SoakFault::reset_mid);
            beat(s, i % w, i / w, i % w == w - 1, height);
        }
        return;
    }
    if (r < 26 && w >= 2) {  // reset inside the last row: before its column c, 1 <= c < W
        const int c = 1 + static_cast<int>(below(static_cast<uint32_t>(w - 1)));
        for (int i = 0; i < total; ++i) {
            if (i == (h - 1) * w + c) cut(s, SoakFault::reset_last_row);
            beat(s, i % w, i / w, i % w == w - 1, height);
        }
        return;
    }
    const size_t first = s.in.size();
    for (int i = 0; i < total; ++i) beat(s, i % w, i / w, i % w == w - 1, height);
    if (r < 29) {  // reset while the block flushes the last row
        cut(s, SoakFault::reset_flush);
        return;
    }
    ++s.clean_frames;
    clean_.push_back(CleanFrame{first, w, h});
}

// Every kind that frames up to max_width pixels wide can have (a one-pixel row cannot end early).
bool every_kind(const SoakStream& s, int max_width) {
    for (int k = 0; k < kSoakFaultKinds; ++k) {
        const auto kind = static_cast<SoakFault>(k);
        if (max_width < 2 && (kind == SoakFault::short_row || kind == SoakFault::reset_last_row))
            continue;
        if (s.faults[k] == 0) return false;
    }
    return true;
}

}  // namespace

Expected expected_outputs(const std::vector<InBeat>& in, const std::vector<size_t>& reset_before,
                          int max_width, uint16_t threshold, bool per_frame_threshold) {
    Expected e;
    FrontModel model(max_width, threshold, per_frame_threshold);
    int errors_before = 0;  // errors of the models of finished segments
    size_t c = 0;
    e.out.reserve(in.size());
    for (size_t i = 0; i <= in.size(); ++i) {
        for (; c < reset_before.size() && reset_before[c] == i; ++c) {
            errors_before += model.errors();
            e.resets.push_back(ResetPoint{
                static_cast<uint32_t>(i), static_cast<uint32_t>(e.out.size()),
                static_cast<uint32_t>(e.edges.size()), static_cast<uint32_t>(errors_before)});
            model = FrontModel(max_width, threshold, per_frame_threshold);
        }
        if (i == in.size()) break;
        model.push(in[i], e.out, e.edges);
    }
    e.errors = errors_before + model.errors();
    return e;
}

SoakStream make_soak_stream(uint64_t seed, uint64_t pixels, int max_width) {
    SoakStream s;
    s.threshold = static_cast<uint16_t>(1 + Pcg32(seed ^ 0x7468726573686f6cULL).below(128));
    Generator gen(seed, max_width);
    while (s.in.size() < pixels || !every_kind(s, max_width)) gen.item(s);

    // A reset placed right after an error must really follow one: the gradient model alone,
    // segment by segment, says which beats are errors.
    std::vector<size_t> points;
    {
        GradientModel model(max_width);
        std::vector<OutBeat> scratch;
        bool last_beat_error = false;
        size_t c = 0;
        const std::vector<Cut>& cuts = gen.cuts();
        for (size_t i = 0; i <= s.in.size(); ++i) {
            for (; c < cuts.size() && cuts[c].in_beat == i; ++c) {
                if (cuts[c].after_error && !last_beat_error)
                    throw std::logic_error("soak stream: reset " + std::to_string(c) +
                                           " is not right after an error");
                points.push_back(i);
                model = GradientModel(max_width);
                last_beat_error = false;
            }
            if (i == s.in.size()) break;
            const int before = model.errors();
            scratch.clear();
            model.push(s.in[i], scratch);
            last_beat_error = model.errors() != before;
        }
    }
    s.expected = expected_outputs(s.in, points, max_width, s.threshold, true);

    // core = model on every clean frame small enough for core's list here.
    for (const CleanFrame& f : gen.clean()) {
        io::GreyImage img(f.width, f.height);
        for (int i = 0; i < f.width * f.height; ++i)
            img.pixels[static_cast<size_t>(i)] = s.in[f.first_beat + static_cast<size_t>(i)].pixel;
        FrontModel model(max_width, s.threshold, true);
        std::vector<OutBeat> words;
        std::vector<EdgeOutBeat> edges;
        for (int i = 0; i < f.width * f.height; ++i)
            model.push(s.in[f.first_beat + static_cast<size_t>(i)], words, edges);
        std::vector<edge_beat> core;
        std::string why;
        if (words.empty() ||
            !core_edge_beats(img, frame_threshold(s.threshold, words.front().word), core, why))
            continue;
        size_t i = 0;
        while (i < edges.size() && i < core.size() && edges[i].data == core[i]) ++i;
        if (i != edges.size() || i != core.size())
            throw std::logic_error("soak stream: core's edges of the clean " +
                                   std::to_string(f.width) + "x" + std::to_string(f.height) +
                                   " frame at input beat " + std::to_string(f.first_beat) +
                                   " differ from the model's at beat " + std::to_string(i));
        ++s.core_frames;
    }
    return s;
}

}  // namespace qt::vec
