/* Elastic collisions of the grains with a fixed Maxwellian background, the
 * J_EL part of paper B (docs/theory.md §5), in the same exact jump scheme as the binary
 * collisions (no time splitting: the engine draws which process fires).
 *
 * The background f^B = rho_B M(m_B, u_B, T_B) is never stored: a partner w is
 * drawn fresh for each event and the grain's new velocity follows
 * sim_collide_elastic (paper B Eq. (2)).  Kernels B1 = C1 (Maxwell) and
 * B1 = C1 |g| (hard spheres), omega uniform on S^2:
 *
 *  - Maxwell, Algorithm 1: E1 = 4 pi C1 rho_B for every grain, so the rate is
 *    pi1 = 4 pi C1 rho_B n; i uniform, w ~ f^B / rho_B, always accepted.
 *
 *  - Hard spheres, Algorithm 2: the majorant of the rate density of the pair
 *    (i, w) is, by the triangle inequality |v_i - w| <= a_max + |w - u_B|
 *    with a_max >= a_i = |v_i - u_B|,
 *        4 pi C1 (a_max + |w - u_B|) f^B(w),
 *    whose total is pi1 = C1 rho_B n (4 pi a_max + 8 sqrt(pi) b),
 *    b = sqrt(2 T_B / m_B), because ∫ |w - u_B| f^B = rho_B 2 b / sqrt(pi).
 *    It is sampled exactly in O(1): i uniform; w from the mixture of f^B / rho_B
 *    (weight a_max) and p2 ∝ |w - u_B| f^B (weight 2 b / sqrt(pi)); accept
 *    with |v_i - w| / (a_max + |w - u_B|).  This is the split of docs/theory.md §5.2
 *    (uniform choice for the b part, rejection against max a_i for the a part)
 *    with the two rejections folded into one test, and it has the same total
 *    as the paper's per-grain majorant Σ E1max(v_i) with a_i <= a_max.  We use
 *    it instead of Walker's alias table because the weights E1max(v_i) change
 *    at every event and an alias table costs O(n) to rebuild, while here the
 *    only state is a_max, which is the shared velocity bound of run.h centred
 *    at u_B (so the binary majorant U2max = a_max of Algorithm 2 is the same
 *    number).
 * The partner samplers are in background_partner.h.
 */
#include <math.h>
#include <stdlib.h>

#include "background_partner.h"
#include "collide.h"
#include "effect.h"
#include "rng.h"
#include "run.h"

typedef struct background_params {
    int hard_spheres;
    double mass_ratio;     /* alpha = m_B / (m + m_B) */
    double velocity[3];    /* u_B */
    double sigma;          /* sqrt(T_B / m_B): the partner's per-component spread */
    double b;              /* sqrt(2 T_B / m_B) */
    double mean_speed;     /* 2 b / sqrt(pi) = E |w - u_B| */
    double rate_maxwell;   /* Maxwell: 4 pi C1 rho_B n */
    double rate_a;         /* hard spheres: C1 rho_B n 4 pi (times a_max) */
    double rate_b;         /* hard spheres: C1 rho_B n 8 sqrt(pi) b */
} background_params;

typedef struct background_state {
    double radius;   /* the bound's R when the rate was last computed */
    double a_max;    /* R + |centre - u_B| >= max_i |v_i - u_B| */
    double offset;   /* |centre - u_B| (0 when the engine centres at u_B) */
    double rate;
} background_state;

static int background_needs_bound(const sim_event *e)
{
    return ((const background_params *)e->params)->hard_spheres;
}

static int background_centre(const sim_event *e, double centre[3])
{
    const background_params *p = e->params;
    if (!p->hard_spheres)
        return 0;
    for (int k = 0; k < 3; k++)
        centre[k] = p->velocity[k];
    return 1;
}

static inline double follow_bound(const background_params *p, background_state *s,
                                  const sim_run *run)
{
    if (run->radius != s->radius) {
        s->radius = run->radius;
        s->a_max = run->radius + s->offset;
        s->rate = p->rate_a * s->a_max + p->rate_b;
    }
    return s->rate;
}

