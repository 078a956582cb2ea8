/* The Lees-Edwards slab (sim/slab.h, paper E §IV A, docs/theory.md §6.3, issue 17):
 * - the wrap: a particle leaving through the top re-enters at the bottom with
 *   v_x - aL, through the bottom at the top with v_x + aL, k crossings in one
 *   step give k aL; v_y, v_z unchanged;
 * - a gas started at rest with zero momentum keeps <ux> = 0 in the mean over
 *   the ensembles (the wrap is symmetric) and uy = uz = 0 exactly;
 * - at a = 0, without and with elastic collisions, the slab stays in
 *   equilibrium: flat profiles, the layer-peculiar T at its expectation,
 *   energy and momentum conserved to round-off;
 * - the observation centres each particle on its layer's velocity: a
 *   Maxwellian laid on u_x = a y has T + m a^2 dy^2/36, not T + m a^2 L^2/36;
 * - a candidate pair is uniform over the layer's ordered pairs (chi-square);
 * - the collision rate is the hard-sphere rate at the layer's density, and
 *   shear.candidates = paper raises it by E Sigma N_I^2 / E Sigma N_I (N_I - 1);
 *   at equilibrium it does not depend on the step;
 * - the slab's memory is counted in the workspace estimate. */
#include "test_sim_util.h"

#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_cdf.h>

#include "rng.h"
#include "run.h"
#include "slab.h"

/* Mean free path 1: 1/lambda0 = 4 sqrt(2) pi gamma C. */
#define HS_CONSTANT (1.0 / (4.0 * sqrt(2.0) * M_PI))

static sim_scene slab_scene(double a, double L, size_t M, size_t n, double alpha)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.scheme = SIM_SCHEME_TIMESTEP;
    s.dt = 0.01;
    s.t_end = 1.0;
    s.outputs = 11;
    s.seed = 1717;
    s.particles.n = n;
    s.particles.ensembles = 8;
    s.particles.maxwellian.temperature = 0.5;
    s.particles.zero_momentum = 1;
    s.collisions.present = 1;
    s.collisions.kernel = SIM_KERNEL_HARD_SPHERES;
    s.collisions.exponent = 1.0;
    s.collisions.constant = HS_CONSTANT;
    s.collisions.restitution = alpha;
    s.shear.present = 1;
    s.shear.rate = a;
    s.shear.boundary = SIM_SHEAR_LEES_EDWARDS;
    s.shear.length = L;
    s.shear.layers = M;
    return s;
}

/* No candidate is ever drawn: the candidate time 1/(kappa P_I 2 R_I) is ~1e300. */
static void collisionless(sim_scene *s)
{
    s->collisions.constant = 1e-300;
}

/* The standard error over the ensembles of observable k at output m (the ci
 * is SIM_LAMBDA_P of them). */
static double se_of(const sim_ensemble_result *r, size_t m, int k)
{
    return sim_result_ci(r, m, k) / SIM_LAMBDA_P;
}

/* |mean - want| <= z standard errors (printing both on failure). */
static void assert_z(const sim_ensemble_result *r, size_t m, int k, double want, double z,
                     const char *what)
{
    const double x = sim_result_mean(r, m, k), se = se_of(r, m, k);
    if (!(fabs(x - want) <= z * se))
        print_error("%s (output %zu, column %d): %.8g +- %.3g (se), expected %.8g (z = %.2f)\n",
                    what, m, k, x, se, want, (x - want) / se);
    assert_true(fabs(x - want) <= z * se);
}

/* ------------------------------------------------ a slab driven by hand */

typedef struct hand {
    sim_scene scene;   /* outlives params, which points at it */
    sim_event collisions;   /* ... as do the effects */
    sim_flow drag;
    size_t nflows;
    sim_slab_params *params;
    sim_slab *slab;
    sim_run run;
} hand;

