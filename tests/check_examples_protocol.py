#!/usr/bin/env python3
"""examples/python/gdsmc_protocol.py against the engine's definitions.

Reads examples-protocol-engine.txt, which test_examples_protocol writes (a
fixed velocity array and the engine's sim_observe and sim_steady_sample
values for it), and requires of the Python helpers: every observable and
every steady quantity but the pair-sampled ones equal to round-off; mu2 and
mu4, the engine's and the helpers' (each by its number of random pairs),
within |z| <= 4.5 of their exact mean over all ordered pairs; the
exact steady relations of the engine's values as the helpers define them.

    check_examples_protocol.py ENGINE_VALUES EXAMPLES_PYTHON_DIR
"""
import math
import sys

import numpy as np

PY_PAIRS = 200000   # the helpers' own sample (the engine's is larger: the file says)


def main(argv):
    sys.path.insert(0, argv[2])
    import gdsmc_protocol as gp

    conf, v, obs, steady, times = {}, [], {}, {}, []
    with open(argv[1]) as f:
        for line in f:
            w = line.split()
            if w[0] == "v":
                v.append([float(x) for x in w[1:]])
            elif w[0] == "obs":
                obs[w[1]] = float(w[2])
            elif w[0] == "steady":
                steady[w[1]] = float(w[2])
            elif w[0] == "time":
                times.append(float(w[1]))
            else:
                conf[w[0]] = float(w[1])
    v = np.array(v)
    mass, alpha, pairs = conf["mass"], conf["alpha"], int(conf["pairs"])
    bad = []

    def close(name, got, want, rtol=1e-12):
        ok = abs(got - want) <= rtol * abs(want)
        print("%-4s %-16s %.17g vs engine %.17g" % ("ok" if ok else "BAD", name, got, want))
        if not ok:
            bad.append(name)

    mine = gp.observables(v, mass)
    if list(mine) != list(obs) or list(obs) != list(gp.OBSERVABLES):
        bad.append("observable names %s vs %s" % (list(mine), list(obs)))
    for k, want in obs.items():
        close(k, float(mine[k]), want)

    with open("examples-protocol-steady.ini", "w") as f:
        f.write("[collisions]\nrestitution = %.17g\n[steady]\npairs = %d\nbins = %d\n"
                "c_max = %.17g\n" % (alpha, PY_PAIRS, int(conf["bins"]), conf["c_max"]))
    st = gp.Steady(gp.Scene("examples-protocol-steady.ini"))
    if st.names != list(steady):
        bad.append("steady names %s vs %s" % (st.names, list(steady)))
    rng = np.random.default_rng(20261127)
    sample = st.sample_values(v, mass, rng)
    for k, want in steady.items():
        if not (k.startswith("mu") or k.startswith("f_") and want == 0.0):
            close(k, float(sample[k]), want)
        elif k.startswith("f_") and sample[k] != 0.0:
            bad.append("%s = %g where the engine has 0" % (k, sample[k]))

    # mu2, mu4: exact means over all ordered pairs i != j
    C = v - v.mean(axis=0)
    v0 = math.sqrt(2.0 * (C * C).sum() / (3.0 * len(v)))
    i, j = np.nonzero(~np.eye(len(v), dtype=bool))
    p2, p4 = gp.phi24(C[i], C[j], alpha)
    for name, p, power in (("mu2", p2, 3), ("mu4", p4, 5)):
        x = p / v0 ** power
        exact = x.mean()
        for who, got, count in (("engine", steady[name], pairs),
                                ("helpers", float(sample[name]), PY_PAIRS)):
            z = (got - exact) / (x.std() / math.sqrt(count))
            ok = abs(z) <= 4.5
            print("%-4s %-16s %s %.6f vs exact %.6f: z = %.2f" % ("ok" if ok else "BAD", name,
                                                                who, got, exact, z))
            if not ok:
                bad.append("%s (%s)" % (name, who))
    rel = gp.steady_relations(steady["mu2"], steady["a2"], steady["c1"], steady["c3"])
    for k, x in rel.items():
        close(k + " (relation)", x, steady[k], 1e-14)

    # the output times, bit for bit, and the defaults
    with open("examples-protocol-scene.ini", "w") as f:
        f.write("[scene]\nt_end = 7.3   ; a comment\noutputs = 37\n\n[collisions]\n"
                "kernel = hard-spheres\nmodel = ehs\nrestitution = 0.6\n")
    scene = gp.Scene("examples-protocol-scene.ini")
    if scene.output_times() != times:
        bad.append("output times %s vs the engine's %s" % (scene.output_times(), times))
    for key, want in ((("collisions", "exponent"), 1.0), (("collisions", "beta"), 0.8),
                      (("collisions", "constant"), 1.0 / (4.0 * math.pi)),
                      (("heating", "type"), "white-noise"), (("steady", "c_max"), 5.0),
                      (("particles", "n"), 64)):
        got = scene.get(*key)
        if got != want and not (isinstance(want, float) and abs(got - want) < 1e-15):
            bad.append("%s.%s = %r, expected %r" % (key + (got, want)))
    if {"collisions.model", "collisions.restitution"} & scene._read:
        bad.append("a default taken from other keys read them")
    if scene.present("heating") or not scene.present("collisions"):
        bad.append("present()")

    if bad:
        print("FAILED: %s" % ", ".join(bad))
        return 1
    print("all agree")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
