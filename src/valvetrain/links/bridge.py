"""The valve bridge (crosshead) of a four-valve head: one rocker drives a pair of same-name valves through a bridge
resting on their tips.  It joins a chain with a lever (the ``rocker`` and ``pushrod`` layouts) where the valve gives
one of its keys (``[parts] bridge_span_mm``, ``bridge_width_mm``, ``bridge_height_mm``, ``[drive.masses]
bridge_kg``); a ``[valves.NAME]`` section is one valve of the pair.

The bridge moves with the valves (ratio 1): its mass per valve, ``bridge_kg`` (half the bridge), adds to the train's
mass reduced to the valve (:func:`valvetrain.layouts.train_mass`) and is a node of its own in a multi-mass train,
between the rocker's joint and the valve; its stiffness per valve (below) is a link of the drive in series with the
others (an elastic link: its mass between two halves of twice its stiffness).  It is a beam simply supported on the two valve tips
``l`` apart and loaded at mid-span by the rocker, which pushes both valves, F = 2 F_v; at its middle section (width b,
height h in the plane of bending)

.. math:: \\sigma = \\frac{M}{W}, \\qquad M = \\frac{F l}{4} = \\frac{F_v l}{2}, \\qquad W = \\frac{b h^2}{6}

and its mid-span deflection y = F l^3 / (48 E I), I = b h^3 / 12, makes its stiffness per valve (the force at one
valve per unit deflection) F_v / y = 24 E I / l^3, said in the check's note; without the three dimensions the
drive's stiffness gives it a share, as any link whose geometry is not given (:func:`valvetrain.design.dynamics.drive_links`).

References
----------
Shigley's Mechanical Engineering Design, 9th ed. (2011), Table A-9 (simple supports, centre load: M = F l / 4,
y = F l^3 / (48 E I)); Valve-train practical works (n.d.), eq. (7.15) (the bending allowable of the rocker gear's steels,
150 MPa, taken for the bridge).
"""

from .. import strength
from ..locale import note
from ..units import to_display
from .base import Link, register


def bridge_stiffness(span, width, height, modulus=strength.STEEL_MODULUS) -> float:
    """The stiffness of a valve bridge per valve, 24 E I / l^3 with I = b h^3 / 12 [N/m]: the force at one valve per
    unit mid-span deflection of a beam simply supported on the two valve tips ``span`` [m] apart, its middle section
    ``width`` x ``height`` [m], of modulus ``modulus`` [Pa] (Shigley's Mechanical Engineering Design, 9th ed. (2011),
    Table A-9).

    Examples
    --------
    A 40 mm span, 14 x 12 mm section, steel: I = 14 * 12^3 / 12 = 2016 mm^4, 24 * 2.1e5 * 2016 / 40^3 = 158760 N/mm.

    >>> round(bridge_stiffness(0.040, 0.014, 0.012) / 1e3)
    158760
    """
    return 24.0 * modulus * width * height**3 / 12.0 / span**3


@register
class ValveBridge(Link):
    """A valve bridge between the rocker and a pair of valves: an elastic link of the train at the valve."""

    name = "valve_bridge"
    mass_key = mass_attr = "bridge_kg"
    elastic = True
    at_valve = True
    part_keys = ("bridge_span_mm", "bridge_width_mm", "bridge_height_mm")

    def joins(self, links, valve) -> bool:
        """Where a lever drives it (a link of ``links`` is a :attr:`~valvetrain.links.Link.lever`) and the valve (SI
        view) gives one of its keys or its mass."""
        masses = valve.drive.masses
        return any(link.lever for link in links) and (self.given(valve.parts.section)
                                                       or (masses is not None and masses.bridge_kg is not None))

    def valve_mass(self, masses) -> float:
        """Its mass per valve [kg] (``[drive.masses] bridge_kg``, 0 not given): it moves with the valve, ratio 1."""
        return masses.bridge_kg or 0.0

    def stiffness(self, parts) -> float | None:
        """Its stiffness per valve, 24 E I / l^3 (:func:`bridge_stiffness`), where its span and section are given."""
        if None in (parts.bridge_span, parts.bridge_width, parts.bridge_height):
            return None
        return bridge_stiffness(parts.bridge_span, parts.bridge_width, parts.bridge_height)

    def node(self, masses, ratio, arm) -> tuple[str, float] | None:
        """Its node in a multi-mass train: its mass per valve at the valve (ratio 1, whatever the rocker's)."""
        return (self.name, masses.bridge_kg) if masses.bridge_kg else None

    def checks(self, loads) -> list:
        """Its bending stress at mid-span under the rocker's force on both valves, 2 x the valve force, where its span
        and section are given; the note gives its stiffness per valve."""
        if not loads.need(list(self.part_keys), "bridge_bending"):
            return []
        parts = loads.parts
        moment = 2.0 * loads.valve_force * parts.bridge_span / 4.0
        stress = strength.rectangle_bending_stress(moment, parts.bridge_width, parts.bridge_height)
        stiffness = bridge_stiffness(parts.bridge_span, parts.bridge_width, parts.bridge_height)
        return [strength.verdict("bridge_bending", stress, loads.where + note(
            "strength.bridge_beam", moment_Nm=moment, stiffness_N_mm=to_display(stiffness, "N/mm")))]
