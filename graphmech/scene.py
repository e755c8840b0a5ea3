"""Read a scene file: the TOML that says what to construct, draw and check.

A scene describes either a linkage (frame points, a driver, Assur dyads in assembly order,
extra points on links, and the driver's positions), a disc cam (its base circle, follower
and motion program, table ``[cam]``) or a flywheel problem (a machine — a linkage or none —
with its masses and loads, table ``[flywheel]``, read by :mod:`graphmech.problems.flywheel.scene`),
together with the drawing scales, what to show and find, and the values a draughtsman
measured on paper. Every number is converted to SI on load.

Validation collects *every* problem and raises one :class:`~graphmech.errors.SceneError`;
its key paths read the way the user wrote the file (``dyad[0].lengths[1]``,
``driver.angle_deg[2]``, ``frame.D``, ``cam.segment[2].angle``), and its message is the first
problem in file order.
Whether a linkage can be *assembled* at a position is not decided here: the construction
does that, position by position.

The format, with an example of every feature, is ``docs/scene-format.md``.
"""

from __future__ import annotations

import difflib
import math
import os
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Mapping, NoReturn

from graphmech.errors import SceneError
from graphmech.scales import PAPER, phi_axis_problem, scale_out_of_range
from graphmech.mechanisms.cam import (
    DiscCam,
    Follower,
    MotionProgram,
    OscillatingFollower,
    Segment,
    TranslatingFollower,
)
from graphmech.mechanisms.machine import Machine
from graphmech.mechanisms.linkage import (
    RPP,
    RPR,
    RRP,
    RRR,
    Crank,
    Driver,
    Guide,
    Linkage,
    LinkPoint,
    Positions,
    SliderInput,
)
from graphmech.tolerances import DRAWING_PRECISION_MM, MAX_PRECISION_MM, PARALLEL_SIN

#: A scene file larger than this (bytes) is refused before it is parsed.
MAX_BYTES = 1 << 20
#: The most driver positions one scene may ask for.
MAX_POSITIONS = 3600
#: The longest title, in characters.
MAX_TITLE = 200
#: What a scene may show, in the order a textbook draws them.
SHOW_CHOICES = ("mechanism", "velocity", "acceleration", "instant_centres")
#: What a cam scene may show: the profile by inversion and the s–δ, v–δ, a–δ diagrams.
CAM_SHOW_CHOICES = ("profile", "displacement", "velocity", "acceleration")
#: What a cam scene shows when it does not say.
CAM_SHOW_DEFAULT = ("profile",)
#: The inversion's division step when a cam scene does not give one, rad (15°).
CAM_STEP_DEFAULT = math.radians(15.0)
#: The finest division step, rad (0.1°: at most 3600 divisions).
CAM_STEP_MIN = math.radians(0.1)
#: The coarsest division step, rad (90°).
CAM_STEP_MAX = math.radians(90.0)
#: The most segments a cam's motion program may have.
MAX_SEGMENTS = 100
#: The most points a ``table`` law may have.
MAX_TABLE_POINTS = 1000
#: Named paper sizes, (width, height) in mm: one table for the whole package.
PAPER_SIZES = PAPER


@dataclass(frozen=True)
class Page:
    """The drawing sheet.

    Parameters
    ----------
    size : (float, float)
        Width and height, mm; A4 landscape by default (see :data:`PAPER_SIZES`).
    """

    size: tuple[float, float] = (297.0, 210.0)


@dataclass(frozen=True)
class CamScene:
    """The cam of a cam scene.

    Parameters
    ----------
    cam : DiscCam
        The cam, its follower and motion program, in SI (m, rad, rad/s).
    step : float
        The division step of the inversion, rad (default 15°); the inversion also divides
        at the joints of the motion program's segments.
    roller_circles : bool
        Draw the roller circles of the inversion (always False without a roller).
    """

    cam: DiscCam
    step: float
    roller_circles: bool = True


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
    method: str = "wittenbauer"
    tangents: str = "exact"
    pole_distance: float | None = None
    true_motion: TrueMotionSpec | None = None
    braking: Braking | None = None


@dataclass(frozen=True)
class Scene:
    """A validated scene, all in SI units.

    A scene is a linkage scene (``linkage`` and ``positions`` set, ``cam`` and ``flywheel``
    None), a cam scene (``cam`` set, ``linkage`` and ``positions`` None) or a flywheel scene
    (``flywheel`` set; ``linkage`` and ``positions`` set when it has a linkage, else None).

    Parameters
    ----------
    source : str
        The file name used in messages.
    title : str
        Free text (the renderer escapes it).
    show : tuple of str
        A subset of :data:`SHOW_CHOICES` (a cam scene: :data:`CAM_SHOW_CHOICES`; a flywheel
        scene: :data:`graphmech.problems.flywheel.scene.FLYWHEEL_SHOW_CHOICES`, with a linkage also
        "mechanism") in the user's order, no duplicates.
    find : tuple of str
        Quantity names as written (``"v_C"``, ``"omega_3"``, ``"alpha_max"``, ``"J_F"``);
        ``check`` validates them against the construction.
    scales : dict
        Only the scales given: ``"l"`` m/mm, ``"v"`` (m/s)/mm, ``"a"`` (m/s²)/mm; a cam scene
        also ``"s"`` m/mm and ``"phi"`` rad/mm, and for an oscillating follower ``"s"`` is
        rad/mm, ``"v"`` (rad/s)/mm, ``"a"`` (rad/s²)/mm; a flywheel scene ``"phi"`` rad/mm,
        ``"M"`` (N·m)/mm, ``"J"`` (kg·m²)/mm, ``"T"`` J/mm, and with a linkage ``"l"``, ``"v"``.
    linkage : Linkage or None
        The mechanism, in m and rad (None in a cam scene and a flywheel scene without one).
    positions : Positions or None
        Driver values in SI (rad or m) and their labels as written in the scene's unit
        (``"50"``), used as name suffixes such as ``v_C@50`` (None in a cam scene). In a
        flywheel scene with a linkage, the crank's absolute angles at its N positions,
        labelled ``"1"`` … ``"N"``.
    measured : tuple of (str, float)
        The ``[measured]`` table in file order, raw: quantity values in SI or drawn
        segment lengths in mm (``("p'c'", 40.5)``); ``check`` interprets them.
    precision_mm : float
        Drawing precision for judging measured values, mm.
    page : Page
        The sheet.
    cam : CamScene or None
        The cam of a cam scene (None otherwise).
    flywheel : FlywheelScene or None
        The machine and the flywheel problem of a flywheel scene (None otherwise).
    cycle : graphmech.problems.cycle.scene.CycleScene or None
        A linkage scene's full cycle ([cycle]) and characteristics (None when it asks for
        neither).
    """

    source: str
    title: str
    show: tuple[str, ...]
    find: tuple[str, ...]
    scales: dict[str, float] = field(hash=False)
    linkage: Linkage | None = None
    positions: Positions | None = None
    measured: tuple[tuple[str, float], ...] = ()
    precision_mm: float = DRAWING_PRECISION_MM
    page: Page = Page()
    cam: CamScene | None = None
    flywheel: FlywheelScene | None = None
    forces: Any = None  # a ForceScene (graphmech.problems.forces.scene) in a force scene
    efficiency: Any = None  # graphmech.problems.efficiency.scene.EfficiencyProblem of an [efficiency] scene
    balancing: Any = None  # graphmech.problems.balancing.scene.BalancingProblem of a [balancing] scene
    cycle: Any = None  # graphmech.problems.cycle.scene.CycleScene: a full cycle and/or the characteristics
    structure: Any = None  # graphmech.problems.structure.scene.StructureScene of a [structure] scene


# --------------------------------------------------------------------------------------------
# Units: each kind of quantity, the units a [units] table may name, and the key suffixes.
# A conversion is (numerator, denominator): SI value = written value · num / den, so that
# 60 mm becomes exactly 0.06 m.
# --------------------------------------------------------------------------------------------

_UNITS: dict[str, dict[str, tuple[float, float]]] = {
    "length": {"mm": (1.0, 1000.0), "cm": (1.0, 100.0), "m": (1.0, 1.0)},
    "angle": {"deg": (math.pi, 180.0), "rad": (1.0, 1.0)},
    "omega": {"rad/s": (1.0, 1.0), "rpm": (math.pi, 30.0), "deg/s": (math.pi, 180.0)},
    "epsilon": {
        "rad/s2": (1.0, 1.0),
        "rad/s²": (1.0, 1.0),
        "rad/s^2": (1.0, 1.0),
        "deg/s2": (math.pi, 180.0),
        "deg/s²": (math.pi, 180.0),
        "deg/s^2": (math.pi, 180.0),
    },
    "velocity": {"m/s": (1.0, 1.0), "mm/s": (1.0, 1000.0)},
    "acceleration": {
        "m/s2": (1.0, 1.0),
        "m/s²": (1.0, 1.0),
        "m/s^2": (1.0, 1.0),
        "mm/s2": (1.0, 1000.0),
        "mm/s²": (1.0, 1000.0),
        "mm/s^2": (1.0, 1000.0),
    },
    "mass": {"kg": (1.0, 1.0)},
    "inertia": {"kgm2": (1.0, 1.0), "kg·m2": (1.0, 1.0), "kg·m²": (1.0, 1.0)},
    "moment": {"Nm": (1.0, 1.0), "N·m": (1.0, 1.0), "kNm": (1000.0, 1.0), "kN·m": (1000.0, 1.0)},
    "energy": {"J": (1.0, 1.0), "kJ": (1000.0, 1.0)},
    "force": {"N": (1.0, 1.0), "kN": (1000.0, 1.0)},
    "pressure": {
        "MPa": (1e6, 1.0),
        "kPa": (1000.0, 1.0),
        "Pa": (1.0, 1.0),
        "bar": (1e5, 1.0),
    },
    "time": {"s": (1.0, 1.0), "ms": (1.0, 1000.0)},
    "area": {
        "mm2": (1.0, 1e6),
        "mm²": (1.0, 1e6),
        "cm2": (1.0, 1e4),
        "cm²": (1.0, 1e4),
        "m2": (1.0, 1.0),
        "m²": (1.0, 1.0),
    },
    "mass_radius": {"kgm": (1.0, 1.0), "kg·m": (1.0, 1.0), "kgcm": (1.0, 100.0), "kg·cm": (1.0, 100.0),
                    "kgmm": (1.0, 1000.0), "kg·mm": (1.0, 1000.0)},
}

