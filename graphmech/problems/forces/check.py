"""From a force scene to checked values: kinematics, inertia loads, group-by-group force
polygons, the matrix method and Zhukovsky's lever, compared row by row.

The kinematics are the linkage scene's own (:func:`graphmech.problems.linkage.check.analyse`: the velocity and
acceleration polygons, checked against the closed form). The force polygons
(:mod:`graphmech.methods.kinetostatics`) take their accelerations from those polygons; the matrix
method (:mod:`graphmech.exact.kinetostatics`) takes them from the closed form and solves every
reaction at once. Each row of the table is a value read off a force polygon (drawn length × μF)
against the matrix method's; ``M_b_lever`` is Zhukovsky's lever against the matrix method.

Only what the scene asks for is computed: no polygons kept unless they are drawn, no lever
unless ``M_b_lever`` is asked or the lever is drawn, no successive approximation without friction.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, cast

import numpy as np

from graphmech.accuracy import DISCRETISATION, relative
from graphmech.problems.linkage.check import Analysis, analyse, judge
from graphmech.problems.judging import Row, Verdict, split_name
from graphmech.problems.reader import page_size, positions_of
from graphmech.problems.linkage.sizes import position_text
from graphmech.errors import DegenerateConstruction, SceneError
from graphmech.exact.kinetostatics import ExactForces, solve_forces
from graphmech.mechanisms.linkage import PRP, Guide, LinkGuide
from graphmech.methods.kinetostatics import (
    SHALLOW_SIN,
    GuideReaction,
    KinetostaticSolution,
    Lever,
    PolygonKinematics,
    construction_targets,
    iteration_error,
    kinematics_from_construction,
    kinetostatics,
    zhukovsky_lever,
)
from graphmech.scales import round_scale, round_scale_below
from graphmech.tolerances import COND_WARN

if TYPE_CHECKING:
    from graphmech.drawing.primitives import Panel, Sheet
    from graphmech.mechanisms.linkage import Crank, SliderInput
    from graphmech.methods.polygons import LinkageConstruction
    from graphmech.mechanisms.linkage import Positions
    from graphmech.problems.forces.scene import ForceScene
    from graphmech.problems.reader import Scene

#: The force quantities a scene may ask for (links are one character: R_12, F_i2, h_2).
FORCE_NAME = re.compile(
    r"(?:M_b|M_b_lever|M_b0|F_b|F_b_lever|F_b0|eta|F_i(?P<fi>\w)(?P<fic>_x|_y)?|M_i(?P<mi>\w)|h_(?P<h>\w)"
    r"|R_(?P<ri>\w)(?P<rj>\w)(?P<rc>_x|_y)?|(?P<gm>M|e)_(?P<gi>\w)(?P<gj>\w))")
#: Room for the largest force polygon, mm (μF is chosen so that it fits).
POLYGON_ROOM_MM = 70.0
#: The lengths a stated μF may draw the largest force at (mm): outside, the scale is absurd.
POLYGON_RANGE_MM = (1.0, 1e5)
#: The largest force a drawn polygon is laid out with, N: a side's length is √(Fx² + Fy²) and the
#: page's geometry squares lengths again, so beyond ≈ 1e154 N double precision overflows to inf (and
#: the sides to NaN). 1e152 keeps a margin; forces that large come only from absurd data. The check
#: table alone stays exact beyond it (its lengths are forces over a μF chosen as large).
FORCE_LIMIT_N = 1e152


def is_force_name(name: str) -> bool:
    return FORCE_NAME.fullmatch(split_name(name)[0]) is not None


@dataclass
class ForceAnalysis:
    """Everything a force scene produced."""

    scene: Scene[ForceScene]
    kinematics: Analysis  # the linkage check (its build, plan, solutions, exact kinematics)
    kin: PolygonKinematics
    solution: KinetostaticSolution
    exact: ExactForces
    scales: dict[str, float]
    stated: set[str]
    labels: tuple[str, ...]
    frictionless: KinetostaticSolution | None = None
    exact_frictionless: ExactForces | None = None
    lever: Lever | None = None
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    verdicts: list[Verdict] = field(default_factory=list)
    ill: dict[int, bool] = field(default_factory=dict)  # position → some polygon is ill-conditioned
    spill_mm: float = 0.0  # how far the force sheet runs off its page at the chosen scales
    #: The force polygons' details (their short vectors drawn again larger) are drawn: they give
    #: way first where the sheet does not fit its page (the check table names those vectors).
    details: bool = True

    @property
    def build(self) -> LinkageConstruction:
        return self.kinematics.build

    def scale_notes(self) -> list[str]:
        notes = self.kinematics.scale_notes()
        if "F" in self.scales:
            notes.append(f"μF = {self.scales['F']:.6g} N/mm" + ("" if "F" in self.stated else " (chosen)"))
        return notes

    def friction_summary(self) -> dict[str, Any]:
        return {"iterations": self.solution.iterations,
                "tolerance_N": self.scene.problem.model.tolerance}


#: Factors by which the chosen scales are made coarser, in turn, until the force sheet fits its
#: page (the loads, every free body, the polygons and the lever share it).
FIT_COARSER = (1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0)
#: Where no scale fits the sheet (captions and arrows not to scale take room too), a coarser one
#: is taken only if it spills this much less, mm: drawings are not shrunk for nothing.
FIT_GAIN_MM = 2.0


#: The last analysis made, with the scene it was made of (the very object, which the analysis
#: holds anyway) and the measured values given: a scene drawn and then checked (``graphmech batch``,
#: the API's render then check) is analysed once — each analysis lays its sheet out, labels and
#: all, to choose its scales. One entry: the next force scene replaces it.
_LAST: list[tuple[Scene[ForceScene], tuple[tuple[str, float], ...], ForceAnalysis]] = []


def analyse_forces(scene: Scene[ForceScene], extra_measured: tuple[tuple[str, float], ...] = ()) -> ForceAnalysis:
    """Build and check a force scene (``extra_measured``: values from the command line).

    The scales a scene does not state are chosen so that the sheet it draws fits its page: μl
    and μv first (the finest round ones that fit), then μF too; the check table then reads the
    lengths at the μ the figure is drawn at. The same scene object with the same values asked
    again gives the analysis made last (nothing changes an analysis once made).
    """
    extra = tuple(extra_measured)
    if _LAST and _LAST[0][0] is scene and _LAST[0][1] == extra:
        return _LAST[0][2]
    fa = _fitted(scene, extra)
    _LAST[:] = [(scene, extra, fa)]
    return fa


def _fitted(scene: Scene[ForceScene], extra_measured: tuple[tuple[str, float], ...]) -> ForceAnalysis:
    """The analysis at the scales that fit the page (:func:`analyse_forces`)."""
    # a value that overflows is reported once, in one line, as "not finite" (no numpy warnings)
    with np.errstate(all="ignore"):
        fa = _analyse_forces(scene, extra_measured, {})
        drawn = any(p in FORCE_PANELS for p in scene.show) and len(positions_of(scene).values) == 1
        if not (drawn and solved(fa, 0)):
            return fa
        if (largest := _largest_force(fa)) > FORCE_LIMIT_N:  # the table is exact still; the drawing is not
            raise SceneError([("forces", f"the forces reach {largest:.3g} N, more than {FORCE_LIMIT_N:g} N: their "
                                         "polygons cannot be drawn in double precision (see the driver's speed and "
                                         "acceleration and the masses; without the force panels in show, the "
                                         "table is still checked)")], scene.source)
        forced: dict[str, float]
        best, spill, forced = fa, _spill(fa), {}
        details = True
        if spill > 0.0:  # the details are the first to give way, before any drawing is made smaller
            fa.details = False
            s = _spill(fa)
            if s < spill:
                best, spill, details = fa, s, False
            else:
                fa.details = True
        tried: set[tuple[tuple[str, float], ...]] = set()
        keys: tuple[str, ...]
        for keys in (("l", "v"), ("F",)):  # the drawings of the mechanism first, then the polygons
            keys = tuple(k for k in keys if k not in fa.stated)
            for factor in FIT_COARSER:
                if spill == 0.0 or not keys:
                    break
                trial = {**forced, **{k: round_scale(fa.scales[k] * factor) for k in keys}}
                if tuple(sorted(trial.items())) in tried:
                    continue
                tried.add(tuple(sorted(trial.items())))
                candidate = _analyse_forces(scene, extra_measured, trial)
                candidate.details = details
                s = _spill(candidate)
                if s == 0.0 or s < spill - FIT_GAIN_MM:
                    best, spill, forced = candidate, s, trial
        if not details and spill == 0.0:  # at the scales that fit, the details may fit too
            best.details = True
            if _spill(best) > 0.0:
                best.details = False
        best.spill_mm = spill
        return best


def _spill(fa: ForceAnalysis) -> float:
    """How far the force sheet runs off its page, mm (0: it fits), its labels placed as drawn."""
    from graphmech.render.layout import footer_room, layout_sheet
    from graphmech.render.sheet import panel_labels, panel_shapes
    from graphmech.render.style import DEFAULT

    sheet = _sheet(fa, ("graphmech",))  # a rendered sheet has a one-line footer: it takes room too
    shapes = [panel_shapes(p) for p in sheet.panels]
    placed = [panel_labels(p, sh) for p, sh in zip(sheet.panels, shapes)]
    layout = layout_sheet(sheet, label_boxes=[[pl.box for pl in labels] for labels in placed])
    if not layout.warnings:
        return 0.0
    m = DEFAULT.page_margin
    # the room above the footer line, as render.layout reckons it
    bottom = sheet.page[1] - m - footer_room(len(sheet.footer), m)
    right = sheet.page[0] - m
    over = [max(p.frame[3] - bottom, p.frame[2] - right, m - p.frame[0]) for p in layout.panels]
    return max([0.0, *over]) + 1e-6  # (a sheet that warns never ranks with one that fits)


def _analyse_forces(scene: Scene[ForceScene], extra_measured: tuple[tuple[str, float], ...],
                    forced: dict[str, float]) -> ForceAnalysis:
    """The analysis at the scene's scales, those in ``forced`` imposed (still reported as chosen)."""
    model = scene.problem.model
    measured = [(n, v) for n, v in scene.measured if not is_force_name(n)]
    extra_kin = tuple((n, v) for n, v in extra_measured if not is_force_name(n))
    force_measured = [(f"measured.{n}", n, v) for n, v in scene.measured if is_force_name(n)] + [
        (f"--measured {n}", n, v) for n, v in extra_measured if is_force_name(n)]
    kin_find = tuple(n for n in scene.find if not is_force_name(n))
    kin_show = tuple(p for p in scene.show if p in ("mechanism", "velocity", "acceleration")) or ("mechanism",)
    kin_forced = {k: v for k, v in forced.items() if k in ("l", "v")}
    plain = replace(cast("Scene[ForceScene | None]", scene), find=kin_find, show=kin_show, measured=tuple(measured), kind="linkage", problem=None,
                    scales={**scene.scales, **kin_forced})
    an = analyse(plain, extra_kin)
    an.stated = an.stated - set(kin_forced)  # imposed to fit the sheet, not stated by the scene
    b = an.build
    plan = b.g.prune(construction_targets(b))
    batch = plan.evaluate_batch({b.param: an.positions})
    kin = kinematics_from_construction(b, batch.values, batch.valid)
    draw = "force_polygons" in scene.show
    try:
        sol = kinetostatics(b.linkage, model, kin, polygons=draw)
    except DegenerateConstruction as e:  # friction that does not settle, closing lines parallel
        raise SceneError([("forces", str(e))], scene.source) from None
    exact = solve_forces(b.linkage, model, an.positions, an.exact)
    names = [split_name(n)[0] for n in scene.find] + [split_name(n)[0] for _, n, _ in force_measured]
    fa = ForceAnalysis(scene, an, kin, sol, exact, dict(an.scales), set(an.stated), an.labels)
    fa.warnings = list(an.warnings)
    fa.rows = list(an.rows)
    wants_frictionless = any(n in ("M_b_lever", "M_b0", "F_b_lever", "F_b0", "eta") for n in names) \
        or "lever" in scene.show
    if model.has_friction and wants_frictionless:
        bare = replace(model, revolute_friction=(), sliding_friction=())
        fa.frictionless = kinetostatics(b.linkage, bare, kin, polygons=False)
        fa.exact_frictionless = solve_forces(b.linkage, bare, an.positions, an.exact)
    if "M_b_lever" in names or "F_b_lever" in names or "lever" in scene.show:
        try:
            fa.lever = zhukovsky_lever(b.linkage, model, kin)
        except DegenerateConstruction as e:  # a driver at rest: say which key asked for the lever
            asked = [f"find[{k}]" for k, n in enumerate(scene.find) if split_name(n)[0] in ("M_b_lever", "F_b_lever")]
            key = "show" if "lever" in scene.show else (asked[0] if asked else "--measured")
            raise SceneError([(key, f"{e.step}: {e.reason}")], scene.source) from None
    _choose_force_scale(fa, forced.get("F"))
    _conditioning(fa)
    _rows(fa)
    _short_vectors(fa)
    fa.verdicts = list(judge(an, None)) if (measured or extra_kin) else []
    fa.verdicts += _judge_forces(fa, force_measured)
    return fa


