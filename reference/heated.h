/* References for paper A: the uniformly heated granular gas (docs/theory.md §11).
 *
 * dT/dt = 2 beta - gamma (1 - alpha^2)/24 ∫∫ B1(|g|) |g|^2 f f, with the
 * particle mass m = 1 (paper A's units; callers refuse other masses).
 */
#ifndef GDSMC_REF_HEATED_H
#define GDSMC_REF_HEATED_H

#include <stddef.h>

#include "ode.h"

/* The double-valued functions below return NaN when p is NULL or a parameter
 * is out of range (so an error propagates instead of passing for a number);
 * ref_heated_hs_T returns REF_EINVAL with a message naming the parameter. */
typedef struct ref_heated_params {
    double alpha;   /* restitution, (0, 1] */
    double beta;    /* white-noise heating, >= 0 */
    double gamma;   /* collision rate factor, > 0 */
    double C;       /* kernel constant: C0 (Maxwell) or C1 (hard spheres) */
    double T0;      /* initial temperature, > 0 */
} ref_heated_params;

/* Maxwell molecules: k = gamma pi C0 (1 - alpha^2) (docs/theory.md §11.1, A.13-14). */
double ref_heated_maxwell_rate(const ref_heated_params *p);
/* T_inf = 2 beta / k (A.14); +inf when k = 0 (alpha = 1) and beta > 0, T0 when
 * k = 0 and beta = 0 (the limit of T(t)). */
double ref_heated_maxwell_T_inf(const ref_heated_params *p);
/* T(t) = T0 e^{-kt} + T_inf (1 - e^{-kt})  (A.13); T0 + 2 beta t when k = 0. */
double ref_heated_maxwell_T(const ref_heated_params *p, double t);

/* Exact expectations of the n-particle DSMC estimators for Maxwell molecules
 * (docs/theory.md §11.2: exact finite-n behaviour), for i.i.d. initial velocities from a
 * Maxwellian at rest with temperature T0.  With X = Σ|v_i - V|^2, collisions
 * conserve momentum and remove k X on average, heating adds 6 beta (n-1), so
 * E X(t) = 3 (n-1) T(t); E|Σ v_i|^2 / n = 3 T0 + 6 beta t.  Hence
 *   E T_centred = (1 - 1/n) T(t),
 *   E T_raw     = T(t) + (T0 + 2 beta t - T(t)) / n,
 * where T_centred = (1/3n) Σ|v_i - V|^2 and T_raw = (1/3n) Σ|v_i|^2.
 * n >= 1 and t finite, else NaN. */
double ref_heated_maxwell_T_centred_mean(const ref_heated_params *p, double n, double t);
double ref_heated_maxwell_T_raw_mean(const ref_heated_params *p, double n, double t);

/* Heated hard spheres (docs/theory.md §11.4), two closures of the temperature
 * equation with B1 = 4 pi C1 |g| and <|g|^3> = (32/sqrt(pi)) T^{3/2}:
 *   MAXWELLIAN: dT/dt = 2 beta - gamma (1-alpha^2)/24 4 pi C1 (32/sqrt(pi)) T^{3/2}
 *   SONINE:     the same loss times (1 + 3 a2/16), a2 from (C.10), d = 3. */
typedef enum ref_heated_closure {
    REF_HEATED_MAXWELLIAN_CLOSURE,
    REF_HEATED_SONINE_CLOSURE
} ref_heated_closure;

/* Steady temperature of a closure, in closed form:
 * T* = (2 beta / (gamma (1-alpha^2)/24 4 pi C1 (32/sqrt(pi)) factor))^{2/3};
 * +inf when alpha = 1 and beta > 0, T0 when alpha = 1 and beta = 0. */
double ref_heated_hs_T_steady(const ref_heated_params *p, ref_heated_closure closure);

/* The steady temperature of the Maxwellian closure for a VHS kernel B1 =
 * 4 pi C |g|^lambda (0 <= lambda <= 1; docs/theory.md §11.4): with <|g|^p> = (4T)^(p/2)
 * Gamma((3 + p)/2)/Gamma(3/2) over two Maxwellians at T, p = 2 + lambda,
 *   2 beta = gamma (1 - alpha^2)/24 4 pi C 4^(p/2) Gamma((3 + p)/2)/Gamma(3/2) T^(p/2).
 * Exact for Maxwell molecules (lambda = 0: T* = 2 beta/k, A.14); the ratio
 * of the first-Sonine factor 1 + a2 p (p - 2)/16 (3 a2/16 for hard spheres) is
 * its model error.  NaN for a bad p or lambda; +inf when alpha = 1 and beta >
 * 0. */
double ref_heated_vhs_T_steady_maxwellian(const ref_heated_params *p, double lambda);

/* The high-speed tail of the white-noise heated gas with the VHS kernel B1 =
 * 4 pi C |g|^lambda (docs/theory.md §11.5, "The heated tail"): far out, a particle
 * of speed v loses itself at the rate gamma 4 pi C v^lambda and the heating
 * diffuses it with coefficient beta, so f ~ K exp(-a v^b) with b = 1 +
 * lambda/2 and a = sqrt(4 pi gamma C / beta) / b.  Returns A = a v0^b, the
 * amplitude in the reduced speed c = |v|/v0, v0 = sqrt(2T) at the steady T
 * (m = 1).  For hard spheres this is paper C's Eq. (36) once the steady
 * energy balance ties beta to mu2 and T.  NaN for a bad p or lambda, beta <= 0
 * or T <= 0. */
double ref_heated_tail_A(const ref_heated_params *p, double lambda, double T);

/* Integrate a closure with CVODE at times t[0..nt-1] (t[0] is the initial
 * time, where T = T0); T_out[m] = T(t[m]).  opt may be NULL (defaults).
 * Bad p, closure, t (NULL, nt = 0, not finite or not strictly increasing) or
 * T_out give REF_EINVAL; solver failures are those of ref_ode_solve. */
ref_status ref_heated_hs_T(const ref_heated_params *p, ref_heated_closure closure,
                           const double *t, size_t nt, const ref_ode_options *opt,
                           double *T_out, char *msg, size_t msglen);

#endif
