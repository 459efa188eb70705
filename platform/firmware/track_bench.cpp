// Instruction count and host cross-check of qt::LineTracker on the Cortex-M4 (QEMU).
//
// For each configuration of track_sequence.h (closest-point model with 1, 2 and 3 filters, turn
// model): generate the synthetic line motion of track_sequence.h on the target (fixed point, no
// float), init() on frame 0, then track kTrackFrames frames with predict(), line(),
// update(measured) (track_step). Print the instructions per line per frame, sizeof(LineTracker),
// the frame rate that implies for a quadrangle (4 lines) on a 100 MHz core at one instruction
// per cycle, and the checksum of every line() result, compared with the host's:
// QT_TRACK_EXPECTED comes from track_expected.h, written at build time by a host program
// running the same track_sequence.h on the build machine (platform/firmware/CMakeLists.txt).
// Exit status 0 only if every checksum matches.
//
// Timing, in SysTick ticks, 40 instructions each under -icount shift=0 (cycle_counter.h): one
// reading around the loop of kTrackFrames frames. The measurements are generated before it, so
// the count is predict() + line() + update() plus the loop's own few instructions per frame
// (index, storing rho and theta) and one ticks_now() pair (a few tens of instructions) per
// kTrackFrames frames; the 40-instruction quantum is spread over kTrackFrames frames too.
#include <stdint.h>

#include "cycle_counter.h"
#include "semihosting.h"
#include "stack_usage.h"
#include "track_expected.h"  // generated: #define QT_TRACK_EXPECTED {{"1KF", 0x...u}, ...}
#include "track_sequence.h"
#include "tracking/line_tracker.h"

namespace {

struct Expected {
    const char* name;
    uint32_t checksum;
};
constexpr Expected kExpected[] = QT_TRACK_EXPECTED;
static_assert(sizeof kExpected / sizeof kExpected[0] == qt::kTrackCaseCount,
              "track_expected.h must hold one checksum per track case");

constexpr uint32_t kClockHz = 100000000u;  // the core the frame rate is quoted for
constexpr uint32_t kQuadLines = 4;

// The measurements of frames 0 .. kTrackFrames, and rho/theta of each tracked frame's line().
qt::Segment g_measured[qt::kTrackFrames + 1];
int32_t g_rho[qt::kTrackFrames];
qt::angle_t g_theta[qt::kTrackFrames];

bool same_text(const char* a, const char* b) {
    while (*a != 0 && *a == *b) ++a, ++b;
    return *a == *b;
}

struct Result {
    uint64_t ticks = 0;
    uint32_t checksum = 0;
};

Result run_case(const qt::TrackCase& c) {
    qt::TrackSequence seq;
    for (qt::Segment& m : g_measured) m = seq.next();

    qt::LineTracker tracker;
    tracker.init(g_measured[0], qt::track_params(c));
    const uint64_t t0 = ticks_now();
    for (int k = 0; k < qt::kTrackFrames; ++k) {
        const qt::Segment line = qt::track_step(tracker, g_measured[k + 1]);
        g_rho[k] = line.rho.raw;
        g_theta[k] = line.theta;
    }
    const uint64_t t1 = ticks_now();

    Result r;
    r.ticks = t1 - t0;
    qt::Fnv1a h;
    for (int k = 0; k < qt::kTrackFrames; ++k) qt::track_fold(h, g_rho[k], g_theta[k]);
    r.checksum = h.hash;
    return r;
}

}  // namespace

int main() {
    cycle_counter_init();
    int passed = 0;
    for (int i = 0; i < qt::kTrackCaseCount; ++i) {
        const qt::TrackCase& c = qt::kTrackCases[i];
        const Result r = run_case(c);
        const uint64_t instructions = ticks_to_instructions(r.ticks);
        const uint64_t frames = qt::kTrackFrames;
        // Rounded to nearest; the frame rate from the unrounded count, truncated.
        const uint64_t per_frame = (instructions + frames / 2) / frames;
        const uint64_t quad_fps =
            instructions == 0 ? 0 : kClockHz * frames / (kQuadLines * instructions);

        sh_write("track ");
        sh_write(c.name);
        sh_write(": ");
        sh_dec(per_frame);
        sh_write(" instr/line/frame, sizeof(LineTracker) = ");
        sh_dec(sizeof(qt::LineTracker));
        sh_write(" B; 4 lines (a quadrangle) at 100 MHz, 1 instr/cycle: ");
        sh_dec(quad_fps);
        sh_write(" frames/s\n");

        const bool pass =
            same_text(c.name, kExpected[i].name) && r.checksum == kExpected[i].checksum;
        passed += pass ? 1 : 0;
        sh_write("track ");
        sh_write(c.name);
        sh_write(" checksum 0x");
        sh_hex(r.checksum, 8);
        sh_write(", host ");
        sh_write(kExpected[i].name);
        sh_write(" 0x");
        sh_hex(kExpected[i].checksum, 8);
        sh_write(pass ? " PASS\n" : " FAIL\n");
    }

    sh_write("track: ");
    if (passed == qt::kTrackCaseCount) {
        sh_write("all ");
        sh_dec(qt::kTrackCaseCount);
        sh_write(" models PASS");
    } else {
        sh_dec(static_cast<uint64_t>(qt::kTrackCaseCount - passed));
        sh_write(" of ");
        sh_dec(qt::kTrackCaseCount);
        sh_write(" models FAIL");
    }
    sh_write(" (");
    sh_dec(qt::kTrackFrames);
    sh_write(" frames each); stack peak ");
    sh_dec(stack_peak_bytes());
    sh_write(" of ");
    sh_dec(stack_size_bytes());
    sh_write(" bytes\n");
    return passed == qt::kTrackCaseCount ? 0 : 1;
}
