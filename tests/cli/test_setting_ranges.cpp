// Every setting's range, declared once in core (base/setting_range.h), against each place a user
// meets it: every flag of every command (its --help line shows the range; parsing accepts both
// ends, refuses a step beyond either, takes `off` exactly when the check can be off, and takes
// back the default its help shows), and every qt_config field (qt_config_check accepts both ends
// and refuses beyond them; quadtrack_c.h's comment gives the same range).
#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "api/quadtrack_c.h"
#include "cli/cli_options.h"
#include "cli/target_options.h"
#include "lines/line_detector.h"
#include "tracking/quad_tracker.h"
#include "tracking/tracking_mode.h"

namespace {

using qt::SettingRange;

// The flags that take a name, a file, a pattern or a box rather than a number.
const std::set<std::string> kNotNumbers = {"edge-front-end", "contrast",    "complete-hidden-side",
                                           "capacity",       "draw",        "lines",
                                           "model",          "roi",         "method",
                                           "reset",          "formulation", "search-region",
                                           "rep-gate",       "detector",    "coast-track",
                                           "frame-corners",  "pairs",       "tracking-mode",
                                           "template-pose"};

// A value lo / 10^decimals + steps / 10^decimals written out in decimal.
std::string value_text(const SettingRange& r, int64_t scaled) {
    const int64_t scale = r.scale();
    std::ostringstream s;
    if (scaled < 0) s << '-';
    const int64_t a = scaled < 0 ? -scaled : scaled;
    s << a / scale;
    if (a % scale != 0) {
        std::string frac = std::to_string(scale + a % scale).substr(1);
        s << '.' << frac;
    }
    return s.str();
}

// The value as the flag takes it ("WxH" flags: the same value for both).
std::string as_flag_value(const char* placeholder, const std::string& v) {
    return std::string(placeholder) == "WxH" ? v + "x" + v : v;
}

template <class Options, class Command>
void check_flags(const qt::cli::FlagTable<Options, Command>& table, int& checked) {
    for (const auto& f : table.flags) {
        INFO("--" << f.name);
        if (f.range == nullptr) {
            CHECK(kNotNumbers.count(f.name) == 1);
            continue;
        }
        CHECK(kNotNumbers.count(f.name) == 0);
        Options o;
        std::string why;
        // The default its help line shows is taken back.
        CHECK(f.set(f.show(Options{}), o, why));
        const SettingRange& r = *f.range;
        CHECK(f.help.find(", " + qt::cli::range_text(r)) != std::string::npos);
        CHECK(f.set(as_flag_value(f.value, value_text(r, r.lo)), o, why));
        CHECK(f.set(as_flag_value(f.value, value_text(r, r.hi)), o, why));
        CHECK_FALSE(f.set(as_flag_value(f.value, value_text(r, r.lo - 1)), o, why));
        CHECK_FALSE(f.set(as_flag_value(f.value, value_text(r, r.hi + 1)), o, why));
        CHECK(f.set("off", o, why) == r.can_be_off);
        if (r.can_be_off) CHECK(f.show(o) == "off");
        ++checked;
    }
}

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The comment after `field;` in quadtrack_c.h's qt_config, up to the next field.
std::string header_comment(const std::string& header, const std::string& field) {
    const size_t at = header.find(" " + field + ";");
    if (at == std::string::npos) return "";
    const size_t end = header.find("*/", at);
    return header.substr(at, end - at);
}

struct ConfigField {
    const char* name;
    SettingRange range;
    int64_t type_max;  // the field's type's largest value
    std::function<void(qt_config&, int64_t)> set;
};

}  // namespace

TEST_CASE("Every flag's range is the one core declares, in --help and in parsing",
          "[cli][ranges]") {
    int checked = 0;
    check_flags(qt::cli::detect_flags(), checked);
    check_flags(qt::cli::target_flags(), checked);
    // The number flags of the four commands (guards against a table the test no longer sees).
    CHECK(checked >= 60);
}

