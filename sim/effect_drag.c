/* The drag of frictional elastic hard spheres (EHS, paper E Eq. (4.22),
 * docs/theory.md §6.2; issue 16), a flow of the time-step scheme (and, beside the
 * homogeneous shear, of the jump scheme: sheared_drag_scale_after).
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

static void drag_step(const sim_flow *e, sim_run *run, double h)
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

/* The Lees-Edwards slab's layer (E Eq. 4.12): the drag about the layer's
 * velocity u_I at its temperature, zeta_I = zeta0(T_I) n_I/n. */
static void drag_step_layer(const sim_flow *e, double (*v)[3], size_t count, const double u[3],
                            double theta, double density, double h)
{
    const drag_params *p = e->params;
    const double f = exp(-0.5 * p->zeta_factor * sqrt(theta) * density * h);
    for (size_t i = 0; i < count; i++)
        for (int c = 0; c < 3; c++)
            v[i][c] = u[c] + f * (v[i][c] - u[c]);
}

static const sim_flow_type drag_type = {
    .name = "drag",
    .step = drag_step,
    .step_layer = drag_step_layer,
};

/* Paper E's EHS gas under the homogeneous shear (issue 18), in one of two
 * ways the engine chooses (engine.c, resolve_modes):
 *
 *  - eagerly, when the stages draw by the contact rule: the shear's step
 *    (effect_shear.c) and then the drag's, with T taken after the shear, in
 *    one pass over the particles instead of three (sheared_drag_step);
 *
 *  - lazily, when they accept by |g| (collisions.rule = relative-speed): the
 *    shear is applied to a particle when a stage draws it (advance, as
 *    effect_shear.c alone) and the drag, a scaling about the mean velocity
 *    with which collisions and the shear commute, is one global factor
 *    (its linear map, run->scale), so a step costs O(1) plus its collisions;
 *    the jump scheme keeps the same two, with the scale's exact map between
 *    candidates (scale_after).
 *
 * Either way T comes from running sums of v and v v^T of the velocities at
 * the step's time: the shear maps them by V_x <- V_x - a h V_y (sim_shear_sums)
 * and the drag by V <- u + f (V - u), each in O(1), and the collisions keep
 * them.  The engine recomputes them from the particles at every output time,
 * so their round-off stays that of a few steps. */

