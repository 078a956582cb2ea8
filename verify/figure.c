#include "figure.h"

#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>

#include "table.h"

int vfy_gnuplot(const char *script_path)
{
    if (!vfy_writes_files())   /* another process (MPI rank 0) draws it */
        return 0;
    if (system("command -v gnuplot >/dev/null 2>&1") != 0)
        return 0;
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "gnuplot '%s' 2>/dev/null", script_path);
    int status = system(cmd);
    return status == 0 ? 1 : -1;
}
