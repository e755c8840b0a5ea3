"""Checking an efficiency scene: force polygons against the closed-form trigonometric answers.

The counterpart of :mod:`graphmech.problems.linkage.check` for ``[efficiency]`` scenes. The forces are read off
the polygons of :mod:`graphmech.methods.efficiency` (drawn length × μF) and set against
:mod:`graphmech.exact.efficiency`; the self-locking limit is found on the construction by
redrawing it until η = 0 and set against its closed form (α = φ, ψ = φv, γ = 2φ). A chain of
machines is walked stage by stage from the output back to the motor and set against the product
formulas. Only what the scene asks for is computed: a screw scene that wants ψ alone draws no
polygon and needs no friction coefficient.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, cast

from graphmech.problems.judging import Row, Verdict, close_names, judge_value, measured_entries
from graphmech.errors import DegenerateConstruction, SceneError
from graphmech.exact import efficiency as ex
from graphmech.methods import efficiency as gm
from graphmech.scales import format_scale, round_scale
from graphmech.problems.efficiency.scene import DEFAULT_FIND, EfficiencyProblem
from graphmech.tolerances import EPS, SHALLOW_DEG

if TYPE_CHECKING:
    from graphmech.drawing.primitives import Sheet
    from graphmech.methods.efficiency import Direction
    from graphmech.problems.reader import Scene

#: The longest side of a force polygon when graphmech chooses μF, mm.
POLYGON_MM = 80.0
#: A stated μF must draw the largest force between these lengths, mm.
DRAWN_MM = (2.0, 2000.0)

#: A polygon that closes at an angle below SHALLOW_DEG is ill-conditioned for a hand construction.
COND_HAND = 1.0 / math.sin(math.radians(SHALLOW_DEG))


@dataclass
class EfficiencyAnalysis:
    """What one efficiency scene produced: the strokes (per direction), the rows, the warnings."""

    scene: Scene[EfficiencyProblem]
    problem: EfficiencyProblem
    strokes: dict[Direction, gm.Stroke] = field(default_factory=dict)
    chain: tuple[float, tuple[gm.StageResult, ...]] | None = None  # η and the stages, of a chain
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    stated: set[str] = field(default_factory=set)
    extra_measured: tuple[tuple[str, float], ...] = ()
    values: dict[str, tuple[float, float, float | None, float, bool, float]] = field(default_factory=dict)

    def scale_notes(self) -> list[str]:
        return [format_scale(k, v) + ("" if k in self.stated else " (chosen)") for k, v in self.scales.items()]

    @property
    def phi(self) -> float:
        """The (equivalent) friction angle, rad."""
        p = self.problem
        return ex.equivalent_friction_angle(p.f or 0.0, p.half_angle if p.type == "screw" else 0.0)

    @property
    def angle(self) -> float:
        """The incline's α or the screw's lead angle ψ (φv at the self-locking limit), rad."""
        p = self.problem
        # read_efficiency refuses an incline, a clamp or a buffer without α, and a screw without ψ off the limit
        if p.type in ("incline", "wedge_clamp", "buffer"):
            return float(cast(float, p.angle))
        return self.phi if p.at_limit else float(cast(float, p.lead_angle))


def requested(scene: Scene[EfficiencyProblem], extra: tuple[tuple[str, float], ...] = ()) -> list[str]:
    """The row names the scene asks for, expanded over its directions; bad names → SceneError."""
    p: EfficiencyProblem = scene.problem
    q = p.quantities()
    names = list(scene.find) or list(DEFAULT_FIND[p.type])
    multi = len(p.directions) > 1
    out: list[str] = []
    problems = []
    checks = [(f"find[{i}]", n) for i, n in enumerate(scene.find)] or [("find", n) for n in names]
    checks += [(k, n) for k, n, _ in measured_entries(scene, extra)]
    for key, name in checks:
        base, _, at = name.partition("@")
        if base not in q:
            problems.append((key, f"unknown {p.type} quantity {base!r}{close_names(base, q)}"))
            continue
        if at and (not q[base][1] or at not in p.directions):
            what = f"one of {', '.join(p.directions)}" if q[base][1] else "none: it does not depend on the direction"
            problems.append((key, f"{base}@{at}: no such direction (directions: {what})"))
            continue
        if not at and multi and q[base][1] and not key.startswith("find"):
            problems.append((key, f"{base} depends on the direction: write "
                                  f"{' or '.join(f'{base}@{d}' for d in p.directions)}"))
            continue
        if q[base][2] and p.f is None:
            problems.append((key, f"{base} needs the friction coefficient: add f to [efficiency]"))
            continue
        if base == "eta_self_locking_max" and not p.f:
            problems.append((key, "eta_self_locking_max needs f > 0: without friction no screw self-locks"))
            continue
        if base == "M" and p.d2 is None:
            problems.append((key, "M needs the pitch diameter: add d2_mm to [efficiency]"))
            continue
        missing = _screw_needs(p, base)
        if missing:
            problems.append((key, f"{base} needs {missing} in [efficiency]"))
            continue
        if base in ("r_f", "sigma") and (p.collar if base == "r_f" else p.d1) is None:
            need = "collar_mm = [d0, dw]" if base == "r_f" else "d1_mm"
            problems.append((key, f"{base} needs {need} in [efficiency]"))
            continue
        if key.startswith("find"):
            if q[base][1] and not at:
                out += [f"{base}@{d}" if multi else base for d in p.directions]
            else:
                out.append(name if (at and multi) or not at else base)
    if problems:
        raise SceneError(problems, scene.source)
    return list(dict.fromkeys(out))


#: What each of a screw's collar, wrench and drive quantities needs besides f: (field, key to add).
_SCREW_NEEDS = {
    "r_c": ("collar",), "M_c": ("collar", "f_c"), "T_tighten": ("collar", "f_c", "d2"),
    "F_a": ("collar", "f_c", "d2", "torque"), "sigma_a": ("collar", "f_c", "d2", "torque", "d1"),
    "P_drive": ("speed",), "n_screw": ("speed", "lead"),
}
_NEED_KEYS = {"collar": "collar_mm = [d0, dw]", "f_c": "f_c (the collar's friction coefficient)",
              "d2": "d2_mm", "torque": "torque_Nm (the wrench's torque)", "d1": "d1_mm",
              "speed": "speed_m_s (the load's lift speed)", "lead": "pitch_mm (the lead L = n·P)"}


def _screw_needs(p: EfficiencyProblem, base: str) -> str:
    """The keys a screw quantity still needs, said as a phrase ('' when it has them all)."""
    return " and ".join(_NEED_KEYS[k] for k in _SCREW_NEEDS.get(base, ()) if getattr(p, k) is None)


def analyse_efficiency(scene: Scene[EfficiencyProblem], extra_measured: tuple[tuple[str, float], ...] = ()) -> EfficiencyAnalysis:
    """Carry out what the efficiency scene asks for and build its check table."""
    p: EfficiencyProblem = scene.problem
    names = requested(scene, extra_measured)
    an = EfficiencyAnalysis(scene, p, extra_measured=tuple(extra_measured))
    if p.type == "chain":
        an.chain = gm.chain([(s.name, s.branches) for s in p.stages], _chain_power(p))
    else:
        bases = {n.partition("@")[0] for n in names} | {
            m.partition("@")[0] for _, m, _ in measured_entries(scene, extra_measured)}
        needs_polygon = "polygon" in scene.show or bool(
            bases & {"F", "F0", "eta", "R", "R12", "R32", "R31", "R42", "R_face1", "M"})
        if needs_polygon:
            _strokes(an)
    for name in names:
        an.rows.append(_row(an, name))
    return an


def _chain_power(p: EfficiencyProblem) -> float:
    """The chain's output power Q·v, W (read_efficiency refuses a chain without both)."""
    return cast(float, p.load) * cast(float, p.speed)


