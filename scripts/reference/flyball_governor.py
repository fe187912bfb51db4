#!/usr/bin/env python3
"""Reference solution of the IFToMM A05 stiff flyball governor (examples/flyball_governor.yaml),
independent of momenta: the equations of motion derived by hand from the Lagrangian and solved
by SciPy's Radau IIA (order 5, implicit) at rtol = atol = 1e-12, checked against SciPy's DOP853
at the same tolerances.

Coordinates (as the model file's joints): φ the shaft's turn about world z, s the slider's height
above the shaft's foot, θ1, θ2 the rods' angles about y from pointing up (rod i points along
u = (sin θ, 0, cos θ) in the shaft's frame, its pivot at (x_i, 0, 1) with x = ±0.05 m).

In the shaft's frame every point of a rod at distance d from its pivot moves in the x–z plane at
d θ̇ and out of it at ω (x_i + d sin θ), so with ω = φ̇

  T = ½ J(θ1, θ2) ω² + ½ m_s ṡ² + ½ I_θ (θ̇1² + θ̇2²)
  J = I_shaft + I_slider + Σ_i [I_⊥ sin²θ_i + I_∥ cos²θ_i + m_r (x_i + ½ sin θ_i)² + m_b (x_i + sin θ_i)²]
  I_θ = I_⊥ + m_r/4 + m_b
  V = g [m_s s + Σ_i (m_r (1 + ½ cos θ_i) + m_b (1 + cos θ_i))] + springs,

the springs from (x_i, 0, s) on the slider to the rod's midpoint: d_i = (½ sin θ_i, 0,
1 + ½ cos θ_i − s), tension k (ℓ − ℓ0) + c ℓ̇ along it. Lagrange's equations:

  (J ω)˙ = 0
  m_s s̈ = −m_s g − Σ T_i ∂ℓ_i/∂s
  I_θ θ̈_i = ½ ∂J/∂θ_i ω² − ∂V_g/∂θ_i − T_i ∂ℓ_i/∂θ_i

Run: python3 scripts/reference/flyball_governor.py   (prints s and ω at the test's times)
"""
import warnings

import numpy as np
from scipy.integrate import solve_ivp

rho, g = 3000.0, 9.81
m_r = rho * 0.01 * 0.01 * 1.0               # 0.3 kg: shaft and rods
m_s = rho * 0.1 ** 3                        # 3 kg: the slider
m_b = 5.0                                   # each ball
I_perp = m_r * (0.01 ** 2 + 1.0 ** 2) / 12  # a rod about a transverse axis through its midpoint
I_par = m_r * (2 * 0.01 ** 2) / 12          # a rod (or the shaft) about its own axis
I_slider = m_s * (2 * 0.1 ** 2) / 12        # the cube about z
k, c, l0 = 8e5, 4e4, 0.5
x_pivot = (0.05, -0.05)
I_theta = I_perp + m_r / 4 + m_b


def inertia_about_z(theta):
    J = I_par + I_slider
    dJ = np.zeros(2)
    for i, (x, th) in enumerate(zip(x_pivot, theta)):
        sn, cs = np.sin(th), np.cos(th)
        J += I_perp * sn * sn + I_par * cs * cs + m_r * (x + 0.5 * sn) ** 2 + m_b * (x + sn) ** 2
        dJ[i] = 2 * (I_perp - I_par) * sn * cs + m_r * (x + 0.5 * sn) * cs + 2 * m_b * (x + sn) * cs
    return J, dJ


def rates(t, y):
    phi, s, th1, th2, w, sd, thd1, thd2 = y
    theta, theta_dot = (th1, th2), np.array([thd1, thd2])
    J, dJ = inertia_about_z(theta)
    w_dot = -(dJ @ theta_dot) * w / J
    force_s = -m_s * g
    th_dd = np.zeros(2)
    for i, th in enumerate(theta):
        sn, cs = np.sin(th), np.cos(th)
        d = np.array([0.5 * sn, 1 + 0.5 * cs - s])
        dd_dth = np.array([0.5 * cs, -0.5 * sn])
        dd_ds = np.array([0.0, -1.0])
        length = np.linalg.norm(d)
        length_dot = d @ (dd_dth * theta_dot[i] + dd_ds * sd) / length
        tension = k * (length - l0) + c * length_dot
        force_s -= tension * (d @ dd_ds) / length
        gravity = g * (0.5 * m_r + m_b) * sn          # −∂V_g/∂θ
        th_dd[i] = (0.5 * dJ[i] * w * w + gravity - tension * (d @ dd_dth) / length) / I_theta
    return [w, sd, thd1, thd2, w_dot, force_s / m_s, th_dd[0], th_dd[1]]


TIMES = [0.1, 0.2, 0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0]
y0 = [0.0, 0.5, np.radians(120.0), np.radians(-120.0), 2 * np.pi, 0.0, 0.0, 0.0]

if __name__ == "__main__":
    warnings.simplefilter("ignore", RuntimeWarning)  # SciPy's Jacobian probe of the unused φ column
    radau = solve_ivp(rates, (0, 10), y0, method="Radau", rtol=1e-12, atol=1e-12, t_eval=TIMES)
    dop = solve_ivp(rates, (0, 10), y0, method="DOP853", rtol=1e-12, atol=1e-12, t_eval=TIMES)
    print(f"Radau: {radau.nfev} evaluations; DOP853: {dop.nfev}")
    print("t, s (m), omega (rad/s), |Radau - DOP853| in s")
    for i, t in enumerate(TIMES):
        print(f"{{{t:.1f}, {radau.y[1, i]:.12f}, {radau.y[4, i]:.12f}}},  // {abs(radau.y[1, i] - dop.y[1, i]):.1e}")
