/* Paper D's heat-flux force and its observers (docs/theory.md §7, §10.5, issue 15), and the
 * time-step collision stage of every kernel:
 * - the force step with its projection keeps the momentum at 0 and T at T0
 *   to round-off, on a non-Maxwellian system;
 * - in the engine: eps = 0 gives q_x = 0 within its interval, q_x < 0 for
 *   eps > 0 and > 0 for eps < 0; the identity b'_1 = (15 sqrt(pi)/16)
 *   kappa'/kappa0 to round-off; the two estimators of b'_k agree;
 * - the observers' normalisation: on a static sample of
 *   f = f_M (1 + delta c_x L_2^{(3/2)}(c^2)) both estimators give b'_2 =
 *   delta/eps* and b'_1 = b'_3 = 0 (D Eqs. 3.10, 3.12; the marginal of
 *   c_x L_k^{(3/2)}(c^2) f_M is c_x L_k^{(1/2)}(c_x^2) g_M), and a wrong P_k
 *   is told apart;
 * - Maxwell and VHS collisions in the time-step scheme collide at the exact
 *   rate 2 pi gamma C (n - 1) E|g|^lambda and keep energy and momentum when
 *   elastic.
 * Every statistical check also meets a wrong answer and must fail it. */
#include "test_sim_util.h"

#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_sf_gamma.h>

#include "effect.h"
#include "engine.h"
#include "ensemble.h"
#include "rng.h"
#include "run.h"
#include "steady.h"

#define ZMAX 4.5

/* Paper D's scene in its units (verify/cases/scenes/msg.ini): T0 = 1/2, m = 1,
 * lambda = tau = 1, so eps* = eps. */
static sim_scene heat_flux_scene(double eps, size_t n, size_t N)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.scheme = SIM_SCHEME_TIMESTEP;
    s.dt = 0.01;
    s.t_end = 8.0;
    s.outputs = 41;
    s.seed = 3003;
    s.particles.n = n;
    s.particles.ensembles = N;
    s.particles.maxwellian.temperature = 0.5;
    s.particles.zero_momentum = 1;
    s.collisions.present = 1;
    s.collisions.kernel = SIM_KERNEL_HARD_SPHERES;
    s.collisions.exponent = 1.0;
    s.collisions.constant = 1.0 / (4.0 * sqrt(2.0) * M_PI);
    s.collisions.restitution = 1.0;
    s.heat_flux.present = 1;
    s.heat_flux.strength = eps;
    s.steady.present = 1;
    s.steady.from = 3.0;
    s.steady.bins = 10;
    s.steady.c_max = 3.0;
    return s;
}

static double steady(const sim_scene *s, const sim_ensemble_result *r, const char *name,
                     double *sigma)
{
    const long k = sim_steady_find(s, name);
    assert_true(k >= 0);
    if (sigma)
        *sigma = sim_result_steady_ci(r, (size_t)k) / SIM_LAMBDA_P;
    return sim_result_steady_mean(r, (size_t)k);
}

/* The step on a skewed system: momentum 0 and T = T0 after every step. */
static void test_step_projection(void **state)
{
    (void)state;
    sim_scene s = heat_flux_scene(0.3, 500, 1);
    sim_run r;
    memset(&r, 0, sizeof r);
    sim_error err;
    assert_int_equal(sim_particles_alloc(&r.p, 500, 0, &err), SIM_OK);
    r.rng = sim_rng_alloc();
    r.radius = INFINITY;
    sim_rng_set_stream(r.rng, 5, 1);
    for (size_t i = 0; i < r.p.n; i++) {   /* exponential components: skewed, moving */
        for (int k = 0; k < 3; k++)
            r.p.v[i][k] = sim_rng_exponential(r.rng, 1.0);
    }
    sim_flow e;
    assert_int_equal(sim_effect_heat_flux(&s, &e, &err), SIM_OK);
    for (int step = 0; step < 50; step++) {
        e.type->step(&e, &r, 0.05);
        double p[3] = {0, 0, 0}, c2 = 0.0;
        for (size_t i = 0; i < r.p.n; i++)
            for (int k = 0; k < 3; k++) {
                p[k] += r.p.v[i][k];
                c2 += r.p.v[i][k] * r.p.v[i][k];
            }
        for (int k = 0; k < 3; k++)
            assert_close(p[k] / (double)r.p.n, 0.0, 0.0, 1e-15);
        assert_close(c2 / (3.0 * (double)r.p.n), 0.5, 1e-14, 0.0);
    }
    free(e.params);
    sim_particles_free(&r.p);
    gsl_rng_free(r.rng);
}

/* q_x follows the force: 0 without it, against it with it; T stays T0 and
 * the momentum 0; b'_1 and kappa' are one estimator; the estimators of b'_k
 * agree. */
