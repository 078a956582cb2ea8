/* The state of one ensemble in progress, shared by the engine and the effects
 * (internal to sim/: not part of the public engine API). */
#ifndef GDSMC_SIM_RUN_H
#define GDSMC_SIM_RUN_H

#include <math.h>
#include <stdint.h>

#include <gsl/gsl_rng.h>

#include "effect.h"
#include "engine.h"
#include "observe.h"
#include "particles.h"

/* The velocity bound shared by the event processes whose majorants depend on
 * speeds (hard-sphere and VHS kernels, docs/theory.md §8.3, §5.2): every velocity
 * an event can see lies within `radius` of `centre`.  The engine sets it at
 * each output time from the synchronised system (plus the lazy flow's reach
 * over the next interval); an effect that changes a velocity calls
 * sim_run_cover, and an effect whose majorant uses the bound re-reads it.
 * When no event needs it, radius is +inf and covering is a no-op. */
struct sim_run {
    sim_particles p;
    gsl_rng *rng;
    const sim_flow *flow;     /* the lazy flow, or NULL */
    double centre[3];
    double radius;
    int bound_grew;           /* set by sim_run_cover; the engine re-reads rates */
    sim_counts counts;
    sim_sums sums;            /* of the stored velocities and stamps, when the engine
                                 observes from them (observe.h), else unused */
    double scale;             /* a linear flow's factor not yet applied to the stored
                                 velocities (effect.h, linear_factor), else 1 */
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

/* Let the bound cover velocity v. */
static inline void sim_run_cover(sim_run *run, const double v[3])
{
    double d[3] = {v[0] - run->centre[0], v[1] - run->centre[1], v[2] - run->centre[2]};
    double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (r2 > run->radius * run->radius) {
        run->radius = sqrt(r2);
        run->bound_grew = 1;
    }
}

#endif
