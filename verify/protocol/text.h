/* Text of any length: a growable string, and printf into fresh memory.
 *
 * The reports' texts (check names, labels, notes, figure titles) are made
 * from the case descriptions' templates; their length is the description's,
 * not a buffer's, so they are built here instead of in fixed arrays.  Out of
 * memory is never fatal: the functions say so by their return value and the
 * caller returns SIM_ENOMEM (or records what it can).
 */
#ifndef GDSMC_VFY_TEXT_H
#define GDSMC_VFY_TEXT_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#include "error.h"

/* A string that grows as text is appended.  {0} is the empty text; after a
 * failed append (out of memory) it keeps what it held and `failed` is set,
 * and every later append fails too. */
typedef struct vfy_text {
    char *s;           /* NUL-terminated, or NULL while empty */
    size_t len, cap;   /* characters held, bytes allocated */
    int failed;        /* an append ran out of memory */
} vfy_text;

/* Append printf-style; returns 0, or -1 when out of memory. */
int vfy_text_printf(vfy_text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
int vfy_text_vprintf(vfy_text *t, const char *fmt, va_list ap)
    __attribute__((format(printf, 2, 0)));

/* Append the n first characters of s (fewer where s ends first); 0 or -1. */
int vfy_text_append(vfy_text *t, const char *s, size_t n);

/* The text so far ("" while empty); valid until the next append or free. */
const char *vfy_text_str(const vfy_text *t);

/* The text as a string the caller frees (t is emptied), or NULL when an
 * append failed or there is no memory for the empty string. */
char *vfy_text_take(vfy_text *t);

void vfy_text_free(vfy_text *t);

/* printf into fresh memory: the string (the caller frees it), or NULL when
 * out of memory. */
char *vfy_aprintf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
char *vfy_vaprintf(const char *fmt, va_list ap) __attribute__((format(printf, 1, 0)));

/* The whole file at path, at most max bytes, as NUL-terminated text: *text
 * (the caller frees it) and *len, its length without the NUL.  Returns
 * SIM_OK, or an error with `why` the reason alone, for the caller to put
 * after the file's name: "cannot open: REASON" or "cannot read: REASON"
 * (SIM_EIO), "too large (allowed at most MAX bytes)" (SIM_EINVAL), "out of
 * memory reading the file" (SIM_ENOMEM).  A NUL byte inside is the
 * caller's to refuse. */
sim_status vfy_read_file(const char *path, size_t max, char **text, size_t *len, char *why,
                         size_t whylen);

/* A copy of s (NULL: of ""), or NULL when out of memory. */
char *vfy_strdup(const char *s);

/* text as one CSV field: quoted when it holds a comma, a quote or a line
 * break (a quote doubled, a line break written as a space). */
void vfy_csv_field(FILE *f, const char *text);

/* The fields of one line of CSV text (RFC 4180 quoting), NUL-terminated in
 * place in `line`: fields[k] for k < the count returned (at most max). */
size_t vfy_csv_split(char *line, char **fields, size_t max);

#endif
