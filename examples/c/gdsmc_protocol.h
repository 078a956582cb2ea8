/* gdsmc_protocol.h: helpers for a C solver behind gdsmc's solver protocol,
 * version 1 (docs/solver-protocol.md).  One header of static inline
 * functions, C99, libc and libm only: copy it beside your solver and include
 * it.
 *
 *   gp_scene_load     the scene INI gdsmc wrote; every getter applies the
 *                     key's default (docs/scenes.md, sim/scene.h) and marks
 *                     the key as read
 *   gp_refuse         the protocol's refusal: the reason as the last line of
 *                     standard error, exit status 3 (nothing else is one)
 *   gp_refuse_unread  refuse a scene that holds a key (or a section) the
 *                     solver never read: "key X not supported" (but t_end,
 *                     outputs, n and N, which gp_result follows, the title
 *                     and the seed)
 *   gp_output_time    t_m = m t_end / (outputs - 1), as the engine computes it
 *   gp_observe        T, T_raw, ux .. a3 of n velocities, as sim/observe.c
 *   gp_steady_*       the steady quantities of sim/steady.c (T a2 a3 c1 c3
 *                     mu2 mu4 mu4_* and the speed histogram f_k)
 *   gp_result_*       ensemble mean and sample variance (divisor N - 1) of
 *                     each quantity, and the result file (%.17g)
 *   gp_rng_*          a small random number generator (xoshiro256**) with a
 *                     stream per ensemble
 *
 * A solver's main (hard_spheres_gaussian.c and template_adapter.c beside
 * this file are complete examples):
 *
 *   static gp_scene scene;                 (large: static or malloc'd)
 *   gp_scene_load(&scene, argv[1]);
 *   gp_only(&scene, "collisions.kernel", "hard-spheres");
 *   size_t n = gp_count(&scene, "particles.n");  ...   (read every key you do)
 *   gp_refuse_unread(&scene);                           (refuse the rest)
 *   gp_result res;  gp_result_init(&res, &scene, NULL);
 *   for each ensemble, for each output m:
 *       advance to gp_output_time(&scene, m); gp_observe(v, n, mass, obs);
 *       gp_result_add(&res, m, obs);
 *   gp_result_write(&res, &scene, argv[2], &info);
 *
 * Errors in the input (a malformed scene, a file that cannot be written)
 * stop the program with exit status 2 (gp_fail): gdsmc reports a crash.
 * Not covered: paper D's heat-flux and paper E's shear-flow quantities.
 */
#ifndef GDSMC_PROTOCOL_H
#define GDSMC_PROTOCOL_H

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define GP_PROTOCOL_VERSION 1
#define GP_EXIT_REFUSED 3    /* a refusal (protocol v1) */
#define GP_EXIT_FAILED 2     /* bad input or an internal error */
#define GP_REASON_MAX 239    /* the longest reason gdsmc quotes */

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ------------------------------------------------------------- refusals */

static inline void gp_vexit(int status, const char *fmt, va_list ap)
{
    char text[GP_REASON_MAX + 1];
    vsnprintf(text, sizeof text, fmt, ap);
    for (char *p = text; *p; p++)   /* one line */
        if (*p == '\n' || *p == '\r')
            *p = ' ';
    fflush(stdout);
    fprintf(stderr, "%s\n", text);
    fflush(stderr);
    exit(status);
}

/* Refuse the scene: the reason (printf-style, one line of at most 239
 * bytes) as the last line of standard error, exit status 3. */
static inline void gp_refuse(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    gp_vexit(GP_EXIT_REFUSED, fmt, ap);
    va_end(ap);
}

/* Stop on bad input or an internal error (not a refusal): exit status 2. */
static inline void gp_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    gp_vexit(GP_EXIT_FAILED, fmt, ap);
    va_end(ap);
}

/* ------------------------------------------------------------- the scene */

/* Every key gdsmc knows (verify/protocol/scene_ini.c) and its default as text
 * (sim_scene_defaults); NULL: none, or one that depends on other keys
 * (gp_text explains). */