TEST_CASE("qt_config_check and quadtrack_c.h give every field the range core declares",
          "[capi][ranges]") {
    const SettingRange contrast{"", 0, QT_CONTRAST_ANY}, model{"", 0, QT_MODEL_TURN},
        tracking_mode{"", 0, QT_TRACKING_MODE_ON};
    const std::vector<ConfigField> fields = {
        {"edge_threshold", qt::kLineRanges.edge_threshold, 65535,
         [](qt_config& c, int64_t v) { c.edge_threshold = static_cast<uint16_t>(v); }},
        {"hough_threshold", qt::kHoughRanges.threshold, 65535,
         [](qt_config& c, int64_t v) { c.hough_threshold = static_cast<uint16_t>(v); }},
        {"min_line_length", qt::kHoughRanges.min_line_length, 65535,
         [](qt_config& c, int64_t v) { c.min_line_length = static_cast<uint16_t>(v); }},
        {"max_line_gap", qt::kHoughRanges.max_line_gap, 65535,
         [](qt_config& c, int64_t v) { c.max_line_gap = static_cast<uint16_t>(v); }},
        {"contrast", contrast, 255,
         [](qt_config& c, int64_t v) { c.contrast = static_cast<uint8_t>(v); }},
        {"model", model, 255, [](qt_config& c, int64_t v) { c.model = static_cast<uint8_t>(v); }},
        {"filters", qt::kQuadTrackerRanges.filters, 255,
         [](qt_config& c, int64_t v) { c.filters = static_cast<uint8_t>(v); }},
        {"max_predicted", qt::kQuadTrackerRanges.max_predicted, 255,
         [](qt_config& c, int64_t v) { c.max_predicted = static_cast<uint8_t>(v); }},
        {"gate_angle_deg", qt::kQuadTrackerRanges.gate_angle, 65535,
         [](qt_config& c, int64_t v) { c.gate_angle_deg = static_cast<uint16_t>(v); }},
        {"gate_distance_px", qt::kQuadTrackerRanges.gate_distance, 65535,
         [](qt_config& c, int64_t v) { c.gate_distance_px = static_cast<uint16_t>(v); }},
        {"tracking_mode", tracking_mode, 255,
         [](qt_config& c, int64_t v) { c.tracking_mode = static_cast<uint8_t>(v); }},
        {"band_half_width_px", qt::kTrackingModeRanges.half_width, 255,
         [](qt_config& c, int64_t v) { c.band_half_width_px = static_cast<uint8_t>(v); }},
        {"full_every", qt::kTrackingModeRanges.full_every, 65535,
         [](qt_config& c, int64_t v) { c.full_every = static_cast<uint16_t>(v); }},
    };
    const std::string header = read_file(std::string(QT_SOURCE_DIR) + "/core/api/quadtrack_c.h");
    REQUIRE(!header.empty());

    // Every field of qt_config is in the list above.
    const size_t begin = header.find("typedef struct qt_config {");
    const size_t end = header.find("} qt_config;");
    REQUIRE((begin != std::string::npos && end != std::string::npos));
    std::istringstream body(header.substr(begin, end - begin));
    int declared = 0;
    for (std::string line; std::getline(body, line);) {
        std::istringstream words(line);
        std::string type, name;
        words >> type >> name;
        if (type.rfind("uint", 0) != 0 || name.empty() || name.back() != ';') continue;
        ++declared;
        name.pop_back();
        bool listed = false;
        for (const ConfigField& f : fields) listed = listed || name == f.name;
        INFO(name);
        CHECK(listed);
    }
    CHECK(declared == static_cast<int>(fields.size()));

    for (const ConfigField& f : fields) {
        INFO(f.name);
        REQUIRE(f.range.decimals == 0);
        qt_config c;
        qt_config_default(&c, 320, 240);
        REQUIRE(qt_config_check(&c) == QT_OK);
        const qt_config defaults = c;
        const auto check_with = [&](int64_t v) {
            qt_config changed = defaults;
            f.set(changed, v);
            return qt_config_check(&changed);
        };
        CHECK(check_with(f.range.lo) == QT_OK);
        CHECK(check_with(f.range.hi) == QT_OK);
        if (f.range.lo > 0) CHECK(check_with(f.range.lo - 1) == QT_BAD_CONFIG);
        if (f.range.hi < f.type_max)
            CHECK(check_with(f.range.hi + 1) ==
                  (f.range.can_be_off && f.range.hi + 1 == qt::kCheckOff ? QT_OK : QT_BAD_CONFIG));
        if (f.range.can_be_off) CHECK(check_with(qt::kCheckOff) == QT_OK);
        const std::string text = std::to_string(f.range.lo) + ".." + std::to_string(f.range.hi);
        INFO(header_comment(header, f.name));
        CHECK(header_comment(header, f.name).find(text) != std::string::npos);
    }
}