#: Key suffix (after ``base_``) → unit, per kind; the first is the one messages suggest.
_SUFFIXES: dict[str, dict[str, str]] = {
    "length": {"mm": "mm", "cm": "cm", "m": "m"},
    "angle": {"deg": "deg", "rad": "rad"},
    "omega": {"rad_s": "rad/s", "rpm": "rpm", "deg_s": "deg/s"},
    "epsilon": {"rad_s2": "rad/s2", "deg_s2": "deg/s2"},
    "velocity": {"m_s": "m/s", "mm_s": "mm/s"},
    "acceleration": {"m_s2": "m/s2", "mm_s2": "mm/s2"},
    "mass": {"kg": "kg"},
    "inertia": {"kgm2": "kgm2"},
    "moment": {"Nm": "Nm", "kNm": "kNm"},
    "energy": {"J": "J", "kJ": "kJ"},
    "force": {"N": "N", "kN": "kN"},
    "pressure": {"MPa": "MPa", "kPa": "kPa", "Pa": "Pa", "bar": "bar"},
    "time": {"s": "s", "ms": "ms"},
    "area": {"mm2": "mm2", "cm2": "cm2", "m2": "m2"},
    "mass_radius": {"kgm": "kgm", "kgcm": "kgcm", "kgmm": "kgmm"},
}

_KIND_WORDS = {
    "length": "a length",
    "angle": "an angle",
    "omega": "an angular velocity",
    "epsilon": "an angular acceleration",
    "velocity": "a velocity",
    "acceleration": "an acceleration",
    "mass": "a mass",
    "inertia": "a moment of inertia",
    "moment": "a moment",
    "energy": "an energy",
    "force": "a force",
    "pressure": "a pressure",
    "time": "a time",
    "area": "an area",
    "mass_radius": "a mass-radius product",
}

_PER_MM = "_per_mm"
_ALL_SUFFIXES = {s for table in _SUFFIXES.values() for s in table} | {
    s + _PER_MM for table in _SUFFIXES.values() for s in table
}

# Names. fullmatch() everywhere: "$" would let a trailing newline through.
_POINT_NAME = re.compile(r"[A-Z]+[0-9]*['′]*")
_LINK_ID = re.compile(r"[0-9A-Za-z]{1,8}")
_LABEL = r"(?:@[0-9A-Za-z.+\-]{1,24})?"
_QUANTITY_NAME = re.compile(r"[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)*" + _LABEL)
_SEGMENT_NAME = re.compile(r"(?:[a-zπ][0-9]*['′]*){2,8}" + _LABEL)

_TOP_KEYS = (
    "title",
    "show",
    "find",
    "scales",
    "units",
    "frame",
    "driver",
    "dyad",
    "point",
    "measured",
    "check",
    "page",
    "cam",
    "flywheel",
    "forces",
    "structure",
)

#: The tables only a linkage scene has.
_LINKAGE_KEYS = ("frame", "driver", "dyad", "point")

_MISSING: Any = object()

#: Frame point name → coordinates in m (None when they were invalid: the name still counts).
_Frame = Mapping[str, "tuple[float, float] | None"]


def _say(value: Any, limit: int = 40) -> str:
    """A user-written string made safe for a one-line message (quoted, escaped, cut short)."""
    text = str(value)
    if len(text) > limit:
        text = text[: limit - 1] + "…"
    return repr(text)


def _key_text(key: str) -> str:
    """A key as it appears in a key path: plain when harmless, else quoted and escaped."""
    return key if re.fullmatch(r"[A-Za-z0-9_'′@.+\-π]{1,60}", key) else _say(key, 60)


def _type_name(value: Any) -> str:
    if isinstance(value, bool):
        return "true/false"
    if isinstance(value, (int, float)):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a table"
    return "a date/time" if hasattr(value, "isoformat") else type(value).__name__


def _label(value: float) -> str:
    """Compact text of a number as the user wrote it: 50.0 → "50", 12.5 → "12.5"."""
    text = f"{value:.12g}"
    return "0" if text == "-0" else text


def _choices(words: Iterable[str]) -> str:
    words = [str(w) for w in words]
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " or " + words[-1]


def _did_you_mean(word: str, candidates: Iterable[str]) -> str:
    """``"; did you mean X?"`` for the nearest candidate, or ``""``."""
    pool = sorted(set(candidates))
    same_letters = [c for c in pool if c.casefold() == word.casefold()]
    close = same_letters or difflib.get_close_matches(word, pool, n=3, cutoff=0.6)
    swapped = [c for c in close if sorted(c) == sorted(word)]  # "stpe" is "step", not "stop"
    close = swapped or close
    return f"; did you mean {close[0]}?" if close else ""


def _maybe(word: str, candidates: Iterable[str]) -> str:
    """``" (did you mean X?)"`` for the nearest candidate, or ``""``."""
    tip = _did_you_mean(word, candidates)
    return f" ({tip[2:]})" if tip else ""


# --------------------------------------------------------------------------------------------
# The reader: one TOML table, its key path, the keys it has read; problems go to one list.
# --------------------------------------------------------------------------------------------


@dataclass
class _Given:
    """A quantity as found in a table: the key as written, the raw value, its conversion."""

    key: str
    value: Any
    num: float
    den: float

    def si(self, x: float) -> float:
        return x * self.num / self.den


@dataclass
class _Value:
    """A quantity read and converted: SI value, and how to say a length or an angle in the
    unit the user wrote it in (for messages)."""

    si: float
    unit: str
    path: str
    num: float
    den: float

    def text(self, si: float | None = None) -> str:
        """``si`` (default: this value) in the user's unit: ``"35 mm"``, ``"25°"``."""
        x = (self.si if si is None else si) * self.den / self.num
        label = _label(float(f"{x:.6g}"))
        return f"{label}°" if self.unit == "deg" else f"{label} {self.unit}"


