"""Checking a gear scene: the constructions (the involute by points, the line of action cut by the
tip circles, the caliper over k teeth, the pins) against the closed forms.

Every row is a length or an angle measured on a construction of :mod:`graphmech.methods.involute`
or :mod:`graphmech.methods.gear_meshing` — divided by its panel's μl it is the drawn length — set
against :mod:`graphmech.exact.gear` (inv α, ε from the tip pressure angles, W_k, M). Only what the
scene's ``find`` (or ``[measured]``) names is constructed.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from graphmech.errors import (
    GraphmechError,
    NoSolution,
    NotApplicable,
    OutOfDomain,
    SceneError,
)
from graphmech.exact import gear as ex
from graphmech.exact import profile_shift as exs
from graphmech.geometry.kernels import ScalarOps, intersect_lines
from graphmech.mechanisms.gear import GearSet, SpurGear
from graphmech.methods import gear_meshing as gmesh
from graphmech.methods import involute as inv
from graphmech.methods import profile_shift as shift
from graphmech.problems.gears import generation as gen
from graphmech.problems.gears.scene import (
    AT_RADIUS,
    GEAR_SHOW_CHOICES,
    PAIR_QUANTITIES,
    TOOTH_QUANTITIES,
    GearScene,
    quantity_unit,
)
from graphmech.problems.judging import (
    Row,
    Verdict,
    in_double_precision,
    judge_value,
    measured_entries,
)
from graphmech.problems.reader import page_size
from graphmech.scales import drawn_size_problem, format_scale, round_scale
from graphmech.tolerances import COINCIDENT_REL

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene

#: The page's parts, mm: the title above the panels, the notes under each, the side margins.
TITLE_MM, CAPTION_MM, SIDE_MM = 38.0, 40.0, 40.0
#: Three teeth take up to this share of a row's width (the construction's strings run beside them).
TOOTH_SHARE = 0.9
#: On the meshing panel B₁B₂ is drawn at least this long; a pair too large for that is drawn
#: around the line of action (the circles as arcs).
MESH_B1B2_MM = 5.0
#: The book's least tip thickness, as a multiple of m (s_a ≥ 0.25m … 0.4m).
SA_MIN = 0.25

#: Default finds: one gear, a pair.
DEFAULT_TOOTH = ("d", "db", "da", "df", "s_pitch", "sa", "alpha_a", "rho_pitch", "rho_a")
DEFAULT_PAIR = ("a_w", "alpha_w", "alpha_a1", "alpha_a2", "B1B2", "pb", "eps_alpha")


@dataclass
class GearAnalysis:
    """What one gear scene produced: the constructions it needed, rows, warnings, scales."""

    scene: Scene[GearScene]
    problem: GearScene
    names: list[str] = field(default_factory=list)
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    stated: set[str] = field(default_factory=set)
    extra_measured: tuple[tuple[str, float], ...] = ()
    panels: tuple[str, ...] = ()
    #: whether the rows carry their own error estimates (the check's); a figure needs none, and
    #: a generation's costs two more cuttings of the blank
    estimates: bool = True
    # the constructions, by gear label ("" for one gear, "1", "2" in a pair), made when first asked
    radii: dict[tuple[str, float], inv.AtRadius] = field(default_factory=dict)
    pointed: dict[str, inv.AtRadius] = field(default_factory=dict)
    spans: dict[str, inv.SpanMeasurement] = field(default_factory=dict)
    pins: dict[str, inv.PinMeasurement] = field(default_factory=dict)
    mesh: gmesh.MeshConstruction | None = None
    exact_mesh: Any = None
    root_base: tuple[float, float] | None = None
    mesh_whole: bool = True
    shift_sum: float | None = None
    generation: gen.GenerationAnalysis | None = None  # [gear.generation] (problems/gears/generation.py)

    def scale_notes(self) -> list[str]:
        words = {"l": "", "tooth": "tooth, ", "zones": "contact zones, ", "generation": "generation, "}
        return [format_scale(k, v) + (f" ({words[k]}stated)" if k in self.stated and words[k] else
                                      "" if k in self.stated else f" ({words[k]}chosen)")
                for k, v in self.scales.items()]

    @property
    def gears(self) -> GearSet:
        return self.problem.gears

    def gear(self, label: str) -> SpurGear:
        return self.gears.gears[int(label) - 1] if label else self.gears.gears[0]

    def index(self, label: str) -> int:
        return int(label) - 1 if label else 0


def default_find(p: GearScene) -> tuple[str, ...]:
    if not p.gears.pair:
        return DEFAULT_TOOTH
    out = [n for n in DEFAULT_PAIR if quantity_unit(n, p) is not None]
    return tuple(out)


def split_gear(name: str, p: GearScene) -> tuple[str, str, float | None]:
    """``"s_k1@85"`` → (stem ``s_k``, gear label ``1``, radius 0.085 m); ``"B1B2"`` → (``B1B2``, "", None)."""
    base, _, at = name.partition("@")
    for label in p.labels:
        if label and not base.endswith(label):
            continue
        stem = base[: len(base) - len(label)] if label else base
        if (at and stem in AT_RADIUS) or (not at and stem in TOOTH_QUANTITIES):
            return stem, label, (float(at) / 1000.0 if at else None)
    return base, "", None


def panels_for(names: list[str], p: GearScene) -> tuple[str, ...]:
    """The panels that draw what ``names`` measure, in the sheet's order."""
    want = set()
    for name in names:
        stem, _, _ = split_gear(name, p)
        if gen.answers(p.generation, name):
            want.add("generation")
        elif stem in ("W", "d_pin", "M"):
            want.add("measurement")
        elif stem in TOOTH_QUANTITIES or stem in AT_RADIUS or stem == "p":
            want.add("tooth")
        elif stem == "z_root_eq_base":
            want.add("root_base")
        elif stem in ("B1B2", "eps_alpha", "single_contact", "double_contact", "pb") and p.gears.pair:
            want.update(("meshing", "zones"))
        elif stem in PAIR_QUANTITIES:
            want.add("meshing")
        elif stem == "pb":
            want.add("tooth")
    return tuple(s for s in GEAR_SHOW_CHOICES if s in want)