static void test_engine_response(void **state)
{
    (void)state;
    const double eps[] = {0.0, 0.2, -0.2};
    for (int c = 0; c < 3; c++) {
        sim_scene s = heat_flux_scene(eps[c], 2000, 8);
        sim_ensemble_result r;
        run(&s, &r);
        for (size_t m = 0; m < r.outputs; m++) {
            if (m > 0)   /* the sampled initial T differs from T0 */
                assert_close(sim_result_mean(&r, m, SIM_OBS_T), 0.5, 1e-13, 0.0);
            assert_close(sim_result_mean(&r, m, SIM_OBS_UX), 0.0, 0.0, 1e-15);
        }
        double sq, qx = steady(&s, &r, "qx", &sq);
        print_message("eps = %+.1f: qx = %+.5f ± %.5f (z = %+.1f)\n", eps[c], qx, sq, qx / sq);
        if (eps[c] == 0.0) {
            assert_true(fabs(qx / sq) < ZMAX);
            assert_true(isnan(steady(&s, &r, "b1", NULL)));
        } else {
            assert_true(qx / sq * (eps[c] > 0 ? -1.0 : 1.0) > 3.0 * ZMAX);
            const double kappa = steady(&s, &r, "kappa_prime", NULL);
            assert_true(kappa > 0.8 && kappa < 1.3);   /* 1.025 in linear response */
            assert_close(steady(&s, &r, "b1", NULL), 15.0 * sqrt(M_PI) / 16.0 * kappa, 1e-10,
                         0.0);
            const char *est[][2] = {{"b1", "b1_x"}, {"b2", "b2_x"}, {"b3", "b3_x"}};
            for (int k = 0; k < 3; k++) {
                double s1, s2, b = steady(&s, &r, est[k][0], &s1),
                              bx = steady(&s, &r, est[k][1], &s2);
                const double z = (b - bx) / sqrt(s1 * s1 + s2 * s2);
                print_message("  %s = %.4f ± %.4f, %s = %.4f ± %.4f (z = %.2f)\n", est[k][0], b,
                              s1, est[k][1], bx, s2, z);
                assert_true(fabs(z) < ZMAX);
            }
            /* the wrong answer: b'_1 is not b'_2 */
            double s1, s2, b1 = steady(&s, &r, "b1", &s1), b2x = steady(&s, &r, "b2_x", &s2);
            assert_true(fabs(b1 - b2x) / sqrt(s1 * s1 + s2 * s2) > ZMAX);
        }
        sim_ensemble_result_free(&r);
    }
}

/* L_2^{(3/2)}(x) = 35/8 - (7/2) x + x^2/2. */
static double laguerre2_32(double x) { return 35.0 / 8.0 - 3.5 * x + 0.5 * x * x; }

/* The observers on f = f_M (1 + delta c_x L_2^{(3/2)}(c^2)) (rejection from a
 * Maxwellian at T0 = 1/2, v0 = 1): b'_2 = delta/eps* from both estimators,
 * b'_1 = b'_3 = 0 (the orthogonality the P_k, Q_k normalise). */
static void test_observer_normalisation(void **state)
{
    (void)state;
    const double delta = 0.02, eps = 0.5;
    sim_scene s = heat_flux_scene(eps, 400000, 1);
    sim_particles p;
    sim_error err;
    assert_int_equal(sim_particles_alloc(&p, s.particles.n, 0, &err), SIM_OK);
    gsl_rng *rng = sim_rng_alloc();
    sim_rng_set_stream(rng, 11, 0);
    for (size_t i = 0; i < p.n;) {
        double c[3];
        sim_rng_normal3(rng, c);
        for (int k = 0; k < 3; k++)
            c[k] *= sqrt(0.5);   /* f_M = pi^{-3/2} e^{-c^2} */
        const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        /* w < 0 (c > 3.3, probability below 1e-5) is never accepted; w <= 64 up to
         * c = 6 (beyond: probability e^{-36}) */
        const double w = 1.0 + delta * c[0] * laguerre2_32(c2);
        if (sim_rng_uniform(rng) * 64.0 < w) {
            memcpy(p.v[i], c, sizeof c);
            i++;
        }
    }
    const size_t count = sim_steady_count(&s);
    double *sum = calloc(count, sizeof *sum);
    assert_non_null(sum);
    sim_steady_sample(&s, &p, 1.0, NULL, NULL, sum);
    sim_steady_finish(&s, sum);
    const size_t hf = sim_steady_heat_flux_first(&s);
    /* one sample of n: sigma of P_k <c_x L_k>/eps* is P_k sqrt(<c_x^2 L_k^2>/n)/eps*
     * = sqrt(P_k/n)/eps*, and about as large for the c_x estimator */
    const double want[3] = {0.0, delta / eps, 0.0};
    const double P[3] = {4.0 / 5.0, 16.0 / 35.0, 32.0 / 105.0};
    for (int k = 0; k < 3; k++) {
        const double sigma = sqrt(P[k] / (double)p.n) / eps * 1.2;
        const double b = sum[hf + SIM_HF_B1 + (size_t)k], bx = sum[hf + SIM_HF_B1_X + (size_t)k];
        print_message("b%d = %.5f, b%d_x = %.5f (want %.5f ± %.5f)\n", k + 1, b, k + 1, bx,
                      want[k], sigma);
        assert_true(fabs(b - want[k]) < ZMAX * sigma);
        assert_true(fabs(bx - want[k]) < ZMAX * sigma);
    }
    /* the wrong answer: b'_2 normalised with the c_x estimator's Q_2 = 16/15 */
    const double wrong = sum[hf + SIM_HF_B2] * (16.0 / 15.0) / P[1];
    assert_true(fabs(wrong - want[1]) > ZMAX * sqrt(P[1] / (double)p.n) / eps * 1.2);
    /* beta1's last bin is b1_x over |c_x| < c_max: the rest is the particles beyond
     * (c = v here: the sample's T differs from T0 by O(n^-1/2), so rescale) */
    double theta = 0.0, V[3] = {0, 0, 0};
    for (size_t i = 0; i < p.n; i++)
        for (int k = 0; k < 3; k++)
            V[k] += p.v[i][k] / (double)p.n;
    for (size_t i = 0; i < p.n; i++)
        for (int k = 0; k < 3; k++)
            theta += (p.v[i][k] - V[k]) * (p.v[i][k] - V[k]) / (3.0 * (double)p.n);
    double beyond = 0.0;
    for (size_t i = 0; i < p.n; i++) {
        const double cx = (p.v[i][0] - V[0]) / sqrt(2.0 * theta);
        if (fabs(cx) >= s.steady.c_max)
            beyond += 4.0 / 3.0 * cx * (1.5 - cx * cx) / (double)p.n / eps;
    }
    const double last = sum[hf + SIM_HF_SCALARS + 2 * s.steady.bins - 1];
    assert_close(last + beyond, sum[hf + SIM_HF_B1_X], 1e-10, 1e-12);
    free(sum);
    gsl_rng_free(rng);
    sim_particles_free(&p);
}