static const struct gp_key {
    const char *name, *def;
} gp_keys[] = {
    {"scene.title", ""}, {"scene.scheme", "jump"}, {"scene.dt", NULL},
    {"scene.splitting", "euler"}, {"scene.step_follows_temperature", "false"},
    {"scene.observation", "sampled"}, {"scene.t_end", "1"}, {"scene.outputs", "2"},
    {"scene.seed", "1"},
    {"particles.n", "64"}, {"particles.ensembles", "1"}, {"particles.initial", "maxwellian"},
    {"particles.mass", "1"}, {"particles.temperature", "1"}, {"particles.velocity", "0 0 0"},
    {"particles.fraction", "0.5"}, {"particles.mass1", "1"}, {"particles.velocity1", "0 0 0"},
    {"particles.temperature1", "1"}, {"particles.mass2", "1"},
    {"particles.velocity2", "0 0 0"}, {"particles.temperature2", "1"},
    {"particles.zero_momentum", "false"}, {"particles.density_wave", "0"},
    {"particles.flow_wave", "0"},
    {"collisions.kernel", "maxwell"}, {"collisions.exponent", NULL},
    {"collisions.constant", "0.079577471545947673"},   /* 1/(4 pi) */
    {"collisions.rate", "1"}, {"collisions.restitution", "1"}, {"collisions.model", "ihs"},
    {"collisions.beta", NULL}, {"collisions.rule", "contact"},
    {"heating.type", "white-noise"}, {"heating.strength", "0"},
    {"heating.keep_temperature", "false"},
    {"background.density", "1"}, {"background.mass", "1"}, {"background.temperature", "1"},
    {"background.velocity", "0 0 0"}, {"background.kernel", "maxwell"},
    {"background.constant", "1"},
    {"shear.rate", "0"}, {"shear.boundary", "homogeneous"}, {"shear.length", "1"},
    {"shear.layers", "1"}, {"shear.candidates", "unbiased"}, {"shear.pairs", "0"},
    {"heat-flux.strength", "0"},
    {"steady.from", "0"}, {"steady.pairs", "0"}, {"steady.bins", "0"}, {"steady.c_max", "5"},
};

/* Keys gp_refuse_unread never asks for: the output times, n and N, which
 * gp_result follows itself; a label; and the seed, which the protocol leaves
 * to the solver (independent ensembles are what matters). */
static const char *const gp_handled[] = {"scene.t_end", "scene.outputs", "particles.n",
                                         "particles.ensembles", "scene.title", "scene.seed"};

/* Keys a solver may treat as algorithm choices (gp_substitute). */
static const char *const gp_algorithm_choices[] = {"collisions.rule", "scene.scheme",
                                                   "scene.dt"};

#define GP_MAX_ENTRIES 128
#define GP_MAX_SECTIONS 16

typedef struct gp_entry {
    char name[64];       /* "section.key" */
    char value[256];
    int line, read;
} gp_entry;

typedef struct gp_scene {
    char path[512];
    gp_entry entry[GP_MAX_ENTRIES];
    size_t nentries;
    char section[GP_MAX_SECTIONS][32];   /* the sections, in file order */
    int looked[GP_MAX_SECTIONS];         /* gp_present asked, or a key was read */
    size_t nsections;
    char substituted[256];               /* "key,key": gp_substitute */
    char text[32];                       /* gp_text's buffer for derived defaults */
} gp_scene;

static inline char *gp_trim(char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n')
        s++;
    size_t len = strlen(s);
    while (len > 0 && strchr(" \t\r\n", s[len - 1]))
        s[--len] = '\0';
    return s;
}

static inline int gp_find_section(const gp_scene *s, const char *section, size_t len)
{
    for (size_t k = 0; k < s->nsections; k++)
        if (strlen(s->section[k]) == len && strncmp(s->section[k], section, len) == 0)
            return (int)k;
    return -1;
}

static inline gp_entry *gp_find(gp_scene *s, const char *name)
{
    for (size_t k = 0; k < s->nentries; k++)
        if (strcmp(s->entry[k].name, name) == 0)
            return &s->entry[k];
    return NULL;
}

/* Read the scene file at path into s, as gdsmc reads it with inih: ';' and
 * '#' comment lines, ';' after white space starts an inline comment, a key
 * at most once.  Stops with exit status 2 when the file cannot be read or
 * is malformed. */
