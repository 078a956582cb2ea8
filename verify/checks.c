#include "checks.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "ensemble.h"

void vfy_report_init(vfy_report *r, FILE *echo)
{
    memset(r, 0, sizeof *r);
    r->echo = echo;
}

void vfy_report_free(vfy_report *r)
{
    free(r->checks);
    memset(r, 0, sizeof *r);
}

static const char *verdict_word(vfy_verdict v)
{
    return v == VFY_PASS ? "PASS" : v == VFY_FAIL ? "FAIL" : "SKIP";
}

/* The one place a verdict is recorded. */
__attribute__((format(printf, 4, 5)))
static vfy_verdict record(vfy_report *r, vfy_verdict v, const char *name, const char *fmt, ...)
{
    if (r->count == r->capacity) {
        size_t cap = r->capacity ? 2 * r->capacity : 32;
        vfy_check *grown = realloc(r->checks, cap * sizeof *grown);
        if (grown == NULL) {   /* keep counting failures even without memory for text */
            r->failed += v == VFY_FAIL;
            return v;
        }
        r->checks = grown;
        r->capacity = cap;
    }
    vfy_check *c = &r->checks[r->count++];
    c->verdict = v;
    snprintf(c->name, sizeof c->name, "%s", name);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->detail, sizeof c->detail, fmt, ap);
    va_end(ap);
    r->failed += v == VFY_FAIL;
    if (r->echo) {
        fprintf(r->echo, "%s  %s: %s\n", verdict_word(v), c->name, c->detail);
        fflush(r->echo);
    }
    return v;
}

vfy_verdict vfy_check_relative(vfy_report *r, const char *name, double value, double expected,
                               double rtol)
{
    double dev = value / expected - 1.0;
    vfy_verdict v = isfinite(dev) && fabs(dev) <= rtol ? VFY_PASS : VFY_FAIL;
    return record(r, v, name, "%.4g vs %.4g (%+.1f%%, allowed ±%.0f%%)", value, expected,
                  100.0 * dev, 100.0 * rtol);
}

vfy_verdict vfy_check_range(vfy_report *r, const char *name, double value, double lo, double hi)
{
    vfy_verdict v = value >= lo && value <= hi ? VFY_PASS : VFY_FAIL;
    return record(r, v, name, "%.4g (allowed [%g, %g])", value, lo, hi);
}

vfy_verdict vfy_check_absolute(vfy_report *r, const char *name, double value, double expected,
                               double atol)
{
    vfy_verdict v = fabs(value - expected) <= atol ? VFY_PASS : VFY_FAIL;
    return record(r, v, name, "%.6g vs %.6g (|diff| %.2g, allowed %.2g)", value, expected,
                  fabs(value - expected), atol);
}

vfy_verdict vfy_check_zscore(vfy_report *r, const char *name, const double *mean,
                             const double *ci, const double *exact, size_t count, double zmax,
                             double *max_z)
{
    double worst = 0.0;
    size_t at = 0;
    int exact_mismatch = 0;
    for (size_t m = 0; m < count; m++) {
        double diff = fabs(mean[m] - exact[m]);
        if (ci[m] > 0.0) {
            double z = diff / (ci[m] / SIM_LAMBDA_P);
            if (!(z <= worst)) {   /* also catches NaN */
                worst = z;
                at = m;
            }
        } else if (!(diff <= 1e-12 * fabs(exact[m]))) {
            exact_mismatch = 1;
            at = m;
        }
    }
    if (max_z)
        *max_z = exact_mismatch ? INFINITY : worst;
    if (exact_mismatch)
        return record(r, VFY_FAIL, name, "point %zu: %.10g differs from exact %.10g with no "
                      "statistical error", at, mean[at], exact[at]);
    vfy_verdict v = worst <= zmax ? VFY_PASS : VFY_FAIL;
    return record(r, v, name, "max |z| = %.2f at point %zu (allowed %.1f; mean %.6g, exact %.6g)",
                  worst, at, zmax, count ? mean[at] : 0.0, count ? exact[at] : 0.0);
}

vfy_verdict vfy_check_printed(vfy_report *r, const char *name, double value, double ci,
                              double printed, int digits)
{
    double rounding = 0.5 * pow(10.0, -digits), dev = fabs(value - printed);
    vfy_verdict v = dev <= rounding + ci ? VFY_PASS : VFY_FAIL;
    return record(r, v, name, "%.6g vs %.*f printed (|diff| %.2g, allowed %.2g: rounding %.2g "
                  "+ ci %.2g)", value, digits, printed, dev, rounding + ci, rounding, ci);
}

vfy_verdict vfy_check_count(vfy_report *r, const char *name, uint64_t value, uint64_t expected)
{
    vfy_verdict v = value == expected ? VFY_PASS : VFY_FAIL;
    return record(r, v, name, "%llu (expected %llu)", (unsigned long long)value,
                  (unsigned long long)expected);
}

vfy_verdict vfy_check_true(vfy_report *r, const char *name, int ok, const char *fmt, ...)
{
    char detail[sizeof r->checks[0].detail];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(detail, sizeof detail, fmt, ap);
    va_end(ap);
    return record(r, ok ? VFY_PASS : VFY_FAIL, name, "%s", detail);
}

void vfy_skip(vfy_report *r, const char *name, const char *reason)
{
    record(r, VFY_SKIP, name, "%s", reason);
}
