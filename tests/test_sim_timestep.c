/* The time-step scheme, the thermostats of paper C and the steady-state
 * observers (docs/theory.md §8.5, §10), against exact results:
 * - each thermostat's step on its own (effect level): white-noise variance,
 *   the Gaussian scaling, the keep-T rescaling and the non-Gaussian increment
 *   with its momentum correction, on hand-made particle systems;
 * - white-noise heating only: E T_raw = T0 + 2 beta t for any h, Euler and
 *   Strang;
 * - Gaussian thermostat with elastic hard spheres: T_raw(t) = T_raw(0) e^{2 zeta t}
 *   in every ensemble (to round-off);
 * - keep-T (homogeneous cooling state in scaled variables): T constant;
 * - non-Gaussian thermostat: momentum kept to round-off;
 * - elastic hard spheres: energy and momentum conserved, no majorant
 *   violation, and the number of collisions against the exact rate
 *   4 pi gamma C |g|/n per pair, in both schemes;
 * - the time-step scheme converges to the jump scheme as h -> 0 (and a large
 *   Euler step is told apart);
 * - the same numbers for 1 and 2 threads;
 * - the steady observers on a Maxwellian (a2, a3, <c>, <c^3>, mu2^(0),
 *   mu4^(0), the shell histogram), their time averages, and that pair
 *   sampling never changes the trajectory.
 * Every statistical check also meets a wrong answer and must fail it. */
#include "test_sim_util.h"

#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "engine.h"
#include "ensemble.h"
#include "rng.h"
#include "run.h"
#include "sonine.h"
#include "steady.h"

#define ZMAX 4.5   /* max over output times of |mean - exact| / sigma */

/* Paper A Ex 5's gas (docs/theory.md §11.4): hard spheres, alpha = 1/2, gamma = 4,
 * C1 = 1/(4 pi), white noise beta = 1/8, in the time-step scheme. */
static sim_scene ex5_scene(size_t n, size_t ensembles, double dt, sim_splitting split)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.scheme = SIM_SCHEME_TIMESTEP;
    s.dt = dt;
    s.splitting = split;
    s.t_end = 0.6;
    s.outputs = 7;
    s.seed = 2000;
    s.particles.n = n;
    s.particles.ensembles = ensembles;
    s.collisions.present = 1;
    s.collisions.kernel = SIM_KERNEL_HARD_SPHERES;
    s.collisions.exponent = 1.0;
    s.collisions.rate = 4.0;
    s.collisions.restitution = 0.5;
    s.heating.present = 1;
    s.heating.type = SIM_HEATING_WHITE_NOISE;
    s.heating.strength = 0.125;
    return s;
}

static double max_z_against(const sim_ensemble_result *r, int k, const double *exact)
{
    double z = 0.0;
    for (size_t m = 1; m < r->outputs; m++)
        z = fmax(z, fabs(sim_result_mean(r, m, k) - exact[m])
                        / (sim_result_ci(r, m, k) / SIM_LAMBDA_P));
    return z;
}

/* ------------------------------------------------------- effect level */

typedef struct bench_run {
    sim_run run;
    sim_flow effect;
} bench_run;

/* A run with n particles and no bound (covering is a no-op). */
static void bench_init(bench_run *b, const sim_scene *s, size_t n)
{
    memset(b, 0, sizeof *b);
    sim_error err;
    assert_int_equal(sim_particles_alloc(&b->run.p, n, 0, &err), SIM_OK);
    b->run.rng = sim_rng_alloc();
    assert_non_null(b->run.rng);
    sim_rng_set_stream(b->run.rng, 77, 3);
    b->run.radius = INFINITY;
    assert_int_equal(sim_effect_heating(s, &b->effect, &err), SIM_OK);
    assert_non_null(b->effect.type->step);
}

static void bench_free(bench_run *b)
{
    sim_particles_free(&b->run.p);
    gsl_rng_free(b->run.rng);
    free(b->effect.params);
}

static sim_scene heating_scene(sim_heating_kind type, double strength)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.scheme = SIM_SCHEME_TIMESTEP;
    s.dt = 0.1;
    s.heating.present = 1;
    s.heating.type = type;
    s.heating.strength = strength;
    return s;
}

