"""The drawing vocabulary figures are made of: primitives (segments, arcs, arrows, labels in a
panel at a scale μ, panels on a sheet) and lettering. The renderer (:mod:`graphmech.render`)
lays them out and writes them; the figures of each kind of problem produce them."""
