#include "cases.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "checkpoint.h"
#include "driver.h"
#include "engine.h"
#include "scene_ini.h"
#include "scene_refs.h"
#include "solver.h"
#include "table.h"
#include "text.h"
#include "verdicts.h"

/* The cases, in suite order: case_grw.c (paper A), case_brs.c (paper B). */
extern const vfy_case_desc vfy_grw_ex3, vfy_grw_ex4, vfy_grw_ex5, vfy_grw_ex6, vfy_grw_ex7,
    vfy_grw_ex8;
/* case_brs.c */
extern const vfy_case_desc vfy_brs_ex1, vfy_brs_ex2, vfy_brs_ex3, vfy_brs_ex4, vfy_brs_ex5;
/* case_ms.c (paper C) */
extern const vfy_case_desc vfy_ms_white_noise, vfy_ms_gaussian, vfy_ms_non_gaussian,
    vfy_ms_table1, vfy_ms_tails;
/* case_msg.c (paper D) */
extern const vfy_case_desc vfy_msg_kappa, vfy_msg_sonine, vfy_msg_distribution;
extern const vfy_case_desc vfy_protocol;
/* case_as.c (paper E) */
extern const vfy_case_desc vfy_as_steady;
extern const vfy_case_desc vfy_as_transient;
extern const vfy_case_desc vfy_as_distribution;
extern const vfy_case_desc vfy_as_slab;
extern const vfy_case_desc vfy_as_slab_vs_homogeneous;
/* case_vro.c (issue 4: variance-reduced observation) */
extern const vfy_case_desc vfy_vro_grw_ex3;
/* case_split.c (docs/theory.md §8.5) */
extern const vfy_case_desc vfy_split_ex5;
extern const vfy_case_desc vfy_split_gaussian;
/* case_cost.c (docs/theory.md §1.4: accuracy against CPU cost) */
extern const vfy_case_desc vfy_cost_grw_ex3, vfy_cost_brs_ex2;
extern const vfy_case_desc vfy_cost_split_ex5;
/* case_hard.c (the hard suite, issue #5 item 1) */
extern const vfy_case_desc vfy_hard_dissipation, vfy_hard_nongaussian, vfy_hard_tails,
    vfy_hard_tiny, vfy_hard_long_run, vfy_hard_stiff, vfy_hard_extreme;