/* Elastic Maxwell molecules and VHS in the time-step scheme: collisions at
 * the rate 2 pi gamma C (n - 1) E|g|^lambda, E|g|^lambda = 2^lambda
 * Gamma((3 + lambda)/2)/Gamma(3/2) for a Maxwellian at T/m = 1; energy and
 * momentum kept in each ensemble. */
static void test_timestep_kernels(void **state)
{
    (void)state;
    const double lambdas[] = {0.0, 0.5};
    const size_t n = 200, N = 50;
    const double t_end = 2.0;
    for (int c = 0; c < 2; c++) {
        const double lambda = lambdas[c];
        sim_scene s;
        sim_scene_defaults(&s);
        s.scheme = SIM_SCHEME_TIMESTEP;
        s.dt = 0.05;
        s.t_end = t_end;
        s.outputs = 3;
        s.seed = 77;
        s.particles.n = n;
        s.particles.ensembles = N;
        s.collisions.present = 1;
        s.collisions.kernel = lambda == 0.0 ? SIM_KERNEL_MAXWELL : SIM_KERNEL_VHS;
        s.collisions.exponent = lambda;
        s.collisions.constant = 1.0 / (4.0 * M_PI);
        s.collisions.rate = 3.0;
        s.collisions.restitution = 1.0;
        const double Eg = pow(2.0, lambda) * gsl_sf_gamma(1.5 + 0.5 * lambda) / gsl_sf_gamma(1.5);
        const double expected = 2.0 * M_PI * 3.0 / (4.0 * M_PI) * (double)(n - 1) * Eg * t_end
                                * (double)N;
        sim_engine *e = NULL;
        sim_workspace *ws = NULL;
        assert_int_equal(sim_engine_create(&s, &e, NULL), SIM_OK);
        assert_int_equal(sim_workspace_create(e, &ws, NULL), SIM_OK);
        sim_counts counts = {0};
        for (size_t j = 0; j < N; j++) {
            double obs[3 * SIM_OBS_BASE];
            sim_engine_run(e, ws, j, obs, &counts);
            const double *last = obs + 2 * SIM_OBS_BASE;
            for (int k = SIM_OBS_UX; k <= SIM_OBS_UZ; k++)
                assert_close(last[k], obs[k], 0.0, 1e-14);
            assert_close(last[SIM_OBS_T_RAW], obs[SIM_OBS_T_RAW], 1e-13, 0.0);
        }
        /* Maxwell: a Poisson-free count (floor of the credit), so only the
         * rounding; VHS: Bernoulli acceptances */
        const double count = (double)counts.collisions, z = (count - expected) / sqrt(expected);
        const double z2 = (count - 2.0 * expected) / sqrt(2.0 * expected);
        print_message("lambda = %.1f: %.0f collisions, expected %.0f (z = %.2f)\n", lambda, count,
                      expected, z);
        assert_true(fabs(z) < ZMAX);
        assert_true(fabs(z2) > ZMAX);   /* the wrong answer: ordered pairs counted twice */
        assert_int_equal(counts.violations, 0);
        sim_workspace_free(ws);
        sim_engine_free(e);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_step_projection),
        cmocka_unit_test(test_engine_response),
        cmocka_unit_test(test_observer_normalisation),
        cmocka_unit_test(test_timestep_kernels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
