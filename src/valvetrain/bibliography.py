"""The works this package cites, once: a short key for each, the full reference and a short in-text form.

In code a source is written ``cite("shang1988", "eq. (2.6)")`` -> ``"Shang Hanji (1988), eq. (2.6)"``;
:func:`entry` gives the full reference, as printed at the end of the design report in the form of GOST 7.1
(authors, title, place, publisher, year, pages; each work described in its own language, a title in another
script transliterated, with its translation in brackets).  The design report cites a work by its number in that list
(``[2, work 5]``, :func:`valvetrain.report.html.numbered_citations`).

Four of the Russian and Ukrainian documents the package was built from have no title page in the copies used:
they are described under a descriptive title in the original language, and what the document does not give (its
authors, place, publisher, year, pages) is said so in words (the catalogue's ``[reference_words]``, :mod:`valvetrain.locale`).  The authors and the journal of the
Ukrainian article are those of its catalogue record (DOI 10.18664/1994-7852.184.2019.171481); the extent of Shang's
book is its imprint's.  Nothing here is guessed.

Misprints of these works and what the package uses instead are explained in the corrections notes
shipped with the package (:func:`corrections_text`, ``valvetrain/data/corrections.md``).

>>> cite("shang1988", "eq. (2.6)")
'Shang Hanji (1988), eq. (2.6)'
>>> entry("hertz1882")
'Hertz H. Über die Berührung fester elastischer Körper [On the contact of elastic solids] // Journal für die reine und angewandte Mathematik. – 1882. – Vol. 92. – P. 156–171. – In German.'
"""

from dataclasses import dataclass
from importlib import resources
import re

from .locale import catalogue

UNKNOWN = "year not given in the document"
"""The year of a work whose document gives none."""

NO_AUTHORS = "authors not given in the document"
"""The authors of a work whose document names none."""

PLAIN_KINDS = ("book", "textbook", "journal article", "article", "conference paper", "standard", "web page")
"""Kinds of work a reference does not name (its form says it); another kind (a teaching manual) follows the title."""


