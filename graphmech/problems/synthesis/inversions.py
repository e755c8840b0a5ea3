"""The positions forms found by inversion on a slider, a rocker or a coupler (``task = "positions"``).

slider-crank through crank and slider positions
    ``A``, ``l_AB``, the crank's angles ``phi`` and the slider's displacements ``s`` along the
    guide (``guide_angle``; with two positions the pin's path ``guide_through``): seen from the
    slider the frame translates back, B_i shifted by −(s_i − s₁) to B_i′, the pin C₁ the centre of
    the circle through B₁, B₂′, B₃′ (:func:`graphmech.methods.synthesis_positions.slider_crank_positions`).
a rocker leading a slider (seed 000 连杆 4)
    ``D`` and ``[[synthesis.position]]`` tables of the rocker's end ``C`` and the slider's ``F``:
    seen from the rocker the frame turns back, F_i turned about D to F_i′, the joint E the centre
    of the circle through them, the figure drawn in the position ``invert_to`` (the seed's
    "转至位置2作图") (:func:`~graphmech.methods.synthesis_positions.joint_by_inversion`).
a coupler point through three points (seed 000 连杆 5)
    ``A``, ``D``, ``l_CD``, ``l_EC`` and tables of ``E``: the arcs give C_i; seen from the coupler
    CE the pivot A moves, carried back to A₂′, A₃′; B₁ the centre of the circle through A, A₂′,
    A₃′ (:func:`~graphmech.methods.synthesis_positions.fourbar_through_coupler_points`).

Each is drawn at μl, its lengths measured against :mod:`graphmech.exact.synthesis_positions`
(complex rotation, translation and the circumcentre's linear equations) and re-analysed there
through the prescribed positions.
"""
from __future__ import annotations

import cmath
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from graphmech.errors import GraphmechError, SceneError
from graphmech.problems.reader import MISSING
from graphmech.problems.synthesis.common import (
    arcs_sin,
    conditioning,
    design_rows,
    exact_joint,
    line_arc_sin,
    lines_sin,
    on_line,
    read_angles,
    read_length,
    read_lengths,
    read_point,
    read_side,
    unit,
)

if TYPE_CHECKING:
    from graphmech.drawing.primitives import Panel, Primitive
    from graphmech.exact.synthesis_positions import Reanalysis
    from graphmech.methods.synthesis_positions import (
        Bisector,
        CouplerPointDesign,
        JointDesign,
        SliderCrankDesign,
    )
    from graphmech.problems.judging import Row
    from graphmech.problems.reader import Reader

XY = tuple[float, float]
Cut = tuple[str, float, tuple[str, ...]]
#: |sin| of the angle at F₁ below which the slider's three positions count as on one line.
COLLINEAR_SIN = 1e-9


@dataclass(frozen=True)
class SliderCrankPositions:
    """The crank AB at φ_i and the slider at s_i along the guide (angle ``guide_angle``; with two
    positions the pin's path through ``through``), m and rad."""

    A: XY
    l_AB: float
    phi: tuple[float, ...]
    s: tuple[float, ...]
    guide_angle: float
    through: XY | None
    key: str


@dataclass(frozen=True)
class RockerSliderPositions:
    """The rocker DC_i and the slider's F_i (m); the figure turned to position ``invert_to``
    (1-based); with two positions l_DE and the side of the bisector's cut."""

    D: XY
    C: tuple[XY, ...]
    F: tuple[XY, ...]
    invert_to: int
    l_DE: float | None
    side: float
    key: str


@dataclass(frozen=True)
class CouplerPointPositions:
    """The pivots A, D, the coupler point's E_i, l_CD, l_EC (m) and each C_i's side of D → E_i."""

    A: XY
    D: XY
    E: tuple[XY, ...]
    l_CD: float
    l_EC: float
    side: tuple[float, ...]
    key: str


Form = SliderCrankPositions | RockerSliderPositions | CouplerPointPositions


# --------------------------------------------------------------------------------- the readers


def read_slider_crank(r: Reader) -> SliderCrankPositions | None:
    """``A``, ``l_AB``, ``phi``, ``s``, ``guide_angle`` (with two positions ``guide_through``)."""
    A, a = read_point(r, "A"), read_length(r, "l_AB")
    phi, s = read_angles(r, "phi"), read_lengths(r, "s")
    guide = r.scalar("guide_angle", "angle")
    through = read_point(r, "guide_through", required=False)
    key = r.at(r.present("s") or "s")
    if phi is not None and s is not None and len(phi) != len(s):
        r.problem(key, f"{len(s)} slider positions for {len(phi)} crank angles: give as many of each")
        return None
    if phi is not None and len(phi) == 2 and through is None and r.present("guide_through") is None:
        r.problem(r.at("guide_through"), "with two positions the pin C₁ lies anywhere on the bisector: give "
                                         "guide_through_mm (a point of the pin's path)")
    if phi is not None and len(phi) == 3 and r.present("guide_through") is not None:
        r.problem(r.at(r.present("guide_through") or "guide_through"),
                  "three positions fix the slider's pin: no guide_through is taken")
    if A is None or a is None or phi is None or s is None or guide is None or (len(phi) == 2 and through is None):
        return None
    return SliderCrankPositions(A, a, phi, s, guide, through if len(phi) == 2 else None, key)


def _tables(r: Reader, names: tuple[str, ...], counts: tuple[int, ...]) -> list[tuple[XY, ...]] | None:
    """The ``[[synthesis.position]]`` tables' points ``names``, or None after saying why not."""
    tables = r.tables_at("position")
    got: list[tuple[XY, ...]] = []
    for t in tables:
        pts = [read_point(t, n) for n in names]
        t.finish()
        if all(p is not None for p in pts):
            got.append(tuple(p for p in pts if p is not None))
    if len(tables) not in counts:
        r.problem(r.at("position"), f"give {' or '.join(('two', 'three')[c - 2] for c in counts)} "
                                    f"[[{r.at('position')}]] tables, not {len(tables)}")
        return None
    return got if len(got) == len(tables) else None


