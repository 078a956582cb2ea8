/* The suites: the cases in suite order and the runs of a suite (suites.h). */
#include "suites.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "driver.h"
#include "table.h"
#include "verdicts.h"

/* The cases, in suite order: case_grw.c (paper A), case_brs.c (paper B). */
extern const vfy_case_desc vfy_grw_ex3, vfy_grw_ex4, vfy_grw_ex5, vfy_grw_ex6, vfy_grw_ex7,
    vfy_grw_ex8;
/* case_brs.c */
extern const vfy_case_desc vfy_brs_ex1, vfy_brs_ex2, vfy_brs_ex3, vfy_brs_ex4, vfy_brs_ex5;
/* case_ms.c (paper C) */
extern const vfy_case_desc vfy_ms_white_noise, vfy_ms_gaussian, vfy_ms_non_gaussian,
    vfy_ms_table1, vfy_ms_tails;
/* case_msg.c (paper D) */
extern const vfy_case_desc vfy_msg_kappa, vfy_msg_sonine, vfy_msg_distribution;
extern const vfy_case_desc vfy_protocol;
/* case_as.c (paper E) */
extern const vfy_case_desc vfy_as_steady;
extern const vfy_case_desc vfy_as_transient;
extern const vfy_case_desc vfy_as_distribution;
extern const vfy_case_desc vfy_as_slab;
extern const vfy_case_desc vfy_as_slab_vs_homogeneous;
/* case_vro.c (issue 4: variance-reduced observation) */
extern const vfy_case_desc vfy_vro_grw_ex3;
/* case_split.c (docs/theory.md §8.5) */
extern const vfy_case_desc vfy_split_ex5;
extern const vfy_case_desc vfy_split_gaussian;
/* case_cost.c (docs/theory.md §1.4: accuracy against CPU cost) */
extern const vfy_case_desc vfy_cost_grw_ex3, vfy_cost_brs_ex2;
extern const vfy_case_desc vfy_cost_split_ex5;
/* case_hard.c (the hard suite, issue #5 item 1) */
extern const vfy_case_desc vfy_hard_dissipation, vfy_hard_nongaussian, vfy_hard_tails,
    vfy_hard_tiny, vfy_hard_long_run, vfy_hard_stiff, vfy_hard_extreme;

