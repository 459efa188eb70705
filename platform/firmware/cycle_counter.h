/* Elapsed time from SysTick, extended to 64 bits. The mps2 machines have no DWT CYCCNT.
 *
 * SysTick runs from the processor clock, 25 MHz on mps2-an386, with LOAD = 0xFFFFFF: one
 * wrap every 2^24 ticks (0.67 s), counted by SysTick_Handler. Under QEMU -icount shift=0 one
 * guest instruction takes 1 ns of virtual time, so one tick is exactly 40 executed
 * instructions: counts are deterministic but quantised to 40 instructions per reading. */
#pragma once
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define QT_TICK_HZ 25000000u  /* SysTick clock, ticks per second */
#define QT_INSTR_PER_TICK 40u /* 1e9 instr/s (-icount 0) / 25 MHz */

void cycle_counter_init(void); /* starts SysTick and its wrap interrupt; call once */
uint64_t ticks_now(void);      /* ticks since cycle_counter_init(), 64-bit */

static inline uint64_t ticks_to_instructions(uint64_t ticks) { return ticks * QT_INSTR_PER_TICK; }

#ifdef __cplusplus
}
#endif
