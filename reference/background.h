/* References for paper B: a granular gas in a host medium (docs/theory.md §12).
 *
 * The grains (mass m, number density rho) collide elastically with a fixed
 * Maxwellian background f^B = rho_B M(m_B, u_B, T_B) through the kernel B1 and
 * inelastically (restitution e) with each other through B2.  Mass ratio
 * alpha = m_B/(m + m_B) (not a restitution coefficient), beta = (1 - e)/2.
 *
 * Time.  Every function here takes the physical time t of the scene.
 *  - Maxwell kernels (B1 = C1, B2 = C2): the paper's scaled time is
 *    rho_B C1 t and Kn = rho C2/(rho_B C1) (paper B Eq. 12); the functions
 *    evaluate (B.13)-(B.18) at rho_B C1 t.
 *  - Hard spheres (B1 = C1|g|, B2 = C2|g|): the paper writes (B.21)-(B.22) in
 *    t̄ = (rho_B/rho) rho_B C1 t with K = (rho/rho_B)^2 C2/C1 (Eq. 23).  Those
 *    give the grain-grain term the physical rate K (rho_B^2/rho) C1 = rho C2,
 *    but the background terms the rate (rho_B^2/rho) C1, which depends on the
 *    grain density; a grain's collision rate with the background is
 *    E1 = 4 pi C1 rho_B (...) (docs/theory.md §5.1) whatever rho is, and the Grad
 *    coefficient of du/dt in (B.22) is exactly the rho_B C1-rate one derived
 *    from it.  So ref_background_hs uses the physical rates: the background
 *    terms of (B.21)/(B.22) times rho_B C1, the grain-grain terms (the ones
 *    with K) with K rho_B C1 replaced by rho C2.  When rho = rho_B (all of the
 *    paper's examples) this is exactly the paper's t̄ and K, with
 *    t̄ = rho_B C1 t and K = C2/C1; otherwise it is the scene the DSMC engine
 *    simulates, and the paper's scaling would not be.
 *
 * Bad input.  p is checked by every function: NULL, mass, bg_mass,
 * bg_density, bg_temperature, C1, density or T0 not finite and > 0, C2 not
 * finite and >= 0, restitution outside (0, 1], or a non-finite component of
 * bg_velocity or u0.  Double-returning functions then return NaN (so an
 * error propagates instead of passing for a number); status-returning ones
 * return REF_EINVAL with a message naming the parameter, its value and the
 * allowed range.  Nothing is printed; all functions are thread-safe (no
 * global state; each CVODE call has its own context).
 */
#ifndef GDSMC_REF_BACKGROUND_H
#define GDSMC_REF_BACKGROUND_H

#include <stddef.h>

#include "ode.h"

typedef struct ref_background_params {
    double mass;           /* m, grain mass, > 0 */
    double bg_density;     /* rho_B, > 0 */
    double bg_mass;        /* m_B, > 0 */
    double bg_temperature; /* T_B, > 0 */
    double bg_velocity[3]; /* u_B, finite */
    double C1;             /* background kernel constant, > 0 */
    double density;        /* rho of the gas (1 in the paper's examples), > 0 */
    double C2;             /* binary kernel constant, >= 0 (0: no grain-grain collisions) */
    double restitution;    /* e in (0, 1] */
    double T0;             /* initial temperature, > 0 */
    double u0[3];          /* initial bulk velocity, finite */
} ref_background_params;

/* ---------------------------------------------------------------- Maxwell kernels */

/* Bulk velocity, paper B Eq. (B.14):
 *   u(t) = u_B + (u0 - u_B) e^{-4 pi alpha rho_B C1 t}.
 * t must be finite and >= 0 (the initial state is at t = 0).  On bad p or t,
 * u (if not NULL) is filled with NaN. */
void ref_background_maxwell_u(const ref_background_params *p, double t, double u[3]);