class _Reader:
    """A view of one table that tracks its key path and collects problems.

    Every ``read``-like method marks the key as used and remembers it as a known key, so
    that :meth:`finish` can report the rest as unknown, with a suggestion.
    """

    def __init__(
        self,
        table: Mapping[str, Any],
        path: str,
        problems: list[tuple[str, str]],
        units: Mapping[str, str | None],
    ) -> None:
        self.table = table
        self.path = path
        self.problems = problems
        self.units = units
        self.used: set[str] = set()
        self.known: set[str] = set()

    # -- paths and problems ------------------------------------------------------------------
    def at(self, key: str | int) -> str:
        if isinstance(key, int):
            return f"{self.path}[{key}]"
        key = _key_text(key)
        return f"{self.path}.{key}" if self.path else key

    def problem(self, path: str, reason: str) -> None:
        self.problems.append((path, reason))

    def sub(self, table: Mapping[str, Any], path: str) -> _Reader:
        return _Reader(table, path, self.problems, self.units)

    # -- raw access ----------------------------------------------------------------------------
    def raw(self, key: str, *, required: bool = False, hint: str = "") -> Any:
        """The value under ``key`` (marked used), or ``_MISSING``."""
        self.known.add(key)
        if key not in self.table:
            if required:
                self.problem(self.at(key), "missing" + (f": {hint}" if hint else ""))
            return _MISSING
        self.used.add(key)
        return self.table[key]

    def finish(self, hint: str = "") -> None:
        """Report every key that was not read, suggesting the nearest known key."""
        for key in self.table:
            if key not in self.used:
                tip = _did_you_mean(key, self.known) or (f"; {hint}" if hint else "")
                self.problem(self.at(key), "unknown key" + tip)

    # -- typed values ------------------------------------------------------------------------
    def number(self, value: Any, path: str, *, positive: bool = False) -> float | None:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.problem(path, f"must be a number, not {_type_name(value)}")
            return None
        try:
            x = float(value)
        except OverflowError:
            self.problem(path, "number too large")
            return None
        if not math.isfinite(x):
            self.problem(path, f"must be a finite number, not {value!r}")
            return None
        if positive and x <= 0:
            self.problem(path, "must be > 0")
            return None
        return x

    def numbers(
        self, value: Any, path: str, count: int, *, positive: bool = False, shape: str = "[x, y]"
    ) -> list[float] | None:
        """A list of exactly ``count`` numbers; ``shape`` shows the user what is meant."""
        if not isinstance(value, list) or len(value) != count:
            shape = f"{shape}: a list of {count} numbers"
            got = f"a list of {len(value)}" if isinstance(value, list) else _type_name(value)
            self.problem(path, f"must be {shape}, not {got}")
            return None
        out = [self.number(v, f"{path}[{i}]", positive=positive) for i, v in enumerate(value)]
        return None if any(x is None for x in out) else out  # type: ignore[return-value]

    def string(
        self,
        key: str,
        *,
        choices: Iterable[str] | None = None,
        required: bool = False,
        default: str | None = None,
    ) -> str | None:
        options = tuple(choices) if choices is not None else None
        hint = f"write {key} = {_choices(repr(c) for c in options)}" if options else ""
        value = self.raw(key, required=required, hint=hint.replace("'", '"'))
        if value is _MISSING:
            return default
        if not isinstance(value, str):
            self.problem(self.at(key), f"must be a string, not {_type_name(value)}")
            return None
        if options is not None and value not in options:
            self.problem(
                self.at(key),
                f"unknown value {_say(value)}: use {_choices(options)}" + _maybe(value, options),
            )
            return None
        return value

    def flag(self, key: str) -> bool | None:
        """A true/false key: its value, or None when it is missing or not a boolean (said)."""
        value = self.raw(key)
        if value is _MISSING:
            return None
        if not isinstance(value, bool):
            self.problem(self.at(key), f"must be true or false, not {_type_name(value)}")
            return None
        return value

    def point_name(self, value: Any, path: str) -> str | None:
        if not isinstance(value, str):
            self.problem(
                path, f'must be a point name (a string such as "B"), not {_type_name(value)}'
            )
            return None
        if not _POINT_NAME.fullmatch(value) or len(value) > 8:
            self.problem(
                path,
                f"{_say(value)} is not a point name: capital letters, then digits or primes "
                "(B, C2, E')",
            )
            return None
        return value

    def link_id(self, value: Any, path: str) -> str | None:
        if isinstance(value, int) and not isinstance(value, bool) and 0 <= value < 10**8:
            return str(value)
        if isinstance(value, str) and _LINK_ID.fullmatch(value):
            return value
        self.problem(
            path,
            'must be a link number such as "2", not '
            + (_say(value) if isinstance(value, str) else _type_name(value)),
        )
        return None

    def name_list(self, key: str, count: int, check: Any) -> list[tuple[str | None, str]]:
        """``count`` names under ``key``, each checked by ``check``; (name or None, path)."""
        value = self.raw(key, required=True, hint=f"a list of {count}")
        path = self.at(key)
        if value is _MISSING:
            return [(None, f"{path}[{i}]") for i in range(count)]
        if not isinstance(value, list) or len(value) != count:
            got = f"a list of {len(value)}" if isinstance(value, list) else _type_name(value)
            self.problem(path, f"must be a list of {count}, not {got}")
            return [(None, f"{path}[{i}]") for i in range(count)]
        return [(check(v, f"{path}[{i}]"), f"{path}[{i}]") for i, v in enumerate(value)]

    def table_at(self, key: str, *, required: bool = False, hint: str = "") -> _Reader | None:
        value = self.raw(key, required=required, hint=hint)
        if value is _MISSING:
            return None
        if not isinstance(value, dict):
            self.problem(self.at(key), f"must be a table, not {_type_name(value)}")
            return None
        return self.sub(value, self.at(key))

    def tables_at(self, key: str) -> list[_Reader]:
        """An array of tables (``[[key]]``), each with its path ``key[i]``."""
        value = self.raw(key)
        if value is _MISSING:
            return []
        if isinstance(value, dict):  # [dyad] for [[dyad]]: say so, then read it anyway
            self.problem(self.at(key), f"must be an array of tables: write [[{self.at(key)}]]")
            value = [value]
        if not isinstance(value, list):
            self.problem(self.at(key), f"must be an array of tables: write [[{self.at(key)}]]")
            return []
        out = []
        for i, item in enumerate(value):
            if isinstance(item, dict):
                out.append(self.sub(item, f"{self.at(key)}[{i}]"))
            else:
                self.problem(f"{self.at(key)}[{i}]", f"must be a table, not {_type_name(item)}")
        return out

    # -- quantities with units -----------------------------------------------------------------
    def quantity(
        self, base: str, kind: str, *, required: bool = True, per_mm: bool = False
    ) -> _Given | None:
        """Find ``base`` written with a unit suffix (``base_mm``) or plain under ``[units]``.

        Returns None (after reporting, if there is something to report) when the quantity is
        absent, given twice, or its unit is wrong or not stated.
        """
        tail = _PER_MM if per_mm else ""
        suffixes = {s + tail: u for s, u in _SUFFIXES[kind].items()}
        preferred = base + "_" + next(iter(suffixes))
        self.known.update([base, *(f"{base}_{s}" for s in suffixes)])
        found: list[tuple[str, str | None]] = []
        wrong_unit = False
        for key in self.table:
            if key == base:
                found.append((key, None))
            elif key.startswith(base + "_"):
                rest = key[len(base) + 1 :]
                if rest in suffixes:
                    found.append((key, suffixes[rest]))
                elif rest in _ALL_SUFFIXES:
                    self.used.add(key)
                    wrong_unit = True
                    fits = _choices(f"{base}_{s}" for s in suffixes)
                    self.problem(
                        self.at(key), f"{rest} is not a unit of {_KIND_WORDS[kind]}; write {fits}"
                    )
        for key, _ in found:
            self.used.add(key)
        if len(found) > 1:
            self.problem(self.at(found[1][0]), f"given twice (also as {found[0][0]})")
            return None
        if not found:
            if required and not wrong_unit:
                self.problem(
                    self.at(base), f"missing: write {preferred} (or {base} with [units] {kind})"
                )
            return None
        key, unit = found[0]
        if unit is None:
            if kind not in self.units:
                self.problem(
                    self.at(key), f"unit not stated: write {preferred} or set [units] {kind}"
                )
                return None
            unit = self.units[kind]
            if unit is None:  # the [units] entry itself is wrong and already reported
                return None
        num, den = _UNITS[kind][unit]
        return _Given(key, self.table[key], num, den)

    def scalar(
        self,
        base: str,
        kind: str,
        *,
        required: bool = True,
        default: float | None = None,
        positive: bool = False,
    ) -> float | None:
        """A single number with a unit, in SI; ``default`` (SI) when absent and not required."""
        if not required and self.present(base) is None:
            self.quantity(base, kind, required=False)  # registers the known keys
            return default
        v = self.value(base, kind, required=required, positive=positive)
        return None if v is None else v.si

    def value(
        self, base: str, kind: str, *, required: bool = True, positive: bool = False
    ) -> _Value | None:
        """Like :meth:`scalar`, keeping the unit and key path for messages; None when absent."""
        if not required and self.present(base) is None:
            self.quantity(base, kind, required=False)  # registers the known keys
            return None
        given = self.quantity(base, kind, required=required)
        if given is None:
            return None
        path = self.at(given.key)
        x = self.number(given.value, path, positive=positive)
        if x is None:
            return None
        if positive and not given.si(x) > 0.0:  # 5e-324 rpm is a positive number, and 0 rad/s
            self.problem(path, f"{x:g} is 0 once converted to SI units: too small for double precision")
            return None
        if kind == "angle" and not abs(given.si(x)) <= MAX_ANGLE_TURNS * 2.0 * math.pi:
            # 1e300° is a direction only by the accident of argument reduction: no reader meant it
            self.problem(path, f"{x:g} is more than {MAX_ANGLE_TURNS} turns: give the angle within one turn")
            return None
        if given.key == base:
            unit = self.units[kind] or ""
        else:
            unit = _SUFFIXES[kind][given.key[len(base) + 1 :]]
        return _Value(given.si(x), unit, path, given.num, given.den)

    def ignore(self, *bases: str) -> None:
        """Mark ``base`` and ``base_<anything>`` as read, silently (their context is broken)."""
        for key in self.table:
            if any(key == b or key.startswith(b + "_") for b in bases):
                self.used.add(key)
        self.known.update(bases)

    def present(self, base: str) -> str | None:
        """The key under which ``base`` is written (plain or with any suffix), if any."""
        return next((k for k in self.table if k == base or k.startswith(base + "_")), None)

    def pair(self, base: str, *, required: bool = True) -> tuple[float, float] | None:
        """A point [x, y] with a length unit, in m."""
        given = self.quantity(base, "length", required=required)
        if given is None:
            return None
        xy = self.numbers(given.value, self.at(given.key), 2)
        return None if xy is None else (given.si(xy[0]), given.si(xy[1]))

    def positions(self, base: str, kind: str) -> Positions | None:
        """Driver positions: one number, a list, or a range table {start, stop, step}."""
        given = self.quantity(base, kind)
        if given is None:
            return None
        path, value = self.at(given.key), given.value
        if isinstance(value, dict):
            written = self._range(value, path)
        elif isinstance(value, list):
            if not value:
                self.problem(path, "no positions: give at least one")
                return None
            if len(value) > MAX_POSITIONS:
                self.problem(path, f"absurd position count ({len(value)} > {MAX_POSITIONS})")
                return None
            items = [self.number(v, f"{path}[{i}]") for i, v in enumerate(value)]
            written = [x for x in items if x is not None]
            if len(written) < len(items):
                return None
        else:
            x = self.number(value, path)
            written = None if x is None else [x]
        if written is None:
            return None
        labels = [_label(x) for x in written]
        seen: dict[str, int] = {}
        for i, lab in enumerate(labels):
            if lab in seen:
                where = f"{path}[{i}]" if isinstance(value, list) else path
                self.problem(where, f"position {lab} is given twice")
                return None
            seen[lab] = i
        return Positions(tuple(given.si(x) for x in written), tuple(labels))

    def _range(self, table: dict[str, Any], path: str) -> list[float] | None:
        r = self.sub(table, path)
        ends = {}
        for key in ("start", "stop", "step"):
            v = r.raw(key, required=True, hint="a range is {start = 0, stop = 360, step = 30}")
            ends[key] = None if v is _MISSING else r.number(v, r.at(key))
        r.finish()
        start, stop, step = ends["start"], ends["stop"], ends["step"]
        if start is None or stop is None or step is None:
            return None
        if step == 0:
            self.problem(r.at("step"), "must not be 0")
            return None
        steps = (stop - start) / step
        count = math.ceil(steps - 1e-9) if math.isfinite(steps) else 0  # stop is exclusive
        if not math.isfinite(steps) or count > MAX_POSITIONS:
            how_many = f"{count} > {MAX_POSITIONS}" if math.isfinite(steps) else "endless"
            self.problem(path, f"absurd position count ({how_many})")
            return None
        if count < 1:
            self.problem(
                path, "the range is empty: stop must lie beyond start, in the sense of step"
            )
            return None
        return [start + i * step for i in range(count)]


# --------------------------------------------------------------------------------------------
# What each driver, dyad or point adds to the structure, for the cross-checks.
# --------------------------------------------------------------------------------------------


@dataclass
class _Part:
    """One element's names and links, with the key paths to blame."""

    where: str  # "driver", "dyad[1]", "point[0]"
    needs: list[tuple[str, str]] = field(default_factory=list)  # (name, path) used, must exist
    defines: list[tuple[str, str]] = field(default_factory=list)  # (name, path) new points
    links: list[tuple[str, str]] = field(default_factory=list)  # (link, path) new moving links
    carries: list[tuple[str, list[str]]] = field(default_factory=list)  # link → its points
    translating: list[str] = field(default_factory=list)  # links that only translate
    on: tuple[str | None, str] | None = None  # a [[point]]'s link (None if invalid), its path
    model: Any = None  # the model object, when its own values were valid
    opaque: bool = False  # its type is unknown: names and links kept, nothing checked


