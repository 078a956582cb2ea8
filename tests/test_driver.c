/* The case driver (verify/driver/driver.h), the statistics (stats.h) and the metrics (metrics.h):
 * every metric moves with a wrong answer, every rule and guard can fail or
 * skip, templates expand as documented, sweeps enumerate their rows, and a
 * small description run end to end passes with the right solver and fails
 * with a wrong one. */
#include "test_verify_util.h"

#include <gsl/gsl_cdf.h>
#include <unistd.h>

#include "driver.h"
#include "figure.h"
#include "metrics.h"
#include "references.h"
#include "scene_ini.h"
#include "scene_refs.h"

/* A description's column words: HEADER[=VALUE]:FORMAT, and each malformed
 * word named. */
static void test_columns(void **state)
{
    (void)state;
    vfy_column *cols;
    size_t n;
    char *text, msg[200];
    assert_int_equal(vfy_parse_columns("n:%.0f  candidates=events:%.0f\n scheme:%s "
                                       VFY_COST_COLUMNS, &cols, &n, &text, msg, sizeof msg), 0);
    assert_int_equal(n, 7);
    assert_string_equal(cols[0].header, "n");
    assert_null(cols[0].value);
    assert_string_equal(cols[0].format, "%.0f");
    assert_string_equal(cols[1].header, "candidates");
    assert_string_equal(cols[1].value, "events");
    assert_string_equal(cols[2].format, "%s");
    assert_string_equal(cols[6].header, "ns_per_event");
    assert_string_equal(cols[6].format, "%.1f");
    free(cols);
    free(text);
    static const char *const bad[] = {"n", "n:", ":%.0f", "n:.0f", "=v:%g", "h=:%g",
                                      "a:%g:b=c", NULL};
    for (size_t k = 0; bad[k]; k++) {
        char spec[64], want[120];
        snprintf(spec, sizeof spec, "T:%%.5f %s", bad[k]);
        assert_int_equal(vfy_parse_columns(spec, &cols, &n, &text, msg, sizeof msg), -1);
        snprintf(want, sizeof want, "column '%s' is not HEADER[=VALUE]:FORMAT", bad[k]);
        assert_string_equal(msg, want);
        free(cols);
        free(text);
    }
}

static void test_values(void **state)
{
    (void)state;
    vfy_values v = {0};
    for (int i = 0; i < 100; i++) {   /* grows past its first capacity */
        char name[16];
        snprintf(name, sizeof name, "x%d", i);
        assert_int_equal(vfy_values_set(&v, name, i), 0);
    }
    vfy_values_set(&v, "x7", 70.0);   /* replaced, not added */
    assert_int_equal(v.count, 100);
    assert_close(vfy_values_get(&v, "x7"), 70.0, 0, 0);
    assert_close(vfy_values_get(&v, "x99"), 99.0, 0, 0);
    assert_true(isnan(vfy_values_get(&v, "absent")));
    assert_false(vfy_values_has(&v, "absent"));
    vfy_values_free(&v);
}

/* Paper A's Emax on three points: the right mean gives the largest relative
 * error; a wrong one moves it. */
static void test_pure_metrics(void **state)
{
    (void)state;
    const double exact[3] = {1.0, 2.0, 4.0};
    double mean[3] = {1.01, 1.98, 4.0};
    assert_close(vfy_max_rel_err(mean, exact, 3), 0.01, 1e-12, 0);
    mean[2] = 4.2;
    assert_close(vfy_max_rel_err(mean, exact, 3), 0.05, 1e-12, 0);
    assert_close(vfy_max_ratio_dev(mean, exact, 3), 0.05, 1e-12, 0);
    const double ci[3] = {0.01, 0.1, 0.1};
    assert_close(vfy_max_rel_ci(ci, exact, 3), 0.05, 1e-12, 0);
    const double ux[2] = {0.0, 3.0}, uy[2] = {1.0, 4.0}, uz[2] = {0.0, 0.0};
    assert_close(vfy_max_norm3(ux, uy, uz, 2), 5.0, 1e-15, 0);
    /* a term that is NaN (not reported) makes the maximum NaN, wherever it is */
    mean[0] = NAN;
    assert_true(isnan(vfy_max_rel_err(mean, exact, 3)));
    mean[0] = 1.01;
    mean[2] = NAN;
    assert_true(isnan(vfy_max_rel_err(mean, exact, 3)));
    assert_true(isnan(vfy_max_ratio_dev(mean, exact, 3)));
    mean[2] = 4.2;
    assert_close(vfy_fictitious_fraction(25.0, 100.0), 0.75, 1e-15, 0);
    assert_close(vfy_fictitious_fraction(0.0, 0.0), 0.0, 0, 0);   /* no events */
    /* the first point (t = 0) is not counted: its variances are equal or 0 */
    const double va[4] = {1.0, 2.0, 3.0, 4.0}, vb[4] = {0.0, 1.0, 1.0, 4.0};
    double mean_ratio, min_ratio;
    vfy_variance_ratio(va, vb, 4, &mean_ratio, &min_ratio);
    assert_close(mean_ratio, 2.0, 1e-15, 0);
    assert_close(min_ratio, 1.0, 0, 0);
}

/* T_i = 2 + 3/n_i is extrapolated to 2 with chi^2 = 0; data with an
 * O(1/sqrt n) error do not fit the O(1/n) model (large chi^2). */
static void test_extrapolation(void **state)
{
    (void)state;
    const size_t n[4] = {64, 256, 1024, 4096};
    double T[4], sigma[4] = {1e-3, 1e-3, 1e-3, 1e-3}, T_inf, sd, chi2;
    for (int i = 0; i < 4; i++)
        T[i] = 2.0 + 3.0 / (double)n[i];
    vfy_extrapolate_inverse_n(4, n, T, sigma, &T_inf, &sd, &chi2);
    assert_close(T_inf, 2.0, 1e-12, 0);
    assert_true(chi2 < 1e-12);
    for (int i = 0; i < 4; i++)
        T[i] = 2.0 + 1.0 / sqrt((double)n[i]);
    vfy_extrapolate_inverse_n(4, n, T, sigma, &T_inf, &sd, &chi2);
    assert_true(chi2 > 100.0);
}

/* The tail probability of the normal bound 3.2 needs 3.916 with 15 degrees
 * of freedom (16 ensembles); the two-sided p = 0.999 quantile is 4.073
 * (GSL; tables give 4.073); many degrees of freedom give the normal one. */
static void test_student_t(void **state)
{
    (void)state;
    double p = gsl_cdf_ugaussian_P(3.2);
    assert_close(vfy_student_t(p, 15.0), 3.916474, 1e-6, 0);
    assert_close(vfy_student_t(0.9995, 15.0), 4.072765, 1e-6, 0);
    assert_close(vfy_student_t(p, 1e6), 3.2, 1e-4, 0);
}

/* The z bound of a mean over N ensembles (vfy_zmax_ensembles): 4.5 for a
 * normal z becomes Student's t at the same tail, times sqrt(N/(N - 1)); it
 * tends to 4.5 and never falls below it. */
static void test_zmax_ensembles(void **state)
{
    (void)state;
    assert_close(vfy_zmax_ensembles(4.5, 10), 9.7546, 1e-4, 0);
    assert_close(vfy_zmax_ensembles(4.5, 2000), 4.5131, 1e-4, 0);
    assert_close(vfy_zmax_ensembles(4.5, 1), 4.5, 0, 0);
    assert_true(vfy_zmax_ensembles(4.5, 4) > vfy_zmax_ensembles(4.5, 16));
    assert_true(vfy_zmax_ensembles(4.5, 100000000) >= 4.5);
}

static void test_sweeps(void **state)
{
    (void)state;
    char v[32];
    const vfy_sweep zipped = {.keys = VFY_KEYS({"particles.n", "64 256 1024", NULL},
                                               {"particles.ensembles", "10 20 30 40", NULL})};
    assert_int_equal(vfy_sweep_rows(&zipped), 3);   /* the shorter list */
    vfy_sweep_value(&zipped, 2, 1, v, sizeof v);
    assert_string_equal(v, "30");
    const vfy_sweep grid = {.keys = VFY_KEYS({"particles.n", "64 256", NULL},
                                             {"particles.ensembles", "10 20 30", NULL}),
                            .grid = 1};
    assert_int_equal(vfy_sweep_rows(&grid), 6);
    vfy_sweep_value(&grid, 4, 0, v, sizeof v);   /* the first key slowest */
    assert_string_equal(v, "256");
    vfy_sweep_value(&grid, 4, 1, v, sizeof v);
    assert_string_equal(v, "20");
    static const char *const rows[] = {"a: x.y=1", "b: x.y=2", NULL};
    const vfy_sweep explicit_rows = {.rows = rows};
    assert_int_equal(vfy_sweep_rows(&explicit_rows), 2);
    const vfy_sweep none = {.keys = NULL};
    assert_int_equal(vfy_sweep_rows(&none), 0);
}

/* A run with two rows of values, for templates, rules and guards. */
/* out_dir/name, whole, into buf (len bytes, terminated); the file must exist. */
static const char *read_out_file(const char *name, char *buf, size_t len)
{
    char path[600];
    snprintf(path, sizeof path, "%s/%s", out_dir, name);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    buf[fread(buf, 1, len - 1, f)] = '\0';
    fclose(f);
    return buf;
}

static const vfy_case test_case = {"test-case", "test", "a test", 0, NULL};
static const vfy_case_desc test_desc = {.paper = "Table 9"};
static const vfy_options test_options = {.size = VFY_QUICK};

