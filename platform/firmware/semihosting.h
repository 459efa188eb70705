/* Arm semihosting (BKPT 0xAB) for output and exit under QEMU with
 * -semihosting-config enable=on. No printf: strings and integers only. */
#pragma once
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

void sh_write(const char* s);             /* NUL-terminated string (SYS_WRITE0) */
void sh_putc(char c);                     /* one character (SYS_WRITEC) */
void sh_dec(uint64_t v);                  /* unsigned decimal */
void sh_hex(uint64_t v, unsigned digits); /* lower-case hex, zero-padded to digits (max 16) */

/* Ends the program: QEMU exits with `status` (mod 256). Does not return. */
__attribute__((noreturn)) void sh_exit(int status);

#ifdef __cplusplus
}
#endif