def _wedge_angles(p: EfficiencyProblem) -> tuple[float, float]:
    """γ and β of a wedge (read_efficiency refuses a wedge without both)."""
    return cast(float, p.gamma), cast(float, p.beta)


def _stroke(an: EfficiencyAnalysis, direction: Direction, mu_F: float) -> gm.Stroke:
    p = an.problem
    # drawn only for what needs Q: read_efficiency then requires it, or a wrench's torque gives it
    load = p.load if p.load is not None else _bolt_force(an)[0]
    if p.type == "wedge":
        return gm.wedge(load, *_wedge_angles(p), an.phi, direction, mu_F)
    if p.type == "wedge_clamp":
        return gm.wedge_clamp(load, an.angle, *_face_angles(p), direction, mu_F)
    if p.type == "buffer":
        return gm.buffer(load, an.angle, an.phi, direction, mu_F)
    names = ("F", "R")
    push = p.push if p.type == "incline" else "horizontal"
    return gm.incline(load, an.angle, an.phi if p.f is not None else 0.0, direction, mu_F, push,
                      names=names)


def _face_angles(p: EfficiencyProblem) -> tuple[float, float]:
    """φ1 and φ2 of a wedge clamp's two faces (read_efficiency refuses any other count), rad."""
    (_, f1), (_, f2) = p.faces
    return math.atan(f1), math.atan(f2)