static void hand_create(hand *h, const sim_scene *scene, uint64_t seed)
{
    sim_error err;
    memset(h, 0, sizeof *h);
    h->scene = *scene;
    assert_int_equal(sim_effect_collisions(&h->scene, &h->collisions, &err), SIM_OK);
    if (scene->collisions.model == SIM_MODEL_EHS && scene->collisions.restitution < 1.0) {
        assert_int_equal(sim_effect_ehs_drag(&h->scene, &h->drag, &err), SIM_OK);
        h->nflows = 1;
    }
    assert_int_equal(sim_slab_params_create(&h->scene, &h->collisions, 1, &h->drag, h->nflows,
                                            &h->params, &err), SIM_OK);
    assert_int_equal(sim_particles_alloc(&h->run.p, scene->particles.n, 0, &err), SIM_OK);
    h->run.rng = sim_rng_alloc();
    assert_non_null(h->run.rng);
    sim_rng_set_stream(h->run.rng, seed, 0);
    h->run.radius = INFINITY;
    assert_int_equal(sim_slab_create(h->params, &h->run.p, &h->slab, &err), SIM_OK);
    assert_non_null(h->run.p.y);
}

static void hand_free(hand *h)
{
    sim_slab_free(h->slab);
    sim_slab_params_free(h->params);
    free(h->collisions.params);
    free(h->drag.params);
    sim_particles_free(&h->run.p);
    gsl_rng_free(h->run.rng);
}

/* The index of the particle whose v_z is vz (the sort moves particles). */
static size_t find_by_vz(const sim_particles *p, double vz)
{
    for (size_t i = 0; i < p->n; i++)
        if (p->v[i][2] == vz)
            return i;
    fail_msg("no particle with v_z = %g", vz);
    return 0;
}

/* 1. The Lees-Edwards wrap (E Eq. 4.11), one step of a collisionless slab.
 * Proves: leaving through the top at y + v_y h > L/2 re-enters at
 * y + v_y h - L with v_x - aL, through the bottom at y + v_y h + L with
 * v_x + aL, v_y and v_z untouched, a particle inside moves by v_y h and keeps
 * its velocity; a long step with two crossings shifts v_x by 2aL and y by 2L.
 * Rejects: the wrong sign of the shift (v_x + aL at the top), a wrap that
 * counts one crossing whatever the distance (v_x - aL, y - L for k = 2), a
 * wrap that changes v_y, and any drawn candidate at C = 1e-300. */
static void test_wrap(void **state)
{
    (void)state;
    const double a = 4.0, L = 2.5, aL = a * L;
    sim_scene s = slab_scene(a, L, 5, 3, 1.0);
    collisionless(&s);
    hand h;
    hand_create(&h, &s, 1);
    sim_particles *p = &h.run.p;
    /* up through the top, down through the bottom, and one staying inside */
    const double y0[3] = {0.5 * L - 0.01, -0.5 * L + 0.01, 0.1};
    const double v0[3][3] = {{0.3, 1.0, -0.25}, {-0.7, -1.0, 0.125}, {0.2, 0.5, 0.75}};
    for (size_t i = 0; i < 3; i++) {
        p->y[i] = y0[i];
        memcpy(p->v[i], v0[i], sizeof v0[i]);
    }
    sim_slab_start(h.params, h.slab, &h.run);
    const double dt = 0.05;
    sim_slab_step(h.params, h.slab, &h.run, dt);
    const double want_y[3] = {y0[0] + v0[0][1] * dt - L, y0[1] + v0[1][1] * dt + L,
                              y0[2] + v0[2][1] * dt};
    const double want_vx[3] = {v0[0][0] - aL, v0[1][0] + aL, v0[2][0]};
    for (size_t c = 0; c < 3; c++) {
        const size_t i = find_by_vz(p, v0[c][2]);
        assert_close(p->y[i], want_y[c], 0.0, 1e-12);
        assert_close(p->v[i][0], want_vx[c], 0.0, 1e-12);
        assert_true(p->v[i][1] == v0[c][1]);
        assert_true(p->y[i] >= -0.5 * L && p->y[i] < 0.5 * L);
    }
    /* the sort put them in layer order: the one now at the bottom first */
    assert_true(p->y[0] < p->y[1] && p->y[1] < p->y[2]);
    assert_int_equal(h.run.counts.candidates, 0);
    assert_int_equal(h.run.counts.collisions, 0);

    /* a long step: k = 2 crossings up (6.1 -> 1.1) and down (-5.9 -> -0.9) */
    const double yk[2] = {0.1, 0.1};
    const double vk[2][3] = {{0.5, 3.0, -1.5}, {0.5, -3.0, 1.5}};
    for (size_t i = 0; i < 2; i++) {
        p->y[i] = yk[i];
        memcpy(p->v[i], vk[i], sizeof vk[i]);
    }
    p->y[2] = 0.0;   /* the third at rest in the middle */
    p->v[2][0] = p->v[2][1] = 0.0;
    p->v[2][2] = 0.0;
    sim_slab_start(h.params, h.slab, &h.run);
    const double H = 2.0;
    sim_slab_step(h.params, h.slab, &h.run, H);
    for (size_t c = 0; c < 2; c++) {
        const size_t i = find_by_vz(p, vk[c][2]);
        const double k = c == 0 ? 2.0 : -2.0;
        assert_close(p->y[i], yk[c] + vk[c][1] * H - k * L, 0.0, 1e-12);
        assert_close(p->v[i][0], vk[c][0] - k * aL, 0.0, 1e-12);
        assert_true(p->v[i][1] == vk[c][1]);
    }
    assert_int_equal(h.run.counts.candidates, 0);
    hand_free(&h);
}

