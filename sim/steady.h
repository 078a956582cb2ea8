/* Steady-state observers (docs/theory.md §10, paper C §3): quantities sampled at the
 * output times t >= steady.from of each ensemble and averaged over those
 * times, so that each ensemble yields one time average and the ensemble layer
 * gives their mean and a confidence half-width from N independent ensembles
 * (ensemble.h).  The scene's [steady] section turns them on.
 *
 * Reduced units: with V the bulk velocity, C = v - V, T the centred
 * temperature and v0 = sqrt(2T/m), c = C/v0 (<c^2> = 3/2).  Per sample:
 *   T                          centred temperature
 *   a2, a3                     as observe.h (docs/theory.md §1.2)
 *   c1 = <c>, c3 = <c^3>
 *   mu2, mu4                   collisional moments by pair sampling, paper C
 *                              Eqs. (65)-(67): v0^{-p-1} (1/N') Σ' Phi_p(C_i, C_j)
 *                              over N' = steady.pairs random pairs i != j (NaN
 *                              when pairs = 0); alpha = collisions.restitution
 *                              (its default 1 when the scene sets none)
 *   mu4_white                  5 mu2            (exact steady relation, white noise, Eq. (23))
 *   mu4_gaussian               5 (1 + a2) mu2   (Gaussian thermostat, Eq. (38))
 *   mu4_nongaussian            2 mu2 c3/c1      (non-Gaussian thermostat, Eq. (44))
 *   f_0 ... f_{bins-1}         the reduced distribution averaged over the shell
 *                              k Δ <= |c| < (k+1) Δ, Δ = c_max/bins: the fraction of
 *                              particles in it over its volume 4 pi/3 ((k+1)^3 - k^3) Δ^3,
 *                              so that ∫ f d^3c = 1 (paper C's f̃(c); Maxwellian:
 *                              pi^{-3/2} e^{-c^2})
 * The relations are computed per sample so that the difference between a
 * direct mu4 and an indirect one has its own confidence interval.
 *
 * With a [heat-flux] section (paper D, docs/theory.md §10.5), eps* = lambda eps with
 * lambda = 1/(sqrt(2) pi n sigma^2) and n sigma^2 = 4 gamma C (the hard-sphere
 * convention, used for every kernel), these follow the bins:
 *   qx                         (m/2) <|C|^2 C_x>
 *   kappa_prime                kappa'/kappa0 = -(64/(75 sqrt(pi))) <c^2 c_x>/eps*
 *                              (kappa' = -q_x/(T eps), kappa0 the elastic first
 *                              Sonine conductivity; D Eq. 2.47)
 *   b1, b2, b3                 P_k <c_x L_k^{(3/2)}(c^2)>/eps*, P_k = 4/5, 16/35, 32/105
 *                              (D Eq. 3.10)
 *   b1_x, b2_x, b3_x           Q_k <c_x L_k^{(1/2)}(c_x^2)>/eps*, Q_k = 4/3, 16/15, 32/35
 *                              (D Eq. 3.12)
 *   b1_x_outer                 b1_x restricted to c_x^2 > 6 (the heat flux carried
 *                              beyond c_x^2 = 6: D §4 prints 13% at alpha = 1)
 *   g1_0 ... g1_{bins-1}       g^(1)(c_x)/eps* = [g(c_x) - g(-c_x)]/(2 eps*) averaged
 *                              over |c_x| in bin k of [0, c_max) (D Eq. 3.15; g the
 *                              reduced marginal of c_x, ∫ g = 1), so that
 *                              phi(c_x^2) = sqrt(pi) e^{c_x^2} g1/c_x (D Eq. 4.3)
 *   beta1_0 ... beta1_{bins-1} beta_1 at the upper edge of bin k: b1_x restricted to
 *                              |c_x| below it (D Eq. 4.6: beta_1/b'_1 is the part of
 *                              b'_1, hence of the heat flux, carried by those c_x)
 * The time averages divide by eps* only once the sample is taken, so eps = 0
 * gives NaN for everything but qx.
 *
 * With a [shear] section (paper E, docs/theory.md §10.6), last: the time averages of the
 * output row's shear observables (observe.h, sim_observe_shear)
 *   Pxy_reduced, N1, N2, a_star, v12_ratio, R0, R1, R2, R3
 * and, with steady.bins = B > 0, E's marginals of the reduced velocity
 * C = (v - V)/sqrt(2T/m) (E Eqs. 3.16-3.20), as densities averaged over bins:
 *   gx_0 ... gx_{2B-1}         g_x^(+)(C_x) on 2B bins of [-c_max, c_max): the density of
 *                              C_x among the particles with C_y > 0, symmetrised by
 *                              E Eq. (5.3), (1/2)[g_x^(+)(C_x) + g_x^(-)(-C_x)]
 *                              (∫ gx = 1/2)
 *   gy_0 ... gy_{2B-1}         g_y^(+)(C_y) likewise (C_x > 0; ∫ gy = 1/2)
 *   F_0 ... F_{B-1}            F(C) = C^2 ∫ dΩ f*: the fraction of particles with |C| in
 *                              speed bin k over its width (∫ F = 1)
 *
 * Pair sampling draws from its own random substream (rng.h), so observing
 * never changes the simulated trajectory.
 */
#ifndef GDSMC_SIM_STEADY_H
#define GDSMC_SIM_STEADY_H

#include <stddef.h>

#include <gsl/gsl_rng.h>

#include "particles.h"
#include "scene.h"

