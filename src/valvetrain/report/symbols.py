"""The symbols of the report and their meanings in English and Russian, and the legend that explains each where it
is first used."""

from collections.abc import Callable

from markupsafe import Markup

from .i18n import TEXT

SYMBOLS = {
    "D": ("D", "bore, mm", "диаметр цилиндра, мм"), "S": ("S", "piston stroke, mm", "ход поршня, мм"),
    "ic": ("i<sub>c</sub>", "number of cylinders", "число цилиндров"),
    "Vh": ("V<sub>h</sub>", "swept volume of one cylinder, cm³", "рабочий объём цилиндра, см³"),
    "n": ("n", "crank speed, rpm", "частота вращения коленчатого вала, мин⁻¹"),
    "cp": ("c<sub>p</sub>", "mean piston speed, m/s", "средняя скорость поршня, м/с"),
    "spring_text": ("D", "mean coil diameter of the spring, mm", "средний диаметр пружины, мм"),
    "Fp": ("F<sub>p</sub>", "piston area, mm²", "площадь поршня, мм²"),
    "i": ("i", "number of valves of the kind per cylinder", "число одноимённых клапанов в цилиндре"),
    "dg": ("d<sub>g</sub>", "throat diameter, mm", "диаметр горловины, мм"),
    "phi_seat": ("φ", "seat angle, deg", "угол фаски клапана, град"),
    "hv": ("h<sub>v</sub>", "valve lift, mm", "подъём клапана, мм"),
    "h0": ("h<sub>0</sub>", "valve clearance (the ramp height on the tappet side), mm",
           "тепловой зазор (высота участка сбега на толкателе), мм"),
    "ik": ("i<sub>k</sub>", "rocker ratio (valve side / tappet side)", "передаточное отношение коромысла (клапан / толкатель)"),
    "r0": ("r<sub>0</sub>", "base radius of the cam, mm", "радиус начальной окружности кулачка, мм"),
    "w1": ("w′", "tappet velocity at the ramp end, mm/deg", "скорость толкателя в конце участка сбега, мм/град"),
    "Phi123": ("Φ<sub>1</sub>, Φ<sub>2</sub>, Φ<sub>3</sub>",
               "cam angles of the positive acceleration, of its fall and of the negative acceleration, cam deg",
               "углы участков положительного ускорения, его спада и отрицательного ускорения, град ПРВ"),
    "Kz": ("K<sub>z</sub>", "spring reserve: spring force / inertia force", "коэффициент запаса пружины: сила пружины / сила инерции"),
    "V1": ("V′", "conditional gas velocity in the throat, m/s", "условная скорость газа в горловине, м/с"),
    "V2": ("V″", "conditional gas velocity in the curtain at full lift, m/s",
           "условная скорость газа в проходном сечении при полном подъёме, м/с"),
    "V3": ("V‴", "conditional gas velocity by the time-area, m/s", "условная скорость газа по время-сечению, м/с"),
    "fg": ("f<sub>g</sub>", "throat area, mm²", "площадь горловины, мм²"),
    "fmax": ("f<sub>max</sub>", "curtain area at full lift, mm²", "проходное сечение при полном подъёме, мм²"),
    "f": ("f", "curtain area of the valve, mm²", "проходное сечение клапана, мм²"),
    "hT": ("h<sub>T</sub>", "tappet lift, mm", "подъём толкателя, мм"),
    "vT": ("v<sub>T</sub>", "tappet velocity, m/s", "скорость толкателя, м/с"),
    "aT": ("a<sub>T</sub>", "tappet acceleration, m/s²", "ускорение толкателя, м/с²"),
    "jT": ("j<sub>T</sub>", "tappet jerk, m/s³", "рывок толкателя, м/с³"),
    "av": ("a<sub>v</sub>", "valve acceleration i<sub>k</sub>a<sub>T</sub>, m/s²", "ускорение клапана i<sub>k</sub>a<sub>T</sub>, м/с²"),
    "phi_p0": ("φ<sub>p0</sub>", "half-angle of the main part of the cam, cam deg", "полуугол основного участка кулачка, град ПРВ"),
    "Phi0": ("Φ<sub>0</sub>", "ramp angle, cam deg", "угол участка сбега, град ПРВ"),
    "omega_cam": ("ω<sub>cam</sub>", "camshaft angular speed, rad/s", "угловая скорость распределительного вала, рад/с"),
    "c_ij": ("c<sub>11</sub>...c<sub>33</sub>", "coefficients of the Kurz cam segments (2.23)-(2.31), mm",
             "коэффициенты участков кулачка Курца (2.23)-(2.31), мм"),
    "k_i": ("k<sub>1</sub>, k<sub>2</sub>, k<sub>3</sub>", "auxiliary coefficients of the Kurz cam (2.32)-(2.34)",
            "вспомогательные коэффициенты кулачка Курца (2.32)-(2.34)"),
    "K12": ("K<sub>1</sub>, K<sub>2</sub>", "ratios of the acceleration extremes of the Kurz cam",
            "отношения экстремальных ускорений кулачка Курца"),
    "h_max": ("h<sub>max</sub>", "max tappet lift of the polydyne cam, mm", "наибольший подъём толкателя полидинамического кулачка, мм"),
    "C_poly": ("C<sub>2</sub>, C<sub>p</sub>, C<sub>q</sub>, C<sub>r</sub>, C<sub>s</sub>",
               "coefficients of the polydyne polynomial (3.1)", "коэффициенты полинома полидинамического кулачка (3.1)"),
    "pqrs": ("p, q, r, s", "exponents of the polydyne polynomial", "показатели степени полинома полидинамического кулачка"),
    "coefficients": ("", "coefficients of the lift law", "коэффициенты закона подъёма"),
    "dt": ("∫f dt", "time-area, mm²·s", "время-сечение, мм²·с"),
    "phi": ("φ", "camshaft angle from the cam nose, cam deg", "угол поворота распределительного вала от вершины кулачка, град ПРВ"),
    "vvp": ("v<sub>vp</sub>", "mean charge velocity, m/s", "средняя скорость заряда, м/с"),
    "xi": ("ξ", "fullness coefficient of the lift diagram", "коэффициент полноты диаграммы подъёма"),
    "Phi_open": ("Φ", "cam angle of the valve's stroke, cam deg", "угол такта клапана, град ПРВ"),
    "rho": ("ρ", "radius of curvature of the cam profile, mm", "радиус кривизны профиля кулачка, мм"),
    "hpp": ("h″", "second derivative of the tappet lift by the cam angle, mm/rad²",
            "вторая производная подъёма толкателя по углу кулачка, мм/рад²"),
    "b": ("b", "offset of the contact point on the flat tappet, mm", "смещение точки контакта на плоском толкателе, мм"),
    "E": ("E", "Young's modulus, MPa", "модуль упругости, МПа"),
    "gap": ("Δ", "valve-piston clearance, mm", "зазор между клапаном и поршнем, мм"),
    "s0": ("s<sub>0</sub>", "valve-piston gap at TDC with the valve closed, mm", "зазор клапан-поршень в ВМТ при закрытом клапане, мм"),
    "hv0": ("h<sub>v0</sub>", "piston travel from TDC, mm", "перемещение поршня от ВМТ, мм"),
    "Pin": ("P<sub>in</sub>", "inertia force of the valve, N", "сила инерции клапана, Н"),
    "mv": ("m<sub>v</sub>", "mass reduced to the valve, kg", "масса, приведённая к клапану, кг"),
    "Pspr": ("P<sub>spr</sub>", "required spring force, N", "необходимая сила пружины, Н"),
    "Pgas": ("P<sub>gas</sub>", "gas force on the valve head, N", "сила давления газов на тарелку клапана, Н"),
    "fmin": ("f<sub>min</sub>", "preload deflection of the spring, mm", "предварительная деформация пружины, мм"),
    "fmax_spring": ("f<sub>max</sub>", "deflection of the spring at full lift, mm", "деформация пружины при полном подъёме, мм"),
    "tau": ("τ", "shear stress of the spring wire, MPa", "касательное напряжение в проволоке пружины, МПа"),
    "chi": ("χ", "stress factor of the coil curvature", "коэффициент, учитывающий кривизну витка"),
    "P": ("P", "spring force, N", "сила пружины, Н"),
    "D_spring": ("D", "mean coil diameter, mm", "средний диаметр пружины, мм"),
    "d_wire": ("d", "wire diameter, mm", "диаметр проволоки, мм"),
    "iw": ("i<sub>w</sub>", "number of working coils", "число рабочих витков"),
    "n_safety": ("n", "fatigue safety factor of the spring", "запас прочности пружины"),
    "omega_c1": ("ω<sub>c1</sub>", "first natural angular frequency of the spring, rad/s", "первая собственная угловая частота пружины, рад/с"),
    "PT": ("P<sub>T</sub>", "load on the cam, N", "нагрузка на кулачок, Н"),
    "mT": ("m<sub>T</sub>", "mass reduced to the tappet, kg", "масса, приведённая к толкателю, кг"),
    "R": ("R", "crank radius, mm", "радиус кривошипа, мм"), "L": ("L", "connecting-rod length, mm", "длина шатуна, мм"),
    "lambda": ("λ", "R/L", "R/L"), "beta": ("β", "connecting-rod angle, deg", "угол отклонения шатуна, град"),
    "pg": ("Δp<sub>g</sub>", "gauge gas pressure on the piston, MPa", "избыточное давление газов на поршень, МПа"),
    "pin": ("p<sub>in</sub>", "specific inertia force of the reciprocating masses, MPa",
            "удельная сила инерции поступательно движущихся масс, МПа"),
    "p_total": ("p", "total specific force on the piston pin axis, MPa", "суммарная удельная сила на оси поршневого пальца, МПа"),
    "pN": ("p<sub>N</sub>", "specific side force normal to the cylinder wall, MPa", "удельная нормальная сила на стенку цилиндра, МПа"),
    "pS": ("p<sub>S</sub>", "specific force along the connecting rod, MPa", "удельная сила, действующая вдоль шатуна, МПа"),
    "pK": ("p<sub>K</sub>", "specific radial force on the crank, MPa", "удельная радиальная сила на кривошипе, МПа"),
    "pT": ("p<sub>T</sub>", "specific tangential force on the crank, MPa", "удельная тангенциальная сила на кривошипе, МПа"),
    "T": ("T", "tangential force, kN", "тангенциальная сила, кН"), "M": ("M", "torque, N·m", "крутящий момент, Н·м"),
    "Wi": ("W<sub>i</sub>", "indicated work of the cycle, J", "индикаторная работа цикла, Дж"),
    "tau_strokes": ("τ", "strokes of the cycle", "тактность двигателя"),
    "mj": ("m<sub>j</sub>", "reciprocating mass, kg", "масса поступательно движущихся частей, кг"),
    "mr": ("m<sub>r</sub>", "rotating mass, kg", "масса вращающихся частей, кг"),
    "Kr": ("K<sub>r</sub>", "centrifugal force of the rotating masses, N", "центробежная сила вращающихся масс, Н"),
    "pi": ("p<sub>i</sub>", "mean indicated pressure, MPa", "среднее индикаторное давление, МПа"),
    "K1K2": ("K<sub>1</sub>, K<sub>2</sub>", "factors of the port time-area (8.6)-(8.7)", "коэффициенты время-сечения окна (8.6)-(8.7)"),
    "Z": ("Z", "time-area of a port, mm²·s", "время-сечение окна, мм²·с"),
}
"""Every symbol of the report: ``key: (HTML, English, Russian)`` -- explained where it is first used."""


