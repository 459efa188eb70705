// Whether what a command wrote reached its file: stdio buffers writes, so a full disk, a closed
// descriptor or a reader that went away shows only at a flush. Every command checks its output
// before it reports success, and the sequence commands after each frame's line, so that a
// pipeline never takes a run that lost its results for one that succeeded.
#pragma once
#include <cstdio>

namespace qt::io {

// Flushes `out`; when that or any earlier write to it failed, prints one line "WHO: cannot write
// the results: REASON" on `err` and returns false.
bool output_written(std::FILE* out, std::FILE* err, const char* who);

}  // namespace qt::io
