"""Checking a gear-train scene: the velocity diagram and the book's solution against every mesh
solved as one linear system.

The graphical column of a speed is its length on the velocity diagram's ω line × μω, a ratio the
ratio of two lengths (:mod:`graphmech.problems.trains.diagram`, the diagram the sheet draws) —
for a train whose axes are all parallel; a spatial train's (and the converted ratios, tooth
numbers, mobility) come from the book's method (:mod:`graphmech.methods.train_split`: the split
into basic trains, Willis' equation per carrier, the ordinary ratios, solved together). The exact
column is :func:`graphmech.exact.gear_train.solve`, which shares none of it. Only what ``find``
asks is put in the table (by default every free member's speed and the mobility).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from graphmech import tolerances as T
from graphmech.accuracy import percent
from graphmech.errors import NoSolution, SceneError, UnknownName
from graphmech.exact import gear_train as ex
from graphmech.mechanisms.gear_train import AXES, GearTrain
from graphmech.methods.train_senses import arrow
from graphmech.methods.train_velocity import TrainVelocityDiagram
from graphmech.methods.train_split import Split, SplitSolution, solve, split
from graphmech.problems.judging import Row, Verdict, judge_value, measured_entries
from graphmech.problems.trains.diagram import drawn
from graphmech.problems.trains.dynamics import dynamics_lines, dynamics_rows, is_dynamics_name
from graphmech.problems.trains.names import Name, parse_name
from graphmech.scales import format_scale

if TYPE_CHECKING:
    from graphmech.problems.kind import Extra
    from graphmech.problems.reader import Scene
    from graphmech.problems.trains.scene import TrainScene

#: rad/s → r/min.
RPM = 30.0 / math.pi


@dataclass
class TrainAnalysis:
    """What one gear-train scene produced: the split, its solution per input value, the exact
    solution per input value, the rows and the warnings."""

    scene: Scene[TrainScene]
    split: Split
    solutions: list[SplitSolution] = field(default_factory=list)
    exact: list[ex.TrainSolution] = field(default_factory=list)
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    extra_measured: Extra = ()
    diagrams: dict[int, TrainVelocityDiagram | None] = field(default_factory=dict)
    #: row name → the book's value (the split's solution) of a row read off the velocity diagram
    book: dict[str, float] = field(default_factory=dict)

    def scale_notes(self) -> list[str]:
        return [format_scale(k, v) for k, v in self.scales.items()]

    @property
    def problem(self) -> TrainScene:
        return self.scene.problem


def value_sets(p: TrainScene) -> list[dict[str, float]]:
    """The inputs of each solve: one per value of the list input (one solve without a list)."""
    count = max((len(v) for v in p.input_values.values()), default=1)
    return [{k: (v[j] if len(v) > 1 else v[0]) for k, v in p.input_values.items()} for j in range(count)]


def requested(scene: Scene[TrainScene], extra: Extra = ()) -> list[Name]:
    """The find names read (the scene reader has refused the unknown ones); by default every
    free member's speed and the mobility."""
    p = scene.problem
    count = len(value_sets(p))
    texts = list(scene.find) or [f"n{m.name}" for m in p.train.members
                                 if m.name not in p.train.fixed and m.name not in p.input_values] + ["dof"]
    problems = []
    for key, name, _ in measured_entries(scene, extra):
        if is_dynamics_name(name):
            continue
        try:
            parse_name(name, p.train, p.solved_z, count)
        except UnknownName as e:  # said with its key
            problems.append((key, str(e)))
    if problems:
        raise SceneError(problems, scene.source)
    return [parse_name(t, p.train, p.solved_z, count) for t in texts if not is_dynamics_name(t)]


