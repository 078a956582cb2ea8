/* A scene: the parsed, validated description of one simulation (docs/scenes.md).
 *
 * Plain data.  verify/protocol/scene_ini.c fills it from an INI file (each value range-
 * checked there, with file, line and key in the message); sim_engine_create()
 * then builds an engine from the effects it names, refusing combinations that
 * no scheme supports.  Sections that a file does not name have present = 0 and
 * cost nothing at run time.
 */
#ifndef GDSMC_SIM_SCENE_H
#define GDSMC_SIM_SCENE_H

#include <stddef.h>
#include <stdint.h>

typedef enum sim_scheme {
    SIM_SCHEME_JUMP,     /* exact event-driven Markov jump process, no splitting */
    SIM_SCHEME_TIMESTEP  /* Bird-style splitting with step dt */
} sim_scheme;

/* How the time-step scheme composes its stages in one step h (docs/theory.md §8.5). */
typedef enum sim_splitting {
    SIM_SPLIT_EULER,   /* Lie: collisions for h, then free flight for h (paper C §3) */
    SIM_SPLIT_STRANG   /* free flight h/2, collisions h, free flight h/2 */
} sim_splitting;

/* How the jump scheme observes a system whose white-noise heating is applied
 * lazily (issue 4): `sampled` brings every particle to the output time,
 * drawing its pending Brownian increment, and observes it (paper A);
 * `conditional` records T, T_raw, u and P as their exact expectations over
 * those increments from running sums (observe.h, sim_observe_sums; issue 18)
 * and never draws them at output times, which leaves the trajectory law
 * unchanged; q, a2, a3 are then not observed (NaN).  Also without heating
 * (the sums are then the system's own moments, O(1) per output time). */
typedef enum sim_observation {
    SIM_OBSERVE_SAMPLED,
    SIM_OBSERVE_CONDITIONAL
} sim_observation;

typedef enum sim_initial {
    SIM_INITIAL_MAXWELLIAN,
    SIM_INITIAL_TWO_MAXWELLIANS,  /* paper B Eq. (35) */
    SIM_INITIAL_SHELL             /* delta shell, paper E Eq. (3.6) */
} sim_initial;

typedef enum sim_kernel_kind {
    SIM_KERNEL_MAXWELL,      /* B = C (lambda = 0) */
    SIM_KERNEL_VHS,          /* B = C |g|^lambda, 0 <= lambda <= 1 */
    SIM_KERNEL_HARD_SPHERES  /* B = C |g| (lambda = 1) */
} sim_kernel_kind;

typedef enum sim_collision_model {
    SIM_MODEL_IHS,  /* inelastic hard spheres (restitution alpha) */
    SIM_MODEL_EHS   /* frictional elastic hard spheres with drag, paper E */
} sim_collision_model;

/* How the time-step scheme's hard-sphere stage accepts a candidate pair (docs/theory.md §3.2;
 * collisions.rule).  Equal in distribution: both give each pair the rate
 * 4 pi gamma C |g|/n and the same post-collision law. */
typedef enum sim_collision_rule {
    SIM_RULE_CONTACT,        /* paper C: s uniform on S^2, accepted with
                                Θ(g.s) (g.s)/U_max, the contact rule (the default) */
    SIM_RULE_RELATIVE_SPEED  /* paper A: accepted with |g|/U_max, then e uniform (the
                                jump scheme's rule; about 4 times fewer candidates) */
} sim_collision_rule;

typedef enum sim_heating_kind {
    SIM_HEATING_WHITE_NOISE,   /* stochastic thermostat, variance 2 beta per unit time */
    SIM_HEATING_GAUSSIAN,      /* anti-drag F = m zeta v */
    SIM_HEATING_NON_GAUSSIAN   /* F = m g v/|v| */
} sim_heating_kind;

