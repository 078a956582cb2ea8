/* Every kind of verification check passes a right answer and fails a wrong
 * one (a check must be able to fail: docs/verdicts.md). */
#include "test_util.h"

#include <string.h>

#include "checks.h"
#include "text.h"
#include "verdicts.h"

static void test_relative(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    /* paper A Table 1, n = 256: Emax 0.235E-01 */
    assert_int_equal(vfy_check_relative(&r, "near", 0.0251, 0.0235, 0.35), VFY_PASS);
    assert_int_equal(vfy_check_relative(&r, "double", 0.0470, 0.0235, 0.35), VFY_FAIL);
    assert_int_equal(vfy_check_relative(&r, "too small", 0.0150, 0.0235, 0.35), VFY_FAIL);
    assert_int_equal(vfy_check_relative(&r, "nan", NAN, 0.0235, 0.35), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 3);
    assert_string_equal(r.checks[1].detail, "0.047 vs 0.0235 (+100.0%, allowed ±35%)");
    vfy_report_free(&r);
}

static void test_range_and_absolute(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    assert_int_equal(vfy_check_range(&r, "CF", 3.81, 3.2, 5.0), VFY_PASS);
    assert_int_equal(vfy_check_range(&r, "CF", 2.02, 3.2, 5.0), VFY_FAIL);   /* O(1/sqrt n) */
    assert_int_equal(vfy_check_range(&r, "CF", NAN, 3.2, 5.0), VFY_FAIL);
    assert_int_equal(vfy_check_absolute(&r, "T*", 0.9562, 0.956, 5e-4), VFY_PASS);
    assert_int_equal(vfy_check_absolute(&r, "T*", 0.9530, 0.956, 5e-4), VFY_FAIL);
    assert_int_equal(vfy_check_count(&r, "violations", 0, 0), VFY_PASS);
    assert_int_equal(vfy_check_count(&r, "violations", 3, 0), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 4);
    vfy_report_free(&r);
}

/* Paper B Ex 4 prints the kinetic T* = 0.953 (3 decimals).  At paper sizes
 * (T* = 0.95344 ± 0.00040) the kinetic value passes and the LE closure's
 * steady value 0.95571, 0.0027 away, must fail: the old band of ±0.004
 * passed it. */
static void test_printed(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    assert_int_equal(vfy_check_printed(&r, "kinetic", 0.95344, 0.00040, 0.953, 3), VFY_PASS);
    assert_int_equal(vfy_check_printed(&r, "closure", 0.95571, 0.00040, 0.953, 3), VFY_FAIL);
    assert_int_equal(vfy_check_absolute(&r, "old band", 0.95571, 0.953, 0.004), VFY_PASS);
    /* a deterministic value: the rounding alone */
    assert_int_equal(vfy_check_printed(&r, "LE", 0.95571, 0.0, 0.956, 3), VFY_PASS);
    assert_int_equal(vfy_check_printed(&r, "LE off", 0.95545, 0.0, 0.956, 3), VFY_FAIL);
    assert_int_equal(vfy_check_printed(&r, "nan", NAN, 0.0, 0.956, 3), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 3);
    assert_string_equal(r.checks[1].detail, "0.95571 vs 0.953 printed (|diff| 0.0027, allowed "
                                            "0.0009: rounding 0.0005 + ci 0.0004)");
    vfy_report_free(&r);
}

/* z-scores: ci = 3.2 sigma; a mean 3 sigma off passes zmax = 4.5, 6 sigma
 * off fails; an exact point (ci = 0) must match exactly. */
static void test_zscore(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    const double exact[4] = {1.0, 2.0, 2.5, 2.6};
    const double ci[4] = {0.0, 0.032, 0.032, 0.032};
    double mean[4] = {1.0, 2.0 + 0.03, 2.5 - 0.02, 2.6};
    double z;
    assert_int_equal(vfy_check_zscore(&r, "ok", mean, ci, exact, 4, 4.5, &z), VFY_PASS);
    assert_close(z, 3.0, 1e-12, 0.0);
    mean[2] = 2.5 + 0.06;   /* 6 sigma */
    assert_int_equal(vfy_check_zscore(&r, "biased", mean, ci, exact, 4, 4.5, &z), VFY_FAIL);
    assert_close(z, 6.0, 1e-12, 0.0);
    mean[2] = 2.5;
    mean[0] = 1.0 + 1e-9;   /* an exact point that is off */
    assert_int_equal(vfy_check_zscore(&r, "exact point", mean, ci, exact, 4, 4.5, NULL),
                     VFY_FAIL);
    mean[0] = 1.0;
    mean[3] = NAN;
    assert_int_equal(vfy_check_zscore(&r, "nan", mean, ci, exact, 4, 4.5, NULL), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 3);
    vfy_report_free(&r);
}

