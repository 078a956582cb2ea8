/* Binary inelastic collisions, the exact jump scheme of paper A §3 (docs/theory.md §8.3),
 * also the binary part of paper B's Algorithms 1 and 2 (docs/theory.md §5).
 *
 * VHS kernel B = C |g|^lambda with e uniform on S^2, 0 <= lambda <= 1: each
 * unordered pair {i, j} collides at the rate 4 pi gamma C |g|^lambda / n.  The
 * majorant rate is pi_hat = 2 pi gamma C (n - 1) U_max^lambda with U_max = 2 R
 * from the shared velocity bound of run.h: |v_i - c| <= R for every i, so
 * |v_i - v_j| <= |v_i - c| + |v_j - c| <= 2 R.  Paper A takes c = the bulk
 * velocity, paper B's Algorithm 2 c = u_B (U2max = max |v_i - u_B|); the engine
 * chooses.  R is raised whenever a velocity changes (after its flow is applied
 * and after any collision), so R bounds every velocity the scheme has seen.
 * A lazy flow can carry an untouched particle beyond R; that shows when the
 * particle is drawn and is counted as a majorant violation; to make that
 * negligible the engine adds the flow's reach over the time to the next reset
 * to R.  The engine recomputes R from scratch at each output time (and, in
 * runs without a lazy flow, every few n candidates), so the majorant also
 * shrinks when the gas cools.  Maxwell molecules (lambda = 0) need no
 * majorant: every candidate is accepted and the rate never changes.
 *
 * Hard spheres (lambda = 1) use the tighter pairwise bound |g| <= a_i + a_j,
 * a_i = |v_i - c| <= R, in two stages, at the same candidate rate
 * pi_hat = 4 pi gamma C (n - 1) R:
 *   1. i uniform, kept with probability a_i / R (else the candidate is
 *      fictitious after one particle load);
 *   2. j uniform among the others, accepted with |g| / (a_i + a_j).
 * The ordered pair (i, j) then collides at the rate
 *   pi_hat (1/n) (a_i / R) (1/(n-1)) |g| / (a_i + a_j),
 * and since the collision rule is symmetric in i and j (e -> -e is again
 * uniform), the unordered pair at the sum of (i, j) and (j, i):
 *   pi_hat |g| (a_i + a_j) / (n (n-1) R (a_i + a_j)) = 4 pi gamma C |g| / n,
 * exactly the hard-sphere rate.  Compared with one test |g| / (2R) on a
 * uniform pair, the expected number of collisions per candidate is the same,
 * but a candidate rejected in stage 1 (most of them) costs one particle
 * instead of two and no square root of |g|, and stage 2 accepts about 0.7 of
 * the pairs of a Maxwellian (E|g| / E(a_i + a_j) = sqrt(2)/2).  A violation
 * is now a drawn particle with a_i > R.
 *
 * Particle indices come from the run's index stream (particles.h: drawn
 * ahead, their memory prefetched) with a 32-bit uniform each for the
 * acceptance test that follows (rng.h: exact Bernoulli trials).
 *
 * The time-step scheme (docs/theory.md §8.5, paper C §3), hard spheres: a collision
 * stage of length h draws candidates at the rate R_c = 8 pi gamma C (n - 1) U_max
 * (Bird's (1/2) n omega_max h per stage with omega_max = 16 pi gamma C
 * (n - 1)/n U_max; the fractional remainder is kept for the next stage), each an
 * ordered pair i != j with s uniform on S^2, accepted with probability
 * Θ(g.s) (g.s)/U_max, and collides by the contact rule (collide.h).  Since
 * E_s[Θ(g.s)(g.s)] = |g|/4, each unordered pair collides at the rate
 * 4 pi gamma C |g|/n, exactly that of the jump scheme above, so that as h -> 0
 * the two schemes simulate the same n-particle process (up to Bird's
 * deterministic candidate count, an O(1/n) effect in transients).  The pair
 * and the acceptance are drawn in the two stages above: i kept with a_i / R,
 * then j and s, accepted with Θ(g.s) (g.s) / (a_i + a_j); the unordered pair
 * with contact direction s (g.s > 0; (j, i) with -s is the same contact)
 * collides at R_c (g.s) (a_i + a_j) / (n (n-1) R (a_i + a_j)) ds / (4 pi), the
 * rate of the one-stage test (g.s) / U_max.  U_max = 2R follows the shared
 * bound, so the paper's "omega_max updated when exceeded" never has to act;
 * a drawn particle beyond R would still be counted as a violation.  When R
 * grows within the stage, the remaining stage time is spent at the new rate.
 * With collisions.rule = relative-speed the stage accepts as the jump scheme
 * does (stage 2: |g| / (a_i + a_j), then e uniform) at the jump scheme's rate
 * 4 pi gamma C (n - 1) R, a quarter of R_c: equal in distribution (docs/theory.md §3.2).
 * Paper E's frictional elastic hard spheres (collisions.model = ehs) collide
 * elastically at beta = (1 + alpha)/2 times this rate.
 * Maxwell molecules and VHS (issue 15: the heat-flux force on any kernel):
 * the engine's stage fires the jump scheme's candidates (uniform pair, paper
 * A's rule) at their majorant rate for the stage time, with the same
 * remainder (scheme_timestep.c, stage_fired).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "collide.h"
#include "effect.h"
#include "first_stage.h"
#include "particles.h"
#include "rng.h"
#include "run.h"

typedef struct collisions_params {
    double lambda;      /* VHS exponent */
    double alpha;       /* restitution */
    double prefactor;   /* 2 pi gamma C (n - 1) */
    double stage_time;  /* time-step scheme, hard spheres: the time per candidate times
                           U_max, 1 / (8 pi gamma C (n - 1)) by the contact rule and
                           1 / (2 pi gamma C (n - 1)) by |g| (collisions.rule) */
    int contact;        /* ... the contact rule (paper C), else |g| (paper A) */
    /* The Lees-Edwards slab (collisions_layer): a layer's candidate rate per
     * ordered pair and unit of w_I = 2 R_I, 2 pi gamma C beta M/N, and its
     * ordered pairs N_I (N_I - pair_offset) (pair_offset 0: paper E's N_I^2,
     * shear.candidates = paper) */
    double layer_kappa;
    size_t pair_offset;
} collisions_params;

