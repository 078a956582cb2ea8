/* Case files (case_file.h): every key reaches its member, text continues and
 * escapes as documented, bounds are tolerances by name, and each kind of bad
 * input is refused with its file, line and key; the registry's names are
 * unique, and every case file of the source tree loads (suites.h). */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "case_file.h"
#include "metrics.h"
#include "registry.h"
#include "suites.h"
#include "test_util.h"
#include "tolerances.h"

static const char good[] =
    "; a comment\n"
    "[case]\n"
    "suite = grw\n"
    "summary = a test case\n"
    "quick = true\n"
    "needs = T_exact T_finite_n\n"
    "batches = 4 1000\n"
    "variant = a: scene.observation=sampled\n"
    "variant = b: scene.observation=conditional\n"
    "notes = first line\\nsecond\n"
    "    continued, a backslash \\\\ here\n"
    "after_rows = ex5_extrapolate\n"
    "\n"
    "[paper rows]\n"
    "particles.n = 64 256\n"
    "collisions.restitution as alpha = 0.5 0.9\n"
    "sets = particles.ensembles=8;\n"
    "    scene.t_end=4\n"
    "\n"
    "[quick rows]\n"
    "row = one: particles.n=4\n"
    "row = two: particles.n=8\n"
    "\n"
    "[paper columns]\n"
    "Emax_paper = 0.0895 nan\n"
    "\n"
    "[partner ihs]\n"
    "when = is_ehs=1\n"
    "\n"
    "[metric Emax]\n"
    "fn = max_rel_err\n"
    "a = T_raw\n"
    "b = T_exact\n"
    "\n"
    "[check]\n"
    "name = {case} n={n} z\n"
    "rule = zscore\n"
    "value = T\n"
    "tol = VFY_TOL_ZMAX\n"
    "lo = -VFY_TOL_ZMAX\n"
    "from = 1\n"
    "guard = at_most\n"
    "guard_x = 4096\n"
    "\n"
    "[check]\n"
    "name = second\n"
    "rule = range\n"
    "hi = inf\n"
    "differs_paper = the paper\n"
    "differs_evidence = the route\n"
    "differs_judged_by = {case} n={n} z\n"
    "\n"
    "[case check]\n"
    "name = on the case\n"
    "rule = printed\n"
    "\n"
    "[figure]\n"
    "kind = points\n"
    "series = a=x\n"
    "series = b\n"
    "x_lo = 0.5\n"
    "\n"
    "[figure]\n"
    "kind = curves\n"
    "quantity = T\n"
    "\n"
    "[figure]\n"
    "kind = row curves\n"
    "suffix = -{alpha}\n"
    "each_row = true\n"
    "band = true\n"
    "logy = true\n"
    "logx = true\n"
    "key_inside = bottom left\n"
    "curve = y = 1x - 2=grw_curve_local_slope\n"
    "ref_curve = model=grw_curve_line_1_5\n"
    "only = alpha=0.5\n"
    "panel = top\n"
    "panel = bottom\n";

static vfy_case_file *parse_ok(const char *text)
{
    vfy_case_file *f = NULL;
    char msg[1024] = "";
    sim_status st = vfy_case_file_parse(text, "t.case", "t", vfy_named_tables, &f, msg,
                                        sizeof msg);
    if (st != SIM_OK)
        print_error("%s\n", msg);
    assert_int_equal(st, SIM_OK);
    return f;
}

