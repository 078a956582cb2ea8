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
 * this file holds the metrics, guards, rules and hooks they name, listed
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
       TAIL_A_SHELLS, TAIL_A_FIT_C2 };

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
    if (which >= TAIL_A_FIT) {
        double A, A_se;
        const double c_lo = which == TAIL_A_FIT_C2 ? VFY_TOL_TAILS_C_LO : VFY_TOL_TAILS_A_C_LO;
        const size_t used = tail_amplitude(row, c_lo, &A, &A_se);
        return which == TAIL_A_SHELLS ? (double)used : which == TAIL_A_FIT_SE ? A_se : A;
    }
    const vfy_tail_exponent t = tail_fit(row, 0, VFY_TOL_TAILS_C_LO, INFINITY);
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

/* The local slope: the fit over a window of width VFY_TOL_TAILS_WINDOW in c
 * centred at each shell's upper edge, for every window that ends by c_last
 * (from the core, where it is near the Gaussian's 2, along the clean range),
 * against c, beside b_expected and 2 ({case}-local-slope.png); the case
 * values b_near (the clean range's first window), b_local (its last) and the
 * row's range, for the notes.  Returns 0 or -1 (I/O or memory). */
static int tails_local_slope(vfy_case_run *run, const vfy_row *row, const double *edge,
                             const double *f, const double *fci, size_t K)
{
    const double c_first = vfy_values_get(&row->values, "c_first");
    const double c_last = vfy_values_get(&row->values, "c_last");
    const double half = 0.5 * VFY_TOL_TAILS_WINDOW, expected = vfy_values_get(&row->values,
                                                                             "b_expected");
    double *buf = malloc((3 * K + 6) * sizeof *buf);
    if (buf == NULL)
        return -1;
    double *c = buf, *b = c + K, *b_ci = b + K, *lx = b_ci + K, *ly = lx + 2;
    for (size_t k = 0; k < K; k++) {
        const double lo = edge[k] - half, hi = edge[k] + half;
        vfy_tail_exponent w = {.b = NAN, .b_se = NAN};
        if (lo >= edge[0] && hi <= c_last + 1e-9)
            w = vfy_fit_tail_exponent(edge, f, fci, K, 0, lo, hi, VFY_TOL_TAILS_REL_MAX,
                                      SIM_LAMBDA_P);
        c[k] = edge[k];
        b[k] = w.b;
        b_ci[k] = VFY_TOL_TAILS_Z * w.b_se;
    }
    vfy_values_set(&run->values, "b_near",
                   vfy_fit_tail_exponent(edge, f, fci, K, 0, c_first,
                                         c_first + VFY_TOL_TAILS_WINDOW, VFY_TOL_TAILS_REL_MAX,
                                         SIM_LAMBDA_P).b);
    static const char *const copied[] = {"b_local", "b_expected", "c_first", "c_last"};
    for (size_t i = 0; i < sizeof copied / sizeof copied[0]; i++)   /* for the notes */
        vfy_values_set(&run->values, copied[i], vfy_values_get(&row->values, copied[i]));
    lx[0] = 0.0;
    lx[1] = c_last;
    ly[0] = ly[1] = expected;
    ly[2] = ly[3] = 2.0;
    char expected_label[48], name[96], title[200];
    snprintf(expected_label, sizeof expected_label, "b = 1 + lambda/2 = %g", expected);
    const vfy_xy_curve curves[] = {
        {.label = "local slope (DSMC), band: 2 standard errors", .count = K, .x = c,
         .y = {b}, .ci = {b_ci}, .band = 1},
        {.label = expected_label, .reference = 1, .count = 2, .x = lx, .y = {ly}},
        {.label = "b = 2 (Gaussian)", .reference = 1, .count = 2, .x = lx, .y = {ly + 2}}};
    snprintf(name, sizeof name, "%s-local-slope", run->c->name);
    snprintf(title, sizeof title, "%s: the local slope of y_k against x_k (paper A Figs. 7-9) "
             "over windows of width %g in c", run->c->name, VFY_TOL_TAILS_WINDOW);
    const vfy_xy_figure fig = {.name = name, .title = title,
                               .xlabel = "c = |C|/v0 (window centre)",
                               .comment = run->comment, .npanels = 1,
                               .ylabel = {"local slope"}, .ncurves = 3, .curves = curves};
    const int rc = vfy_write_xy(run->o, &fig);
    free(buf);
    return rc;
}

/* The figures: paper A Fig. 6 (the steady histogram beside the initial
 * Maxwellian, ln f against the speed) and Figs. 7-9 (y_k against x_k with
 * the lines y = x - 2, 1.25 x - 2, 1.5 x - 2), in the paper's absolute
 * speed r = c v0 (v0 from the steady T). */