def solved(fa: ForceAnalysis, i: int) -> bool:
    return bool(fa.kin.valid[i] and fa.exact.valid[i] and fa.kinematics.solutions[i] is not None)


def _largest_force(fa: ForceAnalysis) -> float:
    """The largest reaction or inertia force component at any assembled position, N."""
    largest = max((float(np.max(np.abs(r[fa.kin.valid]), initial=0.0)) for r in fa.solution.reactions.values()),
                  default=0.0)
    for il in fa.solution.inertia.values():
        largest = max(largest, float(np.max(np.abs(il.force[fa.kin.valid]), initial=0.0)))
    return largest


#: The share of the page's shorter side the largest force polygon may take when μF is chosen
#: finer than the usual 70 mm polygon so that the forces asked for are readable (the sheet's
#: fit makes it coarser still where the panels do not fit).
POLYGON_PAGE_SHARE = 0.5


def _asked_forces(fa: ForceAnalysis) -> list[tuple[str, float]]:
    """(row name, |F| in N) of every force vector the scene asks for, at every position solved:
    the lengths a student measures on the polygons (a force that is zero is no vector)."""
    out: list[tuple[str, float]] = []
    multi = len(fa.labels) > 1
    size = _characteristic_force(fa)
    for raw in fa.scene.find:
        base, at = split_name(raw)
        if not is_force_name(base) or _known(fa, base) is not None or (at is not None and at not in fa.labels):
            continue
        for i in ([fa.labels.index(at)] if at is not None else range(len(fa.labels))):
            if not solved(fa, i):
                continue
            drawn, _, g, _, unit = force_value(fa, base, i)
            if unit == "N" and drawn is not None and math.isfinite(g) and abs(g) > 1e-9 * size:
                out.append((f"{base}@{fa.labels[i]}" if multi else base, abs(float(g))))
    return out


