/* Scene files (docs/scenes.md): INI text -> validated sim_scene, with inih.
 *
 * Design.  One table, `keys`, describes every key: section, name, kind (text,
 * real, vector, count, word), the field's offset in sim_scene and its allowed
 * range or words; the messages' "(allowed ...)" text is generated from the
 * same entry, so a range and its message cannot drift apart.  Keys from the
 * file and from overrides go through the one function apply(); checks that
 * involve two keys run once at the end (check_scene()).
 *
 * inih 55 (Debian) does not pass line numbers to the handler, so inih reads
 * through our own reader, which hands it exactly one line per call and counts
 * them: when the handler runs, ctx->line is the line of the key.  The reader
 * also drops leading whitespace (so an indented key is never taken for a
 * Python-style continuation of the previous value), checks section headers
 * itself (an unknown section is an error even when it holds no keys; its
 * presence sets the section's present flag) and refuses lines longer than
 * inih's buffer instead of letting inih split them.
 *
 * Work happens on a copy: *scene is written only on success.
 */
#include "scene_ini.h"
#include "text.h"

#include <ctype.h>
#include <errno.h>
#include <ini.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FILE_BYTES (1u << 20)

/* ---- the key table --------------------------------------------------- */

enum { S_SCENE, S_PARTICLES, S_COLLISIONS, S_HEATING, S_BACKGROUND, S_SHEAR, S_HEAT_FLUX,
       S_BATH, S_STEADY };

typedef struct section_desc {
    const char *name;
    int has_present;
    size_t present;  /* offset of the int present flag */
} section_desc;

#define OFF(member) offsetof(sim_scene, member)

static const section_desc sections[] = {
    {"scene", 0, 0},
    {"particles", 0, 0},
    {"collisions", 1, OFF(collisions.present)},
    {"heating", 1, OFF(heating.present)},
    {"background", 1, OFF(background.present)},
    {"shear", 1, OFF(shear.present)},
    {"heat-flux", 1, OFF(heat_flux.present)},
    {"bath", 1, OFF(bath.present)},
    {"steady", 1, OFF(steady.present)},
};
#define NSECTIONS (sizeof sections / sizeof sections[0])

typedef enum key_kind { K_TEXT, K_REAL, K_VEC3, K_SIZE, K_U64, K_WORD } key_kind;

enum { LO_GT = 1, LO_GE = 2, HI_LE = 4, HI_LT = 8 };  /* bounds of a K_REAL */

typedef struct word_desc {
    const char *word;
    int value;
} word_desc;

typedef struct key_desc {
    int section;
    const char *name;
    key_kind kind;
    size_t offset;
    unsigned bounds;          /* K_REAL: x > lo or x >= lo, x <= hi */
    double lo, hi;
    uint64_t min, max;        /* K_SIZE, K_U64 */
    const word_desc *words;   /* K_WORD, {NULL} terminated; field is an enum or int */
    size_t size;              /* K_TEXT: buffer size */
} key_desc;

/* Enum fields are written as int. */
_Static_assert(sizeof(sim_scheme) == sizeof(int), "enum size");
_Static_assert(sizeof(sim_splitting) == sizeof(int), "enum size");
_Static_assert(sizeof(sim_observation) == sizeof(int), "enum size");
_Static_assert(sizeof(sim_initial) == sizeof(int), "enum size");
_Static_assert(sizeof(sim_kernel_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(sim_collision_model) == sizeof(int), "enum size");
_Static_assert(sizeof(sim_collision_rule) == sizeof(int), "enum size");
_Static_assert(sizeof(sim_heating_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(sim_shear_boundary) == sizeof(int), "enum size");
_Static_assert(sizeof(sim_slab_pairs) == sizeof(int), "enum size");

static const word_desc scheme_words[] = {
    {"jump", SIM_SCHEME_JUMP}, {"timestep", SIM_SCHEME_TIMESTEP}, {NULL, 0}};
static const word_desc splitting_words[] = {
    {"euler", SIM_SPLIT_EULER}, {"strang", SIM_SPLIT_STRANG}, {NULL, 0}};
static const word_desc observation_words[] = {
    {"sampled", SIM_OBSERVE_SAMPLED}, {"conditional", SIM_OBSERVE_CONDITIONAL}, {NULL, 0}};
static const word_desc initial_words[] = {{"maxwellian", SIM_INITIAL_MAXWELLIAN},
                                          {"two-maxwellians", SIM_INITIAL_TWO_MAXWELLIANS},
                                          {"shell", SIM_INITIAL_SHELL},
                                          {NULL, 0}};
static const word_desc bool_words[] = {{"true", 1}, {"false", 0}, {NULL, 0}};
static const word_desc kernel_words[] = {{"maxwell", SIM_KERNEL_MAXWELL},
                                         {"vhs", SIM_KERNEL_VHS},
                                         {"hard-spheres", SIM_KERNEL_HARD_SPHERES},
                                         {NULL, 0}};
static const word_desc background_kernel_words[] = {
    {"maxwell", SIM_KERNEL_MAXWELL}, {"hard-spheres", SIM_KERNEL_HARD_SPHERES}, {NULL, 0}};
static const word_desc model_words[] = {
    {"ihs", SIM_MODEL_IHS}, {"ehs", SIM_MODEL_EHS}, {NULL, 0}};
static const word_desc rule_words[] = {
    {"contact", SIM_RULE_CONTACT}, {"relative-speed", SIM_RULE_RELATIVE_SPEED}, {NULL, 0}};
static const word_desc heating_words[] = {{"white-noise", SIM_HEATING_WHITE_NOISE},
                                          {"gaussian", SIM_HEATING_GAUSSIAN},
                                          {"non-gaussian", SIM_HEATING_NON_GAUSSIAN},
                                          {NULL, 0}};
static const word_desc boundary_words[] = {{"homogeneous", SIM_SHEAR_HOMOGENEOUS},
                                           {"lees-edwards", SIM_SHEAR_LEES_EDWARDS},
                                           {NULL, 0}};
static const word_desc candidates_words[] = {{"unbiased", SIM_SLAB_PAIRS_UNBIASED},
                                             {"paper", SIM_SLAB_PAIRS_PAPER},
                                             {NULL, 0}};

#define TEXT(s, k, m) {.section = s, .name = k, .kind = K_TEXT, .offset = OFF(m), \
                       .size = sizeof(((sim_scene *)0)->m)}
#define REAL(s, k, m, b, l, h) {.section = s, .name = k, .kind = K_REAL, .offset = OFF(m), \
                                .bounds = b, .lo = l, .hi = h}
