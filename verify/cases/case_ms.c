/* Paper C (Montanero and Santos 2000): steady states of inelastic hard
 * spheres under three thermostats, with the time-step scheme (docs/theory.md §8.5, §10).
 *
 * Every row is one steady-state run of scene verify/cases/scenes/ms-<thermostat>.ini
 * at one restitution coefficient alpha: N independent ensembles of n
 * particles relax until steady.from, then each averages its reduced moments,
 * its collisional moments mu2, mu4 (pair sampling, paper C Eq. (67)) and its
 * speed histogram over the output times (sim/steady.h); the confidence
 * half-width of every average comes from the spread of the N independent
 * ensembles.  The thermostat's strength is chosen per row so that the steady
 * temperature is close to T0 = 1 (the Maxwellian energy balance corrected by
 * the first Sonine factor 1 + 3 a2/16 with the row's Sonine a2); the reduced
 * steady state does not depend on it (paper C §2), so this only shortens the
 * relaxation.  The Gaussian thermostat runs as the homogeneous cooling state
 * in scaled variables (keep_temperature, docs/theory.md §4.3).
 *
 * Cases:
 *   ms-a2-white-noise, ms-a2-gaussian, ms-a2-non-gaussian: a2 against alpha
 *     beside every Sonine estimate (paper C Figures 1, 4, 8; Figure 6, a3 of
 *     the Gaussian thermostat), with (mu2 - mu2^(0))/mu2^(1) and
 *     (mu4 - mu4^(0))/mu4^(1);
 *   ms-table1: paper C Table 1, mu4 direct (pair sampling) against mu4
 *     through each thermostat's exact steady relation, with mu4^(0);
 *   ms-tails: the high-energy tails, G(c) = e^{A c^b} f(c) and the fitted A
 *     against the theory (white noise alpha = 0.4, 0.5; Gaussian 0.2, 0.4;
 *     Figures 3 and 7).
 * At quick sizes (CI) each case runs one or two rows with small n, N and
 * every tolerance widened by the row's confidence half-width.
 *
 * Each case is a description run by the driver (driver.h); what is paper
 * C's own is here: the thermostat strength derived from alpha, the sizes
 * line of the notes, and the tail analysis with the curves of its G(c)
 * figures.
  *
 * The cases are data (verify/cases/scenes/ms-*.case, docs/adding-a-case.md);
 * this file holds the metrics, guards, rules and curves they name, listed
 * in vfy_ms_named at its end.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "driver.h"
#include "figure.h"
#include "metrics.h"
#include "named.h"
#include "references.h"
#include "steady.h"
#include "tolerances.h"

/* ---------------------------------------------------- a2 against alpha */

/* The exact steady energy balance (vfy_energy_balance): m->x = 0, loss over
 * heating (1 in any steady state, whatever a2); m->x = 1, its relative
 * half-width from those of mu2, T and c1 (added). */
static double ms_balance(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    double rel_ci;
    const double b = vfy_energy_balance(&row->scene, &row->solver, &row->res, &rel_ci);
    return m->x == 1.0 ? rel_ci : b;
}

/* --------------------------------------------------------------- tails */

/* One row's tail analysis (paper C §4, Figures 3 and 7). */
typedef struct ms_tail {
    double A_theory;                /* Eq. (36) or (42) with the simulated mu2 */
    double A_fit2, A_fit3, A_sd3;   /* fitted over c >= 2 and c >= 3 */
    size_t used3;                   /* the shells of the c >= 3 fit */
    double K, K_ci;                 /* the plateau of G(c) over c >= 3 */
    double ratio4, ratio4_ok;       /* f/phi at c = 4, and whether it is measured */
} ms_tail;

/* The shell-averaged f, its half-width, G(c) = e^{A c^b} f(c) with the
 * theory's A and the Maxwellian's G, for each of the row's shells (arrays of
 * steady.bins), and the analysis: the plateau K of G over the shells with
 * c >= 3 (weighted mean); f/phi at c = 4, interpolated geometrically
 * between the two shells whose centres straddle it, each against the
 * Maxwellian averaged over the same shell. */
