/* The engine: scene -> effects -> the exact jump scheme (SPEC §2, §3).
 *
 * The jump scheme simulates the Markov jump process without time splitting
 * (paper A §3, paper B §3): candidate events arrive at rate pi_hat = Σ of the event
 * processes' majorant rates, each is fired by its process (accepted or
 * fictitious), and the one lazy flow (heating) is applied to a particle only
 * when an event touches it or at an output time.  At each output time every
 * particle is brought to that time, the observables are recorded, and the
 * majorants are recomputed from the synchronised system; the pending waiting
 * time is then redrawn, which is exact because the waiting times are
 * exponential (memoryless).
 */
#include "engine.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "rng.h"
#include "run.h"

#define MAX_EVENTS 4

struct sim_engine {
    sim_scene scene;
    double mass;          /* the grain mass */
    char effects[64];
    int has_flow;
    sim_effect flow;
    int bounded;          /* some event needs the velocity bound (run.h) */
    int fixed_centre;     /* ... centred at `centre`, else at the bulk velocity */
    double centre[3];
    size_t nevents;
    sim_effect events[MAX_EVENTS];
    sim_event_fire_fn fire[MAX_EVENTS];
    size_t state_offset[MAX_EVENTS];
    size_t state_bytes;
};

struct sim_workspace {
    sim_run run;
    unsigned char *states;   /* the event processes' per-run states */
};