static const vfy_case cases[] = {
    {"grw-ex3", "grw", "paper A Ex 3, Table 1: heated Maxwell gas, Emax = O(1/n)", 1,
     &vfy_grw_ex3},
    {"grw-ex4", "grw", "paper A Ex 4, Table 2: cooling Maxwell gas, Emax = O(1/n)", 1,
     &vfy_grw_ex4},
    {"grw-ex5", "grw", "paper A Ex 5: heated hard spheres vs Maxwellian and Sonine closures", 1,
     &vfy_grw_ex5},
    {"grw-ex6", "grw", "paper A Ex 6: the steady tail exponent of heated Maxwell molecules "
     "(b = 1)", 1, &vfy_grw_ex6},
    {"grw-ex7", "grw", "paper A Ex 7: the steady tail exponent of heated hard spheres "
     "(b = 3/2)", 1, &vfy_grw_ex7},
    {"grw-ex8", "grw", "paper A Ex 8: the steady tail exponent of heated VHS, lambda = 1/2 "
     "(b = 5/4)", 1, &vfy_grw_ex8},
    {"vro-grw-ex3", "grw", "paper A Ex 3 observed through the exact conditional expectation "
     "over the pending Brownian increments: the variance reduction", 1, &vfy_vro_grw_ex3},
    {"brs-ex1", "brs", "paper B Ex 1, Table 1: Maxwell kernels with a background, Err = O(1/n)",
     1, &vfy_brs_ex1},
    {"brs-ex2", "brs", "paper B Ex 2, Table 2: Maxwell kernels, drifting background", 1,
     &vfy_brs_ex2},
    {"brs-ex3", "brs", "paper B Ex 3: Maxwell kernels, light background (slow relaxation)", 0,
     &vfy_brs_ex3},
    {"brs-ex4", "brs", "paper B Ex 4: hard spheres, K = 1/8: kinetic T* vs LE and Grad closures",
     1, &vfy_brs_ex4},
    {"brs-ex5", "brs", "paper B Ex 5: hard spheres, K = 1: kinetic T* vs LE and Grad closures", 0,
     &vfy_brs_ex5},
    {"ms-a2-white-noise", "ms", "paper C Fig. 1: steady a2 vs alpha, white noise, vs (C.10)", 1,
     &vfy_ms_white_noise},
    {"ms-a2-gaussian", "ms", "paper C Figs. 4, 6: steady a2, a3 vs alpha, Gaussian (HCS)", 1,
     &vfy_ms_gaussian},
    {"ms-a2-non-gaussian", "ms", "paper C Fig. 8: steady a2 vs alpha, non-Gaussian, vs (C.76)",
     1, &vfy_ms_non_gaussian},
    {"ms-table1", "ms", "paper C Table 1: mu4 direct vs through the exact steady relations", 1,
     &vfy_ms_table1},
    {"ms-tails", "ms", "paper C Figs. 3, 7: high-energy tails G(c), fitted A vs theory", 0,
     &vfy_ms_tails},
    {"msg-kappa", "msg", "paper D Figs. 1, 3: kappa'/kappa0 vs alpha from the heat-flux force,"
     " first Sonine, eps* -> 0 at alpha = 1 vs the exact elastic value", 1, &vfy_msg_kappa},
    {"msg-sonine", "msg", "paper D Figs. 2, 4: Sonine coefficients b'_1..b'_3 from both"
     " estimators vs alpha", 1, &vfy_msg_sonine},
    {"msg-distribution", "msg", "paper D Figs. 5-7: phi(c_x^2), its truncations, beta_1/b'_1,"
     " the heat flux from c_x^2 <= 6", 1, &vfy_msg_distribution},
    {"as-steady", "as", "paper E Figs. 14-16: steady uniform shear flow, IHS and EHS at"
     " a tau0 = 4 and 0.1, beside BGK", 1, &vfy_as_steady},
    {"as-transient", "as", "paper E Figs. 5-13: the transient against s, IHS and EHS at"
     " a tau0 = 4 and 0.1, beside BGK; eta*(a*) collapsing at alpha = 0.5", 1,
     &vfy_as_transient},
    {"as-distribution", "as", "paper E Figs. 13, 17-18: steady R0..R3, the marginals g_x, g_y"
     " and F(C) at alpha = 0.9 and 0.5, IHS and EHS, beside BGK", 1, &vfy_as_distribution},
    {"as-slab", "as", "paper E Sec. IV A, Figs. 1-4: the Lees-Edwards slab from E's two initial"
     " states, IHS and EHS: s(t), profiles, steady stresses", 1, &vfy_as_slab},
    {"as-slab-vs-homogeneous", "as", "paper E Fig. 9: the slab from both initial states"
     " against the homogeneous run, IHS at alpha = 0.9, a tau0 = 4", 1,
     &vfy_as_slab_vs_homogeneous},
    {"split-ex5", "split", "docs/theory.md §8.5: splitting error of the time-step scheme vs the"
     " jump scheme, Euler and Strang", 1, &vfy_split_ex5},
    {"split-gaussian", "split", "docs/theory.md §8.5: the same with the Gaussian thermostat,"
     " which the jump scheme runs exactly: Euler and Strang converge to it", 1,
     &vfy_split_gaussian},
    {"cost-grw-ex3", "cost", "docs/theory.md §1.4: Err (systematic + statistical) against CPU"
     " time over n x N, paper A Ex 3", 1, &vfy_cost_grw_ex3},
    {"cost-brs-ex2", "cost", "docs/theory.md §1.4: Err (systematic + statistical) against CPU"
     " time over n x N, paper B Ex 2", 1, &vfy_cost_brs_ex2},
    {"cost-split-ex5", "cost", "docs/theory.md §1.4: Err (systematic + splitting +"
     " statistical) against CPU time over n, N and h, paper A Ex 5", 1, &vfy_cost_split_ex5},
    {"hard-dissipation", "hard", "very strong dissipation: white-noise heated hard spheres,"
     " alpha = 0.05, 0.1, steady a2, mu4 = 5 mu2, exact energy balance", 1,
     &vfy_hard_dissipation},
    {"hard-nongaussian", "hard", "paper C's non-Gaussian thermostat near v = 0, alpha = 0.05,"
     " 0.1: a2, Eq. (44), depletion at v = 0, momentum to round-off", 1,
     &vfy_hard_nongaussian},
    {"hard-tails", "hard", "paper A Ex 7: growing majorant (no violations), overpopulated"
     " tail, exact energy balance", 1, &vfy_hard_tails},
    {"hard-tiny", "hard", "n = 2, 3, 4: exact finite-n expectations (papers A and B), exact"
     " Gaussian bulk velocity, majorant violations", 1, &vfy_hard_tiny},
    {"hard-long-run", "hard", "1e9 events per system: momentum and energy to round-off, exact"
     " T(0) e^{-kt}, no NaN", 1, &vfy_hard_long_run},
    {"hard-stiff", "hard", "paper B closures with K = 100 and 1e-4 through CVODE: success or a"
     " clear failure, never garbage", 1, &vfy_hard_stiff},
    {"hard-extreme", "hard", "restitution 1e-3 and 1, rate 1e6, T0 = 1e-8 and 1e8 against"
     " exact expectations and the Sonine closure", 1, &vfy_hard_extreme},
    {"protocol", "protocol", "the solver protocol's mechanics in seconds: the time grid and"
     " columns, the variance columns, the steady section", 0, &vfy_protocol},
};

