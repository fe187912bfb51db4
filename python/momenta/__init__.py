"""momenta: model, simulate and analyse mechanical systems from first principles.

The same models, algorithms and numbers as the `momenta` command line, with numpy arrays in and
out (docs/python.md):

    import momenta
    model = momenta.load_model("examples/double_pendulum.yaml")
    run = momenta.simulate(model, duration=5)
    run["energy_total"]                      # a numpy column
    ws = momenta.Workspace(model)
    ws.aba(model.initial_q, model.initial_v, [0.0, 0.0])
    linear = momenta.linearize(model)
    momenta.modes(linear)

Units are SI; spatial vectors are rotation first; inertia tensors carry minus the products of
inertia off the diagonal (docs/conventions.md).
"""

import functools as _functools
import os as _os

from . import _core
from ._core import (
    CampbellDiagram,
    CampbellPoint,
    CriticalSpeed,
    Crossing,
    Equilibrium,
    Error,
    FileError,
    FoundPrecession,
    FrequencyResponse,
    Interrupted,
    InvalidArgument,
    InvalidInertia,
    JointSteadyMotion,
    LinearModel,
    LocusPoint,
    LqrDesign,
    MeshError,
    Mode,
    Model,
    ModelBuilder,
    Modes,
    NormalMode,
    NormalModes,
    NumericalError,
    NyquistCount,
    ParseError,
    PolePlacement,
    Reachability,
    RollingSteadyModes,
    RollingSteadyMotion,
    RootLocus,
    SimulationResult,
    StabilityMargins,
    StateSpace,
    SteadyMode,
    SteadyMotionModes,
    SteadyPrecession,
    StepInfo,
    TimeResponse,
    TransferFunction,
    Workspace,
    base_parameters,
    bode,
    c2d,
    campbell_diagram,
    care,
    controllability,
    dare,
    dlyap,
    estimate_inertia,
    find_equilibrium,
    find_rolling_steady_motions,
    find_steady_precession,
    free_body_diagram,
    identify,
    impulse_momentum_diagram,
    impulse_response,
    inertial_parameters,
    inertial_regressor,
    joint_steady_motion,
    linear_analysis,
    linearize,
    load_model,
    lqr,
    lyap,
    margins,
    modes,
    normal_modes,
    nyquist,
    observability,
    place_poles,
    relative_kinematics,
    rolling_steady_modes,
    root_locus,
    simulate,
    steady_motion,
    steady_precession,
    step_info,
    step_response,
    sweep,
    to_mjcf,
    to_urdf,
    transfer_function,
    undamped_modes,
    with_initial_state,
)
from . import inertia

__version__ = _core.__version__

#: Whether this build has the equations in symbols (MOMENTA_WITH_SYMBOLIC; they link GiNaC and
#: CLN, GPL-2.0-or-later: THIRD-PARTY-NOTICES.md).
with_symbolic = _core.with_symbolic

if with_symbolic:
    from ._core import symbolic_transfer_function

    def equations(model, *, format="text", symbols=(), all_symbols=False, names=None,
                  coordinates="quaternion", **options):
        """equations(model: Model, *, format: str = 'text', symbols: List[str] = [], all_symbols: bool = False, names: Dict[str, str] = {}, coordinates: str = 'quaternion', **options: object) -> Any

        The model's equations of motion in symbols, as `momenta equations` prints them: a list of
        strings (format 'text' or 'latex'; options form='lagrange' | 'matrix' | 'newton-euler',
        principal_axes, greek), with format='cpp' or 'python' the code computing M and b as
        `--cpp` / `--python` write it (one string), or with format='sympy' a SympyEquations: sympy.Eq objects with
        the coordinates as sympy.physics.vector dynamicsymbols of t, the matrix form M, h, B as
        sympy matrices, the parameters' values and units, and a LaTeX repr for a notebook
        (docs/python.md; needs python3-sympy). `symbols` names the parameters kept as symbols
        (all_symbols: every one), `names` renames them, coordinates='euler:ZXZ' writes ball
        and free joints as Euler angles (docs/equations.md)."""
        if format == "sympy":
            if options:
                raise TypeError(f"equations(format='sympy') takes symbols, all_symbols, names and "
                                f"coordinates; not {', '.join(options)}")
            from ._sympy import SympyEquations
            return SympyEquations(_core._equation_parts(
                model, symbols=list(symbols), all_symbols=all_symbols, names=names or {},
                coordinates=coordinates))
        return _core.equations(model, format=format, symbols=list(symbols),
                               all_symbols=all_symbols, names=names or {},
                               coordinates=coordinates, **options)
