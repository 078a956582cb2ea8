/* Sonine-approximation formulas (SPEC §5, paper C Appendix).  General
 * dimension d where the paper gives it; d = 3 is the default elsewhere. */
#ifndef GDSMC_REF_SONINE_H
#define GDSMC_REF_SONINE_H

/* a2 of the white-noise heated inelastic hard-sphere gas, paper C Eq. (C.10):
 * 16(1-a)(1-2a^2) / (73 + 56d - 3a(35 + 8d) + 30(1-a)a^2), a = alpha.
 * alpha in [0, 1] and finite d >= 2, else NaN. */
double ref_sonine_a2_white_noise(double alpha, double d);

#endif
