/* The engine: scene -> effects -> the exact jump scheme (docs/theory.md §8.3) or the
 * time-step scheme (docs/theory.md §8.5).
 *
 * The jump scheme simulates the Markov jump process without time splitting
 * (paper A §3, paper B §3): candidate events arrive at rate pi_hat = Σ of the event
 * processes' majorant rates, each is fired by its process (accepted or
 * fictitious), and the one lazy flow (white-noise heating, or the homogeneous
 * shear when it is the only flow) is applied to a particle only when an event
 * touches it or at an output time.  At each output time every
 * particle is brought to that time, the observables are recorded, and the
 * majorants are recomputed from the synchronised system; the pending waiting
 * time is then redrawn, which is exact because the waiting times are
 * exponential (memoryless).  When an event process needs the velocity bound,
 * the bound is also recomputed between output times, about every
 * LAZY_REBOUND_SWEEPS n candidates, without bringing any particle: each
 * carries the flow's reach from its own stamp (lazy_reset).  With
 * scene.observation = conditional nothing is brought: T .. Pyz are the exact
 * expectations over the pending increments, from running sums the events
 * keep (observe.h, sim_sums; recomputed every REBOUND_SWEEPS n candidates).
 * The loop is chosen when the engine is built:
 *
 *  - with a lazy flow (run_jump_timed) every candidate needs its time, so
 *    the waiting times are drawn one by one, tau = -ln(U) / pi_hat;
 *
 *  - without one (run_jump_counted) no candidate needs its time, only how many
 *    fall before the next output time.  pi_hat is constant between the
 *    candidates that change it (a collision that grows the velocity bound),
 *    so the candidates of (t, t_out] are a Poisson number K of rate
 *    pi_hat (t_out - t), fired one after another without any waiting time.
 *    When candidate k of K changes the rate, its time is the k-th of K
 *    uniform points on (t, t_out], t_k = t + (t_out - t) Beta(k, K - k + 1)
 *    (the outcomes of candidates 1..k do not depend on their times); the rest
 *    of the span starts afresh from t_k at the new rate (the process is
 *    Markov and its arrival times are stopping times).  No logarithm per
 *    candidate, and a process that is alone may fire its candidates in its
 *    own loop (effect.h, fire_many).  In these runs the system is always
 *    synchronised, so every REBOUND_SWEEPS n candidates the bound is also
 *    recomputed from scratch (the same change of rate): it follows the
 *    current largest speed instead of the largest ever seen, and the
 *    majorants stay tight.
 *
 * The time-step scheme (Bird; paper C §3) advances the whole system in steps
 * of h, the largest h <= scene.dt that divides the interval between output
 * times, so output times fall on step boundaries.  A step composes the event
 * processes' stages (collisions for h) and the flow's step (free flight with
 * the thermostat) by Lie splitting, collisions then flow (paper C's order,
 * "euler", first order in h), or Strang splitting, flow h/2, collisions h,
 * flow h/2 (second order); the engine picks the step function once.  The
 * velocity bound is recomputed from scratch at each output time and grows
 * (sim_run_cover) whenever a stage moves a velocity beyond it.  When white
 * noise or the homogeneous shear is the only flow and the stages fire the
 * jump scheme's candidates (collisions.rule = relative-speed, or a kernel
 * other than hard spheres) it is lazy here too (interval_lazy), and a step
 * costs O(1) plus its collisions; a Gaussian thermostat alone is a linear
 * map kept global (stages_scaled, apply_linear), which the jump scheme also
 * runs, exactly (run_jump_linear); paper E's sheared EHS gas is both, the
 * shear lazy and the drag a global map (current_sums, lazy_linear_flow), in
 * the jump scheme too (run_jump_lazy_linear).
 *
 * The Lees-Edwards slab (shear.boundary = lees-edwards, slab.h) is the
 * time-step scheme with positions: its own ordered stages per step (streaming
 * with the wrap, the sort into layers, the layer fields, collisions within
 * layers) replace the homogeneous events and flows, and its observer takes T
 * and P against the layers' velocities; the steady observers see those
 * peculiar velocities.
 *
 * Steady-state observers (steady.h), when the scene has [steady], sample at
 * the output times t >= steady.from in either scheme, after the standard
 * observables; pair sampling uses its own random substream.
 */
#include "engine.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "effect.h"
#include "first_stage.h"
#include "rng.h"
#include "run.h"
#include "slab.h"
#include "steady.h"

#define MAX_EVENTS 4
#define MAX_FLOWS 4

/* Candidates between two recomputations of the velocity bound in runs
 * without a lazy flow, in units of n: one pass over the particles every 4 n
 * candidates (about one collision per particle) costs about 1% and keeps the
 * majorant near the current largest speed (run_jump_counted). */
#define REBOUND_SWEEPS 4

/* With a lazy flow the bound carries the flow's reach (7 sigma of white
 * noise's increment; |a| dt |V_y| for the shear) over the span until the next
 * reset (reset_bound), so a long span inflates the majorant: with resets only
 * at paper A Ex 5's output times, 1.6 apart, 12.2 candidates per hard-sphere
 * collision (split-ex5's jump rows, n = 1024).  Runs with a lazy flow and a
 * bounded process therefore also reset every LAZY_REBOUND_SWEEPS n candidates
 * or so (lazy_reset; interval_lazy in the time-step scheme): 6.8 candidates
 * per collision there.  A reset brings no particle (each keeps its own reach
 * from its stamp; about 2n square roots) and is exact anywhere, the waiting
 * times being memoryless.  Resets every 1, 2 and 4 n candidates cost the same
 * CPU time within this machine's noise. */
#define LAZY_REBOUND_SWEEPS 2

/* The largest Poisson mean drawn at once (gsl_ran_poisson returns an
 * unsigned int); a longer span is cut into pieces, which is exact because the
 * counts of disjoint spans are independent. */
#define POISSON_MAX 1e9

typedef void (*step_fn)(const sim_engine *e, sim_workspace *ws, double h);
typedef void (*stages_fn)(const sim_engine *e, sim_workspace *ws, double h);
typedef void (*flows_fn)(const sim_engine *e, sim_workspace *ws, double h);
typedef void (*interval_fn)(const sim_engine *e, sim_workspace *ws);
typedef uint64_t (*fire_some_fn)(const sim_engine *e, sim_workspace *ws, double *rates,
                                 double *total, uint64_t max);
static uint64_t fire_some_alone(const sim_engine *e, sim_workspace *ws, double *rates,
                                double *total, uint64_t max);
static uint64_t fire_some_one(const sim_engine *e, sim_workspace *ws, double *rates,
                              double *total, uint64_t max);
static uint64_t fire_some_mixed(const sim_engine *e, sim_workspace *ws, double *rates,
                                double *total, uint64_t max);

