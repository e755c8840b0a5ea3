"""The synthesis task ``positions``: a coupler led through two or three given positions.

Read: ``[[synthesis.position]]`` tables, each the coupler's joints ``B`` and ``C`` (points); with
two positions the frame line ``frame_through`` (a point) and ``frame_angle`` (its direction).
Analysed: the construction (:func:`graphmech.methods.synthesis_positions.coupler_positions`, the
perpendicular bisectors of B₁B₂, B₂B₃ meet at A, of C₁C₂, C₂C₃ at D) drawn at μl, its lengths and
pivots measured against the exact circumcentres (:mod:`graphmech.exact.synthesis_positions`), and
both designs re-analysed through the positions (the re-analysis error, γ_min), Grashof's class and
the note (no Grashof crank; positions on two branches) said under the table.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from graphmech.errors import GraphmechError, SceneError

if TYPE_CHECKING:
    from graphmech.drawing.primitives import Primitive
    from graphmech.exact.synthesis_positions import Reanalysis
    from graphmech.methods.synthesis_positions import CouplerDesign
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


def read_positions(r: Reader) -> CouplerPositions | None:
    """``[[synthesis.position]]`` with B and C; ``frame_through``, ``frame_angle`` with two."""
    tables = r.tables_at("position")
    B: list[XY] = []
    C: list[XY] = []
    for t in tables:
        b, c = t.pair("B"), t.pair("C")
        t.finish()
        if b is not None and c is not None:
            B.append(b)
            C.append(c)
    key = r.at("position")
    if len(tables) not in (2, 3):
        r.problem(key, f"give two or three [[{key}]] tables (the coupler's positions), not {len(tables)}")
    through = r.pair("frame_through", required=False)
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


def size(p: CouplerPositions) -> float:
    """The drawing's spread, m: the given points and the pivots (where they exist; a refusal is
    said by the analysis)."""
    pts = [*p.B, *p.C]
    try:
        pts += [(z.real, z.imag) for z in exact_pivots(p)]
    except GraphmechError:
        pass
    xs, ys = [x for x, _ in pts], [y for _, y in pts]
    return max(max(xs) - min(xs), max(ys) - min(ys))


def choose_scale(p: CouplerPositions) -> float:
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

    def on_line(Q1: complex, Q2: complex) -> complex:
        # |P + tu − Q1|² = |P + tu − Q2|²: linear in t
        den = 2.0 * ((Q2 - Q1) * u.conjugate()).real
        if den == 0.0:
            raise GraphmechError("the frame line runs along a bisector: it does not cut it")
        return P + u * (abs(Q2 - P) ** 2 - abs(Q1 - P) ** 2) / den

    return on_line(B[0], B[1]), on_line(C[0], C[1])


@dataclass
class PositionsFound:
    """The drawn design (mm), the exact pivots, both re-analyses, the rows, the warnings and what
    ``check --json`` adds."""

    drawn: CouplerDesign
    mm: CouplerPositions
    A: complex
    D: complex
    drawn_re: Reanalysis
    exact_re: Reanalysis
    rows: list[Row]
    warnings: list[str]
    solutions: list[dict[str, Any]]
    names: list[str]


def analyse_positions(p: CouplerPositions, mu: float, find: tuple[str, ...] = (), source: str = "") -> PositionsFound:
    """The construction at μl = ``mu`` against the exact pivots, both re-analysed."""
    from graphmech.exact.synthesis_positions import reanalyse_coupler
    from graphmech.methods.synthesis_positions import coupler_positions
    from graphmech.problems.judging import Row

    def mm(q: XY) -> XY:
        return (q[0] / mu, q[1] / mu)

    pm = CouplerPositions(tuple(mm(b) for b in p.B), tuple(mm(c) for c in p.C),
                          None if p.frame is None else (mm(p.frame[0]), p.frame[1]), p.key)
    try:
        coupler_positions(p.B, p.C, p.frame)  # refused in metres, as given
        g = coupler_positions(pm.B, pm.C, pm.frame)
        A, D = exact_pivots(p)
    except GraphmechError as e:
        raise SceneError([(p.key, str(e))], source) from None
    B = [complex(*b) for b in p.B]
    C = [complex(*c) for c in p.C]
    xr = reanalyse_coupler(A, D, B, C)
    gr = reanalyse_coupler(complex(*g.A) * mu, complex(*g.D) * mu, B, C)
    ex = {"lAB": abs(B[0] - A), "lBC": abs(C[0] - B[0]), "lCD": abs(C[0] - D), "lAD": abs(D - A),
          "xA": A.real, "yA": A.imag, "xD": D.real, "yD": D.imag}
    dr = {"lAB": g.l_AB, "lBC": g.l_BC, "lCD": g.l_CD, "lAD": g.l_AD, "xA": g.A[0], "yA": g.A[1],
          "xD": g.D[0], "yD": g.D[1]}
    size_m = max(ex["lAB"], ex["lBC"], ex["lCD"], ex["lAD"])
    rows = [Row(n, "m", dr[n], mu, dr[n] * mu, ex[n], abs(dr[n] * mu - ex[n]) / size_m) for n in dr]
    rows.append(Row("reanalysis_error", "", None, 1.0, gr.error, xr.error, abs(gr.error - xr.error)))
    names = [*dr, "reanalysis_error"]
    if gr.characteristics is not None and xr.characteristics is not None:
        gg, ge = gr.characteristics.gamma_min, xr.characteristics.gamma_min
        rows.append(Row("gamma_min", "deg", None, 1.0, math.degrees(gg), math.degrees(ge), abs(gg - ge) / math.pi))
        names.append("gamma_min")
    warnings = [xr.note] if xr.note else []
    sol = {"name": "design", **{n: ex[n] for n in ("lAB", "lBC", "lCD", "lAD")}, "A": [A.real, A.imag],
           "D": [D.real, D.imag], "grashof": xr.grashof, "branch": xr.branch, "one_branch": xr.one_branch,
           "reanalysis": {"error": xr.error, "gamma_deg": [math.degrees(x) for x in xr.gamma],
                          **({} if xr.characteristics is None
                             else {"gamma_min_deg": math.degrees(xr.characteristics.gamma_min)})},
           "note": xr.note}
    wanted = set(find) or None
    return PositionsFound(g, pm, A, D, gr, xr, [r for r in rows if wanted is None or r.name in wanted], warnings,
                          [sol], names)


def grashof_line(s: dict[str, Any]) -> str:
    """The design said under the table: Grashof's class, the re-analysis error, the note."""
    cls = str(s["grashof"]).replace("_", " ")
    note = f"; {s['note']}" if s["note"] else ""
    return (f"design: l_AB = {s['lAB'] * 1000:.6g} mm, l_BC = {s['lBC'] * 1000:.6g} mm, l_CD = {s['lCD'] * 1000:.6g} mm, "
            f"l_AD = {s['lAD'] * 1000:.6g} mm: {cls}; re-analysed through the positions: error "
            f"{s['reanalysis']['error']:.1e}{note}")


