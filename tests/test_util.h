/* Shared helpers for the cmocka tests.
 *
 * cmocka 1.1.5's assert_float_equal compares in single precision, so every
 * floating-point comparison goes through assert_close(), which prints both
 * numbers with %.17g on failure.
 */
#ifndef GDSMC_TEST_UTIL_H
#define GDSMC_TEST_UTIL_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <cmocka.h>

/* Pass when |actual - expected| <= atol + rtol |expected|. */
#define assert_close(actual, expected, rtol, atol) \
    assert_close_at((actual), (expected), (rtol), (atol), #actual, __FILE__, __LINE__)

static inline void assert_close_at(double actual, double expected, double rtol, double atol,
                                   const char *what, const char *file, int line)
{
    double tol = atol + rtol * fabs(expected);
    if (!(fabs(actual - expected) <= tol)) {
        print_error("%s = %.17g, expected %.17g (|diff| %.3g > tol %.3g)\n", what, actual,
                    expected, fabs(actual - expected), tol);
        _fail(file, line);
    }
}

#endif