def _choose_force_scale(fa: ForceAnalysis, forced: float | None = None) -> None:
    """μF: the scene's; else the round scale that draws the largest force polygon about
    ``POLYGON_ROOM_MM`` long — or finer, down to the one that draws every force asked for at least
    10 mm long (±0.5 mm of reading within 5 %), as far as the page allows."""
    from graphmech.problems.forces.figures import READ_MIN_MM

    largest = _largest_force(fa)
    mu = fa.scene.problem.mu_F
    if mu is None:
        if forced:
            fa.scales["F"] = forced
            return
        chosen = round_scale(largest / POLYGON_ROOM_MM) if largest > 0 else 1.0
        fa.scales["F"] = chosen  # (the lengths below are forces in N, whatever μF)
        shortest = min((g for _, g in _asked_forces(fa)), default=0.0)
        if shortest > 0 and shortest / chosen < READ_MIN_MM:
            room = POLYGON_PAGE_SHARE * min(page_size(fa.scene))
            finer = max(round_scale_below(shortest / READ_MIN_MM), round_scale(largest / room))
            chosen = min(chosen, finer)
        fa.scales["F"] = chosen
        return
    fa.scales["F"], fa.stated = mu, fa.stated | {"F"}
    drawn = largest / mu
    if largest > 0 and not POLYGON_RANGE_MM[0] <= drawn <= POLYGON_RANGE_MM[1]:
        raise SceneError([(fa.scene.problem.mu_F_path, f"μF = {mu:g} N/mm draws the largest force {drawn:.3g} mm long: choose "
                                          f"μF so that it is {POLYGON_RANGE_MM[0]:g} … {POLYGON_RANGE_MM[1]:g} mm "
                                          f"(about {round_scale(largest / POLYGON_ROOM_MM):g} N/mm)")],
                         fa.scene.source)


