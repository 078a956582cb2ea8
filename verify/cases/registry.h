/* Every function a case file may name (named.h): the driver's and those of
 * the cases' own C (case_*.c), the tables case_file.h looks names up in. */
#ifndef GDSMC_VFY_REGISTRY_H
#define GDSMC_VFY_REGISTRY_H

#include "named.h"

/* NULL-terminated: vfy_driver_named first, then each case_*.c's table. */
extern const vfy_named_fn *const vfy_named_tables[];

#endif