def analyse(scene: Scene[GearScene], extra_measured: tuple[tuple[str, float], ...] = (),
            estimates: bool = True) -> GearAnalysis:
    """Construct what the scene asks for and build its check table (``estimates``: with the rows'
    own error estimates; a figure does without)."""
    p = scene.problem
    if p.gears.spatial is not None:  # the kind sends these to problems/gears/spatial.py
        raise NotApplicable(f"a {p.gears.meshing} pair is analysed by graphmech.problems.gears.spatial, not as spur gears")
    an = GearAnalysis(scene, p, extra_measured=tuple(extra_measured), estimates=estimates)
    problems = [(k, f"unknown gear quantity {n!r}") for k, n, _ in measured_entries(scene, extra_measured)
                if quantity_unit(n, p) is None]
    if problems:
        raise SceneError(problems, scene.source)
    an.names = list(scene.find) or list(default_find(p))
    an.panels = scene.show or panels_for(an.names + [n for _, n, _ in measured_entries(scene, extra_measured)], p)
    with in_double_precision("the gear construction"):
        _warn(an)
        _choose_scales(an)
        try:
            gen.analyse_generation(an)
        except SceneError:
            raise
        except GraphmechError as err:  # the cutting cannot be posed for this gear (h*a = 0: no undercut)
            raise SceneError([("gear.generation", str(err))], scene.source) from None
        for i, name in enumerate(an.names):
            try:
                row = _row(an, name)
            except SceneError:
                raise
            except GraphmechError as err:  # a construction that cannot be made for this gear, said at its name
                raise SceneError([(f"find[{i}]" if scene.find else "gear", f"{name}: {err}")], scene.source) from None
            if row is not None:
                an.rows.append(row)
    return an


def _refuse(an: GearAnalysis, err: GraphmechError, key: str = "gear") -> SceneError:
    return SceneError([(key, str(err))], an.scene.source)


def _mesh(an: GearAnalysis) -> gmesh.MeshConstruction:
    if an.mesh is None:
        try:
            an.mesh = gmesh.construct_meshing(an.gears)
        except (NoSolution, NotApplicable, OutOfDomain) as err:
            raise _mesh_refused(an, err) from None
    return an.mesh


def _mesh_refused(an: GearAnalysis, err: GraphmechError) -> SceneError:
    """A pair that cannot mesh, in the scene's words: a stated a′ too small for the shifts (too
    large for a ring) says which centre distance would do, in mm."""
    a_w = an.gears.centre_distance
    if a_w is None or not isinstance(err, NoSolution):
        return _refuse(an, err, "gear")
    try:
        free = ex.meshing(replace(an.gears, centre_distance=None)).a_w
    except GraphmechError:
        return _refuse(an, err, an.problem.centre_distance_key)
    bound = "greatest" if an.gears.meshing == "internal" else "least"
    if abs(a_w - free) <= COINCIDENT_REL * free:  # a′ is where they mesh: the pair fails for another reason
        return _refuse(an, err, an.problem.centre_distance_key)
    return SceneError([(an.problem.centre_distance_key,
                        f"at a′ = {a_w * 1000:.6g} mm the teeth overlap: the {bound} centre distance for these "
                        f"shifts is {free * 1000:.6g} mm")], an.scene.source)


