/* The hard suite (issue #5 item 1; verify/cases/case_hard.c): every hard check
 * fails on a deliberately broken solver.
 *
 * - The invariant checks are pure functions over a run's summary
 *   (verify/cases/case_hard.h); each gets a good summary (PASS) and corrupted ones
 *   (a NaN, a majorant violation, a momentum or energy drift, a heated
 *   "cooling" gas, a CVODE result that is garbage or a failure without a
 *   message), which must FAIL.
 * - The statistical checks run their case at quick sizes with a wrong solver
 *   through --solver-set (the references keep the right scene), and every
 *   named check must then FAIL; with the right solver the cheap cases pass.
 * Reports go to a temporary directory. */
#include <float.h>

#include "case_hard.h"
#include "test_verify_util.h"

/* ------------------------------------------------------ pure checks */

/* A summary that passes every invariant check: 4 ensembles of 1000
 * particles, momentum and energy at round-off. */
static vfy_hard_summary good_summary(void)
{
    vfy_hard_summary s;
    memset(&s, 0, sizeof s);
    s.ensembles = 4;
    s.n = 1000;
    s.candidates = 5000000;
    s.collisions = 1000000;
    s.values = 4848;
    s.momentum = 3.2e-16;
    s.speed = 2.385;
    s.T_first = 1.0;
    s.T_last = 1.0 + 2e-15;
    s.T_min = 1.0 - 1e-15;
    s.T_max = 1.0 + 3e-15;
    return s;
}

static vfy_verdict last_verdict(const vfy_report *r)
{
    return r->checks[r->count - 1].verdict;
}

static void test_summarize(void **state)
{
    (void)state;
    enum { M = 3, K = SIM_OBS_BASE };
    double mean[M * K], var[M * K], ci[M * K], t[M] = {0.0, 1.0, 2.0};
    for (size_t i = 0; i < M * K; i++) {
        mean[i] = 0.5;
        var[i] = 0.01;
        ci[i] = 0.1;
    }
    for (size_t m = 0; m < M; m++) {
        mean[m * K + SIM_OBS_T] = 2.385 - 0.5 * (double)m;   /* 2.385, 1.885, 1.385 */
        mean[m * K + SIM_OBS_T_RAW] = 2.0;
        var[m * K + SIM_OBS_T_RAW] = 0.25;
        for (int k = SIM_OBS_UX; k <= SIM_OBS_UZ; k++) {
            mean[m * K + k] = 0.0;
            var[m * K + k] = 1e-32;
        }
    }
    mean[1 * K + SIM_OBS_UY] = 3e-16;
    sim_ensemble_result res = {.outputs = M, .observables = K, .ensembles = 4, .n = 1000, .t = t,
                               .mean = mean, .var = var, .ci = ci};
    res.counts.candidates = 17;
    res.counts.violations = 2;
    vfy_hard_summary s;
    vfy_hard_summarize(&res, 1.0, &s);
    assert_int_equal(s.values, 3 * M * K);
    assert_int_equal(s.nonfinite, 0);
    assert_int_equal(s.violations, 2);
    assert_int_equal(s.candidates, 17);
    /* sqrt(N (var + mean^2)) bounds max_j |V_k| */
    assert_close(s.momentum, sqrt(4.0 * (1e-32 + 9e-32)), 1e-12, 0.0);
    assert_close(s.speed, sqrt(3.0 * sqrt(4.0 * (0.25 + 4.0))), 1e-12, 0.0);
    assert_close(s.T_first, mean[SIM_OBS_T], 0, 0);
    assert_close(s.T_last, mean[2 * K + SIM_OBS_T], 0, 0);
    assert_close(s.T_min, mean[2 * K + SIM_OBS_T], 0, 0);
    assert_close(s.T_max, mean[SIM_OBS_T], 0, 0);

    /* a NaN anywhere is found and counted; in u it also poisons the bound */
    var[2 * K + SIM_OBS_UZ] = NAN;
    vfy_hard_summarize(&res, 1.0, &s);
    assert_int_equal(s.nonfinite, 1);
    assert_int_equal(s.first_nonfinite, M * K + 2 * K + SIM_OBS_UZ);
    assert_true(isnan(s.momentum));
    ci[0] = INFINITY;
    vfy_hard_summarize(&res, 1.0, &s);
    assert_int_equal(s.nonfinite, 2);
    assert_int_equal(s.first_nonfinite, M * K + 2 * K + SIM_OBS_UZ);   /* var before ci */
    var[2 * K + SIM_OBS_UZ] = 0.01;
    vfy_hard_summarize(&res, 1.0, &s);
    assert_int_equal(s.nonfinite, 1);
    assert_int_equal(s.first_nonfinite, 2 * M * K);
}

