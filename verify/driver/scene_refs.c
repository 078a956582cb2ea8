#include "scene_refs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "registry.h"

ref_heated_params vfy_heated_params(const sim_scene *scene)
{
    return (ref_heated_params){
        .alpha = scene->collisions.restitution,
        .beta = scene->heating.present ? scene->heating.strength : 0.0,
        .gamma = scene->collisions.rate,
        .C = scene->collisions.constant,
        .T0 = scene->particles.maxwellian.temperature,
    };
}

ref_background_params vfy_background_params(const sim_scene *scene)
{
    const struct sim_initial_spec *init = &scene->particles;
    const double m = sim_scene_grain_mass(scene);
    ref_background_params p = {
        .mass = m,
        .bg_density = scene->background.density,
        .bg_mass = scene->background.mass,
        .bg_temperature = scene->background.temperature,
        .C1 = scene->background.constant,
        .density = 1.0,
        .C2 = scene->collisions.present ? scene->collisions.rate * scene->collisions.constant : 0.0,
        .restitution = scene->collisions.present ? scene->collisions.restitution : 1.0,
        .T0 = init->maxwellian.temperature,
    };
    for (int k = 0; k < 3; k++) {
        p.bg_velocity[k] = scene->background.velocity[k];
        p.u0[k] = init->maxwellian.velocity[k];
    }
    if (init->initial == SIM_INITIAL_TWO_MAXWELLIANS) {   /* paper B Eq. (35) */
        const double f = init->fraction;
        const sim_maxwellian *a = &init->first, *b = &init->second;
        double da2 = 0.0, db2 = 0.0;
        for (int k = 0; k < 3; k++)
            p.u0[k] = f * a->velocity[k] + (1.0 - f) * b->velocity[k];
        for (int k = 0; k < 3; k++) {
            da2 += (a->velocity[k] - p.u0[k]) * (a->velocity[k] - p.u0[k]);
            db2 += (b->velocity[k] - p.u0[k]) * (b->velocity[k] - p.u0[k]);
        }
        p.T0 = f * (a->temperature + m * da2 / 3.0) + (1.0 - f) * (b->temperature + m * db2 / 3.0);
    }
    return p;
}

/* Which paper B references the scene admits; the key at fault otherwise. */
static sim_status check_paper_b(const sim_scene *s, sim_error *err)
{
    if (s->heating.present || s->shear.present || s->heat_flux.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "background",
                             "no reference for a background combined with heating, shear or "
                             "a heat-flux force");
    if (s->background.kernel != SIM_KERNEL_MAXWELL
        && s->background.kernel != SIM_KERNEL_HARD_SPHERES)
        return sim_error_set(err, SIM_EUNSUPPORTED, "background.kernel",
                             "paper B references need kernel maxwell or hard-spheres");
    if (s->collisions.present && s->collisions.exponent != (s->background.kernel
                                                            == SIM_KERNEL_MAXWELL ? 0.0 : 1.0))
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions.kernel",
                             "paper B references need the same kernel for binary and background "
                             "collisions (background.kernel is %s)",
                             s->background.kernel == SIM_KERNEL_MAXWELL ? "maxwell"
                                                                        : "hard-spheres");
    return SIM_OK;
}

/* A new column `name` of refs->outputs values (zeroed); NULL when out of
 * memory. */
static double *add_column(vfy_refs *refs, const char *name)
{
    if (refs->count == refs->capacity) {
        size_t cap = refs->capacity ? 2 * refs->capacity : 4;
        char(*names)[32] = realloc(refs->names, cap * sizeof *names);
        if (names == NULL)
            return NULL;
        refs->names = names;
        double **cols = realloc(refs->cols, cap * sizeof *cols);
        if (cols == NULL)
            return NULL;
        refs->cols = cols;
        refs->capacity = cap;
    }
    double *col = calloc(refs->outputs ? refs->outputs : 1, sizeof *col);
    if (col == NULL)
        return NULL;
    snprintf(refs->names[refs->count], sizeof refs->names[0], "%s", name);
    refs->cols[refs->count++] = col;
    return col;
}

#define NO_MEMORY(err) sim_error_set(err, SIM_ENOMEM, "", "out of memory")

