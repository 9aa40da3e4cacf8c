#!/usr/bin/env python3
"""Nonlinear reference for the spin-up beam of Simo and Vu-Quoc (1986), independent of seflex.

Problem: planar beam, L = 10 m, EI = 1.4e4 N m^2, EA = 2.8e7 N, rho A = 1.2 kg/m, clamped at the origin to a
hub whose angle follows exactly (mbd/src/forces/drive_profile.cpp spin_up_drive)
    phi(t) = w/T (t^2/2 + (cos(c t) - 1)/c^2),  c = 2 pi/T,  t < T;     phi(t) = w (t - T/2),  t >= T,
w = 6 rad/s (or 12 with --rate 12), T = 15 s. Beam straight and at rest at t = 0. No gravity, no damping.

Assumptions: rotary inertia of the cross-section neglected (no mass on the nodal rotations); shear
deformation neglected (Euler-Bernoulli kinematics; for any realistic GA the shear flexibility
EI/(GA L^2) ~ 1e-5 would not show); linear elastic axial and bending laws (N = EA eps, M = EI kappa).

Model: corotational planar beam (Crisfield 1991, vol. 1 ch. 7; the local element is the linear
Euler-Bernoulli element in a frame that follows the chord), absolute nodal coordinates (x, y, theta) in the
inertial frame, so the geometry is exact up to the local small-strain element and converges to the
geometrically exact (Reissner) beam as the mesh is refined. Translational mass consistent with linear
interpolation (rho A l0/6 [[2,1],[1,2]] per direction), constant in the inertial frame: the centrifugal and
Coriolis effects follow from the exact kinematics, nothing is linearised. Hub node: x = y = 0, theta = phi(t).

Time integration: generalised-alpha (Chung and Hulbert 1993), rho_inf = 0.9 (damps the axial / high
bending modes the mesh cannot resolve), internal forces averaged between t_n and t_n+1 (so the massless
rotation equations hold exactly at each step), full Newton with the consistent corotational tangent, banded
solves. Step dt = 1e-3 s by default.

Output (every 0.05 s, t in [0, 30] s): tip displacement in the hub frame (the frame rotating with phi),
u = axial (along the hub x axis, minus L) and v = transverse; also the hub torque the drive applies.

Run (from the repository root; ~1-5 min per case at 20-80 elements):
  nice -n 10 /usr/bin/python3 bench/references/spinup_beam.py --study            # 6 rad/s: 20/40/80 el. + dt check, writes csv
  nice -n 10 /usr/bin/python3 bench/references/spinup_beam.py --study --rate 12  # the 12 rad/s variant
  /usr/bin/python3 bench/references/spinup_beam.py --elements 20 --dt 2e-3        # one quick run, prints landmarks
"""
import argparse
import os
import sys
import time

import numpy as np
from scipy.linalg import solve_banded

L = 10.0
EI = 1.4e4
EA = 2.8e7
RHOA = 1.2
T_RAMP = 15.0
T_END = 30.0
OUT_DT = 0.05


def hub_angle(t, w, T=T_RAMP):
    c = 2.0 * np.pi / T
    if t < T:
        return w / T * (t * t / 2.0 + (np.cos(c * t) - 1.0) / (c * c))
    return w * (t - T / 2.0)


