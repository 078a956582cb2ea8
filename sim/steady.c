#include "steady.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "observe.h"
#include "rng.h"

static const char *const names[SIM_STEADY_BIN0] = {
    "T", "a2", "a3", "c1", "c3", "mu2", "mu4", "mu4_white", "mu4_gaussian", "mu4_nongaussian",
};

static const char *const heat_flux_names[SIM_HF_SCALARS] = {
    "qx", "kappa_prime", "b1", "b2", "b3", "b1_x", "b2_x", "b3_x", "b1_x_outer",
};

static const char *const shear_names[SIM_SHEAR_SCALARS] = {
    "Pxy_reduced", "N1", "N2", "a_star", "v12_ratio", "R0", "R1", "R2", "R3",
};

/* The output row's observables the shear scalars average, in their order. */
static const sim_observable shear_row[SIM_SHEAR_SCALARS] = {
    SIM_OBS_PXY_REDUCED, SIM_OBS_N1, SIM_OBS_N2, SIM_OBS_A_STAR, SIM_OBS_V12_RATIO,
    SIM_OBS_R0, SIM_OBS_R1, SIM_OBS_R2, SIM_OBS_R3,
};

size_t sim_steady_shear_first(const sim_scene *scene)
{
    const size_t bins = scene->steady.bins;
    return SIM_STEADY_BIN0 + bins + (scene->heat_flux.present ? SIM_HF_SCALARS + 2 * bins : 0);
}

size_t sim_steady_count(const sim_scene *scene)
{
    if (!scene->steady.present)
        return 0;
    return sim_steady_shear_first(scene)
           + (scene->shear.present ? SIM_SHEAR_SCALARS + 5 * scene->steady.bins : 0);
}

size_t sim_steady_heat_flux_first(const sim_scene *scene)
{
    return SIM_STEADY_BIN0 + scene->steady.bins;
}

const char *sim_steady_name(const sim_scene *scene, size_t k, char *buf, size_t len)
{
    const size_t bins = scene->steady.bins, hf = sim_steady_heat_flux_first(scene);
    const size_t sh = sim_steady_shear_first(scene);
    if (k >= sh + SIM_SHEAR_SCALARS + 4 * bins)
        snprintf(buf, len, "F_%zu", k - sh - SIM_SHEAR_SCALARS - 4 * bins);
    else if (k >= sh + SIM_SHEAR_SCALARS)
        snprintf(buf, len, "%s_%zu", k - sh - SIM_SHEAR_SCALARS < 2 * bins ? "gx" : "gy",
                 (k - sh - SIM_SHEAR_SCALARS) % (2 * bins));
    else if (k >= sh)
        snprintf(buf, len, "%s", shear_names[k - sh]);
    else if (k < SIM_STEADY_BIN0)
        snprintf(buf, len, "%s", names[k]);
    else if (k < hf)
        snprintf(buf, len, "f_%zu", k - SIM_STEADY_BIN0);
    else if (k < hf + SIM_HF_SCALARS)
        snprintf(buf, len, "%s", heat_flux_names[k - hf]);
    else if (k < hf + SIM_HF_SCALARS + bins)
        snprintf(buf, len, "g1_%zu", k - hf - SIM_HF_SCALARS);
    else
        snprintf(buf, len, "beta1_%zu", k - hf - SIM_HF_SCALARS - bins);
    return buf;
}