static void fake_run(vfy_case_run *run, vfy_row rows[2])
{
    memset(rows, 0, 2 * sizeof *rows);
    *run = (vfy_case_run){.c = &test_case, .d = &test_desc, .o = &test_options, .rows = rows,
                          .nrows = 2};
    run->comment = vfy_strdup("provenance");
    for (size_t i = 0; i < 2; i++) {
        rows[i].index = i;
        rows[i].run = run;
    }
    vfy_values_set(&rows[0].values, "Emax", 0.08);
    vfy_values_set(&rows[0].values, "noise", 0.01);
    vfy_values_set(&rows[1].values, "n", 256);
    vfy_values_set(&rows[1].values, "Emax", 0.02);
    vfy_values_set(&rows[1].values, "noise", 0.01);
    vfy_values_set(&run->values, "wall_total", 12.345);
}

static void free_run(vfy_case_run *run)
{
    for (size_t i = 0; i < run->nrows; i++)
        vfy_row_free(&run->rows[i]);
    vfy_run_free(run);
}

/* Partner rows (vfy_row_partner) and the metrics against them, and a case
 * metric over the rows: four rows (alpha, is_ehs, a_tau0); the EHS row's
 * "ihs" partner is the IHS row of its alpha and a tau0, never a later row,
 * a row outside `when` has none. */
static const vfy_partner test_partners_list[] = {
    {"ihs", "is_ehs=1", "alpha a_tau0", "is_ehs=0 is_jump!=1"}, {NULL, NULL, NULL, NULL}};
static const vfy_case_desc partner_desc = {.partners = test_partners_list};

static void test_partners(void **state)
{
    (void)state;
    vfy_row rows[4];
    memset(rows, 0, sizeof rows);
    vfy_case_run run = {.c = &test_case, .d = &partner_desc, .o = &test_options, .rows = rows,
                        .nrows = 4};
    static const double table[4][5] = {/* alpha, is_ehs, a_tau0, q, q_ci_t */
                                       {0.5, 0, 4, 2.0, 0.1},
                                       {0.7, 0, 4, 3.0, 0.3},
                                       {0.7, 1, 4, 3.3, 0.4},
                                       {0.7, 1, 0.1, 9.0, 0.1}};
    static const char *const names[5] = {"alpha", "is_ehs", "a_tau0", "q", "q_ci_t"};
    for (size_t i = 0; i < 4; i++) {
        rows[i].index = i;
        rows[i].run = &run;
        for (size_t k = 0; k < 5; k++)
            vfy_values_set(&rows[i].values, names[k], table[i][k]);
    }
    assert_ptr_equal(vfy_row_partner(&run, &rows[2], "ihs"), &rows[1]);
    assert_null(vfy_row_partner(&run, &rows[1], "ihs"));   /* not EHS */
    assert_null(vfy_row_partner(&run, &rows[3], "ihs"));   /* no IHS row at a tau0 = 0.1 */
    assert_null(vfy_row_partner(&run, &rows[2], "rate"));  /* not declared */
    const vfy_metric z = {"z", vfy_metric_partner_z, "q", "ihs", 0};
    const vfy_metric pc = {"pc", vfy_metric_partner_percent, "q", "ihs", 0};
    const vfy_metric pci = {"pci", vfy_metric_partner_percent_ci, "q", "ihs", 0};
    assert_close(z.fn(&run, &rows[2], &z), 0.3 / 0.5, 1e-12, 0);
    assert_close(pc.fn(&run, &rows[2], &pc), 10.0, 1e-12, 0);
    assert_close(pci.fn(&run, &rows[2], &pci),
                 100.0 * 1.1 * sqrt(pow(0.4 / 3.3, 2) + pow(0.3 / 3.0, 2)), 1e-12, 0);
    assert_true(isnan(z.fn(&run, &rows[3], &z)));
    const vfy_metric smallest = {"smallest", vfy_metric_rows_min, "q", NULL, 0};
    assert_close(smallest.fn(&run, NULL, &smallest), 2.0, 0, 0);
    const vfy_metric first = {"first", vfy_metric_first_row, "q", NULL, 0};
    assert_close(first.fn(&run, NULL, &first), 2.0, 0, 0);
    const vfy_metric product = {"qa", vfy_metric_product, "q", "alpha", 2.0};
    assert_close(product.fn(&run, &rows[2], &product), 2.0 * 3.3 * 0.7, 1e-15, 0);
    /* the O(1/n) extrapolation over the rows: q = 1 + 2/n exactly gives 1, chi^2 0;
     * a row off by 10 standard errors gives a large chi^2 */
    static const size_t n[4] = {10, 20, 40, 80};
    for (size_t i = 0; i < 4; i++) {
        rows[i].solver.particles.n = n[i];
        vfy_values_set(&rows[i].values, "q", 1.0 + 2.0 / (double)n[i]);
        vfy_values_set(&rows[i].values, "q_sd", 0.01);
    }
    vfy_metric x = {"q_inf", vfy_metric_rows_extrapolate, "q", "q_sd", 0};
    assert_close(x.fn(&run, NULL, &x), 1.0, 1e-12, 0);
    x.x = 1;
    const double ci = x.fn(&run, NULL, &x);
    assert_true(ci > 0.0 && ci < 3.2 * 0.01 * 2.0);
    x.x = 2;
    assert_close(x.fn(&run, NULL, &x), 0.0, 0, 1e-12);
    vfy_values_set(&rows[3].values, "q", 1.0 + 2.0 / 80.0 + 0.1);
    assert_close(x.fn(&run, NULL, &x), 48.69565217391, 1e-9, 0);   /* by hand: 1120/23 */
    for (size_t i = 0; i < 4; i++)
        vfy_row_free(&rows[i]);
}

static void test_templates(void **state)
{
    (void)state;
    vfy_case_run run;
    vfy_row rows[2];
    fake_run(&run, rows);
    char buf[256];
    vfy_expand(buf, sizeof buf, "{case} n={n} Emax={Emax:%.3e} {paper} ({size}) {comment}",
               &run, &rows[1]);
    assert_string_equal(buf, "test-case n=256 Emax=2.000e-02 Table 9 (quick) provenance");
    /* case values without a row; an absent value prints as nan; {{ is a brace */
    vfy_expand(buf, sizeof buf, "{wall_total:%.1f} s, {wall_total}, {nothing}, {{x}", &run,
               NULL);
    assert_string_equal(buf, "12.3 s, 12.345, nan, {x}");
    vfy_expand(buf, 8, "{case} and more", &run, NULL);   /* truncated, terminated */
    assert_string_equal(buf, "test-ca");
    /* text at one size only (quick here); a hook's case text */
    vfy_expand(buf, sizeof buf, "a{at_quick: b (x: 1)}{at_paper: c} {sizes}.", &run, NULL);
    assert_string_equal(buf, "a b (x: 1) nan.");
    assert_int_equal(vfy_run_set_text(&run, "sizes", "n = 4"), 0);
    assert_int_equal(vfy_run_set_text(&run, "sizes", "n = 5"), 0);   /* replaced */
    assert_int_equal(run.ntexts, 1);
    vfy_expand(buf, sizeof buf, "{sizes}", &run, NULL);
    assert_string_equal(buf, "n = 5");
    const vfy_options paper = {.size = VFY_PAPER};
    run.o = &paper;
    vfy_expand(buf, sizeof buf, "a{at_quick: b}{at_paper: c}", &run, NULL);
    assert_string_equal(buf, "a c");
    /* scene keys by name, the row's or (at the case's level) the first row's, a word
     * key as its word; the step and output interval; text on a condition */
    sim_scene_defaults(&rows[0].solver);
    sim_scene_defaults(&rows[1].solver);
    rows[0].solver.particles.n = 2500;
    rows[0].solver.t_end = 18;
    rows[0].solver.outputs = 37;
    rows[0].solver.splitting = SIM_SPLIT_STRANG;
    rows[1].solver.particles.n = 64;
    rows[1].solver.splitting = SIM_SPLIT_EULER;
    const char *keys = "n = {particles.n}, t in [0, {scene.t_end:%g}] every "
                       "{scene.output_interval:%g}, {scene.splitting} "
                       "({if:scene.splitting=strang:Strang}{if:scene.splitting=euler:Euler}"
                       "{if:particles.n=64:, n is 64}), {steady.bins}, {no.such}";
    vfy_expand(buf, sizeof buf, keys, &run, NULL);
    assert_string_equal(buf, "n = 2500, t in [0, 18] every 0.5, strang (Strang), nan, nan");
    vfy_expand(buf, sizeof buf, keys, &run, &rows[1]);
    assert_true(strncmp(buf, "n = 64, ", 8) == 0);
    assert_non_null(strstr(buf, "euler (Euler, n is 64)"));
    free_run(&run);
}

/* Paper A's tail exponent: y_k = ln(ln f_1 - ln f_k) against ln(r_k - r_1)
 * has slope exactly b for f_k = f_1 exp(-a (r_k - r_1)^b); a tail of another
 * order gives another slope; a window uses only its shells; the clean range
 * ends at the first noisy shell; the first shell's error enters b's standard
 * error. */
