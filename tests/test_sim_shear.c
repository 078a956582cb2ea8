/* Paper E's homogeneous shear flow and the EHS drag (docs/theory.md §6.1-§6.2, issue 16):
 * - a collisionless gas sheared for time t: the step is exact, so in every
 *   ensemble Pxy(t) = Pxy(0) - a t Pyy(0), Pxx(t) = Pxx(0) - 2 a t Pxy(0) +
 *   (a t)^2 Pyy(0), Pyy, Pzz unchanged (to round-off);
 * - the EHS model at alpha = 1 is the elastic IHS gas (no drag, beta = 1):
 *   the same numbers;
 * - one EHS drag step takes T to T e^{-zeta0(T) h} and keeps the mean
 *   velocity; with alpha = 1 it changes nothing;
 * - the shear observers (observe.h, steady.h) on an equilibrium gas: R_l = 1,
 *   <V12^3>/<V12^3>_0 = 1, the marginals gx, gy and F the Maxwellian's;
 *   the collision counter s and the clock s0 (with the EHS beta) agree;
 * - elastic hard spheres sheared from equilibrium heat up and build their
 *   shear stress as the BGK model says at short times (issue 16);
 * - the shear as a lazy flow (issue 18): the jump scheme follows the exact
 *   moment equations of sheared Maxwell molecules, and sheared hard spheres
 *   come out the same by the jump scheme, by the time-step scheme with the
 *   lazy shear and by the one that shears every particle each step;
 * - the EHS drag as one global factor beside the lazy shear (issue 18) gives
 *   what the step that shears and drags every particle gives: to round-off
 *   without collisions, within the statistical error with them. */
#include "test_sim_util.h"

#include <string.h>

#include "bgk.h"
#include "effect.h"
#include "rng.h"
#include "run.h"
#include "steady.h"

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
        sim_flow e;
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

/* The sheared EHS drag (effect_drag.c): one step of the fused flow, with T
 * from running sums, moves every velocity as the shear's step and then the
 * drag's step do (to 1e-13), on a moving gas, and leaves the sums equal to
 * those recomputed from the particles (to 1e-12); the steps in the other
 * order, drag then shear, end more than 1e-6 away, so the comparison tells the
 * order apart. */
static void test_sheared_drag_step(void **state)
{
    (void)state;
    const size_t n = 300;
    sim_scene s = shear_scene(2.5, 1);
    s.collisions.model = SIM_MODEL_EHS;
    s.collisions.restitution = 0.5;
    sim_error err;
    sim_flow shear, drag, fused;
    assert_int_equal(sim_effect_shear(&s, &shear, &err), SIM_OK);
    assert_int_equal(sim_effect_ehs_drag(&s, &drag, &err), SIM_OK);
    assert_int_equal(sim_effect_sheared_ehs_drag(&s, &fused, &err), SIM_OK);
    assert_true(fused.type->step_reads_sums);
    sim_run r[3];
    for (int c = 0; c < 3; c++) {
        memset(&r[c], 0, sizeof r[c]);
        assert_int_equal(sim_particles_alloc(&r[c].p, n, 0, &err), SIM_OK);
        r[c].rng = sim_rng_alloc();
        r[c].radius = INFINITY;
        sim_rng_set_stream(r[c].rng, 11, 4);   /* the same velocities in the three */
        for (size_t i = 0; i < n; i++) {
            sim_rng_normal3(r[c].rng, r[c].p.v[i]);
            r[c].p.v[i][0] += 0.3;   /* a moving gas: the drag acts on peculiar velocities */
            r[c].p.v[i][1] -= 0.2;
        }
    }
    const double h = 0.05;
    sim_sums_compute(&r[0].p, &r[0].sums);
    fused.type->step(&fused, &r[0], h);
    shear.type->step(&shear, &r[1], h);
    drag.type->step(&drag, &r[1], h);
    drag.type->step(&drag, &r[2], h);
    shear.type->step(&shear, &r[2], h);
    double apart = 0.0, reversed = 0.0;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            apart = fmax(apart, fabs(r[0].p.v[i][k] - r[1].p.v[i][k]));
            reversed = fmax(reversed, fabs(r[2].p.v[i][k] - r[1].p.v[i][k]));
        }
    assert_true(apart <= 1e-13);
    assert_true(reversed > 1e-6);
    sim_sums fresh;
    sim_sums_compute(&r[0].p, &fresh);
    for (int k = 0; k < 3; k++)
        assert_close(r[0].sums.v[k], fresh.v[k], 0.0, 1e-12);
    for (int k = 0; k < 6; k++)
        assert_close(r[0].sums.vv[k], fresh.vv[k], 1e-12, 1e-12);
    free(shear.params);
    free(drag.params);
    free(fused.params);
    for (int c = 0; c < 3; c++) {
        sim_particles_free(&r[c].p);
        gsl_rng_free(r[c].rng);
    }
}

