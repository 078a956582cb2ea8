/* Effects: the physical processes a scene names (SPEC §2), as type objects.
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
 */
#ifndef GDSMC_SIM_EFFECT_H
#define GDSMC_SIM_EFFECT_H

#include <stddef.h>

#include <gsl/gsl_rng.h>

#include "error.h"
#include "scene.h"

typedef struct sim_run sim_run;         /* one ensemble in progress (run.h) */
typedef struct sim_effect sim_effect;

typedef double (*sim_event_fire_fn)(const sim_effect *e, sim_run *run, void *state, double t);

typedef struct sim_effect_type {
    const char *name;   /* the scene section, e.g. "heating" */

    /* Flows (NULL for event processes). */
    void (*advance)(const sim_effect *e, double v[3], double dt, gsl_rng *rng);
    void (*step)(const sim_effect *e, sim_run *run, double h);
    /* How far the flow may move a velocity in time dt: a bound that event
     * majorants add as a margin (for random flows a bound exceeded with
     * negligible probability; the majorant-violation counter is the proof). */
    double (*reach)(const sim_effect *e, double dt);

    /* Event processes (NULL for flows). */
    size_t state_size;
    /* Nonzero if the majorant uses the shared velocity bound (run.h). */
    int (*needs_bound)(const sim_effect *e);
    /* Optional (may be NULL): a fixed centre this process wants for the bound,
     * e.g. the background velocity u_B of paper B's Algorithm 2; returns 1 and
     * sets centre, or 0 (then the engine uses the bulk velocity). */
    int (*bound_centre)(const sim_effect *e, double centre[3]);
    /* horizon: the time until the next reset (the next output time).  Called
     * after the engine has set the bound. */
    double (*reset)(const sim_effect *e, sim_run *run, void *state, double horizon);
    /* The majorant rate now, after another process grew the bound. */
    double (*rate)(const sim_effect *e, const sim_run *run, void *state);
    /* Choose the fire function for this engine: lazy_flow says whether a flow
     * must bring particles forward before they are used, bounded whether the
     * engine maintains the velocity bound (then every velocity change must be
     * covered). */
    sim_event_fire_fn (*select_fire)(const sim_effect *e, int lazy_flow, int bounded);
} sim_effect_type;

struct sim_effect {
    const sim_effect_type *type;
    void *params;   /* owned; freed with free() by the engine */
};

/* Constructors: fill *effect from the scene's section (which must be present).
 * They check what the engine supports and name the scene key otherwise. */
sim_status sim_effect_collisions(const sim_scene *scene, sim_effect *effect, sim_error *err);
sim_status sim_effect_heating(const sim_scene *scene, sim_effect *effect, sim_error *err);
sim_status sim_effect_background(const sim_scene *scene, sim_effect *effect, sim_error *err);

#endif
