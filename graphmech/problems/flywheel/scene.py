"""Read a flywheel scene: a machine with its masses and loads, and what the flywheel problem asks.

A flywheel scene is a scene with a ``[flywheel]`` table. It may have a linkage (``[frame]``,
``[driver]``, ``[[dyad]]``, ``[[point]]`` as in a linkage scene, driven by a crank) or none: a
machine given only by its reduced inertia and moments, such as an engine's torque curve.
:func:`parse_flywheel_scene` is the rest of :func:`graphmech.scene.parse_scene` for such a
scene, with the same reader, key paths and messages: every problem is collected, then raised
once as a :class:`~graphmech.errors.SceneError`. Everything is converted to SI into a
:class:`~graphmech.mechanisms.machine.Machine`, whose conventions the file follows: φ is
measured from position 1 in the crank's sense of rotation, and a moment on the crank is
signed by its power (positive drives).

The format, with examples, is the "Flywheel scenes" section of ``docs/scene-format.md``.
"""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Mapping
from itertools import pairwise
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

from graphmech.mechanisms.linkage import RPP, RRP, Crank, Guide, Linkage, Positions
from graphmech.mechanisms.machine import (
    TWO_PI,
    CrankMoment,
    LinkMoment,
    Load,
    Machine,
    Mass,
    Motor,
    SliderLoad,
    Table,
)
from graphmech.problems.linkage.scene import read_linkage
from graphmech.problems.reader import MAX_TABLE_POINTS, pole_distances
from graphmech.problems.reader import (
    LINKAGE_KEYS,
    MAX_POSITIONS,
    MISSING,
    QUANTITY_NAME,
    Reader,
    SUFFIXES,
    Scene,
    Value,
    compact,
    key_text,
    not_for,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
    say,
    type_name,
)

if TYPE_CHECKING:
    from graphmech.methods.flywheel import Balance
    from graphmech.methods.wittenbauer import TangentForm

#: The methods that design J_F.
FlywheelMethod = Literal["wittenbauer", "indicator"]
#: The stroke a slider load acts on, and the sense it acts in along the guide.
During = Literal["forward", "backward", "both"]
Stroke = Literal["forward", "backward"]

@dataclass(frozen=True)
class TrueMotionSpec:
    """How to integrate the machine's equation of motion with the designed flywheel.

    Parameters
    ----------
    solver : str
        A ``scipy.integrate.solve_ivp`` method: "Radau", "BDF", "LSODA", "RK45" or "DOP853".
    rtol : float
        Its relative tolerance, 1e-14 … 1e-2.
    """

    solver: str = "Radau"
    rtol: float = 1e-10


@dataclass(frozen=True)
class Braking:
    """The run-down problem: the machine stopped by a brake on its main shaft.

    Parameters
    ----------
    moment : float
        The brake's moment, N·m (> 0).
    time_limit : float or None
        The required stopping time, s (> 0); None: the time is only reported.
    moment_path : str
        The moment's key path as written (``flywheel.braking.moment_Nm``), for a refusal.
    """

    moment: float
    time_limit: float | None = None
    moment_path: str = field(default="flywheel.braking.moment", compare=False)


@dataclass(frozen=True)
class FlywheelScene:
    """The flywheel problem of a flywheel scene.

    Parameters
    ----------
    machine : Machine
        The machine in SI (:mod:`graphmech.mechanisms.machine`): its linkage or None, the
        crank's angle at position 1, the cycle Φ, ω_m, δ, masses, loads, constant inertia,
        which moment balances the work, and the motor for the true motion. A braking-only
        scene that gives no δ has ``delta`` NaN: there is nothing to smooth.
    positions : int
        N, the positions the cycle is divided into (4 … 3600), labelled 1 … N.
    method : str
        Which method designs J_F: "wittenbauer" (the energy–mass diagram) or "indicator"
        (the increment of kinetic energy with the inertia of the links reduced at the mean
        speed).
    tangents : str
        How the Wittenbauer diagram's tangents are inclined: "exact", ω² ∝ (1 ± δ/2)², or
        "book", (1 ± δ).
    pole_distance : float or None
        H, drawing mm (None: chosen by the method).
    true_motion : TrueMotionSpec or None
        Present: integrate the equation of motion with the designed J_F.
    braking : Braking or None
        Present: the run-down problem.
    """

    machine: Machine
    positions: int = 12
    method: FlywheelMethod = "wittenbauer"
    tangents: TangentForm = "exact"
    pole_distance: float | None = None
    true_motion: TrueMotionSpec | None = None
    braking: Braking | None = None


#: What a flywheel scene may show: the reduced moments, their work, the increment of kinetic
#: energy, the reduced inertia, the Wittenbauer (energy–mass) diagram, the indicator diagram;
#: with a linkage also the mechanism, first; ω(φ) of the true motion; with [flywheel.braking] the
#: run-down ω(t).
FLYWHEEL_SHOW_CHOICES = ("moment", "work", "energy", "inertia", "wittenbauer", "indicator", "motion", "rundown")
#: What a flywheel scene shows when it does not say (a braking-only scene: its run-down).
FLYWHEEL_SHOW_DEFAULT = ("energy", "wittenbauer")
BRAKING_SHOW_DEFAULT = ("rundown",)
#: A four-stroke engine's working cycle: two turns of the crank (the reduced machine over 4π).
FOUR_STROKE_CYCLE = 2.0 * TWO_PI
#: The fewest and the default number of positions N the cycle is divided into.
MIN_FLYWHEEL_POSITIONS = 4
DEFAULT_FLYWHEEL_POSITIONS = 12
#: The methods that design J_F, and how the Wittenbauer diagram's tangents are inclined.
FLYWHEEL_METHODS: tuple[FlywheelMethod, ...] = ("wittenbauer", "indicator")
FLYWHEEL_TANGENTS: tuple[TangentForm, ...] = ("exact", "book")
#: Which moment is constant, found from the balance of work over a cycle.
BALANCES: tuple[Balance, ...] = ("driving", "resisting")
#: The ``solve_ivp`` methods the true motion may use, and the range of its rtol.
SOLVERS = ("Radau", "BDF", "LSODA", "RK45", "DOP853")
RTOL_MIN, RTOL_MAX = 1e-14, 1e-2
#: The most masses, and the most loads, one machine may have.
MAX_MACHINE_ITEMS = 100
#: The types of [[flywheel.load]].
LOAD_TYPES = ("slider", "moment", "crank")