static sim_status grw_tails_figures(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    (void)r;
    const vfy_row *row = &run->rows[run->nrows - 1];
    const sim_scene *s = &row->solver;
    const size_t K = s->steady.bins;
    const double T = vfy_values_get(&row->values, "T");
    const double v0 = sqrt(2.0 * T / sim_scene_grain_mass(s));
    double *h = NULL;
    double *buf = malloc(12 * (K ? K : 1) * sizeof *buf);
    if (buf == NULL || tail_histogram(row, &h) != 0) {
        free(buf);
        free(h);
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    const double *edge = h, *f = h + K, *fci = h + 2 * K;
    double *rc = buf, *lnf = rc + K, *lnf_ci = lnf + K, *lnf0 = lnf_ci + K;
    double *x = lnf0 + K, *y = x + K, *y_ci = y + K, *cc = y_ci + K, *lnG = cc + K;
    double *lines = lnG + K;
    const double delta = s->steady.c_max / (double)K;
    const double A = vfy_values_get(&row->values, "A_theory");
    const double b_theory = vfy_values_get(&row->values, "b_expected");
    for (size_t k = 0; k < K; k++) {
        const double c = ((double)k + 0.5) * delta;
        rc[k] = c * v0;
        lnf[k] = f[k] > 0.0 ? log(f[k]) : NAN;
        lnf_ci[k] = f[k] > 0.0 ? fci[k] / f[k] : NAN;
        lnf0[k] = -1.5 * log(M_PI) - c * c * T / s->particles.maxwellian.temperature;
        const double d = log(f[0]) - lnf[k];
        x[k] = k > 0 ? log(v0 * (edge[k] - edge[0])) : NAN;
        y[k] = k > 0 && d > 0.0 ? log(d) : NAN;
        y_ci[k] = k > 0 && d > 0.0 ? lnf_ci[k] / d : NAN;
        cc[k] = c;
        lnG[k] = lnf_ci[k] < 0.5 ? lnf[k] + A * pow(c, b_theory) : NAN;   /* the fit's shells */
    }
    /* the initial Maxwellian drawn down to the steady state's smallest ln f
     * (less 2): further down (ln f ~ -800 at r = 40) it would set the scale
     * and flatten the steady state into a line */
    double lnf_min = INFINITY;
    for (size_t k = 0; k < K; k++)
        lnf_min = isfinite(lnf[k]) ? fmin(lnf_min, lnf[k]) : lnf_min;
    for (size_t k = 0; k < K; k++)
        if (lnf0[k] < lnf_min - 2.0)
            lnf0[k] = NAN;
    const double b = vfy_values_get(&row->values, "b");
    vfy_xy_curve hist[] = {
        {.label = "steady state (DSMC)", .count = K, .x = rc, .y = {lnf}, .ci = {lnf_ci}},
        {.label = "initial Maxwellian", .reference = 1, .count = K, .x = rc, .y = {lnf0}}};
    char name[96], title[160];
    snprintf(name, sizeof name, "%s-histogram", run->c->name);
    snprintf(title, sizeof title, "paper A Fig. 6: ln f of the speed r, %s", run->c->name);
    vfy_xy_figure fig = {.name = name, .title = title, .xlabel = "r = |v|",
                         .comment = run->comment, .npanels = 1, .ylabel = {"ln f"},
                         .ncurves = 2, .curves = hist};
    int rc_io = vfy_write_xy(run->o, &fig);

    /* ln G(c) = ln f + A c^b with the balance's A: level where the tail has its form */
    const vfy_xy_curve levelled[] = {
        {.label = "ln G (DSMC)", .count = K, .x = cc, .y = {lnG}, .ci = {lnf_ci}}};
    snprintf(name, sizeof name, "%s-levelled", run->c->name);
    snprintf(title, sizeof title, "%s: ln G(c) = ln f(c) + A c^%g, A = %.4f from the "
             "loss-diffusion balance", run->c->name, b_theory, A);
    fig = (vfy_xy_figure){.name = name, .title = title, .xlabel = "c = |v|/v0",
                          .comment = run->comment, .npanels = 1, .ylabel = {"ln G"},
                          .ncurves = 1, .curves = levelled};
    rc_io |= vfy_write_xy(run->o, &fig);

    /* y = b x - 2 for b = 1, 1.25, 1.5 and the fit, each through two points */
    static const double slopes[] = {1.0, 1.25, 1.5};
    const double x_lo = 0.0, x_hi = log(v0 * s->steady.c_max);
    double *lx = lines, *ly = lines + 2;   /* 2 x values, then 2 y values per line */
    lx[0] = x_lo;
    lx[1] = x_hi;
    vfy_xy_curve curves[4] = {
        {.label = "y_k (DSMC)", .count = K, .x = x, .y = {y}, .ci = {y_ci}}};
    char labels[3][48];
    for (size_t i = 0; i < 3; i++) {
        ly[2 * i] = slopes[i] * x_lo - 2.0;
        ly[2 * i + 1] = slopes[i] * x_hi - 2.0;
        snprintf(labels[i], sizeof labels[i], "y = %gx - 2", slopes[i]);
        curves[1 + i] = (vfy_xy_curve){.label = labels[i], .reference = 1, .count = 2,
                                       .x = lx, .y = {ly + 2 * i}};
    }
    snprintf(title, sizeof title, "paper A Figs. 7-9: y_k = ln(ln f_1 - ln f_k) against "
             "x_k = ln(r_k - r_1), %s (fitted b = %.3f)", run->c->name, b);
    snprintf(name, sizeof name, "%s-exponent", run->c->name);
    fig = (vfy_xy_figure){.name = name, .title = title, .xlabel = "x_k",
                          .comment = run->comment, .npanels = 1, .ylabel = {"y_k"},
                          .ncurves = 4, .curves = curves};
    rc_io |= vfy_write_xy(run->o, &fig);
    rc_io |= tails_local_slope(run, row, edge, f, fci, K);
    free(buf);
    free(h);
    if (rc_io != 0) {
        snprintf(msg, msglen, "%s: cannot write the figures", run->c->name);
        return SIM_EIO;
    }
    return SIM_OK;
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
    VFY_NAMED_HOOK("grw_tails_figures", grw_tails_figures),
    VFY_NAMED_END};