static void test_tail_exponent(void **state)
{
    (void)state;
    enum { BINS = 64 };
    double r[BINS], f[BINS], ci[BINS];
    for (size_t b10 = 10; b10 <= 15; b10 += 5) {
        const double b = 0.1 * (double)b10;
        for (size_t k = 0; k < BINS; k++) {
            r[k] = 0.1 * (double)(k + 1);
            f[k] = 0.3 * exp(-1.7 * pow(r[k] - r[0], b));
            ci[k] = 3.2 * 0.01 * f[k];   /* 1% standard errors */
        }
        ci[0] = 0.0;
        vfy_tail_exponent t = vfy_fit_tail_exponent(r, f, ci, BINS, 0, 2.0, INFINITY, 0.1, 3.2);
        assert_int_equal(t.used, BINS - 19);   /* r = 2.0 ... 6.4 */
        assert_close(t.r_first, 2.0, 1e-12, 0);
        assert_close(t.b, b, 1e-9, 0);
        assert_true(t.b_se < 1e-3);
        /* a Gaussian tail, b = 2, is not either */
        for (size_t k = 1; k < BINS; k++) {
            f[k] = 0.3 * exp(-1.7 * pow(r[k] - r[0], 2.0));
            ci[k] = 3.2 * 0.01 * f[k];
        }
        t = vfy_fit_tail_exponent(r, f, ci, BINS, 0, 2.0, INFINITY, 0.1, 3.2);
        assert_close(t.b, 2.0, 1e-9, 0);
    }
    /* a window (the local slope): only its shells, r = 3.0 ... 4.0 */
    vfy_tail_exponent w = vfy_fit_tail_exponent(r, f, ci, BINS, 0, 2.95, 4.05, 0.1, 3.2);
    assert_int_equal(w.used, 11);
    assert_close(w.r_last, 4.0, 1e-12, 0);
    assert_close(w.b, 2.0, 1e-9, 0);
    /* a shell with a 20% error ends the clean range before it */
    ci[40] = 3.2 * 0.2 * f[40];
    vfy_tail_exponent t = vfy_fit_tail_exponent(r, f, ci, BINS, 0, 2.0, INFINITY, 0.1, 3.2);
    assert_int_equal(t.used, 21);   /* r = 2.0 ... 4.0 */
    assert_close(t.r_last, 4.0, 1e-12, 0);
    /* the first shell's 5% error widens the standard error of b */
    ci[0] = 3.2 * 0.05 * f[0];
    vfy_tail_exponent wide = vfy_fit_tail_exponent(r, f, ci, BINS, 0, 2.0, INFINITY, 0.1, 3.2);
    assert_close(wide.b, 2.0, 1e-9, 0);
    assert_true(wide.b_se > 2.0 * t.b_se);
    /* noise: the slope moves by about its standard error */
    for (size_t k = 1; k < BINS; k++)
        f[k] *= 1.0 + 0.01 * ((k % 3 == 0) ? 1.0 : -0.5);
    ci[0] = 0.0;
    t = vfy_fit_tail_exponent(r, f, ci, BINS, 0, 2.0, INFINITY, 0.1, 3.2);
    assert_true(fabs(t.b - 2.0) < 3.0 * t.b_se);
    assert_true(t.chi2_dof > 0.1);
    /* fewer than 3 shells: no fit */
    t = vfy_fit_tail_exponent(r, f, ci, BINS, 0, 6.25, INFINITY, 0.1, 3.2);
    assert_true(isnan(t.b));
}

/* Paper C's tail fit recovers A and K of f = K exp(-A c^1.5) exactly, and
 * moves with a wrong tail; the arithmetic adapters do what they say. */
static void test_tail_fit_and_adapters(void **state)
{
    (void)state;
    enum { BINS = 40 };
    double c[BINS], f[BINS], ci[BINS], A, sd, K;
    for (size_t k = 0; k < BINS; k++) {
        c[k] = 0.1 * ((double)k + 0.5);
        f[k] = 1.3 * exp(-1.99 * pow(c[k], 1.5));
        ci[k] = 0.1 * f[k];
    }
    size_t used = vfy_fit_tail(c, f, ci, BINS, 1.5, 3.0, 3.2, &A, &sd, &K);
    assert_int_equal(used, 10);   /* c = 3.05 ... 3.95 */
    assert_close(A, 1.99, 1e-9, 0);
    assert_close(K, 1.3, 1e-9, 0);
    f[BINS - 1] *= 10.0;   /* an overpopulated last shell pulls A down */
    vfy_fit_tail(c, f, ci, BINS, 1.5, 3.0, 3.2, &A, &sd, &K);
    assert_true(A < 1.9);
    ci[BINS - 1] = f[BINS - 1];   /* too noisy: left out of the fit */
    assert_int_equal(vfy_fit_tail(c, f, ci, BINS, 1.5, 3.0, 3.2, &A, &sd, &K), 9);
    assert_close(A, 1.99, 1e-9, 0);
    assert_int_equal(vfy_fit_tail(c, f, ci, BINS, 1.5, 3.9, 3.2, &A, &sd, &K), 0);
    assert_true(isnan(A));   /* fewer than 3 shells */

    vfy_case_run run;
    vfy_row rows[2];
    fake_run(&run, rows);
    vfy_row *row = &rows[1];
    vfy_values_set(&row->values, "mu2", 2.0);
    vfy_values_set(&row->values, "mu2_0", 1.5);
    vfy_values_set(&row->values, "mu2_1", 0.25);
    vfy_values_set(&row->values, "mu2_ci", 0.05);
    const vfy_metric ratio = {"r", vfy_metric_sonine_ratio, "mu2", NULL, 0},
                     ratio_ci = {"r_ci", vfy_metric_sonine_ratio, "mu2", NULL, 1},
                     sum = {"s", vfy_metric_sum, "mu2", "mu2_ci", 2},
                     pdiff = {"p", vfy_metric_percent_diff, "mu2", "mu2_0", 0},
                     pof = {"q", vfy_metric_percent_of, "mu2_ci", "mu2", 0},
                     max = {"m", vfy_metric_max_of, "mu2_ci", "mu2", 0.003},
                     absw = {"a", vfy_metric_abs_widened, "mu2_1", "mu2_ci", 0};
    assert_close(ratio.fn(&run, row, &ratio), 2.0, 1e-15, 0);
    assert_close(ratio_ci.fn(&run, row, &ratio_ci), 0.2, 1e-15, 0);
    assert_close(sum.fn(&run, row, &sum), 2.1, 1e-15, 0);
    assert_close(pdiff.fn(&run, row, &pdiff), 100.0 / 3.0, 1e-12, 0);
    assert_close(pof.fn(&run, row, &pof), 2.5, 1e-15, 0);
    assert_close(max.fn(&run, row, &max), 0.05, 0, 0);
    assert_close(absw.fn(&run, row, &absw), 0.3, 1e-15, 0);   /* quick: widened */
    vfy_values_set(&row->values, "mu2_1", 0.0);   /* the elastic limit: no ratio */
    assert_true(isnan(ratio.fn(&run, row, &ratio)));
    assert_int_equal(vfy_row_set_text(row, "relation", "mu2"), 0);
    const vfy_metric named = {"n", vfy_metric_named_by_text, "relation", "_ci", 0};
    assert_close(named.fn(&run, row, &named), 0.05, 0, 0);
    free_run(&run);
}

static void test_rules_and_guards(void **state)
{
    (void)state;
    vfy_case_run run;
    vfy_row rows[2];
    fake_run(&run, rows);
    vfy_report r;
    vfy_report_init(&r, NULL);
    vfy_check_spec rel = {.name = "rel", .rule = vfy_rule_relative, .value = "Emax",
                          .x = 0.0235, .tol = 0.35};
    assert_int_equal(rel.rule(&r, "rel", &run, &rows[1], &rel), VFY_PASS);
    rel.x = 0.04;   /* Emax twice the paper's */
    assert_int_equal(rel.rule(&r, "rel", &run, &rows[1], &rel), VFY_FAIL);
    rel.value = "absent";   /* a missing value never passes */
    assert_int_equal(rel.rule(&r, "rel", &run, &rows[1], &rel), VFY_FAIL);
    vfy_check_spec range = {.rule = vfy_rule_range, .value = "Emax", .lo = 0.0, .hi = 0.01};
    assert_int_equal(range.rule(&r, "range", &run, &rows[1], &range), VFY_FAIL);
    vfy_check_spec absolute = {.rule = vfy_rule_absolute, .value = "Emax",
                               .expected = "noise", .tol = 0.005};
    assert_int_equal(absolute.rule(&r, "abs", &run, &rows[1], &absolute), VFY_FAIL);
    absolute.tol = 0.0101;
    assert_int_equal(absolute.rule(&r, "abs", &run, &rows[1], &absolute), VFY_PASS);
    vfy_values_set(&rows[1].values, "violations", 2);
    vfy_check_spec count = {.rule = vfy_rule_count, .value = "violations"};
    assert_int_equal(count.rule(&r, "count", &run, &rows[1], &count), VFY_FAIL);

    /* CF = 4 is judged only where Emax is 4 x the noise on both rows */
    const vfy_guard clean = {vfy_guard_clean_pair, "Emax", "noise", 4.0, "noisy"};
    assert_int_equal(clean.fn(&run, &rows[0], &clean), VFY_OMIT);
    assert_int_equal(clean.fn(&run, &rows[1], &clean), VFY_GUARD_SKIP);   /* 0.02 < 0.04 */
    vfy_values_set(&rows[1].values, "noise", 0.004);
    assert_int_equal(clean.fn(&run, &rows[1], &clean), VFY_JUDGE);
    const vfy_guard at_most = {vfy_guard_at_most, "n", NULL, 4096, "large n"};
    assert_int_equal(at_most.fn(&run, &rows[1], &at_most), VFY_JUDGE);
    vfy_values_set(&rows[1].values, "n", 16384);
    assert_int_equal(at_most.fn(&run, &rows[1], &at_most), VFY_GUARD_SKIP);
    /* the absolute rule's tolerance: tol + rtol |expected| + plus + plus_quick */
    vfy_values_set(&rows[1].values, "a", 1.0);
    vfy_values_set(&rows[1].values, "ci", 0.01);
    vfy_check_spec widened = {.rule = vfy_rule_absolute, .value = "a", .x = 1.1, .tol = 0.05,
                              .rtol = 0.04};
    assert_int_equal(widened.rule(&r, "w", &run, &rows[1], &widened), VFY_FAIL);   /* 0.094 */
    widened.plus = "ci";
    assert_int_equal(widened.rule(&r, "w", &run, &rows[1], &widened), VFY_PASS);   /* 0.104 */
    widened.plus = NULL;
    widened.plus_quick = "ci";   /* the same at quick sizes only */
    assert_int_equal(widened.rule(&r, "w", &run, &rows[1], &widened), VFY_PASS);
    const vfy_options paper = {.size = VFY_PAPER};
    run.o = &paper;
    assert_int_equal(widened.rule(&r, "w", &run, &rows[1], &widened), VFY_FAIL);
    run.o = &test_options;
    const vfy_guard at_least = {vfy_guard_at_least, "n", NULL, 20000, "small n"},
                    only_at_least = {vfy_guard_only_at_least, "n", NULL, 20000, NULL},
                    unless = {vfy_guard_unless, "unjudged", NULL, 0, "not judged"};
    assert_int_equal(at_least.fn(&run, &rows[1], &at_least), VFY_GUARD_SKIP);
    assert_int_equal(only_at_least.fn(&run, &rows[1], &only_at_least), VFY_OMIT);
    vfy_values_set(&rows[1].values, "n", 20000);
    assert_int_equal(at_least.fn(&run, &rows[1], &at_least), VFY_JUDGE);
    assert_int_equal(only_at_least.fn(&run, &rows[1], &only_at_least), VFY_JUDGE);
    assert_int_equal(unless.fn(&run, &rows[1], &unless), VFY_JUDGE);   /* absent */
    vfy_values_set(&rows[1].values, "unjudged", 1);
    assert_int_equal(unless.fn(&run, &rows[1], &unless), VFY_GUARD_SKIP);
    assert_int_equal(r.counts[VFY_FAIL], 7);
    vfy_report_free(&r);
    free_run(&run);
}

