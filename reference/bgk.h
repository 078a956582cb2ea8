/* Paper E's BGK-model reference for homogeneous uniform shear flow (docs/theory.md §15,
 * §16; Astillero and Santos, PRE 71 (2005) 031309, seed 004, "E").
 *
 * Units and time scales (E Eqs. 2.12-2.18 as docs/theory.md §2.3 takes them).  Hard
 * spheres with B = C|g| and rate factor gamma, so that, with the suite's
 * normalisation ∫ f dv = 1, n sigma^2 = 4 gamma C and
 *   lambda0     = 1/(sqrt(2) pi n sigma^2)                 (E 2.12)
 *   tau(T)      = lambda0/sqrt(2T/m)                        (E 2.13)
 *   tau_eta(T)  = c_eta (5 sqrt(pi)/8) tau(T)               (E 2.18, c_eta = 1.016)
 *   zeta0(T)    = (2/(3 sqrt(pi))) (1 - alpha^2)/tau(T)     (E 2.16)
 *   beta        = (1 + alpha)/2,  nu'(T) = beta/tau_eta'(T)
 * where tau_eta' is tau_eta with its own constant c_eta_nu (below).  Both
 * nu' and zeta0 grow like sqrt(T).
 *
 * The model.  E's BGK-like kinetic model (E §V, its refs. [4, 6, 26]),
 *   df/dt - a V_y df/dV_x = -nu' (f - f_LE) + (zeta0/2) d/dV . (V f),
 * is the model of the frictional EHS gas of E §II B (elastic collisions at
 * beta times the IHS rate, i.e. relaxation rate beta/tau_eta, and the drag
 * -m (zeta0/2) V).  Its second moments P_ij = n m <V_i V_j> close exactly:
 *   dP_ij/dt = -a (delta_ix P_yj + delta_jx P_yi) - nu' (P_ij - p delta_ij)
 *              - zeta0 P_ij,           p = tr P/3 = n T          (docs/theory.md §15.1)
 * (shear term: the moment of a V_y df/dV_x; drag: of (zeta0/2) d/dV.(Vf)
 * gives -zeta0 P_ij).  In components (xz = yz = 0 stay 0 from an isotropic
 * start), with P written per unit density (P/n, temperature units):
 *   dPxx/dt = -2a Pxy - nu' (Pxx - T) - zeta0 Pxx
 *   dPyy/dt =         - nu' (Pyy - T) - zeta0 Pyy
 *   dPzz/dt =         - nu' (Pzz - T) - zeta0 Pzz
 *   dPxy/dt = -a Pyy  - (nu' + zeta0) Pxy
 *   dT/dt   = -(2a/3) Pxy - zeta0 T     (the trace: viscous heating vs cooling)
 * The same system is the reference for IHS and EHS (the model does not tell
 * them apart); only the local-equilibrium collision counter differs:
 *   IHS: ds0/dt  = 1/(sqrt(pi) tau(T))        (E 3.13)
 *   EHS: ds0'/dt = beta/(sqrt(pi) tau(T))     (tau' = tau/beta, E 2.19)
 * and E's figures plot s'/beta.
 *
 * Steady state (derived from the system above; docs/theory.md §15.2).  Set the time
 * derivatives to 0 and x = zeta0/nu' (a function of alpha only, since both
 * rates are proportional to sqrt(T)):
 *   Pyy = Pzz = nu' T/(nu' + zeta0) = T/(1 + x)
 *   Pxy = -a Pyy/(nu' + zeta0)      = -a nu' T/(nu' + zeta0)^2
 *   T equation: (2a/3)(-Pxy) = zeta0 T  =>  a^2 = 3 zeta0 (nu' + zeta0)^2/(2 nu'),
 *     i.e. a/nu' = sqrt(3x/2) (1 + x)
 *   -Pxy/p        = a nu'/(nu' + zeta0)^2 = sqrt(3x/2)/(1 + x)
 *   (Pxx - Pyy)/p = 2a (-Pxy)/((nu' + zeta0) T) = 3 zeta0/(nu' + zeta0) = 3x/(1 + x)
 *   (Pzz - Pyy)/p = 0
 * The first relation fixes a tau(T_s) = (a/nu')(nu' tau); as tau is
 * proportional to T^(-1/2), T_s/T0 = (a tau0/(a tau_s))^2 with tau0 = tau(T0).
 * Then a* = a tau_eta(T_s) (with c_eta) and eta* = (-Pxy/p)/a*.
 * docs/theory.md §15.2 check, alpha = 0.9, c_eta = c_eta_nu = 1.016: a tau_s = 0.32627,
 * -Pxy/p = 0.32855, (Pxx - Pyy)/p = 0.23417, a* = 0.36722.
 *
 * The two 1.016's.  E's printed ratios need c_eta = 1.016 in a* = a tau_eta
 * (docs/theory.md §15.2).  Inside nu' = beta/tau_eta the 1.016 is a convention E does not
 * settle; c_eta_nu lets the caller choose it.  Moving c_eta_nu from 1.016 to
 * 1 scales x by 1/1.016 and moves the steady values by less than 1 - 1/1.016
 * = 1.6% (by at most 1.5% over E's range alpha = 0.5-0.95; the largest
 * change is that of (Pxx - Pyy)/p and T_s/T0, -Pxy/p and a tau_s move by
 * less than 0.8%).
 * Both default to REF_BGK_C_ETA.  beta = (1 + alpha)/2 is settled (E's
 * eta*_NS = 1.1 for BGK at alpha = 0.5 needs it; docs/theory.md §15.2).
 *
 * Bad input.  Every function checks p: NULL; alpha outside (0, 1];
 * shear_rate not finite or < 0; gamma, C, mass, T0, c_eta, c_eta_nu not
 * finite and > 0; model neither IHS nor EHS.  It then returns REF_EINVAL and
 * writes into msg (msglen bytes; msg may be NULL when msglen is 0) a message
 * naming the parameter, its value and the allowed range.  Nothing is printed;
 * all functions are thread-safe (no global state; each CVODE call has its own
 * context).
 */
