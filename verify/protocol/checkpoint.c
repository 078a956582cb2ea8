#include "checkpoint.h"

#include <errno.h>
#include <inttypes.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "table.h"

#define CHECKPOINT_MAGIC "gdsmc-checkpoint 1"

uint64_t vfy_hash(uint64_t h, const void *data, size_t len)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < len; i++) {
        h ^= p[i];
        h *= UINT64_C(0x100000001b3);
    }
    return h;
}

/* The running executable's identity: a hash of its bytes (/proc/self/exe),
 * so that a checkpoint another build wrote is never taken for this one's
 * (a change to the engine may draw other numbers for the same scene and
 * version); 0 where the executable cannot be read, the version alone then
 * telling builds apart.  Computed once, about 2 ms for gdsmc's 2.3 MB. */
static uint64_t build_identity;
static pthread_once_t build_identity_once = PTHREAD_ONCE_INIT;

static void build_identity_compute(void)
{
    FILE *f = fopen("/proc/self/exe", "rb");
    if (f == NULL)
        return;
    unsigned char buf[1 << 16];
    uint64_t h = VFY_HASH_START;
    size_t got;
    while ((got = fread(buf, 1, sizeof buf, f)) > 0)
        h = vfy_hash(h, buf, got);
    if (!ferror(f))
        build_identity = h;
    fclose(f);
}

uint64_t vfy_build_identity(void)
{
    pthread_once(&build_identity_once, build_identity_compute);
    return build_identity;
}

uint64_t vfy_checkpoint_key(const sim_scene *s)
{
    return vfy_checkpoint_key_for(s, vfy_build_identity());
}

uint64_t vfy_checkpoint_key_for(const sim_scene *s, uint64_t build)
{
    /* The scene's bytes without what does not change the numbers.  Scenes
     * start zeroed (sim_scene_defaults), so their padding hashes alike; a
     * scene whose padding differs only costs a recomputation, never a wrong
     * reuse. */
    sim_scene numbers;
    memcpy(&numbers, s, sizeof numbers);
    memset(numbers.file, 0, sizeof numbers.file);
    memset(numbers.title, 0, sizeof numbers.title);
    memset(numbers.keys, 0, sizeof numbers.keys);
    numbers.nkeys = 0;
    uint64_t h = vfy_hash(VFY_HASH_START, GDSMC_VERSION, sizeof GDSMC_VERSION);
    h = vfy_hash(h, &build, sizeof build);
    return vfy_hash(h, &numbers, sizeof numbers);
}

static const char *checkpoint_path(const char *dir, uint64_t key, char *buf, size_t len)
{
    snprintf(buf, len, "%s/%016" PRIx64 ".ckpt", dir, key);
    return buf;
}

/* The statistics arrays of a result and their lengths, in file order. */
static size_t stats_len(const sim_ensemble_result *r)
{
    return r->outputs * r->observables + r->nsteady;
}

static void write_array(FILE *f, const char *name, const double *x, size_t len)
{
    fputs(name, f);
    for (size_t i = 0; i < len; i++)
        fprintf(f, " %a", x[i]);
    fputc('\n', f);
}

