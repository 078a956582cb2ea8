#include "message.h"

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
