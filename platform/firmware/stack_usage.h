/* Worst stack depth: startup.c paints the unused stack with QT_STACK_PAINT at reset; words
 * still holding the pattern were never written. */
#pragma once
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define QT_STACK_PAINT 0xDEADBEEFu /* not a byte repeat, so no memset can produce it */

uint32_t stack_size_bytes(void); /* bytes reserved by the linker script (QT_STACK_SIZE) */
uint32_t stack_peak_bytes(void); /* deepest use since reset, in bytes (4-byte resolution) */

#ifdef __cplusplus
}
#endif
