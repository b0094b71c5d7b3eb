"""Issue 24: worked substitution.  Every worked line of the built-in example's report evaluates (its numbers as
printed, to 4 significant figures) to its printed result, and the lines give the numbers of a hand calculation:

- f_g = pi 36.8^2 / 4 = 1063.6 mm2;  f_max = pi 10 (36.8 cos 45 + 10 sin 45 cos^2 45) = 928.56 mm2;
- V' = 18 x 5026.5 / 1063.6 = 85.07 m/s;  V'' = 18 x 5026.5 / 928.56 = 97.44 m/s (the example's c_p = 18 m/s);
- Kurz coefficients of the appendix (h = 6.25 mm, w' = 0.02 mm/deg = 1.1459 mm/rad, Phi = 27/6/38 deg, Z = 5/8),
  by hand: k1 = 8 x 0.625 x (6/180)^2 = 0.0055556 rad2;  c11 = 5.0404 mm/rad (the docstring example of
  kurz_coefficients, the manual's appendix);
- pushrod 8/5 mm, 220 mm, E = 210000 MPa: J = pi (8^4 - 5^4)/64 = 170.41 mm4, P_E = pi^2 210000 170.41 / 220^2
  = 7297 N;
- polydyne p = 8 (q, r, s = 14, 20, 26): C_2 = -8 x 14 x 20 x 26 / (6 x 12 x 18 x 24) = -58240 / 31104 = -1.872
  (the closed form's docstring example, -1.87243); a polydyne with a ramp (no closed form) has no lines;
- the diesel's power-polynomial ramp (S_b = 0.8 mm, phi_0 = 12 deg = 0.20944 rad, v_qb = 6 mm/rad), by hand from
  A + B + C = 0, A + B/2 + C/3 = v/phi_0, A/2 + B/6 + C/12 = S/phi_0^2: A_0 = 12 x 18.238 - 6 x 28.648
  = 46.97 mm/rad2 (the docstring example of ramp_coefficients: 46.966, -15.978, -30.988);
- the roller finger of modern-dohc-roller-finger (r_r = 8.75 mm, b = 14 mm, E = 210000 MPa): sigma = 0.418
  sqrt(P E (1/rho + 1/r_r) / b) with the force and the cam's radius at the worst angle; by hand for the intake,
  0.418 x sqrt(863.2 x 210000 x (1/10.76 + 1/8.75) / 14) = 0.418 x 1638.0 = 684.7 MPa;
- crank R = 38.571 mm, n = 7000 rpm: omega = 733.04 rad/s, m_j = 0.38 + 0.1375 = 0.5175 kg, m_r = 0.45 + 0.3625
  = 0.8125 kg, K_R = -0.8125 x 0.038571 x 733.04^2 = -16840 N.
"""

import math
from pathlib import Path
import re

import pytest

from valvetrain.design import run
from valvetrain.report.html import _material
from valvetrain.specification import load_spec
from valvetrain.report.worked import crank_lines, flow_lines, law_lines, spring_lines, strength_lines, time_area_lines
from valvetrain.tables import lift_table_columns
from valvetrain.units import UNITS

from appendix import appendix_spec

UNIT_SYMBOLS = sorted({row[i] for row in UNITS.values() for i in (2, 3) if row[i]}, key=len, reverse=True)
"""Every unit symbol the report prints, longest first (``mm²·s`` before ``mm²`` before ``mm``)."""

POWERS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def evaluate(line, lang="en"):
    """The number a line's substituted text gives: units dropped, the operators made Python's."""
    text = line["substituted"]
    if lang == "ru":
        text = text.replace(",", ".")
    text = re.sub(r"·10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)", lambda m: "e" + m[1].translate(POWERS), text)
    units = "|".join(re.escape(u) for u in UNIT_SYMBOLS)
    text = re.sub(rf"(?<=[\d.])\s(?:{units})(?=[\s)]|$)", "", text)
    text = text.replace("π", "pi").replace("×", "*").replace("−", "-").replace("cos² ", "cos2 ").replace("√", "sqrt")
    text = text.replace("²", "**2").replace("³", "**3").replace("⁴", "**4")
    text = re.sub(r"(\d)°", r"\1", text)
    text = re.sub(r"(sin|cos2|cos) ([\d.]+)", r"\1(\2)", text)
    return eval(text, {"pi": math.pi, "sqrt": math.sqrt, "sin": lambda x: math.sin(math.radians(x)),
                       "cos": lambda x: math.cos(math.radians(x)), "cos2": lambda x: math.cos(math.radians(x)) ** 2})


