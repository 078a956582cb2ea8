/* The accuracy-cost report (SPEC §10, "Work-precision: error against CPU time
 * across (n, N, dt); which n and N reach a given error fastest").
 *
 * cost-grw-ex3, cost-brs-ex2: the scenes of paper A Ex 3 (grw-ex3.ini) and
 * paper B Ex 2 (brs-ex2.ini), both Maxwell kernels, over a grid of n x N.
 * The error is the papers' (SPEC §1): Err = max over the output times t_m of
 * |F(t_m) - eta1(t_m)| / F(t_m), with paper A's uncentred T_raw against
 * (A.13) and paper B's centred T against (B.15).  With E xi^(n)(t) the exact
 * expectation of the n-particle estimator (reference/heated.h,
 * reference/background.h) the error splits exactly at every output time,
 *   eta1 - F = (eta1 - E xi^(n)) + (E xi^(n) - F) = statistical + systematic,
 * and each grid point reports
 *   Err_sys  = max_m |E xi^(n) - F| / F   exact, no noise (O(1/n));
 *   Err_stat = max_m |eta1 - E xi^(n)| / F   measured (O(1/sqrt(n N)));
 *   Conf     = max_m c / F, c = 3.2 sqrt(Var/N), its 99.9% scale;
 * so that |Err - Err_sys| <= Err_stat <= ... and Err <= Err_sys + Err_stat.
 * Model for the whole grid and beyond it: Err ≈ sqrt(Err_sys^2 + (k Conf)^2),
 * with Err_sys exact at every n, Conf^2 N = A/n + B/n^2 (weighted least
 * squares; B carries T_raw's bulk-velocity term, of order 1/n^2 in the
 * variance) and k = the geometric mean of Err_stat / Conf over the grid (the
 * typical largest |z| over the output times, over lambda_p).  The plain sum
 * Err_sys + k Conf was tried too: it is an upper bound, but it overestimated
 * the paper-size grid of cost-grw-ex3 by up to a factor 2 where both parts
 * are comparable, the quadrature sum by at most 1.4 either way.  CPU seconds:
 * cpu = kappa n N (the work of these Maxwell scenes is proportional to n N).
 *
 * cost-split-ex5: the hard-sphere gas of paper A Ex 5 (split-ex5.ini), the
 * time-averaged steady temperature T̄ (steady.h) with the exact jump scheme
 * over n x N and with the time-step scheme (SPEC §10) over h, Euler and
 * Strang.  No exact solution: the reference T̄_inf comes from the jump rows,
 * T̄_jump(n) = T̄_inf + b/n (weighted least squares, its chi^2 judged; T̄_inf
 * is compared with the first-Sonine closure's steady state).  A row's error
 *   T̄ - T̄_inf = (T̄ - E T̄) + (E T̄(h) - E T̄(jump)) + (E T̄(jump) - T̄_inf)
 *              = statistical + splitting + systematic,
 * with systematic = b/n, splitting = c1 h^p + c2 h^(p+1) (p = 1 Euler, 2
 * Strang; weighted least squares of the time-step rows' difference from
 * T̄_inf + b/n, chi^2 judged) and the statistical part the residual.  Model:
 * Err ≈ sqrt((|b/n| + |split|)^2 + (k Conf)^2), k = sqrt(2/pi)/lambda_p
 * (E|Z| of one Gaussian number: right when either part dominates); no credit
 * is taken for the two biases' opposite signs.  CPU seconds: kappa n N (jump), n N (a + g/h) (time step:
 * collisions, and one Gaussian kick per particle and step).
 *
 * Every row's CPU time is res.cpu_seconds of that very run.  Targets 1e-2,
 * 1e-3, 1e-4: the cheapest measured grid point with Err <= target, and the
 * cheapest point the model predicts (n = powers of 2 up to 2^24, N among the
 * grid's, h halvings of the grid's largest), marked as a prediction.
 */
#include "case_cost.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "cases.h"
#include "driver.h"
#include "figure.h"
#include "heated.h"
#include "metrics.h"
#include "scene_ini.h"
#include "scene_refs.h"
#include "steady.h"
#include "table.h"

#define ZMAX 4.5               /* |z| bound for exact expectations and fitted models */
#define MODEL_FACTOR 2.0       /* measured Err within a factor 2 of the model */
#define DOMINANCE 3.0          /* ... where one part is 3 times the other */
#define SONINE_MODEL_RTOL 0.002  /* first-Sonine closure's own error (as grw-ex5) */
#define PRED_N_MAX ((size_t)1 << 24)
#define PRED_H_HALVINGS 12
#define GRID_MAX 64            /* grid points of one case */
#define VFY_COST_TARGETS_TITLE "Cheapest grid point per target, and the model's prediction"
#define AXIS_MAX 8             /* values of n or N on one axis */


/* ------------------------------------------------------------ shared pieces */

size_t vfy_cost_cheapest(const double *err, const double *cost, size_t count, double target)
{
    size_t best = count;
    for (size_t i = 0; i < count; i++) {
        if (!(err[i] <= target) || cost[i] != cost[i])
            continue;
        if (best == count || cost[i] < cost[best]
            || (cost[i] == cost[best] && err[i] < err[best]))   /* a tie: the smaller Err */
            best = i;
    }
    return best;
}

int vfy_cost_lsq2(size_t count, const double *x1, const double *x2, const double *y,
                  const double *w, double c[2], double *chi2)
{
    double s11 = 0, s12 = 0, s22 = 0, s1y = 0, s2y = 0;
    if (count < 2)
        return -1;
    for (size_t i = 0; i < count; i++) {
        s11 += w[i] * x1[i] * x1[i];
        s12 += w[i] * x1[i] * x2[i];
        s22 += w[i] * x2[i] * x2[i];
        s1y += w[i] * x1[i] * y[i];
        s2y += w[i] * x2[i] * y[i];
    }
    double det = s11 * s22 - s12 * s12;
    if (!(fabs(det) > 1e-12 * s11 * s22))   /* also NaN */
        return -1;
    c[0] = (s1y * s22 - s2y * s12) / det;
    c[1] = (s11 * s2y - s12 * s1y) / det;
    if (chi2) {
        *chi2 = 0.0;
        for (size_t i = 0; i < count; i++) {
            double e = y[i] - c[0] * x1[i] - c[1] * x2[i];
            *chi2 += w[i] * e * e;
        }
    }
    return 0;
}

vfy_verdict vfy_cost_check_stat_scaling(vfy_report *r, const char *name, const double *conf1,
                                        const double *conf2, size_t count, size_t N1, size_t N2,
                                        double zmax, double *ratio)
{
    double s = 0.0;
    for (size_t i = 0; i < count; i++)
        s += log(conf1[i] / conf2[i]);
    double R = count ? exp(s / (double)count) / sqrt((double)N2 / (double)N1) : NAN;
    double sd = sqrt((2.0 + VFY_COST_KURTOSIS) / 4.0 * (1.0 / (double)N1 - 1.0 / (double)N2)
                     / (double)count);
    if (ratio)
        *ratio = R;
    /* vfy_check_range fails NaN too (N2 <= N1 gives a NaN sd) */
    return vfy_check_range(r, name, N2 > N1 ? R : NAN, 1.0 - zmax * sd, 1.0 + zmax * sd);
}

