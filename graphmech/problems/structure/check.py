"""Checking a structure scene: the Grübler–Kutzbach count against the constraint Jacobian's rank,
and the decomposition into drivers and Assur groups.

The two mobility methods are independent: the count uses only the topology (how many links and
pairs, which compound hinges, which rollers), the rank only the geometry (the linearised pair
constraints at the given joint coordinates, numpy's SVD with the relative tolerance
:data:`graphmech.mechanisms.topology.RANK_REL`). Where they differ the mechanism has redundant
constraints (虚约束) the count did not know of, or stands in a singular position; the check
table says which. ``graphmech check --json`` adds a ``"structure"`` section with every count,
the rank, the groups and the class.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from graphmech.mechanisms.topology import Mobility, Structure, grubler, mobility, roman, structure
from graphmech.scales import drawn_size_problem

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene
    from graphmech.problems.structure.scene import StructureScene

#: find names that need the Jacobian (the others are counts or the decomposition).
_NEEDS_RANK = {"F", "F_actual", "rank", "p_redundant", "p_redundant_actual"}


@dataclass
class StructureAnalysis:
    scene: Scene[StructureScene]
    mobility: Mobility | None
    structure: Structure | None
    rows: list[Any] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    cases: list[dict[str, Any]] = field(default_factory=list)

    def scale_notes(self) -> list[str]:
        from graphmech.scales import format_scale

        return [format_scale(k, v) for k, v in self.scales.items()]

    def summary(self) -> dict[str, Any]:
        """The ``"structure"`` section of ``check --json``."""
        out: dict[str, Any] = {}
        if self.cases:
            out["cases"] = self.cases
        m = self.mobility
        if m is not None:
            out.update({"n": m.n, "pl": m.pl, "ph": m.ph, "F_local": m.F_local, "p_redundant": m.p_redundant,
                        "F_count": m.F_count, "F": m.F, "compound_hinges": list(m.compound),
                        "rollers": list(m.rollers)})
            if m.rank is not None:
                out["jacobian"] = {"rank": m.rank, "equations": m.equations, "F_actual": m.F_actual,
                                   "p_redundant": m.p_redundant_actual, "tolerance": m.tolerance,
                                   "singular_values": list(m.singular_values)}
        s = self.structure
        if s is not None:
            out["drivers"] = list(s.drivers)
            out["groups"] = [{"links": list(g.links), "class": g.grade, "pairs": list(g.pairs)} for g in s.groups]
            out["class"] = s.grade
            out["higher_pairs_replaced"] = list(s.replaced)
            out["messages"] = list(s.messages)
        return out


def formula(m: Mobility) -> str:
    """``F = 3·3 − (2·4 + 0 − 0) − 0 = 1`` as the book writes it."""
    return formula_text(m.n, m.pl, m.ph, m.p_redundant, m.F_local, m.F)


def case_formula(c: dict[str, Any]) -> str:
    """The count of a printed case (as :attr:`StructureAnalysis.cases` holds it) written out."""
    return formula_text(c["n"], c["pl"], c["ph"], c["p_redundant"], c["F_local"], c["F"])


def formula_text(n: int, pl: int, ph: int, p_redundant: int, F_local: int, F: int) -> str:
    """Grübler–Kutzbach's count written out: ``F = 3·3 − (2·4 + 0 − 0) − 0 = 1``."""
    return f"F = 3·{n} − (2·{pl} + {ph} − {p_redundant}) − {F_local} = {F}"


