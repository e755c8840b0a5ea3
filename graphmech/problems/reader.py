"""Reading a scene file, whatever its kind: the toolkit every kind's reader uses.

A :class:`Reader` is a view of one TOML table that tracks its key path and collects problems;
its typed methods (``value``, ``quantity``, ``string``, ``point_name`` …) convert to SI and say
what is wrong in the user's words. The common tables — ``title``/``show``/``find``, ``[units]``,
``[scales]``, ``[measured]``, ``[check]``, ``[page]`` — are read here once for every kind, and
:class:`Scene` is what every reader returns. A kind's own tables are read in
``graphmech/problems/<kind>/scene.py``.
"""
from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass, field
from decimal import Decimal
from typing import Any, Generic, Iterable, Mapping, NoReturn, Self, TypeGuard, TypeVar, cast, overload

from graphmech.errors import OutOfDomain, SceneError
from graphmech.drawing.primitives import TitleBlock
from graphmech.scales import FIT, FIT_WORKING_AREA, PAPER, scale_out_of_range
from graphmech.mechanisms.linkage import Linkage, Positions
from graphmech.tolerances import DRAWING_PRECISION_MM, MAX_PRECISION_MM, POLE_RANGE_MM

#: The most driver positions one scene may ask for.
MAX_POSITIONS = 3600
#: The notations a drawing can be lettered in (see graphmech.drawing.notation).
NOTATIONS = ("en", "zh", "ru")

#: The longest title, in characters.
MAX_TITLE = 200
#: Named paper sizes, (width, height) in mm: one table for the whole package.
PAPER_SIZES = PAPER


#: The strings of a ``[page.title_block]``, in the order the block is read.
TITLE_BLOCK_KEYS = ("title", "name", "group", "date", "sheet")
#: The longest value of a title block's cell other than its title, in characters.
MAX_TITLE_BLOCK_CELL = 60


@dataclass(frozen=True)
class Page:
    """The drawing sheet.

    Parameters
    ----------
    size : (float, float)
        Width and height, mm; A4 landscape by default (see :data:`PAPER_SIZES`). For a fit
        page, the working area its scales are chosen for and the kinds judge "does the sheet
        fit" on (:data:`graphmech.scales.FIT_WORKING_AREA`): :func:`page_size` is always this.
    notation : str
        Whose symbols and captions the drawing uses: ``"en"`` (default), ``"zh"`` (孙桓's
        symbols, Chinese captions) or ``"ru"`` (the Russian course-project page's). Drawn text
        only: the names in ``find`` and ``check`` never change.
    fit : bool
        ``size = "fit"``: the drawn page is cropped to the content with the page margin.
    title_block : TitleBlock or None
        ``[page.title_block]``: a course-project sheet's title block, drawn at the lower right.
    """

    size: tuple[float, float] = (297.0, 210.0)
    notation: str = "en"
    fit: bool = False
    title_block: TitleBlock | None = None


#: The choices of a string key, such as Literal["left", "right"]: what Reader.string returns.
S = TypeVar("S", bound=str)
#: The part of a scene its kind reads from its own tables (a CamScene, a FlywheelScene …).
P = TypeVar("P", covariant=True)  # a Scene[CamScene] is a Scene[object]: the scene is frozen


