"""Names a designer reads for the keys, units, values and texts of a design, in English and Russian.

The records of a design (``results.json``, the specification, the CSV headers) keep their machine keys
(``tappet_acceleration_m_s2``); the report shows :func:`label` of a key (``"tappet acceleration a_T, m/s²"``,
``"ускорение толкателя a_T, м/с²"``).  A key is looked up with the path of the table it belongs to
(``spring.count`` before ``count``); the unit comes from the key's suffix (``_mm``, ``_m_s2``, ``_MPa``...) and its
symbol from the one unit table :data:`valvetrain.units.UNITS`.  The names of the checks are not here: they are
renderings of their codes from the catalogue :mod:`valvetrain.locale`.

Texts made with numbers (the notes of the checks, the cylinder-pressure model) are translated by their
skeleton: the numbers are taken out, the Russian skeleton is looked up in the catalogue (``ru.toml`` ``[texts]``
of :mod:`valvetrain.locale`) and the numbers put back (:func:`translate`).  A key, a value or a text without a Russian entry is shown as it is (in English):
``tests/report/test_i18n.py`` finds them.

Symbols: one symbol for one quantity throughout the report and the plots: ``h`` lift, ``v`` velocity,
``a`` acceleration, ``j`` jerk (index ``T`` tappet side, ``v`` valve side).
"""

import re

from ..locale import LANGS, catalogue, check_text, record_text, spring_text
from ..units import SUFFIXES, symbol as unit_text
from .stage_names import STAGE_NAMES

