/* Helpers shared by the engine tests. */
#ifndef GDSMC_TEST_SIM_UTIL_H
#define GDSMC_TEST_SIM_UTIL_H

#include "engine.h"
#include "ensemble.h"
#include "test_util.h"

/* Build the engine of scene s and run its ensembles into res (the test fails,
 * naming the key, if the engine refuses the scene). */
static inline void run(const sim_scene *s, sim_ensemble_result *res)
{
    sim_engine *e = NULL;
    sim_error err;
    sim_status st = sim_engine_create(s, &e, &err);
    if (st != SIM_OK)
        print_error("%s: %s\n", err.key, err.msg);
    assert_int_equal(st, SIM_OK);
    assert_int_equal(sim_ensemble_run(e, NULL, NULL, res, &err), SIM_OK);
    sim_engine_free(e);
}

#endif
