"""Helpers for a solver behind gdsmc's solver protocol, version 1 (docs/solver-protocol.md).

Python 3 and NumPy only (Debian's python3-numpy).  What a solver needs to
stand where gdsmc's own engine does:

  Scene(path)           the scene INI gdsmc wrote, every key with its default
                        applied (docs/scenes.md, sim/scene.h), remembering which
                        keys the solver read
  Scene.only(...)       read a key and refuse the scene unless its value is one
                        the solver implements
  Scene.refuse_unread() refuse the scene when it holds a key (or a section) the
                        solver never read: "key X not supported"
  refuse(reason)        the protocol's refusal: the reason as the last line of
                        standard error, exit status 3
  Scene.output_times()  t_m = m t_end / (outputs - 1), as the engine computes it
  observables(v, mass)  T, T_raw, ux .. a3 of a velocity array (n, 3), or of
                        many at once (..., n, 3), exactly as sim/observe.c
  Steady(scene)         the steady quantities of sim/steady.c (T a2 a3 c1 c3 mu2
                        mu4 mu4_* and the speed histogram f_k), time-averaged
                        per ensemble over the output times t >= steady.from
  Result(scene)         the ensemble mean and sample variance (divisor N - 1)
                        of every quantity; Result.write(path) writes the result
                        file (version 1, numbers as %.17g)

A solver's main is then (heated_maxwell.py and template_adapter.py beside this
file are complete examples):

    scene = Scene(sys.argv[1])
    n, N = scene.get("particles", "n"), scene.get("particles", "ensembles")
    scene.only("collisions", "kernel", "maxwell")
    ...                                  # read every key the solver implements
    scene.refuse_unread()                # and refuse the scene if there is more
    result = Result(scene)
    for m, t in enumerate(scene.output_times()):
        ...                              # advance the N systems v (N, n, 3) to t
        result.add(m, observables(v, mass))
    result.write(sys.argv[2], solver="mysolver 1.0")

Not covered: paper D's heat-flux and paper E's shear-flow quantities (the
[heat-flux] and [shear] rows and steady sections); a solver that needs them
computes them itself (sim/steady.h and sim/observe.h define them).  A quantity
a result does not report is simply a SKIP of every check that needs it.
"""
import math
import sys

import numpy as np

PROTOCOL_VERSION = 1

# The base observables of docs/theory.md §9.1, in the engine's column order.
OBSERVABLES = ("T", "T_raw", "ux", "uy", "uz", "Pxx", "Pyy", "Pzz", "Pxy", "Pxz", "Pyz",
               "qx", "qy", "qz", "a2", "a3")

# The steady quantities before the histogram bins f_0 .. f_{bins-1} (sim/steady.h).
STEADY_SCALARS = ("T", "a2", "a3", "c1", "c3", "mu2", "mu4", "mu4_white", "mu4_gaussian",
                  "mu4_nongaussian")

# The exit status of a refusal (protocol v1), and of bad input or a crash.
EXIT_REFUSED = 3
EXIT_FAILED = 2

# The longest reason gdsmc quotes (the last line of standard error).
REASON_MAX = 239


def refuse(reason):
    """Refuse the scene: the reason as the last line of standard error, exit 3.

    gdsmc counts nothing else as a refusal: any other non-zero exit is a crash.
    The reason is one line (newlines become spaces) of at most 239 bytes."""
    sys.stdout.flush()
    text = " ".join(str(reason).split())
    data = text.encode("utf-8")[:REASON_MAX].decode("utf-8", "ignore")
    sys.stderr.write(data + "\n")
    sys.stderr.flush()
    sys.exit(EXIT_REFUSED)


def fail(message):
    """Stop on bad input or an internal error (not a refusal): exit 2."""
    sys.stdout.flush()
    sys.stderr.write(str(message) + "\n")
    sys.stderr.flush()
    sys.exit(EXIT_FAILED)


# --------------------------------------------------------------------- the scene

