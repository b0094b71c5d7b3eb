"""Texts of the report's chapters of the further stages in English and Russian: the hydraulic valve actuation, the
lubrication of the cam contact, the hydraulic lash adjuster, the whole camshaft, the breathing and the cam phaser
(:mod:`.i18n` merges them into its ``TEXT``)."""

STAGE_TEXT = {"en": {}, "ru": {}}
"""The texts of the chapters of the further stages, ``lang -> key -> text``."""

STAGE_TEXT["en"].update({
    "hy_chapter": "9. Hydraulic valve actuation",
    "hy_method": "The cam drives a plunger that feeds a pipe to an actuator piston on the valve. The pipe is solved by the "
                 "method of characteristics with a constant Darcy friction factor (time step L / (N a), the wave speed "
                 "a corrected for the elasticity of the wall); the pump and actuator chambers are compressible "
                 "volumes (V / K) dp/dt = inflow − outflow with leakage, fill and relief valves; the valve is one mass "
                 "on its spring, its damping, a rigid seat and a stiff stop at the end of its stroke (a valve that "
                 "reaches it, or that is not back on its seat when the plunger lifts again, fails). Pressures are "
                 "absolute; a pressure that falls to the "
                 "vapour pressure is held there and flagged as cavitation (the cavity volume is not tracked). The "
                 "rigid drive lifts the valve by the plunger lift times A_p / A_a; the delays are taken at 5 % of its "
                 "largest lift",
    "hy_title": "hydraulic drive: pressures and valve lift", "hy_pressure": "absolute pressure, MPa",
    "hy_lift": "lift, mm", "hy_pump": "pump end", "hy_actuator": "actuator end", "hy_vapour": "vapour pressure",
    "hy_valve": "valve", "hy_rigid": "rigid drive", "hy_cavitation": "cavitation", "hy_table": "Table against camshaft angle",
    "hy_names": {
        "speed_rpm": "engine speed, rpm", "wave_speed_m_s": "wave speed a in the pipe, m/s",
        "time_step_us": "time step L / (N a), µs", "area_ratio": "area ratio A_p / A_a",
        "rigid_lift_mm": "largest lift of the rigid drive, mm", "valve_lift_mm": "largest valve lift, mm",
        "lift_loss_mm": "lift loss, mm", "opening_delay_cam_deg": "opening delay, cam deg",
        "closing_delay_cam_deg": "closing delay (negative: early), cam deg",
        "max_pressure_MPa": "largest pressure, MPa", "max_pressure_cam_deg": "where it is largest, cam deg",
        "min_pressure_MPa": "smallest pressure, MPa", "vapour_pressure_MPa": "vapour pressure, MPa", "cavitation": "cavitation (pressure at the vapour pressure)",
        "seating_velocity_m_s": "seating velocity (negative: closing), m/s",
        "bounce_mm": "largest lift after the first seating (bounce), mm", "speeds": "speeds swept",
        "stop_mm": "valve stop (end of its stroke), mm", "stop_reached": "the valve reaches its stop (a failure)",
        "residual_lift_mm": "lift left when the plunger lifts again (above 0: not closed, a failure), mm",
        "gas_force.head_diameter_mm": "diameter the cylinder pressure acts on, mm",
        "gas_force.port_pressure_MPa": "pressure behind the valve head (port), MPa",
        "gas_force.lift_off_crank_deg": "valve leaves its seat, crank deg from the gas-exchange TDC (0...720)",
        "gas_force.cylinder_pressure_at_lift_off_MPa": "cylinder pressure there, MPa",
        "gas_force.gas_force_at_lift_off_N": "gas force on the valve head there, N",
        "gas_force.lift_off_pressure_MPa": "actuator pressure that lifts the valve there, MPa",
        "gas_force.opening_delay_cam_deg": "opening delay the gas force adds, cam deg",
        "gas_force.lift_loss_mm": "lift loss the gas force adds, mm",
        "gas_force.pressure_rise_MPa": "rise of the largest pressure by the gas force, MPa",
    },
    "hy_gas": "Gas force on the valve head",
    "hy_gas_method": "The valve opens against the cylinder pressure on its head: the force (p_cyl − p_port) π d² / 4 "
                     "acts towards the seat at the crank angle of the cam nose plus twice the camshaft angle; the "
                     "cycle is the engine's as given (its blowdown does not wait for the valve), the effects are "
                     "against the same drive without the force",
    "hy_gas_source": "Cylinder pressure",
    "hy_stop": "stop (end of the stroke)", "hy_lift_off": "valve leaves its seat (gas force {force} kN)",
    "hy_sweep": "Speed sweep (one revolution per speed)",
    "hy_sweep_title": "hydraulic drive against engine speed", "hy_sweep_table": "Table against engine speed",
    "hy_max_pressure": "largest pressure, MPa", "hy_lift_loss": "lift loss, mm", "hy_delay": "delay, cam deg",
    "hy_opening_delay": "opening", "hy_closing_delay": "closing (negative: early)",
    "hy_notes": "Values not given in the specification",
})

