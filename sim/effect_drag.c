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
    double shear_rate;    /* a, for the sheared drag (below) */
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

/* Paper E's EHS gas under the homogeneous shear: the shear's step
 * (effect_shear.c) and then the drag's, with T taken after the shear, in one
 * pass over the particles instead of three (issue 18).  T comes from the
 * running sums of v and v v^T that the collision stages keep (run->sums):
 * the shear maps them by V_x <- V_x - a h V_y and the drag by V <- u + f (V -
 * u), each in O(1).  The engine recomputes them from the particles at every
 * output time, so their round-off stays that of a few steps. */
static void sheared_drag_step(const sim_effect *e, sim_run *run, double h)
{
    const drag_params *p = e->params;
    sim_sums *s = &run->sums;
    const size_t n = run->p.n;
    const double ah = p->shear_rate * h, dn = (double)n;
    /* the sums after the shear: vv = xx, yy, zz, xy, xz, yz */
    s->v[0] -= ah * s->v[1];
    s->vv[0] += ah * (ah * s->vv[1] - 2.0 * s->vv[3]);
    s->vv[3] -= ah * s->vv[1];
    s->vv[4] -= ah * s->vv[5];
    const double u[3] = {s->v[0] / dn, s->v[1] / dn, s->v[2] / dn};
    const double theta = ((s->vv[0] + s->vv[1] + s->vv[2]) / dn
                          - (u[0] * u[0] + u[1] * u[1] + u[2] * u[2])) / 3.0;
    const double f = theta > 0.0 ? exp(-0.5 * p->zeta_factor * sqrt(theta) * h) : 1.0;
    /* the bound followed on local copies (the stores to v cannot move them) */
    const double c[3] = {run->centre[0], run->centre[1], run->centre[2]};
    double r2 = run->radius * run->radius;
    for (size_t i = 0; i < n; i++) {
        double *v = run->p.v[i];
        const double x = u[0] + f * (v[0] - ah * v[1] - u[0]);
        const double y = u[1] + f * (v[1] - u[1]), z = u[2] + f * (v[2] - u[2]);
        v[0] = x;
        v[1] = y;
        v[2] = z;
        const double d2 = (x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1])
                          + (z - c[2]) * (z - c[2]);
        r2 = d2 > r2 ? d2 : r2;
    }
    if (r2 > run->radius * run->radius) {   /* sim_run_cover's effect, once */
        run->radius = sqrt(r2);
        run->bound_grew = 1;
    }
    /* the drag keeps the mean: v v^T - n u u^T shrinks by f^2 */
    static const int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
    for (int k = 0; k < 6; k++) {
        const double mean = dn * u[row[k]] * u[col[k]];
        s->vv[k] = mean + f * f * (s->vv[k] - mean);
    }
}

static const sim_effect_type sheared_drag_type = {
    .name = "shear+drag",
    .step = sheared_drag_step,
    .step_reads_sums = 1,
};

sim_status sim_effect_sheared_ehs_drag(const sim_scene *scene, sim_effect *effect,
                                       sim_error *err)
{
    sim_status status = sim_effect_ehs_drag(scene, effect, err);
    if (status == SIM_OK) {
        ((drag_params *)effect->params)->shear_rate = scene->shear.rate;
        effect->type = &sheared_drag_type;
    }
    return status;
}

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
    p->shear_rate = 0.0;
    *effect = (sim_effect){.type = &drag_type, .params = p};
    return SIM_OK;
}
