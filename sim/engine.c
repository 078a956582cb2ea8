/* The DSMC engine (docs/theory.md §8): scene -> the registry's effects ->
 * a scheme.
 *
 * The engine walks the registry (registry.h) to build the effects the scene
 * names, as type objects (effect.h), and resolves once, from what their types
 * offer, how the scheme runs them: which flow is lazy (brought forward per
 * particle: white noise, the homogeneous shear), which is a linear map kept
 * global (the Gaussian thermostat; the sheared EHS drag is both), whether
 * the events keep running sums, and each event's fire function.  The scheme
 * (scheme.h) then resolves its loop: the exact jump scheme (scheme_jump.c),
 * the time-step scheme (scheme_timestep.c) or the Lees-Edwards slab
 * (scheme_slab.c).  This file also holds what the schemes share: the velocity
 * bound and the majorants' reset, the output times' observation, and the
 * steady-state observers (steady.h), which sample at the output times
 * t >= steady.from after the standard observables; pair sampling uses its
 * own random substream.
 */
#include "engine.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "first_stage.h"
#include "registry.h"
#include "rng.h"
#include "run.h"
#include "scheme.h"
#include "steady.h"

static void append_name(sim_engine *e, const char *name)
{
    size_t len = strlen(e->effects);
    snprintf(e->effects + len, sizeof e->effects - len, "%s%s", len ? " " : "", name);
}

static void add_event(sim_engine *e, sim_event event)
{
    e->events[e->nevents] = event;
    e->state_offset[e->nevents] = e->state_bytes;
    /* keep every state block aligned for doubles */
    e->state_bytes += (event.type->state_size + 15) & ~(size_t)15;
    e->nevents++;
}

/* The scheme the scene asks for: the first that claims it (the slab, the time
 * step with positions, before the homogeneous time-step scheme). */
static const sim_scheme_type *scheme_of(const sim_scene *scene)
{
    static const sim_scheme_type *const schemes[] = {&sim_scheme_slab, &sim_scheme_timestep,
                                                     &sim_scheme_jump};
    size_t k = 0;
    while (k + 1 < sizeof schemes / sizeof schemes[0] && !schemes[k]->claims(scene))
        k++;
    return schemes[k];
}

/* What no scheme can run: a scene the parser should have refused, two masses. */
static sim_status check_scene(const sim_scene *scene, sim_error *err)
{
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
    return SIM_OK;
}

/* Which registry entries the engine builds: those the scene names, with a
 * fused flow in place of its parts when they are all present and no other
 * flow is (registry.h). */
static void select_entries(const sim_scene *scene, int use[])
{
    size_t flows = 0;
    for (size_t k = 0; k < sim_registry_count; k++) {
        const sim_effect_entry *en = &sim_registry[k];
        use[k] = en->present && en->present(scene);
        flows += use[k] && en->create_flow;
    }
    for (size_t k = 0; k < sim_registry_count; k++) {
        const sim_effect_entry *en = &sim_registry[k];
        size_t parts = 0, present = 0;
        for (; parts < SIM_FUSES_MAX && en->fuses[parts]; parts++) {
            const sim_effect_entry *part = sim_registry_find(en->fuses[parts]);
            present += part && use[part - sim_registry];
        }
        if (parts == 0 || present != parts || flows != parts)
            continue;
        use[k] = 1;
        for (size_t q = 0; q < parts; q++)
            use[sim_registry_find(en->fuses[q]) - sim_registry] = 0;
    }
}

/* The event processes of the selected entries, in the table's order, each
 * accepted by the scheme. */
static sim_status build_events(sim_engine *e, const int use[], sim_error *err)
{
    for (size_t k = 0; k < sim_registry_count; k++) {
        const sim_effect_entry *en = &sim_registry[k];
        if (!use[k] || !en->create_event)
            continue;
        sim_event event;
        sim_status status = en->create_event(&e->scene, &event, err);
        if (status != SIM_OK)
            return status;
        add_event(e, event);
        if (e->scheme->accept_event
            && (status = e->scheme->accept_event(&e->scene, &event, err)) != SIM_OK)
            return status;
    }
    return SIM_OK;
}

/* The flows of the selected entries in their flow_order (the table's order
 * among equals). */
