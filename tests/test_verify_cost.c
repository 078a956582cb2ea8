/* The accuracy-cost report (verify/cases/case_cost.h, docs/theory.md §1.4): each of its check
 * kinds passes a right answer and fails a wrong one, its pieces give known
 * answers, and the three cost cases at quick sizes pass with the right solver
 * and fail with a deliberately wrong one (--solver-set). */
#include "case_cost.h"
#include "test_verify_util.h"

#include "driver.h"

/* The cheapest point reaching a target: least cost among err <= target; a
 * tie in cost goes to the smaller error; none: count. */
static void test_cheapest(void **state)
{
    (void)state;
    const double err[] = {3.1e-2, 8.7e-3, 9.9e-4, 6.2e-3, NAN, 4.4e-3};
    const double cost[] = {0.12, 1.9, 41.0, 7.5, 0.01, 1.9};
    assert_int_equal(vfy_cost_cheapest(err, cost, 6, 1e-2), 5);   /* ties 1, smaller Err */
    assert_int_equal(vfy_cost_cheapest(err, cost, 6, 5e-3), 5);
    assert_int_equal(vfy_cost_cheapest(err, cost, 6, 1e-3), 2);
    assert_int_equal(vfy_cost_cheapest(err, cost, 6, 1e-4), 6);   /* not reached; NaN never */
    assert_int_equal(vfy_cost_cheapest(err, cost, 0, 1.0), 0);
}

/* Weighted least squares in two unknowns recovers exact coefficients and
 * refuses a singular system. */
static void test_lsq2(void **state)
{
    (void)state;
    double x1[5], x2[5], y[5], w[5], c[2], chi2;
    for (int i = 0; i < 5; i++) {   /* y = 2.385/n - 0.731/n^2 */
        double n = 16.0 * (1 << (2 * i));
        x1[i] = 1.0 / n;
        x2[i] = 1.0 / (n * n);
        y[i] = 2.385 * x1[i] - 0.731 * x2[i];
        w[i] = 1.0 / (y[i] * y[i]);
    }
    assert_int_equal(vfy_cost_lsq2(5, x1, x2, y, w, c, &chi2), 0);
    assert_close(c[0], 2.385, 1e-10, 0.0);
    assert_close(c[1], -0.731, 1e-8, 0.0);
    assert_close(chi2, 0.0, 0.0, 1e-16);
    y[2] *= 1.1;   /* one point 10% off: chi^2 = w e^2 > 0 */
    assert_int_equal(vfy_cost_lsq2(5, x1, x2, y, w, c, &chi2), 0);
    assert_true(chi2 > 1e-4);
    assert_int_equal(vfy_cost_lsq2(1, x1, x2, y, w, c, NULL), -1);
    assert_int_equal(vfy_cost_lsq2(5, x1, x1, y, w, c, NULL), -1);   /* collinear */
}

/* The statistical part scales as 1/sqrt(N): Conf falls by 2 from N = 128 to
 * 512.  Wrong answers: 1/N (a factor 4) and no N dependence (correlated
 * ensembles) both fail, and so does N2 <= N1. */
static void test_stat_scaling(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    const double conf1[] = {8.31e-2, 4.02e-2, 2.11e-2, 1.03e-2, 5.2e-3};
    double right[5], quarter[5], same[5], ratio;
    for (int i = 0; i < 5; i++) {
        right[i] = conf1[i] / 2.0 * (i % 2 ? 1.04 : 0.97);   /* estimation noise */
        quarter[i] = conf1[i] / 4.0;
        same[i] = conf1[i];
    }
    assert_int_equal(vfy_cost_check_stat_scaling(&r, "right", conf1, right, 5, 128, 512, 1, 4.5,
                                                 &ratio), VFY_PASS);
    assert_close(ratio, 1.0, 0.03, 0.0);
    assert_int_equal(vfy_cost_check_stat_scaling(&r, "1/N", conf1, quarter, 5, 128, 512, 1, 4.5,
                                                 &ratio), VFY_FAIL);
    assert_close(ratio, 2.0, 1e-12, 0.0);
    assert_int_equal(vfy_cost_check_stat_scaling(&r, "no N", conf1, same, 5, 128, 512, 1, 4.5,
                                                 &ratio), VFY_FAIL);
    assert_int_equal(vfy_cost_check_stat_scaling(&r, "N2 <= N1", conf1, right, 5, 512, 512, 1,
                                                 4.5, NULL), VFY_FAIL);
    /* quick sizes (N = 64, 256, three n): the band is wider, 1/N still fails */
    assert_int_equal(vfy_cost_check_stat_scaling(&r, "quick 1/N", conf1, quarter, 3, 64, 256, 1,
                                                 4.5, NULL), VFY_FAIL);
    /* independent runs (an external solver): the wider band of 1/N1 + 1/N2 */
    assert_int_equal(vfy_cost_check_stat_scaling(&r, "independent", conf1, right, 5, 128, 512, 0,
                                                 4.5, NULL), VFY_PASS);
    assert_int_equal(vfy_cost_check_stat_scaling(&r, "independent 1/N", conf1, quarter, 5, 128,
                                                 512, 0, 4.5, NULL), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 5);
    vfy_report_free(&r);
}

/* The error model against the measured Err: within a factor 2 passes; a
 * model three times too small or too large fails, as does NaN. */
