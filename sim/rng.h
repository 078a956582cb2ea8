/* Counter-based random streams (Random123 Philox4x64-10) for the engine.
 *
 * One stream per ensemble, keyed by (seed, ensemble index): an ensemble draws
 * the same numbers whichever thread runs it, so results do not depend on the
 * thread count (SPEC §10, reproducibility).  The stream is a gsl_rng of type
 * sim_rng_philox4x64, so GSL's exact samplers (the ziggurat normal among them)
 * run on it; the inline functions below are its fast path.
 *
 * Thread safety: a stream belongs to one thread at a time.
 */
#ifndef GDSMC_SIM_RNG_H
#define GDSMC_SIM_RNG_H

#include <math.h>
#include <stdint.h>

#include <Random123/philox.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

typedef struct sim_rng_state {
    philox4x64_key_t key;   /* (seed, stream) */
    philox4x64_ctr_t ctr;   /* block counter */
    philox4x64_ctr_t block; /* current four output words */
    unsigned next;          /* next unused word of block, 4 = empty */
    uint64_t words;         /* 64-bit words drawn so far */
    uint64_t normals;       /* standard normal variates drawn so far */
} sim_rng_state;

extern const gsl_rng_type *sim_rng_philox4x64;

/* A new stream (keyed (0, 0) until sim_rng_set_stream); NULL if out of memory.
 * Free with gsl_rng_free. */
gsl_rng *sim_rng_alloc(void);

/* Restart r as stream `stream` of `seed`, at its first word. */
void sim_rng_set_stream(gsl_rng *r, uint64_t seed, uint64_t stream);

/* Restart r as substream `sub` of stream (seed, stream): the same key with the
 * counter's last word set to sub, so substreams never overlap each other or the
 * stream itself (sub = 0), which uses only the first counter word.  Observers
 * that need random numbers (pair sampling) draw from substream 1 so that
 * observing never changes the simulated trajectory. */
void sim_rng_set_substream(gsl_rng *r, uint64_t seed, uint64_t stream, uint64_t sub);

__extension__ typedef unsigned __int128 sim_u128;  /* for the exact index draw */
_Static_assert(sizeof(unsigned long) == 8, "gsl_rng words must hold 64 bits");

static inline sim_rng_state *sim_rng_state_of(gsl_rng *r) { return (sim_rng_state *)r->state; }

/* Next 64 random bits. */
static inline uint64_t sim_rng_u64(gsl_rng *r)
{
    sim_rng_state *s = sim_rng_state_of(r);
    if (s->next == 4) {
        s->block = philox4x64(s->ctr, s->key);
        s->ctr.v[0]++;
        s->next = 0;
    }
    s->words++;
    return s->block.v[s->next++];
}

/* Uniform on [0, 1) with 53 random bits. */
static inline double sim_rng_uniform(gsl_rng *r)
{
    return (double)(sim_rng_u64(r) >> 11) * 0x1.0p-53;
}

/* Uniform on (0, 1): never 0, so -log() is finite. */
static inline double sim_rng_uniform_pos(gsl_rng *r)
{
    return ((double)(sim_rng_u64(r) >> 11) + 0.5) * 0x1.0p-53;
}

/* Uniform integer in [0, n), n >= 1, exactly (Lemire's multiply-and-reject). */
static inline uint64_t sim_rng_index(gsl_rng *r, uint64_t n)
{
    sim_u128 m = (sim_u128)sim_rng_u64(r) * n;
    uint64_t low = (uint64_t)m;
    if (low < n) {
        uint64_t threshold = -n % n;
        while (low < threshold) {
            m = (sim_u128)sim_rng_u64(r) * n;
            low = (uint64_t)m;
        }
    }
    return (uint64_t)(m >> 64);
}

/* Exponential waiting time with the given rate (> 0). */
static inline double sim_rng_exponential(gsl_rng *r, double rate)
{
    return -log(sim_rng_uniform_pos(r)) / rate;
}

/* Three independent standard normal variates (GSL's ziggurat, exact). */
static inline void sim_rng_normal3(gsl_rng *r, double xi[3])
{
    xi[0] = gsl_ran_gaussian_ziggurat(r, 1.0);
    xi[1] = gsl_ran_gaussian_ziggurat(r, 1.0);
    xi[2] = gsl_ran_gaussian_ziggurat(r, 1.0);
    sim_rng_state_of(r)->normals += 3;
}

/* A point uniform on the unit sphere S^2 (Archimedes: z uniform on [-1, 1],
 * azimuth uniform), exact in distribution. */
static inline void sim_rng_unit_sphere(gsl_rng *r, double e[3])
{
    double z = 2.0 * sim_rng_uniform(r) - 1.0;
    double phi = 2.0 * M_PI * sim_rng_uniform(r);
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    e[0] = s * cos(phi);
    e[1] = s * sin(phi);
    e[2] = z;
}

#endif
