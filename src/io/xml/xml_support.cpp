#include "xml/xml_support.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/one_line.hpp"
#include "momenta/io/files_read.hpp"

namespace momenta::io::detail {

void check_xml_document(const tinyxml2::XMLDocument& document, const std::string& file_name,
                        std::string_view empty_hint) {
  if (!document.Error()) return;
  if (document.ErrorID() == tinyxml2::XML_ERROR_EMPTY_DOCUMENT) {
    throw ParseError(file_name, 0, 0, fmt::format("the file is empty: {}", empty_hint));
  }
  // tinyxml2's name for the error, in words: XML_ERROR_MISMATCHED_ELEMENT → mismatched element.
  std::string what = document.ErrorName();
  if (what.rfind("XML_ERROR_", 0) == 0) what.erase(0, 10);
  std::transform(what.begin(), what.end(), what.begin(), [](unsigned char c) {
    return c == '_' ? ' ' : static_cast<char>(std::tolower(c));
  });
  throw ParseError(file_name, document.ErrorLineNum(), 0,
                   fmt::format("not well-formed XML ({})", what));
}

std::optional<std::vector<double>> parse_number_list(std::string_view text) {
  std::vector<double> numbers;
  std::size_t i = 0;
  while (true) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i == text.size()) return numbers;
    std::size_t end = i;
    while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
    const std::string word(text.substr(i, end - i));
    char* stop = nullptr;
    const double value = std::strtod(word.c_str(), &stop);
    if (stop != word.c_str() + word.size() || !std::isfinite(value)) return std::nullopt;
    numbers.push_back(value);
    i = end;
  }
}

int xml_column(std::string_view text, const tinyxml2::XMLElement* element, const char* attribute) {
  if (element == nullptr) return 0;
  // The element's line.
  std::size_t start = 0;
  for (int line = 1; line < element->GetLineNum(); ++line) {
    start = text.find('\n', start);
    if (start == std::string_view::npos) return 0;
    ++start;
  }
  const std::size_t end = std::min(text.find('\n', start), text.size());
  const std::string_view line = text.substr(start, end - start);
  const std::size_t tag = line.find(std::string("<") + element->Name());
  if (tag == std::string_view::npos) return 0;
  if (attribute != nullptr) {
    const std::string key = std::string(attribute) + "=";
    for (std::size_t at = line.find(key, tag); at != std::string_view::npos;
         at = line.find(key, at + 1)) {
      if (std::isspace(static_cast<unsigned char>(line[at - 1]))) return static_cast<int>(at) + 1;
    }
  }
  return static_cast<int>(tag) + 1;
}

model::Model build_at_lines(const model::ModelBuilder& builder,
                            const std::vector<ItemLocation>& items, const std::string& file_name,
                            const std::function<std::string(const InvalidArgument&)>& hint) {
  try {
    return builder.build();
  } catch (const InvalidArgument& error) {
    int line = 0, column = 0;
    if (error.item()) {
      for (const ItemLocation& at : items) {
        if (at.item.kind == error.item()->kind && at.item.name == error.item()->name) {
          line = at.line;
          column = at.column;
        }
      }
    }
    throw ParseError(file_name, line, column,
                     OptionMessage{one_line(error.spelled(keep_option_marks)) +
                                   (hint ? hint(error) : std::string())});
  }
}

std::string read_xml_text(const std::string& path, std::string_view what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(fmt::format("{}: cannot open the {}", path, what));
  note_file_read(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace momenta::io::detail
