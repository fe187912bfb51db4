// The equations' parameters by source, and the equations as terms with coefficients in the
// parameters (symbolic::Equations::equation_terms): what a live report evaluates with the
// numbers a reader changed (docs/report.md, "The live report").
//
// References: the textbook's coefficients (Franklin's quarter car, eq. 2.12; the pendulum's
// m L² θ̈ + m g L sin θ = 0), and a second derivation — the sources evaluated on a changed model
// must give the values a fresh derivation of that model gives.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "momenta/io/file_template.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/model/parameter_source.hpp"
#include "momenta/symbolic/equations.hpp"

namespace momenta {
namespace equation_terms_test {

std::string example(const std::string& name) {
  return std::string(MOMENTA_SOURCE_DIR) + "/examples/" + name + ".yaml";
}

symbolic::Equations all_symbols(const io::ModelFile& file) {
  symbolic::EquationOptions options;
  options.all_symbols = true;
  options.names = file.given_symbol_names();
  return symbolic::derive_equations(file.model, options);
}

// Equation `row`'s coefficients at the parameters' values, by the term's LaTeX, the right side's
// negated (moved to the left).
std::map<std::string, double> coefficients(const symbolic::Equations& e, int row) {
  const auto terms = e.equation_terms(row);
  EXPECT_TRUE(terms.has_value());
  std::map<std::string, double> out;
  if (!terms) return out;
  for (const symbolic::EquationTerm& term : *terms) {
    double c = 0;
    for (const auto& m : term.coefficient) {
      double product = m.factor;
      for (const auto& [index, exponent] : m.powers)
        product *= std::pow(e.parameters()[static_cast<std::size_t>(index)].value, exponent);
      c += product;
    }
    out[term.latex] += term.right ? -c : c;
  }
  return out;
}

std::vector<double> sorted_values(const std::map<std::string, double>& terms) {
  std::vector<double> values;
  for (const auto& [latex, c] : terms)
    if (c != 0.0) values.push_back(c);
  std::sort(values.begin(), values.end());
  return values;
}

// Franklin eq. 2.12, the wheel: m1 ẍ + b (ẋ − ẏ) + ks (x − y) + kw (x − r) = 0 — the terms ẍ,
// ẋ, ẏ, x, y, r with m1, b, −b, ks + kw, −ks, −kw (the file's numbers: sums exact in binary).
TEST(EquationTerms, QuarterCarWheelHasFranklinsCoefficients) {
  const io::ModelFile file = io::read_model_file(example("quarter_car"));
  const symbolic::Equations e = all_symbols(file);
  const double m1 = 20, b = 9800, ks = 130000, kw = 1000000;
  std::vector<double> expected{m1, b, -b, ks + kw, -ks, -kw};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(sorted_values(coefficients(e, 0)), expected);
  // The body: m2 ÿ + b (ẏ − ẋ) + ks (y − x) = 0.
  std::vector<double> body{375, b, -b, ks, -ks};
  std::sort(body.begin(), body.end());
  EXPECT_EQ(sorted_values(coefficients(e, 1)), body);
}

// The pendulum with m = 2.5 kg and L = 0.8 m: m L² θ̈ ± m g L sin θ = 0, the acceleration's term
// first.
TEST(EquationTerms, PendulumIsMlSquaredAndMgl) {
  const io::ModelTemplate model_template(example("pendulum"));
  const std::vector<io::NumberOverride> changes{{"bodies.bob.mass", 2.5},
                                                {"bodies.bob.position.2", -0.8}};
  const symbolic::Equations e = all_symbols(model_template.with(changes));
  const auto terms = e.equation_terms(0);
  ASSERT_TRUE(terms.has_value());
  ASSERT_EQ(terms->size(), 2u);
  const std::map<std::string, double> c = coefficients(e, 0);
  EXPECT_NEAR(c.at(terms->front().latex), 2.5 * 0.8 * 0.8, 1e-15);
  EXPECT_NEAR(std::abs(c.at((*terms)[1].latex)), 2.5 * 9.81 * 0.8, 1e-14);
  EXPECT_NE((*terms)[1].latex.find("\\sin"), std::string::npos) << (*terms)[1].latex;
}

// Every bundled example: each parameter's sources give its value, each form number its value,
// no term's rest holds a parameter (a row with one inside a function has no terms); and with every
// body's mass a quarter up (where the file writes one), the sources evaluated on the changed model
// give the values a fresh derivation of it gives.
TEST(EquationTerms, SourcesGiveAFreshDerivationsValuesOnAChangedModel) {
  int examples = 0, checked = 0, rows = 0, with_terms = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(
           std::string(MOMENTA_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string path = entry.path().string();
    if (path.find("/sweeps/") != std::string::npos ||
        path.find("/identification/") != std::string::npos ||
        path.find("/parts/") != std::string::npos)
      continue;
    SCOPED_TRACE(path);
    std::optional<io::ModelFile> read;
    try {
      read.emplace(io::read_model_file(path));
    } catch (const std::exception&) {
      continue;  // not a model file (a part, a sweep's design)
    }
    const io::ModelFile& file = *read;
    int free_speeds = file.model.nv();
    for (const model::Joint& j : file.model.joints())
      if (j.is_prescribed()) free_speeds -= j.nv();
    if (free_speeds > 8) continue;  // the report shows no equations
    const symbolic::Equations e = all_symbols(file);
    for (const symbolic::Parameter& p : e.parameters()) {
      ASSERT_FALSE(p.sources.empty()) << p.name;
      for (const model::ParameterSource& s : p.sources)
        EXPECT_EQ(model::parameter_value(file.model, s), p.value) << p.name;
    }
    for (const symbolic::FormNumber& n : e.form_numbers())
      EXPECT_EQ(model::parameter_value(file.model, n.source), n.value) << n.name;
    for (int r = 0; r < free_speeds; ++r) {
      const auto terms = e.equation_terms(r);
      ++rows;
      if (!terms) continue;
      ++with_terms;
      for (const symbolic::EquationTerm& term : *terms)
        for (const symbolic::Parameter& p : e.parameters()) {
          if (p.latex.size() < 3) continue;  // "b" would be found in \beta
          EXPECT_EQ(term.latex.find(p.latex), std::string::npos) << term.latex << ": " << p.name;
        }
    }
    ++examples;

    const io::ModelTemplate model_template(path);
    std::vector<io::NumberOverride> changes;
    for (int b = 1; b < file.model.num_bodies(); ++b) {
      const std::string mass = "bodies." + file.model.body(b).name + ".mass";
      std::optional<double> m;
      try {
        m = model_template.number_at(mass);
      } catch (const std::exception&) {
        continue;  // a body the file does not list (a URDF's link)
      }
      if (m && *m > 0) changes.push_back({mass, *m * 1.25});
    }
    if (changes.empty()) continue;
    const io::ModelFile changed = model_template.with(changes);
    const symbolic::Equations fresh = all_symbols(changed);
    ASSERT_EQ(fresh.parameters().size(), e.parameters().size());
    for (std::size_t k = 0; k < e.parameters().size(); ++k) {
      const symbolic::Parameter& p = e.parameters()[k];
      ASSERT_EQ(fresh.parameters()[k].name, p.name);
      EXPECT_EQ(model::parameter_value(changed.model, p.sources.front()),
                fresh.parameters()[k].value)
          << p.name;
      ++checked;
    }
  }
  EXPECT_GE(examples, 40);    // 42 measured
  EXPECT_GE(with_terms, 95);  // of 106 rows: 101 measured; the rest a parameter in a function
  EXPECT_LE(with_terms, rows);
  EXPECT_GE(checked, 350);  // 368 measured
}

}  // namespace equation_terms_test
}  // namespace momenta
