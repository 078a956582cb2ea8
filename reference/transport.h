/* Heat-flux transport coefficients of paper D (docs/theory.md §14; Montanero, Santos and
 * Garzó, "First-order Chapman-Enskog velocity distribution function in a
 * granular gas", Physica A 376 (2007) 75, seed 003).  Equation numbers
 * "D (N)" are paper D's.
 *
 * Three families of values:
 *
 *  1. The standard first Sonine approximation (Maxwellian weight), D Eqs.
 *     (2.14), (2.16), (2.38), (2.41), (2.42), (2.46), (2.47).
 *  2. The modified first Sonine approximation of D ref. [28] (Garzó, Santos
 *     and Montanero, "Modified Sonine approximation for the Navier-Stokes
 *     transport coefficients of a granular gas", Physica A 376 (2007) 94,
 *     arXiv cond-mat/0604079), in which the trial functions are the HCS
 *     distribution f^(0) times S(V) instead of the Maxwellian times S(V).  As
 *     that paper's abstract says, only the coefficient of a2 in the collision
 *     frequency changes:
 *       nu*_kappa,mod = ((1+alpha)/d) [(d-1)/2 + (3/16)(d+8)(1-alpha)
 *                       + (296 + 217d - 3(160 + 11d) alpha)/256 a2].
 *     The paper's body was not available here; this coefficient is the one
 *     recalled from it AND re-derived for this module: the Galerkin projection
 *     of D (2.28)/(2.30) on S(V) with the trial function A = a f^(0) S gives
 *       nu_kappa = ∫S·L[f^(0)S] / ∫S·f^(0)S - ((d+2)/2) zeta a2,
 *     the last term because f^(0) S violates the solubility condition
 *     ∫V·A = 0 by ∫V·A / ∫S·A = a2 (to first order).  The collision integral
 *     was evaluated by exact Gaussian quadrature of the inelastic hard-sphere
 *     collision operator at d = 2, 3, 4 and several alpha, and the result
 *     linearised in a2 is exactly the formula above (tests/test_reference_
 *     transport.c repeats that quadrature at d = 3).  zeta* is an HCS
 *     property and is the same in both approximations; kappa, kappa' and mu
 *     follow from the same exact relations D (2.38), (2.41), (2.42).
 *  3. The exact ELASTIC solution (alpha = 1, d = 3 hard spheres): the heat
 *     conduction problem of the linearised elastic Boltzmann operator solved by
 *     a Sonine expansion (Laguerre L_k^(3/2)(c^2) c_x, k >= 1) taken to
 *     convergence, as Pekeris and Alterman did (kappa/kappa0 = 1.025218, the
 *     value paper D quotes from its ref. [37]; D §4).
 *
 * Units: reduced as in docs/theory.md §14: nu0 of D (2.15) for rates (zeta* = zeta/nu0,
 * nu*_kappa = nu_kappa/nu0), kappa0 of D (2.47) (the elastic FIRST-Sonine
 * conductivity) for kappa and kappa', and mu* = n mu/(T kappa0).
 *
 * Domain of the (alpha, d) functions: alpha in [0, 1] and d finite with
 * REF_SONINE_D_MIN <= d <= REF_SONINE_D_MAX (sonine_a2.h; d need not be an
 * integer).  Anything else, NaN included, returns NaN.  They are pure and
 * thread-safe.  The elastic functions are d = 3 only and documented below.
 */
#ifndef GDSMC_REF_TRANSPORT_H
#define GDSMC_REF_TRANSPORT_H

#include <stddef.h>

#include "ode.h" /* ref_status */

/* ------------------------------------------- first Sonine, both weights */

/* Which trial function of the first Sonine approximation. */
typedef enum ref_transport_weight {
    REF_TRANSPORT_STANDARD, /* A = a1 f_M(V) S(V): Maxwellian weight, D (2.44) truncated */
    REF_TRANSPORT_MODIFIED  /* A = a1 f^(0)(V) S(V): HCS weight, D ref. [28] */
} ref_transport_weight;

/* Every first-Sonine value at one (alpha, d, a2). */
typedef struct ref_transport_sonine {
    double a2;               /* the fourth cumulant used */
    double zeta_star;        /* zeta^(0)/nu0, D (2.14) */
    double nu_kappa_star;    /* nu_kappa/nu0 = nu_kappa'/nu0 */
    double kappa_star;       /* kappa/kappa0, D (2.41), (2.47) */
    double kappa_prime_star; /* kappa'/kappa0, D (2.42), (2.47) */
    double mu_star;          /* n mu/(T kappa0) = 2 (kappa - kappa')/kappa0, D (2.38) */
} ref_transport_sonine;