/* The engine fuses the shear and the EHS drag only when no other flow moves
 * the particles behind the running sums' back: with white-noise heating
 * beside them the three flows stay apart (a fused drag would read sums the
 * heating had made stale). */
static void test_sheared_drag_only_alone(void **state)
{
    (void)state;
    sim_scene s = shear_scene(2.5, 1);
    s.collisions.model = SIM_MODEL_EHS;
    s.collisions.restitution = 0.5;
    sim_engine *e = NULL;
    sim_error err;
    assert_int_equal(sim_engine_create(&s, &e, &err), SIM_OK);
    assert_string_equal(sim_engine_effects(e), "collisions shear+drag");
    sim_engine_free(e);
    s.heating.present = 1;
    s.heating.type = SIM_HEATING_WHITE_NOISE;
    s.heating.strength = 0.5;
    assert_int_equal(sim_engine_create(&s, &e, &err), SIM_OK);
    assert_string_equal(sim_engine_effects(e), "collisions shear drag heating");
    sim_engine_free(e);
}

/* |x - want| <= ci (3.2 standard errors over the ensembles), and the same
 * estimate tells `wrong` apart (|x - wrong| > ci). */
static void assert_within(double x, double ci, double want, double wrong, const char *what)
{
    if (!(fabs(x - want) <= ci) || !(fabs(x - wrong) > ci))
        print_error("%s: %.6g +- %.3g, expected %.6g (and not %.6g)\n", what, x, ci, want,
                    wrong);
    assert_true(fabs(x - want) <= ci);
    assert_true(fabs(x - wrong) > ci);
}

/* The Maxwellian's fraction of reduced speeds below x. */
static double maxwell_below(double x)
{
    return erf(x) - 2.0 * x * exp(-x * x) / sqrt(M_PI);
}

/* An equilibrium gas (no collisions, a = 0) observed by the shear observers:
 * E's shell ratios R_l and <V12^3>/<V12^3>_0 are 1, the symmetrised marginals
 * gx, gy are e^{-C^2}/(2 sqrt(pi)) and F(C) = 4 C^2 e^{-C^2}/sqrt(pi), each bin
 * against the exact bin average (E Eqs. 3.15-3.20 at local equilibrium). */