vfy_verdict vfy_cost_check_model(vfy_report *r, const char *name, const double *err,
                                 const double *model, size_t count, double factor,
                                 double *worst)
{
    double w = 1.0, wl = 0.0;
    for (size_t i = 0; i < count; i++) {
        double l = fabs(log(err[i] / model[i]));
        if (!(l <= wl)) {   /* NaN becomes the worst, and stays */
            wl = l;
            w = err[i] / model[i];
            if (isnan(l))
                break;
        }
    }
    if (worst)
        *worst = w;
    return vfy_check_range(r, name, w, 1.0 / factor, factor);
}

vfy_verdict vfy_cost_check_chi2(vfy_report *r, const char *name, double chi2, size_t dof)
{
    if (dof < 1) {
        vfy_skip(r, name, "no degrees of freedom left (as many rows as fitted parameters)");
        return VFY_SKIP;
    }
    return vfy_check_range(r, name, chi2, 0.0, gsl_cdf_chisq_Qinv(1e-3, (double)dof));
}

/* ------------------------------------------------------------ helpers */

/* The provenance comment (as vfy_run_comment), without N: the grid sets n
 * and N (and the scheme and h) row by row. */
static const char *grid_comment(const sim_scene *s, char *buf, size_t len)
{
    snprintf(buf, len, "gdsmc %s verify: scene %s, seed %llu, %zu outputs on [0, %g]",
             GDSMC_VERSION, vfy_display_path(s->file), (unsigned long long)s->seed, s->outputs,
             s->t_end);
    return buf;
}

/* Conf from the fitted variance model, Conf^2 N = A/n + B/n^2. */
static double conf_model(const double AB[2], double n, double N)
{
    return sqrt((AB[0] / n + AB[1] / (n * n)) / N);
}

/* Fit Conf^2 N = A/n + B/n^2 to the points (relative least squares); keep
 * B = 0 if the fit would make the variance negative at the smallest n. */
static void fit_conf(size_t count, const double *n, const double *N, const double *conf,
                     double AB[2])
{
    double x1[GRID_MAX] = {0}, x2[GRID_MAX] = {0}, y[GRID_MAX] = {0}, w[GRID_MAX] = {0};
    double n_min = INFINITY;
    for (size_t i = 0; i < count; i++) {
        x1[i] = 1.0 / n[i];
        x2[i] = 1.0 / (n[i] * n[i]);
        y[i] = conf[i] * conf[i] * N[i];
        w[i] = 1.0 / (y[i] * y[i]);
        n_min = fmin(n_min, n[i]);
    }
    if (vfy_cost_lsq2(count, x1, x2, y, w, AB, NULL) != 0 || !(AB[0] > 0.0)
        || !(AB[0] + AB[1] / n_min > 0.0)) {
        double s = 0.0;   /* A alone: the mean of y n, relative weights */
        for (size_t i = 0; i < count; i++)
            s += y[i] * n[i];
        AB[0] = s / (double)count;
        AB[1] = 0.0;
    }
}

/* The targets table's cells for one point, or empty cells. */
static void target_cells(vfy_table *t, int present, const char *scheme, size_t n, size_t N,
                         double h, double err, double cpu)
{
    if (scheme)
        vfy_table_cell(t, "%s", present ? scheme : "");
    vfy_table_number(t, present, "%.0f", (double)n);
    vfy_table_number(t, present, "%.0f", (double)N);
    if (scheme)
        vfy_table_number(t, present && h > 0.0, "%g", h);
    vfy_table_number(t, present, "%.2e", err);
    vfy_table_number(t, present, "%.3g", cpu);
}

/* ------------------------------------------------ Maxwell kernels: n x N */

/* max_m |E xi^(n) - F| / F of the scene at n particles (exact, references):
 * the systematic part of Err, beyond the grid for the predictions. */
static sim_status exact_sys(const char *exact_name, const char *finite_name,
                            const sim_scene *scene, size_t n, double *sys, char *msg,
                            size_t msglen)
{
    sim_scene s = *scene;
    vfy_refs refs;
    sim_error err;
    s.particles.n = n;
    sim_status status = vfy_scene_references(&s, &refs, &err);
    if (status != SIM_OK) {
        vfy_scene_format_error(&s, &err, msg, msglen);
        return status;
    }
    double *buf = malloc(2 * refs.outputs * sizeof *buf);
    if (buf == NULL) {
        snprintf(msg, msglen, "out of memory");
        status = SIM_ENOMEM;
    } else if (!vfy_refs_column(&refs, exact_name, buf)
               || !vfy_refs_column(&refs, finite_name, buf + refs.outputs)) {
        snprintf(msg, msglen, "%s: no %s and %s references for this scene", s.file, exact_name,
                 finite_name);
        status = SIM_EINVAL;
    } else
        *sys = vfy_max_rel_err(buf + refs.outputs, buf, refs.outputs);
    free(buf);
    vfy_refs_free(&refs);
    return status;
}

/* The grid's axes: its distinct n (slowest) and N, in order. */
static size_t grid_axis(const vfy_case_run *run, const char *name, double *axis)
{
    size_t count = 0;
    for (size_t i = 0; i < run->nrows; i++) {
        const double v = vfy_values_get(&run->rows[i].values, name);
        size_t k = 0;
        while (k < count && axis[k] != v)
            k++;
        if (k == count && count < AXIS_MAX)
            axis[count++] = v;
    }
    return count;
}

/* The targets table: the cheapest measured point and the model's
 * prediction per target, and the summary line of the notes. */
static void grid_targets(vfy_case_run *run, size_t P, const double *gn, const double *gN,
                         const double *err, const double *cpu, size_t np, const double *pn,
                         const double *pN, const double *perr, const double *pcost,
                         vfy_wp_prediction *pred, char *summary, size_t len)
{
    static const char *const tcols[] = {
        "target", "grid", "n", "N", "Err", "cpu_s", "predicted_n", "predicted_N",
        "predicted_Err", "predicted_cpu_s"};
    vfy_table *tg = &run->second;
    vfy_table_init(tg, sizeof tcols / sizeof *tcols, tcols);
    summary[0] = '\0';
    for (size_t t = 0; t < VFY_WP_TARGETS; t++) {
        const double target = vfy_wp_targets[t];
        size_t i = vfy_cost_cheapest(err, cpu, P, target);
        size_t j = vfy_cost_cheapest(perr, pcost, np, target);
        if (j < np) {
            pred->cpu[pred->count] = pcost[j];
            pred->err[pred->count] = perr[j];
            snprintf(pred->label[pred->count++], sizeof pred->label[0], "%.0e: n=%.0f N=%.0f",
                     target, pn[j], pN[j]);
        }
        vfy_table_cell(tg, "%.0e", target);
        vfy_table_cell(tg, "%s", i < P ? "reached" : "not reached in the grid");
        target_cells(tg, i < P, NULL, i < P ? (size_t)gn[i] : 0, i < P ? (size_t)gN[i] : 0, 0.0,
                     i < P ? err[i] : NAN, i < P ? cpu[i] : NAN);
        target_cells(tg, j < np, NULL, j < np ? (size_t)pn[j] : 0, j < np ? (size_t)pN[j] : 0,
                     0.0, j < np ? perr[j] : NAN, j < np ? pcost[j] : NAN);
        char line[200];
        if (i < P)
            snprintf(line, sizeof line, "%s%.0e: n = %.0f, N = %.0f (%.3g CPU s)", t ? "; " : "",
                     target, gn[i], gN[i], cpu[i]);
        else if (j < np)
            snprintf(line, sizeof line, "%s%.0e: not in the grid; predicted n = %.0f, N = %.0f "
                     "(%.3g CPU s)", t ? "; " : "", target, pn[j], pN[j], pcost[j]);
        else
            snprintf(line, sizeof line, "%s%.0e: not in the grid nor below n = 2^24", t ? "; "
                     : "", target);
        strncat(summary, line, len - strlen(summary) - 1);
    }
}

