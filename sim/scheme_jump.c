/* The exact jump scheme (docs/theory.md §8.3): the Markov jump process
 * without time splitting (paper A §3, paper B §3).  Candidate events arrive at rate pi_hat = Σ of the event
 * processes' majorant rates, each is fired by its process (accepted or
 * fictitious), and the one lazy flow (white-noise heating, or the homogeneous
 * shear when it is the only flow) is applied to a particle only when an event
 * touches it or at an output time.  At each output time every
 * particle is brought to that time, the observables are recorded, and the
 * majorants are recomputed from the synchronised system; the pending waiting
 * time is then redrawn, which is exact because the waiting times are
 * exponential (memoryless).  When an event process needs the velocity bound,
 * the bound is also recomputed between output times, about every
 * SIM_LAZY_REBOUND_SWEEPS n candidates (scheme.h), without bringing any particle: each
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
 *    own loop (effect.h, select_fire_many).  In these runs the system is always
 *    synchronised, so every REBOUND_SWEEPS n candidates the bound is also
 *    recomputed from scratch (the same change of rate): it follows the
 *    current largest speed instead of the largest ever seen, and the
 *    majorants stay tight;
 *
 *  - with a Gaussian thermostat kept as one global linear map
 *    (run_jump_linear), and with the sheared EHS drag, the shear lazy and the
 *    drag a global map (run_jump_lazy_linear).
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <gsl/gsl_randist.h>

#include "rng.h"
#include "scheme.h"

/* Candidates between two recomputations of the velocity bound in runs
 * without a lazy flow, in units of n: one pass over the particles every 4 n
 * candidates (about one collision per particle) costs about 1% and keeps the
 * majorant near the current largest speed (run_jump_counted). */
#define REBOUND_SWEEPS 4

/* The largest Poisson mean drawn at once (gsl_ran_poisson returns an
 * unsigned int); a longer span is cut into pieces, which is exact because the
 * counts of disjoint spans are independent. */
#define POISSON_MAX 1e9

/* Runs without a lazy flow, between output times: R = max |v_i - c| from
 * scratch about the same centre (binary collisions keep the bulk velocity,
 * and a fixed centre stays), and every process's rate for it; returns the
 * total.  One pass over the particles, no reset of the processes.  The
 * running sums, when kept, are recomputed in the same pass's place. */
static double rebound(const sim_engine *e, sim_workspace *ws, double rates[SIM_EVENTS_MAX])
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

/* The reset of a lazy_rebound run at time t (the output time at t_out, or
 * earlier): the bound and the majorants for a span of sim_lazy_candidates at
 * the current total rate, at most to t_out; returns the new total and sets
 * *t_span to the span's end. */
static double lazy_reset(const sim_engine *e, sim_workspace *ws, double rates[SIM_EVENTS_MAX],
                         double total, double t, double t_out, double *t_span)
{
    const double left = t_out - t;
    double span = sim_lazy_candidates(e) / total;
    if (!(span < left))
        span = left;
    *t_span = span < left ? t + span : t_out;
    return sim_engine_reset_events(e, ws, rates, t, span);
}

/* The exact jump scheme from t = 0 to t_end (the initial state is sampled),
 * with a lazy flow: every candidate gets its waiting time. */
static void run_jump_timed(const sim_engine *e, sim_workspace *ws, double *obs, size_t *samples)
{
    const sim_scene *scene = &e->scene;
    sim_run *run = &ws->run;
    gsl_rng *rng = run->rng;

    const double interval = sim_scene_output_time(scene, 1);   /* between resets */
    double rates[SIM_EVENTS_MAX] = {0};
    double t = 0.0;
    double total = sim_engine_reset_events(e, ws, rates, t, interval);
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
        sim_engine_observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs && !e->lazy_rebound)   /* else at the loop's top */
            total = sim_engine_reset_events(e, ws, rates, t, interval);
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
    double rates[SIM_EVENTS_MAX] = {0};
    double t = 0.0;
    double total = sim_engine_reset_events(e, ws, rates, t, interval);
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
        sim_engine_observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs)
            total = sim_engine_reset_events(e, ws, rates, t, interval);
        until_rebound = e->rebound_every;
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
    const sim_flow *flow = &e->flows[0];
    const double interval = sim_scene_output_time(scene, 1), lambda = e->rate_exponent;
    const int flowing = flow->type->linear->rate != NULL;
    const double growth = flowing ? lambda * flow->type->linear->rate(flow) : 0.0;
    double rates[SIM_EVENTS_MAX] = {0};
    double t = 0.0;
    double total = sim_engine_reset_events(e, ws, rates, t, interval), speed = 1.0;
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
                run->scale *= flow->type->linear->factor(flow, run, 0.0);
                speed = lambda == 1.0 ? run->scale : pow(run->scale, lambda);
            }
        }
        if (flowing)
            run->scale = flow->type->linear->factor(flow, run, t_out - t);
        t = t_out;
        sim_engine_apply_linear(e, run);
        speed = 1.0;
        sim_engine_observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs)
            total = sim_engine_reset_events(e, ws, rates, t, interval);
    }
}

