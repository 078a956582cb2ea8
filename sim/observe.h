/* Observables of one particle system (docs/theory.md §1.2, §9).
 *
 * Every observable is an estimator xi^(n) computed from the n velocities with
 * weights 1/n; the ensemble layer averages them over N ensembles.  With m the
 * particle mass, V the numerical bulk velocity and C = v - V:
 *   T     = (m/3) <|C|^2>            (centred)
 *   T_raw = (m/3) <|v|^2>            (uncentred, paper A's Tables 1-2)
 *   u     = V
 *   P_ij  = m <C_i C_j>
 *   q     = (m/2) <|C|^2 C>          (= paper A's r - (M + (tr M/2 - |V|^2) I) V)
 *   a2    = <|C|^4> / (15 (T/m)^2) - 1
 *   a3    = -<|C|^6> / (105 (T/m)^3) + 1 + 3 a2
 */
#ifndef GDSMC_SIM_OBSERVE_H
#define GDSMC_SIM_OBSERVE_H

#include <stddef.h>

#include <stdint.h>

#include <gsl/gsl_rng.h>

#include "particles.h"
#include "scene.h"

typedef enum sim_observable {
    SIM_OBS_T, SIM_OBS_T_RAW,
    SIM_OBS_UX, SIM_OBS_UY, SIM_OBS_UZ,
    SIM_OBS_PXX, SIM_OBS_PYY, SIM_OBS_PZZ, SIM_OBS_PXY, SIM_OBS_PXZ, SIM_OBS_PYZ,
    SIM_OBS_QX, SIM_OBS_QY, SIM_OBS_QZ,
    SIM_OBS_A2, SIM_OBS_A3,
    SIM_OBS_BASE,  /* the observables every scene records, first in each output row */
    /* Paper E's uniform shear flow (docs/theory.md §9.3, E §III), after the base set in a
     * scene with [shear]; sim_observe_shear below defines them. */
    SIM_OBS_S = SIM_OBS_BASE, SIM_OBS_S0, SIM_OBS_T_RATIO,
    SIM_OBS_PXY_REDUCED, SIM_OBS_N1, SIM_OBS_N2, SIM_OBS_A_STAR, SIM_OBS_ETA_STAR,
    SIM_OBS_PSI1, SIM_OBS_PSI2, SIM_OBS_V12_RATIO,
    SIM_OBS_R0, SIM_OBS_R1, SIM_OBS_R2, SIM_OBS_R3,
    SIM_OBS_SHEAR_END,  /* the row of a homogeneous shear flow ends here */
    /* The Lees-Edwards slab (paper E §IV A, docs/theory.md §9.4), after the shear set; sim/slab.h
     * defines them.  Then four profiles of shear.layers columns each, M = layers:
     * n_0 .. n_{M-1}, ux_0 .., T_0 .., Pxy_0 .. (SIM_OBS_PROFILE + k M + I). */
    SIM_OBS_UX_CENTRE = SIM_OBS_SHEAR_END, SIM_OBS_UX_TOP, SIM_OBS_N_CENTRE, SIM_OBS_N_TOP,
    SIM_OBS_T_CENTRE, SIM_OBS_T_TOP, SIM_OBS_UX_SLOPE,
    SIM_OBS_PROFILE,
    SIM_OBS_MAX = SIM_OBS_PROFILE + 4 * SIM_SLAB_LAYERS_MAX  /* the longest row */
} sim_observable;

/* The four profiles of the slab, in the order of their columns. */
typedef enum sim_profile { SIM_PROFILE_N, SIM_PROFILE_UX, SIM_PROFILE_T, SIM_PROFILE_PXY,
                           SIM_PROFILES } sim_profile;

/* Longest observable name, with its terminating NUL. */
#define SIM_OBS_NAME_LEN 32

/* Column name of observable k of the scene's row ("T", "T_raw", "ux", ..., "s",
 * "Pxy_reduced", ..., "n_0", ..., "Pxy_49"), in buf. */
const char *sim_observable_name(const sim_scene *scene, size_t k, char buf[SIM_OBS_NAME_LEN]);

/* The index of the observable named by the len characters at name in the
 * scene's row (sim_observe_row_length), or -1 when none is. */
int sim_observable_find(const sim_scene *scene, const char *name, size_t len);

/* Compute all observables of p (particles of mass `mass`) into out[SIM_OBS_BASE]. */
void sim_observe(const sim_particles *p, double mass, double out[SIM_OBS_BASE]);

/* The bit of base observable k in a scene's observe_only mask, and every base
 * observable's. */
#define SIM_OBS_BIT(k) (UINT32_C(1) << (k))
#define SIM_OBS_ALL_BASE (SIM_OBS_BIT(SIM_OBS_BASE) - 1u)
_Static_assert(SIM_OBS_BASE <= 32, "a uint32_t mask holds the base observables");

/* sim_observe for the observables in mask `only` (0: all of them), the others
 * NaN: a pass over the particles is made only for what they need (the second,
 * centred pass only for T, P, q, a2 or a3; |C|^4 only for a2 and a3, |C|^6
 * only for a3).  Each observable computed has the same bits as sim_observe's,
 * whatever else is asked: its sum runs over the particles in the same order. */
