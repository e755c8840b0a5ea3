"""The synthesis task ``positions``: a coupler led through two or three given positions.

Read: ``[[synthesis.position]]`` tables, each the coupler's joints ``B`` and ``C`` (points); with
two positions the frame line ``frame_through`` (a point) and ``frame_angle`` (its direction).
Analysed: the construction (:func:`graphmech.methods.synthesis_positions.coupler_positions`, the
perpendicular bisectors of B₁B₂, B₂B₃ meet at A, of C₁C₂, C₂C₃ at D) drawn at μl, its lengths and
pivots measured against the exact circumcentres (:mod:`graphmech.exact.synthesis_positions`), and
both designs re-analysed through the positions (the re-analysis error, γ_min), Grashof's class and
the note (no Grashof crank; positions on two branches) said under the table. The four-bar from
corresponding input/output positions by inversion is here too; the slider-crank, the rocker
leading a slider and the coupler point are in :mod:`.inversions`, dispatched from here.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from graphmech.errors import GraphmechError, SceneError
from graphmech.problems.reader import MISSING
from graphmech.problems.synthesis import inversions
from graphmech.problems.synthesis.common import (
    conditioning,
    design_rows,
    exact_joint,
    line_arc_sin,
    lines_sin,
    on_line,
    read_angles,
    read_length,
    read_point,
    unit,
)

if TYPE_CHECKING:
    from graphmech.drawing.primitives import Panel, Primitive
    from graphmech.exact.synthesis_positions import Reanalysis
    from graphmech.methods.synthesis_positions import CouplerDesign, FourbarDesign
    from graphmech.problems.judging import Row
    from graphmech.problems.reader import Reader

XY = tuple[float, float]
#: The rows of a coupler design, with their units.
COUPLER_NAMES = {"lAB": "m", "lBC": "m", "lCD": "m", "lAD": "m", "xA": "m", "yA": "m", "xD": "m", "yD": "m",
                 "reanalysis_error": "", "gamma_min": "deg"}


@dataclass(frozen=True)
class CouplerPositions:
    """The coupler's joints at each given position (m) and, with two, the frame line."""

    B: tuple[XY, ...]
    C: tuple[XY, ...]
    frame: tuple[XY, float] | None
    key: str


@dataclass(frozen=True)
class FourbarPositions:
    """Corresponding positions of the input AB (φ_i) and the output DC (ψ_i): A, D (m), l_AB and,
    with two positions, l_CD and the side of the bisector's foot C₁ is taken on."""

    A: XY
    D: XY
    l_AB: float
    phi: tuple[float, ...]
    psi: tuple[float, ...]
    l_CD: float | None
    side: float
    key: str


def _read_fourbar(r: Reader) -> FourbarPositions | None:
    A, D = read_point(r, "A"), read_point(r, "D")
    a = read_length(r, "l_AB")
    phi, psi = read_angles(r, "phi"), read_angles(r, "psi")
    c = read_length(r, "l_CD", required=False)
    side_raw = r.raw("side")
    side = 1.0
    if side_raw is not MISSING:
        if side_raw not in (1, -1) or isinstance(side_raw, bool):
            r.problem(r.at("side"), "must be 1 or -1 (C₁ ahead of or behind the foot of D on the bisector)")
            return None
        side = float(side_raw)
    if phi is not None and psi is not None and len(phi) != len(psi):
        r.problem(r.at(r.present("psi") or "psi"), f"{len(psi)} output angles for {len(phi)} input angles: "
                                                   "give as many of each")
        return None
    if phi is not None and len(phi) == 2 and c is None:
        r.problem(r.at("l_CD"), "with two positions C₁ lies anywhere on the bisector: give l_CD_mm (the output link)")
    if phi is not None and len(phi) == 3 and (c is not None or side_raw is not MISSING):
        r.problem(r.at(r.present("l_CD") or "side"), "three positions fix C₁: no l_CD or side is taken")
    if A is not None and D is not None and math.dist(A, D) <= 1e-12 * max(abs(x) for x in (*A, *D, 1e-3)):
        r.problem(r.at(r.present("D") or "D"), "A and D coincide: the frame AD has no length")
        return None
    if A is None or D is None or a is None or phi is None or psi is None or (len(phi) == 2 and c is None):
        return None
    return FourbarPositions(A, D, a, phi, psi, c, side, r.at(r.present("psi") or "psi"))


