#!/usr/bin/env python3
"""Writes the measured logs of the grey-box examples — what a rig's data logger would record —
from the textbooks' own equations integrated by SciPy (solve_ivp, DOP853, rtol 1e-12; not
momenta's dynamics), with Gaussian sensor noise from a seeded generator:

  cruise_control_log.csv   Franklin ch. 2: m v̇ + b v = u; m = 1000 kg, b = 50 N·s/m; u = 500 N,
                           then 200 N from t = 60 s; logged at 2 Hz; speed noise σ = 0.05 m/s.
  cruise_control_short_log.csv  the same car under a steady 500 N from rest: 16 samples over
                           60 s from a speedometer with σ = 2.5 m/s — so little, so noisy, that
                           the cost is far from quadratic in m and b (profile intervals).
  quarter_car_log.csv      Franklin eq. 2.12 with ks = 130 000 N/m, b = 9 800 N·s/m (m1 = 20 kg,
                           m2 = 375 kg, kw = 1e6 N/m) over ../quarter_car.yaml's road (a 5 cm step
                           at 0.1 s, quintic rise over 10 ms); body travel y at 500 Hz, σ = 0.5 mm.
  damped_pendulum_log.csv  m L² θ̈ + c θ̇ + m g L sin θ = 0; m = 1 kg, L = 1 m, c = 0.05 N·m·s/rad,
                           released from rest at 28.5°; angle at 20 Hz, σ = 0.2°.
  damped_pendulum_release_60.csv  the same pendulum released from rest at 61.2° (the operator
                           aimed at 60°), 20 s at 20 Hz, σ = 0.2°: the second test of
                           damped_pendulum_releases_identify.yaml, whose release angles are each
                           estimated for their own test.

  quarter_car_shaker_bode.csv  a shaker-table test of the same quarter car: the body's travel
                           against the road's at 40 frequencies from 0.5 to 30 Hz, from the
                           transfer function of Franklin eq. 2.12 (closed form, not momenta's
                           linearization), with 0.2 dB of magnitude and 1° of phase noise.

The engine force is logged at the rate it was commanded, and between samples it moved linearly
(what a table input between samples means: docs/identification.md).

    python3 examples/identification/make_grey_box_logs.py
"""

import math
import pathlib

import numpy as np
from scipy.integrate import solve_ivp

HERE = pathlib.Path(__file__).resolve().parent
SOLVER = dict(method="DOP853", rtol=1e-12, atol=1e-14)


def write(name, header, columns):
    rows = np.column_stack(columns)
    with open(HERE / name, "w", encoding="utf-8") as out:
        out.write(header + "\n")
        for row in rows:
            out.write(",".join(f"{x:.10g}" for x in row) + "\n")


def cruise_control(rng):
    m, b = 1000.0, 50.0
    t = np.linspace(0.0, 120.0, 241)
    force = np.where(t < 60.0, 500.0, 200.0)
    u = lambda s: np.interp(s, t, force)  # noqa: E731
    sol = solve_ivp(lambda s, v: [(u(s) - b * v[0]) / m], (0.0, 120.0), [0.0], t_eval=t,
                    max_step=0.1, **SOLVER)
    speed = sol.y[0] + rng.normal(0.0, 0.05, t.size)
    write("cruise_control_log.csv", "time,force,speed", [t, force, speed])


def cruise_control_short(rng):
    m, b, u = 1000.0, 50.0, 500.0
    t = np.linspace(0.0, 60.0, 16)
    sol = solve_ivp(lambda s, v: [(u - b * v[0]) / m], (0.0, 60.0), [0.0], t_eval=t, **SOLVER)
    speed = sol.y[0] + rng.normal(0.0, 2.5, t.size)
    write("cruise_control_short_log.csv", "time,force,speed", [t, np.full(t.size, u), speed])


def quarter_car_shaker(rng):
    m1, m2, ks, kw, b = 20.0, 375.0, 130000.0, 1.0e6, 9800.0
    f = np.geomspace(0.5, 30.0, 40)
    s = 2j * np.pi * f
    # Y/R from Franklin eq. 2.12 with r the input: the wheel's and body's equations solved.
    g = kw * (b * s + ks) / ((m1 * s**2 + b * s + ks + kw) * (m2 * s**2 + b * s + ks)
                             - (b * s + ks) ** 2)
    magnitude = np.abs(g) * 10.0 ** (rng.normal(0.0, 0.2, f.size) / 20.0)
    phase = np.degrees(np.unwrap(np.angle(g))) + rng.normal(0.0, 1.0, f.size)
    write("quarter_car_shaker_bode.csv", "frequency,magnitude,phase", [f, magnitude, phase])


def smooth_step(s, start=0.1, rise=0.01, final=0.05):
    x = min(max((s - start) / rise, 0.0), 1.0)
    return final * x ** 3 * (10.0 - 15.0 * x + 6.0 * x * x)


def quarter_car(rng):
    m1, m2, ks, kw, b = 20.0, 375.0, 130000.0, 1.0e6, 9800.0

    def rates(s, z):
        x, y, xd, yd = z
        r = smooth_step(s)
        xdd = (-b * (xd - yd) - ks * (x - y) - kw * (x - r)) / m1
        ydd = (-b * (yd - xd) - ks * (y - x)) / m2
        return [xd, yd, xdd, ydd]

    t = np.linspace(0.0, 1.5, 751)
    sol = solve_ivp(rates, (0.0, 1.5), [0.0, 0.0, 0.0, 0.0], t_eval=t, max_step=1e-3, **SOLVER)
    y = sol.y[1] + rng.normal(0.0, 0.0005, t.size)
    write("quarter_car_log.csv", "time,body_travel", [t, y])


def damped_pendulum(rng, name="damped_pendulum_log.csv", release_deg=28.5, duration=30.0):
    m, L, c, g = 1.0, 1.0, 0.05, 9.81
    theta0 = math.radians(release_deg)
    t = np.linspace(0.0, duration, int(round(duration * 20)) + 1)
    sol = solve_ivp(lambda s, z: [z[1], -(g / L) * math.sin(z[0]) - c / (m * L * L) * z[1]],
                    (0.0, duration), [theta0, 0.0], t_eval=t, max_step=0.01, **SOLVER)
    angle = sol.y[0] + rng.normal(0.0, math.radians(0.2), t.size)
    write(name, "time,angle", [t, angle])


if __name__ == "__main__":
    rng = np.random.default_rng(20261205)
    cruise_control(rng)
    quarter_car(rng)
    damped_pendulum(rng)
    damped_pendulum(rng, "damped_pendulum_release_60.csv", release_deg=61.2, duration=20.0)
    cruise_control_short(rng)
    quarter_car_shaker(rng)
