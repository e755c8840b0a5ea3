"""Dynamics and efficiency through a gear train (``[train.dynamics]``, ``[train.efficiency]``):
moments of inertia and moments reduced to a chosen member (planets: their carrier motion and
spin), the efficiency of trains in series and of a planetary train by the converted-train
method, a worm's self-locking. Being built (issue 19)."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class TrainDynamics:
    """Placeholder: the dynamics tables of a train scene in SI."""