struct sim_engine {
    sim_scene scene;
    double mass;          /* the grain mass */
    char effects[64];
    size_t nflows;        /* the flows in the order a step applies them: shear, the EHS
                             drag, then a thermostat or the heat-flux force */
    sim_effect flows[MAX_FLOWS];
    int lazy_flow;        /* flows[0] is applied lazily (stamps): white noise */
    int linear;           /* flows[0] is a linear map kept global (run->scale) */
    double rate_exponent; /* ... the collisions' lambda: their rate scales as scale^lambda */
    int stage_sums;       /* ... its factor reads run->sums: the stages keep them (then sums) */
    int current_sums;     /* ... and flows[0] is also lazy (the sheared EHS drag): the sums
                             are of the velocities at the stages' time (effect.h,
                             advance_sums), not of the stored ones */
    int conditional;      /* scene.observation = conditional: T .. Pyz as expectations
                             over the lazy flow's pending increments, which are never
                             drawn at output times (observe.h, sim_observe_sums) */
    double pending_spread;/* ... the lazy flow's variance per unit time, or 0 */
    int sums;             /* ... from running sums the events keep (else a pass) */
    int bounded;          /* some event needs the velocity bound (run.h) */
    int lazy_rebound;     /* ... and a lazy flow: reset between output times too */
    int fixed_centre;     /* ... centred at `centre`, else at the bulk velocity */
    double centre[3];
    size_t nevents;
    sim_effect events[MAX_EVENTS];
    sim_event_fire_fn fire[MAX_EVENTS];
    size_t state_offset[MAX_EVENTS];
    size_t state_bytes;
    /* jump scheme without a lazy flow (run_jump_counted) */
    fire_some_fn fire_some;            /* the candidates of a span, up to a change of rate */
    sim_event_fire_many_fn fire_many;  /* the only process's own loop, or NULL */
    uint64_t rebound_every;            /* candidates between bound recomputations */
    /* time-step scheme */
    sim_event_stage_fn stage[MAX_EVENTS];
    step_fn step;         /* Lie (euler) step, or collisions only */
    stages_fn stages;     /* the stages of a step (scaled by a linear flow's factor) */
    flows_fn flow_step;   /* the flows of a step (or the linear flow's factor) */
    interval_fn interval; /* one output interval of steps */
    size_t steps;         /* steps per output interval */
    double h;             /* the step */
    size_t observables;   /* per output row (sim_engine_observables) */
    sim_slab_params *slab;/* the Lees-Edwards slab (slab.h), or NULL */
    /* steady-state observers */
    size_t nsteady;
    size_t steady_from;   /* first output index with t >= steady.from */
};

struct sim_workspace {
    sim_run run;
    unsigned char *states;   /* the event processes' per-run states */
    gsl_rng *observer_rng;   /* pair sampling (shear and steady observers), or NULL */
    sim_slab *slab;          /* the slab's layers and buffers, or NULL */
    double *steady_sum;      /* [nsteady] sums of the samples of the current run */
    size_t samples;          /* how many samples those sums hold */
    size_t steps;            /* time-step scheme: steps in the current output interval */
    double h;                /* ... and their length */
    double t0;               /* ... and its start */
    double rates[MAX_EVENTS];/* ... with a lazy flow: the processes' majorant rates */
    double credit[MAX_EVENTS];/* ... and the stage time they have not spent */
    int time_outputs;        /* add the time of output times to output_seconds */
    double output_seconds;
};

static void append_name(sim_engine *e, const char *name)
{
    size_t len = strlen(e->effects);
    snprintf(e->effects + len, sizeof e->effects - len, "%s%s", len ? " " : "", name);
}

static void add_flow(sim_engine *e, sim_effect effect)
{
    e->flows[e->nflows++] = effect;
    append_name(e, effect.type->name);
}

static void add_event(sim_engine *e, sim_effect effect)
{
    e->events[e->nevents] = effect;
    e->state_offset[e->nevents] = e->state_bytes;
    /* keep every state block aligned for doubles */
    e->state_bytes += (effect.type->state_size + 15) & ~(size_t)15;
    e->nevents++;
    append_name(e, effect.type->name);
}

static void stage_fired(const sim_engine *e, sim_workspace *ws, size_t k, double h, double t);
static double lazy_candidates(const sim_engine *e);
static double reset_events(const sim_engine *e, sim_workspace *ws, double rates[MAX_EVENTS],
                           double t, double horizon);

/* The time-step scheme's steps: stages and the flow's step composed.  A
 * process without a stage of its own fires its candidates (stage_fired; no
 * lazy flow here, so their time does not matter). */
static void stages(const sim_engine *e, sim_workspace *ws, double h)
{
    for (size_t k = 0; k < e->nevents; k++) {
        if (e->stage[k])
            e->stage[k](&e->events[k], &ws->run, ws->states + e->state_offset[k], h);
        else
            stage_fired(e, ws, k, h, 0.0);
    }
}

/* Every flow's step of length h, in order. */
static void flow_steps(const sim_engine *e, sim_workspace *ws, double h)
{
    for (size_t k = 0; k < e->nflows; k++)
        e->flows[k].type->step(&e->flows[k], &ws->run, h);
}

/* With a linear flow kept global (effect.h, linear_factor): the stored
 * velocities w stand for o + scale (w - o), and a collision rule is covariant
 * under that map (collide.h: translation and scaling commute with it), so the
 * stages act on w; only the rate scales, as |g|^lambda, so a stage of h at the
 * true velocities is one of h scale^lambda at the stored ones.  O(1) per step;
 * the map is applied to every particle at output times (apply_linear). */
static double scaled_stage(const sim_engine *e, const sim_workspace *ws, double h)
{
    const double s = ws->run.scale, lambda = e->rate_exponent;
    return h * (lambda == 1.0 ? s : lambda == 0.0 ? 1.0 : pow(s, lambda));
}

static void stages_scaled(const sim_engine *e, sim_workspace *ws, double h)
{
    stages(e, ws, scaled_stage(e, ws, h));
}

static void linear_step(const sim_engine *e, sim_workspace *ws, double h)
{
    ws->run.scale *= e->flows[0].type->linear_factor(&e->flows[0], &ws->run, h);
}

static void step_euler(const sim_engine *e, sim_workspace *ws, double h)
{
    e->stages(e, ws, h);
    e->flow_step(e, ws, h);
}

static void step_no_flow(const sim_engine *e, sim_workspace *ws, double h)
{
    stages(e, ws, h);
}

/* One output interval of ws->steps steps of ws->h. */
static void interval_lie(const sim_engine *e, sim_workspace *ws)
{
    for (size_t k = 0; k < ws->steps; k++)
        e->step(e, ws, ws->h);
}

/* A stage of length h of event process k made of the jump scheme's
 * candidates, all at time t (each brings the particles it draws to t):
 * floor(credit x rate) of them at the process's majorant rate, the remainder
 * kept for the next stage, as the other stages do; when a candidate changes
 * the rate (a collision grows the bound) the stage time left is spent at the
 * new rate. */
static void stage_fired(const sim_engine *e, sim_workspace *ws, size_t k, double h, double t)
{
    void *state = ws->states + e->state_offset[k];
    double credit = ws->credit[k] + h, rate = ws->rates[k];
    for (;;) {
        if (!(rate > 0.0)) {   /* every velocity equal: no collision can happen */
            credit = 0.0;
            break;
        }
        const double count = floor(credit * rate);
        if (!(count >= 1.0))
            break;
        double after = rate;
        uint64_t done = 0;
        while (done < (uint64_t)count && after == rate) {
            done++;
            after = e->fire[k](&e->events[k], &ws->run, state, t);
        }
        credit -= (double)done / rate;
        rate = after;
        if (done == (uint64_t)count)
            break;
    }
    ws->credit[k] = fmax(credit, 0.0);
    ws->rates[k] = rate;
}

/* The sheared EHS drag's flow over dt with the shear lazy (current_sums):
 * the sums sheared to the end of the flow, then the drag's global factor
 * from the temperature they give. */
static void lazy_linear_flow(const sim_engine *e, sim_workspace *ws, double dt)
{
    const sim_effect *f = &e->flows[0];
    f->type->advance_sums(f, &ws->run.sums, dt);
    ws->run.scale *= f->type->linear_factor(f, &ws->run, dt);
}