def analyse(scene: Scene[TrainScene], extra: Extra = ()) -> TrainAnalysis:
    """Split and solve the train as the book does, solve it exactly, and build the rows asked for."""
    p = scene.problem
    names = requested(scene, extra)
    sp = split(p.train)
    an = TrainAnalysis(scene, sp, scales=dict(scene.scales), extra_measured=tuple(extra))
    for inputs in value_sets(p):  # the senses under the table need the speeds whatever is asked
        t = p.train.with_inputs(inputs)
        an.solutions.append(solve(t, sp))
        an.exact.append(ex.solve(t))
    an.warnings += list(p.coaxial_notes)
    for n in names:
        try:
            an.rows += _rows(an, n)
        except NoSolution as e:  # a ratio to a member at rest: said at the name asked
            if n.text not in scene.find:
                raise
            raise SceneError([(f"find[{list(scene.find).index(n.text)}]", str(e))], scene.source) from None
    _short_lengths(an)
    asked = [t for t in scene.find if is_dynamics_name(t)]
    if asked:  # reduced J and M at the book's speeds; efficiency by the converted train
        book = {k: float(v) for k, v in an.solutions[0].speeds.items()}
        an.rows += dynamics_rows(scene, book, asked)
    return an


def _indices(an: TrainAnalysis, n: Name) -> list[int | None]:
    """Which solves a speed or ratio row reads: the one asked, or each value of a list input."""
    if n.index is not None:
        return [n.index]
    return [None] if len(an.solutions) == 1 else list(range(len(an.solutions)))


def _diagram(an: TrainAnalysis, j: int) -> TrainVelocityDiagram | None:
    """The velocity diagram of solve j as the sheet draws it (None: a spatial train, or one whose
    layout does not close — said once, and its rows are the book's equations)."""
    if j not in an.diagrams:
        d = None
        if an.problem.parallel:
            try:
                d = drawn(an.scene, value_sets(an.problem)[j] if j else None).velocity
            except NoSolution as e:
                if not any(w.startswith("no velocity diagram") for w in an.warnings):
                    an.warnings.append(f"no velocity diagram: {e}; the speeds are the book's equations'")
        an.diagrams[j] = d
    return an.diagrams[j]


def _graphical(an: TrainAnalysis, n: Name, j: int) -> tuple[float, float | None, float]:
    """(value, drawn mm or None, μ) of a speed or ratio: read off the velocity diagram where the
    train has one — a speed is its length ℓ on the ω line × μω (signed along the member's axis), a
    ratio the ratio of two lengths — else by the book's equations (the split, Willis)."""
    d = _diagram(an, j)
    if d is not None and n.what in ("n", "omega", "i"):
        longest = max(abs(x) for x in d.lengths.values())
        # a cut within round-off of the pole's foot is the foot: that member is at rest
        ell = {m: 0.0 if abs(x) <= T.COINCIDENT_REL * longest else d.sense[m] * x for m, x in d.lengths.items()}
        if n.what in ("n", "omega"):
            drawn_mm = ell[an.problem.train.member_of(n.a or "")]
            mu = d.mu_omega * (RPM if n.what == "n" else 1.0)
            return drawn_mm * mu, drawn_mm, mu
        lb = ell[an.problem.train.member_of(n.b or "")]
        if lb == 0.0:
            raise NoSolution(f"{n.text} has no value: {n.b} is at rest")
        return ell[an.problem.train.member_of(n.a or "")] / lb, None, 1.0
    return _book(an, n, j), None, 1.0


def spin_carrier(train: GearTrain, member: str) -> str | None:
    """The carrier a member's speed is counted relative to: a planet whose axis is not parallel
    to its carrier's (a bevel planet) turns about no fixed axis, and the book's speed of it is its
    spin about its own axis relative to the carrier, n_k − n_H; None for every other member."""
    m = train.member(member)
    if m.carrier is None:
        return None
    u, v = AXES[m.axis], AXES[train.member(m.carrier).axis]
    return None if abs(u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) == 1 else m.carrier


