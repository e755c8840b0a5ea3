"""graphmech: the textbook's graphical methods of the theory of machines as exact geometric
constructions, drawn to SVG at stated scales μ and checked against independent exact solutions."""

__version__ = "0.1.0"