#: A flywheel scene's own scales: name → kind (drawing mm each), and a linkage's.
_FLYWHEEL_SCALES = (("phi", "angle"), ("M", "moment"), ("J", "inertia"), ("T", "energy"))
_LINKAGE_SCALES = (("l", "length"), ("v", "velocity"))
#: The keys only a slider load has, and only a moment or crank load has.
_SLIDER_KEYS = ("point", "during", "sense", "s_over_H", "pressure", "force", "piston_diameter", "area")
_MOMENT_KEYS = ("link", "phi", "moment")
_DURING: tuple[During, ...] = ("forward", "backward", "both")
_STROKES: tuple[Stroke, ...] = ("forward", "backward")
_CRANK_ONLY = (
    'a flywheel scene\'s driver is a crank (type = "crank"): the machine is reduced to its crank'
)
_NEEDS_LINKAGE = "needs a linkage ([frame], [driver], [[dyad]] …)"
#: A fraction a/b, as δ may be written ("1/25").
_FRACTION = re.compile(r"\s*([0-9]+(?:\.[0-9]*)?)\s*/\s*([0-9]+(?:\.[0-9]*)?)\s*")


@dataclass
class _Series:
    """A list of numbers read from one key: SI values, values as written, key path, unit."""

    si: list[float]
    path: str
    unit: str = ""
    num: float = 1.0
    den: float = 1.0

    def text(self, si: float) -> str:
        """An SI value of this series in the user's unit: ``"180°"``, ``"0.5 MPa"``."""
        x = compact(float(f"{si * self.den / self.num:.6g}"))
        return f"{x}°" if self.unit == "deg" else f"{x} {self.unit}".rstrip()


@dataclass
class _Machine:
    """What the rest of the scene tells the [flywheel] table: the linkage (None when there is
    none, or it is wrong), whether the scene has one at all, and the driver's speed."""

    has_linkage: bool
    linkage: Linkage | None
    omega: float | None = None  # |ω| of the driver, rad/s
    omega_path: str = "driver.omega"
    omega_given: bool = False  # the driver's omega was read (so ω_m is known or reported)


def _count_text(value: Any) -> str:
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return compact(float(value)) if math.isfinite(value) else repr(value)
    return type_name(value)


# --------------------------------------------------------------------------------------------
# Lists and tables
# --------------------------------------------------------------------------------------------


#: The largest magnitude of a table's value in SI (N, Pa, N·m, rad): far beyond any machine.
MAX_TABLE_SI = 1e15


def _series(r: Reader, base: str, kind: str) -> _Series | None:
    """A list of at least two numbers with a unit (``phi_deg = [0, 180, 360]``), in SI."""
    given = r.quantity(base, kind)
    if given is None:
        return None
    path = r.at(given.key)
    written = _number_list(r, given.value, path)
    if written is None:
        return None
    if given.key == base:
        unit = r.units.get(kind) or ""
    else:
        unit = SUFFIXES[kind][given.key[len(base) + 1 :]]
    si = [given.si(x) for x in written]
    for i, x in enumerate(si):
        if not abs(x) <= MAX_TABLE_SI:  # a load of 1e300 Pa: its diagram's arrows collapse in round-off
            r.problem(f"{path}[{i}]", f"{written[i]:g} is beyond {MAX_TABLE_SI:g} in SI units: no machine of "
                                      "the book, and no diagram can be drawn of it")
            return None
    return _Series(si, path, unit, given.num, given.den)


def _number_list(r: Reader, value: Any, path: str) -> list[float] | None:
    if not isinstance(value, list):
        r.problem(path, f"must be a list of numbers, not {type_name(value)}")
        return None
    if len(value) < 2:
        r.problem(path, f"must have at least 2 points, not {len(value)}")
        return None
    if len(value) > MAX_TABLE_POINTS:
        r.problem(path, f"too many points ({len(value)} > {MAX_TABLE_POINTS})")
        return None
    items = [r.number(v, f"{path}[{i}]") for i, v in enumerate(value)]
    valid = [x for x in items if x is not None]
    return valid if len(valid) == len(items) else None


def _non_decreasing(r: Reader, s: _Series, what: str) -> bool:
    for i in range(1, len(s.si)):
        if s.si[i] < s.si[i - 1]:
            r.problem(
                f"{s.path}[{i}]",
                f"{s.text(s.si[i])} comes after {s.text(s.si[i - 1])}: the {what} must not "
                "decrease (a repeated value is a step)",
            )
            return False
    return True


def _same_length(r: Reader, x: _Series, y: _Series, x_key: str, what: str) -> bool:
    """``y`` has one value for each of ``x`` (the key ``x_key``)."""
    if len(x.si) == len(y.si):
        return True
    r.problem(y.path, f"has {len(y.si)} values, {x_key} has {len(x.si)}: one {what} for each")
    return False


def _phi_table(r: Reader, cycle: float | None) -> Table | None:
    """``phi`` (non-decreasing, within [0, Φ]) and ``moment``: a moment against φ."""
    phi = _series(r, "phi", "angle")
    moment = _series(r, "moment", "moment")
    ok = phi is not None and _non_decreasing(r, phi, "angles")
    if phi is not None and ok and cycle is not None:
        for i, x in enumerate(phi.si):
            if x < 0 or x > cycle * (1 + 1e-12):
                r.problem(
                    f"{phi.path}[{i}]",
                    f"{phi.text(x)} is outside the cycle: φ runs from 0 at position 1 to "
                    f"Φ = {phi.text(cycle)}",
                )
                ok = False
                break
    if phi is None or moment is None or not ok:
        return None
    if not _same_length(r, phi, moment, phi.path.rsplit(".", 1)[-1], "moment"):
        return None
    angles = tuple(min(v, cycle) if cycle is not None else v for v in phi.si)
    return Table(angles, tuple(v + 0.0 for v in moment.si))


