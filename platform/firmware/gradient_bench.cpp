// Golden-vector check and benchmark of qt::GradientStage<640> on the Cortex-M4 (QEMU).
//
// For each case in QT_GRADIENT_CASES (from vectors/gradient/manifest.txt, CMakeLists.txt):
// parse the linked-in .in.hex beats row by row, as a camera delivers them, push each row
// into the stage, format every output word as its .out.hex line, and FNV-1a-hash the
// .in.hex bytes followed by that text. The hash must equal the manifest's. Only push_row
// is timed (minus the time spent hashing inside the sink), in SysTick ticks, 40
// instructions each under -icount shift=0. Exit status 0 only if every case passes.
// Each reading is quantised to 40 instructions (unbiased over many rows), and the timing
// calls themselves leave about 58 instructions per push_row in the figure (measured with an
// empty stage): +0.1 instr/pixel at 640 wide, +0.9 at 64 wide; tiny frames are dominated by it.
#include <stdint.h>

#include "cycle_counter.h"
#include "gradient/gradient_stage.h"
#include "semihosting.h"
#include "stack_usage.h"

// Each case X-macro: QT_CASE(identifier, "WxH[+WxH...]", fnv1a64); the blobs come from
// vector_blob.S as qt_vec_<identifier>_begin/_end.
#ifndef QT_GRADIENT_CASES
#error "QT_GRADIENT_CASES must list the vector cases (platform/firmware/CMakeLists.txt)"
#endif

#define QT_CASE(id, sizes, hash) \
    extern "C" const uint8_t qt_vec_##id##_begin[], qt_vec_##id##_end[];
QT_GRADIENT_CASES
#undef QT_CASE

namespace {

constexpr uint16_t kMaxWidth = 640;  // the stage's capacity in pixels per row

struct Case {
    const char* name;
    const char* sizes;
    const uint8_t* in_begin;
    const uint8_t* in_end;
    uint64_t expected_hash;
};

#define QT_CASE(id, sizes, hash) {#id, sizes, qt_vec_##id##_begin, qt_vec_##id##_end, hash},
constexpr Case kCases[] = {QT_GRADIENT_CASES};
#undef QT_CASE

// FNV-1a, 64-bit (docs/gradient.md manifest).
struct Fnv1a64 {
    uint64_t h = 0xcbf29ce484222325ULL;
    void add(uint8_t b) {
        h ^= b;
        h *= 0x100000001b3ULL;
    }
};

// One .in.hex beat: 7 lower-case hex digits {height[15:0], tlast, tuser, pixel[7:0]} + '\n'.
constexpr unsigned kBeatChars = 8;
struct Beat {
    uint8_t pixel;
    bool tuser, tlast;
    uint16_t height;
};

bool parse_beat(const uint8_t* p, Beat& beat) {
    uint32_t v = 0;
    for (unsigned i = 0; i < kBeatChars - 1; ++i) {
        const uint8_t c = p[i];
        uint32_t d;
        if (c >= '0' && c <= '9')
            d = static_cast<uint32_t>(c - '0');
        else if (c >= 'a' && c <= 'f')
            d = static_cast<uint32_t>(c - 'a' + 10);
        else
            return false;
        v = (v << 4) | d;
    }
    if (p[kBeatChars - 1] != '\n' || (v >> 26) != 0) return false;
    beat = {static_cast<uint8_t>(v), ((v >> 8) & 1u) != 0, ((v >> 9) & 1u) != 0,
            static_cast<uint16_t>(v >> 10)};
    return true;
}

// One .out.hex line: 9 lower-case hex digits {eof, tlast, tuser, word[31:0]} + '\n', hashed
// character by character without building the text (eof: the frame's last word).
void hash_out_line(Fnv1a64& hash, qt::gradient_word word, bool tuser, bool tlast, bool eof) {
    static constexpr char kHex[] = "0123456789abcdef";
    hash.add(static_cast<uint8_t>(kHex[(eof ? 4u : 0u) | (tlast ? 2u : 0u) | (tuser ? 1u : 0u)]));
    for (int shift = 28; shift >= 0; shift -= 4)
        hash.add(static_cast<uint8_t>(kHex[(word >> shift) & 15u]));
    hash.add('\n');
}

struct Result {
    const char* error = nullptr;  // why the stream could not be run, or nullptr
    uint64_t hash = 0;
    uint64_t pixels = 0;       // gradient words produced
    uint64_t stage_ticks = 0;  // in push_row, excluding the sink's hashing
};

qt::GradientStage<kMaxWidth> g_stage;  // 6·640 bytes of line and output buffers, in .bss
uint8_t g_row[kMaxWidth];              // the row being received from the "camera"

Result failed(Result r, const char* why) {
    r.error = why;
    return r;
}

Result run_case(const Case& c) {
    Result r;
    Fnv1a64 hash;
    for (const uint8_t* p = c.in_begin; p != c.in_end; ++p) hash.add(*p);

    uint64_t sink_ticks = 0;
    uint16_t frame_height = 0;  // rows of the frame in progress
    auto sink = [&](uint16_t y, const qt::gradient_word* words, uint16_t width) {
        const uint64_t t0 = ticks_now();
        for (uint16_t x = 0; x < width; ++x) {
            const bool last = x + 1u == width;
            hash_out_line(hash, words[x], y == 0 && x == 0, last, last && y + 1u == frame_height);
        }
        r.pixels += width;
        sink_ticks += ticks_now() - t0;
    };

    const uint8_t* p = c.in_begin;
    bool first_row = true;
    while (p != c.in_end) {
        // Receive one row: beats up to and including the one with tlast.
        uint16_t length = 0;
        bool start_of_frame = false, end_of_row = false;
        uint16_t height = 0;
        while (!end_of_row) {
            Beat b;
            if (static_cast<unsigned>(c.in_end - p) < kBeatChars)
                return failed(r, "truncated beat");
            if (!parse_beat(p, b)) return failed(r, "malformed beat");
            p += kBeatChars;
            if (length == kMaxWidth) return failed(r, "row wider than 640");
            if (b.tuser) {
                if (length != 0) return failed(r, "start of frame inside a row");
                start_of_frame = true;
                height = b.height;
            }
            g_row[length++] = b.pixel;
            end_of_row = b.tlast;
        }
        if (start_of_frame) {
            // A frame left open by an earlier failed case is no fault of this one.
            frame_height = height;
            const qt::Status s = g_stage.begin_frame(length, height);
            const bool leftover = s == qt::Status::previous_frame_incomplete && first_row;
            if (s != qt::Status::ok && !leftover) return failed(r, qt::status_name(s));
        }
        first_row = false;

        const uint64_t t0 = ticks_now();
        const qt::Status s = g_stage.push_row(g_row, length, sink);
        r.stage_ticks += ticks_now() - t0;
        if (s != qt::Status::ok) return failed(r, qt::status_name(s));
    }
    if (g_stage.in_frame()) return failed(r, "stream ended inside a frame");
    r.stage_ticks -= sink_ticks;
    r.hash = hash.h;
    return r;
}

// Instructions per pixel in tenths, rounded: ticks · 40 · 10 / pixels.
void print_per_pixel(uint64_t ticks, uint64_t pixels) {
    const uint64_t tenths = (ticks_to_instructions(ticks) * 10u + pixels / 2u) / pixels;
    sh_dec(tenths / 10u);
    sh_putc('.');
    sh_dec(tenths % 10u);
}

}  // namespace

