"""Issue 23, item 1: checks identified by a stable code, their texts rendered from a catalogue kept as data
(src/valvetrain/locale/LANG.toml), ``[[accepted]]`` by code or by the printed text, and check records that name
their code, valve and parameters."""

import ast
import copy
from dataclasses import replace
import importlib.util
import json
from pathlib import Path
import pickle
import string

import pytest

from valvetrain import checks, locale, strength
from valvetrain.checks import apply_acceptances, check
from valvetrain.design import run
from valvetrain.design.valve_checks import LAYOUT_BANDS
from valvetrain.locale import LANGS, NoteText, catalogue, code_of, codes, note, note_text, parameters
from valvetrain.report.html import WARNING_SYMBOLS
from valvetrain.report.names import quantity_text
from valvetrain.specification import SpecError
from valvetrain.specification.models import Acceptance

from appendix import appendix_spec

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "src" / "valvetrain"


def _fields(template):
    return {name for _, name, _, _ in string.Formatter().parse(template) if name}


def _literals():
    """Every string constant of the package's source, and the first arguments of its ``check`` calls."""
    found, first = set(), []
    for path in PACKAGE.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                found.add(node.value)
            if (isinstance(node, ast.Call) and getattr(node.func, "id", None) in ("check", "_ArrayCheck", "layout_check")
                    and node.args):
                first.append((path.name, node.args[0]))
    return found, first


def test_every_code_has_a_text_in_every_language_with_the_same_parameters():
    record = catalogue("en")["record"]
    for lang in LANGS:
        assert set(catalogue(lang)["checks"]) == set(record), lang
        assert set(catalogue(lang)["springs"]) == set(catalogue("en")["springs"]), lang
        assert set(catalogue(lang)["chapters"]) == set(catalogue("en")["chapters"]), lang
        assert set(catalogue(lang)["designer"]) == set(catalogue("en")["designer"]), lang
        for code, template in catalogue(lang)["checks"].items():
            assert _fields(template) == _fields(record[code]), (lang, code)


def test_every_code_is_used_and_every_check_names_a_code():
    """A catalogue entry no check makes is dead text; a check made with a literal that is no code is refused at
    run time, and found here before it runs.  The strength checks are made by their key of ``strength.LIMITS``."""
    found, first = _literals()
    made = found | {f"strength.{key}" for key in strength.LIMITS}
    assert [c for c in codes() if c not in made] == []
    literal = [(f, a.value) for f, a in first if isinstance(a, ast.Constant)]
    assert literal and [(f, c) for f, c in literal if c not in codes()] == []
    assert set(LAYOUT_BANDS) <= set(codes())
    assert {c for group in WARNING_SYMBOLS.values() for c in group} <= set(codes())


def test_a_check_without_a_text_is_refused_naming_the_catalogue():
    with pytest.raises(ValueError, match=r"'lash_adjuster\.collapse' has no text in src/valvetrain/locale/en\.toml"):
        check("lash_adjuster.collapse", 1.0, high=2.0, source="s")


def test_the_table_of_codes_in_the_docs_is_the_catalogues():
    spec = importlib.util.spec_from_file_location("check_codes", ROOT / "tools" / "check_codes.py")
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    assert (ROOT / "docs" / "checks.md").read_text(encoding="utf-8") == tool.text()
    assert all(f"`{code}`" in tool.text() for code in codes())


def test_a_record_text_maps_to_its_code_and_parameters():
    """Hand-written: the texts printed before the codes, as a user typed them in [[accepted]]."""
    assert code_of("closing lag") == ("timing.closing_lag", {})
    assert code_of("Power-polynomial exponent   q") == ("law.power_polynomial.exponent", {"exponent": "q"})
    assert code_of("equivalent throat diameter sqrt(2) d / bore") == ("flow.equivalent_throat_to_bore",
                                                                       {"count": "2"})
    assert code_of("lash adjuster collapse") is None
    assert parameters("ports.width_to_bore") == ("port",)


def _exponents():
    return [check("law.power_polynomial.exponent", 9.0, 2.0, 3.0, source="s", params={"exponent": k}).of_valve("intake")
            for k in "nm"]


@pytest.mark.parametrize("quantity, accepted", [
    ("law.power_polynomial.exponent", [True, True]),            # the code: every exponent
    ("intake: power-polynomial exponent m", [False, True]),     # the printed text: that exponent only
    ("power-polynomial exponent n", [True, False]),
])
def test_an_acceptance_names_a_check_by_its_code_or_by_its_printed_text(quantity, accepted):
    out, unmatched = apply_acceptances(_exponents(), [Acceptance(quantity=quantity, reason="r")], {"intake"})
    assert [c.accepted for c in out] == accepted and unmatched == []