static void test_every_key_reaches_its_member(void **state)
{
    (void)state;
    vfy_case_file *f = parse_ok(good);
    const vfy_case *c = vfy_case_file_case(f);
    const vfy_case_desc *d = c->desc;
    assert_string_equal(c->name, "t");
    assert_string_equal(c->suite, "grw");
    assert_int_equal(c->quick, 1);
    assert_string_equal(d->needs[0], "T_exact");
    assert_string_equal(d->needs[1], "T_finite_n");
    assert_null(d->needs[2]);
    assert_int_equal(d->batches.count, 4);
    assert_int_equal(d->batches.seed_stride, 1000);
    assert_string_equal(d->variants[1], "b: scene.observation=conditional");
    assert_null(d->variants[2]);
    /* a continuation joins with one space; \n and \\ are escapes */
    assert_string_equal(d->notes, "first line\nsecond continued, a backslash \\ here");
    assert_non_null(d->after_rows);
    assert_string_equal(d->paper_rows.keys[0].key, "particles.n");
    assert_null(d->paper_rows.keys[0].name);
    assert_string_equal(d->paper_rows.keys[1].key, "collisions.restitution");
    assert_string_equal(d->paper_rows.keys[1].name, "alpha");
    assert_string_equal(d->paper_rows.keys[1].values, "0.5 0.9");
    assert_null(d->paper_rows.keys[2].key);
    /* none after a ';' */
    assert_string_equal(d->paper_rows.sets, "particles.ensembles=8;scene.t_end=4");
    assert_string_equal(d->quick_rows.rows[1], "two: particles.n=8");
    assert_null(d->quick_rows.rows[2]);
    assert_string_equal(d->paper_columns[0].name, "Emax_paper");
    assert_int_equal(d->paper_columns[0].count, 2);
    assert_close(d->paper_columns[0].v[0], 0.0895, 0, 0);
    assert_true(isnan(d->paper_columns[0].v[1]));
    assert_null(d->paper_columns[1].name);
    assert_string_equal(d->partners[0].name, "ihs");
    assert_string_equal(d->partners[0].when, "is_ehs=1");
    assert_string_equal(d->metrics[0].name, "Emax");
    assert_ptr_equal(d->metrics[0].fn, vfy_metric_max_rel_err);
    assert_null(d->metrics[1].name);
    assert_ptr_equal(d->checks[0].rule, vfy_rule_zscore);
    assert_close(d->checks[0].tol, VFY_TOL_ZMAX, 0, 0);
    assert_close(d->checks[0].lo, -VFY_TOL_ZMAX, 0, 0);
    assert_int_equal(d->checks[0].from, 1);
    assert_ptr_equal(d->checks[0].guard.fn, vfy_guard_at_most);
    assert_close(d->checks[0].guard.x, 4096, 0, 0);
    assert_null(d->checks[0].differs);
    assert_true(isinf(d->checks[1].hi));
    assert_string_equal(d->checks[1].differs->judged_by, "{case} n={n} z");
    assert_null(d->checks[2].name);
    assert_string_equal(d->case_checks[0].name, "on the case");
    assert_int_equal(d->figures[0].kind, VFY_FIGURE_POINTS);
    assert_string_equal(d->figures[0].series[0], "a=x");
    assert_string_equal(d->figures[0].series[1], "b");
    assert_null(d->figures[0].series[2]);
    assert_int_equal(d->figures[1].kind, VFY_FIGURE_CURVES);
    const vfy_figure_spec *rows = &d->figures[2];
    assert_int_equal(rows->kind, VFY_FIGURE_ROW_CURVES);
    assert_string_equal(rows->suffix, "-{alpha}");
    assert_true(rows->each_row && rows->band && rows->logx && rows->logy);
    assert_string_equal(rows->key_inside, "bottom left");
    /* the label ends at the last '='; a fixed-x curve has its x */
    assert_string_equal(rows->curves->label, "y = 1x - 2");
    assert_non_null(rows->curves->fn);
    assert_false(rows->curves->reference);
    assert_true(isnan(rows->curves->x));
    assert_string_equal(rows->curves->next->label, "model");
    assert_true(rows->curves->next->reference);
    assert_close(rows->curves->next->x, 1.5, 0, 0);
    assert_null(rows->curves->next->next);
    assert_string_equal(rows->only, "alpha=0.5");
    assert_string_equal(rows->panels[1], "bottom");
    assert_null(rows->panels[2]);
    assert_int_equal(d->figures[3].kind, VFY_FIGURE_NONE);
    assert_null(d->label);   /* absent: NULL, as in a C description */
    vfy_case_file_free(f);
}

/* text with line `at` replaced by `line` ("" removes it). */
static char *with_line(const char *text, int at, const char *line)
{
    char *out = malloc(strlen(text) + strlen(line) + 2), *o = out;
    int n = 1;
    for (const char *p = text; *p; n++) {
        const char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t)(nl - p + 1) : strlen(p);
        if (n == at) {
            if (line[0])
                o += sprintf(o, "%s\n", line);
        } else {
            memcpy(o, p, len);
            o += len;
        }
        p += len;
    }
    *o = '\0';
    return out;
}

/* "needs =" with no word: an empty list, not none (each row's references are
 * made, none required of every row). */
static void test_empty_needs_is_a_list(void **state)
{
    (void)state;
    char *text = with_line(good, 6, "needs =");
    vfy_case_file *f = parse_ok(text);
    const vfy_case_desc *d = vfy_case_file_case(f)->desc;
    assert_non_null(d->needs);
    assert_null(d->needs[0]);
    assert_null(d->values);
    vfy_case_file_free(f);
    free(text);
}

