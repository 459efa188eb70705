// A setting's unit and accepted range, declared once beside the parameter struct that holds it
// (kHoughRanges beside HoughParams, kQuadRanges beside QuadParams, ...). The CLI's flags (their
// parsing and --help) and the C API's qt_config_check read the ranges from there;
// tests/cli/test_setting_ranges.cpp checks both against them.
//
// The range is in the unit a user gives the value (pixels, degrees, %, frames): from
// lo / 10^decimals to hi / 10^decimals, both included. The field may store it scaled (q16_16
// pixels, binary angles, Q15 scores).
//
// A check is switched off one way: its limit set to kCheckOff (the CLI's value `off`). Such a
// limit's range says so (can_be_off); kCheckOff lies outside every such range or at its end.
#pragma once
#include <stdint.h>

namespace qt {

// The value of a uint8_t limit that switches its check off.
constexpr uint8_t kCheckOff = 255;

struct SettingRange {
    const char* unit;         // "px", "degrees", "%", ...; "" for a count or a factor
    int64_t lo;               // least accepted value × 10^decimals
    int64_t hi;               // greatest accepted value × 10^decimals
    uint8_t decimals = 0;     // 0: whole numbers only
    bool can_be_off = false;  // kCheckOff (`off`) also accepted: the check is not made

    constexpr int64_t scale() const {
        int64_t s = 1;
        for (uint8_t i = 0; i < decimals; ++i) s *= 10;
        return s;
    }
    // A whole number v within the range (or kCheckOff when the check can be off).
    constexpr bool contains(int64_t v) const {
        return (lo <= v * scale() && v * scale() <= hi) || (can_be_off && v == kCheckOff);
    }
};

}  // namespace qt
