/* The WebAssembly half of js/tools/libm/ties.py: wasi-libc's libm (musl's) on arguments the native core passed
 * to glibc's. Function numbers as trace.c's. */
#include <math.h>

__attribute__((export_name("libm"))) double libm(int fn, double x, double y);

double libm(int fn, double x, double y) {
    switch (fn) {
    case 0: return sin(x);
    case 1: return cos(x);
    case 2: return asin(x);
    case 3: return atan2(x, y);
    case 4: return hypot(x, y);
    case 5: return pow(x, y);
    case 6: return acos(x);
    case 7: return atan(x);
    default: return tan(x);
    }
}
