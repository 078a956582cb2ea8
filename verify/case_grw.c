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
#include "cases.h"
#include "scene_ini.h"
#include "scene_refs.h"
#include "table.h"

#include "driver.h"
#include "tolerances.h"

#define SONINE_MODEL_RTOL VFY_TOL_SONINE_MODEL_RTOL
#define ZMAX VFY_TOL_ZMAX

/* Load the case's scenes (reference and solver) and its rows: n = 64, 256,
 * ... (paper_rows or quick_rows of them); N is the scene's at paper sizes,
 * quick_ensembles at quick sizes. */
static sim_status load_rows(const vfy_case *c, const vfy_options *o, size_t paper_rows,
                            size_t quick_rows, size_t quick_ensembles, sim_scene *scene,
                            sim_scene *solver, size_t n[VFY_ROWS_MAX], size_t *rows, char *msg,
                            size_t msglen)
{
    sim_status status = vfy_load_case_scene(c, o, scene, solver, msg, msglen);
    *rows = o->size == VFY_PAPER ? paper_rows : quick_rows;
    if (o->size == VFY_QUICK)
        scene->particles.ensembles = solver->particles.ensembles = quick_ensembles;
    for (size_t i = 0; i < *rows; i++)
        n[i] = (size_t)64 << (2 * i);
    return status;
}

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
static const vfy_column grw_columns[] = {
    {"n", NULL, "%.0f"}, {"N", NULL, "%.0f"}, {"Emax", NULL, "%.3e"},
    {"Emax_paper", NULL, "%.3e"}, {"CF", NULL, "%.2f"}, {"CF_paper", NULL, "%.2f"},
    {"V_inf", NULL, "%.3e"}, {"V_inf_paper", NULL, "%.3e"}, {"Emax_T", NULL, "%.3e"},
    {"noise", NULL, "%.3e"}, {"z_T_raw", NULL, "%.2f"}, {"z_T", NULL, "%.2f"},
    VFY_COST_COLUMN_SPECS, {NULL, NULL, NULL}};
