#include "metrics.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "observe.h"
#include "steady.h"

/* ------------------------------------------------------------ adapters */

/* Two series of a row into freshly allocated arrays (a's mean and ci, b's
 * mean); NULL when out of memory or a series is missing. */
static double *two_series(const vfy_row *row, const char *a, const char *b, double **a_ci,
                          double **b_mean)
{
    size_t M = row->res.outputs;
    double *buf = malloc(3 * M * sizeof *buf);
    if (buf == NULL)
        return NULL;
    if (vfy_row_series(row, a, buf, buf + M) != 0
        || (b != NULL && vfy_row_series(row, b, buf + 2 * M, NULL) != 0)) {
        free(buf);
        return NULL;
    }
    *a_ci = buf + M;
    *b_mean = buf + 2 * M;
    return buf;
}

/* fn of series a's means (or, with ci, its half-widths) against series b's
 * means. */
static double series_pair(const vfy_row *row, const vfy_metric *m,
                          double (*fn)(const double *, const double *, size_t), int ci)
{
    double *a_ci, *b, *a = two_series(row, m->a, m->b, &a_ci, &b);
    double v = a ? fn(ci ? a_ci : a, b, row->res.outputs) : NAN;
    free(a);
    return v;
}

double vfy_metric_max_rel_err(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    return series_pair(row, m, vfy_max_rel_err, 0);
}

double vfy_metric_max_rel_ci(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    return series_pair(row, m, vfy_max_rel_ci, 1);
}

double vfy_metric_max_ratio_dev(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    return series_pair(row, m, vfy_max_ratio_dev, 0);
}

/* Series a at the last output: its mean (ci = 0) or its half-width (ci = 1). */
static double final_value(const vfy_row *row, const char *a, int ci)
{
    double *c, *unused, *mean = two_series(row, a, NULL, &c, &unused);
    size_t M = row->res.outputs;
    double v = mean && M > 0 ? (ci ? c[M - 1] : mean[M - 1]) : NAN;
    free(mean);
    return v;
}

double vfy_metric_final_mean(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    return final_value(row, m->a, 0);
}

double vfy_metric_final_ci(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    return final_value(row, m->a, 1);
}

double vfy_metric_fictitious_fraction(const vfy_case_run *run, const vfy_row *row,
                                      const vfy_metric *m)
{
    (void)run;
    (void)m;
    return vfy_fictitious_fraction(vfy_values_get(&row->values, "collisions")
                                       + vfy_values_get(&row->values, "background"),
                                   vfy_values_get(&row->values, "events"));
}

double vfy_metric_variance_ratio(const vfy_case_run *run, const vfy_row *row,
                                 const vfy_metric *m)
{
    const sim_ensemble_result *a = vfy_row_result(run, row, NULL);
    const sim_ensemble_result *b = vfy_row_result(run, row, m->b);
    const int k = sim_observable_find(&row->solver, m->a, strlen(m->a));
    size_t M = a->outputs;
    double *va = malloc(2 * M * sizeof *va), mean = NAN, min = NAN;
    if (b != NULL && k >= 0 && va != NULL) {
        for (size_t t = 0; t < M; t++) {
            va[t] = sim_result_var(a, t, k);
            va[M + t] = sim_result_var(b, t, k);
        }
        vfy_variance_ratio(va, va + M, M, &mean, &min);
    }
    free(va);
    return m->x == 0 ? mean : min;
}

double vfy_metric_max_velocity(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    (void)m;
    double *uy, *uz, *ux = two_series(row, "ux", "uz", &uy, &uz);
    if (ux == NULL)
        return NAN;
    vfy_row_series(row, "uy", uy, NULL);
    double v = vfy_max_norm3(ux, uy, uz, row->res.outputs);
    free(ux);
    return v;
}

double vfy_metric_ratio_previous(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const vfy_row *prev = vfy_row_previous(run, row);
    return prev ? vfy_values_get(&prev->values, m->a) / vfy_values_get(&row->values, m->a)
                : NAN;
}

/* Value `name` (vfy_value: the row's own, a scene key, else the case's). */
static double value_of(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    return vfy_value(run, row, name);
}

double vfy_metric_product(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    return m->x * value_of(run, row, m->a) * (m->b ? value_of(run, row, m->b) : 1.0);
}

