#include "result.h"

#include <ctype.h>
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "observe.h"
#include "scene_ini.h"
#include "steady.h"

/* The engine's population variance over N ensembles as the protocol's
 * sample variance. */
static double sample_variance(double var, size_t N)
{
    return N > 1 ? var * (double)N / (double)(N - 1) : 0.0;
}

int vfy_result_write(FILE *f, const char *solver, const sim_scene *scene,
                     const sim_ensemble_result *res)
{
    const size_t N = res->ensembles;
    const int K = (int)sim_observe_row_length(scene);   /* the scene's row (observe.h) */
    fprintf(f, "# gdsmc-result %d\n# solver = %s\n# n = %zu\n# ensembles = %zu\n",
            VFY_RESULT_VERSION, solver, res->n, N);
    fprintf(f, "# cpu_seconds = %.17g\n# events = %" PRIu64 "\n# violations = %" PRIu64 "\n",
            res->cpu_seconds, res->counts.candidates, res->counts.violations);
    /* an observable the run did not observe (NaN, e.g. q with conditional
     * observation) is not reported: no column */
    int reported[SIM_OBS_MAX];
    fputs("t", f);
    for (int k = 0; k < K; k++) {
        char column[SIM_OBS_NAME_LEN];
        reported[k] = 1;
        for (size_t m = 0; m < res->outputs; m++)
            reported[k] &= !isnan(sim_result_mean(res, m, k));
        sim_observable_name(scene, (size_t)k, column);
        if (reported[k])
            fprintf(f, ",%s,%s_var", column, column);
    }
    fputc('\n', f);
    for (size_t m = 0; m < res->outputs; m++) {
        fprintf(f, "%.17g", res->t[m]);
        for (int k = 0; k < K; k++)
            if (reported[k])
                fprintf(f, ",%.17g,%.17g", sim_result_mean(res, m, k),
                        sample_variance(sim_result_var(res, m, k), N));
        fputc('\n', f);
    }
    if (res->nsteady > 0) {
        fputs("# steady\nname,mean,var\n", f);
        for (size_t k = 0; k < res->nsteady; k++) {
            char name[32];
            if (!isfinite(res->steady_mean[k]))   /* not measured (mu2 without steady.pairs) */
                continue;
            fprintf(f, "%s,%.17g,%.17g\n", sim_steady_name(scene, k, name, sizeof name),
                    res->steady_mean[k], sample_variance(res->steady_var[k], N));
        }
    }
    return ferror(f) ? -1 : 0;
}

/* ---- reading (vfy_result_parse) --------------------------------------- */

typedef struct reader {
    const char *name;
    const char *p, *end;    /* the text not yet taken */
    int line;               /* the number of the line last taken */
    const char *at;         /* that line, and its length (no newline) */
    size_t len;
    char *msg;
    size_t msglen;
} reader;