def speed_of(train: GearTrain, speed: Callable[[str], float], name: str) -> float:
    """ω of a member or gear as the rows report it: absolute, or a bevel planet's spin relative to
    its carrier (:func:`spin_carrier`); ``speed`` gives the solution's absolute speeds."""
    h = spin_carrier(train, train.member_of(name))
    return speed(name) - (speed(h) if h is not None else 0.0)


def _book(an: TrainAnalysis, n: Name, j: int) -> float:
    """A speed or ratio by the book's equations (the split's solution)."""
    sol = an.solutions[j]
    if n.what == "n":
        return speed_of(an.problem.train, sol.speed, n.a or "") * RPM
    if n.what == "omega":
        return speed_of(an.problem.train, sol.speed, n.a or "")
    wb = sol.speed(n.b or "")
    if wb == 0.0:
        raise NoSolution(f"{n.text} has no value: {n.b} is at rest")
    return sol.speed(n.a or "") / wb


#: A length on the ω line read within the drawing precision to worse than this fraction is flagged.
SHORT_READING = 0.05


def _short_lengths(an: TrainAnalysis) -> None:
    """Flag the speeds whose length ℓ on the ω line is too short to read on paper (a slow output
    beside a fast input at one pole distance: the method's limit), and say how to draw it longer."""
    prec = an.scene.precision_mm
    short = [r for r in an.rows if r.drawn_mm is not None and r.drawn_mm != 0.0 and prec / abs(r.drawn_mm) > SHORT_READING]
    if not short:
        return
    an.rows = [replace(r, ill_conditioned=True) if r in short else r for r in an.rows]
    said = ", ".join(f"{r.name} ({abs(r.drawn_mm or 0.0):.3g} mm, ±{percent(prec / abs(r.drawn_mm or 1.0))})"
                     for r in short)
    an.warnings.append(f"short lengths on the ω line, read at {prec:g} mm: {said}; a larger pole distance "
                       "([train] pole_distance_mm or [scales] omega) draws them longer, and the fast members' "
                       "longer still: one diagram cannot read a large ratio's both ends on paper")


def _rows(an: TrainAnalysis, n: Name) -> list[Row]:
    p = an.problem
    if n.what == "dof":
        e = float(ex.mobility(p.train))
        return [Row(n.text, "", None, 1.0, float(an.split.mobility), e, abs(an.split.mobility - e) / max(e, 1.0))]
    if n.what == "z":
        g = float(p.solved_z[n.a or ""])
        e = float(ex.coaxial_tooth_number(*p.coaxial_sets[n.a or ""]))
        return [Row(n.text, "", None, 1.0, g, e, abs(g - e) / e)]
    if n.what == "iH":
        h, a, b = n.carrier or "", n.a or "", n.b or ""
        g = float(an.split.converted_ratio(a, b, h))
        e = ex.converted_train_ratio(p.train, a, b, h)
        return [Row(n.text, "", None, 1.0, g, e, abs(g - e) / max(abs(e), 1e-300),
                    basis="the converted train's tooth numbers")]
    out = []
    for j in _indices(an, n):
        k = 0 if j is None else j
        g, drawn, mu = _graphical(an, n, k)
        sol = an.exact[k]
        if n.what == "i":
            e = sol.ratio(n.a or "", n.b or "")
            char = abs(e)
        else:
            e = speed_of(p.train, sol.speed, n.a or "") * (RPM if n.what == "n" else 1.0)
            char = max(abs(w) for w in sol.omega.values()) * (RPM if n.what == "n" else 1.0)
        name = n.text if j is None or n.index is not None else f"{n.text}[{j}]"
        on_diagram = an.diagrams.get(k) is not None
        if on_diagram:
            an.book[name] = _book(an, n, k)
        basis = (("a length on the ω line × μω" if drawn is not None else "a ratio of lengths on the ω line")
                 if on_diagram else "the book's equations (the split, Willis)")
        out.append(Row(name, n.unit, drawn, mu, g, e, abs(g - e) / max(abs(e), char, 1e-300), basis=basis))
    return out


