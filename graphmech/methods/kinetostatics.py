"""Kinetostatic analysis by force polygons, Assur group by Assur group (动态静力分析).

The textbook order, for every position at once (arrays over positions):

1. **Inertia loads** from the acceleration polygon: F_i = −m·a_S at the centre of mass S,
   M_i = −J_S·α, and the single resultant's offset h = |M_i/F_i| from S.
2. **The groups, farthest from the driver first** (the dyads in reverse assembly order). For a
   dyad P–C–Q the reaction at each outer joint is split into a tangential component ⟂ PC (QC),
   found from the moments of *one* link about the middle joint C, and a normal component ∥ PC
   (QC), found from the group's **force polygon**: lay off R^t_P, the known forces of both links,
   R^t_Q head to tail; through the end draw ∥ QC, through the start ∥ PC; they meet at the
   polygon's closing vertex. The middle joint's reaction closes the polygon of one link. For a
   slider (RRP) the guide's reaction is ⟂ guide (tilted by φ with friction) and its line of
   action comes from the slider's moments about C; a guide on a moving link bears the opposite
   reaction on the same line, a load of that link when its own group is solved. Two blocks
   pinned at C on two guides (PRP): the group's polygon closes on the two guides' normals. A guide bar and block (RPR): the bar's
   reaction on the block from the bar's moments about its pivot. A block in a slot of a slider
   (RPP): the slotted slider's polygon closes on the slot's and the guide's directions.
3. **The driver**: what the groups put on the crank, its own loads, the frame's reaction R_01
   closing its polygon and the **balancing moment** M_b from its moments about the pivot (a
   driving slider: the **balancing force** F_b along its guide and the guide's reaction).
4. **Friction** (摩擦圆, 摩擦角) by successive approximation from the frictionless solution: each
   round the revolute reactions are moved tangent to their friction circles (a couple −ρ|R|
   against the relative rotation) and the slider reactions tilted by φ = arctan f against the
   sliding velocity, with the magnitudes and senses of the round before; the groups are solved
   again until no reaction changes by more than the tolerance.
5. **Zhukovsky's lever** (茹可夫斯基杠杆): the velocity polygon turned 90°, every load applied at
   its point's image, moments about the pole p: M_b = μv·ΣM_p/ω1 (virtual power; a driving
   slider: F_b = μv·ΣM_p/v).

Plane vectors are complex numbers ``x + iy`` (arrays of shape (N,)); ``u × w = Im(ū·w)``. A
reaction ``R_ij`` is the force of link i on link j.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any, cast

import numpy as np

from graphmech.errors import DegenerateConstruction
from graphmech.mechanisms.forces import ForceModel, LinkMass
from graphmech.mechanisms.linkage import PRP, RPP, RPR, RRP, RRR, Crank, Guide, Linkage, LinkGuide, SliderInput, Triad
from graphmech.tolerances import PARALLEL_SIN, SHALLOW_DEG

#: |sin| of the angle between the two unknown directions of a polygon below which a hand
#: construction is unreliable (the closing vertex moves by 1/sin of a pencil's error).
SHALLOW_SIN = math.sin(math.radians(SHALLOW_DEG))


# --------------------------------------------------------------------------------------------
# The motion, as read off the polygons


@dataclass(frozen=True)
class PolygonKinematics:
    """The motion the force analysis needs, read off the kinematic diagram and the polygons.

    Every array has shape (N,); vectors are complex (x + iy).

    Parameters
    ----------
    point : dict of str to ndarray
        Point name → position, m.
    vel : dict of str to ndarray
        Point name → velocity, m/s (image in the velocity polygon × μv).
    acc : dict of str to ndarray
        Point name → acceleration, m/s² (image in the acceleration polygon × μa).
    omega, alpha : dict of str to ndarray
        Moving link id → angular velocity (rad/s) and acceleration (rad/s²), + CCW.
    mu_v : float
        The velocity polygon's scale, (m/s)/mm (for Zhukovsky's lever).
    valid : ndarray of bool
        Where the construction could be built.
    """

    point: dict[str, np.ndarray]
    vel: dict[str, np.ndarray]
    acc: dict[str, np.ndarray]
    omega: dict[str, np.ndarray]
    alpha: dict[str, np.ndarray]
    mu_v: float
    valid: np.ndarray


def kinematics_from_construction(build: Any, values: dict[str, Any], valid: np.ndarray) -> PolygonKinematics:
    """Read positions, images and angular rates off an evaluated polygon construction.

    ``build`` is a :class:`~graphmech.methods.linkage_construction.LinkageConstruction`, ``values`` its
    (batch) step values, ``valid`` the positions that could be built. Drawn millimetres are
    multiplied by μ: the force analysis works in SI.
    """
    n = valid.shape[0]
    ml, mv, ma = build.scales["l"], build.scales["v"], build.scales["a"]
    ox, oy = build.origin

    def vec(step: str, mu: float, shift: complex = 0j) -> np.ndarray:
        x, y = values[step]
        return np.broadcast_to((np.asarray(x, float) + 1j * np.asarray(y, float)) * mu + shift, (n,)).copy()

    def rate(step: str) -> np.ndarray:
        drawn, scale = values[step]
        return np.broadcast_to(np.asarray(drawn, float) * np.asarray(scale, float), (n,)).copy()

    point = {k: vec(s, ml, complex(ox, oy)) for k, s in build.mech.items()}
    vel = {k: vec(s, mv) for k, s in build.vel.items()}
    acc = {k: vec(s, ma) for k, s in build.acc.items()}
    omega = {k: rate(s) for k, s in build.omega.items()}
    alpha = {k: rate(s) for k, s in build.alpha.items()}
    for k in build.translating:
        omega.setdefault(k, np.zeros(n))
        alpha.setdefault(k, np.zeros(n))
    return PolygonKinematics(point, vel, acc, omega, alpha, mv, valid)


def construction_targets(build: Any) -> list[str]:
    """The steps whose values :func:`kinematics_from_construction` reads."""
    return [*build.mech.values(), *build.vel.values(), *build.acc.values(), *build.omega.values(),
            *build.alpha.values()]


# --------------------------------------------------------------------------------------------
# Inertia loads


@dataclass(frozen=True)
class InertiaLoad:
    """The inertia load of one link: F_i = −m·a_S at S, M_i = −J_S·α, h = |M_i|/|F_i|.

    Arrays over positions; ``force`` complex (N), ``moment`` N·m, ``offset`` m (0 where F_i = 0).
    The single resultant is F_i moved by h to the side that makes its moment about S equal M_i.
    """

    link: str
    point: str
    force: np.ndarray
    moment: np.ndarray
    offset: np.ndarray

    @property
    def resultant_shift(self) -> np.ndarray:
        """The vector from S to a point of the single resultant's line of action, m (complex)."""
        f = self.force
        mag2 = np.abs(f) ** 2
        safe = np.where(mag2 > 0, mag2, 1.0)
        # r × F = M with r ⟂ F: r = M·(i·F)… turned so that Im(r̄·F) = M → r = −i·M·F/|F|².
        return np.where(mag2 > 0, -1j * self.moment * f / safe, 0j)