static sim_status build_flows(sim_engine *e, const int use[], sim_error *err)
{
    const sim_effect_entry *order[SIM_FLOWS_MAX];
    size_t count = 0;
    for (size_t k = 0; k < sim_registry_count; k++) {
        const sim_effect_entry *en = &sim_registry[k];
        if (!use[k] || !en->create_flow)
            continue;
        size_t at = count++;
        for (; at > 0 && order[at - 1]->flow_order > en->flow_order; at--)
            order[at] = order[at - 1];
        order[at] = en;
    }
    for (size_t k = 0; k < count; k++) {
        sim_status status = order[k]->create_flow(&e->scene, &e->flows[e->nflows], err);
        if (status != SIM_OK)
            return status;
        e->flow_entries[e->nflows++] = order[k];
    }
    return SIM_OK;
}

/* The effects: the events, the scheme's own refusals, the flows; then their
 * names for sim_engine_effects. */
static sim_status build_effects(sim_engine *e, sim_error *err)
{
    int use[sim_registry_count];
    select_entries(&e->scene, use);
    sim_status status = build_events(e, use, err);
    if (status == SIM_OK && e->scheme->accept)
        status = e->scheme->accept(&e->scene, err);
    if (status == SIM_OK)
        status = build_flows(e, use, err);
    if (status != SIM_OK)
        return status;
    if (e->scheme->effect_name)
        append_name(e, e->scheme->effect_name);
    for (size_t k = 0; k < e->nevents; k++)
        append_name(e, e->events[k].type->name);
    for (size_t k = 0; k < e->nflows; k++)
        append_name(e, e->flows[k].type->name);
    return SIM_OK;
}

/* How the one flow runs beside the events, from what its type offers: lazy
 * (advance), always in the jump scheme and in the time-step scheme when every
 * stage may fire the jump scheme's candidates (not by the contact rule, which
 * the batched stage draws without bringing particles); a global linear map
 * when the only event process is covariant under it (its rate scales as
 * scale^lambda: binary collisions), also lazy when the map carries running
 * sums (the sheared EHS drag: current_sums). */
static void resolve_modes(sim_engine *e)
{
    const int timestep = e->scene.scheme == SIM_SCHEME_TIMESTEP;
    e->rate_exponent = 1.0;   /* the scale stays 1 without a linear map */
    if (e->nflows != 1)
        return;
    const sim_flow_type *type = e->flows[0].type;
    int stages_fire = 1;
    for (size_t k = 0; k < e->nevents; k++) {
        const sim_event_stages *st = e->events[k].type->stages;
        stages_fire &= st && st->fires_candidates && st->fires_candidates(&e->events[k]);
    }
    const sim_event *ev = e->nevents == 1 ? &e->events[0] : NULL;
    const int covariant = ev && ev->type->rate_exponent;
    if (covariant)
        e->rate_exponent = ev->type->rate_exponent(ev);
    const sim_linear_map *map = type->linear;
    e->lazy_flow = type->advance != NULL && (!timestep || stages_fire);
    e->linear = map != NULL && covariant
                && (type->advance == NULL
                    || (e->lazy_flow && map->advance_sums != NULL
                        && (timestep || map->scale_after != NULL)));
    e->current_sums = e->lazy_flow && e->linear;
    e->stage_sums = (e->linear && map->reads_sums) || type->step_reads_sums;
}

/* Conditional observation needs the jump scheme and at most a lazy flow with
 * a spread; observe_only, the base set; neither goes with an effect that
 * observes every particle. */
static sim_status check_observation(sim_engine *e, sim_error *err)
{
    const sim_scene *scene = &e->scene;
    const char *observer;
    const int every = sim_registry_observes_every_particle(scene, &observer);
    if (scene->observation == SIM_OBSERVE_CONDITIONAL) {
        if (scene->scheme == SIM_SCHEME_TIMESTEP || scene->steady.present || every
            || (e->nflows > 0 && (!e->lazy_flow || e->flows[0].type->spread == NULL)))
            return sim_error_set(err, SIM_EUNSUPPORTED, "scene.observation",
                                 "conditional needs scheme = jump, at most one lazy flow "
                                 "whose increments are Gaussian and independent of the "
                                 "velocity, and no [steady]%s%s%s (they observe every "
                                 "particle)", every ? " or [" : "", every ? observer : "",
                                 every ? "]" : "");
        e->pending_spread = e->lazy_flow ? e->flows[0].type->spread(&e->flows[0]) : 0.0;
        e->conditional = 1;
    }
    const uint32_t only = scene->observe_only;
    if (only == 0)
        return SIM_OK;
    if (only & ~SIM_OBS_ALL_BASE)
        return sim_error_set(err, SIM_EINVAL, "scene.observe_only",
                             "0x%" PRIx32 " names observables beyond the base set", only);
    if (every)
        return sim_error_set(err, SIM_EUNSUPPORTED, "scene.observe_only",
                             "[%s] computes its observables from every base one", observer);
    if (scene->step_follows_temperature && !(only & SIM_OBS_BIT(SIM_OBS_T)))
        return sim_error_set(err, SIM_EINVAL, "scene.observe_only",
                             "step_follows_temperature needs T");
    return SIM_OK;
}

