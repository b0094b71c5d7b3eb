"""The Russian report's citations and typography: the locators of the numbered citations (work, eq., section) and
the notes of the sources in Russian, the decimal comma and «» quotes.

The report cites every work by its number in its list of sources (:func:`valvetrain.report.html.numbered_citations`),
each work described in its own language (:meth:`valvetrain.bibliography.Work.reference`);
:func:`russian_citations` turns the locators and the notes of the rendered Russian report's citations into Russian.
"""

from html import escape, unescape
import re

from .typography import map_text

LOCATORS = (
    (r"corrections notes? (\d+)", r"поправка \1"), (r"\bworks (\d)", r"работы \1"), (r"\bwork (\d)", r"работа \1"),
    (r"\beqs\. ", "формулы "), (r"\beq\. ", "формула "), (r"\bsections (\d)", r"разделы \1"),
    (r"\bsection (\d)", r"раздел \1"), (r"\bchapter (\d)", r"глава \1"), (r"\bch\. (\d)", r"гл. \1"),
    (r"\bTable (\S)", r"таблица \1"),
    (r"\bappendix\b", "приложение"), (r"\bp\. (\d)", r"с. \1"),
    (r"the follower's force at the adjuster's push ([\d.]+) N at the valve, where its check valve opens \(",
     r"сила толкателя у гидрокомпенсатора \1 Н, приведённая к клапану, при которой открывается его обратный клапан ("),
)
"""Locators of a citation in Russian (regular expression, replacement)."""

