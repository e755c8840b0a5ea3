"""Dynamics and efficiency through a gear train, solved independently of the book's formulas.

* The reduced moment of inertia from the kinetic energy: J_red = 2T/ω_r², T summed body by body —
  a member turning about a fixed axis ½Jω², a planet ½m v_c² (its centre on the carrier's arm,
  v_c = |ω_H|·arm) plus ½ω·Jω with its absolute angular velocity ω = ω_H û_H + (ω_p − ω_H) û_p (a
  bevel planet: a vector sum, its axial and transverse parts each with its moment of inertia).
* The reduced moment from the power: M_red = Σ M_k (ω·û_k)/ω_r.
* The efficiency from a power balance: every mesh is a force between two members whose
  generalised forces (Q_a, Q_b on the members, Q_H = −Q_a − Q_b on the carrier whose frame it is
  written in: the pair does no work when everything turns with the carrier) pass, in that frame,
  η of the power the driving gear gives: Q_N·u_N = −η·Q_D·u_D, u = ω − ω_H. Every member is in
  equilibrium, Σ_j Q_jk + M_k = 0, the output loaded by 1 W, the input's moment and the fixed
  members' reactions unknown: a square linear system, eliminated in exact rationals
  (:func:`graphmech.exact.gear_train.reduce`). Which gear drives each mesh comes from the
  frictionless solution. The book's converted-train formula is not used here.
"""
from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.exact.efficiency import screw_efficiency
from graphmech.exact.gear_train import Row, mesh_row, reduce, solve
from graphmech.mechanisms.gear_train import GearTrain, Member
from graphmech.mechanisms.train_dynamics import (
    Body,
    MeshLosses,
    axis_cos,
    check_body,
    planet_arm,
)


def angular_parts(train: GearTrain, omega: Mapping[str, float], member: str,
                  axes: Mapping[str, str]) -> tuple[float, float]:
    """A member's absolute angular velocity along its axis and across it (rad/s).

    A member on a fixed axis, or a planet parallel to its carrier, turns at its own ω (the model's
    speeds are absolute there); a planet at an angle θ to its carrier spins at ω_p − ω_H relative to
    it, so ω_abs = ω_H û_H + (ω_p − ω_H) û_p: ω_H cos θ + ω_p − ω_H along û_p, ω_H sin θ across.
    """
    h = train.member(member).carrier
    w = omega[member]
    if h is None:
        return w, 0.0
    c = axis_cos(axes, h, member)
    if abs(c) == 1.0:
        return w, 0.0
    wh = omega[h]
    return wh * c + (w - wh), abs(wh) * math.sqrt(1.0 - c * c)


def kinetic_energy(train: GearTrain, omega: Mapping[str, float], bodies: Sequence[Body], module: float,
                   axes: Mapping[str, str] | None = None, modules: Mapping[str, float] | None = None) -> float:
    """T of the bodies at the speeds ``omega`` (J)."""
    axes = axes or {}
    t = 0.0
    for b in bodies:
        check_body(train, b)
        axial, across = angular_parts(train, omega, b.member, axes)
        if across and b.inertia_transverse is None and b.inertia:
            raise OutOfDomain(f"member {b.member} is a bevel planet: its absolute ω has a part across its "
                              "axis, so its inertia about a diameter is needed too")
        e = b.inertia * axial * axial + (b.inertia_transverse or 0.0) * across * across
        h = train.member(b.member).carrier
        if h is not None and b.mass:
            arm = b.arm if b.arm is not None else _arm(train, module, b.member, axes, modules)
            v = omega[h] * arm
            e += b.mass * v * v
        t += 0.5 * b.count * e
    return t


def _arm(train: GearTrain, module: float, planet: str, axes: Mapping[str, str],
         modules: Mapping[str, float] | None) -> float:
    h = train.member(planet).carrier
    assert h is not None
    if abs(axis_cos(axes, h, planet)) != 1.0:
        raise OutOfDomain(f"member {planet} is a bevel planet: state its arm (its centre's distance from "
                          f"the axis of {h})")
    return planet_arm(train, module, planet, modules)


