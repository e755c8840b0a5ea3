"""Read a linkage scene's full-cycle and characteristics parts: ``[cycle]``, ``[characteristics]``
and the ``show`` entries ``"cycle"``, ``"paths"``, ``"diagrams"``, ``"characteristics"``.

:func:`read_cycle` is called by :func:`graphmech.problems.linkage.scene.parse_linkage_scene`
for a linkage scene that has either table or shows one of these entries; it uses the same
reader, key paths and messages (every problem collected, raised once). A ``[cycle]`` divides
the crank's turn into N positions numbered 1 … N from its ``start`` — the crank's stated angle,
or the extreme position where the working stroke begins — and the scene's positions become
those N, labelled ``"1"`` … ``"N"`` (``v_C@3``). The format is the "Full cycle and
characteristics" section of ``docs/scene-format.md``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from collections.abc import Mapping
from typing import Any

from graphmech.mechanisms.linkage import Crank, Linkage, Positions
from graphmech.scales import phi_axis_problem
from graphmech.tolerances import POLE_RANGE_MM
from graphmech.problems.reader import pole_distances
from graphmech.problems.reader import MAX_POSITIONS, MISSING, Reader, read_scales, say, type_name

__all__ = ["CYCLE_SHOW_CHOICES", "CharacteristicsSpec", "CycleScene", "CycleSpec", "read_cycle"]

#: The show entries of this part: the mechanism overlaid at N positions, the paths of points, the
#: s–φ, v–φ, a–φ diagrams, and the characteristics (extreme positions, θ, ψ, γ_min).
CYCLE_SHOW_CHOICES = ("cycle", "paths", "diagrams", "characteristics")
#: What needs a [cycle] table.
_NEEDS_CYCLE = ("cycle", "paths", "diagrams", "velocity", "acceleration")
#: The fewest and the default number of positions of a cycle.
MIN_CYCLE_POSITIONS, DEFAULT_CYCLE_POSITIONS = 4, 12
START_CHOICES = ("driver", "extreme")
#: The pole distances H₁, H₂ when the scene gives none, mm.
DEFAULT_POLE_MM = 20.0
#: The longest pole distance, mm (stated or fixed by a stated μv, μa): farther, the pole leaves any page.
MIN_POLE_MM, MAX_POLE_MM = POLE_RANGE_MM


@dataclass(frozen=True)
class CycleSpec:
    """``[cycle]``: N, where position 1 is, the points whose paths and the subjects whose diagrams
    are drawn, the diagrams' stated scales (``phi`` rad/mm, ``s`` m/mm, ``psi`` rad/mm; ``v``, ``a``
    or for a link ``omega``, ``epsilon``, which fix the pole distances) and pole distances (mm;
    None: chosen, or fixed by the stated μv, μa)."""

    positions: int = DEFAULT_CYCLE_POSITIONS
    start: str = "driver"
    paths: tuple[str, ...] = ()
    diagrams: tuple[str, ...] = ()
    scales: dict[str, float] = field(default_factory=dict, hash=False)
    pole_distance_mm: tuple[float, float] | None = None


@dataclass(frozen=True)
class CharacteristicsSpec:
    """``[characteristics]``: the working stroke's time (s) for the timing, and whether to find
    the Grashof ranges of the crank's length."""

    t_work: float | None = None
    ranges: bool = False


@dataclass(frozen=True)
class CycleScene:
    """The full-cycle and characteristics parts of a linkage scene.

    ``characteristics`` is set when they are shown, tabled or may be found (always for a scene
    of this kind; computing them is lazy); ``start_angle`` is the crank's angle at position 1
    (rad).
    """

    cycle: CycleSpec | None
    characteristics: CharacteristicsSpec
    start_angle: float


def _names(r: Reader, key: str, check: Any) -> tuple[str, ...]:
    value = r.raw(key)
    if value is MISSING:
        return ()
    if not isinstance(value, list):
        r.problem(r.at(key), f"must be a list of names, not {type_name(value)}")
        return ()
    out: list[str] = []
    for i, item in enumerate(value):
        path = f"{r.at(key)}[{i}]"
        if isinstance(item, int) and not isinstance(item, bool):
            item = str(item)
        if not isinstance(item, str):
            r.problem(path, f"must be a name, not {type_name(item)}")
        elif item in out:
            r.problem(path, f"{say(item)} is listed twice")
        elif check(item, path):
            out.append(item)
    return tuple(out)