sim_status vfy_checkpoint_save(const char *dir, const char *label, const sim_scene *s,
                               const sim_ensemble_result *res, char *msg, size_t msglen)
{
    char path[1100], tmp[1200];
    const uint64_t key = vfy_checkpoint_key(s);
    checkpoint_path(dir, key, path, sizeof path);
    FILE *f = vfy_ensure_dir(dir) == 0 ? vfy_file_begin(path, tmp, sizeof tmp) : NULL;
    if (f == NULL) {
        snprintf(msg, msglen, "%s: cannot write: %s", path, strerror(errno));
        return SIM_EIO;
    }
    const sim_counts *c = &res->counts;
    fprintf(f, CHECKPOINT_MAGIC "\nversion %s\nkey %016" PRIx64 "\nlabel %s\n", GDSMC_VERSION,
            key, label);
    fprintf(f, "sizes %zu %zu %zu %zu %zu\n", res->outputs, res->observables, res->ensembles,
            res->n, res->nsteady);
    fprintf(f, "counts %" PRIu64 " %" PRIu64 " %" PRIu64 " %" PRIu64 " %" PRIu64 " %u\n",
            c->candidates, c->collisions, c->background, c->violations, c->normals,
            res->missing);
    fprintf(f, "seconds %a %a %d\n", res->cpu_seconds, res->wall_seconds, res->threads);
    write_array(f, "t", res->t, res->outputs);
    write_array(f, "mean", res->mean, stats_len(res));
    write_array(f, "var", res->var, stats_len(res));
    write_array(f, "ci", res->ci, stats_len(res));
    fputs("end\n", f);
    if (vfy_file_commit(f, tmp, path, 1) != 0) {
        snprintf(msg, msglen, "%s: cannot write: %s", path, strerror(errno));
        return SIM_EIO;
    }
    return SIM_OK;
}

static int read_array(FILE *f, const char *name, double *x, size_t len)
{
    char word[16];
    if (fscanf(f, "%15s", word) != 1 || strcmp(word, name) != 0)
        return 0;
    for (size_t i = 0; i < len; i++)
        if (fscanf(f, "%la", &x[i]) != 1)
            return 0;
    return 1;
}

int vfy_checkpoint_load(const char *dir, const sim_scene *s, sim_ensemble_result *res)
{
    memset(res, 0, sizeof *res);
    char path[1100], line[600], version[64];
    const uint64_t key = vfy_checkpoint_key(s);
    FILE *f = fopen(checkpoint_path(dir, key, path, sizeof path), "r");
    if (f == NULL)
        return 0;
    uint64_t file_key = 0;
    sim_counts *c = &res->counts;
    int ok = fgets(line, sizeof line, f) && strcmp(line, CHECKPOINT_MAGIC "\n") == 0
             && fscanf(f, "version %63s key %" SCNx64 " ", version, &file_key) == 2
             && strcmp(version, GDSMC_VERSION) == 0 && file_key == key
             && fgets(line, sizeof line, f) && strncmp(line, "label ", 6) == 0
             && fscanf(f, "sizes %zu %zu %zu %zu %zu ", &res->outputs, &res->observables,
                       &res->ensembles, &res->n, &res->nsteady) == 5
             && res->outputs == s->outputs && res->observables >= SIM_OBS_BASE
             && res->observables < 1000000 && res->ensembles == s->particles.ensembles
             && res->n == s->particles.n && res->nsteady < 1000000
             && fscanf(f, "counts %" SCNu64 " %" SCNu64 " %" SCNu64 " %" SCNu64 " %" SCNu64
                          " %u ", &c->candidates, &c->collisions, &c->background,
                       &c->violations, &c->normals, &res->missing) == 6
             && fscanf(f, "seconds %la %la %d", &res->cpu_seconds, &res->wall_seconds,
                       &res->threads) == 3;
    const size_t len = ok ? stats_len(res) : 0;
    if (ok) {
        res->t = malloc(res->outputs * sizeof *res->t);
        res->mean = malloc(len * sizeof *res->mean);
        res->var = malloc(len * sizeof *res->var);
        res->ci = malloc(len * sizeof *res->ci);
        char end[8];
        ok = res->t && res->mean && res->var && res->ci
             && read_array(f, "t", res->t, res->outputs) && read_array(f, "mean", res->mean, len)
             && read_array(f, "var", res->var, len) && read_array(f, "ci", res->ci, len)
             && fscanf(f, "%7s", end) == 1 && strcmp(end, "end") == 0;
    }
    fclose(f);
    if (!ok) {
        sim_ensemble_result_free(res);
        return 0;
    }
    const size_t rows_len = res->outputs * res->observables;
    res->steady_mean = res->mean + rows_len;
    res->steady_var = res->var + rows_len;
    res->steady_ci = res->ci + rows_len;
    return 1;
}
