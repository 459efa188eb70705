#include "stack_usage.h"

extern uint32_t __stack_limit[], __stack_top[]; /* mps2_an386.ld */

uint32_t stack_size_bytes(void) {
    return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)__stack_limit);
}

/* The stack grows down from __stack_top: scan up from the limit to the first overwritten
 * word. (A frame that skips words without writing them can hide a few bytes; this gives a
 * lower bound, exact in practice.) */
uint32_t stack_peak_bytes(void) {
    const uint32_t* p = __stack_limit;
    while (p < __stack_top && *p == QT_STACK_PAINT) ++p;
    return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)p);
}