#: What the positions task reads: one of its forms.
PositionsProblem = CouplerPositions | FourbarPositions | inversions.Form


def read_positions(r: Reader) -> PositionsProblem | None:
    """``[[synthesis.position]]`` with B and C; ``frame_through``, ``frame_angle`` with two. Or
    the input/output form: ``A``, ``D``, ``l_AB``, ``phi``, ``psi`` (``l_CD``, ``side`` with two).
    Or one of the forms by inversion on a slider, a rocker or a coupler (:mod:`.inversions`)."""
    if inversions.is_form(r):
        return inversions.read_form(r)
    if r.present("phi") is not None:
        return _read_fourbar(r)
    tables = r.tables_at("position")
    B: list[XY] = []
    C: list[XY] = []
    for t in tables:
        b, c = read_point(t, "B"), read_point(t, "C")
        t.finish()
        if b is not None and c is not None:
            B.append(b)
            C.append(c)
    key = r.at("position")
    if len(tables) not in (2, 3):
        r.problem(key, f"give two or three [[{key}]] tables (the coupler's positions), not {len(tables)}")
    through = read_point(r, "frame_through", required=False)
    angle = r.scalar("frame_angle", "angle", required=False)
    if len(tables) == 2 and (through is None or angle is None):
        r.problem(r.at("frame_through"), "with two positions each pivot lies anywhere on its bisector: "
                                         "give frame_through_mm and frame_angle_deg (the frame line)")
    if len(tables) == 3 and (r.present("frame_through") or r.present("frame_angle")):
        r.problem(r.at(r.present("frame_through") or r.present("frame_angle") or "frame_through"),
                  "three positions fix both pivots: no frame line is taken")
    if len(B) != len(tables) or len(B) not in (2, 3):
        return None
    frame = (through, angle) if len(B) == 2 and through is not None and angle is not None else None
    if len(B) == 2 and frame is None:
        return None
    return CouplerPositions(tuple(B), tuple(C), frame, key)


def size(p: PositionsProblem) -> float:
    """The drawing's spread, m: the given points and the pivots (where they exist; a refusal is
    said by the analysis)."""
    if not isinstance(p, (CouplerPositions, FourbarPositions)):
        return inversions.size(p)
    if isinstance(p, FourbarPositions):
        pts = [p.A, p.D, *((p.A[0] + p.l_AB * math.cos(f), p.A[1] + p.l_AB * math.sin(f)) for f in p.phi)]
        try:
            z = exact_C1(p)
            pts.append((z.real, z.imag))
        except GraphmechError:
            pass
    else:
        pts = [*p.B, *p.C]
        try:
            pts += [(z.real, z.imag) for z in exact_pivots(p)]
        except GraphmechError:
            pass
    xs, ys = [x for x, _ in pts], [y for _, y in pts]
    return max(max(xs) - min(xs), max(ys) - min(ys))


def choose_scale(p: PositionsProblem) -> float:
    """μl that draws the linkage about 100 mm across."""
    from graphmech.scales import round_scale

    return round_scale(size(p) / 100.0)


def exact_pivots(p: CouplerPositions) -> tuple[complex, complex]:
    """A and D by the exact side: the circumcentres solved as linear systems, or with two
    positions the frame line's point equally far from B₁ and B₂ (C₁ and C₂)."""
    from graphmech.exact.synthesis_positions import circumcentre

    B = [complex(*b) for b in p.B]
    C = [complex(*c) for c in p.C]
    if p.frame is None:
        return circumcentre(*B), circumcentre(*C)
    P, u = complex(*p.frame[0]), complex(math.cos(p.frame[1]), math.sin(p.frame[1]))
    return on_line(P, u, B[0], B[1]), on_line(P, u, C[0], C[1])


