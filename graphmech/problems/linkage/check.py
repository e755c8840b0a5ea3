"""From a scene to checked values: choose μ, build and prune the construction, evaluate it at
every position, measure, compare with the independent exact solution, judge hand measurements.

Like every kind's check (and the scene readers, and ``cli``) it knows about users: it turns
problems into :class:`~graphmech.errors.SceneError` with key paths, and conditioning into
warnings.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any, cast

import numpy as np

from graphmech import tolerances as T
from graphmech.errors import DegenerateConstruction, OutOfDomain, SceneError
from graphmech.exact.linkage import Kinematics, solve as solve_exact
from graphmech.mechanisms.linkage import Linkage, Triad
from graphmech.geometry.primitives import degrees_0_360
from graphmech.methods.linkage_construction import ACCELERATION_POLE, VELOCITY_POLE
from graphmech.methods.polygons import PANELS, LinkageConstruction, build_polygons
from graphmech.scales import drawn_size_problem, format_scale, round_scale
from graphmech.problems.instant_centres import check as ic_check
from graphmech.problems.linkage.higher_pair import add_rows as hp_rows, claims as hp_claims, pairs_of
from graphmech.problems.judging import (
    OUT_OF_RANGE,
    Row,
    SEGMENT,
    Verdict,
    close_names,
    conditioning_warning,
    in_double_precision,
    is_segment,
    measured_entries,
    split_name,
)
from graphmech.problems.linkage.sizes import (
    characteristic,
    mechanism_size,
    offset_warning,
    position_text,
    refuse_far_from_origin,
)
from graphmech.problems.reader import linkage_of, page_size, positions_of

if TYPE_CHECKING:
    from graphmech.construction.graph import Solution
    from graphmech.methods.quantities import Exact
    from graphmech.problems.reader import Scene

SCALE_KEYS = {"mechanism": "l", "velocity": "v", "acceleration": "a"}
_PANEL_WORDS = {"mechanism": "the mechanism", "velocity": "the velocity polygon", "acceleration": "the acceleration polygon"}

#: The smallest drawing a panel may get, mm; a sheet whose positions leave less is refused.
MIN_PANEL_MM = 25.0

#: A vector a student measures should be at least this long (FIGURES.md: the reading error ±0.5 mm
#: is then at most 5 %); a shorter one is named in a warning with its reading error.
SHORTEST_VECTOR_MM = 10.0
#: The reading error of a length measured on the drawing, mm.
READING_MM = 0.5
#: A vector whose exact value is below this fraction of the mechanism's typical value is a zero
#: (a velocity at a dead centre): a point of the polygon, not a vector to measure.
ZERO_VECTOR = 1e-9


def rows_that_fit(page: tuple[float, float]) -> int:
    """How many positions (one row of panels each) one sheet of this size can hold."""
    return max(1, int((page[1] - 38.0) // (MIN_PANEL_MM + 35.0)))


# ---------------------------------------------------------------------------- results


@dataclass
class Analysis:
    """Everything one scene produced: the construction, its solutions, the exact solution."""

    scene: Scene[object]
    build: LinkageConstruction
    plan: Any
    scales: dict[str, float]
    stated: set[str]  # which μ the scene stated (the others were chosen)
    positions: np.ndarray
    labels: tuple[str, ...]
    solutions: list[Solution | None]  # per position: None where it failed
    failures: list[str]  # per position: "" or the reason
    exact: Kinematics
    warnings: list[str] = field(default_factory=list)
    rows: list[Row] = field(default_factory=list)
    extra_measured: tuple[tuple[str, float], ...] = ()
    size: float = 1.0  # the mechanism's typical length, m
    dependencies: dict[str, set[str]] = field(default_factory=dict)  # step → the steps it needs (cache)
    instant_centres: Any = None  # graphmech.problems.instant_centres.check.ICAnalysis when the scene asks for instant centres

    def scale_notes(self) -> list[str]:
        """μ as written on the drawing, marked where graphmech chose it."""
        return [format_scale(k, v) + ("" if k in self.stated else " (chosen)") for k, v in self.scales.items()]


# ---------------------------------------------------------------------------- names


def _requested(scene: Scene[object], build: LinkageConstruction, labels: tuple[str, ...]) -> list[tuple[str, str, int]]:
    """(display name, quantity name, position index) for every ``find`` entry; bad names → SceneError."""
    problems = []
    out = []
    multi = len(labels) > 1
    for k, raw in enumerate(scene.find):
        base, at = split_name(raw)
        if ic_check.claims(raw):  # the instant-centre method's names (graphmech.problems.instant_centres.check)
            continue
        if hp_claims(raw):  # a higher pair's names (graphmech.problems.linkage.higher_pair)
            continue
        if base not in build.quantities:
            close = close_names(base, build.quantities)
            if base.startswith(("gamma_", "pressure_angle_")):  # a joint with no transmission angle
                here = sorted(n for n in build.quantities if n.startswith(base.rpartition("_")[0] + "_"))
                close = (": γ and α are found at the output joint of a dyad whose output turns about a frame "
                         "pivot or slides on a frame guide" + (f" (here: {', '.join(here)})" if here else
                                                               " (this linkage has none)"))
            problems.append((f"find[{k}]", f"unknown quantity {base!r}{close}"))
            continue
        idx: range | list[int]
        if at is None:
            idx = range(len(labels))
        elif at in labels:
            idx = [labels.index(at)]
        else:
            problems.append((f"find[{k}]", f"no position {at!r} (positions: {', '.join(labels)})"))
            continue
        for i in idx:
            out.append((f"{base}@{labels[i]}" if multi else base, base, i))
    if problems:
        raise SceneError(problems, scene.source)
    return out


# ---------------------------------------------------------------------------- scales


def choose_scales(scene: Scene[object], linkage: Linkage, positions: np.ndarray) -> tuple[dict[str, float], set[str]]:
    """μ from the scene where stated; otherwise the round value that fits the panel on the page.

    That is the finest round μ the panel's room allows, so where it still draws a vector the
    scene asks for shorter than :data:`SHORTEST_VECTOR_MM`, only a larger page helps:
    :func:`short_vector_warnings` names it.

    The construction is linear in 1/μ, so one provisional evaluation at μ = 1 gives every
    panel's extent in real units; each μ is then the smallest round number that fits that
    extent into the room one panel has (the panels stand side by side, one row per position).
    """
    stated: set[str] = {k for k in ("l", "v", "a") if k in scene.scales}
    scales: dict[str, float] = {k: float(scene.scales[k]) for k in ("l", "v", "a") if k in stated}
    provisional = {k: scales.get(k, 1.0) for k in ("l", "v", "a")}
    b = build_polygons(linkage, provisional)
    steps = [s for s in b.g.steps.values() if s.kind == "point"]
    plan = b.g.prune([s.name for s in steps])
    sol = plan.evaluate_batch({b.param: positions})
    w, h = page_size(scene)
    shown = [p for p in PANELS if p in scene.show] or ["mechanism"]
    # Room for one panel's drawing: the page less margins (10), title (12) and footer (6); one
    # row of panels per position, each row less its gap (12), caption (11) and labels (2 × 6).
    rows = max(1, len(positions))
    room_w = (w - 20.0 - 12.0 * (len(shown) - 1)) / len(shown) - 12.0
    room_h = max((h - 38.0) / rows - 35.0, MIN_PANEL_MM)
    for panel, key in SCALE_KEYS.items():
        xs, ys = [], []
        for s in steps:
            if s.panel != panel:
                continue
            x, y = sol.values[s.name]
            xs.append(np.broadcast_to(x, sol.valid.shape)[sol.valid])
            ys.append(np.broadcast_to(y, sol.valid.shape)[sol.valid])
        if not xs or not any(a.size for a in xs):
            scales.setdefault(key, 1.0)  # nothing drawn at this μ: a stated one stays as stated
            continue
        xa, ya = np.concatenate(xs), np.concatenate(ys)
        ext_x = (xa.max() - xa.min()) * provisional[key]
        ext_y = (ya.max() - ya.min()) * provisional[key]
        if key in stated:  # drawn as stated, if a page can hold it legibly (a polygon of 0 is a point)
            size = max(ext_x, ext_y)
            why = size > 0 and drawn_size_problem(size, scales[key], key, _PANEL_WORDS[panel])
            if why:
                raise SceneError([("scales", why)], scene.source)
            continue
        need = max(ext_x / room_w, ext_y / room_h)
        if not math.isfinite(need):  # a link of 1e300 m: the figure's extent overflows
            raise DegenerateConstruction("the construction", OUT_OF_RANGE)
        scales[key] = round_scale(need) if need > 0 else 1.0
    return {k: scales[k] for k in ("l", "v", "a")}, stated


def short_vector_warnings(an: Analysis) -> list[str]:
    """The polygons' vectors the scene asks for that are drawn shorter than
    :data:`SHORTEST_VECTOR_MM` (read to ±0.5 mm, their error is more than 5 %), at a stated μ
    or at the finest one the page allows. A zero (a velocity at a dead centre) is a point, not
    a vector."""
    out = []
    for r in an.rows:
        q = an.build.quantities.get(split_name(r.name)[0])
        if q is None or q.panel not in ("velocity", "acceleration") or r.drawn_mm is None:
            continue
        drawn = abs(r.drawn_mm)
        if drawn >= SHORTEST_VECTOR_MM or abs(r.exact) <= ZERO_VECTOR * characteristic(an.build.linkage, q.unit, an.size):
            continue
        key = SCALE_KEYS[q.panel]
        out.append(f"{r.name} is drawn {drawn:.3g} mm long at {format_scale(key, an.scales[key])}, under "
                   f"{SHORTEST_VECTOR_MM:g} mm: read to ±{READING_MM:g} mm it is ±{100.0 * READING_MM / drawn:.2g} % "
                   f"(a smaller μ{key} or a larger page makes it longer)")
    return out


# ---------------------------------------------------------------------------- analysis


def analyse(scene: Scene[object], extra_measured: tuple[tuple[str, float], ...] = ()) -> Analysis:
    """Build, prune, evaluate and check one scene (``extra_measured``: values from the command line).

    Numbers beyond double precision (an ω of 1e155 rad/s squared) are a one-line
    :class:`DegenerateConstruction`, never a traceback, an inf or a NaN.
    """
    with in_double_precision("the construction"):
        return _analyse(scene, extra_measured)


def _analyse(scene: Scene[object], extra_measured: tuple[tuple[str, float], ...]) -> Analysis:
    linkage = linkage_of(scene)
    refuse_far_from_origin(scene, linkage, mechanism_size(linkage))
    positions = np.asarray(positions_of(scene).values, dtype=float)
    labels = tuple(positions_of(scene).labels) or tuple(f"{v:g}" for v in positions)
    i: int | np.intp
    sol: Solution | None
    scales, stated = choose_scales(scene, linkage, positions)
    build = build_polygons(linkage, scales)
    wanted = _requested(scene, build, labels)
    measured_q = _measured_quantities(measured_entries(scene, extra_measured), build, labels)
    targets = [build.quantities[q].slot for _, q, _ in wanted] + [build.quantities[q].slot for q in measured_q]
    for panel in PANELS:
        if panel in scene.show:
            targets += build.steps_of_panel(panel)
    ic = ic_check.asked(scene, extra_measured)
    if ic:  # the instant centres are found on the kinematic diagram: every point of it
        targets += list(build.mech.values())
    if pairs_of(scene):  # a higher pair's contact and normal are found on the kinematic diagram too
        targets += list(build.mech.values())
    plan = build.g.prune(targets)

    solutions: list[Any] = []
    failures: list[str] = []
    if len(positions) == 1:
        where = position_text(build, labels[0])
        try:  # one position asked for: if it cannot be built, the caller reports why
            sol = plan.solve({build.param: float(positions[0])}, where)
        except (OverflowError, ZeroDivisionError) as e:
            raise DegenerateConstruction("the construction", f"numbers out of range ({e})", where) from None
        if not _finite(sol.values):
            raise DegenerateConstruction("the construction", OUT_OF_RANGE, where)
        solutions.append(sol)
        failures.append("")
    else:
        batch = plan.evaluate_batch({build.param: positions})
        reason = [""] * len(positions)
        for step, (mask, why) in batch.failures.items():
            for i in np.flatnonzero(mask):
                reason[i] = f"{step}: {why}"
        for i in range(len(positions)):
            sol = batch.at(i) if batch.valid[i] else None
            if sol is not None and not _finite(sol.values):
                sol, reason[i] = None, OUT_OF_RANGE
            solutions.append(sol)
            failures.append(reason[i])
    exact = solve_exact(linkage, positions)
    other = _other_assembly(build, solutions, exact)
    if other and len(positions) == 1:
        raise DegenerateConstruction("the class III group", other[0], position_text(build, labels[0]))
    if other:  # not compared: the two would be different mechanisms
        valid = exact.valid.copy()
        valid[list(other)] = False
        exact = replace(exact, valid=valid)
    an = Analysis(scene, build, plan, scales, stated, positions, labels, solutions, failures, exact)
    an.extra_measured = tuple(extra_measured)
    an.size = mechanism_size(linkage, exact)
    far = offset_warning(linkage, an.size)
    if far:
        an.warnings.append(far)
    for i, why in enumerate(failures):
        if why:
            an.warnings.append(f"{position_text(build, labels[i])}: construction impossible — {why}")
    for i, why in other.items():
        an.warnings.append(f"{position_text(build, labels[i])}: {why}; its values are not checked")
    for i, ok in enumerate(exact.valid):
        if not ok and solutions[i] is not None and i not in other:
            an.warnings.append(f"{position_text(build, labels[i])}: the exact solution is undefined here "
                               f"({exact.reason[i]}); its values are not checked")
    wanted = [(display, q, i) for display, q, i in wanted if solutions[i] is not None and exact.valid[i]]
    nowhere = {(q, i): no_dir for _, q, i in wanted if (no_dir := undefined_direction(an, q, i))}
    if nowhere and len(positions) == 1:  # the one position asked for: refused at its find entry
        q0 = next(iter(nowhere))[0]
        k = next(k for k, raw in enumerate(scene.find) if split_name(raw)[0] == q0)
        raise SceneError([(f"find[{k}]", next(iter(nowhere.values())))], scene.source)
    an.warnings.extend(dict.fromkeys(nowhere.values()))
    an.rows = [_row(an, display, q, i) for display, q, i in wanted if (q, i) not in nowhere]
    if far:
        an.rows = [replace(r, ill_conditioned=True) for r in an.rows]
    an.warnings.extend(_conditioning_warnings(an, [q for _, q, _ in wanted] + measured_q))
    an.warnings.extend(short_vector_warnings(an))
    if ic:
        an.instant_centres = ic_check.add_rows(an)
    if pairs_of(scene):  # the higher pairs' rows (issue 22 item 4)
        hp_rows(an)
    return an


def _other_assembly(build: LinkageConstruction, solutions: list[Any], exact: Kinematics) -> dict[int, str]:
    """Positions where a class III group's construction (Newton's method from ``start``) reached
    another assembly than the exact solution (the one nearest ``start``), and why: far from the
    start the two rules may part, and then they describe two different mechanisms."""
    out: dict[int, str] = {}
    for y in build.linkage.dyads:
        if not isinstance(y, Triad):
            continue
        tol = T.COINCIDENT_REL ** 0.5 * (sum(y.lengths) + sum(y.ternary)) / build.mu_l  # drawing mm
        for i, sol in enumerate(solutions):
            if sol is None or not exact.valid[i] or i in out:
                continue
            if any(math.dist(sol[build.mech[P]], build.to_drawing(tuple(exact.point[P][i]))) > tol for P in y.inner):
                out[i] = (f"Newton's method from the start reached another assembly of the class III group {y.name} "
                          "than the one nearest the start (give start near the group at this position)")
    return out


def _finite(values: Any) -> bool:
    """Whether every number in a solution's values is finite."""
    for v in values.values():
        for x in (v if isinstance(v, tuple) else (v,)):
            if isinstance(x, float) and not math.isfinite(x):
                return False
    return True