def _opaque(
    r: _Reader, where: str, name_keys: tuple[str, ...], link_keys: tuple[str, ...]
) -> _Part:
    """A driver or dyad of unknown type: keep whatever names and links it gives, silently,
    so that the one wrong ``type`` does not bring a cascade of "not defined" after it."""

    def valid(values: Any, pattern: re.Pattern[str]) -> list[str]:
        items = values if isinstance(values, list) else [values]
        return [str(v) for v in items if isinstance(v, (str, int)) and pattern.fullmatch(str(v))]

    names = [n for key in name_keys for n in valid(r.table.get(key), _POINT_NAME)]
    links = [x for key in link_keys for x in valid(r.table.get(key), _LINK_ID)]
    return _Part(
        where,
        defines=[(n, where) for n in names],
        links=[(x, where) for x in links],
        carries=[(x, names) for x in links],
        opaque=True,
    )


def _valid(*values: Any) -> bool:
    return all(v is not None for v in values)


# --------------------------------------------------------------------------------------------
# One function per table.
# --------------------------------------------------------------------------------------------


def _read_units(top: _Reader) -> dict[str, str | None]:
    """[units]: kind → unit name (None when the entry is wrong: no cascade of 'not stated')."""
    r = top.table_at("units")
    units: dict[str, str | None] = {}
    if r is None:
        return units
    for kind, table in _UNITS.items():
        value = r.raw(kind)
        if value is _MISSING:
            continue
        if isinstance(value, str) and value in table:
            units[kind] = value
            continue
        units[kind] = None
        options = [u for u in table if "²" not in u and "^" not in u]
        if isinstance(value, str):
            r.problem(
                r.at(kind),
                f"unknown unit {_say(value)}: use {_choices(options)}" + _maybe(value, table),
            )
        else:
            r.problem(
                r.at(kind), f'must be a unit name such as "{options[0]}", not {_type_name(value)}'
            )
    r.finish()
    return units


def _read_header(
    top: _Reader,
    choices: tuple[str, ...] = SHOW_CHOICES,
    default: tuple[str, ...] = SHOW_CHOICES,
) -> tuple[str, tuple[str, ...], tuple[str, ...]]:
    """title, show (from ``choices``, ``default`` when absent), find."""
    title = top.string("title", default="") or ""
    if len(title) > MAX_TITLE:
        top.problem("title", f"too long ({len(title)} characters; at most {MAX_TITLE})")

    show: list[str] = []
    value = top.raw("show")
    if value is _MISSING:
        show = list(default)
    elif not isinstance(value, list) or not value:
        top.problem("show", f"must be a non-empty list from {_choices(choices)}")
    else:
        for i, item in enumerate(value):
            if not isinstance(item, str) or item not in choices:
                top.problem(
                    f"show[{i}]",
                    f"unknown value {_say(item)}: use {_choices(choices)}"
                    + (_did_you_mean(item, choices) if isinstance(item, str) else ""),
                )
            elif item in show:
                top.problem(f"show[{i}]", f"{item} is listed twice")
            else:
                show.append(item)

    find: list[str] = []
    value = top.raw("find")
    if value is not _MISSING:
        if not isinstance(value, list):
            top.problem("find", f"must be a list of quantity names, not {_type_name(value)}")
        else:
            for i, item in enumerate(value):
                if not isinstance(item, str) or not item.strip():
                    top.problem(f"find[{i}]", "must be a non-empty string (a quantity name)")
                elif item in find:
                    top.problem(f"find[{i}]", f"{_say(item)} is listed twice")
                else:
                    find.append(item)
    return title, tuple(show), tuple(find)


#: A cam scene's scales: name → kind of quantity, for a translating and an oscillating follower.
_CAM_SCALES = (
    ("l", "length", "length"),
    ("s", "length", "angle"),
    ("phi", "angle", "angle"),
    ("v", "velocity", "omega"),
    ("a", "acceleration", "epsilon"),
)


def _read_scales(
    top: _Reader,
    cam: bool = False,
    follower: str | None = None,
    entries: Iterable[tuple[str, str | None]] | None = None,
    refuse: Iterable[tuple[str, str]] = (),
) -> dict[str, float]:
    """[scales]: l, v, a per drawing mm, converted to SI per mm.

    A cam scene also has s and phi, and the kind of s, v and a depends on the follower
    (``follower`` None: unknown, those scales are skipped silently). Other scenes give their
    own ``entries`` (scale name, kind) and the scales they ``refuse`` (name, reason).
    """
    r = top.table_at("scales")
    scales: dict[str, float] = {}
    if r is None:
        return scales
    for name, reason in refuse:
        _not_for(r, [name], reason)
    kinds: list[tuple[str, str | None]]
    if entries is not None:
        kinds = list(entries)
    elif cam:
        kinds = [
            (name, None if follower is None else (lin if follower == "translating" else ang))
            for name, lin, ang in _CAM_SCALES
        ]
        kinds[0] = ("l", "length")
        kinds[2] = ("phi", "angle")
    else:
        kinds = [("l", "length"), ("v", "velocity"), ("a", "acceleration")]
    for name, kind in kinds:
        if kind is None:
            r.ignore(name)
            continue
        given = r.quantity(name, kind, required=False, per_mm=True)
        if given is not None:
            x = r.number(given.value, r.at(given.key), positive=True)
            if x is not None and (why := scale_out_of_range(given.si(x))):
                r.problem(r.at(given.key), f"{x:g}: {why}")
            elif x is not None:
                scales[name] = given.si(x)
    r.finish()
    return scales


def _read_frame(top: _Reader) -> tuple[dict[str, tuple[float, float] | None], str | None]:
    """[frame]: point coordinates (m; None when invalid) and the optional frame link number."""
    r = top.table_at("frame")
    points: dict[str, tuple[float, float] | None] = {}
    if r is None:
        return points, None
    link = None
    value = r.raw("link")
    if value is not _MISSING:
        link = r.link_id(value, r.at("link"))
    for key in list(r.table):
        if key in r.used or key == "link":
            continue
        name = key.split("_", 1)[0]
        if not _POINT_NAME.fullmatch(name) or len(name) > 8:
            continue  # finish() reports it
        points[name] = r.pair(name)  # the name counts even if its coordinates are wrong
    r.finish("a frame point is named in capitals with its coordinates, e.g. A_mm = [0, 0]")
    return points, link


def _read_guide(parent: _Reader, key: str, frame: _Frame) -> Guide | None:
    """A frame guide {through = [x, y] or a frame point's name, angle (default 0)}."""
    r = parent.table_at(
        key, required=True, hint=f"write {key} = {{through_mm = [0, 0], angle_deg = 0}}"
    )
    if r is None:
        return None
    through: tuple[float, float] | None
    if isinstance(r.table.get("through"), str):
        name = r.raw("through")
        through = frame.get(name)
        if name not in frame:
            r.problem(r.at("through"), f"{_say(name)} is not a frame point")
    else:
        through = r.pair("through")
    angle = r.scalar("angle", "angle", required=False, default=0.0)
    r.finish()
    return Guide(through, angle) if _valid(through, angle) else None  # type: ignore[arg-type]


def _read_driver(
    top: _Reader, frame: _Frame, crank_only: str = ""
) -> tuple[_Part, Positions | None]:
    """[driver]: a crank or a slider, and the positions it is drawn at.

    ``crank_only``: the reason a slider is refused (a scene whose driver must be a crank).
    """
    part = _Part("driver")
    r = top.table_at(
        "driver", required=True, hint='add a [driver] table (type = "crank" or "slider")'
    )
    if r is None:
        return part, None
    kind = r.string("type", choices=("crank", "slider"), required=True)
    if kind == "slider" and crank_only:
        r.problem(r.at("type"), crank_only)
        kind = None
    if kind is None:
        return _opaque(r, "driver", ("pivot", "tip", "point"), ("link",)), None
    link_value = r.raw("link", required=True, hint='the driver\'s link number, e.g. link = "1"')
    link = None if link_value is _MISSING else r.link_id(link_value, r.at("link"))
    if link is not None:
        part.links.append((link, r.at("link")))

    def name(key: str) -> str | None:
        value = r.raw(key, required=True, hint='a point name such as "B"')
        return None if value is _MISSING else r.point_name(value, r.at(key))

    model: Driver | None = None
    if kind == "crank":
        pivot, tip = name("pivot"), name("tip")
        length = r.scalar("length", "length", positive=True)
        positions = r.positions("angle", "angle")
        omega = r.scalar("omega", "omega")
        epsilon = r.scalar("epsilon", "epsilon", required=False, default=0.0)
        direction = r.string("direction", choices=("ccw", "cw"), default="ccw")
        if direction == "cw" and omega is not None and epsilon is not None:
            if omega < 0:
                r.problem(
                    r.at("direction"), 'with direction = "cw" give omega as a magnitude (≥ 0)'
                )
                omega = None
            else:  # both read positive clockwise; stored CCW-positive
                omega, epsilon = -omega + 0.0, -epsilon + 0.0
        if pivot is not None:
            if pivot not in frame:
                known = f"frame points: {', '.join(frame)}" if frame else "add it to [frame]"
                r.problem(r.at("pivot"), f"{pivot} is not a frame point ({known})")
            else:
                part.needs.append((pivot, r.at("pivot")))
        if tip is not None:
            part.defines.append((tip, r.at("tip")))
        if link is not None:
            part.carries.append((link, [n for n in (pivot, tip) if n]))
        if _valid(link, pivot, tip, length, omega, epsilon, direction):
            model = Crank(link, pivot, tip, length, omega, epsilon)  # type: ignore[arg-type]
    else:
        point = name("point")
        guide = _read_guide(r, "guide", frame)
        positions = r.positions("position", "length")
        velocity = r.scalar("velocity", "velocity")
        acceleration = r.scalar("acceleration", "acceleration", required=False, default=0.0)
        if point is not None:
            part.defines.append((point, r.at("point")))
        if link is not None:
            part.carries.append((link, [point] if point else []))
            part.translating.append(link)
        if _valid(link, point, guide, velocity, acceleration):
            model = SliderInput(link, point, guide, velocity, acceleration)  # type: ignore[arg-type]
    r.finish()
    part.model = model
    return part, positions


_DYAD_TYPES = ("RRR", "RRP", "RPR", "RPP")


