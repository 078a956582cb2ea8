#include "checks.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "ensemble.h"
#include "table.h"
#include "text.h"

void vfy_report_init(vfy_report *r, FILE *echo)
{
    memset(r, 0, sizeof *r);
    r->echo = echo;
}

void vfy_report_free(vfy_report *r)
{
    for (size_t i = 0; i < r->count; i++)
        free(r->checks[i].text);
    free(r->checks);
    memset(r, 0, sizeof *r);
}

const char *vfy_verdict_word(vfy_verdict v)
{
    static const char *const words[VFY_VERDICTS] = {"FAIL", "PASS", "SKIP", "DIFFERS"};
    return (unsigned)v < VFY_VERDICTS ? words[v] : "?";
}

/* What a check judged: value against reference within allowed (a bound
 * printed with %g, or the text `range` when it is not NULL). */
typedef struct judged {
    double value, reference, allowed;
    const char *range;
} judged;
#define NOT_JUDGED ((judged){NAN, NAN, NAN, ""})

/* The check's texts in one allocation (c->text), each NUL-terminated:
 * group, id, row, name, allowed, detail; or all "" without memory. */
static void check_texts(vfy_check *c, const char *const texts[6])
{
    size_t len[6], total = 0;
    for (int k = 0; k < 6; k++)
        total += (len[k] = strlen(texts[k])) + 1;
    const char **field[6] = {&c->group, &c->id, &c->row, &c->name, &c->allowed, &c->detail};
    char *at = c->text = malloc(total);
    for (int k = 0; k < 6; k++) {
        *field[k] = at != NULL ? memcpy(at, texts[k], len[k] + 1) : "";
        at = at != NULL ? at + len[k] + 1 : NULL;
    }
}

/* The one place a verdict is recorded: a FAIL under r->differs becomes
 * DIFFERS, with the declared reason after the detail. */
__attribute__((format(printf, 5, 6)))
static vfy_verdict record(vfy_report *r, vfy_verdict v, judged j, const char *name,
                          const char *fmt, ...)
{
    if (v == VFY_FAIL && r->differs != NULL)
        v = VFY_DIFFERS;
    r->counts[v]++;
    if (r->count == r->capacity) {
        size_t cap = r->capacity ? 2 * r->capacity : 32;
        vfy_check *grown = realloc(r->checks, cap * sizeof *grown);
        if (grown == NULL)   /* keep counting even without memory for text */
            return v;
        r->checks = grown;
        r->capacity = cap;
    }
    vfy_check *c = &r->checks[r->count++];
    c->verdict = v;
    c->value = j.value;
    c->reference = j.reference;
    char allowed[64];
    if (j.range == NULL)
        snprintf(allowed, sizeof allowed, "%g", j.allowed);   /* at most 13 characters */
    vfy_text detail = {0};
    va_list ap;
    va_start(ap, fmt);
    vfy_text_vprintf(&detail, fmt, ap);
    va_end(ap);
    if (v == VFY_DIFFERS)
        vfy_text_printf(&detail, "; known difference: %s", r->differs);
    const char *const texts[6] = {r->group ? r->group : "gdsmc", r->check_id ? r->check_id : "",
                                  r->row ? r->row : "", name,
                                  j.range != NULL ? j.range : allowed, vfy_text_str(&detail)};
    check_texts(c, texts);
    vfy_text_free(&detail);
    if (r->echo) {
        fprintf(r->echo, "%s  %s: %s\n", vfy_verdict_word(v), c->name, c->detail);
        fflush(r->echo);
    }
    return v;
}

/* A NaN where the data may be incomplete (r->missing): a SKIP saying so. */
#define SKIP_IF_MISSING(r, name, x)                        \
    do {                                                   \
        if ((r)->missing != NULL && isnan(x)) {            \
            vfy_skip((r), (name), (r)->missing);           \
            return VFY_SKIP;                               \
        }                                                  \
    } while (0)

vfy_verdict vfy_check_relative(vfy_report *r, const char *name, double value, double expected,
                               double rtol)
{
    SKIP_IF_MISSING(r, name, value);
    double dev = value / expected - 1.0;
    vfy_verdict v = isfinite(dev) && fabs(dev) <= rtol ? VFY_PASS : VFY_FAIL;
    char band[48];
    snprintf(band, sizeof band, "±%g%%", 100.0 * rtol);
    return record(r, v, (judged){value, expected, rtol, band}, name,
                  "%.4g vs %.4g (%+.1f%%, allowed ±%.0f%%)", value, expected, 100.0 * dev,
                  100.0 * rtol);
}

vfy_verdict vfy_check_range(vfy_report *r, const char *name, double value, double lo, double hi)
{
    SKIP_IF_MISSING(r, name, value);
    vfy_verdict v = value >= lo && value <= hi ? VFY_PASS : VFY_FAIL;
    char range[48];
    snprintf(range, sizeof range, "[%g, %g]", lo, hi);
    return record(r, v, (judged){value, NAN, NAN, range}, name, "%.4g (allowed %s)", value,
                  range);
}

vfy_verdict vfy_check_absolute(vfy_report *r, const char *name, double value, double expected,
                               double atol)
{
    SKIP_IF_MISSING(r, name, value - expected);
    vfy_verdict v = fabs(value - expected) <= atol ? VFY_PASS : VFY_FAIL;
    return record(r, v, (judged){value, expected, atol, NULL}, name,
                  "%.6g vs %.6g (|diff| %.2g, allowed %.2g)", value, expected,
                  fabs(value - expected), atol);
}