static void append_name(sim_engine *e, const char *name)
{
    size_t len = strlen(e->effects);
    snprintf(e->effects + len, sizeof e->effects - len, "%s%s", len ? " " : "", name);
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

sim_status sim_engine_create(const sim_scene *scene, sim_engine **engine, sim_error *err)
{
    *engine = NULL;
    if (scene->scheme != SIM_SCHEME_JUMP)
        return sim_error_set(err, SIM_EUNSUPPORTED, "scene.scheme",
                             "the time-step scheme is not implemented yet (supported: jump)");
    if (scene->particles.initial == SIM_INITIAL_TWO_MAXWELLIANS
        && scene->particles.first.mass != scene->particles.second.mass)
        return sim_error_set(err, SIM_EUNSUPPORTED, "particles.mass2",
                             "the engine simulates one species: mass2 = %g must equal "
                             "mass1 = %g", scene->particles.second.mass,
                             scene->particles.first.mass);
    if (scene->shear.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "shear", "shear flow is not implemented yet");
    if (scene->heat_flux.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "heat-flux",
                             "the heat-flux force is not implemented yet");
    if (scene->particles.n < 2 || scene->outputs < 2 || !(scene->t_end > 0.0))
        return sim_error_set(err, SIM_EINVAL, "",
                             "scene not validated: n = %zu, outputs = %zu, t_end = %g",
                             scene->particles.n, scene->outputs, scene->t_end);

    sim_engine *e = calloc(1, sizeof *e);
    if (e == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    e->scene = *scene;
    e->mass = sim_scene_grain_mass(scene);

    sim_status status = SIM_OK;
    if (scene->collisions.present) {
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
    if (status == SIM_OK && scene->heating.present) {
        status = sim_effect_heating(scene, &e->flow, err);
        if (status == SIM_OK) {
            e->has_flow = 1;
            append_name(e, e->flow.type->name);
        }
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
    for (size_t k = 0; k < e->nevents; k++)
        e->fire[k] = e->events[k].type->select_fire(&e->events[k], e->has_flow, e->bounded);
    *engine = e;
    return SIM_OK;
}

void sim_engine_free(sim_engine *engine)
{
    if (engine == NULL)
        return;
    for (size_t k = 0; k < engine->nevents; k++)
        free(engine->events[k].params);
    free(engine->flow.params);
    free(engine);
}

const sim_scene *sim_engine_scene(const sim_engine *engine) { return &engine->scene; }

const char *sim_engine_effects(const sim_engine *engine) { return engine->effects; }

sim_status sim_workspace_create(const sim_engine *engine, sim_workspace **ws, sim_error *err)
{
    *ws = NULL;
    sim_workspace *w = calloc(1, sizeof *w);
    if (w == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    sim_status status = sim_particles_alloc(&w->run.p, engine->scene.particles.n,
                                            engine->has_flow, err);
    if (status == SIM_OK) {
        w->run.rng = sim_rng_alloc();
        w->states = calloc(1, engine->state_bytes + 16);
        if (w->run.rng == NULL || w->states == NULL)
            status = sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    }
    if (status != SIM_OK) {
        sim_workspace_free(w);
        return status;
    }
    w->run.flow = engine->has_flow ? &engine->flow : NULL;
    *ws = w;
    return SIM_OK;
}

void sim_workspace_free(sim_workspace *ws)
{
    if (ws == NULL)
        return;
    sim_particles_free(&ws->run.p);
    if (ws->run.rng)
        gsl_rng_free(ws->run.rng);
    free(ws->states);
    free(ws);
}

/* The velocity bound of run.h from the synchronised system: centre c (fixed,
 * or the bulk velocity), R = max |v_i - c| plus the lazy flow's reach over
 * the horizon; R = +inf (no bound) when no event needs one. */
static void reset_bound(const sim_engine *e, sim_run *run, double horizon)
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
    for (size_t i = 0; i < n; i++) {
        double d[3] = {run->p.v[i][0] - c[0], run->p.v[i][1] - c[1], run->p.v[i][2] - c[2]};
        r2 = fmax(r2, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    memcpy(run->centre, c, sizeof c);
    run->radius = sqrt(r2) + (run->flow ? run->flow->type->reach(run->flow, horizon) : 0.0);
}

/* Recompute the bound and every event process's majorant; return their total
 * rate. */
static double reset_events(const sim_engine *e, sim_workspace *ws, double rates[MAX_EVENTS],
                           double horizon)
{
    reset_bound(e, &ws->run, horizon);
    double total = 0.0;
    for (size_t k = 0; k < e->nevents; k++) {
        rates[k] = e->events[k].type->reset(&e->events[k], &ws->run,
                                            ws->states + e->state_offset[k], horizon);
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

void sim_engine_run(const sim_engine *e, sim_workspace *ws, uint64_t index, double *obs,
                    sim_counts *counts)
{
    const sim_scene *scene = &e->scene;
    sim_run *run = &ws->run;
    gsl_rng *rng = run->rng;
    const double mass = e->mass;
    const size_t n = run->p.n;

    sim_rng_set_stream(rng, scene->seed, index);
    memset(&run->counts, 0, sizeof run->counts);
    sim_particles_sample(&run->p, scene, rng);
    sim_observe(&run->p, mass, obs);

    const double interval = sim_scene_output_time(scene, 1);   /* between resets */
    double rates[MAX_EVENTS] = {0};
    double total = reset_events(e, ws, rates, interval);
    double t = 0.0;
    for (size_t m = 1; m < scene->outputs; m++) {
        const double t_out = sim_scene_output_time(scene, m);
        for (;;) {
            double t_next = total > 0.0 ? t + sim_rng_exponential(rng, total) : INFINITY;
            if (t_next >= t_out)
                break;
            t = t_next;
            size_t k = e->nevents == 1 ? 0 : pick_event(e, rng, rates, total);
            rates[k] = e->fire[k](&e->events[k], run, ws->states + e->state_offset[k], t);
            total = e->nevents == 1 ? rates[0] : update_rates(e, ws, rates, k);
        }
        t = t_out;
        if (run->flow)
            for (size_t i = 0; i < n; i++)
                sim_run_bring(run, i, t);
        sim_observe(&run->p, mass, obs + m * SIM_OBS_COUNT);
        total = reset_events(e, ws, rates, interval);
    }

    if (counts) {
        run->counts.normals = sim_rng_state_of(rng)->normals;
        sim_counts_add(counts, &run->counts);
    }
}

void sim_counts_add(sim_counts *to, const sim_counts *from)
{
    to->candidates += from->candidates;
    to->collisions += from->collisions;
    to->background += from->background;
    to->violations += from->violations;
    to->normals += from->normals;
}
