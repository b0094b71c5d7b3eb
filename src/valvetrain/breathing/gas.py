"""Thermodynamic properties of the cylinder's gases: air, the burned gas of a fuel and their mixtures.

Each species' specific heat and enthalpy is the NASA 7-coefficient polynomial of the NASA Glenn database as
Cantera ships it (``nasa_gas.yaml``: McBride, Zehe and Gordon (2002)), read once through Cantera's species
interface.  A gas of fixed composition is summed into one polynomial per unit mass, so that a mixture of two
gases (the fresh air and the burned or residual gas of the cylinder) is the same polynomial with coefficients
linear in the mass fraction: the compiled cycle evaluates it without Cantera.

Enthalpies are *sensible*, zero at 298.15 K for every species: the chemical energy of combustion enters the
cylinder as the heat release (the fuel's lower heating value, from the same polynomials), the single-zone
model's convention (Heywood (1988), chapter 9).  SI units: K, J/kg, J/(kg K), kg/mol.
"""

from dataclasses import dataclass
from functools import cache

import numpy as np
from numba import njit

from ..errors import InputError

SPECIES_FILE = "nasa_gas.yaml"
"""Cantera's file of the NASA Glenn thermodynamic data (McBride, Zehe and Gordon (2002)), 200-6000 K."""

GAS_CONSTANT = 8.314462618
"""Molar gas constant R [J/(mol K)] (the 2018 CODATA value, exact since the 2019 SI; Cantera's ``gas_constant``)."""

T_REFERENCE = 298.15
"""Temperature at which the sensible enthalpies are zero and the heating value is taken [K]."""

AIR = {"N2": 0.7809, "O2": 0.2095, "Ar": 0.0093, "CO2": 0.0003}
"""Mole fractions of dry air (Heywood (1988), Table 3.1)."""

FUELS = {"isooctane": "C8H18,isooctane", "n-heptane": "C7H16,n-heptane", "methane": "CH4", "propane": "C3H8",
         "ethanol": "C2H5OH"}
"""Fuels a fired cycle may burn: the name in a specification -> the species of :data:`SPECIES_FILE` (vapour)."""

COEFFICIENTS = 6
"""Coefficients of a gas's polynomial per temperature range: cp = c0 + c1 T + c2 T^2 + c3 T^3 + c4 T^4
[J/(kg K)] and the sensible enthalpy h = c0 T + c1 T^2/2 + c2 T^3/3 + c3 T^4/4 + c4 T^5/5 + c5 [J/kg]."""


@cache
def _species(names) -> dict:
    """``name -> (molar mass [kg/mol], NASA-7 coefficients (2, 7) below and above the middle temperature, middle
    temperature [K], elements)`` of the species of :data:`SPECIES_FILE`, read once."""
    import cantera as ct

    found = {s.name: s for s in ct.Species.list_from_file(SPECIES_FILE) if s.name in names}
    out = {}
    for name in names:
        s = found[name]
        data = s.thermo.input_data
        if data["model"] != "NASA7":
            raise InputError(f"{name} in {SPECIES_FILE}: NASA7 polynomials expected, not {data['model']}")
        weight = sum(ct.Element(e).weight * n for e, n in s.composition.items()) / 1000.0
        rows = np.array(data["data"], dtype=float)
        ranges = data["temperature-ranges"]
        # a species of one range (argon: its middle temperature is its upper limit) has one polynomial
        single = len(rows) == 1 or ranges[1] >= ranges[-1]
        out[name] = (weight, np.vstack([rows[0], rows[0]]) if single else rows, 0.0 if single else float(ranges[1]),
                     dict(s.composition))
    return out


def species(names) -> dict:
    """The NASA-7 data of the named species of :data:`SPECIES_FILE` (read once, through Cantera).

    Parameters
    ----------
    names : iterable of str
        Species names as the file spells them (``"N2"``, ``"C8H18,isooctane"``).

    Returns
    -------
    dict
        ``name -> (molar mass [kg/mol], coefficients (2, 7) of the ranges below and above the middle temperature,
        middle temperature [K] (0 for a species of one range, whose two rows are the same), elements -> atoms per
        molecule)``.

    References
    ----------
    McBride, Zehe and Gordon (2002); Goodwin et al. (2025) (Cantera).
    """
    return _species(tuple(sorted(set(names))))


def _molar_enthalpy(coefficients, mid, temperature):
    """Absolute molar enthalpy of one species [J/mol] at ``temperature`` [K] from its NASA-7 polynomials."""
    a = coefficients[0 if temperature < mid else 1]
    t = temperature
    return GAS_CONSTANT * (a[0] * t + a[1] * t**2 / 2 + a[2] * t**3 / 3 + a[3] * t**4 / 4 + a[4] * t**5 / 5 + a[5])


