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

import math
from dataclasses import dataclass, field
from collections.abc import Mapping
from typing import Any

from graphmech.mechanisms.linkage import Crank, Linkage, Positions
from graphmech.scales import phi_axis_problem
from graphmech.tolerances import COINCIDENT_REL, POLE_RANGE_MM
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
    between: str | tuple[float, float] | None = None  # a swing: "limits" or its ends (rad or m), as written


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
    swing: tuple[float, float] | None = None  # a swing's ends (φ unwrapped, rad; or s, m): positions 1 and N/2 + 1
    stated: float | None = None  # a swing's driver position as stated (it picks the swing whose limits are found)


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


def read_between(cy: Reader, top: Reader, linkage: Linkage | None, count: int | None, diagrams: tuple[str, ...],
                 start: str | None) -> str | tuple[float, float] | None:
    """``[cycle] between``: "limits" or the swing's two ends (a crank's angles, a slider's positions)."""
    raw = cy.table.get("between")
    if raw is None and cy.present("between") is None:
        cy.known.add("between")
        return None
    out: str | tuple[float, float] | None = None
    if isinstance(raw, str):
        cy.raw("between")
        if raw != "limits":
            cy.problem(cy.at("between"), 'must be "limits" or the swing\'s ends [from, to] with a unit '
                                         f"(between_deg, between_mm), not {say(raw)}")
            return None
        out = "limits"
    elif linkage is not None:
        kind = "angle" if isinstance(linkage.driver, Crank) else "length"
        given = cy.quantity("between", kind)
        if given is None:
            return None
        ends = cy.numbers(given.value, cy.at(given.key), 2, shape="[from, to]")
        if ends is None:
            return None
        out = (given.si(ends[0]), given.si(ends[1]))
        turns = (out[1] - out[0]) % (2.0 * math.pi) if kind == "angle" else 1.0
        if out[0] == out[1]:
            cy.problem(cy.at(given.key), "the swing's two ends are one position")
            return None
        if min(turns, 2.0 * math.pi - turns) <= COINCIDENT_REL * 2.0 * math.pi:  # 0 and 360°: one place
            cy.problem(cy.at(given.key), "the swing's two ends are one place on the turn (a swing is less than a "
                                         "turn; for the full turn leave out between)")
            return None
    else:
        cy.ignore("between")
        return None
    if count is not None and count % 2:
        cy.problem(cy.at("positions"), f"a swing goes out and back in equal steps: N must be even, not {count} "
                                       "(positions 1 … N/2 + 1 out, the rest back)")
    if diagrams:
        cy.problem(cy.at("diagrams"), "the chord diagrams need a driver moving one way: over a swing it reverses at "
                                      "each end, where v jumps — drop diagrams (the polygons give v, a at every position)")
    if "start" in cy.table and start == "extreme":
        cy.problem(cy.at("start"), 'a swing starts at its first end: drop start = "extreme"')
    d = linkage.driver if linkage is not None else None
    if isinstance(d, Crank) and (d.omega == 0.0 or d.epsilon != 0.0):
        top.problem("driver.epsilon" if d.epsilon else "driver.omega",
                    "over a swing the rocker moves uniformly at |ω| ≠ 0, reversing at the ends: ω ≠ 0, ε = 0")
    if d is not None and not isinstance(d, Crank) and (d.velocity == 0.0 or d.acceleration != 0.0):
        top.problem("driver.acceleration" if d.acceleration else "driver.velocity",
                    "over a stroke the slider moves uniformly at |v| ≠ 0, reversing at the ends: v ≠ 0, acceleration 0")
    return out


def swing_scene(top: Reader, spec: CycleSpec, linkage: Linkage, positions: Positions,
                characteristics: CharacteristicsSpec) -> tuple[CycleScene | None, Positions | None]:
    """A swing's N positions: its ends stated, or its limits constructed about the driver's position."""
    from graphmech.errors import NotApplicable
    from graphmech.methods.swing import driver_limits, swing_positions

    d = linkage.driver
    q0 = positions.values[0]
    sense = (1.0 if d.omega > 0 else -1.0) if isinstance(d, Crank) else (1.0 if d.velocity > 0 else -1.0)
    crank = isinstance(d, Crank)
    if spec.between == "limits":
        try:
            lower, upper = driver_limits(linkage, q0)
        except NotApplicable as e:
            top.problem("cycle.between", str(e))
            return None, positions
        q_from, q_to = (lower, upper) if sense > 0 else (upper, lower)
    else:
        assert isinstance(spec.between, tuple)
        q_from, q_to = spec.between
        if crank:  # the first stroke turns from `from` to `to` in the crank's sense
            q_to = q_from + sense * ((sense * (q_to - q_from)) % (2.0 * math.pi))
        elif (q_to - q_from) * sense < 0:
            top.problem("cycle.between", f"the first stroke runs from {q_from * 1000:g} to {q_to * 1000:g} mm, against "
                                         "the slider's velocity: swap the ends or reverse the velocity")
            return None, positions
    q, _ = swing_positions(q_from, q_to, spec.positions)
    labels = tuple(str(k) for k in range(1, spec.positions + 1))
    return CycleScene(spec, characteristics, q_from, (q_from, q_to), q0), Positions(tuple(float(x) for x in q), labels)


def read_cycle(top: Reader, data: Mapping[str, Any], show: tuple[str, ...], linkage: Linkage | None,
               positions: Positions | None) -> tuple[CycleScene | None, Positions | None]:
    """The [cycle] and [characteristics] tables; the scene's positions (N of them with a cycle).

    Problems go to ``top``'s list (the caller raises them with the rest).
    """
    from graphmech.methods.full_cycle import diagram_subjects

    show_list = list(show)
    crank = isinstance(linkage.driver, Crank) if linkage is not None else None
    cy = top.table_at("cycle")
    ch = top.table_at("characteristics")
    if crank is False and (ch is not None or "characteristics" in show):
        top.problem("driver.type", 'the characteristics need a crank (type = "crank") as driver')
    elif crank is False and cy is not None and cy.present("between") is None:
        top.problem("driver.type", 'a slider drives over a stroke, not a turn: [cycle] between_mm = [from, to] or '
                                   'between = "limits"')
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
        between = read_between(cy, top, linkage, count, diagrams, start)
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
            key, what = ("driver.angle", "crank's angle") if crank is not False else ("driver.position", "slider's position")
            top.problem(key, f"one number in a scene with [cycle]: the {what} at position 1 "
                             "(the cycle's positions divide the turn from there)" if between is None else
                        f"one number in a scene with [cycle]: the {what} inside the swing")
        if count is not None and start is not None:
            spec = CycleSpec(count, start, paths, diagrams, scales, poles, between)
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
    if linkage is None or positions is None or top.problems:
        return None, positions
    if spec is not None and spec.between is not None:
        return swing_scene(top, spec, linkage, positions, CharacteristicsSpec(t_work, ranges))
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
    if spec is not None and isinstance(linkage.driver, Crank):  # a slider's cycle is a swing (above)
        from graphmech.methods.full_cycle import cycle_positions

        sense = -1.0 if linkage.driver.omega < 0 else 1.0
        angles = cycle_positions(start_angle, spec.positions, sense)
        positions = Positions(tuple(float(a) for a in angles), tuple(str(k) for k in range(1, spec.positions + 1)))
    return CycleScene(spec, CharacteristicsSpec(t_work, ranges), start_angle), positions

