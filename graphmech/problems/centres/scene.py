"""Read an instant-centre scene given by its direct centres: the ``[centres]`` table.

A mechanism that is no linkage of dyads — wheels in pure rolling contact, a friction planetary
drive — is stated by its links and their *direct* instant centres: revolutes at named points
(``[[centres.revolute]]``) and rolling contacts where two links' wheels touch
(``[[centres.rolling]]``, the point found from ``[[centres.wheel]]``). Kennedy's theorem finds
the rest (:mod:`graphmech.problems.centres.check`); the format is in docs/scene-format.md
("Instant centres from the direct centres").
"""
from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from graphmech.mechanisms.rolling import (
    Revolute,
    Rolling,
    RollingDrive,
    Wheel,
    contact,
    on_wheel,
)
from graphmech.problems.reader import (
    LINKAGE_KEYS,
    MISSING,
    POINT_NAME,
    Reader,
    Scene,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
    say,
)

#: What a centres scene may show.
CENTRES_SHOW_CHOICES = ("instant_centres",)
#: The find names: a centre (P12, x_P12, y_P12), ω by the centres (omega_2_ic), ω_i/ω_j (ratio_1_2).
CENTRE_NAME = re.compile(r"(x_|y_)?P([0-9A-Za-z]+?)_?([0-9A-Za-z]+)")
OMEGA_NAME = re.compile(r"omega_([0-9A-Za-z]{1,8})_ic")
RATIO_NAME = re.compile(r"ratio_([0-9A-Za-z]{1,8})_([0-9A-Za-z]{1,8})")
#: The most wheels, revolutes or contacts one scene may list.
MAX_ITEMS = 50


@dataclass(frozen=True)
class CentresScene:
    """The drive, and each rolling contact's point as the scene gave it (None: found from the wheels)."""

    drive: RollingDrive


def _links(r: Reader, key: str, two: bool) -> tuple[str, ...] | None:
    value = r.raw(key, required=True, hint='a list of link numbers such as ["1", "2"]')
    if value is MISSING:
        return None
    if not isinstance(value, list) or len(value) < 2 or (two and len(value) != 2):
        r.problem(r.at(key), ("must be a list of the two links in contact" if two else
                              "must be a list of two or more links (a compound hinge: more)") +
                  f', such as ["1", "2"], not {say(value)}')
        return None
    out = [r.link_id(v, f"{r.at(key)}[{i}]") for i, v in enumerate(value)]
    if any(x is None for x in out):
        return None
    if len(set(out)) != len(out):
        r.problem(r.at(key), "a link is listed twice")
        return None
    return tuple(x for x in out if x is not None)