/* A function named once per quantity (named.h: fixed_x) sets x; the file
 * may not set it too, before the name or after. */
static void test_fixed_x_is_the_function_s(void **state)
{
    (void)state;
    char *text = with_line(good, 31, "fn = hard_violations_hs");
    vfy_case_file *f = parse_ok(text);
    const vfy_metric *m = &vfy_case_file_case(f)->desc->metrics[0];
    const vfy_named_fn *e = NULL;
    for (const vfy_named_fn *const *t = vfy_named_tables; *t && e == NULL; t++)
        e = vfy_named_find(*t, VFY_FN_METRIC, "hard_violations_hs");
    assert_non_null(e);
    assert_int_equal(e->fixed_x, 1);
    assert_ptr_equal(m->fn, e->metric);
    assert_close(m->x, e->x, 0, 0);
    assert_true(m->x > 0);   /* not the default */
    vfy_case_file_free(f);
    free(text);
    char msg[1024];
    const char *twice[] = {"fn = hard_violations_hs\nx = 3", "x = 3\nfn = hard_violations_hs"};
    for (size_t i = 0; i < 2; i++) {
        text = with_line(good, 31, twice[i]);
        f = (vfy_case_file *)1;
        assert_int_equal(vfy_case_file_parse(text, "t.case", "t", vfy_named_tables, &f, msg,
                                             sizeof msg), SIM_EINVAL);
        assert_null(f);
        assert_non_null(strstr(msg, "'hard_violations_hs' sets x itself"));
        free(text);
    }
}

/* The file `good` with line `at` replaced is refused with a message
 * containing `expected`. */
static void refused(int at, const char *line, const char *expected)
{
    char *text = with_line(good, at, line);
    vfy_case_file *f = (vfy_case_file *)1;
    char msg[1024] = "";
    sim_status st = vfy_case_file_parse(text, "t.case", "t", vfy_named_tables, &f, msg,
                                        sizeof msg);
    if (st == SIM_OK || strstr(msg, expected) == NULL)
        print_error("line %d '%s': got '%s', expected '%s'\n", at, line, msg, expected);
    assert_int_not_equal(st, SIM_OK);
    assert_null(f);
    assert_non_null(strstr(msg, expected));
    free(text);
}

static void test_bad_input_names_file_line_and_key(void **state)
{
    (void)state;
    refused(3, "suite = grw\nsuit = x", "t.case:4: [case] suit: unknown key (allowed suite,");
    refused(5, "quick = yes", "t.case:5: [case] quick: 'yes' (allowed true, false)");
    refused(7, "batches = 0 1000", "t.case:7: [case] batches:");
    refused(12, "after_rows = no_such_hook", "t.case:12: [case] after_rows: unknown hook "
            "'no_such_hook'");
    refused(14, "[paper row]", "t.case:14: [paper row]: unknown section");
    refused(16, "collisions.restitution as = 0.5", "t.case:16: [paper rows] "
            "collisions.restitution as: a swept key is");
    refused(25, "Emax_paper = 1\nEmax_paper = 2", "t.case:26: [paper columns] Emax_paper: set "
            "twice");
    refused(25, "Emax_paper = 0.0895 x", "t.case:25: [paper columns] Emax_paper: 'x' is not "
            "a number");
    refused(31, "fn = max_rel_error", "t.case:31: [metric Emax] fn: unknown metric");
    refused(37, "rule = zscores", "t.case:37: [check] rule: unknown rule 'zscores'");
    refused(39, "tol = VFY_TOL_ZMAXX", "t.case:39: [check] tol: 'VFY_TOL_ZMAXX' is no tolerance");
    refused(39, "tol = 4.5.", "t.case:39: [check] tol: '4.5.' is not a number");
    refused(41, "from = -1", "t.case:41: [check] from: '-1' is not a count");
    refused(42, "guard = at_most\nguard = at_least", "t.case:43: [check] guard: set twice");
    refused(37, "", "t.case:35: [check] needs name and rule");
    refused(51, "", "t.case:45: [check] second: a known difference needs");
    refused(58, "kind = bars", "t.case:58: [figure] kind: 'bars' (allowed curves, points, "
            "row curves, row points)");
    refused(75, "curve = grw_curve_ln_f", "t.case:75: [figure] curve: 'grw_curve_ln_f' "
            "(allowed LABEL=FUNCTION)");
    refused(75, "curve = f=no_such_curve", "t.case:75: [figure] curve: unknown curve "
            "'no_such_curve'");
    refused(75, "row_label = {label}", "t.case:67: [figure]: row_label (a curve per row) or "
            "each_row (a figure per row), not both");
    refused(75, "", "t.case:67: [figure] of kind row curves or row points needs a curve");
    refused(77, "only = alpha", "t.case:67: [figure] only: 'alpha' (allowed NAME=VALUE)");
    refused(69, "suffix = -rows", "t.case:67: [figure] each_row needs a suffix that tells");
    refused(61, "x_lo = 0.5\nlogy = true", "t.case:57: [figure]: curve, ref_curve, row_label, "
            "each_row, band, logx, logy, key_inside and only are for kinds row curves and "
            "row points");
    refused(54, "name = on the case\nguard = after_first", "t.case:55: [case check] guard: "
            "'after_first' needs a row (allowed here at_most,");
    refused(32, "    more", "t.case:32: [metric Emax] fn: an indented line continues only a "
            "text value");
    refused(31, "fn max_rel_err", "t.case:31: not a [section] header");
    refused(3, "", "t.case: [case] needs suite and summary");
    refused(12, "derived = scene.t_end=no_such_value", "t.case: [case] derived: "
            "'scene.t_end=no_such_value' (allowed KEY=NAME[:FORMAT]");
    refused(12, "derived = no.key=Emax", "t.case: [case] derived: 'no.key=Emax'");
    /* The empty name: found by fuzz_case, it read past the registry's names. */
    refused(12, "derived = scene.t_end=", "t.case: [case] derived: 'scene.t_end='");
    refused(12, "derived = scene.t_end=Emax:g", "t.case: [case] derived: 'scene.t_end=Emax:g'");
    char long_line[260];
    memset(long_line, 'x', sizeof long_line - 1);
    long_line[sizeof long_line - 1] = '\0';
    refused(1, long_line, "t.case:1: line too long");
    refused(10, "notes = a \\q b", "t.case:10: [case] notes: unknown escape '\\q'");
}

