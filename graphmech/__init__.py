"""graphmech: the textbook's graphical methods of the theory of machines as exact geometric
constructions, drawn to SVG at stated scales μ and checked against independent exact solutions.

The Python API (:mod:`graphmech.api`)::

    import graphmech as gm
    p = gm.load("figures/scenes/kin.oscillating_block.toml")   # or gm.loads(text), gm.from_dict(d)
    table = p.check(measured={"pc": 40.5})                      # rows, verdicts, .to_json(), .to_pandas()
    p.render().save("sheet.pdf")                                # .svg; shown inline by Jupyter
    p.replace({"driver.angle": 60})                             # a variant

Importing graphmech imports nothing else: the API is loaded on first use.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from graphmech.version import __version__

if TYPE_CHECKING:
    from graphmech.api import CheckTable, Drawing, Problem, from_dict, load, loads

_API = ("CheckTable", "Drawing", "Problem", "from_dict", "load", "loads")


def __getattr__(name: str) -> Any:
    # PEP 562: `gm.load` imports the API (numpy, the registry) only when it is used
    if name in _API:
        from graphmech import api

        return getattr(api, name)
    raise AttributeError(f"module 'graphmech' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *_API])


__all__ = ["CheckTable", "Drawing", "Problem", "__version__", "from_dict", "load", "loads"]
