/* vro-grw-ex3: variance-reduced observation on paper A Ex 3 (issue 4).
 *
 * The jump scheme applies the white-noise heating lazily: at an output time
 * every particle still owes a Brownian increment N(0, 2 beta (t - stamp_i))
 * per component.  scene.observation = sampled draws them and observes the
 * brought system (paper A); conditional records T, T_raw, u and P as their
 * exact expectations over those increments from running sums (sim/observe.h,
 * sim_observe_sums) and never draws them at output times, which leaves the
 * law of the trajectory unchanged (a later increment over the merged interval
 * has the same distribution); the two modes are then independent runs of
 * the same process, observed with the same mean (Rao-Blackwell: the variance
 * of the conditional estimator can only be smaller).
 *
 * Each row runs the scene both ways (two variants) at one n and reports the
 * variance reduction factor Var_sampled / Var_conditional of T_raw and T
 * (mean and smallest over the output times t > 0).  Checks: the conditional
 * means agree with the exact expectations of the n-particle estimators
 * (reference/heated.h) within |z| <= 4.5 at every output time; the two modes
 * agree with each other (the same bound, with both half-widths in
 * quadrature); the factor exceeds 1.
 */
#include <math.h>

#include "driver.h"
#include "metrics.h"
#include "tolerances.h"

static const char *const vro_needs[] = {"T_finite_n", "T_raw_finite_n", NULL};
static const char *const vro_variants[] = {"sampled: scene.observation=sampled",
                                           "conditional: scene.observation=conditional", NULL};
static const vfy_metric vro_metrics[] = {
    {"var_ratio_T_raw", vfy_metric_variance_ratio, "T_raw", "conditional", 0},
    {"var_ratio_T_raw_min", vfy_metric_variance_ratio, "T_raw", "conditional", 1},
    {"var_ratio_T", vfy_metric_variance_ratio, "T", "conditional", 0},
    {"var_ratio_T_min", vfy_metric_variance_ratio, "T", "conditional", 1},
    {NULL, NULL, NULL, NULL, 0}};
/* The two variants follow the same trajectories only in this engine (the
 * same random streams, observed two ways). */
#define SAME_STREAMS "the conditional variant is this engine's observation from running sums"
static const vfy_check_spec vro_checks[] = {
    {.name = "{case} n={n} conditional T_raw vs exact finite-n expectation",
     .rule = vfy_rule_zscore, .value = "T_raw@conditional", .expected = "T_raw_finite_n",
     .tol = VFY_TOL_ZMAX, .out = "z_T_raw"},
    {.name = "{case} n={n} sampled vs conditional T_raw", .rule = vfy_rule_zscore_pair,
     .value = "T_raw", .expected = "T_raw@conditional", .tol = VFY_TOL_ZMAX, .out = "z_modes",
     .builtin_only = SAME_STREAMS},
    {.name = "{case} n={n} conditional T vs exact finite-n expectation", .rule = vfy_rule_zscore,
     .value = "T@conditional", .expected = "T_finite_n", .tol = VFY_TOL_ZMAX, .out = "z_T"},
    {.name = "{case} n={n} sampled vs conditional T", .rule = vfy_rule_zscore_pair,
     .value = "T",
     .expected = "T@conditional", .tol = VFY_TOL_ZMAX, .out = "z_modes",
     .builtin_only = SAME_STREAMS},
    /* Var_sampled = Var_conditional + E Var(increments): a factor at or below
     * 1 means the expectation was not taken. */
    {.name = "{case} n={n} variance reduction of T_raw (mean over t)", .rule = vfy_rule_range,
     .value = "var_ratio_T_raw", .lo = VFY_TOL_VRO_VAR_RATIO_MIN, .hi = INFINITY,
     .builtin_only = SAME_STREAMS},
    {.name = NULL}};
static const char vro_columns[] =
    "n:%.0f N:%.0f var_ratio_T_raw:%.3f var_ratio_T_raw_min:%.3f var_ratio_T:%.3f "
    "var_ratio_T_min:%.3f z_T_raw:%.2f z_T:%.2f z_modes:%.2f cpu_s_sampled=cpu_s:%.2f "
    "cpu_s_conditional=cpu_s@conditional:%.2f";


const vfy_case_desc vfy_vro_grw_ex3 = {
    .must_fail = "heating.strength=1.05 collisions.constant=1.05",
    .scene = "grw-ex3",
    .paper_rows = {.keys = VFY_KEYS({"particles.n", "64 256 1024", NULL})},
    .quick_rows = {.keys = VFY_KEYS({"particles.n", "64 256", NULL}),
                   .sets = "particles.ensembles=2000"},
    .needs = vro_needs, .needs_why = VFY_NEEDS_MAXWELL, .variants = vro_variants,
    .metrics = vro_metrics, .checks = vro_checks, .columns = vro_columns,
    .row_progress = "{case} n={n}: variance reduction T_raw {var_ratio_T_raw:%.3f} (min "
                    "{var_ratio_T_raw_min:%.3f}), T {var_ratio_T:%.3f} (min {var_ratio_T_min:%.3f})",
    .case_metrics = (const vfy_metric[]){{"smallest_T_raw", vfy_metric_rows_min,
                                           "var_ratio_T_raw", NULL, 0},
                                          {NULL, NULL, NULL, NULL, 0}},
    .title = "{case}: variance-reduced observation, paper A Ex 3 ({size} sizes)",
    .notes = "{comment}.\n\nThe same scene and seed observed two ways at every output time: "
             "sampled (each particle's pending Brownian increment of the white-noise heating is "
             "drawn, paper A) and conditional (T, T_raw, u, P are their exact expectations over "
             "those increments, from running sums kept by the events, and the increments are "
             "never drawn at output times, so the two are independent runs of the same "
             "process). var_ratio_X = Var_sampled / Var_conditional "
             "of X, the mean over the output times t > 0 and the smallest (_min): the variance "
             "reduction factor, i.e. how many times fewer ensembles the conditional estimator "
             "needs for the same confidence half-width. z_T_raw, z_T: max |z| of the "
             "conditional means against the exact expectations of the n-particle estimators; "
             "z_modes: max |z| between the two modes (both half-widths in quadrature). Smallest mean factor for T_raw over the "
             "rows: {smallest_T_raw:%.3f}."};
