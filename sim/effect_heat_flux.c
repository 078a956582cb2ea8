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
#include <stdlib.h>

#include "effect.h"
#include "run.h"

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