def unit_thread(an: EfficiencyAnalysis) -> gm.Stroke:
    """The unrolled thread's raising polygon at Q = 1 N, μF = 1 N/mm: its F is tan(ψ + φv) as drawn."""
    try:
        return gm.incline(1.0, an.angle, an.phi, "forward", 1.0)
    except DegenerateConstruction as e:
        raise SceneError([("efficiency", str(e))], an.scene.source) from None


def _collar_radius(p: EfficiencyProblem) -> tuple[float, float]:
    """(as drawn/summed, closed form) of the collar's friction radius by the scene's rule, m."""
    d0, dw = cast("tuple[float, float]", p.collar)  # requested() refuses r_c and the rest without it
    if p.collar_rule == "mean":
        return (d0 + dw) / 4.0, 0.5 * (0.5 * d0 + 0.5 * dw)
    R, r = dw / 2.0, d0 / 2.0
    return 2.0 / 3.0 * (R ** 3 - r ** 3) / (R ** 2 - r ** 2), ex.annulus_friction_radius(d0, dw)


def _bolt_force(an: EfficiencyAnalysis) -> tuple[float, float]:
    """F_a from the wrench's torque: T over the unrolled thread's drawn F (at 1 N) × d2/2 plus
    the collar's f_c·r_c; against the closed form."""
    p = an.problem
    T, d2, fc = cast(float, p.torque), cast(float, p.d2), cast(float, p.f_c)
    rg, re = _collar_radius(p)
    k_t = cast(float, unit_thread(an).F)  # a raising polygon of a thread (ψ, φv < 90°) closes
    return T / (k_t * d2 / 2.0 + fc * rg), ex.bolt_force_from_torque(T, d2, an.angle, an.phi, fc, re)


def _screw_extra(an: EfficiencyAnalysis, base: str) -> tuple[float, float, float | None, float, bool, float]:
    """A screw's collar, wrench and drive quantities (requested() has checked what each needs)."""
    p = an.problem
    if base == "r_c":
        g, e = _collar_radius(p)
        return g, e, None, 1.0, False, e
    if base in ("F_a", "sigma_a"):
        g, e = _bolt_force(an)
        if base == "sigma_a":
            d1 = cast(float, p.d1)
            g, e = g / (math.pi * d1 * d1 / 4.0), 4.0 * e / (math.pi * d1 ** 2)
        return g, e, None, 1.0, False, e
    if base == "n_screw":  # rev/min: the lift speed over the lead, once round per lead
        v, lead = cast(float, p.speed), cast(float, p.lead)
        return 60.0 * v / lead, 60.0 * ex.screw_speed(v, lead), None, 1.0, False, 1.0
    Q, Qe = (p.load, p.load) if p.load is not None else _bolt_force(an)  # the load, or the wrench's F_a
    if base == "P_drive":  # Q·v over η read off the raising polygon
        v = cast(float, p.speed)
        return Q * v / unit_thread(an).eta, ex.screw_drive_power(Qe, v, an.angle, an.phi), None, 1.0, False, Qe * v
    fc = cast(float, p.f_c)
    rg, re = _collar_radius(p)
    if base == "M_c":
        return fc * Q * rg, fc * Qe * re, None, 1.0, False, Qe * re
    d2 = cast(float, p.d2)  # T_tighten
    k_t = cast(float, unit_thread(an).F)
    return Q * (k_t * d2 / 2.0 + fc * rg), ex.tightening_torque(Qe, d2, an.angle, an.phi, fc, re), None, 1.0, \
        False, Qe * d2


