"""Read a gear-train scene (``[train]``) into a :class:`TrainScene`: the model
(:class:`graphmech.mechanisms.gear_train.GearTrain`, spatial meshes' senses resolved from the
arrows), and what the drawing needs (the module, each member's axis, the sides and ``towards`` of
the meshes). The keys: docs/scene-format.md, "Gear-train scenes".
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from graphmech.mechanisms.gear_train import GearTrain

if TYPE_CHECKING:
    from graphmech.problems.reader import Reader, Scene
    from graphmech.problems.trains.dynamics import TrainDynamics

#: What a gear-train scene may show.
TRAIN_SHOW_CHOICES = ("schematic", "velocity")


@dataclass(frozen=True)
class TrainScene:
    """A ``[train]`` table in SI.

    train : the model; its ``inputs`` hold the first value of each input (a list input's others
        are in ``input_values``), spatial meshes' ``sign`` resolved from ``towards`` and ``hand``.
    module : m in metres (1 mm when not stated: ``module_stated`` False, radii in module units).
    axes : member → its axis in the drawing (``"+x"`` … ``"-z"``), every member listed.
    sides : mesh index → +1 (b's axis above a's, the default) or −1 (below); parallel meshes only.
    towards : mesh index → the directions from a's and b's axes to the pitch point (spatial meshes
        that state them).
    hands : mesh index → ``"right"`` or ``"left"`` (worm meshes).
    coaxial : pairs of members the scene puts on one axis although no mesh says so.
    solved_z : gear → the tooth number solved from the coaxial condition (``"coaxial"`` in ``z``).
    input_values : member → every value of its input speed (rad/s); one value unless a list.
    stated_mobility : the ``mobility`` the scene expects (None: not stated).
    pole_distance : H of the velocity diagram's ω line in drawing mm (None: chosen).
    dynamics : the dynamics and efficiency tables (None: not posed).
    """

    train: GearTrain
    module: float = 1e-3
    module_stated: bool = False
    axes: Mapping[str, str] = field(default_factory=dict)
    sides: Mapping[int, int] = field(default_factory=dict)
    towards: Mapping[int, tuple[str, str]] = field(default_factory=dict)
    hands: Mapping[int, str] = field(default_factory=dict)
    coaxial: tuple[tuple[str, str], ...] = ()
    solved_z: Mapping[str, int] = field(default_factory=dict)
    input_values: Mapping[str, tuple[float, ...]] = field(default_factory=dict)
    stated_mobility: int | None = None
    pole_distance: float | None = None
    dynamics: TrainDynamics | None = None


def parse_train_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[TrainScene]:
    """The whole scene file, ``[train]`` and the common tables (docs/scene-format.md)."""
    raise NotImplementedError  # the reader is being built (issue 19)