/* 2. A slab sheared from rest with zero momentum (a = 4, L = 2.5, M = 10,
 * alpha = 0.9).  Proves: the ensemble mean of ux stays at 0 (within 4 standard
 * errors at every output: the dynamics is symmetric under y, v -> -y, -v),
 * and uy, uz stay 0 to round-off in every ensemble (the wrap changes only
 * v_x, collisions conserve momentum).  Rejects: a one-sided wrap (the shift
 * at one wall only drifts ux by about -aL per crossing per particle, ~ -1 by
 * t = 1), a wrap touching v_y, a start without the zero-momentum shift at
 * m = 0. */
static void test_zero_momentum_start(void **state)
{
    (void)state;
    sim_scene s = slab_scene(4.0, 2.5, 10, 400, 0.9);
    s.particles.ensembles = 40;
    sim_ensemble_result r;
    run(&s, &r);
    assert_true(r.counts.collisions > 0);
    assert_close(sim_result_mean(&r, 0, SIM_OBS_UX), 0.0, 0.0, 1e-14);
    for (size_t m = 1; m < r.outputs; m++) {
        assert_true(se_of(&r, m, SIM_OBS_UX) > 0.0);   /* the wrap did act */
        assert_z(&r, m, SIM_OBS_UX, 0.0, 4.0, "ux");
    }
    for (size_t m = 0; m < r.outputs; m++) {
        assert_close(sim_result_mean(&r, m, SIM_OBS_UY), 0.0, 0.0, 1e-13);
        assert_close(sim_result_mean(&r, m, SIM_OBS_UZ), 0.0, 0.0, 1e-13);
        assert_true(sqrt(sim_result_var(&r, m, SIM_OBS_UY)) < 1e-13);
    }
    sim_ensemble_result_free(&r);
}

/* The expectation of the layer-peculiar temperature of n exchangeable
 * velocities of temperature T0 (mean removed) in M occupied layers: each
 * layer's mean costs one degree of freedom of three, E T = T0 (1 - M/n). */
static double layer_T(double T0, size_t M, size_t n)
{
    return T0 * (1.0 - (double)M / (double)n);
}

/* 3, 4. A slab at a = 0 (M = 10, n = 2000, t = 2, 64 ensembles; the particles
 * cross the slab about once), collisionless or with elastic hard spheres.
 * Proves: it stays in equilibrium: n_I/n and T_I/T flat (z 4.5 of 1 in every
 * layer at every output), the layer-peculiar T at its expectation 0.5 (1 -
 * M/n) and a2 at 0 (z 4.5), energy (T_raw) and momentum conserved to
 * round-off in every ensemble; collisionless: no candidate is drawn; elastic:
 * collisions happen.  Rejects: a wrap or layer assignment that piles
 * particles up at a wall, a sort that loses or duplicates a particle (T_raw
 * changes), any change to a velocity without collisions, collisions that do
 * not conserve energy or momentum, collisions that favour some layers, a slab
 * without collisions. */
