"""The synthesis task ``time_ratio``: a linkage designed from its time ratio K.

Read, by ``mechanism``: a crank-rocker from ``K``, the rocker ``rocker`` (l_CD), the frame
``frame`` (l_AD) and either the swing ``swing`` (ψ) or one limit position ``limit_angle`` (∠ADC₁);
an offset slider-crank from ``K``, ``stroke`` (H) and ``offset`` (e); a guide bar from ``K``,
``frame`` (l_AC) and optionally ``stroke`` (the ram's H). Analysed: every design the construction
(:mod:`graphmech.methods.synthesis_time_ratio`) draws, its lengths measured at μl against the
closed forms (:mod:`graphmech.exact.synthesis`), then re-analysed as a linkage — drawn
(:func:`graphmech.methods.characteristics.draw_characteristics`) against exact
(:mod:`graphmech.exact.characteristics`) — so that its K, ψ (or H) and γ_min are in the table and
the re-analysis error against what was asked is said under it.
"""
from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from graphmech.errors import SceneError
from graphmech.problems.reader import MISSING, Reader, not_for

if TYPE_CHECKING:
    from graphmech.exact.synthesis import Design
    from graphmech.methods.synthesis_time_ratio import (
        DrawnDesign,
        DrawnGuideBar,
        DrawnSlider,
    )
    from graphmech.problems.judging import Row

#: The mechanisms the time-ratio task designs.
MECHANISMS = ("crank_rocker", "slider_crank", "guide_bar")
#: A guide bar's K at and above this asks θ = ψ ≥ 170°: a crank all but as long as the frame (at
#: θ = 180° the bar turns fully).
K_MAX_GUIDE = 35.0
#: A slider-crank's rows (one design: no prefix); ``stroke`` is the re-analysed H.
SLIDER_NAMES = {"theta": "deg", "AC1": "m", "AC2": "m", "lAB": "m", "lBC": "m", "K": "", "stroke": "m",
                "gamma_min": "deg"}
#: A guide bar's rows (one design: no prefix).
GUIDE_NAMES = {"theta": "deg", "lAB": "m", "lCD": "m", "K": "", "psi": "deg", "gamma_min": "deg"}
#: K at and above this asks θ ≥ 90°: no crank-rocker is designed so (the θ-circle's arc
#: would lie on the rocker's side).
K_MAX = 3.0
#: Above 1 and below this, θ (< 1.6e-6 rad) draws a θ-circle more than 10⁶ chords across: the
#: design is K = 1's to the drawing's precision, and its construction would be round-off.
K_NEAR_1 = 1.0 + 1e-6
#: The smallest swing ψ drawn, rad: C₁C₂ = 2·l_CD·sin(ψ/2) stays far above the round-off of C's
#: coordinates (1e-16 of l_CD); 1e-300° put C₁ on C₂ and the chord's direction divided by zero.
#: A limit angle ∠ADC₁ keeps as far from 0 and 180° (C₁ off the frame line, and off A where
#: l_CD = l_AD).
MIN_SWING = 1e-9
#: What each design's rows are called, with their units (the bank's keys without a unit).
SOLUTION_NAMES = {"AC1": "m", "AC2": "m", "lAB": "m", "lBC": "m", "K": "", "psi": "deg", "gamma_min": "deg"}
#: The most designs one construction gives (two rays, two cuts each).
MAX_SOLUTIONS = 4


@dataclass(frozen=True)
class TimeRatio:
    """A crank-rocker to design, SI: K, the rocker c = l_CD, the frame d = l_AD and the swing ψ
    or the limit angle λ = ∠ADC₁ (exactly one of them)."""

    mechanism: str
    K: float
    rocker: float
    frame: float
    swing: float | None = None
    limit_angle: float | None = None
    #: The key the swing or the limit angle was written under (``swing_deg``), for messages.
    key: str = ""
    #: The direction of the rocker's middle position DC on the drawing (with the swing), rad.
    middle: float = math.pi / 2

    @property
    def theta(self) -> float:
        """θ = 180°(K − 1)/(K + 1), rad."""
        return math.pi * (self.K - 1.0) / (self.K + 1.0)