def symbol_legend(lang) -> Callable[..., str]:
    """A Jinja function ``legend(*symbols)``: the symbols not yet explained in this report, each with its meaning
    and unit (every symbol is explained where it is first used)."""
    seen = set()

    def legend(*keys):
        new = [k for k in keys if k not in seen]
        seen.update(new)
        if not new:
            return ""
        items = Markup("; ").join(Markup("{} — {}").format(Markup(SYMBOLS[k][0]), Markup(SYMBOLS[k][1 if lang == "en" else 2]))
                                  for k in new)
        return Markup('<p class="legend">{}: {}.</p>').format(TEXT[lang]["where"], items)
    return legend


INPUT_SYMBOLS = ("i", "dg", "phi_seat", "hv", "h0", "ik", "r0", "w1", "Phi123", "Kz")
"""Symbols of the valve's input table."""

WARNING_SYMBOLS = {
    "V1": ("flow.throat_velocity",), "V2": ("flow.curtain_velocity",), "V3": ("flow.time_area_velocity",),
    "vvp": ("flow.charge_velocity",), "aT": ("tappet_acceleration.max", "tappet_acceleration.min"),
    "dg": ("flow.throat_to_bore", "flow.equivalent_throat_to_bore", "flow.lift_to_throat"),
    "hv": ("flow.lift_to_throat", "cam.base_radius_to_lift", "hydraulic.max_lift", "hydraulic.residual_lift"),
    "h0": ("valve.clearance",), "ik": ("drive.rocker_ratio",), "r0": ("cam.base_radius_to_lift",),
    "rho": ("profile.undercut_flat", "profile.rho_min"), "Kz": ("spring.reserve",),
    "Phi123": ("law.kurz.phi2_to_phi3", "law.kurz.negative_to_positive"), "w1": ("ramp.end_velocity",),
    "lambda": ("engine.rod_ratio", "crank.rod_ratio"),
}
"""Symbols of the legend that the checks of these codes use."""
