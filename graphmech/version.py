"""The version of graphmech: one place (pyproject.toml reads it, ``graphmech --version`` prints it)."""

__version__ = "0.1.0"