/* Paper B: closed forms and the exact finite-n T (Maxwell), or the two
 * closures (hard spheres), into refs (values allocated, t the output times). */
static sim_status background_references(const sim_scene *scene, const double *t,
                                        vfy_refs *refs, sim_error *err)
{
    const size_t M = scene->outputs;
    const ref_background_params p = vfy_background_params(scene);
    char msg[256];
    if (scene->background.kernel == SIM_KERNEL_MAXWELL) {
        static const char *const names[] = {"T_exact", "ux_exact", "uy_exact", "uz_exact"};
        double *col[4];
        for (size_t j = 0; j < 4; j++)
            if ((col[j] = add_column(refs, names[j])) == NULL)
                return NO_MEMORY(err);
        for (size_t m = 0; m < M; m++) {
            double u[3];
            col[0][m] = ref_background_maxwell_T(&p, t[m]);
            ref_background_maxwell_u(&p, t[m], u);
            for (int k = 0; k < 3; k++)
                col[1 + k][m] = u[k];
        }
        if (scene->particles.zero_momentum)
            return SIM_OK;
        double *T = malloc(M * sizeof *T);
        if (T == NULL)
            return NO_MEMORY(err);
        ref_status st = ref_background_maxwell_T_mean(&p, (double)scene->particles.n, t, M, NULL,
                                                      T, msg, sizeof msg);
        double *finite = st == REF_OK ? add_column(refs, "T_finite_n") : NULL;
        if (finite != NULL)
            memcpy(finite, T, M * sizeof *T);
        free(T);
        if (st == REF_OK && finite == NULL)
            return NO_MEMORY(err);
        return st == REF_OK ? SIM_OK
                            : sim_error_set(err, SIM_EINVAL, "", "T_finite_n: %s", msg);
    }
    static const struct {
        ref_background_closure closure;
        const char *suffix;
    } closures[] = {{REF_BACKGROUND_LE, "le"}, {REF_BACKGROUND_GRAD, "grad"}};
    double *u = malloc(3 * M * sizeof *u), *T = malloc(M * sizeof *T);
    sim_status status = SIM_OK;
    if (u == NULL || T == NULL)
        status = sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    for (size_t c = 0; c < 2 && status == SIM_OK; c++) {
        if (ref_background_hs(&p, closures[c].closure, t, M, NULL, u, T, msg, sizeof msg)
            != REF_OK) {
            status = sim_error_set(err, SIM_EINVAL, "", "T_%s: %s", closures[c].suffix, msg);
            break;
        }
        static const char *const quantities[] = {"T", "ux", "uy", "uz"};
        double *col[4];
        for (size_t j = 0; j < 4 && status == SIM_OK; j++) {
            char name[32];
            snprintf(name, sizeof name, "%s_%s", quantities[j], closures[c].suffix);
            if ((col[j] = add_column(refs, name)) == NULL)
                status = NO_MEMORY(err);
        }
        for (size_t m = 0; m < M && status == SIM_OK; m++) {
            col[0][m] = T[m];
            for (int k = 0; k < 3; k++)
                col[1 + k][m] = u[3 * m + k];
        }
    }
    free(u);
    free(T);
    return status;
}

/* Paper E: the BGK model's parameters of a homogeneous shear scene. */
ref_bgk_params vfy_bgk_params(const sim_scene *s)
{
    ref_bgk_params p = ref_bgk_default_params();
    p.alpha = s->collisions.restitution;
    p.shear_rate = s->shear.rate;
    p.gamma = s->collisions.rate;
    p.C = s->collisions.constant;
    p.mass = s->particles.maxwellian.mass;
    p.T0 = s->particles.maxwellian.temperature;
    p.model = s->collisions.model == SIM_MODEL_EHS ? REF_BGK_EHS : REF_BGK_IHS;
    return p;
}

