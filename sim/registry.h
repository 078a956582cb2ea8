/* The registry of effects (docs/theory.md §2.1): every effect a scene can
 * name, in one table (registry.c).
 *
 * An entry says how to tell that a scene names the effect, how to build it,
 * where it stands among the flows of a step, and which columns it adds to the
 * output row and to the steady quantities.  The engine builds itself by
 * walking the table (engine.c names no effect); steady.c and observe.c take
 * the columns' offsets from it, and verify's references refuse an effect no
 * reference models.  A new effect is one file with its type object and
 * constructor, and one line here (its section's keys go to the scene:
 * docs/layout.md, "Adding an effect").
 *
 * A fused flow (the homogeneous shear with the EHS drag, read from running
 * sums in one pass) declares the flows it replaces: it is used instead of
 * them when all of them are present and no other flow is (another flow would
 * move the particles behind the sums' back).
 */
#ifndef GDSMC_SIM_REGISTRY_H
#define GDSMC_SIM_REGISTRY_H

#include <stddef.h>
#include <stdint.h>

#include <gsl/gsl_rng.h>

#include "effect.h"
#include "engine.h"
#include "error.h"
#include "particles.h"
#include "scene.h"
#include "steady.h"

#define SIM_FUSES_MAX 2   /* flows one fused flow replaces */

/* An effect's observer of the output row (the shear's: effect_shear.c): at
 * output m, from the system p of grains of mass `mass`, the run's counts so
 * far, the row before (NULL at m = 0) and the observers' stream. */
typedef void (*sim_effect_observe_fn)(const sim_scene *scene, const sim_particles *p,
                                      double mass, const sim_counts *counts, size_t m,
                                      const double *prev, gsl_rng *rng, double *row);

/* The shear's observer (sim_observe_shear with the run's collisions). */
void sim_shear_observe(const sim_scene *scene, const sim_particles *p, double mass,
                       const sim_counts *counts, size_t m, const double *prev, gsl_rng *rng,
                       double *row);

/* The most entries the table may hold (a compile-time check in registry.c):
 * the engine sizes its effects by it. */
#define SIM_EFFECTS_MAX 16

typedef struct sim_effect_entry {
    const char *section;   /* its name, the scene section for most, e.g. "heating" */
    /* The scene names it (NULL: a fused flow, present when its parts are). */
    int (*present)(const sim_scene *scene);
    /* One of the two constructors (effect.h); the other is NULL. */
    sim_status (*create_event)(const sim_scene *scene, sim_event *event, sim_error *err);
    sim_status (*create_flow)(const sim_scene *scene, sim_flow *flow, sim_error *err);
    int flow_order;        /* flows are applied in increasing order within a step */
    const char *fuses[SIM_FUSES_MAX];   /* a fused flow: the sections it replaces */
    /* The key a refusal names when the jump scheme cannot apply the flow (it is
     * neither lazy nor a global map there); NULL: scene.scheme. */
    const char *jump_key;
    /* The quantities it adds to the steady ones (steady.h) after the base
     * quantities, in the table's order, or NULL. */
    const sim_steady_block *steady;
    /* The observables it adds to the output row after the base set, computed
     * from every particle (so it refuses conditional observation and
     * observe_only): their number for the scene, or NULL. */
    size_t (*observables)(const sim_scene *scene);
    /* ... and its observer of the row (after the base set; NULL: the scheme
     * observes them, as the slab does), and whether it draws pairs from the
     * observers' random stream (NULL: never). */
    sim_effect_observe_fn observe;
    int (*observe_draws)(const sim_scene *scene);
} sim_effect_entry;

extern const sim_effect_entry sim_registry[];
extern const size_t sim_registry_count;

/* The entry of that name, or NULL. */
const sim_effect_entry *sim_registry_find(const char *section);

/* The first steady column of entry `section` for the scene: the base
 * quantities, then the columns of the entries before it in the table. */
size_t sim_registry_steady_first(const sim_scene *scene, const char *section);

/* Every steady column the entries add for the scene. */
size_t sim_registry_steady_columns(const sim_scene *scene);

/* The block that holds steady quantity k and its first index, or NULL (a
 * base quantity). */
const sim_steady_block *sim_registry_steady_block(const sim_scene *scene, size_t k,
                                                  size_t *first);

/* Every block's sample (sim_steady_block.sample) and finish, into sum. */
void sim_registry_steady_sample(const sim_scene *scene, const sim_particles *p, double mass,
                                const double V[3], double theta, const double *row,
                                double *sum);
void sim_registry_steady_finish(const sim_scene *scene, double *avg);

/* Nonzero if an observer of the scene draws from the observers' stream. */
int sim_registry_observers_draw(const sim_scene *scene);

/* Every observable the entries add to the row for the scene. */
size_t sim_registry_observables(const sim_scene *scene);

/* Nonzero if a present entry adds observables computed from every particle;
 * sets *section to its name. */
int sim_registry_observes_every_particle(const sim_scene *scene, const char **section);

#endif