static void test_bounds(void **state)
{
    (void)state;
    const double u = 0.5 * DBL_EPSILON;
    vfy_hard_summary s = good_summary();
    /* 6 u s (sqrt(2 U)/n + 2) and 6 u (8 sqrt(C)/n + 2 sqrt(n)) */
    assert_close(vfy_hard_momentum_bound(&s, 1e9), 6.0 * u * 2.385 * (sqrt(2e9) / 1000.0 + 2.0),
                 1e-14, 0.0);
    assert_close(vfy_hard_energy_bound(&s, 1e8), 6.0 * u * (8e4 / 1000.0 + 2.0 * sqrt(1000.0)),
                 1e-14, 0.0);
}

static void test_check_finite(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    vfy_hard_summary s = good_summary();
    assert_int_equal(vfy_hard_check_finite(&r, "run", &s), VFY_PASS);
    s.nonfinite = 1;
    s.first_nonfinite = 17;
    assert_int_equal(vfy_hard_check_finite(&r, "run", &s), VFY_FAIL);
    assert_non_null(strstr(r.checks[1].detail, "1 of 4848 values NaN or infinite"));
    s = good_summary();
    s.values = 0;   /* nothing inspected is no evidence */
    assert_int_equal(vfy_hard_check_finite(&r, "run", &s), VFY_FAIL);
    assert_string_equal(r.checks[0].name, "run no NaN or infinity");
    assert_int_equal(r.counts[VFY_FAIL], 2);
    vfy_report_free(&r);
}

static void test_check_violations(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    vfy_hard_summary s = good_summary();
    assert_int_equal(vfy_hard_check_violations(&r, "run", &s), VFY_PASS);
    s.violations = 1;   /* one candidate whose true rate exceeded the majorant */
    assert_int_equal(vfy_hard_check_violations(&r, "run", &s), VFY_FAIL);
    assert_string_equal(r.checks[1].detail,
                        "1 in 5000000 candidate events (expected 0; 1000000 accepted)");
    vfy_report_free(&r);
}

static void test_check_momentum(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    vfy_hard_summary s = good_summary();
    assert_int_equal(vfy_hard_check_momentum(&r, "run", &s, 1e6), VFY_PASS);
    /* momentum kept only to single precision (float velocities, or a
     * collision rule updating v and w with different roundings of g) */
    s.momentum = 1e-8;
    assert_int_equal(vfy_hard_check_momentum(&r, "run", &s, 1e6), VFY_FAIL);
    /* a small systematic drift: 1e-20 per update, 1e9 updates */
    s.momentum = 1e-11;
    assert_int_equal(vfy_hard_check_momentum(&r, "run", &s, 1e9), VFY_FAIL);
    s.momentum = NAN;
    assert_int_equal(vfy_hard_check_momentum(&r, "run", &s, 1e6), VFY_FAIL);
    s = good_summary();
    s.speed = NAN;   /* a NaN bound must not pass either */
    assert_int_equal(vfy_hard_check_momentum(&r, "run", &s, 1e6), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 4);
    vfy_report_free(&r);
}

static void test_check_energy(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    vfy_hard_summary s = good_summary();
    assert_int_equal(vfy_hard_check_energy(&r, "run", &s, 1e6), VFY_PASS);
    s.T_last = 1.0 + 1e-9;   /* an elastic collision rule losing energy slowly */
    assert_int_equal(vfy_hard_check_energy(&r, "run", &s, 1e6), VFY_FAIL);
    s = good_summary();
    s.T_min = 0.99;   /* ... or only in between */
    assert_int_equal(vfy_hard_check_energy(&r, "run", &s, 1e6), VFY_FAIL);
    s = good_summary();
    s.T_max = NAN;
    assert_int_equal(vfy_hard_check_energy(&r, "run", &s, 1e6), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 3);
    vfy_report_free(&r);
}