/* White noise (paper C Eqs. (59)-(60)): each component gains N(0, 2 beta h). */
static void test_white_noise_step(void **state)
{
    (void)state;
    sim_scene s = heating_scene(SIM_HEATING_WHITE_NOISE, 0.37);
    bench_run b;
    bench_init(&b, &s, 200000);
    memset(b.run.p.v, 0, 200000 * sizeof *b.run.p.v);
    b.effect.type->step(&b.effect, &b.run, 0.25);
    double sum = 0.0, sum2 = 0.0;
    for (size_t i = 0; i < 200000; i++)
        for (int k = 0; k < 3; k++) {
            sum += b.run.p.v[i][k];
            sum2 += b.run.p.v[i][k] * b.run.p.v[i][k];
        }
    const double count = 600000.0, var = 2.0 * 0.37 * 0.25;
    /* the sample variance of a normal: sd var sqrt(2/count) */
    double z = (sum2 / count - var) / (var * sqrt(2.0 / count));
    double z_wrong = (sum2 / count - 0.37 * 0.25) / (0.37 * 0.25 * sqrt(2.0 / count));
    print_message("white noise: variance z = %.2f (xi0^2 = beta instead: z = %.1f)\n", z,
                  z_wrong);
    assert_true(fabs(z) < ZMAX);
    assert_true(fabs(sum / count) < ZMAX * sqrt(var / count));
    assert_true(fabs(z_wrong) > ZMAX);
    assert_int_equal(sim_rng_state_of(b.run.rng)->normals, 600000);
    bench_free(&b);
}

/* Gaussian (Eq. (61)): v -> v e^{zeta h} exactly; keep-T: the peculiar
 * velocities rescaled so that T = T0. */
static void test_gaussian_steps(void **state)
{
    (void)state;
    const double v0[3][3] = {{0.3, -1.2, 2.0}, {-0.7, 0.4, 0.1}, {1.9, 0.05, -0.8}};
    sim_scene s = heating_scene(SIM_HEATING_GAUSSIAN, -0.83);
    bench_run b;
    bench_init(&b, &s, 3);
    memcpy(b.run.p.v, v0, sizeof v0);
    b.effect.type->step(&b.effect, &b.run, 0.3);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            assert_close(b.run.p.v[i][k], v0[i][k] * exp(-0.83 * 0.3), 1e-15, 0.0);
    bench_free(&b);

    s.heating.keep_temperature = 1;
    s.particles.maxwellian.temperature = 2.385;
    s.particles.maxwellian.mass = 1.5;
    bench_init(&b, &s, 3);
    memcpy(b.run.p.v, v0, sizeof v0);
    b.effect.type->step(&b.effect, &b.run, 0.3);
    double V[3] = {0, 0, 0}, V0[3] = {0, 0, 0}, c2 = 0.0;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) {
            V[k] += b.run.p.v[i][k] / 3.0;
            V0[k] += v0[i][k] / 3.0;
        }
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            c2 += (b.run.p.v[i][k] - V[k]) * (b.run.p.v[i][k] - V[k]);
    assert_close(1.5 * c2 / 9.0, 2.385, 1e-14, 0.0);   /* T = (m/3n) Σ |C|^2 */
    for (int k = 0; k < 3; k++)
        assert_close(V[k], V0[k], 0.0, 1e-15);
    bench_free(&b);
}

/* Non-Gaussian (Eq. (62)): w_i = g h (v̂_i - k), k = (1/n) Σ v̂_j. */
static void test_non_gaussian_step(void **state)
{
    (void)state;
    sim_scene s = heating_scene(SIM_HEATING_NON_GAUSSIAN, 0.61);
    bench_run b;
    bench_init(&b, &s, 2);
    const double h = 0.2, gh = 0.61 * 0.2;
    b.run.p.v[0][0] = 3.0, b.run.p.v[0][1] = 0.0, b.run.p.v[0][2] = 4.0;   /* |v| = 5 */
    b.run.p.v[1][0] = 0.0, b.run.p.v[1][1] = -2.0, b.run.p.v[1][2] = 0.0;
    b.effect.type->step(&b.effect, &b.run, h);
    const double k[3] = {0.3, -0.5, 0.4};   /* ((0.6, 0, 0.8) + (0, -1, 0))/2 */
    const double expect[2][3] = {{3.0 + gh * (0.6 - k[0]), gh * (0.0 - k[1]), 4.0 + gh * (0.8 - k[2])},
                                 {gh * (0.0 - k[0]), -2.0 + gh * (-1.0 - k[1]), gh * (0.0 - k[2])}};
    for (int i = 0; i < 2; i++)
        for (int c = 0; c < 3; c++)
            assert_close(b.run.p.v[i][c], expect[i][c], 1e-15, 1e-15);
    bench_free(&b);
}

