"""The equations of motion as SymPy objects: momenta.equations(model, format="sympy").

The symbolic layer (GiNaC, in C++) derives the equations; here its text is read into SymPy with
the coordinates as functions of time, so that a student can go on in SymPy — simplify, solve for
the accelerations, linearize, lambdify, or sympy.physics.mechanics, whose dynamicsymbols these
are — and a notebook shows them typeset with the textbook's dots (q̇, q̈). The matrix form
M(q) v̇ + C(q, v) v + g(q) = Q(q, v, u) comes with them: `M`, `h` = C v + g − Q, and `B` = ∂Q/∂u
where the model has inputs.
"""

import sympy
from sympy.physics.vector import dynamicsymbols
from sympy.physics.vector.printing import vlatex


class SympyEquations:
    """The equations of motion in SymPy (see momenta.equations).

    equations     list of sympy.Eq, one per free speed: lhs = 0
    t             the time symbol
    coordinates   {sympy function of t: coordinate name} (q, then v where v is not q̇)
    parameters    {sympy.Symbol: value in SI} for the parameters kept as symbols
    units         {sympy.Symbol: SI unit}
    M, h, B       sympy.Matrix: M(q) v̇ + h(q, v, u) = 0 with h = C v + g − Q, and B = ∂Q/∂u
    accelerations sympy.Matrix of v̇, the order of M's columns
    inputs        list of the inputs u(t)
    """

    def __init__(self, parts):
        self.t = dynamicsymbols._t
        local = {}
        self.parameters, self.units = {}, {}
        for name, value, unit in parts["parameters"]:
            symbol = sympy.Symbol(name, real=True)
            local[name] = symbol
            self.parameters[symbol] = value
            self.units[symbol] = unit
        configurations = parts["configuration_names"]
        speeds = parts["speed_names"]
        self.coordinates = {}
        for name in configurations:
            q = dynamicsymbols(name)
            local[name] = q
            self.coordinates[q] = name
        accelerations = parts["acceleration_names"]
        for speed, acceleration in zip(speeds, accelerations):
            base = speed[:-4] if speed.endswith("_dot") else None
            if base in configurations:  # v = q̇: the textbook's q̇ and q̈
                local[speed] = local[base].diff(self.t)
                local[acceleration] = local[base].diff(self.t, 2)
            else:  # a quaternion's joint: the angular velocity is its own function of time
                w = dynamicsymbols(speed)
                self.coordinates[w] = speed
                local[speed] = w
                local[acceleration] = w.diff(self.t)
        self.inputs = []
        for name in parts["input_names"]:
            u = dynamicsymbols(name)
            local[name] = u
            self.inputs.append(u)

        def read(text):
            return sympy.sympify(text, locals=local, convert_xor=True)

        free = parts["free_speeds"]
        self.accelerations = sympy.Matrix([local[accelerations[i]] for i in free])
        self.M = sympy.Matrix([[read(x) for x in row] for row in parts["M"]])
        self.h = sympy.Matrix([read(c) + read(g) - read(f) for c, g, f in
                               zip(parts["velocity_product"], parts["gravity"],
                                   parts["generalized_force"])])
        forces = sympy.Matrix([read(f) for f in parts["generalized_force"]])
        self.B = forces.jacobian(self.inputs) if self.inputs else sympy.zeros(len(free), 0)
        self.equations = [sympy.Eq(read(line.rsplit("=", 1)[0]), 0) for line in parts["equations"]]

    def values(self):
        """{symbol: value}: the model's numbers, for .subs()."""
        return dict(self.parameters)

    def __len__(self):
        return len(self.equations)

    def __iter__(self):
        return iter(self.equations)

    def __getitem__(self, index):
        return self.equations[index]

    def __repr__(self):
        return "\n".join(f"{sympy.sstr(eq.lhs)} = 0" for eq in self.equations)

    def _repr_latex_(self):
        rows = r" \\ ".join(vlatex(eq.lhs) + " &= 0" for eq in self.equations)
        return r"$\begin{aligned}" + rows + r"\end{aligned}$"