STAGE_TEXT["ru"].update({
    "hy_chapter": "9. Гидравлический привод клапана",
    "hy_method": "Кулачок приводит плунжер насоса, который по трубопроводу подаёт жидкость к поршню привода клапана. "
                 "Трубопровод рассчитан методом характеристик с постоянным коэффициентом трения Дарси (шаг по "
                 "времени L / (N a), скорость волны a с поправкой на упругость стенки); полости насоса и привода "
                 "сжимаемы: (V / K) dp/dt = приток − отток, с утечками, подпиточным и предохранительным клапанами; "
                 "клапан — одна масса на пружине, с демпфированием, жёстким седлом и жёстким упором в конце хода "
                 "(клапан, дошедший до упора или не вернувшийся на седло к следующему подъёму плунжера, — отказ). "
                 "Давления абсолютные; давление, "
                 "упавшее до давления насыщенных паров, удерживается на нём и отмечается как кавитация (объём "
                 "каверны не отслеживается). Жёсткий привод поднимает клапан на подъём плунжера, умноженный на "
                 "A_p / A_a; запаздывания взяты на уровне 5 % его наибольшего подъёма",
    "hy_title": "гидропривод: давления и подъём клапана", "hy_pressure": "абсолютное давление, МПа",
    "hy_lift": "подъём, мм", "hy_pump": "у насоса", "hy_actuator": "у привода клапана",
    "hy_vapour": "давление насыщенных паров", "hy_valve": "клапан", "hy_rigid": "жёсткий привод",
    "hy_cavitation": "кавитация", "hy_table": "Таблица по углу поворота распределительного вала",
    "hy_names": {
        "speed_rpm": "частота вращения двигателя, мин⁻¹", "wave_speed_m_s": "скорость волны a в трубопроводе, м/с",
        "time_step_us": "шаг по времени L / (N a), мкс", "area_ratio": "отношение площадей A_p / A_a",
        "rigid_lift_mm": "наибольший подъём при жёстком приводе, мм", "valve_lift_mm": "наибольший подъём клапана, мм",
        "lift_loss_mm": "потеря подъёма, мм", "opening_delay_cam_deg": "запаздывание открытия, град ПРВ",
        "closing_delay_cam_deg": "запаздывание закрытия (минус: раньше), град ПРВ",
        "max_pressure_MPa": "наибольшее давление, МПа", "max_pressure_cam_deg": "где оно наибольшее, град ПРВ",
        "min_pressure_MPa": "наименьшее давление, МПа", "vapour_pressure_MPa": "давление насыщенных паров, МПа",
        "cavitation": "кавитация (давление насыщенных паров)",
        "seating_velocity_m_s": "скорость посадки клапана (минус: при закрытии), м/с",
        "bounce_mm": "наибольший подъём после первой посадки (отскок), мм", "speeds": "число частот вращения",
        "stop_mm": "упор клапана (конец его хода), мм", "stop_reached": "клапан доходит до упора (отказ)",
        "residual_lift_mm": "подъём к началу следующего подъёма плунжера (больше 0: клапан не закрылся, отказ), мм",
        "gas_force.head_diameter_mm": "диаметр, на который действует давление в цилиндре, мм",
        "gas_force.port_pressure_MPa": "давление за тарелкой клапана (в канале), МПа",
        "gas_force.lift_off_crank_deg": "клапан отходит от седла, град ПКВ от ВМТ газообмена (0...720)",
        "gas_force.cylinder_pressure_at_lift_off_MPa": "давление в цилиндре в этот момент, МПа",
        "gas_force.gas_force_at_lift_off_N": "сила давления газов на тарелку клапана в этот момент, Н",
        "gas_force.lift_off_pressure_MPa": "давление в приводе, поднимающее клапан в этот момент, МПа",
        "gas_force.opening_delay_cam_deg": "добавочное запаздывание открытия от силы газов, град ПРВ",
        "gas_force.lift_loss_mm": "добавочная потеря подъёма от силы газов, мм",
        "gas_force.pressure_rise_MPa": "рост наибольшего давления от силы газов, МПа",
    },
    "hy_gas": "Сила давления газов на тарелку клапана",
    "hy_gas_method": "Клапан открывается против давления в цилиндре на его тарелку: сила (p_ц − p_к) π d² / 4 "
                     "направлена к седлу и берётся при угле ПКВ вершины кулачка плюс удвоенный угол ПРВ; цикл — "
                     "заданный цикл двигателя (выпуск не ждёт открытия клапана), влияние силы — по сравнению с тем же "
                     "приводом без неё",
    "hy_gas_source": "Давление в цилиндре",
    "hy_stop": "упор (конец хода)", "hy_lift_off": "клапан отходит от седла (сила газов {force} кН)",
    "hy_sweep": "Расчёт по частоте вращения (один оборот на каждой частоте)",
    "hy_sweep_title": "гидропривод в зависимости от частоты вращения двигателя",
    "hy_sweep_table": "Таблица по частоте вращения двигателя",
    "hy_max_pressure": "наибольшее давление, МПа", "hy_lift_loss": "потеря подъёма, мм",
    "hy_delay": "запаздывание, град ПРВ", "hy_opening_delay": "открытия",
    "hy_closing_delay": "закрытия (минус: раньше)",
    "hy_notes": "Величины, не заданные в исходных данных",
})


STAGE_TEXT["en"].update({
    "lu_chapter": "10. Lubrication and friction of the cam contact",
    "lu_method": "Over every engine speed of the strength checks (the simulated force at the speeds of a dynamics "
                 "sweep): the surface velocities of cam and follower relative to the contact (a flat follower's "
                 "contact point runs along the face at ω h″, a roller rolls with its slip), the Dowson-Higginson "
                 "minimum film thickness of the line contact (isothermal, fully flooded, no squeeze film), the film "
                 "parameter λ = h_min / √(Rq1² + Rq2²) and the regime (boundary below 1, full film from 3), a friction "
                 "coefficient falling linearly in λ across the mixed band, a roller's rolling resistance, Blok's flash "
                 "temperature of the sliding contact (steel on steel), the camshaft torque of the friction from the "
                 "power it dissipates and the drive torque with it, F dh/dθ + T_f",
    "lu_zero": "The entraining velocity changes sign (no steady film) at, cam deg",
    "lu_table": "Against engine speed",
    "lu_names": {
        "reduced_modulus_GPa": "reduced modulus E′, GPa", "composite_roughness_um": "composite roughness, µm",
        "min_film_parameter": "smallest film parameter λ", "min_film_parameter_speed_rpm": "at engine speed, rpm",
        "min_film_parameter_cam_deg": "where, cam deg from the nose", "min_film_um": "smallest film h_min, µm",
        "max_contact_temperature_C": "largest contact temperature, °C",
        "max_contact_temperature_speed_rpm": "at engine speed, rpm",
        "rated_friction_power_W": "friction power at the rated speed, W",
        "rated_mean_friction_torque_N_m": "mean friction torque at the rated speed, N·m",
        "rated_max_drive_torque_N_m": "largest drive torque with friction at the rated speed, N·m",
        "speed_rpm": "engine speed, rpm", "boundary_cam_deg": "boundary, cam deg", "mixed_cam_deg": "mixed, cam deg",
        "full_film_cam_deg": "full film, cam deg", "mean_friction_torque_N_m": "mean friction torque, N·m",
        "friction_power_W": "friction power, W", "max_flash_temperature_K": "largest flash temperature rise, K",
        "max_drive_torque_N_m": "largest drive torque, N·m",
    },
})

