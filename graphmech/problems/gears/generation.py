"""Generation by the rack cutter (范成法) in a gear scene: ``[gear.generation]`` read, its rows
checked and its panel drawn (docs/scene-format.md, "Generation by the rack cutter").

Hooks into the gear kind (kept here so that scene.py, check.py and figures.py carry one call
each): :func:`read_generation` from ``_read_gear`` (a blank speed and a datum distance give z and
x, so that [gear] gives neither), :data:`GENERATION_QUANTITIES` in ``quantity_unit``,
:func:`analyse_generation` and :func:`generation_value` from the check, :func:`generation_panel`
for the sheet.

The rows: the rolling circle r constructed from the speeds (the velocity lines ω·y and v cut at
the pitch point), L, n and ω of the blank, z and x found from them (against
:mod:`graphmech.exact.rack_generation`'s kinematics), and the thickness of the tooth the cutter's
N positions per pitch leave, on the reference and tip circles (against the exact generated
profile — the involute, or the fillet where it is undercut), with its own estimate from the positions halfway between.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmech.accuracy import DISCRETISATION
from graphmech.drawing.lettering import LETTER, number, scale_text
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import (
    ArcArrow,
    Arrow,
    Hinge,
    Label,
    Panel,
    Polyline,
    Primitive,
    Segment,
)
from graphmech.errors import GraphmechError, SceneError
from graphmech.exact import gear as ex
from graphmech.exact import rack_generation as erg
from graphmech.exact.profile_shift import x_min_book, z_min_book
from graphmech.mechanisms.gear import MAX_SHIFT, RackGeneration, SpurGear, ToothSystem
from graphmech.methods import involute as inv
from graphmech.methods import rack_generation as rg
from graphmech.problems.gears.figures import clipped_circle, dimension
from graphmech.problems.reader import MISSING, Reader, page_size, type_name
from graphmech.scales import round_scale

#: problems/gears/check.py's GearAnalysis (not imported: check imports this module)
GearAnalysis = Any

#: The names of a generation scene → unit in ``check`` (n in r/min as the book gives it).
GENERATION_QUANTITIES = {"r": "m", "L": "m", "n_blank": "r/min", "omega_blank": "rad/s", "z": "", "x": "",
                         "s_pitch_generated": "m", "sa_generated": "m"}
#: Cutter positions per pitch: the default and the range a scene may ask.
POSITIONS, POSITIONS_RANGE = 12, (2, 400)
#: The error estimate's reference: REFINE·N positions (at most REFINE_MOST, at least 2N).
REFINE, REFINE_MOST = 8, 512
#: A lucky circle's error is at least the scallop of the N half a step later ÷ LUCKY (measured: see estimate).
LUCKY = 20.0
#: The panel's room on the page, mm (its notes take about 40 mm under it), and its margin.
ROOM_H_MOST, MARGIN_MM = 190.0, 8.0

WORDS: dict[str, tuple[str, str, str]] = {
    "generation": ("Generation by the rack cutter", "范成法加工：齿条刀具", "Нарезание реечным инструментом"),
    "undercut": ("undercut", "根切", "подрез"),
    "pitch line": ("cutter's pitch line", "刀具节线", "делительная прямая инструмента"),
    "datum line": ("datum line", "刀具中线", "средняя линия"),
}


@dataclass(frozen=True)
class GenerationReading:
    """``[gear.generation]`` read: the model and, when a blank speed found z, the whole z drawn and
    the x that keeps L with it."""

    model: RackGeneration
    z_drawn: int | None = None
    x_drawn: float | None = None


def read_generation(g: Reader, module: float | None) -> GenerationReading | None:
    """Read ``[gear.generation]`` (None without it) of a [gear] of module ``module`` (None: refused
    already); the refusals name their key path."""
    t = g.table_at("generation")
    if t is None:
        return None
    bad = len(t.problems)
    v = t.scalar("cutter_speed", "velocity", positive=True)
    w = t.scalar("blank_speed", "omega", required=False, positive=True)
    L = t.scalar("datum_distance", "length", required=False, positive=True)
    n = POSITIONS
    raw = t.raw("positions")
    if raw is not MISSING:
        lo, hi = POSITIONS_RANGE
        if isinstance(raw, bool) or not isinstance(raw, int):
            t.problem(t.at("positions"), f"a whole number of positions per pitch, not {type_name(raw)}")
        elif not lo <= raw <= hi:
            t.problem(t.at("positions"), f"{lo} … {hi} positions per pitch, not {raw}")
        else:
            n = raw
    t.finish()
    if isinstance(g.table.get("z"), list) or "meshing" in g.table:
        t.problem(t.path, "generation by the rack cutter poses one gear: give z = one number and no meshing")
    if w is not None and L is None:
        t.problem(t.at(t.present("blank_speed") or "blank_speed"),
                  "a blank speed needs datum_distance too (r = v/ω, x = (L − r)/m)")
    if L is not None and w is None:
        t.problem(t.at(t.present("datum_distance") or "datum_distance"),
                  "a datum distance without blank_speed: state x in [gear] instead (L = r + xm)")
    for key in ("z", "x"):
        if w is not None and L is not None and g.present(key) is not None:
            g.used.add(g.present(key) or key)
            g.problem(g.at(g.present(key) or key), "over-determined: blank_speed and datum_distance already set "
                                                   "z = 2r/m and x = (L − r)/m; give z (and x) or them, not both")
    # refused: a table that poses z itself still answers for it (no "z missing" besides)
    posed = None if w is None or L is None else GenerationReading(RackGeneration(1.0), 1, 0.0)
    if len(t.problems) > bad or v is None:
        return posed
    model = RackGeneration(v, w, L, n)
    if w is None or L is None:
        return GenerationReading(model)
    if module is None:
        return posed
    z = 2.0 * v / (w * module)
    if not 1.0 <= z <= 1e5:
        g.problem(t.at(t.present("blank_speed") or "blank_speed"), f"r = v/ω gives z = 2r/m = {z:.6g}: no gear")
        return posed
    z_drawn = max(1, round(z))
    x = (L - module * z_drawn / 2.0) / module
    if abs(x) > MAX_SHIFT:  # the cutter's datum line that far from the rolling circle cuts no gear
        g.problem(t.at(t.present("datum_distance") or "datum_distance"),
                  f"L = r + xm gives x = {x:.6g}: a shift coefficient beyond ±{MAX_SHIFT:g} is no gear's")
        return posed
    return GenerationReading(model, z_drawn, x)


# ------------------------------------------------------------------------------ the check

@dataclass
class GenerationAnalysis:
    """What the check made of a generation: the exact kinematics, the construction at N and (for
    the estimate) the positions halfway, the exact profile of the gear drawn, the panel's scale."""

    system: ToothSystem
    gear: SpurGear
    model: RackGeneration
    values: erg.GenerationValues
    r_constructed: float
    construction: rg.Generation
    profile: erg.GeneratedProfile
    scale: float
    finer: rg.Generation | None = None
    halfway: rg.Generation | None = None
    notes: tuple[str, ...] = ()

    def reference(self) -> rg.Generation:
        """The reference cut by REFINE·N positions (at least 2N), staggered so that none is one of the
        construction's (a shared position would leave the same scallop where it cuts a circle)."""
        if self.finer is None:
            n = self.model.positions
            self.finer = rg.generate(self.system, self.gear, reference_positions(n), stagger=0.5)
        return self.finer

    def shifted(self) -> rg.Generation:
        """The same N positions half a step later: its scallops fall where the construction's are
        deepest, so its difference from the reference bounds the error a lucky circle hides."""
        if self.halfway is None:
            self.halfway = rg.generate(self.system, self.gear, self.model.positions, stagger=0.5)
        return self.halfway