/* ------------------------------------------------------ engine level */

/* Heating only: E T_raw(t) = T0 + 2 beta t exactly (paper A Eq. (18)), for
 * any step and either splitting. */
static void test_white_noise_only(void **state)
{
    (void)state;
    for (int split = 0; split < 2; split++) {
        sim_scene s = ex5_scene(5, 3000, 0.2, split ? SIM_SPLIT_STRANG : SIM_SPLIT_EULER);
        s.collisions.present = 0;
        s.heating.strength = 0.37;
        s.t_end = 2.0;
        s.outputs = 5;
        sim_ensemble_result r;
        run(&s, &r);
        double exact[5], wrong[5];
        for (size_t m = 0; m < 5; m++) {
            exact[m] = 1.0 + 2.0 * 0.37 * r.t[m];
            wrong[m] = 1.0 + 2.0 * 0.40 * r.t[m];
        }
        double z = max_z_against(&r, SIM_OBS_T_RAW, exact);
        print_message("%s: heating only, max z = %.2f\n", split ? "strang" : "euler", z);
        assert_true(z < ZMAX);
        assert_true(max_z_against(&r, SIM_OBS_T_RAW, wrong) > ZMAX);
        assert_int_equal(r.counts.candidates, 0);
        /* white noise is lazy (engine.c, interval_lazy): 3 n normals for the
         * start and 3 n at each of the 4 later output times, whatever h (1/6
         * here) and the splitting; stepping every particle drew 3 n per flow,
         * 3 or 4 flows per interval */
        assert_int_equal(r.counts.normals, 3u * 5u * 3000u * (1 + 4));
        sim_ensemble_result_free(&r);
    }
}

/* Elastic hard spheres with the Gaussian thermostat zeta = 0.7, drifting
 * along x. */
static sim_scene elastic_gaussian_scene(double dt, sim_splitting split)
{
    sim_scene s = ex5_scene(40, 20, dt, split);
    s.collisions.restitution = 1.0;
    s.heating.type = SIM_HEATING_GAUSSIAN;
    s.heating.strength = 0.7;
    s.particles.maxwellian.velocity[0] = 0.4;
    return s;
}

/* The energy changes only by the scaling, so T_raw(t) = T_raw(0) e^{2 zeta t}
 * and u(t) = u(0) e^{zeta t} in every ensemble to round-off. */
static void assert_gaussian_growth(const sim_ensemble_result *r, double zeta)
{
    for (size_t m = 1; m < r->outputs; m++) {
        const double f = exp(2.0 * zeta * r->t[m]);
        assert_close(sim_result_mean(r, m, SIM_OBS_T_RAW),
                     sim_result_mean(r, 0, SIM_OBS_T_RAW) * f, 1e-12, 0.0);
        assert_close(sim_result_mean(r, m, SIM_OBS_UX), sim_result_mean(r, 0, SIM_OBS_UX) * sqrt(f),
                     1e-12, 0.0);
    }
}

/* The Gaussian thermostat with elastic hard spheres in the time-step scheme,
 * Euler and Strang. */
static void test_gaussian_with_elastic_collisions(void **state)
{
    (void)state;
    for (int split = 0; split < 2; split++) {
        sim_scene s = elastic_gaussian_scene(0.05, split ? SIM_SPLIT_STRANG : SIM_SPLIT_EULER);
        sim_ensemble_result r;
        run(&s, &r);
        assert_gaussian_growth(&r, 0.7);
        for (size_t m = 1; m < r.outputs; m++) {
            /* the wrong growth rate is far outside round-off */
            assert_true(fabs(sim_result_mean(&r, m, SIM_OBS_T_RAW)
                             / (sim_result_mean(&r, 0, SIM_OBS_T_RAW) * exp(2.0 * 0.707 * r.t[m]))
                             - 1.0) > 1e-4);
        }
        assert_true(r.counts.collisions > 1000);
        assert_int_equal(r.counts.violations, 0);
        sim_ensemble_result_free(&r);
    }
}

/* keep-T: the homogeneous cooling state in scaled variables keeps T = T0 at
 * every output time; the inelastic collisions meanwhile drive a2 up. */