STAGE_TEXT["ru"].update({
    "lu_chapter": "10. Смазка и трение в контакте кулачка",
    "lu_method": "На каждой частоте вращения расчёта прочности (на частотах расчёта динамики — с рассчитанной силой): "
                 "скорости поверхностей кулачка и толкателя относительно точки контакта (точка контакта плоского "
                 "толкателя движется по его торцу со скоростью ω h″, ролик катится с заданным проскальзыванием), "
                 "наименьшая толщина плёнки линейного контакта по Доусону — Хиггинсону (изотермически, без "
                 "масляного голодания и выдавливания плёнки), параметр плёнки λ = h_min / √(σ1² + σ2²) и режим смазки "
                 "(граничный при λ < 1, жидкостный при λ ≥ 3), коэффициент трения, линейно убывающий по λ в "
                 "смешанном режиме, сопротивление качению ролика, температурная вспышка скользящего контакта по Блоку "
                 "(сталь по стали), момент трения на распределительном валу по рассеиваемой мощности и момент привода "
                 "с трением F dh/dθ + T_f",
    "lu_zero": "Скорость увлечения масла меняет знак (установившейся плёнки нет) при углах, град ПРВ",
    "lu_table": "В зависимости от частоты вращения двигателя",
    "lu_names": {
        "reduced_modulus_GPa": "приведённый модуль упругости E′, ГПа",
        "composite_roughness_um": "суммарная шероховатость, мкм",
        "min_film_parameter": "наименьший параметр плёнки λ", "min_film_parameter_speed_rpm": "при частоте, мин⁻¹",
        "min_film_parameter_cam_deg": "где, град ПРВ от вершины", "min_film_um": "наименьшая толщина плёнки, мкм",
        "max_contact_temperature_C": "наибольшая температура контакта, °C",
        "max_contact_temperature_speed_rpm": "при частоте, мин⁻¹",
        "rated_friction_power_W": "мощность трения на номинальной частоте, Вт",
        "rated_mean_friction_torque_N_m": "средний момент трения на номинальной частоте, Н·м",
        "rated_max_drive_torque_N_m": "наибольший момент привода с трением на номинальной частоте, Н·м",
        "speed_rpm": "частота вращения, мин⁻¹", "boundary_cam_deg": "граничный режим, град ПРВ",
        "mixed_cam_deg": "смешанный режим, град ПРВ", "full_film_cam_deg": "жидкостный режим, град ПРВ",
        "mean_friction_torque_N_m": "средний момент трения, Н·м", "friction_power_W": "мощность трения, Вт",
        "max_flash_temperature_K": "наибольшая температурная вспышка, К",
        "max_drive_torque_N_m": "наибольший момент привода, Н·м",
    },
})


STAGE_TEXT["en"].update({
    "la_chapter": "11. Hydraulic lash adjuster",
    "la_method": "The oil column of the adjuster's high-pressure chamber is compressed from the supply pressure with "
                 "its entrained air (isothermal); its secant stiffness under the largest quasi-static force at the "
                 "rated speed joins the drive stiffness of the dynamics in series, and under the largest force at "
                 "each speed it is tabled against the speed. The plunger's extension is a state of the simulated "
                 "train, carried from one camshaft revolution to the next: under the force it carries it leaks down "
                 "through its annular clearance (laminar flow), and where that force falls to the adjuster's own "
                 "push the check valve opens and the plunger extends, refilling the lash on the base circle. Its "
                 "extension gained while the valve is off its seat before its first return (the follower floating) "
                 "is the pump-up of a revolution, a failure up to the over-speed; the smallest valve lift on the "
                 "base circle is the valve held off its seat. The pump-up accumulates revolution by revolution, no "
                 "further than the plunger's stop: a speed whose plunger still pumps up is integrated on until its "
                 "motion settles, where the leak-down under the spring's force balances the pump-up or the plunger "
                 "is at its stop, and the lift at which the valve held off its seat settles is graded. The leakage "
                 "of an eccentric plunger is 1 + 1.5 (e/c)² times the concentric one's. The follower floats where its force falls to that "
                 "push while the cam lifts the open valve: the plunger follows it, so the contact need not open, "
                 "and a float below the over-speed is a failure as a separation is. At the speeds the dynamics does "
                 "not sweep, the "
                 "leak-down is integrated over the quasi-static force",
    "la_location": "Location", "la_locations": {"pivot": "pivot of an end-pivot finger follower",
                                                "tappet": "in the tappet, in series with the cam contact"},
    "la_names": {
        "motion_ratio": "valve motion / adjuster motion",
        "plunger_eccentricity": "eccentricity of the plunger in its bore e / c",
        "leak_factor": "its leakage / the concentric plunger's, 1 + 1.5 (e / c)²",
        "reference_force_N": "largest force on the adjuster, N",
        "chamber_pressure_MPa": "chamber pressure under it, MPa", "compression_um": "compression of the oil column, µm",
        "stiffness_N_per_mm": "stiffness of the oil column, N/mm",
        "stiffness_at_valve_N_per_mm": "its stiffness at the valve, N/mm",
        "drive_stiffness_with_adjuster_N_per_mm": "drive stiffness of the dynamics with it, N/mm",
        "rated_leak_down_um": "leak-down per revolution at the rated speed, µm",
        "rated_valve_lash_um": "lash at the valve at closing, rated speed, µm",
        "max_refill_share": "largest refill time / base-circle time",
        "plunger_travel_mm": "the plunger's travel from its working position to its stop, mm",
        "max_pump_up_um": "largest pump-up per revolution up to the over-speed, µm",
        "max_pumped_up_um": "largest extension the plunger pumps up to, µm",
        "max_held_open_um": "largest lift at which a valve held on the base circle settles, µm",
        "held_open_speed_rpm": "where, rpm",
        "push_at_valve_N": "the adjuster's push at the valve (check valve opens), N",
        "float_speed_rpm": "float speed (the follower's force at that push while the cam lifts), rpm",
        "speed_rpm": "engine speed, rpm", "leak_down_um": "leak-down per revolution, µm",
        "valve_lash_um": "lash at the valve, µm", "refill_share": "refill time / base-circle time",
        "pump_up_um": "pump-up per revolution, µm", "pumped_up_um": "plunger pumped up to, µm",
        "held_open_um": "valve held open, µm", "revolutions": "revolutions to settle",
        "settled": "settled",
        "oil_stiffness_at_valve_N_per_mm": "stiffness of the oil column at the valve, N/mm",
    },
})