/* Temperature, paper B Eqs. (B.15)-(B.17), s = rho_B C1 t:
 *   T = T0 e^{-Cs} + (D/C)(1 - e^{-Cs}) + A (e^{-Bs} - e^{-Cs})/(C - B)   (B != C, B.15)
 *   T = T0 e^{-Bs} + (D/B)(1 - e^{-Bs}) + A s e^{-Bs}                     (B = C, B.16)
 *   A = (8/3) pi m alpha^2 |u0 - u_B|^2, B = 8 pi alpha,
 *   C = 8 pi alpha (1-alpha) + pi Kn (1 - e^2), D = 8 pi alpha (1-alpha) T_B  (B.17).
 * The B != C quotient is evaluated as e^{-min(B,C) s} (1 - e^{-|C-B| s})/|C-B|
 * with expm1, which has no cancellation as C -> B and tends continuously to
 * the s e^{-Bs} of (B.16), used when C = B to the last bit.  t finite and
 * >= 0, else NaN. */
double ref_background_maxwell_T(const ref_background_params *p, double t);

/* Steady temperature T* = D/C, paper B Eq. (B.18).  C = 0 only when alpha
 * underflows to 0 with no inelastic loss; T(t) then tends to T0 + A/B (T0
 * when B = 0 too), which is returned.  NaN on bad p. */
double ref_background_maxwell_T_steady(const ref_background_params *p);

/* Integrate the moment equations (B.13) with CVODE (state (u, T), dimension
 * 4, in physical time: the right-hand side of (B.13) times rho_B C1):
 *   du/dt = -4 pi alpha (u - u_B),
 *   dT/dt = (8/3) pi [m alpha^2 |u - u_B|^2 - 3 alpha (1-alpha)(T - T_B)] - pi Kn (1-e^2) T.
 * The initial state (u0, T0) is taken at t[0] (so the result matches the
 * closed forms when t[0] = 0).  t[0..nt-1] finite and strictly increasing;
 * u_out[3 m + i] = u_i(t[m]) (u_out may be NULL when only T is wanted),
 * T_out[m] = T(t[m]).  opt may be NULL (ref_ode_default_options()).
 * Returns REF_EINVAL for bad p, t, nt = 0 or T_out = NULL, REF_ENOMEM, or the
 * failures of ref_ode_solve; msg (msglen bytes, may be NULL when msglen is 0)
 * is "" on success. */
ref_status ref_background_maxwell_ode(const ref_background_params *p, const double *t, size_t nt,
                                      const ref_ode_options *opt, double *u_out, double *T_out,
                                      char *msg, size_t msglen);

/* Exact expectation of the n-particle DSMC estimator of the centred
 * temperature, T_n = (m/3n) Σ |v_i - V|^2, for Maxwell kernels (docs/theory.md §12.2:
 * exact finite-n behaviour), when the n initial velocities are i.i.d. with
 * mean u0 and temperature T0 (a Maxwellian or the mixture B.35).  With
 * x_i = v_i - u_B, Q = E Σ|x_i|^2 and P = E|Σ x_i|^2 obey a closed linear
 * system: a background collision (rate lambda = 4 pi C1 rho_B per grain)
 * gives E x' = (1-alpha) x and E|x'|^2 = ((1-alpha)^2 + alpha^2)|x|^2 + 6 alpha^2 theta
 * (theta = T_B/m_B); a binary collision (rate 2 pi rho C2 (n-1), ordered pair
 * uniform) keeps Σ x and removes (1-e^2)/4 |g|^2 on average, so
 *   Q' = -(2 lambda alpha (1-alpha) + k) Q + (k/n) P + 6 n lambda alpha^2 theta,
 *   P' = 2 lambda alpha^2 Q - 2 lambda alpha P + 6 n lambda alpha^2 theta,
 * k = pi rho C2 (1-e^2), Q(0) = n(|u0-u_B|^2 + 3 T0/m), P(0) = Q(0) + n(n-1)|u0-u_B|^2,
 * and E T_n = (m/3n)(Q - P/n); as n -> infinity this is (B.13).  Integrated
 * with CVODE at the times t (t[0] = 0 is the initial state); n >= 2.  Also
 * E u_n(t) = u(t) exactly (ref_background_maxwell_u): background collisions act
 * on one grain linearly and binary ones conserve momentum.  Failures as for
 * ref_background_maxwell_ode. */
ref_status ref_background_maxwell_T_mean(const ref_background_params *p, double n,
                                         const double *t, size_t nt,
                                         const ref_ode_options *opt, double *T_out, char *msg,
                                         size_t msglen);