static inline void gp_scene_load(gp_scene *s, const char *path)
{
    memset(s, 0, sizeof *s);
    snprintf(s->path, sizeof s->path, "%s", path);
    FILE *f = fopen(path, "r");
    if (f == NULL)
        gp_fail("%s: cannot open the scene", path);
    char buf[1024], section[32] = "";
    int line = 0, have_section = 0;
    while (fgets(buf, sizeof buf, f) != NULL) {
        line++;
        if (strchr(buf, '\n') == NULL && !feof(f))
            gp_fail("%s:%d: line too long (at most %d characters)", path, line,
                    (int)sizeof buf - 2);
        char *p = buf;
        if (line == 1 && strncmp(p, "\xEF\xBB\xBF", 3) == 0)
            p += 3;
        p = gp_trim(p);
        if (*p == '\0' || *p == ';' || *p == '#')
            continue;
        for (char *c = p + 1; *c; c++)   /* an inline comment: " ;" */
            if (*c == ';' && (c[-1] == ' ' || c[-1] == '\t')) {
                *c = '\0';
                p = gp_trim(p);
                break;
            }
        if (*p == '[') {
            char *end = strchr(p, ']');
            if (end == NULL || (size_t)(end - p - 1) >= sizeof section)
                gp_fail("%s:%d: a bad section header", path, line);
            *end = '\0';
            snprintf(section, sizeof section, "%s", gp_trim(p + 1));
            have_section = 1;
            if (gp_find_section(s, section, strlen(section)) < 0) {
                if (s->nsections == GP_MAX_SECTIONS)
                    gp_fail("%s:%d: too many sections", path, line);
                snprintf(s->section[s->nsections++], sizeof s->section[0], "%s", section);
            }
            continue;
        }
        char *cut = strpbrk(p, "=:");
        if (cut == NULL || cut == p)
            gp_fail("%s:%d: syntax error (expected key = value or [section])", path, line);
        *cut = '\0';
        const char *key = gp_trim(p), *value = gp_trim(cut + 1);
        if (!have_section)
            gp_fail("%s:%d: %s: a key outside any section", path, line, key);
        char name[64];
        if ((size_t)snprintf(name, sizeof name, "%s.%s", section, key) >= sizeof name
            || strlen(value) >= sizeof s->entry[0].value)
            gp_fail("%s:%d: %s: too long", path, line, key);
        if (gp_find(s, name) != NULL)
            gp_fail("%s:%d: %s: set twice", path, line, name);
        if (s->nentries == GP_MAX_ENTRIES)
            gp_fail("%s:%d: too many keys", path, line);
        gp_entry *e = &s->entry[s->nentries++];
        snprintf(e->name, sizeof e->name, "%s", name);
        snprintf(e->value, sizeof e->value, "%s", value);
        e->line = line;
    }
    if (ferror(f))
        gp_fail("%s: cannot read the scene", path);
    fclose(f);
}

/* Whether the scene has the section (an effect is on when it is). */
static inline int gp_present(gp_scene *s, const char *section)
{
    const int k = gp_find_section(s, section, strlen(section));
    if (k >= 0)
        s->looked[k] = 1;
    return k >= 0;
}

/* Whether the file sets key "section.key" (a default is not set); does not
 * mark it as read. */
static inline int gp_is_set(gp_scene *s, const char *name)
{
    return gp_find(s, name) != NULL;
}

/* The value of key "section.key" as text, its default when the file does
 * not set it; marks it as read when `mark` (gp_text below). */
static inline const char *gp_value(gp_scene *s, const char *name, int mark)
{
    const char *dot = strchr(name, '.');
    const int k = dot ? gp_find_section(s, name, (size_t)(dot - name)) : -1;
    if (k >= 0 && mark)   /* reading a key looks at its section */
        s->looked[k] = 1;
    gp_entry *e = gp_find(s, name);
    if (e != NULL) {
        e->read |= mark;
        return e->value;
    }
    if (strcmp(name, "collisions.exponent") == 0) {   /* the defaults of other keys */
        const char *kernel = gp_value(s, "collisions.kernel", 0);
        return strcmp(kernel, "maxwell") == 0        ? "0"
               : strcmp(kernel, "hard-spheres") == 0 ? "1"
                                                     : NULL;
    }
    if (strcmp(name, "collisions.beta") == 0) {
        const double alpha = strtod(gp_value(s, "collisions.restitution", 0), NULL);
        const int ehs = strcmp(gp_value(s, "collisions.model", 0), "ehs") == 0;
        snprintf(s->text, sizeof s->text, "%.17g", ehs ? 0.5 * (1.0 + alpha) : 1.0);
        return s->text;
    }
    for (size_t i = 0; i < sizeof gp_keys / sizeof gp_keys[0]; i++)
        if (strcmp(gp_keys[i].name, name) == 0)
            return gp_keys[i].def;
    gp_fail("%s is not a scene key (docs/scenes.md)", name);
    return NULL;
}

/* The value of key "section.key" as text (also for words), its default when
 * the file does not set it; marks it as read.  Two defaults depend on other
 * keys (which this does not mark): collisions.exponent (0 for maxwell, 1 for
 * hard-spheres; vhs requires it) and collisions.beta (1 for ihs, (1 +
 * alpha)/2 for ehs).  scene.dt has none (NULL).  A name that is no key and
 * not in the file stops the program. */
static inline const char *gp_text(gp_scene *s, const char *name)
{
    return gp_value(s, name, 1);
}

static inline const char *gp_need(gp_scene *s, const char *name)
{
    const char *text = gp_text(s, name);
    if (text == NULL)
        gp_fail("%s: %s is not set", s->path, name);
    return text;
}