def _read(c: Reader) -> RollingDrive | None:
    frame = c.raw("frame", required=True, hint='the fixed link\'s number, e.g. frame = "4"')
    frame_id = None if frame is MISSING else c.link_id(frame, c.at("frame"))
    driver = c.raw("driver", required=True, hint='the driving link\'s number, e.g. driver = "1"')
    driver_id = None if driver is MISSING else c.link_id(driver, c.at("driver"))
    omega = c.scalar("omega", "omega")
    points: dict[str, tuple[float, float]] = {}
    pts = c.table_at("points", required=True, hint="the named points, e.g. points = { O = [0, 0] }")
    if pts is not None:
        for key in list(pts.table):
            if key in pts.used:
                continue
            name = key.split("_", 1)[0]
            if not POINT_NAME.fullmatch(name) or len(name) > 8:
                continue  # finish() reports it
            xy = pts.pair(name)
            if xy is not None:
                points[name] = xy
        pts.finish("a point is named in capitals with its coordinates, e.g. O_mm = [0, 0]")
    wheels: list[Wheel] = []
    tables = {k: c.tables_at(k) for k in ("wheel", "revolute", "rolling")}
    for key, ts in tables.items():
        if len(ts) > MAX_ITEMS:
            c.problem(c.at(key), f"{len(ts)} entries: at most {MAX_ITEMS}")
            return None
    for w in tables["wheel"]:
        link = w.raw("link", required=True, hint='the link the wheel belongs to, e.g. link = "2"')
        lid = None if link is MISSING else w.link_id(link, w.at("link"))
        centre = w.raw("centre", required=True, hint='the wheel\'s centre, a point name such as "C"')
        cname = None if centre is MISSING else w.point_name(centre, w.at("centre"))
        radius = w.scalar("radius", "length", positive=True)
        internal = w.flag("internal")
        w.finish()
        if cname is not None and points and cname not in points:
            w.problem(w.at("centre"), f"no point {cname!r} in {c.at('points')}")
        elif lid is not None and any(x.link == lid for x in wheels):
            w.problem(w.at("link"), f"link {lid!r} has a wheel already: one wheel per link")
        elif lid is not None and cname is not None and radius is not None:
            wheels.append(Wheel(lid, cname, radius, bool(internal)))
    revolutes: list[Revolute] = []
    for r in tables["revolute"]:
        links = _links(r, "links", two=False)
        at = r.raw("at", required=True, hint='the joint, a point name such as "O"')
        joint = None if at is MISSING else r.point_name(at, r.at("at"))
        r.finish()
        if joint is not None and points and joint not in points:
            r.problem(r.at("at"), f"no point {joint!r} in {c.at('points')}")
        elif links is not None and joint is not None:
            revolutes.append(Revolute(links, joint))
    contacts: list[Rolling] = []
    for r in tables["rolling"]:
        links = _links(r, "links", two=True)
        given = r.pair("at", required=False)
        r.finish()
        if links is None:
            continue
        found = _contact(r, links, wheels, points, given)
        if found is not None:
            contacts.append(Rolling((links[0], links[1]), found))
    if not tables["rolling"] and not tables["revolute"]:
        c.problem(c.at("revolute"), "no [[centres.revolute]] or [[centres.rolling]]: state the direct centres")
    c.finish()
    if c.problems or frame_id is None or driver_id is None or omega is None:
        return None
    drive = RollingDrive(frame_id, driver_id, omega, points, tuple(wheels), tuple(revolutes), tuple(contacts))
    _connected(c, drive)
    return drive


def _contact(r: Reader, links: tuple[str, ...], wheels: list[Wheel], points: Mapping[str, tuple[float, float]],
             given: tuple[float, float] | None) -> tuple[float, float] | None:
    """The contact point of the two links' wheels (checked against ``at`` where given)."""
    ws = [next((w for w in wheels if w.link == x), None) for x in links]
    for x, w in zip(links, ws):
        if w is None:
            r.problem(r.at("links"), f"link {x!r} has no [[centres.wheel]]: a rolling contact is where two wheels touch")
            return None
    a, b = ws
    assert a is not None and b is not None
    if a.centre not in points or b.centre not in points:
        return None
    found = contact(a, points[a.centre], b, points[b.centre])
    if isinstance(found, str):
        r.problem(r.at("links"), found)
        return None
    if given is not None:
        for w in (a, b):
            if not on_wheel(w, points[w.centre], given):
                d = math.dist(points[w.centre], given)
                r.problem(r.at(r.present("at") or "at"),
                          f"({given[0] * 1e3:g}, {given[1] * 1e3:g}) mm is not on wheel {w.link}: "
                          f"{d * 1e3:.6g} mm from {w.centre}, its radius is {w.radius * 1e3:g} mm")
                return None
        if math.dist(given, found) > 1e-6 * max(a.radius, b.radius):
            r.problem(r.at(r.present("at") or "at"),
                      f"the wheels touch at ({found[0] * 1e3:.6g}, {found[1] * 1e3:.6g}) mm, not there")
            return None
    return found


def _connected(c: Reader, d: RollingDrive) -> None:
    """The frame and the driver take part, and the driver turns about a revolute on the frame."""
    links = d.links()
    if not any(d.frame in r.links for r in d.revolutes) and not any(d.frame in x.links for x in d.contacts):
        c.problem(c.at("frame"), f"no revolute or contact joins the frame {d.frame!r}")
    if d.driver == d.frame:
        c.problem(c.at("driver"), "the driver is the frame: it does not turn")
    elif not any(d.frame in r.links and d.driver in r.links for r in d.revolutes):
        c.problem(c.at("driver"), f"link {d.driver!r} must turn about a revolute on the frame {d.frame!r}")
    if len(links) < 3:
        c.problem(c.at("revolute"), "fewer than three links: nothing for Kennedy's theorem")


