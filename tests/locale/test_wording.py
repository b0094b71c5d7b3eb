"""The words of the data the physics returns (report/wording.py) and the messages of the laws built from their data
(laws/errors.py): the expected sentences are written out by hand from the data given."""

import numpy as np
import pytest

from valvetrain.laws.errors import LawError
from valvetrain.laws.measured import lobe_table
from valvetrain.design.drive import diagnosis_record
from valvetrain.design.results import record as json_record
from valvetrain.locale import note_text
from valvetrain.locale.wording import diagnosis_text
from valvetrain.springs import Conflict, Diagnosis, Remedy, StressWindow
from valvetrain.springs.diagnosis import PAIR_FREQUENCIES

RATED = np.pi * 7000.0 / 30.0

PAIR = Diagnosis(
    pair=True, frequency_difference=0.1,
    conflicts=(Conflict("outer", "tau_max", "tau_max", 600e6, 500e6, "MPa", 0.2),
               Conflict("inner", "installed_length", "installed length", 0.036, 0.030, "mm", 0.2)),
    window=StressWindow("VDSiCr", 11.0, 3.2, 0.010 * 3.2 / 2.2, 720e6, 752e6), kind=PAIR_FREQUENCIES,
    remedies=(Remedy("material", "60S2A", False, "material"),
              Remedy("max_installed_length", None, False, "installed_length_mm"),
              Remedy("rated_speed_factor", 0.8, True, "rated_speed_rpm", rated_speed=0.8 * RATED),
              Remedy("reduced_mass_factor", 0.1, False)))
"""A pair whose two springs cannot both reach the resonance ratio 11 with frequencies 10 % apart: 720 MPa x 1.1 =
792 MPa needed against 752 MPa allowed; f_max = 10 mm x 3.2 / 2.2 = 14.5 mm; 0.8 x 7000 rpm = 5600 rpm."""


def test_the_diagnosis_in_english_from_its_data():
    """Every sentence of the English diagnosis, with the SI values of the data shown in MPa, mm and rpm; a length
    remedy tried in vain has no length to show."""
    assert diagnosis_text(PAIR, "en") == (
        "No nested pair passes; the best pair: outer tau_max 600 MPa against 500 MPa (short by 20.0%); inner "
        "installed length 36 mm against 30 mm (short by 20.0%). The two springs of a pair share f_max, so their "
        "frequencies stand as tau_max / chi: frequencies 10% apart with both resonance ratios >= 11 need tau_max up "
        "to 792 MPa even at D/d = 12 and f_max/f_min = 3.2 (f_max = 14.5 mm), while VDSiCr allows at most 752 MPa "
        "there ([tau] and the fatigue safety): no nested pair of this grade can pass at this speed and lift. A spring "
        "passes with a rated speed lowered to 80.0% (5600 rpm). None passes with material = \"60S2A\", no installed "
        "length limit, a reduced mass down to 10 %.")


def test_the_diagnosis_in_russian_from_its_data():
    """The Russian report states the conflicts of each spring of the pair, the stress the pair's frequencies need
    (792 MPa) against the 752 MPa allowed, and the remedies, with decimal commas."""
    text = diagnosis_text(PAIR, "ru")
    assert text.startswith("Ни одна пара пружин не проходит все проверки; лучшая пара: наружная пружина: τ_max ")
    assert "600 МПа при допустимом 500 МПа (не хватает 20,0%); внутренняя пружина: " in text
    assert "36 мм при допустимом 30 мм" in text
    assert "требуют τ_max до 792 МПа даже при D/d = 12 и f_max/f_min = 3,2 (f_max = 14,5 мм), а сталь VDSiCr " \
        "допускает там не более 752 МПа" in text
    assert text.endswith("Пружина проходит, если задать: номинальную частоту вращения, сниженную до 80,0% (5600 мин⁻¹). "
                         "Ни одна пружина не проходит, если задать: material = «60S2A», длину в установленном положении "
                         "без ограничения, приведённую массу до 10 %.")


def test_the_diagnosis_record_of_results_json():
    """results.json: values in the check's display unit, the window in MPa and mm, the remedies that help apart from
    those tried in vain, a length tried in vain without a value; a frozen typed record read by attribute."""
    typed = diagnosis_record(PAIR)
    assert typed.resonance.needed == 720e6 and typed.tried[1].to is None
    record = json_record(typed)
    assert [(x["value"], x["limit"], x["unit"]) for x in record["conflicts"]] == [
        (600.0, 500.0, "MPa"), (pytest.approx(36.0), pytest.approx(30.0), "mm")]
    assert record["resonance"] == {"material": "VDSiCr", "deflection_ratio": 3.2,
                                   "max_deflection_mm": pytest.approx(160 / 11), "stress_needed_MPa": 720.0,
                                   "stress_allowed_MPa": 752.0}
    assert record["remedies"] == [{"change": "rated_speed_factor", "to": 0.8, "rated_speed_rpm": pytest.approx(5600.0)}]
    assert record["tried"] == [{"change": "material", "to": "60S2A"}, {"change": "max_installed_length_mm"},
                               {"change": "reduced_mass_factor", "to": 0.1}]
    assert record["text"] == diagnosis_text(PAIR, "en")


def test_a_law_refuses_with_its_data_and_one_message():
    """A table row 0.05 mm below the base circle (3 x 0.005 mm allowed): the error carries the code and the values in
    SI, and its message shows them in mm and degrees."""
    angle = np.arange(0.0, 362.0, 2.0)
    lift = np.clip(8.0 * np.cos(np.radians(angle - 180.0)), 0.0, None)
    lift[5] = -0.05
    with pytest.raises(LawError) as err:
        lobe_table(angle, lift, "crank", accuracy_mm=0.005)
    assert err.value.code == "below_base_circle"
    assert err.value.values["lift"] == pytest.approx(-0.05e-3) and err.value.values["least"] == pytest.approx(-15e-6)
    assert err.value.values["angle"] == pytest.approx(np.radians(10.0))
    assert str(err.value) == ("lift_mm = -0.05 at angle_deg = 10 lies below the base circle; allowed >= -0.015 mm (3 x "
                              "accuracy_mm of measurement noise)")
    # issue 41: its words are the catalogue's (law_error.below_base_circle), said in Russian with a decimal comma
    assert note_text(err.value.args[0].parts, "ru") == (
        "lift_mm = -0,05 при angle_deg = 10 лежит ниже окружности затылка; допускается ≥ -0,015 мм (3 × accuracy_mm "
        "шума измерения)")