NAMES = {
    # engine
    "name": ("name", "наименование"), "bore": ("bore D", "диаметр цилиндра D"),
    "stroke": ("piston stroke S", "ход поршня S"), "rated_speed": ("rated speed n", "номинальная частота вращения n"),
    "idle_speed": ("idle speed (lowest speed of the strength checks)",
                   "частота холостого хода (наименьшая в расчёте на прочность)"),
    "cylinders": ("number of cylinders", "число цилиндров"), "strokes": ("strokes of the cycle", "тактность"),
    "over_speed_ratio": ("over-speed / rated speed", "отношение максимальной частоты вращения к номинальной"),
    "engine_class": ("engine class (of the recommended bands)", "класс двигателя (для рекомендуемых пределов)"),
    "type": ("engine type", "тип двигателя"), "chamber": ("combustion chamber", "камера сгорания"),
    "layout": ("layout", "компоновка"), "bank_angle": ("bank angle", "угол развала"),
    "firing_order": ("firing order", "порядок работы цилиндров"),
    "mean_piston_speed": ("mean piston speed c_p", "средняя скорость поршня c_p"),
    "swept_volume": ("swept volume of one cylinder V_h", "рабочий объём цилиндра V_h"),
    "displacement": ("displacement i_c V_h", "литраж i_c V_h"), "piston_area": ("piston area F_p", "площадь поршня F_p"),
    "banks": ("bank of each cylinder", "ряд каждого цилиндра"),
    "crank_throws": ("crank throw angles", "углы колен вала"),
    "output.table_step_cam": ("step of the lift table", "шаг таблицы подъёма"),
    "output.contour_points": ("points of the contour", "число точек профиля"),
    "output.export_step": ("step of the exported tables", "шаг таблиц для изготовления"),
    # valve
    "kind": ("valve kind", "вид клапана"), "count": ("number of valves of this kind i", "число клапанов i"),
    "throat_diameter": ("throat diameter d_g", "диаметр горловины d_г"),
    "seat_angle": ("seat angle φ", "угол фаски φ"), "max_lift": ("valve lift h_v max", "подъём клапана h_v max"),
    "clearance": ("valve clearance h0", "тепловой зазор h0"),
    "opens": ("opening advance (before TDC)", "угол опережения открытия (до ВМТ)"),
    "closes": ("closing lag (after BDC)", "угол запаздывания закрытия (после НМТ)"),
    "rocker_ratio": ("rocker ratio i_k", "передаточное отношение коромысла i_k"),
    "ramp_type": ("ramp type", "вид участка сбега"),
    "ramp_acceleration_fraction": ("share of the ramp with acceleration", "доля участка сбега с ускорением"),
    "base_radius": ("base radius r0", "радиус начальной окружности r0"),
    "follower": ("follower", "толкатель"), "law": ("lift law", "закон подъёма"),
    "ramp_end_velocity": ("velocity at the ramp end w′", "скорость в конце участка сбега w′"),
    "phi1": ("angle Φ1 (positive acceleration)", "угол Φ1 (положительное ускорение)"),
    "phi2": ("angle Φ2", "угол Φ2"), "phi3": ("angle Φ3 (negative acceleration)", "угол Φ3 (отрицательное ускорение)"),
    "shape_factor": ("shape factor", "коэффициент формы"),
    "reconstruction": ("reconstruction of the formulas", "реконструкция формул"),
    "ramp_angle": ("ramp angle φ0", "протяжённость участка выборки зазора φ0"),
    "ramp_end_velocity_mm_per_rad": ("velocity analogue at the ramp end v_qb", "аналог скорости в конце участка сбега v_q,b"),
    "peak_acceleration": ("peak acceleration analogue a_qd", "наибольший аналог ускорения a_q,d"),
    "peak_position": ("position of the positive peak x_d", "положение максимума положительного участка x_d"),
    "trough_position": ("position of the negative peak x_g", "положение максимума отрицательного участка x_g"),
    "sharpness": ("sharpness χ of the bumps", "острота χ участков"),
    "power_polynomial": ("power-polynomial cam", "степенно-полиномиальный кулачок"),
    "dwell": ("top dwell φ_вв", "верхний выстой φ_вв"),
    "S_e": ("lift S_e at the end of the positive part", "перемещение S_e в конце участка положительных ускорений"),
    "v_e": ("velocity analogue v_e at the end of the positive part",
            "аналог скорости v_e в конце участка положительных ускорений"),
    "v_e_mm_per_rad": ("velocity analogue v_e at the end of the positive part, mm/rad",
                       "аналог скорости v_e в конце участка положительных ускорений, мм/рад"),
    "tappet_fullness": ("fullness η_П of the tappet lift", "коэффициент полноты η_П диаграммы перемещений толкателя"),
    "S_h": ("dwell lift S_h", "перемещение на выстое S_h"),
    "a_qd": ("peak acceleration analogue a_qd", "наибольший аналог ускорения a_q,d"),
    "a_g": ("negative peak acceleration analogue a_g", "наименьший аналог ускорения a_g"),
    "phi0": ("ramp angle φ0", "протяжённость участка выборки зазора φ0"),
    "A0": ("A0", "A0"), "B0": ("B0", "B0"), "C0": ("C0", "C0"),
    "x_d": ("x_d", "x_d"), "x_g": ("x_g", "x_g"), "chi": ("χ", "χ"),
    "roller_radius": ("roller radius", "радиус ролика"),
    "drive.layout": ("drive layout", "схема привода"),
    "spring_reserve": ("spring reserve K_z", "коэффициент запаса пружины K_з"),
    "valve_arm": ("rocker arm on the valve side", "плечо коромысла со стороны клапана"),
    "masses.valve": ("valve mass", "масса клапана"), "masses.retainer": ("retainer mass", "масса тарелки пружины"),
    "masses.cotters": ("cotters mass", "масса сухарей"), "masses.pushrod": ("pushrod mass", "масса штанги"),
    "masses.tappet": ("tappet mass", "масса толкателя"), "masses.spring": ("spring mass", "масса пружины"),
    "drive.stiffness": ("drive stiffness c, cam to valve (given)", "жёсткость привода c от кулачка до клапана (задана)"),
    "drive.specific_mass": ("specific mass of the drive m′ (given)", "удельная масса привода m′ (задана)"),
    "spring.shear_modulus": ("shear modulus of the wire G", "модуль сдвига проволоки G"),
    "spring.density": ("density of the wire", "плотность проволоки"),
    "spring.allowable_stress": ("allowable stress of the wire", "допускаемое напряжение проволоки"),
    "spring.endurance_limit": ("endurance limit of the wire", "предел выносливости проволоки"),
    "spring.mean_stress_factor": ("mean stress factor", "коэффициент влияния среднего напряжения"),
    "cam.nose_radius": ("nose radius", "радиус вершины кулачка"),
    "cam.flank_radius": ("flank radius", "радиус боковой дуги кулачка"),
    "cam.flank_angle": ("flank angle", "угол боковой дуги кулачка"),
    "cam.kappa": ("ratio κ of the last negative acceleration to A2", "отношение κ последнего отрицательного ускорения к A2"),
    "cam.junction_order": ("order of the junctions", "порядок сопряжения участков"),
    "cam.design_speed": ("design speed of the cam", "расчётная частота вращения кулачка"),
    "cam.drive_stiffness": ("drive stiffness of the cam's design train", "жёсткость привода расчётной модели кулачка"),
    "cam.spring_rate": ("spring rate of the cam's design train", "жёсткость пружины расчётной модели кулачка"),
    "cam.spring_preload": ("spring preload of the cam's design train",
                           "сила предварительной затяжки пружины расчётной модели кулачка"),
    "segments.length": ("length of the segment", "протяжённость участка"),
    "cam.p": ("exponent p", "показатель степени p"), "cam.q": ("exponent q", "показатель степени q"),
    "cam.r": ("exponent r", "показатель степени r"), "cam.s": ("exponent s", "показатель степени s"),
    "cam.m": ("exponent m", "показатель степени m"), "cam.n": ("exponent n", "показатель степени n"),
    "cam.t": ("exponent t", "показатель степени t"), "cam.u": ("exponent u", "показатель степени u"),
    "cam.exponents": ("exponents", "показатели степени"),
    "cam.segments": ("segments (shape, length)", "участки (форма, протяжённость)"),
    "cam.ratios": ("ratios of the accelerations at the segments' ends", "отношения ускорений в концах участков"),
    "cam.table_angles": ("angles of the table's points", "углы точек таблицы"),
    "cam.table_lifts": ("lifts of the table's points", "подъёмы точек таблицы"),
    "masses.rocker_inertia": ("rocker moment of inertia", "момент инерции коромысла"),
    "spring.count": ("number of springs", "число пружин"), "inner_share": ("share of the inner spring", "доля внутренней пружины"),
    "material": ("spring steel", "материал пружины"), "min_safety_factor": ("minimum fatigue safety factor", "наименьший запас прочности"),
    "min_resonance_ratio": ("minimum resonance ratio", "наименьшее отношение частот"),
    "min_margin": ("design margin sought on fatigue and resonance", "запас проектирования по усталости и резонансу"),
    "design_margin": ("design margin achieved on fatigue and resonance",
                      "достигнутый запас проектирования по усталости и резонансу"),
    "coil_gap_factor": ("coil gap at full lift / wire diameter", "зазор между витками при полном подъёме / диаметр проволоки"),
    "mean_diameter_ratio": ("mean diameter / throat diameter", "средний диаметр / диаметр горловины"),
    "wire_diameter_range": ("wire diameters", "диаметры проволоки"), "wire_step": ("wire step", "шаг диаметра проволоки"),
    "deflection_ratio_range": ("ratios f_max/f_min", "отношения f_max/f_min"),
    "min_frequency_difference": ("minimum frequency difference of a pair", "наименьшая разница частот пары"),
    "radial_gap": ("radial gap between the springs", "радиальный зазор между пружинами"),
    "installed_length": ("installed length", "длина в установленном состоянии"),
    "spring.installed_length": ("installed length", "длина в установленном состоянии"),
    "max_free_length": ("max free length", "наибольшая длина в свободном состоянии"),
    "contact_modulus": ("contact modulus", "приведённый модуль упругости в контакте"),
    "head_diameter": ("valve head diameter", "диаметр тарелки клапана"),
    "stem_diameter": ("valve stem diameter", "диаметр стержня клапана"), "cam_width": ("cam width", "ширина кулачка"),
    "camshaft_diameter": ("camshaft diameter", "диаметр распределительного вала"),
    "camshaft_bore": ("camshaft bore", "диаметр отверстия распределительного вала"),
    "camshaft_span": ("camshaft span between bearings", "пролёт распределительного вала между опорами"),
    "cam_to_bearing": ("cam to bearing", "расстояние от кулачка до опоры"),
    "camshaft_modulus": ("camshaft Young's modulus", "модуль упругости распределительного вала"),
    "camshaft_deflection_coefficient": ("camshaft deflection coefficient", "коэффициент в формуле прогиба вала"),
    "tappet_diameter": ("tappet diameter", "диаметр толкателя"),
    "tappet_guide_length": ("tappet guide length", "длина направляющей толкателя"),
    "pushrod_length": ("pushrod length", "длина штанги"), "pushrod_diameter": ("pushrod diameter", "диаметр штанги"),
    "pushrod_bore": ("pushrod bore", "диаметр отверстия штанги"),
    "pushrod_modulus": ("pushrod Young's modulus", "модуль упругости штанги"),
    "ball_radius": ("ball radius of the pushrod", "радиус сферы наконечника штанги"),
    "socket_radius": ("socket radius", "радиус сферической опоры"),
    "pushrod_head_area": ("pushrod head bearing area", "площадь опоры наконечника штанги"),
    "rocker_pad_width": ("rocker pad width", "ширина бойка коромысла"),
    "rocker_pad_radius": ("rocker pad radius", "радиус бойка коромысла"),
    "rocker_shaft_span": ("rocker shaft span", "пролёт оси коромысла"),
    "rocker_shaft_diameter": ("rocker shaft diameter", "диаметр оси коромысла"),
    "rocker_shaft_bore": ("rocker shaft bore", "диаметр отверстия оси коромысла"),
    "rocker_width": ("rocker bearing width", "ширина втулки коромысла"),
    "rocker_pivot_ball_radius": ("pivot ball radius of a stud-mounted rocker", "радиус шаровой опоры коромысла"),
    "rocker_pivot_seat_radius": ("seat radius of the rocker on its pivot ball",
                                 "радиус сферического гнезда коромысла"),
    "table_file": ("lift table file", "файл таблицы подъёма"), "table_angle": ("angles of the table", "углы таблицы"),
    "table_lift_at": ("lift of the table at", "подъём в таблице на"), "table_zero": ("table angles from", "начало отсчёта углов таблицы"),
    "fit": ("fit", "аппроксимация"), "accuracy": ("accuracy of the fit", "точность аппроксимации"),
    "accuracy_from": ("accuracy of the fit from", "точность аппроксимации"),
    "max_harmonics": ("max number of harmonics", "наибольшее число гармоник"),
    "straight_flanks": ("straight flanks", "прямолинейные участки"),
    "points": ("points fitted", "число аппроксимируемых точек"), "rows_per_point": ("rows per point", "строк на точку"),
    "relative_height": ("relative height", "относительная высота"), "limit": ("limit", "предел"),
    # cam and flow
    "V1": ("V′ throat velocity", "V′ условная скорость в горловине"),
    "V2": ("V″ curtain velocity at full lift", "V″ условная скорость в проходном сечении при полном подъёме"),
    "V3": ("V‴ time-area velocity", "V‴ условная скорость по время-сечению"),
    "throat_area": ("throat area f_g", "площадь горловины f_г"),
    "valve_lift": ("valve lift h_v", "подъём клапана h_v"),
    "max_curtain_area": ("curtain area at full lift f_max", "проходное сечение при полном подъёме f_max"),
    "time_area": ("time-area over the valve's stroke ∫f dt", "время-сечение за такт ∫f dt"),
    "time_area_open": ("time-area over the whole opening", "время-сечение за всё открытие"),
    "time_area_analytic": ("time-area on the analytic law", "время-сечение по аналитическому закону"),
    "mean_charge_velocity": ("mean charge velocity v_vp", "средняя скорость заряда v_вп"),
    "fullness": ("fullness coefficient ξ", "коэффициент полноты ξ"),
    "stroke_crank": ("the valve's own stroke", "такт клапана"),
    "max_velocity": ("max tappet velocity v_T max", "наибольшая скорость толкателя v_T max"),
    "max_acceleration": ("max tappet acceleration a_T max", "наибольшее ускорение толкателя a_T max"),
    "min_acceleration": ("min tappet acceleration a_T min", "наименьшее ускорение толкателя a_T min"),
    "rho_min": ("min radius of curvature ρ_min", "наименьший радиус кривизны ρ_min"),
    "rho_max": ("max radius of curvature ρ_max", "наибольший радиус кривизны ρ_max"),
    "rho_min_cam": ("cam angle of ρ_min", "угол ПРВ при ρ_min"), "rho_max_cam": ("cam angle of ρ_max", "угол ПРВ при ρ_max"),
    "phi_p0": ("main half-angle φ_p0", "полуугол основного участка φ_р0"),
    "ramp": ("ramp angle Φ0", "угол участка сбега Φ0"), "ramp_height": ("ramp height h0", "высота участка сбега h0"),
    "tappet_lift": ("tappet lift h_T max", "подъём толкателя h_T max"),
    "event_cam": ("whole event with the ramps", "продолжительность с участками сбега"),
    "nose_crank": ("crank angle of the cam nose", "угол ПКВ вершины кулачка"),
    "camshaft_speed": ("camshaft angular speed ω_cam", "угловая скорость распределительного вала ω_р"),
    "heel_radius": ("heel radius r0 − h0", "радиус тыльной части r0 − h0"),
    "max_contact_offset": ("max contact offset on the flat follower b", "наибольшее смещение точки контакта на плоском толкателе b"),
    "max_pressure_angle": ("max pressure angle", "наибольший угол давления"),
    "min_concave_radius": ("concave radius closest to zero", "ближайший к нулю вогнутый радиус"),
    "undercut": ("profile undercut", "подрез профиля"),
    "finger_pivot_x": ("finger's pivot from the cam centre, x", "опора рычага от центра кулачка, x"),
    "finger_pivot_y": ("finger's pivot from the cam centre, y (towards the follower)",
                       "опора рычага от центра кулачка, y (к толкателю)"),
    "finger_roller_arm": ("pivot to roller centre", "плечо ролика от опоры"),
    "finger_pad_arm": ("pivot to the valve pad's centre, along the finger", "плечо площадки клапана от опоры вдоль рычага"),
    "finger_pad_drop": ("the valve pad's centre across the finger", "смещение центра площадки клапана поперёк рычага"),
    "finger_pad_radius": ("radius of the valve pad", "радиус площадки клапана"),
    "finger_valve_angle": ("valve axis from the follower's direction", "наклон оси клапана к направлению толкателя"),
    "finger_tip_offset": ("contact on the valve tip off its axis, valve shut",
                          "смещение контакта на торце клапана от оси при закрытом клапане"),
    "finger_roller_load_max": ("largest load on the finger's roller and its bearing",
                               "наибольшая нагрузка на ролик рычага и его подшипник"),
    "finger_pivot_load_max": ("largest load on the finger's pivot", "наибольшая нагрузка на опору рычага"),
    "finger_bending_moment_max": ("largest bending moment of the finger at its critical section",
                                  "наибольший изгибающий момент рычага в опасном сечении"),
    "finger_bending_stress_max": ("largest bending stress of the finger at its critical section",
                                  "наибольшее напряжение изгиба рычага в опасном сечении"),
    "finger_section_width": ("finger's width at its critical section (material only)",
                             "ширина рычага в опасном сечении (без выреза)"),
    "finger_section_height": ("finger's height at its critical section", "высота рычага в опасном сечении"),
    "ratio_at_rest": ("finger's lever ratio on the heel circle", "передаточное отношение рычага на тыльной окружности"),
    "ratio_min": ("smallest lever ratio over the lift", "наименьшее передаточное отношение рычага за подъём"),
    "ratio_max": ("largest lever ratio over the lift", "наибольшее передаточное отношение рычага за подъём"),
    "ratio_at_full_lift": ("lever ratio at the full lift", "передаточное отношение рычага при полном подъёме"),
    "swing": ("finger's turn to the full lift", "угол поворота рычага до полного подъёма"),
    "roller_lift": ("lift of the roller centre (synthesised cam)", "подъём центра ролика (синтезированный кулачок)"),
    "tip_contact": ("contact on the valve tip across its axis: shut, full lift",
                    "точка контакта на торце клапана от его оси: закрыт, полный подъём"),
    "tip_scrub": ("travel of the contact across the valve tip", "перемещение точки контакта по торцу клапана"),
    "tip_contact_max": ("largest distance of the contact from the valve axis",
                        "наибольшее смещение точки контакта от оси клапана"),
    "pressure_angle_at_rest": ("pressure angle on the heel circle", "угол давления на тыльной окружности"),
    "min_clearance": ("min valve-piston clearance", "наименьший зазор клапан-поршень"),
    "crank": ("at crank angle", "при угле ПКВ"), "piston_gap_tdc": ("valve-piston gap at TDC", "зазор клапан-поршень в ВМТ"),
    "valve_opens_crank": ("valve opens (from TDC)", "клапан открывается (от ВМТ)"),
    "valve_closes_crank": ("valve closes (from TDC)", "клапан закрывается (от ВМТ)"),
    "valve_opening_velocity": ("valve velocity at the start of the lift", "скорость клапана в начале подъёма"),
    "valve_seating_velocity": ("valve seating velocity", "скорость посадки клапана"),
    "h_max": ("max lift h_max", "наибольший подъём h_max"),
    # measured table
    "max_lift_table": ("max lift in the table", "наибольший подъём в таблице"),
    "measured.max_lift": ("max lift in the table", "наибольший подъём в таблице"),
    "lobe_centre": ("lobe centre after the asymmetry correction (from the gas-exchange TDC)",
                    "ось кулачка после исправления асимметрии (от ВМТ газообмена)"),
    "lobe_centre_cam": ("lobe centre after the asymmetry correction", "ось кулачка после исправления асимметрии"),
    "harmonics": ("harmonics of the N-harmonic fit", "число гармоник аппроксимации"),
    "asymmetry_rms": ("rms odd part (true asymmetry) after the correction", "СКО нечётной части (истинная асимметрия) после исправления"),
    "opens_deg_at_0.1mm": ("opens at 0.1 mm valve lift, crank deg", "открытие при подъёме клапана 0,1 мм, град ПКВ"),
    "closes_deg_at_0.1mm": ("closes at 0.1 mm valve lift, crank deg", "закрытие при подъёме клапана 0,1 мм, град ПКВ"),
    "source": ("source", "источник"), "rms_residual": ("rms residual", "СКО отклонения"),
    "max_residual": ("max residual", "наибольшее отклонение"),
    "jerk_sign_changes": ("sign changes of the jerk j", "перемены знака рывка j"),
    # masses
    "at_valve": ("reduced mass at the valve m_v", "приведённая к клапану масса m_кл"),
    "at_tappet": ("reduced mass at the tappet m_T", "приведённая к толкателю масса m_т"),
    "masses.source": ("source", "источник"), "masses.layout": ("drive layout", "схема привода"),
    # spring
    "preload": ("preload P_min", "сила предварительной затяжки P_min"),
    "max_force": ("force at full lift P_max", "сила при полном подъёме P_max"), "rate": ("spring rate c", "жёсткость пружины c"),
    "required_preload": ("required preload", "необходимая сила затяжки"),
    "required_rate": ("required rate", "необходимая жёсткость"),
    "required_max_force": ("required force at full lift", "необходимая сила при полном подъёме"),
    "required_deflection_ratio": ("f_max/f_min of the required line", "f_max/f_min необходимой характеристики"),
    "preload_set_by_gas_force": ("preload set by the gas force", "затяжка определена силой давления газов"),
    "gas_force": ("gas force on the valve head P_gas", "сила давления газов на клапан P_г"),
    "gas_force_source": ("gas force from", "источник силы давления газов"),
    "preload_set_by_seat_load": ("preload set by the seat load", "затяжка определена посадочным усилием"),
    "seat_load": ("seat load", "посадочное усилие"), "seat_load_source": ("seat load from", "источник посадочного усилия"),
    "deflection_ratio": ("ratio f_max/f_min", "отношение f_max/f_min"),
    "candidates_passing": ("candidates passing every check", "вариантов, прошедших все проверки"),
    "candidates_tried": ("candidates tried", "рассмотрено вариантов"),
    "wire": ("wire diameter d", "диаметр проволоки d"), "mean_diameter": ("mean coil diameter D", "средний диаметр пружины D"),
    "outer_diameter": ("outer diameter", "наружный диаметр"), "active_coils": ("working coils i_w", "число рабочих витков i_р"),
    "total_coils": ("total coils", "полное число витков"), "free_length": ("free length", "длина в свободном состоянии"),
    "min_length": ("length at full lift", "длина при полном подъёме"), "min_pitch": ("min pitch", "наименьший шаг витков"),
    "installed_pitch": ("pitch at the installed length", "шаг витков в установленном состоянии"),
    "free_pitch": ("pitch of the free spring", "шаг витков в свободном состоянии"),
    "preload_deflection": ("preload deflection f_min", "предварительная деформация f_min"),
    "max_deflection": ("max deflection f_max", "наибольшая деформация f_max"),
    "spring_index": ("spring index D/d", "индекс пружины D/d"), "wahl_factor": ("Wahl factor", "коэффициент Валя"),
    "tau_max": ("max shear stress τ_max", "наибольшее касательное напряжение τ_max"),
    "tau_min": ("min shear stress τ_min", "наименьшее касательное напряжение τ_min"),
    "safety_factor": ("fatigue safety factor n", "запас прочности n"),
    "natural_frequency": ("natural frequency of the spring", "собственная частота пружины"),
    "resonance_ratio": ("resonance ratio ω_c1/ω_cam", "отношение частот ω_c1/ω_р"),
    "mass": ("mass of the spring", "масса пружины"), "target_deflection_ratio": ("target f_max/f_min", "заданное f_max/f_min"),
    "guide_sleeve_needed": ("guide sleeve needed", "нужна направляющая втулка"),
    "passes_all_checks": ("passes every check", "проходит все проверки"),
    "binding_check": ("binding check", "определяющая проверка"),
    "working_coils": ("working coils", "число рабочих витков"), "fatigue_safety": ("fatigue safety factor", "запас прочности"),
    "coil_gap_at_full_lift": ("coil gap at full lift", "зазор между витками при полном подъёме"),
    "frequency_difference": ("frequency difference of the pair", "разница частот пары"),
    # strength
    "cam_force_max": ("max cam load P_T", "наибольшая нагрузка на кулачок P_T"),
    "roller_side_force_max": ("largest side force of the roller follower", "наибольшая боковая сила на роликовом толкателе"),
    "roller_side_force_cam": ("cam angle of the largest side force", "угол ПРВ наибольшей боковой силы"),
    "flat_follower_edge_loading": ("flat follower edge loading", "кромочный контакт плоского толкателя"),
    "tappet_face_diameter": ("tappet face diameter", "диаметр тарелки толкателя"),
    "fit_reason": ("fit used and why", "аппроксимация и почему она выбрана"),
    # the train of the dynamics chapter
    "dynamics.model": ("model", "расчётная модель"), "dynamics.layout": ("drive layout", "схема привода"),
    "dynamics.mass": ("reduced mass at the valve M", "приведённая к клапану масса M"),
    "dynamics.drive_stiffness": ("drive stiffness at the valve c", "жёсткость привода, приведённая к клапану, c"),
    "dynamics.damping_ratio": ("damping ratio of the drive ζ", "относительное демпфирование привода ζ"),
    "dynamics.spring_rate": ("spring rate K", "жёсткость пружины K"),
    "dynamics.spring_preload": ("spring preload F0", "предварительная затяжка пружины F0"),
    "dynamics.rocker_ratio": ("rocker ratio i_k", "передаточное отношение коромысла i_k"),
    "dynamics.lash": ("lash at the valve", "зазор на клапане"),
    "dynamics.seat_stiffness": ("seat stiffness", "жёсткость седла"),
    "dynamics.seat_damping_ratio": ("damping ratio of the seat", "относительное демпфирование седла"),
    "dynamics.revolutions": ("most camshaft revolutions per speed (it stops once its motion repeats)",
                             "наибольшее число оборотов распредвала на каждую частоту (до повторения движения)"),
    "dynamics.step": ("integration step", "шаг интегрирования"),
    "dynamics.coils_per_spring": ("coil masses per spring", "масс витков на пружину"),
    "dynamics.link_stiffnesses": ("stiffnesses of the links at the valve", "жёсткости звеньев, приведённые к клапану"),
    "dynamics.link_names": ("links of the drive", "звенья привода"),
    "dynamics.speeds": ("speeds of the sweep", "число частот вращения в расчёте"),
    "dynamics.allow_large_sweep": ("a sweep above the limits of work and memory allowed",
                                   "расчёт сверх пределов объёма вычислений и памяти разрешён"),
    "dynamics.spring_mass": ("mass of the active coils of the spring", "масса рабочих витков пружины"),
    "cam_force_max_cam": ("cam angle of the max cam load", "угол ПРВ наибольшей нагрузки на кулачок"),
    "strength.speed_range": ("engine speeds of the strength checks", "частоты вращения двигателя в расчёте на прочность"),
    "lowest_speed_source": ("where the lowest speed comes from", "откуда взята наименьшая частота вращения"),
    "cam_force_max_speed": ("engine speed of the max cam load", "частота вращения наибольшей нагрузки на кулачок"),
    "cam_contact_stress_speed": ("engine speed of the max contact stress",
                                 "частота вращения наибольшего контактного напряжения"),
    "roller_side_force_speed": ("engine speed of the largest side force", "частота вращения наибольшей боковой силы"),
    "valve_force_max": ("max force at the valve", "наибольшая сила на клапане"),
    "gas_force_at_opening": ("gas force at the valve's opening", "сила давления газов в момент открытия"),
    "cam_contact_stress_cam": ("cam angle of the max contact stress", "угол ПРВ наибольшего контактного напряжения"),
    "cam_contact_force": ("cam load at the max contact stress",
                          "нагрузка на кулачок при наибольшем контактном напряжении"),
    "camshaft_deflection": ("camshaft deflection", "стрела прогиба распределительного вала"),
    "cam_contact_stress": ("contact stress of the cam", "контактное напряжение кулачка"),
    "tappet_side_pressure": ("side pressure on the tappet", "удельное давление на боковую поверхность толкателя"),
    "pushrod_buckling_margin": ("buckling safety factor of the pushrod", "запас устойчивости штанги"),
    "ball_socket_stress": ("contact stress of the pushrod ball", "контактное напряжение наконечника штанги"),
    "pushrod_head_pressure": ("bearing pressure on the pushrod head", "напряжение смятия наконечника штанги"),
    "rocker_pad_stress": ("contact stress of the rocker pad", "контактное напряжение бойка коромысла"),
    "rocker_shaft": ("rocker shaft", "ось коромысла"),
    "rocker_pivot_stress": ("contact stress of the rocker's pivot ball",
                            "контактное напряжение шаровой опоры коромысла"),
    "rocker_shaft_bending": ("bending stress of the rocker shaft", "напряжение изгиба оси коромысла"),
    "finger_bending": ("bending stress of the finger at its critical section",
                       "напряжение изгиба рычага в опасном сечении"),
    "rocker_shaft_shear": ("shear stress of the rocker shaft", "касательное напряжение оси коромысла"),
    "rocker_shaft_bearing": ("bearing pressure of the rocker shaft", "напряжение смятия оси коромысла"),
    # crank
    "rod_length": ("connecting-rod length L", "длина шатуна L"), "offset": ("piston pin offset", "дезаксаж"),
    "kinematics": ("kinematics", "кинематика"), "pv_method": ("indicator diagram", "индикаторная диаграмма"),
    "compression_ratio": ("compression ratio ε", "степень сжатия ε"),
    "ambient_pressure": ("ambient pressure p_0", "давление окружающей среды p_0"),
    "step": ("step", "шаг"), "piston": ("piston mass", "масса поршня"), "rod": ("connecting-rod mass", "масса шатуна"),
    "crank.crank": ("crank mass", "масса кривошипа"),
    "rod_pin_fraction": ("share of the rod mass at the piston pin", "доля массы шатуна на поршневом пальце"),
    "heat_input": ("heat input", "подведённая теплота"), "intake_pressure": ("intake pressure", "давление впуска"),
    "exhaust_pressure": ("exhaust pressure", "давление выпуска"),
    "combustion_start": ("start of combustion (from firing TDC)", "начало сгорания (от ВМТ сгорания)"),
    "combustion_duration": ("combustion duration", "продолжительность сгорания"),
    "wiebe_a": ("Wiebe a", "коэффициент Вибе a"), "wiebe_m": ("Wiebe exponent m", "показатель сгорания Вибе m"),
    "gamma": ("ratio of specific heats γ", "показатель адиабаты γ"),
    "cylinder_intake_pressure": ("cylinder pressure on intake", "давление в цилиндре при впуске"),
    "cylinder_exhaust_pressure": ("cylinder pressure on exhaust", "давление в цилиндре при выпуске"),
    "exhaust_back_pressure": ("exhaust back pressure", "противодавление выпуска"),
    "exhaust_opening_pressure": ("cylinder pressure at exhaust opening", "давление в цилиндре при открытии выпуска"),
    "intake_port_pressure": ("intake port pressure", "давление во впускном канале"),
    "speed": ("crank speed n", "частота вращения n"), "lambda": ("λ = R/L", "λ = R/L"),
    "max_velocity_crank": ("crank angle of the max piston velocity", "угол ПКВ наибольшей скорости поршня"),
    "max_acceleration_crank": ("crank angle of the max piston acceleration", "угол ПКВ наибольшего ускорения поршня"),
    "min_acceleration_crank": ("crank angle of the min piston acceleration", "угол ПКВ наименьшего ускорения поршня"),
    "crank.max_velocity": ("max piston velocity v_p", "наибольшая скорость поршня v_п"),
    "crank.max_acceleration": ("max piston acceleration a_p", "наибольшее ускорение поршня a_п"),
    "crank.min_acceleration": ("min piston acceleration a_p", "наименьшее ускорение поршня a_п"),
    "textbook.max_velocity": ("max piston velocity, approximate formula", "наибольшая скорость поршня по приближённой формуле"),
    "textbook.max_acceleration": ("max piston acceleration, approximate formula", "наибольшее ускорение поршня по приближённой формуле"),
    "textbook.min_acceleration": ("min piston acceleration, approximate formula", "наименьшее ускорение поршня по приближённой формуле"),
    "textbook.min_acceleration_crank": ("its crank angle, approximate formula", "его угол ПКВ по приближённой формуле"),
    "textbook.source": ("approximate formulas from", "источник приближённых формул"),
    "max_rod_angle": ("max connecting-rod angle β", "наибольший угол отклонения шатуна β"),
    "tdc_crank": ("TDC at crank angle", "ВМТ при угле ПКВ"), "bdc_crank": ("BDC at crank angle", "НМТ при угле ПКВ"),
    "masses.piston": ("piston mass", "масса поршня"), "masses.rod": ("connecting-rod mass", "масса шатуна"),
    "masses.crank": ("crank mass", "масса кривошипа"),
    "rod_at_pin": ("rod mass at the piston pin", "масса шатуна на поршневом пальце"),
    "rod_at_crank": ("rod mass at the crank pin", "масса шатуна на шатунной шейке"),
    "reciprocating": ("reciprocating mass m_j", "масса поступательно движущихся частей m_j"),
    "rotating": ("rotating mass m_r", "масса вращающихся частей m_r"),
    "centrifugal_force": ("centrifugal force K_r", "центробежная сила K_r"),
    "max_gas_pressure": ("max gas pressure", "наибольшее давление газов"),
    "max_gas_pressure_crank": ("crank angle of the max gas pressure", "угол ПКВ наибольшего давления газов"),
    "mean_torque": ("mean torque M_mean", "средний крутящий момент M_ср"),
    "max_torque": ("max torque", "наибольший крутящий момент"), "min_torque": ("min torque", "наименьший крутящий момент"),
    "nonuniformity": ("torque nonuniformity (M_max − M_min)/M_mean", "неравномерность крутящего момента (M_max − M_min)/M_ср"),
    "cylinder_mean_torque": ("mean torque of one cylinder", "средний крутящий момент одного цилиндра"),
    "torque_period": ("period of the total torque", "период суммарного крутящего момента"),
    "even_firing": ("even firing", "равномерное чередование вспышек"),
    "firing_angles": ("firing angles", "углы вспышек"), "firing": ("firing", "чередование вспышек"),
    "indicated_work": ("indicated work W_i", "индикаторная работа W_i"),
    "imep": ("mean indicated pressure p_i", "среднее индикаторное давление p_i"),
    "mean_torque_from_work": ("mean torque from the work W_i/(πτ)", "средний момент по работе W_i/(πτ)"),
    "torque_work_balance": ("relative difference of the two mean torques", "относительная разница двух средних моментов"),
    "specific_piston": ("specific piston mass", "удельная масса поршня"),
    "specific_rod": ("specific rod mass", "удельная масса шатуна"), "specific_crank": ("specific crank mass", "удельная масса кривошипа"),
    "cycle.intake_pressure": ("intake pressure", "давление впуска"),
    # two-stroke
    "ports.kind": ("port kind", "вид окна"), "width": ("port width", "ширина окна"), "height": ("port height", "высота окна"),
    "lower_edge": ("lower edge above the piston crown at BDC", "нижняя кромка над днищем поршня в НМТ"),
    "opens_crank": ("opens (from TDC)", "открывается (от ВМТ)"), "closes_crank": ("closes (from TDC)", "закрывается (от ВМТ)"),
    "duration": ("open", "открыто"), "max_area": ("max port area", "наибольшая площадь окна"),
    "opens_before_bdc": ("opens before BDC", "открывается до НМТ"),
    "opens_before_bdc_series": ("opens before BDC, series formula (8.1)", "открывается до НМТ, по формуле (8.1)"),
    "speed_range": ("range of speeds", "диапазон частот вращения"),
    # breathing
    "breathing.mode": ("cycle: motored or fired", "цикл: прокрутка или рабочий"),
    "breathing.wall_temperature": ("wall temperature", "температура стенок"),
    "wall_temperature": ("wall temperature", "температура стенок"),
    "breathing.heat_transfer": ("wall heat transfer", "теплоотдача в стенки"),
    "breathing.fuel": ("fuel", "топливо"), "breathing.equivalence_ratio": ("equivalence ratio φ", "коэффициент избытка топлива φ"),
    "breathing.combustion_efficiency": ("share of the fuel's heat released", "доля выделившейся теплоты топлива"),
    "breathing.cell": ("longest cell of the runners", "наибольшая ячейка трубопроводов"),
    "breathing.cycle_tolerance": ("relative change at which the cycles repeat", "относительное изменение, при котором циклы повторяются"),
    "breathing.max_cycles": ("most cycles", "наибольшее число циклов"),
    "intake.lift": ("intake valves' lift: designed or by the dynamics",
                    "подъём впускных клапанов: расчётный или по динамике привода"),
    "exhaust.lift": ("exhaust valves' lift: designed or by the dynamics",
                     "подъём выпускных клапанов: расчётный или по динамике привода"),
    "intake.lift_file": ("file of the intake valve's lift", "файл подъёма впускного клапана"),
    "exhaust.lift_file": ("file of the exhaust valve's lift", "файл подъёма выпускного клапана"),
    "intake.valves": ("intake valves", "число впускных клапанов"), "exhaust.valves": ("exhaust valves", "число выпускных клапанов"),
    "intake.cd_file": ("file of the intake valve's C_D(L/D)", "файл C_D(L/D) впускного клапана"),
    "exhaust.cd_file": ("file of the exhaust valve's C_D(L/D)", "файл C_D(L/D) выпускного клапана"),
    "intake.cd_diameter": ("reference diameter D of the intake C_D", "опорный диаметр D коэффициента C_D впуска"),
    "exhaust.cd_diameter": ("reference diameter D of the exhaust C_D", "опорный диаметр D коэффициента C_D выпуска"),
    "intake.cd_reference": ("reference area of the intake C_D", "опорная площадь C_D впуска"),
    "exhaust.cd_reference": ("reference area of the exhaust C_D", "опорная площадь C_D выпуска"),
    "intake.runner_length": ("intake runner length", "длина впускного трубопровода"),
    "exhaust.runner_length": ("exhaust runner length", "длина выпускного трубопровода"),
    "intake.runner_diameter": ("intake runner diameter", "диаметр впускного трубопровода"),
    "exhaust.runner_diameter": ("exhaust runner diameter", "диаметр выпускного трубопровода"),
    "breathing.intake_pressure": ("intake plenum pressure p_i", "давление во впускном ресивере p_i"),
    "breathing.intake_temperature": ("intake plenum temperature T_i", "температура во впускном ресивере T_i"),
    "breathing.exhaust_pressure": ("exhaust plenum pressure p_e", "давление в выпускном ресивере p_e"),
    "breathing.exhaust_temperature": ("mean exhaust temperature", "средняя температура отработавших газов"),
    "breathing.curve.exhaust_temperature": ("exhaust plenum temperature", "температура в выпускном ресивере"),
    "breathing.curve.points": ("speeds of the curve", "число частот вращения"),
    "breathing.air_mass_flow": ("air mass flow ṁ_a", "расход воздуха ṁ_в"),
    "breathing.volumetric_efficiency": ("volumetric efficiency η_v", "коэффициент наполнения η_v"),
    "breathing.trapped_mass": ("trapped mass", "масса заряда"),
    "breathing.residual_gas_fraction": ("residual gas fraction", "коэффициент остаточных газов"),
    "breathing.intake_backflow": ("back-flow into the intake port a cycle", "обратный выброс во впускной канал за цикл"),
    "breathing.exhaust_backflow": ("back-flow from the exhaust port a cycle", "заброс из выпускного канала за цикл"),
    "breathing.pmep": ("pumping mean effective pressure PMEP", "давление насосных потерь"),
    "breathing.imep": ("net IMEP", "среднее индикаторное давление нетто"),
    "breathing.imep_gross": ("gross IMEP", "среднее индикаторное давление брутто"),
    "breathing.peak_pressure": ("peak cylinder pressure", "наибольшее давление в цилиндре"),
    "breathing.peak_pressure_crank": ("where the pressure peaks, from the gas-exchange TDC",
                                      "угол наибольшего давления от ВМТ газообмена"),
    "intake_temperature": ("intake plenum temperature", "температура во впускном ресивере"),
    "breathing.wall_heat": ("heat to the walls a cycle", "теплота в стенки за цикл"),
    "breathing.torque": ("indicated torque", "индикаторный крутящий момент"),
    "breathing.power": ("indicated power", "индикаторная мощность"),
    "breathing.cycles": ("cycles to repeat", "число циклов до повторения"), "piston_height": ("piston height", "высота поршня"),
}
"""Names of the keys without their unit suffix (or a whole key where the suffix is no unit): ``(en, ru)``."""