STAGE_TEXT["ru"].update({
    "la_chapter": "11. Гидрокомпенсатор зазора",
    "la_method": "Столб масла в камере высокого давления гидрокомпенсатора сжимается от давления подачи вместе с "
                 "нерастворённым воздухом (изотермически); его секущая жёсткость при наибольшей квазистатической "
                 "силе на номинальной частоте включается последовательно в жёсткость привода в расчёте динамики, а "
                 "при наибольшей силе на каждой частоте приведена в таблице по частотам. Выдвижение плунжера — "
                 "переменная состояния рассчитываемого привода, переносимая с одного оборота распределительного вала "
                 "на следующий: под действующей на него силой плунжер проседает из-за утечки через кольцевой зазор "
                 "(ламинарное течение), а там, где эта сила падает до собственного усилия гидрокомпенсатора, "
                 "открывается обратный клапан и плунжер выдвигается, выбирая зазор на цилиндрической части кулачка. "
                 "Выдвижение, набранное, пока клапан не сел на седло в первый раз после открытия (толкатель "
                 "оторвался от кулачка), — выдвижение плунжера за оборот, недопустимое до заброса оборотов; "
                 "наименьший подъём клапана на цилиндрической части — клапан, не севший на седло. Выдвижение "
                 "накапливается от оборота к обороту, не дальше упора плунжера: частота, на которой плунжер ещё "
                 "выдвигается, рассчитывается дальше, пока движение не установится — там, где проседание под силой "
                 "пружины уравновешивает выдвижение за оборот, или на упоре плунжера, — и оценивается подъём, на "
                 "котором устанавливается не севший на седло клапан. Утечка через зазор эксцентричного плунжера в "
                 "1 + 1,5 (e/c)² раза больше, чем соосного. Толкатель "
                 "отрывается там, где его сила падает до этого усилия, пока кулачок поднимает открытый клапан: "
                 "плунжер выдвигается за ним, контакт может не раскрыться, и отрыв ниже частоты заброса оборотов — "
                 "отказ, как и отрыв толкателя без гидрокомпенсатора. На частотах вне "
                 "расчёта динамики проседание интегрируется по квазистатической силе",
    "la_location": "Расположение", "la_locations": {"pivot": "опора рычага с опорой на конце",
                                                    "tappet": "в толкателе, последовательно с контактом кулачка"},
    "la_names": {
        "motion_ratio": "перемещение клапана / перемещение гидрокомпенсатора",
        "plunger_eccentricity": "эксцентриситет плунжера в отверстии e / c",
        "leak_factor": "его утечка / утечка соосного плунжера, 1 + 1,5 (e / c)²",
        "reference_force_N": "наибольшая сила на гидрокомпенсатор, Н",
        "chamber_pressure_MPa": "давление в камере при ней, МПа",
        "compression_um": "сжатие столба масла, мкм", "stiffness_N_per_mm": "жёсткость столба масла, Н/мм",
        "stiffness_at_valve_N_per_mm": "она же, приведённая к клапану, Н/мм",
        "drive_stiffness_with_adjuster_N_per_mm": "жёсткость привода в расчёте динамики с ним, Н/мм",
        "rated_leak_down_um": "проседание за оборот на номинальной частоте, мкм",
        "rated_valve_lash_um": "зазор у клапана при посадке на номинальной частоте, мкм",
        "max_refill_share": "наибольшее отношение времени заполнения к времени на цилиндрической части",
        "plunger_travel_mm": "ход плунжера от рабочего положения до упора, мм",
        "max_pump_up_um": "наибольшее выдвижение плунжера при отрыве за оборот до заброса оборотов, мкм",
        "max_pumped_up_um": "наибольшее выдвижение, до которого накачивается плунжер, мкм",
        "max_held_open_um": "наибольший подъём, на котором устанавливается клапан, удерживаемый на цилиндрической "
                            "части, мкм",
        "held_open_speed_rpm": "где, мин⁻¹",
        "push_at_valve_N": "усилие гидрокомпенсатора, приведённое к клапану (открывается обратный клапан), Н",
        "float_speed_rpm": "частота отрыва (сила толкателя падает до этого усилия, пока кулачок поднимает клапан), "
                           "мин⁻¹",
        "speed_rpm": "частота вращения, мин⁻¹", "leak_down_um": "проседание за оборот, мкм",
        "valve_lash_um": "зазор у клапана, мкм", "refill_share": "время заполнения / время на цилиндрической части",
        "pump_up_um": "выдвижение при отрыве за оборот, мкм", "pumped_up_um": "плунжер накачан до, мкм",
        "held_open_um": "клапан удерживается открытым, мкм", "revolutions": "оборотов до установления",
        "settled": "установилось",
        "oil_stiffness_at_valve_N_per_mm": "жёсткость столба масла, приведённая к клапану, Н/мм",
    },
})