def exact_C1(p: FourbarPositions, near: complex | None = None) -> complex:
    """C₁ by the exact side: B_i turned back about D by ψ_i − ψ₁ (complex rotation); the
    circumcentre of B₁, B₂′, B₃′, or with two the point of the bisector of B₁B₂′ at l_CD from D
    (of the two, the one nearer ``near``, the construction's: the side is a choice, not a value)."""
    import cmath

    A, D = complex(*p.A), complex(*p.D)
    B = [A + p.l_AB * cmath.exp(1j * f) for f in p.phi]
    return exact_joint(B, D, p.psi, p.l_CD, near)


@dataclass
class PositionsFound:
    """The drawn design (mm), the exact pivots, both re-analyses, the rows, the warnings and what
    ``check --json`` adds."""

    drawn: CouplerDesign | FourbarDesign
    mm: CouplerPositions | FourbarPositions
    A: complex
    D: complex
    drawn_re: Reanalysis
    exact_re: Reanalysis
    rows: list[Row]
    warnings: list[str]
    solutions: list[dict[str, Any]]
    names: list[str]


def analyse_fourbar(p: FourbarPositions, mu: float, find: tuple[str, ...] = (), source: str = "") -> PositionsFound:
    """The inversion at μl = ``mu`` against the exact C₁, both designs driven through φ_i."""
    from graphmech.exact.synthesis_positions import reanalyse_fourbar
    from graphmech.methods.synthesis_positions import fourbar_positions

    pm = FourbarPositions((p.A[0] / mu, p.A[1] / mu), (p.D[0] / mu, p.D[1] / mu), p.l_AB / mu, p.phi, p.psi,
                          None if p.l_CD is None else p.l_CD / mu, p.side, p.key)
    try:
        fourbar_positions(p.A, p.D, p.l_AB, p.phi, p.psi, p.l_CD, p.side)  # refused in metres, as given
        g = fourbar_positions(pm.A, pm.D, pm.l_AB, pm.phi, pm.psi, pm.l_CD, pm.side)
        C1 = exact_C1(p, complex(*g.C1) * mu)
        A, D = complex(*p.A), complex(*p.D)
        B1 = A + p.l_AB * complex(math.cos(p.phi[0]), math.sin(p.phi[0]))
        ex = {"lBC": abs(C1 - B1), "lCD": abs(C1 - D), "xC1": C1.real, "yC1": C1.imag}
        dr = {"lBC": g.l_BC, "lCD": g.l_CD, "xC1": g.C1[0], "yC1": g.C1[1]}
        xr = reanalyse_fourbar(A, D, p.l_AB, ex["lBC"], ex["lCD"], p.phi, p.psi, C1)
        gC1 = complex(*g.C1) * mu
        gr = reanalyse_fourbar(A, D, p.l_AB, g.l_BC * mu, g.l_CD * mu, p.phi, p.psi, gC1)
        rows, names = design_rows(dr, ex, mu, max(p.l_AB, ex["lBC"], ex["lCD"], abs(D - A)), gr, xr)
    except GraphmechError as e:
        raise SceneError([(p.key, str(e))], source) from None
    sol = {"name": "design", "lAB": p.l_AB, "lBC": ex["lBC"], "lCD": ex["lCD"], "lAD": abs(D - A),
           "C1": [C1.real, C1.imag], "grashof": xr.grashof, "branch": xr.branch, "one_branch": xr.one_branch,
           "reanalysis": {"error": xr.error, "gamma_deg": [math.degrees(x) for x in xr.gamma],
                          **({} if xr.characteristics is None
                             else {"gamma_min_deg": math.degrees(xr.characteristics.gamma_min)})},
           "note": xr.note}
    wanted = set(find) or None
    j = g.construction
    joint = ("lBC", "lCD", "xC1", "yC1")
    cuts = ([(f"C1 = {j.bisectors[0].label} ∩ {j.bisectors[1].label}", lines_sin(j.bisectors[0].line, j.bisectors[1].line),
              joint)] if len(j.bisectors) == 2 else
            [(f"C1 = arc ∩ {j.bisectors[0].label}", line_arc_sin(j.bisectors[0].line, pm.D, g.C1), joint)])
    kept, shallow = conditioning(cuts, [r for r in rows if wanted is None or r.name in wanted])
    return PositionsFound(g, pm, A, D, gr, xr, kept, ([xr.note] if xr.note else []) + shallow, [sol], names)