VALUES = {
    "deactivation": "отключение клапана", "two_step": "двухступенчатый подъём",
    "pivot": "опора рычага", "chain": "цепь", "belt": "зубчатый ремень", "gears": "шестерни",
    "intake": "впускной", "exhaust": "выпускной", "inlet": "впускное", "transfer": "продувочное",
    "flat": "плоский", "roller": "роликовый", "finger": "роликовый рычаг", "direct": "непосредственный",
    "rocker": "с коромыслом",
    "pushrod": "со штангой и коромыслом", "inline": "рядный", "v": "V-образный", "si": "с искровым зажиганием",
    "si_injected": "с искровым зажиганием и впрыском", "diesel": "дизель", "side_valve": "нижнеклапанная",
    "overhead": "верхнеклапанная", "prechamber_diesel": "предкамерная (дизель)",
    "direct_injection_diesel": "неразделённая (дизель)", "wedge": "клиновая", "hemispherical": "полусферическая",
    "automotive_petrol": "автомобильный бензиновый", "automotive_diesel": "автомобильный дизель",
    "heavy_duty": "тяжёлого класса (тепловозный, судовой, стационарный)",
    "exact": "точная", "approximate": "приближённая", "brix": "по методу Брикса", "cosine": "косинусоидальный",
    "constant_velocity": "с постоянной скоростью", "constant_acceleration": "с постоянным ускорением",
    "kurz": "безударный кулачок Курца", "polydyne": "полидинамический кулачок", "polynomial": "полиномиальный",
    "power_polynomial": "кулачок со степенно-полиномиальным графиком ускорений",
    "combined": "составной", "dynamic": "динамический синтез", "harmonic": "гармонический",
    "three_arc": "трёхдуговой", "tangent": "тангенциальный", "table": "по измеренной таблице",
    "crank": "по коленчатому валу", "cam": "по распределительному валу", "valve": "на клапане", "tappet": "на толкателе",
    "gas_exchange_tdc": "ВМТ газообмена", "firing_tdc": "ВМТ сгорания", "auto": "автоматически", "spline": "сплайн",
    "stated": "задана в исходных данных",
    "true": "да", "false": "нет", "outer": "наружная", "inner": "внутренняя", "any": "любое",
    "1dof": "одномассовая", "multi": "многомассовая", "none": "нет", "infeed": "подачей круга",
    "motored": "прокрутка", "fired": "рабочий цикл", "woschni": "по Вошни", "adiabatic": "нет (адиабатные стенки)",
    "port": "площадь канала π D²/4", "curtain": "площадь цилиндрической щели π D L", "isooctane": "изооктан",
    "n-heptane": "н-гептан", "methane": "метан", "propane": "пропан", "ethanol": "этанол",
    "designed": "расчётный, по закону кулачка",
    "dynamics": "по динамической модели привода при каждой частоте",
}
"""Russian of the text values of the specification and the records (their English is the value itself)."""

