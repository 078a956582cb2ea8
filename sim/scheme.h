/* The schemes behind the engine, and the engine's state they share
 * (docs/theory.md §8).  Internal to sim/.
 *
 * A scheme is a type object: the exact jump scheme (scheme_jump.c, §8.3), the
 * time-step scheme (scheme_timestep.c, §8.5) and the Lees-Edwards slab
 * (scheme_slab.c, §6.3), the time-step scheme with positions.  The engine
 * (engine.c) builds the effects from the registry, lets the scheme accept the
 * scene and resolve its loop once, and runs it; the scheme fills the output
 * rows through sim_engine_observe_output.
 */
#ifndef GDSMC_SIM_SCHEME_H
#define GDSMC_SIM_SCHEME_H

#include <stddef.h>
#include <stdint.h>

#include "effect.h"
#include "engine.h"
#include "registry.h"
#include "run.h"
#include "scene.h"

/* Each registry entry adds at most one effect, so no scene exceeds these
 * (registry.c holds the table to SIM_EFFECTS_MAX at compile time). */
#define SIM_EVENTS_MAX SIM_EFFECTS_MAX
#define SIM_FLOWS_MAX SIM_EFFECTS_MAX
#define SIM_OBSERVERS_MAX SIM_EFFECTS_MAX

typedef void (*sim_step_fn)(const sim_engine *e, sim_workspace *ws, double h);
typedef void (*sim_interval_fn)(const sim_engine *e, sim_workspace *ws);
typedef uint64_t (*sim_fire_some_fn)(const sim_engine *e, sim_workspace *ws, double *rates,
                                     double *total, uint64_t max);

/* A scheme's per-thread state (the slab's layers and buffers). */
typedef struct sim_scheme_state {
    size_t (*bytes)(const sim_engine *e, size_t n);   /* for n particles */
    sim_status (*create)(const sim_engine *e, sim_workspace *ws, sim_error *err);
    void (*free)(void *state);
} sim_scheme_state;

typedef struct sim_scheme_type {
    /* The name it adds before the effects' in sim_engine_effects when it is an
     * effect of its own (the slab's "slab"), or NULL. */
    const char *effect_name;
    /* Nonzero if the scene asks for this scheme. */
    int (*claims)(const sim_scene *scene);
    /* Refuse, naming the key, a scene the scheme cannot simulate, once the
     * event processes are built and before the flows are; NULL: any. */
    sim_status (*accept)(const sim_scene *scene, sim_error *err);
    /* Refuse an event process the scheme cannot run for the scene, naming its
     * section (the time-step schemes need its stages); NULL: any. */
    sim_status (*accept_event)(const sim_scene *scene, const sim_event *event, sim_error *err);
    /* Refuse, once the engine's modes are resolved (engine.c), a flow the
     * scheme would never apply; NULL: none. */
    sim_status (*check)(const sim_engine *e, sim_error *err);
    /* Resolve the loop once everything else is. */
    sim_status (*build)(sim_engine *e, sim_error *err);
    const sim_scheme_state *state;   /* per-thread state, or NULL */
    /* After the initial state is drawn (NULL: nothing to do). */
    void (*start)(const sim_engine *e, sim_workspace *ws);
    /* From t = 0 to t_end: every output row after row 0. */
    void (*evolve)(const sim_engine *e, sim_workspace *ws, double *obs, size_t *samples);
    /* The output row from the scheme's own observer (NULL: the engine's);
     * returns the system the steady observers see. */
    const sim_particles *(*observe)(const sim_engine *e, sim_workspace *ws, size_t m,
                                    const double *prev, double *row);
} sim_scheme_type;

/* The time-step schemes' accept_event: with scheme = timestep, the process
 * has stages. */
sim_status sim_scheme_needs_stages(const sim_scene *scene, const sim_event *event,
                                   sim_error *err);

extern const sim_scheme_type sim_scheme_jump, sim_scheme_timestep, sim_scheme_slab;