/* NaN fails every check, unless the report says the data may be
 * incomplete (an external solver's result): then it is a SKIP with that
 * reason, and a finite wrong value still fails. */
static void test_missing_is_skip(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    const double nan_series[2] = {1.0, NAN}, ci[2] = {0.1, 0.1}, exact[2] = {1.0, 1.0};
    assert_int_equal(vfy_check_range(&r, "range", NAN, 3.2, 5.0), VFY_FAIL);
    assert_int_equal(vfy_check_zscore(&r, "z", nan_series, ci, exact, 2, 4.5, NULL), VFY_FAIL);
    r.missing = "needs quantities the solver did not report";
    assert_int_equal(vfy_check_range(&r, "range", NAN, 3.2, 5.0), VFY_SKIP);
    assert_string_equal(r.checks[r.count - 1].detail, "needs quantities the solver did not report");
    assert_int_equal(vfy_check_relative(&r, "relative", NAN, 1.0, 0.35), VFY_SKIP);
    assert_int_equal(vfy_check_absolute(&r, "absolute", 1.0, NAN, 0.1), VFY_SKIP);
    assert_int_equal(vfy_check_printed(&r, "printed", NAN, 0.0, 0.953, 3), VFY_SKIP);
    assert_int_equal(vfy_check_zscore(&r, "z", nan_series, ci, exact, 2, 4.5, NULL), VFY_SKIP);
    assert_int_equal(vfy_check_range(&r, "range", 2.0, 3.2, 5.0), VFY_FAIL);
    assert_int_equal(vfy_check_zero(&r, "violations", NAN), VFY_SKIP);
    assert_int_equal(vfy_check_zero(&r, "violations", 3.0), VFY_FAIL);
    assert_int_equal(vfy_check_zero(&r, "violations", 0.0), VFY_PASS);
    r.missing = NULL;
    assert_int_equal(vfy_check_zero(&r, "violations", NAN), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 5);
    vfy_report_free(&r);
}

static void test_skip_is_not_failure(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    vfy_skip(&r, "CF", "noise-dominated");
    assert_int_equal(r.counts[VFY_FAIL], 0);
    assert_int_equal(r.count, 1);
    assert_int_equal(r.checks[0].verdict, VFY_SKIP);
    assert_string_equal(r.checks[0].detail, "noise-dominated");
    vfy_report_free(&r);
}

/* A paper comparison with a declared known difference (r.differs): its
 * FAIL is a DIFFERS, counted apart and never a failure; its PASS stays a
 * PASS, and the checks after it fail again.  docs/verdicts.md. */
static void test_differs_is_not_failure(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    r.differs = "E: EHS and IHS agree in -Pxy/nT";
    assert_int_equal(vfy_check_relative(&r, "ehs", 0.96, 1.0, 0.03), VFY_DIFFERS);
    assert_int_equal(vfy_check_relative(&r, "ehs near", 0.98, 1.0, 0.03), VFY_PASS);
    r.differs = NULL;
    assert_int_equal(vfy_check_relative(&r, "ehs judged", 0.96, 1.0, 0.03), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 1);
    assert_int_equal(r.counts[VFY_DIFFERS], 1);
    assert_int_equal(r.counts[VFY_PASS], 1);
    assert_int_equal(r.counts[VFY_FAIL], 1);
    assert_string_equal(r.checks[0].detail, "0.96 vs 1 (-4.0%, allowed ±3%); known difference: "
                                            "E: EHS and IHS agree in -Pxy/nT");
    assert_string_equal(vfy_verdict_word(r.checks[0].verdict), "DIFFERS");
    /* what was judged, for the verdicts file */
    assert_true(r.checks[0].value == 0.96 && r.checks[0].reference == 1.0);
    assert_string_equal(r.checks[0].allowed, "±3%");
    vfy_report_free(&r);
}

/* The verdicts file's CSV fields read back as written: quotes and commas. */
static void test_csv_split(void **state)
{
    (void)state;
    char line[] = "{case} n={n} CF,\"a, b\",PASS,1.5,,\"[3.2, 5]\",\"say \"\"hi\"\"\",x\n";
    char *f[8];
    assert_int_equal(vfy_csv_split(line, f, 8), 8);
    assert_string_equal(f[0], "{case} n={n} CF");
    assert_string_equal(f[1], "a, b");
    assert_string_equal(f[4], "");
    assert_string_equal(f[5], "[3.2, 5]");
    assert_string_equal(f[6], "say \"hi\"");
    assert_string_equal(f[7], "x");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_relative),
        cmocka_unit_test(test_printed),
        cmocka_unit_test(test_range_and_absolute),
        cmocka_unit_test(test_zscore),
        cmocka_unit_test(test_skip_is_not_failure),
        cmocka_unit_test(test_missing_is_skip),
        cmocka_unit_test(test_differs_is_not_failure),
        cmocka_unit_test(test_csv_split),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