/* Grid points as arrays, in row order. */
enum { G_N, G_NN, G_ERR, G_SYS, G_STAT, G_CONF, G_CPU, G_MODEL, G_CONF_FIT, G_ARRAYS };

/* After the grid (vfy_hook_fn): the model Err_model = sqrt(Err_sys^2 + (k
 * Conf_fit)^2) with Conf_fit^2 N = A/n + B/n^2 and k the geometric mean of
 * Err_stat/Conf_fit, cpu = kappa n N; its checks, the targets table and
 * the work-precision figure. */
static sim_status grid_model(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    const char *exact = run->d->needs[0], *finite = run->d->needs[1];
    const char *obs = run->d->checks[0].value;
    const size_t P = run->nrows;
    double ns[AXIS_MAX], Ns[AXIS_MAX];
    const size_t nn = grid_axis(run, "n", ns), nN = grid_axis(run, "N", Ns);
    if (P > GRID_MAX || nn * nN != P) {
        snprintf(msg, msglen, "%s: grid of %zu points, %zu x %zu (allowed up to %d, %d x %d)",
                 run->c->name, P, nn, nN, GRID_MAX, AXIS_MAX, AXIS_MAX);
        return SIM_EINVAL;
    }
    double g[G_ARRAYS][GRID_MAX];
    uint64_t violations = 0;
    static const char *const names[] = {"n", "N", "Err", "Err_sys", "Err_stat", "Conf",
                                        "cpu_s"};
    for (size_t i = 0; i < P; i++) {
        for (size_t k = 0; k < sizeof names / sizeof *names; k++)
            g[k][i] = vfy_values_get(&run->rows[i].values, names[k]);
        violations += (uint64_t)vfy_values_get(&run->rows[i].values, "violations");
    }
    double AB[2], lk = 0.0, work = 0.0, cpu_sum = 0.0;
    fit_conf(P, g[G_N], g[G_NN], g[G_CONF], AB);
    for (size_t i = 0; i < P; i++) {
        g[G_CONF_FIT][i] = conf_model(AB, g[G_N][i], g[G_NN][i]);
        lk += log(g[G_STAT][i] / g[G_CONF_FIT][i]);
        work += g[G_N][i] * g[G_NN][i];
        cpu_sum += g[G_CPU][i];
    }
    const double k = exp(lk / (double)P), kappa = cpu_sum / work;
    double cpu_dev = 0.0, lo = INFINITY, hi = 0.0;
    for (size_t i = 0; i < P; i++) {
        const double model = hypot(g[G_SYS][i], k * g[G_CONF_FIT][i]);
        g[G_MODEL][i] = model;
        vfy_values_set(&run->rows[i].values, "Err_model", model);
        vfy_values_set(&run->rows[i].values, "Err_over_model", g[G_ERR][i] / model);
        lo = fmin(lo, g[G_ERR][i] / model);
        hi = fmax(hi, g[G_ERR][i] / model);
        if (g[G_CPU][i] >= 1.0)   /* shorter runs are dominated by start-up */
            cpu_dev = fmax(cpu_dev, fabs(g[G_CPU][i] / (kappa * g[G_N][i] * g[G_NN][i]) - 1.0));
    }

    /* Checks: the 1/sqrt(N) law of the statistical part, pooled over n for
     * each step of N; the model against the grid; no violations. */
    char name[200];
    for (size_t b = 1; b < nN; b++) {
        double c1[AXIS_MAX], c2[AXIS_MAX], ratio;
        for (size_t a = 0; a < nn; a++) {
            c1[a] = g[G_CONF][a * nN + b - 1];
            c2[a] = g[G_CONF][a * nN + b];
        }
        snprintf(name, sizeof name, "%s Conf(N=%.0f)/Conf(N=%.0f) over sqrt(%.0f/%.0f), pooled "
                 "over n", run->c->name, Ns[b - 1], Ns[b], Ns[b], Ns[b - 1]);
        vfy_cost_check_stat_scaling(r, name, c1, c2, nn, (size_t)Ns[b - 1], (size_t)Ns[b],
                                    ZMAX, &ratio);
    }
    /* Judged where one part dominates (by DOMINANCE): where the two are
     * comparable, noise of the opposite sign can cancel the bias and Err
     * fall far below either, which no smooth model follows. */
    double worst, dom_err[GRID_MAX], dom_model[GRID_MAX];
    size_t ndom = 0;
    for (size_t i = 0; i < P; i++) {
        double a = g[G_SYS][i], b2 = k * g[G_CONF_FIT][i];
        if (fmax(a, b2) >= DOMINANCE * fmin(a, b2)) {
            dom_err[ndom] = g[G_ERR][i];
            dom_model[ndom++] = g[G_MODEL][i];
        }
    }
    snprintf(name, sizeof name, "%s Err/model where one part dominates (%zu of %zu points)",
             run->c->name, ndom, P);
    if (ndom > 0)
        vfy_cost_check_model(r, name, dom_err, dom_model, ndom, MODEL_FACTOR, &worst);
    else
        vfy_skip(r, name, "no grid point where one part dominates");
    snprintf(name, sizeof name, "%s majorant violations (all points)", run->c->name);
    vfy_check_count(r, name, violations, 0);

    /* Predictions: n = n_min 2^j up to 2^24, N among the grid's. */
    enum { PRED_MAX = 32 * AXIS_MAX };
    double perr[PRED_MAX], pcost[PRED_MAX], pn[PRED_MAX], pN[PRED_MAX];
    size_t np = 0;
    sim_status status = SIM_OK;
    for (size_t n = (size_t)ns[0]; n <= PRED_N_MAX && status == SIM_OK; n *= 2) {
        double s;
        status = exact_sys(exact, finite, &run->rows[0].scene, n, &s, msg, msglen);
        for (size_t b = 0; b < nN && np < PRED_MAX && status == SIM_OK; b++, np++) {
            pn[np] = (double)n;
            pN[np] = Ns[b];
            perr[np] = hypot(s, k * conf_model(AB, pn[np], pN[np]));
            pcost[np] = kappa * pn[np] * pN[np];
        }
    }
    if (status != SIM_OK)
        return status;
    char summary[600];
    vfy_wp_prediction pred = {0};
    grid_targets(run, P, g[G_N], g[G_NN], g[G_ERR], g[G_CPU], np, pn, pN, perr, pcost, &pred,
                 summary, sizeof summary);
    if (run->o->progress)
        fprintf(run->o->progress, "   %s: cheapest per target: %s\n", run->c->name, summary);
    const double v[][2] = {{AB[0], 0}, {AB[1], 0}, {k, 0}, {lo, 0}, {hi, 0},
                           {1e6 * kappa, 0}, {100.0 * cpu_dev, 0}};
    static const char *const vnames[] = {"A", "B", "k", "ratio_lo", "ratio_hi", "kappa_us",
                                         "cpu_dev_percent"};
    for (size_t i = 0; i < sizeof vnames / sizeof *vnames; i++)
        vfy_values_set(&run->values, vnames[i], v[i][0]);
    run->second_suffix = "-targets";
    run->second_title = VFY_COST_TARGETS_TITLE;
    snprintf(run->second_notes, sizeof run->second_notes,
             "grid: the cheapest measured point (least cpu_s) with Err <= target, or \"not "
             "reached in the grid\". predicted_*: the cheapest (n, N) by the model above "
             "(a prediction, not a measurement) over n = %.0f 2^j up to 2^24 and N among the "
             "grid's values (%.0f to %.0f). The cost kappa n N is linear in n while Err_sys "
             "falls as 1/n, so at a given n N the model always prefers more particles and "
             "fewer ensembles: the prediction sits at the grid's smallest N, and fewer "
             "ensembles than that would leave Var (and so the confidence interval) poorly "
             "estimated (among powers of two several (n, N) cost the same; the one with the "
             "smaller Err is shown). The model assumes kappa stays constant as n grows beyond the grid "
             "(memory effects are not modelled). Summary: %s.",
             ns[0], Ns[0], Ns[nN - 1], summary);

    vfy_wp_series series[AXIS_MAX];
    size_t idx[AXIS_MAX][AXIS_MAX];
    char labels[GRID_MAX][24], ftitle[200];
    for (size_t b = 0; b < nN; b++) {
        snprintf(series[b].title, sizeof series[b].title, "N = %.0f (n grows)", Ns[b]);
        series[b].count = nn;
        series[b].idx = idx[b];
        for (size_t a = 0; a < nn; a++)
            idx[b][a] = a * nN + b;
    }
    for (size_t i = 0; i < P; i++)
        snprintf(labels[i], sizeof labels[i], "n=%.0f", g[G_N][i]);
    snprintf(ftitle, sizeof ftitle, "%s: Err against CPU time, %s", run->c->name, obs);
    if (vfy_write_work_precision(run->o, run->c->name, ftitle,
                                 "Err (relative, max norm over the output times)", series, nN,
                                 g[G_CPU], g[G_ERR], g[G_MODEL], labels, &pred) != 0)
        return vfy_io_error(run->c->name, msg, msglen);
    return SIM_OK;
}

