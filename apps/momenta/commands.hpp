#pragma once
// The subcommands of the momenta CLI. Each lives in its own <name>_command.cpp, parses its
// arguments into the library's types and calls the library; no mechanics lives here.

#include <CLI/CLI.hpp>

namespace momenta::cli {

/// `momenta version`.
void add_version_command(CLI::App& app);

/// `momenta inertia FILE`: mass properties of a mesh or a composite part file (docs/cli.md).
void add_inertia_command(CLI::App& app);

/// `momenta balance ROTOR`: unbalance, bearing reactions, corrections, grade (docs/balancing.md).
void add_balance_command(CLI::App& app);

/// `momenta simulate MODEL`: integrates a model file, CSV out, summary and audit on stderr.
void add_simulate_command(CLI::App& app);

/// `momenta report MODEL -o FILE`: a run and its HTML report (docs/report.md).
void add_report_command(CLI::App& app);

/// `momenta info MODEL`: degrees of freedom, bodies, joints, elements, signals, outputs.
void add_info_command(CLI::App& app);

/// `momenta linearize MODEL`: A, B, C, D about an operating point (docs/cli.md).
void add_linearize_command(CLI::App& app);

/// `momenta modes MODEL`: eigenvalues, frequencies, damping ratios and mode shapes.
void add_modes_command(CLI::App& app);

/// `momenta campbell MODEL --speed-range A B`: whirl frequencies against spin speed.
void add_campbell_command(CLI::App& app);
void add_steady_command(CLI::App& app);

/// `momenta sweep SWEEP -o results.csv` and `momenta sweep-merge`: sweeps and Monte Carlo.
void add_sweep_command(CLI::App& app);
void add_sweep_merge_command(CLI::App& app);

/// Thrown by a command that has nothing to add to its exit code (an MPI rank other than 0, whose
/// error rank 0 reports).
struct QuietExit {
  int code = 1;
};

/// `momenta kinematics MODEL --point BODY:x,y,z --frame BODY`: rotating-frame kinematics.
void add_kinematics_command(CLI::App& app);
/// `momenta impact MODEL --at BODY:x,y,z --impulse Px,Py,Pz`: impulse and momentum.
void add_impact_command(CLI::App& app);
/// `momenta diagram MODEL --body NAME [-o fbd.svg]`: free-body and kinetic diagrams.
void add_diagram_command(CLI::App& app);

/// `momenta export MODEL --mjcf FILE | --urdf FILE`: the model written for MuJoCo or ROS.
void add_export_command(CLI::App& app);

/// `momenta identify MODEL --data LOG.csv`: base inertial parameters from measured data.
void add_identify_command(CLI::App& app);

/// `momenta equations MODEL`: equations of motion in symbols (docs/equations.md).
void add_equations_command(CLI::App& app);

/// `momenta response MODEL`: step, impulse or Bode response of one input–output pair.
void add_response_command(CLI::App& app);

/// `momenta lqr MODEL --Q … --R …`: the linear–quadratic regulator of a linearized model.
void add_lqr_command(CLI::App& app);
/// `momenta place MODEL --poles …`: pole placement on a linearized model.
void add_place_command(CLI::App& app);

}  // namespace momenta::cli
