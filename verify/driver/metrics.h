/* Metrics of the verification cases (docs/theory.md §1.4), as pure functions of arrays,
 * and the adapters that let a case description name them (driver.h).
 *
 * Each pure function has a test in tests/test_driver.c that hands it a
 * wrong answer and sees the metric move.  A maximum or minimum over output
 * times is NaN when any term is (a quantity an external solver did not
 * report), never the extreme of the others.
 */
#ifndef GDSMC_VFY_METRICS_H
#define GDSMC_VFY_METRICS_H

#include <stddef.h>

#include "driver.h"

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

/* ------------------------------------------------- adapters (vfy_metric_fn) */

/* vfy_max_rel_err of series a against series b. */
vfy_metric_func vfy_metric_max_rel_err;
/* vfy_max_rel_ci of series a's half-widths against series b. */
vfy_metric_func vfy_metric_max_rel_ci;
/* vfy_max_ratio_dev of series a against series b. */
vfy_metric_func vfy_metric_max_ratio_dev;
/* Series a's mean, and its confidence half-width, at the last output time. */
vfy_metric_func vfy_metric_final_mean;
vfy_metric_func vfy_metric_final_ci;
/* vfy_fictitious_fraction of the row's counts (binary and background
 * collisions accepted). */
vfy_metric_func vfy_metric_fictitious_fraction;
/* vfy_variance_ratio of observable a between the row's first variant and
 * variant b: the mean (x = 0) or the smallest (x = 1). */
vfy_metric_func vfy_metric_variance_ratio;
/* vfy_max_norm3 of the mean velocity (ux, uy, uz). */
vfy_metric_func vfy_metric_max_velocity;
/* Value a of the previous row over value a of this one (a convergence
 * factor); NAN on the first row. */
vfy_metric_func vfy_metric_ratio_previous;

/* Arithmetic on the row's values a and b (the row's own, else the case's). */
/* a + x b */
vfy_metric_func vfy_metric_sum;
vfy_metric_func vfy_metric_percent_diff;   /* 100 (a - b)/b */
vfy_metric_func vfy_metric_percent_of;   /* 100 a/b */
/* max(a, x b) */
vfy_metric_func vfy_metric_max_of;
vfy_metric_func vfy_metric_abs_widened;   /* |a|, plus b at quick sizes */
/* Paper C's ratio of a collisional moment to its first Sonine terms:
 * (a - a_0)/a_1, or a_ci/a_1 with x = 1 (a = "mu2": the values mu2, mu2_0,
 * mu2_1); NAN where it is not finite (a_1 = 0 in the elastic limit). */
vfy_metric_func vfy_metric_sonine_ratio;
/* The value named by the row's text a, followed by b ("$relation=mu4_white",
 * b = "_ci": the value mu4_white_ci). */
vfy_metric_func vfy_metric_named_by_text;
/* Confidence half-width a (SIM_LAMBDA_P standard errors over the row's N
 * ensembles) with Student's t quantile for N - 1 degrees of freedom instead
 * of the normal one: a x t(VFY_STUDENT_P, N - 1) / SIM_LAMBDA_P (4.07/3.2
 * for N = 16). */
vfy_metric_func vfy_metric_student_ci;
/* Over the row's variants run as independent batches (driver.h): the sum of
 * value a over them (costs and counts); the mean of the batches' time
 * averages of series a over t >= x t_end, and its standard error (the
 * spread of the batches over sqrt(batches)); a standard error a as a
 * confidence half-width, with Student's t for batches - 1 degrees of
 * freedom. */
vfy_metric_func vfy_metric_variants_sum;

/* Against the row's partner b (vfy_row_partner; NAN without one): |a - a'|
 * over the quadrature sum of their Student's half-widths a_ci_t (how many
 * joint half-widths apart); 100 (a - a')/a'; and that percentage's
 * half-width, 100 |a/a'| times the quadrature sum of the relative ones. */
vfy_metric_func vfy_metric_partner_z;
vfy_metric_func vfy_metric_partner_percent;
vfy_metric_func vfy_metric_partner_percent_ci;

/* x a b (x a when b is NULL): n N = {"nN", vfy_metric_product, "n", "N", 1}. */
vfy_metric_func vfy_metric_product;

/* Case metrics (vfy_case_desc.case_metrics; row NULL): the smallest value a
 * over the rows; value a of the first row; the O(1/n) extrapolation of value
 * a over the rows, each with standard error b (vfy_extrapolate_inverse_n): x
 * = 0 its n = infinity value, x = 1 that value's half-width (SIM_LAMBDA_P
 * standard errors), x = 2 the fit's chi^2. */
vfy_metric_func vfy_metric_rows_min;
vfy_metric_func vfy_metric_first_row;
vfy_metric_func vfy_metric_rows_extrapolate;
vfy_metric_func vfy_metric_batch_mean;
vfy_metric_func vfy_metric_batch_se;
vfy_metric_func vfy_metric_batch_t_ci;
/* max_m |a[m] - b[m]| / c[m] for series a and b = "B/C" (paper A's
 * statistical part of Err: |eta1 - E xi^(n)| / F). */
vfy_metric_func vfy_metric_max_rel_diff;
/* vfy_max_abs_diff of series a against series b. */
vfy_metric_func vfy_metric_max_abs_diff;
/* x a / b, 0 where b <= 0 (ns_per_event = 1e9 cpu_s / events). */
vfy_metric_func vfy_metric_per;
/* The solver scene's thermostat strength and time step. */
vfy_metric_func vfy_metric_heating_strength;
vfy_metric_func vfy_metric_time_step;

#endif