def _read_count(r: Reader) -> int | None:
    value = r.raw("positions")
    if value is MISSING:
        return DEFAULT_CYCLE_POSITIONS
    bounds = f"{MIN_CYCLE_POSITIONS} … {MAX_POSITIONS}"
    if isinstance(value, bool) or not isinstance(value, int):
        shown = say(value) if isinstance(value, float) else type_name(value)
        r.problem(r.at("positions"), f"must be a whole number of positions ({bounds}), not {shown}")
        return None
    if not MIN_CYCLE_POSITIONS <= value <= MAX_POSITIONS:
        r.problem(r.at("positions"), f"must lie between {MIN_CYCLE_POSITIONS} and {MAX_POSITIONS}, not {value}")
        return None
    return value


def _read_poles(r: Reader) -> tuple[float, float] | None:

    h = pole_distances(r, 2)
    return None if h is None else (h[0], h[1])


def _loop_problem(linkage: Linkage | None) -> str:
    """Why the linkage has no characterisable basic loop ("" if it has one)."""
    from graphmech.methods.characteristics import basic_loop

    if linkage is None:
        return ""
    try:
        basic_loop(linkage)
    except ValueError as e:
        return str(e)
    return ""


def read_cycle(top: Reader, data: Mapping[str, Any], show: tuple[str, ...], linkage: Linkage | None,
               positions: Positions | None) -> tuple[CycleScene | None, Positions | None]:
    """The [cycle] and [characteristics] tables; the scene's positions (N of them with a cycle).

    Problems go to ``top``'s list (the caller raises them with the rest).
    """
    from graphmech.methods.full_cycle import diagram_subjects

    show_list = list(show)
    crank = isinstance(linkage.driver, Crank) if linkage is not None else None
    if crank is False:
        top.problem("driver.type", 'a full cycle and the characteristics need a crank (type = "crank") as driver')
    cy = top.table_at("cycle")
    ch = top.table_at("characteristics")
    for i, s in enumerate(show_list):
        if s == "mechanism":
            top.problem(f"show[{i}]", 'with a full cycle or the characteristics the mechanism is drawn as "cycle" '
                                      '(all N positions) or "characteristics" (its extreme positions): drop "mechanism"')
        elif s == "instant_centres":  # a sheet of rows, one per position: not on the cycle's sheet
            top.problem(f"show[{i}]", 'the instant centres are drawn one row per position on a linkage sheet: show them '
                                      'in a scene without [cycle] and [characteristics] (find still takes P13, '
                                      'omega_3_ic@3 … here)')
        elif s in _NEEDS_CYCLE and cy is None:
            top.problem(f"show[{i}]", f'"{s}" needs a [cycle] table (positions = 12, start = "extreme" …)')
    spec = None
    if cy is not None:
        count = _read_count(cy)
        start = cy.string("start", choices=START_CHOICES, default="driver")
        mech_points = set() if linkage is None else (
            {p for pts in linkage.links().values() for p in pts} | set(linkage.frame_points))
        subjects = diagram_subjects(linkage) if linkage is not None else {}

        def is_point(name: str, path: str) -> bool:
            if linkage is not None and name not in mech_points:
                cy.problem(path, f"{say(name)} is not a point of the linkage ({', '.join(sorted(mech_points))})")
                return False
            if linkage is not None and name in linkage.frame_points:
                cy.problem(path, f"{say(name)} is a point of the frame: it does not move, it has no path")
                return False
            return True

        def is_subject(name: str, path: str) -> bool:
            if linkage is not None and name not in subjects:
                what = {"point": "slider", "link": "link", "path": "point"}
                choices = ", ".join(f"{k} ({what[v]})" for k, v in subjects.items())
                cy.problem(path, f"{say(name)} has no s–φ diagram: name a slider, a rotating link or a moving "
                                 f"point ({choices})")
                return False
            return True

        paths = _names(cy, "paths", is_point)
        diagrams = _names(cy, "diagrams", is_subject)
        scales = read_scales(cy, entries=[("phi", "angle"), ("s", "length"), ("psi", "angle"), ("v", "velocity"),
                                           ("a", "acceleration"), ("omega", "omega"), ("epsilon", "epsilon")])
        poles = _read_poles(cy)
        why = phi_axis_problem(scales["phi"]) if "phi" in scales else None  # a whole turn's φ axis must fit a drawing
        if why:
            tab = cy.table.get("scales")
            key = next((k for k in tab if k.startswith("phi")), "phi") if isinstance(tab, dict) else "phi"
            cy.problem(f"cycle.scales.{key}", why)
        derived = [k for k in ("v", "a", "omega", "epsilon") if k in scales]
        if poles is not None and derived:  # μv = μs·ω₁/(μφ·H₁): one fixes the other
            cy.problem(cy.at("pole_distance_mm"), f"give the pole distances or the diagrams' μ{derived[0]}, not both: "
                                                  "they fix each other (μv = μs·ω₁/(μφ·H₁), μa = μv·ω₁/(μφ·H₂))")
        cy.finish()
        for i, s in enumerate(show_list):
            if s == "paths" and "paths" not in cy.table:
                top.problem(f"show[{i}]", '"paths" needs the points: [cycle] paths = ["C", …]')
            if s == "diagrams" and "diagrams" not in cy.table:
                top.problem(f"show[{i}]", '"diagrams" needs what to plot: [cycle] diagrams = ["C", "3"] '
                                          "(sliders, rotating links)")
        if diagrams and linkage is not None and isinstance(linkage.driver, Crank) and linkage.driver.omega == 0.0:
            top.problem("driver.omega", "the s–φ, v–φ, a–φ diagrams need a turning crank (ω ≠ 0): at ω = 0 their "
                                        "φ axis is no time axis and every v, a is 0")
        if diagrams and linkage is not None and isinstance(linkage.driver, Crank) and linkage.driver.epsilon != 0.0:
            top.problem("driver.epsilon", "the s–φ, v–φ, a–φ diagrams need a crank turning uniformly (ε = 0): "
                                          "their φ axis is a time axis only then")
        if positions is not None and len(positions.values) != 1:
            top.problem("driver.angle", "one number in a scene with [cycle]: the crank's angle at position 1 "
                                        "(the cycle's positions divide the turn from there)")
        if count is not None and start is not None:
            spec = CycleSpec(count, start, paths, diagrams, scales, poles)
    t_work, ranges = None, False
    if ch is not None:
        v = ch.value("t_work", "time", required=False, positive=True)
        t_work = None if v is None else v.si
        ranges = ch.flag("ranges") or False
        ch.finish()
    wants = "characteristics" in show or ch is not None or (spec is not None and spec.start == "extreme")
    why = _loop_problem(linkage) if wants and crank else ""
    if why:
        where = "cycle.start" if spec is not None and spec.start == "extreme" else (
            f"show[{show_list.index('characteristics')}]" if "characteristics" in show_list else "characteristics")
        top.problem(where, why)
    if ranges and not why and linkage is not None and crank:
        from graphmech.methods.characteristics import basic_loop

        if basic_loop(linkage).kind != "fourbar":
            top.problem("characteristics.ranges", "the Grashof ranges are those of a hinged four-bar")
    if linkage is None or not isinstance(linkage.driver, Crank) or positions is None or top.problems:
        return None, positions
    start_angle = positions.values[0]
    if spec is not None and spec.start == "extreme":
        from graphmech.methods.characteristics import draw_characteristics

        try:
            first = draw_characteristics(linkage, 1e-3).phi_start
        except (ValueError, ArithmeticError) as e:  # a refusal, or the extreme pin cannot be assembled
            top.problem("cycle.start", f"no extreme position to start from: {e}")
            return None, positions
        if first is None:
            top.problem("cycle.start", "no extreme position to start from: the output turns fully too "
                                       '(a double crank); start = "driver"')
            return None, positions
        start_angle = first
    if spec is not None:
        from graphmech.methods.full_cycle import cycle_positions

        sense = -1.0 if linkage.driver.omega < 0 else 1.0
        angles = cycle_positions(start_angle, spec.positions, sense)
        positions = Positions(tuple(float(a) for a in angles), tuple(str(k) for k in range(1, spec.positions + 1)))
    return CycleScene(spec, CharacteristicsSpec(t_work, ranges), start_angle), positions