int main() {
    cycle_counter_init();
    unsigned passed = 0;
    constexpr unsigned kCount = sizeof kCases / sizeof kCases[0];
    for (const Case& c : kCases) {
        const Result r = run_case(c);
        const bool pass = r.error == nullptr && r.hash == c.expected_hash;
        passed += pass ? 1u : 0u;
        sh_write("gradient ");
        sh_write(c.name);
        sh_write(" ");
        sh_write(c.sizes);
        sh_write(" hash=");
        sh_hex(r.hash, 16);
        sh_write(pass ? " PASS" : " FAIL");
        if (r.error != nullptr) {
            sh_write(" error: ");
            sh_write(r.error);
        } else if (!pass) {
            sh_write(" expected=");
            sh_hex(c.expected_hash, 16);
        }
        if (r.pixels != 0) {
            sh_write(" instr_per_pixel=");
            print_per_pixel(r.stage_ticks, r.pixels);
        }
        sh_write("\n");
    }
    sh_write("gradient: ");
    if (passed == kCount) {
        sh_write("all ");
        sh_dec(kCount);
        sh_write(" cases PASS");
    } else {
        sh_dec(kCount - passed);
        sh_write(" of ");
        sh_dec(kCount);
        sh_write(" cases FAIL");
    }
    sh_write("; stack peak ");
    sh_dec(stack_peak_bytes());
    sh_write(" of ");
    sh_dec(stack_size_bytes());
    sh_write(" bytes; GradientStage<640> ");
    sh_dec(sizeof g_stage);
    sh_write(" bytes + row buffer ");
    sh_dec(sizeof g_row);
    sh_write(" bytes\n");
    return passed == kCount ? 0 : 1;
}
