/* The engine end to end on small systems, against exact results:
 * - Maxwell molecules with white-noise heating: the exact finite-n
 *   expectations of T_raw and T (reference/heated.h), z-tested at every
 *   output time;
 * - heating only: E T_raw = T0 + 2 beta t (paper A Eq. (18));
 * - momentum conservation and elastic energy conservation per ensemble;
 * - a scene without heating draws no Gaussian numbers after the initial state;
 * - the same numbers for 1 and 2 threads;
 * - hard spheres (the two-stage majorant of effect_collisions.c): the number
 *   of collisions against the exact rate in each loop the engine can build
 *   (its own loop, one candidate per call with a lazy flow, and mixed with a
 *   background), under strong white noise (the bound reset between output
 *   times), and for two particles, whose rate |g|/2 never changes,
 *   through the Poisson counts and beta-distributed times of the loop without
 *   a lazy flow;
 * - paper B's background (docs/theory.md §5): collision counts against the exact rates
 *   4 pi C1 rho_B (Maxwell) and E1(v) (hard spheres, Algorithm 2), the
 *   equilibrium with the background preserved, and for Maxwell kernels the
 *   exact finite-n expectations of u and T (reference/background.h). */
#include "test_sim_util.h"

#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "collide.h"
#include "engine.h"
#include "ensemble.h"
#include "background.h"
#include "heated.h"

#define ZMAX 4.5   /* max over output times of |mean - exact| / sigma */

/* Paper A Ex 3 at small n: Maxwell, alpha = 1/2, beta = 1, gamma = 4, C0 = 1/(4 pi). */
static sim_scene heated_maxwell_scene(size_t n, size_t ensembles)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.t_end = 2.0;
    s.outputs = 9;
    s.seed = 2385;
    s.particles.n = n;
    s.particles.ensembles = ensembles;
    s.collisions.present = 1;
    s.collisions.rate = 4.0;
    s.collisions.restitution = 0.5;
    s.heating.present = 1;
    s.heating.strength = 1.0;
    return s;
}

/* Largest |mean - exact| / sigma over the output times (sigma = ci / lambda_p). */
static double max_z(const sim_ensemble_result *r, int k, double (*exact)(double t, void *),
                    void *ctx)
{
    double z = 0.0;
    for (size_t m = 1; m < r->outputs; m++) {
        double sigma = sim_result_ci(r, m, k) / SIM_LAMBDA_P;
        z = fmax(z, fabs(sim_result_mean(r, m, k) - exact(r->t[m], ctx)) / sigma);
    }
    return z;
}

typedef struct finite_n {
    ref_heated_params p;
    double n;
} finite_n;

static double exact_T_raw(double t, void *ctx)
{
    finite_n *f = ctx;
    return ref_heated_maxwell_T_raw_mean(&f->p, f->n, t);
}

static double exact_T_centred(double t, void *ctx)
{
    finite_n *f = ctx;
    return ref_heated_maxwell_T_centred_mean(&f->p, f->n, t);
}

static void test_heated_maxwell_exact_finite_n(void **state)
{
    (void)state;
    sim_scene s = heated_maxwell_scene(8, 4000);
    sim_ensemble_result r;
    run(&s, &r);
    finite_n f = {{.alpha = 0.5, .beta = 1.0, .gamma = 4.0, .C = s.collisions.constant,
                   .T0 = 1.0},
                  8.0};
    double z_raw = max_z(&r, SIM_OBS_T_RAW, exact_T_raw, &f);
    double z_centred = max_z(&r, SIM_OBS_T, exact_T_centred, &f);
    print_message("max z: T_raw %.2f, T %.2f\n", z_raw, z_centred);
    assert_true(z_raw < ZMAX);
    assert_true(z_centred < ZMAX);
    /* The same check fails for a solver with the wrong restitution: the
     * O(1/n) terms at n = 8 are far larger than the statistical error. */
    f.p.alpha = 0.45;
    assert_true(max_z(&r, SIM_OBS_T_RAW, exact_T_raw, &f) > ZMAX);
    /* ... and for the infinite-n curve, which ignores the O(1/n) bias. */
    f.p.alpha = 0.5;
    f.n = 1e30;
    assert_true(max_z(&r, SIM_OBS_T_RAW, exact_T_raw, &f) > ZMAX);
    assert_int_equal(r.counts.violations, 0);
    sim_ensemble_result_free(&r);
}

