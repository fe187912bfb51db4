#!/usr/bin/env python3
"""Writes two_link_arm_log.csv: 10 s of the built two-link arm (two_link_arm.yaml's header)
following an exciting trajectory, logged at 50 Hz — positions, rates and accelerations exact
(as from a smooth, differentiated encoder signal), efforts from the textbook's closed form
(Spong, Hutchinson & Vidyasagar, §7.4.1; not momenta's dynamics) plus Gaussian noise of
σ = 0.02 N·m, seeded. Standard library only.

    python3 examples/identification/make_two_link_arm_log.py
"""

import math
import pathlib
import random

M1, L1, LC1, I1 = 2.0, 0.8, 0.35, 0.12
M2, LC2, I2 = 1.5, 0.4, 0.06
G = 9.81
SIGMA = 0.02

# Each joint: a sum of sines (a finite Fourier series, Swevers et al. 1997), (amplitude rad,
# angular frequency rad/s, phase rad).
TERMS = {
    0: [(1.2, 0.9, 0.0), (0.5, 2.3, 1.0), (0.25, 4.1, 2.0)],
    1: [(1.0, 1.3, 0.5), (0.6, 2.9, 2.5), (0.3, 5.2, 0.3)],
}


def joint_motion(k, t):
    q = sum(a * math.sin(w * t + p) for a, w, p in TERMS[k])
    v = sum(a * w * math.cos(w * t + p) for a, w, p in TERMS[k])
    a_ = sum(-a * w * w * math.sin(w * t + p) for a, w, p in TERMS[k])
    return q, v, a_


def efforts(q, v, a):
    c2, h = math.cos(q[1]), M2 * L1 * LC2 * math.sin(q[1])
    d11 = M1 * LC1 ** 2 + M2 * (L1 ** 2 + LC2 ** 2 + 2 * L1 * LC2 * c2) + I1 + I2
    d12 = M2 * (LC2 ** 2 + L1 * LC2 * c2) + I2
    d22 = M2 * LC2 ** 2 + I2
    g2 = M2 * LC2 * G * math.sin(q[0] + q[1])
    tau1 = d11 * a[0] + d12 * a[1] - h * (2 * v[0] * v[1] + v[1] ** 2) \
        + (M1 * LC1 + M2 * L1) * G * math.sin(q[0]) + g2
    tau2 = d12 * a[0] + d22 * a[1] + h * v[0] ** 2 + g2
    return tau1, tau2


def main():
    rng = random.Random(2026)
    rows = ["time,shoulder.angle,elbow.angle,shoulder.angle_rate,elbow.angle_rate,"
            "shoulder.angle_rate_dot,elbow.angle_rate_dot,shoulder.effort,elbow.effort"]
    for i in range(501):
        t = i * 0.02
        (q1, v1, a1), (q2, v2, a2) = joint_motion(0, t), joint_motion(1, t)
        tau = efforts((q1, q2), (v1, v2), (a1, a2))
        measured = [x + rng.gauss(0.0, SIGMA) for x in tau]
        rows.append(",".join(f"{x:.10g}" for x in (t, q1, q2, v1, v2, a1, a2, *measured)))
    out = pathlib.Path(__file__).with_name("two_link_arm_log.csv")
    out.write_text("\n".join(rows) + "\n", encoding="utf-8")
    print(f"wrote {out} ({len(rows) - 1} samples)")


if __name__ == "__main__":
    main()
