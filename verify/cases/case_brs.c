/* Paper B (Bisi, Rjasanow, Spiga 2010): a granular gas in a host medium,
 * binary inelastic collisions and elastic collisions with a background in one
 * exact jump scheme (docs/theory.md §5, §12).
 *
 * brs-ex1, brs-ex2 (Tables 1 and 2), brs-ex3: Maxwell kernels.  Rows n = 4,
 * 16, 64, ... with N = 16 n; Err = max over the output times of
 * |T(t) - eta1(t)| / T(t) with the centred estimator T against the closed
 * form (B.15); Conf = max over the output times of c(t)/T(t), c the
 * confidence half-width lambda_p sqrt(Var/N).  Beyond the paper: the exact
 * expectation of the n-particle estimator T_n (reference/background.h), so
 * each row's mean is z-tested at every output time and its systematic error
 * e_sys is known exactly; and E u_n(t) = u(t) exactly for every n, z-tested.
 *
 * brs-ex4, brs-ex5: hard spheres (Algorithm 2).  The kinetic steady
 * temperature T* for each n is the time average of eta1 over the second half
 * of the run; its O(1/n) extrapolation (weighted least squares in 1/n) is
 * compared with the paper's kinetic value, beside both closures' steady
 * states (GSL root finding) and their CVODE trajectories.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "cases.h"
#include "driver.h"
#include "metrics.h"
#include "tolerances.h"

/* What every brs case reads of a result: T and u (the engine computes no more). */
#define BRS_OBSERVES "T ux uy uz"

/* brs-ex1, brs-ex2, brs-ex3 (paper B Ex 1-3, docs/theory.md §12.1): Maxwell kernels, rows n = 4,
 * 16, 64, ... with N = 16 n. */
static const char *const conv_needs[] = {"T_exact", "T_finite_n", "ux_exact", "uy_exact",
                                         "uz_exact", NULL};
static const vfy_metric conv_metrics[] = {
    {"Err", vfy_metric_max_rel_err, "T", "T_exact", 0},
    {"Conf", vfy_metric_max_rel_ci, "T", "T_exact", 0},
    {"e_sys", vfy_metric_max_rel_err, "T_finite_n", "T_exact", 0},
    {"CF", vfy_metric_ratio_previous, "Err", NULL, 0},
    {"CF_Conf", vfy_metric_ratio_previous, "Conf", NULL, 0},
    {"fictitious_fraction", vfy_metric_fictitious_fraction, NULL, NULL, 0},
    {NULL, NULL, NULL, NULL, 0}};
/* The z-tests, the CFs and the violations; the paper's checks come first
 * in the tables' own lists. */
#define BRS_Z(Q, REF, OUT, NAME)                                                         \
    {.name = "{case} n={n} " NAME, .rule = vfy_rule_zscore, .value = Q, .expected = REF,  \
     .from = 1, .tol = VFY_TOL_ZMAX, .out = OUT}
#define BRS_EXACT_CHECKS                                                                 \
    BRS_Z("T", "T_finite_n", "z_T", "T vs exact finite-n expectation"),                  \
        BRS_Z("ux", "ux_exact", "z_u", "ux vs exact u(t)"),                               \
        BRS_Z("uy", "uy_exact", "z_u", "uy vs exact u(t)"),                               \
        BRS_Z("uz", "uz_exact", "z_u", "uz vs exact u(t)")
#define BRS_CF_CHECKS                                                                    \
    {.name = "{case} n={n} CF of Err", .rule = vfy_rule_range, .value = "CF",            \
     .lo = VFY_TOL_BRS_ERR_CF_LO, .hi = VFY_TOL_BRS_ERR_CF_HI,                           \
     .guard = {vfy_guard_after_first, NULL, NULL, 0, NULL}},                              \
        {.name = "{case} n={n} CF of Conf", .rule = vfy_rule_range, .value = "CF_Conf",  \
         .lo = VFY_TOL_BRS_CONF_CF_LO, .hi = VFY_TOL_BRS_CONF_CF_HI,                     \
         .guard = {vfy_guard_after_first, NULL, NULL, 0, NULL}},                          \
        {.name = "{case} n={n} majorant violations", .rule = vfy_rule_violations,          \
         .value = "violations"}
