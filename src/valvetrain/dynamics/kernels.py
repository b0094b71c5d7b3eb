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

Every speed is an independent problem.  Speeds with the same sub-step count walk the same
excitation samples at the same steps, so they are integrated in lockstep as a block
(:func:`blocks`): the state is stored (node, speed), and each element's force is computed for all
speeds of the block in one branch-free loop that the compiler turns into SIMD instructions (one
speed per lane, each lane doing exactly the scalar arithmetic, so the results do not depend on the
blocking).  A train of one node (the one-mass train) has a kernel of its own, :func:`integrate_node`, whose state
is one array per quantity over the block's speeds: the same records to the bit, two to three times as fast; it also
holds a valve at rest on its seat while the base circle passes (its records then within 2 pm of the integration's,
:data:`~.sweep.REST_AMPLITUDE`), which takes a third to a half off the time of a block whose valves all come to rest.
The blocks run on threads of the caller (the kernels release the interpreter lock,
``nogil=True``), the costliest first; one compiled signature serves every train, and the kernels are
cached on disk (``cache=True``) so a second process pays no compile time.  The first compile is kept short: one
RK4 body (:func:`_rk4`) serves the lockstep step and the split step, the helpers are compiled without the wrappers
a call from Python would need, and arrays are copied and cleared by explicit loops (numba's slice assignment
compiles a generic broadcasting routine, a third of the former compile time).  The helpers a step calls (:func:`_rk4`,
:func:`_forces`, :func:`_record`) are inlined into the kernel by numba (``inline='always'``): called, they cost a
block of one speed 0.69 us a step of the 0.83 it took on the one-mass train (a block of 64 speeds about the same
3.8 us either way), 0.29 inlined; the refinement's and a tolerance sample's sweeps of one or two speeds run twice as
fast, and the first compile takes about 13 instead of 10.5 s of processor time (measured under load).

A speed is integrated until it repeats: after each camshaft revolution its state is compared with
the state at the start of that revolution, and a block stops once all its speeds repeat (most
trains settle within the first revolution from rest; a floating valve may never repeat and runs
to the cap).
"""

import numpy as np
from numba import njit

GROUND = -1
"""Node index of the fixed head (seat, spring seat)."""

CAM = -2
"""Node index of the cam excitation: displacement u = k h(theta), velocity omega k h'(theta)."""


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline='always')
def _forces(x, v, inv_mass, ra, rb, k, d, gap, pre, uni, vnode, vtab, acc, q, force):
    """Element forces (compression positive, +f on row rb, -f on row ra) and row accelerations of a block.

    ``x``, ``v`` and ``acc[q]`` are (rows, B): one column per speed of the block, the node rows first, then a
    row of the ground (always 0) and a row of the cam excitation; ``inv_mass`` is 0 on those two rows, so
    their accelerations stay 0.  The accelerations go to ``acc[q]`` of the stages' array ``acc`` (4, rows, B), indexed
    in place: a row view made at every stage of every step cost the kernel a reference count each (numba's NRT).  The element's case (contact or spring) is decided once per element, and the
    loop over the block's speeds has no branch the compiler cannot turn into a select: it runs in SIMD lanes.
    The node ``vnode`` (-1: none) has the mass of the table ``vtab`` (its ``inv_mass`` 1, so that its row sums
    the force; :func:`_variable_mass`).
    """
    rows, bsize = x.shape
    for i in range(rows):
        for s in range(bsize):
            acc[q, i, s] = 0.0
    for e in range(ra.size):
        ia, ib = ra[e], rb[e]
        ke, de, ge = k[e], d[e], gap[e]
        ma, mb = inv_mass[ia], inv_mass[ib]
        if uni[e]:
            for s in range(bsize):
                delta = x[ia, s] - x[ib, s] - ge
                f = ke * delta + de * (v[ia, s] - v[ib, s])
                f = f if (delta > 0.0) & (f > 0.0) else 0.0
                force[e, s] = f
                acc[q, ib, s] += f * mb
                acc[q, ia, s] -= f * ma
        else:
            pe = pre[e]
            for s in range(bsize):
                f = pe + ke * (x[ia, s] - x[ib, s] - ge) + de * (v[ia, s] - v[ib, s])
                force[e, s] = f
                acc[q, ib, s] += f * mb
                acc[q, ia, s] -= f * ma
    if vnode >= 0:
        _variable_mass(x[vnode], v[vnode], acc[q, vnode], vtab)


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _variable_mass(x, v, acc, table):
    """The acceleration of a node of mass m(x) under the force ``acc`` (B,) [N] at positions ``x`` [m] and velocities
    ``v`` [m/s], in place: (F - m'(x) v^2 / 2) / m(x) (:class:`~valvetrain.dynamics.models.VariableMass`).

    ``table`` (3, K): evenly spaced positions [m], m [kg] and m' [kg/m] there; between them the cubic Hermite of m
    and m' (its derivative the m' used), beyond the ends m at the end and m' = 0.
    """
    x0 = table[0, 0]
    dx = table[0, 1] - x0
    last = table.shape[1] - 1
    for s in range(x.size):
        u = (x[s] - x0) / dx
        if u <= 0.0:
            m, dm = table[1, 0], 0.0
        elif u >= last:
            m, dm = table[1, last], 0.0
        else:
            j = min(int(u), last - 1)
            t = u - j
            t2 = t * t
            t3 = t2 * t
            m0, m1 = table[1, j], table[1, j + 1]
            s0, s1 = table[2, j] * dx, table[2, j + 1] * dx
            m = ((2.0 * t3 - 3.0 * t2 + 1.0) * m0 + (t3 - 2.0 * t2 + t) * s0 + (3.0 * t2 - 2.0 * t3) * m1
                 + (t3 - t2) * s1)
            dm = ((6.0 * t2 - 6.0 * t) * (m0 - m1) + (3.0 * t2 - 4.0 * t + 1.0) * s0 + (3.0 * t2 - 2.0 * t) * s1) / dx
        acc[s] = (acc[s] - 0.5 * dm * v[s] * v[s]) / m


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline='always')
def _rk4(x, v, xn, vn, h, cam_x, cam_v, off, im, ra, rb, k, d, gap, pre, uni, vnode, vtab, xs, vs, kx, acc, scratch):
    """One classical RK4 step of every column of a block's state ``x``, ``v`` (rows, B) into the node rows of ``xn``,
    ``vn`` (the same arrays for a step in place).

    Column s advances by ``h[s]`` [s]; at stage q (0-3: start, middle twice, end) the cam row is ``cam_x[q]`` [m]
    and ``cam_v[q, s]`` [m/s], shifted by the lash adjuster's extension ``off[s]`` [m].  ``acc[0]`` holds the
    accelerations at the start (the caller has evaluated them,
    :func:`_forces`, for its record).  ``xs``, ``vs`` (rows, B), ``kx``, ``acc`` (4, rows, B) and ``scratch``
    (E, B) are work arrays, the ground row of ``xs`` zero.  The one RK4 body serves the lockstep steps of a block
    and the split step of one speed (:func:`_split_step`), so that it is compiled once.
    """
    rows, bsize = x.shape
    n = rows - 2
    cam = n + 1
    for q in range(1, 4):
        c = 0.5 if q < 3 else 1.0
        for i in range(n):
            if q == 1:
                for s in range(bsize):
                    xs[i, s] = x[i, s] + c * h[s] * v[i, s]
            else:
                for s in range(bsize):
                    xs[i, s] = x[i, s] + c * h[s] * kx[q - 1, i, s]
            for s in range(bsize):
                vs[i, s] = v[i, s] + c * h[s] * acc[q - 1, i, s]
        for s in range(bsize):
            xs[cam, s] = cam_x[q] + off[s]
            vs[cam, s] = cam_v[q, s]
        for i in range(n):
            for s in range(bsize):
                kx[q, i, s] = vs[i, s]
        _forces(xs, vs, im, ra, rb, k, d, gap, pre, uni, vnode, vtab, acc, q, scratch)
    for i in range(n):
        for s in range(bsize):
            xn[i, s] = x[i, s] + h[s] / 6.0 * (v[i, s] + 2.0 * kx[1, i, s] + 2.0 * kx[2, i, s] + kx[3, i, s])
            vn[i, s] = v[i, s] + h[s] / 6.0 * (acc[0, i, s] + 2.0 * acc[1, i, s] + 2.0 * acc[2, i, s] + acc[3, i, s])


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline='always')
def _half_steps(j0, half, period):
    """The excitation samples half a step and a whole step after sample ``j0`` (``half`` samples a half step), the
    whole step's wrapped round the revolution of ``period`` samples."""
    j1 = j0 + half
    j2 = j1 + half
    return j1, 0 if j2 == period else j2


