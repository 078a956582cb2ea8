/* Paper C (Montanero and Santos 2000): steady states of inelastic hard
 * spheres under three thermostats, with the time-step scheme (SPEC §5).
 *
 * Every row is one steady-state run of scene verify/scenes/ms-<thermostat>.ini
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
 * in scaled variables (keep_temperature, SPEC §2).
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
 */
#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "cases.h"
#include "engine.h"
#include "figure.h"
#include "scene_ini.h"
#include "sonine.h"
#include "steady.h"
#include "table.h"

#define MS_ROWS_MAX 12
#define A2_WHITE_TOL 0.006     /* |a2 - (C.10)| for the white-noise thermostat */
#define A2_NG_RTOL 0.25        /* non-Gaussian a2 within 25% of (C.76) */
#define MU4_GAP_RTOL 0.002     /* direct and indirect mu4 within 0.2% */
#define MU4_PAPER_RTOL 0.003   /* ... and each within max(ci, 0.3%) of Table 1 */
#define A_FIT_RTOL 0.05        /* tails: the fitted A (c >= 3) within 5% of the theory */
#define K_RTOL 0.20            /* the plateau K within 20% of the paper's reading */
#define RATIO4_RTOL 0.35       /* f/phi at c = 4 within 35% of the paper's reading */
#define A3_SMALL 0.01          /* Gaussian |a3| "small" for alpha >= 0.6 (paper C §4.2) */
#define A3_LARGE 0.03          /* ... and "increasing rapidly" below: |a3| >= 0.03 at <= 0.3 */

typedef enum ms_thermostat { MS_WHITE, MS_GAUSSIAN, MS_NONGAUSSIAN, MS_THERMOSTATS } ms_thermostat;

static const struct {
    const char *stem;    /* scene file stem */
    const char *label;
    const char *figure;  /* paper C's figure of a2 */
} ms_info[MS_THERMOSTATS] = {
    {"ms-white-noise", "white noise (stochastic thermostat)", "Figure 1"},
    {"ms-gaussian", "Gaussian thermostat (HCS in scaled variables)", "Figure 4"},
    {"ms-non-gaussian", "non-Gaussian thermostat", "Figure 8"},
};

/* A case's constants. */
struct ms_case_data {
    int kind;            /* 0: a2 figure, 1: Table 1, 2: tails */
    ms_thermostat th;    /* a2 figure */
};
const struct ms_case_data vfy_ms_white_noise = {0, MS_WHITE};
const struct ms_case_data vfy_ms_gaussian = {0, MS_GAUSSIAN};
const struct ms_case_data vfy_ms_non_gaussian = {0, MS_NONGAUSSIAN};
const struct ms_case_data vfy_ms_table1 = {1, MS_WHITE};
const struct ms_case_data vfy_ms_tails = {2, MS_WHITE};

/* Paper C Table 1: alpha, mu4^(0), then direct and indirect for the white
 * noise, Gaussian and non-Gaussian thermostats. */
static const double paper_table1[4][8] = {
    {0.2, 10.925, 12.157, 12.155, 13.881, 13.881, 8.744, 8.750},
    {0.4, 9.812, 10.602, 10.600, 11.494, 11.488, 7.631, 7.631},
    {0.6, 7.797, 8.036, 8.038, 8.213, 8.217, 5.811, 5.810},
    {0.8, 4.638, 4.499, 4.503, 4.414, 4.412, 3.335, 3.333},
};

/* Entries of Table 1 not judged against the paper (NULL: judged), with the
 * short reason for the verdict line; the Markdown notes give the long one. */
static const char *const paper_table1_note[4][MS_THERMOSTATS] = {
    {NULL, NULL, NULL},
    {NULL, NULL, NULL},
    {NULL, NULL, NULL},
    {NULL, "the paper's entry contradicts its own mu2 (see ms-table1.md)", NULL},
};
static const char paper_table1_long_note[] =
    " The paper's Gaussian alpha = 0.8 entry (4.414 direct, 4.412 indirect) is reported but "
    "not judged: with its a2 (about -0.014, its Figure 4) the relation mu4 = 5 (1 + a2) mu2 "
    "needs mu2 = 0.8954, 0.5% below the first-Sonine mu2^(0)(1 + 3 a2/16) = 0.8999 that "
    "every other entry of the table meets to 0.05%; three independent runs here (keep-T; "
    "fixed zeta with Strang splitting; n = 2x10^5 as in the paper) give 4.429 to 4.437, "
    "0.4% above it, with direct and indirect agreeing to 0.1%.";

/* ----------------------------------------------------------- theory */

/* The Sonine a2 each thermostat's strength is set with. */
static double ms_a2_theory(ms_thermostat th, double alpha)
{
    switch (th) {
    case MS_WHITE:
        return ref_sonine_a2_white_noise(alpha, 3.0);
    case MS_GAUSSIAN:
        return ref_sonine_a2_gaussian_alt(alpha, 3.0);
    default:
        return ref_sonine_a2_nongaussian_fit(alpha, 3.0);
    }
}

/* Collisional energy loss rate dT/dt at temperature T (grain mass 1):
 * gamma (1 - alpha^2)/24 4 pi C (32/sqrt(pi)) T^{3/2} (1 + 3 a2/16) (SPEC §3
 * Ex 5's closure with its first Sonine factor). */
static double ms_cooling(const sim_scene *s, double T, double a2)
{
    const double alpha = s->collisions.restitution;
    return s->collisions.rate * (1.0 - alpha * alpha) / 24.0 * 4.0 * M_PI * s->collisions.constant
           * 32.0 / sqrt(M_PI) * pow(T, 1.5) * (1.0 + 3.0 * a2 / 16.0);
}

/* Set the solver's thermostat strength so that its steady T is about T0:
 * white noise 2 beta = loss, Gaussian 2 zeta T0 = loss, non-Gaussian
 * (2/3) g <|v|> = loss with <|v|> = sqrt(2 T0) (2/sqrt(pi)) (1 - a2/8)
 * (paper C Eq. (48)).  Keeps a strength the user set with --solver-set. */
