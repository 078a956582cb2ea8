/* Tests of verify/protocol/scene_ini.c: scene files to sim_scene (docs/scenes.md).
 *
 * Good scenes are checked field by field, with their present flags and key
 * lines; the trap group provokes each kind of bad input and asserts the
 * status and the exact message.  The engine trap and reference trap groups
 * do the same for scenes that parse but that sim_engine_create() or
 * vfy_scene_references() refuse (docs/scenes.md, "Keys together": a combination no scheme supports
 * gets a clear error naming the file, line and key), with the message as
 * `gdsmc run` and `gdsmc reference` print it (vfy_scene_format_error).
 * GDSMC_SOURCE_DIR (set by CTest) locates verify/cases/scenes/, whose files must
 * all load.
 */
#include <dirent.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "engine.h"
#include "scene_ini.h"
#include "scene_refs.h"
#include "test_util.h"

static const char *source_dir(void)
{
    const char *dir = getenv("GDSMC_SOURCE_DIR");
    return dir && dir[0] ? dir : "..";
}

static void assert_vec(const double v[3], double x, double y, double z)
{
    assert_close(v[0], x, 0.0, 0.0);
    assert_close(v[1], y, 0.0, 0.0);
    assert_close(v[2], z, 0.0, 0.0);
}

static void parse_ok(const char *text, const char *const *ov, size_t nov, sim_scene *s)
{
    char msg[1024] = "unset";
    sim_status st = vfy_scene_parse(text, "t.ini", ov, nov, s, msg, sizeof msg);
    if (st != SIM_OK)
        print_error("unexpected error: %s\n", msg);
    assert_int_equal(st, SIM_OK);
    assert_string_equal(msg, "");
}

/* ---- good scenes ------------------------------------------------------- */

/* Every key but those of two-maxwellians, with high-entropy values. */
static const char good_text[] =
    "; a scene with every effect\n"                    /*  1 */
    "# comment styles: ';' and '#' at line start\n"    /*  2 */
    "[scene]\n"                                        /*  3 */
    "title = Good scene #1\n"                          /*  4 */
    "scheme = timestep\n"                              /*  5 */
    "dt = 0.015625\n"                                  /*  6 */
    "t_end = 2.385\n"                                  /*  7 */
    "outputs = 17\n"                                   /*  8 */
    "seed = 18446744073709551615\n"                    /*  9 */
    "\n"                                               /* 10 */
    "[particles]\n"                                    /* 11 */
    "n = 1000\n"                                       /* 12 */
    "ensembles = 37\n"                                 /* 13 */
    "initial = shell\n"                                /* 14 */
    "mass = 2.5\n"                                     /* 15 */
    "temperature = 1.75\n"                             /* 16 */
    "velocity = 0.25 -1.5 3e-2\n"                      /* 17 */
    "zero_momentum = true\n"                           /* 18 */
    "[collisions]\n"                                   /* 19 */
    "kernel = vhs\n"                                   /* 20 */
    "exponent = 0.35\n"                                /* 21 */
    "constant = 0.0795774715459476678\n"               /* 22 */
    "rate = 4.125\n"                                   /* 23 */
    "restitution = 0.85 ; inline comment\n"            /* 24 */
    "model = ehs\n"                                    /* 25 */
    "[heating]\n"                                      /* 26 */
    "type = non-gaussian\n"                            /* 27 */
    "strength = -0.375\n"                              /* 28 */
    "[background]\n"                                   /* 29 */
    "density = 1.25\n"                                 /* 30 */
    "mass = 0.125\n"                                   /* 31 */
    "temperature = 3.5\n"                              /* 32 */
    "velocity = 0 1 -2\n"                              /* 33 */
    "kernel = hard-spheres\n"                          /* 34 */
    "constant = 0.5\n"                                 /* 35 */
    "[shear]\n"                                        /* 36 */
    "rate = -0.7\n"                                    /* 37 */
    "boundary = lees-edwards\n"                        /* 38 */
    "length = 6.25\n"                                  /* 39 */
    "layers = 12\n"                                    /* 40 */
    "[heat-flux]\n"                                    /* 41 */
    "strength = 0.0625\n";                             /* 42 */

static void test_good_scene(void **state)
{
    (void)state;
    sim_scene s;
    parse_ok(good_text, NULL, 0, &s);

    assert_string_equal(s.file, "t.ini");
    assert_string_equal(s.title, "Good scene #1");
    assert_int_equal(s.scheme, SIM_SCHEME_TIMESTEP);
    assert_close(s.dt, 0.015625, 0.0, 0.0);
    assert_close(s.t_end, 2.385, 0.0, 0.0);
    assert_int_equal(s.outputs, 17);
    assert_true(s.seed == UINT64_MAX);

    assert_int_equal(s.particles.n, 1000);
    assert_int_equal(s.particles.ensembles, 37);
    assert_int_equal(s.particles.initial, SIM_INITIAL_SHELL);
    assert_close(s.particles.maxwellian.mass, 2.5, 0.0, 0.0);
    assert_close(s.particles.maxwellian.temperature, 1.75, 0.0, 0.0);
    assert_vec(s.particles.maxwellian.velocity, 0.25, -1.5, 3e-2);
    assert_int_equal(s.particles.zero_momentum, 1);

    assert_int_equal(s.collisions.present, 1);
    assert_int_equal(s.collisions.kernel, SIM_KERNEL_VHS);
    assert_close(s.collisions.exponent, 0.35, 0.0, 0.0);
    assert_close(s.collisions.constant, 1.0 / (4.0 * M_PI), 1e-15, 0.0);
    assert_close(s.collisions.rate, 4.125, 0.0, 0.0);
    assert_close(s.collisions.restitution, 0.85, 0.0, 0.0);
    assert_int_equal(s.collisions.model, SIM_MODEL_EHS);

    assert_int_equal(s.heating.present, 1);
    assert_int_equal(s.heating.type, SIM_HEATING_NON_GAUSSIAN);
    assert_close(s.heating.strength, -0.375, 0.0, 0.0);

    assert_int_equal(s.background.present, 1);
    assert_close(s.background.density, 1.25, 0.0, 0.0);
    assert_close(s.background.mass, 0.125, 0.0, 0.0);
    assert_close(s.background.temperature, 3.5, 0.0, 0.0);
    assert_vec(s.background.velocity, 0.0, 1.0, -2.0);
    assert_int_equal(s.background.kernel, SIM_KERNEL_HARD_SPHERES);
    assert_close(s.background.constant, 0.5, 0.0, 0.0);

    assert_int_equal(s.shear.present, 1);
    assert_close(s.shear.rate, -0.7, 0.0, 0.0);
    assert_int_equal(s.shear.boundary, SIM_SHEAR_LEES_EDWARDS);
    assert_close(s.shear.length, 6.25, 0.0, 0.0);
    assert_int_equal(s.shear.layers, 12);

    assert_int_equal(s.heat_flux.present, 1);
    assert_close(s.heat_flux.strength, 0.0625, 0.0, 0.0);

    static const struct { const char *key; int line; } lines[] = {
        {"scene.title", 4}, {"scene.scheme", 5}, {"scene.dt", 6}, {"scene.t_end", 7},
        {"scene.outputs", 8}, {"scene.seed", 9}, {"particles.n", 12},
        {"particles.ensembles", 13}, {"particles.initial", 14}, {"particles.mass", 15},
        {"particles.temperature", 16}, {"particles.velocity", 17},
        {"particles.zero_momentum", 18}, {"collisions.kernel", 20},
        {"collisions.exponent", 21}, {"collisions.constant", 22}, {"collisions.rate", 23},
        {"collisions.restitution", 24}, {"collisions.model", 25}, {"heating.type", 27},
        {"heating.strength", 28}, {"background.density", 30}, {"background.mass", 31},
        {"background.temperature", 32}, {"background.velocity", 33},
        {"background.kernel", 34}, {"background.constant", 35}, {"shear.rate", 37},
        {"shear.boundary", 38}, {"shear.length", 39}, {"shear.layers", 40},
        {"heat-flux.strength", 42},
        {"particles.fraction", 0}, {"particles.mass1", 0}, {"no.such", 0},
    };
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        if (sim_scene_key_line(&s, lines[i].key) != lines[i].line)
            print_error("%s: line %d, expected %d\n", lines[i].key,
                        sim_scene_key_line(&s, lines[i].key), lines[i].line);
        assert_int_equal(sim_scene_key_line(&s, lines[i].key), lines[i].line);
    }
    assert_int_equal(s.nkeys, 32);
}

/* Paper B Ex 1 initial state (docs/theory.md §12.1), hard spheres with the implied exponent. */
/* The keys of the time-step scheme, the Gaussian thermostat's rescaling and
 * the steady-state observers (docs/theory.md §10), and their defaults. */
