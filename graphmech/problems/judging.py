"""Judging what a construction gives: the rows of a check table, the verdicts on a user's own
measurements, and the rules every kind shares (a hand measurement's tolerance, numbers that leave
double precision, names with a position ``v_C@50``).

A row is ``drawn length × μ = graphical value`` against the exact value from the independent
solution, with the relative error and how accurate the method says it is
(:mod:`graphmech.accuracy`); a verdict is a measured value against the expected one, within the
drawing precision × μ for a length read off the drawing.
"""
from __future__ import annotations

import math
import re
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any, Protocol, TypeVar

import numpy as np

from graphmech import tolerances as T
from graphmech.accuracy import CONSTRUCTION, percent
from graphmech.errors import DegenerateConstruction
from graphmech.problems.reader import Written

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene


@dataclass(frozen=True)
class Row:
    """One line of the check table."""

    name: str
    unit: str
    drawn_mm: float | None
    scale: float
    graphical: float
    exact: float
    rel_error: float
    ill_conditioned: bool = False
    # How accurate the method says it is (graphmech.accuracy): a construction is exact but for
    # round-off; a discretised or read-off value carries its own relative error estimate and the
    # basis it was found on ("12 positions", "15° divisions").
    error_source: str = CONSTRUCTION
    error_estimate: float | None = None
    basis: str = ""

    def as_dict(self) -> dict[str, Any]:
        return {"name": self.name, "unit": self.unit, "drawn_mm": self.drawn_mm, "scale": self.scale,
                "graphical": self.graphical, "exact": self.exact, "rel_error": self.rel_error,
                "ill_conditioned": self.ill_conditioned, "error_source": self.error_source,
                "error_estimate": self.error_estimate, "basis": self.basis}

    def estimated(self, source: str, estimate: float, basis: str) -> "Row":
        """This row as a discretised or read-off value with its own error estimate."""
        return replace(self, error_source=source, error_estimate=float(estimate), basis=basis)


def conditioning_warning(where: str, step: str, cond: float, what: str = "") -> tuple[bool, str | None]:
    """Whether a cut of condition number ``cond`` (≈ 1/sin of the angle at which its loci meet)
    makes what depends on it ill-conditioned, and the warning to print: ill-conditioned past
    ``tolerances.COND_WARN`` (the round-off estimate passes the agreement asked), shallow for a hand
    construction past 1/sin ``SHALLOW_DEG``; None below both. ``what`` names what depends on it;
    ``where`` (a position, a design) prefixes the warning, none where empty. Loci that touch
    (``cond`` infinite) are said as such, never with an infinite number.

    >>> conditioning_warning("φ = 30°", "A = c1 ∩ c2", 2.0)
    (False, None)
    >>> conditioning_warning("sol1", "A = c1 ∩ c2", 1e4)[0]
    True
    """
    at = f"{where}: " if where else ""
    angle = math.degrees(math.asin(min(1.0, 1.0 / cond))) if cond > 0 else 90.0
    est = T.COND_SAFETY * cond * cond * T.EPS
    if not math.isfinite(est):
        # loci that touch (exact data can make them tangent): an error ε of the drawing moves the
        # point of contact by about √ε along the tangent — no condition number to print
        return True, (f"{at}ill-conditioned intersection '{step}': the loci touch (they meet at 0°, a point "
                      f"of tangency); {what or 'the drawing'} may be wrong by about "
                      f"{T.COND_SAFETY * math.sqrt(T.EPS):.1g} relative or more")
    if cond > T.COND_WARN:
        return True, (f"{at}ill-conditioned intersection '{step}': the loci meet at {angle:.3g}° "
                      f"(condition number {cond:.3g}); {what or 'the drawing'} may be wrong by about "
                      f"{est:.1g} relative or more")
    if cond > 1.0 / math.sin(math.radians(T.SHALLOW_DEG)):
        return False, (f"{at}shallow intersection '{step}' at {angle:.3g}°: a hand construction "
                       f"is unreliable here (a 0.5 mm error becomes about {0.5 * cond:.2g} mm)")
    return False, None


