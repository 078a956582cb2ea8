/* Paper A (Gamba, Rjasanow, Wagner 2003): the uniformly heated granular gas
 * with the exact jump scheme (docs/theory.md §8.3, §11).
 *
 * grw-ex3, grw-ex4: Tables 1 and 2.  Emax = max_m |T(t_m) - eta1(t_m)| / T(t_m)
 * with paper A's uncentred estimator T_raw (docs/theory.md §1.2), against the closed form
 * (A.13); CF = Emax(previous row) / Emax.  Beyond the paper, each row's mean
 * is z-tested at every output time against the exact expectation of the
 * n-particle estimator (reference/heated.h), which separates the O(1/n) bias
 * from noise exactly.
 *
 * grw-ex5: hard spheres.  No exact solution: the DSMC temperature for each n,
 * its O(1/n) extrapolation to n = infinity (weighted least squares in 1/n at
 * every output time), and both closures of docs/theory.md §11.4.
  *
 * The cases are data (verify/cases/scenes/grw-ex*.case, docs/adding-a-case.md);
 * this file holds the metrics, guards, rules, curves and hooks they name, listed
 * in vfy_grw_named at its end.
 */
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "driver.h"
#include "figure.h"
#include "heated.h"
#include "metrics.h"
#include "named.h"
#include "scene_refs.h"
#include "steady.h"
#include "tolerances.h"

/* The O(1/n) extrapolation at every output time: <case>-extrapolated.csv, the
 * fit's chi^2 and T_inf(t_end) against the Sonine closure, and the n =
 * infinity curve of the figure. */