def _strokes(an: EfficiencyAnalysis) -> None:
    p = an.problem
    stated = an.scene.scales.get("F")
    try:
        if stated is None:  # draw once at 1 N/mm to see the sizes, then at a round μF
            trial = [_stroke(an, d, 1.0) for d in p.directions]
            longest = max((math.hypot(s.end[0] - s.start[0], s.end[1] - s.start[1])
                           for st in trial for poly in st.polygons for s in poly.forces), default=1.0)
            an.scales["F"] = round_scale(max(longest, EPS) / POLYGON_MM)
        else:
            an.scales["F"] = stated
            an.stated.add("F")
        for d in p.directions:
            an.strokes[d] = _stroke(an, d, an.scales["F"])
    except DegenerateConstruction as e:
        raise SceneError([("efficiency", str(e))], an.scene.source) from None
    if stated is not None:
        longest = max((math.hypot(s.end[0] - s.start[0], s.end[1] - s.start[1])
                       for st in an.strokes.values() for poly in st.polygons for s in poly.forces), default=1.0)
        if not DRAWN_MM[0] <= longest <= DRAWN_MM[1]:
            raise SceneError([("scales", f"μF = {stated:g} N/mm draws the largest force {longest:.3g} mm "
                               f"long: choose μF so that it is {DRAWN_MM[0]:g} … {DRAWN_MM[1]:g} mm (about "
                               f"{round_scale(longest * stated / POLYGON_MM):g} N/mm)")], an.scene.source)
    for d, st in an.strokes.items():
        what = {"forward": "forward stroke (F drives)", "reverse": "reverse stroke (the load drives)"}[d]
        if st.F is None:
            an.warnings.append(f"{what}: the polygon cannot close (F ∥ the total reaction): no finite force moves "
                               "it — self-locked, η = 0")
        elif st.eta == 0.0:
            an.warnings.append(f"{what}: at the self-locking limit, η = 0 exactly")
        elif st.eta < 0.0 and d == "forward":
            an.warnings.append(f"{what}: self-locking (η = {st.eta:.4g} ≤ 0): no force F in its direction, however "
                               "large, moves it")
        elif st.eta < 0.0:
            an.warnings.append(f"{what}: self-locking (η = {st.eta:.4g} ≤ 0): the load cannot drive it; F must act "
                               "the other way to move it")
        if st.F is not None and st.cond > COND_HAND:
            angle = math.degrees(math.asin(min(1.0, 1.0 / st.cond)))
            an.warnings.append(f"{what}: the polygon closes at {angle:.3g}° (nearly collinear forces): the drawn "
                               f"forces are ill-conditioned (a 0.5 mm slip moves them ×{st.cond:.3g})")


def _rel(g: float, e: float, char: float) -> float:
    return abs(g - e) / max(abs(e), abs(char), 1e-300)


def _row(an: EfficiencyAnalysis, name: str) -> Row:
    base, _, at = name.partition("@")
    unit = an.problem.quantities()[base][0]
    g, e, drawn, scale, ill, char = _values(an, base, _direction(an, at))
    return Row(name, unit, drawn, scale, g, e, _rel(g, e, char), ill)


def _direction(an: EfficiencyAnalysis, at: str) -> Direction:
    """The direction a name gives after its @ (requested() has checked it), else the scene's first."""
    named = [d for d in an.problem.directions if d == at]
    return named[0] if named else (an.problem.directions[0] if an.problem.directions else "forward")


def _eta_reverse_at(an: EfficiencyAnalysis, angle: float) -> float:
    """The reverse η = F/F0 of the polygons at this angle, its sign unrounded (Stroke.eta reports
    |η| ≤ ETA_ZERO as 0, which would blur the limit by 1e-12 of itself)."""
    p = an.problem
    push = p.push if p.type == "incline" else "horizontal"
    try:
        st = gm.incline(1.0, angle, an.phi, "reverse", 1.0, push)
    except DegenerateConstruction:
        return 0.0
    return 0.0 if st.F is None else st.F / st.F0