def _fractions(r: Reader) -> _Series | None:
    """``s_over_H``: the slider's displacement over its stroke, 0 first, 1 last, rising."""
    value = r.raw(
        "s_over_H",
        required=True,
        hint="the indicator diagram's abscissae s/H, from 0 to 1, e.g. s_over_H = [0, 0.5, 1]",
    )
    if value is MISSING:
        return None
    path = r.at("s_over_H")
    written = _number_list(r, value, path)
    if written is None:
        return None
    s = _Series(list(written), path)
    for i, x in enumerate(written):
        if not 0 <= x <= 1:
            r.problem(
                f"{path}[{i}]",
                f"must lie between 0 and 1, not {compact(x)}: s/H is the slider's displacement "
                "over its stroke",
            )
            return None
    if not _non_decreasing(r, s, "values"):
        return None
    if written[0] != 0:
        r.problem(f"{path}[0]", f"must be 0, not {compact(written[0])}: s/H runs from 0 to 1")
        return None
    if written[-1] != 1:
        r.problem(
            f"{path}[{len(written) - 1}]",
            f"must be 1, not {compact(written[-1])}: s/H runs from 0 to 1",
        )
        return None
    return s


def _non_negative(r: Reader, s: _Series | None, why: str) -> _Series | None:
    if s is None:
        return None
    for i, x in enumerate(s.si):
        if x < 0:
            r.problem(f"{s.path}[{i}]", f"must be ≥ 0, not {s.text(x)}: {why}")
            return None
    return s


def _at_least_zero(r: Reader, v: Value | None) -> Value | None:
    if v is not None and v.si < 0:
        r.problem(v.path, f"must be ≥ 0, not {v.text()}")
        return None
    if v is not None and 0.0 < v.si < sys.float_info.min:  # subnormal: at a drawing's scale it is 0
        r.problem(v.path, f"must be 0 or at least {sys.float_info.min:.3g}, not {v.text()}")
        return None
    return v


# --------------------------------------------------------------------------------------------
# [flywheel] and its tables
# --------------------------------------------------------------------------------------------


def _read_count(fw: Reader) -> int | None:
    """``positions``: N, a whole number 4 … 3600 (12 when absent)."""
    value = fw.raw("positions")
    if value is MISSING:
        return DEFAULT_FLYWHEEL_POSITIONS
    bounds = f"{MIN_FLYWHEEL_POSITIONS} … {MAX_POSITIONS}"
    if isinstance(value, bool) or not isinstance(value, int):
        fw.problem(
            fw.at("positions"),
            f"must be a whole number of positions ({bounds}), not {_count_text(value)}",
        )
        return None
    if not MIN_FLYWHEEL_POSITIONS <= value <= MAX_POSITIONS:
        why = "too few to draw the diagrams" if value < MIN_FLYWHEEL_POSITIONS else "absurd"
        fw.problem(
            fw.at("positions"),
            f"must lie between {MIN_FLYWHEEL_POSITIONS} and {MAX_POSITIONS}, not {value}: {why}",
        )
        return None
    return value


#: The least δ read: the tangents' slopes differ by 2δ, and double precision keeps ~1e-16 of them.
MIN_DELTA = 1e-9
#: The least mean speed read, rad/s: ω² must not underflow (no machine turns this slowly).
MIN_SPEED = 1e-100


def _read_delta(fw: Reader, required: bool) -> float | None:
    """``delta``: δ, a number or a fraction "1/25", 0 < δ < 2."""
    value = fw.raw(
        "delta",
        required=required,
        hint='the coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_m, e.g. delta = 0.04 '
        'or "1/25"',
    )
    if value is MISSING:
        return None
    path = fw.at("delta")
    if isinstance(value, str):
        m = _FRACTION.fullmatch(value)
        if m is None or float(m.group(2)) == 0:
            fw.problem(
                path, f'{say(value)} is not a fraction: write a number (0.04) or "1/25"'
            )
            return None
        delta, text = float(m.group(1)) / float(m.group(2)), say(value)
    else:
        x = fw.number(value, path)
        if x is None:
            return None
        delta, text = x, compact(x)
    if not 0 < delta < 2:
        fw.problem(
            path,
            f"must lie between 0 and 2, not {text}: δ = (ω_max − ω_min)/ω_m, and ω_min > 0",
        )
        return None
    if delta < MIN_DELTA:  # the tangents' slopes ω²(1 ± δ) differ by 2δ: lost near 1e-16
        fw.problem(path, f"{text} is below {MIN_DELTA:g}: the Wittenbauer tangents' slopes ω²(1 ± δ) would not "
                         "differ in double precision, and no flywheel is made to that")
        return None
    return delta


def _read_cycle(fw: Reader) -> float | None:
    """``cycle``: Φ, dividing one turn a whole number of times, or two turns (a four-stroke
    engine's working cycle); 360° when absent."""
    v = fw.value("cycle", "angle", required=False, positive=True)
    if v is None:
        return TWO_PI if fw.present("cycle") is None else None
    if abs(v.si - FOUR_STROKE_CYCLE) <= 1e-9 * FOUR_STROKE_CYCLE:
        return FOUR_STROKE_CYCLE
    k = TWO_PI / v.si
    if not (math.isfinite(k) and 1 <= k <= MAX_POSITIONS) or abs(k - round(k)) > 1e-9 * k:
        fw.problem(
            v.path,
            f"must divide one turn a whole number of times (360°, 180°, 120° …) or be two turns "
            f"(720°, a four-stroke engine), not {v.text()}",
        )
        return None
    return TWO_PI / round(k)


