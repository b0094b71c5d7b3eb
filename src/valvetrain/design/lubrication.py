"""The lubrication stage: oil film, regime, friction and flash temperature of the cam contact over the speed range,
and the camshaft drive torque with the friction (Dowson and Higginson (1977); Hamrock, Schmid and Jacobson (2004);
Blok (1937))."""

from dataclasses import dataclass

import numpy as np

from .. import tribology
from ..bibliography import cite
from ..checks import Check, check
from ..locale import NoteText, cited, note
from ..errors import InputError
from ..numerics import first_largest
from ..specification.messages import Problem, SpecError, said
from ..strength import hertz_half_width
from ..units import to_display
from .drive_strength import contact_loads, event_load_maps
from .results import quantity

STEEL_EFFUSIVITY = float(np.sqrt(46.6 * 7850.0 * 460.0))
"""Thermal effusivity sqrt(k rho c) of a steel cam and follower [W s^0.5 / (m^2 K)]: k = 46.6 W/(m K), rho = 7850
kg/m^3, c = 460 J/(kg K), a plain carbon steel."""

SOURCES = (f"{cite('dowson1977')}; {cite('hamrock2004')}; {cite('blok1937')}; {cite('dowson1986')}")
"""The works of the chapter, for the report."""


@dataclass(frozen=True)
class LubricationPerSpeed:
    """The cam contact at each engine speed of the strength checks (SI)."""

    speed: tuple[float, ...] = quantity("speed_rpm", "rpm", "engine speed")
    load: tuple[str, ...] = quantity("load", label="the cam force at that speed: quasi-static or dynamic")
    min_film: tuple[float, ...] = quantity("min_film_um", "um", "smallest minimum film thickness of the loaded event")
    min_lambda: tuple[float, ...] = quantity("min_film_parameter", label="smallest film parameter lambda")
    min_lambda_angle: tuple[float, ...] = quantity("min_film_parameter_cam_deg", "cam deg", "where, from the nose")
    boundary: tuple[float, ...] = quantity("boundary_cam_deg", "cam deg", "loaded cam angle in boundary "
                                           "lubrication (lambda < 1)")
    mixed: tuple[float, ...] = quantity("mixed_cam_deg", "cam deg", "in mixed lubrication (1 <= lambda < 3)")
    full: tuple[float, ...] = quantity("full_film_cam_deg", "cam deg", "in full film (lambda >= 3)")
    max_friction_force: tuple[float, ...] = quantity("max_friction_force_N", "N", "largest friction force along the "
                                                     "contact (mu F, a roller's rolling resistance included)")
    max_friction_torque: tuple[float, ...] = quantity("max_friction_torque_N_m", "N m", "largest camshaft torque "
                                                      "of the friction")
    mean_friction_torque: tuple[float, ...] = quantity("mean_friction_torque_N_m", "N m", "its mean over a "
                                                       "camshaft revolution")
    friction_power: tuple[float, ...] = quantity("friction_power_W", "W", "mean power of the friction")
    max_flash: tuple[float, ...] = quantity("max_flash_temperature_K", "K", "largest flash temperature rise (Blok)")
    max_contact_temperature: tuple[float, ...] = quantity("max_contact_temperature_C", "degC", "oil temperature + "
                                                          "the largest flash temperature rise")
    max_drive_torque: tuple[float, ...] = quantity("max_drive_torque_N_m", "N m", "largest camshaft drive torque "
                                                   "with friction, F dh/dtheta + T_f")
    mean_drive_torque: tuple[float, ...] = quantity("mean_drive_torque_N_m", "N m", "its mean over a revolution")


@dataclass(frozen=True)
class LubricationResult:
    """The oil film and the friction of the cam contact over the speed range (SI)."""

    follower: str = quantity("follower", label="flat or roller follower")
    reduced_modulus: float = quantity("reduced_modulus_GPa", "GPa", "E' = E_m / (1 - 0.3^2)")
    composite_roughness: float = quantity("composite_roughness_um", "um", "sqrt(Rq_cam^2 + Rq_follower^2)")
    min_lambda: float = quantity("min_film_parameter", label="smallest film parameter over the speeds and the loaded "
                                 "event")
    min_lambda_speed: float = quantity("min_film_parameter_speed_rpm", "rpm", "at which engine speed")
    min_lambda_angle: float = quantity("min_film_parameter_cam_deg", "cam deg", "where, from the nose")
    min_film: float = quantity("min_film_um", "um", "smallest minimum film thickness")
    max_contact_temperature: float = quantity("max_contact_temperature_C", "degC", "largest contact temperature, "
                                              "oil + flash")
    max_contact_temperature_speed: float = quantity("max_contact_temperature_speed_rpm", "rpm",
                                                    "at which engine speed")
    rated_friction_power: float = quantity("rated_friction_power_W", "W", "mean friction power at the rated speed")
    rated_mean_friction_torque: float = quantity("rated_mean_friction_torque_N_m", "N m", "mean camshaft torque of "
                                                 "the friction at the rated speed")
    rated_max_drive_torque: float = quantity("rated_max_drive_torque_N_m", "N m", "largest drive torque with "
                                             "friction at the rated speed")
    zero_entrainment: tuple[float, ...] = quantity(
        "zero_entrainment_cam_deg", "cam deg", "cam angles where the entraining velocity changes sign (no steady film "
        "there: a flat follower's nose; none for a roller)")
    per_speed: LubricationPerSpeed = quantity("per_speed", label="the cam contact at each speed")


