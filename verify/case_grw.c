/* Paper A (Gamba, Rjasanow, Wagner 2003): the uniformly heated granular gas
 * with the exact jump scheme (SPEC §3).
 *
 * grw-ex3, grw-ex4: Tables 1 and 2.  Emax = max_m |T(t_m) - eta1(t_m)| / T(t_m)
 * with paper A's uncentred estimator T_raw (SPEC §1), against the closed form
 * (A.13); CF = Emax(previous row) / Emax.  Beyond the paper, each row's mean
 * is z-tested at every output time against the exact expectation of the
 * n-particle estimator (reference/heated.h), which separates the O(1/n) bias
 * from noise exactly.
 *
 * grw-ex5: hard spheres.  No exact solution: the DSMC temperature for each n,
 * its O(1/n) extrapolation to n = infinity (weighted least squares in 1/n at
 * every output time), and both closures of SPEC §3 Ex 5.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "driver.h"
#include "metrics.h"
#include "tolerances.h"


/* grw-ex3, grw-ex4 (paper A Tables 1 and 2): the same description but for
 * the paper's numbers (SPEC §3 Ex 3, Ex 4). */
static const char *const grw_needs[] = {"T_exact", "T_finite_n", "T_raw_finite_n", NULL};
static const vfy_metric grw_metrics[] = {
    {"Emax", vfy_metric_max_rel_err, "T_raw", "T_exact", 0},
    {"noise", vfy_metric_max_rel_ci, "T_raw", "T_exact", 0},
    {"Emax_T", vfy_metric_max_rel_err, "T", "T_exact", 0},
    {"V_inf", vfy_metric_max_velocity, NULL, NULL, 0},
    {"CF", vfy_metric_ratio_previous, "Emax", NULL, 0},
    {NULL, NULL, NULL, NULL, 0}};
static const vfy_check_spec grw_checks[] = {
    {.name = "{case} n={n} Emax vs paper {paper}", .rule = vfy_rule_relative, .value = "Emax",
     .expected = "Emax_paper", .tol = VFY_TOL_GRW_PAPER_RTOL,
     .guard = {vfy_guard_at_most, "n", NULL, 4096,
               "n > 4096: the paper's own statistical error is comparable to its Emax"}},
    {.name = "{case} n={n} CF", .rule = vfy_rule_range, .value = "CF",
     .lo = VFY_TOL_GRW_CF_LO, .hi = VFY_TOL_GRW_CF_HI,
     .guard = {vfy_guard_clean_pair, "Emax", "noise", VFY_TOL_GRW_CLEAN_RATIO,
               "statistical error not well below Err (Emax {Emax:%.3g}, largest ci/T "
               "{noise:%.3g}): CF {CF:%.3g} not judged"}},
    {.name = "{case} n={n} T_raw vs exact finite-n expectation", .rule = vfy_rule_zscore,
     .value = "T_raw", .expected = "T_raw_finite_n", .from = 1, .tol = VFY_TOL_ZMAX,
     .out = "z_T_raw"},
    {.name = "{case} n={n} T vs exact finite-n expectation", .rule = vfy_rule_zscore,
     .value = "T", .expected = "T_finite_n", .from = 1, .tol = VFY_TOL_ZMAX, .out = "z_T"},
    {.name = NULL}};
static const char grw_columns[] =
    "n:%.0f N:%.0f Emax:%.3e Emax_paper:%.3e CF:%.2f CF_paper:%.2f V_inf:%.3e "
    "V_inf_paper:%.3e Emax_T:%.3e noise:%.3e z_T_raw:%.2f z_T:%.2f "
    VFY_COST_COLUMNS;
#define GRW_TABLE(LABEL, PAPER)                                                         \
    {.paper = LABEL,                                                                  \
     .paper_rows = {.keys = {"particles.n"}, .values = {"64 256 1024 4096 16384"}},   \
     .quick_rows = {.keys = {"particles.n"},                                          \
                    .values = {"64 256 1024"},                                        \
                    .sets = "particles.ensembles=2000"},                              \
     .needs = grw_needs, .needs_why = VFY_NEEDS_MAXWELL, .paper_columns = PAPER,      \
     .metrics = grw_metrics, .checks = grw_checks, .columns = grw_columns,           \
     .figures = {{.kind = VFY_FIGURE_CURVES, .quantity = "T_raw", .refs = {"T_exact"},  \
                  .x_from = 2.0, .panel_per_row = 1}},                                \
     .title = "{case}: paper A {paper} reproduced ({size} sizes)", .notes = grw_notes}
static const char grw_notes[] =
    "{comment}.\n\nEmax = max over the {outputs} output times of |T(t) - eta1(t)|/T(t), with "
    "paper A's uncentred estimator T_raw = (1/3n) Σ|v_i|^2 and T(t) from (A.13); Emax_T uses "
    "the centred T instead. CF = Emax(previous row)/Emax. V_inf = max_m |eta1 of V(t_m)|. "
    "noise = max_m c/T(t_m) with c = 3.2 sqrt(Var/N), the confidence half-width (the paper's "
    "Conf band is 2c wide). z_T_raw, z_T = max_m |eta1 - E xi^(n)|/sigma against the exact "
    "expectation of the n-particle estimator (Maxwell molecules; SPEC §10). events = candidate "
    "collisions (all accepted for Maxwell molecules); cpu_s is process CPU time over all "
    "threads. Total wall time {wall_total:%.1f} s.";
