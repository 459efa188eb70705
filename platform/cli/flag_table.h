// A command's flags as one table: each flag's name, value placeholder, help line, how to show
// its default and how to parse it, so parsing and --help cannot disagree. A flag of a number
// reads its unit and range from the SettingRange core declares beside the field
// (base/setting_range.h): --help prints them and parsing checks them. detect/track
// (cli_options) and homography/target (target_options) are instances. Host only.
#pragma once
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "base/setting_range.h"
#include "gradient/binning.h"
#include "host/parse_number.h"
#include "io/error_line.h"
#include "io/write_check.h"

namespace qt::cli {

template <class Options, class Command>
struct Flag {
    const char* name;
    const char* value;                         // placeholder in the help
    std::string help;                          // with unit and range
    std::function<std::string(Options)> show;  // the value in a copy of the options
    std::function<bool(const std::string&, Options&, std::string&)> set;  // parse, check, store
    Command command{};                    // the one command it serves, or the table's `every`
    const SettingRange* range = nullptr;  // a number's unit and range, declared in core
};

// "lo..hi" of a range in its unit's numbers (1e6 for a 1 and six zeros or more), ", or off"
// when the check can be switched off.
inline std::string range_text(const SettingRange& r) {
    const auto number = [&r](int64_t n) {
        const int64_t scale = r.scale();
        std::string sign = n < 0 ? "-" : "";
        const int64_t a = n < 0 ? -n : n;
        int64_t m = a / scale, e = 0;
        while (a % scale == 0 && m != 0 && m % 10 == 0) m /= 10, ++e;
        if (e >= 6) return sign + std::to_string(m) + "e" + std::to_string(e);
        std::string text = sign + std::to_string(a / scale);
        if (a % scale != 0) {
            std::string frac = std::to_string(scale + a % scale).substr(1);
            while (frac.back() == '0') frac.pop_back();
            text += "." + frac;
        }
        return text;
    };
    return number(r.lo) + ".." + number(r.hi) + (r.can_be_off ? ", or off" : "");
}

inline double range_lo(const SettingRange& r) { return double(r.lo) / double(r.scale()); }
inline double range_hi(const SettingRange& r) { return double(r.hi) / double(r.scale()); }

// A help line: "what, unit, lo..hi (note)", the unit and range from core.
inline std::string described(const char* what, const SettingRange& r, const char* note = "") {
    std::string text = what;
    if (r.unit[0] != '\0') text += std::string(", ") + r.unit;
    text += ", " + range_text(r);
    if (note[0] != '\0') text += std::string(" (") + note + ")";
    return text;
}

// Parses "off" (when the range allows it) or a whole number within the range.
inline bool parse_in_range(const std::string& text, const SettingRange& r, long& out,
                           std::string& error) {
    if (r.can_be_off && text == "off") {
        out = kCheckOff;
        return true;
    }
    const bool ok = host::parse_int(text, static_cast<long>(range_lo(r)),
                                    static_cast<long>(range_hi(r)), out, error);
    if (!ok && r.can_be_off) error += ", or off";
    return ok;
}

// A decimal number within the range.
inline bool parse_in_range(const std::string& text, const SettingRange& r, double& out,
                           std::string& error) {
    return host::parse_double(text, range_lo(r), range_hi(r), out, error);
}

template <class Options, class Command>
struct FlagTable {
    std::vector<Flag<Options, Command>> flags;
    Command every;       // a flag with this command serves every command
    size_t help_column;  // where the help text starts in help()

    const Flag<Options, Command>* find(const std::string& name, Command c) const {
        for (const auto& f : flags)
            if (name == f.name && (f.command == every || f.command == c)) return &f;
        return nullptr;
    }

    // "  --name VALUE   text (default d)" for every flag of command c.
    std::string help(Command c) const {
        const Options defaults;
        std::string text;
        for (const auto& f : flags) {
            if (f.command != every && f.command != c) continue;
            std::string flag = std::string("  --") + f.name + " " + f.value;
            flag.resize(flag.size() < help_column ? help_column : flag.size() + 1, ' ');
            text += flag + f.help + " (default " + f.show(defaults) + ")\n";
        }
        return text;
    }

