/* Effects: the physical processes a scene names (docs/theory.md §2.1), as type objects.
 *
 * An effect is {type, params}: a const table of functions and the effect's
 * parameters, built once from the scene by its constructor, which the
 * registry (registry.h) names.  Two kinds:
 *
 *  - flows (sim_flow) move every particle continuously between events:
 *    white-noise heating (Brownian motion), the Gaussian and non-Gaussian
 *    thermostats, the EHS drag, the homogeneous shear, the heat-flux force.
 *    The jump scheme applies a flow lazily, a particle brought forward only
 *    when an event touches it or at an output time (`advance`, exact in
 *    distribution for any dt), or as one global linear map (`linear`).  The
 *    time-step scheme calls `step` on the whole system (flows that couple
 *    particles, such as the non-Gaussian thermostat, have only `step`).
 *
 *  - event processes (sim_event) fire at the random times of a Poisson
 *    process thinned from a majorant rate: binary collisions and collisions
 *    with a background.  `reset` computes the per-run state (majorants) from
 *    a synchronised system and returns the majorant rate; the fire function
 *    performs one candidate (accepted or fictitious) and returns the majorant
 *    rate that holds after it.
 *
 * The engine resolves everything that depends on the scene when it is built:
 * which flow is lazy or linear, which events, and for each event the fire
 * function specialised for its kernel and for the presence of a flow, so the
 * hot loop carries no branch on scene options.
 *
 * The time-step scheme (docs/theory.md §8.5) alternates whole-system stages of
 * length h: an event process's stage (Bird's collision stage: candidates at
 * the majorant rate, the fractional remainder kept in the per-run state) and
 * a flow's `step`.  Both keep the shared velocity bound covering every
 * velocity they change (sim_run_cover), so the majorant stays a true bound.
 * The Lees-Edwards slab (scheme_slab.c) calls the same effects per layer
 * (sim_flow_type.step_layer, sim_event_stages.layer).
 */
#ifndef GDSMC_SIM_EFFECT_H
#define GDSMC_SIM_EFFECT_H

#include <stddef.h>
#include <stdint.h>

#include <gsl/gsl_rng.h>

#include "error.h"
#include "scene.h"

typedef struct sim_run sim_run;         /* one ensemble in progress (run.h) */
typedef struct sim_sums sim_sums;       /* running sums of the velocities (observe.h) */
typedef struct sim_flow_type sim_flow_type;
typedef struct sim_event_type sim_event_type;

/* An effect: its type object and the parameters its constructor built from
 * the scene (owned; freed with free() by the engine). */
typedef struct sim_flow {
    const sim_flow_type *type;
    void *params;
} sim_flow;

typedef struct sim_event {
    const sim_event_type *type;
    void *params;
} sim_event;

/* ------------------------------------------------------------------ flows */

/* For a flow that maps every velocity by one affine map over a step,
 * v -> o + f (v - o) (the Gaussian thermostat, paper C Eqs. (12), (61); the
 * EHS drag, paper E Eq. (4.22), beside the lazy shear): the engine keeps the
 * map global instead of stepping every particle (docs/theory.md §8.5):
 * collisions are covariant under it, so they act on the stored velocities
 * with their rate scaled by f^lambda. */
typedef struct sim_linear_map {
    /* f over a step of h, given run->scale (the product of the factors not yet
     * applied to the stored velocities) and run->sums (of the stored velocities) */
    double (*factor)(const sim_flow *f, const sim_run *run, double h);
    int centred;      /* o = the bulk velocity (else o = 0) */
    int reads_sums;   /* factor reads run->sums (the stages keep them) */
    /* A map that flows in time, f = e^{rate h} whatever the velocities (the
     * Gaussian thermostat with a fixed zeta): rate; NULL for one that acts at
     * collisions (keep_temperature).  The jump scheme then runs candidates at
     * the rate that grows as e^{lambda rate t} (scheme_jump.c, run_jump_linear). */
    double (*rate)(const sim_flow *f);
    /* For a lazy flow that also carries the map (the homogeneous shear beside
     * the EHS drag): the sums of velocities the lazy part maps over dt, in
     * O(1); NULL otherwise.  The engine then keeps run->sums of the
     * velocities at the current time rather than of the stored ones (a
     * collision changes them: sim_event_fast.select_fire_current_sums), and
     * advances them with the flow between stages. */
    void (*advance_sums)(const sim_flow *f, sim_sums *s, double dt);
    /* For such a flow whose factor reads the temperature (the sheared EHS
     * drag): run->scale after dt more of the flow, from run->scale and
     * run->sums now, with no collision in between (the exact map between the
     * jump scheme's candidates); NULL otherwise.  The scale must not grow (the
     * engine thins by it). */
    double (*scale_after)(const sim_flow *f, const sim_run *run, double dt);
} sim_linear_map;

