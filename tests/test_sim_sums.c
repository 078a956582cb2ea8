/* Observation from running sums (scene.observation = conditional, issue 18;
 * sim/observe.h, sim_sums): the rows the engine writes from the sums the
 * events keep agree with a direct recomputation from the stored particles and
 * stamps at the last output time, for every engine shape that keeps them
 * (Maxwell molecules and VHS with and without white-noise heating, with a
 * background) and for hard spheres (no sums: a pass without draws); and
 * conditional observation draws no Gaussian numbers at output times: with
 * heating exactly 3 per particle brought by an event, 3n fewer per output
 * time than paper A's sampled observation.
 *
 * With GDSMC_SUMS_EVENTS set (tests/CMakeLists.txt: the `long` test
 * test_sim_sums_1e9), one run of 1e9 events: the sums must still agree with a
 * direct recomputation to 1e-12 relative (of the scale sqrt(n Σ|v|^2) for the
 * first moments). */
#include "test_sim_util.h"

#include <stdlib.h>
#include <string.h>

#include "engine.h"
#include "observe.h"

static sim_scene base_scene(size_t n, double t_end, size_t outputs)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.t_end = t_end;
    s.outputs = outputs;
    s.seed = 20261125;
    s.particles.n = n;
    s.particles.ensembles = 1;
    s.particles.maxwellian.velocity[1] = 0.3;   /* a bulk velocity: P is centred */
    s.collisions.present = 1;
    s.collisions.rate = 4.0;
    s.collisions.restitution = 0.5;
    s.observation = SIM_OBSERVE_CONDITIONAL;
    return s;
}

/* Run ensemble 0 of s; the last row's T .. Pyz against the sums recomputed
 * from the stored particles (relative to the row's scale: T for the second
 * moments, sqrt(T/m) for u); returns the largest relative difference and the
 * counts. */
static double last_row_error(const sim_scene *s, sim_counts *counts)
{
    sim_engine *e = NULL;
    sim_workspace *ws = NULL;
    sim_error err;
    sim_status st = sim_engine_create(s, &e, &err);
    if (st != SIM_OK)
        print_error("%s: %s\n", err.key, err.msg);
    assert_int_equal(st, SIM_OK);
    assert_int_equal(sim_workspace_create(e, &ws, &err), SIM_OK);
    const size_t L = sim_engine_observables(e), M = s->outputs;
    double *obs = malloc(M * L * sizeof *obs);
    assert_non_null(obs);
    memset(counts, 0, sizeof *counts);
    sim_engine_run(e, ws, 0, obs, counts);
    const double *row = obs + (M - 1) * L;
    sim_sums direct;
    sim_sums_compute(sim_workspace_particles(ws), &direct);
    double want[SIM_OBS_BASE];
    const double spread = s->heating.present ? 2.0 * s->heating.strength : 0.0;
    sim_observe_sums(&direct, s->particles.n, 1.0, s->t_end, spread, want);
    const double T = want[SIM_OBS_T];
    double worst = 0.0;
    for (int k = SIM_OBS_T; k <= SIM_OBS_PYZ; k++) {
        const double scale = k >= SIM_OBS_UX && k <= SIM_OBS_UZ ? sqrt(T) : T;
        worst = fmax(worst, fabs(row[k] - want[k]) / scale);
    }
    for (int k = SIM_OBS_QX; k <= SIM_OBS_A3; k++)
        assert_true(isnan(row[k]));   /* not observed from sums */
    free(obs);
    sim_workspace_free(ws);
    sim_engine_free(e);
    return worst;
}

static void test_sums_match_recomputation(void **state)
{
    (void)state;
    sim_counts c;
    /* Maxwell molecules, heated (fire_maxwell_flow_sums) */
    sim_scene s = base_scene(300, 4.0, 9);
    s.heating.present = 1;
    s.heating.strength = 1.0;
    assert_true(last_row_error(&s, &c) < 1e-12);
    assert_true(c.collisions > 2000);   /* 2 (n - 1) per unit time */
    /* VHS lambda = 1/2, heated: the bound from the unsynchronised system */
    s.collisions.kernel = SIM_KERNEL_VHS;
    s.collisions.exponent = 0.5;
    assert_true(last_row_error(&s, &c) < 1e-12);
    assert_int_equal(c.violations, 0);
    /* hard spheres, heated: no sums, the same expectation from a pass */
    s.collisions.kernel = SIM_KERNEL_HARD_SPHERES;
    s.collisions.exponent = 1.0;
    assert_true(last_row_error(&s, &c) < 1e-12);
    assert_int_equal(c.violations, 0);
    /* Maxwell molecules with paper B's background, no heating (the counted loop) */
    s = base_scene(300, 2.0, 5);
    s.background.present = 1;
    s.background.velocity[1] = 1.0;
    assert_true(last_row_error(&s, &c) < 1e-12);
    assert_true(c.background > 100);
}

/* Conditional observation draws the pending increments never: 3 normals per
 * particle for the initial state and 3 per particle an event brings forward
 * (2 per candidate, each with dt > 0); sampled observation 3n more per output
 * time after the first. */
static void test_conditional_draws_nothing_at_outputs(void **state)
{
    (void)state;
    const size_t n = 200, outputs = 41;
    sim_scene s = base_scene(n, 2.0, outputs);
    s.heating.present = 1;
    s.heating.strength = 1.0;
    sim_counts c;
    last_row_error(&s, &c);
    assert_int_equal(c.normals, 3 * n + 6 * c.candidates);
    s.observation = SIM_OBSERVE_SAMPLED;
    sim_engine *e = NULL;
    sim_workspace *ws = NULL;
    sim_error err;
    assert_int_equal(sim_engine_create(&s, &e, &err), SIM_OK);
    assert_int_equal(sim_workspace_create(e, &ws, &err), SIM_OK);
    double *obs = malloc(outputs * sim_engine_observables(e) * sizeof *obs);
    assert_non_null(obs);
    sim_counts sampled = {0};
    sim_engine_run(e, ws, 0, obs, &sampled);
    /* the output times bring every particle that an event has not just brought */
    assert_true(sampled.normals > 3 * n + 6 * sampled.candidates + 3 * n * (outputs - 1) * 9 / 10);
    free(obs);
    sim_workspace_free(ws);
    sim_engine_free(e);
}

/* 1e9 events (GDSMC_SUMS_EVENTS): Maxwell molecules without a flow, n = 1000,
 * two output times. */
static void test_sums_after_1e9_events(void **state)
{
    (void)state;
    const char *events = getenv("GDSMC_SUMS_EVENTS");
    if (events == NULL)
        skip();
    const double target = strtod(events, NULL);
    const size_t n = 1000;
    /* 2 pi gamma C (n - 1) candidates per unit time, C = 1/(4 pi), gamma = 4 */
    sim_scene s = base_scene(n, target / (2.0 * (double)(n - 1)), 2);
    s.collisions.restitution = 1.0;   /* elastic: T stays 1 over the run */
    sim_counts c;
    const double err = last_row_error(&s, &c);
    print_message("%llu events: largest relative difference %.3g\n",
                  (unsigned long long)c.candidates, err);
    assert_true((double)c.candidates > 0.9 * target);
    assert_true(err < 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sums_match_recomputation),
        cmocka_unit_test(test_conditional_draws_nothing_at_outputs),
        cmocka_unit_test(test_sums_after_1e9_events),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