def read_rocker_slider(r: Reader) -> RockerSliderPositions | None:
    """``D``, the tables' ``C`` and ``F``, ``invert_to`` (with two positions ``l_DE``, ``side``)."""
    D = read_point(r, "D")
    pts = _tables(r, ("C", "F"), (2, 3))
    raw = r.raw("invert_to")
    n = len(pts) if pts is not None else 3
    k = 1
    if raw is not MISSING:
        if isinstance(raw, bool) or raw not in range(1, n + 1):
            r.problem(r.at("invert_to"), f"must be the number of a position, 1 to {n} (the rocker held still there)")
            return None
        k = int(raw)  # type: ignore[call-overload]
    l_DE = read_length(r, "l_DE", required=False)
    side = read_side(r, "E ahead of or behind the foot of D on the bisector")
    if pts is not None and len(pts) == 2 and l_DE is None and r.present("l_DE") is None:
        r.problem(r.at("l_DE"), "with two positions E lies anywhere on the bisector: give l_DE_mm (D to E on the rocker)")
    if pts is not None and len(pts) == 3 and (r.present("l_DE") or r.present("side")):
        r.problem(r.at(r.present("l_DE") or "side"), "three positions fix E: no l_DE or side is taken")
    if D is None or pts is None or side is None or (len(pts) == 2 and l_DE is None):
        return None
    key = r.at("position")
    C, F = tuple(p[0] for p in pts), tuple(p[1] for p in pts)
    arms = [math.dist(D, c) for c in C]
    if min(arms) <= 0.0 or max(arms) - min(arms) > 1e-9 * max(arms):
        r.problem(key, f"the rocker is not rigid: DC_i = {', '.join(f'{x:.6g}' for x in arms)} m differ")
        return None
    size = max(arms) + max(math.dist(f, D) for f in F)
    for i in range(len(C)):
        for j in range(i + 1, len(C)):
            if math.dist(C[i], C[j]) <= 1e-12 * size:
                r.problem(key, f"C{i + 1} and C{j + 1} coincide: the rocker must turn from one position to the next")
                return None
    if max(math.dist(f, g) for f in F for g in F) <= 1e-12 * size:
        r.problem(key, "the slider's positions coincide: it stands still, no guide and no coupler are found")
        return None
    if len(F) == 3:
        u, v = (F[1][0] - F[0][0], F[1][1] - F[0][1]), (F[2][0] - F[0][0], F[2][1] - F[0][1])
        if abs(u[0] * v[1] - u[1] * v[0]) > COLLINEAR_SIN * math.hypot(*u) * math.hypot(*v):
            r.problem(key, "F1, F2, F3 do not lie on one straight line: the slider moves on a straight guide")
            return None
    return RockerSliderPositions(D, C, F, k, l_DE if len(pts) == 2 else None, side, key)


def read_coupler_point(r: Reader) -> CouplerPointPositions | None:
    """``A``, ``D``, ``l_CD``, ``l_EC``, ``side`` (one or three) and three tables of ``E``."""
    A, D = read_point(r, "A"), read_point(r, "D")
    c, e = read_length(r, "l_CD"), read_length(r, "l_EC")
    pts = _tables(r, ("E",), (3,))
    raw = r.raw("side")
    sides: tuple[float, ...] | None = (1.0, 1.0, 1.0)
    if raw is not MISSING:
        xs = raw if isinstance(raw, list) else [raw]
        if len(xs) not in (1, 3) or any(isinstance(x, bool) or x not in (1, -1) for x in xs):
            r.problem(r.at("side"), "must be 1 or -1, or a list of three (C_i left or right of D → E_i)")
            sides = None
        else:
            sides = tuple(1.0 if x == 1 else -1.0 for x in (xs * 3 if len(xs) == 1 else xs))
    if A is None or D is None or c is None or e is None or pts is None or sides is None:
        return None
    return CouplerPointPositions(A, D, tuple(p[0] for p in pts), c, e, sides, r.at("position"))


def read_form(r: Reader) -> Form | None:
    """The form the keys ask: ``s`` with ``phi`` a slider-crank, tables of ``F`` a rocker leading
    a slider, of ``E`` a coupler point (None: not one of these, for the caller's forms)."""
    if r.present("phi") is not None and r.present("s") is not None:
        return read_slider_crank(r)
    tables = r.table.get("position")
    first = tables[0] if isinstance(tables, list) and tables and isinstance(tables[0], dict) else {}
    if any(k == "F" or k.startswith("F_") for k in first):
        return read_rocker_slider(r)
    if any(k == "E" or k.startswith("E_") for k in first):
        return read_coupler_point(r)
    return None


def is_form(r: Reader) -> bool:
    """Whether the table asks one of this module's forms."""
    if r.present("phi") is not None and r.present("s") is not None:
        return True
    tables = r.table.get("position")
    first = tables[0] if isinstance(tables, list) and tables and isinstance(tables[0], dict) else {}
    return any(k in ("E", "F") or k.startswith(("E_", "F_")) for k in first)


# --------------------------------------------------------------------------------- the exact side


def _z(p: XY) -> complex:
    return complex(p[0], p[1])


def _xy(z: complex) -> XY:
    return (z.real, z.imag)


def exact_slider_pin(p: SliderCrankPositions) -> complex:
    """C₁ by the exact side: B_i translated back by −(s_i − s₁) along the guide; the circumcentre
    of B₁, B₂′, B₃′ or, with two, the pin's path cut by the bisector of B₁B₂′."""
    from graphmech.exact.synthesis_positions import circumcentre

    A, g = _z(p.A), cmath.exp(1j * p.guide_angle)
    im = [A + p.l_AB * cmath.exp(1j * f) - (x - p.s[0]) * g for f, x in zip(p.phi, p.s)]
    if len(im) == 3:
        return circumcentre(*im)
    assert p.through is not None
    return on_line(_z(p.through), g, im[0], im[1])


def _order(p: RockerSliderPositions) -> list[int]:
    """The positions in the order the construction takes them: the one turned to first."""
    k = p.invert_to - 1
    return [k, *(i for i in range(len(p.F)) if i != k)]


def rocker_angles(p: RockerSliderPositions) -> list[float]:
    """The rocker's angle at each position (of DC_i, rad), unwrapped from position 1."""
    a = [math.atan2(c[1] - p.D[1], c[0] - p.D[0]) for c in p.C]
    return [a[0] + math.remainder(x - a[0], 2 * math.pi) for x in a]