struct sim_engine {
    sim_scene scene;
    const sim_scheme_type *scheme;
    double mass;          /* the grain mass */
    char effects[64];
    size_t nflows;        /* the flows in the order of a step (registry.h, flow_order) */
    sim_flow flows[SIM_FLOWS_MAX];
    const sim_effect_entry *flow_entries[SIM_FLOWS_MAX];   /* their registry entries */
    int lazy_flow;        /* flows[0] is applied lazily (stamps): white noise, the shear */
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
    sim_event events[SIM_EVENTS_MAX];
    sim_event_fire_fn fire[SIM_EVENTS_MAX];
    size_t state_offset[SIM_EVENTS_MAX];
    size_t state_bytes;
    /* jump scheme without a lazy flow (run_jump_counted) */
    sim_fire_some_fn fire_some;        /* the candidates of a span, up to a change of rate */
    sim_event_fire_many_fn fire_many;  /* the only process's own loop, or NULL */
    uint64_t rebound_every;            /* candidates between bound recomputations */
    /* time-step scheme */
    sim_event_stage_fn stage[SIM_EVENTS_MAX];
    sim_step_fn step;         /* Lie (euler) step, or collisions only */
    sim_step_fn stages;       /* the stages of a step (scaled by a linear flow's factor) */
    sim_step_fn flow_step;    /* the flows of a step (or the linear flow's factor) */
    sim_interval_fn interval; /* one output interval of steps */
    size_t steps;         /* steps per output interval */
    double h;             /* the step */
    size_t observables;   /* per output row (sim_engine_observables) */
    void *scheme_params;  /* the scheme's own (the slab's layers), freed with free_params */
    void (*free_params)(void *params);
    /* steady-state observers */
    size_t nsteady;
    size_t steady_from;   /* first output index with t >= steady.from */
    /* the effects' own observers of the row (registry.h), in the table's order */
    size_t nobservers;
    const sim_effect_entry *observers[SIM_OBSERVERS_MAX];
};

struct sim_workspace {
    sim_run run;
    unsigned char *states;   /* the event processes' per-run states */
    gsl_rng *observer_rng;   /* pair sampling (shear and steady observers), or NULL */
    void *scheme_state;      /* the scheme's per-thread state (the slab's), or NULL */
    void (*free_state)(void *state);   /* ... and how to free it */
    double *steady_sum;      /* [nsteady] sums of the samples of the current run */
    size_t samples;          /* how many samples those sums hold */
    size_t steps;            /* time-step scheme: steps in the current output interval */
    double h;                /* ... and their length */
    double t0;               /* ... and its start */
    double rates[SIM_EVENTS_MAX];  /* ... with a lazy flow: the processes' majorant rates */
    double credit[SIM_EVENTS_MAX]; /* ... and the stage time they have not spent */
    int time_outputs;        /* add the time of output times to output_seconds */
    double output_seconds;
};

/* With a lazy flow the bound carries the flow's reach (7 sigma of white
 * noise's increment; |a| dt |V_y| for the shear) over the span until the next
 * reset (reset_bound), so a long span inflates the majorant: with resets only
 * at paper A Ex 5's output times, 1.6 apart, 12.2 candidates per hard-sphere
 * collision (split-ex5's jump rows, n = 1024).  Runs with a lazy flow and a
 * bounded process therefore also reset every SIM_LAZY_REBOUND_SWEEPS n
 * candidates or so (scheme_jump.c, lazy_reset; scheme_timestep.c,
 * interval_lazy): 6.8 candidates per collision there.  A reset brings no
 * particle (each keeps its own reach from its stamp; about 2n square roots)
 * and is exact anywhere, the waiting times being memoryless.  Resets every 1,
 * 2 and 4 n candidates cost the same CPU time within this machine's noise. */
#define SIM_LAZY_REBOUND_SWEEPS 2

static inline double sim_lazy_candidates(const sim_engine *e)
{
    return SIM_LAZY_REBOUND_SWEEPS * (double)e->scene.particles.n;
}

/* Recompute the velocity bound at time t (with a lazy flow, each particle's
 * reach to t + horizon) and every event process's majorant; returns their
 * total rate (engine.c). */
double sim_engine_reset_events(const sim_engine *e, sim_workspace *ws,
                               double rates[SIM_EVENTS_MAX], double t, double horizon);

/* Output time m at time t after the events: the lazy flow's pending
 * increments drawn (unless observation is conditional), the observables, a
 * steady sample (engine.c). */
void sim_engine_observe_output(const sim_engine *e, sim_workspace *ws, size_t m, double t,
                               double *obs, size_t *samples);

/* Apply a linear flow's pending factor run->scale to every stored velocity
 * (at output times); the running sums follow (engine.c). */
void sim_engine_apply_linear(const sim_engine *e, sim_run *run);

/* The steps of the output interval that starts at output m - 1 into ws->steps
 * and ws->h: the engine's, or with step_follows_temperature the largest
 * h <= dt sqrt(T0/T) that divides the interval (engine.c). */
void sim_engine_interval_steps(const sim_engine *e, sim_workspace *ws, const double *obs,
                               size_t m);

/* Bring every particle to time t with the lazy flow. */
static inline void sim_run_bring_all(sim_run *run, double t)
{
    for (size_t i = 0; i < run->p.n; i++)
        sim_run_bring(run, i, t);
}

#endif