typedef struct collisions_state {
    double radius;      /* the bound's R when umax was last computed */
    double umax;        /* 2 R */
    double rate;        /* prefactor umax^lambda */
    double scale;       /* 2^32 / R: stage 1's acceptance a_i / R as sim_rng_accept32's x */
    double credit;      /* time-step scheme: stage time not yet spent on candidates */
    double margin;      /* the lazy flow's reach until the next reset (0 without one) */
    double margin_vy;   /* ... its part per |v_y| (the shear; effect.h, reach_vy) */
    int started;        /* the index stream is filled (the engine zeroes the state
                           at the start of every run) */
    int batch_started;  /* ... and the blocks of first particles */
    sim_pick pick;      /* the run's particle indices, drawn ahead */
    sim_batch batch;    /* first particles in blocks (the batched loops below) */
} collisions_state;

enum kernel_case { KERNEL_MAXWELL, KERNEL_HARD_SPHERES, KERNEL_VHS };

/* Follow the shared bound: recompute umax and the rate if R has changed. */
static inline double follow_bound(const collisions_params *p, collisions_state *s,
                                  const sim_run *run)
{
    if (run->radius != s->radius) {
        s->radius = run->radius;
        s->umax = 2.0 * run->radius;
        s->scale = run->radius > 0.0 ? 0x1p32 / run->radius : 0.0;
        s->rate = p->lambda == 1.0 ? p->prefactor * s->umax
                                   : p->prefactor * pow(s->umax, p->lambda);
    }
    return s->rate;
}

static int collisions_needs_bound(const sim_event *e)
{
    return ((const collisions_params *)e->params)->lambda != 0.0;
}

static double collisions_rate(const sim_event *e, const sim_run *run, void *vstate)
{
    const collisions_params *p = e->params;
    if (p->lambda == 0.0)
        return p->prefactor;
    return follow_bound(p, vstate, run);
}

static double collisions_reset(const sim_event *e, sim_run *run, void *vstate, double horizon)
{
    /* the engine has added the flow's reach to the bound; velocities this
     * process changes get the same margin (cover_moving) */
    collisions_state *s = vstate;
    const sim_flow *flow = run->flow;
    s->margin = flow ? flow->type->reach(flow, horizon) : 0.0;
    s->margin_vy = flow && flow->type->reach_vy ? flow->type->reach_vy(flow, horizon) : 0.0;
    if (!s->started) {   /* the first reset of a run, after the initial state */
        sim_pick_start(&s->pick, &run->p, run->rng);
        s->started = 1;
    }
    s->radius = -1.0;   /* force a recomputation */
    return collisions_rate(e, run, s);
}