struct sim_flow_type {
    const char *name;   /* the effect's name in sim_engine_effects, e.g. "heating" */
    /* The jump scheme's lazy form: bring one velocity forward by dt, exact in
     * distribution for any dt; NULL if the flow has none. */
    void (*advance)(const sim_flow *f, double v[3], double dt, gsl_rng *rng);
    /* The time-step scheme's free-flight stage: move every velocity by the flow
     * over h, covering each new velocity (sim_run_cover).  NULL: the flow has
     * no time-step form. */
    void (*step)(const sim_flow *f, sim_run *run, double h);
    /* Nonzero if the step reads run->sums and keeps them current: the engine
     * then has the stages keep them too (the sheared EHS drag). */
    int step_reads_sums;
    /* How far the flow may move a velocity v in time dt, reach(dt) +
     * reach_vy(dt) |v_y|: a bound that event majorants add as a margin (for
     * random flows a bound exceeded with negligible probability; the
     * majorant-violation counter is the proof).  reach_vy is NULL but for the
     * homogeneous shear, which moves V_x by a dt V_y. */
    double (*reach)(const sim_flow *f, double dt);
    double (*reach_vy)(const sim_flow *f, double dt);
    /* For a flow whose increment over dt is Gaussian with mean 0 and the same
     * variance in each component, independent of the velocity (white noise):
     * that variance per unit time; NULL otherwise.  Conditional observation
     * (observe.h, sim_observe_sums) needs it. */
    double (*spread)(const sim_flow *f);
    const sim_linear_map *linear;   /* the map kept global, or NULL */
    /* The Lees-Edwards slab's per-layer stage (scheme_slab.c): move the layer's
     * count velocities v by the flow over h, given the layer's fields at the
     * start of the step (velocity u, theta = T_I/m, density n_I/n); NULL: the
     * flow has no per-layer form. */
    void (*step_layer)(const sim_flow *f, double (*v)[3], size_t count, const double u[3],
                       double theta, double density, double h);
};

/* ----------------------------------------------------------------- events */

typedef double (*sim_event_fire_fn)(const sim_event *e, sim_run *run, void *state, double t);
typedef void (*sim_event_stage_fn)(const sim_event *e, sim_run *run, void *state, double h);
/* Fire up to `max` (>= 1) candidates in a row, as `fire` would one by one,
 * and stop after the first one that changes the majorant rate; returns the
 * number fired and sets *rate to the rate after the last. */
typedef uint64_t (*sim_event_fire_many_fn)(const sim_event *e, sim_run *run, void *state,
                                          uint64_t max, double *rate);

/* The jump scheme's optional fast paths (each may be NULL, or return NULL). */
typedef struct sim_event_fast {
    /* As select_fire, for an engine that observes from running sums
     * (observe.h, sim_sums): the fire function also keeps run->sums current
     * for every particle it changes or brings forward. */
    sim_event_fire_fn (*select_fire_sums)(const sim_event *e, int lazy_flow, int bounded);
    /* As select_fire with a lazy flow that has a linear map with advance_sums,
     * for an engine that keeps run->sums at the candidates' time t: the fire
     * function brings the particles it draws to t and keeps the sums current
     * for every velocity it changes. */
    sim_event_fire_fn (*select_fire_current_sums)(const sim_event *e);
    /* For an engine in which this is the only event process and no flow is
     * lazy, so candidate times are never needed (scheme_jump.c). */
    sim_event_fire_many_fn (*select_fire_many)(const sim_event *e);
} sim_event_fast;

/* The time-step scheme's forms of a process (NULL: it has none, and the
 * time-step scheme refuses it). */
