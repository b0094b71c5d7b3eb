"""Compiled fixed-step integrator of a lumped valve-train network, all speeds of a sweep at once.

The network (see :class:`~valvetrain.dynamics.models.Network`) is a set of masses on one
axis (valve-side coordinates, positive in the opening direction) joined by elements:
bilateral spring-dampers with a preload (the valve-spring coils) and unilateral contacts
with a gap (cam-follower contact with the lash, joints of the drive, the valve seat).
Node index ``GROUND`` (-1) is the fixed head, ``CAM`` (-2) the cam excitation.

Scheme
------
Classical fourth-order Runge-Kutta with a step fixed in **camshaft angle**.  The cam
excitation is sampled once on a half-step grid of camshaft angle shared by every speed; at
camshaft speed omega the time step is dtheta / omega, so each speed walks the same arrays.
RK4 is chosen over a symplectic or Newmark scheme because the contact laws are nonlinear and
switch (a Newmark step would need an iteration at every switch) and because its error
constant is small enough for the 1 um lift accuracy at 0.1 cam deg; its stability bound on
an undamped mode is omega_n dt < 2.83.  The caller (:mod:`.sweep`) divides the angle step
by a power of two per speed so that |lambda| dt <= 1 for the fastest eigenvalue of the
linearised network; there RK4 damps an undamped mode by under 1 % a step, a mild numerical
dissipation of modes far above the cam harmonics (references: Hairer, Nørsett and Wanner (1993), section II.1 and IV.2 for the
stability function 1 + z + z^2/2 + z^3/6 + z^4/24).

Every speed is an independent problem: the loop over speeds runs in parallel (``prange``),
the kernels are cached on disk (``cache=True``) so a second process pays no compile time.
"""

import numpy as np
from numba import njit, prange

GROUND = -1
"""Node index of the fixed head (seat, spring seat)."""

CAM = -2
"""Node index of the cam excitation: displacement u = k h(theta), velocity omega k h'(theta)."""


@njit(cache=True)
def _forces(x, v, u, du, inv_mass, a, b, k, d, gap, pre, uni, acc, force):
    """Element forces (compression positive, +f on node b, -f on node a) and node accelerations."""
    acc[:] = 0.0
    for e in range(a.size):
        ia, ib = a[e], b[e]
        if ia == CAM:
            xa, va = u, du
        elif ia == GROUND:
            xa, va = 0.0, 0.0
        else:
            xa, va = x[ia], v[ia]
        if ib == GROUND:
            xb, vb = 0.0, 0.0
        else:
            xb, vb = x[ib], v[ib]
        delta = xa - xb - gap[e]
        if uni[e]:
            f = 0.0
            if delta > 0.0:
                f = k[e] * delta + d[e] * (va - vb)
                if f < 0.0:
                    f = 0.0
        else:
            f = pre[e] + k[e] * delta + d[e] * (va - vb)
        force[e] = f
        if ib >= 0:
            acc[ib] += f * inv_mass[ib]
        if ia >= 0:
            acc[ia] -= f * inv_mass[ia]