def analyse_structure(scene: Scene[StructureScene]) -> StructureAnalysis:
    """Count, rank and decompose what the scene asks for."""
    from graphmech.problems.judging import Row

    ss = scene.problem
    an = StructureAnalysis(scene, None, None, scales=dict(scene.scales))
    for c in ss.cases:
        f = grubler(c.n, c.pl, c.ph, c.p_redundant, c.F_local)
        an.cases.append({"label": c.label, "n": c.n, "pl": c.pl, "ph": c.ph, "p_redundant": c.p_redundant,
                         "F_local": c.F_local, "F": f})
        if f <= 0:
            an.warnings.append(f"{c.label}: F = {f}: a rigid structure (桁架), it cannot move")
    topo = ss.topology
    if topo is None:
        return an
    if ss.geometry and "l" in scene.scales:  # a stated μl must draw the pairs on paper
        xs, ys = zip(*(p.at for p in topo.pairs))
        why = drawn_size_problem(max(max(xs) - min(xs), max(ys) - min(ys)), float(scene.scales["l"]))
        if why:
            from graphmech.errors import SceneError

            raise SceneError([("scales", why)], scene.source)
    find = {n.partition("@")[0] for n in scene.find}
    rank = ss.geometry and (not find or bool(find & _NEEDS_RANK) or "structure" in scene.show)
    an.mobility = m = mobility(topo, bool(rank))
    if not find or "class" in find or "structure" in scene.show:
        an.structure = st = structure(topo)
        msgs = list(st.messages)
        if st.leftover and m.p_redundant_actual:  # the book removes redundant links before the analysis
            msgs[-1] = (f"links {', '.join(st.leftover)} form no Assur group: with {m.p_redundant_actual} redundant "
                        "constraint(s) they repeat a motion already fixed — leave them out, as the book does, "
                        "for the structure")
            from dataclasses import replace

            an.structure = replace(st, messages=tuple(msgs))
        an.warnings.extend(msgs)
    if m.rank is not None:
        assert m.F_actual is not None and m.p_redundant_actual is not None
        for name, g, e in (("F", m.F, m.F_actual), ("p_redundant", m.p_redundant, m.p_redundant_actual)):
            if name == "p_redundant" and topo.redundant is None:
                continue  # nothing stated to check: the Jacobian's value is in the summary
            if not find or name in find:
                an.rows.append(Row(name, "", None, 1.0, float(g), float(e), abs(g - e) / max(abs(e), 1.0)))
        if m.F != m.F_actual:
            an.warnings.append(f"the count gives F = {m.F} but the constraint Jacobian has rank {m.rank} of "
                               f"{m.equations} equations: F = {m.F_actual} at this geometry "
                               f"({m.p_redundant_actual} redundant constraint(s)) — state redundant = "
                               f"{m.p_redundant_actual} if they are the design's, else the position is singular")
    elif topo.redundant is None and find & {"F_actual", "rank", "p_redundant_actual"}:
        an.warnings.append("no coordinates for the pairs: the actual mobility (the Jacobian's rank) is not found")
    f = m.F_actual if m.F_actual is not None else m.F  # what the mechanism does, where it is known
    if f <= 0:
        an.warnings.append(f"F = {f}: the links form a rigid structure and cannot move")
    elif topo.drivers and f != len(topo.drivers):
        an.warnings.append(f"F = {f} but {len(topo.drivers)} driver(s): the motion is "
                           + ("not determined" if f > len(topo.drivers) else "over-constrained"))
    return an


def judge_structure(an: StructureAnalysis, extra: tuple[tuple[str, float], ...] = ()) -> list[Any]:
    """Verdicts on measured counts (``F = 1``, ``class = 2`` …): whole numbers, judged exactly.

    Raises
    ------
    SceneError
        For a name that is not a count of this scene (or cannot be found without coordinates).
    """
    from graphmech.problems.judging import Verdict
    from graphmech.errors import SceneError

    doc = an.summary()
    values: dict[str, Any] = {k: doc[k] for k in ("n", "pl", "ph", "F_local", "p_redundant", "F_count", "F", "class") if k in doc}
    if "jacobian" in doc:
        j = doc["jacobian"]
        values.update({"F_actual": j["F_actual"], "rank": j["rank"], "p_redundant_actual": j["p_redundant"]})
    out, problems = [], []
    entries = [(f"measured.{n}", n, v) for n, v in an.scene.measured] + [(f"--measured {n}", n, v) for n, v in extra]
    for key, name, value in entries:
        if name not in values:
            problems.append((key, f"{name} is not found by this scene (it finds {', '.join(values) or 'nothing'})"))
            continue
        if value != int(value):
            problems.append((key, f"{name} is a count: a whole number, not {value:g}"))
            continue
        e = float(values[name])
        out.append(Verdict(name, value, e, 0.0, value == e, ""))
    if problems:
        raise SceneError(problems, an.scene.source)
    return out


def text_summary(an: StructureAnalysis) -> list[str]:
    """Lines for ``graphmech check`` (without --json)."""
    lines = []
    for c in an.cases:
        lines.append(f"{c['label']:<24} " + case_formula(c))
    m = an.mobility
    if m is not None:
        lines.append(formula(m))
        if m.compound:
            lines.append(f"compound hinges: {', '.join(m.compound)}")
        if m.rollers:
            lines.append(f"local freedoms (rollers): {', '.join(m.rollers)}")
        if m.rank is not None:
            lines.append(f"constraint Jacobian: rank {m.rank} of {m.equations} equations (tolerance {m.tolerance:g} "
                         f"relative): F = 3·{m.n} − {m.rank} − {m.F_local} = {m.F_actual}, "
                         f"{m.p_redundant_actual} redundant")
    s = an.structure
    if s is not None:
        parts = [f"drivers {', '.join(s.drivers) or '—'} (class I)"]
        parts += [f"class {roman(g.grade)} group ({', '.join(g.links)})" for g in s.groups]
        lines.append(" + ".join(parts) + f": a class {roman(s.grade)} mechanism")
    return lines


__all__ = ["StructureAnalysis", "analyse_structure", "case_formula", "formula", "formula_text", "judge_structure",
           "text_summary"]