STAGE_TEXT["en"].update({
    "cs_chapter": "The whole camshaft: drive torque, torsion, bending and the timing drive",
    "cs_method": "Every lobe of the camshaft's valves on every cylinder of the shaft, each at its nose's camshaft "
                 "angle from the engine's firing order (the camshaft turns at half the crank angle of a "
                 "four-stroke); one lobe's torque at the rated speed is its valve's drive torque F dh/dθ under the "
                 "cam force of the valve's stages (the simulated force where the dynamics ran), with the friction "
                 "torque of the cam contact where the lubrication was computed. The orders of the camshaft speed by "
                 "the discrete Fourier transform of a revolution; the lag of each lobe station behind the crankshaft "
                 "under the instantaneous torque, quasi-static, the shaft's sections in series (T l / G J) after the "
                 "timing drive's stretch (T / k r²; none with a rigid drive); the torsional natural frequencies of "
                 "the stations' inertias (lobes, the valve train reduced to the camshaft, the shaft) and of the "
                 "sprocket on the timing drive's stiffness (without it, the shaft held at its drive end); the "
                 "bending deflection of each station "
                 "under its largest cam force on a simply supported span between its journals; the force of the "
                 "timing drive, the torque over the pitch radius",
    "cs_valves": "Lobes of the valves",
    "cs_angle": "camshaft angle from the gas-exchange TDC of cylinder 1",
    "cs_cam_deg": "camshaft angle from the gas-exchange TDC of cylinder 1, deg",
    "cs_order": "order of the camshaft speed", "cs_amplitude": "amplitude, N·m",
    "cs_torque_title": "drive torque of the camshaft and its orders",
    "cs_stations": "Lobe stations", "cs_cylinder": "cylinder",
    "cs_orders": "Significant orders of the camshaft speed",
    "cs_names": {
        "lobes": "lobes", "camshaft_per_crank_revolution": "camshaft revolutions per crank revolution",
        "peak_torque_Nm": "largest drive torque, N·m", "peak_torque_cam_deg": "where, cam deg",
        "lowest_torque_Nm": "smallest drive torque, N·m", "mean_torque_Nm": "mean drive torque, N·m",
        "fluctuating_torque_Nm": "fluctuating torque (largest − smallest), N·m",
        "rms_fluctuating_torque_Nm": "root mean square of the fluctuation, N·m",
        "power_W": "power taken at the rated speed, W",
        "natural_frequencies_Hz": "torsional natural frequencies, Hz",
        "frequency_ratio": "first natural frequency / highest significant order at the over-speed",
        "largest_twist_cam_deg": "largest lag behind the crankshaft, cam deg",
        "largest_twist_crank_deg": "the same, crank deg", "largest_deflection_mm": "largest bending deflection, mm",
        "drive_force_max_N": "largest force of the timing drive, N", "drive_force_mean_N": "mean force, N",
        "drive_allowable_force_N": "allowable force, N",
        "drive_windup_cam_deg": "largest stretch of the timing drive, cam deg",
        "drive_end_inertia_kg_mm2": "inertia at the drive end (sprocket and shaft), kg·mm²",
        "station_positions_mm": "position from the drive end, mm",
        "station_inertias_kg_mm2": "inertia, kg·mm²", "max_twist_cam_deg": "largest lag, cam deg",
        "deflection_mm": "bending deflection, mm", "order": "order", "order_amplitudes_Nm": "amplitude, N·m",
        "resonance_speeds_rpm": "resonant engine speed, rpm",
        "damping_ratio": "modal damping ratio of the torsional modes",
        "speed_range_rpm": "running range, rpm",
        "timing_fluctuation_allowable_cam_deg": "allowable fluctuation of a lobe's timing, cam deg",
        "largest_timing_fluctuation_cam_deg": "largest fluctuation of a lobe's timing, cam deg",
        "largest_timing_fluctuation_speed_rpm": "where, rpm",
        "largest_timing_fluctuation_cylinder": "at the lobes of cylinder",
        "largest_drive_force_N": "largest force of the timing drive, N",
        "largest_drive_force_speed_rpm": "where, rpm",
        "mode": "mode", "natural_frequency_Hz": "natural frequency, Hz", "speed_rpm": "engine speed, rpm",
        "timing_fluctuation_cam_deg": "fluctuation of the timing, cam deg", "drive_force_N": "force of the drive, N",
    },
    "cs_response": "Torsional response over the running range",
    "cs_response_method": "The camshaft and its timing drive as the chain of the natural frequencies above, the "
                           "crankshaft turning evenly, answer each order of the lobes' torque at every speed of the "
                           "running range (the torque of each speed from the valve's load map: the simulated force "
                           "where the dynamics ran, else the quasi-static one, with the friction where the "
                           "lubrication was computed) by modal superposition, every mode damped by the damping ratio "
                           "given; the steady lag of each lobe station, summed over the orders, gives the fluctuation "
                           "of its timing (largest less smallest lag over a revolution) and the drive's spring the "
                           "largest force of the timing drive. A resonance inside the running range is graded by that "
                           "response: the timing against the movement of the cam sprocket against the crankshaft a "
                           "maker accepts in service, the force against the drive's allowable",
    "cs_resonances": "Natural frequencies met by a significant order in the running range",
    "cs_torsion_title": "torsional response of the camshaft against the engine speed",
    "cs_fluctuation": "fluctuation of the lobes' timing, cam deg", "cs_drive_force": "force of the timing drive, N",
    "cs_allowable": "allowable", "cs_speed": "engine speed, rpm",
})