/* The next particle of the index stream, brought to time t by a lazy flow;
 * j != i when called with the first particle i (else i = UINT32_MAX). */
static inline __attribute__((always_inline)) uint32_t
draw_particle(collisions_state *s, sim_run *run, uint32_t other, double t, uint32_t *spare,
              const int lazy_flow, const int sums)
{
    uint32_t i;
    do
        i = sim_pick_next(&s->pick, &run->p, run->rng, spare, lazy_flow);
    while (i == other);   /* uniform over the others: redraw (probability 1/n) */
    if (sums)   /* out of the running sums until the caller puts it back */
        sim_sums_add(&run->sums, run->p.v[i], lazy_flow ? run->p.stamp[i] : 0.0, -1.0);
    if (lazy_flow)
        sim_run_bring(run, i, t);
    return i;
}

/* Particles i and j back into the running sums (with sums, a constant). */
static inline __attribute__((always_inline)) void
sums_restore(sim_run *run, uint32_t i, uint32_t j, const int lazy_flow, const int sums)
{
    if (sums) {
        sim_sums_add(&run->sums, run->p.v[i], lazy_flow ? run->p.stamp[i] : 0.0, 1.0);
        sim_sums_add(&run->sums, run->p.v[j], lazy_flow ? run->p.stamp[j] : 0.0, 1.0);
    }
}

/* Velocities vi and vj (no lazy flow: stamps 0) out of the running sums
 * before a collision changes them (with sums, a constant). */
static inline __attribute__((always_inline)) void
sums_remove(sim_run *run, const double vi[3], const double vj[3], const int sums)
{
    if (sums) {
        sim_sums_add(&run->sums, vi, 0.0, -1.0);
        sim_sums_add(&run->sums, vj, 0.0, -1.0);
    }
}

/* Let the bound cover velocity v of a particle that a lazy flow will keep
 * moving: with the flow's reach until the next reset as a margin, as the
 * engine gives every particle at the reset.  Without it a particle just
 * covered (a = R) would outrun R with probability 1/2 as soon as the flow
 * moves it, and stage 1 (a_i / R) needs a_i <= R for every drawn particle. */
static inline void cover_moving(sim_run *run, const collisions_state *s, const double v[3])
{
    const double a = sqrt(sim_dist2(v, run->centre)) + s->margin + s->margin_vy * fabs(v[1]);
    if (a > run->radius) {
        run->radius = a;
        run->bound_grew = 1;
    }
}

/* a = |v - c|; a drawn particle beyond the bound is a majorant violation,
 * which only a lazy flow can cause (with probability below P(chi_3 > 7) per
 * particle and interval, effect_heating.c): it is counted and covered. */
static inline double bounded_distance(const collisions_params *p, collisions_state *s,
                                      sim_run *run, const double v[3], const int lazy_flow)
{
    const double a = sqrt(sim_dist2(v, run->centre));
    if (a > run->radius) {
        run->counts.violations++;
        if (lazy_flow) {
            cover_moving(run, s, v);
            follow_bound(p, s, run);
        }
    }
    return a;
}

/* One candidate hard-sphere collision at time t (paper A Algorithm, steps
 * 2.3-2.10, with the two-stage acceptance of the header comment). */