def _read_reduced_inertia(fw: Reader, cycle: float | None) -> tuple[Table | None, bool]:
    """[flywheel.reduced_inertia]: Jп(φ) as a table (> 0, φ rising from 0, closed at Φ); whether it
    was read (or is absent)."""
    return _read_cycle_table(fw, cycle, "reduced_inertia", ("inertia", "inertia"), "Jп")


def _read_energy_increment(fw: Reader, cycle: float | None) -> tuple[Table | None, bool]:
    """[flywheel.energy_increment]: ΔT(φ) as a table (0 at φ = 0, φ rising from 0, closed at Φ);
    whether it was read (or is absent)."""
    return _read_cycle_table(fw, cycle, "energy_increment", ("increment", "energy"), "ΔT")


def _read_cycle_table(fw: Reader, cycle: float | None, key: str, value: tuple[str, str], symbol: str
                      ) -> tuple[Table | None, bool]:
    """A quantity of the cycle as a table against φ: ``phi`` strictly rising from 0 within Φ and
    the ``value`` (base key, unit kind), closed at Φ (its last value equal to its first, or the
    table closed back to it over a gap no longer than its longest step); Jп > 0, ΔT from 0.
    Linear between its points (no steps). Whether it was read (or is absent)."""
    r = fw.table_at(key)
    if r is None:
        return None, key not in fw.table
    phi = _series(r, "phi", "angle")
    ys = _series(r, *value)
    r.finish()
    if phi is None or ys is None or cycle is None:
        return None, False
    if not _same_length(r, phi, ys, phi.path.rsplit(".", 1)[-1], symbol):
        return None, False
    x, y = phi.si, ys.si
    unit = {"inertia": "kg·m²"}.get(value[1], ys.unit)

    def written(v: float) -> str:  # the number as written, the unit as printed
        return f"{ys.text(v).split()[0]} {unit}".rstrip()

    if value[1] == "inertia":
        for i, v in enumerate(y):
            if not v > 0:
                r.problem(f"{ys.path}[{i}]", f"must be > 0, not {written(v)}: a reduced moment of inertia")
                return None, False
    elif y[0] != 0:
        r.problem(f"{ys.path}[0]", f"must be 0, not {written(y[0])}: {symbol} is counted from position 1 (φ = 0)")
        return None, False
    if x[0] != 0:
        r.problem(f"{phi.path}[0]", f"must be 0, not {phi.text(x[0])}: the table starts at position 1 (φ = 0)")
        return None, False
    for i in range(1, len(x)):
        if not x[i] > x[i - 1]:
            r.problem(f"{phi.path}[{i}]", f"{phi.text(x[i])} comes after {phi.text(x[i - 1])}: the angles must "
                                          f"increase ({symbol}(φ) has no steps)")
            return None, False
    last = len(x) - 1
    if x[-1] > cycle * (1 + 1e-12):
        r.problem(f"{phi.path}[{last}]", f"{phi.text(x[-1])} is outside the cycle: φ runs from 0 at position 1 "
                                         f"to Φ = {phi.text(cycle)}")
        return None, False
    if x[-1] >= cycle * (1 - 1e-12):
        if y[-1] != y[0]:
            r.problem(f"{ys.path}[{last}]", f"{written(y[-1])} at Φ = {phi.text(cycle)} differs from "
                                            f"{written(y[0])} at φ = 0: {symbol} repeats every cycle")
            return None, False
        return Table((*x[:-1], cycle), tuple(y)), True
    step = max(b - a for a, b in pairwise(x))
    if cycle - x[-1] > step * (1 + 1e-9):
        r.problem(phi.path, f"ends at {phi.text(x[-1])}, {phi.text(cycle - x[-1])} short of the cycle "
                            f"Φ = {phi.text(cycle)}, more than its longest step ({phi.text(step)}): "
                            "a table of another period?")
        return None, False
    return Table((*x, cycle), (*y, y[0])), True  # closed: back to its value at φ = 0 at Φ


def _read_pole_distance(fw: Reader) -> float | None:
    """``pole_distance_mm``: H, drawing mm, always in millimetres of drawing."""
    h = pole_distances(fw)
    return None if h is None else h[0]


def _read_masses(fw: Reader, machine: _Machine) -> tuple[list[Mass], bool]:
    """[[flywheel.mass]]: the moving links' inertias; whether any was given."""
    if "mass" in fw.table and not machine.has_linkage:
        fw.used.add("mass")
        fw.known.add("mass")
        fw.problem(
            fw.at("mass"),
            f"[[flywheel.mass]] {_NEEDS_LINKAGE}: without one give the machine's whole "
            "reduced inertia as flywheel.inertia_kgm2",
        )
        return [], True
    readers = fw.tables_at("mass")
    if len(readers) > MAX_MACHINE_ITEMS:
        fw.problem(fw.at("mass"), f"too many masses ({len(readers)} > {MAX_MACHINE_ITEMS})")
        return [], True
    links = machine.linkage.links() if machine.linkage is not None else None
    frame_link = machine.linkage.frame_link if machine.linkage is not None else None
    masses: list[Mass] = []
    seen: dict[str, str] = {}
    for r in readers:
        value = r.raw("link", required=True, hint='the number of the link, e.g. link = "2"')
        link = None if value is MISSING else r.link_id(value, r.at("link"))
        value = r.raw("point", required=True, hint='its centre of mass S, a point of that link')
        point = None if value is MISSING else r.point_name(value, r.at("point"))
        mass = _at_least_zero(r, r.value("mass", "mass"))
        inertia = _at_least_zero(r, r.value("inertia", "inertia", required=False))
        r.finish()
        if link is not None and links is not None:
            if link in seen:
                r.problem(r.at("link"), f"link {link} already has its mass ({seen[link]})")
                link = None
            elif link == frame_link:
                r.problem(r.at("link"), f"link {link} is the frame: it does not move")
                link = None
            elif link not in links:
                r.problem(
                    r.at("link"),
                    f"link {link} is not a moving link (links: {', '.join(links)})",
                )
                link = None
            else:
                seen[link] = r.path
                if point is not None and point not in links[link]:
                    r.problem(
                        r.at("point"),
                        f"{point} is not a point of link {link} (it carries "
                        f"{', '.join(links[link])})",
                    )
                    point = None
        if link is not None and point is not None and mass is not None and (
            inertia is not None or r.present("inertia") is None
        ):
            masses.append(Mass(link, point, mass.si, inertia.si if inertia else 0.0))
    return masses, bool(readers)