def analyse_generation(an: GearAnalysis) -> None:
    """Construct the generation of a scene with ``[gear.generation]`` (warnings, the panel's scale)."""
    model = an.problem.generation
    if model is None:
        if "generation" in an.panels:
            raise SceneError([("show", "the generation panel draws [gear.generation]: give its cutter_speed")],
                             an.scene.source)
        return
    s = an.gears.system
    g = an.gears.gears[0]
    values = erg.kinematics(s, model, None if model.blank_speed is not None else g.z, g.x)
    _within_work(an, s, g, model.positions)
    try:
        construction = rg.generate(s, g, model.positions)
        profile = erg.generated_profile(s, g)
    except GraphmechError as err:
        raise SceneError([("gear.generation", str(err))], an.scene.source) from None
    omega = model.blank_speed if model.blank_speed is not None else values.omega
    r_c = rg.rolling_radius(model.cutter_speed, omega)
    notes = []
    if model.blank_speed is not None and abs(values.z - g.z) > 1e-9 * g.z:
        an.warnings.append(f"r = v/ω gives z = 2r/m = {values.z:.6g}, not a whole number (the speed is rounded): "
                           f"the gear is drawn with z = {g.z} on the same L (x = {g.x:.6g})")
    if profile.undercut:
        x_book = x_min_book(s, g.z)
        x_exact = ex.undercut(s, g).x_min_exact
        below = (f"x = {number(g.x, 4)} < x_{{min}} = {number(x_book, 4)} (h_{{a}}*({z_min_book(s)} − z)/{z_min_book(s)})"
                 if g.x < x_book - 1e-12 else f"x = {number(g.x, 4)} ≥ the book's x_{{min}} = {number(x_book, 4)}")
        notes.append(f"{below}, exact limit h_{{a}}* − z·sin²α/2 = {number(x_exact, 4)}: undercut — the fillet cuts "
                     f"the involute below r = {number(profile.r_limit * 1000, 4)} mm")
    w, h = page_size(an.scene)
    tall = construction.L + (s.ha_star + s.c_star + 1.0) * s.m
    wide = 3.0 * math.pi * s.m * max(1.0, construction.L / construction.r) + 2.0 * s.m
    mu = an.scales.get("generation") or round_scale(max(tall / min(h - 80.0, ROOM_H_MOST), wide / (w - 60.0)))
    an.scales["generation"] = mu
    an.generation = GenerationAnalysis(s, g, model, values, r_c, construction, profile, mu, notes=tuple(notes))