@dataclass(frozen=True)
class Gas:
    """A gas of fixed composition as one polynomial per unit mass (sensible enthalpy, see :data:`COEFFICIENTS`).

    Attributes
    ----------
    name : str
    mass_fractions : dict
        Species -> mass fraction (empty for a calorically perfect gas made by :meth:`perfect`).
    molar_mass : float
        [kg/mol].
    gas_constant : float
        Specific gas constant R = R_u / M [J/(kg K)].
    coefficients : ndarray
        (2, 6): the ranges below and above ``t_mid`` (:data:`COEFFICIENTS`).
    t_mid : float
        Temperature where the ranges meet [K].
    """

    name: str
    mass_fractions: dict
    molar_mass: float
    gas_constant: float
    coefficients: np.ndarray
    t_mid: float

    @classmethod
    def of(cls, name, moles) -> "Gas":
        """The gas of the given amounts of species of :data:`SPECIES_FILE` (mol, any scale).

        Parameters
        ----------
        name : str
        moles : dict
            Species -> amount.

        Returns
        -------
        Gas

        Notes
        -----
        With mass fractions :math:`Y_i` and :math:`R_i = R_u / M_i`, the mixture's coefficients per unit mass are
        :math:`c_k = \\sum_i Y_i R_i a_{i,k}` (k = 0...4) and the sensible constant
        :math:`c_5 = \\sum_i Y_i (R_i a_{i,5} - h_i(T_{ref}))`, so that h(298.15 K) = 0.

        References
        ----------
        McBride, Zehe and Gordon (2002) (the polynomials h/(R T) = a_1 + a_2 T/2 + ... + a_6/T).
        """
        data = species(moles)
        mids = {data[s][2] for s in moles} - {0.0} or {1000.0}
        if len(mids) != 1:
            raise InputError(f"{name}: the species' polynomials change range at different temperatures {sorted(mids)}")
        masses = {s: n * data[s][0] for s, n in moles.items()}
        total = sum(masses.values())
        fractions = {s: m / total for s, m in masses.items()}
        coefficients = np.zeros((2, COEFFICIENTS))
        for s, y in fractions.items():
            weight, a, mid, _ = data[s]
            r = GAS_CONSTANT / weight
            coefficients[:, :5] += y * r * a[:, :5]
            coefficients[:, 5] += y * (r * a[:, 5] - _molar_enthalpy(a, mid, T_REFERENCE) / weight)
        molar_mass = total / sum(moles.values())
        return cls(name, fractions, molar_mass, GAS_CONSTANT / molar_mass, coefficients, mids.pop())

    @classmethod
    def perfect(cls, gas_constant, gamma, name="perfect gas") -> "Gas":
        """A calorically perfect gas: cp = gamma R / (gamma - 1) at every temperature, h = cp (T - 298.15 K).

        Parameters
        ----------
        gas_constant : float
            R [J/(kg K)].
        gamma : float
            Ratio of specific heats.

        Returns
        -------
        Gas
        """
        cp = gamma * gas_constant / (gamma - 1.0)
        row = [cp, 0.0, 0.0, 0.0, 0.0, -cp * T_REFERENCE]
        return cls(name, {}, GAS_CONSTANT / gas_constant, gas_constant, np.array([row, row]), 1000.0)


@njit(cache=True, nogil=True)
def cp_at(temperature, coefficients, t_mid) -> float:
    """Specific heat at constant pressure [J/(kg K)] of a gas's polynomial (:data:`COEFFICIENTS`) at a temperature
    [K]."""
    c = coefficients[0] if temperature < t_mid else coefficients[1]
    t = temperature
    return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * c[4])))


@njit(cache=True, nogil=True)
def enthalpy_at(temperature, coefficients, t_mid) -> float:
    """Sensible enthalpy [J/kg] of a gas's polynomial (:data:`COEFFICIENTS`) at a temperature [K]."""
    c = coefficients[0] if temperature < t_mid else coefficients[1]
    t = temperature
    return t * (c[0] + t * (c[1] / 2.0 + t * (c[2] / 3.0 + t * (c[3] / 4.0 + t * c[4] / 5.0)))) + c[5]