# Every key gdsmc knows (verify/protocol/scene_ini.c) with its kind and default
# (sim_scene_defaults in sim/scene.c).  Kinds: text, real, vec3, count, bool,
# and a tuple of the words allowed.  A default of None: see Scene.get.
_WORDS = {
    "scheme": ("jump", "timestep"),
    "splitting": ("euler", "strang"),
    "observation": ("sampled", "conditional"),
    "initial": ("maxwellian", "two-maxwellians", "shell"),
    "kernel": ("maxwell", "vhs", "hard-spheres"),
    "model": ("ihs", "ehs"),
    "rule": ("contact", "relative-speed"),
    "type": ("white-noise", "gaussian", "non-gaussian"),
    "bg_kernel": ("maxwell", "hard-spheres"),
    "boundary": ("homogeneous", "lees-edwards"),
    "candidates": ("unbiased", "paper"),
}
KEYS = {
    "scene": {
        "title": ("text", ""),
        "scheme": (_WORDS["scheme"], "jump"),
        "dt": ("real", None),                    # required with scheme = timestep
        "splitting": (_WORDS["splitting"], "euler"),
        "step_follows_temperature": ("bool", False),
        "observation": (_WORDS["observation"], "sampled"),
        "t_end": ("real", 1.0),
        "outputs": ("count", 2),
        "seed": ("count", 1),
    },
    "particles": {
        "n": ("count", 64),
        "ensembles": ("count", 1),
        "initial": (_WORDS["initial"], "maxwellian"),
        "mass": ("real", 1.0),
        "temperature": ("real", 1.0),
        "velocity": ("vec3", (0.0, 0.0, 0.0)),
        "fraction": ("real", 0.5),
        "mass1": ("real", 1.0),
        "velocity1": ("vec3", (0.0, 0.0, 0.0)),
        "temperature1": ("real", 1.0),
        "mass2": ("real", 1.0),
        "velocity2": ("vec3", (0.0, 0.0, 0.0)),
        "temperature2": ("real", 1.0),
        "zero_momentum": ("bool", False),
        "density_wave": ("real", 0.0),
        "flow_wave": ("real", 0.0),
    },
    "collisions": {
        "kernel": (_WORDS["kernel"], "maxwell"),
        "exponent": ("real", None),              # 0 for maxwell, 1 for hard-spheres
        "constant": ("real", 1.0 / (4.0 * math.pi)),
        "rate": ("real", 1.0),
        "restitution": ("real", 1.0),
        "model": (_WORDS["model"], "ihs"),
        "beta": ("real", None),                  # 1 for ihs, (1 + alpha)/2 for ehs
        "rule": (_WORDS["rule"], "contact"),
    },
    "heating": {
        "type": (_WORDS["type"], "white-noise"),
        "strength": ("real", 0.0),
        "keep_temperature": ("bool", False),
    },
    "background": {
        "density": ("real", 1.0),
        "mass": ("real", 1.0),
        "temperature": ("real", 1.0),
        "velocity": ("vec3", (0.0, 0.0, 0.0)),
        "kernel": (_WORDS["bg_kernel"], "maxwell"),
        "constant": ("real", 1.0),
    },
    "shear": {
        "rate": ("real", 0.0),
        "boundary": (_WORDS["boundary"], "homogeneous"),
        "length": ("real", 1.0),
        "layers": ("count", 1),
        "candidates": (_WORDS["candidates"], "unbiased"),
        "pairs": ("count", 0),
    },
    "heat-flux": {
        "strength": ("real", 0.0),
    },
    "steady": {
        "from": ("real", 0.0),
        "pairs": ("count", 0),
        "bins": ("count", 0),
        "c_max": ("real", 5.0),
    },
}

# Keys refuse_unread() never asks for: the output times, n and N, which
# Result follows itself; a label; and the seed, which the protocol leaves to
# the solver (independent ensembles are what matters).
HANDLED = ("scene.t_end", "scene.outputs", "particles.n", "particles.ensembles",
           "scene.title", "scene.seed")