@pytest.fixture(scope="module")
def results():
    return run(appendix_spec())


def _lines(results, lang):
    valve = results.spec.valves["intake"]
    v = results.valves["intake"]
    table = lift_table_columns(v.table)
    spring = v.drive.spring.design
    return (flow_lines(valve, v.flow, results.engine, lang)
            + time_area_lines(v.flow, v.cam, results.engine, valve.count, table, lang) + law_lines(v.law, v.cam, lang)
            + spring_lines(spring, _material(results.spec.valves["intake"], spring), v.cam.cam_speed, lang)
            + strength_lines(valve.parts, v.drive.strength, table, "flat", lang)
            + crank_lines(results.crank.figures, lang))


def _value(text):
    mantissa, _, power = text.split()[0].replace(",", ".").partition("·10")
    return float(mantissa) * 10.0 ** int(power.translate(POWERS) or 0)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_line_evaluates_to_its_result(results, lang):
    lines = _lines(results, lang)
    assert len(lines) >= 30
    for line in lines:
        assert evaluate(line, lang) == pytest.approx(_value(line["result"]), rel=3e-3), line  # 4 figures in and out


def test_a_wrong_line_does_not_evaluate_to_its_result(results):
    """The evaluation reads the printed numbers: a line whose substitution is off by 1 % fails."""
    line = dict(_lines(results, "en")[0])
    line["substituted"] = line["substituted"].replace("36.8", "37.0")
    assert evaluate(line) != pytest.approx(_value(line["result"]), rel=3e-3)


def test_the_lines_give_the_hand_calculation(results):
    by_symbol = {}
    for line in _lines(results, "en"):
        by_symbol.setdefault(line["symbol"], line)
    assert by_symbol["f_g"]["result"] == "1064 mm²" and math.pi * 36.8**2 / 4 == pytest.approx(1063.6, abs=0.05)
    assert by_symbol["f_max"]["result"] == "928.6 mm²"
    assert by_symbol["V′"]["result"] == "85.07 m/s" and by_symbol["V″"]["result"] == "97.44 m/s"
    assert by_symbol["f_max"]["substituted"] == "π × 10 mm × (36.8 mm × cos 45° + 10 mm × sin 45° × cos² 45°)"
    assert by_symbol["k_1"]["result"] == "0.005556 rad²" and by_symbol["c_11"]["result"] == "5.04 mm/rad"
    assert by_symbol["J"]["result"] == "170.4 mm⁴" and _value(by_symbol["P_E"]["result"]) == pytest.approx(7297, abs=1)
    assert by_symbol["ω"]["result"] == "733 rad/s" and by_symbol["m_j"]["result"] == "0.5175 kg"
    assert by_symbol["m_r"]["result"] == "0.8125 kg" and by_symbol["K_R"]["result"] == "-16840 N"


LAW_EXAMPLES = {"seed000-polydyne.toml": 5, "ukrsurt2019-diesel.toml": 4}
"""Examples whose laws are not Kurz laws, and how many law lines they print (an unramped polydyne 5, a ramped one
none; the power-polynomial law's ramp 3 and its negative amplitude 1)."""


@pytest.fixture(scope="module")
def law_examples():
    examples = Path(__file__).parents[2] / "examples"
    return {name: run(load_spec(examples / name)) for name in LAW_EXAMPLES}


def _law_lines(results, lang):
    return [line for v in results.valves.values() for line in law_lines(v.law, v.cam, lang)]


@pytest.mark.parametrize("lang", ["en", "ru"])
@pytest.mark.parametrize("example", sorted(LAW_EXAMPLES))
def test_law_lines_of_other_laws_evaluate_to_their_results(law_examples, example, lang):
    lines = _law_lines(law_examples[example], lang)
    assert len(lines) == LAW_EXAMPLES[example]
    for line in lines:
        assert evaluate(line, lang) == pytest.approx(_value(line["result"]), rel=3e-3), line


