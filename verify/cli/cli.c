#include "cli.h"

#include <errno.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <signal.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cases.h"
#include "engine.h"
#include "bench.h"
#include "ensemble.h"
#include "scene_ini.h"
#include "references.h"
#include "suites.h"
#include "result.h"
#include "steady.h"
#include "scene_refs.h"
#include "checkpoint.h"
#include "solver.h"
#include "gate.h"
#include "sonine.h"
#include "table.h"

/* 130 = 128 + SIGINT, the shell's code for a run stopped by Ctrl-C. */
enum { EXIT_OK = 0, EXIT_CHECK_FAILED = 1, EXIT_BAD_INPUT = 2, EXIT_STOPPED = 130 };
#define MAX_SETS 64

static const char usage_main[] =
    "usage: gdsmc COMMAND [OPTIONS]\n"
    "\n"
    "Verification suite for DSMC solvers of the spatially homogeneous granular\n"
    "Boltzmann equation (see README.md and docs/theory.md).\n"
    "\n"
    "commands:\n"
    "  run SCENE        simulate a scene; CSV of ensemble means and confidence half-widths\n"
    "  reference SCENE  the deterministic references that apply to a scene, as CSV\n"
    "  verify           run verification cases and write tables and figures to reports/\n"
    "  sonine           Sonine-approximation values of papers C and D (a2, mu2, mu4, tails;\n"
    "                   kappa', kappa, mu, the exact elastic conductivity), CSV\n"
    "  bench            throughput of the engine against a bare floor loop, one core\n"
    "  check-result SCENE RESULT  validate a solver's result file against its scene\n"
    "\n"
    "  gdsmc COMMAND --help   options of a command\n"
    "  gdsmc --version\n"
    "\n"
    "exit status: 0 success, 1 a verification check failed, 2 bad input or error.\n";

static const char usage_run[] =
    "usage: gdsmc run SCENE [--set SECTION.KEY=VALUE]... [--out FILE.csv] [--result FILE]\n"
    "                 [--steady FILE.csv]\n"
    "\n"
    "Simulate the scene's N ensembles of n particles and write one CSV row per\n"
    "output time: t, then for each observable its ensemble mean NAME and its\n"
    "confidence half-width NAME_ci = 3.2 sqrt(Var/N) (p = 0.999). Observables:\n"
    "T (centred temperature), T_raw ((m/3n) sum |v|^2, paper A's tables), ux uy uz,\n"
    "Pxx Pyy Pzz Pxy Pxz Pyz, qx qy qz, a2, a3. Lines starting with '#' carry the\n"
    "version, scene, seed and run counters.\n"
    "\n"
    "  --set S.K=V   override a scene key (same checks as the file), repeatable\n"
    "  --out FILE    write the CSV to FILE (default: standard output, unless --result\n"
    "                or --steady)\n"
    "  --result FILE write the solver protocol's result file (docs/solver-protocol.md):\n"
    "                every observable's mean and sample variance, 17 digits\n"
    "  --steady FILE write the scene's steady averages ([steady]: time averages over\n"
    "                t >= steady.from, per ensemble) as name,mean,ci rows: T, a2, a3, c1,\n"
    "                c3, mu2, mu4, mu4_*, the speed shells f_K; with [heat-flux] (paper D)\n"
    "                qx, kappa_prime (kappa'/kappa0), b1 b2 b3, b1_x b2_x b3_x, b1_x_outer,\n"
    "                g1_K (odd c_x marginal / eps*), beta1_K (docs/cases.md)\n"
    "  --quiet       no progress or summary on standard error\n"
    "\n"
    "Threads: OMP_NUM_THREADS; the numbers do not depend on it.\n";

static const char usage_reference[] =
    "usage: gdsmc reference SCENE [--set SECTION.KEY=VALUE]... [--out FILE.csv]\n"
    "       gdsmc reference --list\n"
    "\n"
    "Write the references that apply to the scene on its output times, one column\n"
    "per reference named QUANTITY_MODEL: for heated Maxwell molecules T_exact\n"
    "(paper A Eq. 13) and the exact expectations of the n-particle estimators\n"
    "T_finite_n and T_raw_finite_n; for heated hard spheres T_maxwell_closure and\n"
    "T_sonine_closure (CVODE). With a [background] (paper B): for Maxwell kernels\n"
    "T_exact ux_exact uy_exact uz_exact (B.14-B.17) and T_finite_n (the exact\n"
    "expectation of the n-particle T); for hard spheres the local-equilibrium and\n"
    "Grad closures T_le ux_le uy_le uz_le, T_grad ux_grad uy_grad uz_grad (B.21,\n"
    "B.22, CVODE). Exit 2 when no reference applies.\n"
    "\n"
    "  --list   every reference the verification cases name, as CSV name,kind,what:\n"
    "           the series above and the values at a scene's restitution (paper C's\n"
    "           and D's Sonine estimates, the exact elastic conductivity)\n";