static void test_observers_at_equilibrium(void **state)
{
    (void)state;
    sim_scene s = shear_scene(0.0, 0);
    s.particles.n = 20000;
    s.particles.ensembles = 8;
    s.outputs = 3;
    s.t_end = 0.2;
    s.shear.pairs = 20000;
    s.steady.present = 1;
    s.steady.from = 0.0;
    s.steady.bins = 6;
    s.steady.c_max = 3.0;
    sim_ensemble_result r;
    run(&s, &r);
    const size_t last = r.outputs - 1;
    for (int l = 0; l < 4; l++) {
        char what[16];
        snprintf(what, sizeof what, "R%d", l);
        /* a ratio off by 10% (R3: by 100%, it counts 9 particles per system) */
        assert_within(sim_result_mean(&r, last, SIM_OBS_R0 + l),
                      sim_result_ci(&r, last, SIM_OBS_R0 + l), 1.0, l == 3 ? 2.0 : 1.1, what);
    }
    assert_within(sim_result_mean(&r, last, SIM_OBS_V12_RATIO),
                  sim_result_ci(&r, last, SIM_OBS_V12_RATIO), 1.0, 1.05, "v12_ratio");
    /* T/T0 of the sample: 1 to its spread, 0.3% (n = 2e4, N = 8); T/(2 T0) would be 0.5 */
    assert_close(sim_result_mean(&r, last, SIM_OBS_T_RATIO), 1.0, 0.005, 0.0);
    const double width = 0.5;   /* c_max/bins */
    for (size_t k = 0; k < 2 * s.steady.bins; k++) {
        char name[32];
        const double lo = sim_steady_marginal_centre(&s, k) - 0.5 * width, hi = lo + width;
        const double want = (erf(hi) - erf(lo)) / (4.0 * width);   /* ∫ e^{-c^2}/(2 sqrt pi) */
        for (int xy = 0; xy < 2; xy++) {
            snprintf(name, sizeof name, "%s_%zu", xy ? "gy" : "gx", k);
            const long q = sim_steady_find(&s, name);
            assert_true(q >= 0);
            /* a marginal not halved would be twice as large */
            assert_within(sim_result_steady_mean(&r, (size_t)q),
                          sim_result_steady_ci(&r, (size_t)q), want, 2.0 * want, name);
        }
    }
    for (size_t k = 0; k < s.steady.bins; k++) {
        char name[32];
        snprintf(name, sizeof name, "F_%zu", k);
        const long q = sim_steady_find(&s, name);
        assert_true(q >= 0);
        const double lo = sim_steady_bin_lower(&s, k), hi = sim_steady_bin_lower(&s, k + 1);
        const double want = (maxwell_below(hi) - maxwell_below(lo)) / width;
        /* F at the bin centre instead of its average is 1-5% off: told apart */
        const double c = 0.5 * (lo + hi);
        const double centre = 4.0 * c * c * exp(-c * c) / sqrt(M_PI);
        if (fabs(centre - want) > 0.02 * want)
            assert_within(sim_result_steady_mean(&r, (size_t)q),
                          sim_result_steady_ci(&r, (size_t)q), want, centre, name);
        else
            assert_true(fabs(sim_result_steady_mean(&r, (size_t)q) - want)
                        <= sim_result_steady_ci(&r, (size_t)q));
    }
    sim_ensemble_result_free(&r);
}

/* Elastic hard spheres at rest (a = 0): T stays at its sampled value, so E's
 * clock is s0(t) = beta t/(sqrt(pi) tau(T)) (to the ensembles' spread of
 * sqrt(T), 1e-5 relative), and the collisions per particle s(t) follow it (the
 * equilibrium hard-sphere collision rate per particle, each collision counted
 * once, is 1/(sqrt(pi) tau)).  With model = ehs and collisions.beta = 0.6
 * (alpha = 1: no drag) both carry the 0.6. */
static void test_collision_counter(void **state)
{
    (void)state;
    const double betas[] = {1.0, 0.6};
    for (int c = 0; c < 2; c++) {
        sim_scene s = shear_scene(0.0, 1);
        s.particles.n = 2000;
        s.particles.ensembles = 8;
        s.t_end = 2.0;
        s.outputs = 5;
        if (c == 1) {
            s.collisions.model = SIM_MODEL_EHS;
            s.collisions.beta = betas[c];
        }
        sim_ensemble_result r;
        run(&s, &r);
        for (size_t m = 0; m < r.outputs; m++) {
            /* lambda0 = 1, m = 1: 1/tau = sqrt(2T) */
            const double T = sim_result_mean(&r, m, SIM_OBS_T);
            const double s0 = betas[c] * r.t[m] * sqrt(2.0 * T) / sqrt(M_PI);
            assert_close(sim_result_mean(&r, m, SIM_OBS_S0), s0, 1e-4, 1e-15);
            if (m > 0)   /* a counter at the other beta would be 0.6 or 1/0.6 times it */
                assert_within(sim_result_mean(&r, m, SIM_OBS_S), sim_result_ci(&r, m, SIM_OBS_S),
                              s0, c == 0 ? 0.6 * s0 : s0 / 0.6, "s");
        }
        sim_ensemble_result_free(&r);
    }
}

/* Elastic hard spheres (IHS, alpha = 1) sheared at a tau0 = 2 from local
 * equilibrium: for t <= 0.5 tau0 the temperature and the shear stress follow
 * the BGK model (reference/bgk.h, nu' = 1/tau_eta), within the ensembles'
 * intervals; the collisionless values (T = T0 (1 + (a t)^2/3), Pxy = -a t T0)
 * are told apart at t = 0.5, so the collisions' share is resolved. */
