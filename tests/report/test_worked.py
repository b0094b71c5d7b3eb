"""Issue 24: worked substitution.  Every worked line of the built-in example's report evaluates (its numbers as
printed, to 4 significant figures) to its printed result, and the lines give the numbers of a hand calculation:

- f_g = pi 36.8^2 / 4 = 1063.6 mm2;  f_max = pi 10 (36.8 cos 45 + 10 sin 45 cos^2 45) = 928.56 mm2;
- V' = 18 x 5026.5 / 1063.6 = 85.07 m/s;  V'' = 18 x 5026.5 / 928.56 = 97.44 m/s (the example's c_p = 18 m/s).
"""

import math
import re

import pytest

from valvetrain.design import run
from valvetrain.report.worked import flow_lines, spring_lines

from appendix import appendix_spec


def evaluate(line, lang="en"):
    """The number a line's substituted text gives: units dropped, the operators made Python's."""
    text = line["substituted"]
    if lang == "ru":
        text = text.replace(",", ".")
    text = text.replace("π", "pi").replace("×", "*").replace("cos² ", "cos2 ").replace("²", "**2").replace("³", "**3")
    text = re.sub(r"(\d)°", r"\1", text)
    text = re.sub(r"\s(mm\*\*2|mm|m/s|N/mm|N|MPa|мм\*\*2|мм|м/с|Н/мм|Н|МПа)(?=[\s)*+/]|$)", " ", text)
    text = re.sub(r"(sin|cos2|cos) ([\d.]+)", r"\1(\2)", text)
    return eval(text, {"pi": math.pi, "sin": lambda x: math.sin(math.radians(x)),
                       "cos": lambda x: math.cos(math.radians(x)), "cos2": lambda x: math.cos(math.radians(x)) ** 2})


def _lines(lang):
    results = run(appendix_spec())
    valve = results.spec.model_dump()["valves"]["intake"]
    v = results.valves["intake"]
    return flow_lines(valve, v.flow, results.engine, lang) + spring_lines(v.drive.spring.design, lang)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_line_evaluates_to_its_result(lang):
    for line in _lines(lang):
        result = float(line["result"].split()[0].replace(",", "."))
        assert evaluate(line, lang) == pytest.approx(result, rel=3e-3), line     # 4 figures in, 4 figures out


def test_the_flow_lines_give_the_hand_calculation():
    by_symbol = {line["symbol"]: line for line in _lines("en")}
    assert by_symbol["f_g"]["result"] == "1064 mm²" and math.pi * 36.8**2 / 4 == pytest.approx(1063.6, abs=0.05)
    assert by_symbol["f_max"]["result"] == "928.6 mm²"
    assert by_symbol["V′"]["result"] == "85.07 m/s" and by_symbol["V″"]["result"] == "97.44 m/s"
    assert by_symbol["f_max"]["substituted"] == "π × 10 mm × (36.8 mm × cos 45° + 10 mm × sin 45° × cos² 45°)"