#define BRS_PAPER_ERR                                                                    \
    {.name = "{case} n={n} Err vs paper {paper}", .rule = vfy_rule_relative, .value = "Err", \
     .expected = "Err_paper", .tol = VFY_TOL_BRS_PAPER_ERR_RTOL,                         \
     .guard = {vfy_guard_only_at_most, "n", NULL, VFY_TOL_BRS_PAPER_MAX_N, NULL}}
/* Paper B's Table 1 Conf: a known difference, the T series judged against the
 * exact finite-n expectation instead */
static const vfy_difference table1_conf_difference = {
    .paper = "B Table 1: Conf, the largest confidence band c/T over the run",
    .evidence = "Table 1's Conf is 5.1 to 5.4 times max c/T at every row at the paper's sizes "
                "(Conf_paper over Conf), while its Err agrees and the same Conf reproduces Table "
                "2 within 4% from n = 16 on; no reading of the band (c or 2c, absolute or "
                "relative, T or T_raw) gives its numbers (docs/differences.md)",
    .judged_by = "{case} n={n} T vs exact finite-n expectation"};
static const vfy_check_spec table1_checks[] = {
    BRS_EXACT_CHECKS, BRS_PAPER_ERR,
    {.name = "{case} n={n} Conf vs paper {paper}", .rule = vfy_rule_relative, .value = "Conf",
     .expected = "Conf_paper", .tol = VFY_TOL_BRS_PAPER_CONF_RTOL,
     .guard = {vfy_guard_only_at_most, "n", NULL, VFY_TOL_BRS_PAPER_MAX_N, NULL},
     .differs = &table1_conf_difference},
    BRS_CF_CHECKS, {.name = NULL}};
static const vfy_check_spec table2_checks[] = {
    BRS_EXACT_CHECKS, BRS_PAPER_ERR,
    {.name = "{case} n={n} Conf vs paper {paper}", .rule = vfy_rule_relative, .value = "Conf",
     .expected = "Conf_paper", .tol = VFY_TOL_BRS_PAPER_CONF_RTOL,
     .guard = {vfy_guard_only_at_most, "n", NULL, VFY_TOL_BRS_PAPER_MAX_N, NULL}},
    BRS_CF_CHECKS, {.name = NULL}};
static const vfy_check_spec no_table_checks[] = {BRS_EXACT_CHECKS, BRS_CF_CHECKS,
                                                 {.name = NULL}};
static const char conv_columns[] =
    "n:%.0f N:%.0f Err:%.3e Err_paper:%.2e CF:%.2f CF_paper:%.2f Conf:%.3e "
    "Conf_paper:%.2e CF_Conf:%.2f CF_Conf_paper:%.2f e_sys:%.3e z_T:%.2f z_u:%.2f "
    "fictitious_fraction:%.3f violations:%.0f "
    VFY_COST_COLUMNS;
static const char conv_notes[] =
    "{comment}; N = 16 n per row.\n\nErr = max over the {outputs} output times of |T(t) - "
    "eta1(t)|/T(t), with the centred temperature and T(t) from (B.15). Conf = max over the "
    "output times of c(t)/T(t), c = 3.2 sqrt(Var/N) the confidence half-width (the band is 2c "
    "thick). CF = previous row / this row. e_sys = max |E T_n - T|/T, the exact systematic "
    "error of the n-particle estimator (reference/background.h); z_T = max |eta1 - E T_n|/sigma "
    "and z_u = the same for u against the exact u(t) (= E u_n for every n), over all output "
    "times. events = candidate events (binary and background); fictitious_fraction = 1 - "
    "accepted/candidates (0 for Maxwell kernels, Algorithm 1); cpu_s is process CPU time over "
    "all threads. Total wall time {wall_total:%.1f} s.";