static void equilibrium_slab(int collide)
{
    const size_t M = 10, n = 2000;
    sim_scene s = slab_scene(0.0, 2.5, M, n, 1.0);
    if (!collide)
        collisionless(&s);
    s.particles.ensembles = 64;
    s.t_end = 2.0;
    s.outputs = 5;
    s.dt = 0.02;
    sim_ensemble_result r;
    run(&s, &r);
    if (collide)   /* about n t / sqrt(pi) = 2257 collisions per ensemble */
        assert_true((double)r.counts.collisions > 1000.0 * (double)s.particles.ensembles);
    else
        assert_int_equal(r.counts.candidates, 0);
    const double Traw0 = sim_result_mean(&r, 0, SIM_OBS_T_RAW);
    for (size_t m = 0; m < r.outputs; m++) {
        assert_close(sim_result_mean(&r, m, SIM_OBS_T_RAW), Traw0, 1e-12, 0.0);
        for (int k = 0; k < 3; k++)
            assert_close(sim_result_mean(&r, m, SIM_OBS_UX + k), 0.0, 0.0, 1e-13);
        for (size_t I = 0; I < M; I++) {
            assert_z(&r, m, SIM_OBS_PROFILE + SIM_PROFILE_N * (int)M + (int)I, 1.0, 4.5, "n_I/n");
            assert_z(&r, m, SIM_OBS_PROFILE + SIM_PROFILE_T * (int)M + (int)I, 1.0, 4.5, "T_I/T");
        }
        assert_z(&r, m, SIM_OBS_T, layer_T(0.5, M, n), 4.5, "T");
        assert_z(&r, m, SIM_OBS_A2, 0.0, 4.5, "a2");
    }
    sim_ensemble_result_free(&r);
}

static void test_collisionless_equilibrium(void **state)
{
    (void)state;
    equilibrium_slab(0);
}

static void test_elastic_equilibrium(void **state)
{
    (void)state;
    equilibrium_slab(1);
}

/* 5. The observation against the layers' velocities (E Eqs. 4.6-4.9): a
 * Maxwellian of temperature T laid on u_x = a y (y uniform, a = 4, L = 2.5),
 * observed by sim_slab_observe.  Within a layer of width dy = L/M the flow
 * spreads v_x uniformly over a dy, so the expected T is T + m a^2 dy^2/36
 * (and the layer means cost T M/n).  Proves: row T within 5 standard errors
 * of that, for M = 50 (dy = 0.05) and M = 5 (dy = 0.5, where the in-layer
 * term is ~100 standard errors); Pxy = 0 within 5 standard errors; the slope
 * of u_I,x is a (1 to 1e-2); ux_top = 1 - 3/M, ux_centre = 0 (E Fig. 3).
 * Rejects: T centred on the global mean (T + m a^2 L^2/36: > 100 standard
 * errors away), T centred on the exact flow a y (T: ~100 standard errors away
 * at M = 5), a slope off by the factor of a column mix-up. */