NOTES = {
    "usually 30 deg inlet, 45 deg exhaust": "обычно 30° у впускного, 45° у выпускного клапана",
    "i_k = 1 for direct drive, 1.4-1.75 with a rocker or lever":
        "i_к = 1 при непосредственном приводе, 1,4-1,75 с коромыслом или рычагом",
    "tappet, pushrod and rocker 400-500 kg/m2": "толкатель, штанга и коромысло 400-500 кг/м²",
    "direct drive 200-300 kg/m2": "непосредственный привод 200-300 кг/м²",
    "negative 500...1500 m/s2": "отрицательное 500...1500 м/с²",
    "positive 1500...3500 m/s2": "положительное 1500...3500 м/с²",
    "1.5-2.0; supercharged 3.0-4.0": "1,5-2,0; с наддувом 3,0-4,0",
    "automotive engines": "автомобильные двигатели",
    "with the rounded coils": "с округлённым числом витков",
    "rounded down to half coils": "с округлением вниз до половины витка",
    "hard to meet at high speed": "трудно выполнимо при высокой частоте вращения",
    "the two ratios must differ": "два отношения должны различаться",
    "central mechanism": "центральный механизм",
    "corrected": "исправлено",
    "engine builders' rule of at least 0.080 in intake, 0.100 in exhaust (HP Academy, "
    "'Measuring piston to valve clearance'); gap": "правило мотористов: не менее 0,080 дюйма у впускного и 0,100 "
    "дюйма у выпускного клапана (HP Academy, «Measuring piston to valve clearance»); зазор",
    "with a ramp derived in this package": "с рампой, выведенной в этой программе",
    "specific mass ": "удельная масса ", "default for a pushrod drive": "по умолчанию для привода со штангой",
    "default for a rocker drive": "по умолчанию для привода с коромыслом",
    "default for a direct drive": "по умолчанию для непосредственного привода",
    "the master cam of a cam grinder and the effect of the wheel radius on the cam profile; the formulas are derived "
    "in this package from the contour geometry of": "копир кулачкового шлифовального станка и влияние радиуса круга "
                                                   "на профиль кулачка; формулы выведены в этой программе из "
                                                   "геометрии контура,",
    "ramp (": "рампа (", "segments (": "участки (", "coefficients (": "коэффициенты (", "extremes (": "экстремумы (",
    "one-mass and multi-mass trains, jump, seating, bounce":
        "одномассовая и многомассовая модели привода, отрыв, посадка, отскок",
    "resonant harmonic and distortion": "резонансная гармоника и искажение",
    "(side_valve chamber)": "(нижнее расположение клапанов)", "(overhead chamber)": "(верхнее расположение клапанов)",
    "(prechamber_diesel chamber)": "(вихрекамерные и предкамерные дизели)",
    "(direct_injection_diesel chamber)": "(дизели с непосредственным впрыском)",
    "(wedge chamber)": "(клиновидная и плоскоовальная камеры сгорания)",
    "(hemispherical chamber)": "(полусферическая камера сгорания)",
    "the chosen springs' rounded coils can move it off the required line's ratio":
        "округлённое число витков выбранной пружины может сместить его от отношения необходимой характеристики",
    " with [tau] of ": " с [τ] стали ", "tau_-1 and psi_tau of ": "τ₋₁ и ψ_τ стали ", "Tables ": "таблицы ",
    "table A-9": "таблица A-9", "(R_m of ASTM A401)": "(R_m по ASTM A401)", "(psi_tau: literature, ": "(ψ_τ: по литературе, ",
    "installed_length_mm of the specification, or 6 x lift (a stated default)":
        "установочная длина из исходных данных или 6 × подъём (принято по умолчанию)",
    "0.3-0.5 m/s usual, graded at every speed swept up to the rated one":
        "обычно 0,3-0,5 м/с; оценивается на всех частотах расчёта до номинальной",
    "0.3-0.5 m/s usual": "обычно 0,3-0,5 м/с", "ch. 3 and ch. 7": "гл. 3 и 7",
    ": no separation below [engine] over_speed_ratio x the rated speed":
        ": без отрыва толкателя до наибольшей частоты вращения (over_speed_ratio × номинальная)",
    "(flat-faced follower face width)": "(ширина торца плоского толкателя)",
    "a factor of 3 beyond ": "пределы, расширенные в 3 раза относительно: ",
    ": an engine delivers work; a cycle whose pressures give a negative mean torque absorbs it (a motored engine), "
    "and its non-uniformity is undefined": ": двигатель совершает работу; цикл, давления которого дают отрицательный "
    "средний момент, её поглощает (двигатель прокручивается извне), и его неравномерность не определена",
    "(pressure angle: side load F_n sin(alpha)); no source gives an allowable":
        "(угол давления: боковая сила F_n sin α); допускаемого значения источники не дают",
    "(hydraulic valve actuation)": "(гидравлический привод клапана)",
    "(wave speed, method of characteristics)": "(скорость волны, метод характеристик)",
    "(the lost-motion drive)": "(привод с потерянным ходом)", "(the orifice equation)": "(уравнение истечения)",
    "5 % of the rigid lift, the level of the delays (this package's)":
        "5 % подъёма при жёстком приводе, уровень отсчёта запаздываний (принято в этой программе)",
    ": accuracy_mm, met by N <= 9 harmonics (N by the residual against the accuracy, 0.002-0.01 mm)":
        ": accuracy_mm, достигается при N ≤ 9 гармониках (N по отклонению относительно точности, 0,002-0,01 мм)",
    ": <= 150 MPa, the bending allowable of the rocker gear's steels 20Kh, 40Kh, 45, taken for the finger; "
    "sigma = 6 M / (b h^2) of its rectangular section, ": ": ≤ 150 МПа, допускаемое напряжение изгиба сталей "
    "коромысла 20Х, 40Х, 45, принятое для рычага; σ = 6 M / (b h²) его прямоугольного сечения, ",
    ": boundary lubrication below lambda = 1; ": ": граничное трение при λ < 1; ",
    ": scuffing at a critical temperature of the oil; ": ": задир при критической температуре масла; ",
    ": annular leakage and the check valve's orifice flow; ":
        ": утечки через кольцевой зазор и расход через отверстие обратного клапана; ",
    ": the plunger's extension simulated with the train up to [engine] over_speed_ratio x the rated speed; ":
        ": выдвижение плунжера рассчитано вместе с приводом до наибольшей частоты вращения (over_speed_ratio × "
        "номинальная); ",
    "), while the cam lifts the open valve: no float below [engine] over_speed_ratio x the rated speed; ":
        "), пока кулачок поднимает открытый клапан: без отрыва до наибольшей частоты вращения (over_speed_ratio × "
        "номинальная); ",
    ": the valve's lift on the base circle simulated with the plunger's extension; ":
        ": подъём клапана на тыльной части кулачка рассчитан с выдвижением плунжера; ",
    " (torsion); ": " (кручение); ", " (an engineering assumption)": " (инженерное допущение)",
    "(the maker's allowable of the chain": "(допускаемое значение изготовителя цепи",
    "(the maker's allowable of the belt": "(допускаемое значение изготовителя ремня",
    "(the maker's allowable of the gears": "(допускаемое значение изготовителя шестерён",
    " applied to the master and its roller": " применительно к копиру и его ролику",
    " (the wheel radius must not exceed the concave radius of the cam); ":
        " (радиус круга не должен превышать радиус вогнутого участка кулачка); ",
    ": exponent ranges from the authors' search studies": ": диапазоны показателей степени по поисковым расчётам авторов",
    "of the specification: the smaller margin of the fatigue safety and the resonance ratio above their minima":
        "задания: меньший из запасов по усталости и по отношению частот сверх их наименьших значений",
}
"""The notes the sources of the checks carry, in Russian."""

