"""The drive stage (valvetrain.design.drive): the stage's spring lines."""

from valvetrain.design.drive import SpringLines
from valvetrain.springs import Characteristic


def test_spring_lines_name_the_lines_there_are_in_drawing_order():
    """The spring figure draws the required line first and the chosen one last, over a pair's outer and inner springs
    (the order of Valve-train practical works (n.d.), Fig. 5.1); one spring has no pair lines."""
    required, chosen = Characteristic(200.0, 20e3, 0.01), Characteristic(220.0, 21e3, 0.01)
    outer, inner = Characteristic(150.0, 14e3, 0.01), Characteristic(70.0, 7e3, 0.01)
    assert SpringLines(required, chosen).named() == (("required", required), ("chosen", chosen))
    assert [name for name, _ in SpringLines(required, chosen, outer, inner).named()] == ["required", "outer", "inner",
                                                                                          "chosen"]


def test_a_failed_spring_check_carries_the_diagnosis_as_codes_rendered_in_either_language():
    """Issue 41: the diagnosis on a failed spring check is codes of [notes] with their numbers: the English record
    as before, the Russian report rendered from the codes (before, the report looked the English up by skeleton in
    ru.toml [texts], found none and printed it in English).  Hand-written from the data: tau_max 600 MPa against
    500 MPa is 20 % short; a VDSiCr spring of 50 g passes."""
    from dataclasses import replace
    from types import SimpleNamespace

    from valvetrain.checks import check
    from valvetrain.design.drive import _spring_checks
    from valvetrain.locale.wording import diagnosis_note
    from valvetrain.report.check_rows import check_note
    from valvetrain.springs import Conflict, Diagnosis, Remedy

    d = Diagnosis(pair=False, frequency_difference=0.1, window=None, kind=None,
                  conflicts=(Conflict("spring", "tau_max", "tau_max", 600e6, 500e6, "MPa", 0.2),),
                  remedies=(Remedy("material", "VDSiCr", True, "material", spring_mass=0.05),))
    tau = check("spring.tau_max", 600.0, high=500.0, unit="MPa", source="s", severity="failure")
    free = check("spring.free_length", 40.0, high=50.0, unit="mm", source="s")
    failed, passed = _spring_checks("spring", SimpleNamespace(checks={"tau_max": tau, "free_length": free}),
                                    diagnosis_note(d))
    assert failed.note == ('No spring passes; the best candidate: tau_max 600 MPa against 500 MPa (short by 20.0%). '
                           'A spring passes with material = "VDSiCr" (50 g).')
    assert failed.note_parts == diagnosis_note(d) and failed.as_dict()["note"] == failed.note
    assert check_note(failed, "ru") == ("Ни одна пружина не проходит все проверки; лучший вариант: τ_max 600 МПа при "
                                        "допустимом 500 МПа (не хватает 20,0%). Пружина проходит, если задать: "
                                        "material = «VDSiCr» (50 г).")
    assert passed == free.of_spring("spring") and passed.note_parts == ()
    assert _spring_checks("spring", SimpleNamespace(checks={"tau_max": tau}))[0] == replace(tau.of_spring("spring"),
                                                                                           note="")
