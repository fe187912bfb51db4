#include "momenta/io/yaml_reader.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta_test/tolerance.hpp"

namespace momenta::io {
namespace {

// Runs `f`, expects a ParseError and returns its message (empty if none was thrown).
template <typename F>
std::string parse_error_of(F&& f) {
  try {
    f();
  } catch (const ParseError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ParseError thrown";
  return "";
}

TEST(YamlReader, MalformedYamlReportsYamlCppsLineAndColumn) {
  // The flow sequence on line 1 is never closed; yaml-cpp notices on line 2, column 2.
  try {
    YamlNode::load_string("a: [1, 2\nb: 3\n", "bad.yaml");
    FAIL() << "no ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "bad.yaml");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 2);
    EXPECT_NE(std::string(e.what()).find("bad.yaml:2:2: malformed YAML"), std::string::npos)
        << e.what();
  }
  // Bad indentation.
  const std::string m = parse_error_of([] { YamlNode::load_string("a: 1\n b: 2\n", "i.yaml"); });
  EXPECT_NE(m.find("i.yaml:2:"), std::string::npos) << m;
}

TEST(YamlReader, UnterminatedQuoteIsReportedWhereItOpens) {
  // yaml-cpp takes a quoted string that never closes as running to the end of the file (it
  // would then say 'missing required key bodies' at 1:1); the reader points at the quote.
  const auto message = [](const std::string& text) {
    return parse_error_of([&] { YamlNode::load_string(text, "q.yaml"); });
  };
  EXPECT_NE(message("name: \"abc\nbodies: []\n")
                .find("q.yaml:1:7: malformed YAML: this quoted "
                      "string has no closing \""),
            std::string::npos);
  EXPECT_NE(message("bodies:\n  - name: 'rod\n").find("q.yaml:2:11:"), std::string::npos);
  // Inside a flow map yaml-cpp notices the missing brace itself.
  EXPECT_NE(message("{\"key: 1}\n").find("malformed YAML"), std::string::npos);
  // Quoted strings that do close, over lines and with their escapes, are fine.
  const YamlNode root = YamlNode::load_string(
      "a: \"one \\\" two\n  three\"\nb: 'it''s'\nc: \"ends in a backslash \\\\\"\n", "ok.yaml");
  EXPECT_EQ(root.at("a").as_string(), "one \" two three");
  EXPECT_EQ(root.at("b").as_string(), "it's");
  EXPECT_EQ(root.at("c").as_string(), "ends in a backslash \\");
}

// "Billion laughs": `levels` lines, each a list of `fan` aliases of the line before.
std::string alias_bomb(int levels, int fan) {
  std::string text = "a0: &a0 [lol]\n";
  for (int level = 1; level < levels; ++level) {
    text += fmt::format("a{0}: &a{0} [", level);
    for (int k = 0; k < fan; ++k) text += fmt::format("{}*a{}", k ? ", " : "", level - 1);
    text += "]\n";
  }
  return text;
}

TEST(YamlReader, AliasBombIsRefusedAtTheNodeThatExplodes) {
  // 9 levels of 9 aliases: 1.2 kB standing for 9^8 ≈ 4.3e7 lists. The checks once followed every
  // alias again (hours); each written node is now visited once and the expansion is capped.
  const std::string text = alias_bomb(9, 9);
  ASSERT_LT(text.size(), 1300u);
  const std::string m = parse_error_of([&] { YamlNode::load_string(text, "lol.yaml"); });
  // Line k + 1 holds a_k, standing for s_k = 1 + 9 s_(k-1) nodes (s_0 = 2): a5 on line 6 for
  // 125 479, a6 on line 7 for 1 129 312, the first past the limit.
  EXPECT_NE(m.find("lol.yaml:7:"), std::string::npos) << m;
  EXPECT_NE(m.find("expand it to more than 1000000 nodes"), std::string::npos) << m;
  // Aliases that expand modestly are YAML and are read as written.
  const YamlNode small = YamlNode::load_string(alias_bomb(4, 3), "few.yaml");
  ASSERT_EQ(small.at("a3").size(), 3u);
  EXPECT_EQ(small.at("a3").elements()[2].elements()[1].elements()[0].elements()[0].as_string(),
            "lol");
}

TEST(YamlReader, EmptyOrCommentOnlyFileIsAnError) {
  EXPECT_THROW(YamlNode::load_string("", "e.yaml"), ParseError);
  const std::string m = parse_error_of([] { YamlNode::load_string("# nothing\n", "e.yaml"); });
  EXPECT_NE(m.find("e.yaml: the file holds no YAML document"), std::string::npos) << m;
}

TEST(YamlReader, MissingFileIsAFileError) {
  EXPECT_THROW(YamlNode::load_file("/nonexistent/dir/x.yaml"), FileError);
}

TEST(YamlReader, LoadsFilesAndNamesThemInMessages) {
  const auto path = std::filesystem::temp_directory_path() / "momenta_yaml_reader_test.yaml";
  {
    std::ofstream out(path);
    out << "mass: -1\n";
  }
  const YamlNode root = YamlNode::load_file(path);
  EXPECT_EQ(root.file(), path.string());
  const std::string m = parse_error_of([&] { root.number("mass", Bound::kPositive); });
  EXPECT_EQ(m, path.string() + ":1:7: mass: must be positive, got -1");
  std::filesystem::remove(path);
}

TEST(YamlReader, KeyPathsAndPositionsOfNestedValues) {
  const YamlNode root = YamlNode::load_string(
      "parts:\n"
      "  - radius: 0.5\n"
      "    position: [1, 2, 3]\n"
      "  - radius: -0.25\n",
      "p.yaml");
  const auto parts = root.at("parts").elements();
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[1].key_path(), "parts[1]");
  const YamlNode r = parts[1].at("radius");
  EXPECT_EQ(r.key_path(), "parts[1].radius");
  EXPECT_EQ(r.line(), 4);
  EXPECT_EQ(r.column(), 13);
  EXPECT_EQ(parts[0].number("radius", Bound::kPositive), 0.5);
  EXPECT_EQ(parse_error_of([&] { r.as_double(Bound::kPositive); }),
            "p.yaml:4:13: parts[1].radius: must be positive, got -0.25");
  // Elements of a flow list carry their own columns.
  const auto xyz = parts[0].at("position").elements(3);
  EXPECT_EQ(xyz[2].key_path(), "parts[0].position[2]");
  EXPECT_EQ(xyz[2].line(), 3);
  EXPECT_EQ(xyz[2].column(), 22);
  EXPECT_EQ(parts[0].at("position").as_vec3(), Vec3(1, 2, 3));
}

TEST(YamlReader, MissingRequiredKeyNamesTheKeyAndTheMap) {
  const YamlNode root = YamlNode::load_string("part:\n  radius: 1\n", "m.yaml");
  EXPECT_EQ(parse_error_of([&] { root.at("part").at("length"); }),
            "m.yaml:2:3: part: missing required key 'length'");
  EXPECT_FALSE(root.at("part").find("length").has_value());
  EXPECT_TRUE(root.at("part").has("radius"));
}

TEST(YamlReader, EmptyValueIsReportedAtItsKey) {
  // yaml-cpp marks an empty value at the start of the next line; the key is where the user looks.
  const YamlNode root = YamlNode::load_string("a: 1\nmass:\nb: 2\n", "n.yaml");
  const YamlNode mass = root.at("mass");
  EXPECT_TRUE(mass.is_null());
  EXPECT_EQ(parse_error_of([&] { mass.as_double(); }),
            "n.yaml:2:1: mass: expected a number, got nothing");
}

TEST(YamlReader, UnknownKeyGetsASuggestionAtTheKey) {
  const YamlNode root =
      YamlNode::load_string("shape: box\nsize: [1, 1, 1]\ndensty: 7850\n", "u.yaml");
  const std::string m = parse_error_of([&] {
    root.check_keys({"shape", "size", "density", "mass"});
  });
  EXPECT_NE(m.find("u.yaml:3:1: unknown key 'densty' (did you mean 'density'?)"), std::string::npos)
      << m;
  // Nothing close: no suggestion, but the allowed keys are listed.
  const YamlNode other = YamlNode::load_string("colour: red\n", "c.yaml");
  const std::string m2 = parse_error_of([&] { other.check_keys({"mass", "density"}); });
  EXPECT_EQ(m2.find("did you mean"), std::string::npos) << m2;
  EXPECT_NE(m2.find("expected one of 'mass', 'density'"), std::string::npos) << m2;
  EXPECT_NO_THROW(root.check_keys({"shape", "size", "densty"}));
}

TEST(YamlReader, DuplicateKeyIsAnError) {
  const YamlNode root = YamlNode::load_string("mass: 1\nmass: 2\n", "d.yaml");
  EXPECT_EQ(parse_error_of([&] { root.check_keys({"mass"}); }),
            "d.yaml:2:1: key 'mass' given twice");
}

TEST(YamlReader, NumbersAreFiniteAndWithinTheirBound) {
  const YamlNode root = YamlNode::load_string(
      "zero: 0\nneg: -2.5\nnan: .nan\ninf: .inf\nword: heavy\nlist: [1]\nsci: 1.5e-3\n", "b.yaml");
  EXPECT_EQ(root.number("zero"), 0.0);
  EXPECT_EQ(root.number("zero", Bound::kNonNegative), 0.0);
  EXPECT_EQ(root.number("sci", Bound::kPositive), 1.5e-3);
  EXPECT_NE(parse_error_of([&] {
              root.number("zero", Bound::kPositive);
            }).find("must be positive, got 0"),
            std::string::npos);
  EXPECT_NE(parse_error_of([&] {
              root.number("neg", Bound::kNonNegative);
            }).find("b.yaml:2:6: neg: must not be negative, got -2.5"),
            std::string::npos);
  EXPECT_NE(
      parse_error_of([&] { root.number("nan"); }).find("expected a finite number, got '.nan'"),
      std::string::npos);
  EXPECT_NE(parse_error_of([&] { root.number("inf"); }).find("finite"), std::string::npos);
  EXPECT_NE(parse_error_of([&] { root.number("word"); }).find("expected a number, got 'heavy'"),
            std::string::npos);
  EXPECT_NE(parse_error_of([&] { root.number("list"); }).find("expected a number, got a list"),
            std::string::npos);
  EXPECT_FALSE(root.find_number("absent").has_value());
}

TEST(YamlReader, StringsBoolsAndIntegers) {
  const YamlNode root =
      YamlNode::load_string("name: shaft\nhole: true\nn: 12\nx: 1.5\nflag: maybe\n", "s.yaml");
  EXPECT_EQ(*root.find_string("name"), "shaft");
  EXPECT_TRUE(*root.find_bool("hole"));
  EXPECT_EQ(root.at("n").as_integer(), 12);
  EXPECT_THROW(root.at("x").as_integer(), ParseError);
  EXPECT_NE(parse_error_of([&] { root.at("flag").as_bool(); }).find("expected true or false"),
            std::string::npos);
  EXPECT_EQ(root.keys(), (std::vector<std::string>{"name", "hole", "n", "x", "flag"}));
}

TEST(YamlReader, VectorsAndMatrices) {
  const YamlNode root = YamlNode::load_string(
      "v2: [1, 2]\n"
      "R: [[0, -1, 0], [1, 0, 0], [0, 0, 1]]\n"
      "bad_row: [[1, 0, 0], [0, 1], [0, 0, 1]]\n"
      "flat: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n"
      "any: [4, 5, 6, 7]\n"
      "sizes: [1, 0, 2]\n",
      "v.yaml");
  EXPECT_NE(parse_error_of([&] {
              root.at("v2").as_vec3();
            }).find("v.yaml:1:5: v2: expected a list of 3 elements, got 2"),
            std::string::npos);
  Mat3 R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // Rows as written.
  EXPECT_EQ(root.at("R").as_mat3(), R);
  EXPECT_NE(parse_error_of([&] {
              root.at("bad_row").as_mat3();
            }).find("bad_row[1]: expected a list of 3 elements, got 2"),
            std::string::npos);
  EXPECT_NE(parse_error_of([&] { root.at("flat").as_mat3(); }).find("3×3 matrix"),
            std::string::npos);
  const VecX any = root.at("any").as_vector();
  ASSERT_EQ(any.size(), 4);
  EXPECT_EQ(any[3], 7.0);
  EXPECT_THROW(root.at("any").as_vector(3), ParseError);
  EXPECT_NE(parse_error_of([&] {
              root.at("sizes").as_vec3(Bound::kPositive);
            }).find("v.yaml:6:12: sizes[1]: must be positive, got 0"),
            std::string::npos);
}

TEST(YamlReader, WhichOfTakesExactlyOneAlternative) {
  const YamlNode both = YamlNode::load_string("mass: 1\ndensity: 2\n", "w.yaml");
  EXPECT_EQ(parse_error_of([&] {
              both.which_of({"mass", "density"});
            }),
            "w.yaml:2:1: give only one of 'mass', 'density': both 'mass' and 'density' are given");
  const YamlNode one = YamlNode::load_string("density: 2\n", "w.yaml");
  EXPECT_EQ(*one.which_of({"mass", "density"}), "density");
  EXPECT_FALSE(one.which_of({"mass", "volume"}).has_value());
}

TEST(YamlReader, AnglesInRadiansOrDegreesWhereTheKeySaysSo) {
  const YamlNode root = YamlNode::load_string(
      "a: 0.5\nb_deg: 90\nc: [0, 1, 2]\nd_deg: [180, -90, 45]\ne: 1\ne_deg: 2\n", "a.yaml");
  EXPECT_EQ(*root.find_angle("a"), 0.5);
  // 90° is π/2 to the last bit: 90 · (π/180) rounds once.
  EXPECT_DOUBLE_EQ(*root.find_angle("b"), std::numbers::pi / 2);
  EXPECT_EQ(*root.find_angles("c"), Vec3(0, 1, 2));
  EXPECT_MATRIX_NEAR(*root.find_angles("d"),
                     Vec3(std::numbers::pi, -std::numbers::pi / 2, std::numbers::pi / 4), 1e-15);
  EXPECT_FALSE(root.find_angle("z").has_value());
  EXPECT_NE(parse_error_of([&] { root.find_angle("e"); }).find("give only one of 'e', 'e_deg'"),
            std::string::npos);
}

TEST(YamlReader, WrongKindsAreNamed) {
  const YamlNode root = YamlNode::load_string("parts: 3\nm: {a: 1}\n", "k.yaml");
  EXPECT_EQ(parse_error_of([&] { root.at("parts").elements(); }),
            "k.yaml:1:8: parts: expected a list, got '3'");
  EXPECT_NE(parse_error_of([&] {
              root.at("parts").expect_map("a part");
            }).find("expected a part, got '3'"),
            std::string::npos);
  EXPECT_NE(parse_error_of([&] { root.at("m").as_string(); }).find("expected a text, got a map"),
            std::string::npos);
  EXPECT_THROW(root.at("parts").find("x"), ParseError);
  EXPECT_FALSE(root.at("parts").has("x"));
  EXPECT_EQ(root.size(), 2u);
}

}  // namespace
}  // namespace momenta::io