@dataclass(frozen=True)
class GuideBar:
    """A guide bar (shaper) to design, SI: K, the frame l_AC (crank pivot A to the bar's pivot C)
    and, optionally, the ram's stroke H (it gives the bar's length l_CD)."""

    K: float
    frame: float
    stroke: float | None = None
    mechanism: str = "guide_bar"

    @property
    def theta(self) -> float:
        """θ = ψ = 180°(K − 1)/(K + 1), rad."""
        return math.pi * (self.K - 1.0) / (self.K + 1.0)


@dataclass(frozen=True)
class SliderCrank:
    """A slider-crank to design, SI: K, the stroke H and the offset e ≥ 0 of A from the guide."""

    K: float
    stroke: float
    offset: float
    mechanism: str = "slider_crank"
    #: The key the offset was written under (``synthesis.offset_mm``), for messages.
    key: str = "synthesis.offset"

    @property
    def theta(self) -> float:
        """θ = 180°(K − 1)/(K + 1), rad."""
        return math.pi * (self.K - 1.0) / (self.K + 1.0)


#: What the time-ratio task designs.
Problem = TimeRatio | SliderCrank | GuideBar


def read_time_ratio(r: Reader) -> TimeRatio | SliderCrank | GuideBar | None:
    """The rest of [synthesis] for ``task = "time_ratio"`` (None after reporting)."""
    mech = r.string("mechanism", choices=MECHANISMS, required=True)
    K = _read_K(r)
    if mech == "guide_bar":
        return _read_guide_bar(r, K)
    if K is not None and K >= K_MAX:
        what = "crank-rocker" if mech == "crank_rocker" else "slider-crank"
        r.problem(r.at("K"), f"K = {K:g} ≥ 3 asks θ = {180 * (K - 1) / (K + 1):.4g}° ≥ 90°: no {what} "
                             "is designed so (the crank angle between the limits stays below 90°)")
        K = None
    if mech == "slider_crank":
        return _read_slider_crank(r, K)
    return _read_crank_rocker(r, mech, K)


def _read_slider_crank(r: Reader, K: float | None) -> SliderCrank | None:
    not_for(r, ("rocker", "frame", "swing", "limit_angle"), "not for a slider-crank: give stroke and offset")
    if K == 1.0:
        r.problem(r.at("K"), "K = 1: θ = 0 asks a centred slider-crank, l_AB = H/2 with any l_BC — K does not "
                             "fix the design (give K > 1 and the offset)")
        K = None
    H = r.scalar("stroke", "length", positive=True)
    e = r.scalar("offset", "length")
    if e is not None and e < 0.0:
        r.problem(r.at(r.present("offset") or "offset"), "the offset is a distance ≥ 0 (the drawing puts A above the guide)")
        e = None
    elif e == 0.0:
        r.problem(r.at(r.present("offset") or "offset"), "e = 0: a centred slider-crank has θ = 0, K = 1 — a quick "
                                                         "return needs an offset")
        e = None
    for value, base in ((H, "stroke"), (e, "offset")):
        if value is not None and not 1e-9 <= value <= 1e9:
            r.problem(r.at(r.present(base) or base), f"{value:g} m is absurd for a slider-crank (1e-9 … 1e9 m)")
            return None
    if K is None or H is None or e is None:
        return None
    return SliderCrank(K, H, e, key=r.at(r.present("offset") or "offset"))