def inertia_load(mass: float, inertia: float, a_S: Any, alpha: Any) -> tuple[Any, Any, Any]:
    """The textbook's arithmetic: F_i = −m·a_S, M_i = −J_S·α, h = |M_i/F_i|.

    Parameters
    ----------
    mass : float
        m, kg.
    inertia : float
        J_S, kg·m².
    a_S : complex or ndarray or float
        Acceleration of the centre of mass, m/s² (a complex vector, or a magnitude).
    alpha : float or ndarray
        Angular acceleration, rad/s².

    Returns
    -------
    (F_i, M_i, h)
        N (same type as a_S), N·m, m (0 where F_i = 0).

    Examples
    --------
    The piston and rod of a slider-crank, weights 21 N and 25 N, a_C = 1800, a_S2 = 2122.5 m/s²,
    α2 = 5000 rad/s², J_S2 = 0.0425 kg·m²:

    >>> F3, _, _ = inertia_load(21 / 9.81, 0.0, 1800.0, 0.0)
    >>> F2, M2, h2 = inertia_load(25 / 9.81, 0.0425, 2122.5, 5000.0)
    >>> round(abs(F3), 1), round(abs(F2), 1), round(abs(M2), 2), round(h2, 4)
    (3853.2, 5409.0, 212.5, 0.0393)
    """
    f = -mass * np.asarray(a_S)
    m = -inertia * np.asarray(alpha, dtype=float)
    mag = np.abs(f)
    h = np.where(mag > 0, np.abs(m) / np.where(mag > 0, mag, 1.0), 0.0)
    if np.ndim(h) == 0:
        return f.item(), float(m), float(h)
    return f, m, h


def inertia_loads(masses: tuple[LinkMass, ...], kin: PolygonKinematics) -> dict[str, InertiaLoad]:
    """Link id → its inertia load, from the acceleration images of the centres of mass."""
    out = {}
    for lm in masses:
        a = kin.acc[lm.point]
        al = kin.alpha.get(lm.link, np.zeros_like(a.real))
        f, m, h = inertia_load(lm.mass, lm.inertia, a, al)
        out[lm.link] = InertiaLoad(lm.link, lm.point, np.asarray(f), np.asarray(m), np.asarray(h))
    return out


# --------------------------------------------------------------------------------------------
# Loads on the links


@dataclass(frozen=True)
class Force:
    """A force acting on a link: its label, vector (complex, N) and point of application (m)."""

    name: str
    vector: np.ndarray
    at: np.ndarray
    point: str = ""  # the named point it acts at ("" for a guide reaction's line of action)


@dataclass(frozen=True)
class Couple:
    name: str
    moment: np.ndarray
    link: str = ""  # the link it acts on (set when it is put on one)


def _cross(u: np.ndarray, w: np.ndarray) -> np.ndarray:
    return cast(np.ndarray, (np.conj(u) * w).imag)


#: A relative rotation or sliding speed below this fraction of the mechanism's largest is no
#: motion at all (two links turning together at a position): no sense, so no friction there.
STILL = 1e-9


def _sign(x: np.ndarray, scale: Any = 0.0) -> np.ndarray:
    """sign(x), 0 where |x| ≤ STILL·scale (rounding must not pick a friction's sense)."""
    return np.where(np.abs(x) > STILL * np.asarray(scale), np.sign(x), 0.0).astype(float)


def _largest(rates: dict[str, np.ndarray], n: int) -> np.ndarray:
    """The largest |value| among the links (or points) at each position."""
    return cast(np.ndarray, np.max(np.abs(np.stack(list(rates.values()) or [np.zeros(n)])), axis=0))


@dataclass
class _Loads:
    """The forces and couples known on each link, growing as the groups are solved."""

    forces: dict[str, list[Force]] = field(default_factory=dict)
    couples: dict[str, list[Couple]] = field(default_factory=dict)

    def force(self, link: str, f: Force) -> None:
        self.forces.setdefault(link, []).append(f)

    def couple(self, link: str, c: Couple) -> None:
        self.couples.setdefault(link, []).append(replace(c, link=link))

    def total(self, link: str, n: int) -> np.ndarray:
        return sum((f.vector for f in self.forces.get(link, [])), np.zeros(n, complex))

    def moment_about(self, link: str, o: np.ndarray) -> np.ndarray:
        m = np.zeros(o.shape, float)
        for f in self.forces.get(link, []):
            m = m + _cross(f.at - o, f.vector)
        for c in self.couples.get(link, []):
            m = m + c.moment
        return m


def external_loads(model: ForceModel, kin: PolygonKinematics, inertia: dict[str, InertiaLoad],
                   frame: str) -> _Loads:
    """Weights, inertia loads, external forces and moments, per link (the textbook's 'known forces')."""
    n = kin.valid.shape[0]
    loads = _Loads()
    for lm in model.masses:
        if lm.link == frame:
            continue
        if model.gravity > 0 and lm.mass > 0:
            g = np.full(n, -1j * lm.mass * model.gravity)
            loads.force(lm.link, Force(f"G_{lm.link}", g, kin.point[lm.point], lm.point))
        il = inertia[lm.link]
        if lm.mass > 0:
            loads.force(lm.link, Force(f"F_i{lm.link}", il.force, kin.point[lm.point], lm.point))
        if lm.inertia > 0:
            loads.couple(lm.link, Couple(f"M_i{lm.link}", il.moment))
    for pf in model.forces:
        vec = np.full(n, complex(*pf.vector))
        if pf.resistance:  # a working resistance acts only while it opposes the motion
            power = (np.conj(vec) * kin.vel[pf.point]).real
            vec = np.where(power < 0, vec, 0j)
        loads.force(pf.link, Force(pf.name, vec, kin.point[pf.point], pf.point))
    for c in model.couples:
        loads.couple(c.link, Couple(c.name, np.full(n, c.moment)))
    return loads


# --------------------------------------------------------------------------------------------
# Structure: the groups and their joints


@dataclass(frozen=True)
class Joint:
    """A revolute between link ``a`` (the earlier one, or the frame) and link ``b`` at ``point``."""

    point: str
    a: str
    b: str


def carriers(linkage: Linkage) -> dict[str, str]:
    """Point name → the link that first carries it (frame points → the frame link)."""
    out = {p: linkage.frame_link for p in linkage.frame_points}
    d = linkage.driver
    out.setdefault(d.tip if isinstance(d, Crank) else d.point, d.link)
    for y in linkage.dyads:
        if isinstance(y, RRR):
            out.setdefault(y.c, y.links[0])
        elif isinstance(y, RRP):
            out.setdefault(y.c, y.links[0])
        elif isinstance(y, RPR):
            out.setdefault(y.coincident[0], y.bar_link)
            out.setdefault(y.coincident[1], y.block_link)
        elif isinstance(y, RPP):
            out.setdefault(y.c, y.links[1])
        elif isinstance(y, PRP):
            out.setdefault(y.c, y.links[0])
        elif isinstance(y, Triad):
            for x in y.inner:
                out.setdefault(x, y.links[3])
    for pt in linkage.points:
        out.setdefault(pt.name, pt.link)
    return out


