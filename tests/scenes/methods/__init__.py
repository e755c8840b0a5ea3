"""Shared linkages of the method tests (tests/methods/), as Python objects: see :mod:`.linkages`."""
