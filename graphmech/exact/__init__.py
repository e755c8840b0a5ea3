"""Independent analytical solutions, used only to check the graphical constructions.

Nothing here imports ``graphmech.construction``, ``graphmech.methods`` or ``graphmech.geometry``.
"""
from graphmech.exact.linkage import Kinematics, solve

__all__ = ["Kinematics", "solve"]
