"""Geometry: frozen value objects and pure construction functions (kernels).

The kernels in :mod:`graphmech.geometry.kernels` work on plain components
(``x, y`` as floats for one position, or numpy arrays for many) so that one body of
code serves the fast single-position path and the vectorised batch path.
"""
from graphmech.geometry.primitives import Circle, Line, Point, Vector

__all__ = ["Point", "Vector", "Line", "Circle"]
