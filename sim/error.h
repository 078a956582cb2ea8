/* Status codes and error records shared by the engine and the scene layer.
 *
 * Library code never exits or aborts: every fallible function returns a
 * sim_status and, where a handle or caller-owned record is at hand, fills a
 * sim_error with a message that names the parameter (scene key), the value
 * and what is allowed.  sim_error_set() is the one place errors are recorded,
 * so one breakpoint catches them all.
 */
#ifndef GDSMC_SIM_ERROR_H
#define GDSMC_SIM_ERROR_H

#include <stddef.h>

typedef enum sim_status {
    SIM_OK = 0,
    SIM_EINVAL,      /* a parameter or scene value is out of range */
    SIM_ENOMEM,      /* an allocation failed (or would be too large) */
    SIM_EUNSUPPORTED,/* a valid combination no scheme implements yet */
    SIM_EIO,         /* a file could not be read or written */
    SIM_ECANCELED    /* stopped on request (SIGINT, SIGTERM) before finishing */
} sim_status;

/* A recorded error: the scene key at fault ("collisions.restitution", or ""
 * when no single key is), and a message without the key. */
typedef struct sim_error {
    char key[64];
    char msg[448];
} sim_error;

/* Human-readable name of a status ("invalid argument", ...). */
const char *sim_strerror(sim_status status);

/* Record an error in err (which may be NULL) and return status.  The message
 * is printf-formatted.  Use as `return sim_error_set(err, SIM_EINVAL, key, ...)`. */
sim_status sim_error_set(sim_error *err, sim_status status, const char *key,
                         const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#endif