def exact_rocker_joint(p: RockerSliderPositions, near: complex | None = None) -> complex:
    """E at the position turned to, by the exact side (each F_i turned back about D)."""
    rot, order = rocker_angles(p), _order(p)
    return exact_joint([_z(p.F[i]) for i in order], _z(p.D), [rot[i] for i in order], p.l_DE, near)


def exact_coupler_point(p: CouplerPointPositions) -> tuple[list[complex], list[complex]]:
    """C_i (the circles l_CD about D and l_EC about E_i, on the side asked) and B_i by the exact
    side: A carried with the coupler to position 1, B₁ the circumcentre of A, A₂′, A₃′, carried on."""
    from graphmech.exact.synthesis_positions import circumcentre

    D, A = _z(p.D), _z(p.A)
    C = []
    for Ei, side in zip(p.E, p.side):
        d = _z(Ei) - D
        if d == 0:
            raise GraphmechError("a point E_i on D: the arcs about D and E_i are concentric, they do not cut")
        along = (p.l_CD ** 2 - p.l_EC ** 2 + abs(d) ** 2) / (2 * abs(d))
        h2 = p.l_CD ** 2 - along ** 2
        if h2 < 0.0:
            raise GraphmechError(f"the arcs about D and E do not meet ({abs(d):.6g} m apart)")
        u = d / abs(d)
        C.append(D + u * (along + 1j * side * math.sqrt(h2)))
    E = [_z(e) for e in p.E]

    def carry(z: complex, i: int, j: int) -> complex:  # with the coupler from position i to j
        return C[j] + (z - C[i]) * (E[j] - C[j]) / (E[i] - C[i])

    B1 = circumcentre(A, carry(A, 1, 0), carry(A, 2, 0))
    return C, [B1, carry(B1, 0, 1), carry(B1, 0, 2)]


# --------------------------------------------------------------------------------- the analysis


@dataclass
class InversionFound:
    """The drawn design (mm), the form in mm, the exact re-analysis, the rows, the warnings and
    what ``check --json`` adds."""

    drawn: SliderCrankDesign | JointDesign | CouplerPointDesign
    mm: Form
    exact_re: Reanalysis
    rows: list[Row]
    warnings: list[str]
    solutions: list[dict[str, Any]]
    names: list[str]


def _in_mm(p: Form, mu: float) -> Form:
    def m(q: XY) -> XY:
        return (q[0] / mu, q[1] / mu)

    if isinstance(p, SliderCrankPositions):
        return SliderCrankPositions(m(p.A), p.l_AB / mu, p.phi, tuple(x / mu for x in p.s), p.guide_angle,
                                    None if p.through is None else m(p.through), p.key)
    if isinstance(p, RockerSliderPositions):
        return RockerSliderPositions(m(p.D), tuple(map(m, p.C)), tuple(map(m, p.F)), p.invert_to,
                                     None if p.l_DE is None else p.l_DE / mu, p.side, p.key)
    return CouplerPointPositions(m(p.A), m(p.D), tuple(map(m, p.E)), p.l_CD / mu, p.l_EC / mu, p.side, p.key)


def _construct(p: Form) -> SliderCrankDesign | JointDesign | CouplerPointDesign:
    from graphmech.methods.synthesis_positions import (
        fourbar_through_coupler_points,
        joint_by_inversion,
        slider_crank_positions,
    )

    if isinstance(p, SliderCrankPositions):
        return slider_crank_positions(p.A, p.l_AB, p.phi, p.s, p.guide_angle, p.through)
    if isinstance(p, RockerSliderPositions):
        rot, order = rocker_angles(p), _order(p)
        return joint_by_inversion([p.F[i] for i in order], p.D, [rot[i] for i in order], "F", "E", p.l_DE, p.side,
                                  [i + 1 for i in order])
    return fourbar_through_coupler_points(p.A, p.D, p.E, p.l_CD, p.l_EC, p.side)


def _bisector_cuts(bis: tuple[Bisector, ...], joint: str, names: tuple[str, ...], arc: tuple[XY, XY] | None = None,
                   line: tuple[float, float, float, float] | None = None) -> list[Cut]:
    if len(bis) == 2:
        return [(f"{joint} = {bis[0].label} ∩ {bis[1].label}", lines_sin(bis[0].line, bis[1].line), names)]
    if arc is not None:
        return [(f"{joint} = arc ∩ {bis[0].label}", line_arc_sin(bis[0].line, *arc), names)]
    assert line is not None
    return [(f"{joint} = {bis[0].label} ∩ guide", lines_sin(bis[0].line, line), names)]