static void test_elastic_short_times_follow_bgk(void **state)
{
    (void)state;
    const double a = 2.0;
    sim_scene s = shear_scene(a, 1);
    s.particles.n = 4000;
    s.particles.ensembles = 16;
    s.t_end = 0.5;
    s.outputs = 6;
    s.dt = 0.002;
    sim_ensemble_result r;
    run(&s, &r);
    ref_bgk_params p = ref_bgk_default_params();
    p.alpha = 1.0;
    p.gamma = s.collisions.rate;
    p.C = s.collisions.constant;
    p.T0 = 0.5;
    p.shear_rate = a;
    double T[6], Pxy[6];
    const ref_bgk_output out = {.T = T, .Pxy = Pxy};
    char msg[200];
    assert_int_equal(ref_bgk_solve(&p, r.t, r.outputs, NULL, &out, msg, sizeof msg), REF_OK);
    for (size_t m = 2; m < r.outputs; m++) {
        const double at = a * r.t[m];
        const double pxy = sim_result_mean(&r, m, SIM_OBS_PXY);
        const double dT = sim_result_mean(&r, m, SIM_OBS_T) - 0.5;
        const double free_dT = 0.5 * at * at / 3.0;
        print_message("t = %.1f: Pxy %.5f +- %.5f (BGK %.5f, free %.5f), T - T0 %.5f +- %.5f "
                      "(BGK %.5f, free %.5f)\n", r.t[m], pxy, sim_result_ci(&r, m, SIM_OBS_PXY),
                      Pxy[m], -at * 0.5, dT, sim_result_ci(&r, m, SIM_OBS_T), T[m] - 0.5, free_dT);
        assert_true(fabs(pxy - Pxy[m]) <= sim_result_ci(&r, m, SIM_OBS_PXY));
        assert_true(fabs(dT - (T[m] - 0.5)) <= sim_result_ci(&r, m, SIM_OBS_T));
        if (m == r.outputs - 1) {   /* the collisions' share is resolved */
            assert_true(fabs(pxy + at * 0.5) > sim_result_ci(&r, m, SIM_OBS_PXY));
            assert_true(fabs(dT - free_dT) > sim_result_ci(&r, m, SIM_OBS_T));
        }
    }
    sim_ensemble_result_free(&r);
}

/* The second moments P = (1/n) Σ V V^T (m = 1, mean velocity 0) of Maxwell
 * molecules under the shear obey closed equations: a collision turns g into
 * (1 - alpha)/2 g + (1 + alpha)/2 |g| e (collide.h) at the total rate
 * nu (n - 1), nu = 2 pi gamma C, and over the uniform pairs E[g g^T] =
 * 2 n P/(n - 1), so
 *   dP/dt = -a (X P + P X^T) + nu [((1 - alpha)^2/4 - 1) P + (1 + alpha)^2/4 (tr P/3) I],
 * X = x̂ ŷ^T.  Their right-hand side into d. */
static void sheared_maxwell_rhs(double P[3][3], double a, double nu, double alpha,
                                double d[3][3])
{
    const double c1 = 0.25 * (1.0 - alpha) * (1.0 - alpha) - 1.0;
    const double c2 = 0.25 * (1.0 + alpha) * (1.0 + alpha) * (P[0][0] + P[1][1] + P[2][2]) / 3.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d[i][j] = -a * ((i == 0 ? P[1][j] : 0.0) + (j == 0 ? P[i][1] : 0.0))
                      + nu * (c1 * P[i][j] + (i == j ? c2 : 0.0));
}

/* P from t0 to t1 by the classical Runge-Kutta method, 1e4 steps per unit time. */
static void sheared_maxwell_advance(double P[3][3], double a, double nu, double alpha, double t0,
                                    double t1)
{
    const int steps = (int)ceil((t1 - t0) * 1e4);
    const double h = (t1 - t0) / steps;
    for (int s = 0; s < steps; s++) {
        double k[4][3][3], y[3][3];
        sheared_maxwell_rhs(P, a, nu, alpha, k[0]);
        for (int q = 1; q < 4; q++) {
            const double f = q == 3 ? h : 0.5 * h;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    y[i][j] = P[i][j] + f * k[q - 1][i][j];
            sheared_maxwell_rhs(y, a, nu, alpha, k[q]);
        }
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                P[i][j] += h / 6.0
                           * (k[0][i][j] + 2.0 * k[1][i][j] + 2.0 * k[2][i][j] + k[3][i][j]);
    }
}

