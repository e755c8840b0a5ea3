"""The efficiency of a gear train as the book finds it: basic trains in series, a planetary train
by its converted train (转化轮系法), a worm's efficiency and self-locking.

* A planetary train of central gear a, carrier H, the other central gear fixed: in the converted
  train (H held) a carries the power P^H_a = M_a(ω_a − ω_H) = P_a(1 − 1/i_aH). The converted
  train loses (1 − η^H)·|P^H_a| where a drives it (P^H_a > 0 while a gives power), and
  (1/η^H − 1)·|P^H_a| where a is driven; η of the train follows from its input power and that loss.
  With a driving and i_aH > 1: η = 1 − (1 − η^H)(i_aH − 1)/i_aH.
* η^H is the converted train's meshes in series, ∏η_j; a train of basic trains in series
  η = ∏η_i (:func:`graphmech.methods.efficiency.chain`).
* A worm: η = tan γ/tan(γ + φ_v) with the worm driving, η′ = tan(γ − φ_v)/tan γ with the wheel
  driving; γ ≤ φ_v self-locks (η′ ≤ 0).

The path of the power through a compound train is found on the train's graph: the ordinary meshes
and each planetary basic train (a fixed central gear) are the stages; a differential inside the
train (its power divides) or two paths from input to output have no series rule and are refused.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.mechanisms.gear_train import GearTrain, Mesh
from graphmech.mechanisms.train_dynamics import MeshLosses
from graphmech.methods.efficiency import chain


def worm_efficiency(gamma: float, phi_v: float, worm_drives: bool = True) -> float:
    """η = tan γ/tan(γ + φ_v) (the worm drives) or η′ = tan(γ − φ_v)/tan γ (the wheel drives)."""
    if not 0.0 < gamma < math.pi / 2 or not 0.0 <= phi_v < math.pi / 2:
        raise OutOfDomain("a worm's lead angle lies in (0°, 90°), its friction angle in [0°, 90°)")
    if worm_drives:
        return math.tan(gamma) / math.tan(gamma + phi_v)
    return math.tan(gamma - phi_v) / math.tan(gamma)


def self_locks(gamma: float, phi_v: float) -> bool:
    """The book's condition: the wheel cannot drive the worm when γ ≤ φ_v."""
    return gamma <= phi_v


def series(etas: Sequence[float]) -> float:
    """η = ∏η_i of stages in series (the book's chain of machines)."""
    return chain([(f"stage {k + 1}", [(1.0, [e])]) for k, e in enumerate(etas)], 1.0)[0]


@dataclass(frozen=True)
class Planetary:
    """A planetary stage by its converted train.

    eta : the stage's η; x : P^H_a/P_a = 1 − 1/i_aH; a_drives_converted : whether central gear a
    drives the converted train; loss : the converted train's loss per unit of the stage's input
    power.
    """

    eta: float
    x: float
    a_drives_converted: bool
    loss: float


def planetary_efficiency(i_aH: float, eta_H: float, a_is_input: bool) -> Planetary:
    """η of a planetary train from a to H (``a_is_input``) or from H to a, the other central gear fixed.

    >>> round(planetary_efficiency(5.0, 0.97, True).eta, 12)  # 1 − 0.03·4/5
    0.976
    """
    if i_aH == 0.0 or not math.isfinite(i_aH):
        raise OutOfDomain(f"i_aH = {i_aH}: the carrier or the central gear is at rest")
    x = 1.0 - 1.0 / i_aH
    if a_is_input:
        drives = x > 0.0  # P^H_a has the sign of P_a·x, and P_a > 0
        loss = abs(x) * ((1.0 - eta_H) if drives else (1.0 / eta_H - 1.0))
        return Planetary(1.0 - loss, x, drives, loss)
    drives = x < 0.0  # a gives out power: P_a < 0
    out_loss = abs(x) * ((1.0 - eta_H) if drives else (1.0 / eta_H - 1.0))  # per unit of |P_a|
    eta = 1.0 / (1.0 + out_loss)
    return Planetary(eta, x, drives, out_loss * eta)


# ------------------------------------------------------------------- the path through a train


@dataclass(frozen=True)
class Stage:
    """One stage on the power's path: ``kind`` "mesh" (an ordinary mesh) or "planetary";
    from member ``source`` to ``sink``; its η, and the converted train's η^H (a planetary stage)."""

    kind: str
    source: str
    sink: str
    eta: float
    carrier: str | None = None
    eta_H: float | None = None
    i: float | None = None


def _mesh_eta(train: GearTrain, losses: MeshLosses, k: int, driver_member: str) -> float:
    worm = losses.worm(k)
    if worm is None:
        return losses.eta[k]
    return worm_efficiency(worm.gamma, worm.phi_v, train.gear(train.meshes[k].a).member == driver_member)


def _converted_chain(train: GearTrain, carrier: str, a: str, b: str) -> list[tuple[int, str, str]]:
    """The meshes of H's converted train from central member a to b: (index, from member, to member)."""
    meshes = [(k, m) for k, m in enumerate(train.meshes) if train.mesh_frame(m) == carrier]
    prev: dict[str, tuple[int, str, str]] = {}
    seen, todo = {a}, [a]
    while todo:
        u = todo.pop(0)
        for k, m in meshes:
            ma, mb = train.gear(m.a).member, train.gear(m.b).member
            for p, q in ((ma, mb), (mb, ma)):
                if p == u and q not in seen:
                    seen.add(q)
                    prev[q] = (k, p, q)
                    todo.append(q)
    if b not in seen:
        raise OutOfDomain(f"the converted train of {carrier} does not join {a} to {b}")
    path: list[tuple[int, str, str]] = []
    v = b
    while v != a:
        path.append(prev[v])
        v = prev[v][1]
    return path[::-1]


