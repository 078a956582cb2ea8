/* Checkpoints (verify/protocol/checkpoint.h): a saved result comes back bit for bit;
 * a checkpoint of another scene, or a damaged one, is never used; a
 * simulation one verify run needs twice runs once (verify/driver/cases.h).  And the
 * solver protocol's result file (verify/protocol/result.h), the other way a result
 * is written down. */
#include "test_util.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cases.h"
#include "checkpoint.h"
#include "observe.h"
#include "result.h"

static char dir[64];

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/gdsmc-ckpt-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static sim_scene small_scene(void)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.outputs = 3;
    s.particles.n = 8;
    s.particles.ensembles = 5;
    s.seed = 42;
    return s;
}

/* A result with awkward numbers: non-representable decimals, a subnormal,
 * an infinity, a negative zero. */
static void fill(sim_ensemble_result *r, const sim_scene *s)
{
    memset(r, 0, sizeof *r);
    r->outputs = s->outputs;
    r->ensembles = s->particles.ensembles;
    r->n = s->particles.n;
    r->observables = SIM_OBS_BASE + 50;   /* as with a 50-layer profile: no cap */
    size_t len = r->outputs * r->observables;
    r->t = malloc(r->outputs * sizeof *r->t);
    r->mean = malloc(len * sizeof *r->mean);
    r->var = malloc(len * sizeof *r->var);
    r->ci = malloc(len * sizeof *r->ci);
    assert_non_null(r->t && r->mean && r->var && r->ci);
    for (size_t m = 0; m < r->outputs; m++)
        r->t[m] = 0.1 * (double)m;
    for (size_t i = 0; i < len; i++) {
        r->mean[i] = 1.0 / 3.0 + (double)i;
        r->var[i] = 4.9e-324 * (double)(i + 1);
        r->ci[i] = i == 1 ? INFINITY : i == 2 ? -0.0 : sqrt((double)i);
    }
    r->counts = (sim_counts){12345678901234ULL, 7, 8, 0, 99};
    r->cpu_seconds = 1.2345678901234567;
    r->wall_seconds = 0.1;
    r->threads = 2;
}

/* The solver protocol's result file (verify/protocol/result.h) carries every number
 * exactly: the means as they are, the population variances as sample
 * variances (times N/(N - 1)), the steady quantities in their own section. */
static void test_result_file(void **state)
{
    (void)state;
    sim_scene s = small_scene();
    sim_ensemble_result a;
    fill(&a, &s);
    a.nsteady = 2;   /* the last two numbers stand for steady T and a2 */
    const size_t rows = a.outputs * a.observables;
    a.steady_mean = a.mean + rows - 2;
    a.steady_var = a.var + rows - 2;
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    assert_non_null(f);
    assert_int_equal(vfy_result_write(f, "test solver 1.0", &s, &a), 0);
    assert_int_equal(fclose(f), 0);
    assert_non_null(strstr(text, "# gdsmc-result 1\n# solver = test solver 1.0\n# n = 8\n"
                                 "# ensembles = 5\n# cpu_seconds = 1.2345678901234567\n"
                                 "# events = 12345678901234\n# violations = 0\n"
                                 "t,T,T_var,T_raw,T_raw_var,"));
    const double N = (double)a.ensembles;
    char *line = strstr(text, "\n0,");
    for (size_t m = 0; m < a.outputs; m++) {
        assert_non_null(line);
        char *p = line + 1;
        assert_true(strtod(p, &p) == a.t[m]);
        for (int k = 0; k < SIM_OBS_BASE; k++) {
            assert_int_equal(*p++, ',');
            assert_true(strtod(p, &p) == sim_result_mean(&a, m, k));
            assert_int_equal(*p++, ',');
            assert_true(strtod(p, &p) == sim_result_var(&a, m, k) * N / (N - 1.0));
        }
        assert_int_equal(*p, '\n');
        line = p;
    }
    char want[200];
    snprintf(want, sizeof want, "\n# steady\nname,mean,var\nT,%.17g,%.17g\na2,", a.steady_mean[0],
             a.steady_var[0] * N / (N - 1.0));
    assert_non_null(strstr(text, want));
    free(text);
    sim_ensemble_result_free(&a);
}