@dataclass(frozen=True)
class Scene(Generic[P]):
    """A validated scene, all in SI units: what every kind shares, and its own ``problem``.

    Parameters
    ----------
    source : str
        The file name used in messages.
    title : str
        Free text (the renderer escapes it).
    show : tuple of str
        What to draw, from the kind's choices, in the user's order, no duplicates.
    find : tuple of str
        Quantity names as written (``"v_C"``, ``"omega_3"``, ``"alpha_max"``, ``"J_F"``);
        ``check`` validates them against the construction.
    scales : dict
        Only the scales given, SI per drawing mm: ``"l"`` m/mm, ``"v"`` (m/s)/mm, ``"a"``
        (m/s²)/mm; a cam scene also ``"s"`` and ``"phi"``, a flywheel scene ``"phi"``, ``"M"``,
        ``"J"``, ``"T"`` (docs/scene-format.md lists them all).
    linkage : Linkage or None
        The mechanism, in m and rad (None in a scene without one: a cam, a machine given by
        its reduced moments, an efficiency or balancing problem).
    positions : Positions or None
        Driver values in SI (rad or m) and their labels as written in the scene's unit
        (``"50"``), used as name suffixes such as ``v_C@50``. In a flywheel scene with a
        linkage, the crank's absolute angles at its N positions, labelled ``"1"`` … ``"N"``.
    measured : tuple of (str, float)
        The ``[measured]`` table in file order, raw: quantity values in SI or drawn
        segment lengths in mm (``("p'c'", 40.5)``); ``check`` interprets them.
    precision_mm : float
        Drawing precision for judging measured values, mm.
    page : Page
        The sheet.
    kind : str
        The kind of problem the scene poses, a name in :data:`graphmech.problems.KINDS`.
    problem : P
        What the kind read from its own tables: a ``CamScene`` for a cam, a ``FlywheelScene``,
        ``ForceScene``, ``CycleScene``, ``EfficiencyProblem``, ``BalancingProblem``,
        ``StructureScene`` (each in ``graphmech/problems/<kind>/scene.py``); None for a plain
        linkage, which has all it needs in ``linkage`` and ``positions``.
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
    kind: str = "linkage"
    problem: P = cast(P, None)  # None for a plain linkage, a Scene[None]


def linkage_of(scene: Scene[object]) -> Linkage:
    """The linkage of a scene whose reader requires one (a linkage, cycle or forces scene):
    a statement of that guarantee for the type checker, not a check."""
    return cast(Linkage, scene.linkage)


def positions_of(scene: Scene[object]) -> Positions:
    """The positions of a scene whose reader requires a linkage (they come with it)."""
    return cast(Positions, scene.positions)


# --------------------------------------------------------------------------------------------
# Units: each kind of quantity, the units a [units] table may name, and the key suffixes.
# A conversion is (numerator, denominator): SI value = written value · num / den, so that
# 60 mm becomes exactly 0.06 m.
# --------------------------------------------------------------------------------------------

UNITS: dict[str, dict[str, tuple[float, float]]] = {
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
    "velocity": {"m/s": (1.0, 1.0), "mm/s": (1.0, 1000.0), "m/min": (1.0, 60.0), "mm/min": (1.0, 60000.0)},
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
SUFFIXES: dict[str, dict[str, str]] = {
    "length": {"mm": "mm", "cm": "cm", "m": "m"},
    "angle": {"deg": "deg", "rad": "rad"},
    "omega": {"rad_s": "rad/s", "rpm": "rpm", "deg_s": "deg/s"},
    "epsilon": {"rad_s2": "rad/s2", "deg_s2": "deg/s2"},
    "velocity": {"m_s": "m/s", "mm_s": "mm/s", "m_min": "m/min", "mm_min": "mm/min"},
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

KIND_WORDS = {
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

PER_MM = "_per_mm"
ALL_SUFFIXES = {s for table in SUFFIXES.values() for s in table} | {
    s + PER_MM for table in SUFFIXES.values() for s in table
}

# Names. fullmatch() everywhere: "$" would let a trailing newline through.
POINT_NAME = re.compile(r"[A-Z]+[0-9]*['′]*")
LINK_ID = re.compile(r"[0-9A-Za-z]{1,8}")
LABEL_SUFFIX = r"(?:@[0-9A-Za-z.+\-]{1,24})?"
QUANTITY_NAME = re.compile(r"[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)*" + LABEL_SUFFIX)
SEGMENT_NAME = re.compile(r"(?:[a-zπ][0-9]*['′]*){2,8}" + LABEL_SUFFIX)
#: The tables and keys every scene may have, whatever its kind (each kind adds its own tables,
#: graphmech.problems.tables()).
COMMON_KEYS = ("title", "show", "find", "scales", "units", "measured", "check", "page")
#: The tables of a linkage: a linkage scene's own, and read by the kinds built on a linkage
#: (forces, a flywheel's machine).
LINKAGE_KEYS = ("frame", "driver", "dyad", "point", "triad")

MISSING: Any = object()


def say(value: Any, limit: int = 40) -> str:
    """A user-written string made safe for a one-line message (quoted, escaped, cut short)."""
    text = str(value)
    if len(text) > limit:
        text = text[: limit - 1] + "…"
    return repr(text)


def key_text(key: str) -> str:
    """A key as it appears in a key path: plain when harmless, else quoted and escaped."""
    return key if re.fullmatch(r"[A-Za-z0-9_'′@.+\-π]{1,60}", key) else say(key, 60)


def type_name(value: Any) -> str:
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


def is_choice(value: object, choices: tuple[S, ...]) -> TypeGuard[S]:
    """Whether ``value`` is one of the string ``choices``: narrows it to their Literal."""
    return isinstance(value, str) and value in choices


def compact(value: float) -> str:
    """Compact text of a number as the user wrote it: 50.0 → "50", 12.5 → "12.5"."""
    text = f"{value:.12g}"
    return "0" if text == "-0" else text


def one_of(words: Iterable[str]) -> str:
    words = [str(w) for w in words]
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " or " + words[-1]


def did_you_mean(word: str, candidates: Iterable[str]) -> str:
    """``"; did you mean X?"`` for the nearest candidate, or ``""``."""
    pool = sorted(set(candidates))
    same_letters = [c for c in pool if c.casefold() == word.casefold()]
    close = same_letters or difflib.get_close_matches(word, pool, n=3, cutoff=0.6)
    swapped = [c for c in close if sorted(c) == sorted(word)]  # "stpe" is "step", not "stop"
    close = swapped or close
    return f"; did you mean {close[0]}?" if close else ""


def maybe(word: str, candidates: Iterable[str]) -> str:
    """``" (did you mean X?)"`` for the nearest candidate, or ``""``."""
    tip = did_you_mean(word, candidates)
    return f" ({tip[2:]})" if tip else ""


# --------------------------------------------------------------------------------------------
# The reader: one TOML table, its key path, the keys it has read; problems go to one list.
# --------------------------------------------------------------------------------------------


@dataclass
class Given:
    """A quantity as found in a table: the key as written, the raw value, its conversion."""

    key: str
    value: Any
    num: float
    den: float

    def si(self, x: float) -> float:
        return x * self.num / self.den


@dataclass
class Value:
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
        label = compact(float(f"{x:.6g}"))
        return f"{label}°" if self.unit == "deg" else f"{label} {self.unit}"


class Reader:
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
        key = key_text(key)
        return f"{self.path}.{key}" if self.path else key

    def problem(self, path: str, reason: str) -> None:
        self.problems.append((path, reason))

    def sub(self, table: Mapping[str, Any], path: str) -> Reader:
        return Reader(table, path, self.problems, self.units)

    # -- raw access ----------------------------------------------------------------------------
    def raw(self, key: str, *, required: bool = False, hint: str = "") -> object:
        """The value under ``key`` (marked used), or ``MISSING``."""
        self.known.add(key)
        if key not in self.table:
            if required:
                self.problem(self.at(key), "missing" + (f": {hint}" if hint else ""))
            return MISSING
        self.used.add(key)
        return self.table[key]

    def finish(self, hint: str = "") -> None:
        """Report every key that was not read, suggesting the nearest known key."""
        for key in self.table:
            if key not in self.used:
                tip = did_you_mean(key, self.known) or (f"; {hint}" if hint else "")
                self.problem(self.at(key), "unknown key" + tip)

    # -- typed values ------------------------------------------------------------------------
    def number(self, value: Any, path: str, *, positive: bool = False) -> float | None:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.problem(path, f"must be a number, not {type_name(value)}")
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
            got = f"a list of {len(value)}" if isinstance(value, list) else type_name(value)
            self.problem(path, f"must be {shape}, not {got}")
            return None
        out = [self.number(v, f"{path}[{i}]", positive=positive) for i, v in enumerate(value)]
        valid = [x for x in out if x is not None]
        return valid if len(valid) == len(out) else None

    @overload
    def string(
        self, key: str, *, choices: Iterable[S], required: bool = False, default: S | None = None
    ) -> S | None: ...

    @overload
    def string(
        self, key: str, *, choices: None = None, required: bool = False, default: str | None = None
    ) -> str | None: ...

    def string(
        self,
        key: str,
        *,
        choices: Iterable[str] | None = None,
        required: bool = False,
        default: str | None = None,
    ) -> str | None:
        """A string under ``key``; with ``choices``, one of them (typed as the choices are: a
        tuple of Literal names gives that Literal)."""
        options = tuple(choices) if choices is not None else None
        hint = f"write {key} = {one_of(repr(c) for c in options)}" if options else ""
        value = self.raw(key, required=required, hint=hint.replace("'", '"'))
        if value is MISSING:
            return default
        if not isinstance(value, str):
            self.problem(self.at(key), f"must be a string, not {type_name(value)}")
            return None
        if options is not None and value not in options:
            self.problem(
                self.at(key),
                f"unknown value {say(value)}: use {one_of(options)}" + maybe(value, options),
            )
            return None
        return value

    def flag(self, key: str) -> bool | None:
        """A true/false key: its value, or None when it is missing or not a boolean (said)."""
        value = self.raw(key)
        if value is MISSING:
            return None
        if not isinstance(value, bool):
            self.problem(self.at(key), f"must be true or false, not {type_name(value)}")
            return None
        return value

    def point_name(self, value: Any, path: str) -> str | None:
        if not isinstance(value, str):
            self.problem(
                path, f'must be a point name (a string such as "B"), not {type_name(value)}'
            )
            return None
        if not POINT_NAME.fullmatch(value) or len(value) > 8:
            self.problem(
                path,
                f"{say(value)} is not a point name: capital letters, then digits or primes "
                "(B, C2, E')",
            )
            return None
        return value

    def link_id(self, value: Any, path: str) -> str | None:
        if isinstance(value, int) and not isinstance(value, bool) and 0 <= value < 10**8:
            return str(value)
        if isinstance(value, str) and LINK_ID.fullmatch(value):
            return value
        self.problem(
            path,
            'must be a link number such as "2", not '
            + (say(value) if isinstance(value, str) else type_name(value)),
        )
        return None

    def name_list(self, key: str, count: int, check: Any) -> list[tuple[str | None, str]]:
        """``count`` names under ``key``, each checked by ``check``; (name or None, path)."""
        value = self.raw(key, required=True, hint=f"a list of {count}")
        path = self.at(key)
        if value is MISSING:
            return [(None, f"{path}[{i}]") for i in range(count)]
        if not isinstance(value, list) or len(value) != count:
            got = f"a list of {len(value)}" if isinstance(value, list) else type_name(value)
            self.problem(path, f"must be a list of {count}, not {got}")
            return [(None, f"{path}[{i}]") for i in range(count)]
        return [(check(v, f"{path}[{i}]"), f"{path}[{i}]") for i, v in enumerate(value)]

    def table_at(self, key: str, *, required: bool = False, hint: str = "") -> Reader | None:
        value = self.raw(key, required=required, hint=hint)
        if value is MISSING:
            return None
        if not isinstance(value, dict):
            self.problem(self.at(key), f"must be a table, not {type_name(value)}")
            return None
        return self.sub(value, self.at(key))

    def tables_at(self, key: str) -> list[Reader]:
        """An array of tables (``[[key]]``), each with its path ``key[i]``."""
        value = self.raw(key)
        if value is MISSING:
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
                self.problem(f"{self.at(key)}[{i}]", f"must be a table, not {type_name(item)}")
        return out

    # -- quantities with units -----------------------------------------------------------------
    def quantity(
        self, base: str, kind: str, *, required: bool = True, per_mm: bool = False
    ) -> Given | None:
        """Find ``base`` written with a unit suffix (``base_mm``) or plain under ``[units]``.

        Returns None (after reporting, if there is something to report) when the quantity is
        absent, given twice, or its unit is wrong or not stated.
        """
        tail = PER_MM if per_mm else ""
        suffixes = {s + tail: u for s, u in SUFFIXES[kind].items()}
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
                elif rest in ALL_SUFFIXES:
                    self.used.add(key)
                    wrong_unit = True
                    fits = one_of(f"{base}_{s}" for s in suffixes)
                    self.problem(
                        self.at(key), f"{rest} is not a unit of {KIND_WORDS[kind]}; write {fits}"
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
        num, den = UNITS[kind][unit]
        return Given(key, self.table[key], num, den)

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
    ) -> Value | None:
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
            unit = SUFFIXES[kind][given.key[len(base) + 1 :]]
        return Value(given.si(x), unit, path, given.num, given.den)

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
        labels = [compact(x) for x in written]
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
            ends[key] = None if v is MISSING else r.number(v, r.at(key))
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
# The tables every scene may have, one function each.
# --------------------------------------------------------------------------------------------


def read_units(top: Reader) -> dict[str, str | None]:
    """[units]: kind → unit name (None when the entry is wrong: no cascade of 'not stated')."""
    r = top.table_at("units")
    units: dict[str, str | None] = {}
    if r is None:
        return units
    for kind, table in UNITS.items():
        value = r.raw(kind)
        if value is MISSING:
            continue
        if isinstance(value, str) and value in table:
            units[kind] = value
            continue
        units[kind] = None
        options = [u for u in table if "²" not in u and "^" not in u]
        if isinstance(value, str):
            r.problem(
                r.at(kind),
                f"unknown unit {say(value)}: use {one_of(options)}" + maybe(value, table),
            )
        else:
            r.problem(
                r.at(kind), f'must be a unit name such as "{options[0]}", not {type_name(value)}'
            )
    r.finish()
    return units


def read_header(
    top: Reader,
    choices: tuple[str, ...],
    default: tuple[str, ...],
) -> tuple[str, tuple[str, ...], tuple[str, ...]]:
    """title, show (from ``choices``, ``default`` when absent), find."""
    title = top.string("title", default="") or ""
    if len(title) > MAX_TITLE:
        top.problem("title", f"too long ({len(title)} characters; at most {MAX_TITLE})")

    show: list[str] = []
    value = top.raw("show")
    if value is MISSING:
        show = list(default)
    elif not isinstance(value, list) or not value:
        top.problem("show", f"must be a non-empty list from {one_of(choices)}")
    else:
        for i, item in enumerate(value):
            if not isinstance(item, str) or item not in choices:
                top.problem(
                    f"show[{i}]",
                    f"unknown value {say(item)}: use {one_of(choices)}"
                    + (did_you_mean(item, choices) if isinstance(item, str) else ""),
                )
            elif item in show:
                top.problem(f"show[{i}]", f"{item} is listed twice")
            else:
                show.append(item)

    find: list[str] = []
    value = top.raw("find")
    if value is not MISSING:
        if not isinstance(value, list):
            top.problem("find", f"must be a list of quantity names, not {type_name(value)}")
        else:
            for i, item in enumerate(value):
                if not isinstance(item, str) or not item.strip():
                    top.problem(f"find[{i}]", "must be a non-empty string (a quantity name)")
                elif item in find:
                    top.problem(f"find[{i}]", f"{say(item)} is listed twice")
                else:
                    find.append(item)
    return title, tuple(show), tuple(find)


#: A cam scene's scales: name → kind of quantity, for a translating and an oscillating follower.
CAM_SCALES = (
    ("l", "length", "length"),
    ("s", "length", "angle"),
    ("phi", "angle", "angle"),
    ("v", "velocity", "omega"),
    ("a", "acceleration", "epsilon"),
)


def read_scales(
    top: Reader,
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
        not_for(r, [name], reason)
    kinds: list[tuple[str, str | None]]
    if entries is not None:
        kinds = list(entries)
    elif cam:
        kinds = [
            (name, None if follower is None else (lin if follower == "translating" else ang))
            for name, lin, ang in CAM_SCALES
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


#: A number as a student writes it: a sign, digits with at most one decimal point, an exponent.
WRITTEN_NUMBER = re.compile(r"([+-]?)([0-9]*)(?:\.([0-9]*))?(?:[eE]([+-]?[0-9]{1,6}))?")


class Written(float):
    """A measured value as written (``"1.440"``, ``"+2.17"``, ``"1.44e3"``): the number, and what
    its writing says — ``figures`` significant figures (every digit from the first non-zero one,
    trailing zeros included; 0 for a written zero), ``half_unit`` (half a unit of the last written
    digit: the interval the value stands for) and ``signed`` (a sign was written); judged as a
    teacher does by :func:`graphmech.problems.judging.judge_written`.

    >>> w = Written("1.440")
    >>> float(w), w.figures, w.half_unit, w.signed
    (1.44, 4, 0.0005, False)
    >>> Written("1440").figures, Written("1.44e3").half_unit, Written("-2.17").signed
    (4, 5.0, True)
    """

    text: str
    figures: int
    half_unit: float
    signed: bool

    def __new__(cls, text: str) -> Self:
        written = text.strip()
        m = WRITTEN_NUMBER.fullmatch(written)
        if written.lstrip("+-").lower() in ("nan", "inf", "infinity"):
            raise OutOfDomain(f"must be a finite number, not {text!r}")
        if m is None or not (m[2] or m[3]):
            raise OutOfDomain(f"must be a finite number as written (1.44, +2.17, -0.0120, 1.44e3), not {text!r}")
        x = float.__new__(cls, written)
        place = int(m[4] or 0) - len(m[3] or "")
        half = float(Decimal(5).scaleb(place - 1))
        if not (math.isfinite(x) and math.isfinite(half)):
            raise OutOfDomain(f"must be a finite number in double precision's range, not {text!r}")
        x.text, x.half_unit, x.signed = written, half, bool(m[1])
        x.figures = len(((m[2] or "") + (m[3] or "")).lstrip("0"))
        return x

    def __reduce__(self) -> tuple[type[Written], tuple[str]]:  # a batch's worker gets the text again
        return Written, (self.text,)

    def __repr__(self) -> str:
        return f"Written({self.text!r})"


def read_measured(
    top: Reader, labels: tuple[str, ...] | None, cam: bool = False
) -> tuple[tuple[str, float], ...]:
    """[measured]: quantity values (SI) or drawn segments (mm), kept raw and in order; a string
    is a value as written (:class:`Written`, judged by its digits and sign).

    A cam scene has no driver positions, so its names take no ``@label``, only a reading's cam
    angle in degrees (``s@45``).
    """
    r = top.table_at("measured")
    if r is None:
        return ()
    out: list[tuple[str, float]] = []
    for key, value in r.table.items():
        r.used.add(key)
        path = r.at(key)
        if not (QUANTITY_NAME.fullmatch(key) or SEGMENT_NAME.fullmatch(key)):
            r.problem(
                path,
                "not a measured name: a quantity (v_C, omega_2, a_k_C2C3, v_C@50) "
                "or a drawn segment (pc, \"p'c'\", \"n'c'\")",
            )
            continue
        if isinstance(value, str):  # a value as written: its digits and sign are judged
            try:
                x: float | None = Written(value)
            except ValueError as e:
                r.problem(path, str(e))
                continue
        else:
            x = r.number(value, path)
        if x is None:
            continue
        if "@" in key and cam and not _cam_reading(key):  # s@45: a reading at a cam angle, in degrees
            r.problem(
                path,
                "a cam scene has no driver positions: write the name without "
                f"@{say(key.split('@', 1)[1])[1:-1]}",
            )
            continue
        if "@" in key and labels is not None:
            label = key.split("@", 1)[1]
            if label not in labels and label != "ic":  # omega_3@ic: by instant centres (graphmech.problems.instant_centres)
                r.problem(path, f"no position is labelled {label} (positions: {', '.join(labels)})")
                continue
        out.append((key, x))
    return tuple(out)


#: A cam scene's readings at a division (graphmech.problems.cam.check.AT_DIVISION): s@45, psi@45, alpha@45.
CAM_READINGS = ("s", "psi", "alpha")


def _cam_reading(key: str) -> bool:
    """A cam scene's reading at a division names its cam angle in degrees (s@45, psi@7.5)."""
    base, _, label = key.partition("@")
    try:
        return base in CAM_READINGS and math.isfinite(float(label))
    except ValueError:
        return False


