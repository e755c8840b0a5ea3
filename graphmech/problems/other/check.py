"""Checking a scene of the other mechanisms: the Geneva wheel's sizes and the wheel's ω₂, ε₂ by
construction (:mod:`graphmech.methods.geneva`) against the closed forms of
:mod:`graphmech.exact.geneva`; the differential screw's lead (both branches) or travel.

The sizes are lengths on the layout × μl; k is the dial's engaged turn 2φ₁ (measured at O₁ from the
line of centres to the entry point K) over a whole turn, and T, t_motion, t_rest, n_dial follow
from it and the rest or speed given; ω₂, ε₂, the pin's sliding speed and its Coriolis
acceleration are read off the pin's polygons at the dial angle.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from graphmech.errors import SceneError
from graphmech.exact import geneva as ex
from graphmech.methods.geneva import GenevaLayout, PinPolygons, layout, polygons
from graphmech.problems.judging import (
    Row,
    Verdict,
    close_names,
    judge_value,
    measured_entries,
)
from graphmech.problems.other.scene import (
    GENEVA_AT_ANGLE,
    GENEVA_QUANTITIES,
    SCREW_QUANTITIES,
    GenevaProblem,
    OtherScene,
    ScrewProblem,
)
from graphmech.scales import drawn_size_problem, format_scale, round_scale

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene

#: The mechanism's width on paper when graphmech chooses μl, mm; the polygons' longest side (μv, μa).
GENEVA_MM, POLYGON_MM = 150.0, 50.0
#: Dial angles at which the ω₂(φ), ε₂(φ) curves are constructed across the engagement.
CURVE_POINTS = 49


@dataclass
class OtherAnalysis:
    """What one scene produced: the Geneva layout and polygons, the screw's branches, the rows."""

    scene: Scene[OtherScene]
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    stated: set[str] = field(default_factory=set)
    lay: GenevaLayout | None = None
    at_angle: PinPolygons | None = None
    #: (φ, ω₂, ε₂) by construction across the engagement (``geneva_curves``), ω₂ and ε₂ in the
    #: book's sense (positive: the wheel turns against the dial, speeds up)
    curves: list[tuple[float, float, float]] = field(default_factory=list)
    #: the screw: (name, lead, hand, "against" | "with" | "given") per branch
    screw: list[tuple[str, float, str, str]] = field(default_factory=list)
    extra_measured: tuple[tuple[str, float], ...] = ()

    def scale_notes(self) -> list[str]:
        return [format_scale(k, v) + ("" if k in self.stated else " (chosen)") for k, v in self.scales.items()]

    def summary(self) -> dict[str, Any]:
        """What ``check --json`` adds: the screw's branches with their hands."""
        if not self.screw:
            return {}
        return {"differential_screw": [{"name": n, "lead": p, "hand": h, "link_2_moves": m}
                                       for n, p, h, m in self.screw]}


def units(p: OtherScene) -> dict[str, str]:
    out: dict[str, str] = {}
    if p.geneva is not None:
        out.update(GENEVA_QUANTITIES)
        if p.geneva.phi is not None:
            out.update(GENEVA_AT_ANGLE)
    if p.screw is not None:
        out.update({"p_B": "m", "p_B_alt": "m"} if p.screw.travel is not None else {"s_B": "m"})
    return out


def requested(scene: Scene[OtherScene], extra: tuple[tuple[str, float], ...] = ()) -> list[str]:
    p = scene.problem
    q = units(p)
    problems = []
    for key, name in [(f"find[{i}]", n) for i, n in enumerate(scene.find)] + \
            [(k, n) for k, n, _ in measured_entries(scene, extra)]:
        if name in q:
            continue
        if name in GENEVA_AT_ANGLE and p.geneva is not None:
            problems.append((key, f"{name} needs [geneva] dial_angle (the dial's angle from the line of centres)"))
        elif name in GENEVA_QUANTITIES or name in GENEVA_AT_ANGLE:
            problems.append((key, f"{name} needs a [geneva] table"))
        elif name in SCREW_QUANTITIES and p.screw is not None:
            problems.append((key, f"{name} needs [differential_screw] " + ("lead_B with hand_B (screw B given)"
                                                                          if name == "s_B" else
                                                                          "travel (the travel asked for)")))
        elif name in SCREW_QUANTITIES:
            problems.append((key, f"{name} needs a [differential_screw] table"))
        else:
            problems.append((key, f"unknown quantity {name!r} of this scene{close_names(name, q)}"))
    if problems:
        raise SceneError(problems, scene.source)
    return list(scene.find) or [n for n in q if n != "omega_wheel_max"]


