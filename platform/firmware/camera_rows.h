// A linked PGM frame fed to a streaming stage as a camera delivers it: each row first copied
// into a word-aligned line buffer, untimed (a camera interface's DMA does that without the
// CPU), then pushed; only the push calls are timed.
#pragma once
#include <stdint.h>
#include <string.h>

#include "base/status.h"
#include "cycle_counter.h"
#include "pgm_view.h"

// Pushes rows with push(line, width) until the last or the first status other than ok (left
// in s). Returns the instructions the push calls took (SysTick, cycle_counter.h).
template <class Push>
uint64_t push_camera_rows(const Pgm& pgm, uint8_t* line, qt::Status& s, Push&& push) {
    const uint8_t* row = pgm.raster;
    uint64_t ticks = 0;
    for (uint16_t y = 0; y < pgm.height && s == qt::Status::ok; ++y, row += pgm.width) {
        memcpy(line, row, pgm.width);
        const uint64_t t0 = ticks_now();
        s = push(line, pgm.width);
        ticks += ticks_now() - t0;
    }
    return ticks_to_instructions(ticks);
}