def _read_guide_bar(r: Reader, K: float | None) -> GuideBar | None:
    not_for(r, ("rocker", "swing", "limit_angle"), "not for a guide bar: its bar swings ψ = θ, set by K")
    if K == 1.0:
        r.problem(r.at("K"), "K = 1: a guide bar's θ is its swing ψ > 0, it always returns quick — no guide bar "
                             "has K = 1")
        K = None
    elif K is not None and K >= K_MAX_GUIDE:
        r.problem(r.at("K"), f"K = {K:g} asks θ = ψ = {180 * (K - 1) / (K + 1):.4g}° ≥ 170°: a crank all but as "
                             "long as the frame (at 180° the bar turns fully)")
        K = None
    d = r.scalar("frame", "length", positive=True)
    H = r.scalar("stroke", "length", required=False, positive=True)
    for value, base in ((d, "frame"), (H, "stroke")):
        if value is not None and not 1e-9 <= value <= 1e9:
            r.problem(r.at(r.present(base) or base), f"{value:g} m is absurd for a link (1e-9 … 1e9 m)")
            return None
    if K is None or d is None or (H is None and r.present("stroke") is not None):
        return None
    return GuideBar(K, d, H)


def _read_K(r: Reader) -> float | None:
    raw = r.raw("K", required=True, hint="the time ratio, a number ≥ 1")
    K = None if raw is MISSING else r.number(raw, r.at("K"))
    if K is not None and K < 1.0:
        r.problem(r.at("K"), f"K = {K:g} < 1: the time ratio (180° + θ)/(180° − θ) is at least 1 "
                             "(K = 1: no quick return)")
        K = None
    elif K is not None and 1.0 < K < K_NEAR_1:
        r.problem(r.at("K"), f"K = {K!r} is within 1e-6 of 1: θ = {180 * (K - 1) / (K + 1):.3g}° draws a θ-circle "
                             "millions of chords across — write K = 1 (no quick return)")
        K = None
    return K


def _read_crank_rocker(r: Reader, mech: str | None, K: float | None) -> TimeRatio | None:
    not_for(r, ("stroke",), "not for a crank-rocker: its rocker swings (swing or limit_angle)")
    c = r.scalar("rocker", "length", positive=True)
    d = r.scalar("frame", "length", positive=True)
    swing = r.scalar("swing", "angle", required=False)
    limit = r.scalar("limit_angle", "angle", required=False)
    middle = r.scalar("rocker_middle", "angle", required=False)
    if middle is not None and limit is not None:
        r.problem(r.at(r.present("rocker_middle") or "rocker_middle"),
                  "with limit_angle the frame line is drawn level and sets the rocker's direction: "
                  "rocker_middle goes with swing")
    given = [k for k in ("swing", "limit_angle") if r.present(k) is not None]
    if not given:
        r.problem(r.at("swing"), "missing: write swing_deg (the rocker's swing ψ) or limit_angle_deg "
                                 "(∠ADC₁ of one limit position)")
    elif len(given) == 2:
        r.problem(r.at(r.present("limit_angle") or "limit_angle"),
                  "give the swing or one limit position, not both")
    for value, base, what in ((swing, "swing", "ψ"), (limit, "limit_angle", "∠ADC₁")):
        if value is not None and not 0.0 < value < math.pi:
            r.problem(r.at(r.present(base) or base), f"{what} must lie between 0 and 180°")
            return None
    if swing is not None and swing < MIN_SWING:  # C₁, C₂ one point: the chord C₁C₂ has no direction
        r.problem(r.at(r.present("swing") or "swing"),
                  f"ψ = {math.degrees(swing):.3g}° is under {math.degrees(MIN_SWING):.2g}°: C₁ and C₂ all but "
                  "coincide (the chord C₁C₂ under 1e-9 of l_CD) — the rocker must swing")
        return None
    if limit is not None and not MIN_SWING <= limit <= math.pi - MIN_SWING:  # DC₁ along the frame line
        r.problem(r.at(r.present("limit_angle") or "limit_angle"),
                  f"∠ADC₁ = {math.degrees(limit):.12g}° is within {math.degrees(MIN_SWING):.2g}° of the frame line: "
                  "the rocker lies along the frame, C₁ all but on the line AD")
        return None
    for value, base in ((c, "rocker"), (d, "frame")):
        if value is not None and not 1e-9 <= value <= 1e9:
            r.problem(r.at(r.present(base) or base), f"{value:g} m is absurd for a link (1e-9 … 1e9 m)")
            return None
    if mech is None or K is None or c is None or d is None or len(given) != 1 or (swing is None and limit is None):
        return None
    return TimeRatio(mech, K, c, d, swing, limit, r.at(r.present(given[0]) or given[0]),
                     math.pi / 2 if middle is None else middle)