static sim_status ex5_extrapolate(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    static const char *const xcols[] = {"t", "T_inf", "T_inf_ci", "T_maxwell_closure",
                                        "T_sonine_closure", "diff_maxwell", "diff_sonine",
                                        "chi2"};
    const size_t rows = run->nrows, M = run->rows[0].res.outputs;
    const double *t = run->rows[0].res.t;
    double *buf = malloc(3 * M * sizeof *buf);
    if (buf == NULL || vfy_run_extrapolate(run, "T", buf + 2 * M) != 0) {
        free(buf);
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    double *maxw = buf, *son = buf + M, *chi2 = buf + 2 * M;
    vfy_row_series(&run->rows[0], "T_maxwell_closure", maxw, NULL);
    vfy_row_series(&run->rows[0], "T_sonine_closure", son, NULL);
    vfy_table xtable;
    vfy_table_init(&xtable, sizeof xcols / sizeof *xcols, xcols);
    double chi2_max = 0.0;
    for (size_t m = 0; m < M; m++) {
        const double *T = run->extra_mean, *Tci = run->extra_ci;
        if (m > 0)   /* NaN (a quantity not reported) stays NaN */
            chi2_max = isnan(chi2[m]) ? NAN : fmax(chi2_max, chi2[m]);
        vfy_table_cell(&xtable, "%.4g", t[m]);
        vfy_table_cell(&xtable, "%.6f", T[m]);
        vfy_table_cell(&xtable, "%.6f", Tci[m]);
        vfy_table_cell(&xtable, "%.6f", maxw[m]);
        vfy_table_cell(&xtable, "%.6f", son[m]);
        vfy_table_cell(&xtable, "%+.6f", T[m] - maxw[m]);
        vfy_table_cell(&xtable, "%+.6f", T[m] - son[m]);
        vfy_table_cell(&xtable, "%.2f", chi2[m]);
    }
    const double T_inf = run->extra_mean[M - 1], ci_end = run->extra_ci[M - 1];
    vfy_values_set(&run->values, "t_end", t[M - 1]);
    vfy_values_set(&run->values, "T_inf", T_inf);
    vfy_values_set(&run->values, "T_inf_ci", ci_end);
    vfy_values_set(&run->values, "diff_maxwell", T_inf - maxw[M - 1]);
    vfy_values_set(&run->values, "diff_sonine", T_inf - son[M - 1]);
    vfy_values_set(&run->values, "chi2_max", chi2_max);

    /* The O(1/n) model must describe the rows: chi^2 with rows - 2 degrees of
     * freedom below its family-wise quantile over the M - 1 times judged
     * (VFY_TOL_FAMILY_P; 19.1 for 1 degree of freedom over 80 times, 22.6 for 2;
     * the per-time 0.999 quantile, 10.8, failed a right solver in seed run 3).
     * The kinetic T at t_end, extrapolated to n = infinity, agrees with the
     * first-Sonine closure within its confidence half-width plus the
     * closure's own model error. */
    char name[128], path[1024];
    vfy_check_range(r, vfy_expand(name, sizeof name, "{case} O(1/n) fit chi^2 (max over t)", run,
                                  NULL),
                    chi2_max, 0.0,
                    gsl_cdf_chisq_Qinv(VFY_TOL_FAMILY_P / (double)(M - 1), (double)(rows - 2)));
    vfy_check_absolute(r, vfy_expand(name, sizeof name, "{case} T_inf(t_end) vs Sonine closure",
                                     run, NULL),
                       T_inf, son[M - 1], ci_end + VFY_TOL_SONINE_MODEL_RTOL * son[M - 1]);
    if (run->o->progress)
        fprintf(run->o->progress, "   %s: at t = %g, T_inf = %.5f ± %.5f; Maxwellian closure "
                "%+.5f, Sonine closure %+.5f\n", run->c->name, t[M - 1], T_inf, ci_end,
                T_inf - maxw[M - 1], T_inf - son[M - 1]);
    char xname[160];
    snprintf(xname, sizeof xname, "%s-extrapolated", run->c->name);
    sim_status status = SIM_OK;
    if (vfy_table_write_csv(&xtable, vfy_report_path(run->o, xname, ".csv", path, sizeof path),
                            run->comment) != 0)
        status = vfy_io_error(path, msg, msglen);
    vfy_table_free(&xtable);
    free(buf);
    return status;
}

/* grw-ex6, grw-ex7, grw-ex8 (docs/theory.md §11.5, paper A §4.3): the steady tail
 * of the white-noise heated gas, alpha = 0.1, beta = 30, gamma = 16, C =
 * 1/(4 pi), for Maxwell molecules, hard spheres and VHS lambda = 1/2.  The
 * histogram is the steady observers' (steady.h): the reduced speed c = |C|/v0,
 * v0 = sqrt(2T/m), in K = 128 shells to c_max = R/v0(T_steady) (R = 40, 16,
 * 24 as the paper's), time-averaged per ensemble over the steady output
 * times.  The exponent b is the slope of paper A's y_k = ln(ln f_1 - ln f_k)
 * against x_k = ln(r_k - r_1) (vfy_fit_tail_exponent, anchored at the first
 * shell as the paper's figures are); it is scale-free, so reduced and
 * absolute speeds give the same b.  b_far is the same fit from c = 3.5 on;
 * b_anchored anchors at the first shell of the clean range (exact for b = 1
 * with any prefactor constant). */
enum { TAIL_B, TAIL_B_SE, TAIL_CHI2, TAIL_C_FIRST, TAIL_C_LAST, TAIL_SHELLS,
       TAIL_B_FAR, TAIL_B_FAR_SE, TAIL_B_LOCAL, TAIL_B_LOCAL_SE, TAIL_B_ANCHORED,
       TAIL_B_ANCHORED_SE, TAIL_B_EXPECTED, TAIL_A_THEORY, TAIL_A_FIT, TAIL_A_FIT_SE,
       TAIL_A_SHELLS, TAIL_A_FIT_C2, TAIL_B_NEAR };

/* The row's histogram: upper edges r[k], f[k], ci[k] (bins each). */
static int tail_histogram(const vfy_row *row, double **buf)
{
    const sim_scene *s = &row->solver;
    const size_t bins = s->steady.bins;
    if (bins == 0 || row->res.nsteady < SIM_STEADY_BIN0 + bins
        || (*buf = malloc(3 * bins * sizeof **buf)) == NULL)
        return -1;
    double *r = *buf, *f = r + bins, *ci = f + bins;
    for (size_t k = 0; k < bins; k++) {
        r[k] = sim_steady_bin_lower(s, k + 1);
        f[k] = sim_result_steady_mean(&row->res, SIM_STEADY_BIN0 + k);
        ci[k] = sim_result_steady_ci(&row->res, SIM_STEADY_BIN0 + k);
    }
    return 0;
}

/* The paper's fit anchored at shell k0 over reduced speeds c_lo .. c_hi of
 * the clean range (c_hi = INFINITY: to its end). */
static vfy_tail_exponent tail_fit(const vfy_row *row, size_t k0, double c_lo, double c_hi)
{
    double *h = NULL;
    vfy_tail_exponent t = {NAN, NAN, NAN, NAN, NAN, 0};
    if (tail_histogram(row, &h) == 0) {
        const size_t bins = row->solver.steady.bins;
        t = vfy_fit_tail_exponent(h, h + bins, h + 2 * bins, bins, k0, c_lo, c_hi,
                                  VFY_TOL_TAILS_REL_MAX, SIM_LAMBDA_P);
    }
    free(h);
    return t;
}

/* The amplitude A of f ~ K exp(-A c^b) at the scene's b = 1 + lambda/2:
 * vfy_fit_tail over the shell centres c >= c_lo (reduced speed); *A_se its
 * standard error; returns the shells used (0: no histogram). */
static size_t tail_amplitude(const vfy_row *row, double c_lo, double *A, double *A_se)
{
    const sim_scene *s = &row->solver;
    const size_t bins = s->steady.bins;
    double *h = NULL, K;
    size_t used = 0;
    *A = *A_se = NAN;
    if (tail_histogram(row, &h) == 0) {
        for (size_t k = 0; k < bins; k++)   /* the upper edges become centres */
            h[k] = sim_steady_bin_centre(s, k);
        const double b = 1.0 + 0.5 * row->scene.collisions.exponent;
        used = vfy_fit_tail(h, h + bins, h + 2 * bins, bins, b, c_lo, SIM_LAMBDA_P, A, A_se, &K);
    }
    free(h);
    return used;
}

static double grw_tail_metric(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    const int which = (int)m->x;
    if (which == TAIL_B_EXPECTED)
        return 1.0 + 0.5 * row->solver.collisions.exponent;
    if (which == TAIL_A_THEORY) {   /* the scene's parameters at the measured steady T */
        const ref_heated_params p = vfy_heated_params(&row->scene);
        return ref_heated_tail_A(&p, row->scene.collisions.exponent,
                                 vfy_values_get(&row->values, "T"));
    }
    if (which >= TAIL_A_FIT && which <= TAIL_A_FIT_C2) {
        double A, A_se;
        const double c_lo = which == TAIL_A_FIT_C2 ? VFY_TOL_TAILS_C_LO : VFY_TOL_TAILS_A_C_LO;
        const size_t used = tail_amplitude(row, c_lo, &A, &A_se);
        return which == TAIL_A_SHELLS ? (double)used : which == TAIL_A_FIT_SE ? A_se : A;
    }
    const vfy_tail_exponent t = tail_fit(row, 0, VFY_TOL_TAILS_C_LO, INFINITY);
    if (which == TAIL_B_NEAR)   /* the clean range's first window */
        return tail_fit(row, 0, t.r_first, t.r_first + VFY_TOL_TAILS_WINDOW).b;
    if (which == TAIL_B_FAR || which == TAIL_B_FAR_SE) {
        const vfy_tail_exponent far = tail_fit(row, 0, VFY_TOL_TAILS_C_FAR, INFINITY);
        return which == TAIL_B_FAR ? far.b : far.b_se;
    }
    if (which == TAIL_B_LOCAL || which == TAIL_B_LOCAL_SE) {   /* the clean range's last window */
        const vfy_tail_exponent w =
            t.used < 3 ? t : tail_fit(row, 0, t.r_last - VFY_TOL_TAILS_WINDOW, t.r_last);
        return which == TAIL_B_LOCAL ? w.b : w.b_se;
    }
    if (which == TAIL_B_ANCHORED || which == TAIL_B_ANCHORED_SE) {
        if (t.used < 3)
            return NAN;
        /* the shell whose upper edge is r_first is the anchor */
        const double delta = row->solver.steady.c_max / (double)row->solver.steady.bins;
        const size_t k0 = (size_t)lround(t.r_first / delta) - 1;
        const vfy_tail_exponent a = tail_fit(row, k0, 0.0, INFINITY);
        return which == TAIL_B_ANCHORED ? a.b : a.b_se;
    }
    switch (which) {
    case TAIL_B:
        return t.b;
    case TAIL_B_SE:
        return t.b_se;
    case TAIL_CHI2:
        return t.chi2_dof;
    case TAIL_C_FIRST:
        return t.r_first;
    case TAIL_C_LAST:
        return t.r_last;
    default:
        return (double)t.used;
    }
}

/* ---------------------------------------------- the tails' figures' curves */

/* The figures of grw-ex6..8 (their [figure]s): paper A Fig. 6, the steady
 * histogram beside the initial Maxwellian, ln f against the speed; Figs.
 * 7-9, y_k against x_k with the lines y = x - 2, 1.25 x - 2, 1.5 x - 2, in
 * the paper's absolute speed r = c v0 (v0 from the steady T); ln G(c) = ln f
 * + A c^b; and the local slope.  Each curve (vfy_curve_fn) is one of these,
 * made from the row's histogram. */
enum { CURVE_LN_F, CURVE_MAXWELLIAN, CURVE_LN_G, CURVE_EXPONENT };

/* The curves by shell (which: a CURVE_ above). */
static int tail_shells(const vfy_row *row, int which, vfy_curve *out)
{
    const sim_scene *s = &row->solver;
    const size_t K = s->steady.bins;
    const double T = vfy_values_get(&row->values, "T");
    const double v0 = sqrt(2.0 * T / sim_scene_grain_mass(s));
    const double delta = s->steady.c_max / (double)K;
    const double A = vfy_values_get(&row->values, "A_theory");
    const double b_theory = vfy_values_get(&row->values, "b_expected");
    double *h = NULL;
    if (tail_histogram(row, &h) != 0 || vfy_curve_alloc(out, K, which != CURVE_MAXWELLIAN) != 0) {
        free(h);
        return -1;
    }
    const double *edge = h, *f = h + K, *fci = h + 2 * K;
    double lnf_min = INFINITY;   /* the initial Maxwellian is drawn down to the steady
                                    state's smallest ln f (less 2): further down (ln f ~
                                    -800 at r = 40) it would set the scale and flatten
                                    the steady state into a line */
    for (size_t k = 0; k < K; k++)
        lnf_min = f[k] > 0.0 ? fmin(lnf_min, log(f[k])) : lnf_min;
    for (size_t k = 0; k < K; k++) {
        const double c = ((double)k + 0.5) * delta;
        const double lnf = f[k] > 0.0 ? log(f[k]) : NAN;
        const double lnf_ci = f[k] > 0.0 ? fci[k] / f[k] : NAN;
        const double d = log(f[0]) - lnf;
        const double lnf0 = -1.5 * log(M_PI) - c * c * T / s->particles.maxwellian.temperature;
        switch (which) {
        case CURVE_LN_F:
            out->x[k] = c * v0;
            out->y[0][k] = lnf;
            out->ci[0][k] = lnf_ci;
            break;
        case CURVE_MAXWELLIAN:
            out->x[k] = c * v0;
            out->y[0][k] = lnf0 < lnf_min - 2.0 ? NAN : lnf0;
            break;
        case CURVE_LN_G:   /* the fit's shells */
            out->x[k] = c;
            out->y[0][k] = lnf_ci < 0.5 ? lnf + A * pow(c, b_theory) : NAN;
            out->ci[0][k] = lnf_ci;
            break;
        default:
            out->x[k] = k > 0 ? log(v0 * (edge[k] - edge[0])) : NAN;
            out->y[0][k] = k > 0 && d > 0.0 ? log(d) : NAN;
            out->ci[0][k] = k > 0 && d > 0.0 ? lnf_ci / d : NAN;
        }
    }
    free(h);
    return 0;
}

/* The curve by shell `which` (a CURVE_, the name's fixed x). */
static int grw_curve_shells(const vfy_case_run *run, const vfy_row *row, double which,
                            vfy_curve *out)
{
    (void)run;
    return tail_shells(row, (int)which, out);
}

/* Paper A's line y = x_slope * x - 2 over the exponent figure's x range,
 * through two points. */
static int grw_curve_line(const vfy_case_run *run, const vfy_row *row, double slope,
                          vfy_curve *out)
{
    (void)run;
    const sim_scene *s = &row->solver;
    const double v0 = sqrt(2.0 * vfy_values_get(&row->values, "T") / sim_scene_grain_mass(s));
    if (vfy_curve_alloc(out, 2, 0) != 0)
        return -1;
    out->x[0] = 0.0;
    out->x[1] = log(v0 * s->steady.c_max);
    out->y[0][0] = slope * out->x[0] - 2.0;
    out->y[0][1] = slope * out->x[1] - 2.0;
    return 0;
}

/* The local slope: the fit over a window of width VFY_TOL_TAILS_WINDOW in c
 * centred at each shell's upper edge, for every window that ends by c_last
 * (from the core, where it is near the Gaussian's 2, along the clean range),
 * against c; its ci VFY_TOL_TAILS_Z standard errors. */
static int grw_curve_local_slope(const vfy_case_run *run, const vfy_row *row, double x,
                                 vfy_curve *out)
{
    (void)run, (void)x;
    const size_t K = row->solver.steady.bins;
    const double c_last = vfy_values_get(&row->values, "c_last");
    const double half = 0.5 * VFY_TOL_TAILS_WINDOW;
    double *h = NULL;
    if (tail_histogram(row, &h) != 0 || vfy_curve_alloc(out, K, 1) != 0) {
        free(h);
        return -1;
    }
    const double *edge = h, *f = h + K, *fci = h + 2 * K;
    for (size_t k = 0; k < K; k++) {
        const double lo = edge[k] - half, hi = edge[k] + half;
        vfy_tail_exponent w = {.b = NAN, .b_se = NAN};
        if (lo >= edge[0] && hi <= c_last + 1e-9)
            w = vfy_fit_tail_exponent(edge, f, fci, K, 0, lo, hi, VFY_TOL_TAILS_REL_MAX,
                                      SIM_LAMBDA_P);
        out->x[k] = edge[k];
        out->y[0][k] = w.b;
        out->ci[0][k] = VFY_TOL_TAILS_Z * w.b_se;
    }
    free(h);
    return 0;
}

/* A level line under the local slope, from c = 0 to c_last: at b_expected
 * (level NaN), or at the level (the Gaussian's 2). */
static int grw_curve_slope_level(const vfy_case_run *run, const vfy_row *row, double level,
                                 vfy_curve *out)
{
    (void)run;
    if (vfy_curve_alloc(out, 2, 0) != 0)
        return -1;
    out->x[0] = 0.0;
    out->x[1] = vfy_values_get(&row->values, "c_last");
    out->y[0][0] = out->y[0][1] = isnan(level) ? vfy_values_get(&row->values, "b_expected")
                                               : level;
    return 0;
}

/* The functions this file's case files name (named.h, registry.c). */
const vfy_named_fn vfy_grw_named[] = {
    VFY_NAMED_HOOK("ex5_extrapolate", ex5_extrapolate),
    VFY_NAMED_METRIC_X("grw_tail_b", grw_tail_metric, TAIL_B),
    VFY_NAMED_METRIC_X("grw_tail_b_se", grw_tail_metric, TAIL_B_SE),
    VFY_NAMED_METRIC_X("grw_tail_chi2", grw_tail_metric, TAIL_CHI2),
    VFY_NAMED_METRIC_X("grw_tail_c_first", grw_tail_metric, TAIL_C_FIRST),
    VFY_NAMED_METRIC_X("grw_tail_c_last", grw_tail_metric, TAIL_C_LAST),
    VFY_NAMED_METRIC_X("grw_tail_shells", grw_tail_metric, TAIL_SHELLS),
    VFY_NAMED_METRIC_X("grw_tail_b_far", grw_tail_metric, TAIL_B_FAR),
    VFY_NAMED_METRIC_X("grw_tail_b_far_se", grw_tail_metric, TAIL_B_FAR_SE),
    VFY_NAMED_METRIC_X("grw_tail_b_local", grw_tail_metric, TAIL_B_LOCAL),
    VFY_NAMED_METRIC_X("grw_tail_b_local_se", grw_tail_metric, TAIL_B_LOCAL_SE),
    VFY_NAMED_METRIC_X("grw_tail_b_anchored", grw_tail_metric, TAIL_B_ANCHORED),
    VFY_NAMED_METRIC_X("grw_tail_b_anchored_se", grw_tail_metric, TAIL_B_ANCHORED_SE),
    VFY_NAMED_METRIC_X("grw_tail_b_expected", grw_tail_metric, TAIL_B_EXPECTED),
    VFY_NAMED_METRIC_X("grw_tail_a_theory", grw_tail_metric, TAIL_A_THEORY),
    VFY_NAMED_METRIC_X("grw_tail_a_fit", grw_tail_metric, TAIL_A_FIT),
    VFY_NAMED_METRIC_X("grw_tail_a_fit_se", grw_tail_metric, TAIL_A_FIT_SE),
    VFY_NAMED_METRIC_X("grw_tail_a_shells", grw_tail_metric, TAIL_A_SHELLS),
    VFY_NAMED_METRIC_X("grw_tail_a_fit_c2", grw_tail_metric, TAIL_A_FIT_C2),
    VFY_NAMED_METRIC_X("grw_tail_b_near", grw_tail_metric, TAIL_B_NEAR),
    VFY_NAMED_CURVE_X("grw_curve_ln_f", grw_curve_shells, CURVE_LN_F),
    VFY_NAMED_CURVE_X("grw_curve_maxwellian", grw_curve_shells, CURVE_MAXWELLIAN),
    VFY_NAMED_CURVE_X("grw_curve_ln_g", grw_curve_shells, CURVE_LN_G),
    VFY_NAMED_CURVE_X("grw_curve_exponent", grw_curve_shells, CURVE_EXPONENT),
    VFY_NAMED_CURVE_X("grw_curve_line_1", grw_curve_line, 1.0),
    VFY_NAMED_CURVE_X("grw_curve_line_1_25", grw_curve_line, 1.25),
    VFY_NAMED_CURVE_X("grw_curve_line_1_5", grw_curve_line, 1.5),
    VFY_NAMED_CURVE("grw_curve_local_slope", grw_curve_local_slope),
    VFY_NAMED_CURVE("grw_curve_slope_expected", grw_curve_slope_level),
    VFY_NAMED_CURVE_X("grw_curve_slope_gaussian", grw_curve_slope_level, 2.0),
    VFY_NAMED_END};
