/* Binary inelastic collisions, the exact jump scheme of paper A §3 (SPEC §3),
 * also the binary part of paper B's Algorithms 1 and 2 (SPEC §4).
 *
 * VHS kernel B = C |g|^lambda with e uniform on S^2, 0 <= lambda <= 1.  The
 * majorant rate is pi_hat = 2 pi gamma C (n - 1) U_max^lambda; a candidate is
 * an ordered pair i != j chosen uniformly, accepted with (|g| / U_max)^lambda.
 *
 * U_max = 2 R from the shared velocity bound of run.h: |v_i - v_j| <=
 * |v_i - c| + |v_j - c| <= 2 R.  Paper A takes c = the bulk velocity, paper B's
 * Algorithm 2 c = u_B (U2max = max |v_i - u_B|, accept |g| / (2 U2max)); the
 * engine chooses.  R is raised whenever a velocity changes (after its flow is
 * applied and after any collision), so 2 R bounds every pair the scheme has
 * seen.  A lazy flow can carry an untouched particle beyond R; that would show
 * when the pair is drawn (|g| > U_max in use) and is counted as a majorant
 * violation; to make that negligible the engine adds the flow's reach over
 * the time to the next reset to R.  At each output time, with every particle
 * synchronised, R is recomputed from scratch, so the majorant also shrinks
 * when the gas cools.  Maxwell molecules (lambda = 0) need no majorant: every
 * candidate is accepted and the rate never changes.
 *
 * The time-step scheme (SPEC §5, paper C §3), hard spheres only: a collision
 * stage of length h draws candidates at the rate R_c = 8 pi gamma C (n - 1) U_max
 * (Bird's (1/2) n omega_max h per stage with omega_max = 16 pi gamma C
 * (n - 1)/n U_max; the fractional remainder is kept for the next stage), each an
 * ordered pair i != j with s uniform on S^2, accepted with probability
 * Θ(g.s) (g.s)/U_max, and collides by the contact rule (collide.h).  Since
 * E_s[Θ(g.s)(g.s)] = |g|/4, each unordered pair collides at the rate
 * 4 pi gamma C |g|/n, exactly that of the jump scheme above, so that as h -> 0
 * the two schemes simulate the same n-particle process (up to Bird's
 * deterministic candidate count, an O(1/n) effect in transients).  U_max = 2R
 * follows the shared bound as above, so g.s <= |g| <= U_max always holds and
 * the paper's "omega_max updated when exceeded" never has to act; a candidate
 * with g.s > U_max would still be counted as a violation.  When U_max grows
 * within the stage, the remaining stage time is spent at the new rate.
 */
#include <math.h>
#include <stdlib.h>

#include "collide.h"
#include "effect.h"
#include "rng.h"
#include "run.h"

typedef struct collisions_params {
    double lambda;      /* VHS exponent */
    double alpha;       /* restitution */
    double prefactor;   /* 2 pi gamma C (n - 1) */
    double stage_time;  /* time-step scheme: 1 / (8 pi gamma C (n - 1)), the time per
                           candidate times U_max */
} collisions_params;

typedef struct collisions_state {
    double radius;      /* the bound's R when umax was last computed */
    double umax;        /* 2 R */
    double rate;        /* prefactor umax^lambda */
    double credit;      /* time-step scheme: stage time not yet spent on candidates */
} collisions_state;

enum kernel_case { KERNEL_MAXWELL, KERNEL_HARD_SPHERES, KERNEL_VHS };

/* Follow the shared bound: recompute umax and the rate if R has changed. */
static inline double follow_bound(const collisions_params *p, collisions_state *s,
                                  const sim_run *run)
{
    if (run->radius != s->radius) {
        s->radius = run->radius;
        s->umax = 2.0 * run->radius;
        s->rate = p->lambda == 1.0 ? p->prefactor * s->umax
                                   : p->prefactor * pow(s->umax, p->lambda);
    }
    return s->rate;
}

