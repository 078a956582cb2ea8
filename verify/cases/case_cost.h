/* The accuracy-cost (work-precision) report, docs/theory.md §1.4: error against CPU time
 * over a grid of particle numbers n, ensembles N and, for the time-step
 * scheme, steps h; which grid point reaches a target error most cheaply, and
 * which one a model fitted to the grid predicts beyond it.
 *
 * Cases (verify/cases/case_cost.c): cost-grw-ex3 (paper A Ex 3, Table 1's Err),
 * cost-brs-ex2 (paper B Ex 2, Table 2's Err), both Maxwell kernels, whose
 * systematic error is known exactly (reference/heated.h, background.h); and
 * cost-split-ex5 (paper A Ex 5's hard spheres, jump and time-step schemes).
 *
 * The pieces below are pure functions of the measured numbers, so that
 * tests/test_verify_cost.c can hand each check a wrong answer.
 */
#ifndef GDSMC_VFY_CASE_COST_H
#define GDSMC_VFY_CASE_COST_H

#include <stddef.h>

#include "checks.h"

/* Excess kurtosis allowed for the per-ensemble estimator when judging
 * standard deviations estimated from N samples (a Gaussian has 0; paper A's
 * T_raw carries a chi-square part |V|^2 at small n). */
#define VFY_COST_KURTOSIS 2.0

/* Index of the cheapest point (smallest cost[i]) with err[i] <= target, or
 * count when none reaches it.  NaN entries never qualify. */
size_t vfy_cost_cheapest(const double *err, const double *cost, size_t count, double target);

/* Weighted least squares of y = c[0] x1 + c[1] x2 with weights w (> 0):
 * the 2 x 2 normal equations.  *chi2 (may be NULL) = Σ w (y - fit)^2.
 * Returns 0, or -1 when count < 2 or the system is singular (c untouched). */
int vfy_cost_lsq2(size_t count, const double *x1, const double *x2, const double *y,
                  const double *w, double c[2], double *chi2);

/* The statistical part scales as 1/sqrt(N) (docs/theory.md §1.3: c = lambda_p sqrt(Var/N)):
 * for `count` particle numbers, conf1[i] at N1 ensembles and conf2[i] at
 * N2 > N1.  The pooled ratio R = exp(mean_i ln(conf1[i]/conf2[i])) /
 * sqrt(N2/N1) must lie within 1 ± zmax s, where s^2 = ((2 + kurtosis)/4)
 * (1/N1 - 1/N2)/count is the variance of ln of the ratio of two nested
 * standard-deviation estimates (nested: the N2 run contains the N1 run's
 * ensembles, as the built-in engine's streams make it), or with 1/N1 +
 * 1/N2 of two independent ones (an external solver's runs), kurtosis =
 * VFY_COST_KURTOSIS.  *ratio (may be NULL) receives R. */
vfy_verdict vfy_cost_check_stat_scaling(vfy_report *r, const char *name, const double *conf1,
                                        const double *conf2, size_t count, size_t N1, size_t N2,
                                        int nested, double zmax, double *ratio);

/* The error model describes the grid: max_i |ln(err[i]/model[i])| <=
 * ln(factor).  *worst (may be NULL) receives the err/model ratio farthest
 * from 1 (in the log). */
vfy_verdict vfy_cost_check_model(vfy_report *r, const char *name, const double *err,
                                 const double *model, size_t count, double factor,
                                 double *worst);

/* A chi^2 with `dof` degrees of freedom below its 1 - p quantile (p =
 * VFY_TOL_COST_CHI2_P = 0.001, tolerances.h): a fitted model (the O(1/n)
 * bias, the splitting error) describes the rows within their standard
 * errors.  Skipped (with the reason) when dof < 1. */
vfy_verdict vfy_cost_check_chi2(vfy_report *r, const char *name, double chi2, size_t dof);

#endif