@njit(cache=True, nogil=True)
def temperature_at(energy, coefficients, t_mid, gas_constant, guess) -> float:
    """Temperature [K] at which the sensible internal energy u = h - R T of a gas's polynomial is ``energy`` [J/kg].

    Newton's iteration from ``guess`` [K] (the previous step's temperature in the cycle), to 1e-10 K; u(T) rises
    monotonically (cv > 0), so the iteration converges from any positive guess in a few steps.
    """
    t = guess if guess > 10.0 else 300.0
    for _ in range(50):
        f = enthalpy_at(t, coefficients, t_mid) - gas_constant * t - energy
        step = f / (cp_at(t, coefficients, t_mid) - gas_constant)
        t -= step
        if t < 10.0:
            t = 10.0
        if abs(step) < 1e-10 * t:
            break
    return t


@njit(cache=True, nogil=True)
def _apply(kind, temperature, coefficients, t_mid, gas_constant, out):
    for i in range(temperature.size):
        t = temperature[i]
        if kind == 0:
            out[i] = cp_at(t, coefficients, t_mid)
        elif kind == 1:
            out[i] = enthalpy_at(t, coefficients, t_mid)
        else:
            out[i] = temperature_at(t, coefficients, t_mid, gas_constant, 300.0)


def _over(kind, gas, values):
    values = np.asarray(values, dtype=float)
    out = np.empty(values.size)
    _apply(kind, values.ravel(), gas.coefficients, gas.t_mid, gas.gas_constant, out)
    return out.reshape(values.shape) if values.ndim else float(out[0])


def specific_heat(gas, temperature) -> float | np.ndarray:
    """Specific heat at constant pressure cp [J/(kg K)] of ``gas`` at ``temperature`` [K].

    Notes
    -----
    :math:`c_p = c_0 + c_1 T + c_2 T^2 + c_3 T^3 + c_4 T^4` (:data:`COEFFICIENTS`).

    References
    ----------
    McBride, Zehe and Gordon (2002).

    Examples
    --------
    A calorically perfect gas has cp = gamma R / (gamma - 1) everywhere:

    >>> round(specific_heat(Gas.perfect(287.0, 1.4), 1500.0), 6)
    1004.5
    """
    return _over(0, gas, temperature)


def enthalpy(gas, temperature) -> float | np.ndarray:
    """Sensible enthalpy h [J/kg] of ``gas`` at ``temperature`` [K], zero at 298.15 K.

    Notes
    -----
    :math:`h = c_0 T + c_1 T^2/2 + c_2 T^3/3 + c_3 T^4/4 + c_4 T^5/5 + c_5`.

    References
    ----------
    McBride, Zehe and Gordon (2002).

    Examples
    --------
    >>> round(enthalpy(Gas.perfect(287.0, 1.4), 398.15), 6)
    100450.0
    """
    return _over(1, gas, temperature)


def internal_energy(gas, temperature) -> float | np.ndarray:
    """Sensible internal energy u = h - R T [J/kg] of ``gas`` at ``temperature`` [K]."""
    return enthalpy(gas, temperature) - gas.gas_constant * np.asarray(temperature, dtype=float)


def ratio_of_specific_heats(gas, temperature) -> float | np.ndarray:
    """gamma = cp / (cp - R) of ``gas`` at ``temperature`` [K]."""
    cp = specific_heat(gas, temperature)
    return cp / (cp - gas.gas_constant)


def temperature(gas, energy) -> float | np.ndarray:
    """Temperature [K] at which ``gas`` has the sensible internal energy ``energy`` [J/kg] (the inverse of
    :func:`internal_energy`, by Newton's iteration)."""
    return _over(2, gas, energy)


def mixture(a, b, fraction) -> np.ndarray:
    """Polynomial coefficients (2, 6) of a mixture with the mass fraction ``fraction`` of gas ``b`` in gas ``a``.

    Notes
    -----
    Per-unit-mass properties add by mass fraction, so the coefficients and the gas constant are linear in it:
    :math:`c = c_a + x (c_b - c_a)`, :math:`R = R_a + x (R_b - R_a)`.
    """
    if a.t_mid != b.t_mid:
        raise InputError(f"{a.name} and {b.name} change range at {a.t_mid:g} and {b.t_mid:g} K")
    return a.coefficients + fraction * (b.coefficients - a.coefficients)


def air() -> Gas:
    """Dry air of :data:`AIR` (Heywood (1988), Table 3.1) with the polynomials of :data:`SPECIES_FILE`.

    Returns
    -------
    Gas

    Examples
    --------
    Its gas constant, R_u / 28.96 g/mol:

    >>> round(air().gas_constant, 1)
    287.1
    """
    return _air()


@cache
def _air():
    return Gas.of("air", AIR)