/* The jump scheme with the lazy shear on Maxwell molecules (alpha = 1 and
 * 0.5, a = 2, nu = 1/2): Pxx, Pyy, Pzz and Pxy within their half-widths (3.2
 * standard errors over 1000 ensembles) of the exact equations above, started
 * from each run's own P(0), at every output time to t = 2 (Pxx grows tenfold);
 * at t = 2 the same estimates tell apart the collisionless gas (nu = 0) and
 * the shear of the opposite sign. */
static void test_jump_shear_maxwell_moments(void **state)
{
    (void)state;
    const double alphas[] = {1.0, 0.5}, a = 2.0;
    static const int obs[4] = {SIM_OBS_PXX, SIM_OBS_PYY, SIM_OBS_PZZ, SIM_OBS_PXY};
    static const int at[4][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}};
    for (int c = 0; c < 2; c++) {
        sim_scene s = shear_scene(a, 1);
        s.scheme = SIM_SCHEME_JUMP;
        s.t_end = 2.0;
        s.particles.n = 200;
        s.particles.ensembles = 1000;
        s.particles.maxwellian.temperature = 1.0;
        s.collisions.kernel = SIM_KERNEL_MAXWELL;
        s.collisions.exponent = 0.0;
        s.collisions.constant = 1.0 / (4.0 * M_PI);
        s.collisions.restitution = alphas[c];
        sim_ensemble_result r;
        run(&s, &r);
        const double nu = 2.0 * M_PI * s.collisions.rate * s.collisions.constant;
        double P[3][3], free[3][3], reversed[3][3];
        const int row0[3][3] = {{SIM_OBS_PXX, SIM_OBS_PXY, SIM_OBS_PXZ},
                                {SIM_OBS_PXY, SIM_OBS_PYY, SIM_OBS_PYZ},
                                {SIM_OBS_PXZ, SIM_OBS_PYZ, SIM_OBS_PZZ}};
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                P[i][j] = free[i][j] = reversed[i][j] = sim_result_mean(&r, 0, row0[i][j]);
        for (size_t m = 1; m < r.outputs; m++) {
            sheared_maxwell_advance(P, a, nu, alphas[c], r.t[m - 1], r.t[m]);
            sheared_maxwell_advance(free, a, 0.0, alphas[c], r.t[m - 1], r.t[m]);
            sheared_maxwell_advance(reversed, -a, nu, alphas[c], r.t[m - 1], r.t[m]);
            for (int q = 0; q < 4; q++) {
                const double x = sim_result_mean(&r, m, obs[q]), ci = sim_result_ci(&r, m, obs[q]);
                const double want = P[at[q][0]][at[q][1]];
                if (!(fabs(x - want) <= ci))
                    print_error("alpha %g, t = %g, P component %d: %.6g +- %.3g, exact %.6g\n",
                                alphas[c], r.t[m], q, x, ci, want);
                assert_true(fabs(x - want) <= ci);
            }
        }
        const size_t last = r.outputs - 1;
        assert_within(sim_result_mean(&r, last, SIM_OBS_PXX), sim_result_ci(&r, last, SIM_OBS_PXX),
                      P[0][0], free[0][0], "Pxx against the collisionless gas");
        assert_within(sim_result_mean(&r, last, SIM_OBS_PXY), sim_result_ci(&r, last, SIM_OBS_PXY),
                      P[0][1], reversed[0][1], "Pxy against the reversed shear");
        assert_int_equal(r.counts.violations, 0);
        sim_ensemble_result_free(&r);
    }
}

/* The largest |a - b| over the quadrature sum of their half-widths, over the
 * observables obs[0 .. count) at the output times after the first. */
static double largest_z(const sim_ensemble_result *a, const sim_ensemble_result *b,
                        const int *obs, int count)
{
    double z = 0.0;
    for (size_t m = 1; m < a->outputs; m++)
        for (int q = 0; q < count; q++) {
            const double d = sim_result_mean(a, m, obs[q]) - sim_result_mean(b, m, obs[q]);
            z = fmax(z, fabs(d) / hypot(sim_result_ci(a, m, obs[q]), sim_result_ci(b, m, obs[q])));
        }
    return z;
}