def converted_ratio(train: GearTrain, chain_: Sequence[tuple[int, str, str]]) -> Fraction:
    """Willis' i^H_ab along the chain: ∏ (ω_p − ω_H)/(ω_q − ω_H) = ∏ s·z_q/z_p per mesh, kept as
    the fraction of tooth numbers the book writes (i_aH = 1 − i^H_ab cancels: 1 − 9999/10000)."""
    i = Fraction(1)
    for k, p, q in chain_:
        m: Mesh = train.meshes[k]
        gp, gq = (m.a, m.b) if train.gear(m.a).member == p else (m.b, m.a)
        i *= Fraction(m.relative_sign * train.gear(gq).z, train.gear(gp).z)
    return i


def converted_eta(train: GearTrain, losses: MeshLosses, carrier: str, driver: str, driven: str) -> float:
    """η^H: the converted train's meshes in series from ``driver`` to ``driven``."""
    return series([_mesh_eta(train, losses, k, p) for k, p, _ in _converted_chain(train, carrier, driver, driven)])


def _central(train: GearTrain, carrier: str) -> list[str]:
    planets = set(train.planets(carrier))
    used = {train.gear(g).member for m in train.meshes if train.mesh_frame(m) == carrier for g in (m.a, m.b)}
    return [m.name for m in train.members if m.name in used and m.name not in planets]


def _edges(train: GearTrain, losses: MeshLosses) -> list[tuple[str, str, str, int | str]]:
    """(kind, member, member, mesh index or carrier) of the train's stages."""
    edges: list[tuple[str, str, str, int | str]] = []
    for k, m in enumerate(train.meshes):
        if train.mesh_frame(m) is None:
            edges.append(("mesh", train.gear(m.a).member, train.gear(m.b).member, k))
    for h in train.carriers:
        central = _central(train, h)
        fixed = [c for c in central if c in train.fixed]
        moving = [c for c in central if c not in train.fixed]
        if len(central) != 2 or len(fixed) != 1:
            raise OutOfDomain(f"the basic train of carrier {h} (central {', '.join(central)}) is not a planetary "
                              "train with one of two central gears fixed: its power divides, and the book's "
                              "series rule does not give the train's efficiency")
        edges.append(("planetary", moving[0], h, h))
    return edges


def train_path(train: GearTrain, losses: MeshLosses, source: str, sink: str) -> tuple[Stage, ...]:
    """The stages from ``source`` to ``sink`` in series, each with its η (the book's path)."""
    src, snk = train.member_of(source), train.member_of(sink)
    edges = _edges(train, losses)
    paths: list[list[tuple[str, str, str, int | str]]] = []

    def walk(u: str, seen: set[str], path: list[tuple[str, str, str, int | str]]) -> None:
        if u == snk:
            paths.append(list(path))
            return
        for e in edges:
            for p, q in ((e[1], e[2]), (e[2], e[1])):
                if p == u and q not in seen:
                    walk(q, seen | {q}, path + [(e[0], p, q, e[3])])

    walk(src, {src}, [])
    if not paths:
        raise NoSolution(f"no path of meshes carries the power from {src} to {snk}")
    staged = [_stages(train, losses, path) for path in paths]
    # power that divides among branches of one efficiency (identical idlers, a copied planet set)
    # loses the same fraction whichever way it divides: the series rule holds for each branch
    if len({series([s.eta for s in st]) for st in staged}) > 1:
        raise OutOfDomain(f"the power from {src} to {snk} has {len(paths)} paths of different efficiencies: it "
                          "divides, and the book's series rule does not give the train's efficiency")
    return staged[0]


def _stages(train: GearTrain, losses: MeshLosses, path: Sequence[tuple[str, str, str, int | str]]) -> tuple[Stage, ...]:
    """The stages of one path of the power, each with its η."""
    stages: list[Stage] = []
    for kind, p, q, ref in path:
        if kind == "mesh":
            assert isinstance(ref, int)
            stages.append(Stage("mesh", p, q, _mesh_eta(train, losses, ref, p)))
            continue
        h = str(ref)
        a = p if p != h else q
        b = next(c for c in _central(train, h) if c in train.fixed)
        i_ab = converted_ratio(train, _converted_chain(train, h, a, b))
        i_aH = 1 - i_ab  # ω_b = 0: (ω_a − ω_H)/(−ω_H) = i^H_ab
        if i_aH == 0:
            raise NoSolution(f"i^{h}_{a}{b} = 1: the train locks")
        a_in = p == a
        drives = (1 - 1 / i_aH > 0) == a_in  # which central gear drives the converted train
        eta_H = converted_eta(train, losses, h, a if drives else b, b if drives else a)
        i = float(i_aH)
        stages.append(Stage("planetary", p, q, planetary_efficiency(i, eta_H, a_in).eta, h, eta_H, i))
    return tuple(stages)


def book_train_efficiency(train: GearTrain, losses: MeshLosses, source: str, sink: str) -> float:
    """η = ∏ of the stages' η on the power's path."""
    return series([s.eta for s in train_path(train, losses, source, sink)])


__all__ = ["Planetary", "Stage", "book_train_efficiency", "converted_eta", "converted_ratio", "planetary_efficiency",
           "self_locks", "series", "train_path", "worm_efficiency"]