static void test_observe_linear_profile(void **state)
{
    (void)state;
    const double a = 4.0, L = 2.5, T0 = 0.5;
    const size_t n = 200000, layers[2] = {50, 5};
    for (int c = 0; c < 2; c++) {
        const size_t M = layers[c];
        sim_scene s = slab_scene(a, L, M, n, 1.0);
        hand h;
        hand_create(&h, &s, 5 + (uint64_t)c);
        sim_particles *p = &h.run.p;
        const double mass = sim_scene_grain_mass(&s), sd = sqrt(T0 / mass);
        for (size_t i = 0; i < n; i++) {
            p->y[i] = L * (sim_rng_uniform(h.run.rng) - 0.5);
            sim_rng_normal3(h.run.rng, p->v[i]);
            for (int k = 0; k < 3; k++)
                p->v[i][k] *= sd;
            p->v[i][0] += a * p->y[i];
        }
        sim_slab_start(h.params, h.slab, &h.run);
        double *row = calloc(sim_observe_row_length(&s), sizeof *row);
        assert_non_null(row);
        sim_slab_observe(h.params, h.slab, &h.run, 0, NULL, NULL, row);

        const double dy = L / (double)M, theta = T0 / mass;
        /* C_x = thermal + uniform on (-b, b), b = a dy/2: E C_x^2 = theta + b^2/3,
         * Var C_x^2 = 2 theta^2 + (4/3) theta b^2 + (4/45) b^4; C_y, C_z: 2 theta^2 */
        const double b = 0.5 * a * dy;
        const double var_x = 2.0 * theta * theta + 4.0 / 3.0 * theta * b * b
                             + 4.0 / 45.0 * b * b * b * b;
        const double se_T = mass / 3.0 * sqrt((var_x + 4.0 * theta * theta) / (double)n);
        const double want = T0 + mass * a * a * dy * dy / 36.0 - T0 * (double)M / (double)n;
        const double global = T0 + mass * a * a * L * L / 36.0;
        const double T = row[SIM_OBS_T];
        print_message("M = %zu: T = %.6f, expected %.6f +- %.2g (se), global %.4f, flow %.4f\n",
                      M, T, want, se_T, global, T0);
        assert_true(fabs(T - want) < 5.0 * se_T);
        assert_true(fabs(T - global) > 100.0 * se_T);
        if (M == 5)   /* the in-layer spread is resolved: not centred on a y itself */
            assert_true(fabs(T - T0) > 50.0 * se_T);
        /* Pxy = m <C_x C_y>, se = m sqrt((theta + b^2/3) theta / n) */
        const double se_P = mass * sqrt((theta + b * b / 3.0) * theta / (double)n);
        assert_true(fabs(row[SIM_OBS_PXY]) < 5.0 * se_P);
        assert_close(row[SIM_OBS_UX_SLOPE], 1.0, 0.0, 1e-2);
        assert_close(row[SIM_OBS_UX_TOP], 1.0 - 3.0 / (double)M, 0.0, 1e-2);
        assert_close(row[SIM_OBS_UX_CENTRE], 0.0, 0.0, 1e-2);
        assert_close(row[SIM_OBS_N_TOP], 1.0, 0.0, 0.05);
        assert_close(row[SIM_OBS_N_CENTRE], 1.0, 0.0, 0.05);
        /* the profile of u_x follows a y_I (per layer, 5 of its standard errors) */
        for (size_t I = 0; I < M; I++) {
            const double yI = ((double)I + 0.5) * dy - 0.5 * L;
            const double NI = row[SIM_OBS_PROFILE + SIM_PROFILE_N * M + I] * (double)n / (double)M;
            const double se_u = sqrt((theta + b * b / 3.0) / NI);
            assert_close(row[SIM_OBS_PROFILE + SIM_PROFILE_UX * M + I], a * yI, 0.0, 5.0 * se_u);
        }
        free(row);
        hand_free(&h);
    }
}

/* ------------------------------------------------------- pair selection */

/* The chi-square statistic of counts[k] against a uniform expectation. */
static double chi_square(const unsigned long *counts, size_t cells, double total)
{
    const double want = total / (double)cells;
    double chi2 = 0.0;
    for (size_t k = 0; k < cells; k++)
        chi2 += ((double)counts[k] - want) * ((double)counts[k] - want) / want;
    return chi2;
}

/* The off-by-one a picker could have: the partner skips i only when it lands
 * on it (j += j == i), so (i, i + 1) is drawn twice as often and (i, count - 1)
 * never (for i < count - 2). */
static void biased_pick(gsl_rng *rng, size_t lo, size_t count, size_t *i, size_t *j)
{
    *i = lo + (size_t)sim_rng_index(rng, count);
    *j = lo + (size_t)sim_rng_index(rng, count - 1);
    *j += *j == *i;
}

