/* Effects: the physical processes a scene names (docs/theory.md §2.1), as type objects.
 *
 * An effect is {type, params}: a const table of functions and the effect's
 * parameters, built once from the scene by its constructor.  Two kinds:
 *
 *  - flows move every particle continuously between events: white-noise
 *    heating (Brownian motion), and later the Gaussian and non-Gaussian
 *    thermostats, drag, homogeneous shear, the heat-flux force.  The jump
 *    scheme applies a flow lazily: a particle is brought forward only when an
 *    event touches it or at an output time, with `advance`, which must be exact
 *    in distribution for any dt.  The time-step scheme calls `step` on the whole
 *    system (flows that couple particles, such as the non-Gaussian thermostat,
 *    have only `step`).
 *
 *  - event processes fire at the random times of a Poisson process thinned
 *    from a majorant rate: binary collisions and collisions with a background.  `reset` computes the per-run state (majorants) from a
 *    synchronised system and returns the majorant rate; `fire` performs one
 *    candidate event at time t (accepted or fictitious) and returns the
 *    majorant rate that holds after it.
 *
 * The engine resolves everything that depends on the scene when it is built:
 * which flow (at most one lazy flow in the jump scheme), which events, and for
 * each event the `fire` specialised for its kernel and for the presence of a
 * flow, so the hot loop carries no branch on scene options.
 *
 * The time-step scheme (docs/theory.md §8.5) alternates whole-system stages of length
 * h: an event process's `stage` (Bird's collision stage: candidates at the
 * majorant rate, the fractional remainder kept in the per-run state) and a
 * flow's `step`.  Both keep the shared velocity bound covering every velocity
 * they change (sim_run_cover), so the majorant stays a true bound.
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
typedef struct sim_effect sim_effect;

typedef double (*sim_event_fire_fn)(const sim_effect *e, sim_run *run, void *state, double t);
typedef void (*sim_event_stage_fn)(const sim_effect *e, sim_run *run, void *state, double h);
/* Fire up to `max` (>= 1) candidates in a row, as `fire` would one by one,
 * and stop after the first one that changes the majorant rate; returns the
 * number fired and sets *rate to the rate after the last. */
typedef uint64_t (*sim_event_fire_many_fn)(const sim_effect *e, sim_run *run, void *state,
                                          uint64_t max, double *rate);