def _warn(an: GearAnalysis) -> None:
    """What a student must be told whatever was asked: undercut, pointed or thin tips, ε < 1,
    interference, a ring's tip circle inside its base circle."""
    s = an.gears.system
    for label in an.problem.labels:
        g = an.gear(label)
        name = f"gear {label}" if label else "the gear"
        if not g.internal:
            u = ex.undercut(s, g)
            if u.undercut:
                an.warnings.append(f"{name} (z = {g.z}, x = {g.x:g}) is undercut by a rack cutter: z < z_min = "
                                   f"{u.z_min_exact:.4g} for this shift (x_min = {u.x_min_exact:.4g}); the fillet "
                                   "cuts into the involute above the base circle")
        t = ex.tooth(s, g)
        if t.sa is not None and t.sa <= 0.0:
            ra = ex.pointed_tip(s, g).ra_pointed
            an.warnings.append(f"{name}'s tooth is pointed below its tip circle (at r = {ra * 1000:.4g} mm): s_a "
                               "would be negative")
        elif t.sa is not None and t.sa < SA_MIN * s.m:
            an.warnings.append(f"{name}'s tip is thin: s_a = {t.sa * 1000:.4g} mm < {SA_MIN:g}m = "
                               f"{SA_MIN * s.m * 1000:.4g} mm (the book asks s_a ≥ 0.25m … 0.4m)")
        if g.internal and t.da / 2.0 < t.db / 2.0:
            an.warnings.append(f"{name} is a ring whose tip circle (r_a = {t.da * 500:.4g} mm) lies inside its base "
                               f"circle (r_b = {t.db * 500:.4g} mm): its teeth are not involute there")
    if an.gears.pair:
        try:
            an.exact_mesh = ex.meshing(an.gears)
        except (NoSolution, NotApplicable, OutOfDomain) as err:
            raise _mesh_refused(an, err) from None
        an.warnings.extend(an.exact_mesh.notes)


def _choose_scales(an: GearAnalysis) -> None:
    """μl of each drawing, stated or chosen round so that its panel fits its share of the page:
    the rows are the teeth (one per gear drawn), the pair (meshing beside zones), the measurement
    (span beside pins), the root–base diagram; a panel's notes take about CAPTION_MM under it."""
    s = an.gears.system
    stated = an.scene.scales
    for key in ("l", "tooth", "zones", "generation"):
        if key in stated:
            an.scales[key] = stated[key]
            an.stated.add(key)
    panels = set(an.panels)
    _legible(an)
    w, h = page_size(an.scene)
    n_rows = (len(_drawn_labels(an)) if "tooth" in panels else 0) + bool({"meshing", "zones"} & panels) \
        + ("measurement" in panels) + ("root_base" in panels)
    room_h = max((h - TITLE_MM) / max(n_rows, 1) - CAPTION_MM, 30.0)
    room_w = w - SIDE_MM
    if "tooth" not in an.scales and "tooth" in panels:  # three teeth, the construction's strings beside them
        need = []
        for label in _drawn_labels(an):
            t = ex.tooth(s, an.gear(label))
            depth = t.ha + t.hf
            need += [(3.0 * t.p + 2.0 * depth) / (TOOTH_SHARE * room_w), 2.0 * depth / room_h]
        an.scales["tooth"] = round_scale(max(need))
    if "l" not in an.scales and "measurement" in panels and not ({"meshing", "zones"} & panels):
        need = []  # the whole gear with its pins, the caliper over k teeth beside it
        for label in _drawn_labels(an):
            g = an.gear(label)
            t = ex.tooth(s, g)
            k = 2 if g.internal or g.z < 2 else an.problem.span_teeth[an.index(label)] or ex.span_teeth(s, g)
            need += [(min(k, g.z / 2.0) * t.p + 2.0 * (t.ha + t.hf)) / (0.45 * room_w),
                     (max(t.da, t.df) + 4.0 * t.p) / room_h]
        an.scales["l"] = round_scale(max(need))
    if an.gears.pair and ({"meshing", "zones"} & panels):
        em = an.exact_mesh
        share = 0.5 if {"meshing", "zones"} <= panels else 1.0
        if "zones" not in an.scales and "zones" in panels:
            an.scales["zones"] = round_scale(max(em.B1B2, em.pb) * 1.3 / (share * room_w - 20.0))
        if "l" not in an.scales and "meshing" in panels:
            tall, wide = _pair_extent(an)
            mu = round_scale(max(tall / room_h, wide / (share * room_w)))
            if em.B1B2 / mu < MESH_B1B2_MM:  # a large pair: drawn around the line of action
                mu = round_scale(max(em.B1B2, em.pb) * 4.0 / min(room_h, share * room_w))
                an.mesh_whole = False
            an.scales["l"] = mu