static double heating_only_T_raw(double t, void *ctx)
{
    return 1.0 + 2.0 * *(double *)ctx * t;
}

static void test_heating_only(void **state)
{
    (void)state;
    sim_scene s = heated_maxwell_scene(5, 3000);
    s.collisions.present = 0;
    s.heating.strength = 0.37;
    sim_ensemble_result r;
    run(&s, &r);
    double beta = 0.37;
    assert_true(max_z(&r, SIM_OBS_T_RAW, heating_only_T_raw, &beta) < ZMAX);
    beta = 0.40;
    assert_true(max_z(&r, SIM_OBS_T_RAW, heating_only_T_raw, &beta) > ZMAX);
    assert_int_equal(r.counts.candidates, 0);
    sim_ensemble_result_free(&r);
}

/* Binary collisions conserve each ensemble's momentum (to round-off); elastic
 * hard spheres also its energy, and they never violate the majorant. */
static void test_conservation(void **state)
{
    (void)state;
    sim_scene s = heated_maxwell_scene(50, 1);
    s.heating.present = 0;
    s.collisions.kernel = SIM_KERNEL_HARD_SPHERES;
    s.collisions.exponent = 1.0;
    s.collisions.restitution = 1.0;
    s.particles.maxwellian.velocity[1] = 0.731;
    sim_engine *e = NULL;
    sim_workspace *ws = NULL;
    assert_int_equal(sim_engine_create(&s, &e, NULL), SIM_OK);
    assert_int_equal(sim_workspace_create(e, &ws, NULL), SIM_OK);
    assert_int_equal(sim_engine_observables(e), SIM_OBS_BASE);   /* obs fits */
    double obs[9 * SIM_OBS_BASE];
    sim_counts c = {0};
    sim_engine_run(e, ws, 3, obs, &c);
    double *last = obs + 8 * SIM_OBS_BASE;
    for (int k = SIM_OBS_UX; k <= SIM_OBS_UZ; k++)
        assert_close(last[k], obs[k], 0.0, 1e-14);
    assert_close(last[SIM_OBS_T_RAW], obs[SIM_OBS_T_RAW], 1e-13, 0.0);
    assert_true(c.collisions > 300);   /* about 2 (n-1) E|g| t_end = 440 */
    assert_true(c.candidates > c.collisions);   /* hard spheres: some fictitious */
    assert_int_equal(c.violations, 0);
    assert_int_equal(c.normals, 3 * 50);        /* the initial Maxwellian only */
    sim_workspace_free(ws);
    sim_engine_free(e);
}

/* sim_engine_start then sim_engine_evolve is sim_engine_run, also on a
 * workspace that ran another ensemble before (steady averages included:
 * their sample count lives in the workspace between the two calls). */
static void test_start_evolve_is_run(void **state)
{
    (void)state;
    sim_scene s = heated_maxwell_scene(40, 1);
    s.steady.present = 1;
    s.steady.from = 1.0;
    s.steady.pairs = 100;
    sim_engine *e = NULL;
    sim_workspace *fresh = NULL, *used = NULL;
    assert_int_equal(sim_engine_create(&s, &e, NULL), SIM_OK);
    assert_int_equal(sim_workspace_create(e, &fresh, NULL), SIM_OK);
    assert_int_equal(sim_workspace_create(e, &used, NULL), SIM_OK);
    const size_t len = s.outputs * sim_engine_observables(e) + sim_engine_steady_count(e);
    assert_true(sim_engine_steady_count(e) > 0);
    double *whole = calloc(len, sizeof *whole), *parts = calloc(len, sizeof *parts);
    assert_non_null(whole);
    assert_non_null(parts);
    sim_counts a = {0}, b = {0}, other = {0};
    sim_engine_run(e, fresh, 3, whole, &a);
    sim_engine_run(e, used, 5, parts, &other);
    sim_engine_start(e, used, 3, parts);
    sim_engine_evolve(e, used, parts, &b);
    assert_memory_equal(whole, parts, len * sizeof *whole);
    assert_memory_equal(&a, &b, sizeof a);
    assert_true(a.collisions > 0);
    assert_memory_not_equal(&a, &other, sizeof a);   /* ensemble 5 differs */
    free(whole);
    free(parts);
    sim_workspace_free(fresh);
    sim_workspace_free(used);
    sim_engine_free(e);
}

