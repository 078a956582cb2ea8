/* Scene files: INI text (parsed with inih) to a validated sim_scene (SPEC §2).
 *
 * Every key is checked as it is read: unknown sections and keys, malformed or
 * out-of-range numbers (strtod with end pointer, errno and finiteness checks),
 * unknown enum words and duplicate keys are refused with a message of the form
 *     FILE:LINE: section.key: what is wrong (allowed ...)
 * before any work starts.  Overrides "section.key=value" (the command line's
 * --set) pass the same checks and are reported as
 *     --set section.key=value: section.key: what is wrong (allowed ...)
 * On failure the scene is left unspecified and nothing is written anywhere.
 */
#ifndef GDSMC_VFY_SCENE_INI_H
#define GDSMC_VFY_SCENE_INI_H

#include <stddef.h>

#include "error.h"
#include "scene.h"

/* Read the scene file at path, then apply the overrides in order.  Returns
 * SIM_OK, SIM_EIO (file missing or unreadable: msg names the file and the
 * system's reason) or SIM_EINVAL (msg as above). */
sim_status vfy_scene_load(const char *path, const char *const *overrides, size_t noverrides,
                          sim_scene *scene, char *msg, size_t msglen);

/* The same from text in memory; name stands for the file name in messages
 * (tests and the fuzzer use this). */
sim_status vfy_scene_parse(const char *text, const char *name, const char *const *overrides,
                           size_t noverrides, sim_scene *scene, char *msg, size_t msglen);

/* Format an error reported later (by the engine or a reference) about a key of
 * this scene as "FILE:LINE: key: message", or "FILE: key: message" when the key
 * kept its default, or "FILE: message" when err->key is empty. */
void vfy_scene_format_error(const sim_scene *scene, const sim_error *err, char *msg,
                            size_t msglen);

#endif