static const char usage_verify[] =
    "usage: gdsmc verify [--suite quick|paper|grw|brs|...] [--case NAME[,NAME...]]\n"
    "                    [--out DIR] [--scenes DIR] [--set S.K=V]... [--solver-set S.K=V]...\n"
    "                    [--solver 'COMMAND {scene} {out}'] [--solver-timeout S]\n"
    "                    [--junit FILE.xml] [--resume] [--list] [--perturb S.K=FACTOR]...\n"
    "                    [--seeds K | --must-fail | --power | --dry-run]\n"
    "\n"
    "Run solver against reference and write DIR/<case>.csv, DIR/<case>.md,\n"
    "DIR/<case>-curves.csv, a gnuplot figure DIR/<case>.png (when gnuplot is\n"
    "installed), the verdicts DIR/<case>-verdicts.csv and the index DIR/README.md.\n"
    "Prints one verdict per check and exits 1 if any check fails:\n"
    "  PASS     judged, and it held\n"
    "  FAIL     judged, and it did not: the solver is wrong\n"
    "  SKIP     not judged, with the reason\n"
    "  DIFFERS  a paper's printed number or sentence this project shows to be off\n"
    "           (docs/differences.md); the check named in its detail judges the\n"
    "           solver instead; never a failure\n"
    "\n"
    "  --suite S    quick (CI sizes, minutes), paper (every case at the paper's\n"
    "               sizes, the default), or a paper's own suite at the paper's\n"
    "               sizes: grw (paper A), brs (paper B), ..., hard (cases chosen\n"
    "               to break a careless solver) (--list shows all); protocol: a\n"
    "               solver adapter's mechanics in seconds (reports/protocol)\n"
    "  --case NAME[,NAME...]  only these cases, in suite order (at the suite's\n"
    "               sizes); --list shows them\n"
    "  --out DIR    where reports go (default: reports for the quick suite,\n"
    "               reports/paper for the papers' sizes)\n"
    "  --scenes DIR where the case scenes are (default: the source tree's\n"
    "               verify/cases/scenes)\n"
    "  --set S.K=V  override a key of every case's scene, for the simulation and\n"
    "               the references alike (e.g. --set scene.seed=7)\n"
    "  --solver-set S.K=V  override a key for the simulation only: a deliberately\n"
    "               wrong solver, which the checks must catch (e.g.\n"
    "               --solver-set collisions.restitution=0.45)\n"
    "  --solver 'COMMAND ARGS'  verify another program instead of the built-in\n"
    "               engine: for every simulation gdsmc writes the scene as INI,\n"
    "               runs COMMAND with {scene} and {out} replaced by the scene's and\n"
    "               the result's paths (no shell), and reads the result file\n"
    "               (docs/solver-protocol.md); a check on a quantity the solver\n"
    "               does not report is a SKIP; a scene it refuses (exit status 3,\n"
    "               the reason as the last line of its standard error) makes\n"
    "               that row's checks SKIPs, and the run goes on\n"
    "  --solver-timeout S  seconds one solver run may take (default 3600); then\n"
    "               it is killed and the case stops with an error\n"
    "  --junit FILE also write the verdicts as JUnit XML (a testsuite per case, a\n"
    "               testcase per check), as CI systems read it\n"
    "  --resume     take the simulations an earlier run with the same options and\n"
    "               build finished from DIR/.checkpoint: the tables come out\n"
    "               byte-identical to an uninterrupted run's\n"
    "  --list       list the cases and suites\n"
    "  --perturb S.K=FACTOR  multiply the simulated scene's value of number key\n"
    "               S.K by FACTOR: a relative error, as a bug makes one\n"
    "\n"
    "  --seeds K    K runs with seeds derived from each scene's: DIR/seeds.md\n"
    "               counts each check's false alarms (docs/verdicts.md)\n"
    "  --must-fail  each case under each error it declares it must catch:\n"
    "               CAUGHT or MISSED, exit 1 when one is missed\n"
    "  --power      the smallest error each case detects: DIR/power.md\n"
    "  --dry-run    simulate nothing: write each row's scene as the solver would\n"
    "               get it to DIR/CASE/row-NN.ini (DIR: --out, else\n"
    "               reports/dry-run) and list what each check reads\n"
    "\n"
    "Every finished simulation is saved at once in DIR/.checkpoint, and one a\n"
    "later row needs again is taken from there. SIGINT or SIGTERM stops the run\n"
    "after the ensemble in progress, with exit status 130 (docs/running.md).\n";

static const char usage_bench[] =
    "usage: gdsmc bench [--out FILE.csv] [--md FILE.md] [--max-n N] [--seconds S]\n"
    "\n"
    "Measure, on one core (CPU seconds of the thread), events per second of:\n"
    "  floor     the engine's hard-sphere kernel without its bookkeeping: the same\n"
    "            random indices, two-stage acceptance test, unit vector and\n"
    "            collision arithmetic, no candidate times, rates or counters\n"
    "  hs-relax  the engine on elastic hard spheres in one cell relaxing from two\n"
    "            counter-streaming Maxwellians, n = 1e3, 1e4, ... up to --max-n\n"
    "            (accepted collisions per second; the best of 3 runs of engine and\n"
    "            floor each, at least 2 collisions per particle in each run)\n"
    "  grw-ex3, brs-ex2  paper A Ex 3 and paper B Ex 2 at n = 1024 as their cases\n"
    "            run them (81 and 513 output times), beside grw-ex3-bare and\n"
    "            brs-ex2-bare (no heating, no output time between start and end)\n"
    "            and floor-maxwell (the Maxwell kernel alone); floor-maxwell-heated\n"
    "            adds the draws paper A's heating needs at the least (a waiting\n"
    "            time and 6 normal variates per collision)\n"
    "  brs-ex4   paper B Ex 4, Algorithm 2, at n = 1024 (candidate events)\n"
    "  ms-timestep-white, ms-timestep-gaussian  the time-step scheme on paper C's\n"
    "            gas, one system of n = 2e5, with white noise and with the keep-T\n"
    "            Gaussian thermostat; hcs-jump  the exact jump scheme with the\n"
    "            keep-T thermostat; each beside the floor at n = 2e5\n"
    "  as-slab   paper E's Lees-Edwards slab (IHS, 50 layers, dt = 1e-3 tau0 sqrt(T0/T))\n"
    "            at n = 1e4 and, when --max-n allows, 1e6 (accepted collisions),\n"
    "            beside the floor at the same n\n"
    "  grw-ex3-N10000  paper A Ex 3 with 10 000 ensembles on 1 and on 2 threads\n"
    "            (events per wall second, and the speed-up; the best of 5 runs\n"
    "            on each, alternately; fewer ensembles when S < 1)\n"
    "Engine runs are timed from their initial state (drawn and observed before\n"
    "the clock starts, as the floor's) to t_end.  Print the table (Markdown) with\n"
    "floor_ratio = rate / floor rate at the same n (the paper scenes against the\n"
    "floor at n = 1000), the acceptance (accepted / candidates), bytes per\n"
    "particle of a workspace and the process's peak memory; the paper-scene rows\n"
    "break their ns per accepted collision into ns_events (the scene without\n"
    "heating, outside its output times), ns_flows (the rest: heating, running\n"
    "sums) and ns_observation (the output times).  Progress lines, with\n"
    "the load average, go to standard error.\n"
    "\n"
    "  --out FILE    also write the table as CSV\n"
    "  --md FILE     also write it as Markdown\n"
    "  --max-n N     largest n of hs-relax (default 10000000; at least 1000)\n"
    "  --seconds S   about S CPU seconds per row (default 2)\n";

