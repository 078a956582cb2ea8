/* The engine's contract (engine.h, sim_engine_create) as a test: every
 * combination of scheme and effects over the registry's sections is built,
 * and the engine must accept exactly those engine.h documents, and refuse
 * every other naming a key of a rule the combination breaks.  The rules here
 * are written from engine.h's text, not from the engine's code, so the header
 * and the code cannot drift apart unnoticed.  The wrong answer this rejects:
 * an engine that accepts a combination it would not simulate (the jump
 * scheme's Gaussian thermostat with no collisions left T at T0 until 0.3.0),
 * or a header that promises one it refuses. */
#include "test_sim_util.h"

#include <stdio.h>
#include <string.h>

#include "engine.h"
#include "scene.h"

enum scheme { JUMP, TIMESTEP, TIMESTEP_SPEED, SLAB, SLAB_JUMP, SCHEMES };
enum collisions { C_NONE, C_MAXWELL, C_VHS, C_HS, C_EHS, C_EHS_ELASTIC, COLLISIONS };
enum heating { H_NONE, H_WHITE, H_GAUSSIAN, H_KEEP_T, H_NON_GAUSSIAN, HEATINGS };

typedef struct combo {
    int scheme, collisions, background, heating, heat_flux, shear, bath, conditional;
} combo;

static const char *const scheme_names[] = {"jump", "timestep", "timestep (relative-speed)",
                                           "slab", "slab (jump)"};
static const char *const collision_names[] = {"none", "maxwell", "vhs", "hard-spheres",
                                              "ehs", "ehs (elastic)"};
static const char *const heating_names[] = {"none", "white-noise", "gaussian",
                                            "gaussian keep_temperature", "non-gaussian"};

static sim_scene scene_of(const combo *c)
{
    sim_scene s;
    sim_scene_defaults(&s);
    s.t_end = 1.0;
    s.outputs = 3;
    s.particles.n = 8;
    s.particles.ensembles = 1;
    s.particles.zero_momentum = 1;
    s.scheme = c->scheme == JUMP || c->scheme == SLAB_JUMP ? SIM_SCHEME_JUMP
                                                           : SIM_SCHEME_TIMESTEP;
    s.dt = 0.1;
    if (c->collisions != C_NONE) {
        s.collisions.present = 1;
        s.collisions.kernel = c->collisions == C_MAXWELL ? SIM_KERNEL_MAXWELL
                              : c->collisions == C_VHS   ? SIM_KERNEL_VHS
                                                         : SIM_KERNEL_HARD_SPHERES;
        s.collisions.exponent = c->collisions == C_MAXWELL ? 0.0
                                : c->collisions == C_VHS   ? 0.5
                                                           : 1.0;
        s.collisions.restitution = c->collisions == C_EHS_ELASTIC ? 1.0 : 0.8;
        s.collisions.model = c->collisions >= C_EHS ? SIM_MODEL_EHS : SIM_MODEL_IHS;
        s.collisions.rule = c->scheme == TIMESTEP_SPEED ? SIM_RULE_RELATIVE_SPEED
                                                        : SIM_RULE_CONTACT;
    }
    if (c->background) {
        s.background.present = 1;
        s.background.density = s.background.mass = s.background.temperature = 1.0;
        s.background.constant = 0.1;
    }
    if (c->heating != H_NONE) {
        s.heating.present = 1;
        s.heating.type = c->heating == H_WHITE          ? SIM_HEATING_WHITE_NOISE
                         : c->heating == H_NON_GAUSSIAN ? SIM_HEATING_NON_GAUSSIAN
                                                        : SIM_HEATING_GAUSSIAN;
        s.heating.keep_temperature = c->heating == H_KEEP_T;
        s.heating.strength = 0.5;
    }
    s.bath.present = c->bath;
    if (c->heat_flux) {
        s.heat_flux.present = 1;
        s.heat_flux.strength = 0.1;
    }
    if (c->shear || c->scheme == SLAB || c->scheme == SLAB_JUMP) {
        s.shear.present = 1;
        s.shear.rate = 0.5;
        s.shear.boundary = c->shear ? SIM_SHEAR_HOMOGENEOUS : SIM_SHEAR_LEES_EDWARDS;
        s.shear.length = 1.0;
        s.shear.layers = 4;
    }
    s.observation = c->conditional ? SIM_OBSERVE_CONDITIONAL : SIM_OBSERVE_SAMPLED;
    return s;
}

/* The keys a refusal may name: those of every rule of engine.h the
 * combination breaks ("" when it breaks none). */
typedef struct keys {
    char list[256];
} keys;

/* Whether key is an item of k's list: ",key," in ",list" (so that
 * "collisions" is not found in "collisions.model,"). */
static int names(const keys *k, const char *key)
{
    char item[72], list[sizeof k->list + 1];
    snprintf(item, sizeof item, ",%s,", key);
    snprintf(list, sizeof list, ",%s", k->list);
    return strstr(list, item) != NULL;
}

