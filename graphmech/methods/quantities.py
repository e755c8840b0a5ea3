"""Named quantities a construction can report, and how each is measured on the drawing.

A quantity is *measured*: a scalar step of the construction returns ``(drawn_mm, scale)``,
the length on the drawing (signed where the quantity has a sense) and the μ that turns it
into a value; graphical value = drawn_mm × scale. ``exact`` says, in words the independent
check understands, which exact value it must equal (it never says *how* to compute it).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

#: What a quantity equals, read by the exact solution: a kind and its arguments, e.g.
#: ``("speed", "C")``, ``("slide_v", "C", gx, gy)``.
Exact = tuple[Any, ...]  # names (str) and, for a slide, the guide's direction (float)

#: Units of the kinematic quantities, by the name's prefix.
UNITS = {
    "v": "m/s",
    "a": "m/s²",
    "omega": "rad/s",
    "alpha": "rad/s²",
    "theta": "deg",
    "l": "m",
}


@dataclass(frozen=True)
class Quantity:
    """A reportable quantity.

    Attributes
    ----------
    name : str
        As in the scene's ``find`` (``v_C``, ``a_CB_t``, ``omega_2``, ``a_k_C2C3``).
    unit : str
        SI unit (angles in degrees).
    slot : str
        The construction step whose value is ``(drawn_mm, scale)``; for angles drawn_mm is
        the angle in degrees and scale is 1.
    exact : tuple
        What it equals, e.g. ``("speed", "C")``, ``("omega", "2")``.
    panel : str
        The figure it is measured on (mechanism, velocity, acceleration).
    segment : tuple of str
        The drawn segment's end labels (``("p", "c")``), empty for derived values.
    """

    name: str
    unit: str
    slot: str
    exact: Exact
    panel: str
    segment: tuple[str, ...] = ()