static void test_model_check(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    const double err[] = {1.28e-1, 2.81e-2, 6.8e-3, 1.15e-2};
    double model[4], worst;
    for (int i = 0; i < 4; i++)
        model[i] = err[i] * (i == 2 ? 1.38 : 0.9);
    assert_int_equal(vfy_cost_check_model(&r, "right", err, model, 4, 2.0, &worst), VFY_PASS);
    assert_close(worst, 1.0 / 1.38, 1e-12, 0.0);
    model[1] = err[1] / 3.0;   /* the systematic part missed */
    assert_int_equal(vfy_cost_check_model(&r, "too small", err, model, 4, 2.0, &worst),
                     VFY_FAIL);
    assert_close(worst, 3.0, 1e-12, 0.0);
    model[1] = err[1] * 3.0;
    assert_int_equal(vfy_cost_check_model(&r, "too large", err, model, 4, 2.0, NULL),
                     VFY_FAIL);
    model[1] = NAN;
    assert_int_equal(vfy_cost_check_model(&r, "nan", err, model, 4, 2.0, NULL), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 3);
    vfy_report_free(&r);
}

/* chi^2 of a fit against its 0.999 quantile (13.8 for 2 degrees of freedom);
 * no degrees of freedom: skipped, never failed. */
static void test_chi2(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    assert_int_equal(vfy_cost_check_chi2(&r, "fits", 2.7, 2), VFY_PASS);
    assert_int_equal(vfy_cost_check_chi2(&r, "wrong order", 41.5, 2), VFY_FAIL);
    assert_int_equal(vfy_cost_check_chi2(&r, "wrong order", 24.0, 5), VFY_FAIL);
    assert_int_equal(vfy_cost_check_chi2(&r, "nan", NAN, 5), VFY_FAIL);
    assert_int_equal(vfy_cost_check_chi2(&r, "no dof", 0.0, 0), VFY_SKIP);
    assert_int_equal(r.counts[VFY_FAIL], 3);
    vfy_report_free(&r);
}

/* Failed checks of a cost case at quick sizes with a wrong solver; the
 * number of checks judged (passed) in *passed. */
static size_t run_case(const char *case_name, const char *const *wrong, size_t nwrong,
                       size_t *passed)
{
    return count_quick_failed(case_name, NULL, 0, wrong, nwrong, passed);
}

/* Paper A Ex 3: restitution 0.45 instead of 0.5 moves T_inf by 5%: the
 * exact finite-n z-tests fail, and the Err model (built on the exact
 * systematic part) with them. */
static void test_cost_grw_ex3(void **state)
{
    (void)state;
    size_t passed;
    assert_int_equal(run_case("cost-grw-ex3", NULL, 0, &passed), 0);
    assert_true(passed >= 9);
    const char *wrong[] = {"collisions.restitution=0.45"};
    assert_true(run_case("cost-grw-ex3", wrong, 1, NULL) >= 3);
}

/* Paper B Ex 2: binary collisions twice too frequent (Kn = 1/4). */
static void test_cost_brs_ex2(void **state)
{
    (void)state;
    size_t passed;
    assert_int_equal(run_case("cost-brs-ex2", NULL, 0, &passed), 0);
    assert_true(passed >= 9);
    const char *wrong[] = {"collisions.constant=0.25"};
    assert_true(run_case("cost-brs-ex2", wrong, 1, NULL) >= 3);
}

/* The time-step axis: time-step rows of another gas (heating 20% stronger
 * than the jump rows') leave an offset that no c1 h^p + c2 h^(p+1) fits. */
static void test_cost_split_ex5(void **state)
{
    (void)state;
    size_t passed;
    assert_int_equal(run_case("cost-split-ex5", NULL, 0, &passed), 0);
    assert_true(passed >= 6);
    const char *wrong[] = {"heating.strength=0.15"};
    assert_true(run_case("cost-split-ex5", wrong, 1, NULL) >= 2);
}

/* A grid larger than the hook once allowed (64 points, 8 values an axis):
 * 9 values of n by 8 of N, tiny systems, runs and draws one curve per N. */
static void test_big_grid(void **state)
{
    (void)state;
    vfy_case_desc d = *vfy_case_find("cost-grw-ex3")->desc;
    d.quick_rows = (vfy_sweep){
        .keys = VFY_KEYS({"particles.n", "2 3 4 5 6 7 8 9 10", NULL},
                         {"particles.ensembles", "8 16 24 32 40 48 56 64", NULL}),
        .grid = 1, .sets = "scene.outputs=5"};
    const vfy_case c = {"cost-big-grid", "cost", "", 0, &d};
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512], path[600], line[512];
    const sim_status st = vfy_run_described(&c, &o, &r, msg, sizeof msg);
    if (st != SIM_OK)
        print_error("%s\n", msg);
    assert_int_equal(st, SIM_OK);
    size_t scaling = 0;
    for (size_t i = 0; i < r.count; i++)
        scaling += strstr(r.checks[i].name, "pooled over n") != NULL;
    assert_int_equal(scaling, 7);   /* one per step of N */
    vfy_report_free(&r);
    snprintf(path, sizeof path, "%s/cost-big-grid-points.csv", out_dir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t curves = 0;
    while (fgets(line, sizeof line, f) != NULL)
        curves += strncmp(line, "# N = ", 6) == 0;
    fclose(f);
    assert_int_equal(curves, 8);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cheapest),
        cmocka_unit_test(test_lsq2),
        cmocka_unit_test(test_stat_scaling),
        cmocka_unit_test(test_model_check),
        cmocka_unit_test(test_chi2),
        cmocka_unit_test(test_cost_grw_ex3),
        cmocka_unit_test(test_cost_brs_ex2),
        cmocka_unit_test(test_cost_split_ex5),
        cmocka_unit_test(test_big_grid),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