/* Hard spheres of restitution alpha sheared at a = 2 from T0 = 1 to t = 2,
 * 400 ensembles of 200, h = 0.002 (the lazy-flow comparisons below). */
static sim_scene sheared_hard_spheres(double alpha)
{
    sim_scene s = shear_scene(2.0, 1);
    s.t_end = 2.0;
    s.particles.n = 200;
    s.particles.ensembles = 400;
    s.particles.maxwellian.temperature = 1.0;
    s.collisions.constant = 1.0 / (4.0 * M_PI);
    s.collisions.restitution = alpha;
    s.dt = 0.002;
    return s;
}

/* Inelastic hard spheres (alpha = 0.9) sheared at a = 2 from T0 = 1 to t = 2:
 * the jump scheme (exact, the shear lazy), the time-step scheme accepting by
 * |g| (the shear lazy: each particle sheared when a stage draws it) and the
 * time-step scheme by the contact rule (every particle sheared each step),
 * h = 0.002, agree in T, Pxx, Pyy and Pxy at every output time within the
 * quadrature sum of their half-widths; no majorant violation (the shear's
 * reach |a| dt |V_y| is a bound, not a probable one). */
static void test_lazy_shear_schemes_agree(void **state)
{
    (void)state;
    sim_scene s = sheared_hard_spheres(0.9);
    sim_ensemble_result r[3];
    s.scheme = SIM_SCHEME_JUMP;
    run(&s, &r[0]);
    s.scheme = SIM_SCHEME_TIMESTEP;
    s.collisions.rule = SIM_RULE_RELATIVE_SPEED;
    run(&s, &r[1]);
    s.collisions.rule = SIM_RULE_CONTACT;
    run(&s, &r[2]);
    static const int obs[4] = {SIM_OBS_T, SIM_OBS_PXX, SIM_OBS_PYY, SIM_OBS_PXY};
    const double zmax = fmax(largest_z(&r[1], &r[0], obs, 4), largest_z(&r[2], &r[0], obs, 4));
    /* a gas sheared 10% harder is told apart */
    s.shear.rate = 2.2;
    sim_ensemble_result harder;
    run(&s, &harder);
    const double zwrong = largest_z(&harder, &r[0], obs, 4);
    sim_ensemble_result_free(&harder);
    print_message("sheared hard spheres: time-step (|g|, lazy) and (contact) against the jump "
                  "scheme, largest |difference| / joint half-width %.2f (a 10%% harder shear: "
                  "%.2f)\n", zmax, zwrong);
    assert_true(zmax <= 1.0);
    assert_true(zwrong > 1.0);
    for (int k = 0; k < 3; k++) {
        assert_int_equal(r[k].counts.violations, 0);
        sim_ensemble_result_free(&r[k]);
    }
}

/* The sheared EHS gas with its collisions switched off (collisions.beta =
 * 1e-30: no candidate in the whole run), so that only the flows act: the
 * time-step scheme accepting by |g| (the shear lazy, the drag one global
 * factor from running sums at the stages' time: engine.c, current_sums) gives
 * what the one shearing and dragging every particle each step (the contact
 * rule) gives, at every output time to 1e-12 relative, by Lie and by Strang
 * splitting; a shear 1% harder or a restitution 1% higher (a weaker drag)
 * moves the same observables by more than 1e-5. */