/* Which BGK references a shear scene admits; the key at fault otherwise. */
static sim_status check_paper_e(const sim_scene *s, sim_error *err)
{
    const double *u = s->particles.maxwellian.velocity;
    if (s->shear.boundary != SIM_SHEAR_HOMOGENEOUS)
        return sim_error_set(err, SIM_EUNSUPPORTED, "shear.boundary",
                             "the BGK reference is for homogeneous shear");
    if (!s->collisions.present || s->collisions.kernel != SIM_KERNEL_HARD_SPHERES)
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions.kernel",
                             "the BGK reference of paper E needs hard spheres");
    if (s->heating.present || s->heat_flux.present || s->background.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, s->heating.present ? "heating"
                                                    : s->heat_flux.present ? "heat-flux"
                                                                           : "background",
                             "the BGK reference of paper E is for shear and collisions only");
    if (s->particles.initial != SIM_INITIAL_MAXWELLIAN || u[0] != 0 || u[1] != 0 || u[2] != 0)
        return sim_error_set(err, SIM_EUNSUPPORTED, "particles.initial",
                             "the BGK reference starts from local equilibrium: a Maxwellian "
                             "at rest");
    return SIM_OK;
}

/* Paper E: the BGK model's T and stresses (per unit density) and s0 (CVODE). */
static sim_status bgk_references(const sim_scene *scene, const double *t, vfy_refs *refs,
                                 sim_error *err)
{
    static const char *const names[] = {"T_bgk",   "Pxx_bgk", "Pyy_bgk",
                                        "Pzz_bgk", "Pxy_bgk", "s0_bgk"};
    double *col[6];
    for (size_t j = 0; j < 6; j++)
        if ((col[j] = add_column(refs, names[j])) == NULL)
            return NO_MEMORY(err);
    const ref_bgk_params p = vfy_bgk_params(scene);
    const ref_bgk_output out = {.T = col[0], .Pxx = col[1], .Pyy = col[2], .Pzz = col[3],
                                .Pxy = col[4], .s0 = col[5]};
    char msg[256];
    if (ref_bgk_solve(&p, t, scene->outputs, NULL, &out, msg, sizeof msg) != REF_OK)
        return sim_error_set(err, SIM_EINVAL, "", "T_bgk: %s", msg);
    return SIM_OK;
}

/* Which paper A references the scene admits; the key at fault otherwise. */
static sim_status check_paper_a(const sim_scene *s, sim_error *err)
{
    const double *u = s->particles.maxwellian.velocity;
    if (!s->collisions.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions",
                             "no reference applies: paper A references need [collisions]");
    if (s->heat_flux.present)   /* (a background goes to paper B, shear to paper E) */
        return sim_error_set(err, SIM_EUNSUPPORTED, "heat-flux",
                             "no time series reference for the heat-flux force (its references "
                             "are values: gdsmc sonine)");
    if (s->heating.present && s->heating.type != SIM_HEATING_WHITE_NOISE)
        return sim_error_set(err, SIM_EUNSUPPORTED, "heating.type",
                             "paper A references need white-noise heating");
    if (s->particles.initial != SIM_INITIAL_MAXWELLIAN)
        return sim_error_set(err, SIM_EUNSUPPORTED, "particles.initial",
                             "paper A references need an initial Maxwellian at rest "
                             "(allowed maxwellian)");
    if (u[0] != 0 || u[1] != 0 || u[2] != 0)
        return sim_error_set(err, SIM_EUNSUPPORTED, "particles.velocity",
                             "paper A references need an initial Maxwellian at rest "
                             "(allowed 0 0 0)");
    if (s->particles.maxwellian.mass != 1.0)
        return sim_error_set(err, SIM_EUNSUPPORTED, "particles.mass",
                             "paper A references are for unit mass (got %g)",
                             s->particles.maxwellian.mass);
    if (s->collisions.kernel == SIM_KERNEL_VHS && s->collisions.exponent != 0.0
        && s->collisions.exponent != 1.0)
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions.exponent",
                             "no reference for VHS lambda = %g (only 0 and 1)",
                             s->collisions.exponent);
    return SIM_OK;
}

/* The effects the references know, each family refusing below what it does
 * not model; an effect registered since (sim/registry.c) is refused here,
 * naming its section, rather than silently left out of a reference. */