#ifndef GDSMC_REF_BGK_H
#define GDSMC_REF_BGK_H

#include <stddef.h>

#include "ode.h"

/* E Eq. (2.18): tau_eta = 1.016 (5 sqrt(pi)/8) tau. */
#define REF_BGK_C_ETA 1.016

/* Which collision counter s0 the integrator returns (the stresses and T are
 * the same for both). */
typedef enum ref_bgk_model {
    REF_BGK_IHS,   /* ds0/dt = 1/(sqrt(pi) tau) */
    REF_BGK_EHS    /* ds0'/dt = beta/(sqrt(pi) tau) */
} ref_bgk_model;

typedef struct ref_bgk_params {
    double alpha;      /* restitution, (0, 1] */
    double shear_rate; /* a, finite, >= 0 (0: homogeneous cooling) */
    double gamma;      /* collision rate factor, > 0 */
    double C;          /* hard-sphere kernel constant (B = C|g|), > 0 */
    double mass;       /* m, > 0 */
    double T0;         /* initial temperature, > 0 */
    double c_eta;      /* the constant of tau_eta in a* = a tau_eta, > 0 (1.016) */
    double c_eta_nu;   /* the constant of tau_eta inside nu' = beta/tau_eta, > 0 (1.016) */
    ref_bgk_model model;
} ref_bgk_params;

/* E's homogeneous runs in the suite's units: alpha = 0.9, gamma = C = m =
 * T0 = 1, c_eta = c_eta_nu = REF_BGK_C_ETA, IHS, and shear_rate such that
 * a tau0 = 4.  Callers change what they need. */
ref_bgk_params ref_bgk_default_params(void);

/* Time scales and rates at temperature T (E 2.12-2.18). */
typedef struct ref_bgk_rates {
    double lambda0; /* 1/(sqrt(2) pi 4 gamma C) */
    double tau;     /* lambda0/sqrt(2T/m) */
    double tau_eta; /* c_eta (5 sqrt(pi)/8) tau (the one of a*) */
    double beta;    /* (1 + alpha)/2 */
    double nu;      /* nu' = beta/(c_eta_nu (5 sqrt(pi)/8) tau) */
    double zeta0;   /* (2/(3 sqrt(pi)))(1 - alpha^2)/tau */
} ref_bgk_rates;