# Keys the protocol lets a solver treat as algorithm choices (it may use its
# own algorithm instead, and say so with Scene.substitute).
ALGORITHM_CHOICES = ("collisions.rule", "scene.scheme", "scene.dt")


def _parse_ini(text, path):
    """(sections in order, {section: {key: (value, line)}}) of an INI text read
    as gdsmc reads it with inih: ';' and '#' comment lines, ';' after white
    space starts an inline comment, a key may appear once per section."""
    sections, order = {}, []
    section = None
    for number, raw in enumerate(text.splitlines(), 1):
        line = raw.lstrip("\ufeff").strip()
        if not line or line[0] in ";#":
            continue
        if line[0] == "[":
            end = line.find("]")
            if end < 0:
                fail("%s:%d: a section header without ']'" % (path, number))
            section = line[1:end].strip()
            if section not in sections:
                sections[section] = {}
                order.append(section)
            continue
        for k in range(1, len(line)):           # an inline comment: " ;"
            if line[k] == ";" and line[k - 1] in " \t":
                line = line[:k].rstrip()
                break
        cut = min((k for k in (line.find("="), line.find(":")) if k >= 0), default=-1)
        key, value = line[:max(cut, 0)].strip(), line[cut + 1:].strip()
        if cut < 0 or not key:
            fail("%s:%d: syntax error (expected key = value or [section])" % (path, number))
        if section is None:
            fail("%s:%d: %s: key outside any section" % (path, number, key))
        if key in sections[section]:
            fail("%s:%d: %s.%s: set twice" % (path, number, section, key))
        sections[section][key] = (value, number)
    return order, sections


