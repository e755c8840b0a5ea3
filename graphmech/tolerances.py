"""The shared tolerances, in one place."""

#: Relative agreement required between graphical and exact values in regular positions.
REL_AGREEMENT = 1e-9

#: |sin| of the angle between two lines below which they count as parallel (no intersection).
PARALLEL_SIN = 1e-13

#: Machine epsilon used in error estimates.
EPS = 2.220446049250313e-16

#: Condition number of an intersection above which results depending on it are reported as
#: ill-conditioned. Near a toggle the same shallow angle recurs in the position, velocity and
#: acceleration constructions, each feeding the next, and the error observed grows like
#: COND_SAFETY·EPS·cond²; against a 50-digit reference near a four-bar's toggle the factor
#: reached ≈ 19, so flag where 20·EPS·cond² passes REL_AGREEMENT (cond ≈ 475, about 0.12°).
COND_SAFETY = 20.0
COND_WARN = (REL_AGREEMENT / (COND_SAFETY * EPS)) ** 0.5

#: Angle (degrees) between two construction lines below which a *hand* construction is unreliable
#: (a 0.5 mm pencil error grows by 1/sin of this angle, ≥ 14×).
SHALLOW_DEG = 4.0

#: Two points closer than this, relative to the size of their coordinates, are one point
#: (rounding, not a direction).
COINCIDENT_REL = 1e-12

#: Relative slack with which two circles that "just touch" still count as meeting (tangent).
TANGENT_REL = 1e-9

#: Default drawing precision for judging a hand construction, in drawing millimetres.
DRAWING_PRECISION_MM = 0.5
#: The coarsest drawing precision a check accepts, mm: coarser judges nothing (and 1e308 overflowed).
MAX_PRECISION_MM = 10.0


#: A stated scale μ (SI units per drawing mm) outside this range draws a textbook figure on no
#: page (1e-15 m/mm puts a metre at 1e15 mm) and sends 1/μ or lengths/μ to inf or 0 on the way:
#: refused when read. Each sheet then bounds what its own quantities draw (0.1 mm … the page).
SCALE_RANGE_SI = (1e-15, 1e15)

#: A pole distance H (drawing mm) of graphical differentiation or integration: under 1 mm the
#: rays cannot be drawn and H·Δy/Δx overflows; over 1 m the pole leaves the page.
POLE_RANGE_MM = (1.0, 1000.0)