SEGMENTS = {
    "ramp": "участок сбега", "polydyne": "полидинамический участок", "harmonic": "гармонический участок",
    "measured": "измеренный участок", "clearance take-up": "выборка зазора", "dynamic": "основной участок",
    "flank": "боковой участок", "nose": "вершина", "A1": "A1", "A2": "A2", "A3": "A3",
    "Phi1": "Φ1", "Phi2": "Φ2", "Phi3": "Φ3",
    "dwell": "верхний выстой", "b-d": "b-d", "d-e": "d-e", "e-g": "e-g", "g-h": "g-h",
}
"""Names of the lift-law segments (``"Phi1 opening"``) without their side."""

NUMBER = re.compile(r"(?:[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?)+")
"""A number, or a run of numbers without a blank between them (``1-5-3-6-2-4``, ``700-7700``): one ``{}`` of a
skeleton."""


def _candidates(path):
    """``(name path, unit)`` to look up for a key: the whole key, then without each unit suffix it ends with,
    the shortest suffix first (``max_velocity_crank_deg`` is ``max_velocity_crank`` in deg before it is
    ``max_velocity`` in crank deg)."""
    leaf = path.rsplit(".", 1)[-1]
    prefix = path[: len(path) - len(leaf)]
    out = [(path, "")]
    for suffix, unit in sorted(SUFFIXES, key=lambda s: len(s[0])):
        if leaf.endswith(suffix) and len(leaf) > len(suffix):
            out.append((prefix + leaf[: -len(suffix)], unit))
    return out