class Scene:
    """A scene file with its defaults, and the record of what the solver read.

    get() and only() mark a key as read; present() marks a section as looked
    at.  refuse_unread() then refuses a scene that holds anything else: a key
    the solver never read is one it does not implement."""

    def __init__(self, path):
        self.path = path
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            fail("%s: %s" % (path, e))
        self._order, self._values = _parse_ini(text, path)
        self._read = set()          # "section.key" read by the solver
        self._looked = set()        # sections whose presence the solver asked
        self.substituted = []       # keys the solver replaced by its own algorithm

    # -- what the file holds

    def present(self, section):
        """Whether the scene has the section (an effect is on when it is)."""
        self._looked.add(section)
        return section in self._values

    def is_set(self, section, key):
        """Whether the file sets the key (a default is not set).  Does not mark
        it as read."""
        return key in self._values.get(section, {})

    def get(self, section, key):
        """The key's value, typed: float (real), int (count), bool, tuple of
        three floats (vec3), str (text and words); the default when the file
        does not set it.  Marks the key as read.  Two defaults depend on other
        keys (which this does not mark): collisions.exponent (0 for maxwell, 1
        for hard-spheres; vhs requires it) and collisions.beta (1 for ihs,
        (1 + alpha)/2 for ehs); scene.dt has none (None when unset)."""
        self._read.add("%s.%s" % (section, key))
        self._looked.add(section)
        return self._value(section, key)

    def _value(self, section, key):
        name = "%s.%s" % (section, key)
        spec = KEYS.get(section, {}).get(key)
        entry = self._values.get(section, {}).get(key)
        if spec is None:
            if entry is None:
                raise KeyError("%s is not a scene key (docs/scenes.md)" % name)
            return entry[0]                    # a key this module does not know
        kind, default = spec
        if entry is None:
            if name == "collisions.exponent":
                kernel = self._value("collisions", "kernel")
                return {"maxwell": 0.0, "hard-spheres": 1.0}.get(kernel)
            if name == "collisions.beta":
                alpha = self._value("collisions", "restitution")
                return 0.5 * (1.0 + alpha) if self._value("collisions", "model") == "ehs" else 1.0
            return default
        value, line = entry
        where = "%s:%d: %s" % (self.path, line, name)
        try:
            if kind == "real":
                x = float(value)
                if not math.isfinite(x):
                    raise ValueError
                return x
            if kind == "count":
                if not (value.isascii() and value.isdigit()):
                    raise ValueError
                return int(value)
            if kind == "vec3":
                v = tuple(float(x) for x in value.split())
                if len(v) != 3 or not all(math.isfinite(x) for x in v):
                    raise ValueError
                return v
            if kind == "bool":
                if value not in ("true", "false"):
                    raise ValueError
                return value == "true"
            if kind == "text":
                return value
            if value not in kind:                  # a word
                raise ValueError
            return value
        except ValueError:
            fail("%s: '%s' is not valid (%s)" % (where, value, kind if isinstance(kind, str)
                                                  else "allowed " + " | ".join(kind)))

    def only(self, section, key, *allowed):
        """get(), refusing the scene unless the value is one of `allowed`."""
        value = self.get(section, key)
        if value not in allowed:
            refuse("%s.%s = %s not supported (this solver: %s)"
                   % (section, key, _show(value), " | ".join(_show(a) for a in allowed)))
        return value

    def substitute(self, key, reason=""):
        """Declare that the solver uses its own algorithm instead of what key
        (one of ALGORITHM_CHOICES) asks, when the file sets it: the key counts
        as read, and Result.write(..., declare_substitutions=True) lists it on
        the line '# substituted = KEY,...'."""
        if key not in ALGORITHM_CHOICES:
            raise ValueError("%s is not an algorithm choice (%s)"
                             % (key, ", ".join(ALGORITHM_CHOICES)))
        section, name = key.split(".", 1)
        self.get(section, name)
        if self.is_set(section, name) and key not in self.substituted:
            self.substituted.append(key)

    def refuse_unread(self):
        """Refuse the scene when it holds a section or a key the solver never
        read (but those of HANDLED): 'key X not supported'."""
        unread = []
        for section in self._order:
            keys = self._values[section]
            if not keys and section not in self._looked:
                unread.append("[%s]" % section)
            for key in keys:
                name = "%s.%s" % (section, key)
                if name not in self._read and name not in HANDLED:
                    unread.append(name)
        if len(unread) == 1:
            refuse("key %s not supported" % unread[0])
        if unread:
            refuse("keys %s not supported" % ", ".join(unread))

    # -- derived values

    def output_times(self):
        """The output times t_m = m t_end / (outputs - 1), m = 0 .. outputs - 1,
        computed as the engine does (sim_scene_output_time)."""
        t_end, outputs = self.get("scene", "t_end"), self.get("scene", "outputs")
        return [t_end * float(m) / float(outputs - 1) for m in range(outputs)]


def _show(x):
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, tuple):
        return " ".join("%.17g" % c for c in x)
    if isinstance(x, float):
        return "%.17g" % x
    return str(x)


# ---------------------------------------------------------------- observables

