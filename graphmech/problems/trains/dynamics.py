"""Dynamics and efficiency through a gear train (``[train.dynamics]``, ``[train.efficiency]``):
moments of inertia and moments reduced to a chosen member (planets: their carrier motion and
spin), the efficiency of trains in series and of a planetary train by the converted-train
method, a worm's self-locking. The keys and names: docs/scene-format.md, "Dynamics and efficiency
through a train".

The book's rows come from :mod:`graphmech.methods.train_reduction` and
:mod:`graphmech.methods.train_efficiency` at the speeds the caller gives (the book's); the exact
ones from :mod:`graphmech.exact.train_dynamics` at the speeds of the independent solution.
"""
from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol

from graphmech.errors import GraphmechError, SceneError
from graphmech.mechanisms.gear_train import GearTrain
from graphmech.mechanisms.train_dynamics import Body, MeshLosses, Worm
from graphmech.problems.judging import Row
from graphmech.problems.reader import MISSING, Reader, say

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene


@dataclass(frozen=True)
class BodyEntry:
    """One ``[[train.dynamics.member]]`` as read (SI); ``name`` a member or a gear."""

    name: str
    path: str
    inertia: float = 0.0
    inertia_transverse: float | None = None
    mass: float = 0.0
    arm: float | None = None
    moment: float = 0.0
    count: int = 1


@dataclass(frozen=True)
class WormEntry:
    """One ``[[train.efficiency.worm]]``: its gears (None: the train's one worm mesh), γ or q, φ_v."""

    path: str
    gears: tuple[str, str] | None
    gamma: float | None
    q: float | None
    phi_v: float


@dataclass(frozen=True)
class TrainDynamics:
    """The dynamics tables of a train scene in SI (None where a table is absent).

    reduce_to : the member (or gear) of ``[train.dynamics] reduce_to``.
    bodies : the ``[[train.dynamics.member]]`` entries.
    eta_mesh : one efficiency for every mesh, or one per ``[[train.mesh]]``.
    source, sink : ``[train.efficiency] input`` (None: the train's input) and ``output``.
    worms : the ``[[train.efficiency.worm]]`` entries.
    """

    reduce_to: str | None = None
    bodies: tuple[BodyEntry, ...] = ()
    eta_mesh: float | tuple[float, ...] | None = None
    source: str | None = None
    sink: str | None = None
    worms: tuple[WormEntry, ...] = ()
    has_dynamics: bool = False
    has_efficiency: bool = False


class TrainTables(Protocol):
    """What this part reads of a TrainScene (scene.py imports this module: no import back)."""

    @property
    def train(self) -> GearTrain: ...
    @property
    def module(self) -> float: ...
    @property
    def gear_modules(self) -> Mapping[str, float]: ...
    @property
    def axes(self) -> Mapping[str, str]: ...
    @property
    def dynamics(self) -> TrainDynamics | None: ...


# ----------------------------------------------------------------------------------- reading


#: The largest inertia, mass, arm or moment read, in SI (the flywheel kind's bound).
MAX_TABLE_SI = 1e15
#: The poorest mesh efficiency read: below it a mesh transmits nothing, and a chain of such meshes
#: compounds beyond double precision.
MIN_ETA = 0.01


def _eta(r: Reader, value: object, path: str) -> float | None:
    x = r.number(value, path)
    if x is not None and not 0.0 < x <= 1.0:
        r.problem(path, f"an efficiency lies in (0, 1], not {x:g}")
        return None
    if x is not None and x < MIN_ETA:
        r.problem(path, f"{x:g} is below {MIN_ETA:g}, the poorest mesh efficiency read (such a mesh transmits "
                        "nothing)")
        return None
    return x


def _name(r: Reader, key: str, *, required: bool = False) -> str | None:
    value = r.raw(key, required=required, hint="a member's name")
    if value is MISSING:
        return None
    if isinstance(value, int) and not isinstance(value, bool):
        value = str(value)
    if not isinstance(value, str) or not value:
        r.problem(r.at(key), f"must be a member's name (a string such as \"1\"), not {say(value)}")
        return None
    return value


