// The target pipeline's result for one frame as one line of text, written alike by the firmware
// (target_bench.cpp) and by the host program that computes the expected text
// (target_expected_main.cpp): the ctest compares the two byte for byte. Every float is written
// twice: rounded to 1/1000 (for a reader) and as its IEEE-754 bit pattern in hex (so that equal
// text means equal numbers, not merely close ones). Header-only, no heap, no printf: the
// firmware links no formatted output.
//
//   NAME status=ok started=0 tracking=1 state=measured x=161.508:4321821a y=... unseen=0
//     features=96 matches=71 inliers=64 iterations=9 geometry=ok rep=0.213:3e5a1cac
//     h=3f800000,...(9) window=161.2:...,120.1:...,4.000:... hit=1,41344,30776,32101,81
// (one line; hit = found, x and y in 1/256 px, NCC score Q15, candidate centres scored).
#pragma once
#include <stdint.h>
#include <string.h>

#include "base/status.h"
#include "target/float/target_pipeline.h"

namespace qt::fw {

// A line buffer with append operations; the caller hands text() to its sink.
class TextLine {
public:
    void text(const char* s) {
        while (*s != 0 && n_ + 1 < sizeof buf_) buf_[n_++] = *s++;
        buf_[n_] = 0;
    }
    void dec(int64_t v) {
        char digits[24];
        int k = 0;
        // Magnitude as unsigned: -v would overflow for INT64_MIN.
        uint64_t m = v < 0 ? 0u - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
        do {
            digits[k++] = static_cast<char>('0' + m % 10);
            m /= 10;
        } while (m != 0);
        if (v < 0) text("-");
        char out[24];
        for (int i = 0; i < k; ++i) out[i] = digits[k - 1 - i];
        out[k] = 0;
        text(out);
    }
    void hex(uint32_t v) {
        char out[9];
        for (int i = 0; i < 8; ++i) out[i] = "0123456789abcdef"[(v >> (28 - 4 * i)) & 0xfu];
        out[8] = 0;
        text(out);
    }
    // v rounded to 1/1000 (half away from zero) when |v| < 10^6, else "big"; then ':' and the
    // bits. The rounding is one float multiply and add, the same on every IEEE-754 target.
    void real(float v) {
        if (v > -1.0e6f && v < 1.0e6f) {
            const float scaled = v * 1000.0f;
            const int64_t milli = static_cast<int64_t>(scaled < 0 ? scaled - 0.5f : scaled + 0.5f);
            const uint64_t m =
                milli < 0 ? 0u - static_cast<uint64_t>(milli) : static_cast<uint64_t>(milli);
            if (milli < 0) text("-");
            dec(static_cast<int64_t>(m / 1000));
            text(".");
            const uint64_t frac = m % 1000;
            text(frac < 10 ? "00" : frac < 100 ? "0" : "");
            dec(static_cast<int64_t>(frac));
        } else {
            text("big");
        }
        text(":");
        uint32_t bits;
        memcpy(&bits, &v, sizeof bits);
        hex(bits);
    }
    void field(const char* name) {
        text(" ");
        text(name);
        text("=");
    }
    const char* str() const { return buf_; }

private:
    char buf_[512] = {};
    unsigned n_ = 0;
};

// Writes "NAME status=... ...\n" through sink(const char*).
template <class Sink>
void write_target_text(const char* name, Status status, const TargetFrame& f, Sink&& sink) {
    TextLine t;
    t.text(name);
    t.field("status");
    t.text(status_name(status));
    t.field("started");
    t.dec(f.started ? 1 : 0);
    t.field("tracking");
    t.dec(f.tracking ? 1 : 0);
    t.field("state");
    t.text(target_state_name(f.estimate.state));
    t.field("x");
    t.real(f.estimate.x);
    t.field("y");
    t.real(f.estimate.y);
    t.field("unseen");
    t.dec(f.estimate.unseen);
    t.field("features");
    t.dec(f.features);
    sink(t.str());

    TextLine g;
    g.field("matches");
    g.dec(f.geometry.matches);
    g.field("inliers");
    g.dec(f.geometry.ransac.inliers);
    g.field("iterations");
    g.dec(f.geometry.ransac.iterations);
    g.field("geometry");
    g.text(homography_status_name(f.geometry.ransac.status));
    g.field("rep");
    g.real(f.geometry.ransac.reprojection_px);
    g.field("h");
    for (int i = 0; i < 9; ++i) {
        uint32_t bits;
        memcpy(&bits, &f.geometry.ransac.h.m[i], sizeof bits);
        if (i > 0) g.text(",");
        g.hex(bits);
    }
    sink(g.str());

    TextLine w;
    w.field("window");
    w.real(f.window.x);
    w.text(",");
    w.real(f.window.y);
    w.text(",");
    w.real(f.window.radius);
    w.field("hit");
    w.dec(f.hit.found ? 1 : 0);
    w.text(",");
    w.dec(f.hit.x_q8);
    w.text(",");
    w.dec(f.hit.y_q8);
    w.text(",");
    w.dec(f.hit.score_q15);
    w.text(",");
    w.dec(f.hit.positions);
    w.text("\n");
    sink(w.str());
}

}  // namespace qt::fw
