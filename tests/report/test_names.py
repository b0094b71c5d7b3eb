"""Names of the report (report/names.py): the label of a results key with its symbol and unit, the text of a value,
in English and Russian."""

from valvetrain.report.names import label, value_text


def test_labels_and_values():
    assert label("tappet_acceleration_m_s2", "ru") == "tappet acceleration m s2"  # no name: shown as the key
    assert label("lift.tappet_acceleration_m_s2", "ru") == "ускорение толкателя a_T, м/с²"
    assert label("lift.tappet_acceleration_m_s2", "en") == "tappet acceleration a_T, m/s²"
    assert label("spring.count", "ru") == "число пружин" and label("count", "ru") == "число клапанов i"
    assert label("crank.max_velocity_crank_deg", "ru") == "угол ПКВ наибольшей скорости поршня, град"
    assert label("phi1_deg", "ru").endswith("град ПРВ") and label("opens_deg", "en").endswith("crank deg")
    assert value_text("Phi1 opening", "ru") == "Φ1, подъём" and value_text("pushrod", "en") == "pushrod"
