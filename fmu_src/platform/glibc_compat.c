/* The FMU binaries load on glibc 2.17 (the manylinux2014 baseline: RHEL/CentOS 7 and 8, Ubuntu
 * 18.04), although they are built on a newer glibc.
 *
 * glibc 2.29 gave exp, exp2, log, log2 and pow new symbol versions (new implementations without
 * the SVID error handling), and glibc 2.35 hypot (used by the exact engine); a binary linked
 * against them needs that glibc. The linker redirects
 * every call of these functions, SUNDIALS' included (-Wl,--wrap=pow etc., see CMakeLists.txt),
 * to the wrappers below, which call the x86-64 baseline versions (GLIBC_2.2.5). On a new glibc
 * those are compatibility wrappers around the same implementation, so results do not change.
 * Only the CMake build of the FMU binaries uses this file; a build from the FMU's sources does not
 * need it. tests/c/check_glibc_versions.cmake checks the result. */
#include <math.h> /* defines __GLIBC__ on glibc */

#if defined(__GLIBC__) && defined(__x86_64__)

#define BASELINE_LIBM(name) __asm__(".symver glibc_baseline_" #name ", " #name "@GLIBC_2.2.5")

BASELINE_LIBM(exp);
BASELINE_LIBM(exp2);
BASELINE_LIBM(log);
BASELINE_LIBM(log2);
BASELINE_LIBM(pow);
BASELINE_LIBM(hypot);

double glibc_baseline_exp(double x);
double glibc_baseline_exp2(double x);
double glibc_baseline_log(double x);
double glibc_baseline_log2(double x);
double glibc_baseline_pow(double x, double y);
double glibc_baseline_hypot(double x, double y);

double __wrap_exp(double x);
double __wrap_exp2(double x);
double __wrap_log(double x);
double __wrap_log2(double x);
double __wrap_pow(double x, double y);
double __wrap_hypot(double x, double y);

double __wrap_exp(double x) { return glibc_baseline_exp(x); }
double __wrap_exp2(double x) { return glibc_baseline_exp2(x); }
double __wrap_log(double x) { return glibc_baseline_log(x); }
double __wrap_log2(double x) { return glibc_baseline_log2(x); }
double __wrap_pow(double x, double y) { return glibc_baseline_pow(x, y); }
double __wrap_hypot(double x, double y) { return glibc_baseline_hypot(x, y); }

#else
typedef int glibc_compat_not_needed; /* ISO C forbids an empty translation unit */
#endif
