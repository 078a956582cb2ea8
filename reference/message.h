/* Messages about bad arguments, shared by the reference modules (internal). */
#ifndef GDSMC_REF_MESSAGE_H
#define GDSMC_REF_MESSAGE_H

#include <stddef.h>

/* printf into buf (may be NULL when len is 0, truncated to fit); returns 1,
 * so that checks read `if (bad) return ref_say(msg, len, "...")`. */
int ref_say(char *buf, size_t len, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