static const vfy_case cases[] = {
    {"grw-ex3", "grw", "paper A Ex 3, Table 1: heated Maxwell gas, Emax = O(1/n)", 1,
     &vfy_grw_ex3},
    {"grw-ex4", "grw", "paper A Ex 4, Table 2: cooling Maxwell gas, Emax = O(1/n)", 1,
     &vfy_grw_ex4},
    {"grw-ex5", "grw", "paper A Ex 5: heated hard spheres vs Maxwellian and Sonine closures", 1,
     &vfy_grw_ex5},
    {"grw-ex6", "grw", "paper A Ex 6: the steady tail exponent of heated Maxwell molecules "
     "(b = 1)", 1, &vfy_grw_ex6},
    {"grw-ex7", "grw", "paper A Ex 7: the steady tail exponent of heated hard spheres "
     "(b = 3/2)", 1, &vfy_grw_ex7},
    {"grw-ex8", "grw", "paper A Ex 8: the steady tail exponent of heated VHS, lambda = 1/2 "
     "(b = 5/4)", 1, &vfy_grw_ex8},
    {"vro-grw-ex3", "grw", "paper A Ex 3 observed through the exact conditional expectation "
     "over the pending Brownian increments: the variance reduction", 1, &vfy_vro_grw_ex3},
    {"brs-ex1", "brs", "paper B Ex 1, Table 1: Maxwell kernels with a background, Err = O(1/n)",
     1, &vfy_brs_ex1},
    {"brs-ex2", "brs", "paper B Ex 2, Table 2: Maxwell kernels, drifting background", 1,
     &vfy_brs_ex2},
    {"brs-ex3", "brs", "paper B Ex 3: Maxwell kernels, light background (slow relaxation)", 0,
     &vfy_brs_ex3},
    {"brs-ex4", "brs", "paper B Ex 4: hard spheres, K = 1/8: kinetic T* vs LE and Grad closures",
     1, &vfy_brs_ex4},
    {"brs-ex5", "brs", "paper B Ex 5: hard spheres, K = 1: kinetic T* vs LE and Grad closures", 0,
     &vfy_brs_ex5},
    {"ms-a2-white-noise", "ms", "paper C Fig. 1: steady a2 vs alpha, white noise, vs (C.10)", 1,
     &vfy_ms_white_noise},
    {"ms-a2-gaussian", "ms", "paper C Figs. 4, 6: steady a2, a3 vs alpha, Gaussian (HCS)", 1,
     &vfy_ms_gaussian},
    {"ms-a2-non-gaussian", "ms", "paper C Fig. 8: steady a2 vs alpha, non-Gaussian, vs (C.76)",
     1, &vfy_ms_non_gaussian},
    {"ms-table1", "ms", "paper C Table 1: mu4 direct vs through the exact steady relations", 1,
     &vfy_ms_table1},
    {"ms-tails", "ms", "paper C Figs. 3, 7: high-energy tails G(c), fitted A vs theory", 0,
     &vfy_ms_tails},
    {"msg-kappa", "msg", "paper D Figs. 1, 3: kappa'/kappa0 vs alpha from the heat-flux force,"
     " first Sonine, eps* -> 0 at alpha = 1 vs the exact elastic value", 1, &vfy_msg_kappa},
    {"msg-sonine", "msg", "paper D Figs. 2, 4: Sonine coefficients b'_1..b'_3 from both"
     " estimators vs alpha", 1, &vfy_msg_sonine},
    {"msg-distribution", "msg", "paper D Figs. 5-7: phi(c_x^2), its truncations, beta_1/b'_1,"
     " the heat flux from c_x^2 <= 6", 1, &vfy_msg_distribution},
    {"as-steady", "as", "paper E Figs. 14-16: steady uniform shear flow, IHS and EHS at"
     " a tau0 = 4 and 0.1, beside BGK", 1, &vfy_as_steady},
    {"as-transient", "as", "paper E Figs. 5-13: the transient against s, IHS and EHS at"
     " a tau0 = 4 and 0.1, beside BGK; eta*(a*) collapsing at alpha = 0.5", 1,
     &vfy_as_transient},
    {"as-distribution", "as", "paper E Figs. 13, 17-18: steady R0..R3, the marginals g_x, g_y"
     " and F(C) at alpha = 0.9 and 0.5, IHS and EHS, beside BGK", 1, &vfy_as_distribution},
    {"as-slab", "as", "paper E Sec. IV A, Figs. 1-4: the Lees-Edwards slab from E's two initial"
     " states, IHS and EHS: s(t), profiles, steady stresses", 1, &vfy_as_slab},
    {"as-slab-vs-homogeneous", "as", "paper E Fig. 9: the slab from both initial states"
     " against the homogeneous run, IHS at alpha = 0.9, a tau0 = 4", 1,
     &vfy_as_slab_vs_homogeneous},
    {"split-ex5", "split", "docs/theory.md §8.5: splitting error of the time-step scheme vs the"
     " jump scheme, Euler and Strang", 1, &vfy_split_ex5},
    {"split-gaussian", "split", "docs/theory.md §8.5: the same with the Gaussian thermostat,"
     " which the jump scheme runs exactly: Euler and Strang converge to it", 1,
     &vfy_split_gaussian},
    {"cost-grw-ex3", "cost", "docs/theory.md §1.4: Err (systematic + statistical) against CPU"
     " time over n x N, paper A Ex 3", 1, &vfy_cost_grw_ex3},
    {"cost-brs-ex2", "cost", "docs/theory.md §1.4: Err (systematic + statistical) against CPU"
     " time over n x N, paper B Ex 2", 1, &vfy_cost_brs_ex2},
    {"cost-split-ex5", "cost", "docs/theory.md §1.4: Err (systematic + splitting +"
     " statistical) against CPU time over n, N and h, paper A Ex 5", 1, &vfy_cost_split_ex5},
    {"hard-dissipation", "hard", "very strong dissipation: white-noise heated hard spheres,"
     " alpha = 0.05, 0.1, steady a2, mu4 = 5 mu2, exact energy balance", 1,
     &vfy_hard_dissipation},
    {"hard-nongaussian", "hard", "paper C's non-Gaussian thermostat near v = 0, alpha = 0.05,"
     " 0.1: a2, Eq. (44), depletion at v = 0, momentum to round-off", 1,
     &vfy_hard_nongaussian},
    {"hard-tails", "hard", "paper A Ex 7: growing majorant (no violations), overpopulated"
     " tail, exact energy balance", 1, &vfy_hard_tails},
    {"hard-tiny", "hard", "n = 2, 3, 4: exact finite-n expectations (papers A and B), exact"
     " Gaussian bulk velocity, majorant violations", 1, &vfy_hard_tiny},
    {"hard-long-run", "hard", "1e9 events per system: momentum and energy to round-off, exact"
     " T(0) e^{-kt}, no NaN", 1, &vfy_hard_long_run},
    {"hard-stiff", "hard", "paper B closures with K = 100 and 1e-4 through CVODE: success or a"
     " clear failure, never garbage", 1, &vfy_hard_stiff},
    {"hard-extreme", "hard", "restitution 1e-3 and 1, rate 1e6, T0 = 1e-8 and 1e8 against"
     " exact expectations and the Sonine closure", 1, &vfy_hard_extreme},
    {"protocol", "protocol", "the solver protocol's mechanics in seconds: the time grid and"
     " columns, the variance columns, the steady section", 0, &vfy_protocol},
};

