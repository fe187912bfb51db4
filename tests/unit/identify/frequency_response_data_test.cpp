// A Bode test's data and the model's response to compare with it: the cruise car's
// G(jω) = 1/(m jω + b) from the engine force to the speed, its magnitude in dB and phase and
// their derivatives in m and b against the closed form; the data file's errors at their lines.

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/identify/frequency_response_data.hpp"
#include "momenta/io/file_template.hpp"
#include "momenta/io/measured_data.hpp"

namespace momenta::identify {
namespace {

using ::testing::HasSubstr;

constexpr double kDegrees = 180.0 / std::numbers::pi;

ModelFactory cruise_car() {
  return
      [file = std::make_shared<io::ModelTemplate>("examples/cruise_control.yaml")](const VecX& p) {
        const std::vector<io::NumberOverride> numbers = {{"bodies.car.mass", p[0]},
                                                         {"joints.road.damping", p[1]}};
        return file->with(numbers).model;
      };
}

std::vector<model::OutputSpec> cruise_outputs() {
  return io::ModelTemplate("examples/cruise_control.yaml")
      .with(std::vector<io::NumberOverride>{})
      .outputs;
}

// dB = −10 log₁₀(b² + m²ω²), phase = −atan(mω/b), and their derivatives in m and b.
TEST(FrequencyResponseData, CruiseCarResponseAndItsDerivativesMatchTheClosedForm) {
  const double m = 1200.0, b = 40.0;
  const VecX f = (VecX(5) << 1e-4, 1e-3, 5.3e-3, 0.02, 1.0).finished();  // Hz; corner 5.3 mHz
  VecX near = VecX::Constant(5, -360.0);  // measured on another branch: the model follows it
  const SampledFrequencyResponse r = sample_frequency_response(
      cruise_car(), (VecX(2) << m, b).finished(), "u", "speed", cruise_outputs(), f, near, true);
  ASSERT_EQ(r.values.rows(), 5);
  ASSERT_EQ(r.sensitivities.rows(), 10);
  EXPECT_EQ(r.linearizations, 5);
  for (Eigen::Index k = 0; k < f.size(); ++k) {
    SCOPED_TRACE(f[k]);
    const double w = 2.0 * std::numbers::pi * f[k], d = b * b + m * m * w * w;
    EXPECT_NEAR(r.values(k, 0), -10.0 * std::log10(d), 1e-10);
    EXPECT_NEAR(r.values(k, 1), -std::atan2(m * w, b) * kDegrees - 360.0, 1e-9);
    const double db_m = -20.0 / std::log(10.0) * m * w * w / d;
    const double db_b = -20.0 / std::log(10.0) * b / d;
    const double phase_m = -kDegrees * b * w / d, phase_b = kDegrees * m * w / d;
    // Central differences with h = 10⁻⁴|p|: truncation h²/6 of the third derivative, ~10⁻⁹
    // relative here; 10⁻⁷ of each derivative's size, or of 1 dB or 1° per unit p at most.
    EXPECT_NEAR(r.sensitivities(2 * k, 0), db_m, 1e-7 * std::abs(db_m) + 1e-15);
    EXPECT_NEAR(r.sensitivities(2 * k, 1), db_b, 1e-7 * std::abs(db_b) + 1e-15);
    EXPECT_NEAR(r.sensitivities(2 * k + 1, 0), phase_m, 1e-7 * std::abs(phase_m) + 1e-15);
    EXPECT_NEAR(r.sensitivities(2 * k + 1, 1), phase_b, 1e-7 * std::abs(phase_b) + 1e-15);
  }
}

TEST(FrequencyResponseData, UnknownNamesAreRefusedAsTheLinearizationNamesThem) {
  const VecX f = VecX::Constant(1, 1.0), near = VecX::Zero(1);
  const VecX p = (VecX(2) << 1000.0, 50.0).finished();
  EXPECT_THROW(
      sample_frequency_response(cruise_car(), p, "v", "speed", cruise_outputs(), f, near, false),
      InvalidArgument);
  EXPECT_THROW(
      sample_frequency_response(cruise_car(), p, "u", "sped", cruise_outputs(), f, near, false),
      InvalidArgument);
}

std::string error_of(const std::string& text) {
  try {
    frequency_response_data(io::parse_measured_csv(text, "bode.csv"));
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(FrequencyResponseData, ColumnsFrequenciesAndMagnitudesAreCheckedAtTheirLines) {
  const io::MeasuredTable db =
      io::parse_measured_csv("frequency,magnitude_db,phase\n1,-6,-10\n2,-12,-20\n", "bode.csv");
  const MeasuredFrequencyResponse data = frequency_response_data(db);
  EXPECT_EQ(data.magnitude_db, (VecX(2) << -6.0, -12.0).finished());
  const io::MeasuredTable absolute =
      io::parse_measured_csv("frequency,magnitude,phase\n1,0.1,-10\n2,100,-20\n", "bode.csv");
  EXPECT_NEAR(frequency_response_data(absolute).magnitude_db[0], -20.0, 1e-12);
  EXPECT_NEAR(frequency_response_data(absolute).magnitude_db[1], 40.0, 1e-12);

  EXPECT_THAT(error_of("frequency,gain,phase\n1,2,3\n"),
              HasSubstr("bode.csv: no column 'magnitude' (|G|, or a magnitude_db column in dB)"));
  EXPECT_THAT(error_of("freq,magnitude,phase\n1,2,3\n"), HasSubstr("no column 'frequency'"));
  EXPECT_THAT(error_of("frequency,magnitude,phase\n1,2,3\n1,2,3\n"),
              HasSubstr("bode.csv:3: frequency 1 Hz does not increase"));
  EXPECT_THAT(error_of("frequency,magnitude,phase\n0,2,3\n"),
              HasSubstr("bode.csv:2: frequency 0 Hz: a test frequency must be > 0"));
  EXPECT_THAT(error_of("frequency,magnitude,phase\n1,2,3\n2,0,3\n"),
              HasSubstr("bode.csv:3: magnitude 0: |G| must be > 0"));
}

}  // namespace
}  // namespace momenta::identify