#define BRS_CONVERGENCE(LABEL, PAPER, CHECKS, ...)                                  \
    {.paper = LABEL,                                                                      \
     __VA_ARGS__,                                                                        \
     .paper_rows = {.keys = VFY_KEYS({"particles.n", "4 16 64 256 1024", NULL},           \
                                     {"particles.ensembles", "64 256 1024 4096 16384",    \
                                      NULL})},                                            \
     .quick_rows = {.keys = VFY_KEYS({"particles.n", "4 16 64", NULL},                    \
                                     {"particles.ensembles", "64 256 1024", NULL})},      \
     .needs = conv_needs, .needs_why = VFY_NEEDS_BRS_MAXWELL, .paper_columns = PAPER,    \
     .observes = BRS_OBSERVES,                                                            \
     .metrics = conv_metrics, .checks = CHECKS, .columns = conv_columns,                 \
     .figures = VFY_FIGURES({.kind = VFY_FIGURE_CURVES, .suffix = "-T", .quantity = "T",  \
                             .refs = VFY_LIST("T_exact"), .panel_per_row = 1},            \
                            {.kind = VFY_FIGURE_CURVES, .suffix = "-uy", .quantity = "uy",\
                             .refs = VFY_LIST("uy_exact"), .panel_per_row = 1}),          \
     .title = "{case}: paper B {paper} ({size} sizes)", .notes = conv_notes}
/* Paper B Ex 1 (its Table 1) and Ex 2 (Table 2): rows n = 4 ... 1024. */
static const vfy_paper_column brs_table1[] = {
    VFY_PAPER_COLUMN("Err_paper", 3.49e-1, 8.80e-2, 1.99e-2, 5.51e-3, 1.08e-3),
    VFY_PAPER_COLUMN("CF_paper", NAN, 3.97, 4.42, 3.61, 5.10),
    VFY_PAPER_COLUMN("Conf_paper", 1.15e+0, 2.50e-1, 6.41e-2, 1.62e-2, 3.99e-3),
    VFY_PAPER_COLUMN("CF_Conf_paper", NAN, 4.60, 3.90, 3.96, 4.06),
    {NULL, 0, NULL}};
static const vfy_paper_column brs_table2[] = {
    VFY_PAPER_COLUMN("Err_paper", 3.14e-1, 9.20e-2, 2.34e-2, 5.71e-3, 1.48e-3),
    VFY_PAPER_COLUMN("CF_paper", NAN, 3.41, 3.93, 4.10, 3.86),
    VFY_PAPER_COLUMN("Conf_paper", 1.99e-1, 4.51e-2, 1.13e-2, 2.73e-3, 6.80e-4),
    VFY_PAPER_COLUMN("CF_Conf_paper", NAN, 3.68, 3.99, 4.14, 4.01),
    {NULL, 0, NULL}};
const vfy_case_desc vfy_brs_ex1 = BRS_CONVERGENCE("Table 1", brs_table1, table1_checks,
                    .must_fail = "collisions.constant=1.05 collisions.restitution=0.95 background.constant=1.05");
const vfy_case_desc vfy_brs_ex2 = BRS_CONVERGENCE("Table 2", brs_table2, table2_checks,
                    .must_fail = "background.constant=1.05",
              .power_keys = "collisions.constant=1.05 collisions.restitution=0.95");
const vfy_case_desc vfy_brs_ex3 =
    BRS_CONVERGENCE("Maxwell kernels, relaxation", NULL, no_table_checks,
                    .must_fail = "background.constant=1.05 background.mass=1.05");

/* brs-ex4, brs-ex5 (paper B Ex 4, 5; docs/theory.md §12.3): hard spheres.  Rows with n N fixed
 * (2^21 at paper sizes, 2^14 at quick), so each row costs about the same;
 * each row runs in 32 independent batches (vfy_batches: seeds scene
 * seed + 1000 (row + 1) + batch): the spread of the batches' time averages
 * gives T*'s confidence interval, which a time average of correlated
 * per-time intervals cannot. */
static const char *const steady_needs[] = {"T_le", "T_grad", "uy_le", "uy_grad", NULL};
static const char *const steady_values[] = {"T_star_le", "T_star_grad", NULL};
/* T* = the batches' mean of the time average over the second half; the
 * costs and counts summed over the batches. */
