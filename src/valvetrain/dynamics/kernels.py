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
blocking).  The blocks run in parallel (``prange``), the costliest first; the kernels are cached on
disk (``cache=True``) so a second process pays no compile time.
"""

import numpy as np
from numba import config, njit, prange

GROUND = -1
"""Node index of the fixed head (seat, spring seat)."""

CAM = -2
"""Node index of the cam excitation: displacement u = k h(theta), velocity omega k h'(theta)."""


@njit(cache=True)
def _forces(x, v, inv_mass, ra, rb, k, d, gap, pre, uni, acc, force):
    """Element forces (compression positive, +f on row rb, -f on row ra) and row accelerations of a block.

    ``x``, ``v`` and ``acc`` are (rows, B): one column per speed of the block, the node rows first, then a
    row of the ground (always 0) and a row of the cam excitation; ``inv_mass`` is 0 on those two rows, so
    their accelerations stay 0.  The element's case (contact or spring) is decided once per element, and the
    loop over the block's speeds has no branch the compiler cannot turn into a select: it runs in SIMD lanes.
    """
    bsize = x.shape[1]
    acc[:, :] = 0.0
    for e in range(ra.size):
        ia, ib = ra[e], rb[e]
        ke, de, ge = k[e], d[e], gap[e]
        ma, mb = inv_mass[ia], inv_mass[ib]
        xa, va, xb, vb = x[ia], v[ia], x[ib], v[ib]
        fa, fb, fe = acc[ia], acc[ib], force[e]
        if uni[e]:
            for s in range(bsize):
                delta = xa[s] - xb[s] - ge
                f = ke * delta + de * (va[s] - vb[s])
                f = f if (delta > 0.0) & (f > 0.0) else 0.0
                fe[s] = f
                fb[s] += f * mb
                fa[s] -= f * ma
        else:
            pe = pre[e]
            for s in range(bsize):
                f = pe + ke * (xa[s] - xb[s] - ge) + de * (va[s] - vb[s])
                fe[s] = f
                fb[s] += f * mb
                fa[s] -= f * ma


@njit(cache=True)
def _block(idx, omegas, n_sub, dtheta, cam_u, cam_du, per_step, steps_per_rev, revolutions, inv_mass, x_init,
           ra, rb, k, d, gap, pre, uni, rec_nodes, rec_elems, clash_gap, surge_ref, surge_w,
           out_x, out_v, out_f, out_clash, out_surge):
    """RK4 of the speeds ``idx`` (all with ``n_sub`` sub-steps) in lockstep, one SIMD lane per speed."""
    n = x_init.size
    rows = n + 2
    cam = n + 1
    ne = ra.size
    bsize = idx.size
    x = np.zeros((rows, bsize))
    v = np.zeros((rows, bsize))
    xs, vs = np.zeros((rows, bsize)), np.zeros((rows, bsize))
    k1v, k2v, k3v, k4v = (np.zeros((rows, bsize)), np.zeros((rows, bsize)), np.zeros((rows, bsize)),
                          np.zeros((rows, bsize)))
    k2x, k3x = np.zeros((rows, bsize)), np.zeros((rows, bsize))
    force, scratch = np.zeros((ne, bsize)), np.zeros((ne, bsize))
    om, dt = np.empty(bsize), np.empty(bsize)
    im = np.zeros(rows)
    im[:n] = inv_mass
    for s in range(bsize):
        om[s] = omegas[idx[s]]
        dt[s] = dtheta / (n_sub * om[s])
        for i in range(n):
            x[i, s] = x_init[i]
        for e in range(ne):
            out_clash[idx[s], e] = np.inf
        for i in range(n):
            out_surge[idx[s], i] = 0.0
    half = per_step // (2 * n_sub)          # half-grid indices per half step
    period = cam_u.size
    total = revolutions * steps_per_rev * n_sub
    first_recorded = (revolutions - 1) * steps_per_rev * n_sub
    j0 = 0
    countdown = 0                           # sub-steps to the next recorded angle
    for step in range(total):
        j1 = j0 + half
        j2 = j1 + half
        if j2 == period:
            j2 = 0
        u0, u1, u2 = cam_u[j0], cam_u[j1], cam_u[j2]
        d0, d1, d2 = cam_du[j0], cam_du[j1], cam_du[j2]
        for s in range(bsize):
            x[cam, s] = u0
            v[cam, s] = om[s] * d0
        _forces(x, v, im, ra, rb, k, d, gap, pre, uni, k1v, force)
        if step >= first_recorded:
            if countdown == 0:
                r = (step - first_recorded) // n_sub
                countdown = n_sub
                _record(r, idx, x, v, force, ra, rb, rec_nodes, rec_elems, clash_gap, surge_ref, surge_w,
                        out_x, out_v, out_f, out_clash, out_surge)
            countdown -= 1
        for i in range(n):
            for s in range(bsize):
                xs[i, s] = x[i, s] + 0.5 * dt[s] * v[i, s]
                vs[i, s] = v[i, s] + 0.5 * dt[s] * k1v[i, s]
        for s in range(bsize):
            xs[cam, s] = u1
            vs[cam, s] = om[s] * d1
        _forces(xs, vs, im, ra, rb, k, d, gap, pre, uni, k2v, scratch)
        for i in range(n):
            for s in range(bsize):
                k2x[i, s] = vs[i, s]
                xs[i, s] = x[i, s] + 0.5 * dt[s] * k2x[i, s]
                vs[i, s] = v[i, s] + 0.5 * dt[s] * k2v[i, s]
        _forces(xs, vs, im, ra, rb, k, d, gap, pre, uni, k3v, scratch)
        for i in range(n):
            for s in range(bsize):
                k3x[i, s] = vs[i, s]
                xs[i, s] = x[i, s] + dt[s] * k3x[i, s]
                vs[i, s] = v[i, s] + dt[s] * k3v[i, s]
        for s in range(bsize):
            xs[cam, s] = u2
            vs[cam, s] = om[s] * d2
        _forces(xs, vs, im, ra, rb, k, d, gap, pre, uni, k4v, scratch)
        for i in range(n):
            for s in range(bsize):
                x[i, s] += dt[s] / 6.0 * (v[i, s] + 2.0 * k2x[i, s] + 2.0 * k3x[i, s] + vs[i, s])
                v[i, s] += dt[s] / 6.0 * (k1v[i, s] + 2.0 * k2v[i, s] + 2.0 * k3v[i, s] + k4v[i, s])
        j0 = j2


