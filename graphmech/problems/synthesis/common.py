"""What every positions form shares (``task = "positions"``): reading points, lengths and angle
lists bounded by :data:`MAX_SIZE`, the rows drawn against exact with the re-analysis, the
exact joint found by inversion, and the conditioning of the construction's cuts — two bisectors
(or a bisector and a line or an arc) that meet at a shallow angle put the pivot far off and make
it very sensitive: said in a warning, the rows that hang on it marked ill-conditioned.
"""
from __future__ import annotations

import cmath
import math
from collections.abc import Iterable, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

from graphmech.errors import GraphmechError

if TYPE_CHECKING:
    from graphmech.exact.synthesis_positions import Reanalysis
    from graphmech.problems.judging import Row
    from graphmech.problems.reader import Reader

XY = tuple[float, float]
#: A line as the constructions give it: a point and a unit direction (px, py, dx, dy).
LineXY = tuple[float, float, float, float]

#: The largest coordinate or length a positions design takes, m: beyond it the bisectors' and the
#: re-analysis's squares leave double precision (and no mechanism is a thousand kilometres across).
MAX_SIZE = 1e6
#: The shortest link a design takes, m (as the time-ratio task's): below it the squares of the
#: lengths (Freudenstein's b², the bisectors' |p|²) leave double precision long before the page does.
MIN_LENGTH = 1e-9


def _two_or_three(r: Reader, base: str, kind: str) -> tuple[float, ...] | None:
    """A list of two or three quantities of ``kind`` in SI (one position each)."""
    g = r.quantity(base, kind)
    if g is None:
        return None
    n = len(g.value) if isinstance(g.value, list) and len(g.value) in (2, 3) else 3
    xs = r.numbers(g.value, r.at(g.key), n, shape=f"[{base}1, {base}2, {base}3] or two")
    return None if xs is None else tuple(g.si(x) for x in xs)


def read_angles(r: Reader, base: str) -> tuple[float, ...] | None:
    """A list of two or three angles (rad), e.g. ``phi_deg = [45, 90, 135]``."""
    return _two_or_three(r, base, "angle")


def read_lengths(r: Reader, base: str) -> tuple[float, ...] | None:
    """A list of two or three signed lengths (m), e.g. ``s_mm = [0, 20, 45]``, each within MAX_SIZE."""
    out = _two_or_three(r, base, "length")
    return out if out is not None and sized(r, base, out) is not None else None


def sized(r: Reader, base: str, value: tuple[float, ...] | float | None) -> tuple[float, ...] | float | None:
    """``value`` unless a coordinate or a length exceeds :data:`MAX_SIZE` (then said at its key)."""
    if value is None:
        return None
    xs = value if isinstance(value, tuple) else (value,)
    if any(abs(x) > MAX_SIZE for x in xs):
        r.problem(r.at(r.present(base) or base), f"{max(abs(x) for x in xs):g} m is beyond {MAX_SIZE:g} m: "
                                                 "too large for a linkage to be designed in double precision")
        return None
    return value


def read_point(r: Reader, base: str, required: bool = True) -> XY | None:
    """A point ``[x, y]`` with a length unit (m), within MAX_SIZE."""
    v = sized(r, base, r.pair(base, required=required))
    return (v[0], v[1]) if isinstance(v, tuple) else None


def read_length(r: Reader, base: str, required: bool = True) -> float | None:
    """A positive length (m), from MIN_LENGTH to MAX_SIZE."""
    v = sized(r, base, r.scalar(base, "length", positive=True, required=required))
    # 1e-6 mm converts to a hair under 1e-9 m: the bound is the nanometre as written
    if isinstance(v, float) and v < MIN_LENGTH * (1.0 - 1e-9):
        r.problem(r.at(r.present(base) or base), f"{v:g} m is below {MIN_LENGTH:g} m: too short for a link "
                                                 "to be designed in double precision")
        return None
    return v if isinstance(v, float) else None


def read_side(r: Reader, what: str) -> float | None:
    """``side`` = 1 or −1 (default 1), or None after saying why not."""
    from graphmech.problems.reader import MISSING

    raw = r.raw("side")
    if raw is MISSING:
        return 1.0
    if raw not in (1, -1) or isinstance(raw, bool):
        r.problem(r.at("side"), f"must be 1 or -1 ({what})")
        return None
    return float(raw)


def exact_joint(points: Sequence[complex], pivot: complex, rotations: Sequence[float], length: float | None = None,
                near: complex | None = None) -> complex:
    """The joint at position 1 on a link turning about ``pivot`` (rotation i from position 1,
    rad) that carries a second link's joint through ``points``, by the exact side: each point
    turned back about the pivot (complex rotation), the circumcentre of the images, or with two
    the point of their bisector at ``length`` from the pivot (the one nearer ``near``)."""
    from graphmech.exact.synthesis_positions import circumcentre

    im = [pivot + (points[i] - pivot) * cmath.exp(-1j * (rotations[i] - rotations[0])) for i in range(len(points))]
    if len(im) == 3:
        return circumcentre(*im)
    assert length is not None
    mid, u = (im[0] + im[1]) / 2, (im[1] - im[0]) * 1j
    if abs(u) == 0.0:
        raise GraphmechError("the point and its inverted image coincide: no bisector")
    u /= abs(u)
    t0 = ((pivot - mid) * u.conjugate()).real  # the foot of the pivot on the bisector
    h2 = length ** 2 - abs(mid + t0 * u - pivot) ** 2
    if h2 < 0.0:
        raise GraphmechError(f"the arc of {length:.6g} m about the pivot does not reach the bisector")
    cands = [mid + (t0 + k * math.sqrt(h2)) * u for k in (1.0, -1.0)]
    return min(cands, key=lambda z: abs(z - (near if near is not None else cands[0])))