@dataclass(frozen=True)
class Work:
    """One cited work, described in its own language (GOST 7.1).

    Attributes
    ----------
    short : str
        The in-text form, e.g. ``"Shang Hanji (1988)"``.
    authors : str
        Authors or editor, ``"Surname, I. I."`` joined by ``"; "`` (a Chinese name as written, surname first), or the
        institution; :data:`NO_AUTHORS` where the document names none.
    title : str
        Title in the original language, transliterated in Latin letters where its script is not Latin or Cyrillic.
    kind : str
        Book, article, teaching manual, standard, web page...; a kind not in :data:`PLAIN_KINDS` (in the work's
        language) follows the title.
    translation : str
        The title in English, for a work in another language.
    translation_ru : str
        The title in Russian, for a work in a language a Russian reader does not read (Chinese).
    edition : str
        The edition statement (``"2nd ed."``, ``"2-е изд."``).
    publisher, place, year : str
        Publisher (empty for an article), place, year or :data:`UNKNOWN`.
    journal, volume : str
        The journal or proceedings holding an article and its volume and issue (``"Vol. 22, no. 158"``).
    pages : str
        The extent of a book (``"236 p."``) or the pages of an article (``"P. 156–171"``).
    isbn, doi, url : str
    language : str
        The work's language (English, Russian, Ukrainian, Chinese, German).
    missing : tuple of str
        What the document does not give, of ``authors``, ``place``, ``publisher``, ``year``, ``pages``.
    note, note_ru : str
        What of the work is used, or what the copy used lacks, in English and in Russian.
    """

    short: str
    authors: str
    title: str
    kind: str
    translation: str = ""
    translation_ru: str = ""
    edition: str = ""
    publisher: str = ""
    place: str = ""
    year: str = UNKNOWN
    journal: str = ""
    volume: str = ""
    pages: str = ""
    isbn: str = ""
    doi: str = ""
    url: str = ""
    language: str = "English"
    missing: tuple = ()
    note: str = ""
    note_ru: str = ""

    def reference(self, lang="en") -> str:
        """The full reference as one line of text in the form of GOST 7.1, in the work's own language; the
        translation of its title, what its document does not give and the note in the report's language ``lang``.

        >>> print(WORKS["shang1988"].reference())
        Shang Hanji. Neiranji peiqi tulun jigou — sheji yu jisuan [Valve cam mechanisms of internal-combustion engines: design and calculation]. – Shanghai : Fudan University Press, 1988. – 236 p. – ISBN 7-309-00035-8. – In Chinese. – Note: Chapter 1 and section 2.1 (design criteria) are used; further sections named by the book's contents are reconstructed by this package, as their docstrings say.
        """
        words = catalogue(lang)["reference_words"]
        translation = self.translation_ru if lang == "ru" and self.translation_ru else \
            self.translation if lang == "en" or self.translation_ru else ""
        title = self.title + (f" [{translation}]" if translation else "")
        if self.kind not in PLAIN_KINDS:
            title += f" : {self.kind}"
        authors = "" if self.authors == NO_AUTHORS or self.kind in ("standard", "web page") else _authors(self.authors)
        head = f"{authors}{'' if authors.endswith(('.', ')')) else '.'} {title}" if authors else title
        areas = [head + (f" // {self.journal}" if self.journal else "")
                 + (f" // {self.authors}" if self.kind == "web page" else "")]
        areas += [self.edition] if self.edition else []
        if self.journal:
            areas += [", ".join(p for p in (self.place, self.year) if p and p != UNKNOWN)]
            areas += [self.volume]
        elif self.publisher or self.place:
            areas += [f"{self.place} : {self.publisher}, {self.year}" if self.place and self.publisher
                      else ", ".join(p for p in (self.place or self.publisher, self.year) if p != UNKNOWN)]
        areas += [self.pages]
        areas += [f"ISBN {self.isbn}"] if self.isbn else []
        areas += [f"DOI {self.doi}"] if self.doi else []
        areas += [f"URL: {self.url}"] if self.url else []
        if self.missing:
            missing = [words[k] for k in self.missing]
            missing = ", ".join(missing[:-1]) + f" {words['and']} " + missing[-1] if len(missing) > 1 else missing[0]
            areas.insert(1, "[" + words["phrase"].format(missing) + "]")
        if self.language in words["languages"]:
            areas += [words["language"].format(words["languages"][self.language])]
        note = self.note_ru if lang == "ru" and self.note_ru else self.note
        areas += [words["note"].format(note)] if note else []
        return " – ".join(a if a.endswith(".") else a + "." for a in areas if a)


def _authors(authors) -> str:
    """Authors in a reference's heading: ``"Kolchin, A. I.; Demidov, V. P."`` -> ``"Kolchin A. I., Demidov V. P."``."""
    return ", ".join(a.replace(", ", " ", 1) for a in authors.split("; "))


