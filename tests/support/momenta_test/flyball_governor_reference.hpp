#pragma once
// The reference solution of examples/flyball_governor.yaml (IFToMM benchmark A05): SciPy's Radau
// IIA at rtol = atol = 1e-12 on hand-derived Lagrange equations, independent of momenta
// (scripts/reference/flyball_governor.py prints these; DOP853 agrees to 3e-13 m). For the
// validation test and bench/stiff_bench.cpp.

#include <array>

namespace momenta::test {

struct GovernorReference {
  double t;      // s
  double s;      // m: the slider's height above the shaft's foot
  double omega;  // rad/s: the shaft's speed
};

inline constexpr std::array<GovernorReference, 13> kFlyballGovernor = {{
    {0.1, 0.523836475570, 6.103717808831},
    {0.2, 0.585079811821, 5.722380645600},
    {0.5, 0.743249424786, 5.103415421972},
    {1.0, 0.501420922380, 6.271125741877},
    {2.0, 0.505909294297, 6.236223614436},
    {3.0, 0.513246078340, 6.180672706286},
    {4.0, 0.523223371026, 6.108008053110},
    {5.0, 0.535563103722, 6.022496499759},
    {6.0, 0.549928665906, 5.928650227064},
    {7.0, 0.565938157719, 5.830800910953},
    {8.0, 0.583178336710, 5.732788321369},
    {9.0, 0.601218402047, 5.637779256048},
    {10.0, 0.619622917061, 5.548203622656},
}};

}  // namespace momenta::test
