"""Cam followers: the interface every follower implements (:mod:`.base`), the flat face, the roller and the pivoted
roller finger (:mod:`.finger`).

``REGISTRY`` maps the specification's ``follower`` value to its class; :func:`follower_of` builds the follower of
a cam.  A new follower is a new module here, imported below (see :mod:`valvetrain.followers.base`).
"""

from .base import REGISTRY, Follower, follower_of, register
from .flat import FlatFollower
from .roller import RollerFollower
from .finger import PivotedFollower

FLAT = FlatFollower()
"""The flat follower (it has no dimensions)."""

__all__ = ["FLAT", "FlatFollower", "Follower", "REGISTRY", "PivotedFollower", "RollerFollower", "follower_of", "register"]
