/* The first stage of the hard-sphere acceptance (effect_collisions.c), shared
 * with the bench's floor loop (verify/bench/bench.c) so that the floor runs the
 * engine's own kernel.
 *
 * |v_i - v_j| <= a_i + a_j with a_i = |v_i - c|: the first particle of a
 * candidate is kept with probability a_i / R (R the velocity bound), the pair
 * then accepted with |g| / (a_i + a_j).
 */
#ifndef GDSMC_SIM_FIRST_STAGE_H
#define GDSMC_SIM_FIRST_STAGE_H

#include <math.h>
#include <stdint.h>

#include "particles.h"
#include "rng.h"

/* Every entry of a block, for `which`. */
#define SIM_BATCH_ALL (((uint32_t)1 << SIM_BATCH) - 1u)

/* |v - c|^2, in the order reset_bound (engine.c) and sim_run_cover use, so
 * that a_i <= R holds to the last bit for every covered velocity. */
static inline double sim_dist2(const double v[3], const double c[3])
{
    const double d[3] = {v[0] - c[0], v[1] - c[1], v[2] - c[2]};
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

/* Stage 1 for the entries `which` of the current block (scale = 2^32 / R):
 * bit k of the result is set when entry k's particle is kept (a_k / R:
 * sim_rng_accept32's test without branches; the undecided case
 * u < x < u + 1, of probability 2^-32, draws its further bits here).  A
 * particle beyond the bound (a_k > R, a violation) has x > 2^32 and is always
 * kept: the caller counts it then. */
static inline __attribute__((always_inline)) uint32_t
sim_first_stage(const sim_batch *b, uint32_t which, const sim_particles *p, const double c[3],
                double scale, gsl_rng *rng)
{
    /* u + 1 <= x and u < x compared as squares: no square root (a few
     * cycles of throughput each) for the three in four entries rejected */
    const double scale2 = scale * scale;
    uint32_t keep = 0, below = 0;
    for (unsigned k = 0; k < SIM_BATCH; k++) {
        const double x2 = sim_dist2(p->v[b->index[k]], c) * scale2;
        const double u = (double)b->spare[k], u1 = u + 1.0;
        keep |= (uint32_t)(u1 * u1 <= x2) << k;
        below |= (uint32_t)(u * u < x2) << k;
    }
    for (uint32_t tie = below & ~keep & which; tie; tie &= tie - 1) {
        const unsigned k = (unsigned)__builtin_ctz(tie);
        const double x = sqrt(sim_dist2(p->v[b->index[k]], c)) * scale;
        keep |= (uint32_t)(sim_rng_uniform(rng) < x - (double)b->spare[k]) << k;
    }
    return keep & which;
}

#endif