def _row(an: Analysis, display: str, qname: str, i: int) -> Row:
    q = an.build.quantities[qname]
    drawn, scale = cast("Solution", an.solutions[i])[q.slot]  # a row is made only where it was constructed
    drawn, scale = float(drawn), float(scale)
    g = drawn * scale
    e = exact_value(an.exact, q.exact, i)
    if not (math.isfinite(g) and math.isfinite(e)):
        raise DegenerateConstruction(f"measure {qname}", OUT_OF_RANGE, position_text(an.build, an.labels[i]))
    if q.unit == "deg":
        err = abs((g - e + 180.0) % 360.0 - 180.0) / 360.0
        drawn_mm = None
    else:
        err = abs(g - e) / max(abs(e), characteristic(an.build.linkage, q.unit, an.size))
        drawn_mm = drawn
    return Row(display, q.unit, drawn_mm, scale, g, e, err, _ill(an, q.slot, i))


# ---------------------------------------------------------------------------- exact values


def exact_value(kin: Kinematics, spec: Exact, i: int) -> float:
    """The exact value that a quantity's ``exact`` description names, at position i."""
    kind = spec[0]
    P, V, A = kin.point, kin.vel, kin.acc
    if kind == "speed":
        return float(np.hypot(*V[spec[1]][i]))
    if kind == "acc":
        return float(np.hypot(*A[spec[1]][i]))
    if kind in ("slide_v", "slide_a"):
        vec = (V if kind == "slide_v" else A)[spec[1]][i]
        return float(vec[0] * spec[2] + vec[1] * spec[3])
    if kind == "rel_v":
        return float(np.hypot(*(V[spec[1]][i] - V[spec[2]][i])))
    if kind == "rel_a":
        return float(np.hypot(*(A[spec[1]][i] - A[spec[2]][i])))
    if kind == "length":
        return float(np.hypot(*(P[spec[1]][i] - P[spec[2]][i])))
    if kind == "normal":
        _, x, y, link = spec
        return float(kin.omega[link][i] ** 2 * np.hypot(*(P[x][i] - P[y][i])))
    if kind == "tangential":
        _, x, y, link = spec
        return float(abs(kin.alpha[link][i]) * np.hypot(*(P[x][i] - P[y][i])))
    if kind == "omega":
        return float(kin.omega[spec[1]][i])
    if kind == "alpha":
        return float(kin.alpha[spec[1]][i])
    if kind == "angle":
        return degrees_0_360(float(kin.angle[spec[1]][i]))
    if kind in ("dir_v", "dir_a"):
        vec = (V if kind == "dir_v" else A)[spec[1]][i]
        return degrees_0_360(math.atan2(float(vec[1]), float(vec[0])))
    if kind in ("gamma", "pressure"):
        g = _gamma_exact(kin, spec[1:], i)
        return g if kind == "gamma" else 90.0 - g
    if kind in ("coriolis", "rel_slide_a"):
        _, x, y, link = spec
        vr = V[x][i] - V[y][i]
        k = 2.0 * kin.omega[link][i] * np.array([-vr[1], vr[0]])
        if kind == "coriolis":
            return float(np.hypot(*k))
        return float(np.hypot(*(A[x][i] - A[y][i] - k)))
    raise ValueError(f"unknown exact quantity {spec!r}")


