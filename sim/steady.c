#include "steady.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "observe.h"
#include "registry.h"
#include "rng.h"

static const char *const names[SIM_STEADY_BIN0] = {
    "T", "a2", "a3", "c1", "c3", "mu2", "mu4", "mu4_white", "mu4_gaussian", "mu4_nongaussian",
};

size_t sim_steady_count(const sim_scene *scene)
{
    if (!scene->steady.present)
        return 0;
    return SIM_STEADY_BIN0 + scene->steady.bins + sim_registry_steady_columns(scene);
}

size_t sim_steady_heat_flux_first(const sim_scene *scene)
{
    return sim_registry_steady_first(scene, "heat-flux");
}

size_t sim_steady_shear_first(const sim_scene *scene)
{
    return sim_registry_steady_first(scene, "shear");
}

const char *sim_steady_name(const sim_scene *scene, size_t k, char *buf, size_t len)
{
    size_t first;
    const sim_steady_block *b = sim_registry_steady_block(scene, k, &first);
    if (b != NULL)
        b->name(scene, k - first, buf, len);
    else if (k < SIM_STEADY_BIN0)
        snprintf(buf, len, "%s", names[k]);
    else
        snprintf(buf, len, "f_%zu", k - SIM_STEADY_BIN0);
    return buf;
}

int sim_steady_scalar(const sim_scene *scene, size_t k)
{
    size_t first;
    const sim_steady_block *b = sim_registry_steady_block(scene, k, &first);
    return b != NULL ? k - first < b->scalars : k < SIM_STEADY_BIN0;
}

long sim_steady_find(const sim_scene *scene, const char *name)
{
    const size_t count = sim_steady_count(scene);
    for (size_t k = 0; k < count; k++) {
        char buf[32];
        if (strcmp(sim_steady_name(scene, k, buf, sizeof buf), name) == 0)
            return (long)k;
    }
    return -1;
}

double sim_steady_bin_lower(const sim_scene *scene, size_t k)
{
    return scene->steady.c_max * (double)k / (double)scene->steady.bins;
}

double sim_steady_bin_centre(const sim_scene *scene, size_t k)
{
    return scene->steady.c_max * ((double)k + 0.5) / (double)scene->steady.bins;
}

double sim_steady_marginal_centre(const sim_scene *scene, size_t k)
{
    return sim_steady_bin_centre(scene, k) - scene->steady.c_max;
}

/* Pairs drawn ahead by the collisional-moment sampler (sim_steady_sample). */
#define PAIR_BLOCK 32

/* The peculiar velocities of a block of pairs, by component (c1 of the
 * first particle, c2 of the second). */
typedef struct pair_block {
    double c1[3][PAIR_BLOCK], c2[3][PAIR_BLOCK];
} pair_block;

/* Paper C Eqs. (65), (66): Phi2 and Phi4 of every pair of the block.  A loop
 * of a constant count over columns, which GCC -O2 vectorizes (two pairs per
 * SSE2 instruction); each pair's operations are those of the formulas as
 * written, so the values are those of one pair at a time. */
static void phi24_block(const pair_block *b, double alpha, double phi2[PAIR_BLOCK],
                        double phi4[PAIR_BLOCK])
{
    const double a2 = alpha * alpha;
    for (size_t k = 0; k < PAIR_BLOCK; k++) {
        const double gx = b->c1[0][k] - b->c2[0][k], Gx = 0.5 * (b->c1[0][k] + b->c2[0][k]);
        const double gy = b->c1[1][k] - b->c2[1][k], Gy = 0.5 * (b->c1[1][k] + b->c2[1][k]);
        const double gz = b->c1[2][k] - b->c2[2][k], Gz = 0.5 * (b->c1[2][k] + b->c2[2][k]);
        const double g2 = gx * gx + gy * gy + gz * gz;
        const double G2 = Gx * Gx + Gy * Gy + Gz * Gz;
        const double gG = gx * Gx + gy * Gy + gz * Gz;
        const double gn = sqrt(g2);
        phi2[k] = M_PI * (1.0 - a2) / 8.0 * g2 * gn;
        phi4[k] = 0.25 * M_PI * gn
                  * (5.0 * (1.0 - a2) / 3.0 * g2 * G2 + (1.0 - a2) * (2.0 + a2) / 12.0 * g2 * g2
                     + (3.0 - alpha) * (1.0 + alpha) * (gG * gG - g2 * G2 / 3.0));
    }
}

/* Reduced speed moments <c>, <c^3>, <c^4>, <c^6> (sums over the particles)
 * and, when `histogram` (a constant in each caller), the shell counts. */
static inline void speed_moments(const sim_particles *p, const double V[3], double inv_v0,
                                 const int histogram, double c_max, size_t bins, double *sum,
                                 double m[4])
{
    const size_t n = p->n;
    const double delta = c_max / (double)bins;
    const double shell = 4.0 * M_PI / 3.0 * delta * delta * delta * (double)n;
    double m1 = 0.0, m3 = 0.0, m4 = 0.0, m6 = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double c[3] = {p->v[i][0] - V[0], p->v[i][1] - V[1], p->v[i][2] - V[2]};
        const double c2 = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) * inv_v0 * inv_v0;
        const double cn = sqrt(c2);
        m1 += cn;
        m3 += c2 * cn;
        m4 += c2 * c2;
        m6 += c2 * c2 * c2;
        if (histogram && cn < c_max) {
            size_t b = (size_t)(cn / delta);
            if (b >= bins)   /* round-off at the last edge */
                b = bins - 1;
            const double kb = (double)b;   /* shell volume ∝ (k+1)^3 - k^3 */
            sum[SIM_STEADY_BIN0 + b] += 1.0 / (shell * (3.0 * kb * kb + 3.0 * kb + 1.0));
        }
    }
    m[0] = m1, m[1] = m3, m[2] = m4, m[3] = m6;
}