#: The most short vectors a warning names one by one.
SHORT_NAMED = 6


def _short_vectors(fa: ForceAnalysis) -> None:
    """Warn of the forces asked for that μF draws shorter than 10 mm, each with its reading error
    (the drawing precision, ±0.5 mm, over its length): a stated μF that does it is the scene's to
    change; a chosen one does it only where a finer round μF would not fit the page."""
    from graphmech.problems.forces.figures import READ_MIN_MM

    mu = fa.scales["F"]
    short = sorted(((name, g / mu) for name, g in _asked_forces(fa) if g / mu < READ_MIN_MM), key=lambda s: s[1])
    if not short:
        return
    prec = fa.scene.precision_mm
    named = ", ".join(f"{name} {length:.3f} mm (±{100.0 * prec / length:.2g} %)" for name, length in short[:SHORT_NAMED])
    more = f" and {len(short) - SHORT_NAMED} more" if len(short) > SHORT_NAMED else ""
    if "F" in fa.stated:
        how = (f"μF = {mu:g} N/mm (stated) draws {len(short)} of the forces asked for shorter than "
               f"{READ_MIN_MM:g} mm")
        fix = (f"; μF = {round_scale_below(short[0][1] * mu / READ_MIN_MM):g} N/mm draws them all at least "
               f"{READ_MIN_MM:g} mm long")
    else:
        how = (f"μF = {mu:g} N/mm (chosen: a finer round scale does not fit the page) draws {len(short)} of the "
               f"forces asked for shorter than {READ_MIN_MM:g} mm")
        fix = ""
    fa.warnings.append(f"{how}, where reading to ±{prec:g} mm errs by more than "
                       f"{100.0 * prec / READ_MIN_MM:.2g} %: {named}{more}{fix}")