#define POSITIVE(s, k, m) REAL(s, k, m, LO_GT, 0.0, 0.0)
#define FINITE(s, k, m) REAL(s, k, m, 0, 0.0, 0.0)
#define VEC3(s, k, m) {.section = s, .name = k, .kind = K_VEC3, .offset = OFF(m)}
#define COUNT(s, k, m, a, b) {.section = s, .name = k, .kind = K_SIZE, .offset = OFF(m), \
                              .min = a, .max = b}
#define WORDS(s, k, m, w) {.section = s, .name = k, .kind = K_WORD, .offset = OFF(m), .words = w}

static const key_desc keys[] = {
    TEXT(S_SCENE, "title", title),
    WORDS(S_SCENE, "scheme", scheme, scheme_words),
    POSITIVE(S_SCENE, "dt", dt),
    WORDS(S_SCENE, "splitting", splitting, splitting_words),
    WORDS(S_SCENE, "step_follows_temperature", step_follows_temperature, bool_words),
    WORDS(S_SCENE, "observation", observation, observation_words),
    POSITIVE(S_SCENE, "t_end", t_end),
    COUNT(S_SCENE, "outputs", outputs, 2, 10000000),
    {.section = S_SCENE, .name = "seed", .kind = K_U64, .offset = OFF(seed), .min = 0,
     .max = UINT64_MAX},

    COUNT(S_PARTICLES, "n", particles.n, 2, 1000000000),
    COUNT(S_PARTICLES, "ensembles", particles.ensembles, 1, SIZE_MAX),
    WORDS(S_PARTICLES, "initial", particles.initial, initial_words),
    POSITIVE(S_PARTICLES, "mass", particles.maxwellian.mass),
    POSITIVE(S_PARTICLES, "temperature", particles.maxwellian.temperature),
    VEC3(S_PARTICLES, "velocity", particles.maxwellian.velocity),
    REAL(S_PARTICLES, "fraction", particles.fraction, LO_GE | HI_LE, 0.0, 1.0),
    POSITIVE(S_PARTICLES, "mass1", particles.first.mass),
    VEC3(S_PARTICLES, "velocity1", particles.first.velocity),
    POSITIVE(S_PARTICLES, "temperature1", particles.first.temperature),
    POSITIVE(S_PARTICLES, "mass2", particles.second.mass),
    VEC3(S_PARTICLES, "velocity2", particles.second.velocity),
    POSITIVE(S_PARTICLES, "temperature2", particles.second.temperature),
    WORDS(S_PARTICLES, "zero_momentum", particles.zero_momentum, bool_words),
    REAL(S_PARTICLES, "density_wave", particles.density_wave, LO_GE | HI_LT, 0.0, 1.0),
    FINITE(S_PARTICLES, "flow_wave", particles.flow_wave),

    WORDS(S_COLLISIONS, "kernel", collisions.kernel, kernel_words),
    REAL(S_COLLISIONS, "exponent", collisions.exponent, LO_GE | HI_LE, 0.0, 1.0),
    POSITIVE(S_COLLISIONS, "constant", collisions.constant),
    POSITIVE(S_COLLISIONS, "rate", collisions.rate),
    REAL(S_COLLISIONS, "restitution", collisions.restitution, LO_GT | HI_LE, 0.0, 1.0),
    WORDS(S_COLLISIONS, "model", collisions.model, model_words),
    POSITIVE(S_COLLISIONS, "beta", collisions.beta),
    WORDS(S_COLLISIONS, "rule", collisions.rule, rule_words),

    WORDS(S_HEATING, "type", heating.type, heating_words),
    FINITE(S_HEATING, "strength", heating.strength), /* sign checked in check_scene() */
    WORDS(S_HEATING, "keep_temperature", heating.keep_temperature, bool_words),

    POSITIVE(S_BACKGROUND, "density", background.density),
    POSITIVE(S_BACKGROUND, "mass", background.mass),
    POSITIVE(S_BACKGROUND, "temperature", background.temperature),
    VEC3(S_BACKGROUND, "velocity", background.velocity),
    WORDS(S_BACKGROUND, "kernel", background.kernel, background_kernel_words),
    POSITIVE(S_BACKGROUND, "constant", background.constant),

    FINITE(S_SHEAR, "rate", shear.rate),
    WORDS(S_SHEAR, "boundary", shear.boundary, boundary_words),
    POSITIVE(S_SHEAR, "length", shear.length),
    COUNT(S_SHEAR, "layers", shear.layers, 1, SIM_SLAB_LAYERS_MAX),
    WORDS(S_SHEAR, "candidates", shear.candidates, candidates_words),
    COUNT(S_SHEAR, "pairs", shear.pairs, 0, SIZE_MAX),

    FINITE(S_HEAT_FLUX, "strength", heat_flux.strength),

    POSITIVE(S_BATH, "friction", bath.friction),
    POSITIVE(S_BATH, "temperature", bath.temperature),

    REAL(S_STEADY, "from", steady.from, LO_GE, 0.0, 0.0),
    COUNT(S_STEADY, "pairs", steady.pairs, 0, SIZE_MAX),
    COUNT(S_STEADY, "bins", steady.bins, 0, 100000),
    POSITIVE(S_STEADY, "c_max", steady.c_max),
};
#define NKEYS (sizeof keys / sizeof keys[0])
_Static_assert(NKEYS <= SIM_SCENE_MAX_KEYS, "every key must fit in sim_scene.keys");

/* ---- parser state and error recording -------------------------------- */

typedef struct parse_ctx {
    sim_scene scene;       /* work copy */
    const char *name;      /* file name for messages */
    const char *pos;       /* reader: rest of the text */
    int line;              /* line being parsed; -1 while applying an override */
    const char *override;  /* override being applied */
    int failed;
    sim_status status;
    sim_error err;
    int err_line;
    const char *err_override;
} parse_ctx;