def reduced_inertia(train: GearTrain, omega: Mapping[str, float], bodies: Sequence[Body], to: str,
                    module: float, axes: Mapping[str, str] | None = None,
                    modules: Mapping[str, float] | None = None) -> float:
    """J_red = 2T/ω_r² (kg·m²), T taken at the speeds divided by ω_r (the same J_red: T scales
    as ω², and ω_r² may underflow where the ratios do not)."""
    wr = _speed_of(train, omega, to)
    unit = {k: v / wr for k, v in omega.items()}
    return 2.0 * kinetic_energy(train, unit, bodies, module, axes, modules)


def reduced_moment(train: GearTrain, omega: Mapping[str, float], bodies: Sequence[Body], to: str,
                   axes: Mapping[str, str] | None = None) -> float:
    """M_red = (Σ M_k·ω_k)/ω_r: the moments' power over the reduction member's speed (N·m)."""
    wr = _speed_of(train, omega, to)
    power = sum(b.count * b.moment * angular_parts(train, omega, b.member, axes or {})[0] for b in bodies)
    return power / wr


def _speed_of(train: GearTrain, omega: Mapping[str, float], name: str) -> float:
    w = omega[train.member_of(name)]
    if w == 0.0:
        raise NoSolution(f"nothing can be reduced to {name}: it is at rest")
    return w


# ------------------------------------------------------------------------------- efficiency


@dataclass(frozen=True)
class Flow:
    """The power balance of a train loaded at ``output`` with 1 W.

    eta : P_out/P_in (≤ 0: the train cannot be driven that way — it self-locks).
    moment_in : the input member's moment, N·m.
    drivers : mesh index → the gear that drives it in its carrier's frame (None: no relative
        motion, no loss); redundant meshes (identical planets beyond the first) are left out.
    mesh_forces : mesh index → the generalised forces of the mesh on each member it acts on.
    """

    eta: float
    moment_in: float
    drivers: Mapping[int, str | None]
    mesh_forces: Mapping[int, Mapping[str, Fraction]]


def _relative(train: GearTrain, omega: Mapping[str, float], k: int, gear: str) -> float:
    mesh = train.meshes[k]
    h = train.mesh_frame(mesh)
    return omega[train.gear(gear).member] - (omega[h] if h is not None else 0.0)


def mesh_eta(train: GearTrain, losses: MeshLosses, k: int, driver: str | None) -> float:
    """η of mesh k driven by ``driver`` (a worm's forward or reverse efficiency)."""
    if driver is None:
        return 1.0
    worm = losses.worm(k)
    if worm is None:
        return losses.eta[k]
    return screw_efficiency(worm.gamma, worm.phi_v, "forward" if driver == train.meshes[k].a else "reverse")


def independent_meshes(train: GearTrain) -> list[int]:
    """The meshes whose constraints the others do not imply (an identical planet's counted once)."""
    index = {m.name: i for i, m in enumerate(train.members)}
    rows: list[Row] = [({index[f]: Fraction(1)}, Fraction(0)) for f in train.fixed]
    keep: list[int] = []
    rank = reduce(rows, len(index)).rank
    for k, mesh in enumerate(train.meshes):
        trial = rows + [(mesh_row(train, mesh, index), Fraction(0))]
        r = reduce(trial, len(index)).rank
        if r > rank:
            rows, rank = trial, r
            keep.append(k)
    return keep


def _forces(train: GearTrain, k: int, driver: str | None, eta: float) -> dict[str, Fraction]:
    """Mesh k's generalised forces per unit multiplier: Q_D = z_D, Q_N = −η·s·z_N, Q_H the rest."""
    mesh = train.meshes[k]
    s = mesh.relative_sign
    d, n = (mesh.a, mesh.b) if driver in (None, mesh.a) else (mesh.b, mesh.a)
    gd, gn = train.gear(d), train.gear(n)
    e = Fraction(1) if driver is None else Fraction(eta)
    q: dict[str, Fraction] = {}
    q[gd.member] = q.get(gd.member, Fraction(0)) + gd.z
    q[gn.member] = q.get(gn.member, Fraction(0)) - e * s * gn.z
    h = train.mesh_frame(mesh)
    if h is not None:
        q[h] = q.get(h, Fraction(0)) - q[gd.member] - q[gn.member]
    return q