double vfy_metric_first_row(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)row;
    return run->nrows > 0 ? vfy_values_get(&run->rows[0].values, m->a) : NAN;
}

double vfy_metric_constant(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    (void)row;
    return m->x;
}

double vfy_metric_last_row(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)row;
    return run->nrows > 0 ? vfy_values_get(&run->rows[run->nrows - 1].values, m->a) : NAN;
}

double vfy_metric_rows_extrapolate(const vfy_case_run *run, const vfy_row *row,
                                   const vfy_metric *m)
{
    (void)row;
    const size_t rows = run->nrows;
    double *y = malloc(2 * rows * sizeof *y);
    size_t *n = malloc(rows * sizeof *n);
    double inf = NAN, sd = NAN, chi2 = NAN;
    if (y != NULL && n != NULL && rows > 0) {
        for (size_t i = 0; i < rows; i++) {
            n[i] = run->rows[i].solver.particles.n;
            y[i] = vfy_values_get(&run->rows[i].values, m->a);
            y[rows + i] = vfy_values_get(&run->rows[i].values, m->b);
        }
        vfy_extrapolate_inverse_n(rows, n, y, y + rows, &inf, &sd, &chi2);
    }
    free(y);
    free(n);
    return m->x == 0.0 ? inf : m->x == 1.0 ? SIM_LAMBDA_P * sd : chi2;
}

double vfy_metric_sum(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    return value_of(run, row, m->a) + m->x * value_of(run, row, m->b);
}

double vfy_metric_percent_diff(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const double b = value_of(run, row, m->b);
    return 100.0 * (value_of(run, row, m->a) - b) / b;
}

double vfy_metric_percent_of(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    return 100.0 * value_of(run, row, m->a) / value_of(run, row, m->b);
}

double vfy_metric_max_of(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    return fmax(value_of(run, row, m->a), m->x * value_of(run, row, m->b));
}

double vfy_metric_abs_widened(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const double v = fabs(value_of(run, row, m->a));
    return run->o->size == VFY_QUICK ? v + value_of(run, row, m->b) : v;
}

double vfy_metric_sonine_ratio(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    char name[48];
    snprintf(name, sizeof name, "%s_1", m->a);
    const double first = value_of(run, row, name);
    snprintf(name, sizeof name, m->x != 0 ? "%s_ci" : "%s_0", m->a);
    const double v = m->x != 0 ? value_of(run, row, name) / first
                               : (value_of(run, row, m->a) - value_of(run, row, name)) / first;
    return isfinite(v) ? v : NAN;
}

double vfy_metric_named_by_text(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const char *text = vfy_row_text(row, m->a);
    char name[64];
    snprintf(name, sizeof name, "%s%s", text ? text : "", m->b ? m->b : "");
    return text ? value_of(run, row, name) : NAN;
}

double vfy_metric_heating_strength(const vfy_case_run *run, const vfy_row *row,
                                   const vfy_metric *m)
{
    (void)run;
    (void)m;
    return row->solver.heating.strength;
}

double vfy_metric_time_step(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    (void)m;
    return vfy_scene_step(&row->solver);
}

double vfy_metric_student_ci(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const double N = value_of(run, row, "N");
    return value_of(run, row, m->a) * vfy_student_t(VFY_STUDENT_P, N - 1.0) / SIM_LAMBDA_P;
}

/* name of variant k of the row's case: "a" (k = 0) or "a@VARIANT". */
static const char *variant_name(const vfy_case_run *run, const char *a, size_t k, char *buf,
                                size_t len)
{
    char text[48];
    const char *v = vfy_variant_text(run->d, k, text, sizeof text);
    v = v ? v : "";
    snprintf(buf, len, "%s%s%.*s", a, k ? "@" : "", k ? (int)strcspn(v, ":") : 0, v);
    return buf;
}

double vfy_metric_partner_z(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const vfy_row *other = vfy_row_partner(run, row, m->b);
    if (other == NULL)
        return NAN;
    char ci[64];
    snprintf(ci, sizeof ci, "%s_ci_t", m->a);
    return vfy_z_pair(vfy_values_get(&row->values, m->a), vfy_values_get(&row->values, ci),
                      vfy_values_get(&other->values, m->a), vfy_values_get(&other->values, ci));
}

