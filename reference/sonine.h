/* Sonine-approximation formulas of paper C (docs/theory.md §13; Montanero and Santos,
 * "Computer simulation of uniformly heated granular fluids", seed 002):
 * estimates of the fourth cumulant a2 for three thermostats, the first Sonine
 * expansion of the collisional moments mu2 and mu4, the constants beta_n and
 * the high-energy tail amplitudes.  Equation numbers "(N)" below are paper C's.
 *
 * Units: reduced, c = v/v0 with v0 = sqrt(2T/m); the collisional moments
 * mu_p = -∫ c^p I[f, f] dc (paper C Eq. (22)) are in the units of Eq. (17)
 * (the factor chi n sigma^(d-1) v0 divided out).
 *
 * Domain, for every function: restitution alpha in [0, 1] and dimension d
 * finite with REF_SONINE_D_MIN <= d <= REF_SONINE_D_MAX (d need not be an
 * integer: the formulas are analytic in d).  Anything else, NaN included,
 * returns NaN; so does a d = 3-only formula at another d.  Functions are pure
 * (no state, no errno contract) and thread-safe.
 *
 * The a2 estimates and the domain's bounds are declared in sonine_a2.h,
 * included here: the transport coefficients (transport.h) take their a2 from
 * there, and the full listing below lists them, so the dependencies run
 * sonine -> transport -> sonine_a2. */
#ifndef GDSMC_REF_SONINE_H
#define GDSMC_REF_SONINE_H

#include <stddef.h>

#include "sonine_a2.h" /* the domain and the a2 estimates */

/* ------------------------------------------------------------ constants */

/* beta_n = ∫ dr Θ(c·r)(c·r)^n = pi^((d-1)/2) Gamma((n+1)/2) / Gamma((n+d)/2),
 * paper C Eq. (A.7).  beta_1 = pi and beta_3 = pi/2 at d = 3.
 * n > -1 and finite (else NaN). */
double ref_sonine_beta(double n, double d);

/* ----------------------------------- collisional moments, Eqs. (26)-(30) */

/* mu2^(0) = pi^((d-1)/2) / (sqrt(2) Gamma(d/2)) (1 - alpha^2), Eq. (27);
 * sqrt(2 pi)(1 - alpha^2) at d = 3.  The Maxwellian value of mu2. */
double ref_sonine_mu2_0(double alpha, double d);

/* mu2^(1) = (3/16) mu2^(0), Eq. (28). */
double ref_sonine_mu2_1(double alpha, double d);

/* mu4^(0) = (d + 3/2 + alpha^2) mu2^(0), Eq. (29); 10.925 at alpha = 0.2,
 * d = 3 (paper C Table 1). */
double ref_sonine_mu4_0(double alpha, double d);

/* mu4^(1) = [(3/32)(10d + 39 + 10 alpha^2) + (d-1)/(1-alpha)] mu2^(0),
 * Eq. (30).  Evaluated with (d-1)(1-alpha^2)/(1-alpha) = (d-1)(1+alpha), so
 * alpha = 1 gives the finite limit 2(d-1) pi^((d-1)/2)/(sqrt(2) Gamma(d/2)). */
double ref_sonine_mu4_1(double alpha, double d);

/* The first Sonine expansions at a given a2, Eq. (26):
 * mu2 ≈ mu2^(0) + mu2^(1) a2 and mu4 ≈ mu4^(0) + mu4^(1) a2.
 * a2 must be finite (else NaN). */
double ref_sonine_mu2(double alpha, double d, double a2);
double ref_sonine_mu4(double alpha, double d, double a2);

/* The non-Gaussian thermostat's semi-empirical slopes, d = 3 only (NaN at
 * other d): mu2 ≈ mu2^(0) + (21/20) mu2^(1) a2, Eq. (72), and
 * mu4 ≈ mu4^(0) + (13/15) mu4^(1) a2, Eq. (73). */
double ref_sonine_mu2_nongaussian_fit(double alpha, double d, double a2);
double ref_sonine_mu4_nongaussian_fit(double alpha, double d, double a2);

/* Speed moments in the first Sonine approximation f = phi (1 + a2 S2(c^2)):
 * <c>   ≈ Gamma((d+1)/2)/Gamma(d/2) (1 - a2/8),   Eq. (48);
 * <c^3> ≈ Gamma((d+3)/2)/Gamma(d/2) (1 + 3a2/8),  Eq. (49).
 * With mu2, mu4 of Eq. (26) they enter the non-Gaussian relation
 * mu4 = 2 mu2 <c^3>/<c>, Eq. (44).  d in range and a2 finite, else NaN. */
double ref_sonine_mean_c(double d, double a2);
double ref_sonine_mean_c3(double d, double a2);

/* The a2 estimates, Eqs. (5), (10), (32), (40), (50), (76): sonine_a2.h. */

/* ------------------------------------------------------ tail amplitudes */