/* Record the first error only, at the current position. */
__attribute__((format(printf, 4, 5)))
static sim_status fail(parse_ctx *c, sim_status status, const char *key, const char *fmt, ...)
{
    if (c->failed)
        return c->status;
    char text[sizeof c->err.msg];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    c->failed = 1;
    c->status = sim_error_set(&c->err, status, key, "%s", text);
    c->err_line = c->line;
    c->err_override = c->override;
    return status;
}

static const char syntax_msg[] = "syntax error (expected key = value or [section])";

/* "FILE:LINE: key: msg", "FILE: key: msg" (line 0) or "--set OVERRIDE: key: msg". */
static void format_at(const parse_ctx *c, char *msg, size_t msglen)
{
    const char *key = c->err.key, *sep = key[0] ? ": " : "";
    if (c->err_override)
        snprintf(msg, msglen, "--set %s: %s%s%s", c->err_override, key, sep, c->err.msg);
    else if (c->err_line > 0)
        snprintf(msg, msglen, "%s:%d: %s%s%s", c->name, c->err_line, key, sep, c->err.msg);
    else
        snprintf(msg, msglen, "%s: %s%s%s", c->name, key, sep, c->err.msg);
}

/* ---- tables to text -------------------------------------------------- */

static void append(char *buf, size_t len, const char *s)
{
    size_t used = strlen(buf);
    if (used < len)
        snprintf(buf + used, len - used, "%s", s);
}

static void section_list(char *buf, size_t len)
{
    buf[0] = '\0';
    for (size_t i = 0; i < NSECTIONS; i++) {
        append(buf, len, i ? ", " : "");
        append(buf, len, sections[i].name);
    }
}

static void key_list(int section, char *buf, size_t len)
{
    buf[0] = '\0';
    for (size_t i = 0; i < NKEYS; i++)
        if (keys[i].section == section) {
            append(buf, len, buf[0] ? ", " : "");
            append(buf, len, keys[i].name);
        }
}

/* The "allowed" text of a key: "0 < restitution <= 1", "maxwell, vhs", ... */
static void describe(const key_desc *d, char *buf, size_t len)
{
    switch (d->kind) {
    case K_TEXT:
        snprintf(buf, len, "at most %zu characters", d->size - 1);
        break;
    case K_REAL: {
        const char *lo = (d->bounds & LO_GT) ? "<" : "<=";
        if ((d->bounds & (LO_GT | LO_GE)) && (d->bounds & (HI_LE | HI_LT)))
            snprintf(buf, len, "%g %s %s %s %g", d->lo, lo, d->name,
                     (d->bounds & HI_LT) ? "<" : "<=", d->hi);
        else if (d->bounds & (LO_GT | LO_GE))
            snprintf(buf, len, "%s %s %g", d->name, (d->bounds & LO_GT) ? ">" : ">=", d->lo);
        else
            snprintf(buf, len, "any finite number");
        break;
    }
    case K_VEC3:
        snprintf(buf, len, "three finite numbers separated by spaces");
        break;
    case K_SIZE:
    case K_U64:
        if (d->kind == K_SIZE && d->max == SIZE_MAX)
            snprintf(buf, len, "%s >= %llu", d->name, (unsigned long long)d->min);
        else
            snprintf(buf, len, "%llu <= %s <= %llu", (unsigned long long)d->min, d->name,
                     (unsigned long long)d->max);
        break;
    case K_WORD:
        buf[0] = '\0';
        for (const word_desc *w = d->words; w->word; w++) {
            append(buf, len, w == d->words ? "" : ", ");
            append(buf, len, w->word);
        }
        break;
    }
}

/* ---- value parsers: NULL on success, else what is wrong -------------- */

static const char *parse_real(const char *s, double *out, const char **end_out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s)
        return "is not a number";
    if (end_out)
        *end_out = end;
    else {
        while (isspace((unsigned char)*end))
            end++;
        if (*end)
            return "is not a number";
    }
    if (errno == ERANGE)
        return "is out of range of a double";
    if (!isfinite(v))
        return "is not a finite number";
    *out = v;
    return NULL;
}

static const char *parse_vec3(const char *s, double v[3])
{
    const char *p = s;
    for (int i = 0; i < 3; i++) {
        if (i > 0 && !isspace((unsigned char)*p))
            return "is not three numbers";
        const char *why = parse_real(p, &v[i], &p);
        if (why)
            return strcmp(why, "is not a number") == 0 ? "is not three numbers"
                                                       : "is not three finite numbers";
    }
    while (isspace((unsigned char)*p))
        p++;
    return *p ? "is not three numbers" : NULL;
}

static const char *parse_count(const char *s, uint64_t *out)
{
    if (s[0] == '-' && isdigit((unsigned char)s[1]))
        return "is negative";
    if (!isdigit((unsigned char)s[0]))  /* no sign, no leading space */
        return "is not a whole number";
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    while (isspace((unsigned char)*end))
        end++;
    if (*end)
        return "is not a whole number";
    if (errno == ERANGE)
        return "is out of range";
    *out = v;
    return NULL;
}

/* ---- applying one key ------------------------------------------------ */

static int find_section(const char *name)
{
    for (size_t i = 0; i < NSECTIONS; i++)
        if (strcmp(sections[i].name, name) == 0)
            return (int)i;
    return -1;
}

static void mark_present(sim_scene *s, int section)
{
    if (sections[section].has_present)
        *(int *)((char *)s + sections[section].present) = 1;
}

static void record_key(sim_scene *s, const char *full, int line)
{
    for (size_t i = 0; i < s->nkeys; i++)
        if (strcmp(s->keys[i].key, full) == 0) {
            s->keys[i].line = line;
            return;
        }
    size_t len = strlen(full);  /* known keys are short; the asserts make room */
    if (s->nkeys < SIM_SCENE_MAX_KEYS && len < sizeof s->keys[0].key) {
        memcpy(s->keys[s->nkeys].key, full, len + 1);
        s->keys[s->nkeys++].line = line;
    }
}