UNITS = ((r"(\d) kg/m2\b", r"\1 кг/м²"), (r"(\d) MPa\b", r"\1 МПа"), (r"(\d) mm\b", r"\1 мм"), (r"(\d) deg\b", r"\1°"))
"""Units inside a citation's note."""

_CITE = re.compile(r'(<span class="cite">)(.*?)(</span>)', re.S)


def citation(text) -> str:
    """One citation in Russian: its locators, the notes of its source and their units.

    >>> citation("[2, work 1, eq. (1.1)]")
    '[2, работа 1, формула (1.1)]'
    >>> citation("[1, section 2.1, eqs. (2.13)-(2.14)] (usually 30 deg inlet, 45 deg exhaust)")
    '[1, раздел 2.1, формулы (2.13)-(2.14)] (обычно 30° у впускного, 45° у выпускного клапана)'
    """
    for en, ru in NOTES.items():
        text = text.replace(en, ru)
    for pattern, ru in LOCATORS + UNITS:
        text = re.sub(pattern, ru, text)
    return text


def russian_citations(page) -> str:
    """The rendered Russian report with its citations in Russian (:func:`citation` on every ``span.cite``)."""
    return _CITE.sub(lambda m: m.group(1) + escape(citation(unescape(m.group(2))), quote=False) + m.group(3), page)


_DECIMAL = re.compile(r"(?<![\d,])(?<!\d\.)(?<!\()(?<!ф\. )(?<!рис\. )(?<!раздел )(?<!разделы )(?<!гл\. )"
                      r"(?<!глава )(?<!формула )(?<!формулы )(?<!таблица )(\d+)\.(\d+)(?!\.?\d)")
"""A decimal point between digits, not in a locator of a source (``(7.4)``, ``раздел 2.1``, ``ф. 2.5``) nor in a
version (``0.1.0``)."""
_QUOTED = re.compile(r'"([^"<>]*)"')


def russian_typography(page) -> str:
    """The rendered Russian report with a decimal comma in every number of its text and «» for quotation marks
    (:data:`_DECIMAL`; the designer's names, links, the file's head and works in other languages as they are).

    >>> russian_typography('<p>при 7700 мин⁻¹, -56.87 град, формулы (7.4)-(7.5), "quoted"</p>')
    '<p>при 7700 мин⁻¹, -56,87 град, формулы (7.4)-(7.5), «quoted»</p>'
    >>> russian_typography('<span class="name">v1.5</span> 0.5...0.75 <a href="x">tables/a.0.5.csv</a>')
    '<span class="name">v1.5</span> 0,5...0,75 <a href="x">tables/a.0.5.csv</a>'
    """
    return map_text(page, lambda text: _QUOTED.sub(r"«\1»", _DECIMAL.sub(r"\1,\2", text)), "ru")