def _values(an: EfficiencyAnalysis, base: str, d: Direction) -> tuple[float, float, float | None, float, bool, float]:
    """(graphical, exact, drawn mm or None, μ, ill-conditioned, characteristic size)."""
    p = an.problem
    if p.type == "chain":
        eta_g, stages = cast("tuple[float, tuple[gm.StageResult, ...]]", an.chain)  # walked by analyse_efficiency
        branches = [[ex.series_efficiency(series) for _, series in s.branches] for s in p.stages]
        eta_e = ex.series_efficiency([ex.parallel_efficiency([sh for sh, _ in s.branches], b)
                                      for s, b in zip(p.stages, branches)])
        p_out = _chain_power(p)
        if base == "eta":
            return eta_g, eta_e, None, 1.0, False, 1.0
        if base == "P_in":
            return stages[0].power_in, p_out / eta_e, None, 1.0, False, p_out
        return stages[-1].power_out, p_out, None, 1.0, False, p_out
    if base in _SCREW_NEEDS:
        return _screw_extra(an, base)
    if base in ("phi_face1", "phi_face2"):
        f = p.faces[0 if base == "phi_face1" else 1][1]
        return math.degrees(_face_angles(p)[0 if base == "phi_face1" else 1]), math.degrees(math.atan2(f, 1.0)), \
            None, 1.0, False, 1.0
    if base in ("alpha_lock_forward", "alpha_lock_reverse", "f_lock_forward", "f_lock_reverse"):
        try:
            return _lock_limits(an, base)
        except DegenerateConstruction as e:
            raise SceneError([("find", f"{base}: {e}")], an.scene.source) from None
    phi = an.phi
    Q = float(p.load) if p.load is not None else (_bolt_force(an)[0] if p.torque is not None else 1.0)
    mu = an.scales.get("F", 1.0)
    if base in ("phi", "phi_v"):
        return math.degrees(phi), math.degrees(math.atan((p.f or 0.0) / math.cos(p.half_angle))), None, 1.0, False, 1.0
    if base == "psi":
        if p.at_limit:
            return math.degrees(an.angle), math.degrees(ex.equivalent_friction_angle(p.f or 0.0, p.half_angle)), \
                None, 1.0, False, 1.0
        if p.lead is not None:  # the unrolled thread: the hypotenuse over π·d2 and L, its slope read off
            d2 = cast(float, p.d2)  # read_efficiency refuses a pitch without d2
            g = math.degrees(math.atan2(p.lead, math.pi * d2))
            return g, math.degrees(ex.lead_angle(p.lead, d2)), None, 1.0, False, 1.0
        return math.degrees(an.angle), math.degrees(float(cast(float, p.lead_angle))), None, 1.0, False, 1.0
    # requested() refuses r_f without the collar, sigma without d1, M without d2
    if base == "r_f":
        d0, dw = cast("tuple[float, float]", p.collar)
        return (d0 + dw) / 4.0, 0.5 * (0.5 * d0 + 0.5 * dw), None, 1.0, False, dw
    if base == "sigma":
        d1 = float(cast(float, p.d1))
        area = math.pi * d1 * d1 / 4.0
        return Q / area, 4.0 * Q / (math.pi * d1 ** 2), None, 1.0, False, 1.0
    if base in ("self_locking_angle", "gamma_limit", "eta_self_locking_max"):
        if phi == 0.0 and base != "eta_self_locking_max":  # no friction, nothing locks: the limit is 0
            return 0.0, 0.0, None, 1.0, False, 1.0
        try:
            return _limits(an, base, phi)
        except DegenerateConstruction as e:
            raise SceneError([("find", f"{base}: {e}")], an.scene.source) from None
    st = an.strokes[d]
    ill = st.F is not None and st.cond > COND_HAND
    if p.type == "wedge":
        exact = ex.wedge_forces(Q, *_wedge_angles(p), phi, d)
        F0e = ex.wedge_ideal_force(Q, *_wedge_angles(p))
        exact_R = {"R12": exact.R12, "R32": exact.R32, "R31": exact.R31}
        Fe = exact.F
    elif p.type == "wedge_clamp":
        p1, p2 = _face_angles(p)
        Fe = ex.wedge_clamp_force(Q, an.angle, p1, p2, d)
        F0e = ex.wedge_clamp_force(Q, an.angle, 0.0, 0.0, d)
        exact_R = {"R_face1": ex.wedge_clamp_reaction(Q, an.angle, p1, p2, d)}
    elif p.type == "buffer":
        Fe = ex.buffer_force(Q, an.angle, phi, d)
        F0e = ex.buffer_force(Q, an.angle, 0.0, d)
        # the guides carry R12's parts: across the spring's line (R42, as P on wedge 1) and along it (R31 = Q)
        exact_R = {"R12": ex.buffer_reaction(Q, an.angle, phi, d), "R42": abs(Fe), "R31": Q}
    else:
        push = p.push if p.type == "incline" else "horizontal"
        Fe = ex.incline_force(Q, an.angle, phi, d, push)
        F0e = ex.incline_force(Q, an.angle, 0.0, d, push)
        exact_R = {"R": ex.incline_reaction(Q, an.angle, phi, d, push)}
    if base == "F0":
        return st.F0, F0e, st.F0 / mu, mu, False, Q
    if base == "eta":
        eta_e = ex.efficiency(d, F0e, Fe)
        return st.eta, 0.0 if abs(eta_e) <= gm.ETA_ZERO else eta_e, None, 1.0, ill, 1.0
    if st.F is None:
        raise SceneError([("find", f"{base}@{d}: no finite force moves the {d} stroke (self-locked)")], an.scene.source)
    if base == "F":
        return st.F, Fe, st.F / mu, mu, ill, Q
    if base == "M":
        d2 = float(cast(float, p.d2))
        r2 = d2 / 2.0
        Me = ex.screw_torque(Q, d2, an.angle, phi, d)
        return st.F * r2, Me, st.F / mu, mu * r2, ill, Q * r2
    value = dict(st.reactions)[base]
    return value, exact_R[base], value / mu, mu, ill, Q