static sim_status set_value(parse_ctx *c, const key_desc *d, const char *full, const char *value)
{
    char *field = (char *)&c->scene + d->offset;
    char allowed[160];
    const char *why = "is not valid";
    describe(d, allowed, sizeof allowed);

    switch (d->kind) {
    case K_TEXT: {
        size_t len = strlen(value);
        if (len >= d->size)
            return fail(c, SIM_EINVAL, full, "is too long: %zu characters (allowed %s)", len,
                        allowed);
        memcpy(field, value, len + 1);
        return SIM_OK;
    }
    case K_REAL: {
        double v;
        if ((why = parse_real(value, &v, NULL)))
            break;
        if (((d->bounds & LO_GT) && !(v > d->lo)) || ((d->bounds & LO_GE) && !(v >= d->lo)) ||
            ((d->bounds & HI_LE) && !(v <= d->hi)) || ((d->bounds & HI_LT) && !(v < d->hi)))
            return fail(c, SIM_EINVAL, full, "'%s' is out of range (allowed %s)", value, allowed);
        memcpy(field, &v, sizeof v);
        return SIM_OK;
    }
    case K_VEC3: {
        double v[3];
        if ((why = parse_vec3(value, v)))
            break;
        memcpy(field, v, sizeof v);
        return SIM_OK;
    }
    case K_SIZE:
    case K_U64: {
        uint64_t v;
        if ((why = parse_count(value, &v)))
            break;
        if (v < d->min || v > d->max)
            return fail(c, SIM_EINVAL, full, "'%s' is out of range (allowed %s)", value, allowed);
        if (d->kind == K_SIZE) {
            size_t z = (size_t)v;
            memcpy(field, &z, sizeof z);
        } else
            memcpy(field, &v, sizeof v);
        return SIM_OK;
    }
    case K_WORD:
        for (const word_desc *w = d->words; w->word; w++)
            if (strcmp(w->word, value) == 0) {
                memcpy(field, &w->value, sizeof w->value);
                return SIM_OK;
            }
        why = "is unknown";
        break;
    }
    return fail(c, SIM_EINVAL, full, "'%s' %s (allowed %s)", value, why, allowed);
}

static sim_status unknown_section(parse_ctx *c, const char *section)
{
    char list[128], key[80];
    snprintf(key, sizeof key, "[%s]", section);
    section_list(list, sizeof list);
    return fail(c, SIM_EINVAL, key, "unknown section (allowed %s)", list);
}

/* Apply section.name = value at the current position (file line or override). */
static sim_status apply(parse_ctx *c, const char *section, const char *name, const char *value)
{
    char list[256], full[96];
    if (value == NULL || name[0] == '\0')
        return fail(c, SIM_EINVAL, "", syntax_msg);
    if (section[0] == '\0') {
        section_list(list, sizeof list);
        return fail(c, SIM_EINVAL, name, "key outside any section (allowed sections %s)", list);
    }
    int s = find_section(section);
    if (s < 0)
        return unknown_section(c, section);
    snprintf(full, sizeof full, "%s.%s", section, name);
    const key_desc *d = NULL;
    for (size_t i = 0; i < NKEYS && !d; i++)
        if (keys[i].section == s && strcmp(keys[i].name, name) == 0)
            d = &keys[i];
    if (!d) {
        key_list(s, list, sizeof list);
        return fail(c, SIM_EINVAL, full, "unknown key (allowed %s)", list);
    }
    int first = sim_scene_key_line(&c->scene, full);
    if (c->line > 0 && first > 0)
        return fail(c, SIM_EINVAL, full, "set twice (first at line %d)", first);
    sim_status st = set_value(c, d, full, value);
    if (st != SIM_OK)
        return st;
    mark_present(&c->scene, s);
    record_key(&c->scene, full, c->line);
    return SIM_OK;
}

/* ---- inih glue ------------------------------------------------------- */

static int handler(void *user, const char *section, const char *name, const char *value)
{
    parse_ctx *c = user;
    return !c->failed && apply(c, section, name, value) == SIM_OK;
}

/* Hand inih one whole line per call (see the top of the file). */
static char *reader(char *buf, int num, void *stream)
{
    parse_ctx *c = stream;
    if (c->failed || *c->pos == '\0')
        return NULL;
    const char *p = c->pos, *nl = strchr(p, '\n');
    const char *end = nl ? nl + 1 : p + strlen(p);
    c->pos = end;
    c->line++;
    if (c->line == 1 && strncmp(p, "\xEF\xBB\xBF", 3) == 0)
        p += 3;
    while (p < end && *p != '\n' && isspace((unsigned char)*p))
        p++;
    size_t len = (size_t)(end - p);
    if (num < 3 || len > (size_t)num - 1) {
        fail(c, SIM_EINVAL, "", "line too long (allowed at most %d characters)", num - 2);
        return NULL;
    }
    if (*p == '[') {  /* a section header, as inih reads it: up to the first ']' */
        const char *rb = memchr(p, ']', len);
        if (rb) {
            char section[64];
            snprintf(section, sizeof section, "%.*s", (int)(rb - p - 1), p + 1);
            int s = find_section(section);
            if (s < 0) {
                unknown_section(c, section);
                return NULL;
            }
            mark_present(&c->scene, s);
        }
    }
    memcpy(buf, p, len);
    buf[len] = '\0';
    return buf;
}

/* ---- checks across keys ---------------------------------------------- */

static int is_set(const sim_scene *s, const char *key)
{
    return sim_scene_key_line(s, key) != 0;
}

/* The keys of the initial states: two-maxwellians needs all of `two` and
 * refuses `one`; the other initial states refuse `two`. */
static const char *const two[] = {"particles.fraction", "particles.mass1",
                                  "particles.velocity1", "particles.temperature1",
                                  "particles.mass2", "particles.velocity2",
                                  "particles.temperature2"};
static const char *const one[] = {"particles.mass", "particles.temperature",
                                  "particles.velocity"};
#define N_TWO (sizeof two / sizeof two[0])
#define N_ONE (sizeof one / sizeof one[0])

static int in_list(const char *const *list, size_t n, const char *key)
{
    for (size_t i = 0; i < n; i++)
        if (strcmp(list[i], key) == 0)
            return 1;
    return 0;
}

/* Cross-key checks, after the file and the overrides; also sets the exponent
 * that kernel = maxwell (0) or hard-spheres (1) implies. */
