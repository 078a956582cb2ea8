/* libFuzzer target over case files (case_file.h): whatever the text, the
 * parser returns a status with a message naming the file (never crash, read
 * out of bounds or leak: AddressSanitizer watches), and a case it accepts
 * is freed whole.
 *
 * Built only with clang and -DGDSMC_FUZZ=ON; `make fuzz` runs it with the
 * case files of verify/cases/scenes as the seed corpus. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "case_file.h"
#include "registry.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (text == NULL)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    vfy_case_file *f = NULL;
    char msg[1024] = "";
    sim_status status = vfy_case_file_parse(text, "fuzz.case", "fuzz", vfy_named_tables, &f,
                                            msg, sizeof msg);
    if (status != SIM_OK && strncmp(msg, "fuzz.case", 9) != 0)
        abort();   /* every refusal names the file */
    if ((status == SIM_OK) != (f != NULL))
        abort();
    vfy_case_file_free(f);
    free(text);
    return 0;
}