static void test_round_trip_is_exact(void **state)
{
    (void)state;
    sim_scene s = small_scene();
    sim_ensemble_result a, b;
    fill(&a, &s);
    char msg[256];
    assert_int_equal(vfy_checkpoint_save(dir, "test n=8", &s, &a, msg, sizeof msg), SIM_OK);
    assert_int_equal(vfy_checkpoint_load(dir, &s, &b), 1);
    size_t len = a.outputs * a.observables;
    assert_int_equal(b.outputs, a.outputs);
    assert_int_equal(b.observables, a.observables);
    assert_int_equal(b.ensembles, a.ensembles);
    assert_int_equal(b.n, a.n);
    assert_memory_equal(b.t, a.t, a.outputs * sizeof *a.t);
    assert_memory_equal(b.mean, a.mean, len * sizeof *a.mean);
    assert_memory_equal(b.var, a.var, len * sizeof *a.var);
    assert_memory_equal(b.ci, a.ci, len * sizeof *a.ci);
    assert_memory_equal(&b.counts, &a.counts, sizeof a.counts);
    assert_memory_equal(&b.cpu_seconds, &a.cpu_seconds, sizeof a.cpu_seconds);
    assert_memory_equal(&b.wall_seconds, &a.wall_seconds, sizeof a.wall_seconds);
    assert_int_equal(b.threads, 2);
    sim_ensemble_result_free(&a);
    sim_ensemble_result_free(&b);
}

/* Another seed, n or heating is another simulation: nothing to resume.  The
 * file name and title are not part of the key. */
static void test_other_scene_not_used(void **state)
{
    (void)state;
    sim_scene s = small_scene();
    sim_ensemble_result a, b;
    fill(&a, &s);
    char msg[256];
    assert_int_equal(vfy_checkpoint_save(dir, "test", &s, &a, msg, sizeof msg), SIM_OK);
    sim_scene other = s;
    other.seed = 43;
    assert_int_equal(vfy_checkpoint_load(dir, &other, &b), 0);
    assert_null(b.mean);
    other = s;
    other.particles.n = 9;
    assert_int_equal(vfy_checkpoint_load(dir, &other, &b), 0);
    other = s;
    other.heating.strength = 1e-300;
    assert_int_equal(vfy_checkpoint_load(dir, &other, &b), 0);
    other = s;
    snprintf(other.file, sizeof other.file, "elsewhere/same.ini");
    snprintf(other.title, sizeof other.title, "another title");
    assert_int_equal(vfy_checkpoint_load(dir, &other, &b), 1);
    sim_ensemble_result_free(&a);
    sim_ensemble_result_free(&b);
}

/* A checkpoint cut short (as by a crash of an older version writing in
 * place) or with a wrong word is ignored, never half-used. */
static void test_damaged_not_used(void **state)
{
    (void)state;
    sim_scene s = small_scene();
    s.seed = 7;
    sim_ensemble_result a, b;
    fill(&a, &s);
    char msg[256], path[128];
    assert_int_equal(vfy_checkpoint_save(dir, "test", &s, &a, msg, sizeof msg), SIM_OK);
    snprintf(path, sizeof path, "%s/%016llx.ckpt", dir,
             (unsigned long long)vfy_checkpoint_key(&s));
    FILE *f = fopen(path, "r+");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fclose(f);
    assert_int_equal(truncate(path, size - 10), 0);   /* loses "end" and a number */
    assert_int_equal(vfy_checkpoint_load(dir, &s, &b), 0);
    assert_null(b.mean);

    assert_int_equal(vfy_checkpoint_save(dir, "test", &s, &a, msg, sizeof msg), SIM_OK);
    f = fopen(path, "r+");
    assert_non_null(f);
    fputs("gdsmc-checkpoint 2", f);   /* a format this version does not know */
    fclose(f);
    assert_int_equal(vfy_checkpoint_load(dir, &s, &b), 0);
    sim_ensemble_result_free(&a);
}

/* A checkpoint another build wrote (its key made with another executable
 * identity) is never used: another build's engine may draw other numbers. */