def analyse(p: Form, mu: float, find: tuple[str, ...] = (), source: str = "") -> InversionFound:
    """The construction at μl = ``mu`` against the exact side, both designs re-analysed."""
    from graphmech.exact.synthesis_positions import (
        reanalyse_coupler,
        reanalyse_rocker_slider,
        reanalyse_slider_crank,
    )
    from graphmech.methods.synthesis_positions import (
        CouplerPointDesign,
        JointDesign,
        SliderCrankDesign,
    )

    pm = _in_mm(p, mu)
    try:
        _construct(p)  # refused in metres, as given
        g = _construct(pm)
        if isinstance(p, SliderCrankPositions):
            assert isinstance(g, SliderCrankDesign) and isinstance(pm, SliderCrankPositions)
            C1 = exact_slider_pin(p)
            A, B1 = _z(p.A), _z(p.A) + p.l_AB * cmath.exp(1j * p.phi[0])
            gv = cmath.exp(1j * p.guide_angle)
            e = ((A - C1) * gv.conjugate()).imag  # + with A left of the guide's direction
            ex = {"lBC": abs(C1 - B1), "e": e, "xC1": C1.real, "yC1": C1.imag}
            dr = {"lBC": g.l_BC, "e": g.offset, "xC1": g.C1[0], "yC1": g.C1[1]}
            xr = reanalyse_slider_crank(A, p.l_AB, ex["lBC"], p.phi, p.s, p.guide_angle, C1)
            gr = reanalyse_slider_crank(A, p.l_AB, g.l_BC * mu, p.phi, p.s, p.guide_angle, _z(g.C1) * mu)
            size = max(p.l_AB, ex["lBC"])
            names: tuple[str, ...] = ("lBC", "e", "xC1", "yC1")
            g_line = (g.C1[0], g.C1[1], math.cos(p.guide_angle), math.sin(p.guide_angle))
            cuts = _bisector_cuts(g.construction.bisectors, "C1", names, line=g_line)
            sol = {"lAB": p.l_AB, "lBC": ex["lBC"], "e": e, "C1": [C1.real, C1.imag]}
        elif isinstance(p, RockerSliderPositions):
            assert isinstance(g, JointDesign) and isinstance(pm, RockerSliderPositions)
            k = p.invert_to - 1
            Ek = exact_rocker_joint(p, _z(g.joint) * mu)
            D, Fk = _z(p.D), _z(p.F[k])
            rot = rocker_angles(p)

            def first(E: complex) -> complex:  # E at position 1, from the position turned to
                return D + (E - D) * cmath.exp(1j * (rot[0] - rot[k]))

            ex = {"lDE": abs(Ek - D), "lEF": abs(Fk - Ek), "xE": Ek.real, "yE": Ek.imag}
            gE = _z(g.joint)
            dr = {"lDE": abs(gE - _z(pm.D)), "lEF": abs(_z(pm.F[k]) - gE), "xE": gE.real, "yE": gE.imag}
            F = [_z(f) for f in p.F]
            xr = reanalyse_rocker_slider(D, rot, first(Ek), F)
            gr = reanalyse_rocker_slider(D, rot, first(gE * mu), F)
            size = max(ex["lDE"], ex["lEF"])
            names = ("lDE", "lEF", "xE", "yE")
            cuts = _bisector_cuts(g.bisectors, f"E{p.invert_to}", names, arc=(pm.D, g.joint))
            sol = {"lDE": ex["lDE"], "lEF": ex["lEF"], f"E{p.invert_to}": [Ek.real, Ek.imag]}
        else:
            assert isinstance(g, CouplerPointDesign) and isinstance(pm, CouplerPointPositions)
            C, B = exact_coupler_point(p)
            A, D, E = _z(p.A), _z(p.D), [_z(x) for x in p.E]
            ex = {"lAB": abs(B[0] - A), "lBC": abs(C[0] - B[0]), "lBE": abs(E[0] - B[0]),
                  "xB1": B[0].real, "yB1": B[0].imag}
            dr = {"lAB": g.l_AB, "lBC": g.l_BC, "lBE": g.l_BE, "xB1": g.B[0][0], "yB1": g.B[0][1]}
            xr = reanalyse_coupler(A, D, B, C, E)
            gr = reanalyse_coupler(A, D, [_z(b) * mu for b in g.B], [_z(c) * mu for c in g.C], E)
            size = max(ex["lAB"], ex["lBC"], p.l_CD, abs(D - A))
            names = ("lAB", "lBC", "lBE", "xB1", "yB1")
            cuts = _bisector_cuts(g.construction.bisectors, "B1", names)
            cuts += [(f"C{i + 1} = arc D ∩ arc E{i + 1}", arcs_sin(pm.D, pm.E[i], g.C[i]), names) for i in range(3)]
            sol = {"lAB": ex["lAB"], "lBC": ex["lBC"], "lCD": p.l_CD, "lAD": abs(D - A), "lBE": ex["lBE"],
                   "lEC": p.l_EC, "B1": [B[0].real, B[0].imag], "C1": [C[0].real, C[0].imag]}
        rows, known = design_rows(dr, ex, mu, size, gr, xr)
    except GraphmechError as err:
        raise SceneError([(p.key, str(err))], source) from None
    wanted = set(find) or None
    kept, shallow = conditioning(cuts, [r for r in rows if wanted is None or r.name in wanted])
    sol = {"name": "design", **sol, "grashof": xr.grashof, "branch": xr.branch, "one_branch": xr.one_branch,
           "reanalysis": {"error": xr.error, "gamma_deg": [math.degrees(x) for x in xr.gamma],
                          **({} if xr.characteristics is None
                             else {"gamma_min_deg": math.degrees(xr.characteristics.gamma_min)})},
           "note": xr.note}
    return InversionFound(g, pm, xr, kept, ([xr.note] if xr.note else []) + shallow, [sol], known)


def size(p: Form) -> float:
    """The drawing's spread, m: the given points and the joints found (where they exist)."""
    pts: list[XY] = []
    try:
        if isinstance(p, SliderCrankPositions):
            g = cmath.exp(1j * p.guide_angle)
            pts = [p.A, *(_xy(_z(p.A) + p.l_AB * cmath.exp(1j * f)) for f in p.phi)]
            C1 = exact_slider_pin(p)
            pts += [_xy(C1 + (x - p.s[0]) * g) for x in p.s]
        elif isinstance(p, RockerSliderPositions):
            pts = [p.D, *p.C, *p.F]
            pts.append(_xy(exact_rocker_joint(p)))
        else:
            pts = [p.A, p.D, *p.E]
            C, B = exact_coupler_point(p)
            pts += [_xy(z) for z in (*C, *B)]
    except GraphmechError:
        pass  # said by the analysis
    xs, ys = [x for x, _ in pts], [y for _, y in pts]
    return max(max(xs) - min(xs), max(ys) - min(ys))


def lines(f: InversionFound) -> list[str]:
    """Under the table: the design's lengths, class and re-analysis error."""
    return [design_line(f.solutions[0])]


def design_line(s: dict[str, Any]) -> str:
    """A positions design said under the table (every form's, from its ``check --json`` record):
    the lengths it has, Grashof's class, the re-analysis error and the note."""
    mm = {k: f"{s[k] * 1000:.6g} mm" for k in ("lAB", "lBC", "lCD", "lAD", "lBE", "lEC", "lDE", "lEF", "e") if k in s}
    said = ", ".join(f"l_{k[1:]} = {v}" if k != "e" else f"e = {v}" for k, v in mm.items())
    cls = str(s["grashof"]).replace("_", " ")
    note = f"; {s['note']}" if s["note"] else ""
    return f"design: {said}: {cls}; re-analysed through the positions: error {s['reanalysis']['error']:.1e}{note}"