STAGE_TEXT["ru"].update({
    "cs_chapter": "Распределительный вал в целом: момент привода, кручение, изгиб, привод вала",
    "cs_method": "Все кулачки клапанов вала на всех его цилиндрах, каждый при угле поворота распределительного вала "
                 "своей вершины по порядку работы цилиндров (распределительный вал четырёхтактного двигателя "
                 "поворачивается на половину угла коленчатого вала); момент одного кулачка на номинальной частоте — "
                 "момент привода его клапана F dh/dθ от силы на кулачке, найденной расчётом клапана (рассчитанной "
                 "динамикой силы, где она считалась), с моментом трения в контакте кулачка, где рассчитана смазка. "
                 "Гармоники частоты вращения распределительного вала — дискретным преобразованием Фурье за оборот; "
                 "отставание каждого сечения кулачков от коленчатого вала под мгновенным моментом, "
                 "квазистатически, участки вала последовательно (T l / G J) после растяжения привода "
                 "(T / k r²; при жёстком приводе его нет); собственные частоты крутильных колебаний моментов инерции "
                 "сечений (кулачки, привод клапана, приведённый к валу, сам вал) и звёздочки на жёсткости привода "
                 "(без неё — на валу, закреплённом у приводного конца); прогиб вала у каждого сечения под "
                 "наибольшей силой на кулачке как "
                 "балки на двух опорах между его шейками; окружная сила привода — момент, делённый на радиус "
                 "начальной окружности",
    "cs_valves": "Кулачки клапанов",
    "cs_angle": "угол поворота распределительного вала от ВМТ газообмена цилиндра 1",
    "cs_cam_deg": "угол поворота распределительного вала от ВМТ газообмена цилиндра 1, °",
    "cs_order": "порядок гармоники частоты вращения распределительного вала", "cs_amplitude": "амплитуда, Н·м",
    "cs_torque_title": "момент привода распределительного вала и его гармоники",
    "cs_stations": "Сечения кулачков", "cs_cylinder": "цилиндр",
    "cs_orders": "Значимые гармоники частоты вращения распределительного вала",
    "cs_names": {
        "lobes": "число кулачков", "camshaft_per_crank_revolution": "оборотов распределительного вала за оборот "
                                                                    "коленчатого вала",
        "peak_torque_Nm": "наибольший момент привода, Н·м", "peak_torque_cam_deg": "где, град ПРВ",
        "lowest_torque_Nm": "наименьший момент привода, Н·м", "mean_torque_Nm": "средний момент привода, Н·м",
        "fluctuating_torque_Nm": "размах момента (наибольший − наименьший), Н·м",
        "rms_fluctuating_torque_Nm": "среднеквадратичное колебание момента, Н·м",
        "power_W": "мощность привода на номинальной частоте, Вт",
        "natural_frequencies_Hz": "собственные частоты крутильных колебаний, Гц",
        "frequency_ratio": "первая собственная частота / наивысшая значимая гармоника на максимальной частоте",
        "largest_twist_cam_deg": "наибольшее отставание от коленчатого вала, град ПРВ",
        "largest_twist_crank_deg": "то же, град ПКВ", "largest_deflection_mm": "наибольший прогиб, мм",
        "drive_force_max_N": "наибольшая окружная сила привода, Н", "drive_force_mean_N": "средняя окружная сила, Н",
        "drive_allowable_force_N": "допустимая сила, Н",
        "drive_windup_cam_deg": "наибольшее растяжение привода, град ПРВ",
        "drive_end_inertia_kg_mm2": "момент инерции приводного конца (звёздочка и вал), кг·мм²",
        "station_positions_mm": "расстояние от приводного конца, мм",
        "station_inertias_kg_mm2": "момент инерции, кг·мм²", "max_twist_cam_deg": "наибольшее отставание, град ПРВ",
        "deflection_mm": "прогиб, мм", "order": "порядок", "order_amplitudes_Nm": "амплитуда, Н·м",
        "resonance_speeds_rpm": "резонансная частота вращения двигателя, мин⁻¹",
        "damping_ratio": "коэффициент демпфирования форм крутильных колебаний",
        "speed_range_rpm": "рабочий диапазон частот вращения, мин⁻¹",
        "timing_fluctuation_allowable_cam_deg": "допустимое колебание фазы кулачка, град ПРВ",
        "largest_timing_fluctuation_cam_deg": "наибольшее колебание фазы кулачка, град ПРВ",
        "largest_timing_fluctuation_speed_rpm": "где, мин⁻¹",
        "largest_timing_fluctuation_cylinder": "у кулачков цилиндра",
        "largest_drive_force_N": "наибольшая сила привода, Н",
        "largest_drive_force_speed_rpm": "где, мин⁻¹",
        "mode": "форма", "natural_frequency_Hz": "собственная частота, Гц", "speed_rpm": "частота вращения, мин⁻¹",
        "timing_fluctuation_cam_deg": "колебание фазы, град ПРВ", "drive_force_N": "сила привода, Н",
    },
    "cs_response": "Крутильные колебания в рабочем диапазоне частот вращения",
    "cs_response_method": "Распределительный вал с приводом — цепь масс и жёсткостей, собственные частоты которой "
                          "приведены выше, коленчатый вал вращается равномерно — отвечает на каждую гармонику "
                          "момента кулачков на каждой частоте рабочего диапазона (момент на каждой частоте — по "
                          "нагрузке клапана: рассчитанной динамикой силе, где она считалась, иначе квазистатической, "
                          "с трением, где рассчитана смазка) методом разложения по собственным формам, каждая форма "
                          "с заданным коэффициентом демпфирования; установившееся отставание каждого сечения "
                          "кулачков, просуммированное по гармоникам, даёт колебание его фазы (разность наибольшего "
                          "и наименьшего отставания за оборот), а жёсткость привода — наибольшую силу привода. "
                          "Резонанс в рабочем диапазоне оценивается по этому отклику: фаза — по смещению звёздочки "
                          "распределительного вала относительно коленчатого, допускаемому изготовителем в "
                          "эксплуатации, сила — по допустимой силе привода",
    "cs_resonances": "Собственные частоты, на которые попадают значимые гармоники в рабочем диапазоне",
    "cs_torsion_title": "крутильные колебания распределительного вала в зависимости от частоты вращения",
    "cs_fluctuation": "колебание фазы кулачков, град ПРВ", "cs_drive_force": "сила привода, Н",
    "cs_allowable": "допустимое", "cs_speed": "частота вращения, мин⁻¹",
})

STAGE_TEXT["en"].update({
    "breathing_chapter": "Breathing: the gas exchange of the cylinder",
    "br_method": "A one-zone cylinder (the mass and energy balance of air and burned or residual gas, their properties "
                 "the NASA polynomials of their species; wall heat by Woschni's correlation) breathes through its "
                 "valves (quasi-steady compressible flow, choked or not, either way, through the effective area "
                 "C<sub>D</sub>A of the valves' lift) and its runners (quasi-one-dimensional gas dynamics by finite "
                 "volumes: HLLC fluxes on a limited linear reconstruction, the ends matched to the waves that reach "
                 "them); cycle follows cycle until the trapped mass, the delivered mass and the pressure at the intake "
                 "valve's closing repeat. The volumetric efficiency is referred to the intake plenum's density; the "
                 "net IMEP is the work of the whole cycle, the gross IMEP that of compression and expansion, the PMEP "
                 "their difference, each over the swept volume; a fired cycle burns the trapped air's fuel on the "
                 "Wiebe schedule of the crank chapter",
    "br_conditions": "The conditions: the converged cycle's figures", "br_curve": "The figures against the speed",
    "br_inputs": "Input data of the breathing", "br_curve_inputs": "The speeds of the curve",
    "br_pv_title": "indicator diagrams: p-V and log p - log V",
    "br_speed_title": "volumetric efficiency (and indicated torque) against the speed",
    "br_pv": "p-V", "br_log_pv": "log p - log V", "br_volume": "cylinder volume V, cm³",
    "br_pressure": "cylinder pressure p, kPa", "br_efficiency": "volumetric efficiency η_v",
    "br_torque": "indicated torque, N·m", "br_condition": "{speed} rpm, {pressure} kPa",
})

