#!/usr/bin/env python3
"""An independent solver behind gdsmc's solver protocol (docs/solver-protocol.md).

The exact jump process of paper A (docs/theory.md §8.3) for Maxwell pseudo-molecules
with white-noise heating, written from the paper with NumPy, all ensembles
advanced together: a collision happens at total rate 2 pi gamma C (n - 1); it
picks i, then j != i, both uniformly, brings the two to the collision time
with their pending Brownian motion (variance 2 beta per unit time and
component), and collides them with restitution alpha and e uniform on the
sphere.  At each output time every particle is brought to it and the
estimators of docs/theory.md §1.2 are formed: T (centred, weights 1/n), T_raw
(uncentred) and the bulk velocity.

    python3 heated_maxwell.py SCENE.ini RESULT.csv [--halve-heating]

gdsmc runs it as
    gdsmc verify --suite quick --case grw-ex3 \\
        --solver 'python3 examples/python/heated_maxwell.py {scene} {out}'
and --halve-heating is a deliberate error (beta / 2) that the checks must catch.
It refuses, with exit status 2 and a message on standard error, every scene
key or value it does not implement.
"""
import configparser
import math
import sys
import time

import numpy as np

# The keys this solver implements, with the values it accepts (None: any).
# observation = conditional asks for the exact expectations over the pending
# heating increments; this solver reports paper A's sampled estimates, which
# have the same expectations (and a larger variance), so it accepts both.
SUPPORTED = {
    "scene": {"title": None, "scheme": {"jump"}, "t_end": None, "outputs": None,
              "seed": None, "observation": {"sampled", "conditional"}},
    "particles": {"n": None, "ensembles": None, "initial": {"maxwellian"}, "mass": None,
                  "temperature": None, "velocity": None, "zero_momentum": {"false"}},
    "collisions": {"kernel": {"maxwell"}, "exponent": None, "constant": None,
                   "rate": None, "restitution": None, "model": {"ihs"}},
    "heating": {"type": {"white-noise"}, "strength": None},
}


def refuse(path, what):
    sys.stderr.write("heated_maxwell.py: %s: %s\n" % (path, what))
    sys.exit(2)


def read_scene(path):
    ini = configparser.ConfigParser(interpolation=None)
    try:
        with open(path) as f:
            ini.read_file(f)
    except (OSError, configparser.Error) as e:
        refuse(path, str(e))
    for section in ini.sections():
        if section not in SUPPORTED:
            refuse(path, "[%s] is not implemented here" % section)
        for key, value in ini[section].items():
            allowed = SUPPORTED[section].get(key, ())
            if allowed is not None and value not in allowed:
                refuse(path, "%s.%s = %s is not implemented here" % (section, key, value))
    for section in ("collisions", "heating"):
        if section not in ini:
            refuse(path, "[%s] is required here" % section)
    get = lambda s, k, d: float(ini[s].get(k, d))
    scene = {
        "t_end": get("scene", "t_end", "1"), "outputs": int(ini["scene"].get("outputs", "2")),
        "seed": int(ini["scene"].get("seed", "1")),
        "n": int(ini["particles"].get("n", "64")),
        "N": int(ini["particles"].get("ensembles", "1")),
        "mass": get("particles", "mass", "1"), "T0": get("particles", "temperature", "1"),
        "u0": np.array([float(x) for x in ini["particles"].get("velocity", "0 0 0").split()]),
        "C": get("collisions", "constant", str(1 / (4 * math.pi))),
        "gamma": get("collisions", "rate", "1"),
        "alpha": get("collisions", "restitution", "1"),
        "beta": get("heating", "strength", "0"),
    }
    if get("collisions", "exponent", "0") != 0.0:
        refuse(path, "collisions.exponent must be 0 (Maxwell molecules)")
    return scene