class UndercutError(InputError):
    """The cam profile has no line contact with its follower somewhere."""


def _weights(theta) -> np.ndarray:
    """Trapezoid weights of a sorted angle grid [rad]."""
    edges = np.concatenate([[theta[0]], (theta[1:] + theta[:-1]) / 2.0, [theta[-1]]])
    return np.diff(edges)


def _zero_entrainment(cam, theta) -> tuple[float, ...]:
    """Camshaft angles [rad] where the entraining velocity changes sign (a sliding face's nose; none for a roller)."""
    follower, heel = cam.follower_model, cam.heel_radius
    h, dh, d2h = cam.law.derivatives(theta)[:3]
    u_cam, u_follower = follower.surface_velocities(1.0, heel, h, dh, d2h, follower.curvature(heel, h, dh, d2h))
    e = np.sign(u_cam + u_follower)
    return tuple(float(t) for t in theta[1:][e[1:] * e[:-1] < 0.0])


def contact_map(lub, cam, width, modulus, theta, force, omega) -> dict[str, np.ndarray]:
    """Film, regime, friction and temperature of the cam contact over speeds x camshaft angles.

    Parameters
    ----------
    lub : SI view of ``[valves.NAME.lubrication]``.
    cam : CamResult
    width : float
        Cam width [m].
    modulus : float
        Effective contact modulus E_m [Pa].
    theta : ndarray (n,)
        Camshaft angles [rad from the nose].
    force : ndarray (S, n)
        Normal force at the cam [N]; where it is not positive there is no contact (no values there).
    omega : ndarray (S, 1)
        Camshaft speeds [rad/s].

    Returns
    -------
    dict of ndarray (S, n)
        ``film`` [m], ``lam``, ``friction_force`` [N], ``friction_torque`` [N m], ``flash`` [K], ``drive_torque``
        [N m] (NaN where there is no contact, except the torques, 0 there) and ``entraining`` [m/s].

    Notes
    -----
    The frictionless drive torque is the power of the force along the law's lift over the camshaft speed, the normal
    force over the follower's :meth:`~valvetrain.followers.Follower.force_ratio` times dh/dtheta (a finger's law is
    the valve's: F_valve dv/dtheta).
    """
    follower, heel = cam.follower_model, cam.heel_radius
    h, dh, d2h = cam.law.derivatives(theta)[:3]
    rho = follower.curvature(heel, h, dh, d2h)
    if not np.all(follower.line_contact(rho)):
        raise UndercutError("the cam profile is undercut (no line contact)")
    u_cam, u_follower = follower.surface_velocities(omega, heel, h, dh, d2h, rho)
    u_follower, rolling_friction, rolling = follower.rolling_losses(u_follower, lub.roller_slip,
                                                                    lub.roller_rolling_friction)
    curvature = follower.contact_curvature(rho)
    loaded = force > 0.0
    load = np.where(loaded, force, 1.0)
    reduced = tribology.reduced_modulus(modulus)
    entraining = np.broadcast_to((u_cam + u_follower) / 2.0, force.shape)
    film = tribology.film_thickness_line(entraining, 1.0 / curvature, load / width, lub.oil_viscosity,
                                         lub.pressure_viscosity, reduced)
    lam = tribology.film_parameter(film, lub.cam_roughness, lub.follower_roughness)
    mu = tribology.friction_coefficient(lam, lub.boundary_friction, lub.full_film_friction)
    sliding = u_cam - u_follower
    half = hertz_half_width(load, width, curvature, modulus)
    flash = tribology.flash_temperature(mu, load / width, u_cam, u_follower, half, STEEL_EFFUSIVITY, STEEL_EFFUSIVITY)
    torque = np.where(loaded, tribology.friction_torque(load, mu, sliding, rolling_friction, rolling, omega), 0.0)
    friction_force = np.where(loaded, load * (mu * (np.abs(sliding) > 0.0) + rolling_friction), np.nan)
    none = np.where(loaded, 1.0, np.nan)
    return {"film": film * none, "lam": lam * none, "friction_force": friction_force, "friction_torque": torque,
            "flash": flash * none,
            "drive_torque": np.where(loaded, force, 0.0) * dh / follower.force_ratio(heel, h, dh) + torque,
            "entraining": entraining}