static double background_rate(const sim_event *e, const sim_run *run, void *vstate)
{
    const background_params *p = e->params;
    return p->hard_spheres ? follow_bound(p, vstate, run) : p->rate_maxwell;
}

static double background_reset(const sim_event *e, sim_run *run, void *vstate, double horizon)
{
    (void)horizon;   /* the engine has added the flow's reach to the bound */
    const background_params *p = e->params;
    background_state *s = vstate;
    double d[3];
    for (int k = 0; k < 3; k++)
        d[k] = run->centre[k] - p->velocity[k];
    s->offset = sim_norm3(d);
    s->radius = -1.0;   /* force a recomputation */
    return background_rate(e, run, s);
}

/* One candidate background collision at time t; hard_spheres, lazy_flow and
 * bounded are compile-time constants in each instance below. */
static inline __attribute__((always_inline)) double
fire_candidate(const sim_event *e, sim_run *run, void *vstate, double t, const int hard_spheres,
               const int lazy_flow, const int bounded, const int sums)
{
    const background_params *p = e->params;
    background_state *s = vstate;
    gsl_rng *rng = run->rng;

    size_t i = (size_t)sim_rng_index(rng, run->p.n);
    double *v = run->p.v[i];
    if (sums)   /* out of the running sums until it is put back below */
        sim_sums_add(&run->sums, v, lazy_flow ? run->p.stamp[i] : 0.0, -1.0);
    if (lazy_flow)
        sim_run_bring(run, i, t);
    double w[3], gnorm;
    run->counts.candidates++;

    if (hard_spheres) {
        double a[3] = {v[0] - p->velocity[0], v[1] - p->velocity[1], v[2] - p->velocity[2]};
        if (sim_norm3(a) > s->a_max)
            run->counts.violations++;
        if (lazy_flow) {   /* the flow moved i since the bound last covered it */
            sim_run_cover(run, v);
            follow_bound(p, s, run);
        }
        double partner_speed;   /* |w - u_B| */
        if (sim_rng_uniform(rng) * (s->a_max + p->mean_speed) < s->a_max) {
            sim_background_partner(p->velocity, p->sigma, rng, w);
            double d[3] = {w[0] - p->velocity[0], w[1] - p->velocity[1], w[2] - p->velocity[2]};
            partner_speed = sim_norm3(d);
        } else {
            partner_speed = sim_background_flux_partner(p->velocity, p->b, rng, w);
        }
        double g[3] = {v[0] - w[0], v[1] - w[1], v[2] - w[2]};
        gnorm = sim_norm3(g);
        if (sim_rng_uniform(rng) * (s->a_max + partner_speed) >= gnorm) {
            if (sums)
                sim_sums_add(&run->sums, v, lazy_flow ? run->p.stamp[i] : 0.0, 1.0);
            return s->rate;   /* fictitious */
        }
    } else {
        sim_background_partner(p->velocity, p->sigma, rng, w);
        double g[3] = {v[0] - w[0], v[1] - w[1], v[2] - w[2]};
        gnorm = sim_norm3(g);
    }

    double unit[3];
    sim_rng_unit_sphere(rng, unit);
    sim_collide_elastic(v, w, p->mass_ratio, gnorm, unit);
    run->counts.background++;
    if (sums)
        sim_sums_add(&run->sums, v, lazy_flow ? run->p.stamp[i] : 0.0, 1.0);
    if (bounded)
        sim_run_cover(run, v);
    return hard_spheres ? follow_bound(p, s, run) : p->rate_maxwell;
}

#define FIRE_INSTANCE(name, hard_spheres, lazy, bounded, sums)                               \
    static double name(const sim_event *e, sim_run *run, void *state, double t)           \
    {                                                                                        \
        return fire_candidate(e, run, state, t, hard_spheres, lazy, bounded, sums);          \
    }
