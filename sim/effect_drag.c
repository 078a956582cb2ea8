/* The drag of frictional elastic hard spheres (EHS, paper E Eq. (4.22),
 * SPEC §7; issue 16), a flow of the time-step scheme.
 *
 * Paper E's EHS gas collides elastically at beta = (1 + alpha)/2 times the
 * inelastic rate (effect_collisions.c, model ehs) and loses energy to a drag
 * -m (zeta0/2) V on the peculiar velocities, with the local-equilibrium cooling
 * rate of inelastic hard spheres at the current temperature,
 *     zeta0 = (2/(3 sqrt(pi))) (1 - alpha^2)/tau,  tau = lambda0/sqrt(2T/m),
 *     lambda0 = 1/(sqrt(2) pi n sigma^2),  n sigma^2 = 4 gamma C,
 * so that its temperature follows the inelastic gas's.  Per step h:
 * V <- u + (V - u) e^{-zeta0 h/2}, u the mean velocity, T taken before the
 * step (exact for a fixed zeta0; zeta0 changes by O(zeta0 h) within a step).
 * With alpha = 1 there is no drag (a test).
 */
#include <math.h>
#include <stdlib.h>

#include "effect.h"
#include "run.h"

typedef struct drag_params {
    double zeta_factor;   /* zeta0 = zeta_factor sqrt(T/m) */
} drag_params;

static void drag_step(const sim_effect *e, sim_run *run, double h)
{
    const drag_params *p = e->params;
    const size_t n = run->p.n;
    double u[3] = {0, 0, 0}, s2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double *v = run->p.v[i];
        u[0] += v[0];
        u[1] += v[1];
        u[2] += v[2];
        s2 += v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    }
    for (int k = 0; k < 3; k++)
        u[k] /= (double)n;
    /* one pass: in the Lagrangian frame u is 0 to round-off, so <v^2> - u^2 loses
     * nothing to cancellation */
    const double theta = (s2 / (double)n - (u[0] * u[0] + u[1] * u[1] + u[2] * u[2])) / 3.0;
    if (!(theta > 0.0))
        return;
    const double f = exp(-0.5 * p->zeta_factor * sqrt(theta) * h);
    for (size_t i = 0; i < n; i++) {
        double *v = run->p.v[i];
        for (int k = 0; k < 3; k++)
            v[k] = u[k] + f * (v[k] - u[k]);
        sim_run_cover(run, v);
    }
}

static const sim_effect_type drag_type = {
    .name = "drag",
    .step = drag_step,
};

sim_status sim_effect_ehs_drag(const sim_scene *scene, sim_effect *effect, sim_error *err)
{
    if (scene->scheme != SIM_SCHEME_TIMESTEP)
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions.model",
                             "ehs (its drag depends on the temperature) needs scheme = timestep");
    if (scene->collisions.exponent != 1.0)
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions.model",
                             "ehs is a model of hard spheres (kernel = hard-spheres)");
    drag_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    const double alpha = scene->collisions.restitution;
    /* zeta0 = (2/(3 sqrt(pi))) (1 - alpha^2) sqrt(2 T/m)/lambda0 */
    p->zeta_factor = 2.0 / (3.0 * sqrt(M_PI)) * (1.0 - alpha * alpha) * sqrt(2.0)
                     / sim_scene_mean_free_path(scene);
    *effect = (sim_effect){.type = &drag_type, .params = p};
    return SIM_OK;
}
