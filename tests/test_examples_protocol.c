/* The solver-protocol helpers of examples/c/gdsmc_protocol.h against the
 * engine's own definitions (sim/observe.c, sim/steady.c): for one fixed
 * velocity array (a drift, unequal spreads and a skewed component, so that
 * every observable is far from 0) the helpers' observables and steady
 * quantities must be the engine's to round-off, and the pair-sampled mu2,
 * mu4 of both must agree with their exact mean over all ordered pairs,
 * computed here from paper C Eqs. (65)-(66), within |z| <= 4.5.  The output
 * times and the defaults of a scene file are the engine's.
 *
 * The test also writes the array and the engine's values to
 * examples-protocol-engine.txt in its working directory, which
 * tests/check_examples_protocol.py holds examples/python/gdsmc_protocol.py
 * to (the CTest fixture examples_engine_values).
 */
#include "test_util.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../examples/c/gdsmc_protocol.h"
#include "observe.h"
#include "rng.h"
#include "steady.h"

enum { NP = 400, BINS = 25, PAIRS = 4000000 };   /* PAIRS: a 0.5% error in Phi2 is z = 5 */
static const double mass = 2.385, alpha = 0.3, c_max = 4.0;
static double v[NP][3];

static int setup(void **state)
{
    (void)state;
    gp_rng r;
    gp_rng_seed(&r, 20261127, 0);
    for (int i = 0; i < NP; i++) {
        const double x = gp_rng_normal(&r);
        v[i][0] = 0.31 + 0.8 * x + 0.45 * x * x;   /* skewed: q and a3 far from 0 */
        v[i][1] = -0.72 + 1.3 * gp_rng_normal(&r);
        v[i][2] = 1.1 + 0.6 * gp_rng_normal(&r);
    }
    return 0;
}

static sim_scene steady_scene(size_t pairs)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.steady.present = 1;
    s.steady.bins = BINS;
    s.steady.c_max = c_max;
    s.steady.pairs = pairs;
    s.collisions.present = 1;
    s.collisions.restitution = alpha;
    return s;
}

static gp_steady gp_spec(size_t pairs)
{
    gp_steady st = {.active = 1, .from = 0.0, .c_max = c_max, .alpha = alpha,
                    .pairs = pairs, .bins = BINS};
    return st;
}

/* The base observables, to round-off. */
static void test_observables(void **state)
{
    (void)state;
    sim_particles p = {NP, v, NULL, NULL};
    double engine[SIM_OBS_BASE], helper[GP_NOBS];
    sim_observe(&p, mass, engine);
    gp_observe((const double (*)[3])v, NP, mass, helper);
    assert_int_equal(GP_NOBS, SIM_OBS_BASE);
    for (int k = 0; k < GP_NOBS; k++) {
        char name[SIM_OBS_NAME_LEN];
        sim_scene s;
        sim_scene_defaults(&s);
        assert_string_equal(gp_obs_name[k], sim_observable_name(&s, (size_t)k, name));
        assert_true(fabs(engine[k]) > 1e-3);
        assert_close(helper[k], engine[k], 1e-13, 0.0);
    }
}

/* The steady quantities without pairs (mu2, mu4 and the relations NaN in
 * both), to round-off: T, a2, a3, c1, c3 and every histogram shell. */
static void test_steady_without_pairs(void **state)
{
    (void)state;
    sim_particles p = {NP, v, NULL, NULL};
    sim_scene s = steady_scene(0);
    const gp_steady st = gp_spec(0);
    assert_int_equal(sim_steady_count(&s), gp_steady_count(&st));
    double engine[GP_STEADY_SCALARS + BINS] = {0}, helper[GP_STEADY_SCALARS + BINS] = {0};
    sim_steady_sample(&s, &p, mass, NULL, NULL, engine);
    gp_steady_sample(&st, (const double (*)[3])v, NP, mass, NULL, helper);
    size_t filled = 0;
    for (size_t k = 0; k < gp_steady_count(&st); k++) {
        char a[32], b[32];
        assert_string_equal(gp_steady_name(k, a), sim_steady_name(&s, k, b, sizeof b));
        if (isnan(engine[k])) {
            assert_true(isnan(helper[k]));
            continue;
        }
        assert_close(helper[k], engine[k], 1e-13, 1e-300);
        filled += k >= GP_STEADY_SCALARS && engine[k] > 0.0;
    }
    assert_true(filled > BINS / 2);   /* the histogram is exercised */
}

