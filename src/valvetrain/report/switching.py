"""The report's chapter of a switching roller finger follower (:mod:`valvetrain.design.switching`): its figures, the
unlatched arm's smallest force on its cam against the speed (deactivation), both modes' events, time-area and
breathing (two-step) and its checks, in the words of the catalogue's ``[switching]`` section
(:mod:`valvetrain.locale`)."""

from ..design.results import shown
from ..locale import catalogue

ROWS = ("mode", "latched_lift", "unlatched_lift", "arm_swing", "over_speed", "reserve", "required_torque", "preload",
        "rate", "max_torque", "coils", "stress", "stress_share", "frequency", "frequency_orders", "jump_speed",
        "jump_speed_static", "sweep_top", "arm_force", "valve_force", "valve_preload", "cam_force", "latch_force",
        "latch_stress", "air_work", "air_loss", "air_peak", "air_revolutions")
"""The rows of the chapter's table (fields of :class:`~valvetrain.design.switching.SwitchingRecord`)."""

TWO_STEP_ROWS = ("latched_opens", "latched_closes", "unlatched_opens", "unlatched_closes", "time_area_latched",
                 "time_area_unlatched", "low_rho_min", "valve_jump")
"""The rows of a two-step finger's table of modes (fields of :class:`~valvetrain.design.switching.TwoStepRecord`)."""

LATCH_ROWS = ("window", "window_time", "engage", "back", "share")
"""The rows of the latch's switching table (fields of :class:`~valvetrain.design.switching.LatchSwitching`)."""

BREATH_COLUMNS = ("speed", "trapped_mass", "volumetric_efficiency", "residual_gas_fraction", "pmep", "imep")
"""The columns of a two-step finger's breathing table after the mode (fields of
:class:`~valvetrain.design.two_step.ModeBreath`)."""

SOURCES = ("Hendriksma, Kunz, Greene (2007)", "Norton (2009)", "Wahl (1944)", "Johnson (1985)", "Woschni (1967)")
"""The works the chapter's method cites."""


def switching_chapters(results, checks, lang) -> list[dict]:
    """One chapter a valve with a [switching] section: ``name``, the catalogue's words ``words``, the table's
    ``rows`` (key, display value), the sweep's ``speeds`` (rows of speed and smallest force; none two-step), a
    two-step finger's ``two_step`` rows (key, display value; None deactivated), its ``breathing`` (the columns' keys
    and rows of the mode's word and the values; None without [breathing]), the latch's switching ``latch`` (key,
    display value; None without the latch's oil and spring) and ``checks``."""
    words = catalogue(lang)["switching"]
    out = []
    for name, s in results.switching.items():
        f = s.figures
        rows = shown(f, *(k for k in ROWS if getattr(f, k) is not None))
        speeds = list(zip(dict(shown(f, "speeds"))["sweep_speeds_rpm"], dict(shown(f, "min_force"))[
            "arm_contact_force_min_N"], strict=True))
        modes = f.two_step
        breath = None
        if modes is not None and modes.breathing:
            keys = [k for k, _ in shown(modes.breathing[0], *BREATH_COLUMNS)]
            breath = {"columns": keys, "rows": [(words[b.mode], [v for _, v in shown(b, *BREATH_COLUMNS)])
                                                for b in modes.breathing]}
        out.append({"name": name, "words": words, "rows": rows, "speeds": speeds, "sources": SOURCES,
                    "two_step": None if modes is None else shown(modes, *TWO_STEP_ROWS), "breathing": breath,
                    "latch": None if f.latch is None else shown(f.latch, *LATCH_ROWS),
                    "checks": checks[name].get("switching", [])})
    return out