/* The time-step scheme with a lazy flow (white noise, the shear; effect.h):
 * the flow's steps only move the clock, and step k's stages fire at t0 + (k +
 * theta) h, theta = 0 for Lie splitting (collisions, then the flow) and 1/2
 * for Strang (half the flow, collisions, half the flow): each particle a stage
 * draws is brought to that time, so the same increments are drawn, in law, as
 * by stepping every particle (Gaussian increments over adjoining times add;
 * shears compose).  With current_sums the flow also carries a global linear
 * map (the EHS drag), applied where interval_lie and interval_strang apply
 * the flow's step, and the stages run at the rate scaled by it, as
 * stages_scaled. */
static void interval_lazy(const sim_engine *e, sim_workspace *ws)
{
    const int strang = e->scene.splitting == SIM_SPLIT_STRANG;
    const double theta = strang ? 0.5 : 0.0;
    size_t next_reset = e->lazy_rebound ? 0 : ws->steps;
    if (e->current_sums && strang)
        lazy_linear_flow(e, ws, 0.5 * ws->h);
    for (size_t k = 0; k < ws->steps; k++) {
        const double stage = scaled_stage(e, ws, ws->h);
        if (k == next_reset) {   /* lazy_rebound: a reset for the stages of `span`
                                    steps, about lazy_candidates(e) candidates */
            double total = 0.0;
            for (size_t q = 0; q < e->nevents; q++)
                total += ws->rates[q];
            const double steps = floor(lazy_candidates(e) / (total * stage));
            const size_t left = ws->steps - k;
            const size_t span = !(steps >= 1.0) ? 1 : steps < (double)left ? (size_t)steps : left;
            /* the span's stages fire at t0 + (k + theta) h ... t0 + (k + span - 1
             * + theta) h: the reach is needed that far, not to the span's end */
            reset_events(e, ws, ws->rates, ws->t0 + (double)k * ws->h,
                         ((double)span - 1.0 + theta) * ws->h);
            next_reset = k + span;
        }
        for (size_t q = 0; q < e->nevents; q++)
            stage_fired(e, ws, q, stage, ws->t0 + ((double)k + theta) * ws->h);
        if (e->current_sums)
            lazy_linear_flow(e, ws, strang && k + 1 == ws->steps ? 0.5 * ws->h : ws->h);
    }
}

/* Strang: flow h/2, collisions h, flow h/2 per step, with the two half flows
 * of adjacent steps merged into one flow of h (as in leapfrog): exact in
 * distribution for white noise (Gaussian increments add) and for the Gaussian
 * thermostat (scalings multiply), so Strang costs one flow per step like
 * Euler.  For the non-Gaussian flow the merged step differs from two half
 * steps by O(h^2 |k|), k = the mean direction (about 0 in an isotropic gas);
 * the keep-T rescaling is a projection, for which Strang and Euler coincide.
 * Several flows are applied in order in each (merged) half: for flows that do
 * not commute (shear and drag) that is a splitting of its own, O(h^2) per step.
 * The output times see whole steps. */
static void interval_strang(const sim_engine *e, sim_workspace *ws)
{
    const double h = ws->h;
    e->flow_step(e, ws, 0.5 * h);
    for (size_t k = 1; k < ws->steps; k++) {
        e->stages(e, ws, h);
        e->flow_step(e, ws, h);
    }
    e->stages(e, ws, h);
    e->flow_step(e, ws, 0.5 * h);
}

/* One output interval of the Lees-Edwards slab: its own ordered stages per
 * step (slab.h) instead of the homogeneous events and flows. */
static void interval_slab(const sim_engine *e, sim_workspace *ws)
{
    for (size_t k = 0; k < ws->steps; k++)
        sim_slab_step(e->slab, ws->slab, &ws->run, ws->h);
}

/* Resolve the time-step scheme: stages, the step function, h. */
static sim_status build_timestep(sim_engine *e, sim_error *err)
{
    const sim_scene *scene = &e->scene;
    for (size_t k = 0; k < e->nevents; k++) {
        const sim_effect *ev = &e->events[k];
        e->stage[k] = ev->type->select_stage ? ev->type->select_stage(ev, e->stage_sums) : NULL;
    }
    for (size_t k = 0; k < e->nflows; k++)
        if (e->flows[k].type->step == NULL)
            return sim_error_set(err, SIM_EUNSUPPORTED, e->flows[k].type->name,
                                 "%s has no time-step form", e->flows[k].type->name);
    e->stages = e->linear ? stages_scaled : stages;
    e->flow_step = e->linear ? linear_step : flow_steps;
    e->step = e->nflows ? step_euler : step_no_flow;
    e->interval = e->lazy_flow ? interval_lazy
                  : e->nflows && scene->splitting == SIM_SPLIT_STRANG ? interval_strang
                                                                      : interval_lie;
    if (!(scene->dt > 0.0) || !isfinite(scene->dt))
        return sim_error_set(err, SIM_EINVAL, "scene.dt", "%g is not a positive step",
                             scene->dt);
    const double interval = sim_scene_output_time(scene, 1);
    double steps = ceil(interval / scene->dt * (1.0 - 1e-9));
    if (steps < 1.0)
        steps = 1.0;
    if (steps > 1e12)
        return sim_error_set(err, SIM_EINVAL, "scene.dt",
                             "%g gives %.3g steps between output times (allowed at most 1e12)",
                             scene->dt, steps);
    e->steps = (size_t)steps;
    e->h = interval / steps;
    return SIM_OK;
}