def _line_angle(u: Any, v: Any) -> float:
    """The acute angle between two lines, degrees."""
    return math.degrees(math.atan2(abs(float(u[0] * v[1] - u[1] * v[0])), abs(float(u[0] * v[0] + u[1] * v[1]))))


def _gamma_exact(kin: Kinematics, spec: tuple[Any, ...], i: int) -> float:
    """γ at an output joint from the exact positions (see :func:`graphmech.methods.measure.transmission`)."""
    P = kin.point
    if spec[0] == "bar":  # a guide bar: pushed across its line, X turning about its pivot
        _, x, pivot, link = spec
        th = float(kin.angle[link][i])
        return 90.0 - _line_angle(P[pivot][i] - P[x][i], (math.cos(th), math.sin(th)))
    x, pusher, along = spec
    arm = P[pusher][i] - P[x][i]
    if isinstance(along, str):  # a rocker about ``along``
        return _line_angle(arm, P[along][i] - P[x][i])
    return 90.0 - _line_angle(arm, along)  # a slider on a fixed guide


def undefined_direction(an: Analysis, qname: str, i: int) -> str | None:
    """Why a direction (dir_v_X, dir_a_X) is not defined at position i: the vector is zero."""
    q = an.build.quantities[qname]
    if q.exact[0] not in ("dir_v", "dir_a"):
        return None
    table, unit, what = (an.exact.vel, "m/s", "v") if q.exact[0] == "dir_v" else (an.exact.acc, "m/s²", "a")
    size = float(np.hypot(*table[q.exact[1]][i]))
    if size > ZERO_VECTOR * characteristic(an.build.linkage, unit, an.size):
        return None
    return (f"{position_text(an.build, an.labels[i])}: {what}_{q.exact[1]} = 0 here, so {qname} has no "
            "direction")