def analyse_positions(p: PositionsProblem, mu: float, find: tuple[str, ...] = (),
                      source: str = "") -> PositionsFound | inversions.InversionFound:
    """The construction at μl = ``mu`` against the exact pivots, both re-analysed."""
    if not isinstance(p, (CouplerPositions, FourbarPositions)):
        return inversions.analyse(p, mu, find, source)
    if isinstance(p, FourbarPositions):
        return analyse_fourbar(p, mu, find, source)
    from graphmech.exact.synthesis_positions import reanalyse_coupler
    from graphmech.methods.synthesis_positions import coupler_positions

    def mm(q: XY) -> XY:
        return (q[0] / mu, q[1] / mu)

    pm = CouplerPositions(tuple(mm(b) for b in p.B), tuple(mm(c) for c in p.C),
                          None if p.frame is None else (mm(p.frame[0]), p.frame[1]), p.key)
    try:
        coupler_positions(p.B, p.C, p.frame)  # refused in metres, as given
        g = coupler_positions(pm.B, pm.C, pm.frame)
        A, D = exact_pivots(p)
        B = [complex(*b) for b in p.B]
        C = [complex(*c) for c in p.C]
        xr = reanalyse_coupler(A, D, B, C)
        gr = reanalyse_coupler(complex(*g.A) * mu, complex(*g.D) * mu, B, C)
        ex = {"lAB": abs(B[0] - A), "lBC": abs(C[0] - B[0]), "lCD": abs(C[0] - D), "lAD": abs(D - A),
              "xA": A.real, "yA": A.imag, "xD": D.real, "yD": D.imag}
        dr = {"lAB": g.l_AB, "lBC": g.l_BC, "lCD": g.l_CD, "lAD": g.l_AD, "xA": g.A[0], "yA": g.A[1],
              "xD": g.D[0], "yD": g.D[1]}
        rows, names = design_rows(dr, ex, mu, max(ex["lAB"], ex["lBC"], ex["lCD"], ex["lAD"]), gr, xr)
    except GraphmechError as e:
        raise SceneError([(p.key, str(e))], source) from None
    warnings = [xr.note] if xr.note else []
    sol = {"name": "design", **{n: ex[n] for n in ("lAB", "lBC", "lCD", "lAD")}, "A": [A.real, A.imag],
           "D": [D.real, D.imag], "grashof": xr.grashof, "branch": xr.branch, "one_branch": xr.one_branch,
           "reanalysis": {"error": xr.error, "gamma_deg": [math.degrees(x) for x in xr.gamma],
                          **({} if xr.characteristics is None
                             else {"gamma_min_deg": math.degrees(xr.characteristics.gamma_min)})},
           "note": xr.note}
    wanted = set(find) or None
    kept, shallow = conditioning(coupler_cuts(g, pm), [r for r in rows if wanted is None or r.name in wanted])
    return PositionsFound(g, pm, A, D, gr, xr, kept, warnings + shallow, [sol], names)


def coupler_cuts(g: CouplerDesign, pm: CouplerPositions) -> list[tuple[str, float, tuple[str, ...]]]:
    """Where the coupler form's pivots are cut: two bisectors, or a bisector and the frame line."""
    b = g.bisectors
    at_A, at_D = ("lAB", "lAD", "xA", "yA"), ("lCD", "lAD", "xD", "yD")
    if pm.frame is None:
        return [(f"A = {b[0].label} ∩ {b[1].label}", lines_sin(b[0].line, b[1].line), at_A),
                (f"D = {b[2].label} ∩ {b[3].label}", lines_sin(b[2].line, b[3].line), at_D)]
    (fx, fy), ang = pm.frame
    frame = (fx, fy, math.cos(ang), math.sin(ang))
    return [(f"A = {b[0].label} ∩ frame line", lines_sin(b[0].line, frame), at_A),
            (f"D = {b[1].label} ∩ frame line", lines_sin(b[1].line, frame), at_D)]


#: The task's protocol names (:data:`graphmech.problems.synthesis.check.SELF_CONTAINED`).
analyse = analyse_positions