def _limits(an: EfficiencyAnalysis, base: str, phi: float) -> tuple[float, float, float | None, float, bool, float]:
    """The self-locking limits, found on the construction by redrawing it until η = 0."""
    p = an.problem
    if base == "gamma_limit":
        g = gm.wedge_locking_angle(float(_wedge_angles(p)[1]), phi)
        return math.degrees(g), math.degrees(2.0 * phi), None, 1.0, False, 1.0
    g = gm.limiting_angle(lambda x: _eta_reverse_at(an, x), *gm.INCLINE_LIMIT_RANGE)
    if base == "self_locking_angle":
        return math.degrees(g), math.degrees(phi), None, 1.0, False, 1.0
    eta = gm.incline(1.0, g, phi, "forward", 1.0).eta
    return eta, ex.self_locking_efficiency_bound(phi), None, 1.0, False, 1.0


def _lock_limits(an: EfficiencyAnalysis, base: str) -> tuple[float, float, float | None, float, bool, float]:
    """The self-locking limits of a wedge clamp (reverse) or a buffer (both), found on the
    construction: the polygon at Q = 1 N is redrawn at other wedge angles (or friction angles, for
    f_lock) until the driving force F changes sign (η = 0), against the closed forms."""
    p = an.problem
    d: Direction = "forward" if base.endswith("forward") else "reverse"

    def drawn_F(st: gm.Stroke) -> float:
        return 0.0 if st.F is None else st.F

    if p.type == "wedge_clamp":
        p1, p2 = _face_angles(p)
        if p1 + p2 == 0.0:  # both faces frictionless: nothing locks, the limit is 0
            return 0.0, 0.0, None, 1.0, False, 1.0
        # up to α − φ2 = 90°, where face 1 would let go; the limit φ1 + φ2 lies below it
        g = gm.limiting_angle(lambda a: drawn_F(gm.wedge_clamp(1.0, a, p1, p2, "reverse", 1.0)), 1e-200,
                              math.pi / 2 + p2 - 1e-9)
        return math.degrees(g), math.degrees(ex.wedge_clamp_locking(p1, p2)), None, 1.0, False, 1.0
    phi, alpha = an.phi, an.angle
    if base.startswith("alpha"):
        if phi == 0.0:  # frictionless: it locks only at the ends, α = 0° forward and 90° reverse
            e = 0.0 if d == "forward" else 90.0
            return e, e, None, 1.0, False, 1.0
        # at 0° and 90° the frictionless polygon of wedge 2 (R12 ∥ R42) no longer closes: the wedge's range
        g = gm.limiting_angle(lambda a: drawn_F(gm.buffer(1.0, a, phi, d, 1.0)), *gm.WEDGE_LIMIT_RANGE)
        e = ex.buffer_locking(phi)[0 if d == "forward" else 1]
        return math.degrees(g), math.degrees(e), None, 1.0, False, 1.0
    g = gm.limiting_angle(lambda x: drawn_F(gm.buffer(1.0, alpha, x, d, 1.0)), *gm.INCLINE_LIMIT_RANGE)
    e = ex.buffer_locking_coefficients(alpha)[0 if d == "forward" else 1]
    return math.tan(g), e, None, 1.0, False, e


