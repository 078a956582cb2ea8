/* The gate's own declarations (docs/verdicts.md): every case declares the
 * errors it must catch (must_fail) on keys its scene has; every known
 * difference from a paper names a check of its case that judges the solver
 * instead; --perturb refuses what it cannot multiply; --seeds derives
 * unrelated seeds.  No simulation runs here: the runs are the CLI tests'
 * (cli_verify_must_fail, cli_verify_perturb_*). */
#include "test_verify_util.h"

#include "driver.h"
#include "gate.h"
#include "references.h"
#include "scene_ini.h"

/* The scene stem of a case's first quick row: a "scene=STEM" of its
 * settings or first row, else the description's scene or the case's name. */
static void first_row_stem(const vfy_case *c, char *stem, size_t len)
{
    const vfy_sweep *s = &c->desc->quick_rows;
    const char *texts[] = {s->sets, s->rows ? s->rows[0] : NULL};
    snprintf(stem, len, "%s", c->desc->scene ? c->desc->scene : c->name);
    for (size_t k = 0; k < 2; k++) {
        const char *at = texts[k] ? strstr(texts[k], "scene=") : NULL;
        if (at != NULL)
            snprintf(stem, len, "%.*s", (int)strcspn(at + 6, "; "), at + 6);
    }
}

/* Every case that simulates has a must_fail "KEY=FACTOR ..." with at least
 * one word; each word of it and of power_keys is a number key of the case's
 * scene (set or defaulted) and a factor > 0, not 1. */
static void test_every_case_declares_must_fail(void **state)
{
    (void)state;
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    for (size_t i = 0; i < vfy_case_count(); i++) {
        const vfy_case *c = vfy_case_at(i);
        char word[128], key[96], msg[1024];
        if (c->desc->no_simulation) {   /* no solver to perturb: its checks judge references */
            assert_null(c->desc->must_fail);
            continue;
        }
        if (vfy_must_fail_at(c->desc->must_fail, 0, word, sizeof word) != 0)
            fail_msg("%s declares no must_fail", c->name);
        sim_scene scene, solver;
        char stem[64];
        first_row_stem(c, stem, sizeof stem);
        if (vfy_load_scene_stem(stem, &o, &scene, &solver, msg, sizeof msg) != SIM_OK)
            fail_msg("%s: %s", c->name, msg);
        const char *lists[2] = {c->desc->must_fail, c->desc->power_keys};
        for (size_t list = 0; list < 2; list++)
            for (size_t k = 0; vfy_must_fail_at(lists[list], k, word, sizeof word) == 0; k++) {
                double factor, value;
                if (vfy_perturb_parse(word, key, sizeof key, &factor, msg, sizeof msg) != SIM_OK
                    || vfy_scene_real(&scene, key, &value, msg, sizeof msg) != SIM_OK)
                    fail_msg("%s: %s %s: %s", c->name, list ? "power_keys" : "must_fail", word,
                             msg);
                assert_true(factor != 1.0);
            }
    }
}

/* A must_fail (or --perturb) naming a key of a section the scene lacks is
 * refused before any simulation, naming the key and the scene. */
static void test_perturb_absent_section_is_refused(void **state)
{
    (void)state;
    const char *perturb[] = {"shear.rate=1.1"};
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir,
                     .perturbs = perturb, .nperturbs = 1};
    vfy_report r;
    vfy_report_init(&r, NULL);
    char msg[1024];
    assert_int_equal(vfy_run("quick", "grw-ex3", &o, &r, msg, sizeof msg), SIM_EINVAL);
    assert_non_null(strstr(msg, "--perturb shear.rate=1.1: shear.rate: the scene "));
    assert_non_null(strstr(msg, "grw-ex3.ini has no [shear] section"));
    assert_int_equal(r.count, 0);
    vfy_report_free(&r);
}

/* --perturb multiplies a defaulted value too: collisions.beta left to the
 * model is IHS's 1 or EHS's (1 + alpha)/2, not the 0 that stands for it. */
static void test_perturb_defaulted_beta(void **state)
{
    (void)state;
    sim_scene s;
    char msg[512];
    double beta = 0.0;
    assert_int_equal(vfy_scene_parse("[collisions]\nkernel = hard-spheres\nrestitution = 0.6\n"
                                     "model = ehs\n", "ehs.ini", NULL, 0, &s, msg, sizeof msg),
                     SIM_OK);
    assert_int_equal(vfy_scene_real(&s, "collisions.beta", &beta, msg, sizeof msg), SIM_OK);
    assert_close(beta, 0.8, 1e-15, 0.0);
    assert_int_equal(vfy_scene_parse("[collisions]\nkernel = hard-spheres\n", "ihs.ini", NULL,
                                     0, &s, msg, sizeof msg), SIM_OK);
    assert_int_equal(vfy_scene_real(&s, "collisions.beta", &beta, msg, sizeof msg), SIM_OK);
    assert_close(beta, 1.0, 0.0, 0.0);
    assert_int_equal(vfy_scene_parse("[collisions]\nkernel = hard-spheres\nbeta = 0.3\n"
                                     "model = ehs\n", "set.ini", NULL, 0, &s, msg, sizeof msg),
                     SIM_OK);
    assert_int_equal(vfy_scene_real(&s, "collisions.beta", &beta, msg, sizeof msg), SIM_OK);
    assert_close(beta, 0.3, 0.0, 0.0);
}