class Beam:
    """n_el corotational elements, 3 dofs per node (x, y, theta), node 0 at the hub."""

    def __init__(self, n_el):
        self.n_el = n_el
        self.l0 = L / n_el
        self.nn = n_el + 1
        self.ndof = 3 * self.nn
        self.X = np.zeros(self.ndof)
        self.X[0::3] = np.linspace(0.0, L, self.nn)
        e = np.arange(n_el)
        self.edofs = np.stack([3 * e, 3 * e + 1, 3 * e + 2, 3 * e + 3, 3 * e + 4, 3 * e + 5], axis=1)  # (ne,6)
        # mass (constant): consistent linear translational, none on rotations
        self.mdiag = np.zeros(self.ndof)
        self.moff = np.zeros(self.ndof)     # coupling between dof i and i+3 (same direction, next node)
        m = RHOA * self.l0 / 6.0
        for d in (0, 1):
            self.mdiag[d::3] = np.r_[2 * m, 4 * m * np.ones(self.nn - 2), 2 * m]   # end nodes 2m, interior 4m
            self.moff[d:self.ndof - 3:3] = m
        self.kl = EI / self.l0 * np.array([[4.0, 2.0], [2.0, 4.0]])
        # banded storage helpers (half bandwidth 5)
        self.bw = 5
        i = self.edofs[:, :, None] + 0 * self.edofs[:, None, :]
        j = self.edofs[:, None, :] + 0 * self.edofs[:, :, None]
        self.band_flat = ((self.bw + i - j) * self.ndof + j).ravel()

    def mass_times(self, a):
        r = self.mdiag * a
        r[:-3] += self.moff[:-3] * a[3:]
        r[3:] += self.moff[:-3] * a[:-3]
        return r

    def mass_band(self):
        ab = np.zeros((2 * self.bw + 1, self.ndof))
        ab[self.bw] = self.mdiag
        ab[self.bw - 3, 3:] = self.moff[:-3]      # upper: A[i, i+3] at row bw-3, column i+3
        ab[self.bw + 3, :-3] = self.moff[:-3]     # lower: A[i+3, i] at row bw+3, column i
        return ab

    def local_strains(self, q):
        """Per element: current length l, chord direction (c, s), axial stretch ul, end rotations t1, t2 from the chord."""
        qe = q[self.edofs]
        dx = qe[:, 3] - qe[:, 0]
        dy = qe[:, 4] - qe[:, 1]
        l = np.hypot(dx, dy)
        beta = np.arctan2(dy, dx)
        t1 = np.angle(np.exp(1j * (qe[:, 2] - beta)))
        t2 = np.angle(np.exp(1j * (qe[:, 5] - beta)))
        ul = (l * l - self.l0 ** 2) / (l + self.l0)
        return l, dx / l, dy / l, ul, t1, t2

    def strain_energy(self, q):
        _, _, _, ul, t1, t2 = self.local_strains(q)
        k = self.kl
        return np.sum(0.5 * EA / self.l0 * ul ** 2 + 0.5 * (k[0, 0] * t1 * t1 + 2 * k[0, 1] * t1 * t2 + k[1, 1] * t2 * t2))

    def kinetic_energy(self, v):
        return 0.5 * v @ self.mass_times(v)

    def forces(self, q, tangent=True):
        """Internal force (ndof) and tangent in banded form, q = absolute nodal (x, y, theta)."""
        l, c, s, ul, t1, t2 = self.local_strains(q)
        N = EA / self.l0 * ul
        M1 = self.kl[0, 0] * t1 + self.kl[0, 1] * t2
        M2 = self.kl[1, 0] * t1 + self.kl[1, 1] * t2
        z0 = np.zeros_like(c)
        r = np.stack([-c, -s, z0, c, s, z0], axis=1)
        z = np.stack([s, -c, z0, -s, c, z0], axis=1)
        B1 = -z / l[:, None]
        B1[:, 2] += 1.0
        B2 = -z / l[:, None]
        B2[:, 5] += 1.0
        fe = r * N[:, None] + B1 * M1[:, None] + B2 * M2[:, None]
        f = np.bincount(self.edofs.ravel(), weights=fe.ravel(), minlength=self.ndof)
        if not tangent:
            return f, None
        k = self.kl
        Ke = (EA / self.l0) * r[:, :, None] * r[:, None, :]
        Ke += k[0, 0] * B1[:, :, None] * B1[:, None, :] + k[0, 1] * (B1[:, :, None] * B2[:, None, :] + B2[:, :, None] * B1[:, None, :]) \
            + k[1, 1] * B2[:, :, None] * B2[:, None, :]
        Ke += (N / l)[:, None, None] * z[:, :, None] * z[:, None, :]
        Ke += ((M1 + M2) / l ** 2)[:, None, None] * (r[:, :, None] * z[:, None, :] + z[:, :, None] * r[:, None, :])
        ab = np.bincount(self.band_flat, weights=Ke.ravel(), minlength=(2 * self.bw + 1) * self.ndof)
        return f, ab.reshape(2 * self.bw + 1, self.ndof)