def prefix(k: int, count: int) -> str:
    """``sol1_`` … where the construction gives several designs, nothing for one."""
    return f"sol{k + 1}_" if count > 1 else ""


def names(count: int) -> list[str]:
    """Every row name of a scene whose construction gives ``count`` designs."""
    return ["theta"] + [prefix(k, count) + n for k in range(count) for n in SOLUTION_NAMES]


def designs(p: TimeRatio, mu_l: float) -> tuple[list[DrawnDesign], list[Design]]:
    """The drawn designs (mm) and the exact ones (m), longest coupler first, paired by order."""
    from graphmech.exact import synthesis as ex
    from graphmech.methods import synthesis_time_ratio as gm

    c_mm, d_mm = p.rocker / mu_l, p.frame / mu_l
    if p.limit_angle is not None:
        return (gm.draw_from_limit(c_mm, d_mm, p.limit_angle, gm.theta_of_K(p.K)),
                ex.crank_rocker_from_limit(p.rocker, p.frame, p.limit_angle, ex.theta_of_K(p.K)))
    assert p.swing is not None
    return (gm.draw_from_swing(c_mm, d_mm, p.swing, gm.theta_of_K(p.K), p.middle),
            ex.crank_rocker_from_swing(p.rocker, p.frame, p.swing, ex.theta_of_K(p.K)))


def size(p: Problem) -> float:
    """The designed linkage's size, m: the rocker and the frame; the frame or the bar; a
    slider-crank's A to its far limit C₂ and the offset (its θ-circle, H/sin θ across, is drawn as
    an arc where it is larger: K near 1), or the θ-circle where no design exists."""
    if isinstance(p, SliderCrank):
        from graphmech.exact.synthesis import slider_crank_from_K

        found = slider_crank_from_K(p.stroke, p.offset, p.theta)
        if found is None:
            return p.stroke / math.sin(p.theta) + p.offset
        return max(found[2], p.stroke) + p.offset
    if isinstance(p, GuideBar):
        from graphmech.exact.synthesis import guide_bar_from_K

        return max(p.frame, guide_bar_from_K(p.frame, p.theta, p.stroke)[1] or 0.0)
    return p.rocker + p.frame


def choose_scale(p: Problem) -> float:
    """μl that draws the linkage about 100 mm across."""
    from graphmech.scales import round_scale

    return round_scale(size(p) / 100.0)


@dataclass
class Designed:
    """What the task found: the drawn and the exact designs (paired by order), the rows, the
    warnings and, per design, what ``check --json`` adds."""

    drawn: list[DrawnDesign]
    exact: list[Design]
    rows: list[Row]
    warnings: list[str]
    solutions: list[dict[str, Any]]
    #: Every name the scene could ask for.
    names: list[str]
    #: A guide bar's drawing (None for a crank-rocker).
    guide: DrawnGuideBar | None = None
    #: A slider-crank's drawing.
    slider: DrawnSlider | None = None


