// The PGM parser of the firmware's frames (pgm_view.h) on the target, against small headers good
// and bad: each must be accepted or refused as listed. Prints each failure and "pgm parser: all N
// header checks PASS"; exit status 0 only then.
#include <stdint.h>
#include <string.h>

#include "pgm_view.h"
#include "semihosting.h"

namespace {

constexpr uint16_t kWidth = 320, kHeight = 240;  // the chain's frames (BoardDetectorQvga)

struct PgmCheck {
    const char* text;
    bool accept;
};
constexpr PgmCheck kPgmChecks[] = {
    {"P5\n2 2\n255\nabcd", true},
    {"P5 2 2 255 \n\n\n\n", true},  // raster bytes that look like whitespace
    {"P5\n# comment\n2\t2 # more\n255\rabcd", true},
    {"P2\n2 2\n255\nabcd", false},        // ASCII greymap
    {"P52 2\n255\nabcd", false},          // no separator after the magic
    {"P5\n2 2\n65535\nabcdefgh", false},  // two bytes per pixel
    {"P5\n2 2\n127\nabcd", false},
    {"P5\n2 2\n255abcd", false},      // no whitespace before the raster
    {"P5\n2 2\n255\n\nabcd", false},  // two: the raster would be 5 bytes
    {"P5\n2 2\n255\nabc", false},     // short raster
    {"P5\n2 2\n255\nabcde", false},   // trailing byte
    {"P5\n0 2\n255\n", false},
    {"P5\n321 1\n255\n", false},  // wider than the detector
    {"P5\n2 -2\n255\nabcd", false},
    {"P5\n2 2", false},
    {"", false},
};

}  // namespace

int main() {
    unsigned failed = 0;
    for (const PgmCheck& c : kPgmChecks) {
        const uint8_t* p = reinterpret_cast<const uint8_t*>(c.text);
        const Pgm pgm = parse_pgm(p, p + strlen(c.text), kWidth, kHeight);
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
    constexpr unsigned kChecks = sizeof kPgmChecks / sizeof kPgmChecks[0];
    if (failed != 0) {
        sh_dec(failed);
        sh_write(" of the pgm parser's header checks FAIL\n");
        return 1;
    }
    sh_write("pgm parser: all ");
    sh_dec(kChecks);
    sh_write(" header checks PASS\n");
    return 0;
}
