#include "cases.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "checkpoint.h"
#include "engine.h"
#include "scene_ini.h"
#include "scene_refs.h"
#include "solver.h"
#include "table.h"
#include "text.h"

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
