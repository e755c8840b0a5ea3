"""From a full-cycle or characteristics scene to checked values.

Like :mod:`graphmech.problems.linkage.check` for one position, this module knows about users: it chooses the
scales the scene leaves open, evaluates only what the scene shows or finds, compares each drawn
value with the exact one and words the warnings.

What can be found (``find``)
----------------------------
characteristics (from the construction of :mod:`graphmech.methods.characteristics`, checked
against the closed forms of :mod:`graphmech.exact.characteristics`)
    ``theta``, ``psi`` (a rocker's or bar's swing), ``stroke`` (a slider's H), ``K``,
    ``gamma_min``, ``gamma_min_at`` (the crank's angle there), ``phi_start``/``phi_end`` (the
    crank's angles at the extreme positions; the working stroke runs from the first), with
    ``[characteristics] t_work`` also ``phi_work``, ``phi_return``, ``t_return``,
    ``crank_period``, ``n_crank``; the Grashof ranges of the crank's length,
    ``l_AB_<class>_min`` / ``_max`` (a class met twice gets ``_2``; drawn with ``ranges = true``).
the diagrams of a cycle (graphical differentiation, against the exact kinematics)
    ``s_C@k`` (a slider's displacement from position 1), ``v_C_diagram@k.5`` (the v–φ diagram
    at the middle of interval k … k+1), ``a_C_diagram@k``; for a link ``psi_3@k`` (deg),
    ``omega_3_diagram@k.5``, ``alpha_3_diagram@k``; for any other point the same names as a
    slider's, meaning its way along its path, its speed and its tangential acceleration.
the polygons at the cycle's positions
    any quantity of a linkage scene, ``v_C@3``, ``omega_3@12`` (by :func:`graphmech.problems.linkage.check.analyse`).

Angles are reported in degrees, everything else in SI (``n_crank`` in r/min).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any, Callable, cast

import numpy as np

from graphmech.accuracy import DISCRETISATION, extrapolated, relative
from graphmech.problems.judging import Row, Verdict, in_double_precision, measured_entries
from graphmech.problems.linkage.check import analyse, judge
from graphmech.problems.linkage.sizes import characteristic, mechanism_size
from graphmech.problems.reader import linkage_of, page_size, positions_of
from graphmech.errors import SceneError, UnknownName
from graphmech.problems.cycle.scene import MAX_POLE_MM, MIN_POLE_MM
from graphmech.exact import characteristics as exact_ch
from graphmech.exact.linkage import solve as solve_exact
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage, SliderInput
from graphmech.methods.characteristics import DrawnCharacteristics, Loop, draw_characteristics, grashof_ranges
from graphmech.methods.full_cycle import (CycleDiagram, FullCycle, driver_text, evaluate_cycle, finer_positions,
                                         reversed_driver, sliders)
from graphmech.scales import DRAWN_SIZE_RANGE_MM, drawn_size_problem, format_scale, round_scale

if TYPE_CHECKING:
    from graphmech.problems.cycle.scene import CycleScene, CycleSpec
    from graphmech.problems.reader import Scene

__all__ = ["CycleAnalysis", "analyse_cycle", "judge_cycle", "CHARACTERISTICS", "nice_pole"]

#: Characteristic quantities → unit.
CHARACTERISTICS = {"theta": "deg", "psi": "deg", "stroke": "m", "K": "", "gamma_min": "deg",
                   "gamma_min_at": "deg", "phi_start": "deg", "phi_end": "deg"}
TIMING = {"phi_work": "deg", "phi_return": "deg", "t_return": "s", "crank_period": "s", "n_crank": "rpm"}
#: A swing's ends: the driver's position (φ in °, or a slider's s in m) at position 1 and at N/2 + 1;
#: and the output's swing over it (°).
SWING = ("driver_from", "driver_to", "output_swing")
#: Round pole distances a draftsman takes, mm.
POLES_MM = (5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0, 100.0)
#: The height a diagram is given when its scale or pole is chosen, mm; the φ axis's length.
DIAGRAM_MM, PHI_AXIS_MM = 30.0, 120.0
_DIAGRAM_NAME = re.compile(r"(s|psi|v|omega|a|alpha)_([A-Za-z0-9']+?)(_diagram)?")


def nice_pole(max_slope: float, height_mm: float = DIAGRAM_MM) -> float:
    """The largest round pole distance H whose derivative diagram stays within ``height_mm``.

    >>> nice_pole(1.0), nice_pole(0.01), nice_pole(100.0)
    (30.0, 100.0, 5.0)
    """
    if not max_slope > 0.0:
        return POLES_MM[-1]
    fits = [h for h in POLES_MM if h * max_slope <= height_mm * (1 + 1e-12)]
    return fits[-1] if fits else POLES_MM[0]


@dataclass
class CycleAnalysis:
    """What one full-cycle or characteristics scene produced."""

    scene: Scene[CycleScene]
    scales: dict[str, float]
    stated: set[str]
    cycle: FullCycle | None = None
    drawn: DrawnCharacteristics | None = None
    exact: exact_ch.ExactCharacteristics | None = None
    ranges: list[tuple[str, float, float]] | None = None
    ranges_exact: list[tuple[str, float, float]] | None = None
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    summary: dict[str, Any] = field(default_factory=dict)
    polygons: Any = None  # graphmech.problems.linkage.check.Analysis of the polygon quantities asked for
    polygons_back: Any = None  # … of a swing's return stroke (the driver reversed)
    extra_measured: tuple[tuple[str, float], ...] = ()
    exact_series: dict[str, dict[str, np.ndarray]] = field(default_factory=dict)  # subject → exact s, v, a
    refined: dict[tuple[str, int, bool], CycleDiagram] = field(default_factory=dict)  # the same diagram at m·N
    far: bool = False  # the mechanism lies so far from the origin that its coordinates lose its digits
    ill: set[str] = field(default_factory=set)  # characteristics whose conditioning exceeds 1e-9

    def summary_lines(self) -> list[str]:
        """What the check table does not show: the Grashof class and ranges, the diagrams' errors."""
        out = []
        ch = self.summary.get("characteristics")
        if ch and ch["loop"] == "fourbar":
            out.append(f"four-bar: {ch['grashof'].replace('_', ' ')} by Grashof's rule, "
                       f"{ch['grashof_exact'].replace('_', ' ')} by the closure of the loop")
        elif ch:
            out.append(f"{ch['loop'].replace('_', '-')}: the crank turns fully")
        if self.summary.get("grashof_ranges"):
            out.append("Grashof ranges of the crank's length:")
        for r in self.summary.get("grashof_ranges", []):
            out.append(f"  {r['class'].replace('_', ' ')}: {r['min'] * 1000:.6g} … {r['max'] * 1000:.6g} mm")
        for d in self.summary.get("diagrams", []):
            if d["max_rel_error_v"] is not None:
                out.append(f"diagrams of {d['subject']} by chords (H1 = {d['H1_mm']:g}, H2 = {d['H2_mm']:g} mm): "
                           f"largest error over the cycle {d['max_rel_error_v']:.1e} (v), {d['max_rel_error_a']:.1e} (a)")
        return out

    def scale_notes(self) -> list[str]:
        out = []
        units = {"s": "m/mm", "v": "(m/s)/mm", "a": "(m/s²)/mm", "psi": "°/mm", "omega": "(rad/s)/mm",
                 "alpha": "(rad/s²)/mm"}
        symbols = {"psi": "ψ", "omega": "ω", "alpha": "ε"}
        for k, v in self.scales.items():
            base, _, subject = k.partition("@")
            if subject:  # a diagram's own scale: μs(C), μω(3)
                shown = math.degrees(v) if base == "psi" else v
                text = f"μ{symbols.get(base, base)}({subject}) = {shown:.6g} {units[base]}"
            else:
                text = format_scale(base, v)
            out.append(text + ("" if k in self.stated else " (chosen)"))
        return out