STAGE_TEXT["ru"].update({
    "breathing_chapter": "Газообмен цилиндра",
    "br_method": "Цилиндр как один объём (баланс массы и энергии воздуха и продуктов сгорания или остаточных газов, "
                 "свойства которых — полиномы НАСА их компонентов; теплоотдача в стенки по формуле Вошни) наполняется "
                 "и очищается через клапаны (квазистационарное течение сжимаемого газа, критическое и докритическое, в "
                 "обе стороны, через эффективное сечение C<sub>D</sub>A по подъёму клапанов) и через впускной и "
                 "выпускной трубопроводы (квазиодномерная газовая динамика методом конечных объёмов: потоки "
                 "Хартена — Лакса — ван Лира с контактной волной по ограниченной линейной реконструкции, граничные "
                 "условия по приходящим волнам); циклы рассчитываются до повторения массы заряда, поданной массы и давления в момент закрытия впускного клапана. "
                 "Коэффициент наполнения отнесён к плотности во впускном ресивере; индикаторное давление нетто — "
                 "работа всего цикла, брутто — работа сжатия и расширения, давление насосных потерь — их разность, "
                 "все на единицу рабочего объёма; в рабочем цикле сгорает топливо воздуха заряда по закону Вибе "
                 "из расчёта кривошипно-шатунного механизма",
    "br_conditions": "Режимы: показатели установившегося цикла", "br_curve": "Показатели по частоте вращения",
    "br_inputs": "Исходные данные расчёта газообмена", "br_curve_inputs": "Частоты вращения для кривой",
    "br_pv_title": "индикаторные диаграммы в координатах p-V и в логарифмических координатах",
    "br_speed_title": "коэффициент наполнения (и индикаторный крутящий момент) по частоте вращения",
    "br_pv": "p-V", "br_log_pv": "в логарифмических координатах", "br_volume": "объём цилиндра V, см³",
    "br_pressure": "давление в цилиндре p, кПа", "br_efficiency": "коэффициент наполнения η_v",
    "br_torque": "индикаторный крутящий момент, Н·м", "br_condition": "{speed} мин⁻¹, {pressure} кПа",
})

STAGE_TEXT["en"].update({
    "ph_chapter": "Cam phaser of the valve",
    "ph_method": "The phaser turns the valve's camshaft against its drive: every event of the valve moves by the phase, "
                 "an advance positive (the events earlier), in crank degrees (half as many camshaft degrees of a "
                 "four-stroke); phase 0 is the designed timing",
    "ph_dynamics": "The lift law about the camshaft and the camshaft's speed do not change with the phase, so neither "
                   "does the valve train's dynamics at a given speed: its chapter holds over the whole range; the "
                   "valve-to-piston gap does change, and is checked at both ends of the range, and so do the gas "
                   "pressures on the shut valve, whose largest force over the map the spring's preload must hold",
    "ph_torque_camshaft": "The phaser holds the drive torque of the camshaft of the camshaft chapter (the torque at each "
                          "camshaft angle does not change with the phase): its peak and lowest over a revolution and "
                          "its mean",
    "ph_torque_valve": "The phaser holds the drive torque of a camshaft carrying the valve's lobes on every cylinder in "
                       "firing order, computed as in the camshaft chapter (the torque at each camshaft angle does not "
                       "change with the phase): its peak and lowest over a revolution and its mean",
    "ph_table": "The phaser's range and the torque it holds", "ph_checks": "the cam phaser",
    "ph_events": "The valve's events at the ends of the phaser's range and at phase 0",
    "ph_map_method": "The breathing chapter's model at every phase of the map and every condition of the breathing "
                     "(at phase 0 the breathing chapter's own result); the best phase maximises the",
    "ph_objective": {"torque": "indicated torque", "volumetric_efficiency": "volumetric efficiency"},
    "ph_search": "the map's best phase refined by a bounded Brent search (scipy.optimize.minimize_scalar) between its "
                 "neighbours of the map, to {tolerance} crank deg",
    "ph_map": "The objective over the map: phase (rows) and condition (columns)",
    "ph_best_table": "The best phase at each condition",
    "ph_figure": "phaser map and best phase against the speed",
    "ph_title": "cam phaser of the valve {valve}", "ph_map_title": "the objective against the phase",
    "ph_best_title": "the best phase against the speed", "ph_advance": "phase (advance), crank deg",
    "ph_best": "best phase (advance), crank deg", "ph_pressure": "intake plenum {pressure} kPa",
    "ph_opening_method": "An exhaust valve opens against the cylinder's pressure, which the phase moves: at each end of "
                         "the range and at phase 0, the cylinder's and the port's pressure where the valve leaves its "
                         "seat are read from the breathing's cycles at that phase (the condition where they differ "
                         "most), and the strength chapter's cam load is found again with the gas force on the head "
                         "F = A (p_c - p_p) they give in place of the one of [gas]",
    "ph_opening": "The exhaust valve's opening and the cam's load at the ends of the range",
    "ph_names": {
        "advance_range_crank_deg": "phaser's range, advance positive, crank deg",
        "advance_range_cam_deg": "the same in camshaft degrees",
        "holding_torque_peak_Nm": "torque the phaser holds: peak, N·m",
        "holding_torque_lowest_Nm": "torque the phaser holds: lowest, N·m",
        "holding_torque_mean_Nm": "torque the phaser holds: mean, N·m",
        "gas_load_max_N": "largest gas force on the shut valve over the map, N",
        "gas_load_max_advance_crank_deg": "at the phase, crank deg",
        "advance_crank_deg": "phase (advance), crank deg",
        "valve_opens_crank_deg": "valve opens, crank deg from the gas-exchange TDC",
        "valve_closes_crank_deg": "valve closes, crank deg from the gas-exchange TDC",
        "min_piston_clearance_mm": "smallest valve-to-piston gap, mm",
        "min_piston_clearance_crank_deg": "where, crank deg",
        "speed_rpm": "speed, rpm", "intake_pressure_kPa": "intake plenum pressure, kPa",
        "volumetric_efficiency": "volumetric efficiency", "residual_gas_fraction": "residual gas fraction",
        "pmep_kPa": "PMEP, kPa", "torque_Nm": "indicated torque, N·m", "gain_percent": "gain over phase 0, %",
        "evaluations": "cycles of the search",
        "cylinder_pressure_at_opening_MPa": "cylinder pressure at the opening, MPa",
        "port_pressure_at_opening_MPa": "exhaust port pressure there, MPa",
        "gas_force_at_opening_N": "gas force on the valve head as it opens, N",
        "cam_force_max_N": "largest cam force, N", "cam_contact_stress_max_MPa": "largest cam contact stress, MPa",
    },
})