def _legible(an: GearAnalysis) -> None:
    """Refuse a stated μ that draws its panel beyond any page (graphmech.scales.DRAWN_SIZE_RANGE_MM,
    the rule every kind keeps): a pair at 1e-12 m/mm would be kilometres of arcs to dash."""
    s = an.gears.system
    g = an.gears.gears[0]
    t = ex.tooth(s, g)
    sizes = {"tooth": ("the teeth", 3.0 * t.p + 2.0 * (t.ha + t.hf)),
             "l": ("the gears", max(max(ex.tooth(s, x).da, ex.tooth(s, x).df) for x in an.gears.gears)
                   + (an.exact_mesh.a_w if an.gears.pair else 0.0)),
             "zones": ("B₁B₂", an.exact_mesh.B1B2 if an.gears.pair else t.pb),
             "generation": ("the blank and the cutter", t.da)}
    for key in an.stated:
        what, size = sizes[key]
        why = drawn_size_problem(size, an.scales[key], key, what)
        if why is not None:
            raise SceneError([(f"scales.{key}", why)], an.scene.source)


def _pair_extent(an: GearAnalysis) -> tuple[float, float]:
    """How tall (along O₁O₂) and how wide the whole pair is drawn, m."""
    s = an.gears.system
    tips = [ex.tooth(s, g).da / 2.0 for g in an.gears.gears]
    a_w = an.exact_mesh.a_w
    if an.gears.meshing == "external":
        return a_w + tips[0] + tips[1], 2.0 * max(tips)
    if an.gears.meshing == "internal":
        rim = ex.tooth(s, an.gears.gears[1]).df + 2.0 * s.m
        return rim, rim
    return a_w + tips[0] + 2.0 * s.m, max(2.0 * tips[0], 4.0 * s.m * math.pi)


def _drawn_labels(an: GearAnalysis) -> list[str]:
    """The gears whose teeth are drawn: those the names ask about (the first gear if none)."""
    p = an.problem
    return [lab for lab in p.labels if _asks_tooth(an, lab)] or [p.labels[0]]


def _at(an: GearAnalysis, label: str, r: float) -> inv.AtRadius:
    key = (label, r)
    if key not in an.radii:
        try:
            an.radii[key] = inv.at_radius(an.gears.system, an.gear(label), r)
        except (OutOfDomain, NotApplicable) as err:
            raise _refuse(an, err, "find") from None
    return an.radii[key]


def _values(an: GearAnalysis, name: str) -> tuple[float, float, float | None, float] | None:
    """(graphical, exact, the length on the drawing in mm or None, μ) of a name, in SI (angles in rad)."""
    p = an.problem
    s = p.gears.system
    if an.generation is not None and gen.answers(an.generation.model, name):
        return gen.generation_value(an, name)
    stem, label, r_k = split_gear(name, p)
    mu_t = an.scales.get("tooth")
    if stem in AT_RADIUS:
        assert r_k is not None
        c = _at(an, label, r_k)
        e = ex.at_radius(s, an.gear(label), r_k)
        ra = ex.tooth(s, an.gear(label)).da / 2.0
        beyond = r_k < ra if an.gear(label).internal else r_k > ra
        where = f"r = {r_k * 1000:g} mm"
        note = (f"{where} lies beyond the tip circle (r_a = {ra * 1000:.4g} mm): the involute extended, not the tooth"
                if beyond else f"at {where} the flanks have crossed (s_k < 0): the tooth is pointed below it"
                if c.s_k < 0.0 else "")
        if note and note not in an.warnings:
            an.warnings.append(note)
        return {"s_k": (c.s_k, e.s_k, *_drawn(c.s_k, mu_t)), "alpha_k": (c.alpha_k, e.alpha_k, None, 1.0),
                "rho_k": (c.rho_k, e.rho_k, *_drawn(c.rho_k, mu_t)),
                "theta_k": (c.theta_k, e.theta_k, None, 1.0)}[stem]
    if stem in SHIFT_STEMS:
        return _shift_value(an, stem, label)
    if stem in TOOTH_QUANTITIES:
        return _tooth_value(an, stem, label, mu_t)
    if stem == "z_root_eq_base":
        z, _ = _root_base(an)
        return z, ex.z_root_eq_base(s, an.gear(p.labels[0]).x), None, 1.0
    if stem == "p" or (stem == "pb" and not p.gears.pair):
        g = an.gear(p.labels[0])
        t = ex.tooth(s, g)
        if stem == "p":  # the reference circle divided into z: a definition, as d = mz is
            pitch = 2.0 * math.pi * (t.d / 2.0) / g.z
            return pitch, t.p, *_drawn(pitch, mu_t)
        cb = _at(an, p.labels[0], t.db / 2.0)
        pitch_b = 2.0 * math.pi * math.hypot(*cb.N_left) / g.z
        return pitch_b, t.pb, *_drawn(pitch_b, mu_t)
    return _pair_value(an, stem)


#: The names of the shift's design: not lengths on a panel, each a construction or the book's rule.
SHIFT_STEMS = ("x", "x_min", "x_min_exact", "z_min", "z_min_exact", "x_sum", "y", "delta_y")
#: Those that are shift coefficients (lengths in modules; z_min is a tooth number).
COEFFICIENT_STEMS = ("x", "x_min", "x_min_exact", "x_sum", "y", "delta_y")