sim_status sim_engine_create(const sim_scene *scene, sim_engine **engine, sim_error *err)
{
    *engine = NULL;
    const int timestep = scene->scheme == SIM_SCHEME_TIMESTEP;
    if (timestep && scene->background.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "background",
                             "the background is not implemented in the time-step scheme "
                             "(supported: jump)");
    if (scene->particles.initial == SIM_INITIAL_TWO_MAXWELLIANS
        && scene->particles.first.mass != scene->particles.second.mass)
        return sim_error_set(err, SIM_EUNSUPPORTED, "particles.mass2",
                             "the engine simulates one species: mass2 = %g must equal "
                             "mass1 = %g", scene->particles.second.mass,
                             scene->particles.first.mass);
    if (scene->particles.n < 2 || scene->outputs < 2 || !(scene->t_end > 0.0))
        return sim_error_set(err, SIM_EINVAL, "",
                             "scene not validated: n = %zu, outputs = %zu, t_end = %g",
                             scene->particles.n, scene->outputs, scene->t_end);
    if (scene->particles.n > SIM_PARTICLES_MAX)
        return sim_error_set(err, SIM_EINVAL, "particles.n", "%zu is out of range (allowed "
                             "n <= %lu)", scene->particles.n,
                             (unsigned long)SIM_PARTICLES_MAX);

    sim_engine *e = calloc(1, sizeof *e);
    if (e == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    e->scene = *scene;
    e->mass = sim_scene_grain_mass(scene);
    e->observables = sim_observe_row_length(scene);

    sim_status status = SIM_OK;
    const int slab = scene->shear.present && scene->shear.boundary == SIM_SHEAR_LEES_EDWARDS;
    if (slab && (status = sim_slab_params_create(&e->scene, &e->slab, err)) == SIM_OK)
        append_name(e, sim_slab_effects(e->slab));
    if (status == SIM_OK && !slab && scene->collisions.present) {
        sim_effect collisions;
        status = sim_effect_collisions(scene, &collisions, err);
        if (status == SIM_OK)
            add_event(e, collisions);
    }
    if (status == SIM_OK && scene->background.present) {
        sim_effect background;
        status = sim_effect_background(scene, &background, err);
        if (status == SIM_OK)
            add_event(e, background);
    }
    /* the flows, in the order of a step */
    sim_effect flow;
    const int ehs_drag = !slab && scene->collisions.present
                         && scene->collisions.model == SIM_MODEL_EHS
                         && scene->collisions.restitution < 1.0;   /* elastic: no drag */
    const int shear = !slab && scene->shear.present;
    /* both in one pass per step, reading running sums, when no other flow
     * moves the particles behind the sums' back */
    const int fused = shear && ehs_drag && !scene->heating.present && !scene->heat_flux.present;
    if (status == SIM_OK && fused
        && (status = sim_effect_sheared_ehs_drag(scene, &flow, err)) == SIM_OK)
        add_flow(e, flow);
    if (status == SIM_OK && shear && !fused
        && (status = sim_effect_shear(scene, &flow, err)) == SIM_OK)
        add_flow(e, flow);
    if (status == SIM_OK && ehs_drag && !fused
        && (status = sim_effect_ehs_drag(scene, &flow, err)) == SIM_OK)
        add_flow(e, flow);
    if (status == SIM_OK && scene->heating.present
        && (status = sim_effect_heating(scene, &flow, err)) == SIM_OK)
        add_flow(e, flow);
    if (status == SIM_OK && scene->heat_flux.present   /* refuses [heating] */
        && (status = sim_effect_heat_flux(scene, &flow, err)) == SIM_OK)
        add_flow(e, flow);
    /* White noise and the homogeneous shear are lazy, and a Gaussian
     * thermostat a global linear map, when it is the only flow: always in the
     * jump scheme; in the time-step scheme
     * when the stage fires the jump scheme's candidates (not by the contact
     * rule, which the batched stage draws without bringing particles) and
     * the background and the slab are absent (the heating constructor
     * refuses the other thermostats in the jump scheme).  The sheared EHS
     * drag is both: the shear lazy, the drag a global map, with running sums
     * at the stages' or candidates' time (current_sums). */
    const int hard_contact = scene->collisions.present && scene->collisions.exponent == 1.0
                             && scene->collisions.rule == SIM_RULE_CONTACT;
    if (status == SIM_OK && e->nflows == 1 && (scene->heating.present || scene->shear.present)
        && !slab) {
        const sim_effect_type *type = e->flows[0].type;
        e->lazy_flow = type->advance != NULL && (!timestep || !hard_contact);
        e->linear = type->linear_factor != NULL && e->nevents == 1 && scene->collisions.present
                    && (type->advance == NULL
                        || (e->lazy_flow && type->advance_sums != NULL
                            && (timestep || type->scale_after != NULL)));
        e->current_sums = e->lazy_flow && e->linear;
        e->rate_exponent = scene->collisions.exponent;
        e->stage_sums = e->linear && type->linear_reads_sums;
    }
    if (status == SIM_OK && e->nflows == 1 && e->flows[0].type->step_reads_sums)
        e->stage_sums = 1;
    /* with no event process either: a flow that is neither lazy nor global would
     * never be applied (a Gaussian thermostat alone left T unchanged) */
    if (status == SIM_OK && !timestep && e->nflows > 0 && !e->lazy_flow && !e->linear)
        status = sim_error_set(err, SIM_EUNSUPPORTED,
                               scene->heating.present ? "heating.type" : "scene.scheme",
                               "the jump scheme applies a flow only lazily (white noise, or "
                               "[shear] alone) or as one global map with binary collisions "
                               "(gaussian, without [background])");
    if (status == SIM_OK && scene->observation == SIM_OBSERVE_CONDITIONAL) {
        if (timestep || scene->steady.present || scene->shear.present
            || (e->nflows > 0 && (!e->lazy_flow || e->flows[0].type->spread == NULL)))
            status = sim_error_set(err, SIM_EUNSUPPORTED, "scene.observation",
                                   "conditional needs scheme = jump, at most white-noise "
                                   "heating, and no [steady] or [shear] (they observe every "
                                   "particle)");
        else
            e->pending_spread = e->lazy_flow ? e->flows[0].type->spread(&e->flows[0]) : 0.0;
        e->conditional = status == SIM_OK;
    }
    if (status == SIM_OK && scene->observe_only != 0) {
        const uint32_t only = scene->observe_only;
        if (only & ~SIM_OBS_ALL_BASE)
            status = sim_error_set(err, SIM_EINVAL, "scene.observe_only",
                                   "0x%" PRIx32 " names observables beyond the base set", only);
        else if (scene->shear.present)
            status = sim_error_set(err, SIM_EUNSUPPORTED, "scene.observe_only",
                                   "[shear] computes its observables from every base one");
        else if (scene->step_follows_temperature && !(only & SIM_OBS_BIT(SIM_OBS_T)))
            status = sim_error_set(err, SIM_EINVAL, "scene.observe_only",
                                   "step_follows_temperature needs T");
    }
    if (status == SIM_OK && timestep)
        status = build_timestep(e, err);
    if (status == SIM_OK && slab)
        e->interval = interval_slab;
    if (status == SIM_OK && scene->steady.present) {
        e->nsteady = sim_steady_count(scene);
        /* the first output time >= from, in O(1) (outputs may be large) */
        double first = ceil(scene->steady.from * (double)(scene->outputs - 1) / scene->t_end);
        size_t m = first <= 0.0 ? 0 : first >= (double)scene->outputs ? scene->outputs
                                                                        : (size_t)first;
        while (m > 0 && sim_scene_output_time(scene, m - 1) >= scene->steady.from)
            m--;
        while (m < scene->outputs && sim_scene_output_time(scene, m) < scene->steady.from)
            m++;
        e->steady_from = m;
        if (scene->steady.bins > 0 && !(scene->steady.c_max > 0.0))
            status = sim_error_set(err, SIM_EINVAL, "steady.c_max", "%g is not positive",
                                   scene->steady.c_max);
        if (e->steady_from == scene->outputs)
            status = sim_error_set(err, SIM_EINVAL, "steady.from",
                                   "%g is after the last output time %g",
                                   scene->steady.from, scene->t_end);
    }
    if (status != SIM_OK) {
        sim_engine_free(e);
        return status;
    }
    for (size_t k = 0; k < e->nevents; k++) {
        const sim_effect *ev = &e->events[k];
        e->bounded |= ev->type->needs_bound(ev);
        if (ev->type->bound_centre && ev->type->bound_centre(ev, e->centre))
            e->fixed_centre = 1;
    }
    /* running sums where every event process keeps them: for conditional
     * observation, and for the keep-temperature rescaling (run_jump_linear,
     * linear_step), which needs them */
    const int linear_sums = e->stage_sums;
    e->sums = e->conditional || linear_sums;
    for (size_t k = 0; k < e->nevents; k++) {
        const sim_effect *ev = &e->events[k];
        if (e->current_sums)
            e->fire[k] = ev->type->select_fire_current_sums
                             ? ev->type->select_fire_current_sums(ev) : NULL;
        else
            e->fire[k] = ev->type->select_fire_sums
                             ? ev->type->select_fire_sums(ev, e->lazy_flow, e->bounded) : NULL;
        e->sums &= e->fire[k] != NULL;
    }
    for (size_t k = 0; k < e->nevents; k++)
        if (!e->sums)
            e->fire[k] = e->events[k].type->select_fire(&e->events[k], e->lazy_flow,
                                                         e->bounded);
    if (linear_sums && !e->sums) {
        const int current = e->current_sums;
        sim_engine_free(e);
        if (current)   /* the constructors make this unreachable: ehs is hard spheres */
            return sim_error_set(err, SIM_EUNSUPPORTED, "collisions.kernel",
                                 "the sheared ehs drag needs hard spheres");
        return sim_error_set(err, SIM_EUNSUPPORTED, "heating.keep_temperature",
                             "the keep-temperature rescaling needs collisions that keep "
                             "running sums (supported: maxwell, vhs, hard-spheres)");
    }
    if (e->nevents == 1 && !e->sums && e->events[0].type->select_fire_many)
        e->fire_many = e->events[0].type->select_fire_many(&e->events[0]);
    e->fire_some = e->fire_many ? fire_some_alone : e->nevents == 1 ? fire_some_one
                                                                    : fire_some_mixed;
    e->lazy_rebound = e->bounded && e->lazy_flow;
    e->rebound_every = (e->bounded && !e->lazy_flow) || e->sums
                           ? REBOUND_SWEEPS * (uint64_t)scene->particles.n : UINT64_MAX;
    *engine = e;
    return SIM_OK;
}

void sim_engine_free(sim_engine *engine)
{
    if (engine == NULL)
        return;
    for (size_t k = 0; k < engine->nevents; k++)
        free(engine->events[k].params);
    for (size_t k = 0; k < engine->nflows; k++)
        free(engine->flows[k].params);
    sim_slab_params_free(engine->slab);
    free(engine);
}

const sim_scene *sim_engine_scene(const sim_engine *engine) { return &engine->scene; }

const char *sim_engine_effects(const sim_engine *engine) { return engine->effects; }

size_t sim_engine_steady_count(const sim_engine *engine) { return engine->nsteady; }

size_t sim_engine_observables(const sim_engine *engine) { return engine->observables; }

size_t sim_engine_workspace_bytes(const sim_engine *engine)
{
    return engine->scene.particles.n * sim_particles_bytes_per_particle(engine->lazy_flow)
           + engine->state_bytes + engine->nsteady * sizeof(double) + sizeof(sim_workspace)
           + (engine->slab ? sim_slab_bytes(engine->slab, engine->scene.particles.n) : 0);
}

double sim_engine_step(const sim_engine *engine)
{
    return engine->scene.scheme == SIM_SCHEME_TIMESTEP ? engine->h : 0.0;
}

sim_status sim_workspace_create(const sim_engine *engine, sim_workspace **ws, sim_error *err)
{
    *ws = NULL;
    sim_workspace *w = calloc(1, sizeof *w);
    if (w == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    sim_status status = sim_particles_alloc(&w->run.p, engine->scene.particles.n,
                                            engine->lazy_flow, err);
    if (status == SIM_OK) {
        w->run.rng = sim_rng_alloc();
        w->states = calloc(1, engine->state_bytes + 16);
        if (w->run.rng == NULL || w->states == NULL)
            status = sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    }
    if (status == SIM_OK && engine->slab)
        status = sim_slab_create(engine->slab, &w->run.p, &w->slab, err);
    if (status == SIM_OK && engine->nsteady > 0
        && (w->steady_sum = calloc(engine->nsteady, sizeof *w->steady_sum)) == NULL)
        status = sim_error_set(err, SIM_ENOMEM, "steady", "out of memory");
    const int pairs = (engine->nsteady > 0 && engine->scene.steady.pairs > 0)
                      || (engine->scene.shear.present && engine->scene.shear.pairs > 0);
    if (status == SIM_OK && pairs && (w->observer_rng = sim_rng_alloc()) == NULL)
        status = sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    if (status != SIM_OK) {
        sim_workspace_free(w);
        return status;
    }
    w->run.flow = engine->lazy_flow ? &engine->flows[0] : NULL;
    *ws = w;
    return SIM_OK;
}

const sim_particles *sim_workspace_particles(const sim_workspace *ws) { return &ws->run.p; }

void sim_workspace_time_outputs(sim_workspace *ws, int on)
{
    ws->time_outputs = on;
    ws->output_seconds = 0.0;
}

double sim_workspace_output_seconds(const sim_workspace *ws) { return ws->output_seconds; }

void sim_workspace_free(sim_workspace *ws)
{
    if (ws == NULL)
        return;
    sim_particles_free(&ws->run.p);
    if (ws->run.rng)
        gsl_rng_free(ws->run.rng);
    if (ws->observer_rng)
        gsl_rng_free(ws->observer_rng);
    free(ws->steady_sum);
    free(ws->states);
    sim_slab_free(ws->slab);
    free(ws);
}

/* The velocity bound of run.h at time t: centre c (fixed, or the bulk
 * velocity), R = max |v_i - c| plus, with a lazy flow, each particle's reach
 * over t + horizon - stamp_i (the system is synchronised only at sampled
 * output times, where this is the reach over the horizon); R = +inf (no
 * bound) when no event needs one. */
static void reset_bound(const sim_engine *e, sim_run *run, double t, double horizon)
{
    const size_t n = run->p.n;
    run->bound_grew = 0;
    if (!e->bounded) {
        run->radius = INFINITY;
        return;
    }
    double c[3] = {0, 0, 0}, r2 = 0.0;
    if (e->fixed_centre) {
        memcpy(c, e->centre, sizeof c);
    } else {
        for (size_t i = 0; i < n; i++)
            for (int k = 0; k < 3; k++)
                c[k] += run->p.v[i][k];
        for (int k = 0; k < 3; k++)
            c[k] /= (double)n;
    }
    memcpy(run->centre, c, sizeof c);
    if (run->flow) {
        const sim_effect *f = run->flow;
        double r = 0.0;
        for (size_t i = 0; i < n; i++) {
            const double dt = t + horizon - run->p.stamp[i];
            double a = sqrt(sim_dist2(run->p.v[i], c)) + f->type->reach(f, dt);
            if (f->type->reach_vy)   /* the shear: V_y stays */
                a += f->type->reach_vy(f, dt) * fabs(run->p.v[i][1]);
            r = a > r ? a : r;
        }
        run->radius = r;
        return;
    }
    for (size_t i = 0; i < n; i++) {
        double d[3] = {run->p.v[i][0] - c[0], run->p.v[i][1] - c[1], run->p.v[i][2] - c[2]};
        const double x = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        r2 = x > r2 ? x : r2;   /* not fmax: a library call on baseline x86-64 */
    }
    run->radius = sqrt(r2);
}

/* Recompute the bound and every event process's majorant; return their total
 * rate. */
static double reset_events(const sim_engine *e, sim_workspace *ws, double rates[MAX_EVENTS],
                           double t, double horizon)
{
    reset_bound(e, &ws->run, t, horizon);
    double total = 0.0;
    for (size_t k = 0; k < e->nevents; k++) {
        rates[k] = e->events[k].type->reset(&e->events[k], &ws->run,
                                            ws->states + e->state_offset[k], horizon);
        total += rates[k];
    }
    return total;
}

/* Runs without a lazy flow, between output times: R = max |v_i - c| from
 * scratch about the same centre (binary collisions keep the bulk velocity,
 * and a fixed centre stays), and every process's rate for it; returns the
 * total.  One pass over the particles, no reset of the processes.  The
 * running sums, when kept, are recomputed in the same pass's place. */
static double rebound(const sim_engine *e, sim_workspace *ws, double rates[MAX_EVENTS])
{
    sim_run *run = &ws->run;
    if (e->sums)
        sim_sums_compute(&run->p, &run->sums);
    if (!e->bounded) {
        double total = 0.0;
        for (size_t k = 0; k < e->nevents; k++)
            total += rates[k];
        return total;
    }
    const double *c = run->centre;
    double r2 = 0.0;
    for (size_t i = 0; i < run->p.n; i++) {
        const double *v = run->p.v[i];
        const double d[3] = {v[0] - c[0], v[1] - c[1], v[2] - c[2]};
        const double x = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        r2 = x > r2 ? x : r2;
    }
    run->radius = sqrt(r2);
    run->bound_grew = 0;
    double total = 0.0;
    for (size_t k = 0; k < e->nevents; k++) {
        rates[k] = e->events[k].type->rate(&e->events[k], run, ws->states + e->state_offset[k]);
        total += rates[k];
    }
    return total;
}

/* The total rate after process `fired` returned its rate; if it grew the
 * bound, the other processes' majorants grow too. */
static double update_rates(const sim_engine *e, sim_workspace *ws, double *rates, size_t fired)
{
    sim_run *run = &ws->run;
    if (run->bound_grew) {
        run->bound_grew = 0;
        for (size_t k = 0; k < e->nevents; k++)
            if (k != fired)
                rates[k] = e->events[k].type->rate(&e->events[k], run,
                                                   ws->states + e->state_offset[k]);
    }
    double total = 0.0;
    for (size_t k = 0; k < e->nevents; k++)
        total += rates[k];
    return total;
}

/* The event process that fires: k with probability rates[k] / total. */
static size_t pick_event(const sim_engine *e, gsl_rng *rng, const double *rates, double total)
{
    double x = sim_rng_uniform(rng) * total;
    size_t k = 0;
    while (k + 1 < e->nevents && x >= rates[k]) {
        x -= rates[k];
        k++;
    }
    return k;
}

/* Bring every particle to time t with the lazy flow (paper A's sampled
 * observation: the pending increments are drawn). */
static void bring_all(sim_run *run, double t)
{
    for (size_t i = 0; i < run->p.n; i++)
        sim_run_bring(run, i, t);
}

/* Output time m: the standard observables (with [shear], paper E's after
 * them), and a steady sample if t_m >= from. */
static void observe_at(const sim_engine *e, sim_workspace *ws, size_t m, double *obs,
                       size_t *samples)
{
    double *row = obs + m * e->observables;
    const double *prev = m > 0 ? row - e->observables : NULL;
    const sim_particles *observed = &ws->run.p;
    if (e->slab) {   /* against the layers' velocities (slab.h) */
        sim_slab_observe(e->slab, ws->slab, &ws->run, m, prev, ws->observer_rng, row);
        observed = sim_slab_peculiar(ws->slab);
    } else if (e->conditional) {   /* no pass over the particles with sums */
        sim_sums pass;
        const sim_sums *sums = &ws->run.sums;
        if (!e->sums) {
            sim_sums_compute(&ws->run.p, &pass);
            sums = &pass;
        }
        sim_observe_sums(sums, ws->run.p.n, e->mass, sim_scene_output_time(&e->scene, m),
                         e->pending_spread, row);
        sim_observe_drop(e->scene.observe_only, row);
    } else {
        sim_observe_only(&ws->run.p, e->mass, e->scene.observe_only, row);
        if (e->scene.shear.present)
            sim_observe_shear(&e->scene, &ws->run.p, e->mass, ws->run.counts.collisions, m,
                              prev, ws->observer_rng, row);
    }
    if (e->nsteady > 0 && m >= e->steady_from) {
        sim_steady_sample(&e->scene, observed, e->mass, ws->observer_rng, row,
                          ws->steady_sum);
        (*samples)++;
    }
}

/* A monotonic clock, not the thread's CPU clock: that is a system call of
 * about 1.2 us on this project's VMs (vDSO reads of the monotonic clock take
 * 30 ns), and brs-ex2's 513 output times would pay it twice each, about 45
 * ns per collision, more than the observation itself.  The bench runs the
 * engine on one thread, so over one output time the two agree but for
 * preemption. */
static double clock_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Output time m at time t after the events: paper A's sampled observation
 * first draws every particle's pending increment of a lazy flow; then the
 * observables.  With ws->time_outputs, its time is added to
 * ws->output_seconds (the bench's breakdown; two clock reads per output). */
static void observe_output(const sim_engine *e, sim_workspace *ws, size_t m, double t,
                           double *obs, size_t *samples)
{
    const double start = ws->time_outputs ? clock_seconds() : 0.0;
    if (e->lazy_flow && !e->conditional)
        bring_all(&ws->run, t);
    observe_at(e, ws, m, obs, samples);
    if (ws->time_outputs)
        ws->output_seconds += clock_seconds() - start;
}

/* The candidates between two resets of a lazy_rebound run; and its reset at
 * time t (the output time at t_out, or earlier): the bound and the
 * majorants for a span of that many candidates at the current total rate, at
 * most to t_out; returns the new total and sets *t_span to the span's end. */
static double lazy_candidates(const sim_engine *e)
{
    return LAZY_REBOUND_SWEEPS * (double)e->scene.particles.n;
}

static double lazy_reset(const sim_engine *e, sim_workspace *ws, double rates[MAX_EVENTS],
                         double total, double t, double t_out, double *t_span)
{
    const double left = t_out - t;
    double span = lazy_candidates(e) / total;
    if (!(span < left))
        span = left;
    *t_span = span < left ? t + span : t_out;
    return reset_events(e, ws, rates, t, span);
}

/* The exact jump scheme from t = 0 to t_end (the initial state is sampled),
 * with a lazy flow: every candidate gets its waiting time. */
static void run_jump_timed(const sim_engine *e, sim_workspace *ws, double *obs, size_t *samples)
{
    const sim_scene *scene = &e->scene;
    sim_run *run = &ws->run;
    gsl_rng *rng = run->rng;

    const double interval = sim_scene_output_time(scene, 1);   /* between resets */
    double rates[MAX_EVENTS] = {0};
    double t = 0.0;
    double total = reset_events(e, ws, rates, t, interval);
    uint64_t until_resum = e->rebound_every;   /* the running sums' recomputation */
    for (size_t m = 1; m < scene->outputs; m++) {
        const double t_out = sim_scene_output_time(scene, m);
        double t_span = t_out;   /* the end of the span the bound covers */
        if (e->lazy_rebound)
            total = lazy_reset(e, ws, rates, total, t, t_out, &t_span);
        for (;;) {
            double t_next = total > 0.0 ? t + sim_rng_exponential(rng, total) : INFINITY;
            if (t_next >= t_span) {
                if (t_span >= t_out)
                    break;
                t = t_span;   /* only with lazy_rebound */
                total = lazy_reset(e, ws, rates, total, t, t_out, &t_span);
                continue;
            }
            t = t_next;
            size_t k = e->nevents == 1 ? 0 : pick_event(e, rng, rates, total);
            rates[k] = e->fire[k](&e->events[k], run, ws->states + e->state_offset[k], t);
            total = e->nevents == 1 ? rates[0] : update_rates(e, ws, rates, k);
            if (--until_resum == 0) {   /* only with sums (else 2^64 candidates away) */
                sim_sums_compute(&run->p, &run->sums);
                until_resum = e->rebound_every;
            }
        }
        t = t_out;
        observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs && !e->lazy_rebound)   /* else at the loop's top */
            total = reset_events(e, ws, rates, t, interval);
    }
}

/* fire_some_fn: up to `max` candidates of the jump scheme without a lazy flow
 * (no times: the fire functions use t only to bring particles forward),
 * stopping after the first that changes the total rate; returns how many.
 * One instance per engine shape, chosen when the engine is built. */

/* The only process, in its own loop. */
static uint64_t fire_some_alone(const sim_engine *e, sim_workspace *ws, double *rates,
                                double *total, uint64_t max)
{
    const uint64_t fired = e->fire_many(&e->events[0], &ws->run, ws->states, max, &rates[0]);
    *total = rates[0];
    return fired;
}

/* The only process, one candidate per call. */
static uint64_t fire_some_one(const sim_engine *e, sim_workspace *ws, double *rates,
                              double *total, uint64_t max)
{
    const double before = *total;
    for (uint64_t c = 1; c <= max; c++) {
        rates[0] = e->fire[0](&e->events[0], &ws->run, ws->states, 0.0);
        if (rates[0] != before) {
            *total = rates[0];
            return c;
        }
    }
    return max;
}

/* Several processes: each candidate belongs to process k with probability
 * rates[k] / total (the superposition of independent Poisson processes). */
static uint64_t fire_some_mixed(const sim_engine *e, sim_workspace *ws, double *rates,
                                double *total, uint64_t max)
{
    const double before = *total;
    for (uint64_t c = 1; c <= max; c++) {
        const size_t k = pick_event(e, ws->run.rng, rates, before);
        rates[k] = e->fire[k](&e->events[k], &ws->run, ws->states + e->state_offset[k], 0.0);
        const double after = update_rates(e, ws, rates, k);
        if (after != before) {
            *total = after;
            return c;
        }
    }
    return max;
}

/* The exact jump scheme without a lazy flow: Poisson numbers of candidates
 * per span of constant rate, and the time of a candidate only when it changes
 * the rate (the header comment). */
static void run_jump_counted(const sim_engine *e, sim_workspace *ws, double *obs,
                             size_t *samples)
{
    const sim_scene *scene = &e->scene;
    gsl_rng *rng = ws->run.rng;
    const double interval = sim_scene_output_time(scene, 1);   /* between resets */
    double rates[MAX_EVENTS] = {0};
    double t = 0.0;
    double total = reset_events(e, ws, rates, t, interval);
    uint64_t until_rebound = e->rebound_every;
    for (size_t m = 1; m < scene->outputs; m++) {
        const double t_out = sim_scene_output_time(scene, m);
        while (t < t_out && total > 0.0) {
            /* the candidates of (t, end] at the constant rate `total` */
            double end = t_out, mean = total * (t_out - t);
            if (mean > POISSON_MAX) {
                end = fmin(t_out, t + POISSON_MAX / total);
                mean = POISSON_MAX;
            }
            const uint64_t count = gsl_ran_poisson(rng, mean);
            uint64_t done = 0;
            int changed = 0;
            while (done < count && !changed) {
                const uint64_t max = count - done < until_rebound ? count - done : until_rebound;
                const double before = total;
                const uint64_t fired = e->fire_some(e, ws, rates, &total, max);
                done += fired;
                until_rebound -= fired;
                changed = total != before || until_rebound == 0;
            }
            if (!changed) {
                t = end;
                continue;
            }
            /* candidate `done` of `count` is the done-th of `count` uniform points */
            t += (end - t) * gsl_ran_beta(rng, (double)done, (double)(count - done + 1));
            if (until_rebound == 0) {
                total = rebound(e, ws, rates);
                until_rebound = e->rebound_every;
            }
        }
        t = t_out;
        observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs)
            total = reset_events(e, ws, rates, t, interval);
        until_rebound = e->rebound_every;
    }
}

/* The steps of the output interval that starts at output m - 1: the
 * engine's, or with step_follows_temperature the largest h <= dt sqrt(T0/T)
 * that divides the interval, T the centred temperature just observed (the
 * mean free time scales as T^{-1/2}; paper E's dt = 1e-3 tau0 sqrt(T0/T)). */
static void interval_steps(const sim_engine *e, sim_workspace *ws, const double *obs, size_t m)
{
    const sim_scene *scene = &e->scene;
    ws->steps = e->steps;
    ws->h = e->h;
    const double T = obs[(m - 1) * e->observables + SIM_OBS_T];
    if (!scene->step_follows_temperature || !(T > 0.0))
        return;
    const double interval = sim_scene_output_time(scene, 1);
    const double dt = scene->dt * sqrt(scene->particles.maxwellian.temperature / T);
    const double steps = fmin(fmax(ceil(interval / dt * (1.0 - 1e-9)), 1.0), 1e12);
    ws->steps = (size_t)steps;
    ws->h = interval / steps;
}

/* Apply a linear flow's pending factor to every stored velocity (at output
 * times): v -> o + scale (v - o), o the bulk velocity for a centred map, else
 * 0; the running sums follow. */
static void apply_linear(const sim_engine *e, sim_run *run)
{
    const size_t n = run->p.n;
    const double f = run->scale;
    double o[3] = {0, 0, 0};
    if (e->flows[0].type->linear_centred) {
        for (size_t i = 0; i < n; i++)
            for (int k = 0; k < 3; k++)
                o[k] += run->p.v[i][k];
        for (int k = 0; k < 3; k++)
            o[k] /= (double)n;
    }
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            run->p.v[i][k] = o[k] + f * (run->p.v[i][k] - o[k]);
    run->scale = 1.0;
    if (e->sums)
        sim_sums_compute(&run->p, &run->sums);
}

/* The time-step scheme from t = 0 to t_end. */
static void run_timestep(const sim_engine *e, sim_workspace *ws, double *obs, size_t *samples)
{
    const sim_scene *scene = &e->scene;
    const double interval = sim_scene_output_time(scene, 1);
    reset_events(e, ws, ws->rates, 0.0, interval);
    for (size_t m = 1; m < scene->outputs; m++) {
        interval_steps(e, ws, obs, m);
        ws->t0 = sim_scene_output_time(scene, m - 1);
        e->interval(e, ws);
        const double t = sim_scene_output_time(scene, m);
        if (e->current_sums)   /* the lazy flow first: the sums are then of the true velocities */
            bring_all(&ws->run, t);
        if (e->linear)
            apply_linear(e, &ws->run);
        else if (e->sums)   /* kept by the stages and the flow: their round-off reset */
            sim_sums_compute(&ws->run.p, &ws->run.sums);
        observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs && !e->lazy_rebound)   /* synchronised; else interval_lazy */
            reset_events(e, ws, ws->rates, t, interval);
    }
}

