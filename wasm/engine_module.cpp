// The report's in-page engine: momenta's model-file reader, dynamics, integrators and
// simulation compiled to WebAssembly (emscripten, embind), for a page that re-simulates when a
// reader moves a slider (docs/report.md, "The live report"). A front end like the command line
// and the Python module: it reads a model file as they do (the same ModelTemplate a sweep uses
// for its numbers by path) and runs it as `momenta simulate` does; nothing here is mechanics.
//
// From JavaScript (the module built as one file, the wasm inlined: wasm/CMakeLists.txt):
//
//     const engine = await createMomentaEngine();
//     const run = engine.simulate(modelText, "double_pendulum.yaml",
//                                 [{path: "bodies.upper.mass", value: 1.5}]);
//     run.columns        // ["time", "shoulder.angle", ...], as the CSV's header
//     run.rows           // Float64Array, row after row (columns.length values each)
//     run.summary        // the text `momenta simulate` prints on stderr
//     JSON.parse(engine.reportData(modelText, "double_pendulum.yaml", overrides))
//                        // the data `momenta report` embeds in its page (less its equations)
//     engine.reportDataParts(modelText, "double_pendulum.yaml", overrides, marker, "all")
//                        // {json, arrays}: the same, its long arrays as typed arrays apart
//                        // ("motion", then "analysis": the same data in two, one run)
//     engine.equationNumbers(modelText, "double_pendulum.yaml", overrides,
//                            data.equations.parameters, data.equations.form)
//                        // {values, zeroed, formChanges}: the symbols' values in the changed model
//     engine.numberAt(modelText, "double_pendulum.yaml", "bodies.upper.mass")   // 1 (or null)
//     engine.textWith(modelText, "double_pendulum.yaml", overrides)  // the file, numbers changed
//
// Errors are thrown as JavaScript Errors carrying momenta's message ("double_pendulum.yaml:12:5:
// bodies[0].mass: must be ≥ 0, got -1").

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/io/file_template.hpp"
#include "momenta/model/parameter_source.hpp"
#include "momenta/report/report.hpp"
#include "momenta/simulate/run_request.hpp"
#include "momenta/simulate/simulation.hpp"

namespace {

using emscripten::val;
using namespace momenta;

// The page's model file, written to emscripten's in-memory file system under its own name, in
// the working folder, so that the reader's messages name it as the command line does.
std::filesystem::path written_model(const std::string& text, const std::string& file_name) {
  const std::filesystem::path directory = "/model";
  std::filesystem::create_directories(directory);
  std::filesystem::current_path(directory);
  const std::filesystem::path path = std::filesystem::path(file_name).filename();
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  return path;
}

std::vector<io::NumberOverride> overrides_of(const val& list) {
  std::vector<io::NumberOverride> overrides;
  const auto count = list["length"].as<unsigned>();
  for (unsigned i = 0; i < count; ++i) {
    const val item = list[i];
    overrides.push_back({item["path"].as<std::string>(), item["value"].as<double>()});
  }
  return overrides;
}

// The page's model file, kept between calls. A page hands the engine one file's text each time
// and changes some of its numbers: the file is read (parsed, its model read and checked) once,
// not at every change, and the changed file last read and accepted is kept for the next call
// with the same numbers, with its report run (a live page's change asks for two steps of report
// data and the equations' values: 12 of the quarter car's 80 ms in the engine went to reading
// the file twice per call, Chromium's profiler).
class PageFile {
 public:
  const io::ModelTemplate& file_template(const std::string& text, const std::string& file_name) {
    if (!template_ || text != text_ || file_name != file_name_) {
      template_.reset();
      report_run_.reset();
      accepted_.reset();
      template_.emplace(written_model(text, file_name));
      text_ = text;
      file_name_ = file_name;
    }
    return *template_;
  }

  // The file with the overrides, read and accepted as the command line reads it.
  const io::ModelFile& accepted(const std::string& text, const std::string& file_name,
                                const val& overrides) {
    const io::ModelTemplate& file = file_template(text, file_name);
    std::vector<io::NumberOverride> changes = overrides_of(overrides);
    if (!accepted_ || !same(changes, overrides_)) {
      report_run_.reset();
      accepted_.reset();
      io::ModelFile changed = file.with(changes);
      frontend::accept_model(changed);
      accepted_.emplace(std::move(changed));
      overrides_ = std::move(changes);
    }
    return *accepted_;
  }