def _read_dyad(r: _Reader, index: int, frame: _Frame) -> _Part:
    """One [[dyad]]: its joints, links and dimensions, by type."""
    where = f"dyad[{index}]"
    part = _Part(where)
    kind = r.string("type", choices=_DYAD_TYPES, required=True)
    if kind is None:
        return _opaque(r, where, ("joints",), ("links",))
    count = 3 if kind == "RRR" else 2
    joints = r.name_list("joints", count, r.point_name)
    links = r.name_list("links", 2, r.link_id)
    (i, i_path), (j, j_path) = links
    part.links = [(x, p) for x, p in links if x is not None]
    if i is not None and i == j:
        r.problem(j_path, "a dyad's two links must differ")
    names = [n for n, _ in joints]

    def carry(link: str | None, *points: str | None) -> None:
        if link is not None:
            part.carries.append((link, [p for p in points if p]))

    def new(k: int, name: str | None = None) -> None:
        n = joints[k][0] if name is None else name
        if n is not None:
            part.defines.append((n, joints[k][1]))

    def need(*ks: int) -> None:
        for k in ks:
            n, path = joints[k]
            if n is not None:
                part.needs.append((n, path))

    if kind == "RRR":
        p, c, q = names
        lengths_given = r.quantity("lengths", "length")
        lengths = None
        if lengths_given is not None:
            raw = r.numbers(
                lengths_given.value,
                r.at(lengths_given.key),
                2,
                positive=True,
                shape=f"[l_{p or 'P'}{c or 'C'}, l_{q or 'Q'}{c or 'C'}]",
            )
            lengths = None if raw is None else tuple(lengths_given.si(x) for x in raw)
        branch = r.string("branch", choices=("left", "right"), required=True)
        need(0, 2)
        new(1)
        carry(i, p, c)
        carry(j, q, c)
        if _valid(p, c, q, i, j, lengths, branch):
            part.model = RRR(p, c, q, (i, j), lengths, branch)  # type: ignore[arg-type]
        if p is not None and p == q:
            r.problem(joints[2][1], f"the two outer joints must differ ({p} twice)")
    elif kind == "RRP":
        p, c = names
        length = r.scalar("length", "length", positive=True)
        guide = _read_guide(r, "guide", frame)
        branch = r.string("branch", choices=("forward", "backward"), required=True)
        need(0)
        new(1)
        carry(i, p, c)
        carry(j, c)
        if j is not None:
            part.translating.append(j)
        if _valid(p, c, i, j, length, guide, branch):
            part.model = RRP(p, c, (i, j), length, guide, branch)  # type: ignore[arg-type]
    elif kind == "RPR":
        p, q = names
        bar = r.string("bar", choices=("first", "second"), required=True)
        need(0, 1)
        if p is not None and p == q:
            r.problem(joints[1][1], f"the two pivots must differ ({p} twice)")
        if _valid(p, q, i, j, bar):
            model = RPR(p, q, (i, j), bar)  # type: ignore[arg-type]
            part.model = model
            on_bar, on_block = model.coincident
            k = 1 if bar == "first" else 0  # the sliding point is the block's pivot
            new(k, on_bar)
            new(k, on_block)
            carry(model.bar_link, model.bar_pivot, on_bar)
            carry(model.block_link, model.block_pivot, on_block)
        else:
            carry(i, p)
            carry(j, q)
    else:  # RPP
        p, c = names
        slot = r.scalar("slot_angle", "angle")
        guide = _read_guide(r, "guide", frame)
        need(0)
        new(1)
        if p is not None and i is not None and j is not None:
            new(0, p + i)
            new(0, p + j)
        carry(i, p, p + i if p and i else None)
        carry(j, c, p + j if p and j else None)
        part.translating.extend(x for x in (i, j) if x is not None)
        if (
            slot is not None
            and guide is not None
            and abs(math.sin(slot - guide.angle)) < PARALLEL_SIN
        ):
            r.problem(r.at("slot_angle"), "the slot is parallel to the guide: the dyad cannot move")
        elif _valid(p, c, i, j, slot, guide):
            part.model = RPP(p, c, (i, j), slot, guide)  # type: ignore[arg-type]
    r.finish()
    return part


def _read_point(r: _Reader, index: int) -> _Part:
    """One [[point]]: a point fixed on a link, placed from one or two points of that link."""
    part = _Part(f"point[{index}]")
    value = r.raw("name", required=True, hint='a point name such as "E"')
    name = None if value is _MISSING else r.point_name(value, r.at("name"))
    value = r.raw("link", required=True, hint="the number of the link that carries the point")
    link = None if value is _MISSING else r.link_id(value, r.at("link"))
    bases: list[tuple[str, str]] = []
    value = r.raw("base", required=True, hint='base = ["B", "C"] (or one point with offset)')
    ok = value is not _MISSING
    if ok and (not isinstance(value, list) or len(value) not in (1, 2)):
        r.problem(r.at("base"), "must be a list of 1 or 2 point names")
        ok = False
    elif ok:
        for k, b in enumerate(value):
            b_name = r.point_name(b, f"{r.at('base')}[{k}]")
            ok = ok and b_name is not None
            if b_name is not None:
                bases.append((b_name, f"{r.at('base')}[{k}]"))
        if len(bases) == 2 and bases[0][0] == bases[1][0]:
            r.problem(bases[1][1], f"the two base points must differ ({bases[0][0]} twice)")
            ok = False
    along = left = None
    if ok and len(bases) == 1:  # a translating link: offset [dx, dy] from the one point
        offset = r.pair("offset", required=False)
        if offset is None and r.present("offset") is None:
            r.problem(r.at("offset"), "missing: with one base point give offset_mm = [dx, dy]")
        for key in filter(None, (r.present("along"), r.present("left"))):
            r.used.add(key)
            r.problem(r.at(key), "with one base point give offset = [dx, dy] instead")
        if offset is not None:
            along, left = offset
    elif ok:  # U + along·û + left·n̂
        along = r.scalar("along", "length")
        left = r.scalar("left", "length", required=False, default=0.0)
        offset_key = r.present("offset")
        if offset_key is not None:
            r.used.add(offset_key)
            r.problem(
                r.at(offset_key), "offset needs a single base point; with two give along/left"
            )
    else:  # base is broken: still read the rest so that it is not reported as unknown
        for extra in ("along", "left", "offset"):
            r.quantity(extra, "length", required=False)
    r.finish()
    if name is not None:
        part.defines.append((name, r.at("name")))
    part.needs, part.on = bases, (link, r.at("link"))
    if _valid(name, link, along, left) and ok:
        part.model = LinkPoint(name, link, tuple(b for b, _ in bases), along, left)  # type: ignore[arg-type]
    return part


def _read_measured(
    top: _Reader, labels: tuple[str, ...] | None, cam: bool = False
) -> tuple[tuple[str, float], ...]:
    """[measured]: quantity values (SI) or drawn segments (mm), kept raw and in order.

    A cam scene has no driver positions, so its names take no ``@label``.
    """
    r = top.table_at("measured")
    if r is None:
        return ()
    out: list[tuple[str, float]] = []
    for key, value in r.table.items():
        r.used.add(key)
        path = r.at(key)
        if not (_QUANTITY_NAME.fullmatch(key) or _SEGMENT_NAME.fullmatch(key)):
            r.problem(
                path,
                "not a measured name: a quantity (v_C, omega_2, a_k_C2C3, v_C@50) "
                "or a drawn segment (pc, \"p'c'\", \"n'c'\")",
            )
            continue
        x = r.number(value, path)
        if x is None:
            continue
        if "@" in key and cam:
            r.problem(
                path,
                "a cam scene has no driver positions: write the name without "
                f"@{_say(key.split('@', 1)[1])[1:-1]}",
            )
            continue
        if "@" in key and labels is not None:
            label = key.split("@", 1)[1]
            if label not in labels and label != "ic":  # omega_3@ic: by instant centres (ic_check)
                r.problem(path, f"no position is labelled {label} (positions: {', '.join(labels)})")
                continue
        out.append((key, x))
    return tuple(out)


def _read_check(top: _Reader) -> float:
    """[check]: precision_mm > 0."""
    r = top.table_at("check")
    if r is None:
        return DRAWING_PRECISION_MM
    value = r.raw("precision_mm")
    precision = DRAWING_PRECISION_MM
    if value is not _MISSING:
        x = r.number(value, r.at("precision_mm"), positive=True)
        if x is not None and x > MAX_PRECISION_MM:
            r.problem(r.at("precision_mm"), f"at most {MAX_PRECISION_MM:g} mm, not {x:g}: coarser judges nothing")
            x = None
        precision = precision if x is None else x
    r.finish()
    return precision


def _read_page(top: _Reader) -> Page:
    """[page]: size = "A4" (or another name in PAPER_SIZES) or [w, h] in mm."""
    r = top.table_at("page")
    if r is None:
        return Page()
    value = r.raw("size")
    size = Page().size
    if isinstance(value, str):
        if value in PAPER_SIZES:
            size = PAPER_SIZES[value]
        else:
            r.problem(
                r.at("size"),
                f"unknown paper {_say(value)}: use {_choices(PAPER_SIZES)} or [width, height] in mm"
                + _maybe(value, PAPER_SIZES),
            )
    elif value is not _MISSING:
        wh = r.numbers(value, r.at("size"), 2, positive=True, shape="[width, height]")
        if wh is not None:
            size = (wh[0], wh[1])
    r.finish()
    return Page(size)


# --------------------------------------------------------------------------------------------
# A cam scene: [cam], [cam.follower], [cam.program], [[cam.segment]].
# --------------------------------------------------------------------------------------------

_FOLLOWER_TYPES = ("translating", "oscillating")
_CONTACTS = ("knife", "roller", "flat")
_SEGMENT_KINDS = ("rise", "return", "dwell")
#: The keys only one type of follower has.
_TRANSLATING_ONLY = ("offset",)
_OSCILLATING_ONLY = ("pivot_distance", "arm", "sense")


def _read_tail(top: _Reader, known: Iterable[str] = _TOP_KEYS) -> tuple[float, Page]:
    """The end of every scene reader: [check] and [page], then any top-level key not in ``known``
    is an unknown key. Returns the drawing precision (mm) and the page."""
    precision, page = _read_check(top), _read_page(top)
    top.known.update(known)
    top.finish()
    return precision, page


def _peek_follower(data: Mapping[str, Any]) -> str | None:
    """The follower's type if the scene states a valid one (to choose the scales' units)."""
    cam = data.get("cam")
    follower = cam.get("follower") if isinstance(cam, dict) else None
    kind = follower.get("type") if isinstance(follower, dict) else None
    return kind if kind in _FOLLOWER_TYPES else None