def on_line(P: complex, u: complex, Q1: complex, Q2: complex) -> complex:
    """The point of the line P + t·u (u a unit) equally far from Q1 and Q2 (their bisector cut)."""
    # |P + tu − Q1|² = |P + tu − Q2|²: linear in t
    den = 2.0 * ((Q2 - Q1) * u.conjugate()).real
    if den == 0.0:
        raise GraphmechError("the line runs along the bisector: it does not cut it")
    return P + u * (abs(Q2 - P) ** 2 - abs(Q1 - P) ** 2) / den


def design_rows(drawn: dict[str, float], exact: dict[str, float], mu: float, size_m: float, gr: Reanalysis,
                xr: Reanalysis) -> tuple[list[Row], list[str]]:
    """Every form's rows: each length and coordinate drawn (mm × μl) against exact (its error
    relative to the design's largest link), then the re-analysis error and γ_min of the drawn
    design against the exact one; and the names they answer. A re-analysis that cannot assemble a
    prescribed position (an infinite error) is refused (GraphmechError), never a row."""
    from graphmech.problems.judging import Row

    if not (math.isfinite(gr.error) and math.isfinite(xr.error)):
        # the design passes through its positions by construction: only round-off (links too
        # unequal for double precision) leaves one unassembled
        raise GraphmechError("the designed linkage cannot be assembled at every prescribed position when "
                             "re-analysed: its links are too unequal for double precision")
    rows = [Row(n, "m", d, mu, d * mu, exact[n], abs(d * mu - exact[n]) / size_m) for n, d in drawn.items()]
    rows.append(Row("reanalysis_error", "", None, 1.0, gr.error, xr.error, abs(gr.error - xr.error)))
    if gr.characteristics is not None and xr.characteristics is not None:
        gg, ge = gr.characteristics.gamma_min, xr.characteristics.gamma_min
        rows.append(Row("gamma_min", "deg", None, 1.0, math.degrees(gg), math.degrees(ge), abs(gg - ge) / math.pi))
    return rows, [r.name for r in rows]


def unit(p: XY, q: XY) -> XY:
    """The unit vector from p towards q (a figure's direction; (0, 0) where they coincide)."""
    n = math.hypot(q[0] - p[0], q[1] - p[1]) or 1.0
    return ((q[0] - p[0]) / n, (q[1] - p[1]) / n)


def lines_sin(a: LineXY, b: LineXY) -> float:
    """|sin| of the angle two lines meet at."""
    return abs(a[2] * b[3] - a[3] * b[2])


def line_arc_sin(line: LineXY, centre: XY, at: XY) -> float:
    """|sin| of the angle a line makes with a circle about ``centre`` where it cuts it at ``at``:
    the line against the tangent, i.e. |cos| of the line against the radius."""
    rx, ry = at[0] - centre[0], at[1] - centre[1]
    r = math.hypot(rx, ry)
    return 1.0 if r == 0.0 else abs(line[2] * rx + line[3] * ry) / r


def arcs_sin(c1: XY, c2: XY, at: XY) -> float:
    """|sin| of the angle two circles about c1 and c2 meet at ``at``: that of their radii."""
    a = (at[0] - c1[0], at[1] - c1[1])
    b = (at[0] - c2[0], at[1] - c2[1])
    n = math.hypot(*a) * math.hypot(*b)
    return 1.0 if n == 0.0 else abs(a[0] * b[1] - a[1] * b[0]) / n


def conditioning(cuts: Iterable[tuple[str, float, tuple[str, ...]]], rows: list[Row]) -> tuple[list[Row], list[str]]:
    """The rows with those that hang on a shallow cut marked ill-conditioned, and the warnings.

    ``cuts``: (the cut in words, |sin| of the angle its loci meet at, the row names it carries).
    Worded by :func:`graphmech.problems.judging.conditioning_warning`, as a linkage's intersections
    are: past ``COND_WARN`` the round-off itself is said; below ``SHALLOW_DEG`` the hand construction.
    """
    from graphmech.problems.judging import conditioning_warning

    out: list[str] = []
    marked: set[str] = set()
    for text, s, names in cuts:
        present = [n for n in names if any(r.name == n for r in rows)]
        qs = ", ".join(present) or "the drawing"
        ill, said = conditioning_warning("", text, math.inf if s <= 0.0 else 1.0 / s, qs)
        if said is None:
            continue
        out.append(said if ill else f"{said}; {qs} marked ill-conditioned")
        marked.update(present)
    return [replace(r, ill_conditioned=True) if r.name in marked else r for r in rows], out


__all__ = [
    "MAX_SIZE",
    "MIN_LENGTH",
    "arcs_sin",
    "conditioning",
    "design_rows",
    "exact_joint",
    "line_arc_sin",
    "lines_sin",
    "on_line",
    "read_angles",
    "read_length",
    "read_lengths",
    "read_point",
    "read_side",
    "sized",
    "unit",
]