/* A small description end to end on paper A Ex 3's scene: two rows, a
 * z-test against the exact finite-n expectation, a convergence factor, the
 * table and its rows.  The right solver passes; alpha = 0.45 fails. */
static const char *const e2e_needs[] = {"T_raw_finite_n", NULL};
static const vfy_metric e2e_metrics[] = {
    {"Emax", vfy_metric_max_rel_err, "T_raw", "T_exact", 0},
    {"CF", vfy_metric_ratio_previous, "Emax", NULL, 0},
    {NULL, NULL, NULL, NULL, 0}};
static const vfy_check_spec e2e_checks[] = {
    {.name = "{case} n={n} z", .rule = vfy_rule_zscore, .value = "T_raw",
     .expected = "T_raw_finite_n", .from = 1, .tol = 4.5, .out = "z"},
    {.name = NULL}};
static const char e2e_columns[] = "n:%.0f N:%.0f CF:%.2f z:%.2f";
static const vfy_case_desc e2e_desc = {
    .scene = "grw-ex3",
    .quick_rows = {.keys = VFY_KEYS({"particles.n", "16 64", NULL}),
                   .sets = "particles.ensembles=400;scene.outputs=21"},
    .needs = e2e_needs, .needs_why = "Maxwell molecules", .metrics = e2e_metrics,
    .checks = e2e_checks, .columns = e2e_columns, .title = "{case}",
    .notes = "{rows} rows, {outputs} outputs"};
static const vfy_case e2e_case = {"driver-e2e", "test", "", 0,
                                  &e2e_desc};

static size_t run_e2e(const char *const *wrong, size_t nwrong, char *table, size_t len)
{
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir,
                     .solver_overrides = wrong, .nsolver_overrides = nwrong};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512];
    assert_int_equal(vfy_run_described(&e2e_case, &o, &r, msg, sizeof msg), SIM_OK);
    assert_int_equal(r.count, 2);   /* one z-test a row */
    size_t failed = r.counts[VFY_FAIL];
    vfy_report_free(&r);
    read_out_file("driver-e2e.csv", table, len);
    return failed;
}

static void test_end_to_end(void **state)
{
    (void)state;
    char table[4096];
    assert_int_equal(run_e2e(NULL, 0, table, sizeof table), 0);
    /* the header, then n and N of each row; the first row has no CF */
    assert_non_null(strstr(table, "\nn,N,CF,z\n16,400,,"));
    assert_non_null(strstr(table, "\n64,400,"));
    const char *wrong[] = {"collisions.restitution=0.45"};
    assert_true(run_e2e(wrong, 1, table, sizeof table) >= 1);
    /* --set fixes a key the sweep also sets: the user's value wins */
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    const char *sets[] = {"particles.ensembles=300"};
    o.overrides = sets;
    o.noverrides = 1;
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512];
    assert_int_equal(vfy_run_described(&e2e_case, &o, &r, msg, sizeof msg), SIM_OK);
    vfy_report_free(&r);
    read_out_file("driver-e2e.csv", table, sizeof table);
    assert_non_null(strstr(table, "\n16,300,"));
}

/* `observes`: the engine computes what the case reads alone.  The row's T_raw
 * is judged as before; T, which the description does not list, is NaN and
 * its check fails (never a silent pass); a name that is no observable stops
 * the case with a message naming it. */
static const vfy_check_spec observes_checks[] = {
    {.name = "{case} n={n} T_raw", .rule = vfy_rule_zscore, .value = "T_raw",
     .expected = "T_raw_finite_n", .from = 1, .tol = 4.5},
    {.name = "{case} n={n} T", .rule = vfy_rule_zscore, .value = "T",
     .expected = "T_finite_n", .from = 1, .tol = 4.5},
    {.name = NULL}};

static void test_observes(void **state)
{
    (void)state;
    static const char *const needs[] = {"T_raw_finite_n", "T_finite_n", NULL};
    vfy_case_desc d = e2e_desc;
    d.needs = needs;
    d.metrics = NULL;
    d.checks = observes_checks;
    d.columns = "n:%.0f";
    d.observes = "T_raw";
    const vfy_case c = {"driver-observes", "test", "", 0, &d};
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512];
    assert_int_equal(vfy_run_described(&c, &o, &r, msg, sizeof msg), SIM_OK);
    assert_int_equal(r.count, 4);
    for (size_t k = 0; k < r.count; k++)
        assert_int_equal(r.checks[k].verdict, k % 2 == 0 ? VFY_PASS : VFY_FAIL);
    vfy_report_free(&r);
    d.observes = "T_raw Tx";
    vfy_report_init(&r, NULL);
    assert_int_equal(vfy_run_described(&c, &o, &r, msg, sizeof msg), SIM_EINVAL);
    assert_non_null(strstr(msg, "\"Tx\""));
    vfy_report_free(&r);
}

/* Explicit rows with text values, two variants of each row, an adjust hook
 * and a figure with a suffix. */
static sim_status rows_adjust(const vfy_row *row, sim_scene *solver, char *msg, size_t msglen)
{
    (void)msg;
    (void)msglen;
    if (strcmp(vfy_row_text(row, "kind"), "large") == 0)
        solver->particles.ensembles = 50;
    return SIM_OK;
}
static const char *const rows_rows[] = {"small: $kind=tiny; $h=0.5; particles.n=8",
                                        "big: $kind=large; particles.n=32", NULL};
static const char *const rows_variants[] = {"a: scene.seed=1", "b: scene.seed=2", NULL};
static const vfy_check_spec rows_checks[] = {
    {.name = "{case} {label} {kind} b", .rule = vfy_rule_zscore, .value = "T_raw@b",
     .expected = "T_raw_finite_n", .from = 1, .tol = 4.5, .out = "z_b"},
    /* two seeds of one scene agree; T_raw against T (12% apart at n = 8) does not */
    {.name = "{case} {label} a vs b", .rule = vfy_rule_zscore_pair, .value = "T_raw@a",
     .expected = "T_raw@b", .from = 1, .tol = 4.5},
    {.name = "{case} {label} wrong pair", .rule = vfy_rule_zscore_pair, .value = "T_raw@a",
     .expected = "T@b", .from = 1, .tol = 4.5, .guard = {vfy_guard_at_most, "n", NULL, 8, ""}},
    {.name = NULL}};
static const char rows_columns[] = "kind:%s h:%g n:%.0f N:%.0f N_b=N@b:%.0f absent:%s";
static const vfy_case_desc rows_desc = {
    .scene = "grw-ex3",
    .quick_rows = {.rows = rows_rows, .sets = "particles.ensembles=200;scene.outputs=11"},
    .needs = e2e_needs, .label = "{case} {label}", .variants = rows_variants,
    .adjust = rows_adjust, .checks = rows_checks, .columns = rows_columns,
    .figures = VFY_FIGURES({.kind = VFY_FIGURE_CURVES, .suffix = "-x", .quantity = "T_raw@b",
                 .refs = VFY_LIST("T_exact"), .title = "{case}: its own title"}),
    .title = "{case}", .notes = "notes"};
static const vfy_case rows_case = {"driver-rows", "test", "", 0,
                                   &rows_desc};

static void test_rows_variants_adjust(void **state)
{
    (void)state;
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512], path[600], table[2048];
    assert_int_equal(vfy_run_described(&rows_case, &o, &r, msg, sizeof msg), SIM_OK);
    assert_int_equal(r.count, 6);   /* the wrong pair is skipped at n = 32 */
    assert_int_equal(r.counts[VFY_FAIL], 1);
    assert_string_equal(r.checks[0].name, "driver-rows small tiny b");
    assert_string_equal(r.checks[2].name, "driver-rows small wrong pair");
    assert_int_equal(r.checks[2].verdict, VFY_FAIL);
    vfy_report_free(&r);
    read_out_file("driver-rows.csv", table, sizeof table);
    /* texts print as text, a missing one and the big row's h as empty cells;
     * the adjust hook gave the big row's solver 50 ensembles, both variants */
    assert_non_null(strstr(table, "\nkind,h,n,N,N_b,absent\ntiny,0.5,8,200,200,\nlarge,,32,50,50,\n"));
    snprintf(path, sizeof path, "%s/driver-rows-x-curves.csv", out_dir);
    assert_int_equal(access(path, R_OK), 0);
    /* the figure's own title, not the case's; its key off the curves */
    read_out_file("driver-rows-x.gp", table, sizeof table);
    assert_non_null(strstr(table, "'driver-rows: its own title'"));
    assert_non_null(strstr(table, "set key below\n"));
}