/* A number key (real), its default applied; marks it read. */
static inline double gp_real(gp_scene *s, const char *name)
{
    const char *text = gp_need(s, name);
    char *end;
    const double x = strtod(text, &end);
    if (end == text || *end != '\0' || !isfinite(x))
        gp_fail("%s: %s = '%s' is not a number", s->path, name, text);
    return x;
}

/* A whole-number key (n, ensembles, outputs, seed, bins, pairs, ...). */
static inline unsigned long long gp_count(gp_scene *s, const char *name)
{
    const char *text = gp_need(s, name);
    char *end;
    if (text[0] < '0' || text[0] > '9')
        gp_fail("%s: %s = '%s' is not a whole number", s->path, name, text);
    const unsigned long long x = strtoull(text, &end, 10);
    if (*end != '\0')
        gp_fail("%s: %s = '%s' is not a whole number", s->path, name, text);
    return x;
}

/* A true | false key. */
static inline int gp_bool(gp_scene *s, const char *name)
{
    const char *text = gp_need(s, name);
    if (strcmp(text, "true") != 0 && strcmp(text, "false") != 0)
        gp_fail("%s: %s = '%s' is not true or false", s->path, name, text);
    return strcmp(text, "true") == 0;
}

/* A vector key: three numbers separated by spaces. */
static inline void gp_vec3(gp_scene *s, const char *name, double out[3])
{
    const char *text = gp_need(s, name);
    char *p = (char *)text, *end;
    for (int k = 0; k < 3; k++, p = end) {
        out[k] = strtod(p, &end);
        if (end == p || !isfinite(out[k]))
            gp_fail("%s: %s = '%s' is not three numbers", s->path, name, text);
    }
    while (*p == ' ' || *p == '\t')
        p++;
    if (*p != '\0')
        gp_fail("%s: %s = '%s' is not three numbers", s->path, name, text);
}

/* The key's value (text), refusing the scene unless it is one of the words
 * in `allowed`, separated by '|' ("euler|strang"). */
static inline const char *gp_only(gp_scene *s, const char *name, const char *allowed)
{
    const char *value = gp_text(s, name);
    const size_t len = value ? strlen(value) : 0;
    for (const char *a = allowed; value && *a;) {
        const char *bar = strchr(a, '|');
        const size_t alen = bar ? (size_t)(bar - a) : strlen(a);
        if (alen == len && strncmp(a, value, len) == 0)
            return value;
        a += alen + (bar != NULL);
    }
    gp_refuse("%s = %s not supported (this solver: %s)", name, value ? value : "(unset)",
              allowed);
    return NULL;
}

/* A number key, refusing the scene unless it equals `value`. */
static inline double gp_only_real(gp_scene *s, const char *name, double value)
{
    const double x = gp_real(s, name);
    if (x != value)
        gp_refuse("%s = %.17g not supported (this solver: %.17g)", name, x, value);
    return x;
}

/* Declare that the solver uses its own algorithm instead of what key `name`
 * (collisions.rule, scene.scheme or scene.dt) asks, when the file sets it:
 * the key counts as read, and gp_result_write with declare_substitutions
 * lists it on the line "# substituted = KEY,...". */
static inline void gp_substitute(gp_scene *s, const char *name)
{
    int choice = 0;
    for (size_t k = 0; k < sizeof gp_algorithm_choices / sizeof gp_algorithm_choices[0]; k++)
        choice |= strcmp(gp_algorithm_choices[k], name) == 0;
    if (!choice)
        gp_fail("gp_substitute: %s is not an algorithm choice", name);
    gp_text(s, name);
    if (gp_is_set(s, name) && strstr(s->substituted, name) == NULL) {
        const size_t used = strlen(s->substituted);
        snprintf(s->substituted + used, sizeof s->substituted - used, "%s%s", used ? "," : "",
                 name);
    }
}

/* Refuse the scene when it holds a section or a key the solver never read
 * (but those of gp_handled): "key X not supported". */
static inline void gp_refuse_unread(gp_scene *s)
{
    char list[GP_REASON_MAX + 1] = "";
    size_t count = 0, used = 0;
    for (size_t k = 0; k < s->nsections; k++) {
        int has_keys = 0;
        const size_t len = strlen(s->section[k]);
        for (size_t i = 0; i < s->nentries; i++)
            has_keys |= strncmp(s->entry[i].name, s->section[k], len) == 0
                        && s->entry[i].name[len] == '.';
        if (!has_keys && !s->looked[k]) {
            used += (size_t)snprintf(list + used, used < sizeof list ? sizeof list - used : 0,
                                     "%s[%s]", count ? ", " : "", s->section[k]);
            count++;
        }
    }
    for (size_t i = 0; i < s->nentries; i++) {
        int skip = s->entry[i].read;
        for (size_t k = 0; k < sizeof gp_handled / sizeof gp_handled[0]; k++)
            skip |= strcmp(s->entry[i].name, gp_handled[k]) == 0;
        if (skip)
            continue;
        used += (size_t)snprintf(list + used, used < sizeof list ? sizeof list - used : 0,
                                 "%s%s", count ? ", " : "", s->entry[i].name);
        count++;
    }
    if (count > 0)
        gp_refuse("%s %s not supported", count == 1 ? "key" : "keys", list);
}