def _read_load(r: Reader, machine: _Machine, cycle: float | None) -> Load | None:
    """One [[flywheel.load]]: a slider's indicator diagram, a moment on a link, or on the crank."""
    kind = r.string("type", choices=LOAD_TYPES, required=True)
    if kind is None:  # nothing to judge the other keys by
        r.ignore(*_SLIDER_KEYS, *_MOMENT_KEYS)
        r.finish()
        return None
    if kind != "crank" and not machine.has_linkage:
        r.problem(
            r.at("type"),
            f'a "{kind}" load {_NEEDS_LINKAGE}: without one give the moments reduced to the '
            'crank, type = "crank"',
        )
        r.ignore(*_SLIDER_KEYS, *_MOMENT_KEYS)
        r.finish()
        return None
    if kind == "slider":
        return _read_slider_load(r, machine)
    not_for(r, _SLIDER_KEYS, f'only for type = "slider" (this load is {kind})')
    link: str | None = None
    if kind == "moment":
        value = r.raw("link", required=True, hint='the number of the link it acts on, e.g. link = "3"')
        link = None if value is MISSING else r.link_id(value, r.at("link"))
    else:
        not_for(
            r,
            ["link"],
            'a "crank" load acts on the crank itself: leave link out (or write type = "moment")',
        )
    table = _phi_table(r, cycle)
    r.finish()
    if kind == "crank":
        return None if table is None else CrankMoment(table)
    linkage = machine.linkage
    if link is not None and linkage is not None:
        links = linkage.links()
        if link == linkage.frame_link:
            r.problem(r.at("link"), f"link {link} is the frame: a moment on it does no work")
            return None
        if link not in links:
            r.problem(r.at("link"), f"link {link} is not a moving link (links: {', '.join(links)})")
            return None
    return None if link is None or table is None else LinkMoment(link, table)


def _read_slider_load(r: Reader, machine: _Machine) -> SliderLoad | None:
    """A force on a slider along its guide, from its indicator diagram F(s/H) or p(s/H)·A."""
    not_for(r, _MOMENT_KEYS, 'only for type = "moment" or "crank" (this load is slider)')
    value = r.raw("point", required=True, hint='the slider\'s point, e.g. point = "C"')
    point = None if value is MISSING else r.point_name(value, r.at("point"))
    during = r.string("during", choices=_DURING, required=True)
    sense = r.string("sense", choices=_STROKES, required=True)
    s = _fractions(r)
    has_force, has_pressure = r.present("force") is not None, r.present("pressure") is not None
    magnitude = "the diagram gives the force's magnitude; sense gives its direction"
    force = pressure = None
    if has_force:
        force = _non_negative(r, _series(r, "force", "force"), magnitude)
    if has_pressure:
        pressure = _non_negative(r, _series(r, "pressure", "pressure"), magnitude)
    area: float | None = None
    if has_pressure and has_force:
        r.problem(
            r.at(r.present("force") or "force"),
            "give force or pressure (with the piston's area), not both",
        )
        r.ignore("piston_diameter", "area")
    elif has_pressure:
        diameter = r.value("piston_diameter", "length", required=False, positive=True)
        given = r.value("area", "area", required=False, positive=True)
        if r.present("piston_diameter") is not None and r.present("area") is not None:
            r.problem(
                r.at(r.present("area") or "area"),
                "give piston_diameter or area, not both",
            )
        elif r.present("piston_diameter") is None and r.present("area") is None:
            r.problem(
                r.at("piston_diameter"),
                "missing: with pressure give piston_diameter_mm (the area is π d²/4) or area_mm2",
            )
        elif diameter is not None:
            area = math.pi * diameter.si * diameter.si / 4  # inf, not OverflowError, for d = 1e300
        elif given is not None:
            area = given.si
    elif has_force:
        not_for(r, ["piston_diameter", "area"], "only with pressure (force is already a force)")
    else:
        r.value("piston_diameter", "length", required=False, positive=True)
        r.value("area", "area", required=False, positive=True)
        r.problem(
            r.at("force"),
            "missing: give force_N = [...] (one per s_over_H), or pressure_MPa = [...] with "
            "piston_diameter_mm",
        )
    r.finish()
    y = force if has_force else pressure
    if s is None or y is None or not _same_length(r, s, y, "s_over_H", "value"):
        return None
    if has_force and not has_pressure:
        forces = tuple(y.si)
    elif has_pressure and area is not None and not has_force:
        forces = tuple(p * area for p in y.si)
    else:
        return None
    if not all(abs(f) <= MAX_TABLE_SI for f in forces):  # the piston's area times the pressure
        r.problem(r.at(r.present("piston_diameter") or r.present("area") or "area"),
                  f"the piston's force p·A reaches beyond {MAX_TABLE_SI:g} N: no machine of the book, "
                  "and no diagram can be drawn of it")
        return None
    linkage = machine.linkage
    if point is None or during is None or sense is None or linkage is None:
        return None
    sliders = {d.c: d.guide.angle for d in linkage.dyads if isinstance(d, (RRP, RPP)) and isinstance(d.guide, Guide)}
    if point not in sliders:
        which = f"this linkage's: {', '.join(sliders)}" if sliders else "this linkage has none"
        r.problem(
            r.at("point"),
            f"{point} is not a slider: a slider load acts on the slider point of an RRP or RPP "
            f"dyad ({which})",
        )
        return None
    return SliderLoad(
        point,
        sliders[point],
        1 if sense == "forward" else -1,
        during,
        Table(tuple(s.si), forces),
    )