static void test_keep_temperature(void **state)
{
    (void)state;
    sim_scene s = ex5_scene(100, 40, 0.02, SIM_SPLIT_EULER);
    s.collisions.restitution = 0.3;
    s.heating.type = SIM_HEATING_GAUSSIAN;
    s.heating.keep_temperature = 1;
    s.heating.strength = 0.0;
    s.particles.maxwellian.temperature = 1.7;
    s.particles.zero_momentum = 1;
    s.t_end = 2.0;
    s.outputs = 5;
    sim_ensemble_result r;
    run(&s, &r);
    for (size_t m = 0; m < r.outputs; m++) {
        if (m > 0)
            assert_close(sim_result_mean(&r, m, SIM_OBS_T), 1.7, 1e-13, 0.0);
        assert_close(sim_result_ci(&r, m, SIM_OBS_UX), 0.0, 0.0, 1e-14);
    }
    /* HCS a2 at alpha = 0.3 is about 0.1 (C.5, C.40): far from the Maxwellian */
    assert_true(sim_result_mean(&r, r.outputs - 1, SIM_OBS_A2) > 0.05);
    sim_ensemble_result_free(&r);
}

/* The non-Gaussian thermostat keeps the total momentum (k in Eq. (62)); the
 * gas heats up (g > 0 feeds energy). */
static void test_non_gaussian_momentum(void **state)
{
    (void)state;
    sim_scene s = ex5_scene(50, 30, 0.01, SIM_SPLIT_STRANG);
    s.heating.type = SIM_HEATING_NON_GAUSSIAN;
    s.heating.strength = 1.3;
    s.particles.maxwellian.velocity[1] = -0.6;
    s.particles.zero_momentum = 1;
    sim_ensemble_result r;
    run(&s, &r);
    for (size_t m = 0; m < r.outputs; m++) {
        assert_close(sim_result_mean(&r, m, SIM_OBS_UY), -0.6, 0.0, 1e-13);
        assert_close(sim_result_ci(&r, m, SIM_OBS_UY), 0.0, 0.0, 1e-13);
    }
    assert_true(r.counts.collisions > 1000);
    assert_int_equal(r.counts.violations, 0);
    sim_ensemble_result_free(&r);
}

/* Elastic hard spheres in equilibrium: each ensemble keeps its energy and
 * momentum, and the number of accepted collisions is that of the rate
 * 4 pi gamma C |g|/n per pair, i.e. 2 pi gamma C (n - 1) E|g| in total with
 * E|g| = 4 sqrt(T/(pi m)) for a Maxwellian, in both schemes. */
static void test_elastic_rate(void **state)
{
    (void)state;
    const size_t n = 200, N = 100;
    const double t_end = 2.0;
    const double expected = 2.0 * M_PI * 4.0 / (4.0 * M_PI) * (double)(n - 1)
                            * 4.0 / sqrt(M_PI) * t_end * (double)N;
    for (int scheme = 0; scheme < 3; scheme++) {   /* jump, time-step by contact, by |g| */
        sim_scene s = ex5_scene(n, N, 0.05, SIM_SPLIT_EULER);
        s.scheme = scheme ? SIM_SCHEME_TIMESTEP : SIM_SCHEME_JUMP;
        s.collisions.rule = scheme == 1 ? SIM_RULE_CONTACT : SIM_RULE_RELATIVE_SPEED;
        s.collisions.restitution = 1.0;
        s.heating.present = 0;
        s.t_end = t_end;
        s.outputs = 3;
        sim_engine *e = NULL;
        sim_workspace *ws = NULL;
        assert_int_equal(sim_engine_create(&s, &e, NULL), SIM_OK);
        assert_int_equal(sim_workspace_create(e, &ws, NULL), SIM_OK);
        sim_counts c = {0};
        for (size_t j = 0; j < N; j++) {
            assert_int_equal(sim_engine_observables(e), SIM_OBS_BASE);   /* obs fits */
            double obs[3 * SIM_OBS_BASE];
            sim_engine_run(e, ws, j, obs, &c);
            double *last = obs + 2 * SIM_OBS_BASE;
            for (int k = SIM_OBS_UX; k <= SIM_OBS_UZ; k++)
                assert_close(last[k], obs[k], 0.0, 1e-14);
            assert_close(last[SIM_OBS_T_RAW], obs[SIM_OBS_T_RAW], 1e-13, 0.0);
        }
        double count = (double)c.collisions, z = (count - expected) / sqrt(expected);
        double z4 = (count - 4.0 * expected) / sqrt(4.0 * expected);
        print_message("%s: %.0f collisions, expected %.0f (z = %.2f); %llu candidates\n",
                      scheme == 0 ? "jump" : scheme == 1 ? "time-step, contact"
                                                         : "time-step, |g|", count, expected, z,
                      (unsigned long long)c.candidates);
        assert_true(fabs(z) < ZMAX);
        /* the wrong answer: accepting with Θ(g.s) g.s / U_max at the jump
         * scheme's candidate rate (E_s[Θ(g.s) g.s] = |g|/4 forgotten) */
        assert_true(fabs(z4) > ZMAX);
        assert_int_equal(c.violations, 0);
        sim_workspace_free(ws);
        sim_engine_free(e);
    }
}