static void test_check_cooling_range(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    vfy_hard_summary s = good_summary();
    s.T_last = s.T_min = 0.0183;
    s.T_max = s.T_first;
    assert_int_equal(vfy_hard_check_cooling_range(&r, "run", &s), VFY_PASS);
    s.T_max = 1.001;   /* a gas without heating got hotter */
    assert_int_equal(vfy_hard_check_cooling_range(&r, "run", &s), VFY_FAIL);
    s.T_max = s.T_first;
    s.T_min = -1e-300;   /* negative temperature */
    assert_int_equal(vfy_hard_check_cooling_range(&r, "run", &s), VFY_FAIL);
    s.T_min = 0.0;   /* collapsed to 0 */
    assert_int_equal(vfy_hard_check_cooling_range(&r, "run", &s), VFY_FAIL);
    s.T_min = NAN;
    assert_int_equal(vfy_hard_check_cooling_range(&r, "run", &s), VFY_FAIL);
    s.T_min = 0.0183;
    s.T_max = INFINITY;
    assert_int_equal(vfy_hard_check_cooling_range(&r, "run", &s), VFY_FAIL);
    assert_int_equal(r.counts[VFY_FAIL], 5);
    vfy_report_free(&r);
}

static void test_check_ode(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    /* Paper B Ex 2's steady state T* = 64/67, reached on the grid */
    const double Ts = 64.0 / 67.0;
    double T[4] = {1.0, 0.97, 0.956, Ts}, Tx[4] = {1.0, 0.97, 0.956, Ts};
    double u[12] = {0, 0, 0, 0, 0.5, 0, 0, 0.9, 0, 0, 1, 0};
    vfy_hard_ode run = {.status = REF_OK, .msg = "", .nt = 4, .T = T, .u = u, .T_exact = Tx,
                        .T_steady = Ts, .rtol = 1e-6};
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_PASS);
    /* success reported with garbage */
    T[2] = NAN;
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_FAIL);
    T[2] = -0.956;
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_FAIL);
    T[2] = 0.956;
    u[7] = INFINITY;
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_FAIL);
    u[7] = 0.9;
    T[3] = Ts * (1.0 + 1e-4);   /* off the steady state found by Brent */
    Tx[3] = T[3];
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_FAIL);
    T[3] = Tx[3] = Ts;
    T[1] = 0.98;   /* off the closed form */
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_FAIL);
    T[1] = 0.97;
    run.T = NULL;   /* success without a solution */
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_FAIL);
    run.T = T;
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_PASS);
    /* failures: with a message they are clean; without one they are not */
    run.status = REF_ESOLVER;
    run.msg = "CVODE failed at t = 0.0001: CV_TOO_MUCH_WORK";
    T[0] = NAN;   /* never read after a failure */
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_PASS);
    assert_non_null(strstr(r.checks[r.count - 1].detail, "failed cleanly"));
    run.msg = "";
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_FAIL);
    run.msg = NULL;
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_FAIL);
    /* where the solver must succeed (BDF on hard-stiff), a clean failure fails */
    run.msg = "CVODE failed at t = 0.0001: CV_TOO_MUCH_WORK";
    run.must_succeed = 1;
    assert_int_equal(vfy_hard_check_ode(&r, "ode", &run), VFY_FAIL);
    assert_non_null(strstr(r.checks[r.count - 1].detail, "must succeed"));
    assert_int_equal(r.counts[VFY_FAIL], 9);
    vfy_report_free(&r);
}

static void test_check_true(void **state)
{
    (void)state;
    vfy_report r;
    vfy_report_init(&r, NULL);
    assert_int_equal(vfy_check_true(&r, "yes", 1, "%d of %d", 3, 3), VFY_PASS);
    assert_int_equal(vfy_check_true(&r, "no", 0, "%s", "because"), VFY_FAIL);
    assert_int_equal(last_verdict(&r), VFY_FAIL);
    assert_string_equal(r.checks[0].detail, "3 of 3");
    assert_string_equal(r.checks[1].detail, "because");
    assert_int_equal(r.counts[VFY_FAIL], 1);
    vfy_report_free(&r);
}

