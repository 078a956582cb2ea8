/* The driver's functions by name (named.h). */
#include "named.h"

#include <string.h>

#include "metrics.h"

const vfy_named_fn vfy_driver_named[] = {
    VFY_NAMED_RULE("relative", vfy_rule_relative),
    VFY_NAMED_RULE("range", vfy_rule_range),
    VFY_NAMED_RULE("absolute", vfy_rule_absolute),
    VFY_NAMED_RULE("count", vfy_rule_count),
    VFY_NAMED_RULE("violations", vfy_rule_violations),
    VFY_NAMED_RULE("zscore", vfy_rule_zscore),
    VFY_NAMED_RULE("zscore_pair", vfy_rule_zscore_pair),
    VFY_NAMED_RULE("printed", vfy_rule_printed),
    VFY_NAMED_GUARD("at_most", vfy_guard_at_most),
    VFY_NAMED_GUARD("only_at_most", vfy_guard_only_at_most),
    VFY_NAMED_GUARD("at_least", vfy_guard_at_least),
    VFY_NAMED_GUARD("only_at_least", vfy_guard_only_at_least),
    VFY_NAMED_GUARD("unless", vfy_guard_unless),
    VFY_NAMED_GUARD("only_unless", vfy_guard_only_unless),
    VFY_NAMED_GUARD("paper_sizes", vfy_guard_paper_sizes),
    VFY_NAMED_GUARD("after_first", vfy_guard_after_first),
    VFY_NAMED_GUARD("clean_pair", vfy_guard_clean_pair),
    VFY_NAMED_METRIC("max_rel_err", vfy_metric_max_rel_err),
    VFY_NAMED_METRIC("max_rel_ci", vfy_metric_max_rel_ci),
    VFY_NAMED_METRIC("max_ratio_dev", vfy_metric_max_ratio_dev),
    VFY_NAMED_METRIC("final_mean", vfy_metric_final_mean),
    VFY_NAMED_METRIC("final_ci", vfy_metric_final_ci),
    VFY_NAMED_METRIC("fictitious_fraction", vfy_metric_fictitious_fraction),
    VFY_NAMED_METRIC("variance_ratio", vfy_metric_variance_ratio),
    VFY_NAMED_METRIC("max_velocity", vfy_metric_max_velocity),
    VFY_NAMED_METRIC("ratio_previous", vfy_metric_ratio_previous),
    VFY_NAMED_METRIC("sum", vfy_metric_sum),
    VFY_NAMED_METRIC("percent_diff", vfy_metric_percent_diff),
    VFY_NAMED_METRIC("percent_of", vfy_metric_percent_of),
    VFY_NAMED_METRIC("max_of", vfy_metric_max_of),
    VFY_NAMED_METRIC("abs_widened", vfy_metric_abs_widened),
    VFY_NAMED_METRIC("sonine_ratio", vfy_metric_sonine_ratio),
    VFY_NAMED_METRIC("named_by_text", vfy_metric_named_by_text),
    VFY_NAMED_METRIC("student_ci", vfy_metric_student_ci),
    VFY_NAMED_METRIC("variants_sum", vfy_metric_variants_sum),
    VFY_NAMED_METRIC("partner_z", vfy_metric_partner_z),
    VFY_NAMED_METRIC("partner_percent", vfy_metric_partner_percent),
    VFY_NAMED_METRIC("partner_percent_ci", vfy_metric_partner_percent_ci),
    VFY_NAMED_METRIC("product", vfy_metric_product),
    VFY_NAMED_METRIC("constant", vfy_metric_constant),
    VFY_NAMED_METRIC("rows_min", vfy_metric_rows_min),
    VFY_NAMED_METRIC("first_row", vfy_metric_first_row),
    VFY_NAMED_METRIC("last_row", vfy_metric_last_row),
    VFY_NAMED_METRIC("rows_extrapolate", vfy_metric_rows_extrapolate),
    VFY_NAMED_METRIC("batch_mean", vfy_metric_batch_mean),
    VFY_NAMED_METRIC("batch_se", vfy_metric_batch_se),
    VFY_NAMED_METRIC("batch_t_ci", vfy_metric_batch_t_ci),
    VFY_NAMED_METRIC("max_rel_diff", vfy_metric_max_rel_diff),
    VFY_NAMED_METRIC("max_abs_diff", vfy_metric_max_abs_diff),
    VFY_NAMED_METRIC("per", vfy_metric_per),
    VFY_NAMED_METRIC("heating_strength", vfy_metric_heating_strength),
    VFY_NAMED_METRIC("time_step", vfy_metric_time_step),
    VFY_NAMED_END};

const vfy_named_fn *vfy_named_find(const vfy_named_fn *table, vfy_fn_kind kind,
                                   const char *name)
{
    for (const vfy_named_fn *e = table; e->name != NULL; e++)
        if (e->kind == kind && strcmp(e->name, name) == 0)
            return e;
    return NULL;
}

const char *vfy_fn_kind_word(vfy_fn_kind kind)
{
    static const char *const words[] = {"metric", "rule", "guard", "hook", "adjust", "curve"};
    return (size_t)kind < sizeof words / sizeof *words ? words[kind] : "function";
}