/* Settings derived from value references (vfy_case_desc.derived): the
 * thermostat strength that holds T0 reaches the solver in the description's
 * format, and a reference that does not apply (a series) sets nothing; a
 * row metric of the name is evaluated before the run (t_end halved); a
 * requirement the scene does not meet stops the case, naming it. */
static const vfy_metric derived_metrics[] = {
    {"beta", vfy_metric_heating_strength, NULL, NULL, 0},
    {"t_half", vfy_metric_constant, NULL, NULL, 0.05}, {NULL, NULL, NULL, NULL, 0}};
static const vfy_case_desc derived_desc = {
    .scene = "grw-ex5",
    .quick_rows = {.keys = VFY_KEYS({"particles.n", "8", NULL}),
                   .sets = "particles.ensembles=2;scene.outputs=3;scene.t_end=0.1"},
    .derived = "heating.strength=heating_strength_T0:%.6g scene.t_end=T_exact "
               "scene.t_end=t_half",
    .require = "[heating] heating.type=white-noise", .require_why = "white noise, please",
    .metrics = derived_metrics, .columns = "beta:%.9g", .title = "{case}",
    .notes = ""};
static const vfy_case derived_case = {"driver-derived", "test", "", 0, &derived_desc};

static void test_derived_and_required(void **state)
{
    (void)state;
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    vfy_report r;
    char msg[512], table[1024], want[64];
    vfy_report_init(&r, NULL);
    assert_int_equal(vfy_run_described(&derived_case, &o, &r, msg, sizeof msg), SIM_OK);
    vfy_report_free(&r);
    /* 2 beta = the first-Sonine loss at T0 = 1, alpha = 0.5, gamma = 4 (a scene.t_end
     * of NaN would have stopped the case) */
    const double a2 = 4.0 / 156.25;
    const double beta = 0.5 * 4.0 * 0.0795774715459476678 * 0.75 / 24.0 * 4.0 * M_PI * 32.0
                        / sqrt(M_PI) * (1.0 + 3.0 * a2 / 16.0);
    char derived[32];
    snprintf(derived, sizeof derived, "%.6g", beta);
    snprintf(want, sizeof want, "\nbeta\n%.9g\n", strtod(derived, NULL));
    read_out_file("driver-derived.csv", table, sizeof table);
    if (strstr(table, want) == NULL)
        print_error("wanted %s in:\n%s\n", want, table);
    assert_non_null(strstr(table, want));
    assert_non_null(strstr(table, "3 outputs on [0, 0.05]"));

    vfy_case_desc wrong = derived_desc;
    wrong.require = "[heating] heating.type=gaussian";
    const vfy_case wrong_case = {"driver-derived", "test", "", 0, &wrong};
    vfy_report_init(&r, NULL);
    assert_int_equal(vfy_run_described(&wrong_case, &o, &r, msg, sizeof msg), SIM_EINVAL);
    assert_non_null(strstr(msg, "grw-ex5.ini: white noise, please (needs heating.type=gaussian)"));
    vfy_report_free(&r);
    wrong.require = "heating.type>gaussian";   /* a malformed word: the description's fault */
    vfy_report_init(&r, NULL);
    assert_int_equal(vfy_run_described(&wrong_case, &o, &r, msg, sizeof msg), SIM_EINVAL);
    assert_non_null(strstr(msg, "case driver-derived: requirement on heating.type"));
    vfy_report_free(&r);
}

/* Seeded batches (brs-ex4's way, vfy_batches): three batches of each row,
 * the batch metrics and the mean over the variants (NAME@*), a hook that sets
 * case values and case checks on them; the exact time average of the
 * finite-n expectation is met, a wrong printed value is not. */
static const vfy_metric batch_metrics[] = {
    {"T_star", vfy_metric_batch_mean, "T_raw", NULL, 0.5},
    {"T_star_se", vfy_metric_batch_se, "T_raw", NULL, 0.5},
    {"T_star_ci", vfy_metric_batch_t_ci, "T_star_se", NULL, 0},
    {"N", vfy_metric_variants_sum, "N", NULL, 0},
    {"stat", vfy_metric_max_rel_diff, "T_raw@*", "T_raw_finite_n/T_exact", 0},
    {"dev", vfy_metric_max_abs_diff, "T_raw@*", "T_raw_finite_n", 0},
    {NULL, NULL, NULL, NULL, 0}};
/* The exact time average of E T_raw over the same times. */
static sim_status batch_hook(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    (void)r;
    (void)msg;
    (void)msglen;
    const vfy_row *row = &run->rows[0];
    double exact[64];
    assert_true(row->res.outputs <= 64);
    assert_int_equal(vfy_row_series(row, "T_raw_finite_n", exact, NULL), 0);
    vfy_values_set(&run->values, "T_exact_avg",
                   vfy_time_average(row->res.t, exact, row->res.outputs, 0.5 * row->solver.t_end));
    vfy_values_set(&run->values, "T_star", vfy_values_get(&row->values, "T_star"));
    vfy_values_set(&run->values, "T_star_ci", vfy_values_get(&row->values, "T_star_ci"));
    return SIM_OK;
}
static const vfy_check_spec batch_case_checks[] = {
    {.name = "{case} T* vs exact", .rule = vfy_rule_absolute, .value = "T_star",
     .expected = "T_exact_avg", .plus = "T_star_ci"},
    {.name = "{case} T* vs a wrong printed value", .rule = vfy_rule_printed, .value = "T_star",
     .plus = "T_star_ci", .x = 9.99, .tol = 2},
    {.name = NULL}};
static const char batch_columns[] = "n:%.0f N:%.0f T_star:%.5f";
static const vfy_case_desc batch_desc = {
    .scene = "grw-ex3",
    .quick_rows = {.keys = VFY_KEYS({"particles.n", "16", NULL}),
                   .sets = "particles.ensembles=300;scene.outputs=21"},
    .needs = e2e_needs, .batches = {3, 1000},
    .metrics = batch_metrics, .columns = batch_columns, .after_rows = batch_hook,
    .case_checks = batch_case_checks,
    .figures = VFY_FIGURES({.kind = VFY_FIGURE_CURVES, .suffix = "-T", .quantity = "T_raw@*",
                 .refs = VFY_LIST("T_raw_finite_n")}),
    .title = "{case}", .notes = "{rows} row"};
static const vfy_case batch_case = {"driver-batches", "test", "", 0, &batch_desc};

static void test_batches_and_case_checks(void **state)
{
    (void)state;
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512], table[1024];
    assert_int_equal(vfy_run_described(&batch_case, &o, &r, msg, sizeof msg), SIM_OK);
    assert_int_equal(r.count, 2);
    assert_int_equal(r.checks[0].verdict, VFY_PASS);
    assert_string_equal(r.checks[1].name, "driver-batches T* vs a wrong printed value");
    assert_int_equal(r.checks[1].verdict, VFY_FAIL);
    vfy_report_free(&r);
    read_out_file("driver-batches.csv", table, sizeof table);
    assert_non_null(strstr(table, "\nn,N,T_star\n16,900,"));   /* N summed over 3 batches */
    /* the figure draws the batches' mean as T_raw */
    read_out_file("driver-batches-T-curves.csv", table, sizeof table);
    assert_null(strstr(table, "@*"));
}

/* A curves figure over rows with output times of their own (as-transient's
 * rows differ in t_end and outputs): each row is drawn on its own times, one
 * block per curve, every value read from that row (the shared-grid layout
 * would pair the short row with the long row's times and print memory past
 * its end). */
static const char *const grid_rows[] = {"short: scene.outputs=6; scene.t_end=0.5",
                                        "long: scene.outputs=11", NULL};
static const vfy_case_desc grid_desc = {
    .scene = "grw-ex3",
    .quick_rows = {.rows = grid_rows, .sets = "particles.n=8;particles.ensembles=50"},
    .needs = e2e_needs, .label = "{case} {label}", .columns = "n:%.0f",
    .figures = VFY_FIGURES(
        {.kind = VFY_FIGURE_CURVES, .quantity = "T_raw", .refs = VFY_LIST("T_exact")}),
    .title = "{case}", .notes = "notes"};
static const vfy_case grid_case = {"driver-grids", "test", "", 0, &grid_desc};

static void test_curves_by_row(void **state)
{
    (void)state;
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512], path[600], line[256];
    assert_int_equal(vfy_run_described(&grid_case, &o, &r, msg, sizeof msg), SIM_OK);
    vfy_report_free(&r);
    snprintf(path, sizeof path, "%s/driver-grids-curves.csv", out_dir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    /* blocks: short (6 points to t = 0.5), its T_exact, long (11 to t = 8), its
     * T_exact; every value near T0 = 1 or the heated gas's T_raw (at most 6) */
    size_t block = 0, points[4] = {0}, headers = 0;
    double last_t[4] = {0};
    while (fgets(line, sizeof line, f) != NULL) {
        if (line[0] == '#') {
            if (strstr(line, "driver-grids ") != NULL)
                block = headers++;
            continue;
        }
        double t, y;
        if (sscanf(line, "%lf,%lf", &t, &y) != 2)
            continue;
        assert_true(block < 4);
        assert_true(y > 0.5 && y < 6.0);
        points[block]++;
        last_t[block] = t;
    }
    fclose(f);
    assert_int_equal(headers, 4);
    assert_int_equal(points[0], 6);
    assert_int_equal(points[2], 11);
    assert_close(last_t[0], 0.5, 1e-12, 0);
    assert_close(last_t[2], 8.0, 1e-12, 0);
}

/* The pure helpers of the steady and cost cases: a time average over the
 * second half, the largest absolute difference, and two estimates' distance
 * in joint half-widths; each moves with a wrong input. */
