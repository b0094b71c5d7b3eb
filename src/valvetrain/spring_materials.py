"""Valve-spring wire grades: shear modulus, density, allowable stress and fatigue limits (SI).

The strength of a drawn or oil-tempered wire falls with its diameter, so the limits are
functions of the wire diameter d [m]; every function takes and returns numpy arrays.

Grades (:data:`GRADES`, selected by ``[valves.NAME.spring] material``):

``60S2A``
    The manual's spring steels (60G, 65G, 60S2A, 60S2G, 50KhGA, 50KhFA, HRC 40-45, shot
    peened) with the middle of its ranges, the same for every wire: G = 8.0e4 MPa
    (7.6-8.2e4), rho = 7850 kg/m3 (7800-7900), [tau] = 500 MPa (350-600), tau_-1 = 370 MPa
    (340-400) (Valve-train practical works (n.d.), work 6).  The mean-stress factor psi_tau = 0.2 of the fatigue check
    is not in the manual (corrections note 24; 0.1-0.2 in the literature).

``VDSiCr``, ``VDCrV``
    The valve-spring grades of oil-hardened and tempered chrome-silicon and chrome-vanadium
    wire (EN 10270-2; 54SiCr6-type, e.g. OTEVA 70, and 51CrV4-type).  The design sources give no
    figures for them; from the engineering literature:

    * G = 79.5 GPa, rho = 7850 kg/m3: EN 13906-1 (cylindrical helical compression springs),
      values for oil-hardened and tempered wire to EN 10270-2.
    * Minimum tensile strength R_m = A / d^m with d in mm: R. G. Budynas, J. K. Nisbett,
      *Shigley's Mechanical Engineering Design*, 9th ed., McGraw-Hill 2011, Table 10-4:
      chrome-vanadium ASTM A232 (the valve-spring quality, as VDCrV) A = 2005 MPa mm^m,
      m = 0.168 for d = 0.8-11.1 mm; chrome-silicon ASTM A401 A = 1974 MPa mm^m, m = 0.108 for
      d = 1.6-9.5 mm.  A401 is the commercial chrome-silicon wire; its strength is taken for
      the valve-spring grade VDSiCr, which is assumed to be at least as strong (the grades
      differ in cleanliness and surface quality).
    * Allowable stress at the full-lift load [tau] = 0.50 R_m: Shigley Table 10-6 (maximum
      allowable torsional stress of hardened and tempered low-alloy steel springs before set
      removal, after Joerres); EN 13906-1 allows the same 0.5 R_m under static load.
    * Fatigue (infinite life) of shot-peened springs: Zimmerli's data, independent of
      material and size below 10 mm, S_sa = 398 MPa at S_sm = 534 MPa (Shigley section
      10-9), with the torsional ultimate strength S_su = 0.67 R_m (Shigley section 10-9).
      The Goodman line through that point and S_su gives the fully reversed limit
      tau_-1 = S_sa / (1 - S_sm / S_su) and the mean-stress factor psi_tau = tau_-1 / S_su,
      so that the manual's n = tau_-1 / (tau_a + psi_tau tau_m) (eq. 6.12) is the Goodman
      safety factor.

An explicit ``shear_modulus_MPa``, ``density_kg_m3``, ``allowable_stress_MPa``,
``endurance_limit_MPa`` or ``mean_stress_factor`` of the specification replaces the
grade's value for every wire.
"""

from dataclasses import dataclass

import numpy as np

from .errors import InputError
from .locale import NoteText, cited, note
from .units import MPA

ALLOWABLE_SHARE = 0.50
"""[tau] / R_m of hardened and tempered low-alloy spring wire (Shigley Table 10-6; EN 13906-1)."""

TORSIONAL_ULTIMATE_SHARE = 0.67
"""S_su / R_m (Shigley section 10-9)."""

ZIMMERLI_PEENED = (398e6, 534e6)
"""Zimmerli's endurance point of shot-peened springs (S_sa, S_sm) [Pa], d < 10 mm (Shigley section 10-9)."""


def tensile_strength(wire_diameter, a, m) -> float | np.ndarray:
    """Minimum tensile strength R_m = A / d^m of spring wire [Pa].

    Parameters
    ----------
    wire_diameter : ndarray
        d [m].
    a : float
        A [MPa mm^m].
    m : float
        Exponent.

    References
    ----------
    Shigley's Mechanical Engineering Design, 9th ed. (2011), Table 10-4.

    Examples
    --------
    Chrome-vanadium wire A232 of 4 mm: 2005 / 4^0.168 = 1588.4 MPa.

    >>> round(float(tensile_strength(4e-3, 2005.0, 0.168)) / 1e6, 1)
    1588.4
    """
    return a * MPA / (np.asarray(wire_diameter, dtype=float) * 1e3) ** m