/* A scene without heating draws no Gaussian numbers beyond the 3 n of the
 * initial state; with heating it draws them for every Brownian catch-up. */
static void test_no_heating_draws_no_gaussians(void **state)
{
    (void)state;
    sim_scene s = heated_maxwell_scene(16, 40);
    sim_ensemble_result r;
    s.heating.present = 0;
    run(&s, &r);
    assert_true(r.counts.collisions > 0);
    assert_int_equal(r.counts.normals, 3 * 16 * 40);
    sim_ensemble_result_free(&r);

    s.heating.present = 1;
    run(&s, &r);
    assert_true(r.counts.normals > 3 * 16 * 40 + 2 * 3 * r.counts.collisions);
    sim_ensemble_result_free(&r);
}

/* Ensemble j uses stream (seed, j) and sums go in fixed blocks: the results
 * are bit-identical for 1 and 2 threads. */
static void test_thread_count_independence(void **state)
{
    (void)state;
    sim_scene s = heated_maxwell_scene(12, 300);
    s.collisions.kernel = SIM_KERNEL_VHS;
    s.collisions.exponent = 0.5;
    sim_ensemble_result a, b;
    omp_set_num_threads(1);
    run(&s, &a);
    omp_set_num_threads(2);
    run(&s, &b);
    assert_int_equal(a.threads, 1);
    assert_int_equal(b.threads, 2);   /* else the comparison would be vacuous */
    assert_memory_equal(a.mean, b.mean, a.outputs * a.observables * sizeof(double));
    assert_memory_equal(a.ci, b.ci, a.outputs * a.observables * sizeof(double));
    assert_int_equal(a.counts.candidates, b.counts.candidates);
    sim_ensemble_result_free(&a);
    sim_ensemble_result_free(&b);
}

/* Elastic hard spheres (C = 1/(4 pi), gamma = 1) from a standard
 * Maxwellian, heated with strength beta (0: no heating). */
static sim_scene elastic_hard_sphere_scene(size_t n, size_t N, double t_end, size_t outputs,
                                           double beta)
{
    sim_scene s = heated_maxwell_scene(n, N);
    s.t_end = t_end;
    s.outputs = outputs;
    s.collisions.kernel = SIM_KERNEL_HARD_SPHERES;
    s.collisions.exponent = 1.0;
    s.collisions.rate = 1.0;
    s.collisions.restitution = 1.0;
    s.heating.present = beta > 0.0;
    s.heating.strength = beta;
    return s;
}

/* The collision count of N runs of n particles against its expectation: the
 * standard deviation is Poisson's and that of the runs' temperatures (E|g| ~
 * sqrt(T), Var T / T^2 = 2 / (3 n) per run, so the relative variance of the
 * expectation is 1 / (6 n N)); 5% fewer collisions must fail the same
 * z-test.  Returns z. */
static double assert_collision_count(double count, double expected, size_t n, size_t N)
{
    const double sigma = sqrt(expected + expected * expected / (6.0 * (double)(n * N)));
    const double z = (count - expected) / sigma, z_wrong = (count - 0.95 * expected) / sigma;
    assert_true(fabs(z) < ZMAX);
    assert_true(fabs(z_wrong) > ZMAX);
    return z;
}

