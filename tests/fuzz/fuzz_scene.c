/* libFuzzer target over scene parsing and validation (issue 5): the text of a
 * scene file, then the engine's own checks of the parsed scene.  Whatever the
 * input, the parser must return a status and a message (never crash, read out
 * of bounds or leak: AddressSanitizer watches), and a scene it accepts must be
 * one the engine either builds or refuses with a key named.
 *
 * Built only with clang and -DGDSMC_FUZZ=ON; `make fuzz` runs it with the
 * scenes of verify/cases/scenes as the seed corpus. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine.h"
#include "scene_ini.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (text == NULL)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    sim_scene scene;
    char msg[512];
    sim_status status = vfy_scene_parse(text, "fuzz.ini", NULL, 0, &scene, msg, sizeof msg);
    if (status != SIM_OK && msg[0] == '\0')
        abort();   /* every refusal says why */
    if (status == SIM_OK) {
        sim_engine *engine = NULL;
        sim_error err = {{0}, {0}};
        status = sim_engine_create(&scene, &engine, &err);
        if (status != SIM_OK && err.msg[0] == '\0')
            abort();
        sim_engine_free(engine);
    }
    free(text);
    return 0;
}