static void test_lazy_drag_matches_eager(void **state)
{
    (void)state;
    static const int obs[6] = {SIM_OBS_T, SIM_OBS_PXX, SIM_OBS_PYY,
                               SIM_OBS_PZZ, SIM_OBS_PXY, SIM_OBS_PXZ};
    for (int strang = 0; strang < 2; strang++) {
        sim_scene s = shear_scene(2.5, 1);
        s.particles.n = 300;
        s.particles.ensembles = 2;
        s.collisions.model = SIM_MODEL_EHS;
        s.collisions.restitution = 0.5;
        s.collisions.beta = 1e-30;
        s.splitting = strang ? SIM_SPLIT_STRANG : SIM_SPLIT_EULER;
        sim_ensemble_result r[4];
        s.collisions.rule = SIM_RULE_RELATIVE_SPEED;
        run(&s, &r[0]);
        s.collisions.rule = SIM_RULE_CONTACT;
        run(&s, &r[1]);
        s.shear.rate = 2.525;
        run(&s, &r[2]);
        s.shear.rate = 2.5;
        s.collisions.restitution = 0.505;
        run(&s, &r[3]);
        double apart = 0.0, harder = INFINITY, weaker = INFINITY;
        for (int q = 0; q < 6; q++) {
            double d[3] = {0, 0, 0};
            for (size_t m = 1; m < r[0].outputs; m++)
                for (int c = 0; c < 3; c++) {
                    const double x = sim_result_mean(&r[c == 0 ? 0 : c + 1], m, obs[q]);
                    const double want = sim_result_mean(&r[1], m, obs[q]);
                    d[c] = fmax(d[c], fabs(x - want) / fabs(want));
                }
            apart = fmax(apart, d[0]);
            harder = fmin(harder, d[1]);
            weaker = fmin(weaker, d[2]);
        }
        print_message("collisionless sheared EHS drag (%s): lazy against eager %.2g relative; "
                      "a 1%% harder shear %.2g, a 1%% weaker drag %.2g\n",
                      strang ? "strang" : "euler", apart, harder, weaker);
        assert_true(apart <= 1e-12);
        assert_true(harder > 1e-5);
        assert_true(weaker > 1e-5);
        for (int c = 0; c < 4; c++) {
            assert_int_equal(r[c].counts.candidates, 0);
            sim_ensemble_result_free(&r[c]);
        }
    }
}

/* dP/dt of a collisionless sheared gas under the EHS drag (m = 1): the shear
 * V_x' = -a V_y and the drag V' = -(zeta0/2) V, zeta0 = zeta_f sqrt(T),
 * T = tr P/3; P = xx, yy, zz, xy, xz, yz. */
static void drag_moment_rates(const double P[6], double a, double zeta_f, double dP[6])
{
    const double T = (P[0] + P[1] + P[2]) / 3.0, zeta = zeta_f * sqrt(T);
    const double shear[6] = {-2.0 * a * P[3], 0.0, 0.0, -a * P[1], -a * P[5], 0.0};
    for (int k = 0; k < 6; k++)
        dP[k] = shear[k] - zeta * P[k];
}

/* The jump scheme on the sheared EHS gas with its collisions switched off
 * (collisions.beta = 1e-30): the drag's scale follows its exact map between
 * candidates (effect_drag.c, scale_after; here over whole output intervals),
 * so the ensemble's centred P follows the moment equations above, integrated
 * by RK4 (2e4 steps per unit time) from its own P(0), to 1e-9 relative at every
 * output time; the equations with a restitution of 0.505 (a drag 2% weaker)
 * end more than 1e-5 away. */
static void test_jump_drag_collisionless_exact(void **state)
{
    (void)state;
    static const int obs[6] = {SIM_OBS_PXX, SIM_OBS_PYY, SIM_OBS_PZZ,
                               SIM_OBS_PXY, SIM_OBS_PXZ, SIM_OBS_PYZ};
    const double a = 2.5;
    sim_scene s = shear_scene(a, 1);
    s.scheme = SIM_SCHEME_JUMP;
    s.particles.n = 300;
    s.particles.ensembles = 1;
    s.collisions.model = SIM_MODEL_EHS;
    s.collisions.restitution = 0.5;
    s.collisions.beta = 1e-30;
    sim_ensemble_result r;
    run(&s, &r);
    assert_int_equal(r.counts.collisions, 0);
    double apart = 0.0, weaker = INFINITY;
    for (int c = 0; c < 2; c++) {   /* the reference at alpha = 0.5, then at 0.505 */
        const double alpha = c == 0 ? 0.5 : 0.505;
        /* lambda0 = 1 (C = 1/(4 sqrt(2) pi)): zeta0 = (2/(3 sqrt(pi))) (1 - alpha^2) sqrt(2T) */
        const double zeta_f = 2.0 / (3.0 * sqrt(M_PI)) * (1.0 - alpha * alpha) * sqrt(2.0);
        double P[6];
        for (int k = 0; k < 6; k++)
            P[k] = sim_result_mean(&r, 0, obs[k]);
        const size_t steps = 2000;   /* per output interval of 0.1 */
        for (size_t m = 1; m < r.outputs; m++) {
            const double h = (r.t[m] - r.t[m - 1]) / (double)steps;
            for (size_t q = 0; q < steps; q++) {
                double k1[6], k2[6], k3[6], k4[6], x[6];
                drag_moment_rates(P, a, zeta_f, k1);
                for (int k = 0; k < 6; k++)
                    x[k] = P[k] + 0.5 * h * k1[k];
                drag_moment_rates(x, a, zeta_f, k2);
                for (int k = 0; k < 6; k++)
                    x[k] = P[k] + 0.5 * h * k2[k];
                drag_moment_rates(x, a, zeta_f, k3);
                for (int k = 0; k < 6; k++)
                    x[k] = P[k] + h * k3[k];
                drag_moment_rates(x, a, zeta_f, k4);
                for (int k = 0; k < 6; k++)
                    P[k] += h / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
            }
            const double scale = P[0] + P[1] + P[2];
            for (int k = 0; k < 6; k++) {
                const double d = fabs(sim_result_mean(&r, m, obs[k]) - P[k]) / scale;
                if (c == 0)
                    apart = fmax(apart, d);
                else if (k == 0)
                    weaker = fmin(weaker, m == 1 ? INFINITY : d);
            }
        }
    }
    sim_ensemble_result_free(&r);
    print_message("collisionless sheared EHS gas, jump scheme against the moment equations: "
                  "%.2g relative (the reference with a 2%% weaker drag: %.2g)\n", apart, weaker);
    assert_true(apart <= 1e-9);
    assert_true(weaker > 1e-5);
}