def estimate_text(row: Row) -> str:
    """How accurate a discretised or read-off row says it is, as every check table prints it:
    ``±8 % (12 positions)``; ``""`` for a row with no estimate."""
    if row.error_estimate is None:
        return ""
    return f"±{percent(row.error_estimate)} ({row.basis or row.error_source})"


@dataclass(frozen=True)
class Verdict:
    """A hand measurement judged against the exact value, within the drawing precision; a value
    as written (:class:`~graphmech.problems.reader.Written`) also keeps its text and the rules
    that judged it (:func:`judge_written`)."""

    name: str
    measured: float
    expected: float
    tolerance: float
    ok: bool
    unit: str
    written: str = ""  # the value as written ("" for a number given as a number)
    rule: str = ""  # "rounding to 3 s.f., magnitude only", "drawing precision, sign checked" …
    figures: int | None = None  # its significant figures (0: a written zero)

    def as_dict(self) -> dict[str, Any]:
        doc = {"name": self.name, "measured": self.measured, "expected": self.expected,
               "tolerance": self.tolerance, "ok": self.ok, "unit": self.unit}
        if self.written:  # a number given as a number keeps the JSON it always had
            doc.update(written=self.written, rule=self.rule, significant_figures=self.figures)
        return doc


#: The rules a written value is judged by (docs/scene-format.md, [measured]); the rounding rule
#: is named with its figures by :func:`rounding_rule`.
DRAWING_PRECISION = "drawing precision"
MAGNITUDE_ONLY = "magnitude only"
SIGN_CHECKED = "sign checked"


def rounding_rule(value: Written) -> str:
    """``rounding to 3 s.f.``; a written zero, to its last digit (``rounding to ±0.005``)."""
    return f"rounding to {value.figures} s.f." if value.figures else f"rounding to ±{value.half_unit:g}"


def judge_written(name: str, value: Written, expected: float, reading: float | None, unit: str,
                  ok: bool = False) -> Verdict:
    """A value as written judged as a teacher does. Right when the exact value lies within half a
    unit of the last written digit, both ends included (a tie is right whichever way it was
    rounded) — or, for a value read off the drawing (``reading``: the tolerance the drawing gives
    it; None for a computed value), within the drawing precision where that is wider: a reading is
    never judged finer than it can be read. Without a written sign the magnitudes are compared
    (the book asks for a magnitude); with one, the signed values. ``ok``: the kind's own verdict
    on the value as written within ``reading`` (an angle judged across 0°/360°), which stands.

    >>> from graphmech.problems.reader import Written
    >>> judge_written("psi", Written("1.44"), 1.43755802, None, "deg").ok
    True
    >>> judge_written("psi", Written("1.43"), 1.43755802, None, "deg").ok
    False
    """
    x, e = (float(value), float(expected)) if value.signed else (abs(float(value)), abs(float(expected)))
    by_drawing = reading is not None and reading >= value.half_unit
    tol = float(reading) if by_drawing and reading is not None else value.half_unit
    good = abs(x - e) <= tol + 1e-12 * abs(e) or (ok and reading is not None)
    rule = f"{DRAWING_PRECISION if by_drawing else rounding_rule(value)}, " \
           f"{SIGN_CHECKED if value.signed else MAGNITUDE_ONLY}"
    return Verdict(name, value, expected, tol, bool(good), unit, value.text, rule, value.figures)


def as_written(v: Verdict) -> Verdict:
    """A kind's verdict judged again as a teacher does when its value was written
    (:func:`judge_written`, the kind's tolerance being what the drawing gives it). A number given
    as a number, a verdict already so judged (:func:`judge_value`) and an exact one (tolerance 0:
    a count, or a name with nothing to judge it against) stand as they are."""
    if not isinstance(v.measured, Written) or v.written or v.tolerance == 0:
        return v
    return judge_written(v.name, v.measured, v.expected, v.tolerance, v.unit, v.ok)


