// One error line: what every quadtrack command prints on stderr when it fails, and what the
// image readers put in their error strings. Scripts read errors line by line, so control
// characters that reach a message from the user's arguments, file names or a garbled file
// header are shown as '?', and bytes above 0x7F as \xNN: a message is printable ASCII whatever the
// input held.
#pragma once
#include <cstdio>
#include <string>

namespace qt::io {

// `s` with every control character (below 0x20, and 0x7F) replaced by '?' and every byte above
// 0x7F by the four characters \xNN (lower-case hex).
std::string one_line(std::string s);

// printf-style `format` (no trailing newline), made one line, then '\n', on `err`.
void print_error_line(std::FILE* err, const char* format, ...)
    __attribute__((format(printf, 2, 3)));

}  // namespace qt::io
