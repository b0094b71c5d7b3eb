"""The links of the train between the contact (:mod:`valvetrain.followers`) and the valve: the interface every link
implements (:mod:`.base`), the tappet, the pushrod, the rocker, a stud-mounted rocker's pivot ball and the valve bridge
of a pair of valves (:mod:`.bridge`).

``REGISTRY`` maps a link's name to its instance; a drive layout (:mod:`valvetrain.layouts`) is a contact plus a chain
of them.  A new link is a new module here, imported below (see :mod:`valvetrain.links.base`).
"""

from .base import REGISTRY, Link, Loads, register
from .tappet import Tappet
from .pushrod import Pushrod
from .rocker import Rocker
from .rocker_pivot import RockerPivot
from .bridge import ValveBridge

__all__ = ["Link", "Loads", "Pushrod", "REGISTRY", "Rocker", "RockerPivot", "Tappet", "ValveBridge", "register"]