static void test_perturb_parse(void **state)
{
    (void)state;
    char key[96], msg[512];
    double factor;
    assert_int_equal(vfy_perturb_parse("heating.strength=1.05", key, sizeof key, &factor, msg,
                                       sizeof msg), SIM_OK);
    assert_string_equal(key, "heating.strength");
    assert_true(factor == 1.05);
    static const struct {
        const char *text, *says;
    } bad[] = {{"heating.strength=0", "factor '0' is not a positive number"},
               {"heating.strength=-1", "factor '-1' is not a positive number"},
               {"heating.strength=x", "factor 'x' is not a positive number"},
               {"heating.strength", "is not SECTION.KEY=FACTOR"},
               {"heating.nope=1.1", "heating.nope: unknown key (allowed"},
               {"heating.type=1.1", "not a number key"},
               {"particles.velocity=1.1", "not a number key"}};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        assert_int_equal(vfy_perturb_parse(bad[i].text, key, sizeof key, &factor, msg,
                                           sizeof msg), SIM_EINVAL);
        if (strstr(msg, bad[i].says) == NULL)
            fail_msg("%s: \"%s\" does not say \"%s\"", bad[i].text, msg, bad[i].says);
    }
}

/* Run 0 is the scene's own seed; the others differ from it and each other. */
static void test_derived_seeds(void **state)
{
    (void)state;
    assert_true(vfy_derived_seed(20030328, 0) == 20030328);
    uint64_t s[20];
    for (size_t k = 0; k < 20; k++) {
        s[k] = vfy_derived_seed(20030328, k);
        assert_true(s[k] == vfy_derived_seed(20030328, k));
        for (size_t j = 0; j < k; j++)
            assert_true(s[j] != s[k]);
    }
    assert_true(vfy_derived_seed(20030329, 1) != s[1]);
}

/* The check a difference names, among the description's. */
static const vfy_check_spec *find_check(const vfy_case_desc *d, const char *name)
{
    const vfy_check_spec *lists[] = {d->checks, d->case_checks};
    for (size_t k = 0; k < 2; k++)
        for (const vfy_check_spec *c = lists[k]; c && c->name; c++)
            if (strcmp(c->name, name) == 0)
                return c;
    return NULL;
}

/* A declared difference is never a bare silencer: it says what the paper
 * says and what shows it off, and names an independent check of the same
 * case, itself without a difference, that judges the solver instead. */
static void test_differences_name_their_check(void **state)
{
    (void)state;
    for (size_t i = 0; i < vfy_case_count(); i++) {
        const vfy_case_desc *d = vfy_case_at(i)->desc;
        const vfy_check_spec *lists[] = {d->checks, d->case_checks};
        for (size_t k = 0; k < 2; k++)
            for (const vfy_check_spec *c = lists[k]; c && c->name; c++) {
                if (c->differs == NULL)
                    continue;
                const vfy_difference *x = c->differs;
                if (!x->paper || !x->paper[0] || !x->evidence || !x->evidence[0]
                    || !x->judged_by)
                    fail_msg("%s: \"%s\": a difference without its paper text, evidence or "
                             "check", vfy_case_at(i)->name, c->name);
                const vfy_check_spec *j = find_check(d, x->judged_by);
                if (j == NULL || j->differs != NULL)
                    fail_msg("%s: \"%s\" is judged by \"%s\", which is no check of the case "
                             "without a difference of its own", vfy_case_at(i)->name, c->name,
                             x->judged_by);
            }
    }
}

/* Every description's data words are well formed: its derived settings
 * pass vfy_derived_check (KEY=NAME[:FORMAT], NAME a value reference or a row
 * metric of the case), and the requirements hold on the case's own first
 * scene (so none is malformed, and none refuses the shipped scenes). */
static void test_derived_and_required_words(void **state)
{
    (void)state;
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir};
    size_t derived = 0, required = 0;
    for (size_t i = 0; i < vfy_case_count(); i++) {
        const vfy_case *c = vfy_case_at(i);
        const char *bad;
        size_t badlen;
        if (!vfy_derived_check(c->desc, &bad, &badlen))
            fail_msg("%s: derived word '%.*s' is not KEY=NAME[:FORMAT]", c->name, (int)badlen,
                     bad);
        const char *w = c->desc->derived;
        for (w = w ? w + strspn(w, " ") : NULL; w && *w; w += strspn(w, " ")) {
            derived++;
            w += strcspn(w, " ");
        }
        if (c->desc->require == NULL)
            continue;
        sim_scene scene, solver;
        char stem[64], msg[1024];
        first_row_stem(c, stem, sizeof stem);
        if (vfy_load_scene_stem(stem, &o, &scene, &solver, msg, sizeof msg) != SIM_OK)
            fail_msg("%s: %s", c->name, msg);
        if (vfy_scene_requires(&scene, c->desc->require, msg, sizeof msg) != 1)
            fail_msg("%s: its scene %s does not meet '%s': %s", c->name, stem,
                     c->desc->require, msg);
        assert_non_null(c->desc->require_why);
        required++;
    }
    assert_true(derived >= 9 && required >= 14);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_case_declares_must_fail),
        cmocka_unit_test(test_perturb_absent_section_is_refused),
        cmocka_unit_test(test_perturb_defaulted_beta),
        cmocka_unit_test(test_perturb_parse),
        cmocka_unit_test(test_derived_seeds),
        cmocka_unit_test(test_differences_name_their_check),
        cmocka_unit_test(test_derived_and_required_words),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