def _not_for(r: _Reader, bases: Iterable[str], reason: str) -> None:
    """Refuse every key of ``bases`` (plain or with a suffix) present in the table."""
    for base in bases:
        r.known.add(base)
        for key in list(r.table):
            if key == base or key.startswith(base + "_"):
                r.used.add(key)
                r.problem(r.at(key), reason)


def _read_follower(
    cam: _Reader, r0: _Value | None
) -> tuple[Follower | None, str | None, str | None, bool]:
    """[cam.follower]: the follower, its type and contact (None when invalid), and whether
    anything in it was wrong."""
    r = cam.table_at(
        "follower",
        required=True,
        hint='add a [cam.follower] table (type = "translating" or "oscillating")',
    )
    if r is None:
        return None, None, None, True
    before = len(r.problems)
    kind = r.string("type", choices=_FOLLOWER_TYPES, required=True)
    contact = r.string("contact", choices=_CONTACTS, required=True)
    if kind is None:  # the keys belong to one type or the other: nothing to judge them by
        r.ignore("roller_radius", *_TRANSLATING_ONLY, *_OSCILLATING_ONLY)
        r.finish()
        return None, None, contact, True

    roller: _Value | None = None
    if contact == "roller":
        roller = r.value("roller_radius", "length", positive=True)
        if roller is not None and r0 is not None and roller.si >= r0.si:
            r.problem(
                roller.path,
                f"r_r = {roller.text()} is not smaller than the base radius r0 = {r0.text()}: "
                "the working profile's base circle (r0 − r_r) would vanish",
            )
            roller = None
    elif contact is None:
        r.ignore("roller_radius")
    else:
        _not_for(r, ["roller_radius"], f'only for contact = "roller" (this follower is {contact})')

    model: Follower | None = None
    # a value can be None without a problem here (a wrong [units] entry is reported there)
    complete = contact is not None and (contact != "roller" or roller is not None)
    if kind == "translating":
        offset = r.value("offset", "length", required=False)
        _not_for(r, _OSCILLATING_ONLY, f"only for an oscillating follower (this one is {kind})")
        if offset is not None and r0 is not None and abs(offset.si) >= r0.si:
            r.problem(
                offset.path,
                f"|e| = {offset.text(abs(offset.si))} is not smaller than the base radius "
                f"r0 = {r0.text()}: the follower's axis misses the base circle",
            )
        e = 0.0 if offset is None else offset.si + 0.0
        complete = complete and (offset is not None or r.present("offset") is None)
        if complete and len(r.problems) == before:
            model = TranslatingFollower(e, contact, roller.si if roller else 0.0)  # type: ignore[arg-type]
    else:
        a = r.value("pivot_distance", "length", positive=True)
        # a flat face lies along the rocker through A: it has no arm length (docs: not used)
        arm = r.value("arm", "length", positive=True, required=contact != "flat")
        sense = r.string("sense", choices=("opposite", "same"), required=True)
        _not_for(r, _TRANSLATING_ONLY, f"only for a translating follower (this one is {kind})")
        if contact == "flat":
            # the face is the line through the pivot A along the rocker, tangent to the base
            # circle at the start (ψ0 = asin(r0/a)); the arm length is not used
            if a is not None and r0 is not None and not r0.si < a.si:
                r.problem(
                    a.path,
                    f"a flat face through the pivot cannot touch the base circle: the base radius "
                    f"r0 = {r0.text()} must be smaller than pivot_distance a = {a.text()}",
                )
        elif a is not None and arm is not None and r0 is not None:
            near, far = abs(a.si - arm.si), a.si + arm.si
            if not near < r0.si < far:
                r.problem(
                    arm.path,
                    f"the arm cannot reach the base circle: r0 = {r0.text()} must lie between "
                    f"|a − l| = {r0.text(near)} and a + l = {r0.text(far)} "
                    f"(pivot_distance a = {a.text()}, arm l = {arm.text()})",
                )
        complete = complete and (arm is not None or (contact == "flat" and r.present("arm") is None))
        if complete and _valid(a, sense) and len(r.problems) == before:
            model = OscillatingFollower(
                a.si, arm.si if arm else 0.0, contact, roller.si if roller else 0.0, sense  # type: ignore[arg-type, union-attr]
            )
    r.finish()
    return model, kind, contact, len(r.problems) != before


def _motion_path(
    path: str, segments: list[tuple[str, str]], stroke_path: str
) -> str:
    """A key path of :func:`graphmech.mechanisms.motion.validate` as the scene writes it."""
    if path == "program.stroke":
        return stroke_path
    m = re.fullmatch(r"program\.segments(?:\[(\d+)\](.*))?", path)
    if m is None:
        return "cam." + path
    if m.group(1) is None:
        return "cam.segment"
    i = int(m.group(1))
    if i >= len(segments):
        return "cam.segment"
    where, angle_path = segments[i]
    return angle_path if m.group(2) == ".angle" else where + m.group(2)


def _read_program(cam: _Reader, follower: str | None) -> tuple[MotionProgram | None, bool]:
    """[cam.program] (the stroke) and [[cam.segment]]: the motion program; whether it had
    problems."""
    from graphmech.mechanisms.motion import LAWS, validate

    before = len(cam.problems)
    stroke: _Value | None = None
    stroke_path = "cam.program.stroke"
    p = cam.table_at(
        "program",
        required=True,
        hint="add a [cam.program] table with the stroke (stroke_mm = 16, or an oscillating "
        "follower's stroke_deg = 25)",
    )
    if p is not None:
        if follower is None:
            p.ignore("stroke")
        else:
            kind = "length" if follower == "translating" else "angle"
            stroke = p.value("stroke", kind, positive=True)
            if stroke is not None:
                stroke_path = stroke.path
                if kind == "angle" and stroke.si >= math.pi:
                    p.problem(
                        stroke.path,
                        f"an oscillating follower's stroke (its swing) must be below 180°, "
                        f"not {stroke.text()}",
                    )
                    stroke = None
        p.finish("the segments are [[cam.segment]] tables, beside [cam.program]")

    if cam.raw("segment") is _MISSING:
        cam.problem(
            cam.at("segment"),
            "missing: add [[cam.segment]] tables (kind = \"rise\", \"dwell\", \"return\" …) "
            "whose angles add up to 360°",
        )
        return None, True
    readers = cam.tables_at("segment")
    if len(readers) > MAX_SEGMENTS:
        cam.problem(cam.at("segment"), f"too many segments ({len(readers)} > {MAX_SEGMENTS})")
        return None, True
    intact = isinstance(cam.table["segment"], list) and len(readers) == len(cam.table["segment"])
    if not readers:
        if isinstance(cam.table["segment"], list) and not cam.table["segment"]:
            cam.problem(cam.at("segment"), "no segments: a program needs at least a rise and a return")
        return None, True

    segments: list[Segment] = []
    where: list[tuple[str, str]] = []  # each segment's path and its angle's path
    angles: list[_Value | None] = []
    kinds_ok = True
    for s in readers:
        kind = s.string("kind", choices=_SEGMENT_KINDS, required=True)
        kinds_ok = kinds_ok and kind is not None
        angle = s.value("angle", "angle")
        if kind == "dwell" and angle is not None and angle.si == 0:
            # a 0° dwell is no dwell: the rise runs straight into the return (or the next rise)
            _not_for(s, ["law"], "a dwell has no motion law: leave law out")
            s.finish()
            continue
        if angle is not None and angle.si <= 0:
            s.problem(angle.path, "must be > 0")
            angle = None
        angles.append(angle)
        law: str | None = None
        table: tuple[tuple[float, float], ...] = ()
        if kind in ("rise", "return"):
            law = s.string("law", choices=LAWS, required=True)
        elif kind == "dwell":
            _not_for(s, ["law"], "a dwell has no motion law: leave law out")
        else:
            s.ignore("law")
        if law == "table":
            table_value = s.raw(
                "table", required=True, hint="table = [[0, 0], [0.5, 0.3], [1, 1]] (fractions)"
            )
            parsed = _read_table(s, table_value) if table_value is not _MISSING else None
            if parsed is None:
                law = None  # reported: do not let validate() repeat it
            else:
                table = parsed
        elif law is not None or kind == "dwell":
            _not_for(s, ["table"], 'only with law = "table"')
        else:
            s.ignore("table")
        s.finish()
        segments.append(
            Segment(
                kind or "dwell",  # type: ignore[arg-type]
                angle.si if angle is not None else 1.0,
                (law or "uniform") if kind in ("rise", "return") else None,  # type: ignore[arg-type]
                table,
            )
        )
        where.append((s.path, angle.path if angle is not None else s.at("angle")))

    # The motion program's own rules (alternation, laws, tables), on the scene's paths.
    # Angles and the stroke are judged here, in the scene's units; a placeholder stands in
    # for whatever was already reported.
    program = MotionProgram(stroke.si if stroke is not None else 1.0, tuple(segments))
    if intact:
        for path, reason in validate(program):
            if path == "program.stroke" or path.endswith(".angle"):
                continue
            if reason.startswith("the angles add up"):
                continue
            if not kinds_ok and (path.endswith(".kind") or path == "program.segments"):
                continue
            cam.problem(_motion_path(path, where, stroke_path), reason)

    if intact and all(a is not None for a in angles):
        total = sum(a.si for a in angles)  # type: ignore[union-attr]
        if abs(total - 2.0 * math.pi) > 1e-9:
            in_rad = any(a.unit == "rad" for a in angles)  # type: ignore[union-attr]
            rad = f" ({total:.9g} rad, not 2π = {2.0 * math.pi:.9g})" if in_rad else ""
            cam.problem(
                cam.at("segment"),
                f"the segment angles add up to {_label(float(f'{math.degrees(total):.9g}'))}°, "
                f"not 360°{rad}: together they are one turn of the cam",
            )
    ok = len(cam.problems) == before and stroke is not None
    return (program if ok else None), not ok


def _read_table(s: _Reader, value: Any) -> tuple[tuple[float, float], ...] | None:
    """A ``table`` law's points [[x, y], …], fractions of the segment's angle and the stroke."""
    path = s.at("table")
    if not isinstance(value, list):
        s.problem(path, f"must be a list of [x, y] points, not {_type_name(value)}")
        return None
    if len(value) > MAX_TABLE_POINTS:
        s.problem(path, f"too many points ({len(value)} > {MAX_TABLE_POINTS})")
        return None
    points = [s.numbers(v, f"{path}[{j}]", 2, shape="[x, y]") for j, v in enumerate(value)]
    if any(pt is None for pt in points):
        return None
    return tuple((pt[0], pt[1]) for pt in points)  # type: ignore[index]


