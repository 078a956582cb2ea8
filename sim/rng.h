/* Counter-based random streams (Random123 Philox4x64-10) for the engine.
 *
 * One stream per ensemble, keyed by (seed, ensemble index): an ensemble draws
 * the same numbers whichever thread runs it, so results do not depend on the
 * thread count (docs/theory.md §8.6, reproducibility).  The stream is a gsl_rng of type
 * sim_rng_philox4x64, so GSL's exact samplers (the ziggurat normal, Poisson
 * and beta variates among them) run on it; the inline functions below are its
 * fast path.  Every sampler here is exact in distribution (to the rounding of
 * doubles): integer draws by Lemire's multiply-and-reject, Bernoulli trials by
 * comparing a uniform that is refined with further bits whenever 32 bits
 * cannot decide, directions by Marsaglia's method.
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

/* Philox blocks computed per refill.  rng.c computes them two at a time so
 * that their rounds overlap in the multiplier: about 11 ns a block, against
 * 14.5 ns when each block waits for the one before (measured on this
 * project's 2-core Xeon VM, one word at a time as the engine draws them). */
#define SIM_RNG_BLOCKS 8
#define SIM_RNG_WORDS (4 * SIM_RNG_BLOCKS)

typedef struct sim_rng_state {
    philox4x64_key_t key;   /* (seed, stream) */
    philox4x64_ctr_t ctr;   /* counter of the next block to compute */
    uint64_t word[SIM_RNG_WORDS];   /* blocks ctr - SIM_RNG_BLOCKS .. ctr - 1 */
    unsigned next;          /* next unused word, SIM_RNG_WORDS = empty */
    uint64_t normals;       /* standard normal variates drawn so far */
    uint32_t half;          /* the unused high half of a word (sim_rng_u32) */
    unsigned has_half;
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

/* The next SIM_RNG_BLOCKS blocks of four words (rng.c): kept out of line so
 * that the fast path below stays small enough to inline into every hot loop. */
void sim_rng_refill(sim_rng_state *s);

/* Next 64 random bits: word k of the stream is word k % 4 of the Philox block
 * with counter k / 4 (all four words of every block are used; how many blocks
 * a refill computes does not change the stream). */
static inline uint64_t sim_rng_u64(gsl_rng *r)
{
    sim_rng_state *s = sim_rng_state_of(r);
    if (s->next == SIM_RNG_WORDS)
        sim_rng_refill(s);
    return s->word[s->next++];
}

/* Next 32 random bits: the low half of a fresh word, then its high half. */
static inline uint32_t sim_rng_u32(gsl_rng *r)
{
    sim_rng_state *s = sim_rng_state_of(r);
    if (s->has_half) {
        s->has_half = 0;
        return s->half;
    }
    const uint64_t w = sim_rng_u64(r);
    s->half = (uint32_t)(w >> 32);
    s->has_half = 1;
    return (uint32_t)w;
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

/* A uniform index in [0, n), 1 <= n < 2^32, from the 32-bit uniform x
 * (Lemire's multiply-and-reject with 32-bit products: exact; on the rare
 * rejection, with probability below n / 2^32, fresh words are drawn). */
static inline uint32_t sim_rng_index_from32(gsl_rng *r, uint32_t x, uint32_t n)
{
    uint64_t m = (uint64_t)x * n;
    if ((uint32_t)m < n) {
        const uint32_t threshold = (uint32_t)-n % n;
        while ((uint32_t)m < threshold)
            m = (uint64_t)(uint32_t)sim_rng_u64(r) * n;
    }
    return (uint32_t)(m >> 32);
}

/* One word, two uses: a uniform index in [0, n), 1 <= n < 2^32, from its low
 * half (sim_rng_index_from32) and its high half in *spare, a 32-bit uniform
 * independent of the index, for sim_rng_accept32. */
static inline uint32_t sim_rng_index32(gsl_rng *r, uint32_t n, uint32_t *spare)
{
    const uint64_t w = sim_rng_u64(r);
    *spare = (uint32_t)(w >> 32);
    return sim_rng_index_from32(r, (uint32_t)w, n);
}

/* A Bernoulli trial with success probability p = x / 2^32 from the 32-bit
 * uniform u, exactly: U = (u + V) / 2^32 with V uniform on [0, 1) is uniform
 * on [0, 1), and U < p is decided by u alone unless u < x < u + 1, which has
 * probability below 2^-32; only then is V drawn.  x >= 2^32 always succeeds,
 * x <= 0 (or NaN) never does. */
static inline int sim_rng_accept32(gsl_rng *r, uint32_t u, double x)
{
    const double du = (double)u;
    if (du + 1.0 <= x)
        return 1;
    if (!(du < x))
        return 0;
    return sim_rng_uniform(r) < x - du;   /* exact: 0 < x - du < 1 */
}

/* A Bernoulli trial with success probability num / den (num >= 0, den > 0)
 * from the 32-bit uniform u: sim_rng_accept32 with x = num 2^32 / den, the
 * division made only in the undecided case (probability below 2^-32); the
 * two decisive comparisons multiply instead (equal to the divided test up to
 * the rounding of one product).  den <= 0 (or NaN) never succeeds. */
static inline int sim_rng_accept32_ratio(gsl_rng *r, uint32_t u, double num, double den)
{
    const double du = (double)u, y = num * 0x1p32;
    if ((du + 1.0) * den <= y && den > 0.0)
        return 1;
    if (!(du * den < y) || !(den > 0.0))
        return 0;
    return sim_rng_uniform(r) < y / den - du;
}

/* Exponential waiting time with the given rate (> 0). */
static inline double sim_rng_exponential(gsl_rng *r, double rate)
{
    return -log(sim_rng_uniform_pos(r)) / rate;
}

/* Three independent standard normal variates (GSL's ziggurat, exact).  The
 * initial states draw these: their streams fix every committed table. */
static inline void sim_rng_normal3_gsl(gsl_rng *r, double xi[3])
{
    xi[0] = gsl_ran_gaussian_ziggurat(r, 1.0);
    xi[1] = gsl_ran_gaussian_ziggurat(r, 1.0);
    xi[2] = gsl_ran_gaussian_ziggurat(r, 1.0);
    sim_rng_state_of(r)->normals += 3;
}

/* The ziggurat of Marsaglia and Tsang (J. Stat. Softw. 5(8), 2000) for
 * exp(-x^2/2), 128 layers of equal area (rng.c builds the tables): layer i
 * spans [0, x[i]) in x; its part left of x[i+1] lies under the curve.  Layer
 * 0 is the base strip with the tail beyond r = x[1]; x[128] = 0. */
#define SIM_ZIGGURAT_LAYERS 128
typedef struct sim_ziggurat {
    double k[SIM_ZIGGURAT_LAYERS];         /* 2^24 x[i+1] / x[i]: |u| < k[i] is under the curve */
    double w[SIM_ZIGGURAT_LAYERS];         /* x[i] / 2^24 */
    double f[SIM_ZIGGURAT_LAYERS + 1];     /* exp(-x[i]^2 / 2), f[128] = 1 (f[0] unused) */
    double r;                              /* x[1], where the tail begins */
} sim_ziggurat;
extern sim_ziggurat sim_ziggurat_table;

/* The signed position u in (-2^24, 2^24) on a grid of half-integers,
 * symmetric about 0, from bits 7..31 (bits 0..6 pick the layer). */
static inline double sim_ziggurat_position(uint32_t bits)
{
    return (double)(bits >> 7) - 0x1p24 + 0.5;
}

/* The rare rest of sim_rng_normal (about 1.2% of draws): the base strip's
 * tail, the wedges, and fresh draws after a rejection (rng.c). */
double sim_rng_normal_rest(gsl_rng *r, uint32_t bits);

/* A standard normal variate from 32 bits: 7 of layer and 25 of signed
 * position (GSL's ziggurat takes the same 7 + 1 + 24 from a whole word),
 * inline, without a branch on the sign. */
static inline double sim_rng_normal(gsl_rng *r)
{
    const uint32_t bits = sim_rng_u32(r);
    const unsigned i = bits & 0x7f;
    const double u = sim_ziggurat_position(bits);
    if (fabs(u) < sim_ziggurat_table.k[i])
        return u * sim_ziggurat_table.w[i];
    return sim_rng_normal_rest(r, bits);
}

/* Three independent standard normal variates (sim_rng_normal): the hot path
 * of white-noise heating, 1.5 words and no call for the three. */
static inline void sim_rng_normal3(gsl_rng *r, double xi[3])
{
    xi[0] = sim_rng_normal(r);
    xi[1] = sim_rng_normal(r);
    xi[2] = sim_rng_normal(r);
    sim_rng_state_of(r)->normals += 3;
}

/* A point uniform on the unit sphere S^2, exact in distribution (Marsaglia,
 * Ann. Math. Stat. 43 (1972) 645): (x, y) uniform in the unit disc by
 * rejection from the square (acceptance pi/4), q = x^2 + y^2; then
 * e = (2 x sqrt(1 - q), 2 y sqrt(1 - q), 1 - 2 q) has e_z = 1 - 2q uniform on
 * (-1, 1] and a uniform azimuth (Archimedes).  No trigonometric function:
 * 2.55 uniforms and one square root on average, about half the cost of
 * drawing z and the azimuth and calling sin and cos. */
static inline void sim_rng_unit_sphere(gsl_rng *r, double e[3])
{
    double x, y, q;
    do {
        x = 2.0 * sim_rng_uniform(r) - 1.0;
        y = 2.0 * sim_rng_uniform(r) - 1.0;
        q = x * x + y * y;
    } while (q >= 1.0);
    const double f = 2.0 * sqrt(1.0 - q);
    e[0] = f * x;
    e[1] = f * y;
    e[2] = 1.0 - 2.0 * q;
}

/* A candidate pair of the range [lo, lo + count), count >= 2: i uniform, j
 * uniform among the others, so every ordered pair has probability
 * 1/(count (count - 1)) (the Lees-Edwards slab's layers). */
static inline void sim_pick_pair_in(gsl_rng *rng, size_t lo, size_t count, size_t *i, size_t *j)
{
    *i = lo + (size_t)sim_rng_index(rng, count);
    *j = lo + (size_t)sim_rng_index(rng, count - 1);
    *j += *j >= *i;
}

#endif