typedef struct sim_effect_type {
    const char *name;   /* the scene section, e.g. "heating" */

    /* Flows (NULL for event processes). */
    void (*advance)(const sim_effect *e, double v[3], double dt, gsl_rng *rng);
    /* The time-step scheme's free-flight stage: move every velocity by the flow
     * over h, covering each new velocity (sim_run_cover).  NULL: the flow has
     * no time-step form. */
    void (*step)(const sim_effect *e, sim_run *run, double h);
    /* Nonzero if the step reads run->sums and keeps them current: the engine
     * then has the stages keep them too (the sheared EHS drag). */
    int step_reads_sums;
    /* How far the flow may move a velocity v in time dt, reach(dt) +
     * reach_vy(dt) |v_y|: a bound that event majorants add as a margin (for
     * random flows a bound exceeded with negligible probability; the
     * majorant-violation counter is the proof).  reach_vy is NULL but for the
     * homogeneous shear, which moves V_x by a dt V_y. */
    double (*reach)(const sim_effect *e, double dt);
    double (*reach_vy)(const sim_effect *e, double dt);
    /* For a flow whose increment over dt is Gaussian with mean 0 and the same
     * variance in each component, independent of the velocity (white noise):
     * that variance per unit time; 0 otherwise.  Conditional observation
     * (observe.h, sim_observe_sums) needs it. */
    double (*spread)(const sim_effect *e);
    /* For a flow that maps every velocity by one affine map over a step,
     * v -> o + f (v - o) (the Gaussian thermostat, paper C Eqs. (12), (61);
     * the EHS drag, paper E Eq. (4.22), beside the lazy shear: advance_sums):
     * the factor f over a step of h, given the run (run->scale, the product of
     * the factors not yet applied to the stored velocities, and run->sums, of
     * the stored velocities); NULL otherwise.  The engine then keeps the map
     * global instead of stepping every particle (engine.c): collisions are
     * covariant under it, so they act on the stored velocities with their rate
     * scaled by f^lambda. */
    double (*linear_factor)(const sim_effect *e, const sim_run *run, double h);
    int linear_centred;      /* ... o = the bulk velocity (else o = 0) */
    int linear_reads_sums;   /* ... f reads run->sums (the stages keep them) */
    /* ... a map that flows in time, f = e^{rate h} whatever the velocities (the
     * Gaussian thermostat with a fixed zeta): rate; NULL for one that acts at
     * collisions (keep_temperature).  The jump scheme then runs candidates at
     * the rate that grows as e^{lambda rate t} (engine.c, run_jump_linear). */
    double (*linear_rate)(const sim_effect *e);
    /* For a lazy flow that is deterministic and linear and also carries a
     * global map (the homogeneous shear beside the EHS drag): the sums of
     * velocities the flow maps over dt, mapped in O(1); NULL otherwise.  With it the engine
     * keeps run->sums of the velocities at the current time rather than of the
     * stored ones: bringing a particle forward leaves them as they are, a
     * collision changes them (select_fire_current_sums), and the engine
     * advances them with the flow between stages (engine.c, interval_lazy). */
    void (*advance_sums)(const sim_effect *e, sim_sums *s, double dt);
    /* For such a flow with a global map whose rate reads the temperature (the
     * sheared EHS drag): run->scale after dt more of the flow, from run->scale
     * and run->sums now, with no collision in between (the exact map between
     * the jump scheme's candidates: engine.c, run_jump_lazy_linear); NULL
     * otherwise.  The scale must not grow (the engine thins by it). */
    double (*scale_after)(const sim_effect *e, const sim_run *run, double dt);

    /* Event processes (NULL for flows). */
    size_t state_size;
    /* Nonzero if the majorant uses the shared velocity bound (run.h). */
    int (*needs_bound)(const sim_effect *e);
    /* Optional (may be NULL): a fixed centre this process wants for the bound,
     * e.g. the background velocity u_B of paper B's Algorithm 2; returns 1 and
     * sets centre, or 0 (then the engine uses the bulk velocity). */
    int (*bound_centre)(const sim_effect *e, double centre[3]);
    /* horizon: the time until the next reset (the next output time, or
     * sooner with a lazy flow: engine.c, lazy_reset).  Called after the
     * engine has set the bound. */
    double (*reset)(const sim_effect *e, sim_run *run, void *state, double horizon);
    /* The majorant rate now, after another process grew the bound. */
    double (*rate)(const sim_effect *e, const sim_run *run, void *state);
    /* Choose the fire function for this engine: lazy_flow says whether a flow
     * must bring particles forward before they are used, bounded whether the
     * engine maintains the velocity bound (then every velocity change must be
     * covered). */
    sim_event_fire_fn (*select_fire)(const sim_effect *e, int lazy_flow, int bounded);
    /* Optional (may be NULL, or return NULL): as select_fire, for an engine
     * that observes from running sums (observe.h, sim_sums): the fire function
     * also keeps run->sums current for every particle it changes or brings
     * forward (scene.observation = conditional, issue 18). */
    sim_event_fire_fn (*select_fire_sums)(const sim_effect *e, int lazy_flow, int bounded);
    /* Optional (may be NULL, or return NULL): as select_fire with a lazy flow
     * that has advance_sums, for an engine that keeps run->sums at the
     * candidates' time t: the fire function brings the particles it draws to t
     * and keeps the sums current for every velocity it changes. */
    sim_event_fire_fn (*select_fire_current_sums)(const sim_effect *e);
    /* The time-step scheme's stage of length h for this process (NULL, or
     * NULL returned: the engine's stage, which fires the process's candidates
     * at its majorant rate for the stage time); with sums, the stage also keeps
     * run->sums current (a linear flow that reads the temperature, engine.c).
     * The per-run state is zeroed at the start of each run and `reset` is
     * called at each output time, as in the jump scheme. */
    sim_event_stage_fn (*select_stage)(const sim_effect *e, int sums);
    /* Optional (may be NULL): the fast path of the jump scheme for an engine in
     * which this is the only event process and no flow is lazy, so candidate
     * times are never needed (engine.c).  See sim_event_fire_many_fn. */
    sim_event_fire_many_fn (*select_fire_many)(const sim_effect *e);
} sim_effect_type;

struct sim_effect {
    const sim_effect_type *type;
    void *params;   /* owned; freed with free() by the engine */
};

/* Constructors: fill *effect from the scene's section (which must be present).
 * They check what the engine supports (for the scene's scheme) and name the
 * scene key otherwise. */
sim_status sim_effect_collisions(const sim_scene *scene, sim_effect *effect, sim_error *err);
sim_status sim_effect_heating(const sim_scene *scene, sim_effect *effect, sim_error *err);
sim_status sim_effect_background(const sim_scene *scene, sim_effect *effect, sim_error *err);
sim_status sim_effect_heat_flux(const sim_scene *scene, sim_effect *effect, sim_error *err);
sim_status sim_effect_shear(const sim_scene *scene, sim_effect *effect, sim_error *err);
sim_status sim_effect_ehs_drag(const sim_scene *scene, sim_effect *effect, sim_error *err);
/* The homogeneous shear and the EHS drag as one flow (effect_drag.c). */
sim_status sim_effect_sheared_ehs_drag(const sim_scene *scene, sim_effect *effect,
                                       sim_error *err);

/* The homogeneous shear over a time dt with ah = a dt (effect_shear.c; the
 * sheared EHS drag shares it): a velocity, V_x <- V_x - ah V_y, and the running
 * sums of velocities it maps; and a flow's reach of 0 (the shear's whole reach
 * is its reach_vy). */
static inline void sim_shear_velocity(double v[3], double ah)
{
    v[0] -= ah * v[1];
}
void sim_shear_sums(sim_sums *s, double ah);
double sim_reach_none(const sim_effect *e, double dt);

#endif
