/* Paper E's homogeneous shear flow and the EHS drag (SPEC §7, issue 16):
 * - a collisionless gas sheared for time t: the step is exact, so in every
 *   ensemble Pxy(t) = Pxy(0) - a t Pyy(0), Pxx(t) = Pxx(0) - 2 a t Pxy(0) +
 *   (a t)^2 Pyy(0), Pyy, Pzz unchanged (to round-off);
 * - the EHS model at alpha = 1 is the elastic IHS gas (no drag, beta = 1):
 *   the same numbers;
 * - one EHS drag step takes T to T e^{-zeta0(T) h} and keeps the mean
 *   velocity; with alpha = 1 it changes nothing. */
#include "test_sim_util.h"

#include <string.h>

#include "effect.h"
#include "rng.h"
#include "run.h"

/* The mean velocity and the centred T/m of p. */
static void moments(const sim_particles *p, double u[3], double *theta)
{
    double s2 = 0.0;
    u[0] = u[1] = u[2] = 0.0;
    for (size_t i = 0; i < p->n; i++)
        for (int k = 0; k < 3; k++)
            u[k] += p->v[i][k] / (double)p->n;
    for (size_t i = 0; i < p->n; i++)
        for (int k = 0; k < 3; k++)
            s2 += (p->v[i][k] - u[k]) * (p->v[i][k] - u[k]);
    *theta = s2 / (3.0 * (double)p->n);
}

static sim_scene shear_scene(double a, int collisions)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.scheme = SIM_SCHEME_TIMESTEP;
    s.dt = 0.01;
    s.t_end = 1.0;
    s.outputs = 11;
    s.seed = 505;
    s.particles.n = 500;
    s.particles.ensembles = 4;
    s.particles.maxwellian.temperature = 0.5;
    s.particles.zero_momentum = 1;
    s.collisions.present = collisions;
    s.collisions.kernel = SIM_KERNEL_HARD_SPHERES;
    s.collisions.exponent = 1.0;
    s.collisions.constant = 1.0 / (4.0 * sqrt(2.0) * M_PI);
    s.collisions.restitution = 1.0;
    s.shear.present = 1;
    s.shear.rate = a;
    return s;
}

static void test_collisionless_shear(void **state)
{
    (void)state;
    const double a = 2.5;
    sim_scene s = shear_scene(a, 0);
    s.particles.ensembles = 1;   /* the identities hold per ensemble */
    sim_ensemble_result r;
    run(&s, &r);
    const double Pxx0 = sim_result_mean(&r, 0, SIM_OBS_PXX);
    const double Pyy0 = sim_result_mean(&r, 0, SIM_OBS_PYY);
    const double Pzz0 = sim_result_mean(&r, 0, SIM_OBS_PZZ);
    const double Pxy0 = sim_result_mean(&r, 0, SIM_OBS_PXY);
    for (size_t m = 1; m < r.outputs; m++) {
        const double at = a * r.t[m];
        assert_close(sim_result_mean(&r, m, SIM_OBS_PXY), Pxy0 - at * Pyy0, 1e-12, 1e-14);
        assert_close(sim_result_mean(&r, m, SIM_OBS_PXX),
                     Pxx0 - 2.0 * at * Pxy0 + at * at * Pyy0, 1e-12, 1e-14);
        assert_close(sim_result_mean(&r, m, SIM_OBS_PYY), Pyy0, 1e-13, 0.0);
        assert_close(sim_result_mean(&r, m, SIM_OBS_PZZ), Pzz0, 1e-13, 0.0);
    }
    /* the wrong sign of the shear would give Pxy0 + a t Pyy0 */
    const double last = sim_result_mean(&r, r.outputs - 1, SIM_OBS_PXY);
    assert_true(fabs(last - (Pxy0 + a * Pyy0)) > 0.5 * a * Pyy0);
    sim_ensemble_result_free(&r);
}

static void test_ehs_elastic_is_ihs(void **state)
{
    (void)state;
    sim_scene s = shear_scene(1.0, 1);
    sim_ensemble_result ihs, ehs;
    run(&s, &ihs);
    s.collisions.model = SIM_MODEL_EHS;
    run(&s, &ehs);
    assert_memory_equal(ihs.mean, ehs.mean, ihs.outputs * ihs.observables * sizeof(double));
    assert_int_equal(ihs.counts.collisions, ehs.counts.collisions);
    /* and alpha = 0.5 is not: collisions at 3/4 the rate, and the drag */
    s.collisions.restitution = 0.5;
    sim_ensemble_result half;
    run(&s, &half);
    assert_true(half.counts.collisions < 0.8 * (double)ihs.counts.collisions);
    sim_ensemble_result_free(&ihs);
    sim_ensemble_result_free(&ehs);
    sim_ensemble_result_free(&half);
}

/* One drag step (effect level): the peculiar velocities shrink by
 * e^{-zeta0 h/2} with zeta0 = (2/(3 sqrt(pi))) (1 - alpha^2) sqrt(2T/m)/lambda0
 * at the temperature before the step, so T -> T e^{-zeta0 h}; the mean velocity
 * stays; alpha = 1 leaves every velocity as it was. */
static void test_ehs_drag_step(void **state)
{
    (void)state;
    const double alphas[] = {0.5, 1.0};
    for (int c = 0; c < 2; c++) {
        sim_scene s = shear_scene(0.0, 1);
        s.collisions.model = SIM_MODEL_EHS;
        s.collisions.restitution = alphas[c];
        sim_run r;
        memset(&r, 0, sizeof r);
        sim_error err;
        assert_int_equal(sim_particles_alloc(&r.p, 300, 0, &err), SIM_OK);
        r.rng = sim_rng_alloc();
        r.radius = INFINITY;
        sim_rng_set_stream(r.rng, 9, 2);
        for (size_t i = 0; i < r.p.n; i++) {
            sim_rng_normal3(r.rng, r.p.v[i]);
            r.p.v[i][1] += 0.7;   /* a moving gas: the drag acts on peculiar velocities */
        }
        double u0[3], T0;
        moments(&r.p, u0, &T0);
        sim_effect e;
        assert_int_equal(sim_effect_ehs_drag(&s, &e, &err), SIM_OK);
        const double h = 0.05;
        e.type->step(&e, &r, h);
        double u1[3], T1;
        moments(&r.p, u1, &T1);
        /* lambda0 = 1 (C = 1/(4 sqrt(2) pi)), m = 1 */
        const double zeta0 = 2.0 / (3.0 * sqrt(M_PI)) * (1.0 - alphas[c] * alphas[c])
                             * sqrt(2.0 * T0);
        assert_close(T1, T0 * exp(-zeta0 * h), 1e-12, 0.0);
        for (int k = 0; k < 3; k++)
            assert_close(u1[k], u0[k], 0.0, 1e-14);
        if (alphas[c] == 1.0)
            assert_close(T1, T0, 1e-15, 0.0);
        else   /* the cooling is large enough for the test above to tell it apart */
            assert_true(fabs(T0 * exp(-zeta0 * h) - T0) > 1e-3 * T0);
        free(e.params);
        sim_particles_free(&r.p);
        gsl_rng_free(r.rng);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_collisionless_shear),
        cmocka_unit_test(test_ehs_elastic_is_ihs),
        cmocka_unit_test(test_ehs_drag_step),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