size_t vfy_case_count(void) { return sizeof cases / sizeof *cases; }

const vfy_case *vfy_case_at(size_t i) { return i < vfy_case_count() ? &cases[i] : NULL; }

const vfy_case *vfy_case_find(const char *name)
{
    for (size_t i = 0; i < vfy_case_count(); i++)
        if (strcmp(cases[i].name, name) == 0)
            return &cases[i];
    return NULL;
}

/* The next name of a comma-separated list at *at into name (len bytes),
 * *at moved past it and its comma (NULL after the last); its length. */
static size_t next_name(const char **at, char *name, size_t len)
{
    const size_t n = strcspn(*at, ",");
    snprintf(name, len, "%.*s", (int)n, *at);
    *at = (*at)[n] == ',' ? *at + n + 1 : NULL;
    return n;
}

/* Is `name` one of the comma-separated names of `list`? */
static int in_list(const char *list, const char *name)
{
    char item[128];
    for (const char *at = list; at != NULL;)
        if (next_name(&at, item, sizeof item) < sizeof item && strcmp(item, name) == 0)
            return 1;
    return 0;
}

int vfy_case_list_check(const char *list, char *unknown, size_t len)
{
    char item[128];
    for (const char *at = list; at != NULL;)
        if (next_name(&at, item, sizeof item) >= sizeof item || vfy_case_find(item) == NULL) {
            snprintf(unknown, len, "%s", item);
            return 0;
        }
    return 1;
}

int vfy_suite_exists(const char *name)
{
    if (strcmp(name, "quick") == 0 || strcmp(name, "paper") == 0)
        return 1;
    for (size_t i = 0; i < vfy_case_count(); i++)
        if (strcmp(cases[i].suite, name) == 0)
            return 1;
    return 0;
}