def goodman_endurance(amplitude, mean, ultimate) -> float | np.ndarray:
    """Fully reversed torsional endurance limit from one point of a Goodman line, S_sa / (1 - S_sm / S_su) [Pa].

    References
    ----------
    Shigley's Mechanical Engineering Design, 9th ed. (2011), section 10-9.

    Examples
    --------
    Zimmerli's peened point and S_su = 0.67 x 1700 MPa: 749.3 MPa.

    >>> round(float(goodman_endurance(398e6, 534e6, 0.67 * 1700e6)) / 1e6, 1)
    749.3
    """
    return amplitude / (1.0 - mean / np.asarray(ultimate, dtype=float))


@dataclass(frozen=True)
class WireGrade:
    """A spring-wire grade: constants, or a tensile-strength law from which the limits follow (SI)."""

    name: str
    description: str
    shear_modulus: float                 # G [Pa]
    density: float                       # rho [kg/m^3]
    source: NoteText                     # where the figures come from (:func:`~valvetrain.locale.cited`)
    tensile: tuple = None                # (A [MPa mm^m], m) of R_m = A / d^m; None: the constants below
    allowable: float = None              # [tau] [Pa], the same for every wire
    endurance: float = None              # tau_-1 [Pa]
    mean_stress_factor: float = None     # psi_tau

    def tensile_strength(self, wire_diameter) -> np.ndarray:
        """R_m [Pa] (NaN for a grade given by constants)."""
        if self.tensile is None:
            return np.full(np.shape(wire_diameter), np.nan)
        return tensile_strength(wire_diameter, *self.tensile)

    def allowable_stress(self, wire_diameter) -> np.ndarray:
        """[tau] at the full-lift load [Pa]."""
        if self.tensile is None:
            return np.full(np.shape(wire_diameter), self.allowable)
        return ALLOWABLE_SHARE * self.tensile_strength(wire_diameter)

    def endurance_limit(self, wire_diameter) -> np.ndarray:
        """tau_-1 [Pa]: the Goodman line through Zimmerli's peened point for a grade with R_m."""
        if self.tensile is None:
            return np.full(np.shape(wire_diameter), self.endurance)
        return goodman_endurance(*ZIMMERLI_PEENED, TORSIONAL_ULTIMATE_SHARE * self.tensile_strength(wire_diameter))

    def mean_stress(self, wire_diameter) -> np.ndarray:
        """psi_tau of eq. (6.12): tau_-1 / S_su on the Goodman line for a grade with R_m."""
        if self.tensile is None:
            return np.full(np.shape(wire_diameter), self.mean_stress_factor)
        ultimate = TORSIONAL_ULTIMATE_SHARE * self.tensile_strength(wire_diameter)
        return self.endurance_limit(wire_diameter) / ultimate


_SHIGLEY = "Shigley's Mechanical Engineering Design, 9th ed. (2011), Tables 10-4, 10-6, section 10-9; EN 13906-1"

GRADES = {
    "60S2A": WireGrade("60S2A", "silicon spring steel of the manual (60G, 65G, 60S2A, 60S2G, 50KhGA, 50KhFA)",
                       8.0e10, 7850.0, cited(note("source.psi_literature", work="Valve-train practical works (n.d.), work 6")),
                       allowable=500e6, endurance=370e6, mean_stress_factor=0.2),
    "VDSiCr": WireGrade("VDSiCr", "oil-hardened and tempered chrome-silicon valve-spring wire (EN 10270-2)",
                        79.5e9, 7850.0, cited(note("source.standard_strength", work=_SHIGLEY, standard="ASTM A401")),
                        tensile=(1974.0, 0.108)),
    "VDCrV": WireGrade("VDCrV", "oil-hardened and tempered chrome-vanadium valve-spring wire (EN 10270-2)",
                       79.5e9, 7850.0, cited(note("source.standard_strength", work=_SHIGLEY, standard="ASTM A232")),
                       tensile=(2005.0, 0.168)),
}
"""The wire grades a specification can name, by name."""


def grade(name) -> WireGrade:
    """The grade of a name, ignoring case, spaces and hyphens (``"VD-SiCr"`` is ``"VDSiCr"``).

    Raises
    ------
    InputError
        With the names allowed.
    """
    key = name.replace("-", "").replace(" ", "").lower()
    for grade_name, found in GRADES.items():
        if grade_name.lower() == key:
            return found
    raise InputError(f"material = {name!r}: allowed {', '.join(repr(n) for n in GRADES)}")
