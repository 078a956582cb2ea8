/* Uniform shear flow in the Lagrangian frame (paper E §IV B, SPEC §7;
 * issue 16), a flow of the time-step scheme.
 *
 * In the frame moving with the flow u = a y x̂, a homogeneous gas obeys
 * ∂f/∂t - a V_y ∂f/∂V_x = J[f, f]: between collisions the peculiar velocities
 * follow V_x(t + h) = V_x - a V_y h, V_y and V_z unchanged, which the step
 * applies exactly to every particle.  It keeps the mean velocity at 0 when it
 * starts there and heats the gas at the rate -(2a/3n) Pxy (viscous heating).
 *
 * The Lees-Edwards slab (boundary = lees-edwards) is sim/slab.c; the jump
 * scheme is refused here, naming the key.
 */
#include <stdlib.h>

#include "effect.h"
#include "run.h"

typedef struct shear_params {
    double rate;   /* a */
} shear_params;

static void shear_step(const sim_effect *e, sim_run *run, double h)
{
    const shear_params *p = e->params;
    const double ah = p->rate * h;
    const size_t n = run->p.n;
    for (size_t i = 0; i < n; i++) {
        double *v = run->p.v[i];
        v[0] -= ah * v[1];
        sim_run_cover(run, v);
    }
}

static const sim_effect_type shear_type = {
    .name = "shear",
    .step = shear_step,
};

sim_status sim_effect_shear(const sim_scene *scene, sim_effect *effect, sim_error *err)
{
    if (scene->scheme != SIM_SCHEME_TIMESTEP)
        return sim_error_set(err, SIM_EUNSUPPORTED, "scene.scheme",
                             "homogeneous shear needs scheme = timestep");
    shear_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    p->rate = scene->shear.rate;
    *effect = (sim_effect){.type = &shear_type, .params = p};
    return SIM_OK;
}
