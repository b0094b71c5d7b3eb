"""The further stages' key names (report/stage_names.py)."""

import re

from valvetrain.report.names import NAMES, label
from valvetrain.report.stage_names import STAGE_NAMES


def test_every_stage_name_is_in_both_languages_and_joined():
    for key, (en, ru) in STAGE_NAMES.items():
        assert en and not re.search("[а-яё]", en, re.I), key
        assert re.search("[а-яё]", ru, re.I), key
        assert NAMES[key] == (en, ru)


def test_a_switching_key_is_labelled_with_its_unit():
    assert label("switching.inner_arm_mm", "ru") == "внутренний рычаг от оси до центра ролика L_i, мм"
    assert label("switching.inner_arm_mm", "en") == "inner arm, pivot to roller centre L_i, mm"