int sim_steady_scalar(const sim_scene *scene, size_t k)
{
    const size_t hf = sim_steady_heat_flux_first(scene);
    const size_t sh = sim_steady_shear_first(scene);
    return k < SIM_STEADY_BIN0 || (k >= hf && k < hf + SIM_HF_SCALARS)
           || (k >= sh && k < sh + SIM_SHEAR_SCALARS);
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

/* The generalised Laguerre polynomial L_k^{(a)}(x) for k = 1, 2, 3 into
 * L[0..2] (the three-term recurrence from L_0 = 1, L_1 = 1 + a - x). */
static inline void laguerre3(double a, double x, double L[3])
{
    L[0] = 1.0 + a - x;
    L[1] = ((3.0 + a - x) * L[0] - (1.0 + a)) / 2.0;
    L[2] = ((5.0 + a - x) * L[1] - (2.0 + a) * L[0]) / 3.0;
}

double sim_steady_kappa_per_moment(const sim_scene *scene)
{
    return -64.0 / (75.0 * sqrt(M_PI))
           / (sim_scene_mean_free_path(scene) * scene->heat_flux.strength);
}

/* Paper D's heat-flux quantities of one sample (steady.h), added to
 * sum[hf ...] (hf = sim_steady_heat_flux_first). */
static void heat_flux_sample(const sim_scene *scene, const sim_particles *p, double mass,
                             const double V[3], double theta, double *sum)
{
    static const double P[3] = {4.0 / 5.0, 16.0 / 35.0, 32.0 / 105.0};   /* D Eq. 3.10 */
    static const double Q[3] = {4.0 / 3.0, 16.0 / 15.0, 32.0 / 35.0};    /* D Eq. 3.12 */
    const size_t n = p->n, bins = scene->steady.bins;
    const double w = 1.0 / (double)n, v0 = sqrt(2.0 * theta), inv_v0 = 1.0 / v0;
    const double inv_eps = 1.0 / (sim_scene_mean_free_path(scene) * scene->heat_flux.strength);
    const double delta = bins > 0 ? scene->steady.c_max / (double)bins : 1.0;
    double *hf = sum + sim_steady_heat_flux_first(scene);
    double *g1 = hf + SIM_HF_SCALARS, *beta1 = g1 + bins;
    double q = 0.0, b[3] = {0, 0, 0}, bx[3] = {0, 0, 0}, outer = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double c[3] = {(p->v[i][0] - V[0]) * inv_v0, (p->v[i][1] - V[1]) * inv_v0,
                             (p->v[i][2] - V[2]) * inv_v0};
        const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2], cx2 = c[0] * c[0];
        double L[3], Lx[3];
        laguerre3(1.5, c2, L);
        laguerre3(0.5, cx2, Lx);
        q += c2 * c[0];
        for (int k = 0; k < 3; k++) {
            b[k] += c[0] * L[k];
            bx[k] += c[0] * Lx[k];
        }
        if (cx2 > 6.0)
            outer += c[0] * Lx[0];
        const double ax = fabs(c[0]);
        if (ax < scene->steady.c_max && bins > 0) {
            size_t k = (size_t)(ax / delta);
            if (k >= bins)   /* round-off at the last edge */
                k = bins - 1;
            g1[k] += (c[0] > 0.0 ? 1.0 : -1.0) * 0.5 * w / delta * inv_eps;
            /* per bin here; sim_steady_finish makes it cumulative */
            beta1[k] += Q[0] * c[0] * Lx[0] * w * inv_eps;
        }
    }
    hf[SIM_HF_QX] += 0.5 * mass * v0 * v0 * v0 * q * w;
    hf[SIM_HF_KAPPA_PRIME] += sim_steady_kappa_per_moment(scene) * q * w;
    for (int k = 0; k < 3; k++) {
        hf[SIM_HF_B1 + k] += P[k] * b[k] * w * inv_eps;
        hf[SIM_HF_B1_X + k] += Q[k] * bx[k] * w * inv_eps;
    }
    hf[SIM_HF_B1_X_OUTER] += Q[0] * outer * w * inv_eps;
}

/* The bin of x in [0, bins/inv_width), x >= 0 (rounding kept inside). */
static size_t bin_of(double x, double inv_width, size_t bins)
{
    const size_t k = (size_t)(x * inv_width);
    return k < bins ? k : bins - 1;
}

/* Paper E's shear-flow quantities of one sample (steady.h), added to
 * sum[sim_steady_shear_first ...]: the row's shear observables, and with bins
 * the marginals gx, gy (symmetrised, E Eq. 5.3) and F of C = (v - V)/v0. */
static void shear_sample(const sim_scene *scene, const sim_particles *p, const double V[3],
                         double inv_v0, const double *row, double *sum)
{
    double *sh = sum + sim_steady_shear_first(scene);
    for (int k = 0; k < SIM_SHEAR_SCALARS; k++)
        sh[k] += row[shear_row[k]];
    const size_t bins = scene->steady.bins, n = p->n;
    if (bins == 0)
        return;
    double *gx = sh + SIM_SHEAR_SCALARS, *gy = gx + 2 * bins, *F = gy + 2 * bins;
    const double width = scene->steady.c_max / (double)bins, inv_width = 1.0 / width;
    const double c_max = scene->steady.c_max;
    const double half = 0.5 / ((double)n * width);       /* (1/2) per particle per width */
    const double whole = 1.0 / ((double)n * width);
    for (size_t i = 0; i < n; i++) {
        const double cx = (p->v[i][0] - V[0]) * inv_v0, cy = (p->v[i][1] - V[1]) * inv_v0;
        const double cz = (p->v[i][2] - V[2]) * inv_v0;
        /* g_x^(+) at C_x for C_y > 0, g_x^(-)(-C_x) = g_x^(+) at -C_x for C_y < 0 */
        const double x = cy > 0.0 ? cx : -cx, y = cx > 0.0 ? cy : -cy;
        if (fabs(x) < c_max && cy != 0.0)
            gx[bin_of(x + c_max, inv_width, 2 * bins)] += half;
        if (fabs(y) < c_max && cx != 0.0)
            gy[bin_of(y + c_max, inv_width, 2 * bins)] += half;
        const double c = sqrt(cx * cx + cy * cy + cz * cz);
        if (c < c_max)
            F[bin_of(c, inv_width, bins)] += whole;
    }
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
    if (scene->heat_flux.present)
        heat_flux_sample(scene, p, mass, V, theta, sum);
    if (scene->shear.present)
        shear_sample(scene, p, V, inv_v0, row, sum);
}

void sim_steady_finish(const sim_scene *scene, double *avg)
{
    if (!scene->heat_flux.present)
        return;
    const size_t bins = scene->steady.bins;
    double *beta1 = avg + sim_steady_heat_flux_first(scene) + SIM_HF_SCALARS + bins;
    for (size_t k = 1; k < bins; k++)   /* the prefix sum is linear: per bin, then cumulate */
        beta1[k] += beta1[k - 1];
}