/* Paper A Ex 3 with Table 1's estimator (uncentred T_raw against A.13); paper
 * B Ex 2 with Table 2's (centred T against B.15).  Paper sizes: about 280 and
 * 230 CPU seconds (sum n x sum N x 4.8 and 3.8 us).  The grid: n by n, N
 * growing within each n.  OBS is the observable, FINITE the exact
 * expectation of its n-particle estimator. */
#define COST_GRID_METRICS(OBS, FINITE)                                                  \
    {{"Err", vfy_metric_max_rel_err, OBS, "T_exact", 0},                                \
     {"Err_sys", vfy_metric_max_rel_err, FINITE, "T_exact", 0},                         \
     {"Err_stat", vfy_metric_max_rel_diff, OBS, FINITE "/T_exact", 0},                  \
     {"Conf", vfy_metric_max_rel_ci, OBS, "T_exact", 0},                                \
     {NULL, NULL, NULL, NULL, 0}}
#define COST_GRID_CHECKS(OBS, FINITE)                                                   \
    {{.name = "{case} n={n} N={N} " OBS " vs exact finite-n expectation",                \
      .rule = vfy_rule_zscore, .value = OBS, .expected = FINITE, .from = 1, .tol = ZMAX,  \
      .out = "z"},                                                                      \
     {.name = NULL}}
static const vfy_column grid_columns[] = {
    {"n", NULL, "%.0f"}, {"N", NULL, "%.0f"}, {"Err", NULL, "%.3e"},
    {"Err_sys", NULL, "%.3e"}, {"Err_stat", NULL, "%.3e"}, {"Conf", NULL, "%.3e"},
    {"z", NULL, "%.2f"}, {"Err_model", NULL, "%.3e"}, {"Err_over_model", NULL, "%.2f"},
    VFY_COST_COLUMN_SPECS, {NULL, NULL, NULL}};
#define COST_GRID_NOTES(OBS, FINITE)                                                    \
    "{comment}; each row sets n and N.\n\nErr = max over the {outputs} output times of "   \
    "|F(t) - eta1(t)|/F(t) for " OBS " (SPEC §1). With E xi^(n)(t) the exact expectation " \
    "of the n-particle estimator (" FINITE ", SPEC §10), eta1 - F = (eta1 - E "        \
    "xi^(n)) + (E xi^(n) - F) at every output time: Err_sys = max |E xi^(n) - F|/F is the " \
    "systematic part, exact (no noise), O(1/n); Err_stat = max |eta1 - E xi^(n)|/F the "   \
    "statistical part as measured, O(1/sqrt(n N)); Conf = max c/F with c = 3.2 "           \
    "sqrt(Var/N) (99.9%) is its scale, and z = max |eta1 - E xi^(n)|/sigma (judged <= "    \
    "4.5). Err <= Err_sys + Err_stat. All points use the scene's seed, so the run with 4N " \
    "ensembles contains the run with N (common random numbers).\n\nModel: Err_model = "    \
    "sqrt(Err_sys^2 + (k Conf_fit)^2), with Err_sys exact at every n, Conf_fit^2 N = A/n + " \
    "B/n^2 fitted to the grid (A = {A:%.4g}, B = {B:%.4g}) and k = {k:%.3f} the geometric " \
    "mean of Err_stat/Conf_fit; measured/model lies in [{ratio_lo:%.2f}, "                 \
    "{ratio_hi:%.2f}] over the grid (judged within a factor 2 where one part is at least " \
    "3 times the other: where they are comparable, noise of the opposite sign can cancel " \
    "the bias). CPU model: cpu = kappa n N with kappa = {kappa_us:%.3g} us (largest "        \
    "deviation {cpu_dev_percent:%.0f}% over the points with at least 1 CPU s). cpu_s is "  \
    "the process CPU time of that point's run (all threads); events = candidate "          \
    "collision events. Total wall time {wall_total:%.1f} s."
#define COST_GRID(SCENE, WHAT, OBS, FINITE, N_PAPER, N_QUICK)                           \
    {.scene = SCENE,                                                                    \
     .paper_rows = {.keys = {"particles.n", "particles.ensembles"},                      \
                    .values = {N_PAPER, "128 512 2048"}, .grid = 1},                     \
     .quick_rows = {.keys = {"particles.n", "particles.ensembles"},                      \
                    .values = {N_QUICK, "64 256"}, .grid = 1},                           \
     .needs = (const char *const[]){"T_exact", FINITE, NULL},                            \
     .needs_why = "the cost grid needs the exact expectation of the n-particle estimator", \
     .label = "{case} n={n} N={ensembles}",                                              \
     .row_progress = "{case} n={n} N={N}: Err {Err:%.3e} (sys {Err_sys:%.3e} exact, stat " \
                     "{Err_stat:%.3e}, Conf {Conf:%.3e}), {cpu_s:%.2f} CPU s",           \
     .metrics = (const vfy_metric[])COST_GRID_METRICS(OBS, FINITE),                     \
     .checks = (const vfy_check_spec[])COST_GRID_CHECKS(OBS, FINITE),                   \
     .columns = grid_columns, .after_rows = grid_model,                                  \
     .title = "{case}: accuracy against CPU cost, " WHAT " ({size} sizes)",              \
     .notes = COST_GRID_NOTES(OBS, FINITE)}
const vfy_case_desc vfy_cost_grw_ex3 =
    COST_GRID("grw-ex3", "paper A Ex 3 (Table 1's Err: uncentred T_raw vs A.13)", "T_raw",
              "T_raw_finite_n", "64 256 1024 4096 16384", "64 256 1024");
const vfy_case_desc vfy_cost_brs_ex2 =
    COST_GRID("brs-ex2", "paper B Ex 2 (Table 2's Err: centred T vs B.15)", "T", "T_finite_n",
              "16 64 256 1024 4096 16384", "16 64 256");

