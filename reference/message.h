/* Messages about bad arguments, shared by the reference modules (internal). */
#ifndef GDSMC_REF_MESSAGE_H
#define GDSMC_REF_MESSAGE_H

#include <stddef.h>

/* printf into buf (may be NULL when len is 0, truncated to fit); returns 1,
 * so that checks read `if (bad) return ref_say(msg, len, "...")`. */
int ref_say(char *buf, size_t len, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* Output times of a CVODE reference: t not NULL, nt >= 1, finite and strictly
 * increasing.  Returns 0, or 1 with the first fault described in buf. */
int ref_bad_times(const double *t, size_t nt, char *buf, size_t len);

#endif
