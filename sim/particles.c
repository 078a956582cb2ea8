#include "particles.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include "rng.h"

#define HUGE_PAGE ((size_t)2 << 20)

/* An array of `bytes`, its pages faulted in (zeroed) here, when the
 * workspace is made, rather than by the first run that writes it; from 2 MB
 * on, aligned to and rounded up to 2 MB and marked for transparent huge
 * pages, so that random accesses into hundreds of megabytes walk few
 * page-table entries (with 4 kB pages nearly every access at n = 1e7 also
 * misses the TLB).  The hint may be refused; nothing else changes then.
 * Freed with free(). */
static void *array_alloc(size_t bytes)
{
    if (bytes < HUGE_PAGE)
        return calloc(1, bytes);
    const size_t rounded = (bytes + HUGE_PAGE - 1) & ~(HUGE_PAGE - 1);
    void *a = aligned_alloc(HUGE_PAGE, rounded);
    if (a == NULL)
        return NULL;
#ifdef MADV_HUGEPAGE
    (void)madvise(a, rounded, MADV_HUGEPAGE);
#endif
    memset(a, 0, rounded);
    return a;
}

size_t sim_particles_bytes_per_particle(int with_stamps)
{
    return sizeof(double[3]) + (with_stamps ? sizeof(double) : 0);
}

sim_status sim_particles_alloc(sim_particles *p, size_t n, int with_stamps, sim_error *err)
{
    memset(p, 0, sizeof *p);
    if (n < 1 || n > SIM_PARTICLES_MAX)
        return sim_error_set(err, SIM_EINVAL, "particles.n", "%zu is out of range (allowed 1 "
                             "<= n <= %lu)", n, (unsigned long)SIM_PARTICLES_MAX);
    p->v = array_alloc(n * sizeof *p->v);
    if (with_stamps)
        p->stamp = array_alloc(n * sizeof *p->stamp);
    if (p->v == NULL || (with_stamps && p->stamp == NULL)) {
        sim_particles_free(p);
        return sim_error_set(err, SIM_ENOMEM, "particles.n",
                             "cannot allocate %zu particles (%zu bytes)", n,
                             n * sim_particles_bytes_per_particle(with_stamps));
    }
    p->n = n;
    return SIM_OK;
}

sim_status sim_particles_alloc_positions(sim_particles *p, sim_error *err)
{
    if (p->y == NULL && (p->y = array_alloc(p->n * sizeof *p->y)) == NULL)
        return sim_error_set(err, SIM_ENOMEM, "particles.n",
                             "cannot allocate the positions of %zu particles (%zu bytes)", p->n,
                             p->n * sizeof *p->y);
    return SIM_OK;
}

void sim_particles_free(sim_particles *p)
{
    free(p->v);
    free(p->stamp);
    free(p->y);
    memset(p, 0, sizeof *p);
}

/* One velocity from a Maxwellian: drift + sqrt(T/m) xi (GSL's normals: the
 * initial states of the committed tables, rng.h). */
static void sample_maxwellian(const sim_maxwellian *m, gsl_rng *rng, double v[3])
{
    double xi[3], s = sqrt(m->temperature / m->mass);
    sim_rng_normal3_gsl(rng, xi);
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

    const double L = scene->shear.length, wave = init->density_wave;
    for (size_t i = 0; i < p->n; i++) {
        if (p->y) {   /* paper E Eq. (3.7): accept y with (1 + w sin(2 pi y/L))/(1 + w) */
            double y;
            do
                y = L * (sim_rng_uniform(rng) - 0.5);
            while (wave > 0.0
                   && sim_rng_uniform(rng) * (1.0 + wave) >= 1.0 + wave * sin(2.0 * M_PI * y / L));
            p->y[i] = y;
        }
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
        if (p->y)   /* paper E Eq. (3.8) */
            p->v[i][0] += init->flow_wave * (cos(M_PI * p->y[i] / L) - 2.0 / M_PI);
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