static const char usage_sonine[] =
    "usage: gdsmc sonine --alpha A [--d D] [--out FILE.csv]\n"
    "\n"
    "Print every Sonine-approximation value of papers C and D (docs/theory.md §13, §14) at\n"
    "restitution coefficient A as CSV: a '#' line, the header 'name,value', then one\n"
    "row per value (15 significant digits). Paper C's equation numbers:\n"
    "  beta_1 beta_3             beta_n, (A.7)\n"
    "  mu2_0 mu2_1 mu4_0 mu4_1   first Sonine coefficients of mu2, mu4, (27)-(30)\n"
    "  a2_white_noise (10), a2_white_noise_ratio (32), a2_gaussian (5),\n"
    "  a2_gaussian_alt (40), a2_nongaussian (50), a2_nongaussian_fit (76, d = 3 only)\n"
    "  mu2_X, mu4_X              mu2, mu4 = mu^(0) + mu^(1) a2, (26), at a2_X for X =\n"
    "                            white_noise, gaussian, gaussian_alt, nongaussian;\n"
    "                            mu2/mu4_nongaussian_fit by (72), (73) at (76)\n"
    "Paper D (docs/theory.md §14), first Sonine with a2 of (C.40): zeta_star (2.14),\n"
    "nu_kappa_star (2.46), kappa_over_kappa0 (2.41), kappa_prime_over_kappa0 (2.42),\n"
    "mu_star (2.38); the same with the HCS weight, *_modified (D ref. [28]); and,\n"
    "d = 3 only, the linearised elastic Boltzmann equation solved by a Sonine\n"
    "expansion to convergence: kappa_elastic_exact (1.025218), b1_elastic_exact ...\n"
    "b3_elastic_exact (D Eq. 3.10)\n"
    "  A_white_noise             tail f ~ exp(-A c^1.5), (36), mu2 at a2 (10)\n"
    "  A_gaussian                tail f ~ exp(-A c), (42), mu2 at a2 (40)\n"
    "  A_white_noise_mu2_0, A_gaussian_mu2_0   the same with mu2^(0)\n"
    "  Aprime_nongaussian        loss-term-only amplitude of exp(-A' c^2), (52)\n"
    "'nan' marks a d = 3-only value at another d; tail amplitudes are 'inf' at alpha = 1.\n"
    "\n"
    "  --alpha A    restitution coefficient, 0 <= A <= 1 (required)\n"
    "  --d D        dimension, 2 <= D <= 100 (default 3; need not be an integer)\n"
    "  --out FILE   write the CSV to FILE (default: standard output)\n";

/* The command line of any command (the options it does not take stay NULL
 * or 0). */
typedef struct args {
    const char *scene, *out, *suite, *case_name, *scenes;
    const char *result;                      /* run: a solver-protocol result file */
    const char *steady;                      /* run: the steady averages */
    const char *solver, *solver_timeout;     /* verify: an external solver */
    const char *junit;                       /* verify: a JUnit XML report */
    const char *alpha, *d;                   /* sonine */
    const char *md, *max_n, *seconds;        /* bench */
    const char *sets[MAX_SETS], *solver_sets[MAX_SETS], *perturbs[MAX_SETS];
    size_t nsets, nsolver_sets, nperturbs;
    const char *seeds;                       /* verify: --seeds K */
    const char *checked;                     /* check-result: the RESULT file */
    int quiet, list, resume, power, must_fail, dry_run;
} args;

/* Every option of every command: the commands that take it (words) and
 * where it goes in args: a value, a flag, or one more --set or --solver-set. */
typedef enum option_kind { OPT_VALUE, OPT_FLAG, OPT_SET, OPT_SOLVER_SET, OPT_PERTURB } option_kind;
typedef struct option_spec {
    const char *name, *commands;
    option_kind kind;
    size_t offset;   /* of the value (const char *) or the flag (int) */
} option_spec;

static const option_spec options[] = {
    {"--out", "run reference verify sonine bench", OPT_VALUE, offsetof(args, out)},
    {"--set", "run reference verify check-result", OPT_SET, 0},
    {"--result", "run", OPT_VALUE, offsetof(args, result)},
    {"--steady", "run", OPT_VALUE, offsetof(args, steady)},
    {"--quiet", "run reference verify", OPT_FLAG, offsetof(args, quiet)},
    {"--list", "reference verify", OPT_FLAG, offsetof(args, list)},
    {"--suite", "verify", OPT_VALUE, offsetof(args, suite)},
    {"--case", "verify", OPT_VALUE, offsetof(args, case_name)},
    {"--scenes", "verify", OPT_VALUE, offsetof(args, scenes)},
    {"--solver-set", "verify", OPT_SOLVER_SET, 0},
    {"--resume", "verify", OPT_FLAG, offsetof(args, resume)},
    {"--solver", "verify", OPT_VALUE, offsetof(args, solver)},
    {"--junit", "verify", OPT_VALUE, offsetof(args, junit)},
    {"--solver-timeout", "verify", OPT_VALUE, offsetof(args, solver_timeout)},
    {"--perturb", "verify", OPT_PERTURB, 0},
    {"--seeds", "verify", OPT_VALUE, offsetof(args, seeds)},
    {"--power", "verify", OPT_FLAG, offsetof(args, power)},
    {"--must-fail", "verify", OPT_FLAG, offsetof(args, must_fail)},
    {"--dry-run", "verify", OPT_FLAG, offsetof(args, dry_run)},
    {"--alpha", "sonine", OPT_VALUE, offsetof(args, alpha)},
    {"--d", "sonine", OPT_VALUE, offsetof(args, d)},
    {"--md", "bench", OPT_VALUE, offsetof(args, md)},
    {"--max-n", "bench", OPT_VALUE, offsetof(args, max_n)},
    {"--seconds", "bench", OPT_VALUE, offsetof(args, seconds)},
};

/* Only async-signal-safe calls here (clock_gettime, _exit, a sig_atomic_t
 * flag).  A repeat within a second is the same request delivered twice:
 * timeout(1) signals the child and then its process group. */
static void on_stop_signal(int sig)
{
    static struct timespec first;   /* written only here, both signals blocked */
    struct timespec now;
    (void)sig;
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (!sim_ensemble_stop_requested()) {
        first = now;
        sim_ensemble_request_stop();
    } else if ((double)(now.tv_sec - first.tv_sec) + 1e-9 * (double)(now.tv_nsec - first.tv_nsec)
               >= 1.0) {
        _exit(EXIT_STOPPED);   /* a deliberate second signal: stop at once */
    }
}

/* SIGINT and SIGTERM ask the ensembles to stop (exit 130 with what is done
 * on disk); another signal a second or more later ends the process at once. */
static void catch_stop_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

static int bad_usage(const char *cmd, const char *fmt, const char *what)
{
    fprintf(stderr, "gdsmc %s: ", cmd);
    fprintf(stderr, fmt, what);
    fprintf(stderr, " (see gdsmc %s --help)\n", cmd);
    return EXIT_BAD_INPUT;
}

/* Whether the space-separated words of list include word. */
static int has_word(const char *list, const char *word)
{
    const size_t len = strlen(word);
    for (const char *w = strstr(list, word); w != NULL; w = strstr(w + 1, word))
        if ((w == list || w[-1] == ' ') && (w[len] == ' ' || w[len] == '\0'))
            return 1;
    return 0;
}