def _read_body(m: Reader) -> BodyEntry | None:
    name = _name(m, "name", required=True)
    inertia = m.scalar("inertia", "inertia", required=False, default=0.0)
    transverse = m.scalar("inertia_transverse", "inertia", required=False)
    mass = m.scalar("mass", "mass", required=False, default=0.0)
    arm = m.scalar("arm", "length", required=False)
    moment = m.scalar("moment", "moment", required=False, default=0.0)
    count_raw = m.raw("count")
    count = 1
    if count_raw is not MISSING:
        if isinstance(count_raw, bool) or not isinstance(count_raw, int) or count_raw < 1:
            m.problem(m.at("count"), f"must be a whole number ≥ 1, not {say(count_raw)}")
        else:
            count = count_raw
    for key, v in (("inertia", inertia), ("inertia_transverse", transverse), ("mass", mass)):
        if v is not None and v < 0:
            m.problem(m.at(m.present(key) or key), "must be ≥ 0")
            return None
    for key, v in (("inertia", inertia), ("inertia_transverse", transverse), ("mass", mass), ("arm", arm),
                   ("moment", moment)):
        if v is not None and abs(v) > MAX_TABLE_SI:
            m.problem(m.at(m.present(key) or key), f"{v:g} in SI units is beyond the work limit of "
                                                   f"{MAX_TABLE_SI:g} (reduced through the train, it would leave "
                                                   "double precision)")
            return None
    if arm is not None and not arm > 0:
        m.problem(m.at(m.present("arm") or "arm"), "must be > 0")
        return None
    m.finish()
    if name is None or inertia is None or mass is None or moment is None:
        return None
    return BodyEntry(name, m.path, inertia, transverse, mass, arm, moment, count)


def _read_worm(w: Reader) -> WormEntry | None:
    gears_raw = w.raw("gears")
    gears: tuple[str, str] | None = None
    if gears_raw is not MISSING:
        if (not isinstance(gears_raw, list) or len(gears_raw) != 2
                or not all(isinstance(g, (str, int)) and not isinstance(g, bool) for g in gears_raw)):
            w.problem(w.at("gears"), "must be the worm mesh's two gears, [worm, wheel]")
        else:
            gears = (str(gears_raw[0]), str(gears_raw[1]))
    gamma = w.value("lead_angle", "angle", required=False)
    q_raw = w.raw("q")
    q = None if q_raw is MISSING else w.number(q_raw, w.at("q"), positive=True)
    if (gamma is None) == (q_raw is MISSING):
        w.problem(w.path, "give the worm's lead angle (lead_angle_deg) or its diameter quotient q, one of them")
    if gamma is not None and not 0.0 < gamma.si < math.pi / 2:
        w.problem(gamma.path, "a lead angle lies between 0° and 90°")
        return None
    phi = w.value("phi_v", "angle", required=False)
    f_raw = w.raw("f_v")
    f = None if f_raw is MISSING else w.number(f_raw, w.at("f_v"))
    phi_v: float | None = None
    if (phi is None) == (f_raw is MISSING):
        w.problem(w.path, "give the friction as f_v or phi_v_deg, one of them")
    elif phi is not None:
        phi_v = phi.si
        if not 0.0 <= phi_v < math.pi / 2:
            w.problem(phi.path, "a friction angle lies in [0°, 90°)")
            phi_v = None
    elif f is not None:
        if f < 0:
            w.problem(w.at("f_v"), "must be ≥ 0")
        elif not math.atan(f) < math.pi / 2:  # 1e300 gives 90° in double precision
            w.problem(w.at("f_v"), f"{f:g} makes the friction angle 90°: a friction angle lies in [0°, 90°)")
        else:
            phi_v = math.atan(f)
    w.finish()
    if phi_v is None or (gamma is None and q is None):
        return None
    return WormEntry(w.path, gears, None if gamma is None else gamma.si, q, phi_v)


