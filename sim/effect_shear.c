/* Uniform shear flow in the Lagrangian frame (paper E §IV B, docs/theory.md §6.1;
 * issues 16 and 18).
 *
 * In the frame moving with the flow u = a y x̂, a homogeneous gas obeys
 * ∂f/∂t - a V_y ∂f/∂V_x = J[f, f]: between collisions the peculiar velocities
 * follow V_x(t + dt) = V_x - a V_y dt, V_y and V_z unchanged.  It keeps the
 * mean velocity at 0 when it starts there and heats the gas at the rate
 * -(2a/3n) Pxy (viscous heating).
 *
 * The map is exact over any dt and moves a velocity by |a| dt |V_y| exactly,
 * so when the shear is the only flow the engine applies it lazily, as white
 * noise (engine.c): to a particle only when an event draws it or at an output
 * time, with that deterministic reach in the majorant.  The jump scheme then
 * simulates the sheared gas without splitting error, and a step of the
 * time-step scheme costs O(1) plus its collisions (candidates accepted by |g|,
 * collisions.rule = relative-speed; beside the EHS drag too, which is then a
 * global factor, effect_drag.c; by the contact rule, or beside another flow,
 * the step shears every particle).
 *
 * The Lees-Edwards slab (boundary = lees-edwards) is sim/slab.c.
 */
#include <math.h>
#include <stdlib.h>

#include "effect.h"
#include "run.h"

typedef struct shear_params {
    double rate;   /* a */
} shear_params;

static void shear_advance(const sim_flow *e, double v[3], double dt, gsl_rng *rng)
{
    (void)rng;
    const shear_params *p = e->params;
    sim_shear_velocity(v, p->rate * dt);
}

/* vv = xx, yy, zz, xy, xz, yz */
void sim_shear_sums(sim_sums *s, double ah)
{
    s->v[0] -= ah * s->v[1];
    s->vv[0] += ah * (ah * s->vv[1] - 2.0 * s->vv[3]);
    s->vv[3] -= ah * s->vv[1];
    s->vv[4] -= ah * s->vv[5];
}

static void shear_step(const sim_flow *e, sim_run *run, double h)
{
    const shear_params *p = e->params;
    const double ah = p->rate * h;
    const size_t n = run->p.n;
    for (size_t i = 0; i < n; i++) {
        double *v = run->p.v[i];
        sim_shear_velocity(v, ah);
        sim_run_cover(run, v);
    }
}

double sim_reach_none(const sim_flow *e, double dt)
{
    (void)e;
    (void)dt;
    return 0.0;
}

static double shear_reach_vy(const sim_flow *e, double dt)
{
    const shear_params *p = e->params;
    return fabs(p->rate) * dt;
}

static const sim_flow_type shear_type = {
    .name = "shear",
    .advance = shear_advance,
    .step = shear_step,
    .reach = sim_reach_none,
    .reach_vy = shear_reach_vy,
};

sim_status sim_effect_shear(const sim_scene *scene, sim_flow *effect, sim_error *err)
{
    shear_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    p->rate = scene->shear.rate;
    *effect = (sim_flow){.type = &shear_type, .params = p};
    return SIM_OK;
}
