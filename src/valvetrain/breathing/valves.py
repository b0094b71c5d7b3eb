"""The valves' effective flow areas from their lift: a discharge coefficient against lift over diameter, forward and
reverse, on a reference area.

A measured table gives C_D(L/D) for each direction (forward: into the cylinder for an intake valve, out of it for an
exhaust valve), referred either to the port area pi D^2 / 4 (the reference of 1-D engine codes such as GT-POWER) or
to the curtain area pi D L; without a table the effective area is :data:`DEFAULT_CD` times the valve's flow section
of :func:`valvetrain.flow.curtain_area`, no larger than the throat.  SI units: m, m^2.
"""

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..flow import circle_area, curtain_area
from ..locale import NoteText

DEFAULT_CD = 0.7
"""Discharge coefficient on the flow section (the curtain area, at most the throat area) used where no measured table
is given: an assumption of this package, a typical curtain-area coefficient of a poppet valve in steady flow, whose
measured values depend on the lift and the port (Heywood (1988), section 6.3); a measured table replaces it, and the
breathing's results say which was used."""

REFERENCES = ("port", "curtain")
"""Reference areas of a C_D table: the port area pi D^2 / 4, or the curtain area pi D L."""


class CdTableError(InputError):
    """A discharge-coefficient table that cannot be used; the message names what is wrong."""


@dataclass(frozen=True)
class CdTable:
    """Discharge coefficients of a valve against its lift over the reference diameter.

    Attributes
    ----------
    l_over_d : ndarray
        Lift over the reference diameter, strictly increasing, from 0 or above.
    forward, reverse : ndarray
        C_D of the forward and the reverse flow at each L/D, 0 to 1.
    diameter : float
        Reference diameter D [m].
    reference : str
        ``"port"`` or ``"curtain"`` (:data:`REFERENCES`).
    source : str
        Where the table comes from (a file name), for the messages.
    """

    l_over_d: np.ndarray
    forward: np.ndarray
    reverse: np.ndarray
    diameter: float
    reference: str = "port"
    source: str = "discharge-coefficient table"

    def __post_init__(self):
        check_table(self.l_over_d, self.forward, self.reverse, self.reference, self.source)


def check_table(l_over_d, forward, reverse, reference, source="discharge-coefficient table") -> None:
    """Refuse a C_D table that is not a function of L/D or holds a coefficient outside 0...1.

    Raises
    ------
    CdTableError
        Naming the row and the value.
    """
    x = np.asarray(l_over_d, dtype=float)
    if reference not in REFERENCES:
        raise CdTableError(NoteText.of("cd.reference", where=source, reference=repr(reference),
                                       allowed=", ".join(REFERENCES)))
    if x.ndim != 1 or x.size < 2:
        raise CdTableError(NoteText.of("cd.two_rows", where=source))
    for name, cd in (("forward", forward), ("reverse", reverse)):
        cd = np.asarray(cd, dtype=float)
        if cd.shape != x.shape:
            raise CdTableError(NoteText.of("cd.sizes", where=source, count=cd.size, direction=name, values=x.size))
        bad = np.flatnonzero(~((cd >= 0.0) & (cd <= 1.0)))
        if bad.size:
            raise CdTableError(NoteText.of("cd.range", where=source, row=bad[0] + 1, direction=name, value=cd[bad[0]]))
    if x[0] < 0.0:
        raise CdTableError(NoteText.of("cd.negative", where=source, value=x[0]))
    steps = np.flatnonzero(np.diff(x) <= 0.0)
    if steps.size:
        i = steps[0] + 1
        raise CdTableError(NoteText.of("cd.increasing", where=source, row=i + 1, value=x[i], previous=x[i - 1]))


def effective_areas(lift, table) -> tuple[np.ndarray, np.ndarray]:
    """Effective flow areas C_D A_R of a valve at the given lifts, forward and reverse [m^2].

    Parameters
    ----------
    lift : array_like
        Valve lift L [m]; zero or less is a shut valve.
    table : CdTable

    Returns
    -------
    (ndarray, ndarray)
        Forward and reverse effective areas.

    Notes
    -----
    :math:`A_E = C_D(L/D)\\,A_R` with :math:`A_R = \\pi D^2 / 4` (port) or :math:`\\pi D L` (curtain); C_D linear
    between the rows, the last row's beyond the table; a port-referred table is taken to 0 at zero lift (the valve
    shuts), a curtain-referred one's area vanishes with the lift.

    References
    ----------
    Heywood (1988), section 6.3 and Appendix C (the effective area of a valve).

    Examples
    --------
    A port-referred C_D of 0.5 at L/D = 0.25 on a 40 mm port: 0.5 pi 0.04^2 / 4 = 628.3 mm^2 at 10 mm lift.

    >>> t = CdTable(np.array([0.0, 0.25]), np.array([0.0, 0.5]), np.array([0.0, 0.4]), 0.04)
    >>> [round(float(a) * 1e6, 1) for a in effective_areas(0.010, t)]
    [628.3, 502.7]
    """
    lift = np.clip(np.asarray(lift, dtype=float), 0.0, None)
    x, fwd, rev = table.l_over_d, table.forward, table.reverse
    if table.reference == "port":
        if x[0] > 0.0:
            x, fwd, rev = np.r_[0.0, x], np.r_[0.0, fwd], np.r_[0.0, rev]
        area = circle_area(table.diameter)
    else:
        area = np.pi * table.diameter * lift
    ratio = lift / table.diameter
    shut = lift <= 0.0
    return (np.where(shut, 0.0, np.interp(ratio, x, fwd) * area),
            np.where(shut, 0.0, np.interp(ratio, x, rev) * area))


def default_areas(lift, throat_diameter, seat_angle, cd=DEFAULT_CD) -> np.ndarray:
    """Effective flow area of a valve without a measured table: C_D times its flow section, at most the throat [m^2].

    Parameters
    ----------
    lift : array_like
        Valve lift [m].
    throat_diameter : float
        [m].
    seat_angle : float
        Seat angle from the valve face plane [rad].
    cd : float
        :data:`DEFAULT_CD`.

    Returns
    -------
    ndarray
        The same area forward and reverse.

    Notes
    -----
    :math:`A_E = C_D \\min(f(L), \\pi d^2 / 4)`, f the frustum's curtain area of
    :func:`valvetrain.flow.curtain_area`.

    References
    ----------
    Valve-train practical works (n.d.), work 1, eq. (1.3) (the flow section); :data:`DEFAULT_CD`.
    """
    return cd * np.minimum(curtain_area(lift, throat_diameter, seat_angle), circle_area(throat_diameter))