  // The file with the overrides run as `momenta report` runs it — the file's settings, reactions
  // recorded; a run stopped by a non-finite state keeps its rows and says why —, kept for the
  // next panels' data of the same numbers.
  const report::SimulationRun& report_run(const std::string& text, const std::string& file_name,
                                          const val& overrides) {
    const io::ModelFile& file = accepted(text, file_name, overrides);
    if (!report_run_) {
      report_run_.emplace(
          report::simulate_for_report(file, simulate::resolve_run({}, file.simulation).options));
    }
    if (report_run_->rows.empty()) throw NumericalError(report_run_->stop_reason);
    return *report_run_;
  }

 private:
  static bool same(const std::vector<io::NumberOverride>& a,
                   const std::vector<io::NumberOverride>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& x, const auto& y) {
      // The same bits: -0 and 0 are different numbers written in the file.
      return x.path == y.path && std::memcmp(&x.value, &y.value, sizeof(double)) == 0;
    });
  }

  std::string text_;
  std::string file_name_;
  std::optional<io::ModelTemplate> template_;
  std::vector<io::NumberOverride> overrides_;
  std::optional<io::ModelFile> accepted_;
  std::optional<report::SimulationRun> report_run_;  // of accepted_
};

PageFile page_file;

// A C++ exception as a JavaScript Error with its message.
[[noreturn]] void throw_to_javascript(const std::exception& e) {
  val::global("Error").new_(std::string(e.what())).throw_();
}

// A typed array holding a copy of the values (a view over the module's memory would move as it
// grows).
template <class T>
val typed_array(const char* type, const std::vector<T>& values) {
  const val view =
      val::global(type).new_(emscripten::typed_memory_view(values.size(), values.data()));
  return view.call<val>("slice");
}

val simulate_model(const std::string& text, const std::string& file_name, const val& overrides) {
  try {
    const io::ModelFile& file = page_file.accepted(text, file_name, overrides);
    const simulate::ResolvedRun run = simulate::resolve_run({}, file.simulation);
    simulate::Simulation simulation(file.model, file.outputs, run.options);
    simulate::TableSink table;
    const simulate::SimulationSummary summary = simulation.run(table);

    std::vector<double> flat;
    flat.reserve(table.rows.size() * table.columns.size());
    for (const std::vector<double>& row : table.rows)
      flat.insert(flat.end(), row.begin(), row.end());
    val result = val::object();
    val columns = val::array();
    for (const std::string& name : table.columns) columns.call<void>("push", name);
    result.set("columns", columns);
    result.set("rows", typed_array("Float64Array", flat));
    result.set("integrator", summary.integrator);
    result.set("relativeTolerance", run.options.tolerances.relative);
    result.set("absoluteTolerance", run.options.tolerances.absolute);
    result.set("tEnd", summary.t_end);
    result.set("summary", simulate::format_summary(summary));
    if (!run.thinning_note.empty()) result.set("thinningNote", run.thinning_note);
    return result;
  } catch (const std::exception& e) {
    throw_to_javascript(e);
  }
}

// UTF-8 text as a JavaScript string, decoded by the browser's TextDecoder: embind's conversion of
// a returned std::string scans it byte by byte in JavaScript first (40 ms of a live page's change
// for the quarter car's 1.9 MB of report data).
val javascript_string(const std::string& text) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  return val::global("TextDecoder")
      .new_()
      .call<val>("decode", val(emscripten::typed_memory_view(text.size(), bytes)));
}

report::ReportPanels panels_of(const std::string& name) {
  if (name == "all") return report::ReportPanels::all;
  if (name == "motion") return report::ReportPanels::motion;
  if (name == "analysis") return report::ReportPanels::analysis;
  throw InvalidArgument("reportDataParts: panels '" + name + "': expected all, motion or analysis");
}

// The data of the report `momenta report FILE` writes, as JSON text, for the file with the
// overrides: the page redraws every panel from it (the equations stay the native page's).
val report_data(const std::string& text, const std::string& file_name, const val& overrides) {
  try {
    return javascript_string(
        report::simulation_report_json(page_file.report_run(text, file_name, overrides)));
  } catch (const std::exception& e) {
    throw_to_javascript(e);
  }
}