/* cmd's option named s, or NULL. */
static const option_spec *find_option(const char *cmd, const char *s)
{
    for (size_t k = 0; k < sizeof options / sizeof options[0]; k++)
        if (strcmp(options[k].name, s) == 0 && has_word(options[k].commands, cmd))
            return &options[k];
    return NULL;
}

/* Parse the options of a command (the table above); positional SCENE if
 * wants_scene, and RESULT after it if wants_scene is 2.  Returns -1 when
 * parsing succeeded, else the exit code (help: 0). */
static int parse_args(const char *cmd, const char *usage, int wants_scene, int argc, char **argv,
                      args *a)
{
    memset(a, 0, sizeof *a);
    for (int i = 0; i < argc; i++) {
        const char *s = argv[i];
        if (strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0) {
            fputs(usage, stdout);
            return EXIT_OK;
        }
        const option_spec *opt = find_option(cmd, s);
        if (opt == NULL && s[0] == '-' && s[1] != '\0')
            return bad_usage(cmd, "unknown option '%s'", s);
        if (opt == NULL && wants_scene && a->scene == NULL) {
            a->scene = s;
            continue;
        }
        if (opt == NULL && wants_scene > 1 && a->checked == NULL) {   /* check-result */
            a->checked = s;
            continue;
        }
        if (opt == NULL)
            return bad_usage(cmd, "unexpected argument '%s'", s);
        if (opt->kind == OPT_FLAG) {
            *(int *)((char *)a + opt->offset) = 1;
            continue;
        }
        if (i + 1 >= argc)
            return bad_usage(cmd, "option '%s' needs a value", s);
        const char *value = argv[++i];
        if (opt->kind == OPT_VALUE) {
            *(const char **)((char *)a + opt->offset) = value;
        } else {
            const char **list = opt->kind == OPT_SET          ? a->sets
                                : opt->kind == OPT_SOLVER_SET ? a->solver_sets
                                                              : a->perturbs;
            size_t *count = opt->kind == OPT_SET          ? &a->nsets
                            : opt->kind == OPT_SOLVER_SET ? &a->nsolver_sets
                                                          : &a->nperturbs;
            if (*count == MAX_SETS)
                return bad_usage(cmd, "more than 64 %s options", opt->name);
            list[(*count)++] = value;
        }
    }
    if (wants_scene && a->scene == NULL && !a->list)
        return bad_usage(cmd, "%s", "missing SCENE file");
    if (wants_scene > 1 && a->checked == NULL)
        return bad_usage(cmd, "%s", "missing RESULT file");
    return -1;
}

/* Before long work: can --out FILE be written?  Says why not (exit 2). */
static int probe_out(const char *cmd, const char *path)
{
    if (path == NULL || vfy_file_probe(path) == 0)
        return EXIT_OK;
    fprintf(stderr, "gdsmc %s: %s: cannot write: %s\n", cmd, path, strerror(errno));
    return EXIT_BAD_INPUT;
}

/* Open the output (FILE.tmp, renamed on success) or standard output. */
static FILE *open_out(const char *cmd, const char *path, char *tmp, size_t tmplen)
{
    if (path == NULL)
        return stdout;
    FILE *f = vfy_file_begin(path, tmp, tmplen);
    if (f == NULL)
        fprintf(stderr, "gdsmc %s: %s: cannot write: %s\n", cmd, path, strerror(errno));
    return f;
}

static int close_out(const char *cmd, FILE *f, const char *path, const char *tmp)
{
    if (path == NULL) {
        if (fflush(stdout) == 0 && !ferror(stdout))
            return EXIT_OK;
        fprintf(stderr, "gdsmc %s: standard output: cannot write: %s\n", cmd, strerror(errno));
        return EXIT_BAD_INPUT;
    }
    if (vfy_file_commit(f, tmp, path, 1) != 0) {
        fprintf(stderr, "gdsmc %s: %s: cannot write: %s\n", cmd, path, strerror(errno));
        return EXIT_BAD_INPUT;
    }
    return EXIT_OK;
}

static int load_scene(const char *cmd, const args *a, sim_scene *scene)
{
    char msg[1024];
    if (vfy_scene_load(a->scene, a->sets, a->nsets, scene, msg, sizeof msg) != SIM_OK) {
        fprintf(stderr, "gdsmc %s: %s\n", cmd, msg);
        return EXIT_BAD_INPUT;
    }
    return EXIT_OK;
}

/* The run's summary line on standard error (unless --quiet). */
static void print_summary(const args *a, const sim_ensemble_result *res)
{
    if (!a->quiet)
        fprintf(stderr, "gdsmc run: %zu ensembles of %zu particles, %llu candidate events "
                "(%llu collisions, %llu majorant violations), %llu normal variates, %.2f s CPU, "
                "%.2f s wall on %d threads\n", res->ensembles, res->n,
                (unsigned long long)res->counts.candidates,
                (unsigned long long)res->counts.collisions,
                (unsigned long long)res->counts.violations,
                (unsigned long long)res->counts.normals, res->cpu_seconds,
                res->wall_seconds, res->threads);
}

/* What `gdsmc run` writes, and its writers (each returns nonzero on a
 * write error, which close_out reports). */
typedef struct run_output {
    const sim_scene *scene;
    const sim_ensemble_result *res;
    const char *effects;
} run_output;

static void write_provenance(FILE *f, const run_output *o)
{
    fprintf(f, "# gdsmc %s run %s: seed %llu, n = %zu, N = %zu, effects: %s\n", GDSMC_VERSION,
            o->scene->file, (unsigned long long)o->scene->seed, o->res->n, o->res->ensembles,
            o->effects[0] ? o->effects : "none (free flight)");
}

static void write_result(FILE *f, const run_output *o)
{
    char solver[64];
    snprintf(solver, sizeof solver, "gdsmc %s (built-in engine)", GDSMC_VERSION);
    vfy_result_write(f, solver, o->scene, o->res);
}

/* --steady: the steady averages (steady.h) as name,mean,ci rows. */
static void write_steady(FILE *f, const run_output *o)
{
    write_provenance(f, o);
    fputs("name,mean,ci\n", f);
    for (size_t k = 0; k < o->res->nsteady; k++) {
        char name[32];
        fprintf(f, "%s,%.12g,%.6g\n", sim_steady_name(o->scene, k, name, sizeof name),
                o->res->steady_mean[k], o->res->steady_ci[k]);
    }
}

