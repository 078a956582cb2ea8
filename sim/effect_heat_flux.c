/* The heat-flux force of paper D (docs/theory.md §7, issue 15), a flow of the
 * time-step scheme.
 *
 * A weak velocity-dependent force along x drives a heat flux in a homogeneous
 * state, whose linear response gives the modified thermal conductivity
 * kappa' = -q_x/(T eps).  After the collision stage of each step h (Lie
 * splitting, paper D §4), for every particle
 *     V <- V - (1/2) V (V . eps) h,    eps = (strength, 0, 0)     (D Eq. 4.1)
 * and then the peculiar velocities are taken about their new mean and
 * rescaled so that the temperature returns to T0 = particles.temperature
 * (D Eq. 4.2): this last projection carries the thermostat, the momentum
 * term and the constant part of the force, and keeps T, hence tau and the
 * step, constant.  (Paper D rescales to the initial kinetic energy K0; the
 * sampled K0 differs from 3 n T0/2 by O(n^{-1/2}), the scene's T0 is the
 * value the reduced units use.)  Unlike the keep-T Gaussian thermostat
 * (effect_heating.c), which rescales about the mean, the mean is removed:
 * the force adds a drift -(1/2) eps <V_x^2> h per step that the paper's
 * projection takes away.
 *
 * The force acts on peculiar velocities, so the gas must start at rest
 * (the constructor requires zero_momentum and velocity 0): every step
 * leaves the mean at 0 (to round-off) and collisions keep it there.
 *
 * Momentum and energy after a step are those of the projection, exact to
 * round-off (a test); the flow couples the particles (through the mean and
 * the temperature), so it has only `step`, and the jump scheme refuses it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "effect.h"
#include "run.h"
#include "steady.h"

typedef struct heat_flux_params {
    double strength;   /* eps, along x */
    double target;     /* T0/m */
} heat_flux_params;

static void heat_flux_step(const sim_flow *e, sim_run *run, double h)
{
    const heat_flux_params *p = e->params;
    const size_t n = run->p.n;
    const double k = 0.5 * p->strength * h;
    double sum[3] = {0, 0, 0}, sum2 = 0.0;
    for (size_t i = 0; i < n; i++) {   /* D Eq. 4.1 */
        double *v = run->p.v[i];
        const double f = 1.0 - k * v[0];
        v[0] *= f;
        v[1] *= f;
        v[2] *= f;
        sum[0] += v[0];
        sum[1] += v[1];
        sum[2] += v[2];
        sum2 += v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    }
    const double V[3] = {sum[0] / (double)n, sum[1] / (double)n, sum[2] / (double)n};
    const double c2 = sum2 - (double)n * (V[0] * V[0] + V[1] * V[1] + V[2] * V[2]);
    if (!(c2 > 0.0))   /* every velocity equal: nothing to rescale */
        return;
    const double s = sqrt(3.0 * (double)n * p->target / c2);
    for (size_t i = 0; i < n; i++) {   /* D Eq. 4.2 */
        double *v = run->p.v[i];
        v[0] = s * (v[0] - V[0]);
        v[1] = s * (v[1] - V[1]);
        v[2] = s * (v[2] - V[2]);
        sim_run_cover(run, v);
    }
}

static const sim_flow_type heat_flux_type = {
    .name = "heat-flux",
    .step = heat_flux_step,
};

sim_status sim_effect_heat_flux(const sim_scene *scene, sim_flow *effect, sim_error *err)
{
    const sim_maxwellian *m = &scene->particles.maxwellian;
    if (scene->scheme != SIM_SCHEME_TIMESTEP)
        return sim_error_set(err, SIM_EUNSUPPORTED, "scene.scheme",
                             "the heat-flux force couples the particles (through the mean "
                             "and the temperature) and needs scheme = timestep");
    if (scene->heating.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "heating.type",
                             "heat-flux carries its own thermostat (paper D Eq. 4.2); remove "
                             "[heating]");
    if (scene->particles.initial != SIM_INITIAL_MAXWELLIAN || !scene->particles.zero_momentum
        || m->velocity[0] != 0.0 || m->velocity[1] != 0.0 || m->velocity[2] != 0.0)
        return sim_error_set(err, SIM_EUNSUPPORTED, "particles.zero_momentum",
                             "the heat-flux force acts on peculiar velocities: start from a "
                             "Maxwellian at rest with zero_momentum = true");
    heat_flux_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    p->strength = scene->heat_flux.strength;
    p->target = m->temperature / m->mass;
    *effect = (sim_flow){.type = &heat_flux_type, .params = p};
    return SIM_OK;
}

/* ------------------------------------------------ steady quantities (steady.h) */

static const char *const heat_flux_names[SIM_HF_SCALARS] = {
    "qx", "kappa_prime", "b1", "b2", "b3", "b1_x", "b2_x", "b3_x", "b1_x_outer",
};