static void ms_tail_analyse(const vfy_row *row, double *c, double *f, double *fc, double *G,
                            double *Gc, double *Gphi, ms_tail *t)
{
    const sim_scene *s = &row->solver;
    const size_t bins = s->steady.bins;
    const double b = vfy_values_get(&row->values, "b");
    t->A_theory = vfy_reference_tail_A(s, vfy_values_get(&row->values, "mu2"));
    double K_num = 0.0, K_den = 0.0, r_lo = NAN, r_hi = NAN, r_lo_ci = NAN;
    for (size_t k = 0; k < bins; k++) {
        f[k] = row->res.steady_mean[SIM_STEADY_BIN0 + k];
        fc[k] = row->res.steady_ci[SIM_STEADY_BIN0 + k];
        c[k] = sim_steady_bin_centre(s, k);
        const double e = exp(t->A_theory * pow(c[k], b));
        G[k] = e * f[k];
        Gc[k] = e * fc[k];
        Gphi[k] = e * pow(M_PI, -1.5) * exp(-c[k] * c[k]);
        if (c[k] >= VFY_TOL_MS_TAIL_C && f[k] > 0.0 && fc[k] < VFY_TOL_MS_TAIL_REL_CI * f[k]) {
            const double w = 1.0 / (Gc[k] * Gc[k]);
            K_num += w * G[k];
            K_den += w;
        }
        const double lo = sim_steady_bin_lower(s, k), hi = sim_steady_bin_lower(s, k + 1);
        const double shell = (erf(hi) - 2.0 * hi * exp(-hi * hi) / sqrt(M_PI))
                             - (erf(lo) - 2.0 * lo * exp(-lo * lo) / sqrt(M_PI));
        const double phi = shell / (4.0 * M_PI / 3.0 * (hi * hi * hi - lo * lo * lo));
        if (c[k] <= 4.0) {
            r_lo = f[k] / phi;
            r_lo_ci = fc[k] / phi;
        } else if (isnan(r_hi))
            r_hi = f[k] / phi;
    }
    t->K = K_num / K_den;
    t->K_ci = 1.0 / sqrt(K_den);   /* weights 1/ci^2 */
    const size_t k_lo = (size_t)floor(4.0 / (s->steady.c_max / (double)bins) - 0.5);
    const double t4 = (4.0 - c[k_lo]) / (c[k_lo + 1] - c[k_lo]);
    t->ratio4 = exp((1.0 - t4) * log(r_lo) + t4 * log(r_hi));
    t->ratio4_ok = r_lo_ci < VFY_TOL_MS_TAIL_REL_CI * r_lo && isfinite(t->ratio4);
    double sd2, K2, K3;
    vfy_fit_tail(c, f, fc, bins, b, 2.0, SIM_LAMBDA_P, &t->A_fit2, &sd2, &K2);
    t->used3 = vfy_fit_tail(c, f, fc, bins, b, VFY_TOL_MS_TAIL_C, SIM_LAMBDA_P, &t->A_fit3,
                            &t->A_sd3, &K3);
}

enum { TAIL_A_THEORY, TAIL_A_FIT2, TAIL_A_FIT3, TAIL_A_SD3, TAIL_A_CI3, TAIL_USED3, TAIL_K,
       TAIL_K_CI, TAIL_RATIO4, TAIL_RATIO4_OK };

/* A quantity of the row's tail analysis (m->x: one of the TAIL_ above). */
static double ms_tail_metric(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    const size_t bins = row->solver.steady.bins;
    double *buf = malloc(6 * bins * sizeof *buf);
    if (buf == NULL)
        return NAN;
    ms_tail t;
    ms_tail_analyse(row, buf, buf + bins, buf + 2 * bins, buf + 3 * bins, buf + 4 * bins,
                    buf + 5 * bins, &t);
    free(buf);
    const double v[] = {t.A_theory, t.A_fit2, t.A_fit3, t.A_sd3, SIM_LAMBDA_P * t.A_sd3,
                        (double)t.used3, t.K, t.K_ci, t.ratio4, t.ratio4_ok};
    return v[(size_t)m->x];
}

/* The curves of the G(c) figures (paper C Figures 3, 7; ms-tails' [figure]):
 * the row's G(c) with its half-widths (x NaN), or the Maxwellian's (x 1). */
static int ms_curve_g(const vfy_case_run *run, const vfy_row *row, double x, vfy_curve *out)
{
    (void)run;
    const size_t bins = row->solver.steady.bins;
    double *buf = malloc(6 * (bins ? bins : 1) * sizeof *buf);
    if (buf == NULL || vfy_curve_alloc(out, bins, isnan(x)) != 0) {
        free(buf);
        return -1;
    }
    double *c = buf, *G = buf + 3 * bins, *Gc = buf + 4 * bins, *Gphi = buf + 5 * bins;
    ms_tail t;
    ms_tail_analyse(row, c, buf + bins, buf + 2 * bins, G, Gc, Gphi, &t);
    for (size_t k = 0; k < bins; k++) {
        out->x[k] = c[k];
        out->y[0][k] = isnan(x) ? G[k] : Gphi[k];
        if (out->ci[0] != NULL)
            out->ci[0][k] = Gc[k];
    }
    free(buf);
    return 0;
}

/* The functions this file's case files name (named.h, registry.c). */
const vfy_named_fn vfy_ms_named[] = {
    VFY_NAMED_METRIC("ms_balance", ms_balance),
    VFY_NAMED_METRIC_X("ms_tail_a_theory", ms_tail_metric, TAIL_A_THEORY),
    VFY_NAMED_METRIC_X("ms_tail_a_fit2", ms_tail_metric, TAIL_A_FIT2),
    VFY_NAMED_METRIC_X("ms_tail_a_fit3", ms_tail_metric, TAIL_A_FIT3),
    VFY_NAMED_METRIC_X("ms_tail_a_sd3", ms_tail_metric, TAIL_A_SD3),
    VFY_NAMED_METRIC_X("ms_tail_a_ci3", ms_tail_metric, TAIL_A_CI3),
    VFY_NAMED_METRIC_X("ms_tail_used3", ms_tail_metric, TAIL_USED3),
    VFY_NAMED_METRIC_X("ms_tail_k", ms_tail_metric, TAIL_K),
    VFY_NAMED_METRIC_X("ms_tail_k_ci", ms_tail_metric, TAIL_K_CI),
    VFY_NAMED_METRIC_X("ms_tail_ratio4", ms_tail_metric, TAIL_RATIO4),
    VFY_NAMED_METRIC_X("ms_tail_ratio4_ok", ms_tail_metric, TAIL_RATIO4_OK),
    VFY_NAMED_CURVE("ms_curve_g", ms_curve_g),
    VFY_NAMED_CURVE_X("ms_curve_g_maxwellian", ms_curve_g, 1.0),
    VFY_NAMED_END};