static void write_series(FILE *f, const run_output *o)
{
    const sim_ensemble_result *res = o->res;
    write_provenance(f, o);
    fprintf(f, "# candidate events %llu, collisions %llu, majorant violations %llu\n",
            (unsigned long long)res->counts.candidates,
            (unsigned long long)res->counts.collisions,
            (unsigned long long)res->counts.violations);
    fputs("t", f);
    char name[SIM_OBS_NAME_LEN];
    for (size_t k = 0; k < res->observables; k++) {
        sim_observable_name(o->scene, k, name);
        fprintf(f, ",%s,%s_ci", name, name);
    }
    fputc('\n', f);
    for (size_t m = 0; m < res->outputs; m++) {
        fprintf(f, "%.10g", res->t[m]);
        for (int k = 0; k < (int)res->observables; k++)
            fprintf(f, ",%.12g,%.6g", sim_result_mean(res, m, k), sim_result_ci(res, m, k));
        fputc('\n', f);
    }
}

/* Write path (NULL: standard output) with writer, atomically. */
static int write_output(const char *path, void (*writer)(FILE *, const run_output *),
                        const run_output *o)
{
    char tmp[1100];
    FILE *f = open_out("run", path, tmp, sizeof tmp);
    if (f == NULL)
        return EXIT_BAD_INPUT;
    writer(f, o);
    return close_out("run", f, path, tmp);
}

static int cmd_run(int argc, char **argv)
{
    args a;
    int rc = parse_args("run", usage_run, 1, argc, argv, &a);
    if (rc >= 0)
        return rc;
    sim_scene scene;
    if ((rc = load_scene("run", &a, &scene)) != EXIT_OK)
        return rc;

    /* Build the engine before any output exists, so a refused scene leaves nothing. */
    sim_engine *engine = NULL;
    sim_error err;
    char msg[1024];
    if (sim_engine_create(&scene, &engine, &err) != SIM_OK) {
        vfy_scene_format_error(&scene, &err, msg, sizeof msg);
        fprintf(stderr, "gdsmc run: %s\n", msg);
        return EXIT_BAD_INPUT;
    }
    char effects[64];
    snprintf(effects, sizeof effects, "%s", sim_engine_effects(engine));
    sim_engine_free(engine);
    if (a.steady != NULL && !scene.steady.present) {
        fprintf(stderr, "gdsmc run: --steady %s: %s has no [steady] section (steady averages "
                "need one: from, bins, c_max, pairs)\n", a.steady, scene.file);
        return EXIT_BAD_INPUT;
    }
    if ((rc = probe_out("run", a.out)) != EXIT_OK || (rc = probe_out("run", a.result)) != EXIT_OK
        || (rc = probe_out("run", a.steady)) != EXIT_OK)
        return rc;

    vfy_options o = {.progress = a.quiet ? NULL : stderr};
    sim_ensemble_result res;
    catch_stop_signals();
    sim_status status = vfy_simulate(&scene, &o, scene.file, &res, msg, sizeof msg);
    if (status != SIM_OK) {
        fprintf(stderr, "gdsmc run: %s%s\n", msg,
                status == SIM_ECANCELED ? "; nothing written" : "");
        sim_ensemble_result_free(&res);
        return status == SIM_ECANCELED ? EXIT_STOPPED : EXIT_BAD_INPUT;
    }

    const run_output out = {&scene, &res, effects};
    rc = EXIT_OK;
    if (a.result != NULL)
        rc = write_output(a.result, write_result, &out);
    if (rc == EXIT_OK && a.steady != NULL)
        rc = write_output(a.steady, write_steady, &out);
    if (rc == EXIT_OK && (a.out != NULL || (a.result == NULL && a.steady == NULL)))
        rc = write_output(a.out, write_series, &out);
    print_summary(&a, &res);
    sim_ensemble_result_free(&res);
    return rc;
}

static const char usage_check_result[] =
    "usage: gdsmc check-result SCENE RESULT [--set SECTION.KEY=VALUE]...\n"
    "\n"
    "Validate a solver's result file against the scene it was made for, as gdsmc\n"
    "verify reads it (docs/solver-protocol.md), without judging it: the version\n"
    "line, n and ensembles, the column header, one row per output time at the\n"
    "scene's times, finite numbers and variances, the steady section. Prints what\n"
    "the result reports and what it leaves out (their checks would be SKIPs).\n"
    "\n"
    "exit status: 0 a valid result, 2 not (the message names the file, line and\n"
    "column, and what to fix).\n";

/* gdsmc check-result SCENE RESULT: vfy_result_read, and a summary. */
static int cmd_check_result(int argc, char **argv)
{
    args a;
    int rc = parse_args("check-result", usage_check_result, 2, argc, argv, &a);
    if (rc >= 0)
        return rc;
    sim_scene scene;
    if ((rc = load_scene("check-result", &a, &scene)) != EXIT_OK)
        return rc;
    sim_ensemble_result res;
    vfy_result_info info;
    char msg[1024];
    if (vfy_result_read(a.checked, &scene, &res, &info, msg, sizeof msg) != SIM_OK) {
        fprintf(stderr, "gdsmc check-result: %s\n", msg);
        return EXIT_BAD_INPUT;
    }
    char missing[2048] = "";
    size_t nmissing = 0, used = 0;
    for (size_t k = 0; k < res.observables; k++)
        if (!info.reported[k] && used < sizeof missing) {
            char name[SIM_OBS_NAME_LEN];
            used += (size_t)snprintf(missing + used, sizeof missing - used, " %s",
                                     sim_observable_name(&scene, k, name));
            nmissing++;
        }
    printf("%s: a valid version %d result for %s: %zu output times, %zu ensembles of %zu "
           "particles, %zu of %zu observables, %zu of %zu steady quantities%s%s%s%s%s\n",
           a.checked, VFY_RESULT_VERSION, scene.file, res.outputs, res.ensembles, res.n,
           res.observables - nmissing, res.observables, info.steady_reported, res.nsteady,
           info.has_events ? ", events" : "", info.has_violations ? ", violations" : "",
           info.substituted[0] ? "; substituted " : "", info.substituted,
           info.solver[0] ? "" : " (no '# solver =' line)");
    if (nmissing > 0)
        printf("not reported (checks on them are SKIPs):%s\n", missing);
    sim_ensemble_result_free(&res);
    return EXIT_OK;
}

