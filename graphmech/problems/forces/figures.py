"""The figures of kinetostatics: loads on the mechanism, each Assur group's free body and force
polygon, Zhukovsky's lever — draw primitives on panels (the renderer knows nothing of forces).

* **Loads on the mechanism** (``forces``): the kinematic diagram at μl with every known load at its
  point — weights G, inertia forces F_i through S (thin) and their single resultant moved by h
  (bold), inertia moments M_i and the balancing moment M_b as curved arrows — and the friction
  circles ρ = f_v·r about the journals.
* **Free body and force polygon of each group** (``force_polygons``), the farthest group first:
  the group's links with every force on them (arrow lengths not to scale: the polygon gives the
  magnitudes), and beside it the polygon at μF — the known vectors head to tail (thin), the two
  closing lines (construction), the reactions found (bold), each vector labelled.
* **Zhukovsky's lever** (``lever``): the velocity polygon turned 90° about p, the loads at the
  image points of their points, and the balancing moment it gives.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Sequence

import numpy as np

from graphmech.mechanisms.linkage import RPP, RPR, RRP, Crank, Linkage
from graphmech.problems.linkage.figures import mechanism_items
from graphmech.methods.kinetostatics import (GroupPolygon, GuideReaction, KinetostaticSolution, Lever,
                                            PolygonKinematics)
from graphmech.drawing.primitives import (ArcArrow, Arrow, Circle, Hinge, Label, Panel, Primitive, Role, Segment,
                                         Sheet, Slider)

if TYPE_CHECKING:
    from graphmech.mechanisms.forces import ForceModel
    from graphmech.methods.linkage_construction import LinkageConstruction

#: Mechanism point (m, as a complex number) → drawing (mm).
ToMm = Callable[[complex], tuple[float, float]]

#: Longest and shortest arrow of a free body or of the loads on the mechanism, mm (not to scale).
ARROW_LONG, ARROW_SHORT = 16.0, 5.0
#: How far a polygon's closing line runs past the vertex it finds, mm.
CLOSING_OVERRUN = 8.0

_SUB = str.maketrans("0123456789irtnbf", "₀₁₂₃₄₅₆₇₈₉ᵢᵣₜₙbf")
_SUP = {"t": "ᵗ", "n": "ⁿ"}


def force_label(name: str) -> str:
    """A force's name as the book prints it: ``R^t_12`` → Rᵗ₁₂, ``F_i2`` → Fᵢ₂, ``P_r`` → Pᵣ.

    >>> force_label("R^t_12"), force_label("F_i2"), force_label("M_b")
    ('Rᵗ₁₂', 'Fᵢ₂', 'M_b')
    """
    sup = ""
    if "^" in name:
        head, _, rest = name.partition("^")
        sup_key, _, tail = rest.partition("_")
        sup, name = _SUP.get(sup_key, "^" + sup_key), head + "_" + tail
    head, sep, tail = name.partition("_")
    if not sep:
        return name + sup
    if all(c in "0123456789irtn" for c in tail):
        return head + sup + tail.translate(_SUB)
    return head + sup + "_" + tail


def _c(z: complex) -> tuple[float, float]:
    return (float(z.real), float(z.imag))


def _unit(z: complex) -> tuple[float, float]:
    m = abs(z)
    return (float(z.real / m), float(z.imag / m)) if m > 0 else (0.0, 0.0)


def _arrow_length(mag: float, largest: float) -> float:
    """Not to scale: a readable length that still grows with the force."""
    if largest <= 0 or mag <= 0:
        return 0.0
    return ARROW_SHORT + (ARROW_LONG - ARROW_SHORT) * math.sqrt(mag / largest)


def _arrows(forces: Sequence[tuple[str, complex, complex]], to_mm: ToMm, largest: float,
            role: Role = "result") -> list[Primitive]:
    """Arrows from each force's point of application along the force, labelled at the head."""
    items: list[Primitive] = []
    for name, vec, at in forces:
        length = _arrow_length(abs(vec), largest)
        if length == 0.0:
            continue
        p0 = to_mm(at)
        u = _unit(vec)
        p1 = (p0[0] + length * u[0], p0[1] + length * u[1])
        items.append(Arrow(p0, p1, role))
        items.append(Label(force_label(name), p1, ((-u[0], -u[1]),), 3.0))
    return items


def _moment_arc(at: tuple[float, float], moment: float, name: str, r: float = 5.0) -> list[Primitive]:
    if moment == 0.0:
        return []
    sweep = math.copysign(math.radians(120.0), moment)
    arc = ArcArrow(at, r, math.radians(30.0) - sweep / 2 + math.pi / 2, sweep, "result")
    end = arc.points(2)[2]
    return [arc, Label(force_label(name), end, (), 3.0)]


