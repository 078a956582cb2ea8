#include "rng.h"

#include <pthread.h>
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

/* ------------------------------------------------------------- ziggurat */

/* Marsaglia and Tsang's 128 layers for exp(-x^2/2), base edge r to 13
 * digits (their "rnor"); ziggurat_build refines r to round-off. */
#define ZIGGURAT_R 3.442619855899

sim_ziggurat sim_ziggurat_table;

/* The area of the base strip: the rectangle under f(r) and the tail beyond r. */
static double ziggurat_area(double r)
{
    return r * exp(-0.5 * r * r) + sqrt(M_PI / 2.0) * erfc(r / M_SQRT2);
}

/* The layer edges for base edge r and area V = ziggurat_area(r): x[1] = r,
 * x[i] (f(x[i+1]) - f(x[i])) = V, so x[i+1] = f^-1(f(x[i]) + V / x[i]).
 * Returns f(x[127]) + V / x[127] - 1, which is 0 when the top layer ends at
 * f = 1 (x[128] = 0), and 1 when the layers reach f = 1 early. */
static double ziggurat_edges(double r, double x[SIM_ZIGGURAT_LAYERS + 1])
{
    const double V = ziggurat_area(r);
    x[1] = r;
    for (int i = 1; i < SIM_ZIGGURAT_LAYERS - 1; i++) {
        const double top = V / x[i] + exp(-0.5 * x[i] * x[i]);
        if (!(top < 1.0))
            return 1.0;
        x[i + 1] = sqrt(-2.0 * log(top));
    }
    const double last = x[SIM_ZIGGURAT_LAYERS - 1];
    return V / last + exp(-0.5 * last * last) - 1.0;
}

/* The tables: r by bisection about Marsaglia and Tsang's value (a larger r
 * has smaller layers, which close later), the base strip as wide as its area
 * over its height, x[0] = V / f(r). */
static void ziggurat_build(void)
{
    sim_ziggurat *z = &sim_ziggurat_table;
    double x[SIM_ZIGGURAT_LAYERS + 1], lo = ZIGGURAT_R * (1.0 - 1e-9), hi = ZIGGURAT_R * (1.0 + 1e-9);
    for (int it = 0; it < 64; it++) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
            break;
        if (ziggurat_edges(mid, x) > 0.0)
            lo = mid;
        else
            hi = mid;
    }
    const double r = hi;
    ziggurat_edges(r, x);
    x[0] = ziggurat_area(r) / exp(-0.5 * r * r);
    x[SIM_ZIGGURAT_LAYERS] = 0.0;
    for (int i = 0; i < SIM_ZIGGURAT_LAYERS; i++) {
        z->k[i] = 0x1p24 * x[i + 1] / x[i];
        z->w[i] = x[i] * 0x1p-24;
        z->f[i] = exp(-0.5 * x[i] * x[i]);
    }
    z->f[SIM_ZIGGURAT_LAYERS] = 1.0;
    z->r = r;
}

static pthread_once_t ziggurat_once = PTHREAD_ONCE_INIT;

double sim_rng_normal_rest(gsl_rng *r, uint32_t bits)
{
    const sim_ziggurat *z = &sim_ziggurat_table;
    for (;;) {
        const unsigned i = bits & 0x7f;
        const double u = sim_ziggurat_position(bits), x = u * z->w[i], ax = fabs(x);
        if (fabs(u) < z->k[i])
            return x;
        if (i == 0) {
            if (ax < z->r)
                return x;
            /* the tail beyond r (Marsaglia, Technometrics 6 (1964) 101) */
            double a, b;
            do {
                a = -log(sim_rng_uniform_pos(r)) / z->r;
                b = -log(sim_rng_uniform_pos(r));
            } while (b + b < a * a);
            return copysign(z->r + a, u);
        }
        /* the wedge between x[i+1] and x[i]: a height uniform in layer i */
        const double y = z->f[i] + sim_rng_uniform(r) * (z->f[i + 1] - z->f[i]);
        if (y < exp(-0.5 * ax * ax))
            return x;
        bits = sim_rng_u32(r);
    }
}

/* ---------------------------------------------------------------- stream */

static void philox_set(void *vstate, unsigned long seed)
{
    pthread_once(&ziggurat_once, ziggurat_build);
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