static void test_timestep_and_steady_keys(void **state)
{
    (void)state;
    sim_scene s;
    parse_ok("[scene]\nscheme = timestep\ndt = 0.0375\nsplitting = strang\nt_end = 3.5\n"
             "[heating]\ntype = gaussian\nkeep_temperature = true\n"
             "[steady]\nfrom = 1.25\npairs = 12345\nbins = 48\nc_max = 6.5\n",
             NULL, 0, &s);
    assert_int_equal(s.splitting, SIM_SPLIT_STRANG);
    assert_int_equal(s.heating.type, SIM_HEATING_GAUSSIAN);
    assert_int_equal(s.heating.keep_temperature, 1);
    assert_int_equal(s.steady.present, 1);
    assert_close(s.steady.from, 1.25, 0.0, 0.0);
    assert_int_equal(s.steady.pairs, 12345);
    assert_int_equal(s.steady.bins, 48);
    assert_close(s.steady.c_max, 6.5, 0.0, 0.0);
    assert_int_equal(sim_scene_key_line(&s, "steady.c_max"), 13);

    parse_ok("[scene]\nscheme = timestep\ndt = 0.5\n[steady]\n", NULL, 0, &s);
    assert_int_equal(s.splitting, SIM_SPLIT_EULER);
    assert_int_equal(s.heating.keep_temperature, 0);
    assert_int_equal(s.steady.present, 1);   /* an empty section turns the observers on */
    assert_close(s.steady.from, 0.0, 0.0, 0.0);
    assert_int_equal(s.steady.pairs, 0);
    assert_int_equal(s.steady.bins, 0);
    assert_close(s.steady.c_max, 5.0, 0.0, 0.0);
}

static void test_two_maxwellians(void **state)
{
    (void)state;
    static const char text[] =
        "[particles]\n"
        "initial = two-maxwellians\n"
        "fraction = 0.5\n"
        "mass1 = 1\n"
        "velocity1 = -2 2 0\n"
        "temperature1 = 1.5\n"
        "mass2 = 1.25\n"
        "velocity2 = 2 0 0\n"
        "temperature2 = 0.75\n"
        "zero_momentum = false\n"
        "[collisions]\n"
        "kernel = hard-spheres\n";
    sim_scene s;
    parse_ok(text, NULL, 0, &s);
    assert_int_equal(s.particles.initial, SIM_INITIAL_TWO_MAXWELLIANS);
    assert_close(s.particles.fraction, 0.5, 0.0, 0.0);
    assert_close(s.particles.first.mass, 1.0, 0.0, 0.0);
    assert_vec(s.particles.first.velocity, -2.0, 2.0, 0.0);
    assert_close(s.particles.first.temperature, 1.5, 0.0, 0.0);
    assert_close(s.particles.second.mass, 1.25, 0.0, 0.0);
    assert_vec(s.particles.second.velocity, 2.0, 0.0, 0.0);
    assert_close(s.particles.second.temperature, 0.75, 0.0, 0.0);
    assert_int_equal(s.particles.zero_momentum, 0);
    assert_int_equal(sim_scene_key_line(&s, "particles.temperature2"), 9);

    assert_int_equal(s.collisions.kernel, SIM_KERNEL_HARD_SPHERES);
    assert_close(s.collisions.exponent, 1.0, 0.0, 0.0);  /* implied by the kernel */
    assert_int_equal(sim_scene_key_line(&s, "collisions.exponent"), 0);
    assert_int_equal(s.heating.present, 0);
    assert_int_equal(s.background.present, 0);
    assert_int_equal(s.shear.present, 0);
    assert_int_equal(s.heat_flux.present, 0);
}

/* A case's requirements of its scene (vfy_scene_requires): each kind of word
 * holds where it should and fails where it should, naming the unmet word;
 * a malformed word is an error, not a failed requirement. */
static void test_requirements(void **state)
{
    (void)state;
    static const char text[] = "[scene]\nscheme = timestep\ndt = 0.1\n"
                               "[particles]\nn = 100\nmass = 2\nzero_momentum = true\n"
                               "[collisions]\nkernel = hard-spheres\nrestitution = 0.8\n"
                               "[steady]\nfrom = 1\nbins = 8\n";
    sim_scene s;
    char msg[256];
    parse_ok(text, NULL, 0, &s);
    assert_int_equal(vfy_scene_requires(&s, "[steady] ![heating] scene.scheme=timestep "
                                            "particles.zero_momentum=true steady.bins>=8 "
                                            "steady.bins<9 particles.n>99 "
                                            "collisions.restitution<=0.8 grain_mass=2",
                                        msg, sizeof msg),
                     1);
    assert_int_equal(vfy_scene_requires(&s, "", msg, sizeof msg), 1);
    const char *const unmet[] = {"[heating]", "![steady]", "scene.scheme=jump",
                                 "steady.bins>8", "particles.n<100", "grain_mass=1",
                                 "heating.type=white-noise", "heating.strength>0"};
    for (size_t i = 0; i < sizeof unmet / sizeof *unmet; i++) {
        char words[64];
        snprintf(words, sizeof words, "[steady] %s scene.scheme=timestep", unmet[i]);
        assert_int_equal(vfy_scene_requires(&s, words, msg, sizeof msg), 0);
        assert_string_equal(msg, unmet[i]);
    }
    const char *const malformed[] = {"[nosuch]", "[steady", "steady.nosuch=1", "steady.bins",
                                     "scene.scheme>jump", "scene.scheme=nosuch",
                                     "steady.bins>=x", "scene.title=x"};
    for (size_t i = 0; i < sizeof malformed / sizeof *malformed; i++) {
        msg[0] = '\0';
        assert_int_equal(vfy_scene_requires(&s, malformed[i], msg, sizeof msg), -1);
        assert_true(strlen(msg) > 0);
    }
}

/* Absent keys keep sim_scene_defaults(); an empty section is still present. */
static void test_defaults_and_empty_section(void **state)
{
    (void)state;
    sim_scene s, d;
    parse_ok("[heat-flux]\n", NULL, 0, &s);
    sim_scene_defaults(&d);
    assert_int_equal(s.heat_flux.present, 1);
    assert_int_equal(s.collisions.present, 0);
    assert_int_equal(s.nkeys, 0);
    assert_int_equal(s.scheme, d.scheme);
    assert_close(s.t_end, d.t_end, 0.0, 0.0);
    assert_int_equal(s.outputs, d.outputs);
    assert_true(s.seed == d.seed);
    assert_int_equal(s.particles.n, d.particles.n);
    assert_close(s.collisions.constant, d.collisions.constant, 0.0, 0.0);
    assert_close(s.collisions.restitution, d.collisions.restitution, 0.0, 0.0);

    parse_ok("", NULL, 0, &s);  /* an empty file is the default scene */
    assert_int_equal(s.heat_flux.present, 0);
}

/* Indentation, CRLF, a byte-order mark, "key: value", inline ';' comments. */
static void test_layout(void **state)
{
    (void)state;
    sim_scene s;
    parse_ok("\xEF\xBB\xBF[scene]\r\n"
             "    t_end = 3.25\r\n"
             "\tseed: 42 ; the answer\r\n"
             "  [collisions]\r\n"
             "  restitution = 0.9\r\n",
             NULL, 0, &s);
    assert_close(s.t_end, 3.25, 0.0, 0.0);
    assert_true(s.seed == 42);
    assert_close(s.collisions.restitution, 0.9, 0.0, 0.0);
    assert_int_equal(sim_scene_key_line(&s, "scene.seed"), 3);
    assert_int_equal(sim_scene_key_line(&s, "collisions.restitution"), 5);
}

static void test_overrides(void **state)
{
    (void)state;
    static const char text[] = "[scene]\n"
                               "t_end = 8\n"
                               "[collisions]\n"
                               "restitution = 0.5\n";
    const char *ov[] = {"collisions.restitution=0.25", " heating.strength = 2.5 ",
                        "shear.rate=1.5", "scene.seed=7", "collisions.restitution=0.75",
                        "scene.title=a = b"};
    sim_scene s;
    parse_ok(text, ov, sizeof ov / sizeof ov[0], &s);
    assert_close(s.t_end, 8.0, 0.0, 0.0);
    assert_int_equal(sim_scene_key_line(&s, "scene.t_end"), 2);
    assert_close(s.collisions.restitution, 0.75, 0.0, 0.0);  /* the last one wins */
    assert_int_equal(sim_scene_key_line(&s, "collisions.restitution"), -1);
    assert_int_equal(s.heating.present, 1);  /* an override makes its section present */
    assert_close(s.heating.strength, 2.5, 0.0, 0.0);
    assert_int_equal(s.shear.present, 1);
    assert_close(s.shear.rate, 1.5, 0.0, 0.0);
    assert_true(s.seed == 7);
    assert_string_equal(s.title, "a = b");
    assert_int_equal(sim_scene_key_line(&s, "shear.rate"), -1);
    assert_int_equal(s.nkeys, 6);
}

static void test_format_error(void **state)
{
    (void)state;
    const char *ov[] = {"heating.strength=0.5"};
    sim_scene s;
    sim_error err;
    char msg[512];
    parse_ok("[collisions]\nrestitution = 0.5\n", ov, 1, &s);

    sim_error_set(&err, SIM_EUNSUPPORTED, "collisions.restitution", "not with %s", "shear");
    vfy_scene_format_error(&s, &err, msg, sizeof msg);
    assert_string_equal(msg, "t.ini:2: collisions.restitution: not with shear");

    sim_error_set(&err, SIM_EINVAL, "heating.strength", "too strong");
    vfy_scene_format_error(&s, &err, msg, sizeof msg);
    assert_string_equal(msg, "t.ini: --set heating.strength: too strong");

    sim_error_set(&err, SIM_EINVAL, "particles.n", "too few for 12 layers");
    vfy_scene_format_error(&s, &err, msg, sizeof msg);
    assert_string_equal(msg, "t.ini: particles.n: too few for 12 layers");

    sim_error_set(&err, SIM_ENOMEM, "", "cannot allocate 3 GB");
    vfy_scene_format_error(&s, &err, msg, sizeof msg);
    assert_string_equal(msg, "t.ini: cannot allocate 3 GB");
}