def _lookup(path, table):
    """The entry of the longest tail of a dotted ``path`` in ``table``."""
    parts = path.split(".")
    for i in range(len(parts)):
        tail = ".".join(parts[i:])
        if tail in table:
            return table[tail]
    return None


ANGLE_UNITS = {
    **dict.fromkeys(("opens", "closes", "nose_crank", "stroke_crank", "valve_opens_crank", "valve_closes_crank",
                     "lift.crank", "opens_crank", "closes_crank", "peak_pressure_crank"), "crank deg"),
    **dict.fromkeys(("phi1", "phi2", "phi3", "phi_p0", "ramp", "event_cam", "rho_min_cam", "rho_max_cam", "lift.cam",
                     "output.table_step_cam", "cam_force_max_cam", "cam_contact_stress_cam", "lobe_centre_cam",
                     "roller_side_force_cam"),
                    "cam deg"),
}
"""Angles in degrees of the crank or of the camshaft (their keys end in ``_deg``)."""


def _named(path):
    for name_path, unit in _candidates(path):
        found = _lookup(name_path, NAMES)
        if found is not None:
            if unit == "deg":
                unit = _lookup(name_path, ANGLE_UNITS) or unit
            return found, unit
    return None, ""


def label(path, lang) -> str:
    """The name of a key of a record with its unit: ``"cam.max_velocity_m_s"`` -> ``"max tappet velocity
    v_T max, m/s"``.

    ``path`` is dotted (``"spring.count"``); the longest tail with a name wins, the unit comes from the key's
    suffix.  A key without a name is shown with spaces for its underscores -- :func:`has_name` finds them.
    """
    found, unit = _named(path)
    if found is None:
        return path.rsplit(".", 1)[-1].replace("_", " ")
    name = found[LANGS.index(lang)]
    return f"{name}, {unit_text(unit, lang)}" if unit else name