def judge_value(name: str, value: float, expected: float, drawn: float | None, scale: float,
                precision_mm: float, unit: str) -> Verdict:
    """A measured value against the expected one: a length read off the drawing within the
    drawing precision × its μ, any other value (a computed one) within 0.1 %; a value as written
    by its digits and sign (:func:`judge_written`)."""
    tol = precision_mm * abs(scale) if drawn is not None else max(abs(expected) * 1e-3, T.EPS)
    ok = abs(value - expected) <= tol + 1e-12 * abs(expected)
    if isinstance(value, Written):
        return judge_written(name, value, expected, tol if drawn is not None else None, unit, bool(ok))
    return Verdict(name, value, expected, tol, bool(ok), unit)  # bool: a numpy expected gives a numpy bool


def split_name(name: str) -> tuple[str, str | None]:
    """``"v_C@50"`` → ``("v_C", "50")``."""
    base, _, at = name.partition("@")
    return base, (at or None)


def close_names(name: str, known: Any) -> str:
    import difflib

    m = difflib.get_close_matches(name, sorted(known), n=3)
    return f"; did you mean {', '.join(m)}?" if m else ""


@contextmanager
def in_double_precision(step: str) -> Iterator[None]:
    """Run an analysis whose numbers may leave double precision (a speed of 1e300, a scale of
    5e-324): numpy stays quiet, and an overflow or a division by zero is said in one line."""
    try:
        with np.errstate(all="ignore"):
            yield
    except (OverflowError, ZeroDivisionError, FloatingPointError):
        raise DegenerateConstruction(step, OUT_OF_RANGE) from None


#: The reason given when a number leaves double precision.
OUT_OF_RANGE = "numbers out of the range of double precision (the scene's sizes or speeds are too extreme)"
SEGMENT = re.compile(r"[a-z]\d*['′]*")


def is_segment(name: str) -> bool:
    """``pc``, ``p'c'``, ``n2'c'``: a drawn segment named by its end labels."""
    tokens = SEGMENT.findall(name)
    return "_" not in name and len(tokens) == 2 and "".join(tokens) == name


def measured_entries(scene: Scene[object], extra: tuple[tuple[str, float], ...] = ()) -> list[tuple[str, str, float]]:
    """(key path for messages, name, value) of the scene's [measured] table and the command line's."""
    return [(f"measured.{n}", n, v) for n, v in scene.measured] + [(f"--measured {n}", n, v) for n, v in extra]


class Analysis(Protocol):
    """What a kind's check returns (a CamAnalysis, a FlywheelAnalysis …), as the command line and
    the JSON read it: the scene, the table's rows, the warnings and the scales μ."""

    @property
    def scene(self) -> Scene[Any]: ...
    @property
    def rows(self) -> Sequence[Row]: ...
    @property
    def warnings(self) -> Sequence[str]: ...
    @property
    def scales(self) -> dict[str, float]: ...
    def scale_notes(self) -> list[str]: ...


#: A kind's own analysis.
A = TypeVar("A", bound=Analysis)


def refuse_non_finite(rows: Sequence[Row]) -> None:
    """A value that left double precision (J_F for δ = 5e-324) is refused in words, whatever the
    kind: never an inf or NaN in the table or the JSON."""
    for r in rows:
        if not all(math.isfinite(v) for v in (r.graphical, r.exact)):
            raise DegenerateConstruction(r.name, OUT_OF_RANGE)
        if r.error_estimate is not None and not math.isfinite(r.error_estimate):
            raise DegenerateConstruction(r.name, "its error estimate left double precision: the same method "
                                                 "at more positions or divisions breaks down")


def finite(an: A) -> A:
    """The analysis ``an``, its rows all finite (else refused in words): for a drawing as for a table."""
    refuse_non_finite(an.rows)
    return an
