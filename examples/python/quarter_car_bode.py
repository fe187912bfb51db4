"""Quarter-car suspension (Franklin, Powell & Emami-Naeini, ch. 2): the body's response to the
road, as a Bode plot and a step response, from the model file linearized by momenta.

    python3 examples/python/quarter_car_bode.py [OUTPUT_FOLDER]

Writes quarter_car_bode.png and quarter_car_step.png, and prints the step's figures.
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import momenta

HERE = pathlib.Path(__file__).resolve().parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path.cwd()

model = momenta.load_model(HERE.parent / "quarter_car.yaml")
linear = momenta.linearize(model, inputs=["road"], outputs=["body_y"])
system = linear.system

# Bode: Y/R over two decades either side of the wheel-hop and body modes.
bode = momenta.bode(system, "road", "body_y", omega_min=1.0, omega_max=1000.0, points=400)
fig, (ax_mag, ax_phase) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
ax_mag.semilogx(bode.frequency, bode.magnitude_db)
ax_mag.set_ylabel("|Y/R| (dB)")
ax_mag.grid(True, which="both", alpha=0.3)
ax_phase.semilogx(bode.frequency, bode.phase_deg)
ax_phase.set_xlabel("ω (rad/s)")
ax_phase.set_ylabel("phase (°)")
ax_phase.grid(True, which="both", alpha=0.3)
for mode in momenta.modes(linear):
    if mode.eigenvalue.imag > 0:
        ax_mag.axvline(mode.natural_frequency, color="grey", linestyle=":")
fig.suptitle(f"{model.name}: body height over road height")
fig.savefig(out / "quarter_car_bode.png", dpi=120)

# Step: a 1 m kerb (the response is linear, so scale it to the kerb you like).
step = momenta.step_response(system, "road")
info = momenta.step_info(system, "road", "body_y")
fig, ax = plt.subplots(figsize=(7, 4))
ax.plot(step.time, step.outputs[:, 0])
ax.axhline(info.final_value, color="grey", linestyle=":")
ax.set_xlabel("t (s)")
ax.set_ylabel("body y (m) per m of road step")
ax.set_title(f"overshoot {info.overshoot:.1f} %, settling {info.settling_time:.2f} s")
ax.grid(True, alpha=0.3)
fig.savefig(out / "quarter_car_step.png", dpi=120)

print(f"DC gain {momenta.transfer_function(system, 'road', 'body_y').dc_gain:.6g}")
print(f"rise time {info.rise_time:.4f} s, overshoot {info.overshoot:.2f} %, "
      f"settling time {info.settling_time:.3f} s, peak {info.peak:.4f} at {info.peak_time:.3f} s")
assert np.isclose(info.final_value, 1.0, rtol=1e-9), "the body follows the road at DC"
