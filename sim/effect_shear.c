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
 * The Lees-Edwards slab (boundary = lees-edwards) is the slab scheme, sim/scheme_slab.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "effect.h"
#include "observe.h"
#include "registry.h"
#include "run.h"
#include "steady.h"

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

void sim_shear_observe(const sim_scene *scene, const sim_particles *p, double mass,
                       const sim_counts *counts, size_t m, const double *prev, gsl_rng *rng,
                       double *row)
{
    sim_observe_shear(scene, p, mass, counts->collisions, m, prev, rng, row);
}

/* ------------------------------------------------ steady quantities (steady.h) */

static const char *const shear_names[SIM_SHEAR_SCALARS] = {
    "Pxy_reduced", "N1", "N2", "a_star", "v12_ratio", "R0", "R1", "R2", "R3",
};

/* The output row's observables the shear scalars average, in their order. */
static const sim_observable shear_row[SIM_SHEAR_SCALARS] = {
    SIM_OBS_PXY_REDUCED, SIM_OBS_N1, SIM_OBS_N2, SIM_OBS_A_STAR, SIM_OBS_V12_RATIO,
    SIM_OBS_R0, SIM_OBS_R1, SIM_OBS_R2, SIM_OBS_R3,
};

/* Paper E's shear-flow quantities of one sample (steady.h), added to the
 * block sh: the row's shear observables, and with bins the marginals gx, gy
 * (symmetrised, E Eq. 5.3) and F of C = (v - V)/v0. */
static void shear_sample(const sim_scene *scene, const sim_particles *p, double mass,
                         const double V[3], double theta, const double *row, double *sh)
{
    (void)mass;
    const double v0 = sqrt(2.0 * theta), inv_v0 = 1.0 / v0;
    for (int k = 0; k < SIM_SHEAR_SCALARS; k++)
        sh[k] += row[shear_row[k]];
    const size_t bins = scene->steady.bins, n = p->n;
    if (bins == 0)
        return;
    double *gx = sh + SIM_SHEAR_SCALARS, *gy = gx + 2 * bins, *F = gy + 2 * bins;
    const double width = scene->steady.c_max / (double)bins, inv_width = 1.0 / width;
    const double c_max = scene->steady.c_max;
    const double half = 0.5 / ((double)n * width);       /* (1/2) per particle per width */
    const double whole = 1.0 / ((double)n * width);
    for (size_t i = 0; i < n; i++) {
        const double cx = (p->v[i][0] - V[0]) * inv_v0, cy = (p->v[i][1] - V[1]) * inv_v0;
        const double cz = (p->v[i][2] - V[2]) * inv_v0;
        /* g_x^(+) at C_x for C_y > 0, g_x^(-)(-C_x) = g_x^(+) at -C_x for C_y < 0 */
        const double x = cy > 0.0 ? cx : -cx, y = cx > 0.0 ? cy : -cy;
        if (fabs(x) < c_max && cy != 0.0)
            gx[sim_steady_bin_of(x + c_max, inv_width, 2 * bins)] += half;
        if (fabs(y) < c_max && cx != 0.0)
            gy[sim_steady_bin_of(y + c_max, inv_width, 2 * bins)] += half;
        const double c = sqrt(cx * cx + cy * cy + cz * cz);
        if (c < c_max)
            F[sim_steady_bin_of(c, inv_width, bins)] += whole;
    }
}

static size_t shear_steady_count(const sim_scene *scene)
{
    return scene->shear.present ? SIM_SHEAR_SCALARS + 5 * scene->steady.bins : 0;
}

static void shear_steady_name(const sim_scene *scene, size_t k, char *buf, size_t len)
{
    const size_t bins = scene->steady.bins;
    if (k >= SIM_SHEAR_SCALARS + 4 * bins)
        snprintf(buf, len, "F_%zu", k - SIM_SHEAR_SCALARS - 4 * bins);
    else if (k >= SIM_SHEAR_SCALARS)
        snprintf(buf, len, "%s_%zu", k - SIM_SHEAR_SCALARS < 2 * bins ? "gx" : "gy",
                 (k - SIM_SHEAR_SCALARS) % (2 * bins));
    else
        snprintf(buf, len, "%s", shear_names[k]);
}

const sim_steady_block sim_shear_steady = {
    .count = shear_steady_count,
    .scalars = SIM_SHEAR_SCALARS,
    .name = shear_steady_name,
    .sample = shear_sample,
};