def test_an_acceptance_by_code_keeps_to_its_valve():
    out, unmatched = apply_acceptances(_exponents(), [Acceptance(quantity="law.power_polynomial.exponent",
                                                                 reason="r", valve="exhaust")], {"intake", "exhaust"})
    assert not any(c.accepted for c in out) and unmatched == [0]


def test_a_spring_check_is_accepted_by_its_printed_text_and_by_its_code():
    tau = check("spring.tau_max", 2.0, high=1.0, source="s", severity="failure").of_spring("outer").of_valve("intake")
    assert tau.quantity == "intake: outer tau_max"
    for quantity in ("intake: outer tau_max", "spring.tau_max"):
        (out,), unmatched = apply_acceptances([tau], [Acceptance(quantity=quantity, reason="r")], {"intake"})
        assert out.accepted and unmatched == [], quantity
    assert quantity_text(tau, "ru") == "intake: наружная пружина: τ_max"


def test_an_acceptance_by_code_survives_a_reworded_check(monkeypatch):
    """Before, a check was named by its text: rewording it broke its acceptance silently.  A code does not change
    with the wording; the old text then names no check, and the design refuses it (not silently)."""
    reworded = copy.deepcopy(catalogue("en"))
    reworded["record"]["timing.closing_lag"] = "closing-lag angle"
    original = locale.catalogue
    monkeypatch.setattr(locale, "catalogue", lambda lang: reworded if lang == "en" else original(lang))
    monkeypatch.setattr(checks, "catalogue", locale.catalogue)
    locale._patterns.cache_clear()
    try:
        lag = check("timing.closing_lag", 78.0, 40.0, 60.0, source="s").of_valve("intake")
        assert lag.quantity == "intake: closing-lag angle"
        (out,), unmatched = apply_acceptances([lag], [Acceptance(quantity="timing.closing_lag", reason="r")],
                                              {"intake"})
        assert out.accepted and unmatched == []
        (out,), unmatched = apply_acceptances([lag], [Acceptance(quantity="closing lag", reason="r")], {"intake"})
        assert not out.accepted and unmatched == [0]
    finally:
        locale._patterns.cache_clear()


def test_the_seating_velocity_check_says_what_it_grades_and_its_former_text_still_names_it():
    """Issue 36: the check grades the largest seating velocity of the rated speed and of the speeds swept below it,
    and its record text said "at the rated speed".  Its text says the largest up to the rated speed; an [[accepted]]
    table written with the former text (en.toml [former]) still names it, with or without the valve."""
    seat = check("dynamics.seating_velocity", 0.6, high=0.5, unit="m/s", source="s").of_valve("intake")
    assert seat.quantity == "intake: largest dynamic seating velocity up to the rated speed"
    for quantity in ("intake: dynamic seating velocity at the rated speed", "dynamic seating velocity at the rated speed",
                     "intake: largest dynamic seating velocity up to the rated speed", "dynamics.seating_velocity"):
        (out,), unmatched = apply_acceptances([seat], [Acceptance(quantity=quantity, reason="r")], {"intake"})
        assert out.accepted and unmatched == [], quantity
    former = catalogue("en")["former"]
    assert set(former) <= set(codes())
    assert all(text != catalogue("en")["record"][code] for code, texts in former.items() for text in texts)


def test_the_design_accepts_by_code_and_by_the_old_text_and_refuses_an_unknown_name():
    spec = appendix_spec()
    for quantity in ("timing.closing_lag", "intake: closing lag"):
        accepted = spec.model_copy(update={"accepted": [Acceptance(quantity=quantity, reason="as printed")]})
        assert [c.quantity for c in run(accepted).accepted] == ["intake: closing lag"], quantity
    wrong = spec.model_copy(update={"accepted": [Acceptance(quantity="timing.closing", reason="r")]})
    with pytest.raises(SpecError, match="did you mean 'timing.closing_lag'"):
        run(wrong)


def test_every_check_record_names_its_code_valve_and_parameters():
    records = run(appendix_spec()).to_dict()["checks"]
    for r in records:
        assert r["code"] in codes()
        head, _, rest = r["quantity"].partition(": ")
        if r["valve"] is not None:
            assert head == r["valve"]
            assert r["code"].startswith("spring.") or code_of(rest)[0] == r["code"], r
    by_code = {r["code"]: r for r in records}
    assert by_code["engine.stroke_to_bore"]["valve"] is None
    assert by_code["spring.tau_max"]["params"] == {"spring": "spring"}
    assert by_code["spring.tau_max"]["quantity"] == "intake: spring tau_max"
    pair = check("flow.equivalent_throat_to_bore", 0.5, 0.4, 0.45, source="s", params={"count": 2}).as_dict()
    assert pair["params"] == {"count": 2} and pair["quantity"] == "equivalent throat diameter sqrt(2) d / bore"
    assert {r["valve"] for r in records} == {"intake", None}