def loads_items(build: LinkageConstruction, kin: PolygonKinematics, sol: KinetostaticSolution, model: ForceModel,
                i: int) -> list[Primitive]:
    """The kinematic diagram with the known loads, inertia resultants, M_b and friction circles."""
    linkage: Linkage = build.linkage
    pos = {name: build.to_drawing(_c(complex(p[i]))) for name, p in kin.point.items()}
    items = mechanism_items(build, pos)

    def to_mm(z: complex) -> tuple[float, float]:
        return build.to_drawing(_c(z))

    loads: list[tuple[str, complex, complex]] = []
    shifted: list[tuple[str, complex, complex]] = []
    # A single resultant moved farther than the mechanism is wide is a couple in all but name
    # (a light link turning fast: h = |M_i/F_i| runs to kilometres): F_i and M_i stay at S.
    xs, ys = [p[0] for p in pos.values()], [p[1] for p in pos.values()]
    reach = 2.0 * max(max(xs) - min(xs), max(ys) - min(ys), ARROW_LONG) * build.mu_l
    for lm in model.masses:
        if lm.link == linkage.frame_link:
            continue
        at = complex(kin.point[lm.point][i])
        if model.gravity > 0 and lm.mass > 0:
            loads.append((f"G_{lm.link}", complex(0.0, -lm.mass * model.gravity), at))
        il = sol.inertia.get(lm.link)
        if il is not None and il.moment[i] != 0:
            items += _moment_arc(build.to_drawing(_c(at)), float(il.moment[i]), f"M_i{lm.link}", 4.0)
        if il is not None and abs(il.force[i]) > 0:
            if il.moment[i] != 0 and 0 < il.offset[i] <= reach:
                # F_i through S (thin), and its single resultant moved by h (bold)
                loads.append((f"F_i{lm.link}", complex(il.force[i]), at))
                shifted.append((f"F'_i{lm.link}", complex(il.force[i]), at + complex(il.resultant_shift[i])))
            else:
                loads.append((f"F_i{lm.link}", complex(il.force[i]), at))
    for pf in model.forces:
        vec = complex(*pf.vector)
        if pf.resistance and (np.conj(vec) * kin.vel[pf.point][i]).real >= 0:
            continue
        loads.append((pf.name, vec, complex(kin.point[pf.point][i])))
    largest = max([abs(v) for _, v, _ in loads + shifted], default=0.0)
    items += _arrows(loads, to_mm, largest, "given")
    for name, vec, at in shifted:
        length = _arrow_length(abs(vec), largest)
        p0 = to_mm(at)
        u = _unit(vec)
        items.append(Arrow(p0, (p0[0] + length * u[0], p0[1] + length * u[1]), "result"))
        items.append(Label(force_label(name.replace("'", "")) + "′", (p0[0] + length * u[0], p0[1] + length * u[1]),
                           ((-u[0], -u[1]),), 3.0))
        s = to_mm(at - complex(sol.inertia[name[-1]].resultant_shift[i]))
        items.append(Segment(s, p0, "construction", dashed=True))  # the offset h
    links = linkage.links()
    for c in model.couples:  # the scene's own moments on links (a resisting moment M_r …)
        items += _moment_arc(_middle(kin, links[c.link], i, to_mm), c.moment, c.name, 4.0)
    d = linkage.driver
    if isinstance(d, Crank):
        items += _moment_arc(pos[d.pivot], float(sol.balancing_moment[i]), "M_b", 9.0)
    elif sol.balancing_force is not None and float(sol.balancing_force[i]) != 0.0:
        f_b = float(sol.balancing_force[i]) * complex(math.cos(d.guide.angle), math.sin(d.guide.angle))
        items += _arrows([("F_b", f_b, complex(kin.point[d.point][i]))], to_mm, abs(f_b), "result")
    for fr in model.revolute_friction:
        if fr.rho > 0 and fr.point in pos:
            items.append(Circle(pos[fr.point], max(fr.rho / build.mu_l, 0.3), "construction"))
    return items