def _shift_value(an: GearAnalysis, stem: str, label: str) -> tuple[float, float, float | None, float]:
    """A shift coefficient constructed — the undercut limit from N₁ drawn on the generating rack's
    line of action, the shifts for a′ from the flanks' thickness on the working pitch circles, a
    repair's from the wheel's reference thickness — or by the book's rule (x_min with z_min = 17:
    a rule, equal to itself)."""
    s = an.gears.system
    g = an.gear(label)
    if stem == "x_min":
        v = exs.x_min_book(s, g.z)
        return v, v, None, 1.0
    if stem == "z_min":
        zb = float(exs.z_min_book(s))
        return zb, zb, None, 1.0
    if stem in ("x_min_exact", "z_min_exact"):
        lim = shift.undercut_limit(s, g.z)
        if stem == "z_min_exact":
            return lim.z_min, exs.z_min_exact(s), None, 1.0
        return lim.x_min, exs.x_min_exact(s, g.z), None, 1.0
    if stem in ("x_sum", "y", "delta_y"):
        return _pair_shift(an, stem)
    how = an.problem.shift
    if how == "least":
        return g.x, exs.x_min_book(s, g.z), None, 1.0  # the rule's value, stated as the shift
    if how == "least_exact":
        return shift.undercut_limit(s, g.z).x_min, g.x, None, 1.0
    if how == "repair":
        x2 = shift.shift_for_thickness(s, an.gears.gears[1].z, -float(an.problem.thickness_loss or 0.0))
        return (x2 if an.index(label) == 1 else -x2), g.x, None, 1.0
    if how == "for_centre_distance":
        if an.gears.meshing == "rack":  # the pinion's reference circle a′ − xm from the rack's reference line
            a_w = float(an.gears.centre_distance or 0.0)
            return (a_w - ex.tooth(s, g).d / 2.0) / s.m, g.x, None, 1.0
        x_sum = _shift_sum(an)
        x1 = an.problem.x1_stated if an.problem.x1_stated is not None else 0.5 * x_sum
        return (x1 if an.index(label) == 0 else x_sum - x1), g.x, None, 1.0
    return g.x, g.x, None, 1.0  # stated


def _shift_sum(an: GearAnalysis) -> float:
    """x₁ + x₂ constructed from the distance at which the pair meshes without backlash: the stated
    a′ when the shifts were chosen for it, else the constructed pair's own."""
    if an.shift_sum is None:
        s = an.gears.system
        g1, g2 = an.gears.gears
        if an.problem.shift == "for_centre_distance" and an.gears.centre_distance is not None:
            a_w = an.gears.centre_distance
        elif an.gears.centre_distance is None:
            a_w = _mesh(an).a_w
        else:
            a_w = gmesh.construct_meshing(replace(an.gears, centre_distance=None)).a_w
        an.shift_sum = shift.shift_for_centre_distance(s, g1.z, g2.z, a_w).x_sum
    return an.shift_sum


def _pair_shift(an: GearAnalysis, stem: str) -> tuple[float, float, float | None, float]:
    """x₁ + x₂, y = (a′ − a)/m with a′ the pair's drawn centre distance and a = r₁ ± r₂, and the
    tip shortening Δy = x₁ + x₂ − y (0 when nothing is to be shortened)."""
    s = an.gears.system
    g1, g2 = an.gears.gears
    e = an.exact_mesh
    r1, r2 = ex.tooth(s, g1).d / 2.0, ex.tooth(s, g2).d / 2.0
    a = r2 - r1 if an.gears.meshing == "internal" else r1 + r2
    y = (_mesh(an).a_w - a) / s.m
    want_y = (e.a_w - e.a) / s.m
    if stem == "y":
        return y, want_y, None, 1.0
    x_sum = _shift_sum(an)
    if stem == "x_sum":
        return x_sum, g1.x + g2.x, None, 1.0
    return max(0.0, x_sum - y), exs.tip_shortening(s, g1.z, g2.z, g1.x + g2.x, e.a_w), None, 1.0


def _drawn(value: float, mu: float | None) -> tuple[float | None, float]:
    """(the length on the drawing, mm; its μ) — (None, 1) where the scene draws no panel for it."""
    return (None, 1.0) if mu is None else (value / mu, mu)