size_t vfy_case_count(void) { return sizeof cases / sizeof *cases; }

const vfy_case *vfy_case_at(size_t i) { return i < vfy_case_count() ? &cases[i] : NULL; }

const vfy_case *vfy_case_find(const char *name)
{
    for (size_t i = 0; i < vfy_case_count(); i++)
        if (strcmp(cases[i].name, name) == 0)
            return &cases[i];
    return NULL;
}

/* The next name of a comma-separated list at *at into name (len bytes),
 * *at moved past it and its comma (NULL after the last); its length. */
static size_t next_name(const char **at, char *name, size_t len)
{
    const size_t n = strcspn(*at, ",");
    snprintf(name, len, "%.*s", (int)n, *at);
    *at = (*at)[n] == ',' ? *at + n + 1 : NULL;
    return n;
}

/* Is `name` one of the comma-separated names of `list`? */
static int in_list(const char *list, const char *name)
{
    char item[128];
    for (const char *at = list; at != NULL;)
        if (next_name(&at, item, sizeof item) < sizeof item && strcmp(item, name) == 0)
            return 1;
    return 0;
}

int vfy_case_list_check(const char *list, char *unknown, size_t len)
{
    char item[128];
    for (const char *at = list; at != NULL;)
        if (next_name(&at, item, sizeof item) >= sizeof item || vfy_case_find(item) == NULL) {
            snprintf(unknown, len, "%s", item);
            return 0;
        }
    return 1;
}

int vfy_suite_exists(const char *name)
{
    if (strcmp(name, "quick") == 0 || strcmp(name, "paper") == 0)
        return 1;
    for (size_t i = 0; i < vfy_case_count(); i++)
        if (strcmp(cases[i].suite, name) == 0)
            return 1;
    return 0;
}

const char *vfy_paper_suites(char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < vfy_case_count(); i++) {
        int seen = 0;
        for (size_t j = 0; j < i && !seen; j++)
            seen = strcmp(cases[j].suite, cases[i].suite) == 0;
        if (!seen && used < len)
            used += (size_t)snprintf(buf + used, len - used, "%s%s", used ? ", " : "",
                                     cases[i].suite);
    }
    return buf;
}

/* "paper" is every paper's case (not the protocol's conformance case). */
static int in_suite(const vfy_case *c, const char *suite)
{
    return (strcmp(suite, "paper") == 0 && strcmp(c->suite, "protocol") != 0)
           || (strcmp(suite, "quick") == 0 && c->quick) || strcmp(suite, c->suite) == 0;
}

int vfy_case_selected(const vfy_case *c, const char *suite, const char *case_name)
{
    return case_name ? in_list(case_name, c->name) : in_suite(c, suite ? suite : "paper");
}

sim_status vfy_run(const char *suite, const char *case_name, const vfy_options *o,
                   vfy_report *r, char *msg, size_t msglen)
{
    if (suite == NULL)
        suite = "paper";
    if (vfy_ensure_dir(o->out_dir) != 0) {
        snprintf(msg, msglen, "%s: cannot create the report directory: %s", o->out_dir,
                 strerror(errno));
        return SIM_EIO;
    }
    for (size_t i = 0; i < vfy_case_count(); i++) {
        const vfy_case *c = &cases[i];
        if (!vfy_case_selected(c, suite, case_name))
            continue;
        if (o->progress && o->dry_run == NULL)
            fprintf(o->progress, "== %s (%s sizes): %s\n", c->name,
                    o->size == VFY_QUICK ? "quick" : "paper", c->summary);
        if (r != NULL)
            r->group = c->name;
        sim_status status = vfy_run_described(c, o, r, msg, msglen);
        if (r != NULL)
            r->group = NULL;
        if (status != SIM_OK)
            return status;
    }
    if (o->dry_run != NULL)   /* no reports: nothing was judged */
        return SIM_OK;
    const char *names[sizeof cases / sizeof *cases];
    for (size_t i = 0; i < vfy_case_count(); i++)
        names[i] = cases[i].name;
    return vfy_write_index(o, o->size == VFY_QUICK ? "quick sizes" : "paper sizes", names,
                           vfy_case_count(), msg, msglen);
}

