/* Case files: a verification case as data (docs/adding-a-case.md).
 *
 * A case file, verify/cases/scenes/<case>.case beside the scenes, holds
 * what the C description (vfy_case_desc, driver.h) holds, in INI text read
 * with inih.  Sections and their keys, each the description's member of the
 * same name unless said otherwise:
 *
 *   [case]           suite, summary, quick (true/false: part of the quick
 *                    suite), scene, paper, label, row_progress, derived,
 *                    require, require_why, jump_rows, observes,
 *                    no_simulation, case_progress, columns, title, notes,
 *                    must_fail, power_keys; needs and values (words
 *                    separated by spaces; "needs =" with none: each row's
 *                    references are made, none required of every row);
 *                    needs_why; variant (one per
 *                    variant, in order); batches (COUNT STRIDE); adjust,
 *                    after_rows (a function by name).
 *   [paper rows], [quick rows]
 *                    the sweep: "SECTION.KEY = V1 V2 ..." for each swept
 *                    scene key in order ("SECTION.KEY as NAME = ..." names
 *                    its row value), grid, sets, and row (one per explicit
 *                    row, "LABEL: SET;SET").
 *   [paper columns]  "NAME = V1 V2 ...": a value the paper prints per row
 *                    (nan where it prints none).
 *   [partner NAME]   when, match, has.
 *   [metric NAME], [case metric NAME]
 *                    fn (a metric by name), a, b, x.
 *   [check], [case check]  (each header starts one)
 *                    name, rule (by name), value, expected, x, tol, lo, hi,
 *                    rtol, plus, plus_quick, from, out, builtin_only;
 *                    guard (by name), guard_a, guard_b, guard_x,
 *                    guard_reason; differs_paper, differs_evidence,
 *                    differs_judged_by (a known difference, all three).
 *   [figure]         (each header starts one) kind (curves, points, row
 *                    curves or row points), suffix, quantity, ref (one per
 *                    reference line), x_from, panel_per_row, extrapolated, x,
 *                    series (one per series), x_lo, x_hi, group_by, group
 *                    (one per group), title, xlabel, ylabel; the row kinds'
 *                    curve and ref_curve (LABEL=FUNCTION, one per curve, the
 *                    label ending at the last '='), row_label (each data
 *                    curve once per row; without curves, row curves of row
 *                    series: x, series one per panel), only (NAME=VALUE),
 *                    panel (one per panel), each_row, band, logx, logy,
 *                    key_inside.
 *
 * A number is a decimal number, nan, inf, -inf, or a tolerance of
 * tolerances.h by its name, with a minus sign or without (VFY_TOL_ZMAX): a
 * case file writes no bound literally.  Functions are named as named.h lists
 * them (a name with a fixed x sets the record's x, which the file may then
 * not write).  A text value continues on the lines after it that are indented,
 * joined by one space (none after a \n or a ';'); in text, \n is a line
 * break and \\ a backslash.
 * Comments are lines starting with ';' or '#'; " ;" starts a comment after a
 * value too, so a value never holds it.  A line holds at most 198
 * characters.
 *
 * A line "[include NAME]" reads the file NAME.inc of the case file's folder
 * there, as if its lines stood in its place: the sections several cases
 * share (paper B's exact checks, paper A's tail metrics) are written once.
 * Includes nest up to 8 deep; after an included file, a section header must
 * come before any key.  Messages name the included file and its line.
 *
 * Errors name the file, the line and the key ("FILE:LINE: [check] rule:
 * unknown rule 'relativ'"); nothing of a file that fails is kept.
 */
#ifndef GDSMC_VFY_CASE_FILE_H
#define GDSMC_VFY_CASE_FILE_H

#include <stddef.h>

#include "cases.h"
#include "driver.h"
#include "error.h"
#include "named.h"

/* A parsed case file: the case (its name, suite, summary, quick flag) and
 * its description, and the memory both point into. */
typedef struct vfy_case_file vfy_case_file;

/* Parse NUL-terminated text as the case file of case `name`; `file` stands
 * for the file's name in messages.  Functions are looked up in `tables` (a
 * NULL-terminated list of named-function tables).  Returns SIM_OK with *out
 * (free it with vfy_case_file_free), or SIM_EINVAL or SIM_ENOMEM with msg
 * "FILE:LINE: [SECTION] KEY: what is wrong" and *out NULL. */
sim_status vfy_case_file_parse(const char *text, const char *file, const char *name,
                               const vfy_named_fn *const *tables, vfy_case_file **out,
                               char *msg, size_t msglen);

/* The same for the file at path (SIM_EIO when it cannot be read). */
sim_status vfy_case_file_load(const char *path, const char *name,
                              const vfy_named_fn *const *tables, vfy_case_file **out,
                              char *msg, size_t msglen);

/* The case a parsed file describes (its desc points into the file's memory). */
const vfy_case *vfy_case_file_case(const vfy_case_file *f);

void vfy_case_file_free(vfy_case_file *f);

/* The tolerances of tolerances.h by name (generated at build time from the
 * header), ended by a NULL name. */
typedef struct vfy_tolerance {
    const char *name;
    double value;
} vfy_tolerance;
extern const vfy_tolerance vfy_tolerances[];

#endif