def lines(pf: PositionsFound | inversions.InversionFound) -> list[str]:
    """Under the table: the design's Grashof class, re-analysis error and note."""
    if isinstance(pf, inversions.InversionFound):
        return inversions.lines(pf)
    return [inversions.design_line(s) for s in pf.solutions]


def panels(pf: PositionsFound | inversions.InversionFound, mu: float) -> tuple[str, list[Panel]]:
    """The sheet's title and its one panel: the construction with the design bold."""
    if isinstance(pf, inversions.InversionFound):
        return inversions.panels(pf, mu)
    from graphmech.drawing.primitives import Panel

    name = panel_title(pf)
    return name, [Panel("design", name, tuple(coupler_items(pf)), notes(pf, mu), row=0, scales=(("l", mu),))]


__all__ = [
    "COUPLER_NAMES",
    "PHRASES",
    "CouplerPositions",
    "PositionsFound",
    "PositionsProblem",
    "analyse",
    "analyse_positions",
    "choose_scale",
    "coupler_items",
    "exact_pivots",
    "lines",
    "notes",
    "panels",
    "read_positions",
    "size",
    "steps",
]


def coupler_items(pf: PositionsFound) -> list[Primitive]:
    """The figure as the book draws it: the given positions B_iC_i, the perpendicular bisectors
    to the pivots and the arcs about A through the B_i, about D through the C_i thin; the designed
    linkage bold at position 1 (A B₁ C₁ D)."""
    from graphmech.drawing.primitives import FixedPivot, Hinge, Label, Segment
    from graphmech.methods.synthesis_positions import FourbarDesign

    if isinstance(pf.drawn, FourbarDesign):
        return fourbar_items(pf.drawn)
    g, pm = pf.drawn, pf.mm
    assert isinstance(pm, CouplerPositions)
    n = len(pm.B)
    items: list[Primitive] = []
    for b in g.bisectors:  # from the chord's midpoint on through the pivot it meets
        mid = b.line[:2]
        pivot = g.A if b.label.startswith("bB") else g.D
        t = (pivot[0] - mid[0]) * b.line[2] + (pivot[1] - mid[1]) * b.line[3]
        ext = 8.0 if t >= 0 else -8.0
        items.append(Segment((mid[0] - 0.3 * ext * b.line[2], mid[1] - 0.3 * ext * b.line[3]),
                             (mid[0] + (t + ext) * b.line[2], mid[1] + (t + ext) * b.line[3]), "construction"))
        items.append(Segment(b.ends[0], b.ends[1], "construction", dashed=True))
    for centre, pts in ((g.A, pm.B), (g.D, pm.C)):
        items.append(inversions.arc_about(centre, list(pts)))
    if pm.frame is not None:
        (fx, fy), ang = pm.frame
        u = (math.cos(ang), math.sin(ang))
        ts = [(q[0] - fx) * u[0] + (q[1] - fy) * u[1] for q in (g.A, g.D)]
        lo, hi = min(ts) - 10.0, max(ts) + 10.0
        items.append(Segment((fx + lo * u[0], fy + lo * u[1]), (fx + hi * u[0], fy + hi * u[1]), "construction",
                             dashdot=True))
    for i in range(1, n):  # the other positions as given, dashed
        items += [Segment(pm.B[i], pm.C[i], "given", dashed=True), Hinge(pm.B[i]), Hinge(pm.C[i])]
    B1, C1 = pm.B[0], pm.C[0]
    items += [Segment(g.A, B1, "result"), Segment(B1, C1, "result"), Segment(C1, g.D, "result"),
              Segment(g.A, g.D, "construction", dashdot=True), FixedPivot(g.A), FixedPivot(g.D), Hinge(B1), Hinge(C1),
              Label("A", g.A, (unit(g.A, B1), unit(g.A, g.D))), Label("D", g.D, (unit(g.D, C1), unit(g.D, g.A)))]
    items += [Label(f"B_{{{i + 1}}}", pm.B[i]) for i in range(n)] + [Label(f"C_{{{i + 1}}}", pm.C[i]) for i in range(n)]
    return items