def test_law_lines_of_other_laws_give_the_hand_calculation(law_examples):
    polydyne = {line["symbol"]: line for line in _law_lines(law_examples["seed000-polydyne.toml"], "en")}
    assert polydyne["C_2"]["result"] == "-1.872" and -58240 / 31104 == pytest.approx(-1.87243, abs=5e-6)
    assert polydyne["C_2"]["substituted"] == "−8 × 14 × 20 × 26 / ((8 − 2) × (14 − 2) × (20 − 2) × (26 − 2))"
    diesel = {line["symbol"]: line for line in _law_lines(law_examples["ukrsurt2019-diesel.toml"], "en")}
    assert diesel["A_0"]["result"] == "46.97 mm/rad²" and diesel["B_0"]["result"] == "-15.98 mm/rad²"
    assert diesel["C_0"]["result"] == "-30.99 mm/rad²"
    assert 12 * 0.8 / math.radians(12) ** 2 - 6 * 6 / math.radians(12) == pytest.approx(46.966, abs=1e-3)


@pytest.fixture(scope="module")
def roller_example():
    return run(load_spec(Path(__file__).parents[2] / "examples" / "modern-dohc-roller-finger.toml"))


def _contact_lines(results, lang):
    return [line for name, v in results.valves.items()
            for line in strength_lines(results.spec.valves[name].parts, v.drive.strength,
                                       lift_table_columns(v.table), v.cam.follower, lang, v.cam.roller_radius * 1e3)
            if line["symbol"] in ("σ_c", "σ_к")]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_roller_contact_line_evaluates_to_its_result(roller_example, lang):
    lines = _contact_lines(roller_example, lang)
    assert len(lines) == 2  # intake and exhaust, both on roller fingers
    for line in lines:
        assert "1/8" + (",75" if lang == "ru" else ".75") in line["substituted"]  # the roller's radius is in it
        assert evaluate(line, lang) == pytest.approx(_value(line["result"]), rel=3e-3), line


def test_the_roller_contact_line_gives_the_hand_calculation(roller_example):
    intake = _contact_lines(roller_example, "en")[0]
    assert intake["result"] == "684.7 MPa"
    assert 0.418 * math.sqrt(863.2 * 210000 * (1 / 10.76 + 1 / 8.75) / 14) == pytest.approx(684.7, abs=0.2)


def test_a_table_that_begins_at_its_opening_has_its_lift_integral():
    """A measured lobe's lift table holds the event alone, its first row the opening; a first lift of round-off size
    (6e-17 mm on one BLAS kernel, 0 on another) made the fullness line's integral an empty sum, 0 mm cam deg, beside
    a fullness of 0.52. Every time-area line evaluates to its result with the first row's lift positive."""
    results = run(load_spec(Path(__file__).parents[2] / "examples" / "measured-lobe.toml"))
    v = results.valves["intake"]
    table = dict(lift_table_columns(v.table))
    table["valve_lift_mm"] = [1e-17, *list(table["valve_lift_mm"])[1:]]
    lines = time_area_lines(v.flow, v.cam, results.engine, results.spec.valves["intake"].count, table)
    assert [line["symbol"] for line in lines] == ["V‴", "v_vp", "ξ"]
    for line in lines:
        assert evaluate(line) == pytest.approx(_value(line["result"]), rel=3e-3), line


def test_an_asymmetric_kurz_cam_has_no_law_lines():
    """Two Kurz flanks make a law named "kurz" without the symmetric law's w' and Phi: its coefficients are each
    flank's, so the worked example writes none (fuzz6: tools/fuzz_specs.py's asymmetric Kurz base, the report of
    every run an AttributeError traceback; fails before)."""
    from valvetrain.specification import spec_document, validate
    doc = spec_document(appendix_spec())
    doc["valves"]["intake"]["cam"].update(     # tests/laws/test_asymmetric.py's flanks, adding up to 142 cam deg
        phi1_deg=21.0, phi2_deg=5.0, phi3_deg=30.0,
        closing={"phi1_deg": 30.0, "phi2_deg": 7.0, "phi3_deg": 49.0, "ramp_end_velocity_mm_per_deg": 0.015})
    v = run(validate(doc)).valves["intake"]
    assert v.cam.law.name == "kurz" and law_lines(v.cam.law, v.cam) == []
