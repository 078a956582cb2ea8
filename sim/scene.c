#include "scene.h"

#include <math.h>
#include <string.h>

void sim_scene_defaults(sim_scene *scene)
{
    memset(scene, 0, sizeof *scene);
    scene->scheme = SIM_SCHEME_JUMP;
    scene->t_end = 1.0;
    scene->outputs = 2;
    scene->seed = 1;

    scene->particles.n = 64;
    scene->particles.ensembles = 1;
    scene->particles.initial = SIM_INITIAL_MAXWELLIAN;
    scene->particles.maxwellian = (sim_maxwellian){.mass = 1.0, .temperature = 1.0};
    scene->particles.fraction = 0.5;
    scene->particles.first = scene->particles.maxwellian;
    scene->particles.second = scene->particles.maxwellian;

    scene->collisions.kernel = SIM_KERNEL_MAXWELL;
    scene->collisions.exponent = 0.0;
    scene->collisions.constant = 1.0 / (4.0 * M_PI);
    scene->collisions.rate = 1.0;
    scene->collisions.restitution = 1.0;
    scene->collisions.model = SIM_MODEL_IHS;

    scene->background.density = 1.0;
    scene->background.mass = 1.0;
    scene->background.temperature = 1.0;
    scene->background.kernel = SIM_KERNEL_MAXWELL;
    scene->background.constant = 1.0;

    scene->steady.c_max = 5.0;

    scene->shear.boundary = SIM_SHEAR_HOMOGENEOUS;
    scene->shear.length = 1.0;
    scene->shear.layers = 1;

    scene->bath.friction = 1.0;
    scene->bath.temperature = 1.0;
}

int sim_scene_key_line(const sim_scene *scene, const char *key)
{
    for (size_t i = 0; i < scene->nkeys; i++)
        if (strcmp(scene->keys[i].key, key) == 0)
            return scene->keys[i].line;
    return 0;
}

double sim_scene_output_time(const sim_scene *scene, size_t m)
{
    return scene->t_end * (double)m / (double)(scene->outputs - 1);
}

double sim_scene_grain_mass(const sim_scene *scene)
{
    return scene->particles.initial == SIM_INITIAL_TWO_MAXWELLIANS
               ? scene->particles.first.mass
               : scene->particles.maxwellian.mass;
}

double sim_scene_mean_free_path(const sim_scene *scene)
{
    return 1.0 / (sqrt(2.0) * M_PI * 4.0 * scene->collisions.rate * scene->collisions.constant);
}

double sim_scene_collision_rate_factor(const sim_scene *scene)
{
    if (scene->collisions.beta > 0.0)
        return scene->collisions.beta;
    return scene->collisions.model == SIM_MODEL_EHS ? 0.5 * (1.0 + scene->collisions.restitution)
                                                    : 1.0;
}