void sim_steady_sample(const sim_scene *scene, const sim_particles *p, double mass,
                       gsl_rng *rng, const double *row, double *sum)
{
    const size_t n = p->n, bins = scene->steady.bins;
    const double w = 1.0 / (double)n;
    double V[3] = {0, 0, 0};
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            V[k] += p->v[i][k];
    for (int k = 0; k < 3; k++)
        V[k] *= w;
    double s2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double c[3] = {p->v[i][0] - V[0], p->v[i][1] - V[1], p->v[i][2] - V[2]};
        s2 += c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    }
    const double theta = w * s2 / 3.0;          /* T/m */
    const double v0 = sqrt(2.0 * theta), inv_v0 = 1.0 / v0;

    /* Reduced speed moments and the histogram. */
    double m[4];
    if (bins > 0)
        speed_moments(p, V, inv_v0, 1, scene->steady.c_max, bins, sum, m);
    else
        speed_moments(p, V, inv_v0, 0, 1.0, 1, sum, m);
    const double m1 = m[0] * w, m3 = m[1] * w, m4 = m[2] * w, m6 = m[3] * w;
    /* a2 = (4/15) <c^4> - 1, a3 = -(8/105) <c^6> + 1 + 3 a2 (docs/theory.md §10.2) */
    const double a2 = 4.0 / 15.0 * m4 - 1.0;
    const double a3 = -8.0 / 105.0 * m6 + 1.0 + 3.0 * a2;

    /* Collisional moments by pair sampling, paper C Eq. (67). */
    double mu2 = NAN, mu4 = NAN;
    const size_t pairs = scene->steady.pairs;
    if (pairs > 0 && rng != NULL) {
        const double alpha = scene->collisions.restitution;   /* 1 unless set */
        double s_2 = 0.0, s_4 = 0.0;
        /* The pairs of a block are drawn first and their velocities
         * prefetched, then evaluated together, then summed in the same
         * order: the same draws and sums, bit for bit, as one pair at a
         * time, with the loads and the arithmetic of a block overlapping
         * (ms-gaussian at n = 2e4, best of 7 on one core: 1.66 s, against
         * 1.94 s a pair at a time with its loads prefetched and 2.19 s
         * without). */
        size_t first[PAIR_BLOCK], second[PAIR_BLOCK];
        pair_block block = {0};   /* a last, partial block leaves zeros */
        double f2[PAIR_BLOCK], f4[PAIR_BLOCK];
        for (size_t q0 = 0; q0 < pairs; q0 += PAIR_BLOCK) {
            const size_t count = pairs - q0 < PAIR_BLOCK ? pairs - q0 : PAIR_BLOCK;
            for (size_t b = 0; b < count; b++) {
                const size_t i = (size_t)sim_rng_index(rng, n);
                size_t j = (size_t)sim_rng_index(rng, n - 1);
                j += (j >= i);
                first[b] = i;
                second[b] = j;
                sim_pick_prefetch(p, (uint32_t)i, 0);
                sim_pick_prefetch(p, (uint32_t)j, 0);
            }
            for (size_t b = 0; b < count; b++)
                for (int d = 0; d < 3; d++) {
                    block.c1[d][b] = p->v[first[b]][d] - V[d];
                    block.c2[d][b] = p->v[second[b]][d] - V[d];
                }
            phi24_block(&block, alpha, f2, f4);
            for (size_t b = 0; b < count; b++) {
                s_2 += f2[b];
                s_4 += f4[b];
            }
        }
        mu2 = s_2 / (double)pairs * pow(inv_v0, 3.0);
        mu4 = s_4 / (double)pairs * pow(inv_v0, 5.0);
    }

    sum[SIM_STEADY_T] += mass * theta;
    sum[SIM_STEADY_A2] += a2;
    sum[SIM_STEADY_A3] += a3;
    sum[SIM_STEADY_C1] += m1;
    sum[SIM_STEADY_C3] += m3;
    sum[SIM_STEADY_MU2] += mu2;
    sum[SIM_STEADY_MU4] += mu4;
    sum[SIM_STEADY_MU4_WHITE] += 5.0 * mu2;                   /* (d + 2) mu2 */
    sum[SIM_STEADY_MU4_GAUSSIAN] += 5.0 * (1.0 + a2) * mu2;
    sum[SIM_STEADY_MU4_NONGAUSSIAN] += 2.0 * mu2 * m3 / m1;
    sim_registry_steady_sample(scene, p, mass, V, theta, row, sum);
}

void sim_steady_finish(const sim_scene *scene, double *avg)
{
    sim_registry_steady_finish(scene, avg);
}