static sim_status check_scene(sim_scene *s, sim_error *err)
{
    if (s->scheme == SIM_SCHEME_TIMESTEP && !is_set(s, "scene.dt"))
        return sim_error_set(err, SIM_EINVAL, "scene.scheme",
                             "timestep needs scene.dt (allowed dt > 0)");
    if (s->scheme != SIM_SCHEME_TIMESTEP && is_set(s, "scene.splitting"))
        return sim_error_set(err, SIM_EINVAL, "scene.splitting",
                             "only used with scheme = timestep (scheme is jump)");
    if (s->scheme != SIM_SCHEME_TIMESTEP && s->step_follows_temperature)
        return sim_error_set(err, SIM_EINVAL, "scene.step_follows_temperature",
                             "only used with scheme = timestep (scheme is jump)");
    if (s->observation == SIM_OBSERVE_CONDITIONAL
        && (s->scheme != SIM_SCHEME_JUMP
            || (s->heating.present && s->heating.type != SIM_HEATING_WHITE_NOISE)
            || s->steady.present || s->shear.present || s->heat_flux.present))
        return sim_error_set(err, SIM_EINVAL, "scene.observation",
                             "conditional needs scheme = jump, no heating or white-noise "
                             "heating (it averages over the pending Brownian increments), "
                             "and no [steady], [shear] or [heat-flux] (they observe every "
                             "particle)");

    int mix = s->particles.initial == SIM_INITIAL_TWO_MAXWELLIANS;
    for (size_t i = 0; i < N_TWO; i++) {
        if (!mix && is_set(s, two[i]))
            return sim_error_set(err, SIM_EINVAL, two[i],
                                 "only used with initial = two-maxwellians (initial is %s)",
                                 s->particles.initial == SIM_INITIAL_SHELL ? "shell"
                                                                           : "maxwellian");
        if (mix && !is_set(s, two[i]))
            return sim_error_set(err, SIM_EINVAL, "particles.initial",
                                 "two-maxwellians needs %s (allowed fraction, mass1, velocity1, "
                                 "temperature1, mass2, velocity2, temperature2, all set)",
                                 two[i]);
    }
    for (size_t i = 0; mix && i < N_ONE; i++)
        if (is_set(s, one[i]))
            return sim_error_set(err, SIM_EINVAL, one[i],
                                 "not used with initial = two-maxwellians (allowed the keys "
                                 "ending in 1 and 2)");

    /* docs/theory.md §2.2: maxwell is lambda = 0, hard-spheres lambda = 1, vhs needs lambda. */
    sim_kernel_kind k = s->collisions.kernel;
    int has_exponent = is_set(s, "collisions.exponent");
    if (!has_exponent && k != SIM_KERNEL_VHS)
        s->collisions.exponent = k == SIM_KERNEL_MAXWELL ? 0.0 : 1.0;
    double lambda = s->collisions.exponent;
    if (k == SIM_KERNEL_VHS && !has_exponent)
        return sim_error_set(err, SIM_EINVAL, "collisions.kernel",
                             "vhs needs collisions.exponent (allowed 0 <= exponent <= 1)");
    if ((k == SIM_KERNEL_MAXWELL && lambda != 0.0) ||
        (k == SIM_KERNEL_HARD_SPHERES && lambda != 1.0))
        return sim_error_set(err, SIM_EINVAL, "collisions.exponent",
                             "%g contradicts kernel = %s (allowed %s, or kernel = vhs)", lambda,
                             k == SIM_KERNEL_MAXWELL ? "maxwell" : "hard-spheres",
                             k == SIM_KERNEL_MAXWELL ? "0" : "1");

    if (is_set(s, "collisions.rule")) {   /* docs/theory.md §8.5: only the time step chooses */
        const int slab = s->shear.present && s->shear.boundary == SIM_SHEAR_LEES_EDWARDS;
        if (s->collisions.rule == SIM_RULE_CONTACT && k != SIM_KERNEL_HARD_SPHERES)
            return sim_error_set(err, SIM_EINVAL, "collisions.rule",
                                 "contact needs kernel = hard-spheres (other kernels collide "
                                 "by paper A's rule: allowed relative-speed)");
        if (s->collisions.rule == SIM_RULE_CONTACT && s->scheme == SIM_SCHEME_JUMP)
            return sim_error_set(err, SIM_EINVAL, "collisions.rule",
                                 "the jump scheme accepts by |g| (allowed relative-speed, or "
                                 "scheme = timestep)");
        if (slab)
            return sim_error_set(err, SIM_EINVAL, "collisions.rule",
                                 "not used by the Lees-Edwards slab (its layers accept by "
                                 "|g|, paper A's rule)");
    }
    if (s->heating.type == SIM_HEATING_WHITE_NOISE && s->heating.strength < 0.0)
        return sim_error_set(err, SIM_EINVAL, "heating.strength",
                             "%g is negative (allowed strength >= 0 for type = white-noise)",
                             s->heating.strength);
    if (s->heating.keep_temperature && s->heating.type != SIM_HEATING_GAUSSIAN)
        return sim_error_set(err, SIM_EINVAL, "heating.keep_temperature",
                             "only used with type = gaussian");
    if (s->heating.keep_temperature && is_set(s, "heating.strength"))
        return sim_error_set(err, SIM_EINVAL, "heating.strength",
                             "not used with keep_temperature = true (the rescaling sets zeta)");
    const int slab = s->shear.present && s->shear.boundary == SIM_SHEAR_LEES_EDWARDS;
    static const char *const slab_only[] = {"particles.density_wave", "particles.flow_wave",
                                            "shear.length", "shear.layers", "shear.candidates"};
    for (size_t i = 0; !slab && i < sizeof slab_only / sizeof slab_only[0]; i++)
        if (is_set(s, slab_only[i]))
            return sim_error_set(err, SIM_EINVAL, slab_only[i],
                                 "only used with [shear] boundary = lees-edwards (the slab)");
    if (s->steady.present && s->steady.from > s->t_end)
        return sim_error_set(err, SIM_EINVAL, "steady.from",
                             "%g is after t_end = %g (allowed 0 <= from <= t_end: the time "
                             "averages need at least one output time)", s->steady.from,
                             s->t_end);
    return SIM_OK;
}