/* The exact jump scheme with a Gaussian thermostat kept as one global factor
 * in run->scale (paper C Eq. (12)); candidates arrive at the stored
 * velocities' majorant rate times scale^lambda, their rate at the true
 * velocities, and the map is applied to every particle at output times.
 *  - keep_temperature (the homogeneous cooling state in scaled variables): T
 *    changes only at collisions, so the rescaling that keeps it acts right
 *    after each one (the h -> 0 limit of the time-step scheme, which rescales
 *    after every step); the rate is constant between collisions.
 *  - a fixed zeta: scale = e^{zeta (t - t0)} since the last output time t0,
 *    so the candidates are a Poisson process of rate total e^{g (t - t0)},
 *    g = lambda zeta: no splitting error.  In the operational time
 *    tau = (e^{g (t - t0)} - 1) / g it has the constant rate total, so the
 *    candidates of the interval are those of a homogeneous process before
 *    tau_out, one exponential each, as without the flow; no candidate needs
 *    its time t (no lazy flow), and a candidate that changes total restarts
 *    the homogeneous process at its tau (memoryless). */
static void run_jump_linear(const sim_engine *e, sim_workspace *ws, double *obs, size_t *samples)
{
    const sim_scene *scene = &e->scene;
    sim_run *run = &ws->run;
    gsl_rng *rng = run->rng;
    const sim_effect *flow = &e->flows[0];
    const double interval = sim_scene_output_time(scene, 1), lambda = e->rate_exponent;
    const int flowing = flow->type->linear_rate != NULL;
    const double growth = flowing ? lambda * flow->type->linear_rate(flow) : 0.0;
    double rates[MAX_EVENTS] = {0};
    double t = 0.0;
    double total = reset_events(e, ws, rates, t, interval), speed = 1.0;
    uint64_t until_resum = e->rebound_every;
    for (size_t m = 1; m < scene->outputs; m++) {
        const double t_out = sim_scene_output_time(scene, m);
        /* the interval in the clock the candidates run on: t itself, or tau */
        double clock = t, clock_end = t_out;
        if (flowing) {
            clock = 0.0;
            clock_end = growth == 0.0 ? t_out - t : expm1(growth * (t_out - t)) / growth;
        }
        for (;;) {
            if (!(total > 0.0))
                break;
            clock += sim_rng_exponential(rng, total * speed);
            if (clock >= clock_end)
                break;
            const uint64_t before = run->counts.collisions;
            total = rates[0] = e->fire[0](&e->events[0], run, ws->states, flowing ? t : clock);
            if (e->sums && --until_resum == 0) {
                sim_sums_compute(&run->p, &run->sums);
                until_resum = e->rebound_every;
            }
            if (!flowing && run->counts.collisions != before) {
                run->scale *= flow->type->linear_factor(flow, run, 0.0);
                speed = lambda == 1.0 ? run->scale : pow(run->scale, lambda);
            }
        }
        if (flowing)
            run->scale = flow->type->linear_factor(flow, run, t_out - t);
        t = t_out;
        apply_linear(e, run);
        speed = 1.0;
        observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs)
            total = reset_events(e, ws, rates, t, interval);
    }
}