void sim_observe_only(const sim_particles *p, double mass, uint32_t only,
                      double out[SIM_OBS_BASE]);

/* NaN for the base observables not in mask `only` (0: none). */
void sim_observe_drop(uint32_t only, double out[SIM_OBS_BASE]);

/* Running sums of the stored velocities and the lazy flow's stamps (issue
 * 18, O(1) observation): vv = Σ v_x^2, v_y^2, v_z^2, v_x v_y, v_x v_z, v_y v_z.
 * The event processes keep them current (effect.h, select_fire_sums) and the
 * engine recomputes them from the particles every few n events, so that their
 * round-off stays that of a sum over the particles. */
typedef struct sim_sums {
    double v[3];
    double vv[6];
    double stamp;   /* Σ stamp_i (0 without a lazy flow) */
} sim_sums;

/* sums += sign (v, v v^T, stamp) of one particle (sign = 1 or -1). */
static inline void sim_sums_add(sim_sums *s, const double v[3], double stamp, double sign)
{
    const double x = sign * v[0], y = sign * v[1], z = sign * v[2];
    s->v[0] += x;
    s->v[1] += y;
    s->v[2] += z;
    s->vv[0] += x * v[0];
    s->vv[1] += y * v[1];
    s->vv[2] += z * v[2];
    s->vv[3] += x * v[1];
    s->vv[4] += x * v[2];
    s->vv[5] += y * v[2];
    s->stamp += sign * stamp;
}

/* The sums over every particle of p, from scratch (stamps 0 when p has none). */
void sim_sums_compute(const sim_particles *p, sim_sums *s);

/* The observables at most quadratic in the velocities, T .. Pyz, of a system
 * of n particles with sums s at time t, as exact conditional expectations over
 * the increments a lazy white-noise flow still owes (variance-reduced
 * observation, docs/theory.md §9.2; issue 18): particle i owes a Gaussian increment of
 * mean 0 and variance s_i = spread (t - stamp_i) per component, independent of
 * everything else, so with S = (1/n) Σ s_i = spread (t - Σ stamp_i/n)
 *   E T_raw = T_raw(v) + m S,   E u = u(v),
 *   E P_kk  = P_kk(v) + m S (1 - 1/n),   E P_kl = P_kl(v) (k != l),
 *   E T     = T(v) + m S (1 - 1/n)
 * (the 1/n: the centring velocity V owes S/n per component); spread = 0: the
 * system's own values.  q, a2 and a3 are not observed this way: out gets NaN
 * for them. */
void sim_observe_sums(const sim_sums *s, size_t n, double mass, double t, double spread,
                      double out[SIM_OBS_BASE]);

/* Observables in each output row of the scene: SIM_OBS_BASE, SIM_OBS_SHEAR_END
 * with [shear], or SIM_OBS_PROFILE + 4 shear.layers with the Lees-Edwards
 * slab. */
size_t sim_observe_row_length(const sim_scene *scene);

/* Paper E's shear-flow observables of one system at output m (docs/theory.md §9.3, E
 * Eqs. 3.13-3.15, 4.16-4.19), written into row[SIM_OBS_S .. SIM_OBS_R3] of
 * the full output row `row`, whose base part sim_observe has filled from the
 * same particles; prev is the row of output m - 1 (NULL at m = 0).  With T the
 * centred temperature, theta = T/m, v0 = sqrt(2 theta), lambda0 =
 * sim_scene_mean_free_path, tau = lambda0/v0 and tau_eta = 1.016 (5 sqrt(pi)/8)
 * tau (E Eq. 2.18):
 *   s            collisions/n: the accepted collisions so far per particle, each
 *                counted once (E's s(t); s'(t) for EHS)
 *   s0           the local-equilibrium clock ∫ beta dt/(sqrt(pi) tau(t)) (E Eq. 3.13,
 *                beta = (1 + alpha)/2 for EHS and 1 for IHS) by the trapezoidal rule
 *                over the output times
 *   T_ratio      T/T0 with T0 = particles.temperature
 *   Pxy_reduced  -Pxy/(nT);  N1, N2 = (Pxx - Pyy)/(nT), (Pzz - Pyy)/(nT)
 *   a_star       a tau_eta(T);  eta_star = Pxy_reduced/a_star (E §V C)
 *   Psi1, Psi2   -N1/a*^2, N2/a*^2 (E §V C's viscometric functions)
 *   v12_ratio    <|V12|^3>/<|V12|^3>_0 over shear.pairs random pairs i != j drawn
 *                from rng, <|V12|^3>_0 = (32/sqrt(pi)) theta^{3/2} (NaN without pairs)
 *   R0 .. R3     E Eq. (3.15): the fraction of particles with C_l <= |C|/v0 < C_{l+1}
 *                (C = 0, 1, 2, 3, inf) over the Maxwellian's, P(C_{l+1}) - P(C_l) with
 *                P(x) = erf(x) - 2x e^{-x^2}/sqrt(pi) */
void sim_observe_shear(const sim_scene *scene, const sim_particles *p, double mass,
                       uint64_t collisions, size_t m, const double *prev, gsl_rng *rng,
                       double *row);

#endif