def has_name(path) -> bool:
    """True when :func:`label` has a name for ``path`` (not the key itself)."""
    return _named(path)[0] is not None


def value_text(value, lang) -> str:
    """A text value of a record (``"flat"``, ``"pushrod"``, a segment ``"Phi1 opening"``) in ``lang``."""
    if lang == "en" or not isinstance(value, str):
        return value
    if value in VALUES:
        return VALUES[value]
    for side, ru in ((" opening", "подъём"), (" closing", "опускание")):
        if value.endswith(side) and value[: -len(side)] in SEGMENTS:
            return f"{SEGMENTS[value[: -len(side)]]}, {ru}"
    return translate(value, lang)


LINKS = {
    "camshaft and cam contact": "распределительный вал и контакт кулачка", "pushrod": "штанга",
    "rocker and valve joint": "коромысло и его сочленения", "valve stem and tappet": "стержень клапана и толкатель",
}
"""Russian of the drive links of the dynamics chapter (their English is the name itself)."""


def link_names(names, lang) -> str:
    """The drive links of a dynamics record, comma-separated, in ``lang``."""
    return ", ".join(name if lang == "en" else LINKS.get(name, name) for name in names)


def translate(text, lang) -> str:
    """A text made with numbers in ``lang`` by its skeleton (the catalogue's ``[texts]``); as it is without one.  A text that
    starts with drive links (``"pushrod: ..."``, :data:`LINKS`) has them translated and the rest by its skeleton; a
    text of parts joined by ``"; "`` without a skeleton of its own, part by part (the longest head with one first)."""
    if lang == "en" or not text:
        return text
    head, sep, rest = text.partition(": ")
    if sep and all(name in LINKS for name in head.split(", ")):
        return f"{link_names(head.split(', '), lang)}: {translate(rest, lang)}"
    found = _by_skeleton(text)
    if found is not None:
        return found
    parts = text.split("; ")
    for k in range(len(parts) - 1, 0, -1):
        head = _by_skeleton("; ".join(parts[:k]))
        if head is not None:
            return f"{head}; {translate('; '.join(parts[k:]), lang)}"
    return text


