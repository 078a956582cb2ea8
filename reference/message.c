#include "message.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

int ref_say(char *buf, size_t len, const char *fmt, ...)
{
    if (buf && len > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(buf, len, fmt, ap);
        va_end(ap);
    }
    return 1;
}

int ref_bad_times(const double *t, size_t nt, char *buf, size_t len)
{
    if (!t)
        return ref_say(buf, len, "t is NULL");
    if (nt == 0)
        return ref_say(buf, len, "nt = 0: at least one time (the initial one) is required");
    for (size_t m = 0; m < nt; m++) {
        if (!isfinite(t[m]))
            return ref_say(buf, len, "t[%zu] = %g is not finite", m, t[m]);
        if (m > 0 && !(t[m] > t[m - 1]))
            return ref_say(buf, len,
                           "t[%zu] = %.17g must be > t[%zu] = %.17g (strictly increasing)", m,
                           t[m], m - 1, t[m - 1]);
    }
    return 0;
}