/* Paper C Eqs. (65)-(66), written out once more for the exact means. */
static void phi(const double c1[3], const double c2[3], double *p2, double *p4)
{
    double g[3], G[3];
    for (int k = 0; k < 3; k++) {
        g[k] = c1[k] - c2[k];
        G[k] = 0.5 * (c1[k] + c2[k]);
    }
    const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
    const double G2 = G[0] * G[0] + G[1] * G[1] + G[2] * G[2];
    const double gG = g[0] * G[0] + g[1] * G[1] + g[2] * G[2];
    const double a2 = alpha * alpha, gn = sqrt(g2);
    *p2 = M_PI / 8.0 * (1.0 - a2) * gn * g2;
    *p4 = M_PI / 4.0 * gn
          * (5.0 * (1.0 - a2) / 3.0 * g2 * G2 + (1.0 - a2) * (2.0 + a2) / 12.0 * g2 * g2
             + (3.0 - alpha) * (1.0 + alpha) * (gG * gG - g2 * G2 / 3.0));
}

/* mu2 and mu4 of both, each by PAIRS random pairs, against the exact mean
 * over all ordered pairs; the exact relations of each from its own mu2. */
static void test_steady_pairs(void **state)
{
    (void)state;
    double V[3] = {0, 0, 0}, c2 = 0.0, C[NP][3];
    for (int i = 0; i < NP; i++)
        for (int k = 0; k < 3; k++)
            V[k] += v[i][k] / NP;
    for (int i = 0; i < NP; i++)
        for (int k = 0; k < 3; k++) {
            C[i][k] = v[i][k] - V[k];
            c2 += C[i][k] * C[i][k];
        }
    const double v0 = sqrt(2.0 * c2 / (3.0 * NP));
    double s[2] = {0, 0}, ss[2] = {0, 0}, pairs = 0.0;
    for (int i = 0; i < NP; i++)
        for (int j = 0; j < NP; j++) {
            if (i == j)
                continue;
            double p[2];
            phi(C[i], C[j], &p[0], &p[1]);
            p[0] /= pow(v0, 3.0);
            p[1] /= pow(v0, 5.0);
            for (int k = 0; k < 2; k++) {
                s[k] += p[k];
                ss[k] += p[k] * p[k];
            }
            pairs += 1.0;
        }
    double exact[2], se[2];
    for (int k = 0; k < 2; k++) {
        exact[k] = s[k] / pairs;
        se[k] = sqrt((ss[k] / pairs - exact[k] * exact[k]) / PAIRS);
    }

    sim_particles p = {NP, v, NULL, NULL};
    sim_scene scene = steady_scene(PAIRS);
    const gp_steady st = gp_spec(PAIRS);
    double engine[GP_STEADY_SCALARS + BINS] = {0}, helper[GP_STEADY_SCALARS + BINS] = {0};
    gsl_rng *rng = sim_rng_alloc();
    assert_non_null(rng);
    sim_rng_set_stream(rng, 20261127, 1);
    sim_steady_sample(&scene, &p, mass, rng, NULL, engine);
    gsl_rng_free(rng);
    gp_rng r;
    gp_rng_seed(&r, 20261127, 2);
    gp_steady_sample(&st, (const double (*)[3])v, NP, mass, &r, helper);
    for (int k = 0; k < 2; k++) {
        const double ze = (engine[SIM_STEADY_MU2 + k] - exact[k]) / se[k];
        const double zh = (helper[SIM_STEADY_MU2 + k] - exact[k]) / se[k];
        print_message("mu%d exact %.6f: engine z = %.2f, helper z = %.2f\n", 2 + 2 * k,
                      exact[k], ze, zh);
        assert_true(fabs(ze) <= 4.5);
        assert_true(fabs(zh) <= 4.5);
    }
    const double *both[2] = {engine, helper};
    for (int b = 0; b < 2; b++) {
        const double *x = both[b];
        const double mu2 = x[SIM_STEADY_MU2];
        assert_close(x[SIM_STEADY_MU4_WHITE], 5.0 * mu2, 1e-14, 0.0);
        assert_close(x[SIM_STEADY_MU4_GAUSSIAN], 5.0 * (1.0 + x[SIM_STEADY_A2]) * mu2, 1e-14,
                     0.0);
        assert_close(x[SIM_STEADY_MU4_NONGAUSSIAN],
                     2.0 * mu2 * x[SIM_STEADY_C3] / x[SIM_STEADY_C1], 1e-14, 0.0);
    }

    /* for the Python helpers: the array and the engine's values */
    FILE *f = fopen("examples-protocol-engine.txt", "w");
    assert_non_null(f);
    fprintf(f, "n %d\nmass %.17g\nalpha %.17g\nbins %d\nc_max %.17g\npairs %d\n", NP, mass,
            alpha, BINS, c_max, PAIRS);
    for (int i = 0; i < NP; i++)
        fprintf(f, "v %.17g %.17g %.17g\n", v[i][0], v[i][1], v[i][2]);
    double obs[SIM_OBS_BASE];
    sim_observe(&p, mass, obs);
    for (int k = 0; k < SIM_OBS_BASE; k++)
        fprintf(f, "obs %s %.17g\n", gp_obs_name[k], obs[k]);
    for (size_t k = 0; k < sim_steady_count(&scene); k++) {
        char name[32];
        fprintf(f, "steady %s %.17g\n", sim_steady_name(&scene, k, name, sizeof name), engine[k]);
    }
    sim_scene grid;   /* the output times of t_end = 7.3, outputs = 37 */
    sim_scene_defaults(&grid);
    grid.t_end = 7.3;
    grid.outputs = 37;
    for (size_t m = 0; m < grid.outputs; m++)
        fprintf(f, "time %.17g\n", sim_scene_output_time(&grid, m));
    assert_int_equal(fclose(f), 0);
}