static void ms_set_strength(sim_scene *solver, ms_thermostat th, double alpha)
{
    if (!solver->heating.present || sim_scene_key_line(solver, "heating.strength") < 0
        || solver->heating.keep_temperature)
        return;
    const double T0 = solver->particles.maxwellian.temperature;
    const double a2 = ms_a2_theory(th, alpha), loss = ms_cooling(solver, T0, a2);
    switch (solver->heating.type) {
    case SIM_HEATING_WHITE_NOISE:
        solver->heating.strength = 0.5 * loss;
        break;
    case SIM_HEATING_GAUSSIAN:
        solver->heating.strength = 0.5 * loss / T0;
        break;
    case SIM_HEATING_NON_GAUSSIAN:
        solver->heating.strength = 1.5 * loss
                                   / (sqrt(2.0 * T0) * 2.0 / sqrt(M_PI) * (1.0 - a2 / 8.0));
        break;
    }
}

/* ------------------------------------------------------------- runs */

typedef struct ms_run {
    double alpha;
    double h;                /* the time step used */
    sim_scene solver;
    sim_ensemble_result res; /* owns its arrays */
} ms_run;


/* Load scene stem with the case's overrides (scene) and solver overrides. */
static sim_status ms_load(const vfy_case *c, const vfy_options *o, const char *stem,
                          sim_scene *scene, sim_scene *solver, char *msg, size_t msglen)
{
    vfy_case tmp = *c;
    tmp.name = stem;
    return vfy_load_case_scene(&tmp, o, scene, solver, msg, msglen);
}

/* Quick sizes (CI): n = 2500, N = 16, relaxation to t = 8 (16 mean free
 * times), then 21 samples a mean free time apart, 4000 pairs per sample. */
static void ms_quick_sizes(sim_scene *s)
{
    s->particles.n = 2500;
    s->particles.ensembles = 16;
    s->t_end = 18.0;
    s->outputs = 37;
    s->steady.from = 8.0;
    s->steady.pairs = 4000;
}

/* One steady-state row: thermostat th at restitution alpha.  The solver's
 * restitution follows alpha unless --solver-set fixed it (a wrong solver). */
static sim_status ms_simulate(const vfy_case *c, const vfy_options *o, ms_thermostat th,
                              double alpha, ms_run *run, char *msg, size_t msglen)
{
    sim_scene scene;
    memset(run, 0, sizeof *run);
    run->alpha = alpha;
    sim_status status = ms_load(c, o, ms_info[th].stem, &scene, &run->solver, msg, msglen);
    if (status != SIM_OK)
        return status;
    sim_scene *s = &run->solver;
    if (!s->steady.present || s->scheme != SIM_SCHEME_TIMESTEP) {
        snprintf(msg, msglen, "%s: paper C's cases need [steady] and scheme = timestep",
                 s->file);
        return SIM_EINVAL;
    }
    if (o->size == VFY_QUICK)
        ms_quick_sizes(s);
    if (sim_scene_key_line(s, "collisions.restitution") >= 0)
        s->collisions.restitution = alpha;
    ms_set_strength(s, th, alpha);
    run->h = vfy_scene_step(s);
    char label[96];
    snprintf(label, sizeof label, "%s %s alpha=%.2f", c->name, ms_info[th].stem, alpha);
    status = vfy_simulate(s, o, label, &run->res, msg, msglen);
    if (status == SIM_OK && o->progress)
        fprintf(o->progress, "   %s: a2 = %.5f ± %.5f, mu4 = %.4f ± %.4f, T = %.4f (%.1f s)\n",
                label, sim_result_steady_mean(&run->res, SIM_STEADY_A2),
                sim_result_steady_ci(&run->res, SIM_STEADY_A2),
                sim_result_steady_mean(&run->res, SIM_STEADY_MU4),
                sim_result_steady_ci(&run->res, SIM_STEADY_MU4),
                sim_result_steady_mean(&run->res, SIM_STEADY_T), run->res.wall_seconds);
    return status;
}

static double st_mean(const ms_run *r, size_t k) { return sim_result_steady_mean(&r->res, k); }
static double st_ci(const ms_run *r, size_t k) { return sim_result_steady_ci(&r->res, k); }

/* "n = 20000, N = 16, h = 0.05, strang, samples t in [10, 50] every 0.25, 200000 pairs" */
static const char *ms_sizes(const ms_run *r, char *buf, size_t len)
{
    const sim_scene *s = &r->solver;
    snprintf(buf, len, "n = %zu, N = %zu, h = %g (%s), steady averages over the output times "
             "t in [%g, %g] every %g, %zu pairs per sample for mu2 and mu4",
             s->particles.n, s->particles.ensembles, r->h,
             s->splitting == SIM_SPLIT_STRANG ? "Strang splitting" : "Euler splitting",
             s->steady.from, s->t_end, sim_scene_output_time(s, 1), s->steady.pairs);
    return buf;
}

/* Allowed deviation: tol at paper sizes, tol + ci at quick sizes. */
static double ms_allowed(const vfy_options *o, double tol, double ci)
{
    return o->size == VFY_QUICK ? tol + ci : tol;
}

/* ------------------------------------------------------------ figures */

typedef struct ms_figure {
    const char *name, *title, *xlabel, *ylabel;
    int logy;
    size_t npoints;
    const double *x;
    size_t nseries;
    const char *const *series;
    const double *const *y, *const *ci;
    size_t nfine;
    const double *xfine;
    size_t ncurves;
    const char *const *curves;
    const double *const *yfine;
    const char *comment;   /* provenance (vfy_run_comment), the files' first lines */
} ms_figure;

/* <name>-points.csv (x, each series and its confidence half-width),
 * <name>-theory.csv (the curves on a fine grid) and <name>.gp, rendered to
 * <name>.png when gnuplot is installed.  Returns 0 or -1 (errno). */