def _by_skeleton(text):
    """The Russian of a text made with numbers by its skeleton (``ru.toml`` ``[texts]`` of the catalogue
    :mod:`valvetrain.locale`), or None."""
    ru = catalogue("ru")["texts"].get(NUMBER.sub("{}", text))
    return None if ru is None else ru.format(*NUMBER.findall(text))


def quantity_text(check, lang) -> str:
    """The quantity of a check in ``lang``: its valve or chapter, then the text of its code in the catalogue
    (:mod:`valvetrain.locale`): ``"intake: V′ (условная скорость в горловине)"``."""
    return record_quantity_text({"code": check.code, "params": dict(check.params), "quantity": check.quantity,
                                 "valve": check.valve}, lang)


def record_quantity_text(record, lang) -> str:
    """:func:`quantity_text` of a check record of results.json (``code``, ``params``, ``quantity``, ``valve``)."""
    params = record["params"]
    text = check_text(record["code"], params, lang)
    if "spring" in params:
        text = f"{spring_text(params['spring'], lang)}: {text}"
    head = record["quantity"].partition(": ")[0]
    if record["valve"] is not None:
        return f"{record['valve']}: {text}"
    if record["quantity"] != record_text(record["code"], params) and head in catalogue(lang)["chapters"]:
        return f"{catalogue(lang)['chapters'][head]}: {text}"
    return text