def reference_positions(n: int) -> int:
    """The positions per pitch of the error estimate's reference for N = n."""
    return min(REFINE * n, max(2 * n, REFINE_MOST))


def _within_work(an: GearAnalysis, s: ToothSystem, g: SpurGear, n: int) -> None:
    """Refuse a generation whose cut (or its reference's) would unite more than rg.WORK_MOST
    vertices — minutes of work — naming the most positions per pitch that fit."""
    def fits(k: int) -> bool:
        return max(rg.work(s, g, k), rg.work(s, g, reference_positions(k))) <= rg.WORK_MOST

    if g.internal or fits(n):
        return
    most = next((k for k in range(n - 1, POSITIONS_RANGE[0] - 1, -1) if fits(k)), None)
    said = f"at most positions = {most} fit" if most is not None else "even 2 are too many for so many teeth"
    key = "gear.generation.positions" if n != POSITIONS else "gear.generation"
    why = (f"{n} cutter positions per pitch on z = {g.z} (and the error estimate's {reference_positions(n)}) are too "
           f"many to cut in reasonable time; {said}")
    raise SceneError([(key, why)], an.scene.source)


def answers(model: RackGeneration | None, name: str) -> bool:
    """Whether the generation gives the row ``name``: its own names, and x only when a blank speed
    found it (a stated or designed shift is the shift's own row, problems/gears/check.py)."""
    return model is not None and name in GENERATION_QUANTITIES and (name != "x" or model.blank_speed is not None)


def generation_value(an: GearAnalysis, stem: str) -> tuple[float, float, float | None, float] | None:
    """(graphical, exact, drawn mm, μ) of a generation row."""
    ga: GenerationAnalysis = an.generation
    v = ga.values
    mu = ga.scale
    m = ga.system.m
    if stem == "r":
        return ga.r_constructed, v.r, ga.r_constructed / mu, mu
    if stem == "L":
        got = v.L if ga.model.datum_distance is not None else ga.r_constructed + ga.gear.x * m
        return got, v.L, got / mu, mu
    if stem == "omega_blank":
        w = ga.model.cutter_speed / ga.r_constructed
        return w, v.omega, None, 1.0
    if stem == "n_blank":
        n = 30.0 * ga.model.cutter_speed / ga.r_constructed / math.pi
        return n, v.n, None, 1.0
    if stem == "z":
        return 2.0 * ga.r_constructed / m, v.z, None, 1.0
    if stem == "x":
        L = ga.model.datum_distance
        got = (L - ga.r_constructed) / m if L is not None and ga.model.blank_speed is not None else ga.gear.x
        return got, v.x, None, 1.0
    rho = ga.construction.r if stem == "s_pitch_generated" else ga.construction.ra
    got_s = rg.thickness(ga.construction, rho)
    want = ga.profile.thickness(rho)
    if got_s is None or want is None:
        where = "reference" if stem == "s_pitch_generated" else "tip"
        an.warnings.append(f"{stem}: the generated tooth has no thickness on the {where} circle "
                           f"(r = {rho * 1000:.4g} mm: " + ("inside the root circle" if rho < ga.profile.rf
                                                            else "the tooth is pointed below it") + ")")
        return None
    return got_s, want, got_s / mu, mu


