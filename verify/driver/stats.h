/* Statistics of the verification cases (docs/theory.md §1.4) as pure functions
 * of arrays: errors against a reference, confidence bounds, the O(1/n)
 * extrapolation, tail fits, the steady energy balance.  They know no case,
 * row or run (metrics.h adapts them to descriptions, driver.h).
 *
 * Each function has a test in tests/test_driver.c that hands it a wrong
 * answer and sees it move.  A maximum or minimum over output times is NaN
 * when any term is (a quantity an external solver did not report), never the
 * extreme of the others.
 */
#ifndef GDSMC_VFY_STATS_H
#define GDSMC_VFY_STATS_H

#include <stddef.h>

#include "ensemble.h"
#include "scene.h"

/* max_m |exact[m] - mean[m]| / exact[m]: paper A's Emax, paper B's Err. */
double vfy_max_rel_err(const double *mean, const double *exact, size_t count);

/* max_m |mean[m] / ref[m] - 1|: the largest relative deviation from a
 * closure. */
double vfy_max_ratio_dev(const double *mean, const double *ref, size_t count);

/* 1 - accepted / events (0 without events): the fraction of fictitious
 * (rejected) candidates. */
double vfy_fictitious_fraction(double accepted, double events);

/* Var_a[m] / Var_b[m] over m = 1 .. count-1 (t > 0): its mean (*mean) and
 * smallest (*min) -- a variance reduction factor. */
void vfy_variance_ratio(const double *var_a, const double *var_b, size_t count, double *mean,
                        double *min);

/* max_m ci[m] / exact[m]: the largest relative confidence half-width. */
double vfy_max_rel_ci(const double *ci, const double *exact, size_t count);

/* max_m |(x[m], y[m], z[m])|: the largest norm of a vector series. */
double vfy_max_norm3(const double *x, const double *y, const double *z, size_t count);

/* The O(1/n) extrapolation at one output time: weighted least squares of
 * mean_i = T_inf + b / n_i with weights 1/sigma_i^2 (GSL).  Returns T_inf,
 * its standard error and the fit's chi^2. */
void vfy_extrapolate_inverse_n(size_t rows, const size_t *n, const double *mean,
                               const double *sigma, double *T_inf, double *sd, double *chi2);

/* Student's t quantile: P(T <= q) = p for dof degrees of freedom (GSL). */
double vfy_student_t(double p, double dof);
/* The bound on |z| = |mean - exact| / (ci / SIM_LAMBDA_P) that holds a mean of
 * N ensembles to the same false-alarm probability per point as zmax holds a
 * normal z: its standard error comes from the N samples' population variance
 * (ensemble.h), so z is Student's t with N - 1 degrees of freedom times
 * sqrt(N / (N - 1)).  Never below zmax (docs/verdicts.md; 4.5 becomes 9.75
 * at N = 10, 4.51 at N = 2000). */
double vfy_zmax_ensembles(double zmax, size_t ensembles);
/* The one-sided probability of a confidence half-width: the engine's
 * SIM_LAMBDA_P = 3.2 standard errors is the normal quantile at about it. */
#define VFY_STUDENT_P 0.9995

/* The mean of mean[m] over the output times t[m] >= t_from (a steady
 * value's time average); NAN when there is none. */
double vfy_time_average(const double *t, const double *mean, size_t count, double t_from);

/* max_m |a[m] - b[m]|. */
double vfy_max_abs_diff(const double *a, const double *b, size_t count);

/* max_m |a[m] - b[m]| / scale[m] (paper A's statistical part of Err:
 * |eta1 - E xi^(n)| / F); NaN when any term is. */
double vfy_max_scaled_diff(const double *a, const double *b, const double *scale, size_t count);

/* |a - b| over the quadrature sum of their half-widths sa and sb: how far
 * apart two independent estimates are, in units of their joint half-width. */
double vfy_z_pair(double a, double sa, double b, double sb);

/* The exact steady energy balance of a heated hard-sphere gas (docs/theory.md §11.3;
 * verify/cases/case_hard.c derives it for the n-particle process): the collisional
 * loss of T, gamma pi C (1 - alpha^2) <|g|^3>/6 with <|g|^3> = 8 mu2 (2T)^(3/2)/(pi
 * (1 - alpha'^2)) from the result's steady mu2 (paper C Eq. 65, reduced with the
 * solver's alpha', which its observer used) and T, over the thermostat's input at
 * scene's strength: white noise 2 beta, non-Gaussian (2/3) g <|v|> with <|v|> =
 * c1 sqrt(2T).  1 in every steady state, whatever a2; NAN for another
 * thermostat.  *rel_ci (may be NULL) gets its relative half-width, those of the
 * steady values added. */
double vfy_energy_balance(const sim_scene *scene, const sim_scene *solver,
                          const sim_ensemble_result *res, double *rel_ci);

/* Weighted least squares of ln f = ln K - A c^b over the bins k with
 * c[k] >= c_lo, f[k] > 0 and ci[k] < f[k]/2 (ci = lambda standard errors):
 * a high-energy tail f ~ K exp(-A c^b) (paper C §4).  Sets A, its standard
 * error and K (NAN with fewer than 3 bins); returns the number of bins used. */
size_t vfy_fit_tail(const double *c, const double *f, const double *ci, size_t bins, double b,
                    double c_lo, double lambda, double *A, double *A_sd, double *K);

/* Paper A's tail exponent (docs/theory.md §11.5, A §4.3): with f_k a histogram of
 * the speed in shells, r[k] the upper edge of shell k and k0 < k the anchor
 * shell, the weighted least-squares slope b of
 *   y_k = ln(ln f_k0 - ln f_k)  against  x_k = ln(r_k - r_k0),
 * which is exactly b for f_k = f_k0 exp(-a (r_k - r_k0)^b).  The clean range:
 * the shells from the first with r_k >= r_lo to the last before one whose
 * f_k is not below f_k0 (or not positive) or whose relative standard error
 * ci[k]/(lambda f_k) exceeds rel_max (ci = lambda standard errors), or with
 * r_k <= r_hi (INFINITY: no limit; a finite window gives the local slope).  Weights
 * from the errors of ln f_k; the standard error of b is the fit's, times
 * sqrt(chi^2/dof) when that exceeds 1 (a model that does not fit the shells
 * widens its own error), in quadrature with the change of b when ln f_k0
 * moves by its standard error (an error common to every y_k). */
typedef struct vfy_tail_exponent {
    double b, b_se;           /* NAN with fewer than 3 shells */
    double chi2_dof;
    double r_first, r_last;   /* upper edges of the first and last shell used */
    size_t used;
} vfy_tail_exponent;
vfy_tail_exponent vfy_fit_tail_exponent(const double *r, const double *f, const double *ci,
                                        size_t bins, size_t k0, double r_lo, double r_hi,
                                        double rel_max, double lambda);

#endif