def read_dynamics(train_table: Reader) -> TrainDynamics | None:
    """``[train.dynamics]`` and ``[train.efficiency]`` from the ``[train]`` table's reader (None:
    neither given). Problems go to the reader's list; names are checked against the train by
    :func:`check_dynamics` once it is built."""
    dyn = train_table.table_at("dynamics")
    eff = train_table.table_at("efficiency")
    if dyn is None and eff is None:
        return None
    reduce_to: str | None = None
    bodies: list[BodyEntry] = []
    if dyn is not None:
        reduce_to = _name(dyn, "reduce_to")
        for m in dyn.tables_at("member"):
            b = _read_body(m)
            if b is not None:
                bodies.append(b)
        dyn.finish()
    eta_mesh: float | tuple[float, ...] | None = None
    source = sink = None
    worms: list[WormEntry] = []
    if eff is not None:
        raw = eff.raw("eta_mesh")
        path = eff.at("eta_mesh")
        if isinstance(raw, list):
            etas = [_eta(eff, v, f"{path}[{i}]") for i, v in enumerate(raw)]
            if all(e is not None for e in etas):
                eta_mesh = tuple(e for e in etas if e is not None)
        elif raw is not MISSING:
            eta_mesh = _eta(eff, raw, path)
        source = _name(eff, "input")
        sink = _name(eff, "output")
        for w in eff.tables_at("worm"):
            entry = _read_worm(w)
            if entry is not None:
                worms.append(entry)
        eff.finish()
    return TrainDynamics(reduce_to, tuple(bodies), eta_mesh, source, sink, tuple(worms),
                         dyn is not None, eff is not None)


# ---------------------------------------------------------------------- against the train


@dataclass(frozen=True)
class Resolved:
    """The tables resolved against the train: bodies by member, mesh losses, the members named."""

    bodies: tuple[Body, ...]
    losses: MeshLosses | None
    reduce_to: str | None
    source: str | None
    sink: str | None
    worms: Mapping[str, Worm]  # worm gear → its friction


def check_dynamics(dyn: TrainDynamics, train: GearTrain, problems: list[tuple[str, str]],
                   path: str = "train") -> Resolved:
    """The names checked against ``train`` (problems appended with their key paths)."""
    def member(name: str | None, where: str) -> str | None:
        if name is None:
            return None
        try:
            return train.member_of(name)
        except GraphmechError:
            problems.append((where, f"{say(name)} is not a member or a gear of the train"))
            return None

    summed: dict[str, dict[str, float]] = {}
    counts: dict[str, int] = {}
    extras: dict[str, tuple[float | None, float | None]] = {}
    for b in dyn.bodies:
        m = member(b.name, f"{b.path}.name")
        if m is None:
            continue
        s = summed.setdefault(m, {"inertia": 0.0, "mass": 0.0, "moment": 0.0})
        s["inertia"] += b.inertia
        s["mass"] += b.mass
        s["moment"] += b.moment
        if m in counts and counts[m] != b.count:
            problems.append((f"{b.path}.count", f"member {m} is given count {counts[m]} elsewhere"))
        counts[m] = b.count
        t0, a0 = extras.get(m, (None, None))
        extras[m] = (b.inertia_transverse if b.inertia_transverse is not None else t0,
                     b.arm if b.arm is not None else a0)
        carrier = train.member(m).carrier
        if carrier is None and (b.mass or b.arm is not None or b.count != 1):
            problems.append((b.path, (f"member {m} turns about a fixed axis through its centre: its mass, arm "
                                      "and count add nothing (give its inertia)")))
    bodies = tuple(Body(m, s["inertia"], extras[m][0], s["mass"], extras[m][1], s["moment"], counts[m])
                   for m, s in summed.items())
    reduce_to = member(dyn.reduce_to, f"{path}.dynamics.reduce_to")
    source = member(dyn.source, f"{path}.efficiency.input")
    if source is None and dyn.source is None and train.inputs:
        source = next(iter(train.inputs))
    sink = member(dyn.sink, f"{path}.efficiency.output")
    losses: MeshLosses | None = None
    worms: dict[str, Worm] = {}
    if dyn.has_efficiency:
        n = len(train.meshes)
        etas: tuple[float, ...] | None = None
        if isinstance(dyn.eta_mesh, tuple):
            if len(dyn.eta_mesh) != n:
                problems.append((f"{path}.efficiency.eta_mesh",
                                 f"{len(dyn.eta_mesh)} efficiencies for {n} meshes: one per [[train.mesh]]"))
            else:
                etas = dyn.eta_mesh
        elif dyn.eta_mesh is not None:
            etas = (dyn.eta_mesh,) * n
        worm_meshes = [k for k, m in enumerate(train.meshes) if m.kind == "worm"]
        wlist: list[Worm] = []
        for w in dyn.worms:
            if w.gears is None:
                if len(worm_meshes) != 1:
                    problems.append((f"{w.path}.gears", f"the train has {len(worm_meshes)} worm meshes: say which"))
                    continue
                k = worm_meshes[0]
            else:
                hits = [i for i in worm_meshes if {train.meshes[i].a, train.meshes[i].b} == set(w.gears)]
                if not hits:
                    problems.append((f"{w.path}.gears", f"{list(w.gears)} is not a worm mesh of the train"))
                    continue
                k = hits[0]
            gamma = w.gamma if w.gamma is not None else math.atan(train.gear(train.meshes[k].a).z / (w.q or 1.0))
            if not 0.0 < gamma < math.pi / 2:  # q = 1e-300 or 1e300: tan γ = z₁/q leaves double precision
                problems.append((f"{w.path}.q", (f"{w.q:g} gives a lead angle of {math.degrees(gamma):g}°: a lead "
                                                "angle lies between 0° and 90°")))
                continue
            worm = Worm(k, gamma, w.phi_v)
            wlist.append(worm)
            worms[train.meshes[k].a] = worm
        missing = [k for k in range(n) if k not in {w.mesh for w in wlist}]
        if etas is None and missing and dyn.eta_mesh is None:
            problems.append((f"{path}.efficiency.eta_mesh",
                             "missing: the efficiency of each mesh (a number, or one per [[train.mesh]])"))
        if etas is not None or not missing:
            losses = MeshLosses(etas or (1.0,) * n, tuple(wlist))
        if sink is None and dyn.sink is None:
            problems.append((f"{path}.efficiency.output", "missing: the member loaded"))
    return Resolved(bodies, losses, reduce_to, source, sink, worms)


