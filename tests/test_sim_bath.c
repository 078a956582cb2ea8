/* The Langevin bath (sim/effect_bath.c, docs/theory.md §4.5), the effect
 * added through the registry alone: the energy against its exact law
 * E T_raw(t) = T_b + (T0 - T_b) e^{-2 gamma t} (a gas at rest; elastic
 * collisions keep the energy and the momentum, so the law holds with them),
 * z-tested at every output time
 *  - in the jump scheme, where the bath is a lazy flow brought forward per
 *    particle, alone and beside elastic Maxwell collisions;
 *  - in the time-step scheme, whose step is the same exact law, with a step
 *    much longer than 1/gamma.
 * The wrong answer each must reject: friction at twice the rate (the law with
 * 4 gamma), which moves T by about 0.2 T0 at t = 1/(2 gamma). */
#include "test_sim_util.h"

#include <math.h>

#include "observe.h"

#define ZMAX 4.5   /* max over 9 output times of |mean - exact| / sigma (tolerances.h) */

static sim_scene bath_scene(sim_scheme scheme, int collisions)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.scheme = scheme;
    s.dt = 0.3;   /* time-step: h = 0.25 per output interval, gamma h = 0.5 */
    s.t_end = 2.0;
    s.outputs = 9;
    s.seed = 20261127;
    s.particles.n = 32;
    s.particles.ensembles = 2000;
    s.particles.maxwellian.temperature = 3.0;
    s.bath.present = 1;
    s.bath.friction = 2.0;
    s.bath.temperature = 0.5;
    if (collisions) {
        s.collisions.present = 1;
        s.collisions.rate = 2.0;   /* Maxwell molecules, elastic (the defaults) */
    }
    return s;
}

/* Largest |mean - law| / sigma of T_raw over the output times after 0, for
 * the law with friction `gamma`. */
static double max_z(const sim_scene *s, const sim_ensemble_result *r, double gamma)
{
    double z = 0.0;
    const double T0 = s->particles.maxwellian.temperature, Tb = s->bath.temperature;
    for (size_t m = 1; m < r->outputs; m++) {
        const double law = Tb + (T0 - Tb) * exp(-2.0 * gamma * r->t[m]);
        const double sigma = sim_result_ci(r, m, SIM_OBS_T_RAW) / SIM_LAMBDA_P;
        z = fmax(z, fabs(sim_result_mean(r, m, SIM_OBS_T_RAW) - law) / sigma);
    }
    return z;
}

static void check_law(sim_scheme scheme, int collisions)
{
    const sim_scene s = bath_scene(scheme, collisions);
    sim_ensemble_result r;
    run(&s, &r);
    const double z = max_z(&s, &r, s.bath.friction), wrong = max_z(&s, &r, 2.0 * s.bath.friction);
    print_message("%s%s: max z %.2f against the law, %.1f against twice the friction\n",
                  scheme == SIM_SCHEME_JUMP ? "jump" : "timestep",
                  collisions ? " with elastic collisions" : "", z, wrong);
    assert_true(z < ZMAX);
    assert_true(wrong > ZMAX);
    if (collisions)
        assert_true(r.counts.collisions > 0);
    sim_ensemble_result_free(&r);
}

static void test_jump_alone(void **state)
{
    (void)state;
    check_law(SIM_SCHEME_JUMP, 0);
}

static void test_jump_with_collisions(void **state)
{
    (void)state;
    check_law(SIM_SCHEME_JUMP, 1);
}

static void test_timestep_long_step(void **state)
{
    (void)state;
    check_law(SIM_SCHEME_TIMESTEP, 0);
}

static void test_timestep_with_collisions(void **state)
{
    (void)state;
    check_law(SIM_SCHEME_TIMESTEP, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_jump_alone),
        cmocka_unit_test(test_jump_with_collisions),
        cmocka_unit_test(test_timestep_long_step),
        cmocka_unit_test(test_timestep_with_collisions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