def judge_efficiency(an: EfficiencyAnalysis, precision_mm: float | None = None) -> list[Verdict]:
    """Hand values against the construction: drawn forces within the drawing precision × μF,
    the rest within 0.1 %."""
    prec = precision_mm if precision_mm is not None else an.scene.precision_mm
    out = []
    for _key, name, value in measured_entries(an.scene, an.extra_measured):
        base, _, at = name.partition("@")
        d = _direction(an, at)
        g, _e, drawn, scale, _ill, _c = _values(an, base, d)
        unit = an.problem.quantities()[base][0]
        st = an.strokes.get(d) if base == "eta" and an.problem.type != "chain" else None
        if st is not None and st.F and st.F0:
            # η = F0/F (F/F0) from two lengths read off the polygons, each within the precision
            # × μF: its tolerance follows from theirs (0.1 % would fail a correctly drawn F)
            tol = abs(g) * prec * an.scales["F"] * (1.0 / abs(st.F) + 1.0 / abs(st.F0))
            out.append(Verdict(name, value, g, tol, abs(value - g) <= tol + 1e-12 * abs(g), unit))
            continue
        out.append(judge_value(name, value, g, drawn, scale, prec, unit))
    return out


__all__ = ["EfficiencyAnalysis", "analyse_efficiency", "judge_efficiency", "requested", "unit_thread"]


def efficiency_figure(an: EfficiencyAnalysis, page: tuple[float, float], footer: tuple[str, ...] = ()) -> Sheet:
    """The sheet of the scene's ``show``: the diagram and the force polygons."""
    from graphmech.problems.efficiency.figures import efficiency_sheet

    p = an.problem
    if "polygon" in an.scene.show and not an.strokes and p.type != "chain":
        _strokes(an)
    angle = an.angle if p.type in ("incline", "screw") else None
    show = [s for s in an.scene.show if not (s == "polygon" and p.type == "chain")]
    if p.type == "chain" and "diagram" in show:
        _chain_fits(an, page)
    sheet = efficiency_sheet(an.scene.title, p, an.strokes, an.chain, an.phi, angle, an.scales, show, page, footer,
                             an.scene.page.notation)
    if p.type == "chain" and "diagram" in show:
        _chain_fits(an, page, sheet)
    return sheet


#: The most machines (boxes) a chain's diagram draws, whatever the page: each brings labels that
#: the label placer sets against every other (a textbook chain has a handful; 3 601 took minutes).
MAX_CHAIN_BOXES = 120


def _chain_fits(an: EfficiencyAnalysis, page: tuple[float, float], sheet: Sheet | None = None) -> None:
    """Refuse a chain whose diagram the page cannot show: too many machines to label legibly, or
    (given the sheet) boxes that run off the page — before any label is placed."""
    from graphmech.drawing.lettering import text_box_size
    from graphmech.render.layout import layout_sheet
    from graphmech.drawing.primitives import Label

    boxes = sum(len(s.branches) for s in an.problem.stages)
    if boxes > MAX_CHAIN_BOXES:
        raise SceneError([("efficiency.stage", f"{boxes} machines (boxes) in the chain: a diagram shows at most "
                                               f"{MAX_CHAIN_BOXES} legibly; use graphmech check")], an.scene.source)

    def centred(label: Label) -> tuple[float, float, float, float]:
        w, h = text_box_size(label.text, label.size)
        return (label.anchor[0] - w / 2, label.anchor[1] - h / 2, label.anchor[0] + w / 2, label.anchor[1] + h / 2)

    # each label as if centred on its anchor (the placer only moves them further out): what this
    # lays off the page surely runs off it
    nominal = [[centred(it) for it in panel.items if isinstance(it, Label)] for panel in (sheet.panels if sheet else ())]
    if sheet is not None and layout_sheet(sheet, label_boxes=nominal).warnings:
        n = len(an.problem.stages)
        raise SceneError([("efficiency.stage", f"the chain's diagram ({n} stage{'s' * (n != 1)}, {boxes} "
                                               f"machine{'s' * (boxes != 1)}) does not fit a page of "
                                               f"{page[0]:g} × {page[1]:g} mm: "
                                               "choose a larger [page] size or use graphmech check")],
                         an.scene.source)
