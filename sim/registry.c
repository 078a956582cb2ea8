/* The registry of effects (registry.h). */
#include "registry.h"

#include <string.h>

#include "observe.h"
#include "steady.h"

static int collisions_present(const sim_scene *s) { return s->collisions.present; }
static int background_present(const sim_scene *s) { return s->background.present; }
static int heating_present(const sim_scene *s) { return s->heating.present; }
static int heat_flux_present(const sim_scene *s) { return s->heat_flux.present; }
/* The homogeneous shear flow; the Lees-Edwards slab shears by its boundary
 * (scheme_slab.c).  Its columns are the scene's either way. */
static int shear_present(const sim_scene *s)
{
    return s->shear.present && s->shear.boundary != SIM_SHEAR_LEES_EDWARDS;
}

/* Paper E's EHS gas loses energy to a drag (docs/theory.md §6.2); elastic
 * EHS has none. */
static int drag_present(const sim_scene *s)
{
    return s->collisions.present && s->collisions.model == SIM_MODEL_EHS
           && s->collisions.restitution < 1.0;
}

/* The shear set (docs/theory.md §9.3), and with the Lees-Edwards boundary the
 * slab's columns and profiles (§9.4). */
static size_t shear_observables(const sim_scene *s)
{
    if (!s->shear.present)
        return 0;
    if (s->shear.boundary != SIM_SHEAR_LEES_EDWARDS)
        return SIM_OBS_SHEAR_END - SIM_OBS_BASE;
    return SIM_OBS_PROFILE + SIM_PROFILES * s->shear.layers - SIM_OBS_BASE;
}

static int bath_present(const sim_scene *s) { return s->bath.present; }

static int shear_draws(const sim_scene *s) { return s->shear.pairs > 0; }

/* In the table's order: the steady columns' order.  The flows' order in a
 * step: the shear (or the fused shear and drag), the drag, then a thermostat
 * or the heat-flux force. */
const sim_effect_entry sim_registry[] = {
    {.section = "collisions", .present = collisions_present,
     .create_event = sim_effect_collisions},
    {.section = "background", .present = background_present,
     .create_event = sim_effect_background},
    {.section = "heating", .present = heating_present, .create_flow = sim_effect_heating,
     .flow_order = 3, .jump_key = "heating.type"},
    {.section = "heat-flux", .present = heat_flux_present, .create_flow = sim_effect_heat_flux,
     .flow_order = 4, .steady = &sim_heat_flux_steady},
    {.section = "bath", .present = bath_present, .create_flow = sim_effect_bath, .flow_order = 3},
    {.section = "shear+drag", .create_flow = sim_effect_sheared_ehs_drag, .flow_order = 0,
     .fuses = {"shear", "drag"}},
    {.section = "shear", .present = shear_present, .create_flow = sim_effect_shear,
     .flow_order = 1, .steady = &sim_shear_steady, .observables = shear_observables,
     .observe = sim_shear_observe, .observe_draws = shear_draws},
    {.section = "drag", .present = drag_present, .create_flow = sim_effect_ehs_drag,
     .flow_order = 2},
};

const size_t sim_registry_count = sizeof sim_registry / sizeof sim_registry[0];
_Static_assert(sizeof sim_registry / sizeof sim_registry[0] <= SIM_EFFECTS_MAX,
               "the engine holds at most SIM_EFFECTS_MAX effects: raise it (registry.h)");

const sim_effect_entry *sim_registry_find(const char *section)
{
    for (size_t k = 0; k < sim_registry_count; k++)
        if (strcmp(sim_registry[k].section, section) == 0)
            return &sim_registry[k];
    return NULL;
}

size_t sim_registry_steady_first(const sim_scene *scene, const char *section)
{
    size_t first = SIM_STEADY_BIN0 + scene->steady.bins;
    for (size_t k = 0; k < sim_registry_count && strcmp(sim_registry[k].section, section); k++)
        if (sim_registry[k].steady)
            first += sim_registry[k].steady->count(scene);
    return first;
}

size_t sim_registry_steady_columns(const sim_scene *scene)
{
    size_t count = 0;
    for (size_t k = 0; k < sim_registry_count; k++)
        if (sim_registry[k].steady)
            count += sim_registry[k].steady->count(scene);
    return count;
}

const sim_steady_block *sim_registry_steady_block(const sim_scene *scene, size_t k,
                                                  size_t *first)
{
    size_t at = SIM_STEADY_BIN0 + scene->steady.bins;
    for (size_t e = 0; e < sim_registry_count; e++) {
        const sim_steady_block *b = sim_registry[e].steady;
        const size_t count = b ? b->count(scene) : 0;
        if (k >= at && k < at + count) {
            *first = at;
            return b;
        }
        at += count;
    }
    return NULL;
}

void sim_registry_steady_sample(const sim_scene *scene, const sim_particles *p, double mass,
                                const double V[3], double theta, const double *row,
                                double *sum)
{
    double *block = sum + SIM_STEADY_BIN0 + scene->steady.bins;
    for (size_t e = 0; e < sim_registry_count; e++) {
        const sim_steady_block *b = sim_registry[e].steady;
        const size_t count = b ? b->count(scene) : 0;
        if (count > 0)
            b->sample(scene, p, mass, V, theta, row, block);
        block += count;
    }
}

void sim_registry_steady_finish(const sim_scene *scene, double *avg)
{
    double *block = avg + SIM_STEADY_BIN0 + scene->steady.bins;
    for (size_t e = 0; e < sim_registry_count; e++) {
        const sim_steady_block *b = sim_registry[e].steady;
        const size_t count = b ? b->count(scene) : 0;
        if (count > 0 && b->finish)
            b->finish(scene, block);
        block += count;
    }
}

size_t sim_registry_observables(const sim_scene *scene)
{
    size_t count = 0;
    for (size_t k = 0; k < sim_registry_count; k++)
        if (sim_registry[k].observables)
            count += sim_registry[k].observables(scene);
    return count;
}

int sim_registry_observers_draw(const sim_scene *scene)
{
    for (size_t k = 0; k < sim_registry_count; k++)
        if (sim_registry[k].observe_draws && sim_registry[k].observables
            && sim_registry[k].observables(scene) > 0 && sim_registry[k].observe_draws(scene))
            return 1;
    return 0;
}

int sim_registry_observes_every_particle(const sim_scene *scene, const char **section)
{
    for (size_t k = 0; k < sim_registry_count; k++)
        if (sim_registry[k].observables && sim_registry[k].observables(scene) > 0) {
            *section = sim_registry[k].section;
            return 1;
        }
    return 0;
}