static void test_time_average_and_abs_diff(void **state)
{
    (void)state;
    const double t[5] = {0, 1, 2, 3, 4}, x[5] = {9, 9, 1, 2, 3}, y[5] = {9, 9, 1, 2, 3.5};
    assert_close(vfy_time_average(t, x, 5, 2.0), 2.0, 1e-15, 0);
    assert_close(vfy_time_average(t, y, 5, 2.0), 13.0 / 6.0, 1e-15, 0);
    assert_true(isnan(vfy_time_average(t, x, 5, 5.0)));   /* no time that late */
    assert_close(vfy_max_abs_diff(x, x, 5), 0.0, 0, 0);
    assert_close(vfy_max_abs_diff(x, y, 5), 0.5, 1e-15, 0);
    /* two estimates 5 apart with half-widths 3 and 4: one joint half-width */
    assert_close(vfy_z_pair(1.0, 3.0, 6.0, 4.0), 1.0, 1e-15, 0);
    assert_close(vfy_z_pair(6.0, 3.0, 1.0, 4.0), 1.0, 1e-15, 0);
    assert_close(vfy_z_pair(1.0, 3.0, 11.0, 4.0), 2.0, 1e-15, 0);
}

/* The registry names every series vfy_scene_references gives a shipped
 * scene (so the two cannot drift apart), and value references evaluate at
 * a scene's restitution. */
static void test_reference_registry(void **state)
{
    (void)state;
    static const char *const stems[] = {"grw-ex3", "grw-ex5", "brs-ex1", "brs-ex4"};
    size_t seen = 0;
    for (size_t i = 0; i < sizeof stems / sizeof *stems; i++) {
        char path[700], msg[512];
        snprintf(path, sizeof path, "%s/%s.ini", scene_dir, stems[i]);
        sim_scene scene;
        assert_int_equal(vfy_scene_load(path, NULL, 0, &scene, msg, sizeof msg), SIM_OK);
        vfy_refs refs;
        sim_error err;
        assert_int_equal(vfy_scene_references(&scene, &refs, &err), SIM_OK);
        for (size_t j = 0; j < refs.count; j++, seen++) {
            const vfy_reference *ref = vfy_reference_find(refs.names[j]);
            if (ref == NULL)
                print_error("%s: %s is not in the registry\n", stems[i], refs.names[j]);
            assert_non_null(ref);
            assert_int_equal(ref->kind, VFY_REF_SERIES);
        }
        vfy_refs_free(&refs);
    }
    assert_true(seen >= 10);
    assert_null(vfy_reference_find("T_exac"));   /* whole words only */
    assert_null(vfy_reference_find("exact"));
    sim_scene s;
    sim_scene_defaults(&s);
    s.collisions.restitution = 0.5;
    /* paper C Eq. (10) at alpha = 0.5: 16 (0.5)(0.5) / (73 + 168 - 1.5 (59) + 30 (0.5)(0.25)) */
    assert_close(vfy_reference_value("a2_C10", &s), 4.0 / 156.25, 1e-12, 0);
    assert_true(isnan(vfy_reference_value("T_exact", &s)));   /* a series, not a value */
    assert_true(isnan(vfy_reference_value("no_such", &s)));
}

/* One panel per row for every row (not the first four): six rows in three
 * lines of two panels, each titled by its n. */
static void test_curve_panels(void **state)
{
    (void)state;
    enum { ROWS = 6, M = 3 };
    const double t[M] = {0.0, 1.0, 2.0};
    double mean[ROWS * M], ci[ROWS * M];
    size_t n[ROWS];
    for (size_t i = 0; i < ROWS; i++) {
        n[i] = 4u << i;
        for (size_t m = 0; m < M; m++) {
            mean[i * M + m] = 1.0 + 0.1 * (double)m;
            ci[i * M + m] = 0.01;
        }
    }
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    assert_int_equal(vfy_write_curves(&o, "driver-panels", "six rows", "comment", t, M, 0, NULL,
                                      NULL, ROWS, n, NULL, mean, ci, "T", "T/T0", 0.0, 1),
                     0);
    char path[600], line[512];
    snprintf(path, sizeof path, "%s/driver-panels.gp", out_dir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t panels = 0, layout = 0, axis = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        panels += strncmp(line, "set title 'n = ", 15) == 0;
        layout += strstr(line, "set multiplot layout 3,2 ") != NULL;
        axis += strstr(line, "set ylabel 'T/T0'") != NULL;   /* the label, not the column */
    }
    fclose(f);
    assert_int_equal(panels, ROWS);
    assert_int_equal(layout, 1);
    assert_int_equal(axis, 1);
}

/* A description beyond every former cap: one row with a 134-character
 * label, 12 texts (8 before) one of 600 characters (512), 5 swept keys (4),
 * a check name of over 300 characters (95 kept), 5 figures (3), one of them
 * points with 5 series (4).  Everything comes out whole. */
#define X10 "xxxxxxxxxx"
#define X100 X10 X10 X10 X10 X10 X10 X10 X10 X10 X10
#define LONG_TEXT X100 X100 X100 X100 X100 X100
#define ON "and on "
#define LONG_LABEL                                                                     \
    "a row whose label runs on " ON ON ON ON ON ON ON ON ON ON ON ON ON ON "to its end"
static const char *const long_rows[] = {
    LONG_LABEL ": $t1=a;$t2=b;$t3=c;$t4=d;$t5=e;$t6=f;$t7=g;$t8=h;$t9=i;$t10=j;$t11=k;"
    "$long=" LONG_TEXT,
    NULL};
#define AT "a check named at length, "
static const vfy_check_spec long_checks[] = {
    {.name = "{case} {label} " AT AT AT AT AT AT AT AT AT AT AT AT "index {index}",
     .rule = vfy_rule_range, .value = "index", .lo = 0.0, .hi = 0.0},
    {.name = NULL}};
#define LONG_CURVES(SUFFIX)                                                            \
    {.kind = VFY_FIGURE_CURVES, .suffix = SUFFIX, .quantity = "T_raw",                 \
     .refs = VFY_LIST("T_exact")}
static const vfy_case_desc long_desc = {
    .scene = "grw-ex3",
    .quick_rows = {.rows = long_rows,
                   .keys = VFY_KEYS({"particles.n", "6", NULL},
                                    {"particles.ensembles", "40", NULL},
                                    {"scene.outputs", "5", NULL}, {"scene.t_end", "1", NULL},
                                    {"collisions.restitution", "0.5", "alpha"})},
    .needs = e2e_needs, .label = "{case} {label}", .checks = long_checks,
    .columns = "alpha:%.2f t11:%s long:%s",
    .figures = VFY_FIGURES(LONG_CURVES("-a"), LONG_CURVES("-b"), LONG_CURVES("-c"),
                           LONG_CURVES("-d"),
                           {.kind = VFY_FIGURE_POINTS, .suffix = "-p", .x = "n",
                            .series = VFY_LIST("index", "n", "N", "M", "alpha"),
                            .x_lo = 0.0, .x_hi = 1.0, .title = "{case}", .xlabel = "n",
                            .ylabel = "y"}),
    .title = "{case}", .notes = "{label}"};
static const vfy_case long_case = {"driver-long", "test", "", 0, &long_desc};

static void test_long_description(void **state)
{
    (void)state;
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512], path[600];
    assert_int_equal(vfy_run_described(&long_case, &o, &r, msg, sizeof msg), SIM_OK);
    assert_int_equal(r.count, 1);
    assert_int_equal(r.checks[0].verdict, VFY_PASS);
    assert_true(strlen(r.checks[0].name) > 300);
    assert_string_equal(r.checks[0].row, "driver-long " LONG_LABEL);
    vfy_report_free(&r);
    static const char *const files[] = {"-a-curves.csv", "-b-curves.csv", "-c-curves.csv",
                                        "-d-curves.csv", "-p-points.csv", ".csv"};
    for (size_t k = 0; k < sizeof files / sizeof *files; k++) {
        snprintf(path, sizeof path, "%s/driver-long%s", out_dir, files[k]);
        FILE *f = fopen(path, "r");
        assert_non_null(f);
        char line[2048];
        int found = 0;
        while (fgets(line, sizeof line, f) != NULL)
            found |= k < 4   ? strncmp(line, "t,T_exact,", 10) == 0
                     : k == 4 ? strcmp(line, "n,index,index_ci,n,n_ci,N,N_ci,M,M_ci,alpha,"
                                             "alpha_ci\n") == 0
                              : strcmp(line, "0.50,k," LONG_TEXT "\n") == 0;
        fclose(f);
        assert_true(found);
    }
}

/* A points figure grouped by a row value (driver.h, group_by): each group
 * its own series, columns and symbol, "LABEL (GROUP)" in the legend with
 * what the bars are; a row in no listed group is left out; without a list
 * the groups are the rows' values in order (a number too); ungrouped
 * figures are as before. */
static const char *const group_rows[] = {
    "a: $model=ihs;$k=4;$x=0.1;$y=1;$y_ci=0.1", "b: $model=ehs;$k=0.5;$x=0.1;$y=2;$y_ci=0.2",
    "c: $model=ihs;$k=4;$x=0.2;$y=3;$y_ci=0.3", "d: $model=bgk;$k=0.5;$x=0.2;$y=4;$y_ci=0.4",
    NULL};
#define GROUP_FIGURE(SUFFIX, ...)                                                      \
    {.kind = VFY_FIGURE_POINTS, .suffix = SUFFIX, .x = "x", .series = VFY_LIST("Y=y"),  \
     .title = "{case}", .xlabel = "x", .ylabel = "y", __VA_ARGS__}
static const vfy_case_desc group_desc = {
    .scene = "grw-ex3", .no_simulation = 1, .quick_rows = {.rows = group_rows},
    .label = "{case} {label}", .columns = "x:%g",
    .figures = VFY_FIGURES(GROUP_FIGURE("-listed", .group_by = "model",
                                        .groups = VFY_LIST("IHS=ihs", "EHS=ehs")),
                           GROUP_FIGURE("-found", .group_by = "k"),
                           GROUP_FIGURE("-none", .group_by = NULL),
                           GROUP_FIGURE("-pair", .group_by = "model k",
                                        .groups = VFY_LIST("IHS 4=ihs 4", "EHS 0.5=ehs 0.5"))),
    .title = "{case}", .notes = "notes"};
