/* The particle system of one ensemble (docs/theory.md §1.1): n velocities, weight 1/n each.
 *
 * Structure of arrays, one array per attribute: velocities as one array of
 * 3-vectors (a particle's three components share a cache line, or two
 * neighbouring ones, so a random pair costs two memory loads, not six), and
 * the time stamps of the lazy flow in their own array, allocated only when
 * the scene has such a flow: 24 bytes per particle, 32 with stamps.  Arrays
 * of 2 MB or more are asked for huge pages (Linux madvise; a hint), so that
 * random accesses at large n do not also miss the TLB.
 *
 * sim_pick is the stream of random particle indices of one run, drawn ahead
 * of their use so that the memory the particles live in can be prefetched
 * while earlier candidates are processed.
 */
#ifndef GDSMC_SIM_PARTICLES_H
#define GDSMC_SIM_PARTICLES_H

#include <stddef.h>
#include <stdint.h>

#include <gsl/gsl_rng.h>

#include "error.h"
#include "rng.h"
#include "scene.h"

/* Most particles one system may hold: indices are drawn as 32-bit numbers. */
#define SIM_PARTICLES_MAX UINT32_MAX

typedef struct sim_particles {
    size_t n;
    double (*v)[3];   /* velocities */
    double *stamp;    /* time up to which each particle's flow was applied, or NULL */
    double *y;        /* positions across the Lees-Edwards slab (paper E's y), or NULL */
} sim_particles;

/* Allocate n particles, 1 <= n <= SIM_PARTICLES_MAX (and stamps if
 * with_stamps).  On failure returns SIM_ENOMEM with a message giving the
 * bytes asked for (SIM_EINVAL, naming particles.n, for n out of range); p is
 * then empty. */
sim_status sim_particles_alloc(sim_particles *p, size_t n, int with_stamps, sim_error *err);

/* Give an allocated system positions (the Lees-Edwards slab, sim/slab.h):
 * 8 more bytes per particle, paid only by scenes with a slab.  SIM_ENOMEM
 * (the system is then unchanged). */
sim_status sim_particles_alloc_positions(sim_particles *p, sim_error *err);

/* Free the arrays; harmless on an empty or already freed system. */
void sim_particles_free(sim_particles *p);

/* Bytes the arrays of n particles take, per particle (24, or 32 with stamps). */
size_t sim_particles_bytes_per_particle(int with_stamps);

/* Draw i.i.d. initial velocities from the scene's initial condition
 * (maxwellian, two-maxwellians as paper B Eq. (35), or a shell of speed
 * sqrt(3T/m) with uniform directions), shift to the distribution's mean if
 * zero_momentum, and set every stamp to 0.  A system with positions draws
 * each particle's y first, from the density n (1 + w sin(2 pi y/L)) on
 * (-L/2, L/2) (w = particles.density_wave, L = shear.length; by rejection),
 * and adds the flow U (cos(pi y/L) - 2/pi) x̂ (U = particles.flow_wave) to its
 * velocity: paper E Eqs. (3.5)-(3.8). */
void sim_particles_sample(sim_particles *p, const sim_scene *scene, gsl_rng *rng);

/* ------------------------------------------------------------ index stream */

/* How many indices are drawn ahead of use: the prefetch distance.  About the
 * number of cache misses a core keeps in flight, times the few candidates
 * that pass between two uses of the stream. */
#define SIM_PICK_AHEAD 16

/* Uniform random particle indices, each with a spare 32-bit uniform (the high
 * half of the word it came from, sim_rng_index32) for the acceptance test
 * that usually follows the load.  Entry k of the stream is drawn when entry
 * k - SIM_PICK_AHEAD is used, and its particle is prefetched then.  Exact:
 * every entry is an independent uniform index, and whether an entry is used
 * as a first particle, a partner or a redraw depends only on the entries
 * before it, never on its own value. */
typedef struct sim_pick {
    uint32_t index[SIM_PICK_AHEAD];
    uint32_t spare[SIM_PICK_AHEAD];
    unsigned head;
} sim_pick;

/* stamps: whether the run has a lazy flow (a constant in every caller, so
 * that the hot loops carry no branch on it). */
static inline void sim_pick_prefetch(const sim_particles *p, uint32_t i, const int stamps)
{
    /* 24 bytes may straddle two cache lines */
    __builtin_prefetch(&p->v[i][0], 1);
    __builtin_prefetch(&p->v[i][2], 1);
    if (stamps)
        __builtin_prefetch(&p->stamp[i], 1);
}

/* Fill the stream from rng: call at the start of every run, after the
 * initial state is drawn (it draws SIM_PICK_AHEAD words). */
static inline void sim_pick_start(sim_pick *q, const sim_particles *p, gsl_rng *r)
{
    for (unsigned k = 0; k < SIM_PICK_AHEAD; k++)
        q->index[k] = sim_rng_index32(r, (uint32_t)p->n, &q->spare[k]);
    q->head = 0;
}

/* The next index of the stream and its spare uniform; one new entry is drawn
 * (one word) and prefetched (with its stamp if `stamps`, a constant). */
static inline uint32_t sim_pick_next(sim_pick *q, const sim_particles *p, gsl_rng *r,
                                     uint32_t *spare, const int stamps)
{
    const unsigned h = q->head;
    const uint32_t i = q->index[h];
    *spare = q->spare[h];
    q->index[h] = sim_rng_index32(r, (uint32_t)p->n, &q->spare[h]);
    sim_pick_prefetch(p, q->index[h], stamps);
    q->head = (h + 1) % SIM_PICK_AHEAD;
    return i;
}

/* ------------------------------------------------------ blocks of indices */

/* Entries per block (a bit mask of them fits 32 bits). */
#define SIM_BATCH 8

/* The index stream in blocks, for a loop that first tests many candidates
 * that need one particle each (the hard-sphere first stage): the caller
 * evaluates a whole block's tests without branches, then visits the entries
 * that passed.  The block after the current one is drawn when the current one
 * starts, and its particles are prefetched then.  Exact for the same reason
 * as sim_pick, provided the caller decides each entry with the state at its
 * turn (re-testing entries whose particle changed since the block's tests). */
typedef struct sim_batch {
    uint32_t index[SIM_BATCH], spare[SIM_BATCH];    /* the current block */
    uint32_t ahead[SIM_BATCH], ahead_spare[SIM_BATCH];   /* the next, prefetched */
    unsigned pos;   /* the next entry of the current block to use */
} sim_batch;

/* The current block := the block ahead; draw a new block ahead (SIM_BATCH
 * words) and prefetch its particles. */
static inline void sim_batch_advance(sim_batch *b, const sim_particles *p, gsl_rng *r)
{
    for (unsigned k = 0; k < SIM_BATCH; k++) {
        b->index[k] = b->ahead[k];
        b->spare[k] = b->ahead_spare[k];
        b->ahead[k] = sim_rng_index32(r, (uint32_t)p->n, &b->ahead_spare[k]);
        sim_pick_prefetch(p, b->ahead[k], 0);
    }
    b->pos = 0;
}

/* Fill both blocks: at the start of every run, after the initial state. */
static inline void sim_batch_start(sim_batch *b, const sim_particles *p, gsl_rng *r)
{
    for (unsigned k = 0; k < SIM_BATCH; k++)
        b->ahead[k] = sim_rng_index32(r, (uint32_t)p->n, &b->ahead_spare[k]);
    sim_batch_advance(b, p, r);
}

#endif