WORKS = {
    "shang1988": Work(
        short="Shang Hanji (1988)",
        authors="Shang Hanji",
        title="Neiranji peiqi tulun jigou — sheji yu jisuan",
        translation="Valve cam mechanisms of internal-combustion engines: design and calculation",
        translation_ru="Клапанные кулачковые механизмы двигателей внутреннего сгорания: проектирование и расчёт",
        kind="book", publisher="Fudan University Press", place="Shanghai", year="1988", pages="236 p.",
        isbn="7-309-00035-8", language="Chinese",
        note="Chapter 1 and section 2.1 (design criteria) are used; further sections named by the book's "
             "contents are reconstructed by this package, as their docstrings say.",
        note_ru="Использованы глава 1 и раздел 2.1 (критерии проектирования); следующие разделы, названные в "
                "оглавлении книги, восстановлены в этой программе, как сказано в их описаниях."),
    "vt_works": Work(
        short="Valve-train practical works (n.d.)",
        authors=NO_AUTHORS,
        title="Практические работы № 1–8 по расчёту газораспределительного механизма двигателя внутреннего сгорания",
        translation="Practical works 1–8 on the design of the valve train of an internal-combustion engine",
        kind="учебное пособие: практические работы 1–8 с приложением (безударный кулачок Курца для "
             "газораспределительного механизма бензинового двигателя, таблица П1)",
        language="Russian", missing=("authors", "place", "publisher", "year", "pages"),
        note="The copy used has no title page: the title is descriptive. Works: (1) valve flow sections, (2) Kurz "
             "shock-free cam, (3) polydyne cam, (4) time-area, (5) spring characteristic, (6) spring design, "
             "(7) strength of the drive parts, (8) two-stroke ports.",
        note_ru="В использованном экземпляре нет титульного листа: заглавие описательное. Работы: (1) проходные "
                "сечения клапана, (2) безударный кулачок Курца, (3) полидинамический кулачок, (4) время-сечение, "
                "(5) характеристика пружины, (6) расчёт пружины, (7) прочность деталей привода, (8) окна "
                "двухтактного двигателя."),
    "power_units": Work(
        short="Power units manual (n.d.)",
        authors=NO_AUTHORS,
        title="Методические указания к расчётно-графической работе по дисциплине «Силовые агрегаты»: кинематика "
              "поршня и динамика кривошипно-шатунного механизма",
        translation="Course-work manual for the course \"Power units\": piston kinematics and crank-mechanism "
                    "dynamics",
        kind="учебное пособие вуза", language="Russian", missing=("authors", "place", "publisher", "year", "pages"),
        note="The copy used has no title page: the title is descriptive. Its worked example (section 2.6) is not in "
             "the copy used.",
        note_ru="В использованном экземпляре нет титульного листа: заглавие описательное. Пример расчёта "
                "(раздел 2.6) в использованном экземпляре отсутствует."),
    "valve_dynamics_article": Work(
        short="Valve-train dynamics article (n.d.)",
        authors=NO_AUTHORS,
        title="Исследование динамики МГР с кулачками различного профиля",
        translation="A study of the dynamics of the valve train with cams of various profiles: three-arc, Kurz and "
                    "polydyne",
        kind="journal article", language="Russian",
        missing=("authors", "place", "publisher", "year", "pages"),
        note="The copy used has no title page: the title is that of its section; the journal is not named.",
        note_ru="В использованном экземпляре нет титульного листа: заглавие по заголовку раздела; журнал не указан."),
    "ukrsurt2019": Work(
        short="UkrSURT Proceedings (2019)",
        authors="Bratchenko, A. V.; Gromov, V. I.; Moroz, V. I.",
        title="Динамічний синтез безударних профілів кулачків привода клапанів форсованих транспортних дизелів",
        translation="Dynamic synthesis of shock-free cam profiles of the valve drive of forced transport diesels",
        kind="journal article",
        journal="Збірник наукових праць Українського державного університету залізничного транспорту",
        place="Kharkiv", year="2019", volume="Вип. 184", pages="С. 27 і далі", doi="10.18664/1994-7852.184.2019.171481",
        language="Ukrainian",
        note="The copy used has no title page: the title is descriptive, from the article's abstract; the authors as "
             "the catalogue record of the DOI spells them; the copy shows p. 28 on its second page, its last page "
             "not. Example: the ЧН26/27 (D80) transport diesel.",
        note_ru="В использованном экземпляре нет титульного листа: заглавие описательное, по аннотации статьи; "
                "авторы — по каталожной записи DOI; в экземпляре на второй странице стоит с. 28, последняя "
                "страница не указана. Пример: транспортный дизель ЧН26/27 (Д80)."),
    "kolchin1980": Work(
        short="Kolchin and Demidov (1980)",
        authors="Колчин, А. И.; Демидов, В. П.",
        title="Расчёт автомобильных и тракторных двигателей",
        translation="Design calculation of automotive and tractor engines",
        kind="textbook", edition="2-е изд.", publisher="Высшая школа", place="М.", year="1980",
        language="Russian"),
    "rothbart2004": Work(
        short="Rothbart (2004)",
        authors="Rothbart, H. A. (ed.)",
        title="Cam Design Handbook", kind="book", publisher="McGraw-Hill", place="New York", year="2004",
        isbn="0-07-143328-7"),
    "dudley1948": Work(
        short="Dudley (1948)",
        authors="Dudley, W. M.",
        title="New methods in valve cam design", kind="journal article",
        journal="SAE Quarterly Transactions", volume="Vol. 2, no. 1", pages="P. 19–33", year="1948"),
    "stoddart1953": Work(
        short="Stoddart (1953)",
        authors="Stoddart, D. A.",
        title="Polydyne cam design", kind="journal article",
        journal="Machine Design", volume="Vol. 25", year="1953", note="In three parts."),
    "wiebe1970": Work(
        short="Wiebe (1970)",
        authors="Vibe (Wiebe), I. I.",
        title="Brennverlauf und Kreisprozeß von Verbrennungsmotoren",
        translation="The course of combustion and the cycle of combustion engines", kind="book",
        publisher="VEB Verlag Technik", place="Berlin", year="1970", language="German"),
    "hertz1882": Work(
        short="Hertz (1882)",
        authors="Hertz, H.",
        title="Über die Berührung fester elastischer Körper", translation="On the contact of elastic solids",
        kind="journal article",
        journal="Journal für die reine und angewandte Mathematik", volume="Vol. 92", pages="P. 156–171",
        year="1882", language="German"),
    "wahl1944": Work(
        short="Wahl (1944)",
        authors="Wahl, A. M.",
        title="Mechanical Springs", kind="book", publisher="Penton Publishing", place="Cleveland",
        year="1944"),
    "norton2009": Work(
        short="Norton (2009)",
        authors="Norton, R. L.",
        title="Cam Design and Manufacturing Handbook", edition="2nd ed.", kind="book", publisher="Industrial Press",
        place="New York", year="2009"),
    "wang2007": Work(
        short="Wang (2007)",
        authors="Wang, Y.",
        title="Introduction to Engine Valvetrains", kind="book", publisher="SAE International", place="Warrendale, PA",
        year="2007"),
    "hendriksma2007": Work(
        short="Hendriksma, Kunz, Greene (2007)",
        authors="Hendriksma, N.; Kunz, T.; Greene, C.",
        title="Design and Development of a 2-Step Rocker Arm", kind="conference paper",
        journal="SAE Technical Paper 2007-01-1285", publisher="SAE International", place="Warrendale, PA",
        year="2007", doi="10.4271/2007-01-1285",
        note="The switching roller finger follower: its inner arm, lost-motion spring and latch."),
    "johnson1985": Work(
        short="Johnson (1985)",
        authors="Johnson, K. L.",
        title="Contact Mechanics", kind="book", publisher="Cambridge University Press", place="Cambridge",
        year="1985"),
    "heywood1988": Work(
        short="Heywood (1988)",
        authors="Heywood, J. B.",
        title="Internal Combustion Engine Fundamentals", kind="book", publisher="McGraw-Hill", place="New York",
        year="1988"),
    "wilson1927": Work(
        short="Wilson (1927)",
        authors="Wilson, E. B.",
        title="Probable inference, the law of succession, and statistical inference", kind="article",
        journal="Journal of the American Statistical Association", volume="Vol. 22, no. 158", pages="P. 209–212",
        year="1927"),
    "newcombe1998": Work(
        short="Newcombe (1998)",
        authors="Newcombe, R. G.",
        title="Two-sided confidence intervals for the single proportion: comparison of seven methods",
        kind="article", journal="Statistics in Medicine", volume="Vol. 17, no. 8", pages="P. 857–872", year="1998"),
    "devroye1986": Work(
        short="Devroye (1986)",
        authors="Devroye, L.",
        title="Non-Uniform Random Variate Generation", kind="book", publisher="Springer", place="New York",
        year="1986"),
    "sobol2001": Work(
        short="Sobol' (2001)",
        authors="Sobol', I. M.",
        title="Global sensitivity indices for nonlinear mathematical models and their Monte Carlo estimates",
        kind="article", journal="Mathematics and Computers in Simulation", volume="Vol. 55, no. 1–3",
        pages="P. 271–280", year="2001"),
    "saltelli2002": Work(
        short="Saltelli (2002)",
        authors="Saltelli, A.",
        title="Making best use of model evaluations to compute sensitivity indices", kind="article",
        journal="Computer Physics Communications", volume="Vol. 145, no. 2", pages="P. 280–297", year="2002"),
    "saltelli2010": Work(
        short="Saltelli et al. (2010)",
        authors="Saltelli, A.; Annoni, P.; Azzini, I.; Campolongo, F.; Ratto, M.; Tarantola, S.",
        title="Variance based sensitivity analysis of model output. Design and estimator for the total sensitivity "
              "index", kind="article", journal="Computer Physics Communications", volume="Vol. 181, no. 2",
        pages="P. 259–270", year="2010"),
    "mckay1979": Work(
        short="McKay, Beckman and Conover (1979)",
        authors="McKay, M. D.; Beckman, R. J.; Conover, W. J.",
        title="A comparison of three methods for selecting values of input variables in the analysis of output "
              "from a computer code", kind="article", journal="Technometrics", volume="Vol. 21, no. 2",
        pages="P. 239–245", year="1979"),
    "reinsch1967": Work(
        short="Reinsch (1967)",
        authors="Reinsch, C. H.",
        title="Smoothing by spline functions", kind="article", journal="Numerische Mathematik", volume="Vol. 10",
        pages="P. 177–183", year="1967"),
    "craven1979": Work(
        short="Craven and Wahba (1979)",
        authors="Craven, P.; Wahba, G.",
        title="Smoothing noisy data with spline functions: estimating the correct degree of smoothing by the method "
              "of generalized cross-validation", kind="article",
        journal="Numerische Mathematik", volume="Vol. 31", pages="P. 377–403", year="1979"),
    "sheppard1898": Work(
        short="Sheppard (1898)",
        authors="Sheppard, W. F.",
        title="On the calculation of the most probable values of frequency-constants, for data arranged according "
              "to equidistant division of a scale", kind="article",
        journal="Proceedings of the London Mathematical Society", volume="Vol. 29", pages="P. 353–380",
        year="1898",
        note="The variance q^2/12 that rounding to a grid of step q adds (Sheppard's correction)."),
    "hairer1993": Work(
        short="Hairer, Nørsett and Wanner (1993)",
        authors="Hairer, E.; Nørsett, S. P.; Wanner, G.",
        title="Solving Ordinary Differential Equations I: Nonstiff Problems", edition="2nd ed.", kind="book",
        publisher="Springer", place="Berlin", year="1993"),
    "press2007": Work(
        short="Press et al. (2007)",
        authors="Press, W. H.; Teukolsky, S. A.; Vetterling, W. T.; Flannery, B. P.",
        title="Numerical Recipes: The Art of Scientific Computing", edition="3rd ed.", kind="book",
        publisher="Cambridge University Press", place="Cambridge", year="2007",
        note="Section 5.6: the roots of a quadratic by the form that does not cancel."),
    "dowell1971": Work(
        short="Dowell and Jarratt (1971)",
        authors="Dowell, M.; Jarratt, P.",
        title="A modified regula falsi method for computing the root of an equation", kind="journal article",
        journal="BIT", volume="Vol. 11", pages="P. 168–174", year="1971"),
    "wylie1978": Work(
        short="Wylie and Streeter (1978)",
        authors="Wylie, E. B.; Streeter, V. L.",
        title="Fluid Transients", kind="book", publisher="McGraw-Hill", place="New York", year="1978",
        note="Wave speed in an elastic pipe (Korteweg), the Joukowsky pressure rise and the method of "
             "characteristics for one-dimensional transient pipe flow with friction."),
    "shigley2011": Work(
        short="Shigley's Mechanical Engineering Design, 9th ed. (2011)",
        authors="Budynas, R. G.; Nisbett, J. K.",
        title="Shigley's Mechanical Engineering Design", edition="9th ed.", kind="textbook", publisher="McGraw-Hill",
        place="New York", year="2011"),
    "en13906_1": Work(
        short="EN 13906-1",
        authors="CEN (European Committee for Standardization)",
        title="EN 13906-1:2013. Cylindrical helical springs made from round wire and bar — Calculation and design — "
              "Part 1: Compression springs",
        kind="standard", publisher="CEN", place="Brussels", year="2013"),
    "en10270_2": Work(
        short="EN 10270-2",
        authors="CEN (European Committee for Standardization)",
        title="EN 10270-2:2011. Steel wire for mechanical springs — Part 2: Oil hardened and tempered spring "
              "steel wire",
        kind="standard", publisher="CEN", place="Brussels", year="2011"),
    "hamrock2004": Work(
        short="Hamrock, Schmid and Jacobson (2004)",
        authors="Hamrock, B. J.; Schmid, S. R.; Jacobson, B. O.",
        title="Fundamentals of Fluid Film Lubrication", edition="2nd ed.", kind="book", publisher="Marcel Dekker",
        place="New York", year="2004",
        note="The film parameter and the lubrication regimes, the reduced modulus, the elastohydrodynamic film "
             "thickness of a line contact."),
    "dowson1977": Work(
        short="Dowson and Higginson (1977)",
        authors="Dowson, D.; Higginson, G. R.",
        title="Elasto-Hydrodynamic Lubrication", edition="SI ed.", kind="book", publisher="Pergamon Press",
        place="Oxford", year="1977", note="The minimum film thickness of a line contact."),
    "blok1937": Work(
        short="Blok (1937)",
        authors="Blok, H.",
        title="Theoretical study of temperature rise at surfaces of actual contact under oiliness lubricating "
              "conditions", kind="conference paper",
        journal="Proceedings of the General Discussion on Lubrication and Lubricants. Institution of Mechanical "
                "Engineers", volume="Vol. 2", pages="P. 222–235", place="London", year="1937",
        note="The flash temperature of a sliding line contact."),
    "merritt1967": Work(
        short="Merritt (1967)",
        authors="Merritt, H. E.",
        title="Hydraulic Control Systems", kind="book", publisher="John Wiley & Sons", place="New York", year="1967",
        note="The leakage of an annular clearance, the orifice equation, the effective bulk modulus of a liquid with "
             "entrained air."),
    "bernard2009": Work(
        short="Bernard et al. (2009)",
        authors="Bernard, L.; Ferrari, A.; Micelli, D.; Perotto, A.; Rinolfi, R.; Vattaneo, F.",
        title="Electro-hydraulic valve control with MultiAir technology", kind="journal article",
        journal="MTZ worldwide", volume="Vol. 70, no. 12", pages="P. 4–10", year="2009",
        note="The MultiAir lost-motion intake: a cam-driven pump piston, a normally open solenoid valve to an "
             "accumulator that closes the intake valve early or opens it late, and the hydraulic brake of its "
             "landing."),
    "dowson1986": Work(
        short="Dowson, Harrison and Taylor (1986)",
        authors="Dowson, D.; Harrison, P.; Taylor, C. M.",
        title="The lubrication of automotive cams and followers", kind="conference paper",
        journal="Mechanisms and Surface Distress: Proceedings of the 12th Leeds-Lyon Symposium on Tribology",
        pages="P. 305–322", place="London : Butterworths", year="1986",
        note="The kinematics and the film of a cam and flat follower."),
    "denhartog1956": Work(
        short="Den Hartog (1956)",
        authors="Den Hartog, J. P.",
        title="Mechanical Vibrations", edition="4th ed.", kind="book", publisher="McGraw-Hill", place="New York",
        year="1956", note="The natural frequencies of torsional systems of several masses on an elastic shaft."),
    "diamondchain": Work(
        short="Diamond Chain (n.d.)",
        authors="Diamond Chain Company",
        title="What is working load and what role does it play in selecting roller chain?",
        kind="web page",
        url="https://diamondchain.com/faq/what-is-working-load-and-what-role-does-it-play-in-selecting-roller-chain/",
        missing=("year",),
        note="The working load (chain pull) of a roller chain at most 1/6 of its tensile strength with press-fit "
             "connecting links, 1/9 with slip-fit or offset links."),
    "cottle1992": Work(
        short="Cottle, Pang and Stone (1992)",
        authors="Cottle, R. W.; Pang, J.-S.; Stone, R. E.",
        title="The Linear Complementarity Problem", kind="book", publisher="Academic Press", place="Boston",
        year="1992"),
    "white2006": Work(
        short="White (2006)",
        authors="White, F. M.",
        title="Viscous Fluid Flow", edition="3rd ed.", kind="textbook", publisher="McGraw-Hill", place="New York",
        year="2006",
        note="The laminar flow through an eccentric annulus (the exact solution in bipolar coordinates of Piercy, "
             "Hooper and Winny, 1933); Sutherland's law of the viscosity of air."),
    "enginebuilder2011": Work(
        short="Engine Builder (2011)",
        authors="Engine Builder Magazine",
        title="Getting to the bottom of hydraulic lifter preload", kind="article",
        journal="Engine Builder Magazine", volume="June 2011", year="2011",
        url="https://www.enginebuildermag.com/2011/06/getting-to-the-bottom-of-hydraulic-lifter-preload/",
        note="The lifter preload, the distance the plunger is pushed down from its retaining lock (its stop), is "
             "0.020 to 0.060 in (0.5 to 1.5 mm) for most applications; more pumps the lifter up and holds the valves "
             "open."),
    "sae_j300": Work(
        short="SAE J300 (2015)",
        authors="SAE International",
        title="J300: Engine Oil Viscosity Classification", kind="standard", publisher="SAE International",
        place="Warrendale, PA", year="2015",
        note="The viscosity grades of engine oils: SAE 30 (and xW-30) has a kinematic viscosity at 100 degC from 9.3 "
             "to below 12.5 mm^2/s."),
    "chrysler2002": Work(
        short="DaimlerChrysler (2002)",
        authors="DaimlerChrysler Corporation",
        title="Dodge Ram 3500 truck, 5.9 L V8: timing chain, service and repair (inspection: measuring timing chain "
              "stretch)", kind="service manual",
        year="2002",
        url="https://charm.li/Dodge%20and%20Ram/2002/RAM%203500%20Truck%204WD%20V8-5.9L%20VIN%205%20HDC/"
            "Repair%20and%20Diagnosis/Engine%2C%20Cooling%20and%20Exhaust/Engine/Timing%20Components/"
            "Timing%20Chain/Service%20and%20Repair",
        note="With a torque of 41 N m applied to the camshaft sprocket bolt one way and then the other, the crankshaft "
             "held, a new timing chain is installed if its movement exceeds 3.175 mm (1/8 in)."),
    "woschni1967": Work(
        short="Woschni (1967)",
        authors="Woschni, G.",
        title="A universally applicable equation for the instantaneous heat transfer coefficient in the internal "
              "combustion engine", kind="journal article", journal="SAE Transactions (SAE Technical Paper 670931)",
        volume="Vol. 76", place="New York", year="1967",
        note="The heat-transfer coefficient of the cylinder's gas and its characteristic velocity (constants C1, C2)."),
    "mcbride2002": Work(
        short="McBride, Zehe and Gordon (2002)",
        authors="McBride, B. J.; Zehe, M. J.; Gordon, S.",
        title="NASA Glenn coefficients for calculating thermodynamic properties of individual species",
        kind="technical report NASA/TP-2002-211556", publisher="NASA Glenn Research Center", place="Cleveland, OH",
        year="2002", note="The polynomials of specific heat and enthalpy of the gases, as Cantera's nasa_gas.yaml ships "
        "them."),
    "cantera2025": Work(
        short="Goodwin et al. (2025)",
        authors="Goodwin, D. G.; Moffat, H. K.; Schoegl, I.; Speth, R. L.; Weber, B. W.",
        title="Cantera: an object-oriented software toolkit for chemical kinetics, thermodynamics, and transport "
              "processes", kind="software, version 3.2", publisher="The Cantera Developers", year="2025",
        url="https://cantera.org", note="Its species data (the NASA Glenn polynomials) are read through its species "
        "interface."),
    "mpmath2023": Work(
        short="mpmath development team (2023)",
        authors="The mpmath development team",
        title="mpmath: a Python library for arbitrary-precision floating-point arithmetic", kind="software, version 1.3",
        publisher="The mpmath development team", year="2023", url="https://mpmath.org",
        note="Its LU solver in 50-digit arithmetic solves the polydyne cam's junction conditions."),
    "toro2009": Work(
        short="Toro (2009)",
        authors="Toro, E. F.",
        title="Riemann Solvers and Numerical Methods for Fluid Dynamics: A Practical Introduction", edition="3rd ed.",
        kind="book", publisher="Springer", place="Berlin", year="2009",
        note="The exact Riemann solver, the HLLC flux and the limited (MUSCL) reconstruction of the runners."),
    "davis1988": Work(
        short="Davis (1988)",
        authors="Davis, S. F.",
        title="Simplified second-order Godunov-type methods", kind="journal article",
        journal="SIAM Journal on Scientific and Statistical Computing", volume="Vol. 9, no. 3", pages="P. 445–473",
        year="1988", note="The wave-speed estimates of the HLL-type fluxes."),
    "gottlieb1998": Work(
        short="Gottlieb and Shu (1998)",
        authors="Gottlieb, S.; Shu, C.-W.",
        title="Total variation diminishing Runge-Kutta schemes", kind="journal article",
        journal="Mathematics of Computation", volume="Vol. 67, no. 221", pages="P. 73–85", year="1998"),
    "blasius1913": Work(
        short="Blasius (1913)",
        authors="Blasius, H.",
        title="Das Ähnlichkeitsgesetz bei Reibungsvorgängen in Flüssigkeiten",
        translation="The law of similarity of friction in fluids", kind="report",
        journal="Mitteilungen über Forschungsarbeiten auf dem Gebiete des Ingenieurwesens", volume="No. 131",
        publisher="VDI", place="Berlin", year="1913", language="German",
        note="The friction coefficient of turbulent flow in smooth pipes, 0.0791 Re^-0.25 (Fanning)."),
    "benson1982": Work(
        short="Benson (1982)",
        authors="Benson, R. S.",
        title="The Thermodynamics and Gas Dynamics of Internal-Combustion Engines. Vol. 1 / ed. by J. H. Horlock and "
              "D. E. Winterbone", kind="book", publisher="Clarendon Press", place="Oxford", year="1982",
        note="The boundaries of a pipe at a plenum and at a valve, matched with the waves arriving from the pipe."),
    "brent1973": Work(
        short="Brent (1973)",
        authors="Brent, R. P.",
        title="Algorithms for Minimization without Derivatives", kind="book", publisher="Prentice-Hall",
        place="Englewood Cliffs, NJ", year="1973", note="Chapter 4: finding a zero of a function with guaranteed "
        "convergence."),
    "kinsler2000": Work(
        short="Kinsler et al. (2000)",
        authors="Kinsler, L. E.; Frey, A. R.; Coppens, A. B.; Sanders, J. V.",
        title="Fundamentals of Acoustics", edition="4th ed.", kind="book", publisher="John Wiley & Sons",
        place="New York", year="2000", note="The resonances of a pipe closed at one end."),
    "tcc3": Work(
        short="TCC-III Motored Full View (n.d.)",
        authors="University of Michigan, Internal Combustion Engine Laboratory, with General Motors",
        title="TCC-III engine, motored full view: geometry, valve lift, flow coefficients and operating conditions",
        kind="data set", publisher="University of Michigan Deep Blue", doi="10.7302/Z2MS3QP",
        url="https://doi.org/10.7302/Z2MS3QP", missing=("year",),
        note="The inputs of the UM/GM Transparent Combustion Chamber III engine motored at 800 and 1300 rpm."),
}
"""Every cited work by its key."""


