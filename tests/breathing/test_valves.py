"""The valves' effective areas (valvetrain.breathing.valves): the reference areas by hand, the refused tables."""

import numpy as np
import pytest

from valvetrain.breathing import valves
from valvetrain.flow import curtain_area


def test_port_and_curtain_references():
    """Port: C_D pi D^2 / 4, taken to zero at zero lift; curtain: C_D pi D L."""
    x, cd = np.array([0.05, 0.1, 0.3]), np.array([0.2, 0.4, 0.7])
    port = valves.CdTable(x, cd, cd * 0.9, 0.03)
    fwd, rev = valves.effective_areas(np.array([0.0, 0.75e-3, 3e-3, 20e-3]), port)
    area = np.pi * 0.03**2 / 4
    assert fwd[0] == 0.0 and fwd[1] == pytest.approx(0.5 * 0.2 * area)     # halfway from (0, 0) to the first row
    assert fwd[2] == pytest.approx(0.4 * area) and fwd[3] == pytest.approx(0.7 * area)
    assert rev[2] == pytest.approx(0.9 * 0.4 * area)
    curtain = valves.CdTable(x, cd, cd, 0.03, "curtain")
    assert valves.effective_areas(3e-3, curtain)[0] == pytest.approx(0.4 * np.pi * 0.03 * 3e-3)


def test_default_is_the_flow_section():
    """Without a table: DEFAULT_CD times the curtain area of flow.py, no more than the throat."""
    lift = np.array([1e-3, 30e-3])
    area = valves.default_areas(lift, 0.03, np.pi / 4)
    assert area[0] == pytest.approx(valves.DEFAULT_CD * curtain_area(1e-3, 0.03, np.pi / 4))
    assert area[1] == pytest.approx(valves.DEFAULT_CD * np.pi * 0.03**2 / 4)


@pytest.mark.parametrize("x, cd, message", [
    ([0.0, 0.1, 0.1], [0.0, 0.3, 0.4], r"row 3: L/D = 0.1 after 0.1: C_D must be a function of L/D"),
    ([0.0, 0.2, 0.1], [0.0, 0.3, 0.4], r"row 3: L/D = 0.1 after 0.2"),
    ([0.0, 0.1, 0.2], [0.0, 0.3, 1.4], r"row 3: forward C_D = 1.4; allowed 0 to 1"),
    ([-0.1, 0.1, 0.2], [0.0, 0.3, 0.4], r"row 1: L/D = -0.1"),
])
def test_refused_tables(x, cd, message):
    with pytest.raises(valves.CdTableError, match=message):
        valves.CdTable(np.array(x), np.array(cd), np.array(cd) * 0.5, 0.03, source="cd.csv")
