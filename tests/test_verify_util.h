/* Shared by the cmocka tests of the verify cases: the source tree's scenes,
 * a fresh temporary report directory, and one case run at quick sizes with
 * a deliberately wrong solver (--solver-set) when asked. */
#ifndef GDSMC_TEST_VERIFY_UTIL_H
#define GDSMC_TEST_VERIFY_UTIL_H

#include <stdlib.h>
#include <string.h>

#include "cases.h"
#include "suites.h"
#include "test_util.h"

static char out_dir[256];
static char scene_dir[512];

/* Group setup: scene_dir from GDSMC_SOURCE_DIR (set by CTest), the case
 * files loaded from it (suites.h), a new out_dir. */
static inline int setup(void **state)
{
    (void)state;
    const char *src = getenv("GDSMC_SOURCE_DIR");
    snprintf(scene_dir, sizeof scene_dir, "%s/verify/cases/scenes", src ? src : "..");
    char msg[1024];
    if (vfy_cases_load(scene_dir, msg, sizeof msg) != SIM_OK) {
        print_error("%s\n", msg);
        return -1;
    }
    snprintf(out_dir, sizeof out_dir, "/tmp/gdsmc-test-XXXXXX");
    return mkdtemp(out_dir) ? 0 : -1;
}

/* Run case_name at quick sizes into *r (the caller frees it): sets change
 * every scene (solver and references), wrong only the simulated one.  Each
 * failed check is printed. */
static inline void run_quick_case(const char *case_name, const char *const *sets,
                                  size_t nsets, const char *const *wrong, size_t nwrong,
                                  vfy_report *r)
{
    vfy_options o = {.size = VFY_QUICK, .out_dir = out_dir, .scene_dir = scene_dir,
                     .overrides = sets, .noverrides = nsets,
                     .solver_overrides = wrong, .nsolver_overrides = nwrong};
    vfy_report_init(r, NULL);
    char msg[512];
    sim_status st = vfy_run("quick", case_name, &o, r, msg, sizeof msg);
    if (st != SIM_OK)
        print_error("%s\n", msg);
    assert_int_equal(st, SIM_OK);
    for (size_t i = 0; i < r->count; i++)
        if (r->checks[i].verdict == VFY_FAIL)
            print_message("  FAIL %s: %s\n", r->checks[i].name, r->checks[i].detail);
}

/* The failed checks of that run; *passed (may be NULL) gets the passed ones. */
static inline size_t count_quick_failed(const char *case_name, const char *const *sets,
                                        size_t nsets, const char *const *wrong, size_t nwrong,
                                        size_t *passed)
{
    vfy_report r;
    run_quick_case(case_name, sets, nsets, wrong, nwrong, &r);
    size_t failed = r.counts[VFY_FAIL], ok = 0;
    for (size_t i = 0; i < r.count; i++)
        ok += r.checks[i].verdict == VFY_PASS;
    if (passed)
        *passed = ok;
    vfy_report_free(&r);
    return failed;
}

#endif