/* Output time m: m t_end / (outputs - 1) (sim_scene_output_time). */
static inline double gp_output_time(gp_scene *s, size_t m)
{
    return gp_real(s, "scene.t_end") * (double)m
           / (double)(gp_count(s, "scene.outputs") - 1);
}

/* ------------------------------------------------------------ observables */

enum { GP_T, GP_T_RAW, GP_UX, GP_UY, GP_UZ, GP_PXX, GP_PYY, GP_PZZ, GP_PXY, GP_PXZ, GP_PYZ,
       GP_QX, GP_QY, GP_QZ, GP_A2, GP_A3, GP_NOBS };

static const char *const gp_obs_name[GP_NOBS] = {
    "T", "T_raw", "ux", "uy", "uz", "Pxx", "Pyy", "Pzz", "Pxy", "Pxz", "Pyz",
    "qx", "qy", "qz", "a2", "a3"};

/* The base observables of n velocities v (particle mass `mass`), as
 * sim/observe.c (weights 1/n; V the bulk velocity, C = v - V):
 *   T = (m/3) <|C|^2>, T_raw = (m/3) <|v|^2>, (ux, uy, uz) = V,
 *   P_ij = m <C_i C_j>, q = (m/2) <|C|^2 C>,
 *   a2 = <|C|^4>/(15 (T/m)^2) - 1, a3 = -<|C|^6>/(105 (T/m)^3) + 1 + 3 a2. */
static inline void gp_observe(const double (*v)[3], size_t n, double mass, double out[GP_NOBS])
{
    const double w = 1.0 / (double)n;
    double V[3] = {0, 0, 0}, v2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        V[0] += v[i][0];
        V[1] += v[i][1];
        V[2] += v[i][2];
        v2 += v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2];
    }
    for (int k = 0; k < 3; k++)
        V[k] *= w;
    double P[6] = {0, 0, 0, 0, 0, 0}, q[3] = {0, 0, 0}, c4 = 0.0, c6 = 0.0;
    for (size_t i = 0; i < n; i++) {   /* central moments in a pass of their own */
        const double c[3] = {v[i][0] - V[0], v[i][1] - V[1], v[i][2] - V[2]};
        const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        P[0] += c[0] * c[0];
        P[1] += c[1] * c[1];
        P[2] += c[2] * c[2];
        P[3] += c[0] * c[1];
        P[4] += c[0] * c[2];
        P[5] += c[1] * c[2];
        for (int k = 0; k < 3; k++)
            q[k] += c2 * c[k];
        c4 += c2 * c2;
        c6 += c2 * c2 * c2;
    }
    const double T = mass * w * (P[0] + P[1] + P[2]) / 3.0, theta = T / mass;
    out[GP_T] = T;
    out[GP_T_RAW] = mass * w * v2 / 3.0;
    for (int k = 0; k < 3; k++) {
        out[GP_UX + k] = V[k];
        out[GP_QX + k] = 0.5 * mass * w * q[k];
    }
    for (int k = 0; k < 6; k++)
        out[GP_PXX + k] = mass * w * P[k];
    out[GP_A2] = w * c4 / (15.0 * theta * theta) - 1.0;
    out[GP_A3] = -w * c6 / (105.0 * theta * theta * theta) + 1.0 + 3.0 * out[GP_A2];
}

/* ------------------------------------------------------ random numbers */

/* xoshiro256** (Blackman and Vigna), seeded by splitmix64 from (seed,
 * stream): give each ensemble its own stream. */
typedef struct gp_rng {
    uint64_t s[4];
} gp_rng;

static inline uint64_t gp_splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

static inline void gp_rng_seed(gp_rng *r, uint64_t seed, uint64_t stream)
{
    uint64_t x = seed ^ gp_splitmix64(&stream);
    for (int k = 0; k < 4; k++)
        r->s[k] = gp_splitmix64(&x);
}

static inline uint64_t gp_rng_next(gp_rng *r)
{
    uint64_t *s = r->s;
    const uint64_t x = s[1] * 5, result = ((x << 7) | (x >> 57)) * 9, t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = (s[3] << 45) | (s[3] >> 19);
    return result;
}

/* Uniform on [0, 1), 53 bits. */
static inline double gp_rng_uniform(gp_rng *r)
{
    return (double)(gp_rng_next(r) >> 11) * 0x1p-53;
}

