/* Tests of verify/protocol/result.c, the solver protocol's result files (version 1).
 *
 * What `gdsmc run --result` writes is read back to the same numbers; the
 * trap group hands the reader each kind of bad result and asserts the
 * status and the exact message (file, line, column).
 */
#include "test_util.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "result.h"
#include "scene_ini.h"
#include "solver.h"

/* t_end = 8, 3 outputs (t = 0, 4, 8), n = 8, N = 5; with [steady] (4 bins)
 * when steady is set. */
static sim_scene scene_of(int steady)
{
    sim_scene s;
    char msg[256];
    const char *text = steady ? "[scene]\nt_end = 8\noutputs = 3\n[particles]\nn = 8\n"
                                "ensembles = 5\n[steady]\nbins = 4\n"
                              : "[scene]\nt_end = 8\noutputs = 3\n[particles]\nn = 8\n"
                                "ensembles = 5\n";
    assert_int_equal(vfy_scene_parse(text, "s.ini", NULL, 0, &s, msg, sizeof msg), SIM_OK);
    return s;
}

/* A result of that scene with awkward numbers. */
static void fill(const sim_scene *s, sim_ensemble_result *r)
{
    memset(r, 0, sizeof *r);
    r->outputs = s->outputs;
    r->observables = SIM_OBS_BASE;
    r->ensembles = s->particles.ensembles;
    r->n = s->particles.n;
    r->nsteady = s->steady.present ? 10 + s->steady.bins : 0;
    const size_t rows = r->outputs * r->observables, len = rows + r->nsteady;
    r->t = malloc(r->outputs * sizeof *r->t);
    r->mean = malloc(len * sizeof *r->mean);
    r->var = malloc(len * sizeof *r->var);
    r->ci = malloc(len * sizeof *r->ci);
    assert_true(r->t && r->mean && r->var && r->ci);
    for (size_t m = 0; m < r->outputs; m++)
        r->t[m] = 4.0 * (double)m;
    for (size_t i = 0; i < len; i++) {
        r->mean[i] = (i % 3 ? -1.0 : 1.0) / 3.0 * (double)(i + 1);
        r->var[i] = 0.1 * (double)i + 2.385e-7;
        r->ci[i] = 0.0;
    }
    r->steady_mean = r->mean + rows;
    r->steady_var = r->var + rows;
    r->steady_ci = r->ci + rows;
    r->counts.candidates = 987654321;
    r->cpu_seconds = 0.25;
}

static char *written(const sim_scene *s, const sim_ensemble_result *r)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    assert_non_null(f);
    assert_int_equal(vfy_result_write(f, "mine 2.3", s, r), 0);
    assert_int_equal(fclose(f), 0);
    return text;
}

static void round_trip(int steady)
{
    sim_scene s = scene_of(steady);
    sim_ensemble_result a, b;
    vfy_result_info info;
    char msg[512];
    fill(&s, &a);
    char *text = written(&s, &a);
    sim_status st = vfy_result_parse(text, strlen(text), "r.csv", &s, &b, &info, msg, sizeof msg);
    if (st != SIM_OK)
        print_error("%s\n", msg);
    assert_int_equal(st, SIM_OK);
    assert_string_equal(info.solver, "mine 2.3");
    assert_true(info.has_cpu && info.has_events && info.has_violations);
    assert_int_equal(b.counts.candidates, 987654321);
    assert_true(b.cpu_seconds == 0.25);
    const size_t len = a.outputs * a.observables + a.nsteady;
    assert_int_equal(b.nsteady, a.nsteady);
    assert_int_equal(info.steady_reported, a.nsteady);
    for (size_t i = 0; i < len; i++) {
        assert_true(b.mean[i] == a.mean[i]);                   /* 17 digits: exact */
        assert_close(b.var[i], a.var[i], 4e-16, 0.0);          /* x N/(N-1), x (N-1)/N */
        assert_close(b.ci[i], 3.2 * sqrt(a.var[i] / 5.0), 4e-16, 0.0);
    }
    for (int k = 0; k < SIM_OBS_BASE; k++)
        assert_true(info.reported[k]);
    free(text);
    sim_ensemble_result_free(&a);
    sim_ensemble_result_free(&b);
}

static void test_round_trip(void **state)
{
    (void)state;
    round_trip(0);
    round_trip(1);
}

/* A solver may report only some observables, no steady section and no
 * counts: the rest is NaN, and info says so. */