__attribute__((format(printf, 3, 4)))
static sim_status fail(reader *r, int line, const char *fmt, ...)
{
    char text[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (line > 0)
        snprintf(r->msg, r->msglen, "%s:%d: %s", r->name, line, text);
    else
        snprintf(r->msg, r->msglen, "%s: %s", r->name, text);
    return SIM_EINVAL;
}

/* Take the next line (without its newline or a carriage return before it);
 * 0 at the end of the text. */
static int next_line(reader *r)
{
    if (r->p >= r->end)
        return 0;
    const char *nl = memchr(r->p, '\n', (size_t)(r->end - r->p));
    const char *stop = nl ? nl : r->end;
    r->at = r->p;
    r->len = (size_t)(stop - r->p);
    if (r->len > 0 && r->at[r->len - 1] == '\r')
        r->len--;
    r->p = nl ? nl + 1 : r->end;
    r->line++;
    return 1;
}

static int blank(const char *s, size_t len)
{
    for (size_t i = 0; i < len; i++)
        if (!isspace((unsigned char)s[i]))
            return 0;
    return 1;
}

/* The k-th comma-separated field (from 0) of the line, trimmed, into buf;
 * the number of fields of the line as the return value. */
static size_t field(const reader *r, size_t k, char *buf, size_t cap)
{
    size_t count = 0, start = 0;
    buf[0] = '\0';
    for (size_t i = 0; i <= r->len; i++) {
        if (i < r->len && r->at[i] != ',')
            continue;
        if (count == k) {
            size_t a = start, b = i;
            while (a < b && isspace((unsigned char)r->at[a]))
                a++;
            while (b > a && isspace((unsigned char)r->at[b - 1]))
                b--;
            size_t n = b - a < cap - 1 ? b - a : cap - 1;
            memcpy(buf, r->at + a, n);
            buf[n] = '\0';
        }
        count++;
        start = i + 1;
    }
    return count;
}

/* A number of the whole field text, finite; NULL or why not. */
static const char *number(const char *text, double *x)
{
    char *end;
    errno = 0;
    *x = strtod(text, &end);
    if (end == text || *end != '\0')
        return "is not a number";
    if (!isfinite(*x))
        return "is not finite";
    return NULL;
}

/* "# key = value" lines before the column header. */
static sim_status header_lines(reader *r, const sim_scene *scene, sim_ensemble_result *res,
                               vfy_result_info *info)
{
    int seen_n = 0, seen_N = 0;
    while (r->p < r->end && *r->p == '#') {
        next_line(r);
        char key[32], value[sizeof info->solver];
        const char *eq = memchr(r->at, '=', r->len);
        if (eq == NULL)
            continue;   /* a comment */
        size_t klen = (size_t)(eq - r->at) - 1, vlen = r->len - (size_t)(eq + 1 - r->at);
        const char *k = r->at + 1, *v = eq + 1;
        while (klen > 0 && isspace((unsigned char)*k))
            k++, klen--;
        while (klen > 0 && isspace((unsigned char)k[klen - 1]))
            klen--;
        while (vlen > 0 && isspace((unsigned char)*v))
            v++, vlen--;
        while (vlen > 0 && isspace((unsigned char)v[vlen - 1]))
            vlen--;
        if (klen >= sizeof key || vlen >= sizeof value)
            continue;
        memcpy(key, k, klen);
        key[klen] = '\0';
        memcpy(value, v, vlen);
        value[vlen] = '\0';
        if (strcmp(key, "solver") == 0) {
            snprintf(info->solver, sizeof info->solver, "%s", value);
            continue;
        }
        if (strcmp(key, "substituted") == 0) {   /* algorithm keys the solver replaced */
            char list[sizeof value], *save = NULL;
            snprintf(list, sizeof list, "%s", value);
            info->substituted[0] = '\0';
            for (char *w = strtok_r(list, ", \t", &save); w; w = strtok_r(NULL, ", \t", &save)) {
                const int cls = vfy_scene_key_class(w);
                if (cls != VFY_KEY_ALGORITHM)
                    return fail(r, r->line, "substituted = '%s': %s %s", value, w,
                                cls == VFY_KEY_PHYSICS
                                    ? "is a physics key: a solver must honour it or refuse "
                                      "the scene (docs/scenes.md)"
                                    : "is not a scene key (SECTION.KEY, docs/scenes.md)");
                const size_t used = strlen(info->substituted);
                snprintf(info->substituted + used, sizeof info->substituted - used, "%s%s",
                         used ? ", " : "", w);
            }
            continue;
        }
        double x;
        int known = strcmp(key, "n") == 0 || strcmp(key, "ensembles") == 0
                    || strcmp(key, "cpu_seconds") == 0 || strcmp(key, "events") == 0
                    || strcmp(key, "violations") == 0
                    || strcmp(key, "violations_allowed") == 0;
        if (!known)
            continue;   /* a comment of the solver's */
        const char *why = number(value, &x);
        int whole = strcmp(key, "cpu_seconds") != 0;
        if (why == NULL && (x < 0 || (whole && (x != floor(x) || x > 9e15))))
            why = whole ? "is not a count (allowed 0, 1, 2, ...)" : "is negative";
        if (why != NULL)
            return fail(r, r->line, "%s = '%s' %s", key, value, why);
        if (strcmp(key, "n") == 0) {
            if ((size_t)x != scene->particles.n)
                return fail(r, r->line, "n = %s does not match the scene's particles.n = %zu",
                            value, scene->particles.n);
            seen_n = 1;
        } else if (strcmp(key, "ensembles") == 0) {
            if ((size_t)x != scene->particles.ensembles)
                return fail(r, r->line,
                            "ensembles = %s does not match the scene's particles.ensembles = "
                            "%zu", value, scene->particles.ensembles);
            seen_N = 1;
        } else if (strcmp(key, "cpu_seconds") == 0) {
            res->cpu_seconds = x;
            info->has_cpu = 1;
        } else if (strcmp(key, "events") == 0) {
            res->counts.candidates = (uint64_t)x;
            info->has_events = 1;
        } else if (strcmp(key, "violations_allowed") == 0) {
            info->violations_allowed = x;
        } else {
            res->counts.violations = (uint64_t)x;
            info->has_violations = 1;
        }
    }
    if (!seen_n || !seen_N)
        return fail(r, 0, "no '# %s = ' line (required: the scene's particles.%s)",
                    seen_n ? "ensembles" : "n", seen_n ? "ensembles" : "n");
    return SIM_OK;
}

/* The column header: t, then NAME and NAME_var pairs; obs[j] is the
 * observable of column 1 + 2 j. */
static sim_status column_header(reader *r, const sim_scene *scene,
                                const sim_ensemble_result *res, int *obs,
                                size_t *nobs, vfy_result_info *info)
{
    if (!next_line(r) || blank(r->at, r->len))
        return fail(r, r->line, "no column header (expected t,NAME,NAME_var,...)");
    char name[64], var[64];
    const size_t count = field(r, 0, name, sizeof name);
    if (strcmp(name, "t") != 0)
        return fail(r, r->line, "column 1 is '%s', expected t", name);
    *nobs = 0;
    for (size_t k = 1; k < count; k += 2) {
        field(r, k, name, sizeof name);
        int o = sim_observable_find(scene, name, strlen(name));
        if (o < 0 || o >= (int)res->observables) {
            char allowed[400] = "", known[SIM_OBS_NAME_LEN];
            for (size_t j = 0; j < res->observables && j < SIM_OBS_PROFILE; j++)
                snprintf(allowed + strlen(allowed), sizeof allowed - strlen(allowed), "%s%s",
                         j ? " " : "", sim_observable_name(scene, j, known));
            if (res->observables > SIM_OBS_PROFILE)
                snprintf(allowed + strlen(allowed), sizeof allowed - strlen(allowed),
                         " n_I ux_I T_I Pxy_I for the layers I = 0 .. %zu",
                         scene->shear.layers - 1);
            return fail(r, r->line, "column %zu: '%s' is not an observable (allowed %s)",
                        k + 1, name, allowed);
        }
        if (info->reported[o])
            return fail(r, r->line, "column %zu: %s appears twice", k + 1, name);
        char want[80];
        snprintf(want, sizeof want, "%s_var", name);
        if (k + 1 >= count || (field(r, k + 1, var, sizeof var), strcmp(var, want) != 0))
            return fail(r, r->line, "column %zu: %s must be followed by %s", k + 1, name, want);
        info->reported[o] = 1;
        obs[(*nobs)++] = o;
    }
    return SIM_OK;
}

/* Row m of the time series. */
static sim_status series_row(reader *r, const sim_scene *scene, size_t m, const int *obs,
                             size_t nobs, sim_ensemble_result *res)
{
    char text[128], header[64];
    const size_t count = field(r, 0, text, sizeof text);
    if (count != 1 + 2 * nobs)
        return fail(r, r->line, "%zu fields, the header has %zu", count, 1 + 2 * nobs);
    double t;
    const char *why = number(text, &t);
    if (why != NULL)
        return fail(r, r->line, "column 1 (t): '%s' %s", text, why);
    const double want = sim_scene_output_time(scene, m);
    if (!(fabs(t - want) <= 1e-9 * fmax(fabs(want), 1e-300)))
        return fail(r, r->line, "t = %s, but the scene's output time %zu is %.17g (allowed "
                    "relative difference 1e-9)", text, m, want);
    res->t[m] = want;
    const double N = (double)res->ensembles;
    for (size_t j = 0; j < nobs; j++) {
        double mean, var;
        char name[SIM_OBS_NAME_LEN];
        sim_observable_name(scene, (size_t)obs[j], name);
        field(r, 1 + 2 * j, text, sizeof text);
        if ((why = number(text, &mean)) != NULL)
            return fail(r, r->line, "column %zu (%s): '%s' %s", 2 + 2 * j, name, text, why);
        field(r, 2 + 2 * j, text, sizeof text);
        snprintf(header, sizeof header, "%s_var", name);
        if ((why = number(text, &var)) != NULL)
            return fail(r, r->line, "column %zu (%s): '%s' %s", 3 + 2 * j, header, text, why);
        if (var < 0.0)
            return fail(r, r->line, "column %zu (%s): %s is a negative variance", 3 + 2 * j,
                        header, text);
        const size_t i = m * res->observables + (size_t)obs[j];
        res->mean[i] = mean;
        res->var[i] = N > 1 ? var * (N - 1.0) / N : 0.0;
        res->ci[i] = SIM_LAMBDA_P * sqrt(res->var[i] / N);
    }
    return SIM_OK;
}

/* After "# steady": "name,mean,var", then one row per steady quantity. */
static sim_status steady_section(reader *r, const sim_scene *scene, sim_ensemble_result *res,
                                 vfy_result_info *info)
{
    char text[128];
    if (res->nsteady == 0)
        return fail(r, r->line, "a steady section, but the scene has no [steady]");
    if (!next_line(r) || field(r, 0, text, sizeof text) != 3 || strcmp(text, "name") != 0
        || (field(r, 1, text, sizeof text), strcmp(text, "mean") != 0)
        || (field(r, 2, text, sizeof text), strcmp(text, "var") != 0))
        return fail(r, r->line, "expected the steady section's header name,mean,var");
    unsigned char *seen = calloc(res->nsteady, 1);
    if (seen == NULL)
        return fail(r, 0, "out of memory");
    sim_status status = SIM_OK;
    const double N = (double)res->ensembles;
    while (status == SIM_OK && next_line(r)) {
        if (blank(r->at, r->len))
            continue;
        char name[64], qname[32];
        double mean, var;
        const char *why = NULL;
        if (field(r, 0, name, sizeof name) != 3) {
            status = fail(r, r->line, "%zu fields, the steady section has 3 (name,mean,var)",
                          field(r, 0, name, sizeof name));
            break;
        }
        size_t k = 0;
        while (k < res->nsteady && strcmp(sim_steady_name(scene, k, qname, sizeof qname), name) != 0)
            k++;
        if (k == res->nsteady)
            status = fail(r, r->line, "'%s' is not a steady quantity of this scene (allowed "
                          "T, a2, a3, c1, c3, mu2, mu4, mu4_white, mu4_gaussian, "
                          "mu4_nongaussian, f_0 to f_%zu%s)", name, scene->steady.bins - 1,
                          scene->heat_flux.present ? ", and the heat-flux quantities of "
                                                     "docs/solver-protocol.md" : "");
        else if (seen[k])
            status = fail(r, r->line, "%s appears twice", name);
        else if (field(r, 1, text, sizeof text), (why = number(text, &mean)) != NULL)
            status = fail(r, r->line, "column 2 (mean): '%s' %s", text, why);
        else if (field(r, 2, text, sizeof text), (why = number(text, &var)) != NULL)
            status = fail(r, r->line, "column 3 (var): '%s' %s", text, why);
        else if (var < 0.0)
            status = fail(r, r->line, "column 3 (var): %s is a negative variance", text);
        else {
            seen[k] = 1;
            info->steady_reported++;
            res->steady_mean[k] = mean;
            res->steady_var[k] = N > 1 ? var * (N - 1.0) / N : 0.0;
            res->steady_ci[k] = SIM_LAMBDA_P * sqrt(res->steady_var[k] / N);
        }
    }
    free(seen);
    return status;
}

/* The result's arrays for scene, every number NaN until read. */
static sim_status allocate(const sim_scene *scene, sim_ensemble_result *res)
{
    res->outputs = scene->outputs;
    res->observables = sim_observe_row_length(scene);
    res->ensembles = scene->particles.ensembles;
    res->n = scene->particles.n;
    res->nsteady = sim_steady_count(scene);
    res->threads = 1;
    const size_t rows = res->outputs * res->observables, len = rows + res->nsteady;
    res->t = malloc(res->outputs * sizeof *res->t);
    res->mean = malloc(len * sizeof *res->mean);
    res->var = malloc(len * sizeof *res->var);
    res->ci = malloc(len * sizeof *res->ci);
    if (!res->t || !res->mean || !res->var || !res->ci)
        return SIM_ENOMEM;
    for (size_t i = 0; i < len; i++)
        res->mean[i] = res->var[i] = res->ci[i] = NAN;
    res->steady_mean = res->mean + rows;
    res->steady_var = res->var + rows;
    res->steady_ci = res->ci + rows;
    return SIM_OK;
}

sim_status vfy_result_blank(const sim_scene *scene, sim_ensemble_result *res)
{
    memset(res, 0, sizeof *res);
    sim_status status = allocate(scene, res);
    if (status != SIM_OK) {
        sim_ensemble_result_free(res);
        return status;
    }
    for (size_t m = 0; m < res->outputs; m++)
        res->t[m] = sim_scene_output_time(scene, m);
    res->missing = SIM_MISSING_EVENTS | SIM_MISSING_VIOLATIONS | SIM_MISSING_COLLISIONS;
    return SIM_OK;
}

static sim_status parse(reader *r, const sim_scene *scene, sim_ensemble_result *res,
                        vfy_result_info *info)
{
    if (blank(r->p, (size_t)(r->end - r->p)))
        return fail(r, 0, "empty result (the solver wrote nothing)");
    if (memchr(r->p, '\0', (size_t)(r->end - r->p)) != NULL)
        return fail(r, 0, "holds a NUL byte (a result file is text)");
    next_line(r);
    static const char magic[] = "# gdsmc-result ";
    if (r->len < sizeof magic - 1 || memcmp(r->at, magic, sizeof magic - 1) != 0)
        return fail(r, 1, "the first line must be '# gdsmc-result 1' (the protocol version), "
                    "got '%.*s'", (int)(r->len < 60 ? r->len : 60), r->at);
    if (r->len != sizeof magic || r->at[sizeof magic - 1] != '0' + VFY_RESULT_VERSION)
        return fail(r, 1, "protocol version '%.*s', this gdsmc reads version %d",
                    (int)(r->len - (sizeof magic - 1) < 20 ? r->len - (sizeof magic - 1) : 20),
                    r->at + sizeof magic - 1, VFY_RESULT_VERSION);
    if (allocate(scene, res) != SIM_OK)
        return fail(r, 0, "out of memory");
    sim_status status = header_lines(r, scene, res, info);
    int obs[SIM_OBS_MAX];
    size_t nobs = 0;
    if (status == SIM_OK)
        status = column_header(r, scene, res, obs, &nobs, info);
    for (size_t m = 0; m < res->outputs && status == SIM_OK; m++) {
        if (!next_line(r))
            return fail(r, r->line, "the file ends after %zu rows, the scene has %zu output "
                        "times", m, res->outputs);
        if (r->at[0] == '#' || blank(r->at, r->len))
            return fail(r, r->line, "%zu rows before this line, the scene has %zu output times",
                        m, res->outputs);
        status = series_row(r, scene, m, obs, nobs, res);
    }
    while (status == SIM_OK && next_line(r)) {
        if (blank(r->at, r->len))
            continue;
        if (r->len == 8 && memcmp(r->at, "# steady", 8) == 0)
            status = steady_section(r, scene, res, info);
        else if (r->at[0] != '#')
            status = fail(r, r->line, "more rows than the scene's %zu output times, or text "
                          "after them: '%.*s'", res->outputs, (int)(r->len < 40 ? r->len : 40),
                          r->at);
        else
            status = fail(r, r->line, "unexpected line after the rows: '%.*s' (allowed: the "
                          "steady section, '# steady')", (int)(r->len < 40 ? r->len : 40), r->at);
    }
    return status;
}

sim_status vfy_result_parse(const char *text, size_t len, const char *name,
                            const sim_scene *scene, sim_ensemble_result *res,
                            vfy_result_info *info, char *msg, size_t msglen)
{
    char spare[8];
    reader r = {.name = name, .p = text, .end = text + len, .msg = msg ? msg : spare,
                .msglen = msg ? msglen : sizeof spare};
    memset(res, 0, sizeof *res);
    memset(info, 0, sizeof *info);
    r.msg[0] = '\0';
    sim_status status = parse(&r, scene, res, info);
    if (status != SIM_OK)
        sim_ensemble_result_free(res);
    return status;
}

sim_status vfy_result_read(const char *path, const sim_scene *scene, sim_ensemble_result *res,
                           vfy_result_info *info, char *msg, size_t msglen)
{
    memset(res, 0, sizeof *res);
    FILE *f = fopen(path, "rb");
    char *text = NULL;
    size_t len = 0, cap = 0;
    int failed = f == NULL;
    while (!failed) {
        if (len == cap) {
            char *more = realloc(text, cap = cap ? 2 * cap : 65536);
            if (more == NULL) {
                failed = 1;
                break;
            }
            text = more;
        }
        size_t got = fread(text + len, 1, cap - len, f);
        len += got;
        if (got == 0) {
            failed = ferror(f);
            break;
        }
    }
    if (failed) {
        snprintf(msg, msglen, "%s: cannot read: %s", path, strerror(errno ? errno : EIO));
        free(text);
        if (f)
            fclose(f);
        return SIM_EIO;
    }
    fclose(f);
    sim_status status = vfy_result_parse(text ? text : "", len, path, scene, res, info, msg,
                                         msglen);
    free(text);
    return status;
}