/* As h -> 0 the time-step scheme simulates the jump scheme's process: on
 * paper A Ex 5's transient, Strang at h = 1/80 agrees with the jump scheme
 * within the statistical error at every output time, while Euler at h = 0.1
 * is told apart (its O(h) splitting error, about beta h in T). */
static void converges_to_jump(sim_collision_rule rule, uint64_t *normals)
{
    const size_t n = 64, N = 6000;
    sim_scene s = ex5_scene(n, N, 0.0125, SIM_SPLIT_STRANG);
    sim_ensemble_result jump, fine, coarse;
    s.scheme = SIM_SCHEME_JUMP;
    run(&s, &jump);
    s.scheme = SIM_SCHEME_TIMESTEP;
    s.collisions.rule = rule;
    run(&s, &fine);
    *normals = fine.counts.normals;
    s.dt = 0.1;
    s.splitting = SIM_SPLIT_EULER;
    run(&s, &coarse);
    double z_fine = 0.0, z_coarse = 0.0;
    for (size_t m = 1; m < jump.outputs; m++) {
        double cj = sim_result_ci(&jump, m, SIM_OBS_T) / SIM_LAMBDA_P;
        double cf = sim_result_ci(&fine, m, SIM_OBS_T) / SIM_LAMBDA_P;
        double cc = sim_result_ci(&coarse, m, SIM_OBS_T) / SIM_LAMBDA_P;
        double mj = sim_result_mean(&jump, m, SIM_OBS_T);
        z_fine = fmax(z_fine, fabs(sim_result_mean(&fine, m, SIM_OBS_T) - mj)
                                  / sqrt(cj * cj + cf * cf));
        z_coarse = fmax(z_coarse, fabs(sim_result_mean(&coarse, m, SIM_OBS_T) - mj)
                                      / sqrt(cj * cj + cc * cc));
    }
    print_message("T(t) time-step (%s) vs jump: Strang h = 1/80 max z %.2f, Euler h = 0.1 max "
                  "z %.2f; %llu normals\n", rule == SIM_RULE_CONTACT ? "contact" : "|g|, lazy",
                  z_fine, z_coarse, (unsigned long long)*normals);
    assert_true(z_fine < ZMAX);
    assert_true(z_coarse > ZMAX);
    assert_int_equal(fine.counts.violations, 0);
    sim_ensemble_result_free(&jump);
    sim_ensemble_result_free(&fine);
    sim_ensemble_result_free(&coarse);
}

/* By the contact rule the white noise steps every particle; by |g| it is lazy
 * (engine.c, interval_lazy): the same process, with fewer Gaussian numbers. */
static void test_converges_to_jump(void **state)
{
    (void)state;
    uint64_t eager, lazy;
    converges_to_jump(SIM_RULE_CONTACT, &eager);
    converges_to_jump(SIM_RULE_RELATIVE_SPEED, &lazy);
    assert_true(lazy < eager / 2);
}

/* The keep-T rescaling in the exact jump scheme (after each collision,
 * engine.c run_jump_linear) is the h -> 0 limit of the time-step scheme's
 * (after each step): a2(t) of the homogeneous cooling state at alpha = 0.3
 * agrees with Strang at h = 0.01 within the statistical error, and not with
 * a wrong restitution (0.4); T = T0 to round-off at every output time. */