static inline __attribute__((always_inline)) double
fire_hard_spheres_at(const sim_event *e, sim_run *run, void *vstate, double t,
                     const int lazy_flow, const int sums)
{
    const collisions_params *p = e->params;
    collisions_state *s = vstate;
    follow_bound(p, s, run);   /* another process may have grown the bound */
    run->counts.candidates++;

    uint32_t ui, i = draw_particle(s, run, UINT32_MAX, t, &ui, lazy_flow, 0);
    double *vi = run->p.v[i];
    const double ai = bounded_distance(p, s, run, vi, lazy_flow);
    if (!sim_rng_accept32(run->rng, ui, ai * s->scale))
        return s->rate;   /* stage 1: fictitious */

    uint32_t uj, j = draw_particle(s, run, i, t, &uj, lazy_flow, 0);
    double *vj = run->p.v[j];
    const double aj = bounded_distance(p, s, run, vj, lazy_flow);
    const double g[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
    const double gnorm = sim_norm3(g);
    if (!sim_rng_accept32_ratio(run->rng, uj, gnorm, ai + aj))
        return s->rate;   /* stage 2: fictitious */

    double unit[3];
    sim_rng_unit_sphere(run->rng, unit);
    /* with sums, those of the velocities at t (no flow, or a lazy one with
     * advance_sums: select_fire_current_sums); bringing i and j left them */
    sums_remove(run, vi, vj, sums);
    sim_collide_inelastic(vi, vj, p->alpha, gnorm, unit);
    sums_restore(run, i, j, 0, sums);
    run->counts.collisions++;
    if (lazy_flow) {
        cover_moving(run, s, vi);
        cover_moving(run, s, vj);
    } else {
        sim_run_cover(run, vi);
        sim_run_cover(run, vj);
    }
    return follow_bound(p, s, run);
}

/* One candidate collision with a uniform pair at time t: Maxwell molecules
 * (always accepted) or VHS (accepted with (|g| / U_max)^lambda).  kernel,
 * lazy_flow and bounded are constants in each instance below (bounded is
 * implied by kernel == KERNEL_VHS). */
static inline __attribute__((always_inline)) double
fire_uniform_pair(const sim_event *e, sim_run *run, void *vstate, double t,
                  const enum kernel_case kernel, const int lazy_flow, const int bounded,
                  const int sums)
{
    const collisions_params *p = e->params;
    collisions_state *s = vstate;
    run->counts.candidates++;

    uint32_t ui, i = draw_particle(s, run, UINT32_MAX, t, &ui, lazy_flow, sums);
    uint32_t uj, j = draw_particle(s, run, i, t, &uj, lazy_flow, sums);
    double *vi = run->p.v[i], *vj = run->p.v[j];
    const double g[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
    const double gnorm = sim_norm3(g);

    if (kernel == KERNEL_VHS) {
        follow_bound(p, s, run);   /* another process may have grown the bound */
        if (gnorm > s->umax)
            run->counts.violations++;
        if (lazy_flow) {   /* the flow moved i and j since R last covered them */
            cover_moving(run, s, vi);
            cover_moving(run, s, vj);
            follow_bound(p, s, run);
        }
        if (!sim_rng_accept32(run->rng, uj, pow(gnorm / s->umax, p->lambda) * 0x1p32)) {
            sums_restore(run, i, j, lazy_flow, sums);
            return s->rate;
        }
    }

    double unit[3];
    sim_rng_unit_sphere(run->rng, unit);
    sim_collide_inelastic(vi, vj, p->alpha, gnorm, unit);
    run->counts.collisions++;
    sums_restore(run, i, j, lazy_flow, sums);
    if (bounded && lazy_flow) {
        cover_moving(run, s, vi);
        cover_moving(run, s, vj);
    } else if (bounded) {
        sim_run_cover(run, vi);
        sim_run_cover(run, vj);
    }
    return kernel == KERNEL_MAXWELL ? p->prefactor : follow_bound(p, s, run);
}

#define FIRE_INSTANCE(name, kernel, lazy, bounded, sums)                                     \
    static double name(const sim_event *e, sim_run *run, void *state, double t)           \
    {                                                                                        \
        return fire_uniform_pair(e, run, state, t, kernel, lazy, bounded, sums);             \
    }
FIRE_INSTANCE(fire_maxwell, KERNEL_MAXWELL, 0, 0, 0)
FIRE_INSTANCE(fire_maxwell_flow, KERNEL_MAXWELL, 1, 0, 0)
FIRE_INSTANCE(fire_maxwell_bounded, KERNEL_MAXWELL, 0, 1, 0)
FIRE_INSTANCE(fire_maxwell_flow_bounded, KERNEL_MAXWELL, 1, 1, 0)
FIRE_INSTANCE(fire_vhs, KERNEL_VHS, 0, 1, 0)
FIRE_INSTANCE(fire_vhs_flow, KERNEL_VHS, 1, 1, 0)
/* keeping the running sums (observation = conditional) */
FIRE_INSTANCE(fire_maxwell_sums, KERNEL_MAXWELL, 0, 0, 1)
FIRE_INSTANCE(fire_maxwell_flow_sums, KERNEL_MAXWELL, 1, 0, 1)
FIRE_INSTANCE(fire_maxwell_bounded_sums, KERNEL_MAXWELL, 0, 1, 1)
FIRE_INSTANCE(fire_maxwell_flow_bounded_sums, KERNEL_MAXWELL, 1, 1, 1)
FIRE_INSTANCE(fire_vhs_sums, KERNEL_VHS, 0, 1, 1)
FIRE_INSTANCE(fire_vhs_flow_sums, KERNEL_VHS, 1, 1, 1)

#define FIRE_HS_INSTANCE(name, lazy, sums)                                                  \
    static double name(const sim_event *e, sim_run *run, void *state, double t)           \
    {                                                                                        \
        return fire_hard_spheres_at(e, run, state, t, lazy, sums);                           \
    }
FIRE_HS_INSTANCE(fire_hard_spheres, 0, 0)
FIRE_HS_INSTANCE(fire_hard_spheres_flow, 1, 0)
FIRE_HS_INSTANCE(fire_hard_spheres_sums, 0, 1)
FIRE_HS_INSTANCE(fire_hard_spheres_flow_current_sums, 1, 1)

/* The instance for the engine's shape, [sums][bounded][lazy_flow].  Hard
 * spheres keep running sums only without a lazy flow (for the jump scheme's
 * keep-temperature rescaling; with white noise their jump scheme passes over
 * the particles at every output time for the bound anyway): NULL with one,
 * and the engine then observes conditionally from the particles. */
static sim_event_fire_fn select_instance(const sim_event *e, int lazy_flow, int bounded,
                                         int sums)
{
    static const sim_event_fire_fn maxwell[2][2][2] = {
        {{fire_maxwell, fire_maxwell_flow}, {fire_maxwell_bounded, fire_maxwell_flow_bounded}},
        {{fire_maxwell_sums, fire_maxwell_flow_sums},
         {fire_maxwell_bounded_sums, fire_maxwell_flow_bounded_sums}}};
    static const sim_event_fire_fn hard_spheres[2][2] = {
        {fire_hard_spheres, fire_hard_spheres_flow}, {fire_hard_spheres_sums, NULL}};
    static const sim_event_fire_fn vhs[2][2] = {{fire_vhs, fire_vhs_flow},
                                                {fire_vhs_sums, fire_vhs_flow_sums}};
    const collisions_params *p = e->params;
    const int l = lazy_flow != 0, b = bounded != 0, k = sums != 0;
    return p->lambda == 0.0 ? maxwell[k][b][l] : p->lambda == 1.0 ? hard_spheres[k][l]
                                                                 : vhs[k][l];
}

static sim_event_fire_fn collisions_select_fire(const sim_event *e, int lazy_flow, int bounded)
{
    return select_instance(e, lazy_flow, bounded, 0);
}

static sim_event_fire_fn collisions_select_fire_sums(const sim_event *e, int lazy_flow,
                                                     int bounded)
{
    return select_instance(e, lazy_flow, bounded, 1);
}

/* Sums at the candidates' time under a deterministic lazy flow (effect.h):
 * hard spheres only (paper E's sheared EHS gas), NULL otherwise. */
static sim_event_fire_fn collisions_select_fire_current_sums(const sim_event *e)
{
    const collisions_params *p = e->params;
    return p->lambda == 1.0 ? fire_hard_spheres_flow_current_sums : NULL;
}

/* ------------------------------------------------------ batched loops */

/* Bits lo .. hi - 1 (0 <= lo <= hi <= SIM_BATCH). */
static inline uint32_t bit_range(unsigned lo, unsigned hi)
{
    return ((1u << hi) - 1u) & ~((1u << lo) - 1u);
}

/* Hard-sphere candidates without a lazy flow, first particles from the
 * blocks: up to `max` of them, stopping after a collision that grows the
 * bound; returns how many.  The first stage is decided for a whole block at
 * once and the loop jumps from kept entry to kept entry (most candidates end
 * there, and a data-dependent branch per candidate costs more than the test).
 * After a collision the block's later entries of the two particles are
 * tested again, so every entry is decided with the state at its turn.
 * contact = 0: the jump scheme (stage 2: |g| / (a_i + a_j), then e uniform and
 * the rule of collide.h); 1: the time-step scheme's contact rule (s uniform,
 * stage 2: Θ(g.s) (g.s) / (a_i + a_j)); a constant in each caller. */
static inline __attribute__((always_inline)) uint64_t
batched_hard_spheres(const collisions_params *p, collisions_state *s, sim_run *run, uint64_t max,
                     const int contact, const int sums)
{
    gsl_rng *rng = run->rng;
    sim_particles *ps = &run->p;
    sim_batch *b = &s->batch;
    if (!s->batch_started) {
        sim_batch_start(b, ps, rng);
        s->batch_started = 1;
    }
    const double c[3] = {run->centre[0], run->centre[1], run->centre[2]};
    const double radius = run->radius, scale = s->scale, alpha = p->alpha;
    unsigned pos = b->pos;   /* the next entry of the block, in a register */
    uint32_t keep = sim_first_stage(b, bit_range(pos, SIM_BATCH), ps, c, scale, rng);
    uint64_t done = 0, collisions = 0, violations = 0;
    while (done < max) {
        if (pos == SIM_BATCH) {
            sim_batch_advance(b, ps, rng);
            pos = 0;
            keep = sim_first_stage(b, bit_range(0, SIM_BATCH), ps, c, scale, rng);
        }
        const uint32_t later = keep & bit_range(pos, SIM_BATCH);
        const unsigned k = later ? (unsigned)__builtin_ctz(later) : SIM_BATCH;
        const uint64_t left = max - done;
        if (k - pos >= left) {   /* the last candidates are all rejected in stage 1 */
            pos += (unsigned)left;
            done = max;
            break;
        }
        const unsigned end = k < SIM_BATCH ? k + 1 : SIM_BATCH;
        done += end - pos;
        pos = end;
        if (k == SIM_BATCH)
            continue;

        const uint32_t i = b->index[k];   /* kept in stage 1 */
        double *vi = ps->v[i];
        const double ai = sqrt(sim_dist2(vi, c));
        uint32_t uj, j;
        do
            j = sim_pick_next(&s->pick, ps, rng, &uj, 0);
        while (j == i);
        double *vj = ps->v[j];
        const double aj = sqrt(sim_dist2(vj, c));
        violations += (ai > radius) + (aj > radius);   /* never, without a lazy flow */
        double unit[3];
        if (contact) {
            sim_rng_unit_sphere(rng, unit);
            const double gs = (vi[0] - vj[0]) * unit[0] + (vi[1] - vj[1]) * unit[1]
                              + (vi[2] - vj[2]) * unit[2];
            /* Θ(g.s): gs <= 0 (the spheres move apart) never passes */
            if (!sim_rng_accept32_ratio(rng, uj, gs, ai + aj))
                continue;
            sums_remove(run, vi, vj, sums);
            sim_collide_contact(vi, vj, alpha, gs, unit);
        } else {
            const double g[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
            const double gnorm = sim_norm3(g);
            if (!sim_rng_accept32_ratio(rng, uj, gnorm, ai + aj))
                continue;
            sim_rng_unit_sphere(rng, unit);
            sums_remove(run, vi, vj, sums);
            sim_collide_inelastic(vi, vj, alpha, gnorm, unit);
        }
        if (sums) {
            sim_sums_add(&run->sums, vi, 0.0, 1.0);
            sim_sums_add(&run->sums, vj, 0.0, 1.0);
        }
        collisions++;
        /* sim_run_cover, with the loop's copies of the centre and of R
         * (run->radius == radius until a collision grows it) */
        const double ri = sim_dist2(vi, c), rj = sim_dist2(vj, c);
        if ((ri > rj ? ri : rj) > radius * radius) {
            sim_run_cover(run, vi);
            sim_run_cover(run, vj);
            if (run->radius != radius)
                break;
        }
        uint32_t moved = 0;   /* later entries of the block with particle i or j */
        for (unsigned q = k + 1; q < SIM_BATCH; q++)
            moved |= (uint32_t)(b->index[q] == i || b->index[q] == j) << q;
        if (moved)
            keep = (keep & ~moved) | sim_first_stage(b, moved, ps, c, scale, rng);
    }
    b->pos = pos;
    run->counts.candidates += done;
    run->counts.collisions += collisions;
    run->counts.violations += violations;
    return done;
}

/* The jump scheme's fast path (effect.h: the only event process, no lazy
 * flow): stops after a collision that grows the bound. */
static uint64_t fire_many_hard_spheres(const sim_event *e, sim_run *run, void *vstate,
                                       uint64_t max, double *rate)
{
    const collisions_params *p = e->params;
    collisions_state *s = vstate;
    follow_bound(p, s, run);
    const uint64_t done = batched_hard_spheres(p, s, run, max, 0, 0);
    *rate = follow_bound(p, s, run);
    return done;
}

/* The fast path for Maxwell molecules: every candidate collides and the rate
 * never changes. */
static uint64_t fire_many_maxwell(const sim_event *e, sim_run *run, void *vstate, uint64_t max,
                                  double *rate)
{
    const collisions_params *p = e->params;
    collisions_state *s = vstate;
    gsl_rng *rng = run->rng;
    sim_particles *ps = &run->p;
    for (uint64_t k = 0; k < max; k++) {
        uint32_t spare, i = sim_pick_next(&s->pick, ps, rng, &spare, 0), j;
        do
            j = sim_pick_next(&s->pick, ps, rng, &spare, 0);
        while (j == i);
        double *vi = ps->v[i], *vj = ps->v[j];
        const double g[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
        double unit[3];
        sim_rng_unit_sphere(rng, unit);
        sim_collide_inelastic(vi, vj, p->alpha, sim_norm3(g), unit);
    }
    run->counts.candidates += max;
    run->counts.collisions += max;
    *rate = p->prefactor;
    return max;
}

static sim_event_fire_many_fn collisions_select_fire_many(const sim_event *e)
{
    const collisions_params *p = e->params;
    return p->lambda == 0.0 ? fire_many_maxwell
           : p->lambda == 1.0 ? fire_many_hard_spheres
                              : NULL;
}

/* One collision stage of the time-step scheme (hard spheres, the two-stage
 * acceptance of the header comment, by the contact rule or by |g|):
 * floor(credit / dtc) candidates at dtc = stage_time / U_max each; when a
 * collision grows the bound, the stage time left is spent at the new U_max.
 * contact and sums (keep run->sums current) are constants in each instance. */
static inline __attribute__((always_inline)) void
stage_hard_spheres(const sim_event *e, sim_run *run, void *vstate, double h, const int contact,
                   const int sums)
{
    const collisions_params *p = e->params;
    collisions_state *s = vstate;
    double credit = s->credit + h;
    for (;;) {
        follow_bound(p, s, run);
        if (!(s->umax > 0.0)) {   /* every velocity equal: no collision can happen */
            credit = 0.0;
            break;
        }
        const double dtc = p->stage_time / s->umax;   /* time per candidate */
        const double count = floor(credit / dtc);
        if (!(count >= 1.0))
            break;
        const uint64_t done = batched_hard_spheres(p, s, run, (uint64_t)count, contact, sums);
        credit -= (double)done * dtc;
        if (done == (uint64_t)count)
            break;
    }
    s->credit = fmax(credit, 0.0);
    run->bound_grew = 0;   /* followed above; no other process shares the bound */
}

#define STAGE_HS_INSTANCE(name, contact, sums)                                      \
    static void name(const sim_event *e, sim_run *run, void *state, double h)      \
    {                                                                               \
        stage_hard_spheres(e, run, state, h, contact, sums);                        \
    }
STAGE_HS_INSTANCE(stage_hs_contact, 1, 0)
STAGE_HS_INSTANCE(stage_hs_speed, 0, 0)
STAGE_HS_INSTANCE(stage_hs_contact_sums, 1, 1)
STAGE_HS_INSTANCE(stage_hs_speed_sums, 0, 1)

/* Hard spheres have their batched stage; Maxwell molecules and VHS none
 * (NULL): the engine's stage fires their jump-scheme candidates (paper A's
 * rule: a uniform pair, accepted with (|g|/U_max)^lambda, e uniform) at the
 * majorant rate for the stage time (scheme_timestep.c, stage_fired). */
static sim_event_stage_fn collisions_select_stage(const sim_event *e, int sums)
{
    const collisions_params *p = e->params;
    if (p->lambda != 1.0)
        return NULL;
    if (p->contact)
        return sums ? stage_hs_contact_sums : stage_hs_contact;
    return sums ? stage_hs_speed_sums : stage_hs_speed;
}

/* With a lazy flow the engine fires the jump scheme's candidates in the
 * stages: the same algorithm but for the contact rule of hard spheres, which
 * only the batched stage draws. */
static int collisions_fires_candidates(const sim_event *e)
{
    const collisions_params *p = e->params;
    return !(p->lambda == 1.0 && p->contact);
}

/* The Lees-Edwards slab's layer of count particles from lo (docs/theory.md
 * §6.3, scheme_slab.c): candidates at kappa P_I w_I, P_I the layer's ordered
 * pairs and w_I = 2 R_I, by exponential waiting times, so that the number in
 * a step is exact in distribution whatever the layer held in the steps
 * before (a remainder carried between steps, Bird's, biases the rate by
 * O(1/N_I) when N_I changes from step to step: +10% at N_I = 10,
 * tests/test_sim_slab.c).  A candidate is a uniform ordered pair, accepted
 * with |g|/w_I, and collides by paper A's rule with e uniform (equal in
 * distribution to the contact rule, docs/theory.md §3.2).  When a collision
 * grows R_I, the rest of the step runs at the new rate (memoryless). */
static void collisions_layer(const sim_event *e, sim_run *run, size_t lo, size_t count,
                             const double u[3], double *radius, double h)
{
    const collisions_params *p = e->params;
    gsl_rng *rng = run->rng;
    double R = *radius;
    const double pairs = (double)count * (double)(count - p->pair_offset);
    double rate = p->layer_kappa * pairs * 2.0 * R;
    for (double t = sim_rng_exponential(rng, rate); t < h; t += sim_rng_exponential(rng, rate)) {
        run->counts.candidates++;
        size_t i, j;
        sim_pick_pair_in(rng, lo, count, &i, &j);
        double *vi = run->p.v[i], *vj = run->p.v[j];
        const double g[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
        const double gnorm = sim_norm3(g);
        if (!(sim_rng_uniform(rng) * 2.0 * R < gnorm))
            continue;
        double unit[3];
        sim_rng_unit_sphere(rng, unit);
        sim_collide_inelastic(vi, vj, p->alpha, gnorm, unit);
        run->counts.collisions++;
        /* the layer's bound covers both new velocities */
        const double di[3] = {vi[0] - u[0], vi[1] - u[1], vi[2] - u[2]};
        const double dj[3] = {vj[0] - u[0], vj[1] - u[1], vj[2] - u[2]};
        const double a = fmax(sim_norm3(di), sim_norm3(dj));
        if (a > R) {
            R = a;
            rate = p->layer_kappa * pairs * 2.0 * R;
        }
    }
    *radius = R;
}

/* Covariant under a linear map of the velocities: the rate as |g|^lambda. */
static double collisions_rate_exponent(const sim_event *e)
{
    const collisions_params *p = e->params;
    return p->lambda;
}

static const sim_event_fast collisions_fast = {
    .select_fire_sums = collisions_select_fire_sums,
    .select_fire_current_sums = collisions_select_fire_current_sums,
    .select_fire_many = collisions_select_fire_many,
};

static const sim_event_stages collisions_stages = {
    .select = collisions_select_stage,
    .fires_candidates = collisions_fires_candidates,
    .layer = collisions_layer,
};

static const sim_event_type collisions_type = {
    .name = "collisions",
    .state_size = sizeof(collisions_state),
    .needs_bound = collisions_needs_bound,
    .reset = collisions_reset,
    .rate = collisions_rate,
    .select_fire = collisions_select_fire,
    .rate_exponent = collisions_rate_exponent,
    .fast = &collisions_fast,
    .stages = &collisions_stages,
};

sim_status sim_effect_collisions(const sim_scene *scene, sim_event *effect, sim_error *err)
{
    collisions_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    /* model ehs (paper E, docs/theory.md §3.3): elastic collisions at beta = (1 + alpha)/2
     * times the rate; the engine adds its drag (effect_drag.c) */
    const int ehs = scene->collisions.model == SIM_MODEL_EHS;
    const double alpha = scene->collisions.restitution;
    p->lambda = scene->collisions.exponent;
    p->alpha = ehs ? 1.0 : alpha;
    p->prefactor = 2.0 * M_PI * scene->collisions.rate * scene->collisions.constant
                   * (double)(scene->particles.n - 1) * sim_scene_collision_rate_factor(scene);
    p->contact = scene->collisions.rule == SIM_RULE_CONTACT;
    p->stage_time = p->contact ? 1.0 / (4.0 * p->prefactor) : 1.0 / p->prefactor;
    p->layer_kappa = 2.0 * M_PI * scene->collisions.rate * scene->collisions.constant
                     * sim_scene_collision_rate_factor(scene) * (double)scene->shear.layers
                     / (double)scene->particles.n;
    p->pair_offset = scene->shear.candidates == SIM_SLAB_PAIRS_PAPER ? 0 : 1;
    *effect = (sim_event){.type = &collisions_type, .params = p};
    return SIM_OK;
}
