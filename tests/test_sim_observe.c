/* Conditional observation (sim/observe.h, sim_observe_sums): its values
 * are the exact expectations of the observables over the pending white-noise
 * increments.  A Monte Carlo average over many draws of those increments
 * (fixed seed) must agree within |z| <= 4.5, and must reject the formula
 * without the centring term 1 - 1/n. */
#include "test_util.h"

#include <string.h>

#include "observe.h"
#include "rng.h"

enum { N = 3, DRAWS = 200000 };

static double v0[N][3] = {{0.3, -1.2, 0.5}, {1.1, 0.4, -0.7}, {-0.9, 0.2, 1.5}};
static double stamp0[N] = {0.25, 0.9, 0.0};
static const double t_obs = 1.0, spread = 1.7, mass = 2.0;

/* Monte Carlo mean and standard error of each observable after drawing the
 * increments: v_i += sqrt(spread (t - stamp_i)) xi. */
static void monte_carlo(double mean[SIM_OBS_BASE], double se[SIM_OBS_BASE])
{
    double v[N][3], stamp[N], obs[SIM_OBS_BASE], sum[SIM_OBS_BASE] = {0},
                                                  sum2[SIM_OBS_BASE] = {0};
    sim_particles p = {N, v, stamp, NULL};
    gsl_rng *rng = sim_rng_alloc();
    assert_non_null(rng);
    sim_rng_set_stream(rng, 20261121, 0);
    for (int d = 0; d < DRAWS; d++) {
        for (int i = 0; i < N; i++) {
            double xi[3], s = sqrt(spread * (t_obs - stamp0[i]));
            sim_rng_normal3(rng, xi);
            for (int k = 0; k < 3; k++)
                v[i][k] = v0[i][k] + s * xi[k];
        }
        sim_observe(&p, mass, obs);
        for (int k = 0; k < SIM_OBS_BASE; k++) {
            sum[k] += obs[k];
            sum2[k] += obs[k] * obs[k];
        }
    }
    gsl_rng_free(rng);
    for (int k = 0; k < SIM_OBS_BASE; k++) {
        mean[k] = sum[k] / DRAWS;
        se[k] = sqrt((sum2[k] / DRAWS - mean[k] * mean[k]) / DRAWS);
    }
}

static double z(double mc, double se, double expected) { return fabs(mc - expected) / se; }

/* sim_observe_only under every one of the 2^16 masks: each observable asked
 * for has exactly sim_observe's bits, each other is NaN (a case that reads
 * what it did not declare meets NaN, never a stale value). */
static void test_observe_only_same_bits(void **state)
{
    (void)state;
    enum { M = 37 };
    double v[M][3], all[SIM_OBS_BASE], some[SIM_OBS_BASE];
    sim_particles p = {M, v, NULL, NULL};
    gsl_rng *rng = sim_rng_alloc();
    assert_non_null(rng);
    sim_rng_set_stream(rng, 20261126, 0);
    for (int i = 0; i < M; i++) {
        sim_rng_normal3(rng, v[i]);
        v[i][1] += 0.7;   /* a bulk velocity, so that centring matters */
    }
    gsl_rng_free(rng);
    sim_observe(&p, mass, all);
    for (int k = 0; k < SIM_OBS_BASE; k++)
        assert_true(isfinite(all[k]));
    for (uint32_t only = 1; only <= SIM_OBS_ALL_BASE; only++) {
        sim_observe_only(&p, mass, only, some);
        for (int k = 0; k < SIM_OBS_BASE; k++) {
            if (only & SIM_OBS_BIT(k))
                assert_memory_equal(&some[k], &all[k], sizeof all[k]);
            else
                assert_true(isnan(some[k]));
        }
    }
    sim_observe_only(&p, mass, 0, some);   /* 0: all */
    assert_memory_equal(some, all, sizeof all);
}

