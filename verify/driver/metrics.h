/* The metric adapters that let a case description name a statistic
 * (stats.h) on a row's series and values (driver.h): vfy_metric_fn.
 *
 * Each adapter has a test in tests/test_driver.c that hands it a wrong
 * answer and sees the metric move.
 */
#ifndef GDSMC_VFY_METRICS_H
#define GDSMC_VFY_METRICS_H

#include <stddef.h>

#include "driver.h"
#include "stats.h"

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

/* x: a tolerance or a parameter by its name in the case file, for the notes
 * and titles (x = VFY_TOL_TAILS_WINDOW). */
vfy_metric_func vfy_metric_constant;

/* x a b (x a when b is NULL): n N = {"nN", vfy_metric_product, "n", "N", 1}. */
vfy_metric_func vfy_metric_product;

/* Case metrics (vfy_case_desc.case_metrics; row NULL): the smallest value a
 * over the rows; value a of the first row, of the last row; the O(1/n) extrapolation of value
 * a over the rows, each with standard error b (vfy_extrapolate_inverse_n): x
 * = 0 its n = infinity value, x = 1 that value's half-width (SIM_LAMBDA_P
 * standard errors), x = 2 the fit's chi^2. */
vfy_metric_func vfy_metric_rows_min;
vfy_metric_func vfy_metric_first_row;
vfy_metric_func vfy_metric_last_row;
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