/* The first Sonine approximation at a given a2 (for instance a measured one):
 *   zeta*     = (d+2)/(4d) (1 - alpha^2)(1 + 3 a2/16),                  D (2.14)
 *   nu*_kappa = ((1+alpha)/d)[(d-1)/2 + (3/16)(d+8)(1-alpha) + c a2],   D (2.46)
 *     c = (4 + 5d - 3(4-d) alpha)/512                     (STANDARD, D (2.46))
 *     c = (296 + 217d - 3(160 + 11d) alpha)/256           (MODIFIED, D ref. [28])
 *   kappa*  = ((d-1)/d)(1 + 2 a2)/(nu*_kappa - 2 zeta*),                D (2.41)
 *   kappa'* = ((d-1)/d)(1 + 3 a2/2)/(nu*_kappa - (3/2) zeta*),            D (2.42)
 *   mu*     = 2 (kappa* - kappa'*),                                     D (2.38)
 * (D (2.41)/(2.42) divided by kappa0 of D (2.47)).  Returns REF_EINVAL with a
 * message naming the argument, its value and the allowed range when alpha,
 * d, a2 (finite) or weight is bad, or out is NULL (msg may be NULL when
 * msglen is 0; "" on success); out is then untouched. */
ref_status ref_transport_first_sonine(double alpha, double d, double a2,
                                      ref_transport_weight weight, ref_transport_sonine *out,
                                      char *msg, size_t msglen);

/* The standard first Sonine approximation with a2 of paper C's (C.40) = D
 * (2.16), ref_sonine_a2_gaussian_alt (docs/theory.md §14.1).  At alpha = 0.5, d = 3:
 * kappa'/kappa0 = 1.31870, kappa/kappa0 = 1.90108 (docs/theory.md §14.1).  At alpha = 1
 * every one gives the elastic first-Sonine values: zeta* = 0, mu* = 0,
 * kappa* = kappa'* = 1, nu*_kappa = (d-1)/d. */
double ref_transport_zeta_star(double alpha, double d);        /* D (2.14) at (2.16) */
double ref_transport_nu_kappa_star(double alpha, double d);    /* D (2.46) at (2.16) */
double ref_transport_kappa_star(double alpha, double d);       /* D (2.41)/(2.47) */
double ref_transport_kappa_prime_star(double alpha, double d); /* D (2.42)/(2.47) */
double ref_transport_mu_star(double alpha, double d);          /* D (2.38)/(2.47) */

/* The modified first Sonine approximation, D ref. [28], at the same a2 (C.40).
 * zeta_star_modified equals zeta_star (an HCS property, not a trial-function
 * one); it is listed so that each approximation is complete. */
double ref_transport_zeta_star_modified(double alpha, double d);
double ref_transport_nu_kappa_star_modified(double alpha, double d);
double ref_transport_kappa_star_modified(double alpha, double d);
double ref_transport_kappa_prime_star_modified(double alpha, double d);
double ref_transport_mu_star_modified(double alpha, double d);

/* ------------------------------------------ exact elastic solution, d = 3 */
/*
 * The problem.  The force of docs/theory.md §7 (D Eq. 4.1 with the thermostat of D Eq. 4.2)
 * is the acceleration a = G'·eps, G'_ij = (T/(2m)) delta_ij - V_i V_j/2.
 * Linearising the steady Boltzmann equation ∂_V·(a f) = J[f, f] about the
 * Maxwellian, with f = f_M (1 + phi):
 *   ∂_V·(a f_M) = f_M (V·eps) [c^2 - (d+1)/2 - 1/2] = f_M (V·eps)(c^2 - 5/2)
 * (d = 3; the -V(V·eps)/2 part gives c^2 - 2, the constant part -1/2), which
 * is exactly the Chapman-Enskog source (c^2 - 5/2) V·∇ln T with ∇ln T -> eps:
 * so kappa' = kappa at alpha = 1, and eps > 0 drives q_x < 0.  In reduced
 * units (c = V/v0, lambda = 1/(sqrt2 pi n sigma^2), eps* = lambda eps, docs/theory.md §2.3)
 * with phi = eps* c_x Σ_k b'_k L_k^(3/2)(c^2):
 *   Lop[c_x Phi] = 4 sqrt2 pi c_x (c^2 - 5/2),
 *   Lop[phi](c) = ∫dc1 phi_M(c1) |g| ∫dΩ' [phi' + phi1' - phi - phi1],
 * phi_M = pi^(-3/2) e^(-c^2), isotropic hard-sphere scattering.  Galerkin on
 * psi_k = L_k^(3/2)(c^2) c_x, k = 1..N (psi_0 = c_x is excluded by momentum
 * conservation):  Σ_k A_jk b'_k = 5 sqrt2 pi delta_j1, with
 *   A_jk = (1/4) ∫∫ phi_M phi_M1 |g| ∫dΩ' Δpsi_j Δpsi_k   (symmetric, > 0).
 * A_jk is evaluated by Gaussian quadrature in the centre-of-mass and relative
 * velocities (Gauss-Hermite for G, Gauss-Laguerre for |g|^2/2, Gauss-Legendre
 * for the scattering angle); the integrands are polynomials, so the rules
 * are exact up to rounding (no truncation error at any order).
 *
 * Normalisation.  b'_k = P_k <c_x L_k^(3/2)(c^2)>/eps* (docs/theory.md §10.5, D (3.10)),
 * and the heat flux gives b'_1 = (15 sqrt(pi)/16) kappa'/kappa0, so at order 1
 * b'_1 = 15 sqrt(pi)/16 and kappa/kappa0 = 1 exactly.  kappa/kappa0 at order
 * N is b'_1(N)/b'_1(1).  Order 2 gives 45/44 = 1.0227273 (Chapman-Cowling's
 * second approximation for rigid spheres, [lambda]_2 = (1 + 1/44)[lambda]_1).
 */