def fourbar_items(g: FourbarDesign) -> list[Primitive]:
    """The inversion as the book draws it: the input AB_i and the output's turns given, each B_i
    turned back about D on a thin arc to B_i′, the bisectors of B₁B₂′ (B₂′B₃′) to C₁ (with two,
    the arc of l_CD about D), the four-bar A B₁ C₁ D bold."""
    from graphmech.drawing.primitives import (
        Circle,
        FixedPivot,
        Hinge,
        Label,
        Segment,
    )

    j = g.construction
    items: list[Primitive] = []
    for v in j.inversions:  # the arc of the turn back about D, from B_i to B_i′
        assert v.centre is not None
        items.append(inversions.turn_arc(v.centre, v.original, v.angle))
        items += [Segment(g.A, v.original, "given", dashed=True), Segment(g.D, v.image, "construction", dashed=True),
                  Segment(g.D, v.original, "construction", dashed=True), Hinge(v.original), Hinge(v.image),
                  Label(f"{v.label[0]}_{{{v.label[1:-1]}}}′", v.image),
                  Label(f"{v.label[0]}_{{{v.label[1:-1]}}}", v.original)]
    items += inversions.bisector_items(j.bisectors, g.C1)
    items += [Circle(a.centre, a.radius, "construction") for a in j.arcs]
    items += [Segment(g.A, g.B1, "result"), Segment(g.B1, g.C1, "result"), Segment(g.C1, g.D, "result"),
              Segment(g.A, g.D, "construction", dashdot=True), FixedPivot(g.A), FixedPivot(g.D), Hinge(g.B1),
              Hinge(g.C1), Label("A", g.A, (unit(g.A, g.B1), unit(g.A, g.D))),
              Label("D", g.D, (unit(g.D, g.C1), unit(g.D, g.A))), Label("B_{1}", g.B1), Label("C_{1}", g.C1)]
    return items


def panel_title(pf: PositionsFound) -> str:
    """The panel's (and a title-less sheet's) name."""
    return ("Four-bar from corresponding positions, by inversion" if isinstance(pf.mm, FourbarPositions)
            else "Coupler through given positions")


def notes(pf: PositionsFound, mu: float) -> tuple[str, ...]:
    """The dimensions under the panel, measured at μl."""
    from graphmech.drawing.lettering import number, scale_text

    g = pf.drawn
    return (scale_text("l", mu),
            (f"l_{{AB}} = {number(g.l_AB * mu * 1000)} mm, l_{{BC}} = {number(g.l_BC * mu * 1000)} mm, "
             f"l_{{CD}} = {number(g.l_CD * mu * 1000)} mm, l_{{AD}} = {number(g.l_AD * mu * 1000)} mm"))