def test_a_spring_checks_key_is_its_code():
    """The spring diagnosis names a failing check by its key (``coil_gap_at_full_lift``) and the report names it by
    the code ``spring.KEY``: every spring check's code is ``spring.`` and its key."""
    tree = ast.parse((PACKAGE / "springs" / "candidates.py").read_text(encoding="utf-8"))
    pairs = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Dict):
            pairs += [(k.value, v.args[0].value) for k, v in zip(node.keys, node.values)
                      if isinstance(v, ast.Call) and getattr(v.func, "id", None) == "_ArrayCheck"]
        if (isinstance(node, ast.Assign) and isinstance(node.value, ast.Call)
                and getattr(node.value.func, "id", None) == "_ArrayCheck"):
            pairs.append((node.targets[0].slice.value, node.value.args[0].value))
    assert len(pairs) >= 9 and all(code == f"spring.{key}" for key, code in pairs), pairs


def test_every_text_made_with_numbers_is_rendered_from_its_code():
    """The reason of a check that cannot be evaluated is said in Russian.  A record's note (``NoteText``: the firing
    order, the hydraulic speed plan) is rendered from its code in either language, its list joined by the language's
    words."""
    from valvetrain.report.names import translate
    assert translate(checks.UNEVALUATED, "ru") == "значение не удалось вычислить"
    firing = NoteText(note("crank.firing_even", order="1-5-3-6-2-4"))      # a record's note: rendered from its code
    assert firing == "even firing, order 1-5-3-6-2-4" and translate(firing, "en") == firing
    assert translate(firing, "ru") == "равномерное чередование вспышек, порядок работы 1-5-3-6-2-4"
    assert pickle.loads(pickle.dumps(firing)).parts == firing.parts and json.dumps(firing) == json.dumps(str(firing))
    timing = note("crank.valve_timing", valves=note("crank.intake_valve", opens_deg=-12.5, closes_deg=228.0)
                  + note("crank.exhaust_valve", opens_deg=491.0, closes_deg=10.0))
    assert note_text(timing) == "intake valve -12.5...228 and exhaust valve 491...10 crank deg from the gas-exchange TDC"
    assert note_text(timing, "ru") == ("впускной клапан -12,5...228 и выпускной клапан 491...10 град ПКВ от ВМТ "
                                       "газообмена")
    plan = NoteText(note("hydraulic.speed_range", low_rpm=700.0, high_rpm=7700.0, low_share=0.1, high_share=1.1))
    assert plan == "speed range 700-7700 rpm: 10% to 110% of the rated speed"
    assert translate(plan, "ru") == "диапазон частот 700-7700 мин⁻¹: от 10% до 110% номинальной"


def _note_fields(template):
    """The fields of a note's text and their formats; a list's joiner (``|; or ``) and a word's section (``@checks``)
    are words of the language: only their kind is compared."""
    return sorted((name, spec[0] if spec[:1] in ("|", "@") else spec)
                  for _, name, spec, _ in string.Formatter().parse(template) if name)


def test_every_note_is_in_every_language_with_the_same_numbers_and_is_made():
    """Issue 41: a check's note is a code of ``[notes]`` with parameters: each code has a text in every language that
    takes the same parameters in the same format (the number's digits the same in the report of either language),
    or none said in that language (an empty text: the spring diagnosis' stress window in English), and each is made
    by a ``note("code", ...)`` of the package (a code no stage makes is dead text)."""
    for lang in LANGS:
        assert catalogue(lang)["notes"].keys() == catalogue("en")["notes"].keys(), lang
        for code, template in catalogue(lang)["notes"].items():
            english = catalogue("en")["notes"][code]
            assert not template or not english or _note_fields(template) == _note_fields(english), (lang, code)
    strings = {node.value for path in PACKAGE.rglob("*.py") for node in ast.walk(ast.parse(path.read_text("utf-8")))
               if isinstance(node, ast.Constant) and isinstance(node.value, str)}
    assert sorted(set(catalogue("en")["notes"]) - strings) == []