def observables(v, mass=1.0):
    """The base observables of one system v (n, 3), or of many (..., n, 3),
    as sim/observe.c defines them (weights 1/n; V = the bulk velocity, C = v - V):
      T = (m/3) <|C|^2>, T_raw = (m/3) <|v|^2>, (ux, uy, uz) = V,
      P_ij = m <C_i C_j>, q = (m/2) <|C|^2 C>,
      a2 = <|C|^4>/(15 (T/m)^2) - 1, a3 = -<|C|^6>/(105 (T/m)^3) + 1 + 3 a2.
    Returns {name: value} with a float per system (an array of shape ...)."""
    v = np.asarray(v, dtype=float)
    n = v.shape[-2]
    w = 1.0 / n
    V = v.sum(axis=-2) * w
    out = {"T_raw": mass * w * (v * v).sum(axis=(-2, -1)) / 3.0,
           "ux": V[..., 0], "uy": V[..., 1], "uz": V[..., 2]}
    c = v - V[..., None, :]
    c2 = (c * c).sum(axis=-1)
    P = [(c[..., a] * c[..., b]).sum(axis=-1) for a, b in
         ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))]
    T = mass * w * (P[0] + P[1] + P[2]) / 3.0
    theta = T / mass
    out["T"] = T
    for name, p in zip(("Pxx", "Pyy", "Pzz", "Pxy", "Pxz", "Pyz"), P):
        out[name] = mass * w * p
    for k, name in enumerate(("qx", "qy", "qz")):
        out[name] = 0.5 * mass * w * (c2 * c[..., k]).sum(axis=-1)
    a2 = w * (c2 * c2).sum(axis=-1) / (15.0 * theta * theta) - 1.0
    out["a2"] = a2
    out["a3"] = -w * (c2 * c2 * c2).sum(axis=-1) / (105.0 * theta * theta * theta) + 1.0 + 3.0 * a2
    return {k: out[k] for k in OBSERVABLES}


def phi24(c1, c2, alpha):
    """Paper C Eqs. (65)-(66): Phi2 and Phi4 of pairs with peculiar velocities
    c1, c2 (arrays (..., 3)) and restitution alpha (sim/steady.c, phi24_block)."""
    g = c1 - c2
    G = 0.5 * (c1 + c2)
    g2 = (g * g).sum(axis=-1)
    G2 = (G * G).sum(axis=-1)
    gG = (g * G).sum(axis=-1)
    gn = np.sqrt(g2)
    a2 = alpha * alpha
    phi2 = math.pi * (1.0 - a2) / 8.0 * g2 * gn
    phi4 = 0.25 * math.pi * gn * (5.0 * (1.0 - a2) / 3.0 * g2 * G2
                                  + (1.0 - a2) * (2.0 + a2) / 12.0 * g2 * g2
                                  + (3.0 - alpha) * (1.0 + alpha) * (gG * gG - g2 * G2 / 3.0))
    return phi2, phi4


def steady_relations(mu2, a2, c1, c3):
    """mu4 through each thermostat's exact steady relation, from one sample's
    mu2, a2, c1 = <|c|>, c3 = <|c|^3> (paper C Eqs. (23), (38), (44))."""
    return {"mu4_white": 5.0 * mu2, "mu4_gaussian": 5.0 * (1.0 + a2) * mu2,
            "mu4_nongaussian": 2.0 * mu2 * c3 / c1}