def _scale(an: OtherAnalysis, symbol: str, longest: float, paper: float) -> float:
    scene = an.scene
    if symbol in scene.scales:
        an.stated.add(symbol)
        mu = float(scene.scales[symbol])
        why = drawn_size_problem(longest, mu, symbol, {"l": "the mechanism", "v": "the velocity polygon",
                                                       "a": "the acceleration polygon"}[symbol])
        if why:
            raise SceneError([("scales", why)], scene.source)
    else:
        mu = round_scale(longest / paper)
    an.scales[symbol] = mu
    return mu


def _geneva(an: OtherAnalysis, g: GenevaProblem, names: list[str]) -> None:
    R, S = ex.crank_radius(g.z, g.L), ex.wheel_radius(g.z, g.L)
    mu_l = _scale(an, "l", g.L + R + S, GENEVA_MM)
    an.lay = lay = layout(g.z, g.L, g.r_pin, g.b, mu_l)
    k_g = 2 * lay.half_angle / (2 * math.pi)
    if g.t_rest is not None:
        T_g, T_e = g.t_rest / (1 - k_g), ex.period_from_rest(g.z, g.t_rest)
    else:
        T_g = T_e = 2 * math.pi / g.omega1
    k_e = ex.motion_coefficient(g.z)
    w1 = g.omega1
    needs_polygons = g.phi is not None or "omega_wheel_max" in names or "geneva_curves" in an.scene.show
    mu_v = mu_a = 1.0
    if needs_polygons:
        mu_v = _scale(an, "v", w1 * R, POLYGON_MM)
        mu_a = _scale(an, "a", 2 * w1 * w1 * R, POLYGON_MM)  # π a₁′ = ω₁²R; a₂′ reaches about twice it
    if g.phi is not None:
        an.at_angle = polygons(lay, g.phi, w1, mu_l, mu_v, mu_a)
    if "geneva_curves" in an.scene.show:
        half = lay.half_angle
        for i in range(CURVE_POINTS):
            phi = -half + 2 * half * i / (CURVE_POINTS - 1)
            pp = polygons(lay, phi, w1, mu_l, mu_v, mu_a)
            an.curves.append((phi, -pp.omega2, -pp.epsilon2))
    size, T = g.L, T_e
    for name in names:
        if name not in GENEVA_QUANTITIES and name not in GENEVA_AT_ANGLE:
            continue
        row: tuple[float | None, float, float, float, float]  # drawn, μ, graphical, exact, characteristic
        if name == "R_crank":
            row = (lay.R_mm, mu_l, lay.R_mm * mu_l, R, size)
        elif name == "S_wheel":
            row = (lay.S_mm, mu_l, lay.S_mm * mu_l, S, size)
        elif name == "h_slot":
            row = (lay.h_mm, mu_l, lay.h_mm * mu_l, ex.slot_depth(g.z, g.L, g.r_pin), size)
        elif name == "r_lock":
            row = (lay.r_lock_mm, mu_l, lay.r_lock_mm * mu_l, ex.locking_radius(g.z, g.L, g.r_pin, g.b), size)
        elif name == "k_motion":
            row = (None, 1.0, k_g, k_e, 1.0)
        elif name == "T_cycle":
            row = (None, 1.0, T_g, T_e, T)
        elif name == "t_motion":
            row = (None, 1.0, k_g * T_g, k_e * T_e, T)
        elif name == "t_rest":
            row = (None, 1.0, (1 - k_g) * T_g, (1 - k_e) * T_e, T)
        elif name == "n_dial":
            row = (None, 1.0, 60.0 / T_g, 60.0 / T_e, 60.0 / T)
        elif name == "omega_wheel_max":
            pp = polygons(lay, 0.0, w1, mu_l, mu_v, mu_a)
            row = _omega_row(pp, mu_v, mu_l, ex.wheel_omega_max(g.z, w1), w1)
        else:
            pp = an.at_angle  # type: ignore[assignment]  # requested() asks for dial_angle first
            assert pp is not None and g.phi is not None
            if name == "omega_wheel":
                row = _omega_row(pp, mu_v, mu_l, ex.wheel_omega(g.z, g.phi, w1), w1)
            elif name == "epsilon_wheel":
                t = (pp.a2_[0] - pp.n2_[0], pp.a2_[1] - pp.n2_[1])
                drawn = math.copysign(math.hypot(*t), -pp.epsilon2)
                row = (drawn, mu_a / (pp.O2A_mm * mu_l), -pp.epsilon2, ex.wheel_epsilon(g.z, g.phi, w1), w1 * w1)
            elif name == "v_slide":
                drawn = math.hypot(pp.a1[0] - pp.a2[0], pp.a1[1] - pp.a2[1])
                row = (drawn, mu_v, drawn * mu_v, ex.slide_velocity(g.z, g.L, g.phi, w1), w1 * R)
            else:  # a_k_pin
                drawn = math.hypot(pp.a1_[0] - pp.k_[0], pp.a1_[1] - pp.k_[1])
                row = (drawn, mu_a, drawn * mu_a, ex.coriolis(g.z, g.L, g.phi, w1), w1 * w1 * R)
        length, mu, gv, ev, char = row
        unit = {**GENEVA_QUANTITIES, **GENEVA_AT_ANGLE}[name]
        an.rows.append(Row(name, unit, length, mu, gv, ev, abs(gv - ev) / max(abs(ev), char, 1e-300)))