static void test_partial_result(void **state)
{
    (void)state;
    sim_scene s = scene_of(1);
    const char *text = "# gdsmc-result 1\n# n = 8\n# ensembles = 5\n# a comment = anything\n"
                       "t,T_raw,T_raw_var\n0,1.5,0.25\n4,2,1\n8.000000000001,3,0\n";
    sim_ensemble_result r;
    vfy_result_info info;
    char msg[256];
    assert_int_equal(vfy_result_parse(text, strlen(text), "p.csv", &s, &r, &info, msg,
                                      sizeof msg), SIM_OK);
    assert_true(info.reported[SIM_OBS_T_RAW]);
    assert_false(info.reported[SIM_OBS_T]);
    assert_false(info.has_cpu || info.has_events || info.has_violations);
    assert_int_equal(info.steady_reported, 0);
    assert_true(sim_result_mean(&r, 1, SIM_OBS_T_RAW) == 2.0);
    assert_close(sim_result_ci(&r, 1, SIM_OBS_T_RAW), 3.2 * sqrt(0.8 / 5.0), 1e-15, 0.0);
    assert_true(isnan(sim_result_mean(&r, 1, SIM_OBS_T)));
    assert_true(isnan(r.steady_mean[0]));
    assert_true(r.t[2] == 8.0);
    sim_ensemble_result_free(&r);
}

/* The --solver command split into words as a shell splits a simple
 * command: quotes group, \" and \\ inside double quotes, {scene} kept. */
static void test_split_command(void **state)
{
    (void)state;
    char *w[8], buf[256], msg[128];
    int n = vfy_solver_split("  python3 'my solver.py'  --in={scene} \"a \\\"b\\\" \\\\c\" x''y ",
                             w, 8, buf, sizeof buf, msg, sizeof msg);
    assert_int_equal(n, 5);
    assert_string_equal(w[0], "python3");
    assert_string_equal(w[1], "my solver.py");
    assert_string_equal(w[2], "--in={scene}");
    assert_string_equal(w[3], "a \"b\" \\c");
    assert_string_equal(w[4], "xy");
    assert_int_equal(vfy_solver_split("sh -c \"echo", w, 8, buf, sizeof buf, msg, sizeof msg), -1);
    assert_string_equal(msg, "an unterminated double quote");
    assert_int_equal(vfy_solver_split("   ", w, 8, buf, sizeof buf, msg, sizeof msg), -1);
    assert_string_equal(msg, "no command");
    assert_int_equal(vfy_solver_split("a b c", w, 2, buf, sizeof buf, msg, sizeof msg), -1);
    assert_string_equal(msg, "more than 2 words");
}

/* The solver's identity changes with the command and with the contents of
 * the files it names, not with anything else. */
static void test_solver_identity(void **state)
{
    (void)state;
    char path[] = "/tmp/gdsmc-solver-XXXXXX", command[128];
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, "print(1)\n", 9), 9);
    snprintf(command, sizeof command, "python3 %s {scene} {out}", path);
    const uint64_t a = vfy_solver_identity(command), again = vfy_solver_identity(command);
    assert_true(a == again);
    assert_int_equal(write(fd, "print(2)\n", 9), 9);   /* the script changed */
    assert_true(vfy_solver_identity(command) != a);
    snprintf(command, sizeof command, "python3 %s {scene} {out} --fast", path);
    assert_true(vfy_solver_identity(command) != a);
    close(fd);
    unlink(path);
}

/* ---- traps: each bad result, its status and exact message ------------- */

static void expect(int steady, const char *text, const char *message)
{
    sim_scene s = scene_of(steady);
    sim_ensemble_result r;
    vfy_result_info info;
    char msg[512];
    assert_int_equal(vfy_result_parse(text, strlen(text), "bad.csv", &s, &r, &info, msg,
                                      sizeof msg), SIM_EINVAL);
    assert_string_equal(msg, message);
    assert_null(r.mean);   /* nothing left allocated */
}

#define HEAD "# gdsmc-result 1\n# n = 8\n# ensembles = 5\n"
#define COLS "t,T,T_var\n"