# ------------------------------------------------------------------------------------ names

#: Name prefixes of this part, longest first (docs/scene-format.md).
PREFIXES = ("J_red_", "M_red_", "eta_worm_reverse_", "eta_worm_", "gamma_", "phi_v_", "eta_")


def split_name(name: str) -> tuple[str, str] | None:
    """``"J_red_1"`` → ``("J_red", "1")``; ``"eta_train"`` → ``("eta_train", "")``; None: not ours."""
    if name == "eta_train":
        return "eta_train", ""
    for p in PREFIXES:
        if name.startswith(p) and len(name) > len(p):
            return p[:-1], name[len(p):]
    return None


def is_dynamics_name(name: str) -> bool:
    """Whether ``name`` is one of this part's (the check routes it here)."""
    return split_name(name) is not None


UNITS: Mapping[str, str] = {"J_red": "kg·m²", "M_red": "N·m", "eta_train": "", "eta": "", "eta_worm": "",
                            "eta_worm_reverse": "", "gamma": "deg", "phi_v": "deg"}


def _rel(g: float, e: float) -> float:
    return abs(g - e) / max(abs(e), 1e-300)


def dynamics_rows(scene: Scene[TrainTables], omega: Mapping[str, float],
                  names: Sequence[str] | None = None) -> list[Row]:
    """The rows of the names asked (default: those of ``scene.find`` that are this part's):
    graphical = the book's method at the speeds ``omega`` (rad/s, every member), exact = the
    independent solution. A name the scene's tables cannot answer is refused (SceneError)."""
    from graphmech.exact import train_dynamics as ex
    from graphmech.exact.gear_train import solve
    from graphmech.methods import train_efficiency as bk
    from graphmech.methods.train_reduction import (
        book_reduced_inertia,
        book_reduced_moment,
    )

    ts = scene.problem
    dyn = ts.dynamics
    asked = [n for n in (scene.find if names is None else names) if is_dynamics_name(n)]
    if not asked:
        return []
    problems: list[tuple[str, str]] = []
    if dyn is None:
        raise SceneError([(f"find[{scene.find.index(asked[0]) if asked[0] in scene.find else 0}]",
                           f"{asked[0]} needs [train.dynamics] or [train.efficiency]")], scene.source)
    res = check_dynamics(dyn, ts.train, problems)
    if problems:
        raise SceneError(problems, scene.source)
    train = ts.train
    exact_omega = solve(train).omega
    rows: list[Row] = []

    def refuse(name: str, reason: str) -> SceneError:
        where = f"find[{scene.find.index(name)}]" if name in scene.find else name
        return SceneError([(where, reason)], scene.source)

    flow: ex.Flow | None = None
    for name in asked:
        base, arg = split_name(name) or ("", "")
        unit = UNITS[base]
        try:
            if base in ("J_red", "M_red"):
                try:
                    r = train.member_of(arg)
                except GraphmechError:
                    raise refuse(name, f"{say(arg)} is not a member of the train") from None
                if res.reduce_to is not None and r != res.reduce_to:
                    raise refuse(name, f"[train.dynamics] reduces to {res.reduce_to}, not {r}")
                if base == "J_red":
                    g = book_reduced_inertia(train, omega, res.bodies, r, ts.module, ts.axes, ts.gear_modules)
                    e = ex.reduced_inertia(train, exact_omega, res.bodies, r, ts.module, ts.axes, ts.gear_modules)
                else:
                    g = book_reduced_moment(train, omega, res.bodies, r, ts.axes)
                    e = ex.reduced_moment(train, exact_omega, res.bodies, r, ts.axes)
            elif base in ("gamma", "phi_v", "eta_worm", "eta_worm_reverse"):
                worm = res.worms.get(arg)
                if worm is None:
                    raise refuse(name, f"{say(arg)} is not a worm given in [[train.efficiency.worm]]")
                if base in ("gamma", "phi_v"):
                    g = e = math.degrees(worm.gamma if base == "gamma" else worm.phi_v)
                else:
                    forward = base == "eta_worm"
                    g = bk.worm_efficiency(worm.gamma, worm.phi_v, forward)
                    e = ex.worm_efficiencies(worm.gamma, worm.phi_v)[0 if forward else 1]
            else:
                if res.losses is None or res.source is None or res.sink is None:
                    raise refuse(name, f"{name} needs [train.efficiency] with eta_mesh and output")
                if flow is None:
                    flow = ex.power_flow(train, exact_omega, res.losses, res.source, res.sink)
                if base == "eta_train":
                    g = bk.book_train_efficiency(train, res.losses, res.source, res.sink)
                    e = flow.eta
                else:
                    if arg not in train.carriers:
                        raise refuse(name, f"{say(arg)} is not a carrier of the train")
                    drv = ex.converted_driver(train, exact_omega, flow, arg)
                    sub_central = [c for c in ex.basic_train(train, arg)[1] if c != drv]
                    g = bk.converted_eta(train, res.losses, arg, drv, sub_central[0])
                    e = ex.converted_efficiency(train, res.losses, arg, drv)
        except SceneError:
            raise
        except GraphmechError as err:
            raise refuse(name, str(err)) from None
        rows.append(Row(name, unit, None, 1.0, g, e, _rel(g, e)))
    return rows


