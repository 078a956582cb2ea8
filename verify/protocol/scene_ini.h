/* Scene files: INI text (parsed with inih) to a validated sim_scene (docs/scenes.md).
 *
 * Every key is checked as it is read: unknown sections and keys, malformed or
 * out-of-range numbers (strtod with end pointer, errno and finiteness checks),
 * unknown enum words and duplicate keys are refused with a message of the form
 *     FILE:LINE: section.key: what is wrong (allowed ...)
 * before any work starts.  Overrides "section.key=value" (the command line's
 * --set) pass the same checks and are reported as
 *     --set section.key=value: section.key: what is wrong (allowed ...)
 * The first error wins; on failure *scene is not written and nothing is
 * printed anywhere.
 *
 * Syntax: "[section]" lines and "key = value" (or "key: value") lines; leading
 * white space is ignored (there are no continuation lines); comments are lines
 * starting with ';' or '#', and inline comments start with " ;".  A line may
 * hold at most 198 characters (inih's buffer).  Vectors are three numbers
 * separated by spaces; counts (n, ensembles, outputs, seed, layers) are
 * unsigned decimal integers; booleans are true or false.
 *
 * A section's header, or any key of it (from the file or an override), sets
 * its present flag.  Every key set is recorded in scene->keys with its line
 * (overrides: -1), so sim_scene_key_line() finds it.  Checks across keys,
 * after the overrides, name the key at fault (format as vfy_scene_format_error):
 *   - scheme = timestep needs dt; splitting is only for timestep;
 *   - kernel = maxwell implies exponent 0, hard-spheres 1 (an explicit exponent
 *     that differs is an error), vhs needs an explicit exponent in [0, 1];
 *   - initial = two-maxwellians needs all of fraction, mass1, velocity1,
 *     temperature1, mass2, velocity2, temperature2 (no defaults) and refuses
 *     mass, temperature, velocity; those seven keys are refused otherwise;
 *   - heating type = white-noise needs strength (beta) >= 0; gaussian and
 *     non-gaussian take any finite strength; keep_temperature = true only with
 *     type = gaussian and without strength;
 *   - steady.from <= t_end.
 * Overrides may repeat a key (the last wins); a file may not.
 *
 * Thread safety: no global state is touched (inih's option globals are only
 * read); different scenes may be parsed concurrently.
 */
#ifndef GDSMC_VFY_SCENE_INI_H
#define GDSMC_VFY_SCENE_INI_H

#include <stddef.h>
#include <stdio.h>

#include "error.h"
#include "scene.h"

/* Read the scene file at path (at most 1 MiB of text), then apply the
 * overrides in order.  Returns SIM_OK (msg = ""), SIM_EIO (file missing or
 * unreadable: "FILE: cannot open: No such file or directory"), SIM_ENOMEM, or
 * SIM_EINVAL (msg as above; also for NULL arguments).  msg (msglen bytes,
 * truncated to fit) may be NULL. */
sim_status vfy_scene_load(const char *path, const char *const *overrides, size_t noverrides,
                          sim_scene *scene, char *msg, size_t msglen);

/* The same from NUL-terminated text in memory; name stands for the file name in
 * messages and scene->file (tests and the fuzzer use this). */
sim_status vfy_scene_parse(const char *text, const char *name, const char *const *overrides,
                           size_t noverrides, sim_scene *scene, char *msg, size_t msglen);

/* Format an error reported later (by the engine or a reference) about a key of
 * this scene as "FILE:LINE: key: message", "FILE: --set key: message" when an
 * override set the key, "FILE: key: message" when the key kept its default,
 * or "FILE: message" when err->key is empty. */
void vfy_scene_format_error(const sim_scene *scene, const sim_error *err, char *msg,
                            size_t msglen);

/* Write scene s as canonical INI text: the sections present ([scene] and
 * [particles] always), in the table's order, and in each the keys that were
 * set or differ from their defaults (sim_scene_defaults), numbers with 17
 * significant digits, so that parsing the text gives the same scene (the
 * same value for every key; vfy_scene_differs finds none).  Keys that no
 * longer apply after a change in code (splitting once the scheme is jump,
 * the other initial state's keys, the strength with keep_temperature) are
 * left out, as the parser would refuse them.  Returns 0, or -1 when f
 * reports an error. */
int vfy_scene_write(FILE *f, const sim_scene *s);

/* Whether scenes a and b differ in a section's presence or a key's value;
 * if so, key (keylen bytes) names the first: "[shear]" or "particles.n".
 * Where the scenes came from (file, lines) is not compared. */
int vfy_scene_differs(const sim_scene *a, const sim_scene *b, char *key, size_t keylen);

/* The value of number key `key` ("section.key", a K_REAL key: a rate, a
 * constant, restitution, strength ...) in scene s, set or defaulted, into
 * *value (collisions.beta defaulted: the model's factor,
 * sim_scene_collision_rate_factor).  Returns SIM_OK, or SIM_EINVAL with msg ("section.key: unknown
 * key (allowed ...)", "... is not a number key", "the scene has no
 * [section] section") when there is no such value: s may be NULL to check
 * the key's name alone.  `--perturb` reads the value it multiplies here. */
sim_status vfy_scene_real(const sim_scene *s, const char *key, double *value, char *msg,
                          size_t msglen);

/* The value of scene key `key` ("section.key") in s, set or defaulted: 1
 * with a number key's value in *value (a real, a count, the seed), 2 with a
 * word or text key's text in *word ("strang"; valid while s is), 0 when
 * there is no such key, it is a vector, or its section is absent. */
int vfy_scene_key_value(const sim_scene *s, const char *key, double *value, const char **word);

/* Whether scene s meets every requirement in `words` (space-separated, a
 * case's needs of its scene): "[steady]" (the section is present),
 * "![heating]" (absent), "KEY=WORD" for a word key ("scene.scheme=timestep",
 * "particles.zero_momentum=true"), "KEY=X", "KEY>X", "KEY>=X", "KEY<X",
 * "KEY<=X" for a number key ("steady.bins>=8"; a key of an absent section
 * never holds), and "grain_mass=X" (particles.mass, or mass1 for two
 * Maxwellians).  Returns 1; 0 with the first unmet word in msg; -1 with
 * msg saying what is malformed in a word. */
int vfy_scene_requires(const sim_scene *s, const char *words, char *msg, size_t msglen);

/* The class of scene key `key` ("section.key", docs/scenes.md): physics (a
 * solver must honour it or refuse the scene), algorithm (an engine choice a
 * solver may replace with its own, saying so in its result's
 * "# substituted =" line), or unknown. */
enum { VFY_KEY_UNKNOWN, VFY_KEY_PHYSICS, VFY_KEY_ALGORITHM };
int vfy_scene_key_class(const char *key);

#endif