vfy_verdict vfy_check_zscore(vfy_report *r, const char *name, const double *mean,
                             const double *ci, const double *exact, size_t count, double zmax,
                             double *max_z)
{
    for (size_t m = 0; m < count; m++)
        SKIP_IF_MISSING(r, name, mean[m] - exact[m]);
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
        return record(r, VFY_FAIL, (judged){INFINITY, 0.0, zmax, NULL}, name,
                      "point %zu: %.10g differs from exact %.10g with no statistical error", at,
                      mean[at], exact[at]);
    vfy_verdict v = worst <= zmax ? VFY_PASS : VFY_FAIL;
    return record(r, v, (judged){worst, 0.0, zmax, NULL}, name,
                  "max |z| = %.2f at point %zu (allowed %.2f; mean %.6g, exact %.6g)", worst, at,
                  zmax, count ? mean[at] : 0.0, count ? exact[at] : 0.0);
}

vfy_verdict vfy_check_printed(vfy_report *r, const char *name, double value, double ci,
                              double printed, int digits)
{
    SKIP_IF_MISSING(r, name, value);
    double rounding = 0.5 * pow(10.0, -digits), dev = fabs(value - printed);
    vfy_verdict v = dev <= rounding + ci ? VFY_PASS : VFY_FAIL;
    return record(r, v, (judged){value, printed, rounding + ci, NULL}, name,
                  "%.6g vs %.*f printed (|diff| %.2g, allowed %.2g: rounding %.2g + ci %.2g)",
                  value, digits, printed, dev, rounding + ci, rounding, ci);
}

vfy_verdict vfy_check_count(vfy_report *r, const char *name, uint64_t value, uint64_t expected)
{
    vfy_verdict v = value == expected ? VFY_PASS : VFY_FAIL;
    return record(r, v, (judged){(double)value, (double)expected, 0.0, NULL}, name,
                  "%llu (expected %llu)", (unsigned long long)value,
                  (unsigned long long)expected);
}

vfy_verdict vfy_check_zero(vfy_report *r, const char *name, double count)
{
    SKIP_IF_MISSING(r, name, count);
    if (!(count >= 0.0))
        return record(r, VFY_FAIL, (judged){count, 0.0, 0.0, NULL}, name, "%g (expected 0)", count);
    return vfy_check_count(r, name, (uint64_t)count, 0);
}

vfy_verdict vfy_check_true(vfy_report *r, const char *name, int ok, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *detail = vfy_vaprintf(fmt, ap);
    va_end(ap);
    const vfy_verdict v = record(r, ok ? VFY_PASS : VFY_FAIL, NOT_JUDGED, name, "%s",
                                 detail != NULL ? detail : "out of memory");
    free(detail);
    return v;
}

void vfy_skip(vfy_report *r, const char *name, const char *reason)
{
    record(r, VFY_SKIP, NOT_JUDGED, name, "%s", reason);
}

/* text with XML's five special characters escaped, and control characters
 * (which XML 1.0 cannot hold) as spaces. */
static void xml_text(FILE *f, const char *text)
{
    for (const unsigned char *p = (const unsigned char *)text; *p; p++) {
        switch (*p) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&apos;", f); break;
        default: fputc(*p < 0x20 ? ' ' : *p, f);
        }
    }
}

/* The counts of group g's checks by verdict (all groups when g is NULL). */
static void group_counts(const vfy_report *r, const char *g, size_t count[VFY_VERDICTS])
{
    memset(count, 0, VFY_VERDICTS * sizeof *count);
    for (size_t i = 0; i < r->count; i++)
        if (g == NULL || strcmp(r->checks[i].group, g) == 0)
            count[r->checks[i].verdict]++;
}

/* A DIFFERS is not judged against the solver: JUnit's <skipped>, its
 * message starting "DIFFERS: ". */
int vfy_report_write_junit(const vfy_report *r, const char *path, double seconds)
{
    char tmp[1100];
    FILE *f = vfy_file_begin(path, tmp, sizeof tmp);
    if (f == NULL)
        return -1;
    size_t all[VFY_VERDICTS];
    group_counts(r, NULL, all);
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"gdsmc verify\" "
               "tests=\"%zu\" failures=\"%zu\" skipped=\"%zu\" time=\"%.3f\">\n",
            r->count, all[VFY_FAIL], all[VFY_SKIP] + all[VFY_DIFFERS], seconds);
    for (size_t i = 0; i < r->count; i++) {
        const char *g = r->checks[i].group;
        size_t first = 0;   /* a group's suite opens at its first check */
        while (strcmp(r->checks[first].group, g) != 0)
            first++;
        if (first != i)
            continue;
        size_t n[VFY_VERDICTS];
        group_counts(r, g, n);
        fputs("  <testsuite name=\"", f);
        xml_text(f, g);
        fprintf(f, "\" tests=\"%zu\" failures=\"%zu\" skipped=\"%zu\">\n",
                n[0] + n[1] + n[2] + n[3], n[VFY_FAIL], n[VFY_SKIP] + n[VFY_DIFFERS]);
        for (size_t k = i; k < r->count; k++) {
            const vfy_check *c = &r->checks[k];
            if (strcmp(c->group, g) != 0)
                continue;
            fputs("    <testcase classname=\"", f);
            xml_text(f, g);
            fputs("\" name=\"", f);
            xml_text(f, c->name);
            static const char *const open[VFY_VERDICTS] = {
                "\">\n      <failure message=\"", "\">\n      <system-out>",
                "\">\n      <skipped message=\"", "\">\n      <skipped message=\"DIFFERS: "};
            fputs(open[c->verdict], f);
            xml_text(f, c->detail);
            fputs(c->verdict == VFY_PASS ? "</system-out>\n" : "\"/>\n", f);
            fputs("    </testcase>\n", f);
        }
        fputs("  </testsuite>\n", f);
    }
    fputs("</testsuites>\n", f);
    return vfy_file_commit(f, tmp, path, 1);
}