# --------------------------------------------------------------------------------- the figure


def _sub(label: str) -> str:
    """B2' → B_{2}′ (the lettering's subscript and prime)."""
    prime = label.endswith("'")
    core = label.rstrip("'")
    return f"{core[0]}_{{{core[1:]}}}" + ("′" if prime else "")


def bisector_items(bis: tuple[Bisector, ...], target: XY) -> list[Primitive]:
    """Each chord dashed and its perpendicular bisector thin, from a little before the chord's
    midpoint on through the point it finds."""
    from graphmech.drawing.primitives import Segment

    out: list[Primitive] = []
    for b in bis:
        mid = b.line[:2]
        t = (target[0] - mid[0]) * b.line[2] + (target[1] - mid[1]) * b.line[3]
        ext = 8.0 if t >= 0 else -8.0
        out += [Segment(b.ends[0], b.ends[1], "construction", dashed=True),
                Segment((mid[0] - 0.3 * ext * b.line[2], mid[1] - 0.3 * ext * b.line[3]),
                        (mid[0] + (t + ext) * b.line[2], mid[1] + (t + ext) * b.line[3]), "construction")]
    return out


def arc_about(centre: XY, pts: list[XY], margin: float = 0.12, n: int = 40) -> Primitive:
    """The thin arc about ``centre`` through the points, ``margin`` rad past the first and last."""
    from graphmech.drawing.primitives import Polyline

    r = math.hypot(pts[0][0] - centre[0], pts[0][1] - centre[1])
    a = [math.atan2(q[1] - centre[1], q[0] - centre[0]) for q in pts]
    a = [a[0] + math.remainder(x - a[0], 2 * math.pi) for x in a]
    lo, hi = min(a) - margin, max(a) + margin
    return Polyline(tuple((centre[0] + r * math.cos(lo + (hi - lo) * k / n), centre[1] + r * math.sin(lo + (hi - lo) * k / n))
                          for k in range(n + 1)), "construction")


def turn_arc(centre: XY, P: XY, angle: float) -> Primitive:
    """The thin arc of a turn about ``centre`` by ``angle`` (rad) from P: the inversion drawn."""
    from graphmech.drawing.primitives import Polyline

    r = math.hypot(P[0] - centre[0], P[1] - centre[1])
    a0 = math.atan2(P[1] - centre[1], P[0] - centre[0])
    return Polyline(tuple((centre[0] + r * math.cos(a0 + angle * k / 30), centre[1] + r * math.sin(a0 + angle * k / 30))
                          for k in range(31)), "construction")


def slider_items(g: SliderCrankDesign, p: SliderCrankPositions) -> list[Primitive]:
    """The crank's positions AB_i dashed, the slider's C_i on the guide, each B_i shifted back to
    B_i′ thin, the bisectors to C₁; the slider-crank A B₁ C₁ bold."""
    from graphmech.drawing.primitives import (
        FixedPivot,
        GuideLine,
        Hinge,
        Label,
        Segment,
        Slider,
    )

    u = (math.cos(p.guide_angle), math.sin(p.guide_angle))
    C = [(g.C1[0] + (x - p.s[0]) * u[0], g.C1[1] + (x - p.s[0]) * u[1]) for x in p.s]
    B = [(p.A[0] + p.l_AB * math.cos(f), p.A[1] + p.l_AB * math.sin(f)) for f in p.phi]
    ts = [(q[0] - g.C1[0]) * u[0] + (q[1] - g.C1[1]) * u[1] for q in (*C, p.A)]
    lo, hi = min(ts) - 12.0, max(ts) + 12.0
    items: list[Primitive] = [GuideLine((g.C1[0] + lo * u[0], g.C1[1] + lo * u[1]),
                                        (g.C1[0] + hi * u[0], g.C1[1] + hi * u[1]))]
    items += bisector_items(g.construction.bisectors, g.C1)
    items.append(arc_about(g.C1, [B[0], *(v.image for v in g.construction.inversions)]))
    for i, v in enumerate(g.construction.inversions, start=1):
        items += [Segment(p.A, B[i], "given", dashed=True), Segment(B[i], C[i], "given", dashed=True),
                  Segment(v.original, v.image, "construction", dashed=True), Hinge(B[i]), Hinge(v.image), Hinge(C[i]),
                  Label(f"B_{{{i + 1}}}", B[i]), Label(_sub(v.label), v.image),
                  Label(f"C_{{{i + 1}}}", C[i], ((0.0, 1.0), (0.0, -1.0)))]
    items += [Segment(p.A, B[0], "result"), Segment(B[0], g.C1, "result"), Slider(g.C1, p.guide_angle),
              FixedPivot(p.A), Hinge(B[0]), Hinge(g.C1),
              Label("A", p.A, (unit(p.A, B[0]),)), Label("B_{1}", B[0]),
              Label("C_{1}", g.C1, ((0.0, 1.0), (0.0, -1.0), unit(g.C1, B[0])))]
    return items


def guide_direction(F: tuple[XY, ...]) -> XY:
    """The slider's guide, F₁ → F_n; where it comes back to F₁, along its farthest two positions."""
    a, b = (F[0], F[-1]) if math.dist(F[0], F[-1]) > 0.0 else max(((f, g) for f in F for g in F),
                                                                 key=lambda fg: math.dist(*fg))
    return unit(a, b)