static const vfy_case group_case = {"driver-groups", "test", "", 0, &group_desc};

/* The lines of out_dir/driver-groups<suffix> without its comments, in buf. */
static const char *group_file(const char *suffix, char *buf, size_t len)
{
    char path[600], line[2048];
    snprintf(path, sizeof path, "%s/driver-groups%s", out_dir, suffix);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    buf[0] = '\0';
    while (fgets(line, sizeof line, f) != NULL)
        if (line[0] != '#')
            strncat(buf, line, len - strlen(buf) - 1);
    fclose(f);
    return buf;
}

static void test_points_groups(void **state)
{
    (void)state;
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512], buf[8192];
    assert_int_equal(vfy_run_described(&group_case, &o, &r, msg, sizeof msg), SIM_OK);
    vfy_report_free(&r);
    assert_string_equal(group_file("-listed-points.csv", buf, sizeof buf),
                        "x,Y (IHS),Y (IHS)_ci,Y (EHS),Y (EHS)_ci\n"
                        "0.1,1,0.1,,\n0.1,,,2,0.2\n0.2,3,0.3,,\n");   /* bgk: in no group */
    const char *gp = group_file("-listed.gp", buf, sizeof buf);
    assert_non_null(strstr(gp, "using 1:2:3 with yerrorbars pt 7 lc rgb '#0072b2' "
                               "title 'Y (IHS) " VFY_CI_LEGEND "'"));
    assert_non_null(strstr(gp, "using 1:4:5 with yerrorbars pt 6 lc rgb '#d55e00' "
                               "title 'Y (EHS) " VFY_CI_LEGEND "'"));
    assert_string_equal(group_file("-found-points.csv", buf, sizeof buf),
                        "x,Y (4),Y (4)_ci,Y (0.5),Y (0.5)_ci\n"
                        "0.1,1,0.1,,\n0.1,,,2,0.2\n0.2,3,0.3,,\n0.2,,,4,0.4\n");
    assert_string_equal(group_file("-none-points.csv", buf, sizeof buf),
                        "x,Y,Y_ci\n0.1,1,0.1\n0.1,2,0.2\n0.2,3,0.3\n0.2,4,0.4\n");
    assert_string_equal(group_file("-pair-points.csv", buf, sizeof buf),   /* two names */
                        "x,Y (IHS 4),Y (IHS 4)_ci,Y (EHS 0.5),Y (EHS 0.5)_ci\n"
                        "0.1,1,0.1,,\n0.1,,,2,0.2\n0.2,3,0.3,,\n");
    gp = group_file("-none.gp", buf, sizeof buf);
    assert_non_null(strstr(gp, "using 1:2:3 with yerrorbars pt 5 lc rgb '#0072b2' title 'Y " VFY_CI_LEGEND "'\n"));
    assert_non_null(strstr(gp, "set key top right\n"));
    assert_non_null(strstr(gp, "set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05\n"));
}

/* Figures of the curves a row makes (driver.h, ROW_CURVES and ROW_POINTS):
 * one a row with its suffix a template, or the last row's; the data drawn
 * as points with error bars, the references as lines; data curves that do
 * not share their x are refused. */
static int line_curve(const vfy_case_run *run, const vfy_row *row, double x, vfy_curve *out)
{
    (void)run;
    if (vfy_curve_alloc(out, isnan(x) ? 3 : (size_t)x, isnan(x)) != 0)
        return -1;
    for (size_t k = 0; k < out->count; k++) {
        out->x[k] = (double)k;
        out->y[0][k] = vfy_values_get(&row->values, "y") * (double)k;
        if (out->ci[0])
            out->ci[0][k] = 0.5;
    }
    return 0;
}
static const vfy_figure_curve row_model = {.label = "model", .fn = line_curve, .x = 2,
                                           .reference = 1};
static const vfy_figure_curve row_data = {.label = "y {y:%g}", .fn = line_curve, .x = NAN,
                                          .next = &row_model};
static const vfy_figure_curve row_short = {.label = "short", .fn = line_curve, .x = 2};
static const vfy_figure_curve row_mixed = {.label = "data", .fn = line_curve, .x = NAN,
                                           .next = &row_short};
static const char *const row_rows[] = {"a: $y=1", "b: $y=2", NULL};
/* two panels: y in the first, 10 y in the second; none for row a (left out) */
static int panels_curve(const vfy_case_run *run, const vfy_row *row, double x, vfy_curve *out)
{
    (void)run, (void)x;
    const double y = vfy_values_get(&row->values, "y");
    if (y == 1.0)
        return 1;
    *out = (vfy_curve){.count = 2, .x = malloc(6 * sizeof *out->x)};   /* x, y[0], y[1] */
    if (out->x == NULL)
        return -1;
    out->y[0] = out->x + 2;
    out->y[1] = out->x + 4;
    for (size_t k = 0; k < 2; k++) {
        out->x[k] = (double)k;
        out->y[0][k] = y;
        out->y[1][k] = 10.0 * y;
    }
    out->lc = 3;
    return 0;
}
static const vfy_figure_curve row_panels = {.label = "p", .fn = panels_curve, .x = NAN};
#define ROW_FIGURES(...)                                                               \
    {.scene = "grw-ex3", .no_simulation = 1, .quick_rows = {.rows = row_rows},           \
     .label = "{case} {label}", .columns = "y:%g", .figures = VFY_FIGURES(__VA_ARGS__),   \
     .title = "{case}", .notes = "notes"}
static const vfy_case_desc row_desc = ROW_FIGURES(
    {.kind = VFY_FIGURE_ROW_POINTS, .suffix = "-{label}", .each_row = 1, .curves = &row_data,
     .title = "{case} {label}", .xlabel = "x", .ylabel = "y", .logy = 1,
     .key_inside = "bottom left"},
    {.kind = VFY_FIGURE_ROW_CURVES, .suffix = "-last", .curves = &row_data, .band = 1,
     .xlabel = "x", .ylabel = "y"},
    {.kind = VFY_FIGURE_ROW_CURVES, .suffix = "-panels", .curves = &row_panels,
     .row_label = "{label}", .panels = VFY_LIST("first", "second"), .xlabel = "x"},
    {.kind = VFY_FIGURE_ROW_CURVES, .suffix = "-only", .curves = &row_data, .only = "y=1",
     .xlabel = "x", .ylabel = "y"});
static const vfy_case row_case = {"driver-row-figures", "test", "", 0, &row_desc};
static const vfy_case_desc row_mixed_desc = ROW_FIGURES(
    {.kind = VFY_FIGURE_ROW_POINTS, .suffix = "-mixed", .curves = &row_mixed});
static const vfy_case row_mixed_case = {"driver-row-figures-mixed", "test", "", 0, &row_mixed_desc};

static const vfy_case_desc series_desc = {
    .scene = "grw-ex3",
    .quick_rows = {.keys = VFY_KEYS({"particles.n", "8 16", NULL}),
                   .sets = "particles.ensembles=2;scene.outputs=3;scene.t_end=0.1"},
    .needs = VFY_LIST("T_exact"), .columns = "n:%.0f", .title = "{case}", .notes = "",
    .figures = VFY_FIGURES({.kind = VFY_FIGURE_ROW_CURVES, .suffix = "-series",
                            .row_label = "n = {n}", .x = "T_exact",
                            .series = VFY_LIST("T raw=T_raw", "T=T", "absent=no_such"),
                            .xlabel = "T_exact", .logx = 1})};
static const vfy_case series_case = {"driver-series", "test", "", 0, &series_desc};

static void test_row_figures(void **state)
{
    (void)state;
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[512], buf[8192];
    assert_int_equal(vfy_run_described(&row_case, &o, &r, msg, sizeof msg), SIM_OK);
    vfy_report_free(&r);
    assert_non_null(strstr(read_out_file("driver-row-figures-b-points.csv", buf, sizeof buf),
                           "x,y 2,y 2_ci\n0,0,0.5\n1,2,0.5\n2,4,0.5\n"));
    assert_non_null(strstr(read_out_file("driver-row-figures-a-theory.csv", buf, sizeof buf),
                           "0,0\n1,1\n"));
    read_out_file("driver-row-figures-a.gp", buf, sizeof buf);
    assert_non_null(strstr(buf, "set logscale y"));
    assert_non_null(strstr(buf, "bottom left"));
    assert_non_null(strstr(buf, "title 'model'"));
    read_out_file("driver-row-figures-last.gp", buf, sizeof buf);   /* the last row's */
    assert_non_null(strstr(buf, "'y 2'"));
    assert_null(strstr(buf, "'y 1'"));
    assert_non_null(strstr(buf, "filledcurves"));   /* the band */
    /* panels, a row left out by its curve function; only the rows with y = 1 */
    read_out_file("driver-row-figures-panels-curves.csv", buf, sizeof buf);
    assert_non_null(strstr(buf, "# x,first,first_ci,second,second_ci\n# b\n0,2,0,20,0\n"));
    assert_null(strstr(buf, "# a\n"));
    read_out_file("driver-row-figures-panels.gp", buf, sizeof buf);
    assert_non_null(strstr(buf, "lc rgb"));   /* the curve's colour */
    read_out_file("driver-row-figures-only.gp", buf, sizeof buf);
    assert_non_null(strstr(buf, "'y 1'"));
    assert_null(strstr(buf, "'y 2'"));
    vfy_report_init(&r, NULL);
    assert_int_not_equal(vfy_run_described(&row_mixed_case, &o, &r, msg, sizeof msg), SIM_OK);
    vfy_report_free(&r);

    /* row series: a curve a row against x, a panel a series (one it lacks stays empty) */
    vfy_report_init(&r, NULL);
    assert_int_equal(vfy_run_described(&series_case, &o, &r, msg, sizeof msg), SIM_OK);
    vfy_report_free(&r);
    read_out_file("driver-series-series-curves.csv", buf, sizeof buf);
    assert_non_null(strstr(buf, "# n = 8\n"));
    assert_non_null(strstr(buf, "# n = 16\n"));
    assert_non_null(strstr(buf, "T_exact,T raw,T raw_ci,T,T_ci,absent,absent_ci\n"));
    read_out_file("driver-series-series.gp", buf, sizeof buf);
    assert_non_null(strstr(buf, "set logscale x"));
}

