// The binning stage (core/gradient/binning.h) on the Cortex-M target (QEMU): each case of
// binning_cases.h is made row by row on the target (its pixels are a hash of their coordinates:
// no frame buffer), binned by qt::BinningStage<640>, and every output pixel compared with a
// brute-force block mean computed here from the same hash; the output's checksum is compared
// with the one the host's double-precision reference gave (binning_cases.h). Prints one line per
// case, the instructions per input pixel of the stage (SysTick, 40 instructions a tick under
// -icount shift=0, cycle_counter.h) and "binning: all N cases PASS"; exit status 0 only then.
#include <stdint.h>

#include "binning_cases.h"
#include "cycle_counter.h"
#include "gradient/binning.h"
#include "semihosting.h"
#include "stack_usage.h"

namespace {

qt::BinningStage<640> g_stage;
uint8_t g_row[2048];  // the camera's line buffer: the widest case's row

// The brute-force mean of output pixel (i, j) of case c, rounded half up.
uint8_t block_mean(const qt::BinningCase& c, uint32_t i, uint32_t j) {
    const uint32_t n = c.factor;
    uint32_t sum = 0;
    for (uint32_t y = j * n; y < j * n + n; ++y)
        for (uint32_t x = i * n; x < i * n + n; ++x) sum += qt::binning_pixel(c.seed, c.mode, x, y);
    return static_cast<uint8_t>((2u * sum + n * n) / (2u * n * n));
}

struct CaseResult {
    uint32_t checksum = qt::kFnvOffset;
    uint32_t mismatches = 0;
    uint32_t rows_out = 0;
    uint64_t ticks = 0;
    qt::Status status = qt::Status::ok;
};

CaseResult run_case(const qt::BinningCase& c) {
    CaseResult r;
    r.status = g_stage.begin_frame(c.width, c.height, c.factor);
    if (r.status != qt::Status::ok) return r;
    auto sink = [&](uint16_t j, const uint8_t* row, uint16_t w) {
        for (uint16_t i = 0; i < w; ++i) {
            r.checksum = qt::fnv1a(r.checksum, row[i]);
            if (row[i] != block_mean(c, i, j)) ++r.mismatches;
        }
        ++r.rows_out;
        return qt::Status::ok;
    };
    // First pass: every output pixel checked (untimed).
    for (uint16_t y = 0; y < c.height && r.status == qt::Status::ok; ++y) {
        for (uint16_t x = 0; x < c.width; ++x) g_row[x] = qt::binning_pixel(c.seed, c.mode, x, y);
        r.status = g_stage.push_row(g_row, c.width, sink);
    }
    if (r.status != qt::Status::ok) return r;
    // Second pass: the stage alone, push_row timed, the same rows into an empty sink.
    (void)g_stage.begin_frame(c.width, c.height, c.factor);
    for (uint16_t y = 0; y < c.height; ++y) {
        for (uint16_t x = 0; x < c.width; ++x) g_row[x] = qt::binning_pixel(c.seed, c.mode, x, y);
        const uint64_t t0 = ticks_now();
        (void)g_stage.push_row(g_row, c.width,
                               [](uint16_t, const uint8_t*, uint16_t) { return qt::Status::ok; });
        r.ticks += ticks_now() - t0;
    }
    return r;
}

}  // namespace

int main() {
    cycle_counter_init();
    int passed = 0;
    for (const qt::BinningCase& c : qt::kBinningCases) {
        const CaseResult r = run_case(c);
        const uint32_t out_rows = static_cast<uint32_t>(c.height / c.factor);
        const bool pass = r.status == qt::Status::ok && r.mismatches == 0 &&
                          r.rows_out == out_rows && r.checksum == c.checksum;
        passed += pass ? 1 : 0;
        const uint64_t pixels = static_cast<uint64_t>(c.width) * c.height;
        // Tenths of an instruction per input pixel, rounded to nearest.
        const uint64_t tenths = (ticks_to_instructions(r.ticks) * 10 + pixels / 2) / pixels;
        sh_write("binning ");
        sh_write(c.name);
        sh_write(": ");
        sh_write(qt::status_name(r.status));
        sh_write(", ");
        sh_dec(r.mismatches);
        sh_write(" pixels differ from the block means, checksum 0x");
        sh_hex(r.checksum, 8);
        sh_write(" (host reference 0x");
        sh_hex(c.checksum, 8);
        sh_write("), ");
        sh_dec(tenths / 10);
        sh_write(".");
        sh_dec(tenths % 10);
        sh_write(pass ? " instr/input pixel PASS\n" : " instr/input pixel FAIL\n");
    }
    sh_write("binning: ");
    if (passed == qt::kBinningCaseCount) {
        sh_write("all ");
        sh_dec(static_cast<uint64_t>(passed));
        sh_write(" cases PASS");
    } else {
        sh_dec(static_cast<uint64_t>(qt::kBinningCaseCount - passed));
        sh_write(" cases FAIL");
    }
    sh_write("; BinningStage<640> ");
    sh_dec(qt::BinningStage<640>::ram_bytes());
    sh_write(" B; stack peak ");
    sh_dec(stack_peak_bytes());
    sh_write(" bytes\n");
    return passed == qt::kBinningCaseCount ? 0 : 1;
}