/* Fill *out at temperature T (finite, > 0).  REF_EINVAL on bad p, T or out. */
ref_status ref_bgk_rates_at(const ref_bgk_params *p, double T, ref_bgk_rates *out, char *msg,
                            size_t msglen);

/* The steady state of the model (closed form, see above).  All values are
 * reduced and, except T_ratio, independent of the shear rate and of the
 * initial state. */
typedef struct ref_bgk_steady {
    double x;            /* zeta0/nu' */
    double a_tau;        /* a tau(T_s) */
    double a_star;       /* a* = a tau_eta(T_s) (c_eta) */
    double shear_stress; /* -Pxy/p */
    double normal_xy;    /* (Pxx - Pyy)/p */
    double normal_zy;    /* (Pzz - Pyy)/p, 0 in this model */
    double eta_star;     /* (-Pxy/p)/a* */
    double T_ratio;      /* T_s/T0 = (a tau0/a tau_s)^2 */
    double eta_star_ns;  /* Navier-Stokes limit a* -> 0 of eta*(a*) (see below) */
} ref_bgk_steady;

/* The steady state of p.  Needs alpha < 1 (at alpha = 1, zeta0 = 0, nothing
 * balances the viscous heating and T grows without bound) and shear_rate > 0
 * (at a = 0 the gas cools to T = 0 isotropically); otherwise REF_EINVAL with
 * the reason.
 * eta_star_ns is an extra of this module: the normal (hydrodynamic) solution
 * to first order in a has -Pxy = eta a with eta = p tau_eta eta*_NS and T
 * cooling at dT/dt = -zeta0 T, so dPxy/dt = a eta zeta0/2 and the Pxy
 * equation gives eta (nu' + zeta0/2) = p, i.e.
 *   eta*_NS = 1/(tau_eta (nu' + zeta0/2)),
 * 1.100 at alpha = 0.5 (E §V B: "eta*_NS = 1.1 for EHS and BGK"). */
ref_status ref_bgk_steady_state(const ref_bgk_params *p, ref_bgk_steady *out, char *msg,
                                size_t msglen);