# --------------------------------------------------------------------------------------------
# Results


@dataclass(frozen=True)
class GroupPolygon:
    """One Assur group's free body and force polygon, as the draftsman lays it off.

    Attributes
    ----------
    name : str
        "group 4–5" (the links), or "driver 1".
    links : tuple of str
    free_body : tuple of Force
        Every force on the group's links (known loads and the reactions found), at its point.
    couples : tuple of Couple
    chain : tuple of (str, ndarray)
        The polygon's vectors head to tail in the order drawn; they close (sum 0).
    unknown : tuple of str
        The labels of the vectors found by closing the polygon (drawn bold).
    closing_sin : ndarray
        |sin| of the angle between the two closing directions (small: ill-conditioned).
    """

    name: str
    links: tuple[str, ...]
    free_body: tuple[Force, ...]
    couples: tuple[Couple, ...]
    chain: tuple[tuple[str, np.ndarray], ...]
    unknown: tuple[str, ...]
    closing_sin: np.ndarray


@dataclass(frozen=True)
class GuideReaction:
    """A guide's reaction on a slider: the force and its moment about the slider's point.

    ``frame`` is the guide's link — the frame, or the moving link whose slot or bar the slider
    runs on (which then bears the opposite reaction on the same line)."""

    frame: str
    slider: str
    point: str
    force: np.ndarray
    moment: np.ndarray  # about the slider's point, N·m

    @property
    def name(self) -> str:
        return f"R_{self.frame}{self.slider}"


@dataclass(frozen=True)
class KinetostaticSolution:
    """Reactions at every joint and the balancing moment, at N positions.

    Attributes
    ----------
    reactions : dict of (str, str) to ndarray
        (i, j) → R_ij, the force of link i on link j (complex, N); both orders are present.
    joints : tuple of Joint
    guides : tuple of GuideReaction
    balancing_moment : ndarray
        M_b on the crank, N·m, + CCW (0 for a slider driver).
    inertia : dict of str to InertiaLoad
    groups : tuple of GroupPolygon
        In the order solved (the farthest group first, the driver last); empty unless asked.
    iterations : int
        Rounds of successive approximation (0 without friction).
    friction_moments : dict of (str, str) to ndarray
        (i, j) → the friction couple of link i on link j at their revolute, N·m.
    """

    reactions: dict[tuple[str, str], np.ndarray]
    joints: tuple[Joint, ...]
    guides: tuple[GuideReaction, ...]
    balancing_moment: np.ndarray
    inertia: dict[str, InertiaLoad]
    groups: tuple[GroupPolygon, ...] = ()
    iterations: int = 0
    friction_moments: dict[tuple[str, str], np.ndarray] = field(default_factory=dict)
    closing: dict[str, np.ndarray] = field(default_factory=dict)  # group name → |sin| of its closing lines
    balancing_force: np.ndarray | None = None  # F_b on a slider driver, N along its guide (None: a crank)
    # With friction: the round before this one (whose own ``previous`` is the round before that),
    # so that each value carries its own error estimate (see iteration_error).
    previous: "KinetostaticSolution | None" = None


def iteration_error(value: float, previous: float, earlier: float) -> float:
    """The estimated absolute error of a value of successive approximation from the same value one
    and two rounds earlier: the iteration converges linearly, each change q times the one
    before (q < 0: it overshoots by turns), so what is left after the last change d is
    d·q/(1 − q) (Aitken). A ratio of changes at round-off says nothing: |q| is kept at most 0.9.

    >>> round(iteration_error(1.0 + 1e-4, 1.0 + 1e-3, 1.0 + 1e-2), 12)  # q = 0.1: 9e-4 · 0.1/0.9
    0.0001
    """
    d1, d0 = value - previous, previous - earlier
    q = max(-0.9, min(d1 / d0, 0.9)) if d0 != 0.0 else 0.0
    return abs(d1 * q / (1.0 - q))


# --------------------------------------------------------------------------------------------
# One round: every group, then the driver


@dataclass
class _Friction:
    """What successive approximation carries from one round to the next."""

    rho: dict[str, float]  # joint point → ρ
    f: dict[str, float]  # slider link → f
    previous: KinetostaticSolution | None = None
    #: slider link → the guide's normal reaction (signed along the guide's normal), the round
    #: before and this round: its sense decides which way the reaction is tilted.
    normal: dict[str, np.ndarray] = field(default_factory=dict)
    normal_next: dict[str, np.ndarray] = field(default_factory=dict)

    def couple(self, joint: Joint, omega: dict[str, np.ndarray], n: int) -> np.ndarray:
        """Friction couple of link a on link b: −ρ|R_ab|·sign(ω_b − ω_a) (zero in round 0)."""
        rho = self.rho.get(joint.point, 0.0)
        if self.previous is None or rho == 0.0:
            return np.zeros(n)
        r = np.abs(self.previous.reactions[(joint.a, joint.b)])
        rel = omega.get(joint.b, np.zeros(n)) - omega.get(joint.a, np.zeros(n))
        return cast(np.ndarray, -rho * r * _sign(rel, _largest(omega, n)))


