/* Every function a case file may name (registry.h). */
#include "registry.h"

extern const vfy_named_fn vfy_as_named[], vfy_cost_named[], vfy_grw_named[], vfy_hard_named[],
    vfy_ms_named[], vfy_msg_named[], vfy_protocol_named[], vfy_split_named[];

const vfy_named_fn *const vfy_named_tables[] = {
    vfy_driver_named, vfy_grw_named, vfy_ms_named,   vfy_msg_named,   vfy_as_named,
    vfy_split_named,  vfy_cost_named, vfy_hard_named, vfy_protocol_named, NULL};