/* Elastic hard spheres from a standard Maxwellian keep the product
 * Maxwellian (it is invariant), so the expected number of binary collisions
 * is 2 pi gamma C (n - 1) E|g| t per ensemble, E|g| = 4/sqrt(pi) (docs/theory.md §2.2,
 * the rate 4 pi gamma C |g| / n per pair), in each engine shape:
 *  0: collisions only (the process's own batched loop, Poisson counts),
 *  1: with white-noise heating of strength 1e-12 (the lazy flow: one
 *     candidate per call with its waiting time; T moves by 1e-11),
 *  2: with a hard-sphere background of vanishing mass (m_B = 1e-9: the
 *     grains keep their velocities to 1e-8; candidates of two processes).
 * The count is z-tested (assert_collision_count). */
static void test_hard_sphere_rate_paths(void **state)
{
    (void)state;
    const size_t n = 300, N = 100;
    const double t_end = 4.0;
    const double expected = 2.0 * M_PI / (4.0 * M_PI) * (double)(n - 1) * 4.0 / sqrt(M_PI)
                            * t_end * (double)N;
    const char *names[] = {"collisions only", "with a lazy flow", "with a background"};
    for (int shape = 0; shape < 3; shape++) {
        sim_scene s = elastic_hard_sphere_scene(n, N, t_end, 5, shape == 1 ? 1e-12 : 0.0);
        if (shape == 2) {
            s.background.present = 1;
            s.background.kernel = SIM_KERNEL_HARD_SPHERES;
            s.background.mass = 1e-9;
            s.background.temperature = 1e-9;
        }
        sim_ensemble_result r;
        run(&s, &r);
        const double count = (double)r.counts.collisions;
        const double z = assert_collision_count(count, expected, n, N);
        print_message("hard spheres %s: %.0f collisions, expected %.0f (z = %.2f), %llu "
                      "candidates, %llu background\n", names[shape], count, expected, z,
                      (unsigned long long)r.counts.candidates,
                      (unsigned long long)r.counts.background);
        assert_int_equal(r.counts.violations, 0);
        if (shape == 2)
            assert_true(r.counts.background > 10000);
        sim_ensemble_result_free(&r);
    }
}

/* Elastic hard spheres under strong white noise (beta = 1, T0 = 1): the
 * product Maxwellian stays one, at T(t) = 1 + 2 t (heating convolves each
 * velocity with a Gaussian, elastic collisions keep any product Maxwellian),
 * so the expected number of collisions per ensemble is 2 pi gamma C (n - 1)
 * 4 / sqrt(pi) ∫ sqrt(1 + 2 t) dt = ... ((1 + 2 t_end)^{3/2} - 1) / 3.  Output
 * times 2 apart: the flow's reach over a whole interval (7 sigma = 14)
 * would inflate the majorant, so the engine resets the bound between output
 * times as well (engine.c, lazy_reset), each particle carrying its own reach
 * from its stamp.  The count is exact through those resets (the wrong
 * answer, 5% fewer, fails), no draw outruns the bound, and the majorant
 * stays tight: fewer than 6 candidates per collision (5.29 measured; 9.27
 * with resets at output times only). */
static void test_hard_sphere_heated_rate(void **state)
{
    (void)state;
    const size_t n = 300, N = 100;
    const double t_end = 4.0;
    sim_scene s = elastic_hard_sphere_scene(n, N, t_end, 3, 1.0);
    const double expected = 2.0 * M_PI / (4.0 * M_PI) * (double)(n - 1) * 4.0 / sqrt(M_PI)
                            * (pow(1.0 + 2.0 * t_end, 1.5) - 1.0) / 3.0 * (double)N;
    sim_ensemble_result r;
    run(&s, &r);
    const double count = (double)r.counts.collisions;
    const double z = assert_collision_count(count, expected, n, N);
    const double per_collision = (double)r.counts.candidates / count;
    print_message("heated hard spheres: %.0f collisions, expected %.0f (z = %.2f), %.2f "
                  "candidates per collision\n", count, expected, z, per_collision);
    assert_int_equal(r.counts.violations, 0);
    assert_true(per_collision < 6.0);
    sim_ensemble_result_free(&r);
}