class Steady:
    """The steady quantities of sim/steady.h for a scene with [steady]: each
    system's time average over the output times t >= steady.from of
      T          the centred temperature
      a2, a3     (4/15) <c^4> - 1, -(8/105) <c^6> + 1 + 3 a2, c = C/v0, v0 = sqrt(2T/m)
      c1, c3     <|c|>, <|c|^3>
      mu2, mu4   v0^{-p-1} (1/N') sum Phi_p over N' = steady.pairs random pairs
                 i != j (paper C Eq. (67)), alpha = collisions.restitution; not
                 reported when pairs = 0
      mu4_white = 5 mu2, mu4_gaussian = 5 (1 + a2) mu2,
      mu4_nongaussian = 2 mu2 c3/c1  (each sample's, then averaged)
      f_0 .. f_{bins-1}  the fraction of particles with k D <= |c| < (k+1) D,
                 D = c_max/bins, over the shell's volume (4 pi/3)((k+1)^3 - k^3) D^3

    Reads steady.from, pairs, bins, c_max and collisions.restitution (marking
    them read).  Use: due(t) says whether output time t is sampled; sample(v,
    mass, rng) adds one sample of every system (v of shape (n, 3) or (N, n,
    3), the same shape every time); averages() gives {name: per-system time
    average}, ready for Result.add_steady."""

    def __init__(self, scene):
        self.active = scene.present("steady")
        self.start = scene.get("steady", "from")
        self.pairs = scene.get("steady", "pairs")
        self.bins = scene.get("steady", "bins")
        self.c_max = scene.get("steady", "c_max")
        self.alpha = scene.get("collisions", "restitution")
        self.names = list(STEADY_SCALARS) + ["f_%d" % k for k in range(self.bins)]
        self.reset()

    def reset(self):
        """Forget the samples (before the next batch of systems)."""
        self._sum = None
        self.samples = 0

    def due(self, t):
        """Whether output time t is one of the samples: t >= steady.from."""
        return self.active and t >= self.start

    def sample_values(self, v, mass, rng):
        """One sample of every quantity, {name: float per system}."""
        v = np.asarray(v, dtype=float)
        systems = v.reshape((-1,) + v.shape[-2:])
        out = {name: np.empty(systems.shape[0]) for name in self.names}
        for s, x in enumerate(systems):
            for name, value in self._one(x, mass, rng).items():
                out[name][s] = value
        return {k: a.reshape(v.shape[:-2]) for k, a in out.items()}

    def sample(self, v, mass, rng):
        """Add one sample of every system of v to the time averages."""
        values = self.sample_values(v, mass, rng)
        if self._sum is None:
            self._sum = {k: np.zeros_like(x) for k, x in values.items()}
        for k, x in values.items():
            self._sum[k] = self._sum[k] + x
        self.samples += 1

    def averages(self):
        """{name: time average per system} over the samples so far."""
        if not self.samples:
            raise ValueError("no steady samples: no output time t >= steady.from")
        return {k: x / self.samples for k, x in self._sum.items()}

    def _one(self, v, mass, rng):
        n = v.shape[0]
        w = 1.0 / n
        V = v.sum(axis=0) * w
        C = v - V
        theta = w * (C * C).sum() / 3.0                     # T/m
        inv_v0 = 1.0 / math.sqrt(2.0 * theta)
        c2 = (C * C).sum(axis=1) * inv_v0 * inv_v0
        cn = np.sqrt(c2)
        m1, m3 = cn.sum() * w, (c2 * cn).sum() * w
        m4, m6 = (c2 * c2).sum() * w, (c2 * c2 * c2).sum() * w
        a2 = 4.0 / 15.0 * m4 - 1.0
        a3 = -8.0 / 105.0 * m6 + 1.0 + 3.0 * a2
        mu2 = mu4 = math.nan
        if self.pairs > 0:
            i = rng.integers(0, n, self.pairs)
            j = rng.integers(0, n - 1, self.pairs)
            j += j >= i
            p2, p4 = phi24(C[i], C[j], self.alpha)
            mu2 = p2.sum() / self.pairs * inv_v0 ** 3
            mu4 = p4.sum() / self.pairs * inv_v0 ** 5
        out = {"T": mass * theta, "a2": a2, "a3": a3, "c1": m1, "c3": m3, "mu2": mu2,
               "mu4": mu4}
        out.update(steady_relations(mu2, a2, m1, m3))
        if self.bins > 0:
            delta = self.c_max / self.bins
            shell = 4.0 * math.pi / 3.0 * delta ** 3 * n
            inside = cn[cn < self.c_max]
            b = np.minimum((inside / delta).astype(np.int64), self.bins - 1)
            counts = np.bincount(b, minlength=self.bins).astype(float)
            k = np.arange(self.bins, dtype=float)
            f = counts / (shell * (3.0 * k * k + 3.0 * k + 1.0))
            for kk in range(self.bins):
                out["f_%d" % kk] = f[kk]
        return out


# ------------------------------------------------------------------ the result

