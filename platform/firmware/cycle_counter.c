#include "cycle_counter.h"

/* SysTick and the one SCB register needed (ARMv7-M ARM, B3.3 and B3.2). */
#define SYST_CSR (*(volatile uint32_t*)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t*)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t*)0xE000E018u)
#define SCB_ICSR (*(volatile uint32_t*)0xE000ED04u)

enum {
    kCsrEnable = 1u << 0,
    kCsrTickInt = 1u << 1,     /* interrupt on each wrap to 0 -> LOAD */
    kCsrCoreClock = 1u << 2,   /* count the processor clock, not the external reference */
    kIcsrPendStSet = 1u << 26, /* SysTick exception pending */
    kReload = 0xFFFFFFu,       /* 24-bit counter: period 2^24 ticks */
};

static volatile uint32_t g_wraps; /* completed periods of 2^24 ticks */

void SysTick_Handler(void) { ++g_wraps; }

void cycle_counter_init(void) {
    SYST_CSR = 0;
    SYST_RVR = kReload;
    SYST_CVR = 0; /* any write clears it to 0 (no interrupt); it reloads LOAD on the next tick */
    g_wraps = 0;
    SYST_CSR = kCsrEnable | kCsrTickInt | kCsrCoreClock;
}

/* The counter runs LOAD, LOAD-1, ..., 1, 0, LOAD, ... (2^24 ticks per period) and pends the
 * wrap interrupt on the step to 0, so g_wraps counts the zeros reached; a reading `down`
 * then lies (2^24 - down) mod 2^24 ticks past the last zero. Wraps and counter are read
 * with interrupts masked, so the handler cannot run in between; a zero reached whose
 * handler has not run yet shows as a pending SysTick and is counted here, re-reading the
 * counter, which is then certainly in the new period. */
uint64_t ticks_now(void) {
    uint32_t primask;
    __asm__ volatile("mrs %0, primask\n cpsid i" : "=r"(primask)::"memory");
    uint32_t wraps = g_wraps;
    uint32_t down = SYST_CVR;
    if (SCB_ICSR & kIcsrPendStSet) {
        down = SYST_CVR;
        ++wraps;
    }
    __asm__ volatile("msr primask, %0" ::"r"(primask) : "memory");
    return ((uint64_t)wraps << 24) + ((0u - down) & kReload);
}