def dynamics_lines(scene: Scene[TrainTables], rows: Sequence[Row] = ()) -> list[str]:
    """The sentences of this part: each worm's self-locking said, a train whose η ≤ 0 said."""
    from graphmech.methods.train_efficiency import self_locks, worm_efficiency

    ts = scene.problem
    if ts.dynamics is None:
        return []
    out: list[str] = []
    res = check_dynamics(ts.dynamics, ts.train, [])
    for gear, w in res.worms.items():
        g, p = math.degrees(w.gamma), math.degrees(w.phi_v)
        reverse = worm_efficiency(w.gamma, w.phi_v, False)
        if self_locks(w.gamma, w.phi_v):
            out.append(f"self_locking: worm {gear} self-locks: γ = {g:.4g}° ≤ φ_v = {p:.4g}°, the wheel cannot "
                       f"drive it (η′ = {reverse:.4g})")
        else:
            out.append(f"self_locking: worm {gear} does not self-lock: γ = {g:.4g}° > φ_v = {p:.4g}° "
                       f"(η′ = {reverse:.4g})")
    for r in rows:
        if r.name == "eta_train" and r.exact <= 0.0:
            out.append(f"self_locking: the train self-locks from {res.source} to {res.sink} (η = {r.exact:.4g} ≤ 0): "
                       "the output cannot be driven from the input that way")
    return out


__all__ = ["BodyEntry", "Resolved", "TrainDynamics", "WormEntry", "check_dynamics", "dynamics_lines",
           "dynamics_rows", "is_dynamics_name", "read_dynamics", "split_name"]
