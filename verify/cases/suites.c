/* The suites: the cases in suite order, from their case files, and the runs
 * of a suite (suites.h). */
#include "suites.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case_file.h"
#include "driver.h"
#include "registry.h"
#include "table.h"
#include "verdicts.h"

/* The loaded cases, in suite order (vfy_cases_load). */
static vfy_case_file **files;
static size_t nfiles;

void vfy_cases_unload(void)
{
    for (size_t i = 0; i < nfiles; i++)
        vfy_case_file_free(files[i]);
    free(files);
    files = NULL;
    nfiles = 0;
}

/* The names of DIR/cases.list, one a line ('#' comments, blank lines), into
 * *names (*count of them, each allocated). */
static sim_status read_list(const char *path, char ***names, size_t *count, char *msg,
                            size_t msglen)
{
    *names = NULL;
    *count = 0;
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        snprintf(msg, msglen, "%s: cannot open: %s", path, strerror(errno));
        return SIM_EIO;
    }
    char line[256];
    sim_status st = SIM_OK;
    for (int lineno = 1; st == SIM_OK && fgets(line, sizeof line, f) != NULL; lineno++) {
        line[strcspn(line, "\r\n")] = '\0';
        const char *name = line + strspn(line, " \t");
        if (name[0] == '\0' || name[0] == '#')
            continue;
        if (strspn(name, "abcdefghijklmnopqrstuvwxyz0123456789-") != strlen(name)) {
            snprintf(msg, msglen, "%s:%d: '%s' is not a case name (allowed a-z, 0-9, -)", path,
                     lineno, name);
            st = SIM_EINVAL;
            break;
        }
        for (size_t i = 0; i < *count; i++)
            if (strcmp((*names)[i], name) == 0) {
                snprintf(msg, msglen, "%s:%d: %s listed twice", path, lineno, name);
                st = SIM_EINVAL;
            }
        char **grown = st == SIM_OK ? realloc(*names, (*count + 1) * sizeof *grown) : NULL;
        if (st == SIM_OK && (grown == NULL || (grown[*count] = strdup(name)) == NULL)) {
            if (grown != NULL)
                *names = grown;
            snprintf(msg, msglen, "%s: out of memory", path);
            st = SIM_ENOMEM;
        } else if (st == SIM_OK) {
            *names = grown;
            (*count)++;
        }
    }
    fclose(f);
    return st;
}

const char *vfy_case_dir(void) { return GDSMC_SOURCE_DIR "/verify/cases/scenes"; }

sim_status vfy_cases_load(const char *dir, char *msg, size_t msglen)
{
    vfy_cases_unload();
    char path[4096];
    snprintf(path, sizeof path, "%s/cases.list", dir);
    char **names;
    size_t count;
    sim_status st = read_list(path, &names, &count, msg, msglen);
    files = st == SIM_OK && count ? calloc(count, sizeof *files) : NULL;
    if (st == SIM_OK && count && files == NULL) {
        snprintf(msg, msglen, "%s: out of memory", path);
        st = SIM_ENOMEM;
    }
    for (size_t i = 0; st == SIM_OK && i < count; i++) {
        snprintf(path, sizeof path, "%s/%s.case", dir, names[i]);
        st = vfy_case_file_load(path, names[i], vfy_named_tables, &files[nfiles], msg, msglen);
        nfiles += st == SIM_OK;
    }
    for (size_t i = 0; i < count; i++)
        free(names[i]);
    free(names);
    if (st != SIM_OK)
        vfy_cases_unload();
    return st;
}

size_t vfy_case_count(void) { return nfiles; }

const vfy_case *vfy_case_at(size_t i)
{
    return i < nfiles ? vfy_case_file_case(files[i]) : NULL;
}

const vfy_case *vfy_case_find(const char *name)
{
    for (size_t i = 0; i < nfiles; i++)
        if (strcmp(vfy_case_at(i)->name, name) == 0)
            return vfy_case_at(i);
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
        if (strcmp(vfy_case_at(i)->suite, name) == 0)
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
            seen = strcmp(vfy_case_at(j)->suite, vfy_case_at(i)->suite) == 0;
        if (!seen && used < len)
            used += (size_t)snprintf(buf + used, len - used, "%s%s", used ? ", " : "",
                                     vfy_case_at(i)->suite);
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
        const vfy_case *c = vfy_case_at(i);
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
    const char **names = malloc((nfiles ? nfiles : 1) * sizeof *names);
    if (names == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    for (size_t i = 0; i < nfiles; i++)
        names[i] = vfy_case_at(i)->name;
    sim_status st = vfy_write_index(o, o->size == VFY_QUICK ? "quick sizes" : "paper sizes",
                                    names, nfiles, msg, msglen);
    free(names);
    return st;
}