def power_flow(train: GearTrain, omega: Mapping[str, float], losses: MeshLosses, source: str, sink: str,
               drivers: Mapping[int, str | None] | None = None) -> Flow:
    """The train's equilibrium with ``sink`` loaded by 1 W and ``source`` driving it.

    ``drivers`` fixes which gear drives each mesh (default: found from the frictionless balance,
    then checked against the balance with friction and found again while they change).
    """
    src, snk = train.member_of(source), train.member_of(sink)
    if src == snk:
        raise OutOfDomain(f"the input and the output are one member ({src})")
    for name in (src, snk):
        if name in train.fixed:
            raise OutOfDomain(f"member {name} is fixed: it can be neither the input nor the output")
        if omega[name] == 0.0:
            raise NoSolution(f"member {name} is at rest: no power passes it")
    if len(losses.eta) != len(train.meshes):
        raise OutOfDomain(f"{len(losses.eta)} mesh efficiencies for {len(train.meshes)} meshes")
    keep = independent_meshes(train)
    if drivers is None:
        ideal = _balance(train, omega, losses, src, snk, keep, {k: None for k in keep}, ideal=True)
        found = _drivers(train, omega, ideal)
        for _ in range(4):
            flow = _balance(train, omega, losses, src, snk, keep, found)
            if flow.eta <= 0.0:
                return flow  # self-locked: the driving senses stay those of the free train
            again = _drivers(train, omega, flow)
            if again == found:
                return flow
            found = again
        raise NoSolution("the meshes' power flow does not settle: which gear drives changes with friction")
    return _balance(train, omega, losses, src, snk, keep, drivers)


def _drivers(train: GearTrain, omega: Mapping[str, float], flow: Flow) -> dict[int, str | None]:
    """Each mesh's driving gear: the one whose member gives power to the mesh (−Q·u > 0)."""
    out: dict[int, str | None] = {}
    for k, q in flow.mesh_forces.items():
        mesh = train.meshes[k]
        ua = _relative(train, omega, k, mesh.a)
        if ua == 0.0:
            out[k] = None
            continue
        given = -q[train.gear(mesh.a).member] * Fraction(ua)
        out[k] = mesh.a if given > 0 else mesh.b
    return out


def _balance(train: GearTrain, omega: Mapping[str, float], losses: MeshLosses, src: str, snk: str,
             keep: Sequence[int], drivers: Mapping[int, str | None], *, ideal: bool = False) -> Flow:
    names = [m.name for m in train.members]
    n_mesh = len(keep)
    forces = {k: _forces(train, k, None if ideal else drivers[k],
                         1.0 if ideal else mesh_eta(train, losses, k, drivers[k])) for k in keep}
    unknown_in = n_mesh
    reaction = {f: n_mesh + 1 + i for i, f in enumerate(train.fixed)}
    rows: list[Row] = []
    for name in names:
        coeffs: dict[int, Fraction] = {}
        for j, k in enumerate(keep):
            c = forces[k].get(name)
            if c:
                coeffs[j] = c
        if name == src:
            coeffs[unknown_in] = Fraction(1)
        if name in reaction:
            coeffs[reaction[name]] = Fraction(1)
        rhs = 1 / Fraction(omega[snk]) if name == snk else Fraction(0)  # M_out·ω_out = −1 W
        rows.append((coeffs, rhs))
    size = n_mesh + 1 + len(reaction)
    red = reduce(rows, size)
    m_in = red.determined(unknown_in) if red.consistent else None
    lams = [red.determined(j) if red.consistent else None for j in range(n_mesh)]
    if m_in is None or any(v is None for v in lams):
        raise NoSolution(f"the train is not in equilibrium with {src} driving and {snk} loaded alone "
                         "(a train of mobility 1 is needed)")
    mesh_forces = {k: {m: c * lam for m, c in forces[k].items()} for k, lam in zip(keep, lams) if lam is not None}
    p_in = m_in * Fraction(omega[src])
    try:
        eta = math.inf if p_in == 0 else float(1 / p_in)
        m_in_f = float(m_in)
    except OverflowError:  # the losses of many poor meshes compound beyond double precision
        raise NoSolution(f"the input moment to drive {snk} is beyond double precision: the meshes' efficiencies "
                         "compound to nothing") from None
    return Flow(eta, m_in_f, dict(drivers), mesh_forces)