/* The output times and the defaults, as the engine's. */
static void test_scene_defaults(void **state)
{
    (void)state;
    const char *path = "examples-protocol-scene.ini";
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("[scene]\nt_end = 7.3   ; a comment\noutputs = 37\n\n[collisions]\nkernel = "
          "hard-spheres\nmodel = ehs\nrestitution = 0.6\n\n[steady]\n", f);
    assert_int_equal(fclose(f), 0);
    static gp_scene s;
    gp_scene_load(&s, path);
    sim_scene e;
    sim_scene_defaults(&e);
    e.t_end = 7.3;
    e.outputs = 37;
    for (size_t m = 0; m < e.outputs; m++)
        assert_memory_equal(&(double){gp_output_time(&s, m)},
                            &(double){sim_scene_output_time(&e, m)}, sizeof(double));
    assert_close(gp_real(&s, "collisions.constant"), e.collisions.constant, 0.0, 0.0);
    assert_close(gp_real(&s, "collisions.exponent"), 1.0, 0.0, 0.0);
    assert_close(gp_real(&s, "collisions.beta"), 0.8, 1e-15, 0.0);   /* (1 + alpha)/2 */
    /* a default taken from other keys reads none of them */
    assert_false(gp_find(&s, "collisions.model")->read);
    assert_false(gp_find(&s, "collisions.restitution")->read);
    assert_close(gp_real(&s, "steady.c_max"), e.steady.c_max, 0.0, 0.0);
    assert_int_equal(gp_count(&s, "particles.n"), e.particles.n);
    assert_string_equal(gp_text(&s, "heating.type"), "white-noise");
    assert_true(gp_present(&s, "steady"));
    assert_false(gp_present(&s, "heating"));
    remove(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_observables),
        cmocka_unit_test(test_steady_without_pairs),
        cmocka_unit_test(test_steady_pairs),
        cmocka_unit_test(test_scene_defaults),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
