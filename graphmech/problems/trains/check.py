"""Checking a gear-train scene: the book's solution against every mesh solved as one linear system.

The graphical column is the book's method for now (:mod:`graphmech.methods.train_split`: the
split into basic trains, Willis' equation per carrier, the ordinary ratios, solved together);
the exact column is :func:`graphmech.exact.gear_train.solve`, which shares none of it. The
velocity diagram's lengths (drawn mm × μ) come in at one place, :func:`_graphical`. Only what
``find`` asks is put in the table (by default every free member's speed and the mobility).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from graphmech.errors import SceneError, UnknownName
from graphmech.exact import gear_train as ex
from graphmech.methods.train_senses import arrow
from graphmech.methods.train_split import Split, SplitSolution, solve, split
from graphmech.problems.judging import Row, Verdict, judge_value, measured_entries
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
        an.rows += _rows(an, n)
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


def _graphical(an: TrainAnalysis, n: Name, j: int) -> tuple[float, float | None, float]:
    """(value, drawn mm or None, μ) of a speed or ratio by the book's method.

    The one place the velocity diagram comes in: once it is drawn (methods/train_velocity.py),
    a parallel-axis train's speeds are its lengths × μ (drawn_mm, scale) instead of Willis'.
    """
    sol = an.solutions[j]
    if n.what == "n":
        return sol.speed(n.a or "") * RPM, None, 1.0
    if n.what == "omega":
        return sol.speed(n.a or ""), None, 1.0
    wb = sol.speed(n.b or "")
    if wb == 0.0:
        from graphmech.errors import NoSolution

        raise NoSolution(f"{n.text} has no value: {n.b} is at rest")
    return sol.speed(n.a or "") / wb, None, 1.0


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
        return [Row(n.text, "", None, 1.0, g, e, abs(g - e) / max(abs(e), 1e-300))]
    out = []
    for j in _indices(an, n):
        k = 0 if j is None else j
        g, drawn, mu = _graphical(an, n, k)
        sol = an.exact[k]
        if n.what == "i":
            e = sol.ratio(n.a or "", n.b or "")
            char = abs(e)
        else:
            e = sol.speed(n.a or "") * (RPM if n.what == "n" else 1.0)
            char = max(abs(w) for w in sol.omega.values()) * (RPM if n.what == "n" else 1.0)
        name = n.text if j is None or n.index is not None else f"{n.text}[{j}]"
        out.append(Row(name, n.unit, drawn, mu, g, e, abs(g - e) / max(abs(e), char, 1e-300)))
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
    senses = {} if not an.solutions else {k: arrow(an.problem.axes.get(k, "+x"), v)
                                           for k, v in an.solutions[0].speeds.items()}
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
            w = sol.exact_speeds[m]
            if w == 0:
                out.append(f"sense: {m} is at rest")
            elif p.axes.get(m, "+x") == p.axes.get(inp, "+x"):
                out.append(f"sense: {m} turns {'the same way as' if (w > 0) == (w_in > 0) else 'against'} the input "
                           f"{inp}")
            else:
                out.append(f"sense: {m} turns {'+' if w > 0 else '−'} about its axis {p.axes.get(m, '+x')} "
                           f"(arrow {arrow(p.axes.get(m, '+x'), float(w))})")
    return out


__all__ = ["TrainAnalysis", "analyse", "extras", "judge", "lines", "requested", "value_sets"]