static void test_other_build_not_used(void **state)
{
    (void)state;
    const uint64_t build = vfy_build_identity();
    assert_true(build != 0);   /* this test's executable is readable */
    assert_true(vfy_build_identity() == build);
    sim_scene s = small_scene();
    s.seed = 11;
    assert_true(vfy_checkpoint_key(&s) == vfy_checkpoint_key_for(&s, build));
    assert_true(vfy_checkpoint_key_for(&s, build ^ 1) != vfy_checkpoint_key(&s));
    sim_ensemble_result a, b;
    fill(&a, &s);
    char msg[256], mine[128], theirs[128];
    assert_int_equal(vfy_checkpoint_save(dir, "test", &s, &a, msg, sizeof msg), SIM_OK);
    snprintf(mine, sizeof mine, "%s/%016llx.ckpt", dir,
             (unsigned long long)vfy_checkpoint_key(&s));
    snprintf(theirs, sizeof theirs, "%s/%016llx.ckpt", dir,
             (unsigned long long)vfy_checkpoint_key_for(&s, build ^ 1));
    assert_int_equal(rename(mine, theirs), 0);   /* as if the other build wrote it */
    assert_int_equal(vfy_checkpoint_load(dir, &s, &b), 0);
    assert_null(b.mean);
    sim_ensemble_result_free(&a);
}

/* Within one verify run (o.finished), a simulation an earlier row finished
 * is taken from its checkpoint: a checkpoint doctored after the first run
 * (one collision more) is what the second call returns.  Without o.finished,
 * or for another seed, the engine runs. */
static void test_repeat_taken_from_checkpoint(void **state)
{
    (void)state;
    sim_scene s = small_scene();
    s.t_end = 1.0;
    s.collisions.present = 1;
    vfy_finished finished = {0};
    vfy_options o = {.size = VFY_QUICK, .checkpoint_dir = dir, .finished = &finished};
    sim_ensemble_result first, doctored, repeat, rerun, other;
    char msg[256];
    assert_int_equal(vfy_simulate(&s, &o, "first", &first, msg, sizeof msg), SIM_OK);
    assert_true(first.counts.collisions > 0);
    assert_int_equal(finished.count, 1);

    assert_int_equal(vfy_checkpoint_load(dir, &s, &doctored), 1);
    doctored.counts.collisions++;
    assert_int_equal(vfy_checkpoint_save(dir, "doctored", &s, &doctored, msg, sizeof msg),
                     SIM_OK);
    assert_int_equal(vfy_simulate(&s, &o, "repeat", &repeat, msg, sizeof msg), SIM_OK);
    assert_int_equal(repeat.counts.collisions, first.counts.collisions + 1);
    assert_memory_equal(repeat.mean, first.mean,
                        first.outputs * first.observables * sizeof *first.mean);

    o.finished = NULL;   /* as in a program that does not keep the set */
    assert_int_equal(vfy_simulate(&s, &o, "rerun", &rerun, msg, sizeof msg), SIM_OK);
    assert_int_equal(rerun.counts.collisions, first.counts.collisions);

    o.finished = &finished;
    s.seed++;
    assert_int_equal(vfy_simulate(&s, &o, "other seed", &other, msg, sizeof msg), SIM_OK);
    assert_int_equal(finished.count, 2);   /* it ran: a finished simulation was saved */
    sim_ensemble_result *all[] = {&first, &doctored, &repeat, &rerun, &other};
    for (size_t k = 0; k < sizeof all / sizeof *all; k++)
        sim_ensemble_result_free(all[k]);
    vfy_finished_free(&finished);
}

static void test_unwritable_dir_is_an_error(void **state)
{
    (void)state;
    sim_scene s = small_scene();
    sim_ensemble_result a;
    fill(&a, &s);
    char msg[256];
    assert_int_equal(vfy_checkpoint_save("/proc/gdsmc-no", "test", &s, &a, msg, sizeof msg),
                     SIM_EIO);
    assert_non_null(strstr(msg, "/proc/gdsmc-no/"));
    assert_non_null(strstr(msg, ": cannot write: "));
    sim_ensemble_result_free(&a);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip_is_exact),
        cmocka_unit_test(test_result_file),
        cmocka_unit_test(test_other_scene_not_used),
        cmocka_unit_test(test_damaged_not_used),
        cmocka_unit_test(test_other_build_not_used),
        cmocka_unit_test(test_unwritable_dir_is_an_error),
        cmocka_unit_test(test_repeat_taken_from_checkpoint),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
