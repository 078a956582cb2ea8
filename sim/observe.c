#include "observe.h"

#include <string.h>

static const char *const names[SIM_OBS_BASE] = {
    "T", "T_raw", "ux", "uy", "uz", "Pxx", "Pyy", "Pzz", "Pxy", "Pxz", "Pyz",
    "qx", "qy", "qz", "a2", "a3",
};

const char *sim_observable_name(sim_observable k)
{
    return k < SIM_OBS_BASE ? names[k] : "?";
}

int sim_observable_find(const char *name, size_t len)
{
    for (int k = 0; k < SIM_OBS_BASE; k++)
        if (strlen(names[k]) == len && strncmp(names[k], name, len) == 0)
            return k;
    return -1;
}

void sim_observe(const sim_particles *p, double mass, double out[SIM_OBS_BASE])
{
    const size_t n = p->n;
    const double w = 1.0 / (double)n;
    double V[3] = {0, 0, 0}, v2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double *v = p->v[i];
        V[0] += v[0];
        V[1] += v[1];
        V[2] += v[2];
        v2 += v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    }
    for (int k = 0; k < 3; k++)
        V[k] *= w;

    /* Central moments in a second pass (no cancellation against |V|^2). */
    double P[6] = {0}, q[3] = {0}, c4 = 0.0, c6 = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double c[3] = {p->v[i][0] - V[0], p->v[i][1] - V[1], p->v[i][2] - V[2]};
        const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        P[0] += c[0] * c[0];
        P[1] += c[1] * c[1];
        P[2] += c[2] * c[2];
        P[3] += c[0] * c[1];
        P[4] += c[0] * c[2];
        P[5] += c[1] * c[2];
        q[0] += c2 * c[0];
        q[1] += c2 * c[1];
        q[2] += c2 * c[2];
        c4 += c2 * c2;
        c6 += c2 * c2 * c2;
    }
    const double T = mass * w * (P[0] + P[1] + P[2]) / 3.0;
    const double theta = T / mass;   /* T/m */
    out[SIM_OBS_T] = T;
    out[SIM_OBS_T_RAW] = mass * w * v2 / 3.0;
    out[SIM_OBS_UX] = V[0];
    out[SIM_OBS_UY] = V[1];
    out[SIM_OBS_UZ] = V[2];
    for (int k = 0; k < 6; k++)
        out[SIM_OBS_PXX + k] = mass * w * P[k];
    for (int k = 0; k < 3; k++)
        out[SIM_OBS_QX + k] = 0.5 * mass * w * q[k];
    const double a2 = w * c4 / (15.0 * theta * theta) - 1.0;
    out[SIM_OBS_A2] = a2;
    out[SIM_OBS_A3] = -w * c6 / (105.0 * theta * theta * theta) + 1.0 + 3.0 * a2;
}

void sim_observe_pending(const sim_particles *p, double mass, double t, double spread,
                         double out[SIM_OBS_BASE])
{
    double now[SIM_OBS_BASE];
    sim_observe(p, mass, now);
    const size_t n = p->n;
    double owed = 0.0;
    for (size_t i = 0; i < n; i++)
        owed += t - p->stamp[i];
    const double S = spread * owed / (double)n;
    const double centred = mass * S * (1.0 - 1.0 / (double)n);
    now[SIM_OBS_T_RAW] += mass * S;
    now[SIM_OBS_T] += centred;
    now[SIM_OBS_PXX] += centred;
    now[SIM_OBS_PYY] += centred;
    now[SIM_OBS_PZZ] += centred;
    for (int k = SIM_OBS_T; k <= SIM_OBS_PYZ; k++)
        out[k] = now[k];
}