def rocker_items(g: JointDesign, p: RockerSliderPositions) -> list[Primitive]:
    """The rocker's positions DC_i and the slider's F_i given, each F_i turned about D to F_i′ on
    a thin arc (DF_i, DF_i′ dashed), the bisectors to E; the rocker D C E and E F bold in the
    position turned to."""
    from graphmech.drawing.primitives import (
        FixedPivot,
        GuideLine,
        Hinge,
        Label,
        Segment,
        Slider,
    )

    k = p.invert_to - 1
    F = p.F
    u = guide_direction(F)
    ts = [(q[0] - F[0][0]) * u[0] + (q[1] - F[0][1]) * u[1] for q in F]
    lo, hi = min(ts) - 12.0, max(ts) + 12.0
    items: list[Primitive] = [GuideLine((F[0][0] + lo * u[0], F[0][1] + lo * u[1]),
                                        (F[0][0] + hi * u[0], F[0][1] + hi * u[1]))]
    for v in g.inversions:
        items += [turn_arc(p.D, v.original, v.angle), Segment(p.D, v.original, "construction", dashed=True),
                  Segment(p.D, v.image, "construction", dashed=True), Hinge(v.image), Label(_sub(v.label), v.image)]
    items += bisector_items(g.bisectors, g.joint)
    items.append(arc_about(g.joint, [F[k], *(v.image for v in g.inversions)]))
    items += [arc_about(a.centre, [g.joint], 0.35, 20) for a in g.arcs]  # two positions: the arc of l_DE at E
    for i in range(len(F)):
        if i != k:
            items.append(Segment(p.D, p.C[i], "given", dashed=True))
        items += [Hinge(p.C[i]), Hinge(F[i]), Label(f"C_{{{i + 1}}}", p.C[i], (unit(p.C[i], p.D),)),
                  Label(f"F_{{{i + 1}}}", F[i], (u, (-u[0], -u[1])))]
    E, n = g.joint, p.invert_to
    items += [Segment(p.D, p.C[k], "result"), Segment(p.D, E, "result"), Segment(p.C[k], E, "result"),
              Segment(E, F[k], "result"), Slider(F[k], math.atan2(u[1], u[0])), FixedPivot(p.D), Hinge(E),
              Label("D", p.D, (unit(p.D, p.C[k]), unit(p.D, E))),
              Label(f"E_{{{n}}}", E, (unit(E, F[k]), unit(E, p.D), unit(E, p.C[k])))]
    return items


def coupler_point_items(g: CouplerPointDesign, p: CouplerPointPositions) -> list[Primitive]:
    """The line of E_i, the arc of l_CD about D cut by the arcs of l_EC about E_i at C_i, the
    coupler's positions C_iE_i dashed, A carried with the coupler back to A₂′, A₃′ (the triangles
    C_iE_iA and C₁E₁A_i′ thin), the bisectors to B₁; the four-bar A B₁ C₁ D and its coupler B₁C₁E₁
    bold."""
    from graphmech.drawing.primitives import FixedPivot, Hinge, Label, Segment

    E, C = g.E, g.C
    u = unit(E[0], E[-1])
    ts = [(q[0] - E[0][0]) * u[0] + (q[1] - E[0][1]) * u[1] for q in E]
    lo, hi = min(ts) - 10.0, max(ts) + 10.0
    items: list[Primitive] = [Segment((E[0][0] + lo * u[0], E[0][1] + lo * u[1]),
                                      (E[0][0] + hi * u[0], E[0][1] + hi * u[1]), "construction", dashdot=True),
                              arc_about(g.D, list(C))]
    items += [arc_about(E[i], [C[i]], 0.18, 12) for i in range(3)]
    for i, v in enumerate(g.construction.inversions, start=1):
        items += [Segment(C[i], g.A, "construction", dashed=True), Segment(E[i], g.A, "construction", dashed=True),
                  Segment(C[0], v.image, "construction", dashed=True), Segment(E[0], v.image, "construction", dashed=True),
                  Segment(g.D, C[i], "given", dashed=True), Segment(C[i], E[i], "given", dashed=True),
                  Hinge(v.image), Label(_sub(v.label), v.image)]
    items += bisector_items(g.construction.bisectors, g.B[0])
    items.append(arc_about(g.B[0], [g.A, *(v.image for v in g.construction.inversions)]))
    B1 = g.B[0]
    items += [Segment(g.A, B1, "result"), Segment(B1, C[0], "result"), Segment(C[0], g.D, "result"),
              Segment(B1, E[0], "result"), Segment(C[0], E[0], "result"),
              Segment(g.A, g.D, "construction", dashdot=True), FixedPivot(g.A), FixedPivot(g.D),
              Hinge(B1), Hinge(C[0]), Label("A", g.A, (unit(g.A, B1), unit(g.A, g.D))),
              Label("D", g.D, (unit(g.D, C[0]), unit(g.D, g.A))), Label("B_{1}", B1)]
    items += [Hinge(c) for c in C[1:]] + [Hinge(e) for e in E]
    items += [Label(f"C_{{{i + 1}}}", C[i], (unit(C[i], g.D), unit(C[i], E[i]))) for i in range(3)]
    items += [Label(f"E_{{{i + 1}}}", E[i], (u, (-u[0], -u[1]), unit(E[i], C[i]))) for i in range(3)]
    return items


def title(f: InversionFound) -> str:
    """The panel's (and a title-less sheet's) name."""
    if isinstance(f.mm, SliderCrankPositions):
        return "Slider-crank through given crank and slider positions"
    if isinstance(f.mm, RockerSliderPositions):
        return "A rocker leading a slider through given positions, by inversion"
    return "Four-bar whose coupler point passes three given points"


def notes(f: InversionFound, mu: float) -> tuple[str, ...]:
    """The dimensions under the panel, measured at μl."""
    from graphmech.drawing.lettering import number, scale_text
    from graphmech.methods.synthesis_positions import (
        CouplerPointDesign,
        JointDesign,
        SliderCrankDesign,
    )

    def mm(value: float) -> str:  # drawn mm → the length it stands for
        return f"{number(value * mu * 1000)} mm"

    g, p = f.drawn, f.mm
    if isinstance(p, SliderCrankPositions):
        assert isinstance(g, SliderCrankDesign)
        return (scale_text("l", mu), (f"l_{{AB}} = {number(p.l_AB * mu * 1000)} mm (given), "
                                     f"l_{{BC}} = {mm(g.l_BC)}, e = {mm(g.offset)}"))
    if isinstance(p, RockerSliderPositions):
        assert isinstance(g, JointDesign)
        k = p.invert_to - 1
        E = g.joint
        return (scale_text("l", mu), (f"l_{{DE}} = {mm(math.dist(E, p.D))}, "
                                     f"l_{{EF}} = E_{{{k + 1}}}F_{{{k + 1}}} = {mm(math.dist(E, p.F[k]))}"))
    assert isinstance(g, CouplerPointDesign)
    return (scale_text("l", mu), (f"l_{{AB}} = {mm(g.l_AB)}, l_{{BC}} = {mm(g.l_BC)}, "
                                 f"l_{{BE}} = {mm(g.l_BE)} (l_{{CD}} = {number(p.l_CD * mu * 1000)} mm, "
                                 f"l_{{EC}} = {number(p.l_EC * mu * 1000)} mm given)"))