def _omega_row(pp: PinPolygons, mu_v: float, mu_l: float, exact: float, w1: float
               ) -> tuple[float | None, float, float, float, float]:
    """ω₂ = pa₂·μv/O₂A, in the book's sense (positive: against the dial)."""
    drawn = math.copysign(math.hypot(*pp.a2), -pp.omega2)
    return drawn, mu_v / (pp.O2A_mm * mu_l), -pp.omega2, exact, w1


def _screw(an: OtherAnalysis, s: ScrewProblem, names: list[str]) -> None:
    """Per turn of link 1, link 1 advances p_A along its screw A; link 2 follows it, less (more)
    what screw B turns it back along link 1: the displacements composed, against exact/."""
    other = "left" if s.hand_A == "right" else "right"
    rows: list[tuple[str, float, float]] = []
    if s.travel is not None:
        # link 2 against link 1's advance: x₂ = −s, so screw B carries 2 back by p_A + s (A's hand);
        # with it: x₂ = +s, carried back by p_A − s (A's hand while positive, else the other hand)
        against, along = s.p_A + s.travel, s.p_A - s.travel
        (e1, _), alt = ex.screw_leads(s.p_A, s.travel)
        an.screw.append(("p_B", against, s.hand_A, "against"))
        rows.append(("p_B", against, e1))
        if alt is None:
            an.warnings.append("p_B_alt: a travel equal to the lead p_A leaves screw B no lead (p_B = 0): one branch")
        else:
            an.screw.append(("p_B_alt", abs(along), s.hand_A if along > 0 else other, "with"))
            rows.append(("p_B_alt", abs(along), alt[0]))
    else:
        assert s.p_B is not None and s.hand_B is not None
        same = s.hand_B == s.hand_A
        travel = s.p_A - (s.p_B if same else -s.p_B)  # along link 1's own advance
        an.screw.append(("s_B", travel, s.hand_B, "given"))
        rows.append(("s_B", travel, ex.screw_travel(s.p_A, s.p_B, same)))
    for name, g, e in rows:
        if name in names:
            an.rows.append(Row(name, "m", None, 1.0, g, e, abs(g - e) / max(abs(e), s.p_A)))


def analyse_other(scene: Scene[OtherScene], extra: tuple[tuple[str, float], ...] = ()) -> OtherAnalysis:
    """Construct what the scene needs and build its check table."""
    names = requested(scene, extra)
    an = OtherAnalysis(scene, extra_measured=tuple(extra))
    p = scene.problem
    if p.geneva is not None:
        _geneva(an, p.geneva, names)
    if p.screw is not None:
        _screw(an, p.screw, names)
    return an


def judge_other(an: OtherAnalysis, precision_mm: float | None = None) -> list[Verdict]:
    """Hand values: a length off the drawing within the precision × μ, a computed value within 0.1 %."""
    prec = precision_mm if precision_mm is not None else an.scene.precision_mm
    rows = {r.name: r for r in an.rows}
    q = units(an.scene.problem)
    out = []
    for _key, name, value in measured_entries(an.scene, an.extra_measured):
        r = rows.get(name)
        if r is None:  # measured but not in find: construct it alone
            extra = analyse_other(_only(an.scene, name))
            r = next(x for x in extra.rows if x.name == name)
        out.append(judge_value(name, value, r.graphical, r.drawn_mm, r.scale, prec, q[name]))
    return out


def _only(scene: Scene[OtherScene], name: str) -> Scene[OtherScene]:
    from dataclasses import replace

    return replace(scene, find=(name,), measured=(), show=tuple(s for s in scene.show if s != "geneva_curves"))


def text_lines(an: OtherAnalysis) -> list[str]:
    """The screw's branches with their hands, under the text table."""
    words = {"against": "link 2 moves against link 1's advance (pB = pA + s, the book's branch)",
             "with": "link 2 moves with link 1's advance (pB = |pA − s|)", "given": "s > 0: with link 1's advance"}
    return [f"{n} = {p * 1000:.6g} mm, {h}-hand: {words[m]}" for n, p, h, m in an.screw]


__all__ = ["OtherAnalysis", "analyse_other", "judge_other", "requested", "text_lines", "units"]