def train_efficiency(train: GearTrain, omega: Mapping[str, float], losses: MeshLosses, source: str,
                     sink: str) -> float:
    """η from ``source`` to ``sink`` by the power balance."""
    return power_flow(train, omega, losses, source, sink).eta


# -------------------------------------------------------------------- the converted train


def basic_train(train: GearTrain, carrier: str) -> tuple[GearTrain, tuple[str, ...]]:
    """Carrier H's converted train as a train of its own (H held in the frame, its planets on fixed
    axes) and its central members, in the order of the members."""
    planets = set(train.planets(carrier))
    if not planets:
        raise OutOfDomain(f"member {carrier} carries no planets")
    meshes = tuple(m for m in train.meshes if train.mesh_frame(m) == carrier)
    used = {train.gear(g).member for m in meshes for g in (m.a, m.b)}
    central = tuple(m.name for m in train.members if m.name in used and m.name not in planets)
    # H held: every member on an axis fixed in the frame, the meshes with their senses
    members = tuple(Member(m.name) for m in train.members if m.name in used or m.name == carrier)
    gears = tuple(g for g in train.gears if g.member in used)
    return GearTrain(members, gears, meshes, fixed=(carrier,)), central


def converted_efficiency(train: GearTrain, losses: MeshLosses, carrier: str, driver: str) -> float:
    """η^H: carrier H held, its central member ``driver`` driving the other one (power balance).

    The converted train's meshes keep their efficiencies; a basic train with more than two central
    members has no one η^H and is refused.
    """
    sub, central = basic_train(train, carrier)
    drv = train.member_of(driver)
    if len(central) != 2 or drv not in central:
        raise OutOfDomain(f"the converted train of {carrier} has central members {', '.join(central)}: "
                          f"η^{carrier} is posed between two of them, {driver} one")
    other = central[1] if central[0] == drv else central[0]
    keep = [k for k, m in enumerate(train.meshes) if train.mesh_frame(m) == carrier]
    sub_losses = MeshLosses(tuple(losses.eta[k] for k in keep),
                            tuple(type(w)(keep.index(w.mesh), w.gamma, w.phi_v) for w in losses.worms if w.mesh in keep))
    omega = solve(sub.with_inputs({drv: 1.0})).omega
    return power_flow(sub, omega, sub_losses, drv, other).eta


def converted_driver(train: GearTrain, omega: Mapping[str, float], flow: Flow, carrier: str) -> str:
    """The central member that drives H's converted train in the train's working: the one that
    gives the carrier-frame meshes power, −Σ Q·(ω − ω_H) > 0, the most."""
    planets = set(train.planets(carrier))
    best: tuple[Fraction, str] | None = None
    for name in (m.name for m in train.members):
        if name in planets or name == carrier:
            continue
        q = sum((f.get(name, Fraction(0)) for k, f in flow.mesh_forces.items()
                 if train.mesh_frame(train.meshes[k]) == carrier), Fraction(0))
        if q == 0:
            continue
        given = -q * (Fraction(omega[name]) - Fraction(omega[carrier]))
        if best is None or given > best[0]:
            best = (given, name)
    if best is None or best[0] <= 0:
        raise NoSolution(f"no power passes the converted train of {carrier}")
    return best[1]


def worm_efficiencies(gamma: float, phi_v: float) -> tuple[float, float]:
    """(η with the worm driving, η′ with the wheel driving)."""
    return screw_efficiency(gamma, phi_v, "forward"), screw_efficiency(gamma, phi_v, "reverse")


__all__ = ["Flow", "angular_parts", "basic_train", "converted_driver", "converted_efficiency",
           "independent_meshes", "kinetic_energy", "mesh_eta", "power_flow", "reduced_inertia",
           "reduced_moment", "train_efficiency", "worm_efficiencies"]