/* ---- overrides ------------------------------------------------------- */

/* Copy s[0..n) without surrounding white space; 0 if it does not fit. */
static int copy_trimmed(char *dst, size_t size, const char *s, size_t n)
{
    while (n > 0 && isspace((unsigned char)*s))
        s++, n--;
    while (n > 0 && isspace((unsigned char)s[n - 1]))
        n--;
    if (n >= size)
        return 0;
    memcpy(dst, s, n);
    dst[n] = '\0';
    return 1;
}

static sim_status apply_override(parse_ctx *c, const char *ov)
{
    static const char form[] = "expected section.key=value";
    char section[64], key[64], value[512];
    c->line = -1;
    c->override = ov;
    const char *eq = strchr(ov, '=');
    if (!eq)
        return fail(c, SIM_EINVAL, "", "%s (no '=')", form);
    const char *dot = memchr(ov, '.', (size_t)(eq - ov));
    if (!dot)
        return fail(c, SIM_EINVAL, "", "%s (no '.' between section and key)", form);
    if (!copy_trimmed(section, sizeof section, ov, (size_t)(dot - ov)) ||
        !copy_trimmed(key, sizeof key, dot + 1, (size_t)(eq - dot - 1)) ||
        !copy_trimmed(value, sizeof value, eq + 1, strlen(eq + 1)))
        return fail(c, SIM_EINVAL, "", "%s (too long)", form);
    if (!section[0] || !key[0])
        return fail(c, SIM_EINVAL, "", "%s (empty section or key)", form);
    return apply(c, section, key, value);
}

/* ---- entry points ---------------------------------------------------- */

static void put_msg(char *msg, size_t msglen, const char *text)
{
    if (msg && msglen > 0)
        snprintf(msg, msglen, "%s", text);
}

static void ctx_init(parse_ctx *c, const char *name)
{
    memset(c, 0, sizeof *c);
    sim_scene_defaults(&c->scene);
    c->name = name ? name : "(scene)";
    snprintf(c->scene.file, sizeof c->scene.file, "%s", c->name);
}

/* Parse text (already checked for NUL bytes), apply overrides, check. */
static sim_status run(parse_ctx *c, const char *text, const char *const *overrides,
                      size_t noverrides, sim_scene *scene, char *msg, size_t msglen)
{
    char out[1024] = "";
    c->pos = text;
    int ret = ini_parse_stream(reader, c, handler, c);
    if (ret > 0 && (!c->failed || ret < c->err_line)) {  /* inih's own syntax error first */
        c->failed = 0;
        c->line = ret;
        fail(c, SIM_EINVAL, "", syntax_msg);
    } else if (ret < 0)
        fail(c, SIM_ENOMEM, "", "out of memory while parsing");

    for (size_t i = 0; i < noverrides && !c->failed; i++)
        apply_override(c, overrides[i]);

    if (c->failed) {
        format_at(c, out, sizeof out);
        put_msg(msg, msglen, out);
        return c->status;
    }
    sim_error err;
    sim_status st = check_scene(&c->scene, &err);
    if (st != SIM_OK) {
        vfy_scene_format_error(&c->scene, &err, out, sizeof out);
        put_msg(msg, msglen, out);
        return st;
    }
    *scene = c->scene;
    put_msg(msg, msglen, "");
    return SIM_OK;
}

static sim_status check_args(const void *input, const char *what, const char *const *overrides,
                             size_t noverrides, const sim_scene *scene, char *msg, size_t msglen)
{
    const char *bad = !input ? what : !scene ? "scene" : NULL;
    for (size_t i = 0; !bad && i < noverrides; i++)
        if (!overrides || !overrides[i])
            bad = "overrides";
    if (!bad)
        return SIM_OK;
    if (msg && msglen > 0)
        snprintf(msg, msglen, "%s is NULL", bad);
    return SIM_EINVAL;
}

/* Where the first NUL byte of buf[0..n) is, as a line number (0: none). */
static int nul_line(const char *buf, size_t n)
{
    const char *z = memchr(buf, '\0', n);
    if (!z)
        return 0;
    int line = 1;
    for (const char *p = buf; p < z; p++)
        line += *p == '\n';
    return line;
}

sim_status vfy_scene_parse(const char *text, const char *name, const char *const *overrides,
                           size_t noverrides, sim_scene *scene, char *msg, size_t msglen)
{
    sim_status st = check_args(text, "text", overrides, noverrides, scene, msg, msglen);
    if (st != SIM_OK)
        return st;
    parse_ctx c;
    ctx_init(&c, name);
    return run(&c, text, overrides, noverrides, scene, msg, msglen);
}

sim_status vfy_scene_load(const char *path, const char *const *overrides, size_t noverrides,
                          sim_scene *scene, char *msg, size_t msglen)
{
    sim_status st = check_args(path, "path", overrides, noverrides, scene, msg, msglen);
    if (st != SIM_OK)
        return st;
    parse_ctx c;
    ctx_init(&c, path);
    char out[1024];

    char *buf, why[256];
    size_t n;
    st = vfy_read_file(path, MAX_FILE_BYTES, &buf, &n, why, sizeof why);
    if (st != SIM_OK)
        fail(&c, st, "", "%s", why);
    else if ((c.line = nul_line(buf, n)) > 0)
        fail(&c, SIM_EINVAL, "", "NUL byte (allowed text only)");
    if (c.failed) {
        format_at(&c, out, sizeof out);
        put_msg(msg, msglen, out);
        free(buf);
        return c.status;
    }
    st = run(&c, buf, overrides, noverrides, scene, msg, msglen);
    free(buf);
    return st;
}

void vfy_scene_format_error(const sim_scene *scene, const sim_error *err, char *msg,
                            size_t msglen)
{
    if (!msg || msglen == 0)
        return;
    if (!err) {
        snprintf(msg, msglen, "%s", "");
        return;
    }
    const char *file = scene && scene->file[0] ? scene->file : "(scene)";
    if (!err->key[0]) {
        snprintf(msg, msglen, "%s: %s", file, err->msg);
        return;
    }
    int line = scene ? sim_scene_key_line(scene, err->key) : 0;
    if (line < 0)
        snprintf(msg, msglen, "%s: --set %s: %s", file, err->key, err->msg);
    else if (line == 0)
        snprintf(msg, msglen, "%s: %s: %s", file, err->key, err->msg);
    else
        snprintf(msg, msglen, "%s:%d: %s: %s", file, line, err->key, err->msg);
}

