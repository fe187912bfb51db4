// Model files with numbers changed by their dotted paths (io/file_template.hpp): the value lands
// where the path says, the rest of the file is untouched, and a path that leads nowhere is refused
// naming what is there.

#include "momenta/io/file_template.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"

namespace momenta::io {
namespace {

const std::filesystem::path kQuarterCar = "examples/quarter_car.yaml";

double suspension_stiffness(const ModelFile& f) {
  for (const auto& e : f.model.force_elements()) {
    if (const auto* s = std::get_if<model::LinearSpringDamper>(&e); s && s->name == "suspension") {
      return s->stiffness;
    }
  }
  return -1.0;
}

TEST(FileTemplate, ValuesLandWhereTheirPathsSay) {
  const ModelFile plain = read_model_file(kQuarterCar);
  const ModelFile changed = read_model_file_with(
      kQuarterCar,
      {{"bodies.body.mass", 400.0}, {"forces.suspension.stiffness", 2.5e5}, {"gravity.2", -9.0}});
  const int body = changed.model.body_index("body");
  EXPECT_EQ(changed.model.body(body).mass_properties.mass(), 400.0);
  EXPECT_EQ(suspension_stiffness(changed), 2.5e5);
  EXPECT_EQ(changed.model.gravity().z(), -9.0);
  // The rest as the file has it.
  EXPECT_EQ(changed.model.body(changed.model.body_index("wheel")).mass_properties.mass(),
            plain.model.body(plain.model.body_index("wheel")).mass_properties.mass());
  EXPECT_EQ(changed.name, plain.name);
  // No change: the same model.
  EXPECT_EQ(suspension_stiffness(read_model_file_with(kQuarterCar, {})), 130000.0);
}

// Every number of every bundled model file, listed with its path: the path leads back to it
// (number_at), and a change at that path changes that line of the text and no other.
TEST(FileTemplate, ListsEveryNumberByAPathThatLeadsBackToIt) {
  std::size_t listed = 0;
  for (const char* folder : {"examples", "examples/constraints"}) {
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() != ".yaml") continue;
      SCOPED_TRACE(entry.path().string());
      const ModelTemplate file(entry.path());
      const std::vector<FileNumber> numbers = file.numbers();
      ASSERT_FALSE(numbers.empty());
      for (const FileNumber& n : numbers) {
        EXPECT_EQ(file.number_at(n.path), n.value) << n.path;
      }
      // The last number changed: its line differs, every other line is kept.
      const FileNumber& last = numbers.back();
      const std::string changed =
          file.text_with(std::vector<NumberOverride>{{last.path, last.value + 1.5}});
      std::istringstream before(file.text()), after(changed);
      std::string a, b;
      for (int line = 1; std::getline(before, a) && std::getline(after, b); ++line) {
        EXPECT_EQ(a == b, line != last.line) << last.path << " at line " << line;
      }
      listed += numbers.size();
    }
  }
  EXPECT_GT(listed, 500u);
}

TEST(FileTemplate, NamesItemsByNameAndVectorsByIndex) {
  const ModelTemplate file(kQuarterCar);
  const std::vector<FileNumber> numbers = file.numbers();
  const auto has = [&](const std::string& path, double value) {
    return std::any_of(numbers.begin(), numbers.end(),
                       [&](const FileNumber& n) { return n.path == path && n.value == value; });
  };
  EXPECT_TRUE(has("bodies.body.mass", 375.0));
  EXPECT_TRUE(has("forces.suspension.stiffness", 130000.0));
  EXPECT_TRUE(has("gravity.2", 0.0));
  EXPECT_TRUE(has("simulation.duration", 2.0));
}

TEST(FileTemplate, PathsThatLeadNowhereAreRefused) {
  const auto refused = [](const std::string& path, const std::string& expected) {
    try {
      read_model_file_with(kQuarterCar, {{path, 1.0}});
      ADD_FAILURE() << path << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  refused("bodies.bodyy.mass", "no item named 'bodyy'");
  refused("bodies.bodyy.mass", "did you mean 'body'");
  refused("forces.suspension.stiffness.x", "has no parts");
  refused("name", "other than a number");
  refused("gravity.7", "past the end");
  refused("bodies..mass", "empty segment");
}

// An unphysical value is the model reader's to refuse, with its key and the line of the file
// where the number stands (the document is edited in place, not re-written).
TEST(FileTemplate, AnUnphysicalValueIsRefusedAtTheFilesLine) {
  try {
    read_model_file_with(kQuarterCar, {{"bodies.body.mass", -1.0}});
    ADD_FAILURE() << "a negative mass accepted";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("quarter_car.yaml:36:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mass"), std::string::npos) << e.what();
  }
}

// Parsed copies are lent again with their numbers put back: a model made after another, after a
// refused one and after one with a created key is the model of its own numbers, and a refusal
// still cites the file's line.
TEST(FileTemplate, ReusedDocumentsGetTheirNumbersBack) {
  const ModelTemplate quarter_car(kQuarterCar);
  const NumberOverride heavy{"bodies.body.mass", 500.0};
  const NumberOverride negative{"bodies.body.mass", -1.0};
  const NumberOverride created{"joints.wheel_travel.q0", 0.01};
  EXPECT_EQ(quarter_car.with({&heavy, 1}).model.body(3).mass_properties.mass(), 500.0);
  for (int repeat = 0; repeat < 2; ++repeat) {
    try {
      quarter_car.with({&negative, 1});
      ADD_FAILURE() << "a negative mass accepted";
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find("quarter_car.yaml:36:"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(quarter_car.with({&created, 1}).model.initial_q()(1), 0.01);
  const ModelFile plain = quarter_car.with({});
  EXPECT_EQ(plain.model.body(3).mass_properties.mass(), 375.0);
  EXPECT_EQ(plain.model.initial_q()(1), 0.0);
  EXPECT_EQ(suspension_stiffness(plain), 130000.0);
}

TEST(FileTemplate, TheTemplateGivesTheFilesNumbersAndMakesModelsFromManyThreads) {
  const ModelTemplate quarter_car(kQuarterCar);
  EXPECT_EQ(quarter_car.number_at("forces.suspension.stiffness"), 130000.0);
  EXPECT_EQ(quarter_car.number_at("joints.wheel_travel.q0"), std::nullopt);  // would be created
  EXPECT_THROW(quarter_car.number_at("forces.suspensoin.stiffness"), InvalidArgument);

  std::vector<double> stiffness(8, 0.0);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < stiffness.size(); ++i) {
    threads.emplace_back([&, i] {
      for (int repeat = 0; repeat < 20; ++repeat) {
        const NumberOverride o{"forces.suspension.stiffness", 1000.0 * static_cast<double>(i + 1)};
        stiffness[i] = suspension_stiffness(quarter_car.with({&o, 1}));
      }
    });
  }
  for (std::thread& t : threads) t.join();
  for (std::size_t i = 0; i < stiffness.size(); ++i) {
    EXPECT_EQ(stiffness[i], 1000.0 * static_cast<double>(i + 1));
  }
}

}  // namespace
}  // namespace momenta::io