const char *vfy_paper_suites(char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < vfy_case_count(); i++) {
        int seen = 0;
        for (size_t j = 0; j < i && !seen; j++)
            seen = strcmp(cases[j].suite, cases[i].suite) == 0;
        if (!seen && used < len)
            used += (size_t)snprintf(buf + used, len - used, "%s%s", used ? ", " : "",
                                     cases[i].suite);
    }
    return buf;
}

/* "paper" is every paper's case (not the protocol's conformance case). */
static int in_suite(const vfy_case *c, const char *suite)
{
    return (strcmp(suite, "paper") == 0 && strcmp(c->suite, "protocol") != 0)
           || (strcmp(suite, "quick") == 0 && c->quick) || strcmp(suite, c->suite) == 0;
}

int vfy_case_selected(const vfy_case *c, const char *suite, const char *case_name)
{
    return case_name ? in_list(case_name, c->name) : in_suite(c, suite ? suite : "paper");
}

sim_status vfy_run(const char *suite, const char *case_name, const vfy_options *o,
                   vfy_report *r, char *msg, size_t msglen)
{
    if (suite == NULL)
        suite = "paper";
    if (vfy_ensure_dir(o->out_dir) != 0) {
        snprintf(msg, msglen, "%s: cannot create the report directory: %s", o->out_dir,
                 strerror(errno));
        return SIM_EIO;
    }
    for (size_t i = 0; i < vfy_case_count(); i++) {
        const vfy_case *c = &cases[i];
        if (!vfy_case_selected(c, suite, case_name))
            continue;
        if (o->progress && o->dry_run == NULL)
            fprintf(o->progress, "== %s (%s sizes): %s\n", c->name,
                    o->size == VFY_QUICK ? "quick" : "paper", c->summary);
        if (r != NULL)
            r->group = c->name;
        sim_status status = vfy_run_described(c, o, r, msg, msglen);
        if (r != NULL)
            r->group = NULL;
        if (status != SIM_OK)
            return status;
    }
    if (o->dry_run != NULL)   /* no reports: nothing was judged */
        return SIM_OK;
    return vfy_write_index(o, o->size == VFY_QUICK ? "quick sizes" : "paper sizes", msg,
                           msglen);
}

/* The solver's scene failed where the user's (the same --set) did not, so a
 * --solver-set override is at fault; the scene parser names every override
 * "--set S.K=V": say which option it came from. */
static void relabel_solver_override(const vfy_options *o, char *msg, size_t msglen)
{
    for (size_t i = 0; i < o->nsolver_overrides; i++) {
        char was[1100];
        snprintf(was, sizeof was, "--set %s:", o->solver_overrides[i]);
        const char *at = strstr(msg, was);
        if (at != NULL) {
            char relabelled[2048];
            snprintf(relabelled, sizeof relabelled, "%.*s--solver-set %s", (int)(at - msg), msg,
                     at + strlen("--set "));
            snprintf(msg, msglen, "%s", relabelled);
            return;
        }
    }
}

/* --perturb: the solver's scene loaded again with each "KEY=FACTOR" as the
 * setting KEY = FACTOR x scene's value (set or defaulted, after the sweep
 * and --set), after its other settings. */
