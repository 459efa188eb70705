#include "io/write_check.h"

#include <cerrno>
#include <cstring>

#include "io/error_line.h"

namespace qt::io {

bool output_written(std::FILE* out, std::FILE* err, const char* who) {
    // errno says why: the failed write's when one already failed (the error flag is set), else
    // the flush's.
    if (!std::ferror(out)) errno = 0;
    const bool flushed = std::fflush(out) == 0;
    if (flushed && !std::ferror(out)) return true;
    print_error_line(err, "%s: cannot write the results: %s", who,
                     errno != 0 ? std::strerror(errno) : "a write failed");
    return false;
}

}  // namespace qt::io
