#include "verdicts.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "table.h"
#include "text.h"

static void csv_number(FILE *f, double x)
{
    if (isfinite(x))
        fprintf(f, ",%.10g", x);
    else if (isinf(x))
        fputs(x > 0 ? ",inf" : ",-inf", f);
    else
        fputc(',', f);
}

sim_status vfy_write_verdicts(const vfy_options *o, const char *name, const vfy_report *r,
                              const char *comment, double wall_s, double cpu_s, char *msg,
                              size_t msglen)
{
    char file[128];
    snprintf(file, sizeof file, "%s-verdicts.csv", name);
    vfy_report_file rf;
    if (vfy_report_file_open(&rf, o, file, msg, msglen) != SIM_OK)
        return SIM_EIO;
    FILE *f = rf.f;
    size_t n[VFY_VERDICTS] = {0};
    for (size_t i = 0; i < r->count; i++)
        if (strcmp(r->checks[i].group, name) == 0)
            n[r->checks[i].verdict]++;
    vfy_write_comment(f, comment);
    fprintf(f, "# counts: passed = %zu, failed = %zu, skipped = %zu, differs = %zu\n",
            n[VFY_PASS], n[VFY_FAIL], n[VFY_SKIP], n[VFY_DIFFERS]);
    fprintf(f, "# cost: wall_s = %.2f, cpu_s = %.2f\n", wall_s, cpu_s);
    fputs("check_id,row,verdict,value,reference,allowed,name,detail\n", f);
    for (size_t i = 0; i < r->count; i++) {
        const vfy_check *c = &r->checks[i];
        if (strcmp(c->group, name) != 0)
            continue;
        vfy_csv_field(f, c->id[0] ? c->id : c->name);
        fputc(',', f);
        vfy_csv_field(f, c->row);
        fprintf(f, ",%s", vfy_verdict_word(c->verdict));
        csv_number(f, c->value);
        csv_number(f, c->reference);
        fputc(',', f);
        vfy_csv_field(f, c->allowed);
        fputc(',', f);
        vfy_csv_field(f, c->name);
        fputc(',', f);
        vfy_csv_field(f, c->detail);
        fputc('\n', f);
    }
    return vfy_report_file_close(&rf, msg, msglen);
}

/* ------------------------------------------------------------ the index */

/* One case's verdicts file, read back. */
typedef struct case_verdicts {
    size_t n[VFY_VERDICTS];
    double wall_s, cpu_s;
    char version[64];
} case_verdicts;

/* Read out_dir/<name>-verdicts.csv's counts and cost; with `list`, print
 * its DIFFERS (want = VFY_DIFFERS) or FAIL lines as Markdown list items.
 * Returns 0, or -1 when there is no such file. */
static int read_verdicts(const vfy_options *o, const char *name, case_verdicts *cv, FILE *list,
                         vfy_verdict want)
{
    char path[1100], *line = NULL;
    size_t cap = 0;
    vfy_report_path(o, name, "-verdicts.csv", path, sizeof path);
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return -1;
    memset(cv, 0, sizeof *cv);
    int header = 0;
    while (getline(&line, &cap, f) != -1) {   /* a line as long as its check's texts */
        if (line[0] == '#') {
            if (cv->version[0] == '\0')
                sscanf(line, "# gdsmc %63s", cv->version);
            sscanf(line, "# cost: wall_s = %lf, cpu_s = %lf", &cv->wall_s, &cv->cpu_s);
            continue;
        }
        if (!header++)
            continue;
        char *fields[8];
        if (vfy_csv_split(line, fields, 8) < 8)
            continue;
        for (int v = 0; v < VFY_VERDICTS; v++)
            if (strcmp(fields[2], vfy_verdict_word((vfy_verdict)v)) == 0) {
                cv->n[v]++;
                if (list != NULL && v == (int)want)
                    fprintf(list, "- **%s** %s: %s\n", name, fields[6], fields[7]);
            }
    }
    free(line);
    fclose(f);
    return 0;
}

/* Whether file name `file` (a .png) belongs to case c: <c>.png or <c>-*.png,
 * and no longer case name of `cases` claims it. */
static int figure_of(const char *file, const char *c, const char *const *cases, size_t ncases)
{
    const size_t len = strlen(c), flen = strlen(file);
    if (flen < 4 || strcmp(file + flen - 4, ".png") != 0 || strncmp(file, c, len) != 0
        || (file[len] != '.' && file[len] != '-'))
        return 0;
    for (size_t i = 0; i < ncases; i++) {
        const char *other = cases[i];
        const size_t olen = strlen(other);
        if (olen > len && strncmp(file, other, olen) == 0
            && (file[olen] == '.' || file[olen] == '-'))
            return 0;
    }
    return 1;
}