static int ms_write_figure(const vfy_options *o, const ms_figure *f)
{
    char points[1024], theory[1024], gp[1024], png[1024], tmp[1100], file[256];
    snprintf(file, sizeof file, "%s-points", f->name);
    FILE *out = vfy_file_begin(vfy_report_path(o, file, ".csv", points, sizeof points), tmp,
                               sizeof tmp);
    if (out == NULL)
        return -1;
    vfy_write_comment(out, f->comment);
    fprintf(out, "%s", f->xlabel);
    for (size_t j = 0; j < f->nseries; j++)
        fprintf(out, ",%s,%s_ci", f->series[j], f->series[j]);
    fputc('\n', out);
    for (size_t i = 0; i < f->npoints; i++) {
        fprintf(out, "%.10g", f->x[i]);
        for (size_t j = 0; j < f->nseries; j++)
            fprintf(out, ",%.10g,%.6g", f->y[j][i], f->ci[j][i]);
        fputc('\n', out);
    }
    if (vfy_file_commit(out, tmp, points, 1) != 0)
        return -1;
    snprintf(file, sizeof file, "%s-theory", f->name);
    out = vfy_file_begin(vfy_report_path(o, file, ".csv", theory, sizeof theory), tmp,
                         sizeof tmp);
    if (out == NULL)
        return -1;
    vfy_write_comment(out, f->comment);
    fprintf(out, "%s", f->xlabel);
    for (size_t j = 0; j < f->ncurves; j++)
        fprintf(out, ",%s", f->curves[j]);
    fputc('\n', out);
    for (size_t i = 0; i < f->nfine; i++) {
        fprintf(out, "%.10g", f->xfine[i]);
        for (size_t j = 0; j < f->ncurves; j++)
            fprintf(out, ",%.10g", f->yfine[j][i]);
        fputc('\n', out);
    }
    if (vfy_file_commit(out, tmp, theory, 1) != 0)
        return -1;

    out = vfy_file_begin(vfy_report_path(o, f->name, ".gp", gp, sizeof gp), tmp, sizeof tmp);
    if (out == NULL)
        return -1;
    vfy_write_comment(out, f->comment);
    fprintf(out, "# %s: gnuplot %s\nset terminal pngcairo size 900,650 font ',10'\n"
                 "set termoption noenhanced\nset output '%s'\nset datafile separator ','\n"
                 "set title '%s'\nset xlabel '%s'\nset ylabel '%s'\nset key top right\n%s"
                 "plot",
            f->title, gp, vfy_report_path(o, f->name, ".png", png, sizeof png), f->title,
            f->xlabel, f->ylabel, f->logy ? "set logscale y\n" : "");
    for (size_t j = 0; j < f->ncurves; j++)
        fprintf(out, "%s '%s' skip 1 using 1:%zu with lines lw 2 dt %zu title '%s'",
                j ? "," : "", theory, j + 2, j + 1, f->curves[j]);
    for (size_t j = 0; j < f->nseries; j++)
        fprintf(out, "%s '%s' skip 1 using 1:%zu:%zu with yerrorbars pt %zu title '%s ± c'",
                f->ncurves || j ? "," : "", points, 2 + 2 * j, 3 + 2 * j, 5 + 2 * j,
                f->series[j]);
    fputc('\n', out);
    if (vfy_file_commit(out, tmp, gp, 1) != 0)
        return -1;
    if (vfy_gnuplot(gp) < 0 && o->progress)
        fprintf(o->progress, "   note: gnuplot failed on %s\n", gp);
    return 0;
}

/* ---------------------------------------------------- a2 against alpha */

