#include "stats.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>

#include "observe.h"
#include "steady.h"

/* max(worst, x), NaN when either is: a maximum over output times is NaN if
 * any term is (a quantity an external solver did not report), never the
 * maximum of the others. */
static double max_or_nan(double worst, double x)
{
    return isnan(worst) || isnan(x) ? NAN : fmax(worst, x);
}

double vfy_max_rel_err(const double *mean, const double *exact, size_t count)
{
    double worst = 0.0;
    for (size_t m = 0; m < count; m++)
        worst = max_or_nan(worst, fabs(exact[m] - mean[m]) / exact[m]);
    return worst;
}

double vfy_max_ratio_dev(const double *mean, const double *ref, size_t count)
{
    double worst = 0.0;
    for (size_t m = 0; m < count; m++)
        worst = max_or_nan(worst, fabs(mean[m] / ref[m] - 1.0));
    return worst;
}

double vfy_fictitious_fraction(double accepted, double events)
{
    return events > 0 ? 1.0 - accepted / events : 0.0;
}

void vfy_variance_ratio(const double *var_a, const double *var_b, size_t count, double *mean,
                        double *min)
{
    double sum = 0.0, lo = INFINITY;
    for (size_t m = 1; m < count; m++) {
        double ratio = var_a[m] / var_b[m];
        sum += ratio;
        lo = isnan(ratio) || isnan(lo) ? NAN : fmin(lo, ratio);
    }
    *mean = sum / (double)(count - 1);
    *min = lo;
}

double vfy_max_rel_ci(const double *ci, const double *exact, size_t count)
{
    double worst = 0.0;
    for (size_t m = 0; m < count; m++)
        worst = max_or_nan(worst, ci[m] / exact[m]);
    return worst;
}

double vfy_max_norm3(const double *x, const double *y, const double *z, size_t count)
{
    double worst = 0.0;
    for (size_t m = 0; m < count; m++)
        worst = max_or_nan(worst, sqrt(x[m] * x[m] + y[m] * y[m] + z[m] * z[m]));
    return worst;
}

void vfy_extrapolate_inverse_n(size_t rows, const size_t *n, const double *mean,
                               const double *sigma, double *T_inf, double *sd, double *chi2)
{
    double *x = malloc(2 * rows * sizeof *x), c0 = NAN, c1, cov00 = NAN, cov01, cov11;
    *chi2 = NAN;
    if (x != NULL) {
        double *w = x + rows;
        for (size_t i = 0; i < rows; i++) {
            x[i] = 1.0 / (double)n[i];
            w[i] = sigma[i] > 0.0 ? 1.0 / (sigma[i] * sigma[i]) : 1e300;
        }
        gsl_fit_wlinear(x, 1, w, 1, mean, 1, rows, &c0, &c1, &cov00, &cov01, &cov11, chi2);
        free(x);
    }
    *T_inf = c0;
    *sd = sqrt(cov00);
}

double vfy_student_t(double p, double dof) { return gsl_cdf_tdist_Pinv(p, dof); }

double vfy_zmax_ensembles(double zmax, size_t ensembles)
{
    if (ensembles < 2)   /* no variance: the z-test is an exact comparison */
        return zmax;
    const double N = (double)ensembles;
    const double t = gsl_cdf_tdist_Qinv(gsl_cdf_ugaussian_Q(zmax), N - 1.0) * sqrt(N / (N - 1.0));
    return t > zmax ? t : zmax;
}

double vfy_time_average(const double *t, const double *mean, size_t count, double t_from)
{
    double s = 0.0;
    size_t used = 0;
    for (size_t m = 0; m < count; m++) {
        if (t[m] >= t_from) {
            s += mean[m];
            used++;
        }
    }
    return used ? s / (double)used : NAN;
}

double vfy_max_abs_diff(const double *a, const double *b, size_t count)
{
    double worst = 0.0;
    for (size_t m = 0; m < count; m++)
        worst = max_or_nan(worst, fabs(a[m] - b[m]));
    return worst;
}

double vfy_max_scaled_diff(const double *a, const double *b, const double *scale, size_t count)
{
    double worst = 0.0;
    for (size_t k = 0; k < count; k++)
        worst = max_or_nan(worst, fabs(a[k] - b[k]) / scale[k]);
    return worst;
}

double vfy_z_pair(double a, double sa, double b, double sb)
{
    return fabs(a - b) / sqrt(sa * sa + sb * sb);
}

size_t vfy_fit_tail(const double *c, const double *f, const double *ci, size_t bins, double b,
                    double c_lo, double lambda, double *A, double *A_sd, double *K)
{
    double *x = malloc(3 * (bins ? bins : 1) * sizeof *x);
    size_t m = 0;
    *A = *A_sd = *K = NAN;
    if (x == NULL)
        return 0;
    double *y = x + bins, *w = y + bins;
    for (size_t k = 0; k < bins; k++) {
        if (c[k] < c_lo || !(f[k] > 0.0) || !(ci[k] < 0.5 * f[k]))
            continue;
        double sigma = ci[k] / lambda / f[k];   /* of ln f */
        x[m] = pow(c[k], b);
        y[m] = log(f[k]);
        w[m] = 1.0 / (sigma * sigma);
        m++;
    }
    if (m >= 3) {
        double c0, c1, cov00, cov01, cov11, chi2;
        gsl_fit_wlinear(x, 1, w, 1, y, 1, m, &c0, &c1, &cov00, &cov01, &cov11, &chi2);
        *A = -c1;
        *A_sd = sqrt(cov11);
        *K = exp(c0);
    }
    free(x);
    return m;
}

