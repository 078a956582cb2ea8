#include "result.h"

#include <inttypes.h>

#include "observe.h"
#include "steady.h"

/* The engine's population variance over N ensembles as the protocol's
 * sample variance. */
static double sample_variance(double var, size_t N)
{
    return N > 1 ? var * (double)N / (double)(N - 1) : 0.0;
}

int vfy_result_write(FILE *f, const char *solver, const sim_ensemble_result *res)
{
    const size_t N = res->ensembles;
    fprintf(f, "# gdsmc-result %d\n# solver = %s\n# n = %zu\n# ensembles = %zu\n",
            VFY_RESULT_VERSION, solver, res->n, N);
    fprintf(f, "# cpu_seconds = %.17g\n# events = %" PRIu64 "\n# violations = %" PRIu64 "\n",
            res->cpu_seconds, res->counts.candidates, res->counts.violations);
    fputs("t", f);
    for (int k = 0; k < SIM_OBS_BASE; k++)
        fprintf(f, ",%s,%s_var", sim_observable_name(k), sim_observable_name(k));
    fputc('\n', f);
    for (size_t m = 0; m < res->outputs; m++) {
        fprintf(f, "%.17g", res->t[m]);
        for (int k = 0; k < SIM_OBS_BASE; k++)
            fprintf(f, ",%.17g,%.17g", sim_result_mean(res, m, k),
                    sample_variance(sim_result_var(res, m, k), N));
        fputc('\n', f);
    }
    if (res->nsteady > 0) {
        fputs("# steady\nname,mean,var\n", f);
        for (size_t k = 0; k < res->nsteady; k++) {
            char name[32];
            fprintf(f, "%s,%.17g,%.17g\n", sim_steady_name(k, name, sizeof name),
                    res->steady_mean[k], sample_variance(res->steady_var[k], N));
        }
    }
    return ferror(f) ? -1 : 0;
}