static void test_keep_temperature_jump(void **state)
{
    (void)state;
    sim_scene s = ex5_scene(64, 3000, 0.01, SIM_SPLIT_STRANG);
    s.collisions.restitution = 0.3;
    s.collisions.rule = SIM_RULE_RELATIVE_SPEED;
    s.heating.type = SIM_HEATING_GAUSSIAN;
    s.heating.keep_temperature = 1;
    s.heating.strength = 0.0;
    s.particles.zero_momentum = 1;
    s.t_end = 1.5;
    s.outputs = 6;
    sim_ensemble_result jump, step, wrong;
    s.scheme = SIM_SCHEME_JUMP;
    run(&s, &jump);
    s.scheme = SIM_SCHEME_TIMESTEP;
    run(&s, &step);
    s.collisions.restitution = 0.4;
    run(&s, &wrong);
    double z = 0.0, z_wrong = 0.0;
    for (size_t m = 1; m < jump.outputs; m++) {
        assert_close(sim_result_mean(&jump, m, SIM_OBS_T), 1.0, 1e-13, 0.0);
        const double mj = sim_result_mean(&jump, m, SIM_OBS_A2);
        const double cj = sim_result_ci(&jump, m, SIM_OBS_A2) / SIM_LAMBDA_P;
        const double cs = sim_result_ci(&step, m, SIM_OBS_A2) / SIM_LAMBDA_P;
        const double cw = sim_result_ci(&wrong, m, SIM_OBS_A2) / SIM_LAMBDA_P;
        z = fmax(z, fabs(sim_result_mean(&step, m, SIM_OBS_A2) - mj) / sqrt(cj * cj + cs * cs));
        z_wrong = fmax(z_wrong, fabs(sim_result_mean(&wrong, m, SIM_OBS_A2) - mj)
                                    / sqrt(cj * cj + cw * cw));
    }
    print_message("HCS a2(t), jump vs time-step h = 0.01: max z %.2f (alpha = 0.4: %.2f); a2 "
                  "at t = 1.5: %.4f\n", z, z_wrong,
                  sim_result_mean(&jump, jump.outputs - 1, SIM_OBS_A2));
    assert_true(z < ZMAX);
    assert_true(z_wrong > ZMAX);
    assert_int_equal(jump.counts.violations, 0);
    sim_ensemble_result_free(&jump);
    sim_ensemble_result_free(&step);
    sim_ensemble_result_free(&wrong);
}

/* A fixed-zeta Gaussian thermostat in the exact jump scheme (candidates at a
 * rate growing as e^{lambda zeta t}, engine.c run_jump_linear): with elastic
 * collisions T_raw(t) = T_raw(0) e^{2 zeta t} and u(t) = u(0) e^{zeta t} to
 * round-off; with alpha = 0.5, T(t) and a2(t) agree with the time-step
 * scheme at h = 0.01 (Strang, its h -> 0 limit) within the statistical error,
 * for a heating and a cooling zeta, and not with a zeta 5% off. */
static void test_gaussian_jump(void **state)
{
    (void)state;
    sim_scene s = elastic_gaussian_scene(0.01, SIM_SPLIT_STRANG);
    s.scheme = SIM_SCHEME_JUMP;
    sim_ensemble_result r;
    run(&s, &r);
    assert_gaussian_growth(&r, 0.7);
    assert_true(r.counts.collisions > 1000);
    sim_ensemble_result_free(&r);

    const double zetas[2] = {0.4, -0.3};
    for (int k = 0; k < 2; k++) {
        s = ex5_scene(64, 3000, 0.01, SIM_SPLIT_STRANG);
        s.collisions.rule = SIM_RULE_RELATIVE_SPEED;
        s.heating.type = SIM_HEATING_GAUSSIAN;
        s.heating.strength = zetas[k];
        s.t_end = 1.5;
        s.outputs = 6;
        sim_ensemble_result jump, step, wrong;
        run(&s, &step);
        s.scheme = SIM_SCHEME_JUMP;
        run(&s, &jump);
        s.heating.strength = 1.05 * zetas[k];
        run(&s, &wrong);
        double z[2] = {0.0, 0.0}, z_wrong = 0.0;
        const int obs[2] = {SIM_OBS_T, SIM_OBS_A2};
        for (size_t m = 1; m < jump.outputs; m++)
            for (int q = 0; q < 2; q++) {
                const double mj = sim_result_mean(&jump, m, obs[q]);
                const double cj = sim_result_ci(&jump, m, obs[q]) / SIM_LAMBDA_P;
                const double cs = sim_result_ci(&step, m, obs[q]) / SIM_LAMBDA_P;
                z[q] = fmax(z[q], fabs(sim_result_mean(&step, m, obs[q]) - mj)
                                      / sqrt(cj * cj + cs * cs));
                if (q == 0) {
                    const double cw = sim_result_ci(&wrong, m, SIM_OBS_T) / SIM_LAMBDA_P;
                    z_wrong = fmax(z_wrong, fabs(sim_result_mean(&wrong, m, SIM_OBS_T) - mj)
                                                / sqrt(cj * cj + cw * cw));
                }
            }
        print_message("zeta = %.1f, jump vs time-step h = 0.01: T max z %.2f, a2 max z %.2f "
                      "(zeta 5%% off: T max z %.2f); T(1.5) = %.4f\n", zetas[k], z[0], z[1],
                      z_wrong, sim_result_mean(&jump, jump.outputs - 1, SIM_OBS_T));
        assert_true(z[0] < ZMAX && z[1] < ZMAX);
        assert_true(z_wrong > ZMAX);
        assert_int_equal(jump.counts.violations, 0);
        sim_ensemble_result_free(&jump);
        sim_ensemble_result_free(&step);
        sim_ensemble_result_free(&wrong);
    }
}

