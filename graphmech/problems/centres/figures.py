"""The figure of an instant-centre scene given by its direct centres: the wheels as circles at μl
(a fixed ring hatched on its outside as the frame), the revolutes (a frame pivot where a link
turns on the frame), an arm drawn between two revolutes of one link (a carrier), every centre
P_ij marked and labelled, each line of three centres of three links (Kennedy's line, on which
the book reads ω_i/ω_j) thin; beside it the polygon of links.
"""
from __future__ import annotations

import math
import re
from itertools import combinations

from graphmech.drawing.lettering import LETTER, MINUS, scale_text
from graphmech.drawing.primitives import (
    Circle,
    FixedPivot,
    Hinge,
    Label,
    Panel,
    Primitive,
    Segment,
    Sheet,
)
from graphmech.problems.centres.check import CentresAnalysis, text_lines
from graphmech.problems.instant_centres.figures import circle_panel, label

#: Hatch strokes on a fixed ring: every this many degrees, this long (mm).
HATCH_DEG, HATCH_MM = 6.0, 3.0


def drive_items(an: CentresAnalysis) -> list[Primitive]:
    """The mechanism and its centres, drawing mm at μl."""
    d, ic, mu = an.scene.problem.drive, an.ic, an.mu_l
    pts = {n: (p[0] / mu, p[1] / mu) for n, p in d.points.items()}
    items: list[Primitive] = []
    for w in d.wheels:
        c, r = pts[w.centre], w.radius / mu
        items.append(Circle(c, r, "given"))
        if w.link == d.frame:  # the frame's ring: hatched on the side away from its working surface
            s = 1.0 if w.internal else -1.0
            for k in range(int(360 / HATCH_DEG)):
                a = math.radians(k * HATCH_DEG)
                p0 = (c[0] + r * math.cos(a), c[1] + r * math.sin(a))
                b = a + s * math.radians(45.0)  # the stroke leaves the ring at 45°, to the fixed side
                p1 = (p0[0] + s * HATCH_MM * math.cos(b), p0[1] + s * HATCH_MM * math.sin(b))
                items.append(Segment(p0, p1, "construction"))
        ang = math.radians(150.0)
        at = (c[0] + 0.6 * r * math.cos(ang), c[1] + 0.6 * r * math.sin(ang)) if not w.internal else \
            (c[0] + (r + HATCH_MM + 2.0) * math.cos(ang), c[1] + (r + HATCH_MM + 2.0) * math.sin(ang))
        items.append(Label(w.link, at, (), LETTER, italic=False))
    by_link: dict[str, list[str]] = {}
    for rev in d.revolutes:
        for x in rev.links:
            by_link.setdefault(x, []).append(rev.at)
    for lid, names in by_link.items():  # an arm (a carrier) joins two revolutes of one moving link
        if lid == d.frame:
            continue
        for n0, n1 in combinations(dict.fromkeys(names), 2):
            items.append(Segment(pts[n0], pts[n1], "given"))
            mid = ((pts[n0][0] + pts[n1][0]) / 2, (pts[n0][1] + pts[n1][1]) / 2)
            items.append(Label(lid, mid, (), LETTER, italic=False))
    for rev in d.revolutes:
        items.append(FixedPivot(pts[rev.at]) if d.frame in rev.links else Hinge(pts[rev.at]))
    for i, j, m in combinations(ic.links, 3):  # Kennedy's lines: three centres of three links in line
        cs = [ic.centre(i, j), ic.centre(j, m), ic.centre(i, m)]
        ps = [x.point for x in cs if x.point is not None]
        if len(ps) == 3 and max(math.dist(p, q) for p, q in combinations(ps, 2)) > 1e-6 * ic.size:
            far = max(combinations(ps, 2), key=lambda pq: math.dist(*pq))
            items.append(Segment(far[0], far[1], "construction", dashed=True))
    for key in ic.order:
        p = ic.centres[key].point
        if p is not None:
            items.append(Circle(p, 0.9, "result"))
            items.append(Label(label(*key), p, ((1.0, 0.0), (-1.0, 0.0))))
    return items


def centres_sheet(an: CentresAnalysis, page: tuple[float, float], footer: tuple[str, ...] = ()) -> Sheet:
    """The mechanism with its centres, and the polygon of links."""
    notation = an.scene.page.notation
    # the check's lines, lettered: a true minus on the drawing (−0.75), not a hyphen
    notes = (scale_text("l", an.mu_l),) + tuple(re.sub(r"(?<![\w)])-(?=\d)", MINUS, line)
                                               for line in text_lines(an) if line.startswith("ω"))
    panels = (Panel("centres", "Instant centres" if notation == "en" else ("瞬心" if notation == "zh" else
                                                                           "Мгновенные центры скоростей"),
                    tuple(drive_items(an)), notes, row=0, scales=(("l", an.mu_l),)),
              circle_panel("polygon", an.ic, row=0, notation=notation))
    return Sheet(an.scene.title, panels, page, footer)


__all__ = ["centres_sheet", "drive_items"]
