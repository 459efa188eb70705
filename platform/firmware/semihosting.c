#include "semihosting.h"

enum {
    SYS_WRITEC = 0x03,
    SYS_WRITE0 = 0x04,
    SYS_EXIT = 0x18,
    SYS_EXIT_EXTENDED = 0x20,
    ADP_Stopped_ApplicationExit = 0x20026,
    ADP_Stopped_RunTimeErrorUnknown = 0x20023,
};

/* Operation in r0, argument in r1, result in r0; the debugger (QEMU) may read memory that
 * r1 points to, hence the "memory" clobber. */
static uintptr_t sh_call(uintptr_t op, uintptr_t arg) {
    register uintptr_t r0 __asm__("r0") = op;
    register uintptr_t r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void sh_write(const char* s) { sh_call(SYS_WRITE0, (uintptr_t)s); }

void sh_putc(char c) { sh_call(SYS_WRITEC, (uintptr_t)&c); }

void sh_dec(uint64_t v) {
    char buf[21]; /* 2^64 - 1 has 20 digits, plus NUL */
    char* p = buf + sizeof buf - 1;
    *p = '\0';
    do {
        *--p = (char)('0' + (unsigned)(v % 10u));
        v /= 10u;
    } while (v != 0);
    sh_write(p);
}

void sh_hex(uint64_t v, unsigned digits) {
    char buf[17];
    if (digits > 16) digits = 16;
    char* p = buf + digits;
    *p = '\0';
    while (p != buf) {
        *--p = "0123456789abcdef"[v & 15u];
        v >>= 4;
    }
    sh_write(buf);
}

void sh_exit(int status) {
    /* SYS_EXIT_EXTENDED carries the status (QEMU: exit(subcode) for ApplicationExit). */
    const uintptr_t block[2] = {ADP_Stopped_ApplicationExit, (uintptr_t)(unsigned)status};
    sh_call(SYS_EXIT_EXTENDED, (uintptr_t)block);
    /* Host without the extension: plain SYS_EXIT only tells success (0) from failure (1). */
    sh_call(SYS_EXIT, status == 0 ? ADP_Stopped_ApplicationExit : ADP_Stopped_RunTimeErrorUnknown);
    for (;;) __asm__ volatile("bkpt 0"); /* no host at all: stop here for a debugger */
}