// The same data with its long arrays apart (report::simulation_report_parts), as the live page
// takes it: {json, arrays}, the JSON text writing `marker` + k where the page's file has the k-th
// array as base64 text, each array a Float64Array or (drawn only) a Float32Array. Of the quarter
// car's 1.9 MB, 1.7 MB never become text: no base64 written, decoded or parsed. `panels`: "all",
// or "motion" then "analysis" (report::ReportPanels) — the page redraws the 3-D view and the
// plots before the analysis is made; the run is made once for both.
val report_data_parts(const std::string& text, const std::string& file_name, const val& overrides,
                      const std::string& marker, const std::string& panels) {
  try {
    const report::ReportDataParts parts = report::simulation_report_parts(
        page_file.report_run(text, file_name, overrides), marker, {}, panels_of(panels));
    val arrays = val::array();
    for (const report::ReportArray& array : parts.arrays) {
      arrays.call<void>("push", array.single ? typed_array("Float32Array",
                                                           std::vector<float>(array.values.begin(),
                                                                              array.values.end()))
                                             : typed_array("Float64Array", array.values));
    }
    val out = val::object();
    out.set("json", javascript_string(parts.json));
    out.set("arrays", arrays);
    return out;
  } catch (const std::exception& e) {
    throw_to_javascript(e);
  }
}

// A parameter source as the report's data writes it (report::detail::source_json).
model::ParameterSource source_of(const val& item) {
  const std::string kind = item["kind"].as<std::string>();
  const auto parsed = model::parameter_source_kind(kind);
  if (!parsed) throw InvalidArgument("equations: no parameter source '" + kind + "'");
  const auto number = [&](const char* key, int otherwise) {
    return item[key].isUndefined() ? otherwise : item[key].as<int>();
  };
  model::ParameterSource source;
  source.kind = *parsed;
  source.index = number("index", 0);
  source.row = number("row", 0);
  source.column = number("column", 0);
  source.magnitude = !item["magnitude"].isUndefined() && item["magnitude"].as<bool>();
  source.sign = number("sign", 1);
  return source;
}

// The report's equations' symbols given the values of the file with the overrides, and whether
// they keep their form (report::equation_numbers): `parameters` and `form` as the report's data
// holds them; {values, zeroed, formChanges}.
val equation_numbers(const std::string& text, const std::string& file_name, const val& overrides,
                     const val& parameters, const val& form) {
  try {
    std::vector<report::EquationSymbolSources> symbols;
    for (unsigned i = 0; i < parameters["length"].as<unsigned>(); ++i) {
      const val p = parameters[i];
      report::EquationSymbolSources symbol{p["name"].as<std::string>(), {}};
      for (unsigned k = 0; k < p["sources"]["length"].as<unsigned>(); ++k)
        symbol.sources.push_back(source_of(p["sources"][k]));
      symbols.push_back(std::move(symbol));
    }
    std::vector<report::EquationFormNumber> numbers;
    for (unsigned i = 0; i < form["length"].as<unsigned>(); ++i) {
      const val n = form[i];
      numbers.push_back(
          {n["name"].as<std::string>(), source_of(n["source"]), n["value"].as<double>()});
    }
    const report::EquationNumbers result = report::equation_numbers(
        page_file.accepted(text, file_name, overrides).model, symbols, numbers);
    val out = val::object();
    val values = val::array();
    for (double v : result.values) values.call<void>("push", v);
    const auto strings = [](const std::vector<std::string>& list) {
      val array = val::array();
      for (const std::string& item : list) array.call<void>("push", item);
      return array;
    };
    out.set("values", values);
    out.set("zeroed", strings(result.zeroed));
    out.set("formChanges", strings(result.form_changes));
    return out;
  } catch (const std::exception& e) {
    throw_to_javascript(e);
  }
}

val number_at(const std::string& text, const std::string& file_name, const std::string& path) {
  try {
    const std::optional<double> number = page_file.file_template(text, file_name).number_at(path);
    return number ? val(*number) : val::null();
  } catch (const std::exception& e) {
    throw_to_javascript(e);
  }
}

std::string text_with(const std::string& text, const std::string& file_name, const val& overrides) {
  try {
    return page_file.file_template(text, file_name).text_with(overrides_of(overrides));
  } catch (const std::exception& e) {
    throw_to_javascript(e);
  }
}

}  // namespace

EMSCRIPTEN_BINDINGS(momenta_engine) {
  emscripten::function("simulate", &simulate_model);
  emscripten::function("reportData", &report_data);
  emscripten::function("reportDataParts", &report_data_parts);
  emscripten::function("equationNumbers", &equation_numbers);
  emscripten::function("numberAt", &number_at);
  emscripten::function("textWith", &text_with);
}
