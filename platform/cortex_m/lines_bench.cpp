// Scene check and benchmark of qt::LineDetectorQvga on the Cortex-M4 (QEMU).
//
// For each scene in QT_SCENES (platform/cortex_m/CMakeLists.txt): parse the linked-in binary
// PGM (P5, maxval 255), feed its rows one by one from flash into a static detector with the
// default LineParams, as a camera would, then finish(). Print the frame's text as the host
// writes it (core/line_text.h: header + one line per detected line) and compare it byte for
// byte with the linked-in vectors/scenes/<name>.lines.txt. Exit status 0 only if every frame
// matches.
//
// Timing, in SysTick ticks, 40 instructions each under -icount shift=0 (cycle_counter.h):
//   gradient_edges  all push_row calls of the frame, one reading around the row loop
//   hough_cluster   finish(): PPHT, clustering and joining line ends at corners
//   cluster         cluster_segments() + join_corners() run again, outside the detector, on
//                   the detector's own segments and parameters (same input, same code, so the
//                   same work; its output must equal det.lines()); hough = hough_cluster - cluster.
// finish() cannot be split from outside without changing core/ (the accumulator is private
// and PPHT consumes the edge list), hence the re-run. Each reading is quantised to 40
// instructions and includes one ticks_now() pair (a few tens of instructions).
#include <stdint.h>

#include "cycle_counter.h"
#include "line_cluster.h"
#include "line_detector.h"
#include "line_text.h"
#include "semihosting.h"
#include "stack_usage.h"

// Each scene X-macro: QT_SCENE(identifier); vector_blob.S links <identifier>.pgm as
// qt_scene_<identifier>_pgm_begin/_end and <identifier>.lines.txt as ..._txt_begin/_end.
#ifndef QT_SCENES
#error "QT_SCENES must list the scenes (platform/cortex_m/CMakeLists.txt)"
#endif

#define QT_SCENE(id)                                                                  \
    extern "C" const uint8_t qt_scene_##id##_pgm_begin[], qt_scene_##id##_pgm_end[], \
        qt_scene_##id##_txt_begin[], qt_scene_##id##_txt_end[];
QT_SCENES
#undef QT_SCENE