def estimate(an: GearAnalysis, row: Any) -> Any:
    """A thickness row with its own error: twice its difference from a reference cut by 8N
    positions (none shared with the N: a shared one would leave the same scallop where it cuts the
    circle), at least the difference of the same N half a step later from that reference ÷ LUCKY.
    A circle that passes near a tangent point of the N is lucky: its error is then as small as
    the reference's and the first difference says nothing, while the N half a step later are at
    their worst there. Measured over z = 8 … 60, x = −1.5 … 1, N = 8 … 32 (620 rows): the true
    error ≤ 0.66 of the estimate everywhere; the estimate above 10× the true error in 39 rows
    (circles that pass a tangent point, where the error is far below the scallop). On the
    reference circle the flank passes the pitch point at φ = (πm/4 − xm·tan α)/r: where that is
    one of the positions, the cutter's flank goes through it and the thickness is exact."""
    ga: GenerationAnalysis = an.generation
    if row.name not in ("s_pitch_generated", "sa_generated"):
        return row
    s, g, n = ga.system, ga.gear, ga.model.positions
    if row.name == "s_pitch_generated":
        phi = (math.pi * s.m / 4.0 - g.x * s.m * math.tan(s.alpha)) / ga.construction.r
        k = phi / (2.0 * math.pi / (g.z * n))
        if abs(k - round(k)) < 1e-9:
            return row
    other, half = ga.reference(), ga.shifted()
    rho = other.r if row.name == "s_pitch_generated" else other.ra
    t2, t_half = rg.thickness(other, rho), rg.thickness(half, rho)
    if t2 is None:
        return row
    # a circle that passes near a tangent point of the N is lucky: its error is then as small as
    # the reference's own and their difference says nothing; the N half a step later are unlucky
    # there, and their difference from the reference is the scallop that the N could have left
    diff = max(abs(row.graphical - t2), abs(t_half - t2) / LUCKY if t_half is not None else 0.0)
    err = 2.0 * diff / max(abs(row.graphical), 1e-300)
    rough = "; rough below 8" if n < 8 else ""
    return row.estimated(DISCRETISATION, err, f"{n} positions per pitch, against {other.positions}{rough}")


# ------------------------------------------------------------------------------ the panel

def _word(key: str, notation: str) -> str:
    return word(key, notation, WORDS)


def _runs(points: np.ndarray, box: tuple[float, float, float, float]) -> list[tuple[tuple[float, float], ...]]:
    """The runs of a polyline (paper mm) whose points lie in ``box``."""
    inside = (points[:, 0] >= box[0]) & (points[:, 0] <= box[2]) & (points[:, 1] >= box[1]) & (points[:, 1] <= box[3])
    out, cur = [], []
    for p, ok in zip(points, inside):
        if ok:
            cur.append((float(p[0]), float(p[1])))
        else:
            if len(cur) >= 2:
                out.append(tuple(cur))
            cur = []
    if len(cur) >= 2:
        out.append(tuple(cur))
    return out