static void broken(keys *k, const char *key)
{
    if (!names(k, key))
        snprintf(k->list + strlen(k->list), sizeof k->list - strlen(k->list), "%s,", key);
}

/* engine.h: the Lees-Edwards slab. */
static void slab_rules(const combo *c, keys *k)
{
    if (c->scheme == SLAB_JUMP)
        broken(k, "shear.boundary");
    if (c->collisions != C_HS && c->collisions != C_EHS && c->collisions != C_EHS_ELASTIC)
        broken(k, "shear.boundary");
    if (c->heating != H_NONE || c->background || c->heat_flux || c->bath)
        broken(k, "shear.boundary");
    if (c->background && c->scheme == SLAB)
        broken(k, "background");
    if (c->conditional)
        broken(k, "scene.observation");
}

/* engine.h: the time-step scheme. */
static void timestep_rules(const combo *c, keys *k)
{
    if (c->background)
        broken(k, "background");
    if (c->heat_flux && c->heating != H_NONE)
        broken(k, "heating.type");
    if (c->conditional)
        broken(k, "scene.observation");
}

/* engine.h: the jump scheme. */
static void jump_rules(const combo *c, keys *k)
{
    const int drag = c->collisions == C_EHS;   /* the inelastic EHS gas's drag */
    const int flows = (c->heating != H_NONE) + c->shear + drag + c->heat_flux + c->bath;
    const int only_collisions = c->collisions != C_NONE && !c->background;
    if (c->heat_flux)
        broken(k, "scene.scheme");
    if (c->heating == H_NON_GAUSSIAN)
        broken(k, "heating.type");
    if ((c->heating == H_GAUSSIAN || c->heating == H_KEEP_T) && !only_collisions)
        broken(k, "heating.type");
    if (drag && !(c->shear && flows == 2))
        broken(k, "collisions.model");
    if (drag && c->shear && flows == 2 && !only_collisions)
        broken(k, "collisions");
    if (flows > 1 && !(drag && c->shear && flows == 2))
        broken(k, c->heating != H_NONE ? "heating.type" : "scene.scheme");
    if (c->conditional
        && (c->shear || drag || c->bath || (c->heating != H_NONE && c->heating != H_WHITE)))
        broken(k, "scene.observation");
}

static keys rules(const combo *c)
{
    keys k = {""};
    if (c->scheme == SLAB || c->scheme == SLAB_JUMP)
        slab_rules(c, &k);
    else if (c->scheme == JUMP)
        jump_rules(c, &k);
    else
        timestep_rules(c, &k);
    return k;
}

static void test_every_combination(void **state)
{
    (void)state;
    size_t accepted = 0, refused = 0, wrong = 0;
    combo c;
    for (c.scheme = 0; c.scheme < SCHEMES; c.scheme++)
    for (c.collisions = 0; c.collisions < COLLISIONS; c.collisions++)
    for (c.background = 0; c.background < 2; c.background++)
    for (c.heating = 0; c.heating < HEATINGS; c.heating++)
    for (c.heat_flux = 0; c.heat_flux < 2; c.heat_flux++)
    for (c.shear = 0; c.shear < 2; c.shear++)
    for (c.bath = 0; c.bath < 2; c.bath++)
    for (c.conditional = 0; c.conditional < 2; c.conditional++) {
        if ((c.scheme == SLAB || c.scheme == SLAB_JUMP) && c.shear)
            continue;   /* the slab is the shear */
        const sim_scene s = scene_of(&c);
        const keys expect = rules(&c);
        sim_engine *e = NULL;
        sim_error err = {{0}, {0}};
        const sim_status st = sim_engine_create(&s, &e, &err);
        sim_engine_free(e);
        const int ok = expect.list[0] == '\0' ? st == SIM_OK
                                              : st == SIM_EUNSUPPORTED && names(&expect, err.key);
        accepted += st == SIM_OK;
        refused += st != SIM_OK;
        if (!ok && wrong++ < 10)
            print_error("%s, collisions %s, background %d, heating %s, heat-flux %d, shear %d, "
                        "bath %d, conditional %d: engine %s (%s: %s), engine.h %s%s\n",
                        scheme_names[c.scheme], collision_names[c.collisions], c.background,
                        heating_names[c.heating], c.heat_flux, c.shear, c.bath, c.conditional,
                        st == SIM_OK ? "accepts" : "refuses", err.key, err.msg,
                        expect.list[0] ? "refuses naming one of " : "accepts", expect.list);
    }
    print_message("%zu combinations accepted, %zu refused, %zu against engine.h\n", accepted,
                  refused, wrong);
    assert_int_equal(wrong, 0);
    assert_true(accepted > 200 && refused > 2000);   /* the grid spans both */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_combination),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