namespace {

constexpr uint16_t kMaxWidth = 320, kMaxHeight = 240;  // LineDetectorQvga's capacity
constexpr uint16_t kMaxLines = 32;                     // its line capacity

struct Scene {
    const char* name;
    const uint8_t* pgm_begin;
    const uint8_t* pgm_end;
    const uint8_t* txt_begin;
    const uint8_t* txt_end;
};

#define QT_SCENE(id) \
    {#id, qt_scene_##id##_pgm_begin, qt_scene_##id##_pgm_end, qt_scene_##id##_txt_begin, qt_scene_##id##_txt_end},
constexpr Scene kScenes[] = {QT_SCENES};
#undef QT_SCENE

// --- PGM ---------------------------------------------------------------------------------
// Binary greymap (netpbm P5): "P5", width, height, maxval as decimal ASCII separated by
// whitespace (and '#' comments to the end of a line), exactly one whitespace character, then
// width × height bytes and nothing after them. Only maxval 255 (one byte per pixel), and
// only sizes the detector can take.
struct Pgm {
    const char* error = nullptr;  // why the file was rejected, or nullptr
    const uint8_t* raster = nullptr;
    uint16_t width = 0, height = 0;
};

bool is_space(uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// Skips whitespace and comments; false if there was none (a token must follow whitespace).
bool skip_separator(const uint8_t*& p, const uint8_t* end) {
    const uint8_t* start = p;
    while (p != end) {
        if (is_space(*p)) {
            ++p;
        } else if (*p == '#') {
            while (p != end && *p != '\n' && *p != '\r') ++p;
        } else {
            break;
        }
    }
    return p != start;
}

// A decimal number of 1..5 digits, not followed by another digit.
bool parse_number(const uint8_t*& p, const uint8_t* end, uint32_t& value) {
    value = 0;
    unsigned digits = 0;
    while (p != end && *p >= '0' && *p <= '9') {
        if (++digits > 5) return false;
        value = value * 10u + static_cast<uint32_t>(*p - '0');
        ++p;
    }
    return digits != 0;
}

Pgm parse_pgm(const uint8_t* p, const uint8_t* end) {
    Pgm pgm;
    uint32_t width = 0, height = 0, maxval = 0;
    if (end - p < 2 || p[0] != 'P' || p[1] != '5') {
        pgm.error = "not a binary PGM (magic P5)";
        return pgm;
    }
    p += 2;
    if (!skip_separator(p, end) || !parse_number(p, end, width)) {
        pgm.error = "bad width";
        return pgm;
    }
    if (!skip_separator(p, end) || !parse_number(p, end, height)) {
        pgm.error = "bad height";
        return pgm;
    }
    if (!skip_separator(p, end) || !parse_number(p, end, maxval)) {
        pgm.error = "bad maxval";
        return pgm;
    }
    if (maxval != 255) {
        pgm.error = "maxval is not 255";
        return pgm;
    }
    if (p == end || !is_space(*p)) {
        pgm.error = "no whitespace after maxval";
        return pgm;
    }
    ++p;  // exactly one: the raster may start with a byte that looks like whitespace
    if (width == 0 || height == 0 || width > kMaxWidth || height > kMaxHeight) {
        pgm.error = "size outside 1x1..320x240";
        return pgm;
    }
    if (static_cast<uint32_t>(end - p) != width * height) {
        pgm.error = "raster is not width x height bytes";
        return pgm;
    }
    pgm.raster = p;
    pgm.width = static_cast<uint16_t>(width);
    pgm.height = static_cast<uint16_t>(height);
    return pgm;
}

// The parser against small headers, good and bad: (text, accepted?).
struct PgmCheck {
    const char* text;
    bool accept;
};
constexpr PgmCheck kPgmChecks[] = {
    {"P5\n2 2\n255\nabcd", true},
    {"P5 2 2 255 \n\n\n\n", true},               // raster bytes that look like whitespace
    {"P5\n# comment\n2\t2 # more\n255\rabcd", true},
    {"P2\n2 2\n255\nabcd", false},              // ASCII greymap
    {"P52 2\n255\nabcd", false},                // no separator after the magic
    {"P5\n2 2\n65535\nabcdefgh", false},        // two bytes per pixel
    {"P5\n2 2\n127\nabcd", false},
    {"P5\n2 2\n255abcd", false},                // no whitespace before the raster
    {"P5\n2 2\n255\n\nabcd", false},            // two: the raster would be 5 bytes
    {"P5\n2 2\n255\nabc", false},               // short raster
    {"P5\n2 2\n255\nabcde", false},             // trailing byte
    {"P5\n0 2\n255\n", false},
    {"P5\n321 1\n255\n", false},                // wider than the detector
    {"P5\n2 -2\n255\nabcd", false},
    {"P5\n2 2", false},
    {"", false},
};

size_t text_length(const char* s) {
    size_t n = 0;
    while (s[n] != 0) ++n;
    return n;
}

// Runs kPgmChecks; prints each failure. Returns the number that failed.
unsigned check_pgm_parser() {
    unsigned failed = 0;
    for (const PgmCheck& c : kPgmChecks) {
        const uint8_t* p = reinterpret_cast<const uint8_t*>(c.text);
        const Pgm pgm = parse_pgm(p, p + text_length(c.text));
        if ((pgm.error == nullptr) != c.accept) {
            ++failed;
            sh_write("pgm parser FAIL: ");
            sh_write(c.accept ? "rejected a good header: " : "accepted a bad header\n");
            if (c.accept) {
                sh_write(pgm.error);
                sh_write("\n");
            }
        }
    }
    return failed;
}

// --- Text comparison ------------------------------------------------------------------------
// Walks the expected text alongside the produced lines, remembering the first difference.
struct TextCompare {
    const uint8_t* cursor;
    const uint8_t* end;
    uint32_t line = 0;        // lines compared so far
    uint32_t bad_line = 0;    // 1-based line of the first difference, 0 if none
    uint32_t bad_column = 0;  // 1-based byte within that line
    char got[qt::kLineTextMax] = {};
    char expected[qt::kLineTextMax] = {};  // that expected line, cut at its newline

    TextCompare(const uint8_t* begin, const uint8_t* end_) : cursor(begin), end(end_) {}

    void add(const char* text, size_t length) {
        ++line;
        const uint8_t* line_start = cursor;
        size_t i = 0;
        while (i < length && cursor != end && static_cast<uint8_t>(text[i]) == *cursor) {
            ++i;
            ++cursor;
        }
        if (i == length || bad_line != 0) return;
        bad_line = line;
        bad_column = static_cast<uint32_t>(i + 1);
        copy_line(text, got);
        copy_expected(line_start);
        cursor = end;  // compare nothing after the first difference
    }

    // After the last line: anything left in the expected text is a difference too.
    void finish() {
        if (bad_line != 0 || cursor == end) return;
        bad_line = line + 1;
        bad_column = 1;
        got[0] = 0;
        copy_expected(cursor);
    }

    bool equal() const { return bad_line == 0; }

private:
    static void copy_line(const char* s, char* out) {
        size_t n = 0;
        while (n + 1 < qt::kLineTextMax && s[n] != 0 && s[n] != '\n') out[n] = s[n], ++n;
        out[n] = 0;
    }
    void copy_expected(const uint8_t* p) {
        size_t n = 0;
        while (n + 1 < qt::kLineTextMax && p != end && *p != '\n') expected[n++] = static_cast<char>(*p++);
        expected[n] = 0;
    }
};

// --- The frames -------------------------------------------------------------------------------
qt::LineDetectorQvga g_det;  // ~44 KiB, in .bss
const qt::LineParams kParams{};

// Output of the clustering re-run (timing only; must equal g_det.lines()).
qt::Segment g_cluster_lines[kMaxLines];
uint8_t g_cluster_scratch[64];  // LineDetectorQvga's MaxSegments
qt::CornerCandidate g_corner_scratch[2 * kMaxLines];

struct Result {
    const char* error = nullptr;  // why the frame could not be run, or nullptr
    bool text_equal = false;
    uint64_t gradient_edges_ticks = 0, hough_cluster_ticks = 0, cluster_ticks = 0;
};

Result failed(Result r, const char* why) {
    r.error = why;
    return r;
}

bool same_segment(const qt::Segment& a, const qt::Segment& b) {
    return a.x1.raw == b.x1.raw && a.y1.raw == b.y1.raw && a.x2.raw == b.x2.raw &&
           a.y2.raw == b.y2.raw && a.rho.raw == b.rho.raw && a.theta == b.theta &&
           a.cx.raw == b.cx.raw && a.cy.raw == b.cy.raw && a.points == b.points;
}

Result run_scene(const Scene& scene, bool& frame_open) {
    Result r;
    const Pgm pgm = parse_pgm(scene.pgm_begin, scene.pgm_end);
    if (pgm.error != nullptr) return failed(r, pgm.error);

    // A frame left open by an earlier failed scene is no fault of this one.
    qt::Status s = g_det.begin_frame(pgm.width, pgm.height, kParams);
    if (s == qt::Status::previous_frame_incomplete && frame_open) s = qt::Status::ok;
    if (s != qt::Status::ok) return failed(r, qt::status_name(s));
    frame_open = true;

    const uint8_t* row = pgm.raster;
    const uint64_t t0 = ticks_now();
    for (uint16_t y = 0; y < pgm.height && s == qt::Status::ok; ++y, row += pgm.width)
        s = g_det.push_row(row, pgm.width);
    const uint64_t t1 = ticks_now();
    if (s != qt::Status::ok) return failed(r, qt::status_name(s));
    s = g_det.finish();
    const uint64_t t2 = ticks_now();
    if (s != qt::Status::ok) return failed(r, qt::status_name(s));
    frame_open = false;

    uint16_t count = 0;
    qt::ClusterStats cluster_stats;
    const uint64_t t3 = ticks_now();
    s = qt::cluster_segments(g_det.segments(), g_det.segment_count(), kParams.cluster,
                             g_cluster_scratch, g_cluster_lines, kMaxLines, &count, &cluster_stats);
    if (s == qt::Status::ok) qt::join_corners(g_cluster_lines, count, kParams.corners, g_corner_scratch);
    const uint64_t t4 = ticks_now();
    if (s != qt::Status::ok) return failed(r, qt::status_name(s));
    if (count != g_det.line_count()) return failed(r, "clustering re-run: different line count");
    for (uint16_t i = 0; i < count; ++i)
        if (!same_segment(g_cluster_lines[i], g_det.lines()[i]))
            return failed(r, "clustering re-run: different lines");

    r.gradient_edges_ticks = t1 - t0;
    r.hough_cluster_ticks = t2 - t1;
    r.cluster_ticks = t4 - t3;

    // The frame's text, printed and compared with the host's.
    TextCompare cmp(scene.txt_begin, scene.txt_end);
    char text[qt::kLineTextMax];
    size_t n = qt::format_frame_header(scene.name, g_det.stats().edges, g_det.segment_count(),
                                       g_det.line_count(), text);
    sh_write(text);
    cmp.add(text, n);
    for (uint16_t i = 0; i < g_det.line_count(); ++i) {
        n = qt::format_line_text(g_det.lines()[i], text);
        sh_write(text);
        cmp.add(text, n);
    }
    cmp.finish();
    r.text_equal = cmp.equal();
    if (!r.text_equal) {
        sh_write("lines ");
        sh_write(scene.name);
        sh_write(" text differs from ");
        sh_write(scene.name);
        sh_write(".lines.txt at line ");
        sh_dec(cmp.bad_line);
        sh_write(" byte ");
        sh_dec(cmp.bad_column);
        sh_write("\n  firmware: ");
        sh_write(cmp.got[0] != 0 ? cmp.got : "(no line)");
        sh_write("\n  expected: ");
        sh_write(cmp.expected[0] != 0 ? cmp.expected : "(no line)");
        sh_write("\n");
    }
    return r;
}

void print_figure(const char* name, uint64_t ticks) {
    sh_write(" ");
    sh_write(name);
    sh_write("=");
    sh_dec(ticks_to_instructions(ticks));
}

void print_bytes(const char* name, uint32_t bytes) {
    sh_write(" ");
    sh_write(name);
    sh_write("=");
    sh_dec(bytes);
}

}  // namespace

int main() {
    cycle_counter_init();
    const unsigned parser_failures = check_pgm_parser();
    sh_write("pgm parser: ");
    sh_dec(sizeof kPgmChecks / sizeof kPgmChecks[0] - parser_failures);
    sh_write(" of ");
    sh_dec(sizeof kPgmChecks / sizeof kPgmChecks[0]);
    sh_write(" header checks as expected\n");

    unsigned passed = 0;
    constexpr unsigned kCount = sizeof kScenes / sizeof kScenes[0];
    bool frame_open = false;
    for (const Scene& scene : kScenes) {
        const Result r = run_scene(scene, frame_open);
        const bool pass = r.error == nullptr && r.text_equal;
        passed += pass ? 1u : 0u;
        sh_write("lines ");
        sh_write(scene.name);
        sh_write(pass ? " PASS" : " FAIL");
        if (r.error != nullptr) {
            sh_write(" error: ");
            sh_write(r.error);
        }
        sh_write("\n");
        if (r.error != nullptr) continue;

        sh_write("lines ");
        sh_write(scene.name);
        print_figure("instr_gradient_edges", r.gradient_edges_ticks);
        print_figure("instr_hough_cluster", r.hough_cluster_ticks);
        print_figure("instr_hough", r.hough_cluster_ticks - r.cluster_ticks);
        print_figure("instr_cluster", r.cluster_ticks);
        print_figure("instr_total", r.gradient_edges_ticks + r.hough_cluster_ticks);
        print_bytes("edges", g_det.stats().edges);
        print_bytes("segments", g_det.segment_count());
        print_bytes("lines", g_det.line_count());
        sh_write("\n");
    }

    using Det = qt::LineDetectorQvga;
    sh_write("ram LineDetectorQvga");
    print_bytes("sizeof", sizeof g_det);
    print_bytes("ram_bytes", Det::ram_bytes());
    print_bytes("gradient", Det::gradient_bytes());
    print_bytes("edge_stage", Det::edge_stage_bytes());
    print_bytes("edge_list", Det::edge_list_bytes());
    print_bytes("accumulator", Det::accumulator_bytes());
    print_bytes("line_list", Det::line_list_bytes());
    print_bytes("other", Det::ram_bytes() - Det::gradient_bytes() - Det::edge_stage_bytes() -
                             Det::edge_list_bytes() - Det::accumulator_bytes() - Det::line_list_bytes());
    sh_write("\nram bench_only");
    print_bytes("cluster_rerun", sizeof g_cluster_lines + sizeof g_cluster_scratch + sizeof g_corner_scratch);
    sh_write("\nlines: ");
    if (passed == kCount && parser_failures == 0) {
        sh_write("all ");
        sh_dec(kCount);
        sh_write(" frames PASS");
    } else {
        sh_dec(kCount - passed);
        sh_write(" of ");
        sh_dec(kCount);
        sh_write(" frames FAIL");
        if (parser_failures != 0) sh_write(", pgm parser FAIL");
    }
    sh_write("; stack peak ");
    sh_dec(stack_peak_bytes());
    sh_write(" of ");
    sh_dec(stack_size_bytes());
    sh_write(" bytes\n");
    return passed == kCount && parser_failures == 0 ? 0 : 1;
}
