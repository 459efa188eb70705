/* The float-free check's canary: an image that does float and double arithmetic on a
 * soft-float target, so its link pulls in libgcc's helpers (__aeabi_fmul, __aeabi_i2f,
 * __aeabi_dmul, __aeabi_f2d ...) and float_symbols.cmake must find them. Never run. */
volatile int qt_canary_input = 3;

int main(void) {
    const float scaled = (float)qt_canary_input * 1.5f;
    const double doubled = (double)scaled * 2.5;
    return (int)doubled;
}
