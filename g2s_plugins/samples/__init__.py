"""Procedural sample levels with known ground truth (see ``levels``; ``rooms`` adds doors and ramps)."""

# levels first: rooms builds on its helpers and levels registers the room samples.
from g2s_plugins.samples import levels as levels  # noqa: F401