def analyse_time_ratio(p: Problem, mu: float, find: tuple[str, ...] = (), source: str = "") -> Designed:
    """The designs at μl = ``mu``, their rows (those ``find`` asks; all when it is empty), the
    re-analysis and the words under the table; ``source`` names the file in a refusal."""
    if isinstance(p, GuideBar):
        return _analyse_guide_bar(p, mu, find)
    if isinstance(p, SliderCrank):
        return _analyse_slider_crank(p, mu, find, source)
    from graphmech.exact.characteristics import fourbar, fourbar_class
    from graphmech.mechanisms.linkage import RRR, Crank, Linkage
    from graphmech.methods.characteristics import draw_characteristics
    from graphmech.problems.judging import Row

    drawn, exact = designs(p, mu)
    key = p.key
    if not exact:
        asked = (f"the limit angle {math.degrees(p.limit_angle):.4g}°" if p.limit_angle is not None
                 else f"the swing {math.degrees(p.swing or 0.0):.4g}°")
        raise SceneError([(key, (f"no Grashof crank: no crank-rocker with l_CD = {p.rocker:g} m, l_AD = {p.frame:g} m, "
                                 f"{asked} and K = {p.K:g} (θ = {math.degrees(p.theta):.4g}°) — every cut of the "
                                 "construction gives a crank that does not turn fully or changes branch"))],
                         source)
    if len(drawn) != len(exact):  # the construction and the closed forms disagree: say so, do not pair
        raise SceneError([(key, (f"the construction draws {len(drawn)} design(s) and the closed forms find "
                                 f"{len(exact)}: a limiting case (a cut that just touches) — move the data off it"))],
                         source)
    out = Designed(drawn, exact, [], [], [], names(len(exact)))
    if p.K == 1.0:
        out.warnings.append("K = 1: θ = 0, no quick return — the crank pin's limits lie on one line through A")
    n = len(exact)
    theta = math.degrees(p.theta)
    rows = [Row("theta", "deg", None, 1.0, math.degrees(drawn[0].theta), theta,
                abs(math.degrees(drawn[0].theta) - theta) / 180.0)]
    for k, (g, e) in enumerate(zip(drawn, exact)):
        pre = prefix(k, n)
        # a length is drawn to round-off of the drawing's size (a crank of K → 1 is a hair of it)
        size_m = max(e.AC1, e.AC2, p.rocker, p.frame)
        ill = _conditioning(out.warnings, pre.rstrip("_") or "design", g.cond,
                            "the θ-circle's centre O and its cut" if p.limit_angle is None else "the ray's cut with the rocker's circle")
        for name, mm, si in (("AC1", g.AC1_mm, e.AC1), ("AC2", g.AC2_mm, e.AC2), ("lAB", g.lAB_mm, e.lAB),
                             ("lBC", g.lBC_mm, e.lBC)):
            rows.append(Row(pre + name, "m", mm, mu, mm * mu, si, abs(mm * mu - si) / size_m, ill))
        # the designed linkage re-analysed: drawn as a linkage of its own, and exactly
        A, D = g.points["A"], g.points["D"]
        lk = Linkage({"A": (A[0] * mu, A[1] * mu), "D": (D[0] * mu, D[1] * mu)},
                     Crank("1", "A", "B", g.lAB_mm * mu, 1.0),
                     (RRR("B", "C", "D", ("2", "3"), (g.lBC_mm * mu, g.lCD_mm * mu), g.branch),))
        dc = draw_characteristics(lk, mu)
        xc = fourbar(e.A, e.D, e.lAB, e.lBC, e.lCD, e.branch)
        assert dc.theta is not None and dc.psi is not None and xc.theta is not None and xc.psi is not None
        K_g = (math.pi + dc.theta) / (math.pi - dc.theta)
        K_e = xc.K or 1.0
        rows.append(Row(pre + "K", "", None, 1.0, K_g, K_e, abs(K_g - K_e) / K_e))
        for name, gv, ev in (("psi", dc.psi, xc.psi), ("gamma_min", dc.gamma_min, xc.gamma_min)):
            rows.append(Row(pre + name, "deg", None, 1.0, math.degrees(gv), math.degrees(ev),
                            abs(gv - ev) / math.pi))
        # the re-analysis against what was asked: K, and ψ or the limit angle
        if p.limit_angle is not None:
            limits = [cmath.phase((e.A - e.D) / (C - e.D)) for C in _extreme_pins(e, xc)]
            got = min(limits, key=lambda x: abs(abs(x) - p.limit_angle))  # type: ignore[operator]
            asked_err = abs(abs(got) - p.limit_angle)
            asked = "limit_angle"
        else:
            asked_err = abs(xc.psi - (p.swing or 0.0))
            asked = "psi"
        cls = fourbar_class(e.lAB, e.lBC, e.lCD, e.lAD)
        out.solutions.append({"name": pre.rstrip("_") or "design", "lAB": e.lAB, "lBC": e.lBC, "AC1": e.AC1,
                             "AC2": e.AC2, "grashof": cls, "branch": e.branch,
                             "reanalysis": {"K": K_e, "K_error": abs(K_e - p.K) / p.K,
                                            f"{asked}_error_deg": math.degrees(asked_err),
                                            "psi_deg": math.degrees(xc.psi),
                                            "gamma_min_deg": math.degrees(xc.gamma_min)}})
    wanted = set(find) or None
    out.rows.extend(r for r in rows if wanted is None or r.name in wanted)
    return out