def _fuel(fuel):
    """The species name of ``fuel`` and its atoms of C, H and O per molecule."""
    if fuel not in FUELS:
        raise InputError(f"fuel = {fuel!r}: allowed {', '.join(FUELS)}")
    name = FUELS[fuel]
    atoms = species([name])[name][3]
    return name, {e: atoms.get(e, 0.0) for e in ("C", "H", "O")}


def stoichiometric_oxygen(fuel) -> float:
    """Moles of O2 to burn one mole of ``fuel`` completely, a + b/4 - c/2 for C_a H_b O_c."""
    _, f = _fuel(fuel)
    return f["C"] + f["H"] / 4.0 - f["O"] / 2.0


def _burned_moles(fuel, equivalence_ratio):
    """Moles of products of one mole of fuel burned completely in air at an equivalence ratio <= 1."""
    _, f = _fuel(fuel)
    s = stoichiometric_oxygen(fuel)
    air_moles = s / (equivalence_ratio * AIR["O2"])
    products = {k: air_moles * x for k, x in AIR.items()}
    products["O2"] -= s
    products["CO2"] += f["C"]
    products["H2O"] = f["H"] / 2.0
    return air_moles, {k: v for k, v in products.items() if v > 0.0}


def fuel_air_ratio(fuel, equivalence_ratio) -> float:
    """Fuel-air mass ratio F/A of ``fuel`` at ``equivalence_ratio`` (phi = (F/A) / (F/A)_s).

    Parameters
    ----------
    fuel : str
        A key of :data:`FUELS`.
    equivalence_ratio : float
        phi, 0 < phi <= 1 (lean or stoichiometric).

    Returns
    -------
    float

    Notes
    -----
    For :math:`C_aH_bO_c`: :math:`(F/A) = \\varphi\\,x_{O_2} M_f / ((a + b/4 - c/2)\\,M_{air})`, with the mole
    fraction :math:`x_{O_2}` of air (Heywood (1988), chapter 3).

    Examples
    --------
    Iso-octane, stoichiometric: (A/F)_s = 15.13 (Heywood (1988), Table D.4 gives 15.1):

    >>> round(1.0 / fuel_air_ratio("isooctane", 1.0), 2)
    15.13
    """
    name, _ = _fuel(fuel)
    air_moles, _ = _burned_moles(fuel, equivalence_ratio)
    return float(species([name])[name][0] / (air_moles * air().molar_mass))


def burned_gas(fuel, equivalence_ratio) -> Gas:
    """The products of the complete combustion of ``fuel`` in air at ``equivalence_ratio`` <= 1.

    Returns
    -------
    Gas
        CO2, H2O, N2, Ar and the excess O2.

    Notes
    -----
    :math:`C_aH_bO_c + n (x_{O_2} O_2 + x_{N_2} N_2 + x_{Ar} Ar + x_{CO_2} CO_2) \\to
    (a + n x_{CO_2}) CO_2 + (b/2) H_2O + n x_{N_2} N_2 + n x_{Ar} Ar + (n x_{O_2} - s) O_2` with
    :math:`s = a + b/4 - c/2`, :math:`n = s / (\\varphi x_{O_2})`; no dissociation (lean and stoichiometric
    mixtures below about 2000 K, Heywood (1988), chapter 4).
    """
    if not 0.0 < equivalence_ratio <= 1.0:
        raise InputError(f"equivalence_ratio = {equivalence_ratio:g}: allowed 0 < phi <= 1 (complete combustion)")
    _, products = _burned_moles(fuel, equivalence_ratio)
    return Gas.of(f"burned {fuel}, phi {equivalence_ratio:g}", products)


def lower_heating_value(fuel) -> float:
    """Lower heating value of ``fuel`` vapour at 298.15 K [J/kg], the water of the products as vapour.

    Notes
    -----
    :math:`Q_{LHV} = [h_f + s\\,h_{O_2} - a\\,h_{CO_2} - (b/2)\\,h_{H_2O}](298.15\\,K) / M_f`, the molar
    enthalpies of the NASA polynomials (formation included).

    References
    ----------
    Heywood (1988), chapter 3; McBride, Zehe and Gordon (2002).

    Examples
    --------
    Methane, 50.0 MJ/kg in Heywood (1988), Table D.4:

    >>> round(lower_heating_value("methane") / 1e6, 1)
    50.0
    """
    name, f = _fuel(fuel)
    data = species([name, "O2", "CO2", "H2O"])

    def h(s):
        return _molar_enthalpy(data[s][1], data[s][2], T_REFERENCE)

    released = h(name) + stoichiometric_oxygen(fuel) * h("O2") - f["C"] * h("CO2") - f["H"] / 2.0 * h("H2O")
    return float(released / data[name][0])