@njit(cache=True, nogil=True)
def integrate_block(idx, omegas, n_sub, dtheta, cam_u, cam_du, per_step, steps_per_rev, max_revolutions, tolerance,
                    rate, inv_mass, x_init, ra, rb, k, d, gap, pre, uni, closing, follower, springs, rocker_ratio,
                    clash_gap, surge_ref, surge_w, adjuster, contact, vnode, vtab, out_lift, out_vel, out_acc,
                    out_contact, out_seat, out_spring, out_follower, out_clash, out_surge, out_revs, out_z) -> None:
    """Integrate the speeds ``idx`` of one block (all with ``n_sub`` sub-steps) in lockstep until each repeats.

    Every revolution is recorded over the previous one; after each revolution the state of every speed is compared
    with its state at the start of that revolution, and the block stops once every speed repeats within
    ``tolerance`` (or after ``max_revolutions``).  The record is then the last revolution integrated.  The recorded
    values of the block's speeds are gathered, speed by speed in lockstep, in a tile of :data:`TILE` recorded steps
    and written out a tile at a time (:func:`_flush`): a row of the outputs is a speed, so a value written at every
    step, speed after speed, would touch as many memory pages as the block has speeds (these scattered writes took a
    third of a one-mass sweep).

    Parameters
    ----------
    idx : ndarray (B,) of int64
        Speeds of the block (rows of the output arrays).
    omegas : ndarray (S,)
        Camshaft speeds [rad/s].
    n_sub : int
        Sub-steps per angle step dtheta of this block (a power of two dividing ``per_step // 2``).
    dtheta : float
        Recording step of camshaft angle [rad].
    cam_u, cam_du : ndarray (L,)
        Cam displacement at the valve k h [m] and its derivative k dh/dtheta [m/rad] on one revolution sampled
        every dtheta / per_step from the start angle (periodic; L = steps_per_rev * per_step).
    per_step : int
        Excitation samples per recording step (2 x the largest sub-step count of the sweep).
    steps_per_rev : int
        Recording steps per revolution, 2 pi / dtheta.
    max_revolutions : int
        Most camshaft revolutions integrated.
    tolerance : float
        A speed repeats when no node's position differs by more than this from the start of the revolution, nor
        its velocity by more than ``tolerance * rate`` [m].
    rate : float
        Velocity scale of the comparison [1/s] (the spectral radius of the train).
    inv_mass, x_init : ndarray (n,)
        Inverse node masses [1/kg] and initial positions [m] (the train starts at rest).
    ra, rb : ndarray (E,) of int64
        Element end rows (:func:`rows`).
    k, d, gap, pre : ndarray (E,)
        Element stiffness [N/m], damping [N s/m], gap [m], preload [N].
    uni : ndarray (E,) of bool
        Unilateral flag.
    closing : int
        The valve seat element, whose force is recorded and whose closing is located inside the step: a speed whose
        seat closes during a step redoes that step in two, to the closing and from it (:func:`_split_step`).
    follower : int
        The node on the cam whose position is recorded where it is not the valve (-1: the valve is on the cam).
    springs : ndarray of int64
        The spring elements on the valve; minus the sum of their forces is the recorded spring force.
    rocker_ratio : float
        k: the cam contact's recorded force is k times its force at the valve (the force at the cam).
    clash_gap : ndarray (E,)
        Closing distance of a coil element to coil contact [m] (0: not monitored).
    surge_ref : int
        Node of the valve; ``surge_w`` (n,) the quasi-static share of its motion for each coil node (0: none).
    out_lift, out_vel, out_acc : ndarray (S, steps_per_rev)
        The valve's position [m], velocity [m/s] and acceleration [m/s^2] over the recorded revolution.
    out_contact, out_seat, out_spring : ndarray (S, steps_per_rev)
        The cam contact's force at the cam, the seat's force and the springs' force on the valve [N].
    out_follower : ndarray (S, steps_per_rev)
        The position of the node ``follower`` [m] (untouched without one: it may then have no rows).
    out_clash : ndarray (S, E)
        Smallest coil-contact margin [m] over the recorded revolution (inf where not monitored).
    out_surge : ndarray (S, n)
        Largest deviation of each coil node from its quasi-static share of the valve motion [m].
    out_revs : ndarray (S,) of int64
        The revolution after which the speed repeated (0: not within ``max_revolutions``).
    adjuster : ndarray (7,)
        A hydraulic lash adjuster in series with the cam contact (:func:`_adjust`): its motion ratio (0: none), plunger
        spring [N], plunger area [m^2], supply pressure [Pa], leak coefficient pi d c^3 / (12 mu L) [m^3/(s Pa)],
        largest refill velocity [m/s] and the plunger's travel to its stop [m, at the adjuster].
    contact : int
        The cam-follower contact element (the adjuster's extension shifts its cam end).
    vnode : int
        The node whose mass changes with its position (-1: none), its ``inv_mass`` entry unused.
    vtab : ndarray (3, K)
        Its mass table (:func:`_variable_mass`, :meth:`~valvetrain.dynamics.models.VariableMass.array`).
    out_z : ndarray (S, steps_per_rev)
        The adjuster's plunger extension over the recorded revolution [m, at the adjuster]; left as it is without one
        (the caller's zeros: the writes cost a sixth of a one-mass sweep).

    Its plunger extension z is a state of each speed carried from revolution to revolution, compared with the rest
    of the state for the repetition.
    """
    n = x_init.size
    rows = n + 2
    cam = n + 1
    ne = ra.size
    bsize = idx.size
    x = np.zeros((rows, bsize))
    v = np.zeros((rows, bsize))
    x0, v0 = np.zeros((n, bsize)), np.zeros((n, bsize))
    xn, vn = np.zeros((rows, bsize)), np.zeros((rows, bsize))
    xs, vs = np.zeros((rows, bsize)), np.zeros((rows, bsize))
    kx, acc = np.zeros((4, rows, bsize)), np.zeros((4, rows, bsize))
    force, scratch = np.zeros((ne, bsize)), np.zeros((ne, bsize))
    cam_x, cam_v = np.zeros(4), np.zeros((4, bsize))
    om, dt = np.empty(bsize), np.empty(bsize)
    z, z0, off = np.zeros(bsize), np.zeros(bsize), np.zeros(bsize)
    tile = np.empty((TILE, 8, bsize))
    outs = (out_lift, out_vel, out_acc, out_contact, out_seat, out_spring)
    ratio = adjuster[0]
    k_open, d_open, closed = k.copy(), d.copy(), uni.copy()          # the seat open and closed (_split_step)
    if closing >= 0:
        k_open[closing], d_open[closing], closed[closing] = 0.0, 0.0, False
    one, k_one, f_one = np.zeros((4, rows, 1)), np.zeros((2, 4, rows, 1)), np.zeros((2, ne, 1))
    h_one, cam_x_one, cam_v_one, off_one = np.zeros(1), np.zeros(4), np.zeros((4, 1)), np.zeros(1)
    monitored = False
    for e in range(ne):
        monitored |= clash_gap[e] > 0.0
    for i in range(n):
        monitored |= surge_w[i] > 0.0
    im = np.zeros(rows)
    for i in range(n):
        im[i] = inv_mass[i]
    if vnode >= 0:
        im[vnode] = 1.0
    for s in range(bsize):
        om[s] = omegas[idx[s]]
        dt[s] = dtheta / (n_sub * om[s])
        out_revs[idx[s]] = 0
        for i in range(n):
            x[i, s] = x_init[i]
    half = per_step // (2 * n_sub)          # half-grid indices per half step
    period = cam_u.size
    for rev in range(1, max_revolutions + 1):
        for s in range(bsize):
            for e in range(ne):
                out_clash[idx[s], e] = np.inf
            for i in range(n):
                out_surge[idx[s], i] = 0.0
                x0[i, s] = x[i, s]
                v0[i, s] = v[i, s]
            z0[s] = z[s]
        j0 = 0
        for step in range(steps_per_rev * n_sub):
            j1, j2 = _half_steps(j0, half, period)
            u0, u2, d0, d2 = cam_u[j0], cam_u[j2], cam_du[j0], cam_du[j2]
            cam_x[0], cam_x[1], cam_x[2], cam_x[3] = u0, cam_u[j1], cam_u[j1], u2
            for s in range(bsize):
                cam_v[0, s] = om[s] * d0
                cam_v[1, s] = om[s] * cam_du[j1]
                cam_v[2, s] = cam_v[1, s]
                cam_v[3, s] = om[s] * d2
                x[cam, s] = u0 + off[s]
                v[cam, s] = cam_v[0, s]
            _forces(x, v, im, ra, rb, k, d, gap, pre, uni, vnode, vtab, acc, 0, force)
            if ratio > 0.0:
                _adjust(z, off, x, force, contact, cam, rb[contact], k[contact], gap[contact], adjuster, dt)
                for s in range(bsize):
                    x[cam, s] = u0 + off[s]
                _forces(x, v, im, ra, rb, k, d, gap, pre, uni, vnode, vtab, acc, 0, force)
            if step % n_sub == 0:
                r = step // n_sub
                _record(tile, r % TILE, x, v, acc, force, z, surge_ref, follower, contact, closing, springs,
                        rocker_ratio, ratio > 0.0)
                if r % TILE == TILE - 1 or r == steps_per_rev - 1:
                    r0, count = r - r % TILE, r % TILE + 1
                    for q in range(6):
                        _flush(tile, q, outs[q], idx, r0, count)
                    if follower >= 0:
                        _flush(tile, 6, out_follower, idx, r0, count)
                    if ratio > 0.0:
                        _flush(tile, 7, out_z, idx, r0, count)
                if monitored:
                    _monitor(idx, x, ra, rb, clash_gap, surge_ref, surge_w, out_clash, out_surge)
            _rk4(x, v, xn, vn, dt, cam_x, cam_v, off, im, ra, rb, k, d, gap, pre, uni, vnode, vtab, xs, vs, kx, acc,
                 scratch)
            x, v, xn, vn = xn, vn, x, v             # the step's start stays in xn, vn for a split step
            if closing >= 0:
                ia, ib, ge = ra[closing], rb[closing], gap[closing]
                for s in range(bsize):
                    if xn[ia, s] - xn[ib, s] - ge <= 0.0 and x[ia, s] - x[ib, s] - ge > 0.0:
                        _split_step(s, xn, vn, acc[0], x, v, dt[s], om[s], dtheta / n_sub, u0, d0, u2, d2, off[s],
                                    closing, im, ra, rb, k_open, d_open, k, d, gap, pre, uni, closed, vnode, vtab, one,
                                    k_one, f_one, h_one, cam_x_one, cam_v_one, off_one)
            j0 = j2
        done = True
        for s in range(bsize):
            if out_revs[idx[s]] == 0:
                dev = 0.0
                for i in range(n):
                    dev = max(dev, abs(x[i, s] - x0[i, s]), abs(v[i, s] - v0[i, s]) / rate)
                dev = max(dev, ratio * abs(z[s] - z0[s]))
                if dev <= tolerance:
                    out_revs[idx[s]] = rev
                else:
                    done = False
        if done:
            break


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _node_record(idx, r0, r1, x, v, acc, force, rocker_ratio, contact, closing, springs, out_lift, out_vel, out_acc,
                 out_contact, out_seat, out_spring):
    """Write the records of samples ``r0`` to ``r1`` (exclusive) of the block's speeds ``idx``
    (:func:`integrate_node`), all of the present state: the node's position, velocity and acceleration, the cam
    contact's force at the tappet, the seat's force and the springs' force."""
    for s in range(idx.size):
        g = idx[s]
        total = force[springs[0], s]
        for j in range(1, springs.size):
            total += force[springs[j], s]
        pushed = rocker_ratio * force[contact, s]
        for r in range(r0, r1):
            out_lift[g, r] = x[s]
            out_vel[g, r] = v[s]
            out_acc[g, r] = acc[s]
            out_contact[g, r] = pushed
            out_seat[g, r] = force[closing, s]
            out_spring[g, r] = -total


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline='always')
def _compression(x, cam_x, a, b, gap) -> float:
    """The compression [m] of an element of a one-node train from row ``a`` to row ``b`` (:func:`rows` of
    the one node: 0 the node at ``x``, 1 the ground, 2 the cam at ``cam_x``) with the gap ``gap``."""
    return (x if a == 0 else cam_x if a == 2 else 0.0) - (x if b == 0 else cam_x if b == 2 else 0.0) - gap


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _at_rest(x, v, acc, cam_x, im0, ra, rb, k, d, gap, uni, rest) -> bool:
    """Whether the one node of a train (:func:`_compression`'s rows) at ``x`` [m], ``v`` [m/s] with the acceleration
    ``acc`` [m/s^2], the cam standing at ``cam_x`` [m], moves by no more than ``rest`` [m] about its rest position
    from now on, its contacts staying as they are.

    With its closed elements (the bilateral ones and the contacts compressed: stiffness K, damping C) the node is a
    damped oscillator, M a = -K (x - x_r) - C v, so x - x_r = -(M a + C v) / K, and its energy K (x - x_r)^2 / 2 +
    M v^2 / 2 does not grow: the node stays within A = sqrt((x - x_r)^2 + M v^2 / K) of x_r, so within 2 A of where
    it is, its velocity within A sqrt(K / M).  It holds while no contact changes: each closed contact compressed by
    more than 2 A, its force K_e (delta - 2 A) - C_e sqrt(K / M) A still positive, each open one open by more than
    2 A."""
    stiff, damp = 0.0, 0.0
    for e in range(ra.size):
        if not uni[e] or _compression(x, cam_x, ra[e], rb[e], gap[e]) > 0.0:
            stiff += k[e]
            damp += d[e]
    if not stiff > 0.0:
        return False
    w2 = stiff * im0
    off = (acc + damp * im0 * v) / w2
    amplitude = np.sqrt(off * off + v * v / w2)
    if not amplitude <= rest:
        return False
    w = np.sqrt(w2)
    for e in range(ra.size):
        if uni[e]:
            delta = _compression(x, cam_x, ra[e], rb[e], gap[e])
            if delta > 0.0 and not k[e] * (delta - 2.0 * amplitude) - d[e] * w * amplitude > 0.0:
                return False
            if delta <= 0.0 and not delta < -2.0 * amplitude:
                return False
    return True


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline='always')
def _node_stage(x, v, cam_x, cam_v, im0, k, d, gap, pre, acc, force, keep):
    """The accelerations ``acc`` (B,) of the one node of the one-mass train of every speed of a block at its positions
    ``x`` and velocities ``v`` (B,) [m, m/s] with the cam at ``cam_x`` [m] and ``cam_v`` (B,) [m/s]; with ``keep`` the
    element forces into ``force`` (E, B) (the stage whose forces are recorded).  The train's elements are, in this
    order (:func:`~.sweep.one_node` sends no other train here), a unilateral contact from the cam, a spring from the
    node to the head and a unilateral seat from the head: the arithmetic of :func:`_forces` on each speed, in its
    order, the same numbers to the bit.

    The three elements are one loop over the speeds without a branch, which the compiler turns into SIMD instructions.
    With a loop per element (written for any element of those kinds, in any order) and the forces of every stage
    stored, the sweeps of a tolerance sample's blocks of 1 and 8 speeds took 0.40 and 0.75 ms against 0.29 and 0.56
    (one thread, alternately)."""
    bsize = x.size
    kc, dc, gc = k[0], d[0], gap[0]
    ks, ds, gs, ps = k[1], d[1], gap[1], pre[1]
    kz, dz, gz = k[2], d[2], gap[2]
    for s in range(bsize):
        xs, vs = x[s], v[s]
        delta = cam_x - xs - gc
        fc = kc * delta + dc * (cam_v[s] - vs)
        fc = fc if (delta > 0.0) & (fc > 0.0) else 0.0
        fp = ps + ks * (xs - 0.0 - gs) + ds * (vs - 0.0)
        closed = 0.0 - xs - gz
        fz = kz * closed + dz * (0.0 - vs)
        fz = fz if (closed > 0.0) & (fz > 0.0) else 0.0
        if keep:
            force[0, s], force[1, s], force[2, s] = fc, fp, fz
        acc[s] = 0.0 + fc * im0 - fp * im0 + fz * im0