def lubrication_stage(lub, valve, engine, cam, drive, dynamics=None,
                      name="valve") -> tuple[LubricationResult, list[Check]]:
    """The lubrication of the cam contact from the lowest speed to the over-speed, with its checks.

    Parameters
    ----------
    lub : SI view of ``[valves.NAME.lubrication]``.
    valve, engine : SI views of the valve and the engine.
    cam : CamResult
    drive : DriveResult
        The drive stage (reduced mass, chosen spring line).
    dynamics : DynamicsResult, optional
        Its simulated contact force replaces the quasi-static one at its speeds (as in the strength stage).
    name : str
        The valve's name (the messages' keys).

    Returns
    -------
    (LubricationResult, list of Check)

    Raises
    ------
    SpecError
        On an undercut profile (no line contact); ``parts.cam_width_mm`` (the load per unit width), which the
        specification's validation requires with the section, is taken as given.
    """
    at = f"valves.{name}"
    maps = contact_loads(cam, event_load_maps(valve, engine, cam, drive, dynamics)[1])
    to_cam = cam.cam_speed / engine.rated_speed
    rows, worst = [], None
    for m in maps:
        omega, theta, weights = m.speeds[:, None] * to_cam, m.theta, _weights(m.theta)
        try:
            c = contact_map(lub, cam, valve.parts.cam_width, valve.parts.contact_modulus, theta, m.force, omega)
        except UndercutError as exc:
            raise SpecError([Problem(f"{at}.lubrication", said(exc))]) from None
        for i, speed in enumerate(m.speeds):
            lam = c["lam"][i]
            if not np.any(np.isfinite(lam)):
                continue
            j = int(first_largest(np.where(np.isfinite(lam), -lam, np.nan)))   # a symmetric cam's tie: the first
            band = tribology.regime(np.where(np.isfinite(lam), lam, -1.0))
            shares = [float(weights[np.isfinite(lam) & (band == k)].sum()) for k in range(3)]
            mean_t = float(np.sum(c["friction_torque"][i] * weights) / (2.0 * np.pi))
            flash = float(np.nanmax(c["flash"][i]))
            rows.append((float(speed), m.kind, float(np.nanmin(c["film"][i])), float(lam[j]), float(theta[j]),
                         *shares, float(np.nanmax(c["friction_force"][i])), float(c["friction_torque"][i].max()),
                         mean_t, mean_t * float(omega[i, 0]), flash, lub.oil_temperature_C + flash,
                         float(c["drive_torque"][i].max()),
                         float(np.sum(c["drive_torque"][i] * weights) / (2.0 * np.pi))))
            if worst is None or lam[j] < worst[0]:
                worst = (float(lam[j]), float(speed), float(theta[j]))
    if worst is None:
        raise SpecError([Problem(f"{at}.lubrication", NoteText(note("spec.never_touches")))])
    rows.sort(key=lambda row: row[0])
    per = LubricationPerSpeed(*(tuple(col) for col in zip(*rows, strict=True)))
    hot = int(np.argmax(per.max_contact_temperature))
    rated = int(np.argmin(np.abs(np.asarray(per.speed) - engine.rated_speed)))
    result = LubricationResult(
        cam.follower, tribology.reduced_modulus(valve.parts.contact_modulus),
        float(np.hypot(lub.cam_roughness, lub.follower_roughness)), worst[0], worst[1], worst[2], min(per.min_film),
        per.max_contact_temperature[hot], per.speed[hot], per.friction_power[rated], per.mean_friction_torque[rated],
        per.max_drive_torque[rated],
        _zero_entrainment(cam, maps[0].theta), per)
    where = (note("lubrication.worst_at", speed_rpm=to_display(worst[1], "rpm"),
                  cam_deg=to_display(worst[2], "cam deg"))
             + (note("lubrication.zero_entrainment") if result.zero_entrainment else ()))
    found = [check("lubrication.film_parameter", worst[0],
                   low=lub.min_film_parameter,
                   source=cited(note("source.boundary_lubrication", work=cite("hamrock2004", "ch. 1")),
                                f"{at}.lubrication.min_film_parameter"), severity="warning", note=where),
               check("lubrication.contact_temperature",
                     result.max_contact_temperature, high=lub.max_contact_temperature_C, unit="degC",
                     source=cited(note("source.scuffing", work=cite("blok1937")),
                                  f"{at}.lubrication.max_contact_temperature_C"), severity="failure",
                     note=note("lubrication.hottest_at", speed_rpm=to_display(per.speed[hot], 'rpm')))]
    return result, found