static sim_status check_modelled(const sim_scene *s, sim_error *err)
{
    static const char *const known[] = {"collisions", "background", "heating", "heat-flux",
                                         "shear+drag", "shear", "drag"};
    for (size_t k = 0; k < sim_registry_count; k++) {
        const sim_effect_entry *en = &sim_registry[k];
        size_t q = 0;
        while (q < sizeof known / sizeof known[0] && strcmp(known[q], en->section) != 0)
            q++;
        if (q == sizeof known / sizeof known[0] && en->present && en->present(s))
            return sim_error_set(err, SIM_EUNSUPPORTED, en->section,
                                 "no reference models the %s", en->section);
    }
    return SIM_OK;
}

sim_status vfy_scene_references(const sim_scene *scene, vfy_refs *refs, sim_error *err)
{
    memset(refs, 0, sizeof *refs);
    if (check_modelled(scene, err) != SIM_OK)
        return SIM_EUNSUPPORTED;
    const int paper_b = scene->background.present, paper_e = scene->shear.present && !paper_b;
    sim_status status = paper_b   ? check_paper_b(scene, err)
                        : paper_e ? check_paper_e(scene, err)
                                  : check_paper_a(scene, err);
    if (status != SIM_OK)
        return status;
    const size_t M = scene->outputs;
    refs->outputs = M;
    double *t = malloc(M * sizeof *t), *T = malloc(M * sizeof *T);
    if (!t || !T) {
        free(t);
        free(T);
        vfy_refs_free(refs);
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    }
    for (size_t m = 0; m < M; m++)
        t[m] = sim_scene_output_time(scene, m);

    const ref_heated_params p = vfy_heated_params(scene);
    const double n = (double)scene->particles.n;
    if (paper_b) {
        status = background_references(scene, t, refs, err);
    } else if (paper_e) {
        status = bgk_references(scene, t, refs, err);
    } else if (scene->collisions.exponent == 0.0) {   /* Maxwell molecules: exact */
        double *exact = add_column(refs, "T_exact"), *centred = NULL, *raw = NULL;
        if (exact != NULL && !scene->particles.zero_momentum) {
            centred = add_column(refs, "T_finite_n");
            raw = centred ? add_column(refs, "T_raw_finite_n") : NULL;
        }
        if (exact == NULL || (!scene->particles.zero_momentum && raw == NULL))
            status = NO_MEMORY(err);
        for (size_t m = 0; m < M && status == SIM_OK; m++) {
            exact[m] = ref_heated_maxwell_T(&p, t[m]);
            if (raw != NULL) {
                centred[m] = ref_heated_maxwell_T_centred_mean(&p, n, t[m]);
                raw[m] = ref_heated_maxwell_T_raw_mean(&p, n, t[m]);
            }
        }
    } else {   /* hard spheres: the two closures of docs/theory.md §11.4 */
        const struct { ref_heated_closure closure; const char *name; } closures[] = {
            {REF_HEATED_MAXWELLIAN_CLOSURE, "T_maxwell_closure"},
            {REF_HEATED_SONINE_CLOSURE, "T_sonine_closure"},
        };
        for (size_t j = 0; j < 2 && status == SIM_OK; j++) {
            char msg[256];
            if (ref_heated_hs_T(&p, closures[j].closure, t, M, NULL, T, msg, sizeof msg)
                != REF_OK) {
                status = sim_error_set(err, SIM_EINVAL, "", "%s: %s", closures[j].name, msg);
                break;
            }
            double *col = add_column(refs, closures[j].name);
            if (col == NULL)
                status = NO_MEMORY(err);
            else
                memcpy(col, T, M * sizeof *T);
        }
    }
    free(t);
    free(T);
    if (status != SIM_OK)
        vfy_refs_free(refs);
    return status;
}

const double *vfy_refs_column(const vfy_refs *refs, const char *name)
{
    for (size_t j = 0; j < refs->count; j++)
        if (strcmp(refs->names[j], name) == 0)
            return refs->cols[j];
    return NULL;
}

int vfy_refs_has(const vfy_refs *refs, const char *name)
{
    return vfy_refs_column(refs, name) != NULL;
}

void vfy_refs_free(vfy_refs *refs)
{
    for (size_t j = 0; j < refs->count; j++)
        free(refs->cols[j]);
    free(refs->cols);
    free(refs->names);
    memset(refs, 0, sizeof *refs);
}