/* Uniform on 0 .. n - 1, unbiased (n >= 1). */
static inline uint64_t gp_rng_index(gp_rng *r, uint64_t n)
{
    const uint64_t floor = (0 - n) % n;   /* 2^64 mod n draws are rejected */
    uint64_t x;
    do
        x = gp_rng_next(r);
    while (x < floor);
    return x % n;
}

/* Standard normal (Marsaglia's polar method; the second value is dropped). */
static inline double gp_rng_normal(gp_rng *r)
{
    double x, y, s;
    do {
        x = 2.0 * gp_rng_uniform(r) - 1.0;
        y = 2.0 * gp_rng_uniform(r) - 1.0;
        s = x * x + y * y;
    } while (s >= 1.0 || s == 0.0);
    return x * sqrt(-2.0 * log(s) / s);
}

/* Uniform on the unit sphere (Marsaglia 1972). */
static inline void gp_rng_unit_vector(gp_rng *r, double e[3])
{
    double x, y, s;
    do {
        x = 2.0 * gp_rng_uniform(r) - 1.0;
        y = 2.0 * gp_rng_uniform(r) - 1.0;
        s = x * x + y * y;
    } while (s >= 1.0);
    const double f = 2.0 * sqrt(1.0 - s);
    e[0] = f * x;
    e[1] = f * y;
    e[2] = 1.0 - 2.0 * s;
}

/* ------------------------------------------------------ steady quantities */

#define GP_STEADY_SCALARS 10
static const char *const gp_steady_scalar[GP_STEADY_SCALARS] = {
    "T", "a2", "a3", "c1", "c3", "mu2", "mu4", "mu4_white", "mu4_gaussian", "mu4_nongaussian"};

/* The [steady] section (sim/steady.h): each ensemble's time average over
 * the output times t >= from of
 *   T          the centred temperature
 *   a2, a3     (4/15) <c^4> - 1, -(8/105) <c^6> + 1 + 3 a2, c = C/v0, v0 = sqrt(2T/m)
 *   c1, c3     <|c|>, <|c|^3>
 *   mu2, mu4   v0^{-p-1} (1/N') sum Phi_p(C_i, C_j) over N' = pairs random pairs
 *              i != j (paper C Eqs. (65)-(67)), alpha = collisions.restitution;
 *              NaN (not reported) when pairs = 0
 *   mu4_white = 5 mu2, mu4_gaussian = 5 (1 + a2) mu2, mu4_nongaussian = 2 mu2 c3/c1
 *   f_0 .. f_{bins-1}  the fraction of particles with k D <= |c| < (k+1) D,
 *              D = c_max/bins, over the shell's volume (4 pi/3)((k+1)^3 - k^3) D^3 */
typedef struct gp_steady {
    int active;          /* the scene has [steady] */
    double from, c_max, alpha;
    size_t pairs, bins;
} gp_steady;

/* Read [steady] (from, pairs, bins, c_max) and collisions.restitution. */
static inline void gp_steady_init(gp_steady *st, gp_scene *s)
{
    st->active = gp_present(s, "steady");
    st->from = gp_real(s, "steady.from");
    st->pairs = (size_t)gp_count(s, "steady.pairs");
    st->bins = (size_t)gp_count(s, "steady.bins");
    st->c_max = gp_real(s, "steady.c_max");
    st->alpha = gp_real(s, "collisions.restitution");
}

/* The number of steady quantities: 0 without [steady]. */
static inline size_t gp_steady_count(const gp_steady *st)
{
    return st->active ? GP_STEADY_SCALARS + st->bins : 0;
}

static inline const char *gp_steady_name(size_t k, char buf[32])
{
    if (k < GP_STEADY_SCALARS)
        return gp_steady_scalar[k];
    snprintf(buf, 32, "f_%zu", k - GP_STEADY_SCALARS);
    return buf;
}

/* Whether output time t is sampled: t >= steady.from. */
static inline int gp_steady_due(const gp_steady *st, double t)
{
    return st->active && t >= st->from;
}

/* Add one sample of every quantity of the n velocities v to
 * sum[gp_steady_count(st)] (pairs drawn from rng). */