def _read_motor(
    fw: Reader, balance: str | None, omega: float | None, braking_only: bool
) -> tuple[Motor | None, bool]:
    """[flywheel.motor]: stiffness or synchronous speed; whether it was valid (or absent)."""
    m = fw.table_at("motor")
    if m is None:
        return None, "motor" not in fw.table
    before = len(m.problems)
    if braking_only:
        fw.problem(
            fw.at("motor"),
            "only with [[flywheel.load]]: a motor drives the machine through its cycle, and a "
            "braking-only scene has none",
        )
    elif balance == "resisting":
        fw.problem(
            fw.at("motor"),
            'only with balance = "driving": a motor\'s characteristic gives the driving moment, '
            "and here the constant moment is the resistance",
        )
    value = m.raw("stiffness")
    stiffness = None if value is MISSING else m.number(value, m.at("stiffness"), positive=True)
    synchronous = m.value("synchronous", "omega", required=False, positive=True)
    syn_key = m.present("synchronous")
    if value is not MISSING and syn_key is not None:
        m.problem(m.at(syn_key), "give stiffness or synchronous, not both")
    elif value is MISSING and syn_key is None:
        m.problem(
            m.path,
            "give stiffness (e.g. stiffness = 1e5) or the synchronous speed (synchronous_rpm, "
            "above the mean speed)",
        )
    elif synchronous is not None and omega is not None and not synchronous.si > omega:
        m.problem(
            synchronous.path,
            f"must exceed the mean speed ω_m = {synchronous.text(omega)}: a motor gives no "
            "moment at its synchronous speed",
        )
    m.finish()
    if len(m.problems) != before:
        return None, False
    if stiffness is not None:
        return Motor(stiffness=stiffness), True
    if synchronous is not None:
        return Motor(synchronous=synchronous.si), True
    return None, False


def _read_true_motion(fw: Reader, braking_only: bool) -> tuple[TrueMotionSpec | None, bool]:
    """[flywheel.true_motion]: the solver and its rtol; whether it was valid (or absent)."""
    t = fw.table_at("true_motion")
    if t is None:
        return None, "true_motion" not in fw.table
    before = len(t.problems)
    if braking_only:
        fw.problem(
            fw.at("true_motion"),
            "only with [[flywheel.load]]: the true motion is run with the designed J_F, and a "
            "braking-only scene designs none",
        )
    solver = t.string("solver", choices=SOLVERS, default="Radau")
    value = t.raw("rtol")
    rtol = 1e-10
    if value is not MISSING:
        x = t.number(value, t.at("rtol"), positive=True)
        if x is not None and not RTOL_MIN <= x <= RTOL_MAX:
            t.problem(t.at("rtol"), f"must lie between {RTOL_MIN:g} and {RTOL_MAX:g}, not {x:g}")
        elif x is not None:
            rtol = x
    t.finish()
    if len(t.problems) != before or solver is None:
        return None, False
    return TrueMotionSpec(solver, rtol), True


def _read_braking(fw: Reader) -> tuple[Braking | None, bool]:
    """[flywheel.braking]: the brake's moment (> 0) and the time limit (> 0, optional)."""
    b = fw.table_at("braking")
    if b is None:
        return None, "braking" not in fw.table
    moment = b.value("moment", "moment", positive=True)
    limit = b.value("time_limit", "time", required=False, positive=True)
    b.finish()
    if moment is None or (limit is None and b.present("time_limit") is not None):
        return None, False
    return Braking(moment.si, None if limit is None else limit.si, moment.path), True