def bring(v, stamp, rows, cols, t, beta, rng):
    """Move particles (rows, cols) to time t with their pending Brownian motion."""
    dt = t - stamp[rows, cols]
    v[rows, cols] += np.sqrt(2.0 * beta * dt)[..., None] * rng.standard_normal(dt.shape + (3,))
    stamp[rows, cols] = t


def observe(v, mass):
    """Per-ensemble T (centred), T_raw and bulk velocity (docs/theory.md §1.2)."""
    u = v.mean(axis=1)
    T_raw = mass / 3.0 * (v * v).sum(axis=2).mean(axis=1)
    c = v - u[:, None, :]
    T = mass / 3.0 * (c * c).sum(axis=2).mean(axis=1)
    return {"T": T, "T_raw": T_raw, "ux": u[:, 0], "uy": u[:, 1], "uz": u[:, 2]}


def simulate(s, beta, rng):
    n, N = s["n"], s["N"]
    rate = 2.0 * math.pi * s["gamma"] * s["C"] * (n - 1)   # total collision rate
    a = s["alpha"]
    v = s["u0"] + math.sqrt(s["T0"] / s["mass"]) * rng.standard_normal((N, n, 3))
    stamp = np.zeros((N, n))
    t_next = rng.exponential(1.0 / rate, N)
    times = [s["t_end"] * m / (s["outputs"] - 1) for m in range(s["outputs"])]
    rows = []
    all_rows, all_cols = np.indices((N, n))
    for t_out in times:
        while True:
            e = np.nonzero(t_next < t_out)[0]
            if e.size == 0:
                break
            t = t_next[e]
            i = rng.integers(0, n, e.size)
            j = rng.integers(0, n - 1, e.size)
            j += j >= i
            for p in (i, j):
                dt = t - stamp[e, p]
                v[e, p] += np.sqrt(2.0 * beta * dt)[:, None] * rng.standard_normal((e.size, 3))
                stamp[e, p] = t
            vi, vj = v[e, i], v[e, j]
            g = vi - vj
            unit = rng.standard_normal((e.size, 3))
            unit /= np.linalg.norm(unit, axis=1)[:, None]
            centre = 0.5 * (vi + vj)
            turn = 0.25 * (1 - a) * g + 0.25 * (1 + a) * np.linalg.norm(g, axis=1)[:, None] * unit
            v[e, i] = centre + turn
            v[e, j] = centre - turn
            t_next[e] += rng.exponential(1.0 / rate, e.size)
        bring(v, stamp, all_rows, all_cols, t_out, beta, rng)
        rows.append((t_out, observe(v, s["mass"])))
    return rows


def main(argv):
    if len(argv) not in (3, 4) or (len(argv) == 4 and argv[3] != "--halve-heating"):
        sys.stderr.write("usage: heated_maxwell.py SCENE.ini RESULT.csv [--halve-heating]\n")
        return 2
    s = read_scene(argv[1])
    beta = s["beta"] / 2.0 if len(argv) == 4 else s["beta"]   # the deliberate error
    rng = np.random.default_rng(s["seed"])
    cpu = time.process_time()
    rows = simulate(s, beta, rng)
    cpu = time.process_time() - cpu
    names = ["T", "T_raw", "ux", "uy", "uz"]
    with open(argv[2], "w") as out:
        out.write("# gdsmc-result 1\n# solver = heated_maxwell.py (NumPy %s)%s\n"
                  % (np.__version__, ", heating halved" if len(argv) == 4 else ""))
        out.write("# n = %d\n# ensembles = %d\n# cpu_seconds = %.17g\n" % (s["n"], s["N"], cpu))
        out.write("t," + ",".join("%s,%s_var" % (k, k) for k in names) + "\n")
        for t, obs in rows:
            cells = ["%.17g" % t]
            for k in names:
                x = obs[k]
                cells += ["%.17g" % x.mean(), "%.17g" % (x.var(ddof=1) if x.size > 1 else 0.0)]
            out.write(",".join(cells) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