/* ------------------------------------------------ cases, wrong solvers */

/* Run a case at quick sizes with a wrong solver; fills *r (caller frees);
 * its failures are printed. */
static void run_case(const char *case_name, const char *const *wrong, size_t nwrong,
                     vfy_report *r)
{
    run_quick_case(case_name, NULL, 0, wrong, nwrong, r);
}

/* Every check whose name contains `what` failed, and there is at least one
 * (`count` of them when count > 0). */
static void assert_all_fail(const vfy_report *r, const char *what, size_t count)
{
    size_t seen = 0;
    for (size_t i = 0; i < r->count; i++) {
        if (strstr(r->checks[i].name, what) == NULL)
            continue;
        seen++;
        if (r->checks[i].verdict != VFY_FAIL) {
            print_error("expected FAIL: %s: %s\n", r->checks[i].name, r->checks[i].detail);
            fail();
        }
    }
    if (seen == 0 || (count > 0 && seen != count)) {
        print_error("checks named '*%s*': %zu, expected %zu\n", what, seen, count);
        fail();
    }
}

static void assert_all_pass(const char *case_name)
{
    vfy_report r;
    run_case(case_name, NULL, 0, &r);
    assert_int_equal(r.counts[VFY_FAIL], 0);
    assert_true(r.count > 0);
    vfy_report_free(&r);
}

/* Very strong dissipation: a solver at alpha = 0.5 misses the Sonine a2
 * (0.026 against 0.065) and the energy balance of the reference's alpha (by
 * 0.75/0.9975); Maxwell molecules in place of hard spheres break paper C's
 * Eq. (23), derived for the hard-sphere collision operator. */
static void test_hard_dissipation(void **state)
{
    (void)state;
    vfy_report r;
    const char *alpha[] = {"collisions.restitution=0.5"};
    run_case("hard-dissipation", alpha, 1, &r);
    assert_all_fail(&r, "a2 vs Sonine (C.10)", 2);
    assert_all_fail(&r, "energy balance", 2);
    vfy_report_free(&r);
    const char *kernel[] = {"collisions.kernel=maxwell"};
    run_case("hard-dissipation", kernel, 1, &r);
    assert_all_fail(&r, "mu4 vs 5 mu2", 2);
    vfy_report_free(&r);
}

/* The non-Gaussian thermostat near v = 0: the white-noise thermostat in its
 * place gives a positive a2, mu4 = 5 mu2 instead of Eq. (44), a populated
 * origin, and does not keep the total momentum. */
static void test_hard_nongaussian(void **state)
{
    (void)state;
    vfy_report r;
    const char *white[] = {"heating.type=white-noise"};
    run_case("hard-nongaussian", white, 1, &r);
    assert_all_fail(&r, "a2 vs Sonine (C.76)", 2);
    assert_all_fail(&r, "mu4 vs 2 mu2", 2);
    assert_all_fail(&r, "near v = 0", 2);
    assert_all_fail(&r, "momentum kept to round-off", 2);
    vfy_report_free(&r);
}

/* Paper A Ex 7: right solver passes; alpha = 0.5 thins the tail below the
 * first Sonine value of alpha = 0.1, misses a2 and the energy balance; and
 * Maxwell molecules break Eq. (23). */
static void test_hard_tails(void **state)
{
    (void)state;
    assert_all_pass("hard-tails");
    vfy_report r;
    const char *alpha[] = {"collisions.restitution=0.5"};
    run_case("hard-tails", alpha, 1, &r);
    assert_all_fail(&r, "a2 vs Sonine (C.10)", 1);
    assert_all_fail(&r, "energy balance", 1);
    assert_all_fail(&r, "tail P(c >= 3)", 1);
    vfy_report_free(&r);
    const char *kernel[] = {"collisions.kernel=maxwell"};
    run_case("hard-tails", kernel, 1, &r);
    assert_all_fail(&r, "mu4 vs 5 mu2", 1);
    vfy_report_free(&r);
}

/* Tiny systems: right solver passes; binary collisions 4 times too
 * frequent (C = 0.5 for paper B's 1/8; 6.3 times paper A's 1/(4 pi)) fail
 * the exact finite-n T and T_raw of papers A and B; 20% more heating fails
 * the exact Gaussian bulk velocity; a heavier background fails paper B's
 * exact u(t). */