def _conditioning(fa: ForceAnalysis) -> None:
    """Near a toggle a polygon's closing lines meet at a shallow angle and the reactions grow
    without bound: say where, and flag the rows where rounding itself is amplified."""
    for i, lab in enumerate(fa.labels):
        where = position_text(fa.build, lab)
        if fa.kin.valid[i] and fa.kinematics.exact.valid[i] and not fa.exact.valid[i]:
            fa.warnings.append(f"{where}: the equilibrium equations are singular (condition number "
                               f"{float(fa.exact.condition[i]):.2g}): the transmission angle is 0° and the "
                               "reactions are unbounded; no force values here")
        if not solved(fa, i):
            continue
        for name, sin in fa.solution.closing.items():
            s = float(sin[i])
            if s < SHALLOW_SIN:
                if 1.0 / max(s, 1e-300) > COND_WARN:
                    fa.ill[i] = True
                fa.warnings.append(f"{where}: {name}: the force polygon's closing lines meet at "
                                   f"{math.degrees(math.asin(min(s, 1.0))):.2g}° — near-collinear forces, "
                                   "ill-conditioned: the transmission angle is near 0° and the reactions "
                                   "grow without bound (a hand construction is unreliable here)")


def _characteristic_force(fa: ForceAnalysis) -> float:
    """The scene's force size: its largest reaction over every position solved (N). A relative
    error divides by max(|exact|, this) — per scene, as the kinematic rows do: a position where
    every load vanishes has only round-off to compare (4e-13 N against 4.5e-13 N read 6 %)."""
    ok = np.array([solved(fa, i) for i in range(len(fa.labels))], dtype=bool)
    out = max((float(np.max(np.abs(r[ok]), initial=0.0)) for r in fa.solution.reactions.values()), default=0.0)
    return max(out, 1e-300)