/* The steady velocity distribution and its marginals (E Eqs. 3.16-3.20, E Figs.
 * 17-18; docs/theory.md §15.3).
 *
 * Solution.  In the Lagrangian frame the steady equation of the model reads
 *   div_V(F f) = -nu' (f - f_L),   F = -(zeta0/2) V - a V_y x̂,   div_V F = -3 zeta0/2,
 * i.e. F.grad f = -(nu' - 3 zeta0/2) f + nu' f_L.  Along V(s) = e^{zeta0 s/2}
 * (V + a s V_y x̂), which solves dV/ds = -F(V) with V(0) = V,
 * d/ds f(V(s)) = (nu' - 3 zeta0/2) f(V(s)) - nu' f_L(V(s)); the solution that stays
 * bounded as s -> inf is
 *   f(V) = nu' ∫_0^inf ds e^{-(nu' - 3 zeta0/2) s} f_L(V(s)).
 * In E's reduced variables C = V/sqrt(2 T_s/m), f* = (2 T_s/m)^{3/2} f/n (so
 * ∫ f* d^3C = 1, f_L* = pi^{-3/2} e^{-C^2}), sigma = nu' s, x = zeta0/nu' and
 * A = a/nu' = sqrt(3x/2) (1 + x) (the steady state above):
 *   f*(C) = ∫_0^inf dsigma e^{-(1 - 3x/2) sigma} pi^{-3/2} exp(-k |C + b C_y x̂|^2),
 *   k = e^{x sigma},  b = A sigma,  |C + b C_y x̂|^2 = C.Q.C,
 *   Q = diag(M, 1),  M = [[1, b], [b, 1 + b^2]]  (det M = 1).
 * Checks.  The Gaussian of each sigma has the integral pi^{3/2} k^{-3/2}, so f* is a
 * mixture, with the probability density e^{-sigma}, of Gaussians of covariance
 * Q^{-1}/(2k): ∫ f* = 1, and <C_x C_y> = -∫ e^{-sigma} b/(2k) = -A/(2 (1 + x)^2)
 * = Pxy/(2p), <C_y^2> = 1/(2 (1 + x)) = Pyy/(2p), <C_x^2> = (1 + 3x)/(2 (1 + x))
 * = Pxx/(2p), the closed form above.  f*(-C) = f*(C), so g^(-)(C) = g^(+)(-C).
 *
 * Marginals (E 3.18-3.20), each a single integral over sigma of closed forms:
 *   g_x^(+)(C_x) = ∫dC_z ∫_{C_y > 0} dC_y f*
 *     = ∫ dsigma e^{-(1 - x/2) sigma} exp(-k C_x^2/(1 + b^2))
 *       erfc(b C_x sqrt(k/(1 + b^2))) / (2 sqrt(pi) sqrt(1 + b^2)),
 *   (the C_z integral gives sqrt(pi/k); completing the square in C_y,
 *   ∫_0^inf exp(-k [(C_x + b C_y)^2 + C_y^2]) dC_y = exp(-k C_x^2/(1 + b^2))
 *   (1/2) sqrt(pi/(k (1 + b^2))) erfc(b C_x sqrt(k/(1 + b^2))));
 *   g_y^(+)(C_y) = ∫dC_z ∫_{C_x > 0} dC_x f*
 *     = ∫ dsigma e^{-(1 - x/2) sigma} exp(-k C_y^2) erfc(b C_y sqrt(k)) / (2 sqrt(pi));
 *   F(C) = C^2 ∫ dOmega f*(C Omega)
 *     = (4 C^2/sqrt(pi)) ∫ dsigma e^{-(1 - 3x/2) sigma} ∫_0^1 du
 *       exp(-k C^2 [u^2 + (1 - u^2) l2]) I0s(k C^2 (1 - u^2) (l1 - l2)/2),
 *   with l1 = 1/l2 = 1 + b^2/2 + b sqrt(b^2 + 4)/2 the eigenvalues of M, u = cos theta
 *   about the z axis (Q's third eigenvector, eigenvalue 1), the azimuthal integral
 *   ∫_0^{2pi} exp(-k C^2 sin^2 theta (l1 cos^2 phi + l2 sin^2 phi)) dphi
 *   = 2 pi exp(-k C^2 sin^2 theta (l1 + l2)/2) I0(k C^2 sin^2 theta (l1 - l2)/2),
 *   and I0s(z) = e^{-z} I0(z) (GSL's scaled Bessel function, no overflow).
 * Normalisation: ∫ g_x^(+) = ∫ g_y^(+) = 1/2, ∫_0^inf F = 1, ∫ C^2 F = 3/2.  The
 * mixture also gives, in closed form, ∫ C_x g_x^(+) dC_x = <C_x Theta(C_y)>
 * = -A/(2 sqrt(pi) (1 + x/2)^2) (< 0: g_x^(+)(-|C_x|) > g_x^(+)(|C_x|), E §V) and the
 * fourth and sixth moments (tests/test_reference_bgk.c).  As alpha -> 1 (x -> 0):
 * g_x^(+), g_y^(+) -> e^{-C^2}/(2 sqrt(pi)), F -> 4 C^2 e^{-C^2}/sqrt(pi); to first
 * order F/F_M - 1 = (4x/5) S2(C^2), S2(c) = c^2/2 - 5c/2 + 15/8.
 *
 * Numerics.  GSL's CQUAD (it never calls GSL's error handler for a tolerance it cannot
 * reach) over sigma in [0, h], [h, 4h], [4h, 16h], ... up to sigma = 4, then over
 * sigma = 4 + 4t/(1 - t), t in [0, 1); h = 1/(1 + C^2 (x + A) + A |C|) is the shortest
 * scale of the integrands at sigma = 0, where for |C| >> 1 they are a spike (the
 * Maxwellian tail) that one run over the whole range can miss.  F's u integral: CQUAD
 * on [0, 1].  Asked for relative errors 1e-9 (sigma) and 1e-10 (u); an estimated error
 * above 1e-8 (sigma) or 1e-9 (u) gives REF_ESOLVER.  Measured errors: the g's 3e-10 or
 * less against 25-digit mpmath (alpha = 0.05-0.99999, |C| <= 20); F 4e-11 or less
 * against CQUAD at 1e-13, and 1e-15 against a direct angular quadrature at alpha = 0.9.
 * Each call allocates its own workspaces (thread-safe).  Cost on one core: a g about
 * 0.03 ms, F about 5 ms (2-8 ms). */