static const vfy_metric steady_metrics[] = {
    {"T_star", vfy_metric_batch_mean, "T", NULL, 0.5},
    {"T_star_sd", vfy_metric_batch_se, "T", NULL, 0.5},
    {"T_star_ci", vfy_metric_batch_t_ci, "T_star_sd", NULL, 0},
    {"dev_uy_grad", vfy_metric_max_abs_diff, "uy@*", "uy_grad", 0},
    {"N", vfy_metric_variants_sum, "N", NULL, 0},
    {"violations", vfy_metric_variants_sum, "violations", NULL, 0},
    {"collisions", vfy_metric_variants_sum, "collisions", NULL, 0},
    {"background", vfy_metric_variants_sum, "background", NULL, 0},
    {"events", vfy_metric_variants_sum, "events", NULL, 0},
    {"cpu_s", vfy_metric_variants_sum, "cpu_s", NULL, 0},
    {"wall_s", vfy_metric_variants_sum, "wall_s", NULL, 0},
    {"ns_per_event", vfy_metric_per, "cpu_s", "events", 1e9},
    {"fictitious_fraction", vfy_metric_fictitious_fraction, NULL, NULL, 0},
    {"T_grad_end", vfy_metric_final_mean, "T_grad", NULL, 0},
    {"nN", vfy_metric_product, "n", "N", 1},
    {NULL, NULL, NULL, NULL, 0}};
static const vfy_check_spec steady_checks[] = {
    {.name = "{case} n={n} majorant violations", .rule = vfy_rule_violations, .value = "violations"},
    {.name = NULL}};
static const char steady_columns[] =
    "n:%.0f N:%.0f T_star:%.5f T_star_ci:%.5f dev_uy_grad:%.4f fictitious_fraction:%.3f "
    "violations:%.0f "
    VFY_COST_COLUMNS;

/* n -> infinity: T* (its value, half-width and the fit's chi^2), the
 * closures' steady states and the Grad closure at t_end for the case checks;
 * the figure extrapolates T(t) at every output time. */
static const vfy_metric steady_case_metrics[] = {
    {"T_inf", vfy_metric_rows_extrapolate, "T_star", "T_star_sd", 0},
    {"T_inf_ci", vfy_metric_rows_extrapolate, "T_star", "T_star_sd", 1},
    {"chi2", vfy_metric_rows_extrapolate, "T_star", "T_star_sd", 2},
    {"T_grad_end", vfy_metric_first_row, "T_grad_end", NULL, 0},
    {"T_star_le", vfy_metric_first_row, "T_star_le", NULL, 0},
    {"T_star_grad", vfy_metric_first_row, "T_star_grad", NULL, 0},
    {"nN", vfy_metric_first_row, "nN", NULL, 0},
    {"t_from", vfy_metric_product, "scene.t_end", NULL, 0.5},
    {NULL, NULL, NULL, NULL, 0}};

/* The checks on the extrapolation, against the T* paper B prints (KINETIC,
 * LE, GRAD) to VFY_TOL_BRS_PRINTED_DIGITS decimals. */
#define STEADY_CASE_CHECKS(KINETIC, LE, GRAD)                                          \
    {{.name = "{case} kinetic T* (n -> infinity) vs paper", .rule = vfy_rule_printed,     \
      .value = "T_inf", .plus = "T_inf_ci", .x = KINETIC, .tol = VFY_TOL_BRS_PRINTED_DIGITS}, \
     {.name = "{case} LE closure T* vs paper", .rule = vfy_rule_printed,                 \
      .value = "T_star_le", .x = LE, .tol = VFY_TOL_BRS_PRINTED_DIGITS},                  \
     {.name = "{case} Grad closure T* vs paper", .rule = vfy_rule_printed,               \
      .value = "T_star_grad", .x = GRAD, .tol = VFY_TOL_BRS_PRINTED_DIGITS},              \
     /* the closures have relaxed by t_end (so the DSMC average over the second \
      * half is a steady value too, the closures relaxing on the same scale) */ \
     {.name = "{case} Grad closure at t_end vs its T*", .rule = vfy_rule_absolute,       \
      .value = "T_grad_end", .expected = "T_star_grad",                                   \
      .tol = VFY_TOL_BRS_CLOSURE_RELAXED},                                                \
     /* the O(1/n) model describes the rows: chi^2 with 1 degree of freedom     \
      * below its 0.999 quantile */                                              \
     {.name = "{case} O(1/n) fit of T* chi^2", .rule = vfy_rule_range, .value = "chi2",  \
      .lo = 0.0, .hi = VFY_TOL_BRS_FIT_CHI2},                                            \
     {.name = NULL}}
