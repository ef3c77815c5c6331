"""Points and directions as the run's data holds them (:data:`g2s_core.model.Vec3`): tuples of 3 Python floats.

Shared by the plugins that make positions from numpy rows, YAML lists or JSON
arrays (openings, points terminals, sample levels, the JSON reader); the core
itself builds none.
"""

from __future__ import annotations

from typing import Any

from g2s_core.model import Vec3


def vec3(values: Any) -> Vec3:
    """Return ``values`` (any 3-sequence) as a tuple of 3 Python floats."""
    x, y, z = (float(v) for v in values)
    return (x, y, z)
