/* The fourth-cumulant (a2) estimates of paper C (docs/theory.md §13; Montanero
 * and Santos, seed 002) and the dimensions every Sonine formula accepts.
 * Equation numbers "(N)" are paper C's.
 *
 * A file of its own so that the transport coefficients (transport.c, which
 * take the a2 of Eq. (40)) depend on these alone, while the full listing of
 * sonine.h, which lists the transport coefficients too, sits above both:
 * sonine -> transport -> sonine_a2, one way.  sonine.h includes this header.
 *
 * Domain, for every function: restitution alpha in [0, 1] and dimension d
 * finite with REF_SONINE_D_MIN <= d <= REF_SONINE_D_MAX (d need not be an
 * integer).  Anything else, NaN included, returns NaN; so does a d = 3-only
 * formula at another d.  Functions are pure and thread-safe. */
#ifndef GDSMC_REF_SONINE_A2_H
#define GDSMC_REF_SONINE_A2_H

/* Accepted dimensions.  Above 100, Gamma(d/2) approaches the double range and
 * the formulas have no use. */
#define REF_SONINE_D_MIN 2.0
#define REF_SONINE_D_MAX 100.0

/* ------------------------------------------------------- a2 estimates */
/* All have the factor (1 - alpha), so a2 = 0 at alpha = 1.  The white-noise
 * and Gaussian forms have the factor (1 - 2 alpha^2) and change sign at
 * alpha = 1/sqrt(2); the non-Gaussian forms stay negative for alpha < 1. */

/* White noise (stochastic thermostat), van Noije and Ernst, Eq. (10):
 * 16(1-a)(1-2a^2) / (73 + 56d - 3a(35 + 8d) + 30(1-a)a^2), a = alpha;
 * the linearisation of mu4 = (d+2) mu2, Eqs. (23), (31). */
double ref_sonine_a2_white_noise(double alpha, double d);

/* White noise, ratio route, Eq. (32): linearising mu4/mu2 = d+2 instead,
 * 4(1-a)(1-2a^2) / (19 + 14d - 3a(9 + 2d) + 6(1-a)a^2).  Within about 0.001
 * of Eq. (10). */
double ref_sonine_a2_white_noise_ratio(double alpha, double d);

/* Gaussian thermostat = homogeneous cooling state, Eq. (5) (= Eq. (39),
 * linearising mu4 = (d+2)(1+a2) mu2):
 * 16(1-a)(1-2a^2) / (9 + 24d - a(41 - 8d) + 30(1-a)a^2). */
double ref_sonine_a2_gaussian(double alpha, double d);

/* Gaussian thermostat, Eq. (40) (linearising mu4/(1+a2) = (d+2) mu2):
 * 16(1-a)(1-2a^2) / (25 + 24d - a(57 - 8d) - 2(1-a)a^2).  The paper's
 * simulations favour it over Eq. (5) for alpha < 0.5. */
double ref_sonine_a2_gaussian_alt(double alpha, double d);

/* Non-Gaussian thermostat F = m g v/|v|, Eq. (50) (linearising Eq. (44) with
 * Eqs. (26), (48), (49)):
 * -16(1-a)(1+2a^2) / (63 + 40d - a(95 + 8d) + 30(1-a)a^2).
 * About 20% too small in magnitude (paper C §4.3). */
double ref_sonine_a2_nongaussian(double alpha, double d);

/* Non-Gaussian thermostat, semi-empirical, Eq. (76), d = 3 only (NaN at
 * other d): -240(1-a)(1+2a^2) / (1957 - 1125a + 390(1-a)a^2), from Eq. (44)
 * with the fitted slopes of Eqs. (72)-(75). */
double ref_sonine_a2_nongaussian_fit(double alpha, double d);

#endif
