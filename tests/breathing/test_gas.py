"""Gas properties (valvetrain.breathing.gas) against Cantera's own evaluation of the same species data, and the fuels'
figures against Heywood (1988), Table D.4."""

import cantera as ct
import numpy as np
import pytest

from valvetrain.breathing import gas


@pytest.fixture(scope="module")
def cantera_air():
    """Cantera's ideal-gas mixture of the NASA species of dry air (an independent evaluation of the polynomials)."""
    species = [s for s in ct.Species.list_from_file(gas.SPECIES_FILE) if s.name in ("N2", "O2", "Ar", "CO2", "H2O")]
    solution = ct.Solution(thermo="ideal-gas", species=species)
    solution.TPX = 300.0, ct.one_atm, gas.AIR
    return solution


@pytest.mark.parametrize("temperature", [250.0, 300.0, 999.0, 1001.0, 1800.0, 3000.0])
def test_air_against_cantera(cantera_air, temperature):
    """cp and the sensible enthalpy of air from the summed polynomial equal Cantera's mixture (to 1e-10)."""
    g = cantera_air
    g.TP = gas.T_REFERENCE, ct.one_atm
    h0 = g.enthalpy_mass
    g.TP = temperature, ct.one_atm
    air = gas.air()
    assert gas.specific_heat(air, temperature) == pytest.approx(g.cp_mass, rel=1e-10)
    assert gas.enthalpy(air, temperature) == pytest.approx(g.enthalpy_mass - h0, rel=1e-10, abs=1e-6)
    assert air.gas_constant == pytest.approx(ct.gas_constant / g.mean_molecular_weight, rel=1e-10)


def test_burned_gas_against_cantera():
    """Stoichiometric iso-octane products: CO2 8, H2O 9, N2 and Ar with the air (no O2 left); gamma at 1500 K as
    Cantera's mixture of the same moles gives."""
    burned = gas.burned_gas("isooctane", 1.0)
    assert set(burned.mass_fractions) == {"CO2", "H2O", "N2", "Ar"}
    species = [s for s in ct.Species.list_from_file(gas.SPECIES_FILE) if s.name in ("N2", "CO2", "H2O", "Ar")]
    solution = ct.Solution(thermo="ideal-gas", species=species)
    air = 12.5 / gas.AIR["O2"]
    solution.TPX = 1500.0, ct.one_atm, {"CO2": 8.0 + air * gas.AIR["CO2"], "H2O": 9.0, "N2": air * gas.AIR["N2"],
                                          "Ar": air * gas.AIR["Ar"]}
    assert gas.ratio_of_specific_heats(burned, 1500.0) == pytest.approx(solution.cp_mass / solution.cv_mass, rel=1e-10)


def test_fuels_against_heywood():
    """Heywood (1988), Table D.4: methane LHV 50.0 MJ/kg; iso-octane (A/F)_s 15.1, LHV 44.3 MJ/kg of the liquid, so
    44.3 + 0.31 for the vapour (its enthalpy of vaporisation at 25 degC, 35.1 kJ/mol = 0.307 MJ/kg, NIST Chemistry
    WebBook, 2,2,4-trimethylpentane)."""
    assert gas.lower_heating_value("methane") / 1e6 == pytest.approx(50.0, abs=0.05)
    assert 1.0 / gas.fuel_air_ratio("isooctane", 1.0) == pytest.approx(15.1, abs=0.05)
    assert gas.lower_heating_value("isooctane") / 1e6 == pytest.approx(44.3 + 0.31, abs=0.05)


def test_temperature_inverts_the_energy():
    """temperature(u(T)) = T for air and burned gas across both ranges of the polynomials."""
    for g in (gas.air(), gas.burned_gas("isooctane", 0.8)):
        t = np.array([200.0, 298.15, 700.0, 1000.0, 2500.0])
        assert np.allclose(gas.temperature(g, gas.internal_energy(g, t)), t, rtol=0, atol=1e-8)


def test_mixture_is_linear_in_the_mass_fraction():
    """A 30 % mixture's cp is the mass-weighted mean of its parts' (per-unit-mass properties add by mass)."""
    a, b = gas.air(), gas.burned_gas("methane", 1.0)
    mixed = gas.Gas("mix", {}, 0.0, 0.7 * a.gas_constant + 0.3 * b.gas_constant, gas.mixture(a, b, 0.3), a.t_mid)
    assert gas.specific_heat(mixed, 900.0) == pytest.approx(
        0.7 * gas.specific_heat(a, 900.0) + 0.3 * gas.specific_heat(b, 900.0), rel=1e-12)


def test_refused_fuel_and_mixture():
    with pytest.raises(ValueError, match="fuel = 'kerosene'"):
        gas.lower_heating_value("kerosene")
    with pytest.raises(ValueError, match="equivalence_ratio = 1.2"):
        gas.burned_gas("isooctane", 1.2)