def _read_flywheel(
    fw: Reader, machine: _Machine, start: float | None
) -> tuple[FlywheelScene | None, int | None]:
    """[flywheel]: the flywheel problem and N (None when invalid)."""
    problems = fw.problems
    before = len(problems)
    loads_value = fw.table.get("load", MISSING)
    no_loads = loads_value is MISSING or loads_value == []
    braking_only = _braking_only(fw.table)
    given_dT = "energy_increment" in fw.table  # ΔT as a table: no loads, no constant moment to find

    count = _read_count(fw)
    delta = _read_delta(fw, required=not braking_only)
    omega: float | None
    if machine.has_linkage:
        not_for(
            fw,
            ["speed"],
            f"given twice: with a linkage the mean speed ω_m is the driver's omega "
            f"({machine.omega_path})",
        )
        omega = machine.omega
    else:
        speed = fw.value("speed", "omega", positive=True)
        omega = None if speed is None else speed.si
        if speed is not None and speed.si < MIN_SPEED:  # ω² in every energy and slope would vanish
            fw.problem(speed.path, f"ω_m = {speed.si:g} rad/s is below {MIN_SPEED:g} rad/s: its square, in every "
                                         "kinetic energy and tangent slope, vanishes in double precision")
            omega = None
    cycle = _read_cycle(fw)
    if given_dT:
        not_for(fw, ["balance", "motor", "true_motion"], "not with [flywheel.energy_increment]: the table of ΔT "
                "gives no moments, so there is no constant moment to find and no equation of motion to solve")
    balance = fw.string("balance", choices=BALANCES, required=not (no_loads or given_dT), default="driving")
    method = fw.string("method", choices=FLYWHEEL_METHODS, default="wittenbauer")
    tangents = fw.string("tangents", choices=FLYWHEEL_TANGENTS, default="exact")
    if given_dT:
        not_for(fw, ["pole_distance"], "not with [flywheel.energy_increment]: ΔT is given, nothing is integrated")
    pole = _read_pole_distance(fw)
    inertia = _at_least_zero(fw, fw.value("inertia", "inertia", required=False))
    inertia_ok = inertia is not None or fw.present("inertia") is None
    masses, masses_given = _read_masses(fw, machine)
    jp_table, jp_ok = _read_reduced_inertia(fw, cycle)
    dt_table, dt_ok = _read_energy_increment(fw, cycle)
    if given_dT and not no_loads:
        fw.problem(fw.at("energy_increment"), "not with [[flywheel.load]]: the table of ΔT already holds the "
                   "moments' work; give one or the other")
        dt_ok = False

    fw.known.add("load")
    readers = fw.tables_at("load")
    loads: list[Load | None] = []
    if len(readers) > MAX_MACHINE_ITEMS:
        fw.problem(fw.at("load"), f"too many loads ({len(readers)} > {MAX_MACHINE_ITEMS})")
    else:
        loads = [_read_load(r, machine, cycle) for r in readers]

    motor, motor_ok = _read_motor(fw, balance, omega, braking_only)
    true_motion, true_ok = _read_true_motion(fw, braking_only)
    if "reduced_inertia" in fw.table and "true_motion" in fw.table:
        fw.problem(fw.at("true_motion"), "not with [flywheel.reduced_inertia]: the equation of motion needs "
                   "dJп/dφ, and a table of Jп has none at its points (give the masses instead)")
        true_ok = False
    braking, braking_ok = _read_braking(fw)
    if no_loads and "braking" not in fw.table and not given_dT:
        fw.problem(fw.at("load"), "no [[flywheel.load]]: nothing for the flywheel to smooth")
    no_inertia = inertia_ok and not masses_given and (inertia is None or inertia.si == 0)
    if braking_only and braking is not None and no_inertia:
        fw.problem(
            fw.at("braking"),
            "nothing to stop: a braking-only scene designs no flywheel, so give the "
            "machine's reduced inertia (inertia_kgm2) or its [[flywheel.mass]]",
        )
    fw.finish()

    read_loads = [load for load in loads if load is not None]
    if not (  # complete: every value read
        len(problems) == before
        and count is not None and omega is not None and cycle is not None
        and balance is not None and method is not None and tangents is not None
        and (delta is not None or braking_only)
        and (pole is not None or "pole_distance_mm" not in fw.table)
        and inertia_ok
        and motor_ok
        and true_ok
        and braking_ok
        and jp_ok
        and dt_ok
        and len(read_loads) == len(loads)
        and (machine.linkage is not None or not machine.has_linkage)
        and (start is not None or not machine.has_linkage)
    ):
        return None, count
    model = Machine(
        linkage=machine.linkage,
        start=start if start is not None else 0.0,
        cycle=cycle,
        omega_m=omega,
        delta=delta if delta is not None else math.nan,
        masses=tuple(masses),
        loads=tuple(read_loads),
        inertia=inertia.si if inertia is not None else 0.0,
        balance=balance,
        motor=motor,
        inertia_table=jp_table,
        energy_table=dt_table,
    )
    scene = FlywheelScene(
        machine=model,
        positions=count,
        method=method,
        tangents=tangents,
        pole_distance=pole,
        true_motion=true_motion,
        braking=braking,
    )
    return scene, count


# --------------------------------------------------------------------------------------------
# The driver of a flywheel scene's linkage, and position labels 1 … N
# --------------------------------------------------------------------------------------------


def _driver_rules(top: Reader) -> None:
    """A flywheel scene's driver is a crank, at one angle (position 1), with no epsilon."""
    driver = top.table.get("driver")
    if not isinstance(driver, dict) or driver.get("type") != "crank":
        return
    for key, value in driver.items():
        if (key == "angle" or key.startswith("angle_")) and isinstance(value, (list, dict)):
            top.problem(
                f"driver.{key_text(key)}",
                "one number in a flywheel scene: the crank's angle at position 1 (the "
                "[flywheel] positions divide the cycle from there)",
            )
        if key == "epsilon" or key.startswith("epsilon_"):
            top.problem(
                f"driver.{key_text(key)}",
                "not in a flywheel scene: the crank turns at the mean speed ω_m on average, "
                "and how far it strays is what the flywheel limits; leave epsilon out",
            )


def _braking_only(table: Any) -> bool:
    """A [flywheel] with [flywheel.braking] and no [[flywheel.load]]: the run-down alone."""
    if not isinstance(table, dict):
        return False
    loads = table.get("load", MISSING)
    return (loads is MISSING or loads == []) and "braking" in table


def _check_energy_scale(top: Reader, scales: Mapping[str, float], pole: float | None) -> None:
    """Graphical integration ties the scales: μT = μM·μφ·H. All four given must agree."""
    if pole is None or not all(k in scales for k in ("T", "M", "phi")):
        return
    tied = scales["M"] * scales["phi"] * pole
    if abs(scales["T"] - tied) <= 1e-9 * scales["T"]:
        return
    table = top.table.get("scales")
    key = next((k for k in table if k == "T" or k.startswith("T_")), "T") if isinstance(table, dict) else "T"
    top.problem(
        f"scales.{key_text(key)}",
        f"μT = {scales['T']:.6g} J/mm contradicts μM·μφ·H = {tied:.6g} J/mm (H = pole_distance_mm "
        f"= {compact(pole)}): graphical integration ties the four; give three of them",
    )


def _label_problem(key: str, count: int) -> str | None:
    """Why ``key``'s ``@label`` is not a position 1 … N, or None."""
    if "@" not in key:
        return None
    label = key.split("@", 1)[1]
    if label.isdigit() and str(int(label)) == label and 1 <= int(label) <= count:
        return None
    return f"no position {label}: the positions are numbered 1 … {count}"


def _check_find(top: Reader, count: int | None) -> None:
    """``find``: quantity names, with ``@k`` for a position 1 … N."""
    value = top.table.get("find")
    if not isinstance(value, list):
        return
    for i, item in enumerate(value):
        if not isinstance(item, str) or not item.strip():
            continue  # reported by read_header
        if not QUANTITY_NAME.fullmatch(item):
            top.problem(
                f"find[{i}]",
                f"{say(item)} is not a quantity name: letters, digits and underscores, then "
                "@position if it is one position's (J_F, M_b, Jp@1)",
            )
        elif count is not None:
            reason = _label_problem(item, count)
            if reason:
                top.problem(f"find[{i}]", reason)


# --------------------------------------------------------------------------------------------
# Public
# --------------------------------------------------------------------------------------------