/* Paper A Ex 3 (docs/theory.md §11.1): k = gamma pi C0 (1 - alpha^2) = 3/4,
 * T_inf = 2 beta/k = 8/3. */
static void test_grw_ex3_file(void **state)
{
    (void)state;
    char path[1024], msg[1024];
    snprintf(path, sizeof path, "%s/verify/cases/scenes/grw-ex3.ini", source_dir());
    sim_scene s;
    sim_status st = vfy_scene_load(path, NULL, 0, &s, msg, sizeof msg);
    if (st != SIM_OK)
        print_error("%s\n", msg);
    assert_int_equal(st, SIM_OK);
    double k = s.collisions.rate * M_PI * s.collisions.constant *
               (1.0 - s.collisions.restitution * s.collisions.restitution);
    assert_close(k, 0.75, 1e-15, 0.0);
    assert_close(2.0 * s.heating.strength / k, 8.0 / 3.0, 1e-15, 0.0);
    assert_int_equal(s.particles.n, 64);
    assert_int_equal(s.particles.ensembles, 10000);
    assert_int_equal(s.outputs, 81);
    assert_close(s.t_end, 8.0, 0.0, 0.0);
    assert_true(s.seed == 20030328);
    assert_int_equal(s.collisions.kernel, SIM_KERNEL_MAXWELL);
    assert_close(s.collisions.exponent, 0.0, 0.0, 0.0);
    assert_int_equal(s.heating.type, SIM_HEATING_WHITE_NOISE);
    assert_int_equal(sim_scene_key_line(&s, "collisions.restitution"), 33);
}

static void load_scene_file(const char *name, sim_scene *s)
{
    char path[1024], msg[1024];
    snprintf(path, sizeof path, "%s/verify/cases/scenes/%s", source_dir(), name);
    sim_status st = vfy_scene_load(path, NULL, 0, s, msg, sizeof msg);
    if (st != SIM_OK)
        print_error("%s\n", msg);
    assert_int_equal(st, SIM_OK);
}

/* split-ex5.ini is paper A Ex 5's gas (grw-ex5.ini) in the time-step scheme
 * with [steady]; every h of its ladder dt/2^k (k < 5) divides the output
 * interval.  The paper C scenes are hard spheres with 4 pi gamma C = 1 in the
 * time-step scheme, one thermostat each. */
static void test_split_and_ms_files(void **state)
{
    (void)state;
    sim_scene a, b;
    load_scene_file("grw-ex5.ini", &a);
    load_scene_file("split-ex5.ini", &b);
    assert_int_equal(b.scheme, SIM_SCHEME_TIMESTEP);
    assert_int_equal(b.steady.present, 1);
    assert_int_equal(b.collisions.rule, SIM_RULE_RELATIVE_SPEED);   /* the jump scheme's */
    b.collisions.rule = a.collisions.rule;
    assert_memory_equal(&a.collisions, &b.collisions, sizeof a.collisions);
    assert_memory_equal(&a.heating, &b.heating, sizeof a.heating);
    assert_memory_equal(&a.particles.maxwellian, &b.particles.maxwellian,
                        sizeof a.particles.maxwellian);
    double interval = sim_scene_output_time(&b, 1);
    for (int k = 0; k < 5; k++) {
        double ratio = interval / (b.dt / (double)(1 << k));
        assert_close(ratio, round(ratio), 1e-12, 0.0);
    }
    static const char *const ms[] = {"ms-white-noise.ini", "ms-gaussian.ini",
                                      "ms-non-gaussian.ini"};
    static const sim_heating_kind type[] = {SIM_HEATING_WHITE_NOISE, SIM_HEATING_GAUSSIAN,
                                            SIM_HEATING_NON_GAUSSIAN};
    for (int i = 0; i < 3; i++) {
        load_scene_file(ms[i], &a);
        assert_int_equal(a.scheme, SIM_SCHEME_TIMESTEP);
        assert_int_equal(a.collisions.kernel, SIM_KERNEL_HARD_SPHERES);
        assert_close(4.0 * M_PI * a.collisions.rate * a.collisions.constant, 1.0, 1e-15, 0.0);
        assert_int_equal(a.heating.type, type[i]);
        assert_int_equal(a.heating.keep_temperature, i == 1);
        assert_int_equal(a.steady.present, 1);
        assert_true(a.steady.from < a.t_end);
    }
}

/* Every file in verify/cases/scenes/ loads. */
/* Every shipped scene loads, has a title and builds an engine; the list is
 * the cases' scenes, so a scene that disappears or an unlisted one fails. */
