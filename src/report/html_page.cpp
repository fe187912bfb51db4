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

// Defined in the generated report_bundle.cpp.
extern const char* const kReportScript;
extern const char* const kReportStyle;
// Defined in the generated engine_bundle.cpp, or empty (engine_absent.cpp): the module's script,
// and its wasm gzipped, in base64.
extern const char* const kEngineScript;
extern const char* const kEngineWasm;

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

// The notice the MIT License asks to travel with every copy of the libraries the page embeds
// (THIRD-PARTY-NOTICES.md lists them all). esbuild keeps three.js's own @license comment in the
// bundle, not uPlot's or KaTeX's, so the page carries them here.
constexpr std::string_view kEmbeddedLibrariesNotice =
    "This page embeds three.js (Copyright (c) 2010-2024 three.js authors), uPlot\n"
    "(Copyright (c) 2022 Leon Sorokin) and KaTeX (Copyright (c) 2013-2020 Khan Academy and other\n"
    "contributors), each under the MIT License:\n\n"
    "Permission is hereby granted, free of charge, to any person obtaining a copy of this "
    "software\n"
    "and associated documentation files (the \"Software\"), to deal in the Software without\n"
    "restriction, including without limitation the rights to use, copy, modify, merge, publish,\n"
    "distribute, sublicense, and/or sell copies of the Software, and to permit persons to whom "
    "the\n"
    "Software is furnished to do so, subject to the following conditions:\n\n"
    "The above copyright notice and this permission notice shall be included in all copies or\n"
    "substantial portions of the Software.\n\n"
    "THE SOFTWARE IS PROVIDED \"AS IS\", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR IMPLIED,\n"
    "INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY, FITNESS FOR A PARTICULAR\n"
    "PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE AUTHORS OR COPYRIGHT HOLDERS BE LIABLE "
    "FOR\n"
    "ANY CLAIM, DAMAGES OR OTHER LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE,\n"
    "ARISING FROM, OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE\n"
    "SOFTWARE.";

}  // namespace

bool engine_embedded() { return kEngineScript[0] != '\0'; }

std::string html_page(const std::string& title, const json& data, bool with_engine) {
  const std::string engine =
      with_engine && engine_embedded()
          ? fmt::format(
                "<script type=\"application/gzip;base64\" id=\"momenta-engine\">{}</script>\n"
                "<script>{}</script>\n",
                kEngineWasm, script_safe(kEngineScript, "</script"))
          : std::string();
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<!--\n{}\n-->\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta name=\"generator\" content=\"momenta\">\n<title>{}</title>\n<style>{}</style>\n"
      "</head>\n<body>\n<div id=\"app\"></div>\n"
      "<script type=\"application/json\" id=\"momenta-data\">{}</script>\n"
      "{}<script>{}</script>\n</body>\n</html>\n",
      kEmbeddedLibrariesNotice, escape_html(title), kReportStyle,
      script_safe(data.dump(-1, ' ', false, json::error_handler_t::replace), "</"), engine,
      script_safe(kReportScript, "</script"));
}

}  // namespace detail

void write_report(const std::filesystem::path& path, const std::string& html, bool overwrite) {
  if (std::filesystem::exists(path) && !overwrite) {
    throw FileError(OptionMessage{
        fmt::format("{}: the file exists; pass ‹force› to overwrite it", path.string())});
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