static int collisions_needs_bound(const sim_effect *e)
{
    return ((const collisions_params *)e->params)->lambda != 0.0;
}

static double collisions_rate(const sim_effect *e, const sim_run *run, void *vstate)
{
    const collisions_params *p = e->params;
    if (p->lambda == 0.0)
        return p->prefactor;
    return follow_bound(p, vstate, run);
}

static double collisions_reset(const sim_effect *e, sim_run *run, void *vstate, double horizon)
{
    (void)horizon;   /* the engine has added the flow's reach to the bound */
    collisions_state *s = vstate;
    s->radius = -1.0;   /* force a recomputation */
    return collisions_rate(e, run, s);
}

/* One candidate collision at time t (paper A Algorithm, steps 2.3-2.10).
 * kernel, lazy_flow and bounded are compile-time constants in each instance
 * below (bounded is implied by kernel != KERNEL_MAXWELL). */
static inline double fire_candidate(const sim_effect *e, sim_run *run, void *vstate, double t,
                                    const enum kernel_case kernel, const int lazy_flow,
                                    const int bounded)
{
    const collisions_params *p = e->params;
    collisions_state *s = vstate;
    gsl_rng *rng = run->rng;
    const size_t n = run->p.n;

    size_t i = (size_t)sim_rng_index(rng, n);
    size_t j = (size_t)sim_rng_index(rng, n - 1);
    j += (j >= i);   /* uniform over j != i */
    if (lazy_flow) {
        sim_run_bring(run, i, t);
        sim_run_bring(run, j, t);
    }
    double *vi = run->p.v[i], *vj = run->p.v[j];
    double g[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
    double gnorm = sim_norm3(g);
    run->counts.candidates++;

    if (kernel != KERNEL_MAXWELL) {
        if (gnorm > s->umax)
            run->counts.violations++;
        if (lazy_flow) {   /* the flow moved i and j since R last covered them */
            sim_run_cover(run, vi);
            sim_run_cover(run, vj);
            follow_bound(p, s, run);
        }
        double u = sim_rng_uniform(rng);
        int fictitious = kernel == KERNEL_HARD_SPHERES ? u * s->umax >= gnorm
                                                       : u >= pow(gnorm / s->umax, p->lambda);
        if (fictitious)
            return s->rate;
    }

    double unit[3];
    sim_rng_unit_sphere(rng, unit);
    sim_collide_inelastic(vi, vj, p->alpha, gnorm, unit);
    run->counts.collisions++;
    if (bounded) {
        sim_run_cover(run, vi);
        sim_run_cover(run, vj);
    }
    return kernel == KERNEL_MAXWELL ? p->prefactor : follow_bound(p, s, run);
}

#define FIRE_INSTANCE(name, kernel, lazy, bounded)                                           \
    static double name(const sim_effect *e, sim_run *run, void *state, double t)           \
    {                                                                                        \
        return fire_candidate(e, run, state, t, kernel, lazy, bounded);                      \
    }
FIRE_INSTANCE(fire_maxwell, KERNEL_MAXWELL, 0, 0)
FIRE_INSTANCE(fire_maxwell_flow, KERNEL_MAXWELL, 1, 0)
FIRE_INSTANCE(fire_maxwell_bounded, KERNEL_MAXWELL, 0, 1)
FIRE_INSTANCE(fire_maxwell_flow_bounded, KERNEL_MAXWELL, 1, 1)
FIRE_INSTANCE(fire_hard_spheres, KERNEL_HARD_SPHERES, 0, 1)
FIRE_INSTANCE(fire_hard_spheres_flow, KERNEL_HARD_SPHERES, 1, 1)
FIRE_INSTANCE(fire_vhs, KERNEL_VHS, 0, 1)
FIRE_INSTANCE(fire_vhs_flow, KERNEL_VHS, 1, 1)

static sim_event_fire_fn collisions_select_fire(const sim_effect *e, int lazy_flow, int bounded)
{
    const collisions_params *p = e->params;
    if (p->lambda == 0.0) {
        if (bounded)
            return lazy_flow ? fire_maxwell_flow_bounded : fire_maxwell_bounded;
        return lazy_flow ? fire_maxwell_flow : fire_maxwell;
    }
    if (p->lambda == 1.0)
        return lazy_flow ? fire_hard_spheres_flow : fire_hard_spheres;
    return lazy_flow ? fire_vhs_flow : fire_vhs;
}

/* One collision stage of the time-step scheme (hard spheres, contact rule). */
static void stage_hard_spheres(const sim_effect *e, sim_run *run, void *vstate, double h)
{
    const collisions_params *p = e->params;
    collisions_state *s = vstate;
    gsl_rng *rng = run->rng;
    const size_t n = run->p.n;
    const double alpha = p->alpha;

    follow_bound(p, s, run);
    if (!(s->umax > 0.0)) {   /* every velocity equal: no collision can happen */
        s->credit = 0.0;
        return;
    }
    double dtc = p->stage_time / s->umax;   /* time per candidate */
    double credit = s->credit + h;
    uint64_t candidates = 0, collisions = 0;
    while (credit >= dtc) {
        credit -= dtc;
        candidates++;
        size_t i = (size_t)sim_rng_index(rng, n);
        size_t j = (size_t)sim_rng_index(rng, n - 1);
        j += (j >= i);
        double unit[3];
        sim_rng_unit_sphere(rng, unit);
        double *vi = run->p.v[i], *vj = run->p.v[j];
        double gs = (vi[0] - vj[0]) * unit[0] + (vi[1] - vj[1]) * unit[1]
                    + (vi[2] - vj[2]) * unit[2];
        if (gs <= 0.0)   /* Θ(g.s): the spheres move apart */
            continue;
        if (gs > s->umax)
            run->counts.violations++;
        if (sim_rng_uniform(rng) * s->umax >= gs)
            continue;
        sim_collide_contact(vi, vj, alpha, gs, unit);
        collisions++;
        sim_run_cover(run, vi);
        sim_run_cover(run, vj);
        if (run->radius != s->radius) {
            follow_bound(p, s, run);
            dtc = p->stage_time / s->umax;
        }
    }
    s->credit = credit;
    run->bound_grew = 0;   /* followed above; no other process shares the bound */
    run->counts.candidates += candidates;
    run->counts.collisions += collisions;
}

static sim_event_stage_fn collisions_select_stage(const sim_effect *e)
{
    const collisions_params *p = e->params;
    return p->lambda == 1.0 ? stage_hard_spheres : NULL;
}

static const sim_effect_type collisions_type = {
    .name = "collisions",
    .state_size = sizeof(collisions_state),
    .needs_bound = collisions_needs_bound,
    .reset = collisions_reset,
    .rate = collisions_rate,
    .select_fire = collisions_select_fire,
    .select_stage = collisions_select_stage,
};

sim_status sim_effect_collisions(const sim_scene *scene, sim_effect *effect, sim_error *err)
{
    if (scene->collisions.model != SIM_MODEL_IHS)
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions.model",
                             "model ehs is not implemented yet (supported: ihs)");
    if (scene->scheme == SIM_SCHEME_TIMESTEP && scene->collisions.exponent != 1.0)
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions.kernel",
                             "the time-step scheme implements hard spheres only (the contact "
                             "rule of paper C; kernel exponent is %g)",
                             scene->collisions.exponent);
    collisions_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    p->lambda = scene->collisions.exponent;
    p->alpha = scene->collisions.restitution;
    p->prefactor = 2.0 * M_PI * scene->collisions.rate * scene->collisions.constant
                   * (double)(scene->particles.n - 1);
    p->stage_time = 1.0 / (4.0 * p->prefactor);
    *effect = (sim_effect){.type = &collisions_type, .params = p};
    return SIM_OK;
}
