#include "io/error_line.h"

#include <cstdarg>
#include <vector>

namespace qt::io {

std::string one_line(std::string s) {
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7F) {
            out.push_back('?');
        } else if (u >= 0x80) {
            out += "\\x";
            out.push_back(kHex[u >> 4]);
            out.push_back(kHex[u & 15u]);
        } else {
            out.push_back(c);
        }
    }
    return out;
}

void print_error_line(std::FILE* err, const char* format, ...) {
    va_list args;
    va_start(args, format);
    va_list again;
    va_copy(again, args);
    const int n = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::vector<char> text(n > 0 ? static_cast<size_t>(n) + 1 : 1, '\0');
    if (n > 0) std::vsnprintf(text.data(), text.size(), format, again);
    va_end(again);
    std::fprintf(err, "%s\n", one_line(text.data()).c_str());
}

}  // namespace qt::io