CANNOT_EVALUATE = ("cannot be evaluated", "не может быть вычислено")
"""Said of a check whose value is not a finite number, before its reason."""


def unevaluated_text(check, lang) -> str:
    """``"cannot be evaluated: REASON"`` of a check that cannot be evaluated, in ``lang`` (the reason by
    :func:`translate`)."""
    return f"{CANNOT_EVALUATE[LANGS.index(lang)]}: {translate(check.unevaluated, lang)}"


NAMES.update({
    "lift.cam": ("camshaft angle from the nose φ", "угол поворота распределительного вала от вершины φ"),
    "lift.crank": ("crank angle from the gas-exchange TDC", "угол поворота коленчатого вала от ВМТ газообмена"),
    "lift.segment": ("segment of the lift law", "участок закона подъёма"),
    "lift.tappet_lift": ("tappet lift h_T", "подъём толкателя h_T"),
    "lift.tappet_velocity": ("tappet velocity v_T", "скорость толкателя v_T"),
    "lift.tappet_acceleration": ("tappet acceleration a_T", "ускорение толкателя a_T"),
    "lift.tappet_jerk": ("tappet jerk j_T", "рывок толкателя j_T"),
    "lift.valve_lift": ("valve lift h_v", "подъём клапана h_v"),
    "lift.curtain_area": ("curtain area f", "проходное сечение клапана f"),
    "lift.time_area": ("running time-area ∫f dt", "время-сечение нарастающим итогом ∫f dt"),
    "lift.rho": ("radius of curvature ρ", "радиус кривизны ρ"),
    "lift.pressure_angle": ("pressure angle", "угол давления"),
    "lift.contact_offset": ("contact offset b", "смещение точки контакта b"),
})

NAMES.update(STAGE_NAMES)