/* The slope of y_k against x_k as vfy_fit_tail_exponent describes, with
 * ln f_k0 shifted by `shift` (the weights do not count f_k0's error, which is
 * common to every y_k); t gets b, chi2_dof and the range. */
static void fit_exponent(const double *r, const double *f, const double *ci, size_t bins,
                         size_t k0, double r_lo, double r_hi, double rel_max, double lambda,
                         double shift, double *work, vfy_tail_exponent *t)
{
    double *x = work, *y = x + bins, *w = y + bins;
    const double ln0 = log(f[k0]) + shift;
    size_t m = 0;
    for (size_t k = k0 + 1; k < bins && r[k] <= r_hi; k++) {
        const double s = ci[k] / lambda / f[k];   /* of ln f_k */
        if (!(f[k] > 0.0) || !(f[k] < f[k0]) || !(s <= rel_max)) {
            if (m > 0)
                break;   /* the clean range ends here */
            continue;
        }
        if (r[k] < r_lo)
            continue;
        const double d = ln0 - log(f[k]);
        x[m] = log(r[k] - r[k0]);
        y[m] = log(d);
        w[m] = d * d / (s * s);   /* 1/sigma^2 of y */
        if (m == 0)
            t->r_first = r[k];
        t->r_last = r[k];
        m++;
    }
    t->used = m;
    if (m >= 3) {
        double c0, c1, cov00, cov01, cov11, chi2;
        gsl_fit_wlinear(x, 1, w, 1, y, 1, m, &c0, &c1, &cov00, &cov01, &cov11, &chi2);
        t->b = c1;
        t->chi2_dof = chi2 / (double)(m - 2);
        t->b_se = sqrt(cov11 * (t->chi2_dof > 1.0 ? t->chi2_dof : 1.0));
    }
}

vfy_tail_exponent vfy_fit_tail_exponent(const double *r, const double *f, const double *ci,
                                        size_t bins, size_t k0, double r_lo, double r_hi,
                                        double rel_max, double lambda)
{
    vfy_tail_exponent t = {NAN, NAN, NAN, NAN, NAN, 0}, shifted = t;
    double *work = malloc(3 * (bins ? bins : 1) * sizeof *work);
    if (work == NULL || k0 >= bins || !(f[k0] > 0.0)) {
        free(work);
        return t;
    }
    fit_exponent(r, f, ci, bins, k0, r_lo, r_hi, rel_max, lambda, 0.0, work, &t);
    /* f_k0's error moves every y_k the same way: its share of b's error is
     * the change of b when ln f_k0 moves by one standard error */
    const double s0 = ci[k0] / lambda / f[k0];
    fit_exponent(r, f, ci, bins, k0, r_lo, r_hi, rel_max, lambda, s0, work, &shifted);
    if (t.used >= 3)
        t.b_se = hypot(t.b_se, shifted.b - t.b);
    free(work);
    return t;
}

double vfy_energy_balance(const sim_scene *scene, const sim_scene *solver,
                          const sim_ensemble_result *res, double *rel_ci)
{
    const double mu2 = sim_result_steady_mean(res, SIM_STEADY_MU2);
    const double T = sim_result_steady_mean(res, SIM_STEADY_T);
    const double c1 = sim_result_steady_mean(res, SIM_STEADY_C1);
    const int white = scene->heating.type == SIM_HEATING_WHITE_NOISE;
    if (rel_ci != NULL) {
        *rel_ci = sim_result_steady_ci(res, SIM_STEADY_MU2) / mu2
                  + 1.5 * sim_result_steady_ci(res, SIM_STEADY_T) / T;
        if (!white)   /* the input's <|v|> = c1 sqrt(2T) */
            *rel_ci += sim_result_steady_ci(res, SIM_STEADY_C1) / c1
                       + 0.5 * sim_result_steady_ci(res, SIM_STEADY_T) / T;
    }
    const double a = scene->collisions.restitution, a_obs = solver->collisions.restitution;
    const double g3 = 8.0 * mu2 * pow(2.0 * T, 1.5) / (M_PI * (1.0 - a_obs * a_obs));
    const double loss = scene->collisions.rate * M_PI * scene->collisions.constant * (1.0 - a * a)
                        * g3 / 6.0;
    if (white)
        return loss / (2.0 * scene->heating.strength);
    if (scene->heating.type == SIM_HEATING_NON_GAUSSIAN)
        return loss / (2.0 / 3.0 * scene->heating.strength * c1 * sqrt(2.0 * T));
    return NAN;
}