def generation_panel(ga: GenerationAnalysis, notation: str = "en") -> Panel:
    """The blank and the cutter (孙桓's figure of 范成法): the reference circle (the rolling circle)
    with tip and root circles, O and L to the datum line, the cutter's pitch line tangent at P, the
    cutter at its successive positions thin and at φ = 0 medium, the generated teeth bold, v and ω,
    the undercut marked where the fillet cuts the involute."""

    c = ga.construction
    s, g = ga.system, ga.gear
    mu = ga.scale
    m = s.m
    teeth = c.teeth(range(-1, 2)) / mu
    H = (s.ha_star + s.c_star) * m
    half_w = 1.5 * math.pi * m / mu + 2.0
    top = (c.L + H + 0.6 * m) / mu
    box = (-half_w, min(c.rf / mu - 3.0 * m / mu, 0.0) - MARGIN_MM, half_w, top)
    items: list[Primitive] = []
    labels: list[Primitive] = []
    O = (0.0, 0.0)
    rb = c.r * math.cos(s.alpha)
    for radius, dashdot in ((c.r, True), (rb, True), (c.ra, False), (c.rf, False)):
        items += clipped_circle(O, radius / mu, box, "construction", dashdot=dashdot)
    items.append(Hinge(O))
    labels.append(Label("O", O, ((0.0, 1.0),), LETTER))
    # the cutter at its positions (thin), at φ = 0 (medium)
    for phi in c.phis:
        for run in _runs(c.cutter_at(phi) / mu, box):
            items.append(Polyline(run, "construction"))
    for run in _runs(c.cutter_at(0.0) / mu, box):
        items.append(Polyline(run, "given"))
    # the generated teeth
    for run in _runs(teeth, (box[0] - 1.0, box[1], box[2] + 1.0, box[3])):
        items.append(Polyline(run, "result"))
    # the cutter's pitch line tangent to the rolling circle at P, its datum line at L
    y_r, y_L = c.r / mu, c.L / mu
    items.append(Segment((box[0], y_r), (box[2], y_r), "construction", dashdot=True))
    if abs(y_L - y_r) > 0.3:
        items.append(Segment((box[0], y_L), (box[2], y_L), "construction", dashdot=True))
    labels.append(Label(_word("pitch line", notation), (box[2] - 4.0, y_r), ((0.0, -1.0), (-1.0, 0.0)), LETTER * 0.8,
                        False))
    if abs(y_L - y_r) > 3.0:
        labels.append(Label(_word("datum line", notation), (box[2] - 4.0, y_L), ((0.0, -1.0), (-1.0, 0.0)),
                            LETTER * 0.8, False))
    items.append(Hinge((0.0, y_r), 0.6))
    labels.append(Label("P", (0.0, y_r), ((0.0, -1.0), (1.0, 0.0), (-1.0, 0.0)), LETTER))
    # L from O to the datum line, left of the teeth
    xd = box[0] + 3.0
    items.append(Segment(O, (xd - 1.5, 0.0), "label"))
    items += dimension((xd, 0.0), (xd, y_L), f"L = {number(ga.values.L * 1000, 5)} mm", (-1.0, 0.0))
    # v along the cutter (to the right), ω of the blank (clockwise)
    yv = top - 0.3 * m / mu
    items.append(Arrow((-8.0, yv), (8.0, yv), "result"))
    labels.append(Label(f"v = {number(ga.model.cutter_speed, 4)} m/s", (8.0, yv), ((-1.0, 0.0),), LETTER, False))
    items.append(ArcArrow(O, 6.0, math.radians(150.0), -math.radians(120.0), "result"))
    labels.append(Label(f"ω = {number(ga.values.omega, 4)} rad/s", (0.0, 6.0), ((0.0, -1.0),), LETTER, False))
    if ga.profile.undercut:  # the involute the fillet cut away, dashed, on the tooth right of the space
        lo, hi = max(rb, c.rf), min(ga.profile.r_limit, c.ra)
        turn = -math.pi / g.z
        cs, sn = math.cos(turn), math.sin(turn)
        pts = []
        for rk in np.linspace(lo, hi, 16):
            K = inv.at_radius(s, g, float(rk)).K_left
            pts.append(((cs * K[0] - sn * K[1]) / mu, (sn * K[0] + cs * K[1]) / mu))
        if math.dist(pts[0], pts[-1]) > 0.2:
            items.append(Polyline(tuple(pts), "construction", dashed=True))
        # the word at the neck: the generated flank halfway between the root and the limit point
        prof = np.asarray(c.profile)
        right = prof[: len(prof) // 2] / mu
        k = int(np.argmin(np.abs(np.hypot(right[:, 0], right[:, 1]) - 0.5 * (c.rf + hi) / mu)))
        labels.append(Label(_word("undercut", notation), (float(right[k, 0]), float(right[k, 1])),
                            ((-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)), LETTER, False))
    v = ga.values
    speeds = (f"v = {number(ga.model.cutter_speed, 4)} m/s, ω = {number(v.omega, 5)} rad/s "
              f"(n = {number(v.n, 5)} r/min): r = v/ω = {number(v.r * 1000, 6)} mm")
    drawn = f"; drawn with z = {g.z}, x = {number(g.x, 5)}" if abs(v.z - g.z) > 1e-9 * g.z else ""
    apart = number(math.pi * m / ga.model.positions * 1000, 4)
    notes = [scale_text("l", mu), speeds, f"z = 2r/m = {number(v.z, 6)}, x = (L − r)/m = {number(v.x, 5)}{drawn}",
             f"{ga.model.positions} cutter positions per pitch, πm/N = {apart} mm apart"]
    notes += list(ga.notes)
    return Panel("generation", _word("generation", notation), tuple(items + labels), tuple(notes), None,
                 (("l", mu),))


__all__ = ["GENERATION_QUANTITIES", "GenerationAnalysis", "GenerationReading", "analyse_generation", "answers",
           "estimate", "generation_panel", "generation_value", "read_generation"]
