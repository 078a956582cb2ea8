#include "error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

const char *sim_strerror(sim_status status)
{
    switch (status) {
    case SIM_OK: return "success";
    case SIM_EINVAL: return "invalid argument";
    case SIM_ENOMEM: return "out of memory";
    case SIM_EUNSUPPORTED: return "not supported";
    case SIM_EIO: return "input/output error";
    case SIM_ECANCELED: return "stopped on request";
    }
    return "unknown status";
}

sim_status sim_error_set(sim_error *err, sim_status status, const char *key,
                         const char *fmt, ...)
{
    if (err == NULL)
        return status;
    snprintf(err->key, sizeof err->key, "%s", key ? key : "");
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    return status;
}
