/* Functions by name: what a case file (case_file.h) names where a
 * description holds a function pointer (driver.h).  Each entry names one
 * function of one kind; the driver's own (the rules, guards and metrics any
 * case may use) are here, a case's own are in its case_*.c (registry.h).
 * Names are unique across every table (tests/test_case_file.c). */
#ifndef GDSMC_VFY_NAMED_H
#define GDSMC_VFY_NAMED_H

#include <math.h>

#include "driver.h"

typedef enum vfy_fn_kind {
    VFY_FN_METRIC,   /* vfy_metric_fn: [metric] and [case metric] fn */
    VFY_FN_RULE,     /* vfy_rule_fn: [check] rule */
    VFY_FN_GUARD,    /* vfy_guard_fn: [check] guard */
    VFY_FN_HOOK,     /* vfy_hook_fn: [case] after_rows */
    VFY_FN_ADJUST,   /* vfy_adjust_fn: [case] adjust */
    VFY_FN_CURVE,    /* vfy_curve_fn: [figure] curve, ref_curve */
} vfy_fn_kind;

/* One named function: `name` and the member of its kind set (the others
 * NULL).  A metric or rule that takes one of several quantities by its
 * parameter x (an enum of its file) is named once per quantity, with
 * fixed_x set: a case file naming it gets that x, and may not write x
 * itself ("fn = hard_violations_hs", not "fn = hard_metric" with "x = 19").
 * A table ends with a NULL name. */
typedef struct vfy_named_fn {
    const char *name;
    vfy_fn_kind kind;
    vfy_metric_fn metric;
    vfy_rule_fn rule;
    vfy_guard_fn guard;
    vfy_hook_fn hook;
    vfy_adjust_fn adjust;
    vfy_curve_fn curve;
    int fixed_x;
    double x;
} vfy_named_fn;

#define VFY_NAMED_METRIC(NAME, FN) {NAME, VFY_FN_METRIC, .metric = FN}
#define VFY_NAMED_RULE(NAME, FN) {NAME, VFY_FN_RULE, .rule = FN}
#define VFY_NAMED_GUARD(NAME, FN) {NAME, VFY_FN_GUARD, .guard = FN}
#define VFY_NAMED_HOOK(NAME, FN) {NAME, VFY_FN_HOOK, .hook = FN}
#define VFY_NAMED_ADJUST(NAME, FN) {NAME, VFY_FN_ADJUST, .adjust = FN}
#define VFY_NAMED_CURVE(NAME, FN) {NAME, VFY_FN_CURVE, .curve = FN, .x = NAN}
#define VFY_NAMED_METRIC_X(NAME, FN, X) {NAME, VFY_FN_METRIC, .metric = FN, .fixed_x = 1, .x = X}
#define VFY_NAMED_RULE_X(NAME, FN, X) {NAME, VFY_FN_RULE, .rule = FN, .fixed_x = 1, .x = X}
#define VFY_NAMED_CURVE_X(NAME, FN, X) {NAME, VFY_FN_CURVE, .curve = FN, .fixed_x = 1, .x = X}
#define VFY_NAMED_END {NULL, VFY_FN_METRIC, .metric = NULL}

/* The driver's: the rules ("relative", ...), guards ("at_most", ...) and
 * metrics ("max_rel_err", ...) of driver.h and metrics.h, each named as its
 * function without the vfy_rule_, vfy_guard_ or vfy_metric_ prefix. */
extern const vfy_named_fn vfy_driver_named[];

/* The entry of kind `kind` named `name` in table (NULL-name terminated), or
 * NULL. */
const vfy_named_fn *vfy_named_find(const vfy_named_fn *table, vfy_fn_kind kind,
                                   const char *name);

/* The word for a kind ("metric", "rule", ...), for messages. */
const char *vfy_fn_kind_word(vfy_fn_kind kind);

#endif
