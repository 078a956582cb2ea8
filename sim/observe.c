#include "observe.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "registry.h"
#include "rng.h"

static const char *const names[SIM_OBS_PROFILE] = {
    "T", "T_raw", "ux", "uy", "uz", "Pxx", "Pyy", "Pzz", "Pxy", "Pxz", "Pyz",
    "qx", "qy", "qz", "a2", "a3",
    "s", "s0", "T_ratio", "Pxy_reduced", "N1", "N2", "a_star", "eta_star", "Psi1", "Psi2",
    "v12_ratio", "R0", "R1", "R2", "R3",
    "ux_centre", "ux_top", "n_centre", "n_top", "T_centre", "T_top", "ux_slope",
};
static const char *const profile_names[SIM_PROFILES] = {"n", "ux", "T", "Pxy"};

const char *sim_observable_name(const sim_scene *scene, size_t k, char buf[SIM_OBS_NAME_LEN])
{
    const size_t layers = scene->shear.layers;
    if (k < SIM_OBS_PROFILE)
        snprintf(buf, SIM_OBS_NAME_LEN, "%s", names[k]);
    else if (k < sim_observe_row_length(scene))
        snprintf(buf, SIM_OBS_NAME_LEN, "%s_%zu", profile_names[(k - SIM_OBS_PROFILE) / layers],
                 (k - SIM_OBS_PROFILE) % layers);
    else
        snprintf(buf, SIM_OBS_NAME_LEN, "?");
    return buf;
}

int sim_observable_find(const sim_scene *scene, const char *name, size_t len)
{
    const size_t row = sim_observe_row_length(scene);
    for (size_t k = 0; k < SIM_OBS_PROFILE && k < row; k++)
        if (strlen(names[k]) == len && strncmp(names[k], name, len) == 0)
            return (int)k;
    if (row <= SIM_OBS_PROFILE)
        return -1;
    for (int p = 0; p < SIM_PROFILES; p++) {   /* NAME_I */
        const size_t plen = strlen(profile_names[p]);
        if (len < plen + 2 || strncmp(name, profile_names[p], plen) != 0 || name[plen] != '_')
            continue;
        size_t layer = 0, d = plen + 1;
        for (; d < len && name[d] >= '0' && name[d] <= '9' && layer < SIM_SLAB_LAYERS_MAX; d++)
            layer = 10 * layer + (size_t)(name[d] - '0');
        if (d == len && layer < scene->shear.layers && (len == plen + 2 || name[plen + 1] != '0'))
            return (int)(SIM_OBS_PROFILE + (size_t)p * scene->shear.layers + layer);
    }
    return -1;
}

/* The observables each part of the computation serves. */
#define OBS_Q (SIM_OBS_BIT(SIM_OBS_QX) | SIM_OBS_BIT(SIM_OBS_QY) | SIM_OBS_BIT(SIM_OBS_QZ))
#define OBS_C6 SIM_OBS_BIT(SIM_OBS_A3)
#define OBS_C4 (SIM_OBS_BIT(SIM_OBS_A2) | OBS_C6)   /* a3 = ... + 3 a2 */
#define OBS_CENTRED (SIM_OBS_BIT(SIM_OBS_T) | SIM_OBS_BIT(SIM_OBS_PXX) | SIM_OBS_BIT(SIM_OBS_PYY) \
                     | SIM_OBS_BIT(SIM_OBS_PZZ) | SIM_OBS_BIT(SIM_OBS_PXY)                     \
                     | SIM_OBS_BIT(SIM_OBS_PXZ) | SIM_OBS_BIT(SIM_OBS_PYZ) | OBS_Q | OBS_C4)

/* The centred sums about V: P (always), q, |C|^4 and |C|^6 as the constant
 * flags ask (one instance per combination, no branch in the loop).  Central
 * moments in a pass of their own: no cancellation against |V|^2. */
static inline __attribute__((always_inline)) void
centred_sums(const sim_particles *p, const double V[3], double P[6], double q[3], double *c4,
             double *c6, const int with_q, const int with_c4, const int with_c6)
{
    for (size_t i = 0; i < p->n; i++) {
        const double c[3] = {p->v[i][0] - V[0], p->v[i][1] - V[1], p->v[i][2] - V[2]};
        const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        P[0] += c[0] * c[0];
        P[1] += c[1] * c[1];
        P[2] += c[2] * c[2];
        P[3] += c[0] * c[1];
        P[4] += c[0] * c[2];
        P[5] += c[1] * c[2];
        if (with_q) {
            q[0] += c2 * c[0];
            q[1] += c2 * c[1];
            q[2] += c2 * c[2];
        }
        if (with_c4)
            *c4 += c2 * c2;
        if (with_c6)
            *c6 += c2 * c2 * c2;
    }
}

