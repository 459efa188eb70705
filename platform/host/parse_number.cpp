#include "host/parse_number.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace qt::host {

bool parse_int(const std::string& text, long lo, long hi, long& out, std::string& error) {
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0) {
        error = "'" + text + "' is not an integer";
        return false;
    }
    if (v < lo || v > hi) {
        error = text + " is out of range " + std::to_string(lo) + ".." + std::to_string(hi);
        return false;
    }
    out = v;
    return true;
}

bool parse_double(const std::string& text, double lo, double hi, double& out, std::string& error) {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(v)) {
        error = "'" + text + "' is not a number";
        return false;
    }
    if (v < lo || v > hi) {
        char range[64];
        std::snprintf(range, sizeof range, "%g..%g", lo, hi);
        error = text + " is out of range " + range;
        return false;
    }
    out = v;
    return true;
}

}  // namespace qt::host