#: An angle of more turns than this is refused where it is read (a guide at −1e300° ran a stiff
#: equation of motion for minutes).
MAX_ANGLE_TURNS = 1000


#: A base radius below this fraction of the cam's size is lost in round-off (r0 + s == s).
CAM_R0_MIN_REL = 1e-12


def _lost_in_round_off(r0: _Value, f: Follower, stroke: float) -> list[tuple[str, str]]:
    """A base circle or a rocker position that double precision cannot tell from the degenerate
    one: the profile's normal, curvature and envelope then come out as 0/0."""
    size = stroke if isinstance(f, TranslatingFollower) else f.pivot_distance
    if r0.si < CAM_R0_MIN_REL * size:
        what = f"the stroke h = {r0.text(stroke)}" if isinstance(f, TranslatingFollower) else \
            f"pivot_distance a = {r0.text(size)}"
        return [(r0.path, f"r0 = {r0.text()} is lost in round-off beside {what}: the profile cannot be "
                          f"drawn (r0 ≥ {CAM_R0_MIN_REL:g} × that)")]
    if isinstance(f, TranslatingFollower) and stroke < CAM_R0_MIN_REL * r0.si:  # the other way round
        return [(r0.path, f"r0 = {r0.text()} leaves the stroke h = {r0.text(stroke)} in round-off: the profile "
                          f"is a circle to double precision (r0 ≤ h / {CAM_R0_MIN_REL:g})")]
    if isinstance(f, OscillatingFollower) and f.contact != "flat":
        a, l = f.pivot_distance, f.arm
        if not -1.0 < (a * a + l * l - r0.si * r0.si) / (2.0 * a * l) < 1.0:  # cos of ψ0, as the inversion finds it
            return [(r0.path, f"r0 = {r0.text()} meets the arm's reach |a − l| or a + l within round-off: "
                              "the rocker's start angle ψ0 cannot be found")]
    return []


def _read_cam(top: _Reader) -> CamScene | None:
    """[cam]: the disc cam, its follower and motion program, and how to divide the inversion."""
    r = top.table_at("cam", required=True)
    if r is None:
        return None
    before = len(r.problems)
    r0 = r.value("base_radius", "length", positive=True)
    # a crank's word for it: say so (below) instead of "rotation: missing"
    rotation = r.string("rotation", choices=("ccw", "cw"), required="direction" not in r.table)
    omega = r.value("omega", "omega", positive=True)
    step = r.value("step", "angle", required=False, positive=True)
    if step is not None and not CAM_STEP_MIN <= step.si <= CAM_STEP_MAX:
        r.problem(
            step.path,
            f"must lie between 0.1° and 90°, not {step.text()}: "
            + ("too coarse to draw a profile" if step.si > CAM_STEP_MAX else "too many divisions"),
        )
    alpha = r.value("alpha_permissible", "angle", required=False, positive=True)
    if alpha is not None and not alpha.si < math.pi / 2:
        r.problem(alpha.path, f"must be below 90°, not {alpha.text()}")
    circles = r.flag("roller_circles")
    if "direction" in r.table and "direction" not in r.used:  # the crank's word for it
        r.used.add("direction")
        r.problem(r.at("direction"), 'a cam\'s sense is written rotation = "ccw" or "cw"')
    follower, kind, contact, follower_bad = _read_follower(r, r0)
    if circles is not None and contact is not None and contact != "roller":
        r.problem(r.at("roller_circles"), f'only for contact = "roller" (this follower is {contact})')
    program, program_bad = _read_program(r, kind)
    if r0 is not None and follower is not None and program is not None:
        for path, why in _lost_in_round_off(r0, follower, program.stroke):
            r.problem(path, why)
    r.finish()
    if len(r.problems) != before or follower_bad or program_bad:
        return None
    if r0 is None or rotation is None or omega is None or follower is None or program is None:
        return None  # pragma: no cover - each of these was reported
    disc = DiscCam(
        base_radius=r0.si,
        follower=follower,
        program=program,
        rotation=1 if rotation == "ccw" else -1,
        omega=omega.si,
        alpha_permissible=None if alpha is None else alpha.si,
    )
    return CamScene(
        cam=disc,
        step=CAM_STEP_DEFAULT if step is None else step.si,
        roller_circles=contact == "roller" and circles is not False,
    )


# --------------------------------------------------------------------------------------------
# Cross-checks: names defined once and before use, links new and existing.
# --------------------------------------------------------------------------------------------


def _read_linkage(
    top: _Reader, crank_only: str = ""
) -> tuple[Linkage | None, Positions | None, _Part]:
    """[frame], [driver], [[dyad]] and [[point]], cross-checked.

    Returns the linkage (None when anything in those tables was wrong), the driver's
    positions and the driver as read. ``crank_only``: see :func:`_read_driver`.
    """
    data = top.table
    before = len(top.problems)
    frame, link_value = _read_frame(top)
    frame_link_given = (
        "frame" in data and isinstance(data["frame"], dict) and "link" in data["frame"]
    )
    driver, positions = _read_driver(top, frame, crank_only)
    dyads = [_read_dyad(r, k, frame) for k, r in enumerate(top.tables_at("dyad"))]
    points = [_read_point(r, k) for k, r in enumerate(top.tables_at("point"))]
    frame_link = _check_structure(
        top.problems, frame, (link_value, frame_link_given), driver, dyads, points
    )
    if len(top.problems) != before or any(p.model is None for p in (driver, *dyads, *points)):
        return None, positions, driver
    linkage = Linkage(
        frame_points={name: xy for name, xy in frame.items() if xy is not None},
        driver=driver.model,
        dyads=tuple(d.model for d in dyads),
        points=tuple(p.model for p in points),
        frame_link=frame_link or "0",
    )
    return linkage, positions, driver


def _check_structure(
    problems: list[tuple[str, str]],
    frame: _Frame,
    frame_link: tuple[str | None, bool],
    driver: _Part,
    dyads: list[_Part],
    points: list[_Part],
) -> str | None:
    """Check names and links across the scene; return the frame link (None if unknown)."""
    origin: dict[str, str] = {n: "frame" for n in frame}  # name → who defines it
    stage: dict[str, int] = {n: 0 for n in frame}  # name → first dyad index that may use it
    owner: dict[str, str] = {}  # link → who introduced it
    carried: dict[str, list[str]] = {}
    translating: set[str] = set()

    def define(part: _Part, level: int) -> None:
        for name, path in part.defines:
            if part.opaque and name in origin:
                continue
            if name in origin:
                who = "a frame point" if origin[name] == "frame" else f"by {origin[name]}"
                problems.append((path, f"{name} is already defined ({who})"))
            else:
                origin[name], stage[name] = part.where, level

    def carry(part: _Part) -> None:
        for link, names in part.carries:
            lst = carried.setdefault(link, [])
            lst.extend(n for n in names if n not in lst)
        translating.update(part.translating)

    # Driver and dyads: new links, new points, in assembly order.
    for level, part in enumerate([driver, *dyads]):
        for link, path in part.links:
            if link in owner and owner[link] != part.where and not part.opaque:
                problems.append(
                    (
                        path,
                        f"link {link} is already used by {owner[link]}; "
                        "each dyad adds two new links",
                    )
                )
            owner.setdefault(link, part.where)
        define(part, level)
        carry(part)

    # Points, in file order: on an existing moving link, placed from that link's points.
    for part in points:
        (on, on_path), bases = part.on or (None, ""), part.needs
        level = 0
        for base, path in bases:
            if on is None or on not in carried:
                continue
            if base not in origin:
                later = next(
                    (
                        p.where
                        for p in points
                        if p is not part and any(n == base for n, _ in p.defines)
                    ),
                    None,
                )
                tip = f" ({later} defines it: list that point first)" if later else ""
                problems.append((path, f"{base} is not defined before {part.where}{tip}"))
            elif base not in carried[on]:
                problems.append(
                    (
                        path,
                        f"{base} is not a point of link {on} (it carries {', '.join(carried[on])})",
                    )
                )
            else:
                level = max(level, stage[base])
        if on is not None and on not in carried:
            if on == frame_link[0]:
                problems.append((on_path, "a point on the frame belongs in [frame]"))
            else:
                problems.append(
                    (
                        on_path,
                        f"link {on} does not exist (links: {', '.join(carried) or 'none'})",
                    )
                )
        elif on is not None and len(bases) == 1 and on not in translating:
            problems.append(
                (
                    on_path,
                    f"link {on} turns: an offset from one base point needs a translating "
                    "link (a slider); give base = [U, V] with along/left",
                )
            )
        define(part, level)
        if on is not None and on in carried:
            carry(_Part(part.where, carries=[(on, [n for n, _ in part.defines])]))

    # Dyads' outer joints: defined by the frame, the driver or an earlier dyad (or a point
    # placed from those).
    for k, part in enumerate(dyads):
        for name, path in part.needs:
            if name in stage and stage[name] <= k:
                continue
            if name in origin:
                tip = f" ({origin[name]} defines it: put that first)"
            else:
                tip = ""
            problems.append((path, f"{name} is not defined before {part.where}{tip}"))

    # The frame link.
    fixed, explicit = frame_link
    if explicit:
        if fixed is not None and fixed in owner:
            problems.append(("frame.link", f"link {fixed} is a moving link ({owner[fixed]})"))
        return fixed
    numeric = [int(x) for x in owner if x.isdigit()]
    return str(max(numeric) + 1) if numeric else "0"


def _raise_sorted(problems: list[tuple[str, str]], data: Mapping[str, Any], order: Mapping[str, int],
                  section: str, source: str) -> NoReturn:
    """Raise the problems of a scene whose own table is ``section`` ([cam], [flywheel] …), in the
    order of the file: top-level keys first by ``order``, then the section's keys as written."""
    table = data.get(section)
    sub_order = {k: n for n, k in enumerate(table)} if isinstance(table, dict) else {}
    problems.sort(key=lambda p: _rank(p, order, sub_order, section))
    raise SceneError(problems or [(section, "invalid")], source)


