/* Observables of one particle system (SPEC §1, names of SPEC §9).
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

#include "particles.h"

typedef enum sim_observable {
    SIM_OBS_T, SIM_OBS_T_RAW,
    SIM_OBS_UX, SIM_OBS_UY, SIM_OBS_UZ,
    SIM_OBS_PXX, SIM_OBS_PYY, SIM_OBS_PZZ, SIM_OBS_PXY, SIM_OBS_PXZ, SIM_OBS_PYZ,
    SIM_OBS_QX, SIM_OBS_QY, SIM_OBS_QZ,
    SIM_OBS_A2, SIM_OBS_A3,
    SIM_OBS_BASE   /* the observables every scene records, first in each output row */
} sim_observable;

/* Column name of a base observable ("T", "T_raw", "ux", ...). */
const char *sim_observable_name(sim_observable k);

/* The index of the base observable named by the len characters at name, or
 * -1 when none is. */
int sim_observable_find(const char *name, size_t len);

/* Compute all observables of p (particles of mass `mass`) into out[SIM_OBS_BASE]. */
void sim_observe(const sim_particles *p, double mass, double out[SIM_OBS_BASE]);

/* The observables at most quadratic in the velocities, T .. Pyz (SIM_OBS_T
 * to SIM_OBS_PYZ), of a lazily flowing system at time t, as exact conditional
 * expectations over the increments it still owes (issue 4, variance-reduced
 * observation): particle i owes a Gaussian increment of mean 0 and variance
 * s_i = spread (t - stamp_i) per component, independent of everything else,
 * so with S = (1/n) Σ s_i
 *   E T_raw = T_raw(v) + m S,   E u = u(v),
 *   E P_kk  = P_kk(v) + m S (1 - 1/n),   E P_kl = P_kl(v) (k != l),
 *   E T     = T(v) + m S (1 - 1/n)
 * (the 1/n: the centring velocity V owes S/n per component).  Writes only
 * those entries of out; p is not changed. */
void sim_observe_pending(const sim_particles *p, double mass, double t, double spread,
                         double out[SIM_OBS_BASE]);

#endif