/* 6. sim_pick_pair_in draws every ordered pair i != j of the layer
 * [lo, lo + count) with probability 1/(count (count - 1)).  Proves: 1e6 draws
 * at lo = 7, count = 6 all lie in the layer with i != j, and the 30 ordered
 * pairs' counts pass a chi-square test at the 0.999 level (29 degrees of
 * freedom).  Rejects (the control, same statistic): the picker above, whose
 * partner is not uniform. */
static void test_pick_pair_uniform(void **state)
{
    (void)state;
    enum { LO = 7, COUNT = 6, CELLS = COUNT * (COUNT - 1) };
    const unsigned long draws = 1000000;
    const double limit = gsl_cdf_chisq_Qinv(0.001, CELLS - 1);
    gsl_rng *rng = sim_rng_alloc();
    assert_non_null(rng);
    sim_rng_set_stream(rng, 66, 0);
    for (int control = 0; control < 2; control++) {
        unsigned long counts[CELLS] = {0};
        for (unsigned long d = 0; d < draws; d++) {
            size_t i, j;
            if (control)
                biased_pick(rng, LO, COUNT, &i, &j);
            else
                sim_pick_pair_in(rng, LO, COUNT, &i, &j);
            if (i < LO || i >= LO + COUNT || j < LO || j >= LO + COUNT || i == j) {
                if (!control)
                    fail_msg("pair (%zu, %zu) outside [%d, %d) or not distinct", i, j, LO,
                             LO + COUNT);
                continue;
            }
            /* ordered pair (i, j), j != i: cell i (COUNT - 1) + (j < i ? j : j - 1) */
            const size_t a = i - LO, b = j - LO;
            counts[a * (COUNT - 1) + (b < a ? b : b - 1)]++;
        }
        const double chi2 = chi_square(counts, CELLS, (double)draws);
        print_message("%s picker: chi2 = %.1f (0.999 quantile %.1f)\n",
                      control ? "biased" : "slab", chi2, limit);
        if (control)
            assert_true(chi2 > limit);
        else
            assert_true(chi2 < limit);
    }
    gsl_rng_free(rng);
}

/* ------------------------------------------------------ collision rate */

/* Collisions per particle by time t in an equilibrium slab (a = 0, elastic)
 * of n particles in M layers at temperature T (m = 1, gamma = 1, C as above):
 * each unordered pair of a layer collides at 4 pi gamma C |g| M/n with
 * <|g|> = 4 sqrt(T/(pi m)) (4 pi C = 1/sqrt 2), and uniform independent
 * positions give E Sigma_I N_I (N_I - 1) = n (n - 1)/M, E Sigma_I N_I^2 =
 * n (n - 1)/M + n. */
static double collisions_per_particle(double t, size_t n, size_t M, double T, int paper)
{
    const double N = (double)n;
    const double pairs = N * (N - 1.0) / (double)M + (paper ? N : 0.0);   /* ordered */
    const double g = 4.0 * sqrt(T / M_PI);
    return t * 0.5 * pairs * (g / sqrt(2.0)) * (double)M / N / N;
}

/* An elastic equilibrium slab at a = 0 for the collision counts: n particles,
 * M layers, step dt, t_end t, `ensembles`, candidates counted as `pairs`. */
static void rate_run(size_t n, size_t M, double dt, double t, size_t ensembles,
                     sim_slab_pairs pairs, sim_ensemble_result *r)
{
    sim_scene s = slab_scene(0.0, 2.5, M, n, 1.0);
    s.particles.ensembles = ensembles;
    s.t_end = t;
    s.outputs = 3;
    s.dt = dt;
    s.shear.candidates = pairs;
    run(&s, r);
}

/* 7a. The candidate accounting with large layers (n = 2000, M = 5, N_I ~ 400).
 * Proves: the collisions per particle s(t) of an elastic slab at a = 0 follow
 * the hard-sphere rate at each layer's density, (n - 1)/n sqrt(2T/pi) t,
 * within 4 standard errors at every output, and s n summed over the ensembles
 * is the engine's collision count.  Rejects: a rate per ordered pair off by a
 * factor (kappa), a layer's density taken as n instead of n_I (rate / M), a
 * rate 10% off (told apart at t = 1). */
