#include "text.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Room for `more` characters and the terminator; 0, or -1 (failed set). */
static int reserve(vfy_text *t, size_t more)
{
    if (t->failed)
        return -1;
    if (t->len + more + 1 <= t->cap)
        return 0;
    size_t cap = t->cap ? t->cap : 64;
    while (cap < t->len + more + 1)
        cap *= 2;
    char *grown = realloc(t->s, cap);
    if (grown == NULL) {
        t->failed = 1;
        return -1;
    }
    if (t->s == NULL)
        grown[0] = '\0';
    t->s = grown;
    t->cap = cap;
    return 0;
}

int vfy_text_vprintf(vfy_text *t, const char *fmt, va_list ap)
{
    va_list again;
    va_copy(again, ap);
    const int n = vsnprintf(NULL, 0, fmt, ap);
    int rc = n < 0 || reserve(t, (size_t)n) != 0 ? -1 : 0;
    if (rc == 0) {
        vsnprintf(t->s + t->len, t->cap - t->len, fmt, again);
        t->len += (size_t)n;
    }
    va_end(again);
    return rc;
}

int vfy_text_printf(vfy_text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    const int rc = vfy_text_vprintf(t, fmt, ap);
    va_end(ap);
    return rc;
}

int vfy_text_append(vfy_text *t, const char *s, size_t n)
{
    const size_t have = strnlen(s, n);
    if (reserve(t, have) != 0)
        return -1;
    memcpy(t->s + t->len, s, have);
    t->len += have;
    t->s[t->len] = '\0';
    return 0;
}

const char *vfy_text_str(const vfy_text *t) { return t->s ? t->s : ""; }

char *vfy_text_take(vfy_text *t)
{
    char *s = t->failed ? NULL : t->s ? t->s : vfy_strdup("");
    if (t->failed)
        free(t->s);
    *t = (vfy_text){0};
    return s;
}

void vfy_text_free(vfy_text *t)
{
    free(t->s);
    *t = (vfy_text){0};
}

char *vfy_vaprintf(const char *fmt, va_list ap)
{
    vfy_text t = {0};
    vfy_text_vprintf(&t, fmt, ap);
    return vfy_text_take(&t);
}

char *vfy_aprintf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *s = vfy_vaprintf(fmt, ap);
    va_end(ap);
    return s;
}

char *vfy_strdup(const char *s)
{
    const size_t n = s ? strlen(s) : 0;
    char *copy = malloc(n + 1);
    if (copy != NULL) {
        memcpy(copy, s ? s : "", n);
        copy[n] = '\0';
    }
    return copy;
}

void vfy_csv_field(FILE *f, const char *text)
{
    if (strpbrk(text, ",\"\n\r") == NULL) {
        fputs(text, f);
        return;
    }
    fputc('"', f);
    for (const char *p = text; *p; p++) {
        if (*p == '"')
            fputc('"', f);
        fputc(*p == '\n' || *p == '\r' ? ' ' : *p, f);
    }
    fputc('"', f);
}

size_t vfy_csv_split(char *line, char **fields, size_t max)
{
    size_t count = 0;
    char *p = line;
    while (count < max) {
        char *out = p;
        fields[count++] = out;
        if (*p == '"') {   /* quoted: "" is a quote, the field ends at a lone quote */
            p++;
            while (*p && !(p[0] == '"' && p[1] != '"')) {
                *out++ = *p;
                p += p[0] == '"' ? 2 : 1;
            }
            if (*p == '"')
                p++;
        } else {
            while (*p && *p != ',' && *p != '\n' && *p != '\r')
                *out++ = *p++;
        }
        const char next = *p;
        *out = '\0';
        if (next != ',')
            break;
        p++;
    }
    return count;
}

sim_status vfy_read_file(const char *path, size_t max, char **text, size_t *len, char *why,
                         size_t whylen)
{
    *text = NULL;
    *len = 0;
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        snprintf(why, whylen, "cannot open: %s", strerror(errno));
        return SIM_EIO;
    }
    char *buf = malloc(max + 1);
    size_t n = buf ? fread(buf, 1, max + 1, f) : 0;
    const int read_errno = errno;
    sim_status st = SIM_OK;
    if (buf == NULL)
        snprintf(why, whylen, "out of memory reading the file"), st = SIM_ENOMEM;
    else if (ferror(f))
        snprintf(why, whylen, "cannot read: %s", strerror(read_errno)), st = SIM_EIO;
    else if (n > max)
        snprintf(why, whylen, "too large (allowed at most %zu bytes)", max), st = SIM_EINVAL;
    fclose(f);
    if (st != SIM_OK) {
        free(buf);
        return st;
    }
    buf[n] = '\0';
    *text = buf;
    *len = n;
    return SIM_OK;
}
