// Catch2's main, with core's precondition handler saying where a stated precondition failed
// (base/precondition.h) before the run stops.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>

#include "base/precondition.h"

int main(int argc, char* argv[]) {
    qt::set_precondition_handler([](const char* file, int line, const char* condition) {
        std::fprintf(stderr, "precondition failed: %s:%d: %s\n", file, line, condition);
        std::abort();
    });
    return Catch::Session().run(argc, argv);
}
