/* The state of one ensemble in progress, shared by the engine and the effects
 * (internal to sim/: not part of the public engine API). */
#ifndef GDSMC_SIM_RUN_H
#define GDSMC_SIM_RUN_H

#include <stdint.h>

#include <gsl/gsl_rng.h>

#include "effect.h"
#include "engine.h"
#include "particles.h"

struct sim_run {
    sim_particles p;
    gsl_rng *rng;
    const sim_effect *flow;   /* the lazy flow, or NULL */
    sim_counts counts;
};

/* Bring particle i forward to time t with the lazy flow (run->flow != NULL). */
static inline void sim_run_bring(sim_run *run, size_t i, double t)
{
    double dt = t - run->p.stamp[i];
    if (dt > 0.0) {
        run->flow->type->advance(run->flow, run->p.v[i], dt, run->rng);
        run->p.stamp[i] = t;
    }
}

#endif
