#pragma once
// Internal to momenta::identify: a direction of the parameters the data do not determine, in
// words (grey_box.cpp's identifiability report).

#include <string>
#include <vector>

#include "momenta/math/types.hpp"

namespace momenta::identify::detail {

/// A direction v of the scaled parameters (δ ln p, or δp/|p|) along which no output changes, as
/// a sentence: one parameter ("c changes no output"), equal shares of one sign ("m, k and b
/// scaled by one factor together change no output: the data determine only the ratios k/m and
/// b/m"), two opposite ("only the product X·Y"), else the coefficients. Entries below 0.1 of the
/// largest are left out.
std::string describe_direction(const VecX& v, const std::vector<std::string>& names);

/// A combination of the log-parameters, "+1.00 ln m −0.71 ln k" (entries ≥ 0.1 of the largest).
std::string combination(const VecX& v, const std::vector<std::string>& names);

}  // namespace momenta::identify::detail