static void test_collision_rate(void **state)
{
    (void)state;
    const size_t n = 2000, M = 5;
    sim_ensemble_result r;
    rate_run(n, M, 0.02, 1.0, 16, SIM_SLAB_PAIRS_UNBIASED, &r);
    const size_t last = r.outputs - 1;
    assert_close(sim_result_mean(&r, last, SIM_OBS_S) * (double)n * (double)r.ensembles,
                 (double)r.counts.collisions, 1e-12, 0.0);
    for (size_t m = 1; m < r.outputs; m++) {
        const double want = collisions_per_particle(r.t[m], n, M, 0.5, 0);
        assert_z(&r, m, SIM_OBS_S, want, 4.0, "s (n = 2000, M = 5)");
        if (m == last)
            assert_true(fabs(sim_result_mean(&r, m, SIM_OBS_S) - 1.1 * want)
                        > 4.0 * se_of(&r, m, SIM_OBS_S));
    }
    sim_ensemble_result_free(&r);
}

/* 7b. Small layers (n = 200, M = 20, N_I ~ 10, 200 ensembles, t = 2), where
 * the pair count matters.  Proves: the unbiased count N_I (N_I - 1) gives the
 * hard-sphere rate, shear.candidates = paper (N_I^2) that rate times
 * E Sigma N_I^2 / E Sigma N_I (N_I - 1) = 1 + M/(n - 1) (+10%), each within 4
 * standard errors and more than 4 away from the other's expectation, and the
 * measured ratio of the two is 1 + M/(n - 1).  Rejects: the N_I^2 count used
 * for the default, or ignored for paper; any other bias of the candidate
 * count of order 1/N_I (e.g. a per-layer time counter whose carried-over
 * credit is spent when the layer's candidate time happens to be short). */
static void test_collision_rate_small_layers(void **state)
{
    (void)state;
    const size_t n = 200, M = 20;
    double got[2], se[2];
    for (int paper = 0; paper < 2; paper++) {
        sim_ensemble_result r;
        rate_run(n, M, 0.02, 2.0, 200, paper ? SIM_SLAB_PAIRS_PAPER : SIM_SLAB_PAIRS_UNBIASED,
                 &r);
        const size_t last = r.outputs - 1;
        const double want = collisions_per_particle(r.t[last], n, M, 0.5, paper);
        const double other = collisions_per_particle(r.t[last], n, M, 0.5, !paper);
        got[paper] = sim_result_mean(&r, last, SIM_OBS_S);
        se[paper] = se_of(&r, last, SIM_OBS_S);
        print_message("candidates = %s: s = %.5f +- %.5f (se), expected %.5f, other %.5f\n",
                      paper ? "paper" : "unbiased", got[paper], se[paper], want, other);
        sim_ensemble_result_free(&r);
        if (!(fabs(got[paper] - want) <= 4.0 * se[paper]))
            print_error("s (%s) = %.5f, expected %.5f (z = %.1f)\n",
                        paper ? "paper" : "unbiased", got[paper], want,
                        (got[paper] - want) / se[paper]);
        assert_true(fabs(got[paper] - want) <= 4.0 * se[paper]);
        assert_true(fabs(got[paper] - other) > 4.0 * se[paper]);
    }
    const double ratio = got[1] / got[0];
    const double se_ratio = ratio * hypot(se[0] / got[0], se[1] / got[1]);
    assert_close(ratio, 1.0 + (double)M / (double)(n - 1), 0.0, 4.0 * se_ratio);
}

/* 7c. The equilibrium collision rate does not depend on the step: at a = 0
 * every stage (streaming, sorting, collisions) keeps uniform independent
 * positions and the equilibrium velocities, so the expected collisions per
 * unit time are E Sigma_I kappa N_I (N_I - 1) <|g|> whatever h is.  Proves:
 * s(t = 2) at h = 0.5 and at h = 0.02 agree within 4 standard errors of their
 * difference (n = 200, M = 20, 200 ensembles each).  Needs no formula for
 * the rate.  Rejects: a candidate count per layer and step that is biased by
 * how the layer's population changes between steps (a time counter carried
 * over from step to step spends its credit preferentially at steps where
 * N_I (N_I - 1) R_I is large). */
