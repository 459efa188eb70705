// A command's flags as one table: each flag's name, value placeholder, help line (with unit and
// range), how to show its default and how to parse it, so parsing and --help cannot disagree.
// detect/track (cli_options) and homography/target (target_options) are instances. Host only.
#pragma once
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

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
    Command command{};  // the one command it serves, or the table's `every`
};

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

// An integer flag in [lo, hi] stored in an unsigned field of type T.
template <typename T, class Options, class Command>
Flag<Options, Command> integer_flag(const char* name, const char* value, const char* help, long lo,
                                    long hi, std::function<T&(Options&)> field, Command command) {
    return {name,
            value,
            help,
            [field](Options o) { return std::to_string(field(o)); },
            [field, lo, hi](const std::string& t, Options& o, std::string& e) {
                long v = 0;
                if (!host::parse_int(t, lo, hi, v, e)) return false;
                field(o) = static_cast<T>(v);
                return true;
            },
            command};
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
                "pixels; auto: the smallest N that fits, 1..16",
            [field](Options o) {
                return field(o) == 0 ? std::string("auto") : std::to_string(field(o));
            },
            [field](const std::string& t, Options& o, std::string& e) {
                if (t == "auto") {
                    field(o) = 0;
                    return true;
                }
                long v = 0;
                if (!host::parse_int(t, 1, 16, v, e)) return false;
                field(o) = static_cast<uint8_t>(v);
                return true;
            },
            command};
}

}  // namespace qt::cli