static void test_hard_tiny(void **state)
{
    (void)state;
    assert_all_pass("hard-tiny");
    vfy_report r;
    const char *wrong[] = {"collisions.constant=0.5"};
    run_case("hard-tiny", wrong, 1, &r);
    assert_all_fail(&r, "T vs exact finite-n", 6);
    assert_all_fail(&r, "T_raw vs exact finite-n", 3);
    vfy_report_free(&r);
    const char *heating[] = {"heating.strength=1.2"};
    run_case("hard-tiny", heating, 1, &r);
    assert_all_fail(&r, "grw-ex3 n=2 V Gaussian", 1);
    assert_all_fail(&r, "grw-ex3 n=3 V Gaussian", 1);
    assert_all_fail(&r, "grw-ex3 n=4 V Gaussian", 1);
    assert_all_fail(&r, "grw-ex5 n=2 V Gaussian", 1);
    assert_all_fail(&r, "grw-ex5 n=3 V Gaussian", 1);
    assert_all_fail(&r, "grw-ex5 n=4 V Gaussian", 1);
    vfy_report_free(&r);
    const char *background[] = {"background.mass=1.25"};
    run_case("hard-tiny", background, 1, &r);
    assert_all_fail(&r, "u vs exact expectation", 3);
    vfy_report_free(&r);
}

/* Long runs: right solver passes; collisions 10% too frequent cool the
 * Maxwell gas as e^{-1.1 k t}. */
static void test_hard_long_run(void **state)
{
    (void)state;
    assert_all_pass("hard-long-run");
    vfy_report r;
    const char *wrong[] = {"collisions.rate=4.4"};
    run_case("hard-long-run", wrong, 1, &r);
    assert_all_fail(&r, "T(t) vs T(0) e^{-kt}", 1);
    vfy_report_free(&r);
}

/* Stiff references: no solver is simulated; the CVODE runs pass (or fail
 * cleanly); garbage is test_check_ode's. */
static void test_hard_stiff(void **state)
{
    (void)state;
    assert_all_pass("hard-stiff");
}

/* Extreme parameters: restitution 0.45 and 20% more heating fail the exact
 * finite-n T and T_raw (Maxwell rows), the Sonine closure's T(t_end) (hard
 * spheres from T0 = 1e-8 and 1e8) and the exact Gaussian bulk velocity
 * wherever the heating adds to its variance visibly. */
static void test_hard_extreme(void **state)
{
    (void)state;
    vfy_report r;
    const char *wrong[] = {"collisions.restitution=0.45", "heating.strength=1.2"};
    run_case("hard-extreme", wrong, 2, &r);
    assert_all_fail(&r, "T vs exact finite-n", 5);
    assert_all_fail(&r, "T_raw vs exact finite-n", 5);
    assert_all_fail(&r, "T(t_end) vs Sonine closure", 2);
    /* where the heating shows in V (not beside T0 = 1e8, nor in 3.2e-5) */
    assert_all_fail(&r, "alpha=1e-3 V Gaussian", 1);
    assert_all_fail(&r, "alpha=1 V Gaussian", 1);
    assert_all_fail(&r, "extreme T0=1e-8 V Gaussian", 1);
    assert_all_fail(&r, "hard-spheres T0=1e-8 V Gaussian", 1);
    vfy_report_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_summarize),
        cmocka_unit_test(test_bounds),
        cmocka_unit_test(test_check_finite),
        cmocka_unit_test(test_check_violations),
        cmocka_unit_test(test_check_momentum),
        cmocka_unit_test(test_check_energy),
        cmocka_unit_test(test_check_cooling_range),
        cmocka_unit_test(test_check_ode),
        cmocka_unit_test(test_check_true),
        cmocka_unit_test(test_hard_dissipation),
        cmocka_unit_test(test_hard_nongaussian),
        cmocka_unit_test(test_hard_tails),
        cmocka_unit_test(test_hard_tiny),
        cmocka_unit_test(test_hard_long_run),
        cmocka_unit_test(test_hard_stiff),
        cmocka_unit_test(test_hard_extreme),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