/* Highest order tried by ref_transport_elastic_exact. */
#define REF_TRANSPORT_ELASTIC_MAX_ORDER 24

/* Convergence: the exact solution is the first order N with
 * |kappa_N - kappa_{N-1}| <= REF_TRANSPORT_ELASTIC_TOL (kappa in units of
 * kappa0).  The differences fall by a factor of about 0.4 per order, so the
 * remaining error is below that tolerance too. */
#define REF_TRANSPORT_ELASTIC_TOL 1e-7

/* The solution at one order.  Arrays are indexed from 1; index 0 is NaN. */
typedef struct ref_transport_elastic {
    int order;                                              /* N, number of Sonine terms */
    double kappa;                                           /* kappa/kappa0 at order N */
    double kappa_by_order[REF_TRANSPORT_ELASTIC_MAX_ORDER + 1]; /* [n]: with n terms, 1..N */
    double b[REF_TRANSPORT_ELASTIC_MAX_ORDER + 1];          /* [k]: b'_k at order N, 1..N */
} ref_transport_elastic;

/* Solve with `order` Sonine terms (1 <= order <= REF_TRANSPORT_ELASTIC_MAX_ORDER,
 * else REF_EINVAL naming it).  kappa_by_order[n] is filled for every n <=
 * order (the bases are nested).  REF_ENOMEM when a quadrature cannot be
 * allocated, REF_ESOLVER when the Galerkin matrix is not positive definite
 * (rounding; not seen up to the maximum order).  out NULL: REF_EINVAL.
 * Cost grows like order^7: about 0.05 s at order 8, 0.6 s at order 12, 3 s
 * at order 16.  Thread-safe. */
ref_status ref_transport_elastic_sonine(int order, ref_transport_elastic *out, char *msg,
                                        size_t msglen);

/* The converged solution: orders 8, 12, 16, ... up to the maximum are solved
 * until two successive kappa's differ by at most REF_TRANSPORT_ELASTIC_TOL;
 * out gets the first such order (11 here: kappa/kappa0 = 1.0252181).  Computed
 * once per process, at the first call (any thread; C11 call_once), and then
 * copied from the cache.  REF_ESOLVER when not converged by the maximum order,
 * or the status of the failed solve. */
ref_status ref_transport_elastic_exact(ref_transport_elastic *out, char *msg, size_t msglen);

/* Shorthands of the converged solution: kappa/kappa0 (1.025218) and b'_k for
 * 1 <= k <= its order (NaN for other k, or when the computation failed). */
double ref_transport_kappa_elastic_exact(void);
double ref_transport_b_elastic_exact(int k);

/* P_k = 1/<c_x^2 [L_k^(3/2)(c^2)]^2> under phi_M = 3 k! Gamma(3/2)/Gamma(k + 5/2):
 * 4/5, 16/35, 32/105 for k = 1, 2, 3 (docs/theory.md §10.5, D (3.10)).  k >= 0, else NaN. */
double ref_transport_sonine_P(int k);

/* b'_1/(kappa'/kappa0) = (d/(d-1))/(nu0 tau) = 15 sqrt(pi)/16 = 1.661675 at
 * d = 3 (docs/theory.md §14.2 identity, from q = (m/2)∫V^2 V f and D (2.47)). */
double ref_transport_b1_per_kappa(void);

#endif