/* The sheared EHS drag's flow over dt in the jump scheme (current_sums): the
 * exact scale between collisions (effect.h, scale_after), then the sums
 * sheared to the end. */
static void lazy_linear_advance(const sim_engine *e, sim_workspace *ws, double dt)
{
    const sim_flow *f = &e->flows[0];
    ws->run.scale = f->type->linear->scale_after(f, &ws->run, dt);
    f->type->linear->advance_sums(f, &ws->run.sums, dt);
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
    double rates[SIM_EVENTS_MAX] = {0};
    double t = 0.0;
    double total = sim_engine_reset_events(e, ws, rates, t, interval);
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
                sim_run_bring_all(run, t);
                sim_sums_compute(&run->p, &run->sums);
                until_resum = e->rebound_every;
            }
        }
        t = t_out;
        sim_run_bring_all(run, t);
        sim_engine_apply_linear(e, run);
        sim_engine_observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs && !e->lazy_rebound)
            total = sim_engine_reset_events(e, ws, rates, t, interval);
    }
}


/* The loop for the engine's shape (the header comment). */
static void jump_evolve(const sim_engine *e, sim_workspace *ws, double *obs, size_t *samples)
{
    if (e->current_sums)
        run_jump_lazy_linear(e, ws, obs, samples);
    else if (e->linear)
        run_jump_linear(e, ws, obs, samples);
    else if (e->lazy_flow)
        run_jump_timed(e, ws, obs, samples);
    else
        run_jump_counted(e, ws, obs, samples);
}

/* A flow the jump scheme would never apply is refused: one neither lazy nor
 * a global map (a Gaussian thermostat alone left T unchanged). */
static sim_status jump_check(const sim_engine *e, sim_error *err)
{
    if (e->nflows == 0 || e->lazy_flow || e->linear)
        return SIM_OK;
    const char *key = NULL;   /* the first flow that names one */
    for (size_t k = 0; k < e->nflows && key == NULL; k++)
        key = e->flow_entries[k]->jump_key;
    return sim_error_set(err, SIM_EUNSUPPORTED, key ? key : "scene.scheme",
                         "the jump scheme applies a flow only lazily (white noise, or "
                         "[shear] alone) or as one global map with binary collisions "
                         "(gaussian, without [background])");
}

static sim_status jump_build(sim_engine *e, sim_error *err)
{
    (void)err;
    if (e->nevents == 1 && !e->sums && e->events[0].type->fast
        && e->events[0].type->fast->select_fire_many)
        e->fire_many = e->events[0].type->fast->select_fire_many(&e->events[0]);
    e->fire_some = e->fire_many ? fire_some_alone : e->nevents == 1 ? fire_some_one
                                                                    : fire_some_mixed;
    e->rebound_every = (e->bounded && !e->lazy_flow) || e->sums
                           ? REBOUND_SWEEPS * (uint64_t)e->scene.particles.n : UINT64_MAX;
    return SIM_OK;
}

static int jump_claims(const sim_scene *scene)
{
    return scene->scheme == SIM_SCHEME_JUMP;
}

const sim_scheme_type sim_scheme_jump = {
    .claims = jump_claims,
    .check = jump_check,
    .build = jump_build,
    .evolve = jump_evolve,
};