def _analyse_guide_bar(p: GuideBar, mu: float, find: tuple[str, ...]) -> Designed:
    """The guide bar drawn and in closed form, re-analysed drawn and exact."""
    from graphmech.exact.characteristics import guide_bar
    from graphmech.exact.synthesis import guide_bar_from_K
    from graphmech.mechanisms.linkage import RPR, Crank, Linkage
    from graphmech.methods.characteristics import draw_characteristics
    from graphmech.methods.synthesis_time_ratio import draw_guide_bar
    from graphmech.problems.judging import Row

    g = draw_guide_bar(p.frame / mu, p.theta, None if p.stroke is None else p.stroke / mu)
    a, l_cd = guide_bar_from_K(p.frame, p.theta, p.stroke)
    A, C, B1, B2 = g.points["A"], g.points["C"], g.points["B1"], g.points["B2"]
    u, v = (B1[0] - C[0], B1[1] - C[1]), (B2[0] - C[0], B2[1] - C[1])
    swing = abs(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]))  # ∠B₁CB₂ on the drawing
    theta = math.degrees(p.theta)
    rows = [Row("theta", "deg", None, 1.0, math.degrees(swing), theta, abs(math.degrees(swing) - theta) / 180.0),
            Row("lAB", "m", g.lAB_mm, mu, g.lAB_mm * mu, a, abs(g.lAB_mm * mu - a) / a)]
    if g.lCD_mm is not None and l_cd is not None:
        rows.append(Row("lCD", "m", g.lCD_mm, mu, g.lCD_mm * mu, l_cd, abs(g.lCD_mm * mu - l_cd) / l_cd))
    lk = Linkage({"A": (A[0] * mu, A[1] * mu), "C": (C[0] * mu, C[1] * mu)}, Crank("1", "A", "B", g.lAB_mm * mu, 1.0),
                 (RPR("B", "C", ("2", "3"), "second"),))
    dc = draw_characteristics(lk, mu)
    xc = guide_bar(complex(0.0, p.frame), 0j, a)
    assert dc.theta is not None and dc.psi is not None and xc.theta is not None and xc.psi is not None
    K_g, K_e = (math.pi + dc.theta) / (math.pi - dc.theta), xc.K or 1.0
    rows.append(Row("K", "", None, 1.0, K_g, K_e, abs(K_g - K_e) / K_e))
    for name, gv, ev in (("psi", dc.psi, xc.psi), ("gamma_min", dc.gamma_min, xc.gamma_min)):
        rows.append(Row(name, "deg", None, 1.0, math.degrees(gv), math.degrees(ev), abs(gv - ev) / math.pi))
    solution = {"name": "design", "lAB": a, "lCD": l_cd, "grashof": xc.grashof,
                "reanalysis": {"K": K_e, "K_error": abs(K_e - p.K) / p.K, "psi_deg": math.degrees(xc.psi),
                               "psi_error_deg": abs(math.degrees(xc.psi) - theta),
                               "gamma_min_deg": math.degrees(xc.gamma_min)}}
    known = [n for n in GUIDE_NAMES if n != "lCD" or p.stroke is not None]
    wanted = set(find) or None
    return Designed([], [], [r for r in rows if wanted is None or r.name in wanted], [], [solution], known, g)