@njit(cache=True)
def _record(r, idx, x, v, force, ra, rb, rec_nodes, rec_elems, clash_gap, surge_ref, surge_w,
            out_x, out_v, out_f, out_clash, out_surge):
    """Write the recorded angle r of every speed of a block; update its coil clash and surge extremes."""
    bsize = idx.size
    for s in range(bsize):
        g = idx[s]
        for q in range(rec_nodes.size):
            out_x[g, q, r] = x[rec_nodes[q], s]
            out_v[g, q, r] = v[rec_nodes[q], s]
        for q in range(rec_elems.size):
            out_f[g, q, r] = force[rec_elems[q], s]
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


BLOCK_SPEEDS = 64
"""Most speeds in one block.  The loops over a block's speeds pay a fixed cost per element and stage (the
compiler's checks that the rows do not overlap, the loop set-up), so wide blocks are faster: on a 20-mass train
the time per speed falls by half from 8 to 64 speeds a block and no further beyond (Xeon with AVX-512, 4 lanes
of 64-bit floats used); 64 still leaves several blocks per thread on a sweep of 200 speeds."""


PARALLEL_BLOCKS = max(2, config.NUMBA_NUM_THREADS)
"""Fewest blocks a group of 16 or more speeds is split into, so that a small call (a chunk of a sweep with a
progress bar) still runs on every core.  Frozen into the cached kernel; the blocking never changes the results."""


@njit(cache=True)
def blocks(n_sub):
    """Speeds grouped into blocks of equal sub-step count, the blocks in the order of decreasing cost.

    Returns (order, start, seq): the speeds ``order[start[j]:start[j + 1]]`` form block j; ``seq`` lists the
    blocks by decreasing cost (speeds x sub-steps), the order in which the threads take them.  A block holds up
    to BLOCK_SPEEDS speeds, a multiple of 8 speeds (one AVX-512 register) when it is split; a group of 16 or
    more speeds is split into at least PARALLEL_BLOCKS blocks.
    """
    count = n_sub.size
    order = np.empty(count, dtype=np.int64)
    start = np.zeros(count + 1, dtype=np.int64)
    cost = np.zeros(count + 1)
    nb, filled, last = 0, 0, 0
    while filled < count:                   # the speeds by increasing sub-step count (plain loops compile fast)
        m = -1
        for i in range(count):
            if n_sub[i] > last and (m < 0 or n_sub[i] < m):
                m = n_sub[i]
        lo = filled
        for i in range(count):
            if n_sub[i] == m:
                order[filled] = i
                filled += 1
        pieces = max(-(-(filled - lo) // BLOCK_SPEEDS), min((filled - lo) // 8, PARALLEL_BLOCKS))
        size = -(-(filled - lo) // pieces)
        size = -(-size // 8) * 8 if size > 8 else size
        p = lo
        while p < filled:
            q = min(p + size, filled)
            cost[nb] = (q - p) * m
            nb += 1
            start[nb] = q
            p = q
        last = m
    seq = np.arange(nb)
    for j in range(1, nb):                  # insertion sort by decreasing cost (a handful of blocks)
        c, t = seq[j], j
        while t > 0 and cost[seq[t - 1]] < cost[c]:
            seq[t] = seq[t - 1]
            t -= 1
        seq[t] = c
    return order, start[:nb + 1], seq


@njit(cache=True)
def _rows(a, b, n):
    """Element end rows of a block's state: the node, or row n for the ground and n + 1 for the cam."""
    ra, rb = np.empty_like(a), np.empty_like(b)
    for e in range(a.size):
        ra[e] = n + 1 if a[e] == CAM else (n if a[e] == GROUND else a[e])
        rb[e] = n if b[e] == GROUND else b[e]
    return ra, rb


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
    n = inv_mass.size
    ra, rb = _rows(a, b, n)
    order, start, seq = blocks(n_sub)
    for q in prange(seq.size):
        j = seq[q]
        idx = order[start[j]:start[j + 1]]
        _block(idx, omegas, n_sub[idx[0]], dtheta, cam_u, cam_du, per_step, steps_per_rev, revolutions,
               inv_mass, x_init, ra, rb, k, d, gap, pre, uni, rec_nodes, rec_elems, clash_gap, surge_ref,
               surge_w, out_x, out_v, out_f, out_clash, out_surge)