def panels(f: InversionFound, mu: float) -> tuple[str, list[Panel]]:
    """The sheet's title and its one panel: the construction with the design bold."""
    from graphmech.drawing.primitives import Panel
    from graphmech.methods.synthesis_positions import JointDesign, SliderCrankDesign

    g, p = f.drawn, f.mm
    if isinstance(p, SliderCrankPositions):
        assert isinstance(g, SliderCrankDesign)
        items = slider_items(g, p)
    elif isinstance(p, RockerSliderPositions):
        assert isinstance(g, JointDesign)
        items = rocker_items(g, p)
    else:
        assert not isinstance(g, (JointDesign, SliderCrankDesign))
        items = coupler_point_items(g, p)
    name = title(f)
    return name, [Panel("design", name, tuple(items), notes(f, mu), row=0, scales=(("l", mu),))]


# --------------------------------------------------------------------------------- the steps

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")

#: The phrases of these forms: key → (English, 中文, русский). 孙桓 §8 反转法.
PHRASES: dict[str, tuple[str, str, str]] = {
    "slider given": (("draw A, the crank AB_i (AB = {l}/μl = {mm} mm) at its {n} angles φ_i and the guide at {g}°, "
                      "the slider's C_i at s_i/μl on it"),
                     "作A及曲柄的{n}个位置AB_i（AB = {l}/μl = {mm} mm）和与水平成{g}°的导路，滑块位置C_i按s_i/μl取在导路上",
                     ("строим A, кривошип AB_i (AB = {l}/μl = {mm} mm) в {n} углах φ_i и направляющую под {g}°, "
                      "на ней положения ползуна C_i по s_i/μl")),
    "slider three": (("seen from the slider the frame translates back: shift each B_i along the guide by "
                      "−(s_i − s₁) to B_i′; C₁ is the centre of the circle through B₁, B₂′, B₃′: the bisectors of "
                      "B₁B₂′ and B₂′B₃′ meet there"),
                     "以滑块为参考（反转法）：将各B_i沿导路平移−(s_i − s₁)得B_i′；B₁、B₂′、B₃′所定圆之圆心即C₁：B₁B₂′与B₂′B₃′的中垂线交于C₁",
                     ("относительно ползуна стойка движется назад: сдвигаем каждую B_i вдоль направляющей на "
                      "−(s_i − s₁) в B_i′; C₁ — центр окружности через B₁, B₂′, B₃′: серединные перпендикуляры к "
                      "B₁B₂′ и B₂′B₃′ пересекаются в C₁")),
    "slider two": ("shift B₂ along the guide by −(s₂ − s₁) to B₂′; the bisector of B₁B₂′ cuts the pin's path at C₁",
                   "将B₂沿导路平移−(s₂ − s₁)得B₂′；B₁B₂′的中垂线与铰链C的轨迹线交于C₁",
                   ("сдвигаем B₂ вдоль направляющей на −(s₂ − s₁) в B₂′; серединный перпендикуляр к B₁B₂′ "
                   "пересекает траекторию шарнира в C₁")),
    "slider measure": ("measure B₁C₁ = {b} mm and the offset of A from the guide e = {e} mm: l_BC = {lb} m, e = {le} m",
                       "量得B₁C₁ = {b} mm，A至导路的偏距e = {e} mm：l_BC = {lb} m，e = {le} m",
                       "измеряем B₁C₁ = {b} mm и смещение A от направляющей e = {e} mm: l_BC = {lb} m, e = {le} m"),
    "rocker given": (("draw D, the rocker's {n} given positions DC_i and the slider's F_i on its guide; the "
                     "construction is drawn in position {k} (DC{ks} held still)"),
                     "作D、摇杆的{n}个给定位置DC_i及滑块位置F_i；转至位置{k}作图（DC{ks}不动）",
                     ("строим D, {n} заданных положения коромысла DC_i и ползуна F_i; построение ведём в "
                     "положении {k} (DC{ks} неподвижно)")),
    "rocker three": (("seen from the rocker the frame turns back: turn each F_i about D by the rocker's turn "
                      "from position i to position {k} (∠C_iDC{ks}) to F_i′; E{ks} is the centre of the circle through "
                      "{f1}, {f2}, {f3}: the bisectors of {f1}{f2} and {f2}{f3} meet there"),
                     "以摇杆为参考（反转法）：将各F_i绕D转过∠C_iDC{ks}得F_i′；{f1}、{f2}、{f3}所定圆之圆心即E{ks}：{f1}{f2}与{f2}{f3}的中垂线交于E{ks}",
                     ("относительно коромысла стойка поворачивается назад: каждую F_i поворачиваем около D на "
                      "∠C_iDC{ks} в F_i′; E{ks} — центр окружности через {f1}, {f2}, {f3}: серединные перпендикуляры к "
                      "{f1}{f2} и {f2}{f3} пересекаются в E{ks}")),
    "rocker two": (("turn {f0} about D by ∠{c0}DC{ks} to {f2}; the arc of radius DE = {d}/μl = {dm} mm about D cuts "
                    "the bisector of {f1}{f2} at E{ks}"),
                   "将{f0}绕D转过∠{c0}DC{ks}得{f2}；以D为圆心、DE = {d}/μl = {dm} mm为半径作弧，与{f1}{f2}的中垂线交于E{ks}",
                   ("{f0} поворачиваем около D на ∠{c0}DC{ks} в {f2}; дуга радиуса DE = {d}/μl = {dm} mm около D "
                    "пересекает серединный перпендикуляр к {f1}{f2} в E{ks}")),
    "rocker measure": ("measure DE{ks} = {d} mm, E{ks}F{ks} = {f} mm: l_DE = {ld} m, l_EF = {lf} m",
                       "量得DE{ks} = {d} mm，E{ks}F{ks} = {f} mm：l_DE = {ld} m，l_EF = {lf} m",
                       "измеряем DE{ks} = {d} mm, E{ks}F{ks} = {f} mm: l_DE = {ld} m, l_EF = {lf} m"),
    "point arcs": (("draw A, D and E₁, E₂, E₃; the arc of radius CD = {c}/μl = {cm} mm about D is cut by the arcs of "
                   "radius EC = {e}/μl = {em} mm about E₁, E₂, E₃ at C₁, C₂, C₃"),
                   ("作A、D及E₁、E₂、E₃；以D为圆心、CD = {c}/μl = {cm} mm为半径作弧，分别以E₁、E₂、E₃为圆心、"
                   "EC = {e}/μl = {em} mm为半径作弧交之于C₁、C₂、C₃"),
                   ("строим A, D и E₁, E₂, E₃; дугу радиуса CD = {c}/μl = {cm} mm около D пересекаем дугами радиуса "
                   "EC = {e}/μl = {em} mm около E₁, E₂, E₃ в C₁, C₂, C₃")),
    "point invert": (("seen from the coupler CE the pivot A moves: carry A with the coupler from positions 2 and 3 "
                      "back to position 1 (the triangles C₂E₂A, C₃E₃A copied onto C₁E₁) to A₂′, A₃′; B₁ is the "
                      "centre of the circle through A, A₂′, A₃′: the bisectors of AA₂′ and A₂′A₃′ meet there"),
                     ("以连杆CE为参考（反转法）：把三角形C₂E₂A、C₃E₃A搬到C₁E₁上得A₂′、A₃′；A、A₂′、A₃′所定圆之圆心即B₁："
                      "AA₂′与A₂′A₃′的中垂线交于B₁"),
                     ("относительно шатуна CE шарнир A движется: переносим A с шатуном из положений 2 и 3 в "
                      "положение 1 (треугольники C₂E₂A, C₃E₃A на C₁E₁) в A₂′, A₃′; B₁ — центр окружности через A, "
                      "A₂′, A₃′: серединные перпендикуляры к AA₂′ и A₂′A₃′ пересекаются в B₁")),
    "point measure": ("measure AB₁ = {a} mm, B₁C₁ = {b} mm, B₁E₁ = {e} mm: l_AB = {la} m, l_BC = {lb} m, l_BE = {le} m",
                      "量得AB₁ = {a} mm，B₁C₁ = {b} mm，B₁E₁ = {e} mm：l_AB = {la} m，l_BC = {lb} m，l_BE = {le} m",
                      ("измеряем AB₁ = {a} mm, B₁C₁ = {b} mm, B₁E₁ = {e} mm: l_AB = {la} m, l_BC = {lb} m, "
                      "l_BE = {le} m")),
    "recheck linkage": ("check: the linkage driven through the positions reaches them to {err} (of its longest link)",
                        "校核：该机构经过给定位置，误差{err}（相对最长杆）",
                        "проверка: механизм проходит заданные положения с погрешностью {err} (от длиннейшего звена)"),
}