typedef enum sim_shear_boundary {
    SIM_SHEAR_HOMOGENEOUS,  /* Lagrangian frame */
    SIM_SHEAR_LEES_EDWARDS
} sim_shear_boundary;

/* Most layers a Lees-Edwards slab may have (each adds four profile columns to
 * every output row, observe.h). */
#define SIM_SLAB_LAYERS_MAX 1000

/* How the Lees-Edwards slab counts a layer's candidate pairs (sim/slab.h). */
typedef enum sim_slab_pairs {
    SIM_SLAB_PAIRS_UNBIASED,  /* N_I (N_I - 1): the layer's pairs */
    SIM_SLAB_PAIRS_PAPER      /* N_I^2, paper E Eq. (4.13): +1/N_I in the rate */
} sim_slab_pairs;

/* One Maxwellian: particle mass, drift velocity, temperature. */
typedef struct sim_maxwellian {
    double mass;
    double velocity[3];
    double temperature;
} sim_maxwellian;

/* Where a key was set, so that later errors (engine, references) can name
 * the file line.  line = 0: the key kept its default. */
typedef struct sim_scene_key_origin {
    char key[48];  /* "section.key" */
    int line;
} sim_scene_key_origin;

#define SIM_SCENE_MAX_KEYS 96

typedef struct sim_scene {
    char file[512];   /* where the scene came from ("" if built in code) */

    /* [scene] */
    char title[128];
    sim_scheme scheme;
    double dt;          /* timestep only: the largest step; the engine uses the largest
                           h <= dt that divides the interval between output times */
    sim_splitting splitting;   /* timestep only (default euler) */
    int step_follows_temperature; /* timestep only: the step is dt sqrt(T0/T), T the
                                     centred temperature at the start of each output
                                     interval, T0 = particles.temperature (paper E: the
                                     step follows the mean free time; default false) */
    sim_observation observation; /* how output times observe a lazy flow (default
                                    sampled) */
    uint32_t observe_only;   /* 0: every observable of the row; else only the base
                                observables whose bits are set (bit k: sim_observable
                                k < SIM_OBS_BASE), the others NaN (observe.h,
                                sim_observe_only).  No scene-file key: the verify
                                driver sets it from what a case reads (issue 18) */
    double t_end;
    size_t outputs;     /* equally spaced output times, 0 and t_end included (>= 2) */
    uint64_t seed;

    /* [particles] */
    struct sim_initial_spec {
        size_t n;            /* particles per ensemble (>= 2) */
        size_t ensembles;    /* N independent ensembles (>= 1) */
        sim_initial initial;
        sim_maxwellian maxwellian;   /* initial = maxwellian (or shell: mass, T) */
        double fraction;             /* two-maxwellians: weight of the first */
        sim_maxwellian first, second;/* two-maxwellians */
        int zero_momentum;           /* subtract the sample mean velocity (default 0) */
        /* The Lees-Edwards slab only (paper E Eqs. 3.7-3.8): positions with density
         * n (1 + density_wave sin(2 pi y/L)) and the flow U (cos(pi y/L) - 2/pi) x̂,
         * U = flow_wave, added to every velocity; both 0 by default (uniform, at rest). */
        double density_wave;         /* in [0, 1) */
        double flow_wave;
    } particles;

    /* [collisions] binary inelastic collisions (docs/theory.md §2.2, §3) */
    struct {
        int present;
        sim_kernel_kind kernel;
        double exponent;     /* VHS lambda; 0 for maxwell, 1 for hard-spheres */
        double constant;     /* C of B = C |g|^lambda */
        double rate;         /* gamma of paper A (default 1) */
        double restitution;  /* alpha of A, e of B, in (0, 1] */
        sim_collision_model model;
        double beta;         /* the collision rate factor; 0: the model's (ihs 1, ehs paper
                                E's (1 + alpha)/2) */
        sim_collision_rule rule;  /* homogeneous time-step scheme, hard spheres only (the
                                     jump scheme always accepts by |g|) */
    } collisions;

    /* [heating] thermostats (docs/theory.md §4) */
    struct {
        int present;
        sim_heating_kind type;
        double strength;     /* white-noise: beta; gaussian: zeta; non-gaussian: g */
        int keep_temperature;/* gaussian only: instead of a fixed zeta, rescale after every
                                step so that T stays at particles.temperature (the
                                homogeneous cooling state in scaled variables, paper C) */
    } heating;

    /* [background] host medium (docs/theory.md §5) */
    struct {
        int present;
        double density, mass, temperature;
        double velocity[3];
        sim_kernel_kind kernel;  /* maxwell or hard-spheres */
        double constant;         /* C1 */
    } background;

    /* [shear] uniform shear flow (docs/theory.md §6) */
    struct {
        int present;
        double rate;
        sim_shear_boundary boundary;
        double length;       /* lees-edwards: the slab's width L (-L/2 < y < L/2) */
        size_t layers;       /* lees-edwards: M layers of width L/M */
        sim_slab_pairs candidates;   /* lees-edwards (default unbiased) */
        size_t pairs;        /* random pairs per output for <|V12|^3> (observe.h); 0: none */
    } shear;

    /* [heat-flux] homogeneous heat-flux force (docs/theory.md §7) */
    struct {
        int present;
        double strength;
    } heat_flux;

    /* [bath] Langevin bath: friction and white noise at temperature T_b (docs/theory.md
     * §4.5) */
    struct {
        int present;
        double friction;      /* gamma (default 1) */
        double temperature;   /* T_b (default 1) */
    } bath;

    /* [steady] steady-state observers (docs/theory.md §10): time averages, per ensemble, over the
     * output times t >= from of the reduced moments, the collisional moments mu2, mu4
     * (by `pairs` random pairs per sample) and the reduced speed distribution
     * (`bins` shells on 0 <= c < c_max); see sim/steady.h. */
    struct {
        int present;
        double from;
        size_t pairs;
        size_t bins;
        double c_max;
    } steady;

    /* Provenance of each key that was set, for messages. */
    sim_scene_key_origin keys[SIM_SCENE_MAX_KEYS];
    size_t nkeys;
} sim_scene;