/* Paper E's EHS gas (alpha = 0.7) sheared at a = 2 from T0 = 1 to t = 2 with
 * its collisions: the time-step scheme accepting by |g| (the shear lazy, the
 * drag a global factor) and the one by the contact rule (every particle
 * sheared and dragged each step) agree in T, Pxx, Pyy and Pxy at every output
 * time within the quadrature sum of their half-widths; a restitution of 0.8
 * (a weaker drag, and collisions at 0.9 of the rate instead of 0.85) is told
 * apart; no majorant violation. */
static void test_lazy_drag_schemes_agree(void **state)
{
    (void)state;
    sim_scene s = sheared_hard_spheres(0.7);
    s.collisions.model = SIM_MODEL_EHS;
    sim_ensemble_result r[3], wrong;
    s.collisions.rule = SIM_RULE_RELATIVE_SPEED;
    run(&s, &r[0]);
    s.collisions.rule = SIM_RULE_CONTACT;
    run(&s, &r[1]);
    s.scheme = SIM_SCHEME_JUMP;
    run(&s, &r[2]);
    s.collisions.restitution = 0.8;
    run(&s, &wrong);
    static const int obs[4] = {SIM_OBS_T, SIM_OBS_PXX, SIM_OBS_PYY, SIM_OBS_PXY};
    const double z = fmax(largest_z(&r[0], &r[2], obs, 4), largest_z(&r[1], &r[2], obs, 4));
    const double zwrong = largest_z(&r[0], &wrong, obs, 4);
    print_message("sheared EHS gas: time-step (|g|, lazy shear, global drag) and (contact, "
                  "every particle each step) against the jump scheme (exact), largest "
                  "|difference| / joint half-width %.2f (alpha = 0.8 against 0.7: %.2f)\n", z,
                  zwrong);
    assert_true(z <= 1.0);
    assert_true(zwrong > 1.0);
    for (int k = 0; k < 3; k++) {
        assert_int_equal(r[k].counts.violations, 0);
        sim_ensemble_result_free(&r[k]);
    }
    sim_ensemble_result_free(&wrong);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_collisionless_shear),
        cmocka_unit_test(test_ehs_elastic_is_ihs),
        cmocka_unit_test(test_ehs_drag_step),
        cmocka_unit_test(test_sheared_drag_step),
        cmocka_unit_test(test_sheared_drag_only_alone),
        cmocka_unit_test(test_observers_at_equilibrium),
        cmocka_unit_test(test_collision_counter),
        cmocka_unit_test(test_elastic_short_times_follow_bgk),
        cmocka_unit_test(test_jump_shear_maxwell_moments),
        cmocka_unit_test(test_lazy_shear_schemes_agree),
        cmocka_unit_test(test_lazy_drag_matches_eager),
        cmocka_unit_test(test_jump_drag_collisionless_exact),
        cmocka_unit_test(test_lazy_drag_schemes_agree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