/* The steady observers: their count and the first output time >= from. */
static sim_status resolve_steady(sim_engine *e, sim_error *err)
{
    const sim_scene *scene = &e->scene;
    if (!scene->steady.present)
        return SIM_OK;
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
        return sim_error_set(err, SIM_EINVAL, "steady.c_max", "%g is not positive",
                             scene->steady.c_max);
    if (e->steady_from == scene->outputs)
        return sim_error_set(err, SIM_EINVAL, "steady.from",
                             "%g is after the last output time %g", scene->steady.from,
                             scene->t_end);
    return SIM_OK;
}

/* Event process ev's fire function that keeps run->sums current (at the
 * candidates' time with current_sums), or NULL if it has none. */
static sim_event_fire_fn sums_fire(const sim_engine *e, const sim_event *ev)
{
    const sim_event_fast *fast = ev->type->fast;
    if (fast == NULL)
        return NULL;
    if (e->current_sums)
        return fast->select_fire_current_sums ? fast->select_fire_current_sums(ev) : NULL;
    return fast->select_fire_sums ? fast->select_fire_sums(ev, e->lazy_flow, e->bounded) : NULL;
}

/* The velocity bound, and each event's fire function: with running sums
 * where every process keeps them (for conditional observation, and for a
 * linear map that reads them, which needs them). */
static sim_status resolve_events(sim_engine *e, sim_error *err)
{
    for (size_t k = 0; k < e->nevents; k++) {
        const sim_event *ev = &e->events[k];
        e->bounded |= ev->type->needs_bound(ev);
        if (ev->type->bound_centre && ev->type->bound_centre(ev, e->centre))
            e->fixed_centre = 1;
    }
    e->sums = e->conditional || e->stage_sums;
    size_t lacking = e->nevents;   /* the first process that cannot keep them */
    for (size_t k = 0; k < e->nevents; k++) {
        e->fire[k] = sums_fire(e, &e->events[k]);
        if (e->fire[k] == NULL && lacking == e->nevents)
            lacking = k;
    }
    e->sums &= lacking == e->nevents;
    for (size_t k = 0; k < e->nevents; k++)
        if (!e->sums)
            e->fire[k] = e->events[k].type->select_fire(&e->events[k], e->lazy_flow,
                                                         e->bounded);
    if (e->stage_sums && !e->sums)   /* a flow reads the sums beside a process that cannot */
        return sim_error_set(err, SIM_EUNSUPPORTED, e->events[lacking].type->name,
                             "the %s reads running sums of the velocities, which the %s does "
                             "not keep%s", e->flows[0].type->name,
                             e->events[lacking].type->name,
                             e->lazy_flow ? " beside a lazy flow" : "");
    e->lazy_rebound = e->bounded && e->lazy_flow;
    return SIM_OK;
}

/* The effects' own observers of the output row (registry.h). */
static void resolve_observers(sim_engine *e)
{
    for (size_t k = 0; k < sim_registry_count; k++) {
        const sim_effect_entry *en = &sim_registry[k];
        if (en->observe && en->observables && en->observables(&e->scene) > 0)
            e->observers[e->nobservers++] = en;
    }
}