def judge(an: TrainAnalysis) -> list[Verdict]:
    """Hand values against the book's: within 0.1 % (computed values), or the drawing precision × μ."""
    rows = {r.name: r for r in an.rows}
    out = []
    for key, name, value in measured_entries(an.scene, an.extra_measured):
        if name not in rows:
            raise SceneError([(key, f"{name} is not in the check table: add it to find")], an.scene.source)
        r = rows[name]
        out.append(judge_value(name, value, r.graphical, r.drawn_mm, r.scale, an.scene.precision_mm, r.unit))
    return out


def extras(an: TrainAnalysis) -> dict[str, Any]:
    """``check --json``'s ``"train"``: the basic trains and their equations, how they join, the
    mobility, the redundant meshes, each member's arrow."""
    sp = an.split
    train, sol = an.problem.train, an.solutions[0] if an.solutions else None
    senses = {} if sol is None else {k: arrow(an.problem.axes.get(k, "+x"), speed_of(train, sol.speed, k))
                                     for k in sol.speeds}
    return {"train": {"basic_trains": [b.as_dict() for b in sp.trains], "links": list(sp.links),
                      "mobility": sp.mobility, "redundant_meshes": sp.redundant, "senses": senses}}


def lines(an: TrainAnalysis) -> list[str]:
    """Under the table: the split, the redundant meshes counted once, the sense of the outputs."""
    sp = an.split
    out = ["split: " + " + ".join(f"{b.kind} {b.label}" + (f" (carrier {b.carrier})" if b.carrier else "")
                                  for b in sp.trains)
           + (f"; joined by {'; '.join(sp.links)}" if sp.links else "")]
    if sp.redundant:
        which = ", ".join(f"{b.label}: {b.redundant}" for b in sp.trains if b.redundant)
        out.append(f"redundant meshes counted once: {sp.redundant} (identical planets or idlers; {which})")
    if not an.problem.parallel:
        out.append("a spatial train: its rows come from the book's equations (no velocity diagram)")
    if an.solutions:
        out += _senses(an)
    return out + dynamics_lines(an.scene, an.rows)


def _senses(an: TrainAnalysis) -> list[str]:
    p = an.problem
    sol = an.solutions[0]
    asked = [r.name for r in an.rows if not is_dynamics_name(r.name)]
    shown = []
    for n in (parse_name(t.split("[")[0], p.train, p.solved_z, len(an.solutions)) for t in asked):
        if n.what in ("n", "omega") and n.a is not None:
            m = p.train.member_of(n.a)
            if m not in p.input_values and m not in shown:
                shown.append(m)
    out = []
    for inp in list(p.input_values)[:1]:
        w_in = sol.exact_speeds[inp]
        for m in shown:
            w = speed_of(p.train, lambda k: float(sol.exact_speeds[k]), m)
            h = spin_carrier(p.train, m)
            if w == 0:
                out.append(f"sense: {m} is at rest" + (f" relative to its carrier {h}" if h else ""))
            elif h is not None:
                out.append(f"sense: {m} spins {'+' if w > 0 else '−'} about its axis {p.axes.get(m, '+x')} relative "
                           f"to its carrier {h} (arrow {arrow(p.axes.get(m, '+x'), float(w))}; its axis turns with {h})")
            elif p.axes.get(m, "+x") == p.axes.get(inp, "+x"):
                out.append(f"sense: {m} turns {'the same way as' if (w > 0) == (w_in > 0) else 'against'} the input "
                           f"{inp}")
            else:
                out.append(f"sense: {m} turns {'+' if w > 0 else '−'} about its axis {p.axes.get(m, '+x')} "
                           f"(arrow {arrow(p.axes.get(m, '+x'), float(w))})")
    return out


__all__ = ["TrainAnalysis", "analyse", "extras", "judge", "lines", "requested", "value_sets"]