/* ---- scenes to text (issue 14: the resolved scene a solver reads) ----- */

/* The bytes of key d's field in s, and their count. */
static size_t field_of(const key_desc *d, const sim_scene *s, const char **field)
{
    *field = (const char *)s + d->offset;
    switch (d->kind) {
    case K_TEXT:
        return strlen(*field) + 1;
    case K_REAL:
        return sizeof(double);
    case K_VEC3:
        return 3 * sizeof(double);
    case K_SIZE:
        return sizeof(size_t);
    case K_U64:
        return sizeof(uint64_t);
    case K_WORD:
        return sizeof(int);
    }
    return 0;
}

static int section_present(const sim_scene *s, int section)
{
    return !sections[section].has_present
           || *(const int *)((const char *)s + sections[section].present);
}

/* Whether key `full` means anything in s, by check_scene()'s rules on
 * which keys go together: a scene changed in code after parsing (a jump
 * row made from a timestep scene, say) keeps the record of keys that no
 * longer apply, and writing them would make a scene the parser refuses. */
static int key_applies(const sim_scene *s, const char *full)
{
    const int mix = s->particles.initial == SIM_INITIAL_TWO_MAXWELLIANS;
    if (strcmp(full, "scene.splitting") == 0 || strcmp(full, "scene.step_follows_temperature") == 0)
        return s->scheme == SIM_SCHEME_TIMESTEP;
    if (strcmp(full, "heating.strength") == 0)
        return !s->heating.keep_temperature;
    if (in_list(one, N_ONE, full))
        return !mix;
    if (in_list(two, N_TWO, full))
        return mix;
    return 1;
}

/* Whether key d of s is written: it applies, and it was set or differs from
 * its default. */
static int key_written(const key_desc *d, const sim_scene *s, const sim_scene *def)
{
    char full[64];
    snprintf(full, sizeof full, "%s.%s", sections[d->section].name, d->name);
    if (!key_applies(s, full))
        return 0;
    const char *a, *b;
    size_t na = field_of(d, s, &a), nb = field_of(d, def, &b);
    return is_set(s, full) || na != nb || memcmp(a, b, na) != 0;
}

static void write_value(FILE *f, const key_desc *d, const sim_scene *s)
{
    const char *field = (const char *)s + d->offset;
    switch (d->kind) {
    case K_TEXT:
        fputs(field, f);
        break;
    case K_REAL:
        fprintf(f, "%.17g", *(const double *)field);
        break;
    case K_VEC3: {
        const double *v = (const double *)field;
        fprintf(f, "%.17g %.17g %.17g", v[0], v[1], v[2]);
        break;
    }
    case K_SIZE:
        fprintf(f, "%zu", *(const size_t *)field);
        break;
    case K_U64:
        fprintf(f, "%llu", (unsigned long long)*(const uint64_t *)field);
        break;
    case K_WORD:
        for (const word_desc *w = d->words; w->word; w++)
            if (w->value == *(const int *)field) {
                fputs(w->word, f);
                break;
            }
        break;
    }
}

int vfy_scene_write(FILE *f, const sim_scene *s)
{
    sim_scene def;
    sim_scene_defaults(&def);
    for (int section = 0; section < (int)NSECTIONS; section++) {
        if (!section_present(s, section))
            continue;
        fprintf(f, "%s[%s]\n", section ? "\n" : "", sections[section].name);
        for (size_t i = 0; i < NKEYS; i++) {
            if (keys[i].section != section || !key_written(&keys[i], s, &def))
                continue;
            fprintf(f, "%s = ", keys[i].name);
            write_value(f, &keys[i], s);
            fputc('\n', f);
        }
    }
    return ferror(f) ? -1 : 0;
}

int vfy_scene_differs(const sim_scene *a, const sim_scene *b, char *key, size_t keylen)
{
    for (int section = 0; section < (int)NSECTIONS; section++)
        if (section_present(a, section) != section_present(b, section)) {
            snprintf(key, keylen, "[%s]", sections[section].name);
            return 1;
        }
    for (size_t i = 0; i < NKEYS; i++) {
        const char *fa, *fb;
        size_t na = field_of(&keys[i], a, &fa), nb = field_of(&keys[i], b, &fb);
        if (na != nb || memcmp(fa, fb, na) != 0) {
            snprintf(key, keylen, "%s.%s", sections[keys[i].section].name, keys[i].name);
            return 1;
        }
    }
    return 0;
}

/* The algorithm keys (docs/scenes.md, "Every key"): engine choices a solver
 * may replace with its own algorithm; every other key is physics. */
static const char *const algorithm_keys[] = {
    "scene.title", "scene.scheme", "scene.dt", "scene.splitting",
    "scene.step_follows_temperature", "scene.observation", "scene.seed", "collisions.rule",
    "shear.pairs", "steady.pairs",
};

/* The description of scene key `key` ("section.key") and its section, or
 * NULL with msg naming what is unknown. */
static const key_desc *find_key(const char *key, int *sec, char *msg, size_t msglen)
{
    char section[64], list[1024];
    const char *dot = strchr(key, '.');
    if (dot == NULL || (size_t)(dot - key) >= sizeof section) {
        snprintf(msg, msglen, "%s: not SECTION.KEY", key);
        return NULL;
    }
    snprintf(section, sizeof section, "%.*s", (int)(dot - key), key);
    *sec = find_section(section);
    if (*sec < 0) {
        section_list(list, sizeof list);
        snprintf(msg, msglen, "%s: unknown section '%s' (allowed %s)", key, section, list);
        return NULL;
    }
    for (size_t i = 0; i < NKEYS; i++)
        if (keys[i].section == *sec && strcmp(keys[i].name, dot + 1) == 0)
            return &keys[i];
    key_list(*sec, list, sizeof list);
    snprintf(msg, msglen, "%s: unknown key (allowed %s)", key, list);
    return NULL;
}