@njit(cache=True)
def _one_speed(omega, n_sub, dtheta, cam_u, cam_du, per_step, steps_per_rev, revolutions, inv_mass, x_init,
               a, b, k, d, gap, pre, uni, rec_nodes, rec_elems, clash_gap, surge_ref, surge_w,
               out_x, out_v, out_f, out_clash, out_surge):
    n = inv_mass.size
    ne = a.size
    x = x_init.copy()
    v = np.zeros(n)
    xs, vs = np.empty(n), np.empty(n)
    k1x, k1v, k2x, k2v = np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    k3x, k3v, k4x, k4v = np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    force, scratch = np.empty(ne), np.empty(ne)
    dt = dtheta / (n_sub * omega)
    half = per_step // (2 * n_sub)          # half-grid indices per half step
    period = cam_u.size
    total = revolutions * steps_per_rev * n_sub
    first_recorded = (revolutions - 1) * steps_per_rev * n_sub
    for e in range(ne):
        out_clash[e] = np.inf
    for i in range(n):
        out_surge[i] = 0.0
    j0 = 0
    countdown = 0                           # sub-steps to the next recorded angle
    for step in range(total):
        j1 = j0 + half
        j2 = j1 + half
        if j2 == period:
            j2 = 0
        u0, u1, u2 = cam_u[j0], cam_u[j1], cam_u[j2]
        w0, w1, w2 = omega * cam_du[j0], omega * cam_du[j1], omega * cam_du[j2]
        _forces(x, v, u0, w0, inv_mass, a, b, k, d, gap, pre, uni, k1v, force)
        if step >= first_recorded:
            if countdown == 0:
                r = (step - first_recorded) // n_sub
                countdown = n_sub
                for q in range(rec_nodes.size):
                    out_x[q, r] = x[rec_nodes[q]]
                    out_v[q, r] = v[rec_nodes[q]]
                for q in range(rec_elems.size):
                    out_f[q, r] = force[rec_elems[q]]
                for e in range(ne):
                    if clash_gap[e] > 0.0:
                        xa = x[a[e]] if a[e] >= 0 else 0.0
                        xb = x[b[e]] if b[e] >= 0 else 0.0
                        margin = clash_gap[e] - (xa - xb)
                        if margin < out_clash[e]:
                            out_clash[e] = margin
                for i in range(n):
                    if surge_w[i] > 0.0:
                        dev = abs(x[i] - surge_w[i] * x[surge_ref])
                        if dev > out_surge[i]:
                            out_surge[i] = dev
            countdown -= 1
        for i in range(n):
            k1x[i] = v[i]
            xs[i] = x[i] + 0.5 * dt * k1x[i]
            vs[i] = v[i] + 0.5 * dt * k1v[i]
        _forces(xs, vs, u1, w1, inv_mass, a, b, k, d, gap, pre, uni, k2v, scratch)
        for i in range(n):
            k2x[i] = vs[i]
            xs[i] = x[i] + 0.5 * dt * k2x[i]
            vs[i] = v[i] + 0.5 * dt * k2v[i]
        _forces(xs, vs, u1, w1, inv_mass, a, b, k, d, gap, pre, uni, k3v, scratch)
        for i in range(n):
            k3x[i] = vs[i]
            xs[i] = x[i] + dt * k3x[i]
            vs[i] = v[i] + dt * k3v[i]
        _forces(xs, vs, u2, w2, inv_mass, a, b, k, d, gap, pre, uni, k4v, scratch)
        for i in range(n):
            k4x[i] = vs[i]
            x[i] += dt / 6.0 * (k1x[i] + 2.0 * k2x[i] + 2.0 * k3x[i] + k4x[i])
            v[i] += dt / 6.0 * (k1v[i] + 2.0 * k2v[i] + 2.0 * k3v[i] + k4v[i])
        j0 = j2


@njit(cache=True, parallel=True)
def integrate_network(omegas, n_sub, dtheta, cam_u, cam_du, per_step, steps_per_rev, revolutions, inv_mass, x_init,
                      a, b, k, d, gap, pre, uni, rec_nodes, rec_elems, clash_gap, surge_ref, surge_w,
                      out_x, out_v, out_f, out_clash, out_surge):
    """Integrate the network at every camshaft speed; fill the output arrays of the last revolution.

    Parameters
    ----------
    omegas : ndarray (S,)
        Camshaft speeds [rad/s].
    n_sub : ndarray (S,) of int
        Sub-steps per angle step dtheta for each speed (a power of two dividing ``per_step // 2``).
    dtheta : float
        Recording step of camshaft angle [rad].
    cam_u, cam_du : ndarray (L,)
        Cam displacement at the valve k h [m] and its derivative k dh/dtheta [m/rad] on one revolution
        sampled every dtheta / per_step (periodic; L = steps_per_rev * per_step).
    per_step : int
        Excitation samples per recording step (2 x the largest sub-step count).
    steps_per_rev : int
        Recording steps per revolution, 2 pi / dtheta.
    revolutions : int
        Camshaft revolutions integrated; the last one is recorded.
    inv_mass, x_init : ndarray (n,)
        Inverse node masses [1/kg] and initial positions [m] (the train starts at rest).
    a, b, k, d, gap, pre, uni : ndarray (E,)
        Element end nodes, stiffness [N/m], damping [N s/m], gap [m], preload [N], unilateral flag.
    rec_nodes, rec_elems : ndarray of int
        Nodes whose position and velocity, and elements whose force, are recorded.
    clash_gap : ndarray (E,)
        Closing distance of a coil element to coil contact [m] (0: not monitored).
    surge_ref : int
        Node of the valve; ``surge_w`` (n,) the quasi-static share of its motion for each coil node (0: none).
    out_x, out_v : ndarray (S, len(rec_nodes), steps_per_rev)
    out_f : ndarray (S, len(rec_elems), steps_per_rev)
    out_clash : ndarray (S, E)
        Smallest coil-contact margin [m] over the last revolution (inf where not monitored).
    out_surge : ndarray (S, n)
        Largest deviation of each coil node from its quasi-static share of the valve motion [m].
    """
    for s in prange(omegas.size):
        _one_speed(omegas[s], n_sub[s], dtheta, cam_u, cam_du, per_step, steps_per_rev, revolutions, inv_mass,
                   x_init, a, b, k, d, gap, pre, uni, rec_nodes, rec_elems, clash_gap, surge_ref, surge_w,
                   out_x[s], out_v[s], out_f[s], out_clash[s], out_surge[s])
