"""The diagnosis of a spring search that finds no spring (springs/diagnosis.py): the stress window of Valve-train
practical works (n.d.), corrections note 27, the conflicts and the remedies that pass when tried."""

from dataclasses import replace

import numpy as np
import pytest

from valvetrain import springs
from valvetrain.locale.wording import diagnosis_text
from valvetrain.springs import diagnosis

from conftest import SEED000_OMEGA_EXACT, seed000_law
from springs.test_requirement import _requirement


def test_resonance_needs_more_stress_than_60s2a_allows_at_7000_rpm():
    """Valve-train practical works (n.d.), corrections note 27 in numbers: at the speed (omega_cam = 366.5 rad/s) and lift (10 mm) of the appendix of Valve-train practical works (n.d.) a line of
    f_max/f_min <= 3.2 has f_max >= 14.545 mm; with chi >= 1.1 (D/d <= 12) the ratio 10 needs, by hand,
    10 x 366.52 x 1.1 x 0.014545 x sqrt(2 x 7850 x 8e10) / pi = 661.5 MPa, above [tau] = 500 MPa of 60S2A
    (Valve-train practical works (n.d.), work 6): no spring of the manual's steel can pass."""
    w = springs.stress_window(springs.SpringMaterial(), 0.010, SEED000_OMEGA_EXACT)
    assert w.deflection_ratio == pytest.approx(3.2)
    assert w.max_deflection == pytest.approx(0.010 * 3.2 / 2.2)
    assert w.needed / 1e6 == pytest.approx(661.5, abs=0.1)
    assert w.allowed == pytest.approx(500e6)
    tau = springs.fatigue_stress_limit(370e6, 0.2, 3.2, 1.3)
    assert tau / 1e6 == pytest.approx(2 * 370 / (1.3 * (1 - 1 / 3.2 + 0.2 * (1 + 1 / 3.2))), rel=1e-12)


def test_diagnosis_of_the_example_in_60s2a():
    """The appendix requirement (m_v 0.147 kg: the example's parts with its spring) with the manual's steel:
    no spring passes; the diagnosis names tau_max and the resonance ratio, shows the stress window of Valve-train practical works (n.d.), corrections note 27, and
    each remedy it proposes passes when tried (VDSiCr; a lower speed), while a lower mass does not help (the
    resonance ratio does not depend on the force)."""
    law = seed000_law()
    y, req = _requirement(law, 0.147)
    requirement = springs.Requirement(y, req, springs.seat_load(0.147))
    options = springs.SpringOptions()
    search = springs.design_springs(requirement, 0.0368, SEED000_OMEGA_EXACT, options)
    assert not search.passes and search.passing == 0
    d = springs.diagnose(requirement, 0.0368, SEED000_OMEGA_EXACT, options, search, np.pi * 7000 / 30)
    checks = {x.check for x in d.conflicts}
    assert {"tau_max", "resonance_ratio"} <= checks
    assert d.kind == diagnosis.RESONANCE_STRESS
    assert d.window.needed > d.window.allowed == pytest.approx(500e6)
    remedies = {x.change: x for x in d.helped}
    assert remedies["material"].value == "VDSiCr" and remedies["material"].key == "material"
    vdsicr = replace(options, materials=(springs.SpringMaterial("VDSiCr"),))
    assert springs.design_springs(requirement, 0.0368, SEED000_OMEGA_EXACT, vdsicr).passes
    f = remedies["rated_speed_factor"].value
    assert 0.3 < f < 1.0 and remedies["rated_speed_factor"].rated_speed == pytest.approx(np.pi * 7000 / 30 * f)
    assert remedies["rated_speed_factor"].key == "rated_speed_rpm"
    slower = springs.design_springs(requirement.scaled(f**2), 0.0368, SEED000_OMEGA_EXACT * f, options)
    assert slower.passes
    assert springs.Remedy("reduced_mass_factor", 0.1, False) in d.tried
    text = diagnosis_text(d, "en")
    assert "needs tau_max >= 662 MPa" in text and 'material = "VDSiCr"' in text