/* Two elastic hard spheres: |g| never changes, so each run's number of
 * collisions is Poisson with mean 2 pi gamma C |g| t_end = |g| t_end / 2
 * (C = 1/(4 pi)), |g| = sqrt(12 T) from the run's first row (T = |g|^2/12
 * for n = 2, m = 1).  Without a lazy flow the engine draws Poisson numbers
 * of candidates and recomputes the bound every 4 n = 8 candidates, each time
 * placing the candidate at a beta-distributed time of its span: a wrong time
 * there would bias the count.  The wrong answer (2% off) fails. */
static void test_two_particles_counted(void **state)
{
    (void)state;
    sim_scene s = heated_maxwell_scene(2, 1);
    s.heating.present = 0;
    s.collisions.kernel = SIM_KERNEL_HARD_SPHERES;
    s.collisions.exponent = 1.0;
    s.collisions.rate = 1.0;
    s.collisions.restitution = 1.0;
    s.t_end = 20.0;
    s.outputs = 3;
    sim_engine *e = NULL;
    sim_workspace *ws = NULL;
    assert_int_equal(sim_engine_create(&s, &e, NULL), SIM_OK);
    assert_int_equal(sim_workspace_create(e, &ws, NULL), SIM_OK);
    sim_counts c = {0};
    double mean = 0.0;
    for (uint64_t j = 0; j < 4000; j++) {
        assert_int_equal(sim_engine_observables(e), SIM_OBS_BASE);   /* obs fits */
        double obs[3 * SIM_OBS_BASE];
        sim_engine_run(e, ws, j, obs, &c);
        assert_close(obs[2 * SIM_OBS_BASE + SIM_OBS_T], obs[SIM_OBS_T], 1e-12, 0.0);
        mean += sqrt(12.0 * obs[SIM_OBS_T]) * s.t_end / 2.0;
    }
    const double count = (double)c.collisions, z = (count - mean) / sqrt(mean);
    print_message("two particles: %.0f collisions, expected %.0f (z = %.2f), %llu candidates\n",
                  count, mean, z, (unsigned long long)c.candidates);
    assert_true(fabs(z) < ZMAX);
    assert_true(fabs(count - 0.98 * mean) / sqrt(mean) > ZMAX);
    assert_int_equal(c.violations, 0);
    sim_workspace_free(ws);
    sim_engine_free(e);
}

/* A scene with only a background (docs/theory.md §5): grains of mass 1 at velocity v0
 * (temperature T0), background at rest with rho_B = C1 = 1. */
static sim_scene background_scene(size_t n, size_t ensembles, sim_kernel_kind kernel,
                                  double m_B, double T_B, const double v0[3], double T0)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.t_end = 1.0;
    s.outputs = 11;
    s.seed = 2010;
    s.particles.n = n;
    s.particles.ensembles = ensembles;
    s.particles.maxwellian.temperature = T0;
    memcpy(s.particles.maxwellian.velocity, v0, 3 * sizeof *v0);
    s.background.present = 1;
    s.background.kernel = kernel;
    s.background.mass = m_B;
    s.background.temperature = T_B;
    return s;
}

static ref_background_params background_params_of(const sim_scene *s)
{
    ref_background_params p = {
        .mass = 1.0, .bg_density = s->background.density, .bg_mass = s->background.mass,
        .bg_temperature = s->background.temperature, .C1 = s->background.constant,
        .density = 1.0, .C2 = s->collisions.present ? s->collisions.constant : 0.0,
        .restitution = s->collisions.present ? s->collisions.restitution : 1.0,
        .T0 = s->particles.maxwellian.temperature};
    memcpy(p.bg_velocity, s->background.velocity, sizeof p.bg_velocity);
    memcpy(p.u0, s->particles.maxwellian.velocity, sizeof p.u0);
    return p;
}

