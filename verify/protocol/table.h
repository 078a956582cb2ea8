/* Tables of results and their files (README.md, "What comes out"): CSV (a header row of column
 * names, '#' comment lines before it, plain numbers: opens in a spreadsheet
 * and in gnuplot with `set datafile separator ','`) and Markdown.
 *
 * Files are written to FILE.tmp and renamed into place, so a reader never
 * sees a half-written file.
 */
#ifndef GDSMC_VFY_TABLE_H
#define GDSMC_VFY_TABLE_H

#include <stddef.h>
#include <stdio.h>

typedef struct vfy_table {
    size_t ncols;
    const char *const *cols;  /* column names, not owned */
    size_t ncells, capacity;
    char **cells;             /* row-major, owned */
} vfy_table;

void vfy_table_init(vfy_table *t, size_t ncols, const char *const *cols);
void vfy_table_free(vfy_table *t);

/* Append the next cell (rows fill left to right); "" is an empty cell.
 * Returns 0, or -1 when out of memory. */
int vfy_table_cell(vfy_table *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* A number in fmt when present, else an empty cell (e.g. the CF of a first row). */
int vfy_table_number(vfy_table *t, int present, const char *fmt, double x);

static inline size_t vfy_table_rows(const vfy_table *t) { return t->ncells / t->ncols; }

/* Write the table as CSV; comment (may be NULL, may hold several lines) goes
 * first, each line prefixed "# ".  Returns 0, or -1 with errno set. */
int vfy_table_write_csv(const vfy_table *t, const char *path, const char *comment);

/* Write comment (may be NULL, may hold several lines) as lines prefixed "# ":
 * the provenance header of every CSV file and gnuplot script (seed, version,
 * scene: vfy_run_comment). */
void vfy_write_comment(FILE *f, const char *comment);

/* Write "# title", the notes paragraph (may be NULL) and the table in
 * Markdown; empty cells print as "–".  Returns 0, or -1 with errno set. */
int vfy_table_write_markdown(const vfy_table *t, const char *path, const char *title,
                             const char *notes);

/* The same Markdown on an open stream (e.g. stdout). */
void vfy_table_print_markdown(const vfy_table *t, FILE *f, const char *title,
                              const char *notes);

/* Whether this process writes files (1 by default).  Under MPI only rank 0
 * does (verify/cli/main.c): after vfy_set_writes_files(0), vfy_file_begin opens
 * /dev/null and vfy_file_commit only closes it, so every rank runs the same
 * code and no two processes write one file; vfy_gnuplot draws nothing. */
void vfy_set_writes_files(int on);
int vfy_writes_files(void);

/* Open path.tmp for writing (tmp receives its name, tmplen bytes); commit with
 * vfy_file_commit, which closes it and renames it over path (or removes it
 * when ok = 0).  An existing path that is neither a regular file nor a
 * directory (/dev/stdout, a FIFO) is opened in place instead (tmp = "").
 * Returns NULL (errno set) on failure. */
FILE *vfy_file_begin(const char *path, char *tmp, size_t tmplen);
int vfy_file_commit(FILE *f, const char *tmp, const char *path, int ok);

/* Whether path could be written by vfy_file_begin and vfy_file_commit (its
 * directory takes a new file, it is not a directory): checked before long
 * work, so that an unwritable output is reported before the work, not after.
 * Leaves nothing behind (a device or FIFO is only checked for write
 * permission, not opened).  Returns 0, or -1 with errno set. */
int vfy_file_probe(const char *path);

/* Create directory path and its parents if they do not exist.  Returns 0 or -1. */
int vfy_ensure_dir(const char *path);

#endif