# ---------------------------------------------------------------------------- conditioning


def _deps(an: Analysis, slot: str) -> set[str]:
    if slot not in an.dependencies:
        an.dependencies[slot] = an.build.g.dependencies([slot])
    return an.dependencies[slot]


def _ill(an: Analysis, slot: str, i: int) -> bool:
    sol = cast("Solution", an.solutions[i])
    texts = {an.plan.by_name[n].text for n in _deps(an, slot) if n in an.plan.by_name}
    return any(c > T.COND_WARN for t, c in sol.conds.items() if t in texts)


def _conditioning_warnings(an: Analysis, quantities: list[str]) -> list[str]:
    """Name every intersection that is ill-conditioned (numerically) or shallow (for drafting)."""
    out = []
    relevant: dict[str, list[str]] = {}
    for q in dict.fromkeys(quantities):
        slot = an.build.quantities[q].slot
        for n in _deps(an, slot):
            if n in an.plan.by_name:
                relevant.setdefault(an.plan.by_name[n].text, []).append(q)
    for s in an.plan.steps:
        if s.kind == "point" and s.panel in an.scene.show:
            relevant.setdefault(s.text, [])
    for i, sol in enumerate(an.solutions):
        if sol is None:
            continue
        where = position_text(an.build, an.labels[i])
        for text, c in sol.conds.items():
            if text not in relevant:
                continue
            _, said = conditioning_warning(where, text, c, ", ".join(relevant[text]))
            if said:
                out.append(said)
    return out