/* The number of accepted background collisions is Poisson with mean
 * n N t E1(v) when the grain velocity does not change: a background of
 * vanishing mass (m_B = 1e-9, alpha ~ 1e-9) with T_B/m_B = 1 (b = sqrt 2)
 * leaves v0 in place to 1e-7 over the run.  Hard spheres: E1(v) of docs/theory.md §5.1 at
 * |v0 - u_B| = 1.5 and at v0 = u_B; Maxwell: 4 pi C1 rho_B. */
static void test_background_rates(void **state)
{
    (void)state;
    const double v_list[][3] = {{0.9, -1.2, 0.0}, {0.0, 0.0, 0.0}};
    for (int kernel = 0; kernel < 2; kernel++) {
        for (size_t i = 0; i < 2; i++) {
            sim_scene s = background_scene(50, 200,
                                           kernel ? SIM_KERNEL_HARD_SPHERES : SIM_KERNEL_MAXWELL,
                                           1e-9, 1e-9, v_list[i], 1e-30);
            s.t_end = 4.0;
            s.outputs = 2;
            sim_ensemble_result r;
            run(&s, &r);
            ref_background_params p = background_params_of(&s);
            double E1 = kernel ? ref_background_hs_E1(&p, v_list[i]) : 4.0 * M_PI;
            double mean = 50.0 * 200.0 * 4.0 * E1, count = (double)r.counts.background;
            double z = (count - mean) / sqrt(mean);
            print_message("%s, |v0| = %.1f: %.0f background collisions, expected %.0f (z = "
                          "%.2f), %llu candidates\n", kernel ? "hard spheres" : "Maxwell",
                          sim_norm3(v_list[i]), count, mean, z,
                          (unsigned long long)r.counts.candidates);
            assert_true(fabs(z) < ZMAX);
            assert_int_equal(r.counts.violations, 0);
            assert_int_equal(r.counts.collisions, 0);
            if (kernel && i == 0)   /* fictitious candidates, except when a_max = 0 */
                assert_true(r.counts.candidates > r.counts.background);
            else   /* Maxwell, or hard spheres at v0 = u_B: the majorant is the rate */
                assert_int_equal(r.counts.candidates, r.counts.background);
            /* the wrong answer: the paper's majorant E1max is not the rate */
            if (kernel && i == 0) {
                double wrong = 50.0 * 200.0 * 4.0 * ref_background_hs_E1_majorant(&p, v_list[i]);
                assert_true(fabs(count - wrong) / sqrt(wrong) > ZMAX);
            }
            sim_ensemble_result_free(&r);
        }
    }
}

static double constant_value(double t, void *ctx)
{
    (void)t;
    return *(double *)ctx;
}

/* Grains that start in equilibrium with a hard-sphere background (Maxwellian
 * at T_B, u_B; any mass ratio) stay there: E T_n = (1 - 1/n) T_B and
 * E u_n = u_B at every time.  Algorithm 2 with a wrong partner density would
 * heat or cool the gas. */
static void test_background_hs_equilibrium(void **state)
{
    (void)state;
    const double u_B[3] = {0.0, 1.0, 0.0};
    sim_scene s = background_scene(8, 4000, SIM_KERNEL_HARD_SPHERES, 0.5, 1.3, u_B, 1.3);
    memcpy(s.background.velocity, u_B, sizeof u_B);
    sim_ensemble_result r;
    run(&s, &r);
    double T_mean = (1.0 - 1.0 / 8.0) * 1.3, uy = 1.0, zero = 0.0;
    double zT = max_z(&r, SIM_OBS_T, constant_value, &T_mean);
    double zu = fmax(max_z(&r, SIM_OBS_UY, constant_value, &uy),
                     max_z(&r, SIM_OBS_UX, constant_value, &zero));
    print_message("equilibrium: max z T %.2f, u %.2f; %llu candidates, %llu accepted\n", zT, zu,
                  (unsigned long long)r.counts.candidates,
                  (unsigned long long)r.counts.background);
    assert_true(zT < ZMAX);
    assert_true(zu < ZMAX);
    assert_true(r.counts.background > 100000);
    assert_int_equal(r.counts.violations, 0);
    double T_inf = 1.3;   /* the wrong answer: without the O(1/n) bias */
    assert_true(max_z(&r, SIM_OBS_T, constant_value, &T_inf) > ZMAX);
    sim_ensemble_result_free(&r);
}