def steps(f: InversionFound, mu: float, say: Callable[..., str], num: Callable[[float], str]) -> list[str]:
    """The construction protocol's lines after μl is chosen: the numbers the check's rows read."""
    from graphmech.methods.synthesis_positions import (
        CouplerPointDesign,
        JointDesign,
        SliderCrankDesign,
    )

    g, p = f.drawn, f.mm
    out: list[str]
    if isinstance(p, SliderCrankPositions):
        assert isinstance(g, SliderCrankDesign)
        b, e = g.l_BC, g.offset
        out = [say("slider given", n=str(len(p.phi)), l=num(p.l_AB * mu), mm=num(p.l_AB),
                   g=num(math.degrees(p.guide_angle))),
               say("slider three" if len(p.phi) == 3 else "slider two"),
               say("slider measure", b=num(b), e=num(e), lb=num(b * mu), le=num(e * mu))]
    elif isinstance(p, RockerSliderPositions):
        assert isinstance(g, JointDesign)
        k, ks = p.invert_to, str(p.invert_to).translate(_SUB)
        fs = [f"F{ks}", *(f"F{v.label[1:-1].translate(_SUB)}′" for v in g.inversions)]
        E = g.joint
        d, fl = math.dist(E, p.D), math.dist(E, p.F[k - 1])
        if len(p.F) == 3:
            how = say("rocker three", k=str(k), ks=ks, f1=fs[0], f2=fs[1], f3=fs[2])
        else:
            assert p.l_DE is not None
            how = say("rocker two", ks=ks, f0=fs[1][:-1], c0=f"C{fs[1][1:-1]}", f1=fs[0], f2=fs[1],
                      d=num(p.l_DE * mu), dm=num(p.l_DE))
        out = [say("rocker given", n=str(len(p.F)), k=str(k), ks=ks), how,
               say("rocker measure", ks=ks, d=num(d), f=num(fl), ld=num(d * mu), lf=num(fl * mu))]
    else:
        assert isinstance(g, CouplerPointDesign)
        a, b, e = g.l_AB, g.l_BC, g.l_BE
        out = [say("point arcs", c=num(p.l_CD * mu), cm=num(p.l_CD), e=num(p.l_EC * mu), em=num(p.l_EC)),
               say("point invert"),
               say("point measure", a=num(a), b=num(b), e=num(e), la=num(a * mu), lb=num(b * mu), le=num(e * mu))]
    return [*out, say("recheck linkage", err=f"{f.exact_re.error:.1e}")]


__all__ = [
    "PHRASES",
    "CouplerPointPositions",
    "Form",
    "InversionFound",
    "RockerSliderPositions",
    "SliderCrankPositions",
    "analyse",
    "arc_about",
    "bisector_items",
    "coupler_point_items",
    "design_line",
    "exact_coupler_point",
    "exact_rocker_joint",
    "exact_slider_pin",
    "guide_direction",
    "is_form",
    "lines",
    "panels",
    "read_coupler_point",
    "read_form",
    "read_rocker_slider",
    "read_slider_crank",
    "rocker_angles",
    "rocker_items",
    "size",
    "slider_items",
    "steps",
    "turn_arc",
]