# ---------------------------------------------------------------------------- hand measurements


def _measured_quantities(entries: list[tuple[str, str, float]], build: LinkageConstruction,
                         labels: tuple[str, ...]) -> list[str]:
    out = []
    for key, name, _ in entries:
        try:
            q, _, _ = _resolve(name, build, labels)
        except ValueError:
            continue  # reported by judge()
        out.append(q)
    return out


def _resolve(name: str, build: LinkageConstruction, labels: tuple[str, ...]) -> tuple[str, int, bool]:
    """A measured name → (quantity name, position index, is a drawn segment)."""
    base, at = split_name(name)
    if at is not None and at not in labels:
        raise OutOfDomain(f"no position {at!r} (positions: {', '.join(labels)})")
    idx = labels.index(at) if at is not None else (0 if len(labels) == 1 else None)
    if idx is None:
        raise OutOfDomain(f"the scene has {len(labels)} positions: name one, e.g. {base}@{labels[0]}")
    if base in build.quantities:
        return base, idx, False
    if not is_segment(base):
        raise OutOfDomain(f"unknown quantity or segment {base!r}{close_names(base, build.quantities)}")
    t0, t1 = [t.replace("′", "'") for t in SEGMENT.findall(base)]
    if t0 == t1:
        raise OutOfDomain(f"a drawn segment needs two different ends, not {base!r}")

    def matches(token: str, lab: str) -> bool:
        if token == lab:
            return True
        # "n'" stands for any n₂′, n₃′ … when only one of them fits the other end
        return len(token.rstrip("'")) == 1 and lab[:1] == token[:1] and lab.rstrip("'")[1:].isdigit() \
            and lab.count("'") == token.count("'")

    found = [q.name for q in build.quantities.values() if len(q.segment) == 2 and (
        (matches(t0, q.segment[0]) and matches(t1, q.segment[1])) or
        (matches(t0, q.segment[1]) and matches(t1, q.segment[0])))]
    # Prefer plain lengths (v_X, a_X, components) over ω/α, which share the segment.
    found = sorted(found, key=lambda n: (n.startswith(("omega", "alpha")), n))
    if not found:
        raise OutOfDomain(f"no drawn segment {base!r} in this construction")
    # One drawn segment per pair of end steps, whichever way round it was named: the letters
    # alone may name two (the pole p and the image p of a point P).
    ends: dict[frozenset[str], str] = {}
    for n in found:
        ends.setdefault(frozenset(build.g.steps[build.quantities[n].slot].inputs[-2:]), n)
    if len(ends) > 1:
        segments = sorted({"".join(sorted(build.quantities[n].segment)) for n in ends.values()})
        if len(segments) == len(ends):
            segments = sorted("".join(build.quantities[n].segment) for n in ends.values())
            raise OutOfDomain(f"{base!r} could be any of {', '.join(segments)}: name the segment exactly")
        raise OutOfDomain(f"{base!r} could be any of {', '.join(sorted(ends.values()))}: write one of these instead of {base}")
    return found[0], idx, True


