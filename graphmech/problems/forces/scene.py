"""Read a force scene: a linkage scene with a ``[forces]`` table (kinetostatic analysis).

A force scene is a linkage scene (``[frame]``, ``[driver]`` — a crank or a slider —, ``[[dyad]]``,
``[[point]]``) with a ``[forces]`` table: the links' masses and moments of inertia at named
centres of mass, external forces at named points and moments on links, gravity, friction in the
journals (friction circles) and on the guides (friction angles), and the force scale μF.
:func:`parse_forces_scene` is the rest of :func:`graphmech.scene.parse_scene` for such a scene,
with the same reader, key paths and one-line messages; everything is converted to SI into a
:class:`~graphmech.mechanisms.forces.ForceModel`.

The format, with examples, is the "Force scenes" section of ``docs/scene-format.md``.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, cast

from graphmech.mechanisms.forces import (
    ForceModel,
    LinkCouple,
    LinkMass,
    PointForce,
    RevoluteFriction,
    SlidingFriction,
)
from graphmech.mechanisms.linkage import PRP, RPP, RPR, RRP, RRR, Crank, Linkage, Triad
from graphmech.scales import scale_out_of_range
from graphmech.problems.linkage.scene import SHOW_CHOICES, read_linkage
from graphmech.problems.reader import (
    MISSING,
    Reader,
    Scene,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
    say,
)

#: What a force scene may show: the kinematics' panels, then the loads and reactions on the
#: mechanism ("forces"), each Assur group's free body and force polygon ("force_polygons"), and
#: Zhukovsky's lever ("lever").
FORCE_SHOW_CHOICES = SHOW_CHOICES + ("forces", "force_polygons", "lever")
#: What a force scene shows when it does not say.
FORCE_SHOW_DEFAULT = ("forces", "force_polygons")
#: The most masses, forces, moments or friction entries of one kind.
MAX_ITEMS = 100
#: The most rounds of successive approximation a scene may allow.
MAX_ITERATIONS = 10_000
#: The magnitudes a load, mass, moment of inertia or gravity may have, SI (besides 0).
ABSURD = (1e-9, 1e12)


@dataclass(frozen=True)
class ForceScene:
    """The loads of a force scene and how to draw them.

    Parameters
    ----------
    model : ForceModel
        Masses, loads, friction, in SI.
    mu_F : float or None
        The force polygons' scale, N/mm (None: chosen to fit the page).
    mu_F_path : str
        Where the scene states μF (for messages about it).
    """

    model: ForceModel
    mu_F: float | None = None
    mu_F_path: str = "forces.mu_F"


def _non_negative(r: Reader, base: str, kind: str, *, required: bool = True) -> float | None:
    v = r.value(base, kind, required=required)
    if v is None:
        return None
    if v.si < 0:
        r.problem(v.path, "must be ≥ 0")
        return None
    return _sane(r, v)


def _sane(r: Reader, v: Any) -> float | None:
    """A load, mass or gravity of a machine: 0, or 1e-9 … 1e12 in SI units (beyond, the products
    of the analysis under- or overflow: a denormal mass made h = M_i/F_i infinite)."""
    if v.si != 0 and not ABSURD[0] <= abs(v.si) <= ABSURD[1]:
        r.problem(v.path, f"{v.text()} is absurd for a machine (0, or {ABSURD[0]:g} … {ABSURD[1]:g} in SI units)")
        return None
    return cast("float | None", v.si)


def _name(r: Reader, key: str, hint: str) -> str | None:
    value = r.raw(key, required=True, hint=hint)
    return None if value is MISSING else r.point_name(value, r.at(key))


def _link(r: Reader, links: dict[str, list[str]] | None, frame: str | None) -> str | None:
    value = r.raw("link", required=True, hint='the number of the link, e.g. link = "2"')
    link = None if value is MISSING else r.link_id(value, r.at("link"))
    if link is None or links is None:
        return link
    if link == frame:
        r.problem(r.at("link"), f"link {link} is the frame: it does not move")
        return None
    if link not in links:
        r.problem(r.at("link"), f"link {link} is not a moving link (links: {', '.join(links)})")
        return None
    return link


def _on_link(r: Reader, point: str | None, link: str | None, links: dict[str, list[str]] | None) -> str | None:
    if point is None or link is None or links is None:
        return point
    if point not in links[link]:
        r.problem(r.at("point"), f"{point} is not a point of link {link} (it carries {', '.join(links[link])})")
        return None
    return point


def _label_text(r: Reader, key: str, default: str) -> str:
    value = r.raw(key)
    if value is MISSING:
        return default
    if not isinstance(value, str) or not value.strip() or len(value) > 16:
        r.problem(r.at(key), "must be a short label (1 … 16 characters), e.g. \"P_r\"")
        return default
    return value


def _coefficient(r: Reader, key: str) -> float | None:
    value = r.raw(key, required=True, hint=f"the friction coefficient, e.g. {key} = 0.1")
    if value is MISSING:
        return None
    x = r.number(value, r.at(key))
    if x is None:
        return None
    if not 0 <= x < 10:
        r.problem(r.at(key), f"{say(value)} is not a friction coefficient: 0 ≤ f < 10")
        return None
    return x


def _joint_lengths(linkage: Linkage) -> dict[str, float]:
    """Joint → the shortest fixed distance from it to another joint of a link it belongs to (m):
    a journal must be smaller than half of it, or it overlaps its neighbour."""
    out: dict[str, float] = {}

    def near(a: str, b: str, length: float) -> None:
        for x in (a, b):
            out[x] = min(out.get(x, math.inf), length)

    d = linkage.driver
    if isinstance(d, Crank):
        near(d.pivot, d.tip, d.length)
    for y in linkage.dyads:
        if isinstance(y, RRR):
            near(y.p, y.c, y.lengths[0])
            near(y.q, y.c, y.lengths[1])
        elif isinstance(y, Triad):
            for k in range(3):
                near(y.outer[k], y.inner[k], y.lengths[k])
                near(y.inner[k], y.inner[(k + 1) % 3], y.ternary[k])
        elif isinstance(y, RRP):
            near(y.p, y.c, y.length)
    return out


def _revolute_points(linkage: Linkage) -> set[str]:
    d = linkage.driver
    out = {d.pivot, d.tip} if isinstance(d, Crank) else {d.point}
    for y in linkage.dyads:
        if isinstance(y, RRR):
            out |= {y.p, y.c, y.q}
        elif isinstance(y, RRP):
            out |= {y.p, y.c}
        elif isinstance(y, RPR):
            out |= {y.p, y.q}
        elif isinstance(y, RPP):
            out.add(y.p)
        elif isinstance(y, PRP):
            out.add(y.c)
        elif isinstance(y, Triad):
            out |= {*y.outer, *y.inner}
    return out


def _read_forces(fr: Reader, linkage: Linkage | None) -> ForceScene | None:
    links = None if linkage is None else {k: v for k, v in linkage.links().items() if k != linkage.frame_link}
    frame = None if linkage is None else linkage.frame_link
    before = len(fr.problems)
    mu_F, mu_F_path = None, fr.at("mu_F")
    given = fr.quantity("mu_F", "force", required=False, per_mm=True)
    if given is not None:
        mu_F_path = fr.at(given.key)
        x = fr.number(given.value, mu_F_path, positive=True)
        if x is not None and (why := scale_out_of_range(given.si(x))):
            fr.problem(mu_F_path, f"{x:g}: {why}")
            x = None
        mu_F = None if x is None else given.si(x)
    gravity = _non_negative(fr, "gravity", "acceleration", required=False) or 0.0

    masses: list[LinkMass] = []
    seen: dict[str, str] = {}
    for r in fr.tables_at("mass")[:MAX_ITEMS]:
        link = _link(r, links, frame)
        point = _on_link(r, _name(r, "point", "its centre of mass S, a point of that link"), link, links)
        by_weight = bool(r.present("weight"))
        if r.present("mass") and by_weight:
            r.problem(r.at(cast(str, r.present("weight"))), "give mass or weight, not both")
            r.ignore("weight")
            by_weight = False
        if by_weight:
            w = _non_negative(r, "weight", "force")
            g = gravity or 9.81  # a weight names its mass through g
            mass = None if w is None else w / g
        else:
            mass = _non_negative(r, "mass", "mass")
        inertia = _non_negative(r, "inertia", "inertia", required=False) or 0.0
        r.finish()
        if link is not None and link in seen:
            r.problem(r.at("link"), f"link {link} already has its mass ({seen[link]})")
            continue
        if link is not None:
            seen[link] = r.path
        if link is not None and point is not None and mass is not None:
            masses.append(LinkMass(link, point, mass, inertia))

    forces: list[PointForce] = []
    for k, r in enumerate(fr.tables_at("force")[:MAX_ITEMS]):
        name = _label_text(r, "name", f"F_{k + 1}")
        link = _link(r, links, frame)
        point = _on_link(r, _name(r, "point", "the point the force acts at, on that link"), link, links)
        magnitude = _non_negative(r, "force", "force")
        angle = r.scalar("angle", "angle")  # beyond 1000 turns refused where every angle is read
        resistance = bool(r.flag("resistance"))
        r.finish()
        if link is not None and point is not None and magnitude is not None and angle is not None:
            forces.append(PointForce(link, point, magnitude, angle, resistance, name))

    couples: list[LinkCouple] = []
    for k, r in enumerate(fr.tables_at("moment")[:MAX_ITEMS]):
        name = _label_text(r, "name", f"M_{k + 1}")
        link = _link(r, links, frame)
        given_moment = r.value("moment", "moment")
        moment = None if given_moment is None else _sane(r, given_moment)
        r.finish()
        if link is not None and moment is not None:
            couples.append(LinkCouple(link, moment, name))

    journals: list[RevoluteFriction] = []
    revolutes = _revolute_points(linkage) if linkage is not None else None
    spans = _joint_lengths(linkage) if linkage is not None else {}
    seen_journals: dict[str, str] = {}
    for r in fr.tables_at("journal")[:MAX_ITEMS]:
        point = _name(r, "point", "the revolute's point, e.g. point = \"B\"")
        f_v = _coefficient(r, "f_v")
        radius = _non_negative(r, "radius", "length")
        r.finish()
        if point is not None and revolutes is not None and point not in revolutes:
            r.problem(r.at("point"), f"{point} is not a revolute of the linkage (revolutes: "
                                     f"{', '.join(sorted(revolutes))})")
            continue
        if point is None or f_v is None or radius is None:
            continue
        if point in seen_journals:  # two friction circles on one joint would silently both act
            r.problem(r.at("point"), f"the journal at {point} is already given ({seen_journals[point]})")
            continue
        seen_journals[point] = r.path
        span = spans.get(point, math.inf)
        if radius >= span / 2 or f_v * radius >= span / 2:
            r.problem(r.path, f"the journal at {point} (r = {radius * 1000:g} mm, friction circle ρ = "
                              f"{f_v * radius * 1000:g} mm) is larger than the geometry allows: it must be "
                              f"smaller than half the {span * 1000:g} mm to the next joint")
            continue
        journals.append(RevoluteFriction(point, f_v, radius))

    slides: list[SlidingFriction] = []
    seen_guides: dict[str, str] = {}
    sliders = None if linkage is None else (
        {y.links[1] for y in linkage.dyads if isinstance(y, RRP)}
        | ({linkage.driver.link} if not isinstance(linkage.driver, Crank) else set())
        | {y.block_link for y in linkage.dyads if isinstance(y, RPR)}
        | {k for y in linkage.dyads if isinstance(y, (RPP, PRP)) for k in y.links})
    for r in fr.tables_at("guide")[:MAX_ITEMS]:
        value = r.raw("link", required=True, hint='the slider\'s link number, e.g. link = "3"')
        link = None if value is MISSING else r.link_id(value, r.at("link"))
        f = _coefficient(r, "f")
        r.finish()
        if link is not None and sliders is not None and link not in sliders:
            r.problem(r.at("link"), f"link {link} is not a slider (on a frame guide or a guide bar)"
                                    + (f" (sliders: {', '.join(sorted(sliders))})" if sliders else ""))
            continue
        if link is not None and link in seen_guides:
            r.problem(r.at("link"), f"link {link} already has its guide friction ({seen_guides[link]})")
            continue
        if link is not None and f is not None:
            seen_guides[link] = r.path
            slides.append(SlidingFriction(link, f))

    tolerance, iterations = 1e-10, 100
    value = fr.raw("tolerance_N")
    if value is not MISSING:
        x = fr.number(value, fr.at("tolerance_N"), positive=True)
        tolerance = x if x is not None else tolerance
    value = fr.raw("max_iterations")
    if value is not MISSING:
        if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= MAX_ITERATIONS:
            fr.problem(fr.at("max_iterations"), f"must be a whole number 1 … {MAX_ITERATIONS}")
        else:
            iterations = value
    for key in ("mass", "force", "moment", "journal", "guide"):
        value = fr.table.get(key)
        if isinstance(value, list) and len(value) > MAX_ITEMS:
            fr.problem(fr.at(key), f"too many entries ({len(value)} > {MAX_ITEMS})")
    fr.finish()
    if len(fr.problems) != before or linkage is None:
        return None
    model = ForceModel(tuple(masses), tuple(forces), tuple(couples), gravity, tuple(journals), tuple(slides),
                       tolerance, iterations)
    return ForceScene(model, mu_F, mu_F_path)


def parse_forces_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]
                       ) -> Scene[ForceScene]:
    """The rest of :func:`graphmech.scene.parse_scene` for a linkage scene with a [forces] table.

    Returns
    -------
    Scene
        A linkage scene with ``forces`` set.

    Raises
    ------
    SceneError
        With every problem found, the first in file order in the message.

    Examples
    --------
    >>> from graphmech.scene import parse_scene
    >>> scene = parse_scene({
    ...     "units": {"length": "mm", "angle": "deg"},
    ...     "find": ["M_b"],
    ...     "frame": {"A": [0, 0]},
    ...     "driver": {"type": "crank", "link": "1", "pivot": "A", "tip": "B", "length": 100,
    ...                "angle": 0, "omega_rad_s": 10},
    ...     "forces": {"force": [{"link": "1", "point": "B", "force_N": 50, "angle": -90}]},
    ... }, "crank.toml")
    >>> scene.problem.model.forces[0].magnitude, scene.show
    (50.0, ('forces', 'force_polygons'))
    """
    problems = top.problems
    title, show, find = read_header(top, FORCE_SHOW_CHOICES, FORCE_SHOW_DEFAULT)
    if "instant_centres" in show:  # a sheet of rows, one per position: not on the force sheet
        top.problem(f"show[{list(data['show']).index('instant_centres')}]",
                    "the instant centres are drawn on a linkage sheet: show them in a scene without [forces] "
                    "(find still takes P13, omega_3_ic … here)")
    scales = read_scales(top)
    linkage, positions, _ = read_linkage(top, triads=True)
    triads = [y for y in (linkage.dyads if linkage is not None else ()) if isinstance(y, Triad)]
    for j, y in enumerate(triads):  # a block's reaction on its guide has no point of action known
        if any(g is not None for g in y.guides):
            top.problem(f"triad[{j}].slider_guide", "the force analysis takes a class III group of binary links, not "
                                                  "yet one with a slider leg: draw its polygons in a scene without [forces]")
    fr = top.table_at("forces")
    forces = None if fr is None else _read_forces(fr, linkage)
    measured = read_measured(top, positions.labels if positions else None)
    precision, page = read_tail(top)
    if problems or linkage is None or forces is None:
        raise_sorted(problems, data, order, "forces", source)
    return Scene(
        source=source,
        title=title,
        show=show,
        find=find,
        scales=scales,
        linkage=linkage,
        positions=positions,
        measured=measured,
        precision_mm=precision,
        page=page,
        kind="forces",
        problem=forces,
    )


__all__ = ["FORCE_SHOW_CHOICES", "FORCE_SHOW_DEFAULT", "ForceScene", "parse_forces_scene"]