void sim_observe(const sim_particles *p, double mass, double out[SIM_OBS_BASE])
{
    sim_observe_only(p, mass, 0, out);
}

void sim_observe_only(const sim_particles *p, double mass, uint32_t only,
                      double out[SIM_OBS_BASE])
{
    if (only == 0)
        only = SIM_OBS_ALL_BASE;
    const size_t n = p->n;
    const double w = 1.0 / (double)n;
    double V[3] = {0, 0, 0}, v2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double *v = p->v[i];
        V[0] += v[0];
        V[1] += v[1];
        V[2] += v[2];
        v2 += v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    }
    for (int k = 0; k < 3; k++)
        V[k] *= w;
    out[SIM_OBS_T_RAW] = mass * w * v2 / 3.0;
    out[SIM_OBS_UX] = V[0];
    out[SIM_OBS_UY] = V[1];
    out[SIM_OBS_UZ] = V[2];

    if (only & OBS_CENTRED) {
        double P[6] = {0}, q[3] = {0}, c4 = 0.0, c6 = 0.0;
        const int with_q = (only & OBS_Q) != 0, with_c4 = (only & OBS_C4) != 0;
        switch (4 * with_q + 2 * with_c4 + ((only & OBS_C6) != 0)) {
        case 0: centred_sums(p, V, P, q, &c4, &c6, 0, 0, 0); break;
        case 2: centred_sums(p, V, P, q, &c4, &c6, 0, 1, 0); break;
        case 3: centred_sums(p, V, P, q, &c4, &c6, 0, 1, 1); break;
        case 4: centred_sums(p, V, P, q, &c4, &c6, 1, 0, 0); break;
        case 6: centred_sums(p, V, P, q, &c4, &c6, 1, 1, 0); break;
        default: centred_sums(p, V, P, q, &c4, &c6, 1, 1, 1); break;
        }
        const double T = mass * w * (P[0] + P[1] + P[2]) / 3.0;
        const double theta = T / mass;   /* T/m */
        out[SIM_OBS_T] = T;
        for (int k = 0; k < 6; k++)
            out[SIM_OBS_PXX + k] = mass * w * P[k];
        for (int k = 0; k < 3; k++)
            out[SIM_OBS_QX + k] = 0.5 * mass * w * q[k];
        const double a2 = w * c4 / (15.0 * theta * theta) - 1.0;
        out[SIM_OBS_A2] = a2;
        out[SIM_OBS_A3] = -w * c6 / (105.0 * theta * theta * theta) + 1.0 + 3.0 * a2;
    }
    sim_observe_drop(only, out);
}

void sim_observe_drop(uint32_t only, double out[SIM_OBS_BASE])
{
    if (only == 0)
        return;
    for (int k = 0; k < SIM_OBS_BASE; k++)
        if (!(only & SIM_OBS_BIT(k)))
            out[k] = NAN;
}

void sim_sums_compute(const sim_particles *p, sim_sums *s)
{
    memset(s, 0, sizeof *s);
    for (size_t i = 0; i < p->n; i++)
        sim_sums_add(s, p->v[i], p->stamp ? p->stamp[i] : 0.0, 1.0);
}

void sim_observe_sums(const sim_sums *s, size_t n, double mass, double t, double spread,
                      double out[SIM_OBS_BASE])
{
    const double w = 1.0 / (double)n;
    const double S = spread * (t - s->stamp * w);   /* the mean variance owed */
    const double V[3] = {s->v[0] * w, s->v[1] * w, s->v[2] * w};
    static const int a[6] = {0, 1, 2, 0, 0, 1}, b[6] = {0, 1, 2, 1, 2, 2};
    for (int k = 0; k < 6; k++)
        out[SIM_OBS_PXX + k] = mass * (s->vv[k] * w - V[a[k]] * V[b[k]]
                                       + (k < 3 ? S * (1.0 - w) : 0.0));
    out[SIM_OBS_T] = (out[SIM_OBS_PXX] + out[SIM_OBS_PYY] + out[SIM_OBS_PZZ]) / 3.0;
    out[SIM_OBS_T_RAW] = mass * ((s->vv[0] + s->vv[1] + s->vv[2]) * w / 3.0 + S);
    for (int k = 0; k < 3; k++)
        out[SIM_OBS_UX + k] = V[k];
    for (int k = SIM_OBS_QX; k <= SIM_OBS_A3; k++)
        out[k] = NAN;
}

size_t sim_observe_row_length(const sim_scene *scene)
{
    return SIM_OBS_BASE + sim_registry_observables(scene);
}