@njit(cache=True, nogil=True)
def integrate_node(idx, omegas, n_sub, dtheta, cam_u, cam_du, per_step, steps_per_rev, max_revolutions, tolerance,
                   rate, rest, inv_mass, x_init, ra, rb, k, d, gap, pre, uni, closing, springs, rocker_ratio, contact,
                   vnode, vtab, out_lift, out_vel, out_acc, out_contact, out_seat, out_spring, out_clash, out_surge,
                   out_revs) -> None:
    """:func:`integrate_block` of the one-mass train (one node without a lash adjuster, a node of variable mass or
    coils; its elements the cam contact, a spring and the seat, in this order: :func:`~.sweep.one_node`): the same
    steps, revolutions and records, to the bit, where no speed is held at rest (below).

    The general block keeps its state in (rows, B) arrays and computes every element of every row at each stage;
    here the state of the block's speeds is one array (B,) of each quantity and the elements one loop over the
    speeds (:func:`_node_stage`), which the compiler turns into SIMD instructions, and the records are written
    straight into the outputs' rows (gathered in a tile as the general block does, a block of 56 speeds took 4.2
    against 2.6 ms).  Measured on one thread, the 200-speed sweep of ``benchmarks/bench_dynamics.py``: 16.5 ms
    against 38.8 with the general block (alternately, best of 9, the load of another job about 1.4); speed by speed, as
    this kernel was before, a block of 56 speeds took 13.3 ms.  The speeds ``idx`` of a block (all with ``n_sub``
    sub-steps) run revolution by revolution until every one of them repeats; a seat closing inside a step is split
    there (:func:`_split_step`, speed by speed).  The arguments are those of :func:`integrate_block` (``closing`` the
    seat element, ``contact`` the cam contact, ``vnode`` -1 and ``vtab`` the empty table of a train without a node of
    variable mass: passed on to :func:`_split_step`, whose compiled code the two kernels then share), less those of
    the parts this kernel has not, and ``rest`` [m].

    A speed at rest is held there: at a step where the cam stands still (the base circle: its displacement and slope
    the same at the step's samples, ``quiet``), a speed whose motion about its rest position stays within ``rest``
    (:func:`_at_rest`, looked at every :data:`HOLD_EVERY` steps) keeps its state, and its records are those of that
    state, until the cam moves again; once every speed of the block is held, the steps up to the cam's next motion
    are not integrated, their records written.  The records then differ from the integrated ones by the motion left,
    at most twice ``rest`` in the lift; ``rest`` = 0 holds only a state that an RK4 step leaves as it is (no velocity,
    no acceleration): the records of the integration to the bit.  A speed is held by its own state alone, whatever
    block it runs in.  The valve rests on its seat over 38-46 % of the built-in example's revolution.
    """
    ne = ra.size
    bsize = idx.size
    rows = 3
    im0 = inv_mass[0]
    state = np.empty((20, bsize))        # the speeds' values, one row each
    x, v, x0, v0, xn, vn, om, h, c, h6 = state[0], state[1], state[2], state[3], state[4], state[5], state[6], \
        state[7], state[8], state[9]
    xq, cv, cv1, a0, a1, a2, a3, k1, k2, k3 = state[10], state[11], state[12], state[13], state[14], state[15], \
        state[16], state[17], state[18], state[19]
    split = np.zeros(bsize, dtype=np.bool_)
    force = np.zeros((ne, bsize))
    k_open, d_open, closed = k.copy(), d.copy(), uni.copy()          # the seat open and closed (_split_step)
    if closing >= 0:
        k_open[closing], d_open[closing], closed[closing] = 0.0, 0.0, False
    im = np.zeros(rows)
    im[0] = im0
    xb, vb, ab = np.zeros((rows, 1)), np.zeros((rows, 1)), np.zeros((rows, 1))
    xe, ve = np.zeros((rows, 1)), np.zeros((rows, 1))
    one, k_one, f_one = np.zeros((4, rows, 1)), np.zeros((2, 4, rows, 1)), np.zeros((2, ne, 1))
    h_one, cam_x_one, cam_v_one, off_one = np.zeros(1), np.zeros(4), np.zeros((4, 1)), np.zeros(1)
    first = np.int64(0)
    for s in range(bsize):
        out_revs[idx[s]] = 0
        x[s], v[s] = x_init[0], 0.0
        om[s] = omegas[idx[s]]
        h[s] = dtheta / (n_sub * om[s])
        c[s] = 0.5 * h[s]
        h6[s] = h[s] / 6.0
    seat_a, seat_b, seat_gap = (ra[closing], rb[closing], gap[closing]) if closing >= 0 else (-1, -1, 0.0)
    half = per_step // (2 * n_sub)          # half-grid indices per half step
    period = cam_u.size
    n_steps = steps_per_rev * n_sub
    quiet = np.zeros(n_steps, dtype=np.bool_)          # the cam stands still over the step
    for step in range(n_steps):
        j0 = step * 2 * half                           # the step's first excitation sample
        j1, j2 = _half_steps(j0, half, period)
        quiet[step] = (cam_du[j0] == 0.0) & (cam_du[j1] == 0.0) & (cam_du[j2] == 0.0) & (cam_u[j1] == cam_u[j0]) & \
            (cam_u[j2] == cam_u[j0])
    held = np.zeros(bsize, dtype=np.bool_)
    still = rest * np.sqrt(k.sum() * im0)               # the fastest a speed at rest moves (every element closed)
    n_springs = springs.size
    holding = False                                     # some speed held
    for rev in range(1, max_revolutions + 1):
        for s in range(bsize):
            for e in range(ne):
                out_clash[idx[s], e] = np.inf
            out_surge[idx[s], 0] = 0.0
            x0[s], v0[s] = x[s], v[s]
        skip = 0
        for step in range(n_steps):
            if step < skip:                 # held: recorded already
                continue
            j0 = step * 2 * half
            j1, j2 = _half_steps(j0, half, period)
            u0, u1, u2, d0, d1, d2 = cam_u[j0], cam_u[j1], cam_u[j2], cam_du[j0], cam_du[j1], cam_du[j2]
            for s in range(bsize):          # RK4's stages, each for every speed
                cv[s] = om[s] * d0
                cv1[s] = om[s] * d1
            _node_stage(x, v, u0 + 0.0, cv, im0, k, d, gap, pre, a0, force, True)
            for s in range(bsize):
                k1[s] = v[s] + c[s] * a0[s]
                xq[s] = x[s] + c[s] * v[s]
            resting = False
            if quiet[step] and step % HOLD_EVERY == 0:
                resting = True
                for s in range(bsize):
                    if not held[s] and abs(v[s]) <= still:
                        held[s] = _at_rest(x[s], v[s], a0[s], u0 + 0.0, im0, ra, rb, k, d, gap, uni, rest)
                        holding = holding or held[s]
                    resting = resting and held[s]
            elif holding and not quiet[step]:
                for s in range(bsize):
                    held[s] = False
                holding = False
            if step % n_sub == 0:           # _node_record's arithmetic on one sample, written out: called here, it
                r = step // n_sub           # took the 200-speed sweep's blocks 10-15 % longer (one thread)
                for s in range(bsize):
                    g = idx[s]
                    out_lift[g, r] = x[s]
                    out_vel[g, r] = v[s]
                    out_acc[g, r] = a0[s]
                    out_contact[g, r] = rocker_ratio * force[contact, s]
                    out_seat[g, r] = force[closing, s]
                    total = force[springs[0], s]
                    for j in range(1, n_springs):
                        total += force[springs[j], s]
                    out_spring[g, r] = -total
            if resting:                     # every speed held: the steps up to the cam's next motion are recorded
                skip = step + 1
                while skip < n_steps and quiet[skip]:
                    skip += 1
                _node_record(idx, (step + n_sub) // n_sub, (skip + n_sub - 1) // n_sub, x, v, a0, force, rocker_ratio,
                             contact, closing, springs, out_lift, out_vel, out_acc, out_contact, out_seat, out_spring)
                continue
            _node_stage(xq, k1, u1 + 0.0, cv1, im0, k, d, gap, pre, a1, force, False)
            for s in range(bsize):
                k2[s] = v[s] + c[s] * a1[s]
                xq[s] = x[s] + c[s] * k1[s]
            _node_stage(xq, k2, u1 + 0.0, cv1, im0, k, d, gap, pre, a2, force, False)
            for s in range(bsize):
                k3[s] = v[s] + 1.0 * h[s] * a2[s]
                xq[s] = x[s] + 1.0 * h[s] * k2[s]
                cv[s] = om[s] * d2
            _node_stage(xq, k3, u2 + 0.0, cv, im0, k, d, gap, pre, a3, force, False)
            closings = False
            for s in range(bsize):
                xs, vs = x[s], v[s]
                xe_s = xs + h6[s] * (vs + 2.0 * k1[s] + 2.0 * k2[s] + k3[s])
                xn[s], vn[s] = xe_s, vs + h6[s] * (a0[s] + 2.0 * a1[s] + 2.0 * a2[s] + a3[s])
                shut = ((xs if seat_a == 0 else 0.0) - (xs if seat_b == 0 else 0.0) - seat_gap <= 0.0) & \
                    ((xe_s if seat_a == 0 else 0.0) - (xe_s if seat_b == 0 else 0.0) - seat_gap > 0.0)
                split[s] = shut
                closings |= shut
            if closings and closing >= 0:
                for s in range(bsize):
                    if split[s]:
                        xb[0, 0], vb[0, 0], ab[0, 0] = x[s], v[s], a0[s]
                        xb[2, 0], vb[2, 0] = u0 + 0.0, om[s] * d0
                        xe[0, 0], ve[0, 0] = xn[s], vn[s]
                        _split_step(first, xb, vb, ab, xe, ve, h[s], om[s], dtheta / n_sub, u0, d0, u2, d2, 0.0,
                                    closing, im, ra, rb, k_open, d_open, k, d, gap, pre, uni, closed, vnode, vtab,
                                    one, k_one, f_one, h_one, cam_x_one, cam_v_one, off_one)
                        xn[s], vn[s] = xe[0, 0], ve[0, 0]
            if holding:
                for s in range(bsize):
                    if not held[s]:
                        x[s], v[s] = xn[s], vn[s]
            else:
                for s in range(bsize):
                    x[s], v[s] = xn[s], vn[s]
        done = True
        for s in range(bsize):
            if out_revs[idx[s]] == 0:
                if max(0.0, abs(x[s] - x0[s]), abs(v[s] - v0[s]) / rate) <= tolerance:
                    out_revs[idx[s]] = rev
                else:
                    done = False
        if done:
            break


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _split_step(s, xb, vb, acc, x, v, dt, om, step_angle, u0, d0, u2, d2, shift, e, im, ra, rb, k_open, d_open, k, d,
                gap, pre, uni, closed, vnode, vtab, one, k_one, f_one, h, cam_x, cam_v, off):
    """Redo the step of speed ``s`` in which element ``e`` closed: RK4 from the start (``xb``, ``vb``, acceleration
    ``acc``) to the closing, located by the Taylor series of the element's gap, then RK4 from it to the step's end;
    the result replaces column ``s`` of ``x``, ``v``.  A contact law that switches inside a step (the seat's damping
    force jumps from 0 at the closing) costs a fixed-step scheme its order; split there, each part is smooth.  Each
    part integrates its own law: the element open before the closing (its stiffness and damping 0) and closed after it
    (bilateral), whatever sign its gap takes at a stage near the closing, located to the Taylor series' accuracy only:
    a stage that found it closed (open) in the first (second) part applied (dropped) the damping force C v at that
    stage alone, an error of h C v / (6 M) in the velocity (the built-in example's valve rebounded from its seat 2 %
    slow and bounced 7-11 % low).  The cam runs on the cubic Hermite of its samples ``u0``, ``u2`` [m] and slopes
    ``d0``, ``d2`` [m/rad] at both ends of the step (``step_angle`` [rad]), shifted by the lash adjuster's extension
    ``shift`` [m]; both parts are :func:`_rk4` steps of a block of one speed.  ``k_open``, ``d_open`` are the element
    stiffnesses and dampings with element ``e``'s 0 and ``closed`` the unilateral flags with ``e``'s False; ``one``
    (4, rows, 1), ``k_one`` (2, 4, rows, 1), ``f_one`` (2, E, 1), ``h`` (1,), ``cam_x`` (4,), ``cam_v`` (4, 1) and
    ``off`` (1,) are work arrays (the block's, made once), the ground row of ``one`` zero."""
    rows = xb.shape[0]
    ia, ib = ra[e], rb[e]
    g0 = xb[ia, s] - xb[ib, s] - gap[e]
    g1 = vb[ia, s] - vb[ib, s]
    g2 = acc[ia, s] - acc[ib, s]
    tau = dt * g0 / (g0 - (x[ia, s] - x[ib, s] - gap[e]))
    disc = g1 * g1 - 2.0 * g2 * g0
    if disc >= 0.0 and g1 + np.sqrt(disc) > 0.0:
        root = -2.0 * g0 / (g1 + np.sqrt(disc))          # g0 + g1 t + g2 t^2 / 2 = 0, the root nearest -g0 / g1
        if 0.0 < root < dt:
            tau = root
    xl, vl, xs, vs = one[0], one[1], one[2], one[3]
    kx, kv, force, scratch = k_one[0], k_one[1], f_one[0], f_one[1]
    off[0] = shift
    for i in range(rows):
        xl[i, 0] = xb[i, s]
        vl[i, 0] = vb[i, s]
    for part in range(2):
        ke, de, law = (k_open, d_open, uni) if part == 0 else (k, d, closed)
        fa, fb = (0.0, tau / dt) if part == 0 else (tau / dt, 1.0)
        h[0] = tau if part == 0 else dt - tau
        fm = 0.5 * (fa + fb)
        for q in range(4):
            f = fa if q == 0 else (fm if q < 3 else fb)
            f2, f3 = f * f, f * f * f
            cam_x[q] = ((2 * f3 - 3 * f2 + 1) * u0 + (f3 - 2 * f2 + f) * step_angle * d0 + (-2 * f3 + 3 * f2) * u2
                        + (f3 - f2) * step_angle * d2)
            cam_v[q, 0] = om * ((6 * f2 - 6 * f) * u0 / step_angle + (3 * f2 - 4 * f + 1) * d0
                                + (-6 * f2 + 6 * f) * u2 / step_angle + (3 * f2 - 2 * f) * d2)
        xl[rows - 1, 0] = cam_x[0] + shift
        vl[rows - 1, 0] = cam_v[0, 0]
        _forces(xl, vl, im, ra, rb, ke, de, gap, pre, law, vnode, vtab, kv, 0, force)
        _rk4(xl, vl, xl, vl, h, cam_x, cam_v, off, im, ra, rb, ke, de, gap, pre, law, vnode, vtab, xs, vs, kx, kv,
             scratch)
    for i in range(rows - 2):
        x[i, s] = xl[i, 0]
        v[i, s] = vl[i, 0]


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _adjust(z, off, x, force, contact, cam, b, stiffness, gap, adjuster, dt):
    """Advance the plunger extension ``z`` [m, at the adjuster] of every speed of a block over its step ``dt`` [s]
    and set the cam row's shift ``off`` = i_a z [m, at the valve] (i_a the adjuster's motion ratio).

    ``force[contact]`` (B,) is the cam contact's force at the valve [N] at the step's start, ``x`` the block's positions,
    ``cam``, ``b`` the contact's rows, ``stiffness`` [N/m] and ``gap`` [m] its own; ``adjuster`` as in
    :func:`integrate_block`.

    Notes
    -----
    The chamber pressure of a massless plunger is p = (i_a F - F_s) / A.  Above the supply p_s the chamber leaks
    through the annular clearance (:func:`valvetrain.lash_adjuster.annular_leakage`) and the plunger sinks,

    .. math:: \\dot z = -\\frac{\\pi d c^3}{12 \\mu L}\\,\\frac{p - p_s}{A}

    (explicit Euler: its rate is far below 1 / dt); at or below it the check valve opens and the plunger extends (oil
    flows in, never out) at the refill velocity, no further than to the contact force (F_s + p_s A) / i_a at which
    the valve closes again: a float lets it follow the opened gap (pump-up), and on the base circle it takes up the
    lash.  It extends no further than its stop (the retaining ring), z <= ``adjuster[6]``.  The oil column's
    compliance is in the contact's stiffness (its secant stiffness in series).
    """
    ratio, spring, area, supply, leak, refill, stop = (adjuster[0], adjuster[1], adjuster[2], adjuster[3], adjuster[4],
                                                       adjuster[5], adjuster[6])
    push = (spring + supply * area) / ratio
    for s in range(z.size):
        f = force[contact, s]
        pressure = (ratio * f - spring) / area
        if pressure > supply:
            dz = -leak * (pressure - supply) / area * dt[s]
        else:
            delta = x[cam, s] - x[b, s] - gap
            need = (push - f) / stiffness if (delta > 0.0) & (f > 0.0) else push / stiffness - delta
            dz = max(min(refill * dt[s], need / ratio), 0.0)
        z[s] = min(z[s] + dz, stop)
        off[s] = ratio * z[s]