static inline void gp_steady_sample(const gp_steady *st, const double (*v)[3], size_t n,
                                    double mass, gp_rng *rng, double *sum)
{
    const double w = 1.0 / (double)n;
    double V[3] = {0, 0, 0}, s2 = 0.0;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            V[k] += v[i][k];
    for (int k = 0; k < 3; k++)
        V[k] *= w;
    for (size_t i = 0; i < n; i++) {
        const double c[3] = {v[i][0] - V[0], v[i][1] - V[1], v[i][2] - V[2]};
        s2 += c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    }
    const double theta = w * s2 / 3.0, inv_v0 = 1.0 / sqrt(2.0 * theta);   /* T/m, 1/v0 */
    const double delta = st->bins > 0 ? st->c_max / (double)st->bins : 1.0;
    const double shell = 4.0 * M_PI / 3.0 * delta * delta * delta * (double)n;
    double m1 = 0.0, m3 = 0.0, m4 = 0.0, m6 = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double c[3] = {v[i][0] - V[0], v[i][1] - V[1], v[i][2] - V[2]};
        const double c2 = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) * inv_v0 * inv_v0;
        const double cn = sqrt(c2);
        m1 += cn;
        m3 += c2 * cn;
        m4 += c2 * c2;
        m6 += c2 * c2 * c2;
        if (st->bins > 0 && cn < st->c_max) {
            size_t b = (size_t)(cn / delta);
            if (b >= st->bins)   /* round-off at the last edge */
                b = st->bins - 1;
            const double kb = (double)b;   /* the shell's volume: (k+1)^3 - k^3 */
            sum[GP_STEADY_SCALARS + b] += 1.0 / (shell * (3.0 * kb * kb + 3.0 * kb + 1.0));
        }
    }
    m1 *= w, m3 *= w, m4 *= w, m6 *= w;
    const double a2 = 4.0 / 15.0 * m4 - 1.0, a3 = -8.0 / 105.0 * m6 + 1.0 + 3.0 * a2;
    double mu2 = NAN, mu4 = NAN;
    if (st->pairs > 0) {   /* paper C Eqs. (65)-(67) */
        const double al = st->alpha, al2 = al * al;
        double s_2 = 0.0, s_4 = 0.0;
        for (size_t q = 0; q < st->pairs; q++) {
            const size_t i = (size_t)gp_rng_index(rng, n);
            size_t j = (size_t)gp_rng_index(rng, n - 1);
            j += (j >= i);
            double g[3], G[3];
            for (int k = 0; k < 3; k++) {
                const double ci = v[i][k] - V[k], cj = v[j][k] - V[k];
                g[k] = ci - cj;
                G[k] = 0.5 * (ci + cj);
            }
            const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
            const double G2 = G[0] * G[0] + G[1] * G[1] + G[2] * G[2];
            const double gG = g[0] * G[0] + g[1] * G[1] + g[2] * G[2], gn = sqrt(g2);
            s_2 += M_PI * (1.0 - al2) / 8.0 * g2 * gn;
            s_4 += 0.25 * M_PI * gn
                   * (5.0 * (1.0 - al2) / 3.0 * g2 * G2 + (1.0 - al2) * (2.0 + al2) / 12.0 * g2 * g2
                      + (3.0 - al) * (1.0 + al) * (gG * gG - g2 * G2 / 3.0));
        }
        mu2 = s_2 / (double)st->pairs * pow(inv_v0, 3.0);
        mu4 = s_4 / (double)st->pairs * pow(inv_v0, 5.0);
    }
    const double one[GP_STEADY_SCALARS] = {
        mass * theta, a2, a3, m1, m3, mu2, mu4,
        5.0 * mu2, 5.0 * (1.0 + a2) * mu2, 2.0 * mu2 * m3 / m1};
    for (int k = 0; k < GP_STEADY_SCALARS; k++)
        sum[k] += one[k];
}

/* ------------------------------------------------------------ the result */

/* Count, mean and sum of squared deviations of a stream (Welford). */
typedef struct gp_moments {
    double count, mean, m2;
} gp_moments;

static inline void gp_moments_add(gp_moments *a, double x)
{
    a->count += 1.0;
    const double d = x - a->mean;
    a->mean += d / a->count;
    a->m2 += d * (x - a->mean);
}

/* The sample variance, divisor N - 1 (0 for one value). */
static inline double gp_moments_var(const gp_moments *a)
{
    return a->count > 1.0 ? a->m2 / (a->count - 1.0) : 0.0;
}

typedef struct gp_result {
    size_t outputs, nsteady;
    unsigned long long n, ensembles;
    gp_moments *obs;       /* [outputs][GP_NOBS] */
    gp_moments *steady;    /* [nsteady] */
    int report[GP_NOBS];   /* 1 (the default): write the observable's columns */
} gp_result;

/* What the result file says beside the numbers; a negative count or time is
 * not written. */
typedef struct gp_result_info {
    const char *solver;          /* "# solver = ", or NULL */
    double cpu_seconds;
    long long events, violations;
    int declare_substitutions;   /* write "# substituted = ..." (newer gdsmc only) */
} gp_result_info;

/* For the scene's output times and ensembles, with the steady quantities
 * of st (NULL: none). */