def entry(key) -> str:
    """The full reference of ``key`` (see :data:`WORKS`)."""
    return WORKS[key].reference()


def cite(key, where="") -> str:
    """A short in-text citation: ``cite("shang1988", "eq. (2.6)")`` -> ``"Shang Hanji (1988), eq. (2.6)"``."""
    short = WORKS[key].short
    return f"{short}, {where}" if where else short


def cited_in(text) -> list[str]:
    """Keys of the works whose in-text form occurs in ``text``, in the order of :data:`WORKS`."""
    return [key for key, work in WORKS.items() if work.short in text]


def corrections_text(lang="en") -> str:
    """The corrections notes shipped with the package (Markdown): each misprint of a source and what is used, in
    English (``data/corrections.md``) or Russian (``data/corrections.ru.md``, the same items by the same numbers)."""
    name = "data/corrections.md" if lang == "en" else f"data/corrections.{lang}.md"
    return resources.files("valvetrain").joinpath(name).read_text(encoding="utf-8")


def corrections_notes(lang="en") -> dict[int, tuple[str, str]]:
    """The numbered items of :func:`corrections_text` in ``lang``: ``{N: (title, text)}``, the Markdown's line breaks
    and emphasis removed (the title is the item's bold opening), a key in backquotes written in words."""
    notes = {}
    for m in re.finditer(r"^(\d+)\. (.*?)(?=^\d+\. |^#|^\S|\Z)", corrections_text(lang), flags=re.M | re.S):
        text = " ".join(m.group(2).split())
        bold = re.match(r"(.*?)\*\*(.+?)\*\*\s*(.*)", text)
        title, rest = (bold.group(1) + bold.group(2), bold.group(3)) if bold else ("", text)
        rest = re.sub(r"`([^`]*)`", lambda code: code.group(1).replace("_", " "), rest)   # a key, in words
        notes[int(m.group(1))] = (title.strip(), re.sub(r"\*\*(.+?)\*\*", r"\1", rest))
    return notes