def free_body_items(build: LinkageConstruction, kin: PolygonKinematics, group: GroupPolygon, rho: dict[str, float],
                    joints: set[str], i: int, guides: Sequence[GuideReaction] = ()) -> list[Primitive]:
    """One group cut free: its links, hinges, slider, and every force on it (arrows not to scale).

    A guide's reaction is drawn on its line of action, unless that crosses the guide farther off
    than the group is wide (a small normal force with a moment): then at the slider's point with
    its moment M_ij about it, as the book draws a slider that bears on the ends of its guide."""
    linkage: Linkage = build.linkage
    pts = linkage.links()
    items: list[Primitive] = []

    def to_mm(z: complex) -> tuple[float, float]:
        return build.to_drawing(_c(z))

    drawn: set[str] = set()
    for link in group.links:
        names = pts[link]
        for a, b in zip(names, names[1:]):
            pa, pb = to_mm(complex(kin.point[a][i])), to_mm(complex(kin.point[b][i]))
            if math.dist(pa, pb) > 1e-9:
                items.append(Segment(pa, pb, "given"))
        drawn.update(names)
    for y in linkage.dyads:  # the blocks and slots of the group's sliding pairs
        if isinstance(y, RRP) and y.links[1] in group.links:
            items.append(Slider(to_mm(complex(kin.point[y.c][i])), y.guide.angle))
        elif isinstance(y, RPR) and y.block_link in group.links:
            x, p = complex(kin.point[y.block_pivot][i]), complex(kin.point[y.bar_pivot][i])
            items.append(Slider(to_mm(x), math.atan2((x - p).imag, (x - p).real)))
        elif isinstance(y, RPP) and y.links[0] in group.links:
            c, p = complex(kin.point[y.c][i]), complex(kin.point[y.p][i])
            items.append(Segment(to_mm(c), to_mm(p), "given"))  # the slot
            items.append(Slider(to_mm(p), y.slot_angle, 6.0, 4.0))
            items.append(Slider(to_mm(c), y.guide.angle))
    d = linkage.driver
    if not isinstance(d, Crank) and d.link in group.links:
        items.append(Slider(to_mm(complex(kin.point[d.point][i])), d.guide.angle))
    for name in sorted(drawn):
        if name in joints:
            items.append(Hinge(to_mm(complex(kin.point[name][i]))))
        if name in rho and rho[name] > 0:
            items.append(Circle(to_mm(complex(kin.point[name][i])), max(rho[name] / build.mu_l, 0.3)))
        items.append(Label(name, to_mm(complex(kin.point[name][i])), (), 3.0))
    # With friction a reaction is tangent to its friction circle: its line of action is moved off
    # the joint's centre so that its moment about it is the friction couple M_f.
    friction = {c.name: float(c.moment[i]) for c in group.couples if c.name.startswith("M_f")}
    seen = [to_mm(complex(kin.point[name][i])) for name in drawn]
    reach = 2.0 * max(max(p[0] for p in seen) - min(p[0] for p in seen),
                      max(p[1] for p in seen) - min(p[1] for p in seen), ARROW_LONG) * build.mu_l
    by_name = {g.name: g for g in guides}
    forces, guide_moments = [], []
    for f in group.free_body:
        vec, at = complex(f.vector[i]), complex(f.at[i])
        m = friction.get("M_f" + f.name[2:], 0.0) if f.name.startswith("R_") else 0.0
        if m != 0.0 and abs(vec) > 0:
            at = at - 1j * m * vec / abs(vec) ** 2
        g = by_name.get(f.name)
        if g is not None and abs(at - complex(kin.point[g.point][i])) > reach:
            at = complex(kin.point[g.point][i])
            guide_moments.append((f"M_{g.frame}{g.slider}", float(g.moment[i]), at))
        forces.append((f.name, vec, at))
    largest = max([abs(v) for _, v, _ in forces], default=0.0)
    items += _arrows(forces, to_mm, largest)
    for couple in group.couples:  # M_i, M_b and the scene's own couples; friction couples moved the reactions
        m = float(couple.moment[i])
        if m != 0 and couple.name not in friction:
            items += _moment_arc(_middle(kin, pts[couple.link or group.links[0]], i, to_mm), m, couple.name, 4.0)
    for name, m, at in guide_moments:
        items += _moment_arc(to_mm(at), m, name, 6.0)
    return items


def _middle(kin: PolygonKinematics, names: Sequence[str], i: int, to_mm: ToMm) -> tuple[float, float]:
    """Where a couple on a link is drawn: halfway between its first and last points."""
    return to_mm(complex(kin.point[names[0]][i] + kin.point[names[-1]][i]) / 2)