def _analyse_slider_crank(p: SliderCrank, mu: float, find: tuple[str, ...], source: str) -> Designed:
    """The slider-crank drawn and in closed form, re-analysed drawn and exact."""
    from graphmech.exact.characteristics import slider_crank
    from graphmech.exact.synthesis import slider_crank_from_K
    from graphmech.mechanisms.linkage import RRP, Crank, Guide, Linkage
    from graphmech.methods.characteristics import draw_characteristics
    from graphmech.methods.synthesis_time_ratio import draw_slider_crank
    from graphmech.problems.judging import Row

    g = draw_slider_crank(p.stroke / mu, p.offset / mu, p.theta)
    x = slider_crank_from_K(p.stroke, p.offset, p.theta)
    if g is None or x is None:
        if g is not None or x is not None:
            raise SceneError([(p.key, ("the construction and the closed forms disagree on whether there is a "
                                       "design: a limiting case — move the data off it"))], source)
        raise SceneError([(p.key, (f"no crank: no slider-crank with H = {p.stroke:g} m, e = {p.offset:g} m and "
                                         f"K = {p.K:g} (θ = {math.degrees(p.theta):.4g}°) — the offset line misses the "
                                         "θ-circle's arc behind C₁, or its crank does not turn fully (l_AB + e ≥ l_BC)"))],
                         source)
    A_e, ac1, ac2 = x
    a, b = (ac2 - ac1) / 2.0, (ac1 + ac2) / 2.0
    warnings: list[str] = []
    ill = _conditioning(warnings, "design", g.cond, "the θ-circle's cut with the offset line")
    rows = [Row("theta", "deg", None, 1.0, math.degrees(_angle_at(g.points["A"], g.points["C1"], g.points["C2"])),
                math.degrees(p.theta), abs(_angle_at(g.points["A"], g.points["C1"], g.points["C2"]) - p.theta) / math.pi)]
    for name, mm, si in (("AC1", g.AC1_mm, ac1), ("AC2", g.AC2_mm, ac2), ("lAB", g.lAB_mm, a), ("lBC", g.lBC_mm, b)):
        rows.append(Row(name, "m", mm, mu, mm * mu, si, abs(mm * mu - si) / max(ac1, ac2, p.stroke), ill))
    A = g.points["A"]
    lk = Linkage({"A": (A[0] * mu, A[1] * mu)}, Crank("1", "A", "B", g.lAB_mm * mu, 1.0),
                 (RRP("B", "C", ("2", "3"), g.lBC_mm * mu, Guide((0.0, 0.0), 0.0), "forward"),))
    dc = draw_characteristics(lk, mu)
    xc = slider_crank(A_e, 0j, 0.0, a, b, "forward")
    assert dc.theta is not None and dc.stroke_mm is not None and xc.theta is not None and xc.stroke is not None
    K_g, K_e = (math.pi + dc.theta) / (math.pi - dc.theta), xc.K or 1.0
    rows.append(Row("K", "", None, 1.0, K_g, K_e, abs(K_g - K_e) / K_e))
    rows.append(Row("stroke", "m", dc.stroke_mm, mu, dc.stroke_mm * mu, xc.stroke, abs(dc.stroke_mm * mu - xc.stroke) / xc.stroke))
    rows.append(Row("gamma_min", "deg", None, 1.0, math.degrees(dc.gamma_min), math.degrees(xc.gamma_min),
                    abs(dc.gamma_min - xc.gamma_min) / math.pi))
    solution = {"name": "design", "lAB": a, "lBC": b, "AC1": ac1, "AC2": ac2, "grashof": xc.grashof,
                "reanalysis": {"K": K_e, "K_error": abs(K_e - p.K) / p.K, "stroke": xc.stroke,
                               "stroke_error": abs(xc.stroke - p.stroke) / p.stroke,
                               "gamma_min_deg": math.degrees(xc.gamma_min)}}
    wanted = set(find) or None
    return Designed([], [], [r for r in rows if wanted is None or r.name in wanted], warnings, [solution],
                    list(SLIDER_NAMES), slider=g)


def _conditioning(warnings: list[str], design: str, cond: float, step: str) -> bool:
    """Warn where the cut that placed a design is shallow (K near 1: θ small, the θ-circle huge);
    True where its measured lengths are ill-conditioned."""
    from graphmech.problems.judging import conditioning_warning

    ill, said = conditioning_warning(design, step, cond, "AC₁, AC₂, l_AB, l_BC")
    if said:
        warnings.append(said)
    return ill


