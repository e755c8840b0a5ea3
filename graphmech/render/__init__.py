"""Renderers: they draw primitives with roles and know nothing of methods or checking."""