static void trap_results(void **state)
{
    (void)state;
    expect(0, "", "bad.csv: empty result (the solver wrote nothing)");
    expect(0, " \n\n", "bad.csv: empty result (the solver wrote nothing)");
    expect(0, "t,T,T_var\n", "bad.csv:1: the first line must be '# gdsmc-result 1' (the "
           "protocol version), got 't,T,T_var'");
    expect(0, "# gdsmc-result 2\n", "bad.csv:1: protocol version '2', this gdsmc reads version 1");
    expect(0, "# gdsmc-result 1\n# ensembles = 5\n" COLS,
           "bad.csv: no '# n = ' line (required: the scene's particles.n)");
    expect(0, "# gdsmc-result 1\n# n = 8\n" COLS,
           "bad.csv: no '# ensembles = ' line (required: the scene's particles.ensembles)");
    expect(0, "# gdsmc-result 1\n# n = 64\n# ensembles = 5\n",
           "bad.csv:2: n = 64 does not match the scene's particles.n = 8");
    expect(0, "# gdsmc-result 1\n# n = 8\n# ensembles = 4\n",
           "bad.csv:3: ensembles = 4 does not match the scene's particles.ensembles = 5");
    expect(0, "# gdsmc-result 1\n# n = 8.5\n",
           "bad.csv:2: n = '8.5' is not a count (allowed 0, 1, 2, ...)");
    expect(0, HEAD "# cpu_seconds = fast\n",
           "bad.csv:4: cpu_seconds = 'fast' is not a number");
    expect(0, HEAD "# violations = -1\n",
           "bad.csv:4: violations = '-1' is not a count (allowed 0, 1, 2, ...)");
    expect(0, HEAD, "bad.csv:3: no column header (expected t,NAME,NAME_var,...)");
    expect(0, HEAD "time,T,T_var\n", "bad.csv:4: column 1 is 'time', expected t");
    expect(0, HEAD "t,Temp,Temp_var\n", "bad.csv:4: column 2: 'Temp' is not an observable "
           "(allowed T T_raw ux uy uz Pxx Pyy Pzz Pxy Pxz Pyz qx qy qz a2 a3)");
    expect(0, HEAD "t,T,T_ci\n", "bad.csv:4: column 2: T must be followed by T_var");
    expect(0, HEAD "t,T\n", "bad.csv:4: column 2: T must be followed by T_var");
    expect(0, HEAD "t,T,T_var,T,T_var\n", "bad.csv:4: column 4: T appears twice");
    expect(0, HEAD COLS, "bad.csv:4: the file ends after 0 rows, the scene has 3 output times");
    expect(0, HEAD COLS "0,1,0.1\n4,1,0.1\n",
           "bad.csv:6: the file ends after 2 rows, the scene has 3 output times");
    expect(0, HEAD COLS "0,1,0.1\n# x\n", "bad.csv:6: 1 rows before this line, the scene has 3 "
           "output times");
    expect(0, HEAD COLS "0,1,0.1\n4,1\n", "bad.csv:6: 2 fields, the header has 3");
    expect(0, HEAD COLS "0,1,0.1,7\n", "bad.csv:5: 4 fields, the header has 3");
    expect(0, HEAD COLS "0,1,0.1\n4.0001,1,0.1\n", "bad.csv:6: t = 4.0001, but the scene's "
           "output time 1 is 4 (allowed relative difference 1e-9)");
    expect(0, HEAD COLS "zero,1,0.1\n", "bad.csv:5: column 1 (t): 'zero' is not a number");
    expect(0, HEAD COLS "0,1x,0.1\n", "bad.csv:5: column 2 (T): '1x' is not a number");
    expect(0, HEAD COLS "0,nan,0.1\n", "bad.csv:5: column 2 (T): 'nan' is not finite");
    expect(0, HEAD COLS "0,1,inf\n", "bad.csv:5: column 3 (T_var): 'inf' is not finite");
    expect(0, HEAD COLS "0,1,-0.5\n", "bad.csv:5: column 3 (T_var): -0.5 is a negative variance");
    expect(0, HEAD COLS "0,1,0\n4,1,0\n8,1,0\n12,1,0\n", "bad.csv:8: more rows than the "
           "scene's 3 output times, or text after them: '12,1,0'");
    expect(0, HEAD COLS "0,1,0\n4,1,0\n8,1,0\n# done\n", "bad.csv:8: unexpected line after "
           "the rows: '# done' (allowed: the steady section, '# steady')");
    expect(0, HEAD COLS "0,1,0\n4,1,0\n8,1,0\n# steady\n",
           "bad.csv:8: a steady section, but the scene has no [steady]");
    expect(1, HEAD COLS "0,1,0\n4,1,0\n8,1,0\n# steady\nname,value\n",
           "bad.csv:9: expected the steady section's header name,mean,var");
    expect(1, HEAD COLS "0,1,0\n4,1,0\n8,1,0\n# steady\nname,mean,var\nf_4,1,0\n",
           "bad.csv:10: 'f_4' is not a steady quantity of this scene (allowed T, a2, a3, c1, "
           "c3, mu2, mu4, mu4_white, mu4_gaussian, mu4_nongaussian, f_0 to f_3)");
    expect(1, HEAD COLS "0,1,0\n4,1,0\n8,1,0\n# steady\nname,mean,var\na2,1,0\na2,1,0\n",
           "bad.csv:11: a2 appears twice");
    expect(1, HEAD COLS "0,1,0\n4,1,0\n8,1,0\n# steady\nname,mean,var\na2,1,-1\n",
           "bad.csv:10: column 3 (var): -1 is a negative variance");
    expect(1, HEAD COLS "0,1,0\n4,1,0\n8,1,0\n# steady\nname,mean,var\na2,1\n",
           "bad.csv:10: 2 fields, the steady section has 3 (name,mean,var)");
    const char nul[] = "# gdsmc-result 1\n\0";
    sim_scene s = scene_of(0);
    sim_ensemble_result r;
    vfy_result_info info;
    char msg[256];
    assert_int_equal(vfy_result_parse(nul, sizeof nul - 1, "bad.csv", &s, &r, &info, msg,
                                      sizeof msg), SIM_EINVAL);
    assert_string_equal(msg, "bad.csv: holds a NUL byte (a result file is text)");
    assert_int_equal(vfy_result_read("/nonexistent/r.csv", &s, &r, &info, msg, sizeof msg),
                     SIM_EIO);
    assert_string_equal(msg, "/nonexistent/r.csv: cannot read: No such file or directory");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_partial_result),
        cmocka_unit_test(test_split_command),
        cmocka_unit_test(test_solver_identity),
        cmocka_unit_test(trap_results),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