static int cmd_reference(int argc, char **argv)
{
    args a;
    int rc = parse_args("reference", usage_reference, 1, argc, argv, &a);
    if (rc >= 0)
        return rc;
    if (a.list) {
        printf("name,kind,what\n");
        for (size_t i = 0; i < vfy_reference_count(); i++) {
            const vfy_reference *ref = vfy_reference_at(i);
            char names[256];
            snprintf(names, sizeof names, "%s", ref->name);
            for (char *w = strtok(names, " "); w; w = strtok(NULL, " "))
                printf("%s,%s,\"%s\"\n", w, ref->kind == VFY_REF_SERIES ? "series" : "value",
                       ref->what);
        }
        return EXIT_OK;
    }
    sim_scene scene;
    if ((rc = load_scene("reference", &a, &scene)) != EXIT_OK)
        return rc;
    if ((rc = probe_out("reference", a.out)) != EXIT_OK)
        return rc;
    vfy_refs refs;
    sim_error err;
    char msg[1024];
    if (vfy_scene_references(&scene, &refs, &err) != SIM_OK) {
        vfy_scene_format_error(&scene, &err, msg, sizeof msg);
        fprintf(stderr, "gdsmc reference: %s\n", msg);
        return EXIT_BAD_INPUT;
    }
    char tmp[1100];
    FILE *f = open_out("reference", a.out, tmp, sizeof tmp);
    if (f == NULL) {
        vfy_refs_free(&refs);
        return EXIT_BAD_INPUT;
    }
    fprintf(f, "# gdsmc %s reference %s: seed %llu (unused: deterministic), n = %zu\n",
            GDSMC_VERSION, scene.file, (unsigned long long)scene.seed, scene.particles.n);
    fputs("t", f);
    for (size_t j = 0; j < refs.count; j++)
        fprintf(f, ",%s", refs.names[j]);
    fputc('\n', f);
    for (size_t m = 0; m < refs.outputs; m++) {
        fprintf(f, "%.10g", sim_scene_output_time(&scene, m));
        for (size_t j = 0; j < refs.count; j++)
            fprintf(f, ",%.14g", refs.cols[j][m]);
        fputc('\n', f);
    }
    vfy_refs_free(&refs);
    return close_out("reference", f, a.out, tmp);
}

/* Parse a --alpha or --d value: a finite number in [lo, hi]. */
static int parse_range(const char *opt, const char *text, double lo, double hi,
                       const char *allowed, double *value)
{
    char *end;
    errno = 0;
    double x = strtod(text, &end);
    if (end == text || *end != '\0' || errno == ERANGE || !isfinite(x)) {
        fprintf(stderr, "gdsmc sonine: %s: '%s' is not a number (see gdsmc sonine --help)\n",
                opt, text);
        return EXIT_BAD_INPUT;
    }
    if (!(x >= lo && x <= hi)) {
        fprintf(stderr, "gdsmc sonine: %s: '%s' is out of range (allowed %s)\n", opt, text,
                allowed);
        return EXIT_BAD_INPUT;
    }
    *value = x;
    return EXIT_OK;
}

static int cmd_sonine(int argc, char **argv)
{
    args a;
    int rc = parse_args("sonine", usage_sonine, 0, argc, argv, &a);
    if (rc >= 0)
        return rc;
    const char *alpha_text = a.alpha, *d_text = a.d, *out = a.out;
    if (alpha_text == NULL)
        return bad_usage("sonine", "%s", "missing --alpha");
    double alpha, d = 3.0;
    rc = parse_range("--alpha", alpha_text, 0.0, 1.0, "0 <= alpha <= 1", &alpha);
    if (rc == EXIT_OK && d_text != NULL)
        rc = parse_range("--d", d_text, REF_SONINE_D_MIN, REF_SONINE_D_MAX, "2 <= d <= 100", &d);
    if (rc != EXIT_OK)
        return rc;
    ref_sonine_value v[REF_SONINE_ALL_COUNT];
    size_t n = ref_sonine_all(alpha, d, v, REF_SONINE_ALL_COUNT);
    if (n != REF_SONINE_ALL_COUNT) {
        fprintf(stderr, "gdsmc sonine: no values at alpha = %s, d = %s\n", alpha_text,
                d_text ? d_text : "3");
        return EXIT_BAD_INPUT;
    }
    char tmp[1100];
    FILE *f = open_out("sonine", out, tmp, sizeof tmp);
    if (f == NULL)
        return EXIT_BAD_INPUT;
    fprintf(f, "# gdsmc %s sonine: alpha = %.15g, d = %.15g (papers C and D, Sonine approximation)\n",
            GDSMC_VERSION, alpha, d);
    fputs("name,value\n", f);
    for (size_t i = 0; i < n; i++)
        fprintf(f, "%s,%.15g\n", v[i].name, v[i].value);
    return close_out("sonine", f, out, tmp);
}

static int cmd_bench(int argc, char **argv)
{
    args a;
    int rc = parse_args("bench", usage_bench, 0, argc, argv, &a);
    if (rc >= 0)
        return rc;
    const char *out = a.out, *md = a.md, *max_n_text = a.max_n, *seconds_text = a.seconds;
    vfy_bench_options o = {.max_n = 10000000, .seconds = 2.0,
                           .scene_dir = GDSMC_SOURCE_DIR "/verify/cases/scenes", .progress = stderr};
    char *end;
    if (max_n_text) {
        double x = strtod(max_n_text, &end);
        if (end == max_n_text || *end || !(x >= 1000 && x <= 1e9))
            return bad_usage("bench", "--max-n '%s': allowed 1000 <= N <= 1e9", max_n_text);
        o.max_n = (size_t)x;
    }
    if (seconds_text) {
        o.seconds = strtod(seconds_text, &end);
        if (end == seconds_text || *end || !(o.seconds > 0 && o.seconds <= 3600))
            return bad_usage("bench", "--seconds '%s': allowed 0 < S <= 3600", seconds_text);
    }
    rc = probe_out("bench", out);
    if (rc == EXIT_OK)
        rc = probe_out("bench", md);
    if (rc != EXIT_OK)
        return rc;
    vfy_table table;
    char msg[512];
    if (vfy_bench_run(&o, &table, msg, sizeof msg) != SIM_OK) {
        vfy_table_free(&table);
        fprintf(stderr, "gdsmc bench: %s\n", msg);
        return EXIT_BAD_INPUT;
    }
    char comment[256];
    snprintf(comment, sizeof comment, "gdsmc %s bench: one core, CPU seconds of the thread, "
             "about %g s per row", GDSMC_VERSION, o.seconds);
    if (out && vfy_table_write_csv(&table, out, comment) != 0) {
        fprintf(stderr, "gdsmc bench: %s: cannot write: %s\n", out, strerror(errno));
        rc = EXIT_BAD_INPUT;
    }
    if (md && vfy_table_write_markdown(&table, md, "gdsmc bench", comment) != 0) {
        fprintf(stderr, "gdsmc bench: %s: cannot write: %s\n", md, strerror(errno));
        rc = EXIT_BAD_INPUT;
    }
    vfy_table_print_markdown(&table, stdout, "gdsmc bench", comment);
    vfy_table_free(&table);
    return rc;
}