typedef enum ref_bgk_marginal {
    REF_BGK_GX_PLUS, /* g_x^(+)(C_x): C_z integrated out, C_y > 0 (E 3.18-3.20) */
    REF_BGK_GY_PLUS, /* g_y^(+)(C_y): C_z integrated out, C_x > 0 */
    REF_BGK_F_SPEED  /* F(C): the distribution of |C| = C >= 0 */
} ref_bgk_marginal;

/* *value = the marginal `which` of the steady distribution of p at c (C_x, C_y or
 * C in units of sqrt(2 T_s/m); the marginals are densities in those units).  Only
 * x = zeta0/nu' of p matters (alpha and c_eta_nu).  REF_EINVAL, with a message, for
 * what ref_bgk_steady_state rejects (bad p, alpha = 1, shear_rate = 0), for x >= 1
 * (the quadrature's range; x = (5/6) c_eta_nu (1 - alpha) is below 0.85 for
 * c_eta_nu <= 1.016; f*(0) diverges from x = 2/3 on, g^(+)(0) from x = 2), for an
 * unknown `which`, for c not finite, for c < 0 with REF_BGK_F_SPEED, and for
 * value = NULL; REF_ESOLVER if the quadrature misses its tolerance; *value is then
 * unspecified.  msg is "" on success.  The (-) marginals of E are g^(-)(c) = g^(+)(-c). */
ref_status ref_bgk_steady_marginal(const ref_bgk_params *p, ref_bgk_marginal which, double c,
                                   double *value, char *msg, size_t msglen);

/* Arrays of nt values filled by ref_bgk_solve; any member may be NULL when
 * that quantity is not wanted.  Pij are per unit density (P_ij/n, the units
 * of T); T = (Pxx + Pyy + Pzz)/3; s0 is the IHS or EHS counter of p->model;
 * a_star = a tau_eta(T(t)) (c_eta). */
typedef struct ref_bgk_output {
    double *T;
    double *Pxx, *Pyy, *Pzz, *Pxy;
    double *s0;
    double *a_star;
} ref_bgk_output;

/* Integrate the second-moment system and s0 with CVODE (ref_ode_solve) from
 * the local equilibrium P_ij = n T0 delta_ij, s0 = 0 at t[0] (E 3.12) to the
 * physical times t[0..nt-1] (finite, strictly increasing).  CVODE works on
 * y = (Pxx, Pyy, Pzz, Pxy)/(n T0) and s0, so opt->atol is in units of T0 for
 * the stresses (and absolute for s0); opt may be NULL
 * (ref_ode_default_options()).  A trial step with T <= 0 is a recoverable
 * failure (CVODE cuts the step).  Returns REF_EINVAL for bad p, t, nt = 0 or
 * out = NULL, REF_ENOMEM, or the failures of ref_ode_solve; the outputs are
 * then unspecified.  msg is "" on success. */
ref_status ref_bgk_solve(const ref_bgk_params *p, const double *t, size_t nt,
                         const ref_ode_options *opt, const ref_bgk_output *out, char *msg,
                         size_t msglen);

/* *t_relaxed = the time after which T(t) from the initial state of p stays
 * within the relative band of its steady value T_s: the first of 4000
 * equally spaced times on [0, t_max] after the last outside it, t_max = 64,
 * 128, ... 65536 until the band holds over the last quarter of [0, t_max] at
 * least.  paper E's models relax on the same time scale 1/zeta0, so the
 * steady averages of a simulation start there.  REF_EINVAL for what
 * ref_bgk_steady_state rejects or band <= 0; REF_ESOLVER when the band is
 * not reached by t = 65536; the failures of ref_bgk_solve. */
ref_status ref_bgk_relaxation_time(const ref_bgk_params *p, double band, double *t_relaxed,
                                   char *msg, size_t msglen);

#endif
