// A stated precondition broken on purpose (shr_round_half_away with a shift of 63): the check
// must catch it in the test builds. Prints the handler's line and exits 3; without the check
// it would print the result.
#include <cstdio>
#include <cstdlib>

#include "base/fixed.h"

int main(int argc, char**) {
    qt::set_precondition_handler([](const char* file, int line, const char* condition) {
        std::printf("precondition failed: %s:%d: %s\n", file, line, condition);
        std::exit(3);
    });
    const int shift = 62 + argc;  // 63: not a constant the compiler could fold
    std::printf("unchecked: %lld\n", static_cast<long long>(qt::shr_round_half_away(1, shift)));
    return 0;
}
