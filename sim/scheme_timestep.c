/* The time-step scheme (docs/theory.md §8.5; Bird, paper C §3): the whole
 * system advances in steps of h, the largest h <= scene.dt that divides the interval between output
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
 */
#include <math.h>
#include <stdint.h>

#include "scheme.h"

static void stage_fired(const sim_engine *e, sim_workspace *ws, size_t k, double h, double t);

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
    ws->run.scale *= e->flows[0].type->linear->factor(&e->flows[0], &ws->run, h);
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
    const sim_flow *f = &e->flows[0];
    f->type->linear->advance_sums(f, &ws->run.sums, dt);
    ws->run.scale *= f->type->linear->factor(f, &ws->run, dt);
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
                                    steps, about sim_lazy_candidates(e) candidates */
            double total = 0.0;
            for (size_t q = 0; q < e->nevents; q++)
                total += ws->rates[q];
            const double steps = floor(sim_lazy_candidates(e) / (total * stage));
            const size_t left = ws->steps - k;
            const size_t span = !(steps >= 1.0) ? 1 : steps < (double)left ? (size_t)steps : left;
            /* the span's stages fire at t0 + (k + theta) h ... t0 + (k + span - 1
             * + theta) h: the reach is needed that far, not to the span's end */
            sim_engine_reset_events(e, ws, ws->rates, ws->t0 + (double)k * ws->h,
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

sim_status sim_scheme_needs_stages(const sim_scene *scene, const sim_event *event,
                                   sim_error *err)
{
    if (scene->scheme != SIM_SCHEME_TIMESTEP || event->type->stages != NULL)
        return SIM_OK;
    return sim_error_set(err, SIM_EUNSUPPORTED, event->type->name,
                         "the %s is not implemented in the time-step scheme (supported: jump)",
                         event->type->name);
}

/* Resolve the time-step scheme: stages, the step function, h. */
static sim_status timestep_build(sim_engine *e, sim_error *err)
{
    const sim_scene *scene = &e->scene;
    for (size_t k = 0; k < e->nevents; k++) {
        const sim_event *ev = &e->events[k];
        e->stage[k] = ev->type->stages->select ? ev->type->stages->select(ev, e->stage_sums)
                                               : NULL;
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
    return sim_scene_step(scene, &e->h, &e->steps, err);
}

/* The time-step scheme from t = 0 to t_end. */
static void run_timestep(const sim_engine *e, sim_workspace *ws, double *obs, size_t *samples)
{
    const sim_scene *scene = &e->scene;
    const double interval = sim_scene_output_time(scene, 1);
    sim_engine_reset_events(e, ws, ws->rates, 0.0, interval);
    for (size_t m = 1; m < scene->outputs; m++) {
        sim_engine_interval_steps(e, ws, obs, m);
        ws->t0 = sim_scene_output_time(scene, m - 1);
        e->interval(e, ws);
        const double t = sim_scene_output_time(scene, m);
        if (e->current_sums)   /* the lazy flow first: the sums are then of the true velocities */
            sim_run_bring_all(&ws->run, t);
        if (e->linear)
            sim_engine_apply_linear(e, &ws->run);
        else if (e->sums)   /* kept by the stages and the flow: their round-off reset */
            sim_sums_compute(&ws->run.p, &ws->run.sums);
        sim_engine_observe_output(e, ws, m, t, obs, samples);
        if (m + 1 < scene->outputs && !e->lazy_rebound)   /* synchronised; else interval_lazy */
            sim_engine_reset_events(e, ws, ws->rates, t, interval);
    }
}

sim_status sim_scene_step(const sim_scene *scene, double *h, size_t *steps, sim_error *err)
{
    *h = 0.0;
    *steps = 0;
    if (scene->scheme != SIM_SCHEME_TIMESTEP)
        return SIM_OK;
    if (!(scene->dt > 0.0) || !isfinite(scene->dt))
        return sim_error_set(err, SIM_EINVAL, "scene.dt", "%g is not a positive step",
                             scene->dt);
    const double interval = sim_scene_output_time(scene, 1);
    double count = ceil(interval / scene->dt * (1.0 - 1e-9));
    if (count < 1.0)
        count = 1.0;
    if (count > 1e12)
        return sim_error_set(err, SIM_EINVAL, "scene.dt",
                             "%g gives %.3g steps between output times (allowed at most 1e12)",
                             scene->dt, count);
    *steps = (size_t)count;
    *h = interval / count;
    return SIM_OK;
}

static int timestep_claims(const sim_scene *scene)
{
    return scene->scheme == SIM_SCHEME_TIMESTEP;
}

const sim_scheme_type sim_scheme_timestep = {
    .claims = timestep_claims,
    .accept_event = sim_scheme_needs_stages,
    .build = timestep_build,
    .evolve = run_timestep,
};
