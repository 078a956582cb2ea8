/* libFuzzer target over the solver protocol's result reader (issue 14):
 * whatever an external solver writes, vfy_result_parse must return a status
 * and a message (never crash, read out of bounds or leak: AddressSanitizer
 * watches), leave nothing allocated when it refuses, and accept only
 * results whose reported numbers are finite with variances >= 0.
 *
 * The scene: t_end = 8, 3 outputs, n = 8, N = 5, with [steady] (4 bins) when
 * the input has an odd number of bytes.  Seeds: tests/fuzz/results/. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "result.h"
#include "scene_ini.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char plain[] = "[scene]\nt_end = 8\noutputs = 3\n[particles]\nn = 8\n"
                                "ensembles = 5\n";
    static const char steady[] = "[scene]\nt_end = 8\noutputs = 3\n[particles]\nn = 8\n"
                                 "ensembles = 5\n[steady]\nbins = 4\n";
    sim_scene scene;
    char msg[512];
    if (vfy_scene_parse(size % 2 ? steady : plain, "fuzz.ini", NULL, 0, &scene,
                        msg, sizeof msg) != SIM_OK)
        abort();
    sim_ensemble_result res;
    vfy_result_info info;
    sim_status status = vfy_result_parse((const char *)data, size, "fuzz.result", &scene, &res,
                                         &info, msg, sizeof msg);
    if (status != SIM_OK) {
        if (msg[0] == '\0' || res.mean != NULL)
            abort();   /* every refusal says why and frees what it took */
        return 0;
    }
    const size_t len = res.outputs * res.observables + res.nsteady;
    for (size_t i = 0; i < len; i++)
        if (!isnan(res.mean[i]) && (!isfinite(res.mean[i]) || !(res.var[i] >= 0.0)))
            abort();
    sim_ensemble_result_free(&res);
    return 0;
}