static void write_file(const char *dir, const char *name, const char *text)
{
    char path[600];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* Load dir/t.case: its status, msg as the loader says it. */
static sim_status load_t(const char *dir, vfy_case_file **f, char *msg, size_t len)
{
    char path[600];
    snprintf(path, sizeof path, "%s/t.case", dir);
    return vfy_case_file_load(path, "t", vfy_named_tables, f, msg, len);
}

/* [include NAME] reads NAME.inc where it stands, nested too; each mistake in
 * an included file is named by that file and its line. */
static void test_include(void **state)
{
    (void)state;
    char dir[] = "/tmp/gdsmc-include-XXXXXX", msg[1024] = "";
    assert_non_null(mkdtemp(dir));
    write_file(dir, "t.case", "[case]\nsuite = grw\nsummary = s\n[include checks]\n"
                              "[check]\nname = last\nrule = range\n");
    write_file(dir, "checks.inc", "; shared\n[check]\nname = first\nrule = zscore\n"
                                  "[include more]\n");
    write_file(dir, "more.inc", "[check]\nname = second\nrule = relative\n"
                                "tol = VFY_TOL_ZMAX\n");
    vfy_case_file *f = NULL;
    sim_status st = load_t(dir, &f, msg, sizeof msg);
    if (st != SIM_OK)
        print_error("%s\n", msg);
    assert_int_equal(st, SIM_OK);
    const vfy_check_spec *checks = vfy_case_file_case(f)->desc->checks;
    assert_string_equal(checks[0].name, "first");
    assert_string_equal(checks[1].name, "second");
    assert_close(checks[1].tol, VFY_TOL_ZMAX, 0, 0);
    assert_string_equal(checks[2].name, "last");
    assert_null(checks[3].name);
    vfy_case_file_free(f);

    static const struct {
        const char *file, *text, *msg;
    } bad[] = {
        {"more.inc", "[check]\nname = second\nrule = relativ\n",
         "/more.inc:3: [check] rule: unknown rule 'relativ'"},
        {"more.inc", "[check]\nname = second\n", "/more.inc:1: [check] needs name and rule"},
        {"more.inc", "[check]\nname second\n", "/more.inc:2: not a [section] header"},
        {"checks.inc", "[check]\nname = first\nrule = zscore\n[include Bad]\n",
         "/checks.inc:4: [include NAME]: NAME of a-z"},
        {"checks.inc", "[include none]\n", "/checks.inc:1: [include none]: "},
        {"checks.inc", "[case]\nsummary = again\n", "/checks.inc:2: [case] summary: set twice"},
        {"checks.inc", "[include checks]\n", "includes nested deeper than 8"},
        {"t.case", "[case]\nsuite = grw\nsummary = s\n[include more]\nlabel = x\n",
         "/t.case:5: a key right after an included file"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        write_file(dir, "t.case", "[case]\nsuite = grw\nsummary = s\n[include checks]\n");
        write_file(dir, "checks.inc", "[include more]\n");
        write_file(dir, "more.inc", "[check]\nname = second\nrule = relative\n");
        write_file(dir, bad[i].file, bad[i].text);
        f = (vfy_case_file *)1;
        st = load_t(dir, &f, msg, sizeof msg);
        if (st == SIM_OK || strstr(msg, bad[i].msg) == NULL)
            print_error("%zu: got '%s', expected '%s'\n", i, msg, bad[i].msg);
        assert_int_not_equal(st, SIM_OK);
        assert_null(f);
        assert_non_null(strstr(msg, bad[i].msg));
    }
    /* a NUL byte: not text (the reader shared with scene files, text.h) */
    char path[600];
    snprintf(path, sizeof path, "%s/t.case", dir);
    FILE *nul = fopen(path, "wb");
    assert_non_null(nul);
    fwrite("[case]\0\n", 1, 8, nul);
    fclose(nul);
    assert_int_equal(load_t(dir, &f, msg, sizeof msg), SIM_EINVAL);
    assert_non_null(strstr(msg, "/t.case: NUL byte (allowed text only)"));
    const char *files[] = {"t.case", "checks.inc", "more.inc"};
    for (size_t i = 0; i < 3; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, files[i]);
        remove(path);
    }
    rmdir(dir);
}

/* Every name of every table, unique across the tables, so that a case
 * file's name means one function. */
static void test_registry_names_are_unique(void **state)
{
    (void)state;
    size_t count = 0;
    for (const vfy_named_fn *const *t = vfy_named_tables; *t; t++)
        for (const vfy_named_fn *e = *t; e->name; e++) {
            count++;
            for (const vfy_named_fn *const *u = vfy_named_tables; *u; u++)
                for (const vfy_named_fn *g = *u; g->name; g++)
                    if (g != e && strcmp(g->name, e->name) == 0)
                        fail_msg("%s named twice", e->name);
        }
    assert_true(count > 100);
}

/* The source tree's cases: all load, in cases.list's order; a list naming a
 * missing file, or a name twice, is refused. */
static void test_source_tree_cases_load(void **state)
{
    (void)state;
    const char *src = getenv("GDSMC_SOURCE_DIR");
    char dir[512], msg[1024] = "";
    snprintf(dir, sizeof dir, "%s/verify/cases/scenes", src ? src : "..");
    sim_status st = vfy_cases_load(dir, msg, sizeof msg);
    if (st != SIM_OK)
        print_error("%s\n", msg);
    assert_int_equal(st, SIM_OK);
    assert_true(vfy_case_count() >= 38);
    assert_string_equal(vfy_case_at(0)->name, "grw-ex3");
    assert_non_null(vfy_case_find("as-slab"));

    char tmp[] = "/tmp/gdsmc-cases-XXXXXX", path[600];
    assert_non_null(mkdtemp(tmp));
    snprintf(path, sizeof path, "%s/cases.list", tmp);
    static const struct {
        const char *list;
        sim_status status;
        const char *msg;
    } bad[] = {
        {"# comment\nnone-here\n", SIM_EIO, "none-here.case: cannot open"},
        {"a\na\n", SIM_EINVAL, "cases.list:2: a listed twice"},
        {"Bad_Name\n", SIM_EINVAL, "cases.list:1: 'Bad_Name' is not a case name"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        FILE *f = fopen(path, "w");
        assert_non_null(f);
        fputs(bad[i].list, f);
        fclose(f);
        assert_int_equal(vfy_cases_load(tmp, msg, sizeof msg), bad[i].status);
        assert_non_null(strstr(msg, bad[i].msg));
        assert_int_equal(vfy_case_count(), 0);   /* nothing kept of a failed load */
    }
    remove(path);
    rmdir(tmp);
    vfy_cases_unload();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_key_reaches_its_member),
        cmocka_unit_test(test_empty_needs_is_a_list),
        cmocka_unit_test(test_fixed_x_is_the_function_s),
        cmocka_unit_test(test_bad_input_names_file_line_and_key),
        cmocka_unit_test(test_include),
        cmocka_unit_test(test_registry_names_are_unique),
        cmocka_unit_test(test_source_tree_cases_load),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
