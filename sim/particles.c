#include "particles.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rng.h"

sim_status sim_particles_alloc(sim_particles *p, size_t n, int with_stamps, sim_error *err)
{
    memset(p, 0, sizeof *p);
    p->v = malloc(n * sizeof *p->v);
    if (with_stamps)
        p->stamp = malloc(n * sizeof *p->stamp);
    if (p->v == NULL || (with_stamps && p->stamp == NULL)) {
        sim_particles_free(p);
        return sim_error_set(err, SIM_ENOMEM, "particles.n",
                             "cannot allocate %zu particles (%zu bytes)", n,
                             n * (sizeof *p->v + (with_stamps ? sizeof *p->stamp : 0)));
    }
    p->n = n;
    return SIM_OK;
}

void sim_particles_free(sim_particles *p)
{
    free(p->v);
    free(p->stamp);
    memset(p, 0, sizeof *p);
}

/* One velocity from a Maxwellian: drift + sqrt(T/m) xi. */
static void sample_maxwellian(const sim_maxwellian *m, gsl_rng *rng, double v[3])
{
    double xi[3], s = sqrt(m->temperature / m->mass);
    sim_rng_normal3(rng, xi);
    for (int k = 0; k < 3; k++)
        v[k] = m->velocity[k] + s * xi[k];
}

void sim_particles_sample(sim_particles *p, const sim_scene *scene, gsl_rng *rng)
{
    const struct sim_initial_spec *init = &scene->particles;
    double mean[3] = {0, 0, 0};   /* the distribution's mean velocity */
    for (int k = 0; k < 3; k++) {
        mean[k] = init->initial == SIM_INITIAL_TWO_MAXWELLIANS
                      ? init->fraction * init->first.velocity[k]
                            + (1.0 - init->fraction) * init->second.velocity[k]
                      : init->maxwellian.velocity[k];
    }

    for (size_t i = 0; i < p->n; i++) {
        switch (init->initial) {
        case SIM_INITIAL_MAXWELLIAN:
            sample_maxwellian(&init->maxwellian, rng, p->v[i]);
            break;
        case SIM_INITIAL_TWO_MAXWELLIANS:  /* paper B Eq. (35) */
            sample_maxwellian(sim_rng_uniform(rng) < init->fraction ? &init->first
                                                                    : &init->second,
                              rng, p->v[i]);
            break;
        case SIM_INITIAL_SHELL: {  /* |v - u| = sqrt(3T/m): temperature T */
            double e[3], speed = sqrt(3.0 * init->maxwellian.temperature
                                      / init->maxwellian.mass);
            sim_rng_unit_sphere(rng, e);
            for (int k = 0; k < 3; k++)
                p->v[i][k] = mean[k] + speed * e[k];
            break;
        }
        }
    }

    if (init->zero_momentum) {
        double sum[3] = {0, 0, 0};
        for (size_t i = 0; i < p->n; i++)
            for (int k = 0; k < 3; k++)
                sum[k] += p->v[i][k];
        for (size_t i = 0; i < p->n; i++)
            for (int k = 0; k < 3; k++)
                p->v[i][k] += mean[k] - sum[k] / (double)p->n;
    }
    if (p->stamp)
        memset(p->stamp, 0, p->n * sizeof *p->stamp);
}
