// The page around the data: the embedded front-end (web/, bundled at build time into
// report_bundle.cpp) and the data as one JSON script element the front-end reads.

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <system_error>

#include "momenta/common/error.hpp"
#include "momenta/report/report.hpp"
#include "page_data.hpp"

namespace momenta::report {
namespace detail {

std::string escape_html(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Defined in the generated report_bundle.cpp.
extern const char* const kReportScript;
extern const char* const kReportStyle;

namespace {

// Text inside <script>: "</script" would end the element early. In JSON "</" only occurs inside
// strings, where "<\/" means the same; the bundle's own "</script" can only be inside strings too.
std::string script_safe(std::string text, std::string_view closing) {
  for (std::size_t at = text.find(closing); at != std::string::npos;
       at = text.find(closing, at + 3)) {
    text.replace(at, 2, "<\\/");
  }
  return text;
}

}  // namespace

std::string html_page(const std::string& title, const json& data) {
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta name=\"generator\" content=\"momenta\">\n<title>{}</title>\n<style>{}</style>\n"
      "</head>\n<body>\n<div id=\"app\"></div>\n"
      "<script type=\"application/json\" id=\"momenta-data\">{}</script>\n"
      "<script>{}</script>\n</body>\n</html>\n",
      escape_html(title), kReportStyle,
      script_safe(data.dump(-1, ' ', false, json::error_handler_t::replace), "</"),
      script_safe(kReportScript, "</script"));
}

}  // namespace detail

void write_report(const std::filesystem::path& path, const std::string& html, bool overwrite) {
  if (std::filesystem::exists(path) && !overwrite) {
    throw FileError(
        fmt::format("{}: the file exists; pass --force to overwrite it", path.string()));
  }
  std::filesystem::path temporary = path;
  temporary += ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw FileError(fmt::format("{}: cannot write the report", path.string()));
    out.write(html.data(), static_cast<std::streamsize>(html.size()));
    out.close();
    if (!out) {
      std::filesystem::remove(temporary);
      throw FileError(fmt::format("{}: writing the report failed", path.string()));
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary);
    throw FileError(fmt::format("{}: cannot write the report: {}", path.string(), error.message()));
  }
}

}  // namespace momenta::report