/* tau_eta = 1.016 (5 sqrt(pi)/8) lambda0/sqrt(2 theta), theta = T/m (E Eq. 2.18
 * with the 1.016 of docs/theory.md §2.3). */
static double tau_eta(const sim_scene *scene, double theta)
{
    return 1.016 * 5.0 * sqrt(M_PI) / 8.0 * sim_scene_mean_free_path(scene) / sqrt(2.0 * theta);
}

/* ds0/dt = beta/(sqrt(pi) tau), tau = lambda0/sqrt(2 theta) (E Eq. 3.13). */
static double s0_rate(const sim_scene *scene, double theta)
{
    return sim_scene_collision_rate_factor(scene) * sqrt(2.0 * theta)
           / (sqrt(M_PI) * sim_scene_mean_free_path(scene));
}

/* The Maxwellian's fraction of reduced speeds below x: erf(x) - 2x e^{-x^2}/sqrt(pi). */
static double maxwell_below(double x)
{
    return isinf(x) ? 1.0 : erf(x) - 2.0 * x * exp(-x * x) / sqrt(M_PI);
}

void sim_observe_shear(const sim_scene *scene, const sim_particles *p, double mass,
                       uint64_t collisions, size_t m, const double *prev, gsl_rng *rng,
                       double *row)
{
    static const double edges[5] = {0.0, 1.0, 2.0, 3.0, INFINITY};   /* E's C_l */
    const size_t n = p->n;
    const double T = row[SIM_OBS_T], theta = T / mass, v0 = sqrt(2.0 * theta);
    const double V[3] = {row[SIM_OBS_UX], row[SIM_OBS_UY], row[SIM_OBS_UZ]};

    row[SIM_OBS_S] = (double)collisions / (double)n;
    row[SIM_OBS_S0] = 0.0;
    if (m > 0 && prev != NULL) {
        const double dt = sim_scene_output_time(scene, m) - sim_scene_output_time(scene, m - 1);
        row[SIM_OBS_S0] = prev[SIM_OBS_S0]
                          + 0.5 * dt * (s0_rate(scene, prev[SIM_OBS_T] / mass)
                                        + s0_rate(scene, theta));
    }
    row[SIM_OBS_T_RATIO] = T / scene->particles.maxwellian.temperature;
    /* the base row's P_ij = m <C_i C_j> per particle, so P/(nT) = P_ij/T */
    const double pxy = -row[SIM_OBS_PXY] / T;
    const double n1 = (row[SIM_OBS_PXX] - row[SIM_OBS_PYY]) / T;
    const double n2 = (row[SIM_OBS_PZZ] - row[SIM_OBS_PYY]) / T;
    const double a_star = scene->shear.rate * tau_eta(scene, theta);
    row[SIM_OBS_PXY_REDUCED] = pxy;
    row[SIM_OBS_N1] = n1;
    row[SIM_OBS_N2] = n2;
    row[SIM_OBS_A_STAR] = a_star;
    row[SIM_OBS_ETA_STAR] = pxy / a_star;
    row[SIM_OBS_PSI1] = -n1 / (a_star * a_star);
    row[SIM_OBS_PSI2] = n2 / (a_star * a_star);

    double v12 = NAN;
    const size_t pairs = scene->shear.pairs;
    if (pairs > 0 && rng != NULL) {
        double s3 = 0.0;
        for (size_t q = 0; q < pairs; q++) {
            size_t i = (size_t)sim_rng_index(rng, n);
            size_t j = (size_t)sim_rng_index(rng, n - 1);
            j += (j >= i);
            const double g[3] = {p->v[i][0] - p->v[j][0], p->v[i][1] - p->v[j][1],
                                 p->v[i][2] - p->v[j][2]};
            const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
            s3 += g2 * sqrt(g2);
        }
        v12 = s3 / (double)pairs / (32.0 / sqrt(M_PI) * theta * sqrt(theta));
    }
    row[SIM_OBS_V12_RATIO] = v12;

    /* E Eq. (3.15): shells of |C|/v0 */
    size_t count[4] = {0, 0, 0, 0};
    const double w1 = v0 * v0, w2 = 4.0 * w1, w3 = 9.0 * w1;
    for (size_t i = 0; i < n; i++) {
        const double c[3] = {p->v[i][0] - V[0], p->v[i][1] - V[1], p->v[i][2] - V[2]};
        const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        count[(c2 >= w1) + (c2 >= w2) + (c2 >= w3)]++;
    }
    for (int l = 0; l < 4; l++)
        row[SIM_OBS_R0 + l] = (double)count[l] / (double)n
                              / (maxwell_below(edges[l + 1]) - maxwell_below(edges[l]));
}