def force_value(fa: ForceAnalysis, base: str, i: int) -> tuple[float | None, float, float, float, str]:
    """(drawn mm or None, scale, graphical, exact, unit) of a force quantity at position i."""
    m = FORCE_NAME.fullmatch(base)
    assert m is not None
    mu_F, mu_l = fa.scales["F"], fa.scales["l"]
    sol, ex = fa.solution, fa.exact

    def vector(g: complex, e: np.ndarray, comp: str | None) -> tuple[float | None, float, float, float, str]:
        if comp == "_x":
            gv, ev = g.real, float(e[0])
        elif comp == "_y":
            gv, ev = g.imag, float(e[1])
        else:
            gv, ev = abs(g), float(math.hypot(e[0], e[1]))
        return gv / mu_F, mu_F, (gv / mu_F) * mu_F, ev, "N"

    if m.group("fi"):
        link = m.group("fi")
        il = sol.inertia[link]
        return vector(complex(il.force[i]), ex.inertia_force[link][i], m.group("fic"))
    if m.group("mi"):
        link = m.group("mi")
        return None, 1.0, float(sol.inertia[link].moment[i]), float(ex.inertia_moment[link][i]), "N·m"
    if m.group("h"):
        link = m.group("h")
        f, mo = ex.inertia_force[link][i], ex.inertia_moment[link][i]
        fm = math.hypot(f[0], f[1])
        e = float(abs(mo) / fm) if fm > 0 else 0.0
        h = float(sol.inertia[link].offset[i])
        return h / mu_l, mu_l, (h / mu_l) * mu_l, e, "m"
    if m.group("ri"):
        key = (m.group("ri"), m.group("rj"))
        return vector(complex(sol.reactions[key][i]), ex.reactions[key][i], m.group("rc"))
    g: GuideReaction | float
    if m.group("gi"):
        slider = m.group("gj")
        g = next(gr for gr in sol.guides if gr.slider == slider)
        if m.group("gm") == "M":
            return None, 1.0, float(g.moment[i]), float(ex.guide_moments[slider][i]), "N·m"
        # e: where the guide reaction's line of action crosses the guide, from the slider's point
        # along the guide (M = e·(t × R)), drawn on the free body at μl
        ex_point = fa.kinematics.exact.point
        t = _guide_direction(fa, slider, lambda p: complex(fa.kin.point[p][i]))
        t_x = _guide_direction(fa, slider, lambda p: complex(*ex_point[p][i]))
        tr = (np.conj(t) * complex(g.force[i])).imag
        e_g = float(g.moment[i]) / tr if tr != 0 else 0.0
        r = ex.reactions[(g.frame, slider)][i]
        tr_x = t_x.real * r[1] - t_x.imag * r[0]
        e_x = float(ex.guide_moments[slider][i]) / tr_x if tr_x != 0 else 0.0
        return e_g / mu_l, mu_l, (e_g / mu_l) * mu_l, e_x, "m"
    if base == "M_b":
        return None, 1.0, float(sol.balancing_moment[i]), float(ex.balancing_moment[i]), "N·m"
    bare = fa.frictionless or sol
    bare_ex = fa.exact_frictionless or ex
    if base.startswith("F_b"):  # a driving slider's balancing force, signed along its guide
        assert sol.balancing_force is not None and ex.balancing_force is not None
        assert bare.balancing_force is not None and bare_ex.balancing_force is not None
        if base == "F_b":
            g, e = float(sol.balancing_force[i]), float(ex.balancing_force[i])
        elif base == "F_b0":
            g, e = float(bare.balancing_force[i]), float(bare_ex.balancing_force[i])
        else:
            assert fa.lever is not None and fa.lever.balancing_force is not None
            g, e = float(fa.lever.balancing_force[i]), float(bare_ex.balancing_force[i])
        return g / mu_F, mu_F, (g / mu_F) * mu_F, e, "N"
    if base == "M_b0":
        return None, 1.0, float(bare.balancing_moment[i]), float(bare_ex.balancing_moment[i]), "N·m"
    if base == "M_b_lever":
        assert fa.lever is not None
        return None, 1.0, float(fa.lever.balancing_moment[i]), float(bare_ex.balancing_moment[i]), "N·m"
    # eta: the instantaneous efficiency, ideal over actual driving moment (force), M_b0/M_b, while
    # the driver delivers power (M_b0·ω1 > 0); while the loads drive it (M_b0·ω1 < 0) the driver is
    # the output, and η = M_b/M_b0, actual over ideal output (≤ 0: friction locks that drive) — as
    # the reverse stroke of an [efficiency] scene. The exact sign decides for both columns.
    d = fa.build.linkage.driver
    if (sol.balancing_force is not None and bare.balancing_force is not None  # a slider driver: all four have F_b
            and bare_ex.balancing_force is not None and ex.balancing_force is not None):
        g0, g1 = float(bare.balancing_force[i]), float(sol.balancing_force[i])
        e0, e1 = float(bare_ex.balancing_force[i]), float(ex.balancing_force[i])
        speed = cast("SliderInput", d).velocity
    else:
        g0, g1 = float(bare.balancing_moment[i]), float(sol.balancing_moment[i])
        e0, e1 = float(bare_ex.balancing_moment[i]), float(ex.balancing_moment[i])
        speed = cast("Crank", d).omega
    if e0 * speed < 0 and abs(e0) > 1e-9 * abs(e1):  # (an M_b0 that is round-off of 0 drives nothing)
        return None, 1.0, g1 / g0, e1 / e0, ""
    return None, 1.0, g0 / g1, e0 / e1, ""


def _guide_direction(fa: ForceAnalysis, slider: str, point: Callable[[str], complex]) -> complex:
    """The unit direction of the guide ``slider`` slides on (a moving link's: through → towards at
    this position, ``point`` giving the positions)."""
    guide = next(g for y in (fa.build.linkage.driver, *fa.build.linkage.dyads)
                 for b, g in (zip(y.links, y.guides) if isinstance(y, PRP) else
                              [(getattr(y, "link", None), getattr(y, "guide", None)),
                               (getattr(y, "links", (None, None))[1], getattr(y, "guide", None))])
                 if b == slider and isinstance(g, (Guide, LinkGuide)))
    if isinstance(guide, Guide):
        return complex(math.cos(guide.angle), math.sin(guide.angle))
    d = point(guide.towards) - point(guide.through)
    return d / abs(d) if d != 0 else 1.0 + 0j