typedef struct maxwell_exact {
    ref_background_params p;
    const double *T_mean;   /* at the result's output times */
    const sim_ensemble_result *r;
} maxwell_exact;

static double exact_uy(double t, void *ctx)
{
    double u[3];
    ref_background_maxwell_u(&((maxwell_exact *)ctx)->p, t, u);
    return u[1];
}

static double exact_T_mean(double t, void *ctx)
{
    maxwell_exact *x = ctx;
    for (size_t m = 0; m < x->r->outputs; m++)
        if (x->r->t[m] == t)
            return x->T_mean[m];
    return NAN;
}

/* Paper B Ex 1 at n = 4: two-Maxwellian start, Maxwell kernels for both
 * collision kinds.  E u_n = u(t) and E T_n from the exact finite-n system. */
static void test_background_maxwell_exact(void **state)
{
    (void)state;
    const double zero[3] = {0, 0, 0};
    sim_scene s = background_scene(4, 6000, SIM_KERNEL_MAXWELL, 1.0, 1.0, zero, 1.0);
    s.outputs = 17;
    s.particles.initial = SIM_INITIAL_TWO_MAXWELLIANS;
    s.particles.fraction = 0.5;
    s.particles.first = (sim_maxwellian){1.0, {-2.0, 2.0, 0.0}, 1.0};
    s.particles.second = (sim_maxwellian){1.0, {2.0, 0.0, 0.0}, 1.0};
    s.collisions.present = 1;
    s.collisions.constant = 1.0;
    s.collisions.restitution = 0.5;
    sim_ensemble_result r;
    run(&s, &r);
    maxwell_exact x = {background_params_of(&s), NULL, &r};
    x.p.T0 = 8.0 / 3.0;   /* the mixture's temperature and mean velocity */
    x.p.u0[0] = 0.0;
    x.p.u0[1] = 1.0;
    double T_mean[17];
    char msg[200];
    assert_int_equal(ref_background_maxwell_T_mean(&x.p, 4.0, r.t, r.outputs, NULL, T_mean, msg,
                                                   sizeof msg), REF_OK);
    x.T_mean = T_mean;
    double zu = max_z(&r, SIM_OBS_UY, exact_uy, &x), zT = max_z(&r, SIM_OBS_T, exact_T_mean, &x);
    print_message("Maxwell background, n = 4: max z u_y %.2f, T %.2f\n", zu, zT);
    assert_true(zu < ZMAX);
    assert_true(zT < ZMAX);
    /* the wrong answer: the n = infinity temperature (B.15) */
    for (size_t m = 0; m < r.outputs; m++)
        T_mean[m] = ref_background_maxwell_T(&x.p, r.t[m]);
    assert_true(max_z(&r, SIM_OBS_T, exact_T_mean, &x) > ZMAX);
    sim_ensemble_result_free(&r);
}

/* Every combination of kernels shares the velocity bound: the binary
 * majorant must cover velocities the background changed and vice versa. */
static void test_background_with_binary_kernels(void **state)
{
    (void)state;
    const double zero[3] = {0, 0, 0};
    for (int bin = 0; bin < 2; bin++) {
        for (int bg = 0; bg < 2; bg++) {
            sim_scene s = background_scene(16, 300, bg ? SIM_KERNEL_HARD_SPHERES
                                                        : SIM_KERNEL_MAXWELL, 1.0, 1.0, zero, 3.0);
            s.background.velocity[1] = 2.0;   /* the gas is pulled, so speeds change a lot */
            s.collisions.present = 1;
            s.collisions.kernel = bin ? SIM_KERNEL_HARD_SPHERES : SIM_KERNEL_MAXWELL;
            s.collisions.exponent = bin;
            s.collisions.constant = 1.0;
            s.collisions.restitution = 0.5;
            sim_ensemble_result r;
            run(&s, &r);
            assert_true(r.counts.collisions > 1000);
            assert_true(r.counts.background > 1000);
            assert_int_equal(r.counts.violations, 0);
            sim_ensemble_result_free(&r);
        }
    }
}