def _angle_at(A: tuple[float, float], P: tuple[float, float], Q: tuple[float, float]) -> float:
    """∠PAQ measured on the drawing, rad."""
    u, v = (P[0] - A[0], P[1] - A[1]), (Q[0] - A[0], Q[1] - A[1])
    return abs(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]))


def _extreme_pins(e: Design, xc: object) -> list[complex]:
    """The rocker pin C at the re-analysed linkage's two extremes (from the crank's angles)."""
    from graphmech.exact.characteristics import ExactCharacteristics

    assert isinstance(xc, ExactCharacteristics) and xc.phi_start is not None and xc.phi_end is not None
    out = []
    for phi in (xc.phi_start, xc.phi_end):
        B = e.A + e.lAB * cmath.exp(1j * phi)
        # C at l_BC from B and l_CD from D, on the design's branch
        bd = abs(e.D - B)
        x = (e.lBC ** 2 - e.lCD ** 2 + bd ** 2) / (2.0 * bd)
        h = math.sqrt(max(e.lBC ** 2 - x * x, 0.0))
        u = (e.D - B) / bd
        side = 1.0 if e.branch == "left" else -1.0
        out.append(B + u * (x + 1j * side * h))
    return out


def grashof_line(s: dict[str, object], p: Problem) -> str:
    """One design said under the table: its lengths, Grashof's class and the re-analysis error."""
    re = s["reanalysis"]
    assert isinstance(re, dict)
    if isinstance(p, SliderCrank):
        return (f"design: l_AB = {float(s['lAB']) * 1000:.6g} mm, l_BC = {float(s['lBC']) * 1000:.6g} mm: "  # type: ignore[arg-type]
                f"the crank turns fully (l_AB + e < l_BC); re-analysed: K = {re['K']:.12g} (error {re['K_error']:.1e}), "
                f"H = {re['stroke'] * 1000:.6g} mm (error {re['stroke_error']:.1e}), γ_min = {re['gamma_min_deg']:.6g}°")
    if isinstance(p, GuideBar):
        bar = "" if s["lCD"] is None else f", the bar l_CD = {float(s['lCD']) * 1000:.6g} mm"  # type: ignore[arg-type]
        return (f"design: l_AB = {float(s['lAB']) * 1000:.6g} mm{bar}: a swinging guide bar (l_AB < l_AC); "  # type: ignore[arg-type]
                f"re-analysed: K = {re['K']:.12g} (error {re['K_error']:.1e}), ψ = θ = {re['psi_deg']:.6g}° "
                f"(ψ {re['psi_error_deg']:.1e}° off), γ = 90° throughout")
    a, b = float(s["lAB"]), float(s["lBC"])  # type: ignore[arg-type]
    longest = max(b, p.rocker, p.frame)
    others = b + p.rocker + p.frame - longest
    what = "crank-rocker, the crank AB the Grashof crank" if s["grashof"] == "crank_rocker_AB" else str(s["grashof"])
    err = next(f"{k[:-10]} {v:.1e}°" for k, v in re.items() if k.endswith("_error_deg"))
    return (f"{s['name']}: l_AB = {a * 1000:.6g} mm, l_BC = {b * 1000:.6g} mm: {what} "
            f"({a * 1000:.4g} + {longest * 1000:.4g} < {others * 1000:.4g} mm); re-analysed: K = {re['K']:.12g} "
            f"(error {re['K_error']:.1e}), {err} off, ψ = {re['psi_deg']:.6g}°, γ_min = {re['gamma_min_deg']:.6g}°")


__all__ = [
    "K_MAX",
    "MECHANISMS",
    "SOLUTION_NAMES",
    "Designed",
    "TimeRatio",
    "analyse_time_ratio",
    "choose_scale",
    "designs",
    "grashof_line",
    "names",
    "prefix",
    "read_time_ratio",
]
