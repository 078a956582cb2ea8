/* Helpers shared by the reference-layer tests: output grids, CVODE options,
 * and failures with their messages. */
#ifndef GDSMC_TEST_REFERENCE_UTIL_H
#define GDSMC_TEST_REFERENCE_UTIL_H

#include <string.h>

#include "ode.h"
#include "sonine.h"
#include "test_util.h"

static inline void grid(double *t, size_t n, double t_end)
{
    for (size_t m = 0; m < n; m++)
        t[m] = t_end * (double)m / (double)(n - 1);
}

static inline ref_ode_options opts(ref_ode_method method, double rtol, double atol)
{
    ref_ode_options o = ref_ode_default_options();
    o.method = method;
    o.rtol = rtol;
    o.atol = atol;
    return o;
}

/* Assert a status and that the message contains each of up to two fragments. */
static inline void assert_failure(ref_status st, ref_status expected, const char *msg,
                                  const char *frag1, const char *frag2)
{
    if (st != expected || !strstr(msg, frag1) || (frag2 && !strstr(msg, frag2)))
        print_error("status %d (expected %d), message \"%s\", wanted \"%s\"%s%s\n", (int)st,
                    (int)expected, msg, frag1, frag2 ? " and " : "", frag2 ? frag2 : "");
    assert_int_equal(st, expected);
    assert_non_null(strstr(msg, frag1));
    if (frag2)
        assert_non_null(strstr(msg, frag2));
}

/* The value named `name` of a listing (ref_sonine_all); fails the test if
 * there is none. */
static inline double lookup(const ref_sonine_value *v, size_t n, const char *name)
{
    for (size_t i = 0; i < n; i++)
        if (strcmp(v[i].name, name) == 0)
            return v[i].value;
    fail_msg("no value named %s", name);
    return NAN;
}

#endif