typedef struct sim_event_stages {
    /* The stage of length h (NULL, or NULL returned: the engine's stage, which
     * fires the process's candidates at its majorant rate for the stage
     * time); with sums, the stage also keeps run->sums current.  The per-run
     * state is zeroed at the start of each run and `reset` is called at each
     * output time, as in the jump scheme. */
    sim_event_stage_fn (*select)(const sim_event *e, int sums);
    /* Nonzero if the stage may be replaced by the process's jump candidates
     * fired at the stage's time, as the engine does beside a lazy flow (an
     * algorithm such as the contact rule, which the batched stage draws
     * without bringing particles, may not). */
    int (*fires_candidates)(const sim_event *e);
    /* The Lees-Edwards slab's per-layer stage (scheme_slab.c): the process's
     * candidates for h among the layer's count >= 2 particles from index lo,
     * whose velocities lie within *radius of u (the layer's bound, which the
     * stage grows to cover what it changes); NULL: no per-layer form. */
    void (*layer)(const sim_event *e, sim_run *run, size_t lo, size_t count, const double u[3],
                  double *radius, double h);
} sim_event_stages;

struct sim_event_type {
    const char *name;   /* the effect's name in sim_engine_effects, e.g. "collisions" */
    size_t state_size;  /* the per-run state (zeroed at the start of each run) */
    /* Nonzero if the majorant uses the shared velocity bound (run.h). */
    int (*needs_bound)(const sim_event *e);
    /* Optional (may be NULL): a fixed centre this process wants for the bound,
     * e.g. the background velocity u_B of paper B's Algorithm 2; returns 1 and
     * sets centre, or 0 (then the engine uses the bulk velocity). */
    int (*bound_centre)(const sim_event *e, double centre[3]);
    /* horizon: the time until the next reset (the next output time, or
     * sooner with a lazy flow: scheme_jump.c, lazy_reset).  Called after the
     * engine has set the bound; returns the majorant rate. */
    double (*reset)(const sim_event *e, sim_run *run, void *state, double horizon);
    /* The majorant rate now, after another process grew the bound. */
    double (*rate)(const sim_event *e, const sim_run *run, void *state);
    /* Choose the fire function for this engine: lazy_flow says whether a flow
     * must bring particles forward before they are used, bounded whether the
     * engine maintains the velocity bound (then every velocity change must be
     * covered).  `fire` performs one candidate at time t (accepted or
     * fictitious) and returns the majorant rate that holds after it. */
    sim_event_fire_fn (*select_fire)(const sim_event *e, int lazy_flow, int bounded);
    /* For a process covariant under a flow's linear map v -> o + f (v - o)
     * (binary collisions: translation and scaling commute with the rule), the
     * exponent lambda by which its rate scales, as f^lambda; NULL otherwise
     * (the engine then keeps no map global beside it). */
    double (*rate_exponent)(const sim_event *e);
    const sim_event_fast *fast;       /* optional fast paths, or NULL */
    const sim_event_stages *stages;   /* the time-step forms, or NULL */
};

/* Constructors: fill *flow or *event from the scene's section (which must be
 * present).  They check what the engine supports (for the scene's scheme) and
 * name the scene key otherwise.  The registry (registry.h) lists them. */
sim_status sim_effect_collisions(const sim_scene *scene, sim_event *event, sim_error *err);
sim_status sim_effect_background(const sim_scene *scene, sim_event *event, sim_error *err);
sim_status sim_effect_heating(const sim_scene *scene, sim_flow *flow, sim_error *err);
sim_status sim_effect_heat_flux(const sim_scene *scene, sim_flow *flow, sim_error *err);
sim_status sim_effect_shear(const sim_scene *scene, sim_flow *flow, sim_error *err);
sim_status sim_effect_ehs_drag(const sim_scene *scene, sim_flow *flow, sim_error *err);
sim_status sim_effect_bath(const sim_scene *scene, sim_flow *flow, sim_error *err);
/* The homogeneous shear and the EHS drag as one flow (effect_drag.c). */
sim_status sim_effect_sheared_ehs_drag(const sim_scene *scene, sim_flow *flow, sim_error *err);

/* The homogeneous shear over a time dt with ah = a dt (effect_shear.c; the
 * sheared EHS drag shares it): a velocity, V_x <- V_x - ah V_y, and the running
 * sums of velocities it maps; and a flow's reach of 0 (the shear's whole reach
 * is its reach_vy). */
static inline void sim_shear_velocity(double v[3], double ah)
{
    v[0] -= ah * v[1];
}
void sim_shear_sums(sim_sums *s, double ah);
double sim_reach_none(const sim_flow *f, double dt);

#endif