    // Flags of command c as --name VALUE or --name=VALUE into `options`, every other argument
    // into `positional` in order ("-" is standard input; after "--" every argument is
    // positional); --help or -h prints `usage` on `out`. Returns -1 when the command should run,
    // 0 after the usage (1 when it could not be written), 2 after one error line
    // "quadtrack NAME: ..." on `err` (an unknown flag or -x, a missing or bad value).
    int parse(const std::vector<std::string>& args, Command c, const char* name,
              const std::string& usage, Options& options, std::vector<std::string>& positional,
              std::FILE* out, std::FILE* err) const {
        positional.clear();
        for (size_t i = 0; i < args.size(); ++i) {
            const std::string& a = args[i];
            if (a == "--help" || a == "-h") {
                std::fputs(usage.c_str(), out);
                const std::string who = std::string("quadtrack ") + name;
                return qt::io::output_written(out, err, who.c_str()) ? 0 : 1;
            }
            if (a == "--") {
                positional.insert(positional.end(), args.begin() + static_cast<long>(i) + 1,
                                  args.end());
                break;
            }
            if (a.size() > 1 && a[0] == '-' && a[1] != '-') {
                qt::io::print_error_line(
                    err, "quadtrack %s: unknown option '%s' (see quadtrack %s --help)", name,
                    a.c_str(), name);
                return 2;
            }
            if (a.rfind("--", 0) != 0) {
                positional.push_back(a);
                continue;
            }
            std::string flag = a.substr(2), value;
            const size_t eq = flag.find('=');
            if (eq != std::string::npos) {
                value = flag.substr(eq + 1);
                flag.resize(eq);
            }
            const Flag<Options, Command>* f = find(flag, c);
            if (f == nullptr) {
                qt::io::print_error_line(
                    err, "quadtrack %s: unknown option '--%s' (see quadtrack %s --help)", name,
                    flag.c_str(), name);
                return 2;
            }
            if (eq == std::string::npos) {
                if (i + 1 == args.size()) {
                    qt::io::print_error_line(err, "quadtrack %s: %s needs a value", name,
                                             a.c_str());
                    return 2;
                }
                value = args[++i];
            }
            std::string why;
            if (!f->set(value, options, why)) {
                qt::io::print_error_line(err, "quadtrack %s: --%s: %s", name, flag.c_str(),
                                         why.c_str());
                return 2;
            }
        }
        return -1;
    }
};

// An integer flag within `range` (core's) stored in an unsigned field of type T; help: what,
// the range's unit and range, and the note in parentheses.
template <typename T, class Options, class Command>
Flag<Options, Command> integer_flag(const char* name, const char* value, const char* what,
                                    const SettingRange& range, std::function<T&(Options&)> field,
                                    Command command, const char* note = "") {
    return {name,
            value,
            described(what, range, note),
            [field, range](Options o) {
                return range.can_be_off && field(o) == kCheckOff ? std::string("off")
                                                                 : std::to_string(field(o));
            },
            [field, range](const std::string& t, Options& o, std::string& e) {
                long v = 0;
                if (!parse_in_range(t, range, v, e)) return false;
                field(o) = static_cast<T>(v);
                return true;
            },
            command,
            &range};
}

// --bin N|auto: frames are reduced by N × N block means before the chain (core's binning stage,
// gradient/binning.h); auto (stored as 0) picks the smallest N that fits the build.
// `frames`: which frames are binned.
template <class Options, class Command>
Flag<Options, Command> bin_flag(std::function<uint8_t&(Options&)> field, Command command,
                                const std::string& frames = "frames larger than 640 x 480") {
    return {"bin",
            "N|auto",
            frames +
                " are binned: each pixel the mean of an N x N block, results in the input's "
                "pixels; auto: the smallest N that fits, " +
                range_text(kBinFactorRange),
            [field](Options o) {
                return field(o) == 0 ? std::string("auto") : std::to_string(field(o));
            },
            [field](const std::string& t, Options& o, std::string& e) {
                if (t == "auto") {
                    field(o) = 0;
                    return true;
                }
                long v = 0;
                if (!parse_in_range(t, kBinFactorRange, v, e)) return false;
                field(o) = static_cast<uint8_t>(v);
                return true;
            },
            command,
            &kBinFactorRange};
}

}  // namespace qt::cli
