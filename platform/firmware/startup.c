/* Vector table and reset for the Cortex-M4 on QEMU mps2-an386 (memory map: mps2_an386.ld).
 * Reset: turn the FPU on (hard-float builds), paint the stack, copy .data, zero .bss, run
 * static constructors, call main, and exit through semihosting with main's return value as
 * QEMU's exit status. */
#include <stdint.h>

#include "semihosting.h"
#include "stack_usage.h"

int main(void);

/* Linker script symbols (addresses only; the objects have no meaningful type). */
extern uint32_t __data_load[], __data_start[], __data_end[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_limit[], __stack_top[];
typedef void (*init_fn)(void);
extern init_fn __preinit_array_start[], __preinit_array_end[];
extern init_fn __init_array_start[], __init_array_end[];

enum {
    kExitHardFault = 0x7e,     /* exit status after a HardFault */
    kExitUnexpectedIrq = 0x7d, /* exit status after any exception without a handler */
};

/* The loops below go through volatile pointers so that GCC cannot turn them into
 * memset/memcpy calls: the stack loop must not call anything that pushes onto the very
 * words it is painting. */
void Reset_Handler(void) {
#if defined(__ARM_FP)
    /* The FPU is off at reset (CPACR = 0: any FP instruction faults). Full access for
     * coprocessors 10 and 11, the FPU (ARMv7-M ARM B3.2.20), before any code that may use FP
     * registers; the barriers make the access take effect for the next instruction. */
    volatile uint32_t* const cpacr = (volatile uint32_t*)0xE000ED88u;
    *cpacr |= (3u << 20) | (3u << 22);
    __asm__ volatile("dsb\n isb" ::: "memory");
#endif
    uint32_t* sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (volatile uint32_t* p = __stack_limit; p < sp; ++p) *p = QT_STACK_PAINT;

    const volatile uint32_t* src = __data_load;
    for (volatile uint32_t* p = __data_start; p < __data_end; ++p) *p = *src++;
    for (volatile uint32_t* p = __bss_start; p < __bss_end; ++p) *p = 0;

    for (init_fn* f = __preinit_array_start; f < __preinit_array_end; ++f) (*f)();
    for (init_fn* f = __init_array_start; f < __init_array_end; ++f) (*f)();

    sh_exit(main());
}

/* HardFault: report the stacked PC and the fault status registers, then fail. */
void hard_fault_report(const uint32_t* frame) {
    const volatile uint32_t* const cfsr = (const volatile uint32_t*)0xE000ED28u;
    const volatile uint32_t* const hfsr = (const volatile uint32_t*)0xE000ED2Cu;
    sh_write("HardFault pc=0x");
    sh_hex(frame[6], 8); /* exception frame: r0 r1 r2 r3 r12 lr pc xpsr */
    sh_write(" lr=0x");
    sh_hex(frame[5], 8);
    sh_write(" cfsr=0x");
    sh_hex(*cfsr, 8);
    sh_write(" hfsr=0x");
    sh_hex(*hfsr, 8);
    sh_write("\n");
    sh_exit(kExitHardFault);
}

/* Picks the stack the fault frame was pushed on (EXC_RETURN bit 2: 0 = MSP, 1 = PSP). */
__attribute__((naked)) void HardFault_Handler(void) {
    __asm__ volatile(
        "tst lr, #4\n"
        "ite eq\n"
        "mrseq r0, msp\n"
        "mrsne r0, psp\n"
        "b hard_fault_report\n");
}

void Default_Handler(void) {
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    sh_write("unexpected exception ");
    sh_dec(ipsr & 0x1ffu);
    sh_write("\n");
    sh_exit(kExitUnexpectedIrq);
}

/* Handlers other files may provide (cycle_counter.c has SysTick). */
#define WEAK_DEFAULT __attribute__((weak, alias("Default_Handler")))
void NMI_Handler(void) WEAK_DEFAULT;
void MemManage_Handler(void) WEAK_DEFAULT;
void BusFault_Handler(void) WEAK_DEFAULT;
void UsageFault_Handler(void) WEAK_DEFAULT;
void SVC_Handler(void) WEAK_DEFAULT;
void DebugMon_Handler(void) WEAK_DEFAULT;
void PendSV_Handler(void) WEAK_DEFAULT;
void SysTick_Handler(void) WEAK_DEFAULT;

enum { kExternalIrqs = 32 }; /* QEMU's AN385/AN386 NVIC has 32 external interrupts */

typedef void (*vector)(void);
__attribute__((section(".isr_vector"), used)) const vector qt_vector_table[16 + kExternalIrqs] = {
    (vector)(uintptr_t)__stack_top, /* 0: initial main stack pointer */
    Reset_Handler,                  /* 1 */
    NMI_Handler,                    /* 2 */
    HardFault_Handler,              /* 3 */
    MemManage_Handler,              /* 4 */
    BusFault_Handler,               /* 5 */
    UsageFault_Handler,             /* 6 */
    0,
    0,
    0,
    0,                /* 7..10 reserved */
    SVC_Handler,      /* 11 */
    DebugMon_Handler, /* 12 */
    0,                /* 13 reserved */
    PendSV_Handler,   /* 14 */
    SysTick_Handler,  /* 15 */
    [16 ... 16 + kExternalIrqs - 1] = Default_Handler,
};