STAGE_TEXT["ru"].update({
    "ph_chapter": "Фазовращатель распределительного вала клапана",
    "ph_method": "Фазовращатель поворачивает распределительный вал клапана относительно его привода: все фазы клапана "
                 "смещаются на угол фазирования, опережение положительно (фазы раньше), в градусах поворота "
                 "коленчатого вала (вдвое меньше градусов поворота распределительного вала четырёхтактного двигателя); "
                 "нулевой угол — расчётные фазы",
    "ph_dynamics": "Закон подъёма по углу распределительного вала и его частота вращения от угла фазирования не "
                   "зависят, поэтому не зависит и динамика привода клапана при данной частоте вращения: её расчёт "
                   "справедлив во всём диапазоне; зазор клапан-поршень меняется и проверяется на обоих концах "
                   "диапазона, меняются и давления газов на закрытый клапан, наибольшую силу которых по карте должна "
                   "удерживать предварительная сила пружины",
    "ph_torque_camshaft": "Фазовращатель удерживает момент привода распределительного вала из его главы (момент при "
                          "каждом угле поворота вала от угла фазирования не зависит): наибольший и наименьший за "
                          "оборот и средний",
    "ph_torque_valve": "Фазовращатель удерживает момент привода распределительного вала с кулачками клапана на всех "
                       "цилиндрах в порядке работы, рассчитанный как в главе распределительного вала (момент при "
                       "каждом угле поворота вала от угла фазирования не зависит): наибольший и наименьший за оборот "
                       "и средний",
    "ph_table": "Диапазон фазовращателя и удерживаемый им момент", "ph_checks": "фазовращатель",
    "ph_events": "Фазы клапана на концах диапазона фазовращателя и при нулевом угле",
    "ph_map_method": "Модель главы газообмена при каждом угле фазирования карты и на каждом режиме газообмена (при "
                     "нулевом угле — результат самой главы газообмена); наилучший угол даёт наибольший",
    "ph_objective": {"torque": "индикаторный крутящий момент", "volumetric_efficiency": "коэффициент наполнения"},
    "ph_search": "наилучшая точка карты уточняется методом Брента на отрезке между соседними углами карты с "
                 "точностью {tolerance} град ПКВ",
    "ph_map": "Целевой показатель по карте: угол фазирования (строки) и режим (столбцы)",
    "ph_best_table": "Наилучший угол фазирования на каждом режиме",
    "ph_figure": "карта фазовращателя и наилучший угол по частоте вращения",
    "ph_title": "фазовращатель клапана {valve}", "ph_map_title": "целевой показатель по углу фазирования",
    "ph_best_title": "наилучший угол по частоте вращения", "ph_advance": "угол фазирования (опережение), град ПКВ",
    "ph_best": "наилучший угол (опережение), град ПКВ", "ph_pressure": "во впускном ресивере {pressure} кПа",
    "ph_opening_method": "Выпускной клапан открывается против давления в цилиндре, которое зависит от угла "
                         "фазирования: на концах диапазона и при нулевом угле давление в цилиндре и в выпускном "
                         "канале в момент отрыва клапана от седла берётся из циклов газообмена при этом угле (на "
                         "режиме с наибольшей разностью), и нагрузка кулачка по методу главы прочности определяется "
                         "заново с силой давления газов на тарелку F = A (p_c - p_p) вместо заданной в разделе "
                         "исходных давлений",
    "ph_opening": "Открытие выпускного клапана и нагрузка кулачка на концах диапазона",
    "ph_names": {
        "advance_range_crank_deg": "диапазон фазовращателя, опережение положительно, град ПКВ",
        "advance_range_cam_deg": "то же в градусах поворота распределительного вала",
        "holding_torque_peak_Nm": "момент, удерживаемый фазовращателем: наибольший, Н·м",
        "holding_torque_lowest_Nm": "момент, удерживаемый фазовращателем: наименьший, Н·м",
        "holding_torque_mean_Nm": "момент, удерживаемый фазовращателем: средний, Н·м",
        "gas_load_max_N": "наибольшая сила давления газов на закрытый клапан по карте, Н",
        "gas_load_max_advance_crank_deg": "при угле фазирования, град ПКВ",
        "advance_crank_deg": "угол фазирования (опережение), град ПКВ",
        "valve_opens_crank_deg": "открытие клапана, град ПКВ от ВМТ газообмена",
        "valve_closes_crank_deg": "закрытие клапана, град ПКВ от ВМТ газообмена",
        "min_piston_clearance_mm": "наименьший зазор клапан-поршень, мм",
        "min_piston_clearance_crank_deg": "где, град ПКВ",
        "speed_rpm": "частота вращения, мин⁻¹", "intake_pressure_kPa": "давление во впускном ресивере, кПа",
        "volumetric_efficiency": "коэффициент наполнения", "residual_gas_fraction": "коэффициент остаточных газов",
        "pmep_kPa": "давление насосных потерь, кПа", "torque_Nm": "индикаторный крутящий момент, Н·м",
        "gain_percent": "прирост к нулевому углу, %", "evaluations": "циклов поиска",
        "cylinder_pressure_at_opening_MPa": "давление в цилиндре при открытии, МПа",
        "port_pressure_at_opening_MPa": "давление в выпускном канале при этом, МПа",
        "gas_force_at_opening_N": "сила давления газов на тарелку при открытии, Н",
        "cam_force_max_N": "наибольшая сила на кулачке, Н",
        "cam_contact_stress_max_MPa": "наибольшее контактное напряжение кулачка, МПа",
    },
})
