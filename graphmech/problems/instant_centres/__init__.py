"""Instant centres of a linkage scene (``show = ["instant_centres"]``): all N(N−1)/2 centres by
Kennedy's theorem, ω and v from them, checked against the exact kinematics.

Not a kind of its own — a linkage scene asks for it — so it has no ``KIND``: the linkage's
check adds its rows (check.py), its sheet adds the panels (figures.py), its bench the records
(bench.py).
"""