def _known(fa: ForceAnalysis, base: str) -> str | None:
    """Why ``base`` names nothing in this scene (None if it does)."""
    m = FORCE_NAME.fullmatch(base)
    assert m is not None
    for key in ("fi", "mi", "h"):
        link = m.group(key)
        if link and link not in fa.solution.inertia:
            return f"link {link} has no [[forces.mass]]" + (
                f" (masses on links {', '.join(fa.solution.inertia)})" if fa.solution.inertia else "")
    if m.group("ri") and (m.group("ri"), m.group("rj")) not in fa.solution.reactions:
        pairs = sorted({f"R_{a}{b}" for (a, b) in fa.solution.reactions if a < b})
        return f"links {m.group('ri')} and {m.group('rj')} have no joint (reactions: {', '.join(pairs)})"
    if m.group("gi") and not any(g.slider == m.group("gj") and g.frame == m.group("gi") for g in fa.solution.guides):
        guides = ", ".join(f"M_{g.frame}{g.slider}, e_{g.frame}{g.slider}" for g in fa.solution.guides) or "none"
        return f"no slider {m.group('gj')} on a guide of link {m.group('gi')} (guide moments: {guides})"
    if base in ("eta", "M_b0", "F_b0") and not fa.scene.problem.model.has_friction:
        return f"{base} compares with friction: this scene has none"
    slider_driven = fa.solution.balancing_force is not None
    if base.startswith("M_b") and slider_driven:
        return f"the driver is a slider: its balancing force is {base.replace('M_b', 'F_b')}"
    if base.startswith("F_b") and not slider_driven:
        return f"the driver is a crank: its balancing moment is {base.replace('F_b', 'M_b')}"
    if base == "eta":
        return None
    return None


#: A friction iteration whose own error estimate is below this (relative) has converged to
#: round-off: its rows stay constructions.
ROUND_OFF = 1e-12


def _rows(fa: ForceAnalysis) -> None:
    problems = []
    multi = len(fa.labels) > 1
    force_size = _characteristic_force(fa)
    locked: list[int] = []
    sol = fa.solution
    # with friction, the same quantities one and two rounds earlier: how far the iteration still moves them
    before = None if sol.previous is None else replace(fa, solution=sol.previous)
    earlier = None if before is None else replace(fa, solution=cast("KinetostaticSolution", cast("KinetostaticSolution", sol.previous).previous))
    basis = f"friction: {sol.iterations} rounds to {fa.scene.problem.model.tolerance:g} N"
    for k, raw in enumerate(fa.scene.find):
        base, at = split_name(raw)
        if not is_force_name(base):
            continue
        why = _known(fa, base)
        if why:
            problems.append((f"find[{k}]", why))
            continue
        idx: range | list[int]
        if at is None:
            idx = range(len(fa.labels))
        elif at in fa.labels:
            idx = [fa.labels.index(at)]
        else:
            problems.append((f"find[{k}]", f"no position {at!r} (positions: {', '.join(fa.labels)})"))
            continue
        for i in idx:
            if not solved(fa, i):
                continue
            drawn, scale, g, e, unit = force_value(fa, base, i)
            ch = force_size
            if unit == "N·m":
                ch *= fa.kinematics.size
            elif unit == "m":
                ch = fa.kinematics.size
            elif unit == "":
                ch = 1.0
            if not (math.isfinite(g) and math.isfinite(e)):
                problems.append((f"find[{k}]", f"{base} is not finite at {position_text(fa.build, fa.labels[i])}"))
                continue
            g, e = float(g) + 0.0, float(e) + 0.0  # no "-0" in the table
            err = abs(g - e) / max(abs(e), ch)
            row = Row(f"{base}@{fa.labels[i]}" if multi else base, unit, None if drawn is None else float(drawn),
                      float(scale), g, e, err, bool(fa.ill.get(i, False)))
            if before is not None and earlier is not None:  # friction stopped at its tolerance: how close?
                estimate = relative(iteration_error(g, float(force_value(before, base, i)[2]),
                                                    float(force_value(earlier, base, i)[2])), max(abs(e), ch))
                if estimate > ROUND_OFF:
                    row = row.estimated(DISCRETISATION, estimate, basis)
            fa.rows.append(row)
            if base == "eta" and e <= 0.0:
                locked.append(i)
    if problems:
        raise SceneError(problems, fa.scene.source)
    if locked:  # η ≤ 0: friction takes all the power there, as a self-locking stroke of [efficiency]
        where = position_text(fa.build, fa.labels[locked[0]])
        more = f" and {len(locked) - 1} more position(s)" if len(locked) > 1 else ""
        fa.warnings.append(f"{where}{more}: η ≤ 0 — self-locking: friction takes all the power there (the "
                           "driver cannot move the loads, or the loads cannot drive the driver)")


