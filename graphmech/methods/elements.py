"""Drawn elements shared by the polygons: vectors, plain segments and construction lines.

Step names carry the figure's initial (``v:`` velocity, ``a:`` acceleration) so one
construction holds both polygons without clashes. Within a figure the images of the user's
points are named by their letters (``v:c`` for C), and the construction's own points (the pole
p, the normal-component point n₂′, the Coriolis point k′) by :func:`own` (defined in
:mod:`~graphmech.methods.linkage_construction` with the poles' names), in brackets that no
point name can produce: a point named P, N2 or K has an image ``v:p``, ``a:n2'``, ``a:k'`` that
never meets them. Lines name their points with a separator (``⟂B·CD``), so B + CD ≠ BC + D.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from graphmech.methods.linkage_construction import own

if TYPE_CHECKING:
    from graphmech.construction.graph import Kind, Role
    from graphmech.geometry.kernels import Components
    from graphmech.methods.linkage_construction import LinkageConstruction


def vector(b: "LinkageConstruction", panel: str, start: str, end: str, role: Role = "result",
           kind: Kind = "vector") -> None:
    """A vector start→end drawn with an arrowhead (``kind="segment"``: a plain thin segment,
    e.g. the sides of an image triangle)."""
    name = f"{panel[0]}:{start}->{end}"
    if start != end and not b.g.has(name):
        b.g.add(name, kind, None, (start, end), role=role, text=f"{kind} {start}{end}", panel=panel)


def image(b: "LinkageConstruction", panel: str, images: dict[str, str], point: str, lab: str, kernel: Callable[..., Components],
          inputs: tuple[str, ...], text: str, say: tuple[str, ...] = ()) -> str:
    """The image of a point in a polygon (its letter ``lab``: b, c′ …), found by ``kernel``;
    ``say``: the step for the construction protocol (:class:`~graphmech.construction.graph.Step`)."""
    images[point] = b.g.add(f"{panel[0]}:{lab}", "point", kernel, inputs, role="result", text=text,
                            panel=panel, label=lab, say=say)
    return images[point]


def line(b: "LinkageConstruction", panel: str, name: str, kernel: Callable[..., Components], inputs: tuple[str, ...], text: str,
         say: tuple[str, ...] = ()) -> str:
    """A construction line ("through b draw ⟂ BC"), drawn thin through the points it carries (its
    first input); ``say`` as for :func:`image`."""
    return b.g.add(f"{panel[0]}:{name}", "line", kernel, inputs, role="construction", text=text, panel=panel,
                   say=say)


def direction(b: "LinkageConstruction", x: str, y: str) -> str:
    """The direction X→Y on the kinematic diagram, as one shared step (unit vector and length)."""
    from graphmech.geometry.kernels import unit

    a, c = b.mech[x], b.mech[y]
    name = f"dir:{a}->{c}"
    if not b.g.has(name):
        b.g.add(name, "scalar", unit, (a, c), role="hidden", text=f"direction {x}{y}", panel="mechanism")
    return name


__all__ = ["direction", "image", "line", "own", "vector"]
