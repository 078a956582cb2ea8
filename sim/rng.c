#include "rng.h"

#include <string.h>

/* Two independent blocks per pass, each from its own local counter: the core
 * interleaves their rounds (rng.h, SIM_RNG_BLOCKS; four per pass were no
 * faster, their state no longer fits the registers). */
void sim_rng_refill(sim_rng_state *s)
{
    _Static_assert(SIM_RNG_BLOCKS % 2 == 0, "blocks are computed two at a time");
    const philox4x64_key_t key = s->key;
    philox4x64_ctr_t c0 = s->ctr, c1 = c0;
    c1.v[0] += 1;
    for (unsigned b = 0; b < SIM_RNG_BLOCKS; b += 2) {
        const philox4x64_ctr_t o0 = philox4x64(c0, key), o1 = philox4x64(c1, key);
        memcpy(&s->word[4 * b], o0.v, sizeof o0.v);
        memcpy(&s->word[4 * b + 4], o1.v, sizeof o1.v);
        c0.v[0] += 2;
        c1.v[0] += 2;
    }
    s->ctr = c0;
    s->next = 0;
}

static void philox_set(void *vstate, unsigned long seed)
{
    sim_rng_state *s = vstate;
    memset(s, 0, sizeof *s);
    s->key.v[0] = seed;
    s->next = SIM_RNG_WORDS;
}

static unsigned long philox_get(void *vstate)
{
    gsl_rng r = {.type = NULL, .state = vstate};
    return (unsigned long)sim_rng_u64(&r);
}

static double philox_get_double(void *vstate)
{
    gsl_rng r = {.type = NULL, .state = vstate};
    return sim_rng_uniform(&r);
}

static const gsl_rng_type philox_type = {
    .name = "philox4x64",
    .max = UINT64_MAX,
    .min = 0,
    .size = sizeof(sim_rng_state),
    .set = philox_set,
    .get = philox_get,
    .get_double = philox_get_double,
};

const gsl_rng_type *sim_rng_philox4x64 = &philox_type;

gsl_rng *sim_rng_alloc(void)
{
    return gsl_rng_alloc(sim_rng_philox4x64);
}

void sim_rng_set_stream(gsl_rng *r, uint64_t seed, uint64_t stream)
{
    sim_rng_state *s = sim_rng_state_of(r);
    memset(s, 0, sizeof *s);
    s->key.v[0] = seed;
    s->key.v[1] = stream;
    s->next = SIM_RNG_WORDS;
}

void sim_rng_set_substream(gsl_rng *r, uint64_t seed, uint64_t stream, uint64_t sub)
{
    sim_rng_set_stream(r, seed, stream);
    sim_rng_state_of(r)->ctr.v[3] = sub;
}