/* ------------------------------------- hard spheres: jump and time step */

typedef struct cost_split_spec {
    sim_scheme scheme;
    sim_splitting split;
    size_t n, N;
    double h;   /* time-step rows */
} cost_split_spec;

struct cost_split_data {
    const char *scene;
    const cost_split_spec *paper, *quick;
    size_t npaper, nquick;
    double quick_t_end;     /* quick sizes: shorter runs */
    size_t quick_outputs;
};

#define J(n, N) {SIM_SCHEME_JUMP, SIM_SPLIT_EULER, n, N, 0.0}
#define E(n, N, h) {SIM_SCHEME_TIMESTEP, SIM_SPLIT_EULER, n, N, h}
#define S(n, N, h) {SIM_SCHEME_TIMESTEP, SIM_SPLIT_STRANG, n, N, h}
/* Paper sizes, about 450 CPU s: the jump scheme over n at N = 256 and 1024
 * (the O(1/n) fit and the reference), Strang at n = 256 and 1024, Euler at
 * n = 1024, h = 0.8 ... 0.1 (3 ... 0.4 mean free times). */
static const cost_split_spec split_paper[] = {
    J(64, 256), J(256, 256), J(1024, 256), J(4096, 256), J(64, 1024), J(256, 1024),
    J(1024, 1024),
    S(256, 256, 0.8), S(256, 256, 0.4), S(256, 256, 0.2), S(256, 256, 0.1),
    S(1024, 256, 0.8), S(1024, 256, 0.4), S(1024, 256, 0.2), S(1024, 256, 0.1),
    E(1024, 256, 0.8), E(1024, 256, 0.4), E(1024, 256, 0.2), E(1024, 256, 0.1),
};
static const cost_split_spec split_quick[] = {
    J(32, 64), J(128, 64), J(512, 64),
    S(128, 64, 1.6), S(128, 64, 0.8), S(128, 64, 0.4),
    E(128, 64, 1.6), E(128, 64, 0.8), E(128, 64, 0.4),
};
#undef J
#undef E
#undef S

const struct cost_split_data vfy_cost_split_ex5 = {
    "split-ex5", split_paper, split_quick, sizeof split_paper / sizeof *split_paper,
    sizeof split_quick / sizeof *split_quick, 16.0, 11,
};

static const char *spec_scheme(const cost_split_spec *s)
{
    return s->scheme == SIM_SCHEME_JUMP ? "jump"
           : s->split == SIM_SPLIT_STRANG ? "strang" : "euler";
}

/* The splitting model c1 h^p + c2 h^(p+1). */
static double split_model(const double c[2], sim_splitting split, double h)
{
    double p = split == SIM_SPLIT_STRANG ? 2.0 : 1.0;
    return c[0] * pow(h, p) + c[1] * pow(h, p + 1.0);
}

/* The parts of a row's Err, known once every row is in (relative to T_inf). */
typedef struct split_parts {
    double err, err_hi, sys, split, stat, conf, split_meas, split_meas_ci, model;
} split_parts;

/* One row of the cost-split table; parts NULL: not known yet, those cells
 * empty. */
static void split_point_row(vfy_table *t, const cost_split_spec *spec, double T, double Tci,
                            const split_parts *parts, double cpu, double wall,
                            const sim_counts *counts)
{
    const int ts = spec->scheme == SIM_SCHEME_TIMESTEP, known = parts != NULL;
    const split_parts none = {0};
    const split_parts *q = known ? parts : &none;
    const double coll = (double)counts->collisions;
    vfy_table_cell(t, "%s", spec_scheme(spec));
    vfy_table_cell(t, "%zu", spec->n);
    vfy_table_cell(t, "%zu", spec->N);
    vfy_table_number(t, ts, "%g", spec->h);
    vfy_table_cell(t, "%.6f", T);
    vfy_table_cell(t, "%.6f", Tci);
    vfy_table_number(t, known, "%.3e", q->err);
    vfy_table_number(t, known, "%.3e", q->err_hi);
    vfy_table_number(t, known, "%.3e", q->sys);
    vfy_table_number(t, known && ts, "%.3e", q->split);
    vfy_table_number(t, known, "%.3e", q->stat);
    vfy_table_number(t, known, "%.3e", q->conf);
    vfy_table_number(t, known && ts, "%+.3e", q->split_meas);
    vfy_table_number(t, known && ts, "%.2e", q->split_meas_ci);
    vfy_table_number(t, known, "%.3e", q->model);
    vfy_table_cell(t, "%.2f", cpu);
    vfy_table_cell(t, "%.2f", wall);
    vfy_table_cell(t, "%llu", (unsigned long long)counts->candidates);
    vfy_table_cell(t, "%llu", (unsigned long long)counts->collisions);
    vfy_table_cell(t, "%llu", (unsigned long long)counts->normals);
    vfy_table_cell(t, "%.1f", coll > 0 ? 1e9 * cpu / coll : 0.0);
}