/* The engine refuses scene s with status `status`, naming key. */
static void expect_refused(const sim_scene *s, sim_status status, const char *key)
{
    sim_engine *e = NULL;
    sim_error err;
    assert_int_equal(sim_engine_create(s, &e, &err), status);
    assert_null(e);
    assert_string_equal(err.key, key);
}

/* The heated Maxwell scene in the time-step scheme (dt = 0.01). */
static sim_scene timestep_scene(void)
{
    sim_scene s = heated_maxwell_scene(8, 1);
    s.scheme = SIM_SCHEME_TIMESTEP;
    s.dt = 0.01;
    return s;
}

/* Valid scenes the engine cannot run yet are refused with the key at fault. */
static void test_unsupported(void **state)
{
    (void)state;
    sim_scene s = heated_maxwell_scene(8, 1);
    s.heating.type = SIM_HEATING_NON_GAUSSIAN;   /* the jump scheme: white noise, Gaussian */
    expect_refused(&s, SIM_EUNSUPPORTED, "heating.type");
    s = timestep_scene();   /* no background in the time-step scheme */
    s.collisions.present = 0;
    s.background.present = 1;
    expect_refused(&s, SIM_EUNSUPPORTED, "background");
    s = heated_maxwell_scene(8, 1);
    s.particles.initial = SIM_INITIAL_TWO_MAXWELLIANS;
    s.particles.first.mass = 1.0;
    s.particles.second.mass = 2.0;
    expect_refused(&s, SIM_EUNSUPPORTED, "particles.mass2");
    /* observe_only: base observables only; none with [shear] (its row is
     * made from every base observable); T with step_follows_temperature */
    s = heated_maxwell_scene(8, 1);
    s.observe_only = SIM_OBS_BIT(SIM_OBS_BASE);
    expect_refused(&s, SIM_EINVAL, "scene.observe_only");
    s = timestep_scene();
    s.heating.present = 0;
    s.shear.present = 1;
    s.shear.rate = 1.0;
    s.observe_only = SIM_OBS_BIT(SIM_OBS_T);
    expect_refused(&s, SIM_EUNSUPPORTED, "scene.observe_only");
    s = timestep_scene();
    s.heating.present = 0;
    s.step_follows_temperature = 1;
    s.observe_only = SIM_OBS_BIT(SIM_OBS_T_RAW);
    expect_refused(&s, SIM_EINVAL, "scene.observe_only");
    s.observe_only |= SIM_OBS_BIT(SIM_OBS_T);
    sim_engine *e = NULL;
    assert_int_equal(sim_engine_create(&s, &e, NULL), SIM_OK);
    sim_engine_free(e);
    sim_engine_free(NULL);
    sim_workspace_free(NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_heated_maxwell_exact_finite_n),
        cmocka_unit_test(test_heating_only),
        cmocka_unit_test(test_conservation),
        cmocka_unit_test(test_start_evolve_is_run),
        cmocka_unit_test(test_no_heating_draws_no_gaussians),
        cmocka_unit_test(test_thread_count_independence),
        cmocka_unit_test(test_hard_sphere_rate_paths),
        cmocka_unit_test(test_hard_sphere_heated_rate),
        cmocka_unit_test(test_two_particles_counted),
        cmocka_unit_test(test_background_rates),
        cmocka_unit_test(test_background_hs_equilibrium),
        cmocka_unit_test(test_background_maxwell_exact),
        cmocka_unit_test(test_background_with_binary_kernels),
        cmocka_unit_test(test_unsupported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
