#include "scene_refs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* Which paper A references the scene admits; the key at fault otherwise. */
static sim_status check_paper_a(const sim_scene *s, sim_error *err)
{
    const double *u = s->particles.maxwellian.velocity;
    if (!s->collisions.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "collisions",
                             "no reference applies: paper A references need [collisions]");
    if (s->background.present || s->shear.present || s->heat_flux.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "",
                             "no reference implemented for this combination of effects");
    if (s->heating.present && s->heating.type != SIM_HEATING_WHITE_NOISE)
        return sim_error_set(err, SIM_EUNSUPPORTED, "heating.type",
                             "paper A references need white-noise heating");
    if (s->particles.initial != SIM_INITIAL_MAXWELLIAN || u[0] != 0 || u[1] != 0 || u[2] != 0)
        return sim_error_set(err, SIM_EUNSUPPORTED, "particles.initial",
                             "paper A references need an initial Maxwellian at rest");
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

static void set_name(vfy_refs *refs, const char *name)
{
    snprintf(refs->names[refs->count++], sizeof refs->names[0], "%s", name);
}

sim_status vfy_scene_references(const sim_scene *scene, vfy_refs *refs, sim_error *err)
{
    memset(refs, 0, sizeof *refs);
    sim_status status = check_paper_a(scene, err);
    if (status != SIM_OK)
        return status;
    const size_t M = scene->outputs;
    refs->outputs = M;
    refs->values = calloc(M * VFY_REFS_MAX, sizeof *refs->values);
    double *t = malloc(M * sizeof *t), *T = malloc(M * sizeof *T);
    if (!refs->values || !t || !T) {
        free(t);
        free(T);
        vfy_refs_free(refs);
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    }
    for (size_t m = 0; m < M; m++)
        t[m] = sim_scene_output_time(scene, m);

    const ref_heated_params p = vfy_heated_params(scene);
    const double n = (double)scene->particles.n;
    if (scene->collisions.exponent == 0.0) {   /* Maxwell molecules: exact */
        set_name(refs, "T_exact");
        if (!scene->particles.zero_momentum) {
            set_name(refs, "T_finite_n");
            set_name(refs, "T_raw_finite_n");
        }
        for (size_t m = 0; m < M; m++) {
            double *row = refs->values + m * VFY_REFS_MAX;
            row[0] = ref_heated_maxwell_T(&p, t[m]);
            if (refs->count > 1) {
                row[1] = ref_heated_maxwell_T_centred_mean(&p, n, t[m]);
                row[2] = ref_heated_maxwell_T_raw_mean(&p, n, t[m]);
            }
        }
    } else {   /* hard spheres: the two closures of SPEC §3 Ex 5 */
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
            set_name(refs, closures[j].name);
            for (size_t m = 0; m < M; m++)
                refs->values[m * VFY_REFS_MAX + j] = T[m];
        }
    }
    free(t);
    free(T);
    if (status != SIM_OK)
        vfy_refs_free(refs);
    return status;
}

const double *vfy_refs_column(const vfy_refs *refs, const char *name, double *buf)
{
    for (size_t j = 0; j < refs->count; j++) {
        if (strcmp(refs->names[j], name) == 0) {
            for (size_t m = 0; m < refs->outputs; m++)
                buf[m] = refs->values[m * VFY_REFS_MAX + j];
            return buf;
        }
    }
    return NULL;
}

void vfy_refs_free(vfy_refs *refs)
{
    free(refs->values);
    memset(refs, 0, sizeof *refs);
}
