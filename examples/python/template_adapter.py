#!/usr/bin/env python3
"""A template: put an existing solver behind gdsmc's --solver (docs/solver-protocol.md).

Copy this file (and gdsmc_protocol.py beside it), then
  1. in read_scene(), read every scene key your code handles and turn it into
     your code's parameters; refuse the values it cannot do;
  2. in run_my_solver(), call your code: N independent ensembles of n
     particles, the velocities at every output time;
  3. run it:  gdsmc verify --suite quick --case CASE \\
                  --solver 'python3 my_adapter.py {scene} {out}'

As it stands the "solver" is a stand-in that never changes the particles: right
for a scene with no collisions and no forces (only [scene] and [particles]),
and every effect section is refused.  Refusing is always allowed: a scene your
code cannot do exits with status 3 and the reason as the last line of standard
error (gp.refuse), and gdsmc reports that scene's checks as not judged.  What
you never read, scene.refuse_unread() refuses for you ("key X not supported"),
so a key added to gdsmc later cannot be silently ignored.

    python3 template_adapter.py SCENE.ini RESULT.csv
"""
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gdsmc_protocol as gp  # noqa: E402


def read_scene(path):
    scene = gp.Scene(path)
    p = {}

    # [scene]: the time grid is read by Result (scene.output_times()).
    # The scheme and its dt are algorithm choices: a code with its own time
    # stepping may take them over (scene.substitute("scene.scheme"),
    # scene.substitute("scene.dt")).  This stand-in takes no steps at all.
    scene.substitute("scene.scheme")
    scene.substitute("scene.dt")
    p["seed"] = scene.get("scene", "seed")
    # the time-step scheme's own options: refuse what your code cannot follow
    scene.only("scene", "splitting", "euler")
    scene.only("scene", "step_follows_temperature", False)
    # how output times observe a lazy flow: both have the same expectations
    scene.only("scene", "observation", "sampled", "conditional")

    # [particles]
    p["n"] = scene.get("particles", "n")
    p["N"] = scene.get("particles", "ensembles")
    scene.only("particles", "initial", "maxwellian")    # not two-maxwellians, shell
    p["mass"] = scene.get("particles", "mass")
    p["T0"] = scene.get("particles", "temperature")
    p["u0"] = np.array(scene.get("particles", "velocity"))
    p["zero_momentum"] = scene.get("particles", "zero_momentum")

    # The effects.  Replace a refusal by reading the section's keys when
    # your code does the effect, e.g. for hard-sphere collisions:
    #   scene.only("collisions", "kernel", "hard-spheres")
    #   p["alpha"] = scene.get("collisions", "restitution")  ...
    for section, what in (("collisions", "binary collisions"),
                          ("heating", "a thermostat"),
                          ("background", "a host medium"),
                          ("shear", "uniform shear flow"),
                          ("heat-flux", "the heat-flux force")):
        if scene.present(section):
            gp.refuse("[%s] not supported: this solver does not do %s" % (section, what))

    # [steady]: the time averages are computed by the helpers (gp.Steady).
    p["steady"] = gp.Steady(scene)

    scene.refuse_unread()      # anything not read above is refused
    return scene, p


def run_my_solver(p, times, rng):
    """Yield (m, v) for every output time m, v the velocities of all ensembles
    (N, n, 3).  Replace the body with a call to your code."""
    n, N = p["n"], p["N"]
    v = p["u0"] + np.sqrt(p["T0"] / p["mass"]) * rng.standard_normal((N, n, 3))
    if p["zero_momentum"]:          # each sample's mean velocity moved to the drift
        v += p["u0"] - v.mean(axis=1, keepdims=True)
    for m, t in enumerate(times):
        # ... your code advances v to time t here ...
        yield m, v


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: template_adapter.py SCENE.ini RESULT.csv\n")
        return gp.EXIT_FAILED
    scene, p = read_scene(argv[1])
    rng = np.random.default_rng(p["seed"])
    result = gp.Result(scene)
    steady, times = p["steady"], scene.output_times()
    cpu = time.process_time()
    for m, v in run_my_solver(p, times, rng):
        result.add(m, gp.observables(v, p["mass"]))
        if steady.due(times[m]):
            steady.sample(v, p["mass"], rng)
    if steady.active:
        result.add_steady(steady.averages())
    result.write(argv[2], solver="template_adapter.py", cpu_seconds=time.process_time() - cpu)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