/* The sheared EHS drag's flow over dt in the jump scheme (current_sums): the
 * exact scale between collisions (effect.h, scale_after), then the sums
 * sheared to the end. */
static void lazy_linear_advance(const sim_engine *e, sim_workspace *ws, double dt)
{
    const sim_effect *f = &e->flows[0];
    ws->run.scale = f->type->scale_after(f, &ws->run, dt);
    f->type->advance_sums(f, &ws->run.sums, dt);
}

/* The exact jump scheme with a lazy flow that also carries a global linear
 * map read from the temperature (current_sums: paper E's sheared EHS gas, the
 * shear lazy and the drag as run->scale; effect_drag.c).  A candidate's rate
 * at the true velocities is scale(t) times the stored velocities' majorant,
 * and the scale only falls, so candidates are drawn at total x scale(now) and
 * each is kept with probability scale(t)/scale(now) (thinning; restarted at
 * every candidate, from which on the bound holds again).  Between candidates
 * the scale follows its exact map and the running sums the shear; at an
 * output time every particle is brought forward and the scale applied.  The
 * sums are recomputed from the synchronised particles every rebound_every
 * candidates too (their round-off). */
static void run_jump_lazy_linear(const sim_engine *e, sim_workspace *ws, double *obs,
                                 size_t *samples)
{
    const sim_scene *scene = &e->scene;
    sim_run *run = &ws->run;
    gsl_rng *rng = run->rng;
    const double interval = sim_scene_output_time(scene, 1);
    double rates[MAX_EVENTS] = {0};
    double t = 0.0;
    double total = reset_events(e, ws, rates, t, interval);
    uint64_t until_resum = e->rebound_every;
    for (size_t m = 1; m < scene->outputs; m++) {
        const double t_out = sim_scene_output_time(scene, m);
        double t_span = t_out;
        if (e->lazy_rebound)
            total = lazy_reset(e, ws, rates, total * run->scale, t, t_out, &t_span);
        for (;;) {
            const double bound = run->scale;
            const double t_next = total > 0.0 ? t + sim_rng_exponential(rng, total * bound)
                                              : INFINITY;
            const double to = t_next < t_span ? t_next : t_span;
            lazy_linear_advance(e, ws, to - t);
            t = to;
            if (t_next >= t_span) {
                if (t_span >= t_out)
                    break;
                total = lazy_reset(e, ws, rates, total * run->scale, t, t_out, &t_span);
                continue;
            }
            if (!(sim_rng_uniform(rng) * bound < run->scale)) {
                run->counts.candidates++;   /* thinned: fictitious at the true rate */
                continue;
            }
            total = rates[0] = e->fire[0](&e->events[0], run, ws->states, t);
            if (--until_resum == 0) {
                bring_all(run, t);
                sim_sums_compute(&run->p, &run->sums);
                until_resum = e->rebound_every;
            }
        }
        t = t_out;
        bring_all(run, t);
        apply_linear(e, run);
        observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs && !e->lazy_rebound)
            total = reset_events(e, ws, rates, t, interval);
    }
}