TILE = 64
"""Recorded steps gathered before they are written out (:func:`integrate_block`): 64 values of a speed, eight 64-byte
cache lines of its output row on one memory page.  Each row of the outputs lies on pages of its own (a revolution of
3600 steps is 28.8 kB), so a flush writes to as many pages as the block has speeds times the values recorded; with
eight steps a flush (one cache line a row) the 200-speed one-mass sweep took 39-42 ms on one thread, with 64 steps
33-35 ms (measured alternately under load; 23 ms recording nothing), the writes' page look-ups shared by eight times
the values.  The tile of a block of 64 speeds is 256 kB."""


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline='always')
def _record(tile, t, x, v, acc, force, z, valve, follower, contact, seat, springs, rocker_ratio, adjusted):
    """Gather the recorded values of every speed of a block at one angle into the row ``t`` of ``tile`` (TILE, 8, B):
    the valve's position, velocity and acceleration (stage 0 of ``acc``, :func:`_rk4`), the contact's force times
    ``rocker_ratio``, the seat's force, minus the sum of the ``springs``' forces, the ``follower``'s position (where it
    is a node) and the plunger extension ``z`` (where ``adjusted``); indexed in place, as :func:`_forces`."""
    bsize = x.shape[1]
    for s in range(bsize):
        tile[t, 0, s] = x[valve, s]
        tile[t, 1, s] = v[valve, s]
        tile[t, 2, s] = acc[0, valve, s]
        tile[t, 3, s] = rocker_ratio * force[contact, s]
        tile[t, 4, s] = force[seat, s]
    for s in range(bsize):
        total = force[springs[0], s]
        for j in range(1, springs.size):
            total += force[springs[j], s]
        tile[t, 5, s] = -total
    if follower >= 0:
        for s in range(bsize):
            tile[t, 6, s] = x[follower, s]
    if adjusted:
        for s in range(bsize):
            tile[t, 7, s] = z[s]


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _flush(tile, q, out, idx, r0, count):
    """Write the value ``q`` of the first ``count`` recorded angles of a ``tile`` (TILE, 8, B) into the rows ``idx``
    of ``out`` (S, steps), from the angle ``r0`` on."""
    for s in range(idx.size):
        g = idx[s]
        for t in range(count):
            out[g, r0 + t] = tile[t, q, s]


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _monitor(idx, x, ra, rb, clash_gap, surge_ref, surge_w, out_clash, out_surge):
    """Update the coil clash and surge extremes of every speed of a block at a recorded angle (only where the train
    has coils: the loops that find none cost a tenth of a one-mass sweep)."""
    bsize = idx.size
    for e in range(ra.size):
        if clash_gap[e] > 0.0:
            xa, xb = x[ra[e]], x[rb[e]]
            for s in range(bsize):
                margin = clash_gap[e] - (xa[s] - xb[s])
                if margin < out_clash[idx[s], e]:
                    out_clash[idx[s], e] = margin
    for i in range(surge_w.size):
        if surge_w[i] > 0.0:
            xi, xr = x[i], x[surge_ref]
            for s in range(bsize):
                dev = abs(xi[s] - surge_w[i] * xr[s])
                if dev > out_surge[idx[s], i]:
                    out_surge[idx[s], i] = dev