class _Moments:
    """Count, mean and sum of squared deviations of a stream of values, merged
    batch by batch (Chan et al.), so that the variance is that of all values."""

    def __init__(self):
        self.count, self.mean, self.m2 = 0, 0.0, 0.0

    def add(self, x):
        x = np.asarray(x, dtype=float).ravel()
        if x.size == 0:
            return
        nb, mb = x.size, float(x.mean())
        m2b = float(((x - mb) ** 2).sum())
        n = self.count + nb
        delta = mb - self.mean
        self.mean += delta * nb / n
        self.m2 += m2b + delta * delta * self.count * nb / n
        self.count = n

    def variance(self):
        """The sample variance, divisor N - 1 (0 for one value)."""
        return self.m2 / (self.count - 1) if self.count > 1 else 0.0


class Result:
    """The ensemble statistics of a run, and the result file.

    add(m, values) takes output m's {observable: per-ensemble value(s)} (one
    float, or an array of one per ensemble), add_steady(values) each
    ensemble's steady time averages; both may come in batches of ensembles.
    write() checks that every ensemble was counted, and reports each
    observable that has a finite value at every output time."""

    def __init__(self, scene):
        self.times = scene.output_times()
        self.n = scene.get("particles", "n")
        self.ensembles = scene.get("particles", "ensembles")
        self.substituted = scene.substituted
        self._rows = [dict() for _ in self.times]
        self._steady = {}
        self._steady_order = []

    def add(self, m, values):
        row = self._rows[m]
        for name, x in values.items():
            if name not in OBSERVABLES:
                raise KeyError("%s is not a base observable (%s)" % (name, " ".join(OBSERVABLES)))
            row.setdefault(name, _Moments()).add(x)

    def add_steady(self, values):
        for name, x in values.items():
            if name not in self._steady:
                self._steady[name] = _Moments()
                self._steady_order.append(name)
            self._steady[name].add(x)

    def write(self, path, solver="", cpu_seconds=None, events=None, violations=None,
              declare_substitutions=False):
        """Write the result file, version 1 (docs/solver-protocol.md).  The
        optional counts are written when given.  With declare_substitutions
        and keys declared by Scene.substitute, the header says
        '# substituted = KEY,...' (newer gdsmc only: leave it off for an older
        one)."""
        names = [k for k in OBSERVABLES
                 if all(k in row and np.isfinite(row[k].mean) and np.isfinite(row[k].m2)
                        for row in self._rows)]
        for m, row in enumerate(self._rows):
            for k in names:
                if row[k].count != self.ensembles:
                    raise ValueError("%s at output %d: %d values for %d ensembles"
                                     % (k, m, row[k].count, self.ensembles))
        steady = [k for k in self._steady_order
                  if np.isfinite(self._steady[k].mean) and np.isfinite(self._steady[k].m2)]
        for k in steady:
            if self._steady[k].count != self.ensembles:
                raise ValueError("steady %s: %d values for %d ensembles"
                                 % (k, self._steady[k].count, self.ensembles))
        lines = ["# gdsmc-result %d" % PROTOCOL_VERSION]
        if solver:
            lines.append("# solver = %s" % " ".join(solver.split()))
        lines.append("# n = %d" % self.n)
        lines.append("# ensembles = %d" % self.ensembles)
        if cpu_seconds is not None:
            lines.append("# cpu_seconds = %.17g" % cpu_seconds)
        if events is not None:
            lines.append("# events = %d" % events)
        if violations is not None:
            lines.append("# violations = %d" % violations)
        if declare_substitutions and self.substituted:
            lines.append("# substituted = %s" % ",".join(self.substituted))
        lines.append(",".join(["t"] + ["%s,%s_var" % (k, k) for k in names]))
        for t, row in zip(self.times, self._rows):
            cells = ["%.17g" % t]
            for k in names:
                cells += ["%.17g" % row[k].mean, "%.17g" % row[k].variance()]
            lines.append(",".join(cells))
        if steady:
            lines += ["# steady", "name,mean,var"]
            for k in steady:
                s = self._steady[k]
                lines.append("%s,%.17g,%.17g" % (k, s.mean, s.variance()))
        try:
            with open(path, "w") as out:
                out.write("\n".join(lines) + "\n")
        except OSError as e:
            fail("%s: %s" % (path, e))