def simulate(n_el, dt, w, t_end=T_END, rho_inf=0.9, out_dt=OUT_DT, tol=1e-10, verbose=False):
    beam = Beam(n_el)
    am = (2 * rho_inf - 1) / (rho_inf + 1)
    af = rho_inf / (rho_inf + 1)
    gam = 0.5 - am + af
    bet = 0.25 * (1 - am + af) ** 2
    nd = beam.ndof
    free = np.arange(3, nd)                     # node 0 (hub) x, y, theta prescribed
    q = beam.X.copy()
    v = np.zeros(nd)
    a = np.zeros(nd)
    f_n, _ = beam.forces(q, tangent=False)
    Mab = beam.mass_band()
    bw = beam.bw
    n_steps = int(round(t_end / dt))
    out_every = int(round(out_dt / dt))
    rows = []
    tip = 3 * n_el

    def record(t, q, f):
        ph = hub_angle(t, w)
        cph, sph = np.cos(ph), np.sin(ph)
        x, y = q[tip], q[tip + 1]
        u_h = cph * x + sph * y - L
        v_h = -sph * x + cph * y
        rows.append((t, v_h, u_h, f[2]))       # f[2]: internal moment at the hub = torque the drive applies

    record(0.0, q, f_n)
    work = 0.0               # work of the hub torque, trapezoidal in the hub angle
    e_err = 0.0              # max |W - (T + U)| / max(T + U)
    e_max = 0.0
    iters_total = 0
    c_mass = (1 - am) / (bet * dt * dt)
    t0 = time.time()
    for n in range(1, n_steps + 1):
        t = n * dt
        qn, vn, an = q, v, a
        qp = qn + dt * vn + dt * dt * 0.5 * an       # predictor
        qp[0:2] = 0.0
        qp[2] = hub_angle(t, w)
        Mfree_an = beam.mass_times(an)
        for it in range(30):
            a_new = (qp - qn - dt * vn - dt * dt * (0.5 - bet) * an) / (bet * dt * dt)
            f, Kab = beam.forces(qp)
            R = (1 - am) * beam.mass_times(a_new) + am * Mfree_an + (1 - af) * f + af * f_n
            J = c_mass * Mab + (1 - af) * Kab
            Rf = R[free]
            # banded solve on the free dofs (drop the first 3 rows/cols)
            dq = solve_banded((bw, bw), J[:, 3:], -Rf, check_finite=False)
            qp[3:] += dq
            iters_total += 1
            if np.max(np.abs(dq[0::3])) < tol and np.max(np.abs(dq[1::3])) < tol and np.max(np.abs(dq[2::3])) < tol * 0.1:
                break
        else:
            raise RuntimeError(f"Newton did not converge at t = {t}")
        a_new = (qp - qn - dt * vn - dt * dt * (0.5 - bet) * an) / (bet * dt * dt)
        v = vn + dt * ((1 - gam) * an + gam * a_new)
        a = a_new
        f_old = f_n
        q = qp
        f_n, _ = beam.forces(q, tangent=False)
        work += 0.5 * (f_old[2] + f_n[2]) * (q[2] - qn[2])
        if n % out_every == 0:
            e_tot = beam.kinetic_energy(v) + beam.strain_energy(q)
            e_max = max(e_max, e_tot)
            e_err = max(e_err, abs(work - e_tot))
        if n % out_every == 0:
            record(t, q, f_n)
            if verbose and n % (out_every * 40) == 0:
                print(f"  t = {t:5.2f}  v = {rows[-1][1]:+.5f}  u = {rows[-1][2]:+.6f}  "
                      f"iters/step {iters_total / n:.2f}  {time.time() - t0:.0f} s", file=sys.stderr)
    simulate.energy_error = e_err / e_max      # relative energy-balance error (numerical dissipation)
    return np.array(rows), iters_total / n_steps, time.time() - t0


def landmarks(res):
    t, v = res[:, 0], res[:, 1]
    i = np.argmin(v)
    i10 = np.argmin(np.abs(t - 10.0))
    after = t >= T_RAMP
    return {"vmin": v[i], "t_vmin": t[i], "v10": v[i10], "max_abs_v_after_T": np.max(np.abs(v[after])) if after.any() else np.nan,
            "max_abs_u": np.max(np.abs(res[:, 2]))}