#define GRW_TABLE(LABEL, PAPER)                                                         \
    {.paper = LABEL,                                                                  \
     .paper_rows = {{"particles.n"}, {"64 256 1024 4096 16384"}},                     \
     .quick_rows = {{"particles.n"}, {"64 256 1024"}, .sets = "particles.ensembles=2000"}, \
     .needs = grw_needs, .needs_why = VFY_NEEDS_MAXWELL, .paper_columns = PAPER,      \
     .metrics = grw_metrics, .checks = grw_checks, .columns = grw_columns,           \
     .figure = {VFY_FIGURE_CURVES, "T_raw", {"T_exact"}, 2.0, 1},                      \
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

sim_status vfy_case_grw_hard_spheres(const vfy_case *c, const vfy_options *o, vfy_report *r,
                                     char *msg, size_t msglen)
{
    sim_scene scene, solver;
    size_t n[VFY_ROWS_MAX], rows;
    sim_status status = load_rows(c, o, 4, 3, 300, &scene, &solver, n, &rows, msg, msglen);
    if (status != SIM_OK)
        return status;
    const size_t M = scene.outputs;

    static const char *const cols[] = {"n", "N", "T_end", "T_end_ci", "dev_maxwell_closure",
                                       "dev_sonine_closure", "fictitious_fraction", "violations",
                                       VFY_COST_COLUMNS};
    static const char *const xcols[] = {"t", "T_inf", "T_inf_ci", "T_maxwell_closure",
                                        "T_sonine_closure", "diff_maxwell", "diff_sonine",
                                        "chi2"};
    vfy_table table, xtable;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    vfy_table_init(&xtable, sizeof xcols / sizeof *xcols, xcols);
    vfy_refs refs = {0};
    sim_error err;
    double *t = malloc(M * sizeof *t), *maxw = malloc(M * sizeof *maxw);
    double *sonine = malloc(M * sizeof *sonine);
    double *band_mean = malloc((rows + 1) * M * sizeof *band_mean);
    double *band_ci = malloc((rows + 1) * M * sizeof *band_ci);
    if (!t || !maxw || !sonine || !band_mean || !band_ci) {
        snprintf(msg, msglen, "out of memory");
        status = SIM_ENOMEM;
        goto done;
    }
    if ((status = vfy_scene_references(&scene, &refs, &err)) != SIM_OK) {
        vfy_scene_format_error(&scene, &err, msg, msglen);
        goto done;
    }
    vfy_refs_column(&refs, "T_maxwell_closure", maxw);
    vfy_refs_column(&refs, "T_sonine_closure", sonine);

    double wall_total = 0.0;
    for (size_t i = 0; i < rows; i++) {
        solver.particles.n = n[i];
        char label[96], name[128];
        snprintf(label, sizeof label, "%s n=%zu", c->name, n[i]);
        sim_ensemble_result res;
        status = vfy_simulate(&solver, o, label, &res, msg, msglen);
        if (status != SIM_OK) {
            sim_ensemble_result_free(&res);
            goto done;
        }
        memcpy(t, res.t, M * sizeof *t);
        vfy_result_column(&res, SIM_OBS_T, band_mean + i * M, band_ci + i * M);
        double dev_m = 0.0, dev_s = 0.0;
        for (size_t m = 0; m < M; m++) {
            dev_m = fmax(dev_m, fabs(band_mean[i * M + m] / maxw[m] - 1.0));
            dev_s = fmax(dev_s, fabs(band_mean[i * M + m] / sonine[m] - 1.0));
        }
        vfy_check_count(r, vfy_name(name, sizeof name, "%s n=%zu majorant violations", c->name,
                                    n[i]),
                        res.counts.violations, 0);
        double events = (double)res.counts.candidates;
        vfy_table_cell(&table, "%zu", n[i]);
        vfy_table_cell(&table, "%zu", res.ensembles);
        vfy_table_cell(&table, "%.5f", band_mean[i * M + M - 1]);
        vfy_table_cell(&table, "%.5f", band_ci[i * M + M - 1]);
        vfy_table_cell(&table, "%.4f", dev_m);
        vfy_table_cell(&table, "%.4f", dev_s);
        vfy_table_cell(&table, "%.3f", 1.0 - (double)res.counts.collisions / events);
        vfy_table_cell(&table, "%llu", (unsigned long long)res.counts.violations);
        vfy_cost_cells(&table, res.cpu_seconds, res.wall_seconds, events);
        wall_total += res.wall_seconds;
        sim_ensemble_result_free(&res);
        if ((status = vfy_write_rows_so_far(o, c->name, &table, &solver, msg, msglen)) != SIM_OK)
            goto done;
    }

    /* n -> infinity at every output time. */
    double *T_inf = band_mean + rows * M, *T_inf_ci = band_ci + rows * M;
    double chi2_max = 0.0, diff_m_steady = 0.0, diff_s_steady = 0.0, ci_steady = 0.0;
    for (size_t m = 0; m < M; m++) {
        double mean[VFY_ROWS_MAX], sigma[VFY_ROWS_MAX], sd, chi2;
        for (size_t i = 0; i < rows; i++) {
            mean[i] = band_mean[i * M + m];
            sigma[i] = band_ci[i * M + m] / SIM_LAMBDA_P;
        }
        vfy_extrapolate_inverse_n(rows, n, mean, sigma, &T_inf[m], &sd, &chi2);
        T_inf_ci[m] = SIM_LAMBDA_P * sd;
        if (m > 0)
            chi2_max = fmax(chi2_max, chi2);
        vfy_table_cell(&xtable, "%.4g", t[m]);
        vfy_table_cell(&xtable, "%.6f", T_inf[m]);
        vfy_table_cell(&xtable, "%.6f", T_inf_ci[m]);
        vfy_table_cell(&xtable, "%.6f", maxw[m]);
        vfy_table_cell(&xtable, "%.6f", sonine[m]);
        vfy_table_cell(&xtable, "%+.6f", T_inf[m] - maxw[m]);
        vfy_table_cell(&xtable, "%+.6f", T_inf[m] - sonine[m]);
        vfy_table_cell(&xtable, "%.2f", chi2);
    }
    diff_m_steady = T_inf[M - 1] - maxw[M - 1];
    diff_s_steady = T_inf[M - 1] - sonine[M - 1];
    ci_steady = T_inf_ci[M - 1];

    /* The O(1/n) model must describe the rows: chi^2 with rows - 2 degrees of
     * freedom below its 0.999 quantile at every time (13.8 for 2, 10.8 for 1). */
    char name[128];
    vfy_check_range(r, vfy_name(name, sizeof name, "%s O(1/n) fit chi^2 (max over t)", c->name),
                    chi2_max, 0.0, rows >= 4 ? 13.8 : 10.8);
    /* The kinetic temperature at t_end, extrapolated to n = infinity, agrees
     * with the first-Sonine closure within its confidence half-width plus
     * the closure's own model error. */
    vfy_check_absolute(r, vfy_name(name, sizeof name, "%s T_inf(t_end) vs Sonine closure",
                                   c->name),
                       T_inf[M - 1], sonine[M - 1],
                       ci_steady + SONINE_MODEL_RTOL * sonine[M - 1]);
    if (o->progress)
        fprintf(o->progress, "   %s: at t = %g, T_inf = %.5f ± %.5f; Maxwellian closure %+.5f, "
                "Sonine closure %+.5f\n", c->name, t[M - 1], T_inf[M - 1], ci_steady,
                diff_m_steady, diff_s_steady);

    char path[1024], comment[600], notes[2400], title[160];
    vfy_run_comment(&solver, comment, sizeof comment);
    snprintf(title, sizeof title, "%s: paper A Ex 5, heated hard spheres (%s sizes)", c->name,
             o->size == VFY_PAPER ? "paper" : "quick");
    snprintf(notes, sizeof notes,
             "%s.\n\nNo exact solution exists. T is the centred temperature; dev_* = max over "
             "the output times of |eta1/T_closure - 1|; T_end at t = %g with its confidence "
             "half-width. The extrapolation to n = infinity (weighted least squares in 1/n at "
             "every output time, reports/%s-extrapolated.csv) gives T_inf = %.5f ± %.5f at "
             "t = %g: minus the Maxwellian closure %+.5f, minus the first-Sonine closure "
             "(a2 from C.10) %+.5f. Largest chi^2 of the O(1/n) fit over the output times: "
             "%.2f (%zu rows). Total wall time %.1f s.",
             comment, t[M - 1], c->name, T_inf[M - 1], ci_steady, t[M - 1], diff_m_steady,
             diff_s_steady, chi2_max, rows, wall_total);
    char xname[160];
    snprintf(xname, sizeof xname, "%s-extrapolated", c->name);
    if ((status = vfy_write_case_tables(o, c->name, &table, comment, title, notes, msg,
                                        msglen)) != SIM_OK)
        goto done;
    if (vfy_table_write_csv(&xtable, vfy_report_path(o, xname, ".csv", path, sizeof path),
                            comment) != 0) {
        status = vfy_io_error(path, msg, msglen);
        goto done;
    }
    size_t n_all[VFY_ROWS_MAX + 1];
    memcpy(n_all, n, rows * sizeof *n);
    n_all[rows] = 0;   /* the extrapolated curve */
    const char *ref_names[] = {"T_maxwell_closure", "T_sonine_closure"};
    const double *ref_cols[] = {maxw, sonine};
    if (vfy_write_curves(o, c->name, title, comment, t, M, 2, ref_names, ref_cols, rows + 1, n_all, band_mean,
                     band_ci, "T", 0.0, 0) != 0)
        status = vfy_io_error(c->name, msg, msglen);
done:
    vfy_refs_free(&refs);
    vfy_table_free(&table);
    vfy_table_free(&xtable);
    free(t);
    free(maxw);
    free(sonine);
    free(band_mean);
    free(band_ci);
    return status;
}