sim_status vfy_case_ms_a2(const vfy_case *c, const vfy_options *o, vfy_report *r, char *msg,
                          size_t msglen)
{
    const struct ms_case_data *data = c->data;
    const ms_thermostat th = data->th;
    static const double paper_alphas[] = {0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    static const double quick_alpha[MS_THERMOSTATS] = {0.5, 0.2, 0.5};
    const size_t rows = o->size == VFY_PAPER ? sizeof paper_alphas / sizeof *paper_alphas : 1;
    ms_run *runs = calloc(rows, sizeof *runs);
    if (runs == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    static const char *const cols[] = {
        "alpha", "a2", "a2_ci", "a2_C10", "a2_C32", "a2_C5", "a2_C40", "a2_C50", "a2_C76",
        "mu2_ratio", "mu2_ratio_ci", "mu4_ratio", "mu4_ratio_ci", "a3", "a3_ci", "c1", "c3",
        "mu2", "mu4", "T", "strength", "h", "collisions", "violations", "cpu_s", "wall_s",
        "ns_per_candidate"};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    sim_status status = SIM_OK;
    double wall_total = 0.0;
    char name[160];
    for (size_t i = 0; i < rows && status == SIM_OK; i++) {
        const double alpha = o->size == VFY_PAPER ? paper_alphas[i] : quick_alpha[th];
        ms_run *run = &runs[i];
        status = ms_simulate(c, o, th, alpha, run, msg, msglen);
        if (status != SIM_OK)
            break;
        const double a2 = st_mean(run, SIM_STEADY_A2), a2_ci = st_ci(run, SIM_STEADY_A2);
        const double c10 = ref_sonine_a2_white_noise(alpha, 3.0);
        const double c5 = ref_sonine_a2_gaussian(alpha, 3.0);
        const double c40 = ref_sonine_a2_gaussian_alt(alpha, 3.0);
        const double c76 = ref_sonine_a2_nongaussian_fit(alpha, 3.0);
        const double m2_0 = ref_sonine_mu2_0(alpha, 3.0), m2_1 = ref_sonine_mu2_1(alpha, 3.0);
        const double m4_0 = ref_sonine_mu4_0(alpha, 3.0), m4_1 = ref_sonine_mu4_1(alpha, 3.0);

        vfy_check_count(r, vfy_name(name, sizeof name, "%s alpha=%.2f majorant violations",
                                    c->name, alpha),
                        run->res.counts.violations, 0);
        if (alpha == 1.0) {   /* elastic: a Maxwellian whatever the thermostat */
            vfy_check_absolute(r, vfy_name(name, sizeof name, "%s alpha=1 a2 (elastic: 0)",
                                           c->name),
                               a2, 0.0, a2_ci);
        } else if (th == MS_WHITE) {
            vfy_check_absolute(r, vfy_name(name, sizeof name, "%s alpha=%.2f a2 vs (C.10)",
                                           c->name, alpha),
                               a2, c10, ms_allowed(o, A2_WHITE_TOL, a2_ci));
        } else if (th == MS_GAUSSIAN) {
            vfy_name(name, sizeof name, "%s alpha=%.2f a2 closer to (C.40) than to (C.5): "
                     "|a2 - C40| - |a2 - C5|", c->name, alpha);
            if (alpha > 0.4 + 1e-12)
                ;   /* paper C §4.2: (40) is the better estimate for alpha < 0.5 only */
            else if (a2_ci < 0.5 * fabs(c5 - c40))
                vfy_check_range(r, name, fabs(a2 - c40) - fabs(a2 - c5), -INFINITY, 0.0);
            else {
                char why[200];
                snprintf(why, sizeof why, "a2 = %.4f ± %.4f cannot tell (C.40) = %.4f from "
                         "(C.5) = %.4f", a2, a2_ci, c40, c5);
                vfy_skip(r, name, why);
            }
        } else {
            vfy_check_range(r, vfy_name(name, sizeof name, "%s alpha=%.2f a2 < 0: a2 + ci",
                                        c->name, alpha),
                            a2 + a2_ci, -INFINITY, 0.0);
            vfy_check_absolute(r, vfy_name(name, sizeof name, "%s alpha=%.2f a2 vs (C.76) "
                                           "within 25%%", c->name, alpha),
                               a2, c76, ms_allowed(o, A2_NG_RTOL * fabs(c76), a2_ci));
        }

        /* Paper C Figure 6: the Gaussian thermostat's a3 "remains small for
         * alpha >= 0.6, but for larger dissipation |a3| increases rapidly". */
        const double a3 = st_mean(run, SIM_STEADY_A3), a3_ci = st_ci(run, SIM_STEADY_A3);
        if (th == MS_GAUSSIAN && alpha >= 0.6 - 1e-12)
            vfy_check_absolute(r, vfy_name(name, sizeof name, "%s alpha=%.2f |a3| small",
                                           c->name, alpha),
                               a3, 0.0, ms_allowed(o, A3_SMALL, a3_ci));
        else if (th == MS_GAUSSIAN && alpha <= 0.3 + 1e-12)
            vfy_check_range(r, vfy_name(name, sizeof name, "%s alpha=%.2f |a3| large: |a3|%s",
                                        c->name, alpha, o->size == VFY_QUICK ? " + ci" : ""),
                            fabs(a3) + (o->size == VFY_QUICK ? a3_ci : 0.0), A3_LARGE,
                            INFINITY);

        const double mu2 = st_mean(run, SIM_STEADY_MU2), mu4 = st_mean(run, SIM_STEADY_MU4);
        const double events = (double)run->res.counts.candidates;
        vfy_table_cell(&table, "%.2f", alpha);
        vfy_table_cell(&table, "%.5f", a2);
        vfy_table_cell(&table, "%.5f", a2_ci);
        vfy_table_cell(&table, "%.5f", c10);
        vfy_table_cell(&table, "%.5f", ref_sonine_a2_white_noise_ratio(alpha, 3.0));
        vfy_table_cell(&table, "%.5f", c5);
        vfy_table_cell(&table, "%.5f", c40);
        vfy_table_cell(&table, "%.5f", ref_sonine_a2_nongaussian(alpha, 3.0));
        vfy_table_cell(&table, "%.5f", c76);
        vfy_table_number(&table, alpha < 1.0, "%.5f", (mu2 - m2_0) / m2_1);
        vfy_table_number(&table, alpha < 1.0, "%.5f", st_ci(run, SIM_STEADY_MU2) / m2_1);
        vfy_table_cell(&table, "%.5f", (mu4 - m4_0) / m4_1);
        vfy_table_cell(&table, "%.5f", st_ci(run, SIM_STEADY_MU4) / m4_1);
        vfy_table_cell(&table, "%.5f", st_mean(run, SIM_STEADY_A3));
        vfy_table_cell(&table, "%.5f", st_ci(run, SIM_STEADY_A3));
        vfy_table_cell(&table, "%.5f", st_mean(run, SIM_STEADY_C1));
        vfy_table_cell(&table, "%.5f", st_mean(run, SIM_STEADY_C3));
        vfy_table_cell(&table, "%.5f", mu2);
        vfy_table_cell(&table, "%.5f", mu4);
        vfy_table_cell(&table, "%.4f", st_mean(run, SIM_STEADY_T));
        vfy_table_cell(&table, "%.5g", run->solver.heating.strength);
        vfy_table_cell(&table, "%g", run->h);
        vfy_table_cell(&table, "%llu", (unsigned long long)run->res.counts.collisions);
        vfy_table_cell(&table, "%llu", (unsigned long long)run->res.counts.violations);
        vfy_table_cell(&table, "%.2f", run->res.cpu_seconds);
        vfy_table_cell(&table, "%.2f", run->res.wall_seconds);
        vfy_table_cell(&table, "%.1f", events > 0 ? 1e9 * run->res.cpu_seconds / events : 0.0);
        wall_total += run->res.wall_seconds;
        status = vfy_write_rows_so_far(o, c->name, &table, &run->solver, msg, msglen);
    }
    char comment[600] = "";
    if (status == SIM_OK) {
        char sizes[300], title[200], notes[3000];
        vfy_run_comment(&runs[0].solver, comment, sizeof comment);
        snprintf(title, sizeof title, "%s: paper C %s, a2 against alpha, %s (%s sizes)",
                 c->name, ms_info[th].figure, ms_info[th].label,
                 o->size == VFY_PAPER ? "paper" : "quick");
        snprintf(notes, sizeof notes,
                 "%s; %s.\n\nEach row is one steady state (time-step scheme, contact rule, "
                 "SPEC §5). a2, a3 = time averages of the reduced cumulants; _ci = 3.2 x the "
                 "standard error over the N independent ensembles. Sonine estimates (paper "
                 "C): C10, C32 white noise; C5, C40 Gaussian; C50, C76 non-Gaussian. "
                 "mu2_ratio = (mu2 - mu2^(0))/mu2^(1), mu4_ratio = (mu4 - mu4^(0))/mu4^(1) "
                 "(both equal a2 where the first Sonine expansion holds; mu2 by pair "
                 "sampling, Eq. (67)). c1 = <c>, c3 = <c^3>. T = the steady temperature "
                 "(the thermostat strength is set so that it is close to T0 = 1). "
                 "ns_per_candidate = CPU time per candidate collision, everything included. "
                 "Checks: %s. Total wall time %.1f s.",
                 comment, ms_sizes(&runs[0], sizes, sizeof sizes),
                 th == MS_WHITE ? "|a2 - C10| <= 0.006 at every alpha"
                 : th == MS_GAUSSIAN ? "a2 closer to C40 than to C5 for alpha <= 0.4; |a3| <= "
                                       "0.01 for alpha >= 0.6 and >= 0.03 for alpha <= 0.3 "
                                       "(Figure 6)"
                                     : "a2 < 0 (with its ci) and within 25% of C76 for alpha < 1",
                 wall_total);
        status = vfy_write_case_tables(o, c->name, &table, comment, title, notes, msg, msglen);
    }
    if (status == SIM_OK) {
        /* The figure: a2, (mu2 - mu2^(0))/mu2^(1), (mu4 - mu4^(0))/mu4^(1) and
         * the Sonine curves (paper C Figures 1, 4, 8), plus a3 (Figure 6). */
        enum { NF = 81 };
        double x[MS_ROWS_MAX], a2[MS_ROWS_MAX], a2c[MS_ROWS_MAX], r2[MS_ROWS_MAX],
            r2c[MS_ROWS_MAX], r4[MS_ROWS_MAX], r4c[MS_ROWS_MAX], a3[MS_ROWS_MAX],
            a3c[MS_ROWS_MAX];
        size_t np = 0;
        for (size_t i = 0; i < rows; i++) {
            const ms_run *run = &runs[i];
            const double al = run->alpha;
            if (al >= 1.0)
                continue;   /* the ratios are 0/0 in the elastic limit */
            x[np] = al;
            a2[np] = st_mean(run, SIM_STEADY_A2);
            a2c[np] = st_ci(run, SIM_STEADY_A2);
            r2[np] = (st_mean(run, SIM_STEADY_MU2) - ref_sonine_mu2_0(al, 3.0))
                     / ref_sonine_mu2_1(al, 3.0);
            r2c[np] = st_ci(run, SIM_STEADY_MU2) / ref_sonine_mu2_1(al, 3.0);
            r4[np] = (st_mean(run, SIM_STEADY_MU4) - ref_sonine_mu4_0(al, 3.0))
                     / ref_sonine_mu4_1(al, 3.0);
            r4c[np] = st_ci(run, SIM_STEADY_MU4) / ref_sonine_mu4_1(al, 3.0);
            a3[np] = st_mean(run, SIM_STEADY_A3);
            a3c[np] = st_ci(run, SIM_STEADY_A3);
            np++;
        }
        double xf[NF], y1[NF], y2[NF];
        for (size_t k = 0; k < NF; k++) {
            xf[k] = 0.2 + 0.8 * (double)k / (NF - 1);
            y1[k] = th == MS_WHITE      ? ref_sonine_a2_white_noise(xf[k], 3.0)
                    : th == MS_GAUSSIAN ? ref_sonine_a2_gaussian(xf[k], 3.0)
                                        : ref_sonine_a2_nongaussian(xf[k], 3.0);
            y2[k] = th == MS_WHITE      ? ref_sonine_a2_white_noise_ratio(xf[k], 3.0)
                    : th == MS_GAUSSIAN ? ref_sonine_a2_gaussian_alt(xf[k], 3.0)
                                        : ref_sonine_a2_nongaussian_fit(xf[k], 3.0);
        }
        static const char *const curves[MS_THERMOSTATS][2] = {
            {"a2 (C.10)", "a2 (C.32)"}, {"a2 (C.5)", "a2 (C.40)"}, {"a2 (C.50)", "a2 (C.76)"}};
        const char *series[] = {"a2", "(mu2-mu2_0)/mu2_1", "(mu4-mu4_0)/mu4_1"};
        const double *ys[] = {a2, r2, r4}, *cs[] = {a2c, r2c, r4c}, *yf[] = {y1, y2};
        char title[200], fname[160];
        snprintf(title, sizeof title, "%s: a2 against alpha, %s (paper C %s)", c->name,
                 ms_info[th].label, ms_info[th].figure);
        ms_figure f = {c->name, title, "alpha", "a2", 0, np, x, 3, series, ys, cs,
                       NF, xf, 2, curves[th], yf, comment};
        int rc = np > 0 ? ms_write_figure(o, &f) : 0;
        if (rc == 0 && th == MS_GAUSSIAN && np > 0) {
            const char *s3[] = {"a3"};
            const double *y3[] = {a3}, *c3[] = {a3c};
            snprintf(fname, sizeof fname, "%s-a3", c->name);
            snprintf(title, sizeof title, "%s: a3 against alpha, Gaussian thermostat (paper C "
                     "Figure 6)", c->name);
            ms_figure f3 = {fname, title, "alpha", "a3", 0, np, x, 1, s3, y3, c3,
                            0, NULL, 0, NULL, NULL, comment};
            rc = ms_write_figure(o, &f3);
        }
        if (rc != 0)
            status = vfy_io_error(c->name, msg, msglen);
    }
    for (size_t i = 0; i < rows; i++)   /* rows not run are zeroed: harmless */
        sim_ensemble_result_free(&runs[i].res);
    free(runs);
    vfy_table_free(&table);
    return status;
}

/* ------------------------------------------------------------ Table 1 */

sim_status vfy_case_ms_table1(const vfy_case *c, const vfy_options *o, vfy_report *r,
                              char *msg, size_t msglen)
{
    static const size_t relation[MS_THERMOSTATS] = {
        SIM_STEADY_MU4_WHITE, SIM_STEADY_MU4_GAUSSIAN, SIM_STEADY_MU4_NONGAUSSIAN};
    static const char *const short_name[MS_THERMOSTATS] = {"white", "gaussian", "nongaussian"};
    static const char *const cols[] = {
        "alpha", "thermostat", "mu4_0", "mu4_0_paper", "mu4_direct", "mu4_direct_ci",
        "mu4_direct_paper", "mu4_indirect", "mu4_indirect_ci", "mu4_indirect_paper",
        "gap_percent", "gap_ci_percent", "a2", "a2_ci", "cpu_s", "wall_s"};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    const size_t nalpha = o->size == VFY_PAPER ? 4 : 1;
    const size_t first = o->size == VFY_PAPER ? 0 : 1;   /* quick: alpha = 0.4 */
    sim_status status = SIM_OK;
    double wall_total = 0.0;
    char comment[600] = "", sizes[300] = "", name[160];
    for (size_t ia = first; ia < first + nalpha && status == SIM_OK; ia++) {
        const double *paper = paper_table1[ia];
        const double alpha = paper[0];
        for (int th = 0; th < MS_THERMOSTATS && status == SIM_OK; th++) {
            ms_run run;
            status = ms_simulate(c, o, (ms_thermostat)th, alpha, &run, msg, msglen);
            if (status != SIM_OK) {
                sim_ensemble_result_free(&run.res);
                break;
            }
            if (!comment[0]) {
                vfy_run_comment(&run.solver, comment, sizeof comment);
                ms_sizes(&run, sizes, sizeof sizes);
            }
            const double direct = st_mean(&run, SIM_STEADY_MU4);
            const double direct_ci = st_ci(&run, SIM_STEADY_MU4);
            const double ind = st_mean(&run, relation[th]), ind_ci = st_ci(&run, relation[th]);
            const double gap = direct - ind;
            const double m4_0 = ref_sonine_mu4_0(alpha, 3.0);
            const double p_direct = paper[2 + 2 * th], p_ind = paper[3 + 2 * th];

            vfy_check_count(r, vfy_name(name, sizeof name, "%s alpha=%.1f %s majorant "
                                        "violations", c->name, alpha, short_name[th]),
                            run.res.counts.violations, 0);
            vfy_check_absolute(r, vfy_name(name, sizeof name, "%s alpha=%.1f %s mu4 direct vs "
                                           "indirect (0.2%%)", c->name, alpha, short_name[th]),
                               direct, ind,
                               ms_allowed(o, MU4_GAP_RTOL * fabs(ind), direct_ci + ind_ci));
            const char *note = paper_table1_note[ia][th];
            vfy_name(name, sizeof name, "%s alpha=%.1f %s mu4 direct vs paper C Table 1",
                     c->name, alpha, short_name[th]);
            if (note) {
                char why[300];
                snprintf(why, sizeof why, "%.4f ± %.4f vs %.3f (%+.2f%%), not judged: %s",
                         direct, direct_ci, p_direct, 100.0 * (direct / p_direct - 1.0), note);
                vfy_skip(r, name, why);
            } else
                vfy_check_absolute(r, name, direct, p_direct,
                                   ms_allowed(o, fmax(direct_ci, MU4_PAPER_RTOL * p_direct),
                                              direct_ci));
            vfy_name(name, sizeof name, "%s alpha=%.1f %s mu4 indirect vs paper C Table 1",
                     c->name, alpha, short_name[th]);
            if (note) {
                char why[300];
                snprintf(why, sizeof why, "%.4f ± %.4f vs %.3f (%+.2f%%), not judged: %s", ind,
                         ind_ci, p_ind, 100.0 * (ind / p_ind - 1.0), note);
                vfy_skip(r, name, why);
            } else
                vfy_check_absolute(r, name, ind, p_ind,
                                   ms_allowed(o, fmax(ind_ci, MU4_PAPER_RTOL * p_ind), ind_ci));

            vfy_table_cell(&table, "%.1f", alpha);
            vfy_table_cell(&table, "%s", short_name[th]);
            vfy_table_cell(&table, "%.4f", m4_0);
            vfy_table_cell(&table, "%.3f", paper[1]);
            vfy_table_cell(&table, "%.4f", direct);
            vfy_table_cell(&table, "%.4f", direct_ci);
            vfy_table_cell(&table, "%.3f", p_direct);
            vfy_table_cell(&table, "%.4f", ind);
            vfy_table_cell(&table, "%.4f", ind_ci);
            vfy_table_cell(&table, "%.3f", p_ind);
            vfy_table_cell(&table, "%+.3f", 100.0 * gap / ind);
            vfy_table_cell(&table, "%.3f", 100.0 * (direct_ci + ind_ci) / ind);
            vfy_table_cell(&table, "%.5f", st_mean(&run, SIM_STEADY_A2));
            vfy_table_cell(&table, "%.5f", st_ci(&run, SIM_STEADY_A2));
            vfy_table_cell(&table, "%.2f", run.res.cpu_seconds);
            vfy_table_cell(&table, "%.2f", run.res.wall_seconds);
            wall_total += run.res.wall_seconds;
            status = vfy_write_rows_so_far(o, c->name, &table, &run.solver, msg, msglen);
            sim_ensemble_result_free(&run.res);
        }
    }
    if (status == SIM_OK) {
        char title[200], notes[3000];
        snprintf(title, sizeof title, "%s: paper C Table 1, mu4 direct and through the exact "
                 "steady relations (%s sizes)", c->name,
                 o->size == VFY_PAPER ? "paper" : "quick");
        snprintf(notes, sizeof notes,
                 "%s; %s.\n\nmu4_direct: pair sampling of Phi4 (paper C Eqs. (66), (67)); "
                 "mu4_indirect: the thermostat's exact steady relation evaluated per sample "
                 "with the sampled mu2 — white noise mu4 = 5 mu2 (Eq. (23)), Gaussian mu4 = "
                 "5 (1 + a2) mu2 (Eq. (38)), non-Gaussian mu4 = 2 mu2 <c^3>/<c> (Eq. (44)). "
                 "_ci = 3.2 x the standard error over the N independent ensembles; "
                 "gap_percent = 100 (direct - indirect)/indirect, gap_ci_percent the sum of "
                 "the two half-widths in percent (a bound on the gap's own half-width: "
                 "both come from the same samples). _paper: paper C's Table 1. Checks: "
                 "direct and indirect within 0.2%%; each within max(ci, 0.3%%) of the "
                 "paper's value.%s Total wall time %.1f s.",
                 comment, sizes, o->size == VFY_PAPER ? paper_table1_long_note : "",
                 wall_total);
        status = vfy_write_case_tables(o, c->name, &table, comment, title, notes, msg, msglen);
    }
    vfy_table_free(&table);
    return status;
}

/* --------------------------------------------------------------- tails */

/* Weighted least squares of ln f = ln K - A c^b over the bins with
 * c >= c_lo and a relative half-width below 0.5; returns the number of
 * bins used. */
static size_t ms_fit_tail(const sim_scene *s, const double *f, const double *ci, size_t bins,
                          double b, double c_lo, double *A, double *A_sd, double *K)
{
    double x[512], y[512], w[512];
    size_t m = 0;
    for (size_t k = 0; k < bins && m < 512; k++) {
        double cc = sim_steady_bin_centre(s, k);
        if (cc < c_lo || !(f[k] > 0.0) || !(ci[k] < 0.5 * f[k]))
            continue;
        double sigma = ci[k] / SIM_LAMBDA_P / f[k];   /* of ln f */
        x[m] = pow(cc, b);
        y[m] = log(f[k]);
        w[m] = 1.0 / (sigma * sigma);
        m++;
    }
    *A = *A_sd = *K = NAN;
    if (m < 3)
        return m;
    double c0, c1, cov00, cov01, cov11, chi2;
    gsl_fit_wlinear(x, 1, w, 1, y, 1, m, &c0, &c1, &cov00, &cov01, &cov11, &chi2);
    *A = -c1;
    *A_sd = sqrt(cov11);
    *K = exp(c0);
    return m;
}

sim_status vfy_case_ms_tails(const vfy_case *c, const vfy_options *o, vfy_report *r, char *msg,
                             size_t msglen)
{
    static const struct {
        ms_thermostat th;
        double alpha, b, A_paper, K_paper, ratio4_paper;
    } rows[] = {
        {MS_WHITE, 0.4, 1.5, 1.99, 1.3, 8.0},
        {MS_WHITE, 0.5, 1.5, 2.11, 2.2, 5.0},
        {MS_GAUSSIAN, 0.2, 1.0, 3.82, 7.0, 80.0},
        {MS_GAUSSIAN, 0.4, 1.0, 4.41, 31.0, 34.0},
    };
    static const char *const cols[] = {
        "thermostat", "alpha", "b", "A_theory", "A_paper", "A_fit_c2", "A_fit_c3",
        "A_fit_c3_sd", "fit_bins_c3", "K", "K_ci", "K_paper", "f_over_phi_c4",
        "f_over_phi_c4_paper", "cpu_s", "wall_s"};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    sim_status status = SIM_OK;
    double wall_total = 0.0;
    char comment[600] = "", sizes[300] = "", name[160];
    for (size_t i = 0; i < sizeof rows / sizeof *rows && status == SIM_OK; i++) {
        ms_run run;
        status = ms_simulate(c, o, rows[i].th, rows[i].alpha, &run, msg, msglen);
        if (status != SIM_OK) {
            sim_ensemble_result_free(&run.res);
            break;
        }
        const sim_scene *s = &run.solver;
        const size_t bins = s->steady.bins;
        if (bins < 8 || s->steady.c_max < 4.5) {
            sim_ensemble_result_free(&run.res);
            snprintf(msg, msglen, "%s: the tails need steady.bins >= 8 and steady.c_max >= 4.5",
                     s->file);
            status = SIM_EINVAL;
            break;
        }
        if (!comment[0]) {
            vfy_run_comment(s, comment, sizeof comment);
            ms_sizes(&run, sizes, sizeof sizes);
        }
        const double alpha = rows[i].alpha, b = rows[i].b;
        /* the theory's A with the simulated mu2 (as the paper does) and with
         * the Sonine mu2 (reference/sonine.h) */
        const double mu2 = st_mean(&run, SIM_STEADY_MU2);
        const double A_theory = rows[i].th == MS_WHITE ? ref_sonine_tail_A_white_noise_mu2(mu2, 3.0)
                                                      : ref_sonine_tail_A_gaussian_mu2(mu2, 3.0);
        double *f = malloc(bins * sizeof *f), *fc = malloc(bins * sizeof *fc);
        double *G = malloc(bins * sizeof *G), *Gc = malloc(bins * sizeof *Gc);
        double *Gphi = malloc(bins * sizeof *Gphi), *cc = malloc(bins * sizeof *cc);
        if (!f || !fc || !G || !Gc || !Gphi || !cc) {
            free(f), free(fc), free(G), free(Gc), free(Gphi), free(cc);
            sim_ensemble_result_free(&run.res);
            snprintf(msg, msglen, "out of memory");
            status = SIM_ENOMEM;
            break;
        }
        /* G(c) = e^{A c^b} f(c) with the theory's A; its plateau K over the
         * shells with c >= 3 (weighted mean); f/phi at c = 4, interpolated
         * geometrically between the two shells whose centres straddle it,
         * each against the Maxwellian averaged over the same shell. */
        double K_num = 0.0, K_den = 0.0, r_lo = NAN, r_hi = NAN, r_lo_ci = NAN;
        for (size_t k = 0; k < bins; k++) {
            f[k] = st_mean(&run, SIM_STEADY_BIN0 + k);
            fc[k] = st_ci(&run, SIM_STEADY_BIN0 + k);
            cc[k] = sim_steady_bin_centre(s, k);
            const double e = exp(A_theory * pow(cc[k], b));
            G[k] = e * f[k];
            Gc[k] = e * fc[k];
            Gphi[k] = e * pow(M_PI, -1.5) * exp(-cc[k] * cc[k]);
            if (cc[k] >= 3.0 && f[k] > 0.0 && fc[k] < 0.5 * f[k]) {
                const double w = 1.0 / (Gc[k] * Gc[k]);
                K_num += w * G[k];
                K_den += w;
            }
            const double lo = sim_steady_bin_lower(s, k), hi = sim_steady_bin_lower(s, k + 1);
            const double shell = (erf(hi) - 2.0 * hi * exp(-hi * hi) / sqrt(M_PI))
                                 - (erf(lo) - 2.0 * lo * exp(-lo * lo) / sqrt(M_PI));
            const double phi = shell / (4.0 * M_PI / 3.0 * (hi * hi * hi - lo * lo * lo));
            if (cc[k] <= 4.0) {
                r_lo = f[k] / phi;
                r_lo_ci = fc[k] / phi;
            } else if (isnan(r_hi))
                r_hi = f[k] / phi;
        }
        const double K = K_num / K_den, K_ci = 1.0 / sqrt(K_den);   /* weights 1/ci^2 */
        const size_t k_lo = (size_t)floor(4.0 / (s->steady.c_max / (double)bins) - 0.5);
        const double t4 = (4.0 - cc[k_lo]) / (cc[k_lo + 1] - cc[k_lo]);
        const double ratio4 = exp((1.0 - t4) * log(r_lo) + t4 * log(r_hi));
        double A_fit2, A_sd2, K2, A_fit, A_sd, K_fit;
        ms_fit_tail(s, f, fc, bins, b, 2.0, &A_fit2, &A_sd2, &K2);
        const size_t used = ms_fit_tail(s, f, fc, bins, b, 3.0, &A_fit, &A_sd, &K_fit);

        const char *th_name = rows[i].th == MS_WHITE ? "white" : "gaussian";
        vfy_check_count(r, vfy_name(name, sizeof name, "%s %s alpha=%.1f majorant violations",
                                    c->name, th_name, alpha),
                        run.res.counts.violations, 0);
        vfy_check_relative(r, vfy_name(name, sizeof name, "%s %s alpha=%.1f A (Eq. %s with the "
                                       "simulated mu2) vs paper", c->name, th_name, alpha,
                                       rows[i].th == MS_WHITE ? "36" : "42"),
                           A_theory, rows[i].A_paper, 0.01);
        vfy_name(name, sizeof name, "%s %s alpha=%.1f fitted A (c >= 3) vs theory", c->name,
                 th_name, alpha);
        if (used >= 5)
            vfy_check_absolute(r, name, A_fit, A_theory,
                               ms_allowed(o, A_FIT_RTOL * A_theory, SIM_LAMBDA_P * A_sd));
        else
            vfy_skip(r, name, "fewer than 5 tail shells with a relative half-width below 0.5");
        vfy_name(name, sizeof name, "%s %s alpha=%.1f plateau K of G(c), c >= 3, vs paper",
                 c->name, th_name, alpha);
        if (used >= 5)
            vfy_check_absolute(r, name, K, rows[i].K_paper,
                               ms_allowed(o, K_RTOL * rows[i].K_paper, K_ci));
        else
            vfy_skip(r, name, "fewer than 5 tail shells with a relative half-width below 0.5");
        vfy_name(name, sizeof name, "%s %s alpha=%.1f f/phi at c = 4 vs paper", c->name,
                 th_name, alpha);
        if (r_lo_ci < 0.5 * r_lo && isfinite(ratio4))
            vfy_check_relative(r, name, ratio4, rows[i].ratio4_paper, RATIO4_RTOL);
        else
            vfy_skip(r, name, "the shells at c = 4 hold too few particles at these sizes");

        vfy_table_cell(&table, "%s", th_name);
        vfy_table_cell(&table, "%.1f", alpha);
        vfy_table_cell(&table, "%.1f", b);
        vfy_table_cell(&table, "%.4f", A_theory);
        vfy_table_cell(&table, "%.2f", rows[i].A_paper);
        vfy_table_cell(&table, "%.4f", A_fit2);
        vfy_table_cell(&table, "%.4f", A_fit);
        vfy_table_cell(&table, "%.4f", A_sd);
        vfy_table_cell(&table, "%zu", used);
        vfy_table_cell(&table, "%.3g", K);
        vfy_table_cell(&table, "%.2g", K_ci);
        vfy_table_cell(&table, "%.3g", rows[i].K_paper);
        vfy_table_cell(&table, "%.3g", ratio4);
        vfy_table_cell(&table, "%.3g", rows[i].ratio4_paper);
        vfy_table_cell(&table, "%.2f", run.res.cpu_seconds);
        vfy_table_cell(&table, "%.2f", run.res.wall_seconds);
        wall_total += run.res.wall_seconds;

        /* G(c) with the Maxwellian's beside it (paper C Figures 3, 7) */
        char fname[160], title[200];
        snprintf(fname, sizeof fname, "%s-%s-%.1f", c->name, th_name, alpha);
        snprintf(title, sizeof title, "%s: G(c) = exp(%.3f c^%.1f) f(c), %s, alpha = %.1f",
                 c->name, A_theory, b, th_name, alpha);
        const char *series[] = {"G (DSMC)"}, *curves[] = {"G of the Maxwellian"};
        const double *ys[] = {G}, *cs[] = {Gc}, *yf[] = {Gphi};
        ms_figure fig = {fname, title, "c", "G(c)", 1, bins, cc, 1, series, ys, cs,
                         bins, cc, 1, curves, yf, comment};
        if (ms_write_figure(o, &fig) != 0)
            status = vfy_io_error(fname, msg, msglen);
        else
            status = vfy_write_rows_so_far(o, c->name, &table, &run.solver, msg, msglen);
        free(f), free(fc), free(G), free(Gc), free(Gphi), free(cc);
        sim_ensemble_result_free(&run.res);
    }
    if (status == SIM_OK) {
        char title[200], notes[3000];
        snprintf(title, sizeof title, "%s: paper C high-energy tails (%s sizes)", c->name,
                 o->size == VFY_PAPER ? "paper" : "quick");
        snprintf(notes, sizeof notes,
                 "%s; %s.\n\nf(c) = the reduced speed distribution averaged over shells of "
                 "width c_max/bins (steady.h). Theory (paper C): white noise f ~ K exp(-A "
                 "c^1.5), A = (2/3)(2 d beta_1/mu2)^(1/2) (Eq. (36)); Gaussian f ~ K exp(-A c), "
                 "A = d beta_1/mu2 (Eq. (42)); A_theory uses the simulated mu2, as the paper "
                 "does. A_fit_c2, A_fit_c3: weighted least squares of ln f = ln K - A c^b over "
                 "the shells with c >= 2 (resp. 3) whose relative half-width is below 0.5 "
                 "(A_fit_c3_sd its standard error, fit_bins_c3 the shells used): the "
                 "asymptotic A is approached from below as the range moves out. K = the "
                 "plateau of G(c) = exp(A_theory c^b) f(c), its weighted mean over the same "
                 "shells with c >= 3 (K_ci its confidence half-width); paper C reads K off its "
                 "figures. f_over_phi_c4: f over the Maxwellian at c = 4 (each shell against "
                 "the Maxwellian averaged over it, interpolated geometrically between the two "
                 "shells around c = 4). Figures <case>-<thermostat>-<alpha>.png: G(c) with "
                 "the Maxwellian's G. Checks: A_theory within 1%% of the paper's A; A_fit_c3 "
                 "within 5%% of A_theory; K within 20%% and f/phi at c = 4 within 35%% of the "
                 "paper's values, which are read off its figures (at quick sizes each "
                 "tolerance is widened by the value's own half-width). Total wall time "
                 "%.1f s.",
                 comment, sizes, wall_total);
        status = vfy_write_case_tables(o, c->name, &table, comment, title, notes, msg, msglen);
    }
    vfy_table_free(&table);
    return status;
}