/* Fill every field with its documented default: jump scheme (splitting
 * euler for timestep), t_end = 1, outputs = 2, seed = 1, n = 64, N = 1,
 * standard Maxwellian (m = 1, T = 1, at rest), no effects present;
 * collisions (once present): maxwell kernel, C = 1/(4 pi), rate 1,
 * restitution 1, model ihs; heating: keep_temperature false; steady (once
 * present): from 0, no pairs, no bins, c_max 5. */
void sim_scene_defaults(sim_scene *scene);

/* Line at which "section.key" was set, or 0 if it kept its default. */
int sim_scene_key_line(const sim_scene *scene, const char *key);

/* The grain mass: particles.mass, or mass1 for two-maxwellians (the engine
 * simulates one species and refuses mass1 != mass2). */
double sim_scene_grain_mass(const sim_scene *scene);

/* The mean free path lambda0 = 1/(sqrt(2) pi n sigma^2) with n sigma^2 =
 * 4 gamma C, the hard-sphere convention of papers D and E (docs/theory.md §2.3), used
 * for every kernel: eps* = lambda0 eps, tau = lambda0/sqrt(2T/m). */
double sim_scene_mean_free_path(const sim_scene *scene);

/* The collision rate factor beta: collisions.beta when set, else the
 * model's, 1 for ihs and paper E's (1 + alpha)/2 for ehs (elastic collisions
 * at beta times the IHS rate, docs/theory.md §3.3). */
double sim_scene_collision_rate_factor(const sim_scene *scene);

/* Output time m (0 <= m < outputs): m t_end / (outputs - 1). */
double sim_scene_output_time(const sim_scene *scene, size_t m);

#endif