void sim_engine_start(const sim_engine *e, sim_workspace *ws, uint64_t index, double *obs)
{
    const sim_scene *scene = &e->scene;
    sim_run *run = &ws->run;
    gsl_rng *rng = run->rng;

    sim_rng_set_stream(rng, scene->seed, index);
    memset(&run->counts, 0, sizeof run->counts);
    ws->samples = 0;
    if (e->nsteady > 0)
        memset(ws->steady_sum, 0, e->nsteady * sizeof *ws->steady_sum);
    if (ws->observer_rng)
        sim_rng_set_substream(ws->observer_rng, scene->seed, index, 1);
    sim_particles_sample(&run->p, scene, rng);
    run->scale = 1.0;
    if (e->sums)
        sim_sums_compute(&run->p, &run->sums);
    if (e->slab)
        sim_slab_start(e->slab, ws->slab, run);
    observe_at(e, ws, 0, obs, &ws->samples);
}

void sim_engine_evolve(const sim_engine *e, sim_workspace *ws, double *obs, sim_counts *counts)
{
    const sim_scene *scene = &e->scene;
    sim_run *run = &ws->run;

    /* the processes' per-run states start at 0 (the stages' remainders, the
     * index streams, which their first reset fills) */
    memset(ws->states, 0, e->state_bytes);
    memset(ws->credit, 0, sizeof ws->credit);
    if (scene->scheme == SIM_SCHEME_TIMESTEP)
        run_timestep(e, ws, obs, &ws->samples);
    else if (e->current_sums)
        run_jump_lazy_linear(e, ws, obs, &ws->samples);
    else if (e->linear)
        run_jump_linear(e, ws, obs, &ws->samples);
    else if (e->lazy_flow)
        run_jump_timed(e, ws, obs, &ws->samples);
    else
        run_jump_counted(e, ws, obs, &ws->samples);

    if (e->nsteady > 0) {   /* the time averages follow the rows */
        double *avg = obs + scene->outputs * e->observables;
        for (size_t k = 0; k < e->nsteady; k++)
            avg[k] = ws->steady_sum[k] / (double)ws->samples;
        sim_steady_finish(scene, avg);
    }
    if (counts) {
        run->counts.normals = sim_rng_state_of(run->rng)->normals;
        sim_counts_add(counts, &run->counts);
    }
}

void sim_engine_run(const sim_engine *e, sim_workspace *ws, uint64_t index, double *obs,
                    sim_counts *counts)
{
    sim_engine_start(e, ws, index, obs);
    sim_engine_evolve(e, ws, obs, counts);
}

void sim_counts_add(sim_counts *to, const sim_counts *from)
{
    to->candidates += from->candidates;
    to->collisions += from->collisions;
    to->background += from->background;
    to->violations += from->violations;
    to->normals += from->normals;
}