/* A points figure's data files take its labels as their headers, each one
 * CSV field: a label with a comma or a quote is quoted, not split. */
static void test_points_headers_quoted(void **state)
{
    (void)state;
    const double x[2] = {1.0, 2.0}, y[2] = {3.0, 4.0}, ci[2] = {0.1, 0.2}, fine[2] = {0, 1};
    const double *ys[] = {y}, *cis[] = {ci}, *yfine[] = {fine};
    const char *series[] = {"a, b"}, *curves[] = {"the \"model\""};
    const vfy_points fig = {.name = "driver-quoted", .title = "t", .xlabel = "c, reduced",
                            .ylabel = "y", .npoints = 2, .x = x, .nseries = 1,
                            .series = series, .y = ys, .ci = cis, .nfine = 2, .xfine = x,
                            .ncurves = 1, .curves = curves, .yfine = yfine, .comment = "c"};
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    assert_int_equal(vfy_write_points(&o, &fig), 0);
    char buf[1024];
    assert_non_null(strstr(read_out_file("driver-quoted-points.csv", buf, sizeof buf),
                           "\n\"c, reduced\",\"a, b\",\"a, b_ci\"\n1,3,0.1\n"));
    assert_non_null(strstr(read_out_file("driver-quoted-theory.csv", buf, sizeof buf),
                           "\n\"c, reduced\",\"the \"\"model\"\"\"\n"));
}

/* A curve with a gap (a y it has no value for between two it has, as an
 * empty histogram bin) is read through cell(), for gnuplot to break its line
 * there rather than draw across, and marks its points (a lone bin between
 * two gaps stays seen); a curve that only ends early is drawn as before. */
static void test_xy_gap_breaks_the_line(void **state)
{
    (void)state;
    const double x[4] = {1.0, 2.0, 3.0, 4.0}, gappy[4] = {1.0, NAN, 3.0, 4.0},
                 short_y[4] = {1.0, 2.0, NAN, NAN};
    vfy_xy_curve curves[2] = {{.label = "histogram", .count = 4, .x = x, .y = {gappy}},
                              {.label = "reference", .count = 4, .x = x, .y = {short_y},
                               .reference = 1}};
    const vfy_xy_figure fig = {.name = "driver-gap", .title = "gap", .xlabel = "c",
                               .comment = "comment", .npanels = 1, .ylabel = {"ln f"},
                               .ncurves = 2, .curves = curves};
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    assert_int_equal(vfy_write_xy(&o, &fig), 0);
    char buf[4096];
    read_out_file("driver-gap.gp", buf, sizeof buf);
    assert_non_null(strstr(buf, "\ncell(k) = strlen(strcol(k)) ? real(strcol(k)) : NaN\n"));
    assert_non_null(strstr(buf, "index 0 using 1:(cell(2)) with linespoints pt 7 ps 0.3 lw 1.5 "));
    assert_non_null(strstr(buf, "index 1 using 1:2 with lines lw 2 dt 2 "));
    read_out_file("driver-gap-curves.csv", buf, sizeof buf);
    assert_non_null(strstr(buf, "\n1,1,0\n2,,\n3,3,0\n"));   /* the gap: an empty cell */
}

/* A work-precision figure names each prediction in its key, each with its
 * own open marker, below the plot (labels in the plot crossed the series
 * where they crowd); the predictions are the data file's last block. */
static void test_work_precision_key(void **state)
{
    (void)state;
    const double cpu[3] = {1.0, 2.0, 4.0}, err[3] = {1e-2, 5e-3, 2e-3},
                 model[3] = {1e-2, 5e-3, 2.5e-3};
    const char *const labels[3] = {"n=64", "n=256", "n=1024"};
    const size_t idx[3] = {0, 1, 2};
    const vfy_wp_series series = {.title = "jump", .idx = idx, .count = 3};
    vfy_wp_prediction pred = {.count = 2, .cpu = {0.9, 3.0}, .err = {1e-2, 1e-3},
                              .label = {strdup("1e-02: n=64"), strdup("1e-03: n=4096")}};
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    assert_int_equal(vfy_write_work_precision(&o, "driver-wp", "wp", "comment", "Err", &series,
                                              1, cpu, err, model, labels, &pred),
                     0);
    vfy_wp_prediction_free(&pred);
    char buf[4096];
    read_out_file("driver-wp.gp", buf, sizeof buf);
    assert_non_null(strstr(buf, "set key below center"));
    assert_non_null(strstr(buf, "index 1 every ::0::0 using 1:2 with points pt 6 ps 2.2 lw 2 "
                                "lc rgb 'black' title 'predicted cheapest (model), 1e-02: n=64'"));
    assert_non_null(strstr(buf, "index 1 every ::1::1 using 1:2 with points pt 4 ps 2.2 lw 2 "
                                "lc rgb 'black' title 'predicted cheapest (model), 1e-03: "
                                "n=4096'"));
    read_out_file("driver-wp-points.csv", buf, sizeof buf);
    assert_non_null(strstr(buf, "(predictions)\n0.9,0.01,0.01,1e-02: n=64\n3,0.001,0.001,"));
}

/* A grid of xy panels (figure.h, ncolumns): each column draws its own
 * curves under its title, the rows of panels on one y scale each, the key
 * once below the grid from the first panel's curves, with their colours
 * and dash types; the data's blocks name their column. */
static void test_xy_grid(void **state)
{
    (void)state;
    const double x[3] = {0.0, 0.5, 1.0}, y[3] = {1.0, 2.0, 3.0}, z[3] = {-1.0, 0.0, 5.0};
    vfy_xy_curve curves[4];
    for (size_t j = 0; j < 4; j++)
        curves[j] = (vfy_xy_curve){.label = j % 2 ? "late" : "early", .count = 3, .x = x,
                                   .y = {j < 2 ? y : z, y}, .lc = 1 + (int)(j % 2),
                                   .dt = 1 + (int)(j % 2), .column = j / 2};
    const char *const titles[] = {"left", "right"};
    const vfy_xy_figure fig = {.name = "driver-grid", .title = "grid", .xlabel = "x",
                               .comment = "comment", .npanels = 2, .ylabel = {"u", "v"},
                               .yaxis = {NULL, "v/v0"}, .ncurves = 4, .curves = curves,
                               .ncolumns = 2, .column_title = titles};
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    assert_int_equal(vfy_write_xy(&o, &fig), 0);
    char path[600], line[1024];
    snprintf(path, sizeof path, "%s/driver-grid.gp", out_dir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t panels = 0, titled = 0, key = 0, range = 0, axes = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        panels += strncmp(line, "set lmargin at screen", 21) == 0;
        axes += strstr(line, "set ylabel 'u'") != NULL || strstr(line, "set ylabel 'v/v0'") != NULL;
        titled += strcmp(line, "set title 'left'\n") == 0
                  || strcmp(line, "set title 'right'\n") == 0;
        range += strcmp(line, "set yrange [-1.3:5.3]\n") == 0;   /* z's span and y's, 5% more */
        if (strncmp(line, "plot NaN with lines", 19) == 0) {   /* the key: column 0's curves */
            key++;
            assert_non_null(strstr(line, "dt 1 lc rgb '#0072b2' title 'early', NaN with lines "
                                         "lw 1.5 dt 2 lc rgb '#d55e00' title 'late'\n"));
        } else if (strncmp(line, "plot", 4) == 0)
            assert_non_null(strstr(line, "notitle"));
    }
    fclose(f);
    assert_int_equal(panels, 4 + 1);   /* and the key's strip */
    assert_int_equal(titled, 2);
    assert_int_equal(range, 1);
    assert_int_equal(key, 1);
    assert_int_equal(axes, 2);   /* v's axis named by yaxis, its columns still v */
    snprintf(path, sizeof path, "%s/driver-grid-curves.csv", out_dir);
    f = fopen(path, "r");
    assert_non_null(f);
    size_t blocks = 0, header = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        blocks += strcmp(line, "# right: late\n") == 0;
        header += strcmp(line, "# x,u,u_ci,v,v_ci\n") == 0;
    }
    fclose(f);
    assert_int_equal(blocks, 1);
    assert_int_equal(header, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values),      cmocka_unit_test(test_pure_metrics),
        cmocka_unit_test(test_extrapolation), cmocka_unit_test(test_student_t),
        cmocka_unit_test(test_zmax_ensembles), cmocka_unit_test(test_partners),
        cmocka_unit_test(test_sweeps),      cmocka_unit_test(test_templates),
        cmocka_unit_test(test_rules_and_guards), cmocka_unit_test(test_end_to_end),
        cmocka_unit_test(test_observes),
        cmocka_unit_test(test_reference_registry), cmocka_unit_test(test_rows_variants_adjust),
        cmocka_unit_test(test_tail_exponent),
        cmocka_unit_test(test_tail_fit_and_adapters),
        cmocka_unit_test(test_batches_and_case_checks),
        cmocka_unit_test(test_derived_and_required),
        cmocka_unit_test(test_curves_by_row),
        cmocka_unit_test(test_time_average_and_abs_diff), cmocka_unit_test(test_columns),
        cmocka_unit_test(test_curve_panels), cmocka_unit_test(test_long_description),
        cmocka_unit_test(test_points_groups), cmocka_unit_test(test_points_headers_quoted),
        cmocka_unit_test(test_row_figures),
        cmocka_unit_test(test_xy_grid),
        cmocka_unit_test(test_xy_gap_breaks_the_line),
        cmocka_unit_test(test_work_precision_key),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