sim_status sim_engine_create(const sim_scene *scene, sim_engine **engine, sim_error *err)
{
    *engine = NULL;
    sim_status status = check_scene(scene, err);
    if (status != SIM_OK)
        return status;
    sim_engine *e = calloc(1, sizeof *e);
    if (e == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    e->scene = *scene;
    e->scheme = scheme_of(scene);
    e->mass = sim_scene_grain_mass(scene);
    e->observables = sim_observe_row_length(scene);
    status = build_effects(e, err);
    if (status == SIM_OK) {
        resolve_modes(e);
        if (e->scheme->check)
            status = e->scheme->check(e, err);
    }
    if (status == SIM_OK) {
        resolve_observers(e);
        status = check_observation(e, err);
    }
    if (status == SIM_OK)
        status = resolve_steady(e, err);
    if (status == SIM_OK)
        status = resolve_events(e, err);
    if (status == SIM_OK)
        status = e->scheme->build(e, err);
    if (status != SIM_OK) {
        sim_engine_free(e);
        return status;
    }
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
    if (engine->free_params)
        engine->free_params(engine->scheme_params);
    free(engine);
}

const sim_scene *sim_engine_scene(const sim_engine *engine) { return &engine->scene; }

const char *sim_engine_effects(const sim_engine *engine) { return engine->effects; }

size_t sim_engine_steady_count(const sim_engine *engine) { return engine->nsteady; }

size_t sim_engine_observables(const sim_engine *engine) { return engine->observables; }

size_t sim_engine_workspace_bytes(const sim_engine *engine)
{
    const size_t n = engine->scene.particles.n;
    return n * sim_particles_bytes_per_particle(engine->lazy_flow) + engine->state_bytes
           + engine->nsteady * sizeof(double) + sizeof(sim_workspace)
           + (engine->scheme->state ? engine->scheme->state->bytes(engine, n) : 0);
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
    if (status == SIM_OK && engine->scheme->state)
        status = engine->scheme->state->create(engine, w, err);
    if (status == SIM_OK && engine->nsteady > 0
        && (w->steady_sum = calloc(engine->nsteady, sizeof *w->steady_sum)) == NULL)
        status = sim_error_set(err, SIM_ENOMEM, "steady", "out of memory");
    const int pairs = (engine->nsteady > 0 && engine->scene.steady.pairs > 0)
                      || sim_registry_observers_draw(&engine->scene);
    if (status == SIM_OK && pairs && (w->observer_rng = sim_rng_alloc()) == NULL)
        status = sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    w->free_state = engine->scheme->state ? engine->scheme->state->free : NULL;
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
    if (ws->free_state)
        ws->free_state(ws->scheme_state);
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
        const sim_flow *f = run->flow;
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
double sim_engine_reset_events(const sim_engine *e, sim_workspace *ws, double rates[SIM_EVENTS_MAX],
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

/* Output time m: the standard observables (then the effects' own: paper E's
 * shear set), or the scheme's, and a steady sample if t_m >= from. */
static void observe_at(const sim_engine *e, sim_workspace *ws, size_t m, double *obs,
                       size_t *samples)
{
    double *row = obs + m * e->observables;
    const double *prev = m > 0 ? row - e->observables : NULL;
    const sim_particles *observed = &ws->run.p;
    if (e->scheme->observe) {
        observed = e->scheme->observe(e, ws, m, prev, row);
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
        for (size_t k = 0; k < e->nobservers; k++)
            e->observers[k]->observe(&e->scene, &ws->run.p, e->mass, &ws->run.counts, m, prev,
                                     ws->observer_rng, row);
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
void sim_engine_observe_output(const sim_engine *e, sim_workspace *ws, size_t m, double t,
                           double *obs, size_t *samples)
{
    const double start = ws->time_outputs ? clock_seconds() : 0.0;
    if (e->lazy_flow && !e->conditional)
        sim_run_bring_all(&ws->run, t);
    observe_at(e, ws, m, obs, samples);
    if (ws->time_outputs)
        ws->output_seconds += clock_seconds() - start;
}


/* The steps of the output interval that starts at output m - 1: the
 * engine's, or with step_follows_temperature the largest h <= dt sqrt(T0/T)
 * that divides the interval, T the centred temperature just observed (the
 * mean free time scales as T^{-1/2}; paper E's dt = 1e-3 tau0 sqrt(T0/T)). */
void sim_engine_interval_steps(const sim_engine *e, sim_workspace *ws, const double *obs, size_t m)
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
void sim_engine_apply_linear(const sim_engine *e, sim_run *run)
{
    const size_t n = run->p.n;
    const double f = run->scale;
    double o[3] = {0, 0, 0};
    if (e->flows[0].type->linear->centred) {
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
    if (e->scheme->start)
        e->scheme->start(e, ws);
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
    e->scheme->evolve(e, ws, obs, &ws->samples);

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