double vfy_metric_partner_percent(const vfy_case_run *run, const vfy_row *row,
                                  const vfy_metric *m)
{
    const vfy_row *other = vfy_row_partner(run, row, m->b);
    if (other == NULL)
        return NAN;
    const double b = vfy_values_get(&other->values, m->a);
    return 100.0 * (vfy_values_get(&row->values, m->a) - b) / b;
}

double vfy_metric_partner_percent_ci(const vfy_case_run *run, const vfy_row *row,
                                     const vfy_metric *m)
{
    const vfy_row *other = vfy_row_partner(run, row, m->b);
    if (other == NULL)
        return NAN;
    char ci[64];
    snprintf(ci, sizeof ci, "%s_ci_t", m->a);
    const double a = vfy_values_get(&row->values, m->a), b = vfy_values_get(&other->values, m->a);
    const double ra = vfy_values_get(&row->values, ci) / a;
    const double rb = vfy_values_get(&other->values, ci) / b;
    return 100.0 * fabs(a / b) * sqrt(ra * ra + rb * rb);
}

double vfy_metric_rows_min(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)row;
    double smallest = INFINITY;
    for (size_t i = 0; i < run->nrows; i++)
        smallest = fmin(smallest, vfy_values_get(&run->rows[i].values, m->a));
    return smallest;
}

double vfy_metric_variants_sum(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    double sum = 0.0;
    char name[64];
    for (size_t k = 0; k < vfy_variant_count(run->d); k++)
        sum += value_of(run, row, variant_name(run, m->a, k, name, sizeof name));
    return sum;
}

/* The time averages of series a over t >= x t_end, one per variant, into
 * avg (B of them); returns B, or 0 when out of memory or a series is
 * missing. */
static size_t batch_averages(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m,
                             double *avg)
{
    const size_t B = vfy_variant_count(run->d), M = row->res.outputs;
    double *mean = malloc(M * sizeof *mean);
    char name[64];
    size_t k = 0;
    for (; mean != NULL && k < B; k++) {
        if (vfy_row_series(row, variant_name(run, m->a, k, name, sizeof name), mean, NULL) != 0)
            break;
        avg[k] = vfy_time_average(row->res.t, mean, M, m->x * row->solver.t_end);
    }
    free(mean);
    return k == B ? B : 0;
}

double vfy_metric_batch_mean(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    double *avg = malloc(vfy_variant_count(run->d) * sizeof *avg), v = NAN;
    size_t B = avg ? batch_averages(run, row, m, avg) : 0;
    if (B > 0)
        v = gsl_stats_mean(avg, 1, B);
    free(avg);
    return v;
}

double vfy_metric_batch_se(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    double *avg = malloc(vfy_variant_count(run->d) * sizeof *avg), v = NAN;
    size_t B = avg ? batch_averages(run, row, m, avg) : 0;
    if (B > 1)
        v = gsl_stats_sd_m(avg, 1, B, gsl_stats_mean(avg, 1, B)) / sqrt((double)B);
    free(avg);
    return v;
}

double vfy_metric_batch_t_ci(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const double B = (double)vfy_variant_count(run->d);
    return vfy_student_t(VFY_STUDENT_P, B - 1.0) * value_of(run, row, m->a);
}

double vfy_metric_max_abs_diff(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    return series_pair(row, m, vfy_max_abs_diff, 0);
}

double vfy_metric_per(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const double b = value_of(run, row, m->b);
    return b > 0 ? m->x * value_of(run, row, m->a) / b : 0.0;
}

double vfy_metric_max_rel_diff(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    const size_t M = row->res.outputs;
    const char *slash = strchr(m->b, '/');
    char b[64];
    snprintf(b, sizeof b, "%.*s", slash ? (int)(slash - m->b) : (int)strlen(m->b), m->b);
    double *buf = malloc(3 * M * sizeof *buf), worst = NAN;
    if (buf != NULL && slash != NULL && vfy_row_series(row, m->a, buf, NULL) == 0
        && vfy_row_series(row, b, buf + M, NULL) == 0
        && vfy_row_series(row, slash + 1, buf + 2 * M, NULL) == 0)
        worst = vfy_max_scaled_diff(buf, buf + M, buf + 2 * M, M);
    free(buf);
    return worst;
}