/* ---------------------------------------------------------------- hard spheres */

/* Total rate of background collisions of a grain with velocity v for the
 * hard-sphere kernel B1 = C1 |g| (docs/theory.md §5.1, Algorithm 2), a = |v - u_B|,
 * b = sqrt(2 T_B/m_B):
 *   E1(v) = 4 pi C1 rho_B (pi^{-1/2} b e^{-a^2/b^2} + (2a^2 + b^2)/(2a) erf(a/b)),
 *   E1(u_B) = 8 sqrt(pi) C1 rho_B b,
 * and the paper's majorant E1max(v) = C1 rho_B (4 pi a + 8 sqrt(pi) b) >= E1(v).
 * NaN on bad p or v. */
double ref_background_hs_E1(const ref_background_params *p, const double v[3]);
double ref_background_hs_E1_majorant(const ref_background_params *p, const double v[3]);

/* Hydrodynamic closures for hard spheres (docs/theory.md §12.3; paper B Eqs. B.21, B.22),
 * S = (1-alpha) T_B + alpha T, du = |u - u_B|, written in the paper's scaled
 * time and K (see the top of this file for the conversion to physical time):
 * LE (B.21), local equilibrium:
 *   du/dt = -alpha (16/3) sqrt(2 pi) sqrt(alpha m/S) [du^2/5 + 2 S/(alpha m)] (u - u_B),
 *   dT/dt = alpha (8/3) m sqrt(2 pi) sqrt(alpha m/S) { (1/5)[alpha + alpha T/(3S)] du^4
 *           + 4 (S/(alpha m)) [alpha - alpha T/(3S)] du^2 + 8 (S/(alpha m))^2 [alpha - alpha T/S] }
 *           - (64/3) sqrt(pi) K m beta (1-beta) (T/m)^{3/2};
 * GRAD (B.22), Grad-type expansion:
 *   du/dt = -sqrt(alpha) (32/3) sqrt(pi) sqrt(2 T_B/m) (u - u_B),
 *   dT/dt = -sqrt(alpha) (64/3) sqrt(pi) sqrt(2 T_B/m) { (1-alpha)(T - T_B) - alpha m du^2/3 }
 *           - (4/3) sqrt(pi) K m beta (1-beta) { (1/3)[(m/T_B) du^2 + 3 (T - T_B)/T_B]^2
 *           + 8 (3T - T_B)/T_B } (T_B/m)^{3/2}. */
typedef enum ref_background_closure {
    REF_BACKGROUND_LE,
    REF_BACKGROUND_GRAD
} ref_background_closure;

/* Integrate a closure with CVODE (state (u, T), dimension 4) at the physical
 * times t[0..nt-1]; the initial state (u0, T0) is taken at t[0].  Outputs,
 * options, messages and failures as for ref_background_maxwell_ode; also
 * REF_EINVAL for a closure that is neither LE nor GRAD.  A trial step with
 * T <= 0 in the LE closure (which has sqrt(T)) is a recoverable failure:
 * CVODE retries with a smaller step. */
ref_status ref_background_hs(const ref_background_params *p, ref_background_closure c,
                             const double *t, size_t nt, const ref_ode_options *opt,
                             double *u_out, double *T_out, char *msg, size_t msglen);

/* Steady temperature of a closure: the root of dT/dt at u = u_B, found by GSL's
 * Brent solver (gsl_root_fsolver_brent) on the bracket (0, T_B], to a relative
 * width of 1e-14.  dT/dt > 0 at T = 0 (the background heats a cold gas) and
 * < 0 at T = T_B when there is inelastic loss (rho C2 > 0 and e < 1); with
 * no loss T* = T_B is returned.  The steady state does not depend on the
 * time scale (rho_B C1).  docs/theory.md §12.3 checks (m = m_B = T_B = rho = rho_B = C1 = 1,
 * e = 1/2): K = 1/8: 0.9557 (LE), 0.9562 (GRAD); K = 1: 0.7428, 0.7574.
 * NaN on bad p or closure, or if the solver fails (the bracket and the
 * function are checked first, so GSL's error handler is not reached except
 * when GSL cannot allocate the solver's few bytes). */
double ref_background_hs_T_steady(const ref_background_params *p, ref_background_closure c);

#endif
