/* The DSMC engine (docs/theory.md §8): built once from a scene, then run for any
 * number of ensembles.
 *
 * Lifecycle (as CVODE's): sim_engine_create, then per thread a workspace,
 * sim_engine_run for each ensemble index, sim_workspace_free, sim_engine_free.
 * The engine is immutable after creation and may be shared by threads; a
 * workspace belongs to one thread.  Both _free functions accept NULL.
 */
#ifndef GDSMC_SIM_ENGINE_H
#define GDSMC_SIM_ENGINE_H

#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "observe.h"
#include "particles.h"
#include "scene.h"

typedef struct sim_engine sim_engine;
typedef struct sim_workspace sim_workspace;

/* What one or more runs did. */
typedef struct sim_counts {
    uint64_t candidates;   /* candidate events drawn (accepted + fictitious) */
    uint64_t collisions;   /* accepted binary collisions */
    uint64_t background;   /* accepted collisions with the background (paper B) */
    uint64_t violations;   /* candidates whose true rate exceeded the majorant in use */
    uint64_t normals;      /* standard normal variates drawn (initial state included) */
} sim_counts;

/* to += from, field by field. */
void sim_counts_add(sim_counts *to, const sim_counts *from);

/* Build the engine for a validated scene: the scheme and the effects it names
 * (sim/registry.c), each resolved once.  What it accepts (tests/
 * test_sim_contract.c builds every combination of scheme and effects and
 * holds the engine to this list):
 *
 *  - scheme = jump: [collisions] of any kernel, [background], and at most one
 *    flow: white-noise heating, [bath] or [shear] (homogeneous) beside any
 *    events;
 *    the Gaussian thermostat (a fixed zeta or keep_temperature) with
 *    [collisions] as the only event process; the EHS drag (collisions.model
 *    = ehs, restitution < 1) only with [shear] and [collisions] as the only
 *    event process.  No non-Gaussian thermostat (heating.type), no
 *    [heat-flux] (scene.scheme).  Refused, naming heating.type (or
 *    scene.scheme, collisions.model, collisions), when a flow would not be
 *    applied.  observation = conditional: at most white-noise heating, no
 *    [bath], [shear] or [steady] (scene.observation).
 *  - scheme = timestep: [collisions] of any kernel, rule and model, the
 *    three thermostats, [bath], [shear] (homogeneous), [heat-flux] without [heating]
 *    (heating.type); no [background] (background), no conditional
 *    observation (scene.observation).
 *  - [shear] boundary = lees-edwards (the slab): scheme = timestep,
 *    hard-sphere [collisions] (ihs or ehs), splitting = euler, nothing else
 *    (shear.boundary; background for a [background]).
 *
 * Returns SIM_EUNSUPPORTED, naming the scene key, for a valid combination
 * outside that list, SIM_EINVAL for values the parser should have refused,
 * SIM_ENOMEM. */
sim_status sim_engine_create(const sim_scene *scene, sim_engine **engine, sim_error *err);
void sim_engine_free(sim_engine *engine);

/* The scene the engine was built from (a copy it owns). */
const sim_scene *sim_engine_scene(const sim_engine *engine);

/* Names of the effects in the engine's loop, for reports and tests, e.g.
 * "collisions heating"; "" for free flight. */
const char *sim_engine_effects(const sim_engine *engine);

/* Number of steady-state quantities each run appends (steady.h): 0 without a
 * [steady] section. */
size_t sim_engine_steady_count(const sim_engine *engine);

/* Observables recorded at every output time: the row length of obs below.
 * The base set (observe.h) comes first; an effect that records more (a
 * profile, a series of moments) extends the row, so no scene is capped. */
size_t sim_engine_observables(const sim_engine *engine);

/* Bytes one workspace (sim_workspace_create) holds: its n particles and the
 * effects' state; for refusing runs that cannot fit before allocating. */
size_t sim_engine_workspace_bytes(const sim_engine *engine);

/* The time-step scheme's step h (the largest h <= scene.dt dividing the
 * output interval); 0 for the jump scheme. */
double sim_engine_step(const sim_engine *engine);

/* The same from the scene alone, without building an engine: *h and the
 * *steps per output interval (0 and 0 for the jump scheme).  SIM_EINVAL,
 * naming scene.dt, for a step that is not positive or gives more than 1e12
 * steps per interval. */
sim_status sim_scene_step(const sim_scene *scene, double *h, size_t *steps, sim_error *err);

/* Per-thread memory: the particle system, the random stream, effect states. */
sim_status sim_workspace_create(const sim_engine *engine, sim_workspace **ws, sim_error *err);
void sim_workspace_free(sim_workspace *ws);

/* The particles of the workspace's last run as they are stored (with a lazy
 * flow and conditional observation, each at its own stamp), for tests. */
const sim_particles *sim_workspace_particles(const sim_workspace *ws);

/* For the bench: with on, every later run adds the time its output times
 * take (the pending increments drawn and the observables computed, not the
 * events' own upkeep of running sums; a monotonic clock, as the thread's CPU
 * clock costs a system call per read) to a total, reset here. */
void sim_workspace_time_outputs(sim_workspace *ws, int on);
double sim_workspace_output_seconds(const sim_workspace *ws);

/* Simulate ensemble `index` (its random stream is (scene seed, index)) from
 * t = 0 to t_end.  obs must hold outputs * sim_engine_observables() +
 * sim_engine_steady_count() doubles; row m gets the observables at output
 * time m, and the steady-state time averages (steady.h) follow the last row.
 * counts (may be NULL) is incremented. */
void sim_engine_run(const sim_engine *engine, sim_workspace *ws, uint64_t index, double *obs,
                    sim_counts *counts);

/* sim_engine_run in its two parts, for timing the evolution alone (the
 * bench): sim_engine_start draws ensemble `index`'s initial state and
 * observes it (row 0 of obs); sim_engine_evolve then simulates to t_end and
 * fills the other rows.  Call them in this order, with the same obs. */
void sim_engine_start(const sim_engine *engine, sim_workspace *ws, uint64_t index, double *obs);
void sim_engine_evolve(const sim_engine *engine, sim_workspace *ws, double *obs,
                       sim_counts *counts);

#endif