__all__ = [
    "COUPLER_NAMES",
    "PHRASES",
    "CouplerPositions",
    "PositionsFound",
    "analyse_positions",
    "choose_scale",
    "coupler_items",
    "exact_pivots",
    "grashof_line",
    "notes",
    "read_positions",
    "size",
    "steps",
]


def coupler_items(pf: PositionsFound) -> list[Primitive]:
    """The figure as the book draws it: the given positions B_iC_i, the perpendicular bisectors
    to the pivots and the arcs about A through the B_i, about D through the C_i thin; the designed
    linkage bold at position 1 (A B₁ C₁ D)."""
    from graphmech.drawing.primitives import FixedPivot, Hinge, Label, Segment

    g, pm = pf.drawn, pf.mm
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
        items.append(_arc_through(centre, pts))
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
              Label("A", g.A, (_unit(g.A, B1), _unit(g.A, g.D))), Label("D", g.D, (_unit(g.D, C1), _unit(g.D, g.A)))]
    items += [Label(f"B_{{{i + 1}}}", pm.B[i]) for i in range(n)] + [Label(f"C_{{{i + 1}}}", pm.C[i]) for i in range(n)]
    return items


def notes(pf: PositionsFound, mu: float) -> tuple[str, ...]:
    """The dimensions under the panel, measured at μl."""
    from graphmech.drawing.lettering import number, scale_text

    g = pf.drawn
    return (scale_text("l", mu),
            (f"l_{{AB}} = {number(g.l_AB * mu * 1000)} mm, l_{{BC}} = {number(g.l_BC * mu * 1000)} mm, "
             f"l_{{CD}} = {number(g.l_CD * mu * 1000)} mm, l_{{AD}} = {number(g.l_AD * mu * 1000)} mm"))


def _unit(p: XY, q: XY) -> XY:
    n = math.hypot(q[0] - p[0], q[1] - p[1]) or 1.0
    return ((q[0] - p[0]) / n, (q[1] - p[1]) / n)


def _arc_through(centre: XY, pts: tuple[XY, ...]) -> Primitive:
    """The thin arc about ``centre`` through the points, a little past the first and the last."""
    from graphmech.drawing.primitives import Polyline

    r = math.hypot(pts[0][0] - centre[0], pts[0][1] - centre[1])
    a = [math.atan2(q[1] - centre[1], q[0] - centre[0]) for q in pts]
    a = [a[0] + math.remainder(x - a[0], 2 * math.pi) for x in a]
    lo, hi = min(a) - 0.12, max(a) + 0.12
    return Polyline(tuple((centre[0] + r * math.cos(lo + (hi - lo) * k / 40), centre[1] + r * math.sin(lo + (hi - lo) * k / 40))
                          for k in range(41)), "construction")


#: The positions task's phrases: key → (English, 中文, русский). 孙桓 §8: 按连杆给定位置设计.
PHRASES: dict[str, tuple[str, str, str]] = {
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
    "recheck": ("check: the four-bar driven through the positions reaches them to {err} (of its longest link)",
                "校核：该四杆机构经过给定位置，误差{err}（相对最长杆）",
                "проверка: четырёхзвенник проходит заданные положения с погрешностью {err} (от длиннейшего звена)"),
}


def steps(pf: PositionsFound, mu: float, say: Callable[..., str], num: Callable[[float], str]) -> list[str]:
    """The construction protocol's lines after μl is chosen: the numbers the check's rows read."""
    g = pf.drawn
    return [say("given", n=str(len(pf.mm.B)), mm=num(g.l_BC)), say("three" if pf.mm.frame is None else "two"),
            say("measure", a=num(g.l_AB), c=num(g.l_CD), d=num(g.l_AD), la=num(g.l_AB * mu),
                lc=num(g.l_CD * mu), ld=num(g.l_AD * mu)),
            say("recheck", err=f"{pf.exact_re.error:.1e}")]