def test_a_note_renders_its_numbers_by_the_rule_of_its_language():
    """The note of a check is its English text in the records, and the report renders its code in Russian with a
    decimal comma in each number (the same digits): the lubrication's worst film parameter at 7000 rpm and
    -12.345 cam deg (4 significant figures: -12.35)."""
    from valvetrain.locale import note_text
    from valvetrain.report.check_rows import check_note

    parts = note("lubrication.worst_at", speed_rpm=7000.0, cam_deg=-12.345) + note("lubrication.zero_entrainment")
    c = check("lubrication.film_parameter", 0.8, low=1.0, source="s", note=parts)
    assert c.note == ("at 7000 rpm, -12.35 cam deg from the nose; the film vanishes where the entraining velocity "
                      "changes sign (squeeze film not modelled)") == note_text(parts)
    assert c.note_parts == parts and c.as_dict()["note"] == c.note
    assert check_note(c, "ru").startswith("при 7000 мин⁻¹, -12,35 град ПРВ от вершины кулачка; плёнка исчезает")
    assert check_note(replace(c, note_parts=()), "en") == c.note
    with pytest.raises(ValueError, match=r"'lubrication\.unknown' has no text in src/valvetrain/locale/en\.toml \[notes\]"):
        note("lubrication.unknown")


def test_a_number_in_brackets_of_a_russian_note_has_its_decimal_comma():
    """The Russian report's page-wide decimal comma leaves a number right after "(" as it is (a locator of a source:
    "(7.4)"), so a note's frequency printed "(326.8 Гц)" (pushrod-dynamics' camshaft resonances); a note rendered
    from its code formats its numbers in Russian itself: "(326,8 Гц)"."""
    from valvetrain.locale import note_text
    from valvetrain.report.russian import russian_typography

    parts = note("camshaft.first_resonance_met", order=8, mode=1, frequency_Hz=326.8, speed_rpm=4903.2, cam_deg=0.36,
                 force_N=328.2)
    assert russian_typography(f"<td>{note_text(parts, 'ru')}</td>") == (
        "<td>резонансы: гармоника порядка 8 совпадает с формой 1 (326,8 Гц) при 4903 мин⁻¹: 0,36 град ПРВ, 328,2 Н</td>")
    assert "(326.8 Hz)" in note_text(parts)


def test_a_note_says_a_list_and_a_word_in_its_language():
    """A note's parameter may be a note of its own, said inside the part and joined by the field's ``|joiner``; a
    ``{name:@section}`` field says the value's word of that section in the language, ``@units`` a unit's symbol:
    the spring diagnosis' conflicts of a pair, written out by hand."""
    from valvetrain.locale import note_text

    conflict = note("spring.conflict_of", spring="outer", conflict=note(
        "spring.conflict_in", check="spring.tau_max", value=600.0, limit=500.0, unit="MPa", shortfall=0.2))
    both = note("spring.no_pair_passes", conflicts=conflict + note("spring.conflict_of", spring="inner", conflict=note(
        "spring.conflict", check="spring.fatigue_safety", value=1.1, limit=1.3, shortfall=0.154)))
    assert note_text(both) == ("No nested pair passes; the best pair: outer tau_max 600 MPa against 500 MPa (short by "
                               "20.0%); inner fatigue safety factor 1.1 against 1.3 (short by 15.4%).")
    assert note_text(conflict, "ru") == "наружная пружина: τ_max 600 МПа при допустимом 500 МПа (не хватает 20,0%)"
    assert note_text(note("spring.tried", remedies=note("spring.remedy.no_installed_length_limit")
                          + note("spring.remedy.reduced_mass_tried", percent=10.0))) == \
        "None passes with no installed length limit, a reduced mass down to 10 %."
    assert note_text(note("spring.stress_window", stress_needed_MPa=720.0, stress_allowed_MPa=752.0)) == ""


def test_every_problem_of_a_specification_is_said_in_every_language():
    """Issue 41: a problem the package finds in a specification (a :class:`~valvetrain.specification.messages.Problem`)
    says what is wrong by a note of the catalogue (``spec.*``, ``field.*``, a law's ``law_error.*``), the designer
    says it in its language: no problem is made with a message written in the code as English text.  The two left
    are the programmatic API's (a specification that is not text) and a count with thousands separators."""
    english = []
    for path in PACKAGE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text("utf-8"))):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "Problem" and len(node.args) > 1:
                if isinstance(node.args[1], (ast.Constant, ast.JoinedStr, ast.BinOp)):
                    english.append((path.name, ast.unparse(node.args[1])[:40]))
    assert sorted(english) == [("reading.py", "f'a specification is TOML text or a dict"),
                               ("reading.py", "f'{len(text):,} characters; allowed at m")]