def polygon_items(group: GroupPolygon, mu_F: float, i: int) -> list[Primitive]:
    """The group's force polygon at μF: known vectors head to tail, closing lines, reactions found."""
    items: list[Primitive] = []
    vertex = 0j
    starts: list[complex] = []
    for name, vec in group.chain:
        v = complex(vec[i]) / mu_F
        starts.append(vertex)
        if abs(v) > 1e-9:
            role: Role = "result" if name in group.unknown else "given"
            end = vertex + v
            items.append(Arrow(_c(vertex), _c(end), role))
            mid = vertex + v / 2
            items.append(Label(force_label(name), _c(mid), (_unit(v), _unit(-v)), 3.0))
        vertex = vertex + v
    # The two closing lines: through the end of the known chain and through the start.
    k = len(group.chain)
    if len(group.unknown) == 2 and k >= 2:
        first, last = group.chain[-2], group.chain[-1]
        for (name, vec), s in ((first, starts[-2]), (last, starts[-1])):
            v = complex(vec[i]) / mu_F
            if abs(v) == 0:
                continue
            u = v / abs(v)
            a, b = s - CLOSING_OVERRUN * u, s + v + CLOSING_OVERRUN * u
            items.append(Segment(_c(a), _c(b), "construction"))
    items.append(Label("o", (0.0, 0.0), (), 3.0))
    return items


def lever_items(linkage: Linkage, kin: PolygonKinematics, lever: Lever, i: int) -> list[Primitive]:
    """Zhukovsky's lever: the turned velocity polygon, the loads at the images, the pole p."""
    items: list[Primitive] = []
    pts = linkage.links()
    images = {name: 1j * complex(v[i]) / kin.mu_v for name, v in kin.vel.items()}
    for link, names in pts.items():
        if link == linkage.frame_link:
            continue
        for a, b in zip(names, names[1:]):
            if a in images and b in images and abs(images[a] - images[b]) > 1e-9:
                items.append(Segment(_c(images[a]), _c(images[b]), "given"))
    for name, z in images.items():
        if abs(z) > 1e-9 and name not in linkage.frame_points:
            items.append(Segment((0.0, 0.0), _c(z), "construction"))
            items.append(Label(name.lower(), _c(z), (_unit(-z),), 3.0))
    arms = [(name, complex(f[i]), complex(at[i])) for name, at, f in lever.arms]
    largest = max([abs(v) for _, v, _ in arms], default=0.0)
    items += _arrows(arms, lambda z: _c(z), largest)
    items.append(Label("p", (0.0, 0.0), (), 3.2))
    return items


def force_sheet(title: str, build: LinkageConstruction, kin: PolygonKinematics, sol: KinetostaticSolution, model: ForceModel,
                lever: Lever | None, mu_F: float, show: Sequence[str], i: int, position: str,
                page: tuple[float, float], head: Sequence[Panel] = (), footer: tuple[str, ...] = ()) -> Sheet:
    """The force sheet of one position: the panels of ``show`` after the kinematic ``head`` panels."""
    panels: list[Panel] = list(head)
    mu_l = build.mu_l
    if "forces" in show:
        notes: tuple[str, ...] = (f"μl = {mu_l:.6g} m/mm", "loads: arrows not to scale")
        if any(fr.rho > 0 for fr in model.revolute_friction):
            notes += ("friction circles ρ = f_v·r at μl",)
        panels.append(Panel("forces", f"Loads and inertia forces, {position}",
                            tuple(loads_items(build, kin, sol, model, i)), notes))
    if "force_polygons" in show:
        rho = {fr.point: fr.rho for fr in model.revolute_friction}
        joints = {j.point for j in sol.joints}
        for g in sol.groups:
            key = "-".join(g.links)
            notes = ("arrows not to scale",) + (
                (f"friction circles at μl = {mu_l:.6g} m/mm; reactions tangent to them",) if rho else ())
            panels.append(Panel(f"free-{key}", f"Free body, {g.name}",
                                tuple(free_body_items(build, kin, g, rho, joints, i, sol.guides)), notes))
            panels.append(Panel(f"polygon-{key}", f"Force polygon, {g.name}", tuple(polygon_items(g, mu_F, i)),
                                (f"μF = {mu_F:.6g} N/mm",)))
    if "lever" in show and lever is not None:
        # the lever knows no friction: with friction it gives the frictionless M_b0 (F_b0)
        bare, note = ("0", " (without friction)") if model.has_friction else ("", "")
        if lever.balancing_force is not None:
            result = f"F_b{bare} = μv·ΣM_p/v = {float(lever.balancing_force[i]):.6g} N{note}"
        else:
            result = f"M_b{bare} = μv·ΣM_p/ω1 = {float(lever.balancing_moment[i]):.6g} N·m{note}"
        panels.append(Panel("lever", "Zhukovsky's lever (velocity polygon turned 90°)",
                            tuple(lever_items(build.linkage, kin, lever, i)),
                            (f"μv = {kin.mu_v:.6g} (m/s)/mm", result)))
    return Sheet(title, tuple(panels), page, footer)


__all__ = ["force_sheet", "force_label", "loads_items", "free_body_items", "polygon_items", "lever_items"]
