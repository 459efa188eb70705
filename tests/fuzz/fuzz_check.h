// The one thing the fuzz targets share: a violated invariant prints what and where, then traps
// (libFuzzer and the replay driver both report the trap as a crash of that input).
#pragma once
#include <cstdio>

#define QT_FUZZ_CHECK(cond)                                                                     \
    do {                                                                                        \
        if (!(cond)) {                                                                          \
            std::fprintf(stderr, "%s:%d: invariant violated: %s\n", __FILE__, __LINE__, #cond); \
            std::fflush(stderr);                                                                \
            __builtin_trap();                                                                   \
        }                                                                                       \
    } while (0)
