/* The core's own sin, cos, atan2, hypot and asin (dmath.c): one implementation of the non-exact libm functions
 * the core calls, compiled into every build (native, WebAssembly), so that the same C gives the same bits
 * everywhere and the ids at exact ties do not depend on the platform's libm (issue 34, docs/js.md). Each is
 * within 1 ulp of the exact value over its whole domain (tests/index/test_dmath.py, against mpmath). sqrt,
 * fabs, floor, fmod, ldexp, frexp, rint and copysign are exact by IEEE 754 and stay libm's. */
#ifndef DGGS_DMATH_H
#define DGGS_DMATH_H

double dggs_sin(double x);
double dggs_cos(double x);
void dggs_sincos(double x, double *s, double *c);
double dggs_atan2(double y, double x);
double dggs_hypot(double x, double y);
double dggs_asin(double x);

#endif