int vfy_scene_key_class(const char *key)
{
    for (size_t i = 0; i < sizeof algorithm_keys / sizeof *algorithm_keys; i++)
        if (strcmp(key, algorithm_keys[i]) == 0)
            return VFY_KEY_ALGORITHM;
    int sec;
    char msg[8];
    return find_key(key, &sec, msg, sizeof msg) != NULL ? VFY_KEY_PHYSICS : VFY_KEY_UNKNOWN;
}

sim_status vfy_scene_real(const sim_scene *s, const char *key, double *value, char *msg,
                          size_t msglen)
{
    int sec;
    const key_desc *d = find_key(key, &sec, msg, msglen);
    if (d == NULL)
        return SIM_EINVAL;
    if (d->kind != K_REAL) {
        snprintf(msg, msglen, "%s: not a number key (a rate, constant, strength, "
                 "restitution ...): it cannot be multiplied", key);
        return SIM_EINVAL;
    }
    if (s != NULL && !section_present(s, sec)) {
        snprintf(msg, msglen, "%s: the scene %s has no [%s] section", key, s->file,
                 sections[sec].name);
        return SIM_EINVAL;
    }
    if (s != NULL)
        *value = *(const double *)((const char *)s + d->offset);
    if (s != NULL && strcmp(key, "collisions.beta") == 0 && *value == 0.0)
        *value = sim_scene_collision_rate_factor(s);   /* defaulted: the model's */
    return SIM_OK;
}

int vfy_scene_key_value(const sim_scene *s, const char *key, double *value, const char **word)
{
    int sec;
    char msg[8];
    const key_desc *d = strchr(key, '.') ? find_key(key, &sec, msg, sizeof msg) : NULL;
    if (d == NULL || !section_present(s, sec))
        return 0;
    const char *field = (const char *)s + d->offset;
    switch (d->kind) {
    case K_REAL:
        *value = *(const double *)field;
        return 1;
    case K_SIZE:
        *value = (double)*(const size_t *)field;
        return 1;
    case K_U64:
        *value = (double)*(const uint64_t *)field;
        return 1;
    case K_TEXT:
        *word = field;
        return 2;
    case K_WORD:
        for (const word_desc *wd = d->words; wd->word; wd++)
            if (*(const int *)field == wd->value) {
                *word = wd->word;
                return 2;
            }
        return 0;
    case K_VEC3:
        return 0;
    }
    return 0;
}

/* Whether requirement word `w` (len bytes) holds in s: 1, 0, or -1 with msg
 * when the word is malformed. */
static int requirement_holds(const sim_scene *s, const char *w, size_t len, char *msg,
                             size_t msglen)
{
    char word[160];
    if (len == 0 || len >= sizeof word) {
        snprintf(msg, msglen, "requirement '%.*s': empty or too long", (int)len, w);
        return -1;
    }
    snprintf(word, sizeof word, "%.*s", (int)len, w);
    if (word[0] == '[' || (word[0] == '!' && word[1] == '[')) {   /* a section, present or not */
        const int absent = word[0] == '!';
        char name[64];
        const char *open = word + absent + 1, *close = strchr(open, ']');
        if (close == NULL || close[1] != '\0' || (size_t)(close - open) >= sizeof name) {
            snprintf(msg, msglen, "requirement '%s': not [SECTION] or ![SECTION]", word);
            return -1;
        }
        snprintf(name, sizeof name, "%.*s", (int)(close - open), open);
        const int sec = find_section(name);
        if (sec < 0) {
            snprintf(msg, msglen, "requirement '%s': unknown section", word);
            return -1;
        }
        return section_present(s, sec) != absent;
    }
    const size_t klen = strcspn(word, "=<>");
    const char *op = word + klen, *rhs = op + (op[0] != '\0') + (op[1] == '=');
    if (op[0] == '\0' || *rhs == '\0') {
        snprintf(msg, msglen, "requirement '%s': not KEY=VALUE, KEY>X, KEY>=X, KEY<X or "
                 "KEY<=X", word);
        return -1;
    }
    op = op[0] == '=' ? "=" : op[0] == '>' ? (op[1] == '=' ? ">=" : ">")
                                           : (op[1] == '=' ? "<=" : "<");
    word[klen] = '\0';
    double x;
    if (strcmp(word, "grain_mass") == 0) {
        x = sim_scene_grain_mass(s);
    } else {
        int sec;
        const key_desc *d = find_key(word, &sec, msg, msglen);
        if (d == NULL)
            return -1;
        const char *field = (const char *)s + d->offset;
        if (d->kind == K_WORD) {
            if (strcmp(op, "=") != 0) {
                snprintf(msg, msglen, "requirement on %s: a word key takes KEY=WORD", word);
                return -1;
            }
            for (const word_desc *wd = d->words; wd->word; wd++)
                if (strcmp(wd->word, rhs) == 0)
                    return section_present(s, sec) && *(const int *)field == wd->value;
            snprintf(msg, msglen, "requirement on %s: '%s' is none of its words", word, rhs);
            return -1;
        }
        if (d->kind == K_REAL)
            x = *(const double *)field;
        else if (d->kind == K_SIZE)
            x = (double)*(const size_t *)field;
        else {
            snprintf(msg, msglen, "requirement on %s: only number and word keys", word);
            return -1;
        }
        if (!section_present(s, sec))
            return 0;
    }
    char *end;
    const double v = strtod(rhs, &end);
    if (end == rhs || *end != '\0') {
        snprintf(msg, msglen, "requirement on %s: '%s' is not a number", word, rhs);
        return -1;
    }
    return strcmp(op, "=") == 0    ? x == v
           : strcmp(op, ">") == 0  ? x > v
           : strcmp(op, ">=") == 0 ? x >= v
           : strcmp(op, "<") == 0  ? x < v
                                   : x <= v;
}

int vfy_scene_requires(const sim_scene *s, const char *words, char *msg, size_t msglen)
{
    for (const char *p = words + strspn(words, " "); *p; p += strspn(p, " ")) {
        const size_t len = strcspn(p, " ");
        const int holds = requirement_holds(s, p, len, msg, msglen);
        if (holds <= 0) {
            if (holds == 0)
                snprintf(msg, msglen, "%.*s", (int)len, p);
            return holds;
        }
        p += len;
    }
    return 1;
}