/* --seeds, --must-fail and --power (gate.h): exit 0 when the measurement
 * ran (--must-fail: 1 when a declared error went uncaught), 2 on bad input,
 * 130 when stopped. */
static int verify_gate(const args *a, const vfy_options *o, size_t seeds)
{
    char msg[1024] = "";
    sim_status status;
    size_t clean = 0, flaky = 0, missed = 0;
    if (seeds > 0)
        status = vfy_seeds(a->suite, a->case_name, o, seeds, &clean, &flaky, msg, sizeof msg);
    else if (a->must_fail)
        status = vfy_must_fail(a->suite, a->case_name, o, stdout, &missed, msg, sizeof msg);
    else
        status = vfy_power(a->suite, a->case_name, o, msg, sizeof msg);
    if (status == SIM_ECANCELED) {
        fprintf(stderr, "gdsmc verify: %s\n", msg);
        return EXIT_STOPPED;
    }
    if (status != SIM_OK) {
        fprintf(stderr, "gdsmc verify: %s\n", msg);
        return EXIT_BAD_INPUT;
    }
    if (seeds > 0)
        printf("seeds: %zu of %zu runs passed whole; %zu checks failed in more than one run "
               "(%s/seeds.md)\n", clean, seeds, flaky, o->out_dir);
    else if (a->must_fail)
        printf("must-fail: %zu declared errors not caught\n", missed);
    else
        printf("power: %s/power.md\n", o->out_dir);
    return missed > 0 ? EXIT_CHECK_FAILED : EXIT_OK;
}

/* --list: the suites and every case with its suite and summary; exit 0. */
static int list_cases(void)
{
    char suites[128];
    printf("suites: quick (CI sizes), paper (every paper's case, paper sizes), and per "
           "paper (and protocol): %s\n"
           "cases:\n", vfy_paper_suites(suites, sizeof suites));
    int width = 0;
    for (size_t i = 0; i < vfy_case_count(); i++)
        width = (int)fmax(width, (double)strlen(vfy_case_at(i)->name));
    for (size_t i = 0; i < vfy_case_count(); i++)
        printf("  %-*s %-6s %s%s\n", width, vfy_case_at(i)->name, vfy_case_at(i)->suite,
               vfy_case_at(i)->summary, vfy_case_at(i)->quick ? " [quick]" : "");
    return EXIT_OK;
}

/* The verify options that need no scene: -1 when they make sense together
 * (*seeds from --seeds, 0 without it), else bad_usage's exit code. */
static int check_verify_args(const args *a, size_t *seeds)
{
    if (a->suite && !vfy_suite_exists(a->suite)) {
        char suites[128], why[256];
        snprintf(why, sizeof why, "unknown suite '%s' (allowed quick, paper, %s)", a->suite,
                 vfy_paper_suites(suites, sizeof suites));
        return bad_usage("verify", "%s", why);
    }
    char unknown[128];
    if (a->case_name && !vfy_case_list_check(a->case_name, unknown, sizeof unknown))
        return bad_usage("verify", "unknown case '%s' (gdsmc verify --list shows them)",
                         unknown);
    for (size_t i = 0; i < a->nperturbs; i++) {
        char key[128], why[1024];
        double factor;
        if (vfy_perturb_parse(a->perturbs[i], key, sizeof key, &factor, why, sizeof why)
            != SIM_OK) {
            char text[1200];
            snprintf(text, sizeof text, "--perturb %s", why);
            return bad_usage("verify", "%s", text);
        }
    }
    *seeds = 0;
    if (a->seeds != NULL) {
        char *end;
        double k = strtod(a->seeds, &end);
        if (end == a->seeds || *end || !(k >= 2 && k <= 1000) || k != floor(k))
            return bad_usage("verify", "--seeds '%s': allowed an integer 2 <= K <= 1000 (K "
                             "runs, each with seeds derived from the scenes')", a->seeds);
        *seeds = (size_t)k;
    }
    if ((*seeds > 0) + a->power + a->must_fail > 1)
        return bad_usage("verify", "%s", "--seeds, --power and --must-fail: one at a time");
    if (a->dry_run && (*seeds > 0 || a->power || a->must_fail || a->resume || a->junit))
        return bad_usage("verify", "%s", "--dry-run simulates nothing: not with --seeds, "
                         "--power, --must-fail, --resume or --junit");
    if ((*seeds > 0 || a->power || a->must_fail) && (a->nperturbs > 0 || a->solver != NULL))
        return bad_usage("verify", "%s", "--seeds, --power and --must-fail measure the "
                         "built-in engine: not with --perturb or --solver");
    return -1;
}

/* The run's options from the command line (the report directory by suite
 * unless --out; no solver, checkpoints or stop countdown yet). */
static vfy_options verify_options(const args *a)
{
    return (vfy_options){
        .size = a->suite && strcmp(a->suite, "quick") == 0 ? VFY_QUICK : VFY_PAPER,
        .out_dir = a->out                                              ? a->out
                   : a->suite && strcmp(a->suite, "quick") == 0    ? "reports"
                   : a->suite && strcmp(a->suite, "protocol") == 0 ? "reports/protocol"
                                                                   : "reports/paper",
        .scene_dir = a->scenes ? a->scenes : GDSMC_SOURCE_DIR "/verify/cases/scenes",
        .overrides = a->sets,
        .noverrides = a->nsets,
        .solver_overrides = a->solver_sets,
        .nsolver_overrides = a->nsolver_sets,
        .progress = a->quiet ? NULL : stderr,
        .resume = a->resume,
        .perturbs = a->perturbs,
        .nperturbs = a->nperturbs,
    };
}

/* --solver-timeout and --solver: -1 when they are good (with --solver, o
 * runs the solver, its work directory `work` and its checkpoints under
 * OUT/.checkpoint/solver-ID), else bad_usage's exit code. */
static int verify_solver(const args *a, vfy_options *o, vfy_solver *solver, char *work,
                         size_t worklen, char *checkpoints, size_t checkpointslen)
{
    if (a->solver_timeout != NULL) {
        char *end;
        solver->timeout = strtod(a->solver_timeout, &end);
        if (end == a->solver_timeout || *end
            || !(solver->timeout > 0 && solver->timeout <= 1e6))
            return bad_usage("verify", "--solver-timeout '%s': allowed 0 < S <= 1e6 seconds",
                             a->solver_timeout);
    }
    if (a->solver != NULL) {
        char why[128];
        if (!vfy_solver_command_ok(a->solver, why, sizeof why)) {
            char text[300];
            snprintf(text, sizeof text, "--solver '%s': %s", a->solver, why);
            return bad_usage("verify", "%s", text);
        }
        /* another solver's results are never resumed as this one's */
        snprintf(work, worklen, "%s/.solver", o->out_dir);
        snprintf(checkpoints, checkpointslen, "%s/.checkpoint/solver-%016llx", o->out_dir,
                 (unsigned long long)vfy_solver_identity(a->solver));
        o->solver = solver;
    }
    return -1;
}