static const vfy_paper_column grw_table1[] = {
    VFY_PAPER_COLUMN("Emax_paper", 0.895e-01, 0.235e-01, 0.571e-02, 0.150e-02, 0.305e-03),
    VFY_PAPER_COLUMN("CF_paper", NAN, 3.81, 4.11, 3.81, 4.92),
    VFY_PAPER_COLUMN("V_inf_paper", 0.672e-02, 0.516e-02, 0.211e-02, 0.141e-02, 0.355e-03),
    {NULL, 0, NULL}};
static const vfy_paper_column grw_table2[] = {
    VFY_PAPER_COLUMN("Emax_paper", 0.130e-00, 0.336e-01, 0.823e-02, 0.211e-02, 0.455e-03),
    VFY_PAPER_COLUMN("CF_paper", NAN, 3.87, 4.08, 3.90, 4.64),
    VFY_PAPER_COLUMN("V_inf_paper", 0.306e-02, 0.188e-02, 0.874e-02, 0.581e-02, 0.148e-02),
    {NULL, 0, NULL}};
const vfy_case_desc vfy_grw_ex3 = GRW_TABLE("Table 1", grw_table1);
const vfy_case_desc vfy_grw_ex4 = GRW_TABLE("Table 2", grw_table2);

/* grw-ex5 (SPEC §3 Ex 5): heated hard spheres; no exact solution, so the
 * rows are extrapolated to n = infinity at every output time and compared
 * with both closures. */
static const vfy_metric ex5_metrics[] = {
    {"dev_maxwell_closure", vfy_metric_max_ratio_dev, "T", "T_maxwell_closure", 0},
    {"dev_sonine_closure", vfy_metric_max_ratio_dev, "T", "T_sonine_closure", 0},
    {"T_end", vfy_metric_final_mean, "T", NULL, 0},
    {"T_end_ci", vfy_metric_final_ci, "T", NULL, 0},
    {"fictitious_fraction", vfy_metric_fictitious_fraction, NULL, NULL, 0},
    {NULL, NULL, NULL, NULL, 0}};
static const vfy_check_spec ex5_checks[] = {
    {.name = "{case} n={n} majorant violations", .rule = vfy_rule_count, .value = "violations"},
    {.name = NULL}};
static const char ex5_columns[] =
    "n:%.0f N:%.0f T_end:%.5f T_end_ci:%.5f dev_maxwell_closure:%.4f "
    "dev_sonine_closure:%.4f fictitious_fraction:%.3f violations:%.0f "
    VFY_COST_COLUMNS;

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
     * freedom below its 0.999 quantile at every time (13.8 for 2, 10.8 for 1).
     * The kinetic T at t_end, extrapolated to n = infinity, agrees with the
     * first-Sonine closure within its confidence half-width plus the
     * closure's own model error. */
    char name[128], path[1024];
    vfy_check_range(r, vfy_expand(name, sizeof name, "{case} O(1/n) fit chi^2 (max over t)", run,
                                  NULL),
                    chi2_max, 0.0, rows >= 4 ? 13.8 : 10.8);
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

const vfy_case_desc vfy_grw_ex5 = {
    .paper_rows = {.keys = {"particles.n"}, .values = {"64 256 1024 4096"}},
    .quick_rows = {.keys = {"particles.n"},
                   .values = {"64 256 1024"},
                   .sets = "particles.ensembles=300"},
    .metrics = ex5_metrics, .checks = ex5_checks, .columns = ex5_columns,
    .figures = {{.kind = VFY_FIGURE_CURVES, .quantity = "T",
                 .refs = {"T_maxwell_closure", "T_sonine_closure"}, .extrapolated = 1}},
    .after_rows = ex5_extrapolate,
    .title = "{case}: paper A Ex 5, heated hard spheres ({size} sizes)",
    .notes = "{comment}.\n\nNo exact solution exists. T is the centred temperature; dev_* = "
             "max over the output times of |eta1/T_closure - 1|; T_end at t = {t_end:%g} with "
             "its confidence half-width. The extrapolation to n = infinity (weighted least "
             "squares in 1/n at every output time, {case}-extrapolated.csv beside this table) "
             "gives T_inf = {T_inf:%.5f} ± {T_inf_ci:%.5f} at t = {t_end:%g}: minus the Maxwellian "
             "closure {diff_maxwell:%+.5f}, minus the first-Sonine closure (a2 from C.10) "
             "{diff_sonine:%+.5f}. Largest chi^2 of the O(1/n) fit over the output times: "
             "{chi2_max:%.2f} ({rows} rows). Total wall time {wall_total:%.1f} s."};