def _kind(scene: Scene[CycleScene], name: str) -> str:
    """"char", "timing", "ranges", "diagram" or "polygon"."""
    base = name.partition("@")[0]
    if base in CHARACTERISTICS:
        return "char"
    if base in TIMING:
        return "timing"
    if base in SWING:
        return "swing"
    if base.startswith("l_") and base.endswith(("_min", "_max")) and any(
            k in base for k in ("crank_rocker", "double_crank", "double_rocker", "change_point")):
        return "ranges"
    m = _DIAGRAM_NAME.fullmatch(base)
    cy = scene.problem.cycle
    if m and cy is not None and m.group(2) in cy.diagrams:
        if m.group(1) in ("s", "psi") and m.group(3) is None:
            return "diagram"
        if m.group(1) not in ("s", "psi") and m.group(3):
            return "diagram"
    if m and (m.group(3) or (m.group(1) in ("s", "psi") and "@" in name)):
        return "no_diagram"  # a diagram's ordinate of what has no diagram in this scene
    return "polygon"


def _wants(scene: Scene[CycleScene], names: list[str]) -> dict[str, bool]:
    kinds = {_kind(scene, n) for n in names}
    show = scene.show
    return {"characteristics": "characteristics" in show or bool(kinds & {"char", "timing"})
            or (scene.problem.cycle is not None and scene.problem.cycle.start == "extreme"),
            "ranges": "ranges" in kinds,
            "cycle": scene.problem.cycle is not None and (bool({"cycle", "paths", "diagrams", "velocity", "acceleration"}
                                                             & set(show)) or "diagram" in kinds)}


def _mech_scale(scene: Scene[CycleScene], linkage: Linkage) -> float:
    """μl: stated, or a round value that fits the mechanism's sweep into about 130 mm (or 45 % of the page)."""
    if "l" in scene.scales:
        why = drawn_size_problem(mechanism_size(linkage), float(scene.scales["l"]))
        if why:
            raise SceneError([("scales", why)], scene.source)
        return float(scene.scales["l"])
    size = 2.5 * mechanism_size(linkage)  # the longest link or frame distance; the sweep is about 2.5×
    w, h = page_size(scene)
    return round_scale(size / min(0.45 * w, 0.45 * h, 130.0))


def analyse_cycle(scene: Scene[CycleScene], extra_measured: tuple[tuple[str, float], ...] = (),
                  diagram_errors: bool = True) -> CycleAnalysis:
    """Evaluate what the scene shows and finds, and check it (``diagram_errors``: with each drawn
    diagram's largest error against the exact rates over the cycle — the check's summary; a
    figure does without).

    As for one position (:func:`graphmech.problems.linkage.check.analyse`), numbers beyond double precision (ω of
    1e300 rad/s squared, a crank of 5e-324 mm) are one line, never a traceback, an inf or a NaN.
    """
    with in_double_precision("the construction"):
        return _analyse_cycle(scene, extra_measured, diagram_errors)


def _analyse_cycle(scene: Scene[CycleScene], extra_measured: tuple[tuple[str, float], ...],
                   diagram_errors: bool = True) -> CycleAnalysis:
    linkage = linkage_of(scene)
    measured = [n for _, n, _ in measured_entries(scene, extra_measured)]
    names = list(scene.find)
    wants = _wants(scene, names + measured)
    stated = {k for k in ("l", "v", "a") if k in scene.scales}
    mu_l = _mech_scale(scene, linkage)
    an = CycleAnalysis(scene, {"l": mu_l}, cast("set[str]", stated), extra_measured=tuple(extra_measured))
    if wants["characteristics"]:
        _characteristics(an, linkage, mu_l)
    if wants["ranges"] or (scene.problem.characteristics.ranges and "characteristics" in scene.show):
        from graphmech.methods.characteristics import fourbar_lengths

        try:
            L = fourbar_lengths(linkage)
        except ValueError as e:
            raise SceneError([("find", f"the Grashof ranges: {e}")], scene.source) from None
        an.ranges = grashof_ranges(L["BC"], L["CD"], L["AD"])
        an.ranges_exact = exact_ch.grashof_ranges(L["BC"], L["CD"], L["AD"])
        an.summary["grashof_ranges"] = [{"class": k, "min": lo, "max": hi} for k, lo, hi in an.ranges_exact]
    if wants["cycle"]:
        named = {m.group(2) for n in names + measured if _kind(scene, n) == "diagram"
                 for m in [_DIAGRAM_NAME.fullmatch(n.partition("@")[0])] if m}
        _cycle(an, linkage, named, diagram_errors)
    rows, problems = [], []
    poly = []
    for k, raw in enumerate(names):
        kind = _kind(scene, raw)
        try:
            if kind == "polygon":
                poly.append(raw)
            elif kind == "swing":
                rows += _swing_rows(an, raw)
            else:
                rows += _rows(an, raw, kind)
        except KeyError as e:
            problems.append((f"find[{k}]", str(e.args[0])))
    if problems:
        raise SceneError(problems, scene.source)
    poly_measured = [(n, v) for n, v in scene.measured if _kind(scene, n) == "polygon"]
    if poly or poly_measured or any(_kind(scene, n) == "polygon" for n, _ in extra_measured):
        # the polygons at the sheet's own μ, so a drawn length means the same everywhere
        same: dict[str, float] = {k: an.scales[k] for k in ("l", "v", "a") if k in an.scales}
        extra = tuple((n, v) for n, v in extra_measured if _kind(scene, n) == "polygon")
        back = _return_stroke(scene)
        if back:  # a swing: the return stroke's positions with the driver reversed, each row where it belongs
            ret = [n for n in poly if n.partition("@")[2] in back]
            fwd_names = [n for n in poly if n not in ret]
            rev = replace(scene, linkage=reversed_driver(linkage))
            parts = []
            for sc, names_, keep in ((scene, fwd_names, False), (rev, ret, True)):
                def mine(n: str, keep: bool = keep) -> bool:
                    return (n.partition("@")[2] in back) == keep
                sub = replace(sc, find=tuple(names_), show=(), measured=tuple(e for e in poly_measured if mine(e[0])),
                              scales={**scene.scales, **same})
                part = analyse(sub, tuple(e for e in extra if mine(e[0])))
                parts.append(part)
                an.warnings += [w for w in _renamed(an, part.warnings, part) if w not in an.warnings]
            an.polygons, an.polygons_back = parts
            order = {n: k for k, n in enumerate(poly)}
            rows += sorted(parts[0].rows + parts[1].rows, key=lambda r: order.get(r.name, len(order)))
        else:
            sub = replace(scene, find=tuple(poly), show=(), measured=tuple(poly_measured),
                          scales={**scene.scales, **same})
            an.polygons = analyse(sub, extra)
            an.warnings += _renamed(an, an.polygons.warnings)
            rows += an.polygons.rows
    an.rows = rows
    return an