/* Bit-identical results for 1 and 2 threads, steady observers included. */
static void test_thread_count_independence(void **state)
{
    (void)state;
    sim_scene s = ex5_scene(30, 200, 0.02, SIM_SPLIT_STRANG);
    s.steady.present = 1;
    s.steady.from = 0.3;
    s.steady.pairs = 100;
    s.steady.bins = 10;
    s.steady.c_max = 4.0;
    sim_ensemble_result a, b;
    omp_set_num_threads(1);
    run(&s, &a);
    omp_set_num_threads(2);
    run(&s, &b);
    size_t len = a.outputs * a.observables + a.nsteady;
    assert_int_equal(a.threads, 1);
    assert_int_equal(b.threads, 2);   /* else the comparison would be vacuous */
    assert_int_equal(a.nsteady, SIM_STEADY_BIN0 + 10);
    assert_memory_equal(a.mean, b.mean, len * sizeof(double));
    assert_memory_equal(a.ci, b.ci, len * sizeof(double));
    assert_int_equal(a.counts.candidates, b.counts.candidates);
    sim_ensemble_result_free(&a);
    sim_ensemble_result_free(&b);
}

/* ------------------------------------------------------ steady observers */

/* The Maxwellian fraction in the shell a <= c < b (reduced units). */
static double maxwell_shell(double a, double b)
{
    double P_a = erf(a) - 2.0 * a * exp(-a * a) / sqrt(M_PI);
    double P_b = erf(b) - 2.0 * b * exp(-b * b) / sqrt(M_PI);
    return P_b - P_a;
}

/* On the initial Maxwellian (no effect moves it), every steady quantity has
 * its Maxwellian value: a2 = a3 = 0, <c> = 2/sqrt(pi), <c^3> = 4/sqrt(pi),
 * mu2 = mu2^(0), mu4 = mu4^(0) (paper C Eqs. (27), (29)), and the shell
 * histogram is pi^{-3/2} e^{-c^2} averaged over each shell. */