/* <|v - u|^2> = 3 T/m of the n velocities whose sums are s, u their mean. */
static double sums_spread(const sim_sums *s, size_t n)
{
    const double dn = (double)n;
    const double u[3] = {s->v[0] / dn, s->v[1] / dn, s->v[2] / dn};
    return (s->vv[0] + s->vv[1] + s->vv[2]) / dn - (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
}

/* The drag's factor e^{-zeta0 h/2} over a step of h for the velocities
 * u + scale (v - u), v those the sums s of n particles hold (zeta0 from their
 * T; 1 if every velocity is equal). */
static double drag_factor(const drag_params *p, const sim_sums *s, size_t n, double scale,
                          double h)
{
    const double theta = scale * scale * sums_spread(s, n) / 3.0;
    return theta > 0.0 ? exp(-0.5 * p->zeta_factor * sqrt(theta) * h) : 1.0;
}

static void sheared_drag_step(const sim_flow *e, sim_run *run, double h)
{
    const drag_params *p = e->params;
    sim_sums *s = &run->sums;
    const size_t n = run->p.n;
    const double ah = p->shear_rate * h, dn = (double)n;
    sim_shear_sums(s, ah);
    const double u[3] = {s->v[0] / dn, s->v[1] / dn, s->v[2] / dn};
    const double f = drag_factor(p, s, n, 1.0, h);
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

/* The lazy form: the shear of a stored velocity over dt (exact), its reach
 * |a| dt |V_y|, the sums' shear, and the drag's factor for the velocities
 * u + run->scale (v - u) at the end of a step of h whose shear the sums
 * already hold. */
static void sheared_drag_advance(const sim_flow *e, double v[3], double dt, gsl_rng *rng)
{
    (void)rng;
    const drag_params *p = e->params;
    sim_shear_velocity(v, p->shear_rate * dt);
}

static double sheared_drag_reach_vy(const sim_flow *e, double dt)
{
    const drag_params *p = e->params;
    return fabs(p->shear_rate) * dt;
}

static void sheared_drag_advance_sums(const sim_flow *e, sim_sums *s, double dt)
{
    const drag_params *p = e->params;
    sim_shear_sums(s, p->shear_rate * dt);
}

static double sheared_drag_factor(const sim_flow *e, const sim_run *run, double h)
{
    return drag_factor(e->params, &run->sums, run->p.n, run->scale, h);
}

/* The jump scheme's exact drag between collisions.  The true peculiar
 * velocities are scale (W - u), W the stored ones sheared to the time, so
 * T/m = scale^2 theta_W and d scale/dt = -(zeta_factor/2) scale^2 sqrt(theta_W),
 * that is d(1/scale)/dt = (zeta_factor/2) sqrt(theta_W(t)).  Between
 * collisions the shear makes theta_W(x) = c0 + c1 x + c2 x^2 after x
 * (V_x <- V_x - a x V_y in the sums, sim_shear_sums), so
 *   1/scale(dt) = 1/scale + (zeta_factor/2) ∫_0^dt sqrt(theta_W(x)) dx,
 * the integral by 3-point Gauss-Legendre on panels over which theta_W varies
 * by at most 1% (relative error below 1e-12; one panel between the
 * candidates of any but the smallest systems). */
#define DRAG_PANEL_VARIATION 0.01
#define DRAG_PANELS_MAX 4096
static double sheared_drag_scale_after(const sim_flow *e, const sim_run *run, double dt)
{
    const drag_params *p = e->params;
    const sim_sums *s = &run->sums;
    const double dn = (double)run->p.n, a = p->shear_rate;
    const double u[2] = {s->v[0] / dn, s->v[1] / dn};
    const double c0 = sums_spread(s, run->p.n) / 3.0;
    const double c1 = -2.0 * a * (s->vv[3] / dn - u[0] * u[1]) / 3.0;
    const double c2 = a * a * (s->vv[1] / dn - u[1] * u[1]) / 3.0;
    if (!(c0 > 0.0) || !(dt > 0.0))
        return run->scale;   /* every velocity equal: no drag */
    const double variation = (fabs(c1) * dt + fabs(c2) * dt * dt) / c0;
    const double panels = fmin(ceil(variation / DRAG_PANEL_VARIATION), DRAG_PANELS_MAX);
    const size_t m = panels >= 1.0 ? (size_t)panels : 1;
    const double w = dt / (double)m, g = sqrt(0.6);   /* nodes 0, +-sqrt(3/5) */
    double integral = 0.0;
    for (size_t k = 0; k < m; k++) {
        const double mid = ((double)k + 0.5) * w;
        double sum = 0.0;
        for (int j = -1; j <= 1; j++) {
            const double x = mid + 0.5 * w * g * (double)j;
            const double theta = c0 + x * (c1 + x * c2);
            sum += (j == 0 ? 8.0 : 5.0) * sqrt(theta > 0.0 ? theta : 0.0);
        }
        integral += sum * w / 18.0;
    }
    return 1.0 / (1.0 / run->scale + 0.5 * p->zeta_factor * integral);
}

static const sim_linear_map sheared_drag_map = {
    .factor = sheared_drag_factor,
    .centred = 1,
    .reads_sums = 1,
    .advance_sums = sheared_drag_advance_sums,
    .scale_after = sheared_drag_scale_after,
};

static const sim_flow_type sheared_drag_type = {
    .name = "shear+drag",
    .step = sheared_drag_step,
    .step_reads_sums = 1,
    .advance = sheared_drag_advance,
    .reach = sim_reach_none,
    .reach_vy = sheared_drag_reach_vy,
    .linear = &sheared_drag_map,
};

static sim_status drag_create(const sim_scene *scene, sim_flow *effect, sim_error *err);

/* In either scheme: the jump scheme runs it exactly (scale_after). */
sim_status sim_effect_sheared_ehs_drag(const sim_scene *scene, sim_flow *effect,
                                       sim_error *err)
{
    sim_status status = drag_create(scene, effect, err);
    if (status == SIM_OK) {
        ((drag_params *)effect->params)->shear_rate = scene->shear.rate;
        effect->type = &sheared_drag_type;
    }
    return status;
}

/* Alone (no shear) only in the time-step scheme. */
sim_status sim_effect_ehs_drag(const sim_scene *scene, sim_flow *effect, sim_error *err)
{
    if (scene->scheme != SIM_SCHEME_TIMESTEP)
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions.model",
                             "ehs (its drag depends on the temperature) needs scheme = timestep, "
                             "or [shear] alone beside it");
    return drag_create(scene, effect, err);
}

static sim_status drag_create(const sim_scene *scene, sim_flow *effect, sim_error *err)
{
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
    *effect = (sim_flow){.type = &drag_type, .params = p};
    return SIM_OK;
}