else:
    def _without_symbolic(name):
        def refuse(*args, **kwargs):
            raise Error(f"{name}() needs the equations in symbols, which this momenta was built "
                        "without (-DMOMENTA_WITH_SYMBOLIC=OFF: GiNaC, GPL-2.0-or-later, left out); "
                        "rebuild with -DMOMENTA_WITH_SYMBOLIC=ON")
        refuse.__name__ = name
        return refuse

    equations = _without_symbolic("equations")
    symbolic_transfer_function = _without_symbolic("symbolic_transfer_function")


def _takes_a_model(function):
    """`function`, whose first argument is a Model, saying what to pass when it is something else
    (pybind11's TypeError lists C++ signatures; a file name gets the load_model line)."""

    @_functools.wraps(function)
    def checked(model, *args, **kwargs):
        if not isinstance(model, Model):
            if isinstance(model, (str, _os.PathLike)):
                hint = (f": load the file first, "
                        f"momenta.{function.__name__}(momenta.load_model({str(model)!r}))")
            else:
                hint = " (momenta.load_model(path) or a momenta.ModelBuilder makes one)"
            raise TypeError(f"{function.__name__}() takes a momenta.Model as its first argument, "
                            f"got {type(model).__name__}{hint}")
        return function(model, *args, **kwargs)

    return checked


for _name in ["campbell_diagram", "find_equilibrium", "find_rolling_steady_motions", "find_steady_precession",
              "free_body_diagram", "impulse_momentum_diagram", "joint_steady_motion", "linear_analysis", "linearize", "relative_kinematics",
              "rolling_steady_modes", "simulate", "steady_motion", "steady_precession",
              "with_initial_state"] + (["equations", "symbolic_transfer_function"] if with_symbolic else []):
    globals()[_name] = _takes_a_model(globals()[_name])
del _name


from ._keywords import with_keyword_hints as _with_keyword_hints  # noqa: E402


def _says_when_not_at_rest(function):
    """linearize, warning as `momenta modes` notes when the point is not an equilibrium."""

    @_functools.wraps(function)
    def linearized(*args, **kwargs):
        linear = function(*args, **kwargs)
        models = linear if isinstance(linear, list) else [linear]
        moving = [i for i, one in enumerate(models)
                  if one.largest_acceleration > 1e-9 or one.largest_speed > 1e-9]
        if moving:
            import warnings
            worst = max(moving, key=lambda i: models[i].largest_acceleration)
            which = ("this state is" if not isinstance(linear, list) else
                     f"operating point{'s' if len(moving) > 1 else ''} "
                     f"{', '.join(map(str, moving))} of {len(models)} {'are' if len(moving) > 1 else 'is'}")
            warnings.warn(
                f"linearize: {which} not an equilibrium (largest acceleration "
                f"{models[worst].largest_acceleration:.4g}, largest speed "
                f"{models[worst].largest_speed:.4g}): "
                "A describes the motion linearized at this instant; find_equilibrium(model) "
                "finds a state at rest, linear_analysis(model, about='steady') a steady motion",
                stacklevel=2)
        return linear

    return linearized


linearize = _says_when_not_at_rest(linearize)

for _name in [n for n in dir(ModelBuilder) if n.startswith("add_") or n == "set_gravity"]:
    setattr(ModelBuilder, _name, _with_keyword_hints(getattr(ModelBuilder, _name), _name))
del _name


def _to_pandas(self):
    """The table as a pandas DataFrame indexed by time (needs pandas)."""
    try:
        import pandas
    except ImportError as error:  # pragma: no cover - pandas is optional
        raise ImportError("SimulationResult.to_pandas() needs pandas (Debian: python3-pandas)") from error
    frame = pandas.DataFrame(self.data, columns=self.columns)
    return frame.set_index("time")


SimulationResult.to_pandas = _to_pandas

from . import _html  # noqa: E402  (after the classes it dresses)

Modes._repr_html_ = _html.modes_html
SimulationResult._repr_html_ = _html.simulation_html
for _result in (StateSpace, LinearModel, Equilibrium, Mode, NormalModes, TransferFunction,
                TimeResponse, StepInfo):
    _result._repr_html_ = _html.text_html
del _result

__all__ = [name for name in dir() if not name.startswith("_")]