def parse_flywheel_scene(
    data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]
) -> Scene[FlywheelScene]:
    """The rest of :func:`graphmech.scene.parse_scene` for a scene with a [flywheel] table.

    Parameters
    ----------
    data : dict
        The TOML document.
    source : str
        The name used in messages.
    top : Reader
        The top-level reader, with [units] already read (its problems are kept).
    order : mapping
        Top-level key → its place in the file, to put problems in file order.

    Returns
    -------
    Scene
        With ``flywheel`` set; ``linkage`` and ``positions`` (the crank's angles at positions
        1 … N, labelled "1" … "N") when the scene has a linkage, else None.

    Raises
    ------
    SceneError
        With every problem found, the first in file order in the message.

    Examples
    --------
    >>> from graphmech.scene import parse_scene
    >>> scene = parse_scene({
    ...     "flywheel": {"speed_rpm": 620, "delta": "1/80", "cycle_deg": 180,
    ...                  "balance": "resisting", "inertia_kgm2": 0.02,
    ...                  "load": [{"type": "crank", "phi_deg": [0, 30, 60, 180],
    ...                            "moment_Nm": [0, 150, 150, 0]}]},
    ... }, "engine.toml")
    >>> machine = scene.problem.machine
    >>> machine.linkage is None, machine.delta, round(machine.cycle, 6), scene.problem.positions
    (True, 0.0125, 3.141593, 12)
    >>> machine.loads[0].table.y
    (0.0, 150.0, 150.0, 0.0)
    >>> parse_scene({"flywheel": {"speed_rpm": 620, "delta": 0.04, "balance": "driving"}}, "x.toml")
    Traceback (most recent call last):
    ...
    graphmech.errors.SceneError: x.toml: flywheel.load: no [[flywheel.load]]: nothing for the flywheel to smooth
    """
    problems = top.problems
    has_linkage = any(k in data for k in LINKAGE_KEYS)
    braking_only = _braking_only(data.get("flywheel"))
    choices = (("mechanism",) if has_linkage else ()) + FLYWHEEL_SHOW_CHOICES
    title, show, find = read_header(top, choices, BRAKING_SHOW_DEFAULT if braking_only else FLYWHEEL_SHOW_DEFAULT)
    fw_table = data.get("flywheel")
    has_braking = isinstance(fw_table, dict) and "braking" in fw_table
    given_dT = isinstance(fw_table, dict) and "energy_increment" in fw_table
    if isinstance(data.get("show"), list):
        for i, item in enumerate(data["show"]):
            if not isinstance(item, str) or item not in show:
                continue
            if braking_only and item not in ("rundown", "mechanism"):
                top.problem(
                    f"show[{i}]",
                    f"{item} needs [[flywheel.load]]: a braking-only scene has no cycle to draw "
                    "(show rundown or mechanism, or leave show out)",
                )
            elif given_dT and item in ("moment", "work"):
                top.problem(f"show[{i}]", f"{item} needs the moments: [flywheel.energy_increment] gives ΔT, which "
                            "cannot be split back into its driving and resisting moments")
            elif item == "rundown" and not has_braking:
                top.problem(f"show[{i}]", "rundown needs a [flywheel.braking] table: the run-down under a brake")
    refuse = () if has_linkage else tuple(
        (name, "only with a linkage: a flywheel scene without one has no mechanism to draw")
        for name, _ in _LINKAGE_SCALES
    )
    if given_dT:  # nothing is integrated: no moment diagram, no pole
        refuse += (("M", "not with [flywheel.energy_increment]: ΔT is given, no moment diagram is drawn"),)
    scales = read_scales(
        top,
        entries=_FLYWHEEL_SCALES + (_LINKAGE_SCALES if has_linkage else ()),
        refuse=refuse,
    )

    machine = _Machine(has_linkage, None)
    start: float | None = None
    if has_linkage:
        linkage, positions, driver = read_linkage(top, _CRANK_ONLY)
        _driver_rules(top)
        machine.linkage = linkage
        raw = top.table.get("driver")
        if isinstance(raw, dict):
            key = next((k for k in raw if k == "omega" or k.startswith("omega_")), "omega")
            machine.omega_path = f"driver.{key_text(key)}"
        if isinstance(driver.model, Crank):
            if driver.model.omega == 0:
                top.problem(
                    machine.omega_path,
                    "must not be 0: it is the crank's mean speed ω_m, and its sign the sense "
                    "of rotation",
                )
            else:
                machine.omega = abs(driver.model.omega)
        if positions is not None and len(positions.values) == 1:
            start = positions.values[0]

    fw = top.table_at("flywheel")
    flywheel, count = (None, None) if fw is None else _read_flywheel(fw, machine, start)
    if flywheel is not None:
        _check_energy_scale(top, scales, flywheel.pole_distance)
    _check_find(top, count)
    measured = read_measured(top, None)
    if count is not None:
        for key, _ in measured:
            reason = _label_problem(key, count)
            if reason:
                top.problem(f"measured.{key_text(key)}", reason)
    precision, page = read_tail(top)
    if problems or flywheel is None:
        raise_sorted(problems, data, order, "flywheel", source)
    model = flywheel.machine
    positions_out = None
    if model.linkage is not None:
        positions_out = Positions(
            tuple(model.crank_angle(phi) for phi in model.positions(flywheel.positions)),
            tuple(str(k) for k in range(1, flywheel.positions + 1)),
        )
    return Scene(
        source=source,
        title=title,
        show=show,
        find=find,
        scales=scales,
        linkage=model.linkage,
        positions=positions_out,
        measured=measured,
        precision_mm=precision,
        page=page,
        kind="flywheel",
        problem=flywheel,
    )


__all__ = [
    "BALANCES",
    "DEFAULT_FLYWHEEL_POSITIONS",
    "FLYWHEEL_METHODS",
    "FLYWHEEL_SHOW_CHOICES",
    "FLYWHEEL_SHOW_DEFAULT",
    "FLYWHEEL_TANGENTS",
    "MIN_FLYWHEEL_POSITIONS",
    "SOLVERS",
    "parse_flywheel_scene",
]