def _return_stroke(scene: Scene[CycleScene]) -> set[str]:
    """The labels of a swing's positions that leave on the return stroke (none for a full turn)."""
    cy = scene.problem.cycle
    if cy is None or cy.between is None:
        return set()
    return {str(k) for k in range(cy.positions // 2 + 1, cy.positions + 1)}


def _swing_rows(an: CycleAnalysis, raw: str) -> list[Row]:
    """``driver_from``, ``driver_to``: the swing's ends — with ``between = "limits"`` constructed
    (:mod:`graphmech.methods.swing`) and checked against the closed forms (:mod:`graphmech.exact.swing`)."""
    from graphmech.errors import NotApplicable
    from graphmech.exact.swing import driver_limits as exact_limits
    from graphmech.exact.swing import output_swing as exact_output
    from graphmech.methods.swing import output_swing

    scene = an.scene
    base, _, at = raw.partition("@")
    swing = scene.problem.swing
    if swing is None:
        raise UnknownName(f"{base} is an end of a swing: [cycle] between = \"limits\" or between_deg = [from, to]")
    if at:
        raise UnknownName(f"{base} is a property of the whole swing: write {base!r} without @")
    linkage = linkage_of(scene)
    d = linkage.driver
    ends = swing
    if cast("CycleSpec", scene.problem.cycle).between == "limits":
        lo, hi = exact_limits(linkage, cast(float, scene.problem.stated))
        ends = (lo, hi) if swing[1] > swing[0] else (hi, lo)
    if base == "output_swing":
        try:
            g = output_swing(linkage, *swing)[0]
        except NotApplicable as why:
            raise UnknownName(f"output_swing: {why}") from None
        return [_row(an, base, "deg", math.degrees(g), math.degrees(exact_output(linkage, *ends)), None, 1.0)]
    g, e = (swing[0], ends[0]) if base == "driver_from" else (swing[1], ends[1])
    if isinstance(d, Crank):
        return [_row(an, base, "deg", math.degrees(g), math.degrees(e), None, 1.0)]
    return [_row(an, base, "m", g, e, None, 1.0)]


def _renamed(an: CycleAnalysis, warnings: list[str], part: Any = None) -> list[str]:
    """The polygons' warnings name a cycle's positions by number and angle ("position 3 (φ1 = 60°)"),
    and leave out what the cycle has said already (a polygon that cannot be drawn)."""
    from graphmech.problems.linkage.sizes import position_text

    if an.scene.problem.cycle is None:
        return list(warnings)
    build = (part or an.polygons).build
    driver = linkage_of(an.scene).driver
    said = set(an.cycle.polygon_failures) if an.cycle is not None else set()
    labels = positions_of(an.scene).labels
    prefixes = {position_text(build, lab) + ":": i for i, lab in enumerate(labels)}
    asked = {labels.index(r.name.partition("@")[2]) for r in (part or an.polygons).rows if r.name.partition("@")[2] in labels}
    out = []
    for w in warnings:
        head, sep, rest = w.partition(": ")
        i = prefixes.get(head + ":")
        if i is None:
            out.append(w)
        elif an.cycle is not None and rest.startswith(("shallow intersection", "ill-conditioned intersection")) \
                and (i not in asked or rest.startswith("shallow")):
            continue  # the cycle's one-line summary says it for every position
        elif not (i in said and rest.startswith("construction impossible")):
            out.append(f"position {i + 1} ({driver_text(driver, positions_of(an.scene).values[i])}): {rest}")
    return out


def _characteristics(an: CycleAnalysis, linkage: Linkage, mu_l: float) -> None:
    try:
        an.drawn = draw_characteristics(linkage, mu_l)
    except ValueError as e:
        raise SceneError([("characteristics", str(e))], an.scene.source) from None
    except (ZeroDivisionError, OverflowError):
        # a crank of 26 mm beside a frame of 1e300 mm: their squares leave double precision
        crank = cast(Crank, linkage.driver).length  # a cycle's driver is a crank (its reader refuses a slider)
        raise SceneError([("characteristics", f"the crank ({crank:.3g} m) is {crank / mechanism_size(linkage):.2g} "
                           "of the mechanism's size: too small beside it to be constructed on one drawing")],
                         an.scene.source) from None
    loop = an.drawn.loop
    n = loop.names
    # A guide's point 2⁶⁴ mm from the crank draws a guide no page can hold (and hatching it never ends).
    xs = [c for p in an.drawn.points.values() for c in p]
    extent = max(xs) - min(xs)
    if not extent <= DRAWN_SIZE_RANGE_MM[1]:
        where, fix = (("dyad[0].guide.through", "put the guide's point near the crank") if loop.kind == "slider_crank"
                      else ("scales", "choose a larger μl"))
        raise SceneError([(where, f"the extreme positions' drawing runs {extent:.3g} mm across at μl = {mu_l:g} m/mm: "
                                  f"more than a page can show (at most {DRAWN_SIZE_RANGE_MM[1]:g} mm); {fix}")],
                         an.scene.source)
    from graphmech.problems.linkage.sizes import offset_warning, refuse_far_from_origin

    size = mechanism_size(linkage)
    refuse_far_from_origin(an.scene, linkage, size)
    far = offset_warning(linkage, size)
    if far:  # the characteristics' rows carry as few digits as the coordinates leave
        an.warnings.append(far)
        an.far = True
    A = complex(*linkage.frame_points[n["A"]])

    def closed_form(a: float, b: float, c: float) -> exact_ch.ExactCharacteristics:
        if loop.kind == "fourbar":
            D = complex(*linkage.frame_points[n["D"]])
            y = cast(RRR, linkage.dyads[0])  # a hinged four-bar's dyad
            branch = y.branch if getattr(y, "q", None) == n["D"] else ("right" if y.branch == "left" else "left")
            return exact_ch.fourbar(A, D, a, b, c, branch, loop.sense)
        if loop.kind == "slider_crank":
            s = cast(RRP, linkage.dyads[0])  # a slider-crank's dyad, on a frame guide
            assert isinstance(s.guide, Guide)
            return exact_ch.slider_crank(A, complex(*s.guide.through), s.guide.angle, a, b, s.branch, loop.sense)
        return exact_ch.guide_bar(A, complex(*linkage.frame_points[n["C"]]), a, loop.sense, b)  # b: the offset e

    an.exact = closed_form(loop.a, loop.b, loop.c)
    _characteristics_conditioning(an, loop, closed_form)
    if loop.kind == "fourbar":
        L = [loop.a, loop.b, loop.c, abs(complex(*linkage.frame_points[n["D"]]) - A)]
        exact_class = exact_ch.fourbar_class(*L)
        if exact_class != an.drawn.grashof:
            an.warnings.append(f"Grashof's rule says {an.drawn.grashof}, the closure of the loop {exact_class}")
        if an.drawn.grashof == "change_point":
            an.warnings.append("change point: s + l = p + q (Grashof's equality) — the links can all lie on one "
                               "line, where the output's motion is undetermined")
    an.summary["characteristics"] = {"loop": loop.kind, "grashof": an.drawn.grashof,
                                     "grashof_exact": an.exact.grashof if loop.kind != "fourbar" else exact_class}


#: The relative change of one length by which the characteristics' sensitivity to it is measured.
_NUDGE = 1e-12


def _characteristics_conditioning(an: CycleAnalysis, loop: Loop,
                                  closed_form: Callable[[float, float, float], exact_ch.ExactCharacteristics]) -> None:
    """Name the characteristics that the last bit of a length moves by more than 1e-9.

    Each value's condition number κ = |Δv/v| / |Δl/l| is measured on the closed form with one
    length (crank, coupler, rocker) nudged by 1e-12 of itself; a value with COND_SAFETY·κ·EPS
    above 1e-9 (K of a guide bar with AB/AC = 1 − 1e-9: the extremes 0.005° from a dead point)
    cannot be checked to 1e-9 by any method: its row is marked and one line says why.
    """
    from graphmech import tolerances as T

    base = {k: v[1] for k, v in _ch_values(an)[0].items()}
    exact = an.exact
    kappa = dict.fromkeys(base, 0.0)
    lengths = [loop.a, loop.b, loop.c]
    for k, length in enumerate(lengths):
        if length == 0.0:
            continue
        for sign in (1.0, -1.0):
            nudged = list(lengths)
            nudged[k] = length * (1.0 + sign * _NUDGE)
            try:
                an.exact = closed_form(*nudged)
                moved = _ch_values(an)[0]
            except ValueError:  # a bit further and the crank no longer turns: as ill-conditioned as can be
                moved = {}
            finally:
                an.exact = exact
            for name, v in base.items():
                if name not in moved or moved[name][1] is None:  # no longer defined a bit further on
                    kappa[name] = math.inf
                    continue
                w = moved[name][1]
                rel = abs(((w - v + 180.0) % 360.0 - 180.0) / 360.0 if CHARACTERISTICS.get(name, TIMING.get(name)) == "deg"
                          else (w - v) / max(abs(v), 1e-300))
                kappa[name] = max(kappa[name], rel / _NUDGE)
    bad = {name: c for name, c in kappa.items() if T.COND_SAFETY * c * T.EPS > T.REL_AGREEMENT}
    if bad:
        an.ill = set(bad)
        worst = max(bad, key=lambda k: bad[k])
        names = ", ".join(f"{k} = {base[k]:.6g}" for k in bad)
        how = ("changes the linkage's type (the crank no longer turns)" if math.isinf(bad[worst]) else
               f"moves {worst} by {bad[worst] * T.EPS:.1g} relative (condition number {bad[worst]:.2g})")
        an.warnings.append(f"ill-conditioned characteristics: {names}; the last bit of a link's length {how}, so no "
                           "method can give them to 1e-9")


def _cycle(an: CycleAnalysis, linkage: Linkage, named: set[str], diagram_errors: bool = True) -> None:
    scene = an.scene
    k: int | str
    mu: str | float
    spec = cast("CycleSpec", scene.problem.cycle)  # analysed as a cycle: the scene has [cycle]
    angles = np.asarray(positions_of(scene).values, dtype=float)
    d = linkage.driver
    polygons = [p for p in ("velocity", "acceleration") if p in scene.show]
    back = _return_stroke(scene)
    backward = np.array([lab in back for lab in positions_of(scene).labels]) if back else None
    # the diagrams shown, or only those a value is asked of
    subjects = [s for s in spec.diagrams if "diagrams" in scene.show or s in named]
    mu_phi = spec.scales.get("phi", math.radians(round_scale(360.0 / PHI_AXIS_MM)))
    if "phi" in spec.scales:
        an.stated.add("phi")
    scales = {"l": an.scales["l"], "v": 1.0, "a": 1.0}
    links = linkage.links()  # a link's diagram is of its angle (μψ); a point's of a length (μs)
    derived = {s: ("omega", "epsilon") if s in links else ("v", "a") for s in subjects}  # μ that fix H₁, H₂
    stated_all = (all(k in scene.scales for k in ("v" if p == "velocity" else "a" for p in polygons))
                  and all(("psi" if s in links else "s") in spec.scales for s in subjects)
                  and (spec.pole_distance_mm is not None
                       or all(k in spec.scales for s in subjects for k in derived[s])))
    if stated_all:  # nothing to choose: no provisional pass
        for key in ("v", "a"):
            if key in scene.scales:
                scales[key] = float(scene.scales[key])
        mu_s = {s: spec.scales["psi" if s in links else "s"] for s in subjects}
        H = spec.pole_distance_mm or (20.0, 20.0)
    elif polygons or subjects:  # a provisional pass at μ = 1 gives every extent in real units
        probe = evaluate_cycle(linkage, scales, angles, polygons=polygons, diagrams=subjects, mu_phi=mu_phi, backward=backward,
                               mu_s={s: 1.0 for s in subjects}, H_mm=(1.0, 1.0))
        w, h = page_size(scene)
        room = min(0.4 * w, 0.4 * h, 110.0)
        for key, images in (("v", probe.vel), ("a", probe.acc)):
            if key in scene.scales:
                scales[key] = float(scene.scales[key])
            elif images:
                pts = np.concatenate(list(images.values()))
                ext = float(np.max(pts.max(axis=0) - pts.min(axis=0)))
                scales[key] = round_scale(ext / room) if ext > 0 else 1.0
        mu_s = {}
        for dg in probe.diagrams:
            key = "psi" if dg.subject in links else "s"
            if key in spec.scales:
                mu_s[dg.subject] = spec.scales[key]
            else:
                ext = float(np.max(np.abs(dg.s_mm)))  # real units at μ = 1
                mu_s[dg.subject] = (round_scale(ext / DIAGRAM_MM) if key == "s" else
                                    math.radians(round_scale(math.degrees(ext) / DIAGRAM_MM))) if ext > 0 else 1.0
        probe2 = evaluate_cycle(linkage, scales, angles, diagrams=subjects, mu_phi=mu_phi, mu_s=mu_s,
                                H_mm=(1.0, 1.0)) if subjects else None
        if spec.pole_distance_mm is not None:
            H = spec.pole_distance_mm
        elif probe2 is not None:
            h1 = min(nice_pole(float(np.max(np.abs(g.velocity.derivative_mm)))) for g in probe2.diagrams)
            h2 = min(nice_pole(float(np.max(np.abs(g.acceleration.derivative_mm))) * h1) for g in probe2.diagrams)
            H = (h1, h2)
        else:
            H = (20.0, 20.0)
    else:
        mu_s, H = {}, (20.0, 20.0)
    # a stated μv (μω) fixes H₁ = μs·ω₁/(μφ·μv), a stated μa (με) H₂ = μv·ω₁/(μφ·μa)
    w = abs(d.omega) if isinstance(d, Crank) else abs(d.velocity)
    poles: dict[str, tuple[float, float]] = {}
    for subj in subjects:
        kv, ka = derived[subj]
        h1 = mu_s[subj] * w / (mu_phi * spec.scales[kv]) if kv in spec.scales else H[0]
        mu_v = mu_s[subj] * w / (mu_phi * h1)
        h2 = mu_v * w / (mu_phi * spec.scales[ka]) if ka in spec.scales else H[1]
        poles[subj] = (h1, h2)
        for k, h, mu in ((1, h1, kv), (2, h2, ka)):  # a stated μv, μa far off the diagram's own puts P off the page
            if mu in spec.scales and not MIN_POLE_MM <= h <= MAX_POLE_MM:
                raise SceneError([("cycle.scales", f"μ{mu} of {subj}'s diagram puts its pole P{k} at H{k} = {h:.3g} mm "
                                                   f"({MIN_POLE_MM:g} … {MAX_POLE_MM:g} mm): choose "
                                                   f"{'a larger' if h > MAX_POLE_MM else 'a smaller'} μ{mu}")],
                                 scene.source)
        # what s–φ (ψ–φ) can reach: the mechanism's size, a few turns; a μs that draws it off any page
        reach = 4.0 * mechanism_size(linkage) if subj not in links else 4.0 * math.pi
        if not reach / mu_s[subj] <= DRAWN_SIZE_RANGE_MM[1]:
            key = "psi" if subj in links else "s"
            raise SceneError([("cycle.scales", f"μ{key} = {mu_s[subj]:g} draws the diagram of {subj} up to "
                                               f"{reach / mu_s[subj]:.3g} mm high: more than a page can show "
                                               f"(at most {DRAWN_SIZE_RANGE_MM[1]:g} mm)")], scene.source)
    paths = spec.paths if ("paths" in scene.show) else ()
    an.cycle = evaluate_cycle(linkage, scales, angles, polygons=polygons, diagrams=subjects, mu_phi=mu_phi, backward=backward,
                              mu_s=mu_s, H_mm=poles, paths=paths)
    for k in polygons:
        an.scales["v" if k == "velocity" else "a"] = scales["v" if k == "velocity" else "a"]
    if subjects:
        an.scales["phi"] = mu_phi
        an.summary["diagrams"] = []
    for dg in an.cycle.diagrams:
        key = "psi" if dg.kind == "link" else "s"
        names = ("s", "v", "a") if key == "s" else ("psi", "omega", "alpha")
        for name, mu in zip(names, (dg.mu_s, dg.mu_v, dg.mu_a)):
            an.scales[f"{name}@{dg.subject}"] = mu
        if key in spec.scales:
            an.stated.add(f"{key}@{dg.subject}")
            if spec.pole_distance_mm is not None and "phi" in spec.scales:  # μv, μa follow from what is stated
                an.stated.update(f"{name}@{dg.subject}" for name in names[1:])
        an.stated.update(f"{name}@{dg.subject}" for name, k in zip(names[1:], derived[dg.subject]) if k in spec.scales)
        errs = _diagram_errors(an, dg) if diagram_errors else {}
        an.summary["diagrams"].append({"subject": dg.subject, "kind": dg.kind, "H1_mm": dg.velocity.H_mm,
                                       "H2_mm": dg.acceleration.H_mm,
                                       "mu_s": dg.mu_s, "mu_v": dg.mu_v, "mu_a": dg.mu_a, **errs})
    if spec.between is not None:  # a swing: its ends, as the driver's own coordinate
        unit, conv = ("deg", math.degrees) if isinstance(d, Crank) else ("m", float)
        an.summary["swing"] = {"from": conv(float(angles[0])), "to": conv(float(angles[angles.size // 2])), "unit": unit,
                               "limits": spec.between == "limits"}
    an.summary["cycle"] = {"positions": int(angles.size), "start_deg": math.degrees(float(angles[0])),
                           "start": spec.start}
    an.warnings += _cycle_warnings(an.cycle, d)


def _positions_text(idx: Any, most: int = 12) -> str:
    idx = [int(i) + 1 for i in idx]
    return ", ".join(map(str, idx[:most])) + (f" … ({len(idx)} positions)" if len(idx) > most else "")


def _cycle_warnings(cyc: FullCycle, driver: Crank | SliderInput) -> list[str]:
    """A polygon left out, and the positions where an intersection is ill-conditioned or shallow —
    one line each, however many positions (N may be 3600)."""
    from graphmech import tolerances as T

    out = []
    for i, why in sorted(cyc.polygon_failures.items())[:12]:
        out.append(f"position {i + 1} ({driver_text(driver, float(cyc.angles[i]))}): no polygon — {why} "
                   + ("(an end of the swing: the dyad toggles there, so the driver must stop)" if cyc.swing else
                      "(a change point: the output's motion is undetermined there)"))
    if len(cyc.polygon_failures) > 12:
        out.append(f"… and {len(cyc.polygon_failures) - 12} more positions without a polygon")
    if not cyc.conds:
        return out
    texts = list(cyc.conds)
    c = np.stack([np.asarray(cyc.conds[t], dtype=float) for t in texts])
    c[:, sorted(cyc.polygon_failures)] = 0.0
    worst = c.max(axis=0)
    shallow = 1.0 / math.sin(math.radians(T.SHALLOW_DEG))
    for limit, what in ((T.COND_WARN, "ill-conditioned"), (shallow, "shallow")):
        hit = np.flatnonzero(worst > limit) if what == "ill-conditioned" else \
            np.flatnonzero((worst > shallow) & (worst <= T.COND_WARN))
        if hit.size:
            j = int(hit[np.argmax(worst[hit])])
            step = texts[int(np.argmax(c[:, j]))]
            angle = math.degrees(math.asin(min(1.0, 1.0 / worst[j])))
            tail = ("values drawn there may be wrong by far more than 1e-9" if what == "ill-conditioned" else
                    "a hand construction is unreliable there")
            out.append(f"{what} intersections at positions {_positions_text(hit)}; the worst, '{step}' at position "
                       f"{j + 1}, meets at {angle:.3g}°: {tail}")
    return out


def _exact_series(an: CycleAnalysis, subject: str) -> dict[str, np.ndarray]:
    """The exact s, v, a of a diagram's subject at the positions (s, a) and middles (v)."""
    cache = an.exact_series
    if subject in cache:
        return cache[subject]
    linkage = linkage_of(an.scene)
    cyc = an.cycle
    assert cyc is not None
    n = cyc.n
    mids = cyc.angles + cyc.sense * math.pi / n
    at, mid = solve_exact(linkage, cyc.angles), solve_exact(linkage, mids)
    slide = sliders(linkage)
    if subject in slide:
        g = np.array(slide[subject])
        s = (at.point[subject] - at.point[subject][0]) @ g
        out = {"s": s, "v": mid.vel[subject] @ g, "a": at.acc[subject] @ g, "valid": at.valid & mid.valid}
    elif subject not in linkage.links():  # a point's path: arc length, speed, tangential acceleration
        out = _exact_path(linkage, subject, cyc.angles, cyc.sense, at, mid)
    else:
        th = at.angle[subject]
        out = {"s": np.unwrap(th - th[0]), "v": mid.omega[subject], "a": at.alpha[subject],
               "valid": at.valid & mid.valid}
    cache[subject] = out
    return out


#: Gauss–Legendre nodes per interval for the exact arc length of a path.
ARC_NODES = 20


def _exact_path(linkage: Linkage, point: str, angles: np.ndarray, sense: float, at: Any, mid: Any) -> dict[str, Any]:
    """The exact way along a point's path from position 1 (∫|v|dt by Gauss–Legendre, 20 nodes per
    interval), its speed at the interval middles and its tangential acceleration v·a/|v| at the
    positions (undefined where it stops: a cusp)."""
    d = linkage.driver
    n = angles.size
    step = 2.0 * math.pi / n
    t, wts = np.polynomial.legendre.leggauss(ARC_NODES)
    nodes = (angles[:, None] + sense * step * (t[None, :] + 1.0) / 2.0).ravel()
    q = solve_exact(linkage, nodes)
    speed = np.hypot(*q.vel[point].T).reshape(n, ARC_NODES)
    # ds/dφ = |v|/|ω1|; each interval is Δφ long
    piece = (speed @ wts) * (step / 2.0) / abs(cast("Crank", d).omega)
    s = np.concatenate([[0.0], np.cumsum(piece[:-1])])
    v = np.hypot(*mid.vel[point].T)
    V, A = at.vel[point], at.acc[point]
    vs = np.hypot(*V.T)
    moving = vs > 1e-9 * abs(cast("Crank", d).omega) * max(math.hypot(*p) for p in (at.point[point][0], (1e-300, 0.0)))
    a = np.where(moving, np.einsum("ij,ij->i", V, A) / np.where(moving, vs, 1.0), 0.0)
    valid = at.valid & mid.valid & moving & q.valid.reshape(n, ARC_NODES).all(axis=1)
    return {"s": s, "v": v, "a": a, "valid": valid}


def _diagram_errors(an: CycleAnalysis, dg: Any) -> dict[str, float | None]:
    ex = _exact_series(an, dg.subject)
    linkage = linkage_of(an.scene)
    unit_v, unit_a = ("rad/s", "rad/s²") if dg.kind == "link" else ("m/s", "m/s²")
    size = mechanism_size(linkage)
    v = dg.velocity.derivative_mm * dg.mu_v
    a = dg.a_mm * dg.mu_a
    cv, ca = characteristic(linkage, unit_v, size), characteristic(linkage, unit_a, size)
    ok = ex["valid"]  # where the exact rates exist (not at a change point)
    if not ok.any():
        return {"max_rel_error_v": None, "max_rel_error_a": None}
    return {"max_rel_error_v": float(np.max((np.abs(v - ex["v"]) / np.maximum(np.abs(ex["v"]), cv))[ok])),
            "max_rel_error_a": float(np.max((np.abs(a - ex["a"]) / np.maximum(np.abs(ex["a"]), ca))[ok]))}


def _ch_values(an: CycleAnalysis) -> tuple[dict[str, tuple[float, float, float | None]], dict[str, str]]:
    """name → (graphical, exact, drawn mm or None), and units, for the characteristics."""
    dr, ex = an.drawn, an.exact
    assert dr is not None and ex is not None
    out: dict[str, tuple[float, float, float | None]] = {
        "gamma_min": (math.degrees(dr.gamma_min), math.degrees(ex.gamma_min), None),
        "gamma_min_at": (math.degrees(dr.gamma_min_at), math.degrees(ex.gamma_min_at), None),
    }
    if (dr.theta is None or ex.theta is None  # the output turns fully: no extreme positions
            or dr.phi_start is None or dr.phi_end is None or ex.phi_start is None or ex.phi_end is None):
        return out, {**CHARACTERISTICS, **TIMING}
    out.update({
        "theta": (math.degrees(dr.theta), math.degrees(ex.theta), None),
        "K": (exact_ch.time_ratio(dr.theta), exact_ch.time_ratio(ex.theta), None),
        "phi_start": (math.degrees(dr.phi_start), math.degrees(ex.phi_start), None),
        "phi_end": (math.degrees(dr.phi_end), math.degrees(ex.phi_end), None),
    })
    if dr.psi is not None and ex.psi is not None:
        out["psi"] = (math.degrees(dr.psi), math.degrees(ex.psi), None)
    if dr.stroke_mm is not None and ex.stroke is not None:
        out["stroke"] = (dr.stroke_mm * dr.mu_l, ex.stroke, dr.stroke_mm)
    t_work = an.scene.problem.characteristics.t_work
    if t_work is not None:
        g, e = exact_ch.timing(dr.theta, t_work), exact_ch.timing(ex.theta, t_work)
        for k in TIMING:
            conv = math.degrees if k.startswith("phi") else float
            out[k] = (conv(g[k]), conv(e[k]), None)
    return out, {**CHARACTERISTICS, **TIMING}


def _rows(an: CycleAnalysis, raw: str, kind: str) -> list[Row]:
    scene = an.scene
    drawn: float | np.ndarray | None
    base, _, at = raw.partition("@")
    if kind in ("char", "timing"):
        if at:
            raise UnknownName(f"{base} is a property of the whole cycle: write {base!r} without @")
        values, units = _ch_values(an)
        if base not in values:
            dr = an.drawn
            assert dr is not None
            if dr.theta is None:
                why = (f"{base}: no extreme positions — the output turns fully too "
                       f"({dr.grashof.replace('_', ' ')})")
            elif kind == "timing":
                why = "the timing needs [characteristics] t_work"
            else:
                why = f"{base} is not a characteristic of a {dr.loop.kind.replace('_', '-')}"
            raise UnknownName(why)
        g, e, drawn = values[base]
        unit = units[base]
        return [_row(an, base, unit, g, e, drawn, an.scales["l"] if drawn is not None else 1.0)]
    if kind == "no_diagram":
        subject = cast("re.Match[str]", _DIAGRAM_NAME.fullmatch(base)).group(2)  # _kind matched it
        if scene.problem.cycle is None:
            raise UnknownName(f"{base} is read off a diagram of the full cycle: add a [cycle] table with "
                           f"diagrams = [{subject!r}]".replace("'", '"'))
        raise UnknownName(f"{base} is read off the diagram of {subject}: add {subject} to [cycle] diagrams")
    if kind == "ranges":
        if an.ranges is None or an.ranges_exact is None:
            raise UnknownName(f"{base}: the Grashof ranges need [characteristics] ranges = true")
        names = _range_names(an.ranges, linkage_of(scene))
        names_exact = _range_names(an.ranges_exact, linkage_of(scene))
        if base not in names or base not in names_exact:
            raise UnknownName(f"unknown Grashof range limit {base!r}; the ranges give "
                           f"{', '.join(sorted(names))}")
        return [_row(an, base, "m", names[base], names_exact[base], None, 1.0)]
    # a diagram's value
    m = _DIAGRAM_NAME.fullmatch(base)
    assert m is not None and an.cycle is not None
    what, subject = m.group(1), m.group(2)
    dg = next(g for g in an.cycle.diagrams if g.subject == subject)
    if (what in ("s", "v", "a")) != (dg.kind != "link"):
        raise UnknownName(f"{base}: {subject} is a {'link' if dg.kind == 'link' else 'point'}; write "
                       + ("psi_, omega_…_diagram, alpha_…_diagram" if dg.kind == "link" else "s_, v_…_diagram, a_…_diagram"))
    n = an.cycle.n
    mid = what in ("v", "omega")
    labels = [f"{k}.5" for k in range(1, n + 1)] if mid else [str(k) for k in range(1, n + 1)]
    if at and at not in labels:
        raise UnknownName(f"no {'interval middle' if mid else 'position'} {at!r} "
                       f"({labels[0]} … {labels[-1]})")
    idx = [labels.index(at)] if at else range(n)
    ex = _exact_series(an, subject)
    unit = {"s": "m", "v": "m/s", "a": "m/s²", "psi": "deg", "omega": "rad/s", "alpha": "rad/s²"}[what]
    if what in ("s", "psi"):
        drawn, mu, exact = dg.s_mm, dg.mu_s, ex["s"]
    elif mid:
        drawn, mu, exact = dg.velocity.derivative_mm, dg.mu_v, ex["v"]
    else:
        drawn, mu, exact = dg.a_mm, dg.mu_a, ex["a"]
    out = []
    for i in idx:
        if not ex["valid"][i]:
            an.warnings.append(f"{base}@{labels[i]}: the exact value is undefined there (a change point); "
                               "not checked")
            continue
        g, e = float(drawn[i] * mu), float(exact[i])
        if unit == "deg":
            g, e = math.degrees(g), math.degrees(e)
        row = _row(an, f"{base}@{labels[i]}", unit, g, e, float(drawn[i]), mu if unit != "deg" else math.degrees(mu))
        if what in ("v", "omega", "a", "alpha") or dg.kind == "path":  # chords: an error of order Δφ²
            out.append(row.estimated(DISCRETISATION, _chord_estimate(an, dg, what, i, g), f"{n} positions"))
        else:  # s or ψ read off the kinematic diagram at the position: a construction
            out.append(row)
    return out


def _diagram_at(an: CycleAnalysis, dg: CycleDiagram, m: int, mid: bool) -> CycleDiagram:
    """The same diagram drawn by the same chords over m·N positions, placed so that every one of
    the N positions (``mid``: every middle of the N intervals) is one of its own."""
    key = (dg.subject, m, mid)
    if key not in an.refined:
        cyc = an.cycle
        assert cyc is not None
        fine = evaluate_cycle(linkage_of(an.scene), {"l": an.scales["l"], "v": 1.0, "a": 1.0},
                              finer_positions(float(cyc.angles[0]), cyc.n, cyc.sense, m, mid), diagrams=[dg.subject],
                              mu_phi=cyc.mu_phi, mu_s={dg.subject: dg.mu_s},
                              H_mm=(dg.velocity.H_mm, dg.acceleration.H_mm))
        an.refined[key] = fine.diagrams[0]
    return an.refined[key]


def _chord_estimate(an: CycleAnalysis, dg: CycleDiagram, what: str, i: int, g: float) -> float:
    """The relative error of a value the chords give over N positions, as the chords themselves tell
    it: the same value over 2N and 4N positions, extrapolated (Richardson, order 2: a chord's slope
    is the curve's at its middle to Δφ²), against the one over N."""
    mid = what in ("v", "omega")
    vals = []
    for m in (2, 4):
        f = _diagram_at(an, dg, m, mid)
        if what == "s":  # a point's way along its path
            vals.append(float(f.s_mm[m * i] * f.mu_s))
        elif mid:
            vals.append(float(f.velocity.derivative_mm[m * i] * f.mu_v))
        else:
            vals.append(float(f.a_mm[m * i] * f.mu_a))
    limit = extrapolated(*cast("tuple[float, float]", vals), order=2)  # the values at 2N and 4N
    unit = {"s": "m", "v": "m/s", "a": "m/s²", "omega": "rad/s", "alpha": "rad/s²"}[what]
    linkage = linkage_of(an.scene)
    return relative(abs(g - limit), max(abs(limit), characteristic(linkage, unit, mechanism_size(linkage))))


def _range_names(ranges: list[tuple[str, float, float]], linkage: Linkage) -> dict[str, float]:
    """``l_AB_crank_rocker_max`` → 0.015 …; a class met a second time is ``double_rocker_2``."""
    from graphmech.methods.characteristics import basic_loop

    loop = basic_loop(linkage)
    crank = f"l_{loop.names['A']}{loop.names['B']}"
    seen: dict[str, int] = {}
    out: dict[str, float] = {}
    for k, lo, hi in ranges:
        seen[k] = seen.get(k, 0) + 1
        key = f"{crank}_{k}" + (f"_{seen[k]}" if seen[k] > 1 else "")
        if lo > 0.0:
            out[key + "_min"] = lo
        out[key + "_max"] = hi
    return out


def _row(an: CycleAnalysis, name: str, unit: str, g: float, e: float, drawn: float | None, scale: float) -> Row:
    if unit == "deg":
        err = abs((g - e + 180.0) % 360.0 - 180.0) / 360.0
    elif unit in ("", "s", "rpm"):
        err = abs(g - e) / max(abs(e), 1e-300)
    else:
        linkage = linkage_of(an.scene)
        err = abs(g - e) / max(abs(e), characteristic(linkage, unit, mechanism_size(linkage)))
    return Row(name, unit, drawn, scale, g, e, err, an.far or name in an.ill)


def judge_cycle(an: CycleAnalysis, precision_mm: float | None = None) -> list[Verdict]:
    """Hand readings: the polygons' quantities as in a linkage scene; θ, ψ, γ_min read with a
    protractor on arms of the drawn length (± precision/arm on each arm), the stroke at μl, K from θ;
    a diagram's ordinate (``v_C_diagram@3.5``) against the same chords drawn here, ± precision at
    the diagram's μ (the chords' own discretisation is the method's, not the student's)."""
    scene = an.scene
    prec = precision_mm if precision_mm is not None else scene.precision_mm
    out: list[Verdict] = []
    problems = []
    for key, name, value in measured_entries(scene, an.extra_measured):
        kind = _kind(scene, name)
        if kind == "polygon":
            continue
        if kind == "diagram":  # a hand diagram by chords against these chords, ± precision at its μ
            if "@" not in name:
                problems.append((key, f"{name!r}: name the position, e.g. {name}@3"))
                continue
            try:
                row = _rows(an, name, "diagram")[0]
            except KeyError as e:
                problems.append((key, str(e.args[0])))
                continue
            tol = prec * row.scale
            out.append(Verdict(name, value, row.graphical, tol, abs(value - row.graphical) <= tol + 1e-12 * abs(value),
                               row.unit))
            continue
        if kind != "char" or an.drawn is None:
            problems.append((key, f"{name!r} cannot be judged here: measure the characteristics (theta, psi, "
                                  "stroke, K, gamma_min) or the polygons' quantities"))
            continue
        values, units = _ch_values(an)
        if name not in values or name in ("gamma_min_at", "phi_start", "phi_end"):
            problems.append((key, f"{name!r} cannot be judged here"))
            continue
        g, exact_v, drawn = values[name]
        p = an.drawn.points
        A = p["A"]
        arm = min(math.dist(A, p["C1"]), math.dist(A, p["C2"])) if name in ("theta", "K") else (
            math.dist(p["Cg"], p["Bg"]) if name == "gamma_min" else
            math.dist(p.get("D", p.get("C", A)), p["C1" if "D" in p else "B1"]))
        tol_rad = 2.0 * prec / max(arm, prec)
        if name == "stroke":
            tol = 2.0 * prec * an.drawn.mu_l
        elif name == "K":
            th = cast("exact_ch.ExactCharacteristics", an.exact).theta  # _ch_values above needs it
            tol = 2.0 * math.pi / (math.pi - cast(float, th)) ** 2 * tol_rad
        else:
            tol = math.degrees(tol_rad)
        out.append(Verdict(name, value, exact_v, tol, abs(value - exact_v) <= tol, units[name]))
    if problems:
        raise SceneError(problems, scene.source)
    if an.polygons is not None:
        out = judge(an.polygons, precision_mm) + (judge(an.polygons_back, precision_mm) if an.polygons_back else []) + out
    return out