def _tooth_value(an: GearAnalysis, stem: str, label: str, mu: float | None
                 ) -> tuple[float, float, float | None, float]:
    s = an.gears.system
    g = an.gear(label)
    t = ex.tooth(s, g)
    if stem in ("d", "db", "da", "df"):
        v = getattr(t, stem)
        return v, v, *_drawn(v, mu)  # a circle is drawn at its radius: nothing is constructed
    if stem in ("ha", "hf"):
        v = getattr(t, stem)
        return v, v, *_drawn(v, mu)
    if stem in ("s_pitch", "e_pitch", "rho_pitch"):
        c = _at(an, label, t.d / 2.0)
        pitch = 2.0 * math.pi * (t.d / 2.0) / g.z
        got = {"s_pitch": c.s_k, "e_pitch": pitch - c.s_k, "rho_pitch": c.rho_k}[stem]
        want = {"s_pitch": t.s, "e_pitch": t.e, "rho_pitch": t.rho_pitch}[stem]
        return got, want, *_drawn(got, mu)
    if stem in ("sa", "alpha_a", "rho_a"):
        if t.alpha_a is None:
            raise SceneError([("find", f"{stem}{label}: the tip circle lies inside the base circle: no involute "
                                       "there")], an.scene.source)
        c = _at(an, label, t.da / 2.0)
        if stem == "alpha_a":
            return c.alpha_k, t.alpha_a, None, 1.0
        got = c.s_k if stem == "sa" else c.rho_k
        tip = t.sa if stem == "sa" else t.rho_a
        assert tip is not None  # with α_a (the tip circle outside the base circle) come s_a and ρ_a
        return got, tip, *_drawn(got, mu)
    if stem == "sb":
        c = _at(an, label, t.db / 2.0)
        return c.s_k, t.sb, *_drawn(c.s_k, mu)
    if stem in ("ra_pointed", "alpha_a_pointed", "inv_alpha_a_pointed"):
        if label not in an.pointed:
            try:
                an.pointed[label] = inv.pointed_tip(s, g)
            except (OutOfDomain, NotApplicable, NoSolution) as err:
                raise _refuse(an, err, "find") from None
        c = an.pointed[label]
        e = ex.pointed_tip(s, g)
        if stem == "ra_pointed":
            return c.r_k, e.ra_pointed, *_drawn(c.r_k, mu)
        if stem == "alpha_a_pointed":
            return c.alpha_k, e.alpha_a_pointed, None, 1.0
        return c.theta_k, e.inv_alpha_a_pointed, None, 1.0
    mu = an.scales.get("l")  # the span and the pins are drawn with the whole gear
    if stem == "W":
        if g.internal:
            raise SceneError([("find", f"W{label}: a ring's span cannot be measured with a caliper: measure over "
                                       "pins (M)")], an.scene.source)
        k = an.problem.span_teeth[an.index(label)] or ex.span_teeth(s, g)
        if label not in an.spans:
            an.spans[label] = inv.span(s, g, k)
        w = an.spans[label].W
        return w, ex.span(s, g, k), *_drawn(w, mu)
    # pins
    d_pin = an.problem.pin_diameter[an.index(label)]
    if label not in an.pins:
        try:
            an.pins[label] = inv.over_pins(s, g, d_pin)
        except (OutOfDomain, NotApplicable, NoSolution) as err:
            raise _refuse(an, err, "gear.pin_diameter") from None
    c2 = an.pins[label]
    want_d = d_pin if d_pin is not None else ex.pin_diameter(s, g)
    if stem == "d_pin":
        return c2.d_pin, want_d, *_drawn(c2.d_pin, mu)
    return c2.M, ex.over_pins(s, g, want_d).M, *_drawn(c2.M, mu)


def _pair_value(an: GearAnalysis, stem: str) -> tuple[float, float, float | None, float] | None:
    c = _mesh(an)
    e = an.exact_mesh
    mu_l = an.scales.get("l")
    mu_z = an.scales.get("zones")
    s = an.gears.system
    if stem == "a":
        r = [ex.tooth(s, g).d / 2.0 for g in an.gears.gears]
        got = r[0] + r[1] if an.gears.meshing == "external" else r[1] - r[0] if an.gears.meshing == "internal" \
            else r[0] + an.gears.gears[0].x * s.m
        return got, e.a, *_drawn(got, mu_l)
    if stem in ("alpha_w",):
        return c.alpha_w, e.alpha_w, None, 1.0
    if stem in ("a_w", "rw1", "rw2", "N1N2"):
        got_l = {"a_w": c.a_w, "rw1": c.r_w1, "rw2": c.r_w2, "N1N2": c.N1N2}[stem]
        want_l = {"a_w": e.a_w, "rw1": e.r_w1, "rw2": e.r_w2, "N1N2": e.N1N2}[stem]
        if got_l is None or want_l is None:
            return None
        return got_l, want_l, *_drawn(got_l, mu_l)
    if stem in ("B1B2", "pb"):
        got = c.B1B2 if stem == "B1B2" else c.pb
        return got, getattr(e, stem), *_drawn(got, mu_z)
    if stem == "eps_alpha":
        return c.eps_alpha, e.eps_alpha, None, 1.0
    if stem in ("single_contact", "double_contact"):
        got_z = getattr(c, stem)
        want_z = getattr(e, stem)
        if got_z is None or want_z is None:
            return None
        return got_z, want_z, *_drawn(got_z, mu_z)
    if stem.startswith("eta_"):
        want_eta = getattr(e, stem)
        if want_eta is None:  # a contact at N: the radius of curvature there is 0, the sliding infinite
            return None
        return _sliding(an, c, stem), want_eta, None, 1.0
    if stem == "backlash":
        if c.backlash is None or e.backlash is None:
            return None
        return c.backlash, e.backlash, *_drawn(c.backlash, mu_l)
    return None