/* The generalised Laguerre polynomial L_k^{(a)}(x) for k = 1, 2, 3 into
 * L[0..2] (the three-term recurrence from L_0 = 1, L_1 = 1 + a - x). */
static inline void laguerre3(double a, double x, double L[3])
{
    L[0] = 1.0 + a - x;
    L[1] = ((3.0 + a - x) * L[0] - (1.0 + a)) / 2.0;
    L[2] = ((5.0 + a - x) * L[1] - (2.0 + a) * L[0]) / 3.0;
}

double sim_steady_kappa_per_moment(const sim_scene *scene)
{
    return -64.0 / (75.0 * sqrt(M_PI))
           / (sim_scene_mean_free_path(scene) * scene->heat_flux.strength);
}

/* Paper D's heat-flux quantities of one sample (steady.h), added to the
 * block hf. */
static void heat_flux_sample(const sim_scene *scene, const sim_particles *p, double mass,
                             const double V[3], double theta, const double *row, double *hf)
{
    static const double P[3] = {4.0 / 5.0, 16.0 / 35.0, 32.0 / 105.0};   /* D Eq. 3.10 */
    static const double Q[3] = {4.0 / 3.0, 16.0 / 15.0, 32.0 / 35.0};    /* D Eq. 3.12 */
    const size_t n = p->n, bins = scene->steady.bins;
    const double w = 1.0 / (double)n, v0 = sqrt(2.0 * theta), inv_v0 = 1.0 / v0;
    const double inv_eps = 1.0 / (sim_scene_mean_free_path(scene) * scene->heat_flux.strength);
    const double delta = bins > 0 ? scene->steady.c_max / (double)bins : 1.0;
    (void)row;
    double *g1 = hf + SIM_HF_SCALARS, *beta1 = g1 + bins;
    double q = 0.0, b[3] = {0, 0, 0}, bx[3] = {0, 0, 0}, outer = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double c[3] = {(p->v[i][0] - V[0]) * inv_v0, (p->v[i][1] - V[1]) * inv_v0,
                             (p->v[i][2] - V[2]) * inv_v0};
        const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2], cx2 = c[0] * c[0];
        double L[3], Lx[3];
        laguerre3(1.5, c2, L);
        laguerre3(0.5, cx2, Lx);
        q += c2 * c[0];
        for (int k = 0; k < 3; k++) {
            b[k] += c[0] * L[k];
            bx[k] += c[0] * Lx[k];
        }
        if (cx2 > 6.0)
            outer += c[0] * Lx[0];
        const double ax = fabs(c[0]);
        if (ax < scene->steady.c_max && bins > 0) {
            size_t k = (size_t)(ax / delta);
            if (k >= bins)   /* round-off at the last edge */
                k = bins - 1;
            g1[k] += (c[0] > 0.0 ? 1.0 : -1.0) * 0.5 * w / delta * inv_eps;
            /* per bin here; sim_steady_finish makes it cumulative */
            beta1[k] += Q[0] * c[0] * Lx[0] * w * inv_eps;
        }
    }
    hf[SIM_HF_QX] += 0.5 * mass * v0 * v0 * v0 * q * w;
    hf[SIM_HF_KAPPA_PRIME] += sim_steady_kappa_per_moment(scene) * q * w;
    for (int k = 0; k < 3; k++) {
        hf[SIM_HF_B1 + k] += P[k] * b[k] * w * inv_eps;
        hf[SIM_HF_B1_X + k] += Q[k] * bx[k] * w * inv_eps;
    }
    hf[SIM_HF_B1_X_OUTER] += Q[0] * outer * w * inv_eps;
}

static size_t heat_flux_steady_count(const sim_scene *scene)
{
    return scene->heat_flux.present ? SIM_HF_SCALARS + 2 * scene->steady.bins : 0;
}

static void heat_flux_steady_name(const sim_scene *scene, size_t k, char *buf, size_t len)
{
    const size_t bins = scene->steady.bins;
    if (k < SIM_HF_SCALARS)
        snprintf(buf, len, "%s", heat_flux_names[k]);
    else if (k < SIM_HF_SCALARS + bins)
        snprintf(buf, len, "g1_%zu", k - SIM_HF_SCALARS);
    else
        snprintf(buf, len, "beta1_%zu", k - SIM_HF_SCALARS - bins);
}

/* The beta1 bins are sampled per bin and made cumulative here (the prefix
 * sum is linear). */
static void heat_flux_steady_finish(const sim_scene *scene, double *hf)
{
    const size_t bins = scene->steady.bins;
    double *beta1 = hf + SIM_HF_SCALARS + bins;
    for (size_t k = 1; k < bins; k++)
        beta1[k] += beta1[k - 1];
}

const sim_steady_block sim_heat_flux_steady = {
    .count = heat_flux_steady_count,
    .scalars = SIM_HF_SCALARS,
    .name = heat_flux_steady_name,
    .sample = heat_flux_sample,
    .finish = heat_flux_steady_finish,
};
