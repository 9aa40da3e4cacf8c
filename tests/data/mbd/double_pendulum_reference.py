#!/usr/bin/env python3
"""Reference time history for the rigid double pendulum test (tests/mbd/pendulum_test.cpp).

Independent of seflex: Lagrange's equations of two uniform rods (m = 1 kg, L = 1 m, I_cm = m L^2/12)
in absolute angles theta1, theta2 (from +x, counter-clockwise), joint 1 at the origin, gravity
g = 9.81 m/s^2 along -y, released from rest with both rods along +x (theta1 = theta2 = 0) and
theta2dot(0) = 0.5 rad/s. Integrated with scipy's DOP853 at rtol = atol = 1e-12.
Output columns: t, phi1 = theta1, phi2 = theta2 - theta1 (the seflex hinge angles), their rates,
and the total energy (a check of the reference itself).
Run: /usr/bin/python3 double_pendulum_reference.py > double_pendulum_reference.csv
"""
import numpy as np
from scipy.integrate import solve_ivp

m1 = m2 = 1.0
L = 1.0
I1 = I2 = m1 * L * L / 12.0
g = 9.81


def rhs(t, y):
    t1, t2, w1, w2 = y
    e1 = np.array([np.cos(t1), np.sin(t1)])
    e2 = np.array([np.cos(t2), np.sin(t2)])
    n1 = np.array([-np.sin(t1), np.cos(t1)])
    n2 = np.array([-np.sin(t2), np.cos(t2)])
    J1 = np.column_stack([0.5 * L * n1, np.zeros(2)])   # d c1 / d(theta1, theta2)
    J2 = np.column_stack([L * n1, 0.5 * L * n2])        # d c2 / d(theta1, theta2)
    b1 = -0.5 * L * e1 * w1 ** 2                         # c1'' at zero angular acceleration
    b2 = -L * e1 * w1 ** 2 - 0.5 * L * e2 * w2 ** 2
    G = np.array([0.0, -g])
    M = m1 * J1.T @ J1 + m2 * J2.T @ J2 + np.diag([I1, I2])
    f = m1 * J1.T @ (G - b1) + m2 * J2.T @ (G - b2)
    a = np.linalg.solve(M, f)
    return [w1, w2, a[0], a[1]]


def energy(y):
    t1, t2, w1, w2 = y
    c1 = 0.5 * L * np.array([np.cos(t1), np.sin(t1)])
    c2 = L * np.array([np.cos(t1), np.sin(t1)]) + 0.5 * L * np.array([np.cos(t2), np.sin(t2)])
    v1 = 0.5 * L * w1 * np.array([-np.sin(t1), np.cos(t1)])
    v2 = L * w1 * np.array([-np.sin(t1), np.cos(t1)]) + 0.5 * L * w2 * np.array([-np.sin(t2), np.cos(t2)])
    return (0.5 * m1 * v1 @ v1 + 0.5 * m2 * v2 @ v2 + 0.5 * I1 * w1 ** 2 + 0.5 * I2 * w2 ** 2
            + m1 * g * c1[1] + m2 * g * c2[1])


ts = np.linspace(0.0, 2.0, 201)
sol = solve_ivp(rhs, (0.0, 2.0), [0.0, 0.0, 0.0, 0.5], method="DOP853", rtol=1e-12, atol=1e-12, t_eval=ts)
print("# Rigid double pendulum reference (double_pendulum_reference.py): scipy DOP853, rtol = atol = 1e-12")
print("# t, phi1, phi2, phi1dot, phi2dot, energy")
for k, t in enumerate(sol.t):
    t1, t2, w1, w2 = sol.y[:, k]
    print("%.4f,%.15e,%.15e,%.15e,%.15e,%.15e" % (t, t1, t2 - t1, w1, w2 - w1, energy(sol.y[:, k])))
