/* The particle system of one ensemble (SPEC §1): n velocities, weight 1/n each.
 *
 * Structure of arrays, one array per attribute: velocities as one array of
 * 3-vectors (a particle's three components share a cache line, so a random
 * pair costs two memory loads, not six), and the time stamps of the lazy flow
 * in their own array, allocated only when the scene has such a flow.
 */
#ifndef GDSMC_SIM_PARTICLES_H
#define GDSMC_SIM_PARTICLES_H

#include <stddef.h>

#include <gsl/gsl_rng.h>

#include "error.h"
#include "scene.h"

typedef struct sim_particles {
    size_t n;
    double (*v)[3];   /* velocities */
    double *stamp;    /* time up to which each particle's flow was applied, or NULL */
} sim_particles;

/* Allocate n particles (and stamps if with_stamps).  On failure returns
 * SIM_ENOMEM with a message giving the bytes asked for; p is then empty. */
sim_status sim_particles_alloc(sim_particles *p, size_t n, int with_stamps, sim_error *err);

/* Free the arrays; harmless on an empty or already freed system. */
void sim_particles_free(sim_particles *p);

/* Draw i.i.d. initial velocities from the scene's initial condition
 * (maxwellian, two-maxwellians as paper B Eq. (35), or a shell of speed
 * sqrt(3T/m) with uniform directions), shift to the distribution's mean if
 * zero_momentum, and set every stamp to 0. */
void sim_particles_sample(sim_particles *p, const sim_scene *scene, gsl_rng *rng);

#endif