typedef enum sim_steady_quantity {
    SIM_STEADY_T, SIM_STEADY_A2, SIM_STEADY_A3, SIM_STEADY_C1, SIM_STEADY_C3,
    SIM_STEADY_MU2, SIM_STEADY_MU4,
    SIM_STEADY_MU4_WHITE, SIM_STEADY_MU4_GAUSSIAN, SIM_STEADY_MU4_NONGAUSSIAN,
    SIM_STEADY_BIN0   /* the first histogram bin; bins follow */
} sim_steady_quantity;

/* The heat-flux quantities, in order after the bins (offsets from
 * sim_steady_heat_flux_first); then the g1 bins, then the beta1 bins. */
typedef enum sim_steady_heat_flux {
    SIM_HF_QX, SIM_HF_KAPPA_PRIME, SIM_HF_B1, SIM_HF_B2, SIM_HF_B3,
    SIM_HF_B1_X, SIM_HF_B2_X, SIM_HF_B3_X, SIM_HF_B1_X_OUTER,
    SIM_HF_SCALARS   /* the first g1 bin */
} sim_steady_heat_flux;

/* The shear-flow quantities, last (offsets from sim_steady_shear_first): the
 * scalars, then the gx, gy and F bins. */
typedef enum sim_steady_shear {
    SIM_SHEAR_PXY, SIM_SHEAR_N1, SIM_SHEAR_N2, SIM_SHEAR_A_STAR, SIM_SHEAR_V12,
    SIM_SHEAR_R0, SIM_SHEAR_R1, SIM_SHEAR_R2, SIM_SHEAR_R3,
    SIM_SHEAR_SCALARS
} sim_steady_shear;

/* Number of steady quantities of the scene: SIM_STEADY_BIN0 + steady.bins,
 * plus SIM_HF_SCALARS + 2 steady.bins with [heat-flux], plus SIM_SHEAR_SCALARS
 * + 5 steady.bins with [shear]; 0 without [steady]. */
size_t sim_steady_count(const sim_scene *scene);

/* Index of the first heat-flux quantity (qx): SIM_STEADY_BIN0 + steady.bins. */
size_t sim_steady_heat_flux_first(const sim_scene *scene);

/* Index of the first shear quantity (Pxy_reduced). */
size_t sim_steady_shear_first(const sim_scene *scene);

/* Name of quantity k of the scene ("T", "a2", ..., "f_0", ..., "qx", ...,
 * "g1_0", ..., "beta1_0", ...), in buf. */
const char *sim_steady_name(const sim_scene *scene, size_t k, char *buf, size_t len);

/* Whether quantity k is a single value rather than a bin of a profile. */
int sim_steady_scalar(const sim_scene *scene, size_t k);

/* The index of the quantity named `name`, or -1. */
long sim_steady_find(const sim_scene *scene, const char *name);

/* The reduced speed at the lower edge and the centre of bin k. */
double sim_steady_bin_lower(const sim_scene *scene, size_t k);
double sim_steady_bin_centre(const sim_scene *scene, size_t k);

/* The reduced velocity component at the centre of marginal bin k (gx_k, gy_k):
 * -c_max + (k + 1/2) c_max/bins. */
double sim_steady_marginal_centre(const sim_scene *scene, size_t k);

/* kappa'/kappa0 per unit of the reduced moment <c^2 c_x>: -(64/(75 sqrt(pi)))/eps*
 * (the kappa_prime above; D Eq. 2.47 with q_x = (m/2) v0^3 <c^2 c_x>). */
double sim_steady_kappa_per_moment(const sim_scene *scene);

/* A block of steady quantities an effect adds after the base ones (its
 * registry entry, registry.h, points at it; the blocks follow in the
 * registry's order): the heat-flux force's (effect_heat_flux.c) and the
 * shear's (effect_shear.c). */
typedef struct sim_steady_block {
    size_t (*count)(const sim_scene *scene);   /* 0 when the scene does not name it */
    size_t scalars;   /* its first `scalars` quantities are single values, the rest bins */
    /* The name of its quantity k into buf. */
    void (*name)(const sim_scene *scene, size_t k, char *buf, size_t len);
    /* Add one sample to block[count]: p the system, V its mean velocity, theta
     * = T/m about V, row the output row just observed. */
    void (*sample)(const sim_scene *scene, const sim_particles *p, double mass,
                   const double V[3], double theta, const double *row, double *block);
    /* One ensemble's time averages into the quantities (NULL: nothing to do). */
    void (*finish)(const sim_scene *scene, double *block);
} sim_steady_block;

extern const sim_steady_block sim_heat_flux_steady, sim_shear_steady;

/* The bin of x in [0, bins/inv_width), x >= 0 (rounding kept inside). */
static inline size_t sim_steady_bin_of(double x, double inv_width, size_t bins)
{
    const size_t k = (size_t)(x * inv_width);
    return k < bins ? k : bins - 1;
}

/* Add one sample of every quantity of p to sum[sim_steady_count(scene)]
 * (particles of mass `mass`; pair sampling with rng, which may be NULL when
 * steady.pairs = 0; row: the output row just observed, whose shear
 * observables the [shear] quantities average).  Allocates nothing. */
void sim_steady_sample(const sim_scene *scene, const sim_particles *p, double mass,
                       gsl_rng *rng, const double *row, double *sum);

/* Turn one ensemble's time averages avg[sim_steady_count(scene)] into the
 * quantities above (the beta1 bins are sampled per bin and made cumulative
 * here).  The engine calls it once per ensemble. */
void sim_steady_finish(const sim_scene *scene, double *avg);

#endif
