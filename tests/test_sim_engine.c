/* The engine end to end on small systems, against exact results:
 * - Maxwell molecules with white-noise heating: the exact finite-n
 *   expectations of T_raw and T (reference/heated.h), z-tested at every
 *   output time;
 * - heating only: E T_raw = T0 + 2 beta t (paper A Eq. (18));
 * - momentum conservation and elastic energy conservation per ensemble;
 * - a scene without heating draws no Gaussian numbers after the initial state;
 * - the same numbers for 1 and 2 threads. */
#include "test_util.h"

#include <omp.h>
#include <string.h>

#include "engine.h"
#include "ensemble.h"
#include "heated.h"

#define ZMAX 4.5   /* max over output times of |mean - exact| / sigma */

/* SPEC §3 Ex 3 at small n: Maxwell, alpha = 1/2, beta = 1, gamma = 4, C0 = 1/(4 pi). */
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

static void run(const sim_scene *s, sim_ensemble_result *res)
{
    sim_engine *e = NULL;
    sim_error err;
    assert_int_equal(sim_engine_create(s, &e, &err), SIM_OK);
    assert_int_equal(sim_ensemble_run(e, NULL, NULL, res, &err), SIM_OK);
    sim_engine_free(e);
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
    double obs[9 * SIM_OBS_COUNT];
    sim_counts c = {0};
    sim_engine_run(e, ws, 3, obs, &c);
    double *last = obs + 8 * SIM_OBS_COUNT;
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
    assert_memory_equal(a.mean, b.mean, a.outputs * SIM_OBS_COUNT * sizeof(double));
    assert_memory_equal(a.ci, b.ci, a.outputs * SIM_OBS_COUNT * sizeof(double));
    assert_int_equal(a.counts.candidates, b.counts.candidates);
    sim_ensemble_result_free(&a);
    sim_ensemble_result_free(&b);
}

/* Valid scenes the engine cannot run yet are refused with the key at fault. */
static void test_unsupported(void **state)
{
    (void)state;
    sim_scene s = heated_maxwell_scene(8, 1);
    sim_engine *e = NULL;
    sim_error err;
    s.scheme = SIM_SCHEME_TIMESTEP;
    assert_int_equal(sim_engine_create(&s, &e, &err), SIM_EUNSUPPORTED);
    assert_string_equal(err.key, "scene.scheme");
    assert_null(e);
    s = heated_maxwell_scene(8, 1);
    s.heating.type = SIM_HEATING_GAUSSIAN;
    assert_int_equal(sim_engine_create(&s, &e, &err), SIM_EUNSUPPORTED);
    assert_string_equal(err.key, "heating.type");
    sim_engine_free(NULL);
    sim_workspace_free(NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_heated_maxwell_exact_finite_n),
        cmocka_unit_test(test_heating_only),
        cmocka_unit_test(test_conservation),
        cmocka_unit_test(test_no_heating_draws_no_gaussians),
        cmocka_unit_test(test_thread_count_independence),
        cmocka_unit_test(test_unsupported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