FIRE_INSTANCE(fire_maxwell, 0, 0, 0, 0)
FIRE_INSTANCE(fire_maxwell_flow, 0, 1, 0, 0)
FIRE_INSTANCE(fire_maxwell_bounded, 0, 0, 1, 0)
FIRE_INSTANCE(fire_maxwell_flow_bounded, 0, 1, 1, 0)
FIRE_INSTANCE(fire_hard_spheres, 1, 0, 1, 0)
FIRE_INSTANCE(fire_hard_spheres_flow, 1, 1, 1, 0)
/* keeping the running sums (observation = conditional) */
FIRE_INSTANCE(fire_maxwell_sums, 0, 0, 0, 1)
FIRE_INSTANCE(fire_maxwell_flow_sums, 0, 1, 0, 1)
FIRE_INSTANCE(fire_maxwell_bounded_sums, 0, 0, 1, 1)
FIRE_INSTANCE(fire_maxwell_flow_bounded_sums, 0, 1, 1, 1)
FIRE_INSTANCE(fire_hard_spheres_sums, 1, 0, 1, 1)
FIRE_INSTANCE(fire_hard_spheres_flow_sums, 1, 1, 1, 1)

/* The instance for the engine's shape, [sums][bounded][lazy_flow]. */
static sim_event_fire_fn select_instance(const sim_event *e, int lazy_flow, int bounded,
                                         int sums)
{
    static const sim_event_fire_fn maxwell[2][2][2] = {
        {{fire_maxwell, fire_maxwell_flow}, {fire_maxwell_bounded, fire_maxwell_flow_bounded}},
        {{fire_maxwell_sums, fire_maxwell_flow_sums},
         {fire_maxwell_bounded_sums, fire_maxwell_flow_bounded_sums}}};
    static const sim_event_fire_fn hard_spheres[2][2] = {
        {fire_hard_spheres, fire_hard_spheres_flow},
        {fire_hard_spheres_sums, fire_hard_spheres_flow_sums}};
    const background_params *p = e->params;
    const int l = lazy_flow != 0, b = bounded != 0, k = sums != 0;
    return p->hard_spheres ? hard_spheres[k][l] : maxwell[k][b][l];
}

static sim_event_fire_fn background_select_fire(const sim_event *e, int lazy_flow, int bounded)
{
    return select_instance(e, lazy_flow, bounded, 0);
}

static sim_event_fire_fn background_select_fire_sums(const sim_event *e, int lazy_flow,
                                                     int bounded)
{
    return select_instance(e, lazy_flow, bounded, 1);
}

static const sim_event_fast background_fast = {
    .select_fire_sums = background_select_fire_sums,
};

static const sim_event_type background_type = {
    .name = "background",
    .state_size = sizeof(background_state),
    .needs_bound = background_needs_bound,
    .bound_centre = background_centre,
    .reset = background_reset,
    .rate = background_rate,
    .select_fire = background_select_fire,
    .fast = &background_fast,
};

sim_status sim_effect_background(const sim_scene *scene, sim_event *effect, sim_error *err)
{
    const double grain_mass = sim_scene_grain_mass(scene);
    if (scene->background.kernel != SIM_KERNEL_MAXWELL
        && scene->background.kernel != SIM_KERNEL_HARD_SPHERES)
        return sim_error_set(err, SIM_EUNSUPPORTED, "background.kernel",
                             "supported background kernels: maxwell, hard-spheres");
    background_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    const double rho = scene->background.density, mb = scene->background.mass;
    const double c1_rho_n = scene->background.constant * rho * (double)scene->particles.n;
    p->hard_spheres = scene->background.kernel == SIM_KERNEL_HARD_SPHERES;
    p->mass_ratio = mb / (grain_mass + mb);
    for (int k = 0; k < 3; k++)
        p->velocity[k] = scene->background.velocity[k];
    p->sigma = sqrt(scene->background.temperature / mb);
    p->b = sqrt(2.0 * scene->background.temperature / mb);
    p->mean_speed = 2.0 * p->b / sqrt(M_PI);
    p->rate_maxwell = 4.0 * M_PI * c1_rho_n;
    p->rate_a = 4.0 * M_PI * c1_rho_n;
    p->rate_b = 8.0 * sqrt(M_PI) * p->b * c1_rho_n;
    *effect = (sim_event){.type = &background_type, .params = p};
    return SIM_OK;
}