/* --dry-run: the scenes and what the checks read, under OUT/dry-run (or
 * --out itself); exit 0, or 2 with the message. */
static int verify_dry_run(const args *a, vfy_options *o)
{
    char dry[1100];
    snprintf(dry, sizeof dry, "%s/dry-run", o->out_dir);
    o->out_dir = a->out ? a->out : dry;
    o->dry_run = stdout;
    char msg[1024] = "";
    const sim_status status = vfy_run(a->suite, a->case_name, o, NULL, msg, sizeof msg);
    vfy_finished_free(o->finished);
    if (status != SIM_OK) {
        fprintf(stderr, "gdsmc verify: %s\n", msg);
        return EXIT_BAD_INPUT;
    }
    return EXIT_OK;
}

/* The cases with their report (and --junit's, timed), then the closing
 * line: exit 0 when every check passed, 1 when one failed, 2 on bad input,
 * 130 when stopped (the finished simulations saved in checkpoints). */
static int verify_cases(const args *a, const vfy_options *o, const char *checkpoints)
{
    vfy_report report;
    vfy_report_init(&report, stdout);
    char msg[1024] = "";
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    sim_status status = vfy_run(a->suite, a->case_name, o, &report, msg, sizeof msg);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    vfy_finished_free(o->finished);
    if (status == SIM_OK && a->junit != NULL
        && vfy_report_write_junit(&report, a->junit,
                                  (double)(t1.tv_sec - t0.tv_sec)
                                      + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec)) != 0) {
        status = SIM_EIO;
        snprintf(msg, sizeof msg, "%s: cannot write: %s", a->junit, strerror(errno));
    }
    size_t counts[VFY_VERDICTS];
    memcpy(counts, report.counts, sizeof counts);
    size_t failed = report.counts[VFY_FAIL], refused = report.refused;
    vfy_report_free(&report);
    if (status == SIM_ECANCELED) {
        fprintf(stderr, "gdsmc verify: %s; the finished simulations are saved in %s: run the "
                "same command with --resume to finish\n", msg, checkpoints);
        return EXIT_STOPPED;
    }
    if (status != SIM_OK) {
        fprintf(stderr, "gdsmc verify: %s\n", msg);
        return EXIT_BAD_INPUT;
    }
    printf("verify: %zu passed, %zu failed, %zu skipped", counts[VFY_PASS], failed,
           counts[VFY_SKIP]);
    if (counts[VFY_DIFFERS] > 0)   /* after the closing line's "N skipped" CI readers parse */
        printf(", %zu differ from the papers", counts[VFY_DIFFERS]);
    if (refused > 0)
        printf(", %zu %s refused by the solver", refused, refused == 1 ? "row" : "rows");
    putchar('\n');
    return failed ? EXIT_CHECK_FAILED : EXIT_OK;
}

/* gdsmc verify: --list, or the options checked and then the gate (--seeds,
 * --power, --must-fail), --dry-run or the cases. */
static int verify_loaded(args a);

/* The case files are read first (suites.h): a broken one is bad input. */
static int cmd_verify(int argc, char **argv)
{
    args a;
    int rc = parse_args("verify", usage_verify, 0, argc, argv, &a);
    if (rc >= 0)
        return rc;
    char msg[1024];
    if (vfy_cases_load(vfy_case_dir(), msg, sizeof msg) != SIM_OK) {
        fprintf(stderr, "gdsmc verify: %s\n", msg);
        return EXIT_BAD_INPUT;
    }
    rc = verify_loaded(a);
    vfy_cases_unload();
    return rc;
}

static int verify_loaded(args a)
{
    int rc;
    if (a.list)
        return list_cases();
    size_t seeds = 0;
    if ((rc = check_verify_args(&a, &seeds)) >= 0)
        return rc;
    vfy_options o = verify_options(&a);
    char checkpoints[1100], work[1100];
    snprintf(checkpoints, sizeof checkpoints, "%s/.checkpoint", o.out_dir);
    vfy_solver solver = {.command = a.solver, .timeout = 3600.0, .work_dir = work};
    rc = verify_solver(&a, &o, &solver, work, sizeof work, checkpoints, sizeof checkpoints);
    if (rc >= 0)
        return rc;
    o.checkpoint_dir = checkpoints;
    vfy_finished finished = {0};   /* a simulation two rows need runs once */
    o.finished = &finished;
    /* For tests: behave as if SIGINT arrived after K finished simulations. */
    size_t countdown = 0;
    const char *stop_after = getenv("GDSMC_STOP_AFTER_RUNS");
    if (stop_after && (countdown = strtoul(stop_after, NULL, 10)) > 0)
        o.stop_countdown = &countdown;
    catch_stop_signals();
    if ((rc = probe_out("verify", a.junit)) != EXIT_OK)
        return rc;
    if (seeds > 0 || a.power || a.must_fail)
        return verify_gate(&a, &o, seeds);
    if (a.dry_run)
        return verify_dry_run(&a, &o);
    return verify_cases(&a, &o, checkpoints);
}

int gdsmc_main(int argc, char **argv)
{
    /* GSL reports errors through return codes here; its default handler aborts
     * (STYLE: library code never aborts). */
    gsl_set_error_handler_off();
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        fputs(usage_main, argc < 2 ? stderr : stdout);
        return argc < 2 ? EXIT_BAD_INPUT : EXIT_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("gdsmc %s\n", GDSMC_VERSION);
        return EXIT_OK;
    }
    if (strcmp(argv[1], "run") == 0)
        return cmd_run(argc - 2, argv + 2);
    if (strcmp(argv[1], "reference") == 0)
        return cmd_reference(argc - 2, argv + 2);
    if (strcmp(argv[1], "verify") == 0)
        return cmd_verify(argc - 2, argv + 2);
    if (strcmp(argv[1], "sonine") == 0)
        return cmd_sonine(argc - 2, argv + 2);
    if (strcmp(argv[1], "bench") == 0)
        return cmd_bench(argc - 2, argv + 2);
    if (strcmp(argv[1], "check-result") == 0)
        return cmd_check_result(argc - 2, argv + 2);
    fprintf(stderr, "gdsmc: unknown command '%s' (allowed run, reference, verify, sonine, "
            "bench, check-result; see gdsmc --help)\n", argv[1]);
    return EXIT_BAD_INPUT;
}