def parse_centres_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]
                        ) -> Scene[CentresScene]:
    """The rest of :func:`graphmech.scene.parse_scene` for a scene with a [centres] table.

    Examples
    --------
    >>> from graphmech.scene import parse_scene
    >>> s = parse_scene({"units": {"length": "mm", "omega": "rad/s"}, "centres": {
    ...     "frame": "4", "driver": "1", "omega": 10, "points": {"O": [0, 0], "C": [55, 0]},
    ...     "wheel": [{"link": "1", "centre": "O", "radius": 40}, {"link": "2", "centre": "C", "radius": 15},
    ...               {"link": "4", "centre": "O", "radius": 70, "internal": True}],
    ...     "revolute": [{"links": ["1", "4"], "at": "O"}],
    ...     "rolling": [{"links": ["1", "2"]}, {"links": ["2", "4"]}]}}, "planetary.toml")
    >>> [c.at for c in s.problem.drive.contacts], s.problem.drive.links()
    ([(0.04, 0.0), (0.07, 0.0)], ('1', '2', '4'))
    """
    problems = top.problems
    title, show, find = read_header(top, CENTRES_SHOW_CHOICES, CENTRES_SHOW_CHOICES)
    scales = read_scales(top, entries=(("l", "length"),))
    for key in LINKAGE_KEYS:
        if key in data:
            top.used.add(key)
            top.problem(key, "belongs to a linkage scene; this scene states its direct centres ([centres]): "
                             "put each in a scene of its own")
    c = top.table_at("centres")
    drive = None if c is None else _read(c)
    measured = read_measured(top, None, cam=True)
    precision, page = read_tail(top)
    if problems or drive is None:
        raise_sorted(problems, data, order, "centres", source)
    assert drive is not None
    for i, name in enumerate(find):
        why = name_problem(name.partition("@")[0], drive.links(), drive.frame)
        if why:
            top.problem(f"find[{i}]", why)
    for name, _ in measured:
        why = name_problem(name, drive.links(), drive.frame)
        if why:
            top.problem(f"measured.{name}", why)
    if problems:
        raise_sorted(problems, data, order, "centres", source)
    return Scene(source=source, title=title, show=show, find=find, scales=scales, measured=measured,
                 precision_mm=precision, page=page, kind="centres", problem=CentresScene(drive))


def parse_name(name: str, links: tuple[str, ...]) -> tuple[str, tuple[str, ...]] | None:
    """``("centre", (coord, i, j))``, ``("omega", (k,))`` or ``("ratio", (i, j))``; None if not a name of this kind."""
    m = CENTRE_NAME.fullmatch(name)
    if m:
        i, j = _split(m.group(2), m.group(3), links)
        return "centre", (m.group(1) or "", i, j)
    m = OMEGA_NAME.fullmatch(name)
    if m:
        return "omega", (m.group(1),)
    m = RATIO_NAME.fullmatch(name)
    if m:
        return "ratio", (m.group(1), m.group(2))
    return None


def _split(a: str, b: str, links: tuple[str, ...]) -> tuple[str, str]:
    """``P12`` → ("1", "2"); a longer ``P1_10`` as written."""
    text = a + b
    for k in range(1, len(text)):
        if text[:k] in links and text[k:] in links:
            return text[:k], text[k:]
    return a, b


def name_problem(name: str, links: tuple[str, ...], frame: str) -> str:
    """Why ``name`` is not a value of this scene ("" if it is)."""
    parsed = parse_name(name, links)
    listed = ", ".join(links)
    if parsed is None:
        return (f"unknown quantity {name!r}: a centres scene finds P12 (x_P12, y_P12), omega_2_ic, ratio_1_2 "
                f"(links: {listed})")
    kind, args = parsed
    ids = args[1:] if kind == "centre" else args
    for x in ids:
        if x not in links:
            return f"{name!r}: no link {x!r} (links: {listed})"
    if len(set(ids)) != len(ids):
        return f"{name!r}: the two links must differ"
    if kind == "omega" and args[0] == frame or kind == "ratio" and frame in args:
        return f"{name!r}: link {frame} is the frame: it does not turn"
    return ""


__all__ = ["CENTRES_SHOW_CHOICES", "CentresScene", "name_problem", "parse_centres_scene", "parse_name"]
