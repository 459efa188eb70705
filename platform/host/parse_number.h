// Numbers from command-line text, with a one-line reason on failure (host only).
#pragma once
#include <string>

namespace qt::host {

// A decimal integer in [lo, hi]; false with `error` set ("'x' is not an integer",
// "7 is out of range 1..5") otherwise.
bool parse_int(const std::string& text, long lo, long hi, long& out, std::string& error);

// A finite decimal number in [lo, hi]; false with `error` set otherwise.
bool parse_double(const std::string& text, double lo, double hi, double& out, std::string& error);

}  // namespace qt::host