def _sliding(an: GearAnalysis, c: gmesh.MeshConstruction, stem: str) -> float:
    """Specific sliding from the radii of curvature measured on the line of action."""
    z = [g.z for g in an.gears.gears]
    at = "B1" if stem in ("eta_tip1", "eta_root2") else "B2"
    r1 = c.rho[f"N1{at}"]
    if an.gears.meshing == "rack":
        n1p = math.hypot(c.P[0] - c.N1[0], c.P[1] - c.N1[1])
        return 1.0 - n1p / r1 if stem.endswith("1") else 1.0 - r1 / n1p
    u = z[1] / z[0]
    r2 = c.rho[f"N2{at}"]
    return 1.0 - r2 / (u * r1) if stem.endswith("1") else 1.0 - u * r1 / r2


def _root_base(an: GearAnalysis) -> tuple[float, float]:
    """z at which the root circle is the base circle, constructed: r_f/m and r_b/m against z are
    two straight lines (z/2 − h*a − c* + x and z·cos α/2); where they cross."""
    if an.root_base is None:
        s = an.gears.system
        x = an.gear(an.problem.labels[0]).x
        ops = ScalarOps()
        f0 = -(s.ha_star + s.c_star - x)
        # a line as (point, direction): r_f from (0, f0) with slope ½; r_b from (0, 0) with slope cos α/2
        l1 = ((0.0, f0), (1.0, 0.5))
        l2 = ((0.0, 0.0), (1.0, math.cos(s.alpha) / 2.0))
        z, r = _cross(ops, l1, l2)
        an.root_base = (z, r)
    return an.root_base


def _cross(ops: ScalarOps, l1: Any, l2: Any) -> tuple[float, float]:
    (ax, ay), (ux, uy) = l1
    (bx, by), (vx, vy) = l2
    nu, nv = math.hypot(ux, uy), math.hypot(vx, vy)  # the kernel takes unit directions
    ux, uy, vx, vy = ux / nu, uy / nu, vx / nv, vy / nv
    got = intersect_lines(ops, (ax, ay, ux, uy), (bx, by, vx, vy))
    return float(got[0]), float(got[1])


def _row(an: GearAnalysis, name: str) -> Row | None:
    v = _values(an, name)
    if v is None:
        an.warnings.append(f"{name}: " + ("needs a stated centre_distance (without it the pair meshes with none)"
                                          if name == "backlash" else "not defined for this set (see the notes above)"))
        return None
    g, e, drawn, scale = v
    unit = quantity_unit(name, an.problem) or ""
    if unit == "deg":
        g, e = math.degrees(g), math.degrees(e)
    # a shift coefficient is a length in modules: its error is relative to m where x is near 0
    floor = 1.0 if split_gear(name, an.problem)[0] in COEFFICIENT_STEMS else 1e-300
    row = Row(name, unit, drawn, scale, g, e, abs(g - e) / max(abs(e), floor))
    return gen.estimate(an, row) if an.generation is not None and an.estimates else row


def judge(an: GearAnalysis, precision_mm: float | None = None) -> list[Verdict]:
    """A student's values against the construction: a length within the drawing precision × its
    μl; an angle within the angle a precision-long slip turns its shorter arm by; ε within what
    the precision does to B₁B₂/p_b measured on the same drawing."""
    prec = precision_mm if precision_mm is not None else an.scene.precision_mm
    out = []
    for _key, name, value in measured_entries(an.scene, an.extra_measured):
        v = _values(an, name)
        unit = quantity_unit(name, an.problem) or ""
        if v is None:
            out.append(Verdict(name, value, 0.0, 0.0, False, unit))
            continue
        g, _e, drawn, scale = v
        if unit == "deg":
            arm = _arm_mm(an, name)
            tol = math.degrees(math.atan2(prec, max(arm, prec)))
            gd = math.degrees(g)
            out.append(Verdict(name, value, gd, tol, abs(value - gd) <= tol, unit))
        elif name == "eps_alpha":
            c = _mesh(an)
            mu_z = an.scales.get("zones", an.scales.get("l"))
            # B₁B₂ and p_b both measured on the drawing: their errors add in the ratio
            tol = g * (prec * mu_z / c.B1B2 + prec * mu_z / c.pb) if mu_z is not None else 1e-3 * g
            out.append(Verdict(name, value, g, tol, abs(value - g) <= tol, unit))
        else:
            out.append(judge_value(name, value, g, drawn, scale, prec, unit))
    return out