def fmt_landmarks(lm):
    return (f"v_min {lm['vmin']:+.5f} m at {lm['t_vmin']:.2f} s, v(10 s) {lm['v10']:+.5f} m, "
            f"max|v| after {T_RAMP:.0f} s {lm['max_abs_v_after_T']:.5f} m, max|u| {lm['max_abs_u']:.5f} m")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rate", type=float, default=6.0, help="final hub rate w [rad/s]")
    ap.add_argument("--elements", type=int, default=20)
    ap.add_argument("--dt", type=float, default=1e-3)
    ap.add_argument("--rho-inf", type=float, default=0.9)
    ap.add_argument("--t-end", type=float, default=T_END)
    ap.add_argument("--study", action="store_true", help="20/40/80 elements + a half-step run, write the csv")
    args = ap.parse_args()
    if not args.study:
        res, its, cpu = simulate(args.elements, args.dt, args.rate, args.t_end, args.rho_inf, verbose=True)
        print(f"{args.elements} el, dt {args.dt}: {fmt_landmarks(landmarks(res))} ({its:.2f} Newton it/step, {cpu:.0f} s)")
        return

    w = args.rate
    meshes = [20, 40, 80]
    dt = args.dt
    runs = {}
    eerr = {}
    for ne in meshes:
        res, its, cpu = simulate(ne, dt, w, args.t_end, args.rho_inf)
        runs[(ne, dt)] = res
        eerr[(ne, dt)] = simulate.energy_error
        print(f"w = {w:g} rad/s, {ne:3d} el, dt {dt:g} s: {fmt_landmarks(landmarks(res))} "
              f"[energy balance {simulate.energy_error:.1e}; {its:.2f} it/step, {cpu:.0f} s]", flush=True)
    ne_f = meshes[-1]
    res_h, its, cpu = simulate(ne_f // 2, dt / 2, w, args.t_end, args.rho_inf)
    runs[(ne_f // 2, dt / 2)] = res_h
    eerr[(ne_f // 2, dt / 2)] = simulate.energy_error
    print(f"w = {w:g} rad/s, {ne_f // 2:3d} el, dt {dt / 2:g} s: {fmt_landmarks(landmarks(res_h))} "
          f"[energy balance {simulate.energy_error:.1e}; {its:.2f} it/step, {cpu:.0f} s]", flush=True)

    fine = runs[(ne_f, dt)]
    mid = runs[(meshes[-2], dt)]
    peak = np.max(np.abs(fine[:, 1]))
    d_mesh = np.max(np.abs(fine[:, 1] - mid[:, 1]))
    d_mesh2 = np.max(np.abs(mid[:, 1] - runs[(meshes[0], dt)][:, 1]))
    d_dt = np.max(np.abs(res_h[:, 1] - mid[:, 1]))
    d_mesh_u = np.max(np.abs(fine[:, 2] - mid[:, 2]))
    d_dt_u = np.max(np.abs(res_h[:, 2] - mid[:, 2]))
    summary = [
        f"max|v({meshes[0]}) - v({meshes[1]})| = {d_mesh2:.2e} m, max|v({meshes[1]}) - v({meshes[2]})| = {d_mesh:.2e} m "
        f"({d_mesh / peak * 100:.3f} % of peak |v| = {peak:.4f} m), same dt {dt:g} s",
        f"max|v(dt {dt:g}) - v(dt {dt / 2:g})| at {meshes[1]} el = {d_dt:.2e} m ({d_dt / peak * 100:.3f} % of peak)",
        f"axial u: mesh {meshes[1]}->{meshes[2]} {d_mesh_u:.2e} m, step {d_dt_u:.2e} m",
        f"energy balance (hub-torque work vs kinetic + strain energy), max |W - T - U| / max(T + U): "
        f"{eerr[(ne_f, dt)]:.1e} at {ne_f} el (generalised-alpha dissipation + quadrature)",
    ]
    for s in summary:
        print(s)
    name = "spinup_beam_reference.csv" if w == 6.0 else f"spinup_beam_{w:g}rads_reference.csv"
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.normpath(os.path.join(here, "..", "..", "tests", "data", "mbd", name))
    with open(out, "w") as fo:
        fo.write(f"# Spin-up beam (Simo and Vu-Quoc 1986) nonlinear reference, hub ramp to w = {w:g} rad/s over T = {T_RAMP:g} s,\n")
        fo.write("# phi = w/T (t^2/2 + (cos(ct)-1)/c^2), c = 2 pi/T (t < T), w (t - T/2) after. L = 10 m, EI = 1.4e4 N m^2,\n")
        fo.write("# EA = 2.8e7 N, rho A = 1.2 kg/m, no rotary inertia, no shear deformation, no gravity, no damping.\n")
        fo.write("# Computed by bench/references/spinup_beam.py (independent of seflex): corotational planar Euler-Bernoulli\n")
        fo.write(f"# beam, {ne_f} elements, absolute coordinates, consistent translational mass; generalised-alpha rho_inf = {args.rho_inf:g},\n")
        fo.write(f"# dt = {dt:g} s, full Newton (increment tol 1e-10 m). Convergence:\n")
        for s in summary:
            fo.write("#   " + s + "\n")
        for ne in meshes:
            fo.write(f"#   {ne} el: {fmt_landmarks(landmarks(runs[(ne, dt)]))}\n")
        fo.write(f"#   {ne_f // 2} el, dt {dt / 2:g}: {fmt_landmarks(landmarks(res_h))}\n")
        fo.write("# Hub frame = frame rotating with phi; v = tip transverse displacement, u = tip axial displacement\n")
        fo.write("# (tip position minus (L, 0), expressed in the hub frame); hub_torque = moment the drive applies [N m].\n")
        fo.write("# t [s], v_tip_hub [m], u_tip_hub [m], hub_torque [N m]\n")
        for row in fine:
            fo.write(f"{row[0]:.2f},{row[1]:.9e},{row[2]:.9e},{row[3]:.9e}\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
