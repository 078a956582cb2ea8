/* The engine: scene -> effects -> the exact jump scheme (SPEC §2, §3).
 *
 * The jump scheme simulates the Markov jump process without time splitting
 * (paper A §3): candidate events arrive at rate pi_hat = Σ of the event
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
    char effects[64];
    int has_flow;
    sim_effect flow;
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
    if (scene->background.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "background",
                             "background collisions are not implemented yet");
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

    sim_status status = SIM_OK;
    if (scene->collisions.present) {
        sim_effect collisions;
        status = sim_effect_collisions(scene, &collisions, err);
        if (status == SIM_OK)
            add_event(e, collisions);
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
    for (size_t k = 0; k < e->nevents; k++)
        e->fire[k] = e->events[k].type->select_fire(&e->events[k], e->has_flow);
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

/* Recompute every event process's majorant; return their total rate. */
static double reset_events(const sim_engine *e, sim_workspace *ws, double rates[MAX_EVENTS],
                           double horizon)
{
    double total = 0.0;
    for (size_t k = 0; k < e->nevents; k++) {
        rates[k] = e->events[k].type->reset(&e->events[k], &ws->run,
                                            ws->states + e->state_offset[k], horizon);
        total += rates[k];
    }
    return total;
}

static double sum_rates(const sim_engine *e, const double *rates)
{
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
    const double mass = scene->particles.maxwellian.mass;
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
            total = e->nevents == 1 ? rates[0] : sum_rates(e, rates);
        }
        t = t_out;
        if (run->flow)
            for (size_t i = 0; i < n; i++)
                sim_run_bring(run, i, t);
        sim_observe(&run->p, mass, obs + m * SIM_OBS_COUNT);
        total = reset_events(e, ws, rates, interval);
    }

    if (counts) {
        counts->candidates += run->counts.candidates;
        counts->collisions += run->counts.collisions;
        counts->violations += run->counts.violations;
        counts->normals += sim_rng_state_of(rng)->normals;
    }
}