/* White noise: f ~ K exp(-A c^(3/2)), A = (2/3)(2 d beta_1/mu2)^(1/2),
 * Eq. (36), for a given mu2 >= 0 (mu2 = 0 gives +inf; negative or
 * non-finite mu2, NaN). */
double ref_sonine_tail_A_white_noise_mu2(double mu2, double d);

/* Gaussian thermostat: f ~ K exp(-A c), A = d beta_1/mu2, Eq. (42), for a
 * given mu2 >= 0 (as above). */
double ref_sonine_tail_A_gaussian_mu2(double mu2, double d);

/* Eq. (36) with mu2 = mu2^(0) + mu2^(1) a2 at the white-noise a2 of Eq. (10).
 * The paper evaluates A with its simulated mu2; this choice is the closest
 * theory (the expansion at Eq. (10) is within 0.13% of the simulated mu4 of
 * Table 1) and reproduces the printed A ≈ 1.99 (alpha = 0.4) and 2.11 (0.5)
 * at d = 3: 1.98767 and 2.10593.  (With mu2^(0) alone: 1.99469, 2.11098,
 * which also round to the printed digits.)  +inf at alpha = 1: A diverges
 * as (1-alpha)^(-1/2). */
double ref_sonine_tail_A_white_noise(double alpha, double d);

/* Eq. (42) with mu2 = mu2^(0) + mu2^(1) a2 at the Gaussian a2 of Eq. (40).
 * Of the candidates this is the one that reproduces the printed A ≈ 3.82
 * (alpha = 0.2) and 4.41 (0.4) at d = 3: 3.82316 and 4.41154.  mu2^(0) alone
 * gives 3.91661, 4.47612 and Eq. (5)'s a2 gives 3.80954, 4.40615 (3.81 at
 * alpha = 0.2), both wrong in the printed digits.  +inf at alpha = 1. */
double ref_sonine_tail_A_gaussian(double alpha, double d);

/* Non-Gaussian thermostat, loss term only: A' = beta_1 <c>/mu2, Eq. (52), at
 * the Maxwellian values (a2 = 0), i.e. sqrt(2)/(1 - alpha^2) at d = 3 as the
 * paper states.  Not the tail amplitude itself: the paper argues the gain
 * term is comparable, A = A'(1 - gamma) with gamma unknown (Eq. (54)), and
 * fits A ≈ 1.48 (alpha = 0.3), 1.51 (0.4).  +inf at alpha = 1. */
double ref_sonine_tail_Aprime_nongaussian(double alpha, double d);

/* ------------------------------------------------------ the full listing */

/* One named value of the listing: name (a C identifier, used as the CSV key
 * by `gdsmc sonine`), value, and source (paper C or paper D equation numbers,
 * static strings). */
typedef struct ref_sonine_value {
    const char *name;
    double value;
    const char *source;
} ref_sonine_value;

/* Number of values ref_sonine_all lists; an array of this size holds them. */
#define REF_SONINE_ALL_COUNT 41

/* Every Sonine value at (alpha, d), in a fixed order: beta_1, beta_3, mu2_0,
 * mu2_1, mu4_0, mu4_1, the six a2 estimates (a2_white_noise (10),
 * a2_white_noise_ratio (32), a2_gaussian (5), a2_gaussian_alt (40),
 * a2_nongaussian (50), a2_nongaussian_fit (76)), mu2 and mu4 expanded at each
 * thermostat's a2 (mu2_white_noise, mu4_white_noise at (10); mu2_gaussian,
 * mu4_gaussian at (5); mu2_gaussian_alt, mu4_gaussian_alt at (40);
 * mu2_nongaussian, mu4_nongaussian at (50); mu2_nongaussian_fit,
 * mu4_nongaussian_fit by (72), (73) at (76)), and the tails A_white_noise,
 * A_gaussian, A_white_noise_mu2_0 and A_gaussian_mu2_0 (with mu2^(0)), and
 * Aprime_nongaussian; then paper D's heat-flux coefficients (docs/theory.md §14,
 * transport.h): the first Sonine approximation zeta_star, nu_kappa_star,
 * kappa_over_kappa0, kappa_prime_over_kappa0, mu_star (D (2.14), (2.46),
 * (2.41), (2.42), (2.38) at a2 (40) = D (2.16)), the same five with the
 * suffix _modified (the modified first Sonine approximation of D ref. [28]),
 * and the exact elastic solution kappa_elastic_exact, b1_elastic_exact,
 * b2_elastic_exact, b3_elastic_exact (independent of alpha; d = 3 only;
 * computed at the first call, about 0.6 s, then cached).  d = 3-only
 * values are NaN at other d; tail amplitudes are +inf at alpha = 1.
 *
 * Writes min(REF_SONINE_ALL_COUNT, cap) values to out (out may be NULL when
 * cap is 0) and returns REF_SONINE_ALL_COUNT; returns 0 and writes nothing
 * when alpha or d is out of range. */
size_t ref_sonine_all(double alpha, double d, ref_sonine_value *out, size_t cap);

#endif