HOLD_EVERY = 8
"""Every how many steps :func:`integrate_node` looks whether its speeds are at rest while the cam stands still; a
speed is looked at only once its velocity is within what a motion of ``rest`` allows.  Looked at so, a sweep where
nothing is held takes the time it took without the hold (the benchmark's 200-speed sweep on one thread, alternately:
23.2 against 23.1 ms); every speed looked at every eighth step, 20-40 % longer."""


BLOCK_SPEEDS = 64
"""Most speeds in one block.  The loops over a block's speeds pay a fixed cost per element and stage (the
compiler's checks that the rows do not overlap, the loop set-up), so wide blocks are faster: on a 20-mass train
the time per speed falls by half from 8 to 64 speeds a block and no further beyond (Xeon with AVX-512, 4 lanes
of 64-bit floats used); 64 still leaves several blocks per thread on a sweep of 200 speeds."""


def blocks(n_sub, workers=2) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Speeds grouped into blocks of equal sub-step count, the blocks in the order of decreasing cost.

    Returns (order, start, seq): the speeds ``order[start[j]:start[j + 1]]`` form block j; ``seq`` lists the
    blocks by decreasing cost (speeds x sub-steps), the order in which the threads take them.  A block holds up
    to BLOCK_SPEEDS speeds, a multiple of 8 speeds (one AVX-512 register) when it is split; a group of 16 or
    more speeds is split into at least ``workers`` blocks.  Speeds keep their order inside a group, so that
    neighbouring speeds (which repeat after about as many revolutions) share a block.

    >>> order, start, seq = blocks(np.array([1, 2, 1, 1]))
    >>> order.tolist(), start.tolist(), seq.tolist()
    ([0, 2, 3, 1], [0, 3, 4], [0, 1])
    """
    n_sub = np.asarray(n_sub)
    order = np.argsort(n_sub, kind="stable")
    start, cost = [0], []
    for m in np.unique(n_sub):
        lo, count = start[-1], int(np.count_nonzero(n_sub == m))
        pieces = max(-(-count // BLOCK_SPEEDS), min(count // 8, workers))
        size = -(-count // pieces)
        size = -(-size // 8) * 8 if size > 8 else size
        for p in range(lo, lo + count, size):
            start.append(min(p + size, lo + count))
            cost.append((start[-1] - p) * int(m))
    seq = np.argsort(-np.array(cost), kind="stable")
    return order, np.array(start), seq


def rows(a, b, n) -> tuple[np.ndarray, np.ndarray]:
    """Element end rows of a block's state: the node, or row n for the ground and n + 1 for the cam.

    >>> [r.tolist() for r in rows(np.array([CAM, 0]), np.array([0, GROUND]), 1)]
    [[2, 0], [0, 1]]
    """
    ra = np.where(a == CAM, n + 1, np.where(a == GROUND, n, a)).astype(np.int64)
    return ra, np.where(b == GROUND, n, b).astype(np.int64)