static void test_pending_is_the_conditional_expectation(void **state)
{
    (void)state;
    double stamp[N];
    memcpy(stamp, stamp0, sizeof stamp);
    sim_particles p = {N, v0, stamp, NULL};
    double exact[SIM_OBS_BASE], mc[SIM_OBS_BASE], se[SIM_OBS_BASE];
    sim_sums sums;
    sim_sums_compute(&p, &sums);
    sim_observe_sums(&sums, N, mass, t_obs, spread, exact);
    assert_memory_equal(stamp, stamp0, sizeof stamp);   /* p is not changed */
    monte_carlo(mc, se);
    for (int k = SIM_OBS_T; k <= SIM_OBS_PYZ; k++) {
        double zk = z(mc[k], se[k], exact[k]);
        if (!(zk <= 4.5)) {
            sim_scene scene;
            char name[SIM_OBS_NAME_LEN];
            sim_scene_defaults(&scene);
            print_error("%s: Monte Carlo %.6f ± %.6f, pending %.6f, |z| = %.2f\n",
                        sim_observable_name(&scene, (size_t)k, name), mc[k], se[k], exact[k], zk);
        }
        assert_true(zk <= 4.5);
    }
    for (int k = SIM_OBS_QX; k < SIM_OBS_BASE; k++)
        assert_true(isnan(exact[k]));   /* not observed this way */
    /* spread 0: the system's own values, as sim_observe computes them */
    double own[SIM_OBS_BASE];
    sim_observe(&p, mass, own);
    sim_observe_sums(&sums, N, mass, t_obs, 0.0, exact);
    for (int k = SIM_OBS_T; k <= SIM_OBS_PYZ; k++)
        assert_close(exact[k], own[k], 1e-13, 1e-15);
    /* a particle taken out and put back changed leaves the sums of the new system */
    sim_sums_add(&sums, v0[1], stamp[1], -1.0);
    const double changed[3] = {-0.4, 2.0, 0.1};
    sim_sums_add(&sums, changed, 0.5, 1.0);
    double v[N][3], st[N];
    memcpy(v, v0, sizeof v);
    memcpy(st, stamp0, sizeof st);
    memcpy(v[1], changed, sizeof changed);
    st[1] = 0.5;
    sim_particles q = {N, v, st, NULL};
    sim_sums direct;
    sim_sums_compute(&q, &direct);
    for (int k = 0; k < 3; k++)
        assert_close(sums.v[k], direct.v[k], 1e-13, 1e-15);
    for (int k = 0; k < 6; k++)
        assert_close(sums.vv[k], direct.vv[k], 1e-13, 1e-15);
    assert_close(sums.stamp, direct.stamp, 1e-13, 1e-15);
}

/* The wrong answer: the centred temperature without the 1/n of the centring
 * velocity, T(v) + m S.  The same Monte Carlo must reject it. */
static void test_without_centring_term_is_rejected(void **state)
{
    (void)state;
    double stamp[N];
    memcpy(stamp, stamp0, sizeof stamp);
    sim_particles p = {N, v0, stamp, NULL};
    double now[SIM_OBS_BASE], mc[SIM_OBS_BASE], se[SIM_OBS_BASE];
    sim_observe(&p, mass, now);
    double S = 0.0;
    for (int i = 0; i < N; i++)
        S += spread * (t_obs - stamp0[i]) / N;
    monte_carlo(mc, se);
    assert_true(z(mc[SIM_OBS_T], se[SIM_OBS_T], now[SIM_OBS_T] + mass * S) > 20.0);
    /* and observing without the expectation at all is rejected too */
    assert_true(z(mc[SIM_OBS_T_RAW], se[SIM_OBS_T_RAW], now[SIM_OBS_T_RAW]) > 20.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_observe_only_same_bits),
        cmocka_unit_test(test_pending_is_the_conditional_expectation),
        cmocka_unit_test(test_without_centring_term_is_rejected),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