static inline void gp_result_init(gp_result *r, gp_scene *s, const gp_steady *st)
{
    memset(r, 0, sizeof *r);
    r->outputs = (size_t)gp_count(s, "scene.outputs");
    r->n = gp_count(s, "particles.n");
    r->ensembles = gp_count(s, "particles.ensembles");
    r->nsteady = st ? gp_steady_count(st) : 0;
    r->obs = calloc(r->outputs * GP_NOBS, sizeof *r->obs);
    r->steady = calloc(r->nsteady + 1, sizeof *r->steady);
    if (r->obs == NULL || r->steady == NULL)
        gp_fail("out of memory");
    for (int k = 0; k < GP_NOBS; k++)
        r->report[k] = 1;
}

/* One ensemble's observables at output m. */
static inline void gp_result_add(gp_result *r, size_t m, const double obs[GP_NOBS])
{
    for (size_t k = 0; k < GP_NOBS; k++)
        gp_moments_add(&r->obs[m * GP_NOBS + k], obs[k]);
}

/* One ensemble's steady quantities: its sums over `samples` output times
 * (gp_steady_sample), turned into time averages here. */
static inline void gp_result_add_steady(gp_result *r, const double *sum, size_t samples)
{
    if (r->nsteady > 0 && samples == 0)
        gp_fail("no steady samples: no output time t >= steady.from");
    for (size_t k = 0; k < r->nsteady; k++)
        gp_moments_add(&r->steady[k], sum[k] / (double)samples);
}

static inline int gp_finite(const gp_moments *a)
{
    return isfinite(a->mean) && isfinite(a->m2);
}

/* Write the result file at path (version 1).  An observable is written when
 * report[k] is set and it is finite at every output time; a steady quantity
 * when it is finite.  Stops with exit status 2 when an output lacks an
 * ensemble or the file cannot be written. */
static inline void gp_result_write(const gp_result *r, gp_scene *s, const char *path,
                            const gp_result_info *info)
{
    int put[GP_NOBS];
    for (size_t k = 0; k < GP_NOBS; k++) {
        put[k] = r->report[k];
        for (size_t m = 0; m < r->outputs; m++)
            put[k] &= gp_finite(&r->obs[m * GP_NOBS + k]);
    }
    for (size_t m = 0; m < r->outputs; m++)
        if (r->obs[m * GP_NOBS].count != (double)r->ensembles)
            gp_fail("output %zu: %.0f ensembles of %llu", m, r->obs[m * GP_NOBS].count,
                    r->ensembles);
    FILE *f = fopen(path, "w");
    if (f == NULL)
        gp_fail("%s: cannot write the result", path);
    fprintf(f, "# gdsmc-result %d\n", GP_PROTOCOL_VERSION);
    if (info && info->solver)
        fprintf(f, "# solver = %s\n", info->solver);
    fprintf(f, "# n = %llu\n# ensembles = %llu\n", r->n, r->ensembles);
    if (info && info->cpu_seconds >= 0.0)
        fprintf(f, "# cpu_seconds = %.17g\n", info->cpu_seconds);
    if (info && info->events >= 0)
        fprintf(f, "# events = %lld\n", info->events);
    if (info && info->violations >= 0)
        fprintf(f, "# violations = %lld\n", info->violations);
    if (info && info->declare_substitutions && s->substituted[0])
        fprintf(f, "# substituted = %s\n", s->substituted);
    fputs("t", f);
    for (int k = 0; k < GP_NOBS; k++)
        if (put[k])
            fprintf(f, ",%s,%s_var", gp_obs_name[k], gp_obs_name[k]);
    fputc('\n', f);
    for (size_t m = 0; m < r->outputs; m++) {
        fprintf(f, "%.17g", gp_output_time(s, m));
        for (size_t k = 0; k < GP_NOBS; k++)
            if (put[k])
                fprintf(f, ",%.17g,%.17g", r->obs[m * GP_NOBS + k].mean,
                        gp_moments_var(&r->obs[m * GP_NOBS + k]));
        fputc('\n', f);
    }
    if (r->nsteady > 0)
        fputs("# steady\nname,mean,var\n", f);
    for (size_t k = 0; k < r->nsteady; k++) {
        char buf[32];
        if (gp_finite(&r->steady[k]))
            fprintf(f, "%s,%.17g,%.17g\n", gp_steady_name(k, buf), r->steady[k].mean,
                    gp_moments_var(&r->steady[k]));
    }
    if (ferror(f) | (fclose(f) != 0))
        gp_fail("%s: cannot write the result", path);
}

static inline void gp_result_free(gp_result *r)
{
    free(r->obs);
    free(r->steady);
    memset(r, 0, sizeof *r);
}

/* CPU seconds of the process so far. */
static inline double gp_cpu_seconds(void)
{
    return (double)clock() / (double)CLOCKS_PER_SEC;
}

#endif
