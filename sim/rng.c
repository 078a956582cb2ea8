#include "rng.h"

#include <string.h>

void sim_rng_refill(sim_rng_state *s)
{
    s->block = philox4x64(s->ctr, s->key);
    s->ctr.v[0]++;
    s->next = 0;
}

static void philox_set(void *vstate, unsigned long seed)
{
    sim_rng_state *s = vstate;
    memset(s, 0, sizeof *s);
    s->key.v[0] = seed;
    s->next = 4;
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
    s->next = 4;
}

void sim_rng_set_substream(gsl_rng *r, uint64_t seed, uint64_t stream, uint64_t sub)
{
    sim_rng_set_stream(r, seed, stream);
    sim_rng_state_of(r)->ctr.v[3] = sub;
}