def read_check(top: Reader) -> float:
    """[check]: precision_mm > 0."""
    r = top.table_at("check")
    if r is None:
        return DRAWING_PRECISION_MM
    value = r.raw("precision_mm")
    precision = DRAWING_PRECISION_MM
    if value is not MISSING:
        x = r.number(value, r.at("precision_mm"), positive=True)
        if x is not None and x > MAX_PRECISION_MM:
            r.problem(r.at("precision_mm"), f"at most {MAX_PRECISION_MM:g} mm, not {x:g}: coarser judges nothing")
            x = None
        precision = precision if x is None else x
    r.finish()
    return precision


def read_page(top: Reader) -> Page:
    """[page]: size = "A4" (or another name in PAPER_SIZES), "fit" or [w, h] in mm; notation;
    [page.title_block]."""
    r = top.table_at("page")
    if r is None:
        return Page()
    value = r.raw("size")
    size, fit = Page().size, False
    if value == FIT:
        size, fit = FIT_WORKING_AREA, True
    elif isinstance(value, str):
        if value in PAPER_SIZES:
            size = PAPER_SIZES[value]
        else:
            r.problem(
                r.at("size"),
                f"unknown paper {say(value)}: use {', '.join(PAPER_SIZES)}, {FIT} (the drawing "
                "cropped) or [width, height] in mm" + maybe(value, [*PAPER_SIZES, FIT]),
            )
    elif value is not MISSING:
        wh = r.numbers(value, r.at("size"), 2, positive=True, shape="[width, height]")
        if wh is not None:
            size = (wh[0], wh[1])
    notation = r.string("notation", choices=NOTATIONS, default="en") or "en"
    block = read_title_block(r, notation)
    r.finish()
    return Page(size, notation, fit, block)


