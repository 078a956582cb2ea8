#include "table.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "text.h"

void vfy_table_init(vfy_table *t, size_t ncols, const char *const *cols)
{
    memset(t, 0, sizeof *t);
    t->ncols = ncols;
    t->cols = cols;
}

void vfy_table_free(vfy_table *t)
{
    for (size_t i = 0; i < t->ncells; i++)
        free(t->cells[i]);
    free(t->cells);
    memset(t, 0, sizeof *t);
}

int vfy_table_cell(vfy_table *t, const char *fmt, ...)
{
    if (t->ncells == t->capacity) {
        size_t cap = t->capacity ? 2 * t->capacity : 64;
        char **grown = realloc(t->cells, cap * sizeof *grown);
        if (grown == NULL)
            return -1;
        t->cells = grown;
        t->capacity = cap;
    }
    va_list ap;
    va_start(ap, fmt);
    char *cell = vfy_vaprintf(fmt, ap);   /* as long as it prints: a text value has no limit */
    va_end(ap);
    if (cell == NULL)
        return -1;
    t->cells[t->ncells++] = cell;
    return 0;
}

int vfy_table_number(vfy_table *t, int present, const char *fmt, double x)
{
    if (!present)
        return vfy_table_cell(t, "%s", "");
    char *number = vfy_aprintf(fmt, x);   /* a description's format: "%.0f" of 1e300 too */
    const int rc = number != NULL ? vfy_table_cell(t, "%s", number) : -1;
    free(number);
    return rc;
}

static int writes_files = 1;

void vfy_set_writes_files(int on) { writes_files = on != 0; }
int vfy_writes_files(void) { return writes_files; }

FILE *vfy_file_begin(const char *path, char *tmp, size_t tmplen)
{
    /* An existing device or pipe (/dev/stdout, a FIFO) is written in place:
     * renaming over it would replace the device node with a plain file. */
    struct stat st;
    if (writes_files && stat(path, &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) {
        if (tmplen > 0)
            tmp[0] = '\0';
        return fopen(path, "w");
    }
    if ((size_t)snprintf(tmp, tmplen, "%s.tmp", path) >= tmplen) {
        errno = ENAMETOOLONG;
        return NULL;
    }
    return fopen(writes_files ? tmp : "/dev/null", "w");
}

int vfy_file_commit(FILE *f, const char *tmp, const char *path, int ok)
{
    ok = ok && !ferror(f);
    if (fclose(f) != 0)
        ok = 0;
    if (!writes_files || tmp[0] == '\0')   /* another rank's, or a device written in place */
        return ok ? 0 : -1;
    if (!ok) {
        int saved = errno;
        remove(tmp);
        errno = saved ? saved : EIO;
        return -1;
    }
    if (rename(tmp, path) != 0) {   /* e.g. path is a directory: leave no FILE.tmp */
        int saved = errno;
        remove(tmp);
        errno = saved;
        return -1;
    }
    return 0;
}

int vfy_file_probe(const char *path)
{
    struct stat st;
    if (stat(path, &st) == 0) {
        if (S_ISDIR(st.st_mode)) {   /* the final rename would fail */
            errno = EISDIR;
            return -1;
        }
        /* a device or FIFO is written in place (vfy_file_begin): ask, do not
         * open (opening a FIFO would wait for its reader, and closing it
         * would end the reader's input) */
        if (writes_files && !S_ISREG(st.st_mode))
            return access(path, W_OK);
    }
    /* a new or regular file: FILE.tmp must be creatable beside it */
    char tmp[4096];
    FILE *f = vfy_file_begin(path, tmp, sizeof tmp);
    if (f == NULL)
        return -1;
    fclose(f);
    if (writes_files)
        remove(tmp);
    return 0;
}

int vfy_ensure_dir(const char *path)
{
    char buf[1024];
    if ((size_t)snprintf(buf, sizeof buf, "%s", path) >= sizeof buf) {
        errno = ENAMETOOLONG;
        return -1;
    }
    for (char *p = buf + 1; *p; p++) {   /* each parent, then the directory */
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST)
            return -1;
        *p = '/';
    }
    if (mkdir(buf, 0777) == 0)
        return 0;
    struct stat st;   /* EEXIST: fine if it is a directory, not if it is a file */
    if (errno == EEXIST && stat(buf, &st) == 0 && !S_ISDIR(st.st_mode))
        errno = ENOTDIR;
    return errno == EEXIST ? 0 : -1;
}

void vfy_write_comment(FILE *f, const char *comment)
{
    for (const char *line = comment; line && *line;) {
        const char *end = strchr(line, '\n');
        size_t len = end ? (size_t)(end - line) : strlen(line);
        fprintf(f, "# %.*s\n", (int)len, line);
        line = end ? end + 1 : line + len;
    }
}

int vfy_table_write_csv(const vfy_table *t, const char *path, const char *comment)
{
    char tmp[1024];
    FILE *f = vfy_file_begin(path, tmp, sizeof tmp);
    if (f == NULL)
        return -1;
    vfy_write_comment(f, comment);
    for (size_t c = 0; c < t->ncols; c++)
        fprintf(f, "%s%s", c ? "," : "", t->cols[c]);
    fputc('\n', f);
    for (size_t i = 0; i < t->ncells; i++)
        fprintf(f, "%s%s", t->cells[i], (i + 1) % t->ncols ? "," : "\n");
    return vfy_file_commit(f, tmp, path, 1);
}

void vfy_table_print_markdown(const vfy_table *t, FILE *f, const char *title,
                              const char *notes)
{
    fprintf(f, "# %s\n\n", title);
    if (notes && *notes)
        fprintf(f, "%s\n\n", notes);
    fputc('|', f);
    for (size_t c = 0; c < t->ncols; c++)
        fprintf(f, " %s |", t->cols[c]);
    fputs("\n|", f);
    for (size_t c = 0; c < t->ncols; c++)
        fputs("---:|", f);
    fputc('\n', f);
    for (size_t i = 0; i < t->ncells; i++) {
        if (i % t->ncols == 0)
            fputc('|', f);
        fprintf(f, " %s |", t->cells[i][0] ? t->cells[i] : "–");
        if ((i + 1) % t->ncols == 0)
            fputc('\n', f);
    }
}

int vfy_table_write_markdown(const vfy_table *t, const char *path, const char *title,
                             const char *notes)
{
    char tmp[1024];
    FILE *f = vfy_file_begin(path, tmp, sizeof tmp);
    if (f == NULL)
        return -1;
    vfy_table_print_markdown(t, f, title, notes);
    return vfy_file_commit(f, tmp, path, 1);
}