sim_status vfy_case_cost_split(const vfy_case *c, const vfy_options *o, vfy_report *r,
                               char *msg, size_t msglen)
{
    const struct cost_split_data *d = c->data;
    const cost_split_spec *spec = o->size == VFY_PAPER ? d->paper : d->quick;
    const size_t P = o->size == VFY_PAPER ? d->npaper : d->nquick;
    sim_scene scene, solver;
    sim_status status = vfy_load_scene_stem(d->scene, o, &scene, &solver, msg, msglen);
    if (status != SIM_OK)
        return status;
    if (!scene.steady.present) {
        snprintf(msg, msglen, "%s: the cost case needs [steady] (time averages)", scene.file);
        return SIM_EINVAL;
    }
    if (P == 0 || P > GRID_MAX) {
        snprintf(msg, msglen, "%s: %zu rows (allowed 1 to %d)", c->name, P, GRID_MAX);
        return SIM_EINVAL;
    }
    if (o->size == VFY_QUICK) {
        sim_scene *both[] = {&scene, &solver};
        for (int i = 0; i < 2; i++) {
            both[i]->t_end = d->quick_t_end;
            both[i]->outputs = d->quick_outputs;
        }
    }

    static const char *const cols[] = {
        "scheme", "n", "N", "h", "T", "T_ci", "Err", "Err_hi", "Err_sys", "Err_split",
        "Err_stat",
        "Conf", "split_meas", "split_meas_ci", "Err_model", "cpu_s", "wall_s", "candidates",
        "collisions", "normals", "ns_per_collision"};
    static const char *const tcols[] = {
        "target", "grid", "scheme", "n", "N", "h", "Err_hi", "cpu_s", "predicted_scheme",
        "predicted_n", "predicted_N", "predicted_h", "predicted_Err", "predicted_cpu_s"};
    vfy_table table, tg;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    vfy_table_init(&tg, sizeof tcols / sizeof *tcols, tcols);

    double T[GRID_MAX], Tci[GRID_MAX], cpu[GRID_MAX], wall[GRID_MAX], gn[GRID_MAX];
    double gN[GRID_MAX];
    sim_counts counts[GRID_MAX];
    uint64_t violations = 0;
    char name[200], label[120];
    for (size_t i = 0; i < P && status == SIM_OK; i++) {
        /* jump rows simulate the scene as the references see it, time-step
         * rows the solver's (--solver-set changes only these), as split-ex5 */
        sim_scene s = spec[i].scheme == SIM_SCHEME_JUMP ? scene : solver;
        s.scheme = spec[i].scheme;
        s.splitting = spec[i].split;
        if (spec[i].scheme == SIM_SCHEME_TIMESTEP)
            s.dt = spec[i].h;
        s.particles.n = spec[i].n;
        s.particles.ensembles = spec[i].N;
        if (spec[i].scheme == SIM_SCHEME_JUMP)
            snprintf(label, sizeof label, "%s jump n=%zu N=%zu", c->name, spec[i].n,
                     spec[i].N);
        else
            snprintf(label, sizeof label, "%s %s h=%g n=%zu N=%zu", c->name, spec_scheme(&spec[i]),
                     spec[i].h, spec[i].n, spec[i].N);
        sim_ensemble_result res;
        if ((status = vfy_simulate(&s, o, label, &res, msg, msglen)) == SIM_OK) {
            T[i] = sim_result_steady_mean(&res, SIM_STEADY_T);
            Tci[i] = sim_result_steady_ci(&res, SIM_STEADY_T);
            cpu[i] = res.cpu_seconds;
            wall[i] = res.wall_seconds;
            counts[i] = res.counts;
            gn[i] = (double)spec[i].n;
            gN[i] = (double)spec[i].N;
            violations += res.counts.violations;
            if (o->progress)
                fprintf(o->progress, "   %s: T̄ = %.6f ± %.6f, %.2f CPU s\n", label, T[i],
                        Tci[i], cpu[i]);
            /* rows so far; the parts of Err need the fits over all rows */
            split_point_row(&table, &spec[i], T[i], Tci[i], NULL, cpu[i], wall[i], &counts[i]);
            status = vfy_write_rows_so_far(o, c->name, &table, &solver, msg, msglen);
        }
        sim_ensemble_result_free(&res);
    }
    if (status != SIM_OK)
        goto done;
    vfy_check_count(r, vfy_name(name, sizeof name, "%s majorant violations (all rows)",
                                c->name), violations, 0);

    /* The reference: T̄_jump(n) = T̄_inf + b/n, weighted least squares. */
    double x[GRID_MAX], y[GRID_MAX], w[GRID_MAX];
    size_t nj = 0;
    for (size_t i = 0; i < P; i++) {
        if (spec[i].scheme != SIM_SCHEME_JUMP)
            continue;
        double sigma = Tci[i] / SIM_LAMBDA_P;
        x[nj] = 1.0 / gn[i];
        y[nj] = T[i];
        w[nj++] = 1.0 / (sigma * sigma);
    }
    double T_inf, b, cov00, cov01, cov11, chi2_jump;
    if (nj < 2 || gsl_fit_wlinear(x, 1, w, 1, y, 1, nj, &T_inf, &b, &cov00, &cov01, &cov11,
                                  &chi2_jump) != 0) {
        snprintf(msg, msglen, "%s: the O(1/n) fit needs jump rows at two n at least", c->name);
        status = SIM_EINVAL;
        goto done;
    }
    const double T_inf_ci = SIM_LAMBDA_P * sqrt(cov00);
    vfy_cost_check_chi2(r, vfy_name(name, sizeof name, "%s jump rows: O(1/n) fit chi^2 (%zu "
                                    "rows)", c->name, nj), chi2_jump, nj - 2);
    ref_heated_params hp = vfy_heated_params(&scene);
    const double T_sonine = ref_heated_hs_T_steady(&hp, REF_HEATED_SONINE_CLOSURE);
    vfy_check_absolute(r, vfy_name(name, sizeof name, "%s T_inf (n -> infinity) vs "
                                   "first-Sonine steady T", c->name),
                       T_inf, T_sonine, T_inf_ci + SONINE_MODEL_RTOL * T_sonine);

    /* The splitting error of each splitting: d = T̄ - (T̄_inf + b/n) against
     * c1 h^p + c2 h^(p+1), with the variance of the row and of the fit. */
    double csplit[2][2] = {{0, 0}, {0, 0}}, dsplit[GRID_MAX], dsplit_ci[GRID_MAX];
    int have_split[2] = {0, 0};
    for (int sp = 0; sp < 2; sp++) {
        const sim_splitting split = sp ? SIM_SPLIT_STRANG : SIM_SPLIT_EULER;
        const double p = sp ? 2.0 : 1.0;
        double x1[GRID_MAX], x2[GRID_MAX], ds[GRID_MAX], ws[GRID_MAX], chi2;
        size_t m = 0;
        for (size_t i = 0; i < P; i++) {
            if (spec[i].scheme != SIM_SCHEME_TIMESTEP || spec[i].split != split)
                continue;
            double sigma = Tci[i] / SIM_LAMBDA_P, xn = 1.0 / gn[i];
            double var = sigma * sigma + cov00 + 2.0 * cov01 * xn + cov11 * xn * xn;
            dsplit[i] = T[i] - (T_inf + b * xn);
            dsplit_ci[i] = SIM_LAMBDA_P * sqrt(var);
            x1[m] = pow(spec[i].h, p);
            x2[m] = pow(spec[i].h, p + 1.0);
            ds[m] = dsplit[i];
            ws[m++] = 1.0 / var;
        }
        if (m == 0)
            continue;
        vfy_name(name, sizeof name, "%s %s: splitting-error fit c1 h^%g + c2 h^%g, chi^2 "
                 "(%zu rows)", c->name, sp ? "strang" : "euler", p, p + 1.0, m);
        if (vfy_cost_lsq2(m, x1, x2, ds, ws, csplit[sp], &chi2) != 0) {
            vfy_skip(r, name, "fewer than two distinct steps: no fit");
            continue;
        }
        have_split[sp] = 1;
        vfy_cost_check_chi2(r, name, chi2, m - 2);
    }

    /* Parts, model and the residual z-test of every row. */
    double err[GRID_MAX], sys[GRID_MAX], spl[GRID_MAX], stat[GRID_MAX], conf[GRID_MAX];
    double model[GRID_MAX], fit_mean[GRID_MAX], conf_fit[GRID_MAX], err_hi[GRID_MAX];
    double AB[2];
    for (size_t i = 0; i < P; i++)
        conf[i] = Tci[i] / T_inf;
    fit_conf(P, gn, gN, conf, AB);
    const double k_scalar = sqrt(2.0 / M_PI) / SIM_LAMBDA_P;   /* E|Z| in units of Conf */
    for (size_t i = 0; i < P; i++) {
        const int ts = spec[i].scheme == SIM_SCHEME_TIMESTEP;
        const int sp = spec[i].split == SIM_SPLIT_STRANG;
        double split_signed = ts && have_split[sp] ? split_model(csplit[sp], spec[i].split,
                                                                 spec[i].h) : 0.0;
        fit_mean[i] = T_inf + b / gn[i] + split_signed;
        err[i] = fabs(T[i] - T_inf) / T_inf;
        /* the reference is itself measured: Err's 99.9% upper bound */
        err_hi[i] = err[i] + hypot(Tci[i], T_inf_ci) / T_inf;
        sys[i] = fabs(b / gn[i]) / T_inf;
        spl[i] = fabs(split_signed) / T_inf;
        stat[i] = fabs(T[i] - fit_mean[i]) / T_inf;
        conf_fit[i] = conf_model(AB, gn[i], gN[i]);
        model[i] = hypot(sys[i] + spl[i], k_scalar * conf_fit[i]);
    }
    double zmax;
    vfy_check_zscore(r, vfy_name(name, sizeof name, "%s every row vs the fitted model "
                                 "T_inf + b/n + splitting", c->name),
                     T, Tci, fit_mean, P, ZMAX, &zmax);

    /* Cost: kappa n N for the jump rows; n N (a + g/h) for the time-step rows. */
    double kappa_num = 0.0, kappa_den = 0.0, ag[2] = {NAN, 0.0};
    {
        double one[GRID_MAX], inv_h[GRID_MAX], per[GRID_MAX], wc[GRID_MAX];
        size_t m = 0;
        for (size_t i = 0; i < P; i++) {
            if (spec[i].scheme == SIM_SCHEME_JUMP) {
                kappa_num += cpu[i];
                kappa_den += gn[i] * gN[i];
                continue;
            }
            one[m] = 1.0;
            inv_h[m] = 1.0 / spec[i].h;
            per[m] = cpu[i] / (gn[i] * gN[i]);
            wc[m] = 1.0 / (per[m] * per[m]);
            m++;
        }
        if (m > 0 && (vfy_cost_lsq2(m, one, inv_h, per, wc, ag, NULL) != 0 || !(ag[1] >= 0.0)
                      || !(ag[0] > 0.0))) {
            double s = 0.0;
            for (size_t i = 0; i < m; i++)
                s += per[i];
            ag[0] = s / (double)m;
            ag[1] = 0.0;
        }
    }
    const double kappa = kappa_num / kappa_den;

    vfy_table_free(&table);   /* the rows again, now with the fitted parts */
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    for (size_t i = 0; i < P; i++) {
        const int ts = spec[i].scheme == SIM_SCHEME_TIMESTEP;
        const split_parts parts = {err[i], err_hi[i], sys[i], spl[i], stat[i], conf[i],
                                   ts ? dsplit[i] / T_inf : 0.0, ts ? dsplit_ci[i] / T_inf : 0.0,
                                   model[i]};
        split_point_row(&table, &spec[i], T[i], Tci[i], &parts, cpu[i], wall[i], &counts[i]);
    }

    /* Predictions over n = n_min 2^j, N among the grid's, and the jump scheme
     * or a splitting at h = h_max 2^-j (h_max the largest step of the grid). */
    size_t Nvals[GRID_MAX], nNv = 0;
    double n_min = INFINITY, h_max = 0.0;
    for (size_t i = 0; i < P; i++) {
        size_t v = 0;
        while (v < nNv && Nvals[v] != spec[i].N)
            v++;
        if (v == nNv)
            Nvals[nNv++] = spec[i].N;
        n_min = fmin(n_min, gn[i]);
        if (spec[i].scheme == SIM_SCHEME_TIMESTEP)
            h_max = fmax(h_max, spec[i].h);
    }
    enum { PRED_MAX = 4096 };
    double *perr = malloc(PRED_MAX * sizeof *perr), *pcost = malloc(PRED_MAX * sizeof *pcost);
    double *pn = malloc(PRED_MAX * sizeof *pn), *pN = malloc(PRED_MAX * sizeof *pN);
    double *ph = malloc(PRED_MAX * sizeof *ph);
    int *pscheme = malloc(PRED_MAX * sizeof *pscheme);   /* 0 jump, 1 euler, 2 strang */
    size_t np = 0;
    if (!perr || !pcost || !pn || !pN || !ph || !pscheme) {
        snprintf(msg, msglen, "out of memory");
        status = SIM_ENOMEM;
        goto pred_done;
    }
    for (double n = n_min; n <= (double)PRED_N_MAX; n *= 2.0) {
        for (size_t v = 0; v < nNv; v++) {
            const double N = (double)Nvals[v], cstat = k_scalar * conf_model(AB, n, N);
            const double sys_n = fabs(b / n) / T_inf;
            for (int sch = 0; sch < 3 && np < PRED_MAX; sch++) {
                if (sch > 0 && !have_split[sch - 1])
                    continue;
                for (int j = 0; j <= (sch ? PRED_H_HALVINGS : 0) && np < PRED_MAX; j++) {
                    double h = sch ? h_max / (double)(1u << j) : 0.0;
                    double s = sch ? fabs(split_model(csplit[sch - 1],
                                                      sch == 2 ? SIM_SPLIT_STRANG
                                                               : SIM_SPLIT_EULER, h)) / T_inf
                                   : 0.0;
                    pn[np] = n;
                    pN[np] = N;
                    ph[np] = h;
                    pscheme[np] = sch;
                    perr[np] = hypot(sys_n + s, cstat);
                    pcost[np] = n * N * (sch ? ag[0] + ag[1] / h : kappa);
                    np++;
                }
            }
        }
    }
    static const char *const scheme_names[] = {"jump", "euler", "strang"};
    char summary[900] = "", line[240];
    vfy_wp_prediction pred = {0};
    for (size_t t = 0; t < VFY_WP_TARGETS; t++) {
        size_t i = vfy_cost_cheapest(err_hi, cpu, P, vfy_wp_targets[t]);
        size_t j = vfy_cost_cheapest(perr, pcost, np, vfy_wp_targets[t]);
        if (j < np) {
            pred.cpu[pred.count] = pcost[j];
            pred.err[pred.count] = perr[j];
            if (pscheme[j])
                snprintf(pred.label[pred.count++], sizeof pred.label[0], "%.0e: %s n=%.0f "
                         "N=%.0f h=%g", vfy_wp_targets[t], scheme_names[pscheme[j]], pn[j], pN[j],
                         ph[j]);
            else
                snprintf(pred.label[pred.count++], sizeof pred.label[0], "%.0e: jump n=%.0f "
                         "N=%.0f", vfy_wp_targets[t], pn[j], pN[j]);
        }
        vfy_table_cell(&tg, "%.0e", vfy_wp_targets[t]);
        vfy_table_cell(&tg, "%s", i < P ? "reached" : "not reached in the grid");
        target_cells(&tg, i < P, i < P ? spec_scheme(&spec[i]) : "", i < P ? spec[i].n : 0,
                     i < P ? spec[i].N : 0, i < P ? spec[i].h : 0.0, i < P ? err_hi[i] : NAN,
                     i < P ? cpu[i] : NAN);
        target_cells(&tg, j < np, j < np ? scheme_names[pscheme[j]] : "",
                     j < np ? (size_t)pn[j] : 0, j < np ? (size_t)pN[j] : 0,
                     j < np ? ph[j] : 0.0, j < np ? perr[j] : NAN, j < np ? pcost[j] : NAN);
        char hs[32] = "";
        if (i < P && spec[i].h > 0.0)
            snprintf(hs, sizeof hs, ", h = %g", spec[i].h);
        else if (i == P && j < np && ph[j] > 0.0)
            snprintf(hs, sizeof hs, ", h = %g", ph[j]);
        if (i < P)
            snprintf(line, sizeof line, "%s%.0e: %s n = %zu, N = %zu%s (%.3g CPU s)",
                     t ? "; " : "", vfy_wp_targets[t], spec_scheme(&spec[i]), spec[i].n, spec[i].N,
                     hs, cpu[i]);
        else if (j < np)
            snprintf(line, sizeof line, "%s%.0e: not in the grid; predicted %s n = %.0f, "
                     "N = %.0f%s (%.3g CPU s)", t ? "; " : "", vfy_wp_targets[t],
                     scheme_names[pscheme[j]], pn[j], pN[j], hs, pcost[j]);
        else
            snprintf(line, sizeof line, "%s%.0e: not in the grid nor below n = 2^24",
                     t ? "; " : "", vfy_wp_targets[t]);
        strncat(summary, line, sizeof summary - strlen(summary) - 1);
    }
    if (o->progress)
        fprintf(o->progress, "   %s: T_inf = %.6f ± %.6f (Sonine %.6f); cheapest per target: "
                "%s\n", c->name, T_inf, T_inf_ci, T_sonine, summary);

    double wall_total = 0.0, cand[2] = {0, 0}, coll[2] = {0, 0};
    for (size_t i = 0; i < P; i++) {
        const int ts = spec[i].scheme == SIM_SCHEME_TIMESTEP;
        wall_total += wall[i];
        cand[ts] += (double)counts[i].candidates;
        coll[ts] += (double)counts[i].collisions;
    }
    char comment[600], notes[5000], tnotes[1600], title[200];
    grid_comment(&solver, comment, sizeof comment);
    snprintf(title, sizeof title, "%s: accuracy against CPU cost with the time step as a third "
             "axis, paper A Ex 5's hard spheres (%s sizes)", c->name,
             o->size == VFY_PAPER ? "paper" : "quick");
    snprintf(notes, sizeof notes,
             "%s; every row sets n, N, the scheme and h.\n\nT = T̄, each ensemble's time "
             "average of the centred temperature over the output times t in [%g, %g] (steady "
             "state; steady.h), T_ci = 3.2 x its standard error over the N ensembles. "
             "Reference: T̄_inf = %.6f ± %.6f (99.9%%), with b = %.4f, from the weighted "
             "least squares T̄_jump(n) = T̄_inf + b/n over the %zu jump rows (chi^2 %.2f); "
             "the first-Sonine closure's steady T is %.6f (SPEC §3 Ex 5). Err = |T̄ - "
             "T̄_inf|/T̄_inf, and Err_hi = Err + sqrt(T_ci^2 + T̄_inf's half-width^2)/T̄_inf its "
             "99.9%% upper bound (the reference is measured too); its parts: Err_sys = |b/n|/T̄_inf (the O(1/n) bias), "
             "Err_split = |c1 h^p + c2 h^(p+1)|/T̄_inf (the splitting error, fitted to the "
             "time-step rows: Euler p = 1, c1 = %.4g, c2 = %.4g; Strang p = 2, c1 = %.4g, "
             "c2 = %.4g), Err_stat = |T̄ - (T̄_inf + b/n + splitting)|/T̄_inf (the "
             "residual: statistical), Conf = T_ci/T̄_inf; split_meas = (T̄ - T̄_inf - "
             "b/n)/T̄_inf as measured, with its half-width (row and fit). Every row's T̄ "
             "lies within |z| <= %.2f of the fitted model. Err_model = sqrt((Err_sys + "
             "Err_split)^2 + (k Conf_fit)^2), k = sqrt(2/pi)/3.2 (the mean |z| of one "
             "Gaussian), Conf_fit^2 N = A/n + B/n^2 (A = %.4g, B = %.4g); the O(1/n) bias "
             "is negative and the splitting error positive here, so the measured Err of a "
             "time-step row can fall below the model by their cancellation, for which the "
             "model takes no credit. The reference's own half-width (%.1e relative) bounds "
             "how small an Err this grid can resolve.\n\nCPU: kappa n N with kappa = %.3g us "
             "for the jump rows; n N (a + g/h) with a = %.3g us and g = %.3g us for the "
             "time-step rows (collisions by paper C's contact rule, and one Gaussian kick "
             "per particle and step); candidates per accepted collision: %.1f (jump rows), "
             "%.1f (time-step rows). Total wall time %.1f s.",
             comment, scene.steady.from, scene.t_end, T_inf, T_inf_ci, b, nj, chi2_jump,
             T_sonine, csplit[0][0], csplit[0][1], csplit[1][0], csplit[1][1], zmax, AB[0],
             AB[1], T_inf_ci / T_inf, 1e6 * kappa, 1e6 * ag[0], 1e6 * ag[1],
             cand[0] / coll[0], cand[1] / coll[1], wall_total);
    snprintf(tnotes, sizeof tnotes,
             "grid: the cheapest measured row (least cpu_s) whose Err_hi <= target (reached "
             "with 99.9%% confidence: a small Err by itself may be luck, or the O(1/n) and "
             "splitting biases cancelling, and the reference's own half-width is %.1e), or "
             "\"not reached in the grid\". predicted_*: the cheapest (scheme, n, N, h) by the model above (a "
             "prediction, not a measurement) over n = %.0f 2^j up to 2^24, N among the "
             "grid's values and h = %g 2^-j (j <= %d). As for the Maxwell cases, cost linear "
             "in n N and a bias falling as 1/n favour many particles and few ensembles. The "
             "jump scheme has no splitting error; per particle and ensemble it costs %.3g us "
             "here, the time-step scheme %.3g us at h = %g and %.3g us at h = %g (the model "
             "a + g/h), so the time step pays off only where its step is large enough to be "
             "cheaper and small enough for the target. Summary: %s.",
             T_inf_ci / T_inf, n_min, h_max, PRED_H_HALVINGS, 1e6 * kappa,
             1e6 * (ag[0] + ag[1] / h_max), h_max,
             1e6 * (ag[0] + ag[1] * (double)(1u << PRED_H_HALVINGS) / h_max),
             h_max / (double)(1u << PRED_H_HALVINGS), summary);
    if ((status = vfy_write_case_tables2(o, c->name, &table, comment, title, notes, &tg,
                                        "-targets", VFY_COST_TARGETS_TITLE, tnotes, msg,
                                        msglen)) != SIM_OK)
        goto pred_done;

    /* The figure: the jump rows by N (n grows), the time-step rows by
     * (splitting, n, N) (h shrinks). */
    vfy_wp_series series[GRID_MAX];
    size_t idx[GRID_MAX][GRID_MAX];
    char labels[GRID_MAX][24];
    size_t nseries = 0;
    for (size_t i = 0; i < P; i++) {
        size_t s = 0;
        for (; s < nseries; s++) {
            const cost_split_spec *q = &spec[idx[s][0]];
            if (q->scheme == spec[i].scheme && q->N == spec[i].N
                && (q->scheme == SIM_SCHEME_JUMP || (q->split == spec[i].split
                                                     && q->n == spec[i].n)))
                break;
        }
        if (s == nseries) {
            series[s].count = 0;
            series[s].idx = idx[s];
            if (spec[i].scheme == SIM_SCHEME_JUMP)
                snprintf(series[s].title, sizeof series[s].title, "jump, N = %zu (n grows)",
                         spec[i].N);
            else
                snprintf(series[s].title, sizeof series[s].title, "%s, n = %zu, N = %zu "
                         "(h shrinks)", spec_scheme(&spec[i]), spec[i].n, spec[i].N);
            nseries++;
        }
        idx[s][series[s].count++] = i;
        if (spec[i].scheme == SIM_SCHEME_JUMP)
            snprintf(labels[i], sizeof labels[i], "n=%zu", spec[i].n);
        else
            snprintf(labels[i], sizeof labels[i], "h=%g", spec[i].h);
    }
    char ftitle[200];
    snprintf(ftitle, sizeof ftitle, "%s: Err of the time-averaged T against CPU time", c->name);
    if (vfy_write_work_precision(o, c->name, ftitle,
                                 "Err = |T - T_inf| / T_inf (time-averaged T)", series, nseries,
                                 cpu, err, model, labels, &pred)
        != 0)
        status = vfy_io_error(c->name, msg, msglen);
pred_done:
    free(perr);
    free(pcost);
    free(pn);
    free(pN);
    free(ph);
    free(pscheme);
done:
    vfy_table_free(&table);
    vfy_table_free(&tg);
    return status;
}