def read_title_block(page: Reader, notation: str) -> TitleBlock | None:
    """[page.title_block]: title, name, group, date, sheet — one-line strings, each optional."""
    r = page.table_at("title_block")
    if r is None:
        return None
    cells: dict[str, str] = {}
    for key in TITLE_BLOCK_KEYS:
        value = r.raw(key)
        if value is MISSING:
            continue
        if not isinstance(value, str):
            quoted = f' in quotes: {key} = "{value}"' if hasattr(value, "isoformat") else ""
            r.problem(r.at(key), f"must be a string{quoted or ', not ' + type_name(value)}")
            continue
        most = MAX_TITLE if key == "title" else MAX_TITLE_BLOCK_CELL
        if len(value) > most:
            r.problem(r.at(key), f"too long ({len(value)} characters; at most {most} fit a cell)")
        elif any(ch in value for ch in "\r\n"):
            r.problem(r.at(key), "must be one line: a cell of the title block holds one line")
        else:
            cells[key] = value
    r.finish()
    return TitleBlock(**cells, notation=notation)


def read_tail(top: Reader, known: Iterable[str] = ()) -> tuple[float, Page]:
    """The end of every scene reader: [check] and [page], then any top-level key not in ``known``
    is an unknown key. Returns the drawing precision (mm) and the page."""
    precision, page = read_check(top), read_page(top)
    top.known.update(COMMON_KEYS)
    top.known.update(known)
    top.finish()
    return precision, page


