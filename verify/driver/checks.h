/* Verification checks and their verdicts (docs/verdicts.md).
 *
 * Each check records one line, "PASS|FAIL|SKIP|DIFFERS  name: detail", in a
 * report; a report with any FAIL (counts[VFY_FAIL] > 0) makes `gdsmc verify`
 * exit 1.  Every kind of
 * check here has a test in tests/test_checks.c that hands it a wrong answer
 * and sees it fail.
 *
 * The verdicts mean (docs/verdicts.md):
 *   PASS     judged, and it held;
 *   FAIL     judged, and it did not: the solver is wrong;
 *   SKIP     not judged, with the reason;
 *   DIFFERS  a comparison with a paper's printed number or sentence that
 *            does not hold, where the case declares a known difference
 *            (r->differs: the reason, and the independent check that judges
 *            the solver instead).  Never a failure.
 */
#ifndef GDSMC_VFY_CHECKS_H
#define GDSMC_VFY_CHECKS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef enum vfy_verdict {
    VFY_FAIL = 0,
    VFY_PASS = 1,
    VFY_SKIP = 2,
    VFY_DIFFERS = 3,
} vfy_verdict;
#define VFY_VERDICTS 4

/* The word a verdict prints as ("PASS", ...). */
const char *vfy_verdict_word(vfy_verdict v);

/* One recorded check.  Its texts are as long as they came (a case's check
 * names and reasons have no length limit): they point into `text`, one
 * allocation the report frees, or at "" when there was no memory for it. */
typedef struct vfy_check {
    vfy_verdict verdict;
    const char *group;   /* the report's group when it was made: the case */
    const char *id;      /* the report's check id when it was made (the check's
                            name before a row fills it in), or "" */
    const char *row;     /* the report's row when it was made, or "" */
    const char *name;
    const char *detail;
    double value, reference;   /* what was judged and against what (NaN where
                                  a check has none: a range, a SKIP) */
    const char *allowed;       /* the bound as text ("±35%", "[3.2, 5]", "4.5"), or "" */
    char *text;                /* the texts above, or NULL */
} vfy_check;

typedef struct vfy_report {
    vfy_check *checks;
    size_t count, capacity;
    FILE *echo;   /* if not NULL, each verdict is printed here as it is made */
    const char *group;  /* the case being judged (vfy_run sets it), or NULL */
    const char *missing;  /* if not NULL: a NaN value is a SKIP with this reason, not a FAIL
                             (data an external solver did not report; the driver sets it) */
    const char *check_id; /* if not NULL: the id the next checks carry (the driver sets it) */
    const char *row;      /* if not NULL: the row the next checks belong to */
    const char *differs;  /* if not NULL: a FAIL is recorded as DIFFERS, this text after
                             its detail (a paper comparison with a declared known
                             difference; the driver sets it) */
    size_t counts[VFY_VERDICTS];   /* the checks recorded, by verdict (counted even when
                                      there is no memory for their text) */
    size_t refused;   /* rows an external solver refused (their checks are SKIPs) */
} vfy_report;

void vfy_report_init(vfy_report *r, FILE *echo);
void vfy_report_free(vfy_report *r);

/* Write the report as JUnit XML to path (a testsuite per group, a testcase
 * per check with <failure> or <skipped> and the check's detail as message),
 * as CI systems read it; seconds is the run's wall time.  Returns 0, or -1
 * with errno when path cannot be written (nothing is left behind). */
int vfy_report_write_junit(const vfy_report *r, const char *path, double seconds);

/* |value / expected - 1| <= rtol: a value printed by a paper, within a band. */
vfy_verdict vfy_check_relative(vfy_report *r, const char *name, double value, double expected,
                               double rtol);

/* lo <= value <= hi: e.g. a convergence factor near 4. */
vfy_verdict vfy_check_range(vfy_report *r, const char *name, double value, double lo, double hi);

/* |value - expected| <= atol: e.g. a steady temperature to three digits. */
vfy_verdict vfy_check_absolute(vfy_report *r, const char *name, double value, double expected,
                               double atol);

/* Statistical agreement with an exact expectation at every point:
 * max_m |mean[m] - exact[m]| / (ci[m] / lambda_p) <= zmax, where ci is the
 * confidence half-width lambda_p sigma.  Points with ci = 0 must match exactly
 * (to 1e-12 relative).  *max_z (may be NULL) receives the largest |z|. */
vfy_verdict vfy_check_zscore(vfy_report *r, const char *name, const double *mean,
                             const double *ci, const double *exact, size_t count, double zmax,
                             double *max_z);

/* A number a paper prints rounded to `digits` decimals against our value
 * with confidence half-width ci: |value - printed| <= 0.5 10^-digits + ci
 * (0 for a deterministic value). */
vfy_verdict vfy_check_printed(vfy_report *r, const char *name, double value, double ci,
                              double printed, int digits);

/* value == expected: counters such as majorant violations. */
vfy_verdict vfy_check_count(vfy_report *r, const char *name, uint64_t value, uint64_t expected);

/* count == 0 for a count summed from the rows' values (NaN where a solver
 * did not report it: a SKIP with r->missing's reason, else a FAIL). */
vfy_verdict vfy_check_zero(vfy_report *r, const char *name, double count);

/* A condition judged by the caller (e.g. a pure check over a run's summary,
 * verify/cases/case_hard.h): PASS when ok, FAIL otherwise, with the detail. */
vfy_verdict vfy_check_true(vfy_report *r, const char *name, int ok, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* A check that does not apply here, with the reason (never a failure). */
void vfy_skip(vfy_report *r, const char *name, const char *reason);

#endif