def _rank(
    problem: tuple[str, str],
    order: Mapping[str, int],
    sub_order: Mapping[str, int] | None = None,
    table: str = "cam",
) -> tuple[int, int, int, int, int]:
    """Sort key putting problems in file order: top-level table, then array index; within
    ``table`` ([cam], [flywheel]), its own keys and tables in file order too (``sub_order``).

    Within one table an unknown key comes first: a misspelt key is usually why another
    one is "missing".
    """
    path, reason = problem
    m = re.match(r"([^.\[]+)(?:\[(\d+)\])?", path)
    typo = 0 if reason.startswith("unknown key") else 1
    if not m:
        return (-1, 0, 0, 0, typo)
    sub = sub_index = 0
    if sub_order is not None and m.group(1) == table:
        n = re.match(re.escape(table) + r"\.([^.\[]+)(?:\[(\d+)\])?", path)
        if n:  # a whole array ("cam.segment": the angles' sum) after its items
            whole = n.group(0) == path and n.group(2) is None
            sub = sub_order.get(n.group(1), len(sub_order))
            sub_index = 1 << 30 if whole else int(n.group(2) or 0)
    return (order.get(m.group(1), len(order)), int(m.group(2) or 0), sub, sub_index, typo)


# --------------------------------------------------------------------------------------------
# Public API
# --------------------------------------------------------------------------------------------


def parse_scene(data: dict[str, Any], source: str = "scene") -> Scene:
    """Validate parsed TOML data and build the :class:`Scene`, in SI units.

    Parameters
    ----------
    data : dict
        The TOML document as ``tomllib`` returns it.
    source : str
        The name used in messages.

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        With every problem found (``.problems``); the message is the first, in file order.

    Examples
    --------
    >>> scene = parse_scene({
    ...     "title": "A crank alone",
    ...     "units": {"length": "mm", "angle": "deg"},
    ...     "frame": {"A": [0, 0]},
    ...     "driver": {"type": "crank", "link": "1", "pivot": "A", "tip": "B",
    ...                "length": 50, "angle": [0, 90], "omega_rpm": 60},
    ... }, "crank.toml")
    >>> scene.linkage.driver.length, scene.positions.labels, scene.linkage.frame_link
    (0.05, ('0', '90'), '2')
    >>> round(scene.linkage.driver.omega, 6)
    6.283185
    >>> from graphmech.errors import SceneError
    >>> try:
    ...     parse_scene({
    ...         "frame": {"A_mm": [0, 0]},
    ...         "driver": {"type": "crank", "link": 1, "pivot": "A", "tip": "B",
    ...                    "lenght_mm": 50, "angle_deg": 30, "omega_rad_s": 10},
    ...     }, "bad.toml")
    ... except SceneError as err:
    ...     print(err)
    ...     print(err.problems[1])
    bad.toml: driver.lenght_mm: unknown key; did you mean length_mm? (and 1 more)
    ('driver.length', 'missing: write length_mm (or length with [units] length)')

    A cam scene has a [cam] table instead of [driver]:

    >>> cam = parse_scene({
    ...     "units": {"length": "mm", "angle": "deg"},
    ...     "cam": {"base_radius": 30, "rotation": "ccw", "omega_rad_s": 10,
    ...             "follower": {"type": "translating", "contact": "knife", "offset": 35},
    ...             "program": {"stroke": 16},
    ...             "segment": [{"kind": "rise", "angle": 180, "law": "sine"},
    ...                         {"kind": "return", "angle": 170, "law": "sine"}]},
    ... }, "cam.toml")
    Traceback (most recent call last):
    ...
    graphmech.errors.SceneError: cam.toml: cam.follower.offset: |e| = 35 mm is not smaller than the base radius r0 = 30 mm: the follower's axis misses the base circle (and 1 more)
    """
    problems: list[tuple[str, str]] = []
    if not isinstance(data, dict):
        raise SceneError([("", "a scene must be a TOML table")], source)
    order = {k: n for n, k in enumerate(data)}
    top = _Reader(data, "", problems, {})
    units = _read_units(top)
    top.units = units
    has_cam, has_driver = "cam" in data, "driver" in data
    if "structure" in data:  # mobility and structure: graphmech.problems.structure.scene
        from graphmech.problems.structure.scene import parse_structure_scene

        return parse_structure_scene(data, source, top, order)
    if has_cam and "flywheel" in data:  # one problem, as below
        top.problem(
            "flywheel",
            "a scene is a disc cam ([cam]) or a flywheel problem ([flywheel]), not both: "
            "put each in a scene of its own",
        )
        raise SceneError(problems, source)
    if has_cam and has_driver:  # one problem: which of the two to read is anyone's guess
        top.problem(
            "cam",
            "a scene is a linkage ([driver]) or a disc cam ([cam]), not both: "
            "put the cam in a scene of its own",
        )
        raise SceneError(problems, source)
    if "forces" in data and (has_cam or "flywheel" in data or "efficiency" in data or "balancing" in data):
        other = "cam" if has_cam else "flywheel" if "flywheel" in data else "efficiency or balancing"
        top.problem("forces", "[forces] belongs to a linkage scene (kinetostatics), not to a "
                              f"{other} scene: put it in a scene of its own")
        raise SceneError(problems, source)
    if "forces" in data:
        from graphmech.problems.forces.scene import parse_forces_scene

        return parse_forces_scene(data, source, top, order)
    if "efficiency" in data or "balancing" in data:  # a problem of forces alone: no mechanism
        from graphmech.problems.efficiency.scene import parse_efficiency_scene

        return parse_efficiency_scene(data, source, top, order)
    if has_cam:
        return _parse_cam_scene(data, source, top, order)
    if "flywheel" in data:
        from graphmech.problems.flywheel.scene import parse_flywheel_scene

        return parse_flywheel_scene(data, source, top, order)
    elif not any(k in data for k in _LINKAGE_KEYS):
        top.problem(
            "",
            "nothing to draw: add a [driver] table (a linkage scene) or a [cam] table "
            "(a disc cam scene)",
        )
        _read_header(top)
        _read_scales(top)
        _read_measured(top, None)
        _read_tail(top)
        problems.sort(key=lambda p: _rank(p, order))
        raise SceneError(problems, source)
    from graphmech.problems.cycle.scene import CYCLE_SHOW_CHOICES, read_cycle

    default = ("cycle",) if "cycle" in data else ("characteristics",) if "characteristics" in data else SHOW_CHOICES
    title, show, find = _read_header(top, SHOW_CHOICES + CYCLE_SHOW_CHOICES, default)
    scales = _read_scales(top)
    linkage, positions, _ = _read_linkage(top)
    cycle = None
    if "cycle" in data or "characteristics" in data or any(s in CYCLE_SHOW_CHOICES for s in show):
        cycle, positions = read_cycle(top, data, show, linkage, positions)
    measured = _read_measured(top, positions.labels if positions else None)
    precision, page = _read_tail(top, _TOP_KEYS + ("cycle", "characteristics"))
    if problems or linkage is None:
        problems.sort(key=lambda p: _rank(p, order))
        raise SceneError(problems or [("driver", "invalid")], source)
    return Scene(
        source=source,
        title=title,
        show=show,
        find=find,
        scales=scales,
        linkage=linkage,
        positions=positions,  # type: ignore[arg-type]
        measured=measured,
        precision_mm=precision,
        page=page,
        cycle=cycle,
    )


def _parse_cam_scene(
    data: dict[str, Any], source: str, top: _Reader, order: Mapping[str, int]
) -> Scene:
    """The rest of :func:`parse_scene` for a scene with a [cam] table."""
    problems = top.problems
    title, show, find = _read_header(top, CAM_SHOW_CHOICES, CAM_SHOW_DEFAULT)
    scales = _read_scales(top, cam=True, follower=_peek_follower(data))
    why = phi_axis_problem(scales["phi"]) if "phi" in scales else None  # the diagrams' φ axis, as a cycle's
    if why:
        tab = data.get("scales")
        top.problem("scales." + next((k for k in tab if k.startswith("phi")), "phi"), why)
    for key in _LINKAGE_KEYS:
        if key in data:
            top.used.add(key)
            what = f"[[{key}]]" if key in ("dyad", "point") else f"[{key}]"
            top.problem(key, f"{what} belongs to a linkage scene; this is a cam scene ([cam])")
    cam = _read_cam(top)
    measured = _read_measured(top, None, cam=True)
    precision, page = _read_tail(top)
    if problems or cam is None:
        _raise_sorted(problems, data, order, "cam", source)
    return Scene(
        source=source,
        title=title,
        show=show,
        find=find,
        scales=scales,
        measured=measured,
        precision_mm=precision,
        page=page,
        cam=cam,
    )


def load_scene(path: str | os.PathLike[str]) -> Scene:
    """Read a scene file and validate it.

    Parameters
    ----------
    path : str or path-like
        A UTF-8 TOML file of at most :data:`MAX_BYTES` bytes.

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        For an unreadable, oversized, non-UTF-8 or malformed file, and for every problem
        :func:`parse_scene` finds; messages start with the file name.
    """
    source = Path(path).name
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_BYTES + 1)
    except OSError as exc:
        raise SceneError([("", f"cannot read the file ({exc.strerror or exc})")], source) from None
    if len(raw) > MAX_BYTES:
        raise SceneError(
            [("", "file is larger than 1 MiB; a scene is a few kilobytes, refusing to read it")],
            source,
        )
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise SceneError(
            [
                (
                    f"line {line}",
                    f"not UTF-8 text (byte 0x{raw[exc.start]:02x}); save the file as UTF-8",
                )
            ],
            source,
        ) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        message = str(exc)
        m = re.search(r"\(at line (\d+), column (\d+)\)", message)
        what = re.sub(r"\s*\(at [^)]*\)\s*$", "", message)
        what = what[:1].lower() + what[1:]
        if m:
            raise SceneError(
                [(f"line {m.group(1)}", f"invalid TOML: {what} (column {m.group(2)})")], source
            ) from None
        line = text.count("\n") + 1
        raise SceneError(
            [(f"line {line}", f"invalid TOML: {what} (at the end of the file)")], source
        ) from None
    except RecursionError:
        raise SceneError([("", "invalid TOML: nested too deeply")], source) from None
    return parse_scene(data, source)