def _judge_forces(fa: ForceAnalysis, entries: list[tuple[str, str, float]]) -> list[Verdict]:
    """A measured force is judged within the drawing precision at μF (a moment: × the crank)."""
    out, problems = [], []
    prec = fa.scene.precision_mm
    for key, name, value in entries:
        base, at = split_name(name)
        why = _known(fa, base)
        if why is None and at is not None and at not in fa.labels:
            why = f"no position {at!r} (positions: {', '.join(fa.labels)})"
        if why is None and at is None and len(fa.labels) > 1:
            why = f"the scene has {len(fa.labels)} positions: name one, e.g. {base}@{fa.labels[0]}"
        if why:
            problems.append((key, why))
            continue
        i = fa.labels.index(at) if at is not None else 0
        if not solved(fa, i):
            problems.append((key, f"position {fa.labels[i]} could not be solved"))
            continue
        drawn, scale, g, e, unit = force_value(fa, base, i)
        tol = prec * fa.scales["F"]
        if unit == "N·m":  # a polygon length off by the precision, times the arm it acts at
            tol *= getattr(fa.build.linkage.driver, "length", fa.kinematics.size)
        elif unit == "m":
            tol = prec * fa.scales["l"]
        elif unit == "":
            tol = 0.01
        e = float(e)
        out.append(Verdict(name, value, e, float(tol), bool(abs(value - e) <= tol + 1e-12 * abs(e)), unit))
    if problems:
        raise SceneError(problems, fa.scene.source)
    return out


FORCE_PANELS = ("forces", "force_polygons", "lever")


def render_forces(scene: Scene[ForceScene], footer: tuple[str, ...] = ()) -> tuple[Any, list[str]]:
    """The sheet of a force scene and its warnings: the kinematic panels it shows, then the
    loads, each group's free body and force polygon and Zhukovsky's lever, at one position."""
    drawn = [p for p in scene.show if p in FORCE_PANELS]
    if drawn and len(positions_of(scene).values) > 1:
        raise SceneError([("show", f"{', '.join(drawn)} draw one position and this scene has "
                                   f"{len(cast('Positions', scene.positions).values)}: give the driver one angle "
                                   "(graphmech check takes them all)")], scene.source)
    fa = analyse_forces(scene)
    if drawn and not solved(fa, 0):
        an = fa.kinematics
        raise SceneError([("driver", f"{position_text(an.build, an.labels[0])} cannot be solved: "
                                     f"{an.failures[0] or 'the exact solution is undefined here'}")], scene.source)
    hint = [] if fa.spill_mm == 0.0 else [
        f"the force sheet does not fit a {page_size(scene)[0]:g} × {page_size(scene)[1]:g} mm page at any round "
        "scale (its captions and arrows take room too): give [page] size = \"A3\" or show fewer panels"]
    if not fa.details and "force_polygons" in drawn:
        from graphmech.problems.forces.figures import polygon_detail

        if any(polygon_detail(g, fa.scales["F"], 0) is not None for g in fa.solution.groups):
            hint.append(f"the details of the force polygons (their vectors under 10 mm drawn larger) do not fit a "
                        f"{page_size(scene)[0]:g} × {page_size(scene)[1]:g} mm page and are left out: give a larger "
                        "[page] size to have them drawn")
    return _sheet(fa, footer), list(fa.warnings) + hint


def _sheet(fa: ForceAnalysis, footer: tuple[str, ...] = ()) -> Sheet:
    """The force scene's sheet at the analysis' scales (position 0 solved)."""
    from graphmech.problems.linkage.figures import linkage_sheet
    from graphmech.problems.forces.figures import force_sheet
    from graphmech.drawing.primitives import Sheet

    scene, an = fa.scene, fa.kinematics
    b = an.build
    drawn = [p for p in scene.show if p in FORCE_PANELS]
    kin_show = [p for p in scene.show if p in ("mechanism", "velocity", "acceleration")]
    head: tuple[Panel, ...] = ()
    if kin_show:
        texts = [position_text(b, lab) for lab in an.labels]
        head = linkage_sheet(scene.title, b.linkage, b, an.plan, an.solutions, an.labels, texts, an.scales,
                             kin_show, page_size(scene)).panels
    if not drawn:
        return Sheet(scene.title, tuple(head), page_size(scene), footer)
    return force_sheet(scene.title, b, fa.kin, fa.solution, scene.problem.model, fa.lever, fa.scales["F"],
                       drawn, 0, position_text(b, an.labels[0]), page_size(scene), head, footer,
                       scene.page.notation, fa.details)


__all__ = ["ForceAnalysis", "analyse_forces", "force_value", "solved", "is_force_name", "FORCE_NAME", "render_forces", "FORCE_PANELS"]