static sim_status perturb_solver(const char *path, const vfy_options *o, const sim_scene *scene,
                                 const char *const *sets, size_t count, sim_scene *solver,
                                 char *msg, size_t msglen)
{
    enum { MAX = 8 };
    char storage[MAX][160];   /* a scene key (< 96, vfy_perturb_parse) and a %.17g */
    if (o->nperturbs > MAX) {
        snprintf(msg, msglen, "--perturb: at most %d keys", MAX);
        return SIM_EINVAL;
    }
    const char **all = malloc((count + MAX) * sizeof *all);
    if (all == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    memcpy(all, sets, count * sizeof *sets);
    for (size_t i = 0; i < o->nperturbs; i++) {
        char key[128];
        double factor, value;
        sim_status status = vfy_perturb_parse(o->perturbs[i], key, sizeof key, &factor, msg,
                                              msglen);
        if (status == SIM_OK)
            status = vfy_scene_real(scene, key, &value, msg, msglen);
        if (status != SIM_OK) {
            char why[1024];
            snprintf(why, sizeof why, "%s", msg);
            snprintf(msg, msglen, "--perturb %s: %s", o->perturbs[i], why);
            free(all);
            return status;
        }
        snprintf(storage[i], sizeof storage[i], "%s=%.17g", key, factor * value);
        all[count + i] = storage[i];
    }
    sim_status status = vfy_scene_load(path, all, count + o->nperturbs, solver, msg, msglen);
    free(all);
    if (status != SIM_OK) {
        char why[1024];
        snprintf(why, sizeof why, "%s", msg);
        snprintf(msg, msglen, "--perturb: a perturbed value is refused: %s", why);
    }
    return status;
}

sim_status vfy_perturb_parse(const char *text, char *key, size_t keylen, double *factor,
                             char *msg, size_t msglen)
{
    const char *eq = strchr(text, '=');
    char *end;
    if (eq == NULL || eq == text || (size_t)(eq - text) >= keylen) {
        snprintf(msg, msglen, "'%s' is not SECTION.KEY=FACTOR", text);
        return SIM_EINVAL;
    }
    snprintf(key, keylen, "%.*s", (int)(eq - text), text);
    errno = 0;
    *factor = strtod(eq + 1, &end);
    if (end == eq + 1 || *end != '\0' || errno == ERANGE || !isfinite(*factor)
        || !(*factor > 0.0)) {
        snprintf(msg, msglen, "%s: factor '%s' is not a positive number", key, eq + 1);
        return SIM_EINVAL;
    }
    return vfy_scene_real(NULL, key, NULL, msg, msglen);
}

sim_status vfy_load_scene_stem(const char *stem, const vfy_options *o, sim_scene *scene,
                               sim_scene *solver, char *msg, size_t msglen)
{
    return vfy_load_scene_sets(stem, o, NULL, 0, scene, solver, msg, msglen);
}

sim_status vfy_load_scene_sets(const char *stem, const vfy_options *o, const char *const *pre,
                               size_t npre, sim_scene *scene, sim_scene *solver, char *msg,
                               size_t msglen)
{
    /* as many settings as the row, --set and --solver-set give */
    const char **sets = malloc((npre + o->noverrides + o->nsolver_overrides + 1) * sizeof *sets);
    char *path = vfy_aprintf("%s/%s.ini", o->scene_dir, stem);
    if (sets == NULL || path == NULL) {
        free(sets);
        free(path);
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    size_t count = 0;
    for (size_t i = 0; i < npre; i++)
        sets[count++] = pre[i];
    for (size_t i = 0; i < o->noverrides; i++)
        sets[count++] = o->overrides[i];
    size_t nscene = count;
    for (size_t i = 0; i < o->nsolver_overrides; i++)
        sets[count++] = o->solver_overrides[i];
    sim_status status = vfy_scene_load(path, sets, nscene, scene, msg, msglen);
    if (status == SIM_OK) {
        status = vfy_scene_load(path, sets, count, solver, msg, msglen);
        if (status != SIM_OK)
            relabel_solver_override(o, msg, msglen);
    }
    if (status == SIM_OK && o->nperturbs > 0)
        status = perturb_solver(path, o, scene, sets, count, solver, msg, msglen);
    if (status == SIM_OK && o->seed_run > 0)
        scene->seed = solver->seed = vfy_derived_seed(scene->seed, o->seed_run);
    free(sets);
    free(path);
    return status;
}

uint64_t vfy_derived_seed(uint64_t seed, uint64_t k)
{
    if (k == 0)
        return seed;
    uint64_t z = seed + k * 0x9E3779B97F4A7C15ull;   /* splitmix64's step and finaliser */
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (z ^ (z >> 31)) >> 16;   /* 48 bits: a seed a user can type */
}

sim_status vfy_require_references(const sim_scene *scene, const char *const *names,
                                  size_t count, const char *why, char *msg, size_t msglen)
{
    vfy_refs refs;
    sim_error err;
    sim_status status = vfy_scene_references(scene, &refs, &err);
    if (status != SIM_OK) {
        vfy_scene_format_error(scene, &err, msg, msglen);
        return status;
    }
    size_t k = 0;
    while (k < count && vfy_refs_has(&refs, names[k]))
        k++;
    vfy_refs_free(&refs);
    if (k < count) {
        int len = snprintf(msg, msglen, "%s: the scene has no", scene->file);
        for (size_t i = 0; i < count && len > 0 && (size_t)len < msglen; i++)
            len += snprintf(msg + len, msglen - (size_t)len, " %s", names[i]);
        if (len > 0 && (size_t)len < msglen)
            snprintf(msg + len, msglen - (size_t)len, " references (%s)", why);
        return SIM_EINVAL;
    }
    return SIM_OK;
}

typedef struct progress_state {
    FILE *out;
    const char *label;
    double start, last;
} progress_state;

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* A progress line at most every 5 s, and none for runs that finish sooner. */
static void print_progress(size_t done, size_t total, void *ctx)
{
    progress_state *p = ctx;
    double t = wall_now();
    if (t - p->last < 5.0 || done == total)
        return;
    p->last = t;
    double eta = (t - p->start) * (double)(total - done) / (double)done;
    fprintf(p->out, "   %s: %zu/%zu ensembles, %.0f s elapsed, about %.0f s to go\n", p->label,
            done, total, t - p->start, eta);
    fflush(p->out);
}

void vfy_finished_free(vfy_finished *f)
{
    free(f->keys);
    *f = (vfy_finished){0};
}

static int finished_has(const vfy_finished *f, uint64_t key)
{
    for (size_t k = 0; f != NULL && k < f->count; k++)
        if (f->keys[k] == key)
            return 1;
    return 0;
}

/* Remember key; without memory it is forgotten, which only costs a rerun. */
static void finished_add(vfy_finished *f, uint64_t key)
{
    if (f == NULL || finished_has(f, key))
        return;
    if (f->count == f->cap) {
        const size_t cap = f->cap ? 2 * f->cap : 64;
        uint64_t *keys = realloc(f->keys, cap * sizeof *keys);
        if (keys == NULL)
            return;
        f->keys = keys;
        f->cap = cap;
    }
    f->keys[f->count++] = key;
}

/* A finished simulation: its checkpoint, and the tests' countdown. */
static sim_status finish_simulation(const sim_scene *scene, const vfy_options *o,
                                    const char *label, const sim_ensemble_result *res,
                                    char *msg, size_t msglen)
{
    sim_status status;
    if (o->checkpoint_dir
        && (status = vfy_checkpoint_save(o->checkpoint_dir, label, scene, res, msg, msglen))
               != SIM_OK)
        return status;
    if (o->checkpoint_dir)
        finished_add(o->finished, vfy_checkpoint_key(scene));
    if (o->stop_countdown && *o->stop_countdown > 0 && --*o->stop_countdown == 0)
        sim_ensemble_request_stop();
    return SIM_OK;
}

/* The solvers behind vfy_simulate (issue 14), one signature: the built-in
 * engine, and an external command speaking the solver protocol (solver.h).
 * label names the run in progress lines and messages; checkpoint_label (in
 * cap bytes) receives what the checkpoint calls it. */
typedef sim_status (*simulate_fn)(const sim_scene *scene, const vfy_options *o,
                                  const char *label, sim_ensemble_result *res,
                                  char *checkpoint_label, size_t cap, char *msg, size_t msglen);

static sim_status simulate_engine(const sim_scene *scene, const vfy_options *o,
                                  const char *label, sim_ensemble_result *res,
                                  char *checkpoint_label, size_t cap, char *msg, size_t msglen)
{
    sim_engine *engine = NULL;
    sim_error err = {{0}, {0}};
    snprintf(checkpoint_label, cap, "%s", label);
    sim_status status = sim_engine_create(scene, &engine, &err);
    if (status == SIM_OK) {
        progress_state p = {o->progress, label, wall_now(), wall_now()};
        status = sim_ensemble_run(engine, o->progress ? print_progress : NULL, &p, res, &err);
    }
    sim_engine_free(engine);
    if (status == SIM_ECANCELED)
        snprintf(msg, msglen, "%s: %s", label, err.msg);
    else if (status != SIM_OK)
        vfy_scene_format_error(scene, &err, msg, msglen);
    return status;
}

static sim_status simulate_external(const sim_scene *scene, const vfy_options *o,
                                    const char *label, sim_ensemble_result *res,
                                    char *checkpoint_label, size_t cap, char *msg,
                                    size_t msglen)
{
    vfy_result_info info;
    if (o->progress)
        fprintf(o->progress, "   %s: running the solver\n", label);
    sim_status status = vfy_solver_run(o->solver, scene, label, res, &info, msg, msglen);
    if (status == SIM_EUNSUPPORTED) {   /* refused: a result that reports nothing */
        if (o->progress)
            fprintf(o->progress, "   %s: the solver refused: %s\n", label, msg);
        if (vfy_result_blank(scene, res) != SIM_OK) {
            snprintf(msg, msglen, "out of memory");
            return SIM_ENOMEM;
        }
    }
    if (status != SIM_OK)
        return status;
    res->missing = (info.has_events ? 0u : SIM_MISSING_EVENTS)
                   | (info.has_violations ? 0u : SIM_MISSING_VIOLATIONS)
                   | SIM_MISSING_COLLISIONS;   /* the protocol does not carry them */
    snprintf(checkpoint_label, cap, "%s (solver: %s)", label,   /* which solver made it */
             info.solver[0] ? info.solver : "no solver line");
    snprintf(o->solver->line, sizeof o->solver->line, "%s%s%s", info.solver,
             info.substituted[0] ? "; substituted " : "", info.substituted);
    o->solver->violations_allowed = info.violations_allowed;
    return SIM_OK;
}

sim_status vfy_simulate(const sim_scene *scene, const vfy_options *o, const char *label,
                        sim_ensemble_result *res, char *msg, size_t msglen)
{
    const int repeat = finished_has(o->finished, vfy_checkpoint_key(scene));
    if (o->checkpoint_dir && (o->resume || repeat)
        && vfy_checkpoint_load(o->checkpoint_dir, scene, res)) {
        if (o->progress)
            fprintf(o->progress, "   %s: taken from its checkpoint (%s)\n", label,
                    repeat ? "the same simulation ran earlier in this run" : "--resume");
        if (o->solver != NULL)   /* a checkpoint keeps no declared bound: none, strictly */
            o->solver->violations_allowed = 0.0;
        return SIM_OK;
    }
    memset(res, 0, sizeof *res);
    const simulate_fn simulate = vfy_external(o) ? simulate_external : simulate_engine;
    char named[512];
    sim_status status = simulate(scene, o, label, res, named, sizeof named, msg, msglen);
    return status == SIM_OK ? finish_simulation(scene, o, named, res, msg, msglen) : status;
}

int vfy_external(const vfy_options *o)
{
    return o->solver != NULL;
}

double vfy_scene_step(const sim_scene *s)
{
    double h;
    size_t steps;
    return sim_scene_step(s, &h, &steps, NULL) == SIM_OK ? h : 0.0;
}

const char *vfy_report_path(const vfy_options *o, const char *name, const char *suffix,
                            char *buf, size_t len)
{
    snprintf(buf, len, "%s/%s%s", o->out_dir, name, suffix);
    return buf;
}