static const vfy_check_spec steady4_checks[] = STEADY_CASE_CHECKS(0.953, 0.956, 0.956);
static const vfy_check_spec steady5_checks[] = STEADY_CASE_CHECKS(0.732, 0.743, 0.757);

#define STEADY_NOTES(KINETIC, LE, GRAD)                                                \
    "{comment}; n N = {nN} per row in 32 independent batches (seeds seed + 1000 row + "   \
    "batch).\n\nT_star = time average over t in [{t_from:%g}, {scene.t_end:%g}] of the "    \
    "ensemble "                                                                           \
    "mean of the centred T; T_star_ci = t-quantile(0.9995, 31) x the standard error over " \
    "the batches. Extrapolated to n = infinity (weighted least squares in 1/n): kinetic "  \
    "T* = {T_inf:%.5f} ± {T_inf_ci:%.5f} (paper " KINETIC "), judged within half a unit of " \
    "the paper's last digit (0.0005) plus its confidence half-width, so that it "          \
    "separates the kinetic value from the closures' (0.003 apart for K = 1/8) wherever "   \
    "the half-width is below 0.0025 (paper sizes; at quick sizes it is not, and the check " \
    "is correspondingly loose). Closures' steady states (GSL Brent root of dT/dt at u = "  \
    "u_B): local equilibrium (B.21) {T_star_le:%.5f} (paper " LE "), Grad (B.22) "          \
    "{T_star_grad:%.5f} (paper " GRAD "). chi^2 of the O(1/n) fit {chi2:%.2f}. "           \
    "dev_uy_grad = max over t of |eta1 of u_y - u_y of (B.22)|. fictitious_fraction = 1 - " \
    "accepted/candidate events (binary and background). Total wall time "                 \
    "{wall_total:%.1f} s."
#define BRS_STEADY(CHECKS, NOTES, ...)                                             \
    {__VA_ARGS__,                                                                        \
     .paper_rows = {.keys = VFY_KEYS({"particles.n", "64 256 1024", NULL},                \
                                     {"particles.ensembles", "1024 256 64", NULL})},      \
     .quick_rows = {.keys = VFY_KEYS({"particles.n", "16 64 256", NULL},                  \
                                     {"particles.ensembles", "32 8 2", NULL})},           \
     .label = "{case} n={n} batch", .batches = {32, 1000},                               \
     .needs = steady_needs, .observes = BRS_OBSERVES,                                    \
     .needs_why = "paper B's closures need collisions.kernel = hard-spheres and "        \
                  "background.kernel = hard-spheres",                                    \
     .values = steady_values, .metrics = steady_metrics, .checks = steady_checks,        \
     .columns = steady_columns, .case_metrics = steady_case_metrics,                      \
     .case_progress = "{case}: kinetic T* = {T_inf:%.5f} ± {T_inf_ci:%.5f}; closures LE "    \
                      "{T_star_le:%.5f}, Grad {T_star_grad:%.5f}",                           \
     .case_checks = CHECKS,                                                               \
     .figures = VFY_FIGURES({.kind = VFY_FIGURE_CURVES, .suffix = "-T", .quantity = "T@*",\
                             .refs = VFY_LIST("T_le", "T_grad"), .extrapolated = 1,       \
                             .title = "{case}: T(t), each n and n = infinity, beside the "   \
                                      "closures ({size} sizes)"},                            \
                            {.kind = VFY_FIGURE_CURVES, .suffix = "-uy", .quantity = "uy@*",\
                             .refs = VFY_LIST("uy_le", "uy_grad"),                        \
                             .title = "{case}: u_y(t) beside the closures ({size} sizes)"}), \
     .title = "{case}: paper B, hard spheres, steady temperature ({size} sizes)",       \
     .notes = NOTES}
const vfy_case_desc vfy_brs_ex4 =
    BRS_STEADY(steady4_checks, STEADY_NOTES("0.953", "0.956", "0.956"),
               .must_fail = "collisions.constant=1.2 background.constant=1.2",
              .power_keys = "collisions.restitution=0.95");
const vfy_case_desc vfy_brs_ex5 =
    BRS_STEADY(steady5_checks, STEADY_NOTES("0.732", "0.743", "0.757"),
               .must_fail = "background.constant=1.05 collisions.constant=1.05");