static int compare_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Links to the case's figures in out_dir, in name order (as many as there
 * are; out of memory, those listed so far). */
static void figure_links(FILE *f, const vfy_options *o, const char *c,
                         const char *const *cases, size_t ncases)
{
    DIR *dir = opendir(o->out_dir);
    if (dir == NULL)
        return;
    char **names = NULL;
    size_t count = 0, cap = 0;
    for (struct dirent *e; (e = readdir(dir)) != NULL;) {
        if (!figure_of(e->d_name, c, cases, ncases))
            continue;
        if (count == cap) {
            char **grown = realloc(names, (cap = cap ? 2 * cap : 16) * sizeof *grown);
            if (grown == NULL)
                break;
            names = grown;
        }
        if ((names[count] = strdup(e->d_name)) != NULL)
            count++;
    }
    closedir(dir);
    if (count > 1)
        qsort(names, count, sizeof *names, compare_names);
    for (size_t i = 0; i < count; i++) {
        const char *rest = names[i] + strlen(c);   /* ".png" or "-PART.png" */
        if (rest[0] == '.')
            fprintf(f, ", [figure](%s)", names[i]);
        else
            fprintf(f, ", [%.*s](%s)", (int)(strlen(rest) - 5), rest + 1, names[i]);
        free(names[i]);
    }
    free(names);
}

sim_status vfy_write_index(const vfy_options *o, const char *title, const char *const *cases,
                           size_t ncases, char *msg, size_t msglen)
{
    vfy_report_file rf;
    if (vfy_report_file_open(&rf, o, "README.md", msg, msglen) != SIM_OK)
        return SIM_EIO;
    FILE *f = rf.f;
    fprintf(f, "# Verdicts (%s)\n\n"
               "Made by gdsmc %s verify: scene files, seeds and sizes as each case's table "
               "says, from the `<case>-verdicts.csv` files in this directory (one line per "
               "check: its id, row, verdict, value, reference, bound and detail). PASS: "
               "judged, and it held. FAIL: judged, and it did not. SKIP: not judged, with the "
               "reason. DIFFERS: a paper's printed number or sentence that this project shows "
               "to be off, with the evidence (docs/differences.md); the solver is judged by "
               "the check named there. wall_s and cpu_s are the simulations' seconds, summed "
               "over rows.\n\n",
            title, GDSMC_VERSION);
    fputs("| case | passed | failed | skipped | differs | wall_s | cpu_s | version | files |\n"
          "|---|---:|---:|---:|---:|---:|---:|---|---|\n",
          f);
    case_verdicts all = {0};
    for (size_t i = 0; i < ncases; i++) {
        const char *c = cases[i];
        case_verdicts cv;
        if (read_verdicts(o, c, &cv, NULL, VFY_PASS) != 0)
            continue;
        fprintf(f, "| %s | %zu | %zu | %zu | %zu | %.1f | %.1f | %s | [table](%s.md), "
                   "[verdicts](%s-verdicts.csv)",
                c, cv.n[VFY_PASS], cv.n[VFY_FAIL], cv.n[VFY_SKIP], cv.n[VFY_DIFFERS], cv.wall_s,
                cv.cpu_s, cv.version, c, c);
        figure_links(f, o, c, cases, ncases);
        fputs(" |\n", f);
        for (int v = 0; v < VFY_VERDICTS; v++)
            all.n[v] += cv.n[v];
        all.wall_s += cv.wall_s;
        all.cpu_s += cv.cpu_s;
    }
    fprintf(f, "| **all** | %zu | %zu | %zu | %zu | %.1f | %.1f | | |\n", all.n[VFY_PASS],
            all.n[VFY_FAIL], all.n[VFY_SKIP], all.n[VFY_DIFFERS], all.wall_s, all.cpu_s);
    static const struct {
        vfy_verdict v;
        const char *heading;
    } lists[] = {{VFY_DIFFERS, "Known differences from the papers (DIFFERS)"},
                 {VFY_FAIL, "Failures"}};
    for (size_t k = 0; k < sizeof lists / sizeof *lists; k++) {
        if (all.n[lists[k].v] == 0)
            continue;
        fprintf(f, "\n## %s\n\n", lists[k].heading);
        for (size_t i = 0; i < ncases; i++) {
            case_verdicts cv;
            read_verdicts(o, cases[i], &cv, f, lists[k].v);
        }
    }
    return vfy_report_file_close(&rf, msg, msglen);
}