def _angle_tolerance(an: Analysis, q: Any, sol: Any, precision_mm: float) -> float:
    """An angle read with a protractor: ±precision/length of the shorter drawn arm, in degrees —
    a link's direction along the link, a vector's along the vector, γ and α along the coupler
    (and the rocker)."""
    b = an.build
    kind = q.exact[0]
    if kind in ("dir_v", "dir_a"):
        pole, table = (VELOCITY_POLE, b.vel) if kind == "dir_v" else (ACCELERATION_POLE, b.acc)
        arms = [(pole, table[q.exact[1]])]
    elif kind in ("gamma", "pressure"):
        x, pusher, along = q.exact[2:5] if q.exact[1] == "bar" else q.exact[1:4]
        arms = [(b.mech[x], b.mech[pusher])] + ([(b.mech[x], b.mech[along])] if isinstance(along, str)
                                                  and q.exact[1] != "bar" else [])
    else:
        u, v = b.link_points[q.exact[1]][:2]
        arms = [(b.mech[u], b.mech[v])]
    length = min(math.dist(sol[s], sol[e]) for s, e in arms)
    return math.degrees(precision_mm / max(length, precision_mm))


def judge(an: Analysis, precision_mm: float | None = None) -> list[Verdict]:
    """Verdicts for the scene's ``[measured]`` values (and any given on the command line)."""
    scene = an.scene
    prec = precision_mm if precision_mm is not None else scene.precision_mm
    problems = []
    out = []
    for key, name, value in measured_entries(scene, an.extra_measured):
        if ic_check.claims(name):  # judged by graphmech.problems.instant_centres.check, below
            continue
        if hp_claims(name):  # a higher pair's values (graphmech.problems.linkage.higher_pair)
            problems.append((key, f"{split_name(name)[0]} is found (find = [...]), not judged from a measured value yet"))
            continue
        try:
            qname, i, segment = _resolve(name, an.build, an.labels)
        except ValueError as e:
            problems.append((key, str(e)))
            continue
        q = an.build.quantities[qname]
        sol = an.solutions[i]
        if sol is None:
            problems.append((key, f"position {an.labels[i]} could not be constructed"))
            continue
        if not an.exact.valid[i]:
            problems.append((key, f"the exact value is undefined at {position_text(an.build, an.labels[i])} "
                                  f"({an.exact.reason[i]}), so it cannot be judged"))
            continue
        drawn, scale = sol[q.slot]
        exact_v = exact_value(an.exact, q.exact, i)
        panel_key = SCALE_KEYS[q.panel]
        if segment:
            if panel_key not in an.stated:
                problems.append((key, f"the scene does not state μ{panel_key}, so a drawn length cannot be judged: "
                                      f"state it in [scales] or give the value ({qname}) instead"))
                continue
            expected = abs(exact_v) / float(scale)
            out.append(Verdict(name, value, expected, prec, abs(abs(value) - expected) <= prec, "mm"))
        else:
            why = undefined_direction(an, qname, i)
            if why:
                problems.append((key, f"{why}, so it cannot be judged"))
                continue
            if q.unit == "deg":  # a direction read as 359.8° is 0.4° from 0.2°
                tol = _angle_tolerance(an, q, sol, prec)
                off = abs((value - exact_v + 180.0) % 360.0 - 180.0)
            else:
                tol, off = prec * abs(float(scale)), abs(value - exact_v)
            out.append(Verdict(name, value, exact_v, tol, off <= tol + 1e-12 * abs(exact_v), q.unit))
    if an.instant_centres is not None:
        more, trouble = ic_check.judge(an, prec)
        out += more
        problems += trouble
    if problems:
        raise SceneError(problems, scene.source)
    return out