def not_for(r: Reader, bases: Iterable[str], reason: str) -> None:
    """Refuse every key of ``bases`` (plain or with a suffix) present in the table."""
    for base in bases:
        r.known.add(base)
        for key in list(r.table):
            if key == base or key.startswith(base + "_"):
                r.used.add(key)
                r.problem(r.at(key), reason)


#: An angle of more turns than this is refused where it is read (a guide at −1e300° ran a stiff
#: equation of motion for minutes).
MAX_ANGLE_TURNS = 1000


def raise_sorted(problems: list[tuple[str, str]], data: Mapping[str, Any], order: Mapping[str, int],
                  section: str, source: str) -> NoReturn:
    """Raise the problems of a scene whose own table is ``section`` ([cam], [flywheel] …), in the
    order of the file: top-level keys first by ``order``, then the section's keys as written."""
    table = data.get(section)
    sub_order = {k: n for n, k in enumerate(table)} if isinstance(table, dict) else {}
    problems.sort(key=lambda p: file_order(p, order, sub_order, section))
    raise SceneError(problems or [(section, "invalid")], source)


def file_order(
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


#: The most points a ``table`` law may have.
MAX_TABLE_POINTS = 1000


def pole_distance_value(r: Reader) -> object:
    """The raw ``pole_distance_mm`` of a table (or ``MISSING``); ``pole_distance`` in other units
    is refused: H is always millimetres of drawing."""
    r.known.add("pole_distance_mm")
    for key in list(r.table):
        if key == "pole_distance" or (key.startswith("pole_distance_") and key != "pole_distance_mm"):
            r.used.add(key)
            r.problem(r.at(key), "H is a distance on the drawing: write pole_distance_mm")
    return r.raw("pole_distance_mm")


def pole_distances(r: Reader, count: int = 1) -> tuple[float, ...] | None:
    """``pole_distance_mm``: H in drawing mm, one number (for all ``count`` diagrams) or, when
    ``count`` > 1, a list [H1, H2 …]; each within tolerances.POLE_RANGE_MM."""
    value = pole_distance_value(r)
    if value is MISSING:
        return None
    path = r.at("pole_distance_mm")
    if isinstance(value, list) and count > 1:
        xs = r.numbers(value, path, count, positive=True, shape="[" + ", ".join(f"H{k + 1}" for k in range(count)) + "]")
        where = [(f"{path}[{k}]", f"H{k + 1}") for k in range(count)]
    else:
        x = r.number(value, path, positive=True)
        xs, where = (None if x is None else [x] * count), [(path, "H")] * count
    if xs is None:
        return None
    lo, hi = POLE_RANGE_MM
    for x, (key, name) in zip(xs, where):
        if not lo <= x <= hi:
            r.problem(key, f"{name} = {x:g} mm: a pole distance lies between {lo:g} and {hi:g} mm "
                           "(closer, the rays cannot be drawn; farther, the pole leaves the page)")
            return None
    return tuple(xs)


def page_size(scene: Scene[object]) -> tuple[float, float]:
    """The scene's sheet, (width, height) in mm: what its scales are chosen for and a kind
    judges "does the sheet fit" on — for a fit page, the working area (the drawn page is
    then cropped to the content)."""
    size = scene.page.size
    return (float(size[0]), float(size[1]))