#: The positions task's phrases: key → (English, 中文, русский). 孙桓 §8: 按连杆给定位置设计.
PHRASES: dict[str, tuple[str, str, str]] = {
    **inversions.PHRASES,
    "given": ("draw the coupler's {n} given positions B_iC_i (BC = {mm} mm)",
              "画出连杆的{n}个给定位置B_iC_i（BC = {mm} mm）",
              "строим {n} заданных положения шатуна B_iC_i (BC = {mm} mm)"),
    "three": (("A is the centre of the circle through B₁, B₂, B₃: the perpendicular bisectors of B₁B₂ and B₂B₃ "
               "meet at A; D likewise from C₁, C₂, C₃"),
              "A为过B₁、B₂、B₃之圆的圆心：B₁B₂与B₂B₃的中垂线交于A；同理由C₁、C₂、C₃得D",
              ("A — центр окружности через B₁, B₂, B₃: серединные перпендикуляры к B₁B₂ и B₂B₃ пересекаются в A; "
               "D так же из C₁, C₂, C₃")),
    "two": ("the frame line cuts the perpendicular bisector of B₁B₂ at A and that of C₁C₂ at D",
            "机架线与B₁B₂的中垂线交于A，与C₁C₂的中垂线交于D",
            "линия стойки пересекает серединный перпендикуляр к B₁B₂ в A, к C₁C₂ — в D"),
    "measure": ("measure AB₁ = {a} mm, C₁D = {c} mm, AD = {d} mm: l_AB = {la} m, l_CD = {lc} m, l_AD = {ld} m",
                "量得AB₁ = {a} mm，C₁D = {c} mm，AD = {d} mm：l_AB = {la} m，l_CD = {lc} m，l_AD = {ld} m",
                "измеряем AB₁ = {a} mm, C₁D = {c} mm, AD = {d} mm: l_AB = {la} m, l_CD = {lc} m, l_AD = {ld} m"),
    "inputs": ("draw A, D and the input AB_i (AB = {mm} mm) at its {n} given angles φ_i",
               "作A、D及输入杆的{n}个给定位置AB_i（AB = {mm} mm）",
               "строим A, D и входное звено AB_i (AB = {mm} mm) в {n} заданных углах φ_i"),
    "invert three": (("turn each B_i about D back by the output's turn ψ_i − ψ₁ to B_i′ (the inversion); "
                      "C₁ is the centre of the circle through B₁, B₂′, B₃′: the bisectors of B₁B₂′ and B₂′B₃′ meet there"),
                     "将各B_i绕D反转ψ_i − ψ₁得B_i′（反转法）；B₁、B₂′、B₃′所定圆之圆心即C₁：B₁B₂′与B₂′B₃′的中垂线交于C₁",
                     ("каждую B_i поворачиваем около D назад на ψ_i − ψ₁ в B_i′ (обращение движения); C₁ — центр "
                      "окружности через B₁, B₂′, B₃′: серединные перпендикуляры к B₁B₂′ и B₂′B₃′ пересекаются в C₁")),
    "invert two": (("turn B₂ about D back by ψ₂ − ψ₁ to B₂′ (the inversion); the arc of radius l_CD = {c} mm "
                    "about D cuts the bisector of B₁B₂′ at C₁"),
                   "将B₂绕D反转ψ₂ − ψ₁得B₂′（反转法）；以D为圆心、l_CD = {c} mm为半径作弧，与B₁B₂′的中垂线交于C₁",
                   ("B₂ поворачиваем около D назад на ψ₂ − ψ₁ в B₂′ (обращение движения); дуга радиуса "
                    "l_CD = {c} mm около D пересекает серединный перпендикуляр к B₁B₂′ в C₁")),
    "measure C": ("measure B₁C₁ = {b} mm, C₁D = {c} mm: l_BC = {lb} m, l_CD = {lc} m",
                  "量得B₁C₁ = {b} mm，C₁D = {c} mm：l_BC = {lb} m，l_CD = {lc} m",
                  "измеряем B₁C₁ = {b} mm, C₁D = {c} mm: l_BC = {lb} m, l_CD = {lc} m"),
    "recheck": ("check: the four-bar driven through the positions reaches them to {err} (of its longest link)",
                "校核：该四杆机构经过给定位置，误差{err}（相对最长杆）",
                "проверка: четырёхзвенник проходит заданные положения с погрешностью {err} (от длиннейшего звена)"),
}


def steps(pf: PositionsFound | inversions.InversionFound, mu: float, say: Callable[..., str],
          num: Callable[[float], str]) -> list[str]:
    """The construction protocol's lines after μl is chosen: the numbers the check's rows read."""
    if isinstance(pf, inversions.InversionFound):
        return inversions.steps(pf, mu, say, num)
    g = pf.drawn
    if isinstance(pf.mm, FourbarPositions):
        n = len(pf.mm.phi)
        return [say("inputs", n=str(n), mm=num(pf.mm.l_AB)),
                say("invert three" if n == 3 else "invert two", **({} if pf.mm.l_CD is None else {"c": num(pf.mm.l_CD)})),
                say("measure C", b=num(g.l_BC), c=num(g.l_CD), lb=num(g.l_BC * mu), lc=num(g.l_CD * mu)),
                say("recheck", err=f"{pf.exact_re.error:.1e}")]
    assert isinstance(pf.mm, CouplerPositions)
    return [say("given", n=str(len(pf.mm.B)), mm=num(g.l_BC)), say("three" if pf.mm.frame is None else "two"),
            say("measure", a=num(g.l_AB), c=num(g.l_CD), d=num(g.l_AD), la=num(g.l_AB * mu),
                lc=num(g.l_CD * mu), ld=num(g.l_AD * mu)),
            say("recheck", err=f"{pf.exact_re.error:.1e}")]