def _tangential(loads: _Loads, link: str, c: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rᵗ at a dyad link's outer joint from the link's moments about the middle joint C (N),
    ⟂ the link, and the unit vector from that joint to C."""
    d = c - end
    length = np.abs(d)
    safe = np.where(length > 0, length, 1.0)
    e = d / safe
    return loads.moment_about(link, c) / safe * (1j * e), e


#: Reactions (or friction moments) by joint: (a, b) → the force of a on b at each position.
_Reactions = dict[tuple[str, str], np.ndarray]


def _solve_round(linkage: Linkage, kin: PolygonKinematics, base: _Loads, inertia: dict[str, InertiaLoad],
                 fr: _Friction, keep_groups: bool) -> KinetostaticSolution:
    n = kin.valid.shape[0]
    frame = linkage.frame_link
    owner = carriers(linkage)
    loads = _Loads({k: list(v) for k, v in base.forces.items()}, {k: list(v) for k, v in base.couples.items()})
    reactions: dict[tuple[str, str], np.ndarray] = {}
    fmoments: dict[tuple[str, str], np.ndarray] = {}
    joints: list[Joint] = []
    guides: list[GuideReaction] = []
    groups: list[GroupPolygon] = []
    closing: dict[str, np.ndarray] = {}
    P = kin.point

    def friction(j: Joint) -> None:
        """Put the friction couples of a revolute on both links (known for this round)."""
        m = fr.couple(j, kin.omega, n)
        fmoments[(j.a, j.b)], fmoments[(j.b, j.a)] = m, -m
        if np.any(m != 0):
            loads.couple(j.b, Couple(f"M_f{j.a}{j.b}", m))
            loads.couple(j.a, Couple(f"M_f{j.b}{j.a}", -m))

    def found(j: Joint, r_on_b: np.ndarray) -> None:
        """R_ab is known: record it, and put R_ba on the earlier link a as a known load."""
        reactions[(j.a, j.b)], reactions[(j.b, j.a)] = r_on_b, -r_on_b
        joints.append(j)
        if j.a != frame:
            loads.force(j.a, Force(f"R_{j.b}{j.a}", -r_on_b, P[j.point], j.point))

    for y in reversed(linkage.dyads):  # the group farthest from the driver first
        if isinstance(y, Triad):
            _triad_group(y, kin, loads, owner, friction, found, reactions, joints, groups, closing, keep_groups)
            continue
        if isinstance(y, RPR):
            _rpr_group(y, kin, loads, owner, friction, found, reactions, joints, groups, closing, fr,
                       keep_groups)
            continue
        if isinstance(y, RPP):
            _rpp_group(y, kin, loads, owner, friction, found, reactions, joints, guides, groups, closing, fr,
                       frame, keep_groups)
            continue
        if isinstance(y, PRP):
            _prp_group(y, kin, loads, friction, reactions, joints, guides, groups, closing, fr, frame, keep_groups)
            continue
        i, k = y.links
        jp = Joint(y.p, owner[y.p], i)
        jc = Joint(y.c, i, k)
        if isinstance(y, RRR):
            jq = Joint(y.q, owner[y.q], k)
            for j in (jp, jc, jq):
                friction(j)
        else:
            jq = None
            for j in (jp, jc):
                friction(j)
        C = P[y.c]
        # Tangential components: moments of each link about the middle joint C.
        rt_p, e_p = _tangential(loads, i, C, P[y.p])
        known_i = loads.total(i, n)
        known_k = loads.total(k, n)
        chain: list[tuple[str, np.ndarray]] = [(f"R^t_{jp.a}{i}", rt_p)]
        chain += [(f.name, f.vector) for f in loads.forces.get(i, [])]
        chain += [(f.name, f.vector) for f in loads.forces.get(k, [])]
        s = rt_p + known_i + known_k
        if isinstance(y, RRR):
            rt_q, e_q = _tangential(loads, k, C, P[y.q])
            chain.append((f"R^t_{cast(Joint, jq).a}{k}", rt_q))
            s = s + rt_q
            u_close = e_q  # through the end: ∥ QC
            close_name = f"R^n_{cast(Joint, jq).a}{k}"
        else:
            # The guide's reaction: ⟂ guide, tilted by φ against the sliding velocity (relative to
            # the guide's link when the guide moves).
            g_link, t, v_rel = _guide_line(y.guide, y.c, kin, frame)
            nrm = 1j * t
            u_close = _tilted(t, k, v_rel, fr, n, _largest(kin.vel, n))
            close_name = f"R_{g_link}{k}"
        # Close the polygon: x·e_p (∥ PC, through the start) + y·u_close (through the end) = −s.
        det = _cross(e_p, u_close)
        closing_sin = np.abs(det)
        closing[f"group {i}–{k}"] = closing_sin
        _guard_parallel(closing_sin, kin.valid, f"group {i}–{k}: the force polygon's closing lines "
                        f"(∥ {y.p}{y.c} and {'∥ ' + cast(RRR, y).q + y.c if jq else '⟂ guide'}) are parallel")
        safe = np.where(closing_sin > PARALLEL_SIN, det, 1.0)
        x = _cross(-s, u_close) / safe
        yv = _cross(e_p, -s) / safe
        rn_p = x * e_p
        r_close = yv * u_close
        chain.append((close_name, r_close))
        chain.append((f"R^n_{jp.a}{i}", rn_p))
        r_p = rt_p + rn_p
        # The middle joint closes the polygon of link i: R_ki = −(R_P + ΣF_i).
        r_ki = -(r_p + known_i)
        found(jp, r_p)
        reactions[(k, i)], reactions[(i, k)] = r_ki, -r_ki
        joints.append(jc)
        body = [*loads.forces.get(i, []), *loads.forces.get(k, [])]
        couples = [*loads.couples.get(i, []), *loads.couples.get(k, [])]
        if isinstance(y, RRR):
            r_q = rt_q + r_close
            found(cast(Joint, jq), r_q)  # an RRR group has its third joint Q
            body += [Force(f"R_{jp.a}{i}", r_p, P[y.p], y.p), Force(f"R_{cast(Joint, jq).a}{k}", r_q, P[y.q], y.q)]
        else:
            # Line of action of the guide's reaction: the slider's moments about C.
            m_guide = -loads.moment_about(k, C)  # R_ik acts at C itself
            _guide_found(GuideReaction(g_link, k, y.c, r_close, m_guide), t, C, loads, reactions, guides, frame)
            fr.normal_next[k] = (np.conj(nrm) * r_close).real
            body += [Force(f"R_{jp.a}{i}", r_p, P[y.p], y.p), Force(close_name, r_close, _guide_point(C, t, r_close, m_guide))]
        if keep_groups:
            unknown = (close_name, f"R^n_{jp.a}{i}")
            groups.append(GroupPolygon(f"group {i}–{k}", (i, k), tuple(body), tuple(couples), tuple(chain),
                                       unknown, closing_sin))
    # The driver: the frame's reaction closes its polygon, the balancing moment its moments.
    d = linkage.driver
    if isinstance(d, SliderInput):
        return _slider_driver(d, linkage, kin, loads, reactions, joints, guides, groups, inertia, fmoments,
                              closing, fr, keep_groups)
    ja = Joint(d.pivot, frame, d.link)
    friction(ja)
    A = P[d.pivot]
    r01 = -loads.total(d.link, n)
    m_b = -loads.moment_about(d.link, A)
    reactions[(frame, d.link)], reactions[(d.link, frame)] = r01, -r01
    joints.append(ja)
    if keep_groups:
        chain = [(f.name, f.vector) for f in loads.forces.get(d.link, [])] + [(f"R_{frame}{d.link}", r01)]
        body = [*loads.forces.get(d.link, []), Force(f"R_{frame}{d.link}", r01, A, d.pivot)]
        groups.append(GroupPolygon(f"driver {d.link}", (d.link,), tuple(body),
                                   tuple(loads.couples.get(d.link, [])) + (Couple("M_b", m_b),), tuple(chain),
                                   (f"R_{frame}{d.link}",), np.ones(n)))
    return KinetostaticSolution(reactions, tuple(joints), tuple(guides), m_b, inertia, tuple(groups),
                                0, fmoments, closing)


def _slider_driver(d: SliderInput, linkage: Linkage, kin: PolygonKinematics, loads: _Loads, reactions: _Reactions,
                   joints: list[Joint], guides: list[GuideReaction], groups: list[GroupPolygon],
                   inertia: dict[str, InertiaLoad], fmoments: _Reactions, closing: dict[str, np.ndarray],
                   fr: _Friction, keep_groups: bool) -> KinetostaticSolution:
    """A driving slider: the balancing force F_b along its guide and the guide's reaction ⟂ it
    (tilted by φ with friction) close its polygon; the guide reaction's line of action from the
    slider's moments about its point."""
    n = kin.valid.shape[0]
    frame = linkage.frame_link
    t = complex(math.cos(d.guide.angle), math.sin(d.guide.angle))
    nrm = 1j * t
    C = kin.point[d.point]
    s = loads.total(d.link, n)
    normal = -(np.conj(nrm) * s).real
    f = fr.f.get(d.link, 0.0) if fr.previous is not None else 0.0
    v = (np.conj(t) * kin.vel[d.point]).real
    r_guide = normal * nrm - f * np.abs(normal) * _sign(v, _largest(kin.vel, n)) * t
    f_b = -(np.conj(t) * (s + r_guide)).real
    m_guide = -loads.moment_about(d.link, C)  # F_b acts along the guide through the slider's point
    reactions[(frame, d.link)], reactions[(d.link, frame)] = r_guide, -r_guide
    guides.append(GuideReaction(frame, d.link, d.point, r_guide, m_guide))
    fr.normal_next[d.link] = normal
    if keep_groups:
        chain = [(f.name, f.vector) for f in loads.forces.get(d.link, [])]
        chain += [(f"R_{frame}{d.link}", r_guide), ("F_b", f_b * t)]
        body = [*loads.forces.get(d.link, []), Force(f"R_{frame}{d.link}", r_guide, _guide_point(C, t, r_guide, m_guide)),
                Force("F_b", f_b * t, C, d.point)]
        groups.append(GroupPolygon(f"driver {d.link}", (d.link,), tuple(body), tuple(loads.couples.get(d.link, [])),
                                   tuple(chain), (f"R_{frame}{d.link}", "F_b"), np.ones(n)))
    return KinetostaticSolution(reactions, tuple(joints), tuple(guides), np.zeros(n), inertia, tuple(groups),
                                0, fmoments, closing, f_b)


def _rpr_group(y: RPR, kin: PolygonKinematics, loads: _Loads, owner: dict[str, str], friction: Callable[[Joint], None],
               found: Callable[[Joint, np.ndarray], None], reactions: _Reactions, joints: list[Joint],
               groups: list[GroupPolygon], closing: dict[str, np.ndarray], fr: _Friction,
               keep_groups: bool) -> None:
    """A guide bar b pivoted at P and a block k pivoted at X sliding on it (导杆, 摇块).

    The bar's reaction on the block is N ⟂ the bar (tilted by φ with friction), on the line of
    action X + s·t along the bar. The block's moments about X give s·N; the bar's moments about
    its pivot P give N (the reaction's component along the bar passes through P); then each link's
    polygon closes with its pivot's reaction.
    """
    n = kin.valid.shape[0]
    b, k = y.bar_link, y.block_link
    P, X = kin.point[y.bar_pivot], kin.point[y.block_pivot]
    jb = Joint(y.bar_pivot, owner[y.bar_pivot], b)
    jk = Joint(y.block_pivot, owner[y.block_pivot], k)
    friction(jb)
    friction(jk)
    d = X - P
    L = np.abs(d)
    e = y.offset
    if e != 0.0:  # an offset guide bar: d = (L_t + i·e)·t, L_t the pivot's distance along the bar's line t
        L = np.sqrt(np.maximum(L * L - e * e, 0.0))
        t = d / (L + 1j * e)
        t = t / np.abs(t)
    else:
        t = d / np.where(L > 0, L, 1.0)
    nrm = 1j * t
    _guard_parallel(np.where(L > 0, 1.0, 0.0), kin.valid, f"group {b}–{k}: the block's pivot {y.block_pivot} is "
                    f"on the bar's pivot {y.bar_pivot}, so the bar's moments cannot give the reaction")
    m_bar = loads.moment_about(b, P)  # about the bar's pivot
    m_block = loads.moment_about(k, X)  # about the block's pivot
    # Friction on the slide: −f|N| along the bar against the block's motion relative to the bar.
    f = fr.f.get(k, 0.0) if fr.previous is not None else 0.0
    v_rel = (np.conj(t) * (kin.vel[y.coincident[1]] - kin.vel[y.coincident[0]])).real
    sense = _sign(v_rel, _largest(kin.vel, n))
    # The bar's moments about P: N·L_t + e·f·σ·|N| = m_bar + m_block (the friction along an offset line
    # has the arm e about P); g(N) rises with N while L_t > |e·f|, so N takes the sign of the right side.
    m = m_bar + m_block
    L_safe = np.where(L > 0, L, 1.0)
    N = np.where(m >= 0, m / (L_safe + e * f * sense), m / (L_safe - e * f * sense)) if e != 0.0 else m / L_safe
    r_bk = N * nrm - f * np.abs(N) * sense * t  # the bar on the block
    fr.normal_next[k] = N
    known_b = loads.total(b, n)
    known_k = loads.total(k, n)
    r_pb = r_bk - known_b  # closes the bar's polygon: ΣF_b + R_kb + R_Pb = 0
    r_xk = -r_bk - known_k  # closes the block's polygon
    body = [*loads.forces.get(b, []), *loads.forces.get(k, [])]
    couples = [*loads.couples.get(b, []), *loads.couples.get(k, [])]
    found(jb, r_pb)
    found(jk, r_xk)
    reactions[(b, k)], reactions[(k, b)] = r_bk, -r_bk
    joints.append(Joint(y.block_pivot, b, k))
    closing[f"group {b}–{k}"] = np.ones(n)
    if keep_groups:
        chain = [(f"R_{k}{b}", -r_bk)] + [(f.name, f.vector) for f in loads.forces.get(b, [])]
        chain += [(f"R_{jb.a}{b}", r_pb)]
        body += [Force(f"R_{jb.a}{b}", r_pb, P, y.bar_pivot), Force(f"R_{jk.a}{k}", r_xk, X, y.block_pivot)]
        groups.append(GroupPolygon(f"group {b}–{k}", (b, k), tuple(body), tuple(couples), tuple(chain),
                                   (f"R_{jb.a}{b}",), np.ones(n)))


def _rpp_group(y: RPP, kin: PolygonKinematics, loads: _Loads, owner: dict[str, str], friction: Callable[[Joint], None],
               found: Callable[[Joint, np.ndarray], None], reactions: _Reactions, joints: list[Joint],
               guides: list[GuideReaction], groups: list[GroupPolygon], closing: dict[str, np.ndarray],
               fr: _Friction, frame: str, keep_groups: bool) -> None:
    """A block i pivoted at P slides in the straight slot of j, which slides on a frame guide.

    The slotted link's polygon closes on two known directions — the slot's reaction ⟂ the slot
    and the guide's ⟂ the guide (each tilted by φ with friction); the block's polygon then gives
    the reaction at P; the block's moments about P give the slot reaction's couple, the slotted
    link's moments about C the guide reaction's.
    """
    n = kin.valid.shape[0]
    i, j = y.links
    P, C = kin.point[y.p], kin.point[y.c]
    jp = Joint(y.p, owner[y.p], i)
    friction(jp)
    t1 = complex(math.cos(y.slot_angle), math.sin(y.slot_angle))
    t2 = complex(math.cos(y.guide.angle), math.sin(y.guide.angle))
    speed = _largest(kin.vel, n)

    def tilted(t: complex, link: str, v_rel: np.ndarray) -> np.ndarray:
        f = fr.f.get(link, 0.0) if fr.previous is not None else 0.0
        sigma = np.where(fr.normal.get(link, np.ones(n)) >= 0, 1.0, -1.0)
        u = 1j * t - f * sigma * _sign(v_rel, speed) * t
        return cast(np.ndarray, u / np.abs(u))

    # the slot on the block (against the block's sliding in the slot), the guide on j
    u1 = tilted(t1, i, (np.conj(t1) * (kin.vel[y.coincident[0]] - kin.vel[y.coincident[1]])).real)
    u2 = tilted(t2, j, (np.conj(t2) * kin.vel[y.c]).real)
    known_i, known_j = loads.total(i, n), loads.total(j, n)
    # link j: ΣF_j − N1·u1 + N2·u2 = 0, closed by lines ∥ u1 and ∥ u2
    det = _cross(-u1, u2)
    sin = np.abs(det)
    closing[f"group {i}–{j}"] = sin
    _guard_parallel(sin, kin.valid, f"group {i}–{j}: the slot and the guide are parallel")
    safe = np.where(sin > PARALLEL_SIN, det, 1.0)
    n1 = _cross(-known_j, u2) / safe
    n2 = _cross(-u1, -known_j) / safe
    r_ji = n1 * u1  # the slotted link on the block
    r_guide = n2 * u2
    r_p = -(known_i + r_ji)
    m_slot = -loads.moment_about(i, P)  # couple of j on the block about P
    m_guide = -(loads.moment_about(j, C) + _cross(P - C, -r_ji) - m_slot)
    fr.normal_next[i], fr.normal_next[j] = n1, n2
    body = [*loads.forces.get(i, []), *loads.forces.get(j, [])]
    couples = [*loads.couples.get(i, []), *loads.couples.get(j, [])]
    found(jp, r_p)
    reactions[(j, i)], reactions[(i, j)] = r_ji, -r_ji
    reactions[(frame, j)], reactions[(j, frame)] = r_guide, -r_guide
    joints.append(Joint(y.p, j, i))
    guides.append(GuideReaction(frame, j, y.c, r_guide, m_guide))
    if keep_groups:
        chain = [(f.name, f.vector) for f in loads.forces.get(j, [])]
        chain += [(f"R_{frame}{j}", r_guide), (f"R_{i}{j}", -r_ji)]
        body += [Force(f"R_{jp.a}{i}", r_p, P, y.p),
                 Force(f"R_{frame}{j}", r_guide, _guide_point(C, t2, r_guide, m_guide))]
        groups.append(GroupPolygon(f"group {i}–{j}", (i, j), tuple(body), tuple(couples), tuple(chain),
                                   (f"R_{frame}{j}", f"R_{i}{j}"), sin))


def _guide_line(g: Guide | LinkGuide, c: str, kin: PolygonKinematics, frame: str
                ) -> tuple[str, np.ndarray, np.ndarray]:
    """A guide's link, its unit direction at every position and the sliding velocity along it at C
    relative to that link (a moving guide: its point C<link> coinciding with C)."""
    n = kin.valid.shape[0]
    if isinstance(g, Guide):
        t = np.full(n, complex(math.cos(g.angle), math.sin(g.angle)))
        return frame, t, (np.conj(t) * kin.vel[c]).real
    d = kin.point[g.towards] - kin.point[g.through]
    t = d / np.where(np.abs(d) > 0, np.abs(d), 1.0)
    return g.link, t, (np.conj(t) * (kin.vel[c] - kin.vel[c + g.link])).real


def _tilted(t: np.ndarray, link: str, v_rel: np.ndarray, fr: _Friction, n: int, speed: np.ndarray) -> np.ndarray:
    """The unit direction of a guide's reaction on the slider ``link``: ⟂ the guide (its normal
    i·t), tilted by φ = arctan f against the sliding velocity from the second round on."""
    f = fr.f.get(link, 0.0) if fr.previous is not None else 0.0
    sigma = np.where(fr.normal.get(link, np.ones(n)) >= 0, 1.0, -1.0)
    u = 1j * t - f * sigma * _sign(v_rel, speed) * t
    return cast(np.ndarray, u / np.abs(u))


def _guide_found(g: GuideReaction, t: np.ndarray, C: np.ndarray, loads: _Loads, reactions: _Reactions,
                 guides: list[GuideReaction], frame: str) -> None:
    """Record a guide's reaction on its slider; a guide on a moving link bears −R on the same line
    of action, a known load of that link for the groups solved after (R_ij on the guide's link)."""
    guides.append(g)
    reactions[(g.frame, g.slider)], reactions[(g.slider, g.frame)] = g.force, -g.force
    if g.frame != frame:
        loads.force(g.frame, Force(f"R_{g.slider}{g.frame}", -g.force, _guide_point(C, t, g.force, g.moment)))


def _prp_group(y: PRP, kin: PolygonKinematics, loads: _Loads, friction: Callable[[Joint], None],
               reactions: _Reactions, joints: list[Joint], guides: list[GuideReaction], groups: list[GroupPolygon],
               closing: dict[str, np.ndarray], fr: _Friction, frame: str, keep_groups: bool) -> None:
    """Blocks i and j pinned at C, i sliding on one guide, j on the other (a block on a moving bar,
    the tangent mechanism).

    Each guide's reaction is ⟂ its guide (tilted by φ with friction) with unknown magnitude and
    line of action; the group's polygon closes on the two directions; block i's polygon then gives
    the pin's reaction R_ji; each block's moments about C give its guide reaction's couple (the pin
    passes through C). A guide on a moving link bears −R, a load of that link solved later.
    """
    n = kin.valid.shape[0]
    i, j = y.links
    C = kin.point[y.c]
    jc = Joint(y.c, i, j)
    friction(jc)
    speed = _largest(kin.vel, n)
    (a0, t0, v0), (a1, t1, v1) = (_guide_line(g, y.c, kin, frame) for g in y.guides)
    u0, u1 = _tilted(t0, i, v0, fr, n, speed), _tilted(t1, j, v1, fr, n, speed)
    known_i, known_j = loads.total(i, n), loads.total(j, n)
    # the group: ΣF_i + ΣF_j + N0·u0 + N1·u1 = 0, closed by lines ∥ u0 and ∥ u1
    det = _cross(u0, u1)
    sin = np.abs(det)
    name = f"group {i}–{j}"
    closing[name] = sin
    _guard_parallel(sin, kin.valid, f"{name}: the two guides are parallel")
    safe = np.where(sin > PARALLEL_SIN, det, 1.0)
    s = -(known_i + known_j)
    n0, n1 = _cross(s, u1) / safe, _cross(u0, s) / safe
    r0, r1 = n0 * u0, n1 * u1
    r_ji = -(known_i + r0)  # the pin: block j on block i closes i's polygon
    m0, m1 = -loads.moment_about(i, C), -loads.moment_about(j, C)
    fr.normal_next[i], fr.normal_next[j] = n0, n1
    body = [*loads.forces.get(i, []), *loads.forces.get(j, [])]
    couples = [*loads.couples.get(i, []), *loads.couples.get(j, [])]
    reactions[(j, i)], reactions[(i, j)] = r_ji, -r_ji
    joints.append(jc)
    _guide_found(GuideReaction(a0, i, y.c, r0, m0), t0, C, loads, reactions, guides, frame)
    _guide_found(GuideReaction(a1, j, y.c, r1, m1), t1, C, loads, reactions, guides, frame)
    if keep_groups:
        chain = [(f.name, f.vector) for f in body] + [(f"R_{a1}{j}", r1), (f"R_{a0}{i}", r0)]
        body += [Force(f"R_{a0}{i}", r0, _guide_point(C, t0, r0, m0)), Force(f"R_{a1}{j}", r1, _guide_point(C, t1, r1, m1))]
        groups.append(GroupPolygon(name, (i, j), tuple(body), tuple(couples), tuple(chain),
                                   (f"R_{a1}{j}", f"R_{a0}{i}"), sin))


def _guide_point(C: np.ndarray, t: complex | np.ndarray, r: np.ndarray, m: np.ndarray) -> np.ndarray:
    """Where the guide reaction's line of action crosses the guide line through C: C + s·t with
    s·(t × R) = M."""
    tr = _cross(np.broadcast_to(t, C.shape), r)
    return C + np.where(np.abs(tr) > 0, m / np.where(np.abs(tr) > 0, tr, 1.0), 0.0) * t


def _triad_group(y: Triad, kin: PolygonKinematics, loads: _Loads, owner: dict[str, str],
                 friction: Callable[[Joint], None], found: Callable[[Joint, np.ndarray], None], reactions: _Reactions,
                 joints: list[Joint], groups: list[GroupPolygon], closing: dict[str, np.ndarray],
                 keep_groups: bool) -> None:
    """A class III group by Assur's special point, as for its polygons.

    Each outer joint's reaction R_k = Rᵗ_k (⟂ its binary link, from that link's moments about
    its inner joint) + Rⁿ_k (∥ the link). S, where the lines of two binary links (``assur``) meet,
    is the one point about which the group's moments hold only the third Rⁿ: it comes from them;
    the group's force polygon then closes on the other two directions. Each inner joint's reaction
    closes its binary link's polygon.
    """
    n = kin.valid.shape[0]
    P = kin.point
    t = y.links[3]
    outer = [Joint(y.outer[k], owner[y.outer[k]], y.links[k]) for k in range(3)]
    inner = [Joint(y.inner[k], y.links[k], t) for k in range(3)]
    for j in (*outer, *inner):
        friction(j)
    rt, e = [], []
    for k in range(3):
        r, u = _tangential(loads, y.links[k], P[y.inner[k]], P[y.outer[k]])
        rt.append(r)
        e.append(u)
    i, j2 = y.assur
    k3 = 3 - i - j2
    name = f"group {'–'.join(y.links)}"
    # S = P_i + a·e_i on the line of link j2 as well
    sin_s = _cross(e[i], e[j2])
    _guard_parallel(np.abs(sin_s), kin.valid, f"{name}: Assur's point S is at infinity "
                    f"({y.outer[i]}{y.inner[i]} ∥ {y.outer[j2]}{y.inner[j2]})")
    sin_s = np.where(np.abs(sin_s) > PARALLEL_SIN, sin_s, 1.0)
    S = P[y.outer[i]] + _cross(P[y.outer[j2]] - P[y.outer[i]], e[j2]) / sin_s * e[i]
    known = sum((loads.total(x, n) for x in y.links), np.zeros(n, complex))
    m_s = sum((loads.moment_about(x, S) for x in y.links), np.zeros(n))
    m_s = m_s + sum((_cross(P[y.outer[k]] - S, rt[k]) for k in range(3)), np.zeros(n))
    arm = _cross(P[y.outer[k3]] - S, e[k3])  # the third Rⁿ's moment per newton about S
    scale = np.abs(P[y.outer[k3]] - S) + np.abs(P[y.outer[k3]] - P[y.inner[k3]])
    _guard_parallel(np.abs(arm) / np.where(scale > 0, scale, 1.0), kin.valid,  # the group locks
                    f"{name}: the three binary links' lines meet at one point (the group locks)")
    x3 = -m_s / np.where(np.abs(arm) > 0, arm, 1.0)
    arm_sin = np.abs(arm) / np.where(scale > 0, scale, 1.0)  # ~ sin of the third link's line against S
    rn = {k3: x3 * e[k3]}
    s = sum(rt, np.zeros(n, complex)) + known + rn[k3]
    det = _cross(e[i], e[j2])
    closing_sin = np.abs(det)
    closing[name] = np.minimum(closing_sin, arm_sin)  # flagged when either cut is shallow
    safe = np.where(closing_sin > PARALLEL_SIN, det, 1.0)
    rn[i] = _cross(-s, e[j2]) / safe * e[i]
    rn[j2] = _cross(e[i], -s) / safe * e[j2]
    chain: list[tuple[str, np.ndarray]] = [(f"R^t_{outer[k].a}{y.links[k]}", rt[k]) for k in range(3)]
    chain += [(f.name, f.vector) for x in y.links for f in loads.forces.get(x, [])]
    chain += [(f"R^n_{outer[k].a}{y.links[k]}", rn[k]) for k in (k3, j2, i)]
    body = [f for x in y.links for f in loads.forces.get(x, [])]
    couples = [c for x in y.links for c in loads.couples.get(x, [])]
    for k in range(3):
        link = y.links[k]
        r_k = rt[k] + rn[k]
        r_tk = -(r_k + loads.total(link, n))  # the ternary link on binary link k closes k's polygon
        found(outer[k], r_k)
        reactions[(t, link)], reactions[(link, t)] = r_tk, -r_tk
        joints.append(inner[k])
        body.append(Force(f"R_{outer[k].a}{link}", r_k, P[y.outer[k]], y.outer[k]))
    if keep_groups:  # the third Rⁿ is known (moments about S) before the polygon closes on the other two
        unknown = tuple(f"R^n_{outer[k].a}{y.links[k]}" for k in (j2, i))
        groups.append(GroupPolygon(name, y.links, tuple(body), tuple(couples), tuple(chain), unknown, closing_sin))


def _guard_parallel(sin: np.ndarray, valid: np.ndarray, why: str) -> None:
    bad = (sin <= PARALLEL_SIN) & valid
    if np.any(bad):
        raise DegenerateConstruction("force polygon", why + ": the reactions grow without bound "
                                     "(transmission angle 0°)")


# --------------------------------------------------------------------------------------------
# The whole analysis


def kinetostatics(linkage: Linkage, model: ForceModel, kin: PolygonKinematics, *,
                  polygons: bool = True) -> KinetostaticSolution:
    """Reactions in every joint and the balancing moment, group by group (with friction if any).

    Parameters
    ----------
    linkage : Linkage
        Driven by a crank or a slider; RRR, RRP (its guide on the frame or on a moving link), RPR, RPP
        and PRP dyads, class III groups.
    model : ForceModel
        Masses, loads, friction.
    kin : PolygonKinematics
        The motion read off the polygons.
    polygons : bool
        Keep each group's free body and force polygon (for drawing); False skips them.

    Returns
    -------
    KinetostaticSolution

    Raises
    ------
    DegenerateConstruction
        Where a polygon's closing lines are parallel, or friction does not converge.
    """
    inertia = inertia_loads(model.masses, kin)
    base = external_loads(model, kin, inertia, linkage.frame_link)
    rho = {fr.point: fr.rho for fr in model.revolute_friction if fr.rho > 0}
    f = {fr.link: fr.f for fr in model.sliding_friction if fr.f > 0}
    state = _Friction(rho, f)
    sol = _solve_round(linkage, kin, base, inertia, state, polygons and not model.has_friction)
    if not model.has_friction:
        return sol  # frictionless: one round, no iteration
    change = math.inf
    for it in range(1, model.max_iterations + 1):
        state.previous, state.normal, state.normal_next = sol, state.normal_next, {}
        new = _solve_round(linkage, kin, base, inertia, state, False)
        change = _largest_change(sol, new, kin.valid)
        earlier, sol = sol, new
        if change < model.tolerance:
            # one more round (the drawn one); with the two before it, it estimates its own error
            state.previous, state.normal, state.normal_next = sol, state.normal_next, {}
            final = _solve_round(linkage, kin, base, inertia, state, polygons)
            return replace(final, iterations=it, previous=replace(sol, previous=earlier))
    raise DegenerateConstruction(
        "friction by successive approximation",
        f"does not converge in {model.max_iterations} rounds (the reactions still change by "
        f"{change:.3g} N): the friction is too large for this position — the mechanism may be self-locking")


def _largest_change(a: KinetostaticSolution, b: KinetostaticSolution, valid: np.ndarray) -> float:
    out = float(np.max(np.abs(a.balancing_moment - b.balancing_moment)[valid], initial=0.0))
    if a.balancing_force is not None and b.balancing_force is not None:
        out = max(out, float(np.max(np.abs(a.balancing_force - b.balancing_force)[valid], initial=0.0)))
    for key, r in b.reactions.items():
        out = max(out, float(np.max(np.abs(r - a.reactions[key])[valid], initial=0.0)))
    for ga, gb in zip(a.guides, b.guides):
        out = max(out, float(np.max(np.abs(ga.moment - gb.moment)[valid], initial=0.0)))
    return out if math.isfinite(out) else math.inf


# --------------------------------------------------------------------------------------------
# Zhukovsky's lever


@dataclass(frozen=True)
class Lever:
    """Zhukovsky's lever: the velocity polygon turned 90° with the loads at the image points.

    ``arms`` are (label, image point turned 90° in mm, force N); ``moment`` is ΣM_p (N·mm),
    ``balancing_moment`` = μv·ΣM_p/ω1 (N·m).
    """

    arms: tuple[tuple[str, np.ndarray, np.ndarray], ...]
    moment: np.ndarray
    balancing_moment: np.ndarray
    balancing_force: np.ndarray | None = None  # a slider driver's F_b along its guide, N


def zhukovsky_lever(linkage: Linkage, model: ForceModel, kin: PolygonKinematics) -> Lever:
    """The balancing moment by Zhukovsky's lever (virtual power), frictionless.

    Every known load (weights, inertia forces, external forces) is applied at the image of its
    point in the velocity polygon turned 90° CCW; a couple M on a link becomes the pair of forces
    ±M/|UV|² ⟂ UV at the images of two of its points U, V. The moments about the pole p balance:
    ΣM_p(loads) + M_p(M_b) = 0 with M_p(M_b) = −M_b·ω1/μv, so M_b = μv·ΣM_p/ω1.
    """
    d = linkage.driver
    inertia = inertia_loads(model.masses, kin)
    loads = external_loads(model, kin, inertia, linkage.frame_link)
    mv = kin.mu_v
    arms: list[tuple[str, np.ndarray, np.ndarray]] = []
    total = np.zeros(kin.valid.shape[0])
    for link, fs in loads.forces.items():
        for f in fs:
            image = kin.vel[f.point] / mv * 1j  # the image of its point, turned 90°
            arms.append((f.name, image, f.vector))
            total = total + _cross(image, f.vector)
    pts = linkage.links()
    for link, cs in loads.couples.items():
        u, v = pts[link][0], pts[link][1] if len(pts[link]) > 1 else pts[link][0]
        uv = kin.point[v] - kin.point[u]
        for c in cs:
            if u == v:
                # A link with one point (a rocking block turning with its bar): the couple's power
                # M·ω is put on the lever as its moment −M·ω/μv directly.
                total = total - c.moment * kin.omega.get(link, np.zeros_like(total)) / mv
                continue
            pair = c.moment / np.abs(uv) ** 2 * (1j * uv)
            for name, at, force in ((c.name, v, pair), (c.name, u, -pair)):
                image = kin.vel[at] / mv * 1j
                arms.append((name, image, force))
                total = total + _cross(image, force)
    if isinstance(d, SliderInput):
        # F_b·v + ΣP = 0 with ΣP = −μv·ΣM_p: the balancing force along the guide
        if d.velocity == 0.0:
            raise DegenerateConstruction("Zhukovsky's lever", "the driving slider stands still: no virtual power")
        return Lever(tuple(arms), total, np.zeros_like(total), mv * total / d.velocity)
    if d.omega == 0.0:
        raise DegenerateConstruction("Zhukovsky's lever", "the crank stands still: no virtual power")
    m_b = mv * total / d.omega
    return Lever(tuple(arms), total, m_b)


__all__ = [
    "PolygonKinematics", "kinematics_from_construction", "construction_targets", "InertiaLoad",
    "inertia_load", "inertia_loads", "Force", "Couple", "Joint", "GroupPolygon", "GuideReaction",
    "KinetostaticSolution", "iteration_error", "kinetostatics", "zhukovsky_lever", "Lever", "carriers", "SHALLOW_SIN",
]