def _arm_mm(an: GearAnalysis, name: str) -> float:
    """The shorter arm of a measured angle on the drawing, mm."""
    stem, label, _ = split_gear(name, an.problem)
    if stem == "alpha_w":
        c = _mesh(an)
        return c.B1B2 / an.scales.get("l", c.B1B2 / 10.0)
    t = ex.tooth(an.gears.system, an.gear(label))
    return t.db / 2.0 / an.scales.get("tooth", t.db / 20.0)  # no drawing: a protractor on a 10 mm arm


def lines(an: GearAnalysis) -> list[str]:
    """Under the text table: the contact ratio said in words when it matters, the span's k."""
    out = []
    for label, sp in an.spans.items():
        out.append(f"W{label}: the span over k = {sp.k} teeth")
    drive = _drive(an)
    if drive is not None:
        g1, g2 = an.gears.gears
        dy = g1.delta_y
        out.append(f"{drive} drive: x₁ = {g1.x:.6g}, x₂ = {g2.x:.6g}, x₁ + x₂ = {g1.x + g2.x:.6g}"
                   + (f"; tips shortened by Δy·m = {dy * an.gears.system.m * 1000:.6g} mm (Δy = {dy:.6g})" if dy
                      else ""))
    if an.mesh is not None:
        eps = an.mesh.eps_alpha
        if eps < 1.0:
            out.append(f"ε = {eps:.4g} < 1: the drive is not continuous — one pair leaves contact before the next "
                       "begins")
        elif eps < 2.0:
            out.append(f"ε = {eps:.4g}: two pairs in contact over {(eps - 1) * 100:.0f} % of each base pitch "
                       f"(the two ends of B₁B₂), one pair over the middle {(2 - eps) * 100:.0f} %")
        else:
            n = math.floor(eps)
            out.append(f"ε = {eps:.4g} ≥ 2: {n + 1} pairs in contact over {(eps - n) * 100:.0f} % of each base "
                       f"pitch, {n} over the rest")
    return out


def extras(an: GearAnalysis) -> dict[str, Any]:
    """``check --json``'s "gear" section: the span's k per gear and, for a pair, where the zones lie."""
    out: dict[str, Any] = {}
    if an.spans:
        out["span_teeth"] = {label or "gear": sp.k for label, sp in an.spans.items()}
    if an.mesh is not None:
        out["continuous"] = an.mesh.eps_alpha >= 1.0
    drive = _drive(an)
    if drive is not None:
        out["drive"] = drive
    return {"gear": out} if out else {}


def _drive(an: GearAnalysis) -> str | None:
    """The kind of an external pair's drive by its shifts (standard, equal and opposite, positive, negative)."""
    if an.gears.meshing != "external":
        return None
    g1, g2 = an.gears.gears
    return exs.drive_kind(g1.x, g2.x)


def gear_figure(an: GearAnalysis, page: tuple[float, float], footer: tuple[str, ...] = ()) -> Any:
    """The sheet of the scene's panels."""
    from graphmech.problems.gears.figures import GearDrawing, gear_sheet

    p = an.problem
    s = p.gears.system
    teeth = []
    if "tooth" in an.panels or "measurement" in an.panels:
        for lab in _drawn_labels(an):
            try:
                teeth.append((lab, inv.tooth_outline(s, an.gear(lab))))
            except (NotApplicable, OutOfDomain, NoSolution) as err:
                raise _refuse(an, err, "gear") from None
    if "meshing" in an.panels or "zones" in an.panels:
        _mesh(an)
    if "root_base" in an.panels:
        _root_base(an)
    drawing = GearDrawing(
        gears=p.gears, scales=dict(an.scales), teeth=tuple(teeth),
        at_radii=tuple((lab, c) for (lab, _r), c in an.radii.items()),
        pointed=tuple(an.pointed.items()), span=tuple(an.spans.items()), pins=tuple(an.pins.items()),
        mesh=an.mesh, mesh_whole=an.mesh_whole, root_base=(an.root_base[0], float(an.gear(p.labels[0]).z)) if an.root_base else None,
        generation=gen.generation_panel(an.generation, an.scene.page.notation) if an.generation is not None
        and "generation" in an.panels else None)
    return gear_sheet(an.scene.title, an.panels, drawing, page, footer, an.scene.page.notation)


def _asks_tooth(an: GearAnalysis, label: str) -> bool:
    return any(split_gear(n, an.problem)[1] == label and split_gear(n, an.problem)[0] in {**TOOTH_QUANTITIES,
                                                                                      **AT_RADIUS}
               for n in an.names)


__all__ = ["GearAnalysis", "analyse", "default_find", "extras", "gear_figure", "judge", "lines", "panels_for",
           "split_gear"]