static void test_collision_rate_step_independent(void **state)
{
    (void)state;
    const double steps[2] = {0.5, 0.02};
    double got[2], se[2];
    for (int c = 0; c < 2; c++) {
        sim_ensemble_result r;
        rate_run(200, 20, steps[c], 2.0, 200, SIM_SLAB_PAIRS_UNBIASED, &r);
        got[c] = sim_result_mean(&r, r.outputs - 1, SIM_OBS_S);
        se[c] = se_of(&r, r.outputs - 1, SIM_OBS_S);
        print_message("h = %.2f: s = %.5f +- %.5f (se)\n", steps[c], got[c], se[c]);
        sim_ensemble_result_free(&r);
    }
    assert_close(got[1], got[0], 0.0, 4.0 * hypot(se[0], se[1]));
}

/* ---------------------------------------------------------------- memory */

static size_t workspace_bytes(const sim_scene *s)
{
    sim_engine *e = NULL;
    sim_error err;
    assert_int_equal(sim_engine_create(s, &e, &err), SIM_OK);
    const size_t bytes = sim_engine_workspace_bytes(e);
    sim_engine_free(e);
    return bytes;
}

/* 8. The workspace estimate counts the slab.  Proves: per particle, the
 * homogeneous shear flow costs exactly its velocities
 * (sim_particles_bytes_per_particle(0): no positions), and the slab at least
 * the velocities, the positions and the counting sort's second velocities and
 * positions (24 + 8 + 24 + 8 bytes); at n = 1000 the slab's estimate exceeds the
 * homogeneous one by at least 8 n.  Also the slab engine's effects and row
 * length.  Rejects: a slab whose buffers are left out of the estimate (the
 * memory check of ensemble.h would then pass runs that cannot fit), positions
 * charged to homogeneous scenes. */
static void test_workspace_bytes(void **state)
{
    (void)state;
    const size_t n1 = 1000, n2 = 3000, M = 10;
    sim_scene slab = slab_scene(4.0, 2.5, M, n1, 0.9);
    sim_scene homogeneous = slab;
    homogeneous.shear.boundary = SIM_SHEAR_HOMOGENEOUS;
    const size_t slab1 = workspace_bytes(&slab), hom1 = workspace_bytes(&homogeneous);
    slab.particles.n = homogeneous.particles.n = n2;
    const size_t slab2 = workspace_bytes(&slab), hom2 = workspace_bytes(&homogeneous);
    const size_t dn = n2 - n1;
    assert_int_equal(hom2 - hom1, dn * sim_particles_bytes_per_particle(0));
    assert_true(slab2 - slab1 >= dn * (24 + 8 + 24 + 8));
    assert_true(slab1 >= hom1 + 8 * n1);

    sim_engine *e = NULL;
    sim_error err;
    assert_int_equal(sim_engine_create(&slab, &e, &err), SIM_OK);
    assert_string_equal(sim_engine_effects(e), "slab collisions");
    assert_int_equal(sim_engine_observables(e), SIM_OBS_PROFILE + SIM_PROFILES * M);
    sim_engine_free(e);
    slab.collisions.model = SIM_MODEL_EHS;   /* alpha = 0.9 < 1: the layers' drag */
    assert_int_equal(sim_engine_create(&slab, &e, &err), SIM_OK);
    assert_string_equal(sim_engine_effects(e), "slab collisions drag");
    sim_engine_free(e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_wrap),
        cmocka_unit_test(test_zero_momentum_start),
        cmocka_unit_test(test_collisionless_equilibrium),
        cmocka_unit_test(test_elastic_equilibrium),
        cmocka_unit_test(test_observe_linear_profile),
        cmocka_unit_test(test_pick_pair_uniform),
        cmocka_unit_test(test_collision_rate),
        cmocka_unit_test(test_collision_rate_small_layers),
        cmocka_unit_test(test_collision_rate_step_independent),
        cmocka_unit_test(test_workspace_bytes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
