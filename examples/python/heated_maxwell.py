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
The scene, the estimators and the result file come from gdsmc_protocol.py
beside it; every scene key or value it does not implement is refused (exit
status 3, the reason as the last line of standard error).
"""
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gdsmc_protocol as gp  # noqa: E402

REPORTED = ("T", "T_raw", "ux", "uy", "uz")


def read_scene(path):
    """The parameters this solver implements; every other key is refused."""
    scene = gp.Scene(path)
    # paper A's exact process: no time step; conditional observation asks for
    # the exact expectations over the pending heating increments, and paper A's
    # sampled estimates have the same expectations (a larger variance)
    scene.only("scene", "scheme", "jump")
    scene.only("scene", "observation", "sampled", "conditional")
    scene.only("particles", "initial", "maxwellian")
    scene.only("particles", "zero_momentum", False)
    if not scene.present("collisions"):
        gp.refuse("a scene without [collisions] not supported (this solver: Maxwell "
                  "molecules with white-noise heating)")
    scene.only("collisions", "kernel", "maxwell")
    scene.only("collisions", "exponent", 0.0)
    scene.only("collisions", "model", "ihs")
    if scene.present("heating"):
        scene.only("heating", "type", "white-noise")
    s = {
        "times": scene.output_times(),
        "seed": scene.get("scene", "seed"),
        "n": scene.get("particles", "n"), "N": scene.get("particles", "ensembles"),
        "mass": scene.get("particles", "mass"), "T0": scene.get("particles", "temperature"),
        "u0": np.array(scene.get("particles", "velocity")),
        "C": scene.get("collisions", "constant"),
        "gamma": scene.get("collisions", "rate"),
        "alpha": scene.get("collisions", "restitution"),
        "beta": scene.get("heating", "strength") if scene.present("heating") else 0.0,
    }
    scene.refuse_unread()
    return scene, s


def bring(v, stamp, rows, cols, t, beta, rng):
    """Move particles (rows, cols) to time t with their pending Brownian motion."""
    dt = t - stamp[rows, cols]
    v[rows, cols] += np.sqrt(2.0 * beta * dt)[..., None] * rng.standard_normal(dt.shape + (3,))
    stamp[rows, cols] = t


def simulate(s, beta, rng, result):
    n, N = s["n"], s["N"]
    rate = 2.0 * math.pi * s["gamma"] * s["C"] * (n - 1)   # total collision rate
    a = s["alpha"]
    v = s["u0"] + math.sqrt(s["T0"] / s["mass"]) * rng.standard_normal((N, n, 3))
    stamp = np.zeros((N, n))
    t_next = rng.exponential(1.0 / rate, N)
    all_rows, all_cols = np.indices((N, n))
    for m, t_out in enumerate(s["times"]):
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
        obs = gp.observables(v, s["mass"])
        result.add(m, {k: obs[k] for k in REPORTED})


def main(argv):
    if len(argv) not in (3, 4) or (len(argv) == 4 and argv[3] != "--halve-heating"):
        sys.stderr.write("usage: heated_maxwell.py SCENE.ini RESULT.csv [--halve-heating]\n")
        return 2
    halve = len(argv) == 4
    scene, s = read_scene(argv[1])
    beta = s["beta"] / 2.0 if halve else s["beta"]   # the deliberate error
    rng = np.random.default_rng(s["seed"])
    result = gp.Result(scene)
    cpu = time.process_time()
    simulate(s, beta, rng, result)
    cpu = time.process_time() - cpu
    result.write(argv[2], solver="heated_maxwell.py (NumPy %s)%s"
                 % (np.__version__, ", heating halved" if halve else ""), cpu_seconds=cpu)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