static void test_steady_maxwellian(void **state)
{
    (void)state;
    sim_scene s;
    sim_scene_defaults(&s);
    s.seed = 424242;
    s.particles.n = 8000;   /* the O(1/n) bias of the ratio estimators well below sigma */
    s.particles.ensembles = 150;
    s.particles.maxwellian.temperature = 2.385;
    s.particles.maxwellian.velocity[2] = 1.25;   /* observers use peculiar velocities */
    s.collisions.restitution = 0.5;              /* for Phi_p; no collisions happen */
    s.steady.present = 1;
    s.steady.pairs = 20000;
    s.steady.bins = 30;
    s.steady.c_max = 3.0;
    sim_ensemble_result r;
    run(&s, &r);
    const double alpha = 0.5;
    struct { int k; double exact, wrong; } q[] = {
        {SIM_STEADY_T, 2.385, 2.45},
        {SIM_STEADY_A2, 0.0, 0.01},
        {SIM_STEADY_A3, 0.0, 0.05},
        {SIM_STEADY_C1, 2.0 / sqrt(M_PI), 2.0 / sqrt(M_PI) * 1.01},
        {SIM_STEADY_C3, 4.0 / sqrt(M_PI), 4.0 / sqrt(M_PI) * 1.01},
        {SIM_STEADY_MU2, ref_sonine_mu2_0(alpha, 3.0), ref_sonine_mu2_0(alpha, 3.0) * 1.01},
        /* wrong: mu4^(0) without its alpha^2 term */
        {SIM_STEADY_MU4, ref_sonine_mu4_0(alpha, 3.0), 4.5 * ref_sonine_mu2_0(alpha, 3.0)},
        {SIM_STEADY_MU4_WHITE, 5.0 * ref_sonine_mu2_0(alpha, 3.0), 0.0},
    };
    for (size_t i = 0; i < sizeof q / sizeof *q; i++) {
        double mean = sim_result_steady_mean(&r, (size_t)q[i].k);
        double sigma = sim_result_steady_ci(&r, (size_t)q[i].k) / SIM_LAMBDA_P;
        double z = (mean - q[i].exact) / sigma, zw = (mean - q[i].wrong) / sigma;
        char name[32];
        print_message("%-10s %.6f (exact %.6f, z = %.2f; wrong z = %.1f)\n",
                      sim_steady_name(&s, (size_t)q[i].k, name, sizeof name), mean, q[i].exact, z,
                      zw);
        assert_true(fabs(z) < ZMAX);
        assert_true(fabs(zw) > ZMAX);
    }
    double zmax = 0.0, zmax_wrong = 0.0;
    for (size_t b = 0; b < 30; b++) {
        double lo = sim_steady_bin_lower(&s, b), hi = sim_steady_bin_lower(&s, b + 1);
        double vol = 4.0 * M_PI / 3.0 * (hi * hi * hi - lo * lo * lo);
        double exact = maxwell_shell(lo, hi) / vol;
        double centre = sim_steady_bin_centre(&s, b);
        double wrong = pow(M_PI, -1.5) * exp(-centre * centre * 1.02);
        double mean = sim_result_steady_mean(&r, SIM_STEADY_BIN0 + b);
        double sigma = sim_result_steady_ci(&r, SIM_STEADY_BIN0 + b) / SIM_LAMBDA_P;
        zmax = fmax(zmax, fabs(mean - exact) / sigma);
        zmax_wrong = fmax(zmax_wrong, fabs(mean - wrong) / sigma);
    }
    print_message("histogram: max z %.2f (a 2%% wider exponent: %.1f)\n", zmax, zmax_wrong);
    assert_true(zmax < ZMAX);
    assert_true(zmax_wrong > ZMAX);
    sim_ensemble_result_free(&r);
}

/* The time averages are those of the samples at the output times >= from
 * (their ensemble mean equals the mean over those rows), and sampling pairs
 * (its own random substream) leaves the trajectory unchanged. */
static void test_steady_time_average(void **state)
{
    (void)state;
    sim_scene s = ex5_scene(40, 50, 0.02, SIM_SPLIT_EULER);
    s.t_end = 1.0;
    s.outputs = 11;
    s.steady.present = 1;
    s.steady.from = 0.55;   /* rows 6 ... 10 */
    sim_ensemble_result a, b;
    run(&s, &a);
    s.steady.pairs = 500;
    run(&s, &b);
    assert_memory_equal(a.mean, b.mean, a.outputs * a.observables * sizeof(double));
    const int rows[] = {SIM_OBS_T, SIM_OBS_A2, SIM_OBS_A3};
    const int steady[] = {SIM_STEADY_T, SIM_STEADY_A2, SIM_STEADY_A3};
    for (int q = 0; q < 3; q++) {
        double avg = 0.0;
        for (size_t m = 6; m < 11; m++)
            avg += sim_result_mean(&a, m, rows[q]) / 5.0;
        assert_close(sim_result_steady_mean(&a, (size_t)steady[q]), avg, 1e-12, 1e-14);
    }
    assert_true(isnan(sim_result_steady_mean(&a, SIM_STEADY_MU2)));
    assert_true(isfinite(sim_result_steady_mean(&b, SIM_STEADY_MU2)));
    sim_ensemble_result_free(&a);
    sim_ensemble_result_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_white_noise_step),
        cmocka_unit_test(test_gaussian_steps),
        cmocka_unit_test(test_non_gaussian_step),
        cmocka_unit_test(test_white_noise_only),
        cmocka_unit_test(test_gaussian_with_elastic_collisions),
        cmocka_unit_test(test_keep_temperature),
        cmocka_unit_test(test_non_gaussian_momentum),
        cmocka_unit_test(test_elastic_rate),
        cmocka_unit_test(test_converges_to_jump),
        cmocka_unit_test(test_keep_temperature_jump),
        cmocka_unit_test(test_gaussian_jump),
        cmocka_unit_test(test_thread_count_independence),
        cmocka_unit_test(test_steady_maxwellian),
        cmocka_unit_test(test_steady_time_average),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