static void test_all_scene_files(void **state)
{
    (void)state;
    static const char *const shipped[] = {
        "brs-ex1", "brs-ex2", "brs-ex3", "brs-ex4", "brs-ex5", "grw-ex3", "grw-ex4",
        "grw-ex5", "grw-ex6", "grw-ex7", "grw-ex8", "hard-dissipation", "hard-extreme", "hard-long-run", "hard-nongaussian",
        "hard-stiff", "hard-tails", "ms-gaussian", "ms-non-gaussian", "ms-white-noise",
        "as", "as-slab", "msg", "split-ex5", "split-gaussian", "protocol"};
    const size_t nshipped = sizeof shipped / sizeof *shipped;
    char dir[1024], path[2048], msg[1024];
    snprintf(dir, sizeof dir, "%s/verify/cases/scenes", source_dir());
    DIR *d = opendir(dir);
    if (!d)
        print_error("cannot open %s (set GDSMC_SOURCE_DIR)\n", dir);
    assert_non_null(d);
    size_t count = 0;
    for (struct dirent *e; (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        count += len >= 4 && strcmp(e->d_name + len - 4, ".ini") == 0;
    }
    closedir(d);
    assert_int_equal(count, nshipped);
    for (size_t i = 0; i < nshipped; i++) {
        snprintf(path, sizeof path, "%s/%s.ini", dir, shipped[i]);
        sim_scene s;
        sim_status st = vfy_scene_load(path, NULL, 0, &s, msg, sizeof msg);
        if (st != SIM_OK)
            print_error("%s\n", msg);
        assert_int_equal(st, SIM_OK);
        assert_true(s.title[0] != '\0');
        sim_engine *engine = NULL;
        sim_error err;
        st = sim_engine_create(&s, &engine, &err);
        if (st != SIM_OK)
            print_error("%s: %s: %s\n", path, err.key, err.msg);
        assert_int_equal(st, SIM_OK);
        sim_engine_free(engine);
    }
}

/* ---- the scene writer: parse(write(s)) is s --------------------------- */

/* Write s, parse the text back and compare every key and section. */
static void assert_round_trip(const sim_scene *s)
{
    char *text = NULL, msg[1024], key[64];
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    assert_non_null(f);
    assert_int_equal(vfy_scene_write(f, s), 0);
    assert_int_equal(fclose(f), 0);
    sim_scene back;
    sim_status st = vfy_scene_parse(text, "written.ini", NULL, 0, &back, msg, sizeof msg);
    if (st != SIM_OK)
        print_error("%s\n%s\n", msg, text);
    assert_int_equal(st, SIM_OK);
    if (vfy_scene_differs(s, &back, key, sizeof key))
        print_error("%s differs after a round trip through\n%s\n", key, text);
    assert_false(vfy_scene_differs(s, &back, key, sizeof key));
    free(text);
}

static void test_write_shipped_scenes(void **state)
{
    (void)state;
    char dir[1024], path[2048], msg[1024];
    snprintf(dir, sizeof dir, "%s/verify/cases/scenes", source_dir());
    DIR *d = opendir(dir);
    assert_non_null(d);
    size_t count = 0;
    for (struct dirent *e; (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        if (len < 4 || strcmp(e->d_name + len - 4, ".ini") != 0)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        sim_scene s;
        assert_int_equal(vfy_scene_load(path, NULL, 0, &s, msg, sizeof msg), SIM_OK);
        assert_round_trip(&s);
        count++;
    }
    closedir(d);
    assert_int_equal(count, 26);
}

/* Random valid scenes: random values for random keys (awkward decimals,
 * large counts, every word), on top of scenes of each kind; those the parser
 * accepts go round the writer.  The comparison itself is tested: a changed
 * value and a section gone are found. */
static void test_write_random_scenes(void **state)
{
    (void)state;
    static const char *const bases[] = {
        "[scene]\nt_end = 2\noutputs = 5\n[collisions]\nkernel = hard-spheres\n",
        "[scene]\nscheme = timestep\ndt = 0.3\n[collisions]\n[heating]\ntype = gaussian\n"
        "keep_temperature = true\n[steady]\nfrom = 0.5\npairs = 10\nbins = 4\n",
        "[particles]\ninitial = two-maxwellians\nfraction = 0.25\nmass1 = 1\nmass2 = 1\n"
        "velocity1 = 1 2 3\nvelocity2 = -1 0 0.5\ntemperature1 = 2\ntemperature2 = 0.5\n"
        "[background]\nkernel = hard-spheres\n",
        "[collisions]\nkernel = vhs\nexponent = 0.37\n[shear]\nrate = 0.5\n[heat-flux]\n",
    };
    static const char *const reals[] = {
        "scene.t_end", "particles.mass", "particles.temperature", "collisions.constant",
        "collisions.rate", "background.density", "background.mass", "background.temperature",
        "background.constant", "shear.length", "steady.c_max", "collisions.beta"};
    static const char *const unit[] = {"collisions.restitution", "particles.fraction"};
    static const char *const finite[] = {"heating.strength", "shear.rate",
                                         "heat-flux.strength"};
    static const char *const vectors[] = {"particles.velocity", "background.velocity"};
    static const char *const counts[] = {"particles.n", "particles.ensembles", "scene.seed",
                                         "scene.outputs", "shear.layers", "shear.pairs"};
    static const char *const words[] = {
        "collisions.model=ehs", "collisions.model=ihs", "scene.observation=sampled",
        "particles.zero_momentum=true", "particles.initial=shell", "shear.boundary=lees-edwards",
        "heating.type=non-gaussian", "background.kernel=maxwell", "scene.title=a title"};
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 2385);
    size_t accepted = 0;
    char sets[6][96];
    for (int trial = 0; trial < 2000; trial++) {
        const char *ov[6];
        size_t nov = 1 + gsl_rng_uniform_int(rng, 6);
        for (size_t k = 0; k < nov; k++) {
            const double u = gsl_rng_uniform_pos(rng);
            switch (gsl_rng_uniform_int(rng, 6)) {
            case 0:
                snprintf(sets[k], sizeof sets[k], "%s=%.17g",
                         reals[gsl_rng_uniform_int(rng, 11)], 1e-3 + 1e3 * u * u);
                break;
            case 1:
                snprintf(sets[k], sizeof sets[k], "%s=%.17g", unit[gsl_rng_uniform_int(rng, 2)],
                         u);
                break;
            case 2:
                snprintf(sets[k], sizeof sets[k], "%s=%.17g",
                         finite[gsl_rng_uniform_int(rng, 3)], 20.0 * u - 10.0);
                break;
            case 3:
                snprintf(sets[k], sizeof sets[k], "%s=%.17g -0 %.17g",
                         vectors[gsl_rng_uniform_int(rng, 2)], u - 0.5, 1.0 / 3.0 + u);
                break;
            case 4:
                snprintf(sets[k], sizeof sets[k], "%s=%lu", counts[gsl_rng_uniform_int(rng, 5)],
                         2 + gsl_rng_uniform_int(rng, 4000000000UL));
                break;
            default:
                snprintf(sets[k], sizeof sets[k], "%s", words[gsl_rng_uniform_int(rng, 9)]);
            }
            ov[k] = sets[k];
        }
        sim_scene s;
        char msg[1024];
        const char *base = bases[gsl_rng_uniform_int(rng, 4)];
        if (vfy_scene_parse(base, "random.ini", ov, nov, &s, msg, sizeof msg) != SIM_OK)
            continue;
        assert_round_trip(&s);
        accepted++;
    }
    gsl_rng_free(rng);
    print_message("%zu random valid scenes went round the writer\n", accepted);
    assert_true(accepted >= 500);

    sim_scene a, b;
    char msg[256], key[64];
    /* split-ex5's jump row: a timestep scene made jump in code keeps the record
     * of its splitting key, which must not be written */
    const char *const strang[] = {"scene.splitting=strang"};
    assert_int_equal(vfy_scene_parse(bases[1], "a.ini", strang, 1, &a, msg, sizeof msg), SIM_OK);
    a.scheme = SIM_SCHEME_JUMP;
    a.splitting = SIM_SPLIT_EULER;
    a.heating.type = SIM_HEATING_WHITE_NOISE;
    a.heating.keep_temperature = 0;
    assert_round_trip(&a);
    assert_int_equal(vfy_scene_parse(bases[1], "a.ini", NULL, 0, &a, msg, sizeof msg), SIM_OK);
    b = a;
    assert_false(vfy_scene_differs(&a, &b, key, sizeof key));
    b.collisions.restitution = nextafter(1.0, 0.0);
    assert_true(vfy_scene_differs(&a, &b, key, sizeof key));
    assert_string_equal(key, "collisions.restitution");
    b = a;
    b.steady.present = 0;
    assert_true(vfy_scene_differs(&a, &b, key, sizeof key));
    assert_string_equal(key, "[steady]");
}

/* ---- traps: status and the exact message ------------------------------- */

static void expect_error(const char *text, const char *const *ov, size_t nov,
                         sim_status status, const char *expected)
{
    sim_scene s;
    char msg[1024];
    sim_scene_defaults(&s);
    snprintf(s.title, sizeof s.title, "sentinel");
    sim_status st = vfy_scene_parse(text, "t.ini", ov, nov, &s, msg, sizeof msg);
    assert_int_equal(st, status);
    assert_string_equal(msg, expected);
    assert_string_equal(s.title, "sentinel");  /* the scene is not touched */
    assert_int_equal(s.nkeys, 0);
}

#define TRAP(name, text, expected)                          \
    static void name(void **state)                          \
    {                                                       \
        (void)state;                                        \
        expect_error(text, NULL, 0, SIM_EINVAL, expected);  \
    }

#define TRAP_SET(name, text, override, expected)              \
    static void name(void **state)                            \
    {                                                         \
        (void)state;                                          \
        const char *ov[] = {"scene.seed=5", override};        \
        expect_error(text, ov, 2, SIM_EINVAL, expected);      \
    }

#define SECTIONS "scene, particles, collisions, heating, background, shear, heat-flux, bath, steady"

TRAP(trap_unknown_key, "[collisions]\nrestitution = 0.5\nalpha = 0.5\n",
     "t.ini:3: collisions.alpha: unknown key (allowed kernel, exponent, constant, rate, "
     "restitution, model, beta, rule)")
TRAP(trap_unknown_section, "[scene]\nt_end = 1\n\n[collision]\n",
     "t.ini:4: [collision]: unknown section (allowed " SECTIONS ")")
TRAP(trap_key_outside_section, "; no section yet\nt_end = 1\n",
     "t.ini:2: t_end: key outside any section (allowed sections " SECTIONS ")")
TRAP(trap_restitution_above_1, "[collisions]\nrestitution = 1.7\n",
     "t.ini:2: collisions.restitution: '1.7' is out of range (allowed 0 < restitution <= 1)")
TRAP(trap_restitution_0, "[collisions]\nrestitution = 0\n",
     "t.ini:2: collisions.restitution: '0' is out of range (allowed 0 < restitution <= 1)")
TRAP(trap_negative_temperature, "[particles]\ntemperature = -1\n",
     "t.ini:2: particles.temperature: '-1' is out of range (allowed temperature > 0)")
TRAP(trap_n_0, "[particles]\nn = 0\n",
     "t.ini:2: particles.n: '0' is out of range (allowed 2 <= n <= 1000000000)")
TRAP(trap_n_1, "[particles]\nn = 1\n",
     "t.ini:2: particles.n: '1' is out of range (allowed 2 <= n <= 1000000000)")
TRAP(trap_n_negative, "[particles]\nn = -5\n",
     "t.ini:2: particles.n: '-5' is negative (allowed 2 <= n <= 1000000000)")
TRAP(trap_n_fraction, "[particles]\nn = 2.5\n",
     "t.ini:2: particles.n: '2.5' is not a whole number (allowed 2 <= n <= 1000000000)")
TRAP(trap_n_plus_sign, "[particles]\nn = +64\n",
     "t.ini:2: particles.n: '+64' is not a whole number (allowed 2 <= n <= 1000000000)")
TRAP(trap_n_too_large, "[particles]\nn = 1000000001\n",
     "t.ini:2: particles.n: '1000000001' is out of range (allowed 2 <= n <= 1000000000)")
TRAP(trap_n_overflow, "[particles]\nn = 99999999999999999999999\n",
     "t.ini:2: particles.n: '99999999999999999999999' is out of range "
     "(allowed 2 <= n <= 1000000000)")
TRAP(trap_outputs_1, "[scene]\noutputs = 1\n",
     "t.ini:2: scene.outputs: '1' is out of range (allowed 2 <= outputs <= 10000000)")
TRAP(trap_not_a_number, "[scene]\nt_end = abc\n",
     "t.ini:2: scene.t_end: 'abc' is not a number (allowed t_end > 0)")
TRAP(trap_empty_number, "[scene]\nt_end =\n",
     "t.ini:2: scene.t_end: '' is not a number (allowed t_end > 0)")
TRAP(trap_trailing_garbage, "[scene]\nt_end = 1.5x\n",
     "t.ini:2: scene.t_end: '1.5x' is not a number (allowed t_end > 0)")
TRAP(trap_nan, "[scene]\nt_end = nan\n",
     "t.ini:2: scene.t_end: 'nan' is not a finite number (allowed t_end > 0)")
TRAP(trap_inf, "[shear]\nrate = inf\n",
     "t.ini:2: shear.rate: 'inf' is not a finite number (allowed any finite number)")
TRAP(trap_overflow, "[scene]\nt_end = 1e999\n",
     "t.ini:2: scene.t_end: '1e999' is out of range of a double (allowed t_end > 0)")
TRAP(trap_vector_two_numbers, "[particles]\nvelocity = 1 2\n",
     "t.ini:2: particles.velocity: '1 2' is not three numbers "
     "(allowed three finite numbers separated by spaces)")
TRAP(trap_vector_nan, "[background]\nvelocity = 1 nan 0\n",
     "t.ini:2: background.velocity: '1 nan 0' is not three finite numbers "
     "(allowed three finite numbers separated by spaces)")
TRAP(trap_vector_commas, "[particles]\nvelocity = 1,2,3\n",
     "t.ini:2: particles.velocity: '1,2,3' is not three numbers "
     "(allowed three finite numbers separated by spaces)")
TRAP(trap_bad_word, "[collisions]\nkernel = hard-sphere\n",
     "t.ini:2: collisions.kernel: 'hard-sphere' is unknown "
     "(allowed maxwell, vhs, hard-spheres)")
TRAP(trap_background_vhs, "[background]\nkernel = vhs\n",
     "t.ini:2: background.kernel: 'vhs' is unknown (allowed maxwell, hard-spheres)")
TRAP(trap_bad_bool, "[particles]\nzero_momentum = yes\n",
     "t.ini:2: particles.zero_momentum: 'yes' is unknown (allowed true, false)")
TRAP(trap_duplicate_key, "[scene]\nt_end = 1\nseed = 3\n[scene]\nt_end = 2\n",
     "t.ini:5: scene.t_end: set twice (first at line 2)")
TRAP(trap_syntax_error, "[scene]\nt_end 8\n",
     "t.ini:2: syntax error (expected key = value or [section])")
TRAP(trap_unclosed_section, "[scene\nt_end = 8\n",
     "t.ini:1: syntax error (expected key = value or [section])")
TRAP(trap_empty_key, "[scene]\n= 8\n",
     "t.ini:2: syntax error (expected key = value or [section])")
TRAP(trap_first_error_wins, "[scene]\nt_end = -1\nbogus\n[nope]\n",
     "t.ini:2: scene.t_end: '-1' is out of range (allowed t_end > 0)")
TRAP(trap_syntax_error_first, "[scene]\nbogus\nt_end = -1\n",
     "t.ini:2: syntax error (expected key = value or [section])")
TRAP(trap_vhs_without_exponent, "[collisions]\nrate = 2\nkernel = vhs\n",
     "t.ini:3: collisions.kernel: vhs needs collisions.exponent (allowed 0 <= exponent <= 1)")
TRAP(trap_exponent_contradicts_kernel, "[collisions]\nkernel = hard-spheres\nexponent = 0.5\n",
     "t.ini:3: collisions.exponent: 0.5 contradicts kernel = hard-spheres "
     "(allowed 1, or kernel = vhs)")
TRAP(trap_exponent_out_of_range, "[collisions]\nkernel = vhs\nexponent = 1.5\n",
     "t.ini:3: collisions.exponent: '1.5' is out of range (allowed 0 <= exponent <= 1)")
TRAP(trap_timestep_without_dt, "[scene]\nt_end = 2\nscheme = timestep\n",
     "t.ini:3: scene.scheme: timestep needs scene.dt (allowed dt > 0)")
TRAP(trap_mixture_key_with_maxwellian, "[particles]\ninitial = maxwellian\ntemperature2 = 2\n",
     "t.ini:3: particles.temperature2: only used with initial = two-maxwellians "
     "(initial is maxwellian)")
TRAP(trap_mixture_missing_key,
     "[particles]\ninitial = two-maxwellians\nfraction = 0.5\nmass1 = 1\nvelocity1 = 0 0 0\n"
     "temperature1 = 1\nmass2 = 1\nvelocity2 = 0 0 0\n",
     "t.ini:2: particles.initial: two-maxwellians needs particles.temperature2 (allowed "
     "fraction, mass1, velocity1, temperature1, mass2, velocity2, temperature2, all set)")
TRAP(trap_single_key_with_mixture,
     "[particles]\ninitial = two-maxwellians\nfraction = 0.5\nmass1 = 1\nvelocity1 = 0 0 0\n"
     "temperature1 = 1\nmass2 = 1\nvelocity2 = 0 0 0\ntemperature2 = 2\ntemperature = 1\n",
     "t.ini:10: particles.temperature: not used with initial = two-maxwellians (allowed the "
     "keys ending in 1 and 2)")
TRAP(trap_white_noise_negative, "[heating]\ntype = white-noise\nstrength = -0.5\n",
     "t.ini:3: heating.strength: -0.5 is negative (allowed strength >= 0 for type = white-noise)")
/* Keys of the time-step scheme, the thermostats and [steady] (docs/scenes.md). */
TRAP(trap_splitting_with_jump, "[scene]\nt_end = 2\nsplitting = strang\n",
     "t.ini:3: scene.splitting: only used with scheme = timestep (scheme is jump)")
TRAP(trap_bad_splitting, "[scene]\nscheme = timestep\ndt = 0.1\nsplitting = verlet\n",
     "t.ini:4: scene.splitting: 'verlet' is unknown (allowed euler, strang)")
TRAP(trap_keep_temperature_white_noise, "[heating]\ntype = white-noise\nkeep_temperature = true\n",
     "t.ini:3: heating.keep_temperature: only used with type = gaussian")
TRAP(trap_keep_temperature_with_strength,
     "[heating]\ntype = gaussian\nstrength = 0.3\nkeep_temperature = true\n",
     "t.ini:3: heating.strength: not used with keep_temperature = true (the rescaling sets zeta)")
TRAP(trap_steady_after_t_end, "[scene]\nt_end = 2\n[steady]\nfrom = 2.5\n",
     "t.ini:4: steady.from: 2.5 is after t_end = 2 (allowed 0 <= from <= t_end: the time "
     "averages need at least one output time)")
TRAP(trap_steady_negative_from, "[steady]\nfrom = -1\n",
     "t.ini:2: steady.from: '-1' is out of range (allowed from >= 0)")
TRAP(trap_steady_c_max_zero, "[steady]\nc_max = 0\n",
     "t.ini:2: steady.c_max: '0' is out of range (allowed c_max > 0)")
TRAP(trap_steady_unknown_key, "[steady]\nsamples = 10\n",
     "t.ini:2: steady.samples: unknown key (allowed from, pairs, bins, c_max)")
TRAP(trap_line_too_long,
     "[scene]\ntitle = "
     "0123456789012345678901234567890123456789012345678901234567890123456789012345678901234"
     "5678901234567890123456789012345678901234567890123456789012345678901234567890123456789"
     "01234567890123456789012345678901234567890123456789\n",
     "t.ini:2: line too long (allowed at most 198 characters)")
TRAP_SET(trap_override_no_equals, "", "scene.t_end",
         "--set scene.t_end: expected section.key=value (no '=')")
TRAP_SET(trap_override_no_dot, "", "t_end=4",
         "--set t_end=4: expected section.key=value (no '.' between section and key)")
TRAP_SET(trap_override_empty_key, "", "scene. = 4",
         "--set scene. = 4: expected section.key=value (empty section or key)")
TRAP_SET(trap_override_unknown_section, "", "collision.rate=4",
         "--set collision.rate=4: [collision]: unknown section (allowed " SECTIONS ")")
TRAP_SET(trap_override_unknown_key, "", "scene.tend=4",
         "--set scene.tend=4: scene.tend: unknown key (allowed title, scheme, dt, splitting, "
         "step_follows_temperature, observation, t_end, outputs, seed)")
TRAP_SET(trap_override_bad_value, "[collisions]\nrestitution = 0.5\n",
         "collisions.restitution=1.7",
         "--set collisions.restitution=1.7: collisions.restitution: '1.7' is out of range "
         "(allowed 0 < restitution <= 1)")
TRAP_SET(trap_override_title_too_long, "",
         "scene.title=0123456789012345678901234567890123456789012345678901234567890123456789"
         "0123456789012345678901234567890123456789012345678901234567",
         "--set scene.title=0123456789012345678901234567890123456789012345678901234567890123456789"
         "0123456789012345678901234567890123456789012345678901234567: scene.title: is too long: "
         "128 characters (allowed at most 127 characters)")
TRAP_SET(trap_override_breaks_cross_check, "[scene]\nt_end = 2\n", "scene.scheme=timestep",
         "t.ini: --set scene.scheme: timestep needs scene.dt (allowed dt > 0)")
TRAP_SET(trap_file_error_before_overrides, "[scene]\nt_end = 0\n", "scene.t_end=1",
         "t.ini:2: scene.t_end: '0' is out of range (allowed t_end > 0)")

/* Each remaining branch of the parser's messages (issue 5: every error path). */
TRAP(trap_ensembles_0, "[particles]\nensembles = 0\n",
     "t.ini:2: particles.ensembles: '0' is out of range (allowed ensembles >= 1)")
TRAP(trap_seed_negative, "[scene]\nseed = -1\n",
     "t.ini:2: scene.seed: '-1' is negative (allowed 0 <= seed <= 18446744073709551615)")
TRAP(trap_seed_overflow, "[scene]\nseed = 18446744073709551616\n",
     "t.ini:2: scene.seed: '18446744073709551616' is out of range "
     "(allowed 0 <= seed <= 18446744073709551615)")
TRAP(trap_vector_four_numbers, "[particles]\nvelocity = 1 2 3 4\n",
     "t.ini:2: particles.velocity: '1 2 3 4' is not three numbers "
     "(allowed three finite numbers separated by spaces)")
TRAP(trap_fraction_above_1,
     "[particles]\ninitial = two-maxwellians\nfraction = 1.25\n",
     "t.ini:3: particles.fraction: '1.25' is out of range (allowed 0 <= fraction <= 1)")
TRAP(trap_title_too_long_in_file,
     "[scene]\ntitle = 0123456789012345678901234567890123456789012345678901234567890123"
     "456789012345678901234567890123456789012345678901234567890123456789\n",
     "t.ini:2: scene.title: is too long: 130 characters (allowed at most 127 characters)")
TRAP(trap_mixture_key_with_shell, "[particles]\ninitial = shell\nfraction = 0.5\n",
     "t.ini:3: particles.fraction: only used with initial = two-maxwellians (initial is shell)")
TRAP(trap_slab_key_homogeneous, "[particles]\ndensity_wave = 0.5\n[shear]\nrate = 4\n",
     "t.ini:2: particles.density_wave: only used with [shear] boundary = lees-edwards (the slab)")
TRAP(trap_density_wave_one, "[particles]\ndensity_wave = 1\n",
     "t.ini:2: particles.density_wave: '1' is out of range (allowed 0 <= density_wave < 1)")
TRAP(trap_slab_candidates_unknown, "[shear]\nboundary = lees-edwards\ncandidates = bird\n",
     "t.ini:3: shear.candidates: 'bird' is unknown (allowed unbiased, paper)")
TRAP(trap_exponent_contradicts_maxwell, "[collisions]\nkernel = maxwell\nexponent = 1\n",
     "t.ini:3: collisions.exponent: 1 contradicts kernel = maxwell (allowed 0, or kernel = vhs)")
TRAP(trap_observation_unknown, "[scene]\nobservation = exact\n",
     "t.ini:2: scene.observation: 'exact' is unknown (allowed sampled, conditional)")
TRAP(trap_observation_with_steady, "[scene]\nobservation = conditional\n[collisions]\n[steady]\n",
     "t.ini:2: scene.observation: conditional needs scheme = jump, no heating or white-noise "
     "heating (it averages over the pending Brownian increments), and no [steady], [shear] or "
     "[heat-flux] (they observe every particle)")
TRAP(trap_unknown_section_no_keys, "[collisions]\nrate = 2\n[Heating]\n",
     "t.ini:3: [Heating]: unknown section (allowed " SECTIONS ")")

/* An override longer than its buffers (section 63, key 63, value 511 characters). */
static void trap_override_too_long(void **state)
{
    (void)state;
    char ov[700], expected[800];
    memset(ov, 0, sizeof ov);
    memcpy(ov, "scene.title=", 12);
    memset(ov + 12, 'x', 512);   /* a value of 512 characters */
    snprintf(expected, sizeof expected, "--set %s: expected section.key=value (too long)", ov);
    const char *list[] = {ov};
    expect_error("", list, 1, SIM_EINVAL, expected);

    memset(ov, 0, sizeof ov);
    memset(ov, 's', 64);         /* a section of 64 characters */
    memcpy(ov + 64, ".t_end=2", 8);
    snprintf(expected, sizeof expected, "--set %s: expected section.key=value (too long)", ov);
    expect_error("", list, 1, SIM_EINVAL, expected);
}

/* A file of more than 1 MiB is refused before it is parsed. */
static void trap_file_too_large(void **state)
{
    (void)state;
    char path[] = "/tmp/gdsmc_test_scene_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    char block[4096];
    memset(block, ';', sizeof block);   /* comment lines */
    for (size_t i = 0; i < sizeof block; i += 64)
        block[i + 63] = '\n';
    for (int i = 0; i < 256; i++)       /* exactly 1 MiB: still allowed */
        assert_int_equal(write(fd, block, sizeof block), (ssize_t)sizeof block);
    sim_scene s;
    char msg[1024], expected[1100];
    assert_int_equal(vfy_scene_load(path, NULL, 0, &s, msg, sizeof msg), SIM_OK);
    assert_int_equal(write(fd, "\n", 1), 1);   /* one byte more */
    close(fd);
    sim_status st = vfy_scene_load(path, NULL, 0, &s, msg, sizeof msg);
    unlink(path);
    snprintf(expected, sizeof expected, "%s: too large (allowed at most 1048576 bytes)", path);
    assert_int_equal(st, SIM_EINVAL);
    assert_string_equal(msg, expected);
}

/* ---- engine traps: valid scenes sim_engine_create() refuses ------------ */

static void expect_engine_error(const char *text, sim_status status, const char *expected)
{
    static char dummy;
    sim_scene s;
    sim_error err;
    char msg[1024];
    parse_ok(text, NULL, 0, &s);
    sim_engine *e = (sim_engine *)(void *)&dummy;   /* must come back NULL */
    sim_status st = sim_engine_create(&s, &e, &err);
    if (st == SIM_OK)
        sim_engine_free(e);
    assert_int_equal(st, status);
    assert_null(e);
    vfy_scene_format_error(&s, &err, msg, sizeof msg);
    assert_string_equal(msg, expected);
}

#define ENGINE_TRAP(name, text, expected)                          \
    static void name(void **state)                                 \
    {                                                              \
        (void)state;                                               \
        expect_engine_error(text, SIM_EUNSUPPORTED, expected);     \
    }

ENGINE_TRAP(engine_background_timestep,
            "[scene]\nscheme = timestep\ndt = 0.25\n[collisions]\nkernel = hard-spheres\n"
            "[background]\nkernel = hard-spheres\n",
            "t.ini: background: the background is not implemented in the time-step scheme "
            "(supported: jump)")
ENGINE_TRAP(engine_two_species,
            "[particles]\ninitial = two-maxwellians\nfraction = 0.25\nmass1 = 1\n"
            "velocity1 = 0 0 0\ntemperature1 = 1\nmass2 = 2.5\nvelocity2 = 0 0 0\n"
            "temperature2 = 1\n",
            "t.ini:7: particles.mass2: the engine simulates one species: mass2 = 2.5 must equal "
            "mass1 = 1")
ENGINE_TRAP(engine_shear_heated,
            "[collisions]\nrestitution = 0.5\n[shear]\nrate = 1.5\n[heating]\ntype = white-noise\n"
            "strength = 1\n",
            "t.ini:6: heating.type: the jump scheme applies a flow only lazily (white noise, or "
            "[shear] alone) or as one global map with binary collisions (gaussian, without "
            "[background])")
ENGINE_TRAP(engine_shear_ehs,
            "[collisions]\nrestitution = 0.5\nmodel = ehs\n[shear]\nrate = 1.5\n",
            "t.ini:3: collisions.model: ehs is a model of hard spheres (kernel = hard-spheres)")
ENGINE_TRAP(engine_shear_ehs_heated,
            "[collisions]\nkernel = hard-spheres\nrestitution = 0.5\nmodel = ehs\n[shear]\n"
            "rate = 1.5\n[heating]\ntype = white-noise\nstrength = 1\n",
            "t.ini:4: collisions.model: ehs (its drag depends on the temperature) needs scheme = "
            "timestep, or [shear] alone beside it")
ENGINE_TRAP(engine_lees_edwards, "[shear]\nrate = 1.5\nboundary = lees-edwards\n",
            "t.ini:3: shear.boundary: lees-edwards needs scheme = timestep (the jump scheme "
            "keeps no positions)")
ENGINE_TRAP(engine_lees_edwards_strang,
            "[scene]\nscheme = timestep\ndt = 0.01\nsplitting = strang\n[collisions]\n"
            "kernel = hard-spheres\n[shear]\nrate = 1.5\nboundary = lees-edwards\n",
            "t.ini:4: scene.splitting: lees-edwards steps in one order, streaming then "
            "collisions (docs/theory.md §6.3): strang is not implemented")
ENGINE_TRAP(engine_lees_edwards_maxwell,
            "[scene]\nscheme = timestep\ndt = 0.01\n[collisions]\nkernel = maxwell\n"
            "[shear]\nrate = 1.5\nboundary = lees-edwards\n",
            "t.ini:8: shear.boundary: lees-edwards simulates hard spheres ([collisions] kernel = "
            "hard-spheres)")
ENGINE_TRAP(engine_heat_flux, "[heat-flux]\nstrength = 0.025\n",
            "t.ini: scene.scheme: the heat-flux force couples the particles (through the mean "
            "and the temperature) and needs scheme = timestep")
ENGINE_TRAP(engine_heat_flux_heating,
            "[scene]\nscheme = timestep\ndt = 0.25\n[particles]\nzero_momentum = true\n"
            "[heating]\ntype = white-noise\nstrength = 1\n[heat-flux]\nstrength = 0.025\n",
            "t.ini:7: heating.type: heat-flux carries its own thermostat (paper D Eq. 4.2); remove "
            "[heating]")
ENGINE_TRAP(engine_heat_flux_moving,
            "[scene]\nscheme = timestep\ndt = 0.25\n[heat-flux]\nstrength = 0.025\n",
            "t.ini: particles.zero_momentum: the heat-flux force acts on peculiar velocities: "
            "start from a Maxwellian at rest with zero_momentum = true")
ENGINE_TRAP(engine_ehs, "[collisions]\nkernel = hard-spheres\nmodel = ehs\nrestitution = 0.5\n",
            "t.ini:3: collisions.model: ehs (its drag depends on the temperature) needs scheme "
            "= timestep, or [shear] alone beside it")
#define JUMP_HEATING "(the jump scheme supports white-noise and gaussian)"
/* the jump scheme keeps the Gaussian thermostat global with binary collisions
 * alone (a background's rate does not scale with the map) */
ENGINE_TRAP(engine_keep_temperature_background,
            "[heating]\ntype = gaussian\nkeep_temperature = true\n[collisions]\n"
            "[background]\n",
            "t.ini:2: heating.type: the jump scheme applies a flow only lazily (white noise, or "
            "[shear] alone) or as one global map with binary collisions (gaussian, without "
            "[background])")
ENGINE_TRAP(engine_gaussian_background,
            "[heating]\ntype = gaussian\nstrength = 0.5\n[collisions]\n[background]\n",
            "t.ini:2: heating.type: the jump scheme applies a flow only lazily (white noise, or "
            "[shear] alone) or as one global map with binary collisions (gaussian, without "
            "[background])")
/* ... and not alone: without an event process nothing would apply it (it
 * was accepted and T stayed at T0) */
ENGINE_TRAP(engine_gaussian_alone, "[heating]\ntype = gaussian\nstrength = 0.5\n",
            "t.ini:2: heating.type: the jump scheme applies a flow only lazily (white noise, or "
            "[shear] alone) or as one global map with binary collisions (gaussian, without "
            "[background])")
ENGINE_TRAP(engine_non_gaussian_jump, "[heating]\ntype = non-gaussian\nstrength = 0.5\n",
            "t.ini:2: heating.type: non-gaussian heating needs scene.scheme = timestep "
            JUMP_HEATING)

/* At most 1e12 steps between output times: interval 1 (the defaults t_end = 1,
 * outputs = 2), dt = 1e-13 gives ceil(1e13 (1 - 1e-9)) = 9.99999999e12 steps. */
static void engine_too_many_steps(void **state)
{
    (void)state;
    expect_engine_error("[scene]\nscheme = timestep\ndt = 1e-13\n", SIM_EINVAL,
                        "t.ini:3: scene.dt: 1e-13 gives 1e+13 steps between output times "
                        "(allowed at most 1e12)");
    sim_scene s;   /* the boundary: 1e-12 gives 999999999000 steps, accepted */
    sim_engine *e = NULL;
    sim_error err;
    parse_ok("[scene]\nscheme = timestep\ndt = 1e-12\n", NULL, 0, &s);
    assert_int_equal(sim_engine_create(&s, &e, &err), SIM_OK);
    assert_close(sim_engine_step(e), 1.0 / 999999999000.0, 1e-15, 0.0);
    sim_engine_free(e);
}

/* ---- reference traps: scenes no deterministic reference covers ---------- */

static void refs_error(const char *text, sim_status status, char *msg, size_t msglen)
{
    sim_scene s;
    sim_error err;
    vfy_refs refs;
    parse_ok(text, NULL, 0, &s);
    sim_status st = vfy_scene_references(&s, &refs, &err);
    if (st == SIM_OK)
        vfy_refs_free(&refs);
    assert_int_equal(st, status);
    assert_null(refs.cols);   /* nothing left allocated */
    assert_null(refs.names);
    assert_int_equal(refs.count, 0);
    vfy_scene_format_error(&s, &err, msg, msglen);
}

static void expect_refs_error(const char *text, const char *expected)
{
    char msg[1024];
    refs_error(text, SIM_EUNSUPPORTED, msg, sizeof msg);
    assert_string_equal(msg, expected);
}

#define REFS_TRAP(name, text, expected)        \
    static void name(void **state)             \
    {                                          \
        (void)state;                           \
        expect_refs_error(text, expected);     \
    }

REFS_TRAP(refs_no_collisions, "[heating]\nstrength = 0.5\n",
          "t.ini: collisions: no reference applies: paper A references need [collisions]")
REFS_TRAP(refs_shear, "[collisions]\nrestitution = 0.5\n[shear]\nrate = 1\n",
          "t.ini: collisions.kernel: the BGK reference of paper E needs hard spheres")
REFS_TRAP(refs_shear_heating,
          "[collisions]\nkernel = hard-spheres\n[heating]\nstrength = 1\n[shear]\nrate = 1\n",
          "t.ini: heating: the BGK reference of paper E is for shear and collisions only")
REFS_TRAP(refs_heat_flux, "[collisions]\n[heat-flux]\nstrength = 0.025\n",
          "t.ini: heat-flux: no time series reference for the heat-flux force (its references "
          "are values: gdsmc sonine)")
REFS_TRAP(refs_gaussian,
          "[scene]\nscheme = timestep\ndt = 0.25\n[collisions]\nkernel = hard-spheres\n"
          "[heating]\ntype = gaussian\nstrength = 0.5\n",
          "t.ini:7: heating.type: paper A references need white-noise heating")
REFS_TRAP(refs_two_maxwellians,
          "[particles]\ninitial = two-maxwellians\nfraction = 0.25\nmass1 = 1\n"
          "velocity1 = 0 0 0\ntemperature1 = 1\nmass2 = 1\nvelocity2 = 0 0 0\n"
          "temperature2 = 1\n[collisions]\n",
          "t.ini:2: particles.initial: paper A references need an initial Maxwellian at rest "
          "(allowed maxwellian)")
REFS_TRAP(refs_drift, "[particles]\nvelocity = 0 1 0\n[collisions]\n",
          "t.ini:2: particles.velocity: paper A references need an initial Maxwellian at rest "
          "(allowed 0 0 0)")
REFS_TRAP(refs_mass, "[particles]\nmass = 2\n[collisions]\n",
          "t.ini:2: particles.mass: paper A references are for unit mass (got 2)")
REFS_TRAP(refs_vhs, "[collisions]\nkernel = vhs\nexponent = 0.5\n",
          "t.ini:3: collisions.exponent: no reference for VHS lambda = 0.5 (only 0 and 1)")
REFS_TRAP(refs_background_heating, "[background]\n[heating]\nstrength = 1\n",
          "t.ini: background: no reference for a background combined with heating, shear or a "
          "heat-flux force")
REFS_TRAP(refs_background_kernels, "[collisions]\nkernel = hard-spheres\n[background]\n"
          "kernel = maxwell\n",
          "t.ini:2: collisions.kernel: paper B references need the same kernel for binary and "
          "background collisions (background.kernel is maxwell)")

/* A reference whose integration fails (t_end = 1e300 is far beyond what CVODE
 * can step to) reports which reference, the CVODE flag and the reason.  The
 * text after the flag is SUNDIALS' own, so only the part up to it is exact. */
static void expect_cvode_failure(const char *text, const char *prefix)
{
    char msg[1024];
    refs_error(text, SIM_EINVAL, msg, sizeof msg);
    if (strncmp(msg, prefix, strlen(prefix)) != 0)
        print_error("message '%s' does not start with '%s'\n", msg, prefix);
    assert_int_equal(strncmp(msg, prefix, strlen(prefix)), 0);
    assert_non_null(strstr(msg, " (CVODE in CVode: "));
}

static void refs_cvode_failures(void **state)
{
    (void)state;
    expect_cvode_failure("[scene]\nt_end = 1e300\n[collisions]\nkernel = hard-spheres\n"
                         "rate = 4\nrestitution = 0.5\n[heating]\nstrength = 0.125\n",
                         "t.ini: T_maxwell_closure: CVODE failed at t = 0: CV_");
    expect_cvode_failure("[scene]\nt_end = 1e300\n[background]\n",
                         "t.ini: T_finite_n: CVODE failed at t = 0: CV_");
    expect_cvode_failure("[scene]\nt_end = 1e300\n[background]\nkernel = hard-spheres\n",
                         "t.ini: T_le: CVODE failed at t = 0: CV_");
}

static void trap_missing_file(void **state)
{
    (void)state;
    sim_scene s;
    char msg[1024];
    sim_status st = vfy_scene_load("/nonexistent/gdsmc/none.ini", NULL, 0, &s, msg, sizeof msg);
    assert_int_equal(st, SIM_EIO);
    assert_string_equal(msg, "/nonexistent/gdsmc/none.ini: cannot open: No such file or directory");
}

static void trap_directory(void **state)
{
    (void)state;
    sim_scene s;
    char msg[1024];
    sim_status st = vfy_scene_load("/", NULL, 0, &s, msg, sizeof msg);
    assert_int_equal(st, SIM_EIO);
    assert_string_equal(msg, "/: cannot read: Is a directory");
}

static void trap_nul_byte(void **state)
{
    (void)state;
    char path[] = "/tmp/gdsmc_test_scene_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    static const char data[] = "[scene]\nt_end = 1\nseed\0= 2\n";
    assert_int_equal(write(fd, data, sizeof data - 1), (ssize_t)(sizeof data - 1));
    close(fd);
    sim_scene s;
    char msg[1024], expected[1100];
    sim_status st = vfy_scene_load(path, NULL, 0, &s, msg, sizeof msg);
    unlink(path);
    snprintf(expected, sizeof expected, "%s:3: NUL byte (allowed text only)", path);
    assert_int_equal(st, SIM_EINVAL);
    assert_string_equal(msg, expected);
}

static void trap_null_arguments(void **state)
{
    (void)state;
    sim_scene s;
    char msg[256];
    const char *ov[] = {NULL};
    assert_int_equal(vfy_scene_parse(NULL, "t.ini", NULL, 0, &s, msg, sizeof msg), SIM_EINVAL);
    assert_string_equal(msg, "text is NULL");
    assert_int_equal(vfy_scene_parse("", "t.ini", NULL, 0, NULL, msg, sizeof msg), SIM_EINVAL);
    assert_string_equal(msg, "scene is NULL");
    assert_int_equal(vfy_scene_parse("", "t.ini", ov, 1, &s, msg, sizeof msg), SIM_EINVAL);
    assert_string_equal(msg, "overrides is NULL");
    assert_int_equal(vfy_scene_load(NULL, NULL, 0, &s, NULL, 0), SIM_EINVAL);
    /* msg may be NULL; an error still has its status */
    assert_int_equal(vfy_scene_parse("[x]\n", "t.ini", NULL, 0, &s, NULL, 0), SIM_EINVAL);
}

int main(void)
{
    const struct CMUnitTest good[] = {
        cmocka_unit_test(test_good_scene),
        cmocka_unit_test(test_timestep_and_steady_keys),
        cmocka_unit_test(test_split_and_ms_files),
        cmocka_unit_test(test_two_maxwellians),
        cmocka_unit_test(test_requirements),
        cmocka_unit_test(test_defaults_and_empty_section),
        cmocka_unit_test(test_layout),
        cmocka_unit_test(test_overrides),
        cmocka_unit_test(test_format_error),
        cmocka_unit_test(test_grw_ex3_file),
        cmocka_unit_test(test_all_scene_files),
        cmocka_unit_test(test_write_shipped_scenes),
        cmocka_unit_test(test_write_random_scenes),
    };
    const struct CMUnitTest trap[] = {
        cmocka_unit_test(trap_unknown_key),
        cmocka_unit_test(trap_unknown_section),
        cmocka_unit_test(trap_key_outside_section),
        cmocka_unit_test(trap_restitution_above_1),
        cmocka_unit_test(trap_restitution_0),
        cmocka_unit_test(trap_negative_temperature),
        cmocka_unit_test(trap_n_0),
        cmocka_unit_test(trap_n_1),
        cmocka_unit_test(trap_n_negative),
        cmocka_unit_test(trap_n_fraction),
        cmocka_unit_test(trap_n_plus_sign),
        cmocka_unit_test(trap_n_too_large),
        cmocka_unit_test(trap_n_overflow),
        cmocka_unit_test(trap_outputs_1),
        cmocka_unit_test(trap_not_a_number),
        cmocka_unit_test(trap_empty_number),
        cmocka_unit_test(trap_trailing_garbage),
        cmocka_unit_test(trap_nan),
        cmocka_unit_test(trap_inf),
        cmocka_unit_test(trap_overflow),
        cmocka_unit_test(trap_vector_two_numbers),
        cmocka_unit_test(trap_vector_nan),
        cmocka_unit_test(trap_vector_commas),
        cmocka_unit_test(trap_bad_word),
        cmocka_unit_test(trap_background_vhs),
        cmocka_unit_test(trap_bad_bool),
        cmocka_unit_test(trap_duplicate_key),
        cmocka_unit_test(trap_syntax_error),
        cmocka_unit_test(trap_unclosed_section),
        cmocka_unit_test(trap_empty_key),
        cmocka_unit_test(trap_first_error_wins),
        cmocka_unit_test(trap_syntax_error_first),
        cmocka_unit_test(trap_vhs_without_exponent),
        cmocka_unit_test(trap_exponent_contradicts_kernel),
        cmocka_unit_test(trap_exponent_out_of_range),
        cmocka_unit_test(trap_timestep_without_dt),
        cmocka_unit_test(trap_mixture_key_with_maxwellian),
        cmocka_unit_test(trap_mixture_missing_key),
        cmocka_unit_test(trap_single_key_with_mixture),
        cmocka_unit_test(trap_white_noise_negative),
        cmocka_unit_test(trap_splitting_with_jump),
        cmocka_unit_test(trap_bad_splitting),
        cmocka_unit_test(trap_keep_temperature_white_noise),
        cmocka_unit_test(trap_keep_temperature_with_strength),
        cmocka_unit_test(trap_steady_after_t_end),
        cmocka_unit_test(trap_steady_negative_from),
        cmocka_unit_test(trap_steady_c_max_zero),
        cmocka_unit_test(trap_steady_unknown_key),
        cmocka_unit_test(trap_line_too_long),
        cmocka_unit_test(trap_override_no_equals),
        cmocka_unit_test(trap_override_no_dot),
        cmocka_unit_test(trap_override_empty_key),
        cmocka_unit_test(trap_override_unknown_section),
        cmocka_unit_test(trap_override_unknown_key),
        cmocka_unit_test(trap_override_bad_value),
        cmocka_unit_test(trap_override_title_too_long),
        cmocka_unit_test(trap_override_breaks_cross_check),
        cmocka_unit_test(trap_file_error_before_overrides),
        cmocka_unit_test(trap_missing_file),
        cmocka_unit_test(trap_directory),
        cmocka_unit_test(trap_nul_byte),
        cmocka_unit_test(trap_null_arguments),
        cmocka_unit_test(trap_ensembles_0),
        cmocka_unit_test(trap_seed_negative),
        cmocka_unit_test(trap_seed_overflow),
        cmocka_unit_test(trap_vector_four_numbers),
        cmocka_unit_test(trap_fraction_above_1),
        cmocka_unit_test(trap_title_too_long_in_file),
        cmocka_unit_test(trap_mixture_key_with_shell),
        cmocka_unit_test(trap_exponent_contradicts_maxwell),
        cmocka_unit_test(trap_observation_unknown),
        cmocka_unit_test(trap_observation_with_steady),
        cmocka_unit_test(trap_unknown_section_no_keys),
        cmocka_unit_test(trap_override_too_long),
        cmocka_unit_test(trap_file_too_large),
        cmocka_unit_test(trap_slab_key_homogeneous),
        cmocka_unit_test(trap_density_wave_one),
        cmocka_unit_test(trap_slab_candidates_unknown),
    };
    const struct CMUnitTest engine_trap[] = {
        cmocka_unit_test(engine_background_timestep),
        cmocka_unit_test(engine_two_species),
        cmocka_unit_test(engine_shear_heated), cmocka_unit_test(engine_shear_ehs),
        cmocka_unit_test(engine_shear_ehs_heated),
        cmocka_unit_test(engine_lees_edwards),
        cmocka_unit_test(engine_lees_edwards_maxwell),
        cmocka_unit_test(engine_heat_flux),
        cmocka_unit_test(engine_heat_flux_heating),
        cmocka_unit_test(engine_heat_flux_moving),
        cmocka_unit_test(engine_ehs),
                        cmocka_unit_test(engine_gaussian_background),
        cmocka_unit_test(engine_keep_temperature_background),
        cmocka_unit_test(engine_gaussian_alone),
        cmocka_unit_test(engine_lees_edwards_strang),
        cmocka_unit_test(engine_non_gaussian_jump),
        cmocka_unit_test(engine_too_many_steps),
    };
    const struct CMUnitTest refs_trap[] = {
        cmocka_unit_test(refs_no_collisions),
        cmocka_unit_test(refs_shear),
        cmocka_unit_test(refs_shear_heating),
        cmocka_unit_test(refs_heat_flux),
        cmocka_unit_test(refs_gaussian),
        cmocka_unit_test(refs_two_maxwellians),
        cmocka_unit_test(refs_drift),
        cmocka_unit_test(refs_mass),
        cmocka_unit_test(refs_vhs),
        cmocka_unit_test(refs_background_heating),
        cmocka_unit_test(refs_background_kernels),
        cmocka_unit_test(refs_cvode_failures),
    };
    int failed = cmocka_run_group_tests_name("scene", good, NULL, NULL);
    failed += cmocka_run_group_tests_name("scene trap", trap, NULL, NULL);
    failed += cmocka_run_group_tests_name("scene engine trap", engine_trap, NULL, NULL);
    failed += cmocka_run_group_tests_name("scene reference trap", refs_trap, NULL, NULL);
    return failed ? 1 : 0;
}
